import { createPhysicsWorld, enableThreads, type PhysicsWorld, SCENES, stateHash, step, stepMany } from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { stageThreading } from '../../packages/physics/src/solver/stages-threads.js';
import { warmStartTable } from '../../packages/physics/src/solver/warm-start-kernel.js';
import { threadTestWorlds } from './thread-worlds';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// The contact solver's stages beside the coloured substeps on the world's threads
// (solver/stages-threads.ts): the solver rows' fill, measureApproach and finishBodies do each
// body's or row's one-thread arithmetic, so the state must equal threads: 1 to the bit (stateHash,
// tolerance zero); the restitution stage after a coloured solve goes colour by colour (on one thread
// too), so its state must be the same on 2 threads run twice, on 3 threads and on an adaptive pool (tolerance zero), and,
// checked against the conservation law rather than another run, a pile falling from rest never holds
// more mechanical energy than it started with (tolerance 1e-9 of it: rounding).

const worlds = threadTestWorlds();

const scene = SCENES['balls-in-box']!;

/** balls-in-box with `count` balls; `colored`: the coloured solve from the first contact, else never. */
function pile(count: number, threads: number, colored: boolean, adaptive = false): PhysicsWorld {
  const world = createPhysicsWorld({ ...scene.worldOptions({ count }), seed: 1, ...(threads > 1 ? { threads } : {}) });
  worlds.push(world);
  if (world.threadPool !== null) world.threadPool.adaptive = adaptive;
  world.collision.settings.coloredSolveMinRows = colored ? 0 : Infinity;
  scene.build(world, { count });
  return world;
}

/** Kinetic (translation and spin) plus potential energy of balls 1 .. count, J. */
function energy(world: PhysicsWorld, count: number): number {
  const c = world.components,
    g = -world.gravity[1]!;
  let e = 0;
  for (let i = 1; i <= count; i++) {
    const m = 1 / c.Mass.inv[i]!,
      inv = c.Inertia.inv[i]!;
    e += 0.5 * m * (c.Velocity.x[i]! ** 2 + c.Velocity.y[i]! ** 2) + m * g * c.Position.y[i]!;
    if (inv > 0) e += (0.5 * c.AngularVelocity.z[i]! ** 2) / inv;
  }
  return e;
}

test('solver rows, approach speeds, write-back and the warm-start table on 2 threads (coloured solve off): the one-thread state to the bit', () => {
  stageThreading.minPerThread = 1;
  const count = 300,
    steps = 80;
  const one = pile(count, 1, false);
  stepMany(one, steps);
  const runs = stageThreading.runs;
  const two = pile(count, 2, false);
  // Count the warm-start tables a worker builds (ThreadPool.start).
  const pool = two.threadPool!,
    start = pool.start.bind(pool);
  let tables = 0;
  pool.start = (system, kernel, arrays, params, n) => {
    if (kernel === warmStartTable) tables++;
    start(system, kernel, arrays, params, n);
  };
  stepMany(two, steps);
  // Fill, approach, write-back and the warm-start table each step with contacts: most of the 80.
  expect(stageThreading.runs - runs).toBeGreaterThan(4 * 40);
  expect(tables).toBeGreaterThan(40);
  expect(stateHash(two)).toBe(stateHash(one));
  // The table a worker built while the step finished is storeWarmStart's, slot by slot.
  expect(two.collision.cache.size).toBe(one.collision.cache.size);
  expect(Array.from(two.collision.cache.slots)).toEqual(Array.from(one.collision.cache.slots));
  // The deepest overlap left (not in the hash) is the one-thread value too.
  expect(two.collision.stats.maxOverlap).toBe(one.collision.stats.maxOverlap);
  expect(one.collision.stats.maxOverlap).toBeGreaterThan(0);
});

test('restitution by colours: one state on 2 threads run twice, on 3 threads and on an adaptive pool; the pile never gains energy', () => {
  stageThreading.minPerThread = 1;
  const count = 300,
    steps = 80;
  const run = (threads: number, adaptive: boolean): string => {
    const world = pile(count, threads, true, adaptive);
    const e0 = energy(world, count);
    let worst = -Infinity;
    for (let s = 0; s < steps; s++) {
      step(world);
      worst = Math.max(worst, energy(world, count) - e0);
    }
    expect(worst).toBeLessThan(1e-9 * Math.abs(e0));
    return stateHash(world);
  };
  const bouncing = stageThreading.bouncing,
    runs = stageThreading.runs;
  const a = run(2, false);
  // The stage ran by colours and found rows to bounce (it is not skipped).
  expect(stageThreading.runs).toBeGreaterThan(runs);
  expect(stageThreading.bouncing).toBeGreaterThan(bouncing);
  expect(run(2, false)).toBe(a);
  expect(run(3, false)).toBe(a);
  expect(run(2, true)).toBe(a);
});
