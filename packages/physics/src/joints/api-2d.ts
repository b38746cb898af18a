import { addComponent, entityExists, hasComponent, removeEntity } from 'bitecs';
import { detachClothLink } from '../cloth/solver.js';
import { wakeIsland } from '../islands/sleep.js';
import { createSlot, currentHandle, resolveEntity, SLOT_RANGE } from '../world/handles.js';
import { addNoCollide } from '../world/joint-no-collide.js';
import { ensureJointArrays, IMPULSES } from '../world/joint-state-2d.js';
import { JOINT_TYPE_NAMES, JointFlag, JointType, type JointTypeCode } from '../world/joint-store-2d.js';
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
import { removeJointUnchecked } from './remove.js';

/**
 * Joints between 2D bodies (Box2D v3's set, solved in the contact solver's soft substeps; see
 * joints/solver-2d.ts). Every joint is an entity with a `Joint` component holding its two bodies: A (a
 * body, or the fixed world when omitted or null) and B (a body). Anchors are given in world
 * coordinates where the bodies are when the joint is made; the joint keeps them in the bodies' frames.
 * Removing a body removes its joints. A joint may break: past `breakForce` (N) or `breakTorque` (N m)
 * it is removed and reported in `world.joints.breaks` after the step.
 */

/**
 * Options every joint shares.
 * @category Joints and ropes
 */
export interface JointBaseOptions {
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
   * contacts between two jointed bodies are skipped (both ball and shape colliders), so a hinge's parts
   * may overlap at the hinge; true keeps them colliding. Has no effect when A is the world.
   */
  collideConnected?: boolean;
}

const BASE_KEYS = ['a', 'b', 'breakForce', 'breakTorque', 'collideConnected'] as const;

/** Where a joint's bodies are: slots and poses read for anchors. */
interface Ends {
  a: number;
  b: number;
}

function requireBody(where: string, param: string, world: PhysicsWorld, id: unknown): number {
  const slot = resolveEntity(world, id, where, param);
  const c = world.components;
  if (!hasComponent(world, slot, c.Position) || !hasComponent(world, slot, c.Mass) || !hasComponent(world, slot, c.Angle)) {
    throw new RangeError(`${where}: ${param} must be a body with position, mass and angle (made by addBody), got entity ${describe(id)}`);
  }
  return slot;
}

function checkEnds(where: string, world: PhysicsWorld, options: JointBaseOptions): Ends {
  if (world.dimensions !== 2) throw new RangeError(`${where}: joints need a 2D world, this world has ${world.dimensions} dimensions`);
  if (options === undefined || options === null || typeof options !== 'object') {
    throw new TypeError(`${where}: options must be an object with body b, got ${describe(options)}`);
  }
  const a = options.a === undefined || options.a === null ? 0 : requireBody(where, 'a', world, options.a);
  const b = requireBody(where, 'b', world, options.b);
  if (a === b) throw new RangeError(`${where}: a and b must be different bodies, got ${describe(options.a)} twice`);
  if (options.breakForce !== undefined) assertBreakLimit(where, 'breakForce', options.breakForce);
  if (options.breakTorque !== undefined) assertBreakLimit(where, 'breakTorque', options.breakTorque);
  assertOptionalBoolean(where, 'collideConnected', options.collideConnected);
  return { a, b };
}

/**
 * A break limit: a number > 0, Infinity (the default: never breaks) included. @throws TypeError | RangeError
 * @category Joints and ropes
 */
export function assertBreakLimit(where: string, param: string, value: unknown): void {
  if (typeof value !== 'number') throw new TypeError(`${where}: ${param} must be a number, got ${describe(value)}`);
  if (!(value > 0)) throw new RangeError(`${where}: ${param} must be > 0 (Infinity: never breaks), got ${describe(value)}`);
}

function optionalPoint(where: string, param: string, value: unknown, fallback: [number, number]): [number, number] {
  if (value === undefined) return fallback;
  assertVector(where, param, value, 2);
  return [value[0]!, value[1]!];
}

function centre(world: PhysicsWorld, e: number): [number, number] {
  return [world.components.Position.x[e]!, world.components.Position.y[e]!];
}

