// The aircraft scene and the lifting-surface law: level flight at the trim speed lift = weight
// predicts, the stall past the stall angle, and the roll rate from the aileron torque against
// Euler's equation.

import {
  addBody,
  addLiftingSurface,
  createPhysicsWorld,
  DEFAULT_LIFT_SLOPE,
  evaluateForces,
  type PhysicsWorld,
  Rng,
  setBodyThrust,
  setControlDeflection,
  setInertia,
  setTimeStep,
  step,
} from '@bitphysics/physics';
import { AIRCRAFT, AIRCRAFT_TRIM_SPEED, aircraft, aircraftLevelDrag } from '@bitphysics/projects';
import { describe, expect, test } from 'vitest';

function run(world: PhysicsWorld, seconds: number): void {
  for (let i = 0, n = Math.round(seconds / world.dt); i < n; i++) step(world);
}

describe('aircraft: lifting surfaces', () => {
  test('holds height and speed at the trim speed of m g = rho V^2 S a i / 2', () => {
    expect(AIRCRAFT_TRIM_SPEED).toBeCloseTo(Math.sqrt((2 * 30_000 * 9.81) / (1.225 * 150 * DEFAULT_LIFT_SLOPE * AIRCRAFT.incidence)), 9);
    const world = createPhysicsWorld(aircraft.worldOptions());
    const { body } = aircraft.build(world); // level, trim speed, thrust = level drag
    run(world, 30);
    const P = world.components.Position,
      V = world.components.Velocity;
    // Every force balances exactly at t = 0 (lift = weight, thrust = drag, no pitching moment), so the
    // state stays put to the integrator's rounding over 30 s (1,800 RK4 steps).
    expect(Math.abs(P.y[body]! - 1200)).toBeLessThan(1e-3);
    expect(Math.abs(V.x[body]! - AIRCRAFT_TRIM_SPEED)).toBeLessThan(1e-4);
    // 10 % slow, lift = 0.81 weight: it sinks (a phugoid), which the check above would catch.
    const slow = createPhysicsWorld(aircraft.worldOptions());
    const s = aircraft.build(slow, { speed: 0.9 * AIRCRAFT_TRIM_SPEED, thrust: aircraftLevelDrag(0.9 * AIRCRAFT_TRIM_SPEED) });
    run(slow, 5);
    expect(slow.components.Position.y[s.body]!).toBeLessThan(1200 - 5);
  });

  test('stalls past the stall angle: lift a alpha below it, the flat plate sin(2 alpha) above', () => {
    // One wing (75 m^2) on a body held by no other force, the air meeting it at alpha: compare the
    // evaluated lift with q A C_L on either side of 20 degrees.
    const lift = (alphaDeg: number): number => {
      const world = createPhysicsWorld({ dimensions: 3, gravity: [0, 0, 0] });
      const a = (alphaDeg * Math.PI) / 180,
        v = 100;
      const b = addBody(world, { velocity: [v * Math.cos(a), -v * Math.sin(a), 0], mass: 1000 });
      setInertia(world, b, [1e4, 1e4, 1e4]);
      addLiftingSurface(world, { body: b, area: 75 });
      evaluateForces(world);
      const F = world.components.Force;
      // Lift is the force component perpendicular to the velocity, in the x-y plane.
      return F.x[b]! * Math.sin(a) + F.y[b]! * Math.cos(a);
    };
    const q = 0.5 * 1.225 * 100 * 100 * 75;
    expect(lift(19) / ((q * DEFAULT_LIFT_SLOPE * (19 * Math.PI)) / 180)).toBeCloseTo(1, 9);
    expect(lift(21) / (q * Math.sin((2 * 21 * Math.PI) / 180))).toBeCloseTo(1, 9);
    expect(lift(21)).toBeLessThan(0.5 * lift(19)); // the stall: more than half the lift is lost
  });

  test('aileron roll: initial roll acceleration tau / I_xx (Euler) and the damped roll rate V k delta / (a y)', () => {
    const world = createPhysicsWorld({ ...aircraft.worldOptions(), dt: 1e-5 });
    const { body, surfaces } = aircraft.build(world);
    const delta = 0.1;
    setControlDeflection(world, surfaces.leftWing, delta);
    setControlDeflection(world, surfaces.rightWing, -delta);
    // Euler's equations at w = 0: I dw/dt = tau. Each half gets q A k delta of extra lift at y = 7.5 m.
    const V = AIRCRAFT_TRIM_SPEED,
      q = 0.5 * AIRCRAFT.airDensity * V * V;
    const tau = 2 * q * (AIRCRAFT.wingArea / 2) * AIRCRAFT.aileronPower * delta * AIRCRAFT.wingHalfOffset;
    evaluateForces(world);
    expect(world.components.Torque.x[body]! / tau).toBeCloseTo(1, 9);
    step(world); // 10 us: the roll damping (time ~0.01 s) has not yet acted
    const wx = world.components.AngularVelocity;
    // Left wing up, right down: a roll to the right, a rotation about the body's x axis (+x here).
    expect(wx.x[body]! / world.dt / (tau / AIRCRAFT.inertia[0]!)).toBeCloseTo(1, 2);
    setTimeStep(world, 1 / 240);
    // Steady roll: the aileron lift balanced by the roll's own angle of attack a p y / V at each half,
    // p = V k delta / (a y). Reached within a second (the damping time I / (2 q A a y^2 / V) ~ 0.02 s).
    run(world, 1);
    const p = (V * AIRCRAFT.aileronPower * delta) / (DEFAULT_LIFT_SLOPE * AIRCRAFT.wingHalfOffset);
    const speed = Math.hypot(world.components.Velocity.x[body]!, world.components.Velocity.y[body]!, world.components.Velocity.z[body]!);
    const pNow = (speed * AIRCRAFT.aileronPower * delta) / (DEFAULT_LIFT_SLOPE * AIRCRAFT.wingHalfOffset);
    const roll = Math.hypot(wx.x[body]!, wx.y[body]!, wx.z[body]!);
    expect(Math.abs(roll - pNow) / p).toBeLessThan(0.05);
  });

  test('stays stable in a full-throttle dive: finite, spin under 5 rad/s (RK4 with 4 substeps)', () => {
    // Random stick and rudder for 30 s at full throttle, then hands off for 30 s, over three seeds:
    // without the substeps, the roll damping lambda h passed RK4's limit (about 2.8) near 190 m/s and
    // every run diverged within 40 s (spin over 15 rad/s, then speeds of 1e30 m/s or a NaN force).
    for (const seed of [3, 7, 11]) {
      const world = createPhysicsWorld(aircraft.worldOptions());
      const { body, surfaces } = aircraft.build(world, { altitude: 900 });
      const rng = new Rng(seed);
      const full = (20 * Math.PI) / 180;
      let pitch = 0,
        roll = 0,
        yaw = 0,
        maxSpin = 0,
        maxSpeed = 0;
      setBodyThrust(world, body, [AIRCRAFT.maxThrust, 0, 0]);
      for (let i = 0; i < 3600; i++) {
        if (i % 60 === 0) {
          const on = i < 1800;
          pitch = on ? rng.range(-1, 1) : 0;
          roll = on ? rng.range(-1, 1) : 0;
          yaw = on ? rng.range(-1, 1) : 0;
        }
        setControlDeflection(world, surfaces.tail, -pitch * full);
        setControlDeflection(world, surfaces.leftWing, roll * full);
        setControlDeflection(world, surfaces.rightWing, -roll * full);
        setControlDeflection(world, surfaces.fin, -yaw * full);
        step(world);
        const V = world.components.Velocity,
          W = world.components.AngularVelocity;
        maxSpeed = Math.max(maxSpeed, Math.hypot(V.x[body]!, V.y[body]!, V.z[body]!));
        maxSpin = Math.max(maxSpin, Math.hypot(W.x[body]!, W.y[body]!, W.z[body]!));
      }
      expect(Number.isFinite(maxSpeed)).toBe(true);
      expect(maxSpin).toBeLessThan(5);
      expect(maxSpeed).toBeLessThan(400);
    }
  });

  test('bad input is refused', () => {
    const world = createPhysicsWorld({ dimensions: 3 });
    const b = addBody(world, { mass: 1 });
    expect(() => addLiftingSurface(world, { body: b, area: 1 })).toThrow(/addLiftingSurface: body \d+ must be dynamic and turn/);
    setInertia(world, b, [1, 1, 1]);
    expect(() => addLiftingSurface(world, { body: b, area: -1 })).toThrow(/addLiftingSurface: area must be/);
    expect(() => addLiftingSurface(world, { body: b, area: 1, normal: [1, 0, 0] })).toThrow(/must not lie along the chord/);
    expect(() => setControlDeflection(world, b, 0.1)).toThrow(/setControlDeflection: surface must be a lifting surface .*got entity \d+/);
    expect(() => addLiftingSurface(createPhysicsWorld(), { body: 1, area: 1 })).toThrow(/need a 3D world/);
  });
});
