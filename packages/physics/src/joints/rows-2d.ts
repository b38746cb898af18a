import * as BS from '../solver/body-state-layout.js';
import type { JointState } from '../world/joint-state-2d.js';
import { JointFlag, type JointStore } from '../world/joint-store-2d.js';
import { PIN_FLOATS, PIN_INTS, ROW_FLOATS } from '../world/joint-strides-2d.js';
import * as R from './layout-2d.js';
import { fixedSpring, springImpulse } from './softness.js';

/**
 * The row code the 2D joint types share, working in place on the packed solver bodies (bodies A and B
 * at body-state offsets oA and oB) and on the frame of the row (layout-2d.ts F_*): the frame's pose,
 * impulses applied to both bodies, the point-to-point block (revolute, weld, pins), angular rows, the
 * one-sided limit row, the springs of fixed stiffness, and the rows along and across an axis
 * (prismatic, wheel); the warm starts of the point and axis joints and the axis joints' reading. Each
 * type's own rows are in its file; joints/solver-2d.ts runs them.
 */

/**
 * What the row functions of a pass read (joints/solver-2d.ts fills it): the packed solver bodies
 * (solver/body-state-layout.ts BS2_*), each solver body's rotation since the start of the step (cos,
 * sin, angle), the rows, the frame of the row being worked on, and whether the rigid rows push out
 * their position error as soft constraints (else they only remove relative velocity: the relax pass).
 */
export interface JointPass2D {
  sb: Float64Array;
  rot: Float64Array;
  rows: Float64Array;
  f: Float64Array;
  useBias: boolean;
}

/**
 * A 2D joint type's row functions, which its file exports and joints/solver-2d.ts runs for each of its
 * rows (row offset `o`, bodies of solver indices ia and ib, its pose in the frame): `prepare` at the
 * start of the step (row r of joint j, the start-of-step pose, masses and substep in the frame `f`) and
 * `solve` once a pass (@returns a ROW_* outcome). The stages call the rest by the joint's shape or
 * type, each on locals, so that the engine inlines their few calls: the warm start once a substep
 * (warmStartPoint, warmStartAxis, distance-joint.ts warmStartDistanceRow) and the reading after the
 * step (force N, torque N m, position error m and strain into out[0..3], left 0 where the type has
 * none: each type's `*Reading`, axisReading for the prismatic and wheel joints).
 */
export interface JointTypeRows2D {
  prepare(js: JointState, J: JointStore, j: number, r: number, f: Float64Array): void;
  solve(p: JointPass2D, ia: number, ib: number, o: number, flags: number): number;
}

/** Fills the frame with row `o`'s anchors now (F_RAX..F_RBY): turned with their bodies (solver indices ia, ib) since the start of the step. */
export function anchorsFrame(p: JointPass2D, o: number, ia: number, ib: number): void {
  const { rot, rows, f } = p;
  const cA = rot[ia * 3]!,
    sA = rot[ia * 3 + 1]!,
    cB = rot[ib * 3]!,
    sB = rot[ib * 3 + 1]!;
  f[R.F_RAX] = cA * rows[o + R.RAX]! - sA * rows[o + R.RAY]!;
  f[R.F_RAY] = sA * rows[o + R.RAX]! + cA * rows[o + R.RAY]!;
  f[R.F_RBX] = cB * rows[o + R.RBX]! - sB * rows[o + R.RBY]!;
  f[R.F_RBY] = sB * rows[o + R.RBX]! + cB * rows[o + R.RBY]!;
}

/** Fills the frame with row `o`'s anchor separation B - A now (F_DX, F_DY): the start-of-step offset, the bodies' displacements and the frame's anchors. */
export function separationFrame(p: JointPass2D, o: number, ia: number, ib: number): void {
  const { sb, rows, f } = p;
  const oA = ia * BS.BS2_STRIDE,
    oB = ib * BS.BS2_STRIDE;
  f[R.F_DX] = sb[oB + BS.BS2_DX]! - sb[oA + BS.BS2_DX]! + rows[o + R.DCX]! + f[R.F_RBX]! - f[R.F_RAX]!;
  f[R.F_DY] = sb[oB + BS.BS2_DY]! - sb[oA + BS.BS2_DY]! + rows[o + R.DCY]! + f[R.F_RBY]! - f[R.F_RAY]!;
}

