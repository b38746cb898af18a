/**
 * The solar system's missions, DOM-free (Node tests fly them): send a probe from the Earth to another
 * planet. The player picks the launch (a direction in the ecliptic and a speed leaving the Earth) and
 * the moment; a flight plan (`planFlight`) says at once where that launch would go, and the probe then
 * flies in the page's physics world, pulled by the Sun and every planet.
 *
 * - The probe is a body of negligible mass (`PROBE_MASS` solar masses) in mutual gravity with the Sun
 *   and the planets. It starts `LAUNCH_OFFSET` AU from the Earth-Moon barycentre along the launch
 *   direction d, with the Earth's velocity plus w d, w = sqrt(v_inf^2 + 2 mu_E / LAUNCH_OFFSET): the
 *   speed that climbs out of the Earth's pull with v_inf left (energy conservation, vis-viva), so the
 *   launch speed the player sets is the speed relative to the Earth far from it (v-infinity).
 * - The plan is the two-body (Sun and probe) Kepler motion of that departure, v = v_Earth + v_inf d,
 *   against the target's own Kepler orbit about the Sun (./kepler.ts), sampled over the plan's window.
 *   The planets' pulls on the probe, which the flight feels, bend its real path a little from the plan.
 * - A mission is won when the probe comes within the target's `zone` (AU): the ring drawn round it.
 *   It fails when the probe falls into the Sun (within `SUN_ZONE`), leaves the solar system (beyond
 *   `ESCAPE_DISTANCE`) or flies past the plan's end without arriving.
 * - On the way, burns (`burnProbe`) change the probe's velocity by BURN_STEP km/s along its motion,
 *   against it, away from the Sun or towards it, up to CORRECTION_FUEL km/s in all; the course is
 *   planned again from the probe (`planCourse`), and its arrival miss is what the burns are for.
 * - Stars: for the mission's speed budget, the launch speed plus the burns': 3 for at most
 *   `stars3` km/s, 2 for at most `stars2`, else 1. The least a
 *   launch can take is about the Hohmann transfer's v_inf = v_E (sqrt(2 r / (1 AU + r)) - 1) for
 *   circular orbits (Hohmann 1925; Curtis, Orbital Mechanics, sect. 6.3); the 3-star line is about
 *   0.4 km/s above it, so 3 stars want a good moment (waiting for it), not just any launch that
 *   arrives (scripts/solar-system-pilot.mjs finds a 3-star launch for each mission within 800 days).
 *
 * Units: the world's (AU, days, solar masses; see @bitphysics/projects solar-system). Speeds the
 * player sees are km/s (`KM_S` AU/day each).
 */

import { listCheck, numberCheck, type StorageOptions, type StoredValue, storedValue } from '@bitphysics/game-kit';
import { addBody, enableMutualGravity, type PhysicsWorld, removeBody, setVelocity, slotOf } from '@bitphysics/physics';
import { AU, DAY, type SolarSystemHandles, type SolarSystemPlanet, solarSystemMass } from '@bitphysics/projects';
import { keplerState } from './kepler';

/** One km/s in AU/day: 1000 m/s x DAY s / AU m. */
export const KM_S = (1000 * DAY) / AU;

/** Mass of the probe, solar masses (a 1,000 kg craft is 5e-28: below anything the planets would feel). */
export const PROBE_MASS = 1e-24;

/** Distance from the Earth-Moon barycentre the probe starts at, AU (beyond the Earth's Hill sphere, 0.01 AU). */
export const LAUNCH_OFFSET = 0.012;

/** Within this distance of the Sun's centre the probe has fallen into it, AU (the drawn Sun's size). */
export const SUN_ZONE = 0.04;

/** Beyond this distance from the Sun the probe has left the solar system, AU. */
export const ESCAPE_DISTANCE = 60;

/** Fastest launch the player can set, km/s. */
export const MAX_SPEED = 20;

/**
 * Share of the zone within which a plan calls a launch a hit: the flight, whose path the other
 * planets bend a little from the plan, then still arrives.
 */
export const PLAN_MARGIN = 0.85;

/** Samples of a flight plan (points of its path). */
export const PLAN_SAMPLES = 400;

/** Points of a plan's target track: where the target goes from now to the plan's time (see FlightPlan.targetTrack). */
export const TARGET_TRACK = 24;

/** One mission: the planet to reach, the ring round it that counts as reaching it, and the star thresholds. */
export interface Mission {
  /** The planet to reach. */
  readonly target: SolarSystemPlanet;
  /** Radius of the arrival zone round the target, AU (drawn as a ring; see the file's header). */
  readonly zone: number;
  /** Launch speeds (v_inf, km/s) that still earn 3 stars and 2 stars. */
  readonly stars3: number;
  readonly stars2: number;
  /** The target's mean distance from the Sun (semi-major axis), AU: sets the mission's flight step (`missionTimeStep`). */
  readonly distance: number;
  /** What is new about this mission, one sentence for the player (shown under the goal and on the result card). */
  readonly brief: string;
}

/**
 * The missions in order: Mars, then Venus (inwards: the probe must slow down), Jupiter, Mercury, Saturn,
 * Uranus, Neptune. Zones grow outwards with the orbits, so each ring looks about as large on the
 * compressed scale (./distance-scale.ts).
 */
