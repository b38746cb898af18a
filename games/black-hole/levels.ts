/**
 * Levels for black hole, DOM-free (Node tests run them): a first level a newcomer wins, then holes
 * across the straight path up (the player must steer), more and bigger holes, holes that drift, and
 * a fuel limit. Each cleared level gives a lost life back (up to the starting three). The ship waits at the start until the player thrusts. The page (main.ts) shows the level, the fuel, an
 * end-of-level summary and the best score.
 *
 * A level is a `LevelSpec` (`levelSpec(n)`); `startLevel` lays its holes out in a game made by
 * `createBlackHoleGame` (./rules), and `stepLevel` runs one step of it: the holes drift, the fuel
 * burns while thrusting, then the game's own step (./rules `stepBlackHole`: pull, horizons, lives).
 * Crossing the line clears the level: the step returns 'cleared', `run.summary` says how it went, the
 * field is emptied and the run waits (no steps) until `beginLevel` lays out the next level's holes, so
 * nothing appears on the field while the ship waits.
 *
 * Holes keep M = c^2 r / (2 G) (their drawn radius is their Schwarzschild radius, as in ./rules).
 * Drifting holes move sideways at a constant speed and turn back at the field's edges; they are moved
 * between steps (kinematic), so their pull follows them.
 */
import { addBody, removeBody, setAttractor, setPosition, setVelocity, slotOf } from '@bitphysics/physics';
import {
  type BlackHoleEvent,
  type BlackHoleGame,
  gravitationalConstant,
  LINE_Y,
  MAX_HOLES,
  resetShip,
  schwarzschildMass,
  setThrust,
  stepBlackHole,
} from './rules';

/** What a level asks of the player. */
export interface LevelSpec {
  /** Level number, integer >= 1. */
  readonly level: number;
  /** Holes, integer in [1, MAX_HOLES]. */
  readonly holes: number;
  /** Range of the holes' horizon radii, m. */
  readonly radius: readonly [number, number];
  /** Half-width, m, of a corridor around the start's x (the field's middle) that no hole's centre enters (0: none). Blockers excepted. */
  readonly corridor: number;
  /**
   * Holes laid across the straight path up (integer in [0, 2], at most `holes`): each one's centre is
   * within half its radius of the start's x, at a height of its own, so holding thrust up falls in.
   */
  readonly blockers: number;
  /** Sideways speed of the holes, m/s (0: they stay put). */
  readonly drift: number;
  /** Seconds of thrust the tank holds (Infinity: no limit). */
  readonly fuel: number;
}

/**
 * The spec of level `level`, one new difficulty at a time: level 1 one small hole across the
 * straight path up (holding thrust up falls in; a nudge sideways passes it); level 2 a second hole
 * off that path; level 3 a third hole; level 4 two holes across the path, one above the other;
 * level 5 a fourth hole; from level 6 the holes drift, slowly at first (0.35, then 0.6, 0.8 m/s);
 * from level 8 the fuel is limited (18 s, then 15 s down to 5 s); from level 9 a fifth hole, then a
 * hole more every second level (up to MAX_HOLES), bigger (radius up to 2 m) and faster (up to 3 m/s).
 * @throws RangeError unless level is an integer >= 1.
 */
