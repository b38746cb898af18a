/**
 * The glow trail: small lights (a swarm of glowing plankton) laid along a safe way from the start to
 * the first beacon and from each beacon to the next, over or under the mines and clear of the seabed
 * and the surface, one every `TRAIL.spacing` m. Each one the hull touches is collected and scores, so
 * a pilot following the way has something to catch every second or so, and the trail leads to the
 * next beacon. Headless (no drawing), so the way is tested in node.
 *
 * The way on each leg is the cheapest path through a grid of columns `TRAIL.column` m apart and
 * levels `TRAIL.level` m apart (dynamic programming): cost for straying from the straight line between
 * the two beacons and for climbing or diving, never steeper than the first of `TRAIL.slopes` that
 * finds a way (a boat at full ahead, 8 m/s, and a held Dive makes about 0.5 or more), never into a mine's box,
 * the seabed's or the surface's margin. The way passes every mine over it, never under: a moored
 * mine's cable runs from it down to the seabed, and a trail through the cable reads as a way into the
 * hazard.
 */

import type { SubmarineHandles } from '@bitphysics/projects';
import { SUBMARINE, seabedHeight } from '@bitphysics/projects';
import { courseOrder, hullDistance, MINE_RADIUS, MINE_WARN_MARGIN, type Mine } from './mines';

/** The trail's settings. */
export const TRAIL = Object.freeze({
  /** Distance between two glows along x, m (about 2 s at full ahead, 8 m/s). */
  spacing: 14,
  /** Grid columns of the path search, m apart (fine enough to dive just past a mine to a beacon close behind it). */
  column: 2,
  /** Grid levels of the path search, m apart. */
  level: 0.4,
  /**
   * Steepest climb or dive of the way, m per m ahead, tried in turn until a way is found: a leg
   * whose beacons lie far apart in depth and near in x needs a steeper way (a slower boat).
   */
  slopes: [0.4, 0.7, 1.2, 3, 8] as readonly number[],
  /**
   * The way keeps out of a box round each mine: this far from its centre along x (half the hull, the
   * contact radius, the mine warning's margin and 1.5 m more), m. A hull on the way is never warned of
   * a mine (./mines.ts mineAhead warns within MINE_WARN_MARGIN of contact), so following the trail
   * never leads into a warning too late to act on.
   */
  mineHalfWidth: SUBMARINE.length / 2 + MINE_RADIUS + MINE_WARN_MARGIN + 1.5,
  /**
   * ... and this far over its centre (half the hull's height, the contact radius, the warning's
   * margin and room for a pitched hull or a pilot a little off the way), m, or as far as the surface's
   * margin leaves over a mine near the top (never less than `mineOverLeast`); under a mine the box
   * runs down to the seabed (its cable).
   */
  mineHalfHeight: SUBMARINE.height / 2 + MINE_RADIUS + MINE_WARN_MARGIN + 3,
  /** The least room kept over a mine's centre, m: just out of the warning's reach (half the hull, contact radius, margin). */
  mineOverLeast: SUBMARINE.height / 2 + MINE_RADIUS + MINE_WARN_MARGIN + 0.3,
  /** The way keeps this far over the seabed, m (the hull's centre). */
  bedClearance: 6,
  /** The way keeps this far under the surface, m (the hull's centre). */
  surfaceClearance: 6,
  /** No glow nearer a beacon than this along x, m (the beacon is the catch there). */
  beaconGap: 8,
  /** A glow is collected when it comes this near the hull's box, m. */
  reach: 2.5,
  /** Where the way starts, m (x, y): ahead of the boat's start, under the surface. */
  start: [14, -6] as const,
});

/**
 * How far over the centre of mine `m` the way keeps, m: `TRAIL.mineHalfHeight`, less over a mine
 * whose box would reach into the surface's margin, never less than `TRAIL.mineOverLeast`.
 */
