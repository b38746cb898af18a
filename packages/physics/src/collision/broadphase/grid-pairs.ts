/**
 * The broadphase's cell pass (collision/broadphase/grid.ts: every grid body against its own cell and half of its
 * neighbours), one range kernel (collision/broadphase/grid-pairs-kernel.ts) run on the world's threads
 * when that pays and inline on the calling thread otherwise. Each thread takes a contiguous range of
 * the grid's bodies, in the grid's order, and writes the pairs it finds into its own buffer; the
 * buffers are then appended to the step's pair list in range order, which is the order one range
 * finds them in, so the pair list, and everything after it, is identical to the bit on any thread count.
 *
 * Sleeping balls: the kernel reads the body types as they were when the pass began and lists the
 * sleeping balls it meets that a kinematic ball, or a moving one (no rest time), wakes; the caller
 * then wakes them in range order, skipping those already woken. A ball woken in a pass meets its
 * sleeping neighbours only in the next one: a pass that woke any ball is run again in full
 * (collision/broadphase/grid.ts).
 */

import { runOnPool } from '../../threads/parallel.js';
import { sharedCopy, sharedMemoryAvailable, type ThreadPool } from '../../threads/pool.js';
import type { PhysicsWorld } from '../../world/options.js';
import type { PairBuffers } from '../../world/scratch.js';
import { BodyType, type CollisionState, PairKind } from '../state.js';
import * as PAIRS from './ball-pair-slots.js';
import { ballPairs } from './grid-pairs-kernel.js';

export { ballPairs } from './grid-pairs-kernel.js';

/**
 * Fewest grid bodies a thread for the cell pass to go parallel.
 * @category Collision
 */
export const PAIRS_MIN_PER_THREAD = 2048;

/** Most threads the pass runs on: `counts` holds the ranges' pair counts, then at PAIRS.WAKE_COUNTS + p their wake counts. */
const MAX_PARTS = PAIRS.WAKE_COUNTS;

/** The world's pool if the cell pass over `small` grid bodies may go to its threads, else null. */
function poolFor(world: PhysicsWorld, small: number): ThreadPool | null {
  const pool = world.threadPool;
  if (pool === null || small < PAIRS_MIN_PER_THREAD * pool.threads || pool.threads > MAX_PARTS) return null;
  return pool;
}

/** Int32 buffers of `size` entries, `parts` of each kind, on shared memory for a pool. */
function makeBuffers(parts: number, size: number, shared: boolean): PairBuffers {
  const make = (n: number): Int32Array => (shared ? new Int32Array(new SharedArrayBuffer(4 * n)) : new Int32Array(n));
  const a: Int32Array[] = [],
    b: Int32Array[] = [],
    w: Int32Array[] = [];
  for (let p = 0; p < parts; p++) {
    a.push(make(size));
    b.push(make(size));
    w.push(make(size));
  }
  return { a, b, w, counts: make(2 * MAX_PARTS), arrays: [], params: new Float64Array(8) };
}

/**
 * Runs the cell pass for the `small` grid bodies (on the world's threads when it has them and the grid
 * is large enough, else on the calling thread), appends the pairs to `cs`'s pair list and calls
 * `wake(world, cs, e)` for each sleeping ball to wake, in range order. `mask` is the grid's hash mask
 * (unused by a dense grid, whose origin and spans the kernel reads from `cs.grid`).
 * @throws Error naming broadphaseSystem if a worker thread failed.
 * @category Collision
 */
