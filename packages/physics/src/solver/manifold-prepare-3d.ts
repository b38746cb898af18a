import { type Contact3DState, contact3DStateOf } from '../collision/manifolds-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import * as BS from './body-state-layout.js';
import { effectiveMass, prepareContactSoftness } from './contact-point.js';
import { CP_NORMAL_MASS, CP_NORMAL_ROW, CP_SEPARATION } from './contact-point-layout.js';
import * as M3 from './manifold-layout-3d.js';

/** Preparation of the 3D manifold rows at the start of a step (solver/manifold-rows-3d.ts): world inverse inertia tensors of the solver bodies, Jacobians, effective masses, softness and separations on the solver's base. */

/**
 * World inverse inertia tensors of the solver bodies, effective masses, separations corrected to the solver's base, approach speeds.
 * @category Collision
 */
export function prepareManifolds3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world, true);
  prepareSolverBodies3D(world);
  const cs = world.collision,
    buf = st.current,
    n = buf.count;
  const c = world.components,
    sb = cs.bodyState,
    ex = cs.bodyExtra,
    T = st.invInertia;
  const set = cs.settings,
    hs = world.h / set.solverSubsteps;
  prepareContactSoftness(st.softness, set, hs);
  if (n === 0) return;
  if (st.solveRecord.length < M3.REC_STRIDE * n) {
    const rows = Math.max(n, (2 * st.solveRecord.length) / M3.REC_STRIDE);
    st.jacobiansInv = new Float32Array(M3.JAC_STRIDE * 4 * rows);
    st.frictionInv = new Float32Array(M3.FRICTION_INV_STRIDE * rows);
    st.solveRecord = new Float64Array(M3.REC_STRIDE * rows);
  }
  const RA = buf.anchors,
    R = st.solveRecord,
    JI = st.jacobiansInv;
  const ox = c.PreviousPosition.x,
    oy = c.PreviousPosition.y,
    oz = c.PreviousPosition.z;
  for (let i = 0; i < n; i++) {
    const ka = buf.ia[i]!,
      kb = buf.ib[i]!,
      a = BS.BS3_STRIDE * ka,
      b = BS.BS3_STRIDE * kb,
      ta = BS.II3_STRIDE * ka,
      tb = BS.II3_STRIDE * kb;
    const mA = sb[a + BS.BS3_INV_MASS]!,
      mB = sb[b + BS.BS3_INV_MASS]!;
    const iso = isotropic(T, ta) && isotropic(T, tb);
    buf.iso[i] = iso ? 1 : 0;
    const nx = buf.nx[i]!,
      ny = buf.ny[i]!,
      nz = buf.nz[i]!;
    // Solver base minus where the narrowphase measured (PreviousPosition) along n.
    let shift = 0;
    if (ka > 0) {
      const e = buf.bodyA[i]!;
      shift -=
        (ex[BS.BX_STRIDE * ka + BS.BX_BASE_X]! - ox[e]!) * nx +
        (ex[BS.BX_STRIDE * ka + BS.BX_BASE_Y]! - oy[e]!) * ny +
        (ex[BS.BX_STRIDE * ka + BS.BX_BASE_Z]! - oz[e]!) * nz;
    }
    if (kb > 0) {
      const e = buf.bodyB[i]!;
      shift +=
        (ex[BS.BX_STRIDE * kb + BS.BX_BASE_X]! - ox[e]!) * nx +
        (ex[BS.BX_STRIDE * kb + BS.BX_BASE_Y]! - oy[e]!) * ny +
        (ex[BS.BX_STRIDE * kb + BS.BX_BASE_Z]! - oz[e]!) * nz;
    }
    let minSep = Infinity,
      reachA = 0,
      reachB = 0;
    const m = buf.points[i]!,
      h = M3.REC_STRIDE * i;
    for (let k = 0; k < m; k++) {
      const q = 4 * i + k,
        o = M3.JAC_STRIDE * q,
        p = h + M3.REC_POINTS + M3.POINT_STRIDE * k;
      buf.sep[q] = buf.sep[q]! + shift;
      R[p + CP_SEPARATION] = buf.sep[q]!;
      const r = M3.ANCHOR_STRIDE * q;
      const rax = RA[r + M3.ANCHOR_AX]!,
        ray = RA[r + M3.ANCHOR_AY]!,
        raz = RA[r + M3.ANCHOR_AZ]!,
        rbx = RA[r + M3.ANCHOR_BX]!,
        rby = RA[r + M3.ANCHOR_BY]!,
        rbz = RA[r + M3.ANCHOR_BZ]!;
      if (buf.sep[q]! < minSep) minSep = buf.sep[q]!;
      reachA = Math.max(reachA, rax * rax + ray * ray + raz * raz);
      reachB = Math.max(reachB, rbx * rbx + rby * rby + rbz * rbz);
      // r_A x n, r_B x n, and I_A^-1 (r_A x n), I_B^-1 (r_B x n), then the effective mass.
      const xax = ray * nz - raz * ny,
        xay = raz * nx - rax * nz,
        xaz = rax * ny - ray * nx;
      const xbx = rby * nz - rbz * ny,
        xby = rbz * nx - rbx * nz,
        xbz = rbx * ny - rby * nx;
      R[p + CP_NORMAL_ROW + M3.ROW_AX] = Math.fround(xax);
      R[p + CP_NORMAL_ROW + M3.ROW_AY] = Math.fround(xay);
      R[p + CP_NORMAL_ROW + M3.ROW_AZ] = Math.fround(xaz);
      R[p + CP_NORMAL_ROW + M3.ROW_BX] = Math.fround(xbx);
      R[p + CP_NORMAL_ROW + M3.ROW_BY] = Math.fround(xby);
      R[p + CP_NORMAL_ROW + M3.ROW_BZ] = Math.fround(xbz);
      const k0 = iso
        ? mA + mB + T[ta + BS.II3_XX]! * (xax * xax + xay * xay + xaz * xaz) + T[tb + BS.II3_XX]! * (xbx * xbx + xby * xby + xbz * xbz)
        : mA + mB + inertiaInto(JI, o + M3.ROW_AX, T, ta, xax, xay, xaz) + inertiaInto(JI, o + M3.ROW_BX, T, tb, xbx, xby, xbz);
      R[p + CP_NORMAL_MASS] = Math.fround(effectiveMass(k0));
      // Normal relative velocity at the start (for restitution): n . (v_B - v_A) + w_B . (r_B x n) - w_A . (r_A x n).
      buf.vn0[q] =
        (sb[b + BS.BS3_VX]! - sb[a + BS.BS3_VX]!) * nx +
        (sb[b + BS.BS3_VY]! - sb[a + BS.BS3_VY]!) * ny +
        (sb[b + BS.BS3_VZ]! - sb[a + BS.BS3_VZ]!) * nz +
        sb[b + BS.BS3_WX]! * xbx +
        sb[b + BS.BS3_WY]! * xby +
        sb[b + BS.BS3_WZ]! * xbz -
        sb[a + BS.BS3_WX]! * xax -
        sb[a + BS.BS3_WY]! * xay -
        sb[a + BS.BS3_WZ]! * xaz;
    }
    // The manifold's head (HEAD_*), written here and by prepareFriction3D: the speculative skip's bounds
    // (padded for the single-precision crosses), the normal, tangent, friction and isotropic inertias.
    R[h + M3.HEAD_MIN_SEP] = minSep;
    R[h + M3.HEAD_REACH_A] = Math.sqrt(reachA) * (1 + 1e-5) + 1e-9;
    R[h + M3.HEAD_REACH_B] = Math.sqrt(reachB) * (1 + 1e-5) + 1e-9;
    R[h + M3.HEAD_NX] = nx;
    R[h + M3.HEAD_NY] = ny;
    R[h + M3.HEAD_NZ] = nz;
    R[h + M3.HEAD_MU] = buf.friction[i]!;
    R[h + M3.HEAD_INV_IA] = iso ? T[ta + BS.II3_XX]! : 0;
    R[h + M3.HEAD_INV_IB] = iso ? T[tb + BS.II3_XX]! : 0;
    prepareFriction3D(st, i, iso, mA, mB, ta, tb);
  }
}

