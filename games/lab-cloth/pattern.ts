/**
 * The lab's challenge, headless: shapes printed on the sheet with dashed cutting lines (a circle, a
 * star and a heart), to be cut out. A shape counts as cut out once a piece that came away holds a
 * fifth of its cells (the cells of the sheet at rest whose centres lie inside its line), or less than
 * a quarter of them still hang on the line: it is scored by the piece that came away with most.
 *
 * Its fit says how close to the line the cut ran: a cut removes the cells it runs through, so a cut
 * right on the line takes the shape's edge cells with it. The shape's core (its cells whose centres
 * lie at least one link spacing inside the line) should all be in the piece, and the piece should
 * hold no cloth outside the line: each cell of the piece whose centre lies outside costs from 0 (up
 * to 0.4 spacing out) to a whole cell (0.9 spacing out and beyond), so cloth cut away with the shape
 * counts against it by its area: fit = max(0, 1 - (core cells missing + cells outside) / inside
 * cells), 1 for a cut along the line. Measured on the still sheet at 32 points across: 0.95-1 for
 * the circle or the star cut 4 cm out of the line, 0.85 (2 stars) for the star cut along the pentagon
 * through its points (a hole 1.8 times the star; the fit before outside cloth counted by area gave
 * it 0.97), 0 for the heart cut 0.4 m out or a 1.8 m square round a shape.
 */
import { type Cloth, type PhysicsWorld, slotOf } from '@bitphysics/physics';
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

/** Distance from point (x, y) to the closed polygon `poly`'s outline, m. */
function outlineDistance(poly: readonly number[], x: number, y: number): number {
  let best = Infinity;
  const n = poly.length / 2;
  for (let i = 0, j = n - 1; i < n; j = i++) {
    const ax = poly[2 * j]!,
      ay = poly[2 * j + 1]!,
      dx = poly[2 * i]! - ax,
      dy = poly[2 * i + 1]! - ay,
      l2 = dx * dx + dy * dy;
    const t = l2 > 0 ? Math.max(0, Math.min(1, ((x - ax) * dx + (y - ay) * dy) / l2)) : 0;
    best = Math.min(best, Math.hypot(x - ax - t * dx, y - ay - t * dy));
  }
  return best;
}

/** A shape's cells on a sheet of one size (row-major cell indices; see the header). */
export interface ShapeMask {
  /** Cells whose centres lie inside the line. */
  readonly inside: readonly number[];
  /** Cells whose centres lie at least one link spacing inside the line. */
  readonly core: readonly number[];
  /** Per cell, 1 where its centre lies inside the line or at most one spacing outside it. */
  readonly allowed: Uint8Array;
  /**
   * Per cell, what it costs the fit when it comes away with the shape, in cells (0 to 1): 0 inside the
   * line or up to `EXCESS_FREE` spacings outside it, rising linearly to 1 at `EXCESS_FULL` and beyond.
   */
  readonly excess: Float32Array;
}

/**
 * A cell that comes away with a shape costs the fit nothing while its centre lies up to this many
 * link spacings outside the line (a cut on the line runs through those cells), rising linearly to a
 * whole cell at `EXCESS_FULL` spacings out and beyond.
 */
export const EXCESS_FREE = 0.4;
/** See `EXCESS_FREE`: the distance outside the line, in link spacings, from which a cell costs a whole cell. */
const EXCESS_FULL = 0.9;
/**
 * Per shape of `shapes`, its cells on a sheet of `size` points across, at rest. `slack` (m, >= 0)
 * widens the band along the line that a cut may stray into: cells up to the larger of `slack` and
 * EXCESS_FREE spacings outside cost nothing (then up to a whole cell half a spacing further out), and
 * the core starts the larger of `slack` and a spacing inside. The lab gives a finger more (main.ts).
 * @throws RangeError if `slack` is negative or not finite.
 */
