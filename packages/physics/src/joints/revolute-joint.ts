import * as BS from '../solver/body-state-layout.js';
import { assertKnownKeys } from '../validation/validate.js';
import type { JointState } from '../world/joint-state-2d.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
import { PIN_FLOATS, PIN_INTS, ROW_FLOATS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import {
  BASE_KEYS,
  centre,
  checkDrive,
  checkEnds,
  checkLimits,
  handle,
  type JointBaseOptions,
  makeJoint,
  optionalPoint,
  storeDrive,
} from './joint-2d.js';
import * as R from './layout-2d.js';
import { limitRow, solvePointBlock, unwind } from './rows-2d.js';

/**
 * The 2D revolute joint (a hinge, with an optional angle limit, motor and spring): its options,
 * addRevoluteJoint, its row solve, and the pins' passes (a revolute joint with no spring, motor or
 * limit, packed by joints/prepare-2d.ts: warm start, solve, impulses back into the rows). Its general
 * rows are prepared and finished with the other 2D joints' (joints/prepare-2d.ts, finish-2d.ts) and
 * solved in their loop (joints/solve-2d.ts).
 */

/**
 * Options of `addRevoluteJoint`.
 * @category Joints and ropes
 */
export interface RevoluteJointOptions extends JointBaseOptions {
  /** The pin, world point, m. Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Lower and upper limit of the relative angle (B minus A, from now), rad, in [-pi, pi], lower <= upper. Both or neither. */
  lowerAngle?: number;
  upperAngle?: number;
  /** Motor target speed of B relative to A, rad/s, counter-clockwise. Default 0. */
  motorSpeed?: number;
  /** Motor's largest torque, N m, >= 0; the motor is on when > 0. Default 0 (off). */
  maxMotorTorque?: number;
  /** Angular spring toward the angle at creation, Hz, >= 0 (0 = none). Default 0. */
  hertz?: number;
  /** Damping ratio of the angular spring, >= 0. Default 0. */
  dampingRatio?: number;
}

/**
 * Adds a revolute joint (a pin): B turns about `anchor` relative to A, optionally within angle limits,
 * driven by a motor of at most `maxMotorTorque` toward `motorSpeed`, or held by an angular spring.
 * Box2D v3's revolute joint.
 * @returns the joint entity.
 * @throws TypeError | RangeError on a missing or removed body, a == b, a 3D world, unknown options,
 *   only one limit, lowerAngle > upperAngle or outside [-pi, pi], negative maxMotorTorque, hertz or
 *   damping ratio, non-finite values, or a full world.
 * @category Joints and ropes
 */
export function addRevoluteJoint(world: PhysicsWorld, options: RevoluteJointOptions): number {
  const where = 'addRevoluteJoint';
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchor', 'lowerAngle', 'upperAngle', 'motorSpeed', 'maxMotorTorque', 'hertz', 'dampingRatio'],
    ['a'],
  );
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const limit = checkLimits(where, options.lowerAngle, options.upperAngle, 'lowerAngle', 'upperAngle', Math.PI);
  const drive = checkDrive(where, options.motorSpeed, options.maxMotorTorque, 'maxMotorTorque', options.hertz, options.dampingRatio);
  const j = makeJoint(world, JointType.Revolute, ends, p, p, options);
  storeDrive(world, j, limit, options.lowerAngle, options.upperAngle, drive);
  return handle(world, j);
}

/**
 * One pass of a revolute joint's rows (Box2D v3's b2SolveRevoluteJoint) on the frame `f` of
 * layout-2d.ts: unless neither body can turn, the angular spring, the motor (its impulse capped at
 * the largest a substep) and the angle limits; then the anchors' point-to-point block, soft while
 * `useBias`. @returns ROW_PUSHED.
 */