export const MISSIONS: readonly Mission[] = Object.freeze(
  (
    [
      {
        target: 'Mars',
        zone: 0.14,
        stars3: 3.3,
        stars2: 4.5,
        distance: 1.524,
        brief: 'Mars is farther out: launch along the Earth’s path, fast enough to climb out to its orbit.',
      },
      {
        target: 'Venus',
        zone: 0.1,
        stars3: 2.9,
        stars2: 4,
        distance: 0.723,
        brief: 'Venus is nearer the Sun: launch against the Earth’s path to slow down and fall inwards.',
      },
      {
        target: 'Jupiter',
        zone: 0.75,
        stars3: 9.2,
        stars2: 11,
        distance: 5.203,
        brief: 'Jupiter is 5 AU out and takes almost 3 years to reach: launch where it will be, not where it is.',
      },
      {
        target: 'Mercury',
        zone: 0.08,
        stars3: 7.9,
        stars2: 10,
        distance: 0.387,
        brief: 'Mercury is small and fast, deep in the Sun’s pull: its ring is the smallest, so aim finely.',
      },
      {
        target: 'Saturn',
        zone: 1.2,
        stars3: 10.7,
        stars2: 13,
        distance: 9.537,
        brief: 'Saturn is nearly twice as far out as Jupiter: a cheap launch takes 6 years, so wait for a good moment.',
      },
      {
        target: 'Uranus',
        zone: 1.9,
        stars3: 11.7,
        stars2: 14,
        distance: 19.19,
        brief: 'Uranus is 19 AU out: the slightest error grows over 16 years, so use the burns on the way.',
      },
      {
        target: 'Neptune',
        zone: 3,
        stars3: 12.1,
        stars2: 15,
        distance: 30.07,
        brief: 'Neptune, the last: 30 AU and 30 years of flight for the cheapest launch.',
      },
    ] satisfies Mission[]
  ).map((m) => Object.freeze(m)),
);

/** A launch: direction and speed. */
export interface Aim {
  /**
   * Direction in the ecliptic, degrees in (-180, 180]: 0 along the Earth's motion round the Sun, 90
   * straight away from the Sun, 180 against the Earth's motion, -90 towards the Sun.
   */
  angle: number;
  /** Speed relative to the Earth once clear of its pull (v_inf), km/s, in [0, MAX_SPEED]. */
  speed: number;
}

/** What a launch would do (`planFlight`); one object, filled in place. */
export interface FlightPlan {
  /** Whether the probe would come within PLAN_MARGIN of the target's zone. */
  hit: boolean;
  /** Days from launch to the arrival (a hit) or to the closest approach (a miss). */
  time: number;
  /** Closest approach to the target's centre, AU (within the zone for a hit). */
  distance: number;
  /** Days the plan covers: one orbit of the probe, at most 3 Hohmann transfer times to the target. */
  window: number;
  /**
   * Days until the path first crosses the target's distance from the Sun (now), or, if it never
   * does within the window (or the sampled part of it), comes nearest to it: the flight's deadline
   * lets the probe get that far (`flightDeadline`).
   */
  orbitTime: number;
  /** Whether the probe would fall into the Sun within the window (the path stops there). */
  sun: boolean;
  /** Farthest and nearest the probe gets from the Sun over the window, AU. */
  farthest: number;
  nearest: number;
  /**
   * Where the target would be at `time` relative to the probe, degrees of heliocentric longitude:
   * positive ahead of the probe (in the direction the planets go round), negative behind.
   */
  ahead: number;
  /** Heliocentric path points, AU (x, y, z each), `points` of them, from the launch to `time` (a hit) or the window's end. */
  readonly path: Float64Array;
  points: number;
  /**
   * How many of the path's points lie up to `time` (all of them on a hit): where the probe goes until
   * the closest approach, the rest of a miss's path being after it. A preview that drew the whole
   * path showed it running through the ghost ring of a miss (the probe passes the place before or
   * after the target is there), against the status line and the hint.
   */
  pointsToTime: number;
  /** Where the target goes from now to `time`, heliocentric AU (x, y, z each), TARGET_TRACK points at equal times: its last is `targetAt`. */
  readonly targetTrack: Float64Array;
  /** The probe's and the target's heliocentric places at `time`, AU. */
  readonly probeAt: Float64Array;
  readonly targetAt: Float64Array;
}

/** A fresh, empty flight plan. */
export function createFlightPlan(): FlightPlan {
  return {
    hit: false,
    time: 0,
    distance: Infinity,
    window: 0,
    orbitTime: 0,
    sun: false,
    farthest: 0,
    nearest: 0,
    ahead: 0,
    path: new Float64Array(3 * (PLAN_SAMPLES + 1)),
    points: 0,
    pointsToTime: 0,
    targetTrack: new Float64Array(3 * TARGET_TRACK),
    probeAt: new Float64Array(3),
    targetAt: new Float64Array(3),
  };
}

/** Stars a mission's speed budget (the launch speed plus the burns', km/s) earns on `mission`: 3, 2 or 1. */
export function starsFor(mission: Mission, speed: number): 1 | 2 | 3 {
  return speed <= mission.stars3 + 1e-9 ? 3 : speed <= mission.stars2 + 1e-9 ? 2 : 1;
}

