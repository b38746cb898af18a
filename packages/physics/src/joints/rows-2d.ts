import { JointFlag } from '../world/joint-store-2d.js';
import * as R from './layout-2d.js';

/**
 * The row code the 2D joint types share, on the frame of the row being solved (layout-2d.ts F_*): the
 * fixed-stiffness spring's impulse, the point-to-point block of the revolute and weld joints, and the
 * axis rows of the prismatic and wheel joints; and the soft-constraint coefficients and the angle
 * wrapping that the preparation and the revolute joint use. Each type's own row solve is in its file
 * (distance-joint.ts, revolute-joint.ts, weld-joint.ts, mouse-joint.ts); joints/solve-2d.ts runs them.
 */

/**
 * The impulse of a fixed-stiffness spring row (see `fixedSpring`): `cdot` the velocity along the
 * row, `c` its position error, `k` the inverse effective mass of the moment, `lambda` the impulse the
 * row holds, `bias` and `gamma` from `fixedSpring`.
 */
export function springImpulse(cdot: number, c: number, k: number, lambda: number, bias: number, gamma: number): number {
  if (!(gamma < Infinity)) return -lambda;
  const den = k + gamma;
  return den > 0 ? -(cdot + bias * c + gamma * lambda) / den : 0;
}

/**
 * One pass of a one-sided limit row (its accumulated impulse at `slot` stays >= 0), with position
 * error C (>= 0 inside the limit), velocity `cdot` along the row and effective mass `k`: speculative
 * while C > 0 (bias C / h_s, `invH` = 1 / h_s), soft with the row's JB, JM, JI while `useBias`, else
 * rigid (Catto, "Soft Constraints", GDC 2011; Box2D v3's joint limits).
 * @returns the change of the accumulated impulse.
 */
export function limitRow(
  rows: Float64Array,
  o: number,
  slot: number,
  C: number,
  k: number,
  cdot: number,
  invH: number,
  useBias: boolean,
): number {
  let bias = 0,
    ms = 1,
    is = 0;
  if (C > 0) bias = C * invH;
  else if (useBias) {
    bias = rows[o + R.JB]! * C;
    ms = rows[o + R.JM]!;
    is = rows[o + R.JI]!;
  }
  const old = rows[o + slot]!;
  let next = old - ms * k * (cdot + bias) - is * old;
  if (next < 0) next = 0;
  rows[o + slot] = next;
  return next - old;
}

/**
 * Point-to-point: the anchors coincide, as one 2 x 2 block (the revolute and weld joints' linear
 * rows). `soft`: the rows push out the anchors' separation as a soft constraint (JB, JM, JI); else
 * they only remove relative velocity. Reads and writes the frame's velocities.
 */
export function solvePointBlock(rows: Float64Array, o: number, f: Float64Array, soft: boolean): void {
  const mA = f[R.F_MA]!,
    iA = f[R.F_IA]!,
    mB = f[R.F_MB]!,
    iB = f[R.F_IB]!;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  let vAx = f[R.F_VAX]!,
    vAy = f[R.F_VAY]!,
    wA = f[R.F_WA]!,
    vBx = f[R.F_VBX]!,
    vBy = f[R.F_VBY]!,
    wB = f[R.F_WB]!;
  const cdx = vBx - wB * rBy - vAx + wA * rAy,
    cdy = vBy + wB * rBx - vAy - wA * rAx;
  let bx = 0,
    by = 0,
    ms = 1,
    is = 0;
  if (soft) {
    bx = rows[o + R.JB]! * f[R.F_DX]!;
    by = rows[o + R.JB]! * f[R.F_DY]!;
    ms = rows[o + R.JM]!;
    is = rows[o + R.JI]!;
  }
  const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
  const k12 = -rAy * rAx * iA - rBy * rBx * iB;
  const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
  let det = k11 * k22 - k12 * k12;
  if (det !== 0) det = 1 / det;
  const ex = cdx + bx,
    ey = cdy + by;
  const sx = det * (k22 * ex - k12 * ey),
    sy = det * (k11 * ey - k12 * ex);
  const ix = -ms * sx - is * rows[o + R.ILX]!,
    iy = -ms * sy - is * rows[o + R.ILY]!;
  rows[o + R.ILX] = rows[o + R.ILX]! + ix;
  rows[o + R.ILY] = rows[o + R.ILY]! + iy;
  vAx -= mA * ix;
  vAy -= mA * iy;
  wA -= iA * (rAx * iy - rAy * ix);
  vBx += mB * ix;
  vBy += mB * iy;
  wB += iB * (rBx * iy - rBy * ix);
  f[R.F_VAX] = vAx;
  f[R.F_VAY] = vAy;
  f[R.F_WA] = wA;
  f[R.F_VBX] = vBx;
  f[R.F_VBY] = vBy;
  f[R.F_WB] = wB;
}

