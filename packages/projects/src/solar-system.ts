import {
  addBody,
  enableMutualGravity,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  type SceneDefinition,
  setGravitation,
  slotOf,
} from '@bitphysics/physics';
import { assertFinite, assertInRange, assertKnownKeys, assertPositive, describe } from '@bitphysics/physics/validate';
import {
  type AstroTime,
  BaryState,
  Body,
  HelioVector,
  MakeTime,
  MassProduct,
  Rotation_EQJ_ECL,
  type RotationMatrix,
} from 'astronomy-engine';

/**
 * The solar system of the book's closing project (Ramtal and Dobre ch. 16), started from and checked
 * against a real ephemeris: the npm package astronomy-engine (Don Cross; truncated VSOP87 series for
 * the planets, the Sun's offset from the barycentre from the four giant planets).
 *
 * Units, after the book's chapter on scaling: the world's unit of length is the astronomical unit
 * (1 AU = `AU` m), its unit of time the day (86,400 s) and its unit of mass the Sun's mass, so
 * `world.time` counts days, positions are in AU, velocities in AU/day, and the gravitational constant
 * is the Sun's G M in AU^3/day^2 (0.2959122082855911e-3, the square of Gauss's constant k =
 * 0.01720209895). Axes: x towards the vernal equinox of J2000, y towards the north ecliptic pole (up),
 * z = -(ecliptic y), so the planets orbit counter-clockwise seen from above (+y) in the x-z plane.
 */

/** The bodies of the scene in entity order: the Sun and the eight planets (Earth is the Earth-Moon barycentre). */
export const SOLAR_SYSTEM_BODIES = ['Sun', 'Mercury', 'Venus', 'Earth', 'Mars', 'Jupiter', 'Saturn', 'Uranus', 'Neptune'] as const;
/** A body of the scene. */
export type SolarSystemBody = (typeof SOLAR_SYSTEM_BODIES)[number];
/** The planets (every body but the Sun), in order from the Sun. */
export const SOLAR_SYSTEM_PLANETS = SOLAR_SYSTEM_BODIES.slice(1) as ReadonlyArray<Exclude<SolarSystemBody, 'Sun'>>;
/** A planet of the scene. */
export type SolarSystemPlanet = Exclude<SolarSystemBody, 'Sun'>;

/** The astronomical unit, m (IAU 2012 resolution B2). */
export const AU = 1.495978707e11;
/** The scene's unit of time, s. */
export const DAY = 86_400;
/** Default start date: 2012-01-01 00:00 UTC, the date of the accuracy goal. */
export const SOLAR_SYSTEM_EPOCH = '2012-01-01T00:00:00Z';

/**
 * The relative position error |r_sim - r_ephemeris| / |r_ephemeris| (heliocentric) that this
 * point-mass model reaches against astronomy-engine one year (366 days) after 2012-01-01 once the
 * integration error is negligible: the model's own floor (the ephemeris has the Moon apart from the
 * Earth, the minor bodies and the truncation of its series; this model has none of them). Measured
 * with RK4 at 0.1 h (RK4 at 1 h, 6 h and velocity Verlet at 15 min give the same digits), rounded up
 * in the second digit; the bench's `solar-system` study measures it again.
 */
export const SOLAR_SYSTEM_FLOOR: Readonly<Record<SolarSystemPlanet, number>> = Object.freeze({
  Mercury: 2.9e-3,
  Venus: 1.5e-4,
  Earth: 1.8e-4,
  Mars: 2.5e-4,
  Jupiter: 2.5e-5,
  Saturn: 6.7e-6,
  Uranus: 4.7e-6,
  Neptune: 2.4e-6,
});

/** Options of the `solar-system` scene. */
export interface SolarSystemOptions {
  /** Bodies: must be 9 (the Sun and eight planets) when given; the option exists for the scene registry. */
  count?: number;
  /** Unused (the scene has no randomness); any finite number. */
  seed?: number;
  /**
   * Start date: an ISO 8601 string, a Date or milliseconds since 1970 (UTC), between the years 1700
   * and 2300 (the span where astronomy-engine's series are accurate). Default `SOLAR_SYSTEM_EPOCH`.
   */
  date?: string | number | Date;
  /** Time step of `worldOptions`, hours, in (0, 24 * 365]. Default 1. */
  stepHours?: number;
  /** Integration scheme of `worldOptions`. Default 'rk4'. */
  integrator?: IntegratorName;
}

