import { addComponent } from 'bitecs';
import { addParticle, setMass } from '../bodies/api.js';
import { setCharge, setDrag } from '../forces/api.js';
import { assertInteger, assertOptions, describe } from '../validation/validate.js';
import { ecsOf } from '../world/ecs-internals.js';
import { currentHandle, slotOf } from '../world/handles.js';
import { touchSparseSet } from '../world/lean-ecs.js';
import type { PhysicsWorld } from '../world/options.js';
import { type Archetype, archetypeFromEntity, archetypes, bornSlots, pendingArchetype, prepareArchetype, settle } from './archetype.js';

/**
 * Key of the bare particle (Position and Velocity) in the world's archetype table; emitter kinds use
 * 0..31. A bulk with properties adds their flags (PROPERTY_FLAGS) to it: keys 64..127.
 */
const BARE_PARTICLE = 64;

/** Default drawn size of a coloured bulk particle, m (as an emitter's default `size`). */
const COLORED_PARTICLE_SIZE = 0.1;

/**
 * A per-particle property of `addParticles`: one number for every particle, or an array of `count`
 * numbers, one a particle in order.
 * @category Particles
 */
export type BulkValue = number | ArrayLike<number>;

/**
 * Options of `addParticles`. Arrays hold `world.dimensions` numbers a particle, in particle order.
 * @category Particles
 */
export interface BulkParticleOptions {
  /** Positions, m: x0, y0(, z0), x1, ... (count x dimensions finite numbers). Default: every particle at the origin. */
  positions?: ArrayLike<number>;
  /** Velocities, m/s, laid out like `positions`. Default 0. */
  velocities?: ArrayLike<number>;
  /** Mass, kg, finite and > 0 (the `Mass` component, as `setMass`). Default: none (a bare particle: mass 1 kg where a force law asks). */
  mass?: BulkValue;
  /** Linear drag coefficient k, kg/s, finite and >= 0: force -k v (the `LinearDrag` component, as `setDrag`'s `linear`). Default: none. */
  linearDrag?: BulkValue;
  /** Quadratic drag coefficient k, kg/m, finite and >= 0: force -k |v| v (the `QuadraticDrag` component, as `setDrag`'s `quadratic`). Default: none. */
  quadraticDrag?: BulkValue;
  /** Electric charge, C, finite (the `Charge` component, as `setCharge`). Default: none. */
  charge?: BulkValue;
  /**
   * Lifetime, s, finite and > 0: the particle is removed at the first step whose end reaches it
   * (`lifetimeSystem`, the `Lifetime` component with age 0; `onParticleDeath` hooks run for it).
   * Default: none (lives until removed).
   */
  lifetime?: BulkValue;
  /**
   * Colour, 0xRRGGBB, an integer in [0, 0xFFFFFF]: drawn in that colour by the renderers' particle
   * layer (the `Particle` component, colour fixed over its life, size 0.1 m, opaque). Default: none.
   */
  color?: BulkValue;
}

/** Property options, their component flags and rules. */
const PROPERTIES = [
  { key: 'mass', flag: 1, rule: 'a finite number > 0', ok: (x: number) => Number.isFinite(x) && x > 0 },
  { key: 'linearDrag', flag: 2, rule: 'a finite number >= 0', ok: (x: number) => Number.isFinite(x) && x >= 0 },
  { key: 'quadraticDrag', flag: 4, rule: 'a finite number >= 0', ok: (x: number) => Number.isFinite(x) && x >= 0 },
  { key: 'charge', flag: 8, rule: 'a finite number', ok: (x: number) => Number.isFinite(x) },
  { key: 'lifetime', flag: 16, rule: 'a finite number > 0 (s)', ok: (x: number) => Number.isFinite(x) && x > 0 },
  {
    key: 'color',
    flag: 32,
    rule: 'an integer in [0, 0xFFFFFF]',
    ok: (x: number) => Number.isInteger(x) && x >= 0 && x <= 0xffffff,
  },
] as const;

type PropertyKey = (typeof PROPERTIES)[number]['key'];

