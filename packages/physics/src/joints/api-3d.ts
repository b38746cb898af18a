import { hasComponent } from 'bitecs';
import { install3D } from '../collision/install-3d.js';
import { wakeIsland } from '../islands/sleep.js';
import { createSlot, currentHandle, resolveEntity } from '../world/handles.js';
import { addNoCollide } from '../world/joint-no-collide.js';
import type { PhysicsWorld } from '../world/options.js';
import {
  assertFinite,
  assertKnownKeys,
  assertNonNegative,
  assertOptionalBoolean,
  assertPositive,
  assertVector,
  describe,
} from '../world/validate.js';
import { assertBreakLimit } from './api-2d.js';
import { removeJoint3DUnchecked, removeJoints3DOf } from './remove-3d.js';

export { removeJoint3DUnchecked } from './remove-3d.js';

import { ensureJointArrays } from '../world/joint-state-2d.js';
import { Joint3DFlag, type Joint3DStore, Joint3DType, joints3DOf } from './store-3d.js';

/**
 * Joints between 3D bodies, solved in the contact solver's soft substeps (joints/solver-3d.ts): ball
 * and socket (with an optional cone limit), hinge (angle limits, motor), slider (translation limits,
 * motor), fixed, and distance (rigid, spring, or rope through its length limits). Each joint is its own entity holding its two bodies:
 * A (a body, or the fixed world when omitted or null) and B. Anchors and axes are given in world
 * coordinates where the bodies are when the joint is made; the joint keeps them in the bodies'
 * frames. Removing either body removes the joint. Past `breakForce` (N) or `breakTorque` (N m) a
 * joint breaks: it is removed and listed in `joint3DBreaks(world)` after the step. The two bodies of a
 * joint do not collide with each other unless `collideConnected` is true (as 2D joints, Box2D's
 * default): the pairs are counted in the world's joint state (world/joint-no-collide.ts), which the 3D shape
 * narrowphase and the ball narrowphase both consult.
 */

/**
 * Options every 3D joint shares.
 * @category Joints and ropes
 */
export interface Joint3DBaseOptions {
  /** Body A, or omitted / null for the fixed world. */
  a?: number | null;
  /** Body B. */
  b: number;
  /** Force above which the joint breaks, N, > 0. Default Infinity (never). */
  breakForce?: number;
  /** Torque above which the joint breaks, N m, > 0. Default Infinity (never). */
  breakTorque?: number;
  /**
   * Whether bodies A and B still collide with each other (Box2D's collideConnected). Default false: the
   * contacts between the two jointed bodies are skipped (their shapes may overlap at the joint, as a
   * welded L's or a ragdoll's limbs do, without the contact and the joint fighting); true keeps them
   * colliding. No effect when A is the world.
   */
  collideConnected?: boolean;
}

const BASE = ['a', 'b', 'breakForce', 'breakTorque', 'collideConnected'] as const;

function body(where: string, param: string, world: PhysicsWorld, id: unknown): number {
  const slot = resolveEntity(world, id, where, param);
  const c = world.components;
  if (!hasComponent(world, slot, c.Position) || !hasComponent(world, slot, c.Mass) || !hasComponent(world, slot, c.Orientation)) {
    throw new RangeError(
      `${where}: ${param} must be a 3D body with position, mass and orientation (addBody, addShape3D), got entity ${describe(id)}`,
    );
  }
  return slot;
}

function ends(where: string, world: PhysicsWorld, o: Joint3DBaseOptions, keys: readonly string[]): { a: number; b: number } {
  if (world.dimensions !== 3) throw new RangeError(`${where}: 3D joints need a 3D world, this world has ${world.dimensions} dimensions`);
  if (o === null || typeof o !== 'object') throw new TypeError(`${where}: options must be an object with body b, got ${describe(o)}`);
  assertKnownKeys(where, o, [...BASE, ...keys], ['a']);
  const a = o.a === undefined || o.a === null ? 0 : body(where, 'a', world, o.a);
  const b = body(where, 'b', world, o.b);
  if (a === b) throw new RangeError(`${where}: a and b must be different bodies, got ${describe(o.a)} twice`);
  if (o.breakForce !== undefined) assertBreakLimit(where, 'breakForce', o.breakForce);
  if (o.breakTorque !== undefined) assertBreakLimit(where, 'breakTorque', o.breakTorque);
  assertOptionalBoolean(where, 'collideConnected', o.collideConnected);
  return { a, b };
}

