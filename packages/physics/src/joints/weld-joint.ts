import { JointType } from '../world/joint-store-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { assertKnownKeys, assertNonNegative } from '../world/validate.js';
import { BASE_KEYS, centre, checkEnds, handle, type JointBaseOptions, makeJoint, optionalPoint } from './joint-2d.js';

/**
 * The 2D weld joint (glues two bodies, rigidly or as linear and angular springs): its options and
 * addWeldJoint. Its rows are prepared, solved and finished with the other 2D joints' (joints/prepare-2d.ts,
 * solve-2d.ts, finish-2d.ts).
 */

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
