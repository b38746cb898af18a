/**
 * The solar system's verdict on a launch before the first failed try (games/solar-system/meeting-words.ts):
 * exact on the first mission (the lesson), coarse from the second on, so the player judges the map
 * instead of pressing ↑ and holding Wait until a ✓ shows.
 */

import { describe, expect, test } from 'vitest';
import { CLOSE_DAYS, FAR_DAYS, meetingWords } from '../../games/solar-system/meeting-words';

describe('meetingWords', () => {
  test('the first mission: ✓ on an arrival, else the days Mars misses by', () => {
    expect(meetingWords('Mars', 2, true, true, '★★★', 'closest x')).toEqual(['✓ Mars will be there · ★★★', 'ok']);
    expect(meetingWords('Mars', 23, false, true, '★★★', 'closest x')).toEqual(['✗ Mars gets there 23 days later', 'bad']);
    expect(meetingWords('Mars', -1, false, true, '★★★', 'closest x')).toEqual(['✗ Mars passed there 1 day before', 'bad']);
    expect(meetingWords('Mars', 0.3, false, true, '★★★', 'closest x')).toEqual(['✗ misses Mars: closest x', 'bad']);
  });

  test('from the second mission: no ✓, no days, one colour; an arrival and a near miss read the same', () => {
    const coarse = (lag: number, arrived: boolean) => meetingWords('Venus', lag, arrived, false, '★★', 'closest x');
    // An arrival and a 20-day miss both "close" (the days that arrive span about ±5 for Venus).
    expect(coarse(1, true)).toEqual(['Venus will be close', 'edge']);
    expect(coarse(-20, false)).toEqual(['Venus will be close', 'edge']);
    expect(coarse(CLOSE_DAYS, false)).toEqual(['Venus will be close', 'edge']);
    expect(coarse(CLOSE_DAYS + 1, false)).toEqual(['Venus will be a little behind', 'edge']);
    expect(coarse(-60, false)).toEqual(['Venus will be a little ahead', 'edge']);
    expect(coarse(FAR_DAYS + 1, false)).toEqual(['Venus will be far behind', 'edge']);
    expect(coarse(-300, false)).toEqual(['Venus will be far ahead', 'edge']);
    for (const lag of [-400, -50, -3, 0, 3, 50, 400])
      for (const arrived of [false, true]) expect(coarse(lag, arrived)[0]).not.toMatch(/✓|✗|\d|there/);
    expect(() => meetingWords('Mars', Number.NaN, false, false, '', '')).toThrow(/lag must be a number/);
  });
});