/** What `solarSystem.build` returns. */
export interface SolarSystemHandles {
  /** Entity handle of each body by name (index stores with `slotOf`). */
  readonly bodies: Readonly<Record<SolarSystemBody, number>>;
  /** Entities in `SOLAR_SYSTEM_BODIES` order. */
  readonly ids: Uint32Array;
  /** The date at `world.time` = 0, ms since 1970 UTC (`world.time` counts days after it). */
  readonly epoch: number;
}

const KNOWN = ['count', 'seed', 'date', 'stepHours', 'integrator'];
const MIN_DATE = Date.UTC(1700, 0, 1);
const MAX_DATE = Date.UTC(2300, 0, 1);

/** The astronomy-engine body behind each name (Earth: the Earth-Moon barycentre). */
const ENGINE_BODY: Readonly<Record<SolarSystemBody, Body>> = Object.freeze({
  Sun: Body.Sun,
  Mercury: Body.Mercury,
  Venus: Body.Venus,
  Earth: Body.EMB,
  Mars: Body.Mars,
  Jupiter: Body.Jupiter,
  Saturn: Body.Saturn,
  Uranus: Body.Uranus,
  Neptune: Body.Neptune,
});

/**
 * The mass of each body in solar masses: astronomy-engine's G M (AU^3/day^2) over the Sun's; the
 * Earth-Moon barycentre carries both masses.
 */
export function solarSystemMass(body: SolarSystemBody): number {
  return MassProduct(ENGINE_BODY[body]) / MassProduct(Body.Sun);
}

/** Reads a start date option as ms since 1970 UTC. @throws RangeError | TypeError on anything else. */
function epochOf(where: string, date: string | number | Date | undefined): number {
  const value = date ?? SOLAR_SYSTEM_EPOCH;
  let ms: number;
  if (typeof value === 'string') ms = Date.parse(value);
  else if (typeof value === 'number') ms = value;
  else if (value instanceof Date) ms = value.getTime();
  else throw new TypeError(`${where}: date must be an ISO string, a Date or ms since 1970, got ${describe(value)}`);
  if (!(ms >= MIN_DATE && ms <= MAX_DATE)) {
    throw new RangeError(`${where}: date must be a valid date between 1700 and 2300, got ${describe(date)}`);
  }
  return ms;
}

let eqjToEcl: RotationMatrix | null = null;

/**
 * Writes the J2000 equatorial vector (x, y, z) as the scene's axes into out[offset..offset+2]: first
 * to the J2000 ecliptic (astronomy-engine's Rotation_EQJ_ECL), then (x, y, z)_ecl -> (x, z, -y).
 */
function toScene(x: number, y: number, z: number, out: Float64Array, offset: number): void {
  const r = (eqjToEcl ??= Rotation_EQJ_ECL()).rot;
  // astronomy-engine's matrices act as v'_j = sum_i v_i rot[i][j].
  const ex = x * r[0]![0]! + y * r[1]![0]! + z * r[2]![0]!;
  const ey = x * r[0]![1]! + y * r[1]![1]! + z * r[2]![1]!;
  const ez = x * r[0]![2]! + y * r[1]![2]! + z * r[2]![2]!;
  out[offset] = ex;
  out[offset + 1] = ez;
  out[offset + 2] = -ey;
}

function timeOf(epoch: number, days: number): AstroTime {
  return MakeTime(new Date(epoch)).AddDays(days);
}

/**
 * The ephemeris' barycentric state of `body` at `days` after `epoch` (ms since 1970 UTC): position
 * (AU) in out[0..2] and velocity (AU/day) in out[3..5], in the scene's axes. Source: astronomy-engine's
 * BaryState. @returns out.
 */
export function ephemerisState(body: SolarSystemBody, epoch: number, days: number, out: Float64Array = new Float64Array(6)): Float64Array {
  const s = BaryState(ENGINE_BODY[body], timeOf(epoch, days));
  toScene(s.x, s.y, s.z, out, 0);
  toScene(s.vx, s.vy, s.vz, out, 3);
  return out;
}

/**
 * The ephemeris' heliocentric position of `planet` (AU, scene axes) at `days` after `epoch` (ms since
 * 1970 UTC), written into out[0..2]. Source: astronomy-engine's HelioVector. @returns out.
 */
export function ephemerisHeliocentric(
  planet: SolarSystemPlanet,
  epoch: number,
  days: number,
  out: Float64Array = new Float64Array(3),
): Float64Array {
  const v = HelioVector(ENGINE_BODY[planet], timeOf(epoch, days));
  toScene(v.x, v.y, v.z, out, 0);
  return out;
}

