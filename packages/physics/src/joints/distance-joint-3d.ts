import { assertNonNegative, assertPositive } from '../validation/validate.js';
import { currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import type { DistanceJointOptions } from './distance-joint.js';
import { centre, make, requireJoint3D, wakeJoint3D } from './joint-3d.js';
import { checkDistance, checkEnds, lengthLimits } from './joint-base.js';
import { type JointPass3D, type JointRows3D, limitSoft, limitSoftness } from './rows-3d.js';
import { anchorSpeed, applyLinear, linearK, pa, pb, ra, rb, referenceK, row3D } from './rows-3d-math.js';
import { fixedSpring } from './softness.js';
import { Joint3DFlag, type Joint3DStore, Joint3DType, joints3DOf } from './store-3d.js';

/**
 * The 3D distance joint (a rod, a spring, or a rope through its length limits): its options,
 * addDistanceJoint3D, setDistanceJoint3DLength and setDistanceJoint3DSpring, and its rows
 * (DISTANCE_ROWS_3D), which joints/solver-3d.ts runs with the other 3D joints'.
 */

/**
 * Options of `addDistanceJoint3D`: those of `addDistanceJoint` (anchors as 3D world points, m) but
 * `breakStretch`, its spring's reference mass taken in 3D.
 * @category Joints and ropes
 */
export interface DistanceJoint3DOptions extends Omit<DistanceJointOptions, 'breakStretch' | 'hertz'> {
  /**
   * Spring frequency, Hz (>= 0; 0 rigid). Default 0. A spring of fixed stiffness k = (2 pi hertz)^2 / K_ref,
   * K_ref = mA + mB + (tr(IA^-1) |rA|^2 - rA . IA^-1 rA + the same for B) / 3 (the anchors' levers from the
   * centres; no rotation changes it), so a lever's swing does no work on it.
   */
  hertz?: number;
}

/**
 * Distance: the anchors stay `length` apart (a rod), spring toward it (`hertz` > 0), or stay within
 * [minLength, maxLength] (a rope: minLength 0). @returns the joint's handle.
 * @throws TypeError | RangeError `addDistanceJoint3D: <param> must be ...` as addBallJoint3D, on a missing
 *   anchorA with the world as A, a length <= 0, limits out of order, a negative spring value.
 * @category Joints and ropes
 */
export function addDistanceJoint3D(world: PhysicsWorld, options: DistanceJoint3DOptions): number {
  const where = 'addDistanceJoint3D';
  const e = checkEnds(where, world, options, 3, ['anchorA', 'anchorB', 'length', 'minLength', 'maxLength', 'hertz', 'dampingRatio']);
  const d = checkDistance(where, options, e.a, centre(world, e.a), centre(world, e.b));
  const j = make(world, where, Joint3DType.Distance, DISTANCE_ROWS_3D, e, options, d.pa, d.pb, [0, 1, 0]);
  const s = joints3DOf(world, true);
  storeLength(s, j, d.length, d.minLength, d.maxLength, d.hertz > 0);
  s.hertz[j] = d.hertz;
  s.dampingRatio[j] = d.zeta;
  return currentHandle(world, j);
}

/** Writes distance joint j's rest length and limits (m), and its Spring (`spring`) and Limit (minL < maxL) flags. */
function storeLength(s: Joint3DStore, j: number, length: number, minL: number, maxL: number, spring: boolean): void {
  s.length[j] = length;
  s.lower[j] = minL;
  s.upper[j] = maxL;
  s.flags[j] = (spring ? Joint3DFlag.Spring : 0) | (minL < maxL ? Joint3DFlag.Limit : 0);
}

/**
 * A distance joint's rows after a change (joints/solver-3d.ts): the rod row runs without spring and
 * limits, the spring row with a spring, the lower limit's with limits when lower > 0 or without a
 * spring, the upper's with limits when upper is finite. A row that no longer runs would still be warm
 * started from its last impulse, so that impulse is dropped; rows that still run keep theirs.
 */
function dropIdleDistanceImpulses(s: Joint3DStore, j: number): void {
  const f = s.flags[j]!,
    spring = (f & Joint3DFlag.Spring) !== 0,
    limit = (f & Joint3DFlag.Limit) !== 0;
  if (!spring && limit) s.lx[j] = 0;
  if (!limit || !(s.lower[j]! > 0 || !spring)) s.limit[j] = 0;
  if (!limit || !Number.isFinite(s.upper[j]!)) s.ly[j] = 0;
}

/**
 * Sets a distance joint's rest length and limits, as addDistanceJoint3D's `length`, `minLength` and
 * `maxLength`: 0 <= minLength <= length <= maxLength, m. Omitted limits default as there, from the
 * joint's current spring: both `length` without a spring (a rigid rod), 0 and Infinity with one. A
 * rope of length L: `(L, 0)`. The spring, damping and break thresholds are kept. Limit impulses start
 * again from zero when the limits change; the rod's or spring's is kept while that row still runs; the
 * bodies wake. A body away from the new length is brought there at the rod's soft rate (60 Hz, capped
 * at a quarter of the substep rate), at the spring's own rate, or not at all inside a rope's slack.
 * @param length rest length, m, finite and > 0.
 * @param minLength shortest the anchors may get, m, in [0, length].
 * @param maxLength longest, m, >= length (Infinity allowed).
 * @throws RangeError `setDistanceJoint3DLength: joint must be ...` on a removed entity or a joint that
 *   is not a 3D distance joint; TypeError | RangeError `setDistanceJoint3DLength: <param> must be ...`
 *   naming the parameter and value. A throwing call changes nothing.
 * @category Joints and ropes
 */
export function setDistanceJoint3DLength(world: PhysicsWorld, joint: number, length: number, minLength?: number, maxLength?: number): void {
  const where = 'setDistanceJoint3DLength';
  const { s, j } = requireJoint3D(where, world, joint, [Joint3DType.Distance]);
  assertPositive(where, 'length', length);
  const spring = (s.flags[j]! & Joint3DFlag.Spring) !== 0;
  const [minL, maxL] = lengthLimits(where, length, spring, minLength, maxLength);
  const limitsChanged = s.lower[j] !== minL || s.upper[j] !== maxL;
  storeLength(s, j, length, minL, maxL, spring);
  if (limitsChanged) {
    s.limit[j] = 0;
    s.ly[j] = 0;
  }
  dropIdleDistanceImpulses(s, j);
  wakeJoint3D(world, s, j);
}

/**
 * Sets a distance joint's spring: the anchors are pulled toward the rest length by Box2D's soft spring
 * of natural frequency `hertz` and damping ratio `dampingRatio` (joints/solver-3d.ts). For a body of mass
 * m on the fixed world, anchored at its centre of mass, that is a spring of stiffness
 * k = m (2 pi hertz)^2 with a damper of c = 2 m dampingRatio (2 pi hertz): it swings with the period
 * 2 pi sqrt(m / k) = 1 / hertz (undamped). `hertz` 0 removes the spring: the joint is then rigid between
 * its limits (a rod when minLength = maxLength; a joint made with a spring and default limits, 0 and
 * Infinity, then holds nothing: give limits with setDistanceJoint3DLength). Limits are kept; the rod's
 * or spring's warm-start impulse carries over to the row that replaces it; the bodies wake.
 * @param hertz natural frequency, Hz, finite and >= 0 (0: no spring).
 * @param dampingRatio >= 0 (1: critically damped), finite.
 * @throws RangeError `setDistanceJoint3DSpring: joint must be ...` on a removed entity or a joint that
 *   is not a 3D distance joint; TypeError | RangeError `setDistanceJoint3DSpring: <param> must be ...`
 *   naming the parameter and value. A throwing call changes nothing.
 * @category Joints and ropes
 */
export function setDistanceJoint3DSpring(world: PhysicsWorld, joint: number, hertz: number, dampingRatio: number): void {
  const where = 'setDistanceJoint3DSpring';
  const { s, j } = requireJoint3D(where, world, joint, [Joint3DType.Distance]);
  assertNonNegative(where, 'hertz', hertz);
  assertNonNegative(where, 'dampingRatio', dampingRatio);
  s.hertz[j] = hertz;
  s.dampingRatio[j] = dampingRatio;
  s.flags[j] = hertz > 0 ? s.flags[j]! | Joint3DFlag.Spring : s.flags[j]! & ~Joint3DFlag.Spring;
  dropIdleDistanceImpulses(s, j);
  wakeJoint3D(world, s, j);
}

/** Scratch of a spring's coefficients (fixedSpring). */
const spring = new Float64Array(2);

/**
 * A distance joint's rows along the anchors' line: the spring (soft, fixed stiffness), the rod, and the
 * one-sided length limits (speculative when apart). Anchors that meet reset its impulses.
 */
export function solveDistanceRow3D(p: JointPass3D, j: number, a: number, b: number, flags: number): void {
  const { s, sb, T, hs, useBias, bRate, ms, is } = p;
  let dx = pb[0]! + rb[0]! - pa[0]! - ra[0]!,
    dy = pb[1]! + rb[1]! - pa[1]! - ra[1]!,
    dz = pb[2]! + rb[2]! - pa[2]! - ra[2]!;
  const len = Math.hypot(dx, dy, dz);
  // No direction: nothing was warm-started; the rows start again from zero.
  if (!(len > 1e-12)) {
    s.lx[j] = 0;
    s.limit[j] = 0;
    s.ly[j] = 0;
    return;
  }
  dx /= len;
  dy /= len;
  dz /= len;
  const k = linearK(sb, T, a, b, dx, dy, dz);
  if (!(k > 0)) return;
  const L = s.length[j]!,
    sprung = (flags & Joint3DFlag.Spring) !== 0;
  // The spring (while the pass uses bias), or the rod when there are no limits (soft with the pass's softness).
  if (sprung ? useBias : !(flags & Joint3DFlag.Limit)) {
    let bias = bRate * (len - L),
      m = ms,
      im = is;
    if (sprung) {
      // A spring of fixed stiffness (see fixedSpring): its softness gamma from the reference mass,
      // the row's mass from the effective mass k of the moment.
      fixedSpring(spring, 0, s.hertz[j]!, s.dampingRatio[j]!, hs, referenceK(sb, T, a, b));
      const gamma = spring[1]!,
        soft = gamma < Infinity;
      bias = spring[0]! * (len - L);
      m = soft ? k / (k + gamma) : 0;
      im = soft ? gamma / (k + gamma) : 1;
    }
    s.lx[j] = row3D(sb, T, a, b, true, dx, dy, dz, k, anchorSpeed(sb, a, b, dx, dy, dz), bias, m, im, s.lx[j]!, -Infinity, Infinity);
  }
  if (flags & Joint3DFlag.Limit) {
    // One-sided rows: len >= lower (impulse along +u) and len <= upper (along -u); speculative when apart.
    if (s.lower[j]! > 0 || !(flags & Joint3DFlag.Spring)) {
      limitSoftness(p, len - s.lower[j]!);
      const cdot = anchorSpeed(sb, a, b, dx, dy, dz);
      s.limit[j] = row3D(sb, T, a, b, true, dx, dy, dz, k, cdot, limitSoft[0]!, limitSoft[1]!, limitSoft[2]!, s.limit[j]!, 0, Infinity);
    }
    if (Number.isFinite(s.upper[j]!)) {
      limitSoftness(p, s.upper[j]! - len);
      const cdot = -anchorSpeed(sb, a, b, dx, dy, dz);
      s.ly[j] = row3D(sb, T, a, b, true, -dx, -dy, -dz, k, cdot, limitSoft[0]!, limitSoft[1]!, limitSoft[2]!, s.ly[j]!, 0, Infinity);
    }
  }
}

/**
 * A distance joint's warm start: its rod's or spring's impulse (lx) and its lower limit's (limit) push B
 * along u = (anchor B - anchor A) / length, its upper limit's (ly) against it; nothing when the anchors
 * meet (no direction).
 */
export function warmStartDistanceRow3D(p: JointPass3D, j: number, a: number, b: number): void {
  const { s, sb, T } = p;
  const dx = pb[0]! + rb[0]! - pa[0]! - ra[0]!,
    dy = pb[1]! + rb[1]! - pa[1]! - ra[1]!,
    dz = pb[2]! + rb[2]! - pa[2]! - ra[2]!;
  const len = Math.hypot(dx, dy, dz),
    P = s.lx[j]! + s.limit[j]! - s.ly[j]!;
  if (len > 1e-12 && P !== 0) applyLinear(sb, T, a, b, (P * dx) / len, (P * dy) / len, (P * dz) / len);
}

/** A distance joint's reading: the force along the anchors' line of its rows (rod or spring, lower limit, minus upper limit), no torque. */
export function distanceReading3D(s: Joint3DStore, j: number, hs: number, out: Float64Array): void {
  out[0] = Math.abs(s.lx[j]! + s.limit[j]! - s.ly[j]!) / hs;
  out[1] = 0;
}

/** The 3D distance joint's rows (rows-3d.ts JointRows3D). */
export const DISTANCE_ROWS_3D: JointRows3D = {
  warmStart: warmStartDistanceRow3D,
  solve: solveDistanceRow3D,
  reading: distanceReading3D,
};
