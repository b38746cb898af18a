import { addComponent } from 'bitecs';
import { DEFAULT_MATERIAL, type Vec3Store } from '../world/components.js';
import { NonFiniteStateError } from '../world/errors.js';
import { createSlot, currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { type Archetype, archetypeFromEntity, archetypes, bornSlot, pendingArchetype, prepareArchetype } from './archetype.js';
import { nextSlot } from './bulk.js';
import { CapacityPolicy, EmitterShape } from './emitter-options.js';
import { type ParticleBook, pushParticle, recycleOldest } from './particle-book.js';

/**
 * One particle: drawn from its emitter (where it starts in the emitter's shape, its heading, speed,
 * lifetime and look, its archetype) and spawned, in bulk through the archetype tables (spawnOne) or
 * one by one through bitecs (spawnThroughBitecs).
 */

export const sample = new Float64Array(6);

/**
 * The 2D heading of emitter `em`'s mean direction, rad (atan2 of its unit direction): the same for
 * every particle of a batch, so it is worked out once a batch (`draw` takes it).
 */
export function headingOf(world: PhysicsWorld, em: number): number {
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
export const origin = new Float64Array(7);

/** Fills `origin` for the births of a batch. */
export function setOrigin(x: number, y: number, z: number, bx: number, by: number, bz: number, heading: number): void {
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
export function draw(world: PhysicsWorld, em: number): void {
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
    // A 3D burst seen from the side (projectSphere): cos(theta) uniform in [-1, 1], in-plane part sin(theta).
    let f = 1;
    if (E.projectSphere[em] === 1) {
      const c = rng.range(-1, 1);
      f = Math.sqrt(1 - c * c);
    }
    vx = Math.cos(a) * f;
    vy = Math.sin(a) * f;
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
export function particleKind(world: PhysicsWorld, em: number): number {
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
export function archetypeFor(world: PhysicsWorld, em: number): Archetype | undefined {
  const a = archetypes(world).byKey.get(particleKind(world, em));
  return a !== undefined && prepareArchetype(world, a) ? a : undefined;
}

/** v.x, v.y and v.z [e] = 0, when the store has arrays that long (a lazily allocated one may have none yet). */
function zeroVec(v: Vec3Store, e: number): void {
  if (v.x.length <= e) return;
  v.x[e] = 0;
  v.y[e] = 0;
  v.z[e] = 0;
}

/**
 * Spawns one particle of emitter `em` at (x, y, z) + shape offset with inherited velocity
 * (bx, by, bz) (already scaled), applying the capacity policy. `a` is the archetype of the emitter's
 * particles (from `archetypeFor`), or undefined to make the first one of its kind through bitecs.
 * `kind` and `heading` are the batch's `particleKind` and `headingOf` of the emitter (they do not
 * change within a batch: no user code runs between its births but birth hooks, which a batch
 * re-reads them after). Returns the entity or 0 if dropped.
 */
export function spawnOne(
  world: PhysicsWorld,
  b: ParticleBook,
  em: number,
  generation: number,
  a: Archetype | undefined,
  kind: number,
): number {
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
    zeroVec(c.AngularVelocity, e);
    zeroVec(c.Force, e);
    zeroVec(c.Torque, e);
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
export function nonFiniteSpawn(
  world: PhysicsWorld,
  em: number,
  px: number,
  py: number,
  pz: number,
  vx: number,
  vy: number,
  vz: number,
): never {
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
