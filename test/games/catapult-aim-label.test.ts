/**
 * Where the catapult's aim numbers go (games/catapult/aim-label.ts), headless: the distance from the
 * pull's band to a box against hand-worked cases, and the choice of the first place clear of the band.
 */

import { describe, expect, it } from 'vitest';
import { type Box, placeAimLabel, segmentBoxDistance } from '../../games/catapult/aim-label';

const box: Box = { x: 100, y: 100, w: 50, h: 20 };

describe('catapult aim label', () => {
  it('segmentBoxDistance: 0 through or into the box, else the gap to its nearest side or corner (to 1e-6 px)', () => {
    // Through the box, and ending inside it.
    expect(segmentBoxDistance(0, 110, 300, 110, box)).toBe(0);
    expect(segmentBoxDistance(0, 0, 120, 110, box)).toBe(0);
    // Level with the box, 30 px under it; ending 10 px short of its left side.
    expect(segmentBoxDistance(0, 150, 300, 150, box)).toBeCloseTo(30, 6);
    expect(segmentBoxDistance(0, 110, 90, 110, box)).toBeCloseTo(10, 6);
    // Passing the top-right corner (150, 100) diagonally: the line x - y = 60 is 10 / sqrt 2 from it
    // (and farther from the other corners, where x - y is 0, -20 and 30).
    expect(segmentBoxDistance(60, 0, 300, 240, box)).toBeCloseTo(10 / Math.SQRT2, 6);
    // A point (a press with no pull yet).
    expect(segmentBoxDistance(160, 95, 160, 95, box)).toBeCloseTo(Math.hypot(10, 5), 6);
  });

  it('placeAimLabel: the first place clear of the band (a stranger pulled the knob onto the numbers), else the farthest', () => {
    const over: Box = { x: 10, y: 440, w: 200, h: 50 },
      under: Box = { x: 10, y: 640, w: 200, h: 50 },
      above: Box = { x: 10, y: 300, w: 200, h: 50 };
    // The knob over the catapult (the first place): the next place clear of it.
    expect(placeAimLabel([over, under, above], [270, 380, 60, 470], 15)).toBe(1);
    // The band far from the catapult: over it.
    expect(placeAimLabel([over, under, above], [300, 200, 250, 260], 15)).toBe(0);
    // Every place within 15 px of the band: the farthest (above, 12 px from the band's end at y 362).
    expect(placeAimLabel([over, under, above], [100, 362, 100, 700], 15)).toBe(2);
  });

  it('rejects bad input, naming the function and the value', () => {
    expect(() => placeAimLabel([], [0, 0, 1, 1], 15)).toThrow(/placeAimLabel: boxes/);
    expect(() => placeAimLabel([box], [0, 0, 1, 1], -1)).toThrow(/placeAimLabel: clearance .* got -1/);
  });
});