export function levelSpec(level: number): LevelSpec {
  if (!Number.isInteger(level) || level < 1) throw new RangeError(`levelSpec: level must be an integer >= 1, got ${level}`);
  const spec = (holes: number, radius: [number, number], corridor: number, blockers: number, drift: number, fuel: number): LevelSpec =>
    Object.freeze({ level, holes, radius: Object.freeze(radius) as readonly [number, number], corridor, blockers, drift, fuel });
  switch (level) {
    case 1:
      return spec(1, [0.55, 0.7], 9, 1, 0, Infinity);
    case 2:
      return spec(2, [0.55, 0.9], 6, 1, 0, Infinity);
    case 3:
      return spec(3, [0.55, 1.0], 3, 1, 0, Infinity);
    case 4:
      return spec(3, [0.6, 1.1], 0, 2, 0, Infinity);
    case 5:
      return spec(4, [0.6, 1.1], 0, 2, 0, Infinity);
    case 6:
      return spec(4, [0.6, 1.2], 0, 2, 0.35, Infinity);
    case 7:
      return spec(4, [0.6, 1.2], 0, 2, 0.6, Infinity);
    case 8:
      return spec(4, [0.6, 1.3], 0, 2, 0.8, 18);
    default: {
      const k = level - 9;
      return spec(
        Math.min(MAX_HOLES, 5 + Math.floor(k / 2)),
        [0.6, Math.min(2, 1.35 + 0.07 * k)],
        0,
        2,
        Math.min(3, 1 + 0.2 * k),
        Math.max(5, 15 - k),
      );
    }
  }
}

/** How a cleared level went (shown at the end of the level). */
export interface LevelSummary {
  /** The level cleared. */
  readonly level: number;
  /** Time of the winning attempt, s: from the last start (first thrust after the level began, a fall or an exit) to the line. */
  readonly time: number;
  /** Time from the level's start to the line, failed attempts included, s. */
  readonly totalTime: number;
  /** Lives after the clear (a cleared level gives one back, up to the starting lives). */
  readonly lives: number;
  /** Points it scored (one per hole). */
  readonly points: number;
  /** Fuel left, s of thrust (Infinity when unlimited). */
  readonly fuelLeft: number;
  /** Times the ship fell in during the level. */
  readonly falls: number;
}

/** A game played in levels. */
export interface LevelRun {
  /** The level being played (or, while `waiting`, the next one, laid out when it begins). */
  spec: LevelSpec;
  /** Seconds since the level began. */
  time: number;
  /** Fuel left, s of thrust (Infinity when unlimited). */
  fuelLeft: number;
  /** Sideways velocity of each hole, m/s (same order as game.holes). */
  readonly holeVx: number[];
  /** Between levels (after a clear, before `beginLevel`): steps do nothing. */
  waiting: boolean;
  /** The last cleared level's summary, or null. */
  summary: LevelSummary | null;
  /** Falls counted at the level's start (to report the level's own). */
  fallsAtStart: number;
  /** `time` when the current attempt began (the first thrust after the level's start, a fall or an exit), s. */
  attemptStart: number;
  /**
   * The ship waits at the start, held at rest, until the player thrusts: set when a level begins and
   * after each fall or exit, so a hole's pull (or a hole drifting near) cannot take a life before the
   * player has moved.
   */
  parked: boolean;
}

/**
 * Lays out level `level` in `game` (holes per `levelSpec`, the ship at the start, the fuel full) and
 * returns its run, not waiting. The layout comes from the game's seeded generator.
 * @throws RangeError on a bad level.
 */
export function startLevel(game: BlackHoleGame, level: number): LevelRun {
  const run: LevelRun = {
    spec: levelSpec(level),
    time: 0,
    fuelLeft: 0,
    holeVx: [],
    waiting: false,
    summary: null,
    fallsAtStart: 0,
    attemptStart: 0,
    parked: true,
  };
  layLevel(game, run, level);
  return run;
}

/**
 * Starts the level a cleared run is waiting on: lays out its holes (the field stays empty while
 * waiting), the ship parked at the start, the clock at 0, the fuel full. No effect unless waiting.
 */
export function beginLevel(game: BlackHoleGame, run: LevelRun): void {
  if (!run.waiting) return;
  run.waiting = false;
  layLevel(game, run, run.spec.level);
}

/** The opening line of a level. */
export function levelMessage(spec: LevelSpec): string {
  const parts = [`Level ${spec.level}: reach the green line.`];
  if (spec.drift > 0) parts.push('The holes drift.');
  if (Number.isFinite(spec.fuel)) parts.push(`${spec.fuel} s of fuel.`);
  return parts.join(' ');
}

