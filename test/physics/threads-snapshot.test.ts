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

test('a worker that dies costs no error: the run finishes on the calling thread, the worker is replaced, the world steps on with the same state', async () => {
  // In a child process (its workers are killed). Before, the run after a worker died threw (and before
  // that blocked forever); a dead worker never claims its range, so the calling thread runs it.
  const dir = mkdtempSync(join(tmpdir(), 'bitphysics-dead-worker-'));
  const src = resolve(__dirname, '../../packages/physics/src');
  const entry = join(dir, 'run.ts');
  writeFileSync(
    entry,
    `
import { addParticle, createPhysicsWorld, enableThreads, stateHash, stepMany } from '@bitphysics/physics';
import { testKernel } from '${src}/step/kernel-table.ts';
import { sharedFloat64 } from '${src}/threads/pool.ts';
import { CONTROL } from '${src}/threads/worker-main.ts';
enableThreads();
const results: unknown[] = [];
const pause = (ms: number) => Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, ms);
function timed(f: () => unknown) {
  const t0 = Date.now();
  try { return { ok: true, ms: Date.now() - t0, value: f() }; }
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
  out.fill(-1);
  results.push({ ...timed(() => run(pool, out)), last: out[999], disposed: pool.isDisposed, stats: pool.stats() });
}
// 2. The same, with the exit event seen before the next run (a game loop between frames): the worker
// is replaced, and the new one takes work (a started kernel it claims before the join).
{
  const world = createPhysicsWorld({ capacity: 10, threads: 2 });
  const pool: any = world.threadPool;
  pool.usable();
  const out = sharedFloat64(1000);
  run(pool, out);
  await pool.workers[0].terminate();
  await new Promise((r) => setTimeout(r, 50));
  out.fill(-1);
  results.push({ ...timed(() => run(pool, out)), last: out[999], stats: pool.stats() });
  const before = pool.stats().rangesTakenOver;
  const ctl: Int32Array = pool.ctl;
  // The new worker has started (it takes the commands opened after it joined the control buffer).
  for (let k = 0; k < 2000 && Atomics.load(ctl, CONTROL.READY) < 2; k++) pause(5);
  pool.start('testSystem', testKernel, [out], [3, -1], 1000);
  const gen = Atomics.load(ctl, CONTROL.GEN);
  for (let k = 0; k < 2000 && Atomics.load(ctl, CONTROL.CLAIM + 1) === gen; k++) pause(5);
  results.push({ joined: pool.join(), last: out[999], takenOver: pool.stats().rangesTakenOver - before });
}
// 3. A world whose step runs its loops on the pool, against the same world on one thread.
{
  const n = 2 * 8192 + 1000;
  const make = (threads: number) => {
    const world = createPhysicsWorld({ capacity: n, threads, interpolation: false });
    if (world.threadPool !== null) (world.threadPool as any).adaptive = false;
    for (let i = 0; i < n; i++) addParticle(world, { position: [i, 0], velocity: [1 + (i % 7), 0] });
    return world;
  };
  const world = make(2),
    alone = make(1);
  stepMany(world, 2);
  stepMany(alone, 2);
  (world.threadPool as any).workers[0].terminate();
  pause(200);
  results.push(timed(() => stepMany(world, 1)));
  await new Promise((r) => setTimeout(r, 50)); // the exit event: the worker is replaced at the next run
  results.push(timed(() => stepMany(world, 3)));
  stepMany(alone, 4);
  results.push({ same: stateHash(world) === stateHash(alone), stats: world.threadPool!.stats(), disposed: world.threadPool!.isDisposed });
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
  type Stats = { rangesTakenOver: number; workersReplaced: number; lastWorkerEvent: string | null };
  const [killed, seen, started, stepDied, stepAfter, world] = JSON.parse(stdout.trim()) as Array<{
    ok?: boolean;
    ms?: number;
    value?: number;
    last?: number;
    disposed?: boolean;
    stats?: Stats;
    joined?: number;
    takenOver?: number;
    same?: boolean;
  }>;
  const sum = (999 * 1000) / 2;
  // 1. The run returns its full result at once; the dead worker's range ran on the calling thread.
  expect(killed!.ok).toBe(true);
  expect(killed!.value).toBe(sum);
  expect(killed!.last).toBe(1998);
  expect(killed!.ms).toBeLessThan(3000);
  expect(killed!.disposed).toBe(false);
  expect(killed!.stats!.rangesTakenOver).toBeGreaterThanOrEqual(1);
  // 2. The exit event seen: the worker is replaced, the run is whole, and the new worker serves the pool.
  expect(seen!.ok).toBe(true);
  expect(seen!.value).toBe(sum);
  expect(seen!.last).toBe(1998);
  expect(seen!.stats!.workersReplaced).toBe(1);
  expect(seen!.stats!.lastWorkerEvent).toMatch(/^worker thread 1 exited \(code \d+\); replaced$/);
  expect(started!.joined).toBe(sum);
  expect(started!.last).toBe(2997);
  expect(started!.takenOver).toBe(0);
  // 3. The world steps on, on its pool, to the state of a one-thread world.
  expect(stepDied!.ok).toBe(true);
  expect(stepAfter!.ok).toBe(true);
  expect(world!.same).toBe(true);
  expect(world!.disposed).toBe(false);
  expect(world!.stats!.workersReplaced).toBe(1);
}, 60_000);
