import type { PhysicsWorld } from '../world.js';
import { addParticle } from '../bodies.js';
import { currentHandle, slotOf } from '../handles.js';
import { assertInteger, assertOptions, describe } from '../validate.js';
import { archetypeFromEntity, archetypes, bornSlots, pendingArchetype, prepareArchetype, settle } from './archetype.js';

/** Key of the bare particle (Position and Velocity) in the world's archetype table; emitter kinds use 0..31. */
const BARE_PARTICLE = 64;

/** Options of `addParticles`. Arrays hold `world.dimensions` numbers a particle, in particle order. */
export interface BulkParticleOptions {
  /** Positions, m: x0, y0(, z0), x1, ... (count x dimensions finite numbers). Default: every particle at the origin. */
  positions?: ArrayLike<number>;
  /** Velocities, m/s, laid out like `positions`. Default 0. */
  velocities?: ArrayLike<number>;
}

/**
 * Adds `count` bare particles at once: each exactly what `addParticle` makes (Position and Velocity;
 * it feels the world's gravity and, given more components, anything else), `PreviousPosition` equal to
 * its position, in one pass that writes bitecs' entity index, component masks and query lists directly
 * (particles/archetype.ts) instead of calling addEntity and addComponent per particle: a million
 * particles take about as long as filling the arrays in a bare loop. Slots are taken in the order
 * `addParticle` would take them, so the world is the same as after `count` calls of `addParticle`.
 *
 * Atomic: every option is checked, and room made sure of, before anything changes.
 * @param count particles to add, an integer in [0, capacity - live entities].
 * @returns their handles, in order (a Float64Array of `count`; handles are exact integers below 2^53).
 * @throws TypeError on options that are not an object, unknown or null options, or arrays that are not
 *   array-like; RangeError on a count that is not an integer or exceeds the room left, arrays of the
 *   wrong length, or a position or velocity that is not finite.
 * @example
 * const handles = addParticles(world, 1000, { positions, velocities }); // positions: Float64Array(2000) in 2D
 */
export function addParticles(world: PhysicsWorld, count: number, options: BulkParticleOptions = {}): Float64Array {
  const where = 'addParticles';
  assertOptions(where, options, ['positions', 'velocities']);
  const room = world.capacity - world.entityIndex.aliveCount;
  assertInteger(where, 'count', count, 0, room);
  const d = world.dimensions;
  const p = options.positions, v = options.velocities;
  checkArray(where, 'positions', p, count * d);
  checkArray(where, 'velocities', v, count * d);
  const handles = new Float64Array(count);
  if (count === 0) return handles;
  const table = archetypes(world);
  // Pending deaths (a call from a death hook) leave their queries first: bulk births append.
  settle(world, table);
  const c = world.components;
  const at = (a: ArrayLike<number> | undefined, i: number, j: number): number => (a && j < d ? a[i * d + j]! : 0);
  const slots = new Int32Array(count);
  let done = 0;
  while (done < count) {
    let a = table.byKey.get(BARE_PARTICLE);
    if (a === undefined || !prepareArchetype(world, a)) {
      // The first of its kind (or a store without arrays): through bitecs, whose observers set it up.
      const pending = pendingArchetype(table, nextSlot(world));
      const h = addParticle(world, {
        position: d === 3 ? [at(p, done, 0), at(p, done, 1), at(p, done, 2)] : [at(p, done, 0), at(p, done, 1)],
        velocity: d === 3 ? [at(v, done, 0), at(v, done, 1), at(v, done, 2)] : [at(v, done, 0), at(v, done, 1)],
      });
      a = archetypeFromEntity(world, table, BARE_PARTICLE, slotOf(h), pending);
      handles[done] = h;
      done++;
      continue;
    }
    const n = count - done;
    const fresh = world.entityIndex.maxId; // slots above it were never used: their z and previous state are 0
    bornSlots(world, a, n, slots);
    const X = c.Position.x, Y = c.Position.y, Z = c.Position.z, OX = c.PreviousPosition.x, OY = c.PreviousPosition.y, OZ = c.PreviousPosition.z;
    const VX = c.Velocity.x, VY = c.Velocity.y, VZ = c.Velocity.z;
    for (let k = 0; k < n; k++) {
      const e = slots[k]!;
      if (e <= fresh) { Z[e] = 0; OZ[e] = 0; VZ[e] = 0; }
      handles[done + k] = currentHandle(world, e);
    }
    // One array at a time: coordinate j of particle i is at i * d + j.
    const fill = (T: Float64Array, U: Float64Array | null, src: ArrayLike<number> | undefined, j: number) => {
      for (let k = 0; k < n; k++) {
        const e = slots[k]!, x = src ? src[(done + k) * d + j]! : 0;
        T[e] = x;
        if (U) U[e] = x;
      }
    };
    fill(X, OX, p, 0); fill(Y, OY, p, 1); fill(VX, null, v, 0); fill(VY, null, v, 1);
    if (d === 3) { fill(Z, OZ, p, 2); fill(VZ, null, v, 2); }
    // What the Position observer resets besides (create-world.ts), for stores that exist.
    for (const s of [c.AngularVelocity, c.Force, c.Torque]) {
      if (s.x.length <= world.capacity) continue;
      for (let k = 0; k < n; k++) { const e = slots[k]!; s.x[e] = 0; s.y[e] = 0; s.z[e] = 0; }
    }
    done = count;
  }
  return handles;
}

/** Checks an optional flat array of `n` finite numbers. @throws TypeError | RangeError naming `where` and `name`. */
function checkArray(where: string, name: string, a: ArrayLike<number> | undefined, n: number): void {
  if (a === undefined) return;
  if (a === null || typeof a !== 'object' || typeof a.length !== 'number') {
    throw new TypeError(`${where}: ${name} must be an array of numbers, got ${describe(a)}`);
  }
  if (a.length !== n) throw new RangeError(`${where}: ${name} must hold ${n} numbers (count x dimensions), got ${a.length}`);
  if (a instanceof Float64Array || a instanceof Float32Array) {
    // x - x is 0 exactly for a finite x.
    let i = 0;
    while (i < n && a[i]! - a[i]! === 0) i++;
    if (i === n) return;
  }
  for (let i = 0; i < n; i++) {
    const x = a[i];
    if (typeof x !== 'number' || !Number.isFinite(x)) throw new RangeError(`${where}: ${name}[${i}] must be a finite number, got ${describe(x)}`);
  }
}

/** The slot bitecs hands out next (the slot freed last, else a new one). */
export function nextSlot(world: PhysicsWorld): number {
  const ix = world.entityIndex;
  return ix.aliveCount < ix.dense.length ? ix.dense[ix.aliveCount]! : ix.maxId + 1;
}
