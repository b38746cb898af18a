import type { PhysicsWorld } from '../world.js';
import { BodyType } from './state.js';
import { clearRowIndex, contact3DStateOf, insertRow, lookupRow, pushEvent3D, pushTouch } from './manifolds3d-state.js';
import { currentHandle } from '../handles.js';

/**
 * The 3D shape contacts' rows of the contact solver (solver.ts calls these next to the ball contacts',
 * in the same substeps, on the same packed body state, stride 12: v, w, displacement, 1/m, an inverse
 * inertia flag, pushed): Box2D v3's manifold constraint (contact_solver.c) carried to 3D:
 *
 * - anchors r_A, r_B from the centres of mass at the start of the step; separation tracked as
 *   s = s0 + (d_B + theta_B x r_B - d_A - theta_A x r_A) . n, with d and theta each body's displacement
 *   and rotation so far in the step (rotation linearised);
 * - angular terms through the world inverse inertia tensor I^-1 = R diag(1/I_1, 1/I_2, 1/I_3) R^T
 *   (R from the orientation at the start of the solve); effective mass of a row along u:
 *   1 / (1/m_A + 1/m_B + (r_A x u) . I_A^-1 (r_A x u) + (r_B x u) . I_B^-1 (r_B x u));
 * - normal rows: speculative (s > 0: bias s / h_s) or soft (Box2D's soft constraint; twice as stiff
 *   against infinite mass; push-out speed capped), accumulated impulse >= 0; relax passes without bias;
 * - friction in two tangent directions t1, t2 = n x t1, each |lambda_t| <= mu lambda_n;
 * - per point and direction u (n, t1, t2), r x u and I^-1 (r x u) of both bodies are computed once a
 *   step (`jacobians`), so a pass reads them instead of multiplying tensors; a manifold whose two bodies
 *   are isotropic (I^-1 = i 1: spheres, cubes, or a static side) reads only r x u and scales it by i,
 *   half the memory a pass streams; the points of a manifold are solved in alternating order from
 *   substep to substep; a manifold whose normal rows are all rigid in a pass (speculative, or a relax
 *   pass) is swept until they agree (NORMAL_SWEEPS), so a flat hit does not spin the boxes;
 * - warm start from the previous step's point with the same feature id (shape3d-collision.ts);
 * - restitution after the substeps (Box2D v3 b2ApplyRestitution): a point that approached faster than
 *   the world's restitution threshold and carried an impulse leaves with v_n >= -e v_n0.
 */

/**
 * Numbers a point keeps in `jacobians`: first r_A x u, r_B x u for u = n, t1, t2 in turn (at 6 d, d = 0, 1, 2),
 * then I_A^-1 (r_A x u), I_B^-1 (r_B x u) in the same order (at INV + 6 d), so an isotropic manifold's
 * passes touch only the first 18.
 */
const JAC = 36;
const INV = 18;

/** Stiffness as a fraction of the substep rate (as the 2D shape contacts: manifold-solver.ts). */
const HERTZ_FRACTION = 0.125;

/**
 * A manifold's normal rows are swept again (alternating order, at most NORMAL_SWEEPS sweeps) while every
 * row it met was rigid: a speculative row (s > 0) in any pass, or any row in a relax pass; the soft rows
 * of a biased pass take one sweep, as Box2D's soft step is made for. Only a hit sweeps again: the first
 * sweep changed the manifold's impulse by more than HIT_FRACTION of it (a resting contact's warm-started
 * impulse changes by a few per cent, and keeps its one sweep and its cost). The sweeps stop once a
 * sweep's change of impulse (sum of |delta lambda|) is below SWEEP_TOLERANCE of the manifold's impulse,
 * or moves the bodies apart by less than SWEEP_SPEED m/s ((1/m_A + 1/m_B) sum |delta lambda|).
 *
 * Why: one Gauss-Seidel sweep over the four points of a face that meets another flat gives the whole
 * approach to the first point visited, which stops it by turning the box, and the others then push
 * back on the spin. Two 1 m cubes meeting face to face at 1 m/s with zero restitution parted at
 * 0.033 m/s spinning at 0.13 rad/s; a cube dropped flat at 10 m/s onto a static box floor left at
 * 0.16 m/s sideways, 0.13 m/s back up and 0.23 rad/s. The sweeps converge (a manifold's rigid rows form
 * a symmetric positive semi-definite system: projected Gauss-Seidel) to the exact shares: now both stop
 * (below 1e-3 m/s and rad/s).
 */
const NORMAL_SWEEPS = 8;
/** A second sweep only follows a first that changed the impulse by more than this fraction of it (a hit, not a resting contact's correction). */
const HIT_FRACTION = 0.25;
const SWEEP_TOLERANCE = 1e-3;
const SWEEP_SPEED = 1e-3;

/** Whether the world has 3D shape rows to solve this step. */
export function manifolds3DToSolve(world: PhysicsWorld): boolean {
  const st = contact3DStateOf(world);
  return st !== undefined && st.current.count > 0;
}

