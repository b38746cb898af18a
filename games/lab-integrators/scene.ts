/**
 * Integrators lab scene: one Kepler orbit, built once per integration scheme with the same initial
 * state, so the seven worlds differ only in `integrator`. A static sun with an Attractor at the
 * origin (G = 1 via setGravitation, G M chosen so the orbit of semi-major axis 4 m has a 4 s
 * period) and one planet of 1 kg starting at periapsis on the +x axis. World gravity is zero.
 * A pure, deterministic builder; no DOM.
 */
import {
  addBody,
  createPhysicsWorld,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  setAttractor,
  setGravitation,
} from '@bitphysics/physics';

/** Semi-major axis of the orbit, m. */
export const SEMI_MAJOR_AXIS = 4;
/** Period of the orbit, s (Kepler's third law fixes G M from it). */
export const PERIOD = 4;
/** G M of the sun, m^3/s^2: 4 pi^2 a^3 / T^2 (Kepler's third law), about 157.9. */
export const GM = (4 * Math.PI * Math.PI * SEMI_MAJOR_AXIS ** 3) / (PERIOD * PERIOD);
/**
 * Softening of the sun's pull, m: small against the closest approach (0.2 m at e = 0.95), it keeps
 * a scheme that spirals into the sun from producing infinite forces. The softened potential is still
 * conservative, so energy remains the exact invariant.
 */
export const SOFTENING = 0.02;
/** Radius of the planet ball, m. */
export const PLANET_RADIUS = 0.15;

/** Options of one orbit world. */
export interface KeplerOptions {
  /** Integration scheme. */
  integrator: IntegratorName;
  /** Eccentricity, in [0, 0.95]. */
  eccentricity: number;
  /** Time step, s, in [0.0005, 0.2]. */
  dt: number;
}

/** One orbit world and its bodies. */
export interface KeplerWorld {
  world: PhysicsWorld;
  /** The static sun (attractor, no collider). */
  sun: number;
  /** The planet. */
  planet: number;
}

/**
 * Checks the options. @throws RangeError naming the option and value: an unknown integrator,
 * an eccentricity outside [0, 0.95] or a dt outside [0.0005, 0.2].
 */
export function checkKeplerOptions(options: KeplerOptions): void {
  if (!(INTEGRATOR_NAMES as readonly string[]).includes(options.integrator)) {
    throw new RangeError(
      `lab-integrators: integrator must be one of ${INTEGRATOR_NAMES.join(', ')}, got ${JSON.stringify(options.integrator)}`,
    );
  }
  if (!(options.eccentricity >= 0 && options.eccentricity <= 0.95))
    throw new RangeError(`lab-integrators: eccentricity must be in [0, 0.95], got ${options.eccentricity}`);
  if (!(options.dt >= 0.0005 && options.dt <= 0.2))
    throw new RangeError(`lab-integrators: dt must be in [0.0005, 0.2] s, got ${options.dt}`);
}

/**
 * Creates a 2D world with the orbit. The planet starts at periapsis r_p = a (1 - e) on the +x axis
 * moving along +y at the vis-viva speed sqrt(G M (1 + e) / r_p) (Ramtal and Dobre ch. 6).
 * @throws RangeError on bad options (see `checkKeplerOptions`).
 */
export function createKeplerWorld(options: KeplerOptions): KeplerWorld {
  checkKeplerOptions(options);
  const world = createPhysicsWorld({ dimensions: 2, capacity: 4, gravity: [0, 0], dt: options.dt, integrator: options.integrator });
  setGravitation(world, { constant: 1 });
  const sun = addBody(world, { position: [0, 0], static: true });
  setAttractor(world, sun, { mass: GM, softening: SOFTENING });
  const e = options.eccentricity;
  const rp = SEMI_MAJOR_AXIS * (1 - e);
  const vp = Math.sqrt((GM * (1 + e)) / rp);
  const planet = addBody(world, { position: [rp, 0], velocity: [0, vp], radius: PLANET_RADIUS, mass: 1, rotates: false });
  return { world, sun, planet };
}