export function ballPairsStage(
  world: PhysicsWorld,
  cs: CollisionState,
  small: number,
  mask: number,
  wake: (world: PhysicsWorld, cs: CollisionState, e: number) => void,
): void {
  if (small <= 0) return;
  let pool = poolFor(world, small);
  const c = world.components;
  const g = cs.grid;
  if (pool !== null) {
    // The scratch arrays the pass reads move to shared memory once (and again after they grow).
    g.sorted = sharedCopy(g.sorted);
    g.cellX = sharedCopy(g.cellX);
    g.cellY = sharedCopy(g.cellY);
    g.cellZ = sharedCopy(g.cellZ);
    g.bucketStart = sharedCopy(g.bucketStart);
    cs.margin = sharedCopy(cs.margin);
    cs.bodyType = sharedCopy(cs.bodyType);
    cs.sleep.restTime = sharedCopy(cs.sleep.restTime);
  }
  const parts = pool === null ? 1 : pool.threads;
  const shared = pool !== null || sharedMemoryAvailable();
  // The world's pair buffers (world/scratch.ts), grown to `parts` ranges of `cap` pairs.
  let buf = world.scratch.pairBuffers;
  let cap = 4 * small + 1024;
  for (;;) {
    if (buf === undefined || buf.a.length < parts || buf.a[0]!.length < cap) {
      const size = Math.max(cap, 2 * (buf === undefined ? 0 : buf.a[0]!.length));
      buf = makeBuffers(Math.max(parts, buf?.a.length ?? 0), size, shared);
      world.scratch.pairBuffers = buf;
    }
    const A = buf.arrays;
    A.length = 0;
    A[PAIRS.SORTED] = g.sorted;
    A[PAIRS.CELL_X] = g.cellX;
    A[PAIRS.CELL_Y] = g.cellY;
    A[PAIRS.CELL_Z] = g.cellZ;
    A[PAIRS.BUCKET_START] = g.bucketStart;
    A[PAIRS.OX] = c.PreviousPosition.x;
    A[PAIRS.OY] = c.PreviousPosition.y;
    A[PAIRS.OZ] = c.PreviousPosition.z;
    A[PAIRS.RADIUS] = c.Ball.radius;
    A[PAIRS.MARGIN] = cs.margin;
    A[PAIRS.BODY_TYPE] = cs.bodyType;
    A[PAIRS.COUNTS] = buf.counts;
    A[PAIRS.REST_TIME] = cs.sleep.restTime;
    // From PAIRS.OUT on: each range's output arrays, in the order of the PAIRS.OUT_ slots.
    for (let p = 0; p < parts; p++) A.push(buf.a[p]!, buf.b[p]!, buf.w[p]!);
    const P = buf.params;
    P[PAIRS.HASH_MASK] = mask;
    P[PAIRS.DIMENSIONS] = world.dimensions;
    P[PAIRS.CAPACITY] = buf.a[0]!.length;
    P[PAIRS.SPAN_X] = g.spanX;
    P[PAIRS.SPAN_XZ] = g.spanXZ;
    P[PAIRS.ORIGIN_X] = g.originX;
    P[PAIRS.ORIGIN_Y] = g.originY;
    P[PAIRS.ORIGIN_Z] = g.originZ;
    buf.counts.fill(0);
    let threads = 1;
    if (pool !== null && runOnPool(pool, 'broadphaseSystem', ballPairs, A, P, small, null, PAIRS_MIN_PER_THREAD) !== null) {
      threads = pool.threads;
    } else {
      pool = null;
      ballPairs(A, P, null, 0, small, 0);
    }
    let overflow = false;
    for (let p = 0; p < threads; p++) if (buf.counts[p]! < 0 || buf.counts[MAX_PARTS + p]! < 0) overflow = true;
    if (!overflow) {
      appendPairs(world, cs, buf, threads, wake);
      return;
    }
    // A buffer overflowed: larger ones, and the pass again (on the calling thread).
    cap = 2 * buf.a[0]!.length;
    pool = null;
  }
}

/** Appends the `threads` ranges' pairs of `buf` to `cs`'s pair list and wakes their sleepers, in range order. */
function appendPairs(
  world: PhysicsWorld,
  cs: CollisionState,
  buf: PairBuffers,
  threads: number,
  wake: (world: PhysicsWorld, cs: CollisionState, e: number) => void,
): void {
  let total = 0;
  for (let p = 0; p < threads; p++) total += buf.counts[p]!;
  let n = cs.pairCount;
  if (cs.pairA.length < n + total) {
    let size = Math.max(16, cs.pairA.length);
    while (size < n + total) size *= 2;
    const a = new Int32Array(size),
      b = new Int32Array(size),
      k = new Uint8Array(size);
    a.set(cs.pairA.subarray(0, n));
    b.set(cs.pairB.subarray(0, n));
    k.set(cs.pairKind.subarray(0, n));
    cs.pairA = a;
    cs.pairB = b;
    cs.pairKind = k;
  }
  for (let p = 0; p < threads; p++) {
    const k = buf.counts[p]!;
    if (k === 0) continue;
    cs.pairA.set(buf.a[p]!.subarray(0, k), n);
    cs.pairB.set(buf.b[p]!.subarray(0, k), n);
    cs.pairKind.fill(PairKind.BallBall, n, n + k);
    n += k;
  }
  cs.pairCount = n;
  // Wake in range order, each ball once (the first time it was met).
  const type = cs.bodyType;
  for (let p = 0; p < threads; p++) {
    const W: Int32Array = buf.w[p]!;
    for (let j = 0, k = buf.counts[MAX_PARTS + p]!; j < k; j++) {
      const e = W[j]!;
      if (type[e] === BodyType.Sleeping) wake(world, cs, e);
    }
  }
}