/** Gives every moving body of a 3D manifold a solver index (continuing the list), writes the rows' indices; returns the new count. */
export function gatherManifold3DBodies(world: PhysicsWorld, count: number): number {
  const st = contact3DStateOf(world);
  if (st === undefined || st.current.count === 0) return count;
  const cs = world.collision, buf = st.current;
  const mark = cs.solverMark, index = cs.solverIndex, stamp = cs.solverStamp, type = cs.bodyType;
  let list = cs.solverBodies;
  for (let i = 0; i < buf.count; i++) {
    for (let side = 0; side < 2; side++) {
      const e = side === 0 ? buf.bodyA[i]! : buf.bodyB[i]!;
      let k = 0;
      const t = type[e]!;
      if (e !== 0 && (t === BodyType.Dynamic || t === BodyType.Kinematic)) {
        if (mark[e] !== stamp) {
          mark[e] = stamp;
          if (count >= list.length) { const l = new Int32Array(list.length * 2); l.set(list); list = l; }
          index[e] = count; list[count++] = e;
        }
        k = index[e]!;
      }
      if (side === 0) buf.ia[i] = k; else buf.ib[i] = k;
    }
  }
  cs.solverBodies = list;
  return count;
}

const soft = new Float64Array(3), rigid = new Float64Array(3);

function makeSoftInto(out: Float64Array, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) { out[0] = 0; out[1] = 1; out[2] = 0; return; }
  const omega = 2 * Math.PI * hertz, a1 = 2 * zeta + h * omega, a2 = h * omega * a1, a3 = 1 / (1 + a2);
  out[0] = omega / a1; out[1] = a2 * a3; out[2] = a3;
}

/** World inverse inertia tensors of the solver bodies, effective masses, separations corrected to the solver's base, approach speeds. */
export function prepareManifolds3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world, true);
  prepareSolverBodies3D(world);
  const cs = world.collision, buf = st.current, n = buf.count;
  const count = cs.solverBodyCount;
  const c = world.components, sb = cs.bodyState, ex = cs.bodyExtra, T = st.invInertia;
  const set = cs.settings, hs = world.h / set.solverSubsteps;
  const hertz = Math.min(set.contactHertz, HERTZ_FRACTION / hs);
  makeSoftInto(soft, hertz, set.contactDampingRatio, hs);
  makeSoftInto(rigid, 2 * hertz, set.contactDampingRatio, hs);
  void count;
  if (n === 0) return;
  if (st.jacobians.length < JAC * 4 * n) st.jacobians = new Float32Array(JAC * 4 * Math.max(n, 2 * st.jacobians.length / (4 * JAC)));
  const J = st.jacobians;
  const ox = c.PreviousPosition.x, oy = c.PreviousPosition.y, oz = c.PreviousPosition.z;
  for (let i = 0; i < n; i++) {
    const ka = buf.ia[i]!, kb = buf.ib[i]!, a = 12 * ka, b = 12 * kb, ta = 6 * ka, tb = 6 * kb;
    const mA = sb[a + 9]!, mB = sb[b + 9]!;
    const iso = isotropic(T, ta) && isotropic(T, tb);
    buf.iso[i] = iso ? 1 : 0;
    const nx = buf.nx[i]!, ny = buf.ny[i]!, nz = buf.nz[i]!;
    const t1x = buf.t1x[i]!, t1y = buf.t1y[i]!, t1z = buf.t1z[i]!;
    const t2x = ny * t1z - nz * t1y, t2y = nz * t1x - nx * t1z, t2z = nx * t1y - ny * t1x;
    // Solver base minus where the narrowphase measured (PreviousPosition) along n.
    let shift = 0;
    if (ka > 0) { const e = buf.bodyA[i]!; shift -= (ex[6 * ka]! - ox[e]!) * nx + (ex[6 * ka + 1]! - oy[e]!) * ny + (ex[6 * ka + 2]! - oz[e]!) * nz; }
    if (kb > 0) { const e = buf.bodyB[i]!; shift += (ex[6 * kb]! - ox[e]!) * nx + (ex[6 * kb + 1]! - oy[e]!) * ny + (ex[6 * kb + 2]! - oz[e]!) * nz; }
    let minSep = Infinity, reachA = 0, reachB = 0;
    for (let k = 0, m = buf.points[i]!; k < m; k++) {
      const q = 4 * i + k, o = JAC * q;
      buf.sep[q] = buf.sep[q]! + shift;
      const rax = buf.rax[q]!, ray = buf.ray[q]!, raz = buf.raz[q]!, rbx = buf.rbx[q]!, rby = buf.rby[q]!, rbz = buf.rbz[q]!;
      if (buf.sep[q]! < minSep) minSep = buf.sep[q]!;
      reachA = Math.max(reachA, rax * rax + ray * ray + raz * raz); reachB = Math.max(reachB, rbx * rbx + rby * rby + rbz * rbz);
      // Per direction u (n, t1, t2): r_A x u, r_B x u, and I_A^-1 (r_A x u), I_B^-1 (r_B x u), then the effective mass.
      for (let d = 0; d < 3; d++) {
        const ux = d === 0 ? nx : d === 1 ? t1x : t2x, uy = d === 0 ? ny : d === 1 ? t1y : t2y, uz = d === 0 ? nz : d === 1 ? t1z : t2z;
        const cax = ray * uz - raz * uy, cay = raz * ux - rax * uz, caz = rax * uy - ray * ux;
        const cbx = rby * uz - rbz * uy, cby = rbz * ux - rbx * uz, cbz = rbx * uy - rby * ux;
        const b = o + 6 * d, bi = b + INV;
        J[b] = cax; J[b + 1] = cay; J[b + 2] = caz; J[b + 3] = cbx; J[b + 4] = cby; J[b + 5] = cbz;
        let k0: number;
        if (iso) {
          // I^-1 = i 1 on both sides: (r x u) . I^-1 (r x u) = i |r x u|^2, the products not stored.
          k0 = mA + mB + T[ta]! * (cax * cax + cay * cay + caz * caz) + T[tb]! * (cbx * cbx + cby * cby + cbz * cbz);
        } else {
          const iax = T[ta]! * cax + T[ta + 3]! * cay + T[ta + 4]! * caz, iay = T[ta + 3]! * cax + T[ta + 1]! * cay + T[ta + 5]! * caz, iaz = T[ta + 4]! * cax + T[ta + 5]! * cay + T[ta + 2]! * caz;
          const ibx = T[tb]! * cbx + T[tb + 3]! * cby + T[tb + 4]! * cbz, iby = T[tb + 3]! * cbx + T[tb + 1]! * cby + T[tb + 5]! * cbz, ibz = T[tb + 4]! * cbx + T[tb + 5]! * cby + T[tb + 2]! * cbz;
          J[bi] = iax; J[bi + 1] = iay; J[bi + 2] = iaz; J[bi + 3] = ibx; J[bi + 4] = iby; J[bi + 5] = ibz;
          k0 = mA + mB + cax * iax + cay * iay + caz * iaz + cbx * ibx + cby * iby + cbz * ibz;
        }
        const eff = k0 > 0 ? 1 / k0 : 0;
        if (d === 0) buf.mn[q] = eff; else if (d === 1) buf.mt1[q] = eff; else buf.mt2[q] = eff;
      }
      // Normal relative velocity at the start (for restitution): n . (v_B - v_A) + w_B . (r_B x n) - w_A . (r_A x n).
      buf.vn0[q] = (sb[b]! - sb[a]!) * nx + (sb[b + 1]! - sb[a + 1]!) * ny + (sb[b + 2]! - sb[a + 2]!) * nz
        + sb[b + 3]! * J[o + 3]! + sb[b + 4]! * J[o + 4]! + sb[b + 5]! * J[o + 5]!
        - sb[a + 3]! * J[o]! - sb[a + 4]! * J[o + 1]! - sb[a + 5]! * J[o + 2]!;
    }
    // For the solver's skip of a speculative manifold (solveManifolds3D); padded for the single-precision crosses.
    buf.minSep[i] = minSep; buf.reachA[i] = Math.sqrt(reachA) * (1 + 1e-5) + 1e-9; buf.reachB[i] = Math.sqrt(reachB) * (1 + 1e-5) + 1e-9;
  }
}

