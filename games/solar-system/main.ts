/**
 * Solar system: fly a probe from the Earth to the other planets, in the solar system of the book's
 * closing project (Ramtal and Dobre ch. 16). The Sun and the eight planets (Earth as the Earth-Moon
 * barycentre) attract each other; they start from astronomy-engine's positions and velocities at the
 * start date and are integrated with the world's scheme (default RK4, steps of at most 1 hour).
 *
 * The game (./missions.ts): each mission names a planet. The player turns the launch arrow at the
 * Earth and sets the launch speed while time waits; dots show at once where the probe will go. The
 * player reads the launch on the map until a flight of the mission fails: the dots run to
 * where the path meets the target's orbit, the target's own dots to where it is that day, each end
 * named with the day ("probe on day 259", "Mars on day 259"; ./orbit-crossing.ts), and the status
 * line says how far out (in) the path gets, or the day it is at the orbit and whether the planet is
 * there then (a hit, or how many days before or after the probe it gets there). After a failed try (or
 * with ?verdict=1) a ghost ring, the arrival zone's true edge, shows where the planet will be at
 * the closest approach ("Mars at arrival") with the probe's place then, inside the ring exactly
 * when it arrives, and the status line gives the same verdict (and the stars the speed earns); in
 * flight it gives the course's. That
 * forecast (./forecast.ts) is the flight itself, flown ahead with the world's scheme and the
 * flight's step, so what it says is what the launch does. Launch, and the probe flies in the physics
 * world, pulled by the Sun and every planet, while time speeds up; mid-course burns (the same keys
 * and buttons) change its course, from a small tank of fuel, and the forecast follows each burn.
 * Reaching the ring round the planet wins the mission, with stars for a cheap mission (the launch
 * speed plus the burns; 3 stars want a good moment) and a score (./missions.ts missionScore: cheap,
 * quick, and at the first launch) shown
 * on a result card with the best so far, every mission's stars and the next mission's brief.
 * Waiting lets the planets line up (./wait-pace.ts): a tap of Wait (W) runs time to the next launch
 * window (the Hohmann transfer's phase angle) and stops there; held, it runs time, slowing near a
 * window and standing at it a moment, so the player picks the day by watching the dots meet (a
 * phone's finger taps: at 10 days a tap a window took 170 taps). The Hint button (H) says
 * how to read the map before a failed try, then which way to change the launch and what to watch
 * (./advice.ts finds the change), or in flight which burn arrives and how many presses it takes.
 *
 * Drawn on a compressed distance scale (./distance-scale.ts), so the eight planets fit on one screen
 * with room between the inner four (D switches to the true scale); orbit lines are each planet's
 * Kepler ellipse now; every body keeps a dot and a name beside it. The comparison with the real
 * ephemeris (|r - r_ephemeris| / |r_ephemeris|, heliocentric) is in the side column, folded.
 *
 * Units: AU, days, solar masses (see packages/projects/src/solar-system.ts). One scene unit is 0.1 AU
 * of the display scale. Time: the rate is simulated days per real second; each loop tick runs steps
 * of the mission's step (./missions.ts missionTimeStep: the chosen step, longer for the outer
 * planets), at most MAX_STEPS_PER_TICK of them (a faster rate then runs slower than asked).
 * Keys: ← → turn the launch, ↑ ↓ its speed (in flight: burns in / out, faster / slower), Space
 * launch, W wait (tap: time runs to the next launch window; held: time runs, stopping a moment at each window), H hint, Enter next mission or try again, T try again, [ ] slower / faster, D distances,
 * 1 2 3 views, E sizes, P pause, N single step, R restart the mission (its first date and starting
 * launch; T keeps the last launch).
 * URL: ?mission=1..7, ?verdict=1 (the verdict from the start), ?rate=days-per-second while aiming (0..400, default 0),
 * ?step=hours (0.25|1|6|24), ?integrator=name,
 * ?date=ISO date, ?distances=compressed|true.
 */

import {
  choiceParam,
  createButtonBar,
  createDomResultCard,
  createPanel,
  type DomResultCardContent,
  flagParam,
  getSound,
  numberParam,
  pageLayout,
  type ResultCardButton,
  type ResultCardLine,
} from '@bitphysics/game-kit';
import { startThreeGame } from '@bitphysics/game-kit/three';
import {
  createPhysicsWorld,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  Rng,
  setTimeStep,
  slotOf,
  step,
} from '@bitphysics/physics';
import {
  SOLAR_SYSTEM_BODIES,
  SOLAR_SYSTEM_EPOCH,
  SOLAR_SYSTEM_FLOOR,
  SOLAR_SYSTEM_PLANETS,
  type SolarSystemBody,
  type SolarSystemHandles,
  solarSystem,
  solarSystemErrors,
} from '@bitphysics/projects';
import {
  AdditiveBlending,
  BufferGeometry,
  CanvasTexture,
  ConeGeometry,
  CylinderGeometry,
  Float32BufferAttribute,
  Group,
  Line,
  LineBasicMaterial,
  LineLoop,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Plane,
  PointLight,
  Points,
  PointsMaterial,
  Raycaster,
  SphereGeometry,
  Sprite,
  SpriteMaterial,
  SRGBColorSpace,
  Vector2,
  Vector3,
} from 'three';
import {
  adviseAim,
  adviseBurn,
  burnPressSize,
  createAimAdvice,
  createBurnAdvice,
  SPEED_STEP,
  startAim,
  TURN_STEP,
  tutorialAim,
} from './advice';
import { aimRings, skillStars } from './aim-depth';
import { displayRadius, toDisplay } from './distance-scale';
import { copyForecast, createForecast, ForecastJob } from './forecast';
import { keplerState } from './kepler';
import { forecastWords, meetingWords, staleWords } from './meeting-words';
import {
  type Aim,
  BURN_STEP,
  type BurnDirection,
  burnDirection,
  burnProbe,
  CORRECTION_FUEL,
  checkFlight,
  createFlightPlan,
  endFlight,
  type Flight,
  flightRate,
  heliocentricState,
  hohmannSpeed,
  launchDirection,
  launchProbe,
  MAX_KEPT_SCORE,
  MAX_SPEED,
  MISSIONS,
  type Mission,
  missionProgress,
  missionScore,
  missionTimeStep,
  planFlight,
  starsFor,
  TARGET_TRACK,
} from './missions';
import { meetingPoint, orbitCrossings, orbitRadiusToward, orbitReach, pathDay, targetLag } from './orbit-crossing';
import { type TagBox, tagPlace } from './tag-place';
import { createWaitState, NEAR_WINDOW_DAYS, nextLaunchWindow, releaseRunsOn, waitTick } from './wait-pace';

/** Scene units per display AU. */
const UNITS_PER_AU = 10;
const STEPS = ['0.25', '1', '6', '24'] as const;
/**
 * Most physics steps a loop tick runs (a flight's rate needs at most 24 of its steps, 72 while Wait
 * is held in flight, 128 at the top of the aiming wait's ramp for Venus's hour steps); a rate that
 * needs more runs slower than asked, the steps staying the forecast's.
 */
const MAX_STEPS_PER_TICK = 128;
/** Days per real second of a run to the launch window (the test hook). */
const RUN_RATE = 160;
/** A press of Wait (W or the button) shorter than this, ms, is a tap: time runs on to the next launch window. */
const WAIT_TAP_MS = 250;
/**
 * Real time forecasting may take a frame, ms (in slices of FORECAST_SLICE steps), or a third of the
 * time between frames where they come slowly (at most 40 ms): a longer forecast goes on over the
 * next frames, the line keeping the last verdict until it is done. A probe step takes about 1 us on
 * a desktop, 6 us while the planets' motion for it is worked out too.
 */
const FORECAST_MS_PER_FRAME = 6;
const FORECAST_SLICE = 500;
/** Real time between the last two frames, ms: where frames come slowly, forecasting takes up to a third of it. */
let frameGap = 16;
/** Mean radii, AU (IAU), for true-size drawing. */
const RADIUS_AU: Record<SolarSystemBody, number> = {
  Sun: 4.652e-3,
  Mercury: 1.631e-5,
  Venus: 4.045e-5,
  Earth: 4.259e-5,
  Mars: 2.266e-5,
  Jupiter: 4.673e-4,
  Saturn: 3.893e-4,
  Uranus: 1.695e-4,
  Neptune: 1.646e-4,
};
const COLOR: Record<SolarSystemBody, number> = {
  Sun: 0xffd27a,
  Mercury: 0xb5a89a,
  Venus: 0xe8cf94,
  Earth: 0x4f8fe8,
  Mars: 0xd0643c,
  Jupiter: 0xd9b38c,
  Saturn: 0xe6d19a,
  Uranus: 0x9fd8e0,
  Neptune: 0x5a78e0,
};
const hex = (c: number): string => `#${c.toString(16).padStart(6, '0')}`;

const search = new URLSearchParams(location.search);
/**
 * ?verdict=1 (tests, engineers): the forecast's verdict (the ring "at arrival", ✓ or ✗) from the
 * start; players see it only after a try that did not arrive (see `verdictShown`).
 */
const verdictFromStart = flagParam('verdict');
const params = {
  /**
   * Simulated days per real second while aiming (flights pick their own): none by default, so the
   * forecast is for the very moment of the launch; Wait runs time.
   */
  rate: numberParam('rate', { default: 0, min: 0, max: 400 }),
  step: choiceParam('step', STEPS, '1'),
  integrator: choiceParam('integrator', INTEGRATOR_NAMES, 'rk4') as IntegratorName,
  date: search.get('date') ?? SOLAR_SYSTEM_EPOCH.slice(0, 10),
  distances: choiceParam('distances', ['compressed', 'true'] as const, 'compressed'),
  exaggerate: search.has('exaggerate') ? flagParam('exaggerate') : true,
  mission: String(numberParam('mission', { default: 1, min: 1, max: MISSIONS.length, integer: true })),
  reset: () => restartMission(),
  inner: () => frameView('inner'),
  all: () => frameView('all'),
  /** Frames the mission's planets (key 3). */
  missionView: () => frameView('mission'),
};

// ---- World: the ephemeris at the start date; steps of at most the chosen size ----------------------

let handles: SolarSystemHandles;
/** The start of the world now, ms since 1970 UTC (a retry starts again from its launch's moment). */
let startMs = parseDate(params.date);
/** Days of simulated time owed to the next steps (the rate's fraction of a step carried over). */
let carry = 0;

/** Milliseconds since 1970 of an ISO date, or throws naming the field. */
function parseDate(text: string): number {
  const ms = Date.parse(/T/.test(text) ? text : `${text}T00:00:00Z`);
  if (!Number.isFinite(ms)) throw new RangeError(`start date: not a date: ${JSON.stringify(text)}`);
  return ms;
}

/** A fresh world from the ephemeris at startMs with the chosen scheme and step; any flight is over. */
function createWorld(): PhysicsWorld {
  // The player's reset (R) goes back to the mission's first day (`playerReset` then sets its launch).
  if (!ownReset && worldSerial > 0) startMs = missionStartMs;
  const options = { stepHours: Number(params.step), integrator: params.integrator, date: startMs };
  const world = createPhysicsWorld(solarSystem.worldOptions(options));
  handles = solarSystem.build(world, options);
  carry = 0;
  flight = null;
  phase = 'aim';
  trailCount = 0;
  worldSerial++;
  return world;
}

/** Real seconds a loop tick stands for (the loop runs at 60 Hz, whatever the world's step in days). */
const TICK = 1 / 60;

/**
 * How long a flight's time holds still after a burn, ms, and the share of its rate it runs at then
 * (none): the hint's "Press ↓ 4 times now" is worked out for burns all made now, and a player's
 * taps come a fraction of a second apart. With time running on, the later burns would do less than
 * the hint said and it would ask for more once the fuel was gone; held still, taps less than
 * BURN_SLOW_MS apart all act at the same moment of the flight, as the hint assumes.
 */
const BURN_SLOW_MS = 800;
const BURN_SLOW = 0;

/** The flying probe's distance from the mission's target, AU (Infinity with no flight). */
function targetDistance(): number {
  if (!flight) return Number.POSITIVE_INFINITY;
  const P = shell.world.components.Position;
  const t = slotOf(handles.bodies[flight.mission.target]),
    p = slotOf(flight.probe);
  return Math.hypot(P.x[t]! - P.x[p]!, P.y[t]! - P.y[p]!, P.z[t]! - P.z[p]!);
}

/**
 * Days per real second now: the aiming rate (./wait-pace.ts heldWaitRate while Wait is held or
 * a tap's run goes on: ramping up with the days waited, slow near a launch window, slower still
 * while the aim nearly arrives; none while it stands at a window), RUN_RATE while the test hook
 * runs to a window, a flight's rate (3 times it in the cruise far from the target, 3 times that while held,
 * at most 400; BURN_SLOW of it just after a burn), nothing after a flight ends.
 */
function currentRate(): number {
  if (phase === 'done') return 0;
  if (phase === 'flight') {
    // The cruise runs 3 times faster while the probe is far from the target (over 4 rings away and
    // the forecast's meeting over 40 days ahead), at the flight's own rate for the approach.
    let cruise = flightDaysPerSecond;
    if (flight && forecastKey !== '' && forecast.end - flight.elapsed > 40 && targetDistance() > 4 * flight.mission.zone)
      cruise = Math.min(400, 3 * flightDaysPerSecond);
    const rate = waiting ? Math.min(400, 3 * cruise) : cruise;
    return performance.now() - lastBurn < BURN_SLOW_MS ? BURN_SLOW * rate : rate;
  }
  if (wait.mode !== 'off') return wait.rate;
  if (!Number.isNaN(runTo)) return RUN_RATE;
  return params.rate;
}

/** The chosen step, days (the panel's "longest step"). */
const baseStep = (): number => Number(params.step) / 24;

/**
 * One loop tick: rate x TICK days in steps of the flight's step (./missions.ts missionTimeStep: the
 * forecast's, so the flight is what was forecast, and the planets' motion it worked out serves the
 * next forecast too), at most MAX_STEPS_PER_TICK; during a flight the probe is checked after every step.
 */
function stepWorld(world: PhysicsWorld): void {
  if (phase !== 'aim') {
    runTo = Number.NaN;
    wait.mode = 'off';
  }
  if (phase === 'flight') flightTicks++;
  if (waiting) heldTicks++;
  const dt = flight && phase === 'flight' ? flight.dt : missionTimeStep(mission(), baseStep());
  if (wait.mode === 'off') carry += currentRate() * TICK;
  else {
    // Wait while aiming (./wait-pace.ts waitTick): held, it slows near a launch window and stands
    // at it a moment; a tap's run stops there.
    const w = launchWindow();
    windowNearness = wait.mode === 'run' ? w.next : Math.min(w.next, w.period - w.next);
    // How near the launch as aimed comes to the target now, in rings: near, the held Wait slows (a
    // tap's run and a Wait standing at a window do not read it).
    if (wait.mode === 'held' && wait.pause === 0)
      aimMiss = planFlight(world, handles, mission(), aim, waitPlan, WAIT_PLAN_SAMPLES).distance / mission().zone;
    const days = waitTick(wait, TICK, world.time, w, params.rate, aimMiss);
    carry += days;
    if (wait.stopped) {
      atWindow = world.time + days;
      sound.chime(988, 0.15);
    }
  }
  if (phase === 'aim' && !Number.isNaN(runTo)) {
    carry = Math.min(carry, Math.max(0, runTo - world.time));
    // Within a step of the end: stop here (a whole step more would pass it).
    if (runTo - world.time < dt * (1 - 1e-9)) {
      runTo = Number.NaN;
      carry = 0;
      if (runToWindow) {
        atWindow = world.time;
        sound.chime(988, 0.15);
      }
      return;
    }
  }
  let n = Math.floor(carry / dt + 1e-9);
  if (n > MAX_STEPS_PER_TICK) {
    n = MAX_STEPS_PER_TICK;
    carry = n * dt;
  }
  if (n === 0) return;
  carry = Math.max(0, carry - n * dt);
  if (world.dt !== dt) setTimeStep(world, dt);
  for (let i = 0; i < n; i++) {
    step(world);
    if (flight && phase === 'flight') {
      if (i % 2 === 0 || i === n - 1) recordTrail(world);
      if (checkFlight(world, handles, flight) !== 'flying') {
        endOfFlight();
        carry = 0;
        break;
      }
    }
  }
}

// ---- Missions --------------------------------------------------------------------------------------

type Phase = 'aim' | 'flight' | 'done';
let phase: Phase = 'aim';
let missionIndex = Number(params.mission) - 1;
const aim: Aim = { angle: 0, speed: 3 };
/** The Kepler plan a launch takes its deadline from (./missions.ts launchProbe). */
const plan = createFlightPlan();
/**
 * The forecast shown (./forecast.ts): what the launch aimed now will do, or what the flight under
 * way will do; complete. `forecastKey` names what it is for ('' for nothing yet): see `wantedKey`.
 */
const forecast = createForecast();
let forecastKey = '';
/** The forecast being worked out, a slice a frame, and what it is for. */
const job = new ForecastJob();
let jobKey = '';
/** Counts the worlds made (a reset makes a new one): part of a forecast's key. */
let worldSerial = 0;
let flight: Flight | null = null;
/** Launches on this mission since it started (the score's tries part, ./missions.ts missionScore). */
let launches = 0;
/** The aim's centredness at the last launch (./aim-depth.ts aimRings; 0 on the first mission): three stars want it. */
let launchRings = 0;
/** `aimDepth`'s last answer and the aim and moment it was for. */
let depthKey = '',
  depthRings = 0;
/**
 * How centred the aim is now (./aim-depth.ts aimRings, two-body, cheap), 0 on the first mission
 * (its stars are the speed's alone); worked out once per aim and moment.
 */
function aimDepth(): number {
  if (missionIndex === 0) return 0;
  const key = `${missionIndex} ${shell.world.time} ${aim.angle} ${aim.speed}`;
  if (key !== depthKey) {
    depthRings = aimRings(shell.world, handles, mission(), aim);
    depthKey = key;
  }
  return depthRings;
}
/** Flights on this mission since it started that did not arrive: after one the aim shows the verdict. */
let failedTries = 0;
/**
 * Whether the aim shows the forecast's verdict: the ring where the target will be at the closest
 * approach, the probe's place then, ✓ or ✗ and the hint's presses. Before a mission's first failed
 * try the player reads the map instead (the probe's path to the target's orbit and the day it gets
 * there, the target's own path to that day, and the line’s verdict, `meetingVerdict`):
 * judging the launch on the map is the game, and the ring a check for every press of ↑ made it a
 * search for the ✓.
 */
const verdictShown = (): boolean => verdictFromStart || failedTries > 0;
/** Most points of the probe's trail. */
const TRAIL_POINTS = 4096;
/** The probe's flown path, heliocentric AU (x, y, z each), trailCount points. */
const trail = new Float64Array(3 * TRAIL_POINTS);
let trailCount = 0;
/** The target's heliocentric state at the last launch (AU, AU/day): its orbit, as the map drew it and the forecast read it. */
const launchTarget = new Float64Array(6);
/** The date of the last launch, ms (Try again starts there). */
let launchMs = 0;
/** The rate of the flight under way, days/s (./missions.ts flightRate of its deadline). */
let flightDaysPerSecond = 30;
/** Whether Wait (W or the button) is held. */
let waiting = false;
/** Wait while aiming: held, a tap's run to the next launch window, or off (./wait-pace.ts waitTick). */
const wait = createWaitState();
/** Whether the press of Wait under way stopped a tap's run (its release then starts nothing). */
let stopPress = false;
/** Loop ticks run since Wait was last pressed: under WAIT_TAP_TICKS of them the press is a tap too. */
let heldTicks = 0;
/**
 * A press of Wait that ran fewer loop ticks than this (a quarter second of game time) is a tap,
 * however long it took by the clock (a loaded machine or a paused game runs few ticks).
 */
const WAIT_TAP_TICKS = 15;
/** World time, days, the test hook's run to the window runs time to and stops at; NaN for none. */
let runTo = Number.NaN;
/** Whether runTo is a launch window (the hook's run): the date line then names it. */
let runToWindow = false;
/** Days from now to the nearest launch window, worked out each tick while Wait runs (Infinity otherwise). */
let windowNearness = Number.POSITIVE_INFINITY;
/** The launch as aimed misses the target by, arrival rings (the quick Kepler plan), worked out each tick while Wait runs. */
let aimMiss = Number.POSITIVE_INFINITY;
/** The plan `aimMiss` is read from, and its samples (a quick look each tick: about 1 ms). */
const waitPlan = createFlightPlan();
const WAIT_PLAN_SAMPLES = 100;
/** World time, days, a run last stopped at a launch window (NaN for none): the date line says so. */
let atWindow = Number.NaN;
/**
 * World time, days, the player last stopped Wait short of a window (NaN for none): the date line
 * then says how far the next window is, not only "time waits" (a stop there read as a window).
 */
