import { quaternionProduct, rotateVector, turnQuaternion } from '../math/quaternion.js';
import * as BS from '../solver/body-state-layout.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * The pieces the 3D joint rows are solved with (joints/solver-3d.ts): a body's pose within the step
 * (start pose, displacement and rotation so far), impulses applied to the packed solver bodies, anchor
 * velocities, effective masses of linear and angular rows, a 3 x 3 solve, and the one-row solves of a
 * linear or angular constraint.
 */

// Per-call scratch: pose of the two ends.
export const qa = new Float64Array(4),
  qb = new Float64Array(4),
  pa = new Float64Array(3),
  pb = new Float64Array(3),
  ra = new Float64Array(3),
  rb = new Float64Array(3);

/** pose's rotation owed (x, y, z, angle) and relativeRotation's conjugate of a: scratch. */
const owed = new Float64Array(4),
  conjugate = new Float64Array(4);

/** Current orientation and position of joint end e (solver index k) into q and p. */
export function pose(world: PhysicsWorld, e: number, k: number, q: Float64Array, p: Float64Array): void {
  if (e === 0) {
    q[0] = 0;
    q[1] = 0;
    q[2] = 0;
    q[3] = 1;
    p[0] = 0;
    p[1] = 0;
    p[2] = 0;
    return;
  }
  const c = world.components,
    Q = c.Orientation;
  q[0] = Q.x[e]!;
  q[1] = Q.y[e]!;
  q[2] = Q.z[e]!;
  q[3] = Q.w[e]!;
  if (k === 0) {
    p[0] = c.Position.x[e]!;
    p[1] = c.Position.y[e]!;
    p[2] = c.Position.z[e]!;
    return;
  }
  const ex = world.collision.bodyExtra,
    sb = world.collision.bodyState;
  const rx = ex[BS.BX_STRIDE * k + BS.BX_ROT_X]!,
    ry = ex[BS.BX_STRIDE * k + BS.BX_ROT_Y]!,
    rz = ex[BS.BX_STRIDE * k + BS.BX_ROT_Z]!,
    a = Math.hypot(rx, ry, rz);
  owed[0] = rx;
  owed[1] = ry;
  owed[2] = rz;
  owed[3] = a;
  if (a > 0) turnQuaternion(q, owed, q);
  p[0] = ex[BS.BX_STRIDE * k + BS.BX_BASE_X]! + sb[BS.BS3_STRIDE * k + BS.BS3_DX]!;
  p[1] = ex[BS.BX_STRIDE * k + BS.BX_BASE_Y]! + sb[BS.BS3_STRIDE * k + BS.BS3_DY]!;
  p[2] = ex[BS.BX_STRIDE * k + BS.BX_BASE_Z]! + sb[BS.BS3_STRIDE * k + BS.BS3_DZ]!;
}

/** The rotation of B relative to A, conj(a) b, of unit quaternions a and b (x, y, z, w), into out. */
export function relativeRotation(a: ArrayLike<number>, b: ArrayLike<number>, out: Float64Array): void {
  conjugate[0] = -a[0]!;
  conjugate[1] = -a[1]!;
  conjugate[2] = -a[2]!;
  conjugate[3] = a[3]!;
  quaternionProduct(conjugate, b, out);
}

/** v rotated by the unit quaternion q (x, y, z, w; body to world frame) into out. */
export function rot(q: Float64Array, vx: number, vy: number, vz: number, out: Float64Array): void {
  rotateVector(q[0]!, q[1]!, q[2]!, q[3]!, vx, vy, vz, out);
}

/** I^-1 v for solver body k (0: zero) into out. */
export function invI(T: Float64Array, k: number, vx: number, vy: number, vz: number, out: Float64Array, o: number): void {
  const t = 6 * k;
  out[o] = T[t]! * vx + T[t + 3]! * vy + T[t + 4]! * vz;
  out[o + 1] = T[t + 3]! * vx + T[t + 1]! * vy + T[t + 5]! * vz;
  out[o + 2] = T[t + 4]! * vx + T[t + 5]! * vy + T[t + 2]! * vz;
}

export const tmp = new Float64Array(6);

