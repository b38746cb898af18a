/**
 * Jointed bodies do not collide with each other unless the joint says `collideConnected: true` (Box2D's
 * default). Two overlapping bodies at rest without gravity, held by a slack distance joint (a rope of
 * 0..3 m, so the joint itself pushes nothing apart): with no contact between them nothing acts on them and
 * they stay exactly where they are (momentum and position conserved bit for bit); with collideConnected
 * the contact separates them to at least (close to) their touching distance.
 */

import {
  addBody,
  addBox,
  addDistanceJoint,
  addRevoluteJoint,
  createPhysicsWorld,
  type PhysicsWorld,
  removeJoint,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';

type Maker = (world: PhysicsWorld, x: number) => number;
/** Ball colliders (narrowphase.ts) of radius 0.5 m; box colliders (shape-collision.ts) of half width 0.5 m. */
const ball: Maker = (world, x) => addBody(world, { position: [x, 0], radius: 0.5, mass: 1, inertia: 0.125 });
const box: Maker = (world, x) => addBox(world, { position: [x, 0], halfExtents: [0.5, 0.5], density: 1 });

/** Two bodies 0.6 m apart (touching distance 1 m) on a slack joint; returns their distance after 30 steps. */
function separation(make: Maker, collideConnected: boolean | undefined, remove = false): number {
  const world = createPhysicsWorld({ gravity: [0, 0] });
  const a = make(world, 0),
    b = make(world, 0.6);
  const j = addDistanceJoint(world, {
    a,
    b,
    length: 0.6,
    minLength: 0,
    maxLength: 3,
    ...(collideConnected === undefined ? {} : { collideConnected }),
  });
  if (remove) removeJoint(world, j);
  for (let i = 0; i < 30; i++) step(world);
  const P = world.components.Position;
  return P.x[slotOf(b)]! - P.x[slotOf(a)]!;
}

describe('collideConnected', () => {
  for (const [name, make] of [
    ['balls', ball],
    ['boxes', box],
  ] as const) {
    test(`${name}: jointed bodies do not touch by default, collide with collideConnected, collide again once the joint is gone`, () => {
      // No contact: no force at all, so the distance stays 0.6 m to rounding.
      expect(separation(make, undefined)).toBeCloseTo(0.6, 12);
      expect(separation(make, false)).toBeCloseTo(0.6, 12);
      // Contact: pushed apart to the touching distance 1 m less the solver's allowed overlap (a few mm; 0.05 m is loose).
      expect(separation(make, true)).toBeGreaterThan(0.95);
      expect(separation(make, undefined, true)).toBeGreaterThan(0.95);
    });
  }

  test('only the jointed pair is exempt: a third body still collides with both', () => {
    const world = createPhysicsWorld({ gravity: [0, 0] });
    const a = ball(world, 0),
      b = ball(world, 0.6),
      c = ball(world, -0.6);
    addRevoluteJoint(world, { a, b, anchor: [0.3, 0] });
    for (let i = 0; i < 30; i++) step(world);
    const P = world.components.Position;
    expect(P.x[slotOf(a)]! - P.x[slotOf(c)]!).toBeGreaterThan(0.95);
  });

  test('a collideConnected that is not a boolean is refused and leaves the world as it was', () => {
    const world = createPhysicsWorld({ gravity: [0, 0] });
    const a = ball(world, 0),
      b = ball(world, 0.6);
    expect(() => addDistanceJoint(world, { a, b, collideConnected: 1 as unknown as boolean })).toThrow(
      /addDistanceJoint: collideConnected must be/,
    );
    expect(world.joints.noCollidePairs.size).toBe(0);
  });
});
