import { contact3DStateOf } from '../collision/manifolds-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import {
  BS3_INV_INERTIA,
  BS3_INV_MASS,
  BS3_STRIDE,
  BS3_VX,
  BS3_VY,
  BS3_VZ,
  BS3_WX,
  BS3_WY,
  BS3_WZ,
  BX_BASE_X,
  BX_BASE_Y,
  BX_BASE_Z,
  BX_ROT_X,
  BX_ROT_Y,
  BX_ROT_Z,
  BX_STRIDE,
} from './body-state-layout.js';
import { FI, FJ, JAC, rigid, soft, TWIST } from './manifold-layout-3d.js';

/** Preparation of the 3D manifold rows at the start of a step (solver/manifold-rows-3d.ts): world inverse inertia tensors of the solver bodies, Jacobians, effective masses, softness and separations on the solver's base. */

/** Stiffness as a fraction of the substep rate (as the 2D shape contacts: solver/manifold-prepare-2d.ts). */
const HERTZ_FRACTION = 0.125;

function makeSoftInto(out: Float64Array, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    out[0] = 0;
    out[1] = 1;
    out[2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz,
    a1 = 2 * zeta + h * omega,
    a2 = h * omega * a1,
    a3 = 1 / (1 + a2);
  out[0] = omega / a1;
  out[1] = a2 * a3;
  out[2] = a3;
}

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
  const count = cs.solverBodyCount;
  const c = world.components,
    sb = cs.bodyState,
    ex = cs.bodyExtra,
    T = st.invInertia;
  const set = cs.settings,
    hs = world.h / set.solverSubsteps;
  const hertz = Math.min(set.contactHertz, HERTZ_FRACTION / hs);
  makeSoftInto(soft, hertz, set.contactDampingRatio, hs);
  makeSoftInto(rigid, 2 * hertz, set.contactDampingRatio, hs);
  void count;
  if (n === 0) return;
  if (st.jacobians.length < JAC * 4 * n) {
    const rows = Math.max(n, (2 * st.jacobians.length) / (4 * JAC));
    st.jacobians = new Float32Array(JAC * 4 * rows);
    st.jacobiansInv = new Float32Array(JAC * 4 * rows);
    st.frictionJacobians = new Float32Array(FJ * rows);
    st.frictionInv = new Float32Array(FI * rows);
  }
  const J = st.jacobians,
    JI = st.jacobiansInv,
    F = st.frictionJacobians,
    FV = st.frictionInv;
  const ox = c.PreviousPosition.x,
    oy = c.PreviousPosition.y,
    oz = c.PreviousPosition.z;
  for (let i = 0; i < n; i++) {
    const ka = buf.ia[i]!,
      kb = buf.ib[i]!,
      a = BS3_STRIDE * ka,
      b = BS3_STRIDE * kb,
      ta = 6 * ka,
      tb = 6 * kb;
    const mA = sb[a + BS3_INV_MASS]!,
      mB = sb[b + BS3_INV_MASS]!;
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
        (ex[BX_STRIDE * ka + BX_BASE_X]! - ox[e]!) * nx +
        (ex[BX_STRIDE * ka + BX_BASE_Y]! - oy[e]!) * ny +
        (ex[BX_STRIDE * ka + BX_BASE_Z]! - oz[e]!) * nz;
    }
    if (kb > 0) {
      const e = buf.bodyB[i]!;
      shift +=
        (ex[BX_STRIDE * kb + BX_BASE_X]! - ox[e]!) * nx +
        (ex[BX_STRIDE * kb + BX_BASE_Y]! - oy[e]!) * ny +
        (ex[BX_STRIDE * kb + BX_BASE_Z]! - oz[e]!) * nz;
    }
    let minSep = Infinity,
      reachA = 0,
      reachB = 0;
    // The friction anchor: the points' centre.
    let cax = 0,
      cay = 0,
      caz = 0,
      cbx = 0,
      cby = 0,
      cbz = 0;
    const m = buf.points[i]!;
    for (let k = 0; k < m; k++) {
      const q = 4 * i + k,
        o = JAC * q;
      buf.sep[q] = buf.sep[q]! + shift;
      const rax = buf.rax[q]!,
        ray = buf.ray[q]!,
        raz = buf.raz[q]!,
        rbx = buf.rbx[q]!,
        rby = buf.rby[q]!,
        rbz = buf.rbz[q]!;
      if (buf.sep[q]! < minSep) minSep = buf.sep[q]!;
      reachA = Math.max(reachA, rax * rax + ray * ray + raz * raz);
      reachB = Math.max(reachB, rbx * rbx + rby * rby + rbz * rbz);
      cax += rax;
      cay += ray;
      caz += raz;
      cbx += rbx;
      cby += rby;
      cbz += rbz;
      // r_A x n, r_B x n, and I_A^-1 (r_A x n), I_B^-1 (r_B x n), then the effective mass.
      const xax = ray * nz - raz * ny,
        xay = raz * nx - rax * nz,
        xaz = rax * ny - ray * nx;
      const xbx = rby * nz - rbz * ny,
        xby = rbz * nx - rbx * nz,
        xbz = rbx * ny - rby * nx;
      J[o] = xax;
      J[o + 1] = xay;
      J[o + 2] = xaz;
      J[o + 3] = xbx;
      J[o + 4] = xby;
      J[o + 5] = xbz;
      const k0 = iso
        ? mA + mB + T[ta]! * (xax * xax + xay * xay + xaz * xaz) + T[tb]! * (xbx * xbx + xby * xby + xbz * xbz)
        : mA + mB + inertiaInto(JI, o, T, ta, xax, xay, xaz) + inertiaInto(JI, o + 3, T, tb, xbx, xby, xbz);
      buf.mn[q] = k0 > 0 ? 1 / k0 : 0;
      // Normal relative velocity at the start (for restitution): n . (v_B - v_A) + w_B . (r_B x n) - w_A . (r_A x n).
      buf.vn0[q] =
        (sb[b + BS3_VX]! - sb[a + BS3_VX]!) * nx +
        (sb[b + BS3_VY]! - sb[a + BS3_VY]!) * ny +
        (sb[b + BS3_VZ]! - sb[a + BS3_VZ]!) * nz +
        sb[b + BS3_WX]! * xbx +
        sb[b + BS3_WY]! * xby +
        sb[b + BS3_WZ]! * xbz -
        sb[a + BS3_WX]! * xax -
        sb[a + BS3_WY]! * xay -
        sb[a + BS3_WZ]! * xaz;
    }
    // For the solver's skip of a speculative manifold (solveManifolds3D); padded for the single-precision crosses.
    buf.minSep[i] = minSep;
    buf.reachA[i] = Math.sqrt(reachA) * (1 + 1e-5) + 1e-9;
    buf.reachB[i] = Math.sqrt(reachB) * (1 + 1e-5) + 1e-9;
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
      const dx = buf.rax[q]! - cax,
        dy = buf.ray[q]! - cay,
        dz = buf.raz[q]! - caz,
        dn = dx * nx + dy * ny + dz * nz;
      arm += Math.sqrt(Math.max(dx * dx + dy * dy + dz * dz - dn * dn, 0));
    }
    buf.arm[i] = arm / m;
    const t1x = buf.t1x[i]!,
      t1y = buf.t1y[i]!,
      t1z = buf.t1z[i]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const f = FJ * i;
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
      const o = f + 6 * d;
      F[o] = xax;
      F[o + 1] = xay;
      F[o + 2] = xaz;
      F[o + 3] = xbx;
      F[o + 4] = xby;
      F[o + 5] = xbz;
      const k0 = iso
        ? mA + mB + T[ta]! * (xax * xax + xay * xay + xaz * xaz) + T[tb]! * (xbx * xbx + xby * xby + xbz * xbz)
        : mA + mB + inertiaInto(FV, FI * i + 6 * d, T, ta, xax, xay, xaz) + inertiaInto(FV, FI * i + 6 * d + 3, T, tb, xbx, xby, xbz);
      if (d === 0) buf.mt1[i] = k0 > 0 ? 1 / k0 : 0;
      else buf.mt2[i] = k0 > 0 ? 1 / k0 : 0;
    }
    // Twist about n: 1 / (n . I_A^-1 n + n . I_B^-1 n).
    const kw = iso
      ? T[ta]! + T[tb]!
      : inertiaInto(FV, FI * i + TWIST, T, ta, nx, ny, nz) + inertiaInto(FV, FI * i + TWIST + 3, T, tb, nx, ny, nz);
    buf.mtw[i] = kw > 0 ? 1 / kw : 0;
  }
}

