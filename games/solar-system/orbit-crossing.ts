/**
 * Where a forecast's path meets a planet's orbit, DOM-free (Node tests run it): what the page shows
 * before a mission's first launch instead of the forecast's verdict. The player reads the transfer
 * orbit (the probe's dots to the target's orbit line, and the day it gets there) against where the
 * target will be that day, and judges the launch; the verdict comes after a try.
 *
 * The orbit is the two-body Kepler conic of the target's heliocentric state now, the one the page
 * draws: its radius towards a direction u is p / (1 + e . u), p = h^2 / mu the semi-latus rectum, e
 * the eccentricity vector ((v^2 - mu / r) r - (r . v) v) / mu (Curtis, Orbital Mechanics, sect. 2.6
 * and 2.11). A direction off the orbit's plane is taken by its projection's angle (the planets'
 * orbits lie within a few degrees of the ecliptic, where the probe flies).
 *
 * Units: the world's (AU, days; mu in AU^3/day^2).
 */

import type { Forecast } from './forecast';
import { keplerState } from './kepler';

/**
 * The radius of the Kepler orbit of the heliocentric state `state` (position AU in [0..2], velocity
 * AU/day in [3..5]) about a centre of parameter `mu` (AU^3/day^2) in the direction (x, y, z) from
 * the centre (any length > 0), AU. An open orbit (e >= 1) has no radius where 1 + e . u <= 0:
 * Infinity there.
 * @throws RangeError naming the parameter when mu is not positive and finite, or the direction or
 *   the position is zero or not finite.
 */
export function orbitRadiusToward(state: ArrayLike<number>, mu: number, x: number, y: number, z: number): number {
  if (!(mu > 0 && Number.isFinite(mu))) throw new RangeError(`orbitRadiusToward: mu must be positive and finite, got ${mu}`);
  const n = Math.hypot(x, y, z);
  if (!(n > 0 && Number.isFinite(n)))
    throw new RangeError(`orbitRadiusToward: the direction must be finite and not zero, got (${x}, ${y}, ${z})`);
  const rx = state[0]!,
    ry = state[1]!,
    rz = state[2]!,
    vx = state[3]!,
    vy = state[4]!,
    vz = state[5]!;
  const r = Math.hypot(rx, ry, rz);
  if (!(r > 0 && Number.isFinite(r))) throw new RangeError(`orbitRadiusToward: state's position must be finite and not zero, got r = ${r}`);
  const hx = ry * vz - rz * vy,
    hy = rz * vx - rx * vz,
    hz = rx * vy - ry * vx;
  const h2 = hx * hx + hy * hy + hz * hz;
  const v2 = vx * vx + vy * vy + vz * vz,
    rv = rx * vx + ry * vy + rz * vz;
  const k = v2 - mu / r;
  const ex = (k * rx - rv * vx) / mu,
    ey = (k * ry - rv * vy) / mu,
    ez = (k * rz - rv * vz) / mu;
  // The direction laid into the orbit's plane (its component along h removed), then made unit.
  const hn = Math.sqrt(h2) || 1;
  const along = (x * hx + y * hy + z * hz) / hn;
  let ux = x - (along * hx) / hn,
    uy = y - (along * hy) / hn,
    uz = z - (along * hz) / hn;
  const un = Math.hypot(ux, uy, uz) || 1;
  ux /= un;
  uy /= un;
  uz /= un;
  const q = 1 + ex * ux + ey * uy + ez * uz;
  return q > 0 ? h2 / mu / q : Infinity;
}

/** How near a flown path came to a target's orbit, radially (`orbitReach`). */
export interface OrbitReach {
  /** Whether some point of the path got to within `zone` of the orbit, or past it. */
  reached: boolean;
  /** The Sun distance of the path's point nearest the orbit (or farthest past it), AU. */
  r: number;
  /** The orbit's radius in that point's direction (`orbitRadiusToward`), AU. */
  orbit: number;
}

