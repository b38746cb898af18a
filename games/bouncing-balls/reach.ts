/**
 * Can a player reach a hoop? A search over slingshot throws (hoop.ts throwPath in the scene's
 * default physics: g 9.81 m/s^2, no drag) for a clean basket: the ball's centre goes down through
 * the opening before it touches anything (the box, a ramp, the backboard, the rim or the net), and
 * the throws next to it (the angle 1.5 degrees either way, the speed 0.4 m/s either way) do too, so
 * a hand that is a little off still scores. No DOM: the tests and scripts/bouncing-balls-reach.mjs
 * run it in Node.
 *
 * "Natural" starts: where a newcomer throws from, the lower part of the box above the pile of
 * balls on its floor (NATURAL_BAND), every NATURAL_PITCH m across it, clear of the ramps.
 */
import {
  HOOP_HALF_WIDTH,
  HOOP_RADIUS,
  type HoopSpot,
  hoopCrossing,
  hoopOpening,
  hoopSegments,
  MAX_THROW_SPEED,
  mayScore,
  NET,
  PLAYER_RADIUS,
  throwPath,
  underHoop,
} from './hoop';
import { layoutOf, SEGMENT_RADIUS } from './scene';

/** The band of natural starts: from `low` m above the floor (over the pile of 40 balls) to `high` of the box's height (below its middle). */
export const NATURAL_BAND = Object.freeze({ low: 1.5, high: 0.4 });

/** Spacing of the natural starts, m. */
export const NATURAL_PITCH = 0.5;

/** Steps of the search: throw angle, degrees from +x (counter-clockwise), and speed, m/s. */
const ANGLE_STEP = 3,
  MIN_SPEED = 3;

/** How far the neighbour throws lie from a basket: angle, degrees, and speed, m/s. */
export const ROBUST = Object.freeze({ angle: 1.5, speed: 0.4 });

/** A throw: start (x, y), m, angle, degrees from +x, and speed, m/s. */
export interface Throw {
  readonly x: number;
  readonly y: number;
  readonly angle: number;
  readonly speed: number;
}

function pathOptions(spot: HoopSpot, tall: boolean) {
  const { box, segments } = layoutOf(tall);
  const walls = [
    ...segments.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS] as const),
    ...hoopSegments(spot).map(([ax, ay, bx, by]) => [ax, ay, bx, by, HOOP_RADIUS] as const),
  ];
  const h = 1 / 60;
  return {
    gravity: 9.81,
    drag: 'none' as const,
    k: 0,
    mass: 1,
    radius: PLAYER_RADIUS,
    box,
    every: h,
    step: h,
    seconds: 3,
    bounces: 0,
    walls,
    hoop: spot,
  };
}

/**
 * Whether `t` is a clean basket in the hoop at `spot` of the layout (`tall`): released below the
 * rim's line (hoop.ts mayScore), its centre goes down through the opening before any touch.
 * @throws RangeError on a non-finite throw.
 */
export function cleanBasket(spot: HoopSpot, tall: boolean, t: Throw): boolean {
  if (![t.x, t.y, t.angle, t.speed].every(Number.isFinite))
    throw new RangeError(`cleanBasket: throw must be finite, got ${JSON.stringify(t)}`);
  if (!mayScore(spot, t.y)) return false;
  const o = pathOptions(spot, tall);
  const a = (t.angle * Math.PI) / 180;
  const path = throwPath(t.x, t.y, t.speed * Math.cos(a), t.speed * Math.sin(a), o);
  const full = 1 + Math.round(o.seconds / o.step);
  const opening = hoopOpening(spot);
  // The last point of a path that ended early is its first touch: a crossing into it does not count.
  const last = path.length / 2 - (path.length / 2 < full ? 1 : 0);
  for (let i = 1; i < last; i++) {
    if (hoopCrossing(opening, path[2 * i - 2]!, path[2 * i - 1]!, path[2 * i]!, path[2 * i + 1]!) === -1) return true;
  }
  return false;
}

