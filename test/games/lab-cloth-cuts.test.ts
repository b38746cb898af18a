/**
 * The cloth lab's fit and undo, headless (games/lab-cloth/pattern.ts, undo.ts): hand-like traces of
 * the printed lines (traces.ts) cut on the still first sheet, each from the same saved sheet. A
 * careful cut earns three stars, a careless one one or two, and cutting across a star's narrow points
 * costs its third star even though little of its line or area goes with them; undo takes back the
 * last cut that earned no three stars and keeps the good ones made after it.
 * scripts/lab-cloth-cuts.mjs prints the whole spread of cuts.
 */

import { handleOf, type PhysicsWorld, query, removeJoint, restore, slotOf, snapshot } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { ClothCells } from '../../games/lab-cloth/cells';
import { cutAlong } from '../../games/lab-cloth/cut';
import { LEVELS } from '../../games/lab-cloth/levels';
import { Challenge, type CutOut, shapeMasks } from '../../games/lab-cloth/pattern';
import { createClothScene, DEFAULTS, sheetGrid } from '../../games/lab-cloth/scene';
import { cutTrace, type TraceStyle, traceLine } from '../../games/lab-cloth/traces';
import { CutUndo } from '../../games/lab-cloth/undo';

/** Link spacing of the lab's sheet, m (0.13 m: 14 px on a 1280 x 800 screen, 10 px on a 390 px phone). */
const S = sheetGrid(DEFAULTS.size).spacing;
const SHAPES = LEVELS[0]!.shapes(DEFAULTS.size);
const CIRCLE = 0,
  STAR = 1,
  HEART = 2;

/** The first sheet hanging in still air, and a save of it to start each cut from. */
const sheet = (() => {
  const scene = createClothScene({ ...DEFAULTS, wind: 0, gusts: 0 });
  return { ...scene, cells: new ClothCells(scene.cloth), save: snapshot(scene.world) };
})();

/** A new challenge on the saved sheet (put back as it was). */
function fresh(): Challenge {
  restore(sheet.world, sheet.save);
  sheet.cells.invalidate();
  const challenge = new Challenge(sheet.world, sheet.cloth, sheet.cells, SHAPES);
  challenge.update();
  return challenge;
}

/** Cuts `path` (sheet coordinates) with its marks, and scores it. @returns the shapes cut out. */
function cut(challenge: Challenge, path: readonly number[]): CutOut[] {
  cutTrace(sheet.world, sheet.cloth, path, challenge.marks);
  sheet.cells.loosen(sheet.world);
  return challenge.update();
}

/** Shape `shape` traced in `style` (lengths in link spacings) on the saved sheet: its cut-out, or null if it stays on. */
function traced(shape: number, style: TraceStyle, outline = SHAPES[shape]!.outline): CutOut | null {
  const scaled = {
    ...style,
    offset: (style.offset ?? 0) * S,
    wobble: (style.wobble ?? 0) * S,
    chop: (style.chop ?? 0) * S,
    notch: (style.notch ?? 0) * S,
    slit: (style.slit ?? 0) * S,
  };
  return cut(fresh(), traceLine(outline, scaled)).find((d) => d.shape === shape) ?? null;
}

/** The first sheet's circle shape: its centre (the mean of its outline's points) and radius, m, as [x, y, r]. */
function circleOfCircle(): [number, number, number] {
  const o = SHAPES[CIRCLE]!.outline,
    n = o.length / 2;
  let cx = 0,
    cy = 0;
  for (let i = 0; i < n; i++) {
    cx += o[2 * i]! / n;
    cy += o[2 * i + 1]! / n;
  }
  return [cx, cy, Math.hypot(o[0]! - cx, o[1]! - cy)];
}

