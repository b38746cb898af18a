/**
 * The lab's challenge, headless: shapes printed on the sheet with dashed cutting lines (a circle, a
 * star and a heart), to be cut out. A shape counts as cut out once a piece that came away holds a
 * fifth of its cells (the cells of the sheet at rest whose centres lie inside its line), or less than
 * a quarter of them still hang on the line: it is scored by the piece that came away with most.
 *
 * Its fit says how closely the cut followed the line, both ways (cutFit): how much of the piece's
 * edge lies on the line (cloth cut away with the shape, or a cut inside it, lies off it), and how
 * much of the line the edge follows (a cut inside the line, or across a star's points, leaves it),
 * with the line's sharp corners (a star's points, a pane's corners) weighing as much as the rest of
 * it: a star's narrow points are a small part of its line and area but most of its look. Each
 * sample counts whole up to FIT_FULL link spacings off and nothing from FIT_ZERO. The piece's edge
 * is taken from where the scissors went (Challenge.marks: finer than the grid, whose points lie too
 * far apart to hold a star's points) and, where it tore, from the links it parted along.
 * Measured over a spread of hand-like cuts on the still sheet at 32 points across (a spacing is
 * 0.13 m: 14 px on a desktop; scripts/lab-cloth-cuts.mjs): careful cuts (0.3 spacings off the line,
 * wobbling 0.3) 0.96-1.00, three stars; 0.5 out wobbling 0.4 0.89-0.93; a ragged one (0.3 out,
 * wobbling 0.7 across it) 0.71-0.90, two (its steadiness counts, `Fit.steady`); 0.8 out 0.77-0.80,
 * two; careless ones (1.2 spacings out, a wobble of 1.2, 1 inside) 0.52-0.73, mostly one; the star's
 * points cut across 2 spacings back 0.79; 2 spacings out or more, 0-0.14. The score falls with the
 * distance from 0.45 of a spacing (about 6 px) on, so its percentage says how closely the cut
 * followed the line. A notch or a stray slit or tear into the shape (`Fit.clean`) costs a star from
 * a link and a half deep: a cut on the line with a notch 1.5 spacings deep 0.79. A cut that runs
 * short of the line along a stretch, a corner or a lobe cut off (`Fit.whole`), costs a star too: a
 * heart cut as a 7-sided polygon through its line 0.83 (0.94 on the marks' distances alone).
 */
import { type Cloth, isAlive, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import type { ClothCells } from './cells';
import { type ClothPieces, findPieces } from './pieces';
import { sheetGrid } from './scene';

/** A printed shape: its name and outline on the sheet at rest, m (x right from the left edge, y down from the top). */
export interface Shape {
  readonly name: string;
  /** Outline, m (x, y interleaved), a closed polygon. */
  readonly outline: readonly number[];
  /** Colour of its print, 0xRRGGBB. */
  readonly color: number;
  /**
   * A basket on the lawn the piece must land in: its centre (world x, m) and width (m). Its stars are
   * then for where it lands (Challenge.watch), not for its fit.
   */
  readonly drop?: { readonly x: number; readonly width: number };
  /**
   * How it is printed: 'cut' (a tint inside a dashed cutting line, the default), 'pane' (as 'cut', in
   * a wooden frame half a window bar wide: levels.ts WINDOW_FRAME), 'bag' (a peg bag) or 'tear' (a
   * strip below a perforation).
   */
  readonly style?: 'cut' | 'pane' | 'bag' | 'tear';
}

/** A regular polygon of `n` corners (a circle's outline at n = 48) or a star of n points with inner radius `inner`. */
function ring(cx: number, cy: number, r: number, n: number, inner = r): number[] {
  const out: number[] = [];
  const k = inner === r ? n : 2 * n;
  for (let i = 0; i < k; i++) {
    const a = -Math.PI / 2 + (2 * Math.PI * i) / k,
      rr = inner !== r && i % 2 === 1 ? inner : r;
    out.push(cx + rr * Math.cos(a), cy + rr * Math.sin(a));
  }
  return out;
}

/** A heart of half-width about `s`, its dip at (cx, cy - 0.55 s) and its tip at (cx, cy + 0.95 s) (y down). */
function heart(cx: number, cy: number, s: number): number[] {
  const out: number[] = [];
  for (let i = 0; i < 48; i++) {
    const t = (2 * Math.PI * i) / 48;
    // The classic heart curve x = 16 sin^3 t, y = 13 cos t - 5 cos 2t - 2 cos 3t - cos 4t, scaled.
    const x = 16 * Math.sin(t) ** 3,
      y = 13 * Math.cos(t) - 5 * Math.cos(2 * t) - 2 * Math.cos(3 * t) - Math.cos(4 * t);
    out.push(cx + (s * x) / 16, cy - (s * y) / 16 + 0.1 * s);
  }
  return out;
}

/** The three shapes, side by side across the middle of the 4 m sheet. */
export const SHAPES: readonly Shape[] = Object.freeze([
  { name: 'circle', outline: ring(0.72, 1.55, 0.46, 48), color: 0x2a9d8f },
  { name: 'star', outline: ring(2, 1.5, 0.6, 5, 0.27), color: 0xe9a21b },
  { name: 'heart', outline: heart(3.28, 1.5, 0.5), color: 0xd6336c },
]);

/** Whether point (x, y) is inside the closed polygon `poly` (x, y interleaved): the even-odd rule. */
export function insidePolygon(poly: readonly number[], x: number, y: number): boolean {
  let inside = false;
  const n = poly.length / 2;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const xi = poly[2 * i]!,
      yi = poly[2 * i + 1]!,
      xj = poly[2 * j]!,
      yj = poly[2 * j + 1]!;
    if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/** Distance from point (x, y) to the closed polygon `poly`'s outline, m; the nearest point of it is written to `at`, if given. */
function outlineDistance(poly: readonly number[], x: number, y: number, at?: [number, number]): number {
  let best = Infinity;
  const n = poly.length / 2;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const ax = poly[2 * j]!,
      ay = poly[2 * j + 1]!,
      dx = poly[2 * i]! - ax,
      dy = poly[2 * i + 1]! - ay,
      l2 = dx * dx + dy * dy;
    const t = l2 > 0 ? Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / l2)) : 0;
    const d = Math.hypot(x - ax - t * dx, y - ay - t * dy);
    if (d < best) {
      best = d;
      if (at) {
        at[0] = ax + t * dx;
        at[1] = ay + t * dy;
      }
    }
  }
  return best;
}

