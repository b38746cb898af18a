import { MAX_MANIFOLDS } from '../collision/manifold-limits-2d.js';
import type { ManifoldBuffer } from '../collision/manifolds-2d.js';
import type { CollisionState } from '../collision/state.js';
import type { PhysicsWorld } from '../world/options.js';
import * as BS from './body-state-layout.js';
import { storeVelocities2D } from './body-velocities.js';
import { bouncingList, boundedImpulse, normalBias, normalImpulse, softRow } from './contact-point.js';
import { CP_NORMAL_MASS, CP_SEPARATION, SN_BIAS, SN_RIGID, SN_RIGID_BIAS, SN_SCALES, SN_SOFT_ROW } from './contact-point-layout.js';
import * as M2 from './manifold-layout-2d.js';
import { restitutionCap, restitutionImpulse, restitutionTarget } from './restitution.js';
import { rigidPartner } from './rigid-partner.js';

/**
 * The shape contacts' rows of the contact solver (solver/contact-solver.ts runs these calls next to the ball
 * contacts', in the same substeps, on the same packed body state): Box2D v3's manifold constraint
 * (contact_solver.c), 2D:
 *
 * - each point has fixed anchors r_A, r_B from the centres of mass (where the bodies were at the start
 *   of the step); its separation is tracked as s = s0 + (d_B + dtheta_B x r_B - d_A - dtheta_A x r_A) . n,
 *   with d and dtheta the bodies' displacement and rotation so far in the step (rotation linearised),
 *   that is s0 + (d_B - d_A) . n + dtheta_B (r_B x n) - dtheta_A (r_A x n): the rows keep only the
 *   cross products r x n and r x t (solver/manifold-layout-2d.ts MP_RNA), not the anchors;
 * - normal rows: effective mass 1 / (1/m_A + 1/m_B + (r_A x n)^2 / I_A + (r_B x n)^2 / I_B); the two
 *   rows of a two-point manifold are solved together with their 2 x 2 effective mass (Box2D 2.x's block
 *   solver, a small complementarity problem; soft rows with the soft update written for both rows), so
 *   a face hit, a warm start undone or a heavy load does not spin or tip the body the way one point
 *   after the other does; rows nearly dependent point by point;
 *   speculative (s > 0: bias s / h_s) or soft (s < 0: Box2D's soft constraint, the stiffer softness
 *   against infinite mass, push-out speed capped), accumulated impulse >= 0, warm-started from the
 *   previous step's point with the same feature id;
 * - friction rows along t = (-n_y, n_x): |lambda_t| <= mu lambda_n per point (mu_s while sticking);
 * - a row that carries an impulse (a point's normal or friction impulse, or the rolling impulse, not
 *   0) marks its bodies as pushed (the `pushed` slot of the packed body, as ball contacts and joints
 *   do): they were not in free flight this step, and finishBodies does not give them the free-flight
 *   position correction (-g h h_s / 2), which on a resting box is a drop of 0.34 mm a step at 4
 *   substeps of 1/60 s that the contact then pushes back: on a slope, a creep of mm a second;
 * - rolling resistance (circles and capsules): a torque row on w_B - w_A bounded by the coefficient
 *   times the rolling radius times the manifold's normal impulse (Box2D v3.1's rolling resistance);
 * - restitution after the substeps, by the one definition every row family shares (solver/restitution.ts,
 *   after Box2D v3 b2ApplyRestitution): a point that approached faster than the threshold and carried an
 *   impulse leaves with v_n >= -e v_n0, its rebound within Poisson's cap;
 * - finally, which pairs touch (a point carried a normal impulse, or overlapped) gives the begin and
 *   end touch events, and the rows become the warm-start cache of the next step.
 */
/**
 * `a` if it holds `n` numbers, else a new zeroed array of at least n (twice a's length). Growth runs
 * only in a world's first steps: called before the loops that fill the array (solver/manifold-prepare-2d.ts withRoom).
 */
export function atLeast(a: Float64Array, n: number): Float64Array {
  return a.length >= n ? a : new Float64Array(Math.max(n, 2 * a.length));
}

/**
 * Writes the packed rows' impulses back to the manifold buffer (after the substeps and restitution):
 * the touch events read the step's total normal impulses, and the buffer becomes the next step's
 * warm-start cache.
 * @category Collision
 */
