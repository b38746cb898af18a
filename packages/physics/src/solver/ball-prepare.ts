/**
 * Preparation of the ball contacts' rows (solver/ball-rows.ts stages 2 and 4): combined material,
 * effective masses, tangent basis, stick or slip and last step's impulses (warm start), and the
 * approach speeds the restitution stage reads. 2D runs as range kernels (solver/prepare-contacts-kernel.ts,
 * solver/stages-threads.ts) on the world's threads or inline; 3D runs here.
 */

import { type ContactBuffer, ContactKind, findWarmStart } from '../collision/contacts.js';
import type { KernelArray } from '../threads/kernel-types.js';
import { runOnPool } from '../threads/parallel.js';
import { isShared, sharedLike } from '../threads/pool.js';
import type { PhysicsWorld } from '../world/options.js';
import { BS3_INV_INERTIA, BS3_INV_MASS, BS3_STRIDE, BS3_VX, BS3_VY, BS3_VZ, BS3_WX, BS3_WY, BS3_WZ } from './body-state-layout.js';
import { shareContactBuffer } from './coloring.js';
import { prepareContacts2D } from './prepare-contacts-kernel.js';
import * as PREPARE from './slots/prepare-contacts.js';
import { approachStage } from './stages-threads.js';

/**
 * Fewest contact rows a thread for a threaded 2D world to prepare its rows on its threads.
 * @category Collision
 */
export const PREPARE_MIN_PER_THREAD = 4096;

/** Per world: the shared copy of the spawn stamps, the kernel's arrays and parameters (prepare2DStage). */
const prepareScratch = new WeakMap<PhysicsWorld, { stamp: Uint32Array; arrays: KernelArray[]; params: Float64Array }>();

/**
 * prepareContacts of a 2D world (kernel prepareContacts2D: each row on its own), on its threads when it
 * has them and has at least PREPARE_MIN_PER_THREAD rows a thread (and the pool takes it), else inline
 * over every row: one code path, the same rows to the bit either way.
 * @throws Error naming contactSolverSystem if a worker thread failed.
 */
