/**
 * The Earth-Moon scene in SI units: a pure, deterministic builder (no randomness) (world options +
 * build) shared by the game and its tests; no DOM, no three.js.
 *
 * Earth and Moon attract each other by Newtonian gravity (`enableMutualGravity`, G in SI), starting
 * at perigee of the Moon's mean orbit (semi-major axis 384 400 km, eccentricity 0.0549, inclined
 * 5.145 degrees to the ecliptic, the x-z plane here, y up) with barycentric positions and velocities,
 * so the pair's momentum is zero and the barycentre stays at the origin. The Earth spins once a
 * sidereal day about an axis tilted 23.44 degrees; the Moon spins once a sidereal month (tidally
 * locked). Constants: IAU 2015 nominal values and the JPL lunar fact sheet.
 *
 * Time: `world.dt` is set per frame by `configureStep` from a time scale (simulated seconds per real
 * second), split into substeps of at most `MAX_SUBSTEP` s, so the orbit is integrated the same way
 * whatever the time scale.
 */
import { addBody, enableMutualGravity, G_SI, type PhysicsWorld, type PhysicsWorldOptions } from '@bitphysics/physics';

/** Mass of the Earth, kg. */
export const EARTH_MASS = 5.9722e24;
/** Mean radius of the Earth, m. */
export const EARTH_RADIUS = 6.371e6;
/** Moment of inertia factor of the Earth, I / (M R^2) (a uniform ball would be 0.4). */
export const EARTH_INERTIA_FACTOR = 0.3307;
/** Sidereal day, s. */
export const SIDEREAL_DAY = 86_164.0905;
/** Obliquity of the ecliptic (Earth's axial tilt), rad. */
export const EARTH_TILT = (23.44 * Math.PI) / 180;
/** Mass of the Moon, kg. */
export const MOON_MASS = 7.342e22;
/** Mean radius of the Moon, m. */
export const MOON_RADIUS = 1.7374e6;
/** Semi-major axis of the Moon's orbit, m. */
export const MOON_SEMI_MAJOR_AXIS = 3.844e8;
/** Eccentricity of the Moon's orbit. */
export const MOON_ECCENTRICITY = 0.0549;
/** Inclination of the Moon's orbit to the ecliptic, rad. */
export const MOON_INCLINATION = (5.145 * Math.PI) / 180;
/** One day, s. */
export const DAY = 86_400;
/** Longest substep, s: about 4000 substeps an orbit keep semi-implicit Euler's energy error tiny. */
export const MAX_SUBSTEP = 600;

/**
 * Period of the relative orbit, s, from Kepler's third law for the two-body problem:
 * T = 2 pi sqrt(a^3 / (G (M + m))) (about 27.3 days).
 */
export function siderealMonth(): number {
  return 2 * Math.PI * Math.sqrt(MOON_SEMI_MAJOR_AXIS ** 3 / (G_SI * (EARTH_MASS + MOON_MASS)));
}

/** World options: 3D, no uniform gravity, a real-time tick of `tick` s (the loop's step; `configureStep` sets the simulated dt). */
export function earthMoonWorldOptions(tick = 1 / 60): PhysicsWorldOptions {
  return { dimensions: 3, capacity: 8, gravity: [0, 0, 0], dt: tick };
}

/** What `buildEarthMoon` returns. */
export interface EarthMoonHandles {
  /** Entity of the Earth. */
  earth: number;
  /** Entity of the Moon. */
  moon: number;
}

/**
 * Builds the Earth and the Moon into `world` (a 3D world without uniform gravity).
 * The relative orbit starts at perigee r_p = a (1 - e) with the vis-viva speed v_p = sqrt(mu (1 + e) / r_p),
 * mu = G (M + m); each body gets its barycentric share (Earth -m/(M+m), Moon M/(M+m)).
 * @throws RangeError if the world is not 3D.
 */