/** Whether the world inverse inertia tensor at T[o..o+5] is i 1 (prepareSolverBodies3D writes it exactly so for isotropic bodies). */
function isotropic(T: Float64Array, o: number): boolean {
  return T[o + 3] === 0 && T[o + 4] === 0 && T[o + 5] === 0 && T[o] === T[o + 1] && T[o] === T[o + 2];
}

/**
 * The world inverse inertia tensor of every solver body (I^-1 = R diag(1 / I_k) R^T with R from its
 * orientation; isotropic for a ball) and its rotation owed at the start of the solve (rotations in the
 * substeps are measured from it). Shared by the 3D contact and joint rows.
 */
export function prepareSolverBodies3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world, true);
  const cs = world.collision;
  const count = cs.solverBodyCount;
  if (st.invInertia.length < 6 * count) { st.invInertia = new Float64Array(12 * count); st.rotationBase = new Float64Array(6 * count); }
  const c = world.components, list = cs.solverBodies, sb = cs.bodyState, ex = cs.bodyExtra, T = st.invInertia, base = st.rotationBase;
  const Q = c.Orientation, IT = c.InertiaTensor;
  const hasT = IT.invX.length > 0;
  T.fill(0, 0, 6);
  for (let k = 1; k < count; k++) {
    const e = list[k]!, o = 6 * k;
    base[3 * k] = ex[6 * k + 3]!; base[3 * k + 1] = ex[6 * k + 4]!; base[3 * k + 2] = ex[6 * k + 5]!;
    const ii = sb[12 * k + 10]!;
    if (!(ii > 0)) { T.fill(0, o, o + 6); continue; }
    const ix = hasT ? IT.invX[e]! : 0, iy = hasT ? IT.invY[e]! : 0, iz = hasT ? IT.invZ[e]! : 0;
    // No tensor (a ball), or equal principal moments (a cube, a sphere): R diag(i, i, i) R^T = i 1 exactly.
    if (ix === 0 && iy === 0 && iz === 0 || !(Q.w.length > e)) { T[o] = ii; T[o + 1] = ii; T[o + 2] = ii; T[o + 3] = 0; T[o + 4] = 0; T[o + 5] = 0; continue; }
    if (ix === iy && iy === iz) { T[o] = ix; T[o + 1] = ix; T[o + 2] = ix; T[o + 3] = 0; T[o + 4] = 0; T[o + 5] = 0; continue; }
    const x = Q.x[e]!, y = Q.y[e]!, z = Q.z[e]!, w = Q.w[e]!;
    const r00 = 1 - 2 * (y * y + z * z), r01 = 2 * (x * y - z * w), r02 = 2 * (x * z + y * w);
    const r10 = 2 * (x * y + z * w), r11 = 1 - 2 * (x * x + z * z), r12 = 2 * (y * z - x * w);
    const r20 = 2 * (x * z - y * w), r21 = 2 * (y * z + x * w), r22 = 1 - 2 * (x * x + y * y);
    T[o] = r00 * r00 * ix + r01 * r01 * iy + r02 * r02 * iz;
    T[o + 1] = r10 * r10 * ix + r11 * r11 * iy + r12 * r12 * iz;
    T[o + 2] = r20 * r20 * ix + r21 * r21 * iy + r22 * r22 * iz;
    T[o + 3] = r00 * r10 * ix + r01 * r11 * iy + r02 * r12 * iz;
    T[o + 4] = r00 * r20 * ix + r01 * r21 * iy + r02 * r22 * iz;
    T[o + 5] = r10 * r20 * ix + r11 * r21 * iy + r12 * r22 * iz;
  }
}

