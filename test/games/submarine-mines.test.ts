/**
 * The submarine course's mines and par (games/submarine/mines.ts), headless: the straight run
 * between two beacons meets a mine, mines keep clear of the beacons, the surface and the seabed, the
 * contact test is the distance from a box, and the par time is the sum of its legs.
 */

import { createPhysicsWorld } from '@bitphysics/physics';
import { SUBMARINE, seabedHeight, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import {
  courseOrder,
  layMines,
  MINE_BEACON_CLEARANCE,
  MINE_BED_CLEARANCE,
  MINE_RADIUS,
  MINE_TOP,
  MINE_WAY_CLEARANCE,
  mineOnWay,
  parTime,
  touchesMine,
} from '../../games/submarine/mines';

function course(seed: number, count: number) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed, count });
  return { h, mines: layMines(h.beacons, h.seabed, seed) };
}

describe('submarine mines', () => {
  it('a level run straight from each beacon to the next meets a mine on most legs; none on the first', () => {
    let legs = 0,
      blocked = 0;
    for (const seed of [1, 2, 3, 4, 5]) {
      const { h, mines } = course(seed, 6);
      const order = courseOrder(h.beacons);
      expect(order).toEqual([0, 1, 2, 3, 4, 5]);
      // The first leg (start to beacon 0, x < 75 m) has no mine.
      expect(mines.every((m) => m.x > h.beacons[0]!)).toBe(true);
      for (let leg = 1; leg < order.length; leg++) {
        const [ax, ay, bx, by] = [h.beacons[2 * leg - 2]!, h.beacons[2 * leg - 1]!, h.beacons[2 * leg]!, h.beacons[2 * leg + 1]!];
        let hit = false;
        for (let f = 0; f <= 1 && !hit; f += 0.002)
          for (const m of mines) if (touchesMine(ax + f * (bx - ax), ay + f * (by - ay), 0, m.x, m.y)) hit = true;
        legs++;
        if (hit) blocked++;
      }
    }
    // A mine on the line (offset within 1 m) is moved only when the surface, the bed or a beacon is near.
    expect(legs).toBe(25);
    expect(blocked).toBeGreaterThanOrEqual(20);
  });

  it('keeps clear of the beacons, the surface and the seabed; the same seed lays the same mines', () => {
    for (const [seed, count] of [
      [1, 6],
      [7, 12],
      [3, 20],
    ] as const) {
      const { h, mines } = course(seed, count);
      expect(mines.length).toBeGreaterThan(count); // two a leg, a few left out
      for (const m of mines) {
        for (let i = 0; i < count; i++)
          expect(Math.hypot(h.beacons[2 * i]! - m.x, h.beacons[2 * i + 1]! - m.y)).toBeGreaterThanOrEqual(MINE_BEACON_CLEARANCE);
        expect(m.y).toBeLessThanOrEqual(-MINE_TOP);
        expect(m.anchor).toBe(seabedHeight(h.seabed, m.x));
        expect(m.y - m.anchor).toBeGreaterThanOrEqual(MINE_BED_CLEARANCE);
      }
      expect(course(seed, count).mines).toEqual(mines);
    }
    expect(() => layMines([], { x0: 0, dx: 1, y: new Float64Array(2) }, Number.NaN)).toThrow(/layMines: seed must be finite, got NaN/);
  });

  it('contact: within MINE_RADIUS of the hull box, level or turned', () => {
    const L = SUBMARINE.length / 2,
      H = SUBMARINE.height / 2,
      R = MINE_RADIUS;
    expect(touchesMine(0, 0, 0, L + R - 0.05, 0)).toBe(true); // off the bow
    expect(touchesMine(0, 0, 0, L + R + 0.05, 0)).toBe(false);
    expect(touchesMine(0, 0, 0, 3, H + R - 0.05)).toBe(true); // over the deck
    expect(touchesMine(0, 0, 0, 3, H + R + 0.05)).toBe(false);
    // Off a corner: the distance to the corner, not to the side's line.
    const d = (R + 0.05) / Math.SQRT2;
    expect(touchesMine(0, 0, 0, L + d, H + d)).toBe(false);
    // Turned 90 degrees (bow up): the bow is at (0, L).
    expect(touchesMine(10, -20, Math.PI / 2, 10, -20 + L + R - 0.05)).toBe(true);
    expect(touchesMine(10, -20, Math.PI / 2, 10 + H + R + 0.05, -20)).toBe(false);
  });

  it('par: each leg the longer of its run at 8 m/s and its depth change at 4 m/s, plus 3 s, rounded up to 5 s', () => {
    expect(parTime([60, -20])).toBe(15); // max(7.5, 5) + 3 = 10.5
    expect(parTime([60, -20, 300, -80])).toBe(45); // 10.5 + max(30, 15) + 3 = 43.5
    expect(parTime([40, -60])).toBe(20); // max(5, 15) + 3 = 18
    expect(parTime([])).toBe(0);
  });

  it('mineOnWay: every level run that meets a mine is warned of, with the side to pass; a clear way is not', () => {
    // Independent of the warning's own geometry: the hull box swept along the straight way (touchesMine).
    let meets = 0;
    for (const seed of [1, 2]) {
      const { h, mines } = course(seed, 6);
      const live = mines.map(() => true);
      for (let leg = 1; leg < 6; leg++) {
        const [ax, ay, bx, by] = [h.beacons[2 * leg - 2]!, h.beacons[2 * leg - 1]!, h.beacons[2 * leg]!, h.beacons[2 * leg + 1]!];
        let first = -1;
        for (let f = 0; f <= 1 && first < 0; f += 0.002)
          for (let i = 0; i < mines.length && first < 0; i++)
            if (touchesMine(ax + f * (bx - ax), ay + f * (by - ay), 0, mines[i]!.x, mines[i]!.y)) first = i;
        const way = mineOnWay(ax, ay, bx, by, mines, live);
        if (first >= 0) {
          meets++;
          expect(way?.index).toBe(first);
          // Gone off, it no longer blocks.
          const gone = live.map((_, i) => i !== first);
          expect(mineOnWay(ax, ay, bx, by, mines, gone)?.index).not.toBe(first);
        }
      }
    }
    expect(meets).toBeGreaterThan(3);
    // A mine 3 m under a level way: pass over it; 3 m above: under it; 10 m off: clear.
    const at = (y: number) => [{ x: 50, y, anchor: -80 }];
    expect(mineOnWay(0, -30, 100, -30, at(-33), [true])).toEqual({ index: 0, side: 'over' });
    expect(mineOnWay(0, -30, 100, -30, at(-27), [true])).toEqual({ index: 0, side: 'under' });
    expect(mineOnWay(0, -30, 100, -30, at(-30 - MINE_WAY_CLEARANCE - 0.1), [true])).toBeNull();
    expect(() => mineOnWay(Number.NaN, 0, 1, 1, [], [])).toThrow(/mineOnWay: x0/);
  });
});
