/**
 * The submarine's pause band (games/submarine/pause-band.ts): at the bottom edge, at the top while
 * the boat is low, and clear of the target's label where there is room clear of the boat.
 */

import { describe, expect, it } from 'vitest';
import { PAUSE_HULL_ROOM, pauseBandTop } from '../../games/submarine/pause-band';

/** Whether a band `height` px high at `top` and the span [y, y + h) overlap. */
const covers = (top: number, height: number, y: number, h: number) => y < top + height && top < y + h;

describe('submarine pause band', () => {
  it('sits at the bottom edge, or at the top while the boat is low, as before when no label is in the way', () => {
    expect(pauseBandTop(0, 560, 64, 200, null)).toBe(496);
    expect(pauseBandTop(75, 560, 64, 500, null)).toBe(75);
    // Kept inside the cards at the edges: the bottom one ends at 480 px.
    expect(pauseBandTop(0, 480, 64, 200, [100, 20])).toBe(416);
  });

  it("keeps off the target's label: a phone with the boat low and the label under the top card (issue 34)", () => {
    // Seen on a 390 x 844 phone (the boat 30 m short of beacon A, 40 m under it, low in the view):
    // the band at the top (y 75, under the first-time hint) lay over the target's label at y 85 to
    // 105. Here a 560 px scene with the boat at y 500: the bottom edge is taken by the boat, the top
    // one by the label; just under the label is clear of both.
    const label: [number, number] = [85, 20];
    const top = pauseBandTop(75, 560, 64, 500, label);
    expect(covers(top, 64, label[0], label[1])).toBe(false);
    expect(Math.abs(500 - (top + 32))).toBeGreaterThan(32 + PAUSE_HULL_ROOM - 1);
    expect(top).toBe(109);
    // The label over the bottom band with the boat high: the top edge.
    expect(pauseBandTop(0, 560, 64, 150, [510, 20])).toBe(0);
    // No room clear of both the label and the boat: the boat comes first (the band where it was).
    expect(pauseBandTop(0, 200, 64, 60, [150, 20])).toBe(136);
  });
});
