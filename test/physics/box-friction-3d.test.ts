import { addBody, addShape3D, createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * Friction of a manifold solved once a manifold (manifold3d-solver.ts: two tangent rows at an anchor and
 * a twist row about the normal) against Coulomb's law at the four corners a resting cube stands on.
 * A 1 m cube of 1 kg (I = m a^2 / 6 = 1/6 kg m^2) on a static box floor, mu 0.6 on both (mixed: 0.6), g 10:
 * - sliding at v0, along a face or diagonally: the friction force mu m g decelerates it at mu g = 6 m/s^2;
 * - spinning about the vertical at w0: each corner, at r = a / sqrt(2) = 0.7071 m from the axis, resists
 *   with mu N / 4, so the torque is mu m g r and w falls at mu m g r / I = 25.46 rad/s^2 (the per-point
 *   friction rows gave this torque; a twist row limited by mu arm sum(lambda_n), arm the points' mean
 *   distance from the anchor, gives the same).
 */
function cubeOnFloor(velocity: number[], angularVelocity: number[]): { world: ReturnType<typeof createPhysicsWorld>; e: number } {
  const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -10, 0] });
  const f = addBody(world, { position: [0, 0, 0], static: true });
  addShape3D(world, f, { type: 'box', halfExtents: [20, 0.5, 20], friction: 0.6 });
  // Resting on the floor's top (y = 0.5) from the start.
  const d = addBody(world, { position: [0, 1, 0], velocity, rotates: true, angularVelocity });
  addShape3D(world, d, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1, friction: 0.6 });
  return { world, e: slotOf(d) };
}

describe('3D boxes: friction of a cube on a floor against Coulomb at its corners', () => {
  test('a cube spinning about the vertical at 4 rad/s slows at mu m g r / I = 25.5 rad/s^2 and stops', () => {
    const { world, e } = cubeOnFloor([0, 0, 0], [0, 4, 0]);
    const W = world.components.AngularVelocity,
      P = world.components.Position;
    // 6 steps of 1/60 s: 4 - 25.46 * 0.1 = 1.454 rad/s. Bound 10 % of the 2.546 rad/s lost (the first
    // substeps build the normal impulse, and the limit follows it).
    for (let s = 0; s < 6; s++) step(world);
    expect(Math.abs(W.y[e]! - (4 - 0.6 * 10 * Math.SQRT1_2 * 6 * 0.1))).toBeLessThan(0.1 * 2.546);
    // Stopped (0.157 s) well before 30 steps, without tipping or wandering off the spot.
    for (let s = 6; s < 30; s++) step(world);
    expect(Math.hypot(W.x[e]!, W.y[e]!, W.z[e]!)).toBeLessThan(0.01);
    expect(Math.hypot(P.x[e]!, P.z[e]!)).toBeLessThan(0.005);
    expect(Math.abs(P.y[e]! - 1)).toBeLessThan(0.005);
  });

  test('a cube sliding diagonally at 3 m/s slows at mu g too, not sqrt 2 mu g', () => {
    // Along (1, 0, 1) / sqrt 2, at 45 degrees to the tangent rows: a limit clamping each tangent impulse to
    // mu N separately let the pair take sqrt 2 mu N (0.88 m/s left after 0.25 s instead of 1.5). Bound 5 %.
    const v = 3 * Math.SQRT1_2;
    const { world, e } = cubeOnFloor([v, 0, v], [0, 0, 0]);
    const V = world.components.Velocity;
    for (let s = 0; s < 15; s++) step(world);
    expect(Math.abs(Math.hypot(V.x[e]!, V.z[e]!) - 1.5)).toBeLessThan(0.05 * 1.5);
    // Still heading along the diagonal (within 1 degree).
    expect(Math.abs(Math.atan2(V.z[e]!, V.x[e]!) - Math.PI / 4)).toBeLessThan(Math.PI / 180);
  });

  test('a cube sliding at 3 m/s slows at mu g = 6 m/s^2 without turning', () => {
    const { world, e } = cubeOnFloor([3, 0, 0], [0, 0, 0]);
    const V = world.components.Velocity,
      W = world.components.AngularVelocity;
    // 15 steps: 3 - 6 * 0.25 = 1.5 m/s; bound 5 % of the 1.5 m/s lost.
    for (let s = 0; s < 15; s++) step(world);
    expect(Math.abs(V.x[e]! - 1.5)).toBeLessThan(0.05 * 1.5);
    // The friction acts at the floor, below the centre: the cube must not pitch over (it would need
    // mu > a / (2 (a / 2)) = 1 to tip); spin under 0.05 rad/s, no sideways drift.
    expect(Math.hypot(W.x[e]!, W.y[e]!, W.z[e]!)).toBeLessThan(0.05);
    expect(Math.abs(V.z[e]!)).toBeLessThan(1e-3);
  });
});