let waitStoppedAt = Number.NaN;
/** performance.now() Wait was last pressed (a short press is a tap: a run to the next window). */
let waitPressedAt = -Infinity;

/**
 * Presses Wait (W or the button): while aiming, time runs while it is held; a press while a tap's
 * run goes on stops the run there.
 */
function pressWait(): void {
  if (waiting) return;
  waiting = true;
  waitPressedAt = performance.now();
  heldTicks = 0;
  stopPress = phase === 'aim' && wait.mode === 'run';
  if (stopPress) stopWait(true);
  else if (phase === 'aim') Object.assign(wait, { mode: 'held', waited: 0, pause: 0, rate: 0 });
}
/**
 * Lets Wait go: after a tap (shorter than WAIT_TAP_MS or WAIT_TAP_TICKS) while aiming, time runs
 * on to the next launch window and stops there (unless the tap itself stopped at one); after a hold
 * it stops.
 */
function releaseWait(): void {
  if (!waiting) return;
  waiting = false;
  if (stopPress || wait.mode !== 'held') return;
  const tap = performance.now() - waitPressedAt < WAIT_TAP_MS || heldTicks < WAIT_TAP_TICKS;
  if ((tap && wait.pause === 0) || releaseRunsOn(wait, windowNearness, aimMiss)) wait.mode = 'run';
  else stopWait(true);
}
/**
 * Stops Wait's time (a hold's or a tap's run); `player` when the player stopped it (let go, or
 * tapped Stop): the date line then says how far the window is (`waitStoppedAt`).
 */
function stopWait(player = false): void {
  if (player && wait.mode !== 'off') waitStoppedAt = shell.world.time;
  wait.mode = 'off';
  wait.pause = 0;
  windowNearness = Number.POSITIVE_INFINITY;
  aimMiss = Number.POSITIVE_INFINITY;
}
/**
 * Runs time (RUN_RATE) to the next launch window of the mission's target and stops there (a window
 * less than 2 days off counts as now: the next one). For tests and the console: the player's Wait
 * (a tap) runs there at its own pace (./wait-pace.ts). No effect unless aiming.
 */
function waitForWindow(): void {
  if (phase !== 'aim') return;
  stopWait();
  const w = launchWindow();
  runTo = shell.world.time + (w.next < 2 ? w.next + w.period : w.next);
  runToWindow = true;
}

const windowNow = { next: 0, period: 0 };
/** The next launch window for the mission's target now (./wait-pace.ts launchWindow); a shared object. */
function launchWindow(): { next: number; period: number } {
  const world = shell.world;
  const mu = world.laws.gravitationalConstant * world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
  heliocentricState(world, handles, handles.bodies.Earth, earthHelio);
  heliocentricState(world, handles, handles.bodies[mission().target], state6);
  return nextLaunchWindow(earthHelio, state6, mu, windowNow);
}
/** The date a mission began, ms (the panel's restart goes back there). */
let missionStartMs = startMs;
/** The missions' stars, scores and last mission, kept in local storage (./missions.ts missionProgress). */
const progress = missionProgress();
/** Best stars of each mission (0: not flown). */
const best: number[] = progress.stars.read();
/** Best score of each mission (0: not won; ./missions.ts missionScore). */
const bestScore: number[] = progress.scores.read();

/**
 * The mission (0-based) a page opened without ?mission= resumes at: the last one started (kept in
 * local storage), or, once that one has stars, the next not yet flown after it (round from the
 * first); the last one started when every mission has stars; the first with no storage.
 */
function resumeMission(): number {
  const last = progress.last.read();
  if (best[last] === 0) return last;
  for (let k = 1; k < MISSIONS.length; k++) {
    const i = (last + k) % MISSIONS.length;
    if (best[i] === 0) return i;
  }
  return last;
}

/** Keeps the best stars and scores (a score past MAX_KEPT_SCORE would read back as 0: the scores are then not kept). */
function saveBest(): void {
  progress.stars.write(best);
  if (bestScore.every((s) => s <= MAX_KEPT_SCORE)) progress.scores.write(bestScore);
}

const mission = (): Mission => MISSIONS[missionIndex]!;

/** The heliocentric distance of `body` now, AU. */
function distanceFromSun(body: SolarSystemBody): number {
  heliocentricState(shell.world, handles, handles.bodies[body], state6);
  return Math.hypot(state6[0]!, state6[1]!, state6[2]!);
}
const state6 = new Float64Array(6);

/**
 * Starts mission `index` (0-based) where the world is: the launch arrow along the Earth's motion
 * (outwards) or against it (inwards), the speed short of an arriving course (mission 1 a little
 * short, ./advice.ts tutorialAim; the others short of the target's orbit, startAim), the view
 * framing its planets.
 */
function startMission(index: number): void {
  hideCard();
  if (flight) endFlight(shell.world, flight);
  flight = null;
  missionIndex = Math.max(0, Math.min(MISSIONS.length - 1, index));
  params.mission = String(missionIndex + 1);
  progress.last.write(missionIndex);
  phase = 'aim';
  // A tapped Wait's run ends with the mission it ran in: left set, a restart (R) ran on from day 0.
  runTo = Number.NaN;
  stopWait();
  wait.lastStop = Number.NaN;
  runToWindow = false;
  // A mission that begins at a launch window (Mercury's first, 0.3 days on) says so on the date line.
  const starting = launchWindow();
  atWindow = starting.next < 1 ? shell.world.time + starting.next : Number.NaN;
  trailCount = 0;
  launches = 0;
  failedTries = 0;
  const m = mission();
  const mu = shell.world.laws.gravitationalConstant * shell.world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
  const v = hohmannSpeed(distanceFromSun('Earth'), distanceFromSun(m.target), mu);
  aim.angle = v >= 0 ? 0 : 180;
  aim.speed = Math.min(MAX_SPEED, Math.round(Math.abs(v) * 10) / 10);
  // Missions 2 on start short of the target's orbit (./advice.ts startAim): the player has to aim
  // (at the Hohmann speed, a wait to the launch window and Space won three stars).
  if (missionIndex > 0) Object.assign(aim, startAim(shell.world, handles, m, baseStep()));
  // The first mission is a lesson in one change: the arrow points the way of an arriving course,
  // with the speed a little short of it (./advice.ts tutorialAim); the line shows it falling short
  // of Mars (the Hint button says how much to speed up).
  if (missionIndex === 0) {
    const lesson = tutorialAim(shell.world, handles, m, baseStep());
    if (lesson) Object.assign(aim, lesson.start);
  }
  missionStartMs = handles.epoch + shell.world.time * 86_400_000;
  frameView('mission');
  panel.refresh();
  updateStatus(true);
}

/** Restarts the current mission at the date it began (the panel's button): a fresh world from the ephemeris there. */
function restartMission(): void {
  startMs = missionStartMs;
  resetWorld();
  startMission(missionIndex);
}

/** Whether the page itself is replacing the world now (`resetWorld`); else a reset is the R key's or the toolbar's ↺. */
let ownReset = false;
/** A new world from startMs (a retry, a restart, a new date), not read as the player's reset. */
function resetWorld(): void {
  ownReset = true;
  try {
    shell.reset();
  } finally {
    ownReset = false;
  }
}

/**
 * R (or the toolbar's ↺): the mission from its start, its first day and its starting launch, as a
 * player expects of a reset (it went back to the last launch's moment with the last speed kept,
 * which Try again (T) does). The tries made so far still count: the verdict stays shown after a
 * failed one, and the score's first-try part is not earned again.
 */
function playerReset(): void {
  const tries = { launches, failedTries };
  startMission(missionIndex);
  ({ launches, failedTries } = tries);
  updateStatus(true);
}

/**
 * What the forecast shown should be for now: the launch aimed at this moment of this world, or the
 * flight under way after its burns so far ('' after a flight). The moment comes last, after a '|'.
 */
function wantedKey(): string {
  if (phase === 'aim')
    return `aim ${worldSerial} ${missionIndex} ${aim.angle} ${aim.speed} ${params.step} ${params.integrator}|${shell.world.time}`;
  if (phase === 'flight' && flight) return `flight ${worldSerial} ${flight.launchTime} ${flight.burns}|`;
  return '';
}
const keyBase = (key: string): string => key.slice(0, key.indexOf('|'));

/** Starts the job on the forecast `key` names (wantedKey now). */
function startForecast(key: string): void {
  if (phase === 'aim') job.startLaunch(shell.world, handles, mission(), aim, baseStep());
  else if (flight) job.startCourse(shell.world, handles, flight);
  jobKey = key;
}

/**
 * Brings the forecast shown up to date: FORECAST_MS_PER_FRAME of the job a call, or all of it
 * (`now`). While time runs (Wait held) a forecast under way for a moment just gone is
 * finished and shown before the next is started, so the line keeps up. @returns whether the
 * forecast shown is for now.
 */
function updateForecast(now = false): boolean {
  const key = wantedKey();
  if (key === '' || key === forecastKey) return key !== '';
  const keep = job.busy && !now && keyBase(jobKey) === keyBase(key);
  if (!keep && (jobKey !== key || !job.busy)) startForecast(key);
  const start = performance.now();
  let over = now ? job.run() : job.run(FORECAST_SLICE);
  const budget = Math.min(40, Math.max(FORECAST_MS_PER_FRAME, frameGap / 3));
  while (!over && performance.now() - start < budget) over = job.run(FORECAST_SLICE);
  if (!over) return false;
  if (job.lost) {
    jobKey = '';
    return false;
  }
  const arrivedBefore = forecastKey.startsWith('flight') && forecast.outcome === 'arrived';
  copyForecast(job.forecast, forecast);
  forecastKey = jobKey;
  jobKey = '';
  // A burn that brings the course into the ring chimes.
  if (phase === 'flight' && forecast.outcome === 'arrived' && !arrivedBefore) sound.chime(1320, 0.12);
  updateStatus(true);
  return forecastKey === key;
}

/**
 * A player's launch (Space, the Launch button): it also ends a pause, since a player who asks for
 * the launch wants to see it fly (paused, the probe sat at day 0 with only "paused" in the status
 * line to say why). The test hook `launch` keeps the pause.
 */
function playerLaunch(): void {
  if (phase === 'aim' && shell.paused) shell.paused = false;
  launch();
}

/** Launches the probe with the current aim (Space, the Launch button). No effect unless aiming. */
function launch(): void {
  if (phase !== 'aim') return;
  // The forecast shown is for this very moment and aim (worked out now if it was not yet).
  updateForecast(true);
  launchRings = aimDepth();
  planFlight(shell.world, handles, mission(), aim, plan);
  launchMs = handles.epoch + shell.world.time * 86_400_000;
  flight = launchProbe(shell.world, handles, mission(), aim, plan, baseStep());
  heliocentricState(shell.world, handles, handles.bodies[mission().target], launchTarget);
  flightDaysPerSecond = flightRate(flight.deadline);
  phase = 'flight';
  flightTicks = 0;
  launches++;
  // The launch's forecast is the flight's course from the launch.
  forecastKey = wantedKey();
  trailCount = 0;
  recordTrail(shell.world);
  sound.launch(0.9);
  updateStatus(true);
}
/**
 * The brief's line after a flight: what to do next (the way on, or the miss's fix), short. The header
 * keeps its fixed height (STATUS_ROW); with no line there, a phone showed a blank band.
 */
let doneNote = '';
/** After the probe arrived, fell into the Sun or missed: stars, sound, the result and its buttons. */
function endOfFlight(): void {
  if (!flight) return;
  phase = 'done';
  if (flight.state === 'arrived') {
    arrivalAt = performance.now();
    const spent = flight.aim.speed + flight.fuelUsed;
    const stars = skillStars(missionIndex, flight.mission, spent, launchRings, flight.burns);
    const score = missionScore(flight.mission, Math.max(spent, 1e-3), Math.max(flight.elapsed, 1e-3), Math.max(1, launches));
    const record = score.total > bestScore[missionIndex]!;
    const before = bestScore[missionIndex]!;
    best[missionIndex] = Math.max(best[missionIndex]!, stars);
    bestScore[missionIndex] = Math.max(before, score.total);
    saveBest();
    lastResult = { stars, score, record, before };
    sound.chime(784, 0.4);
    setTimeout(() => sound.chime(1175, 0.7), 160);
  } else if (flight.state === 'sun') {
    sound.explosion(0.4);
  } else {
    sound.chime(196, 0.6);
  }
  lastResult = flight.state === 'arrived' ? lastResult : null;
  const next = MISSIONS[(missionIndex + 1) % MISSIONS.length]!;
  doneNote =
    flight.state === 'arrived'
      ? `${named('Enter', 'Next mission')}: ${next.target} · ${named('T: try again', 'Try again')} to score more`
      : missAdvice(flight, true);
  showCard(flight);
  updateStatus(true);
}

/**
 * Loop ticks a flight has run (counted in `stepWorld`), and how many of them the Abort button waits
 * before it acts (0.8 s at 60 ticks a second): Abort takes Launch's place in the bar, so a double tap
 * on Launch (the second tap ~0.3 s later) landed on Abort and ended the flight it had just begun.
 * Counted in ticks, not ms, so a paused flight keeps it and tests drive it with steps.
 */
let flightTicks = 0;
const ABORT_GUARD_TICKS = 48;
/** The Abort button: `retry`, once the flight has run ABORT_GUARD_TICKS ticks. */
function abortTap(): void {
  if (phase === 'flight' && flightTicks < ABORT_GUARD_TICKS) return;
  retry();
}

/** Try again: back to the moment of the last launch, same aim. */
function retry(): void {
  if (phase === 'aim') return;
  // A miss, a fall or an abort: from now on the aim shows the verdict (the hint after a failed try).
  if (flight?.state !== 'arrived') failedTries++;
  hideCard();
  const keep = { ...aim };
  startMs = launchMs;
  resetWorld();
  Object.assign(aim, keep);
  updateStatus(true);
}

/** Enter or the result's main button: the next mission after an arrival, else try again. */
function advance(): void {
  if (phase !== 'done' || !flight) return;
  if (flight.state === 'arrived') {
    endFlight(shell.world, flight);
    startMission(missionIndex + 1 < MISSIONS.length ? missionIndex + 1 : 0);
  } else retry();
}

/** The course's closest approach (AU) and forecast key before the last run of burns (`burn`). */
let closestBeforeBurn = Number.NaN,
  keyBeforeBurn = '';
/**
 * For a while after a burn (GHOST_MS) once the course after it is forecast, the closest approach
 * before it (AU), which the line shows going to the new one ("closest 0.53 → 0.52 AU"); else NaN.
 * A burn of 0.05 km/s moves the dots little.
 */
function burnChange(): number {
  if (!(performance.now() - lastBurnDone < GHOST_MS) || forecastKey === keyBeforeBurn) return Number.NaN;
  return closestBeforeBurn;
}

/** Least real time between two burns, ms; performance.now() of the last. */
const BURN_GAP_MS = 200;
let lastBurn = -Infinity;
/** performance.now() of the last burn that used fuel. */
let lastBurnDone = -Infinity;

/**
 * A mid-course burn of BURN_STEP km/s (./missions.ts burnProbe) while the probe flies, or the whole
 * burn the hint advises in one press of its key (./advice.ts burnPressSize): the new course is
 * forecast at once (its verdict shows in the status line and the dotted path).
 */
function burn(direction: BurnDirection): void {
  if (phase !== 'flight' || !flight) return;
  // At most one burn each BURN_GAP_MS (a key's own repeat would empty the tank in a second).
  const t = performance.now();
  if (t - lastBurn < BURN_GAP_MS) return;
  lastBurn = t;
  // The course before the burn stays drawn, dim, for a while (the first of a run of presses keeps it).
  if (t - lastBurnDone > GHOST_MS) {
    keepBurnGhost();
    closestBeforeBurn = forecastKey.startsWith('flight') ? forecast.closest : Number.NaN;
    keyBeforeBurn = forecastKey;
  }
  heliocentricState(shell.world, handles, flight.probe, state6);
  burnDirection(state6, direction, burnPush);
  const size = burnPressSize(burnAdvice, direction, hinting && adviceKey === forecastKey);
  if (burnProbe(shell.world, handles, flight, direction, size, plan) > 0) {
    flightDaysPerSecond = flightRate(flight.deadline);
    lastBurnDone = t;
    // A burn is heard: a short whoosh and the chime.
    sound.launch(0.3);
    sound.chime(660, 0.08);
  } else sound.chime(180, 0.1);
  updateStatus(true);
}

function turn(degrees: number): void {
  if (phase === 'flight') {
    burn(degrees < 0 ? 'in' : 'out');
    return;
  }
  if (phase !== 'aim') return;
  let a = aim.angle + degrees;
  a = ((((a + 180) % 360) + 360) % 360) - 180;
  aim.angle = a === -180 ? 180 : Math.round(a * 10) / 10;
  aimChangedAt = performance.now();
  // The line reads the new aim at once, not at the next frame (key presses between frames showed late).
  updateStatus();
}

function changeSpeed(kms: number): void {
  if (phase === 'flight') {
    burn(kms > 0 ? 'faster' : 'slower');
    return;
  }
  if (phase !== 'aim') return;
  aim.speed = Math.min(MAX_SPEED, Math.max(0, Math.round((aim.speed + kms) * 10) / 10));
  aimChangedAt = performance.now();
  updateStatus();
}

// ---- The page ---------------------------------------------------------------------------------------

