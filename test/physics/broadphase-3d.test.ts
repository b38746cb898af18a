import { addBody, addShape3D, createPhysicsWorld, type PhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { contact3DStateOf } from '../../packages/physics/src/collision/manifolds-3d.js';

/**
 * The 3D shape broadphase (packages/physics/src/collision/broadphase/pairs-3d.ts) has two grids: a
 * dense one (a bucket for every cell of the colliders' span) while the span has at most 8 cells a
 * collider, and a hashed one otherwise. The same crowd of touching and nearly touching boxes, once on
 * its own (dense) and once with a static box 100 km away (its span then needs the hashed grid), must
 * give exactly the same pairs their manifolds after a step: each grid is checked against the other.
 */

/**
 * A deterministic crowd of 1 m boxes (plus the far box with `far`; with `resting`, every third box of
 * the lattice static: a collider that does not search, met only as a neighbour), stepped once; its
 * manifold rows' shape pairs, sorted.
 */
function pairsAfterOneStep(far: boolean, resting = false): string[] {
  const world: PhysicsWorld = createPhysicsWorld({ dimensions: 3, gravity: [0, -10, 0], sleep: false, seed: 1 });
  let r = 12345;
  const random = (): number => {
    r = (Math.imul(r, 1103515245) + 12345) >>> 0;
    return r / 2 ** 32;
  };
  // A 7 x 5 x 7 lattice 1.01 m apart (gaps of 1 cm, inside the speculative margin), each box jittered by
  // up to 2 cm and turned by up to ~6 degrees, some moving: face, edge and corner neighbours.
  for (let x = 0; x < 7; x++)
    for (let y = 0; y < 5; y++)
      for (let z = 0; z < 7; z++) {
        const q = [0.05 * (random() - 0.5), 0.05 * (random() - 0.5), 0.05 * (random() - 0.5), 1];
        const still = resting && (x + 7 * y + 35 * z) % 3 === 0;
        const b = addBody(world, {
          static: still,
          position: [1.01 * x + 0.02 * (random() - 0.5), 1.01 * y + 0.02 * (random() - 0.5), 1.01 * z + 0.02 * (random() - 0.5)],
          velocity: [random() - 0.5, random() - 0.5, random() - 0.5],
          orientation: q,
          ...(still ? {} : { mass: 1 }),
        });
        addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
      }
  if (far) {
    const b = addBody(world, { position: [1e5, 0, 0], static: true });
    addShape3D(world, b, { type: 'box', halfExtents: [0.5, 0.5, 0.5] });
  }
  step(world);
  const buf = contact3DStateOf(world)!.current;
  const pairs: string[] = [];
  for (let i = 0; i < buf.count; i++) pairs.push(`${buf.shapeA[i]}-${buf.shapeB[i]}`);
  return pairs.sort();
}

describe('3D broadphase: the dense and the hashed grid', () => {
  test('find the same pairs in a crowd of boxes', () => {
    const dense = pairsAfterOneStep(false),
      hashed = pairsAfterOneStep(true);
    // 245 boxes with about three face neighbours each, and their edge and corner neighbours.
    expect(dense.length).toBeGreaterThan(500);
    expect(new Set(dense).size).toBe(dense.length);
    expect(hashed).toEqual(dense);
  });

  test('find the same pairs when a third of the crowd is static (met only by the moving boxes)', () => {
    const dense = pairsAfterOneStep(false, true),
      hashed = pairsAfterOneStep(true, true);
    // Two static neighbours make no row: fewer pairs than the crowd of moving boxes, still hundreds.
    expect(dense.length).toBeGreaterThan(300);
    expect(new Set(dense).size).toBe(dense.length);
    expect(hashed).toEqual(dense);
  });
});