function unitAxis(where: string, value: unknown, fallback: [number, number]): [number, number] {
  const v = optionalPoint(where, 'axis', value, fallback);
  const n = Math.hypot(v[0], v[1]);
  if (!(n > 0)) throw new RangeError(`${where}: axis must not be zero, got ${describe(value)}`);
  return [v[0] / n, v[1] / n];
}

function checkLimits(where: string, lower: unknown, upper: unknown, lowerName: string, upperName: string, range: number): boolean {
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

/**
 * Makes the joint entity with every field at its default, and the anchors: `anchorA`, `anchorB` are
 * world points, stored in A's and B's body frames (A's stays a world point if A is the world).
 */
function makeJoint(
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
  J.axisX[j] = 1;
  J.axisY[j] = 0;
  J.length[j] = 0;
  J.minLength[j] = 0;
  J.maxLength[j] = Infinity;
  J.hertz[j] = 0;
  J.dampingRatio[j] = 0;
  J.angularHertz[j] = 0;
  J.angularDampingRatio[j] = 0;
  J.flags[j] = 0;
  J.lower[j] = 0;
  J.upper[j] = 0;
  J.motorSpeed[j] = 0;
  J.maxMotorForce[j] = 0;
  J.maxForce[j] = 0;
  J.breakForce[j] = options.breakForce ?? Infinity;
  J.breakTorque[j] = options.breakTorque ?? Infinity;
  J.breakStretch[j] = Infinity;
  J.force[j] = 0;
  J.torque[j] = 0;
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

/** The handle of the joint in `slot` (what the add functions return). */
function handle(world: PhysicsWorld, slot: number): number {
  return currentHandle(world, slot);
}

/**
 * Options of `addDistanceJoint`.
 * @category Joints and ropes
 */
export interface DistanceJointOptions extends JointBaseOptions {
  /** Anchor on A, world point, m. Default A's centre; required when A is the world. */
  anchorA?: ArrayLike<number>;
  /** Anchor on B, world point, m. Default B's centre. */
  anchorB?: ArrayLike<number>;
  /** Rest length, m, > 0. Default the anchors' distance now. */
  length?: number;
  /** Shortest allowed length, m, in [0, length]. Default `length` for a rod (hertz 0), 0 for a spring. */
  minLength?: number;
  /** Longest allowed length, m, >= length (Infinity allowed). Default `length` for a rod, Infinity for a spring. */
  maxLength?: number;
  /**
   * Spring stiffness as a natural frequency, Hz, >= 0; 0 = no spring. Default 0. A spring of fixed stiffness:
   * its stiffness k = (2 pi hertz)^2 / K_ref is fixed, K_ref = mA + mB + (iA |rA|^2 + iB |rB|^2) / 2 (the anchors' levers rA, rB from the centres), so the spring stores 1/2 k C^2 and a lever's swing does no work on it (with both anchors at the centres it is the frequency of the bodies' relative motion).
   */
  hertz?: number;
  /** Spring damping ratio, >= 0 (1 = critical). Default 0. */
  dampingRatio?: number;
  /** Strain (length - rest) / rest past which the joint breaks (tears), > 0. Default Infinity. */
  breakStretch?: number;
}

/**
 * Adds a distance joint between anchor points of A and B: a rigid rod of `length` (default), a spring
 * of `hertz` and `dampingRatio` toward it (a soft constraint: Catto, "Soft Constraints", GDC 2011),
 * and/or a range [minLength, maxLength] it may not leave: `{ minLength: 0 }` makes a rope link that only
 * pulls. Box2D v3's distance joint.
 * @returns the joint entity.
 * @throws TypeError | RangeError on a missing or removed body, a == b, a 3D world, unknown options,
 *   length <= 0, minLength > length, maxLength < length, negative hertz or damping ratio, breakForce or
 *   breakStretch <= 0, or a full world.
 * @example
 * const rod = addDistanceJoint(world, { b: bob, anchorA: [0, 5] });   // bob swings on a 5 m rod... from [0, 5]
 * @category Joints and ropes
 */
export function addDistanceJoint(world: PhysicsWorld, options: DistanceJointOptions): number {
  const where = 'addDistanceJoint';
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchorA', 'anchorB', 'length', 'minLength', 'maxLength', 'hertz', 'dampingRatio', 'breakStretch'],
    ['a'],
  );
  if (ends.a === 0 && options.anchorA === undefined)
    throw new RangeError(`${where}: anchorA (a world point) is required when a is the world`);
  const pa = optionalPoint(where, 'anchorA', options.anchorA, ends.a === 0 ? [0, 0] : centre(world, ends.a));
  const pb = optionalPoint(where, 'anchorB', options.anchorB, centre(world, ends.b));
  const length = options.length ?? Math.hypot(pb[0] - pa[0], pb[1] - pa[1]);
  assertPositive(where, 'length', length);
  const hertz = options.hertz ?? 0;
  assertNonNegative(where, 'hertz', hertz);
  const zeta = options.dampingRatio ?? 0;
  assertNonNegative(where, 'dampingRatio', zeta);
  const minL = options.minLength ?? (hertz > 0 ? 0 : length);
  const maxL = options.maxLength ?? (hertz > 0 ? Infinity : length);
  assertNonNegative(where, 'minLength', minL);
  if (!(minL <= length)) throw new RangeError(`${where}: minLength must be <= length (${length}), got ${describe(minL)}`);
  if (typeof maxL !== 'number' || Number.isNaN(maxL) || !(maxL >= length))
    throw new RangeError(`${where}: maxLength must be >= length (${length}), got ${describe(maxL)}`);
  if (options.breakStretch !== undefined) assertBreakLimit(where, 'breakStretch', options.breakStretch);
  const j = makeJoint(world, JointType.Distance, ends, pa, pb, options);
  const J = world.components.Joint;
  J.length[j] = length;
  J.minLength[j] = minL;
  J.maxLength[j] = maxL;
  J.hertz[j] = hertz;
  J.dampingRatio[j] = zeta;
  J.flags[j] = (hertz > 0 ? JointFlag.Spring : 0) | (minL < maxL ? JointFlag.Limit : 0);
  J.breakStretch[j] = options.breakStretch ?? Infinity;
  return handle(world, j);
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
function checkDrive(
  where: string,
  motorSpeed: number | undefined,
  maxMotor: number | undefined,
  maxName: string,
  hertz: number | undefined,
  zeta: number | undefined,
  defaultHertz = 0,
  defaultZeta = 0,
): Drive {
  const d: Drive = { speed: motorSpeed ?? 0, maxMotor: maxMotor ?? 0, hertz: hertz ?? defaultHertz, zeta: zeta ?? defaultZeta };
  assertFinite(where, 'motorSpeed', d.speed);
  assertNonNegative(where, maxName, d.maxMotor);
  assertNonNegative(where, 'hertz', d.hertz);
  assertNonNegative(where, 'dampingRatio', d.zeta);
  return d;
}

/** Writes joint j's limits (when `limit`), motor and spring, and sets its Limit, Motor and Spring flags from them. */
function storeDrive(world: PhysicsWorld, j: number, limit: boolean, lower: number | undefined, upper: number | undefined, d: Drive): void {
  const J = world.components.Joint;
  if (limit) {
    J.lower[j] = lower!;
    J.upper[j] = upper!;
  }
  J.motorSpeed[j] = d.speed;
  J.maxMotorForce[j] = d.maxMotor;
  J.hertz[j] = d.hertz;
  J.dampingRatio[j] = d.zeta;
  J.flags[j] = (limit ? JointFlag.Limit : 0) | (d.maxMotor > 0 ? JointFlag.Motor : 0) | (d.hertz > 0 ? JointFlag.Spring : 0);
}

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
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchor', 'lowerAngle', 'upperAngle', 'motorSpeed', 'maxMotorTorque', 'hertz', 'dampingRatio'],
    ['a'],
  );
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const limit = checkLimits(where, options.lowerAngle, options.upperAngle, 'lowerAngle', 'upperAngle', Math.PI);
  const drive = checkDrive(where, options.motorSpeed, options.maxMotorTorque, 'maxMotorTorque', options.hertz, options.dampingRatio);
  const j = makeJoint(world, JointType.Revolute, ends, p, p, options);
  storeDrive(world, j, limit, options.lowerAngle, options.upperAngle, drive);
  return handle(world, j);
}