/**
 * Adds `count` bare particles at once: each exactly what `addParticle` makes (Position and Velocity;
 * it feels the world's gravity and, given more components, anything else), `PreviousPosition` equal to
 * its position, in one pass that writes bitecs' entity index, component masks and query lists directly
 * (particles/archetype.ts for freed slots, `bornFresh` here for the run of new ones) instead of
 * calling addEntity and addComponent per particle. Slots are taken in the order
 * `addParticle` would take them, so the world is the same as after `count` calls of `addParticle`.
 *
 * Properties (`mass`, `linearDrag`, `quadraticDrag`, `charge`, `lifetime`, `color`), each one number
 * for all or an array of `count`, give every particle the component that `setMass`, `setDrag`,
 * `setCharge` or an emitter would, written in the same bulk pass (200,000 particles given drag one
 * `setDrag` at a time took 1.4 to 2.1 s of component additions).
 *
 * Atomic: every option is checked, and room made sure of, before anything changes.
 * @param count particles to add, an integer in [0, capacity - live entities].
 * @returns their handles, in order (a Float64Array of `count`; handles are exact integers below 2^53).
 * @throws TypeError on options that are not an object, unknown or null options, or arrays that are not
 *   array-like; RangeError on a count that is not an integer or exceeds the room left, arrays of the
 *   wrong length, a position or velocity that is not finite, or a property outside its range.
 * @example
 * const handles = addParticles(world, 1000, { positions, velocities }); // positions: Float64Array(2000) in 2D
 * addParticles(world, 200_000, { positions, linearDrag: 0.05, lifetime: 3, color: 0xffaa33 });
 * @category Particles
 */
export function addParticles(world: PhysicsWorld, count: number, options: BulkParticleOptions = {}): Float64Array {
  const where = 'addParticles';
  assertOptions(where, options, ['positions', 'velocities', ...PROPERTIES.map((q) => q.key)]);
  const room = world.capacity - world.entityIndex.aliveCount;
  assertInteger(where, 'count', count, 0, room);
  const d = world.dimensions;
  const p = options.positions,
    v = options.velocities;
  checkArray(where, 'positions', p, count * d);
  checkArray(where, 'velocities', v, count * d);
  let key = BARE_PARTICLE;
  for (const q of PROPERTIES) {
    const value = options[q.key];
    if (value === undefined) continue;
    checkProperty(where, q.key, value, count, q.rule, q.ok);
    key += q.flag;
  }
  const handles = new Float64Array(count);
  if (count === 0) return handles;
  const propertyOf = (name: PropertyKey, i: number): number => {
    const x = options[name]!;
    return typeof x === 'number' ? x : x[i]!;
  };
  const table = archetypes(world);
  // Pending deaths (a call from a death hook) leave their queries first: bulk births append.
  settle(world, table);
  const at = (a: ArrayLike<number> | undefined, i: number, j: number): number => (a && j < d ? a[i * d + j]! : 0);
  let done = 0;
  while (done < count) {
    let a = table.byKey.get(key);
    if (a === undefined || !prepareArchetype(world, a)) {
      // The first of its kind (or a store without arrays): through bitecs, whose observers set it up.
      const pending = pendingArchetype(table, nextSlot(world));
      const h = addParticle(world, {
        position: d === 3 ? [at(p, done, 0), at(p, done, 1), at(p, done, 2)] : [at(p, done, 0), at(p, done, 1)],
        velocity: d === 3 ? [at(v, done, 0), at(v, done, 1), at(v, done, 2)] : [at(v, done, 0), at(v, done, 1)],
      });
      if (key !== BARE_PARTICLE) giveProperties(world, h, done, options, propertyOf);
      a = archetypeFromEntity(world, table, key, slotOf(h), pending);
      handles[done] = h;
      done++;
      continue;
    }
    const prev = world.components.PreviousPosition.x.length > world.capacity;
    const job: BulkJob = { world, archetype: a, handles, options, propertyOf, key, p, v, count, prev };
    done = fillRecycled(job, done);
    if (done < count) fillFresh(job, done);
    done = count;
  }
  return handles;
}

/** What one addParticles call fills: its world, archetype, inputs and the handles it returns. */
interface BulkJob {
  world: PhysicsWorld;
  archetype: Parameters<typeof prepareArchetype>[1];
  handles: Float64Array;
  options: BulkParticleOptions;
  propertyOf: (name: PropertyKey, i: number) => number;
  key: number;
  p: ArrayLike<number> | undefined;
  v: ArrayLike<number> | undefined;
  count: number;
  /** Whether the PreviousPosition store has arrays (then it is written too). */
  prev: boolean;
}

