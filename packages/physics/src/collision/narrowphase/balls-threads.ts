/**
 * The narrowphase's ball-ball contacts (collision/narrowphase/balls.ts), one range kernel
 * (collision/narrowphase/balls-kernel.ts) run on the world's threads when that pays and inline on the
 * calling thread otherwise. On the threads, each turns a contiguous range of a run of ball-ball pairs
 * into contacts; the first range (the calling thread's) writes them straight into the contact buffer,
 * the others into arrays of their own, which are then appended after it in range order (typed-array
 * copies), the order one thread makes them in, so the contacts, and everything after them, are
 * identical to the bit on any thread count. Pairs of bodies a joint keeps apart are flagged first (the
 * lookup needs the joints' map, which the workers do not have) and make no contact.
 */

import { shareContactBuffer } from '../../solver/coloring.js';
import type { KernelArray } from '../../threads/kernel-types.js';
import { runOnPool } from '../../threads/parallel.js';
import { sharedCopy, sharedLike, type ThreadPool } from '../../threads/pool.js';
import { jointKeepsApart } from '../../world/joint-no-collide.js';
import type { PhysicsWorld } from '../../world/options.js';
import type { BallContactScratch } from '../../world/scratch.js';
import { type ContactBuffer, ContactKind, growContactBuffer } from '../contacts.js';
import { BodyType, type CollisionState } from '../state.js';
import * as CONTACT from './ball-contact-slots.js';
import { ballContacts } from './balls-kernel.js';

/**
 * Fewest ball-ball pairs a thread for the contacts to be made in parallel.
 * @category Collision
 */
export const CONTACTS_MIN_PER_THREAD = 2048;

/** The contact buffer's fields a range writes, in the order of the CONTACT.OUT_ slots (collision/narrowphase/ball-contact-slots.ts). */
const FIELDS = ['kind', 'nx', 'ny', 'nz', 'separation', 'ra', 'rb', 'a', 'b', 'feature'] as const;

/** The world's threads' buffers (FIELDS' arrays), ranges' counts, skip flags and kernel arguments (world/scratch.ts), made on first use. */
function scratch(world: PhysicsWorld): BallContactScratch {
  let s = world.scratch.ballContacts;
  if (s === undefined) {
    s = { threads: null, counts: new Int32Array(16), skip: new Uint8Array(0), arrays: [], params: new Float64Array(10) };
    world.scratch.ballContacts = s;
  }
  return s;
}

/** The world's pool if `n` ball-ball pairs may go to its threads, else null. */
function poolFor(world: PhysicsWorld, n: number): ThreadPool | null {
  const pool = world.threadPool;
  if (pool === null || n < CONTACTS_MIN_PER_THREAD * pool.threads || pool.threads > 16) return null;
  return pool;
}

/**
 * Appends to `buf` the contacts of `cs`'s ball-ball pairs lo .. hi - 1 (all of kind BallBall), in
 * pair order, skipping pairs of bodies a joint keeps apart: on the world's threads when the run is long
 * enough and the pool takes it, else on the calling thread.
 * @throws Error naming narrowphaseSystem if a worker thread failed.
 * @category Collision
 */