/**
 * How far the closed polygon `poly` reaches across from its outline point (qx, qy) in the direction
 * (ux, uy) (a unit vector into it), m: the distance to the next crossing of its outline (Infinity if none).
 */
function across(poly: readonly number[], qx: number, qy: number, ux: number, uy: number): number {
  let best = Infinity;
  const n = poly.length / 2;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const ax = poly[2 * j]!,
      ay = poly[2 * j + 1]!,
      ex = poly[2 * i]! - ax,
      ey = poly[2 * i + 1]! - ay;
    // q + t u = a + v e, solved for t > 0 and v in [0, 1].
    const den = ux * ey - uy * ex;
    if (Math.abs(den) < 1e-12) continue;
    const t = ((ax - qx) * ey - (ay - qy) * ex) / den,
      v = ((ax - qx) * uy - (ay - qy) * ux) / den;
    if (t > 1e-6 && v >= 0 && v <= 1) best = Math.min(best, t);
  }
  return best;
}

/** A shape on a sheet of one size: its cells, and samples of its line for the fit (see the header). */
export interface ShapeMask {
  /** Cells (row-major indices) whose centres lie inside the line. */
  readonly inside: readonly number[];
  /** Points along the line, every LINE_SAMPLE m or a little less, m (sheet coordinates at rest, x and y interleaved). */
  readonly line: Float64Array;
  /** Its sharp corners (convex, inside angle under CORNER_ANGLE: a star's points, a pane's corners), m (as `line`). */
  readonly corners: Float64Array;
}

/** A convex corner of a line with an inside angle under CORNER_ANGLE radians (100 degrees) is sharp (ShapeMask.corners). */
export const CORNER_ANGLE = (100 * Math.PI) / 180;

/** The convex corners of the closed polygon `poly` (x, y interleaved) with an inside angle under CORNER_ANGLE. */
function sharpCorners(poly: readonly number[]): number[] {
  const n = poly.length / 2;
  let area = 0;
  for (let i = 0, j = n - 1; i < n; j = i++) area += poly[2 * j]! * poly[2 * i + 1]! - poly[2 * i]! * poly[2 * j + 1]!;
  const out: number[] = [];
  for (let k = 0; k < n; k++) {
    const p = (k + n - 1) % n,
      q = (k + 1) % n;
    const x = poly[2 * k]!,
      y = poly[2 * k + 1]!,
      ax = poly[2 * p]! - x,
      ay = poly[2 * p + 1]! - y,
      bx = poly[2 * q]! - x,
      by = poly[2 * q + 1]! - y;
    // Convex: the line turns there the way it winds (the cross product of the sides in and out has the area's sign).
    const convex = Math.sign(area) * (-ax * by + ay * bx) > 0;
    const angle = Math.acos(Math.max(-1, Math.min(1, (ax * bx + ay * by) / (Math.hypot(ax, ay) * Math.hypot(bx, by)))));
    if (convex && angle < CORNER_ANGLE) out.push(x, y);
  }
  return out;
}

/** The line is sampled every LINE_SAMPLE m for the fit (ShapeMask.line). */
export const LINE_SAMPLE = 0.02;
/**
 * The fit's tolerance, in link spacings: a stretch of the cut (or of the line) up to FIT_FULL spacings
 * from the line (from the cut) counts whole, one FIT_ZERO spacings off or more counts nothing, and
 * linearly between: a hand's trace of the line is seldom nearer than half a spacing (6 px on a
 * desktop), and every spacing further off costs 0.65 of the sample's score.
 */
export const FIT_FULL = 0.45,
  FIT_ZERO = 2;

/**
 * A ragged edge's cost (cutFit's `steady`): none while the standard deviation of the edge's distances
 * from the line is within STEADY_FREE link spacings, RAGGED_COST of the fit once it is RAGGED_FULL
 * spacings more, linearly between (so a cut zigzagging across the line within the tolerance does
 * not score as a clean one; see the header's figures). A steady cut 0.4 spacings inside the line on a
 * swaying sheet wanders 0.34 spacings (test/games/lab-cloth.test.ts).
 */
/**
 * A winding cut's cost (cutFit's `steady`): none while the scissors' way along the piece's edge is
 * up to WINDING_FREE times the line's length (a careful trace and a second pass over part of it),
 * RAGGED_COST of the fit once it is WINDING_FULL times more (a zigzag over the line: 4 to 5 times).
 */
