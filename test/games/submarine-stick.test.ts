/**
 * The submarine's on-screen stick (games/submarine/stick.ts): a small radial dead zone, then each
 * axis in proportion to its own push, so a push mostly sideways with some down dives gently too.
 */

import { describe, expect, it } from 'vitest';
import {
  STICK_AXIS,
  STICK_DEAD,
  STICK_LEVEL_ANGLE,
  STICK_MIN_SHARE,
  stickDirection,
  stickHeaveDirection,
  stickShare,
} from '../../games/submarine/stick';

/** The stick's push for a thumb at (dx, dy) px (y down) on a phone's 56 px reach, clamped to the unit disc as game-kit's stick reports it (y up). */
function push(dx: number, dy: number): { x: number; y: number } {
  const r = Math.hypot(dx, dy) / 56,
    s = r > 1 ? 1 / r : 1;
  return { x: (dx / 56) * s, y: (-dy / 56) * s };
}

describe('submarine stick', () => {
  it('60 px right and 20 px down asks for Ahead and a Dive (issue 34: no dive at all), in proportion to each push', () => {
    const p = push(60, 20);
    expect(stickDirection(p.x, p.y)).toBe(1); // ahead
    expect(stickDirection(p.y, p.x)).toBe(-1); // dive
    expect(stickHeaveDirection(p.y, p.x)).toBe(-1); // 18 degrees low moves the depth order
    expect(stickShare(p.x, false)).toBeCloseTo((Math.abs(p.x) - STICK_AXIS) / (1 - STICK_AXIS), 12);
    // More push down, more dive: the share grows with the push from STICK_MIN_SHARE to 1 at the rim.
    let last = 0;
    for (let dy = 12; dy <= 56; dy += 4) {
      const q = push(0, dy);
      expect(stickDirection(q.y, q.x)).toBe(-1);
      const share = stickShare(q.y, false);
      expect(share).toBeGreaterThanOrEqual(Math.max(last, STICK_MIN_SHARE));
      last = share;
    }
    expect(last).toBe(1);
  });

  it('nothing inside the radial dead zone; a thumb wobble of a few px across a push does not ask along that axis', () => {
    const still = push(0.9 * STICK_DEAD * 56 * Math.SQRT1_2, 0.9 * STICK_DEAD * 56 * Math.SQRT1_2);
    expect(stickDirection(still.x, still.y)).toBe(0);
    expect(stickDirection(still.y, still.x)).toBe(0);
    const up = push(6, -50); // straight up with 6 px of wobble sideways
    expect(stickDirection(up.y, up.x)).toBe(1);
    expect(stickDirection(up.x, up.y)).toBe(0);
    // A key asks for all of it.
    expect(stickShare(0.3, true)).toBe(1);
    expect(() => stickDirection(2, 0)).toThrow(/stickDirection: v/);
    expect(() => stickShare(Number.NaN, false)).toThrow(/stickShare: v/);
  });

  it('a push within STICK_LEVEL_ANGLE (14 degrees) of the horizontal does not move the depth order; steeper, it does', () => {
    // Issue 34: Ahead held 10 degrees low ran the order down 1.6 m/s (the boat drifted off its depth).
    for (const deg of [0, 5, 10, 13]) {
      const p = push(56 * Math.cos((deg * Math.PI) / 180), 56 * Math.sin((deg * Math.PI) / 180));
      expect(stickDirection(p.y, p.x), `${deg} degrees`).toBe(deg === 0 ? 0 : deg < 10 ? 0 : -1);
      expect(stickHeaveDirection(p.y, p.x), `${deg} degrees`).toBe(0);
      expect(stickHeaveDirection(-p.y, -p.x), `${deg} degrees up, astern`).toBe(0);
    }
    for (const deg of [15, 30, 45, 90]) {
      const p = push(56 * Math.cos((deg * Math.PI) / 180), 56 * Math.sin((deg * Math.PI) / 180));
      expect(stickHeaveDirection(p.y, p.x), `${deg} degrees`).toBe(-1);
      expect(stickHeaveDirection(-p.y, p.x), `${deg} degrees up`).toBe(1);
    }
    expect(STICK_LEVEL_ANGLE).toBeCloseTo((14 * Math.PI) / 180, 12);
    expect(() => stickHeaveDirection(0, 2)).toThrow(/stickDirection: other/);
  });
});