/** Linear impulse P at the anchors: -P to A, +P to B. */
export function applyLinear(sb: Float64Array, T: Float64Array, a: number, b: number, px: number, py: number, pz: number): void {
  if (a > 0) {
    const o = BS.BS3_STRIDE * a,
      m = sb[o + BS.BS3_INV_MASS]!;
    sb[o + BS.BS3_VX] = sb[o + BS.BS3_VX]! - m * px;
    sb[o + BS.BS3_VY] = sb[o + BS.BS3_VY]! - m * py;
    sb[o + BS.BS3_VZ] = sb[o + BS.BS3_VZ]! - m * pz;
    invI(T, a, ra[1]! * pz - ra[2]! * py, ra[2]! * px - ra[0]! * pz, ra[0]! * py - ra[1]! * px, tmp, 0);
    sb[o + BS.BS3_WX] = sb[o + BS.BS3_WX]! - tmp[0]!;
    sb[o + BS.BS3_WY] = sb[o + BS.BS3_WY]! - tmp[1]!;
    sb[o + BS.BS3_WZ] = sb[o + BS.BS3_WZ]! - tmp[2]!;
  }
  if (b > 0) {
    const o = BS.BS3_STRIDE * b,
      m = sb[o + BS.BS3_INV_MASS]!;
    sb[o + BS.BS3_VX] = sb[o + BS.BS3_VX]! + m * px;
    sb[o + BS.BS3_VY] = sb[o + BS.BS3_VY]! + m * py;
    sb[o + BS.BS3_VZ] = sb[o + BS.BS3_VZ]! + m * pz;
    invI(T, b, rb[1]! * pz - rb[2]! * py, rb[2]! * px - rb[0]! * pz, rb[0]! * py - rb[1]! * px, tmp, 0);
    sb[o + BS.BS3_WX] = sb[o + BS.BS3_WX]! + tmp[0]!;
    sb[o + BS.BS3_WY] = sb[o + BS.BS3_WY]! + tmp[1]!;
    sb[o + BS.BS3_WZ] = sb[o + BS.BS3_WZ]! + tmp[2]!;
  }
}

/** Angular impulse L: -L to A, +L to B. */
export function applyAngular(sb: Float64Array, T: Float64Array, a: number, b: number, lx: number, ly: number, lz: number): void {
  if (a > 0) {
    invI(T, a, lx, ly, lz, tmp, 0);
    const o = BS.BS3_STRIDE * a;
    sb[o + BS.BS3_WX] = sb[o + BS.BS3_WX]! - tmp[0]!;
    sb[o + BS.BS3_WY] = sb[o + BS.BS3_WY]! - tmp[1]!;
    sb[o + BS.BS3_WZ] = sb[o + BS.BS3_WZ]! - tmp[2]!;
  }
  if (b > 0) {
    invI(T, b, lx, ly, lz, tmp, 0);
    const o = BS.BS3_STRIDE * b;
    sb[o + BS.BS3_WX] = sb[o + BS.BS3_WX]! + tmp[0]!;
    sb[o + BS.BS3_WY] = sb[o + BS.BS3_WY]! + tmp[1]!;
    sb[o + BS.BS3_WZ] = sb[o + BS.BS3_WZ]! + tmp[2]!;
  }
}

/** Relative velocity of the anchors, vB + wB x rB - vA - wA x rA, into out[0..2]. */
export function anchorVelocity(sb: Float64Array, a: number, b: number, out: Float64Array): void {
  const oa = BS.BS3_STRIDE * a,
    ob = BS.BS3_STRIDE * b;
  const wax = sb[oa + BS.BS3_WX]!,
    way = sb[oa + BS.BS3_WY]!,
    waz = sb[oa + BS.BS3_WZ]!,
    wbx = sb[ob + BS.BS3_WX]!,
    wby = sb[ob + BS.BS3_WY]!,
    wbz = sb[ob + BS.BS3_WZ]!;
  out[0] = sb[ob + BS.BS3_VX]! + wby * rb[2]! - wbz * rb[1]! - sb[oa + BS.BS3_VX]! - (way * ra[2]! - waz * ra[1]!);
  out[1] = sb[ob + BS.BS3_VY]! + wbz * rb[0]! - wbx * rb[2]! - sb[oa + BS.BS3_VY]! - (waz * ra[0]! - wax * ra[2]!);
  out[2] = sb[ob + BS.BS3_VZ]! + wbx * rb[1]! - wby * rb[0]! - sb[oa + BS.BS3_VZ]! - (wax * ra[1]! - way * ra[0]!);
}