function point(where: string, param: string, v: unknown): [number, number, number] {
  assertVector(where, param, v, 3);
  const p = v as ArrayLike<number>;
  return [p[0]!, p[1]!, p[2]!];
}

function unit(where: string, param: string, v: unknown): [number, number, number] {
  const p = point(where, param, v);
  const l = Math.hypot(p[0], p[1], p[2]);
  if (!(l > 0)) throw new RangeError(`${where}: ${param} must be a non-zero vector, got ${describe(v)}`);
  return [p[0] / l, p[1] / l, p[2] / l];
}

function quat(world: PhysicsWorld, e: number): [number, number, number, number] {
  if (e === 0) return [0, 0, 0, 1];
  const Q = world.components.Orientation;
  return [Q.x[e]!, Q.y[e]!, Q.z[e]!, Q.w[e]!];
}

/** v rotated by the inverse of unit quaternion q (world to body frame). */
function toBody(q: [number, number, number, number], v: [number, number, number]): [number, number, number] {
  const x = -q[0],
    y = -q[1],
    z = -q[2],
    w = q[3];
  const tx = 2 * (y * v[2] - z * v[1]),
    ty = 2 * (z * v[0] - x * v[2]),
    tz = 2 * (x * v[1] - y * v[0]);
  return [v[0] + w * tx + (y * tz - z * ty), v[1] + w * ty + (z * tx - x * tz), v[2] + w * tz + (x * ty - y * tx)];
}

function centre(world: PhysicsWorld, e: number): [number, number, number] {
  const P = world.components.Position;
  return e === 0 ? [0, 0, 0] : [P.x[e]!, P.y[e]!, P.z[e]!];
}

/** Makes the joint entity and its common fields; anchors pa, pb (world), axis (world). */
function make(
  world: PhysicsWorld,
  where: string,
  type: number,
  e: { a: number; b: number },
  o: Joint3DBaseOptions,
  pa: [number, number, number],
  pb: [number, number, number],
  axis: [number, number, number],
): number {
  const j = createSlot(world, where);
  install3D(world);
  const s = joints3DOf(world, true);
  if (s.list.length === 0 && !world.removeHooks.includes(removeJoints3DOf)) world.removeHooks.push(removeJoints3DOf);
  const qa = quat(world, e.a),
    qb = quat(world, e.b),
    ca = centre(world, e.a),
    cb = centre(world, e.b);
  const la = toBody(qa, [pa[0] - ca[0], pa[1] - ca[1], pa[2] - ca[2]]),
    lb = toBody(qb, [pb[0] - cb[0], pb[1] - cb[1], pb[2] - cb[2]]);
  const ua = toBody(qa, axis),
    ub = toBody(qb, axis);
  s.type[j] = type;
  s.flags[j] = 0;
  s.a[j] = e.a;
  s.b[j] = e.b;
  s.ax[j] = la[0];
  s.ay[j] = la[1];
  s.az[j] = la[2];
  s.bx[j] = lb[0];
  s.by[j] = lb[1];
  s.bz[j] = lb[2];
  s.uax[j] = ua[0];
  s.uay[j] = ua[1];
  s.uaz[j] = ua[2];
  s.ubx[j] = ub[0];
  s.uby[j] = ub[1];
  s.ubz[j] = ub[2];
  // conj(qa) qb
  const [x1, y1, z1, w1] = [-qa[0], -qa[1], -qa[2], qa[3]],
    [x2, y2, z2, w2] = qb;
  s.rx[j] = w1 * x2 + x1 * w2 + y1 * z2 - z1 * y2;
  s.ry[j] = w1 * y2 - x1 * z2 + y1 * w2 + z1 * x2;
  s.rz[j] = w1 * z2 + x1 * y2 - y1 * x2 + z1 * w2;
  s.rw[j] = w1 * w2 - x1 * x2 - y1 * y2 - z1 * z2;
  s.lower[j] = 0;
  s.upper[j] = 0;
  s.motorSpeed[j] = 0;
  s.maxMotorTorque[j] = 0;
  s.length[j] = 0;
  s.hertz[j] = 0;
  s.dampingRatio[j] = 0;
  s.breakForce[j] = o.breakForce ?? Infinity;
  s.breakTorque[j] = o.breakTorque ?? Infinity;
  s.lx[j] = 0;
  s.ly[j] = 0;
  s.lz[j] = 0;
  s.wx[j] = 0;
  s.wy[j] = 0;
  s.wz[j] = 0;
  s.limit[j] = 0;
  s.motor[j] = 0;
  s.list.push(j);
  ensureJointArrays(world.joints, world.capacity);
  world.joints.noCollideJoint[j] = 0;
  if (o.collideConnected !== true) addNoCollide(world.joints, j, e.a, e.b);
  // A sleeping body newly held (or pulled) by a joint wakes, with its island (as 2D joints).
  if (e.a !== 0) wakeIsland(world, e.a);
  wakeIsland(world, e.b);
  return j;
}