export function storeManifoldImpulses(cs: CollisionState): void {
  const buf = cs.shapes.manifolds;
  storeRows(buf, cs.shapes.solverRows, buf.count);
}

/**
 * storeManifoldImpulses' loop over the first `n` rows of R into `buf`. Nothing is read before the loop:
 * a world's first call runs the lines before it before V8 gives the function type feedback, V8 compiles
 * the loop while it runs, and the whole function again at the next call, whose lines before the loop
 * then lacked feedback and threw that code away (the same for warmStartRows).
 */
function storeRows(buf: ManifoldBuffer, R: Float64Array, n: number): void {
  for (let i = 0; i < n; i++) {
    const r = i * M2.MR_STRIDE;
    buf.rollingImpulse[i] = R[r + M2.MR_ROLLING_IMPULSE]!;
    for (let p = 0, m = buf.pointCount[i]!; p < m; p++) {
      const q = 2 * i + p,
        o = r + M2.MR_POINT0 + p * M2.MP_STRIDE;
      buf.normalImpulse[q] = R[o + M2.MP_NORMAL_IMPULSE]!;
      buf.tangentImpulse[q] = R[o + M2.MP_TANGENT_IMPULSE]!;
      buf.totalNormalImpulse[q] = R[o + M2.MP_TOTAL_NORMAL_IMPULSE]!;
    }
  }
}

/**
 * Applies every manifold point's accumulated impulses (once per substep).
 * @category Collision
 */
export function warmStartManifolds(cs: CollisionState): void {
  warmStartRows(cs.shapes.solverRows, cs.bodyState, Math.min(cs.shapes.manifolds.count, MAX_MANIFOLDS));
}

/** warmStartManifolds' loop over the first `n` rows of R, on the packed body state sb (see storeRows). */
function warmStartRows(R: Float64Array, sb: Float64Array, n: number): void {
  for (let i = 0; i < n; i++) {
    const r = i * M2.MR_STRIDE;
    const a = (R[r + M2.MR_BODY_A]! & M2.MR_BODY_MASK) * BS.BS2_STRIDE,
      b = (R[r + M2.MR_BODY_B]! & M2.MR_BODY_MASK) * BS.BS2_STRIDE;
    const mA = sb[a + BS.BS2_INV_MASS]!,
      iA = sb[a + BS.BS2_INV_INERTIA]!,
      mB = sb[b + BS.BS2_INV_MASS]!,
      iB = sb[b + BS.BS2_INV_INERTIA]!;
    const nx = R[r + M2.MR_NX]!,
      ny = R[r + M2.MR_NY]!;
    let vax = sb[a + BS.BS2_VX]!,
      vay = sb[a + BS.BS2_VY]!,
      wa = sb[a + BS.BS2_W]!,
      vbx = sb[b + BS.BS2_VX]!,
      vby = sb[b + BS.BS2_VY]!,
      wb = sb[b + BS.BS2_W]!;
    // Each point's normal and friction impulse; whether the row carries an impulse (it pushes its
    // bodies) from the impulses read.
    let carries = false;
    for (let p = 0, m = R[r + M2.MR_POINT_COUNT]!; p < m; p++) {
      const o = r + M2.MR_POINT0 + p * M2.MP_STRIDE;
      const ln = R[o + M2.MP_NORMAL_IMPULSE]!,
        lt = R[o + M2.MP_TANGENT_IMPULSE]!;
      const Px = ln * nx - lt * ny,
        Py = ln * ny + lt * nx;
      // r x (ln n + lt t) = ln (r x n) + lt (r x t).
      wa -= iA * (ln * R[o + M2.MP_RNA]! + lt * R[o + M2.MP_RTA]!);
      vax -= mA * Px;
      vay -= mA * Py;
      wb += iB * (ln * R[o + M2.MP_RNB]! + lt * R[o + M2.MP_RTB]!);
      vbx += mB * Px;
      vby += mB * Py;
      carries = carries || ln !== 0 || lt !== 0;
    }
    const lr = R[r + M2.MR_ROLLING_IMPULSE]!;
    wa -= iA * lr;
    wb += iB * lr;
    storeVelocities2D(sb, a, b, vax, vay, wa, vbx, vby, wb);
    // The marks are written on every row (kept at 1, or set when the row carries an impulse): stores
    // made only when a row carries one would not run in a world's first step (every contact new, no
    // impulse yet), and code V8 compiled then would be thrown away at the first row that does.
    const carry = carries || lr !== 0 ? 1 : 0;
    sb[a + BS.BS2_PUSHED] = sb[a + BS.BS2_PUSHED]! || carry;
    sb[b + BS.BS2_PUSHED] = sb[b + BS.BS2_PUSHED]! || carry;
  }
}