/** The relative spin of B about unit u, (wB - wA) . u, rad/s. */
export function relativeSpin(sb: Float64Array, a: number, b: number, ux: number, uy: number, uz: number): number {
  const oa = BS.BS3_STRIDE * a,
    ob = BS.BS3_STRIDE * b;
  return (
    (sb[ob + BS.BS3_WX]! - sb[oa + BS.BS3_WX]!) * ux +
    (sb[ob + BS.BS3_WY]! - sb[oa + BS.BS3_WY]!) * uy +
    (sb[ob + BS.BS3_WZ]! - sb[oa + BS.BS3_WZ]!) * uz
  );
}

/** Solves the 3 x 3 system M x = r (M row-major) in place into x by Cramer's rule; a singular M gives 0. */
export function solve3(M: Float64Array, r0: number, r1: number, r2: number, x: Float64Array): void {
  const a = M[0]!,
    b = M[1]!,
    c = M[2]!,
    d = M[3]!,
    e = M[4]!,
    f = M[5]!,
    g = M[6]!,
    h = M[7]!,
    i = M[8]!;
  const A = e * i - f * h,
    B = -(d * i - f * g),
    C = d * h - e * g;
  const det = a * A + b * B + c * C;
  if (!(Math.abs(det) > 0)) {
    x[0] = 0;
    x[1] = 0;
    x[2] = 0;
    return;
  }
  const inv = 1 / det;
  x[0] = inv * (A * r0 + (c * h - b * i) * r1 + (b * f - c * e) * r2);
  x[1] = inv * (B * r0 + (a * i - c * g) * r1 + (c * d - a * f) * r2);
  x[2] = inv * (C * r0 + (b * g - a * h) * r1 + (a * e - b * d) * r2);
}

export const K = new Float64Array(9),
  x3 = new Float64Array(3),
  v3 = new Float64Array(3),
  ax = new Float64Array(3),
  bx = new Float64Array(3);

/** Effective mass denominator of a linear row along unit u at the anchors ra, rb: 1/m_A + 1/m_B + (r x u) . I^-1 (r x u) for both. */
export function linearK(sb: Float64Array, T: Float64Array, a: number, b: number, ux: number, uy: number, uz: number): number {
  const cax = ra[1]! * uz - ra[2]! * uy,
    cay = ra[2]! * ux - ra[0]! * uz,
    caz = ra[0]! * uy - ra[1]! * ux;
  const cbx = rb[1]! * uz - rb[2]! * uy,
    cby = rb[2]! * ux - rb[0]! * uz,
    cbz = rb[0]! * uy - rb[1]! * ux;
  invI(T, a, cax, cay, caz, tmp, 0);
  invI(T, b, cbx, cby, cbz, tmp, 3);
  return (
    sb[BS.BS3_STRIDE * a + BS.BS3_INV_MASS]! +
    sb[BS.BS3_STRIDE * b + BS.BS3_INV_MASS]! +
    cax * tmp[0]! +
    cay * tmp[1]! +
    caz * tmp[2]! +
    cbx * tmp[3]! +
    cby * tmp[4]! +
    cbz * tmp[5]!
  );
}

/**
 * The inverse mass of a point joint averaged over directions, a third of the trace of its 3 x 3 block:
 * mA + mB + (tr(IA^-1) |rA|^2 - rA . IA^-1 rA + the same for B) / 3, kg^-1, with the world anchors ra,
 * rb of this moment. Rotating a body turns its anchor and its inverse inertia together, so no motion
 * changes it.
 */
