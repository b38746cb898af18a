/**
 * The lantern show, the fireworks' game: light every lantern in the sky with your bursts, in as few
 * shells as you can. A lantern lights when a hot star of a burst touches it: a star of the burst
 * itself (not a shell's tail) in the first `HOT_FRACTION` of its life, while it is bright and near
 * where it burst, whose centre comes within the lantern's radius (`lightFromSparks`). So a shell has
 * to burst close to a lantern: its hot stars reach about 0.125 sky widths sideways (a quick burst)
 * to 0.2 (the longest hold), and further down, as they droop (`sparkReach`, the page's charging
 * ring). A shell bursts FUSE (1.2 s) after launch, so a drifting lantern must be led.
 *
 * Everything is measured in sky widths (W), as the bursts are (show.ts `reach`): a lantern's x is a
 * fraction of the width, its y a height in widths above the band's middle (`bandMiddle` of the sky's
 * height). A wide sky (a desktop's) plays each level's `lanterns`; a tall one (a phone held upright,
 * `isTall`) plays its `tall` layout, the same lanterns spread over about 0.9 W of height instead of
 * 0.4 W, so the play fills the phone's screen rather than a band across its middle. Each tall layout
 * keeps its level's idea (the pairs 0.4 W apart, the willow columns 0.28 to 0.3 W tall, the finale's low
 * pair meeting 0.32 W under the middle lantern) and moves the rest apart. Stars by shells used
 * against the level's par, the fewest shells that light it (found by search over burst points and
 * holds on maps of where the real bursts' hot stars go; see each level).
 *
 * A level is shown as lit (`clearShown`) CLEAR_DELAY after its last lantern lit, once every
 * lantern's glow (`glowOf`, rising over GLOW_RISE) is full, so the banner never comes up while the
 * last burst still hides the lantern it lit. The lit count the page shows counts a lantern from the
 * moment it lights (`shownLit`), with its glow coming up and the "Double!" over a burst that lit
 * two. A burst whose hot stars go cold having lit
 * nothing is a miss (`watchBursts`), which the page says near it.
 * Pure rules: no DOM, no pixi.
 */
import { listCheck, numberCheck, type StorageOptions, type StoredValue, storedValue } from '@bitphysics/game-kit';
import { type PhysicsWorld, query, slotOf } from '@bitphysics/physics';
import { RECIPES, type RecipeName } from './recipes';
import { burstSize, type FireworksShow, FLASHES, FUSE, MAX_HOLD } from './show';

/** A star lights lanterns while its age is below this fraction of its lifetime (it fades linearly over its life). */
export const HOT_FRACTION = 0.4;

/** A lantern's radius as a fraction of the sky's width (3.84 m in the 120 m desktop sky), at least `LANTERN_MIN_RADIUS`. */
export const LANTERN_SIZE = 0.032;

/** The smallest lantern radius, m: 3.4 m is 21 px in a phone's 64 m sky, so a lantern stands 41 px tall there. */
export const LANTERN_MIN_RADIUS = 3.4;

/** Where a lantern's y = 0 lies in a wide sky, as a fraction of the sky's height; wide layouts keep |y| <= 0.2 W. */
export const BAND_MIDDLE = 0.55;

/** Where a lantern's y = 0 lies in a tall sky (`isTall`), as a fraction of its height; tall layouts keep |y| <= 0.5 W. */
export const TALL_BAND_MIDDLE = 0.52;

/** A sky at least this many times as tall as wide plays the levels' tall layouts. */
export const TALL_RATIO = 1.3;

/** How long a newly lit lantern's glow takes to come up to full, s (world time). */
export const GLOW_RISE = 0.5;

/** How long after the last lantern lit the level is shown as lit (banner, stars, next-level button), s (world time). */
export const CLEAR_DELAY = 1.2;

/** The shells of the lantern show. */
export type LanternShell = Extract<RecipeName, 'peony' | 'willow'>;

/**
 * A lantern: centre x (a fraction of the sky's width) and y (sky widths above the band's middle);
 * a drifting one swings sideways by `drift` (a fraction of the width) with period `period` s,
 * starting at phase `phase` (radians).
 */
export interface Lantern {
  readonly x: number;
  readonly y: number;
  readonly drift?: number;
  readonly period?: number;
  readonly phase?: number;
}

