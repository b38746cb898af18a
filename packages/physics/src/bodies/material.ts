import { assertInRange, assertInteger, assertNonNegative } from '../validation/validate.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * A collider's surface options, shared by everything that collides: its material (restitution and
 * friction, the Material component) and, for shapes, its collision filter (Box2D's b2Filter).
 */

/**
 * Surface material fields (the Material component). Where a body, shape, segment, plane or boundary
 * is made, an omitted field takes its default (restitution 0, friction 0.6, static friction equal to
 * friction); in `setMaterial` an omitted field keeps its value.
 * @category Bodies
 */
export interface MaterialOptions {
  /** Restitution in [0, 1]: the ratio of separating to approaching normal speed. Default 0. */
  restitution?: number;
  /** Kinetic friction coefficient mu_k >= 0 (also sets static friction unless that is given). Default 0.6. */
  friction?: number;
  /** Static friction coefficient mu_s >= 0, used while a contact sticks. Default equal to `friction`. */
  staticFriction?: number;
}

/**
 * Checks the material fields that are given: restitution in [0, 1], frictions >= 0.
 * @param where the public function the caller was called as, named in the message.
 * @throws RangeError `<where>: <field> must be ...` naming the first bad field.
 */
export function assertMaterial(where: string, m: MaterialOptions): void {
  if (m.restitution !== undefined) assertInRange(where, 'restitution', m.restitution, 0, 1);
  if (m.friction !== undefined) assertNonNegative(where, 'friction', m.friction);
  if (m.staticFriction !== undefined) assertNonNegative(where, 'staticFriction', m.staticFriction);
}

/**
 * Writes the given material fields (already checked) into entity `eid`'s Material component; a
 * friction without a static friction sets both, as Box2D's single friction does.
 */
export function writeMaterial(world: PhysicsWorld, eid: number, m: MaterialOptions): void {
  const M = world.components.Material;
  if (m.restitution !== undefined) M.restitution[eid] = m.restitution;
  if (m.friction !== undefined) {
    M.friction[eid] = m.friction;
    M.staticFriction[eid] = m.friction;
  }
  if (m.staticFriction !== undefined) M.staticFriction[eid] = m.staticFriction;
}

/**
 * A shape's collision filter (Box2D's b2Filter): two shapes collide if each one's category is in the
 * other's mask, unless they share a non-zero group, which decides alone.
 * @category Shapes
 */
export interface FilterOptions {
  /** Category bits, integer in [0, 2^32 - 1]. Default 1. */
  category?: number;
  /** Mask bits: the categories this shape collides with, integer in [0, 2^32 - 1]. Default 0xFFFFFFFF (all). */
  mask?: number;
  /** Group, integer in [-2^31, 2^31 - 1]: shapes of the same non-zero group always collide (> 0) or never (< 0). Default 0. */
  group?: number;
}

/**
 * Checks the filter fields that are given: category and mask integers in [0, 2^32 - 1], group in
 * [-2^31, 2^31 - 1].
 * @param where the public function the caller was called as, named in the message.
 * @throws RangeError | TypeError `<where>: <field> must be ...` naming the first bad field.
 */
export function assertFilter(where: string, f: FilterOptions): void {
  if (f.category !== undefined) assertInteger(where, 'category', f.category, 0, 0xffffffff);
  if (f.mask !== undefined) assertInteger(where, 'mask', f.mask, 0, 0xffffffff);
  if (f.group !== undefined) assertInteger(where, 'group', f.group, -0x80000000, 0x7fffffff);
}
