import { assertKnownKeys } from '../validation/validate.js';
import { JointType } from '../world/joint-store-2d.js';
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
  setAxis,
  storeDrive,
  unitAxis,
} from './joint-2d.js';

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
  const where = 'addPrismaticJoint';
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchor', 'axis', 'lower', 'upper', 'motorSpeed', 'maxMotorForce', 'hertz', 'dampingRatio'],
    ['a'],
  );
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const axis = unitAxis(where, options.axis, [1, 0]);
  const limit = checkLimits(where, options.lower, options.upper, 'lower', 'upper', Infinity);
  const drive = checkDrive(where, options.motorSpeed, options.maxMotorForce, 'maxMotorForce', options.hertz, options.dampingRatio);
  const j = makeJoint(world, JointType.Prismatic, ends, p, p, options);
  setAxis(world, j, ends.a, axis);
  storeDrive(world, j, limit, options.lower, options.upper, drive);
  return handle(world, j);
}
