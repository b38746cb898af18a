/**
 * The ball contacts' rows of the contact solver (solver/contact-solver.ts): the rows between balls
 * (2D discs and 3D spheres), and between a ball and a segment or the boundary box. Each function here
 * is one of the solver's named stages for these rows; the solver calls them through the table of
 * solver/rows-balls.ts, which `installBalls` (collision/install-balls.ts) fills when a program first
 * makes a ball, so a program of shapes and joints only does not bring them into its bundle.
 *
 * Stages, in the solver's order: `prepareBallRows` (combined material, effective masses, tangent
 * basis, last step's impulses: warm start); `approachBallRows` (the impact stage of solver/impacts.ts,
 * the coloured solve's plan on a threaded 2D world, the approach speeds for restitution, the soft
 * coefficients); `planBallRows` (the relax sweep's first rows, the coloured substeps when they take the
 * step); per substep `warmStartBallRows` and `solveBallRows` (with soft bias, then relaxed) and
 * `endBallSubstep`; `ballRestitution`; `storeBallRows` (the impulses kept for the next step's warm start).
 */
import { type ContactBuffer, ContactKind, findWarmStart, storeWarmStart } from '../collision/contacts.js';
import type { CollisionState } from '../collision/state.js';
import { BodyType } from '../collision/state.js';
import { KERNEL, type KernelArray } from '../threads/kernels.js';
import { runOnPool } from '../threads/parallel.js';
import { isShared, sharedLike } from '../threads/pool.js';
import type { PhysicsWorld } from '../world/options.js';
import { shareContactBuffer, solveColoredSubsteps, startStripPlan, useColoredSolve } from './coloring.js';
import { ballContactHertz, ballContactPushSpeed, ballStickSpeed, contactLength } from './contact-scale.js';
import { applyImpacts, releaseImpactedRows } from './impacts.js';
import { prepareContacts2D } from './prepare-contacts-kernel.js';
import { approach2DStage, restitutionOnThreads, storeWarmStartOnThreads } from './stages-threads.js';
import { downward3Into, downwardInto, heavierAbove, holdsLower, markFirstRelaxRows, SUPPORT_COS } from './support.js';

/**
 * Stage 2 for the ball rows: prepares this step's rows (prepareContacts) with the friction stick
 * speed of the balls' size (solver/contact-scale.ts).
 * @category Collision
 */
export function prepareBallRows(world: PhysicsWorld, buf: ContactBuffer): void {
  prepareContacts(world, buf, ballStickSpeed(world.collision.settings, contactLength(buf)));
}

/**
 * Stages 3 and 4 for the ball rows, after the other rows are prepared: a threaded 2D world starts
 * planning the coloured solve (solver/coloring.ts), the impact stage runs (solver/impacts.ts), the
 * approach speeds are measured (unless the coloured solve takes the step and measures them on its
 * threads), and the soft coefficients of the substep `hs` (s) are set. `others` is true when joints or
 * shape manifolds share the solve. Returns true when the coloured solve takes the step.
 * @category Collision
 */
export function approachBallRows(world: PhysicsWorld, buf: ContactBuffer, others: boolean, hs: number): boolean {
  const is2D = world.dimensions === 2;
  if (is2D) startStripPlan(world, buf, others);
  applyImpacts(world, buf);
  const colored = is2D && useColoredSolve(world, buf, others);
  if (!colored) measureApproach(world, buf);
  const st = world.collision.settings;
  const length = contactLength(buf);
  // Softness (Box2D b2MakeSoft): stiffness from the balls' size, capped at the substep rate
  // (solver/contact-scale.ts); contacts against infinite mass twice as stiff.
  const hertz = ballContactHertz(st, length, hs);
  const sp = solveParams;
  sp[0] = hs;
  sp[1] = ballContactPushSpeed(st, length);
  makeSoftInto(sp, 4, hertz, st.contactDampingRatio, hs);
  makeSoftInto(sp, 7, 2 * hertz, st.contactDampingRatio, hs);
  return colored;
}

/**
 * Stage 5's start for the ball rows, after the joints are prepared: which way is down and which rows
 * the relax sweep takes first (solver/support.ts); then the coloured substeps when `colored`
 * (solver/coloring.ts), else the impacted rows are released (solver/impacts.ts).
 * @category Collision
 */
