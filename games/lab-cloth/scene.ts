/**
 * The cloth lab's world, headless (no DOM, no Pixi), shared by the page and its tests: a sheet pegged
 * to a washing line in a yard, in a breeze.
 *
 * The sheet is createCloth's grid of point masses with compliant structural links (it stretches
 * visibly under a pull and springs back), soft shear links (it sways and leans in the wind) and
 * bending links. Its top row is held by pegs: hard pins (pinClothPoint) at a few points along the
 * line, set a little closer together than the cloth between them, so the hem hangs in shallow swags.
 * The two top rows are the hem: their links are stiffer and never tear, so a gust cannot blow the
 * sheet off the line; the rest tears where a structural link is stretched past the tear strain (the
 * soft shear and bending links go with the links they lie over: cells.ts ClothCells.loosen). The yard
 * is the world's boundary box: the lawn, a wall on either side and a high ceiling.
 *
 * The air: linear drag on every point against the world's wind (setWind), a breeze that swings both
 * ways (a small mean, a slow gust cycle and turbulence). A point's terminal speed in still air is
 * m g / c (CLOTH_MASS g / DRAG for the whole sheet, about 2.5 m/s), so torn scraps flutter down in
 * about a second, and the wind's push on the sheet is c u: at 2.5 m/s about the sheet's weight, so it
 * leans about 45 degrees.
 */
import {
  type Cloth,
  ClothLinkKind,
  createCloth,
  createPhysicsWorld,
  type PhysicsWorld,
  pinClothPoint,
  query,
  setBoundary,
  setWind,
  slotOf,
  step,
} from '@bitphysics/physics';

/** Width of the sheet at rest, m. */
export const SHEET_WIDTH = 4;
/** Height of the washing line above the ground, m. */
export const LINE_Y = 4.9;
/** Left end of the sheet at rest, m (the sheet spans [SHEET_X, SHEET_X + SHEET_WIDTH]). */
export const SHEET_X = 0;
/** Total mass of the sheet, kg (a light cotton sheet). */
export const CLOTH_MASS = 1;
/** Total air drag of the sheet, N s/m, shared by its points (terminal fall speed CLOTH_MASS g / DRAG). */
export const DRAG = 4;
/**
 * Compliance of the sheet's structural links for a sheet of 32 points across, m/N (stiffness 80 N/m a
 * link, 0.13 m long): the sheet's own weight stretches its upper links a few percent, a hand's pull of
 * 10-20 N stretches the links near it 15-35%. Scaled with the link length for other sizes (a finer sheet
 * has more, shorter links in series: the same fabric).
 */
export const COMPLIANCE = 0.0125;
/**
 * Shear links' compliance over the structural links': the diagonals hardly resist shear (fabric
 * shears easily), so the sheet leans in the wind like a curtain and a scrap on the lawn slumps into a
 * low heap; without them a scrap would lie flat as a line, with stiff ones it stands up like a plate.
 */
export const SHEAR = 200;
/** Bending links' compliance over the structural links'. */
export const BEND = 4;
/**
 * Friction of the lawn and the walls (the boundary box's, position-based): a scrap on the lawn stays
 * about where it fell in the breeze, which gusts both ways; one the Gust button blows against the brick
 * wall slides down it when the gust drops.
 */
export const FRICTION = 1;
/** The yard: ground (y = 0), walls and ceiling of the world's boundary box, m. */
export const YARD = Object.freeze({ minX: -0.6, minY: 0, maxX: 5.1, maxY: 12 });
/** Pegs along the line (including both ends). */
export const PEGS = 7;
/** How much closer the pegs are than the cloth between them at rest (the hem's swags), in (0, 1]. */
export const GATHER = 0.9;

/**
 * The lab's cloth solver substeps a step. The compliant links converge in fewer than the inextensible
 * links of a stiff sheet need; 12 keep the hanging sheet's extra (solver) stretch small at half the cost of 24.
 */
export const CLOTH_SUBSTEPS = 12;

/** Steps the new sheet hangs before it is shown (1/3 s). */
export const SETTLE = 20;

/** The lab's settings that shape its world. */
export interface ClothSceneParams {
  /** Points across the sheet, integer in [8, 48]; the rows follow from the sheet's 4:3 shape. */
  size: number;
  /** Mean wind to the right, m/s, >= 0. */
  wind: number;
  /** Amplitude of the slow gust cycle and RMS of the turbulence, m/s, >= 0. */
  gusts: number;
  /** Strain past which the sheet's links tear (the hem's never do), > 0. */
  tear: number;
  /** Cloth solver substeps a step, integer >= 1. */
  substeps: number;
}

/** The breezes of the lab's days, calm to windy (the levels' winds: levels.ts). */
export const SHEETS: readonly { readonly name: string; readonly wind: number; readonly gusts: number }[] = Object.freeze([
  { name: 'a calm day', wind: 0.1, gusts: 0.5 },
  { name: 'a breezy day', wind: 0.3, gusts: 1.2 },
  { name: 'a windy day', wind: 0.5, gusts: 2 },
]);