/**
 * The two normal impulses x of the manifold whose packed row starts at `r`, from the linear
 * complementarity problem K x + c = w, x >= 0, w >= 0, x . w = 0 with the row's block K (Box2D 2.x's
 * block solver: its four cases tried in turn, both points pushing first, then one point letting go,
 * then both). Writes x as the row's normal impulses and returns true, or returns false and leaves the
 * row as it was if no case holds. Soft rows (overlap with bias) that both push are solved as a block
 * too: one point after the other, a column of light boxes under a heavy one (1 kg boxes, 100 kg on
 * top) tips its boxes a little at every pass, the tilt grows and the column buckles; the block keeps
 * the two points' impulses symmetric, and the column stands.
 */
function solveBlock(R: Float64Array, r: number, c1: number, c2: number): boolean {
  const K11 = R[r + M2.MR_K11]!,
    K22 = R[r + M2.MR_K22]!,
    K12 = R[r + M2.MR_K12]!;
  const B11 = R[r + M2.MR_B11]!,
    B12 = R[r + M2.MR_B12]!,
    B22 = R[r + M2.MR_B22]!;
  let n1 = -(B11 * c1 + B12 * c2),
    n2 = -(B12 * c1 + B22 * c2);
  let ok = n1 >= 0 && n2 >= 0;
  // A point that lets go (one or both impulses 0: an impact undone, a box lifting off an edge).
  if (!ok) {
    n1 = -c1 / K11;
    n2 = 0;
    ok = n1 >= 0 && K12 * n1 + c2 >= 0;
  }
  if (!ok) {
    n1 = 0;
    n2 = -c2 / K22;
    ok = n2 >= 0 && K12 * n2 + c1 >= 0;
  }
  if (!ok) {
    n1 = 0;
    n2 = 0;
    ok = c1 >= 0 && c2 >= 0;
  }
  if (ok) {
    R[r + M2.MR_POINT0 + M2.MP_NORMAL_IMPULSE] = n1;
    R[r + M2.MR_POINT0 + M2.MP_STRIDE + M2.MP_NORMAL_IMPULSE] = n2;
  }
  return ok;
}

/**
 * The rolling resistance row of the manifold whose packed row starts at `r` (its `MR_ROLLING` > 0): the
 * accumulated torque impulse about the normal, bounded by the rolling coefficient times the rolling
 * radius times `total` (the manifold's normal impulse), updated against the relative spin `dw`
 * (w_B - w_A, rad/s). Returns the impulse added, N m s (A gets minus it).
 */
function solveRolling(R: Float64Array, r: number, total: number, dw: number): number {
  const old = R[r + M2.MR_ROLLING_IMPULSE]!;
  const next = boundedImpulse(old, R[r + M2.MR_ROLLING_MASS]!, dw, R[r + M2.MR_ROLLING]! * total);
  R[r + M2.MR_ROLLING_IMPULSE] = next;
  return next - old;
}

/** Adds the normal impulses of the row whose first point starts at `o1` (two points if `two`) to their step totals. */
function accumulateRow(R: Float64Array, o1: number, two: boolean): void {
  R[o1 + M2.MP_TOTAL_NORMAL_IMPULSE] = R[o1 + M2.MP_TOTAL_NORMAL_IMPULSE]! + R[o1 + M2.MP_NORMAL_IMPULSE]!;
  const o2 = o1 + M2.MP_STRIDE;
  if (two) R[o2 + M2.MP_TOTAL_NORMAL_IMPULSE] = R[o2 + M2.MP_TOTAL_NORMAL_IMPULSE]! + R[o2 + M2.MP_NORMAL_IMPULSE]!;
}

