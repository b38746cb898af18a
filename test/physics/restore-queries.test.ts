import {
  addBody,
  addBox,
  addShape3D,
  createPhysicsWorld,
  overlapAABB,
  overlapAABB3D,
  overlapPoint,
  overlapPoint3D,
  type PhysicsWorld,
  rayCastAll,
  rayCastAll3D,
  restore,
  setBoundary,
  snapshot,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { Rng } from '../../packages/physics/src/math/rng.js';

// A query made right after `restore`, before any step, must see the restored world: the same answers,
// to the bit, as the same queries made on the world when the snapshot was taken. Between the two the
// world is stepped on (so its broadphase grids and contact stores hold a later state, which restore
// must not let through). The reference is the world itself at snapshot time (tolerance zero).

/** Every query's answers at a fixed set of probes, as one string. */
function answers2D(world: PhysicsWorld): string {
  const out: unknown[] = [];
  for (let i = 0; i < 12; i++) {
    const x = -4 + (8 * i) / 11;
    out.push(rayCastAll(world, [x, 12], [0.3, -13]));
    out.push(overlapPoint(world, [x, 0.6]));
    out.push(overlapAABB(world, [x - 0.5, 0], [x + 0.5, 2]));
  }
  return JSON.stringify(out);
}

function answers3D(world: PhysicsWorld): string {
  const out: unknown[] = [];
  for (let i = 0; i < 12; i++) {
    const x = -3 + (6 * i) / 11;
    out.push(rayCastAll3D(world, [x, 10, 0.1], [0.2, -11, 0.1]));
    out.push(overlapPoint3D(world, [x, 0.4, 0]));
    out.push(overlapAABB3D(world, [x - 0.5, 0, -0.5], [x + 0.5, 2, 0.5]));
  }
  return JSON.stringify(out);
}

test('2D boxes and balls: queries right after restore answer as the world did at the snapshot', () => {
  const world = createPhysicsWorld({ dimensions: 2, capacity: 200 });
  setBoundary(world, { min: [-5, 0], max: [5, 20] });
  const rng = new Rng(5);
  for (let i = 0; i < 40; i++)
    addBox(world, { position: [rng.range(-4, 4), 1 + 0.6 * i], halfExtents: [0.25, 0.2], angle: rng.range(0, 3) });
  for (let i = 0; i < 30; i++) addBody(world, { position: [rng.range(-4, 4), 2 + 0.5 * i], radius: 0.2 });
  stepMany(world, 60);
  const snap = snapshot(world);
  const then = answers2D(world);
  const hash = stateHash(world);
  stepMany(world, 90);
  expect(answers2D(world)).not.toBe(then); // the pile moved on: the check below can fail
  restore(world, snap);
  expect(answers2D(world)).toBe(then);
  expect(stateHash(world)).toBe(hash);
});

test('3D boxes and spheres: queries right after restore answer as the world did at the snapshot', () => {
  const world = createPhysicsWorld({ dimensions: 3, capacity: 200 });
  setBoundary(world, { min: [-4, 0, -2], max: [4, 20, 2] });
  const rng = new Rng(9);
  for (let i = 0; i < 30; i++) {
    const b = addBody(world, { position: [rng.range(-3, 3), 1 + 0.7 * i, rng.range(-1, 1)], mass: 1 });
    addShape3D(world, b, i % 2 ? { type: 'box', halfExtents: [0.3, 0.2, 0.3] } : { type: 'sphere', radius: 0.3 });
  }
  stepMany(world, 60);
  const snap = snapshot(world);
  const then = answers3D(world);
  const hash = stateHash(world);
  stepMany(world, 90);
  expect(answers3D(world)).not.toBe(then);
  restore(world, snap);
  expect(answers3D(world)).toBe(then);
  expect(stateHash(world)).toBe(hash);
});
