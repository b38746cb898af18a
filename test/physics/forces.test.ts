import {
  addBody,
  addElectricField,
  addFluidRegion,
  addMagneticField,
  addSpring,
  angularMomentum,
  createPhysicsWorld,
  enableMutualGravity,
  kineticEnergy,
  linearMomentum,
  potentialEnergy,
  removeBody,
  setBuoyancy,
  setCentralForce,
  setCharge,
  setDrag,
  setDrivingForce,
  setElectrostatics,
  setGravitation,
  setGravityScale,
  setLift,
  setRandomForce,
  setThrust,
  setWind,
  step,
  stepMany,
  valueNoise,
  windAt,
} from '@bitphysics/physics';
import { query } from 'bitecs';
import { describe, expect, test } from 'vitest';

const rel = (a: number, b: number) => Math.abs(a - b) / Math.abs(b);

describe('oscillators (RK4, h = 1 ms: global error ~ h^4, far below the tolerances)', () => {
  test('damped oscillator matches x(t) = e^(-gamma t) (cos wd t + (gamma / wd) sin wd t)', () => {
    // m = 1, k = 16 (w0 = 4), c = 1.6 (gamma = c / 2m = 0.8).
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 1e-3, integrator: 'rk4' });
    const b = addBody(world, { position: [1, 0], mass: 1 });
    setCentralForce(world, b, { centre: [0, 0], k: -16, n: 2 });
    setDrag(world, b, { linear: 1.6 });
    const gamma = 0.8,
      wd = Math.sqrt(16 - gamma * gamma);
    let worst = 0;
    for (let i = 0; i < 5000; i++) {
      step(world);
      const t = world.time;
      const exact = Math.exp(-gamma * t) * (Math.cos(wd * t) + (gamma / wd) * Math.sin(wd * t));
      worst = Math.max(worst, Math.abs(world.components.Position.x[b]! - exact));
    }
    expect(worst).toBeLessThan(1e-9);
  });

  test('driven damped oscillator matches transient + steady state', () => {
    // x'' + 2 gamma x' + w0^2 x = (F0 / m) cos(w t), x(0) = 0, v(0) = 0.
    const m = 2,
      w0 = 3,
      gamma = 0.5,
      F0 = 4,
      w = 2;
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 1e-3, integrator: 'rk4' });
    const b = addBody(world, { position: [0, 0], mass: m });
    setCentralForce(world, b, { centre: [0, 0], k: -m * w0 * w0, n: 2 });
    setDrag(world, b, { linear: 2 * gamma * m });
    setDrivingForce(world, b, { amplitude: [F0, 0], omega: w });
    // Steady state A cos(w t - delta); transient e^(-gamma t)(C cos wd t + D sin wd t) fixed by x(0) = v(0) = 0.
    const A = F0 / m / Math.sqrt((w0 * w0 - w * w) ** 2 + (2 * gamma * w) ** 2);
    const delta = Math.atan2(2 * gamma * w, w0 * w0 - w * w);
    const wd = Math.sqrt(w0 * w0 - gamma * gamma);
    const C = -A * Math.cos(delta);
    const D = (-A * w * Math.sin(delta) + gamma * C) / wd;
    let worst = 0;
    for (let i = 0; i < 10000; i++) {
      step(world);
      const t = world.time;
      const exact = A * Math.cos(w * t - delta) + Math.exp(-gamma * t) * (C * Math.cos(wd * t) + D * Math.sin(wd * t));
      worst = Math.max(worst, Math.abs(world.components.Position.x[b]! - exact));
    }
    expect(worst).toBeLessThan(1e-9);
  });

  test('pendulum on a stiff spring: small-angle period 2 pi sqrt(L / g)', () => {
    // A 1 kg bob on a 2 m spring of 1e6 N/m (stretch under its weight m g / k = 1e-5 m, included in L).
    const g = 9.81,
      L0 = 2,
      k = 1e6,
      m = 1;
    const world = createPhysicsWorld({ gravity: [0, -g], dt: 1e-4, integrator: 'velocity-verlet' });
    const L = L0 + (m * g) / k;
    const theta0 = 0.02;
    const bob = addBody(world, { position: [L * Math.sin(theta0), -L * Math.cos(theta0)], mass: m });
    addSpring(world, { anchor: [0, 0], b: bob, stiffness: k, restLength: L0 });
    const crossings: number[] = [];
    let prevX = world.components.Position.x[bob]!;
    for (let i = 0; i < 200000 && crossings.length < 5; i++) {
      step(world);
      const x = world.components.Position.x[bob]!;
      if (prevX > 0 && x <= 0) crossings.push(world.time - world.dt * (x / (x - prevX)));
      prevX = x;
    }
    const period = (crossings[4]! - crossings[0]!) / 4;
    // Small-angle formula, corrected for the finite amplitude: T = 2 pi sqrt(L/g) (1 + theta0^2 / 16).
    const expected = 2 * Math.PI * Math.sqrt(L / g) * (1 + (theta0 * theta0) / 16);
    expect(rel(period, expected)).toBeLessThan(1e-4);
  });
});