/** Points of a mission's score for a speed budget of the Hohmann launch speed (`missionScore`). */
export const SCORE_BUDGET = 1000;

/** Most points of a mission's score for a quick flight (`missionScore`). */
export const SCORE_TIME = 250;

/**
 * Most points of a mission's score for arriving at the first launch (`missionScore`): the map shows
 * the transfer orbit and where the target goes, and the verdict only after a try, so reading the
 * map right pays.
 */
export const SCORE_FIRST_TRY = 250;

/** A mission's score (`missionScore`): its parts and their sum, points. */
export interface MissionScore {
  /** SCORE_BUDGET x (the Hohmann launch speed / the speed budget spent): more than SCORE_BUDGET for a launch cheaper than the Hohmann speed. */
  readonly budget: number;
  /** SCORE_TIME x (the Hohmann transfer time / the days flown), at most SCORE_TIME. */
  readonly time: number;
  /** SCORE_FIRST_TRY / the launches it took: SCORE_FIRST_TRY for an arrival at the first launch, half at the second. */
  readonly tries: number;
  /** budget + time + tries. */
  readonly total: number;
}

/**
 * The score of an arrival on `mission` after a speed budget of `speed` km/s (the launch plus the
 * burns), `days` of flight and `launches` launches on this mission (1: the first arrived): points
 * for a cheap flight (the Hohmann transfer's launch speed between circular orbits, 1 AU to
 * mission.distance, over the budget spent, times SCORE_BUDGET: more than SCORE_BUDGET where the
 * orbits' eccentricity makes a moment cheaper than that), for a quick one (the Hohmann transfer's
 * time over the days flown, times SCORE_TIME, at most SCORE_TIME) and for few tries
 * (SCORE_FIRST_TRY / launches). A quicker flight costs speed, so the first two pull against each
 * other: the best scores wait for the cheapest moment, need no burns and arrive at the first
 * launch. Whole points.
 * @throws RangeError on a speed or days that is not finite and > 0, or launches that is not a whole number >= 1.
 */
export function missionScore(mission: Mission, speed: number, days: number, launches = 1): MissionScore {
  if (!(speed > 0 && Number.isFinite(speed))) throw new RangeError(`missionScore: speed must be finite and > 0 km/s, got ${speed}`);
  if (!(days > 0 && Number.isFinite(days))) throw new RangeError(`missionScore: days must be finite and > 0, got ${days}`);
  if (!(Number.isInteger(launches) && launches >= 1))
    throw new RangeError(`missionScore: launches must be a whole number >= 1, got ${launches}`);
  const vH = Math.abs(hohmannSpeed(1, mission.distance, GAUSS_MU));
  const a = (1 + mission.distance) / 2;
  const tH = Math.PI * Math.sqrt((a * a * a) / GAUSS_MU);
  const budget = Math.round((SCORE_BUDGET * vH) / speed);
  const time = Math.round(SCORE_TIME * Math.min(1, tH / days));
  const tries = Math.round(SCORE_FIRST_TRY / launches);
  return { budget, time, tries, total: budget + time + tries };
}

/** The Sun's gravitational parameter G M_sun in the world, AU^3/day^2. */
function muSun(world: PhysicsWorld, handles: SolarSystemHandles): number {
  return world.laws.gravitationalConstant * world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
}

/**
 * The heliocentric state of `body` now: position (AU) into out[0..2], velocity (AU/day) into
 * out[3..5]. @returns out.
 */
export function heliocentricState(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  body: number,
  out: Float64Array = new Float64Array(6),
): Float64Array {
  const P = world.components.Position,
    V = world.components.Velocity;
  const s = slotOf(handles.bodies.Sun),
    e = slotOf(body);
  out[0] = P.x[e]! - P.x[s]!;
  out[1] = P.y[e]! - P.y[s]!;
  out[2] = P.z[e]! - P.z[s]!;
  out[3] = V.x[e]! - V.x[s]!;
  out[4] = V.y[e]! - V.y[s]!;
  out[5] = V.z[e]! - V.z[s]!;
  return out;
}

function checkAim(where: string, aim: Aim): void {
  if (!(aim.angle > -180 - 1e-9 && aim.angle <= 180 + 1e-9))
    throw new RangeError(`${where}: aim.angle must be in (-180, 180] degrees, got ${aim.angle}`);
  if (!(aim.speed >= 0 && aim.speed <= MAX_SPEED))
    throw new RangeError(`${where}: aim.speed must be in [0, ${MAX_SPEED}] km/s, got ${aim.speed}`);
}

const earthState = new Float64Array(6);

/**
 * The launch direction of `aim` in the scene's axes (a unit vector in the ecliptic, y = 0), written
 * into out[0..2], from the Earth's heliocentric state `earth` (position and velocity, 6 numbers):
 * cos(angle) along the Earth's motion plus sin(angle) away from the Sun (made square to the motion).
 * @returns out.
 */
