/**
 * The solar system's verdict on a launch's meeting with the target before the mission's first failed
 * try (the page's reading line: "… is at Mars’s orbit on day 222 going out. <verdict>"), DOM-free so
 * Node tests check its wording. A launch whose forecast (the flight flown ahead with the flight's own
 * physics and arrival ring, ./forecast.ts) arrives reads "✓ Mars will be there" and its stars on
 * every mission, as the flight's own verdict does once launched. A miss on the first mission (the
 * lesson) says by how many days the target misses the probe (`meetingWords`); from the second on it
 * is coarse (`coarseWords`), in bands of the miss the player must still judge on the map ("Venus
 * will be close", "a little behind", "far ahead"), no days and one colour. A ✓ is for a launch now
 * only: while time runs, the forecast shown is of a moment already gone (`staleWords`).
 */

import type { Forecast } from './forecast';
import { closestSide } from './orbit-crossing';

/**
 * A miss whose closest approach is at most this many arrival rings (the ring's radius) from the
 * target's centre is "close": a near miss, a few presses off. "Close" read an arrival before (a
 * centred one) and never said ✓, while the flight launched on it said "✓ arrives": the line before
 * the launch and the flight's disagreed.
 */
export const CLOSE_RINGS = 2;
/** Beyond this many rings it is "far" behind or ahead; between CLOSE_RINGS and it, "a little". */
export const FAR_RINGS = 5;

/**
 * The coarse verdict on a miss from the second mission on, and its class ('edge': one colour, no
 * ✓): how near the aim comes to the target, in bands of `rings` (its closest approach over the
 * zone's radius, >= 0), and on which side the target is then, `side` (+1: still to come, "behind";
 * -1: gone by, "ahead"; ./orbit-crossing.ts closestSide). @throws RangeError on a negative or NaN `rings`.
 */
export function coarseWords(target: string, rings: number, side: number): [string, string] {
  if (!(rings >= 0)) throw new RangeError(`coarseWords: rings must be >= 0, got ${rings}`);
  if (rings <= CLOSE_RINGS) return [`${target} will be close`, 'edge'];
  return [`${target} will be ${rings > FAR_RINGS ? 'far' : 'a little'} ${side > 0 ? 'behind' : 'ahead'}`, 'edge'];
}

/**
 * The verdict from the second mission on of the launch `forecast` is of (the page's forecast: the
 * flight flown ahead with the flight's own physics, ./forecast.ts): on an arrival "✓ Venus will be
 * there" and `stars` (the stars the launch earns, as text), the flight's own rule; else
 * `coarseWords` of its closest approach to the target over `zone` (the arrival ring's radius, AU >
 * 0) and the target's side then (`closestSide`, `target` its heliocentric state now).
 * @throws RangeError when zone is not > 0.
 */
export function forecastWords(name: string, forecast: Forecast, zone: number, target: ArrayLike<number>, stars = ''): [string, string] {
  if (!(zone > 0)) throw new RangeError(`forecastWords: zone must be > 0, got ${zone}`);
  if (forecast.outcome === 'arrived') return [`✓ ${name} will be there${stars === '' ? '' : ` · ${stars}`}`, 'ok'];
  return coarseWords(name, forecast.closest / zone, closestSide(forecast, target));
}

/**
 * The words for a launch whose forecast arrives but is not of the launch made now: time runs, and
 * the forecast shown was worked out for a moment already gone (at 15 days a second it lagged 12
 * days, and a ✓ shown then missed by 0.18 AU). No ✓: the player stops time (lets go of Wait, taps
 * Stop) and the forecast of the launch then says ✓ or not. `target` the target's name.
 */
export function staleWords(target: string): [string, string] {
  return [`${target} about there: stop time to check`, 'edge'];
}

/**
 * The first mission's exact verdict and its line class ('ok' or 'bad'). `target` the target's
 * name; `lag` days the target reaches the probe's meeting point after the probe (negative: before;
 * ./orbit-crossing.ts targetLag); `arrived` whether the forecast arrives; `stars` the stars the
 * launch speed earns, as text; `closest` the words for a near miss within a day ("closest 0.2 AU,
 * 1.4 rings off"). @throws RangeError on a NaN lag.
 */
export function meetingWords(target: string, lag: number, arrived: boolean, stars: string, closest: string): [string, string] {
  if (Number.isNaN(lag)) throw new RangeError('meetingWords: lag must be a number, got NaN');
  const days = Math.round(Math.abs(lag));
  if (arrived) return [`✓ ${target} will be there · ${stars}`, 'ok'];
  const n = `${days} day${days === 1 ? '' : 's'}`;
  if (days < 1) return [`✗ misses ${target}: ${closest}`, 'bad'];
  // Short: the line should stay on one line at desktop size where it can.
  return [lag > 0 ? `✗ ${target} gets there ${n} later` : `✗ ${target} passed there ${n} before`, 'bad'];
}