export function buildEarthMoon(world: PhysicsWorld): EarthMoonHandles {
  if (world.dimensions !== 3) throw new RangeError(`earth-moon: needs a 3D world, got dimensions ${world.dimensions}`);
  const M = EARTH_MASS,
    m = MOON_MASS,
    total = M + m;
  const e = MOON_ECCENTRICITY;
  const rp = MOON_SEMI_MAJOR_AXIS * (1 - e);
  const vp = Math.sqrt((G_SI * total * (1 + e)) / rp);
  // Relative state in the orbit plane (x out to perigee, velocity along -z so the orbit turns
  // counter-clockwise seen from +y), then tilted by the inclination about x.
  const ci = Math.cos(MOON_INCLINATION),
    si = Math.sin(MOON_INCLINATION);
  const r = [rp, 0, 0];
  const v = [0, vp * si, -vp * ci];
  const fe = -m / total,
    fm = M / total;
  // Earth: spin axis tilted by EARTH_TILT from +y towards +x (the body's y axis is the pole).
  const ht = EARTH_TILT / 2;
  const earthQ = [0, 0, -Math.sin(ht), Math.cos(ht)];
  const we = (2 * Math.PI) / SIDEREAL_DAY;
  const earth = addBody(world, {
    position: [r[0]! * fe, r[1]! * fe, r[2]! * fe],
    velocity: [v[0]! * fe, v[1]! * fe, v[2]! * fe],
    mass: M,
    radius: EARTH_RADIUS,
    inertia: EARTH_INERTIA_FACTOR * M * EARTH_RADIUS * EARTH_RADIUS,
    orientation: earthQ,
    angularVelocity: [Math.sin(EARTH_TILT) * we, Math.cos(EARTH_TILT) * we, 0],
  });
  // Moon: turns once per sidereal month about the orbit normal (0, ci, si), its texture's +x facing Earth.
  const wm = (2 * Math.PI) / siderealMonth();
  const hi = MOON_INCLINATION / 2;
  const moon = addBody(world, {
    position: [r[0]! * fm, r[1]! * fm, r[2]! * fm],
    velocity: [v[0]! * fm, v[1]! * fm, v[2]! * fm],
    mass: m,
    radius: MOON_RADIUS,
    inertia: 0.394 * m * MOON_RADIUS * MOON_RADIUS,
    // Half a turn about y (body +x towards the Earth), then tilted by the inclination about x:
    // q = (sin(i/2), 0, 0, cos(i/2)) (0, 1, 0, 0) = (0, cos(i/2), sin(i/2), 0).
    orientation: [0, Math.cos(hi), Math.sin(hi), 0],
    angularVelocity: [0, wm * ci, wm * si],
  });
  enableMutualGravity(world, earth);
  enableMutualGravity(world, moon);
  return { earth, moon };
}

/**
 * Sets the world's next step to advance `timeScale` x `tick` simulated seconds in substeps of at
 * most MAX_SUBSTEP s (the step keeps PreviousPosition at the start of the whole step, so the renderer
 * interpolates across all substeps). Returns false (nothing to step) when timeScale is 0.
 * @param timeScale simulated seconds per real second, >= 0. @param tick real seconds a step stands for, > 0.
 * @throws RangeError on a negative or non-finite time scale or tick.
 */
export function configureStep(world: PhysicsWorld, timeScale: number, tick: number): boolean {
  if (!(timeScale >= 0) || !Number.isFinite(timeScale))
    throw new RangeError(`earth-moon: timeScale must be finite and >= 0, got ${timeScale}`);
  if (!(tick > 0) || !Number.isFinite(tick)) throw new RangeError(`earth-moon: tick must be finite and > 0, got ${tick}`);
  if (timeScale === 0) return false;
  const dt = timeScale * tick;
  // The physics package documents `setTimeStep` for world.dt but does not export one; dt and substeps
  // are plain writable fields of the world context.
  world.dt = dt;
  world.substeps = Math.min(64, Math.max(1, Math.ceil(dt / MAX_SUBSTEP)));
  return true;
}

/** Distance between the centres of two bodies, m. */
export function distance(world: PhysicsWorld, a: number, b: number): number {
  const P = world.components.Position;
  return Math.hypot(P.x[a]! - P.x[b]!, P.y[a]! - P.y[b]!, P.z[a]! - P.z[b]!);
}
