import { addComponent, hasComponent } from 'bitecs';
import { wakeIsland } from '../islands/sleep.js';
import { assertFinite, assertKnownKeys, assertNonNegative, describe } from '../validation/validate.js';
import { createSlot, currentHandle, resolveEntity } from '../world/handles.js';
import { addNoCollide } from '../world/joint-no-collide.js';
import { ensureJointArrays } from '../world/joint-state-2d.js';
import { JOINT_TYPE_NAMES, JointFlag, type JointTypeCode } from '../world/joint-store-2d.js';
import { IMPULSES } from '../world/joint-strides-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { BASE_KEYS, checkEnds, type Ends, type JointBaseOptions, optionalPoint, wakeEnds } from './joint-base.js';

/**
 * The add-time code the 2D joint types share (their rows are in rows-2d.ts): every joint is an entity
 * with a `Joint` component holding its two bodies, A (a body, or the fixed world when omitted or null)
 * and B (a body). Anchors are given in world coordinates where the bodies are when the joint is made;
 * the joint keeps them in the bodies' frames. Removing a body removes its joints. A joint may break:
 * past `breakForce` (N) or `breakTorque` (N m) it is removed and reported in `world.joints.breaks`
 * after the step. Here: the bodies' and option keys' check, the anchors' and axis' storage, the limits,
 * motor and spring, the joint along an axis (prismatic, wheel), and finding a joint by its handle.
 */

/** The position of body slot `e`, m (its centre of mass; the origin for 0, the fixed world). */
export function centre(world: PhysicsWorld, e: number): [number, number] {
  return e === 0 ? [0, 0] : [world.components.Position.x[e]!, world.components.Position.y[e]!];
}

/**
 * Checks a 2D joint's world, options, bodies, break limits and collideConnected (joint-base.ts
 * checkEnds), then its option keys: JointBaseOptions' and `keys`; returns the bodies' slots.
 * @throws TypeError | RangeError naming `where`, the parameter and the value.
 */
export function checkEnds2D(where: string, world: PhysicsWorld, options: JointBaseOptions, keys: readonly string[]): Ends {
  const ends = checkEnds(where, world, options, 2);
  assertKnownKeys(where, options, [...BASE_KEYS, ...keys], ['a']);
  return ends;
}

/** `value` (an axis, 2 numbers, not zero) normalised, or `fallback` when undefined. @throws TypeError | RangeError naming `where`. */
export function unitAxis(where: string, value: unknown, fallback: [number, number]): [number, number] {
  const v = optionalPoint(where, 'axis', value, fallback);
  const n = Math.hypot(v[0], v[1]);
  if (!(n > 0)) throw new RangeError(`${where}: axis must not be zero, got ${describe(value)}`);
  return [v[0] / n, v[1] / n];
}

/**
 * Checks an optional pair of limits: both or neither, finite, lower <= upper, inside [-range, range].
 * @returns whether limits were given. @throws RangeError naming `where` and the parameters.
 */
export function checkLimits(where: string, lower: unknown, upper: unknown, lowerName: string, upperName: string, range: number): boolean {
  if (lower === undefined && upper === undefined) return false;
  if (lower === undefined || upper === undefined) throw new RangeError(`${where}: give both ${lowerName} and ${upperName}, or neither`);
  assertFinite(where, lowerName, lower);
  assertFinite(where, upperName, upper);
  if (!(lower <= upper)) throw new RangeError(`${where}: ${lowerName} must be <= ${upperName}, got ${lower} > ${upper}`);
  if (range < Infinity && (lower < -range || upper > range)) {
    throw new RangeError(`${where}: ${lowerName} and ${upperName} must be in [-${range}, ${range}], got [${lower}, ${upper}]`);
  }
  return true;
}

/** The Joint fields a new joint starts at 0 (its axis, longest length and breaking thresholds are set apart). */
const ZEROED = [
  ...['axisY', 'length', 'minLength', 'hertz', 'dampingRatio', 'angularHertz', 'angularDampingRatio', 'flags', 'lower', 'upper'],
  ...['motorSpeed', 'maxMotorForce', 'maxForce', 'force', 'torque'],
] as const;

