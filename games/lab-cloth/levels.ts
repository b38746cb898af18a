/**
 * The cloth lab's levels, headless: one sheet each, each asking for something else.
 *
 * 1. Three shapes (a calm day): cut out the circle, the star and the heart along their dashed lines.
 * 2. The window (a breezy day): cut out the four panes of a window, leaving its cross: four straight
 *    sided cuts side by side, the bars between them over two cells wide. The frame and its cross are
 *    sewn (their links never tear), so they stand when the panes are out. As on the first sheet, the
 *    breeze drops while the scissors are down.
 * 3. The peg bag (a breezy day): the sheet is shorter, and a heavy peg bag hangs from its hem on a
 *    ribbon; cut the ribbon so that the bag drops into the basket on the lawn, which stands to the
 *    right of it: wait for the breeze, or blow a gust, to swing it over the basket.
 * 4. The perforation (a windy day): no scissors. A dotted line runs across the sheet, its links
 *    weaker than the rest (they tear at a sixth of the strain); tear the strip below it off along the
 *    line, pulling with the hand or blowing gusts.
 *
 * Each level's targets are `Shape`s (pattern.ts), scored by the same `Challenge`: a piece that comes
 * away with the shape's cells, its fit, its stars; the peg bag's stars are for where it lands.
 */
import { type Cloth, ClothLinkKind, handleOf, type PhysicsWorld, pinClothPoint, query, removeJoint, slotOf } from '@bitphysics/physics';
import { SHAPES, type Shape } from './pattern';
import { SHEET_WIDTH, SHEET_X, SHEETS, sheetGrid } from './scene';

/** A level: its sheet's breeze, what it asks, and how its sheet differs from the plain one. */
export interface Level {
  /** Its name ('The window'). */
  readonly title: string;
  /** The day's name, for the breeze ('a breezy day'). */
  readonly day: string;
  /** Mean wind and gusts, m/s (applyWind). */
  readonly wind: number;
  readonly gusts: number;
  /** What the status line asks, after the level's name ('cut out the four panes ...'). */
  readonly ask: string;
  /** Whether the scissors may be used (the perforation is torn by hand). */
  readonly scissors: boolean;
  /**
   * Whether the breeze drops while the scissors are down, so the sheet hangs still for a careful cut
   * (the shapes and the window; the peg bag's swing is its game).
   */
  readonly calm: boolean;
  /** Its targets on a sheet of `size` points across (sheet coordinates, see Shape). */
  shapes(size: number): Shape[];
  /** Changes a new sheet of `size` points across before it settles (cuts, weights, weak links). */
  prepare?(world: PhysicsWorld, cloth: Cloth, size: number): void;
  /** A line printed across the sheet, m (sheet coordinates, x and y interleaved): the perforation. */
  readonly perforation?: readonly number[];
}

/** An axis-aligned rectangle as a closed outline, m (x0 < x1, y0 < y1, y down). */
function rect(x0: number, y0: number, x1: number, y1: number): number[] {
  return [x0, y0, x1, y0, x1, y1, x0, y1];
}

/** The window: four panes 0.75 x 0.62 m round (2, 1.5) m, the bars between them 0.3 m wide (over two cells). */
export const WINDOW = Object.freeze({ x: 2, y: 1.5, pane: [0.75, 0.62] as const, bar: 0.3 });

/** The window's frame round and between the panes, m wide each side of a pane's line (half the bars). */
export const WINDOW_FRAME = WINDOW.bar / 2;

/**
 * Sews the window's frame: the links with both ends (at rest) in the frame, the band WINDOW_FRAME
 * wide round each pane, never tear, so the cross and the frame stand when the panes are out and the
 * sheet strains round the holes (the scissors still cut them).
 */
function prepareWindow(world: PhysicsWorld, cloth: Cloth, size: number): void {
  const { columns: C, spacing } = sheetGrid(size);
  const panes = windowPanes();
  const inFrame = (x: number, y: number): boolean => {
    let near = false;
    for (const p of panes) {
      const o = p.outline;
      const x0 = o[0]!,
        y0 = o[1]!,
        x1 = o[4]!,
        y1 = o[5]!;
      if (x > x0 && x < x1 && y > y0 && y < y1) return false;
      if (x > x0 - WINDOW_FRAME - 1e-9 && x < x1 + WINDOW_FRAME + 1e-9 && y > y0 - WINDOW_FRAME - 1e-9 && y < y1 + WINDOW_FRAME + 1e-9)
        near = true;
    }
    return near;
  };
  const index = new Map<number, number>();
  for (let i = 0; i < cloth.points.length; i++) index.set(slotOf(cloth.points[i]!), i);
  const L = world.components.ClothLink;
  for (const e of query(world, [L])) {
    const a = index.get(L.a[e]!)!,
      b = index.get(L.b[e]!)!;
    if (inFrame((a % C) * spacing, Math.floor(a / C) * spacing) && inFrame((b % C) * spacing, Math.floor(b / C) * spacing))
      L.tearStretch[e] = Infinity;
  }
  world.cloth.version++;
}