/**
 * A level: its name, a tip shown while it is played (after 'Click' or 'Tap'; short, so the status
 * row's hint stays one line on a phone beside its button), its lanterns in a wide sky and in a tall
 * one (as many, in the same order), par (the fewest shells that light them all, in both), the shell
 * it gives (`shell`) and whether holding makes that shell's burst bigger (`hold`).
 */
export interface LanternLevel {
  readonly name: string;
  readonly tip: string;
  readonly lanterns: readonly Lantern[];
  readonly tall: readonly Lantern[];
  readonly par: number;
  /**
   * The shells the level gives (par or more): once they are spent and their bursts are cold with a
   * lantern still dark, the level is lost and played again (`outOfShells`).
   */
  readonly shells: number;
  readonly shell: LanternShell;
  readonly hold: boolean;
  /**
   * A meeting the level is built round (`meetCue`): two drifting lanterns (`pair`, indices) that
   * swing towards each other, and the lantern (`with`) that a burst where they meet lights with them.
   */
  readonly meet?: { readonly pair: readonly [number, number]; readonly with: number };
}

/**
 * The levels, each needing a new idea. Figures from maps of where the hot stars of real bursts go
 * (3 seeds, 64 m phone sky and 120 m desktop sky, every 0.01 W, five holds), searched for the fewest
 * shells; "spray" is the chance that par shells at random points of the band, at random holds,
 * light everything. A newcomer's aims (scripts/fireworks-levels.mjs --random: par shells each within
 * 0.08 W of a dark lantern where it is, at random holds) light a level in par 0 to 1 times in 30,
 * every level, in both skies: three stars take the level's idea, seen and timed.
 * 1. Quick shells only, five lanterns and four shells: one alone, and two close pairs (0.26 W) that a
 *    quick burst right between lights together (aims within 0.06 W of the middle that light both,
 *    scripts/fireworks-levels.mjs --par), so a shell a lantern runs out: the level is cleared only by
 *    lighting a pair with one shell, as the tip says (with four lanterns and four shells a shell at
 *    each lit it with no idea at all). Par 3 takes both pairs; the spare shell over par lets a first
 *    level survive one stray tap.
 * 2. Two pairs 0.4 W apart, three shells: only a held burst between a pair lights both (0.2 W away,
 *    beyond a quick burst's 0.17), and no two lanterns are nearer (on the desktop the pairs lie on
 *    the diagonal: side by side, a tap between their inner two lit both), so a shell a lantern runs out and
 *    clearing it takes at least one hold, as the tip says; three stars take both held pairs. The tip
 *    says only that a hold makes a bigger burst: which lanterns pair up is for the player to see.
 * 3. Quick shells only, drifting lanterns: lead them by the fuse (the page draws each one's ghost
 *    where it will be when the fuse runs out), and four lanterns for par 3: two swing past each
 *    other, one over the other, every 5 s, and only a shell timed to burst as they pass lights both.
 * 4. Willows only: their stars rise little and fall far, so a held burst at the top of a column of
 *    two (0.28 to 0.3 W apart: a quick burst's stars reach 0.21 W down, a held one's 0.33) lights
 *    both, a quick one only the top, and a burst between columns lights neither pair.
 * 5. Three lanterns high and two that drift towards each other low: when the low two meet, one burst
 *    under the middle lantern lights three (spray 0.3-1.1 %; 2 shells at best, par 3).
 */