/**
 * Options of `addPrismaticJoint`.
 * @category Joints and ropes
 */
export interface PrismaticJointOptions extends JointBaseOptions {
  /** Anchor, world point, m (on both bodies). Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Slide direction in the world now (fixed in A afterwards), normalised here. Default (1, 0). */
  axis?: ArrayLike<number>;
  /** Limits of the translation along the axis from now, m, lower <= upper. Both or neither. */
  lower?: number;
  upper?: number;
  /** Motor target speed along the axis, m/s. Default 0. */
  motorSpeed?: number;
  /** Motor's largest force, N, >= 0; on when > 0. Default 0. */
  maxMotorForce?: number;
  /** Spring along the axis toward translation 0, Hz, >= 0. Default 0 (none). Fixed stiffness, as the distance joint's `hertz`. */
  hertz?: number;
  /** Its damping ratio, >= 0. Default 0. */
  dampingRatio?: number;
}

/**
 * Adds a prismatic joint: B slides along `axis` (fixed in A) and does not turn relative to A;
 * optional limits, motor and spring along the axis. Box2D v3's prismatic joint.
 * @returns the joint entity. @throws TypeError | RangeError as `addRevoluteJoint`, and on a zero axis.
 * @category Joints and ropes
 */
export function addPrismaticJoint(world: PhysicsWorld, options: PrismaticJointOptions): number {
  const where = 'addPrismaticJoint';
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchor', 'axis', 'lower', 'upper', 'motorSpeed', 'maxMotorForce', 'hertz', 'dampingRatio'],
    ['a'],
  );
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const axis = unitAxis(where, options.axis, [1, 0]);
  const limit = checkLimits(where, options.lower, options.upper, 'lower', 'upper', Infinity);
  const drive = checkDrive(where, options.motorSpeed, options.maxMotorForce, 'maxMotorForce', options.hertz, options.dampingRatio);
  const j = makeJoint(world, JointType.Prismatic, ends, p, p, options);
  setAxis(world, j, ends.a, axis);
  storeDrive(world, j, limit, options.lower, options.upper, drive);
  return handle(world, j);
}

