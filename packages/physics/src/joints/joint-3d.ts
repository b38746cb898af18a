import { hasComponent } from 'bitecs';
import { install3D } from '../collision/install-3d.js';
import { wakeIsland } from '../islands/sleep.js';
import { assertFinite, assertKnownKeys, assertNonNegative, assertOptionalBoolean, assertVector, describe } from '../validation/validate.js';
import { createSlot, resolveEntity } from '../world/handles.js';
import { addNoCollide } from '../world/joint-no-collide.js';
import { ensureJointArrays } from '../world/joint-state-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { assertBreakLimit } from './joint-base.js';
import { removeJoints3DOf } from './remove-3d.js';
import { Joint3DFlag, type Joint3DStore, joints3DOf } from './store-3d.js';

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

/** Checks a 3D joint's keys (`keys` besides the shared ones) and its `a` and `b` (a may be omitted or null: the world); returns their slots. @throws TypeError | RangeError naming `where`. */
export function ends(where: string, world: PhysicsWorld, o: Joint3DBaseOptions, keys: readonly string[]): { a: number; b: number } {
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

/** The position of body slot `e`, m (its centre of mass). */
export function centre(world: PhysicsWorld, e: number): [number, number, number] {
  const P = world.components.Position;
  return e === 0 ? [0, 0, 0] : [P.x[e]!, P.y[e]!, P.z[e]!];
}

/** Makes the joint entity and its common fields; anchors pa, pb (world), axis (world). */
export function make(
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
export function limitAndMotor(
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
export function storeLimitAndMotor(s: Joint3DStore, j: number, lm: LimitAndMotor): void {
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
  if (s.a[j] !== 0) wakeIsland(world, s.a[j]!);
  if (s.b[j] !== 0) wakeIsland(world, s.b[j]!);
}