/**
 * One pass over the manifolds: normal rows (soft bias if `useBias`), friction, rolling resistance, with
 * the softness `prepareManifolds` chose. The substep's impulses are added to the step's totals by
 * accumulateManifoldImpulses after its last pass, a loop of its own: a call to it here, made only in
 * the last pass, would have no type feedback when V8 compiles this loop during a first step's earlier
 * passes, and the compiled code would be thrown away at the first last pass.
 *
 * Per row: the bodies' velocities and the row's normal impulses are read into locals once and written
 * back once (offsets in 32-bit integers without overflow checks: the row count is bounded by
 * MAX_MANIFOLDS, the body indices masked by MR_BODY_MASK); points 1 and 2 are unrolled, their levers
 * (r x n and r x t on each body, worked out once a step by prepareManifolds) read once (a one-point row
 * reads its unused second point's slots, inside the row, and never uses them). Each normal row's regime: speculative (s > 0: bias s / h_s, rigid) or, with the bias on, soft.
 * A two-point row with a valid block solves both normal rows at once, as the linear complementarity
 * problem K x + c = w, x >= 0, w >= 0, x . w = 0 of `solveBlock` (both points push, then one lets go,
 * then both), with x the new accumulated impulses and c from each row's own regime,
 * c_i = s_m (v_n,i + bias_i) - (1 - s_i) (K x_old)_i: the soft row's update written for both rows (s_m,
 * s_i its mass and impulse scales). Otherwise point after point, with the velocities the one before
 * left. Then friction, point 1 then point 2 (|lambda_t| <= bound lambda_n), and rolling resistance. A
 * row that carries an impulse marks its bodies as pushed (see the module comment).
 * @category Collision
 */
export function solveManifolds(cs: CollisionState, hs: number, useBias: boolean): void {
  const shapes = cs.shapes;
  // The push-out speed cap as a lower bound of the bias.
  const minBias = -cs.settings.contactPushSpeed;
  const n = Math.min(shapes.manifolds.count, MAX_MANIFOLDS);
  solveRows(shapes.solverRows, cs.bodyState, cs.bodyExtra, shapes.angleBase, shapes.softness, 1 / hs, minBias, useBias ? 1 : 0, n);
}

/**
 * solveManifolds' loop over the first `n` rows of R (see storeRows), with the packed body state and
 * extras sb and ex, the rotations at the step's start `base`, the softness table T, 1 / h_s `invH`
 * (1/s), the bias's lower bound `minBias` (m/s) and `biasOn` (1: soft rows take their bias).
 * The bias and scales against an infinite-mass partner (solver/rigid-partner.ts) are read at an index,
 * not in a branch, so the load has type feedback from the first manifold whichever kind that is (a
 * branch first taken after V8 compiled this loop threw its code away). Each normal row takes its own
 * regime (solver/contact-point.ts): bias, mass and impulse scales. Friction runs point 1 then point 2:
 * v_t = (v_B - v_A) . t + w_B (r_B x t) - w_A (r_A x t), t = (-n_y, n_x).
 */
