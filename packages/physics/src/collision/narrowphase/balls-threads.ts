/**
 * The narrowphase's ball-ball contacts (collision/narrowphase/balls.ts) on the world's threads. Each thread turns a
 * contiguous range of the step's ball-ball pairs into contacts; the first range (the calling
 * thread's) writes them straight into the contact buffer, the others into arrays of their own, which
 * are then appended after it in range order (typed-array copies), the order one thread makes them in,
 * so the contacts, and everything after them, are identical to the bit to the one-thread narrowphase.
 *
 * Only for the leading run of ball-ball pairs (the broadphase lists segment pairs after them) and
 * while no joint keeps bodies apart (that test looks pairs up in a map the workers do not have).
 */

import { shareContactBuffer } from '../../solver/coloring.js';
import type { KernelArray } from '../../threads/kernel-types.js';
import { KERNEL } from '../../threads/kernels.js';
import { runOnPool } from '../../threads/parallel.js';
import { sharedCopy, sharedLike } from '../../threads/pool.js';
import type { PhysicsWorld } from '../../world/options.js';
import { type ContactBuffer, ContactKind, growContactBuffer } from '../contacts.js';
import { BodyType, type CollisionState, PairKind } from '../state.js';

/**
 * Fewest ball-ball pairs a thread for the contacts to be made in parallel.
 * @category Collision
 */
export const CONTACTS_MIN_PER_THREAD = 2048;

/** The contact buffer's fields a range writes, in the kernel's order (collision/narrowphase/balls-kernel.ts). */
const FIELDS = ['kind', 'nx', 'ny', 'nz', 'separation', 'ra', 'rb', 'a', 'b', 'feature'] as const;

/** Each range after the first: its arrays (FIELDS', typed as the buffer's), `cap` rows each; the ranges' counts. */
interface ContactBuffers {
  out: KernelArray[][];
  counts: Int32Array;
  arrays: KernelArray[];
  params: Float64Array;
  cap: number;
}

const buffersOf = new WeakMap<CollisionState, ContactBuffers>();

/**
 * Makes the contacts of the leading ball-ball pairs of `cs` on the world's threads into `buf` (which
 * must be empty) and returns how many pairs it handled (0: none, the caller's loop makes them all).
 * @throws Error naming narrowphaseSystem if a worker thread failed.
 * @category Collision
 */
export function parallelBallContacts(world: PhysicsWorld, cs: CollisionState, buf: ContactBuffer): number {
  const pool = world.threadPool;
  const n = cs.pairCount;
  if (pool === null || n < CONTACTS_MIN_PER_THREAD * pool.threads || pool.threads > 16 || buf.count !== 0) return 0;
  if (world.joints.noCollidePairs.size > 0) return 0;
  let m = 0;
  const kind = cs.pairKind;
  while (m < n && kind[m] === PairKind.BallBall) m++;
  if (m < CONTACTS_MIN_PER_THREAD * pool.threads) return 0;
  cs.pairA = sharedCopy(cs.pairA);
  cs.pairB = sharedCopy(cs.pairB);
  cs.bodyType = sharedCopy(cs.bodyType);
  // The first range writes into the buffer itself: room for every pair, on shared memory.
  if (buf.capacity < m) growContactBuffer(buf, m);
  shareContactBuffer(buf);
  let B = buffersOf.get(cs);
  const want = m + 1024;
  if (B === undefined || B.out.length < pool.threads - 1 || B.cap < want) {
    const cap = Math.max(want, 2 * (B?.cap ?? 0));
    const out: KernelArray[][] = [];
    for (let p = 1; p < pool.threads; p++) out.push(FIELDS.map((f) => sharedLike(buf[f] as KernelArray, cap)));
    B = { out, counts: new Int32Array(new SharedArrayBuffer(4 * 16)), arrays: [], params: new Float64Array(8), cap };
    buffersOf.set(cs, B);
  }
  const c = world.components;
  const A = B.arrays;
  A.length = 0;
  A.push(
    cs.pairA,
    cs.pairB,
    c.PreviousPosition.x,
    c.PreviousPosition.y,
    c.PreviousPosition.z,
    c.Velocity.x,
    c.Velocity.y,
    c.Velocity.z,
    c.Ball.radius,
    cs.bodyType,
    B.counts,
  );
  for (const f of FIELDS) A.push(buf[f]);
  for (let p = 1; p < pool.threads; p++) for (const a of B.out[p - 1]!) A.push(a);
  const P = B.params;
  P[0] = world.h;
  P[1] = cs.settings.speculativeDistance;
  P[2] = BodyType.Static;
  P[3] = ContactKind.Ball;
  P[4] = ContactKind.StaticBall;
  P[5] = B.cap;
  P[6] = buf.capacity;
  P[7] = world.dimensions;
  B.counts.fill(0);
  if (runOnPool(pool, 'narrowphaseSystem', KERNEL.ballContacts, A, P, m, null, CONTACTS_MIN_PER_THREAD) === null) return 0;
  let total = 0;
  for (let p = 0; p < pool.threads; p++) {
    if (B.counts[p]! < 0) {
      buffersOf.delete(cs);
      return 0;
    } // too small a buffer: the caller's loop this step
    total += B.counts[p]!;
  }
  // The first range's rows are in place; the others follow in range order (the one-thread order).
  buf.count = B.counts[0]!;
  if (total > buf.capacity) growContactBuffer(buf, total);
  let r = buf.count;
  for (let p = 1; p < pool.threads; p++) {
    const k = B.counts[p]!;
    if (k === 0) continue;
    const out = B.out[p - 1]!;
    for (let j = 0; j < FIELDS.length; j++) (buf[FIELDS[j]!] as KernelArray).set(out[j]!.subarray(0, k) as never, r);
    r += k;
  }
  buf.count = total;
  return m;
}