export function launchDirection(
  earth: ArrayLike<number>,
  angle: number,
  out: Float64Array | number[] = new Float64Array(3),
): Float64Array | number[] {
  // Along the motion (prograde), in the ecliptic.
  let px = earth[3]!,
    pz = earth[5]!;
  const pn = Math.hypot(px, pz) || 1;
  px /= pn;
  pz /= pn;
  // Away from the Sun, made square to the motion.
  let ox = earth[0]!,
    oz = earth[2]!;
  const along = ox * px + oz * pz;
  ox -= along * px;
  oz -= along * pz;
  const on = Math.hypot(ox, oz) || 1;
  ox /= on;
  oz /= on;
  const a = (angle * Math.PI) / 180;
  out[0] = Math.cos(a) * px + Math.sin(a) * ox;
  out[1] = 0;
  out[2] = Math.cos(a) * pz + Math.sin(a) * oz;
  return out;
}

const dir = new Float64Array(3);
const probe0 = new Float64Array(6);
const target0 = new Float64Array(6);
const pState = new Float64Array(6);
const tState = new Float64Array(6);

/**
 * Fills `plan` with what launching `aim` now towards `mission`'s target would do: the probe's and the
 * target's two-body Kepler motions about the Sun (see the file's header), sampled PLAN_SAMPLES times
 * over the window, the first sample inside PLAN_MARGIN of the zone refined by bisection (a hit) or the closest
 * sample refined by a golden-section search (a miss). `samples` (at most PLAN_SAMPLES) sets how many
 * samples: fewer for a quick look (the hint's search, ./advice.ts). @returns plan.
 * @throws RangeError on an aim out of range or samples not an integer in [8, PLAN_SAMPLES].
 */
export function planFlight(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  mission: Mission,
  aim: Aim,
  plan: FlightPlan,
  samples: number = PLAN_SAMPLES,
): FlightPlan {
  checkAim('planFlight', aim);
  checkSamples('planFlight', samples);
  heliocentricState(world, handles, handles.bodies.Earth, earthState);
  launchDirection(earthState, aim.angle, dir);
  const vInf = aim.speed * KM_S;
  for (let i = 0; i < 3; i++) {
    probe0[i] = earthState[i]! + LAUNCH_OFFSET * dir[i]!;
    probe0[3 + i] = earthState[3 + i]! + vInf * dir[i]!;
  }
  return planFrom(world, handles, mission, probe0, plan, samples);
}

function checkSamples(where: string, samples: number): void {
  if (!(Number.isInteger(samples) && samples >= 8 && samples <= PLAN_SAMPLES))
    throw new RangeError(`${where}: samples must be an integer in [8, ${PLAN_SAMPLES}], got ${samples}`);
}

/**
 * Fills `plan` with where a flight under way is going: the two-body Kepler motion of the probe from
 * its heliocentric state now (as `planFlight` plans a launch, the window counted from now), against
 * the target's. The speed relative to the Earth is taken as what is left of it once clear of the
 * Earth's pull, sqrt(v_rel^2 - 2 mu_E / d) along the same direction (energy conservation, as
 * `launchProbe` adds it), so just after the launch the course is the launch's plan (without it, the
 * climb still to come out of the Earth's pull would read as 0.07 km/s too fast at 3 km/s). After a
 * burn (`burnProbe`) it says where the new course arrives; with `burn`, where a burn of `burn.dv`
 * km/s in `burn.direction` now would take it (the probe is not changed). `samples` as planFlight's.
 * @returns plan.
 */
export function planCourse(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  flight: Flight,
  plan: FlightPlan,
  burn?: { direction: BurnDirection; dv: number },
  samples: number = PLAN_SAMPLES,
): FlightPlan {
  checkSamples('planCourse', samples);
  heliocentricState(world, handles, flight.probe, probe0);
  if (burn) {
    burnDirection(probe0, burn.direction, burnDir);
    for (let i = 0; i < 3; i++) probe0[3 + i] = probe0[3 + i]! + burn.dv * KM_S * burnDir[i]!;
  }
  heliocentricState(world, handles, handles.bodies.Earth, earthState);
  const muEarth = world.laws.gravitationalConstant * solarSystemMass('Earth');
  const d = Math.hypot(probe0[0]! - earthState[0]!, probe0[1]! - earthState[1]!, probe0[2]! - earthState[2]!);
  const rx = probe0[3]! - earthState[3]!,
    ry = probe0[4]! - earthState[4]!,
    rz = probe0[5]! - earthState[5]!;
  const v2 = rx * rx + ry * ry + rz * rz;
  const k = v2 > 0 ? Math.sqrt(Math.max(0, v2 - (2 * muEarth) / d) / v2) : 1;
  probe0[3] = earthState[3]! + k * rx;
  probe0[4] = earthState[4]! + k * ry;
  probe0[5] = earthState[5]! + k * rz;
  return planFrom(world, handles, flight.mission, probe0, plan, samples);
}

const later = new Float64Array(6);

/**
 * The plan (see `planFlight`) of launching `aim` towards `mission`'s target `days` (>= 0) from now,
 * the Earth and the target carried there on their own two-body orbits about the Sun (the giants'
 * pulls left out: a guess of what waiting would do, for the hint's search, ./advice.ts).
 * `samples` as planFlight's. @returns plan. @throws RangeError on a bad aim, samples or days.
 */
