import {
  addBody,
  createPhysicsWorld,
  disposeWorld,
  enableMutualGravity,
  enableThreads,
  type PhysicsWorld,
  Rng,
  setGravitation,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { afterEach, expect, test } from 'vitest';
import { BARNES_HUT_MIN_PER_THREAD } from '../../packages/physics/src/forces/barnes-hut/tree.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

/**
 * The Barnes-Hut build and walk pinned to the bit: a 2D and a 3D world of bodies in mutual gravity,
 * stepped on 1 and 2 threads, must reach the state hashes the engine reached when these were
 * recorded (commit 6266fbf, before the 2D and 3D kernels were written as one). The scenes use only
 * +, -, *, / and sqrt (Rng.range, the field's arithmetic), which IEEE 754 rounds the same on every
 * machine, so the hashes do not depend on the platform. A change to the tree's arithmetic or its
 * summation order changes them: such a change must say so and record the new hashes.
 */

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

/**
 * n bodies of mass 0.5 .. 1.5 kg, 70% uniform in a cube (2D: square) of side 40 m and 30% in 6
 * clumps of side 2 m, so the walk meets far cells, near cells and dense leaves; at rest, G = 1,
 * softening 0.1 m, theta = 0.7.
 */
function world(dims: 2 | 3, threads: number, n: number): PhysicsWorld {
  const w = createPhysicsWorld({ dimensions: dims, capacity: n, gravity: dims === 3 ? [0, 0, 0] : [0, 0], threads });
  if (w.threadPool !== null) w.threadPool.adaptive = false;
  worlds.push(w);
  setGravitation(w, { constant: 1, softening: 0.1, method: 'barnes-hut', openingAngle: 0.7 });
  const rng = new Rng(31 + dims);
  const clumps: number[][] = [];
  for (let c = 0; c < 6; c++) clumps.push([rng.range(-20, 20), rng.range(-20, 20), rng.range(-20, 20)]);
  for (let i = 0; i < n; i++) {
    const c = i % 10 < 7 ? null : clumps[i % 6]!;
    const half = c === null ? 20 : 1;
    const p = [0, 1, 2].map((k) => (c === null ? 0 : c[k]!) + rng.range(-half, half));
    const e = addBody(w, { position: dims === 3 ? p : [p[0]!, p[1]!], mass: rng.range(0.5, 1.5) });
    enableMutualGravity(w, e);
  }
  return w;
}

const n = 2 * BARNES_HUT_MIN_PER_THREAD + 300;

test.each([
  [2, 1],
  [2, 2],
  [3, 1],
  [3, 2],
] as const)(
  '%iD on %i thread(s): the recorded state hash after 3 steps',
  (dims, threads) => {
    const w = world(dims, threads, n);
    stepMany(w, 3);
    if (threads > 1) expect(w.threadPool!.runs, 'the workers ran').toBeGreaterThan(0);
    expect(stateHash(w)).toBe(dims === 2 ? 'ec60fb20b5894d55' : '7e862dac47af6825');
  },
  60_000,
);
