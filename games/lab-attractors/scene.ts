/**
 * The attractors scene, DOM-free (Ramtal and Dobre ch. 12, "particles in force fields"). G = 1 game
 * units: lengths m, particle masses kg, attractor strengths G M in m^3/s^2.
 *
 * - Attractors are static bodies carrying the physics package's Attractor component: each pulls every
 *   particle with F = -G M m r / (r^2 + eps^2)^(3/2) (r from the attractor, Plummer softening eps, so
 *   a particle passing through the centre feels a finite force and swings through instead of being
 *   flung out). Their fields add up.
 * - Particles are 1 kg point masses (no collider) with linear drag F = -k v (k in N s/m: without it
 *   they keep their energy and fill chaotic orbits; with it they sink into the wells).
 * - Vortex (optional): every particle also feels a swirl about the origin, F = k_v (z x r_hat), a
 *   constant-magnitude tangential force (setVortex with n = 1; k_v > 0 counter-clockwise). Against the
 *   drag it drives a steady circulation at speed k_v / k.
 * - Particles that wander beyond `ESCAPE_RADIUS` come back at rest at a random point of the start
 *   area (a game rule: the population stays constant).
 */
import {
  addBody,
  createPhysicsWorld,
  type PhysicsWorld,
  Rng,
  removeBody,
  setAttractor,
  setDrag,
  setGravitation,
  setPosition,
  setVelocity,
  setVortex,
  slotOf,
  step,
} from '@bitphysics/physics';

/** Most attractors at once. */
export const MAX_ATTRACTORS = 8;
/** Particles are placed in [-W, W] x [-H, H], m. */
export const START_AREA = Object.freeze({ w: 11, h: 6.5 });
/** Distance from the origin beyond which a particle comes back, m. */
export const ESCAPE_RADIUS = 30;

/** Settings of the field. */
export interface AttractorSettings {
  /** Particles, integer in [1, 50_000]. Default 3000. */
  count: number;
  /** G M of every attractor, m^3/s^2, (0, 1000]. Default 40. */
  mass: number;
  /** Softening of every attractor, m, [0, 5]. Default 0.4. */
  softening: number;
  /** Linear drag of a particle, N s/m, [0, 5]. Default 0.05. */
  drag: number;
  /** Whether the vortex acts. Default false. */
  vortex: boolean;
  /** Vortex strength k_v, N (tangential force on a particle), [-20, 20]. Default 2. */
  vortexStrength: number;
  /** Seed. Default 1. */
  seed: number;
}

/** The running field. */
export interface AttractorField {
  readonly world: PhysicsWorld;
  /** Particle ids (fixed population). */
  readonly particles: Uint32Array;
  /** Attractor ids, `attractorCount` in use. */
  readonly attractors: Int32Array;
  attractorCount: number;
  readonly settings: AttractorSettings;
  /** Particles that came back after escaping. */
  returns: number;
  readonly rng: Rng;
}

function check(where: string, name: string, v: number, min: number, max: number): void {
  if (typeof v !== 'number' || !(v >= min && v <= max))
    throw new RangeError(`${where}: ${name} must be in [${min}, ${max}], got ${String(v)}`);
}

const p2 = new Float64Array(2),
  v2 = new Float64Array(2);
const ORIGIN = [0, 0] as const;

/**
 * Builds the field: `count` particles scattered over the start area with small random velocities and
 * three attractors. @throws RangeError on a setting out of range.
 */
export function createAttractorField(options: Partial<AttractorSettings> = {}): AttractorField {
  const settings: AttractorSettings = {
    count: 3000,
    mass: 40,
    softening: 0.4,
    drag: 0.05,
    vortex: false,
    vortexStrength: 2,
    seed: 1,
    ...options,
  };
  const where = 'createAttractorField';
  if (!Number.isInteger(settings.count) || settings.count < 1 || settings.count > 50_000)
    throw new RangeError(`${where}: count must be an integer in [1, 50000], got ${settings.count}`);
  check(where, 'mass', settings.mass, 1e-6, 1000);
  check(where, 'softening', settings.softening, 0, 5);
  check(where, 'drag', settings.drag, 0, 5);
  check(where, 'vortexStrength', settings.vortexStrength, -20, 20);
  const world = createPhysicsWorld({ dimensions: 2, capacity: settings.count + MAX_ATTRACTORS + 4, gravity: [0, 0], seed: settings.seed });
  setGravitation(world, { constant: 1 });
  const f: AttractorField = {
    world,
    particles: new Uint32Array(settings.count),
    attractors: new Int32Array(MAX_ATTRACTORS),
    attractorCount: 0,
    settings,
    returns: 0,
    rng: new Rng(settings.seed),
  };
  for (let i = 0; i < settings.count; i++) {
    p2[0] = f.rng.range(-START_AREA.w, START_AREA.w);
    p2[1] = f.rng.range(-START_AREA.h, START_AREA.h);
    v2[0] = f.rng.range(-0.5, 0.5);
    v2[1] = f.rng.range(-0.5, 0.5);
    const e = addBody(world, { position: p2, velocity: v2, mass: 1 });
    f.particles[i] = e;
  }
  setParticleDrag(f, settings.drag);
  setVortexOn(f, settings.vortex, settings.vortexStrength);
  addAttractor(f, -5, 0.5);
  addAttractor(f, 1.5, 2.5);
  addAttractor(f, 3.5, -3);
  return f;
}

