import { entityExists, hasComponent, removeEntity } from 'bitecs';
import { ecsOf } from '../world/ecs-internals.js';
import { registerExternalWorldState } from '../world/external-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { archetypes, killSlot } from './archetype.js';
import { maxSpawnsPerStep, type ParticleBirthHook, type ParticleDeathHook } from './emitter-options.js';

/** The particle book of a world: its live particles in spawn order (the FIFO that recycle-oldest uses), the lifetime system's scratch, and the death and birth hooks. */

export interface ParticleBook {
  /** FIFO of spawned particles (eid and spawn stamp), oldest at head; stale entries skipped. */
  ids: Int32Array;
  stamps: Uint32Array;
  head: number;
  count: number;
  hooks: ParticleDeathHook[];
  /** Hooks run for every particle born (`onParticleBirth`). */
  birthHooks: ParticleBirthHook[];
  /**
   * Scratch: expired particles this step and their spawn stamps, and bursts to spawn (x, y, z, vx, vy,
   * vz, emitter, count, generation).
   */
  expired: Int32Array;
  expiredStamps: Uint32Array;
  bursts: Float64Array;
  burstCount: number;
  /** Spawns left this step (`maxSpawnsPerStep`), and the step (`world.steps`) it belongs to. */
  budget: number;
  budgetStep: number;
  /** Particles whose lifetime ran out, removed by `lifetimeSystem`, since the world was made. */
  expiredTotal: number;
}

/**
 * The particle book of `world` if it has one (`world.features.particles`).
 * @category Particles
 */
export function bookOf(world: PhysicsWorld): ParticleBook | undefined {
  return world.features.particles as ParticleBook | undefined;
}

/**
 * The particle book of `world`, made on first use.
 * @category Particles
 */
export function book(world: PhysicsWorld): ParticleBook {
  let b = bookOf(world);
  if (!b) {
    const n = world.capacity + 1;
    b = {
      // Twice the capacity: the FIFO holds the gone particles too until they reach its head or it is compacted.
      ids: new Int32Array(2 * n),
      stamps: new Uint32Array(2 * n),
      head: 0,
      count: 0,
      hooks: [],
      birthHooks: [],
      expired: new Int32Array(n),
      expiredStamps: new Uint32Array(n),
      bursts: new Float64Array(9 * 64),
      burstCount: 0,
      budget: maxSpawnsPerStep(world),
      budgetStep: world.steps,
      expiredTotal: 0,
    };
    world.features.particles = b;
  }
  return b;
}

export function pushParticle(world: PhysicsWorld, b: ParticleBook, e: number): void {
  const size = b.ids.length;
  if (b.count === size) {
    // Oldest first: drop the gone ones at the head, and compact only if the oldest is still alive.
    const spawn = world.spawnStamp;
    while (b.count > 0 && !(spawn[b.ids[b.head]!] === b.stamps[b.head] && slotAlive(world, b.ids[b.head]!))) {
      b.head = b.head + 1 === size ? 0 : b.head + 1;
      b.count--;
    }
    if (b.count === size) compact(world, b);
  }
  // (head + count) mod size, both below size.
  let i = b.head + b.count;
  if (i >= size) i -= size;
  b.ids[i] = e;
  b.stamps[i] = world.spawnStamp[e]!;
  b.count++;
}

/** Whether the slot's entity is alive (bitecs' entity index, read directly: this runs for every FIFO entry). */
function slotAlive(world: PhysicsWorld, e: number): boolean {
  const ix = world.entityIndex;
  const i = ix.sparse[e];
  return i !== undefined && i < ix.aliveCount && ix.dense[i] === e;
}

/**
 * Drops stale entries (particles already gone: slot empty or its spawn stamp moved on) from the FIFO,
 * keeping order. Runs when the FIFO is full, a few times a lifetime of the particles: O(capacity) then.
 */
function compact(world: PhysicsWorld, b: ParticleBook): void {
  const size = b.ids.length;
  const ids = b.ids,
    stamps = b.stamps,
    spawn = world.spawnStamp;
  let w = 0;
  for (let k = 0; k < b.count; k++) {
    const i = (b.head + k) % size;
    const e = ids[i]!,
      st = stamps[i]!;
    if (spawn[e] === st && slotAlive(world, e)) {
      ids[w] = e;
      stamps[w] = st;
      w++;
    }
  }
  b.head = 0;
  b.count = w;
}

function live(world: PhysicsWorld, e: number, stamp: number): boolean {
  return world.spawnStamp[e] === stamp && entityExists(world, e) && hasComponent(world, e, world.components.Particle);
}

/** Removes the oldest live particle; false if there is none. */
export function recycleOldest(world: PhysicsWorld, b: ParticleBook): boolean {
  const size = b.ids.length;
  while (b.count > 0) {
    const e = b.ids[b.head]!,
      stamp = b.stamps[b.head]!;
    b.head = (b.head + 1) % size;
    b.count--;
    if (live(world, e, stamp)) {
      removeParticle(world, e);
      return true;
    }
  }
  return false;
}

/**
 * Removes particle `e` now: the world's removal hooks (springs, joints, sleeping neighbours), then the
 * churn path's removal (`killSlot`), or bitecs' own for a particle with relations.
 */
function removeParticle(world: PhysicsWorld, e: number): void {
  for (const hook of world.removeHooks) hook(world, e);
  if (!entityExists(world, e)) return;
  if (!killSlot(world, ecsOf(world), archetypes(world), e)) removeEntity(world, e);
}

registerExternalWorldState({
  name: 'particles',
  get: (world, create) => (create ? book(world) : bookOf(world)),
  clear: (world) => {
    world.features.particles = undefined;
  },
  keep: ['hooks', 'birthHooks'],
});
