import { BS3_STRIDE, BS3_WX, BS3_WY, BS3_WZ } from '../solver/body-state-layout.js';
import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, ends, type Joint3DBaseOptions, limitAndMotor, make, point, storeLimitAndMotor, unit } from './joint-3d.js';
import {
  E,
  errorRotation,
  type JointPass3D,
  type JointRows3D,
  pointJointReading,
  preparePointBlock,
  solveAngularLock,
  solvePointRows,
  warmStartPointAndLock,
} from './rows-3d.js';
import { angularRow, applyAngular, ax, bx, qa, rot } from './rows-3d-math.js';
import { useJointType3D } from './solver-3d.js';
import { Joint3DFlag, Joint3DType, joints3DOf } from './store-3d.js';

/**
 * The 3D hinge joint (rotation about one axis, with an optional angle limit and motor): its options,
 * addHingeJoint3D, and its rows (HINGE_ROWS_3D), which joints/solver-3d.ts runs with the other 3D
 * joints'.
 */

/**
 * Options of `addHingeJoint3D`.
 * @category Joints and ropes
 */
export interface HingeJoint3DOptions extends Joint3DBaseOptions {
  /** A point on the hinge's axis (world, m). Default B's centre. */
  anchor?: ArrayLike<number>;
  /** The hinge axis (world, when made); need not be unit length. */
  axis: ArrayLike<number>;
  /** Angle limits, rad, about the axis from the pose when made (right-handed): lower <= 0 <= upper. Default none. */
  lower?: number;
  upper?: number;
  /** Motor: target relative angular speed about the axis, rad/s, and its largest torque, N m (>= 0). Default off. */
  motorSpeed?: number;
  maxMotorTorque?: number;
}

/**
 * Hinge: ball and socket plus two angular rows that keep B's axis along A's, so B turns relative to A
 * about the axis only; optional angle limits and a motor. @returns the joint's handle.
 * @throws TypeError | RangeError `addHingeJoint3D: <param> must be ...` as addBallJoint3D, on a zero
 *   axis, lower > 0 or upper < 0, only one limit, a motor speed without a torque or a negative torque.
 * @category Joints and ropes
 */
export function addHingeJoint3D(world: PhysicsWorld, options: HingeJoint3DOptions): number {
  const where = 'addHingeJoint3D';
  const e = ends(where, world, options, ['anchor', 'axis', 'lower', 'upper', 'motorSpeed', 'maxMotorTorque']);
  const p = options.anchor === undefined ? centre(world, e.b) : point(where, 'anchor', options.anchor);
  const axis = unit(where, 'axis', options.axis);
  const lm = limitAndMotor(where, options.lower, options.upper, options.motorSpeed, options.maxMotorTorque, 'maxMotorTorque');
  const j = make(world, where, Joint3DType.Hinge, e, options, p, p, axis);
  useJointType3D(Joint3DType.Hinge, HINGE_ROWS_3D);
  storeLimitAndMotor(joints3DOf(world, true), j, lm);
  return currentHandle(world, j);
}

/** A hinge's motor and angle limit about its axis (bx, from solveAngularLock), on the angle of E. */
function solveHingeAxial(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  const { s, sb, T, hs, useBias, bRate, ms, is } = p;
  const oa = BS3_STRIDE * a,
    ob = BS3_STRIDE * b;
  const ex = E[0]!,
    ey = E[1]!,
    ez = E[2]!,
    ew = E[3]!;
  const hx = bx[0]!,
    hy = bx[1]!,
    hz = bx[2]!;
  const angle = 2 * Math.atan2(ex * s.uax[j]! + ey * s.uay[j]! + ez * s.uaz[j]!, ew);
  if (flags & Joint3DFlag.Motor) {
    const maxL = s.maxMotorTorque[j]! * hs;
    const rel =
      (sb[ob + BS3_WX]! - sb[oa + BS3_WX]!) * hx + (sb[ob + BS3_WY]! - sb[oa + BS3_WY]!) * hy + (sb[ob + BS3_WZ]! - sb[oa + BS3_WZ]!) * hz;
    s.motor[j] = angularRow(sb, T, a, b, hx, hy, hz, rel, -s.motorSpeed[j]!, 1, 0, s.motor[j]!, -maxL, maxL);
  }
  if (flags & Joint3DFlag.Limit) {
    const lo = s.lower[j]!,
      hi = s.upper[j]!;
    const nearLower = angle - lo < hi - angle;
    const C = nearLower ? angle - lo : hi - angle,
      sg = nearLower ? 1 : -1;
    let bias = 0,
      m = 1,
      im = 0;
    if (C > 0) bias = C / hs;
    else if (useBias) {
      bias = bRate * C;
      m = ms;
      im = is;
    }
    // A warm-started impulse from the other limit is taken back first.
    if (sg * s.limit[j]! < 0) {
      const l = -s.limit[j]!;
      applyAngular(sb, T, a, b, l * hx, l * hy, l * hz);
      s.limit[j] = 0;
    }
    const rel =
      (sb[ob + BS3_WX]! - sb[oa + BS3_WX]!) * hx + (sb[ob + BS3_WY]! - sb[oa + BS3_WY]!) * hy + (sb[ob + BS3_WZ]! - sb[oa + BS3_WZ]!) * hz;
    const lam = angularRow(sb, T, a, b, sg * hx, sg * hy, sg * hz, sg * rel, bias, m, im, sg * s.limit[j]!, 0, Infinity);
    s.limit[j] = sg * lam;
  }
}

/** A hinge: the two angular rows across its axis, its motor and limit, then the point block. */
export function solveHingeRow3D(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  errorRotation(p, j);
  solveAngularLock(p, j, a, b, true);
  if (flags & (Joint3DFlag.Limit | Joint3DFlag.Motor)) solveHingeAxial(p, j, a, b, flags);
  preparePointBlock(p, a, b);
  solvePointRows(p, j, a, b);
}

/** A hinge's warm start: its point and angular-lock impulses, then its limit's and motor's about its axis (turned with A). */
export function warmStartHingeRow3D(p: JointPass3D, j: number, a: number, b: number): void {
  warmStartPointAndLock(p, j, a, b);
  const { s, sb, T } = p;
  const axial = s.limit[j]! + s.motor[j]!;
  if (axial !== 0) {
    rot(qa, s.uax[j]!, s.uay[j]!, s.uaz[j]!, ax);
    applyAngular(sb, T, a, b, axial * ax[0]!, axial * ax[1]!, axial * ax[2]!);
  }
}

/** The 3D hinge joint's rows (rows-3d.ts JointRows3D). */
export const HINGE_ROWS_3D: JointRows3D = { warmStart: warmStartHingeRow3D, solve: solveHingeRow3D, reading: pointJointReading };
