import { describe, expect, it } from 'vitest';
import { FINGER_PX, gaugeCentre, TOUCH_LIFT } from '../../games/fireworks/gauge';

describe('fireworks hold gauge placement', () => {
  const W = 390,
    H = 700,
    ring = 20,
    room = 18;
  it('goes round a mouse pointer', () => {
    expect(gaugeCentre(100, 300, false, W, H, ring, room)).toEqual([100, 300]);
  });
  it('on a touch screen, sits above the finger, its whole ring clear of the fingertip', () => {
    const [gx, gy] = gaugeCentre(200, 400, true, W, H, ring, room);
    expect(gx).toBe(200);
    expect(gy).toBeLessThan(400);
    // The ring's nearest point to the finger is further than the fingertip covers.
    expect(Math.hypot(gx - 200, gy - 400) - ring).toBeGreaterThan(FINGER_PX);
  });
  it('near the top of the stage, goes to the side with more room, still clear of the finger and on the stage', () => {
    for (const x of [30, 120, 280, 370]) {
      const [gx, gy] = gaugeCentre(x, 50, true, W, H, ring, room);
      expect(gy).toBe(50);
      expect(Math.hypot(gx - x, gy - 50) - ring).toBeGreaterThan(FINGER_PX);
      expect(gx - ring).toBeGreaterThanOrEqual(0);
      expect(gx + ring).toBeLessThanOrEqual(W);
    }
    // Just high enough for the lifted ring and its label: lifted.
    expect(gaugeCentre(100, TOUCH_LIFT + ring + room, true, W, H, ring, room)).toEqual([100, ring + room]);
  });
  it('throws on bad input, naming the function', () => {
    expect(() => gaugeCentre(Number.NaN, 1, true, W, H, ring, room)).toThrow(/gaugeCentre/);
    expect(() => gaugeCentre(1, 1, true, 0, H, ring, room)).toThrow(/gaugeCentre/);
  });
});