function windowPanes(): Shape[] {
  const [w, h] = WINDOW.pane,
    b = WINDOW.bar / 2;
  const names = ['top-left pane', 'top-right pane', 'bottom-left pane', 'bottom-right pane'];
  const out: Shape[] = [];
  for (let k = 0; k < 4; k++) {
    const right = k % 2 === 1,
      bottom = k >= 2;
    const x0 = right ? WINDOW.x + b : WINDOW.x - b - w,
      y0 = bottom ? WINDOW.y + b : WINDOW.y - b - h;
    out.push({ name: names[k]!, outline: rect(x0, y0, x0 + w, y0 + h), color: 0x3d7fc4, style: 'pane' });
  }
  return out;
}

/**
 * The peg bag's sheet, in grid cells of a sheet of `size` points across: the rows kept (the sheet
 * ends at row `hem`), the ribbon's columns [ribbon0, ribbon1] from the hem down to row `bagTop`, and
 * the bag's columns [bag0, bag1] from `bagTop` to the last row. Its mass and the basket: see PEG_BAG.
 */
export function pegBagCells(size: number): { hem: number; bagTop: number; ribbon0: number; ribbon1: number; bag0: number; bag1: number } {
  const { columns, rows, spacing } = sheetGrid(size);
  const mid = (columns - 1) / 2;
  const cells = (m: number) => Math.max(1, Math.round(m / spacing));
  const bagHalf = cells(0.45),
    ribbonHalf = Math.max(1, cells(0.2));
  const bagTop = rows - 1 - cells(0.6);
  return {
    hem: bagTop - cells(0.75),
    bagTop,
    ribbon0: Math.floor(mid) - ribbonHalf + 1,
    ribbon1: Math.ceil(mid) + ribbonHalf - 1,
    bag0: Math.floor(mid) - bagHalf + 1,
    bag1: Math.ceil(mid) + bagHalf - 1,
  };
}

/** The peg bag: its mass, kg (a bag of wooden pegs), and the basket on the lawn: centre x and width, m. */
export const PEG_BAG = Object.freeze({ mass: 0.3, basket: { x: SHEET_X + SHEET_WIDTH / 2 + 0.6, width: 1 } });

function pegBagShape(size: number): Shape[] {
  const { spacing } = sheetGrid(size);
  const c = pegBagCells(size);
  const s = spacing,
    bottom = sheetGrid(size).height;
  // The bag and the ribbon above it, as one outline: a cut anywhere across the ribbon frees it.
  const outline = [
    c.ribbon0 * s,
    c.hem * s,
    c.ribbon1 * s,
    c.hem * s,
    c.ribbon1 * s,
    c.bagTop * s,
    c.bag1 * s,
    c.bagTop * s,
    c.bag1 * s,
    bottom,
    c.bag0 * s,
    bottom,
    c.bag0 * s,
    c.bagTop * s,
    c.ribbon0 * s,
    c.bagTop * s,
  ];
  return [{ name: 'peg bag', outline, color: 0x9c6b3c, drop: PEG_BAG.basket, style: 'bag' }];
}

/**
 * Cuts the peg bag's sheet out of the plain one: every link of the points below the hem that are
 * neither ribbon nor bag goes (those points are pinned where they are, out of the way and never
 * drawn: no cell of theirs is whole), the bag's points share PEG_BAG.mass between them, and the
 * ribbon's and the bag's links never tear and are three times stiffer (only the scissors free it).
 */
function preparePegBag(world: PhysicsWorld, cloth: Cloth, size: number): void {
  const { columns: C, rows: R } = cloth;
  const k = pegBagCells(size);
  const kind = new Int8Array(C * R); // 0 sheet, 1 gone, 2 ribbon, 3 bag
  for (let r = k.hem + 1; r < R; r++)
    for (let c = 0; c < C; c++) {
      const ribbon = r <= k.bagTop && c >= k.ribbon0 && c <= k.ribbon1,
        bag = r >= k.bagTop && c >= k.bag0 && c <= k.bag1;
      kind[r * C + c] = bag ? 3 : ribbon ? 2 : 1;
    }
  for (let c = k.ribbon0; c <= k.ribbon1; c++) kind[k.hem * C + c] = 2;
  const index = new Map<number, number>();
  for (let i = 0; i < C * R; i++) index.set(slotOf(cloth.points[i]!), i);
  const L = world.components.ClothLink;
  const doomed: number[] = [];
  for (const e of query(world, [L])) {
    const a = kind[index.get(L.a[e]!)!]!,
      b = kind[index.get(L.b[e]!)!]!;
    if (a === 1 || b === 1) doomed.push(handleOf(world, e));
    else if (a >= 2 && b >= 2) {
      L.tearStretch[e] = Infinity;
      L.compliance[e] = L.compliance[e]! / 3;
    }
  }
  for (const h of doomed) removeJoint(world, h);
  const P = world.components.Position,
    M = world.components.Mass;
  let bagPoints = 0;
  for (let i = 0; i < C * R; i++) if (kind[i] === 3) bagPoints++;
  for (let i = 0; i < C * R; i++) {
    const e = slotOf(cloth.points[i]!);
    if (kind[i] === 1) pinClothPoint(world, cloth.points[i]!, [P.x[e]!, P.y[e]!]);
    else if (kind[i] === 3) {
      M.value[e] = PEG_BAG.mass / bagPoints;
      M.inv[e] = 1 / M.value[e]!;
    }
  }
  world.cloth.version++;
}