describe('drag', () => {
  test('projectile with linear drag falls y = (m g / k)(t + (m / k) e^(-k t / m) - m / k)', () => {
    const m = 2,
      k = 0.5,
      g = 9.81;
    const world = createPhysicsWorld({ gravity: [0, -g], dt: 1e-3, integrator: 'rk4' });
    const b = addBody(world, { position: [0, 0], mass: m, linearDrag: k });
    let worst = 0;
    for (let i = 0; i < 5000; i++) {
      step(world);
      const t = world.time;
      const fallen = ((m * g) / k) * (t + (m / k) * Math.exp((-k * t) / m) - m / k);
      worst = Math.max(worst, Math.abs(-world.components.Position.y[b]! - fallen));
    }
    expect(worst).toBeLessThan(1e-8);
  });

  test('quadratic drag: v(t) = v_t tanh(g t / v_t) toward the terminal velocity v_t = sqrt(m g / k)', () => {
    const m = 0.5,
      k = 0.02,
      g = 9.81;
    const vt = Math.sqrt((m * g) / k);
    const world = createPhysicsWorld({ gravity: [0, -g], dt: 1e-3, integrator: 'rk4' });
    const b = addBody(world, { mass: m, quadraticDrag: k });
    let worst = 0;
    for (let i = 0; i < 20000; i++) {
      step(world);
      worst = Math.max(worst, Math.abs(-world.components.Velocity.y[b]! - vt * Math.tanh((g * world.time) / vt)));
    }
    expect(worst).toBeLessThan(1e-9);
    expect(rel(-world.components.Velocity.y[b]!, vt)).toBeLessThan(1e-6);
  });

  test('drag acts on the velocity relative to the wind: in a steady wind the body drifts at the wind speed', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], integrator: 'rk4' });
    setWind(world, { velocity: [5, 0] });
    const b = addBody(world, { mass: 1, linearDrag: 2 });
    stepMany(world, 1200);
    // v(t) = 5 (1 - e^(-2 t)): after 20 s it is 5 to within 5 e^-40.
    expect(world.components.Velocity.x[b]!).toBeCloseTo(5, 12);
  });

  test('turbulence is seeded, has the requested RMS speed, and is a pure function of (x, t)', () => {
    const world = createPhysicsWorld({ gravity: [0, 0] });
    setWind(world, { turbulence: { intensity: 2, lengthScale: 10, timeScale: 3, seed: 4, modes: 32 } });
    const out = new Float64Array(3),
      again = new Float64Array(3);
    let sum2 = 0;
    const n = 20000;
    for (let i = 0; i < n; i++) {
      const x = (i * 37.1) % 1000,
        y = (i * 91.7) % 1000,
        t = i * 0.37;
      windAt(world, x, y, 0, t, out);
      sum2 += out[0]! * out[0]!;
      windAt(world, x, y, 0, t, again);
      expect(again[0]).toBe(out[0]);
    }
    // Sampling a 32-mode field at scattered points: the RMS is within 15% of the target.
    expect(Math.abs(Math.sqrt(sum2 / n) - 2) / 2).toBeLessThan(0.15);
  });

  test('lift is perpendicular to the relative velocity, with magnitude k v^2', () => {
    const world = createPhysicsWorld({ gravity: [0, 0] });
    const b = addBody(world, { velocity: [3, 4], mass: 1 });
    setLift(world, b, { k: 0.1 });
    step(world);
    // After one step the force that acted was k |v| (z x v) = 0.1 * 5 * (-4, 3).
    const F = world.components.Force;
    expect(F.x[b]).toBeCloseTo(-2, 12);
    expect(F.y[b]).toBeCloseTo(1.5, 12);
  });
});

