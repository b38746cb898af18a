import { addBody, addDistanceJoint, createPhysicsWorld, isSleeping, setBoundary, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

/**
 * 2D joints in the sleeping islands (islands/edges.ts `joinJointEdges`, the rule 3D joints follow too):
 * bodies tied by a joint sleep and wake together. Two balls rest on the floor of a box, 2 m apart,
 * tied by a 2 m distance joint; the right one hops 5 cm first, so it comes to rest later: neither may
 * sleep without the other. A third ball then hits the right
 * one from the right at 6 m/s: the left one must wake too, and the joint (a rigid 2 m rod) pushes it
 * along by more than 5 cm within 1 s. A left ball left asleep would hold the right one like a fixed
 * anchor and not move at all.
 */
describe('2D joints and sleeping islands', () => {
  test('jointed balls sleep as one island, and a hit on one wakes the other, which the joint pushes along', () => {
    const world = createPhysicsWorld({ gravity: [0, -9.81] });
    setBoundary(world, { min: [-20, 0], max: [20, 20] });
    const left = addBody(world, { position: [-1, 0.5], radius: 0.5 });
    const right = addBody(world, { position: [1, 0.5], radius: 0.5 });
    addDistanceJoint(world, { a: left, b: right, length: 2 });
    // The right ball hops (5 cm): it comes to rest later than the left one.
    world.components.Velocity.y[slotOf(right)] = 1;
    for (let i = 0; i < 240; i++) {
      step(world);
      expect(isSleeping(world, left)).toBe(isSleeping(world, right));
    }
    expect(isSleeping(world, left)).toBe(true);
    expect(isSleeping(world, right)).toBe(true);
    const P = world.components.Position;
    const x0 = P.x[slotOf(left)]!;
    addBody(world, { position: [6, 0.5], velocity: [-6, 0], radius: 0.5 });
    let leftWoke = false;
    for (let i = 0; i < 60; i++) {
      step(world);
      if (!isSleeping(world, left)) leftWoke = true;
    }
    expect(leftWoke).toBe(true);
    // The hit pushes the right ball left: the joint (rigid, 2 m) pushes the left ball along (-x).
    expect(Math.abs(P.x[slotOf(left)]! - x0)).toBeGreaterThan(0.05);
  });
});
