import { DEFAULT_MATERIAL, type Vec3Store } from '../world/components.js';
import type { PhysicsWorld } from '../world/options.js';
import { type Archetype, applyQueuedBirths, archetypes, bornSlotQueued, queuedPending } from './archetype.js';
import { maxSpawnsPerStep } from './emitter-options.js';
import { type ParticleBook, pushParticle } from './particle-book.js';
import { archetypeFor, draw, headingOf, nonFiniteSpawn, origin, particleKind, sample, setOrigin, spawnOne } from './spawn.js';

/** Spawning a step's particles: the queue of births and its flush, within the step's spawn budget. */

/**
 * Births made but not yet written (`queueBirth`, `flushBirths`): each birth's slot, emitter, kind,
 * generation, position, velocity and lifetime, up to `QUEUE` of them. The component stores are then
 * written one array at a time over the queued births instead of every array once a birth: a step's
 * births land in slots scattered over the whole capacity, and writing some thirty arrays per birth
 * touched a different memory page of each (with 4 kB pages, a world of 60,000 slots spreads the
 * stores over some 4,000 pages, more than the processor's address cache holds), so writing each
 * array in turn over all births is about twice as fast as writing each birth in turn.
 *
 * One queue for every world (module scratch, like `sample`): it is always empty when control leaves
 * this module and before any user code (hooks) runs, so it holds births of one world at a time and is
 * never part of a world's state.
 */
const QUEUE = 4096;
interface BirthQueue {
  world: PhysicsWorld | null;
  count: number;
  slot: Int32Array;
  em: Int32Array;
  kind: Uint8Array;
  generation: Float64Array;
  /** Archetype id + 1 of each birth, and the slot's pending mark before it (`bornSlotQueued`). */
  mark: Int32Array;
  pend: Int32Array;
  px: Float64Array;
  py: Float64Array;
  pz: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
  vz: Float64Array;
  life: Float64Array;
}
let queue: BirthQueue | null = null;

function birthQueue(): BirthQueue {
  if (queue === null) {
    const f = () => new Float64Array(QUEUE);
    queue = {
      world: null,
      count: 0,
      slot: new Int32Array(QUEUE),
      em: new Int32Array(QUEUE),
      kind: new Uint8Array(QUEUE),
      generation: f(),
      mark: new Int32Array(QUEUE),
      pend: new Int32Array(QUEUE),
      px: f(),
      py: f(),
      pz: f(),
      vx: f(),
      vy: f(),
      vz: f(),
      life: f(),
    };
  }
  return queue;
}

/**
 * `spawnOne`'s birth for the common case (archetype `a` ready, room in the world, no birth hook):
 * draws the particle exactly as `spawnOne` does (the same random numbers in the same order), makes
 * its entity and queues its component data for `flushBirths`. The caller flushes before anything
 * else can look at the world. Throws `spawnOne`'s NonFiniteStateError (after flushing the births
 * before it, as `spawnOne` would have written them).
 */
export function queueBirth(world: PhysicsWorld, b: ParticleBook, em: number, generation: number, a: Archetype, kind: number): void {
  const E = world.components.Emitter;
  draw(world, em);
  const px = origin[0]! + sample[0]!,
    py = origin[1]! + sample[1]!,
    pz = origin[2]! + sample[2]!;
  const vx = sample[3]! + origin[3]!,
    vy = sample[4]! + origin[4]!,
    vz = sample[5]! + origin[5]!;
  if (px * 0 + py * 0 + pz * 0 + vx * 0 + vy * 0 + vz * 0 !== 0) {
    flushBirths(world);
    nonFiniteSpawn(world, em, px, py, pz, vx, vy, vz);
  }
  const q = birthQueue();
  if (q.count === QUEUE) flushBirths(world);
  q.world = world;
  const e = bornSlotQueued(world, a);
  const k = q.count++;
  q.slot[k] = e;
  q.em[k] = em;
  q.kind[k] = kind;
  q.generation[k] = generation;
  q.mark[k] = a.id + 1;
  q.pend[k] = queuedPending;
  q.px[k] = px;
  q.py[k] = py;
  q.pz[k] = pz;
  q.vx[k] = vx;
  q.vy[k] = vy;
  q.vz[k] = vz;
  q.life[k] = world.rng.range(E.lifeMin[em]!, E.lifeMax[em]!);
  pushParticle(world, b, e);
  E.spawned[em] = E.spawned[em]! + 1;
}

