import { hasComponent } from 'bitecs';
import * as BS from '../solver/body-state-layout.js';
import { assertNonNegative, assertOptions, assertPositive, assertVector, describe, optionOr } from '../validation/validate.js';
import { currentHandle } from '../world/handles.js';
import type { JointState } from '../world/joint-state-2d.js';
import { JointFlag, type JointStore, JointType } from '../world/joint-store-2d.js';
import { ROW_FLOATS } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, makeJoint, requireJoint, wakeJoint } from './joint-2d.js';
import { checkEnds, optionalPoint } from './joint-base.js';
import * as R from './layout-2d.js';
import { type JointPass2D, type JointTypeRows2D, pointForce } from './rows-2d.js';
import { soft } from './softness.js';

/**
 * The 2D mouse joint (a soft, force-capped spring pulling a body's point toward a target, for dragging):
 * its options, addMouseJoint, setMouseTarget, and its row's preparation, solve and reading (its warm
 * start is rows-2d.ts warmStartPoint).
 * joints/solver-2d.ts runs them.
 */

/**
 * Options of `addMouseJoint`.
 * @category Joints and ropes
 */
export interface MouseJointOptions {
  /** The body dragged. */
  b: number;
  /** The point of B grabbed, world, m. Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Where it is pulled, world, m. Default the anchor. Move it with `setMouseTarget`. */
  target?: ArrayLike<number>;
  /** Stiffness of the pull, Hz, > 0. Default 5 Hz. */
  hertz?: number;
  /** Its damping ratio, >= 0. Default 0.7. */
  dampingRatio?: number;
  /** Largest pulling force, N, > 0. Default 1000 times B's mass in kg (Box2D's samples), N. */
  maxForce?: number;
  /** Force above which the joint breaks, N. Default Infinity. */
  breakForce?: number;
}

/**
 * Adds a mouse joint: a soft spring of at most `maxForce` pulling the grabbed point of B toward a
 * target that the game moves with the pointer (`setMouseTarget`); B's spin is damped softly. Box2D
 * v3's mouse joint. Remove it with `removeJoint` on release.
 * @returns the joint entity. @throws TypeError | RangeError on a bad body, options or values.
 * @category Joints and ropes
 */
export function addMouseJoint(world: PhysicsWorld, options: MouseJointOptions): number {
  const where = 'addMouseJoint';
  assertOptions(where, options, ['b', 'anchor', 'target', 'hertz', 'dampingRatio', 'maxForce', 'breakForce']);
  const ends = checkEnds(
    where,
    world,
    { b: options.b, ...(options.breakForce !== undefined ? { breakForce: options.breakForce } : {}) },
    2,
  );
  const C = world.components;
  if (hasComponent(world, ends.b, C.Static) || hasComponent(world, ends.b, C.Kinematic) || !(C.Mass.inv[ends.b]! > 0)) {
    throw new RangeError(`${where}: b must be a dynamic body (a static or kinematic body cannot be dragged), got ${describe(options.b)}`);
  }
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const target = optionalPoint(where, 'target', options.target, p);
  const hertz = optionOr(where, 'hertz', options.hertz, 5, assertPositive);
  const zeta = optionOr(where, 'dampingRatio', options.dampingRatio, 0.7, assertNonNegative);
  const maxForce = optionOr(where, 'maxForce', options.maxForce, 1000 * world.components.Mass.value[ends.b]!, assertPositive);
  const j = makeJoint(world, JointType.Mouse, ends, target, p, { b: ends.b, breakForce: options.breakForce });
  const J = world.components.Joint;
  J.hertz[j] = hertz;
  J.dampingRatio[j] = zeta;
  J.maxForce[j] = maxForce;
  J.flags[j] = JointFlag.Spring;
  return currentHandle(world, j);
}

/**
 * Moves a mouse joint's target, world point, m.
 * @throws RangeError if `joint` is not a live mouse joint; TypeError | RangeError on a bad point.
 * @category Joints and ropes
 */
export function setMouseTarget(world: PhysicsWorld, joint: number, target: ArrayLike<number>): void {
  const j = requireJoint('setMouseTarget', world, joint, [JointType.Mouse]);
  assertVector('setMouseTarget', 'target', target, 2);
  const J = world.components.Joint;
  J.localAx[j] = target[0]!;
  J.localAy[j] = target[1]!;
  wakeJoint(world, j);
}

