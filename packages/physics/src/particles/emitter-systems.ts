import { query as bitecsQuery, entityExists, hasComponent, noCommit, removeEntity } from 'bitecs';
import { ecsOf } from '../world/ecs-internals.js';
import { installSystem } from '../world/install.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout, trustFiniteOutput } from '../world/trusted-systems.js';
import { archetypes, defragment, killSlot } from './archetype.js';
import { flushBirths, spawnFrom } from './birth-queue.js';
import { book, type ParticleBook } from './particle-book.js';

/** The particle systems of the step: the lifetime system (ageing, expiry, death bursts) and the emitter system (rates and bursts), and their installation on the first emitter. */

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
  const { x: px, y: py, z: pz } = c.Position,
    { x: vx, y: vy, z: vz } = c.Velocity;
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
  const { x: px, y: py, z: pz } = c.Position,
    { x: vx, y: vy, z: vz } = c.Velocity;
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

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(lifetimeSystem, (w) => [[w.components.Lifetime]]);