/**
 * Applies impulse lambda along direction u (d: 0 n, 1 t1, 2 t2) at point q: -lambda u to A, +lambda u
 * to B, the angular parts from the point's precomputed I^-1 (r x u), or for an isotropic manifold
 * (`iA`, `iB` >= 0) i (r x u) from its crosses. Body row 0 (the static world) is never written.
 */
function apply(sb: Float64Array, J: Float32Array, ka: number, kb: number, q: number, d: number, lam: number, ux: number, uy: number, uz: number, iA: number, iB: number): void {
  const c = JAC * q + 6 * d, o = c + INV, iso = iA >= 0;
  if (ka > 0) {
    const a = 12 * ka, m = sb[a + 9]! * lam;
    sb[a] = sb[a]! - m * ux; sb[a + 1] = sb[a + 1]! - m * uy; sb[a + 2] = sb[a + 2]! - m * uz;
    if (iso) { const g = iA * lam; sb[a + 3] = sb[a + 3]! - g * J[c]!; sb[a + 4] = sb[a + 4]! - g * J[c + 1]!; sb[a + 5] = sb[a + 5]! - g * J[c + 2]!; }
    else { sb[a + 3] = sb[a + 3]! - lam * J[o]!; sb[a + 4] = sb[a + 4]! - lam * J[o + 1]!; sb[a + 5] = sb[a + 5]! - lam * J[o + 2]!; }
    sb[a + 11] = 1;
  }
  if (kb > 0) {
    const b = 12 * kb, m = sb[b + 9]! * lam;
    sb[b] = sb[b]! + m * ux; sb[b + 1] = sb[b + 1]! + m * uy; sb[b + 2] = sb[b + 2]! + m * uz;
    if (iso) { const g = iB * lam; sb[b + 3] = sb[b + 3]! + g * J[c + 3]!; sb[b + 4] = sb[b + 4]! + g * J[c + 4]!; sb[b + 5] = sb[b + 5]! + g * J[c + 5]!; }
    else { sb[b + 3] = sb[b + 3]! + lam * J[o + 3]!; sb[b + 4] = sb[b + 4]! + lam * J[o + 4]!; sb[b + 5] = sb[b + 5]! + lam * J[o + 5]!; }
    sb[b + 11] = 1;
  }
}

/** Relative velocity of B against A at point q along direction u (d as in `apply`). */
function relativeSpeed(sb: Float64Array, J: Float32Array, a: number, b: number, q: number, d: number, ux: number, uy: number, uz: number): number {
  const o = JAC * q + 6 * d;
  return (sb[b]! - sb[a]!) * ux + (sb[b + 1]! - sb[a + 1]!) * uy + (sb[b + 2]! - sb[a + 2]!) * uz
    + sb[b + 3]! * J[o + 3]! + sb[b + 4]! * J[o + 4]! + sb[b + 5]! * J[o + 5]!
    - sb[a + 3]! * J[o]! - sb[a + 4]! * J[o + 1]! - sb[a + 5]! * J[o + 2]!;
}

