import {
  addBody,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  type PhysicsWorld,
  SCENES,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { afterEach, expect, test } from 'vitest';
import { Rng } from '../../packages/physics/src/math/rng.js';
import { PREPARE_MIN_PER_THREAD } from '../../packages/physics/src/solver/ball-prepare.js';
import { coloringConflicts, lastColorCount } from '../../packages/physics/src/solver/coloring.js';
import { impactChangedRows } from '../../packages/physics/src/solver/impact-state.js';
import { stripPlan2D } from '../../packages/physics/src/solver/strip-plan-kernel.js';
import { stripCut2D } from '../../packages/physics/src/solver/strips-kernel.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// The 2D ball contacts solved by graph colouring on the world's threads (solver/coloring.ts).
// Rows of one colour share no movable body, so how a colour is split over threads cannot change a
// result: the state must be identical to the bit (stateHash, tolerance zero) run after run, on 2 and 3
// threads, and on an adaptive pool that runs some steps on one thread (threads-same-trajectory.test.ts
// checks 1 thread against 2, 3 and 4). The physical checks: the pile settles (overlap under 2 % of a
// radius, every ball settled below 0.1 m/s) and no ball leaves the box.

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

const scene = SCENES['balls-in-box']!;

/** balls-in-box with `count` balls; threads > 1 solve by colours from the first contact (threshold 0). */
function pile(count: number, threads: number, adaptive: boolean): PhysicsWorld {
  const world = createPhysicsWorld({ ...scene.worldOptions({ count }), seed: 1, ...(threads > 1 ? { threads } : {}) });
  worlds.push(world);
  if (world.threadPool !== null) world.threadPool.adaptive = adaptive;
  world.collision.settings.coloredSolveMinRows = 0;
  scene.build(world, { count });
  return world;
}

test('coloured contact solve: one state on 2 threads run twice, on 3 threads and on an adaptive pool; no movable body twice in a colour', () => {
  const count = 600,
    steps = 90;
  const run = (threads: number, adaptive: boolean): string => {
    const world = pile(count, threads, adaptive);
    stepMany(world, steps);
    const check = coloringConflicts(world);
    expect(check.conflicts).toBe(0);
    expect(check.rows).toBeGreaterThan(count);
    expect(lastColorCount(world)).toBeGreaterThan(1);
    return stateHash(world);
  };
  const a = run(2, false);
  expect(run(2, false)).toBe(a);
  expect(run(3, false)).toBe(a);
  // An adaptive pool runs the kernel on one thread at some calls (threads/adaptive.ts): same bits.
  expect(run(2, true)).toBe(a);
});

test("a threaded 2D pile plans and packs its strips on a worker beside the impact stage (the solver bodies' list on shared memory)", () => {
  const world = pile(600, 2, false);
  const pool = world.threadPool!,
    start = pool.start.bind(pool);
  let plans = 0;
  pool.start = (system, kernel, arrays, params, n) => {
    if (kernel === stripPlan2D) plans++;
    start(system, kernel, arrays, params, n);
  };
  stepMany(world, 90);
  // Every step that solved by colours (most of the 90) planned on the worker; none cut there before
  // stop 28, as the list of solver bodies the cut reads was never on shared memory.
  expect(world.collision.solverBodies.buffer instanceof SharedArrayBuffer).toBe(true);
  expect(plans).toBeGreaterThan(45);
});

test('coloured contact solve: a pile of 800 balls settles as on one thread (overlap < 2 % of a radius, every ball slower than 0.1 m/s) and stays in the box', () => {
  const count = 800,
    steps = 300;
  const settle = (threads: number): { overlap: number; inside: boolean; speed: number } => {
    const world = pile(count, threads, false);
    stepMany(world, steps);
    const c = world.components,
      r = 0.5;
    const layout = world.collision.boundary;
    let inside = true,
      speed = 0;
    for (let e = 1; e <= count; e++) {
      const x = c.Position.x[e]!,
        y = c.Position.y[e]!;
      if (x < layout.min[0]! + r - 1e-3 || x > layout.max[0]! - r + 1e-3 || y < layout.min[1]! + r - 1e-3 || y > layout.max[1]! - r + 1e-3)
        inside = false;
      speed = Math.max(speed, Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!));
    }
    // Deepest overlap of any two balls, by brute force over the pairs (a sleeping pile reports no contacts).
    let deepest = 0;
    for (let i = 1; i <= count; i++) {
      for (let j = i + 1; j <= count; j++) {
        const d = 2 * r - Math.hypot(c.Position.x[j]! - c.Position.x[i]!, c.Position.y[j]! - c.Position.y[i]!);
        if (d > deepest) deepest = d;
      }
    }
    return { overlap: deepest / r, inside, speed };
  };
  const one = settle(1),
    two = settle(2);
  expect(two.inside).toBe(true);
  expect(two.overlap).toBeLessThan(0.02);
  expect(one.overlap).toBeLessThan(0.02);
  expect(one.speed).toBeLessThan(0.1);
  // Settled: every ball slower than 0.1 m/s (what gravity adds in 0.6 of a step; a ball still falling or bouncing is faster).
  expect(two.speed).toBeLessThan(0.1);
});

