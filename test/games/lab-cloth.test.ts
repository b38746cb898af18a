/**
 * The cloth lab, headless (games/lab-cloth): the sheet on its line at the lab's defaults. The hand's
 * soft grip (grab.ts) stretches the sheet before it tears it; the scissors (cut.ts) cut what a stroke
 * crosses; a shape cut out (pattern.ts) falls to the lawn and lies there, not pinned to a wall by the
 * breeze; the breeze visibly sways the sheet and a gust leans it; the drawing's cells lose the two
 * triangles beside a torn link.
 */

import { segmentsCross } from '@bitphysics/game-kit';
import { type Cloth, ClothLinkKind, isAlive, type PhysicsWorld, query, removeJoint, slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { ClothCells } from '../../games/lab-cloth/cells';
import { cutAlong, ScissorsStroke } from '../../games/lab-cloth/cut';
import { ClothGrab, GRAB, gripFor } from '../../games/lab-cloth/grab';
import { Challenge, insidePolygon, SHAPES, shapeCells } from '../../games/lab-cloth/pattern';
import { findPieces } from '../../games/lab-cloth/pieces';
import { applyWind, createClothScene, DEFAULTS, SHEET_WIDTH, SHEETS, sheetGrid, YARD } from '../../games/lab-cloth/scene';
import { cutTrace, traceLine } from '../../games/lab-cloth/traces';

const STILL = { ...DEFAULTS, wind: 0, gusts: 0 };

/** The largest strain of the structural links within `radius` m of (x, y) now. */
function strainNear(world: PhysicsWorld, x: number, y: number, radius: number): number {
  const L = world.components.ClothLink,
    P = world.components.Position;
  let most = 0;
  for (const e of query(world, [L])) {
    if (L.kind[e] !== ClothLinkKind.Structural) continue;
    const a = L.a[e]!,
      b = L.b[e]!;
    if (Math.hypot(P.x[a]! - x, P.y[a]! - y) > radius) continue;
    most = Math.max(most, Math.hypot(P.x[b]! - P.x[a]!, P.y[b]! - P.y[a]!) / L.restLength[e]! - 1);
  }
  return most;
}

/** Position of point (row, column) of the cloth, m. */
function pointAt(world: PhysicsWorld, cloth: Cloth, row: number, column: number): [number, number] {
  const e = slotOf(cloth.points[row * cloth.columns + column]!);
  return [world.components.Position.x[e]!, world.components.Position.y[e]!];
}

/** The sheet hanging in still air for 1 s, grabbed at point (row, column) and pulled by (dx, dy) m over `seconds`, then held 0.5 s. */
function pull(row: number, column: number, dx: number, dy: number, seconds: number) {
  const { world, cloth } = createClothScene(STILL);
  const cells = new ClothCells(cloth);
  for (let i = 0; i < 60; i++) step(world);
  const [x0, y0] = pointAt(world, cloth, row, column);
  const before = strainNear(world, x0, y0, 0.6);
  const grab = ClothGrab.at(world, cloth, x0, y0, GRAB)!;
  const steps = Math.round(seconds * 60);
  let torn = 0,
    most = 0;
  for (let i = 1; i <= steps + 30; i++) {
    const f = Math.min(1, i / steps);
    grab.moveTo(x0 + dx * f, y0 + dy * f);
    step(world);
    torn += world.joints.breaks.count;
    cells.loosen(world);
    if (torn === 0) most = Math.max(most, strainNear(world, ...grab.patch([0, 0]), 0.6));
  }
  return { world, cloth, grab, torn, before, most, patch: grab.patch([0, 0]), hand: [x0 + dx, y0 + dy] };
}

describe('lab-cloth', () => {
  it('a short pull stretches the sheet by the hand visibly and tears nothing; a long one tears it and the hand keeps the piece', () => {
    // Measured: a 0.4 m pull down from the lower middle stretches the links by the hand from 1.3% to
    // 20% (tear strain 0.45) and the held patch follows the hand to 0.1 m. Pulled down from there the
    // sheet tears once the hand is 2.1-2.3 m from where it took hold (grab.ts: the grip's pull grows
    // with the hand's lead on the patch, and the links by the hem need 44 N); a 3 m pull over 2 s tears
    // 34 structural links, and the torn flap stays in the hand, 0.6 m behind it (the grip pulls 26 N,
    // what the flap still hanging on at its sides holds: pulled on, it tears on). Thresholds: 10 points
    // more strain, under the tear strain, no tear; over 10 links torn, the hand's patch moved 2 m of
    // the hand's 3 and within 1 m of the hand.
    const soft = pull(19, 16, 0, -0.4, 1);
    expect(soft.torn).toBe(0);
    expect(soft.most - soft.before).toBeGreaterThan(0.1);
    expect(soft.most).toBeLessThan(DEFAULTS.tear);
    const hard = pull(19, 16, 0, -3, 2);
    expect(hard.torn).toBeGreaterThan(10);
    expect(hard.hand[1]! + 3 - hard.patch[1]).toBeGreaterThan(2);
    expect(Math.hypot(hard.patch[0] - hard.hand[0]!, hard.patch[1] - hard.hand[1]!)).toBeLessThan(1);
  });

  it('a gentle pull from the middle of the sheet moves it and tears nothing; only a hard one tears it', () => {
    // The middle of the sheet (row 12 of 24), pulled down at 0.8 m/s. With the grip's pull capped at a
    // fixed 80 N (the hand holding the patch to itself whatever it took) it tore 0.57 m down at any
    // speed from 0.5 to 8 m/s, a flick of the mouse. With the pull growing with the hand's lead
    // (grab.ts: 15 N, and 20 N a metre more), measured: it tears 1.1-1.5 m down. Thresholds: a 0.8 m
    // pull tears nothing and moves the held patch at least 0.5 m; a 2 m pull tears it.
    const gentle = pull(12, 16, 0, -0.8, 1);
    expect(gentle.torn).toBe(0);
    expect(gentle.hand[1]! - gentle.patch[1]).toBeLessThan(0.3);
    const hard = pull(12, 16, 0, -2, 2.5);
    expect(hard.torn).toBeGreaterThan(0);
  });

  it('a pull held well past the sheet hardens until it tears; a gentle one held as long tears nothing', () => {
    // The middle of the sheet pulled 1 m down over 1 s, then held 8 s, the grip updated every step
    // with the step's dt (as the page does). Without the hardening the links by the hand level off
    // at 43.4% (tear strain 0.45) and nothing ever tears (what a stranger saw on a desktop); with it,
    // measured, the sheet tears 1.9 s into the pull (7 links). Pulled 0.8 m the patch keeps within
    // 0.45 m of the hand, the pull never hardens and nothing tears in the 8 s. Thresholds: a tear at
    // all, and none.
    const held = (d: number) => {
      const { world, cloth } = createClothScene(STILL);
      const cells = new ClothCells(cloth);
      for (let i = 0; i < 60; i++) step(world);
      const [x0, y0] = pointAt(world, cloth, 12, 16);
      const grab = ClothGrab.at(world, cloth, x0, y0, GRAB)!;
      let torn = 0;
      for (let i = 1; i <= 9 * 60; i++) {
        grab.moveTo(x0, y0 - d * Math.min(1, i / 60));
        grab.update(world.dt);
        step(world);
        torn += world.joints.breaks.count;
        cells.loosen(world);
      }
      return { torn, hardened: grab.hardened };
    };
    const hard = held(1);
    expect(hard.torn).toBeGreaterThan(0);
    expect(hard.hardened).toBeGreaterThan(0);
    expect(held(0.8).torn).toBe(0);
  });

  it('a hard pull tears the sheet, and the rip stops with the hand: the sheet stays on the line', () => {
    // As the page pulls (the grip updated every step with dt): the hand drawn 2 m down from the middle
    // or 3 m from the lower middle over 1 s (140 or 210 px of a finger on a phone, 70 px a metre),
    // held 1 s, let go, 2 s more. Kept at full pull once it tore (the grip's pull 15 N and 20 N a metre of
    // lead, 55 N at 2 m), the rip ran across the sheet under the hem and 578 and 640 of its 768 points
    // fell; slack at each tear (GrabOptions.give), measured: 5 and 10 links torn, no point off.
    // Thresholds: a tear every time, and at most 40 points off (a hand-sized flap: the grip holds ~30).
    for (const [row, d] of [
      [12, 2],
      [19, 3],
    ] as const) {
      const { world, cloth } = createClothScene(STILL);
      const cells = new ClothCells(cloth);
      for (let i = 0; i < 60; i++) step(world);
      const [x0, y0] = pointAt(world, cloth, row, 16);
      const grab = ClothGrab.at(world, cloth, x0, y0, gripFor(DEFAULTS.size))!;
      let torn = 0;
      for (let i = 1; i <= 240; i++) {
        if (i <= 120) {
          grab.moveTo(x0, y0 - d * Math.min(1, i / 60));
          grab.update(world.dt);
        } else if (i === 121) grab.release();
        step(world);
        torn += world.joints.breaks.count;
        cells.loosen(world);
      }
      const pieces = findPieces(world, cloth);
      const off = pieces.size.reduce((n, size, k) => n + (pieces.held[k] ? 0 : size), 0);
      expect(torn, `row ${row}, ${d} m`).toBeGreaterThan(0);
      expect(off, `row ${row}, ${d} m`).toBeLessThanOrEqual(40);
    }
  });

  it("the grip pulls at most its cap, which grows from the firm pull with the hand's lead on the held patch", () => {
    const { world, cloth } = createClothScene(STILL);
    for (let i = 0; i < 60; i++) step(world);
    const [x0, y0] = pointAt(world, cloth, 12, 16);
    const grab = ClothGrab.at(world, cloth, x0, y0, GRAB)!;
    expect(grab.cap()).toBeCloseTo(GRAB.firm, 6);
    let most = 0;
    for (let i = 1; i <= 120; i++) {
      grab.moveTo(x0, y0 - 0.01 * i);
      const [px, py] = grab.patch([0, 0]);
      const lead = Math.hypot(x0 - px, y0 - 0.01 * i - py);
      // The cap from its definition, independently of ClothGrab.cap.
      const cap = Math.min(GRAB.maxForce, GRAB.firm + GRAB.slope * Math.max(0, lead - GRAB.firm / GRAB.stiffness));
      step(world);
      expect(grab.force()).toBeLessThanOrEqual(cap * (1 + 1e-9));
      most = Math.max(most, grab.force());
    }
    // The pull 1.2 m down went past the firm pull (the sheet resisted), so the cap was felt.
    expect(most).toBeGreaterThan(GRAB.firm);
  });

  it('the scissors cut what a stroke crosses; a shape cut out falls to the lawn and lies there in the breeze', () => {
    const { world, cloth } = createClothScene(DEFAULTS);
    const cells = new ClothCells(cloth);
    const challenge = new Challenge(world, cloth, cells);
    // A vertical stroke 1 cm right of column 3 at rest, from halfway between rows 1 and 2 to halfway
    // between rows 6 and 7: it crosses the horizontal links of rows 2-6 between columns 3 and 4 (5),
    // the shear links it meets near their ends in the cells of rows 1-6 (10: each diagonal crosses
    // x = 3.01 spacings at 0.01 spacings from a row) and the bending links spanning it (from columns 2
    // and 3 in rows 2-6: 10).
    const { spacing } = sheetGrid(DEFAULTS.size);
    const x = 3 * spacing + 0.01;
    const top = world.components.Position.y[slotOf(cloth.points[0]!)]!;
    expect(cutAlong(world, x, top - 1.5 * spacing, x, top - 6.5 * spacing).length / 2).toBe(5 + 10 + 10);
    cells.loosen(world);
    expect(challenge.update()).toEqual([]);
    // The circle: a stroke round its printed line as the sheet lies, 4 cm out.
    cutTrace(world, cloth, traceLine(SHAPES[0]!.outline, { offset: 0.04 }), challenge.marks);
    cells.loosen(world);
    const done = challenge.update();
    // Measured: fit 1.00, 3 stars (pattern.ts: a cut along the line). At least 0.9.
    expect(done.map((d) => d.shape)).toEqual([0]);
    expect(done[0]!.fit).toBeGreaterThan(0.9);
    expect(done[0]!.stars).toBe(3);
    expect(challenge.scraps).toBe(1);
    // The piece falls (terminal speed about 2.5 m/s) from 3.3 m in the breeze and slumps on the lawn:
    // measured, 5 s on it lies in a heap 0.31 m high between x = 1 and 2.1 m (the walls: -0.75 and 5.6 m). Its
    // lowest point on the lawn, its highest under 0.8 m (a piece the wind pinned to a wall would stand
    // up on it, one as stiff as a plate would stand on its edge, 0.9 m tall), all inside the yard.
    const piece = done[0]!.piece;
    const mine = Array.from(cloth.points).filter((_, i) => challenge.pieces!.pieceOf[i] === piece);
    expect(mine.length).toBeGreaterThan(40);
    for (let i = 0; i < 300; i++) {
      step(world);
      cells.loosen(world);
    }
    const P = world.components.Position;
    const ys = mine.map((h) => P.y[slotOf(h)]!),
      xs = mine.map((h) => P.x[slotOf(h)]!);
    expect(Math.min(...ys)).toBeLessThan(0.01);
    expect(Math.max(...ys)).toBeLessThan(0.8);
    expect(Math.min(...xs)).toBeGreaterThan(YARD.minX);
    expect(Math.max(...xs)).toBeLessThan(YARD.maxX);
  });

  it('a circle traced 0.4 of a cell off its line while the sheet sways, stopping just short, is cut out and scores', () => {
    // The windiest sheet's breeze, 1 s in: a hand traces the circle as the sheet lay when the stroke
    // began (the pointer's path fixed in the world), 0.4 of a cell outside or inside the printed line,
    // in 40 moves a step (1/60 s) apart while the sheet swings on, and stops 0.6 of a cell short of
    // where it began. Cut in the cloth's frame (ScissorsStroke's drift) the cut keeps to the line, and
    // `close` cuts the last gap: the circle comes away (fit 0.97 outside, 0.87 inside).
    // Cut where the pointer is in the world, the swing (2.6-3 cells) shifts the cut off the line: two
    // stars (0.68-0.88); without `close` the circle stays joined to the sheet.
    for (const off of [0.4, -0.4]) {
      const { world, cloth } = createClothScene({ ...DEFAULTS, wind: SHEETS[2]!.wind, gusts: SHEETS[2]!.gusts });
      for (let i = 0; i < 60; i++) step(world);
      const cells = new ClothCells(cloth);
      const challenge = new Challenge(world, cloth, cells);
      const P = world.components.Position;
      const C = cloth.columns,
        { spacing } = sheetGrid(DEFAULTS.size);
      const onSheet = (u: number, v: number): [number, number] => {
        const c = Math.min(C - 2, Math.floor(u / spacing)),
          r = Math.floor(v / spacing),
          fu = u / spacing - c,
          fv = v / spacing - r;
        const at = (row: number, col: number) => slotOf(cloth.points[row * C + col]!);
        const [a, b, d, e] = [at(r, c), at(r, c + 1), at(r + 1, c), at(r + 1, c + 1)];
        const mix = (s: Float64Array) => (s[a]! * (1 - fu) + s[b]! * fu) * (1 - fv) + (s[d]! * (1 - fu) + s[e]! * fu) * fv;
        return [mix(P.x), mix(P.y)];
      };
      const r = 0.46 + off * spacing;
      const moves = 40,
        short = (0.6 * spacing) / r;
      const path: [number, number][] = [];
      for (let k = 0; k <= moves; k++) {
        const a = -Math.PI / 2 + ((2 * Math.PI - short) * k) / moves;
        path.push(onSheet(0.72 + r * Math.cos(a), 1.55 + r * Math.sin(a)));
      }
      const stroke = new ScissorsStroke(world, cloth, ...path[0]!, spacing, 0.9);
      const centre = onSheet(0.72, 1.55);
      let swing = 0;
      for (let k = 1; k <= moves; k++) {
        step(world);
        cells.loosen(world);
        stroke.moveTo(...path[k]!);
        cells.loosen(world);
        const now = onSheet(0.72, 1.55);
        swing = Math.max(swing, Math.hypot(now[0] - centre[0], now[1] - centre[1]));
      }
      stroke.close(2 * spacing, 4 * spacing);
      cells.loosen(world);
      // The circle's middle swings by more than a cell during the stroke.
      expect(swing).toBeGreaterThan(spacing);
      const done = challenge.update();
      expect(done.map((d) => d.shape)).toEqual([0]);
      // Outside the line three stars; inside it the sway adds to the 0.4 cell and the fit, which
      // falls with the distance past 0.45 of a cell (pattern.ts FIT_FULL), is 0.86-0.87: two stars,
      // still well above the world-frame cut's (below 0.8 now).
      if (off > 0) expect(done[0]!.stars).toBe(3);
      else expect(done[0]!.fit).toBeGreaterThan(0.85);
    }
  });

  it('a small piece cut from inside the star is not the star cut out; partCuts says how much of it fell (at most its area share) and hangs', () => {
    // A ring of radius 0.18 m round the star's middle (2, 1.5 m): 0.10 m^2 of the star's 0.48 m^2
    // (21 %) at most, less the cells the cut runs through (a cell is 0.13 m square at 32 points
    // across: measured 1 of the star's 31 cells fell, 18 hang). Too little came away to count (a
    // fifth), and the player is told what fell instead of silence.
    const s = createClothScene(STILL);
    const top = s.world.components.Position.y[slotOf(s.cloth.points[0]!)]!;
    const cells = new ClothCells(s.cloth);
    const ch = new Challenge(s.world, s.cloth, cells);
    ch.update();
    expect(ch.partCuts()).toEqual([]);
    const n = 24,
      R = 0.18;
    for (let k = 0; k < n; k++) {
      const a = (2 * Math.PI * k) / n,
        b = (2 * Math.PI * (k + 1)) / n;
      cutAlong(s.world, 2 + R * Math.cos(a), top - 1.5 - R * Math.sin(a), 2 + R * Math.cos(b), top - 1.5 - R * Math.sin(b));
    }
    cells.loosen(s.world);
    expect(ch.update()).toEqual([]);
    const parts = ch.partCuts();
    expect(parts.map((p) => p.shape)).toEqual([1]);
    expect(parts[0]!.fell).toBeGreaterThan(0);
    expect(parts[0]!.fell).toBeLessThanOrEqual(0.21);
    expect(parts[0]!.hangs).toBeGreaterThan(0.5);
    // The cells the cut runs through are in no piece: they neither fell nor hang.
    expect(parts[0]!.fell + parts[0]!.hangs).toBeLessThan(1 - 0.21 * 0.5);
  });

  it('the breeze sways the sheet, and a gust leans it', () => {
    // The hem's middle point over 4 s of the second sheet's breeze (0.3 m/s, gusts of 1.2 m/s both
    // ways): measured, it swings over 1.5-2 m; in a gust (5 m/s more) it is blown 2.5 m right of where
    // it hung at rest, tearing nothing. At least 0.5 m and 1.5 m.
    const p = { ...DEFAULTS, wind: SHEETS[1]!.wind, gusts: SHEETS[1]!.gusts };
    const { world, cloth } = createClothScene(p);
    const hem = slotOf(cloth.points[cloth.points.length - Math.floor(cloth.columns / 2)]!);
    const P = world.components.Position;
    const rest = P.x[hem]!;
    let lo = Infinity,
      hi = -Infinity;
    for (let i = 0; i < 240; i++) {
      step(world);
      lo = Math.min(lo, P.x[hem]!);
      hi = Math.max(hi, P.x[hem]!);
    }
    expect(hi - lo).toBeGreaterThan(0.5);
    applyWind(world, p, 5);
    let torn = 0;
    for (let i = 0; i < 120; i++) {
      step(world);
      torn += world.joints.breaks.count;
    }
    expect(P.x[hem]! - rest).toBeGreaterThan(1.5);
    expect(torn).toBe(0);
  });

  it('a 45-degree cut either way is drawn as a straight edge: each cell it clips keeps its far half', () => {
    // A stroke at 45 degrees through the still sheet clips a corner off each cell it crosses (its two
    // sides by that corner cut). Drawn with one fixed split (upper-left and lower-right triangles),
    // a cut down to the left kept half of each such cell but one down to the right none (stairs of
    // whole cells). Split along the other diagonal where that keeps more, each clipped cell keeps the
    // triangle away from the cut, whose sides are both whole, and the drawn edge is the diagonal.
    for (const dir of [1, -1]) {
      const { world, cloth } = createClothScene(STILL);
      for (let i = 0; i < 30; i++) step(world);
      const cells = new ClothCells(cloth);
      const C = cloth.columns;
      // From 0.3 cells off point (6, 16) (above it), 8 cells each way down the diagonal.
      const [x0, y0] = pointAt(world, cloth, 6, 16);
      const { spacing } = sheetGrid(DEFAULTS.size);
      const y = y0 + 0.3 * spacing;
      expect(cutAlong(world, x0 - dir * 8 * spacing, y + 8 * spacing, x0 + dir * 8 * spacing, y - 8 * spacing).length).toBeGreaterThan(0);
      let clipped = 0;
      for (let cell = 0; cell < cells.across * cells.down; cell++) {
        const q = 4 * cell;
        const [top, left, bottom, right] = [0, 1, 2, 3].map((k) => isAlive(world, cells.sides[q + k]!));
        const dead = [top, left, bottom, right].filter((a) => !a).length;
        if (dead === 0) {
          expect(cells.drawn(world, cell)).toBe(3);
          continue;
        }
        if (dead !== 2 || (top === bottom && left === right)) continue;
        clipped++;
        const t = cells.drawn(world, cell);
        // One triangle, and the one whose two sides are the cell's whole ones.
        const want = top && left ? 1 : bottom && right ? 2 : top && right ? 4 : 8;
        expect(t, `cell ${Math.floor(cell / (C - 1))},${cell % (C - 1)}`).toBe(want);
      }
      // The stroke crosses about 16 cells, clipping a corner of each.
      expect(clipped).toBeGreaterThan(12);
    }
  });

  it('the shapes lie inside the sheet, apart; a torn link takes out the two triangles beside it', () => {
    const { columns, rows, height } = sheetGrid(DEFAULTS.size);
    const masks = shapeCells(DEFAULTS.size);
    const seen = new Set<number>();
    for (const [i, m] of masks.entries()) {
      expect(m.length, SHAPES[i]!.name).toBeGreaterThan(30);
      for (const c of m) {
        expect(seen.has(c)).toBe(false);
        seen.add(c);
      }
      const o = SHAPES[i]!.outline;
      for (let k = 0; k < o.length; k += 2) {
        expect(o[k]!).toBeGreaterThan(0);
        expect(o[k]!).toBeLessThan(SHEET_WIDTH);
        expect(o[k + 1]!).toBeGreaterThan(0);
        expect(o[k + 1]!).toBeLessThan(height);
      }
    }
    // The fit: a cut round the heart 0.4 m out of its line (a hole more than twice the heart) gets no
    // star (measured 0; 0.46 before cloth outside the line counted by its area), nor a 1.8 m square
    // round it (a piece ripped off with it; measured 0).
    const heart = SHAPES[2]!.outline;
    let hx = 0,
      hy = 0;
    for (let k = 0; k < heart.length; k += 2) {
      hx += heart[k]! / (heart.length / 2);
      hy += heart[k + 1]! / (heart.length / 2);
    }
    const scoreOf = (ring: [number, number][]): number[] => {
      const s = createClothScene(STILL);
      const top = s.world.components.Position.y[slotOf(s.cloth.points[0]!)]!;
      const cells = new ClothCells(s.cloth);
      const ch = new Challenge(s.world, s.cloth, cells);
      for (let k = 1; k < ring.length; k++) cutAlong(s.world, ring[k - 1]![0], top - ring[k - 1]![1], ring[k]![0], top - ring[k]![1]);
      cells.loosen(s.world);
      return ch.update().map((d) => d.stars);
    };
    const out: [number, number][] = [];
    for (let k = 0; k <= heart.length; k += 2) {
      const x = heart[k % heart.length]!,
        y = heart[(k + 1) % heart.length]!,
        d = Math.hypot(x - hx, y - hy);
      out.push([x + ((x - hx) / d) * 0.4, y + ((y - hy) / d) * 0.4]);
    }
    expect(scoreOf(out)).toEqual([0]);
    expect(
      scoreOf([
        [hx - 0.9, hy - 0.9],
        [hx + 0.9, hy - 0.9],
        [hx + 0.9, hy + 0.9],
        [hx - 0.9, hy + 0.9],
        [hx - 0.9, hy - 0.9],
      ]),
    ).toEqual([0]);
    expect(insidePolygon([0, 0, 1, 0, 1, 1, 0, 1], 0.5, 0.5)).toBe(true);
    expect(insidePolygon([0, 0, 1, 0, 1, 1, 0, 1], 1.5, 0.5)).toBe(false);
    expect(segmentsCross(0, 0, 1, 1, 0, 1, 1, 0)).toBe(true);
    expect(segmentsCross(0, 0, 1, 0, 0, 1, 1, 1)).toBe(false);
    const { world, cloth } = createClothScene(STILL);
    const cells = new ClothCells(cloth);
    const count = (): number => {
      let n = 0;
      for (let c = 0; c < cells.across * cells.down; c++) n += [0, 1, 1, 2][cells.triangles(world, c)]!;
      return n;
    };
    expect(count()).toBe(2 * (columns - 1) * (rows - 1));
    // Point (5, 5)'s right link: structural links come first, each point's right then down link.
    const right = cloth.links[2 * (5 * columns + 5) - 5]!;
    removeJoint(world, right);
    expect(isAlive(world, right)).toBe(false);
    expect(count()).toBe(2 * (columns - 1) * (rows - 1) - 2);
  });
});