/**
 * Births particles done.. of `job` in slots freed earlier (bitecs hands them out before new ones), one
 * at a time, as many as there are; returns the new `done`.
 */
function fillRecycled(job: BulkJob, done: number): number {
  const { world, handles, options, propertyOf, key, p, v } = job;
  const d = world.dimensions;
  const c = world.components;
  const fresh = world.entityIndex.maxId; // slots above it were never used: their z and previous state are 0
  const recycled = Math.min(job.count - done, world.entityIndex.dense.length - world.entityIndex.aliveCount);
  if (recycled <= 0) return done;
  const slots = new Int32Array(recycled);
  bornSlots(world, job.archetype, recycled, slots);
  const { x: OX, y: OY, z: OZ } = c.PreviousPosition;
  const prev = job.prev;
  for (let k = 0; k < recycled; k++) {
    const e = slots[k]!;
    if (e <= fresh) {
      c.Position.z[e] = 0;
      OZ[e] = 0;
      c.Velocity.z[e] = 0;
    }
    handles[done + k] = currentHandle(world, e);
  }
  // One array at a time: coordinate j of particle i is at i * d + j.
  const fill = (T: Float64Array, U: Float64Array | null, src: ArrayLike<number> | undefined, j: number) => {
    for (let k = 0; k < recycled; k++) {
      const e = slots[k]!,
        x = src ? src[(done + k) * d + j]! : 0;
      T[e] = x;
      if (U) U[e] = x;
    }
  };
  fill(c.Position.x, prev ? OX : null, p, 0);
  fill(c.Position.y, prev ? OY : null, p, 1);
  fill(c.Velocity.x, null, v, 0);
  fill(c.Velocity.y, null, v, 1);
  if (d === 3) {
    fill(c.Position.z, prev ? OZ : null, p, 2);
    fill(c.Velocity.z, null, v, 2);
  }
  // What the Position observer resets besides (create-world.ts), for stores that exist.
  for (const s of [c.AngularVelocity, c.Force, c.Torque]) {
    if (s.x.length <= world.capacity) continue;
    for (let k = 0; k < recycled; k++) {
      const e = slots[k]!;
      s.x[e] = 0;
      s.y[e] = 0;
      s.z[e] = 0;
    }
  }
  if (key !== BARE_PARTICLE) for (let k = 0; k < recycled; k++) writeProperties(world, slots[k]!, done + k, options, propertyOf);
  return done + recycled;
}

/**
 * Births particles done..count-1 of `job` in new slots, consecutive ids: bulk writes of the entity
 * index, masks and query lists.
 */
function fillFresh(job: BulkJob, done: number): void {
  const { world, handles, options, propertyOf, key, p, v } = job;
  const d = world.dimensions;
  const c = world.components;
  const { x: X, y: Y, z: Z } = c.Position,
    { x: VX, y: VY, z: VZ } = c.Velocity;
  const m = job.count - done;
  const first = bornFresh(world, job.archetype, m);
  const end = first + m;
  // Handles: slot + generation x SLOT_RANGE; slots of one spawn stamp share the offset (new slots
  // usually all have stamp 1), others ask currentHandle.
  const spawn = world.spawnStamp,
    s0 = spawn[first]!,
    offset = currentHandle(world, first) - first;
  for (let e = first, i = done; e < end; e++, i++) handles[i] = spawn[e] === s0 ? e + offset : currentHandle(world, e);
  // Consecutive slots: coordinate j of particle i (= done + e - first) is at i * d + j.
  if (d === 2 && p !== undefined && v !== undefined) {
    // Both given in 2D (the common case): one pass, as a bare loop would copy them.
    for (let e = first, o = 2 * done; e < end; e++, o += 2) {
      X[e] = p[o]!;
      Y[e] = p[o + 1]!;
      VX[e] = v[o]!;
      VY[e] = v[o + 1]!;
    }
  } else {
    const run = (T: Float64Array, src: ArrayLike<number> | undefined, j: number) => {
      if (src === undefined) {
        T.fill(0, first, end);
        return;
      }
      for (let e = first, o = done * d + j; e < end; e++, o += d) T[e] = src[o]!;
    };
    run(X, p, 0);
    run(Y, p, 1);
    run(VX, v, 0);
    run(VY, v, 1);
    if (d === 3) {
      run(Z, p, 2);
      run(VZ, v, 2);
    }
  }
  if (job.prev) {
    c.PreviousPosition.x.set(X.subarray(first, end), first);
    c.PreviousPosition.y.set(Y.subarray(first, end), first);
    if (d === 3) c.PreviousPosition.z.set(Z.subarray(first, end), first);
  }
  for (const s of [c.AngularVelocity, c.Force, c.Torque]) {
    if (s.x.length <= world.capacity) continue;
    s.x.fill(0, first, end);
    s.y.fill(0, first, end);
    s.z.fill(0, first, end);
  }
  if (key !== BARE_PARTICLE) for (let e = first, i = done; e < end; e++, i++) writeProperties(world, e, i, options, propertyOf);
}