/** Whether `t` and its neighbours (ROBUST: angle and speed either way) are all clean baskets. */
export function robustBasket(spot: HoopSpot, tall: boolean, t: Throw): boolean {
  if (!cleanBasket(spot, tall, t)) return false;
  for (const [da, ds] of [
    [-ROBUST.angle, 0],
    [ROBUST.angle, 0],
    [0, -ROBUST.speed],
    [0, ROBUST.speed],
  ] as const) {
    if (!cleanBasket(spot, tall, { ...t, angle: t.angle + da, speed: Math.min(MAX_THROW_SPEED, t.speed + ds) })) return false;
  }
  return true;
}

/** Where the search aims in the opening: its centre and 0.3 m either side of it, m. */
const AIM_OFFSETS = [0, -0.3, 0.3];

/**
 * A robust clean basket from (x, y), m, into the hoop at `spot`, or null: for each angle 3 degrees
 * apart (steepest first) and each aim point (AIM_OFFSETS across the opening), the drag-free speed
 * whose parabola passes down through that point (within MAX_THROW_SPEED less ROBUST.speed), tried.
 */
export function findBasket(spot: HoopSpot, tall: boolean, x: number, y: number): Throw | null {
  const g = 9.81;
  const dy = spot.y - y;
  for (let k = 0; k < 180 / ANGLE_STEP - 1; k++) {
    // 90, 93, 87, 96, 84, ...: nearest the vertical first.
    const angle = 90 + (k % 2 === 0 ? 1 : -1) * Math.ceil(k / 2) * ANGLE_STEP;
    const a = (angle * Math.PI) / 180,
      c = Math.cos(a),
      s = Math.sin(a);
    for (const off of AIM_OFFSETS) {
      const dx = spot.x + off - x;
      // Through (dx, dy): dy = dx tan(a) - g dx^2 / (2 v^2 cos^2 a), coming down there (vy < 0).
      const lift = dx * (s / c) - dy;
      if (Math.abs(c) < 1e-6 || lift <= 0 || dx * c <= 0) continue;
      const speed = Math.sqrt((g * dx * dx) / (2 * c * c * lift));
      if (!(speed >= MIN_SPEED && speed <= MAX_THROW_SPEED - ROBUST.speed)) continue;
      const time = dx / (speed * c);
      if (speed * s - g * time >= 0) continue;
      const t = { x, y, angle, speed };
      if (robustBasket(spot, tall, t)) return t;
    }
  }
  return null;
}

/** Distance from (px, py) to the segment (ax, ay)-(bx, by), m. */
function distance(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax,
    ey = by - ay;
  const u = Math.max(0, Math.min(1, ((px - ax) * ex + (py - ay) * ey) / (ex * ex + ey * ey)));
  return Math.hypot(px - ax - u * ex, py - ay - u * ey);
}

/** The natural starts of a layout for the hoop at `spot`, m, flat [x0, y0, x1, y1, ...]: in NATURAL_BAND, clear of the ramps and hoop by a ball and 0.1 m. */
export function naturalStarts(spot: HoopSpot, tall: boolean): number[] {
  const { box, segments } = layoutOf(tall);
  const walls = [
    ...segments.map(([ax, ay, bx, by]) => [ax, ay, bx, by, SEGMENT_RADIUS] as const),
    ...hoopSegments(spot).map(([ax, ay, bx, by]) => [ax, ay, bx, by, HOOP_RADIUS] as const),
  ];
  const out: number[] = [];
  for (let y = box.min[1] + NATURAL_BAND.low; y <= box.min[1] + NATURAL_BAND.high * (box.max[1] - box.min[1]) + 1e-9; y += NATURAL_PITCH) {
    if (!mayScore(spot, y)) continue;
    for (let x = box.min[0] + 0.5; x <= box.max[0] - 0.5 + 1e-9; x += NATURAL_PITCH) {
      if (walls.some(([ax, ay, bx, by, r]) => distance(x, y, ax, ay, bx, by) < PLAYER_RADIUS + r + 0.1)) continue;
      out.push(x, y);
    }
  }
  return out;
}

/**
 * Whether a hoop at `spot` fits the layout (`tall`): its backboard, rim and net (NET) inside the box
 * with 0.2 m to spare below the net and beside the board, and a ball (PLAYER_RADIUS) and 0.1 m clear
 * of every ramp, so the ramps neither cut the net nor wedge a ball against the hoop.
 */