/** Applies a linear impulse P (N s) and angular impulses lA, lB (N m s): -P and -lA to A, +P and +lB to B. */
export function applyImpulse(sb: Float64Array, oA: number, oB: number, px: number, py: number, lA: number, lB: number): void {
  const mA = sb[oA + BS.BS2_INV_MASS]!,
    iA = sb[oA + BS.BS2_INV_INERTIA]!,
    mB = sb[oB + BS.BS2_INV_MASS]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  sb[oA + BS.BS2_VX] = sb[oA + BS.BS2_VX]! - mA * px;
  sb[oA + BS.BS2_VY] = sb[oA + BS.BS2_VY]! - mA * py;
  sb[oA + BS.BS2_W] = sb[oA + BS.BS2_W]! - iA * lA;
  sb[oB + BS.BS2_VX] = sb[oB + BS.BS2_VX]! + mB * px;
  sb[oB + BS.BS2_VY] = sb[oB + BS.BS2_VY]! + mB * py;
  sb[oB + BS.BS2_W] = sb[oB + BS.BS2_W]! + iB * lB;
}

/**
 * The pins' pass (revolute joints without spring, motor or limit, packed by their preparation: a
 * lean loop over their own 8 numbers, not the row's): each pin's anchors turned with their bodies
 * (`rot`, as poseFrame) coincide, as one 2 x 2 system (as solvePointRow). While `useBias` they push out
 * the anchors' separation as soft constraints with the rigid joint softness `sf` (bias rate 1/s, mass
 * scale, impulse scale: Catto, "Soft Constraints", GDC 2011), else they only remove relative velocity.
 */
export function solvePointBlocks(
  sb: Float64Array,
  rot: Float64Array,
  pf: Float64Array,
  pint: Int32Array,
  count: number,
  useBias: boolean,
  sf: Float64Array,
): void {
  const jb = useBias ? sf[0]! : 0,
    jm = useBias ? sf[1]! : 1,
    ji = useBias ? sf[2]! : 0;
  for (let l = 0; l < count; l++) {
    const f = l * PIN_FLOATS,
      i = l * PIN_INTS;
    const ia = pint[i + R.PN_IA]!,
      ib = pint[i + R.PN_IB]!,
      oA = ia * BS.BS2_STRIDE,
      oB = ib * BS.BS2_STRIDE;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * pf[f + R.PN_RAX]! - sA * pf[f + R.PN_RAY]!,
      rAy = sA * pf[f + R.PN_RAX]! + cA * pf[f + R.PN_RAY]!;
    const rBx = cB * pf[f + R.PN_RBX]! - sB * pf[f + R.PN_RBY]!,
      rBy = sB * pf[f + R.PN_RBX]! + cB * pf[f + R.PN_RBY]!;
    let bx = 0,
      by = 0;
    if (useBias) {
      bx = jb * (sb[oB + BS.BS2_DX]! - sb[oA + BS.BS2_DX]! + pf[f + R.PN_DCX]! + rBx - rAx);
      by = jb * (sb[oB + BS.BS2_DY]! - sb[oA + BS.BS2_DY]! + pf[f + R.PN_DCY]! + rBy - rAy);
    }
    const mA = sb[oA + BS.BS2_INV_MASS]!,
      iA = sb[oA + BS.BS2_INV_INERTIA]!,
      mB = sb[oB + BS.BS2_INV_MASS]!,
      iB = sb[oB + BS.BS2_INV_INERTIA]!;
    const vAx = sb[oA + BS.BS2_VX]!,
      vAy = sb[oA + BS.BS2_VY]!,
      wA = sb[oA + BS.BS2_W]!,
      vBx = sb[oB + BS.BS2_VX]!,
      vBy = sb[oB + BS.BS2_VY]!,
      wB = sb[oB + BS.BS2_W]!;
    const cdx = vBx - wB * rBy - vAx + wA * rAy,
      cdy = vBy + wB * rBx - vAy - wA * rAx;
    const k11 = mA + mB + rAy * rAy * iA + rBy * rBy * iB;
    const k12 = -rAy * rAx * iA - rBy * rBx * iB;
    const k22 = mA + mB + rAx * rAx * iA + rBx * rBx * iB;
    let det = k11 * k22 - k12 * k12;
    if (det !== 0) det = 1 / det;
    const ex = cdx + bx,
      ey = cdy + by;
    const sx = det * (k22 * ex - k12 * ey),
      sy = det * (k11 * ey - k12 * ex);
    const ix = -jm * sx - ji * pf[f + R.PN_ILX]!,
      iy = -jm * sy - ji * pf[f + R.PN_ILY]!;
    pf[f + R.PN_ILX] = pf[f + R.PN_ILX]! + ix;
    pf[f + R.PN_ILY] = pf[f + R.PN_ILY]! + iy;
    sb[oA + BS.BS2_VX] = vAx - mA * ix;
    sb[oA + BS.BS2_VY] = vAy - mA * iy;
    sb[oA + BS.BS2_W] = wA - iA * (rAx * iy - rAy * ix);
    sb[oA + BS.BS2_PUSHED] = 1;
    sb[oB + BS.BS2_VX] = vBx + mB * ix;
    sb[oB + BS.BS2_VY] = vBy + mB * iy;
    sb[oB + BS.BS2_W] = wB + iB * (rBx * iy - rBy * ix);
    sb[oB + BS.BS2_PUSHED] = 1;
  }
}