describe('buoyancy', () => {
  test('a floating sphere settles where buoyancy equals weight', () => {
    // 3D ball of radius 0.5 m and density 400 kg/m^3 in water (1000): submerged volume fraction 0.4.
    const r = 0.5,
      rho = 400,
      g = 9.81;
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -g, 0], dt: 1 / 240 });
    addFluidRegion(world, { surface: 0, density: 1000 });
    const mass = rho * (4 / 3) * Math.PI * r ** 3;
    const b = addBody(world, { position: [0, 2, 0], mass });
    setBuoyancy(world, b, { shape: 'ball', radius: r, dragCoefficient: 800 });
    setDrag(world, b, { linear: 400 }); // quadratic drag alone barely damps small bobbing
    stepMany(world, 240 * 30);
    // Depth h of the cap with pi h^2 (3 r - h) / 3 = 0.4 * (4/3) pi r^3, solved by bisection.
    let lo = 0,
      hi = 2 * r;
    for (let i = 0; i < 100; i++) {
      const h = (lo + hi) / 2;
      if ((Math.PI * h * h * (3 * r - h)) / 3 < 0.4 * (4 / 3) * Math.PI * r ** 3) lo = h;
      else hi = h;
    }
    const expectedY = -(lo - r); // centre is r above the lowest point, which is lo below the surface
    expect(Math.abs(world.components.Position.y[b]! - expectedY)).toBeLessThan(1e-4);
    expect(Math.abs(world.components.Velocity.y[b]!)).toBeLessThan(1e-4);
  });

  test('a denser box sinks; a lighter box floats with the submerged fraction of its height', () => {
    const world = createPhysicsWorld({ gravity: [0, -9.81], dt: 1 / 240 });
    addFluidRegion(world, { surface: 0, density: 1000 });
    // 2D box 1 m x 0.6 m, density 700 kg/m^2: floats with 0.7 of its height under.
    const b = addBody(world, { position: [0, 1], mass: 700 * 1 * 0.6 });
    setBuoyancy(world, b, { shape: 'box', halfExtents: [0.5, 0.3], dragCoefficient: 2000 });
    setDrag(world, b, { linear: 400 });
    stepMany(world, 240 * 30);
    expect(Math.abs(world.components.Position.y[b]! - (0.3 - 0.7 * 0.6))).toBeLessThan(1e-4);
  });
});

describe('electromagnetism', () => {
  test('a charge in a magnetic field circles with radius m v / (|q| B) and period 2 pi m / (|q| B)', () => {
    const m = 2,
      q = -0.5,
      B = 4,
      v = 3;
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 1e-3, integrator: 'rk4' });
    addMagneticField(world, { field: B });
    const b = addBody(world, { position: [0, 0], velocity: [v, 0], mass: m });
    setCharge(world, b, q);
    const T = (2 * Math.PI * m) / (Math.abs(q) * B);
    const R = (m * v) / (Math.abs(q) * B);
    // Negative charge, B out of the screen: F = q v x B = -0.5 (3,0) x (0,0,4) = (0, 6): centre at (0, R).
    let worst = 0;
    const n = Math.round(T / world.dt);
    for (let i = 0; i < n; i++) {
      step(world);
      const P = world.components.Position;
      worst = Math.max(worst, Math.abs(Math.hypot(P.x[b]!, P.y[b]! - R) - R));
    }
    expect(worst).toBeLessThan(1e-9);
    // After one period it is back at the start.
    const P = world.components.Position;
    expect(Math.hypot(P.x[b]!, P.y[b]!)).toBeLessThan(1e-3 * R + v * Math.abs(n * world.dt - T));
  });

  test('two charges conserve momentum and energy; like charges repel', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 1e-4, integrator: 'rk4' });
    setElectrostatics(world, { constant: 1 });
    const a = addBody(world, { position: [0, 0], mass: 1 });
    const b = addBody(world, { position: [1, 0], mass: 3 });
    setCharge(world, a, 1);
    setCharge(world, b, 2);
    const E0 = kineticEnergy(world) + potentialEnergy(world);
    stepMany(world, 5000);
    expect(Math.abs(linearMomentum(world)[0]!)).toBeLessThan(1e-12);
    expect(rel(kineticEnergy(world) + potentialEnergy(world), E0)).toBeLessThan(1e-10);
    expect(world.components.Position.x[a]!).toBeLessThan(0);
  });

  test('a uniform electric field accelerates a charge at q E / m', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], integrator: 'rk4' });
    addElectricField(world, { field: [0, 50] });
    const b = addBody(world, { mass: 0.5 });
    setCharge(world, b, 0.01);
    stepMany(world, 60);
    expect(world.components.Velocity.y[b]!).toBeCloseTo(1, 12); // a = 0.01 * 50 / 0.5 = 1 m/s^2 for 1 s
  });
});

