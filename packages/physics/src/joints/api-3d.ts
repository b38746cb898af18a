import { assertFinite, assertNonNegative } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';
import { requireJoint3D, wakeJoint3D } from './joint-3d.js';
import { assertBreakLimit } from './joint-base.js';
import { Joint3DFlag, Joint3DType, joints3DOf, removeJoint3DUnchecked } from './store-3d.js';

/**
 * Calls on the 3D joints of every type: setJoint3DBreak, setJoint3DLimits, setJoint3DMotor, removeJoint3D
 * and joint3DBreaks. Each joint type's options and add call are in a file of its own (ball-joint-3d.ts,
 * hinge-joint-3d.ts, fixed-joint-3d.ts, distance-joint-3d.ts, slider-joint-3d.ts), on the shared checks of
 * joint-3d.ts.
 */

/**
 * Sets the force (N) and torque (N m) past which a 3D joint of any kind breaks (it is removed after the
 * step and listed in `joint3DBreaks`). The force is the point rows' (or a distance joint's rows along
 * its line, a slider's limit and motor included), the torque the angular rows' (a hinge's limit and
 * motor and the cone included); a distance joint has no torque. Checked after each step's substeps, as
 * impulse / substep time.
 * @param breakForce > 0, Infinity for never.
 * @param breakTorque > 0, Infinity for never; omitted keeps the joint's.
 * @throws RangeError `setJoint3DBreak: joint must be ...` on a removed entity or one that is not a 3D
 *   joint; TypeError | RangeError `setJoint3DBreak: <param> must be ...` naming the parameter and value
 *   (NaN, <= 0, not a number). A throwing call changes nothing.
 * @category Joints and ropes
 */
export function setJoint3DBreak(world: PhysicsWorld, joint: number, breakForce: number, breakTorque?: number): void {
  const where = 'setJoint3DBreak';
  const { s, j } = requireJoint3D(where, world, joint);
  assertBreakLimit(where, 'breakForce', breakForce, 'never');
  if (breakTorque !== undefined) assertBreakLimit(where, 'breakTorque', breakTorque, 'never');
  s.breakForce[j] = breakForce;
  if (breakTorque !== undefined) s.breakTorque[j] = breakTorque;
}

/**
 * Sets (or with `lower` null removes) a hinge's angle limits (rad, about its axis from the pose when
 * made, right-handed; within [-pi, pi]) or a slider's translation limits (m, along its axis from the
 * pose when made): lower <= upper. Unlike at creation the pose need not lie between them: a joint
 * outside is brought back at the joints' soft rate. The limit's warm-start impulse starts again from
 * zero; the motor is kept; the bodies wake.
 * @throws RangeError `setJoint3DLimits: joint must be ...` on a removed entity or a joint that is not a
 *   3D hinge or slider; TypeError | RangeError `setJoint3DLimits: <param> must be ...` naming the
 *   parameter and value (upper missing, not finite, lower > upper, a hinge limit outside [-pi, pi]).
 *   A throwing call changes nothing.
 * @category Joints and ropes
 */
export function setJoint3DLimits(world: PhysicsWorld, joint: number, lower: number | null, upper?: number): void {
  const where = 'setJoint3DLimits';
  const { s, j } = requireJoint3D(where, world, joint, [Joint3DType.Hinge, Joint3DType.Slider]);
  if (lower === null) {
    s.flags[j] = s.flags[j]! & ~Joint3DFlag.Limit;
    s.limit[j] = 0;
    wakeJoint3D(world, s, j);
    return;
  }
  assertFinite(where, 'lower', lower);
  if (upper === undefined) throw new RangeError(`${where}: upper must be given with lower, got undefined`);
  assertFinite(where, 'upper', upper);
  if (!(lower <= upper)) throw new RangeError(`${where}: lower must be <= upper (${upper}), got ${lower}`);
  if (s.type[j] === Joint3DType.Hinge) {
    if (!(lower >= -Math.PI)) throw new RangeError(`${where}: lower must be >= -pi for a hinge, got ${lower}`);
    if (!(upper <= Math.PI)) throw new RangeError(`${where}: upper must be <= pi for a hinge, got ${upper}`);
  }
  s.flags[j] = s.flags[j]! | Joint3DFlag.Limit;
  s.lower[j] = lower;
  s.upper[j] = upper;
  s.limit[j] = 0;
  wakeJoint3D(world, s, j);
}

/**
 * Sets a hinge's or slider's motor: the target speed of B relative to A about (hinge, rad/s) or along
 * (slider, m/s) the axis, reached with at most `maxForce` (hinge: torque, N m; slider: force, N);
 * `maxForce` 0 turns the motor off (its impulse is dropped). Limits are kept; the bodies wake.
 * @param speed rad/s or m/s, finite.
 * @param maxForce N m or N, finite and >= 0.
 * @throws RangeError `setJoint3DMotor: joint must be ...` on a removed entity or a joint that is not a
 *   3D hinge or slider; TypeError | RangeError `setJoint3DMotor: <param> must be ...` naming the
 *   parameter and value. A throwing call changes nothing.
 * @category Joints and ropes
 */
export function setJoint3DMotor(world: PhysicsWorld, joint: number, speed: number, maxForce: number): void {
  const where = 'setJoint3DMotor';
  const { s, j } = requireJoint3D(where, world, joint, [Joint3DType.Hinge, Joint3DType.Slider]);
  assertFinite(where, 'speed', speed);
  assertNonNegative(where, 'maxForce', maxForce);
  s.motorSpeed[j] = speed;
  s.maxMotorTorque[j] = maxForce;
  if (maxForce > 0) s.flags[j] = s.flags[j]! | Joint3DFlag.Motor;
  else {
    s.flags[j] = s.flags[j]! & ~Joint3DFlag.Motor;
    s.motor[j] = 0;
  }
  wakeJoint3D(world, s, j);
}

/**
 * Removes a 3D joint and wakes its bodies. @throws RangeError on a removed entity or one that is not a 3D joint.
 * @category Joints and ropes
 */
export function removeJoint3D(world: PhysicsWorld, joint: number): void {
  const { s, j } = requireJoint3D('removeJoint3D', world, joint);
  removeJoint3DUnchecked(world, s, j);
}

/**
 * The 3D joints broken in the last step, as [joint, a, b, step] (handles; a 0: the world; the step count
 * when it broke, world.steps - 1 after that step). Empty when none broke in the last step: a list left
 * from an earlier step (the solver clears it only when it runs) is cleared here.
 * @category Joints and ropes
 */
export function joint3DBreaks(world: PhysicsWorld): number[][] {
  const s = joints3DOf(world);
  if (s === undefined) return [];
  if (s.breaks.length > 0 && s.breaks[0]![3] !== world.steps - 1) s.breaks.length = 0;
  return s.breaks;
}
