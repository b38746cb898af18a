/**
 * The rope lab's framing with the settings drawer open (games/lab-rope/clear-fit.ts): the drawer lies
 * over the scene (measured at 1280 x 800: the canvas 1060 x 774 px, the drawer over its right from
 * x = 680 px down to y = 483 px; at 390 x 844 on a phone: the canvas 390 x 744 px, the drawer, with
 * the chart hidden there, over its top to y = 282 px). Framed as without it, stars lay under it; framed
 * by clearFit, every star (its disc, STAR_REACH) and the basket stand clear of it on every level.
 */
import { describe, expect, it } from 'vitest';
import { clearFit, type MetreRect, type PixelRect } from '../../games/lab-rope/clear-fit';
import { LEVELS, type Level, STAR_REACH, WIDE_LEVELS } from '../../games/lab-rope/scene';

const SCREENS = [
  { name: 'desktop', levels: WIDE_LEVELS, width: 1060, height: 774, cover: { left: 680, top: -18, right: 1052, bottom: 483 } },
  { name: 'phone', levels: LEVELS, width: 390, height: 744, cover: { left: 10, top: -44, right: 390, bottom: 282 } },
] as const;

/** Whether the world disc at (x, y) m of radius r m, shown in `frame` on a canvas `width` px wide, overlaps `cover`. */
function under(frame: MetreRect, width: number, cover: PixelRect, x: number, y: number, r: number): boolean {
  const ppm = width / (frame.maxX - frame.minX);
  const sx = (x - frame.minX) * ppm,
    sy = (frame.maxY - y) * ppm,
    sr = r * ppm;
  return sx + sr > cover.left && sx - sr < cover.right && sy + sr > cover.top && sy - sr < cover.bottom;
}

/** The level's stars and its basket (its rim's middle, the basket's half width) that the drawer hides in `frame`. */
function hidden(level: Level, frame: MetreRect, s: (typeof SCREENS)[number]): number {
  const things: [number, number, number][] = [
    ...level.stars.map(([x, y]): [number, number, number] => [x, y, STAR_REACH]),
    [level.basket[0], level.basket[1] + level.basketDepth / 2, level.basketWidth / 2],
  ];
  return things.filter(([x, y, r]) => under(frame, s.width, s.cover, x, y, r)).length;
}

describe('lab-rope: the level framed clear of the open settings drawer', () => {
  for (const s of SCREENS) {
    it(`${s.name}: no star or basket under the drawer on any level (framed as without it, some were)`, () => {
      let before = 0;
      for (const level of s.levels) {
        before += hidden(level, clearFit(level.view, s.width, s.height, null), s);
        const frame = clearFit(level.view, s.width, s.height, s.cover);
        expect(hidden(level, frame, s), `${s.name} ${level.name}`).toBe(0);
        // Still a usable size: the room at least 40% of the scale it had with the drawer shut.
        const open = s.width / (frame.maxX - frame.minX);
        const shut = s.width / (clearFit(level.view, s.width, s.height, null).maxX - clearFit(level.view, s.width, s.height, null).minX);
        expect(open / shut).toBeGreaterThan(0.4);
      }
      expect(before).toBeGreaterThan(0);
    });
  }
  it('with no drawer it frames the view centred on the whole canvas, 24 px round it', () => {
    const f = clearFit({ minX: 0, minY: 0, maxX: 10, maxY: 5 }, 1000, 600, null);
    // ppm = min(952 / 10, 552 / 5) = 95.2: the canvas spans 1000 / 95.2 m, centred on x = 5.
    expect(f.maxX - f.minX).toBeCloseTo(1000 / 95.2, 9);
    expect((f.minX + f.maxX) / 2).toBeCloseTo(5, 9);
    expect((f.minY + f.maxY) / 2).toBeCloseTo(2.5, 9);
    expect(() => clearFit({ minX: 0, minY: 0, maxX: 0, maxY: 5 }, 1000, 600, null)).toThrow(RangeError);
  });
});
