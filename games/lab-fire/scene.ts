/**
 * The fire scene, DOM-free (Ramtal and Dobre ch. 12, "fire"). SI units, y up, g = 9.81 m/s^2.
 *
 * Four emitters:
 * - flames: many short-lived particles (0.25 to 0.5 s) from a line across the logs, upwards within a
 *   fan of +-0.3 rad. Hot gas rises: gravity scale -1.2 (a net upward force 1.2 m g) against linear
 *   drag k = 4 mN s/m on m = 1 g, so a flame relaxes to the air in m / k = 0.25 s and rises at up to
 *   1.2 m g / k = 2.9 m/s relative to it. Colour yellow-white to orange over its life;
 * - glow: when a flame dies it becomes one glow particle (the emitters' onDeath burst, one
 *   generation), which keeps its velocity and goes from red to dark while it fades: together the two
 *   make the yellow-white -> red -> dark of a flame tongue;
 * - sparks: a few fast, small embers (m = 0.1 g, linear drag 0.2 mN s/m) that the hot air carries up
 *   while gravity (scale 0.6) bends them over, 0.8 to 1.8 s;
 * - smoke (optional): slow grey puffs above the flames that rise, grow and fade.
 * The flames are drawn with additive blending (overlaps glow white), the smoke with normal blending.
 *
 * Flicker: the flame rate is modulated every step by smooth seeded noise, rate = base (0.7 + 0.6 n)
 * with n in [0, 1] changing over about 0.08 s, and the wind carries turbulence on a short time scale
 * (0.35 s) that sways the tongues. `intensity` scales every rate.
 */
import {
  addEmitter,
  createPhysicsWorld,
  type PhysicsWorld,
  setEmitterEnabled,
  setEmitterRate,
  setPosition,
  setWind,
  step,
  valueNoise,
} from '@bitphysics/physics';

/** Base rates at intensity 1, particles per second. */
export const FIRE_RATES = Object.freeze({ flames: 500, sparks: 14, smoke: 30 });
/** Mean lifetimes, s: flames, glow, sparks, smoke (for the expected steady counts). */
export const FIRE_LIFETIMES = Object.freeze({ flames: 0.375, glow: 0.5, sparks: 1.3, smoke: 2.75 });
/** Largest intensity. */
export const MAX_INTENSITY = 3;

/** Settings of the fire. */
export interface FireSettings {
  /** Scales every rate, in [0, MAX_INTENSITY]. Default 1. */
  intensity: number;
  /** Mean wind along x, m/s, in [-6, 6]. Default 0. */
  wind: number;
  /** Smoke above the flames. Default true. */
  smoke: boolean;
  /** Seed. Default 1. */
  seed: number;
}

/** The running fire. */
export interface Fire {
  readonly world: PhysicsWorld;
  /** Emitter ids. */
  readonly flames: number;
  readonly glow: number;
  readonly sparks: number;
  readonly smoke: number;
  /** Where the fire is (the middle of the logs' top), m. */
  readonly at: [number, number];
  readonly settings: FireSettings;
  /** The flame rate this step after the flicker, particles/s. */
  flameRate: number;
}

function check(where: string, name: string, v: number, min: number, max: number): void {
  if (typeof v !== 'number' || !(v >= min && v <= max))
    throw new RangeError(`${where}: ${name} must be in [${min}, ${max}], got ${String(v)}`);
}