export const LEVELS: readonly LanternLevel[] = Object.freeze([
  {
    name: 'First light',
    tip: 'between a close pair: both light',
    par: 3,
    shells: 4,
    shell: 'peony',
    hold: false,
    // A lone lantern and two close pairs 0.26 W apart; lanterns not paired 0.34 W or more apart (a
    // quick burst on one lantern lights one), a burst right between a pair lights both.
    lanterns: [
      { x: 0.08, y: -0.16 },
      { x: 0.28, y: 0.16 },
      { x: 0.54, y: 0.16 },
      { x: 0.66, y: -0.16 },
      { x: 0.92, y: -0.16 },
    ],
    tall: [
      { x: 0.15, y: 0.38 },
      { x: 0.62, y: 0.1 },
      { x: 0.88, y: 0.1 },
      { x: 0.22, y: -0.4 },
      { x: 0.48, y: -0.4 },
    ],
  },
  {
    name: 'Pairs',
    tip: 'and hold: a bigger burst',
    par: 2,
    shells: 3,
    shell: 'peony',
    hold: true,
    // Two pairs 0.4 W apart on the diagonal, 0.5 W and more between the pairs: no two lanterns a
    // quick burst lights together (with the inner two of the pairs side by side, 0.28 W apart one
    // over the other, a tap between them would light both and clear the level without a hold).
    lanterns: [
      { x: 0.06, y: -0.16 },
      { x: 0.3, y: 0.16 },
      { x: 0.7, y: -0.16 },
      { x: 0.94, y: 0.16 },
    ],
    // Two pairs 0.4 W apart as wide, 0.64 W apart in height. The lower pair is centred: a low burst
    // drifts outwards with its shell's sideways speed (less spent by drag low down), and one between
    // these two is launched straight up.
    tall: [
      { x: 0.3, y: -0.22 },
      { x: 0.7, y: -0.22 },
      { x: 0.5, y: 0.42 },
      { x: 0.9, y: 0.42 },
    ],
  },
  {
    name: 'Drifting',
    // A ghost is the dashed ring each drifting lantern trails: where it will be when the shell bursts
    // (the tip fits one line beside its button on a phone).
    tip: 'a ghost: its lantern at burst time',
    par: 3,
    shells: 5,
    shell: 'peony',
    hold: false,
    lanterns: [
      { x: 0.14, y: -0.15, drift: 0.08, period: 4.6, phase: 0 },
      { x: 0.86, y: -0.15, drift: 0.08, period: 5.5, phase: 3 },
      { x: 0.33, y: 0.17, drift: 0.16, period: 5, phase: 0 },
      { x: 0.67, y: 0.09, drift: 0.16, period: 5, phase: Math.PI },
    ],
    // The passing pair 0.08 W apart in height as wide, the lone two 0.42 W and more from it.
    tall: [
      { x: 0.2, y: 0.44, drift: 0.1, period: 4.6, phase: 0 },
      { x: 0.8, y: -0.46, drift: 0.1, period: 5.5, phase: 3 },
      { x: 0.3, y: 0.04, drift: 0.19, period: 5, phase: 0 },
      { x: 0.7, y: -0.04, drift: 0.19, period: 5, phase: Math.PI },
    ],
  },
  {
    name: 'Willows',
    tip: 'and hold on a top lantern: willows fall',
    par: 3,
    shells: 5,
    shell: 'willow',
    hold: true,
    lanterns: [
      { x: 0.1, y: 0.13 },
      { x: 0.1, y: -0.15 },
      { x: 0.5, y: 0.13 },
      { x: 0.5, y: -0.15 },
      { x: 0.9, y: 0.13 },
      { x: 0.9, y: -0.15 },
    ],
    // Three columns of two, 0.3 W tall (beyond a quick willow's reach down, within a held one's, so
    // only a held burst on a top lantern lights its column) and 0.4 W apart, the middle one lower on
    // a phone: a burst between columns reaches neither pair.
    tall: [
      { x: 0.1, y: 0.46 },
      { x: 0.1, y: 0.16 },
      { x: 0.5, y: -0.16 },
      { x: 0.5, y: -0.46 },
      { x: 0.9, y: 0.46 },
      { x: 0.9, y: 0.16 },
    ],
  },
  {
    name: 'Finale',
    tip: 'and hold in the gold ring till “now!”',
    par: 3,
    shells: 5,
    shell: 'peony',
    hold: true,
    meet: { pair: [3, 4], with: 1 },
    lanterns: [
      { x: 0.1, y: 0.17 },
      { x: 0.5, y: 0.17 },
      { x: 0.9, y: 0.17 },
      { x: 0.3, y: -0.15, drift: 0.1, period: 6, phase: 0 },
      { x: 0.7, y: -0.15, drift: 0.1, period: 6, phase: Math.PI },
    ],
    // The middle lantern and the low pair as wide (they meet 0.32 W under it); the sides higher.
    tall: [
      { x: 0.1, y: 0.42 },
      { x: 0.5, y: 0.02 },
      { x: 0.9, y: 0.42 },
      { x: 0.3, y: -0.3, drift: 0.1, period: 6, phase: 0 },
      { x: 0.7, y: -0.3, drift: 0.1, period: 6, phase: Math.PI },
    ],
  },
]);

/** The sky's size, m. */
export interface SkySize {
  readonly width: number;
  readonly height: number;
}