const game = await startThreeGame({
  title: 'Solar system',
  createWorld,
  step: stepWorld,
  // The few controls a mission needs; the rest (time rate, views, distances, sizes, Enter, the
  // camera) are named with their keys in the settings panel, whose note lists them (all 16 lines
  // here would be more than a new player can take in). On a phone the lines naming on-screen buttons stay
  // in the menu's legend, out of the card over the diagram (the kit leaves out gestures ending in "button(s)").
  controls: [
    { keys: '← →', action: 'turn the launch arrow; in flight, burn in / out', touch: 'bottom ↺ ↻ buttons', card: false },
    { keys: '↑ ↓', action: 'launch speed; in flight, burn faster / slower', touch: '− + buttons', card: false },
    { keys: 'Space', action: 'launch the probe', touch: 'Launch button', card: false },
    {
      keys: 'W',
      action: 'wait: tap to run to the next launch window; hold to run time (it stops at each window)',
      touch: 'Wait button',
      card: false,
    },
    { keys: 'H', action: 'hint: what to try', touch: 'Hint button', card: false },
    { keys: 'Click', action: 'aim the launch at a point', touch: 'Tap' },
    { keys: 'R', action: 'restart the mission: its first day and launch (T tries the last launch again)', card: false },
  ],
  keys: [
    { key: 'ArrowLeft', label: 'turn left', action: () => turn(-TURN_STEP), repeat: true },
    { key: 'ArrowRight', label: 'turn right', action: () => turn(TURN_STEP), repeat: true },
    { key: 'ArrowUp', label: 'faster launch', action: () => changeSpeed(SPEED_STEP), repeat: true },
    { key: 'ArrowDown', label: 'slower launch', action: () => changeSpeed(-SPEED_STEP), repeat: true },
    { key: ' ', label: 'launch', action: () => playerLaunch() },
    { key: 'Enter', label: 'next / try again', action: () => advance() },
    { key: 'h', label: 'hint', action: () => toggleHint() },
    { key: 't', label: 'try again', action: () => retry() },
    { key: '[', label: 'slower', action: () => setRate(params.rate / 1.5), repeat: true },
    { key: ']', label: 'faster', action: () => setRate(params.rate === 0 ? 1 : params.rate * 1.5), repeat: true },
    { key: 'd', label: 'distances', action: () => setDistances(params.distances === 'true' ? 'compressed' : 'true') },
    { key: '1', label: 'inner', action: () => frameView('inner') },
    { key: '2', label: 'all', action: () => frameView('all') },
    { key: '3', label: 'mission', action: () => frameView('mission') },
    {
      key: 'e',
      label: 'sizes',
      action: () => {
        params.exaggerate = !params.exaggerate;
        panel.refresh();
      },
    },
  ],
  app: {
    background: 0x020308,
    shadows: false,
    controls: { minDistance: 0.5, maxDistance: 1500, leftButton: 'none' },
    cameraPosition: [0, 60, 90],
  },
  renderer: { unitsPerMeter: UNITS_PER_AU, boundary: 'none', shadows: false, lights: false },
  view: null,
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;
// The bodies are drawn here, on the display scale; the world renderer's own meshes stay hidden.
renderer.root.visible = false;
// The loop ticks at 60 Hz of real time; the world's dt is the physical step in days.
shell.loop.setTimeStep(TICK);
shell.onWorldChange(() => shell.loop.setTimeStep(TICK));
app.scene.add(new PointLight(0xfff2d0, 3, 0, 0));
app.camera.far = 5000;
app.camera.updateProjectionMatrix();
const sound = getSound();

// W held: wait (time runs faster).
window.addEventListener('keydown', (e) => {
  if ((e.key === 'w' || e.key === 'W') && !e.ctrlKey && !e.metaKey && !e.repeat) pressWait();
});
window.addEventListener('keyup', (e) => {
  if (e.key === 'w' || e.key === 'W') releaseWait();
});
window.addEventListener('blur', () => {
  if (waiting && wait.mode === 'held') stopWait();
  waiting = false;
});

/**
 * The sky: STAR_COUNT stars on a sphere of STAR_SKY_RADIUS scene units (beyond the farthest the
 * camera goes, inside its far plane), a third of them crowded towards a tilted band like the Milky
 * Way, white to pale blue and gold, drawn a pixel or two wide whatever the zoom. Fixed (seeded).
 */
const STAR_COUNT = 3000,
  STAR_SKY_RADIUS = 3000;
{
  const rng = new Rng(2012);
  const pos = new Float32Array(3 * STAR_COUNT),
    col = new Float32Array(3 * STAR_COUNT);
  const tilt = 1.05;
  for (let i = 0; i < STAR_COUNT; i++) {
    let x = rng.normal(),
      y = rng.normal(),
      z = rng.normal();
    if (i % 3 === 0) y *= 0.08; // the band: squashed towards the plane y = 0, then tilted
    const n = Math.hypot(x, y, z) || 1;
    x /= n;
    y /= n;
    z /= n;
    const ty = y * Math.cos(tilt) - z * Math.sin(tilt),
      tz = y * Math.sin(tilt) + z * Math.cos(tilt);
    pos.set([x * STAR_SKY_RADIUS, ty * STAR_SKY_RADIUS, tz * STAR_SKY_RADIUS], 3 * i);
    const b = 0.35 + 0.65 * rng.next() ** 3,
      hue = rng.next();
    col.set(hue < 0.2 ? [b, b * 0.9, b * 0.7] : hue < 0.4 ? [b * 0.8, b * 0.9, b] : [b, b, b], 3 * i);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(pos, 3));
  geometry.setAttribute('color', new Float32BufferAttribute(col, 3));
  app.scene.add(new Points(geometry, new PointsMaterial({ size: 1.6, sizeAttenuation: false, vertexColors: true, depthWrite: false })));
}

/** A soft radial glow texture (white core to clear rim), for the Sun and the arrival flash. */
function glowTexture(inner: string, mid: string, outer: string): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = c.height = 128;
  const g = c.getContext('2d')!;
  const grad = g.createRadialGradient(64, 64, 0, 64, 64, 64);
  grad.addColorStop(0, inner);
  grad.addColorStop(0.25, mid);
  grad.addColorStop(1, outer);
  g.fillStyle = grad;
  g.fillRect(0, 0, 128, 128);
  return new CanvasTexture(c);
}
const sunGlow = new Sprite(
  new SpriteMaterial({
    map: glowTexture('rgba(255, 244, 214, 0.9)', 'rgba(255, 200, 110, 0.35)', 'rgba(255, 150, 60, 0)'),
    blending: AdditiveBlending,
    depthWrite: false,
    transparent: true,
  }),
);
app.scene.add(sunGlow);
/** The arrival flash: a glow that swells and fades at the target for ARRIVAL_FLASH_MS. */
const arrivalGlow = new Sprite(
  new SpriteMaterial({
    map: glowTexture('rgba(255, 255, 240, 1)', 'rgba(160, 255, 180, 0.5)', 'rgba(80, 255, 140, 0)'),
    blending: AdditiveBlending,
    depthWrite: false,
    transparent: true,
  }),
);
arrivalGlow.visible = false;
app.scene.add(arrivalGlow);
const ARRIVAL_FLASH_MS = 1400;
let arrivalAt = -Infinity;

// ---- Bodies on the display scale ---------------------------------------------------------------------

/** Colour `c` (0xrrggbb) half way to white, each channel, as a CSS colour. */
function towardWhite(c: number): string {
  const mid = (shift: number): number => Math.round((((c >> shift) & 0xff) + 255) / 2);
  return `rgb(${mid(16)}, ${mid(8)}, ${mid(0)})`;
}

/** A colour `c` with each channel scaled by `k` (clamped), as a CSS colour. */
function shade(c: number, k: number): string {
  const ch = (shift: number) => Math.max(0, Math.min(255, Math.round(((c >> shift) & 255) * k)));
  return `rgb(${ch(16)}, ${ch(8)}, ${ch(0)})`;
}

/**
 * A body's surface, drawn on a 256 x 128 canvas wrapped round its sphere (seeded, so the same every
 * load): the giants in bands of their colour (Jupiter with its Great Red Spot), the Earth oceans
 * with land, cloud and ice caps, Mars rust with dark lowlands and a polar cap, Mercury grey and
 * cratered, Venus veiled in pale cloud, the Sun mottled with a brighter core colour.
 */
function surfaceTexture(name: SolarSystemBody): CanvasTexture {
  const W = 256,
    H = 128;
  const c = document.createElement('canvas');
  c.width = W;
  c.height = H;
  const g = c.getContext('2d')!;
  const rng = new Rng(SOLAR_SYSTEM_BODIES.indexOf(name) + 17);
  const base = COLOR[name];
  g.fillStyle = hex(base);
  g.fillRect(0, 0, W, H);
  const blobs = (n: number, colour: () => string, size: [number, number], squash = 1) => {
    for (let i = 0; i < n; i++) {
      g.fillStyle = colour();
      g.beginPath();
      const r = size[0] + (size[1] - size[0]) * rng.next();
      g.ellipse(rng.next() * W, H * (0.1 + 0.8 * rng.next()), r, r * squash, 0, 0, 2 * Math.PI);
      g.fill();
    }
  };
  if (name === 'Jupiter' || name === 'Saturn' || name === 'Uranus' || name === 'Neptune') {
    // Bands: stripes of lighter and darker tones, many and strong on Jupiter, faint on the ice giants.
    const bands = name === 'Jupiter' ? 14 : name === 'Saturn' ? 10 : 6;
    const depth = name === 'Jupiter' ? 0.5 : name === 'Saturn' ? 0.3 : 0.12;
    let y = 0;
    while (y < H) {
      const h = (H / bands) * (0.5 + rng.next());
      g.fillStyle = shade(base, 1 + depth * (2 * rng.next() - 1));
      g.fillRect(0, y, W, h + 1);
      y += h;
    }
    if (name === 'Jupiter') {
      g.fillStyle = shade(0xc0603a, 1);
      g.beginPath();
      g.ellipse(W * 0.3, H * 0.64, 14, 6, 0, 0, 2 * Math.PI);
      g.fill();
    }
  } else if (name === 'Earth') {
    blobs(14, () => (rng.next() < 0.6 ? '#3f8f4a' : '#9a8a55'), [8, 24], 0.7);
    blobs(22, () => 'rgba(255, 255, 255, 0.55)', [4, 14], 0.35);
    g.fillStyle = '#f4f8ff';
    g.fillRect(0, 0, W, 9);
    g.fillRect(0, H - 10, W, 10);
  } else if (name === 'Mars') {
    blobs(16, () => shade(base, 0.6 + 0.2 * rng.next()), [6, 20], 0.6);
    g.fillStyle = '#f6efe8';
    g.fillRect(0, 0, W, 7);
  } else if (name === 'Mercury') {
    blobs(60, () => shade(base, 0.7 + 0.5 * rng.next()), [1.5, 7]);
  } else if (name === 'Venus') {
    blobs(30, () => shade(base, 0.9 + 0.2 * rng.next()), [10, 30], 0.3);
  } else {
    blobs(80, () => shade(0xffeab0, 0.95 + 0.1 * rng.next()), [2, 6]);
  }
  const t = new CanvasTexture(c);
  t.colorSpace = SRGBColorSpace;
  return t;
}

const sphere = new SphereGeometry(1, 32, 20);
const bodyMeshes = Object.fromEntries(
  SOLAR_SYSTEM_BODIES.map((b) => {
    const map = surfaceTexture(b);
    // The planets lit by the Sun, with a little of their own colour so the night side still reads.
    const material =
      b === 'Sun'
        ? new MeshBasicMaterial({ map })
        : new MeshStandardMaterial({ map, roughness: 0.8, emissive: 0xffffff, emissiveMap: map, emissiveIntensity: 0.25 });
    const mesh = new Mesh(sphere, material);
    // Axes tipped a little (Uranus on its side), so the bands and caps read as a globe.
    mesh.rotation.x = b === 'Uranus' ? 1.7 : 0.4;
    app.scene.add(mesh);
    return [b, mesh];
  }),
) as unknown as Record<SolarSystemBody, Mesh>;

/** A soft halo of its colour round each planet, a few pixels wide at any zoom, so the small ones read as lights. */
const HALO_PX = 56;
const planetHalos = Object.fromEntries(
  SOLAR_SYSTEM_PLANETS.map((b) => {
    const halo = new Sprite(
      new SpriteMaterial({
        map: glowTexture('rgba(255, 255, 255, 0.9)', 'rgba(255, 255, 255, 0.3)', 'rgba(255, 255, 255, 0)'),
        color: COLOR[b],
        blending: AdditiveBlending,
        depthWrite: false,
        transparent: true,
        sizeAttenuation: false,
      }),
    );
    app.scene.add(halo);
    return [b, halo];
  }),
) as unknown as Record<(typeof SOLAR_SYSTEM_PLANETS)[number], Sprite>;
// Saturn's rings: a flat disc that follows Saturn.
const rings = new Mesh(new SphereGeometry(1, 32, 4), new MeshBasicMaterial({ color: 0xcdb98a, transparent: true, opacity: 0.5 }));
app.scene.add(rings);

/**
 * Drawn radius of a body, display AU: the true radius, or exaggerated so every body shows at the
 * scale of the orbits (planets 0.012 AU + 120 times their radius, keeping the giants larger; the Sun 12 times).
 */
function drawnRadius(name: SolarSystemBody): number {
  const r = RADIUS_AU[name];
  if (!params.exaggerate) return r;
  return name === 'Sun' ? 12 * r : 0.012 + 120 * r;
}

/** Share of the true scale drawn now (0 compressed, 1 true), eased towards the chosen one. */
let trueScale = params.distances === 'true' ? 1 : 0;
/** Display places of the bodies this frame, scene units (x, y, z each, SOLAR_SYSTEM_BODIES order). */
const shown = new Float64Array(3 * SOLAR_SYSTEM_BODIES.length);

/** The display place (scene units) of the heliocentric point (x, y, z) AU, into out[o..o+2]. */
function place(x: number, y: number, z: number, out: { [index: number]: number }, o = 0): void {
  toDisplay(x, y, z, trueScale, out, o);
  out[o] = out[o]! * UNITS_PER_AU;
  out[o + 1] = out[o + 1]! * UNITS_PER_AU;
  out[o + 2] = out[o + 2]! * UNITS_PER_AU;
}

/**
 * The display direction (unit, scene axes) of the heliocentric direction d at the heliocentric point
 * r: the radial part stretched by d rho / dr and the rest by rho / r (./distance-scale.ts).
 */
function displayDirection(r: ArrayLike<number>, d: ArrayLike<number>, out: Vector3): Vector3 {
  const rn = Math.hypot(r[0]!, r[1]!, r[2]!);
  const rho = displayRadius(rn, trueScale);
  const h = 1e-6 * rn;
  const drho = (displayRadius(rn + h, trueScale) - rho) / h;
  const ux = r[0]! / rn,
    uy = r[1]! / rn,
    uz = r[2]! / rn;
  const along = d[0]! * ux + d[1]! * uy + d[2]! * uz;
  const k = rho / rn;
  out.set(
    drho * along * ux + k * (d[0]! - along * ux),
    drho * along * uy + k * (d[1]! - along * uy),
    drho * along * uz + k * (d[2]! - along * uz),
  );
  return out.normalize();
}

// ---- Orbit lines: each planet's Kepler ellipse about the Sun from its state now ---------------------

/** Points of a drawn orbit. */
const ORBIT_POINTS = 256;
const orbitLines = Object.fromEntries(
  SOLAR_SYSTEM_PLANETS.map((name) => {
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(3 * ORBIT_POINTS), 3));
    const line = new LineLoop(geometry, new LineBasicMaterial({ color: COLOR[name], transparent: true, opacity: 0.5 }));
    app.scene.add(line);
    return [name, line];
  }),
) as Record<string, LineLoop>;
let orbitsDrawn = 0;
let orbitsAt = -Infinity,
  orbitsScale = -1;
const orbitPoint = [0, 0, 0];

/**
 * Redraws every planet's orbit: the two-body (Sun and planet) Kepler ellipse through its position and
 * velocity now, mu = G (M_sun + m) (AU^3/day^2), from the eccentricity vector e = (v x h) / mu - r / |r|
 * and the semi-major axis a = 1 / (2 / |r| - |v|^2 / mu) (vis-viva): r(f) = a (1 - e^2) / (1 + e cos f)
 * around the focus at the Sun, in the orbit's plane, each point on the display scale. The giants'
 * pull makes the real paths wander a little from these ellipses over the years.
 */
function drawOrbits(world: PhysicsWorld): void {
  const c = world.components,
    G = world.laws.gravitationalConstant,
    sun = slotOf(handles.bodies.Sun);
  orbitsDrawn = 0;
  for (const name of SOLAR_SYSTEM_PLANETS) {
    const s = heliocentricState(world, handles, handles.bodies[name], state6);
    const r = new Vector3(s[0], s[1], s[2]);
    const u = new Vector3(s[3], s[4], s[5]);
    const mu = G * (c.Mass.value[sun]! + c.Mass.value[slotOf(handles.bodies[name])]!);
    const h = new Vector3().crossVectors(r, u);
    const ecc = new Vector3().crossVectors(u, h).divideScalar(mu).sub(r.clone().divideScalar(r.length()));
    const a = 1 / (2 / r.length() - u.lengthSq() / mu);
    const en = ecc.length();
    const line = orbitLines[name]!;
    line.visible = a > 0 && en < 1;
    if (!line.visible) continue;
    // Orbit frame: p toward the perihelion (or along r for a circle), q = h x p.
    const p = en > 1e-9 ? ecc.clone().normalize() : r.clone().normalize();
    const q = new Vector3().crossVectors(h, p).normalize();
    const attr = line.geometry.getAttribute('position') as Float32BufferAttribute;
    const arr = attr.array as Float32Array;
    for (let i = 0; i < ORBIT_POINTS; i++) {
      const f = (2 * Math.PI * i) / ORBIT_POINTS;
      const rr = (a * (1 - en * en)) / (1 + en * Math.cos(f));
      const x = rr * Math.cos(f),
        y = rr * Math.sin(f);
      place(x * p.x + y * q.x, x * p.y + y * q.y, x * p.z + y * q.z, orbitPoint);
      arr[3 * i] = orbitPoint[0]!;
      arr[3 * i + 1] = orbitPoint[1]!;
      arr[3 * i + 2] = orbitPoint[2]!;
    }
    attr.needsUpdate = true;
    line.geometry.computeBoundingSphere();
    orbitsDrawn++;
  }
}

// ---- The launch: arrow, plan, ghost, zone; the probe and its trail -----------------------------------

/** The launch arrow: a shaft and a head (unit length along +y, scaled and turned per frame). */
const arrow = new Group();
{
  const material = new MeshBasicMaterial({ color: 0xffe066 });
  const shaft = new Mesh(new CylinderGeometry(0.035, 0.035, 0.72, 10), material);
  shaft.position.y = 0.36;
  const head = new Mesh(new ConeGeometry(0.11, 0.28, 16), material);
  head.position.y = 0.86;
  arrow.add(shaft, head);
  app.scene.add(arrow);
}
const arrowUp = new Vector3(0, 1, 0);
app.scene.add(arrow);
/**
 * How many times longer and thicker the launch arrow is drawn on a touch screen (a phone): 1 on a
 * desktop. A phone's narrow view made it a sliver beside the Earth, too small to see where a tap aimed it.
 */
const ARROW_SCALE = matchMedia('(pointer: coarse)').matches ? 2.2 : 1;

/** A line of up to `n` points with its own buffer, drawn with `material`. */
function dynamicLine(n: number, material: LineBasicMaterial, loop = false): Line {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(3 * n), 3));
  const line = loop ? new LineLoop(geometry, material) : new Line(geometry, material);
  line.frustumCulled = false;
  app.scene.add(line);
  return line;
}
/** Every PLAN_STRIDE-th point of the forecast is drawn as a dot: dots at equal times, closer where the probe is slow. */
const PLAN_STRIDE = 4;
/** A white disc on a clear ground: point sprites drawn round, not square. */
const DISC = (() => {
  const c = document.createElement('canvas');
  c.width = c.height = 32;
  const g = c.getContext('2d')!;
  g.fillStyle = '#fff';
  g.beginPath();
  g.arc(16, 16, 15, 0, 2 * Math.PI);
  g.fill();
  return new CanvasTexture(c);
})();
/** Dots of the plan the last frame drew. */
let planDotsShown = 0;
/** Forecast points the last frame's dots stand for (from the probe now, or the launch, to the closest approach). */
let planPointsShown = 0;
const planDots = (() => {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(forecast.path.length), 3));
  const points = new Points(
    geometry,
    new PointsMaterial({ color: 0x9fd3ff, size: 4.5, sizeAttenuation: false, map: DISC, alphaTest: 0.5, transparent: true, opacity: 0.95 }),
  );
  points.frustumCulled = false;
  app.scene.add(points);
  return points;
})();
/** The gap between where the probe and the target would be at the closest approach. */
const missLine = dynamicLine(2, new LineBasicMaterial({ color: 0xff9b9b, transparent: true, opacity: 0.8 }));
/** A cloud of `n` dots of `size` px in `color`, its positions written per frame. */
function dotCloud(n: number, color: number, size: number): Points {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(3 * n), 3));
  const points = new Points(
    geometry,
    new PointsMaterial({ color, size, sizeAttenuation: false, map: DISC, alphaTest: 0.5, transparent: true, opacity: 0.95 }),
  );
  points.frustumCulled = false;
  app.scene.add(points);
  return points;
}
/**
 * The preview's timing: the target's own dots from where it is now to the ghost ring (at the same
 * times apart as the probe's), and on a miss a white dot where the probe is then. The probe's dots
 * stop there too: drawn on past it, a miss's path ran through the ghost ring (the probe passing the
 * place before or after the planet is there) while the status line and the hint said it missed.
 */
const trackDots = dotCloud(TARGET_TRACK, 0xffffff, 3);
const probeThen = dotCloud(1, 0xffffff, 10);
/** Before the verdict shows: the target where it is on the day the probe meets its orbit (the end of its dots). */
const targetThen = dotCloud(1, 0xffffff, 12);
const CIRCLE = 64;
/** A unit circle in the x-z plane (scaled and placed per use). */
function circle(color: number, opacity: number): LineLoop {
  const line = dynamicLine(CIRCLE, new LineBasicMaterial({ color, transparent: true, opacity }), true) as LineLoop;
  const arr = (line.geometry.getAttribute('position') as Float32BufferAttribute).array as Float32Array;
  for (let i = 0; i < CIRCLE; i++) {
    arr[3 * i] = Math.cos((2 * Math.PI * i) / CIRCLE);
    arr[3 * i + 2] = Math.sin((2 * Math.PI * i) / CIRCLE);
  }
  line.geometry.computeBoundingSphere();
  return line;
}
/** The arrival zone round the target, and the ghost of the target where the plan meets it. */
const zoneRing = circle(0x7ee787, 0.9);
const ghostRing = circle(0xffffff, 0.8);

/**
 * Draws `line` (a CIRCLE-point loop) as the true edge of a capture zone: the heliocentric circle of
 * radius `r` AU round (cx, cz) in the plane y = `cy` (AU), each point carried to the display by
 * `place`. The display squeezes distances (./distance-scale.ts), differently along and across the
 * radius, so a circle scaled by one number is not the zone's edge; drawn point by point it is, and a
 * place inside the zone is drawn inside the ring. `grow` widens it (the live ring's pulse).
 */
