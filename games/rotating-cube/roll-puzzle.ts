/**
 * The room's roll puzzle, as a grid model of the physical game: the cube on a grid of 1 m cells
 * centred on the lit pad, square to the world's axes, in one of its 24 orientations. A pad that wants
 * a face lies in a bed of tiles (every cell within `bed` cells of it, Chebyshev distance): a slide
 * cannot stop inside it (the game moves a push's target out to the bed's edge, `bedSnap`), so the cube
 * crosses it by rolls, and which face lands on top depends on the route. Every move counts: a slide,
 * a roll over an edge, a quarter turn (Q/E). `movePar` finds the fewest moves from where the cube is
 * by a breadth-first search over (cell, orientation); the game's par is its sum over the round's pads.
 * Pure (no DOM, no three.js): shared by the game, its tests and `scene.ts`.
 */

/**
 * An orientation of the cube square to the grid: `o[d]` is the face (an index into scene.ts FACES:
 * +x, -x, +y, -y, +z, -z of the body) that points along world direction d, in the same order (+x, -x,
 * +y (up), -y, +z, -z). A permutation of 0..5 that keeps opposite faces opposite.
 */
export type GridOrientation = readonly number[];

/** World direction indices: up (+y) and down (-y). */
const UP = 2,
  DOWN = 3;
/** The four level directions a cube rolls in: +x, -x, +z, -z (world direction indices). */
export const ROLL_DIRECTIONS: readonly number[] = Object.freeze([0, 1, 4, 5]);
/** Cell offset (x, z) of a step along each world direction index (level ones only; up and down none). */
const STEP: readonly (readonly [number, number])[] = [
  [1, 0],
  [-1, 0],
  [0, 0],
  [0, 0],
  [0, 1],
  [0, -1],
];

/** The orientation with the body's faces along the world's (+x face along +x, and so on). */
export const GRID_IDENTITY: GridOrientation = Object.freeze([0, 1, 2, 3, 4, 5]);

/**
 * The orientation after rolling the cube one cell along level world direction `d` (0 +x, 1 -x, 4 +z,
 * 5 -z): it tips over its bottom edge on that side, so the face on the far side (pointing -d) comes up,
 * the top goes to the side d, that side goes down and the bottom to the far side.
 * @throws RangeError if `d` is not one of ROLL_DIRECTIONS.
 */
export function rollOrientation(o: GridOrientation, d: number): GridOrientation {
  if (!ROLL_DIRECTIONS.includes(d)) throw new RangeError(`rollOrientation: d must be 0, 1, 4 or 5, got ${d}`);
  const n = [...o];
  n[UP] = o[d ^ 1]!;
  n[d] = o[UP]!;
  n[DOWN] = o[d]!;
  n[d ^ 1] = o[DOWN]!;
  return n;
}

/**
 * The orientation after a quarter turn about the vertical: `direction` +1 anticlockwise seen from
 * above (a turn about +y: the face along +x goes to -z, -z to -x, -x to +z, +z to +x), -1 clockwise.
 * @throws RangeError if `direction` is not 1 or -1.
 */
export function turnOrientation(o: GridOrientation, direction: number): GridOrientation {
  if (direction !== 1 && direction !== -1) throw new RangeError(`turnOrientation: direction must be 1 or -1, got ${direction}`);
  const n = [...o];
  // The cycle of world directions a face moves through on an anticlockwise turn: +x, -z, -x, +z.
  const cycle = [0, 5, 1, 4];
  for (let i = 0; i < 4; i++) n[cycle[(i + direction + 4) % 4]!] = o[cycle[i]!]!;
  return n;
}

/**
 * The grid orientation of a body at quaternion (x, y, z, w): for each body axis the world direction
 * it points most nearly along (of a cube square to the grid, exactly).
 */