function prepare2DStage(world: PhysicsWorld, buf: ContactBuffer, stick: number): void {
  let pool = world.threadPool;
  const n = buf.count;
  const cs = world.collision,
    c = world.components,
    cache = cs.cache;
  const M = c.Material;
  if (pool !== null && n < PREPARE_MIN_PER_THREAD * pool.threads) pool = null;
  if (pool !== null && (!isShared(M.restitution) || !isShared(M.friction) || !isShared(M.staticFriction) || !isShared(cs.bodyState)))
    pool = null;
  let S = prepareScratch.get(world);
  if (S === undefined) {
    S = { stamp: new Uint32Array(0), arrays: [], params: new Float64Array(8) };
    prepareScratch.set(world, S);
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
  const P = S.params;
  P[PREPARE.STICK_SPEED] = stick;
  P[PREPARE.BOX_RESTITUTION] = box.restitution;
  P[PREPARE.BOX_FRICTION] = box.friction;
  P[PREPARE.BOX_STATIC_FRICTION] = box.staticFriction;
  P[PREPARE.PREV_ROWS] = cache.size === 0 ? 0 : prev.count;
  P[PREPARE.SLOT_COUNT] = cache.size;
  P[PREPARE.BALL] = ContactKind.Ball;
  P[PREPARE.BOUNDARY] = ContactKind.Boundary;
  if (pool !== null && runOnPool(pool, 'contactSolverSystem', prepareContacts2D, A, P, n, null, PREPARE_MIN_PER_THREAD) !== null) return;
  prepareContacts2D(A, P, null, 0, n);
}

/**
 * Prepares the step's ball contact rows: effective masses, tangent basis, combined material, stick or
 * slip, the predicted approach, and last step's impulses of the same pair (warm start). 2D: a range
 * kernel (prepare2DStage); the loop here is 3D.
 */
export function prepareContacts(world: PhysicsWorld, buf: ContactBuffer, stick: number): void {
  // The warm-start table may still be building on a worker (storeWarmStartOnThreads).
  world.threadPool?.join();
  if (world.dimensions === 2) {
    prepare2DStage(world, buf, stick);
    return;
  }
  const c = world.components;
  const cs = world.collision;
  const n = buf.count;
  const sb = cs.bodyState;
  const eM = c.Material.restitution,
    fM = c.Material.friction,
    sM = c.Material.staticFriction;
  const box = cs.boundary;
  const cache = cs.cache;
  const prev = cache.rows;
  const stamp = world.spawnStamp;
  const A = buf.a,
    B = buf.b,
    IA = buf.ia,
    IB = buf.ib,
    K = buf.kind,
    F = buf.feature;
  const NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const RA = buf.ra,
    RB = buf.rb;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    RP = buf.rigidPartner;
  const E = buf.restitution,
    MU = buf.friction,
    FB = buf.frictionBound,
    RV = buf.relativeVelocity;
  const TOT = buf.totalNormalImpulse,
    IMP = buf.impulse;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2,
    MAXN = buf.maxNormalImpulse;
  const SA = buf.stampA,
    SB = buf.stampB,
    PREV = buf.previous;
  const pN = prev.normalImpulse,
    p1 = prev.tangentImpulse1,
    p2 = prev.tangentImpulse2;
  const pK = prev.kind,
    pA = prev.a,
    pB = prev.b,
    pF = prev.feature,
    pSA = prev.stampA,
    pSB = prev.stampB;
  const prevCount = cache.size === 0 ? 0 : prev.count;
  let next = 0;

  for (let i = 0; i < n; i++) {
    const a = A[i]!,
      b = B[i]!,
      kind = K[i]!,
      f = F[i]!;
    const oa = IA[i]! * BS3_STRIDE,
      ob = IB[i]! * BS3_STRIDE;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const imA = sb[oa + BS3_INV_MASS]!,
      imB = sb[ob + BS3_INV_MASS]!;
    const iiA = sb[oa + BS3_INV_INERTIA]!,
      iiB = sb[ob + BS3_INV_INERTIA]!;
    const ra = RA[i]!,
      rb = RB[i]!;
    const k = imA + imB;
    NM[i] = k > 0 ? 1 / k : 0;
    const kt = k + iiA * ra * ra + iiB * rb * rb;
    TM[i] = kt > 0 ? 1 / kt : 0;
    RP[i] = imA === 0 || imB === 0 ? 1 : 0;

    // Tangent basis: t1 stored, t2 = n x t1 recomputed where needed.
    let t1x: number, t1y: number, t1z: number;
    if (Math.abs(nx) < 0.57735) {
      const inv = 1 / Math.sqrt(ny * ny + nz * nz);
      t1x = 0;
      t1y = nz * inv;
      t1z = -ny * inv;
    } else {
      const inv = 1 / Math.sqrt(nx * nx + ny * ny);
      t1x = ny * inv;
      t1y = -nx * inv;
      t1z = 0;
    }
    T1X[i] = t1x;
    T1Y[i] = t1y;
    T1Z[i] = t1z;

    // Combined material (Box2D's mixing rules: the bouncier surface wins, friction is the geometric mean).
    let e: number, mu: number, mus: number;
    if (kind === ContactKind.Ball) {
      e = Math.max(eM[a]!, eM[b]!);
      mu = Math.sqrt(fM[a]! * fM[b]!);
      mus = Math.sqrt(sM[a]! * sM[b]!);
    } else if (kind === ContactKind.Boundary) {
      e = Math.max(box.restitution, eM[b]!);
      mu = Math.sqrt(box.friction * fM[b]!);
      mus = Math.sqrt(box.staticFriction * sM[b]!);
    } else {
      e = Math.max(eM[f]!, eM[b]!);
      mu = Math.sqrt(fM[f]! * fM[b]!);
      mus = Math.sqrt(sM[f]! * sM[b]!);
    }
    E[i] = e;
    MU[i] = mu;

    // Tangential speed at the start of the step (gravity rewound): stick or slip.
    const dvx = sb[ob + BS3_VX]! - sb[oa + BS3_VX]!,
      dvy = sb[ob + BS3_VY]! - sb[oa + BS3_VY]!,
      dvz = sb[ob + BS3_VZ]! - sb[oa + BS3_VZ]!;
    // Contact-point velocity: v + w x r with r_A = ra n, r_B = -rb n.
    const sx = -rb * sb[ob + BS3_WX]! - ra * sb[oa + BS3_WX]!,
      sy = -rb * sb[ob + BS3_WY]! - ra * sb[oa + BS3_WY]!,
      sz = -rb * sb[ob + BS3_WZ]! - ra * sb[oa + BS3_WZ]!;
    const cx = dvx + sy * nz - sz * ny,
      cy = dvy + sz * nx - sx * nz,
      cz = dvz + sx * ny - sy * nx;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const u1 = cx * t1x + cy * t1y + cz * t1z,
      u2 = cx * t2x + cy * t2y + cz * t2z;
    const vt = Math.sqrt(u1 * u1 + u2 * u2);
    // Predicted approach for the impact stage's ordering (measureApproach recomputes it after).
    RV[i] =
      (sb[ob + BS3_VX]! - sb[oa + BS3_VX]!) * nx + (sb[ob + BS3_VY]! - sb[oa + BS3_VY]!) * ny + (sb[ob + BS3_VZ]! - sb[oa + BS3_VZ]!) * nz;
    TOT[i] = 0;
    IMP[i] = 0;
    FB[i] = vt < stick ? Math.max(mus, mu) : mu;

    // Warm start from last step's impulses of the same pair.
    const sA = stamp[kind === ContactKind.Ball ? a : kind === ContactKind.Boundary ? 0 : f]!;
    const sB = stamp[b]!;
    SA[i] = sA;
    SB[i] = sB;
    MAXN[i] = 0;
    // The contacts come in much the same order every step: the row after last step's previous match
    // is tried first (one comparison, read in order) before the hash table (the same row: keys are unique).
    let j = next;
    if (j < prevCount && pK[j] === kind && pA[j] === a && pB[j] === b && pF[j] === f) j = pSA[j] === sA && pSB[j] === sB ? j : -1;
    else j = findWarmStart(cache, kind, a, b, f, sA, sB);
    PREV[i] = j;
    if (j >= 0) {
      next = j + 1;
      LN[i] = pN[j]!;
      L1[i] = p1[j]!;
      L2[i] = p2[j]!;
    } else {
      LN[i] = 0;
      L1[i] = 0;
      L2[i] = 0;
    }
  }
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
