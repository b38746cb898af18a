import * as BS from '../solver/body-state-layout.js';
import { currentHandle } from '../world/handles.js';
import type { JointState } from '../world/joint-state-2d.js';
import { JointFlag, type JointStore, JointType } from '../world/joint-store-2d.js';
import { PIN_FLOATS, PIN_INTS, ROW_FLOATS, ROW_INTS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, checkDrive, checkEnds2D, checkLimits, makeJoint, storeDrive } from './joint-2d.js';
import { type JointBaseOptions, optionalPoint } from './joint-base.js';
import * as R from './layout-2d.js';
import {
  angularMass,
  applyImpulse,
  driveImpulse,
  type JointPass2D,
  type JointTypeRows2D,
  limitRow,
  motorImpulse,
  packPin,
  pointForce,
  solvePointBlocks,
  solvePointRow,
  unwind,
} from './rows-2d.js';

/**
 * The 2D revolute joint (a hinge, with an optional angle limit, motor and spring): its options,
 * addRevoluteJoint, its row's preparation, solve and reading (its warm start is rows-2d.ts
 * warmStartPoint), and the pins' passes (a
 * revolute joint with no spring, motor or limit, packed by its preparation: warm start, solve, impulses
 * back into the rows). joints/solver-2d.ts runs them.
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
  const keys = ['anchor', 'lowerAngle', 'upperAngle', 'motorSpeed', 'maxMotorTorque', 'hertz', 'dampingRatio'];
  const ends = checkEnds2D(where, world, options, keys);
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const limit = checkLimits(where, options.lowerAngle, options.upperAngle, 'lowerAngle', 'upperAngle', Math.PI);
  const drive = checkDrive(where, options.motorSpeed, options.maxMotorTorque, 'maxMotorTorque', options.hertz, options.dampingRatio);
  const j = makeJoint(world, JointType.Revolute, ends, p, p, options);
  storeDrive(world, j, limit, options.lowerAngle, options.upperAngle, drive);
  return currentHandle(world, j);
}

/**
 * Prepares revolute joint `j`'s row r (its masses at the start of the step in the frame `f`): the
 * effective mass of the relative rotation; a joint without spring, motor or limit becomes a pin (its
 * row's warm-start impulses already loaded).
 */
export function prepareRevoluteRow(js: JointState, _J: JointStore, _j: number, r: number, f: Float64Array): void {
  const rows = js.rows,
    ri = js.rowInts;
  const o = r * ROW_FLOATS,
    q = r * ROW_INTS;
  rows[o + R.KAX] = angularMass(f[R.F_IA]!, f[R.F_IB]!);
  if (((ri[q + R.TF]! >> 8) & (JointFlag.Spring | JointFlag.Motor | JointFlag.Limit)) !== 0) return;
  ri[q + R.TF] = R.PIN;
  packPin(rows, o, js.pins, js.pinInts, js.pinCount++, ri[q + R.IA]!, ri[q + R.IB]!, r);
}

/**
 * One pass of a revolute joint's rows (Box2D v3's b2SolveRevoluteJoint) on its frame: unless neither
 * body can turn, the angular spring, the motor (its impulse capped at the largest a substep) and the
 * angle limits; then the anchors' point-to-point block, soft while the pass uses bias. @returns ROW_PUSHED.
 */
export function solveRevoluteRow(p: JointPass2D, ia: number, ib: number, o: number, flags: number): number {
  const { sb, rows } = p;
  const oA = ia * BS.BS2_STRIDE,
    oB = ib * BS.BS2_STRIDE;
  const iA = sb[oA + BS.BS2_INV_INERTIA]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  if (iA + iB !== 0) {
    const relAngle = p.f[R.F_REL]!,
      kax = rows[o + R.KAX]!;
    let wA = sb[oA + BS.BS2_W]!,
      wB = sb[oB + BS.BS2_W]!;
    if (flags & JointFlag.Spring) {
      const impulse = -rows[o + R.SM]! * kax * (wB - wA + rows[o + R.SB]! * relAngle) - rows[o + R.SI]! * rows[o + R.ISPR]!;
      rows[o + R.ISPR] = rows[o + R.ISPR]! + impulse;
      wA -= iA * impulse;
      wB += iB * impulse;
    }
    if (flags & JointFlag.Motor) {
      const impulse = motorImpulse(rows, o, kax, wB - wA);
      wA -= iA * impulse;
      wB += iB * impulse;
    }
    if (flags & JointFlag.Limit) {
      // Lower: C = angle - lower >= 0, along wB - wA. Upper: C = upper - angle >= 0, along wA - wB.
      const angle = unwind(relAngle);
      const lower = limitRow(p, o, R.ILOW, angle - rows[o + R.LOW]!, kax, wB - wA);
      wA -= iA * lower;
      wB += iB * lower;
      const upper = limitRow(p, o, R.IUP, rows[o + R.UP]! - angle, kax, wA - wB);
      wA += iA * upper;
      wB -= iB * upper;
    }
    sb[oA + BS.BS2_W] = wA;
    sb[oB + BS.BS2_W] = wB;
  }
  solvePointRow(p, oA, oB, o, p.useBias);
  return R.ROW_PUSHED;
}

