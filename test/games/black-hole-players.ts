/**
 * Scripted players of black hole's levels (games/black-hole/levels.ts), for the difficulty curve
 * (test/games/black-hole-curve.test.ts and scripts/black-hole-curve.mjs): players who fly by eye, as a
 * stranger does, not by the predicted path. Each plans a way up that gives every hole a berth of some
 * horizon radii (`planRoute`), then steers along it with a bounded reaction: a choice of arrow every
 * `react` s (each interval drawn within 25 % of it), pressed `lag` s after the look it was based on.
 * Their skill is in those numbers (`PLAYERS`). A fall starts a new try on the same layout; the
 * jittered reactions make each try different, so a level's share of tries that clear is a rate, not
 * a yes or no.
 */
import { Rng, slotOf } from '@bitphysics/physics';
import { canThrust, type LevelRun, startLevel, stepLevel } from '../../games/black-hole/levels';
import {
  type BlackHoleGame,
  createBlackHoleGame,
  type FieldSize,
  SHIP_RADIUS,
  setThrust,
  THRUST_DIRECTION,
  type Thrust,
} from '../../games/black-hole/rules';

/** How a player flies: s between choices, s from a look to its press, radii of berth, m/s aimed for. */
export interface PlayerStyle {
  /** Mean time between two choices of arrow, s (> 0). */
  readonly react: number;
  /** Time from the look a choice is based on to its press, s (>= 0): a player's reaction. */
  readonly lag: number;
  /** Berth the route gives a hole: this many horizon radii plus the ship's size and 0.5 m from its centre. */
  readonly keep: number;
  /** Speed along the route the player steers for, m/s (> 0). */
  readonly speed: number;
}

/** Three players: a practised one, a middling stranger and a slow thumb on a phone. */
export const PLAYERS: Readonly<Record<'sharp' | 'middle' | 'slow', PlayerStyle>> = Object.freeze({
  sharp: Object.freeze({ react: 0.2, lag: 0.2, keep: 2, speed: 5 }),
  middle: Object.freeze({ react: 0.3, lag: 0.35, keep: 2.2, speed: 4 }),
  slow: Object.freeze({ react: 0.4, lag: 0.5, keep: 2.6, speed: 3 }),
});

/**
 * A way from `from` (m; default the ship's start) to the finish line, or to `to` (m) when given, that
 * keeps `margin(r)` m from each hole's centre (r its horizon radius, m) and prefers open field, as a
 * player picks one by eye: the cheapest path on a 0.5 m grid (8 neighbours; a cell is closed within the
 * margin of a hole or 0.5 m of a side), each move costing its length times 1 + 4 / (1 + the cell's
 * clearance beyond the margin, m). The way ends at the first cell on the line's row, or within 0.5 m
 * of `to` (then at `to` itself).
 * @returns the cells' centres from the start to the end, m (x, y pairs); empty when none reaches it.
 */
export function planRoute(
  g: BlackHoleGame,
  margin: (r: number) => number,
  from: readonly [number, number] = g.start,
  to?: readonly [number, number],
): [number, number][] {
  const cell = 0.5,
    nx = Math.floor(g.field.width / cell),
    ny = Math.ceil(g.lineY / cell) + 1;
  const P = g.world.components.Position;
  const hs = g.holes.map((h, i) => [P.x[slotOf(h)]!, P.y[slotOf(h)]!, margin(g.holeRadius[i]!)] as const);
  const weight = new Float64Array(nx * ny);
  for (let j = 0; j < ny; j++)
    for (let i = 0; i < nx; i++) {
      const x = (i + 0.5) * cell,
        y = j * cell;
      let clear = Math.min(x - 0.5, g.field.width - 0.5 - x) + 2;
      for (const [hx, hy, r] of hs) clear = Math.min(clear, Math.hypot(x - hx, y - hy) - r);
      weight[j * nx + i] = clear > 0 ? 1 + 4 / (1 + clear) : Number.POSITIVE_INFINITY;
    }
  const cellOf = (p: readonly [number, number]): number =>
    Math.max(0, Math.min(ny - 1, Math.round(p[1] / cell))) * nx + Math.max(0, Math.min(nx - 1, Math.floor(p[0] / cell)));
  const startCell = cellOf(from),
    goal = to ? cellOf(to) : -1;
  if (goal >= 0) weight[goal] = 1;
  weight[startCell] = 1;
  const cost = new Float64Array(nx * ny).fill(Number.POSITIVE_INFINITY),
    prev = new Int32Array(nx * ny).fill(-1),
    done = new Uint8Array(nx * ny);
  cost[startCell] = 0;
  // Dijkstra with a plain scan of an open list: the grid is small (about 3000 cells).
  const open = [startCell];
  let end = -1;
  while (open.length > 0) {
    let bi = 0;
    for (let k = 1; k < open.length; k++) if (cost[open[k]!]! < cost[open[bi]!]!) bi = k;
    const c = open[bi]!;
    open[bi] = open[open.length - 1]!;
    open.pop();
    if (done[c]) continue;
    done[c] = 1;
    const i = c % nx,
      j = (c - i) / nx;
    if (goal >= 0 ? c === goal : j === ny - 1) {
      end = c;
      break;
    }
    for (let di = -1; di <= 1; di++)
      for (let dj = -1; dj <= 1; dj++) {
        const a = i + di,
          b = j + dj;
        if ((di === 0 && dj === 0) || a < 0 || a >= nx || b < 0 || b >= ny) continue;
        const d = b * nx + a;
        if (done[d] || weight[d] === Number.POSITIVE_INFINITY) continue;
        const next = cost[c]! + cell * Math.hypot(di, dj) * weight[d]!;
        if (next < cost[d]!) {
          cost[d] = next;
          prev[d] = c;
          open.push(d);
        }
      }
  }
  if (end < 0) return [];
  const cells: number[] = [];
  for (let c = end; c !== startCell; c = prev[c]!) cells.push(c);
  cells.reverse();
  const way = cells.map((c): [number, number] => [((c % nx) + 0.5) * cell, Math.floor(c / nx) * cell]);
  if (to && way.length > 0) way[way.length - 1] = [to[0], to[1]];
  return way;
}

