/**
 * Catapult's full pull (games/catapult/pull.ts): how long a drag on the screen throws at full power.
 * On a phone held upright a stranger needed a drag to the screen's edge (0.9 of its width) for a full
 * pull; a thumb's drag from the screen's middle back to the catapult's side is about half the width.
 */

import { describe, expect, it } from 'vitest';
import { FULL_PULL_MAX_PX, fullPullPx } from '../../games/catapult/pull';

describe('catapult full pull', () => {
  it("upright phones: a full pull is a thumb's drag, at most 55 % of the width and at least 150 px", () => {
    for (const [w, h] of [
      [320, 640],
      [360, 780],
      [390, 844],
      [430, 932],
    ] as const) {
      const px = fullPullPx(w, h, true);
      // At most 55 % of the width: from the screen's middle, a drag down and back at 30 degrees
      // (cos 30 = 0.87 of it across) stays on the screen with room for the thumb.
      expect(px, `${w} x ${h}`).toBeLessThanOrEqual(0.55 * w);
      // At least 150 px: a pixel of drag is under 0.7 % of full power.
      expect(px, `${w} x ${h}`).toBeGreaterThanOrEqual(150);
    }
    expect(fullPullPx(390, 844, true)).toBe(195);
  });

  it('a desktop keeps its long pull: 380 px at 1280 x 800 (and 1060 x 800, the canvas beside the side column)', () => {
    expect(fullPullPx(1280, 800, false)).toBe(FULL_PULL_MAX_PX);
    expect(fullPullPx(1060, 800, false)).toBe(FULL_PULL_MAX_PX);
    // A phone held sideways (844 x 390): 0.32 of the diagonal, 297 px.
    expect(fullPullPx(844, 390, false)).toBeCloseTo(0.32 * Math.hypot(844, 390), 6);
    expect(() => fullPullPx(0, 800, false)).toThrow(RangeError);
  });
});