function zoneEdge(line: LineLoop, cx: number, cy: number, cz: number, r: number, grow = 1): void {
  const attr = line.geometry.getAttribute('position') as Float32BufferAttribute;
  const arr = attr.array as Float32Array;
  for (let i = 0; i < CIRCLE; i++) {
    const a = (2 * Math.PI * i) / CIRCLE;
    place(cx + r * grow * Math.cos(a), cy, cz + r * grow * Math.sin(a), arr, 3 * i);
  }
  attr.needsUpdate = true;
  line.position.set(0, 0, 0);
  line.scale.setScalar(1);
}
const trailLine = dynamicLine(TRAIL_POINTS, new LineBasicMaterial({ color: 0xfff1b8, transparent: true, opacity: 0.85 }));
const probeMesh = new Mesh(sphere, new MeshBasicMaterial({ color: 0xffffff }));
app.scene.add(probeMesh);
/** How long a burn's flame shows, and the course before it (`burnGhost`), after the burn, ms. */
const FLAME_MS = 900,
  GHOST_MS = 4000;
/**
 * A burn's flame: an orange cone out of the probe's back, against the burn's push (`burnPush`),
 * shown FLAME_MS after each burn and shrinking; a stranger saw nothing happen at a burn.
 */
const flame = new Mesh(
  // Its base at the probe, its tip 2 units along -y.
  new ConeGeometry(0.5, 2, 16).rotateX(Math.PI).translate(0, -1, 0),
  new MeshBasicMaterial({ color: 0xffa040, transparent: true, opacity: 0.95, blending: AdditiveBlending, depthWrite: false }),
);
flame.visible = false;
app.scene.add(flame);
/** The last burn's push, a heliocentric unit vector (./missions.ts burnDirection). */
const burnPush = new Float64Array(3);
/** The course's dots just before the last burn, drawn dim for GHOST_MS so the burn's change to the course shows. */
const burnGhost = (() => {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(new Float32Array(forecast.path.length), 3));
  const points = new Points(
    geometry,
    new PointsMaterial({ color: 0x9fd3ff, size: 3, sizeAttenuation: false, map: DISC, alphaTest: 0.2, transparent: true, opacity: 0.35 }),
  );
  points.frustumCulled = false;
  points.visible = false;
  geometry.setDrawRange(0, 0);
  app.scene.add(points);
  return points;
})();
/** Keeps the course's dots drawn now as the ghost of the course before a burn. */
function keepBurnGhost(): void {
  const from = planDots.geometry.getAttribute('position') as Float32BufferAttribute;
  const to = burnGhost.geometry.getAttribute('position') as Float32BufferAttribute;
  (to.array as Float32Array).set(from.array as Float32Array);
  to.needsUpdate = true;
  burnGhost.geometry.setDrawRange(0, planDotsShown);
}
const flameTip = [0, 0, 0];
/**
 * Draws the burn's flame at the probe (display place `at`, probe radius `size`, scene units) and the
 * ghost of the course before it, each for its time after the last burn that used fuel (`lastBurnDone`).
 */
function drawBurn(at: readonly number[], size: number, flying: boolean): void {
  const since = performance.now() - lastBurnDone;
  flame.visible = flying && since < FLAME_MS;
  burnGhost.visible = flying && since < GHOST_MS;
  if (burnGhost.visible) (burnGhost.material as PointsMaterial).opacity = 0.45 * (1 - since / GHOST_MS);
  if (!flame.visible || !flight) return;
  // The flame points against the push: its direction on the display from the probe's place and a
  // point a little behind it (the display squeezes distances, so the push is carried through it).
  heliocentricState(shell.world, handles, flight.probe, state6);
  const e = 0.02 * Math.hypot(state6[0]!, state6[1]!, state6[2]!);
  place(state6[0]! - e * burnPush[0]!, state6[1]! - e * burnPush[1]!, state6[2]! - e * burnPush[2]!, flameTip);
  const d = new Vector3(flameTip[0]! - at[0]!, flameTip[1]! - at[1]!, flameTip[2]! - at[2]!).normalize();
  flame.position.set(at[0]!, at[1]!, at[2]!);
  // The cone's tip is along its -y: turn -y onto the way back.
  flame.quaternion.setFromUnitVectors(new Vector3(0, -1, 0), d);
  // Several times the probe's size (a dot of a few pixels), so it reads at the map's scale (on a
  // phone's narrow view ARROW_SCALE times more, as the launch arrow).
  const left = 1 - since / FLAME_MS;
  const w = size * (1.4 + 0.8 * left) * ARROW_SCALE;
  flame.scale.set(w, size * (3 + 5 * left) * ARROW_SCALE * (0.85 + 0.3 * Math.random()), w);
}

/** Adds the probe's heliocentric place now to its trail (every other step; thinned to half when full). */
function recordTrail(world: PhysicsWorld): void {
  if (!flight) return;
  if (trailCount === TRAIL_POINTS) {
    for (let i = 0; i < TRAIL_POINTS / 2; i++) trail.copyWithin(3 * i, 6 * i, 6 * i + 3);
    trailCount = TRAIL_POINTS / 2;
  }
  heliocentricState(world, handles, flight.probe, state6);
  trail.set(state6.subarray(0, 3), 3 * trailCount++);
}

/** Writes heliocentric points (AU) into a line's buffer on the display scale and shows `count` of them. */
function setLinePoints(line: Line, points: Float64Array, count: number): void {
  const attr = line.geometry.getAttribute('position') as Float32BufferAttribute;
  const arr = attr.array as Float32Array;
  for (let i = 0; i < count; i++) place(points[3 * i]!, points[3 * i + 1]!, points[3 * i + 2]!, arr, 3 * i);
  attr.needsUpdate = true;
  line.geometry.setDrawRange(0, count);
}

// ---- Camera views ------------------------------------------------------------------------------------

/** The camera looks along this, steep enough that the orbits read as near circles. */
const VIEW_DIRECTION: [number, number, number] = [0.1, 1, 0.75];
/**
 * The camera's direction from the Sun on a portrait canvas: nearer top-down, so the ecliptic disc
 * (which the width limits there) is drawn nearly round and fills the height, where the landscape
 * tilt squashed it to a band in the upper middle with a quarter of empty stars below.
 */
const PORTRAIT_VIEW_DIRECTION: [number, number, number] = [0.05, 1, 0.3];
type View = 'inner' | 'all' | 'mission';
let view: View = 'mission';
/** Radius of the framed view, scene units. */
let viewHalf = 10;

/**
 * Frames the Sun and the orbits out to: Mars (inner), Neptune (all), or the farther of the Earth and
 * the mission's planet (mission), at its farthest from the Sun, on the display scale, with a margin
 * (`frameDisc`).
 */
function frameView(which: View): void {
  view = which;
  const far = (name: SolarSystemBody): number => APHELION[name] ?? 1;
  const out = which === 'inner' ? far('Mars') : which === 'all' ? far('Neptune') : Math.max(far('Earth'), far(mission().target));
  frameDisc(displayRadius(out, targetScale()) * UNITS_PER_AU * 1.04 + 0.4);
}
/** Each planet's greatest distance from the Sun, AU (aphelion, rounded up). */
const APHELION: Partial<Record<SolarSystemBody, number>> = {
  Mercury: 0.47,
  Venus: 0.73,
  Earth: 1.02,
  Mars: 1.67,
  Jupiter: 5.46,
  Saturn: 10.1,
  Uranus: 20.1,
  Neptune: 30.3,
};

/** The disc the camera frames (scene units), kept through resizes until the player moves the camera; null once moved. */
let framedRadius: number | null = null;
const ndcPoint = new Vector3();

/**
 * Places the camera along VIEW_DIRECTION (PORTRAIT_VIEW_DIRECTION on a portrait canvas) from the Sun at the least distance that keeps the whole
 * ecliptic disc of `radius` scene units inside the view with a 6 % margin (bisection on the distance,
 * the disc's rim sampled every 10 degrees, a little above and below the plane).
 */
function frameDisc(radius: number): void {
  framedRadius = radius;
  const camera = app.camera;
  const portrait = app.canvas.clientHeight > app.canvas.clientWidth;
  const dir = new Vector3(...(portrait ? PORTRAIT_VIEW_DIRECTION : VIEW_DIRECTION)).normalize();
  // Bisection between a distance too close and one far enough (a 50-degree view fits the disc
  // within 4 radii); the far plane lies beyond both, so every rim point is in front of it.
  let lo = radius * 0.05,
    hi = radius * 8;
  const fits = (d: number): boolean => {
    camera.position.copy(dir).multiplyScalar(d);
    camera.lookAt(0, 0, 0);
    camera.updateMatrixWorld();
    for (let k = 0; k < 72; k++) {
      const a = (k * Math.PI) / 36;
      ndcPoint.set(radius * Math.cos(a), (k % 2 ? 0.04 : -0.04) * radius, radius * Math.sin(a)).project(camera);
      if (ndcPoint.z > 1 || Math.abs(ndcPoint.x) > 0.94 || Math.abs(ndcPoint.y) > 0.94) return false;
    }
    return true;
  };
  camera.near = radius / 400;
  camera.far = Math.max(6000, 20 * radius);
  camera.updateProjectionMatrix();
  for (let i = 0; i < 40; i++) {
    const mid = (lo + hi) / 2;
    if (fits(mid)) hi = mid;
    else lo = mid;
  }
  camera.position.copy(dir).multiplyScalar(hi);
  camera.lookAt(0, 0, 0);
  viewHalf = radius;
  if (app.controls) {
    app.controls.target.set(0, 0, 0);
    app.controls.update();
  }
}
app.controls?.addEventListener('start', () => {
  framedRadius = null;
});
const refit = (): void => {
  if (framedRadius !== null) frameDisc(framedRadius);
};
window.addEventListener('resize', refit);
new ResizeObserver(refit).observe(pageLayout().stage);

const targetScale = (): number => (params.distances === 'true' ? 1 : 0);

function setDistances(which: 'compressed' | 'true'): void {
  params.distances = which;
  frameView(view);
  panel.refresh();
}

// ---- Labels and dots --------------------------------------------------------------------------------

const labelLayer = document.createElement('div');
labelLayer.style.cssText =
  'position: absolute; inset: 0; pointer-events: none; z-index: 5; font: 12px system-ui, sans-serif; color: #dfe7ff';
// Over the canvas (in the layout's stage): the labels are part of the scene.
labelLayer.dataset.sceneOverlay = '';
pageLayout().stage.append(labelLayer);
/** Names on the screen: the bodies, then the probe. */
const LABELS = [...SOLAR_SYSTEM_BODIES, 'probe'] as const;
type LabelName = (typeof LABELS)[number];
const labels = Object.fromEntries(
  LABELS.map((name) => {
    const el = document.createElement('div');
    el.textContent = name === 'Earth' ? 'Earth' : name;
    el.dataset.label = name;
    // A dark translucent backing keeps the name legible over a bright planet or line.
    el.style.cssText =
      'position: absolute; white-space: nowrap; padding: 0 4px; border-radius: 3px; background: rgba(8, 10, 16, 0.78); line-height: 16px';
    labelLayer.append(el);
    return [name, el];
  }),
) as Record<LabelName, HTMLDivElement>;

// A dot of the body's colour at its place, kept a few pixels wide: at the scale of the whole system
// even the exaggerated planets are a pixel or two, and a player could not find them. The dot hides once
// the body itself is drawn larger.
const dots = Object.fromEntries(
  LABELS.map((name) => {
    const el = document.createElement('div');
    const size = name === 'Sun' ? 12 : name === 'Jupiter' || name === 'Saturn' ? 8 : name === 'probe' ? 7 : 6;
    const colour = name === 'probe' ? '#ffffff' : hex(COLOR[name]);
    el.style.cssText = `position: absolute; width: ${size}px; height: ${size}px; margin: ${-size / 2}px 0 0 ${-size / 2}px; border-radius: 50%; background: ${colour}; box-shadow: 0 0 6px ${colour}`;
    el.dataset.dot = name;
    labelLayer.append(el);
    return [name, { el, size }];
  }),
) as Record<LabelName, { el: HTMLDivElement; size: number }>;

/**
 * The forecast's two marks named on the map while aiming: the ring where the target will be when the
 * probe comes closest ("Mars at arrival") and the probe's place then ("probe then"), so a path
 * running through the target's ring of now does not read as a hit.
 */
const TAG_STYLE =
  'position: absolute; white-space: nowrap; padding: 0 4px; border-radius: 3px; background: rgba(8, 10, 16, 0.78); line-height: 16px; font-style: italic; display: none; pointer-events: none';
const forecastTags = (['target-then', 'probe-then'] as const).map((name) => {
  const el = document.createElement('div');
  el.dataset.tag = name;
  el.style.cssText = TAG_STYLE;
  labelLayer.append(el);
  return el;
});
/**
 * Each forecast tag's text ('' hidden) and place (left, top, px) as this frame worked them out:
 * shown with the dots and names, by `showOverlay`, when the frame's scene is drawn (moved at once,
 * a tag sat by the aim's new dots while the canvas still showed the old ones, on a page drawing few
 * frames).
 */
const tagShown = forecastTags.map(() => ({ text: '', x: 0, y: 0 }));
/** A hidden copy of a tag: measures a tag's text before it is shown. */
const tagMeasure = document.createElement('div');
tagMeasure.style.cssText = `${TAG_STYLE}; display: block; visibility: hidden; left: -9999px; top: 0`;
labelLayer.append(tagMeasure);

/** Least gap between a forecast tag and the view's edge, px. */
const TAG_MARGIN = 6;
/** Gap between a forecast tag stacked under or over the other and that tag, px. */
const TAG_GAP = 2;
/** The forecast tags shown this frame: left, top, right, bottom (px), four numbers each; the names keep clear of them (placeLabels). */
const tagBoxes: number[] = [];
/**
 * Shows forecast tag `i` (0 the target then, 1 the probe then) with `text` by scene point (x, y, z):
 * centred `below` px under it (over it when negative) where that is clear, else over (under) it, to
 * its right or to its left, the first place that keeps clear of the other tag, the dots and the
 * names as last placed; each place moved inside the view, so on a phone no tag is cut off at an
 * edge or sits on other names. Where none is, the first of those places, or else a place stacked
 * under or over the other tag, that keeps clear of the other tag (./tag-place.ts tagPlace; the
 * names, placed after the tags, keep clear of both): the two tags never overlap (with the target
 * and the probe meeting, zoomed on Jupiter, "probe on day 427" lay over "Jupiter on day 427").
 * Hides it when `text` is '' or no place clears the other tag. `frame` clears `tagBoxes` before the
 * tags are placed.
 */
function placeTag(i: number, text: string, x: number, y: number, z: number, below: number): void {
  const shown = tagShown[i]!;
  v.set(x, y, z).project(app.camera);
  const show = text !== '' && v.z < 1 && Math.abs(v.x) < 1 && Math.abs(v.y) < 1;
  shown.text = show ? text : '';
  if (!show) return;
  const el = tagMeasure;
  if (el.textContent !== text) el.textContent = text;
  const w = app.canvas.clientWidth,
    h = app.canvas.clientHeight;
  const sx = ((v.x + 1) / 2) * w,
    sy = ((1 - v.y) / 2) * h;
  const tw = el.offsetWidth,
    th = el.offsetHeight || LABEL_HEIGHT;
  const off = Math.abs(below);
  const places: [number, number][] = [
    [sx - tw / 2, below >= 0 ? sy + off : sy - off],
    [sx - tw / 2, below >= 0 ? sy - off - th : sy + off - th],
    [sx + Math.max(8, off * 0.7), sy - th / 2],
    [sx - Math.max(8, off * 0.7) - tw, sy - th / 2],
  ];
  const tags: TagBox[] = [];
  for (let b = 0; b < tagBoxes.length; b += 4) tags.push([tagBoxes[b]!, tagBoxes[b + 1]!, tagBoxes[b + 2]!, tagBoxes[b + 3]!]);
  // TAG_MARGIN px clear of the view's edges (an italic first letter 2 px from the edge looks cut).
  const at = tagPlace(places, tw, th, sx, { w, h, margin: TAG_MARGIN }, tags, (x0, y0, x1, y1) => labelFree(x0, y0, x1, y1, -1), TAG_GAP);
  if (!at) {
    shown.text = '';
    return;
  }
  [shown.x, shown.y] = at;
  tagBoxes.push(shown.x, shown.y, shown.x + tw, shown.y + th);
}

/** Labels placed this frame: left, top, right, bottom (px), four numbers each. */
const placed: number[] = [];
/** Labels the last frame showed. */
let shownLabels = 0;
/**
 * Places a name may take beside its dot, as (side, shift) pairs: side +1 right of it, -1 left, 0
 * centred over (shift -1) or under (shift +1) it; shift in label heights, so a name never sits more
 * than a few pixels from its dot.
 */
const LABEL_PLACES = [1, 0, -1, 0, 1, -0.5, 1, 0.5, -1, -0.5, -1, 0.5, 0, -1, 0, 1, 1, -1, 1, 1, -1, -1, -1, 1];
const LABEL_HEIGHT = 16;

/** Whether the box (x0, y0)-(x1, y1) px clears every label placed this frame and every dot but its own. */
function labelFree(x0: number, y0: number, x1: number, y1: number, own: number): boolean {
  for (let i = 0; i < placed.length; i += 4) {
    if (x0 < placed[i + 2]! && x1 > placed[i]! && y0 < placed[i + 3]! && y1 > placed[i + 1]!) return false;
  }
  for (let j = 0; j < LABELS.length; j++) {
    if (j === own || onScreen[4 * j + 3] !== 1) continue;
    const x = onScreen[4 * j]!,
      y = onScreen[4 * j + 1]!;
    if (x > x0 - 3 && x < x1 + 3 && y > y0 - 3 && y < y1 + 3) return false;
  }
  return true;
}

/** Per label (LABELS order): screen x, y (px), drawn radius (px), on screen (1) or not (0). */
const onScreen = new Float64Array(4 * LABELS.length);
/** The order names are placed in this frame (indices into LABELS). */
const labelOrder = LABELS.map((_, i) => i);
const v = new Vector3();
const dirV = new Vector3();
const scratch3 = [0, 0, 0];

/** Per label (LABELS order): whether its dot shows (1) or not (0) in the frame being made. */
const dotShown = new Uint8Array(LABELS.length);
/** Per label (LABELS order): left and top of its name (px) in the frame being made, NaN when hidden. */
const labelAt = new Float64Array(2 * LABELS.length);

/** Projects scene point (x, y, z) into onScreen entry `i` and works out whether its dot shows (`dotShown`). */
function project(i: number, name: LabelName, x: number, y: number, z: number, radius: number, show: boolean): void {
  const w = app.canvas.clientWidth,
    h = app.canvas.clientHeight;
  onScreen[4 * i + 3] = 0;
  const dotSize = dots[name].size;
  dotShown[i] = 0;
  if (!show) return;
  v.set(x, y, z);
  const distance = v.distanceTo(app.camera.position);
  v.project(app.camera);
  const visible = v.z < 1 && Math.abs(v.x) < 1.05 && Math.abs(v.y) < 1.05;
  const sx = ((v.x + 1) / 2) * w,
    sy = ((1 - v.y) / 2) * h;
  // Radius the body is drawn with, px (perspective: h / 2 px span tan(fov / 2) x distance).
  const drawnPx = (radius * h) / (2 * distance * Math.tan((app.camera.fov * Math.PI) / 360));
  dotShown[i] = visible && drawnPx < dotSize / 2 ? 1 : 0;
  onScreen[4 * i] = sx;
  onScreen[4 * i + 1] = sy;
  onScreen[4 * i + 2] = drawnPx;
  onScreen[4 * i + 3] = visible ? 1 : 0;
}

