import { execFile } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { promisify } from 'node:util';
import {
  addBody,
  addParticle,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  MIN_PARALLEL_PER_THREAD,
  type PhysicsWorld,
  restore,
  setBoundary,
  snapshot,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { build } from 'esbuild';
import { afterEach, expect, test } from 'vitest';
import { Rng } from '../../packages/physics/src/math/rng.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// The reference for snapshots across thread counts is the world the snapshot was taken from: the
// engine runs each body's arithmetic the same on any thread count (threads.test.ts), so a restored
// world must step to the same state to the last bit whatever its own thread count (tolerance zero).

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

/** Enough particles that 4 threads take the parallel loops. */
const N = 4 * MIN_PARALLEL_PER_THREAD + 1001;
const CAPACITY = N + 64;

/** A bare world of `threads` threads whose pool (if any) runs every long loop on its threads. */
function bare(threads: number): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, capacity: CAPACITY, gravity: [0.3, -9.81], threads });
  worlds.push(world);
  if (world.threadPool !== null) world.threadPool.adaptive = false;
  return world;
}

/** Particles in free flight and a few balls colliding in a box. */
function scene(threads: number): PhysicsWorld {
  const world = bare(threads);
  const rng = new Rng(11);
  for (let i = 0; i < N; i++) {
    addParticle(world, { position: [rng.range(-50, 50), rng.range(0, 100)], velocity: [rng.range(-5, 5), rng.range(-5, 5)] });
  }
  setBoundary(world, { min: [-5, 0], max: [5, 10] });
  for (let i = 0; i < 30; i++) addBody(world, { position: [-4 + (i % 8), 1 + Math.floor(i / 8)], radius: 0.4, velocity: [(i % 3) - 1, 0] });
  return world;
}

test('a snapshot of a world of 4 threads restores into worlds of 1 and 2 threads, one of 1 thread into 4: each keeps its pool, all step alike', () => {
  for (const [from, targets] of [
    [4, [1, 2]],
    [1, [4]],
  ] as const) {
    const original = scene(from);
    stepMany(original, 5);
    const saved = snapshot(original);
    stepMany(original, 10);
    const expected = stateHash(original);
    for (const to of targets) {
      const copy = bare(to);
      const pool = copy.threadPool;
      restore(copy, saved);
      // The world's own pool and thread count stay (they are not state).
      expect(copy.threadPool).toBe(pool);
      expect(copy.threads).toBe(to);
      const runs = pool?.runs ?? 0;
      stepMany(copy, 10);
      expect(stateHash(copy)).toBe(expected);
      if (pool !== null) {
        expect(pool.runs).toBeGreaterThan(runs); // its workers did the parallel loops
        disposeWorld(copy);
        expect(pool.isDisposed).toBe(true); // and disposeWorld still ends them
      }
    }
  }
}, 60_000);

test('a worker that dies gives a clear error within a second, the pool is shut down and the world steps on alone', async () => {
  // In a child process: before the fix, the run after a worker died blocked forever.
  const dir = mkdtempSync(join(tmpdir(), 'bitphysics-dead-worker-'));
  const src = resolve(__dirname, '../../packages/physics/src');
  const entry = join(dir, 'run.ts');
  writeFileSync(
    entry,
    `
import { addParticle, createPhysicsWorld, enableThreads, stepMany } from '@bitphysics/physics';
import { testKernel } from '${src}/step/kernel-table.ts';
import { sharedFloat64 } from '${src}/threads/pool.ts';
enableThreads();
const results: unknown[] = [];
const pause = (ms: number) => Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, ms);
function timed(f: () => unknown) {
  const t0 = Date.now();
  try { f(); return { ok: true, ms: Date.now() - t0 }; }
  catch (e) { return { ok: false, ms: Date.now() - t0, message: (e as Error).message }; }
}
const run = (pool: any, out: Float64Array) => pool.run('testSystem', testKernel, [out], [2, -1], 1000, null);
// 1. A worker killed between two runs, with no turn of the event loop in between (its exit event unseen).
{
  const world = createPhysicsWorld({ capacity: 10, threads: 2 });
  const pool: any = world.threadPool;
  pool.usable();
  const out = sharedFloat64(1000);
  run(pool, out);
  pool.workers[0].terminate();
  pause(200); // the thread has surely stopped
  results.push(timed(() => run(pool, out)));
  results.push({ disposed: pool.isDisposed });
}
// 2. The same, with the exit event seen before the next run (a game loop between frames).
{
  const world = createPhysicsWorld({ capacity: 10, threads: 2 });
  const pool: any = world.threadPool;
  pool.usable();
  const out = sharedFloat64(1000);
  run(pool, out);
  await pool.workers[0].terminate();
  await new Promise((r) => setTimeout(r, 50));
  results.push(timed(() => run(pool, out)));
}
// 3. A world whose step runs its loops on the pool.
{
  const n = 2 * 8192 + 1000;
  const world = createPhysicsWorld({ capacity: n, threads: 2, interpolation: false });
  (world.threadPool as any).adaptive = false;
  for (let i = 0; i < n; i++) addParticle(world, { position: [i, 0], velocity: [1, 0] });
  stepMany(world, 2);
  (world.threadPool as any).workers[0].terminate();
  pause(200);
  results.push(timed(() => stepMany(world, 1)));
  results.push(timed(() => stepMany(world, 3))); // on the calling thread alone
}
console.log(JSON.stringify(results));
`,
  );
  const out = join(dir, 'run.mjs');
  await build({
    entryPoints: [entry],
    outfile: out,
    bundle: true,
    // As the package ships: its layout constants folded into the kernels' text (scripts/build.mjs).
    minifySyntax: true,
    platform: 'node',
    format: 'esm',
    logLevel: 'silent',
    conditions: ['bitphysics-source'],
    nodePaths: [join(__dirname, '../../node_modules')],
  });
  // A run that blocks forever hits the timeout (execFile then rejects).
  const { stdout } = await promisify(execFile)(process.execPath, [out], { timeout: 30_000 });
  const [idle, disposed, seen, stepDied, stepAlone] = JSON.parse(stdout.trim()) as Array<{
    ok?: boolean;
    ms?: number;
    message?: string;
    disposed?: boolean;
  }>;
  const shutDown = '; the thread pool is shut down and the world steps on the calling thread alone from now on';
  expect(idle!.ok).toBe(false);
  expect(idle!.message).toBe(`testSystem: worker thread 1 died (it did not take the command within 2000 ms)${shutDown}`);
  expect(idle!.ms).toBeLessThan(3000);
  expect(disposed!.disposed).toBe(true);
  expect(seen!.ok).toBe(false);
  expect(seen!.message).toMatch(/^testSystem: worker thread 1 exited \(code \d+\); the thread pool is shut down/);
  expect(seen!.ms).toBeLessThan(100);
  expect(stepDied!.ok).toBe(false);
  expect(stepDied!.message).toMatch(
    /^.+: worker thread 1 died \(it did not take the command within 2000 ms\); the thread pool is shut down/,
  );
  expect(stepDied!.ms).toBeLessThan(3000);
  expect(stepAlone!.ok).toBe(true);
}, 60_000);