/** Whether `sky` is tall (at least TALL_RATIO times as tall as wide: a phone held upright), which plays the tall layouts. */
export function isTall(sky: SkySize): boolean {
  return sky.height >= TALL_RATIO * sky.width;
}

/** Where a lantern's y = 0 lies in `sky`, as a fraction of its height: TALL_BAND_MIDDLE in a tall sky, else BAND_MIDDLE. */
export function bandMiddle(sky: SkySize): number {
  return isTall(sky) ? TALL_BAND_MIDDLE : BAND_MIDDLE;
}

/** The lanterns of `level` (an index into LEVELS) in `sky`: its tall layout in a tall sky, else its wide one. */
export function lanternsOf(level: number, sky: SkySize): readonly Lantern[] {
  const lv = LEVELS[level];
  if (!lv) throw new RangeError(`lanternsOf: level must be an integer in [0, ${LEVELS.length - 1}], got ${level}`);
  return isTall(sky) ? lv.tall : lv.lanterns;
}

/**
 * Where lantern `lantern` is at `t` s after its level started, m (y = 0 of the band at `bandMiddle`).
 * @throws RangeError if t is not finite.
 */
export function lanternAt(lantern: Lantern, sky: SkySize, t: number): [number, number] {
  if (!Number.isFinite(t)) throw new RangeError(`lanternAt: t must be finite, got ${t}`);
  const swing = lantern.drift && lantern.period ? lantern.drift * Math.sin((2 * Math.PI * t) / lantern.period + (lantern.phase ?? 0)) : 0;
  return [(lantern.x + swing) * sky.width, bandMiddle(sky) * sky.height + lantern.y * sky.width];
}

/** How far past their closest the meeting pair's gap may be for `meetCue` to show, in sky widths. */
export const MEET_WINDOW = 0.07;

/**
 * How far above the mean of the meeting's three lanterns `meetCue` aims, in sky widths: a held
 * burst's hot stars reach further down than up, and at the mean itself the lantern above lit for 20
 * of 25 releases (5 seeds, 5 release times in the cue), from 0.02 to 0.08 W higher for all 25.
 */
export const MEET_LIFT = 0.05;

/** When and where to fire at a level's meeting (`LanternLevel.meet`). */
export interface MeetCue {
  /** Where the shell should burst, m: MEET_LIFT over the middle of the pair and the lantern above, as they will be then. */
  readonly x: number;
  readonly y: number;
  /** The pair's places then (their ghosts), m: [ax, ay, bx, by]. */
  readonly ghosts: readonly [number, number, number, number];
  /**
   * How close the pair will be when a shell let go now bursts (FUSE on), 1 at their closest down to
   * 0 at MEET_WINDOW wider; and the same for a press now held MAX_HOLD before it is let go.
   */
  readonly release: number;
  readonly press: number;
  /** Whether the pair is within the window now (they are meeting as drawn), not only after the fuse. */
  readonly meetingNow: boolean;
}

/**
 * The cue of `level`'s meeting at `t` s after it started: null if the level has none, either lantern
 * of its pair is lit, or neither a shell let go now nor one pressed now and held MAX_HOLD would burst
 * with the pair within MEET_WINDOW sky widths of their closest gap. The burst point is MEET_LIFT over
 * the mean of the pair's and the other lantern's places at that burst (the pair's middle once that
 * lantern is lit).
 * The cue shows the player when to press: "hold when the low two meet" alone does not say when that
 * is, nor that the press must come a hold and a fuse earlier.
 * @throws RangeError on a bad level or a non-finite t.
 */