const helio = new Float64Array(3);

/**
 * Each planet's position error against the ephemeris now (at `world.time` days after the epoch):
 * |(r_planet - r_sun)_world - r_ephemeris| / |r_ephemeris|, heliocentric, dimensionless. Written into
 * `out` (one entry per planet, `SOLAR_SYSTEM_PLANETS` order) and returned.
 */
export function solarSystemErrors(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  out: Float64Array = new Float64Array(SOLAR_SYSTEM_PLANETS.length),
): Float64Array {
  const P = world.components.Position;
  const sun = slotOf(handles.bodies.Sun);
  for (let i = 0; i < SOLAR_SYSTEM_PLANETS.length; i++) {
    const name = SOLAR_SYSTEM_PLANETS[i]!;
    const e = slotOf(handles.bodies[name]);
    ephemerisHeliocentric(name, handles.epoch, world.time, helio);
    const dx = P.x[e]! - P.x[sun]! - helio[0]!,
      dy = P.y[e]! - P.y[sun]! - helio[1]!,
      dz = P.z[e]! - P.z[sun]! - helio[2]!;
    out[i] = Math.hypot(dx, dy, dz) / Math.hypot(helio[0]!, helio[1]!, helio[2]!);
  }
  return out;
}

/**
 * `solar-system`: the Sun and the eight planets (Earth as the Earth-Moon barycentre) as point masses
 * in mutual Newtonian gravity, no softening, starting from astronomy-engine's barycentric positions
 * and velocities at `date`, in AU, days and solar masses (see the file's header). The Sun moves.
 * Deterministic (no randomness). Default world: 3D, no uniform gravity, RK4 at one hour.
 */
export const solarSystem: SceneDefinition<SolarSystemOptions, SolarSystemHandles> = {
  name: 'solar-system',
  description: 'The Sun and eight planets in mutual gravity from a real ephemeris (astronomy-engine), AU and days; 3D',
  defaultCount: SOLAR_SYSTEM_BODIES.length,
  worldOptions(options = {}) {
    const where = 'solarSystem.worldOptions';
    assertKnownKeys(where, options, KNOWN);
    const hours = options.stepHours ?? 1;
    assertPositive(where, 'stepHours', hours);
    assertInRange(where, 'stepHours', hours, 0, 24 * 365);
    const integrator = options.integrator ?? 'rk4';
    if (!(INTEGRATOR_NAMES as readonly string[]).includes(integrator)) {
      throw new RangeError(`${where}: integrator must be one of ${INTEGRATOR_NAMES.join(', ')}, got ${describe(integrator)}`);
    }
    return { dimensions: 3, capacity: 16, gravity: [0, 0, 0], dt: hours / 24, integrator, sleep: false };
  },
  build(world: PhysicsWorld, options: SolarSystemOptions = {}) {
    const where = 'solarSystem.build';
    assertKnownKeys(where, options, KNOWN);
    if (world.dimensions !== 3) throw new RangeError(`${where}: needs a 3D world, got dimensions ${world.dimensions}`);
    if (options.count !== undefined && options.count !== SOLAR_SYSTEM_BODIES.length) {
      throw new RangeError(
        `${where}: count must be ${SOLAR_SYSTEM_BODIES.length} (the Sun and eight planets), got ${describe(options.count)}`,
      );
    }
    if (options.seed !== undefined) assertFinite(where, 'seed', options.seed);
    const start = epochOf(where, options.date);
    const epoch = start - world.time * DAY * 1000;
    if (world.capacity - world.entityIndex.aliveCount < SOLAR_SYSTEM_BODIES.length) {
      throw new RangeError(
        `${where}: the world has room for ${world.capacity - world.entityIndex.aliveCount} more entities, needs ${SOLAR_SYSTEM_BODIES.length}`,
      );
    }
    setGravitation(world, { constant: MassProduct(Body.Sun), softening: 0, method: 'direct' });
    const state = new Float64Array(6);
    const ids = new Uint32Array(SOLAR_SYSTEM_BODIES.length);
    const bodies = {} as Record<SolarSystemBody, number>;
    SOLAR_SYSTEM_BODIES.forEach((name, i) => {
      ephemerisState(name, start, 0, state);
      const eid = addBody(world, { position: state.subarray(0, 3), velocity: state.subarray(3, 6), mass: solarSystemMass(name) });
      enableMutualGravity(world, eid);
      ids[i] = eid;
      bodies[name] = eid;
    });
    return { bodies: Object.freeze(bodies), ids, epoch };
  },
};
