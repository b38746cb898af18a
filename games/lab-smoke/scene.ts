/**
 * The smoke scene, DOM-free (Ramtal and Dobre ch. 12, "smoke"). SI units, y up, g = 9.81 m/s^2.
 *
 * A chimney's emitter releases puffs continuously (`rate` per second) from a short line across its
 * top, upwards within a narrow fan. Each puff is a particle of mass m = 10 g with:
 * - buoyancy: hot smoke is lighter than the air it displaces, modelled as a negative gravity scale
 *   s = -buoyancy, i.e. a net upward force buoyancy m g;
 * - linear drag F = -k (v - u) against the wind u (setWind: a mean wind plus turbulence, a sum of
 *   random divergence-free modes), k = 0.02 N s/m. The puff relaxes to the air's motion in
 *   m / k = 0.5 s and rises relative to it at buoyancy m g / k (1.2 m/s at the default 0.25);
 * - a look over life: it grows from 0.3 m to 2.4 m across as it spreads, lightens from dark to light
 *   grey and fades from alpha 0.5 to 0.
 * Puffs live 4 to 6 s, so the number alive settles at rate x 5 s on average (steady state: as many
 * expire each second as are born).
 */
import {
  addEmitter,
  createPhysicsWorld,
  type PhysicsWorld,
  removeBody,
  setEmitterRate,
  setPosition,
  setWind,
  step,
} from '@bitphysics/physics';

/** Mass of a puff, kg. */
export const PUFF_MASS = 0.01;
/** Linear drag coefficient of a puff, N s/m. */
export const PUFF_DRAG = 0.02;
/** Lifetime range of a puff, s (mean 5 s). */
export const PUFF_LIFETIME: [number, number] = [4, 6];
/** Most puffs emitted per second. */
export const MAX_RATE = 600;

/** Settings of the smoke (every field optional in `createSmoke`). */
export interface SmokeSettings {
  /** Puffs per second, in [0, MAX_RATE]. Default 120. */
  rate: number;
  /** Mean wind along x, m/s, in [-10, 10]. Default 1.5. */
  wind: number;
  /** Turbulence: RMS speed of the random part of the wind, m/s, in [0, 5]. Default 0.8. */
  turbulence: number;
  /** Upward force as a fraction of the puff's weight, in [0, 2]. Default 0.25. */
  buoyancy: number;
  /** Seed of the world (emission) and of the turbulence. Default 1. */
  seed: number;
}

/** The running smoke. */
export interface Smoke {
  readonly world: PhysicsWorld;
  /** The chimney's emitter (rebuilt when the buoyancy changes). */
  emitter: number;
  /** Where the emitter is, m. */
  readonly source: [number, number];
  readonly settings: SmokeSettings;
}

function check(where: string, name: string, v: number, min: number, max: number): void {
  if (typeof v !== 'number' || !(v >= min && v <= max))
    throw new RangeError(`${where}: ${name} must be in [${min}, ${max}], got ${String(v)}`);
}

/** Builds the world and the chimney's emitter. @throws RangeError on a setting out of range. */
export function createSmoke(options: Partial<SmokeSettings> = {}): Smoke {
  const settings: SmokeSettings = { rate: 120, wind: 1.5, turbulence: 0.8, buoyancy: 0.25, seed: 1, ...options };
  check('createSmoke', 'rate', settings.rate, 0, MAX_RATE);
  check('createSmoke', 'wind', settings.wind, -10, 10);
  check('createSmoke', 'turbulence', settings.turbulence, 0, 5);
  check('createSmoke', 'buoyancy', settings.buoyancy, 0, 2);
  // Room for MAX_RATE puffs per second living 6 s; the emitter recycles the oldest beyond that.
  const world = createPhysicsWorld({ dimensions: 2, capacity: MAX_RATE * PUFF_LIFETIME[1] + 64, gravity: [0, -9.81], seed: settings.seed });
  const smoke: Smoke = { world, emitter: 0, source: [2, 1.2], settings };
  smoke.emitter = makeEmitter(smoke);
  applyWind(smoke);
  return smoke;
}

/** A chimney emitter with the current settings at the current source. */
function makeEmitter(smoke: Smoke): number {
  return addEmitter(smoke.world, {
    position: smoke.source,
    rate: smoke.settings.rate,
    shape: 'line',
    size: 0.25,
    direction: [0, 1],
    spread: 0.25,
    speed: [0.6, 1.2],
    lifetime: PUFF_LIFETIME,
    policy: 'recycle-oldest',
    particle: {
      mass: PUFF_MASS,
      linearDrag: PUFF_DRAG,
      gravityScale: -smoke.settings.buoyancy,
      colorStart: 0x55585e,
      colorEnd: 0xc9ccd1,
      sizeStart: 0.3,
      sizeEnd: 2.4,
      alphaStart: 0.5,
      alphaEnd: 0,
    },
  });
}

function applyWind(smoke: Smoke): void {
  const s = smoke.settings;
  setWind(smoke.world, {
    velocity: [s.wind, 0],
    turbulence: { intensity: s.turbulence, lengthScale: 2.5, timeScale: 1.5, seed: s.seed, modes: 16 },
  });
}

/** Sets the emission rate, puffs/s, in [0, MAX_RATE]. @throws RangeError otherwise. */
export function setSmokeRate(smoke: Smoke, rate: number): void {
  check('setSmokeRate', 'rate', rate, 0, MAX_RATE);
  smoke.settings.rate = rate;
  setEmitterRate(smoke.world, smoke.emitter, rate);
}

/** Sets the mean wind (m/s along x, [-10, 10]) and the turbulence (RMS m/s, [0, 5]). @throws RangeError otherwise. */
export function setSmokeWind(smoke: Smoke, wind: number, turbulence: number): void {
  check('setSmokeWind', 'wind', wind, -10, 10);
  check('setSmokeWind', 'turbulence', turbulence, 0, 5);
  smoke.settings.wind = wind;
  smoke.settings.turbulence = turbulence;
  applyWind(smoke);
}

/**
 * Sets the buoyancy of new puffs (fraction of their weight, [0, 2]). An emitter's particle options
 * are fixed when it is made, so the emitter is replaced (same place and rate); puffs already out keep
 * theirs. @throws RangeError otherwise.
 */
export function setSmokeBuoyancy(smoke: Smoke, buoyancy: number): void {
  check('setSmokeBuoyancy', 'buoyancy', buoyancy, 0, 2);
  smoke.settings.buoyancy = buoyancy;
  removeBody(smoke.world, smoke.emitter);
  smoke.emitter = makeEmitter(smoke);
}

/** Moves the source to (x, y), m. */
export function moveSmokeSource(smoke: Smoke, x: number, y: number): void {
  smoke.source[0] = x;
  smoke.source[1] = y;
  setPosition(smoke.world, smoke.emitter, smoke.source);
}

/** One step of the smoke (the world's own step: the emitter and the force laws do everything). */
export function stepSmoke(smoke: Smoke): void {
  step(smoke.world);
}