/**
 * Options of `addBallJoint3D`.
 * @category Joints and ropes
 */
export interface BallJoint3DOptions extends Joint3DBaseOptions {
  /** The joint's point (world, m). Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Cone limit: the axis (world, when made) that B's copy of it may swing away from A's by at most `coneAngle`. Default (0, 1, 0). */
  axis?: ArrayLike<number>;
  /** Cone half angle, rad, in (0, pi). Default none (free swing). */
  coneAngle?: number;
}

/**
 * Ball and socket: the anchor points of A and B coincide (three soft rows); with `coneAngle`, B's axis
 * stays within that angle of A's (a swing cone). @returns the joint's handle.
 * @throws TypeError | RangeError `addBallJoint3D: <param> must be ...` in a 2D world, on missing or bad
 *   bodies (removed, not 3D bodies, the same twice), bad vectors, a cone angle outside (0, pi), a bad
 *   break threshold, or a full world.
 * @category Joints and ropes
 */
export function addBallJoint3D(world: PhysicsWorld, options: BallJoint3DOptions): number {
  const where = 'addBallJoint3D';
  const e = ends(where, world, options, ['anchor', 'axis', 'coneAngle']);
  const p = options.anchor === undefined ? centre(world, e.b) : point(where, 'anchor', options.anchor);
  const axis = options.axis === undefined ? ([0, 1, 0] as [number, number, number]) : unit(where, 'axis', options.axis);
  if (options.coneAngle !== undefined) {
    assertFinite(where, 'coneAngle', options.coneAngle);
    if (!(options.coneAngle > 0 && options.coneAngle < Math.PI))
      throw new RangeError(`${where}: coneAngle must be in (0, pi), got ${describe(options.coneAngle)}`);
  }
  const j = make(world, where, Joint3DType.Ball, e, options, p, p, axis);
  const s = joints3DOf(world, true);
  if (options.coneAngle !== undefined) {
    s.flags[j] = Joint3DFlag.Cone;
    s.upper[j] = options.coneAngle;
  }
  return currentHandle(world, j);
}

/** A hinge's or slider's checked limits and motor (`limitAndMotor`). */
interface LimitAndMotor {
  lower?: number;
  upper?: number;
  motorSpeed?: number;
  maxMotor?: number;
}

/**
 * Checks the limit pair (lower <= 0 <= upper, both or neither) and the motor (a finite speed with a
 * largest torque or force `maxName` >= 0) of addHingeJoint3D and addSliderJoint3D before anything is made.
 * @throws RangeError `<where>: ...` naming the parameter and value.
 */