/** Warm start: last step's impulses applied again (all three directions of a point at once). */
export function warmStartManifolds3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const buf = st.current, sb = world.collision.bodyState, J = st.jacobians, T = st.invInertia;
  const LN = buf.ln, LT1 = buf.lt1, LT2 = buf.lt2;
  for (let i = 0; i < buf.count; i++) {
    const nx = buf.nx[i]!, ny = buf.ny[i]!, nz = buf.nz[i]!, t1x = buf.t1x[i]!, t1y = buf.t1y[i]!, t1z = buf.t1z[i]!;
    const t2x = ny * t1z - nz * t1y, t2y = nz * t1x - nx * t1z, t2z = nx * t1y - ny * t1x;
    const ka = buf.ia[i]!, kb = buf.ib[i]!, a = 12 * ka, b = 12 * kb;
    const mA = sb[a + 9]!, mB = sb[b + 9]!;
    const iso = buf.iso[i] === 1, iA = iso ? T[6 * ka]! : 0, iB = iso ? T[6 * kb]! : 0;
    for (let k = 0, m = buf.points[i]!; k < m; k++) {
      const q = 4 * i + k, ln = LN[q]!, l1 = LT1[q]!, l2 = LT2[q]!;
      if (ln === 0 && l1 === 0 && l2 === 0) continue;
      const o = JAC * q;
      // Linear impulse P = ln n + l1 t1 + l2 t2; angular: the sum of lambda I^-1 (r x u) over the three directions.
      const px = ln * nx + l1 * t1x + l2 * t2x, py = ln * ny + l1 * t1y + l2 * t2y, pz = ln * nz + l1 * t1z + l2 * t2z;
      if (iso) {
        // I^-1 = i 1: the angular impulses are i sum(lambda r x u), from the crosses.
        if (ka > 0) {
          sb[a] = sb[a]! - mA * px; sb[a + 1] = sb[a + 1]! - mA * py; sb[a + 2] = sb[a + 2]! - mA * pz;
          sb[a + 3] = sb[a + 3]! - iA * (ln * J[o]! + l1 * J[o + 6]! + l2 * J[o + 12]!);
          sb[a + 4] = sb[a + 4]! - iA * (ln * J[o + 1]! + l1 * J[o + 7]! + l2 * J[o + 13]!);
          sb[a + 5] = sb[a + 5]! - iA * (ln * J[o + 2]! + l1 * J[o + 8]! + l2 * J[o + 14]!);
          sb[a + 11] = 1;
        }
        if (kb > 0) {
          sb[b] = sb[b]! + mB * px; sb[b + 1] = sb[b + 1]! + mB * py; sb[b + 2] = sb[b + 2]! + mB * pz;
          sb[b + 3] = sb[b + 3]! + iB * (ln * J[o + 3]! + l1 * J[o + 9]! + l2 * J[o + 15]!);
          sb[b + 4] = sb[b + 4]! + iB * (ln * J[o + 4]! + l1 * J[o + 10]! + l2 * J[o + 16]!);
          sb[b + 5] = sb[b + 5]! + iB * (ln * J[o + 5]! + l1 * J[o + 11]! + l2 * J[o + 17]!);
          sb[b + 11] = 1;
        }
        continue;
      }
      if (ka > 0) {
        sb[a] = sb[a]! - mA * px; sb[a + 1] = sb[a + 1]! - mA * py; sb[a + 2] = sb[a + 2]! - mA * pz;
        sb[a + 3] = sb[a + 3]! - ln * J[o + 18]! - l1 * J[o + 24]! - l2 * J[o + 30]!;
        sb[a + 4] = sb[a + 4]! - ln * J[o + 19]! - l1 * J[o + 25]! - l2 * J[o + 31]!;
        sb[a + 5] = sb[a + 5]! - ln * J[o + 20]! - l1 * J[o + 26]! - l2 * J[o + 32]!;
        sb[a + 11] = 1;
      }
      if (kb > 0) {
        sb[b] = sb[b]! + mB * px; sb[b + 1] = sb[b + 1]! + mB * py; sb[b + 2] = sb[b + 2]! + mB * pz;
        sb[b + 3] = sb[b + 3]! + ln * J[o + 21]! + l1 * J[o + 27]! + l2 * J[o + 33]!;
        sb[b + 4] = sb[b + 4]! + ln * J[o + 22]! + l1 * J[o + 28]! + l2 * J[o + 34]!;
        sb[b + 5] = sb[b + 5]! + ln * J[o + 23]! + l1 * J[o + 29]! + l2 * J[o + 35]!;
        sb[b + 11] = 1;
      }
    }
  }
}

