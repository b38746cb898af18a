/**
 * Catapult, headless play for checking levels (no DOM): throws a sequence of pulls at a level as the
 * page would and counts what fell, and a coarse greedy search over pull angle and power for a
 * sequence that clears a level within its shots. The search is for scripts/catapult-levels.mjs (it
 * takes a few seconds a level); test/games/catapult.test.ts replays the sequences it found
 * (`LEVEL_SOLUTIONS`) and runs the search on the first level only.
 */
import { createPhysicsWorld, type PhysicsWorld, restore, snapshot, step } from '@bitphysics/physics';
import { buildLevel, countedDown, LEVEL_COUNT, type Level, launch, PULL, rollingBodies, tally, worldOptions } from './scene';

export { LEVEL_COUNT, levelName } from './scene';

/** Share of a level's pieces that must fall to clear it (one star; the page's PASS_SHARE). */
export const CLEAR_SHARE = 0.5;
/** The page's defaults: gravity, m/s^2, weld strength, N, and the thrown stone's mass, kg. */
export const PAGE_DEFAULTS = { gravity: 9.81, jointStrength: 400, projectileMass: 3 } as const;
/** Steps (60 Hz) between two throws of a sequence, and after the last before it is counted. */
export const STEPS_BETWEEN = 150,
  STEPS_AFTER = 240;

/** A throw: angle above level, degrees, and power, the share (0 to 1] of a full pull. */
export interface Throw {
  angle: number;
  power: number;
}

/**
 * For each level (index 0-based), throws that clear it on seed 1 (the page's), found by
 * scripts/catapult-levels.mjs (`searchLevel`, share 0.5) and replayed by the test: a level whose
 * castle or rules change gets its throws found again there.
 */
export const LEVEL_SOLUTIONS: ReadonlyArray<readonly Throw[]> = [
  [{ angle: 10, power: 0.5 }],
  [{ angle: 10, power: 0.7 }],
  [{ angle: 25, power: 0.8 }],
  [{ angle: 10, power: 0.8 }],
  [{ angle: 10, power: 0.85 }],
  [{ angle: 15, power: 1 }],
  [{ angle: 20, power: 0.7 }],
  [{ angle: 15, power: 1 }],
  [
    { angle: 15, power: 0.75 },
    { angle: 20, power: 0.65 },
    { angle: 25, power: 0.95 },
    { angle: 25, power: 1 },
  ],
];

/** The pieces that must fall to clear a level of `pieces` pieces that count (CLEAR_SHARE, rounded up). */
export function clearTarget(pieces: number): number {
  return Math.ceil(CLEAR_SHARE * pieces);
}

/** A fresh world with level `level` (0-based) of seed `seed`, as the page builds it. */
function fresh(level: number, seed: number): { world: PhysicsWorld; lv: Level } {
  const world = createPhysicsWorld(worldOptions(PAGE_DEFAULTS));
  const lv = buildLevel(world, { level, seed, gravity: PAGE_DEFAULTS.gravity, jointStrength: PAGE_DEFAULTS.jointStrength });
  return { world, lv };
}

/** Throws `t` from the cup: the launch speed PULL.gain x PULL.max x power at t.angle. */
function fire(world: PhysicsWorld, t: Throw): void {
  const v = PULL.gain * PULL.max * t.power,
    a = (t.angle * Math.PI) / 180;
  launch(world, v * Math.cos(a), v * Math.sin(a), PAGE_DEFAULTS.projectileMass);
}

/** Steps `world` n times, tallying (a piece's fall is kept once seen). */
function run(world: PhysicsWorld, lv: Level, n: number): void {
  for (let i = 0; i < n; i++) {
    step(world);
    if (i % 10 === 9) tally(world, lv);
  }
  tally(world, lv);
}

/**
 * Plays `throws` at level `level` (0-based) of seed `seed`: each throw STEPS_BETWEEN steps after the
 * last (1 s after the start for the first), and STEPS_AFTER steps after the last.
 * @returns the pieces fallen and the level's piece count; of the pieces that count toward its share
 * (`countsTowardStars`), how many are down and how many there are; and whether that clears it.
 * @throws RangeError on a level out of range or a throw out of range (angle in [-90, 90], power in (0, 1]).
 */
