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
  const where = 'addWheelJoint';
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchor', 'axis', 'hertz', 'dampingRatio', 'lower', 'upper', 'motorSpeed', 'maxMotorTorque'],
    ['a'],
  );
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const axis = unitAxis(where, options.axis, [0, 1]);
  const limit = checkLimits(where, options.lower, options.upper, 'lower', 'upper', Infinity);
  const drive = checkDrive(
    where,
    options.motorSpeed,
    options.maxMotorTorque,
    'maxMotorTorque',
    options.hertz,
    options.dampingRatio,
    4,
    0.7,
  );
  const j = makeJoint(world, JointType.Wheel, ends, p, p, options);
  setAxis(world, j, ends.a, axis);
  storeDrive(world, j, limit, options.lower, options.upper, drive);
  return handle(world, j);
}