/**
 * Manifold i's friction rows (solver/manifold-rows-3d.ts): the anchor at its points'
 * centre, the twist arm (the points' mean distance from the anchor across n), and the rows along t1, t2
 * (crosses, effective masses) and about n (twist), in i's record in solveRecord and at i's place in
 * frictionInv (solver/manifold-layout-3d.ts). `iso`: both bodies are isotropic; mA, mB their inverse masses (1/kg);
 * ta, tb their rows of st.invInertia.
 */
function prepareFriction3D(st: Contact3DState, i: number, iso: boolean, mA: number, mB: number, ta: number, tb: number): void {
  const buf = st.current,
    RA = buf.anchors,
    T = st.invInertia,
    R = st.solveRecord,
    FV = st.frictionInv;
  const nx = buf.nx[i]!,
    ny = buf.ny[i]!,
    nz = buf.nz[i]!;
  const m = buf.points[i]!;
  // The friction anchor: the points' centre.
  let cax = 0,
    cay = 0,
    caz = 0,
    cbx = 0,
    cby = 0,
    cbz = 0;
  for (let k = 0; k < m; k++) {
    const q = 4 * i + k;
    const r = M3.ANCHOR_STRIDE * q;
    cax += RA[r + M3.ANCHOR_AX]!;
    cay += RA[r + M3.ANCHOR_AY]!;
    caz += RA[r + M3.ANCHOR_AZ]!;
    cbx += RA[r + M3.ANCHOR_BX]!;
    cby += RA[r + M3.ANCHOR_BY]!;
    cbz += RA[r + M3.ANCHOR_BZ]!;
  }
  const iw = 1 / m;
  cax *= iw;
  cay *= iw;
  caz *= iw;
  cbx *= iw;
  cby *= iw;
  cbz *= iw;
  // Twist arm: the points' mean distance from the anchor across n.
  let arm = 0;
  for (let k = 0; k < m; k++) {
    const q = 4 * i + k;
    const r = M3.ANCHOR_STRIDE * q;
    const dx = RA[r + M3.ANCHOR_AX]! - cax,
      dy = RA[r + M3.ANCHOR_AY]! - cay,
      dz = RA[r + M3.ANCHOR_AZ]! - caz,
      dn = dx * nx + dy * ny + dz * nz;
    arm += Math.sqrt(Math.max(dx * dx + dy * dy + dz * dz - dn * dn, 0));
  }
  const h = M3.REC_STRIDE * i;
  R[h + M3.HEAD_ARM] = arm / m;
  const t1x = buf.t1x[i]!,
    t1y = buf.t1y[i]!,
    t1z = buf.t1z[i]!;
  R[h + M3.HEAD_T1X] = t1x;
  R[h + M3.HEAD_T1Y] = t1y;
  R[h + M3.HEAD_T1Z] = t1z;
  const t2x = ny * t1z - nz * t1y,
    t2y = nz * t1x - nx * t1z,
    t2z = nx * t1y - ny * t1x;
  const fv = M3.FRICTION_INV_STRIDE * i;
  for (let d = 0; d < 2; d++) {
    const ux = d === 0 ? t1x : t2x,
      uy = d === 0 ? t1y : t2y,
      uz = d === 0 ? t1z : t2z;
    const xax = cay * uz - caz * uy,
      xay = caz * ux - cax * uz,
      xaz = cax * uy - cay * ux;
    const xbx = cby * uz - cbz * uy,
      xby = cbz * ux - cbx * uz,
      xbz = cbx * uy - cby * ux;
    const o = h + (d === 0 ? M3.REC_T1 : M3.REC_T2),
      ov = fv + (d === 0 ? M3.FRICTION_T1 : M3.FRICTION_T2);
    R[o + M3.ROW_AX] = Math.fround(xax);
    R[o + M3.ROW_AY] = Math.fround(xay);
    R[o + M3.ROW_AZ] = Math.fround(xaz);
    R[o + M3.ROW_BX] = Math.fround(xbx);
    R[o + M3.ROW_BY] = Math.fround(xby);
    R[o + M3.ROW_BZ] = Math.fround(xbz);
    const k0 = iso
      ? mA + mB + T[ta + BS.II3_XX]! * (xax * xax + xay * xay + xaz * xaz) + T[tb + BS.II3_XX]! * (xbx * xbx + xby * xby + xbz * xbz)
      : mA + mB + inertiaInto(FV, ov + M3.ROW_AX, T, ta, xax, xay, xaz) + inertiaInto(FV, ov + M3.ROW_BX, T, tb, xbx, xby, xbz);
    // Effective masses in single precision (as the normal rows'): the same numbers every build.
    R[h + (d === 0 ? M3.HEAD_MT1 : M3.HEAD_MT2)] = Math.fround(effectiveMass(k0));
  }
  // Twist about n: 1 / (n . I_A^-1 n + n . I_B^-1 n).
  const kw = iso
    ? T[ta + BS.II3_XX]! + T[tb + BS.II3_XX]!
    : inertiaInto(FV, fv + M3.FRICTION_TWIST + M3.ROW_AX, T, ta, nx, ny, nz) +
      inertiaInto(FV, fv + M3.FRICTION_TWIST + M3.ROW_BX, T, tb, nx, ny, nz);
  R[h + M3.HEAD_MTW] = Math.fround(effectiveMass(kw));
}

