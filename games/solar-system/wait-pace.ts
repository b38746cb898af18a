/**
 * The pace of the solar system's Wait while aiming (W or the Wait button), DOM-free so Node tests
 * check it. Waiting is how the player picks the launch day: the target's forecast dots move along
 * its orbit as time runs, and the player lets go when they meet the probe's. Held, Wait runs fast
 * across the months between launch windows, slows near one and stops at it for WINDOW_PAUSE_S
 * whatever the aim (the player is waiting for a window: let go there, or hold on past it); a tap
 * runs it on at the same pace to the next window and stops there (a phone's finger taps; at 10 days
 * a tap a window took about 170 of them), or stops a run under way (`waitTick`). A hold let go far
 * from a window, with the aim far from arriving, runs on to the window as a tap does
 * (`releaseRunsOn`): held 4 s from 2012-01-01 on Mars it stopped at 2013-07-22, 181 days short of
 * the window, where no launch arrives.
 *
 * Units: days of world time, days per real second.
 */

/** Days per real second while Wait is held at first: the aiming rate times 4 if that is faster. */
export const WAIT_RATE = 40;

/**
 * Held Wait speeds up with the days it has run: its rate grows by WAIT_RATE's worth every WAIT_RAMP
 * days waited, up to WAIT_MAX_GAIN times it, so a long hold crosses a year in a few seconds.
 */
export const WAIT_RAMP = 20;
export const WAIT_MAX_GAIN = 4;

/**
 * Within this many days of a launch window (either side) a held Wait runs at no more than
 * NEAR_WINDOW_RATE: Mars's arrival window at a near-Hohmann speed is about 50 days wide, 3 s at
 * this pace, long enough to see the dots meet and let go.
 */
export const NEAR_WINDOW_DAYS = 60;
export const NEAR_WINDOW_RATE = 15;

/**
 * While the launch as aimed comes within AIM_NEAR_RINGS arrival rings of the target (the quick Kepler
 * plan's closest approach, ./missions.ts planFlight), a held Wait runs at no more than AIM_NEAR_RATE:
 * the days that arrive then last seconds, so a player holding Wait can let go inside them (at
 * NEAR_WINDOW_RATE they lasted about 1.5 s, and a held Wait ran past them). The starting aim of
 * missions 2 on misses by more (./advice.ts START_SHORT keeps it off the orbit), so it does not slow.
 */
export const AIM_NEAR_RINGS = 1.2;
export const AIM_NEAR_RATE = 3;

/**
 * Real seconds a held Wait stops at each launch window before it runs on (slowly: within
 * NEAR_WINDOW_DAYS of it): long enough to see the date line say so and let go.
 */
export const WINDOW_PAUSE_S = 1.5;

/**
 * Days per real second of a held Wait. `aimingRate` the rate time runs at while aiming (days/s,
 * >= 0), `waited` days since the hold began (>= 0), `fromWindow` days to the nearest launch
 * window of the mission's target (>= 0; Infinity for none), `aimMiss` the launch as aimed now misses
 * the target by, in arrival rings (the Kepler plan's closest approach over the ring's radius, >= 0;
 * Infinity when unknown). @throws RangeError on a negative or NaN argument.
 */
export function heldWaitRate(aimingRate: number, waited: number, fromWindow: number, aimMiss = Infinity): number {
  for (const [name, x] of [
    ['aimingRate', aimingRate],
    ['waited', waited],
    ['fromWindow', fromWindow],
    ['aimMiss', aimMiss],
  ] as const)
    if (!(x >= 0)) throw new RangeError(`heldWaitRate: ${name} must be >= 0, got ${x}`);
  const ramped = Math.max(WAIT_RATE, 4 * aimingRate) * Math.min(WAIT_MAX_GAIN, 1 + waited / WAIT_RAMP);
  const rate = fromWindow < NEAR_WINDOW_DAYS ? Math.min(ramped, NEAR_WINDOW_RATE) : ramped;
  return aimMiss < AIM_NEAR_RINGS ? Math.min(rate, AIM_NEAR_RATE) : rate;
}

/** When the next launch window comes: `next` days from now, in [0, period), and the synodic `period` between windows, days. */
export interface LaunchWindow {
  next: number;
  period: number;
}

/**
 * The next launch window from the Earth to a target planet: when the target leads (or, for an inner
 * planet, trails) the Earth by the angle a Hohmann transfer needs, pi - n_T t_H, the target moving
 * at its mean motion n_T over the transfer's half ellipse t_H = pi sqrt(a^3 / mu), a = (r_E + r_T) / 2
 * (Curtis, Orbital Mechanics, sect. 6.3 and 8.2); on circular orbits in the ecliptic (x-z) plane,
 * each at its mean pace (its orbit's semi-major axis from vis-viva: the distance now would give the
 * Earth's pace in January 2.6 % fast, the window 20 days late). `earth`, `target`: heliocentric
 * states (x, y, z AU, vx, vy, vz AU/day); `mu` the Sun's GM, AU^3/day^2 (> 0). Fills and returns `out`.
 * @throws RangeError when mu is not > 0.
 */