/**
 * Writes the queued births' components (what `spawnOne` writes for a birth of a ready archetype), one
 * array at a time, and empties the queue. No-op when it is empty.
 */
export function flushBirths(world: PhysicsWorld): void {
  const q = queue;
  if (q === null || q.count === 0) return;
  const n = q.count;
  q.count = 0;
  q.world = null;
  const c = world.components,
    E = c.Emitter;
  const S = q.slot,
    EM = q.em,
    K = q.kind;
  // The births' query work (joining the queries, or keeping a pending death's place), one query at a time.
  applyQueuedBirths(archetypes(world), S, q.mark, q.pend, n);
  // What bitecs' observers write when these components are added (create-world.ts); stores a world
  // allocates lazily may have no arrays yet: nothing to reset there.
  zeroVecAt(c.AngularVelocity, S, n, world.capacity);
  zeroVecAt(c.Force, S, n, world.capacity);
  zeroVecAt(c.Torque, S, n, world.capacity);
  let kinds = 0;
  for (let k = 0; k < n; k++) kinds |= K[k]!;
  if (kinds !== 0) {
    const mv = c.Mass.value,
      mi = c.Mass.inv;
    for (let k = 0; k < n; k++) {
      if (K[k] === 0) continue;
      const mass = E.mass[EM[k]!]!,
        m = mass > 0 ? mass : 1;
      mv[S[k]!] = m;
    }
    for (let k = 0; k < n; k++) {
      if (K[k] === 0) continue;
      const mass = E.mass[EM[k]!]!,
        m = mass > 0 ? mass : 1;
      mi[S[k]!] = 1 / m;
    }
    if ((kinds & 2) !== 0) perKind(2, c.LinearDrag.k, E.linearDrag, S, EM, K, n);
    if ((kinds & 4) !== 0) perKind(4, c.QuadraticDrag.k, E.quadraticDrag, S, EM, K, n);
    if ((kinds & 8) !== 0) perKind(8, c.GravityScale.value, E.gravityScale, S, EM, K, n);
    if ((kinds & 16) !== 0) perKind(16, c.Ball.radius, E.radius, S, EM, K, n);
    if ((kinds & 16) !== 0) {
      const M = c.Material;
      for (let k = 0; k < n; k++) {
        if ((K[k]! & 16) === 0) continue;
        const e = S[k]!;
        M.restitution[e] = DEFAULT_MATERIAL.restitution;
        M.friction[e] = DEFAULT_MATERIAL.friction;
        M.staticFriction[e] = DEFAULT_MATERIAL.friction;
      }
    }
  }
  putAt(c.Position.x, S, q.px, n);
  putAt(c.Position.y, S, q.py, n);
  putAt(c.Position.z, S, q.pz, n);
  putAt(c.PreviousPosition.x, S, q.px, n);
  putAt(c.PreviousPosition.y, S, q.py, n);
  putAt(c.PreviousPosition.z, S, q.pz, n);
  putAt(c.Velocity.x, S, q.vx, n);
  putAt(c.Velocity.y, S, q.vy, n);
  putAt(c.Velocity.z, S, q.vz, n);
  const L = c.Lifetime;
  zeroAt(L.age, S, n);
  putAt(L.duration, S, q.life, n);
  const P = c.Particle;
  putAt(P.emitter, S, EM, n);
  lookAt(P.emitterStamp, world.spawnStamp, S, EM, n);
  putAt(P.generation, S, q.generation, n);
  lookAt(P.colorStart, E.colorStart, S, EM, n);
  lookAt(P.colorEnd, E.colorEnd, S, EM, n);
  lookAt(P.sizeStart, E.sizeStart, S, EM, n);
  lookAt(P.sizeEnd, E.sizeEnd, S, EM, n);
  lookAt(P.alphaStart, E.alphaStart, S, EM, n);
  lookAt(P.alphaEnd, E.alphaEnd, S, EM, n);
}

