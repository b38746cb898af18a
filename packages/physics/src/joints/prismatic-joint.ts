import { JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { type AxisJointKind, addAxisJoint, BASE_KEYS, type JointBaseOptions } from './joint-2d.js';

/**
 * The 2D prismatic joint (a slider along an axis, with an optional limit, motor and spring): its options
 * and addPrismaticJoint. Its rows are prepared, solved and finished with the other 2D joints'
 * (joints/prepare-2d.ts, solve-2d.ts, finish-2d.ts).
 */

/**
 * Options of `addPrismaticJoint`.
 * @category Joints and ropes
 */
export interface PrismaticJointOptions extends JointBaseOptions {
  /** Anchor, world point, m (on both bodies). Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Slide direction in the world now (fixed in A afterwards), normalised here. Default (1, 0). */
  axis?: ArrayLike<number>;
  /** Limits of the translation along the axis from now, m, lower <= upper. Both or neither. */
  lower?: number;
  upper?: number;
  /** Motor target speed along the axis, m/s. Default 0. */
  motorSpeed?: number;
  /** Motor's largest force, N, >= 0; on when > 0. Default 0. */
  maxMotorForce?: number;
  /** Spring along the axis toward translation 0, Hz, >= 0. Default 0 (none). Fixed stiffness, as the distance joint's `hertz`. */
  hertz?: number;
  /** Its damping ratio, >= 0. Default 0. */
  dampingRatio?: number;
}

/**
 * Adds a prismatic joint: B slides along `axis` (fixed in A) and does not turn relative to A;
 * optional limits, motor and spring along the axis. Box2D v3's prismatic joint.
 * @returns the joint entity. @throws TypeError | RangeError as `addRevoluteJoint`, and on a zero axis.
 * @category Joints and ropes
 */
export function addPrismaticJoint(world: PhysicsWorld, options: PrismaticJointOptions): number {
  return addAxisJoint(world, PRISMATIC, options);
}

/** What sets the prismatic joint apart from the other joint along an axis (joints/joint-2d.ts addAxisJoint). */
const PRISMATIC: AxisJointKind = {
  where: 'addPrismaticJoint',
  type: JointType.Prismatic,
  keys: [...BASE_KEYS, 'anchor', 'axis', 'lower', 'upper', 'motorSpeed', 'maxMotorForce', 'hertz', 'dampingRatio'],
  maxName: 'maxMotorForce',
  axis: [1, 0],
  hertz: 0,
  dampingRatio: 0,
};
