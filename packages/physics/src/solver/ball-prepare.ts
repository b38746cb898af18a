/**
 * Preparation of the ball contacts' rows (solver/ball-rows.ts stages 2 and 4): combined material,
 * effective masses, tangent basis, stick or slip and last step's impulses (warm start), and the
 * approach speeds the restitution stage reads: range kernels (solver/prepare-contacts-kernel.ts,
 * solver/stages-kernel.ts), 2D and 3D, run on a 2D world's threads or inline.
 */

import { type ContactBuffer, ContactKind } from '../collision/contacts.js';
import { runOnPool } from '../threads/parallel.js';
import { isShared, sharedLike } from '../threads/pool.js';
import type { PhysicsWorld } from '../world/options.js';
import { shareContactBuffer } from './coloring.js';
import { KERNEL_HELPERS } from './kernel-helpers.js';
import { prepareContactRows } from './prepare-contacts-kernel.js';
import * as PREPARE from './slots/prepare-contacts.js';
import { approachStage } from './stages-threads.js';

/**
 * Fewest contact rows a thread for a threaded 2D world to prepare its rows on its threads.
 * @category Collision
 */
export const PREPARE_MIN_PER_THREAD = 4096;

/**
 * prepareContacts (kernel prepareContactRows: each row on its own), on a 2D world's threads when it
 * has them and has at least PREPARE_MIN_PER_THREAD rows a thread (and the pool takes it), else inline
 * over every row: one code path, the same rows to the bit either way.
 * @throws Error naming contactSolverSystem if a worker thread failed.
 */
