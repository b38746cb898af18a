import { addBody, addShape3D, createPhysicsWorld, type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { pairContacts } from './helpers.js';

/**
 * The speculative distance of 3D shapes (shape3d-collision.ts, SHAPE_SPECULATIVE_DISTANCE): Box2D v3's
 * b2_speculativeDistance, 4 linear slops of 5 mm = 0.02 m, capped by the world's speculativeDistance.
 * Two bodies at rest (no gravity, no speed: the margin's speed term is zero) keep speculative points
 * exactly while their gap is under it, and those points push nothing. Gaps are 1 mm either side of the
 * distance (the narrowphase measures them to about 1e-12 m).
 */

function pair(gap: number, worldSpec?: number): { world: PhysicsWorld; a: number; b: number } {
  const world = createPhysicsWorld({ dimensions: 3, gravity: [0, 0, 0], sleep: false });
  if (worldSpec !== undefined) world.collision.settings.speculativeDistance = worldSpec;
  const a = addBody(world, { position: [0, 0, 0] });
  addShape3D(world, a, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1000 });
  const b = addBody(world, { position: [1 + gap, 0, 0] });
  addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 1000 });
  return { world, a, b };
}

describe('3D shapes: speculative contacts within 0.02 m (Box2D v3: 4 linear slops)', () => {
  test('two cubes 19 mm apart have a face manifold of four speculative points at 19 mm that pushes nothing; 21 mm apart, none', () => {
    const near = pair(0.019);
    step(near.world);
    const c = pairContacts(near.world, near.a, near.b);
    expect(c.points).toBe(4);
    expect(c.minSep).toBeCloseTo(0.019, 9);
    // Speculative rows stop an approach only: at rest, neither cube moves.
    expect(near.world.components.Velocity.x[slotOf(near.a)]).toBe(0);
    expect(near.world.components.Velocity.x[slotOf(near.b)]).toBe(0);
    const far = pair(0.021);
    step(far.world);
    expect(pairContacts(far.world, far.a, far.b).points).toBe(0);
  });

  test("a world's smaller speculativeDistance caps it: at 0.01 m, cubes 11 mm apart have no contact, 9 mm apart have one", () => {
    const far = pair(0.011, 0.01);
    step(far.world);
    expect(pairContacts(far.world, far.a, far.b).points).toBe(0);
    const near = pair(0.009, 0.01);
    step(near.world);
    expect(pairContacts(near.world, near.a, near.b).points).toBe(4);
  });
});