describe('gravitation', () => {
  test('two-body motion conserves linear and angular momentum', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 1e-3, integrator: 'velocity-verlet' });
    setGravitation(world, { constant: 1 });
    const a = addBody(world, { position: [-1, 0], velocity: [0, -0.2], mass: 3 });
    const b = addBody(world, { position: [2, 0], velocity: [0.1, 0.6], mass: 1 });
    enableMutualGravity(world, a);
    enableMutualGravity(world, b);
    const p0 = Array.from(linearMomentum(world)),
      L0 = angularMomentum(world)[2]!;
    stepMany(world, 20000);
    const p1 = linearMomentum(world);
    expect(Math.abs(p1[0]! - p0[0]!)).toBeLessThan(1e-12);
    expect(Math.abs(p1[1]! - p0[1]!)).toBeLessThan(1e-12);
    // Velocity Verlet conserves angular momentum exactly for central pair forces (up to rounding).
    expect(rel(angularMomentum(world)[2]!, L0)).toBeLessThan(1e-10);
  });

  test('gravity scale multiplies the uniform gravity a body feels', () => {
    const world = createPhysicsWorld({ gravity: [0, -10] });
    const a = addBody(world, {}),
      b = addBody(world, {});
    setGravityScale(world, b, -0.5);
    stepMany(world, 60);
    expect(world.components.Velocity.y[a]!).toBeCloseTo(-10, 9);
    expect(world.components.Velocity.y[b]!).toBeCloseTo(5, 9);
  });

  test('a central force with n = -1, k < 0 is inverse-square attraction with the matching potential energy', () => {
    const world = createPhysicsWorld({ gravity: [0, 0], dt: 1e-3, integrator: 'rk4' });
    const b = addBody(world, { position: [1, 0], velocity: [0, 1], mass: 1 });
    setCentralForce(world, b, { centre: [0, 0], k: -1, n: -1 }); // circular orbit of radius 1
    const E0 = kineticEnergy(world) + potentialEnergy(world);
    stepMany(world, 6283);
    const P = world.components.Position;
    expect(Math.abs(Math.hypot(P.x[b]!, P.y[b]!) - 1)).toBeLessThan(1e-9);
    expect(rel(kineticEnergy(world) + potentialEnergy(world), E0)).toBeLessThan(1e-10);
  });
});

describe('springs', () => {
  test('a chain of springs conserves energy with no damping, and removing a body removes its springs', () => {
    const world = createPhysicsWorld({ gravity: [0, -9.81], dt: 1e-3, integrator: 'rk4' });
    const ids = [0, 1, 2, 3].map((i) => addBody(world, { position: [0, -i - 1.2], mass: 0.5 }));
    addSpring(world, { anchor: [0, 0], b: ids[0]!, stiffness: 50, restLength: 1 });
    for (let i = 1; i < ids.length; i++) addSpring(world, { a: ids[i - 1]!, b: ids[i]!, stiffness: 50, restLength: 1 });
    const E0 = kineticEnergy(world) + potentialEnergy(world);
    stepMany(world, 3000);
    expect(rel(kineticEnergy(world) + potentialEnergy(world), E0)).toBeLessThan(1e-9);
    const springs = () => query(world, [world.components.Spring]).length;
    expect(springs()).toBe(4);
    removeBody(world, ids[1]!);
    expect(springs()).toBe(2);
    stepMany(world, 10);
  });

  test('a bungee pulls only while stretched', () => {
    const world = createPhysicsWorld({ gravity: [0, 0] });
    const b = addBody(world, { position: [0, -0.5] });
    addSpring(world, { anchor: [0, 0], b, stiffness: 100, restLength: 1, oneSided: true });
    step(world);
    expect(world.components.Velocity.y[b]).toBe(0);
    const c = addBody(world, { position: [0, -2] });
    addSpring(world, { anchor: [0, 0], b: c, stiffness: 100, restLength: 1, oneSided: true });
    step(world);
    expect(world.components.Velocity.y[c]!).toBeGreaterThan(0);
  });
});

