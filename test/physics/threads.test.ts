import { execFile } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { promisify } from 'node:util';
import {
  addBody,
  addParticle,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  MIN_PARALLEL_PER_THREAD,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  stateHash,
  stepMany,
} from '@bitphysics/physics';
import { addComponent, removeEntity } from 'bitecs';
import { build } from 'esbuild';
import { afterEach, expect, test } from 'vitest';
import { Rng } from '../../packages/physics/src/math/rng.js';
import { KERNEL_HELPERS } from '../../packages/physics/src/solver/kernel-helpers.js';
import { KERNELS, testKernel } from '../../packages/physics/src/step/kernel-table.js';
import { sharedFloat64 } from '../../packages/physics/src/threads/pool.js';
import { workerSource } from '../../packages/physics/src/threads/worker-source.js';

// Worlds with threads > 1 need the thread pool (step/enable-threads.ts).
enableThreads();

// Worker threads split the integration and per-body force loops over shared component arrays; each
// body's arithmetic is the single-threaded one, so the promise is equality to the last bit: the
// reference is the one-thread run of the same scene, the tolerance zero (stateHash hashes every bit).

const worlds: PhysicsWorld[] = [];
afterEach(() => {
  for (const w of worlds.splice(0)) disposeWorld(w);
});

function make(options: PhysicsWorldOptions): PhysicsWorld {
  const w = createPhysicsWorld(options);
  worlds.push(w);
  return w;
}

/** Enough entities that 4 threads take the parallel path. */
const N = 4 * MIN_PARALLEL_PER_THREAD + 1001;

function particleWorld(threads: number, interpolation: boolean, holes: boolean): PhysicsWorld {
  const world = make({ dimensions: 2, capacity: N, gravity: [0.3, -9.81], interpolation, threads });
  const rng = new Rng(7);
  const ids: number[] = [];
  for (let i = 0; i < N; i++) {
    ids.push(addParticle(world, { position: [rng.range(-50, 50), rng.range(0, 100)], velocity: [rng.range(-5, 5), rng.range(-5, 5)] }));
  }
  // Removing some makes the query sparse (its ids no longer 1..n): the id-list kernel runs.
  if (holes) for (let i = 0; i < N; i += 97) removeEntity(world, ids[i]!);
  return world;
}

test('particles (dense and sparse, with and without interpolation): 1, 2 and 4 threads give identical states', () => {
  for (const [interpolation, holes] of [
    [false, false],
    [true, true],
  ] as const) {
    {
      const hashes = [1, 2, 4].map((threads) => {
        const world = particleWorld(threads, interpolation, holes);
        stepMany(world, 12);
        if (threads > 1) expect(world.threadPool!.runs, `threads ${threads} used its workers`).toBeGreaterThan(0);
        return stateHash(world);
      });
      expect(hashes[1], `2 threads, interpolation ${interpolation}, holes ${holes}`).toBe(hashes[0]);
      expect(hashes[2], `4 threads, interpolation ${interpolation}, holes ${holes}`).toBe(hashes[0]);
    }
  }
}, 60_000);

test('3D bodies with forces and gravity scale: 1 and 2 threads give identical states; the parabola is the exact one', () => {
  const n = 2 * MIN_PARALLEL_PER_THREAD + 17;
  const run = (threads: number): [string, PhysicsWorld] => {
    const world = make({ dimensions: 3, capacity: n, gravity: [0, -9.81, 0], threads });
    const rng = new Rng(3);
    for (let i = 0; i < n; i++) {
      const e = addBody(world, {
        position: [rng.range(-5, 5), rng.range(0, 10), rng.range(-5, 5)],
        velocity: [rng.range(-1, 1), 0, 0],
        mass: rng.range(0.5, 2),
      });
      addComponent(world, e, world.components.GravityScale);
      world.components.GravityScale.value[e] = rng.range(0, 2);
    }
    stepMany(world, 10);
    return [stateHash(world), world];
  };
  const [one] = run(1);
  const [two, world] = run(2);
  expect(world.threadPool!.runs).toBeGreaterThan(0);
  expect(two).toBe(one);
  // Independent check of the parallel result, body 1's height in closed form: a body a force acts on
  // (here (s - 1) m g) moves by plain semi-implicit Euler under the constant acceleration a = -s g, whose
  // k steps from rest in y move by a h^2 k (k + 1) / 2. 1e-9 m covers rounding.
  const rng = new Rng(3);
  rng.range(-5, 5);
  const y0 = rng.range(0, 10);
  const h = 1 / 60,
    k = 10;
  const s = world.components.GravityScale.value[1]!;
  expect(s).not.toBe(1);
  const expected = y0 - (s * 9.81 * h * h * k * (k + 1)) / 2;
  expect(world.components.Position.y[1]!).toBeCloseTo(expected, 9);
}, 60_000);