/**
 * Makes the joint entity with every field at its default, and the anchors: `anchorA`, `anchorB` are
 * world points, stored in A's and B's body frames (A's stays a world point if A is the world).
 */
export function makeJoint(
  world: PhysicsWorld,
  type: JointTypeCode,
  ends: Ends,
  anchorA: [number, number],
  anchorB: [number, number],
  options: JointBaseOptions,
): number {
  const c = world.components;
  ensureJointArrays(world.joints, world.capacity);
  const j = createSlot(world, 'addJoint');
  addComponent(world, j, c.Joint);
  const J = c.Joint;
  const { a, b } = ends;
  J.type[j] = type;
  J.a[j] = a;
  J.b[j] = b;
  const toLocal = (e: number, p: [number, number]): [number, number] => {
    if (e === 0) return p;
    const t = c.Angle.value[e]!,
      co = Math.cos(t),
      si = Math.sin(t);
    const dx = p[0] - c.Position.x[e]!,
      dy = p[1] - c.Position.y[e]!;
    return [co * dx + si * dy, -si * dx + co * dy];
  };
  const la = toLocal(a, anchorA),
    lb = toLocal(b, anchorB);
  J.localAx[j] = la[0];
  J.localAy[j] = la[1];
  J.localBx[j] = lb[0];
  J.localBy[j] = lb[1];
  J.referenceAngle[j] = (b === 0 ? 0 : c.Angle.value[b]!) - (a === 0 ? 0 : c.Angle.value[a]!);
  for (const k of ZEROED) J[k][j] = 0;
  J.axisX[j] = 1;
  J.maxLength[j] = Infinity;
  J.breakForce[j] = options.breakForce ?? Infinity;
  J.breakTorque[j] = options.breakTorque ?? Infinity;
  J.breakStretch[j] = Infinity;
  world.joints.impulses.fill(0, j * IMPULSES, (j + 1) * IMPULSES);
  const att = world.joints.attached;
  if (a !== 0) {
    att[a] = att[a]! + 1;
    wakeIsland(world, a);
  }
  if (b !== 0) {
    att[b] = att[b]! + 1;
    wakeIsland(world, b);
  }
  world.joints.noCollideJoint[j] = 0;
  if (options.collideConnected !== true) addNoCollide(world.joints, j, a, b);
  return j;
}

/** A revolute, prismatic or wheel joint's checked motor and spring (`checkDrive`). */
interface Drive {
  speed: number;
  maxMotor: number;
  hertz: number;
  zeta: number;
}

/**
 * Checks a joint's motor (finite `motorSpeed`, `maxName` >= 0, the motor on when > 0) and spring
 * (`hertz` and `dampingRatio` >= 0) before anything is made, filling in the given defaults.
 * @throws RangeError `<where>: <param> must be ...` naming the parameter and value.
 */
export function checkDrive(
  where: string,
  motorSpeed: unknown,
  maxMotor: unknown,
  maxName: string,
  hertz: unknown,
  zeta: unknown,
  defaultHertz = 0,
  defaultZeta = 0,
): Drive {
  const speed = motorSpeed ?? 0,
    max = maxMotor ?? 0,
    hz = hertz ?? defaultHertz,
    z = zeta ?? defaultZeta;
  assertFinite(where, 'motorSpeed', speed);
  assertNonNegative(where, maxName, max);
  assertNonNegative(where, 'hertz', hz);
  assertNonNegative(where, 'dampingRatio', z);
  return { speed, maxMotor: max, hertz: hz, zeta: z };
}

/** Writes joint j's limits (when `limit`), motor and spring, and sets its Limit, Motor and Spring flags from them. */
export function storeDrive(world: PhysicsWorld, j: number, limit: boolean, lower: unknown, upper: unknown, d: Drive): void {
  const J = world.components.Joint;
  if (limit) {
    J.lower[j] = lower as number;
    J.upper[j] = upper as number;
  }
  J.motorSpeed[j] = d.speed;
  J.maxMotorForce[j] = d.maxMotor;
  J.hertz[j] = d.hertz;
  J.dampingRatio[j] = d.zeta;
  J.flags[j] = (limit ? JointFlag.Limit : 0) | (d.maxMotor > 0 ? JointFlag.Motor : 0) | (d.hertz > 0 ? JointFlag.Spring : 0);
}

