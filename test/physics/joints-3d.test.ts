import {
  addBallJoint3D,
  addBody,
  addDistanceJoint3D,
  addFixedJoint3D,
  addHingeJoint3D,
  addShape3D,
  createPhysicsWorld,
  joint3DBreaks,
  joints3DOf,
  type PhysicsWorld,
  removeBody,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/** A body's rotation angle from the identity, rad: 2 acos |w| of its unit quaternion. */
function rotationAngle(O: PhysicsWorld['components']['Orientation'], e: number): number {
  return 2 * Math.acos(Math.min(1, Math.abs(O.w[e]!)));
}

function world3() {
  return createPhysicsWorld({ dimensions: 3, gravity: [0, -9.81, 0], sleep: false, dt: 1 / 240 });
}

describe('3D joints', () => {
  test('a hinge pendulum (a small box on a 1 m arm) swings with the period of a physical pendulum (1 %)', () => {
    const world = world3();
    const bob = addBody(world, { position: [0, -1, 0] });
    addShape3D(world, bob, { type: 'box', halfExtents: [0.05, 0.05, 0.05], density: 1000 });
    addHingeJoint3D(world, { b: bob, anchor: [0, 0, 0], axis: [0, 0, 1] });
    const c = world.components,
      e = slotOf(bob);
    c.Velocity.x[e] = 0.3; // small swing (amplitude ~0.1 rad)
    // Physical pendulum: T = 2 pi sqrt(I / (m g d)), I = m d^2 + m (2 a)^2 / 6 for a cube of side 2a.
    const d = 1,
      a = 0.05,
      T = 2 * Math.PI * Math.sqrt((d * d + (4 * a * a) / 6) / (9.81 * d));
    let prev = c.Velocity.x[e]!,
      crossings: number[] = [];
    for (let i = 0; i < 2000 && crossings.length < 3; i++) {
      step(world);
      const v = c.Velocity.x[e]!;
      if ((prev > 0 && v <= 0) || (prev < 0 && v >= 0)) crossings.push(world.time);
      prev = v;
    }
    const period = crossings[2]! - crossings[0]!;
    expect(Math.abs(period - T) / T).toBeLessThan(0.01);
    // The arm keeps its length (soft joint: within 1 mm).
    expect(Math.abs(Math.hypot(c.Position.x[e]!, c.Position.y[e]!, c.Position.z[e]!) - 1)).toBeLessThan(1e-3);
    // The hinge keeps the bob in the x-y plane and its axis along z.
    expect(Math.abs(c.Position.z[e]!)).toBeLessThan(1e-6);
  });

  test('a hinge limit stops the swing at upper = 0.3 rad; a fixed joint holds a box still; a ball joint with a cone', () => {
    const world = world3();
    const arm = addBody(world, { position: [1, 0, 0] });
    addShape3D(world, arm, { type: 'box', halfExtents: [0.5, 0.05, 0.05] });
    addHingeJoint3D(world, { b: arm, anchor: [0.5, 0, 0], axis: [0, 0, 1], lower: -0.3, upper: 0.3 });
    const held = addBody(world, { position: [3, 0, 0] });
    addShape3D(world, held, { type: 'box', halfExtents: [0.5, 0.05, 0.05] });
    addFixedJoint3D(world, { b: held, anchor: [2.5, 0, 0] });
    const hang = addBody(world, { position: [5.5, 0, 0] });
    addShape3D(world, hang, { type: 'box', halfExtents: [0.5, 0.05, 0.05] });
    addBallJoint3D(world, { b: hang, anchor: [5, 0, 0], axis: [1, 0, 0], coneAngle: 0.5 });
    for (let i = 0; i < 480; i++) step(world);
    const c = world.components,
      p = (b: number): number[] => [c.Position.x[slotOf(b)]!, c.Position.y[slotOf(b)]!];
    // Rests at the lower limit (falling clockwise = negative angle): centre at 0.5 + 0.5 (cos 0.3, -sin 0.3) (1 cm).
    expect(p(arm)[0]!).toBeCloseTo(0.5 + 0.5 * Math.cos(0.3), 2);
    expect(p(arm)[1]!).toBeCloseTo(-0.5 * Math.sin(0.3), 2);
    expect(Math.abs(p(held)[1]!)).toBeLessThan(0.01);
    // ... and its orientation: a rigid weld keeps it unturned; the soft rows let the 49 N m load
    // (10 kg at 0.5 m) turn it 0.0235 degrees (measured); 0.1 degree allowed.
    expect(rotationAngle(c.Orientation, slotOf(held))).toBeLessThan((0.1 * Math.PI) / 180);
    expect(p(hang)[1]!).toBeCloseTo(-0.5 * Math.sin(0.5), 2);
  });

  test('a distance joint keeps its length, breaks past its force, and joints go with their bodies', () => {
    const world = world3();
    const b = addBody(world, { position: [0, -2, 0] });
    addShape3D(world, b, { type: 'sphere', radius: 0.1, density: 1000 });
    const rod = addDistanceJoint3D(world, { b, anchorA: [0, 0, 0], breakForce: 1e6 });
    const c = world.components,
      e = slotOf(b);
    c.Velocity.x[e] = 3;
    for (let i = 0; i < 240; i++) step(world);
    expect(Math.abs(Math.hypot(c.Position.x[e]!, c.Position.y[e]!) - 2)).toBeLessThan(2e-3);
    const w2 = world3();
    const heavy = addBody(w2, { position: [0, -1, 0] });
    addShape3D(w2, heavy, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1000 }); // 1000 kg: 9,810 N
    const ball = addBallJoint3D(w2, { b: heavy, anchor: [0, -0.5, 0], breakForce: 5000 });
    // It breaks in the first step (9,810 N > 5,000 N): that step's break list names it (and its
    // bodies, the world 0 and the box), it is no longer listed, and the box falls free.
    step(w2);
    expect(joint3DBreaks(w2)).toEqual([[ball, 0, heavy, 0]]);
    expect(joints3DOf(w2)!.list.length).toBe(0);
    // Then it falls free: after 10 more steps it moves down at least g t (less 1 %). Those steps
    // broke nothing, so the list of the last step's breaks is empty (the world has no other joint or
    // contact, so the solver that clears it does not run: the list is cleared when read).
    for (let i = 0; i < 10; i++) step(w2);
    expect(w2.components.Velocity.y[slotOf(heavy)]!).toBeLessThan(-9.81 * 10 * w2.dt * 0.99);
    expect(joint3DBreaks(w2)).toEqual([]);
    removeBody(world, b);
    expect(joints3DOf(world)!.list.length).toBe(0);
    void rod;
    expect(() => addHingeJoint3D(world, { b: addBody(world, {}), axis: [0, 0, 0] })).toThrow(
      /addHingeJoint3D: axis must be a non-zero vector/,
    );
  });

  test('a fixed joint breaks past its breakTorque and holds below it', () => {
    // A 10 kg lever (1 x 0.1 x 0.1 m, 1,000 kg/m^3) welded at one end to the world: its weight's
    // torque about the weld is m g L / 2 = 49.05 N m (the weld's force, m g = 98.1 N, is unlimited).
    const load = 10 * 9.81 * 0.5;
    const lever = (factor: number): { w: PhysicsWorld; e: number; j: number } => {
      const w = world3();
      const e = addBody(w, { position: [0.5, 0, 0] });
      addShape3D(w, e, { type: 'box', halfExtents: [0.5, 0.05, 0.05], density: 1000 });
      return { w, e, j: addFixedJoint3D(w, { b: e, anchor: [0, 0, 0], breakTorque: factor * load }) };
    };
    // 0.8 of the load: it breaks in the first step (as the soft rows catch the falling lever their
    // torque overshoots the static load by 5 to 10 %, so thresholds near 1.0 are not tested).
    const weak = lever(0.8);
    step(weak.w);
    expect(joint3DBreaks(weak.w)).toEqual([[weak.j, 0, weak.e, 0]]);
    expect(joints3DOf(weak.w)!.list.length).toBe(0);
    // 1.25 of the load: it holds for 1 s, the lever level (its rotation under 0.1 degree; measured 0.0235).
    const strong = lever(1.25);
    let angle = 0;
    for (let i = 0; i < 240; i++) {
      step(strong.w);
      expect(joint3DBreaks(strong.w)).toEqual([]);
      angle = Math.max(angle, rotationAngle(strong.w.components.Orientation, slotOf(strong.e)));
    }
    expect(joints3DOf(strong.w)!.list).toEqual([slotOf(strong.j)]);
    expect(angle).toBeLessThan((0.1 * Math.PI) / 180);

    // Two dynamic bodies welded together: joints-3d-weld.test.ts.
  });
});