function prepareStage(world: PhysicsWorld, buf: ContactBuffer, stick: number): void {
  let pool = world.threadPool;
  const n = buf.count;
  const cs = world.collision,
    c = world.components,
    cache = cs.cache;
  const M = c.Material;
  if (pool !== null && (world.dimensions !== 2 || n < PREPARE_MIN_PER_THREAD * pool.threads)) pool = null;
  if (pool !== null && (!isShared(M.restitution) || !isShared(M.friction) || !isShared(M.staticFriction) || !isShared(cs.bodyState)))
    pool = null;
  // The world's shared copy of the spawn stamps and the kernel's arguments (world/scratch.ts).
  let S = world.scratch.ballPrepare;
  if (S === undefined) {
    S = { stamp: new Uint32Array(0), arrays: [], params: new Float64Array(9) };
    world.scratch.ballPrepare = S;
  }
  let stamp = world.spawnStamp;
  if (pool !== null) {
    shareContactBuffer(buf);
    shareContactBuffer(cache.rows);
    if (!isShared(cache.slots)) {
      const slots = sharedLike(cache.slots, cache.slots.length);
      slots.set(cache.slots);
      cache.slots = slots;
    }
    // The workers read a shared copy of the spawn stamps.
    if (S.stamp.length < stamp.length) S.stamp = sharedLike(stamp, stamp.length);
    S.stamp.set(stamp);
    stamp = S.stamp;
  }
  const prev = cache.rows,
    box = cs.boundary;
  const A = S.arrays;
  A.length = 0;
  A[PREPARE.A] = buf.a;
  A[PREPARE.B] = buf.b;
  A[PREPARE.IA] = buf.ia;
  A[PREPARE.IB] = buf.ib;
  A[PREPARE.KIND] = buf.kind;
  A[PREPARE.FEATURE] = buf.feature;
  A[PREPARE.NX] = buf.nx;
  A[PREPARE.NY] = buf.ny;
  A[PREPARE.RA] = buf.ra;
  A[PREPARE.RB] = buf.rb;
  A[PREPARE.BODY_STATE] = cs.bodyState;
  A[PREPARE.RESTITUTION_OF] = M.restitution;
  A[PREPARE.FRICTION_OF] = M.friction;
  A[PREPARE.STATIC_FRICTION_OF] = M.staticFriction;
  A[PREPARE.SPAWN_STAMP] = stamp;
  A[PREPARE.NORMAL_MASS] = buf.normalMass;
  A[PREPARE.TANGENT_MASS] = buf.tangentMass;
  A[PREPARE.RIGID_PARTNER] = buf.rigidPartner;
  A[PREPARE.T1X] = buf.t1x;
  A[PREPARE.T1Y] = buf.t1y;
  A[PREPARE.T1Z] = buf.t1z;
  A[PREPARE.RESTITUTION] = buf.restitution;
  A[PREPARE.FRICTION] = buf.friction;
  A[PREPARE.FRICTION_BOUND] = buf.frictionBound;
  A[PREPARE.RELATIVE_VELOCITY] = buf.relativeVelocity;
  A[PREPARE.TOTAL_NORMAL_IMPULSE] = buf.totalNormalImpulse;
  A[PREPARE.IMPULSE] = buf.impulse;
  A[PREPARE.NORMAL_IMPULSE] = buf.normalImpulse;
  A[PREPARE.TANGENT_IMPULSE_1] = buf.tangentImpulse1;
  A[PREPARE.TANGENT_IMPULSE_2] = buf.tangentImpulse2;
  A[PREPARE.MAX_NORMAL_IMPULSE] = buf.maxNormalImpulse;
  A[PREPARE.STAMP_A] = buf.stampA;
  A[PREPARE.STAMP_B] = buf.stampB;
  A[PREPARE.PREV_KIND] = prev.kind;
  A[PREPARE.PREV_A] = prev.a;
  A[PREPARE.PREV_B] = prev.b;
  A[PREPARE.PREV_FEATURE] = prev.feature;
  A[PREPARE.PREV_STAMP_A] = prev.stampA;
  A[PREPARE.PREV_STAMP_B] = prev.stampB;
  A[PREPARE.PREV_NORMAL_IMPULSE] = prev.normalImpulse;
  A[PREPARE.PREV_TANGENT_IMPULSE_1] = prev.tangentImpulse1;
  A[PREPARE.PREV_TANGENT_IMPULSE_2] = prev.tangentImpulse2;
  A[PREPARE.SLOTS] = cache.slots;
  A[PREPARE.PREVIOUS] = buf.previous;
  A[PREPARE.NZ] = buf.nz;
  const P = S.params;
  P[PREPARE.STICK_SPEED] = stick;
  P[PREPARE.BOX_RESTITUTION] = box.restitution;
  P[PREPARE.BOX_FRICTION] = box.friction;
  P[PREPARE.BOX_STATIC_FRICTION] = box.staticFriction;
  P[PREPARE.PREV_ROWS] = cache.size === 0 ? 0 : prev.count;
  P[PREPARE.SLOT_COUNT] = cache.size;
  P[PREPARE.BALL] = ContactKind.Ball;
  P[PREPARE.BOUNDARY] = ContactKind.Boundary;
  P[PREPARE.THREE_D] = world.dimensions === 3 ? 1 : 0;
  if (pool !== null && runOnPool(pool, 'contactSolverSystem', prepareContactRows, A, P, n, null, PREPARE_MIN_PER_THREAD) !== null) return;
  prepareContactRows(A, P, null, 0, n, 0, KERNEL_HELPERS);
}

/**
 * Prepares the step's ball contact rows: effective masses, tangent basis, combined material, stick or
 * slip, the predicted approach, and last step's impulses of the same pair (warm start): the range
 * kernel prepareContactRows, 2D or 3D (prepareStage).
 */
export function prepareContacts(world: PhysicsWorld, buf: ContactBuffer, stick: number): void {
  // The warm-start table may still be building on a worker (storeWarmStartOnThreads).
  world.threadPool?.join();
  prepareStage(world, buf, stick);
}

/**
 * Normal relative velocity of each contact at the start of the step after the impact stage (gravity
 * rewound), m/s, into `relativeVelocity`; and the speed at impact into `impactVelocity`:
 * v^2 = v0^2 - 2 a_n s across a gap s > 0 with the relative normal acceleration a_n of gravity. A
 * row the impact stage bounced (impulse > 0) that now separates keeps the approach speed that stage
 * recorded at its time of impact (restitution leaves separating rows alone).
 */
export function measureApproach(world: PhysicsWorld, buf: ContactBuffer): void {
  approachStage(world, buf);
}