export function planBallRows(world: PhysicsWorld, buf: ContactBuffer, colored: boolean, hs: number): void {
  const cs = world.collision;
  const is2D = world.dimensions === 2;
  const sp = solveParams;
  downwardInto(world.gravity, sp, 2);
  if (!is2D) downward3Into(world.gravity, sp, 10);
  relaxFirst = markFirstRelaxRows(
    buf.ia,
    buf.ib,
    buf.nx,
    buf.ny,
    is2D ? null : buf.nz,
    buf.count,
    cs.solverBodyCount,
    cs.bodyState,
    is2D ? 8 : 12,
    sp,
    is2D ? 2 : 10,
  );
  // The coloured solve takes the impacted rows out after it plans (solver/coloring.ts), the others now.
  if (colored) solveColoredSubsteps(world, buf, hs, [sp[4]!, sp[5]!, sp[6]!, sp[7]!, sp[8]!, sp[9]!], sp[1]!);
  else releaseImpactedRows(buf);
}

/**
 * Applies every ball row's accumulated impulse (Box2D v3 warm start, once per substep).
 * @category Collision
 */
export function warmStartBallRows(world: PhysicsWorld, buf: ContactBuffer): void {
  if (world.dimensions === 2) warmStart2D(world.collision, buf);
  else warmStart3D(world.collision, buf);
}

/**
 * One Gauss-Seidel sweep over the ball rows: with soft bias if `useBias`, else the relax sweep.
 * @category Collision
 */
export function solveBallRows(world: PhysicsWorld, buf: ContactBuffer, useBias: boolean): void {
  if (world.dimensions === 2) solve2D(world.collision, buf, useBias);
  else solve3D(world.collision, buf, useBias);
}

/**
 * End of a substep for the ball rows: each row's accumulated impulse is what this substep delivered
 * (warm start plus corrections), added to its total.
 * @category Collision
 */
export function endBallSubstep(buf: ContactBuffer): void {
  const TOT = buf.totalNormalImpulse,
    LN = buf.normalImpulse;
  for (let i = 0, n = buf.count; i < n; i++) TOT[i] = TOT[i]! + LN[i]!;
}

/**
 * Stage 6 for the ball rows: the step's impulses are added up and the rows bounce (applyRestitution).
 * @category Collision
 */
export function ballRestitution(world: PhysicsWorld, buf: ContactBuffer): void {
  const IMP = buf.impulse,
    TOT = buf.totalNormalImpulse;
  for (let i = 0, n = buf.count; i < n; i++) IMP[i] = IMP[i]! + TOT[i]!;
  applyRestitution(world, buf);
}

/**
 * Keeps the step's ball rows for the next step's warm start, if `onThreads` on a worker of a threaded
 * 2D world while the step finishes (solver/stages-threads.ts); returns the contact buffer the next step fills.
 * @category Collision
 */
export function storeBallRows(world: PhysicsWorld, buf: ContactBuffer, onThreads: boolean): ContactBuffer {
  return (onThreads ? storeWarmStartOnThreads(world, buf) : null) ?? storeWarmStart(world.collision.cache, buf);
}

/**
 * Scratch of one contact solve (solveContacts), read by solve2D and solve3D: [0] the substep hs (s),
 * [1] the push-out speed cap (m/s), [2, 3] the unit vector along gravity (2D support rows; (0, 0)
 * without gravity), [4, 5, 6] the soft coefficients of contacts between movable bodies (bias rate
 * 1/s, mass scale, impulse scale), [7, 8, 9] those of contacts against infinite mass, [10, 11, 12]
 * the unit vector along gravity in 3D ((0, 0, 0) without gravity). The doubles pass
 * through this, not as arguments or object fields: V8 boxed (allocated) every double passed to a
 * sweep it did not inline, and each step made two coefficient objects and a direction array. Not world state.
 */
const solveParams = new Float64Array(13);

/** Per ball contact row of the step: 1 for the rows the relax sweep takes first (solver/support.ts markFirstRelaxRows). Not world state. */
let relaxFirst: Uint8Array = new Uint8Array(0);

