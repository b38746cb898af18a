/**
 * The solar system's hints, DOM-free (Node tests run them): which way to change a launch, or which
 * burn to make in flight, and by how much, in the presses of the page's keys and buttons.
 *
 * A hint is only worth giving if it is right, so each is checked with the forecast (./forecast.ts:
 * the flight itself, flown ahead): the two-body Kepler plan (./missions.ts planFlight, planCourse,
 * quick with few samples) picks the candidates, fewest presses first, and the first whose forecast
 * arrives is the hint. Waiting is guessed from the Kepler plan alone (the planets carried on their
 * own orbits), so it is said as "about".
 */

import { type PhysicsWorld, slotOf } from '@bitphysics/physics';
import type { SolarSystemHandles } from '@bitphysics/projects';
import { createForecast, type Forecast, forecastCourse, forecastLaunch } from './forecast';
import {
  type Aim,
  BURN_STEP,
  type BurnDirection,
  CORRECTION_FUEL,
  createFlightPlan,
  type Flight,
  heliocentricState,
  hohmannSpeed,
  MAX_SPEED,
  type Mission,
  planCourse,
  planFlight,
  planFlightLater,
} from './missions';

/** Degrees one press of ← or → turns the launch arrow (the page's turn step). */
export const TURN_STEP = 2;
/** km/s one press of ↑ or ↓ changes the launch speed by (the page's speed step). */
export const SPEED_STEP = 0.1;
/** Most presses of one kind a hint suggests: turns up to 90 degrees, speed changes up to 4 km/s. */
const MAX_TURNS = 45;
const MAX_SPEEDS = 40;
/** Kepler samples of a candidate (a quick look; the forecast checks the one chosen). */
const QUICK = 100;
/** Most candidates a hint checks with the forecast. */
const MAX_CHECKS = 6;
/** Days ahead the waiting guess looks, and its step (5 days: an eighth of a second of Wait). */
const WAIT_HORIZON = 800;
const WAIT_STEP = 5;
/** Speeds added to the launch the waiting guess tries, km/s, least first. */
const WAIT_EXTRA = [0, 0.5, 1, 2];

/** A launch hint (`adviseAim`). */
export interface AimAdvice {
  /**
   * 'launch': the launch arrives as it is; 'change': turn by `turn` and change the speed by `speed`
   * (one of them 0) and it arrives (checked by the forecast); 'wait': waiting about `days` days
   * brings the planets round for this launch, `speed` km/s faster (a Kepler guess); 'none': nothing
   * near it arrives.
   */
  kind: 'launch' | 'change' | 'wait' | 'none';
  /** Degrees to turn the arrow: positive outwards (away from the Sun: → on the page), negative inwards (←). */
  turn: number;
  /** km/s to add to the launch speed (negative: less). */
  speed: number;
  /** Days to wait (kind 'wait'). */
  days: number;
  /** Presses the change takes (kind 'change'): |turn| / TURN_STEP + |speed| / SPEED_STEP. */
  presses: number;
  /** The forecast of the launch hinted (kind 'change'). */
  readonly forecast: Forecast;
}

/** A fresh, empty launch hint. */
export function createAimAdvice(): AimAdvice {
  return { kind: 'none', turn: 0, speed: 0, days: 0, presses: 0, forecast: createForecast() };
}

const quickPlan = createFlightPlan();

/** `angle` in (-180, 180]. */
function wrap(angle: number): number {
  const a = ((((angle + 180) % 360) + 360) % 360) - 180;
  return a === -180 ? 180 : Math.round(a * 10) / 10;
}

/**
 * What to change of the launch `aim` (whose forecast is `current`) so that it arrives: the change
 * of fewest presses (turning or speed, one at a time) whose forecast arrives, else the wait after
 * which the Kepler plan of this launch arrives, into `out`. `baseStep` is the page's aiming step,
 * days (the forecast's, see forecastLaunch). @returns out.
 */
