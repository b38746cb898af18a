import { createPhysicsWorld, enableThreads, type PhysicsWorld, SCENES, stateHash, stepMany } from '@bitphysics/physics';
import { expect, test } from 'vitest';
import { stageThreading } from '../../packages/physics/src/solver/stages-threads.js';
import { testKernel } from '../../packages/physics/src/step/kernel-table.js';
import { holdWorkerForTests, sharedFloat64, type ThreadPool } from '../../packages/physics/src/threads/pool.js';
import { CONTROL } from '../../packages/physics/src/threads/worker-main.js';
import { threadTestWorlds } from './thread-worlds';

// A late worker (one the system does not schedule for a while) costs time, never an error (issue 32;
// threads/pool.ts): the calling thread runs every range a worker has not claimed when it has finished
// its own, the run returns the result it would have had with every worker on time, and the late
// worker, when it wakes, finds its claim gone and writes nothing. The lateness is made with the pool's
// test hook (holdWorkerForTests): the worker blocks in Atomics.wait before it claims, until let go.
// The references are independent: the kernel's values in closed form, and the same world stepped with
// every worker on time and on one thread (threads-same-trajectory.test.ts: one state on any count).

enableThreads();

const worlds = threadTestWorlds();

const pause = (ms: number): void => {
  Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 0, ms);
};

/** Waits (at most 20 s, then the assertion after it fails) until `pool` has counted more than `before` stale wake-ups. */
function awaitStale(pool: ThreadPool, before: number): void {
  for (let k = 0; k < 4000 && pool.stats().staleWakeUps <= before; k++) pause(5);
}

/**
 * Checks that the workers of `pool` serve commands: a kernel started on worker 1 (testKernel over 1,000
 * elements, out[i] = 5 i; the other workers' ranges empty) is claimed by the workers themselves (the
 * test waits for the claims before joining), so the calling thread takes nothing over.
 */
function expectWorkerServes(pool: ThreadPool): void {
  const ctl = (pool as unknown as { ctl: Int32Array }).ctl;
  // A worker started after a command was opened takes the next one, so the command waits until every
  // worker has started: READY counts the workers' starts, the replaced ones' included (it is never
  // lowered), so with a replacement it must reach threads - 1 + workersReplaced (with threads - 1 the
  // wait ended at once, and a replacement that started after the command left its range to the
  // calling thread). The waits are bounded at 60 s.
  const started = pool.threads - 1 + pool.stats().workersReplaced;
  for (let k = 0; k < 12000 && Atomics.load(ctl, CONTROL.READY) < started; k++) pause(5);
  const out = sharedFloat64(1000);
  const before = pool.stats().rangesTakenOver;
  pool.start('testSystem', testKernel, [out], [5, -1], 1000);
  const gen = Atomics.load(ctl, CONTROL.GEN);
  // Every worker claims its range (the others' are empty) before the join.
  for (let i = 1; i < pool.threads; i++) for (let k = 0; k < 12000 && Atomics.load(ctl, CONTROL.CLAIM + i) === gen; k++) pause(5);
  expect(pool.join()).toBe((999 * 1000) / 2);
  expect(out[999]).toBe(4995);
  expect(pool.stats().rangesTakenOver - before).toBe(0);
}

test('a held worker: the run returns the whole result; the late wake-up writes nothing into that run or a later one', () => {
  const world = createPhysicsWorld({ capacity: 10, threads: 2 });
  worlds.push(world);
  const pool = world.threadPool!;
  expect(pool.usable()).toBe(true);
  const a = sharedFloat64(1000),
    b = sharedFloat64(1000);
  // Both arrays reach the worker first, so the held worker lacks nothing when it wakes.
  pool.run('testSystem', testKernel, [a], [1, -1], 1000, null);
  pool.run('testSystem', testKernel, [b], [1, -1], 1000, null);
  const stale = pool.stats().staleWakeUps,
    taken = pool.stats().rangesTakenOver;
  holdWorkerForTests(pool, 1, true);
  // Two runs while the worker is held: each returns the sum of 0..999 and writes every element (the
  // worker's half by the calling thread).
  expect(pool.run('testSystem', testKernel, [a], [2, -1], 1000, null)).toBe((999 * 1000) / 2);
  for (let i = 0; i < 1000; i++) expect(a[i]).toBe(2 * i);
  expect(pool.run('testSystem', testKernel, [b], [3, -1], 1000, null)).toBe((999 * 1000) / 2);
  for (let i = 0; i < 1000; i++) expect(b[i]).toBe(3 * i);
  expect(pool.stats().rangesTakenOver - taken).toBe(2);
  // The caller moves on and reuses the arrays; then the worker wakes. Had it run either command's range
  // late, a sentinel would be overwritten (2 i or 3 i).
  a.fill(-7);
  b.fill(-9);
  holdWorkerForTests(pool, 1, false);
  awaitStale(pool, stale);
  expect(pool.stats().staleWakeUps).toBeGreaterThan(stale);
  pause(20); // anything the worker were still to write would be written by now
  for (let i = 0; i < 1000; i++) {
    expect(a[i]).toBe(-7);
    expect(b[i]).toBe(-9);
  }
  // The pool uses the worker again.
  expectWorkerServes(pool);
  expect(pool.run('testSystem', testKernel, [a], [2, -1], 1000, null)).toBe((999 * 1000) / 2);
  expect(a[999]).toBe(1998);
  expect(pool.isDisposed).toBe(false);
});

