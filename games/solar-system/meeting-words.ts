/**
 * The solar system's verdict on a launch's meeting with the target before the mission's first failed
 * try (the page's reading line: "… is at Mars’s orbit on day 222 going out. <verdict>"), DOM-free so
 * Node tests check its wording. On the first mission (the lesson) it is exact (`meetingWords`): "✓
 * Mars will be there" or by how many days Mars misses the probe. From the second mission on it is
 * coarse (`coarseWords`), in bands of how centred the aim is, which the player must still judge on
 * the map ("Mars will be close": three-star centred; "a little behind", "far ahead"), with no ✓
 * and in one colour:
 * exact, every mission became "press ↑ until green, hold Wait until ✓". The exact verdict (the ring
 * at arrival) comes back after a failed try.
 */

import { STAR_RINGS } from './aim-depth';
import type { Forecast } from './forecast';
import { closestSide } from './orbit-crossing';

/**
 * At most this many arrival rings the target is "close": the aim is centred as three stars want
 * (./aim-depth.ts STAR_RINGS: its path, flown on past the ring's edge, comes within half a ring of
 * the target's centre). A band of 1.2 rings read "close" for every launch from 2.3 to 3.1 km/s to
 * Venus, all of which arrived, so the word told nothing; now "a little" also covers arrivals that
 * only graze the ring (two stars at most). scripts/solar-system-stars.mjs plays it.
 */
export const CLOSE_RINGS = STAR_RINGS;
/** Beyond this many rings it is "far" behind or ahead; between CLOSE_RINGS and it, "a little". */
export const FAR_RINGS = 5;

/**
 * The coarse verdict from the second mission on, and its class ('edge': one colour, no ✓): how near
 * the aim comes to the target, in bands of `rings` (its closest approach over the zone's radius,
 * >= 0), and on which side the target is then, `side` (+1: still to come, "behind"; -1: gone by,
 * "ahead"; ./orbit-crossing.ts closestSide). @throws RangeError on a negative or NaN `rings`.
 */
export function coarseWords(target: string, rings: number, side: number): [string, string] {
  if (!(rings >= 0)) throw new RangeError(`coarseWords: rings must be >= 0, got ${rings}`);
  if (rings <= CLOSE_RINGS) return [`${target} will be close`, 'edge'];
  return [`${target} will be ${rings > FAR_RINGS ? 'far' : 'a little'} ${side > 0 ? 'behind' : 'ahead'}`, 'edge'];
}

/**
 * The coarse verdict on the launch `forecast` is of (the page's forecast: the flight flown ahead with
 * the flight's own physics, ./forecast.ts): `coarseWords` of its closest approach to the target over
 * `zone` (the arrival ring's radius, AU > 0) and the target's side then (`closestSide`, `target` its
 * heliocentric state now). An arrival's forecast stops at the ring's edge, so for one `depth` (the
 * aim's ./aim-depth.ts aimRings, when given) says how centred it is instead.
 * @throws RangeError when zone is not > 0.
 */
export function forecastWords(name: string, forecast: Forecast, zone: number, target: ArrayLike<number>, depth?: number): [string, string] {
  if (!(zone > 0)) throw new RangeError(`forecastWords: zone must be > 0, got ${zone}`);
  const rings = forecast.outcome === 'arrived' && depth !== undefined ? depth : forecast.closest / zone;
  return coarseWords(name, rings, closestSide(forecast, target));
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