/**
 * The way a player takes now on a level with rings (games/black-hole/levels.ts `LevelSpec.rings`):
 * `planRoute` from the start, or from the ring last taken, to the next ring, or to the line when every
 * ring is taken. The player follows it to its end and plans the next leg when the ring is taken.
 */
export function planLeg(g: BlackHoleGame, run: LevelRun, margin: (r: number) => number): [number, number][] {
  const from = run.ringsTaken > 0 ? run.rings[run.ringsTaken - 1]! : g.start;
  return planRoute(g, margin, from, run.rings[run.ringsTaken]);
}

/** How a level went for a player: tries (each fall or exit ends one), whether and when it cleared. */
export interface LevelOutcome {
  /** Whether the line was reached within the time allowed. */
  readonly cleared: boolean;
  /** Tries taken: falls and exits, plus the clearing one. */
  readonly tries: number;
  /** Falls into a hole. */
  readonly falls: number;
  /** Time of the clearing try, s (NaN when not cleared). */
  readonly time: number;
  /** Time from the level's start to the line, all tries, s (NaN when not cleared). */
  readonly totalTime: number;
}

/**
 * How a player slows nearing a ring: at most RING_EASE[0] + RING_EASE[1] x the distance to its centre,
 * m/s (2.5 m/s passing through it, the style's speed from some 3 m out), so the turn to the next ring
 * is not taken at full speed.
 */
export const RING_EASE: readonly [number, number] = Object.freeze([1.5, 0.8]);

const ARROWS: readonly Thrust[] = ['up', 'down', 'left', 'right', 'up-left', 'up-right', 'down-left', 'down-right'];

/**
 * Plays level `level` of a game of seed `seed` on a `field` (m; default the game's 32 x 24) in the
 * given style, for at most `limit` s of game time, lives never running out. Each choice finds the
 * ship where it will be when the press lands (position and velocity carried on `lag` s), the point of
 * the route about 3 m past the nearest one, and presses the arrow or pair (or none, within 0.6 m/s)
 * that best turns the velocity towards `style.speed` m/s at that point (less nearing a ring: `RING_EASE`). Drifting holes are planned
 * round anew at each choice; still ones at the start and after each fall or exit. The interval to the
 * next choice is drawn in [0.75, 1.25] x react from an Rng seeded with `seed`.
 * @throws RangeError unless limit > 0 and the style's numbers are in range.
 */