export const WINDING_FREE = 1.8,
  WINDING_FULL = 1.5;
export const STEADY_FREE = 0.35,
  RAGGED_FULL = 0.35,
  RAGGED_COST = 0.2;

/**
 * A notch's or a stray tear's cost (cutFit's `clean`): how deep into the shape the edge's FLAW_RANK-th
 * deepest sample lies, from the line or, for a cut running inside it, from the edge's mean depth (a
 * notch's or a slit's tip; one stray sample alone does not count, nor does a cut run evenly inside
 * the line, which the rest of the fit scores, nor a stray mark outside: another shape's cut nearby). A sample's depth is its distance d into
 * the shape (out of it: -d), deeper than d past FIT_FULL spacings where the shape is narrow:
 * d / (1 - d / w), w its width across there (d / w at most FLAW_REACH: a notch three quarters across
 * a star's arm counts four times its depth). The flaw
 * costs nothing up to FLAW_FREE link spacings (+ half the slack), FLAW_COST of the fit FLAW_FULL
 * spacings further, linearly between: a slip a link and a half deep into a shape cut along its line
 * costs a star (scripts/lab-cloth-cuts.mjs).
 */
export const FLAW_RANK = 2,
  FLAW_REACH = 0.75,
  FLAW_FREE = 1,
  FLAW_FULL = 0.6,
  FLAW_COST = 0.2;

/**
 * A cut short of the line's cost (cutFit's `whole`): how far inside the line the cut runs along its
 * worst stretch of a link spacing, the line's samples along it measured to the nearest point of the
 * piece's edge where that point lies inside the shape (a chord across a heart's lobe or a star's
 * point, a corner cut off: the piece the player sees misses that part of the shape). Free up to
 * SHORT_FREE link spacings (+ half the slack), SHORT_COST of the fit SHORT_FULL spacings further,
 * linearly between: a heart cut as a 7-sided polygon through its line (1.05 spacings short at the
 * lobes) loses its third star, a careful trace (under 0.3 spacings short) keeps it.
 */
export const SHORT_FREE = 0.5,
  SHORT_FULL = 0.4,
  SHORT_COST = 0.2,
  SHORT_CORNER = 1.5;

/**
 * A scissors' mark (ScissorsStroke's `marks`) counts toward a piece's edge within MARK_REACH link
 * spacings of the middle of a link on the edge (the end of a star's point lies up to 1.5 spacings
 * beyond the grid's last point in it), and stands for that link's cut within MARK_COVER spacings
 * (the stroke crosses a link within half a spacing of its middle).
 */
export const MARK_REACH = 1.5,
  MARK_COVER = 1;

/**
 * The edge of the piece of a cloth of `columns` x `rows` points made of the points `inPiece` says
 * (by point index, row-major), as samples in sheet coordinates at rest (m, x and y interleaved): where
 * the piece parts from the rest of the cloth, the links from a point of the piece to one out of it,
 * and where it is slit, the links between two of its points that are gone (`cutLink`, if given, says
 * whether the link from point i to its right (`down` false) or lower neighbour is). The scissors'
 * marks (`marks`, sheet coordinates at rest) within MARK_REACH spacings of such a link's middle
 * are samples, and the middle of each such link with no mark within MARK_COVER spacings (a tear);
 * and a sample half a spacing out from each of its points on the sheet's edge. The length of the
 * scissors' way along the edge (m: between consecutive marks near it, a step over two spacings being
 * a new stroke) is written to `path.length`, if given.
 */
export function pieceEdge(
  columns: number,
  rows: number,
  inPiece: (i: number) => boolean,
  cutLink?: (i: number, down: boolean) => boolean,
  marks: ArrayLike<number> = [],
  path?: { length: number },
): number[] {
  const { spacing: s } = sheetGrid(columns);
  const C = columns,
    R = rows;
  const links: number[] = [],
    out: number[] = [];
  for (let r = 0; r < R; r++)
    for (let c = 0; c < C; c++) {
      const i = r * C + c,
        here = inPiece(i);
      if (c + 1 < C && (here !== inPiece(i + 1) || (here && cutLink?.(i, false)))) links.push((c + 0.5) * s, r * s);
      if (r + 1 < R && (here !== inPiece(i + C) || (here && cutLink?.(i, true)))) links.push(c * s, (r + 0.5) * s);
      if (!here) continue;
      if (c === 0) out.push(-0.5 * s, r * s);
      if (c === C - 1) out.push((C - 0.5) * s, r * s);
      if (r === 0) out.push(c * s, -0.5 * s);
      if (r === R - 1) out.push(c * s, (R - 0.5) * s);
    }
  const reach2 = (MARK_REACH * s) ** 2,
    cover2 = (MARK_COVER * s) ** 2;
  const covered = new Uint8Array(links.length / 2);
  let nearBefore = false,
    length = 0;
  for (let k = 0; k < marks.length; k += 2) {
    const x = marks[k]!,
      y = marks[k + 1]!;
    let near = false;
    for (let j = 0; j < links.length; j += 2) {
      const d2 = (links[j]! - x) ** 2 + (links[j + 1]! - y) ** 2;
      if (d2 <= reach2) near = true;
      if (d2 <= cover2) covered[j / 2] = 1;
    }
    if (near) out.push(x, y);
    // The way the scissors went along the edge: from each mark near it to the next (a stroke's marks
    // are a quarter spacing apart, a trace's (traces.ts cutTrace) its points; a step over two
    // spacings is a new stroke).
    if (near && nearBefore) {
      const step = Math.hypot(x - marks[k - 2]!, y - marks[k - 1]!);
      if (step <= 2 * s) length += step;
    }
    nearBefore = near;
  }
  if (path) path.length = length;
  for (let j = 0; j < covered.length; j++) if (!covered[j]) out.push(links[2 * j]!, links[2 * j + 1]!);
  return out;
}

