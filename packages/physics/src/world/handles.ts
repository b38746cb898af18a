import { addEntity, entityExists, hasComponent } from 'bitecs';
import { describe } from '../validation/validate.js';
import type { PhysicsWorld } from './options.js';

/**
 * Generational entity handles: what the public API hands out and accepts.
 *
 * Inside a world an entity is its *slot*: bitecs' plain id, an integer in [1, capacity]. Stores are
 * indexed by slot (`world.components.Position.x[slot]`), `query()` returns slots and every system
 * works on slots. bitecs reuses a removed entity's slot for the next entity created, so a slot alone
 * cannot tell an old entity from a new one. A *handle* can:
 *
 *   handle = slot + generation * 2^25,
 *
 * where generation counts the earlier lives of that slot (`world.spawnStamp[slot] - 1`, modulo 2^28 so
 * a handle stays an exact integer below 2^53). A slot needs 25 bits because capacity <= 2^24 and
 * slots start at 1. On a slot's first life the handle equals the slot, so code that indexes stores with
 * a handle keeps working there; after the slot is recycled the old handle is refused by every API
 * function ("refers to a removed entity") instead of acting on the new entity.
 *
 * The rule: index stores with `slotOf(handle)`; `query()` gives slots; `handleOf(world, slot)` turns a
 * slot back into the handle the API accepts. Same design as Rapier's and Box2D v3's ids (index plus
 * generation).
 */

/**
 * 2^25: a slot fits below it (capacity <= 2^24, slots start at 1).
 * @category Bodies
 */
export const SLOT_RANGE = 33_554_432;

/** Generations wrap at 2^28 so slot + generation * 2^25 stays below 2^53 (an exact integer). */
const GENERATIONS = 268_435_456;

/**
 * The slot (store index) of an entity handle: handle mod 2^25. Pure arithmetic; it does not check
 * that the entity is alive (see `isAlive`).
 * @param handle an entity handle as returned by addBody, addParticle, createEntity, ...
 * @returns an integer in [0, 2^25).
 * @category Bodies
 */
export function slotOf(handle: number): number {
  return handle % SLOT_RANGE;
}

/**
 * The handle of the entity that lives in `slot` now (e.g. a slot from `query()`), for API calls.
 * @throws RangeError if no entity lives in that slot.
 * @category Bodies
 */
export function handleOf(world: PhysicsWorld, slot: number): number {
  if (typeof slot !== 'number' || !Number.isInteger(slot) || slot < 1 || slot > world.capacity || !entityExists(world, slot)) {
    throw new RangeError(`handleOf: slot must be the slot of a live entity (an integer in [1, ${world.capacity}]), got ${describe(slot)}`);
  }
  return currentHandle(world, slot);
}

/**
 * Handle of the live entity in `slot` (no checks).
 * @category Bodies
 */
export function currentHandle(world: PhysicsWorld, slot: number): number {
  return slot + ((world.spawnStamp[slot]! - 1) % GENERATIONS) * SLOT_RANGE;
}

/**
 * Whether `handle` names an entity that is alive in `world` now (false for a removed entity, even if its slot was reused).
 * @category Bodies
 */
export function isAlive(world: PhysicsWorld, handle: number): boolean {
  if (typeof handle !== 'number' || !Number.isInteger(handle) || handle < 1) return false;
  const slot = handle % SLOT_RANGE;
  if (slot < 1 || slot > world.capacity || !entityExists(world, slot)) return false;
  return currentHandle(world, slot) === handle;
}

/**
 * The slot of the live entity `handle`, for API functions: the one place a handle is resolved.
 * @param where the function the user called (named in the error).
 * @param param the parameter that holds the handle.
 * @throws RangeError `<where>: <param> refers to a removed entity (id N, slot S now holds handle H)` when the
 *   entity was removed (its slot empty or reused), or `<where>: <param> must be an entity of this world, got V`
 *   when the value is not a handle at all.
 * @category Bodies
 */
export function resolveEntity(world: PhysicsWorld, handle: unknown, where: string, param = 'entity'): number {
  if (typeof handle !== 'number' || !Number.isInteger(handle) || handle < 1) {
    throw new RangeError(`${where}: ${param} must be an entity of this world (a handle returned by the API), got ${describe(handle)}`);
  }
  const slot = handle % SLOT_RANGE;
  if (slot < 1 || slot > world.capacity) {
    throw new RangeError(`${where}: ${param} must be an entity of this world (a handle returned by the API), got ${describe(handle)}`);
  }
  if (!entityExists(world, slot)) {
    if (world.spawnStamp[slot]! === 0) {
      throw new RangeError(`${where}: ${param} must be an entity of this world (a handle returned by the API), got ${describe(handle)}`);
    }
    throw new RangeError(`${where}: ${param} refers to a removed entity (id ${handle}, slot ${slot} is empty)`);
  }
  const now = currentHandle(world, slot);
  if (now !== handle) {
    if (handle > now) {
      throw new RangeError(`${where}: ${param} must be an entity of this world (a handle returned by the API), got ${describe(handle)}`);
    }
    throw new RangeError(`${where}: ${param} refers to a removed entity (id ${handle}, slot ${slot} now holds handle ${now})`);
  }
  return slot;
}

