/**
 * The submarine course's sea mines: moored contact mines, each a buoyant sphere held up on a taut
 * cable from an anchor on the seabed, laid beside the legs between the beacons (below the straight
 * way, so that no cable crosses it, never on it nor near a beacon), so that a boat that strays off the way, or dives or
 * climbs carelessly, meets one and must go over or under it. Also the course's par time. Headless (no drawing), so placement, contact and par are tested in node.
 *
 * Fair: each mine leaves room to pass over it well under the waves, lies far enough past the beacon
 * before it that a boat leaving that beacon at full ahead is warned in time, and far enough from the
 * other mines that two never make a wall; and the warning (`mineAhead`) looks along the course the
 * boat is on, MINE_WARN_TIME s ahead, so it comes in time to rise or dive past at the helm's speeds
 * (HELM.climbSpeed, HELM.diveSpeed) after a pilot's reaction time.
 */

import { Rng } from '@bitphysics/physics';
import { assertFinite, assertPositive } from '@bitphysics/physics/validate';
import { SUBMARINE, type SubmarineHandles, seabedHeight } from '@bitphysics/projects';
import { assertSegment } from './beacons';
import { HELM } from './helm';
import { hullDistance } from './hull';

export { hullDistance };

/** A mine's contact radius (the sphere and its horns' tips), m. */
export const MINE_RADIUS = 2.4;
/**
 * No mine's centre lies nearer a beacon than this, m: the game collects within BEACON_CATCH (8 m), and a
 * boat coming in on a beacon, or turning round at it, has about two hull lengths of clear water.
 */
export const MINE_BEACON_CLEARANCE = 25;
/**
 * No mine's centre lies less than this under the surface, m, so the boat can pass over it with its
 * deck under the waves: its centre MINE_RADIUS + half its height + MINE_WARN_MARGIN (5.4 m) over the
 * mine's leaves the deck 5.1 m deep (at 9 m, a boat rising over a mine near the surface touched it:
 * the helm slows the climb as the deck nears the surface).
 */
export const MINE_TOP = 12;
/** No mine's centre lies less than this over the seabed, m. */
export const MINE_BED_CLEARANCE = 5;
/**
 * A pilot's reaction time to a warning, s: what the warning's timing and the mines' spacing allow for.
 */
export const MINE_REACTION = 1;
/**
 * How far ahead the warning looks along the boat's course, s (mineAhead): 40 m at full ahead
 * (8 m/s, helm.ts HELM.topSpeed). Long enough for a pilot on the keys, whose Dive or Rise asks for part of the speed (helm.ts
 * keyHeaveShare): at 4 s "dive under" would come when the mine is already at the bow. Measured
 * headless (helm and physics, test/games/submarine-mines.test.ts): a boat at full ahead on a level
 * run into a mine on its line, holding Rise from MINE_REACTION s after the warning, passes it with
 * 2 m or more to spare.
 */
export const MINE_WARN_TIME = 5;
/**
 * The least distance ahead the warning looks, m (mineWarnHorizon): a slow boat (a phone's stick
 * part way, 2-3 m/s) looking MINE_WARN_TIME s ahead saw a mine only at its bow.
 */
export const MINE_LOOK_AHEAD = 30;

/**
 * How far ahead in time the warning looks for a boat making `vx` m/s along x (either way; taken as at
 * least 2 m/s as mineAhead does): MINE_WARN_TIME s, or longer at a slow speed so that it looks at
 * least MINE_LOOK_AHEAD m ahead, s.
 * @throws RangeError when `vx` is not finite.
 */
export function mineWarnHorizon(vx: number): number {
  assertFinite('mineWarnHorizon', 'vx', vx);
  return Math.max(MINE_WARN_TIME, MINE_LOOK_AHEAD / Math.max(2, Math.abs(vx)));
}

/** The warning's room round the hull, m: a course that passes a mine closer than this (beyond contact) is warned of. */
export const MINE_WARN_MARGIN = 1.5;
/**
 * No mine lies less than this past the beacon before it along x, m: at full ahead (8 m/s) from
 * the beacon, 5.6 s, enough for MINE_REACTION and the 1.5 s a rise over it takes, with the bow's
 * half length and the mine's radius.
 */
export const MINE_LEAD = 45;
/**
 * No two mines lie nearer than this along x, m, so that two never make a wall: once the way over or
 * under the first is clear, the second is warned of about MINE_WARN_TIME s ahead, still before the
 * first at full ahead (8 m/s).
 */