/** Points along the closed polygon `poly` (x, y interleaved), every `step` m or a little less, from its first corner. */
function alongLine(poly: readonly number[], step: number): number[] {
  const n = poly.length / 2;
  const out: number[] = [];
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    const ax = poly[2 * i]!,
      ay = poly[2 * i + 1]!,
      dx = poly[2 * j]! - ax,
      dy = poly[2 * j + 1]! - ay;
    const k = Math.max(1, Math.ceil(Math.hypot(dx, dy) / step));
    for (let t = 0; t < k; t++) out.push(ax + (dx * t) / k, ay + (dy * t) / k);
  }
  return out;
}

/** Per point of `points` (x, y interleaved), the distance to the nearest point of `to`, m (Infinity if `to` is empty). */
function nearest(points: ArrayLike<number>, to: ArrayLike<number>): Float64Array {
  const out = new Float64Array(points.length / 2);
  for (let k = 0; k < out.length; k++) {
    const x = points[2 * k]!,
      y = points[2 * k + 1]!;
    let best = Infinity;
    for (let j = 0; j < to.length; j += 2) best = Math.min(best, (to[j]! - x) ** 2 + (to[j + 1]! - y) ** 2);
    out[k] = Math.sqrt(best);
  }
  return out;
}

/**
 * Per shape of `shapes`, its cells and its line's samples on a sheet of `size` points across, at rest
 * (see ShapeMask).
 */
export function shapeMasks(size: number, shapes: readonly Shape[] = SHAPES): ShapeMask[] {
  const { columns, rows, spacing } = sheetGrid(size);
  return shapes.map((s) => {
    const inside: number[] = [];
    for (let r = 0; r + 1 < rows; r++)
      for (let c = 0; c + 1 < columns; c++)
        if (insidePolygon(s.outline, (c + 0.5) * spacing, (r + 0.5) * spacing)) inside.push(r * (columns - 1) + c);
    return { inside, line: Float64Array.from(alongLine(s.outline, LINE_SAMPLE)), corners: Float64Array.from(sharpCorners(s.outline)) };
  });
}

/** How well a piece's edge follows a shape's line (cutFit). */
export interface Fit {
  /**
   * The fit, in [0, 1]: the harmonic mean of `onLine` and `followed`, times `whole` and the lesser
   * of `steady` and `clean` (a wobbling cut's inward swings are its raggedness, not a second fault).
   */
  fit: number;
  /**
   * How free of a notch or a stray tear the edge is, in [1 - FLAW_COST, 1]: 1 while `flaw` is within
   * FLAW_FREE spacings (+ half the slack), down by FLAW_COST over the next FLAW_FULL spacings.
   */
  clean: number;
  /** How deep into the shape the edge's FLAW_RANK-th deepest sample lies (from the line, or the edge's mean depth inside it), m (>= 0; see FLAW_RANK). */
  flaw: number;
  /**
   * How steady the edge is, in [(1 - RAGGED_COST)^2, 1]: 1 while the standard deviation of its
   * samples' distances from the line is within STEADY_FREE spacings (+ half the slack), down by
   * RAGGED_COST over the next RAGGED_FULL spacings; times 1 less up to RAGGED_COST for a winding way
   * of the scissors (WINDING_FREE, WINDING_FULL).
   */
  steady: number;
  /**
   * How whole the piece is, in [1 - SHORT_COST, 1]: 1 while `short` is within SHORT_FREE spacings
   * (+ half the slack), down by SHORT_COST over the next SHORT_FULL spacings.
   */
  whole: number;
  /** How far inside the line the cut runs along its worst link spacing of line, m (>= 0; see SHORT_FREE). */
  short: number;
  /** How much of the piece's edge lies on the line (each sample scored by its distance from the line), in [0, 1]. */
  onLine: number;
  /** How much of the line the piece's edge follows (each sample scored by its distance from the edge), in [0, 1]. */
  followed: number;
}

/**
 * The fit of a piece whose edge is `edge` (pieceEdge: sheet coordinates at rest, m) to `shape`, with
 * `mask` its ShapeMask on a sheet of link spacing `spacing` m: each sample of the edge scores by its
 * distance from the line, and each sample of the line by its distance from the edge less its reach:
 * 1 up to FIT_FULL spacings + `slack` m, 0 from FIT_ZERO spacings + `slack`, linearly between.
 * `onLine` is the edge's mean score, `followed` the line's, and the fit their harmonic mean (both
 * must be good: a piece with the shape and cloth round it lies off the line; one cut inside the line,
 * or across a star's arms, leaves parts of the line unfollowed) times the lesser of `steady` and
 * `clean`: a ragged edge (its distance from the line wandering) costs up to RAGGED_COST, and so does
 * a winding way of the scissors along it, `path` m (pieceEdge's `path.length`; 0: not known) against
 * the line's length; a notch, a slit or a tear into the shape costs up to FLAW_COST (see FLAW_RANK);
 * and a stretch of the line the cut runs short of, a corner cut off, up to SHORT_COST (`whole`).
 * 0 for an empty edge.
 * @throws RangeError if `spacing` is not positive or `slack` or `path` is negative or not finite.
 */
