/**
 * Wrecking ball, the cap on how far the camera draws back when its framing widens
 * (games/wrecking-ball/zoom-cap.ts): a widened framing stands at most WIDEN_MAX times the site's
 * framing distance from its target, on the same line of sight, so the structures keep at least
 * 1 / WIDEN_MAX of their framed size on the screen. Tolerance 1e-9 m (floating point only).
 */
import { describe, expect, it } from 'vitest';
import { capDistance, WIDEN_MAX } from '../../games/wrecking-ball/zoom-cap';

describe('wrecking ball zoom cap', () => {
  it('keeps the widened framing within 1.2 to 2 times the framing distance', () => {
    expect(WIDEN_MAX).toBeGreaterThanOrEqual(1.2);
    expect(WIDEN_MAX).toBeLessThanOrEqual(2);
  });
  it('brings a far camera in along its line of sight to the limit, and leaves a near one', () => {
    const target = { x: 1, y: 2, z: 3 };
    const far = { x: 1 + 30, y: 2 + 40, z: 3 };
    expect(capDistance(far, target, 20 * WIDEN_MAX)).toBe(true);
    expect(Math.hypot(far.x - 1, far.y - 2, far.z - 3)).toBeCloseTo(30, 9);
    // Same direction (3 : 4) as before.
    expect((far.y - 2) / (far.x - 1)).toBeCloseTo(4 / 3, 9);
    const near = { x: 1 + 6, y: 2 + 8, z: 3 };
    expect(capDistance(near, target, 30)).toBe(false);
    expect(near).toEqual({ x: 7, y: 10, z: 3 });
  });
});