/** One pass over the rows: normal (soft with `useBias`, else relaxing), then friction in t1 and t2. */
export function solveManifolds3D(world: PhysicsWorld, hs: number, useBias: boolean): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const cs = world.collision, buf = st.current, sb = cs.bodyState, ex = cs.bodyExtra, base = st.rotationBase, J = st.jacobians;
  const push = cs.settings.contactPushSpeed;
  // Points in alternating order from substep to substep (symmetric Gauss-Seidel; the relax pass keeps
  // its substep's order), so the order a manifold's points are solved in leaves no systematic torque.
  if (useBias) st.solveParity ^= 1;
  const backward = st.solveParity === 1;
  const sBias = soft[0]!, sMass = soft[1]!, sImp = soft[2]!, rBias = rigid[0]!, rMass = rigid[1]!, rImp = rigid[2]!;
  const sep = buf.sep, LN = buf.ln, LT1 = buf.lt1, LT2 = buf.lt2, MN = buf.mn, MT1 = buf.mt1, MT2 = buf.mt2, MAX = buf.maxLn;
  const IA = buf.ia, IB = buf.ib, NX = buf.nx, NY = buf.ny, NZ = buf.nz, T1X = buf.t1x, T1Y = buf.t1y, T1Z = buf.t1z, PTS = buf.points, MU = buf.friction;
  const ISO = buf.iso, T = st.invInertia, MINSEP = buf.minSep, RA = buf.reachA, RB = buf.reachB;
  const invHs = 1 / hs;
  for (let i = 0, count = buf.count; i < count; i++) {
    const ka = IA[i]!, kb = IB[i]!, a = 12 * ka, b = 12 * kb;
    const nx = NX[i]!, ny = NY[i]!, nz = NZ[i]!;
    const isRigid = ka === 0 || kb === 0;
    const biasRate = isRigid ? rBias : sBias, massScale = isRigid ? rMass : sMass, impScale = isRigid ? rImp : sImp;
    // Velocities of both bodies in locals for the manifold's rows (written back once at the end).
    let vax = sb[a]!, vay = sb[a + 1]!, vaz = sb[a + 2]!, wax = sb[a + 3]!, way = sb[a + 4]!, waz = sb[a + 5]!;
    let vbx = sb[b]!, vby = sb[b + 1]!, vbz = sb[b + 2]!, wbx = sb[b + 3]!, wby = sb[b + 4]!, wbz = sb[b + 5]!;
    const mA = sb[a + 9]!, mB = sb[b + 9]!;
    // Displacement along n and rotation of each body so far this step.
    const dn = (sb[b + 6]! - sb[a + 6]!) * nx + (sb[b + 7]! - sb[a + 7]!) * ny + (sb[b + 8]! - sb[a + 8]!) * nz;
    let hax = 0, hay = 0, haz = 0, hbx = 0, hby = 0, hbz = 0;
    if (ka > 0) { const e = 6 * ka, r = 3 * ka; hax = ex[e + 3]! - base[r]!; hay = ex[e + 4]! - base[r + 1]!; haz = ex[e + 5]! - base[r + 2]!; }
    if (kb > 0) { const e = 6 * kb, r = 3 * kb; hbx = ex[e + 3]! - base[r]!; hby = ex[e + 4]! - base[r + 1]!; hbz = ex[e + 5]! - base[r + 2]!; }
    const m = PTS[i]!;
    // A speculative manifold that cannot close this substep is skipped, exactly: no impulse yet, and every
    // point's s >= minSep + dn - |theta_A| reach_A - |theta_B| reach_B > 0 with
    // v_n + s / h_s >= (v_B - v_A) . n - |w_A| reach_A - |w_B| reach_B + s_low / h_s >= 0, so each row would
    // compute lambda = max(0 - m (v_n + s / h_s), 0) = 0 and change nothing (friction has no limit then).
    if (MINSEP[i]! > 0) {
      let idle = true;
      for (let k = 0; k < m; k++) { const q = 4 * i + k; if (LN[q] !== 0 || LT1[q] !== 0 || LT2[q] !== 0) { idle = false; break; } }
      if (idle) {
        const rA = RA[i]!, rB = RB[i]!;
        const sLow = MINSEP[i]! + dn - Math.sqrt(hax * hax + hay * hay + haz * haz) * rA - Math.sqrt(hbx * hbx + hby * hby + hbz * hbz) * rB;
        if (sLow > 0) {
          const vLow = (vbx - vax) * nx + (vby - vay) * ny + (vbz - vaz) * nz
            - Math.sqrt(wax * wax + way * way + waz * waz) * rA - Math.sqrt(wbx * wbx + wby * wby + wbz * wbz) * rB;
          if (vLow + sLow * invHs >= 0) continue;
        }
      }
    }
    // Isotropic bodies: I^-1 (r x u) = i (r x u), from the crosses (the stored products are not read).
    const iso = ISO[i] === 1, iA = iso ? T[6 * ka]! : 0, iB = iso ? T[6 * kb]! : 0;
    let pushed = false;
    // Normal rows swept until a flat hit is shared by the points as the exact solve shares it, not by the
    // order they are visited in (NORMAL_SWEEPS); a soft row ends the sweeps after the first.
    const sweeps = m === 1 ? 1 : NORMAL_SWEEPS;
    let softMet = false;
    for (let sw = 0; sw < sweeps; sw++) {
      let change = 0, total = 0;
      for (let kk = 0; kk < m; kk++) {
        const k = (backward !== ((sw & 1) === 1)) ? m - 1 - kk : kk;
        const q = 4 * i + k, o = JAC * q;
        const ra0 = J[o]!, ra1 = J[o + 1]!, ra2 = J[o + 2]!, rb0 = J[o + 3]!, rb1 = J[o + 4]!, rb2 = J[o + 5]!;
        // s = s0 + (d_B - d_A) . n + theta_B . (r_B x n) - theta_A . (r_A x n)
        const s = (sep[q]! + dn) + ((hbx * rb0 + hby * rb1 + hbz * rb2) - (hax * ra0 + hay * ra1 + haz * ra2));
        let bias = 0, ms = 1, is = 0;
        if (s > 0) bias = s * invHs;
        else if (useBias) { bias = Math.max(biasRate * s, -push); ms = massScale; is = impScale; softMet = true; }
        const vn = ((vbx - vax) * nx + (vby - vay) * ny + (vbz - vaz) * nz)
          + ((wbx * rb0 + wby * rb1 + wbz * rb2) - (wax * ra0 + way * ra1 + waz * ra2));
        const old = LN[q]!;
        const lam = Math.max(old - MN[q]! * ms * (vn + bias) - is * old, 0);
        const dl = lam - old;
        LN[q] = lam;
        if (lam > MAX[q]!) MAX[q] = lam;
        if (dl !== 0) {
          // Body row 0 (the static world) has zero inverse mass and inertia, and is never written back.
          const fa = mA * dl, fb = mB * dl;
          vax -= fa * nx; vay -= fa * ny; vaz -= fa * nz;
          vbx += fb * nx; vby += fb * ny; vbz += fb * nz;
          if (iso) {
            const ga = iA * dl, gb = iB * dl;
            wax -= ga * ra0; way -= ga * ra1; waz -= ga * ra2;
            wbx += gb * rb0; wby += gb * rb1; wbz += gb * rb2;
          } else {
            const p = o + INV;
            wax -= dl * J[p]!; way -= dl * J[p + 1]!; waz -= dl * J[p + 2]!;
            wbx += dl * J[p + 3]!; wby += dl * J[p + 4]!; wbz += dl * J[p + 5]!;
          }
          pushed = true;
          change += dl > 0 ? dl : -dl;
        }
        total += lam;
      }
      if (softMet || change <= (sw === 0 ? HIT_FRACTION : SWEEP_TOLERANCE) * total || change * (mA + mB) <= SWEEP_SPEED) break;
    }
    const mu = MU[i]!;
    const t1x = T1X[i]!, t1y = T1Y[i]!, t1z = T1Z[i]!;
    const t2x = ny * t1z - nz * t1y, t2y = nz * t1x - nx * t1z, t2z = nx * t1y - ny * t1x;
    for (let k = 0; k < m; k++) {
      const q = 4 * i + k;
      const limit = mu * LN[q]!;
      const o1 = LT1[q]!, o2 = LT2[q]!;
      // A point that pushes nothing (a speculative one) has no friction to solve.
      if (limit === 0 && o1 === 0 && o2 === 0) continue;
      // t1 (crosses at o, inverse products at o + INV), then t2 (6 further on).
      let o = JAC * q + 6;
      let ca0 = J[o]!, ca1 = J[o + 1]!, ca2 = J[o + 2]!, cb0 = J[o + 3]!, cb1 = J[o + 4]!, cb2 = J[o + 5]!;
      const vt1 = ((vbx - vax) * t1x + (vby - vay) * t1y + (vbz - vaz) * t1z)
        + ((wbx * cb0 + wby * cb1 + wbz * cb2) - (wax * ca0 + way * ca1 + waz * ca2));
      let l1 = o1 - MT1[q]! * vt1;
      l1 = l1 > limit ? limit : l1 < -limit ? -limit : l1;
      LT1[q] = l1;
      const d1 = l1 - o1;
      if (d1 !== 0) {
        const fa = mA * d1, fb = mB * d1;
        vax -= fa * t1x; vay -= fa * t1y; vaz -= fa * t1z;
        vbx += fb * t1x; vby += fb * t1y; vbz += fb * t1z;
        if (iso) {
          const ga = iA * d1, gb = iB * d1;
          wax -= ga * ca0; way -= ga * ca1; waz -= ga * ca2;
          wbx += gb * cb0; wby += gb * cb1; wbz += gb * cb2;
        } else {
          const p = o + INV;
          wax -= d1 * J[p]!; way -= d1 * J[p + 1]!; waz -= d1 * J[p + 2]!;
          wbx += d1 * J[p + 3]!; wby += d1 * J[p + 4]!; wbz += d1 * J[p + 5]!;
        }
        pushed = true;
      }
      o += 6;
      ca0 = J[o]!; ca1 = J[o + 1]!; ca2 = J[o + 2]!; cb0 = J[o + 3]!; cb1 = J[o + 4]!; cb2 = J[o + 5]!;
      const vt2 = ((vbx - vax) * t2x + (vby - vay) * t2y + (vbz - vaz) * t2z)
        + ((wbx * cb0 + wby * cb1 + wbz * cb2) - (wax * ca0 + way * ca1 + waz * ca2));
      let l2 = o2 - MT2[q]! * vt2;
      l2 = l2 > limit ? limit : l2 < -limit ? -limit : l2;
      LT2[q] = l2;
      const d2 = l2 - o2;
      if (d2 !== 0) {
        const fa = mA * d2, fb = mB * d2;
        vax -= fa * t2x; vay -= fa * t2y; vaz -= fa * t2z;
        vbx += fb * t2x; vby += fb * t2y; vbz += fb * t2z;
        if (iso) {
          const ga = iA * d2, gb = iB * d2;
          wax -= ga * ca0; way -= ga * ca1; waz -= ga * ca2;
          wbx += gb * cb0; wby += gb * cb1; wbz += gb * cb2;
        } else {
          const p = o + INV;
          wax -= d2 * J[p]!; way -= d2 * J[p + 1]!; waz -= d2 * J[p + 2]!;
          wbx += d2 * J[p + 3]!; wby += d2 * J[p + 4]!; wbz += d2 * J[p + 5]!;
        }
        pushed = true;
      }
    }
    if (pushed) {
      if (ka > 0) { sb[a] = vax; sb[a + 1] = vay; sb[a + 2] = vaz; sb[a + 3] = wax; sb[a + 4] = way; sb[a + 5] = waz; sb[a + 11] = 1; }
      if (kb > 0) { sb[b] = vbx; sb[b + 1] = vby; sb[b + 2] = vbz; sb[b + 3] = wbx; sb[b + 4] = wby; sb[b + 5] = wbz; sb[b + 11] = 1; }
    }
  }
}

