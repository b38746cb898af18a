/**
 * Scissors, headless: a stroke of the pointer cuts every cloth link it crosses.
 *
 * Every kind of link is cut (structural, shear and bending), so the two sides of a cut are no longer
 * joined by anything and part at once; the solver repacks its links at the next step.
 *
 * The cloth moves between two pointer events, so a stroke is cut from where its last point is now on
 * the cloth (a `ClothAnchor`: that point's place in a triangle of the grid, carried with the cloth)
 * to the new one (`ScissorsStroke`): the cut is continuous in the cloth even while the cloth slides
 * under the pointer. A stroke drawn through the air from point to point would leave gaps where the
 * cloth moved between events, and the piece inside a closed stroke would stay joined across them.
 * The pointer's path is taken in the cloth's frame (ScissorsStroke: a sway during a stroke does not
 * shift the cut off the line being traced).
 */

import { segmentsCross } from '@bitphysics/game-kit';
import { type Cloth, handleOf, type PhysicsWorld, query, removeJoint, slotOf } from '@bitphysics/physics';
import { sheetGrid } from './scene';

/**
 * Cuts the world's cloth links that the stroke from (x0, y0) to (x1, y1), m, crosses at their current
 * positions. @returns the midpoints of the cut links, m (x, y interleaved; empty if none was cut).
 */
export function cutAlong(world: PhysicsWorld, x0: number, y0: number, x1: number, y1: number): number[] {
  const L = world.components.ClothLink,
    P = world.components.Position;
  const minX = Math.min(x0, x1),
    maxX = Math.max(x0, x1),
    minY = Math.min(y0, y1),
    maxY = Math.max(y0, y1);
  const doomed: number[] = [];
  const at: number[] = [];
  for (const e of query(world, [L])) {
    const a = L.a[e]!,
      b = L.b[e]!;
    const ax = P.x[a]!,
      ay = P.y[a]!,
      bx = P.x[b]!,
      by = P.y[b]!;
    // Cheap rejection by the boxes before the crossing test.
    if (Math.max(ax, bx) < minX || Math.min(ax, bx) > maxX || Math.max(ay, by) < minY || Math.min(ay, by) > maxY) continue;
    if (!segmentsCross(x0, y0, x1, y1, ax, ay, bx, by)) continue;
    doomed.push(handleOf(world, e));
    at.push((ax + bx) / 2, (ay + by) / 2);
  }
  for (const h of doomed) removeJoint(world, h);
  return at;
}

/** A place on a cloth: three of its points (indices of `Cloth.points`) and barycentric weights (sum 1). */
export interface ClothAnchor {
  readonly points: readonly [number, number, number];
  readonly weights: readonly [number, number, number];
}

/**
 * The place on `cloth` under world point (x, y), m: the first triangle of the grid (two a cell, whole or
 * torn) that holds it now, with its barycentric weights; else (over a cut, where the triangles have
 * come apart) the nearest point of the cloth within `reach` m; else null.
 */
