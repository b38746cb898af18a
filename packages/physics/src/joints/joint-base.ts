import { hasComponent } from 'bitecs';
import { wakeIsland } from '../islands/sleep.js';
import * as check from '../validation/validate.js';
import { resolveEntity } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * What every joint shares, 2D and 3D: the options of its two bodies, breaking and collisions, their
 * checks, an optional anchor point, waking its bodies, and the checks of a distance joint's anchors,
 * length, spring and limits.
 */

/**
 * Options every joint shares (2D and 3D).
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
   * contacts between two jointed bodies are skipped (every collider of both), so their shapes may
   * overlap at the joint (a hinge's parts, a welded L, a ragdoll's limbs) without the contact and the
   * joint fighting; true keeps them colliding. Has no effect when A is the world.
   */
  collideConnected?: boolean;
}

/** The option keys every joint takes (JointBaseOptions), for each add call's check of unknown keys. */
export const BASE_KEYS = ['a', 'b', 'breakForce', 'breakTorque', 'collideConnected'] as const;

/** A joint's bodies: entity slots, 0 for the fixed world. */
export interface Ends {
  a: number;
  b: number;
}

/**
 * A break limit: a number > 0, Infinity (the default: never breaks) included; `never` is the message's
 * name for Infinity. @throws TypeError | RangeError naming `where`, `param` and the value.
 * @category Joints and ropes
 */
export function assertBreakLimit(where: string, param: string, value: unknown, never = 'never breaks'): void {
  if (typeof value !== 'number') throw new TypeError(`${where}: ${param} must be a number, got ${check.describe(value)}`);
  if (!(value > 0)) throw new RangeError(`${where}: ${param} must be > 0 (Infinity: ${never}), got ${check.describe(value)}`);
}

/** The slot of body `id` (param `param` of `where`): an entity with position, mass and an angle (2D) or orientation (3D). @throws RangeError otherwise. */
function requireBody(where: string, param: string, world: PhysicsWorld, id: unknown, dims: 2 | 3): number {
  const slot = resolveEntity(world, id, where, param);
  const c = world.components;
  if (
    !hasComponent(world, slot, c.Position) ||
    !hasComponent(world, slot, c.Mass) ||
    !hasComponent(world, slot, dims === 2 ? c.Angle : c.Orientation)
  ) {
    throw new RangeError(
      dims === 2
        ? `${where}: ${param} must be a body with position, mass and angle (made by addBody), got entity ${check.describe(id)}`
        : `${where}: ${param} must be a 3D body with position, mass and orientation (addBody, addShape3D), got entity ${check.describe(id)}`,
    );
  }
  return slot;
}

/**
 * Checks a joint's world (of `dims` dimensions), its options object, the option keys (`keys` besides
 * JointBaseOptions', when given), its `a` and `b` (a may be omitted or null: the world), its break
 * limits and collideConnected; returns the bodies' slots.
 * @throws TypeError | RangeError naming `where`, the parameter and the value.
 */
export function checkEnds(where: string, world: PhysicsWorld, options: JointBaseOptions, dims: 2 | 3, keys?: readonly string[]): Ends {
  if (world.dimensions !== dims) {
    const what = dims === 2 ? 'joints need a 2D' : '3D joints need a 3D';
    throw new RangeError(`${where}: ${what} world, this world has ${world.dimensions} dimensions`);
  }
  if (options === undefined || options === null || typeof options !== 'object') {
    throw new TypeError(`${where}: options must be an object with body b, got ${check.describe(options)}`);
  }
  if (keys !== undefined) check.assertKnownKeys(where, options, [...BASE_KEYS, ...keys], ['a']);
  const a = options.a === undefined || options.a === null ? 0 : requireBody(where, 'a', world, options.a, dims);
  const b = requireBody(where, 'b', world, options.b, dims);
  if (a === b) throw new RangeError(`${where}: a and b must be different bodies, got ${check.describe(options.a)} twice`);
  if (options.breakForce !== undefined) assertBreakLimit(where, 'breakForce', options.breakForce);
  if (options.breakTorque !== undefined) assertBreakLimit(where, 'breakTorque', options.breakTorque);
  check.assertOptionalBoolean(where, 'collideConnected', options.collideConnected);
  return { a, b };
}