/** Restitution after the substeps: points that approached faster than the threshold and carried impulse leave at >= e times that speed. */
export function applyManifold3DRestitution(world: PhysicsWorld): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const cs = world.collision, buf = st.current, sb = cs.bodyState, J = st.jacobians, T = st.invInertia;
  const threshold = cs.settings.restitutionThreshold;
  for (let pass = 0; pass < 4; pass++) {
    for (let i = 0; i < buf.count; i++) {
      const e = buf.restitution[i]!;
      if (e === 0) continue;
      const ka = buf.ia[i]!, kb = buf.ib[i]!, a = 12 * ka, b = 12 * kb;
      // apply's isotropic factors (-1: read the stored products).
      const iA = buf.iso[i] === 1 ? T[6 * ka]! : -1, iB = buf.iso[i] === 1 ? T[6 * kb]! : -1;
      const nx = buf.nx[i]!, ny = buf.ny[i]!, nz = buf.nz[i]!;
      for (let k = 0, m = buf.points[i]!; k < m; k++) {
        const q = 4 * i + k;
        if (buf.vn0[q]! > -threshold || buf.maxLn[q] === 0) continue;
        const vn = relativeSpeed(sb, J, a, b, q, 0, nx, ny, nz);
        const old = buf.ln[q]!;
        const lam = Math.max(old - buf.mn[q]! * (vn + e * buf.vn0[q]!), 0);
        const dl = lam - old;
        buf.ln[q] = lam;
        if (dl !== 0) apply(sb, J, ka, kb, q, 0, dl, nx, ny, nz, iA, iB);
      }
    }
  }
}