function limitAndMotor(
  where: string,
  lower: number | undefined,
  upper: number | undefined,
  motorSpeed: number | undefined,
  maxMotor: number | undefined,
  maxName: string,
): LimitAndMotor {
  const out: LimitAndMotor = {};
  if (lower !== undefined || upper !== undefined) {
    if (lower === undefined || upper === undefined)
      throw new RangeError(`${where}: lower and upper must be given together, got lower ${describe(lower)}, upper ${describe(upper)}`);
    assertFinite(where, 'lower', lower);
    assertFinite(where, 'upper', upper);
    if (!(lower <= 0)) throw new RangeError(`${where}: lower must be <= 0, got ${lower}`);
    if (!(upper >= 0)) throw new RangeError(`${where}: upper must be >= 0, got ${upper}`);
    out.lower = lower;
    out.upper = upper;
  }
  if (motorSpeed !== undefined || maxMotor !== undefined) {
    assertFinite(where, 'motorSpeed', motorSpeed ?? 0);
    if (maxMotor === undefined) throw new RangeError(`${where}: ${maxName} must be given with motorSpeed, got undefined`);
    assertNonNegative(where, maxName, maxMotor);
    out.motorSpeed = motorSpeed ?? 0;
    out.maxMotor = maxMotor;
  }
  return out;
}

/** Writes checked limits and motor into joint j's store row (the motor's cap goes in maxMotorTorque, N m or N). */
function storeLimitAndMotor(s: Joint3DStore, j: number, lm: LimitAndMotor): void {
  if (lm.lower !== undefined) {
    s.flags[j] = s.flags[j]! | Joint3DFlag.Limit;
    s.lower[j] = lm.lower;
    s.upper[j] = lm.upper!;
  }
  if (lm.maxMotor !== undefined) {
    s.flags[j] = s.flags[j]! | Joint3DFlag.Motor;
    s.motorSpeed[j] = lm.motorSpeed!;
    s.maxMotorTorque[j] = lm.maxMotor;
  }
}

/**
 * Options of `addHingeJoint3D`.
 * @category Joints and ropes
 */
export interface HingeJoint3DOptions extends Joint3DBaseOptions {
  /** A point on the hinge's axis (world, m). Default B's centre. */
  anchor?: ArrayLike<number>;
  /** The hinge axis (world, when made); need not be unit length. */
  axis: ArrayLike<number>;
  /** Angle limits, rad, about the axis from the pose when made (right-handed): lower <= 0 <= upper. Default none. */
  lower?: number;
  upper?: number;
  /** Motor: target relative angular speed about the axis, rad/s, and its largest torque, N m (>= 0). Default off. */
  motorSpeed?: number;
  maxMotorTorque?: number;
}

/**
 * Hinge: ball and socket plus two angular rows that keep B's axis along A's, so B turns relative to A
 * about the axis only; optional angle limits and a motor. @returns the joint's handle.
 * @throws TypeError | RangeError `addHingeJoint3D: <param> must be ...` as addBallJoint3D, on a zero
 *   axis, lower > 0 or upper < 0, only one limit, a motor speed without a torque or a negative torque.
 * @category Joints and ropes
 */
export function addHingeJoint3D(world: PhysicsWorld, options: HingeJoint3DOptions): number {
  const where = 'addHingeJoint3D';
  const e = ends(where, world, options, ['anchor', 'axis', 'lower', 'upper', 'motorSpeed', 'maxMotorTorque']);
  const p = options.anchor === undefined ? centre(world, e.b) : point(where, 'anchor', options.anchor);
  const axis = unit(where, 'axis', options.axis);
  const lm = limitAndMotor(where, options.lower, options.upper, options.motorSpeed, options.maxMotorTorque, 'maxMotorTorque');
  const j = make(world, where, Joint3DType.Hinge, e, options, p, p, axis);
  storeLimitAndMotor(joints3DOf(world, true), j, lm);
  return currentHandle(world, j);
}

/**
 * Options of `addFixedJoint3D`.
 * @category Joints and ropes
 */
export interface FixedJoint3DOptions extends Joint3DBaseOptions {
  /** The point the bodies are welded at (world, m). Default B's centre. */
  anchor?: ArrayLike<number>;
}

/**
 * Fixed (weld): B keeps its position and orientation relative to A. @returns the joint's handle. @throws as addBallJoint3D.
 * @category Joints and ropes
 */