/**
 * Writes the coefficients of a soft constraint, a spring of frequency `hertz` (Hz, >= 0) and damping
 * ratio `zeta` integrated implicitly over `h` (s), into out[at..at+2]: bias rate (1/s), mass scale and
 * impulse scale (Catto, "Soft Constraints", GDC 2011; Box2D v3 b2MakeSoft); hertz 0 gives 0, 1, 0.
 */
function makeSoftInto(out: Float64Array, at: number, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    out[at] = 0;
    out[at + 1] = 1;
    out[at + 2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  out[at] = omega / a1;
  out[at + 1] = a2 * a3;
  out[at + 2] = a3;
}

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
  A.push(
    buf.a,
    buf.b,
    buf.ia,
    buf.ib,
    buf.kind,
    buf.feature,
    buf.nx,
    buf.ny,
    buf.ra,
    buf.rb,
    cs.bodyState,
    M.restitution,
    M.friction,
    M.staticFriction,
    stamp,
    buf.normalMass,
    buf.tangentMass,
    buf.rigidPartner,
    buf.t1x,
    buf.t1y,
    buf.t1z,
    buf.restitution,
    buf.friction,
    buf.frictionBound,
    buf.relativeVelocity,
    buf.totalNormalImpulse,
    buf.impulse,
    buf.normalImpulse,
    buf.tangentImpulse1,
    buf.tangentImpulse2,
    buf.maxNormalImpulse,
    buf.stampA,
    buf.stampB,
    prev.kind,
    prev.a,
    prev.b,
    prev.feature,
    prev.stampA,
    prev.stampB,
    prev.normalImpulse,
    prev.tangentImpulse1,
    prev.tangentImpulse2,
    cache.slots,
  );
  const P = S.params;
  P[0] = stick;
  P[1] = box.restitution;
  P[2] = box.friction;
  P[3] = box.staticFriction;
  P[4] = cache.size === 0 ? 0 : prev.count;
  P[5] = cache.size;
  P[6] = ContactKind.Ball;
  P[7] = ContactKind.Boundary;
  if (pool !== null && runOnPool(pool, 'contactSolverSystem', KERNEL.prepareContacts2D, A, P, n, null, PREPARE_MIN_PER_THREAD) !== null)
    return;
  prepareContacts2D(A, P, null, 0, n);
}

/**
 * Prepares the step's ball contact rows: effective masses, tangent basis, combined material, stick or
 * slip, the predicted approach, and last step's impulses of the same pair (warm start). 2D: a range
 * kernel (prepare2DStage); the loop here is 3D.
 */