export function cutFit(shape: Shape, mask: ShapeMask, edge: readonly number[], spacing: number, slack = 0, path = 0): Fit {
  if (!(spacing > 0)) throw new RangeError(`cutFit: spacing must be > 0 m, got ${spacing}`);
  if (!(slack >= 0) || !Number.isFinite(slack)) throw new RangeError(`cutFit: slack must be a finite number >= 0, got ${slack}`);
  if (!(path >= 0) || !Number.isFinite(path)) throw new RangeError(`cutFit: path must be a finite length >= 0 m, got ${path}`);
  if (edge.length === 0) return { fit: 0, onLine: 0, followed: 0, steady: 1, clean: 1, flaw: 0, short: 0, whole: 1 };
  const full = FIT_FULL * spacing + slack,
    zero = FIT_ZERO * spacing + slack;
  const score = (d: number): number => Math.max(0, Math.min(1, (zero - d) / (zero - full)));
  let onLine = 0,
    dSum = 0,
    dSum2 = 0;
  // The FLAW_RANK largest depths inside the line (a sample outside it has a negative depth: its
  // distance out), largest first, and the mean depth.
  const worst = new Float64Array(FLAW_RANK).fill(-Infinity);
  let depthSum = 0;
  const q: [number, number] = [0, 0];
  for (let k = 0; k < edge.length; k += 2) {
    const x = edge[k]!,
      y = edge[k + 1]!;
    const d = outlineDistance(shape.outline, x, y, q);
    onLine += score(d);
    dSum += d;
    dSum2 += d * d;
    const inside = insidePolygon(shape.outline, x, y);
    depthSum += inside ? d : -d;
    // Into a narrow part (a star's arm), a notch is deeper than its distance from the line: it
    // reaches across part of the cloth there (`across`), and one halfway across nearly parts it.
    let depth = inside ? d : -d;
    if (inside && d > FIT_FULL * spacing) {
      const width = across(shape.outline, q[0], q[1], (x - q[0]) / d, (y - q[1]) / d);
      depth = d / (1 - Math.min(FLAW_REACH, d / width));
    }
    if (depth > worst[FLAW_RANK - 1]!) {
      let j = FLAW_RANK - 1;
      for (; j > 0 && worst[j - 1]! < depth; j--) worst[j] = worst[j - 1]!;
      worst[j] = depth;
    }
  }
  const n = edge.length / 2;
  // Measured from the line, or from the cut's mean depth where it runs inside the line.
  const flaw = n >= FLAW_RANK ? Math.max(0, worst[FLAW_RANK - 1]! - Math.max(0, depthSum / n)) : 0;
  const clean = 1 - FLAW_COST * Math.min(1, Math.max(0, flaw - FLAW_FREE * spacing - slack / 2) / (FLAW_FULL * spacing));
  onLine /= n;
  // How much the edge's distance from the line wanders (its standard deviation): a steady cut keeps
  // one distance, a ragged one zigzags across the line however near it stays on the whole.
  const wander = Math.sqrt(Math.max(0, dSum2 / n - (dSum / n) ** 2));
  // And how far the scissors went along the edge for the length of the line: a zigzag over the
  // line (within the tolerance every way) goes several times as far as the line.
  let line = 0;
  const o = shape.outline,
    m = o.length / 2;
  for (let i = 0; i < m; i++) line += Math.hypot(o[2 * ((i + 1) % m)]! - o[2 * i]!, o[2 * ((i + 1) % m) + 1]! - o[2 * i + 1]!);
  const winding = Math.min(1, Math.max(0, path / line - WINDING_FREE) / WINDING_FULL);
  const steady =
    (1 - RAGGED_COST * Math.min(1, Math.max(0, wander - (STEADY_FREE * spacing + slack / 2)) / (RAGGED_FULL * spacing))) *
    (1 - RAGGED_COST * winding);
  const mean = (points: ArrayLike<number>): number => {
    const d = nearest(points, edge);
    let sum = 0;
    for (let k = 0; k < d.length; k++) sum += score(d[k]!);
    return sum / d.length;
  };
  // The sharp corners weigh as much as the rest of the line: cutting across a star's points misses
  // little of its line but much of its look.
  const followed = mask.corners.length > 0 ? (mean(mask.line) + mean(mask.corners)) / 2 : mean(mask.line);
  // How far short of the line the piece falls along its worst stretch (SHORT_FREE): per sample of the
  // line, its distance to the nearest sample of the edge if that one lies inside the shape (else 0),
  // and of those the k-th largest, k the samples in a link spacing of line (one stray sample, or a
  // notch's narrow tip, which `clean` scores, does not count).
  const shortBy = new Float64Array(mask.line.length / 2);
  const pointReach2 = (SHORT_CORNER * spacing) ** 2;
  let shortSum = 0;
  for (let k = 0; k < shortBy.length; k++) {
    const x = mask.line[2 * k]!,
      y = mask.line[2 * k + 1]!;
    let nearCorner = false;
    for (let j = 0; j < mask.corners.length; j += 2)
      if ((mask.corners[j]! - x) ** 2 + (mask.corners[j + 1]! - y) ** 2 < pointReach2) nearCorner = true;
    if (nearCorner) continue;
    let best = Infinity,
      at = -1;
    for (let j = 0; j < edge.length; j += 2) {
      const d2 = (edge[j]! - x) ** 2 + (edge[j + 1]! - y) ** 2;
      if (d2 < best) {
        best = d2;
        at = j;
      }
    }
    shortBy[k] = at >= 0 && insidePolygon(shape.outline, edge[at]!, edge[at + 1]!) ? Math.sqrt(best) : 0;
    shortSum += shortBy[k]!;
  }
  shortBy.sort();
  const rank = Math.min(shortBy.length, Math.max(1, Math.round(spacing / LINE_SAMPLE)));
  const short = Math.max(0, (shortBy[shortBy.length - rank] ?? 0) - shortSum / shortBy.length);
  const whole = 1 - SHORT_COST * Math.min(1, Math.max(0, short - SHORT_FREE * spacing - slack / 2) / (SHORT_FULL * spacing));
  const fit = onLine + followed > 0 ? (Math.min(whole, clean, steady) * 2 * onLine * followed) / (onLine + followed) : 0;
  return { fit, onLine, followed, steady, clean, flaw, short, whole };
}