/**
 * Strain past which the perforation's links tear (the sheet's: 0.45 at the lab's default). Measured on the
 * windy day: left alone for 15 s the wind tears 7 of its links; a gust alone 6 in 5 s; the hand pulling
 * the strip 1.7 m down over 1.3 s tears it off along the line (0.09: the pull tore round the hand instead).
 */
export const PERFORATION_TEAR = 0.07;

/** The perforation: a gentle wave across the lower part of the sheet, a little past both edges (sheet coordinates). */
const PERFORATION: readonly number[] = (() => {
  const out: number[] = [];
  for (let i = 0; i <= 40; i++) {
    const x = -0.1 + (i / 40) * (SHEET_WIDTH + 0.2);
    out.push(x, 2.05 + 0.12 * Math.sin((2 * Math.PI * x) / 2.6));
  }
  return out;
})();

/** The strip below the perforation, to the sheet's bottom edge and a little past it. */
function stripShape(size: number): Shape[] {
  const bottom = sheetGrid(size).height + 0.1;
  const outline = [...PERFORATION, SHEET_WIDTH + 0.1, bottom, -0.1, bottom];
  return [{ name: 'strip', outline, color: 0x7d8a99, style: 'tear' }];
}

/** Whether the segments (ax, ay)-(bx, by) and (cx, cy)-(dx, dy) cross. */
function cross(ax: number, ay: number, bx: number, by: number, cx: number, cy: number, dx: number, dy: number): boolean {
  const d1 = (dx - cx) * (ay - cy) - (dy - cy) * (ax - cx),
    d2 = (dx - cx) * (by - cy) - (dy - cy) * (bx - cx),
    d3 = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax),
    d4 = (bx - ax) * (dy - ay) - (by - ay) * (dx - ax);
  return d1 * d2 < 0 && d3 * d4 < 0;
}

/**
 * Weakens the links that cross the perforation (at rest, in sheet coordinates): structural and shear
 * links tear at PERFORATION_TEAR, bending links go with the links they span (ClothCells.loosen).
 */
function preparePerforation(world: PhysicsWorld, cloth: Cloth, size: number): void {
  const { columns: C, spacing } = sheetGrid(size);
  const index = new Map<number, number>();
  for (let i = 0; i < cloth.points.length; i++) index.set(slotOf(cloth.points[i]!), i);
  const at = (slot: number): [number, number] => {
    const i = index.get(slot)!;
    return [(i % C) * spacing, Math.floor(i / C) * spacing];
  };
  const L = world.components.ClothLink;
  for (const e of query(world, [L])) {
    if (L.kind[e] === ClothLinkKind.Bending) continue;
    const [ax, ay] = at(L.a[e]!),
      [bx, by] = at(L.b[e]!);
    for (let k = 2; k < PERFORATION.length; k += 2)
      if (cross(ax, ay, bx, by, PERFORATION[k - 2]!, PERFORATION[k - 1]!, PERFORATION[k]!, PERFORATION[k + 1]!)) {
        L.tearStretch[e] = PERFORATION_TEAR;
        break;
      }
  }
  world.cloth.version++;
}

/** The lab's levels, in order (see the header). */
export const LEVELS: readonly Level[] = Object.freeze([
  {
    title: 'Three shapes',
    day: 'a calm day',
    wind: SHEETS[0]!.wind,
    gusts: SHEETS[0]!.gusts,
    ask: 'cut out the circle, the star and the heart along their dashed lines.',
    scissors: true,
    calm: true,
    shapes: () => [...SHAPES],
  },
  {
    title: 'The window',
    day: 'a breezy day',
    wind: SHEETS[1]!.wind,
    gusts: SHEETS[1]!.gusts,
    ask: "cut out the four panes; leave the window's cross standing.",
    scissors: true,
    calm: true,
    shapes: () => windowPanes(),
    prepare: prepareWindow,
  },
  {
    title: 'The peg bag',
    day: 'a breezy day',
    wind: SHEETS[1]!.wind,
    gusts: SHEETS[1]!.gusts,
    ask: 'cut the ribbon to drop the bag into the basket. Gust swings it.',
    scissors: true,
    calm: false,
    shapes: (size) => pegBagShape(size),
    prepare: preparePegBag,
  },
  {
    title: 'The perforation',
    day: 'a windy day',
    wind: SHEETS[2]!.wind,
    gusts: SHEETS[2]!.gusts,
    ask: 'no scissors: tear the strip off along the dots, with the hand or Gust.',
    scissors: false,
    calm: false,
    shapes: (size) => stripShape(size),
    prepare: preparePerforation,
    perforation: PERFORATION,
  },
]);