/** Places the names: the Sun, the target, the probe and the Earth first, then the planets farthest from the Sun on the screen. */
function placeLabels(): void {
  const w = app.canvas.clientWidth;
  const target = LABELS.indexOf(mission().target);
  const rank = (i: number): number => {
    const name = LABELS[i]!;
    if (name === 'Sun') return 4e6;
    if (i === target) return 3e6;
    if (name === 'probe') return 2e6;
    if (name === 'Earth') return 1e6;
    return Math.hypot(onScreen[4 * i]! - onScreen[0]!, onScreen[4 * i + 1]! - onScreen[1]!);
  };
  labelOrder.sort((a, b) => rank(b) - rank(a));
  // The forecast's tags (placeTag) are placed first this frame: the names keep clear of them.
  placed.length = 0;
  for (let b = 0; b < tagBoxes.length; b++) placed.push(tagBoxes[b]!);
  for (const i of labelOrder) {
    const name = LABELS[i]!;
    const el = labels[name];
    const x = onScreen[4 * i]!,
      y = onScreen[4 * i + 1]!,
      drawnPx = onScreen[4 * i + 2]!,
      visible = onScreen[4 * i + 3] === 1;
    const width = el.offsetWidth || 7.5 * (el.textContent?.length ?? 4) + 8;
    const gap = Math.max(7, drawnPx + 4);
    let free = false,
      x0 = 0,
      y0 = 0;
    if (visible) {
      for (let c = 0; c < LABEL_PLACES.length && !free; c += 2) {
        const side = LABEL_PLACES[c]!,
          shift = LABEL_PLACES[c + 1]!;
        if (side === 0) {
          x0 = x - width / 2;
          y0 = shift < 0 ? y - gap - LABEL_HEIGHT + 3 : y + gap - 3;
        } else {
          x0 = side > 0 ? x + gap : x - gap - width;
          y0 = y - LABEL_HEIGHT / 2 + shift * LABEL_HEIGHT * (Math.abs(shift) === 1 ? 0.75 : 1);
        }
        free = x0 >= 0 && x0 + width <= w && labelFree(x0, y0, x0 + width, y0 + LABEL_HEIGHT, i);
      }
    }
    labelAt[2 * i] = free ? x0 : Number.NaN;
    labelAt[2 * i + 1] = y0;
    if (free) placed.push(x0, y0, x0 + width, y0 + LABEL_HEIGHT);
  }
  shownLabels = (placed.length - tagBoxes.length) / 4;
}

/** `onScreen` as of the last frame drawn (what `showOverlay` showed). */
const shownOnScreen = new Float64Array(4 * LABELS.length);

/** Moves the dots and names to where `project` and `placeLabels` put them this frame. */
function showOverlay(): void {
  shownOnScreen.set(onScreen);
  forecastTags.forEach((el, i) => {
    const t = tagShown[i]!;
    el.style.display = t.text === '' ? 'none' : '';
    if (t.text === '') return;
    if (el.textContent !== t.text) el.textContent = t.text;
    // The target's tag in the target's colour (half way to white: Mars's own red on the tag's dark
    // box was 2.8:1, under the 4.5:1 legible text needs), the probe's white: each reads as its dot's.
    const colour = i === 0 ? towardWhite(COLOR[mission().target]) : '#ffffff';
    if (el.dataset.colour !== colour) {
      el.dataset.colour = colour;
      el.style.color = colour;
    }
    el.style.left = `${t.x}px`;
    el.style.top = `${t.y}px`;
  });
  LABELS.forEach((name, i) => {
    const dot = dots[name].el;
    dot.style.display = dotShown[i] === 1 ? 'block' : 'none';
    if (dotShown[i] === 1) {
      dot.style.left = `${onScreen[4 * i]}px`;
      dot.style.top = `${onScreen[4 * i + 1]}px`;
    }
    const el = labels[name];
    const x0 = labelAt[2 * i]!;
    el.style.display = Number.isNaN(x0) ? 'none' : 'block';
    if (!Number.isNaN(x0)) {
      el.style.left = `${x0}px`;
      el.style.top = `${labelAt[2 * i + 1]}px`;
    }
  });
}

// ---- Each frame -------------------------------------------------------------------------------------

const earthHelio = new Float64Array(6);
const launchDir = new Float64Array(3);
let lastFrame = performance.now();

function frame(): void {
  const now = performance.now();
  const dtReal = Math.min(0.1, (now - lastFrame) / 1000);
  frameGap = now - lastFrame;
  lastFrame = now;
  const world = shell.world;
  // Ease the distance scale towards the chosen one.
  const goal = targetScale();
  if (trueScale !== goal) {
    trueScale = goal > trueScale ? Math.min(goal, trueScale + 2 * dtReal) : Math.max(goal, trueScale - 2 * dtReal);
    if (Math.abs(trueScale - goal) < 1e-3) trueScale = goal;
  }
  SOLAR_SYSTEM_BODIES.forEach((name, i) => {
    heliocentricState(world, handles, handles.bodies[name], state6);
    place(state6[0]!, state6[1]!, state6[2]!, shown, 3 * i);
    const mesh = bodyMeshes[name];
    const r = drawnRadius(name) * UNITS_PER_AU;
    mesh.position.set(shown[3 * i]!, shown[3 * i + 1]!, shown[3 * i + 2]!);
    mesh.scale.setScalar(r);
    // A turn every few real seconds: the surfaces show they are globes.
    mesh.rotation.y += dtReal * (name === 'Sun' ? 0.1 : 0.6);
    const halo = planetHalos[name as (typeof SOLAR_SYSTEM_PLANETS)[number]];
    if (halo) {
      halo.position.copy(mesh.position);
      // Without size attenuation a sprite of scale k spans k / tan(fov / 2) of the half-height.
      const tanHalf = Math.tan(((app.camera.fov / 2) * Math.PI) / 180);
      halo.scale.setScalar((2 * HALO_PX * tanHalf) / Math.max(1, app.renderer.domElement.clientHeight));
    }
    project(i, name, shown[3 * i]!, shown[3 * i + 1]!, shown[3 * i + 2]!, r, true);
  });
  sunGlow.position.set(0, 0, 0);
  sunGlow.scale.setScalar(drawnRadius('Sun') * UNITS_PER_AU * 9);
  const sat = SOLAR_SYSTEM_BODIES.indexOf('Saturn');
  rings.position.set(shown[3 * sat]!, shown[3 * sat + 1]!, shown[3 * sat + 2]!);
  rings.scale.set(1, 0.01, 1).multiplyScalar(drawnRadius('Saturn') * UNITS_PER_AU * 2.2);
  if (world.time - orbitsAt > 30 || orbitsAt > world.time || orbitsScale !== trueScale) {
    drawOrbits(world);
    orbitsAt = world.time;
    orbitsScale = trueScale;
  }
  tagBoxes.length = 0;
  drawLaunch(world);
  placeLabels();
  // The dots and names are HTML over the canvas: they move only when this frame's scene is drawn.
  // The frame pacer skips drawing while the GPU is behind (a slow or software GPU, often several
  // frames in a row); names moved on then sat tens of pixels from the planets the canvas still
  // showed. The shell draws right after this function returns, and a microtask runs after that,
  // before the page is painted.
  // The status line's forecast words change on the same drawn frame as the map's dots and day tags
  // (`drawnForecastKey`): written when the forecast was worked out, they ran a second and more ahead
  // of the map on a software GPU ("day 371" over tags saying "day 366").
  const drawnBefore = app.pacer.drawn;
  queueMicrotask(() => {
    if (app.pacer.drawn <= drawnBefore) return;
    showOverlay();
    if (drawnForecastKey !== forecastKey) {
      drawnForecastKey = forecastKey;
      updateStatus(true);
    }
  });
  updateStatus();
  if (tableFrame++ % 15 === 0 && table.open) updateTable();
}

/** The forecast (its key) the map showed on the last frame drawn: the status line's aim words are this forecast's. */
let drawnForecastKey = '';
/** The status line's aim words last written (the launch, the forecast's verdict) and their class. */
let shownPlan: [string, string] = ['', ''];

/** The forecast (its key) whose closest approach the ghost ring was last drawn for. */
let ghostKey = '';

/** The aim arrow, the plan, the ghost and the zone (aiming), or the probe and its trail (flying). */
function drawLaunch(world: PhysicsWorld): void {
  const m = mission();
  const targetI = SOLAR_SYSTEM_BODIES.indexOf(m.target);
  const earthI = SOLAR_SYSTEM_BODIES.indexOf('Earth');
  const aiming = phase === 'aim';
  // The zone: a ring round the target, its radius the zone on the display scale there.
  heliocentricState(world, handles, handles.bodies[m.target], state6);
  const rT = Math.hypot(state6[0]!, state6[1]!, state6[2]!);
  const zoneShown = ((displayRadius(rT + m.zone, trueScale) - displayRadius(Math.max(0, rT - m.zone), trueScale)) / 2) * UNITS_PER_AU;
  // The ring is the zone itself (the flight's arrival test), not a size chosen to look right.
  const zone = zoneShown;
  zoneEdge(zoneRing, state6[0]!, state6[1]!, state6[2]!, m.zone, 1 + 0.06 * Math.sin(performance.now() / 250));
  (zoneRing.material as LineBasicMaterial).color.setHex(phase === 'done' && flight?.state === 'arrived' ? 0xffe066 : 0x7ee787);
  const flashAge = (performance.now() - arrivalAt) / ARRIVAL_FLASH_MS;
  arrivalGlow.visible = flashAge >= 0 && flashAge < 1;
  if (arrivalGlow.visible) {
    arrivalGlow.position.set(shown[3 * targetI]!, shown[3 * targetI + 1]!, shown[3 * targetI + 2]!);
    arrivalGlow.scale.setScalar(zone * (2 + 10 * flashAge));
    arrivalGlow.material.opacity = 1 - flashAge;
  }
  // The forecast: of the launch while aiming, of the course from the probe while it flies (a burn
  // changes it; ./forecast.ts). Worked out a slice a frame, the last complete one drawn meanwhile.
  const cruising = phase === 'flight' && flight !== null;
  const planned = (aiming || cruising) && forecastKey !== '';
  updateForecast();
  arrow.visible = aiming;
  planDots.visible = planned;
  ghostRing.visible = planned;
  trackDots.visible = false;
  probeThen.visible = false;
  targetThen.visible = false;
  if (!planned) for (const t of tagShown) t.text = '';
  ghostOnScreen[3] = 0;
  missLine.visible = false;
  if (aiming) {
    heliocentricState(world, handles, handles.bodies.Earth, earthHelio);
    launchDirection(earthHelio, aim.angle, launchDir);
    displayDirection(earthHelio, launchDir, dirV);
    // Longer for a faster launch; thick enough to see which way it points at any zoom.
    let len = ARROW_SCALE * viewHalf * (0.16 + (0.4 * aim.speed) / MAX_SPEED);
    // Shortened (to no less than a third) where its tip would leave the view: on a phone the
    // pointing-right arrow of a fast launch ran off the right edge.
    const inView = (k: number): boolean => {
      v.set(shown[3 * earthI]! + k * dirV.x, shown[3 * earthI + 1]! + k * dirV.y, shown[3 * earthI + 2]! + k * dirV.z).project(app.camera);
      const mx = 12 / app.canvas.clientWidth,
        my = 12 / app.canvas.clientHeight;
      return v.z < 1 && Math.abs(v.x) < 1 - 2 * mx && Math.abs(v.y) < 1 - 2 * my;
    };
    if (!inView(len)) {
      let lo = len / 3,
        hi = len;
      for (let k = 0; k < 8; k++) {
        const mid = (lo + hi) / 2;
        if (inView(mid)) lo = mid;
        else hi = mid;
      }
      len = lo;
    }
    arrow.position.set(shown[3 * earthI]!, shown[3 * earthI + 1]!, shown[3 * earthI + 2]!);
    arrow.quaternion.setFromUnitVectors(arrowUp, dirV);
    arrow.scale.set(ARROW_SCALE * viewHalf * 0.3, len, ARROW_SCALE * viewHalf * 0.3);
  }
  if (planned) {
    const f = forecast;
    const arrived = f.outcome === 'arrived',
      sun = f.outcome === 'sun';
    // Before the mission's first failed try (`verdictShown`) the aim is read, not judged: the probe's
    // dots run to where they meet the target's orbit (./orbit-crossing.ts), the target's to where it
    // is that day, each end named with the day; no ring "at arrival", no line across a miss.
    const blind = aiming && !verdictShown();
    const cross = blind && !sun ? pathCrossing(m) : -1;
    const end = cross >= 0 ? cross : f.pointsToClosest;
    const probeEnd = cross >= 0 ? f.path.subarray(3 * cross, 3 * cross + 3) : f.probeAt;
    // The probe's dots from where it is now (in flight) to the closest approach (the arrival),
    // every PLAN_STRIDE-th sample and the place then.
    const attr = planDots.geometry.getAttribute('position') as Float32BufferAttribute;
    const arr = attr.array as Float32Array;
    const first = cruising && flight ? Math.max(0, Math.ceil((flight.elapsed - f.from) / f.every)) : 0;
    let n = 0;
    for (let i = first; i < end; i += PLAN_STRIDE) place(f.path[3 * i]!, f.path[3 * i + 1]!, f.path[3 * i + 2]!, arr, 3 * n++);
    place(probeEnd[0]!, probeEnd[1]!, probeEnd[2]!, arr, 3 * n++);
    attr.needsUpdate = true;
    planDots.geometry.setDrawRange(0, n);
    planDotsShown = n;
    planPointsShown = end - first;
    // The target's own dots from now to then, and on a miss a white dot where the probe is then
    // and a line across the gap.
    const track = trackDots.geometry.getAttribute('position') as Float32BufferAttribute;
    const trackArr = track.array as Float32Array;
    if (cross >= 0) {
      // Where the target goes until the day the probe meets its orbit: its Kepler orbit about the Sun.
      const days = pathDay(f, cross);
      for (let i = 0; i < TARGET_TRACK; i++) {
        keplerState(crossingTarget, crossingTarget.subarray(3), sunMu(), (days * (i + 1)) / TARGET_TRACK, state6);
        place(state6[0]!, state6[1]!, state6[2]!, trackArr, 3 * i);
      }
    } else
      for (let i = 0; i < TARGET_TRACK; i++)
        place(f.targetTrack[3 * i]!, f.targetTrack[3 * i + 1]!, f.targetTrack[3 * i + 2]!, trackArr, 3 * i);
    track.needsUpdate = true;
    (trackDots.material as PointsMaterial).color.setHex(hexColor(m.target));
    trackDots.visible = !sun && !cruising && (!blind || cross >= 0);
    targetThen.visible = cross >= 0;
    if (cross >= 0) {
      const at = targetThen.geometry.getAttribute('position') as Float32BufferAttribute;
      const t = 3 * (TARGET_TRACK - 1);
      (at.array as Float32Array).set(trackArr.subarray(t, t + 3));
      at.needsUpdate = true;
      (targetThen.material as PointsMaterial).color.setHex(hexColor(m.target));
    }
    probeThen.visible = !sun && (aiming || !arrived) && (!blind || cross >= 0);
    const then = probeThen.geometry.getAttribute('position') as Float32BufferAttribute;
    place(probeEnd[0]!, probeEnd[1]!, probeEnd[2]!, then.array as Float32Array, 0);
    then.needsUpdate = true;
    // The dots turn green on an arriving course in flight (while aiming the line and ring say it).
    const judged = arrived && !aiming;
    (planDots.material as PointsMaterial).color.setHex(judged ? 0x7ee787 : sun ? 0xffb4a8 : 0x9fd3ff);
    // The zone's edge where the target is at the closest approach, cut at the probe's height there:
    // the probe's place then (the white dot) is inside this ring exactly when it comes within the
    // zone, which is when the forecast, and the flight, arrive.
    const dy = f.probeAt[1]! - f.targetAt[1]!;
    zoneEdge(ghostRing, f.targetAt[0]!, f.probeAt[1]!, f.targetAt[2]!, Math.sqrt(Math.max(0, m.zone * m.zone - dy * dy)));
    ghostKey = forecastKey;
    place(f.targetAt[0]!, f.targetAt[1]!, f.targetAt[2]!, scratch3);
    (ghostRing.material as LineBasicMaterial).color.setHex(judged ? 0x7ee787 : hexColor(m.target));
    ghostRing.visible = !sun && !blind;
    // Named while aiming: the ring is where the target will be, the white dot where the probe is then.
    v.set(scratch3[0]!, scratch3[1]!, scratch3[2]!);
    const ringPx = (zone * app.canvas.clientHeight) / (2 * app.camera.position.distanceTo(v) * Math.tan((app.camera.fov * Math.PI) / 360));
    // Named while time runs too (Wait held): the player waits for the target's dots to end where
    // the probe's do, so the days named are the guidance then; they are the drawn forecast's, as
    // the dots and the line are.
    const tagged = aiming && !sun;
    v.project(app.camera);
    ghostOnScreen[0] = ((v.x + 1) / 2) * app.canvas.clientWidth;
    ghostOnScreen[1] = ((1 - v.y) / 2) * app.canvas.clientHeight;
    ghostOnScreen[2] = ringPx;
    ghostOnScreen[3] = aiming && !sun && !blind && v.z < 1 ? 1 : 0;
    if (blind) {
      // The two ends, each named with the day: the player judges whether they meet.
      const day = cross >= 0 ? Math.round(pathDay(f, cross)) : 0;
      const t = TARGET_TRACK - 1;
      placeTag(
        0,
        tagged && cross >= 0 ? `${m.target} on day ${day}` : '',
        trackArr[3 * t]!,
        trackArr[3 * t + 1]!,
        trackArr[3 * t + 2]!,
        10,
      );
      place(probeEnd[0]!, probeEnd[1]!, probeEnd[2]!, scratch3);
      placeTag(1, tagged && cross >= 0 ? `probe on day ${day}` : '', scratch3[0]!, scratch3[1]!, scratch3[2]!, -28);
    } else {
      placeTag(0, tagged ? `${m.target} at arrival` : '', scratch3[0]!, scratch3[1]!, scratch3[2]!, ringPx + 2);
      place(f.probeAt[0]!, f.probeAt[1]!, f.probeAt[2]!, scratch3);
      placeTag(1, tagged ? 'probe then' : '', scratch3[0]!, scratch3[1]!, scratch3[2]!, -ringPx - 20);
    }
    if ((aiming || !arrived) && !sun && !blind) {
      missLine.visible = true;
      const attr = missLine.geometry.getAttribute('position') as Float32BufferAttribute;
      const arr = attr.array as Float32Array;
      place(f.probeAt[0]!, f.probeAt[1]!, f.probeAt[2]!, arr, 0);
      place(f.targetAt[0]!, f.targetAt[1]!, f.targetAt[2]!, arr, 3);
      attr.needsUpdate = true;
    }
  }
  const flying = flight !== null && phase !== 'aim';
  trailLine.visible = flying;
  probeMesh.visible = flying;
  const probeI = LABELS.indexOf('probe');
  if (flying && flight) {
    setLinePoints(trailLine, trail, trailCount);
    heliocentricState(world, handles, flight.probe, state6);
    place(state6[0]!, state6[1]!, state6[2]!, scratch3);
    probeMesh.position.set(scratch3[0]!, scratch3[1]!, scratch3[2]!);
    probeMesh.scale.setScalar(viewHalf * 0.006);
    drawBurn(scratch3, viewHalf * 0.006, true);
    project(probeI, 'probe', scratch3[0]!, scratch3[1]!, scratch3[2]!, viewHalf * 0.006, true);
  } else {
    drawBurn(scratch3, 0, false);
    project(probeI, 'probe', 0, 0, 0, 0, false);
  }
}
const hexColor = (name: SolarSystemBody): number => COLOR[name];

// ---- Aiming with the pointer: a click or tap on the sky turns the launch towards that point ----------

const raycaster = new Raycaster();
const ecliptic = new Plane(new Vector3(0, 1, 0), 0);
const ndc = new Vector2();
const hitPoint = new Vector3();

/** The ring "at arrival" on the screen this frame while aiming: x, y, radius (px), 1 if drawn (else 0). */
const ghostOnScreen = new Float64Array(4);

/** A note the brief's line shows while aiming until performance.now() passes `aimNoteUntil` (ms). */
let aimNote = '';
let aimNoteUntil = -Infinity;

/**
 * Turns the launch towards the display point under the pointer (on the ecliptic). A press on the
 * target itself or on its ring "at arrival" (`first`, within 30 px of it) does not point the launch
 * at it, a course no probe flies (it curves round the Sun while the planet moves on): it turns the
 * arrow along the Earth's path (against it for an inner planet), the way a transfer starts, and
 * says why.
 */