/**
 * Gives the particle `h` (index `i` of the bulk) its properties through the public setters (the first
 * particle of a property set, made through bitecs' ordinary path, from which the archetype is read).
 */
function giveProperties(
  world: PhysicsWorld,
  h: number,
  i: number,
  options: BulkParticleOptions,
  propertyOf: (name: PropertyKey, i: number) => number,
): void {
  if (options.mass !== undefined) setMass(world, h, propertyOf('mass', i));
  if (options.linearDrag !== undefined) setDrag(world, h, { linear: propertyOf('linearDrag', i) });
  if (options.quadraticDrag !== undefined) setDrag(world, h, { quadratic: propertyOf('quadraticDrag', i) });
  if (options.charge !== undefined) setCharge(world, h, propertyOf('charge', i));
  const c = world.components,
    e = slotOf(h);
  if (options.lifetime !== undefined) addComponent(world, e, c.Lifetime);
  if (options.color !== undefined) addComponent(world, e, c.Particle);
  writeProperties(world, e, i, options, propertyOf);
}

/** Writes every property's component data of slot `e` (bulk index `i`); the components are in place. */
function writeProperties(
  world: PhysicsWorld,
  e: number,
  i: number,
  options: BulkParticleOptions,
  propertyOf: (name: PropertyKey, i: number) => number,
): void {
  const c = world.components;
  if (options.mass !== undefined) {
    const m = propertyOf('mass', i);
    c.Mass.value[e] = m;
    c.Mass.inv[e] = 1 / m;
  }
  if (options.linearDrag !== undefined) c.LinearDrag.k[e] = propertyOf('linearDrag', i);
  if (options.quadraticDrag !== undefined) c.QuadraticDrag.k[e] = propertyOf('quadraticDrag', i);
  if (options.charge !== undefined) c.Charge.value[e] = propertyOf('charge', i);
  if (options.lifetime !== undefined) {
    c.Lifetime.age[e] = 0;
    c.Lifetime.duration[e] = propertyOf('lifetime', i);
  }
  if (options.color !== undefined) {
    const P = c.Particle,
      rgb = propertyOf('color', i);
    P.emitter[e] = 0;
    P.emitterStamp[e] = 0;
    P.generation[e] = 0;
    P.colorStart[e] = rgb;
    P.colorEnd[e] = rgb;
    P.sizeStart[e] = COLORED_PARTICLE_SIZE;
    P.sizeEnd[e] = COLORED_PARTICLE_SIZE;
    P.alphaStart[e] = 1;
    P.alphaEnd[e] = 1;
    // A coloured particle without a lifetime is drawn at its end look: the same here.
    if (options.lifetime === undefined) {
      c.Lifetime.age[e] = 0;
      c.Lifetime.duration[e] = 0;
    }
  }
}

/**
 * Checks a property: one number, or an array of `count` numbers, each passing `ok`.
 * @throws TypeError | RangeError naming `where`, `name`, the index and the value.
 */