function setAxis(world: PhysicsWorld, j: number, a: number, axis: [number, number]): void {
  const J = world.components.Joint;
  const t = a === 0 ? 0 : world.components.Angle.value[a]!;
  const co = Math.cos(t),
    si = Math.sin(t);
  J.axisX[j] = co * axis[0] + si * axis[1];
  J.axisY[j] = -si * axis[0] + co * axis[1];
}

/**
 * Options of `addWeldJoint`.
 * @category Joints and ropes
 */
export interface WeldJointOptions extends JointBaseOptions {
  /** Weld point, world, m. Default B's centre. */
  anchor?: ArrayLike<number>;
  /** Linear softness, Hz, >= 0 (0 = rigid). Default 0. */
  hertz?: number;
  /** Its damping ratio, >= 0. Default 0. */
  dampingRatio?: number;
  /** Angular softness, Hz, >= 0 (0 = rigid). Default 0. */
  angularHertz?: number;
  /** Its damping ratio, >= 0. Default 0. */
  angularDampingRatio?: number;
}

/**
 * Adds a weld joint: B is glued to A at `anchor` with their relative angle fixed; soft (a springy
 * beam) when given hertz. Box2D v3's weld joint.
 * @returns the joint entity. @throws TypeError | RangeError on bad bodies, options or values.
 * @category Joints and ropes
 */