export function ballContactsStage(world: PhysicsWorld, cs: CollisionState, buf: ContactBuffer, lo: number, hi: number): void {
  const m = hi - lo;
  if (m <= 0) return;
  const s = scratch(world);
  let pool = poolFor(world, m);
  if (pool !== null) {
    cs.pairA = sharedCopy(cs.pairA);
    cs.pairB = sharedCopy(cs.pairB);
    cs.bodyType = sharedCopy(cs.bodyType);
    if (!(s.counts.buffer instanceof SharedArrayBuffer)) s.counts = sharedCopy(s.counts);
  }
  // Room for every pair in the buffer (range 0 writes there), on shared memory for the threads.
  if (buf.capacity < buf.count + m) growContactBuffer(buf, buf.count + m);
  if (pool !== null) shareContactBuffer(buf);
  // Pairs a joint keeps apart: flagged here, skipped by the kernel.
  const joints = world.joints;
  let skipAt = -1;
  if (joints.noCollidePairs.size > 0) {
    if (s.skip.length < hi || (pool !== null && !(s.skip.buffer instanceof SharedArrayBuffer))) {
      const size = Math.max(hi, 2 * s.skip.length);
      s.skip = pool !== null ? sharedLike(s.skip, size) : new Uint8Array(size);
    }
    const skip = s.skip,
      pairA = cs.pairA,
      pairB = cs.pairB;
    for (let i = lo; i < hi; i++) skip[i] = jointKeepsApart(joints, pairA[i]!, pairB[i]!) ? 1 : 0;
  }
  const threads = pool === null ? 1 : pool.threads;
  let B = s.threads;
  if (pool !== null) {
    const want = m + 1024;
    if (B === null || B.out.length < threads - 1 || B.cap < want) {
      const cap = Math.max(want, 2 * (B?.cap ?? 0));
      const out: KernelArray[][] = [];
      for (let p = 1; p < threads; p++) out.push(FIELDS.map((f) => sharedLike(buf[f] as KernelArray, cap)));
      B = { out, cap };
      s.threads = B;
    }
  }
  const c = world.components;
  const A = s.arrays;
  A.length = 0;
  A[CONTACT.PAIR_A] = cs.pairA;
  A[CONTACT.PAIR_B] = cs.pairB;
  A[CONTACT.OX] = c.PreviousPosition.x;
  A[CONTACT.OY] = c.PreviousPosition.y;
  A[CONTACT.OZ] = c.PreviousPosition.z;
  A[CONTACT.VX] = c.Velocity.x;
  A[CONTACT.VY] = c.Velocity.y;
  A[CONTACT.VZ] = c.Velocity.z;
  A[CONTACT.RADIUS] = c.Ball.radius;
  A[CONTACT.BODY_TYPE] = cs.bodyType;
  A[CONTACT.COUNTS] = s.counts;
  // From CONTACT.OUT on: each range's output arrays (FIELDS, in the order of the CONTACT.OUT_ slots).
  for (const f of FIELDS) A.push(buf[f]);
  if (pool !== null) for (let p = 1; p < threads; p++) for (const a of B!.out[p - 1]!) A.push(a);
  if (joints.noCollidePairs.size > 0) {
    skipAt = A.length;
    A.push(s.skip);
  }
  const P = s.params;
  P[CONTACT.H] = world.h;
  P[CONTACT.SPECULATIVE] = cs.settings.speculativeDistance;
  P[CONTACT.STATIC] = BodyType.Static;
  P[CONTACT.BALL] = ContactKind.Ball;
  P[CONTACT.STATIC_BALL] = ContactKind.StaticBall;
  P[CONTACT.CAPACITY] = B === null ? 0 : B.cap;
  P[CONTACT.CAPACITY_0] = buf.capacity;
  P[CONTACT.DIMENSIONS] = world.dimensions;
  P[CONTACT.FIRST_ROW] = buf.count;
  P[CONTACT.SKIP] = skipAt;
  const counts = s.counts;
  counts.fill(0);
  // The kernel's ranges cover lo .. hi - 1: the pool splits 0 .. m, so the pair arrays are offset views.
  if (pool !== null && lo !== 0) pool = null;
  if (pool !== null && runOnPool(pool, 'narrowphaseSystem', ballContacts, A, P, m, null, CONTACTS_MIN_PER_THREAD) !== null) {
    let total = 0,
      overflow = false;
    for (let p = 0; p < threads; p++) {
      if (counts[p]! < 0) overflow = true;
      total += counts[p]!;
    }
    if (!overflow) {
      // The first range's rows are in place; the others follow in range order (the one-thread order).
      const end = buf.count + total;
      buf.count += counts[0]!;
      if (end > buf.capacity) growContactBuffer(buf, end);
      let r = buf.count;
      for (let p = 1; p < threads; p++) {
        const k = counts[p]!;
        if (k === 0) continue;
        const out = B!.out[p - 1]!;
        for (let j = 0; j < FIELDS.length; j++) (buf[FIELDS[j]!] as KernelArray).set(out[j]!.subarray(0, k) as never, r);
        r += k;
      }
      buf.count = end;
      return;
    }
    // A thread's buffer was too small: larger ones next step, and this run on the calling thread.
    s.threads = null;
    counts.fill(0);
  }
  ballContacts(A, P, null, lo, hi, 0);
  buf.count += counts[0]!;
}