test("a worker that throws surfaces its error in the main thread with the system's name", () => {
  const world = make({ capacity: 10, threads: 2 });
  const pool = world.threadPool!;
  expect(pool.usable()).toBe(true);
  const out = sharedFloat64(1000);
  // Worker (thread 1) owns indices 500..999; index 700 throws there.
  expect(() => pool.run('testSystem', testKernel, [out], [2, 700], 1000, null)).toThrow(
    /^testSystem: a worker thread failed: test kernel: index 700/,
  );
  // The pool still works after a failure, and both halves are written.
  expect(pool.run('testSystem', testKernel, [out], [2, -1], 1000, null)).toBe((999 * 1000) / 2);
  expect(out[999]).toBe(1998);
  expect(out[1]).toBe(2);
});

test("a kernel whose text still names a layout constant is refused with its name, before any worker starts; the table's own kernels name none", () => {
  // This file is not folded by the build, so the name stays in the function's text, as in an unfolded bundle.
  const BS2_INV_MASS = 5;
  const unfolded = (A: Float64Array[], _P: Float64Array, _ids: Int32Array | null, lo: number, hi: number) => {
    for (let i = lo; i < hi; i++) A[0]![i] = A[1]![i * 8 + BS2_INV_MASS]!;
    return 0;
  };
  expect(() => workerSource([unfolded as never], [])).toThrow(/kernel unfolded names the constant BS2_INV_MASS/);
  const source = workerSource(KERNELS, KERNEL_HELPERS);
  expect(source).not.toMatch(/(?<![.\w$])((BS2|BS3|BX|PK)_[A-Z_]+|[A-Z][A-Z0-9_]*\.[A-Z][A-Z0-9_]*)\b/);
  // A slot module imported as a namespace and left unfolded is refused too.
  const unfoldedSlot = (A: Float64Array[], P: Float64Array) => A[0]![0]! + P[Math.floor(P[0]!)]! * 0;
  const named = { toString: () => 'function k(A, P) { return A[GATHER.PX][0]; }', name: 'k' };
  expect(() => workerSource([named as never], [])).toThrow(/kernel k names the constant GATHER.PX/);
  expect(() => workerSource([unfoldedSlot as never], [])).not.toThrow();
  expect(source).toContain('function solveColored2D');
});

test('a kernel takes up to 64 parameters; more are refused before anything runs (they were cut to 24 without a word)', () => {
  const world = make({ capacity: 10, threads: 2 });
  const pool = world.threadPool!;
  expect(pool.usable()).toBe(true);
  const out = sharedFloat64(1000).fill(-1);
  // 64 parameters: the kernel reads P[0] (2) and P[1] (no bad index); the rest are padding it passes by.
  const params = new Float64Array(64).fill(7);
  params[0] = 2;
  params[1] = -1;
  expect(pool.run('testSystem', testKernel, [out], params, 1000, null)).toBe((999 * 1000) / 2);
  expect(out[999]).toBe(1998);
  out.fill(-1);
  expect(() => pool.run('testSystem', testKernel, [out], new Float64Array(65), 1000, null)).toThrow(
    /^testSystem: a kernel takes at most 64 parameters, got 65$/,
  );
  expect(() => pool.start('testSystem', testKernel, [out], new Float64Array(65), 1000)).toThrow(
    /^testSystem: a kernel takes at most 64 parameters, got 65$/,
  );
  expect(out[999]).toBe(-1);
});