function checkProperty(where: string, name: string, a: unknown, count: number, rule: string, ok: (x: number) => boolean): void {
  if (typeof a === 'number') {
    if (!ok(a)) throw new RangeError(`${where}: ${name} must be ${rule}, got ${describe(a)}`);
    return;
  }
  if (a === null || typeof a !== 'object' || typeof (a as ArrayLike<number>).length !== 'number') {
    throw new TypeError(`${where}: ${name} must be a number or an array of ${count} numbers, got ${describe(a)}`);
  }
  const arr = a as ArrayLike<number>;
  if (arr.length !== count) throw new RangeError(`${where}: ${name} must hold ${count} numbers (one a particle), got ${arr.length}`);
  for (let i = 0; i < count; i++) {
    const x = arr[i];
    if (typeof x !== 'number' || !ok(x)) throw new RangeError(`${where}: ${name}[${i}] must be ${rule}, got ${describe(x)}`);
  }
}

/** Appends of at least this many ids lengthen the list once instead of pushing. */
const BULK_APPEND = 1 << 12;

/**
 * Appends ids from, from + 1, ..., from + m - 1 to `list` (the same array: bitecs and the query cache
 * hold it). A long run sets the length once and writes the ids in place: pushing a million ids
 * regrows the array's storage about 35 times (each a copy and garbage), which took about three
 * quarters of the bulk creation's bookkeeping. The array's elements kind becomes holey (V8), which a
 * loop over it reads as fast.
 */
function appendRange(list: number[], from: number, m: number): void {
  const n = list.length;
  if (m >= BULK_APPEND) {
    list.length = n + m;
    for (let k = 0; k < m; k++) list[n + k] = from + k;
    return;
  }
  for (let k = 0; k < m; k++) list.push(from + k);
}

/**
 * Creates `m` entities of archetype `a` in the slots above the highest id used so far (the world has
 * no freed slot left to hand out, and room for them), ids first .. first + m - 1 in order: what
 * `bornSlots` does, for consecutive new ids, one array at a time without a call per entity: the
 * entity index's dense list and sparse array, the spawn stamps, each mask generation (one `fill`), and
 * each query the archetype matches (its own `add` for the first id, which allocates a lean set's
 * sparse array, then pushes and one pass over its sparse array). A new id is in no query and no
 * pending removal (no entity ever had it), so no membership is checked. Writes no component data.
 * @returns the first id.
 */
function bornFresh(world: PhysicsWorld, a: Archetype, m: number): number {
  const ecs = ecsOf(world);
  const ix = ecs.entityIndex,
    spawn = world.spawnStamp;
  const first = ix.maxId + 1,
    end = first + m,
    alive = ix.aliveCount;
  const sparse = ix.sparse;
  appendRange(ix.dense, first, m);
  for (let e = first, i = alive; e < end; e++, i++) sparse[e] = i;
  for (let e = first; e < end; e++) spawn[e] = spawn[e]! + 1;
  ix.maxId = end - 1;
  ix.aliveCount = alive + m;
  const masks = a.masks;
  for (let g = 0; g < masks.length; g++) {
    const em = ecs.entityMasks[g]! as number[] | Int32Array,
      mask = masks[g]!;
    if (mask === 0) continue;
    if (em instanceof Int32Array) em.fill(mask, first, end);
    else for (let e = first; e < end; e++) em[e] = mask;
  }
  const qs = a.queries;
  for (let i = 0; i < qs.length; i++) {
    const q = qs[i]!;
    q.add(first);
    const base = q.dense.length - 1;
    appendRange(q.dense, first + 1, m - 1);
    const qs2 = q.sparse;
    for (let e = first + 1, j = base + 1; e < end; e++, j++) qs2[e] = j;
    touchSparseSet(q);
  }
  if (ecs.entityComponents instanceof Map) {
    const sets = ecs.entityComponents;
    for (let e = first; e < end; e++) sets.set(e, new Set(a.components));
  }
  return first;
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
    if (typeof x !== 'number' || !Number.isFinite(x))
      throw new RangeError(`${where}: ${name}[${i}] must be a finite number, got ${describe(x)}`);
  }
}

/**
 * The slot bitecs hands out next (the slot freed last, else a new one).
 * @category Particles
 */
export function nextSlot(world: PhysicsWorld): number {
  const ix = world.entityIndex;
  return ix.aliveCount < ix.dense.length ? ix.dense[ix.aliveCount]! : ix.maxId + 1;
}