export function playLevel(level: number, seed: number, style: PlayerStyle, limit = 60, field?: FieldSize): LevelOutcome {
  if (!(limit > 0 && style.react > 0 && style.lag >= 0 && style.keep >= 0 && style.speed > 0))
    throw new RangeError(`playLevel: limit, react and speed must be > 0 and lag, keep >= 0, got ${limit}, ${JSON.stringify(style)}`);
  const g = createBlackHoleGame({ seed, lives: 9, ...(field ? { field } : {}) });
  const run: LevelRun = startLevel(g, level);
  const dt = g.world.dt,
    rng = new Rng(seed * 7919 + level),
    lagSteps = Math.round(style.lag / dt);
  const margin = (r: number): number => style.keep * r + SHIP_RADIUS + 0.5;
  const P = g.world.components.Position,
    V = g.world.components.Velocity;
  let way = planLeg(g, run, margin),
    leg = run.ringsTaken;
  const pending: { at: number; thrust: Thrust }[] = [];
  let chosen: Thrust = 'none',
    nextLook = 0,
    tries = 1;
  for (let k = 0; k * dt < limit; k++) {
    if (k >= nextLook && canThrust(g, run)) {
      nextLook = k + Math.max(1, Math.round((style.react * rng.range(0.75, 1.25)) / dt));
      if (run.spec.drift > 0 || leg !== run.ringsTaken) [way, leg] = [planLeg(g, run, margin), run.ringsTaken];
      const s = slotOf(g.ship),
        lag = style.lag;
      const vx = V.x[s]! + g.thrustVec[0] * lag,
        vy = V.y[s]! + g.thrustVec[1] * lag,
        x = P.x[s]! + V.x[s]! * lag,
        y = P.y[s]! + V.y[s]! * lag;
      let near = 0;
      for (let i = 1; i < way.length; i++)
        if (Math.hypot(way[i]![0] - x, way[i]![1] - y) < Math.hypot(way[near]![0] - x, way[near]![1] - y)) near = i;
      let aim = near;
      for (let along = 0; aim + 1 < way.length && along < 3; aim++)
        along += Math.hypot(way[aim + 1]![0] - way[aim]![0], way[aim + 1]![1] - way[aim]![1]);
      const [ax, ay] = way.length > 0 ? way[aim]! : (run.rings[run.ringsTaken] ?? [x, g.lineY]);
      const d = Math.hypot(ax - x, ay - y) || 1;
      // Nearing a ring the player eases off (to turn for the next one): RING_EASE.
      const ring = run.rings[run.ringsTaken];
      const speed = ring ? Math.min(style.speed, RING_EASE[0] + RING_EASE[1] * Math.hypot(ring[0] - x, ring[1] - y)) : style.speed;
      const ex = (speed * (ax - x)) / d - vx,
        ey = (speed * (ay - y)) / d - vy,
        e = Math.hypot(ex, ey);
      let want: Thrust = 'none',
        best = Number.NEGATIVE_INFINITY;
      if (e > 0.6)
        for (const t of ARROWS) {
          const dot = THRUST_DIRECTION[t][0] * ex + THRUST_DIRECTION[t][1] * ey;
          if (dot > best) [best, want] = [dot, t];
        }
      pending.push({ at: k + lagSteps, thrust: want });
    }
    while (pending.length > 0 && pending[0]!.at <= k) chosen = pending.shift()!.thrust;
    const want = canThrust(g, run) ? chosen : 'none';
    if (g.thrust !== want) setThrust(g, want);
    const event = stepLevel(g, run);
    if (event === 'cleared') {
      const s = run.summary!;
      return { cleared: true, tries, falls: s.falls, time: s.time, totalTime: s.totalTime };
    }
    if (event === 'fell' || event === 'lost') {
      // The page lets go of every arrow after a fall or an exit; the player looks again and replans.
      tries++;
      pending.length = 0;
      chosen = 'none';
      nextLook = k + 1;
      [way, leg] = [planLeg(g, run, margin), run.ringsTaken];
    }
    if (g.lives < 3) g.lives = 9;
  }
  return { cleared: false, tries, falls: g.falls, time: Number.NaN, totalTime: Number.NaN };
}

/** A level's figures over seeds for one player. */
export interface LevelFigures {
  readonly level: number;
  /** Seeds cleared within the time allowed, of `seeds`. */
  readonly cleared: number;
  readonly seeds: number;
  /** Share of all tries that cleared, in [0, 1]. */
  readonly rate: number;
  /** Tries each seed took (the last one cleared, unless the time ran out), seeds 1 to `seeds` in order. */
  readonly tries: readonly number[];
  /**
   * Mean over the seeds of 1 / tries (0 for a seed not cleared), in [0, 1]: the chance that a try
   * clears, each layout counted once (one layout failed thirty times does not outweigh the rest).
   */
  readonly success: number;
  /** Mean time of the clearing try, s, and mean time to the line with the failed tries, s (NaN when none cleared). */
  readonly time: number;
  readonly totalTime: number;
}

/**
 * `playLevel` on seeds 1 to `seeds` of level `level`: seeds cleared, the share of tries that cleared
 * and the mean times of the clears.
 */
export function levelFigures(level: number, style: PlayerStyle, seeds: number, limit = 60, field?: FieldSize): LevelFigures {
  let cleared = 0,
    tries = 0,
    time = 0,
    totalTime = 0,
    success = 0;
  const each: number[] = [];
  for (let seed = 1; seed <= seeds; seed++) {
    const o = playLevel(level, seed, style, limit, field);
    tries += o.cleared ? o.tries : o.tries - 1;
    each.push(o.tries);
    if (!o.cleared) continue;
    success += 1 / o.tries;
    cleared++;
    time += o.time;
    totalTime += o.totalTime;
  }
  return {
    level,
    cleared,
    seeds,
    rate: cleared / Math.max(1, tries),
    tries: each,
    success: success / seeds,
    time: cleared ? time / cleared : Number.NaN,
    totalTime: cleared ? totalTime / cleared : Number.NaN,
  };
}