export function addWeldJoint(world: PhysicsWorld, options: WeldJointOptions): number {
  const where = 'addWeldJoint';
  const ends = checkEnds(where, world, options);
  assertKnownKeys(where, options, [...BASE_KEYS, 'anchor', 'hertz', 'dampingRatio', 'angularHertz', 'angularDampingRatio'], ['a']);
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const vals = [options.hertz ?? 0, options.dampingRatio ?? 0, options.angularHertz ?? 0, options.angularDampingRatio ?? 0];
  ['hertz', 'dampingRatio', 'angularHertz', 'angularDampingRatio'].forEach((name, i) => {
    assertNonNegative(where, name, vals[i]);
  });
  const j = makeJoint(world, JointType.Weld, ends, p, p, options);
  const J = world.components.Joint;
  J.hertz[j] = vals[0]!;
  J.dampingRatio[j] = vals[1]!;
  J.angularHertz[j] = vals[2]!;
  J.angularDampingRatio[j] = vals[3]!;
  return handle(world, j);
}

/**
 * Options of `addWheelJoint`.
 * @category Joints and ropes
 */
export interface WheelJointOptions extends JointBaseOptions {
  /** Where the wheel is held, world point, m. Default B's (the wheel's) centre. */
  anchor?: ArrayLike<number>;
  /** Suspension direction in the world now (fixed in A), normalised here. Default (0, 1). */
  axis?: ArrayLike<number>;
  /** Suspension spring, Hz, >= 0 (0 = rigid axle). Default 4 Hz. Fixed stiffness, as the distance joint's `hertz`. */
  hertz?: number;
  /** Suspension damping ratio, >= 0. Default 0.7. */
  dampingRatio?: number;
  /** Limits of the suspension travel along the axis, m. Both or neither. */
  lower?: number;
  upper?: number;
  /** Motor target spin of the wheel relative to A, rad/s (counter-clockwise). Default 0. */
  motorSpeed?: number;
  /** Motor's largest torque, N m, >= 0; on when > 0. Default 0. */
  maxMotorTorque?: number;
}

/**
 * Adds a wheel joint: B's anchor stays on the line through A's anchor along `axis`, held by a
 * suspension spring; B spins freely or driven by a motor (a car's wheel on its chassis A). Box2D v3's
 * wheel joint.
 * @returns the joint entity. @throws TypeError | RangeError on bad bodies, options or values.
 * @category Joints and ropes
 */
export function addWheelJoint(world: PhysicsWorld, options: WheelJointOptions): number {
  const where = 'addWheelJoint';
  const ends = checkEnds(where, world, options);
  assertKnownKeys(
    where,
    options,
    [...BASE_KEYS, 'anchor', 'axis', 'hertz', 'dampingRatio', 'lower', 'upper', 'motorSpeed', 'maxMotorTorque'],
    ['a'],
  );
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const axis = unitAxis(where, options.axis, [0, 1]);
  const limit = checkLimits(where, options.lower, options.upper, 'lower', 'upper', Infinity);
  const drive = checkDrive(
    where,
    options.motorSpeed,
    options.maxMotorTorque,
    'maxMotorTorque',
    options.hertz,
    options.dampingRatio,
    4,
    0.7,
  );
  const j = makeJoint(world, JointType.Wheel, ends, p, p, options);
  setAxis(world, j, ends.a, axis);
  storeDrive(world, j, limit, options.lower, options.upper, drive);
  return handle(world, j);
}

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
  if (options === null || typeof options !== 'object') throw new TypeError(`${where}: options must be an object, got ${describe(options)}`);
  assertKnownKeys(where, options, ['b', 'anchor', 'target', 'hertz', 'dampingRatio', 'maxForce', 'breakForce']);
  const ends = checkEnds(where, world, { b: options.b, ...(options.breakForce !== undefined ? { breakForce: options.breakForce } : {}) });
  const C = world.components;
  if (hasComponent(world, ends.b, C.Static) || hasComponent(world, ends.b, C.Kinematic) || !(C.Mass.inv[ends.b]! > 0)) {
    throw new RangeError(`${where}: b must be a dynamic body (a static or kinematic body cannot be dragged), got ${describe(options.b)}`);
  }
  const p = optionalPoint(where, 'anchor', options.anchor, centre(world, ends.b));
  const target = optionalPoint(where, 'target', options.target, p);
  const hertz = options.hertz ?? 5;
  assertPositive(where, 'hertz', hertz);
  const zeta = options.dampingRatio ?? 0.7;
  assertNonNegative(where, 'dampingRatio', zeta);
  const maxForce = options.maxForce ?? 1000 * world.components.Mass.value[ends.b]!;
  assertPositive(where, 'maxForce', maxForce);
  const j = makeJoint(world, JointType.Mouse, ends, target, p, { b: ends.b, breakForce: options.breakForce });
  const J = world.components.Joint;
  J.hertz[j] = hertz;
  J.dampingRatio[j] = zeta;
  J.maxForce[j] = maxForce;
  J.flags[j] = JointFlag.Spring;
  return handle(world, j);
}