/** Adds an attractor at (x, y), m, with the field's mass and softening. @returns its id, or 0 at MAX_ATTRACTORS. */
export function addAttractor(f: AttractorField, x: number, y: number): number {
  if (f.attractorCount >= MAX_ATTRACTORS) return 0;
  p2[0] = x;
  p2[1] = y;
  const e = addBody(f.world, { position: p2, static: true });
  setAttractor(f.world, e, { mass: f.settings.mass, softening: f.settings.softening });
  f.attractors[f.attractorCount++] = e;
  return e;
}

/** Removes attractor `eid`. @throws RangeError if it is not an attractor of the field. */
export function removeAttractor(f: AttractorField, eid: number): void {
  const i = f.attractors.subarray(0, f.attractorCount).indexOf(eid);
  if (i < 0) throw new RangeError(`removeAttractor: ${eid} is not an attractor of the field`);
  removeBody(f.world, eid);
  f.attractors[i] = f.attractors[--f.attractorCount]!;
}

/** Moves attractor `eid` to (x, y), m. @throws RangeError if it is not an attractor of the field. */
export function moveAttractor(f: AttractorField, eid: number, x: number, y: number): void {
  if (f.attractors.subarray(0, f.attractorCount).indexOf(eid) < 0)
    throw new RangeError(`moveAttractor: ${eid} is not an attractor of the field`);
  p2[0] = x;
  p2[1] = y;
  setPosition(f.world, eid, p2);
}

/** The attractor nearest to (x, y), m, within `reach` m, or 0. */
export function attractorNear(f: AttractorField, x: number, y: number, reach: number): number {
  const P = f.world.components.Position;
  let best = 0,
    bestD = reach;
  for (let i = 0; i < f.attractorCount; i++) {
    const e = f.attractors[i]!;
    const d = Math.hypot(P.x[slotOf(e)]! - x, P.y[slotOf(e)]! - y);
    if (d <= bestD) {
      bestD = d;
      best = e;
    }
  }
  return best;
}

/** Sets every attractor's G M (m^3/s^2, (0, 1000]) and softening (m, [0, 5]). @throws RangeError otherwise. */
export function setAttractorField(f: AttractorField, mass: number, softening: number): void {
  check('setAttractorField', 'mass', mass, 1e-6, 1000);
  check('setAttractorField', 'softening', softening, 0, 5);
  f.settings.mass = mass;
  f.settings.softening = softening;
  for (let i = 0; i < f.attractorCount; i++) setAttractor(f.world, f.attractors[i]!, { mass, softening });
}

/** Sets every particle's linear drag, N s/m, [0, 5]. @throws RangeError otherwise. */
export function setParticleDrag(f: AttractorField, k: number): void {
  check('setParticleDrag', 'k', k, 0, 5);
  f.settings.drag = k;
  for (let i = 0; i < f.particles.length; i++) setDrag(f.world, f.particles[i]!, { linear: k });
}

/**
 * Turns the vortex about the origin on (strength k_v N, [-20, 20]) or off (a vortex of strength 0:
 * a body's Vortex component cannot be removed through the API, and k = 0 exerts nothing).
 * @throws RangeError on a strength out of range.
 */
export function setVortexOn(f: AttractorField, on: boolean, strength: number): void {
  check('setVortexOn', 'strength', strength, -20, 20);
  f.settings.vortex = on;
  f.settings.vortexStrength = strength;
  const k = on ? strength : 0;
  for (let i = 0; i < f.particles.length; i++) setVortex(f.world, f.particles[i]!, { centre: ORIGIN, k, n: 1 });
}

/** One step: physics, then escaped particles come back at rest in the start area. */
export function stepAttractors(f: AttractorField): void {
  step(f.world);
  const P = f.world.components.Position;
  const r2 = ESCAPE_RADIUS * ESCAPE_RADIUS;
  for (let i = 0; i < f.particles.length; i++) {
    const e = f.particles[i]!;
    const x = P.x[slotOf(e)]!,
      y = P.y[slotOf(e)]!;
    if (x * x + y * y > r2) {
      p2[0] = f.rng.range(-START_AREA.w, START_AREA.w);
      p2[1] = f.rng.range(-START_AREA.h, START_AREA.h);
      v2[0] = 0;
      v2[1] = 0;
      setPosition(f.world, e, p2);
      setVelocity(f.world, e, v2);
      f.returns++;
    }
  }
}