/** Writes I^-1 x (I^-1 the invInertia row at T[t]) into out[o..o+2] (a row's part, x, y, z) and returns x . I^-1 x. */
function inertiaInto(out: Float32Array, o: number, T: Float64Array, t: number, x: number, y: number, z: number): number {
  const ix = T[t + BS.II3_XX]! * x + T[t + BS.II3_XY]! * y + T[t + BS.II3_XZ]! * z,
    iy = T[t + BS.II3_XY]! * x + T[t + BS.II3_YY]! * y + T[t + BS.II3_YZ]! * z,
    iz = T[t + BS.II3_XZ]! * x + T[t + BS.II3_YZ]! * y + T[t + BS.II3_ZZ]! * z;
  out[o] = ix;
  out[o + 1] = iy;
  out[o + 2] = iz;
  return x * ix + y * iy + z * iz;
}

/** Whether the world inverse inertia tensor at T[o + II3_XX] is i 1 (prepareSolverBodies3D writes it exactly so for isotropic bodies). */
function isotropic(T: Float64Array, o: number): boolean {
  return (
    T[o + BS.II3_XY] === 0 &&
    T[o + BS.II3_XZ] === 0 &&
    T[o + BS.II3_YZ] === 0 &&
    T[o + BS.II3_XX] === T[o + BS.II3_YY] &&
    T[o + BS.II3_XX] === T[o + BS.II3_ZZ]
  );
}