/** Per shape, the cells (row-major indices) of a sheet of `size` points across whose centres at rest lie inside it. */
export function shapeCells(size: number): number[][] {
  return shapeMasks(size).map((m) => [...m.inside]);
}

/** A shape cut out. */
export interface CutOut {
  /** Index in SHAPES. */
  shape: number;
  /** The fit, in [0, 1] (see the header). */
  fit: number;
  /** Stars for the fit (starsFor), 0 to 3. */
  stars: number;
  /** How steady its edge is (Fit.steady), in [(1 - RAGGED_COST)^2, 1]; absent when no piece holds it. */
  steady?: number;
  /** How free of a notch or a stray tear its edge is (Fit.clean), in [1 - FLAW_COST, 1]; absent when no piece holds it. */
  clean?: number;
  /** Its edge's flaw (Fit.flaw), m; absent when no piece holds it. */
  flaw?: number;
  /** The piece it came away in (an index of that moment's ClothPieces), -1 if none holds any of it (cut to bits). */
  piece: number;
  /**
   * For a shape with a basket (Shape.drop): 'falling' until the piece lands, then 'in' or 'out' of
   * the basket (its stars set then: Challenge.watch); absent for the others.
   */
  drop?: 'falling' | 'in' | 'out';
  /** Where a dropped piece landed, world x, m (NaN until it has). */
  landedAt?: number;
}

/** A shape not cut out yet is spoilt (Challenge.spoilt) once more than this share of its inner cells is torn. */
export const SPOILT_SHARE = 0.2;

/** Stars for a fit in [0, 1]: 3 from 0.9, 2 from 0.7, 1 from 0.4, else none. */
export function starsFor(fit: number): number {
  return fit >= 0.9 ? 3 : fit >= 0.7 ? 2 : fit >= 0.4 ? 1 : 0;
}

/**
 * Per cell of the sheet, the free piece it is in (`pieceOfCell`, -1: none) and whether it hangs in a
 * held one (`hanging`, 1 or 0). A cell is in a piece when its four corners are and at least one of
 * its triangles is whole.
 */
function cellOwners(
  world: PhysicsWorld,
  cloth: Cloth,
  cells: ClothCells,
  pieces: ClothPieces,
): { pieceOfCell: Int32Array; hanging: Uint8Array } {
  const C = cloth.columns;
  const cellPiece = (cell: number): number => {
    const r = Math.floor(cell / cells.across),
      c = cell % cells.across;
    const i = r * C + c;
    const p = pieces.pieceOf[i]!;
    if (pieces.pieceOf[i + 1] !== p || pieces.pieceOf[i + C] !== p || pieces.pieceOf[i + C + 1] !== p) return -1;
    return cells.triangles(world, cell) ? p : -1;
  };
  const n = cells.across * cells.down;
  const pieceOfCell = new Int32Array(n);
  const hanging = new Uint8Array(n);
  for (let cell = 0; cell < n; cell++) {
    const p = cellPiece(cell);
    pieceOfCell[cell] = p >= 0 && !pieces.held[p] ? p : -1;
    hanging[cell] = p >= 0 && pieces.held[p] ? 1 : 0;
  }
  return { pieceOfCell, hanging };
}

/**
 * The edge of piece `piece` of `pieces` (pieceEdge), with the structural links cut between two of
 * its points (a slit into it).
 */
function edgeOf(
  world: PhysicsWorld,
  cloth: Cloth,
  cells: ClothCells,
  pieces: ClothPieces,
  piece: number,
  marks: ArrayLike<number>,
  path?: { length: number },
): number[] {
  const C = cloth.columns,
    R = cloth.rows,
    A = cells.across,
    sides = cells.sides;
  // Point (r, c)'s right link is its cell's top side (the bottom side of the cell above on the last
  // row), its lower link its cell's left side (the right side of the cell to its left in the last column).
  const cutLink = (i: number, down: boolean): boolean => {
    const r = Math.floor(i / C),
      c = i % C;
    const h = down
      ? c + 1 < C
        ? sides[4 * (r * A + c) + 1]!
        : sides[4 * (r * A + c - 1) + 3]!
      : r + 1 < R
        ? sides[4 * (r * A + c)]!
        : sides[4 * ((r - 1) * A + c) + 2]!;
    return !isAlive(world, h);
  };
  return pieceEdge(C, R, (i) => pieces.pieceOf[i] === piece, cutLink, marks, path);
}