/**
 * After the solve: which pairs touch (a point carried a normal impulse, or overlapped at the start of
 * the step) against those of the last step gives the begin and end touch events. Called at the end of
 * the contact solver, also on steps without rows (so the last contacts end).
 */
export function finishManifolds3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  if (st.eventStep !== world.steps) {
    st.eventStep = world.steps;
    const ev = st.events;
    ev.begin.count = 0; ev.end.count = 0; ev.sensorBegin.count = 0; ev.sensorEnd.count = 0;
  }
  const buf = st.current, key = world.capacity + 1, prev = st.touching, now = st.touchingNext;
  const h = (e: number): number => e === 0 ? 0 : currentHandle(world, e);
  now.count = 0;
  clearRowIndex(now.index, buf.count);
  for (let i = 0; i < buf.count; i++) {
    let touch = -1;
    for (let k = 0, m = buf.points[i]!; k < m; k++) {
      const q = 4 * i + k;
      if (buf.maxLn[q]! > 0 || buf.sep[q]! < 0) { touch = q; break; }
    }
    if (touch < 0) continue;
    const k = buf.shapeA[i]! * key + buf.shapeB[i]!;
    if (lookupRow(now.index, k) >= 0) continue;
    insertRow(now.index, k, pushTouch(now, k, buf.shapeA[i]!, buf.shapeB[i]!, buf.bodyA[i]!, buf.bodyB[i]!));
    if (lookupRow(prev.index, k) >= 0) continue;
    const ev = st.events.begin;
    const r = pushEvent3D(ev, h(buf.shapeA[i]!), h(buf.shapeB[i]!), h(buf.bodyA[i]!), h(buf.bodyB[i]!));
    const c = world.components, b = buf.bodyB[i]!;
    ev.px[r] = c.PreviousPosition.x[b]! + buf.rbx[touch]!; ev.py[r] = c.PreviousPosition.y[b]! + buf.rby[touch]!; ev.pz[r] = c.PreviousPosition.z[b]! + buf.rbz[touch]!;
    ev.nx[r] = buf.nx[i]!; ev.ny[r] = buf.ny[i]!; ev.nz[r] = buf.nz[i]!;
    ev.approachSpeed[r] = Math.max(0, -buf.vn0[touch]!);
  }
  for (let i = 0; i < prev.count; i++) {
    if (lookupRow(now.index, prev.keys[i]!) >= 0) continue;
    pushEvent3D(st.events.end, h(prev.shapeA[i]!), h(prev.shapeB[i]!), h(prev.bodyA[i]!), h(prev.bodyB[i]!));
  }
  st.touching = now; st.touchingNext = prev;
}

/** The 3D contact and sensor events of the last step (empty lists in a world without 3D shapes). Read rows 0..count-1 of each list; entities are handles. */
export function contactEvents3D(world: PhysicsWorld): import('./manifolds3d-state.js').ContactEvents3D {
  return contact3DStateOf(world, true).events;
}