function mineOver(m: Mine): number {
  return Math.max(TRAIL.mineOverLeast, Math.min(TRAIL.mineHalfHeight, -TRAIL.surfaceClearance - m.y));
}

/** A glow of the trail: its place, m (x, y, y up), and the leg it lies on (0: the start to the first beacon). */
export interface Glow {
  x: number;
  y: number;
  leg: number;
}

/**
 * Whether a level hull running straight from (x0, y0) to (x1, y1), m, stays out of every mine's box
 * (over the mine, down to the seabed) less 1 m along x and up to 1 m over it (the grid's way keeps
 * the whole box at its columns; a run between two glows may cut its corner by that much, still clear
 * of the mine warning's reach) and at least
 * half the bed's margin over the bed, sampled every half metre.
 */
function clearRun(x0: number, y0: number, x1: number, y1: number, seabed: SubmarineHandles['seabed'], mines: readonly Mine[]): boolean {
  const n = Math.max(1, Math.ceil(2 * Math.hypot(x1 - x0, y1 - y0)));
  for (let i = 0; i <= n; i++) {
    const x = x0 + ((x1 - x0) * i) / n,
      y = y0 + ((y1 - y0) * i) / n;
    if (y < seabedHeight(seabed, x) + TRAIL.bedClearance / 2) return false;
    for (const m of mines) {
      const over = mineOver(m);
      if (Math.abs(x - m.x) < TRAIL.mineHalfWidth - 1 && y < m.y + over - Math.min(1, over - TRAIL.mineOverLeast)) return false;
    }
  }
  return true;
}

/**
 * The cheapest way from (ax, ay) to (bx, by), m (bx > ax), as the y of each grid column (x = ax + i
 * dx, i = 0..n), or null when there is none. See the header for the grid and its costs.
 */
function findWay(
  ax: number,
  ay: number,
  bx: number,
  by: number,
  seabed: SubmarineHandles['seabed'],
  mines: readonly Mine[],
  slope: number,
): { xs: number[]; ys: number[] } | null {
  const n = Math.max(1, Math.round((bx - ax) / TRAIL.column)),
    dx = (bx - ax) / n;
  const top = Math.max(ay, by, -TRAIL.surfaceClearance);
  let bottom = Math.min(ay, by);
  for (let i = 0; i <= n; i++) bottom = Math.min(bottom, seabedHeight(seabed, ax + i * dx) + TRAIL.bedClearance);
  const h = TRAIL.level;
  const levels = Math.floor((top - bottom) / h) + 1;
  const level = (j: number) => top - j * h;
  const reach = Math.floor((slope * dx) / h);
  const cost = new Float64Array((n + 1) * levels).fill(Infinity);
  const from = new Int32Array((n + 1) * levels).fill(-1);
  const j0 = Math.max(0, Math.min(levels - 1, Math.round((top - ay) / h))),
    jn = Math.max(0, Math.min(levels - 1, Math.round((top - by) / h)));
  cost[j0] = 0;
  for (let i = 1; i <= n; i++) {
    const x = ax + i * dx,
      line = ay + ((by - ay) * i) / n;
    // This column's margins: the surface's and the bed's, and the boxes of the mines near it.
    const floor = seabedHeight(seabed, x) + TRAIL.bedClearance;
    const near = mines.filter((m) => Math.abs(x - m.x) < TRAIL.mineHalfWidth);
    const open = (y: number): boolean => {
      if (y > -TRAIL.surfaceClearance || y < floor) return false;
      for (const m of near) if (y < m.y + mineOver(m)) return false;
      return true;
    };
    for (let j = 0; j < levels; j++) {
      // The end sits on the beacon, which is always open (mines keep 15 m from beacons).
      if (i === n ? j !== jn : !open(level(j))) continue;
      const stray = level(j) - line;
      let best = Infinity,
        arg = -1;
      for (let k = Math.max(0, j - reach); k <= Math.min(levels - 1, j + reach); k++) {
        const c = cost[(i - 1) * levels + k]! + h * h * (k - j) * (k - j);
        if (c < best) {
          best = c;
          arg = k;
        }
      }
      if (arg < 0) continue;
      cost[i * levels + j] = best + 0.02 * stray * stray * dx;
      from[i * levels + j] = arg;
    }
  }
  if (!Number.isFinite(cost[n * levels + jn]!)) return null;
  const xs: number[] = [],
    ys: number[] = [];
  for (let i = n, j = jn; i >= 0; j = from[i * levels + j]!, i--) {
    xs.push(ax + i * dx);
    ys.push(i === 0 ? ay : i === n ? by : level(j));
  }
  return { xs: xs.reverse(), ys: ys.reverse() };
}