export function clothAnchorAt(world: PhysicsWorld, cloth: Cloth, x: number, y: number, reach = 0): ClothAnchor | null {
  const P = world.components.Position;
  const C = cloth.columns,
    R = cloth.rows;
  const px = (i: number) => P.x[slotOf(cloth.points[i]!)]!,
    py = (i: number) => P.y[slotOf(cloth.points[i]!)]!;
  const inTriangle = (a: number, b: number, c: number): ClothAnchor | null => {
    const ax = px(a),
      ay = py(a),
      bx = px(b),
      by = py(b),
      cx = px(c),
      cy = py(c);
    const d = (by - cy) * (ax - cx) + (cx - bx) * (ay - cy);
    if (d === 0) return null;
    const wa = ((by - cy) * (x - cx) + (cx - bx) * (y - cy)) / d,
      wb = ((cy - ay) * (x - cx) + (ax - cx) * (y - cy)) / d,
      wc = 1 - wa - wb;
    return wa >= 0 && wb >= 0 && wc >= 0 ? { points: [a, b, c], weights: [wa, wb, wc] } : null;
  };
  for (let r = 0; r + 1 < R; r++)
    for (let c = 0; c + 1 < C; c++) {
      const i = r * C + c;
      const hit = inTriangle(i, i + 1, i + C) ?? inTriangle(i + 1, i + C + 1, i + C);
      if (hit) return hit;
    }
  let best = -1,
    bestD = reach;
  for (let i = 0; i < C * R; i++) {
    const d = Math.hypot(px(i) - x, py(i) - y);
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  return best < 0 ? null : { points: [best, best, best], weights: [1, 0, 0] };
}

/** Where `anchor` is now, m, into `out`. */
export function anchorPosition(world: PhysicsWorld, cloth: Cloth, anchor: ClothAnchor, out: [number, number]): [number, number] {
  const P = world.components.Position;
  out[0] = 0;
  out[1] = 0;
  for (let k = 0; k < 3; k++) {
    const e = slotOf(cloth.points[anchor.points[k]!]!);
    out[0] += anchor.weights[k]! * P.x[e]!;
    out[1] += anchor.weights[k]! * P.y[e]!;
  }
  return out;
}

/** Where `anchor` lies on the sheet at rest, m (sheet coordinates: x right from its left edge, y down from its top), into `out`. */
export function anchorAtRest(cloth: Cloth, anchor: ClothAnchor, out: [number, number]): [number, number] {
  const C = cloth.columns,
    { spacing } = sheetGrid(C);
  out[0] = 0;
  out[1] = 0;
  for (let k = 0; k < 3; k++) {
    const i = anchor.points[k]!;
    out[0] += anchor.weights[k]! * (i % C) * spacing;
    out[1] += anchor.weights[k]! * Math.floor(i / C) * spacing;
  }
  return out;
}

/** The median of `v` (sorts it in place). */
function median(v: Float64Array): number {
  v.sort();
  const m = v.length >> 1;
  return v.length % 2 ? v[m]! : (v[m - 1]! + v[m]!) / 2;
}

/**
 * A stroke of the scissors, cut in the cloth's own frame: `moveTo` cuts from where the stroke's last
 * point is now on the cloth (its ClothAnchor, carried with the cloth; off the cloth, where it was) to
 * the new pointer point moved on by as far as the cloth round the stroke's start has moved since the
 * stroke began (`drift`: the median move, in x and in y, of the cloth's points within `frame` m of it
 * then). A hand tracing a line drawn on the cloth as it lay when the stroke began so cuts that line
 * even if the cloth sways meanwhile, as scissors held against the fabric move with it. The median
 * over a patch, not the move of the cut's own edge, leaves out the edges of the cut opening under the
 * sheet's weight and a flap of the shape sagging as the cut goes round it (a minority of the patch). `close` ends a stroke that came back near its start
 * by cutting the last gap to it, so a traced outline comes away even if the hand stops just short.
 * Where the stroke went on the sheet at rest is pushed to `marks`, if given (for the fit: pattern.ts).
 */
export class ScissorsStroke {
  /** The stroke's last point on the cloth's frame, m (the pointer plus `drift`). */
  readonly at: [number, number];
  /** How far the cloth under the stroke has moved since the stroke began, m (x, y). */
  readonly drift: [number, number] = [0, 0];
  /** Length of the stroke so far, m. */
  length = 0;
  private on: ClothAnchor | null;
  private readonly start: ClothAnchor | null;
  private readonly from: [number, number] = [0, 0];
  /** The points (slots) of the patch `drift` follows, and where they were when the stroke began, m (x, y interleaved). */
  private readonly patch: number[] = [];
  private readonly patchWas: number[] = [];
  /** Scratch: the patch points' moves, m (x and y). */
  private readonly moves: [Float64Array, Float64Array];

  /** Scratch: where the stroke's last point lies on the sheet at rest, m. */
  private readonly rest: [number, number] = [0, 0];

  /**
   * Starts a stroke at (x, y), m, on `cloth`; a point within `reach` m of the cloth but on no triangle
   * of it (over a cut) holds on to the nearest point of the cloth. The stroke follows the cloth's
   * points within `frame` m of (x, y) (see the class; 0: none, the pointer as it is). Where it goes on
   * the sheet at rest (sheet coordinates, m, x and y interleaved) is pushed to `marks`, if given:
   * points along it at most a quarter of a link spacing apart, over the cloth only.
   */
  constructor(
    private readonly world: PhysicsWorld,
    private readonly cloth: Cloth,
    x: number,
    y: number,
    private readonly reach: number,
    frame = 0,
    private readonly marks?: number[],
  ) {
    this.at = [x, y];
    this.on = clothAnchorAt(world, cloth, x, y, reach);
    this.start = this.on;
    this.mark(null, this.on);
    const P = world.components.Position;
    for (const h of cloth.points) {
      const e = slotOf(h);
      if (Math.hypot(P.x[e]! - x, P.y[e]! - y) > frame) continue;
      this.patch.push(e);
      this.patchWas.push(P.x[e]!, P.y[e]!);
    }
    this.moves = [new Float64Array(this.patch.length), new Float64Array(this.patch.length)];
  }

  /**
   * Moves the stroke on to the pointer at (x, y), m (cutting to it plus `drift`), cutting the links it
   * crosses. @returns the cut links' midpoints (as cutAlong).
   */
  moveTo(x: number, y: number): number[] {
    const f = this.on ? anchorPosition(this.world, this.cloth, this.on, this.from) : this.at;
    const P = this.world.components.Position,
      n = this.patch.length;
    if (n > 0) {
      const dx = this.moves[0],
        dy = this.moves[1];
      for (let k = 0; k < n; k++) {
        const e = this.patch[k]!;
        dx[k] = P.x[e]! - this.patchWas[2 * k]!;
        dy[k] = P.y[e]! - this.patchWas[2 * k + 1]!;
      }
      this.drift[0] = median(dx);
      this.drift[1] = median(dy);
    }
    const tx = x + this.drift[0],
      ty = y + this.drift[1];
    const cut = cutAlong(this.world, f[0], f[1], tx, ty);
    this.length += Math.hypot(tx - f[0], ty - f[1]);
    this.at[0] = tx;
    this.at[1] = ty;
    const was = this.on;
    this.on = clothAnchorAt(this.world, this.cloth, tx, ty, this.reach);
    this.mark(was, this.on);
    return cut;
  }

  /** Pushes to `marks` the way from anchor `from` (null: none, only `to`) to `to` on the sheet at rest, if both are on the cloth. */
  private mark(from: ClothAnchor | null, to: ClothAnchor | null): void {
    if (!this.marks || !to) return;
    const [x0, y0] = from ? anchorAtRest(this.cloth, from, this.rest) : [Number.NaN, Number.NaN];
    const [x1, y1] = anchorAtRest(this.cloth, to, this.rest);
    const step = sheetGrid(this.cloth.columns).spacing / 4;
    const k = from ? Math.max(1, Math.ceil(Math.hypot(x1 - x0, y1 - y0) / step)) : 1;
    for (let j = 1; j <= k; j++) this.marks.push(from ? x0 + ((x1 - x0) * j) / k : x1, from ? y0 + ((y1 - y0) * j) / k : y1);
  }

  /**
   * Ends the stroke: if it ran at least `minLength` m and its last point is within `gap` m of where
   * its first point is now on the cloth, cuts the straight gap between them (a traced outline closes).
   * @returns the cut links' midpoints (as cutAlong; empty if it did not close).
   */
  close(gap: number, minLength: number): number[] {
    if (!this.start || this.length < minLength) return [];
    const f = this.on ? anchorPosition(this.world, this.cloth, this.on, this.from) : this.at;
    const s = anchorPosition(this.world, this.cloth, this.start, [0, 0]);
    if (Math.hypot(s[0] - f[0], s[1] - f[1]) > gap) return [];
    this.mark(this.on, this.start);
    return cutAlong(this.world, f[0], f[1], s[0], s[1]);
  }
}