function aimAtPointer(clientX: number, clientY: number, first = false): void {
  if (phase !== 'aim') return;
  const ti = LABELS.indexOf(mission().target);
  const rect = app.canvas.getBoundingClientRect();
  const px = clientX - rect.left,
    py = clientY - rect.top;
  const onTarget =
    onScreen[4 * ti + 3] === 1 && Math.hypot(px - onScreen[4 * ti]!, py - onScreen[4 * ti + 1]!) < 30 + onScreen[4 * ti + 2]!;
  // The ring "at arrival" too: aiming at it sent the probe sideways across the orbits (inwards, for Mars).
  const onRing = ghostOnScreen[3] === 1 && Math.hypot(px - ghostOnScreen[0]!, py - ghostOnScreen[1]!) < 30 + ghostOnScreen[2]!;
  if (first && (onTarget || onRing)) {
    const t = mission().target;
    const outward = distanceFromSun(t) > distanceFromSun('Earth');
    aim.angle = outward ? 0 : 180;
    aimChangedAt = performance.now();
    const curve = `${outward ? 'along' : 'against'} the Earth’s motion; the orbit curves ${outward ? 'out' : 'in'} to meet ${t}`;
    aimNote = onTarget
      ? `A probe does not fly straight at ${t}: it curves round the Sun while ${t} moves on. Aimed ${curve}; now time it so the probe meets ${t} at arrival.`
      : `A launch straight at the ring cuts across the orbits: it curves round the Sun. Aimed ${curve} there; change the speed (or wait) until the probe’s last dot is in the ring.`;
    aimNoteUntil = performance.now() + 6000;
    aiming = -1;
    updateStatus(true);
    return;
  }
  const [x, y] = app.toNdc(clientX, clientY);
  ndc.set(x, y);
  raycaster.setFromCamera(ndc, app.camera);
  if (!raycaster.ray.intersectPlane(ecliptic, hitPoint)) return;
  const earthI = SOLAR_SYSTEM_BODIES.indexOf('Earth');
  // The pointer's direction from the Earth on the display, back to a heliocentric direction.
  const ex = shown[3 * earthI]!,
    ez = shown[3 * earthI + 2]!;
  heliocentricState(shell.world, handles, handles.bodies.Earth, earthHelio);
  if (Math.hypot(hitPoint.x - ex, hitPoint.z - ez) < 1e-6) return;
  // The pointer's direction on the display, back through the display's local stretch at the Earth
  // (the inverse of displayDirection: radially by the slope of the compressed radius, sideways by
  // its ratio), so the arrow drawn points at the pointer on the screen.
  const sx = (hitPoint.x - ex) / UNITS_PER_AU,
    sz = (hitPoint.z - ez) / UNITS_PER_AU;
  const rn = Math.hypot(earthHelio[0]!, earthHelio[2]!);
  const rho = displayRadius(rn, trueScale);
  const drho = (displayRadius(rn * (1 + 1e-6), trueScale) - rho) / (1e-6 * rn);
  const ux = earthHelio[0]! / rn,
    uz = earthHelio[2]! / rn;
  const radial = sx * ux + sz * uz;
  const dx = (radial * ux) / drho + ((sx - radial * ux) * rn) / rho,
    dz = (radial * uz) / drho + ((sz - radial * uz) * rn) / rho;
  const p = launchDirection(earthHelio, 0, [0, 0, 0]),
    o = launchDirection(earthHelio, 90, [0, 0, 0]);
  const angle = (Math.atan2(dx * o[0]! + dz * o[2]!, dx * p[0]! + dz * p[2]!) * 180) / Math.PI;
  aim.angle = Math.round(angle) === -180 ? 180 : Math.round(angle);
  aimChangedAt = performance.now();
}
let aiming = -1;
app.canvas.addEventListener('pointerdown', (e) => {
  if (e.button !== 0 || !e.isPrimary) return;
  aiming = e.pointerId;
  aimAtPointer(e.clientX, e.clientY, true);
});
app.canvas.addEventListener('pointermove', (e) => {
  if (e.pointerId === aiming) aimAtPointer(e.clientX, e.clientY);
});
for (const type of ['pointerup', 'pointercancel'] as const)
  app.canvas.addEventListener(type, (e) => {
    if (e.pointerId === aiming) aiming = -1;
  });

// ---- Status: the mission, the plan or the flight, the date; the on-screen buttons --------------------

/**
 * The header's (status's) one height, CSS: on a desktop (over 440 px wide) 6 + 4 px of padding and
 * the goal's line (15 px type), the brief's (13 px), two lines for the plan (14 px), the date's (13
 * px) and three lines for the hint (14 px, last); on a phone the goal (14 px), four 13 px lines for the brief or the
 * hint in its place, three for the plan, and the date (12 px). Lines 1.4 x their type. The header
 * kept its tallest height so far: it grew from 107 to 146 px on a desktop and from 116 to 174 px on
 * a phone in the first two missions, and the map moved down each time.
 */
const STATUS_ROW = {
  wide: `${10 + 1.4 * (15 + 13 + 5 * 14 + 13)}px`,
  phone: `${10 + 1.4 * (14 + 7 * 13 + 12)}px`,
} as const;
const style = document.createElement('style');
style.textContent = `
/* The header's row has one fixed height (STATUS_ROW: each line's slot its lines tall, whatever it
   says), so the map under it never moves; a text longer than its slot (a long hint on a phone) draws
   the status on down over the map's top, on its own backing, rather than push the map down. */
.ss-status-row { position: relative; z-index: 4; overflow: visible; height: ${STATUS_ROW.wide}; }
.ss-status { position: absolute; left: 0; right: 0; top: 0; min-height: 100%; background: inherit; box-sizing: border-box; text-align: center; font: 13px/1.4 system-ui, sans-serif; color: #e8ecf1; padding: 6px 10px 4px; display: flex; flex-direction: column; justify-content: flex-start; }
.ss-status .ss-goal { font-weight: 700; color: #ffe066; font-size: 14px; }
.ss-status .ss-stars { color: #ffd166; letter-spacing: 1px; }
.ss-status .ss-brief { color: #cfd8e6; font-size: 12px; min-height: 1.4em; }
.ss-status .ss-line.ok { color: #7ee787; }
.ss-status .ss-line.bad { color: #ffb4a8; }
.ss-status .ss-line.edge { color: #ffd479; }
.ss-status .ss-line.won { color: #7ee787; font-weight: 700; }
.ss-status .ss-date { color: #b8c4d6; font-size: 12px; }
/* The hint's line is kept (empty) when the hint is off, so pressing Hint does not move the stage. */
.ss-status .ss-hint { color: #9fd3ff; font-weight: 600; min-height: 4.2em; }
.ss-status .ss-line { min-height: 2.8em; }
/* A desktop: 14 px lines at most 760 px long (a 1,000 px line at 13 px was hard to follow). */
@media (min-width: 441px) {
  .ss-status { font-size: 14px; }
  .ss-status .ss-goal { font-size: 15px; }
  .ss-status .ss-brief, .ss-status .ss-date { font-size: 13px; }
  .ss-status > div { max-width: 760px; margin: 0 auto; }
  /* The date under the plan, the hint's room (empty until asked for) last, at the header's foot. */
  .ss-status .ss-date { order: 1; }
  .ss-status .ss-hint { order: 2; }
}
.ss-pad button.ss-hint-button.ss-pulse { animation: ss-pulse 1.2s ease-in-out infinite; }
.ss-arrival { position: absolute; z-index: 3; left: 0; right: 0; top: 4%; padding: 10px 0; text-align: center;
  background: radial-gradient(ellipse at center, rgba(2, 3, 8, 0.75), rgba(2, 3, 8, 0) 70%); font: 700 28px system-ui, sans-serif;
  color: #ffe066; text-shadow: 0 0 12px rgba(0, 0, 0, 0.9), 0 0 24px rgba(255, 224, 102, 0.5); animation: ss-rise 0.5s ease-out; }
.ss-arrival .ss-arrival-stars { font-size: 44px; letter-spacing: 6px; }
.ss-arrival .ss-arrival-stars span { display: inline-block; animation: ss-star-pop 0.45s ease-out backwards; }
.ss-arrival .ss-arrival-stars span.off { color: #4a5568; }
.ss-arrival.ss-low { top: auto; bottom: 4%; }
@keyframes ss-rise { from { transform: translateY(20px); opacity: 0; } }
@keyframes ss-star-pop { from { transform: scale(0.1) rotate(-40deg); opacity: 0; } 70% { transform: scale(1.4); } }
@keyframes ss-pulse { 50% { box-shadow: 0 0 0 4px rgba(159, 211, 255, 0.55); } }
.ss-pad button { min-width: 48px; }
.ss-pad button.ss-go { background: #1f7a3a; border-color: #7ee2a0; min-width: 76px; }
/* One order in every phase: the aim or burn buttons, then Launch, Abort or Try again in one slot,
   Wait or Next mission in the next, Hint last (Wait moved a slot when Abort took Launch's place). */
.ss-pad button[data-pad="launch"], .ss-pad button[data-pad="abort"], .ss-pad button[data-pad="retry"] { order: 5; }
.ss-pad button[data-pad="wait"], .ss-pad button[data-pad="next"] { order: 6; }
.ss-pad button[data-pad="hint"] { order: 7; }
/* A 390 px phone: every phase's buttons (seven at most) on one row of equal cells, each at least
   44 x 44 px; a longer label ("+ fast", "Try again") breaks inside its button, not the row, so the
   buttons never wrap to a second row and move under the finger. */
@media (max-width: 440px) {
  .ss-status-row { height: ${STATUS_ROW.phone}; }
  /* The brief shows on a phone too, so the first mission's is seen: two 13 px lines kept for it (the
     briefs are two; four, the longest hints', left a 36 px empty band over the plan); the hint
     that takes its place four, the plan's three. */
  .ss-status .ss-brief { min-height: ${2 * 1.4 * 13}px; }
  .ss-status .ss-hint { min-height: ${4 * 1.4 * 13}px; }
  .ss-status .ss-line { min-height: ${3 * 1.4 * 13}px; }
  .bp-touchbar.ss-pad { display: grid; grid-auto-flow: column; grid-auto-columns: auto; justify-content: stretch; gap: 4px; }
  .bp-touchbar.ss-pad button { min-width: 44px; padding: 0 3px; font-size: 14px; white-space: normal; line-height: 1.05; }
  .bp-touchbar.ss-pad button.ss-go { min-width: 44px; }
  /* The hint takes the brief's slot, over the plan (not laid over the top of the map, on the
     planets; after the plan, the plan's line moved up into the brief's place). */
  .ss-status .ss-hint:empty { display: none; }
  .ss-status .ss-brief, .ss-status .ss-hint { order: 1; }
  .ss-status .ss-line { order: 2; }
  .ss-status .ss-date { order: 3; }
  .ss-status.ss-hinting .ss-brief { display: none !important; }
}
details.ss-table summary { cursor: pointer; color: #cfd8e6; }
`;
document.head.append(style);
const status = document.createElement('div');
status.className = 'ss-status';
status.setAttribute('role', 'status');
const goalLine = document.createElement('div');
goalLine.className = 'ss-goal';
goalLine.dataset.hud = 'goal';
const briefLine = document.createElement('div');
briefLine.className = 'ss-brief';
briefLine.dataset.hud = 'brief';
const planText = document.createElement('div');
planText.className = 'ss-line';
planText.dataset.hud = 'plan';
const hintLine = document.createElement('div');
hintLine.className = 'ss-hint';
hintLine.dataset.hud = 'hint';
const dateText = document.createElement('div');
dateText.className = 'ss-date';
dateText.dataset.hud = 'date';
status.append(goalLine, briefLine, planText, hintLine, dateText);
pageLayout().status.append(status);
pageLayout().status.classList.add('ss-status-row');

const PAD = [
  { label: '↺', name: 'turn the launch left (←)', press: () => turn(-TURN_STEP) },
  { label: '↻', name: 'turn the launch right (→)', press: () => turn(TURN_STEP) },
  { label: '−', name: 'slower launch (↓)', press: () => changeSpeed(-SPEED_STEP) },
  { label: '+', name: 'faster launch (↑)', press: () => changeSpeed(SPEED_STEP) },
] as const;
/** The same four buttons while the probe flies: mid-course burns (./missions.ts burnProbe). */
const BURN_PAD = [
  { label: '◁ in', name: 'burn towards the Sun (←)' },
  { label: 'out ▷', name: 'burn away from the Sun (→)' },
  { label: '− slow', name: 'burn to slow down (↓)' },
  { label: '+ fast', name: 'burn to speed up (↑)' },
] as const;
/** Repeats a held pad button: once at once, then every 70 ms after 350 ms (every 250 ms for burns). */
let repeatTimer = 0;
function holdRepeat(action: () => void): void {
  action();
  window.clearTimeout(repeatTimer);
  const again = (delay: number): void => {
    repeatTimer = window.setTimeout(() => {
      action();
      again(phase === 'flight' ? 250 : 70);
    }, delay);
  };
  again(350);
}
const stopRepeat = (): void => window.clearTimeout(repeatTimer);
/** Whether the hint line shows (the Hint button or H; it stays, worked out again as things change). */
let hinting = false;
/** Whether the Hint button has been used: until then it pulses on the first mission. */
let hintUsed = false;
/** Shows the hint, or works it out again for now if it shows (H, the Hint button). */
function toggleHint(): void {
  hinting = true;
  hintUsed = true;
  adviceKey = '';
  updateStatus(true);
}
const pad = createButtonBar(
  [
    ...PAD.map((b) => ({ label: b.label, name: b.name, onPress: () => holdRepeat(b.press), onRelease: stopRepeat })),
    { label: 'Launch', name: 'launch the probe (Space)', onTap: () => playerLaunch() },
    {
      label: 'Wait',
      name: 'wait: tap to run to the next launch window, hold to run time (W)',
      onPress: () => pressWait(),
      onRelease: () => releaseWait(),
    },
    { label: 'Abort', name: 'abort the flight: back to the launch', onTap: () => abortTap() },
    { label: 'Try again', name: 'try again from the launch (Enter)', onTap: () => retry() },
    { label: 'Next mission', name: 'next mission (Enter)', onTap: () => advance() },
    { label: 'Hint', name: 'hint: what to try (H)', onTap: () => toggleHint() },
  ],
  { label: 'launch controls', touchOnly: false },
);
pad.element.classList.add('ss-pad');
// The phone's card of gestures over the diagram goes at the first press of a button too (the kit
// hides it at the first touch on the scene, and the buttons are under it).
pad.element.addEventListener('pointerdown', () => document.querySelector('[data-hud="touch-hint"]')?.classList.add('bp-gone'), {
  once: true,
});
pad.buttons[4]!.classList.add('ss-go');
pad.buttons[8]!.classList.add('ss-go');
pad.buttons[9]!.classList.add('ss-hint-button');
pad.buttons.forEach((b, i) => {
  b.dataset.pad = ['left', 'right', 'slower', 'faster', 'launch', 'wait', 'abort', 'retry', 'next', 'hint'][i]!;
});
/** The labels the four aim buttons show now: 'aim' or 'burn'. */
let padLabels: 'aim' | 'burn' = 'aim';
function setPadLabels(which: 'aim' | 'burn'): void {
  if (which === padLabels) return;
  padLabels = which;
  const set = which === 'aim' ? PAD : BURN_PAD;
  set.forEach((b, i) => {
    pad.buttons[i]!.textContent = b.label;
    pad.buttons[i]!.setAttribute('aria-label', b.name);
  });
}

const starText = (n: number): string => '★'.repeat(n) + '☆'.repeat(3 - n);
/**
 * A miss put in words: the closest approach (AU) with enough decimals that it reads as outside the
 * ring's radius `zone` (0.104 against 0.1 must not show as "0.10 ... the ring is 0.1"), after the
 * closest approach `before` a burn changed it, when given ("closest 0.53 → 0.52 AU").
 */
function missWords(closest: number, zone: number, before = Number.NaN): string {
  let digits = 2;
  while (digits < 4 && Number(closest.toFixed(digits)) <= zone) digits++;
  // A burn's change shown with the decimals that tell the two apart (up to 4).
  if (Number.isFinite(before)) while (digits < 4 && before.toFixed(digits) === closest.toFixed(digits)) digits++;
  const was = Number.isFinite(before) ? `${before.toFixed(digits)} → ` : '';
  return `closest ${was}${closest.toFixed(digits)} AU, the ring reaches ${zone} AU`;
}
const aimWords = (a: number): string =>
  Math.abs(a) < 1
    ? 'along the Earth’s path'
    : Math.abs(a) > 179
      ? 'against the Earth’s path'
      : `${Math.abs(Math.round(a))}° ${a > 0 ? 'outwards' : 'inwards'}${Math.abs(a) > 90 ? ' (backwards)' : ''}`;
let shownStatus = '';
/**
 * The hint for a launch whose forecast is nearest `t` at the launch itself (Forecast.closestAtLaunch):
 * at this date the probe only draws away from it, so the launch date, not the speed, is the trouble.
 */
function wrongDate(t: SolarSystemBody): string {
  return `At this date the probe only gets farther from ${t}: tap ${named('W', 'Wait')} to run to the next launch window (or hold it) until ${t}’s dots end where the probe’s do.`;
}

/** Whether the page is used by touch first (a phone): the hints name the buttons, not the keys. */
const touchFirst = matchMedia('(pointer: coarse)').matches;
/** The control a hint names: the key on a desktop, the button on a touch screen. */
const named = (key: string, button: string): string => (touchFirst ? button : key);
const BURN_NAMES: Record<BurnDirection, string> = { faster: '+ fast', slower: '− slow', out: 'out ▷', in: '◁ in' };
const BURN_KEYS: Record<BurnDirection, string> = { faster: '↑', slower: '↓', out: '→', in: '←' };
const BURN_WORDS: Record<BurnDirection, string> = {
  faster: 'faster along its path',
  slower: 'slower along its path',
  out: 'away from the Sun',
  in: 'towards the Sun',
};
/** The hints (./advice.ts), the forecast they were worked out for, and when (performance.now(), ms). */
const aimAdvice = createAimAdvice();
const burnAdvice = createBurnAdvice();
let adviceKey = '',
  adviceClock = -Infinity;
/** performance.now() of the last change of the aim: the launch hint waits until the aim rests. */
let aimChangedAt = -Infinity;
/** How long the aim must rest before the launch hint is worked out again, ms (a search takes up to 0.1 s). */
const HINT_REST_MS = 250;
/** Real time between two burn hints in flight, ms (the burn needed changes as the probe flies). */
const BURN_HINT_MS = 1000;
let hintText = '';

/**
 * What to try now, for the Hint button (./advice.ts): while aiming, the turn or the speed change
 * (or the wait) that makes the launch arrive, in presses; while flying, the burn that brings it into
 * the ring, in presses now. Worked out for the forecast shown once it is for now; '' until then.
 */
function hint(m: Mission): string {
  const world = shell.world;
  if (phase === 'aim') {
    if (forecastKey !== wantedKey() || performance.now() - aimChangedAt < HINT_REST_MS) return '';
    if (!verdictShown()) return readingHint(m);
    if (adviceKey !== forecastKey) {
      adviseAim(world, handles, m, aim, baseStep(), forecast, aimAdvice);
      adviceKey = forecastKey;
    }
    const a = aimAdvice;
    const t = m.target;
    const ahead = `${t} moves while the probe flies: aim where ${t} will be, not where it is.`;
    if (a.kind === 'launch') {
      const s = starsFor(m, aim.speed);
      const more = s < 3 ? ` ${starText(3)} needs ${m.stars3} km/s or less.` : '';
      return `Look where the dots end: if the probe is inside the ring of “${t} at arrival”, ${named('press Space', 'tap Launch')}.${more}`;
    }
    if (a.kind === 'change') {
      if (a.turn !== 0) {
        const cw = a.turn > 0;
        return `${ahead} Try turning the arrow ${cw ? 'clockwise' : 'anticlockwise'} (${named(cw ? '→' : '←', cw ? '↻' : '↺')}) and watch the probe’s last dot.`;
      }
      const up = a.speed > 0;
      const change = up
        ? `A faster launch (${named('↑', '+')}) flies farther ${distanceFromSun(t) > 1 ? 'out' : 'in'} and sooner: watch the probe’s last dot close on the ring.`
        : `A slower launch (${named('↓', '−')}) costs less and arrives later: watch the probe’s last dot close on the ring.`;
      // Nearest at the launch: the date is the trouble, whatever speed happens to catch the planet.
      return forecast.closestAtLaunch ? `${wrongDate(t)} Or: ${change[0]!.toLowerCase()}${change.slice(1)}` : change;
    }
    if (a.kind === 'wait' || a.kind === 'none')
      return forecast.closestAtLaunch
        ? wrongDate(t)
        : `${ahead} Now it is in the wrong place: tap ${named('W', 'Wait')} to run to the next launch window (or hold it) until ${t}’s dots end where the probe’s do, then aim.`;
  }
  if (phase === 'flight' && flight) {
    if (forecastKey !== wantedKey()) return hintText;
    if (adviceKey !== forecastKey || performance.now() - adviceClock > BURN_HINT_MS) {
      adviseBurn(world, handles, flight, forecast, burnAdvice);
      adviceKey = forecastKey;
      adviceClock = performance.now();
    }
    const b = burnAdvice;
    if (b.kind === 'coast') return 'On course for the ring: no burn needed (burns cost stars).';
    if (b.kind === 'empty') return 'No fuel left for burns: the probe coasts. Abort to try the launch again.';
    if (b.kind === 'none') return 'The fuel left cannot bring it into the ring now. Abort to try the launch again.';
    const n = b.presses;
    // One press makes the whole burn (burnPressSize), so the hint cannot expire half done.
    return `${named(`Press ${BURN_KEYS[b.direction]}`, `Tap ${BURN_NAMES[b.direction]}`)} once now: ${(n * BURN_STEP).toFixed(2)} km/s ${BURN_WORDS[b.direction]} in one burn, then it arrives on day ${Math.round(b.forecast.end)}.`;
  }
  return flight?.state === 'arrived'
    ? `Next mission: ${named('Enter', 'tap Next mission')}.`
    : `Try again from the launch: ${named('Enter', 'tap Try again')}.`;
}