/** Writes I^-1 x (I^-1 at T[t..t+5]: xx, yy, zz, xy, xz, yz) into out[o..o+2] and returns x . I^-1 x. */
function inertiaInto(out: Float32Array, o: number, T: Float64Array, t: number, x: number, y: number, z: number): number {
  const ix = T[t]! * x + T[t + 3]! * y + T[t + 4]! * z,
    iy = T[t + 3]! * x + T[t + 1]! * y + T[t + 5]! * z,
    iz = T[t + 4]! * x + T[t + 5]! * y + T[t + 2]! * z;
  out[o] = ix;
  out[o + 1] = iy;
  out[o + 2] = iz;
  return x * ix + y * iy + z * iz;
}

/** Whether the world inverse inertia tensor at T[o..o+5] is i 1 (prepareSolverBodies3D writes it exactly so for isotropic bodies). */
function isotropic(T: Float64Array, o: number): boolean {
  return T[o + 3] === 0 && T[o + 4] === 0 && T[o + 5] === 0 && T[o] === T[o + 1] && T[o] === T[o + 2];
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
  if (st.invInertia.length < 6 * count) {
    st.invInertia = new Float64Array(12 * count);
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
  T.fill(0, 0, 6);
  for (let k = 1; k < count; k++) {
    const e = list[k]!,
      o = 6 * k;
    base[3 * k] = ex[BX_STRIDE * k + BX_ROT_X]!;
    base[3 * k + 1] = ex[BX_STRIDE * k + BX_ROT_Y]!;
    base[3 * k + 2] = ex[BX_STRIDE * k + BX_ROT_Z]!;
    const ii = sb[BS3_STRIDE * k + BS3_INV_INERTIA]!;
    if (!(ii > 0)) {
      T.fill(0, o, o + 6);
      continue;
    }
    const ix = hasT ? IT.invX[e]! : 0,
      iy = hasT ? IT.invY[e]! : 0,
      iz = hasT ? IT.invZ[e]! : 0;
    // No tensor (a ball), or equal principal moments (a cube, a sphere): R diag(i, i, i) R^T = i 1 exactly.
    if ((ix === 0 && iy === 0 && iz === 0) || !(Q.w.length > e)) {
      T[o] = ii;
      T[o + 1] = ii;
      T[o + 2] = ii;
      T[o + 3] = 0;
      T[o + 4] = 0;
      T[o + 5] = 0;
      continue;
    }
    if (ix === iy && iy === iz) {
      T[o] = ix;
      T[o + 1] = ix;
      T[o + 2] = ix;
      T[o + 3] = 0;
      T[o + 4] = 0;
      T[o + 5] = 0;
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
    T[o] = r00 * r00 * ix + r01 * r01 * iy + r02 * r02 * iz;
    T[o + 1] = r10 * r10 * ix + r11 * r11 * iy + r12 * r12 * iz;
    T[o + 2] = r20 * r20 * ix + r21 * r21 * iy + r22 * r22 * iz;
    T[o + 3] = r00 * r10 * ix + r01 * r11 * iy + r02 * r12 * iz;
    T[o + 4] = r00 * r20 * ix + r01 * r21 * iy + r02 * r22 * iz;
    T[o + 5] = r10 * r20 * ix + r11 * r21 * iy + r12 * r22 * iz;
  }
}
