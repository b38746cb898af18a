import { addComponent, query as bitecsQuery, entityExists, hasComponent, noCommit, removeEntity } from 'bitecs';
import { installBalls } from '../collision/install-balls.js';
import { DEFAULT_MATERIAL } from '../world/components.js';
import { NonFiniteStateError } from '../world/errors.js';
import { registerExternalWorldState } from '../world/external-state.js';
import { createSlot, currentHandle, resolveKind } from '../world/handles.js';
import { installSystem } from '../world/install.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { trustFiniteOutput } from '../world/trusted-systems.js';
import {
  assertBoolean,
  assertFinite,
  assertInRange,
  assertInteger,
  assertNonNegative,
  assertOneOf,
  assertOptionalBoolean,
  assertOptions,
  assertPositive,
  assertVector,
  describe,
} from '../world/validate.js';
import {
  type Archetype,
  applyQueuedBirths,
  archetypeFromEntity,
  archetypes,
  bornSlot,
  bornSlotQueued,
  defragment,
  ecsOf,
  killSlot,
  pendingArchetype,
  prepareArchetype,
  queuedPending,
} from './archetype.js';
import { nextSlot } from './bulk.js';

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
 * Emitter shapes: where a particle starts relative to the emitter.
 * @category Particles
 */
export const EmitterShape = Object.freeze({
  /** At the emitter. */
  Point: 0,
  /** Uniformly inside a disc (2D) or ball (3D) of radius `size`. */
  Disc: 1,
  /** On a circle (2D) or sphere (3D) of radius `size`. */
  Ring: 2,
  /** Uniformly inside a box of half extents (size, sizeY, sizeZ). */
  Box: 3,
  /** Uniformly along a segment of half length `size` along x. */
  Line: 4,
} as const);

/**
 * What an emitter does when the world is full: drop the new particle, or remove the oldest.
 * @category Particles
 */
export const CapacityPolicy = Object.freeze({ DropNew: 0, RecycleOldest: 1 } as const);

/**
 * Options of `addEmitter`. Vectors have `world.dimensions` components. Ranges are [min, max] or one number.
 * @category Particles
 */
export interface EmitterOptions {
  /**
   * Put the emitter on this existing body (a ship's exhaust, a firework shell): it emits from the
   * body's position and passes on the body's velocity. Exclusive with position and velocity.
   */
  attachTo?: number;
  /** Where a standalone emitter is, m. */
  position?: ArrayLike<number>;
  /** A standalone emitter's velocity, m/s: it then moves as a kinematic body (no gravity). */
  velocity?: ArrayLike<number>;
  /** Particles per second, in [0, MAX_EMITTER_RATE = 1e9]. Default 0 (bursts only). At most `maxSpawnsPerStep` a step are spawned; the rest count in `Emitter.dropped`. */
  rate?: number;
  /** Spawn shape. Default 'point'. */
  shape?: 'point' | 'disc' | 'ring' | 'box' | 'line';
  /** Radius (disc, ring), half extents (box) or half length (line), m. A number or [x, y(, z)]. */
  size?: number | ArrayLike<number>;
  /** Mean direction of emission (normalised here). Default up. */
  direction?: ArrayLike<number>;
  /** Half-angle of the emission cone (2D: fan), rad, in [0, pi]. Default pi (every direction). */
  spread?: number;
  /** Launch speed range, m/s, >= 0. Default [1, 2]. */
  speed?: number | [number, number];
  /** Lifetime range, s, > 0. Default [1, 2]. */
  lifetime?: number | [number, number];
  /** Fraction of the emitter's (or dying parent's) velocity added to each particle, in [0, 1]. Default 0. */
  inheritVelocity?: number;
  /** What particles carry. */
  particle?: EmittedParticleOptions;
  /** Burst into particles of another emitter when a particle of this one dies. */
  onDeath?: { emitter: number; count: number; maxGeneration: number };
  /** Full-world policy. Default 'drop-new'. */
  policy?: 'drop-new' | 'recycle-oldest';
  /** Whether it emits at its rate. Default true. */
  enabled?: boolean;
}

/**
 * Per-particle properties an emitter hands out.
 * @category Particles
 */
export interface EmittedParticleOptions {
  /** Mass, kg, > 0. Needed for force laws (attractors, drag); default 0 = a bare particle that feels gravity only. */
  mass?: number;
  /** Linear drag coefficient, N s/m (>= 0; needs no mass: one is given). */
  linearDrag?: number;
  /** Quadratic drag coefficient, kg/m (>= 0). */
  quadraticDrag?: number;
  /** Gravity scale (1 = normal). */
  gravityScale?: number;
  /** Collider radius, m (> 0 makes particles collide: splashes on the ground). Default none. */
  radius?: number;
  /** Colour at birth and death, 0xRRGGBB. Default white to white. */
  colorStart?: number;
  colorEnd?: number;
  /** Drawn size at birth and death, m (>= 0). Default 0.1 to 0.1. */
  sizeStart?: number;
  sizeEnd?: number;
  /** Opacity at birth and death, [0, 1]. Default 1 to 0 (fading). */
  alphaStart?: number;
  alphaEnd?: number;
}

/**
 * A hook run for every particle that expires, before it is removed. `eid` is the particle's slot (as
 * `query()` gives it: index stores with it directly; `handleOf(world, eid)` for API calls).
 * @category Particles
 */