test('start runs a kernel on a worker while the caller goes on; join (or the next run) waits for it and surfaces its error', () => {
  const world = make({ capacity: 10, threads: 3 });
  const pool = world.threadPool!;
  expect(pool.usable()).toBe(true);
  const out = sharedFloat64(1000).fill(-1);
  // The first worker takes all of [0, 1000); the caller's range and the second worker's are empty.
  pool.start('testSystem', testKernel, [out], [3, -1], 1000);
  // The caller works meanwhile on memory the kernel does not touch, then joins: the kernel's sum.
  let own = 0;
  for (let i = 0; i < 1e5; i++) own += i;
  expect(own).toBe((1e5 * (1e5 - 1)) / 2);
  expect(pool.join()).toBe((999 * 1000) / 2);
  expect(out[0]).toBe(0);
  expect(out[999]).toBe(2997);
  // Nothing left to join.
  expect(pool.join()).toBe(0);
  // A started kernel that throws: join names the system and the worker's message.
  pool.start('cutSystem', testKernel, [out], [1, 10], 1000);
  expect(() => pool.join()).toThrow(/^cutSystem: a worker thread failed: test kernel: index 10/);
  // A run joins a started kernel first, and reports its error.
  pool.start('cutSystem', testKernel, [out], [1, 20], 1000);
  expect(() => pool.run('testSystem', testKernel, [out], [2, -1], 1000, null)).toThrow(
    /^cutSystem: a worker thread failed: test kernel: index 20/,
  );
  pool.start('cutSystem', testKernel, [out], [5, -1], 1000);
  expect(pool.run('testSystem', testKernel, [out], [2, -1], 1000, null)).toBe((999 * 1000) / 2);
  expect(out[999]).toBe(1998);
});

test('threads: bad values are refused; disposeWorld stops the workers and the world steps on alone', () => {
  expect(() => createPhysicsWorld({ threads: 0 })).toThrow(/^createPhysicsWorld: threads must be/);
  expect(() => createPhysicsWorld({ threads: 1.5 })).toThrow(/^createPhysicsWorld: threads must be/);
  expect(() => createPhysicsWorld({ threads: '2' as never })).toThrow(/^createPhysicsWorld: threads must be/);
  expect(createPhysicsWorld().threadPool).toBeNull();
  const a = particleWorld(2, false, false);
  const b = particleWorld(1, false, false);
  stepMany(a, 3);
  const pool = a.threadPool!;
  disposeWorld(a);
  disposeWorld(a);
  expect(a.threadPool).toBeNull();
  expect(pool.isDisposed).toBe(true);
  stepMany(a, 3);
  stepMany(b, 6);
  expect(stateHash(a)).toBe(stateHash(b));
}, 60_000);

test('a Node process with a threaded world exits by itself when its script ends, disposed or not', async () => {
  const dir = mkdtempSync(join(tmpdir(), 'bitphysics-threads-'));
  const entry = join(dir, 'run.ts');
  writeFileSync(
    entry,
    [
      `import { addParticle, createPhysicsWorld, disposeWorld, enableThreads, stepMany } from '@bitphysics/physics';`,
      `enableThreads();`,
      `for (const dispose of [false, true]) {`,
      `  const world = createPhysicsWorld({ capacity: 70000, threads: 2, interpolation: false });`,
      `  for (let i = 0; i < 70000; i++) addParticle(world, { position: [i, 0] });`,
      `  stepMany(world, 3);`,
      `  if (world.threadPool.runs === 0) throw new Error('no parallel loop ran');`,
      `  if (dispose) disposeWorld(world);`,
      `}`,
      `console.log('done');`,
    ].join('\n'),
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
  // A process held open by its workers would hit the timeout (execFile then rejects).
  const { stdout } = await promisify(execFile)(process.execPath, [out], { timeout: 30_000 });
  expect(stdout.trim()).toBe('done');
}, 60_000);

test('a NaN in a threaded world is still found and named: the parallel integrate and finiteness checks see every range', () => {
  for (const threads of [1, 2]) {
    const world = particleWorld(threads, false, false);
    stepMany(world, 1);
    // In the worker's half of the loop (thread 1 owns the upper half of the ids).
    const e = N - 10;
    world.components.Velocity.x[e] = NaN;
    expect(() => stepMany(world, 1), `threads ${threads}`).toThrow(/Velocity\.x/);
  }
}, 60_000);