/** A revolute joint's reading after the step into out: its point force (N), the torque of its spring, motor and limits (N m), its anchors' separation (m). */
export function revoluteReading(p: JointPass2D, _ia: number, _ib: number, o: number, _flags: number, out: Float64Array): void {
  const { rows, f } = p;
  const dx = f[R.F_DX]!,
    dy = f[R.F_DY]!;
  out[0] = pointForce(p, o);
  out[1] = Math.abs(driveImpulse(rows, o)) * f[R.F_INVH]!;
  out[2] = Math.sqrt(dx * dx + dy * dy);
}

/**
 * The pins' warm start (once per substep, before the contacts'): each pin's accumulated impulse applied
 * again at its anchors as they have turned so far in the step.
 */
export function warmStartPins(world: PhysicsWorld): void {
  const js = world.joints;
  const sb = world.collision.bodyState,
    rot = js.rotation;
  const pf = js.pins,
    pint = js.pinInts;
  for (let l = 0, m = js.pinCount; l < m; l++) {
    const f = l * PIN_FLOATS,
      i = l * PIN_INTS;
    const Px = pf[f + R.PN_ILX]!,
      Py = pf[f + R.PN_ILY]!;
    // One comparison that always runs (|Px| + |Py| is 0 only when both are): the second half of
    // `Px === 0 && Py === 0` runs only in a world's first steps, which V8 compiles as a deoptimisation.
    if (Math.abs(Px) + Math.abs(Py) === 0) continue;
    const ia = pint[i + R.PN_IA]!,
      ib = pint[i + R.PN_IB]!;
    const cA = rot[ia * 3]!,
      sA = rot[ia * 3 + 1]!,
      cB = rot[ib * 3]!,
      sB = rot[ib * 3 + 1]!;
    const rAx = cA * pf[f + R.PN_RAX]! - sA * pf[f + R.PN_RAY]!,
      rAy = sA * pf[f + R.PN_RAX]! + cA * pf[f + R.PN_RAY]!;
    const rBx = cB * pf[f + R.PN_RBX]! - sB * pf[f + R.PN_RBY]!,
      rBy = sB * pf[f + R.PN_RBX]! + cB * pf[f + R.PN_RBY]!;
    applyImpulse(sb, ia * BS.BS2_STRIDE, ib * BS.BS2_STRIDE, Px, Py, rAx * Py - rAy * Px, rBx * Py - rBy * Px);
  }
}

/**
 * The pins' pass: each pin's point-to-point block (rows-2d.ts solvePointBlocks), soft while `useBias`
 * (Box2D's joint softness), exactly as the general loop solves a revolute joint's.
 */
export function solvePins(world: PhysicsWorld, useBias: boolean): void {
  const js = world.joints;
  if (js.pinCount === 0) return;
  solvePointBlocks(world.collision.bodyState, js.rotation, js.pins, js.pinInts, js.pinCount, useBias, js.softness);
}

/** The pins' accumulated impulses back into their rows, which keep them for the next step. */
export function finishPins(js: JointState): void {
  const rows = js.rows;
  const pf = js.pins,
    pint = js.pinInts;
  for (let l = 0, m = js.pinCount; l < m; l++) {
    const f = l * PIN_FLOATS,
      o = pint[l * PIN_INTS + R.PN_ROW]! * ROW_FLOATS;
    rows[o + R.ILX] = pf[f + R.PN_ILX]!;
    rows[o + R.ILY] = pf[f + R.PN_ILY]!;
  }
}

/** The 2D revolute joint's row functions (rows-2d.ts JointTypeRows2D). */
export const REVOLUTE_ROWS_2D: JointTypeRows2D = {
  prepare: prepareRevoluteRow,
  solve: solveRevoluteRow,
};