/** A shape not cut out yet of which some came away (Challenge.partCuts). */
export interface PartCut {
  /** Index of the shape. */
  shape: number;
  /** Fraction of its inside cells in pieces that came away, in (0, 1]. */
  fell: number;
  /** Fraction of its inside cells still hanging on the line, in [0, 1]. */
  hangs: number;
}

/**
 * The shapes among `pending` (indices of SHAPES) that have come off the line: a free piece holds a
 * fifth of their inside cells, or less than a quarter are in pieces still hanging. Each is scored by
 * the free piece holding most of its inside cells (-1 and fit 0 if none holds any), with its fit
 * (cutFit of its edge, pieceEdge with the scissors' `how.marks`, with `how.slack` m). A cell is in a
 * piece when its four corners are and at least one of its triangles is whole.
 * @param masks shapeMasks of the sheet's size.
 * @throws RangeError as cutFit on a negative `how.slack`.
 */
export function scoreCutOuts(
  world: PhysicsWorld,
  cloth: Cloth,
  cells: ClothCells,
  pieces: ClothPieces,
  masks: readonly ShapeMask[],
  pending: readonly number[],
  shapes: readonly Shape[] = SHAPES,
  how: { readonly slack?: number; readonly marks?: ArrayLike<number> } = {},
): CutOut[] {
  const { pieceOfCell, hanging } = cellOwners(world, cloth, cells, pieces);
  const out: CutOut[] = [];
  for (const s of pending) {
    const mask = masks[s]!;
    if (mask.inside.length === 0) continue;
    let held = 0;
    const count = new Map<number, number>();
    for (const cell of mask.inside) {
      held += hanging[cell]!;
      const p = pieceOfCell[cell]!;
      if (p >= 0) count.set(p, (count.get(p) ?? 0) + 1);
    }
    let best = -1,
      most = 0;
    for (const [p, k] of count)
      if (k > most) {
        most = k;
        best = p;
      }
    if (held >= mask.inside.length / 4 && most < mask.inside.length / 5) continue;
    if (best < 0) {
      out.push({ shape: s, fit: 0, stars: 0, piece: -1 });
      continue;
    }
    const path = { length: 0 };
    const edge = edgeOf(world, cloth, cells, pieces, best, how.marks ?? [], path);
    const { fit, steady, clean, flaw } = cutFit(shapes[s]!, mask, edge, sheetGrid(cloth.columns).spacing, how.slack, path.length);
    if (shapes[s]?.drop) out.push({ shape: s, fit, stars: 0, piece: best, drop: 'falling', landedAt: Number.NaN });
    else out.push({ shape: s, fit, stars: starsFor(fit), steady, clean, flaw, piece: best });
  }
  return out;
}

/**
 * The challenge on one sheet: which shapes are still to cut out, the ones cut out (in order), and the
 * pieces that have come away. `update` after the cloth's links changed (a tear or a cut).
 */
export class Challenge {
  /** Shapes cut out so far, in order. */
  readonly done: CutOut[] = [];
  /** Pieces of at least 4 points that have come away (hang from no peg). */
  scraps = 0;
  /** The pieces at the last update. */
  pieces: ClothPieces | null = null;
  /**
   * Where the scissors have been on the sheet, m (sheet coordinates at rest, x and y interleaved):
   * points along each stroke at most a quarter of a link spacing apart (ScissorsStroke's `marks`,
   * cutTrace's). A piece's edge is taken from them where they run along it (pieceEdge), finer than the
   * grid. Cut them back with the sheet on an undo.
   */
  readonly marks: number[] = [];
  private readonly masks: ShapeMask[];
  private slack = 0;
  private seenVersion = -1;
  /** Per falling drop (an index of `done`), the cloth's point indices in its piece. */
  private readonly falling = new Map<number, number[]>();

  /** @param shapes the targets (default: the three shapes). */
  constructor(
    private readonly world: PhysicsWorld,
    readonly cloth: Cloth,
    private readonly cells: ClothCells,
    readonly shapes: readonly Shape[] = SHAPES,
  ) {
    this.masks = shapeMasks(cloth.columns, shapes);
  }

  /**
   * Sets how far a cut may stray from the lines at no cost, m (cutFit's `slack`: a finger's), for the
   * shapes scored from now on. @throws RangeError if `slack` is negative or not finite.
   */
  setSlack(slack: number): void {
    if (!(slack >= 0) || !Number.isFinite(slack))
      throw new RangeError(`Challenge.setSlack: slack must be a finite number >= 0, got ${slack}`);
    this.slack = slack;
  }

  /**
   * Indices of the shapes not cut out yet that are torn inside: more than SPOILT_SHARE of their cells
   * a link spacing or more within the line have a triangle broken (a pull of the hand tore through
   * them, or a stroke cut across them). Such a shape can no longer come away with a clean edge.
   */
  spoilt(): number[] {
    const { columns, spacing } = sheetGrid(this.cloth.columns);
    return this.pending().filter((s) => {
      const mask = this.masks[s]!;
      let deep = 0,
        broken = 0;
      for (const cell of mask.inside) {
        const c = cell % (columns - 1),
          r = Math.floor(cell / (columns - 1));
        const x = (c + 0.5) * spacing,
          y = (r + 0.5) * spacing;
        let near = Infinity;
        for (let k = 0; k < mask.line.length; k += 2) near = Math.min(near, (mask.line[k]! - x) ** 2 + (mask.line[k + 1]! - y) ** 2);
        if (near < spacing * spacing) continue;
        deep++;
        if (this.cells.triangles(this.world, cell) !== 3) broken++;
      }
      return deep > 0 && broken > SPOILT_SHARE * deep;
    });
  }