export function playThrows(
  level: number,
  seed: number,
  throws: readonly Throw[],
): { fallen: number; pieces: number; down: number; counted: number; cleared: boolean } {
  for (const t of throws)
    if (!(t.angle >= -90 && t.angle <= 90 && t.power > 0 && t.power <= 1))
      throw new RangeError(`playThrows: each throw needs angle in [-90, 90] and power in (0, 1], got ${JSON.stringify(t)}`);
  const { world, lv } = fresh(level, seed);
  run(world, lv, 60);
  throws.forEach((t, i) => {
    fire(world, t);
    run(world, lv, i === throws.length - 1 ? STEPS_AFTER : STEPS_BETWEEN);
  });
  const fallen = tally(world, lv).fallen;
  const counted = countedDown(lv);
  return { fallen, pieces: lv.pieces.length, down: counted.down, counted: counted.of, cleared: counted.down >= clearTarget(counted.of) };
}

/** Options of `searchLevel`. */
export interface SearchOptions {
  /** Angles tried, degrees. Default 10 to 70 in steps of 5. */
  angles?: readonly number[];
  /** Powers tried. Default 0.5 to 1 in steps of 0.05. */
  powers?: readonly number[];
  /** Most candidates simulated for each throw (those whose drag-free arc meets the castle, spread over them). Default 14. */
  perThrow?: number;
  /** Share of the pieces to bring down, in (0, 1]. Default CLEAR_SHARE (one star; 0.95 is three). */
  share?: number;
}

/**
 * A coarse greedy search for throws that bring down `o.share` of the pieces of level `level`
 * (0-based) of seed `seed` (by default enough to clear it) within its shots: for each throw, of the grid's (angle, power) pairs whose drag-free arc passes through the
 * castle's box (`Level.castleMinX` to `castleMaxX`, up to `castleTop`), up to `perThrow` spread
 * evenly over them are each simulated STEPS_BETWEEN steps from the same state (snapshot and
 * restore), and the one that brings most down is kept; it stops as soon as the level is cleared.
 * @returns the throws kept, the pieces they bring down (played again by `playThrows`) and whether
 *   that is the share asked for.
 * @throws RangeError on a level out of range.
 */
export function searchLevel(level: number, seed: number, o: SearchOptions = {}): { throws: Throw[]; cleared: boolean; fallen: number } {
  if (!Number.isInteger(level) || level < 0 || level >= LEVEL_COUNT)
    throw new RangeError(`searchLevel: level must be an integer in [0, ${LEVEL_COUNT}), got ${level}`);
  const angles = o.angles ?? Array.from({ length: 13 }, (_, i) => 10 + 5 * i);
  const powers = o.powers ?? Array.from({ length: 11 }, (_, i) => (50 + 5 * i) / 100);
  const perThrow = o.perThrow ?? 14;
  const { world, lv } = fresh(level, seed);
  run(world, lv, 60);
  const g = PAGE_DEFAULTS.gravity;
  // The grid's pairs whose drag-free arc from the cup comes down into the castle's box.
  const candidates: Throw[] = [];
  for (const angle of angles)
    for (const power of powers) {
      const v = PULL.gain * PULL.max * power,
        a = (angle * Math.PI) / 180;
      const vx = v * Math.cos(a),
        vy = v * Math.sin(a);
      let meets = false;
      for (let t = 0; t < 4 && !meets; t += 0.02) {
        const x = vx * t,
          y = 1.5 + vy * t - 0.5 * g * t * t;
        if (y < -2) break;
        meets = x >= lv.castleMinX - 0.3 && x <= lv.castleMaxX && y <= lv.castleTop;
      }
      if (meets) candidates.push({ angle, power });
    }
  const need = Math.ceil((o.share ?? CLEAR_SHARE) * countedDown(lv).of);
  const throws: Throw[] = [];
  const rolling = rollingBodies(world);
  const downNow = (): number => {
    tally(world, lv);
    return countedDown(lv).down;
  };
  for (let k = 0; k < lv.shots && downNow() < need; k++) {
    const saved = snapshot(world),
      down = lv.pieces.map((p) => p.down === true),
      rollingLength = rolling.length;
    const back = (): void => {
      restore(world, saved);
      lv.pieces.forEach((p, i) => {
        p.down = down[i];
      });
      rolling.length = rollingLength;
    };
    let best: Throw | null = null,
      bestFallen = -1;
    // Spread over the candidates, starting from a different one each throw.
    const stride = Math.max(1, Math.floor(candidates.length / perThrow));
    for (let i = 0; i < Math.min(perThrow, candidates.length); i++) {
      const c = candidates[(k + i * stride) % candidates.length]!;
      fire(world, c);
      run(world, lv, STEPS_BETWEEN);
      const fallen = downNow();
      back();
      if (fallen > bestFallen) {
        bestFallen = fallen;
        best = c;
      }
      if (fallen >= need) break;
    }
    if (best === null) break;
    throws.push(best);
    fire(world, best);
    run(world, lv, STEPS_BETWEEN);
  }
  const check = playThrows(level, seed, throws);
  return { throws, cleared: check.down >= need, fallen: check.fallen };
}