export function meetCue(level: number, sky: SkySize, t: number, lit: readonly boolean[]): MeetCue | null {
  const ls = lanternsOf(level, sky);
  if (!Number.isFinite(t)) throw new RangeError(`meetCue: t must be finite, got ${t}`);
  const meet = LEVELS[level]!.meet;
  if (!meet || lit[meet.pair[0]] || lit[meet.pair[1]]) return null;
  const a = ls[meet.pair[0]]!,
    b = ls[meet.pair[1]]!;
  const gap = (u: number): number => {
    const [ax, ay] = lanternAt(a, sky, u),
      [bx, by] = lanternAt(b, sky, u);
    return Math.hypot(bx - ax, by - ay);
  };
  // Their closest gap over a swing (the longer period), sampled.
  const period = Math.max(a.period ?? 1, b.period ?? 1);
  let closest = Infinity;
  for (let k = 0; k < 96; k++) closest = Math.min(closest, gap((period * k) / 96));
  const window = MEET_WINDOW * sky.width;
  const near = (u: number): number => Math.max(0, Math.min(1, 1 - (gap(u) - closest) / window));
  const release = near(t + FUSE),
    press = near(t + MAX_HOLD + FUSE);
  if (release <= 0 && press <= 0) return null;
  const at = release > 0 ? t + FUSE : t + MAX_HOLD + FUSE;
  const [ax, ay] = lanternAt(a, sky, at),
    [bx, by] = lanternAt(b, sky, at);
  const pts = [
    [ax, ay],
    [bx, by],
  ];
  const lift = lit[meet.with] ? 0 : MEET_LIFT * sky.width;
  if (!lit[meet.with]) pts.push(lanternAt(ls[meet.with]!, sky, at));
  const x = pts.reduce((s, p) => s + p[0]!, 0) / pts.length,
    y = pts.reduce((s, p) => s + p[1]!, 0) / pts.length + lift;
  return { x, y, ghosts: [ax, ay, bx, by], release, press, meetingNow: gap(t) - closest <= window };
}

/** A lantern's radius, m, in a sky `width` m wide: LANTERN_SIZE x width, at least LANTERN_MIN_RADIUS. */
export function lanternRadius(width: number): number {
  return Math.max(LANTERN_SIZE * width, LANTERN_MIN_RADIUS);
}

/** How far a burst's hot stars get from where it burst, in sky widths: sideways, up and down. */
export interface SparkReach {
  readonly side: number;
  readonly up: number;
  readonly down: number;
}

/**
 * Measured reach of a quick burst's hot stars, sky widths (where a lantern's centre lights, less the
 * lantern's radius; both sky shapes averaged): willow stars droop under their heavy drag.
 */
const QUICK_REACH: Readonly<Record<LanternShell, SparkReach>> = Object.freeze({
  peony: { side: 0.125, up: 0.095, down: 0.155 },
  willow: { side: 0.095, up: 0.055, down: 0.21 },
});

/**
 * How far the hot stars of a `shell` burst of scale `scale` (burstScale of the hold, in [1, 3]) get,
 * sky widths: the quick burst's measured reach x burstSize(scale)^1.25 (a held burst's three times
 * as many stars also fill its rim more densely: 1.57 times the reach at the longest hold, measured
 * 1.56 to 1.6). The page draws it as the charging ring.
 * @throws RangeError (from burstSize) unless scale >= 1.
 */
export function sparkReach(shell: LanternShell, scale: number): SparkReach {
  const f = burstSize(scale) ** 1.25;
  const q = QUICK_REACH[shell];
  return { side: q.side * f, up: q.up * f, down: q.down * f };
}

/**
 * Whether `run` is lost: every shell of its level (LanternLevel.shells) spent, none still to burst or
 * hot (`pending`: the player's shells in flight plus the watched bursts still hot), and a lantern
 * still dark. @throws RangeError unless pending is an integer >= 0.
 */
export function outOfShells(run: LanternRun, pending: number): boolean {
  if (!(Number.isInteger(pending) && pending >= 0)) throw new RangeError(`outOfShells: pending must be an integer >= 0, got ${pending}`);
  return run.stars === 0 && run.shells >= LEVELS[run.level]!.shells && pending === 0;
}

/**
 * Shells of its level `run` has not launched, lit or not: the status row counts them (it read
 * "Shells 0" while a level won with one to spare waited for its glow). The page launches none once
 * the level is lit, whatever this says.
 */
export function shellsLeft(run: LanternRun): number {
  return Math.max(0, LEVELS[run.level]!.shells - run.shells);
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
  /** World time each lantern lit, s (NaN while unlit). */
  readonly litAt: number[];
}

/** Starts level `level` (an index into LEVELS) at world time `start` s. @throws RangeError on an unknown level. */
export function startLevel(level: number, start: number): LanternRun {
  if (!(Number.isInteger(level) && level >= 0 && level < LEVELS.length))
    throw new RangeError(`startLevel: level must be an integer in [0, ${LEVELS.length - 1}], got ${level}`);
  const n = LEVELS[level]!.lanterns.length;
  return {
    level,
    lit: Array.from({ length: n }, () => false),
    shells: 0,
    start,
    stars: 0,
    litAt: Array.from({ length: n }, () => Number.NaN),
  };
}

