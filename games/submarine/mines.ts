/**
 * The submarine course's sea mines: moored contact mines, each a buoyant sphere held up on a taut
 * cable from an anchor on the seabed, laid across the legs between the beacons so that the straight
 * run from one beacon to the next meets a mine and the pilot must go over or under it. Also the
 * course's par time. Headless (no drawing), so placement, contact and par are tested in node.
 */

import { Rng } from '@bitphysics/physics';
import { assertPositive } from '@bitphysics/physics/validate';
import { SUBMARINE, type SubmarineHandles, seabedHeight } from '@bitphysics/projects';
import { assertSegment } from './beacons';

/** A mine's contact radius (the sphere and its horns' tips), m. */
export const MINE_RADIUS = 2.4;
/** No mine's centre lies nearer a beacon than this, m (the game collects within 7 m). */
export const MINE_BEACON_CLEARANCE = 15;
/** No mine's centre lies less than this under the surface, m, so the boat can pass over it. */
export const MINE_TOP = 9;
/** No mine's centre lies less than this over the seabed, m. */
export const MINE_BED_CLEARANCE = 5;
/**
 * Impulse of a mine's blast on the hull, N s, pushing the hull away from the mine: 110 t (the hull
 * with half-full tanks) thrown at about 4 m/s.
 */
export const MINE_BLAST_IMPULSE = 4.4e5;

/** A moored mine: its centre (x, y, m, y up) and the seabed height under it, where its cable is anchored (m). */
export interface Mine {
  x: number;
  y: number;
  anchor: number;
}

/**
 * The beacons in the order of the course: the first one (close to the start), then the others by x
 * (the scene lays them out so). @returns indices into the (x, y) pairs of `beacons`.
 */
export function courseOrder(beacons: ArrayLike<number>): number[] {
  const n = beacons.length / 2;
  const rest = Array.from({ length: Math.max(0, n - 1) }, (_, i) => i + 1).sort((a, b) => beacons[2 * a]! - beacons[2 * b]!);
  return n > 0 ? [0, ...rest] : [];
}

/**
 * Lays the mines of a course: on each leg between two beacons (none on the first, from the start to
 * the first beacon) one mine on the straight line from one to the next, 40 to 60% of the way, and one
 * 65 to 85% of the way, 5 to 9 m above or below that line. A mine that would lie within
 * `MINE_BEACON_CLEARANCE` of a beacon, above `MINE_TOP` or within `MINE_BED_CLEARANCE` of the
 * seabed is moved into range, and left out if it cannot be. Seeded: the same course has the same mines.
 * @param beacons (x, y) pairs, m, as the scene lays them.
 * @param seabed the scene's seabed.
 * @param seed any finite number (the course's seed).
 * @throws RangeError when `seed` is not finite.
 */
export function layMines(beacons: ArrayLike<number>, seabed: SubmarineHandles['seabed'], seed: number): Mine[] {
  if (!Number.isFinite(seed)) throw new RangeError(`layMines: seed must be finite, got ${seed}`);
  const rng = new Rng(seed * 7919 + 17);
  const order = courseOrder(beacons);
  const mines: Mine[] = [];
  const clearOfBeacons = (x: number, y: number) => {
    for (let i = 0; i < beacons.length; i += 2) if (Math.hypot(beacons[i]! - x, beacons[i + 1]! - y) < MINE_BEACON_CLEARANCE) return false;
    return true;
  };
  for (let leg = 1; leg < order.length; leg++) {
    const a = order[leg - 1]!,
      b = order[leg]!;
    const ax = beacons[2 * a]!,
      ay = beacons[2 * a + 1]!,
      bx = beacons[2 * b]!,
      by = beacons[2 * b + 1]!;
    for (const [f, offset] of [
      [rng.range(0.4, 0.6), rng.range(-1, 1)],
      [rng.range(0.65, 0.85), (rng.next() < 0.5 ? -1 : 1) * rng.range(5, 9)],
    ] as const) {
      const x = ax + f * (bx - ax);
      const anchor = seabedHeight(seabed, x);
      const y = Math.min(-MINE_TOP, Math.max(anchor + MINE_BED_CLEARANCE, ay + f * (by - ay) + offset));
      if (y - anchor < MINE_BED_CLEARANCE || !clearOfBeacons(x, y)) continue;
      mines.push({ x, y, anchor });
    }
  }
  return mines;
}