export function adviseAim(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  mission: Mission,
  aim: Aim,
  baseStep: number,
  current: Forecast,
  out: AimAdvice = createAimAdvice(),
): AimAdvice {
  out.turn = 0;
  out.speed = 0;
  out.days = 0;
  out.presses = 0;
  if (current.outcome === 'arrived') {
    out.kind = 'launch';
    return out;
  }
  // Candidates, fewest presses first: a turn either way, then a speed change either way.
  let checks = 0;
  for (let k = 1; k <= Math.max(MAX_TURNS, MAX_SPEEDS) && checks < MAX_CHECKS; k++) {
    const tries: Array<[number, number]> = [];
    if (k <= MAX_TURNS) tries.push([k * TURN_STEP, 0], [-k * TURN_STEP, 0]);
    if (k <= MAX_SPEEDS) tries.push([0, k * SPEED_STEP], [0, -k * SPEED_STEP]);
    for (const [turn, dv] of tries) {
      const speed = Math.round((aim.speed + dv) * 10) / 10;
      if (speed < 0 || speed > MAX_SPEED) continue;
      const tried = { angle: wrap(aim.angle + turn), speed };
      planFlight(world, handles, mission, tried, quickPlan, QUICK);
      if (!(quickPlan.distance < mission.zone) || checks >= MAX_CHECKS) continue;
      checks++;
      forecastLaunch(world, handles, mission, tried, baseStep, out.forecast);
      if (out.forecast.outcome === 'arrived') {
        out.kind = 'change';
        out.turn = turn;
        out.speed = Math.round(dv * 10) / 10;
        out.presses = k;
        return out;
      }
    }
  }
  // Waiting: the first time this launch's Kepler plan arrives, or with a little more speed (the
  // target may be out of reach at this speed whenever it is).
  for (let days = WAIT_STEP; days <= WAIT_HORIZON; days += WAIT_STEP)
    for (const extra of WAIT_EXTRA) {
      const speed = Math.round((aim.speed + extra) * 10) / 10;
      if (speed > MAX_SPEED) continue;
      if (planFlightLater(world, handles, mission, { angle: aim.angle, speed }, days, quickPlan, QUICK).hit) {
        out.kind = 'wait';
        out.days = days;
        out.speed = extra;
        return out;
      }
    }
  out.kind = 'none';
  return out;
}

/** A burn hint (`adviseBurn`). */
export interface BurnAdvice {
  /**
   * 'coast': on course, no burn needed; 'burn': `presses` burns of BURN_STEP in `direction` now and
   * it arrives (checked by the forecast); 'none': no burn within the fuel left brings it in; 'empty': no fuel left.
   */
  kind: 'coast' | 'burn' | 'none' | 'empty';
  direction: BurnDirection;
  presses: number;
  /** The forecast after the burns hinted (kind 'burn'). */
  readonly forecast: Forecast;
}

/** A fresh, empty burn hint. */
export function createBurnAdvice(): BurnAdvice {
  return { kind: 'none', direction: 'faster', presses: 0, forecast: createForecast() };
}

const DIRECTIONS: readonly BurnDirection[] = ['faster', 'slower', 'out', 'in'];

/**
 * Which burn brings `flight` (whose forecast from now is `current`) into the ring: the fewest
 * presses of one direction, each BURN_STEP km/s now, within the fuel left, whose forecast arrives,
 * into `out`. @returns out.
 */
export function adviseBurn(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  flight: Flight,
  current: Forecast,
  out: BurnAdvice = createBurnAdvice(),
): BurnAdvice {
  out.presses = 0;
  if (current.outcome === 'arrived') {
    out.kind = 'coast';
    return out;
  }
  const most = Math.floor((CORRECTION_FUEL - flight.fuelUsed) / BURN_STEP + 1e-9);
  if (most < 1) {
    out.kind = 'empty';
    return out;
  }
  let checks = 0;
  for (let n = 1; n <= most && checks < MAX_CHECKS; n++) {
    for (const direction of DIRECTIONS) {
      const burn = { direction, dv: n * BURN_STEP };
      planCourse(world, handles, flight, quickPlan, burn, QUICK);
      if (!(quickPlan.distance < flight.mission.zone) || checks >= MAX_CHECKS) continue;
      checks++;
      forecastCourse(world, handles, flight, out.forecast, burn);
      if (out.forecast.outcome === 'arrived') {
        out.kind = 'burn';
        out.direction = direction;
        out.presses = n;
        return out;
      }
    }
  }
  out.kind = 'none';
  return out;
}

/** How far below the slowest arriving launch mission 1 starts, km/s: a few presses of faster launch. */
export const TUTORIAL_SHORTFALL = 0.8;

/**
 * Mission 1's starting aim, a lesson in one change: the launch direction of an arriving course
 * near the Hohmann transfer (`hit`: along the Earth's motion or within 20 degrees of it, the slowest
 * speed on a 0.1 km/s grid from 1 km/s below the Hohmann speed up whose forecast arrives; the Kepler
 * plan picks the candidates), with the speed TUTORIAL_SHORTFALL km/s short of it (`start`, rounded
 * to 0.1 km/s), so the first launch falls short of the target's orbit and the player raises the
 * speed until it arrives. `baseStep` as forecastLaunch's. @returns null when no launch on that grid arrives now.
 */