/** The lab's defaults (the first sheet's breeze). */
export const DEFAULTS: Readonly<ClothSceneParams> = Object.freeze({
  size: 32,
  wind: SHEETS[0]!.wind,
  gusts: SHEETS[0]!.gusts,
  tear: 0.45,
  substeps: CLOTH_SUBSTEPS,
});

/** Period of the breeze's slow rise and fall, s. */
export const GUST_PERIOD = 7;

/**
 * Sets the world's wind: a mean `wind` m/s to the right, a slow cycle of amplitude `gusts` (period
 * GUST_PERIOD), turbulence of RMS 0.7 `gusts`, and `extra` m/s more while the player blows a gust.
 */
export function applyWind(world: PhysicsWorld, p: Pick<ClothSceneParams, 'wind' | 'gusts'>, extra = 0): void {
  setWind(world, {
    velocity: [p.wind + extra, 0],
    gust: [p.gusts, 0],
    gustOmega: (2 * Math.PI) / GUST_PERIOD,
    turbulence: { intensity: 0.7 * p.gusts + 0.25 * extra, lengthScale: 1.2, timeScale: 0.7, seed: 3 },
  });
}

/** The sheet's grid for `size` points across: columns, rows and the link spacing (m). */
export function sheetGrid(size: number): { columns: number; rows: number; spacing: number; height: number } {
  const columns = size;
  const spacing = SHEET_WIDTH / (columns - 1);
  const rows = Math.max(4, Math.round(0.75 * (columns - 1)) + 1);
  return { columns, rows, spacing, height: spacing * (rows - 1) };
}

/** What `createClothScene` made. */
export interface ClothScene {
  world: PhysicsWorld;
  cloth: Cloth;
  /** Handles of the pegged points, left to right. */
  pegs: number[];
  /** Where each peg holds its point, m (x, y interleaved). */
  pegAt: number[];
}

/**
 * Builds the lab's world: the sheet (`size` points across, SHEET_WIDTH wide, rows for a 4:3 sheet)
 * hanging from PEGS pegs on the line at LINE_Y, in the YARD, in the breeze; `prepare` (a level's:
 * levels.ts) changes the sheet before it settles.
 * @throws RangeError (from createCloth) on a size outside [2, 512].
 */
export function createClothScene(p: ClothSceneParams, prepare?: (world: PhysicsWorld, cloth: Cloth, size: number) => void): ClothScene {
  const { columns, rows, spacing, height } = sheetGrid(p.size);
  const n = columns * rows;
  const world = createPhysicsWorld({ gravity: [0, -9.81], capacity: 8 * n + 64 });
  const compliance = (COMPLIANCE * spacing) / (SHEET_WIDTH / 31);
  const cloth = createCloth(world, {
    columns,
    rows,
    width: SHEET_WIDTH,
    height,
    origin: [SHEET_X, LINE_Y],
    mass: CLOTH_MASS,
    pinned: 'none',
    compliance,
    shearCompliance: SHEAR * compliance,
    bendCompliance: BEND * compliance,
    tearStretch: p.tear,
    drag: DRAG / n,
  });
  world.cloth.substeps = p.substeps;
  // The hem: links with an end in the two top rows are three times stiffer and never tear. Shear
  // and bending links never tear by strain (they are soft and stretch far); they go with the
  // structural links they lie over (ClothCells.loosen).
  const L = world.components.ClothLink;
  const hem = new Set<number>();
  for (let i = 0; i < 2 * columns; i++) hem.add(slotOf(cloth.points[i]!));
  for (const e of query(world, [L])) {
    if (L.kind[e] !== ClothLinkKind.Structural) L.tearStretch[e] = Infinity;
    if (!hem.has(L.a[e]!) && !hem.has(L.b[e]!)) continue;
    L.tearStretch[e] = Infinity;
    L.compliance[e] = L.compliance[e]! / 3;
  }
  world.cloth.version++;
  const pegs: number[] = [],
    pegAt: number[] = [];
  const mid = SHEET_X + SHEET_WIDTH / 2;
  for (let k = 0; k < PEGS; k++) {
    const c = Math.round((k * (columns - 1)) / (PEGS - 1));
    const h = cloth.points[c]!;
    const x = mid + (SHEET_X + c * spacing - mid) * GATHER;
    pinClothPoint(world, h, [x, LINE_Y]);
    pegs.push(h);
    pegAt.push(x, LINE_Y);
  }
  setBoundary(world, { min: [YARD.minX, YARD.minY], max: [YARD.maxX, YARD.maxY], friction: FRICTION });
  applyWind(world, p);
  prepare?.(world, cloth, p.size);
  // The pegs move the top row's pegged points inward by up to 0.2 m, straining the hem's links near
  // them by up to 100% (they never tear); SETTLE steps let the sheet take up its swags before it is shown.
  for (let i = 0; i < SETTLE; i++) step(world);
  return { world, cloth, pegs, pegAt };
}