export function solveRevoluteRow(rows: Float64Array, o: number, flags: number, useBias: boolean, f: Float64Array): number {
  const iA = f[R.F_IA]!,
    iB = f[R.F_IB]!;
  if (iA + iB !== 0) {
    const invH = f[R.F_INVH]!,
      relAngle = f[R.F_REL]!;
    let wA = f[R.F_WA]!,
      wB = f[R.F_WB]!;
    const kax = rows[o + R.KAX]!;
    if (flags & JointFlag.Spring) {
      const impulse = -rows[o + R.SM]! * kax * (wB - wA + rows[o + R.SB]! * relAngle) - rows[o + R.SI]! * rows[o + R.ISPR]!;
      rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
    }
    if (flags & JointFlag.Motor) {
      const max = rows[o + R.MMAX]!;
      const old = rows[o + R.IMOT]!;
      let next = old - kax * (wB - wA - rows[o + R.MSPD]!);
      next = next < -max ? -max : next > max ? max : next;
      rows[o + R.IMOT] = next;
      wA -= iA * (next - old);
      wB += iB * (next - old);
    }
    if (flags & JointFlag.Limit) {
      const angle = unwind(relAngle);
      const lower = limitRow(rows, o, R.ILOW, angle - rows[o + R.LOW]!, kax, wB - wA, invH, useBias);
      wA -= iA * lower;
      wB += iB * lower;
      const upper = limitRow(rows, o, R.IUP, rows[o + R.UP]! - angle, kax, wA - wB, invH, useBias);
      wA += iA * upper;
      wB -= iB * upper;
    }
    f[R.F_WA] = wA;
    f[R.F_WB] = wB;
  }
  solvePointBlock(rows, o, f, useBias);
  return R.ROW_PUSHED;
}

/**
 * The pins' warm start (once per substep, before the contacts'): each pin's accumulated impulse applied
 * again at its anchors as they have turned so far in the step.
 */
export function warmStartPins(world: PhysicsWorld): void {
  const js = world.joints;
  const sb = world.collision.bodyState,
    rot = js.rotation;
  const pf = js.pins,
    pint = js.pinInts;
  for (let l = 0, m = js.pinCount; l < m; l++) {
    const f = l * PIN_FLOATS,
      i = l * PIN_INTS;
    const Px = pf[f + 6]!,
      Py = pf[f + 7]!;
    // One comparison that always runs (|Px| + |Py| is 0 only when both are): the second half of
    // `Px === 0 && Py === 0` runs only in a world's first steps, which V8 compiles as a deoptimisation.
    if (Math.abs(Px) + Math.abs(Py) === 0) continue;
    const ia = pint[i]!,
      ib = pint[i + 1]!,
      oA = ia * BS.BS2_STRIDE,
      oB = ib * BS.BS2_STRIDE;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * pf[f]! - sA * pf[f + 1]!,
      rAy = sA * pf[f]! + cA * pf[f + 1]!;
    const rBx = cB * pf[f + 2]! - sB * pf[f + 3]!,
      rBy = sB * pf[f + 2]! + cB * pf[f + 3]!;
    const mA = sb[oA + BS.BS2_INV_MASS]!,
      iA = sb[oA + BS.BS2_INV_INERTIA]!,
      mB = sb[oB + BS.BS2_INV_MASS]!,
      iB = sb[oB + BS.BS2_INV_INERTIA]!;
    sb[oA + BS.BS2_VX] = sb[oA + BS.BS2_VX]! - mA * Px;
    sb[oA + BS.BS2_VY] = sb[oA + BS.BS2_VY]! - mA * Py;
    sb[oA + BS.BS2_W] = sb[oA + BS.BS2_W]! - iA * (rAx * Py - rAy * Px);
    sb[oB + BS.BS2_VX] = sb[oB + BS.BS2_VX]! + mB * Px;
    sb[oB + BS.BS2_VY] = sb[oB + BS.BS2_VY]! + mB * Py;
    sb[oB + BS.BS2_W] = sb[oB + BS.BS2_W]! + iB * (rBx * Py - rBy * Px);
  }
}

