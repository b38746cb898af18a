/**
 * The narrowphase's ball-ball contacts (narrowphase.ts) on the world's threads. Each thread turns a
 * contiguous range of the step's ball-ball pairs into contacts in its own buffer; the buffers are
 * appended to the contact list in range order, the order one thread makes them in, so the contacts,
 * and everything after them, are identical to the bit to the one-thread narrowphase.
 *
 * Only for the leading run of ball-ball pairs (the broadphase lists segment pairs after them) and
 * while no joint keeps bodies apart (that test looks pairs up in a map the workers do not have).
 */

import type { PhysicsWorld } from '../world.js';
import { BodyType, PairKind, type CollisionState } from './state.js';
import { ContactKind, growContactBuffer, type ContactBuffer } from './contacts.js';
import type { KernelArray } from '../threads/kernel-types.js';
import { KERNEL } from '../threads/kernels.js';
import { runOnPool } from '../threads/parallel.js';
import { isShared, sharedLike } from '../threads/pool.js';
import { CONTACT_F, CONTACT_I } from './narrowphase-balls-kernel.js';

/** Fewest ball-ball pairs a thread for the contacts to be made in parallel. */
export const CONTACTS_MIN_PER_THREAD = 2048;

interface ContactBuffers { f: Float64Array[]; i: Int32Array[]; counts: Int32Array; arrays: KernelArray[]; params: Float64Array; cap: number }

const buffersOf = new WeakMap<CollisionState, ContactBuffers>();

function shared<T extends KernelArray>(a: T): T {
  if (isShared(a)) return a;
  const c = sharedLike(a, a.length);
  c.set(a as never);
  return c;
}

/**
 * Makes the contacts of the leading ball-ball pairs of `cs` on the world's threads into `buf` (which
 * must be empty) and returns how many pairs it handled (0: none, the caller's loop makes them all).
 * @throws Error naming narrowphaseSystem if a worker thread failed.
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
  cs.pairA = shared(cs.pairA); cs.pairB = shared(cs.pairB); cs.bodyType = shared(cs.bodyType);
  let B = buffersOf.get(cs);
  const want = m + 1024;
  if (B === undefined || B.f.length < pool.threads || B.cap < want) {
    const cap = Math.max(want, 2 * (B?.cap ?? 0));
    const f: Float64Array[] = [], i: Int32Array[] = [];
    for (let p = 0; p < pool.threads; p++) {
      f.push(new Float64Array(new SharedArrayBuffer(8 * CONTACT_F * cap)));
      i.push(new Int32Array(new SharedArrayBuffer(4 * CONTACT_I * cap)));
    }
    B = { f, i, counts: new Int32Array(new SharedArrayBuffer(4 * 16)), arrays: [], params: new Float64Array(6), cap };
    buffersOf.set(cs, B);
  }
  const c = world.components;
  const A = B.arrays;
  A.length = 0;
  A.push(cs.pairA, cs.pairB, c.PreviousPosition.x, c.PreviousPosition.y, c.PreviousPosition.z,
    c.Velocity.x, c.Velocity.y, c.Velocity.z, c.Ball.radius, cs.bodyType, B.counts);
  for (let p = 0; p < pool.threads; p++) A.push(B.f[p]!, B.i[p]!);
  const P = B.params;
  P[0] = world.h; P[1] = cs.settings.speculativeDistance; P[2] = BodyType.Static;
  P[3] = ContactKind.Ball; P[4] = ContactKind.StaticBall; P[5] = B.cap;
  B.counts.fill(0);
  if (runOnPool(pool, 'narrowphaseSystem', KERNEL.ballContacts, A, P, m, null, CONTACTS_MIN_PER_THREAD) === null) return 0;
  let total = 0;
  for (let p = 0; p < pool.threads; p++) {
    if (B.counts[p]! < 0) { buffersOf.delete(cs); return 0; } // too small a buffer: the caller's loop this step
    total += B.counts[p]!;
  }
  if (total > buf.capacity) growContactBuffer(buf, total);
  // Append in range order: the one-thread order.
  let r = 0;
  for (let p = 0; p < pool.threads; p++) {
    const F = B.f[p]!, I = B.i[p]!, k = B.counts[p]!;
    for (let j = 0; j < k; j++, r++) {
      const f = j * CONTACT_F, q = j * CONTACT_I;
      buf.kind[r] = F[f]!; buf.nx[r] = F[f + 1]!; buf.ny[r] = F[f + 2]!; buf.nz[r] = F[f + 3]!;
      buf.separation[r] = F[f + 4]!; buf.ra[r] = F[f + 5]!; buf.rb[r] = F[f + 6]!;
      buf.a[r] = I[q]!; buf.b[r] = I[q + 1]!; buf.feature[r] = I[q + 2]!;
    }
  }
  buf.count = total;
  return m;
}