export function planFlightLater(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  mission: Mission,
  aim: Aim,
  days: number,
  plan: FlightPlan,
  samples: number = PLAN_SAMPLES,
): FlightPlan {
  checkAim('planFlightLater', aim);
  checkSamples('planFlightLater', samples);
  if (!(days >= 0 && Number.isFinite(days))) throw new RangeError(`planFlightLater: days must be finite and >= 0, got ${days}`);
  const G = world.laws.gravitationalConstant,
    M = world.components.Mass.value,
    sun = M[slotOf(handles.bodies.Sun)]!;
  heliocentricState(world, handles, handles.bodies.Earth, earthState);
  keplerState(earthState, earthState.subarray(3), G * (sun + M[slotOf(handles.bodies.Earth)]!), days, later);
  launchDirection(later, aim.angle, dir);
  const vInf = aim.speed * KM_S;
  for (let i = 0; i < 3; i++) {
    probe0[i] = later[i]! + LAUNCH_OFFSET * dir[i]!;
    probe0[3 + i] = later[3 + i]! + vInf * dir[i]!;
  }
  const target = handles.bodies[mission.target];
  heliocentricState(world, handles, target, target0);
  keplerState(target0, target0.subarray(3), G * (sun + M[slotOf(target)]!), days, later);
  return planFrom(world, handles, mission, probe0, plan, samples, later);
}

/**
 * The plan (see `planFlight`) of a probe at heliocentric state `start` (position AU, velocity AU/day)
 * now, with `samples` samples, against the target as it is now or at heliocentric state `targetState`.
 */
function planFrom(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  mission: Mission,
  start: Float64Array,
  plan: FlightPlan,
  samples: number,
  targetState?: Float64Array,
): FlightPlan {
  const G = world.laws.gravitationalConstant;
  const mu = muSun(world, handles);
  const target = handles.bodies[mission.target];
  if (targetState) target0.set(targetState.subarray(0, 6));
  else heliocentricState(world, handles, target, target0);
  const muTarget = G * (world.components.Mass.value[slotOf(handles.bodies.Sun)]! + world.components.Mass.value[slotOf(target)]!);
  // The window: one orbit of the probe, at most three Hohmann transfer times to the target's distance.
  const r0 = Math.hypot(start[0]!, start[1]!, start[2]!);
  const v0sq = start[3]! ** 2 + start[4]! ** 2 + start[5]! ** 2;
  const alpha = 2 / r0 - v0sq / mu;
  const rT = Math.hypot(target0[0]!, target0[1]!, target0[2]!);
  const hohmann = Math.PI * Math.sqrt(((r0 + rT) / 2) ** 3 / mu);
  const period = alpha > 0 ? (2 * Math.PI) / Math.sqrt(mu * alpha * alpha * alpha) : Infinity;
  const window = Math.min(period, 3 * hohmann);
  plan.window = window;
  plan.orbitTime = 0;
  plan.hit = false;
  plan.sun = false;
  plan.farthest = 0;
  plan.nearest = Infinity;
  let best = Infinity,
    bestT = 0,
    prevT = 0,
    points = 0,
    crossT = -1,
    side = 0,
    nearOrbit = Infinity,
    nearOrbitT = 0;
  const at = (t: number): number => {
    keplerState(start, start.subarray(3), mu, t, pState);
    keplerState(target0, target0.subarray(3), muTarget, t, tState);
    return Math.hypot(pState[0]! - tState[0]!, pState[1]! - tState[1]!, pState[2]! - tState[2]!);
  };
  let hitT = -1;
  for (let k = 0; k <= samples; k++) {
    const t = (window * k) / samples;
    const d = at(t);
    const r = Math.hypot(pState[0]!, pState[1]!, pState[2]!);
    plan.farthest = Math.max(plan.farthest, r);
    plan.nearest = Math.min(plan.nearest, r);
    plan.path.set(pState.subarray(0, 3), 3 * points++);
    // Where the path first crosses the target's distance from the Sun, or comes nearest to it.
    if (crossT < 0 && k > 0 && (r - rT) * side <= 0) crossT = t;
    side = r - rT;
    if (Math.abs(side) < nearOrbit) {
      nearOrbit = Math.abs(side);
      nearOrbitT = t;
    }
    if (r < SUN_ZONE) {
      plan.sun = true;
      break;
    }
    if (d < PLAN_MARGIN * mission.zone) {
      hitT = t;
      break;
    }
    if (d < best) {
      best = d;
      bestT = t;
    }
    prevT = t;
  }
  if (hitT >= 0) {
    // The zone's edge between the last sample outside and the first inside.
    let lo = prevT,
      hi = hitT;
    for (let i = 0; i < 40; i++) {
      const mid = (lo + hi) / 2;
      if (at(mid) < PLAN_MARGIN * mission.zone) hi = mid;
      else lo = mid;
    }
    plan.hit = true;
    plan.time = hi;
    plan.distance = at(hi);
  } else {
    // The closest approach near the closest sample.
    const step = window / samples;
    let lo = Math.max(0, bestT - step),
      hi = Math.min(window, bestT + step);
    const g = (Math.sqrt(5) - 1) / 2;
    for (let i = 0; i < 40; i++) {
      const a = hi - g * (hi - lo),
        b = lo + g * (hi - lo);
      if (at(a) < at(b)) hi = b;
      else lo = a;
    }
    plan.time = (lo + hi) / 2;
    plan.distance = at(plan.time);
  }
  plan.orbitTime = crossT >= 0 ? crossT : nearOrbitT;
  // The target's track from now to plan.time (before the last at() call, which leaves the states at plan.time).
  for (let i = 0; i < TARGET_TRACK; i++) {
    keplerState(target0, target0.subarray(3), muTarget, (plan.time * i) / (TARGET_TRACK - 1), tState);
    plan.targetTrack.set(tState.subarray(0, 3), 3 * i);
  }
  plan.distance = at(plan.time);
  // at() left the states at plan.time.
  plan.points = points;
  if (plan.hit) plan.path.set(pState.subarray(0, 3), 3 * (plan.points - 1));
  plan.pointsToTime = plan.hit ? points : Math.min(points, Math.floor((plan.time / window) * samples) + 1);
  plan.probeAt.set(pState.subarray(0, 3));
  plan.targetAt.set(tState.subarray(0, 3));
  const lonP = Math.atan2(-pState[2]!, pState[0]!),
    lonT = Math.atan2(-tState[2]!, tState[0]!);
  // Longitude grows the way the planets go (counter-clockwise seen from +y is -z from +x: atan2(-z, x)).
  plan.ahead = ((((lonT - lonP) * 180) / Math.PI + 540) % 360) - 180;
  return plan;
}