export function shapeMasks(size: number, shapes: readonly Shape[] = SHAPES, slack = 0): ShapeMask[] {
  if (!(slack >= 0) || !Number.isFinite(slack)) throw new RangeError(`shapeMasks: slack must be a finite number >= 0, got ${slack}`);
  const { columns, rows, spacing } = sheetGrid(size);
  const free = Math.max(EXCESS_FREE * spacing, slack),
    full = free + (EXCESS_FULL - EXCESS_FREE) * spacing,
    coreDepth = Math.max(spacing, slack);
  return shapes.map((s) => {
    const inside: number[] = [],
      core: number[] = [];
    const allowed = new Uint8Array((columns - 1) * (rows - 1));
    const excess = new Float32Array((columns - 1) * (rows - 1));
    for (let r = 0; r + 1 < rows; r++)
      for (let c = 0; c + 1 < columns; c++) {
        const x = (c + 0.5) * spacing,
          y = (r + 0.5) * spacing,
          cell = r * (columns - 1) + c;
        const d = outlineDistance(s.outline, x, y);
        if (insidePolygon(s.outline, x, y)) {
          inside.push(cell);
          allowed[cell] = 1;
          if (d >= coreDepth) core.push(cell);
        } else {
          if (d <= spacing) allowed[cell] = 1;
          excess[cell] = Math.max(0, Math.min(1, (d - free) / (full - free)));
        }
      }
    return { inside, core, allowed, excess };
  });
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

/** Stars for a fit in [0, 1]: 3 from 0.9, 2 from 0.6, 1 from 0.3, else none. */
export function starsFor(fit: number): number {
  return fit >= 0.9 ? 3 : fit >= 0.6 ? 2 : fit >= 0.3 ? 1 : 0;
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
 * the free piece holding most of its
 * inside cells (-1 and fit 0 if none holds any), with its fit (see the header). A cell is in a piece
 * when its four corners are and at least one of its triangles is whole.
 * @param masks shapeMasks of the sheet's size.
 */
export function scoreCutOuts(
  world: PhysicsWorld,
  cloth: Cloth,
  cells: ClothCells,
  pieces: ClothPieces,
  masks: readonly ShapeMask[],
  pending: readonly number[],
  shapes: readonly Shape[] = SHAPES,
): CutOut[] {
  const { pieceOfCell, hanging } = cellOwners(world, cloth, cells, pieces);
  const n = pieceOfCell.length;
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
    let missing = 0,
      beyond = 0;
    for (const cell of mask.core) if (pieceOfCell[cell] !== best) missing++;
    for (let cell = 0; cell < n; cell++) if (pieceOfCell[cell] === best) beyond += mask.excess[cell]!;
    const fit = Math.max(0, 1 - (missing + beyond) / mask.inside.length);
    if (shapes[s]?.drop) out.push({ shape: s, fit, stars: 0, piece: best, drop: 'falling', landedAt: Number.NaN });
    else out.push({ shape: s, fit, stars: starsFor(fit), piece: best });
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
  private masks: ShapeMask[];
  private slack = 0;
  private seenVersion = -1;
  /** Per falling drop (an index of `done`), the cloth's point indices in its piece. */
  private readonly falling = new Map<number, number[]>();

  /** @param shapes the targets (default: the three shapes). */
  constructor(
    private readonly world: PhysicsWorld,
    private readonly cloth: Cloth,
    private readonly cells: ClothCells,
    readonly shapes: readonly Shape[] = SHAPES,
  ) {
    this.masks = shapeMasks(cloth.columns, shapes);
  }

  /**
   * Sets the band along the lines that a cut may stray into, m (shapeMasks' `slack`), for the shapes
   * scored from now on. @throws RangeError as shapeMasks.
   */
  setSlack(slack: number): void {
    if (slack === this.slack) return;
    this.masks = shapeMasks(this.cloth.columns, this.shapes, slack);
    this.slack = slack;
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
    const fresh = scoreCutOuts(this.world, this.cloth, this.cells, pieces, this.masks, this.pending(), this.shapes);
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
