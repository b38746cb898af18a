import * as BS from '../solver/body-state-layout.js';
import { JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { type AxisJointKind, addAxisJoint } from './joint-2d.js';
import type { JointBaseOptions } from './joint-base.js';
import * as R from './layout-2d.js';
import { applyImpulse, type JointPass2D, type JointTypeRows2D, prepareAxisRow, solveAlongAxis } from './rows-2d.js';

/**
 * The 2D wheel joint (a suspension spring along an axis, free rotation with an optional motor): its
 * options, addWheelJoint, and its row's solve (its preparation, warm start and reading are the prismatic
 * joint's: rows-2d.ts prepareAxisRow, warmStartAxis, axisReading). joints/solver-2d.ts runs them.
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
  maxName: 'maxMotorTorque',
  axis: [0, 1],
  hertz: 4,
  dampingRatio: 0.7,
};

/**
 * One pass of a wheel joint's rows (Box2D v3's b2SolveWheelJoint) on its frame: the rotation motor
 * (unless neither body turns), the suspension spring and the translation limits along the axis, then
 * the row across it, soft while the pass uses bias. @returns ROW_PUSHED.
 */
export function solveWheelRow(p: JointPass2D, ia: number, ib: number, o: number, flags: number): number {
  const { sb, rows, f } = p;
  const oA = ia * BS.BS2_STRIDE,
    oB = ib * BS.BS2_STRIDE;
  const mA = sb[oA + BS.BS2_INV_MASS]!,
    iA = sb[oA + BS.BS2_INV_INERTIA]!,
    mB = sb[oB + BS.BS2_INV_MASS]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  solveAlongAxis(p, ia, ib, o, flags, true);
  const s1 = f[R.F_S1]!,
    s2 = f[R.F_S2]!;
  const ms = p.useBias ? rows[o + R.JM]! : 1,
    is = p.useBias ? rows[o + R.JI]! : 0;
  const k = mA + mB + iA * s1 * s1 + iB * s2 * s2;
  const mass = k > 0 ? 1 / k : 0;
  const i1 = -ms * mass * (f[R.F_CD]! + f[R.F_BIAS]!) - is * rows[o + R.ILX]!;
  rows[o + R.ILX] = rows[o + R.ILX]! + i1;
  // The impulse i1 across the axis (-axy, axx) on B, minus on A, and its angular impulses i1 s1 on A and i1 s2 on B.
  applyImpulse(sb, oA, oB, i1 * -f[R.F_AXY]!, i1 * f[R.F_AXX]!, i1 * s1, i1 * s2);
  return R.ROW_PUSHED;
}

/** The 2D wheel joint's row functions (rows-2d.ts JointTypeRows2D). */
export const WHEEL_ROWS_2D: JointTypeRows2D = {
  prepare: prepareAxisRow,
  solve: solveWheelRow,
};
