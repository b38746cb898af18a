/**
 * The slingshot's aim assist of bouncing balls: a pull close to one that throws through the middle of
 * the hoop is drawn to it, for a mouse and a finger alike. Without it the pulls that score are a band
 * some 20 px long and 13 px across on a desktop (420 px full pull) and 37 by 8 px on a phone held
 * upright (138 px: a finger's full pull at 390 x 844, on the phone's curve, hoop.ts slingRoom; at the
 * tightest starts 17 by 5 px), across narrower than a hand holds still while it lets go (medians of
 * `node scripts/bouncing-balls-reach.mjs --pull`). "Close" is measured as a player aims: in share of the pull's length (the throw's speed) and in
 * degrees of its direction, so a long desktop pull and a short phone one get the same leeway of speed
 * and angle, and a finger at least AIM_ASSIST's px either way (a thumb's jitter). No DOM: the page's
 * currentThrow and the node tests call it.
 */
import { type HoopSpot, MAX_THROW_SPEED, type SlingRoom, slingPull } from './hoop';

/**
 * How far the assist reaches from a pull to the pull of a throw through the hoop: `share` of the
 * pull's length along it (about that share of the throw's speed), `degrees` of its direction across
 * it, and for a finger at least `fingerLength` and `fingerSide` px (a thumb moves a few px as it
 * lifts; a phone's pulls that score are 38 to 136 px long). An ellipse: a pull off in both ways at once
 * reaches less far in each.
 */
export const AIM_ASSIST = Object.freeze({ share: 0.1, degrees: 5, fingerLength: 14, fingerSide: 6 });

/**
 * Where in the opening the assist aims, m from its middle towards the backboard: the middle first,
 * then a little towards the board (a flat throw clears the front rim) and towards the front rim.
 */
const AIM_POINTS = [0, 0.3, -0.3];

/** Steps of the search over the pull's direction, radians (a quarter degree). */
const ANGLE_STEP = Math.PI / 720;

/**
 * The pull length, px, of a drag-free throw from (x, y), m, at `angle` (radians from +x,
 * counter-clockwise; y up) that comes down through (aimX, aimY), m, under gravity `g` m/s^2, when
 * `fullPull` px throws at MAX_THROW_SPEED (hoop.ts slingPull; at room.top, from room.low, with a
 * `room`); null when no such throw is there (the point is not ahead of the throw, above its line, or
 * needs more than the top speed or, with a room, less than its low one).
 */
export function basketPull(
  x: number,
  y: number,
  angle: number,
  aimX: number,
  aimY: number,
  g: number,
  fullPull: number,
  room?: SlingRoom,
): number | null {
  const c = Math.cos(angle),
    s = Math.sin(angle);
  const dx = aimX - x,
    dy = aimY - y;
  if (Math.abs(c) < 1e-6 || dx * c <= 0) return null;
  // Through (dx, dy): dy = dx tan(a) - g dx^2 / (2 v^2 cos^2 a).
  const lift = dx * (s / c) - dy;
  if (!(lift > 0)) return null;
  const speed = Math.sqrt((g * dx * dx) / (2 * c * c * lift));
  if (!(speed > (room ? room.low : 0) && speed <= (room ? room.top : MAX_THROW_SPEED))) return null;
  // Coming down there, not still rising.
  if (speed * s - (g * dx) / (speed * c) >= 0) return null;
  return slingPull(speed, fullPull, room);
}

/** Options of `assistAim`. */
export interface AimAssistOptions {
  /** Gravity, m/s^2 down (no assist unless > 0). */
  readonly gravity: number;
  /** The pull, px, that throws at MAX_THROW_SPEED (at room.top with a `room`). */
  readonly fullPull: number;
  /** The tall box's slingshot speeds for this throw (hoop.ts slingRoom); none: the wide box's curve. */
  readonly room?: SlingRoom;
  /** Whether the pull is a finger's (AIM_ASSIST's least reach in px applies). */
  readonly finger: boolean;
}

/**
 * The pull, px (screen x, y down, from the ball to the pointer), that pull (pullX, pullY) of a throw
 * from (x, y), m, is drawn to, or null when none: of the pulls whose drag-free throw comes down
 * through an aim point of the opening of the hoop at `spot` (AIM_POINTS, the middle first), the
 * nearest within AIM_ASSIST's reach for each aim point, nearest first, the first that `scores` (the
 * page's prediction of the throw at a pull, which sees the balls in the way and the world's steps).
 * @throws RangeError on a non-finite pull or start.
 */
export function assistAim(
  pullX: number,
  pullY: number,
  x: number,
  y: number,
  spot: HoopSpot,
  options: AimAssistOptions,
  scores: (pullX: number, pullY: number) => boolean,
): [number, number] | null {
  if (![pullX, pullY, x, y].every(Number.isFinite))
    throw new RangeError(`assistAim: pull and start must be finite, got pull (${pullX}, ${pullY}) from (${x}, ${y})`);
  const length = Math.hypot(pullX, pullY);
  const { gravity, fullPull, finger, room } = options;
  if (length === 0 || !(gravity > 0) || !(fullPull > 0)) return null;
  const reachLength = Math.max(finger ? AIM_ASSIST.fingerLength : 0, AIM_ASSIST.share * length);
  const reachSide = Math.max(finger ? AIM_ASSIST.fingerSide : 0, length * Math.tan((AIM_ASSIST.degrees * Math.PI) / 180));
  const reachAngle = Math.atan2(reachSide, length);
  // The throw goes opposite to the pull (screen y down, world y up).
  const angle = Math.atan2(pullY, -pullX);
  const best: { d: number; angle: number; length: number }[] = [];
  for (const off of AIM_POINTS) {
    let near: { d: number; angle: number; length: number } | null = null;
    for (let da = -reachAngle; da <= reachAngle + 1e-12; da += ANGLE_STEP) {
      const l = basketPull(x, y, angle + da, spot.x + spot.side * off, spot.y, gravity, fullPull, room);
      if (l === null || l > fullPull) continue;
      const d = ((l - length) / reachLength) ** 2 + ((length * Math.sin(da)) / reachSide) ** 2;
      if (d <= 1 && (near === null || d < near.d)) near = { d, angle: angle + da, length: l };
    }
    if (near) best.push(near);
  }
  best.sort((a, b) => a.d - b.d);
  for (const b of best) {
    const px = -b.length * Math.cos(b.angle),
      py = b.length * Math.sin(b.angle);
    if (scores(px, py)) return [px, py];
  }
  return null;
}