export const MINE_GAP = 40;
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
 * No mine's centre lies nearer than this to the straight way between two beacons along the course,
 * m: the mine's radius, half the hull's height and 6 m of water (9.9 m), so a boat running straight
 * from a beacon to the next (and along the glow trail, which keeps near it) passes every mine with
 * room to spare, and a mine is met only by a boat that strays: it is an obstacle beside the way, not
 * a wall across it.
 */
export const MINE_PATH_CLEARANCE = MINE_RADIUS + SUBMARINE.height / 2 + 6;

/** How `layMines` lays a course's mines (./levels.ts gives each level one). */
export interface MineLayout {
  /** The least distance of a mine's centre from the straight way between two beacons, m, at least `MINE_WAY_CLEARANCE`. */
  clearance: number;
  /** Each mine lies up to this much further from the way than `clearance` (drawn evenly), m, >= 0. */
  room: number;
  /** No mine lies less than this past the leg's first beacon along x, m, > 0. */
  lead: number;
  /** No two mines lie nearer than this along x, m, > 0. */
  gap: number;
  /** The places tried on each leg, each a range of shares of the way from one beacon to the next, in (0, 1). */
  places: readonly (readonly [number, number])[];
}

/**
 * The first level's mines: two places a leg (35 to 50 % and 75 to 90 % of the way), `MINE_PATH_CLEARANCE`
 * to 6 m more from the way, `MINE_LEAD` past the beacon before and `MINE_GAP` apart.
 */
export const MINE_LAYOUT: Readonly<MineLayout> = Object.freeze({
  clearance: MINE_PATH_CLEARANCE,
  room: 6,
  lead: MINE_LEAD,
  gap: MINE_GAP,
  places: Object.freeze([Object.freeze([0.35, 0.5] as const), Object.freeze([0.75, 0.9] as const)]),
});

/** Throws a RangeError naming layMines and the field of `layout` out of its range. */
function checkLayout(layout: MineLayout): void {
  const bad = (name: string, v: unknown) => new RangeError(`layMines: layout.${name} is out of range, got ${JSON.stringify(v)}`);
  if (!(Number.isFinite(layout.clearance) && layout.clearance >= MINE_WAY_CLEARANCE)) throw bad('clearance', layout.clearance);
  if (!(Number.isFinite(layout.room) && layout.room >= 0)) throw bad('room', layout.room);
  if (!(Number.isFinite(layout.lead) && layout.lead > 0)) throw bad('lead', layout.lead);
  if (!(Number.isFinite(layout.gap) && layout.gap > 0)) throw bad('gap', layout.gap);
  for (const p of layout.places) if (!(p[0] > 0 && p[0] <= p[1] && p[1] < 1)) throw bad('places', p);
}

/** Distance from (x, y) to the segment (x0, y0)-(x1, y1), m. */
function segmentDistance(x: number, y: number, x0: number, y0: number, x1: number, y1: number): number {
  const dx = x1 - x0,
    dy = y1 - y0,
    len2 = dx * dx + dy * dy;
  const u = len2 > 0 ? Math.max(0, Math.min(1, ((x - x0) * dx + (y - y0) * dy) / len2)) : 0;
  return Math.hypot(x - x0 - u * dx, y - y0 - u * dy);
}

/**
 * Lays the mines of a course: on each leg between two beacons (none on the first, from the start to
 * the first beacon) one mine 35 to 50% of the way from one to the next and one 75 to 90% of the way,
 * each `MINE_PATH_CLEARANCE` to 6 m more below the straight way (never above it: its cable would
 * run down across the way; just MINE_PATH_CLEARANCE where the water under it is too shallow for more). A mine above `MINE_TOP`, within `MINE_BED_CLEARANCE` of the
 * seabed, nearer than `MINE_PATH_CLEARANCE` to any leg of the course, within `MINE_BEACON_CLEARANCE`
 * of a beacon, less than `MINE_LEAD` past the leg's first beacon along x, or within `MINE_GAP` of
 * another mine along x is left out (a short leg has one mine or none).
 * Seeded: the same course has the same mines. A harder level (./levels.ts) lays them by `layout`:
 * more places on each leg, nearer the way, closer to each other and to the beacon before.
 * @param beacons (x, y) pairs, m, as the scene lays them.
 * @param seabed the scene's seabed.
 * @param seed any finite number (the course's seed).
 * @param layout how the mines are laid (default `MINE_LAYOUT`, the first level's).
 * @throws RangeError when `seed` is not finite, or a `layout` field is out of its range.
 */
