import { installBalls } from '../collision/install-balls.js';
import * as check from '../validation/validate.js';
import { resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';

/** The options of emitters and their particles: types, bounds, and the checks and writes shared by addEmitter and setEmitter. */

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
  /**
   * 2D worlds only: emit as a 3D burst seen from the side. Each particle also draws a polar angle
   * theta with cos(theta) uniform in [-1, 1] (a direction uniform on the sphere) and keeps only the
   * part of its velocity in the world's plane: in-plane speed = speed * sin(theta), direction from the
   * fan as usual. A burst of equal speeds then fills a disc densest at its rim, as a spherical shell
   * of stars looks in projection, instead of a ring. Only the launch is projected: drag and gravity
   * then act on the in-plane velocity, so under quadratic drag (which slows the fast particles most)
   * the disc's middle thins as it spreads. Default false. @throws RangeError in a 3D world.
   */
  projectSphere?: boolean;
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

function range(where: string, name: string, v: number | [number, number], positive: boolean): [number, number] {
  const pair: [number, number] = typeof v === 'number' ? [v, v] : v;
  if (!Array.isArray(pair) || pair.length !== 2)
    throw new TypeError(`${where}: ${name} must be a number or [min, max], got ${check.describe(v)}`);
  for (let i = 0; i < 2; i++) {
    if (positive) check.assertPositive(where, `${name}[${i}]`, pair[i]);
    else check.assertNonNegative(where, `${name}[${i}]`, pair[i]);
  }
  if (!(pair[1] >= pair[0])) throw new RangeError(`${where}: ${name} must be [min, max] with max >= min, got ${check.describe(v)}`);
  return [pair[0], pair[1]];
}

const SHAPE_NAMES = ['point', 'disc', 'ring', 'box', 'line'] as const;
const SHAPES: Record<(typeof SHAPE_NAMES)[number], number> = { point: 0, disc: 1, ring: 2, box: 3, line: 4 };
export const SETTINGS = [
  'rate',
  'shape',
  'size',
  'direction',
  'spread',
  'projectSphere',
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
  projectSphere?: boolean;
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
export function checkSettings(
  world: PhysicsWorld,
  where: string,
  options: Omit<EmitterOptions, 'attachTo' | 'position' | 'velocity'>,
): CheckedSettings {
  const d = world.dimensions;
  const out: CheckedSettings = {};
  if (options.rate !== undefined) {
    check.assertInRange(where, 'rate', options.rate, 0, MAX_EMITTER_RATE);
    out.rate = options.rate;
  }
  if (options.shape !== undefined) {
    check.assertOneOf(where, 'shape', options.shape, SHAPE_NAMES);
    out.shape = SHAPES[options.shape];
  }
  if (options.size !== undefined) {
    if (typeof options.size === 'number') {
      check.assertNonNegative(where, 'size', options.size);
      out.size = [options.size, options.size, options.size];
    } else {
      check.assertVector(where, 'size', options.size, d);
      for (let i = 0; i < d; i++) check.assertNonNegative(where, `size[${i}]`, options.size[i]);
      out.size = [options.size[0]!, options.size[1]!, d === 3 ? options.size[2]! : 0];
    }
  }
  if (options.direction !== undefined) out.dir = check.unitVector(where, 'direction', options.direction, d);
  if (options.spread !== undefined) {
    check.assertInRange(where, 'spread', options.spread, 0, Math.PI);
    out.spread = options.spread;
  }
  check.assertOptionalBoolean(where, 'projectSphere', options.projectSphere);
  if (options.projectSphere !== undefined) {
    if (options.projectSphere && d === 3)
      throw new RangeError(
        `${where}: projectSphere is for 2D worlds (a 3D emitter's directions are already on the sphere), got true in a 3D world`,
      );
    out.projectSphere = options.projectSphere;
  }
  if (options.speed !== undefined) out.speed = range(where, 'speed', options.speed, false);
  if (options.lifetime !== undefined) out.life = range(where, 'lifetime', options.lifetime, true);
  if (options.inheritVelocity !== undefined) {
    check.assertInRange(where, 'inheritVelocity', options.inheritVelocity, 0, 1);
    out.inherit = options.inheritVelocity;
  }
  if (options.policy !== undefined) {
    check.assertOneOf(where, 'policy', options.policy, ['drop-new', 'recycle-oldest']);
    out.policy = options.policy === 'recycle-oldest' ? CapacityPolicy.RecycleOldest : CapacityPolicy.DropNew;
  }
  check.assertOptionalBoolean(where, 'enabled', options.enabled);
  if (options.enabled !== undefined) out.enabled = options.enabled;
  const p = options.particle;
  if (p !== undefined) {
    check.assertOptions(where, p, PARTICLE_OPTIONS, 'particle');
    if (p.mass !== undefined) check.assertPositive(where, 'particle.mass', p.mass);
    if (p.linearDrag !== undefined) check.assertNonNegative(where, 'particle.linearDrag', p.linearDrag);
    if (p.quadraticDrag !== undefined) check.assertNonNegative(where, 'particle.quadraticDrag', p.quadraticDrag);
    if (p.gravityScale !== undefined) check.assertFinite(where, 'particle.gravityScale', p.gravityScale);
    if (p.radius !== undefined) check.assertPositive(where, 'particle.radius', p.radius);
    for (const k of ['colorStart', 'colorEnd'] as const)
      if (p[k] !== undefined) check.assertInteger(where, `particle.${k}`, p[k], 0, 0xffffff);
    for (const k of ['sizeStart', 'sizeEnd'] as const) if (p[k] !== undefined) check.assertNonNegative(where, `particle.${k}`, p[k]);
    for (const k of ['alphaStart', 'alphaEnd'] as const) if (p[k] !== undefined) check.assertInRange(where, `particle.${k}`, p[k], 0, 1);
    out.particle = p;
  }
  if (options.onDeath !== undefined) {
    const od = options.onDeath;
    check.assertOptions(where, od, ['emitter', 'count', 'maxGeneration'], 'onDeath');
    // 0 (setEmitter only) clears the death emitter.
    const slot = od.emitter === 0 && where === 'setEmitter' ? 0 : resolveKind(world, od.emitter, 'emitter', where, 'onDeath.emitter');
    check.assertInteger(where, 'onDeath.count', od.count, 0, 1_000_000);
    check.assertInteger(where, 'onDeath.maxGeneration', od.maxGeneration, 0, 1000);
    out.onDeath = { slot, count: od.count, maxGeneration: od.maxGeneration };
  }
  return out;
}

/** Writes checked settings into the emitter in slot `em`; settings not given keep their value. */
export function writeSettings(world: PhysicsWorld, em: number, s: CheckedSettings): void {
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
  if (s.projectSphere !== undefined) E.projectSphere[em] = s.projectSphere ? 1 : 0;
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