function solveRows(
  R: Float64Array,
  sb: Float64Array,
  ex: Float64Array,
  base: Float64Array,
  T: Float64Array,
  invH: number,
  minBias: number,
  biasOn: number,
  n: number,
): void {
  for (let i = 0; i < n; i++) {
    const r = i * M2.MR_STRIDE;
    const ia = R[r + M2.MR_BODY_A]! & M2.MR_BODY_MASK,
      ib = R[r + M2.MR_BODY_B]! & M2.MR_BODY_MASK;
    const a = ia * BS.BS2_STRIDE,
      b = ib * BS.BS2_STRIDE;
    const mA = sb[a + BS.BS2_INV_MASS]!,
      iA = sb[a + BS.BS2_INV_INERTIA]!,
      mB = sb[b + BS.BS2_INV_MASS]!,
      iB = sb[b + BS.BS2_INV_INERTIA]!;
    let vax = sb[a + BS.BS2_VX]!,
      vay = sb[a + BS.BS2_VY]!,
      wa = sb[a + BS.BS2_W]!,
      vbx = sb[b + BS.BS2_VX]!,
      vby = sb[b + BS.BS2_VY]!,
      wb = sb[b + BS.BS2_W]!;
    const dax = sb[a + BS.BS2_DX]!,
      day = sb[a + BS.BS2_DY]!,
      dbx = sb[b + BS.BS2_DX]!,
      dby = sb[b + BS.BS2_DY]!;
    const ta = ia === 0 ? 0 : ex[ia * BS.BX_STRIDE + BS.BX_ROT_Z]! - base[ia]!,
      tb = ib === 0 ? 0 : ex[ib * BS.BX_STRIDE + BS.BX_ROT_Z]! - base[ib]!;
    const nx = R[r + M2.MR_NX]!,
      ny = R[r + M2.MR_NY]!;
    const rigid = rigidPartner(mA, mB);
    const biasRate = T[SN_BIAS + rigid * (SN_RIGID_BIAS - SN_BIAS)]!,
      scales = SN_SCALES + SN_RIGID * rigid;
    const two = R[r + M2.MR_POINT_COUNT] === 2;
    const o1 = r + M2.MR_POINT0,
      o2 = o1 + M2.MP_STRIDE;
    const n1a = R[o1 + M2.MP_RNA]!,
      n1b = R[o1 + M2.MP_RNB]!,
      t1a = R[o1 + M2.MP_RTA]!,
      t1b = R[o1 + M2.MP_RTB]!;
    const n2a = R[o2 + M2.MP_RNA]!,
      n2b = R[o2 + M2.MP_RNB]!,
      t2a = R[o2 + M2.MP_RTA]!,
      t2b = R[o2 + M2.MP_RTB]!;
    const dn = (dbx - dax) * nx + (dby - day) * ny;
    const s1 = R[o1 + CP_SEPARATION]! + dn + tb * n1b - ta * n1a;
    const s2 = R[o2 + CP_SEPARATION]! + dn + tb * n2b - ta * n2a;
    const soft1 = softRow(s1, biasOn),
      soft2 = softRow(s2, biasOn);
    const b1 = normalBias(s1, invH, biasRate, minBias, soft1),
      b2 = normalBias(s2, invH, biasRate, minBias, soft2);
    const sel1 = scales + SN_SOFT_ROW * soft1,
      sel2 = scales + SN_SOFT_ROW * soft2;
    const m1 = T[sel1]!,
      i1 = T[sel1 + 1]!,
      m2 = T[sel2]!,
      i2 = T[sel2 + 1]!;
    let l1 = R[o1 + M2.MP_NORMAL_IMPULSE]!,
      l2 = R[o2 + M2.MP_NORMAL_IMPULSE]!;
    let total = 0;
    let solved = false;
    if (R[r + M2.MR_BLOCK_VALID] === 1) {
      const dvn = (vbx - vax) * nx + (vby - vay) * ny;
      const vn1 = dvn + wb * n1b - wa * n1a;
      const vn2 = dvn + wb * n2b - wa * n2a;
      const K11 = R[r + M2.MR_K11]!,
        K22 = R[r + M2.MR_K22]!,
        K12 = R[r + M2.MR_K12]!;
      const c1 = m1 * (vn1 + b1) - (1 - i1) * (K11 * l1 + K12 * l2);
      const c2 = m2 * (vn2 + b2) - (1 - i2) * (K12 * l1 + K22 * l2);
      solved = solveBlock(R, r, c1, c2);
      if (solved) {
        const n1 = R[o1 + M2.MP_NORMAL_IMPULSE]!,
          n2 = R[o2 + M2.MP_NORMAL_IMPULSE]!;
        const d1 = n1 - l1,
          d2 = n2 - l2;
        if (d1 > R[o1 + M2.MP_MAX_NORMAL_IMPULSE]!) R[o1 + M2.MP_MAX_NORMAL_IMPULSE] = d1;
        if (d2 > R[o2 + M2.MP_MAX_NORMAL_IMPULSE]!) R[o2 + M2.MP_MAX_NORMAL_IMPULSE] = d2;
        l1 = n1;
        l2 = n2;
        total = n1 + n2;
        const d = d1 + d2;
        vax -= mA * d * nx;
        vay -= mA * d * ny;
        wa -= iA * (d1 * n1a + d2 * n2a);
        vbx += mB * d * nx;
        vby += mB * d * ny;
        wb += iB * (d1 * n1b + d2 * n2b);
      }
    }
    for (let p = 0; p < (two ? 2 : 1) && !solved; p++) {
      const o = o1 + p * M2.MP_STRIDE;
      const na = p === 0 ? n1a : n2a,
        nb = p === 0 ? n1b : n2b;
      const old = p === 0 ? l1 : l2;
      const vn = (vbx - vax) * nx + (vby - vay) * ny + wb * nb - wa * na;
      const next = normalImpulse(old, R[o + CP_NORMAL_MASS]!, p === 0 ? m1 : m2, p === 0 ? i1 : i2, vn, p === 0 ? b1 : b2);
      const dl = next - old;
      if (p === 0) l1 = next;
      else l2 = next;
      total += next;
      if (dl > R[o + M2.MP_MAX_NORMAL_IMPULSE]!) R[o + M2.MP_MAX_NORMAL_IMPULSE] = dl;
      const Px = dl * nx,
        Py = dl * ny;
      vax -= mA * Px;
      vay -= mA * Py;
      wa -= iA * dl * na;
      vbx += mB * Px;
      vby += mB * Py;
      wb += iB * dl * nb;
    }
    R[o1 + M2.MP_NORMAL_IMPULSE] = l1;
    if (two) R[o2 + M2.MP_NORMAL_IMPULSE] = l2;
    const bound = R[r + M2.MR_FRICTION_BOUND]!;
    let f1 = 0,
      f2 = 0;
    for (let p = 0; p < (two ? 2 : 1); p++) {
      const o = o1 + p * M2.MP_STRIDE;
      const la = p === 0 ? t1a : t2a,
        lb = p === 0 ? t1b : t2b;
      const old = R[o + M2.MP_TANGENT_IMPULSE]!;
      const vt = (vby - vay) * nx - (vbx - vax) * ny + wb * lb - wa * la;
      const next = boundedImpulse(old, R[o + M2.MP_TANGENT_MASS]!, vt, bound * (p === 0 ? l1 : l2));
      const dl = next - old;
      R[o + M2.MP_TANGENT_IMPULSE] = next;
      if (p === 0) f1 = next;
      else f2 = next;
      const Px = -dl * ny,
        Py = dl * nx;
      vax -= mA * Px;
      vay -= mA * Py;
      wa -= iA * dl * la;
      vbx += mB * Px;
      vby += mB * Py;
      wb += iB * dl * lb;
    }
    if (R[r + M2.MR_ROLLING]! > 0) {
      const dl = solveRolling(R, r, total, wb - wa);
      wa -= iA * dl;
      wb += iB * dl;
    }
    storeVelocities2D(sb, a, b, vax, vay, wa, vbx, vby, wb);
    if (total > 0 || l1 !== 0 || f1 !== 0 || (two && (l2 !== 0 || f2 !== 0)) || R[r + M2.MR_ROLLING_IMPULSE] !== 0) markPushed(sb, a, b);
  }
}

