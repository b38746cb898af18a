/**
 * The solar system's verdict on a launch before the first failed try (games/solar-system/meeting-words.ts):
 * ✓ on every arrival, as the flight's own verdict; a miss exact on the first mission (the lesson),
 * coarse from the second on, so the player judges the map to find the arrival.
 */

import { describe, expect, test } from 'vitest';
import { CLOSE_RINGS, coarseWords, FAR_RINGS, meetingWords, staleWords } from '../../games/solar-system/meeting-words';

describe('meetingWords', () => {
  test('the first mission: ✓ on an arrival, else the days Mars misses by', () => {
    expect(meetingWords('Mars', 2, true, '★★★', 'closest x')).toEqual(['✓ Mars will be there · ★★★', 'ok']);
    expect(meetingWords('Mars', 23, false, '★★★', 'closest x')).toEqual(['✗ Mars gets there 23 days later', 'bad']);
    expect(meetingWords('Mars', -1, false, '★★★', 'closest x')).toEqual(['✗ Mars passed there 1 day before', 'bad']);
    expect(meetingWords('Mars', 0.3, false, '★★★', 'closest x')).toEqual(['✗ misses Mars: closest x', 'bad']);
  });

  test('from the second mission: ✓ on an arrival (with its stars); a miss in bands of its closest approach in rings, no days, one colour', () => {
    const coarse = (rings: number, side: number) => coarseWords('Venus', rings, side);
    // "Close" is a near miss (an arrival reads ✓, ./solar-system-coarse.test.ts).
    expect(coarse(1.4, 1)).toEqual(['Venus will be close', 'edge']);
    expect(coarse(CLOSE_RINGS, -1)).toEqual(['Venus will be close', 'edge']);
    expect(coarse(CLOSE_RINGS + 0.01, 1)).toEqual(['Venus will be a little behind', 'edge']);
    expect(coarse(3, -1)).toEqual(['Venus will be a little ahead', 'edge']);
    expect(coarse(FAR_RINGS + 0.01, 1)).toEqual(['Venus will be far behind', 'edge']);
    expect(coarse(40, -1)).toEqual(['Venus will be far ahead', 'edge']);
    for (const rings of [1, 1.9, 2.5, 9]) for (const side of [1, -1]) expect(coarse(rings, side)[0]).not.toMatch(/✓|✗|\d|there/);
    expect(() => coarseWords('Mars', Number.NaN, 1)).toThrow(/rings must be >= 0/);
    expect(() => meetingWords('Mars', Number.NaN, false, '', '')).toThrow(/lag must be a number/);
  });

  test('while time runs an arrival is not a ✓: the forecast is of a moment gone', () => {
    expect(staleWords('Mars')).toEqual(['Mars about there: stop time to check', 'edge']);
    expect(staleWords('Venus')[0]).not.toMatch(/✓/);
  });
});