/**
 * The world inverse inertia tensor of every solver body (I^-1 = R diag(1 / I_k) R^T with R from its
 * orientation; isotropic for a ball) and its rotation owed at the start of the solve (rotations in the
 * substeps are measured from it). Shared by the 3D contact and joint rows.
 * @category Collision
 */
export function prepareSolverBodies3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world, true);
  const cs = world.collision;
  const count = cs.solverBodyCount;
  if (st.invInertia.length < BS.II3_STRIDE * count) {
    st.invInertia = new Float64Array(2 * BS.II3_STRIDE * count);
    st.rotationBase = new Float64Array(6 * count);
  }
  const c = world.components,
    list = cs.solverBodies,
    sb = cs.bodyState,
    ex = cs.bodyExtra,
    T = st.invInertia,
    base = st.rotationBase;
  const Q = c.Orientation,
    IT = c.InertiaTensor;
  const hasT = IT.invX.length > 0;
  T.fill(0, 0, BS.II3_STRIDE);
  for (let k = 1; k < count; k++) {
    const e = list[k]!,
      o = BS.II3_STRIDE * k;
    base[3 * k] = ex[BS.BX_STRIDE * k + BS.BX_ROT_X]!;
    base[3 * k + 1] = ex[BS.BX_STRIDE * k + BS.BX_ROT_Y]!;
    base[3 * k + 2] = ex[BS.BX_STRIDE * k + BS.BX_ROT_Z]!;
    const ii = sb[BS.BS3_STRIDE * k + BS.BS3_INV_INERTIA]!;
    if (!(ii > 0)) {
      T.fill(0, o, o + BS.II3_STRIDE);
      continue;
    }
    const ix = hasT ? IT.invX[e]! : 0,
      iy = hasT ? IT.invY[e]! : 0,
      iz = hasT ? IT.invZ[e]! : 0;
    // No tensor (a ball: the body's own inverse inertia), or equal principal moments (a cube, a
    // sphere): R diag(i, i, i) R^T = i 1 exactly.
    const untensored = (ix === 0 && iy === 0 && iz === 0) || !(Q.w.length > e);
    if (untensored || (ix === iy && iy === iz)) {
      const i = untensored ? ii : ix;
      T[o + BS.II3_XX] = i;
      T[o + BS.II3_YY] = i;
      T[o + BS.II3_ZZ] = i;
      T[o + BS.II3_XY] = 0;
      T[o + BS.II3_XZ] = 0;
      T[o + BS.II3_YZ] = 0;
      continue;
    }
    const x = Q.x[e]!,
      y = Q.y[e]!,
      z = Q.z[e]!,
      w = Q.w[e]!;
    const r00 = 1 - 2 * (y * y + z * z),
      r01 = 2 * (x * y - z * w),
      r02 = 2 * (x * z + y * w);
    const r10 = 2 * (x * y + z * w),
      r11 = 1 - 2 * (x * x + z * z),
      r12 = 2 * (y * z - x * w);
    const r20 = 2 * (x * z - y * w),
      r21 = 2 * (y * z + x * w),
      r22 = 1 - 2 * (x * x + y * y);
    T[o + BS.II3_XX] = r00 * r00 * ix + r01 * r01 * iy + r02 * r02 * iz;
    T[o + BS.II3_YY] = r10 * r10 * ix + r11 * r11 * iy + r12 * r12 * iz;
    T[o + BS.II3_ZZ] = r20 * r20 * ix + r21 * r21 * iy + r22 * r22 * iz;
    T[o + BS.II3_XY] = r00 * r10 * ix + r01 * r11 * iy + r02 * r12 * iz;
    T[o + BS.II3_XZ] = r00 * r20 * ix + r01 * r21 * iy + r02 * r22 * iz;
    T[o + BS.II3_YZ] = r10 * r20 * ix + r11 * r21 * iy + r12 * r22 * iz;
  }
}