/** A component field array (any typed array a store uses). */
type Writable = { [i: number]: number; readonly length: number };

/** T[S[k]] = V[k] for k < n. */
function putAt(T: Writable, S: Int32Array, V: ArrayLike<number>, n: number): void {
  for (let k = 0; k < n; k++) T[S[k]!] = V[k]!;
}

/** T[S[k]] = 0 for k < n. */
function zeroAt(T: Writable, S: Int32Array, n: number): void {
  for (let k = 0; k < n; k++) T[S[k]!] = 0;
}

/** v.x, v.y and v.z [S[k]] = 0 for k < n, when the store has arrays (longer than `capacity`; a lazily allocated one may have none yet). */
function zeroVecAt(v: Vec3Store, S: Int32Array, n: number, capacity: number): void {
  if (v.x.length <= capacity) return;
  zeroAt(v.x, S, n);
  zeroAt(v.y, S, n);
  zeroAt(v.z, S, n);
}

/** T[S[k]] = from[EM[k]] for k < n: a field every particle takes from its emitter. */
function lookAt(T: Writable, from: ArrayLike<number>, S: Int32Array, EM: Int32Array, n: number): void {
  for (let k = 0; k < n; k++) T[S[k]!] = from[EM[k]!]!;
}

/** `lookAt` for the births whose kind has `bit`. */
function perKind(bit: number, T: Writable, from: ArrayLike<number>, S: Int32Array, EM: Int32Array, K: Uint8Array, n: number): void {
  for (let k = 0; k < n; k++) if ((K[k]! & bit) !== 0) T[S[k]!] = from[EM[k]!]!;
}

/** Takes up to `count` spawns from this step's budget (`maxSpawnsPerStep`); returns how many were granted. */
function takeBudget(world: PhysicsWorld, b: ParticleBook, count: number): number {
  if (b.budgetStep !== world.steps) {
    b.budgetStep = world.steps;
    b.budget = maxSpawnsPerStep(world);
  }
  const n = count < b.budget ? count : b.budget;
  b.budget -= n;
  return n;
}

/**
 * Spawns `count` particles of emitter `em` within this step's budget; the rest, and every spawn left
 * once one is refused because the world is full, are counted in `Emitter.dropped` without a loop.
 */
export function spawnFrom(
  world: PhysicsWorld,
  b: ParticleBook,
  em: number,
  count: number,
  x: number,
  y: number,
  z: number,
  vx: number,
  vy: number,
  vz: number,
  generation: number,
): void {
  const E = world.components.Emitter;
  const n = takeBudget(world, b, count);
  if (n < count) E.dropped[em] = E.dropped[em]! + (count - n);
  const k = E.inherit[em]!;
  let a = archetypeFor(world, em);
  let kind = particleKind(world, em),
    heading = headingOf(world, em);
  const bx = k * vx,
    by = k * vy,
    bz = k * vz;
  setOrigin(x, y, z, bx, by, bz, heading);
  const ix = world.entityIndex;
  // An integer (generations are at most 1000; bursts carry them in a Float64Array): passed on unboxed.
  const gen = generation | 0;
  for (let i = 0; i < n; i++) {
    if (a !== undefined && b.birthHooks.length === 0 && ix.aliveCount < world.capacity) {
      queueBirth(world, b, em, gen, a, kind);
      continue;
    }
    // The births queued so far are written before anything else may look at the world (removal or birth hooks).
    flushBirths(world);
    // A birth hook of the last birth may have spawned from another emitter: `origin` is this batch's again.
    setOrigin(x, y, z, bx, by, bz, heading);
    if (spawnOne(world, b, em, gen, a, kind) === 0) {
      // The world is full and the policy could not make room: the rest of this batch cannot fit either.
      E.dropped[em] = E.dropped[em]! + (n - i - 1);
      return;
    }
    // A birth hook may have changed the emitter (setEmitter): the next birth follows it.
    if (a === undefined || b.birthHooks.length > 0) {
      a = archetypeFor(world, em);
      kind = particleKind(world, em);
      heading = headingOf(world, em);
      setOrigin(x, y, z, bx, by, bz, heading);
    }
  }
}
