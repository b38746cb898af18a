import {
  addBallJoint3D,
  addBody,
  addHingeJoint3D,
  addShape3D,
  addSliderJoint3D,
  createPhysicsWorld,
  joint3DBreaks,
  joints3DOf,
  removeBody,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

const G = 9.81;

function world3(gravity = -G) {
  return createPhysicsWorld({ dimensions: 3, gravity: [0, gravity, 0], sleep: false, dt: 1 / 240 });
}

/** A 1 kg cube of half extent 0.1 m at p. */
function cube(world: ReturnType<typeof world3>, p: number[]): number {
  const b = addBody(world, { position: p });
  addShape3D(world, b, { type: 'box', halfExtents: [0.1, 0.1, 0.1], density: 1 / 0.008 });
  return b;
}

describe('3D slider joint', () => {
  test('a box on a frictionless slider tilted 45 deg slides with a = g sin 45 (0.5 %), stays on the line (1 mm) and does not turn', () => {
    const world = world3();
    const b = cube(world, [0, 0, 0]);
    const u = [Math.SQRT1_2, -Math.SQRT1_2, 0];
    addSliderJoint3D(world, { b, axis: u });
    const c = world.components,
      e = slotOf(b);
    const n = 240; // 1 s
    for (let i = 0; i < n; i++) step(world);
    const t = world.time,
      x = c.Position.x[e]!,
      y = c.Position.y[e]!,
      z = c.Position.z[e]!;
    const along = x * u[0]! + y * u[1]!;
    // Independent reference: motion along a line under gravity, s = g_parallel t^2 / 2.
    const expected = (G * Math.SQRT1_2 * t * t) / 2;
    expect(Math.abs(along - expected) / expected).toBeLessThan(0.005);
    expect(Math.hypot(x - along * u[0]!, y - along * u[1]!, z)).toBeLessThan(1e-3);
    expect(Math.hypot(c.AngularVelocity.x[e]!, c.AngularVelocity.y[e]!, c.AngularVelocity.z[e]!)).toBeLessThan(1e-6);
  });

  test('limits stop the slide at lower = -0.5 m (1 cm); a motor drives 2 m/s, and with a 3 N cap accelerates a 1 kg box at 3 m/s^2 (1 %)', () => {
    const world = world3();
    const hanging = cube(world, [0, 0, 0]);
    addSliderJoint3D(world, { b: hanging, axis: [0, 1, 0], lower: -0.5, upper: 0.5 });
    const fast = cube(world, [5, 0, 0]);
    addSliderJoint3D(world, { b: fast, axis: [1, 0, 0], motorSpeed: 2, maxMotorForce: 1000 });
    const capped = cube(world, [10, 0, 0]);
    addSliderJoint3D(world, { b: capped, axis: [0, 0, 1], motorSpeed: 100, maxMotorForce: 3 });
    const c = world.components;
    for (let i = 0; i < 240; i++) step(world);
    expect(c.Position.y[slotOf(hanging)]!).toBeCloseTo(-0.5, 2);
    expect(Math.abs(c.Velocity.x[slotOf(fast)]! - 2)).toBeLessThan(0.02);
    // Free motion along z under a constant force F: v = F t / m.
    expect(Math.abs(c.Velocity.z[slotOf(capped)]! - 3 * world.time) / (3 * world.time)).toBeLessThan(0.01);
  });

  test('limit and motor impulses are warm-started: a box resting on a slider limit holds its weight from the first substep of each step', () => {
    const world = world3();
    const b = cube(world, [0, 0, 0]);
    const j = addSliderJoint3D(world, { b, axis: [0, 1, 0], lower: -0.2, upper: 0.2 });
    for (let i = 0; i < 240; i++) step(world);
    const s = joints3DOf(world)!,
      e = slotOf(j);
    // The limit row carries the weight: impulse per substep m g h_s along +y (soft rows: 1 %).
    const hs = world.dt / world.collision.settings.solverSubsteps;
    expect(Math.abs(s.limit[e]! - G * hs) / (G * hs)).toBeLessThan(0.01);
    // Kept from step to step (warm start): the box does not creep below the limit.
    const y0 = world.components.Position.y[slotOf(b)]!;
    for (let i = 0; i < 240; i++) step(world);
    expect(Math.abs(world.components.Position.y[slotOf(b)]! - y0)).toBeLessThan(1e-4);
  });

  test('a slider breaks past its force and goes with its body; bad input gets clear errors and changes nothing', () => {
    const world = world3();
    const b = cube(world, [0, 0, 0]);
    addSliderJoint3D(world, { b, axis: [1, 0, 0], breakForce: 5 }); // holds 9.81 N across the axis: breaks
    step(world);
    expect(joint3DBreaks(world).length).toBe(1);
    const kept = cube(world, [3, 0, 0]);
    addSliderJoint3D(world, { b: kept, axis: [1, 0, 0] });
    expect(joints3DOf(world)!.list.length).toBe(1);
    removeBody(world, kept);
    expect(joints3DOf(world)!.list.length).toBe(0);
    const other = cube(world, [6, 0, 0]);
    expect(() => addSliderJoint3D(world, { b: other, axis: [0, 0, 0] })).toThrow('addSliderJoint3D: axis must be a non-zero vector');
    expect(() => addSliderJoint3D(world, { b: other, axis: [1, 0, 0], lower: 0.1, upper: 1 })).toThrow(
      'addSliderJoint3D: lower must be <= 0, got 0.1',
    );
    expect(() => addSliderJoint3D(world, { b: other, axis: [1, 0, 0], motorSpeed: 1 })).toThrow(
      'addSliderJoint3D: maxMotorForce must be given with motorSpeed',
    );
    // A joint to a removed body.
    expect(() => addSliderJoint3D(world, { b: kept, axis: [1, 0, 0] })).toThrow(/addSliderJoint3D: b .*removed/);
    expect(() => addHingeJoint3D(world, { a: kept, b: other, axis: [0, 0, 1] })).toThrow(/addHingeJoint3D: a .*removed/);
    expect(() => addBallJoint3D(world, { b: kept })).toThrow(/addBallJoint3D: b .*removed/);
    expect(joints3DOf(world)!.list.length).toBe(0);
  });
});
