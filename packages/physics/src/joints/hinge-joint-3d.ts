import type { PhysicsWorld } from '../world/options.js';
import { type AxisJoint3DKind, addAxisJoint3D, type Joint3DBaseOptions } from './joint-3d.js';
import * as R3 from './rows-3d.js';
import { Joint3DFlag, Joint3DType } from './store-3d.js';

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
  return addAxisJoint3D(world, HINGE, options);
}

/** A hinge: the two angular rows across its axis, its motor and angle limit about it, then the point block. */
export function solveHingeRow3D(p: R3.JointPass3D, j: number, a: number, b: number, flags: number): void {
  R3.errorRotation(p, j);
  R3.solveAngularLock(p, j, a, b, true);
  if (flags & (Joint3DFlag.Limit | Joint3DFlag.Motor)) {
    // About the axis (world, left in bx by the lock), on the angle of the error rotation E.
    const s = p.s;
    const angle = 2 * Math.atan2(R3.E[0]! * s.uax[j]! + R3.E[1]! * s.uay[j]! + R3.E[2]! * s.uaz[j]!, R3.E[3]!);
    if (flags & Joint3DFlag.Motor) R3.axisMotor3D(p, j, a, b, false, 0);
    if (flags & Joint3DFlag.Limit) R3.axisLimit3D(p, j, a, b, false, 0, angle);
  }
  R3.preparePointBlock(p, a, b);
  R3.solvePointRows(p, j, a, b);
}

/** A hinge's warm start: its point and angular-lock impulses, then its limit's and motor's about its axis (turned with A). */
export function warmStartHingeRow3D(p: R3.JointPass3D, j: number, a: number, b: number): void {
  R3.warmStartAxis3D(p, j, a, b, false);
}

/** The 3D hinge joint's rows (rows-3d.ts JointRows3D). */
export const HINGE_ROWS_3D: R3.JointRows3D = { warmStart: warmStartHingeRow3D, solve: solveHingeRow3D, reading: R3.pointJointReading };

/** What sets the hinge apart from the other 3D joint along an axis (joint-3d.ts addAxisJoint3D). */
const HINGE: AxisJoint3DKind = { where: 'addHingeJoint3D', type: Joint3DType.Hinge, rows: HINGE_ROWS_3D, maxName: 'maxMotorTorque' };