export type ParticleDeathHook = (world: PhysicsWorld, eid: number) => void;

/**
 * A hook run for every particle an emitter spawns, once it is complete (position, velocity, lifetime,
 * look and the emitter's force components written). `eid` is the particle's slot (as `query()` gives
 * it; `handleOf(world, eid)` for API calls). The place to give every particle a component of your
 * own (`addComponent(world, eid, world.components.Charge)` and its value): emitters make particles
 * without bitecs' onAdd observers.
 * @category Particles
 */
export type ParticleBirthHook = (world: PhysicsWorld, eid: number) => void;

/**
 * Largest emitter rate the API accepts, particles/s: 1e9. With the largest time step (1e6 s) rate x dt
 * stays below 2^53, so the whole particles and the carried fraction of each step are exact.
 * @category Particles
 */
export const MAX_EMITTER_RATE = 1e9;

/**
 * Most particles one step spawns over all emitters and death bursts: the world's capacity (more could
 * not all be alive at the end of the step). The excess is counted in `Emitter.dropped`.
 * @category Particles
 */
export function maxSpawnsPerStep(world: PhysicsWorld): number {
  return world.capacity;
}

interface ParticleBook {
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

const books = new WeakMap<PhysicsWorld, ParticleBook>();
registerExternalWorldState({
  name: 'particles',
  get: (world, create) => (create ? book(world) : books.get(world)),
  clear: (world) => {
    books.delete(world);
  },
  keep: ['hooks', 'birthHooks'],
});

/**
 * The particle book of `world`, made on first use.
 * @category Particles
 */
export function book(world: PhysicsWorld): ParticleBook {
  let b = books.get(world);
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
    books.set(world, b);
  }
  return b;
}

