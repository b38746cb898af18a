// The finger's power ring kept on the canvas (games/bouncing-balls/pull-fit.ts ringInside). Figures
// from 390 x 844 (a ball by the left wall at x 12 px; the ring's outer edge 44 px from its centre).
import { describe, expect, it } from 'vitest';
import { ringInside } from '../../games/bouncing-balls/pull-fit';

describe('bouncing-balls ringInside', () => {
  it('keeps a 44 px ring round a finger at the left edge wholly on a 390 px wide canvas', () => {
    const [x, y] = ringInside(12, 600, 44, 390, 722);
    expect(x - 44).toBeGreaterThanOrEqual(0);
    expect(x).toBe(46);
    expect(y).toBe(600);
  });
  it('moves it in from the right and bottom edges, and leaves one inside where it is', () => {
    expect(ringInside(388, 720, 44, 390, 722)).toEqual([344, 676]);
    expect(ringInside(200, 300, 44, 390, 722)).toEqual([200, 300]);
  });
  it('centres it on an axis the canvas is too small for', () => {
    expect(ringInside(5, 5, 44, 60, 500)[0]).toBe(30);
  });
});