describe('lab-cloth fit', () => {
  it("a star's narrow points: cut along its line, 3 stars; across its points or round them, 2", () => {
    // Measured fits: 1.00 on the line and 0.3 spacings inside it; across the points 2 spacings back
    // along their sides (0.3 out elsewhere) 0.76, though only 8 % of the star's area and 1.5
    // spacings of each point go (the grid's points lie too far apart to hold the ends of them); the
    // pentagon through its points (a hole 1.8 times the star) 0.85; 1 spacing inside the line 0.59.
    // The star's sharp corners are its five points.
    expect(shapeMasks(DEFAULTS.size, SHAPES).map((m) => m.corners.length / 2)).toEqual([0, 5, 1]);
    const star = SHAPES[STAR]!.outline;
    const along = traced(STAR, {})!;
    expect(along.fit).toBeGreaterThan(0.95);
    expect(along.stars).toBe(3);
    expect(traced(STAR, { offset: -0.3 })!.stars).toBe(3);
    const across = traced(STAR, { offset: 0.3, chop: 2 })!;
    expect(across.fit).toBeLessThan(0.85);
    expect(across.stars).toBe(2);
    const pentagon = traced(
      STAR,
      {},
      star.filter((_, i) => i % 4 < 2),
    )!;
    expect(pentagon.fit).toBeLessThan(0.9);
    expect(pentagon.stars).toBeLessThanOrEqual(2);
    expect(traced(STAR, { offset: -1 })!.stars).toBeLessThanOrEqual(2);
  });

  it('a heart cut as a coarse polygon through its line, its lobes and tip cut off: no 3 stars', () => {
    // Each corner of the cut lies on the line, so every mark is near it: the fit once scored only
    // the marks' distances from the line and gave the 7-sided polygon 0.94, 3 stars, though its piece
    // misses the lobes and the tip (pattern.ts SHORT_FREE). Measured now: 7 sides 0.83 (0.89 turned
    // by two corners), 5 sides 0.67; 8 sides 0.99 and 14 sides 1.00 keep theirs, as does a careful trace.
    const heart = SHAPES[HEART]!.outline;
    const polygon = (sides: number): number[] => {
      const n = heart.length / 2,
        out: number[] = [];
      for (let j = 0; j < sides; j++) {
        const i = Math.round((j * n) / sides) % n;
        out.push(heart[2 * i]!, heart[2 * i + 1]!);
      }
      return out;
    };
    const seven = traced(HEART, {}, polygon(7))!;
    expect(seven.fit).toBeLessThan(0.9);
    expect(seven.stars).toBeLessThanOrEqual(2);
    expect(traced(HEART, {}, polygon(5))!.stars).toBeLessThanOrEqual(1);
    expect(traced(HEART, {}, polygon(14))!.stars).toBe(3);
    expect(traced(HEART, { offset: 0.3, wobble: 0.3, seed: 2 })!.stars).toBe(3);
    expect(traced(HEART, { offset: -0.3 })!.stars).toBe(3);
  });

  it('over a spread of cuts the stars spread: careful 3, ragged 2, careless 1 or 2, sloppy 0 or 1', () => {
    // Lengths in link spacings (14 px on a desktop). Measured (scripts/lab-cloth-cuts.mjs): careful
    // 0.95-1.00; ragged (a wobble of 0.7) 0.85-0.89 at seed 3; careless 0.50-0.79 (1.2 out: circle
    // 0.50, star 0.54, heart 0.55); 2 out 0.00-0.13.
    const careful: TraceStyle[] = [
      { offset: 0.3, wobble: 0.3, seed: 2 },
      { offset: 0.3, wobble: 0.3, seed: 3 },
    ];
    const careless: TraceStyle[] = [{ offset: 1.2 }, { offset: 0.5, wobble: 1.2, seed: 1 }];
    const stars = (styles: TraceStyle[]) => styles.flatMap((st) => [CIRCLE, STAR, HEART].map((k) => traced(k, st)?.stars ?? -1));
    expect(stars(careful)).toEqual(Array(6).fill(3));
    // A ragged cut round the three shapes does not score as a clean one (it scored 9 of 9).
    expect(stars([{ offset: 0.3, wobble: 0.7, seed: 3 }])).toEqual([2, 2, 2]);
    // Nor does a zigzag over the circle's line, 0.7 spacings either side of 0.3 out every 5 degrees:
    // near the line all along, but the scissors go about 4 times as far as the line (in the lab
    // at 1280 x 800 it scored 0.97, three stars; now 0.78 there and 0.74 here, two).
    const [cx, cy, radius] = circleOfCircle();
    const zigzag: number[] = [];
    for (let k = 0; k <= 72; k++) {
      const r = radius + S * (0.3 + (k % 2 === 0 ? 0.7 : -0.7)),
        a = (2 * Math.PI * k) / 72;
      zigzag.push(cx + r * Math.cos(a), cy + r * Math.sin(a));
    }
    const zig = cut(fresh(), zigzag).find((d) => d.shape === CIRCLE)!;
    expect(zig.stars).toBeLessThan(3);
    expect(zig.steady).toBeLessThan(0.85);
    const loose = stars(careless);
    for (const n of loose) expect([1, 2]).toContain(n);
    expect(loose).toContain(1);
    expect(stars([{ offset: 2 }]).every((n) => n <= 1)).toBe(true);
  });
});