function requireJoint(where: string, world: PhysicsWorld, joint: unknown, types?: readonly JointTypeCode[]): number {
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

function wakeJoint(world: PhysicsWorld, j: number): void {
  const J = world.components.Joint;
  if (J.a[j] !== 0) wakeIsland(world, J.a[j]!);
  wakeIsland(world, J.b[j]!);
}

/**
 * Whether `id` is the handle of a live joint (or cloth link) of this world.
 * @category Joints and ropes
 */
export function isJoint(world: PhysicsWorld, id: number): boolean {
  if (world.dimensions !== 2 || typeof id !== 'number' || !Number.isInteger(id) || id < 1) return false;
  const slot = id % SLOT_RANGE;
  if (slot < 1 || slot > world.capacity || !entityExists(world, slot) || currentHandle(world, slot) !== id) return false;
  return hasComponent(world, slot, world.components.Joint) || hasComponent(world, slot, world.components.ClothLink);
}

/**
 * Removes a joint or a cloth link (the bodies of a joint wake).
 * @throws RangeError if `joint` is not the handle of a live joint or cloth link.
 * @category Joints and ropes
 */
export function removeJoint(world: PhysicsWorld, joint: number): void {
  const slot = resolveEntity(world, joint, 'removeJoint', 'joint');
  if (world.dimensions === 2 && hasComponent(world, slot, world.components.ClothLink)) {
    detachClothLink(world, slot);
    removeEntity(world, slot);
    return;
  }
  removeJointUnchecked(world, requireJoint('removeJoint', world, joint));
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
 * Sets a joint's motor: target `speed` (rad/s for revolute and wheel, m/s for prismatic) and largest
 * torque (N m) or force (N) `maxForce`, >= 0; 0 turns the motor off.
 * @throws RangeError if `joint` is not a live revolute, prismatic or wheel joint, or on bad values.
 * @category Joints and ropes
 */
export function setJointMotor(world: PhysicsWorld, joint: number, speed: number, maxForce: number): void {
  const where = 'setJointMotor';
  const j = requireJoint(where, world, joint, [JointType.Revolute, JointType.Prismatic, JointType.Wheel]);
  assertFinite(where, 'speed', speed);
  assertNonNegative(where, 'maxForce', maxForce);
  const J = world.components.Joint;
  J.motorSpeed[j] = speed;
  J.maxMotorForce[j] = maxForce;
  J.flags[j] = maxForce > 0 ? J.flags[j]! | JointFlag.Motor : J.flags[j]! & ~JointFlag.Motor;
  if (maxForce === 0) world.joints.impulses[j * IMPULSES + 4] = 0;
  wakeJoint(world, j);
}

/**
 * Sets (or with `lower` null, removes) a joint's limits: revolute angles, rad in [-pi, pi]; prismatic
 * and wheel translations, m; lower <= upper.
 * @throws RangeError if `joint` is not a live revolute, prismatic or wheel joint, or on bad limits.
 * @category Joints and ropes
 */
export function setJointLimits(world: PhysicsWorld, joint: number, lower: number | null, upper?: number): void {
  const where = 'setJointLimits';
  const j = requireJoint(where, world, joint, [JointType.Revolute, JointType.Prismatic, JointType.Wheel]);
  const J = world.components.Joint;
  const base = j * IMPULSES;
  world.joints.impulses[base + 5] = 0;
  world.joints.impulses[base + 6] = 0;
  if (lower === null) {
    J.flags[j] = J.flags[j]! & ~JointFlag.Limit;
    wakeJoint(world, j);
    return;
  }
  checkLimits(where, lower, upper, 'lower', 'upper', J.type[j] === JointType.Revolute ? Math.PI : Infinity);
  J.lower[j] = lower;
  J.upper[j] = upper!;
  J.flags[j] = J.flags[j]! | JointFlag.Limit;
  wakeJoint(world, j);
}

/**
 * Sets a joint's spring: natural frequency `hertz` (Hz, >= 0; 0 removes the spring, or makes a weld's
 * linear part or a distance joint rigid) and `dampingRatio` (>= 0). Mouse joints need hertz > 0.
 * @throws RangeError if `joint` is not a live joint, or on bad values.
 * @category Joints and ropes
 */
export function setJointSpring(world: PhysicsWorld, joint: number, hertz: number, dampingRatio: number): void {
  const where = 'setJointSpring';
  const j = requireJoint(where, world, joint);
  const J = world.components.Joint;
  if (J.type[j] === JointType.Mouse) assertPositive(where, 'hertz', hertz);
  else assertNonNegative(where, 'hertz', hertz);
  assertNonNegative(where, 'dampingRatio', dampingRatio);
  J.hertz[j] = hertz;
  J.dampingRatio[j] = dampingRatio;
  if (J.type[j] !== JointType.Weld && J.type[j] !== JointType.Mouse) {
    J.flags[j] = hertz > 0 ? J.flags[j]! | JointFlag.Spring : J.flags[j]! & ~JointFlag.Spring;
  }
  world.joints.impulses[j * IMPULSES + 3] = 0;
  wakeJoint(world, j);
}

/**
 * The current length of a distance joint (distance between its anchors), m.
 * @throws RangeError if `joint` is not a live distance joint.
 * @category Joints and ropes
 */
export function jointLength(world: PhysicsWorld, joint: number): number {
  const j = requireJoint('jointLength', world, joint, [JointType.Distance]);
  const [ax, ay, bx, by] = anchorsOf(world, j);
  return Math.hypot(bx - ax, by - ay);
}

/**
 * The relative angle of a revolute or weld joint: angle of B minus angle of A minus the angle between
 * them when the joint was made, rad, wrapped into [-pi, pi].
 * @throws RangeError if `joint` is not a live revolute or weld joint.
 * @category Joints and ropes
 */
export function jointAngle(world: PhysicsWorld, joint: number): number {
  const j = requireJoint('jointAngle', world, joint, [JointType.Revolute, JointType.Weld]);
  const J = world.components.Joint,
    ang = world.components.Angle.value;
  let x = (J.b[j] === 0 ? 0 : ang[J.b[j]!]!) - (J.a[j] === 0 ? 0 : ang[J.a[j]!]!) - J.referenceAngle[j]!;
  x -= 2 * Math.PI * Math.round(x / (2 * Math.PI));
  return x;
}

/**
 * The world positions of a joint's two anchors, m: [ax, ay, bx, by] (A's is the fixed point or the
 * mouse target when A is the world). @throws RangeError if `joint` is not a live joint.
 * @category Joints and ropes
 */
export function jointAnchors(world: PhysicsWorld, joint: number): [number, number, number, number] {
  return anchorsOf(world, requireJoint('jointAnchors', world, joint));
}

function anchorsOf(world: PhysicsWorld, j: number): [number, number, number, number] {
  const J = world.components.Joint,
    P = world.components.Position,
    ang = world.components.Angle.value;
  const point = (e: number, lx: number, ly: number): [number, number] => {
    if (e === 0) return [lx, ly];
    const co = Math.cos(ang[e]!),
      si = Math.sin(ang[e]!);
    return [P.x[e]! + co * lx - si * ly, P.y[e]! + si * lx + co * ly];
  };
  const a = point(J.a[j]!, J.localAx[j]!, J.localAy[j]!),
    b = point(J.b[j]!, J.localBx[j]!, J.localBy[j]!);
  return [a[0], a[1], b[0], b[1]];
}
