import { type PhysicsWorld, resolveEntity } from '@bitphysics/physics';

/**
 * The slot (store index) of the live entity `eid` of `world`, where `eid` is a handle as the physics
 * API returns it (see @bitphysics/physics' handles: slot + generation * 2^25). The renderers'
 * per-entity methods (setColor, colorOf, ...) resolve their argument with it, so a removed entity's
 * handle is refused even after its slot holds a new entity.
 * @throws RangeError `<where>: eid refers to a removed entity (...)` or `<where>: eid must be an entity of this world ..., got <eid>`.
 */
export function entitySlot(where: string, world: PhysicsWorld, eid: unknown): number {
  return resolveEntity(world, eid, where, 'eid');
}

/**
 * Throws unless `eid` is the handle of a live entity of `world` (see `entitySlot`, which also returns
 * its slot).
 * @throws RangeError as entitySlot.
 */
export function assertLiveEntity(where: string, world: PhysicsWorld, eid: unknown): asserts eid is number {
  entitySlot(where, world, eid);
}