/** Stores `axis` (a world unit vector) in body A's frame at its current angle (the world's frame when `a` is 0). */
export function setAxis(world: PhysicsWorld, j: number, a: number, axis: [number, number]): void {
  const J = world.components.Joint;
  const t = a === 0 ? 0 : world.components.Angle.value[a]!;
  const co = Math.cos(t),
    si = Math.sin(t);
  J.axisX[j] = co * axis[0] + si * axis[1];
  J.axisY[j] = -si * axis[0] + co * axis[1];
}

/** What addPrismaticJoint and addWheelJoint differ in: their name and joint type, the name of the motor's largest force or torque, and the defaults of the axis and the spring. */
export interface AxisJointKind {
  where: string;
  type: JointTypeCode;
  maxName: 'maxMotorForce' | 'maxMotorTorque';
  axis: [number, number];
  hertz: number;
  dampingRatio: number;
}

/** The options of a joint along an axis as addAxisJoint reads them (PrismaticJointOptions, WheelJointOptions; documented there), each checked there. */
type AxisJointOptions = JointBaseOptions &
  Partial<Record<'anchor' | 'axis' | 'lower' | 'upper' | 'motorSpeed' | AxisJointKind['maxName'] | 'hertz' | 'dampingRatio', unknown>>;

/**
 * Adds a joint along an axis (addPrismaticJoint, addWheelJoint): B's anchor stays on the line through A's
 * along `axis` (fixed in A); the travel's limits, a motor of at most the option `kind.maxName` (N for a
 * prismatic joint, N m for a wheel) and a spring along the axis. Checks the bodies, the keys, the anchor, the axis, the
 * limits, then the motor and spring.
 * @returns the joint entity. @throws TypeError | RangeError naming `kind.where` on bad bodies, options or values.
 */
export function addAxisJoint(world: PhysicsWorld, kind: AxisJointKind, options: AxisJointOptions): number {
  const where = kind.where;
  const keys = ['anchor', 'axis', 'lower', 'upper', 'motorSpeed', kind.maxName, 'hertz', 'dampingRatio'];
  const ends = checkEnds2D(where, world, options, keys);
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const axis = unitAxis(where, options.axis, kind.axis);
  const limit = checkLimits(where, options.lower, options.upper, 'lower', 'upper', Infinity);
  const { motorSpeed, hertz, dampingRatio } = options;
  const drive = checkDrive(where, motorSpeed, options[kind.maxName], kind.maxName, hertz, dampingRatio, kind.hertz, kind.dampingRatio);
  const j = makeJoint(world, kind.type, ends, p, p, options);
  setAxis(world, j, ends.a, axis);
  storeDrive(world, j, limit, options.lower, options.upper, drive);
  return currentHandle(world, j);
}

/** The slot of 2D joint `joint`, of one of `types` if given. @throws RangeError naming `where` otherwise. */
export function requireJoint(where: string, world: PhysicsWorld, joint: unknown, types?: readonly JointTypeCode[]): number {
  const J = world.components.Joint;
  const slot = resolveEntity(world, joint, where, 'joint');
  if (world.dimensions !== 2 || !hasComponent(world, slot, J)) {
    throw new RangeError(`${where}: joint must be a joint of this world, got ${describe(joint)} (not a joint)`);
  }
  if (types && !types.includes(J.type[slot] as JointTypeCode)) {
    throw new RangeError(
      `${where}: joint must be a ${types.map((t) => JOINT_TYPE_NAMES[t]).join(' or ')} joint, got a ${JOINT_TYPE_NAMES[J.type[slot]!]} joint`,
    );
  }
  return slot;
}

/** Wakes the islands of a joint's bodies. */
export function wakeJoint(world: PhysicsWorld, j: number): void {
  wakeEnds(world, world.components.Joint.a[j]!, world.components.Joint.b[j]!);
}