/** What a flight step reports. */
export type FlightEvent = 'flying' | 'arrived' | 'sun' | 'missed';

/** A flight under way (`launchProbe`) and how it ended. */
export interface Flight {
  /** The mission flown. */
  readonly mission: Mission;
  /** The launch. */
  readonly aim: Readonly<Aim>;
  /** The probe's entity. */
  readonly probe: number;
  /** world.time at the launch, days. */
  readonly launchTime: number;
  /**
   * Days of flight after which a probe that has not arrived has missed: the plan's time with a
   * margin, within its window (moved by a burn to the new course's: `burnProbe`).
   */
  deadline: number;
  /**
   * The step the flight is flown with, days (`missionTimeStep`): the page steps the world with it
   * and the forecast (./forecast.ts) with the same, so the forecast's verdict is the flight's.
   */
  readonly dt: number;
  /** The plan at the launch. */
  readonly planned: Readonly<Pick<FlightPlan, 'hit' | 'time' | 'distance'>>;
  /** Closest approach to the target so far, AU, and the flight time then, days. */
  closest: number;
  closestAt: number;
  /** How the flight ended ('flying' while it goes on). */
  state: FlightEvent;
  /** Days from the launch to the end (or to now while flying). */
  elapsed: number;
  /** Speed changed by mid-course burns so far, km/s (at most CORRECTION_FUEL). */
  fuelUsed: number;
  /** Mid-course burns so far. */
  burns: number;
}

/** Speed the probe's mid-course burns may change in all, km/s (its fuel for corrections). */
export const CORRECTION_FUEL = 1;

/** Speed change of one burn (a key press or a tap), km/s. */
export const BURN_STEP = 0.05;

/** Directions of a mid-course burn: along the probe's motion round the Sun, against it, away from the Sun, towards it. */
export type BurnDirection = 'faster' | 'slower' | 'out' | 'in';

/** Launch angles (`launchDirection`) of each burn direction, degrees. */
const BURN_ANGLE: Record<BurnDirection, number> = { faster: 0, slower: 180, out: 90, in: -90 };

/**
 * The unit direction of a burn in `direction` for a probe of heliocentric state `state` (position AU,
 * velocity AU/day, 6 numbers), in the ecliptic, into out[0..2] (as `launchDirection` turns a launch).
 * @returns out.
 */
export function burnDirection(state: ArrayLike<number>, direction: BurnDirection, out: Float64Array): Float64Array {
  launchDirection(state, BURN_ANGLE[direction], out);
  return out;
}

/** Real seconds a flight lasts at most on the page: its rate is its deadline over this (`flightRate`). */
export const FLIGHT_SECONDS = 20;

/** Physics steps the page runs in a real second of a flight at most at its rate (60 frames of 24 steps). */
export const FLIGHT_STEPS_PER_SECOND = 60 * 24;

/**
 * Days of flight after which a probe that has not arrived has missed, from the plan `plan` of its
 * course (`planFlight`, `planCourse`) towards a target with a ring of `zone` AU: within the plan's
 * window, the later of the plan's time (its arrival or closest approach) and its time to the
 * target's orbit (or nearest it), or for a wide miss (closest approach beyond 3 rings) the time to
 * the orbit alone, with a margin (1.2 x and 30 days). So a probe is not given up before it reaches
 * the target's orbit (a launch whose closest approach is at the start, the target then on the far
 * side, would otherwise be given up after 30 days, a tenth of the way out to Jupiter), nor flown for decades to a
 * closest approach of many AU (Uranus: 17,900 days, 45 s at the fastest rate).
 */
export function flightDeadline(plan: Pick<FlightPlan, 'time' | 'window' | 'orbitTime' | 'distance'>, zone: number): number {
  const t = plan.distance > 3 * zone ? plan.orbitTime : Math.max(plan.time, plan.orbitTime);
  return Math.min(plan.window, t) * 1.2 + 30;
}