function prepareContacts(world: PhysicsWorld, buf: ContactBuffer, stick: number): void {
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
    SB = buf.stampB;
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
    const oa = IA[i]! * 12,
      ob = IB[i]! * 12;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const imA = sb[oa + 9]!,
      imB = sb[ob + 9]!;
    const iiA = sb[oa + 10]!,
      iiB = sb[ob + 10]!;
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
    const dvx = sb[ob]! - sb[oa]!,
      dvy = sb[ob + 1]! - sb[oa + 1]!,
      dvz = sb[ob + 2]! - sb[oa + 2]!;
    // Contact-point velocity: v + w x r with r_A = ra n, r_B = -rb n.
    const sx = -rb * sb[ob + 3]! - ra * sb[oa + 3]!,
      sy = -rb * sb[ob + 4]! - ra * sb[oa + 4]!,
      sz = -rb * sb[ob + 5]! - ra * sb[oa + 5]!;
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
    RV[i] = (sb[ob]! - sb[oa]!) * nx + (sb[ob + 1]! - sb[oa + 1]!) * ny + (sb[ob + 2]! - sb[oa + 2]!) * nz;
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
function measureApproach(world: PhysicsWorld, buf: ContactBuffer): void {
  // 2D: a range kernel, run on the threads or inline (solver/stages-threads.ts).
  if (world.dimensions === 2) {
    approach2DStage(world, buf);
    return;
  }
  const cs = world.collision;
  const sb = cs.bodyState,
    type = cs.bodyType;
  const g = world.gravity;
  const gx = g[0]!,
    gy = g[1]!,
    gz = g[2]!;
  const A = buf.a,
    B = buf.b,
    IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  const RV = buf.relativeVelocity,
    IV = buf.impactVelocity,
    S0 = buf.separation,
    IMP = buf.impulse;
  for (let i = 0, n = buf.count; i < n; i++) {
    const oa = IA[i]! * 12,
      ob = IB[i]! * 12;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const rv = (sb[ob]! - sb[oa]!) * nx + (sb[ob + 1]! - sb[oa + 1]!) * ny + (sb[ob + 2]! - sb[oa + 2]!) * nz;
    RV[i] = rv;
    // A row the impact stage bounced and that now separates keeps the approach speed of its impact.
    if (IMP[i]! > 0 && rv >= 0) continue;
    const gap = S0[i]!;
    if (!(rv < 0 && gap > 0)) {
      IV[i] = rv;
      continue;
    } // no gap to fall across: -sqrt(rv^2) = rv
    const a = A[i]!,
      b = B[i]!;
    const an = ((type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0)) * (gx * nx + gy * ny + gz * nz);
    const v2 = rv * rv - 2 * an * gap;
    IV[i] = v2 > 0 ? -Math.sqrt(v2) : rv;
  }
}

/** Applies every contact's accumulated impulse (Box2D v3 warm start, once per substep), 2D. */
function warmStart2D(cs: CollisionState, buf: ContactBuffer): void {
  const n = buf.count,
    sb = cs.bodyState;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    RA = buf.ra,
    RB = buf.rb;
  const LN = buf.normalImpulse,
    LT = buf.tangentImpulse1;
  for (let i = 0; i < n; i++) {
    const ln = LN[i]!,
      lt = LT[i]!;
    if (ln === 0 && lt === 0) continue;
    const a = IA[i]! * 8,
      b = IB[i]! * 8;
    sb[a + 7] = 1;
    sb[b + 7] = 1;
    const nx = NX[i]!,
      ny = NY[i]!;
    const Px = ln * nx - lt * ny,
      Py = ln * ny + lt * nx;
    const imA = sb[a + 5]!,
      imB = sb[b + 5]!;
    sb[a] = sb[a]! - imA * Px;
    sb[a + 1] = sb[a + 1]! - imA * Py;
    sb[b] = sb[b]! + imB * Px;
    sb[b + 1] = sb[b + 1]! + imB * Py;
    sb[a + 2] = sb[a + 2]! - sb[a + 6]! * RA[i]! * lt;
    sb[b + 2] = sb[b + 2]! - sb[b + 6]! * RB[i]! * lt;
  }
}

/** Applies every contact's accumulated impulse, 3D. Angular: dw_A = -I_A^-1 (ra n x P), dw_B = I_B^-1 (-rb n x P). */
function warmStart3D(cs: CollisionState, buf: ContactBuffer): void {
  const n = buf.count,
    sb = cs.bodyState;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz,
    RA = buf.ra,
    RB = buf.rb;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2;
  for (let i = 0; i < n; i++) {
    const ln = LN[i]!,
      l1 = L1[i]!,
      l2 = L2[i]!;
    if (ln === 0 && l1 === 0 && l2 === 0) continue;
    const a = IA[i]! * 12,
      b = IB[i]! * 12;
    sb[a + 11] = 1;
    sb[b + 11] = 1;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!,
      t1x = T1X[i]!,
      t1y = T1Y[i]!,
      t1z = T1Z[i]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const Px = ln * nx + l1 * t1x + l2 * t2x,
      Py = ln * ny + l1 * t1y + l2 * t2y,
      Pz = ln * nz + l1 * t1z + l2 * t2z;
    const imA = sb[a + 9]!,
      imB = sb[b + 9]!;
    sb[a] = sb[a]! - imA * Px;
    sb[a + 1] = sb[a + 1]! - imA * Py;
    sb[a + 2] = sb[a + 2]! - imA * Pz;
    sb[b] = sb[b]! + imB * Px;
    sb[b + 1] = sb[b + 1]! + imB * Py;
    sb[b + 2] = sb[b + 2]! + imB * Pz;
    const cx = ny * Pz - nz * Py,
      cy = nz * Px - nx * Pz,
      cz = nx * Py - ny * Px;
    const ka = sb[a + 10]! * RA[i]!,
      kb = sb[b + 10]! * RB[i]!;
    sb[a + 3] = sb[a + 3]! - ka * cx;
    sb[a + 4] = sb[a + 4]! - ka * cy;
    sb[a + 5] = sb[a + 5]! - ka * cz;
    sb[b + 3] = sb[b + 3]! - kb * cx;
    sb[b + 4] = sb[b + 4]! - kb * cy;
    sb[b + 5] = sb[b + 5]! - kb * cz;
  }
}

/**
 * One Gauss-Seidel sweep over the 2D ball contacts: with soft bias if `useBias`, else the relax sweep,
 * which takes the rows against static bodies first and last and solves the support rows (frictionless,
 * or with the heavier ball above) with the lower ball held when that only slows the upper one
 * (solver/support.ts; (downX, downY) is the unit vector along gravity, (0, 0) without). The substep,
 * push-out cap, down vector and soft coefficients are read from `solveParams`.
 */
function solve2D(cs: CollisionState, buf: ContactBuffer, useBias: boolean): void {
  const sp = solveParams;
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[2]!,
    downY = sp[3]!;
  const n = buf.count,
    sb = cs.bodyState;
  const invH = 1 / hs;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    RA = buf.ra,
    RB = buf.rb,
    S0 = buf.separation;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    FB = buf.frictionBound,
    RP = buf.rigidPartner;
  const LN = buf.normalImpulse,
    LT = buf.tangentImpulse1,
    MAXN = buf.maxNormalImpulse;
  const dBias = sp[4]!,
    dMass = sp[5]!,
    dImp = sp[6]!;
  const rBias = sp[7]!,
    rMass = sp[8]!,
    rImp = sp[9]!;

  // The sweep with bias takes the rows in order. The relax sweep takes first the touching rows that
  // hold a ball under a heavier one against a static body (solver/support.ts markFirstRelaxRows), so that ball
  // is at rest when the support row above it is relaxed and may hold it, taking the heavy ball's
  // push-out speed away; then the rows between two balls; then the rows against static bodies (walls,
  // floor, segments), which take out what the others pushed into them.
  const first = relaxFirst;
  const end = useBias ? n : 3 * n;
  for (let k = 0; k < end; k++) {
    const i = k < n ? k : k < 2 * n ? k - n : k - 2 * n;
    if (!useBias && (k < n ? first[i] === 0 : k < 2 * n === (IA[i] === 0))) continue;
    const a = IA[i]! * 8,
      b = IB[i]! * 8;
    const nx = NX[i]!,
      ny = NY[i]!;
    const imA = sb[a + 5]!,
      imB = sb[b + 5]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!;
    // The normal impulse's inverse masses and effective mass: a support row of the relax sweep, one
    // without friction or one whose upper ball is the heavier, may hold its lower ball (solver/support.ts).
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny);
      if ((up > SUPPORT_COS || up < -SUPPORT_COS) && (FB[i] === 0 || (up > 0 ? heavierAbove(imA, imB) : heavierAbove(imB, imA)))) {
        const va = Math.abs(vax * nx + vay * ny),
          vb = Math.abs(vbx * nx + vby * ny);
        if (up > 0 ? holdsLower(va, vb) : holdsLower(vb, va)) {
          if (up > 0) jmA = 0;
          else jmB = 0;
          nm = 1 / (jmA + jmB);
        }
      }
    }

    // Non-penetration, soft when overlapping and useBias, speculative when apart.
    const s = S0[i]! + (sb[b + 3]! - sb[a + 3]!) * nx + (sb[b + 4]! - sb[a + 4]!) * ny;
    let bias = 0,
      massScale = 1,
      impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      if (RP[i] === 1) {
        bias = rBias * s;
        massScale = rMass;
        impulseScale = rImp;
      } else {
        bias = dBias * s;
        massScale = dMass;
        impulseScale = dImp;
      }
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny;
    const oldN = LN[i]!;
    // A speculative row with no impulse whose gap stays open this substep does nothing (every impulse below is 0).
    if (s > 0 && oldN === 0 && vn + bias >= 0 && LT[i] === 0) continue;
    let lambda = -nm * massScale * (vn + bias) - impulseScale * oldN;
    let newN = oldN + lambda;
    if (newN < 0) newN = 0;
    lambda = newN - oldN;
    LN[i] = newN;
    if (lambda > MAXN[i]!) MAXN[i] = lambda;
    let Px = lambda * nx,
      Py = lambda * ny;
    vax -= jmA * Px;
    vay -= jmA * Py;
    vbx += jmB * Px;
    vby += jmB * Py;

    // Coulomb friction along t = (-ny, nx) at the contact point.
    const ra = RA[i]!,
      rb = RB[i]!;
    let wa = sb[a + 2]!,
      wb = sb[b + 2]!;
    const vt = (vbx - vax) * -ny + (vby - vay) * nx - wb * rb - wa * ra;
    lambda = -TM[i]! * vt;
    const maxF = FB[i]! * newN;
    const oldT = LT[i]!;
    let newT = oldT + lambda;
    newT = newT < -maxF ? -maxF : newT > maxF ? maxF : newT;
    lambda = newT - oldT;
    LT[i] = newT;
    Px = -lambda * ny;
    Py = lambda * nx;
    vax -= imA * Px;
    vay -= imA * Py;
    vbx += imB * Px;
    vby += imB * Py;
    wa -= sb[a + 6]! * ra * lambda;
    wb -= sb[b + 6]! * rb * lambda;

    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = wa;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = wb;
    if (newN !== 0 || newT !== 0) {
      sb[a + 7] = 1;
      sb[b + 7] = 1;
    }
  }
}