/** Writes row `o`'s start-of-step anchors and centres and its point impulse as pin `n` of pf, pint (layout-2d.ts PN_*), of solver bodies ia, ib and row r. */
export function packPin(
  rows: Float64Array,
  o: number,
  pf: Float64Array,
  pint: Int32Array,
  n: number,
  ia: number,
  ib: number,
  r: number,
): void {
  const p = n * PIN_FLOATS,
    i = n * PIN_INTS;
  pf[p + R.PN_RAX] = rows[o + R.RAX]!;
  pf[p + R.PN_RAY] = rows[o + R.RAY]!;
  pf[p + R.PN_RBX] = rows[o + R.RBX]!;
  pf[p + R.PN_RBY] = rows[o + R.RBY]!;
  pf[p + R.PN_DCX] = rows[o + R.DCX]!;
  pf[p + R.PN_DCY] = rows[o + R.DCY]!;
  pf[p + R.PN_ILX] = rows[o + R.ILX]!;
  pf[p + R.PN_ILY] = rows[o + R.ILY]!;
  pint[i + R.PN_IA] = ia;
  pint[i + R.PN_IB] = ib;
  pint[i + R.PN_ROW] = r;
}

/**
 * The point-to-point block of general row `o` (revolute, weld) on its frame: the anchors coincide, as
 * one 2 x 2 system; `soft`, it pushes out their separation with the row's rigid softness (JB, JM, JI),
 * else it only removes their relative velocity.
 */
export function solvePointRow(p: JointPass2D, oA: number, oB: number, o: number, soft: boolean): void {
  const { sb, rows, f } = p;
  const mA = sb[oA + BS.BS2_INV_MASS]!,
    iA = sb[oA + BS.BS2_INV_INERTIA]!,
    mB = sb[oB + BS.BS2_INV_MASS]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const vAx = sb[oA + BS.BS2_VX]!,
    vAy = sb[oA + BS.BS2_VY]!,
    wA = sb[oA + BS.BS2_W]!,
    vBx = sb[oB + BS.BS2_VX]!,
    vBy = sb[oB + BS.BS2_VY]!,
    wB = sb[oB + BS.BS2_W]!;
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
  applyImpulse(sb, oA, oB, ix, iy, rAx * iy - rAy * ix, rBx * iy - rBy * ix);
}

/**
 * A motor (a revolute or wheel joint's about its pin, a prismatic joint's along its axis): the change
 * of its accumulated impulse (N m s or N s) driving the relative speed `spin` (wB - wA, rad/s; or along
 * the axis, m/s) toward the row's motor speed with effective mass `k`, the impulse capped at the
 * largest a substep (MMAX).
 */
export function motorImpulse(rows: Float64Array, o: number, k: number, spin: number): number {
  const max = rows[o + R.MMAX]!;
  const old = rows[o + R.IMOT]!;
  let next = old - k * (spin - rows[o + R.MSPD]!);
  next = next < -max ? -max : next > max ? max : next;
  rows[o + R.IMOT] = next;
  return next - old;
}

/**
 * One pass of a one-sided limit row (its accumulated impulse at `slot` stays >= 0), with position
 * error C (>= 0 inside the limit), velocity `cdot` along the row and effective mass `k`: speculative
 * while C > 0 (bias C / h_s), soft with the row's JB, JM, JI while the pass uses bias, else rigid
 * (Catto, "Soft Constraints", GDC 2011; Box2D v3's joint limits).
 * @returns the change of the accumulated impulse.
 */
