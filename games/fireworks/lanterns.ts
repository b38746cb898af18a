/**
 * The lantern show, the fireworks' game: light every lantern in the sky with your bursts, in as few
 * shells as you can. A burst lights each lantern within its reach: the radius of the charging ring
 * the page draws while the button is held (PREVIEW_SECONDS x BURST_SPEED x reach x burstSize), about
 * how far the burst's fastest stars get in their first 0.7 s. Holding longer makes a bigger burst
 * that can light two lanterns at once; a shell bursts FUSE (2 s) after launch, so a drifting lantern
 * must be led. Stars by shells used against the level's par. Pure rules: no DOM, no pixi.
 */
import { BURST_SPEED, burstSize } from './show';

/** The charging ring's radius over the burst's fastest star speed, s (see `burstReach`). */
export const PREVIEW_SECONDS = 0.7;

/** A lantern's radius as a fraction of the sky's width (3.6 m in the 120 m desktop sky). */
export const LANTERN_SIZE = 0.03;

/**
 * A lantern: centre at fractions (fx of the sky's width, fy of its height); drifting lanterns swing
 * sideways by `drift` (a fraction of the width) with period `period` s.
 */
export interface Lantern {
  readonly fx: number;
  readonly fy: number;
  readonly drift?: number;
  readonly period?: number;
}

/** A level: its name, a tip shown while it is played (after 'Click' or 'Tap'), its lanterns, and par (the fewest shells that can light them all). */
export interface LanternLevel {
  readonly name: string;
  readonly tip: string;
  readonly lanterns: readonly Lantern[];
  readonly par: number;
}

/**
 * The levels. A quick burst reaches 0.175 sky widths (W), a held one up to 0.252 W, plus a lantern's
 * radius (0.03 W). Pairs are 0.44 W apart and the row's lanterns 0.22 W: a burst between or on them
 * is 0.22 W from the next, beyond a quick burst's 0.205 W but within a held one's 0.282 W.
 */
export const LEVELS: readonly LanternLevel[] = Object.freeze([
  {
    name: 'Three lanterns',
    tip: 'near a lantern: your shell bursts there 2 s later',
    par: 3,
    lanterns: [
      { fx: 0.25, fy: 0.6 },
      { fx: 0.5, fy: 0.78 },
      { fx: 0.75, fy: 0.6 },
    ],
  },
  {
    name: 'Hold for two',
    tip: 'between two lanterns and hold: a bigger burst lights both',
    par: 2,
    lanterns: [
      { fx: 0.28, fy: 0.72 },
      { fx: 0.72, fy: 0.72 },
      { fx: 0.5, fy: 0.42 },
    ],
  },
  {
    name: 'Drifting',
    tip: 'ahead of a lantern: it drifts on during the 2 s fuse',
    par: 3,
    lanterns: [
      { fx: 0.3, fy: 0.55, drift: 0.14, period: 7 },
      { fx: 0.55, fy: 0.8, drift: 0.18, period: 6 },
      { fx: 0.72, fy: 0.45, drift: 0.12, period: 8 },
    ],
  },
  {
    name: 'A row of five',
    tip: 'and hold: five lanterns, par two shells',
    par: 2,
    lanterns: [
      { fx: 0.06, fy: 0.62 },
      { fx: 0.28, fy: 0.62 },
      { fx: 0.5, fy: 0.62 },
      { fx: 0.72, fy: 0.62 },
      { fx: 0.94, fy: 0.62 },
    ],
  },
  {
    name: 'Finale',
    tip: 'near a lantern · hold to light two at once',
    par: 4,
    lanterns: [
      { fx: 0.15, fy: 0.8 },
      { fx: 0.55, fy: 0.8 },
      { fx: 0.35, fy: 0.55, drift: 0.1, period: 6 },
      { fx: 0.8, fy: 0.6, drift: 0.12, period: 7 },
      { fx: 0.2, fy: 0.38 },
      { fx: 0.6, fy: 0.38 },
    ],
  },
]);

/** The sky's size, m. */
export interface SkySize {
  readonly width: number;
  readonly height: number;
}

/**
 * Where lantern `lantern` is at `t` s after its level started, m.
 * @throws RangeError if t is not finite.
 */
export function lanternAt(lantern: Lantern, sky: SkySize, t: number): [number, number] {
  if (!Number.isFinite(t)) throw new RangeError(`lanternAt: t must be finite, got ${t}`);
  const swing = lantern.drift && lantern.period ? lantern.drift * Math.sin((2 * Math.PI * t) / lantern.period) : 0;
  return [(lantern.fx + swing) * sky.width, lantern.fy * sky.height];
}

/** A lantern's radius, m, in a sky `width` m wide. */
export function lanternRadius(width: number): number {
  return LANTERN_SIZE * width;
}

/**
 * How far a burst reaches, m: PREVIEW_SECONDS x BURST_SPEED x reach x burstSize(scale), the charging
 * ring's radius (reach: the show's sky factor; scale: burstScale of the hold, in [1, 3]).
 */
export function burstReach(reach: number, scale: number): number {
  return PREVIEW_SECONDS * BURST_SPEED * reach * burstSize(scale);
}

/** Stars for lighting a level with `shells` shells: 3 at par or better, 2 up to par + 2, else 1. */
export function starsFor(shells: number, par: number): 1 | 2 | 3 {
  return shells <= par ? 3 : shells <= par + 2 ? 2 : 1;
}

/** A level being played. */
export interface LanternRun {
  /** Index into LEVELS. */
  readonly level: number;
  /** Which lanterns are lit. */
  readonly lit: boolean[];
  /** Shells the player launched in this level. */
  shells: number;
  /** World time the level started, s (the lanterns' drift clock). */
  readonly start: number;
  /** Stars earned once all are lit; 0 while playing. */
  stars: 0 | 1 | 2 | 3;
}

/** Starts level `level` (an index into LEVELS) at world time `start` s. @throws RangeError on an unknown level. */
export function startLevel(level: number, start: number): LanternRun {
  if (!(Number.isInteger(level) && level >= 0 && level < LEVELS.length))
    throw new RangeError(`startLevel: level must be an integer in [0, ${LEVELS.length - 1}], got ${level}`);
  return { level, lit: LEVELS[level]!.lanterns.map(() => false), shells: 0, start, stars: 0 };
}

/** The player launched a shell (counted until the level is lit). */
export function countShell(run: LanternRun): void {
  if (run.stars === 0) run.shells++;
}

/**
 * A player's shell burst at (x, y), m, at world time `time` s with burst scale `scale`: lights every
 * unlit lantern whose edge the burst's reach touches, and gives the stars once all are lit.
 * @returns how many lanterns this burst lit.
 */
export function burstAt(run: LanternRun, sky: SkySize, reach: number, x: number, y: number, scale: number, time: number): number {
  if (run.stars !== 0) return 0;
  const r = burstReach(reach, scale) + lanternRadius(sky.width);
  const level = LEVELS[run.level]!;
  let n = 0;
  for (const [i, lantern] of level.lanterns.entries()) {
    if (run.lit[i]) continue;
    const [lx, ly] = lanternAt(lantern, sky, time - run.start);
    if (Math.hypot(lx - x, ly - y) <= r) {
      run.lit[i] = true;
      n++;
    }
  }
  if (run.lit.every(Boolean)) run.stars = starsFor(run.shells, level.par);
  return n;
}
