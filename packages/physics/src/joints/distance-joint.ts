import { JointFlag, JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { assertKnownKeys, assertNonNegative, assertPositive, describe } from '../world/validate.js';
import { assertBreakLimit, BASE_KEYS, centre, checkEnds, handle, type JointBaseOptions, makeJoint, optionalPoint } from './joint-2d.js';

/**
 * The 2D distance joint (a rod, a rope or a spring between two anchors): its options and addDistanceJoint.
 * Its rows are prepared, solved and finished with the other 2D joints' (joints/prepare-2d.ts, solve-2d.ts,
 * finish-2d.ts).
 */

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
