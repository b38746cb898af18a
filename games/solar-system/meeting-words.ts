/**
 * The solar system's verdict on a launch's meeting with the target before the mission's first failed
 * try (the page's reading line: "… is at Mars’s orbit on day 222 going out. <verdict>"), DOM-free so
 * Node tests check its wording. On the first mission (the lesson) it is exact: "✓ Mars will be there"
 * or by how many days Mars misses the probe. From the second mission on it is coarse, in bands of days
 * the player must still judge on the map ("Mars will be close", "a little behind", "far ahead"), with
 * no ✓ and in one colour: exact, every mission became "press ↑ until green, hold Wait until ✓". The
 * exact verdict (the ring at arrival) comes back after a failed try.
 */

/** Within this many days of the probe at its meeting point the target is "close" (the coarse verdict). */
export const CLOSE_DAYS = 25;
/** Beyond this many days it is "far" behind or ahead; between, "a little". */
export const FAR_DAYS = 90;

/**
 * The verdict and its line class ('ok', 'bad' or, for the coarse words, 'edge'). `target` the
 * target's name; `lag` days the target reaches the probe's meeting point after the probe (negative:
 * before; ./orbit-crossing.ts targetLag); `arrived` whether the forecast arrives; `exact` whether to
 * say it exactly (the first mission); `stars` the stars the launch speed earns, as text; `closest`
 * the words for a near miss within a day ("closest 0.2 AU, 1.4 rings off"). @throws RangeError on a NaN lag.
 */
export function meetingWords(
  target: string,
  lag: number,
  arrived: boolean,
  exact: boolean,
  stars: string,
  closest: string,
): [string, string] {
  if (Number.isNaN(lag)) throw new RangeError('meetingWords: lag must be a number, got NaN');
  const days = Math.round(Math.abs(lag));
  if (!exact) {
    // Bands wider than the days that arrive (Mars about 10 either side), so "close" is no ✓.
    if (days <= CLOSE_DAYS) return [`${target} will be close`, 'edge'];
    const side = lag > 0 ? 'behind' : 'ahead';
    return [`${target} will be ${days > FAR_DAYS ? 'far' : 'a little'} ${side}`, 'edge'];
  }
  if (arrived) return [`✓ ${target} will be there · ${stars}`, 'ok'];
  const n = `${days} day${days === 1 ? '' : 's'}`;
  if (days < 1) return [`✗ misses ${target}: ${closest}`, 'bad'];
  // Short: the line should stay on one line at desktop size where it can.
  return [lag > 0 ? `✗ ${target} gets there ${n} later` : `✗ ${target} passed there ${n} before`, 'bad'];
}