/**
 * The rows of a prismatic (`prismatic` true) or wheel joint along and across its axis (Box2D v3's
 * prismatic_joint.c and wheel_joint.c): the wheel's rotation motor, the axial spring, the prismatic's
 * axial motor, the translation limits, then across the axis one row (wheel) or, with the relative
 * angle, a 2 x 2 block (prismatic). Reads and writes the frame's velocities. @returns ROW_PUSHED.
 */
export function solveAxisRow(rows: Float64Array, o: number, flags: number, useBias: boolean, f: Float64Array, prismatic: boolean): number {
  const mA = f[R.F_MA]!,
    iA = f[R.F_IA]!,
    mB = f[R.F_MB]!,
    iB = f[R.F_IB]!;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  const cA = f[R.F_CA]!,
    sA = f[R.F_SA]!;
  const invH = f[R.F_INVH]!;
  let vAx = f[R.F_VAX]!,
    vAy = f[R.F_VAY]!,
    wA = f[R.F_WA]!,
    vBx = f[R.F_VBX]!,
    vBy = f[R.F_VBY]!,
    wB = f[R.F_WB]!;
  const fixedRotation = iA + iB === 0;
  const axx = cA * rows[o + R.AXX]! - sA * rows[o + R.AXY]!,
    axy = sA * rows[o + R.AXX]! + cA * rows[o + R.AXY]!;
  const translation = axx * dx + axy * dy;
  const a1 = (dx + rAx) * axy - (dy + rAy) * axx,
    a2 = rBx * axy - rBy * axx;
  const kax = rows[o + R.KAX]!;
  const kA = iA * a1,
    kB = iB * a2;
  // Axial impulses: P = lambda axis on B (minus on A), angular lambda a1 on A and lambda a2 on B.
  if (!prismatic && flags & JointFlag.Motor && !fixedRotation) {
    const max = rows[o + R.MMAX]!;
    const old = rows[o + R.IMOT]!;
    let next = old - rows[o + R.KMOT]! * (wB - wA - rows[o + R.MSPD]!);
    next = next < -max ? -max : next > max ? max : next;
    rows[o + R.IMOT] = next;
    wA -= iA * (next - old);
    wB += iB * (next - old);
  }
  if (flags & JointFlag.Spring) {
    const cdot = axx * (vBx - vAx) + axy * (vBy - vAy) + a2 * wB - a1 * wA;
    const impulse = springImpulse(cdot, translation, mA + mB + kA * a1 + kB * a2, rows[o + R.ISPR]!, rows[o + R.SB]!, rows[o + R.SM]!);
    rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
    vAx -= mA * impulse * axx;
    vAy -= mA * impulse * axy;
    wA -= kA * impulse;
    vBx += mB * impulse * axx;
    vBy += mB * impulse * axy;
    wB += kB * impulse;
  }
  if (prismatic && flags & JointFlag.Motor) {
    const cdot = axx * (vBx - vAx) + axy * (vBy - vAy) + a2 * wB - a1 * wA;
    const max = rows[o + R.MMAX]!;
    const old = rows[o + R.IMOT]!;
    let next = old + kax * (rows[o + R.MSPD]! - cdot);
    next = next < -max ? -max : next > max ? max : next;
    rows[o + R.IMOT] = next;
    const impulse = next - old;
    vAx -= mA * impulse * axx;
    vAy -= mA * impulse * axy;
    wA -= kA * impulse;
    vBx += mB * impulse * axx;
    vBy += mB * impulse * axy;
    wB += kB * impulse;
  }
  if (flags & JointFlag.Limit) {
    for (let side = 0; side < 2; side++) {
      // Lower: C = translation - lower >= 0. Upper (signs flipped): C = upper - translation >= 0.
      const sign = side === 0 ? 1 : -1;
      const C = side === 0 ? translation - rows[o + R.LOW]! : rows[o + R.UP]! - translation;
      const cdot = sign * (axx * (vBx - vAx) + axy * (vBy - vAy) + a2 * wB - a1 * wA);
      const impulse = sign * limitRow(rows, o, side === 0 ? R.ILOW : R.IUP, C, kax, cdot, invH, useBias);
      vAx -= mA * impulse * axx;
      vAy -= mA * impulse * axy;
      wA -= kA * impulse;
      vBx += mB * impulse * axx;
      vBy += mB * impulse * axy;
      wB += kB * impulse;
    }
  }
  f[R.F_VAX] = vAx;
  f[R.F_VAY] = vAy;
  f[R.F_WA] = wA;
  f[R.F_VBX] = vBx;
  f[R.F_VBY] = vBy;
  f[R.F_WB] = wB;
  solveAcrossAxis(rows, o, useBias, f, prismatic, axx, axy);
  return R.ROW_PUSHED;
}

/**
 * The rows across a prismatic or wheel joint's axis (world direction (axx, axy)): one row against
 * sideways motion (wheel), or with the relative angle a 2 x 2 block (prismatic). Reads and writes the
 * frame's velocities.
 */
