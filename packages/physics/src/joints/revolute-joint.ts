import { assertKnownKeys } from '../validation/validate.js';
import { JointFlag, JointType } from '../world/joint-store-2d.js';
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
import {
  F_IA,
  F_IB,
  F_INVH,
  F_REL,
  F_WA,
  F_WB,
  ILOW,
  IMOT,
  ISPR,
  IUP,
  KAX,
  LOW,
  MMAX,
  MSPD,
  ROW_PUSHED,
  SB,
  SI,
  SM,
  UP,
} from './layout-2d.js';
import { limitRow, solvePointBlock, unwind } from './rows-2d.js';

/**
 * The 2D revolute joint (a hinge, with an optional angle limit, motor and spring): its options and
 * addRevoluteJoint. Its rows are prepared, solved and finished with the other 2D joints'
 * (joints/prepare-2d.ts, solve-2d.ts, finish-2d.ts).
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
  const iA = f[F_IA]!,
    iB = f[F_IB]!;
  if (iA + iB !== 0) {
    const invH = f[F_INVH]!,
      relAngle = f[F_REL]!;
    let wA = f[F_WA]!,
      wB = f[F_WB]!;
    const kax = rows[o + KAX]!;
    if (flags & JointFlag.Spring) {
      const impulse = -rows[o + SM]! * kax * (wB - wA + rows[o + SB]! * relAngle) - rows[o + SI]! * rows[o + ISPR]!;
      rows[o + ISPR] = rows[o + ISPR]! + impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
    }
    if (flags & JointFlag.Motor) {
      const max = rows[o + MMAX]!;
      const old = rows[o + IMOT]!;
      let next = old - kax * (wB - wA - rows[o + MSPD]!);
      next = next < -max ? -max : next > max ? max : next;
      rows[o + IMOT] = next;
      wA -= iA * (next - old);
      wB += iB * (next - old);
    }
    if (flags & JointFlag.Limit) {
      const angle = unwind(relAngle);
      const lower = limitRow(rows, o, ILOW, angle - rows[o + LOW]!, kax, wB - wA, invH, useBias);
      wA -= iA * lower;
      wB += iB * lower;
      const upper = limitRow(rows, o, IUP, rows[o + UP]! - angle, kax, wA - wB, invH, useBias);
      wA += iA * upper;
      wB -= iB * upper;
    }
    f[F_WA] = wA;
    f[F_WB] = wB;
  }
  solvePointBlock(rows, o, f, useBias);
  return ROW_PUSHED;
}