export function gridOrientationOf(x: number, y: number, z: number, w: number): GridOrientation {
  // The body's axes in the world: the columns of its rotation matrix.
  const cols = [
    [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
    [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
    [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)],
  ];
  const o = [-1, -1, -1, -1, -1, -1];
  const taken = [false, false, false];
  // The most nearly aligned axis claims its world axis first, so a cube tipped near 45 degrees still gives a permutation.
  const order = [0, 1, 2].sort((a, b) => Math.max(...cols[b]!.map(Math.abs)) - Math.max(...cols[a]!.map(Math.abs)));
  for (const i of order) {
    const c = cols[i]!;
    let k = -1;
    for (let j = 0; j < 3; j++) if (!taken[j] && (k < 0 || Math.abs(c[j]!) > Math.abs(c[k]!))) k = j;
    taken[k] = true;
    const positive = c[k]! >= 0;
    o[2 * k + (positive ? 0 : 1)] = 2 * i;
    o[2 * k + (positive ? 1 : 0)] = 2 * i + 1;
  }
  return o;
}

/** A pad's puzzle: where it is, the face it wants and its bed, and which cells the room leaves for the cube. */
export interface RollPuzzle {
  /** The pad's centre (x, z), m. */
  pad: readonly [number, number];
  /** The face it wants on top (index into FACES), or -1 for any face. */
  want: number;
  /**
   * The bed's radius in cells: -1 none (a slide onto the pad counts); 0 the pad's cell alone (a slide
   * may stop on it, but only a roll onto it counts); from 1 the cells around it too, a bed of tiles
   * that a slide cannot stop in (`bedSnap`).
   */
  bed: number;
  /** The largest |x| and |z| of a cell centre the cube can rest on, m (the room's inside half width less the cube's half edge and a margin). */
  reach: number;
}

/** Whether the cell at offset (i, j) from the pad (cells of 1 m) has its centre where the cube fits in the room. */
function cellFits(p: RollPuzzle, i: number, j: number): boolean {
  return Math.abs(p.pad[0] + i) <= p.reach + 1e-9 && Math.abs(p.pad[1] + j) <= p.reach + 1e-9;
}

/** The cells at the bed's edge (Chebyshev distance bed + 1 from the pad) that fit in the room: where a slide stops. */
export function edgeCells(p: RollPuzzle): [number, number][] {
  const r = p.bed + 1,
    cells: [number, number][] = [];
  for (let i = -r; i <= r; i++)
    for (let j = -r; j <= r; j++) if (Math.max(Math.abs(i), Math.abs(j)) === r && cellFits(p, i, j)) cells.push([i, j]);
  return cells;
}

/**
 * Where a slide towards (x, z), m, stops: with a bed of tiles (`bed` >= 1), a target within the bed
 * or its edge row (Chebyshev distance under bed + 1.5 m from the pad) moves to the centre of the
 * nearest edge cell (`edgeCells`), so a slide never stops in the bed and stops square on the grid
 * beside it; any other target, and every target of a pad without tiles, stays. @returns [x, z], m.
 */
export function bedSnap(p: RollPuzzle, x: number, z: number): [number, number] {
  if (p.bed < 1 || Math.max(Math.abs(x - p.pad[0]), Math.abs(z - p.pad[1])) >= p.bed + 1.5) return [x, z];
  let best: [number, number] = [x, z],
    bestD = Infinity;
  for (const [i, j] of edgeCells(p)) {
    const cx = p.pad[0] + i,
      cz = p.pad[1] + j;
    const d = Math.hypot(cx - x, cz - z);
    if (d < bestD) [best, bestD] = [[cx, cz], d];
  }
  return best;
}

/** One move of a route (`moveRoute`): a slide to a cell offset from the pad (null: away), a roll along a level world direction, a quarter turn. */
export type RollMove =
  | { kind: 'slide'; to: readonly [number, number] | null }
  | { kind: 'roll'; direction: number }
  | { kind: 'turn'; direction: 1 | -1 };

/** A state of the search: the cube's cell offset from the pad (null: away) and its orientation. */
interface RollState {
  cell: readonly [number, number] | null;
  o: GridOrientation;
}

/**
 * A shortest route (slides, rolls, quarter turns) that brings the cube to rest on the pad with the
 * face it wants on top, by breadth-first search over (cell, orientation): every cell offset from the
 * pad that fits in the room, and "away" (off the grid, where rolls and turns change only the
 * orientation). A slide goes from anywhere to a cell outside the tiles (at the bed's edge or beyond:
 * `bedSnap` stops one aimed into the tiles at their edge) or away (with no bed, onto the pad too; with
 * one a slide onto the pad does not count); a roll moves one cell (into a cell that does not fit, a
 * wall: not at all); a turn keeps the cell. Every cell of the room is in the search, so a roll
 * towards the pad from a cell beyond the bed's edge counts as the one move it is.
 * @param from the cube's cell offset (i, j) from the pad, or null when away (so is one that does not fit).
 * @param o its orientation.
 * @returns the moves in order (empty when it already rests there with the face), or null if none reaches it.
 */
export function moveRoute(p: RollPuzzle, from: readonly [number, number] | null, o: GridOrientation): RollMove[] | null {
  const r = p.bed + 1;
  // Offsets up to R from the pad hold every cell that fits in the room (|pad + i| <= reach).
  const R = Math.max(r, Math.floor(p.reach + Math.max(Math.abs(p.pad[0]), Math.abs(p.pad[1])) + 1e-9));
  // A state's number: its cell (offsets within R of the pad, or away) times 36, plus its orientation by its top and +x faces.
  const side = 2 * R + 1;
  const key = (s: RollState): number => (s.cell ? (s.cell[0] + R) * side + s.cell[1] + R : side * side) * 36 + s.o[UP]! * 6 + s.o[0]!;
  const done = (s: RollState): boolean => !!s.cell && s.cell[0] === 0 && s.cell[1] === 0 && (p.want < 0 || s.o[UP] === p.want);
  if (from && (Math.max(Math.abs(from[0]), Math.abs(from[1])) > R || !cellFits(p, from[0], from[1]))) from = null;
  const start: RollState = { cell: from, o };
  if (done(start)) return [];
  // Slides stop on any cell outside the tiles (with no bed, r = 0: the pad's too).
  const slideTo: ([number, number] | null)[] = [null];
  for (let i = -R; i <= R; i++)
    for (let j = -R; j <= R; j++) if (Math.max(Math.abs(i), Math.abs(j)) >= r && cellFits(p, i, j)) slideTo.push([i, j]);
  /** Each state reached: the state it was reached from and the move. */
  const parent = new Map<number, { from: RollState; move: RollMove } | null>([[key(start), null]]);
  const routeTo = (s: RollState): RollMove[] => {
    const moves: RollMove[] = [];
    for (let step = parent.get(key(s)); step; step = parent.get(key(step.from))) moves.unshift(step.move);
    return moves;
  };
  let frontier: RollState[] = [start];
  while (frontier.length > 0) {
    const next: RollState[] = [];
    for (const s of frontier) {
      const options: [RollState, RollMove][] = [];
      for (const to of slideTo)
        options.push([
          { cell: to, o: s.o },
          { kind: 'slide', to },
        ]);
      for (const direction of [1, -1] as const)
        options.push([
          { cell: s.cell, o: turnOrientation(s.o, direction) },
          { kind: 'turn', direction },
        ]);
      for (const d of ROLL_DIRECTIONS) {
        const q = rollOrientation(s.o, d),
          move: RollMove = { kind: 'roll', direction: d };
        if (!s.cell) options.push([{ cell: null, o: q }, move]);
        else {
          const i = s.cell[0] + STEP[d]![0],
            j = s.cell[1] + STEP[d]![1];
          if (cellFits(p, i, j)) options.push([{ cell: [i, j], o: q }, move]);
        }
      }
      for (const [t, move] of options) {
        const k = key(t);
        if (parent.has(k)) continue;
        parent.set(k, { from: s, move });
        if (done(t)) return routeTo(t);
        next.push(t);
      }
    }
    frontier = next;
  }
  return null;
}

/**
 * The fewest moves (slides, rolls, quarter turns) that bring the cube to rest on the pad with the face
 * it wants on top: the length of `moveRoute` (see there for the moves and `from`).
 * @returns the moves, >= 0 (0 when it already rests there with the face), or -1 if no sequence reaches it.
 */
export function movePar(p: RollPuzzle, from: readonly [number, number] | null, o: GridOrientation): number {
  return moveRoute(p, from, o)?.length ?? -1;
}