/**
 * `value` as a point of `fallback`'s dimensions (2 or 3 numbers, world, m), or `fallback` when undefined.
 * @throws TypeError | RangeError naming `where` and `param` on a malformed vector.
 */
export function optionalPoint<P extends [number, number] | [number, number, number]>(
  where: string,
  param: string,
  value: unknown,
  fallback: P,
): P {
  if (value === undefined) return fallback;
  check.assertVector(where, param, value, fallback.length);
  return (fallback.length === 2 ? [value[0]!, value[1]!] : [value[0]!, value[1]!, value[2]!]) as P;
}

/** Wakes the islands of a joint's bodies `a` and `b` (entity slots; 0, the fixed world, has none). */
export function wakeEnds(world: PhysicsWorld, a: number, b: number): void {
  if (a !== 0) wakeIsland(world, a);
  if (b !== 0) wakeIsland(world, b);
}

/** The options of a distance joint that checkDistance reads (DistanceJointOptions, DistanceJoint3DOptions; documented there). */
type DistanceShapeOptions = Partial<
  Record<'anchorA' | 'anchorB', unknown> & Record<'length' | 'minLength' | 'maxLength' | 'hertz' | 'dampingRatio', number>
>;

/** A distance joint's checked anchors pa, pb (world, m), rest length and limits (m) and spring (hertz, Hz; zeta, its damping ratio). */
export type DistanceShape<P> = { pa: P; pb: P } & Record<'length' | 'minLength' | 'maxLength' | 'hertz' | 'zeta', number>;

/**
 * Checks the options of a 2D or 3D distance joint with body A `a` (0: the world): its anchors (default
 * the centres `centreA`, `centreB`; anchorA required when A is the world), its rest length (> 0, default
 * the anchors' distance), its spring (hertz and dampingRatio >= 0, default 0) and its limits
 * (lengthLimits).
 * @throws TypeError | RangeError naming `where`, the parameter and the value.
 */
export function checkDistance<P extends [number, number] | [number, number, number]>(
  where: string,
  options: DistanceShapeOptions,
  a: number,
  centreA: P,
  centreB: P,
): DistanceShape<P> {
  if (a === 0 && options.anchorA === undefined) throw new RangeError(`${where}: anchorA (a world point) is required when a is the world`);
  const pa = optionalPoint(where, 'anchorA', options.anchorA, centreA);
  const pb = optionalPoint(where, 'anchorB', options.anchorB, centreB);
  const length = check.optionOr(where, 'length', options.length, Math.hypot(...pb.map((v, i) => v - pa[i]!)), check.assertPositive);
  const hertz = check.optionOr(where, 'hertz', options.hertz, 0, check.assertNonNegative);
  const zeta = check.optionOr(where, 'dampingRatio', options.dampingRatio, 0, check.assertNonNegative);
  const [minLength, maxLength] = lengthLimits(where, length, hertz > 0, options.minLength, options.maxLength);
  return { pa, pb, length, minLength, maxLength, hertz, zeta };
}

/**
 * A distance joint's limits [minLength, maxLength] around its rest `length` (m, already checked > 0):
 * as given, or by default both `length` (a rod) without a spring, 0 and Infinity with one.
 * @throws RangeError naming `where` unless 0 <= minLength <= length <= maxLength.
 */
export function lengthLimits(where: string, length: number, spring: boolean, minLength: unknown, maxLength: unknown): [number, number] {
  const minL = minLength ?? (spring ? 0 : length),
    maxL = maxLength ?? (spring ? Infinity : length);
  check.assertNonNegative(where, 'minLength', minL);
  if (!(minL <= length)) throw new RangeError(`${where}: minLength must be <= length (${length}), got ${check.describe(minL)}`);
  if (typeof maxL !== 'number' || Number.isNaN(maxL) || !(maxL >= length))
    throw new RangeError(`${where}: maxLength must be >= length (${length}), got ${check.describe(maxL)}`);
  return [minL, maxL];
}
