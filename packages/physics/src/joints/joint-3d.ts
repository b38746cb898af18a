import { install3D } from '../collision/install-3d.js';
import { rotateVectorInverse } from '../math/quaternion.js';
import { assertFinite, assertNonNegative, assertVector, describe, optionOr } from '../validation/validate.js';
import { createSlot, currentHandle, resolveEntity } from '../world/handles.js';
import { addNoCollide } from '../world/joint-no-collide.js';
import { ensureJointArrays } from '../world/joint-state-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { checkEnds, type JointBaseOptions, optionalPoint, wakeEnds } from './joint-base.js';
import type { JointRows3D } from './rows-3d.js';
import { relativeRotation } from './rows-3d-math.js';
import { useJointType3D } from './solver-3d.js';
import { Joint3DFlag, type Joint3DStore, joints3DOf, removeJoints3DOf } from './store-3d.js';

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
 * Options every 3D joint shares: those of every joint (JointBaseOptions).
 * @category Joints and ropes
 */
export type Joint3DBaseOptions = JointBaseOptions;

/** `v` as a 3D point, m. @throws TypeError | RangeError naming `where` and `param` on a malformed vector. */
export function point(where: string, param: string, v: unknown): [number, number, number] {
  assertVector(where, param, v, 3);
  const p = v as ArrayLike<number>;
  return [p[0]!, p[1]!, p[2]!];
}

/** `v` (3 numbers, not zero) normalised. @throws TypeError | RangeError naming `where` and `param`. */
export function unit(where: string, param: string, v: unknown): [number, number, number] {
  const p = point(where, param, v);
  const l = Math.hypot(p[0], p[1], p[2]);
  if (!(l > 0)) throw new RangeError(`${where}: ${param} must be a non-zero vector, got ${describe(v)}`);
  return [p[0] / l, p[1] / l, p[2] / l];
}

/** The orientation of body slot `e` (the world's identity for 0). */
function quat(world: PhysicsWorld, e: number): [number, number, number, number] {
  if (e === 0) return [0, 0, 0, 1];
  const Q = world.components.Orientation;
  return [Q.x[e]!, Q.y[e]!, Q.z[e]!, Q.w[e]!];
}

/** v rotated by the inverse of unit quaternion q (world to body frame). */
function toBody(q: [number, number, number, number], v: [number, number, number]): [number, number, number] {
  const out = new Float64Array(3);
  rotateVectorInverse(q[0], q[1], q[2], q[3], v[0], v[1], v[2], out);
  return [out[0]!, out[1]!, out[2]!];
}

/** The position of body slot `e`, m (its centre of mass). */
export function centre(world: PhysicsWorld, e: number): [number, number, number] {
  const P = world.components.Position;
  return e === 0 ? [0, 0, 0] : [P.x[e]!, P.y[e]!, P.z[e]!];
}

/** Makes the joint entity of `type` and its common fields, anchors pa, pb (world) and axis (world), and hands the solver the type's `rows`. */
export function make(
  world: PhysicsWorld,
  where: string,
  type: number,
  rows: JointRows3D,
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
  // The anchors and the axis in each body's frame into their x, y, z columns at j.
  const columns = [
    [s.ax, s.ay, s.az, la],
    [s.bx, s.by, s.bz, lb],
    [s.uax, s.uay, s.uaz, ua],
    [s.ubx, s.uby, s.ubz, ub],
  ] as const;
  for (const [x, y, z, v] of columns) {
    x[j] = v[0];
    y[j] = v[1];
    z[j] = v[2];
  }
  const rel = new Float64Array(4);
  relativeRotation(qa, qb, rel);
  s.rx[j] = rel[0]!;
  s.ry[j] = rel[1]!;
  s.rz[j] = rel[2]!;
  s.rw[j] = rel[3]!;
  for (const k of ['lower', 'upper', 'motorSpeed', 'maxMotorTorque', 'length', 'hertz', 'dampingRatio'] as const) s[k][j] = 0;
  for (const k of ['lx', 'ly', 'lz', 'wx', 'wy', 'wz', 'limit', 'motor'] as const) s[k][j] = 0;
  s.breakForce[j] = o.breakForce ?? Infinity;
  s.breakTorque[j] = o.breakTorque ?? Infinity;
  s.list.push(j);
  ensureJointArrays(world.joints, world.capacity);
  world.joints.noCollideJoint[j] = 0;
  if (o.collideConnected !== true) addNoCollide(world.joints, j, e.a, e.b);
  // A sleeping body newly held (or pulled) by a joint wakes, with its island (as 2D joints).
  wakeEnds(world, e.a, e.b);
  useJointType3D(type, rows);
  return j;
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
  lower: unknown,
  upper: unknown,
  motorSpeed: unknown,
  maxMotor: unknown,
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
    const speed = optionOr(where, 'motorSpeed', motorSpeed, 0, assertFinite);
    if (maxMotor === undefined) throw new RangeError(`${where}: ${maxName} must be given with motorSpeed, got undefined`);
    assertNonNegative(where, maxName, maxMotor);
    out.motorSpeed = speed;
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

/** What addHingeJoint3D and addSliderJoint3D differ in: their name, joint type and rows, and the name of the motor's largest torque or force. */
export interface AxisJoint3DKind {
  where: string;
  type: number;
  rows: JointRows3D;
  maxName: 'maxMotorTorque' | 'maxMotorForce';
}

/** The options of a 3D joint along or about an axis as addAxisJoint3D reads them (HingeJoint3DOptions, SliderJoint3DOptions; documented there), each checked there. */
type AxisJoint3DOptions = JointBaseOptions &
  Partial<Record<'anchor' | 'axis' | 'lower' | 'upper' | 'motorSpeed' | AxisJoint3DKind['maxName'], unknown>>;

/**
 * Adds a 3D joint along or about an axis (addHingeJoint3D, addSliderJoint3D): checks the bodies and
 * keys, the anchor (default B's centre), the axis, the limits and the motor of at most the option
 * `kind.maxName`, then makes the joint and hands the solver the type's rows.
 * @returns the joint's handle. @throws TypeError | RangeError naming `kind.where` on bad bodies, options or values.
 */
export function addAxisJoint3D(world: PhysicsWorld, kind: AxisJoint3DKind, options: AxisJoint3DOptions): number {
  const where = kind.where;
  const e = checkEnds(where, world, options, 3, ['anchor', 'axis', 'lower', 'upper', 'motorSpeed', kind.maxName]);
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, e.b));
  const axis = unit(where, 'axis', options.axis);
  const lm = limitAndMotor(where, options.lower, options.upper, options.motorSpeed, options[kind.maxName], kind.maxName);
  const j = make(world, where, kind.type, kind.rows, e, options, p, p, axis);
  storeLimitAndMotor(joints3DOf(world, true), j, lm);
  return currentHandle(world, j);
}

/** Names of the 3D joint types, for errors. */
const TYPE_NAMES = ['ball', 'hinge', 'fixed', 'distance', 'slider'];

/**
 * The slot of the live 3D joint `joint` (a handle), of one of `types` when given.
 * @throws RangeError `<where>: joint must be ...` naming the value (a removed entity, not a 3D joint, another type).
 */
export function requireJoint3D(
  where: string,
  world: PhysicsWorld,
  joint: unknown,
  types?: readonly number[],
): { s: Joint3DStore; j: number } {
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
export function wakeJoint3D(world: PhysicsWorld, s: Joint3DStore, j: number): void {
  wakeEnds(world, s.a[j]!, s.b[j]!);
}
