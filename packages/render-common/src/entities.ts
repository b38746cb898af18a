import { entityExists, type PhysicsWorld } from '@bitphysics/physics';
import { describe } from '@bitphysics/physics/validate';

/**
 * Throws unless `eid` is the id of a live entity of `world`: an integer in [1, world.capacity] that
 * bitecs knows as alive. The renderers' per-entity methods (setColor, colorOf, ...) check their
 * argument with it.
 * @throws RangeError `<where>: eid must be a live entity id of the world, got <eid>`.
 */
export function assertLiveEntity(where: string, world: PhysicsWorld, eid: unknown): asserts eid is number {
  if (typeof eid !== 'number' || !Number.isInteger(eid) || eid < 1 || eid > world.capacity || !entityExists(world, eid)) {
    throw new RangeError(`${where}: eid must be a live entity id of the world, got ${describe(eid)}`);
  }
}