/** Builds the world and the four emitters. @throws RangeError on a setting out of range. */
export function createFire(options: Partial<FireSettings> = {}): Fire {
  const settings: FireSettings = { intensity: 1, wind: 0, smoke: true, seed: 1, ...options };
  check('createFire', 'intensity', settings.intensity, 0, MAX_INTENSITY);
  check('createFire', 'wind', settings.wind, -6, 6);
  // Room for the most particles alive at once: the largest rates (flicker peak 1.3) times the longest lifetimes.
  const R = FIRE_RATES,
    k = MAX_INTENSITY * 1.3;
  const capacity = Math.ceil(k * (R.flames * (0.5 + 0.7) + R.sparks * 1.8 + R.smoke * 3.5)) + 64;
  const world = createPhysicsWorld({ dimensions: 2, capacity, gravity: [0, -9.81], seed: settings.seed });
  const at: [number, number] = [0, 0.25];
  const glow = addEmitter(world, {
    position: at,
    speed: [0, 0.3],
    lifetime: [0.3, 0.7],
    inheritVelocity: 1,
    policy: 'recycle-oldest',
    particle: {
      mass: 0.001,
      linearDrag: 0.004,
      gravityScale: -0.8,
      colorStart: 0xff4a12,
      colorEnd: 0x2a0000,
      sizeStart: 0.34,
      sizeEnd: 0.5,
      alphaStart: 0.6,
      alphaEnd: 0,
    },
  });
  const flames = addEmitter(world, {
    position: at,
    rate: R.flames * settings.intensity,
    shape: 'line',
    size: 0.45,
    direction: [0, 1],
    spread: 0.3,
    speed: [0.3, 1.2],
    lifetime: [0.25, 0.5],
    policy: 'recycle-oldest',
    particle: {
      mass: 0.001,
      linearDrag: 0.004,
      gravityScale: -1.2,
      colorStart: 0xffe9a8,
      colorEnd: 0xff7a1c,
      sizeStart: 0.4,
      sizeEnd: 0.3,
      alphaStart: 0.5,
      alphaEnd: 0.45,
    },
    onDeath: { emitter: glow, count: 1, maxGeneration: 1 },
  });
  const sparks = addEmitter(world, {
    position: at,
    rate: R.sparks * settings.intensity,
    shape: 'line',
    size: 0.3,
    direction: [0, 1],
    spread: 0.5,
    speed: [2, 5],
    lifetime: [0.8, 1.8],
    policy: 'recycle-oldest',
    particle: {
      mass: 1e-4,
      linearDrag: 2e-4,
      gravityScale: 0.6,
      colorStart: 0xfff0a0,
      colorEnd: 0xff3000,
      sizeStart: 0.08,
      sizeEnd: 0.035,
      alphaStart: 1,
      alphaEnd: 0,
    },
  });
  const smoke = addEmitter(world, {
    position: [at[0], at[1] + 1.3],
    rate: R.smoke * settings.intensity,
    shape: 'line',
    size: 0.3,
    direction: [0, 1],
    spread: 0.3,
    speed: [0.3, 0.8],
    lifetime: [2, 3.5],
    enabled: settings.smoke,
    policy: 'recycle-oldest',
    particle: {
      mass: 0.01,
      linearDrag: 0.02,
      gravityScale: -0.3,
      colorStart: 0x2c2824,
      colorEnd: 0x707070,
      sizeStart: 0.4,
      sizeEnd: 2.2,
      alphaStart: 0.32,
      alphaEnd: 0,
    },
  });
  const fire: Fire = { world, flames, glow, sparks, smoke, at, settings, flameRate: R.flames * settings.intensity };
  applyWind(fire);
  return fire;
}

function applyWind(fire: Fire): void {
  const w = fire.settings.wind;
  setWind(fire.world, {
    velocity: [w, 0],
    turbulence: { intensity: 0.35 + 0.15 * Math.abs(w), lengthScale: 1.2, timeScale: 0.35, seed: fire.settings.seed, modes: 12 },
  });
}

/** Sets the intensity (scales every rate), in [0, MAX_INTENSITY]. @throws RangeError otherwise. */
export function setFireIntensity(fire: Fire, intensity: number): void {
  check('setFireIntensity', 'intensity', intensity, 0, MAX_INTENSITY);
  fire.settings.intensity = intensity;
  setEmitterRate(fire.world, fire.sparks, FIRE_RATES.sparks * intensity);
  setEmitterRate(fire.world, fire.smoke, FIRE_RATES.smoke * intensity);
  // The flame rate is set every step by the flicker.
}

/** Sets the mean wind along x, m/s, in [-6, 6] (with turbulence growing with it). @throws RangeError otherwise. */
export function setFireWind(fire: Fire, wind: number): void {
  check('setFireWind', 'wind', wind, -6, 6);
  fire.settings.wind = wind;
  applyWind(fire);
}

/** Turns the smoke on or off. */
export function setFireSmoke(fire: Fire, on: boolean): void {
  fire.settings.smoke = on;
  setEmitterEnabled(fire.world, fire.smoke, on);
}

/** Moves the fire to (x, y), m (its flames, sparks and smoke). */
export function moveFire(fire: Fire, x: number, y: number): void {
  fire.at[0] = x;
  fire.at[1] = y;
  setPosition(fire.world, fire.flames, fire.at);
  setPosition(fire.world, fire.sparks, fire.at);
  setPosition(fire.world, fire.smoke, [x, y + 1.3]);
}

/** One step: the flicker sets this step's flame rate, then the world steps. */
export function stepFire(fire: Fire): void {
  const n = 0.5 + 0.5 * valueNoise(fire.settings.seed, fire.world.time, 0.08, 0);
  fire.flameRate = FIRE_RATES.flames * fire.settings.intensity * (0.7 + 0.6 * n);
  setEmitterRate(fire.world, fire.flames, fire.flameRate);
  step(fire.world);
}