export function nextLaunchWindow(earth: ArrayLike<number>, target: ArrayLike<number>, mu: number, out: LaunchWindow): LaunchWindow {
  if (!(mu > 0)) throw new RangeError(`nextLaunchWindow: mu must be > 0, got ${mu}`);
  const ex = earth[0]!,
    ez = earth[2]!;
  // The sense the planets go round in the x-z plane (+1 where the angle atan2(z, x) grows).
  const sense = Math.sign(ex * earth[5]! - ez * earth[3]!) || 1;
  const semiMajor = (st: ArrayLike<number>): number =>
    1 / (2 / Math.hypot(st[0]!, st[1]!, st[2]!) - (st[3]! ** 2 + st[4]! ** 2 + st[5]! ** 2) / mu);
  const rE = semiMajor(earth),
    rT = semiMajor(target);
  const lead = sense * (Math.atan2(target[2]!, target[0]!) - Math.atan2(ez, ex));
  const nE = Math.sqrt(mu / rE ** 3),
    nT = Math.sqrt(mu / rT ** 3);
  const transfer = Math.PI * Math.sqrt(((rE + rT) / 2) ** 3 / mu);
  const rel = nT - nE;
  const period = (2 * Math.PI) / Math.abs(rel);
  let days = ((Math.PI - nT * transfer - lead) / rel) % period;
  if (days < 0) days += period;
  out.next = days;
  out.period = period;
  return out;
}

/**
 * The state of Wait while aiming (`waitTick`): `mode` 'off', 'held' (time runs while it is held) or
 * 'run' (a tap's run to the next launch window); `waited` days run since it began (the ramp);
 * `pause` real seconds still to stand at a window; `rate` its pace at the last tick, days per real
 * second (0 standing); `lastStop` the world day it last stopped at a window (NaN for none: a window
 * there is not stopped at twice); `stopped` whether the last tick stopped at one (a chime);
 * `lastNext` the days to the next window at the last tick (NaN before the first of a Wait).
 */
export interface WaitState {
  mode: 'off' | 'held' | 'run';
  waited: number;
  pause: number;
  rate: number;
  lastStop: number;
  stopped: boolean;
  lastNext: number;
}

/** A Wait that is off. */
export function createWaitState(): WaitState {
  return { mode: 'off', waited: 0, pause: 0, rate: 0, lastStop: Number.NaN, stopped: false, lastNext: Number.NaN };
}

/** Stops a Wait at a window on world day `at`: a held one stands there WINDOW_PAUSE_S, a run ends. */
function standAt(s: WaitState, at: number): void {
  s.lastStop = at;
  s.stopped = true;
  if (s.mode === 'held') s.pause = WINDOW_PAUSE_S;
  else s.mode = 'off';
}

/**
 * Days a Wait runs time on in a tick of `tick` real seconds (> 0), and its state after: nothing when
 * off or standing at a window; else `heldWaitRate` (the ramp, slow near a window) for the tick, cut
 * at the next launch window. There a held Wait stands for WINDOW_PAUSE_S, then runs on; a tap's run
 * ends (it slows only for that window, and not for the aim). `day` the world day now, `window` the
 * next launch window from now (`nextLaunchWindow`), `aimingRate` and `aimMiss` as heldWaitRate's.
 * @throws RangeError when tick is not > 0.
 */
export function waitTick(s: WaitState, tick: number, day: number, window: LaunchWindow, aimingRate: number, aimMiss = Infinity): number {
  if (!(tick > 0)) throw new RangeError(`waitTick: tick must be > 0, got ${tick}`);
  s.stopped = false;
  if (s.mode === 'off') return 0;
  if (s.pause > 0) {
    s.pause = Math.max(0, s.pause - tick);
    s.rate = 0;
    return 0;
  }
  // The window just stopped at (within 2 days), or one under 2 days off when the Wait begins (it
  // is the window now: kept as stopped at, for the ticks after too), is behind: the next is a
  // synodic period on.
  let next = window.next;
  if (s.waited === 0) s.lastNext = Number.NaN;
  // The window went by between two ticks: the estimate of it (the planets' places) falls faster
  // than the clock near Mars's window (1.26 days a day), so a tick that ran less than the days left
  // could find it just behind, a whole period off, and a tap's run went on to the window after.
  // It stops here, a step past it.
  const passed = s.lastNext < 2 && next > window.period / 2 && !(Math.abs(day - s.lastStop) < 2);
  s.lastNext = next;
  if (passed) {
    s.rate = 0;
    standAt(s, day);
    return 0;
  }
  if (s.waited === 0 && next < 2) s.lastStop = day + next;
  if (Math.abs(day + next - s.lastStop) < 2) next += window.period;
  // A tap's run slows only for the window ahead, where it stops (not for one just gone by), and not
  // for the aim: it stops at the window whatever the aim (at AIM_NEAR_RATE a run lasted 20 s).
  const run = s.mode === 'run';
  const near = run ? next : Math.min(window.next, window.period - window.next);
  s.rate = heldWaitRate(aimingRate, s.waited, near, run ? Infinity : aimMiss);
  let days = s.rate * tick;
  if (days >= next) {
    days = next;
    standAt(s, day + next);
  }
  s.waited += days;
  return days;
}

/**
 * Whether letting go of a held Wait runs time on to the next launch window, as a tap's run does
 * (else it stops where it is let go): when it is not standing at a window (`s.pause` 0), the nearest
 * window is NEAR_WINDOW_DAYS or more away (`fromWindow`, days, either side) and the launch as aimed
 * misses by AIM_NEAR_RINGS or more (`aimMiss`, heldWaitRate's): no launch arrives there, so a stop
 * there only looked like a window. Near a window, or near an arriving aim, the player lets go to
 * launch then. @throws RangeError on a negative or NaN fromWindow or aimMiss.
 */
export function releaseRunsOn(s: WaitState, fromWindow: number, aimMiss: number): boolean {
  if (!(fromWindow >= 0)) throw new RangeError(`releaseRunsOn: fromWindow must be >= 0, got ${fromWindow}`);
  if (!(aimMiss >= 0)) throw new RangeError(`releaseRunsOn: aimMiss must be >= 0, got ${aimMiss}`);
  return s.mode === 'held' && s.pause === 0 && fromWindow >= NEAR_WINDOW_DAYS && aimMiss >= AIM_NEAR_RINGS;
}