/** Marks the bodies at packed offsets a and b of sb as pushed (see the module comment). */
function markPushed(sb: Float64Array, a: number, b: number): void {
  sb[a + BS.BS2_PUSHED] = 1;
  sb[b + BS.BS2_PUSHED] = 1;
}

/**
 * Adds each point's substep impulse to its step total (once per substep, after relaxing; the last
 * relax pass of solveManifolds does it when asked).
 * @category Collision
 */
export function accumulateManifoldImpulses(cs: CollisionState): void {
  const R = cs.shapes.solverRows;
  for (let i = 0, n = Math.min(cs.shapes.manifolds.count, MAX_MANIFOLDS); i < n; i++) {
    const r = i * M2.MR_STRIDE;
    accumulateRow(R, r + M2.MR_POINT0, R[r + M2.MR_POINT_COUNT] === 2);
  }
}

/** applyManifoldRestitution's scratch: the cap of each point's accumulated impulse (two a manifold). Not world state. */
let restitutionCaps = new Float64Array(0);

/**
 * The 2D manifolds' restitution stage, by the one definition of solver/restitution.ts: a point that
 * carried an impulse and approached faster than its threshold at the start of the step bounces; its
 * accumulated normal impulse is moved toward the target v_n = -e v_n0 by `restitutionIterations`
 * sequential-impulse passes, kept >= 0 and at most its start plus Poisson's cap. The first pass visits
 * every manifold and lists those with a bouncing point, the others only those. The two points of a
 * manifold with a valid block (see `prepareManifolds`) that both bounce are solved together, as the
 * 2 x 2 complementarity problem of Box2D 2.x's block solver, so a face-on hit rebounds without spin;
 * if that solution passes a cap, the points go one after the other.
 * @category Collision
 */
