/**
 * Black hole's velocity tick (games/black-hole/view.ts `velocityTick`, drawn by main.ts from the
 * ship). The issue this answers: with the path off the ship always points up, so nothing showed
 * which way it moved; a stranger on level 5 drifted left into a hole with the nose up. The tick
 * points along the velocity (screen y down) and grows with speed.
 */
import { describe, expect, test } from 'vitest';
import { TICK_MIN_SPEED, velocityTick } from '../../games/black-hole/view';

describe('black hole: the velocity tick', () => {
  test('points along the velocity on screen (y down), longer the faster, none near rest', () => {
    const k = 20;
    // Drifting left: the tick points left, level (exact: a pure function of the velocity).
    const left = velocityTick(-3, 0, k)!;
    expect(left[0]).toBeLessThan(0);
    expect(left[1]).toBeCloseTo(0, 12);
    // Climbing right: screen x right, screen y up (negative).
    const [ux, uy] = velocityTick(2, 2, k)!;
    expect(ux).toBeGreaterThan(0);
    expect(uy).toBeLessThan(0);
    expect(Math.abs(ux + uy)).toBeLessThan(1e-9);
    // Length grows with speed, from 0.8 k to at most 2.4 k (readable next to a 1 k ship, never a stick).
    let last = 0;
    for (const v of [0.5, 1, 2, 4, 8, 12]) {
      const t = velocityTick(0, v, k)!;
      const len = Math.hypot(t[0], t[1]);
      expect(len).toBeGreaterThanOrEqual(last);
      expect(len).toBeGreaterThanOrEqual(0.8 * k - 1e-9);
      expect(len).toBeLessThanOrEqual(2.4 * k + 1e-9);
      last = len;
    }
    expect(Math.hypot(...velocityTick(0, 8, k)!)).toBeGreaterThan(Math.hypot(...velocityTick(0, 1, k)!) + 0.5 * k);
    // At rest (parked) or nearly: no tick.
    expect(velocityTick(0, 0, k)).toBeNull();
    expect(velocityTick(TICK_MIN_SPEED / 2, 0, k)).toBeNull();
    expect(velocityTick(Number.NaN, 1, k)).toBeNull();
  });
});