/** How a single hold (`singleHold`) ended: 'cleared' reached the line, 'fell', 'lost' (left the field) or 'timeout'. */
export type HoldEnd = 'cleared' | 'fell' | 'lost' | 'timeout';

/**
 * The one-hold player the strangers found clears late levels with the predicted path shown: on level
 * `level` of a game of seed `seed` on `field` (default the game's 32 x 24 m), ↑ pressed `wait` s
 * after the level began (the holes drift meanwhile: a player waits for the path to turn blue), held
 * `hold` s (> 0) and let go, then nothing else pressed, the game stepped (`stepLevel`) until the
 * line is crossed, the ship falls in or leaves the field, or `limit` s of game time pass. `rings`
 * false takes the level's rings away (games/black-hole/levels.ts `LevelSpec.rings`), so the line
 * counts at once: the hold then meets the holes alone.
 * @throws RangeError unless hold > 0 and limit > hold.
 */
export function singleHold(level: number, seed: number, hold: number, field?: FieldSize, wait = 0, limit = 20, rings = true): HoldEnd {
  return flyHold(level, seed, hold, field, wait, limit, rings).end;
}

/** @throws RangeError unless hold > 0, wait >= 0 and limit > wait + hold (`singleHold`'s arguments). */
function checkHold(hold: number, wait: number, limit: number): void {
  if (!(hold > 0 && wait >= 0 && limit > wait + hold))
    throw new RangeError(`singleHold: hold must be > 0 s, wait >= 0 s and limit > wait + hold, got ${hold}, ${wait}, ${limit}`);
}

/** `singleHold`'s flight: how it ended, the loop step it ended at (`end` 'timeout': the last), and the game's step, s. */
function flyHold(
  level: number,
  seed: number,
  hold: number,
  field: FieldSize | undefined,
  wait: number,
  limit: number,
  rings: boolean,
): { end: HoldEnd; at: number; dt: number } {
  checkHold(hold, wait, limit);
  const g = createBlackHoleGame({ seed, lives: 9, ...(field ? { field } : {}) });
  const run = startLevel(g, level);
  if (!rings) run.rings.length = 0;
  const dt = g.world.dt;
  const from = Math.round(wait / dt),
    to = from + Math.round(hold / dt);
  let k = 0;
  for (; k * dt < limit; k++) {
    const want: Thrust = k >= from && k < to && canThrust(g, run) ? 'up' : 'none';
    if (g.thrust !== want) setThrust(g, want);
    const event = stepLevel(g, run);
    if (event === 'cleared') return { end: 'cleared', at: k, dt };
    if (event === 'fell' || event === 'over') return { end: 'fell', at: k, dt };
    if (event === 'lost') return { end: 'lost', at: k, dt };
  }
  return { end: 'timeout', at: k, dt };
}

/**
 * `singleHold` for each of `holds` (s, each > 0) on one level, seed, field and wait, flying fewer
 * games: two flights get the same inputs from the same start until the shorter hold lets go, and the
 * steps are deterministic, so where a longer hold's flight ended (a fall, the line) at a step while
 * ↑ was still held in a shorter one, the shorter one ends the same way at that step and is not flown.
 * The holds are flown longest first; the answers are in the order of `holds`.
 * @throws RangeError as `singleHold` does.
 */
export function singleHolds(
  level: number,
  seed: number,
  holds: readonly number[],
  field?: FieldSize,
  wait = 0,
  limit = 20,
  rings = true,
): HoldEnd[] {
  for (const hold of holds) checkHold(hold, wait, limit);
  const out: HoldEnd[] = new Array(holds.length);
  const order = holds.map((_, i) => i).sort((a, b) => holds[b]! - holds[a]!);
  // The earliest end among the flights flown so far (all of holds as long as the next or longer).
  let first: { end: HoldEnd; at: number; dt: number } | null = null;
  for (const i of order) {
    const hold = holds[i]!;
    // The first step without ↑ in this flight, as `flyHold` counts it.
    const to = first === null ? 0 : Math.round(wait / first.dt) + Math.round(hold / first.dt);
    if (first !== null && first.at < to) {
      out[i] = first.end;
      continue;
    }
    const f = flyHold(level, seed, hold, field, wait, limit, rings);
    out[i] = f.end;
    if (first === null || f.at < first.at) first = f;
  }
  return out;
}