export function tutorialAim(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  mission: Mission,
  baseStep: number,
): { start: Aim; hit: Aim } | null {
  const mu = world.laws.gravitationalConstant * world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
  const distance = (body: number): number => {
    const s = heliocentricState(world, handles, body, state6);
    return Math.hypot(s[0]!, s[1]!, s[2]!);
  };
  const v = hohmannSpeed(distance(handles.bodies.Earth), distance(handles.bodies[mission.target]), mu);
  const guess = Math.round(Math.abs(v) * 10) / 10,
    base = v >= 0 ? 0 : 180;
  for (const turn of [0, 10, -10, 20, -20]) {
    const angle = wrap(base + turn);
    for (let k = -10; k <= 15; k++) {
      const speed = Math.round((guess + 0.1 * k) * 10) / 10;
      if (speed < 0 || speed > MAX_SPEED) continue;
      planFlight(world, handles, mission, { angle, speed }, quickPlan, QUICK);
      if (!(quickPlan.distance < mission.zone)) continue;
      if (forecastLaunch(world, handles, mission, { angle, speed }, baseStep, tutorialForecast).outcome === 'arrived')
        return { start: { angle, speed: Math.max(0, Math.round((speed - TUTORIAL_SHORTFALL) * 10) / 10) }, hit: { angle, speed } };
    }
  }
  return null;
}
const tutorialForecast = createForecast();
const state6 = new Float64Array(6);

/**
 * How far short of the target's orbit the starting aim of missions 2 on keeps the probe's path, as a
 * share of the orbit's semi-major axis, beyond the arrival ring and the orbit's nearest (farthest)
 * point from the Sun: a path this short meets the target at no launch date.
 */
export const START_SHORT = 0.05;

/**
 * The starting aim of missions 2 on, which the player has to change to arrive: along the Earth's
 * motion (outwards) or against it (inwards), at a speed at least `TUTORIAL_SHORTFALL` km/s under
 * the Hohmann transfer's (rounded down to 0.1 km/s), lowered 0.1 km/s at a time (to no less than
 * 0) until the forecast's path turns back `START_SHORT` of the orbit's size (and the ring) short of
 * the target's orbit at its nearest to the Earth's (its perihelion going out, its aphelion going
 * in; the orbit from the target's state now, two-body): it does not arrive, now or after any wait
 * (at the Hohmann speed it would at the launch window, so a wait to the window then Space would win three
 * stars with no aiming). `baseStep` as forecastLaunch's.
 */
export function startAim(world: PhysicsWorld, handles: SolarSystemHandles, mission: Mission, baseStep: number): Aim {
  const mu = world.laws.gravitationalConstant * world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
  const earth = heliocentricState(world, handles, handles.bodies.Earth, state6);
  const rE = Math.hypot(earth[0]!, earth[1]!, earth[2]!);
  const t = heliocentricState(world, handles, handles.bodies[mission.target], state6);
  const r = Math.hypot(t[0]!, t[1]!, t[2]!),
    v2 = t[3]! ** 2 + t[4]! ** 2 + t[5]! ** 2;
  // The target's orbit: semi-major axis (vis-viva) and eccentricity (from the angular momentum).
  const hx = t[1]! * t[5]! - t[2]! * t[4]!,
    hy = t[2]! * t[3]! - t[0]! * t[5]!,
    hz = t[0]! * t[4]! - t[1]! * t[3]!;
  const a = 1 / (2 / r - v2 / mu),
    e = Math.sqrt(Math.max(0, 1 - (hx * hx + hy * hy + hz * hz) / (mu * a)));
  const v = hohmannSpeed(rE, r, mu);
  const outward = v >= 0,
    angle = outward ? 0 : 180;
  let speed = Math.max(0, Math.floor((Math.abs(v) - TUTORIAL_SHORTFALL) * 10 + 1e-9) / 10);
  for (; speed > 0; speed = Math.max(0, Math.round((speed - 0.1) * 10) / 10)) {
    const f = forecastLaunch(world, handles, mission, { angle, speed }, baseStep, startForecast);
    const short = outward ? f.farthest < a * (1 - e - START_SHORT) - mission.zone : f.nearest > a * (1 + e + START_SHORT) + mission.zone;
    if (short && f.outcome !== 'arrived') break;
  }
  return { angle, speed };
}
const startForecast = createForecast();

/**
 * How much one press of a burn key in `direction` burns, km/s: the whole advised burn (`advice`'s
 * presses x BURN_STEP) when the hint shows it (`shown`: the hint is on and its advice is for the
 * course now) and the press is its direction, else one BURN_STEP. A hint of "Press ↑ 17 times now"
 * was out of date before 17 presses could be made (on Mercury the flight ended 13 days later), and
 * at 0.05 km/s a press a big correction took many; one press now makes the burn the hint worked out.
 */
export function burnPressSize(
  advice: Pick<BurnAdvice, 'kind' | 'direction' | 'presses'>,
  direction: BurnDirection,
  shown: boolean,
): number {
  return shown && advice.kind === 'burn' && advice.direction === direction && advice.presses > 0 ? advice.presses * BURN_STEP : BURN_STEP;
}