/**
 * Whether the flown path `path` (heliocentric x, y, z per point, AU; its first `points` points) got
 * out to (`outward`) or in to (not `outward`) the orbit of the target whose heliocentric state at
 * the launch is `target`, within `zone` AU: the orbit the map drew and the forecast read ("is at
 * Mars's orbit on day 309"), so a miss's advice agrees with it. The target's distance from the Sun
 * at the launch said "short of Mars's orbit (1.66 AU)" of a path that crossed the drawn orbit at 1.45 AU.
 * @returns the reach: reached, and the point of the path that came nearest the orbit (or went
 *   farthest past it) with the orbit's radius there; r = orbit = NaN for no points.
 * @throws RangeError naming the parameter when points is negative, not an integer or beyond the
 *   path, or zone is negative or not finite (and as `orbitRadiusToward` for mu and the target).
 */
export function orbitReach(
  path: ArrayLike<number>,
  points: number,
  target: ArrayLike<number>,
  mu: number,
  zone: number,
  outward: boolean,
): OrbitReach {
  if (!(Number.isInteger(points) && points >= 0 && 3 * points <= path.length))
    throw new RangeError(`orbitReach: points must be an integer in [0, ${Math.floor(path.length / 3)}], got ${points}`);
  if (!(zone >= 0 && Number.isFinite(zone))) throw new RangeError(`orbitReach: zone must be finite and >= 0, got ${zone}`);
  let best = -Infinity,
    r = Number.NaN,
    orbit = Number.NaN;
  for (let i = 0; i < points; i++) {
    const x = path[3 * i]!,
      y = path[3 * i + 1]!,
      z = path[3 * i + 2]!;
    const ri = Math.hypot(x, y, z);
    if (!(ri > 0)) continue;
    const oi = orbitRadiusToward(target, mu, x, y, z);
    // How far out past the orbit (outward) or in past it (inward): < 0 short of it.
    const past = outward ? ri - oi : oi - ri;
    if (past > best) {
      best = past;
      r = ri;
      orbit = oi;
    }
  }
  return { reached: best >= -zone, r, orbit };
}

/**
 * The points of `forecast`'s path on or past the orbit of the target whose heliocentric state now
 * is `target` (about a centre of parameter `mu`): each point where the probe's distance from the
 * Sun, compared with the orbit's radius in the probe's direction (`orbitRadiusToward`), has changed
 * side since the point before (a path that climbs out past the orbit and falls back crosses it
 * twice), written into `out` (emptied first). None for a launch too slow to climb out, or fall in,
 * to the orbit.
 * @returns out: indices into forecast.path, each in [1, forecast.points - 1], rising.
 */
export function orbitCrossings(forecast: Forecast, target: ArrayLike<number>, mu: number, out: number[] = []): number[] {
  out.length = 0;
  const p = forecast.path;
  let side = 0;
  for (let i = 0; i < forecast.points; i++) {
    const x = p[3 * i]!,
      y = p[3 * i + 1]!,
      z = p[3 * i + 2]!;
    const s = Math.sign(Math.hypot(x, y, z) - orbitRadiusToward(target, mu, x, y, z)) || 1;
    if (i > 0 && s !== side) out.push(i);
    side = s;
  }
  return out;
}

const crossings: number[] = [];
const then = new Float64Array(6);

/**
 * Where the player should compare the probe with the target: of the path's crossings of the
 * target's orbit (`orbitCrossings`), and its last point when the forecast arrives (inside the ring
 * before the orbit's line), the one nearest the target's own place that day (its two-body Kepler
 * orbit from `target`, ./kepler.ts): the moment the launch is about, not whether it arrives.
 * @returns an index into forecast.path, or -1 when the path never gets to the orbit and does not arrive.
 */
export function meetingPoint(forecast: Forecast, target: ArrayLike<number>, mu: number): number {
  orbitCrossings(forecast, target, mu, crossings);
  if (forecast.outcome === 'arrived' && forecast.points > 0) crossings.push(forecast.points - 1);
  let best = -1,
    nearest = Infinity;
  const p = forecast.path;
  for (const i of crossings) {
    keplerState(target, [target[3]!, target[4]!, target[5]!], mu, pathDay(forecast, i), then);
    const d = Math.hypot(p[3 * i]! - then[0]!, p[3 * i + 1]! - then[1]!, p[3 * i + 2]! - then[2]!);
    if (d < nearest) [best, nearest] = [i, d];
  }
  return best;
}