export function layMines(
  beacons: ArrayLike<number>,
  seabed: SubmarineHandles['seabed'],
  seed: number,
  layout: MineLayout = MINE_LAYOUT,
): Mine[] {
  if (!Number.isFinite(seed)) throw new RangeError(`layMines: seed must be finite, got ${seed}`);
  checkLayout(layout);
  const { clearance: pathClearance, room, lead, gap, places } = layout;
  const rng = new Rng(seed * 7919 + 17);
  const order = courseOrder(beacons);
  const mines: Mine[] = [];
  const clear = (x: number, y: number) => {
    for (let i = 0; i < beacons.length; i += 2) if (Math.hypot(beacons[i]! - x, beacons[i + 1]! - y) < MINE_BEACON_CLEARANCE) return false;
    for (let leg = 1; leg < order.length; leg++) {
      const a = 2 * order[leg - 1]!,
        b = 2 * order[leg]!;
      if (segmentDistance(x, y, beacons[a]!, beacons[a + 1]!, beacons[b]!, beacons[b + 1]!) < pathClearance) return false;
    }
    return true;
  };
  for (let leg = 1; leg < order.length; leg++) {
    const a = order[leg - 1]!,
      b = order[leg]!;
    const ax = beacons[2 * a]!,
      ay = beacons[2 * a + 1]!,
      bx = beacons[2 * b]!,
      by = beacons[2 * b + 1]!;
    // Each place's share of the leg and offset drawn in turn (the first level's draws kept in their order).
    for (const [f, off] of places.map(([lo, hi]) => [rng.range(lo, hi), rng.range(0, room)] as const)) {
      const x = ax + f * (bx - ax);
      if (x - ax < lead || mines.some((m) => Math.abs(m.x - x) < gap)) continue;
      const anchor = seabedHeight(seabed, x);
      const line = ay + f * (by - ay);
      // Across the way, the vertical offset that puts the centre MINE_PATH_CLEARANCE + off from the line.
      const slope = (by - ay) / (bx - ax);
      // Where the water under the way is too shallow for the offset drawn, as near the way as is clear.
      for (const o of [off, 0]) {
        const y = line - (pathClearance + 0.5 + o) * Math.sqrt(1 + slope * slope);
        if (y > -MINE_TOP || y - anchor < MINE_BED_CLEARANCE || !clear(x, y)) continue;
        mines.push({ x, y, anchor });
        break;
      }
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

/** A mine on the boat's course (mineAhead). */
export interface MineAhead {
  /** Index of the mine. */
  index: number;
  /** Which side to pass it: 'over', or 'under' when the course runs below its centre and there is room under it. */
  side: 'over' | 'under';
  /** In how long the course would touch it (with MINE_WARN_MARGIN to spare), s. */
  time: number;
}

/**
 * The first live mine the hull would touch (with `MINE_WARN_MARGIN` to spare) within `horizon` s
 * (> 0) if it kept on its course: from its centre at (x, y), m (y up), along x at its speed `vx`
 * (m/s; at least 2 m/s the way it goes, ahead when it is still), and in depth on toward the ordered
 * depth `holdY` (m; NaN: none, surfaced or steering by the nose) at up to the helm's climb or dive
 * speed; and, while Dive or Rise is held (`options.heaving`: on the way it goes, speeding up to the
 * share `options.heave` of the helm's dive or climb speed that the control asks for) or no depth is
 * ordered (on at its vertical speed `vy`, m/s), also on: the first contact on either course. Null
 * when the course is clear.
 * Which side to pass: the one the hull can clear with more to spare by the time it gets there,
 * rising or diving flat out from its vertical speed now (HELM.climbSpeed, HELM.diveSpeed, reached at
 * HELM.brake), that does not run it into another mine on the way; under only where the hull has
 * room under the mine over the seabed (`seabed`, the scene's); over has room (MINE_TOP).
 * @param mines the course's mines; `live[i]` false for one that went off.
 * @param options `horizon`: how far ahead to look, s (default MINE_WARN_TIME); `prefer`: the last
 * warning (a mine's index and the side told), whose side is kept for that mine while the hull can
 * still make it (or can make neither) and it runs into no other mine, so the warning does not flip
 * as the hull turns to it; `heaving`: Dive or Rise is held (default false); `heave`: the share of
 * the helm's dive or climb speed that the held Dive or Rise asks for, in (0, 1] (default 1; a key
 * asks for ./helm.ts keyHeaveShare, 0.5 at rest to 0.8 at full speed), so the warning foresees the
 * dive the boat really makes: a course that took a key's dive at the full 10 m/s would run under a
 * mine that the boat, diving at 5 to 8 m/s, meets, and the warning would come only at the mine.
 * @throws RangeError when x, y, vx or vy is not finite, `horizon` is not positive or `heave` is not in (0, 1].
 */
export function mineAhead(
  x: number,
  y: number,
  vx: number,
  vy: number,
  holdY: number,
  mines: readonly Mine[],
  live: readonly boolean[],
  seabed: SubmarineHandles['seabed'],
  options: {
    readonly horizon?: number;
    readonly prefer?: { readonly index: number; readonly side: 'over' | 'under' } | null;
    readonly heaving?: boolean;
    readonly heave?: number;
  } = {},
): MineAhead | null {
  const horizon = options.horizon ?? MINE_WARN_TIME;
  const share = options.heave ?? 1;
  if (!(share > 0 && share <= 1)) throw new RangeError(`mineAhead: options.heave must be in (0, 1], got ${share}`);
  for (const [name, v] of [
    ['x', x],
    ['y', y],
    ['vx', vx],
    ['vy', vy],
  ] as const)
    assertFinite('mineAhead', name, v);
  assertPositive('mineAhead', 'horizon', horizon);
  const u = Math.abs(vx) >= 2 ? vx : vx < -0.3 ? -2 : 2;
  const reach = MINE_RADIUS + MINE_WARN_MARGIN;
  const dt = 0.05;
  /** The first live mine but `skip` that a level hull at (hx, hy) comes within `reach` of, -1 for none. */
  const touching = (hx: number, hy: number, skip: number): number => {
    for (let i = 0; i < mines.length; i++) {
      const m = mines[i]!;
      if (i === skip || !live[i] || Math.abs(m.x - hx) > SUBMARINE.length / 2 + reach) continue;
      if (hullDistance(hx, hy, 0, m.x, m.y) < reach) return i;
    }
    return -1;
  };
  let found = -1;
  /**
   * Whether rising (`dir` 1) or diving (-1) flat out from now to the depth `to` (m, the hull's
   * centre) and holding it until the hull is past mine `found`, and MINE_REACTION s more, runs it
   * into another live mine or takes its keel within MINE_WARN_MARGIN of the seabed.
   */
  const blocked = (dir: number, to: number): boolean => {
    const m = mines[found]!,
      pass = (Math.abs(m.x - x) + SUBMARINE.length / 2 + reach) / Math.abs(u) + MINE_REACTION;
    for (let t = dt; t <= pass; t += dt) {
      const rise = dir * heave(dir * vy, dir > 0 ? HELM.climbSpeed : HELM.diveSpeed, t);
      const hx = x + u * t,
        hy = Math.min(0, dir > 0 ? Math.min(Math.max(y, to), y + rise) : Math.max(Math.min(y, to), y + rise));
      if (touching(hx, hy, found) >= 0) return true;
      if (dir < 0 && hy - SUBMARINE.height / 2 - MINE_WARN_MARGIN < seabedHeight(seabed, hx)) return true;
    }
    return false;
  };
  // The courses: on toward the order, and on at the vertical speed while Dive or Rise is held (or
  // no depth is ordered); the first contact on either counts.
  const toOrder = !Number.isNaN(holdY),
    onAsGoing = options.heaving === true || !toOrder;
  for (let t = dt; t <= horizon + 1e-9; t += dt) {
    const cx = x + u * t;
    found = -1;
    let cy = y;
    if (toOrder) {
      cy = Math.min(0, y + Math.max(-HELM.diveSpeed * t, Math.min(HELM.climbSpeed * t, holdY - y)));
      found = touching(cx, cy, -1);
    }
    if (found < 0 && onAsGoing) {
      // Held on: speeding up (or slowing) to the share asked of the helm's climb or dive speed the
      // way it goes (HELM.brake).
      const on = !options.heaving ? vy * t : vy >= 0 ? heave(vy, share * HELM.climbSpeed, t) : -heave(-vy, share * HELM.diveSpeed, t);
      cy = Math.min(0, y + on);
      found = touching(cx, cy, -1);
    }
    if (found >= 0) {
      const i = found,
        m = mines[i]!;
      // Over: the hull's centre MINE_RADIUS + half its height + the margin over the mine's; under:
      // as far under it, with the keel a margin over the seabed there (under the hull's length).
      const overY = m.y + MINE_RADIUS + SUBMARINE.height / 2 + MINE_WARN_MARGIN,
        underY = m.y - MINE_RADIUS - SUBMARINE.height / 2 - MINE_WARN_MARGIN;
      let bed = -Infinity;
      for (let k = -1; k <= 1; k++) bed = Math.max(bed, seabedHeight(seabed, m.x + (k * SUBMARINE.length) / 2));
      const roomUnder = underY - SUBMARINE.height / 2 - MINE_WARN_MARGIN > bed;
      // The side the hull can clear sooner, rising or diving flat out from its vertical speed now
      // (a boat diving fast cannot turn back up over a mine just below it in time, but can dive on
      // under it), and not into another mine or the bed on the way: its time to spare (s) before it
      // gets there, -Infinity where the way is blocked.
      const spareOver = blocked(1, overY) ? -Infinity : t - heaveTime(vy, HELM.climbSpeed, overY - y),
        spareUnder = !roomUnder || blocked(-1, underY) ? -Infinity : t - heaveTime(-vy, HELM.diveSpeed, y - underY);
      let side: 'over' | 'under' = spareUnder > spareOver ? 'under' : 'over';
      // The side told before for this mine (`options.prefer`) stays while it can still be made, or
      // neither can, and its way is not blocked.
      const prefer = options.prefer?.index === i ? options.prefer.side : null;
      const kept = prefer === 'over' ? spareOver : prefer === 'under' ? spareUnder : Number.NaN;
      if (prefer && kept > -Infinity && (kept >= 0 || Math.max(spareOver, spareUnder) < 0)) side = prefer;
      return { index: i, side, time: t };
    }
  }
  return null;
}

/**
 * How far a boat rises in `t` s (m; negative: it sinks) rising from a vertical speed `v` (m/s, up)
 * at the helm's speed asked for, `most` (m/s), reached at HELM.brake (m/s^2): speeding up to it, or
 * slowing to it from a faster `v`.
 */
function heave(v: number, most: number, t: number): number {
  const a = most >= v ? HELM.brake : -HELM.brake,
    t1 = Math.min(t, (most - v) / a);
  return v * t1 + 0.5 * a * t1 * t1 + most * (t - t1);
}

/** How long a boat rising flat out as `heave` takes to rise `d` m (0 if d <= 0; s). */
function heaveTime(v: number, most: number, d: number): number {
  if (d <= 0) return 0;
  const a = HELM.brake,
    t1 = Math.max(0, (most - v) / a);
  // Still speeding up: v t + a t^2 / 2 = d; else at `most` after the first t1 s.
  const first = heave(v, most, t1);
  return d <= first ? (-v + Math.sqrt(v * v + 2 * a * d)) / a : t1 + (d - first) / most;
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
 * What a steady pilot on the keys takes for a leg of the course (scripts/submarine-pilot.mjs: full
 * ahead, letting go or braking with Astern to reach the beacon's x as it reaches its depth, Dive /
 * Rise held at the keys' steady share, passing the mines as warned), fitted to its times on the 60
 * courses it won of seeds 1 to 30 with 6 and 10 beacons (each within 7 % of it): the longer of the
 * run ahead at `ahead` m/s (under the boat's top speed, helm.ts HELM.topSpeed) and the depth change
 * at `depth` m/s, plus `perBeacon` s.
 */
export const PILOT_LEG = Object.freeze({ ahead: 7.3, depth: 5, perBeacon: 0.5 });
/**
 * Par over the steady pilot's time: a newcomer who has to find the beacons, learn the helm and pass
 * the mines takes longer than a pilot that knows the way (the pilot itself is at most 1.07 times its
 * fitted time, so par is at least 1.49 times what it took on every course).
 */
export const PAR_MARGIN = 1.6;

/**
 * The course's par time, s: `PAR_MARGIN` times the steady pilot's time (`PILOT_LEG`) along the
 * course from the start (0, 0) through every beacon in `courseOrder`, rounded up to 5 s.
 */
export function parTime(beacons: ArrayLike<number>): number {
  let x = 0,
    y = 0,
    t = 0;
  for (const i of courseOrder(beacons)) {
    const bx = beacons[2 * i]!,
      by = beacons[2 * i + 1]!;
    t += Math.max(Math.abs(bx - x) / PILOT_LEG.ahead, Math.abs(by - y) / PILOT_LEG.depth) + PILOT_LEG.perBeacon;
    x = bx;
    y = by;
  }
  return Math.ceil((PAR_MARGIN * t) / 5) * 5;
}
