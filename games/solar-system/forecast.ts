/**
 * The solar system's forecast, DOM-free (Node tests and scripts/solar-system-forecast.mjs run it):
 * what a launch, or a flight under way, will do, found by flying it ahead of time with the flight's
 * own physics. The page flies a probe in the physics world with a fixed step (`Flight.dt`,
 * ./missions.ts) and checks it after every step (`checkFlight`). The forecast copies the world's
 * bodies (the Sun and the eight planets, each pulling every other, Newton without softening) and
 * the probe, steps the copy with the world's scheme, the classical fourth-order Runge-Kutta method
 * (integrators/schemes.ts rk4: slopes at the start, twice at the midpoint and at the end, weighted
 * 1/6, 2/6, 2/6, 1/6; Ramtal and Dobre ch. 14), its force sum (forces/pairwise.ts: each pair once,
 * in entity order) and the same step, and applies the flight's rules after every step: inside the
 * target's zone it has arrived, inside SUN_ZONE it has fallen into the Sun, beyond ESCAPE_DISTANCE
 * or past the deadline it has missed. The arithmetic is the world's, in the same order, so the
 * forecast is the flight to the last bit: scripts/solar-system-forecast.mjs flies a spread of
 * launches both ways and finds the same verdicts, days and closest approaches (differences 0).
 *
 * The probe's pull on a planet is 1e-24 of the Sun's, below the last bit of the planet's
 * acceleration, so the planets' motion is the same whatever the probe does: it is worked out once
 * (`PlanetTrack`, the four stage positions of every step) and reused by every forecast from the
 * same moment and step (every aim tried while time waits, the burns tried in flight), which then
 * only moves the probe: about 1 microsecond a step on a desktop, a tenth of the whole copy's cost.
 *
 * Only the world's 'rk4' is copied; with another scheme (the panel's integrator, for engineers) the
 * forecast stays RK4 at the flight's step and `Forecast.scheme` names the flight's.
 *
 * Units: the world's (AU, days, solar masses).
 */

