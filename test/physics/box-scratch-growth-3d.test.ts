import { addBody, addPlane, addShape3D, createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

describe('3D collide stage: the first step of many boxes', () => {
  // Regression: the collider scratch of the 3D broadphase grew while it was being filled and dropped
  // what it held, so on the first step of a world with more than 64 colliders the earlier boxes took no
  // part in collisions (their boxes read as empty, at the origin): resting boxes fell through the floor
  // for that step, and every pair of them went to the narrowphase.
  test('200 boxes resting on a floor (2 m apart) all stay up on their first step; none touches another', () => {
    const world = createPhysicsWorld({ dimensions: 3, gravity: [0, -10, 0] });
    addPlane(world, { normal: [0, 1, 0] });
    const boxes: number[] = [];
    for (let i = 0; i < 200; i++) {
      const b = addBody(world, { position: [3 * (i % 20), 0.5, 3 * Math.floor(i / 20)] });
      addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
      boxes.push(slotOf(b));
    }
    step(world);
    // Four corner points on the floor per box, none between boxes (2 m gaps, far past the 0.1 m speculative distance).
    expect(world.collision.stats.contacts).toBe(4 * boxes.length);
    // Held by the floor: a box the floor missed would fall at v = -g h = -0.167 m/s after one step;
    // a held one keeps |v_y| far below that (1 % of g h allows for the soft contact's settling).
    const c = world.components,
      gh = 10 * world.dt;
    for (const b of boxes) expect(Math.abs(c.Velocity.y[b]!)).toBeLessThan(0.01 * gh);
    // The count is the step's, not a running sum (with no balls in the world, nothing else resets it).
    step(world);
    expect(world.collision.stats.contacts).toBe(4 * boxes.length);
  });
});
