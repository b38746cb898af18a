import { createPhysicsWorld, restore, snapshot, stateHash, stepMany, type WorldSnapshot } from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { mixedScene } from './snapshot-scenes.js';

// Reference: the original world itself, stepped on; a snapshot written over an older snapshot's buffer
// (a rollback ring) must restore to a world that steps to the same state bit for bit (tolerance zero).

test('snapshot(world, reuse): a ring of 3 snapshots written over each other restores bit-identically, and a large enough buffer is reused', () => {
  const world = mixedScene();
  stepMany(world, 10);
  const ring: WorldSnapshot[] = [snapshot(world), snapshot(world), snapshot(world)];
  let reused = 0;
  for (let r = 0; r < 9; r++) {
    stepMany(world, 3);
    const old = ring[r % 3]!;
    const oldBuffer = old.buffers[0]!;
    const fits = oldBuffer.byteLength >= snapshot(world).buffers[0]!.byteLength;
    ring[r % 3] = snapshot(world, old);
    if (fits) expect(ring[r % 3]!.buffers[0]).toBe(oldBuffer);
    if (ring[r % 3]!.buffers[0] === oldBuffer) reused++;
  }
  // A reuse that missed allocates room to grow: with 3 steps between reuses, later ones fit.
  expect(reused).toBeGreaterThan(0);
  const latest = ring[8 % 3]!;
  stepMany(world, 1);
  const copy = createPhysicsWorld({ dimensions: world.dimensions, capacity: world.capacity });
  restore(copy, latest);
  restore(world, latest);
  stepMany(world, 50);
  stepMany(copy, 50);
  expect(stateHash(copy)).toBe(stateHash(world));
});