function solveAcrossAxis(
  rows: Float64Array,
  o: number,
  useBias: boolean,
  f: Float64Array,
  prismatic: boolean,
  axx: number,
  axy: number,
): void {
  const mA = f[R.F_MA]!,
    iA = f[R.F_IA]!,
    mB = f[R.F_MB]!,
    iB = f[R.F_IB]!;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  let vAx = f[R.F_VAX]!,
    vAy = f[R.F_VAY]!,
    wA = f[R.F_WA]!,
    vBx = f[R.F_VBX]!,
    vBy = f[R.F_VBY]!,
    wB = f[R.F_WB]!;
  // Perpendicular to the axis (and, for prismatic, the relative angle).
  const pxx = -axy,
    pxy = axx;
  const s1 = (dx + rAx) * pxy - (dy + rAy) * pxx,
    s2 = rBx * pxy - rBy * pxx;
  const cd1 = pxx * (vBx - vAx) + pxy * (vBy - vAy) + s2 * wB - s1 * wA;
  let ms = 1,
    is = 0,
    b1 = 0,
    b2 = 0;
  if (useBias) {
    ms = rows[o + R.JM]!;
    is = rows[o + R.JI]!;
    b1 = rows[o + R.JB]! * (pxx * dx + pxy * dy);
    b2 = rows[o + R.JB]! * f[R.F_REL]!;
  }
  const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
  if (prismatic) {
    const k12 = iA * s1 + iB * s2;
    let k22 = iA + iB;
    if (k22 === 0) k22 = 1;
    let det = k11 * k22 - k12 * k12;
    if (det !== 0) det = 1 / det;
    const e1 = cd1 + b1,
      e2 = wB - wA + b2;
    const x1 = det * (k22 * e1 - k12 * e2),
      x2 = det * (k11 * e2 - k12 * e1);
    const i1 = -ms * x1 - is * rows[o + R.ILX]!,
      i2 = -ms * x2 - is * rows[o + R.IANG]!;
    rows[o + R.ILX] = rows[o + R.ILX]! + i1;
    rows[o + R.IANG] = rows[o + R.IANG]! + i2;
    const Px = i1 * pxx,
      Py = i1 * pxy;
    vAx -= mA * Px;
    vAy -= mA * Py;
    wA -= iA * (i1 * s1 + i2);
    vBx += mB * Px;
    vBy += mB * Py;
    wB += iB * (i1 * s2 + i2);
  } else {
    const mass = k11 > 0 ? 1 / k11 : 0;
    const i1 = -ms * mass * (cd1 + b1) - is * rows[o + R.ILX]!;
    rows[o + R.ILX] = rows[o + R.ILX]! + i1;
    const Px = i1 * pxx,
      Py = i1 * pxy;
    vAx -= mA * Px;
    vAy -= mA * Py;
    wA -= iA * i1 * s1;
    vBx += mB * Px;
    vBy += mB * Py;
    wB += iB * i1 * s2;
  }
  f[R.F_VAX] = vAx;
  f[R.F_VAY] = vAy;
  f[R.F_WA] = wA;
  f[R.F_VBX] = vBx;
  f[R.F_VBY] = vBy;
  f[R.F_WB] = wB;
}

/**
 * Writes the soft-constraint coefficients of a spring of `hertz` (Hz, >= 0) and damping ratio `zeta`
 * (>= 0) integrated implicitly over `h` (s) at rows[o..o+2]: bias rate omega / (2 zeta + h omega) (1/s),
 * mass scale a / (1 + a) and impulse scale 1 / (1 + a), a = h omega (2 zeta + h omega) (Catto, "Soft
 * Constraints", GDC 2011; Box2D v3 b2MakeSoft). hertz 0 gives the rigid 0, 1, 0. Written so every
 * coefficient stays finite and in range at any hertz: a spring so soft that a rounds to 0 (a denormal
 * hertz) gives 0, 0, 1, no impulse at all; one so stiff that a overflows gives 1 / h, 1, 0.
 */
export function soft(rows: Float64Array, o: number, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    rows[o] = 0;
    rows[o + 1] = 1;
    rows[o + 2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz;
  const hw = h * omega;
  const a = hw * (2 * zeta + hw);
  if (!(a > 0)) {
    rows[o] = 0;
    rows[o + 1] = 0;
    rows[o + 2] = 1;
    return;
  }
  rows[o] = zeta === 0 ? 1 / h : 1 / (h + (2 * zeta) / omega);
  rows[o + 1] = 1 / (1 + 1 / a);
  rows[o + 2] = 1 / (1 + a);
}

/** Wraps an angle into [-pi, pi]. */
export function unwind(x: number): number {
  if (x > Math.PI) return x - 2 * Math.PI * Math.floor((x + Math.PI) / (2 * Math.PI));
  if (x < -Math.PI) return x + 2 * Math.PI * Math.floor((Math.PI - x) / (2 * Math.PI));
  return x;
}