/** Days of flight at point `index` of `forecast`'s path: equal steps of `every` from `from`, the last point at `end`. */
export function pathDay(forecast: Forecast, index: number): number {
  if (!(Number.isInteger(index) && index >= 0 && index < forecast.points))
    throw new RangeError(`pathDay: index must be a whole number in [0, ${forecast.points - 1}], got ${index}`);
  return index === forecast.points - 1 ? forecast.end : forecast.from + index * forecast.every;
}

const lagAt = new Float64Array(6);

/**
 * How many days after the probe the target gets to point `index` of `forecast`'s path (where the
 * page compares them, `meetingPoint`): the angle about the target's orbit normal from the target's
 * place on the probe's day (its two-body Kepler orbit from `target`) to that point, over the
 * target's angular speed there, refined a few times on the orbit. Positive: the target is still to
 * come (the probe is early); negative: it passed there before the probe (the probe is late). Turned
 * into the preview's verdict before a first try: "Mars gets there 23 days after the probe".
 * @returns days, in (-P / 2, P / 2] of the target's period P about.
 * @throws RangeError (from `pathDay`) when index is not a point of the path.
 */
export function targetLag(forecast: Forecast, index: number, target: ArrayLike<number>, mu: number): number {
  const day = pathDay(forecast, index);
  const p = forecast.path,
    px = p[3 * index]!,
    py = p[3 * index + 1]!,
    pz = p[3 * index + 2]!;
  const v0 = [target[3]!, target[4]!, target[5]!];
  let lag = 0;
  for (let k = 0; k < 6; k++) {
    keplerState(target, v0, mu, day + lag, lagAt);
    const [x, y, z, vx, vy, vz] = lagAt as unknown as number[];
    // The orbit's normal h = r x v, and the signed angle from r to the point about it.
    const hx = y! * vz! - z! * vy!,
      hy = z! * vx! - x! * vz!,
      hz = x! * vy! - y! * vx!;
    const h = Math.hypot(hx, hy, hz);
    const cx = y! * pz - z! * py,
      cy = z! * px - x! * pz,
      cz = x! * py - y! * px;
    const angle = Math.atan2((cx * hx + cy * hy + cz * hz) / h, x! * px + y! * py + z! * pz);
    // Angular speed h / r^2 (Kepler's second law).
    const step = angle / (h / (x! * x! + y! * y! + z! * z!));
    lag += step;
    if (Math.abs(step) < 1e-3) break;
  }
  return lag;
}

/**
 * Which side of the probe the target is at the forecast's closest approach (`forecast.probeAt`,
 * `forecast.targetAt`): +1 when the target is still to come there (the probe is ahead of it along
 * the target's motion: the target is "behind", as a positive `targetLag`), -1 when it has gone by
 * (it is "ahead"). The target's motion there is taken as h x r, h = r x v the normal of its orbit
 * from `target` (position AU in [0..2], velocity AU/day in [3..5]): along its (near circular) orbit.
 * @returns +1 or -1 (+1 when the two places coincide).
 */
export function closestSide(forecast: Forecast, target: ArrayLike<number>): 1 | -1 {
  const hx = target[1]! * target[5]! - target[2]! * target[4]!,
    hy = target[2]! * target[3]! - target[0]! * target[5]!,
    hz = target[0]! * target[4]! - target[1]! * target[3]!;
  const [x, y, z] = forecast.targetAt as unknown as [number, number, number];
  // h x r: the way the target goes round at its place then.
  const ax = hy * z - hz * y,
    ay = hz * x - hx * z,
    az = hx * y - hy * x;
  const along = (forecast.probeAt[0]! - x) * ax + (forecast.probeAt[1]! - y) * ay + (forecast.probeAt[2]! - z) * az;
  return along >= 0 ? 1 : -1;
}