/** A flight's rate on the page, simulated days per real second: its deadline over FLIGHT_SECONDS, within [10, 400]. */
export function flightRate(deadline: number): number {
  return Math.min(400, Math.max(10, deadline / FLIGHT_SECONDS));
}

/** Gauss's gravitational constant squared: the Sun's G M, AU^3/day^2 (for the missions' nominal flight times). */
const GAUSS_MU = 0.01720209895 ** 2;

/**
 * The fixed step of `mission`'s flights (and of the world while aiming at it), days: the aiming step
 * `baseStep` (days), or longer when the rate of a nominal flight, a Hohmann transfer between
 * circular orbits (1 AU to mission.distance; Curtis, Orbital Mechanics, sect. 6.3) with the
 * deadline's margin, needs more than FLIGHT_STEPS_PER_SECOND steps (Jupiter 1.02 hours, the three
 * outermost 400 / 1440 days, 6.7 hours). One step for every launch of a mission, so the planets'
 * motion worked out for one forecast serves them all (./forecast.ts).
 * @throws RangeError on a baseStep that is not finite and > 0.
 */
export function missionTimeStep(mission: Mission, baseStep: number): number {
  if (!(baseStep > 0 && Number.isFinite(baseStep)))
    throw new RangeError(`missionTimeStep: baseStep must be finite and > 0 days, got ${baseStep}`);
  const a = (1 + mission.distance) / 2;
  const hohmann = Math.PI * Math.sqrt((a * a * a) / GAUSS_MU);
  return Math.max(baseStep, flightRate(hohmann * 1.2 + 30) / FLIGHT_STEPS_PER_SECOND);
}

const launchPos = new Float64Array(3);
const launchVel = new Float64Array(3);

/**
 * Launches a probe now with `aim` on `mission`: adds it to the world (see the file's header) and
 * returns its flight, with the deadline taken from `plan` (made for the same aim and moment by
 * `planFlight`; `flightDeadline`) and the step `missionTimeStep(mission, baseStep)` (baseStep in
 * days, default the world's step now). The caller steps the world with `flight.dt` while it flies.
 * @throws RangeError on a bad aim or a world without room for one more body.
 */
export function launchProbe(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  mission: Mission,
  aim: Aim,
  plan: FlightPlan,
  baseStep: number = world.dt,
): Flight {
  checkAim('launchProbe', aim);
  const P = world.components.Position,
    V = world.components.Velocity;
  const earth = slotOf(handles.bodies.Earth);
  heliocentricState(world, handles, handles.bodies.Earth, earthState);
  launchDirection(earthState, aim.angle, dir);
  const G = world.laws.gravitationalConstant;
  const muEarth = G * solarSystemMass('Earth');
  const vInf = aim.speed * KM_S;
  const w = Math.sqrt(vInf * vInf + (2 * muEarth) / LAUNCH_OFFSET);
  launchPos[0] = P.x[earth]! + LAUNCH_OFFSET * dir[0]!;
  launchPos[1] = P.y[earth]! + LAUNCH_OFFSET * dir[1]!;
  launchPos[2] = P.z[earth]! + LAUNCH_OFFSET * dir[2]!;
  launchVel[0] = V.x[earth]! + w * dir[0]!;
  launchVel[1] = V.y[earth]! + w * dir[1]!;
  launchVel[2] = V.z[earth]! + w * dir[2]!;
  const probe = addBody(world, { position: launchPos, velocity: launchVel, mass: PROBE_MASS });
  enableMutualGravity(world, probe);
  const deadline = flightDeadline(plan, mission.zone);
  return {
    mission,
    aim: Object.freeze({ ...aim }),
    probe,
    launchTime: world.time,
    deadline,
    dt: missionTimeStep(mission, baseStep),
    planned: Object.freeze({ hit: plan.hit, time: plan.time, distance: plan.distance }),
    closest: Infinity,
    closestAt: 0,
    state: 'flying',
    elapsed: 0,
    fuelUsed: 0,
    burns: 0,
  };
}

const burnState = new Float64Array(6);
const burnDir = new Float64Array(3);

/**
 * A mid-course burn: changes the velocity of `flight`'s probe by `dv` km/s in `direction` (in the
 * ecliptic, from its heliocentric motion now: along it, against it, away from the Sun or towards
 * it, as `launchDirection` turns a launch), at most the CORRECTION_FUEL left. Then plans the new
 * course into `plan` (`planCourse`) and moves the flight's deadline to the new plan's time with the
 * launch's margin. No burn (and no plan) once the flight has ended or the fuel is gone.
 * @returns the speed change made, km/s (0 when none). @throws RangeError on a dv that is not finite and > 0 or an unknown direction.
 */
