/**
 * Catapult's castle inset on an upright phone (games/catapult/pull.ts insetBesidePull): while the
 * player pulls, the inset in the earth under the ground stands clear of the pull's band. A stranger's
 * pull from the screen's middle down and back ran through the inset, over its "castle 7 m ahead" label.
 */

import { describe, expect, it } from 'vitest';
import { insetBesidePull, PULL_CLEAR, segmentMeetsBox } from '../../games/catapult/pull';

describe('catapult castle inset beside the pull', () => {
  it('segmentMeetsBox: through, beside, ending inside and along an edge', () => {
    const box: [number, number, number, number] = [10, 10, 20, 20];
    expect(segmentMeetsBox(0, 0, 40, 40, box)).toBe(true);
    expect(segmentMeetsBox(0, 35, 40, 35, box)).toBe(false);
    expect(segmentMeetsBox(0, 0, 15, 15, box)).toBe(true);
    expect(segmentMeetsBox(35, 0, 35, 40, box)).toBe(false);
  });

  it("a phone's pull down and back from the screen's middle: the inset moves clear of it, as large as the earth holds", () => {
    // A 390 x 788 canvas, ground at 394 px, the earth's band 406 to 780 px; level 1's inset 437 x 209
    // px at scale 1 (366 x 175 at 0.838, centred at the band's top: the figures the page showed).
    const slot: [number, number] = [406, 780];
    const w = 437,
      h = 209,
      zoom = 0.838;
    // The browser test's pull: from (234, 394), 196 px down and back at 30 degrees, clamped to the full pull.
    const pull: [number, number, number, number] = [234, 394, 234 - 195 * Math.cos(Math.PI / 6), 394 + 195 * Math.sin(Math.PI / 6)];
    const usual: [number, number, number, number] = [Math.round((390 - w * zoom) / 2), slot[0], w * zoom, h * zoom];
    // The usual place is crossed (what the stranger saw).
    expect(segmentMeetsBox(...pull, usual)).toBe(true);
    const place = insetBesidePull(pull, slot, 390, w, h, zoom, 6, null);
    expect(place).not.toBeNull();
    const p = place!;
    const box: [number, number, number, number] = [
      p.bx - PULL_CLEAR,
      p.by - PULL_CLEAR,
      w * p.zoom + 2 * PULL_CLEAR,
      h * p.zoom + 2 * PULL_CLEAR,
    ];
    expect(segmentMeetsBox(...pull, box), JSON.stringify(p)).toBe(false);
    // Inside the screen and the earth's band (to a pixel: rounding), and no smaller than before
    // (the earth under the pull holds it whole).
    expect(p.bx).toBeGreaterThanOrEqual(0);
    expect(p.bx + w * p.zoom).toBeLessThanOrEqual(390 + 1);
    expect(p.by + h * p.zoom).toBeLessThanOrEqual(slot[1] + 1);
    expect(p.zoom).toBeGreaterThanOrEqual(0.99 * zoom);
    // Kept while the finger moves and stays clear of it (no new size every frame).
    expect(insetBesidePull([234, 394, pull[2] + 5, pull[3] - 3], slot, 390, w, h, zoom, 6, p)).toBe(p);
  });

  it('a pull clear of the usual place leaves the inset there; a long pull down puts it beside the pull', () => {
    const slot: [number, number] = [406, 780];
    // A pull in the sky, over the ground: the inset stays put.
    expect(insetBesidePull([300, 200, 200, 260], slot, 390, 437, 209, 0.838, 6, null)).toBeNull();
    // From near the right edge straight down through the whole earth: the inset goes left of it, smaller.
    const pull: [number, number, number, number] = [330, 380, 330, 775];
    const p = insetBesidePull(pull, slot, 390, 437, 209, 0.838, 6, null)!;
    const box: [number, number, number, number] = [
      p.bx - PULL_CLEAR,
      p.by - PULL_CLEAR,
      437 * p.zoom + 2 * PULL_CLEAR,
      209 * p.zoom + 2 * PULL_CLEAR,
    ];
    expect(segmentMeetsBox(...pull, box), JSON.stringify(p)).toBe(false);
    expect(p.bx).toBe(12);
    expect(p.zoom).toBeGreaterThan(0.5);
  });
});