export function hoopFits(spot: HoopSpot, tall: boolean): boolean {
  const { box, segments } = layoutOf(tall);
  const [board, rim] = hoopSegments(spot);
  const left = Math.min(board![0], rim![2]) - 0.2,
    right = Math.max(board![0], rim![2]) + 0.2;
  if (left < box.min[0] - 0.3 || right > box.max[0] + 0.3) return false;
  if (spot.y - NET.depth - 0.2 < box.min[1] || board![3] > box.max[1] - 0.1) return false;
  // The hoop's outline: backboard, rim, net sides and bottom.
  const L = spot.x - HOOP_HALF_WIDTH,
    R = spot.x + HOOP_HALF_WIDTH,
    b = spot.y - NET.depth;
  const parts = [board!, rim!, [L, spot.y, L + NET.narrow, b], [R, spot.y, R - NET.narrow, b], [L + NET.narrow, b, R - NET.narrow, b]];
  const clear = 2 * PLAYER_RADIUS + 0.1;
  for (const [ax, ay, bx, by] of segments)
    for (const p of parts)
      for (let u = 0; u <= 1; u += 0.1) {
        const px = p[0]! + u * (p[2]! - p[0]!),
          py = p[1]! + u * (p[3]! - p[1]!);
        if (distance(px, py, ax, ay, bx, by) < clear) return false;
      }
  return true;
}

/** Spacing of the points across the opening that anyBasket aims its throws through, m. */
const ANY_AIM_PITCH = 0.1;

/**
 * Whether some slingshot throw from (x, y), m, at a speed over `low` and up to `top`, m/s (the
 * slingshot's range there: hoop.ts slingRoom's low and top on the phone's tall box, 0 and
 * MAX_THROW_SPEED on the wide one), is a clean basket in the hoop at `spot` (cleanBasket: drag-free, the
 * other balls left out). Searched as a player's pulls are: every direction 1 degree apart, through
 * points across the opening ANY_AIM_PITCH apart at the drag-free speed that comes down through each.
 * False for a start above the shot line (mayScore). About 3,000 short flights when none scores.
 * @throws RangeError on a non-finite start or speed.
 */
export function anyBasket(spot: HoopSpot, tall: boolean, x: number, y: number, low: number, top: number): boolean {
  if (![x, y, low, top].every(Number.isFinite))
    throw new RangeError(`anyBasket: start and speeds must be finite, got (${x}, ${y}), ${low}..${top}`);
  if (!mayScore(spot, y)) return false;
  const g = 9.81,
    dy = spot.y - y,
    { minX, maxX } = hoopOpening(spot);
  for (let k = 0; k < 179; k++) {
    // 90, 91, 89, 92, 88, ...: nearest the vertical first (where most baskets are).
    const angle = 90 + (k % 2 === 0 ? 1 : -1) * Math.ceil(k / 2);
    const a = (angle * Math.PI) / 180,
      c = Math.cos(a),
      s = Math.sin(a);
    if (Math.abs(c) < 1e-6) continue;
    for (let aim = minX + ANY_AIM_PITCH / 2; aim < maxX; aim += ANY_AIM_PITCH) {
      const dx = aim - x,
        lift = dx * (s / c) - dy;
      if (lift <= 0 || dx * c <= 0) continue;
      const speed = Math.sqrt((g * dx * dx) / (2 * c * c * lift));
      if (!(speed > low && speed <= top)) continue;
      // Coming down through the rim's line there, not still rising.
      if (speed * s - (g * dx) / (speed * c) >= 0) continue;
      if (cleanBasket(spot, tall, { x, y, angle, speed })) return true;
    }
  }
  return false;
}

/**
 * What the aiming label says for a throw from (x, y), m, at the hoop at `spot` when no pull there
 * scores (anyBasket with the slingshot's `low` and `top` speeds, m/s): under the hoop (hoop.ts
 * underHoop) 'no shot from under the hoop: start further out', elsewhere 'no shot from here: start
 * further out'; '' when some pull scores, or the start is above the shot line (the page says "too
 * high" for those).
 */
export function noShotWords(spot: HoopSpot, tall: boolean, x: number, y: number, low: number, top: number): string {
  if (!mayScore(spot, y) || anyBasket(spot, tall, x, y, low, top)) return '';
  return underHoop(spot, x, y) ? 'no shot from under the hoop: start further out' : 'no shot from here: start further out';
}
