/**
 * The cloth lab's levels (games/lab-cloth/levels.ts), headless: each one can be completed the way a
 * player would, and a finger's cut is given the slack its width asks for.
 */

import { slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { ClothCells } from '../../games/lab-cloth/cells';
import { cutAlong } from '../../games/lab-cloth/cut';
import { ClothGrab, GRAB } from '../../games/lab-cloth/grab';
import { LEVELS, PEG_BAG, pegBagCells } from '../../games/lab-cloth/levels';
import { Challenge } from '../../games/lab-cloth/pattern';
import { applyWind, createClothScene, DEFAULTS, sheetGrid } from '../../games/lab-cloth/scene';
import { cutTrace, traceLine } from '../../games/lab-cloth/traces';

/** Level `n`'s sheet at the lab's default size, its cells and its challenge. */
function level(n: number) {
  const L = LEVELS[n]!;
  const p = { ...DEFAULTS, wind: L.wind, gusts: L.gusts };
  const s = createClothScene(p, L.prepare);
  const cells = new ClothCells(s.cloth);
  return { ...s, cells, challenge: new Challenge(s.world, s.cloth, cells, L.shapes(p.size)), p, L };
}

/** Steps `world` `n` times, loosening the cells and scoring the challenge after each; stops early when `until` holds. */
function run(s: ReturnType<typeof level>, n: number, until: () => boolean = () => false): number {
  for (let i = 1; i <= n; i++) {
    step(s.world);
    s.cells.loosen(s.world);
    s.challenge.update();
    s.challenge.watch();
    if (until()) return i;
  }
  return n;
}

describe('lab-cloth levels', () => {
  it('the levels ask for different things: shapes, a window of four panes, a peg bag to drop, a strip to tear', () => {
    expect(LEVELS.map((l) => l.shapes(32).map((s) => s.name))).toEqual([
      ['circle', 'star', 'heart'],
      ['top-left pane', 'top-right pane', 'bottom-left pane', 'bottom-right pane'],
      ['peg bag'],
      ['strip'],
    ]);
    expect(LEVELS.map((l) => l.scissors)).toEqual([true, true, true, false]);
  });

  it('the shapes and the window: each cut 4 cm out of its line as the sheet lies comes away with 3 stars', () => {
    for (const n of [0, 1]) {
      const s = level(n);
      for (const shape of s.challenge.shapes) cutTrace(s.world, s.cloth, traceLine(shape.outline, { offset: 0.04 }), s.challenge.marks);
      s.cells.loosen(s.world);
      s.challenge.update();
      expect(s.challenge.finished(), s.L.title).toBe(true);
      expect(s.challenge.done.map((d) => d.stars)).toEqual(s.challenge.shapes.map(() => 3));
      // The window's cross still hangs a second on, the sheet straining round the holes in the
      // breeze: the middle of the bars is in a piece held by the pegs (its links are sewn).
      if (n === 1) {
        run(s, 60);
        const C = s.cloth.columns,
          { spacing } = sheetGrid(DEFAULTS.size);
        const p = s.challenge.pieces!;
        const mid = Math.round(1.5 / spacing) * C + Math.round(2 / spacing);
        expect(p.held[p.pieceOf[mid]!]).toBe(true);
      }
    }
  });

  it('the peg bag: blown over the basket by a 1.5 s gust and its ribbon cut, it lands in the basket', () => {
    // Measured (the basket 1 m wide, its middle 0.6 m right of the bag at rest): cut at once the bag
    // lands 0.40 m left of the basket's middle (in, 1 star); after a 1.5 s gust (5 m/s more) 0.25 m
    // right of it (2 stars); after a 1 s gust 1.58 m right, after 2 s 0.80 m left (out); cut 2 s or
    // 4 s into the breeze, 0.75 m (out) and 0.48 m left (in).
    const s = level(2);
    const k = pegBagCells(DEFAULTS.size),
      C = s.cloth.columns,
      P = s.world.components.Position;
    applyWind(s.world, s.p, 5);
    run(s, 90);
    applyWind(s.world, s.p, 0);
    const row = Math.round((k.hem + k.bagTop) / 2);
    const left = slotOf(s.cloth.points[row * C + k.ribbon0]!),
      right = slotOf(s.cloth.points[row * C + k.ribbon1]!);
    const y = (P.y[left]! + P.y[right]!) / 2 - 0.06;
    cutAlong(s.world, P.x[left]! - 0.4, y, P.x[right]! + 0.4, y);
    s.cells.loosen(s.world);
    expect(s.challenge.update().map((d) => d.drop)).toEqual(['falling']);
    run(s, 240, () => s.challenge.finished());
    const bag = s.challenge.done[0]!;
    expect(bag.drop).toBe('in');
    expect(Math.abs(bag.landedAt! - PEG_BAG.basket.x)).toBeLessThan(PEG_BAG.basket.width / 3);
    expect(bag.stars).toBeGreaterThanOrEqual(2);
  });

  it('the perforation: the hand pulling the strip down tears it off along the dotted line within 2 s', () => {
    // Measured: off at 1.3 s (1.7 m pulled), fit 1.00; the wind alone tears 7 of its links in 15 s.
    const s = level(3);
    run(s, 30);
    const C = s.cloth.columns,
      P = s.world.components.Position;
    const e = slotOf(s.cloth.points[18 * C + Math.floor(C / 2)]!);
    const x0 = P.x[e]!,
      y0 = P.y[e]!;
    const grab = ClothGrab.at(s.world, s.cloth, x0, y0, GRAB)!;
    let steps = 0;
    for (; steps < 120 && !s.challenge.finished(); steps++) {
      grab.moveTo(x0, y0 - 2.5 * Math.min(1, (steps + 1) / 120));
      run(s, 1);
    }
    expect(s.challenge.finished()).toBe(true);
    expect(s.challenge.done[0]!.fit).toBeGreaterThan(0.9);
  });

  it("a finger's slack: a circle cut 1 link spacing out of its line scores 3 stars with a finger's 0.064 m, 2 without", () => {
    // The circle's line moved 1 spacing (0.13 m, 10 px on a 390 px phone) out, as the sheet lies in
    // the calm day's breeze. Measured fits, without slack (the mouse) and with a finger's 0.064 m
    // (5 px on the phone, main.ts FINGER_SLACK_PX): 0.86 and 1.00 at 0.8 spacings out, 0.72 and 1.00
    // at 1, 0.57 and 0.93 at 1.2.
    const fits = [0, 0.064].map((slack) => {
      const s = level(0);
      s.challenge.setSlack(slack);
      cutTrace(
        s.world,
        s.cloth,
        traceLine(s.challenge.shapes[0]!.outline, { offset: sheetGrid(DEFAULTS.size).spacing }),
        s.challenge.marks,
      );
      s.cells.loosen(s.world);
      return s.challenge.update()[0]!;
    });
    expect(fits[0]!.stars).toBeLessThan(3);
    expect(fits[1]!.stars).toBe(3);
    expect(() => level(0).challenge.setSlack(-1)).toThrow(/slack must be a finite number >= 0, got -1/);
  });
});
