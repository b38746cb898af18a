/**
 * Orbits lab scene: planets around a fixed sun. The sun is a static body with an Attractor of mass
 * M in scaled units (G = 1 through setGravitation, so G M = M m^3/s^2); the planets are dynamic
 * balls of 1 kg, started at periapsis of seeded Kepler ellipses with geometrically spaced semi-major
 * axes (ratio 1.3, eccentricities up to 0.1, so no two orbits cross). World gravity is zero: only the
 * attractor pulls. A pure, deterministic builder; no DOM.
 */
import {
  addBody,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  type PhysicsWorldOptions,
  Rng,
  removeBody,
  setAttractor,
  setGravitation,
} from '@bitphysics/physics';

/** Options of the scene; every field optional. */
export interface OrbitsOptions {
  /** Planets, integer in [1, 8]. Default 5. */
  planets?: number;
  /** G M of the sun, m^3/s^2, in [1, 500]. Default 50. */
  gm?: number;
  /** Softening length of the sun's pull, m, in [0, 3]. Default 0. */
  softening?: number;
  /** Integration scheme. Default 'semi-implicit-euler'. */
  integrator?: IntegratorName;
  /** Seed of eccentricities and starting angles. Default 1. */
  seed?: number;
}

/** Resolved options. */
export type OrbitsParams = Required<OrbitsOptions>;

/** Defaults. */
export const ORBITS_DEFAULTS: Readonly<OrbitsParams> = Object.freeze({
  planets: 5,
  gm: 50,
  softening: 0,
  integrator: 'semi-implicit-euler',
  seed: 1,
});

/** Radius the sun is drawn with, m; a body closer than this to its centre falls in and is removed. */
export const SUN_RADIUS = 0.5;
/** Semi-major axis of the innermost planet, m, and the ratio between neighbours. */
export const FIRST_ORBIT = 2.5;
export const ORBIT_RATIO = 1.3;
/** Bodies launched by the user that may exist at once (the oldest goes first). */
export const LAUNCH_BUDGET = 24;
/** Bodies farther than this from the sun, m, have escaped and are removed. */
export const ESCAPE_DISTANCE = 120;

/** What the builder returns. */
export interface OrbitsHandles {
  /** The sun (static, no collider: it is drawn by the page). */
  sun: number;
  /** The planets the scene started with (removed ones are dropped). */
  planets: number[];
  /** Bodies launched by the user, oldest first. */
  launched: number[];
  /** The options used (gm and softening kept up to date by `setCentralMass`). */
  params: OrbitsParams;
}

/**
 * Fills in defaults and checks the options.
 * @throws TypeError on an unknown option; RangeError naming the option and value when out of range.
 */
export function resolveOrbitsOptions(options: OrbitsOptions = {}): OrbitsParams {
  for (const k of Object.keys(options)) {
    if (!(k in ORBITS_DEFAULTS))
      throw new TypeError(`lab-orbits: unknown option ${JSON.stringify(k)}; known: ${Object.keys(ORBITS_DEFAULTS).join(', ')}`);
  }
  const p = { ...ORBITS_DEFAULTS, ...options } as OrbitsParams;
  if (!(Number.isInteger(p.planets) && p.planets >= 1 && p.planets <= 8))
    throw new RangeError(`lab-orbits: planets must be an integer in [1, 8], got ${String(p.planets)}`);
  if (!(p.gm >= 1 && p.gm <= 500)) throw new RangeError(`lab-orbits: gm must be in [1, 500] m^3/s^2, got ${String(p.gm)}`);
  if (!(p.softening >= 0 && p.softening <= 3))
    throw new RangeError(`lab-orbits: softening must be in [0, 3] m, got ${String(p.softening)}`);
  if (!(INTEGRATOR_NAMES as readonly string[]).includes(p.integrator)) {
    throw new RangeError(`lab-orbits: integrator must be one of ${INTEGRATOR_NAMES.join(', ')}, got ${JSON.stringify(p.integrator)}`);
  }
  if (!Number.isFinite(p.seed)) throw new RangeError(`lab-orbits: seed must be finite, got ${String(p.seed)}`);
  return p;
}

