// The finger's power ring kept on the canvas (games/bouncing-balls/pull-fit.ts ringInside). Figures
// from 390 x 844 (a ball by the left wall at x 12 px; the ring's outer edge 44 px from its centre).
import { describe, expect, it } from 'vitest';
import { pressInBox, ringInside } from '../../games/bouncing-balls/pull-fit';

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

// A press on the steel frame round the box (the phone's 15 px strips beside its walls did nothing).
describe('bouncing-balls pressInBox', () => {
  const min = [0, 0],
    max = [8, 14];
  it('moves a press beside the box onto its side wall and one over it onto its top', () => {
    expect(pressInBox(-0.3, 5, min, max)).toEqual([0, 5]);
    expect(pressInBox(8.4, 5, min, max)).toEqual([8, 5]);
    expect(pressInBox(4, 14.5, min, max)).toEqual([4, 14]);
  });
  it('leaves a press inside the box, and one under its floor (the stand), where it is', () => {
    expect(pressInBox(3, 7, min, max)).toEqual([3, 7]);
    expect(pressInBox(3, -1.2, min, max)).toEqual([3, -1.2]);
  });
});