test('a held worker while start left a kernel on it: join runs it on the calling thread, whole', () => {
  const world = createPhysicsWorld({ capacity: 10, threads: 3 });
  worlds.push(world);
  const pool = world.threadPool!;
  expect(pool.usable()).toBe(true);
  const out = sharedFloat64(1000).fill(-1);
  pool.run('testSystem', testKernel, [out], [1, -1], 1000, null);
  holdWorkerForTests(pool, 1, true);
  // The caller reuses its argument list before the join (the solver's stages keep one list a world).
  const args = [out],
    other = sharedFloat64(1000).fill(-1);
  pool.start('testSystem', testKernel, args, [4, -1], 1000);
  args[0] = other;
  expect(pool.join()).toBe((999 * 1000) / 2);
  for (let i = 0; i < 1000; i++) expect(out[i]).toBe(4 * i);
  expect(other[999]).toBe(-1);
  const stale = pool.stats().staleWakeUps;
  out.fill(-3);
  holdWorkerForTests(pool, 1, false);
  awaitStale(pool, stale);
  pause(20);
  for (let i = 0; i < 1000; i++) expect(out[i]).toBe(-3);
  expectWorkerServes(pool);
});

/** balls-in-box with `count` balls, seed 1, on `threads` threads (a fixed pool: every stage on the threads). */
function pile(count: number, threads: number): PhysicsWorld {
  const scene = SCENES['balls-in-box']!;
  const world = createPhysicsWorld({ ...scene.worldOptions({ count }), seed: 1, ...(threads > 1 ? { threads } : {}) });
  worlds.push(world);
  if (world.threadPool !== null) world.threadPool.adaptive = false;
  world.collision.settings.coloredSolveMinRows = 0;
  scene.build(world, { count });
  return world;
}

for (const threads of [2, 3]) {
  test(`${threads} threads: steps with a held worker return the state of steps with every worker on time and of one thread; the wake-up changes nothing`, () => {
    // Every solver stage on the threads from the first row, the coloured solve from the first contact.
    stageThreading.minPerThread = 1;
    const count = 1500;
    const late = pile(count, threads),
      onTime = pile(count, threads),
      one = pile(count, 1);
    for (const w of [late, onTime, one]) stepMany(w, 40);
    const pool = late.threadPool!;
    const held = threads - 1; // with 3 threads, worker 1 stays on time
    const taken = pool.stats().rangesTakenOver,
      stale = pool.stats().staleWakeUps,
      runs = pool.runs;
    holdWorkerForTests(pool, held, true);
    stepMany(late, 3);
    expect(pool.runs).toBeGreaterThan(runs); // the steps ran their loops on the pool
    expect(pool.stats().rangesTakenOver).toBeGreaterThan(taken);
    for (const w of [onTime, one]) stepMany(w, 3);
    const hash = stateHash(late);
    expect(hash).toBe(stateHash(onTime));
    expect(hash).toBe(stateHash(one));
    holdWorkerForTests(pool, held, false);
    awaitStale(pool, stale);
    expect(pool.stats().staleWakeUps).toBeGreaterThan(stale);
    pause(20);
    expect(stateHash(late)).toBe(hash);
    // The pool's workers serve again, and the world steps on to the same state.
    expectWorkerServes(pool);
    const after = pool.runs;
    for (const w of [late, onTime, one]) stepMany(w, 20);
    expect(pool.runs).toBeGreaterThan(after);
    expect(stateHash(late)).toBe(stateHash(onTime));
    expect(stateHash(late)).toBe(stateHash(one));
    expect(pool.isDisposed).toBe(false);
    expect(pool.stats().workersReplaced).toBe(0);
  }, 120_000);
}

test('a worker terminated while it waits to claim: the steps return, it is replaced, the state is that of one thread', async () => {
  stageThreading.minPerThread = 1;
  const count = 1500;
  const world = pile(count, 2),
    one = pile(count, 1);
  stepMany(world, 30);
  stepMany(one, 30);
  const pool = world.threadPool!;
  holdWorkerForTests(pool, 1, true);
  stepMany(world, 2); // the worker blocks at the step's first command
  await (pool as unknown as { workers: Array<{ terminate(): Promise<number> }> }).workers[0]!.terminate();
  stepMany(world, 2); // its exit event not seen yet: its ranges run on the calling thread
  await new Promise((r) => setTimeout(r, 50)); // a turn of the event loop, as between frames: the exit event
  stepMany(world, 20); // replaced before the next command
  stepMany(one, 24);
  expect(stateHash(world)).toBe(stateHash(one));
  const stats = pool.stats();
  expect(stats.workersReplaced).toBe(1);
  expect(stats.lastWorkerEvent).toMatch(/^worker thread 1 exited \(code \d+\); replaced$/);
  expect(pool.isDisposed).toBe(false);
  expectWorkerServes(pool);
}, 180_000);