/**
 * The hint before the mission's first failed try (`verdictShown`): how to read the map, not what
 * to press: get the probe's dots to the target's orbit, then make its end and the target's meet.
 */
function readingHint(m: Mission): string {
  const t = m.target;
  if (forecast.outcome === 'sun') return `It falls into the Sun: turn the arrow ${named('(← →)', '(↺ ↻)')} along the Earth’s path.`;
  if (pathCrossing(m) < 0)
    return `First get the probe’s dots to ${t}’s orbit: a faster launch ${named('(↑)', '(+)')} flies farther ${m.distance > 1 ? 'out' : 'in'}.`;
  return `${t} moves on while the probe flies: launch when ${t}’s dots end where the probe’s do (${named('↑ ↓ ← →', '+ − ↺ ↻')} move the probe’s end, Wait moves ${t}’s).`;
}

/**
 * The line's end for the forecast shown on `m`, and its class: the forecast's verdict (the flight
 * flown ahead with its own physics, ./forecast.ts; the flight does the same). The ring "at arrival"
 * and the white dot on the map are drawn from the same closest approach, so the line and the map
 * agree: ✓ exactly when the dot is inside the ring. A launch that does not get out (or in) as far as
 * the target will be then says how far it gets; otherwise the line says by how much it misses.
 */
function verdict(m: Mission): [string, string] {
  const f = forecast;
  const scheme = f.scheme === 'rk4' ? '' : ` (forecast with rk4; this flight uses ${f.scheme})`;
  if (phase === 'aim' && !verdictShown()) return reading(m);
  if (f.outcome === 'sun') return [`✗ falls into the Sun${scheme}`, 'bad'];
  if (phase === 'aim') {
    if (f.outcome === 'arrived' && !forecastIsNow()) return staleWords(m.target);
    if (f.outcome === 'arrived')
      return [
        `✓ meets ${m.target} on day ${Math.round(f.end)} · ${starText(skillStars(missionIndex, m, aim.speed, aimDepth(), 0))}${scheme}`,
        'ok',
      ];
    // The target's distance from the Sun when the probe comes closest (not now: it moves meanwhile).
    const rT = Math.hypot(f.targetAt[0]!, f.targetAt[1]!, f.targetAt[2]!);
    const outward = rT > distanceFromSun('Earth');
    if (outward && f.farthest < rT - m.zone)
      return [`✗ goes out only to ${f.farthest.toFixed(2)} AU from the Sun; ${m.target} will be at ${rT.toFixed(2)} AU${scheme}`, 'bad'];
    if (!outward && f.nearest > rT + m.zone)
      return [`✗ falls in only to ${f.nearest.toFixed(2)} AU from the Sun; ${m.target} will be at ${rT.toFixed(2)} AU${scheme}`, 'bad'];
    // Nearest at the launch: say so, or the same distance at every speed reads as a stale forecast.
    const when = f.closestAtLaunch ? ' (at the launch; then only farther)' : '';
    return [`✗ misses ${m.target}: ${missWords(f.closest, m.zone)}${when}${scheme}`, 'bad'];
  }
  if (f.outcome === 'arrived') return [`✓ arrives on day ${Math.round(f.end)}${scheme}`, 'ok'];
  return [`✗ misses ${m.target}: ${missWords(f.closest, m.zone, burnChange())}${scheme}`, 'bad'];
}

/**
 * Whether the forecast shown is of the launch made now: worked out for this moment and aim, with
 * time standing (not paused: a paused clock stands too). While time runs the forecast is of a moment
 * already gone (worked out over frames while the world steps on: 12 days behind at 15 days a
 * second), so its ✓ is not shown: a launch on it missed.
 */
function forecastIsNow(): boolean {
  return forecastKey !== '' && forecastKey === wantedKey() && (shell.paused || currentRate() === 0);
}

/**
 * How far the next launch window of `m`'s target is, for the date line after the player stopped
 * Wait short of it: "Wait stopped · Mars’s next window in 181 days" (a stop there read as a window).
 */
function windowWords(m: Mission): string {
  const n = Math.round(launchWindow().next);
  return `Wait stopped · ${m.target}’s next window in ${n} day${n === 1 ? '' : 's'}`;
}

/** G M_sun in the world now, AU^3/day^2. */
const sunMu = (): number => shell.world.laws.gravitationalConstant * shell.world.components.Mass.value[slotOf(handles.bodies.Sun)]!;
/** The target's heliocentric state when `pathCrossing` was last worked out (for the forecast `crossingKey`). */
const crossingTarget = new Float64Array(6);
let crossingAt = -1,
  crossingKey = '';
/**
 * The point of the forecast's path to compare with the target (./orbit-crossing.ts meetingPoint:
 * of its crossings of the target's orbit line, the one nearest the target that day), -1 when it
 * never gets there or falls into the Sun; worked out once per forecast.
 */
function pathCrossing(m: Mission): number {
  if (crossingKey === forecastKey) return crossingAt;
  heliocentricState(shell.world, handles, handles.bodies[m.target], crossingTarget);
  crossingAt = forecast.outcome === 'sun' ? -1 : meetingPoint(forecast, crossingTarget, sunMu());
  crossingKey = forecastKey;
  return crossingAt;
}

/**
 * The line's end while aiming before the full verdict shows (`verdictShown`: the ring at arrival on
 * the map): what the launch's path does, to read against the map, and its verdict: short of the
 * target's orbit (how far it gets), or the day it meets the orbit line and whether the target is
 * there then (`meetingVerdict`: exact on the first mission, coarse from the second).
 */
function reading(m: Mission): [string, string] {
  const f = forecast;
  if (f.outcome === 'sun') return ['✗ falls into the Sun', 'bad'];
  const i = pathCrossing(m);
  const t = m.target;
  if (i < 0)
    return m.distance > 1
      ? [`✗ goes out only to ${f.farthest.toFixed(2)} AU from the Sun, short of ${t}’s orbit`, 'edge']
      : [`✗ falls in only to ${f.nearest.toFixed(2)} AU from the Sun, short of ${t}’s orbit`, 'edge'];
  // The path crosses the orbit once going out and once coming back in (more on a path that goes
  // round again); the day given is the crossing where the target is then nearest (./orbit-crossing.ts
  // meetingPoint). Each speed moves the target's place on each crossing, so the crossing picked can
  // switch, and the day with it (222 going out at 2.6 km/s, 341 coming in at 2.7): the line names
  // the way the probe goes there and the other crossings' days, so the jump reads as a switch.
  const ways = orbitCrossings(f, crossingTarget, sunMu(), crossingList).map((k) => ({
    k,
    day: Math.round(pathDay(f, k)),
    way: crossingWay(f, k, true),
  }));
  const day = Math.round(pathDay(f, i));
  const others = ways.filter((c) => c.k !== i).map((c) => `day ${c.day} ${c.way}`);
  const which = ` ${crossingWay(f, i, crossingList.includes(i))}`;
  // Short enough for the line to stay on one line at desktop size.
  const also = others.length > 0 ? ` (${others.join(', ')}, ${t} farther then)` : '';
  const [judged, cls] = meetingVerdict(m, i);
  return [`is at ${t}’s orbit on day ${day}${which}${also}. ${judged}`, cls];
}

/**
 * The reading line's verdict on the meeting at point `i` of the forecast's path (`pathCrossing`),
 * ./meeting-words.ts: on an arrival "✓ Mars will be there" and the stars on every mission, as the
 * flight will say (while time runs, `staleWords` instead: the forecast is of a moment gone); on a
 * miss, exact on the first mission (by how many days the target misses the probe there,
 * ./orbit-crossing.ts targetLag), coarse from the second on, from the flight's real closest
 * approach ("Venus will be close", "a little behind", "far ahead": forecastWords).
 */
function meetingVerdict(m: Mission, i: number): [string, string] {
  if (forecast.outcome === 'arrived' && !forecastIsNow()) return staleWords(m.target);
  if (missionIndex > 0)
    return forecastWords(m.target, forecast, m.zone, crossingTarget, starText(skillStars(missionIndex, m, aim.speed, aimDepth(), 0)));
  const lag = targetLag(forecast, i, crossingTarget, sunMu());
  const arrived = forecast.outcome === 'arrived';
  return meetingWords(m.target, lag, arrived, starText(starsFor(m, aim.speed)), missWords(forecast.closest, m.zone));
}
/** The path's crossings of the target's orbit (`reading`), indices into the forecast's path. */
const crossingList: number[] = [];
/**
 * Which way the probe goes at point `k` of the forecast's path across the target's orbit line
 * (`crossingTarget`, as `pathCrossing` last set it): at a crossing (`crossed`: the point just past
 * the line) 'going out' when it is outside the line there, else 'coming in'; at a point short of the
 * line (an arrival inside the ring before the line), the other way: outside it is still to come in.
 * Read from the side of the line, not from the Sun distance rising: near the far end of its path the
 * probe's distance barely changes while the (elliptic) orbit's radius does.
 */
function crossingWay(f: typeof forecast, k: number, crossed: boolean): string {
  const p = f.path;
  const x = p[3 * k]!,
    y = p[3 * k + 1]!,
    z = p[3 * k + 2]!;
  const outside = Math.hypot(x, y, z) >= orbitRadiusToward(crossingTarget, sunMu(), x, y, z);
  return outside === crossed ? 'going out' : 'coming in';
}

/** The simulated days per real second measured over the last second or so (eased), and the last sample: world time (days) and real time (ms). */
const measured = { rate: Number.NaN, time: Number.NaN, real: Number.NaN };
/**
 * The rate the status line shows, days per real second: `asked` while the page keeps up, else what
 * time really runs at (measured from the world's time and the clock, eased over about a second). A
 * page drawing few frames runs fewer steps than asked, and the line said "40 days a second" all
 * the same. 0 when `asked` is 0.
 */
function shownRate(time: number, asked: number): number {
  const real = performance.now();
  const dt = (real - measured.real) / 1000;
  if (asked === 0 || !(dt > 0) || dt > 1 || !(time >= measured.time)) measured.rate = Number.NaN;
  else if (dt > 0.02) {
    const sample = (time - measured.time) / dt;
    const k = Math.min(1, dt);
    measured.rate = Number.isFinite(measured.rate) ? measured.rate + k * (sample - measured.rate) : sample;
  } else return !Number.isFinite(measured.rate) || measured.rate > 0.85 * asked ? asked : measured.rate;
  measured.time = time;
  measured.real = real;
  // Within 15 % of the rate asked it is the rate asked (a frame's jitter is not news).
  return !Number.isFinite(measured.rate) || measured.rate > 0.85 * asked ? asked : measured.rate;
}

function updateStatus(force = false): void {
  const m = mission();
  const world = shell.world;
  const total = best.reduce((s, n) => s + n, 0);
  // The goal, and the forecast's verdict: what the launch (or the flight) will do. What to change
  // is the player's to work out (the Hint button says, on request).
  const goal = `Mission ${missionIndex + 1}/${MISSIONS.length}: fly to ${m.target} · ★★★ ≤ ${m.stars3} km/s`;
  let line = '',
    cls = '';
  if (phase === 'aim') {
    const head = `Launch ${aim.speed.toFixed(1)} km/s ${aimWords(aim.angle)} →`;
    // The speed and direction read at once; a new aim's words read "…" until its forecast is
    // worked out and drawn (the last aim's words under the new speed named a day not its own).
    const stale = keyBase(forecastKey) !== keyBase(wantedKey());
    if (forecastKey === '' || stale) line = `${head} …`;
    else if (forecastKey !== drawnForecastKey && shownPlan[0] !== '')
      [line, cls] = shownPlan[0].startsWith(`${head} `) ? shownPlan : [`${head} …`, ''];
    else {
      const [words, c] = verdict(m);
      line = `${head} ${words}`;
      cls = c;
    }
    shownPlan = [line, cls];
  } else if (phase === 'flight' && flight) {
    const P = world.components.Position;
    const t = slotOf(handles.bodies[m.target]),
      p = slotOf(flight.probe);
    const d = Math.hypot(P.x[t]! - P.x[p]!, P.y[t]! - P.y[p]!, P.z[t]! - P.z[p]!);
    const fuel = `fuel ${(CORRECTION_FUEL - flight.fuelUsed).toFixed(2)} km/s`;
    const [words, c] = verdict(m);
    line = `Day ${Math.round(flight.elapsed)} · ${d.toFixed(2)} AU to ${m.target} · ${words} · ${fuel}`;
    cls = c;
  } else if (phase === 'done' && flight) {
    const burns = flight.fuelUsed > 0 ? ` + ${flight.fuelUsed.toFixed(2)} km/s of burns` : '';
    if (flight.state === 'arrived') {
      const s = skillStars(missionIndex, m, flight.aim.speed + flight.fuelUsed, launchRings, flight.burns);
      const why =
        missionIndex > 0 && s === 2 && starsFor(m, flight.aim.speed + flight.fuelUsed) === 3
          ? ', a centred launch with no burn earns ★★★'
          : '';
      line = `✓ Arrived at ${m.target} after ${Math.round(flight.elapsed)} days! ${starText(s)} (${flight.aim.speed.toFixed(1)} km/s launch${burns}; 3 stars up to ${m.stars3} km/s in all${why})`;
      if (best.every((b) => b > 0)) line += ` · All missions flown: ${total} of ${3 * MISSIONS.length} stars`;
      cls = 'won';
    } else if (flight.state === 'sun') {
      line = '✗ The probe fell into the Sun.';
      cls = 'bad';
    } else {
      line = `✗ Missed ${m.target}: ${missWords(flight.closest, m.zone)}.`;
      cls = 'bad';
    }
  }
  // The hint, worked out again (./advice.ts) when what it is for has changed.
  if (hinting) hintText = hint(m) || (phase === 'aim' ? 'Hint: working it out…' : hintText);
  const date = new Date(handles.epoch + world.time * 86_400_000).toISOString().slice(0, 10);
  // Paused, no days run whatever rate is set: the line says so, not the rate set ("11 days a second").
  const rate = shell.paused ? 0 : shownRate(world.time, currentRate());
  const stars = `Stars ${total} / ${3 * MISSIONS.length}`;
  const atTheWindow = phase === 'aim' && Math.abs(world.time - atWindow) < 1;
  const stoppedShort = phase === 'aim' && !atTheWindow && Math.abs(world.time - waitStoppedAt) < 1e-9 ? windowWords(m) : '';
  const clock = shell.paused
    ? atTheWindow
      ? `launch window for ${m.target}: aim ahead of it (paused)`
      : 'paused'
    : rate === 0
      ? phase === 'aim'
        ? atTheWindow
          ? `launch window for ${m.target}: aim ahead of it`
          : stoppedShort !== ''
            ? stoppedShort
            : // The first mission's lesson launches now; from the second on the window is the first step.
              missionIndex === 0
              ? 'time waits while you aim'
              : `time waits: tap ${named('W', 'Wait')} for the next launch window`
        : 'time stopped'
      : `${rate < 10 ? rate.toFixed(1) : Math.round(rate)} days a second${wait.mode === 'off' ? '' : windowNearness < NEAR_WINDOW_DAYS ? ` (near ${m.target}’s window)` : wait.mode === 'run' ? ` (to ${m.target}’s launch window)` : ' (waiting)'}`;
  const dateLine = `${date} · ${clock} · ${stars}`;
  const shownHint = hinting ? hintText : '';
  // In flight, what the four buttons (keys) do then, while there is fuel: they burn.
  const flying = `Burns (${named('← → ↑ ↓', '◁ ▷ − +')}) bend the path onto ${m.target}’s ring`;
  const brief =
    phase === 'aim'
      ? performance.now() < aimNoteUntil
        ? aimNote
        : m.brief
      : phase === 'done'
        ? doneNote
        : flight && flight.fuelUsed < CORRECTION_FUEL
          ? flying
          : '';
  const key = `${goal}|${brief}|${line}|${cls}|${dateLine}|${phase}|${shownHint}`;
  if (!force && key === shownStatus) return;
  shownStatus = key;
  goalLine.textContent = goal;
  briefLine.textContent = brief;
  planText.textContent = line;
  planText.className = `ss-line ${cls}`;
  hintLine.textContent = shownHint;
  status.classList.toggle('ss-hinting', shownHint !== '');
  dateText.textContent = dateLine;
  const aimingNow = phase === 'aim';
  setPadLabels(phase === 'flight' ? 'burn' : 'aim');
  for (let i = 0; i < 4; i++) pad.show(i, phase !== 'done');
  pad.show(4, aimingNow);
  pad.show(5, phase !== 'done');
  pad.show(6, phase === 'flight');
  pad.show(7, phase === 'done');
  pad.show(8, phase === 'done' && flight?.state === 'arrived');
  // A tap's run shows on the Wait button, which stops it ("Stop").
  pad.setActive(5, waiting || wait.mode === 'run');
  const waitLabel = phase === 'aim' && wait.mode === 'run' && !waiting ? 'Stop' : 'Wait';
  if (pad.buttons[5]!.textContent !== waitLabel) pad.buttons[5]!.textContent = waitLabel;
  pad.setActive(9, hinting);
  pad.buttons[9]!.classList.toggle('ss-pulse', missionIndex === 0 && !hintUsed);
}

// ---- The result card: stars, score and the way on, over the scene after each flight ----------------

/** What the last arrival earned (null after a miss): shown on the result card. */
let lastResult: { stars: number; score: ReturnType<typeof missionScore>; record: boolean; before: number } | null = null;
/** Real time between the end of a flight and its card, ms: the arrival's flash and banner show first. */
const CARD_DELAY_MS = 900;
/** The same after an arrival, ms: the flash, then the stars earned over the scene. */
const ARRIVAL_CARD_DELAY_MS = 1800;
/**
 * The arrival's banner over the scene ("Mars reached!" and the stars, popping in one by one) until
 * the card shows; near the top or the foot of the view (`placeArrivalBanner`), clear of the Sun and
 * its name at the view's centre.
 */
const arrivalBanner = document.createElement('div');
arrivalBanner.dataset.hud = 'arrival-banner';
arrivalBanner.className = 'ss-arrival';
arrivalBanner.hidden = true;
labelLayer.append(arrivalBanner);
// The result card is game-kit's; these are the styles of the solar system's own lines in it.
const cardStyle = document.createElement('style');
cardStyle.textContent = `
.ss-card .ss-card-score { font-size: 22px; font-weight: 700; color: #ffffff; margin: 4px 0 0; }
.ss-card .ss-card-record { color: #7ee787; font-weight: 700; }
.ss-card .ss-card-small { color: #c3cedf; font-size: 13px; }
.ss-card .ss-card-parts { display: grid; grid-template-columns: 1fr auto; gap: 0 10px; text-align: left; margin: 6px 4px; font-size: 13px; color: #d6deea; }
.ss-card .ss-card-parts b { text-align: right; color: #ffffff; }
.ss-card .ss-card-map { display: flex; justify-content: center; gap: 4px; flex-wrap: wrap; margin: 8px 0 4px; }
.ss-card .ss-card-map button { padding: 1px 6px; border-radius: 6px; background: #1a2336; color: #d6deea; font: inherit; font-size: 12px; border: 1px solid #2c3a55; cursor: pointer; min-height: 28px; }
.ss-card .ss-card-map button.now { border-color: #ffe066; color: #ffe066; }
.ss-card .ss-card-map i { font-style: normal; color: #ffd166; }
.ss-card .ss-card-next { color: #9fd3ff; font-size: 13px; margin: 4px 0 0; }
`;
document.head.append(cardStyle);
/** The result card (game-kit's): its ✕ hides it to see the map; Enter and T are the game's keys. */
const card = createDomResultCard(pageLayout().stage, {
  name: 'result-card',
  className: 'ss-card',
  ariaLabel: 'flight result',
  width: 'min(380px, calc(100% - 24px))',
  accent: '#ffe066',
  lostColour: '#ffb4a8',
  primaryColours: { background: '#1f7a3a', text: '#ffffff', border: '#7ee2a0' },
  close: { ariaLabel: 'hide the result to see the map', onClose: () => hideCard() },
});
let cardTimer = 0;