/**
 * Lays the course's glow trail: from `TRAIL.start` to the first beacon of `courseOrder`, then from
 * each beacon to the next, a glow every `TRAIL.spacing` m along x (none within `TRAIL.beaconGap` of
 * a beacon) on the way `findWay` finds; a leg with no way (never seen on the scene's courses) gets
 * no glows.
 * @param beacons (x, y) pairs, m, as the scene lays them.
 * @param seabed the scene's seabed.
 * @param mines the course's mines (layMines).
 */
export function layTrail(beacons: ArrayLike<number>, seabed: SubmarineHandles['seabed'], mines: readonly Mine[]): Glow[] {
  const glows: Glow[] = [];
  let ax: number = TRAIL.start[0],
    ay: number = TRAIL.start[1];
  const order = courseOrder(beacons);
  for (let leg = 0; leg < order.length; leg++) {
    const bx = beacons[2 * order[leg]!]!,
      by = beacons[2 * order[leg]! + 1]!;
    let way: { xs: number[]; ys: number[] } | null = null;
    if (bx > ax + 2 * TRAIL.beaconGap) for (const slope of TRAIL.slopes) if (!way) way = findWay(ax, ay, bx, by, seabed, mines, slope);
    if (way) {
      const dxWay = way.xs[1]! - way.xs[0]!;
      const yAt = (x: number): number => {
        const i = Math.max(0, Math.min(way.xs.length - 2, Math.floor((x - ax) / dxWay)));
        const f = (x - way.xs[i]!) / dxWay;
        return way.ys[i]! + f * (way.ys[i + 1]! - way.ys[i]!);
      };
      const first = leg === 0 ? ax : ax + TRAIL.beaconGap;
      const count = Math.ceil((bx - TRAIL.beaconGap - first) / TRAIL.spacing);
      // Spread evenly between the gaps at the two ends.
      const step = count > 0 ? (bx - TRAIL.beaconGap - first) / count : 0;
      const xs: number[] = [];
      for (let k = 0; k <= count; k++) xs.push(first + k * step);
      // Where the straight run from one glow to the next (or from or to a beacon) would cut a
      // corner of the way into a mine's box or the bed's margin, a glow more goes half way between
      // them on the way, until every run is clear.
      const points = [ax, ...xs, bx];
      for (let k = 1; k < points.length; k++) {
        const x0 = points[k - 1]!,
          x1 = points[k]!;
        const y0 = x0 === ax ? ay : yAt(x0),
          y1 = x1 === bx ? by : yAt(x1);
        if (x1 - x0 > 2 && !clearRun(x0, y0, x1, y1, seabed, mines)) {
          points.splice(k, 0, (x0 + x1) / 2);
          k--;
        }
      }
      for (const x of points.slice(1, -1)) glows.push({ x, y: yAt(x), leg });
    }
    ax = bx;
    ay = by;
  }
  return glows;
}

/**
 * Whether the hull, a box `SUBMARINE.length` x `SUBMARINE.height` centred at (x, y) m and turned by
 * `angle` rad, comes within `TRAIL.reach` of the glow at (gx, gy).
 */
export function touchesGlow(x: number, y: number, angle: number, gx: number, gy: number): boolean {
  return hullDistance(x, y, angle, gx, gy) < TRAIL.reach;
}