/**
 * How near the straight way of the hull's centre may pass a mine's centre before the pointer warns,
 * m: the mine's radius, half the hull's height and 3 m of room (6.9 m).
 */
export const MINE_WAY_CLEARANCE = MINE_RADIUS + SUBMARINE.height / 2 + 3;

/**
 * The first live mine along the straight way from the hull at (x0, y0) to the beacon at (x1, y1),
 * m (y up): the one nearest the hull whose centre lies within `clearance` (m, > 0) of the segment,
 * and on which side the way should pass it: 'over' when the mine lies below the line (or on it
 * with more room above: deeper than half the water between it and the surface), else 'under'.
 * Null when the way is clear. Going straight for the beacon would otherwise set it off.
 * @param mines the course's mines; `live[i]` false for one that went off.
 * @throws RangeError when a coordinate is not finite or `clearance` is not positive.
 */
export function mineOnWay(
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  mines: readonly Mine[],
  live: readonly boolean[],
  clearance: number = MINE_WAY_CLEARANCE,
): { index: number; side: 'over' | 'under' } | null {
  assertSegment('mineOnWay', x0, y0, x1, y1);
  assertPositive('mineOnWay', 'clearance', clearance);
  const dx = x1 - x0,
    dy = y1 - y0,
    len2 = dx * dx + dy * dy;
  let best: { index: number; side: 'over' | 'under' } | null = null,
    bestU = Infinity;
  for (let i = 0; i < mines.length; i++) {
    if (!live[i]) continue;
    const m = mines[i]!;
    const u = len2 > 0 ? Math.max(0, Math.min(1, ((m.x - x0) * dx + (m.y - y0) * dy) / len2)) : 0;
    const lx = x0 + u * dx,
      ly = y0 + u * dy;
    if (Math.hypot(m.x - lx, m.y - ly) >= clearance || u >= bestU) continue;
    bestU = u;
    // Below the line: over it. Near the line: the side with the more water, above (to the surface) or under (to the bed).
    const side = m.y < ly - 0.5 ? 'over' : m.y > ly + 0.5 ? 'under' : -m.y > m.y - m.anchor ? 'over' : 'under';
    best = { index: i, side };
  }
  return best;
}

/**
 * Distance, m, from the point (px, py) to the hull, a box `SUBMARINE.length` x `SUBMARINE.height`
 * centred at (x, y) m and turned by `angle` rad (0 inside it): the point taken into the hull's frame
 * (u along, v across), then to the nearest point of the box.
 */
export function hullDistance(x: number, y: number, angle: number, px: number, py: number): number {
  const dx = px - x,
    dy = py - y,
    co = Math.cos(angle),
    s = Math.sin(angle);
  const u = dx * co + dy * s,
    v = -dx * s + dy * co;
  const nu = Math.max(-SUBMARINE.length / 2, Math.min(SUBMARINE.length / 2, u)),
    nv = Math.max(-SUBMARINE.height / 2, Math.min(SUBMARINE.height / 2, v));
  return Math.hypot(u - nu, v - nv);
}

/**
 * Whether the hull, a box `SUBMARINE.length` x `SUBMARINE.height` centred at (x, y) m and turned by
 * `angle` rad, touches a mine of radius `MINE_RADIUS` at (mx, my): the distance from the mine's
 * centre to the nearest point of the box is under the radius.
 */
export function touchesMine(x: number, y: number, angle: number, mx: number, my: number): boolean {
  return hullDistance(x, y, angle, mx, my) < MINE_RADIUS;
}

/**
 * The course's par time, s: along the course from the start (0, 0) through every beacon in
 * `courseOrder`, each leg takes the longer of its run ahead at 8 m/s and its depth change at 4 m/s
 * (about 60% of the boat's top speed ahead, 12.9 m/s, and of its dive speed, 10 m/s: the rest goes
 * to the turns and the detours round the mines), plus 3 s a beacon; rounded up to 5 s.
 */
export function parTime(beacons: ArrayLike<number>): number {
  let x = 0,
    y = 0,
    t = 0;
  for (const i of courseOrder(beacons)) {
    const bx = beacons[2 * i]!,
      by = beacons[2 * i + 1]!;
    t += Math.max(Math.abs(bx - x) / 8, Math.abs(by - y) / 4) + 3;
    x = bx;
    y = by;
  }
  return Math.ceil(t / 5) * 5;
}
