import type { PhysicsWorld } from '../world/options.js';
import { type AxisJoint3DKind, addAxisJoint3D, type Joint3DBaseOptions } from './joint-3d.js';
import * as R3 from './rows-3d.js';
import { applyLinear, bx, K, linearK, qa, restrictToPlane, rot, solve3, v3, x3 } from './rows-3d-math.js';
import { Joint3DFlag, type Joint3DStore, Joint3DType } from './store-3d.js';

/**
 * The 3D slider joint (translation along one axis, no rotation, with an optional limit and motor): its
 * options, addSliderJoint3D, and its rows (SLIDER_ROWS_3D), which joints/solver-3d.ts runs with the
 * other 3D joints'.
 */

/**
 * Options of `addSliderJoint3D`.
 * @category Joints and ropes
 */
export interface SliderJoint3DOptions extends Joint3DBaseOptions {
  /** A point on the slide line (world, m), fixed in both bodies when made. Default B's centre. */
  anchor?: ArrayLike<number>;
  /** The slide axis (world, when made; it turns with A); need not be unit length. */
  axis: ArrayLike<number>;
  /** Lower translation limit along the axis, m, from the pose when made, <= 0 (given with `upper`). Default none. */
  lower?: number;
  /** Upper translation limit along the axis, m, from the pose when made, >= 0 (given with `lower`). Default none. */
  upper?: number;
  /** Motor: target speed of B relative to A along the axis, m/s (given with `maxMotorForce`). Default off. */
  motorSpeed?: number;
  /** Motor: its largest force, N, >= 0. Default off. */
  maxMotorForce?: number;
}

/**
 * Slider (prismatic): B keeps A's orientation (three angular rows, as the fixed joint) and its anchor
 * stays on the line through A's anchor along the axis (two point rows perpendicular to it), so B only
 * slides along the axis; optional translation limits and a motor (Box2D v3's prismatic joint in 3D).
 * @returns the joint's handle.
 * @throws TypeError | RangeError `addSliderJoint3D: <param> must be ...` as addBallJoint3D, on a zero
 *   axis, lower > 0 or upper < 0, only one limit, a motor speed without a force or a negative force.
 * @category Joints and ropes
 */
export function addSliderJoint3D(world: PhysicsWorld, options: SliderJoint3DOptions): number {
  return addAxisJoint3D(world, SLIDER, options);
}

/**
 * A slider's point block restricted to the plane across A's axis, then along the axis (at the point
 * of A under B's anchor) its motor and translation limit.
 */
function solveSliderAxis(p: R3.JointPass3D, j: number, a: number, b: number, flags: number): void {
  const { s, sb, T, bRate, ms, is } = p;
  // Only the part perpendicular to the axis (A's, in the world) is held.
  rot(qa, s.uax[j]!, s.uay[j]!, s.uaz[j]!, bx);
  const hx = bx[0]!,
    hy = bx[1]!,
    hz = bx[2]!;
  const Cx = R3.C3[0]!,
    Cy = R3.C3[1]!,
    Cz = R3.C3[2]!;
  const t = Cx * hx + Cy * hy + Cz * hz,
    dv = v3[0]! * hx + v3[1]! * hy + v3[2]! * hz;
  restrictToPlane(hx, hy, hz);
  solve3(
    K,
    v3[0]! - dv * hx + bRate * (Cx - t * hx),
    v3[1]! - dv * hy + bRate * (Cy - t * hy),
    v3[2]! - dv * hz + bRate * (Cz - t * hz),
    x3,
  );
  let px = -ms * x3[0]! - is * s.lx[j]!,
    py = -ms * x3[1]! - is * s.ly[j]!,
    pz = -ms * x3[2]! - is * s.lz[j]!;
  const d = px * hx + py * hy + pz * hz;
  px -= d * hx;
  py -= d * hy;
  pz -= d * hz;
  s.lx[j] = s.lx[j]! + px;
  s.ly[j] = s.ly[j]! + py;
  s.lz[j] = s.lz[j]! + pz;
  applyLinear(sb, T, a, b, px, py, pz);
  if (flags & (Joint3DFlag.Limit | Joint3DFlag.Motor)) {
    // Axial rows act at the point of A under B's anchor.
    R3.sliderAnchor();
    const k = linearK(sb, T, a, b, hx, hy, hz);
    if (k > 0 && flags & Joint3DFlag.Motor) R3.axisMotor3D(p, j, a, b, true, k);
    if (k > 0 && flags & Joint3DFlag.Limit) R3.axisLimit3D(p, j, a, b, true, k, t);
  }
}

/** A slider: the three angular rows, the point block across its axis, then its motor and limit along it. */
export function solveSliderRow3D(p: R3.JointPass3D, j: number, a: number, b: number, flags: number): void {
  R3.errorRotation(p, j);
  R3.solveAngularLock(p, j, a, b, false);
  R3.preparePointBlock(p, a, b);
  solveSliderAxis(p, j, a, b, flags);
}

/**
 * A slider's warm start: its point and angular-lock impulses, then its limit's and motor's along its
 * axis (turned with A), at the point of A under B's anchor.
 */
export function warmStartSliderRow3D(p: R3.JointPass3D, j: number, a: number, b: number): void {
  R3.warmStartAxis3D(p, j, a, b, true);
}

/**
 * A slider's reading: the force of its point impulse plus its limit's and motor's along the axis, and
 * the torque of its angular lock.
 */
export function sliderReading3D(s: Joint3DStore, j: number, hs: number, out: Float64Array): void {
  out[0] = (Math.hypot(s.lx[j]!, s.ly[j]!, s.lz[j]!) + (Math.abs(s.limit[j]!) + Math.abs(s.motor[j]!))) / hs;
  out[1] = Math.hypot(s.wx[j]!, s.wy[j]!, s.wz[j]!) / hs;
}

/** The 3D slider joint's rows (rows-3d.ts JointRows3D). */
export const SLIDER_ROWS_3D: R3.JointRows3D = { warmStart: warmStartSliderRow3D, solve: solveSliderRow3D, reading: sliderReading3D };

/** What sets the slider apart from the other 3D joint along an axis (joint-3d.ts addAxisJoint3D). */
const SLIDER: AxisJoint3DKind = { where: 'addSliderJoint3D', type: Joint3DType.Slider, rows: SLIDER_ROWS_3D, maxName: 'maxMotorForce' };