/**
 * The pins' pass: the revolute joint's point-to-point block (2 x 2 effective mass from the current
 * anchors), soft while `useBias` (Box2D's joint softness), exactly as the general loop solves it.
 */
export function solvePins(world: PhysicsWorld, useBias: boolean): void {
  const js = world.joints;
  const m = js.pinCount;
  if (m === 0) return;
  const sb = world.collision.bodyState,
    rot = js.rotation,
    pf = js.pins,
    pint = js.pinInts;
  const jb = useBias ? js.softness[0]! : 0,
    jm = useBias ? js.softness[1]! : 1,
    ji = useBias ? js.softness[2]! : 0;
  for (let l = 0; l < m; l++) {
    const f = l * PIN_FLOATS,
      i = l * PIN_INTS;
    const ia = pint[i]!,
      ib = pint[i + 1]!,
      oA = ia * BS.BS2_STRIDE,
      oB = ib * BS.BS2_STRIDE;
    const mA = sb[oA + BS.BS2_INV_MASS]!,
      iA = sb[oA + BS.BS2_INV_INERTIA]!,
      mB = sb[oB + BS.BS2_INV_MASS]!,
      iB = sb[oB + BS.BS2_INV_INERTIA]!;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * pf[f]! - sA * pf[f + 1]!,
      rAy = sA * pf[f]! + cA * pf[f + 1]!;
    const rBx = cB * pf[f + 2]! - sB * pf[f + 3]!,
      rBy = sB * pf[f + 2]! + cB * pf[f + 3]!;
    let vAx = sb[oA + BS.BS2_VX]!,
      vAy = sb[oA + BS.BS2_VY]!,
      wA = sb[oA + BS.BS2_W]!,
      vBx = sb[oB + BS.BS2_VX]!,
      vBy = sb[oB + BS.BS2_VY]!,
      wB = sb[oB + BS.BS2_W]!;
    const cdx = vBx - wB * rBy - vAx + wA * rAy,
      cdy = vBy + wB * rBx - vAy - wA * rAx;
    let bx = 0,
      by = 0;
    if (useBias) {
      bx = jb * (sb[oB + BS.BS2_DX]! - sb[oA + BS.BS2_DX]! + pf[f + 4]! + rBx - rAx);
      by = jb * (sb[oB + BS.BS2_DY]! - sb[oA + BS.BS2_DY]! + pf[f + 5]! + rBy - rAy);
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
    const ix = -jm * sx - ji * pf[f + 6]!,
      iy = -jm * sy - ji * pf[f + 7]!;
    pf[f + 6] = pf[f + 6]! + ix;
    pf[f + 7] = pf[f + 7]! + iy;
    vAx -= mA * ix;
    vAy -= mA * iy;
    wA -= iA * (rAx * iy - rAy * ix);
    vBx += mB * ix;
    vBy += mB * iy;
    wB += iB * (rBx * iy - rBy * ix);
    sb[oA + BS.BS2_VX] = vAx;
    sb[oA + BS.BS2_VY] = vAy;
    sb[oA + BS.BS2_W] = wA;
    sb[oA + BS.BS2_PUSHED] = 1;
    sb[oB + BS.BS2_VX] = vBx;
    sb[oB + BS.BS2_VY] = vBy;
    sb[oB + BS.BS2_W] = wB;
    sb[oB + BS.BS2_PUSHED] = 1;
  }
}

/** The pins' accumulated impulses back into their rows, which keep them for the next step. */
export function finishPins(js: JointState): void {
  const rows = js.rows;
  const pf = js.pins,
    pint = js.pinInts;
  for (let l = 0, m = js.pinCount; l < m; l++) {
    const f = l * PIN_FLOATS,
      o = pint[l * PIN_INTS + 2]! * ROW_FLOATS;
    rows[o + R.ILX] = pf[f + 6]!;
    rows[o + R.ILY] = pf[f + 7]!;
  }
}