export function applyManifoldRestitution(world: PhysicsWorld): void {
  const cs = world.collision,
    R = cs.shapes.solverRows,
    sb = cs.bodyState;
  const threshold = cs.settings.restitutionThreshold,
    elasticThreshold = cs.settings.elasticRestitutionThreshold;
  const n = cs.shapes.manifolds.count;
  if (restitutionCaps.length < 2 * n) restitutionCaps = new Float64Array(4 * n);
  const list = bouncingList(n),
    caps = restitutionCaps;
  let listed = 0;
  for (let pass = 0, passes = cs.settings.restitutionIterations; pass < passes; pass++) {
    const all = pass === 0;
    for (let k = 0, count = all ? n : listed; k < count; k++) {
      const i = all ? k : list[k]!;
      const r = i * M2.MR_STRIDE;
      const e = R[r + M2.MR_RESTITUTION]!;
      if (e === 0) continue;
      const m = R[r + M2.MR_POINT_COUNT]!;
      const o1 = r + M2.MR_POINT0,
        o2 = o1 + M2.MP_STRIDE;
      const v1 = R[o1 + M2.MP_RELATIVE_VELOCITY]!,
        v2 = R[o2 + M2.MP_RELATIVE_VELOCITY]!;
      const t1 = m > 0 && R[o1 + M2.MP_MAX_NORMAL_IMPULSE]! > 0 ? restitutionTarget(e, v1, v1, threshold, elasticThreshold) : -1,
        t2 = m > 1 && R[o2 + M2.MP_MAX_NORMAL_IMPULSE]! > 0 ? restitutionTarget(e, v2, v2, threshold, elasticThreshold) : -1;
      if (t1 < 0 && t2 < 0) continue;
      // The bodies' velocities are read from and written to sb point by point (pushPoint): a bouncing row
      // is rare, and the values are those a row's locals would carry.
      const a = (R[r + M2.MR_BODY_A]! & M2.MR_BODY_MASK) * BS.BS2_STRIDE,
        b = (R[r + M2.MR_BODY_B]! & M2.MR_BODY_MASK) * BS.BS2_STRIDE;
      const nx = R[r + M2.MR_NX]!,
        ny = R[r + M2.MR_NY]!;
      const wa = sb[a + BS.BS2_W]!,
        wb = sb[b + BS.BS2_W]!;
      const dvn = (sb[b + BS.BS2_VX]! - sb[a + BS.BS2_VX]!) * nx + (sb[b + BS.BS2_VY]! - sb[a + BS.BS2_VY]!) * ny;
      if (all) {
        // Each point's cap: its impulse now plus Poisson's rebound; its compression is what it delivered
        // over the substeps plus what stops its approach now (in a block, with the other: -K^-1 v_n).
        list[listed++] = i;
        const vn1 = dvn + wb * R[o1 + M2.MP_RNB]! - wa * R[o1 + M2.MP_RNA]!,
          vn2 = m > 1 ? dvn + wb * R[o2 + M2.MP_RNB]! - wa * R[o2 + M2.MP_RNA]! : 0;
        let s1 = -R[o1 + CP_NORMAL_MASS]! * vn1,
          s2 = -R[o2 + CP_NORMAL_MASS]! * vn2;
        if (m > 1 && R[r + M2.MR_BLOCK_VALID] === 1) {
          s1 = -(R[r + M2.MR_B11]! * vn1 + R[r + M2.MR_B12]! * vn2);
          s2 = -(R[r + M2.MR_B12]! * vn1 + R[r + M2.MR_B22]! * vn2);
        }
        caps[2 * i] = R[o1 + M2.MP_NORMAL_IMPULSE]! + restitutionCap(e, R[o1 + M2.MP_TOTAL_NORMAL_IMPULSE]!, s1 > 0 ? s1 : 0);
        caps[2 * i + 1] = R[o2 + M2.MP_NORMAL_IMPULSE]! + restitutionCap(e, R[o2 + M2.MP_TOTAL_NORMAL_IMPULSE]!, s2 > 0 ? s2 : 0);
      }
      const l1 = R[o1 + M2.MP_NORMAL_IMPULSE]!,
        l2 = R[o2 + M2.MP_NORMAL_IMPULSE]!;
      let block = false;
      if (t1 >= 0 && t2 >= 0 && R[r + M2.MR_BLOCK_VALID] === 1) {
        // Both points at once: K x + c = w >= 0, x >= 0, x . w = 0, with w_i = v_n,i - t_i after the
        // impulses x (the linear complementarity problem of the block solve), within the caps.
        const K12 = R[r + M2.MR_K12]!;
        const c1 = dvn + wb * R[o1 + M2.MP_RNB]! - wa * R[o1 + M2.MP_RNA]! - t1 - (R[r + M2.MR_K11]! * l1 + K12 * l2),
          c2 = dvn + wb * R[o2 + M2.MP_RNB]! - wa * R[o2 + M2.MP_RNA]! - t2 - (K12 * l1 + R[r + M2.MR_K22]! * l2);
        block =
          solveBlock(R, r, c1, c2) && R[o1 + M2.MP_NORMAL_IMPULSE]! <= caps[2 * i]! && R[o2 + M2.MP_NORMAL_IMPULSE]! <= caps[2 * i + 1]!;
        if (!block) {
          R[o1 + M2.MP_NORMAL_IMPULSE] = l1;
          R[o2 + M2.MP_NORMAL_IMPULSE] = l2;
        }
      }
      // Point after point (the block's impulses, or each point's own step toward its target).
      for (let p = 0; p < m; p++) {
        const o = o1 + p * M2.MP_STRIDE;
        const target = p === 0 ? t1 : t2;
        if (target < 0) continue;
        const na = R[o + M2.MP_RNA]!,
          nb = R[o + M2.MP_RNB]!;
        const old = p === 0 ? l1 : l2;
        let next = R[o + M2.MP_NORMAL_IMPULSE]!;
        if (!block) {
          const vn =
            (sb[b + BS.BS2_VX]! - sb[a + BS.BS2_VX]!) * nx +
            (sb[b + BS.BS2_VY]! - sb[a + BS.BS2_VY]!) * ny +
            sb[b + BS.BS2_W]! * nb -
            sb[a + BS.BS2_W]! * na;
          next = restitutionImpulse(old, R[o + CP_NORMAL_MASS]!, vn, target, caps[2 * i + p]!);
          R[o + M2.MP_NORMAL_IMPULSE] = next;
        }
        const dl = next - old;
        R[o + M2.MP_TOTAL_NORMAL_IMPULSE] = R[o + M2.MP_TOTAL_NORMAL_IMPULSE]! + dl;
        pushPoint(sb, a, b, dl * nx, dl * ny, dl, na, nb);
      }
    }
    if (listed === 0) break;
  }
}