export function limitRow(p: JointPass2D, o: number, slot: number, C: number, k: number, cdot: number): number {
  const rows = p.rows;
  let bias = 0,
    ms = 1,
    is = 0;
  if (C > 0) bias = C * p.f[R.F_INVH]!;
  else if (p.useBias) {
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

/** The effective mass of the relative rotation, 1 / (iA + iB), kg m^2 (0 when neither body turns). */
export function angularMass(iA: number, iB: number): number {
  return iA + iB > 0 ? 1 / (iA + iB) : 0;
}

/** Row `o`'s accumulated impulse of its spring, motor and limits (revolute about its pin, N m s; prismatic along its axis, N s). */
export function driveImpulse(rows: Float64Array, o: number): number {
  return rows[o + R.ISPR]! + rows[o + R.IMOT]! + rows[o + R.ILOW]! - rows[o + R.IUP]!;
}

/** Row `o`'s accumulated impulse of its spring and limits (along a distance joint's line or a wheel joint's axis), N s. */
export function springLimitImpulse(rows: Float64Array, o: number): number {
  return rows[o + R.ISPR]! + rows[o + R.ILOW]! - rows[o + R.IUP]!;
}

/**
 * A point joint's warm start (revolute, weld, mouse) on row `o` of solver bodies ia, ib: its linear
 * impulse (ILX, ILY) at the anchors as turned so far in the step, and its angular one about them (N m
 * s): a revolute joint's spring, motor and limits (`revolute`, driveImpulse), else the angular row's.
 */
export function warmStartPoint(p: JointPass2D, ia: number, ib: number, o: number, revolute: boolean): void {
  const { sb, rows, f } = p;
  const axial = revolute ? driveImpulse(rows, o) : rows[o + R.IANG]!;
  anchorsFrame(p, o, ia, ib);
  const rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const px = rows[o + R.ILX]!,
    py = rows[o + R.ILY]!;
  applyImpulse(sb, ia * BS.BS2_STRIDE, ib * BS.BS2_STRIDE, px, py, rAx * py - rAy * px + axial, rBx * py - rBy * px + axial);
}

/** The force (N) of a point joint's linear impulse over the substep (the frame's F_INVH). */
export function pointForce(p: JointPass2D, o: number): number {
  const rows = p.rows;
  return Math.sqrt(rows[o + R.ILX]! * rows[o + R.ILX]! + rows[o + R.ILY]! * rows[o + R.ILY]!) * p.f[R.F_INVH]!;
}

/**
 * The spring of fixed stiffness (softness.ts fixedSpring) of joint `j`'s row `o` (distance, prismatic,
 * wheel), when it has one: its reference mass mA + mB + (iA |rA|^2 + iB |rB|^2) / 2 from the frame's
 * masses and the anchors' levers in the bodies' frames; `hs` the substep, s.
 */
export function springRow(rows: Float64Array, o: number, J: JointStore, j: number, f: Float64Array): void {
  const hertz = J.hertz[j]!;
  if (!(hertz > 0)) return;
  const lax = J.localAx[j]!,
    lay = J.localAy[j]!,
    lbx = J.localBx[j]!,
    lby = J.localBy[j]!;
  const kRef = f[R.F_MA]! + f[R.F_MB]! + 0.5 * (f[R.F_IA]! * (lax * lax + lay * lay) + f[R.F_IB]! * (lbx * lbx + lby * lby));
  fixedSpring(rows, o + R.SB, hertz, J.dampingRatio[j]!, f[R.F_HS]!, kRef);
}

// The rows along and across an axis (prismatic and wheel joints: Box2D v3's prismatic_joint.c and
// wheel_joint.c). Along the axis the impulse lambda acts as lambda axis on B (minus on A) and as the
// angular impulses lambda a1 on A and lambda a2 on B; across it, along the perpendicular (-axy, axx),
// with s1 and s2.

/**
 * Prepares a joint along an axis' row r (prismatic, wheel; its anchors, pose and masses at the start of
 * the step in the frame `f`): the effective masses along the axis and of the relative rotation, and
 * the spring of fixed stiffness along the axis (`hs` the substep, s).
 */
export function prepareAxisRow(js: JointState, J: JointStore, j: number, r: number, f: Float64Array): void {
  const rows = js.rows,
    o = r * ROW_FLOATS;
  const mA = f[R.F_MA]!,
    iA = f[R.F_IA]!,
    mB = f[R.F_MB]!,
    iB = f[R.F_IB]!;
  springRow(rows, o, J, j, f);
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!,
    axx = rows[o + R.AXX]!,
    axy = rows[o + R.AXY]!;
  const a1 = (dx + f[R.F_RAX]!) * axy - (dy + f[R.F_RAY]!) * axx,
    a2 = f[R.F_RBX]! * axy - f[R.F_RBY]! * axx;
  const k = mA + mB + iA * a1 * a1 + iB * a2 * a2;
  rows[o + R.KAX] = k > 0 ? 1 / k : 0;
  rows[o + R.KMOT] = angularMass(iA, iB);
}

/** The axis of row `o` turned with A, B's translation along it and the angular Jacobians along and across it, into the frame (F_AXX..F_S2). */
export function axisFrame(p: JointPass2D, o: number, ia: number): void {
  const { rot, rows, f } = p;
  const cA = rot[ia * 3]!,
    sA = rot[ia * 3 + 1]!;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!,
    rAx = f[R.F_RAX]!,
    rAy = f[R.F_RAY]!,
    rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  const axx = cA * rows[o + R.AXX]! - sA * rows[o + R.AXY]!,
    axy = sA * rows[o + R.AXX]! + cA * rows[o + R.AXY]!;
  f[R.F_AXX] = axx;
  f[R.F_AXY] = axy;
  f[R.F_TRANS] = axx * dx + axy * dy;
  f[R.F_A1] = (dx + rAx) * axy - (dy + rAy) * axx;
  f[R.F_A2] = rBx * axy - rBy * axx;
  f[R.F_S1] = (dx + rAx) * axx - (dy + rAy) * -axy;
  f[R.F_S2] = rBx * axx - rBy * -axy;
}

/**
 * The rows along a joint's axis (prismatic, wheel) on its frame: a wheel's rotation motor (`wheel`;
 * unless neither body turns), the spring of fixed stiffness toward translation 0 (softness.ts
 * fixedSpring), a prismatic joint's motor along the axis, the translation limits (one-sided rows:
 * limitRow); each capped motor impulse at the largest a substep. Fills the frame's axis (axisFrame),
 * and for the row across it its velocity error after these rows (F_CD) and its bias while the pass
 * uses bias (F_BIAS: the rigid softness's rate times B's offset across the axis).
 */
export function solveAlongAxis(p: JointPass2D, ia: number, ib: number, o: number, flags: number, wheel: boolean): void {
  const { sb, rows, f } = p;
  const oA = ia * BS.BS2_STRIDE,
    oB = ib * BS.BS2_STRIDE;
  axisFrame(p, o, ia);
  const mA = sb[oA + BS.BS2_INV_MASS]!,
    iA = sb[oA + BS.BS2_INV_INERTIA]!,
    mB = sb[oB + BS.BS2_INV_MASS]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  const axx = f[R.F_AXX]!,
    axy = f[R.F_AXY]!,
    translation = f[R.F_TRANS]!,
    a1 = f[R.F_A1]!,
    a2 = f[R.F_A2]!;
  let vAx = sb[oA + BS.BS2_VX]!,
    vAy = sb[oA + BS.BS2_VY]!,
    wA = sb[oA + BS.BS2_W]!,
    vBx = sb[oB + BS.BS2_VX]!,
    vBy = sb[oB + BS.BS2_VY]!,
    wB = sb[oB + BS.BS2_W]!;
  const kax = rows[o + R.KAX]!;
  const kA = iA * a1,
    kB = iB * a2;
  if (wheel && flags & JointFlag.Motor && iA + iB !== 0) {
    const impulse = motorImpulse(rows, o, rows[o + R.KMOT]!, wB - wA);
    wA -= iA * impulse;
    wB += iB * impulse;
  }
  // Each row's impulse along the axis, and the relative velocity along it.
  let impulse = 0;
  for (let row = 0; row < 4; row++) {
    const cdot = axx * (vBx - vAx) + axy * (vBy - vAy) + a2 * wB - a1 * wA;
    if (row === 0) {
      if (!(flags & JointFlag.Spring)) continue;
      impulse = springImpulse(cdot, translation, mA + mB + kA * a1 + kB * a2, rows[o + R.ISPR]!, rows[o + R.SB]!, rows[o + R.SM]!);
      rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
    } else if (row === 1) {
      if (wheel || !(flags & JointFlag.Motor)) continue;
      impulse = motorImpulse(rows, o, kax, cdot);
    } else {
      if (!(flags & JointFlag.Limit)) continue;
      // Lower: C = translation - lower >= 0. Upper (signs flipped): C = upper - translation >= 0.
      const sign = row === 2 ? 1 : -1;
      const C = row === 2 ? translation - rows[o + R.LOW]! : rows[o + R.UP]! - translation;
      impulse = sign * limitRow(p, o, row === 2 ? R.ILOW : R.IUP, C, kax, sign * cdot);
    }
    vAx -= mA * impulse * axx;
    vAy -= mA * impulse * axy;
    wA -= kA * impulse;
    vBx += mB * impulse * axx;
    vBy += mB * impulse * axy;
    wB += kB * impulse;
  }
  sb[oA + BS.BS2_VX] = vAx;
  sb[oA + BS.BS2_VY] = vAy;
  sb[oA + BS.BS2_W] = wA;
  sb[oB + BS.BS2_VX] = vBx;
  sb[oB + BS.BS2_VY] = vBy;
  sb[oB + BS.BS2_W] = wB;
  // Across the axis: the perpendicular (-axy, axx).
  const pxx = -axy,
    pxy = axx;
  f[R.F_CD] = pxx * (vBx - vAx) + pxy * (vBy - vAy) + f[R.F_S2]! * wB - f[R.F_S1]! * wA;
  f[R.F_BIAS] = p.useBias ? rows[o + R.JB]! * (pxx * f[R.F_DX]! + pxy * f[R.F_DY]!) : 0;
}

/**
 * A joint along an axis' warm start (prismatic, wheel) on row `o` of solver bodies ia, ib, at the
 * anchors as turned and moved so far in the step: the impulse along its axis turned with A (N s: a
 * prismatic joint's spring, motor and limits, a `wheel`'s spring and limits), the row's across it (ILX)
 * and the angular one (N m s: a prismatic joint's angular row, a wheel's motor).
 */
export function warmStartAxis(p: JointPass2D, ia: number, ib: number, o: number, wheel: boolean): void {
  const { sb, rows, f } = p;
  const axial = wheel ? springLimitImpulse(rows, o) : driveImpulse(rows, o),
    angular = rows[o + (wheel ? R.IMOT : R.IANG)]!;
  anchorsFrame(p, o, ia, ib);
  separationFrame(p, o, ia, ib);
  axisFrame(p, o, ia);
  const axx = f[R.F_AXX]!,
    axy = f[R.F_AXY]!;
  const perp = rows[o + R.ILX]!;
  const lA = axial * f[R.F_A1]! + perp * f[R.F_S1]! + angular,
    lB = axial * f[R.F_A2]! + perp * f[R.F_S2]! + angular;
  applyImpulse(sb, ia * BS.BS2_STRIDE, ib * BS.BS2_STRIDE, axial * axx + perp * -axy, axial * axy + perp * axx, lA, lB);
}

/**
 * A joint along an axis' reading into out (force N, torque N m, error m): the force of its impulses
 * along the axis (a prismatic joint's spring, limits and motor, a `wheel`'s spring and limits) and
 * across it, the torque of its angular row (a wheel's motor), B's offset across the axis turned with A.
 */
export function axisReading(p: JointPass2D, ia: number, o: number, out: Float64Array, wheel: boolean): void {
  const { rot, rows, f } = p;
  const invH = f[R.F_INVH]!,
    cA = rot[ia * 3]!,
    sA = rot[ia * 3 + 1]!;
  const axx = cA * rows[o + R.AXX]! - sA * rows[o + R.AXY]!,
    axy = sA * rows[o + R.AXX]! + cA * rows[o + R.AXY]!;
  const axial = springLimitImpulse(rows, o) + (wheel ? 0 : rows[o + R.IMOT]!);
  out[0] = Math.hypot(axial, rows[o + R.ILX]!) * invH;
  out[1] = Math.abs(rows[o + (wheel ? R.IMOT : R.IANG)]!) * invH;
  out[2] = Math.abs(-axy * f[R.F_DX]! + axx * f[R.F_DY]!);
}

/** Wraps an angle into [-pi, pi]. */
export function unwind(x: number): number {
  if (x > Math.PI) return x - 2 * Math.PI * Math.floor((x + Math.PI) / (2 * Math.PI));
  if (x < -Math.PI) return x + 2 * Math.PI * Math.floor((Math.PI - x) / (2 * Math.PI));
  return x;
}