/**
 * One Gauss-Seidel sweep over the 3D ball contacts (with soft bias if `useBias`); parameters from
 * `solveParams` as solve2D, and its relax sweep as solve2D's: static rows first and last, support rows
 * (frictionless or with the heavier ball above) holding their lower ball when that only slows the upper.
 */
function solve3D(cs: CollisionState, buf: ContactBuffer, useBias: boolean): void {
  const sp = solveParams;
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[10]!,
    downY = sp[11]!,
    downZ = sp[12]!;
  const n = buf.count,
    sb = cs.bodyState;
  const invH = 1 / hs;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz,
    RA = buf.ra,
    RB = buf.rb,
    S0 = buf.separation;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    FB = buf.frictionBound,
    RP = buf.rigidPartner;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2,
    MAXN = buf.maxNormalImpulse;

  // Row order as in solve2D: the relax sweep takes the rows under heavier balls, the ball pairs, the static rows.
  const first = relaxFirst;
  const end = useBias ? n : 3 * n;
  for (let k = 0; k < end; k++) {
    const i = k < n ? k : k < 2 * n ? k - n : k - 2 * n;
    if (!useBias && (k < n ? first[i] === 0 : k < 2 * n === (IA[i] === 0))) continue;
    const a = IA[i]! * 12,
      b = IB[i]! * 12;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const imA = sb[a + 9]!,
      imB = sb[b + 9]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      vaz = sb[a + 2]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!,
      vbz = sb[b + 2]!;
    // A support row of the relax sweep may hold its lower ball (solver/support.ts), as in solve2D.
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny + downZ * nz);
      if ((up > SUPPORT_COS || up < -SUPPORT_COS) && (FB[i] === 0 || (up > 0 ? heavierAbove(imA, imB) : heavierAbove(imB, imA)))) {
        const va = Math.abs(vax * nx + vay * ny + vaz * nz),
          vb = Math.abs(vbx * nx + vby * ny + vbz * nz);
        if (up > 0 ? holdsLower(va, vb) : holdsLower(vb, va)) {
          if (up > 0) jmA = 0;
          else jmB = 0;
          nm = 1 / (jmA + jmB);
        }
      }
    }

    const s = S0[i]! + (sb[b + 6]! - sb[a + 6]!) * nx + (sb[b + 7]! - sb[a + 7]!) * ny + (sb[b + 8]! - sb[a + 8]!) * nz;
    let bias = 0,
      massScale = 1,
      impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      const at = RP[i] === 1 ? 7 : 4;
      bias = sp[at]! * s;
      massScale = sp[at + 1]!;
      impulseScale = sp[at + 2]!;
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny + (vbz - vaz) * nz;
    const oldN = LN[i]!;
    let newN = oldN - nm * massScale * (vn + bias) - impulseScale * oldN;
    if (newN < 0) newN = 0;
    const dl = newN - oldN;
    LN[i] = newN;
    if (dl > MAXN[i]!) MAXN[i] = dl;
    vax -= jmA * dl * nx;
    vay -= jmA * dl * ny;
    vaz -= jmA * dl * nz;
    vbx += jmB * dl * nx;
    vby += jmB * dl * ny;
    vbz += jmB * dl * nz;

    // Friction in the tangent plane, clamped to the Coulomb cone.
    const ra = RA[i]!,
      rb = RB[i]!;
    let wax = sb[a + 3]!,
      way = sb[a + 4]!,
      waz = sb[a + 5]!,
      wbx = sb[b + 3]!,
      wby = sb[b + 4]!,
      wbz = sb[b + 5]!;
    let ux = vbx - vax,
      uy = vby - vay,
      uz = vbz - vaz;
    const sx = -rb * wbx - ra * wax,
      sy = -rb * wby - ra * way,
      sz = -rb * wbz - ra * waz;
    ux += sy * nz - sz * ny;
    uy += sz * nx - sx * nz;
    uz += sx * ny - sy * nx;
    const t1x = T1X[i]!,
      t1y = T1Y[i]!,
      t1z = T1Z[i]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const tm = TM[i]!;
    const o1 = L1[i]!,
      o2 = L2[i]!;
    let n1 = o1 - tm * (ux * t1x + uy * t1y + uz * t1z);
    let n2 = o2 - tm * (ux * t2x + uy * t2y + uz * t2z);
    const maxF = FB[i]! * newN;
    const mag2 = n1 * n1 + n2 * n2;
    if (mag2 > maxF * maxF) {
      const k = maxF / Math.sqrt(mag2);
      n1 *= k;
      n2 *= k;
    }
    const d1 = n1 - o1,
      d2 = n2 - o2;
    L1[i] = n1;
    L2[i] = n2;
    if (d1 !== 0 || d2 !== 0) {
      const Px = d1 * t1x + d2 * t2x,
        Py = d1 * t1y + d2 * t2y,
        Pz = d1 * t1z + d2 * t2z;
      vax -= imA * Px;
      vay -= imA * Py;
      vaz -= imA * Pz;
      vbx += imB * Px;
      vby += imB * Py;
      vbz += imB * Pz;
      const cx = ny * Pz - nz * Py,
        cy = nz * Px - nx * Pz,
        cz = nx * Py - ny * Px;
      const ka = sb[a + 10]! * ra,
        kb = sb[b + 10]! * rb;
      wax -= ka * cx;
      way -= ka * cy;
      waz -= ka * cz;
      wbx -= kb * cx;
      wby -= kb * cy;
      wbz -= kb * cz;
    }
    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = vaz;
    sb[a + 3] = wax;
    sb[a + 4] = way;
    sb[a + 5] = waz;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = vbz;
    sb[b + 3] = wbx;
    sb[b + 4] = wby;
    sb[b + 5] = wbz;
    if (newN !== 0 || n1 !== 0 || n2 !== 0) {
      sb[a + 11] = 1;
      sb[b + 11] = 1;
    }
  }
}