/** A new element of `tag` with class `cls` and text `text` in `parent`. */
function put(parent: HTMLElement, tag: string, cls: string, text = ''): HTMLElement {
  const e = document.createElement(tag);
  if (cls) e.className = cls;
  e.textContent = text;
  parent.append(e);
  return e;
}

/**
 * Puts the arrival banner near the top of the view or near its foot, whichever covers fewer of the
 * names shown (at the top it hid Jupiter's when Jupiter was there; in the middle, the Sun's).
 */
function placeArrivalBanner(): void {
  const covered = (): number => {
    // The banner spans the view's width; its words and stars, centred, about 440 px of it.
    const b = arrivalBanner.getBoundingClientRect(),
      mid = (b.left + b.right) / 2,
      half = Math.min(b.width, 440) / 2;
    let n = 0;
    for (const el of Object.values(labels)) {
      const r = el.getBoundingClientRect();
      if (r.width > 0 && r.bottom > b.top && r.top < b.bottom && r.right > mid - half && r.left < mid + half) n++;
    }
    return n;
  };
  arrivalBanner.classList.remove('ss-low');
  const high = covered();
  if (high === 0) return;
  arrivalBanner.classList.add('ss-low');
  if (covered() >= high) arrivalBanner.classList.remove('ss-low');
}

/** Hides the result card (a new flight, a retry, another mission, or the ✕ to see the map). */
function hideCard(): void {
  window.clearTimeout(cardTimer);
  arrivalBanner.hidden = true;
  card.hide();
}

/**
 * Why flight `f` (not arrived) failed, from its flown path (the trail) against the target's orbit at
 * the launch (the one the map drew and the forecast read, ./orbit-crossing.ts orbitReach), and what
 * to change: a path that never reached the orbit wants more speed, one that reached it came at the
 * wrong time (wait, or turn).
 */
function missAdvice(f: Flight, short = false): string {
  const m = f.mission;
  if (f.state === 'sun')
    return short
      ? 'Launch slower against the Earth’s path, or turn it outwards.'
      : 'It fell into the Sun: launch slower against the Earth’s path, or turn it more outwards.';
  const outward = m.distance > 1;
  const reach = orbitReach(trail, trailCount, launchTarget, sunMu(), m.zone, outward);
  const t = m.target;
  if (short)
    return reach.reached
      ? `It got to ${t}’s orbit at the wrong moment: wait, or turn the launch.`
      : `Launch faster${outward ? '' : ' against the Earth’s path'}: it stopped short of ${t}’s orbit.`;
  if (!reach.reached && outward)
    return `It turned back ${reach.r.toFixed(2)} AU from the Sun, short of ${t}’s orbit there (${reach.orbit.toFixed(2)} AU): launch faster.`;
  if (!reach.reached)
    return `It fell in only to ${reach.r.toFixed(2)} AU from the Sun, short of ${t}’s orbit there (${reach.orbit.toFixed(2)} AU): launch faster against the Earth’s path.`;
  const near2 = missWords(f.closest, m.zone);
  return `It crossed ${m.target}’s orbit when ${m.target} was elsewhere (${near2}): wait for a better moment, turn the launch, or burn on the way.`;
}

/**
 * Fills the result card for `f` (ended) and shows it CARD_DELAY_MS later: on an arrival the stars,
 * the score in parts, the best, every mission's stars, the next mission and its brief, Try again
 * (T) and Next mission (Enter); after a miss, how near it came and Try again (Enter).
 */
function showCard(f: Flight): void {
  hideCard();
  const m = f.mission;
  const won = f.state === 'arrived' && lastResult;
  const lines: (string | ResultCardLine | Node)[] = [];
  const small = (text: string): ResultCardLine => ({ text, className: 'ss-card-small' });
  const buttons: ResultCardButton[] = [];
  const button = (label: string, name: string, go: boolean, act: () => void): void => {
    buttons.push({ label, ariaLabel: name, action: go ? 'go' : 'retry', primary: go, onPress: act });
  };
  if (won) {
    const r = lastResult!;
    lines.push({ text: `${r.score.total} points`, className: 'ss-card-score' });
    lines.push(
      r.record
        ? { text: r.before > 0 ? `New best! (was ${r.before})` : 'First arrival!', className: 'ss-card-record' }
        : small(`Best ${bestScore[missionIndex]}`),
    );
    const parts = document.createElement('div');
    parts.className = 'ss-card-parts';
    const spent = f.aim.speed + f.fuelUsed;
    put(parts, 'span', '', `Speed spent ${spent.toFixed(2)} km/s${f.fuelUsed > 0 ? ` (${f.fuelUsed.toFixed(2)} in burns)` : ''}`);
    put(parts, 'b', '', `${r.score.budget}`);
    put(parts, 'span', '', `Flight ${Math.round(f.elapsed)} days`);
    put(parts, 'b', '', `${r.score.time}`);
    put(parts, 'span', '', launches <= 1 ? 'Arrived at the first launch' : `Arrived at launch ${launches}`);
    put(parts, 'b', '', `${r.score.tries}`);
    lines.push(
      parts,
      small(
        r.stars < 3
          ? spent <= m.stars3 + 1e-9
            ? '★★★ also wants a launch centred on the ring (the line before it reads ★★★) and no burn: aim again.'
            : `★★★ needs ${m.stars3} km/s or less in all: hold Wait for a cheaper moment, then aim again.`
          : 'Fewer km/s or a quicker flight scores more: a better moment may be cheaper.',
      ),
    );
  } else {
    lines.push(
      small(missAdvice(f)),
      small(
        verdictShown()
          ? `Stuck? ${named('Press H', 'Tap Hint')} for what to change.`
          : `From now on the map shows where ${m.target} will be when the probe comes closest, and ${named('H', 'Hint')} says what to change.`,
      ),
    );
  }
  const sum = bestScore.reduce((a, b) => a + b, 0);
  if (sum > 0)
    lines.push(small(`All missions: ${best.reduce((a, b) => a + b, 0)} of ${3 * MISSIONS.length} stars · best scores ${sum} in all`));
  const map = document.createElement('div');
  map.className = 'ss-card-map';
  MISSIONS.forEach((x, i) => {
    // Each mission's tag is a button that flies it (it looked like one and did nothing).
    const chip = put(map, 'button', i === missionIndex ? 'now' : '', `${i + 1} ${x.target} `) as HTMLButtonElement;
    chip.type = 'button';
    chip.title = `Fly mission ${i + 1}: ${x.target}`;
    chip.addEventListener('click', () => startMission(i));
    put(chip, 'i', '', best[i]! > 0 ? '★'.repeat(best[i]!) : '–');
  });
  lines.push(map);
  if (won) {
    const next = MISSIONS[(missionIndex + 1) % MISSIONS.length]!;
    lines.push({
      text:
        missionIndex + 1 < MISSIONS.length
          ? `Next: ${next.target}. ${next.brief}`
          : `All seven flown: ${best.reduce((a, b) => a + b, 0)} of ${3 * MISSIONS.length} stars. Next: Mars again, to beat your scores.`,
      className: 'ss-card-next',
    });
    button(named('Try again (T)', 'Try again'), 'try again from the launch (T)', false, () => retry());
    button(named('Next mission (Enter)', 'Next mission'), 'next mission (Enter)', true, () => advance());
  } else button(named('Try again (Enter)', 'Try again'), 'try again from the launch (Enter)', true, () => retry());
  const content: DomResultCardContent = {
    title: won ? `${m.target} reached!` : f.state === 'sun' ? 'The probe fell into the Sun' : `Missed ${m.target}`,
    stars: won ? { earned: lastResult!.stars, outOf: 3 } : undefined,
    lost: !won,
    lines,
    buttons,
  };
  const ended = f;
  // An arrival gets its moment: the flash at the planet, then the stars one by one over the scene.
  if (won && lastResult) {
    arrivalBanner.replaceChildren();
    put(arrivalBanner, 'div', '', `${m.target} reached!`);
    const row = put(arrivalBanner, 'div', 'ss-arrival-stars');
    for (let i = 0; i < 3; i++) {
      const star = put(row, 'span', i < lastResult.stars ? '' : 'off', i < lastResult.stars ? '★' : '☆');
      star.style.animationDelay = `${300 + 250 * i}ms`;
      if (i < lastResult.stars) window.setTimeout(() => sound.chime(880 * 1.26 ** i, 0.25), 300 + 250 * i);
    }
    arrivalBanner.hidden = false;
    placeArrivalBanner();
  }
  cardTimer = window.setTimeout(
    () => {
      arrivalBanner.hidden = true;
      if (phase === 'done' && flight === ended) card.show(content);
    },
    won ? ARRIVAL_CARD_DELAY_MS : CARD_DELAY_MS,
  );
}

// ---- The engineer's comparison with the ephemeris (folded) ------------------------------------------

const table = document.createElement('details');
table.className = 'bp-hud ss-table';
table.dataset.hud = 'ephemeris';
const summary = table.appendChild(document.createElement('summary'));
summary.textContent = 'Accuracy against the real ephemeris';
const tableBody = table.appendChild(document.createElement('div'));
tableBody.style.whiteSpace = 'pre-line';
const rows = Object.fromEntries(SOLAR_SYSTEM_PLANETS.map((p) => [p, table.appendChild(document.createElement('div'))]));
pageLayout().side.append(table);
table.addEventListener('toggle', () => updateTable());
const errors = new Float64Array(SOLAR_SYSTEM_PLANETS.length);
let tableFrame = 0;

function updateTable(): void {
  const world = shell.world;
  const date = new Date(handles.epoch + world.time * 86_400_000);
  tableBody.textContent = `Position error |r − r_ephemeris| / |r_ephemeris| against astronomy-engine, heliocentric (floor of this point-mass model after a year in brackets).\n${date.toISOString().slice(0, 16).replace('T', ' ')} UTC · day ${world.time.toFixed(1)} since the start\n${params.integrator}, steps of ${params.step} h at most`;
  solarSystemErrors(world, handles, errors);
  SOLAR_SYSTEM_PLANETS.forEach((p, i) => {
    rows[p]!.textContent = `${p.padEnd(8)} ${errors[i]!.toExponential(2)}  (${SOLAR_SYSTEM_FLOOR[p].toExponential(1)})`;
  });
}

function setRate(days: number): void {
  params.rate = Math.min(400, Math.max(0, days < 0.05 ? 0 : Math.round(days * 100) / 100));
  panel.refresh();
}

const MISSION_CHOICES = MISSIONS.map((_, i) => String(i + 1));
const panel = createPanel(
  params,
  [
    {
      type: 'choice',
      key: 'mission',
      label: 'mission',
      options: Object.fromEntries(MISSIONS.map((m, i) => [`${i + 1}: ${m.target}`, MISSION_CHOICES[i]!])),
      onChange: (n) => startMission(Number(n) - 1),
    },
    { type: 'slider', key: 'rate', label: 'time while aiming (days/s; [ ])', min: 0, max: 400, step: 0.5 },
    {
      type: 'choice',
      key: 'distances',
      label: 'distances (D)',
      options: ['compressed', 'true'],
      onChange: (d) => setDistances(d as 'compressed' | 'true'),
    },
    { type: 'checkbox', key: 'exaggerate', label: 'exaggerated sizes (E)' },
    { type: 'button', key: 'missionView', label: 'view the mission (3)' },
    { type: 'button', key: 'inner', label: 'view the inner planets (1)' },
    { type: 'button', key: 'all', label: 'view all eight planets (2)' },
    { type: 'choice', key: 'step', label: 'longest step (hours)', options: STEPS, onChange: () => restartMission() },
    { type: 'choice', key: 'integrator', label: 'integrator', options: INTEGRATOR_NAMES, onChange: () => restartMission() },
    {
      type: 'text',
      key: 'date',
      label: 'start date (UTC)',
      onChange: () => {
        try {
          startMs = parseDate(params.date);
          resetWorld();
          startMission(missionIndex);
        } catch (error) {
          shell.hud.showError(String((error as Error).message));
        }
      },
    },
    { type: 'button', key: 'reset', label: 'restart the mission' },
  ],
  { title: 'Solar system' },
);
// The keys left out of the legend, said once under the panel's controls.
{
  const note = document.createElement('p');
  note.dataset.hud = 'more-keys';
  note.style.cssText = 'margin: 6px 8px 8px; font: 12px/1.4 system-ui, sans-serif; color: #cfd8e6';
  note.textContent =
    'More keys: Enter next mission / try again; T try again; [ ] time slower / faster; 1 2 3 views; D distances; E sizes. Right-drag turns the view, the wheel zooms.';
  panel.gui.domElement.append(note);
}
// A new world: fresh orbits (the forecast's key names the world); the player's R restarts the mission.
shell.onWorldChange(() => {
  orbitsAt = -Infinity;
  hideCard();
  if (!ownReset) playerReset();
});
// A reload goes on where the player was (./resumeMission); ?mission= picks one.
if (!search.has('mission')) missionIndex = resumeMission();
startMission(missionIndex);

shell.expose({
  params,
  panel,
  /** Entities by name. */
  bodies: () => handles.bodies,
  /** Each planet's relative error against the ephemeris now, by name. */
  errors: (): Record<string, number> => {
    solarSystemErrors(shell.world, handles, errors);
    return Object.fromEntries(SOLAR_SYSTEM_PLANETS.map((p, i) => [p, errors[i]!]));
  },
  /** Days per real second time runs at now, and real ms since the last burn (Infinity: none). */
  rate: () => ({ days: currentRate(), sinceBurn: performance.now() - lastBurn }),
  /**
   * A burn's feedback as last drawn: whether the flame shows at the probe, whether the course before
   * the burn shows as dim dots, and how many of them.
   */
  burnLook: () => ({ flame: flame.visible, ghost: burnGhost.visible, ghostDots: burnGhost.geometry.drawRange.count }),
  /** Sets the aiming rate, simulated days per real second, clamped to [0, 400]. */
  setRate,
  /** Runs time to the next launch window and stops there (not the player's Wait, which never stops there). */
  waitForWindow,
  /** A body's heliocentric state now: position (AU) then velocity (AU/day), six numbers. */
  heliocentric: (name: SolarSystemBody): number[] => [...heliocentricState(shell.world, handles, handles.bodies[name])],
  /** Orbit lines drawn (one a planet). */
  orbitCount: (): number => orbitsDrawn,
  /** Labels the last frame showed (overlapping ones hidden). */
  shownLabels: (): number => shownLabels,
  /**
   * What the last frame drawn showed of each body and the probe, by name: its place on the canvas
   * (px), its drawn radius (px), whether its dot shows and whether it is on screen.
   */
  markers: (): Record<string, { x: number; y: number; radius: number; dot: boolean; visible: boolean }> =>
    Object.fromEntries(
      LABELS.map((name, i) => [
        name,
        {
          x: shownOnScreen[4 * i]!,
          y: shownOnScreen[4 * i + 1]!,
          radius: shownOnScreen[4 * i + 2]!,
          dot: dots[name].el.style.display !== 'none',
          visible: shownOnScreen[4 * i + 3] === 1,
        },
      ]),
    ),
  /** The planets whose centre the camera sees now (projected inside the canvas). */
  planetsInView: (): string[] =>
    SOLAR_SYSTEM_PLANETS.filter((name) => {
      const i = SOLAR_SYSTEM_BODIES.indexOf(name);
      v.set(shown[3 * i]!, shown[3 * i + 1]!, shown[3 * i + 2]!).project(app.camera);
      return v.z < 1 && Math.abs(v.x) <= 1 && Math.abs(v.y) <= 1;
    }),
  /**
   * The mission state: its number (1-based), target, phase, the aim, the forecast shown (of the
   * launch, or of the course while flying: `plan.hit` whether it arrives, `time` the days of flight
   * at the end, `distance` the closest approach, AU, `sun` whether it falls into the Sun, `current`
   * whether it is for the aim and moment now, `shown` whether the map and the status line show it) and the flight.
   */
  mission: () => ({
    number: missionIndex + 1,
    target: mission().target,
    phase,
    aim: { ...aim },
    plan: {
      hit: forecast.outcome === 'arrived',
      time: forecast.end,
      distance: forecast.closest,
      sun: forecast.outcome === 'sun',
      current: forecastKey !== '' && forecastKey === wantedKey(),
      /** Whether a frame showing this forecast has been drawn (the status line's aim words are then this forecast's). */
      shown: forecastKey !== '' && forecastKey === drawnForecastKey,
      key: forecastKey,
    },
    flight: flight
      ? { state: flight.state, elapsed: flight.elapsed, closest: flight.closest, fuelUsed: flight.fuelUsed, burns: flight.burns }
      : null,
    stars: [...best],
    trueScale,
  }),
  /** Sets the aim (degrees, km/s) as the keys would. */
  setAim: (angle: number, speed: number): void => {
    if (phase !== 'aim') return;
    aim.angle = angle;
    aim.speed = speed;
    aimChangedAt = performance.now();
  },
  /**
   * Flies the flight under way to its end at once, with its own step and checks (as the loop would
   * over the next seconds), and pauses: for tests. @returns how it ended ('' with no flight under way).
   */
  finishFlight: (): string => {
    if (phase !== 'flight' || !flight) return '';
    shell.paused = true;
    const world = shell.world;
    if (world.dt !== flight.dt) setTimeStep(world, flight.dt);
    while (phase === 'flight' && flight) {
      step(world);
      recordTrail(world);
      if (checkFlight(world, handles, flight) !== 'flying') endOfFlight();
    }
    return flight?.state ?? '';
  },
  /** Launches (Space), starts a mission (0-based), goes on after a flight (Enter). */
  launch,
  startMission,
  advance,
  /**
   * What the last frame's preview showed: the probe's dots drawn, the forecast points they were
   * drawn from (from the probe now, or the launch, to the closest approach), whether the white dot of
   * the probe at the closest approach (a miss) and the target's own dots (while aiming) show, and the
   * forecast's points up to that time and in all.
   */
  /**
   * The ghost ring and the white dot as the last frame drew them, canvas px: the ring's points (x, y
   * pairs) and the dot, with the key of the forecast they were drawn for (`mission().plan.key`).
   */
  ghost: () => {
    const attr = ghostRing.geometry.getAttribute('position') as Float32BufferAttribute;
    const w = app.canvas.clientWidth,
      h = app.canvas.clientHeight;
    const px = (p: Vector3): [number, number] => {
      p.project(app.camera);
      return [((p.x + 1) / 2) * w, ((1 - p.y) / 2) * h];
    };
    ghostRing.updateMatrixWorld();
    const ring: [number, number][] = [];
    for (let i = 0; i < CIRCLE; i++) ring.push(px(new Vector3().fromBufferAttribute(attr, i).applyMatrix4(ghostRing.matrixWorld)));
    const dot = new Vector3().fromBufferAttribute(probeThen.geometry.getAttribute('position') as Float32BufferAttribute, 0);
    return { key: ghostKey, visible: ghostRing.visible, ring, dot: px(dot) };
  },
  /**
   * The launch arrow as the last frame drew it, canvas CSS px: its base (at the Earth) and its tip,
   * and whether it shows (only while aiming).
   */
  arrow: () => {
    const w = app.canvas.clientWidth,
      h = app.canvas.clientHeight;
    const px = (p: Vector3): [number, number] => {
      p.project(app.camera);
      return [((p.x + 1) / 2) * w, ((1 - p.y) / 2) * h];
    };
    arrow.updateMatrixWorld();
    return {
      visible: arrow.visible,
      base: px(new Vector3(0, 0, 0).applyMatrix4(arrow.matrixWorld)),
      tip: px(new Vector3(0, 1, 0).applyMatrix4(arrow.matrixWorld)),
    };
  },
  preview: () => ({
    dots: planDotsShown,
    shownPoints: planPointsShown,
    probeThen: probeThen.visible,
    track: trackDots.visible,
    pointsToTime: forecast.pointsToClosest,
    points: forecast.points,
  }),
});
