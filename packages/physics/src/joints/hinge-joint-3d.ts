import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, ends, type Joint3DBaseOptions, limitAndMotor, make, point, storeLimitAndMotor, unit } from './joint-3d.js';
import { Joint3DType, joints3DOf } from './store-3d.js';

/**
 * The 3D hinge joint (rotation about one axis, with an optional angle limit and motor): its options and
 * addHingeJoint3D. Its rows are solved with the other 3D joints' (joints/solver-3d.ts).
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
  storeLimitAndMotor(joints3DOf(world, true), j, lm);
  return currentHandle(world, j);
}