function pushParticle(world: PhysicsWorld, b: ParticleBook, e: number): void {
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
function recycleOldest(world: PhysicsWorld, b: ParticleBook): boolean {
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

const sample = new Float64Array(6);

/**
 * The 2D heading of emitter `em`'s mean direction, rad (atan2 of its unit direction): the same for
 * every particle of a batch, so it is worked out once a batch (`draw` takes it).
 */
function headingOf(world: PhysicsWorld, em: number): number {
  const E = world.components.Emitter;
  return Math.atan2(E.dirY[em]!, E.dirX[em]!);
}

/**
 * Where the particles of the batch being spawned start and what they inherit: x, y, z (m), the
 * inherited velocity bx, by, bz (m/s, already scaled by the emitter's fraction) and the 2D heading of
 * the emitter (`headingOf`, rad). Set by the batch's caller (spawnFrom, emitNow) before each birth it
 * asks for, read by `draw`, `spawnOne` and `queueBirth`: numbers passed as arguments to a call that
 * is not inlined are boxed, which allocated some 16 bytes a number a birth (312 kB a step in a
 * fountain of a million particles).
 */
const origin = new Float64Array(7);

/** Fills `origin` for the births of a batch. */
function setOrigin(x: number, y: number, z: number, bx: number, by: number, bz: number, heading: number): void {
  origin[0] = x;
  origin[1] = y;
  origin[2] = z;
  origin[3] = bx;
  origin[4] = by;
  origin[5] = bz;
  origin[6] = heading;
}

/**
 * Draws a start offset and velocity for a particle of emitter `em` (into `sample`): shape offset,
 * direction within the spread, speed in range; the 2D heading is `origin[6]` (`headingOf(world, em)`).
 */
function draw(world: PhysicsWorld, em: number): void {
  const E = world.components.Emitter;
  const rng = world.rng;
  const is3D = world.dimensions === 3;
  let ox = 0,
    oy = 0,
    oz = 0;
  const shape = E.shape[em]!,
    s = E.size[em]!;
  if (shape === EmitterShape.Disc || shape === EmitterShape.Ring) {
    if (is3D) {
      const z = rng.range(-1, 1),
        a = rng.range(0, 2 * Math.PI),
        r = Math.sqrt(1 - z * z);
      const rad = shape === EmitterShape.Ring ? s : s * Math.cbrt(rng.next());
      ox = rad * r * Math.cos(a);
      oy = rad * r * Math.sin(a);
      oz = rad * z;
    } else {
      const a = rng.range(0, 2 * Math.PI);
      const rad = shape === EmitterShape.Ring ? s : s * Math.sqrt(rng.next());
      ox = rad * Math.cos(a);
      oy = rad * Math.sin(a);
    }
  } else if (shape === EmitterShape.Box) {
    ox = rng.range(-s, s);
    oy = rng.range(-E.sizeY[em]!, E.sizeY[em]!);
    oz = is3D ? rng.range(-E.sizeZ[em]!, E.sizeZ[em]!) : 0;
  } else if (shape === EmitterShape.Line) {
    ox = rng.range(-s, s);
  }
  const speed = rng.range(E.speedMin[em]!, E.speedMax[em]!);
  const spread = E.spread[em]!;
  const dx = E.dirX[em]!,
    dy = E.dirY[em]!,
    dz = E.dirZ[em]!;
  let vx: number, vy: number, vz: number;
  if (!is3D) {
    const a = origin[6]! + rng.range(-spread, spread);
    vx = Math.cos(a);
    vy = Math.sin(a);
    vz = 0;
  } else {
    // Uniform in the cone of half-angle `spread` about d: cos(theta) uniform in [cos spread, 1].
    const ct = rng.range(Math.cos(spread), 1),
      st = Math.sqrt(Math.max(0, 1 - ct * ct)),
      phi = rng.range(0, 2 * Math.PI);
    // Orthonormal basis (u, w) perpendicular to d.
    let ux: number, uy: number, uz: number;
    if (Math.abs(dx) < 0.9) {
      ux = 0;
      uy = dz;
      uz = -dy;
    } else {
      ux = -dz;
      uy = 0;
      uz = dx;
    }
    const un = Math.hypot(ux, uy, uz);
    ux /= un;
    uy /= un;
    uz /= un;
    const wx = dy * uz - dz * uy,
      wy = dz * ux - dx * uz,
      wz = dx * uy - dy * ux;
    const cp = Math.cos(phi) * st,
      sp = Math.sin(phi) * st;
    vx = ct * dx + cp * ux + sp * wx;
    vy = ct * dy + cp * uy + sp * wy;
    vz = ct * dz + cp * uz + sp * wz;
  }
  sample[0] = ox;
  sample[1] = oy;
  sample[2] = oz;
  sample[3] = vx * speed;
  sample[4] = vy * speed;
  sample[5] = vz * speed;
}

/**
 * The particle kind of emitter `em`: which components its particles carry beyond Position, Velocity,
 * Lifetime and Particle, as bits (1: mass and a force accumulator, 2: LinearDrag, 4: QuadraticDrag,
 * 8: GravityScale, 16: Ball). Particles of one kind share an archetype.
 */
function particleKind(world: PhysicsWorld, em: number): number {
  const E = world.components.Emitter;
  const mass = E.mass[em]!,
    ld = E.linearDrag[em]!,
    qd = E.quadraticDrag[em]!,
    gs = E.gravityScale[em]!,
    r = E.radius[em]!;
  if (!(mass > 0 || ld > 0 || qd > 0 || gs !== 1 || r > 0)) return 0;
  return 1 | (ld > 0 ? 2 : 0) | (qd > 0 ? 4 : 0) | (gs !== 1 ? 8 : 0) | (r > 0 ? 16 : 0);
}

/**
 * The archetype of emitter `em`'s particles, ready for a batch of births (`prepareArchetype`), or
 * undefined if no particle of its kind was made yet in this world, or a store of the kind has no
 * arrays (the next particle then goes through bitecs).
 */
function archetypeFor(world: PhysicsWorld, em: number): Archetype | undefined {
  const a = archetypes(world).byKey.get(particleKind(world, em));
  return a !== undefined && prepareArchetype(world, a) ? a : undefined;
}

/**
 * Spawns one particle of emitter `em` at (x, y, z) + shape offset with inherited velocity
 * (bx, by, bz) (already scaled), applying the capacity policy. `a` is the archetype of the emitter's
 * particles (from `archetypeFor`), or undefined to make the first one of its kind through bitecs.
 * `kind` and `heading` are the batch's `particleKind` and `headingOf` of the emitter (they do not
 * change within a batch: no user code runs between its births but birth hooks, which a batch
 * re-reads them after). Returns the entity or 0 if dropped.
 */
function spawnOne(world: PhysicsWorld, b: ParticleBook, em: number, generation: number, a: Archetype | undefined, kind: number): number {
  const x = origin[0]!,
    y = origin[1]!,
    z = origin[2]!,
    bx = origin[3]!,
    by = origin[4]!,
    bz = origin[5]!;
  const c = world.components;
  const E = c.Emitter;
  if (world.entityIndex.aliveCount >= world.capacity) {
    if (E.policy[em] !== CapacityPolicy.RecycleOldest || !recycleOldest(world, b)) {
      E.dropped[em] = E.dropped[em]! + 1;
      return 0;
    }
    // The removal hooks may have removed entities through bitecs.
    if (a !== undefined && !prepareArchetype(world, a)) a = undefined;
  }
  draw(world, em);
  const px = x + sample[0]!,
    py = y + sample[1]!,
    pz = z + sample[2]!;
  const vx = sample[3]! + bx,
    vy = sample[4]! + by,
    vz = sample[5]! + bz;
  // x * 0 is NaN exactly when x is NaN or infinite: refuse the spawn before creating anything.
  if (px * 0 + py * 0 + pz * 0 + vx * 0 + vy * 0 + vz * 0 !== 0) nonFiniteSpawn(world, em, px, py, pz, vx, vy, vz);
  let e: number;
  if (a === undefined) {
    e = spawnThroughBitecs(world, em);
  } else {
    e = bornSlot(world, a);
    // What bitecs' observers write when these components are added (create-world.ts), then the
    // particle (stores a world allocates lazily may have no arrays yet: nothing to reset there).
    const W = c.AngularVelocity,
      F = c.Force,
      T = c.Torque;
    if (W.x.length > e) {
      W.x[e] = 0;
      W.y[e] = 0;
      W.z[e] = 0;
    }
    if (F.x.length > e) {
      F.x[e] = 0;
      F.y[e] = 0;
      F.z[e] = 0;
    }
    if (T.x.length > e) {
      T.x[e] = 0;
      T.y[e] = 0;
      T.z[e] = 0;
    }
    if (kind !== 0) {
      const mass = E.mass[em]!,
        m = mass > 0 ? mass : 1;
      c.Mass.value[e] = m;
      c.Mass.inv[e] = 1 / m;
      if ((kind & 2) !== 0) c.LinearDrag.k[e] = E.linearDrag[em]!;
      if ((kind & 4) !== 0) c.QuadraticDrag.k[e] = E.quadraticDrag[em]!;
      if ((kind & 8) !== 0) c.GravityScale.value[e] = E.gravityScale[em]!;
      if ((kind & 16) !== 0) {
        c.Ball.radius[e] = E.radius[em]!;
        const M = c.Material;
        M.restitution[e] = DEFAULT_MATERIAL.restitution;
        M.friction[e] = DEFAULT_MATERIAL.friction;
        M.staticFriction[e] = DEFAULT_MATERIAL.friction;
      }
    }
  }
  c.Position.x[e] = px;
  c.Position.y[e] = py;
  c.Position.z[e] = pz;
  c.PreviousPosition.x[e] = px;
  c.PreviousPosition.y[e] = py;
  c.PreviousPosition.z[e] = pz;
  c.Velocity.x[e] = vx;
  c.Velocity.y[e] = vy;
  c.Velocity.z[e] = vz;
  const L = c.Lifetime;
  L.age[e] = 0;
  L.duration[e] = world.rng.range(E.lifeMin[em]!, E.lifeMax[em]!);
  const P = c.Particle;
  P.emitter[e] = em;
  P.emitterStamp[e] = world.spawnStamp[em]!;
  P.generation[e] = generation;
  P.colorStart[e] = E.colorStart[em]!;
  P.colorEnd[e] = E.colorEnd[em]!;
  P.sizeStart[e] = E.sizeStart[em]!;
  P.sizeEnd[e] = E.sizeEnd[em]!;
  P.alphaStart[e] = E.alphaStart[em]!;
  P.alphaEnd[e] = E.alphaEnd[em]!;
  pushParticle(world, b, e);
  E.spawned[em] = E.spawned[em]! + 1;
  const hooks = b.birthHooks;
  for (let h = 0; h < hooks.length; h++) hooks[h]!(world, e);
  return e;
}

/**
 * Births made but not yet written (`queueBirth`, `flushBirths`): each birth's slot, emitter, kind,
 * generation, position, velocity and lifetime, up to `QUEUE` of them. The component stores are then
 * written one array at a time over the queued births instead of every array once a birth: a step's
 * births land in slots scattered over the whole capacity, and writing some thirty arrays per birth
 * touched a different memory page of each (with 4 kB pages, a world of 60,000 slots spreads the
 * stores over some 4,000 pages, more than the processor's address cache holds), which made each
 * birth's writes about twice as slow as the same writes taken one array at a time (measured: 1,000
 * births into 35 arrays of 62,565 doubles, 0.56 ms particle by particle against 0.29 ms array by array).
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
function queueBirth(world: PhysicsWorld, b: ParticleBook, em: number, generation: number, a: Archetype, kind: number): void {
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
function flushBirths(world: PhysicsWorld): void {
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
  const W = c.AngularVelocity,
    F = c.Force,
    T = c.Torque;
  if (W.x.length > world.capacity) {
    zeroAt(W.x, S, n);
    zeroAt(W.y, S, n);
    zeroAt(W.z, S, n);
  }
  if (F.x.length > world.capacity) {
    zeroAt(F.x, S, n);
    zeroAt(F.y, S, n);
    zeroAt(F.z, S, n);
  }
  if (T.x.length > world.capacity) {
    zeroAt(T.x, S, n);
    zeroAt(T.y, S, n);
    zeroAt(T.z, S, n);
  }
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

/** T[S[k]] = from[EM[k]] for k < n: a field every particle takes from its emitter. */
function lookAt(T: Writable, from: ArrayLike<number>, S: Int32Array, EM: Int32Array, n: number): void {
  for (let k = 0; k < n; k++) T[S[k]!] = from[EM[k]!]!;
}

/** `lookAt` for the births whose kind has `bit`. */
function perKind(bit: number, T: Writable, from: ArrayLike<number>, S: Int32Array, EM: Int32Array, K: Uint8Array, n: number): void {
  for (let k = 0; k < n; k++) if ((K[k]! & bit) !== 0) T[S[k]!] = from[EM[k]!]!;
}

/**
 * The first particle of a kind: made through bitecs (observers write the defaults, allocate lazy
 * stores and add dependent components), and its component set registered as the kind's archetype.
 * Returns its slot; the caller writes position, velocity, lifetime and look.
 */
function spawnThroughBitecs(world: PhysicsWorld, em: number): number {
  const pending = pendingArchetype(archetypes(world), nextSlot(world));
  const c = world.components;
  const E = c.Emitter;
  const e = createSlot(world, 'emitter');
  addComponent(world, e, c.Position);
  addComponent(world, e, c.Velocity);
  addComponent(world, e, c.Lifetime);
  addComponent(world, e, c.Particle);
  const mass = E.mass[em]!,
    ld = E.linearDrag[em]!,
    qd = E.quadraticDrag[em]!,
    gs = E.gravityScale[em]!,
    r = E.radius[em]!;
  if (mass > 0 || ld > 0 || qd > 0 || gs !== 1 || r > 0) {
    addComponent(world, e, c.Mass);
    const m = mass > 0 ? mass : 1;
    c.Mass.value[e] = m;
    c.Mass.inv[e] = 1 / m;
    addComponent(world, e, c.Force);
    if (ld > 0) {
      addComponent(world, e, c.LinearDrag);
      c.LinearDrag.k[e] = ld;
    }
    if (qd > 0) {
      addComponent(world, e, c.QuadraticDrag);
      c.QuadraticDrag.k[e] = qd;
    }
    if (gs !== 1) {
      addComponent(world, e, c.GravityScale);
      c.GravityScale.value[e] = gs;
    }
    if (r > 0) {
      addComponent(world, e, c.Ball);
      c.Ball.radius[e] = r;
    }
  }
  archetypeFromEntity(world, archetypes(world), particleKind(world, em), e, pending);
  return e;
}

/**
 * Throws the NonFiniteStateError of a particle emitter `em` would spawn at a non-finite position or
 * velocity (an emitter placed or moving near the largest double), naming the emitter.
 */
function nonFiniteSpawn(world: PhysicsWorld, em: number, px: number, py: number, pz: number, vx: number, vy: number, vz: number): never {
  const values: Array<[string, number]> = [
    ['Position.x', px],
    ['Position.y', py],
    ['Position.z', pz],
    ['Velocity.x', vx],
    ['Velocity.y', vy],
    ['Velocity.z', vz],
  ];
  const [field, value] = values.find(([, v]) => !Number.isFinite(v))!;
  const P = world.components.Position;
  throw new NonFiniteStateError(
    currentHandle(world, em),
    field,
    value,
    'spawn',
    `It is emitter ${currentHandle(world, em)} at (${P.x[em]}, ${P.y[em]}, ${P.z[em]}) m, and a particle it would spawn there has that ${field}; nothing was spawned.`,
  );
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
function spawnFrom(
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

/**
 * Stage 1, first: ages every particle by dt, and removes the ones whose lifetime ran out, after
 * running the death hooks and recording bursts into their emitter's death emitter (if the particle's
 * generation is below the limit); then spawns the bursts. Every expiring particle's hooks (the
 * `onParticleDeath` hooks, then the world's removal hooks) run before any of them is removed, and the
 * removals come after the pass over the live list (bitecs trap). Births of the bursts reuse the slots
 * just freed in place (see archetype.ts), so steady churn leaves the query lists in slot order.
 * @category Particles
 */
export function lifetimeSystem(world: PhysicsWorld): void {
  const c = world.components;
  const ents = query(world, [c.Lifetime]);
  if (ents.length === 0) return;
  const b = book(world);
  const L = c.Lifetime,
    P = c.Particle,
    E = c.Emitter;
  const dt = world.dt;
  // A particle expires at the first step whose end reaches its lifetime; the slack absorbs the
  // rounding of summed steps (thirty steps of 1/60 s add up to just under 0.5 s).
  const slack = 1e-9 * dt;
  const age = L.age,
    duration = L.duration;
  const stamps = world.spawnStamp,
    expired = b.expired,
    expiredStamps = b.expiredStamps;
  let n = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const a = age[e]! + dt;
    age[e] = a;
    if (a >= duration[e]! - slack) {
      expired[n] = e;
      expiredStamps[n] = stamps[e]!;
      n++;
    }
  }
  if (n === 0) return;
  const px = c.Position.x,
    py = c.Position.y,
    pz = c.Position.z,
    vx = c.Velocity.x,
    vy = c.Velocity.y,
    vz = c.Velocity.z;
  b.burstCount = 0;
  const hooks = b.hooks,
    removeHooks = world.removeHooks;
  // Without death hooks, an expiring particle can only be gone if a removal hook removed entities
  // (they remove springs and joints, never create): check liveness only once the live count moved.
  const ix = world.entityIndex,
    alive0 = ix.aliveCount;
  // The death emitter of the last emitter looked at (0: none, -1: not looked at): particles of one
  // emitter die together. Valid while no user hook runs (a hook may remove an emitter).
  let lastEm = 0,
    lastStamp = 0,
    lastTarget = -1;
  // hasComponent(world, e, Particle) read from the masks directly (it looks the component up in a Map per call).
  const ecs = ecsOf(world);
  // (The mask array is read per particle: a hook's first churn may swap it for a typed one, archetype.ts typedMasks.)
  const pData = ecs.componentMap.get(P)!,
    pGen = pData.generationId,
    pFlag = pData.bitflag,
    masks = ecs.entityMasks;
  // Hooks first, for every expiring particle still alive (a hook may remove another one).
  for (let k = 0; k < n; k++) {
    const e = expired[k]!;
    if ((hooks.length > 0 || ix.aliveCount !== alive0) && (stamps[e] !== expiredStamps[k] || !entityExists(world, e))) continue;
    if (hooks.length > 0) {
      for (let h = 0; h < hooks.length; h++) hooks[h]!(world, e);
      lastTarget = -1;
      if (stamps[e] !== expiredStamps[k] || !entityExists(world, e)) continue;
    }
    if ((masks[pGen]![e]! & pFlag) === pFlag) {
      const em = P.emitter[e]!;
      if (lastTarget < 0 || em !== lastEm || P.emitterStamp[e] !== lastStamp) {
        lastEm = em;
        lastStamp = P.emitterStamp[e]!;
        lastTarget = 0;
        if (em > 0 && stamps[em] === lastStamp && entityExists(world, em) && hasComponent(world, em, E)) {
          const target = E.deathEmitter[em]!;
          if (target > 0 && entityExists(world, target) && hasComponent(world, target, E)) lastTarget = target;
        }
      }
      if (lastTarget > 0) {
        const target = lastTarget,
          gen = P.generation[e]!;
        if (gen < E.maxGeneration[em]!) {
          if ((b.burstCount + 1) * 9 > b.bursts.length) {
            const nb = new Float64Array(b.bursts.length * 2);
            nb.set(b.bursts);
            b.bursts = nb;
          }
          const o = b.burstCount++ * 9;
          const B = b.bursts;
          B[o] = px[e]!;
          B[o + 1] = py[e]!;
          B[o + 2] = pz[e]!;
          B[o + 3] = vx[e]!;
          B[o + 4] = vy[e]!;
          B[o + 5] = vz[e]!;
          B[o + 6] = target;
          B[o + 7] = E.deathCount[em]!;
          B[o + 8] = gen + 1;
        }
      }
    }
    for (let h = 0; h < removeHooks.length; h++) removeHooks[h]!(world, e);
  }
  // Then the removals, and the bursts' births into the freed slots.
  const table = archetypes(world);
  const sure = hooks.length === 0 && ix.aliveCount === alive0;
  for (let k = 0; k < n; k++) {
    const e = expired[k]!;
    if (!sure && (stamps[e] !== expiredStamps[k] || !entityExists(world, e))) continue;
    if (!killSlot(world, ecs, table, e)) removeEntity(world, e);
    b.expiredTotal++;
  }
  // Death bursts need emitters, whose code installEmitters brings (none made, no burst: b.burstCount is 0).
  if (spawnBursts !== null) spawnBursts(world, b);
}

/**
 * The death bursts of the expired particles (b.bursts, b.burstCount) born into the freed slots, and
 * every queued birth flushed: set by installEmitters, so lifetimes alone do not bring the spawning code.
 */
let spawnBursts: ((world: PhysicsWorld, b: ParticleBook) => void) | null = null;

/** The bursts of lifetimeSystem's expired particles (see spawnBursts). */
function spawnDeathBursts(world: PhysicsWorld, b: ParticleBook): void {
  const B = b.bursts;
  for (let k = 0; k < b.burstCount; k++) {
    const o = k * 9;
    spawnFrom(world, b, B[o + 6]!, B[o + 7]!, B[o]!, B[o + 1]!, B[o + 2]!, B[o + 3]!, B[o + 4]!, B[o + 5]!, B[o + 8]!);
  }
  flushBirths(world);
}

let emittersTrusted = false;

/**
 * Installs the emitters' system into `world`'s spawn stage at its place (world/install.ts; idempotent),
 * as `addEmitter` does for the first emitter and a snapshot restore does: a program that never makes
 * an emitter does not bundle it (nor the death bursts of lifetimeSystem, which need emitters). The
 * system checks the particles it spawns itself (step/finite.ts).
 * @category Particles
 */
export function installEmitters(world: PhysicsWorld): void {
  if (!emittersTrusted) {
    emittersTrusted = true;
    trustFiniteOutput([emitterSystem]);
    spawnBursts = spawnDeathBursts;
  }
  installSystem(world, 'spawn', 'emitter', emitterSystem);
}

/**
 * Stage 1, second: every enabled emitter spawns rate x dt particles (the fraction carried to the
 * next step) plus any burst requested with `burst`, within the step's budget (`maxSpawnsPerStep`;
 * the excess is counted in `Emitter.dropped`). A rate x dt of 2^53 or more (possible only by writing
 * `Emitter.rate` directly past `MAX_EMITTER_RATE`) or not finite asks for 2^53 particles and carries
 * nothing. Runs in O(spawned) time, at most O(capacity) a step.
 * @throws NonFiniteStateError (stage 'spawn') if a particle would start at a non-finite position or
 *   velocity; it names the emitter, and nothing is spawned for it.
 * @category Particles
 */
export function emitterSystem(world: PhysicsWorld): void {
  const c = world.components;
  // Without committing pending removals (bitecs' noCommit): the particles that expired this step keep
  // their places in the query lists for the births below. An emitter removed but not yet committed
  // is skipped.
  const ems = bitecsQuery(world as never, [c.Emitter, c.Position], noCommit);
  if (ems.length === 0) return;
  const b = book(world);
  const E = c.Emitter;
  const dt = world.dt;
  const px = c.Position.x,
    py = c.Position.y,
    pz = c.Position.z,
    vx = c.Velocity.x,
    vy = c.Velocity.y,
    vz = c.Velocity.z;
  for (let i = 0; i < ems.length; i++) {
    const em = ems[i]!;
    if (!entityExists(world, em) || !hasComponent(world, em, E)) continue;
    let n = E.pendingBurst[em]!;
    E.pendingBurst[em] = 0;
    if (E.enabled[em] === 1 && E.rate[em]! > 0) {
      const carry = E.carry[em]! + E.rate[em]! * dt;
      if (carry < 9007199254740992) {
        const whole = Math.floor(carry);
        E.carry[em] = carry - whole;
        n += whole;
      } else {
        E.carry[em] = 0;
        n += 9007199254740992;
      }
    }
    if (n === 0) continue;
    const moving = hasComponent(world, em, c.Velocity);
    spawnFrom(world, b, em, n, px[em]!, py[em]!, pz[em]!, moving ? vx[em]! : 0, moving ? vy[em]! : 0, moving ? vz[em]! : 0, 0);
  }
  flushBirths(world);
  // Once a step, after the births that could take the expired particles' places.
  defragment(world, archetypes(world));
}

function range(where: string, name: string, v: number | [number, number], positive: boolean): [number, number] {
  const pair: [number, number] = typeof v === 'number' ? [v, v] : v;
  if (!Array.isArray(pair) || pair.length !== 2)
    throw new TypeError(`${where}: ${name} must be a number or [min, max], got ${describe(v)}`);
  for (let i = 0; i < 2; i++) {
    if (positive) assertPositive(where, `${name}[${i}]`, pair[i]);
    else assertNonNegative(where, `${name}[${i}]`, pair[i]);
  }
  if (!(pair[1] >= pair[0])) throw new RangeError(`${where}: ${name} must be [min, max] with max >= min, got ${describe(v)}`);
  return [pair[0], pair[1]];
}

const SHAPE_NAMES = ['point', 'disc', 'ring', 'box', 'line'] as const;
const SHAPES: Record<(typeof SHAPE_NAMES)[number], number> = { point: 0, disc: 1, ring: 2, box: 3, line: 4 };
const SETTINGS = [
  'rate',
  'shape',
  'size',
  'direction',
  'spread',
  'speed',
  'lifetime',
  'inheritVelocity',
  'particle',
  'onDeath',
  'policy',
  'enabled',
] as const;
const PARTICLE_OPTIONS = [
  'mass',
  'linearDrag',
  'quadraticDrag',
  'gravityScale',
  'radius',
  'colorStart',
  'colorEnd',
  'sizeStart',
  'sizeEnd',
  'alphaStart',
  'alphaEnd',
] as const;

/** Emitter settings after checking: only the ones given, in store units. */
interface CheckedSettings {
  rate?: number;
  shape?: number;
  size?: [number, number, number];
  dir?: [number, number, number];
  spread?: number;
  speed?: [number, number];
  life?: [number, number];
  inherit?: number;
  policy?: number;
  enabled?: boolean;
  particle?: EmittedParticleOptions;
  onDeath?: { slot: number; count: number; maxGeneration: number };
}

/**
 * Checks the settings shared by addEmitter and setEmitter without touching the world (keys were
 * checked by the caller). @throws TypeError | RangeError naming `where`.
 */
function checkSettings(
  world: PhysicsWorld,
  where: string,
  options: Omit<EmitterOptions, 'attachTo' | 'position' | 'velocity'>,
): CheckedSettings {
  const d = world.dimensions;
  const out: CheckedSettings = {};
  if (options.rate !== undefined) {
    assertInRange(where, 'rate', options.rate, 0, MAX_EMITTER_RATE);
    out.rate = options.rate;
  }
  if (options.shape !== undefined) {
    assertOneOf(where, 'shape', options.shape, SHAPE_NAMES);
    out.shape = SHAPES[options.shape];
  }
  if (options.size !== undefined) {
    if (typeof options.size === 'number') {
      assertNonNegative(where, 'size', options.size);
      out.size = [options.size, options.size, options.size];
    } else {
      assertVector(where, 'size', options.size, d);
      for (let i = 0; i < d; i++) assertNonNegative(where, `size[${i}]`, options.size[i]);
      out.size = [options.size[0]!, options.size[1]!, d === 3 ? options.size[2]! : 0];
    }
  }
  if (options.direction !== undefined) {
    assertVector(where, 'direction', options.direction, d);
    const x = options.direction[0]!,
      y = options.direction[1]!,
      z = d === 3 ? options.direction[2]! : 0;
    const n = Math.hypot(x, y, z);
    if (!(n > 0)) throw new RangeError(`${where}: direction must not be zero, got ${describe(options.direction)}`);
    out.dir = [x / n, y / n, z / n];
  }
  if (options.spread !== undefined) {
    assertInRange(where, 'spread', options.spread, 0, Math.PI);
    out.spread = options.spread;
  }
  if (options.speed !== undefined) out.speed = range(where, 'speed', options.speed, false);
  if (options.lifetime !== undefined) out.life = range(where, 'lifetime', options.lifetime, true);
  if (options.inheritVelocity !== undefined) {
    assertInRange(where, 'inheritVelocity', options.inheritVelocity, 0, 1);
    out.inherit = options.inheritVelocity;
  }
  if (options.policy !== undefined) {
    assertOneOf(where, 'policy', options.policy, ['drop-new', 'recycle-oldest']);
    out.policy = options.policy === 'recycle-oldest' ? CapacityPolicy.RecycleOldest : CapacityPolicy.DropNew;
  }
  assertOptionalBoolean(where, 'enabled', options.enabled);
  if (options.enabled !== undefined) out.enabled = options.enabled;
  const p = options.particle;
  if (p !== undefined) {
    assertOptions(where, p, PARTICLE_OPTIONS, 'particle');
    if (p.mass !== undefined) assertPositive(where, 'particle.mass', p.mass);
    if (p.linearDrag !== undefined) assertNonNegative(where, 'particle.linearDrag', p.linearDrag);
    if (p.quadraticDrag !== undefined) assertNonNegative(where, 'particle.quadraticDrag', p.quadraticDrag);
    if (p.gravityScale !== undefined) assertFinite(where, 'particle.gravityScale', p.gravityScale);
    if (p.radius !== undefined) assertPositive(where, 'particle.radius', p.radius);
    for (const k of ['colorStart', 'colorEnd'] as const) if (p[k] !== undefined) assertInteger(where, `particle.${k}`, p[k], 0, 0xffffff);
    for (const k of ['sizeStart', 'sizeEnd'] as const) if (p[k] !== undefined) assertNonNegative(where, `particle.${k}`, p[k]);
    for (const k of ['alphaStart', 'alphaEnd'] as const) if (p[k] !== undefined) assertInRange(where, `particle.${k}`, p[k], 0, 1);
    out.particle = p;
  }
  if (options.onDeath !== undefined) {
    const od = options.onDeath;
    assertOptions(where, od, ['emitter', 'count', 'maxGeneration'], 'onDeath');
    // 0 (setEmitter only) clears the death emitter.
    const slot = od.emitter === 0 && where === 'setEmitter' ? 0 : resolveKind(world, od.emitter, 'emitter', where, 'onDeath.emitter');
    assertInteger(where, 'onDeath.count', od.count, 0, 1_000_000);
    assertInteger(where, 'onDeath.maxGeneration', od.maxGeneration, 0, 1000);
    out.onDeath = { slot, count: od.count, maxGeneration: od.maxGeneration };
  }
  return out;
}

/** Writes checked settings into the emitter in slot `em`; settings not given keep their value. */
function writeSettings(world: PhysicsWorld, em: number, s: CheckedSettings): void {
  const E = world.components.Emitter;
  if (s.rate !== undefined) E.rate[em] = s.rate;
  if (s.shape !== undefined) E.shape[em] = s.shape;
  if (s.size) {
    E.size[em] = s.size[0];
    E.sizeY[em] = s.size[1];
    E.sizeZ[em] = s.size[2];
  }
  if (s.dir) {
    E.dirX[em] = s.dir[0];
    E.dirY[em] = s.dir[1];
    E.dirZ[em] = s.dir[2];
  }
  if (s.spread !== undefined) E.spread[em] = s.spread;
  if (s.speed) {
    E.speedMin[em] = s.speed[0];
    E.speedMax[em] = s.speed[1];
  }
  if (s.life) {
    E.lifeMin[em] = s.life[0];
    E.lifeMax[em] = s.life[1];
  }
  if (s.inherit !== undefined) E.inherit[em] = s.inherit;
  if (s.policy !== undefined) E.policy[em] = s.policy;
  if (s.enabled !== undefined) E.enabled[em] = s.enabled ? 1 : 0;
  const p = s.particle;
  if (p) {
    if (p.mass !== undefined) E.mass[em] = p.mass;
    if (p.linearDrag !== undefined) E.linearDrag[em] = p.linearDrag;
    if (p.quadraticDrag !== undefined) E.quadraticDrag[em] = p.quadraticDrag;
    if (p.gravityScale !== undefined) E.gravityScale[em] = p.gravityScale;
    if (p.radius !== undefined) E.radius[em] = p.radius;
    // Particles with a radius collide as balls (collision/install-balls.ts).
    if (p.radius !== undefined && p.radius > 0) installBalls(world);
    for (const k of ['colorStart', 'colorEnd', 'sizeStart', 'sizeEnd', 'alphaStart', 'alphaEnd'] as const)
      if (p[k] !== undefined) E[k][em] = p[k];
  }
  if (s.onDeath) {
    E.deathEmitter[em] = s.onDeath.slot;
    E.deathCount[em] = s.onDeath.count;
    E.maxGeneration[em] = s.onDeath.maxGeneration;
  }
}

/**
 * Adds an emitter entity (or puts one on an existing body with `attachTo`). Atomic: every option is
 * checked, and room for the emitter made sure of, before anything changes.
 * @returns the emitter's handle (the body's handle when attached).
 * @throws TypeError on options that are not an object, unknown or null options, a non-boolean `enabled`
 *   or malformed vectors; RangeError on negative rates, speeds or sizes, lifetimes <= 0, spread outside
 *   [0, pi], inherit outside [0, 1], an unknown shape or policy, an `attachTo` or `onDeath.emitter`
 *   that was removed or is of the wrong kind, or a full world.
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
  E.rate[em] = 0;
  E.carry[em] = 0;
  E.pendingBurst[em] = 0;
  E.enabled[em] = 1;
  E.shape[em] = EmitterShape.Point;
  E.size[em] = 0;
  E.sizeY[em] = 0;
  E.sizeZ[em] = 0;
  E.dirX[em] = 0;
  E.dirY[em] = 1;
  E.dirZ[em] = 0;
  E.spread[em] = Math.PI;
  E.speedMin[em] = 1;
  E.speedMax[em] = 2;
  E.lifeMin[em] = 1;
  E.lifeMax[em] = 2;
  E.inherit[em] = 0;
  E.mass[em] = 0;
  E.linearDrag[em] = 0;
  E.quadraticDrag[em] = 0;
  E.gravityScale[em] = 1;
  E.radius[em] = 0;
  const p = options.particle ?? {};
  E.colorStart[em] = 0xffffff;
  E.colorEnd[em] = p.colorStart ?? 0xffffff;
  E.sizeStart[em] = 0.1;
  E.sizeEnd[em] = p.sizeStart ?? 0.1;
  E.alphaStart[em] = 1;
  E.alphaEnd[em] = 0;
  E.deathEmitter[em] = 0;
  E.deathCount[em] = 0;
  E.maxGeneration[em] = 0;
  E.policy[em] = CapacityPolicy.DropNew;
  E.spawned[em] = 0;
  E.dropped[em] = 0;
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
  return books.get(world)?.expiredTotal ?? 0;
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