export function burnProbe(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  flight: Flight,
  direction: BurnDirection,
  dv: number,
  plan: FlightPlan,
): number {
  if (!(dv > 0 && Number.isFinite(dv))) throw new RangeError(`burnProbe: dv must be finite and > 0 km/s, got ${dv}`);
  if (!(direction in BURN_ANGLE))
    throw new RangeError(`burnProbe: direction must be one of ${Object.keys(BURN_ANGLE).join(', ')}, got ${String(direction)}`);
  const left = CORRECTION_FUEL - flight.fuelUsed;
  if (flight.state !== 'flying' || left <= 1e-9) return 0;
  const change = Math.min(dv, left);
  heliocentricState(world, handles, flight.probe, burnState);
  burnDirection(burnState, direction, burnDir);
  const V = world.components.Velocity,
    p = slotOf(flight.probe);
  const k = change * KM_S;
  launchVel[0] = V.x[p]! + k * burnDir[0]!;
  launchVel[1] = V.y[p]! + k * burnDir[1]!;
  launchVel[2] = V.z[p]! + k * burnDir[2]!;
  setVelocity(world, flight.probe, launchVel);
  flight.fuelUsed = Math.min(CORRECTION_FUEL, flight.fuelUsed + change);
  flight.burns++;
  planCourse(world, handles, flight, plan);
  flight.deadline = flight.elapsed + flightDeadline(plan, flight.mission.zone);
  return change;
}

/**
 * Checks a flight after a step of the world: arrived within the zone, fallen into the Sun, gone past
 * ESCAPE_DISTANCE or the deadline (missed), or still flying. The probe stays in the world (the page
 * removes it with `endFlight`). A flight that has ended keeps its state. @returns the state.
 */
export function checkFlight(world: PhysicsWorld, handles: SolarSystemHandles, flight: Flight): FlightEvent {
  if (flight.state !== 'flying') return flight.state;
  const P = world.components.Position;
  const p = slotOf(flight.probe),
    t = slotOf(handles.bodies[flight.mission.target]),
    s = slotOf(handles.bodies.Sun);
  const px = P.x[p]!,
    py = P.y[p]!,
    pz = P.z[p]!;
  const d = Math.hypot(px - P.x[t]!, py - P.y[t]!, pz - P.z[t]!);
  const r = Math.hypot(px - P.x[s]!, py - P.y[s]!, pz - P.z[s]!);
  flight.elapsed = world.time - flight.launchTime;
  if (d < flight.closest) {
    flight.closest = d;
    flight.closestAt = flight.elapsed;
  }
  if (d < flight.mission.zone) flight.state = 'arrived';
  else if (r < SUN_ZONE) flight.state = 'sun';
  else if (r > ESCAPE_DISTANCE || flight.elapsed > flight.deadline) flight.state = 'missed';
  return flight.state;
}

/** Removes a flight's probe from the world (after it ended, or to abandon it). No effect if it is already gone. */
export function endFlight(world: PhysicsWorld, flight: Flight): void {
  try {
    removeBody(world, flight.probe);
  } catch {
    /* already removed (a reset made a new world) */
  }
}

/**
 * The Hohmann transfer's launch speed from the Earth (a circular orbit of radius rEarth, AU) to a
 * circular orbit of radius rTarget (AU) about a centre of parameter mu (AU^3/day^2), km/s: positive
 * outwards (along the Earth's motion), negative inwards (against it).
 */
export function hohmannSpeed(rEarth: number, rTarget: number, mu: number): number {
  const v = Math.sqrt(mu / rEarth);
  return (v * (Math.sqrt((2 * rTarget) / (rEarth + rTarget)) - 1)) / KM_S;
}

/** The storage key of the best stars per mission: a JSON list, one whole number 0 to 3 a mission of MISSIONS (0: not flown). */
export const STARS_KEY = 'bitphysics.solar-system.stars';
/** The storage key of the best score per mission: a JSON list, one whole number of points a mission (0: not won). */
export const SCORES_KEY = 'bitphysics.solar-system.scores';
/** The storage key of the last mission started: its index in MISSIONS (0-based), as a number's text. */
export const LAST_MISSION_KEY = 'bitphysics.solar-system.mission';
/** The highest mission score kept, points: far over any `missionScore` total, so a higher stored one is garbage. */
export const MAX_KEPT_SCORE = 1e9;

/** The missions' progress kept across reloads (`missionProgress`). */
export interface MissionProgress {
  /** Best stars of each mission, a whole number in [0, 3] (0: not flown). */
  stars: StoredValue<number[]>;
  /** Best score of each mission, whole points in [0, MAX_KEPT_SCORE] (0: not won). */
  scores: StoredValue<number[]>;
  /** The last mission started, an index in MISSIONS (0 where none is kept). */
  last: StoredValue<number>;
}

/**
 * The missions' progress in the page's storage (or `options.storage`), under STARS_KEY, SCORES_KEY
 * and LAST_MISSION_KEY; a stored entry out of its range, or not a whole number, reads as 0.
 */
export function missionProgress(options?: StorageOptions): MissionProgress {
  const n = MISSIONS.length;
  const zeros = MISSIONS.map(() => 0);
  return {
    stars: storedValue(STARS_KEY, listCheck(numberCheck({ max: 3, integer: true }), n, 0), zeros, options),
    scores: storedValue(SCORES_KEY, listCheck(numberCheck({ max: MAX_KEPT_SCORE, integer: true }), n, 0), zeros, options),
    last: storedValue(LAST_MISSION_KEY, numberCheck({ max: n - 1, integer: true }), 0, options),
  };
}