export function referenceK(sb: Float64Array, T: Float64Array, a: number, b: number): number {
  invI(T, a, ra[0]!, ra[1]!, ra[2]!, tmp, 0);
  invI(T, b, rb[0]!, rb[1]!, rb[2]!, tmp, 3);
  const ta = 6 * a,
    tb = 6 * b;
  const ka =
    (T[ta]! + T[ta + 1]! + T[ta + 2]!) * (ra[0]! ** 2 + ra[1]! ** 2 + ra[2]! ** 2) -
    (ra[0]! * tmp[0]! + ra[1]! * tmp[1]! + ra[2]! * tmp[2]!);
  const kb =
    (T[tb]! + T[tb + 1]! + T[tb + 2]!) * (rb[0]! ** 2 + rb[1]! ** 2 + rb[2]! ** 2) -
    (rb[0]! * tmp[3]! + rb[1]! * tmp[4]! + rb[2]! * tmp[5]!);
  return sb[BS.BS3_STRIDE * a + BS.BS3_INV_MASS]! + sb[BS.BS3_STRIDE * b + BS.BS3_INV_MASS]! + (ka + kb) / 3;
}

/**
 * One row along (`linear`: at the anchors, effective mass 1 / k) or about (angular: k from the bodies'
 * inverse inertias) unit u, impulse +lambda u to B: lambda = clamp(acc - ms (cdot + bias) / k - is acc,
 * lo, hi); applies the change and returns the new lambda (acc when an angular row has no effective mass).
 */
export function row3D(
  sb: Float64Array,
  T: Float64Array,
  a: number,
  b: number,
  linear: boolean,
  ux: number,
  uy: number,
  uz: number,
  k: number,
  cdot: number,
  bias: number,
  ms: number,
  is: number,
  acc: number,
  lo: number,
  hi: number,
): number {
  if (!linear) {
    invI(T, a, ux, uy, uz, tmp, 0);
    invI(T, b, ux, uy, uz, tmp, 3);
    k = ux * (tmp[0]! + tmp[3]!) + uy * (tmp[1]! + tmp[4]!) + uz * (tmp[2]! + tmp[5]!);
    if (!(k > 0)) return acc;
  }
  let lam = acc - (ms * (cdot + bias)) / k - is * acc;
  lam = lam < lo ? lo : lam > hi ? hi : lam;
  const d = lam - acc;
  if (d !== 0) {
    if (linear) applyLinear(sb, T, a, b, d * ux, d * uy, d * uz);
    else applyAngular(sb, T, a, b, d * ux, d * uy, d * uz);
  }
  return lam;
}

/** Relative velocity of the anchors along unit u. */
export function anchorSpeed(sb: Float64Array, a: number, b: number, ux: number, uy: number, uz: number): number {
  anchorVelocity(sb, a, b, v3);
  return v3[0]! * ux + v3[1]! * uy + v3[2]! * uz;
}

/** K := P K P + u u^T with P = 1 - u u^T: the 3 x 3 block restricted to the plane perpendicular to unit u (invertible, the same on the plane). */
export function restrictToPlane(ux: number, uy: number, uz: number): void {
  P9[0] = 1 - ux * ux;
  P9[1] = -ux * uy;
  P9[2] = -ux * uz;
  P9[3] = -uy * ux;
  P9[4] = 1 - uy * uy;
  P9[5] = -uy * uz;
  P9[6] = -uz * ux;
  P9[7] = -uz * uy;
  P9[8] = 1 - uz * uz;
  for (let r = 0; r < 3; r++)
    for (let c = 0; c < 3; c++) {
      let v = 0;
      for (let m = 0; m < 3; m++) for (let n = 0; n < 3; n++) v += P9[3 * r + m]! * K[3 * m + n]! * P9[3 * n + c]!;
      KP[3 * r + c] = v;
    }
  const u0 = ux,
    u1 = uy,
    u2 = uz;
  K[0] = KP[0]! + u0 * u0;
  K[1] = KP[1]! + u0 * u1;
  K[2] = KP[2]! + u0 * u2;
  K[3] = KP[3]! + u1 * u0;
  K[4] = KP[4]! + u1 * u1;
  K[5] = KP[5]! + u1 * u2;
  K[6] = KP[6]! + u2 * u0;
  K[7] = KP[7]! + u2 * u1;
  K[8] = KP[8]! + u2 * u2;
}

const P9 = new Float64Array(9),
  KP = new Float64Array(9);