export function addFixedJoint3D(world: PhysicsWorld, options: FixedJoint3DOptions): number {
  const where = 'addFixedJoint3D';
  const e = ends(where, world, options, ['anchor']);
  const p = options.anchor === undefined ? centre(world, e.b) : point(where, 'anchor', options.anchor);
  return currentHandle(world, make(world, where, Joint3DType.Fixed, e, options, p, p, [0, 1, 0]));
}

/**
 * Options of `addDistanceJoint3D`.
 * @category Joints and ropes
 */
export interface DistanceJoint3DOptions extends Joint3DBaseOptions {
  /** Anchor on A (world, m); required when A is the world, else default A's centre. */
  anchorA?: ArrayLike<number>;
  /** Anchor on B (world, m). Default B's centre. */
  anchorB?: ArrayLike<number>;
  /** Rest length, m, > 0. Default the anchors' distance when made. */
  length?: number;
  /** Limits, m: 0 <= minLength <= length <= maxLength. Defaults: both `length` (a rigid rod), or 0 and Infinity with a spring. A rope: minLength 0. */
  minLength?: number;
  maxLength?: number;
  /**
   * Spring frequency, Hz (>= 0; 0 rigid), and damping ratio (>= 0). Default 0, 0. A spring of fixed stiffness
   * k = (2 pi hertz)^2 / K_ref, K_ref = mA + mB + (tr(IA^-1) |rA|^2 - rA . IA^-1 rA + the same for B) / 3 (the
   * anchors' levers from the centres; no rotation changes it), so a lever's swing does no work on it.
   */
  hertz?: number;
  dampingRatio?: number;
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
  const e = ends(where, world, options, ['anchorA', 'anchorB', 'length', 'minLength', 'maxLength', 'hertz', 'dampingRatio']);
  if (e.a === 0 && options.anchorA === undefined) throw new RangeError(`${where}: anchorA (a world point) is required when a is the world`);
  const pa = options.anchorA === undefined ? centre(world, e.a) : point(where, 'anchorA', options.anchorA);
  const pb = options.anchorB === undefined ? centre(world, e.b) : point(where, 'anchorB', options.anchorB);
  const length = options.length ?? Math.hypot(pb[0] - pa[0], pb[1] - pa[1], pb[2] - pa[2]);
  assertPositive(where, 'length', length);
  const hertz = options.hertz ?? 0,
    zeta = options.dampingRatio ?? 0;
  assertNonNegative(where, 'hertz', hertz);
  assertNonNegative(where, 'dampingRatio', zeta);
  const minL = options.minLength ?? (hertz > 0 ? 0 : length),
    maxL = options.maxLength ?? (hertz > 0 ? Infinity : length);
  assertNonNegative(where, 'minLength', minL);
  if (!(minL <= length)) throw new RangeError(`${where}: minLength must be <= length (${length}), got ${describe(minL)}`);
  if (typeof maxL !== 'number' || Number.isNaN(maxL) || !(maxL >= length))
    throw new RangeError(`${where}: maxLength must be >= length (${length}), got ${describe(maxL)}`);
  const j = make(world, where, Joint3DType.Distance, e, options, pa, pb, [0, 1, 0]);
  const s = joints3DOf(world, true);
  s.length[j] = length;
  s.lower[j] = minL;
  s.upper[j] = maxL;
  s.hertz[j] = hertz;
  s.dampingRatio[j] = zeta;
  s.flags[j] = (hertz > 0 ? Joint3DFlag.Spring : 0) | (minL < maxL ? Joint3DFlag.Limit : 0);
  return currentHandle(world, j);
}

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

/** Names of the 3D joint types, for errors. */
const TYPE_NAMES = ['ball', 'hinge', 'fixed', 'distance', 'slider'];

/**
 * The slot of the live 3D joint `joint` (a handle), of one of `types` when given.
 * @throws RangeError `<where>: joint must be ...` naming the value (a removed entity, not a 3D joint, another type).
 */
