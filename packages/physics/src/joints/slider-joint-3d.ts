import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { centre, ends, type Joint3DBaseOptions, limitAndMotor, make, point, storeLimitAndMotor, unit } from './joint-3d.js';
import { Joint3DType, joints3DOf } from './store-3d.js';

/**
 * The 3D slider joint (translation along one axis, no rotation, with an optional limit and motor): its
 * options and addSliderJoint3D. Its rows are solved with the other 3D joints' (joints/solver-3d.ts).
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
  const where = 'addSliderJoint3D';
  const e = ends(where, world, options, ['anchor', 'axis', 'lower', 'upper', 'motorSpeed', 'maxMotorForce']);
  const p = options.anchor === undefined ? centre(world, e.b) : point(where, 'anchor', options.anchor);
  const axis = unit(where, 'axis', options.axis);
  const lm = limitAndMotor(where, options.lower, options.upper, options.motorSpeed, options.maxMotorForce, 'maxMotorForce');
  const j = make(world, where, Joint3DType.Slider, e, options, p, p, axis);
  storeLimitAndMotor(joints3DOf(world, true), j, lm);
  return currentHandle(world, j);
}