function layLevel(game: BlackHoleGame, run: LevelRun, level: number): void {
  const spec = levelSpec(level);
  run.spec = spec;
  run.time = 0;
  run.attemptStart = 0;
  run.fuelLeft = spec.fuel;
  run.fallsAtStart = game.falls;
  const world = game.world;
  clearHoles(game, run);
  const rng = game.rng;
  const G = gravitationalConstant(game),
    c = game.params.c;
  const [r0, r1] = spec.radius;
  for (let k = 0; k < spec.holes; k++) {
    let bestX = 0,
      bestY = 0,
      bestR = r0,
      bestGap = -Infinity;
    for (let attempt = 0; attempt < 300; attempt++) {
      const r = rng.range(r0, r1);
      let x: number, y: number;
      if (k < spec.blockers) {
        // Across the straight path up, one blocker in each band of heights (lower band first).
        // Bands measured on the 22 m climb of the default field, scaled to this field's.
        const s = game.lineY / LINE_Y;
        x = game.start[0] + rng.range(-0.5, 0.5) * r;
        const [lo, hi] = spec.blockers === 1 ? [9, 15] : k === 0 ? [7.5, 10.5] : [14, 17];
        y = rng.range(lo * s, hi * s);
      } else {
        const W = game.field.width;
        x = rng.range(1.5 + r, W - 1.5 - r);
        if (spec.corridor > 0) {
          // Outside the corridor: on the side the draw fell on.
          const side = x < game.start[0] ? -1 : 1;
          const lo = game.start[0] + spec.corridor,
            hi = W - 1.5 - r;
          x = side > 0 ? Math.max(x, lo) : Math.min(x, W - lo);
          if (lo > hi) x = side > 0 ? hi : W - hi;
        }
        y = rng.range(5 + r, game.lineY - 3 - r);
      }
      let gap = Math.hypot(x - game.start[0], y - game.start[1]) - r - 4;
      for (let j = 0; j < game.holes.length; j++) {
        const h = game.holes[j]!;
        const P = world.components.Position;
        gap = Math.min(gap, Math.hypot(x - P.x[slotOf(h)]!, y - P.y[slotOf(h)]!) - r - game.holeRadius[j]! - 3);
      }
      if (gap > bestGap) {
        bestGap = gap;
        bestX = x;
        bestY = y;
        bestR = r;
      }
      if (gap >= 0) break;
    }
    const mass = schwarzschildMass(bestR, c, G);
    const e = addBody(world, { position: [bestX, bestY], static: true });
    setAttractor(world, e, { mass });
    game.holes.push(e);
    game.holeRadius.push(bestR);
    game.holeMass.push(mass);
    run.holeVx.push(spec.drift * (rng.range(0, 1) < 0.5 ? -1 : 1));
  }
  game.version++;
  game.message = levelMessage(spec);
  run.parked = true;
  resetShip(game);
}

/** Removes every hole from the field (and its drift speed). */
function clearHoles(game: BlackHoleGame, run: LevelRun): void {
  for (const h of game.holes) removeBody(game.world, h);
  game.holes.length = 0;
  game.holeRadius.length = 0;
  game.holeMass.length = 0;
  run.holeVx.length = 0;
  game.version++;
}

