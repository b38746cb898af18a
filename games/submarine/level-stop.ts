/**
 * The beacon's depth as a stop on the way down or up: a held Dive or Rise whose depth order (./helm.ts
 * `HelmState.holdY`, where the boat would stop if let go) reaches the target beacon's depth stops
 * there, as if the key had been let go at the right moment, and holds the boat level with the
 * beacon until it has been stopped there `LEVEL_STOP_HOLD` s (at most `LEVEL_STOP_MOST` s in all);
 * a key still held then takes the boat on past it. Strangers could not tell whether the boat would
 * reach the beacon's depth, and let go too late or too early: a held key at 5 to 8 m/s, a reaction
 * of half a second and the boat's run-on put the stop 5 to 10 m off, the edge of the ring's reach
 * (`LEVEL_BAND`). Once per press: let go and pressed again, the boat goes on at once. Headless (no
 * drawing or sound), so it is tested in node.
 */

import { SUBMARINE } from '@bitphysics/projects';
import { BEACON_CATCH } from './beacons';

/**
 * How far the hull's centre may pass over or under a beacon and still collect it going straight
 * past, m: the ring's reach (`BEACON_CATCH`) plus half the hull's height, less a metre and a half
 * for the waves, the pitch and the boat settling on its depth. The page shows the boat "level" with
 * the target within it.
 */
export const LEVEL_BAND = BEACON_CATCH + SUBMARINE.height / 2 - 1.5;

/**
 * How long the boat holds the beacon's depth once stopped there while Dive or Rise is still held, s:
 * long enough for a player who watches the hull to see it level with the ring and let go (a reaction
 * of 0.25 to 0.7 s), short enough that a player who means to go on is not kept waiting.
 */
export const LEVEL_STOP_HOLD = 0.8;

/** The longest the stop lasts from the moment the order reached the beacon's depth, s (the boat braking onto it included). */
export const LEVEL_STOP_MOST = 3;

/** Within this of the beacon's depth (m) and slower than `LEVEL_STOPPED_SPEED` (m/s) the boat counts as stopped there. */
export const LEVEL_STOPPED_NEAR = 0.6;
/** See `LEVEL_STOPPED_NEAR`, m/s. */
export const LEVEL_STOPPED_SPEED = 0.4;

/** What the stop keeps between steps. */
export interface LevelStop {
  /** The press it belongs to: -1 dive, 1 rise, 0 none held. */
  dir: -1 | 0 | 1;
  /** The target beacon the press started with (-1: none). */
  beacon: number;
  /** Which side of the beacon's depth the press started on: -1 under, 1 over it, 0 none (no stop this press). */
  side: -1 | 0 | 1;
  /** Game time the order reached the beacon's depth, s; NaN while no stop runs. */
  since: number;
  /** Game time the boat was first stopped on the beacon's depth, s; NaN until then. */
  stoppedAt: number;
  /** Whether this press's stop has been made (it is made once a press). */
  done: boolean;
}

/** A stop with no press running. */
export function createLevelStop(): LevelStop {
  return { dir: 0, beacon: -1, side: 0, since: Number.NaN, stoppedAt: Number.NaN, done: false };
}

/** What `levelStop` reads of the step about to run. */
export interface LevelStopStep {
  /** Dive or Rise asked for this step: -1 dive, 1 rise, 0 neither. */
  dir: -1 | 0 | 1;
  /** Game time, s. */
  now: number;
  /** The target beacon's index (-1: none) and its depth as a height, m (y up, negative under water). */
  beacon: number;
  beaconY: number;
  /** The depth order after the last step, m (NaN while none), and the hull's height and vertical speed, m and m/s. */
  order: number;
  y: number;
  vy: number;
  /** Whether a mine or the seabed is warned of on the course: the stop is not made then (the player dives or rises away from it). */
  warned: boolean;
}

/**
 * One step of the stop: whether Dive or Rise, asked for this step, is held back (the boat holds
 * `beaconY` instead: the page sets the order there and steers with neither). A press that starts
 * over (under) the beacon's depth and dives (rises) toward it stops when the order reaches that
 * depth, then the boat brakes onto it and holds it until it has been stopped there `LEVEL_STOP_HOLD`
 * s, or `LEVEL_STOP_MOST` s from the start; then the press goes on. A press started level with the
 * beacon, or away from it, or a warning on the course, makes no stop; nor does a second one of the
 * same press.
 * @throws RangeError when `now`, `y` or `vy` is not finite.
 */
export function levelStop(stop: LevelStop, s: LevelStopStep): boolean {
  if (!Number.isFinite(s.now)) throw new RangeError(`levelStop: now must be finite s, got ${s.now}`);
  if (!Number.isFinite(s.y)) throw new RangeError(`levelStop: y must be finite m, got ${s.y}`);
  if (!Number.isFinite(s.vy)) throw new RangeError(`levelStop: vy must be finite m/s, got ${s.vy}`);
  const valid = s.beacon >= 0 && Number.isFinite(s.beaconY);
  if (s.dir !== stop.dir || s.dir === 0) {
    // A new press (or none): the side it starts on, from where the boat was going to stop.
    const from = Number.isFinite(s.order) ? s.order : s.y;
    stop.dir = s.dir;
    stop.beacon = s.beacon;
    stop.since = stop.stoppedAt = Number.NaN;
    stop.done = false;
    const d = valid ? from - s.beaconY : 0;
    // Only toward the beacon's depth, and from more than a metre off it.
    stop.side = s.dir !== 0 && valid && Math.abs(d) > 1 && Math.sign(d) === -s.dir ? (Math.sign(d) as -1 | 1) : 0;
    if (s.dir === 0) return false;
  }
  if (stop.done || stop.side === 0 || s.beacon !== stop.beacon || !valid) return false;
  if (Number.isNaN(stop.since)) {
    // Running on: the stop starts when the order reaches the beacon's depth, unless a warning asks to go on.
    if (s.warned || !Number.isFinite(s.order) || Math.sign(s.order - s.beaconY) === stop.side) return false;
    stop.since = s.now;
  }
  if (Number.isNaN(stop.stoppedAt) && Math.abs(s.y - s.beaconY) < LEVEL_STOPPED_NEAR && Math.abs(s.vy) < LEVEL_STOPPED_SPEED)
    stop.stoppedAt = s.now;
  const over = s.now - stop.since >= LEVEL_STOP_MOST || s.now - stop.stoppedAt >= LEVEL_STOP_HOLD;
  if (over) stop.done = true;
  return !over;
}

/**
 * Where the boat stands to the beacon's depth `beaconY` (m, y up): by the depth it is going to
 * (`order`, m; the hull's height `y` while none): 0 level with it (within `LEVEL_BAND`), 1 over it,
 * -1 under it, and the metres from it to the band's edge (0 when level).
 */
export function levelWith(order: number, y: number, beaconY: number): { side: -1 | 0 | 1; off: number } {
  const d = (Number.isFinite(order) ? order : y) - beaconY;
  if (Math.abs(d) <= LEVEL_BAND) return { side: 0, off: 0 };
  return { side: d > 0 ? 1 : -1, off: Math.abs(d) - LEVEL_BAND };
}