describe('lab-cloth flaws', () => {
  it('a notch or a stray slit a link and a half into a shape costs a star; a clean cut keeps three', () => {
    // Issue 34: a star cut along its line but for a notch scored 99 %, three stars. Measured (lengths
    // in link spacings; scripts/lab-cloth-cuts.mjs): clean 1.00; a V notch 1.5 deep 0.79 (a third of
    // the way round: on the star, into an arm), a slit 1.5 long 0.79, both 2 stars; a notch 1 deep
    // 0.91-0.96, still 3 (the grid holds a clean cut within half a spacing of the line).
    for (const k of [CIRCLE, STAR, HEART]) {
      const clean = traced(k, { at: 0.3 })!;
      expect(clean.stars).toBe(3);
      expect(clean.clean).toBe(1);
      for (const flawed of [traced(k, { notch: 1.5, at: 0.3 })!, traced(k, { slit: 1.5, at: 0.3 })!]) {
        expect(flawed.stars).toBe(2);
        expect(flawed.fit).toBeLessThan(clean.fit - 0.1);
        expect(flawed.clean).toBeLessThan(0.95);
      }
      expect(traced(k, { notch: 1, at: 0.3 })!.stars).toBe(3);
    }
  });

  it('a shape torn across inside its line is spoilt; a clean cut round another spoils nothing', () => {
    const challenge = fresh();
    expect(challenge.spoilt()).toEqual([]);
    // A careful star: cut out, and the circle and the heart untouched.
    cut(challenge, traceLine(SHAPES[STAR]!.outline));
    expect(challenge.spoilt()).toEqual([]);
    // A slash straight across the circle's middle (as a pull of the hand tears it).
    const [cx, cy, radius] = circleOfCircle();
    const P = sheet.world.components.Position;
    const corner = slotOf(sheet.cloth.points[0]!);
    // Sheet coordinates at rest to the world: the sheet hangs still, its first point at its top left.
    const wx = (u: number) => P.x[corner]! + u,
      wy = (v: number) => P.y[corner]! - v;
    cutAlong(sheet.world, wx(cx - 0.8 * radius), wy(cy + 0.1 * S), wx(cx + 0.8 * radius), wy(cy + 0.1 * S));
    sheet.cells.loosen(sheet.world);
    expect(challenge.spoilt()).toEqual([CIRCLE]);
  });

  it('a tear into the piece is a flaw as a slit is', () => {
    // The circle cut on its line, then two links across its edge torn (removed, no scissors' marks):
    // the tear's links are on the piece's edge, 1 and 2 spacings inside the line.
    const challenge = fresh();
    const o = SHAPES[CIRCLE]!.outline;
    // The circle's lowest point, and the links straight up from it inside the circle.
    let low = 0;
    for (let i = 1; i < o.length / 2; i++) if (o[2 * i + 1]! > o[2 * low + 1]!) low = i;
    const c = Math.round(o[2 * low]! / S),
      r = Math.floor(o[2 * low + 1]! / S);
    const C = sheet.cloth.columns;
    const L = sheet.world.components.ClothLink;
    const doomed = new Set<string>();
    for (let k = 0; k < 3; k++)
      doomed.add(`${slotOf(sheet.cloth.points[(r - k) * C + c]!)}-${slotOf(sheet.cloth.points[(r - k) * C + c + 1]!)}`);
    for (const e of query(sheet.world, [L])) if (doomed.has(`${L.a[e]}-${L.b[e]}`)) removeJoint(sheet.world, handleOf(sheet.world, e));
    const d = cut(challenge, traceLine(o)).find((x) => x.shape === CIRCLE)!;
    expect(d.stars).toBeLessThan(3);
    expect(d.clean).toBeLessThan(1);
  });
});

