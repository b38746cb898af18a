/**
 * The rope lab's known solutions and their star windows, headless: for each level (scene.ts LEVELS and
 * WIDE_LEVELS) the plan that wins it, its earlier cuts at fixed times and its last cut anywhere in a
 * window, and the measure of that window: for each time of the last cut, which stars the ball catches
 * and whether it lands in the basket. Used by the tests (test/games/lab-rope.test.ts) and the
 * measuring scripts (scripts/lab-rope-cuts.mjs, scripts/lab-rope-stars.mjs).
 */
import { type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import {
  BALL_DRAG,
  createRopeScene,
  cutRope,
  DEFAULTS,
  LEVELS,
  type Level,
  type Outcome,
  pathReaches,
  predictFlight,
  RopeGame,
  type RopeScene,
  STAR_REACH,
  WIDE_LEVELS,
} from './scene';

/** How a level is won: earlier cuts at fixed times, then the last rope cut anywhere in [from, to]. */
export interface LevelPlan {
  /** The earlier cuts: [time s, rope index], each at its rope's middle. */
  readonly before: readonly (readonly [number, number])[];
  /** The rope cut last. */
  readonly last: number;
  /** The sideways push given to the ball at the start, m/s (a drag, in play). */
  readonly push?: number;
  /** The times the last cut is measured over, s. */
  readonly from: number;
  readonly to: number;
  /**
   * The widest run of last-cut times, s, that win all three stars, measured in the engine every
   * 0.02 s at the rope's middle (scripts/lab-rope-stars.mjs --engine): its first and last time.
   */
  readonly threeStars: readonly [number, number];
}

/** The plans of LEVELS, in order. */
export const PLANS: readonly LevelPlan[] = Object.freeze([
  { before: [], last: 0, from: 0.2, to: 4.5, threeStars: [1, 1.88] },
  { before: [[0.5, 0]], last: 1, from: 0.6, to: 3, threeStars: [1.34, 2.46] },
  { before: [], last: 0, from: 0.2, to: 4, threeStars: [0.82, 1.38] },
  {
    before: [
      [2.03, 2],
      [2.36, 1],
    ],
    last: 0,
    from: 2.4,
    to: 6,
    threeStars: [4.26, 6.0],
  },
  { before: [], last: 0, push: 5, from: 0.2, to: 6, threeStars: [3.54, 4.28] },
  { before: [], last: 0, from: 0.3, to: 8, threeStars: [2.3, 2.92] },
  { before: [], last: 0, from: 0.3, to: 3.5, threeStars: [0.9, 1.58] },
  { before: [], last: 0, from: 0.3, to: 3.5, threeStars: [1.02, 1.56] },
]);

/** The plans of WIDE_LEVELS, in order. */
export const WIDE_PLANS: readonly LevelPlan[] = Object.freeze([
  { before: [], last: 0, from: 0.8, to: 3, threeStars: [1.42, 1.86] },
  { before: [[0.5, 0]], last: 1, from: 0.6, to: 3.2, threeStars: [1.56, 2.18] },
  { before: [], last: 0, from: 0.3, to: 3.5, threeStars: [1.9, 2.5] },
  {
    before: [
      [1.0, 2],
      [1.3, 1],
    ],
    last: 0,
    from: 1.4,
    to: 7,
    threeStars: [2.68, 3.32],
  },
  { before: [], last: 0, push: 5, from: 0.2, to: 6, threeStars: [4.08, 5.02] },
  { before: [], last: 0, from: 0.3, to: 8, threeStars: [2.86, 3.44] },
  { before: [], last: 0, from: 0.3, to: 3.5, threeStars: [1.22, 1.68] },
  { before: [], last: 0, from: 0.3, to: 3.5, threeStars: [1.34, 1.78] },
]);

/** The plans of `levels` (LEVELS or WIDE_LEVELS). */
export function plansOf(levels: readonly Level[]): readonly LevelPlan[] {
  return levels === WIDE_LEVELS ? WIDE_PLANS : PLANS;
}

/** Cuts rope `rope` of the scene at the link `at` of the way from its pin to the ball (0 to 1). */
export function cutAlong(s: RopeScene, rope: number, at = 0.5): void {
  const links = s.ropes[rope]!.links;
  cutRope(s.world, s.ropes[rope]!, links[Math.min(links.length - 1, Math.floor(at * links.length))]!);
}

/**
 * Plays level `index` of `levels` in the engine: the plan's push and earlier cuts, the last cut at
 * `t` s `at` of the way down its rope, for at most `seconds` s (`plan`: the level's own by default). @returns the outcome, stars and the
 * world time it was decided at, s.
 */
export function playPlan(
  levels: readonly Level[],
  index: number,
  t: number,
  at = 0.5,
  seconds = 14,
  plan: LevelPlan = plansOf(levels)[index]!,
): { outcome: Outcome; stars: number; time: number } {
  const s = createRopeScene(index, DEFAULTS, levels);
  const g = new RopeGame(s);
  if (plan.push) s.world.components.Velocity.x[slotOf(s.ball)] = plan.push;
  const cuts = [...plan.before.map(([time, r]) => [time, r, 0.5] as const), [t, plan.last, at] as const].sort((a, b) => a[0] - b[0]);
  let k = 0;
  for (let i = 0; i < 60 * seconds && g.outcome === 'playing'; i++) {
    while (k < cuts.length && s.world.time >= cuts[k]![0]) {
      const [, r, place] = cuts[k++]!;
      cutAlong(s, r, place);
    }
    step(s.world);
    g.update();
  }
  return { outcome: g.outcome, stars: g.stars(), time: s.world.time };
}

/** What a last cut at one time would do, by predictFlight: the stars caught (swing and flight) and whether it lands. */
export interface CutForecast {
  /** The time of the last cut, s. */
  t: number;
  /** Which stars are caught: by the swing up to `t` or along the flight from there. */
  stars: boolean[];
  /** Whether the flight ends in the basket's opening. */
  lands: boolean;
}

/**
 * The forecast of every last cut from plan.from to plan.to, one a step (1/60 s): the level played
 * once in the engine with its push and earlier cuts and the last rope never cut, and at each step
 * the stars the swing has caught so far and predictFlight's path from the ball as it is (the stars
 * it passes within STAR_REACH of, and whether it ends in the basket). One run of the engine, so
 * cheap enough for a test; the engine's own flight agrees with predictFlight to 6 cm for 0.6 s
 * (test/games/lab-rope.test.ts), and playPlan checks the windows' edges. `plan`: the level's own by default.
 */
export function forecastCuts(levels: readonly Level[], index: number, plan: LevelPlan = plansOf(levels)[index]!): CutForecast[] {
  const s = createRopeScene(index, DEFAULTS, levels);
  if (plan.push) s.world.components.Velocity.x[slotOf(s.ball)] = plan.push;
  const swing = s.level.stars.map(() => false);
  const out: CutForecast[] = [];
  const path: number[] = [];
  let k = 0;
  while (s.world.time <= plan.to + 1e-9) {
    while (k < plan.before.length && s.world.time >= plan.before[k]![0]) cutAlong(s, plan.before[k++]![1]);
    const [x, y, vx, vy] = ballState(s.world, s.ball);
    s.level.stars.forEach(([sx, sy], i) => {
      if (Math.hypot(x - sx, y - sy) < STAR_REACH) swing[i] = true;
    });
    if (s.world.time >= plan.from - 1e-9) {
      const lands = predictFlight(s.level, x, y, vx, vy, -s.world.gravity[1]!, BALL_DRAG / DEFAULTS.ballMass, path, 1 / 60);
      const stars = swing.map((c, i) => c || pathReaches(path, s.level.stars[i]![0], s.level.stars[i]![1]));
      out.push({ t: s.world.time, stars, lands });
    }
    step(s.world);
  }
  return out;
}

/** The ball's place and velocity: [x, y, vx, vy]. */
function ballState(world: PhysicsWorld, ball: number): [number, number, number, number] {
  const e = slotOf(ball);
  const P = world.components.Position,
    V = world.components.Velocity;
  return [P.x[e]!, P.y[e]!, V.x[e]!, V.y[e]!];
}

/**
 * The widest run of consecutive forecasts for which `ok` holds: [from, to] s (the times of its
 * first and last), or null if none does.
 */
export function widestRun(forecasts: readonly CutForecast[], ok: (f: CutForecast) => boolean): [number, number] | null {
  let best: [number, number] | null = null,
    start = -1;
  forecasts.forEach((f, i) => {
    if (ok(f) && start < 0) start = i;
    const endsHere = start >= 0 && (!ok(f) || i === forecasts.length - 1);
    if (endsHere) {
      const end = ok(f) ? i : i - 1;
      const run: [number, number] = [forecasts[start]!.t, forecasts[end]!.t];
      if (!best || run[1] - run[0] > best[1] - best[0]) best = run;
      start = -1;
    }
  });
  return best;
}

export { LEVELS, WIDE_LEVELS };