describe('driving and rockets', () => {
  test('random driving force is seeded and reproducible, and bounded by its magnitude', () => {
    const run = () => {
      const world = createPhysicsWorld({ gravity: [0, 0], integrator: 'rk4' });
      const b = addBody(world, { mass: 1 });
      setRandomForce(world, b, { magnitude: 3, correlationTime: 0.5, seed: 17 });
      stepMany(world, 300);
      return [world.components.Position.x[b]!, world.components.Position.y[b]!];
    };
    expect(run()).toEqual(run());
    for (let t = 0; t < 50; t += 0.01) expect(Math.abs(valueNoise(17, t, 0.5, 0))).toBeLessThanOrEqual(1);
  });

  for (const integrator of ['semi-implicit-euler', 'rk4'] as const) {
    test(`a rocket reaches the Tsiolkovsky delta-v ve ln(m0 / m1) (${integrator})`, () => {
      const h = 1 / 600;
      const world = createPhysicsWorld({ gravity: [0, 0], dt: h, integrator });
      const m0 = 1000,
        fuel = 600,
        ve = 2500,
        mdot = 50;
      const b = addBody(world, { mass: m0 });
      setThrust(world, b, { exhaustVelocity: ve, massFlowRate: mdot, fuel, direction: [0, 1] });
      stepMany(world, 600 * 15); // burns out after 12 s
      const dv = ve * Math.log(m0 / (m0 - fuel));
      // The rocket law gives the exact acceleration ve mdot / m(t) at every evaluation (thrustSystem),
      // so the error is the scheme's quadrature error of that smooth function of time: RK4 (Simpson's
      // rule per step) is exact to ~1e-9 here; semi-implicit Euler takes the start-of-step value, a
      // left Riemann sum whose error is h (a_end - a_start) / 2 = 0.156 m/s; we allow 10% over it.
      const aStart = (ve * mdot) / m0,
        aEnd = (ve * mdot) / (m0 - fuel);
      const tol = integrator === 'rk4' ? 1e-6 : 1.1 * 0.5 * h * (aEnd - aStart);
      expect(Math.abs(world.components.Velocity.y[b]! - dv)).toBeLessThan(tol);
      // 7,200 decrements of 1/12 kg leave ~1e-10 kg of rounding; inverse mass stays consistent with mass.
      expect(Math.abs(world.components.Mass.value[b]! - (m0 - fuel))).toBeLessThan(1e-8);
      expect(Math.abs(world.components.Mass.value[b]! * world.components.Mass.inv[b]! - 1)).toBeLessThan(1e-15);
    });
  }
});

describe('bad input for force laws', () => {
  const world = createPhysicsWorld();
  const body = addBody(world, {});
  test.each([
    ['negative drag', () => setDrag(world, body, { linear: -1 }), /linear must be >= 0, got -1/],
    ['negative softening', () => setGravitation(world, { softening: -0.1 }), /softening must be >= 0, got -0.1/],
    [
      'unknown gravity method',
      () => setGravitation(world, { method: 'fmm' as never }),
      /method must be one of 'direct', 'barnes-hut', got "fmm"/,
    ],
    [
      'spring to a missing entity',
      () => addSpring(world, { a: body, b: 4242, stiffness: 1 }),
      /b must be an entity of this world .*got 4242/,
    ],
    [
      'spring with negative stiffness',
      () => addSpring(world, { anchor: [0, 0], b: body, stiffness: -5 }),
      /stiffness must be >= 0, got -5/,
    ],
    ['spring with both a and anchor', () => addSpring(world, { a: body, anchor: [0, 0], b: body, stiffness: 1 }), /exactly one of a/],
    [
      'fuel heavier than the body',
      () => setThrust(world, body, { exhaustVelocity: 100, massFlowRate: 1, fuel: 2, direction: [0, 1] }),
      /fuel \(2 kg\) must be less than/,
    ],
    [
      'negative exhaust velocity',
      () => setThrust(world, body, { exhaustVelocity: -1, massFlowRate: 1, fuel: 0.5, direction: [0, 1] }),
      /exhaustVelocity must be > 0/,
    ],
    [
      'unknown buoyancy shape',
      () => setBuoyancy(world, body, { shape: 'cone' as never }),
      /shape must be one of 'ball', 'box', got "cone"/,
    ],
    [
      'negative turbulence',
      () => setWind(world, { turbulence: { intensity: -1, lengthScale: 1, timeScale: 1 } }),
      /intensity must be >= 0/,
    ],
    ['NaN charge', () => setCharge(world, body, NaN), /charge must be finite, got NaN/],
  ])('%s', (_name, run, message) => {
    expect(run).toThrow(RangeError);
    expect(run).toThrow(message);
  });
});
