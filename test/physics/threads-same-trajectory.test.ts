import {
  addBody,
  addDistanceJoint,
  createPhysicsWorld,
  enableThreads,
  type PhysicsWorld,
  SCENES,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { CONTACTS_MIN_PER_THREAD } from '../../packages/physics/src/collision/narrowphase/balls-threads.js';
import { Rng } from '../../packages/physics/src/math/rng.js';
import { lastColorCount } from '../../packages/physics/src/solver/coloring.js';
import { stageThreading } from '../../packages/physics/src/solver/stages-threads.js';
import { threadTestWorlds } from './thread-worlds';

// One trajectory on any thread count (issue 32): every stage's order is the same with `threads: 1` and
// `threads: n`, so stateHash (every bit of every body) after a run must be equal on 1, 2, 3 and 4
// threads, with tolerance zero. The reference is the one-thread world, which runs every stage's kernel
// inline; a threaded world must reproduce it whichever way its pool splits the work. The thresholds
// that keep small worlds on one thread are lowered so these small scenes take the threaded paths: the
// solver stages (stageThreading.minPerThread) and the 2D coloured solve (coloredSolveMinRows) from the
// first row. Each threaded count runs twice: with a fixed pool (every stage on the threads) and an
// adaptive one (threads/adaptive.ts: one thread or the threads by timing, so which stages run where
// varies from run to run); the state must not depend on that choice either.

enableThreads();

const worlds = threadTestWorlds();

/** `scene` with `count` bodies on `threads` threads, stepped `steps` times; its state hash. */
function run(scene: string, count: number, steps: number, threads: number, adaptive: boolean): { hash: string; world: PhysicsWorld } {
  const sc = SCENES[scene]!;
  const world = createPhysicsWorld({ ...sc.worldOptions({ count }), seed: 1, ...(threads > 1 ? { threads } : {}) });
  worlds.push(world);
  if (world.threadPool !== null) world.threadPool.adaptive = adaptive;
  world.collision.settings.coloredSolveMinRows = 0;
  sc.build(world, { count });
  stepMany(world, steps);
  return { hash: stateHash(world), world };
}

/** Expects the same state hash on 1, 2, 3 and 4 threads (fixed and adaptive pools); returns the one-thread world. */
function sameOnEveryCount(scene: string, count: number, steps: number): PhysicsWorld {
  stageThreading.minPerThread = 1;
  const one = run(scene, count, steps, 1, false);
  for (const threads of [2, 3, 4]) {
    expect(run(scene, count, steps, threads, false).hash, `${scene} on ${threads} threads`).toBe(one.hash);
    expect(run(scene, count, steps, threads, true).hash, `${scene} on ${threads} threads, adaptive`).toBe(one.hash);
  }
  return one.world;
}

test('balls-in-box (2D, coloured solve): the same state on 1, 2, 3 and 4 threads', () => {
  const before = stageThreading.runs;
  const world = sameOnEveryCount('balls-in-box', 800, 70);
  // The one-thread world solved by colours too (the threshold is 0), and the stages' kernels ran.
  expect(lastColorCount(world)).toBeGreaterThan(1);
  expect(stageThreading.runs).toBeGreaterThan(before);
}, 120_000);

test('pyramid (2D boxes): the same state on 1, 2, 3 and 4 threads', () => {
  sameOnEveryCount('pyramid', 12, 80);
}, 120_000);

test('box-pile-3d (3D boxes): the same state on 1, 2, 3 and 4 threads', () => {
  sameOnEveryCount('box-pile-3d', 200, 60);
}, 120_000);

test('joint-grid (2D joints): the same state on 1, 2, 3 and 4 threads', () => {
  sameOnEveryCount('joint-grid', 12, 60);
}, 120_000);

test('spheres-in-box (3D balls): the same state on 1, 2, 3 and 4 threads', () => {
  sameOnEveryCount('spheres-in-box', 600, 60);
}, 120_000);

test('a lattice of balls, some pairs joined by joints that keep them apart: the same state on 1, 2 and 3 threads', () => {
  // 70 x 64 balls 0.02 diameters apart with small random velocities (past CONTACTS_MIN_PER_THREAD
  // ball pairs a thread, so the narrowphase's kernel runs on the threads), every 7th ball joined to its
  // right neighbour by a slack distance joint without collideConnected: their pairs must make no
  // contact on the threads either (the kernel's skip flags), so the state matches one thread exactly.
  const run = (threads: number): { hash: string; pairs: number } => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 70 * 64 + 1000, gravity: [0, -1], ...(threads > 1 ? { threads } : {}) });
    worlds.push(world);
    if (world.threadPool !== null) world.threadPool.adaptive = false;
    const rng = new Rng(7);
    const ids: number[] = [];
    for (let j = 0; j < 64; j++) {
      for (let i = 0; i < 70; i++)
        ids.push(addBody(world, { position: [1.02 * i, 1.02 * j], velocity: [rng.range(-0.3, 0.3), rng.range(-0.3, 0.3)], radius: 0.5 }));
    }
    for (let k = 0; k + 1 < ids.length; k += 7) {
      if (k % 70 === 69) continue;
      addDistanceJoint(world, { a: ids[k]!, b: ids[k + 1]!, length: 1.02, minLength: 0, maxLength: 3 });
    }
    stepMany(world, 20);
    return { hash: stateHash(world), pairs: world.collision.pairCount };
  };
  const one = run(1);
  expect(one.pairs).toBeGreaterThan(3 * CONTACTS_MIN_PER_THREAD);
  expect(run(2).hash).toBe(one.hash);
  expect(run(3).hash).toBe(one.hash);
}, 120_000);

test('a one-thread world without SharedArrayBuffer (a page that is not cross-origin isolated) solves by colours to the same state', () => {
  const g = globalThis as { SharedArrayBuffer?: unknown };
  const saved = g.SharedArrayBuffer;
  const make = (): PhysicsWorld => {
    const sc = SCENES['balls-in-box']!;
    const world = createPhysicsWorld({ ...sc.worldOptions({ count: 400 }), seed: 1 });
    worlds.push(world);
    world.collision.settings.coloredSolveMinRows = 0;
    sc.build(world, { count: 400 });
    return world;
  };
  const withShared = make();
  stepMany(withShared, 60);
  let hash: string;
  try {
    g.SharedArrayBuffer = undefined;
    const without = make();
    stepMany(without, 60);
    hash = stateHash(without);
    expect(lastColorCount(without)).toBeGreaterThan(1);
  } finally {
    g.SharedArrayBuffer = saved;
  }
  expect(hash).toBe(stateHash(withShared));
}, 60_000);
