import { addComponent, hasComponent } from 'bitecs';
import { assertBoolean, assertInRange, assertInteger, assertOptions, assertVector, describe } from '../validation/validate.js';
import { createSlot, currentHandle, resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { flushBirths, queueBirth } from './birth-queue.js';
import {
  CapacityPolicy,
  checkSettings,
  type EmitterOptions,
  EmitterShape,
  MAX_EMITTER_RATE,
  type ParticleBirthHook,
  type ParticleDeathHook,
  SETTINGS,
  writeSettings,
} from './emitter-options.js';
import { installEmitters } from './emitter-systems.js';
import { book, bookOf } from './particle-book.js';
import { archetypeFor, headingOf, particleKind, setOrigin, spawnOne } from './spawn.js';

/**
 * Particle systems (Ramtal and Dobre ch. 12): emitters spawn particles with a rate and in bursts,
 * from a shape, in a direction with a spread, with speeds and lifetimes drawn from ranges, passing
 * on part of the emitter's velocity; particles carry the force laws the emitter gives them (mass,
 * drag, gravity scale, a collider) and a look over their life (colour, size, alpha) for renderers;
 * they expire when their lifetime runs out, and may burst into particles of another emitter when
 * they do (fireworks), up to a generation limit.
 *
 * Capacity: a world never grows. When it is full an emitter applies its policy: 'drop-new' skips the
 * spawn (counted in `Emitter.dropped`), 'recycle-oldest' removes the oldest particle first (a FIFO of
 * spawn order, stale entries skipped). No exception is thrown in the middle of a game, and a long run
 * with constant churn keeps the entity count and the heap flat.
 *
 * Spawns per step: at most `maxSpawnsPerStep(world)` (the world's capacity) over all emitters and
 * death bursts together, since no more could be alive at the end of the step; the rest are counted
 * in their emitter's `Emitter.dropped`. Once the world is full and a spawn is refused, the emitter's
 * remaining spawns of that step are counted as dropped at once. So a step's spawning costs at most
 * O(capacity) whatever rate x dt asks for (rates and steps are bounded at the API:
 * `MAX_EMITTER_RATE`, and the world's largest dt).
 *
 * Everything random comes from the world's seeded generator, so a scene replays identically.
 */

/**
 * Every Emitter field's value on a new emitter, before the options given are written (documented on
 * EmitterOptions and EmittedParticleOptions). colorEnd and sizeEnd default to the particle's
 * colorStart and sizeStart, so addEmitter writes them after these.
 */
const EMITTER_DEFAULTS: ReadonlyArray<readonly [Exclude<keyof PhysicsWorld['components']['Emitter'], 'colorEnd' | 'sizeEnd'>, number]> = [
  ['rate', 0],
  ['carry', 0],
  ['pendingBurst', 0],
  ['enabled', 1],
  ['shape', EmitterShape.Point],
  ['size', 0],
  ['sizeY', 0],
  ['sizeZ', 0],
  ['dirX', 0],
  ['dirY', 1],
  ['dirZ', 0],
  ['spread', Math.PI],
  ['projectSphere', 0],
  ['speedMin', 1],
  ['speedMax', 2],
  ['lifeMin', 1],
  ['lifeMax', 2],
  ['inherit', 0],
  ['mass', 0],
  ['linearDrag', 0],
  ['quadraticDrag', 0],
  ['gravityScale', 1],
  ['radius', 0],
  ['colorStart', 0xffffff],
  ['sizeStart', 0.1],
  ['alphaStart', 1],
  ['alphaEnd', 0],
  ['deathEmitter', 0],
  ['deathCount', 0],
  ['maxGeneration', 0],
  ['policy', CapacityPolicy.DropNew],
  ['spawned', 0],
  ['dropped', 0],
];

/**
 * Adds an emitter entity (or puts one on an existing body with `attachTo`). Atomic: every option is
 * checked, and room for the emitter made sure of, before anything changes.
 * @returns the emitter's handle (the body's handle when attached).
 * @throws TypeError on options that are not an object, unknown or null options, a non-boolean `enabled`
 *   or `projectSphere`, or malformed vectors; RangeError on negative rates, speeds or sizes, lifetimes
 *   <= 0, spread outside [0, pi], inherit outside [0, 1], an unknown shape or policy, `projectSphere`
 *   in a 3D world, an `attachTo` or `onDeath.emitter` that was removed or is of the wrong kind, or a
 *   full world.
 * @category Particles
 */
export function addEmitter(world: PhysicsWorld, options: EmitterOptions = {}): number {
  const where = 'addEmitter';
  assertOptions(where, options, ['attachTo', 'position', 'velocity', ...SETTINGS]);
  const d = world.dimensions;
  const c = world.components;
  let host = 0;
  if (options.attachTo !== undefined) {
    if (options.position !== undefined || options.velocity !== undefined)
      throw new TypeError(`${where}: attachTo excludes position and velocity (the body has its own)`);
    host = resolveKind(world, options.attachTo, 'body', where, 'attachTo');
    if (hasComponent(world, host, c.Emitter)) throw new RangeError(`${where}: attachTo ${options.attachTo} already has an emitter`);
  }
  if (options.position !== undefined) assertVector(where, 'position', options.position, d);
  if (options.velocity !== undefined) assertVector(where, 'velocity', options.velocity, d);
  const settings = checkSettings(world, where, options);

  let em: number;
  if (host !== 0) {
    em = host;
  } else {
    em = createSlot(world, where);
    addComponent(world, em, c.Position);
    if (options.position) {
      c.Position.x[em] = options.position[0]!;
      c.Position.y[em] = options.position[1]!;
      c.Position.z[em] = d === 3 ? options.position[2]! : 0;
      c.PreviousPosition.x[em] = c.Position.x[em]!;
      c.PreviousPosition.y[em] = c.Position.y[em]!;
      c.PreviousPosition.z[em] = c.Position.z[em]!;
    }
    if (options.velocity) {
      addComponent(world, em, c.Velocity);
      addComponent(world, em, c.Kinematic);
      c.Velocity.x[em] = options.velocity[0]!;
      c.Velocity.y[em] = options.velocity[1]!;
      c.Velocity.z[em] = d === 3 ? options.velocity[2]! : 0;
    }
  }
  installEmitters(world);
  addComponent(world, em, c.Emitter);
  const E = c.Emitter;
  // Defaults (documented on EmitterOptions and EmittedParticleOptions), then the options given.
  for (const [field, value] of EMITTER_DEFAULTS) E[field][em] = value;
  const p = options.particle ?? {};
  E.colorEnd[em] = p.colorStart ?? 0xffffff;
  E.sizeEnd[em] = p.sizeStart ?? 0.1;
  writeSettings(world, em, settings);
  return currentHandle(world, em);
}

/** The slot of emitter handle `em`. @throws RangeError naming `where` on a removed entity or one that is not an emitter. */
function emitterSlot(where: string, world: PhysicsWorld, em: unknown): number {
  return resolveKind(world, em, 'emitter', where, 'emitter');
}

/**
 * Asks emitter `em` for `count` particles at the next spawn stage (e.g. a firework shell bursting,
 * a splash). @param em an emitter's handle.
 * @throws RangeError on a removed entity, one that is not an emitter, or a count that is not an integer in [0, 10^7].
 * @category Particles
 */
export function burst(world: PhysicsWorld, em: number, count: number): void {
  const slot = emitterSlot('burst', world, em);
  assertInteger('burst', 'count', count, 0, 10_000_000);
  const E = world.components.Emitter;
  E.pendingBurst[slot] = E.pendingBurst[slot]! + count;
}

/**
 * Spawns `count` particles of emitter `em` now, at `position` (default: the emitter's) with
 * `velocity` passed on at the emitter's inherit fraction. Returns how many were spawned (fewer if the
 * world was full and the policy drops). @param em an emitter's handle.
 * @throws TypeError | RangeError on a removed entity, one that is not an emitter, or bad values.
 * @category Particles
 */
export function emitNow(
  world: PhysicsWorld,
  em: number,
  count: number,
  position?: ArrayLike<number>,
  velocity?: ArrayLike<number>,
): number {
  const where = 'emitNow';
  const slot = emitterSlot(where, world, em);
  assertInteger(where, 'count', count, 0, 10_000_000);
  const d = world.dimensions;
  if (position !== undefined) assertVector(where, 'position', position, d);
  if (velocity !== undefined) assertVector(where, 'velocity', velocity, d);
  const P = world.components.Position;
  const x = position ? position[0]! : P.x[slot]!,
    y = position ? position[1]! : P.y[slot]!,
    z = position && d === 3 ? position[2]! : position ? 0 : P.z[slot]!;
  const k = world.components.Emitter.inherit[slot]!;
  const before = world.components.Emitter.spawned[slot]!;
  const b = book(world);
  let a = archetypeFor(world, slot);
  let kind = particleKind(world, slot),
    heading = headingOf(world, slot);
  const bx = velocity ? k * velocity[0]! : 0,
    by = velocity ? k * velocity[1]! : 0,
    bz = velocity && d === 3 ? k * velocity[2]! : 0;
  setOrigin(x, y, z, bx, by, bz, heading);
  const ix = world.entityIndex;
  for (let i = 0; i < count; i++) {
    if (a !== undefined && b.birthHooks.length === 0 && ix.aliveCount < world.capacity) {
      queueBirth(world, b, slot, 0, a, kind);
      continue;
    }
    flushBirths(world);
    setOrigin(x, y, z, bx, by, bz, heading);
    spawnOne(world, b, slot, 0, a, kind);
    // A birth hook may have changed the emitter (setEmitter): the next birth follows it.
    if (a === undefined || b.birthHooks.length > 0) {
      a = archetypeFor(world, slot);
      kind = particleKind(world, slot);
      heading = headingOf(world, slot);
      setOrigin(x, y, z, bx, by, bz, heading);
    }
  }
  flushBirths(world);
  return world.components.Emitter.spawned[slot]! - before;
}

/**
 * Turns an emitter's continuous emission on or off. @param em an emitter's handle.
 * @throws TypeError if `enabled` is not a boolean; RangeError on a removed entity or one that is not an emitter.
 * @category Particles
 */
export function setEmitterEnabled(world: PhysicsWorld, em: number, enabled: boolean): void {
  const slot = emitterSlot('setEmitterEnabled', world, em);
  assertBoolean('setEmitterEnabled', 'enabled', enabled);
  world.components.Emitter.enabled[slot] = enabled ? 1 : 0;
}

/**
 * Sets an emitter's rate, particles/s, in [0, MAX_EMITTER_RATE = 1e9]. @param em an emitter's handle.
 * @throws RangeError on a bad rate, a removed entity or one that is not an emitter.
 * @category Particles
 */
export function setEmitterRate(world: PhysicsWorld, em: number, rate: number): void {
  const slot = emitterSlot('setEmitterRate', world, em);
  assertInRange('setEmitterRate', 'rate', rate, 0, MAX_EMITTER_RATE);
  world.components.Emitter.rate[slot] = rate;
}

/**
 * Registers a hook run for every particle that expires, just before it is removed (its components are
 * still readable). Returns a function that unregisters it. @throws TypeError if not a function.
 * @category Particles
 */
export function onParticleDeath(world: PhysicsWorld, hook: ParticleDeathHook): () => void {
  if (typeof hook !== 'function') throw new TypeError(`onParticleDeath: hook must be a function, got ${describe(hook)}`);
  const b = book(world);
  b.hooks.push(hook);
  return () => {
    const i = b.hooks.indexOf(hook);
    if (i >= 0) b.hooks.splice(i, 1);
  };
}

/**
 * Registers a hook run for every particle an emitter spawns (bursts, rates, `emitNow`), right after it
 * is made. Returns a function that unregisters it. @throws TypeError if not a function.
 * @category Particles
 */
export function onParticleBirth(world: PhysicsWorld, hook: ParticleBirthHook): () => void {
  if (typeof hook !== 'function') throw new TypeError(`onParticleBirth: hook must be a function, got ${describe(hook)}`);
  const b = book(world);
  b.birthHooks.push(hook);
  return () => {
    const i = b.birthHooks.indexOf(hook);
    if (i >= 0) b.birthHooks.splice(i, 1);
  };
}

/**
 * How many particles' lifetimes ran out in `world` since it was made: every particle the spawn stage
 * removed on expiry (not those removed by the API or recycled by a full world's 'recycle-oldest'
 * policy). An exact count, kept in snapshots; with each emitter's `Emitter.spawned` it gives births
 * and deaths per step without a death hook.
 * @category Particles
 */
export function particlesExpired(world: PhysicsWorld): number {
  return bookOf(world)?.expiredTotal ?? 0;
}

/**
 * A particle's look now: colour 0xRRGGBB, size (m) and alpha, linear in age / duration.
 * @category Particles
 */
export interface ParticleLook {
  color: number;
  size: number;
  alpha: number;
}

/**
 * The look of particle `eid` at its current age (for renderers), written into `out`.
 * Colours interpolate per channel. `eid` is a slot, as `query()` gives it (renderers' loops call this
 * per particle; no checks).
 * @category Particles
 */
export function particleLook(world: PhysicsWorld, eid: number, out: ParticleLook): ParticleLook {
  const c = world.components;
  const P = c.Particle,
    L = c.Lifetime;
  const d = L.duration[eid]!;
  let t = d > 0 ? L.age[eid]! / d : 1;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const a = P.colorStart[eid]!,
    b = P.colorEnd[eid]!;
  const r = ((a >> 16) & 255) + (((b >> 16) & 255) - ((a >> 16) & 255)) * t;
  const g = ((a >> 8) & 255) + (((b >> 8) & 255) - ((a >> 8) & 255)) * t;
  const bl = (a & 255) + ((b & 255) - (a & 255)) * t;
  out.color = (Math.round(r) << 16) | (Math.round(g) << 8) | Math.round(bl);
  out.size = P.sizeStart[eid]! + (P.sizeEnd[eid]! - P.sizeStart[eid]!) * t;
  out.alpha = P.alphaStart[eid]! + (P.alphaEnd[eid]! - P.alphaStart[eid]!) * t;
  return out;
}

/**
 * Changes an emitter's settings: any of addEmitter's options except attachTo, position and velocity
 * (move an emitter with setPosition / setVelocity); `onDeath.emitter` 0 removes the death emitter.
 * Omitted options keep their value. Particles already emitted keep what they were given. Every option
 * is checked before any is written, so a refused call changes nothing.
 * @param em an emitter's handle.
 * @throws TypeError | RangeError as addEmitter does, on a missing options object, or if `em` was removed or is not an emitter.
 * @category Particles
 */
export function setEmitter(world: PhysicsWorld, em: number, options: Omit<EmitterOptions, 'attachTo' | 'position' | 'velocity'>): void {
  const where = 'setEmitter';
  const slot = emitterSlot(where, world, em);
  assertOptions(where, options, SETTINGS);
  writeSettings(world, slot, checkSettings(world, where, options));
}