/** Moves drifting holes by one step (dt s), turning them back at the field's edges. */
function driftHoles(game: BlackHoleGame, run: LevelRun, dt: number): void {
  if (run.spec.drift === 0) return;
  const P = game.world.components.Position;
  const at: [number, number] = [0, 0];
  for (let i = 0; i < game.holes.length; i++) {
    const h = game.holes[i]!,
      r = game.holeRadius[i]!;
    // Holes laid out by other means (the page's holes slider) have no speed: they stay put.
    const vx = run.holeVx[i] ?? 0;
    if (vx === 0) continue;
    let x = P.x[slotOf(h)]! + vx * dt;
    const lo = 1.5 + r,
      hi = game.field.width - 1.5 - r;
    if (x < lo) {
      x = 2 * lo - x;
      run.holeVx[i] = Math.abs(run.holeVx[i]!);
    }
    if (x > hi) {
      x = 2 * hi - x;
      run.holeVx[i] = -Math.abs(run.holeVx[i]!);
    }
    at[0] = x;
    at[1] = P.y[slotOf(h)]!;
    setPosition(game.world, h, at);
  }
  game.version++;
}

/**
 * One step of a level: nothing while waiting; else the holes drift, the fuel burns while thrusting
 * (at zero the thrust stops and stays off), the game steps (./rules `stepBlackHole`), and a parked
 * ship (see `LevelRun.parked`) is put back at the start at rest. A crossing of
 * the line becomes 'cleared': a lost life comes back, the summary is kept, the field is emptied (the
 * next level is laid out by `beginLevel`) and the run waits with the ship at the start.
 * @returns the game's event, with 'scored' reported as 'cleared', or 'waiting'.
 */
export function stepLevel(game: BlackHoleGame, run: LevelRun): BlackHoleEvent | 'cleared' | 'waiting' {
  if (run.waiting) return 'waiting';
  const dt = game.world.dt;
  driftHoles(game, run, dt);
  if (game.thrust !== 'none' && !game.over) {
    run.fuelLeft = Math.max(0, run.fuelLeft - dt);
    if (run.fuelLeft === 0) setThrust(game, 'none');
  }
  if (game.thrust !== 'none' && run.parked) {
    // A new attempt: its clock starts, and the message about the last one (a fall, an exit) goes.
    run.parked = false;
    run.attemptStart = run.time;
    game.message = levelMessage(run.spec);
  }
  const time = run.time + dt;
  run.time = time;
  const event = stepBlackHole(game);
  if (event === 'fell' || event === 'lost') run.parked = true;
  else if (event === 'none' && run.parked) {
    setPosition(game.world, game.ship, game.start);
    setVelocity(game.world, game.ship, REST);
  }
  if (event !== 'scored') return event;
  // A life back for every level cleared, up to the game's starting lives.
  const bonus = game.lives < game.params.lives;
  if (bonus) game.lives++;
  run.summary = Object.freeze({
    level: run.spec.level,
    time: time - run.attemptStart,
    totalTime: time,
    lives: game.lives,
    points: run.spec.holes,
    fuelLeft: run.fuelLeft,
    falls: game.falls - run.fallsAtStart,
  });
  // ./rules scored one point per hole on screen and laid out one more hole: the levels lay out their
  // own, when the next level begins; until then the field is empty and the ship parked at the start.
  clearHoles(game, run);
  run.spec = levelSpec(run.spec.level + 1);
  run.parked = true;
  resetShip(game);
  setThrust(game, 'none');
  run.waiting = true;
  const s = run.summary;
  game.message =
    `Level ${s.level} cleared in ${s.time.toFixed(1)} s` +
    (s.falls > 0 ? ` (${s.totalTime.toFixed(1)} s in all, ${s.falls} ${s.falls === 1 ? 'fall' : 'falls'})` : '') +
    (bonus
      ? `: a life back, ${s.lives} ${s.lives === 1 ? 'life' : 'lives'} now. `
      : ` with ${s.lives} ${s.lives === 1 ? 'life' : 'lives'} left. `) +
    `Tap here or press Enter for level ${run.spec.level}.`;
  return 'cleared';
}

const REST: readonly [number, number] = [0, 0];

/** Whether thrust is possible now (fuel left, not waiting, not over). */
export function canThrust(game: BlackHoleGame, run: LevelRun): boolean {
  return !run.waiting && !game.over && run.fuelLeft > 0;
}
