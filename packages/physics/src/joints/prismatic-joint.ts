import * as BS from '../solver/body-state-layout.js';
import { JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { type AxisJointKind, addAxisJoint } from './joint-2d.js';
import type { JointBaseOptions } from './joint-base.js';
import * as R from './layout-2d.js';
import { applyImpulse, type JointPass2D, type JointTypeRows2D, prepareAxisRow, solveAlongAxis } from './rows-2d.js';

/**
 * The 2D prismatic joint (a slider along an axis, with an optional limit, motor and spring): its
 * options, addPrismaticJoint, and its row's solve (its preparation, warm start and reading are the
 * wheel joint's: rows-2d.ts prepareAxisRow, warmStartAxis, axisReading). joints/solver-2d.ts runs them.
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
  maxName: 'maxMotorForce',
  axis: [1, 0],
  hertz: 0,
  dampingRatio: 0,
};

/**
 * One pass of a prismatic joint's rows (Box2D v3's b2SolvePrismaticJoint) on its frame: along the axis
 * the spring, the motor (its impulse capped at the largest a substep) and the translation limits; then
 * across it the perpendicular row and the relative angle as one 2 x 2 block, soft while the pass uses
 * bias. @returns ROW_PUSHED.
 */
export function solvePrismaticRow(p: JointPass2D, ia: number, ib: number, o: number, flags: number): number {
  const { sb, rows, f } = p;
  const oA = ia * BS.BS2_STRIDE,
    oB = ib * BS.BS2_STRIDE;
  solveAlongAxis(p, ia, ib, o, flags, false);
  const mA = sb[oA + BS.BS2_INV_MASS]!,
    iA = sb[oA + BS.BS2_INV_INERTIA]!,
    mB = sb[oB + BS.BS2_INV_MASS]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  const s1 = f[R.F_S1]!,
    s2 = f[R.F_S2]!;
  let ms = 1,
    is = 0,
    b2 = 0;
  if (p.useBias) {
    ms = rows[o + R.JM]!;
    is = rows[o + R.JI]!;
    b2 = rows[o + R.JB]! * f[R.F_REL]!;
  }
  // Across the axis and the relative angle as one 2 x 2 block.
  const k11 = mA + mB + iA * s1 * s1 + iB * s2 * s2;
  const k12 = iA * s1 + iB * s2;
  let k22 = iA + iB;
  if (k22 === 0) k22 = 1;
  let det = k11 * k22 - k12 * k12;
  if (det !== 0) det = 1 / det;
  const e1 = f[R.F_CD]! + f[R.F_BIAS]!,
    e2 = sb[oB + BS.BS2_W]! - sb[oA + BS.BS2_W]! + b2;
  const x1 = det * (k22 * e1 - k12 * e2),
    x2 = det * (k11 * e2 - k12 * e1);
  const i1 = -ms * x1 - is * rows[o + R.ILX]!,
    i2 = -ms * x2 - is * rows[o + R.IANG]!;
  rows[o + R.ILX] = rows[o + R.ILX]! + i1;
  rows[o + R.IANG] = rows[o + R.IANG]! + i2;
  applyImpulse(sb, oA, oB, i1 * -f[R.F_AXY]!, i1 * f[R.F_AXX]!, i1 * s1 + i2, i1 * s2 + i2);
  return R.ROW_PUSHED;
}

/** The 2D prismatic joint's row functions (rows-2d.ts JointTypeRows2D). */
export const PRISMATIC_ROWS_2D: JointTypeRows2D = {
  prepare: prepareAxisRow,
  solve: solvePrismaticRow,
};