function requireJoint3D(where: string, world: PhysicsWorld, joint: unknown, types?: readonly number[]): { s: Joint3DStore; j: number } {
  const j = resolveEntity(world, joint, where, 'joint');
  const s = joints3DOf(world);
  if (s === undefined || !s.list.includes(j)) throw new RangeError(`${where}: joint must be a 3D joint, got entity ${describe(joint)}`);
  if (types !== undefined && !types.includes(s.type[j]!)) {
    const want = types.map((t) => TYPE_NAMES[t]).join(' or ');
    throw new RangeError(`${where}: joint must be a 3D ${want} joint, got a ${TYPE_NAMES[s.type[j]!]} joint (${describe(joint)})`);
  }
  return { s, j };
}

/** Wakes the islands of a joint's two bodies (a setter changed what holds them). */
function wakeJoint3D(world: PhysicsWorld, s: Joint3DStore, j: number): void {
  if (s.a[j] !== 0) wakeIsland(world, s.a[j]!);
  if (s.b[j] !== 0) wakeIsland(world, s.b[j]!);
}

/**
 * Sets (or with `coneAngle` null removes) a ball-and-socket joint's cone limit: B's copy of the cone
 * axis (the `axis` given to addBallJoint3D, default (0, 1, 0), as the bodies were when the joint was
 * made) may swing at most `coneAngle` away from A's. A joint made without a cone gets one about that
 * axis. The cone's warm-start impulse starts again from zero; the bodies wake. Bodies already outside
 * a narrower cone are brought back at the joints' soft rate (60 Hz, capped at a quarter of the
 * substep rate), not in one step.
 * @param coneAngle half angle, rad, in (0, pi); null removes the limit.
 * @throws RangeError `setBallJoint3DCone: joint must be ...` on a removed entity or a joint that is not
 *   a 3D ball joint; TypeError | RangeError `setBallJoint3DCone: coneAngle must be ...` naming the value.
 *   A throwing call changes nothing.
 * @category Joints and ropes
 */
export function setBallJoint3DCone(world: PhysicsWorld, joint: number, coneAngle: number | null): void {
  const where = 'setBallJoint3DCone';
  const { s, j } = requireJoint3D(where, world, joint, [Joint3DType.Ball]);
  if (coneAngle !== null) {
    assertFinite(where, 'coneAngle', coneAngle);
    if (!(coneAngle > 0 && coneAngle < Math.PI)) throw new RangeError(`${where}: coneAngle must be in (0, pi), got ${describe(coneAngle)}`);
    s.flags[j] = s.flags[j]! | Joint3DFlag.Cone;
    s.upper[j] = coneAngle;
  } else s.flags[j] = s.flags[j]! & ~Joint3DFlag.Cone;
  s.limit[j] = 0;
  wakeJoint3D(world, s, j);
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
  const minL = minLength ?? (spring ? 0 : length),
    maxL = maxLength ?? (spring ? Infinity : length);
  assertNonNegative(where, 'minLength', minL);
  if (!(minL <= length)) throw new RangeError(`${where}: minLength must be <= length (${length}), got ${describe(minL)}`);
  if (typeof maxL !== 'number' || Number.isNaN(maxL) || !(maxL >= length))
    throw new RangeError(`${where}: maxLength must be >= length (${length}), got ${describe(maxL)}`);
  const limitsChanged = s.lower[j] !== minL || s.upper[j] !== maxL;
  s.length[j] = length;
  s.lower[j] = minL;
  s.upper[j] = maxL;
  s.flags[j] = (spring ? Joint3DFlag.Spring : 0) | (minL < maxL ? Joint3DFlag.Limit : 0);
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
  const check = (param: string, v: unknown): void => {
    if (typeof v !== 'number') throw new TypeError(`${where}: ${param} must be a number, got ${describe(v)}`);
    if (!(v > 0)) throw new RangeError(`${where}: ${param} must be > 0 (Infinity: never), got ${describe(v)}`);
  };
  check('breakForce', breakForce);
  if (breakTorque !== undefined) check('breakTorque', breakTorque);
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
  const j = resolveEntity(world, joint, 'removeJoint3D', 'joint');
  const s = joints3DOf(world);
  if (s === undefined || !s.list.includes(j))
    throw new RangeError(`removeJoint3D: joint must be a 3D joint, got entity ${describe(joint)}`);
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
