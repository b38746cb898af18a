import { JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { type AxisJointKind, addAxisJoint, BASE_KEYS, type JointBaseOptions } from './joint-2d.js';

/**
 * The 2D wheel joint (a suspension spring along an axis, free rotation with an optional motor): its options
 * and addWheelJoint. Its rows are prepared, solved and finished with the other 2D joints'
 * (joints/prepare-2d.ts, solve-2d.ts, finish-2d.ts).
 */

/**
 * Options of `addWheelJoint`.
 * @category Joints and ropes
 */
export interface WheelJointOptions extends JointBaseOptions {
  /** Where the wheel is held, world point, m. Default B's (the wheel's) centre. */
  anchor?: ArrayLike<number>;
  /** Suspension direction in the world now (fixed in A), normalised here. Default (0, 1). */
  axis?: ArrayLike<number>;
  /** Suspension spring, Hz, >= 0 (0 = rigid axle). Default 4 Hz. Fixed stiffness, as the distance joint's `hertz`. */
  hertz?: number;
  /** Suspension damping ratio, >= 0. Default 0.7. */
  dampingRatio?: number;
  /** Limits of the suspension travel along the axis, m. Both or neither. */
  lower?: number;
  upper?: number;
  /** Motor target spin of the wheel relative to A, rad/s (counter-clockwise). Default 0. */
  motorSpeed?: number;
  /** Motor's largest torque, N m, >= 0; on when > 0. Default 0. */
  maxMotorTorque?: number;
}

/**
 * Adds a wheel joint: B's anchor stays on the line through A's anchor along `axis`, held by a
 * suspension spring; B spins freely or driven by a motor (a car's wheel on its chassis A). Box2D v3's
 * wheel joint.
 * @returns the joint entity. @throws TypeError | RangeError on bad bodies, options or values.
 * @category Joints and ropes
 */
export function addWheelJoint(world: PhysicsWorld, options: WheelJointOptions): number {
  return addAxisJoint(world, WHEEL, options);
}

/** What sets the wheel joint apart from the other joint along an axis (joints/joint-2d.ts addAxisJoint). */
const WHEEL: AxisJointKind = {
  where: 'addWheelJoint',
  type: JointType.Wheel,
  keys: [...BASE_KEYS, 'anchor', 'axis', 'hertz', 'dampingRatio', 'lower', 'upper', 'motorSpeed', 'maxMotorTorque'],
  maxName: 'maxMotorTorque',
  axis: [0, 1],
  hertz: 4,
  dampingRatio: 0.7,
};