  /** Indices of the shapes not cut out yet. */
  pending(): number[] {
    return this.shapes.map((_, i) => i).filter((i) => !this.done.some((d) => d.shape === i));
  }

  /** Total stars of the shapes cut out. */
  stars(): number {
    return this.done.reduce((sum, d) => sum + d.stars, 0);
  }

  /** Whether every shape is cut out (and every dropped piece has landed). */
  finished(): boolean {
    return this.done.length === this.shapes.length && this.done.every((d) => d.drop !== 'falling');
  }

  /**
   * Follows the dropped pieces still falling: one has landed when its lowest point is on the lawn and
   * none of its points moves faster than 0.3 m/s. Its stars are then for how near the middle of the
   * basket its centre lies: 3 within a sixth of the basket's width, 2 within a third, 1 inside it,
   * none outside ('out'). Call it every step. @returns the drops that landed at this step.
   */
  watch(): CutOut[] {
    const landed: CutOut[] = [];
    if (this.falling.size === 0) return landed;
    const P = this.world.components.Position,
      V = this.world.components.Velocity;
    for (const [k, points] of this.falling) {
      const d = this.done[k];
      if (d?.drop !== 'falling') {
        this.falling.delete(k);
        continue;
      }
      let low = Infinity,
        fast = 0,
        x = 0;
      for (const i of points) {
        const e = slotOf(this.cloth.points[i]!);
        low = Math.min(low, P.y[e]!);
        fast = Math.max(fast, Math.hypot(V.x[e]!, V.y[e]!));
        x += P.x[e]! / points.length;
      }
      if (low > 0.02 || fast > 0.3) continue;
      const basket = this.shapes[d.shape]!.drop!;
      const off = Math.abs(x - basket.x) / basket.width;
      d.stars = off <= 1 / 6 ? 3 : off <= 1 / 3 ? 2 : off <= 1 / 2 ? 1 : 0;
      d.drop = d.stars > 0 ? 'in' : 'out';
      d.landedAt = x;
      this.falling.delete(k);
      landed.push(d);
    }
    return landed;
  }

  /**
   * Regroups the pieces if the cloth's links changed since the last call (cheap otherwise) and scores
   * the shapes that came away. @returns the shapes cut out by this change (usually none).
   */
  update(): CutOut[] {
    const version = this.world.cloth.version;
    if (version === this.seenVersion) return [];
    this.seenVersion = version;
    const pieces = findPieces(this.world, this.cloth);
    this.pieces = pieces;
    this.scraps = pieces.size.filter((n, k) => n >= 4 && !pieces.held[k]).length;
    const fresh = scoreCutOuts(this.world, this.cloth, this.cells, pieces, this.masks, this.pending(), this.shapes, {
      slack: this.slack,
      marks: this.marks,
    });
    for (const d of fresh) {
      this.done.push(d);
      if (d.drop === 'falling') {
        const points: number[] = [];
        for (let i = 0; i < this.cloth.points.length; i++) if (pieces.pieceOf[i] === d.piece) points.push(i);
        this.falling.set(this.done.length - 1, points);
      }
    }
    return fresh;
  }

  /**
   * Makes the next `update` group the pieces again (after the world was restored to an earlier
   * state), and forgets the drops no longer in `done`.
   */
  invalidate(): void {
    this.seenVersion = -1;
    for (const k of [...this.falling.keys()]) if (k >= this.done.length) this.falling.delete(k);
  }

  /**
   * The shapes still to cut out of which some came away in the pieces of the last update (a cut off
   * the line: not enough came away together for scoreCutOuts to count it), with how much of each fell
   * and how much still hangs, for telling the player what happened. Empty before the first update.
   */
  partCuts(): PartCut[] {
    const pieces = this.pieces;
    if (!pieces) return [];
    const { pieceOfCell, hanging } = cellOwners(this.world, this.cloth, this.cells, pieces);
    const out: PartCut[] = [];
    for (const s of this.pending()) {
      const inside = this.masks[s]!.inside;
      if (inside.length === 0) continue;
      let fell = 0,
        hangs = 0;
      for (const cell of inside) {
        if (pieceOfCell[cell]! >= 0) fell++;
        hangs += hanging[cell]!;
      }
      if (fell > 0) out.push({ shape: s, fell: fell / inside.length, hangs: hangs / inside.length });
    }
    return out;
  }

  /** Where piece `piece` of the last update is, m: the mean of its points. */
  centre(piece: number, out: [number, number]): [number, number] {
    const P = this.world.components.Position,
      p = this.pieces;
    let x = 0,
      y = 0,
      n = 0;
    if (p)
      for (let i = 0; i < this.cloth.points.length; i++) {
        if (p.pieceOf[i] !== piece) continue;
        const e = slotOf(this.cloth.points[i]!);
        x += P.x[e]!;
        y += P.y[e]!;
        n++;
      }
    out[0] = n > 0 ? x / n : 0;
    out[1] = n > 0 ? y / n : 0;
    return out;
  }
}