/**
 * How brightly lantern `i` of `run` glows at world time `time` s, in [0, 1]: 0 while unlit, rising
 * evenly to 1 over GLOW_RISE after it lit.
 */
export function glowOf(run: LanternRun, i: number, time: number): number {
  const at = run.litAt[i];
  if (at === undefined || Number.isNaN(at)) return 0;
  return Math.max(0, Math.min(1, (time - at) / GLOW_RISE));
}

/**
 * Whether the level is shown as lit at world time `time` s: every lantern lit, the last CLEAR_DELAY
 * or more ago (every glow full by then, as CLEAR_DELAY > GLOW_RISE).
 */
export function clearShown(run: LanternRun, time: number): boolean {
  if (run.stars === 0) return false;
  let last = -Infinity;
  for (const t of run.litAt) last = Math.max(last, t);
  return time - last >= CLEAR_DELAY - 1e-9;
}

/** The player launched a shell (counted until the level is lit; the page launches none once `shellsLeft` is 0). */
export function countShell(run: LanternRun): void {
  if (run.stars === 0) run.shells++;
}

/** Lights lantern `i` of the run (if unlit) at world time `time` s and gives the stars once all are lit. @returns whether it was lit now. */
function light(run: LanternRun, i: number, time: number): boolean {
  if (run.lit[i]) return false;
  run.lit[i] = true;
  run.litAt[i] = time;
  if (run.lit.every(Boolean)) run.stars = starsFor(run.shells, LEVELS[run.level]!.par);
  return true;
}

/**
 * A hot star at (x, y), m, at world time `time` s: lights every unlit lantern whose centre is within
 * a lantern's radius of it, and gives the stars once all are lit.
 * @returns the indices of the lanterns it lit.
 */
export function starAt(run: LanternRun, sky: SkySize, x: number, y: number, time: number): number[] {
  const out: number[] = [];
  if (run.stars !== 0) return out;
  const r = lanternRadius(sky.width);
  for (const [i, lantern] of lanternsOf(run.level, sky).entries()) {
    if (run.lit[i]) continue;
    const [lx, ly] = lanternAt(lantern, sky, time - run.start);
    if ((lx - x) ** 2 + (ly - y) ** 2 <= r * r && light(run, i, time)) out.push(i);
  }
  return out;
}

/** Slots of the show's burst emitters (its stars' emitters, not the shells' tails), per show. */
const burstEmitters = new WeakMap<FireworksShow, Set<number>>();

function burstEmittersOf(show: FireworksShow): Set<number> {
  let set = burstEmitters.get(show);
  if (!set) {
    // Particle.emitter holds the emitter's slot.
    set = new Set([...show.emitters.sparks, ...show.recipeEmitters.values()].map(slotOf));
    burstEmitters.set(show, set);
  }
  return set;
}

/**
 * Lights the lanterns the burst stars of `show` touch now (world time `world.time`): every star of a
 * burst (generation 0 of the show's burst emitters; the shells' tails and the stars' own bursts do
 * not count) in the first HOT_FRACTION of its life whose centre is within a lantern's radius of an
 * unlit lantern's centre. Call it after each step of the lantern show.
 * @returns the indices of the lanterns lit by this call.
 * @throws RangeError if the world is not 2D.
 */
export function lightFromSparks(world: PhysicsWorld, show: FireworksShow, run: LanternRun): number[] {
  const out: number[] = [];
  if (world.dimensions !== 2) throw new RangeError(`lightFromSparks: needs the show's 2D world, got dimensions ${world.dimensions}`);
  if (run.stars !== 0) return out;
  const emitters = burstEmittersOf(show);
  const sky = show.params.sky;
  const lanterns = lanternsOf(run.level, sky);
  const r2 = lanternRadius(sky.width) ** 2;
  const at = lanterns.map((l) => lanternAt(l, sky, world.time - run.start));
  const c = world.components;
  const P = c.Particle,
    L = c.Lifetime,
    X = c.Position.x,
    Y = c.Position.y;
  for (const e of query(world, [P, c.Position])) {
    if (P.generation[e] !== 0 || L.age[e]! > HOT_FRACTION * L.duration[e]! || !emitters.has(P.emitter[e]!)) continue;
    const x = X[e]!,
      y = Y[e]!;
    for (let i = 0; i < at.length; i++) {
      if (run.lit[i]) continue;
      const [lx, ly] = at[i]!;
      if ((lx - x) ** 2 + (ly - y) ** 2 <= r2 && light(run, i, world.time)) out.push(i);
    }
    if (run.stars !== 0) break;
  }
  return out;
}