/** World options: 2D, no uniform gravity, room for the planets and launched bodies, 1/60 s steps. */
export function orbitsWorldOptions(options: OrbitsOptions = {}): PhysicsWorldOptions {
  const p = resolveOrbitsOptions(options);
  return { dimensions: 2, capacity: p.planets + LAUNCH_BUDGET + 4, gravity: [0, 0], integrator: p.integrator, dt: 1 / 60, seed: p.seed };
}

/** Largest distance from the sun any planet of `planets` reaches, m (apoapsis bound). */
export function outerRadius(planets: number): number {
  return FIRST_ORBIT * ORBIT_RATIO ** (planets - 1) * 1.1;
}

/**
 * Builds the scene into a fresh 2D world (ideally from `orbitsWorldOptions`).
 * @throws TypeError | RangeError on bad options or a 3D world.
 */
export function buildOrbits(world: PhysicsWorld, options: OrbitsOptions = {}): OrbitsHandles {
  const p = resolveOrbitsOptions(options);
  if (world.dimensions !== 2) throw new RangeError(`lab-orbits: needs a 2D world, got dimensions ${world.dimensions}`);
  setGravitation(world, { constant: 1 });
  const sun = addBody(world, { position: [0, 0], static: true });
  setAttractor(world, sun, { mass: p.gm, softening: p.softening });
  const h: OrbitsHandles = { sun, planets: [], launched: [], params: p };
  const rng = new Rng(p.seed);
  for (let i = 0; i < p.planets; i++) {
    const a = FIRST_ORBIT * ORBIT_RATIO ** i;
    const e = rng.range(0, 0.1);
    const phi = rng.range(0, 2 * Math.PI);
    // Start at periapsis r_p = a (1 - e) with the vis-viva speed v_p = sqrt(G M (1 + e) / (a (1 - e)))
    // (Kepler orbit set-up; Ramtal and Dobre ch. 6), moving counter-clockwise.
    const rp = a * (1 - e);
    const vp = Math.sqrt((p.gm * (1 + e)) / rp);
    const c = Math.cos(phi),
      s = Math.sin(phi);
    h.planets.push(
      addBody(world, {
        position: [rp * c, rp * s],
        velocity: [-vp * s, vp * c],
        radius: 0.12 + 0.03 * (i % 3),
        mass: 1,
        restitution: 1,
        friction: 0,
      }),
    );
  }
  return h;
}

/**
 * Adds a body at (x, y), m, with velocity (vx, vy), m/s (a launch). When the launch budget is used
 * up, the oldest launched body is removed first.
 * @returns its entity id. @throws RangeError on non-finite input or a point inside the sun.
 */
export function launchBody(world: PhysicsWorld, h: OrbitsHandles, x: number, y: number, vx: number, vy: number): number {
  for (const [name, v] of [
    ['x', x],
    ['y', y],
    ['vx', vx],
    ['vy', vy],
  ] as const) {
    if (!Number.isFinite(v)) throw new RangeError(`lab-orbits: launch ${name} must be finite, got ${v}`);
  }
  if (Math.hypot(x, y) < SUN_RADIUS)
    throw new RangeError(`lab-orbits: cannot launch inside the sun (r = ${Math.hypot(x, y).toFixed(2)} m < ${SUN_RADIUS} m)`);
  if (h.launched.length >= LAUNCH_BUDGET) removeOrbiter(world, h, h.launched[0]!);
  const eid = addBody(world, { position: [x, y], velocity: [vx, vy], radius: 0.14, mass: 1, restitution: 1, friction: 0 });
  h.launched.push(eid);
  return eid;
}

/** Removes orbiting body `eid`. @throws RangeError if it is not one of the scene's bodies. */
export function removeOrbiter(world: PhysicsWorld, h: OrbitsHandles, eid: number): void {
  const list = h.planets.includes(eid) ? h.planets : h.launched;
  const i = list.indexOf(eid);
  if (i < 0) throw new RangeError(`lab-orbits: ${eid} is not an orbiting body of this scene`);
  list.splice(i, 1);
  removeBody(world, eid);
}

/**
 * Sets the sun's G M (m^3/s^2, in [1, 500]) and softening (m, in [0, 3]) on the running world.
 * @throws RangeError out of range.
 */
export function setCentralMass(world: PhysicsWorld, h: OrbitsHandles, gm: number, softening: number): void {
  const p = resolveOrbitsOptions({ ...h.params, gm, softening });
  setAttractor(world, h.sun, { mass: p.gm, softening: p.softening });
  h.params = p;
}