describe('lab-cloth undo', () => {
  /** Positions and velocities of the cloth's points, and the cloth links left. */
  function state(world: PhysicsWorld) {
    const P = world.components.Position,
      V = world.components.Velocity;
    const pts = Array.from(sheet.cloth.points, (h) => slotOf(h));
    return {
      pos: pts.flatMap((e) => [P.x[e]!, P.y[e]!]),
      vel: pts.flatMap((e) => [V.x[e]!, V.y[e]!]),
      links: query(world, [world.components.ClothLink]).length,
    };
  }

  it('takes back the last action only, then the one before; at most `depth` actions', () => {
    // Undo used to pass over a stroke that cut out a ★★★ shape and take back the one before it with
    // the good cuts after it made again; a player expects the last action undone (issue 34).
    const challenge = fresh();
    const history = new CutUndo<{ cut: number }>(sheet.world, sheet.cells, challenge, 3);
    const stroke = (path: number[], n: number): boolean => {
      history.begin({ cut: n });
      cut(challenge, path);
      return history.end();
    };
    const start = state(sheet.world);
    // A careless heart (1.2 spacings out: 1 star), then a careful star (3 stars).
    expect(stroke(traceLine(SHAPES[HEART]!.outline, { offset: 1.2 * S }), 1)).toBe(true);
    const afterHeart = state(sheet.world),
      heartMarks = challenge.marks.slice();
    expect(stroke(traceLine(SHAPES[STAR]!.outline, {}), 2)).toBe(true);
    expect(afterHeart.links - state(sheet.world).links).toBeGreaterThan(0);
    expect(challenge.done.map((d) => [d.shape, d.stars])).toEqual([
      [HEART, 1],
      [STAR, 3],
    ]);
    // A stroke through the air beside the sheet cuts nothing and is not kept.
    expect(stroke([-2, -2, -1.5, -2, -1.5, -1.5], 3)).toBe(false);
    expect(history.count).toBe(2);
    // Undo: the star's cut (the last) goes; the heart stays cut out, the sheet as it was after it.
    const undone = history.undo()!;
    expect(undone.extra).toEqual({ cut: 2 });
    expect(challenge.done.map((d) => [d.shape, d.stars])).toEqual([[HEART, 1]]);
    expect(challenge.marks).toEqual(heartMarks);
    expect(state(sheet.world)).toEqual(afterHeart);
    expect(history.count).toBe(1);
    expect(challenge.partCuts()).toEqual([]);
    // Then the heart's, and the sheet is as it began, bit for bit.
    const again = history.undo()!;
    expect(again.extra).toEqual({ cut: 1 });
    expect(challenge.done).toEqual([]);
    expect(challenge.marks).toEqual([]);
    expect(state(sheet.world)).toEqual(start);
    expect(history.undo()).toBeNull();
    // At most `depth` (3) strokes are kept: 4 snips across the sheet's lower left corner, 3 to undo.
    const P = sheet.world.components.Position;
    const corner = slotOf(sheet.cloth.points[sheet.cloth.points.length - sheet.cloth.columns]!);
    for (let k = 0; k < 4; k++) {
      history.begin({ cut: k });
      const y = P.y[corner]! + 0.1 + 0.2 * k;
      cutAlong(sheet.world, P.x[corner]! - 0.2, y, P.x[corner]! + 0.3, y);
      expect(history.end()).toBe(true);
    }
    expect(history.count).toBe(3);
    history.clear();
    expect(history.count).toBe(0);
    expect(() => new CutUndo(sheet.world, sheet.cells, challenge, 0)).toThrow(/CutUndo: depth must be an integer >= 1, got 0/);
  });
});