test('contact rows prepared on 2 threads (coloured solve off): the one-thread state to the bit', () => {
  // A 70 x 64 lattice of balls 0.02 diameters apart, no gravity, small random velocities: about 8,800
  // rows from the first step, past PREPARE_MIN_PER_THREAD a thread. Each row is prepared on its own
  // with the one-thread arithmetic, so the state must match threads: 1 exactly (tolerance zero).
  const run = (threads: number): [string, PhysicsWorld] => {
    const world = createPhysicsWorld({ dimensions: 2, capacity: 70 * 64, gravity: [0, 0], ...(threads > 1 ? { threads } : {}) });
    worlds.push(world);
    if (world.threadPool !== null) world.threadPool.adaptive = false;
    world.collision.settings.coloredSolveMinRows = Infinity;
    const rng = new Rng(5);
    for (let j = 0; j < 64; j++) {
      for (let i = 0; i < 70; i++)
        addBody(world, { position: [1.02 * i, 1.02 * j], velocity: [rng.range(-0.1, 0.1), rng.range(-0.1, 0.1)], radius: 0.5 });
    }
    stepMany(world, 3);
    return [stateHash(world), world];
  };
  const [one] = run(1);
  const [two, world] = run(2);
  expect(world.collision.stats.contacts).toBeGreaterThan(2 * PREPARE_MIN_PER_THREAD);
  // The kernel ran: it moves the contact buffers onto shared memory first.
  expect(world.collision.cache.rows.normalMass.buffer instanceof SharedArrayBuffer).toBe(true);
  expect(two).toBe(one);
});

test("a threaded pile whose rows grow step by step keeps its solver bodies' list (the pool is not handed a new array each step)", () => {
  // The pool keeps every array it is given (threads/pool.ts), posted to each worker: the list grown to
  // exactly twice the rows was a new array in nearly every step of a landing pile (about 0.5 ms a step
  // of posting and syncing at 20,000 balls, and every old list kept). Grown by doubling, a 600-ball
  // pile's list changes a few times in 120 steps.
  const world = pile(600, 2, false);
  const lists = new Set<Int32Array>();
  for (let k = 0; k < 120; k++) {
    stepMany(world, 1);
    lists.add(world.collision.solverBodies);
  }
  expect(lists.size).toBeLessThanOrEqual(6);
});