/**
 * Prepares mouse joint `j`'s row r (B's masses at the start of the step in the frame `f`): B's
 * rotational mass, the largest impulse a substep of `hs` s, and the pull's softness.
 */
export function prepareMouseRow(js: JointState, J: JointStore, j: number, r: number, f: Float64Array): void {
  const hs = f[R.F_HS]!;
  const rows = js.rows,
    o = r * ROW_FLOATS;
  const iB = f[R.F_IB]!;
  rows[o + R.KAX] = iB > 0 ? 1 / iB : 0;
  rows[o + R.FMAX] = J.maxForce[j]! * hs;
  soft(rows, o + R.AB, J.hertz[j]!, J.dampingRatio[j]!, hs);
}

/**
 * One pass of a mouse joint's rows (Box2D v3's b2SolveMouseJoint) on its frame: B's spin damped
 * softly, then its anchor pulled toward the target by a soft point row whose accumulated impulse is
 * capped at the largest a substep (maxForce). @returns ROW_PUSHED.
 */
export function solveMouseRow(p: JointPass2D, _ia: number, ib: number, o: number, _flags: number): number {
  const { sb, rows, f } = p;
  const oB = ib * BS.BS2_STRIDE;
  const mB = sb[oB + BS.BS2_INV_MASS]!,
    iB = sb[oB + BS.BS2_INV_INERTIA]!;
  const rBx = f[R.F_RBX]!,
    rBy = f[R.F_RBY]!;
  let vBx = sb[oB + BS.BS2_VX]!,
    vBy = sb[oB + BS.BS2_VY]!,
    wB = sb[oB + BS.BS2_W]!;
  // Damp B's spin softly, then pull its anchor toward the target with at most maxForce.
  const kax = rows[o + R.KAX]!;
  {
    const impulse = -rows[o + R.AM]! * kax * wB - rows[o + R.AI]! * rows[o + R.IANG]!;
    rows[o + R.IANG] = rows[o + R.IANG]! + impulse;
    wB += iB * impulse;
  }
  const cdx = vBx - wB * rBy,
    cdy = vBy + wB * rBx;
  const bx = rows[o + R.SB]! * f[R.F_DX]!,
    by = rows[o + R.SB]! * f[R.F_DY]!,
    ms = rows[o + R.SM]!,
    is = rows[o + R.SI]!;
  const k11 = mB + rBy * rBy * iB,
    k12 = -rBy * rBx * iB,
    k22 = mB + rBx * rBx * iB;
  let det = k11 * k22 - k12 * k12;
  if (det !== 0) det = 1 / det;
  const ex = cdx + bx,
    ey = cdy + by;
  const sx = det * (k22 * ex - k12 * ey),
    sy = det * (k11 * ey - k12 * ex);
  const oldX = rows[o + R.ILX]!,
    oldY = rows[o + R.ILY]!;
  let nx = oldX - ms * sx - is * oldX,
    ny = oldY - ms * sy - is * oldY;
  const max = rows[o + R.FMAX]!;
  const mag2 = nx * nx + ny * ny;
  if (mag2 > max * max) {
    const s = max / Math.sqrt(mag2);
    nx *= s;
    ny *= s;
  }
  rows[o + R.ILX] = nx;
  rows[o + R.ILY] = ny;
  const ix = nx - oldX,
    iy = ny - oldY;
  vBx += mB * ix;
  vBy += mB * iy;
  wB += iB * (rBx * iy - rBy * ix);
  sb[oB + BS.BS2_VX] = vBx;
  sb[oB + BS.BS2_VY] = vBy;
  sb[oB + BS.BS2_W] = wB;
  return R.ROW_PUSHED;
}

/** A mouse joint's reading after the step into out: its pull's force (N) and its spin damping's torque (N m). */
export function mouseReading(p: JointPass2D, _ia: number, _ib: number, o: number, _flags: number, out: Float64Array): void {
  out[0] = pointForce(p, o);
  out[1] = Math.abs(p.rows[o + R.IANG]!) * p.f[R.F_INVH]!;
}

/** The 2D mouse joint's row functions (rows-2d.ts JointTypeRows2D). */
export const MOUSE_ROWS_2D: JointTypeRows2D = {
  prepare: prepareMouseRow,
  solve: solveMouseRow,
};