/**
 * How many lanterns of `run` the player sees lit at world time `time` s: those lit at or before
 * `time` (their glow coming up). The page's "Lit n/m" counts these, in step with the lanterns'
 * glow and the "Double!" over a burst that lit two (counted once the glow is full, it would say
 * "Lit 0/4" under a "Double!" and two glowing lanterns).
 */
export function shownLit(run: LanternRun, time: number): number {
  let n = 0;
  for (let i = 0; i < run.lit.length; i++) {
    const at = run.litAt[i];
    if (run.lit[i] && at !== undefined && at <= time) n++;
  }
  return n;
}

/** A burst watched for what it lights: where it burst, m, when and until when its stars are hot (world time, s), and the lanterns it lit. */
export interface WatchedBurst {
  readonly x: number;
  readonly y: number;
  readonly time: number;
  readonly until: number;
  lit: number;
}

/** The bursts of a level being watched (`watchBursts`): how many of the show's bursts were seen, and those still hot. */
export interface BurstWatch {
  seen: number;
  readonly bursts: WatchedBurst[];
}

/** A new watch for `show`, counting its bursts so far as seen. */
export function startWatch(show: FireworksShow): BurstWatch {
  return { seen: show.flashCount, bursts: [] };
}

/**
 * Follows the bursts of the lantern show after a step at world time `time` s, in which the lanterns
 * `lit` (indices, from `lightFromSparks`) lit: each new burst of `show` (its flashes since
 * `watch.seen`) is watched while its stars are hot (HOT_FRACTION of the longest star life of the
 * level's shell); each lantern lit is credited to the nearest watched burst; a burst whose stars went
 * cold having lit nothing is a miss. Once the level is lit nothing is watched.
 * @returns the misses of this step (no longer watched).
 * @throws RangeError if time is not finite.
 */
export function watchBursts(watch: BurstWatch, show: FireworksShow, run: LanternRun, lit: readonly number[], time: number): WatchedBurst[] {
  if (!Number.isFinite(time)) throw new RangeError(`watchBursts: time must be finite, got ${time}`);
  const hot = HOT_FRACTION * RECIPES[LEVELS[run.level]!.shell].lifetime[1];
  for (let k = Math.max(watch.seen, show.flashCount - FLASHES); k < show.flashCount; k++) {
    const f = 4 * (k % FLASHES);
    const at = show.flashes[f + 2]!;
    watch.bursts.push({ x: show.flashes[f]!, y: show.flashes[f + 1]!, time: at, until: at + hot, lit: 0 });
  }
  watch.seen = show.flashCount;
  if (run.stars !== 0) {
    watch.bursts.length = 0;
    return [];
  }
  const sky = show.params.sky;
  const lanterns = lanternsOf(run.level, sky);
  for (const i of lit) {
    const [lx, ly] = lanternAt(lanterns[i]!, sky, time - run.start);
    let best: WatchedBurst | null = null,
      bestD = Infinity;
    for (const b of watch.bursts) {
      const d = (b.x - lx) ** 2 + (b.y - ly) ** 2;
      if (d < bestD) {
        bestD = d;
        best = b;
      }
    }
    if (best) best.lit++;
  }
  const misses: WatchedBurst[] = [];
  for (let k = watch.bursts.length - 1; k >= 0; k--) {
    const b = watch.bursts[k]!;
    if (time <= b.until) continue;
    watch.bursts.splice(k, 1);
    if (b.lit === 0) misses.push(b);
  }
  return misses;
}

/** The storage key of the best stars per level: a JSON list, one entry a level of LEVELS, 1 to 3 stars or 0 (not yet lit). */
export const STARS_KEY = 'bitphysics.fireworks.stars';

/**
 * The best stars of each level of LEVELS (0 to 3 a level, 0: not yet lit), kept under STARS_KEY in
 * the page's storage (or `options.storage`); a stored entry that is not such a whole number, or
 * missing, reads as 0.
 */
export function bestStarsStore(options?: StorageOptions): StoredValue<number[]> {
  const perLevel = listCheck(numberCheck({ max: 3, integer: true }), LEVELS.length, 0);
  return storedValue(
    STARS_KEY,
    perLevel,
    LEVELS.map(() => 0),
    options,
  );
}