/**
 * What an API function needs of its entity. `body`: a moving thing (Position and Velocity: bodies,
 * particles, moving emitters); `emitter`, `electric-field`, `magnetic-field`, `fluid-region`, `spring`:
 * entities made by addEmitter, addElectricField, addMagneticField, addFluidRegion, addSpring.
 * @category Bodies
 */
export type EntityKind = 'body' | 'emitter' | 'electric-field' | 'magnetic-field' | 'fluid-region' | 'spring' | 'collider';

const KIND_NAMES: Record<EntityKind, string> = {
  body: 'a body (it needs Position and Velocity; addBody or addParticle make one)',
  emitter: 'an emitter (addEmitter makes one)',
  'electric-field': 'an electric field (addElectricField makes one)',
  'magnetic-field': 'a magnetic field (addMagneticField makes one)',
  'fluid-region': 'a fluid region (addFluidRegion makes one)',
  spring: 'a spring (addSpring makes one)',
  collider: 'a body, segment or plane',
};

/**
 * Short description of what the entity in `slot` is, for error messages.
 * @category Bodies
 */
export function kindOf(world: PhysicsWorld, slot: number): string {
  const c = world.components;
  const has = (x: object) => hasComponent(world, slot, x);
  if (has(c.Emitter)) return has(c.Velocity) && !has(c.Kinematic) ? 'a body carrying an emitter' : 'an emitter';
  if (has(c.Position) && has(c.Velocity)) return 'a body';
  if (has(c.Segment)) return 'a segment';
  if (has(c.Plane)) return 'a plane';
  if (has(c.ElectricField)) return 'an electric field';
  if (has(c.MagneticField)) return 'a magnetic field';
  if (has(c.FluidRegion)) return 'a fluid region';
  if (has(c.Spring)) return 'a spring';
  return 'an entity with no physics components';
}

/**
 * Whether the entity in `slot` is of `kind` (see EntityKind).
 * @category Bodies
 */
function isKind(world: PhysicsWorld, slot: number, kind: EntityKind): boolean {
  const c = world.components;
  switch (kind) {
    case 'body':
      return hasComponent(world, slot, c.Position) && hasComponent(world, slot, c.Velocity);
    case 'emitter':
      return hasComponent(world, slot, c.Emitter);
    case 'electric-field':
      return hasComponent(world, slot, c.ElectricField);
    case 'magnetic-field':
      return hasComponent(world, slot, c.MagneticField);
    case 'fluid-region':
      return hasComponent(world, slot, c.FluidRegion);
    case 'spring':
      return hasComponent(world, slot, c.Spring);
    case 'collider':
      return (
        (hasComponent(world, slot, c.Position) && hasComponent(world, slot, c.Velocity)) ||
        hasComponent(world, slot, c.Segment) ||
        hasComponent(world, slot, c.Plane)
      );
  }
}

/**
 * `resolveEntity`, then checks the entity is of `kind`.
 * @returns the entity's slot.
 * @throws RangeError as resolveEntity, or `<where>: <param> must be <kind>, got <what it is> (id N)`.
 * @category Bodies
 */
export function resolveKind(world: PhysicsWorld, handle: unknown, kind: EntityKind, where: string, param = 'entity'): number {
  const slot = resolveEntity(world, handle, where, param);
  if (!isKind(world, slot, kind)) {
    throw new RangeError(`${where}: ${param} must be ${KIND_NAMES[kind]}, got ${kindOf(world, slot)} (id ${handle as number})`);
  }
  return slot;
}

/**
 * Throws unless the world has room for one more entity. Creating functions call it before they change
 * anything, so a full world leaves no trace of the refused call.
 * @param where the function the user called.
 * @throws RangeError `<where>: the world is full (capacity N entities); ...`.
 * @category Bodies
 */
export function assertRoom(world: PhysicsWorld, where: string): void {
  if (world.entityIndex.aliveCount >= world.capacity) {
    throw new RangeError(
      `${where}: the world is full (capacity ${world.capacity} entities); remove entities or create the world with a larger capacity`,
    );
  }
}

/**
 * Internal: adds an empty entity and returns its slot (store index), counting its life in
 * `world.spawnStamp`. The public functions return `currentHandle(world, slot)`.
 * @throws RangeError (naming `where`) if the world is full.
 * @category Bodies
 */
export function createSlot(world: PhysicsWorld, where: string): number {
  assertRoom(world, where);
  const slot = addEntity(world);
  world.spawnStamp[slot] = world.spawnStamp[slot]! + 1;
  return slot;
}