test('rows packed on a worker while the impact stage runs: the state of a pack made after the stage (rows the stage changed packed again)', () => {
  // Two threaded piles, restitution 0.5: one packs on the worker beside the impact stage (stripPlan2D
  // with P[8] = 1), the other only cuts and plans there and packs in the solve, after the stage. The
  // stage changes some rows' normals and gaps meanwhile, which the first must pack again
  // (coloredRepack2D); tolerance zero, the same arithmetic on the same rows.
  const run = (packOnWorker: boolean): { hash: string; changed: number } => {
    const world = pile(600, 2, false);
    const pool = world.threadPool!,
      start = pool.start.bind(pool);
    let changed = 0;
    pool.start = (system, kernel, arrays, params, n) => {
      if (kernel === stripPlan2D && !packOnWorker) {
        const Q = Float64Array.from(params);
        Q[8] = 0;
        params = Q;
      }
      start(system, kernel, arrays, params, n);
    };
    for (let k = 0; k < 120; k++) {
      stepMany(world, 1);
      changed += impactChangedRows().count;
    }
    return { hash: stateHash(world), changed };
  };
  const worker = run(true),
    after = run(false);
  expect(worker.changed).toBeGreaterThan(100);
  expect(worker.hash).toBe(after.hash);
});

test('the strip cut made on a worker (ThreadPool.start, beside the impact stage) is the cut made on the calling thread', () => {
  // 3,000 solver bodies (every 7th fixed, every 5th other kinematic, moving) and 9,000 rows between random bodies,
  // on shared memory; the kernel's outputs compared slot by slot (tolerance zero: the same arithmetic).
  const world = createPhysicsWorld({ threads: 2 });
  worlds.push(world);
  const pool = world.threadPool!;
  const bodies = 3000,
    rows = 9000,
    bins = 4096,
    rng = new Rng(5);
  const shared = <T extends Float64Array | Int32Array | Uint8Array | Uint16Array>(
    C: { new (b: SharedArrayBuffer): T; BYTES_PER_ELEMENT: number },
    n: number,
  ): T => new C(new SharedArrayBuffer(n * C.BYTES_PER_ELEMENT));
  const sb = shared(Float64Array, 8 * bodies),
    ex = shared(Float64Array, 6 * bodies),
    type = shared(Uint8Array, bodies + 1),
    list = shared(Int32Array, bodies);
  const IA = shared(Int32Array, rows),
    IB = shared(Int32Array, rows);
  for (let k = 1; k < bodies; k++) {
    list[k] = k;
    type[k] = k % 7 === 0 ? 3 : k % 5 === 0 ? 2 : 0; // 0 dynamic (P[4]), others not
    sb[k * 8 + 5] = k % 7 === 0 || k % 5 === 0 ? 0 : 1;
    sb[k * 8] = k % 5 === 0 ? 0.5 : 0;
    ex[k * 6] = rng.range(-3, 3);
    ex[k * 6 + 1] = rng.range(0, 2);
  }
  for (let i = 0; i < rows; i++) {
    IA[i] = i % 9 === 0 ? 0 : 1 + Math.floor(rng.range(0, bodies - 1));
    IB[i] = 1 + Math.floor(rng.range(0, bodies - 1));
  }
  const outputs = () => [
    shared(Uint8Array, bodies),
    shared(Uint8Array, bodies),
    shared(Uint16Array, bodies),
    shared(Int32Array, bins),
    shared(Uint8Array, bins),
  ];
  // P[6] = 0: the cut's arrays are A's only ones.
  const P = new Float64Array([bodies, rows, 32, bins, 0, 0xffff, 0]);
  const inline = outputs(),
    worker = outputs();
  stripCut2D([sb, ex, type, list, ...inline, IA, IB], P, null, 0, 1);
  pool.start('contactSolverSystem', stripCut2D, [sb, ex, type, list, ...worker, IA, IB], P, 1);
  pool.join();
  for (let j = 0; j < inline.length; j++) expect(Array.from(worker[j]!)).toEqual(Array.from(inline[j]!));
  // A real cut: fixed bodies in no strip, the others spread over all 32 strips, every row counted once.
  const strip = inline[1]!;
  expect(strip[7]).toBe(255);
  expect(new Set(Array.from(strip.subarray(1)).filter((v) => v !== 255)).size).toBe(32);
  expect(Array.from(inline[3]!).reduce((a, b) => a + b, 0)).toBe(
    rows - Array.from({ length: rows }, (_, i) => i).filter((i) => strip[IA[i]!] === 255 && strip[IB[i]!] === 255).length,
  );
});
