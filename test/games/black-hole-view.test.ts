/**
 * Black hole's field beside the open settings panel (games/black-hole/view.ts): on a wide window the
 * panel opened over the field's top right corner and hid the finish line and the ship's path there.
 */
import { describe, expect, test } from 'vitest';
import { fieldRightPx, MOST_VIEW, viewBeside } from '../../games/black-hole/view';

describe('black hole field beside the settings panel', () => {
  // The desktop's stage at a 1280 x 800 window: about 1060 x 700 px, padding 8; the panel's left edge some 748 px in.
  const field = { width: 32, height: 24 },
    W = 1060,
    H = 700;

  test('with the panel open the field is drawn left of it, as large as it can be; closed, as before', () => {
    // Closed (no panel: right edge Infinity), or a panel past the field's right edge: the field's own width.
    expect(viewBeside(field, W, H, 8, Infinity)).toBe(32);
    const own = fieldRightPx(32, 24, 32, W, H, 8);
    expect(viewBeside(field, W, H, 8, own + 1)).toBe(32);
    // Open at 748 px: the field's right edge within 0.5 px left of it (the bisection's 0.01 m is about 0.2 px).
    const view = viewBeside(field, W, H, 8, 740);
    expect(view).toBeGreaterThan(32);
    const edge = fieldRightPx(32, 24, view, W, H, 8);
    expect(edge).toBeLessThanOrEqual(740);
    expect(edge).toBeGreaterThan(739.5);
    // As large as the room left of the panel allows: 732 px wide (740 px less the padding at the
    // left), of the 912 px it had (within 0.5 px: the bisection stops within 0.01 m, some 0.2 px).
    const drawn = (view: number): number => 32 * Math.min((W - 16) / view, (H - 16) / 24);
    expect(drawn(32)).toBeCloseTo(912, 0);
    expect(Math.abs(drawn(view) - 732)).toBeLessThan(0.5);
  });

  test('a panel over nearly all the stage: the view stops at MOST_VIEW field widths; bad sizes throw', () => {
    expect(viewBeside(field, W, H, 8, 10)).toBe(MOST_VIEW * 32);
    expect(() => viewBeside(field, 0, H, 8, 100)).toThrow(RangeError);
  });
});