import { type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { type SolarSystemHandles, solarSystemMass } from '@bitphysics/projects';
import {
  type Aim,
  type BurnDirection,
  burnDirection,
  createFlightPlan,
  ESCAPE_DISTANCE,
  type Flight,
  type FlightPlan,
  flightDeadline,
  KM_S,
  LAUNCH_OFFSET,
  launchDirection,
  type Mission,
  missionTimeStep,
  PROBE_MASS,
  planCourse,
  planFlight,
  SUN_ZONE,
  TARGET_TRACK,
} from './missions';

/** Points of a forecast's path (and of the target's with it), at equal times; one more at the end. */
export const FORECAST_SAMPLES = 400;

/** The world's bodies the forecast copies (the Sun first, handles.ids order). */
const B = 9;

/** What a flight will do (`forecastLaunch`, `forecastCourse`, `ForecastJob`); one object, filled in place. */
export interface Forecast {
  /** How the flight ends: it arrives in the target's zone, falls into the Sun, or misses (past its deadline, or out of the solar system). */
  outcome: 'arrived' | 'sun' | 'missed';
  /** Days of flight (since the launch) at the end: the arrival, the fall or the miss. */
  end: number;
  /** Closest approach to the target's centre over the whole flight, AU, and when, days of flight. */
  closest: number;
  closestAt: number;
  /** The flight's fixed step, days, and its deadline, days of flight (./missions.ts `missionTimeStep`, `flightDeadline`). */
  dt: number;
  deadline: number;
  /** Farthest and nearest the probe gets from the Sun from now to the end, AU. */
  farthest: number;
  nearest: number;
  /** Steps flown ahead. */
  steps: number;
  /** Days of flight at the forecast's start (0 for a launch). */
  from: number;
  /**
   * The probe's heliocentric path from now, AU (x, y, z each), `points` of them at equal times, the
   * last at the end; the first `pointsToClosest` of them lie before the closest approach (all of
   * them on an arrival), which is at `probeAt`.
   */
  readonly path: Float64Array;
  points: number;
  pointsToClosest: number;
  /** Days of flight between two points of the path (the last may be closer to the one before). */
  every: number;
  /** Where the target goes from now to the closest approach, heliocentric AU, TARGET_TRACK points at equal times (the last at targetAt). */
  readonly targetTrack: Float64Array;
  /** The probe's and the target's heliocentric places at the closest approach (the arrival), AU. */
  readonly probeAt: Float64Array;
  readonly targetAt: Float64Array;
  /** The world's integration scheme: 'rk4', which the forecast copies, or another (the forecast is RK4 all the same). */
  scheme: string;
  /**
   * Whether a launch that misses comes closest to the target at the launch itself (within the first
   * sample): from then on the probe only gets farther from it, whatever it does. Then `closest` and
   * `closestAt` are still that approach, but `pointsToClosest`, `probeAt`, `targetAt` and
   * `targetTrack` run to the sample where the probe comes nearest the target's orbit (its distance
   * from the Sun then): a path of one point drew nothing and put "probe then" at the Earth.
   */
  closestAtLaunch: boolean;
}

/** A fresh, empty forecast. */
export function createForecast(): Forecast {
  return {
    outcome: 'missed',
    end: 0,
    closest: Infinity,
    closestAt: 0,
    dt: 0,
    deadline: 0,
    farthest: 0,
    nearest: Infinity,
    steps: 0,
    from: 0,
    path: new Float64Array(3 * (FORECAST_SAMPLES + 2)),
    points: 0,
    pointsToClosest: 0,
    every: 0,
    targetTrack: new Float64Array(3 * TARGET_TRACK),
    probeAt: new Float64Array(3),
    targetAt: new Float64Array(3),
    scheme: 'rk4',
    closestAtLaunch: false,
  };
}

// ---- The planets' motion, worked out once per moment and step -----------------------------------

/** Steps of the planet track kept in one block. */
const BLOCK = 1024;
/** Numbers a step keeps: the nine bodies' positions (x, y, z) at each of RK4's four stages. */
const PER_STEP = 4 * 3 * B;

/**
 * The Sun's and the planets' motion from one moment of one world with one step: the positions the
 * world's rk4 gives them at each stage of each step (the probe feels them there), grown as far as
 * forecasts need. Valid while the world is the same object and its bodies are where the track says
 * (a forecast from later on, after the world has stepped along it, starts from the track's step
 * then; the blocks before that are let go).
 */
class PlanetTrack {
  world: PhysicsWorld | null = null;
  /** Counts the restarts (`reset`): a forecast under way from an earlier track must start again. */
  generation = 0;
  /** world.time at step 0, days; the step, days. */
  t0 = 0;
  dt = 0;
  /** The gravitational constant and the bodies' masses (handles.ids order). */
  G = 0;
  readonly mass = new Float64Array(B);
  readonly inv = new Float64Array(B);
  /** Steps worked out. */
  count = 0;
  /** Blocks of BLOCK steps (block i holds steps i BLOCK to (i + 1) BLOCK - 1; null once let go). */
  readonly blocks: Array<Float64Array | null> = [];
  /** Blocks let go, for reuse. */
  private readonly spare: Float64Array[] = [];
  // The integrator's state after `count` steps and its scratch.
  private readonly x = new Float64Array(3 * B);
  private readonly v = new Float64Array(3 * B);
  private readonly x0 = new Float64Array(3 * B);
  private readonly v0 = new Float64Array(3 * B);
  private readonly force = new Float64Array(3 * B);
  private readonly acc = new Float64Array(3 * B);
  private readonly kv = new Float64Array(3 * B);
  private readonly sumX = new Float64Array(3 * B);
  private readonly sumV = new Float64Array(3 * B);

  /** Starts the track at the world's state now with step `dt` (days). */
  reset(world: PhysicsWorld, handles: SolarSystemHandles, dt: number): void {
    const P = world.components.Position,
      V = world.components.Velocity,
      M = world.components.Mass;
    this.world = world;
    this.t0 = world.time;
    this.dt = dt;
    this.G = world.laws.gravitationalConstant;
    for (let i = 0; i < B; i++) {
      const e = slotOf(handles.ids[i]!);
      this.x[3 * i] = P.x[e]!;
      this.x[3 * i + 1] = P.y[e]!;
      this.x[3 * i + 2] = P.z[e]!;
      this.v[3 * i] = V.x[e]!;
      this.v[3 * i + 1] = V.y[e]!;
      this.v[3 * i + 2] = V.z[e]!;
      this.mass[i] = M.value[e]!;
      this.inv[i] = M.inv[e]!;
    }
    this.count = 0;
    for (const b of this.blocks) if (b) this.spare.push(b);
    this.blocks.length = 0;
    this.generation++;
  }

  /**
   * The track's step at which the world is now, from the same world with the same step (its bodies
   * bit for bit where the track has them, the track grown to there if need be), or -1.
   */
  stepOf(world: PhysicsWorld, handles: SolarSystemHandles, dt: number): number {
    if (world !== this.world || dt !== this.dt || world.laws.gravitationalConstant !== this.G) return -1;
    const k = Math.round((world.time - this.t0) / dt);
    if (k < 0 || k > this.count + 100_000) return -1;
    const block = this.blockOf(k);
    if (!block) return -1;
    const o = (k % BLOCK) * PER_STEP;
    const P = world.components.Position;
    for (let i = 0; i < B; i++) {
      const e = slotOf(handles.ids[i]!);
      if (block[o + 3 * i] !== P.x[e] || block[o + 3 * i + 1] !== P.y[e] || block[o + 3 * i + 2] !== P.z[e]) return -1;
    }
    // The world has moved on to step k: the blocks before its block are not needed again.
    for (let i = 0; i < Math.floor(k / BLOCK); i++) {
      const b = this.blocks[i];
      if (b) {
        this.spare.push(b);
        this.blocks[i] = null;
      }
    }
    return k;
  }

  /** Works the track out to at least `steps` steps. */
  grow(steps: number): void {
    while (this.count < steps) {
      const k = this.count;
      if (this.blocks.length <= Math.floor(k / BLOCK)) this.blocks.push(this.spare.pop() ?? new Float64Array(BLOCK * PER_STEP));
      this.step(this.blocks[Math.floor(k / BLOCK)]!, (k % BLOCK) * PER_STEP);
      this.count++;
    }
  }

  /**
   * The block holding step `k`'s stage positions (4 x 27 numbers from offset (k % BLOCK) PER_STEP),
   * the track grown to there; null if that block was let go.
   */
  blockOf(k: number): Float64Array | null {
    this.grow(k + 1);
    return this.blocks[Math.floor(k / BLOCK)] ?? null;
  }

  /** The world's pair sum over the nine bodies at x, then a = F / m, into acc. */
  private accelerations(): void {
    const { x, force, acc, mass, inv } = this;
    force.fill(0);
    for (let i = 0; i < B; i++) {
      const sa = this.G * mass[i]!;
      const xa = x[3 * i]!,
        ya = x[3 * i + 1]!,
        za = x[3 * i + 2]!;
      let sx = 0,
        sy = 0,
        sz = 0;
      for (let j = i + 1; j < B; j++) {
        const dx = x[3 * j]! - xa,
          dy = x[3 * j + 1]! - ya,
          dz = x[3 * j + 2]! - za;
        const r2 = dx * dx + dy * dy + dz * dz;
        if (r2 === 0) continue;
        const k = (sa * mass[j]!) / (r2 * Math.sqrt(r2));
        const kx = k * dx,
          ky = k * dy,
          kz = k * dz;
        sx += kx;
        sy += ky;
        sz += kz;
        force[3 * j] = force[3 * j]! - kx;
        force[3 * j + 1] = force[3 * j + 1]! - ky;
        force[3 * j + 2] = force[3 * j + 2]! - kz;
      }
      force[3 * i] = force[3 * i]! + sx;
      force[3 * i + 1] = force[3 * i + 1]! + sy;
      force[3 * i + 2] = force[3 * i + 2]! + sz;
    }
    for (let i = 0; i < 3 * B; i++) acc[i] = force[i]! * inv[Math.floor(i / 3)]!;
  }

  /** Keeps the stage's positions at out[o..o+26], then its slopes into the sums (set when `reset`). */
  private stage(out: Float64Array, o: number, weight: number, reset: boolean): void {
    out.set(this.x, o);
    this.accelerations();
    const { v, acc, kv, sumX, sumV } = this;
    for (let k = 0; k < 3 * B; k++) {
      kv[k] = v[k]!;
      sumX[k] = reset ? weight * v[k]! : sumX[k]! + weight * v[k]!;
      sumV[k] = reset ? weight * acc[k]! : sumV[k]! + weight * acc[k]!;
    }
  }

  /** x = x0 + cx dx, v = v0 + cv dv (the world's writeTrial). */
  private trial(cx: number, dx: Float64Array, cv: number, dv: Float64Array): void {
    const { x, v, x0, v0 } = this;
    for (let k = 0; k < 3 * B; k++) {
      x[k] = x0[k]! + cx * dx[k]!;
      v[k] = v0[k]! + cv * dv[k]!;
    }
  }

  /** One rk4 step of the nine bodies, its four stages' positions kept at out[o..o+107]. */
  private step(out: Float64Array, o: number): void {
    const h = this.dt;
    this.x0.set(this.x);
    this.v0.set(this.v);
    this.stage(out, o, 1 / 6, true);
    this.trial(h / 2, this.kv, h / 2, this.acc);
    this.stage(out, o + 27, 2 / 6, false);
    this.trial(h / 2, this.kv, h / 2, this.acc);
    this.stage(out, o + 54, 2 / 6, false);
    this.trial(h, this.kv, h, this.acc);
    this.stage(out, o + 81, 1 / 6, false);
    this.trial(h, this.sumX, h, this.sumV);
  }
}

/** The one planet track the forecasts share (the page has one world at a time). */
const track = new PlanetTrack();

/** The track's step for the world now with step dt: the track kept when it matches, else started again here. */
function trackStep(world: PhysicsWorld, handles: SolarSystemHandles, dt: number): number {
  const k = track.stepOf(world, handles, dt);
  if (k >= 0) return k;
  track.reset(world, handles, dt);
  return 0;
}

// ---- A forecast under way ------------------------------------------------------------------------

/**
 * One forecast worked out a slice at a time (`run`), so the page can spread a long one over frames:
 * `startLaunch` or `startCourse`, then `run` until it returns true; the result is in `forecast`.
 */
export class ForecastJob {
  /** The result (complete once `run` returned true). */
  readonly forecast: Forecast;
  /** Whether a forecast is under way (started and not finished). */
  busy = false;
  /**
   * Whether the last forecast was given up unfinished: the planets' track it flew along was started
   * again (another world, or the world moved off it) by another forecast. Start it again.
   */
  lost = false;
  private generation = -1;
  private mission: Mission | null = null;
  private target = 0;
  private k = 0;
  private time = 0;
  private launchTime = 0;
  private stride = 1;
  private closestStep = 0;
  // The probe: position and velocity, the step's start, slopes and sums.
  private readonly p = new Float64Array(3);
  private readonly u = new Float64Array(3);
  private readonly p0 = new Float64Array(3);
  private readonly u0 = new Float64Array(3);
  private readonly a = new Float64Array(3);
  private readonly kv = new Float64Array(3);
  private readonly sumX = new Float64Array(3);
  private readonly sumV = new Float64Array(3);
  /** The target's heliocentric place at each sample, AU. */
  private readonly targetPath = new Float64Array(3 * (FORECAST_SAMPLES + 2));

  constructor(forecast: Forecast = createForecast()) {
    this.forecast = forecast;
  }

  /**
   * Starts the forecast of launching `aim` now towards `mission`'s target: the launch as
   * ./missions.ts launchProbe makes it, with the step `missionTimeStep(mission, baseStep)` (days)
   * and the deadline `flightDeadline` of the Kepler plan (`planFlight`, written into `plan`).
   * @throws RangeError on a bad aim (planFlight) or a baseStep that is not finite and > 0.
   */
  startLaunch(
    world: PhysicsWorld,
    handles: SolarSystemHandles,
    mission: Mission,
    aim: Aim,
    baseStep: number,
    plan: FlightPlan = keplerPlan,
  ): void {
    if (!(baseStep > 0 && Number.isFinite(baseStep)))
      throw new RangeError(`ForecastJob.startLaunch: baseStep must be finite and > 0 days, got ${baseStep}`);
    planFlight(world, handles, mission, aim, plan);
    const deadline = flightDeadline(plan, mission.zone);
    const dt = missionTimeStep(mission, baseStep);
    // The launch of missions.ts launchProbe.
    const P = world.components.Position,
      V = world.components.Velocity;
    const e = slotOf(handles.bodies.Earth),
      s = slotOf(handles.bodies.Sun);
    state6[0] = P.x[e]! - P.x[s]!;
    state6[1] = P.y[e]! - P.y[s]!;
    state6[2] = P.z[e]! - P.z[s]!;
    state6[3] = V.x[e]! - V.x[s]!;
    state6[4] = V.y[e]! - V.y[s]!;
    state6[5] = V.z[e]! - V.z[s]!;
    launchDirection(state6, aim.angle, dir);
    const muEarth = world.laws.gravitationalConstant * solarSystemMass('Earth');
    const vInf = aim.speed * KM_S;
    const w = Math.sqrt(vInf * vInf + (2 * muEarth) / LAUNCH_OFFSET);
    this.p[0] = P.x[e]! + LAUNCH_OFFSET * dir[0]!;
    this.p[1] = P.y[e]! + LAUNCH_OFFSET * dir[1]!;
    this.p[2] = P.z[e]! + LAUNCH_OFFSET * dir[2]!;
    this.u[0] = V.x[e]! + w * dir[0]!;
    this.u[1] = V.y[e]! + w * dir[1]!;
    this.u[2] = V.z[e]! + w * dir[2]!;
    this.begin(world, handles, mission, dt, deadline, world.time, Infinity, 0);
  }

  /**
   * Starts the forecast of `flight` from now, with its step and deadline; with `burn`, of the flight
   * after a burn of `burn.dv` km/s in `burn.direction` now, with the deadline that burn would give it
   * (./missions.ts burnProbe; the world is not changed). The closest approach counts the flight's so far.
   */
  startCourse(world: PhysicsWorld, handles: SolarSystemHandles, flight: Flight, burn?: { direction: BurnDirection; dv: number }): void {
    const P = world.components.Position,
      V = world.components.Velocity;
    const q = slotOf(flight.probe);
    this.p[0] = P.x[q]!;
    this.p[1] = P.y[q]!;
    this.p[2] = P.z[q]!;
    this.u[0] = V.x[q]!;
    this.u[1] = V.y[q]!;
    this.u[2] = V.z[q]!;
    let deadline = flight.deadline;
    if (burn) {
      const s = slotOf(handles.bodies.Sun);
      state6[0] = this.p[0] - P.x[s]!;
      state6[1] = this.p[1] - P.y[s]!;
      state6[2] = this.p[2] - P.z[s]!;
      state6[3] = this.u[0] - V.x[s]!;
      state6[4] = this.u[1] - V.y[s]!;
      state6[5] = this.u[2] - V.z[s]!;
      burnDirection(state6, burn.direction, dir);
      const k = burn.dv * KM_S;
      for (let c = 0; c < 3; c++) this.u[c] = this.u[c]! + k * dir[c]!;
      planCourse(world, handles, flight, keplerPlan, burn);
      deadline = flight.elapsed + flightDeadline(keplerPlan, flight.mission.zone);
    }
    this.begin(world, handles, flight.mission, flight.dt, deadline, flight.launchTime, flight.closest, flight.closestAt);
  }

  private begin(
    world: PhysicsWorld,
    handles: SolarSystemHandles,
    mission: Mission,
    dt: number,
    deadline: number,
    launchTime: number,
    closest: number,
    closestAt: number,
  ): void {
    const f = this.forecast;
    this.mission = mission;
    this.target = handles.ids.indexOf(handles.bodies[mission.target]);
    this.k = trackStep(world, handles, dt);
    this.generation = track.generation;
    this.lost = false;
    this.time = world.time;
    this.launchTime = launchTime;
    f.scheme = world.integrator;
    f.dt = dt;
    f.deadline = deadline;
    f.from = world.time - launchTime;
    f.closest = closest;
    f.closestAt = closestAt;
    f.farthest = 0;
    f.nearest = Infinity;
    f.steps = 0;
    f.points = 0;
    // A sample every `stride` steps: FORECAST_SAMPLES of them reach the deadline; one more at the end.
    this.stride = Math.max(1, Math.ceil(Math.max(1, (deadline - f.from) / dt) / FORECAST_SAMPLES));
    f.every = this.stride * dt;
    const block = track.blockOf(this.k)!,
      o = (this.k % BLOCK) * PER_STEP;
    this.record(block, o);
    // Until the first step, the places now (the flight's closest approach so far, if any, came earlier).
    this.closestStep = 0;
    this.place(block, o, f.probeAt, f.targetAt);
    this.busy = true;
  }

  /** Writes the probe's and the target's heliocentric places (the bodies at block[o..]) into the two. */
  private place(block: Float64Array, o: number, probe: Float64Array, target: Float64Array, to = 0): void {
    const t = o + 3 * this.target;
    for (let c = 0; c < 3; c++) {
      probe[to + c] = this.p[c]! - block[o + c]!;
      target[to + c] = block[t + c]! - block[o + c]!;
    }
  }

  private record(block: Float64Array, o: number): void {
    const f = this.forecast;
    this.place(block, o, f.path, this.targetPath, 3 * f.points);
    f.points++;
  }

  /** The probe's acceleration with the bodies at block[o..o+26], into a: the world's pair sum, each body j before the probe, then a = F / m. */
  private accelerate(block: Float64Array, o: number): void {
    const G = track.G,
      mass = track.mass,
      p = this.p;
    let fx = 0,
      fy = 0,
      fz = 0;
    for (let j = 0; j < B; j++) {
      const dx = p[0]! - block[o + 3 * j]!,
        dy = p[1]! - block[o + 3 * j + 1]!,
        dz = p[2]! - block[o + 3 * j + 2]!;
      const r2 = dx * dx + dy * dy + dz * dz;
      if (r2 === 0) continue;
      const k = (G * mass[j]! * PROBE_MASS) / (r2 * Math.sqrt(r2));
      fx = fx - k * dx;
      fy = fy - k * dy;
      fz = fz - k * dz;
    }
    this.a[0] = fx * INV_PROBE;
    this.a[1] = fy * INV_PROBE;
    this.a[2] = fz * INV_PROBE;
  }

  private stage(block: Float64Array, o: number, weight: number, reset: boolean): void {
    this.accelerate(block, o);
    const { u, a, kv, sumX, sumV } = this;
    for (let c = 0; c < 3; c++) {
      kv[c] = u[c]!;
      sumX[c] = reset ? weight * u[c]! : sumX[c]! + weight * u[c]!;
      sumV[c] = reset ? weight * a[c]! : sumV[c]! + weight * a[c]!;
    }
  }

  private trial(cx: number, dx: Float64Array, cv: number, dv: Float64Array): void {
    for (let c = 0; c < 3; c++) {
      this.p[c] = this.p0[c]! + cx * dx[c]!;
      this.u[c] = this.u0[c]! + cv * dv[c]!;
    }
  }

  /**
   * Flies the forecast on by at most `maxSteps` steps (all of them by default).
   * @returns whether it is over: complete (`forecast` holds it), lost (`lost`) or none under way.
   */
  run(maxSteps = Infinity): boolean {
    if (!this.busy) return true;
    if (this.generation !== track.generation) {
      this.busy = false;
      this.lost = true;
      return true;
    }
    const f = this.forecast,
      m = this.mission!,
      h = f.dt;
    for (let n = 0; n < maxSteps; n++) {
      const block = track.blockOf(this.k),
        next = track.blockOf(this.k + 1);
      if (!block || !next || this.generation !== track.generation) {
        this.busy = false;
        this.lost = true;
        return true;
      }
      const o = (this.k % BLOCK) * PER_STEP;
      this.p0.set(this.p);
      this.u0.set(this.u);
      this.stage(block, o, 1 / 6, true);
      this.trial(h / 2, this.kv, h / 2, this.a);
      this.stage(block, o + 27, 2 / 6, false);
      this.trial(h / 2, this.kv, h / 2, this.a);
      this.stage(block, o + 54, 2 / 6, false);
      this.trial(h, this.kv, h, this.a);
      this.stage(block, o + 81, 1 / 6, false);
      this.trial(h, this.sumX, h, this.sumV);
      this.k++;
      f.steps++;
      this.time = this.time + h;
      const elapsed = this.time - this.launchTime;
      // The bodies at the end of the step: the next step's start.
      const b = next,
        q = (this.k % BLOCK) * PER_STEP,
        t = q + 3 * this.target;
      const d = Math.hypot(this.p[0]! - b[t]!, this.p[1]! - b[t + 1]!, this.p[2]! - b[t + 2]!);
      const r = Math.hypot(this.p[0]! - b[q]!, this.p[1]! - b[q + 1]!, this.p[2]! - b[q + 2]!);
      f.farthest = Math.max(f.farthest, r);
      f.nearest = Math.min(f.nearest, r);
      if (d < f.closest) {
        f.closest = d;
        f.closestAt = elapsed;
        this.closestStep = f.steps;
        this.place(b, q, f.probeAt, f.targetAt);
      }
      // The flight's rules (missions.ts checkFlight), in its order.
      const outcome = d < m.zone ? 'arrived' : r < SUN_ZONE ? 'sun' : r > ESCAPE_DISTANCE || elapsed > f.deadline ? 'missed' : null;
      if ((outcome !== null || f.steps % this.stride === 0) && f.points < FORECAST_SAMPLES + 2) this.record(b, q);
      if (outcome !== null) {
        f.outcome = outcome;
        f.end = elapsed;
        this.finish();
        return true;
      }
    }
    return false;
  }

  private finish(): void {
    const f = this.forecast;
    this.busy = false;
    // The samples before the closest approach (the drawing ends at probeAt); all of them on an arrival.
    f.pointsToClosest = f.outcome === 'arrived' ? f.points : Math.min(f.points, Math.floor(this.closestStep / this.stride) + 1);
    // A launch nearest the target at the start: show where it gets to instead, the sample nearest the target's orbit.
    f.closestAtLaunch = f.from === 0 && f.outcome !== 'arrived' && f.pointsToClosest <= 1 && f.points > 1;
    if (f.closestAtLaunch) {
      let best = 1,
        gap = Infinity;
      for (let i = 1; i < f.points; i++) {
        const p = f.path,
          t = this.targetPath;
        const g = Math.abs(Math.hypot(p[3 * i]!, p[3 * i + 1]!, p[3 * i + 2]!) - Math.hypot(t[3 * i]!, t[3 * i + 1]!, t[3 * i + 2]!));
        if (g < gap) {
          gap = g;
          best = i;
        }
      }
      f.pointsToClosest = best + 1;
      f.probeAt.set(f.path.subarray(3 * best, 3 * best + 3));
      f.targetAt.set(this.targetPath.subarray(3 * best, 3 * best + 3));
    }
    // The target's track from now to the closest approach: TARGET_TRACK of its samples, the last at targetAt.
    const last = f.pointsToClosest - 1;
    for (let i = 0; i < TARGET_TRACK - 1; i++) {
      const k = Math.round((last * i) / (TARGET_TRACK - 1));
      f.targetTrack.set(this.targetPath.subarray(3 * k, 3 * k + 3), 3 * i);
    }
    f.targetTrack.set(f.targetAt, 3 * (TARGET_TRACK - 1));
  }
}

const INV_PROBE = 1 / PROBE_MASS;
const dir = new Float64Array(3);
const state6 = new Float64Array(6);
const keplerPlan = createFlightPlan();
const syncJob = new ForecastJob();

/**
 * What launching `aim` now towards `mission`'s target will do (`ForecastJob.startLaunch`, run to the
 * end), into `out`. @returns out. @throws RangeError as startLaunch.
 */
export function forecastLaunch(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  mission: Mission,
  aim: Aim,
  baseStep: number,
  out: Forecast = createForecast(),
): Forecast {
  syncJob.startLaunch(world, handles, mission, aim, baseStep);
  syncJob.run();
  return copyForecast(syncJob.forecast, out);
}

/** What `flight` will do from now, or after `burn` now (`ForecastJob.startCourse`, run to the end), into `out`. @returns out. */
export function forecastCourse(
  world: PhysicsWorld,
  handles: SolarSystemHandles,
  flight: Flight,
  out: Forecast = createForecast(),
  burn?: { direction: BurnDirection; dv: number },
): Forecast {
  syncJob.startCourse(world, handles, flight, burn);
  syncJob.run();
  return copyForecast(syncJob.forecast, out);
}

/** Copies forecast `from` into `to`. @returns to. */
export function copyForecast(from: Forecast, to: Forecast): Forecast {
  if (from === to) return to;
  const { path, targetTrack, probeAt, targetAt, ...scalars } = from;
  Object.assign(to, scalars);
  to.path.set(path.subarray(0, 3 * from.points));
  to.targetTrack.set(targetTrack);
  to.probeAt.set(probeAt);
  to.targetAt.set(targetAt);
  return to;
}