/**
 * Applies a point's impulse P = (px, py) = dl n to the bodies at packed offsets a and b of sb, with the
 * point's arms na = r_A x n and nb = r_B x n: v_A -= P / m_A, w_A -= dl na / I_A, v_B += P / m_B, w_B += dl nb / I_B.
 */
function pushPoint(sb: Float64Array, a: number, b: number, px: number, py: number, dl: number, na: number, nb: number): void {
  sb[a + BS.BS2_VX] = sb[a + BS.BS2_VX]! - sb[a + BS.BS2_INV_MASS]! * px;
  sb[a + BS.BS2_VY] = sb[a + BS.BS2_VY]! - sb[a + BS.BS2_INV_MASS]! * py;
  sb[a + BS.BS2_W] = sb[a + BS.BS2_W]! - sb[a + BS.BS2_INV_INERTIA]! * dl * na;
  sb[b + BS.BS2_VX] = sb[b + BS.BS2_VX]! + sb[b + BS.BS2_INV_MASS]! * px;
  sb[b + BS.BS2_VY] = sb[b + BS.BS2_VY]! + sb[b + BS.BS2_INV_MASS]! * py;
  sb[b + BS.BS2_W] = sb[b + BS.BS2_W]! + sb[b + BS.BS2_INV_INERTIA]! * dl * nb;
}
