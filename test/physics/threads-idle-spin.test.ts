import {
  addBody,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  type PhysicsWorld,
  setBoundary,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { afterEach, expect, test } from 'vitest';
import { Rng } from '../../packages/physics/src/math/rng.js';
import { IDLE_SPIN_MICROSECONDS } from '../../packages/physics/src/threads/pool.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// An idle worker watches for the next run for `idleSpin` microseconds before it blocks (threads/pool.ts,
// worker-main.ts). The promises: the spin changes no result (stateHash, every bit), it is bounded (an
// idle pool stops using CPU), and bad values are refused.

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

/**
 * 20,000 balls in a box: enough that the integration and collision loops run on both threads (a loop
 * goes to the pool from 2 x MIN_PARALLEL_PER_THREAD = 16,384 entities, threads/parallel.ts).
 */
function balls(spin: number): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, capacity: 20_000, gravity: [0, -10], threads: 2 });
  worlds.push(world);
  world.threadPool!.adaptive = false;
  world.threadPool!.idleSpin = spin;
  setBoundary(world, { min: [0, 0], max: [200, 200] });
  const rng = new Rng(3);
  for (let i = 0; i < 20_000; i++)
    addBody(world, { position: [rng.range(1, 199), rng.range(1, 199)], radius: 0.4, velocity: [rng.range(-2, 2), 0] });
  return world;
}

test('the idle spin changes no result: 0, the default and 0.1 s give the same state', () => {
  const hashes = [0, IDLE_SPIN_MICROSECONDS, 100_000].map((spin) => {
    const world = balls(spin);
    stepMany(world, 10);
    expect(world.threadPool!.runs).toBeGreaterThan(10);
    return stateHash(world);
  });
  expect(hashes[1]).toBe(hashes[0]);
  expect(hashes[2]).toBe(hashes[0]);
}, 60_000);

test('an idle pool stops spinning: under 0.1 s of CPU in one of two 0.3 s windows after a spin of 20 ms', async () => {
  const world = balls(20_000);
  stepMany(world, 2);
  // The spin ends 20 ms after the last run; the wait also lets the process's own after-work settle
  // (V8 compiling the step's code and collecting the world's build on its background threads), which
  // process.cpuUsage counts with the workers.
  await new Promise((r) => setTimeout(r, 400));
  const used: number[] = [];
  for (let window = 0; window < 2; window++) {
    const before = process.cpuUsage();
    await new Promise((r) => setTimeout(r, 300));
    const u = process.cpuUsage(before);
    used.push((u.user + u.system) / 1e6);
  }
  // A spinning worker uses up to 0.3 s a window (a whole core; a 1 s spin used 0.15 and 0.22 here), and
  // one that ignored the 20 ms and spun for the longest spin allowed (1 s) would still be spinning in
  // both windows (0.4 to 1.0 s after the run); an idle process uses little, and a passing background
  // job spoils one window, not both.
  expect(Math.min(...used), `CPU seconds in each window: ${used.join(', ')}`).toBeLessThan(0.1);
}, 60_000);

test('idleSpin refuses what is not an integer in [0, 1e6] microseconds, and keeps its value', () => {
  const world = balls(0);
  const pool = world.threadPool!;
  for (const bad of [-1, 1.5, 2e6, Number.NaN]) {
    expect(() => {
      pool.idleSpin = bad;
    }).toThrow(`ThreadPool.idleSpin: microseconds must be an integer in [0, 1e6], got ${bad}`);
  }
  expect(pool.idleSpin).toBe(0);
  pool.idleSpin = 250;
  expect(pool.idleSpin).toBe(250);
});
