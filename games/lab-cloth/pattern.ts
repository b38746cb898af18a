/**
 * The lab's challenge, headless: shapes printed on the sheet with dashed cutting lines (a circle, a
 * star and a heart), to be cut out. A shape counts as cut out once a piece that has come away holds
 * at least half of it; its fit is the overlap of that piece with the shape, as cells of the sheet at
 * rest: |shape and piece| / |shape or piece| (the Jaccard index), 1 for a clean cut along the line.
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

/** Per shape, the cells (row-major indices) of a sheet of `size` points across whose centres at rest lie inside it. */
export function shapeCells(size: number): number[][] {
  const { columns, rows, spacing } = sheetGrid(size);
  return SHAPES.map((s) => {
    const cells: number[] = [];
    for (let r = 0; r + 1 < rows; r++)
      for (let c = 0; c + 1 < columns; c++)
        if (insidePolygon(s.outline, (c + 0.5) * spacing, (r + 0.5) * spacing)) cells.push(r * (columns - 1) + c);
    return cells;
  });
}

/** A shape cut out. */
export interface CutOut {
  /** Index in SHAPES. */
  shape: number;
  /** The fit, in [0, 1] (see the header). */
  fit: number;
  /** Stars for the fit: 3 from 0.8, 2 from 0.6, else 1. */
  stars: number;
  /** The piece it came away in (an index of that moment's ClothPieces). */
  piece: number;
}

/** Stars for a fit in [0, 1]: 3 from 0.8, 2 from 0.6, else 1. */
export function starsFor(fit: number): number {
  return fit >= 0.8 ? 3 : fit >= 0.6 ? 2 : 1;
}

/**
 * The shapes among `pending` (indices of SHAPES) that pieces which came away now hold: for each, the
 * free piece holding most of its cells, if at least half. A cell is in a piece when its four corners
 * are and at least one of its triangles is whole.
 * @param masks shapeCells of the sheet's size.
 */
export function scoreCutOuts(
  world: PhysicsWorld,
  cloth: Cloth,
  cells: ClothCells,
  pieces: ClothPieces,
  masks: readonly number[][],
  pending: readonly number[],
): CutOut[] {
  const C = cloth.columns;
  const cellPiece = (cell: number): number => {
    const r = Math.floor(cell / cells.across),
      c = cell % cells.across;
    const i = r * C + c;
    const p = pieces.pieceOf[i]!;
    if (pieces.pieceOf[i + 1] !== p || pieces.pieceOf[i + C] !== p || pieces.pieceOf[i + C + 1] !== p) return -1;
    return cells.triangles(world, cell) ? p : -1;
  };
  // Cells of each free piece.
  const freeCells = new Map<number, number>();
  const n = cells.across * cells.down;
  const pieceOfCell = new Int32Array(n);
  for (let cell = 0; cell < n; cell++) {
    const p = cellPiece(cell);
    pieceOfCell[cell] = p >= 0 && !pieces.held[p] ? p : -1;
    if (pieceOfCell[cell]! >= 0) freeCells.set(p, (freeCells.get(p) ?? 0) + 1);
  }
  const out: CutOut[] = [];
  for (const s of pending) {
    const mask = masks[s]!;
    if (mask.length === 0) continue;
    const count = new Map<number, number>();
    for (const cell of mask) {
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
    if (best < 0 || most < mask.length / 2) continue;
    const fit = most / (mask.length + freeCells.get(best)! - most);
    out.push({ shape: s, fit, stars: starsFor(fit), piece: best });
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
  private readonly masks: number[][];
  private seenVersion = -1;

  constructor(
    private readonly world: PhysicsWorld,
    private readonly cloth: Cloth,
    private readonly cells: ClothCells,
  ) {
    this.masks = shapeCells(cloth.columns);
  }

  /** Indices of the shapes not cut out yet. */
  pending(): number[] {
    return SHAPES.map((_, i) => i).filter((i) => !this.done.some((d) => d.shape === i));
  }

  /** Total stars of the shapes cut out. */
  stars(): number {
    return this.done.reduce((sum, d) => sum + d.stars, 0);
  }

  /** Whether every shape is cut out. */
  finished(): boolean {
    return this.done.length === SHAPES.length;
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
    const fresh = scoreCutOuts(this.world, this.cloth, this.cells, pieces, this.masks, this.pending());
    this.done.push(...fresh);
    return fresh;
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