/** Scratch of applyRestitution: the indices of the rows that take part, in row order. Not world state. */
let restitutionRows = new Int32Array(256);

/**
 * Restitution, after Box2D v3 b2ApplyRestitution but solved as a small LCP rather than one pass.
 * A contact that approached faster than the threshold and carried an impulse this step must leave
 * with normal speed v_n >= -e v_impact, where v_impact is the approach speed at impact (start-of-step
 * speed plus gravity across the speculative gap); every other contact that carried an impulse must
 * not approach (v_n >= 0). `restitutionIterations` sequential-impulse passes solve these together with
 * a non-negative accumulated impulse, so coupled bounces in a dense pile share the rebound instead of
 * each contact adding its own on top of its neighbours'. A contact's rebound impulse is capped at e
 * times its compression impulse (delivered this step, plus what still stops a residual approach):
 * Poisson's hypothesis (Stronge, Impact Mechanics, 2000, ch. 2), which keeps a perfectly elastic
 * pile from creating energy.
 */
function applyRestitution(world: PhysicsWorld, buf: ContactBuffer): void {
  if (restitutionOnThreads(world, buf)) return; // after a coloured solve: by colours (solver/stages-threads.ts)
  const cs = world.collision;
  const threshold = cs.settings.restitutionThreshold,
    elasticThreshold = cs.settings.elasticRestitutionThreshold;
  const iterations = cs.settings.restitutionIterations;
  const n = buf.count,
    sb = cs.bodyState;
  const S = world.dimensions === 2 ? 8 : 12,
    is2D = S === 8,
    im = is2D ? 5 : 9;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  const NM = buf.normalMass,
    E = buf.restitution,
    RV = buf.relativeVelocity,
    IV = buf.impactVelocity;
  const MAXN = buf.maxNormalImpulse,
    TOT = buf.totalNormalImpulse,
    IMP = buf.impulse;
  // Reuse relativeVelocity as the target speed, maxNormalImpulse as the rebound's accumulated impulse
  // and totalNormalImpulse as its cap (all spent by now); a negative target marks a contact that
  // takes no part. A contact that closed its gap only in the last substep may still be approaching:
  // the impulse to stop that is part of its compression, so it counts toward the cap too.
  // The rows that take part, in row order (the passes below visit only these).
  if (restitutionRows.length < n) restitutionRows = new Int32Array(Math.max(n, 2 * restitutionRows.length));
  const rows = restitutionRows;
  let taking = 0;
  let bouncing = 0;
  for (let i = 0; i < n; i++) {
    const e = E[i]!;
    if (MAXN[i] === 0) {
      RV[i] = -1;
      continue;
    }
    rows[taking++] = i;
    MAXN[i] = 0;
    if (e > 0 && RV[i]! < -(e >= 1 ? elasticThreshold : threshold)) {
      RV[i] = -e * IV[i]!;
      const a = IA[i]! * S,
        b = IB[i]! * S;
      let vn = (sb[b]! - sb[a]!) * NX[i]! + (sb[b + 1]! - sb[a + 1]!) * NY[i]!;
      if (!is2D) vn += (sb[b + 2]! - sb[a + 2]!) * NZ[i]!;
      const stop = vn < 0 ? -NM[i]! * vn : 0;
      TOT[i] = stop + e * (TOT[i]! + stop);
      bouncing++;
    } else RV[i] = 0;
  }
  if (bouncing === 0) return;
  for (let it = 0; it < iterations; it++) {
    for (let k = 0; k < taking; k++) {
      const i = rows[k]!;
      const target = RV[i]!;
      const a = IA[i]! * S,
        b = IB[i]! * S;
      const nx = NX[i]!,
        ny = NY[i]!,
        nz = NZ[i]!;
      let vn = (sb[b]! - sb[a]!) * nx + (sb[b + 1]! - sb[a + 1]!) * ny;
      if (!is2D) vn += (sb[b + 2]! - sb[a + 2]!) * nz;
      const old = MAXN[i]!;
      let acc = old - NM[i]! * (vn - target);
      if (acc < 0) acc = 0;
      if (target > 0 && acc > TOT[i]!) acc = TOT[i]!;
      const dl = acc - old;
      if (dl === 0) continue;
      MAXN[i] = acc;
      IMP[i] = IMP[i]! + dl;
      const ka = sb[a + im]! * dl,
        kb = sb[b + im]! * dl;
      sb[a] = sb[a]! - ka * nx;
      sb[a + 1] = sb[a + 1]! - ka * ny;
      sb[b] = sb[b]! + kb * nx;
      sb[b + 1] = sb[b + 1]! + kb * ny;
      if (!is2D) {
        sb[a + 2] = sb[a + 2]! - ka * nz;
        sb[b + 2] = sb[b + 2]! + kb * nz;
      }
    }
  }
}
