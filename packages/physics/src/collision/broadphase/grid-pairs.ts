/**
 * The broadphase's cell pass (collision/broadphase/grid.ts: every grid body against its own cell and half of its
 * neighbours) on the world's threads. Each thread takes a contiguous range of the grid's bodies, in
 * the grid's order, and writes the pairs it finds into its own buffer; the buffers are then appended
 * to the step's pair list in range order, which is exactly the order one thread finds them in, so
 * the pair list, and everything after it, is identical to the bit to the one-thread broadphase.
 *
 * Sleeping balls: the threads read the body types as they were when the pass began and list the
 * sleeping balls they meet that a moving or kinematic ball wakes; the caller then wakes them in range
 * order, skipping those already woken. The one-thread loop wakes each as it meets it, but the woken
 * ball has rested (so it wakes nobody) and is met where it slept (waking leaves its start-of-step
 * position), so the same balls wake in the same order; a pass that woke any ball is run again in
 * full either way (collision/broadphase/grid.ts), so the pairs are the one-thread ones too.
 */

import type { KernelArray } from '../../threads/kernel-types.js';
import { KERNEL } from '../../threads/kernels.js';
import { runOnPool } from '../../threads/parallel.js';
import { sharedCopy } from '../../threads/pool.js';
import type { PhysicsWorld } from '../../world/options.js';
import { BodyType, type CollisionState, PairKind } from '../state.js';

export { ballPairs } from './grid-pairs-kernel.js';

/**
 * Fewest grid bodies a thread for the cell pass to go parallel.
 * @category Collision
 */
export const PAIRS_MIN_PER_THREAD = 2048;

/** Most threads the pass runs on: `counts` holds the ranges' pair counts, then at 16 + p their wake counts (the kernel's layout). */
const MAX_PARTS = 16;

interface PairBuffers {
  a: Int32Array[];
  b: Int32Array[];
  w: Int32Array[];
  counts: Int32Array;
  arrays: KernelArray[];
  params: Float64Array;
}

const buffersOf = new WeakMap<CollisionState, PairBuffers>();

/**
 * Runs the cell pass for the `small` grid bodies on the world's threads, appends the pairs to `cs`'s
 * pair list and calls `wake(world, cs, e)` for each sleeping ball to wake (in the one-thread order),
 * when the world has threads and the grid is large enough; returns false (nothing done) otherwise, and
 * the caller runs its own loop. `mask` is the grid's hash mask (unused by a dense grid, whose origin
 * and spans the kernel reads from `cs.grid`).
 * @throws Error naming broadphaseSystem if a worker thread failed.
 * @category Collision
 */
export function parallelBallPairs(
  world: PhysicsWorld,
  cs: CollisionState,
  small: number,
  mask: number,
  wake: (world: PhysicsWorld, cs: CollisionState, e: number) => void,
): boolean {
  const pool = world.threadPool;
  if (pool === null || small < PAIRS_MIN_PER_THREAD * pool.threads || pool.threads > MAX_PARTS) return false;
  // Sleepers have rested at least timeToSleep: with 0 a sleeper may not have, and then a ball the
  // one-thread loop wakes may wake others in the same pass (see the file's header).
  if (!(cs.sleep.timeToSleep > 0)) return false;
  const c = world.components;
  const g = cs.grid;
  // The scratch arrays the pass reads move to shared memory once (and again after they grow).
  g.sorted = sharedCopy(g.sorted);
  g.cellX = sharedCopy(g.cellX);
  g.cellY = sharedCopy(g.cellY);
  g.cellZ = sharedCopy(g.cellZ);
  g.bucketStart = sharedCopy(g.bucketStart);
  cs.margin = sharedCopy(cs.margin);
  cs.bodyType = sharedCopy(cs.bodyType);
  cs.sleep.restTime = sharedCopy(cs.sleep.restTime);
  let buf = buffersOf.get(cs);
  const cap = 4 * small + 1024;
  if (buf === undefined || buf.a.length < pool.threads || buf.a[0]!.length < cap) {
    const size = Math.max(cap, 2 * (buf === undefined ? 0 : buf.a[0]!.length));
    const a: Int32Array[] = [],
      b: Int32Array[] = [],
      w: Int32Array[] = [];
    for (let p = 0; p < pool.threads; p++) {
      a.push(new Int32Array(new SharedArrayBuffer(4 * size)));
      b.push(new Int32Array(new SharedArrayBuffer(4 * size)));
      w.push(new Int32Array(new SharedArrayBuffer(4 * size)));
    }
    buf = { a, b, w, counts: new Int32Array(new SharedArrayBuffer(4 * 2 * MAX_PARTS)), arrays: [], params: new Float64Array(8) };
    buffersOf.set(cs, buf);
  }
  const A = buf.arrays;
  A.length = 0;
  A.push(
    g.sorted,
    g.cellX,
    g.cellY,
    g.cellZ,
    g.bucketStart,
    c.PreviousPosition.x,
    c.PreviousPosition.y,
    c.PreviousPosition.z,
    c.Ball.radius,
    cs.margin,
    cs.bodyType,
    buf.counts,
    cs.sleep.restTime,
  );
  for (let p = 0; p < pool.threads; p++) A.push(buf.a[p]!, buf.b[p]!, buf.w[p]!);
  const P = buf.params;
  P[0] = mask;
  P[1] = world.dimensions;
  P[2] = buf.a[0]!.length;
  P[3] = g.spanX;
  P[4] = g.spanXZ;
  P[5] = g.originX;
  P[6] = g.originY;
  P[7] = g.originZ;
  buf.counts.fill(0);
  if (runOnPool(pool, 'broadphaseSystem', KERNEL.ballPairs, A, P, small, null, PAIRS_MIN_PER_THREAD) === null) return false;
  let total = 0;
  for (let p = 0; p < pool.threads; p++) {
    const k = buf.counts[p]!;
    if (k < 0 || buf.counts[MAX_PARTS + p]! < 0) {
      buffersOf.delete(cs);
      return false;
    } // a buffer overflowed: the caller's loop this step, larger buffers next
    total += k;
  }
  // Append in range order: the one-thread order.
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
  for (let p = 0; p < pool.threads; p++) {
    const k = buf.counts[p]!;
    if (k === 0) continue;
    cs.pairA.set(buf.a[p]!.subarray(0, k), n);
    cs.pairB.set(buf.b[p]!.subarray(0, k), n);
    cs.pairKind.fill(PairKind.BallBall, n, n + k);
    n += k;
  }
  cs.pairCount = n;
  // Wake in range order, each ball once (the first time it was met, as the one-thread loop does).
  const type = cs.bodyType;
  for (let p = 0; p < pool.threads; p++) {
    const W: Int32Array = buf.w[p]!;
    for (let j = 0, k = buf.counts[MAX_PARTS + p]!; j < k; j++) {
      const e = W[j]!;
      if (type[e] === BodyType.Sleeping) wake(world, cs, e);
    }
  }
  return true;
}
