/**
 * The submarine game's levels: each a course of its own, harder than the one before. Level 1 is the
 * page's course as it always was (the seed and beacon count of the page, the mines of
 * ./mines.ts MINE_LAYOUT); each later one adds beacons (shorter legs, more of them), lays its sea
 * from another seed, and lays more mines, nearer the straight way between the beacons (narrower
 * passages between the mines and that way, which the glow trail follows) and nearer each other.
 * Headless, tested in node (test/games/submarine-levels.test.ts).
 */

import { numberCheck, type StorageOptions, type StoredRecord, storedRecord } from '@bitphysics/game-kit';
import { MINE_GAP, MINE_LAYOUT, MINE_LEAD, MINE_PATH_CLEARANCE, MINE_WAY_CLEARANCE, type MineLayout } from './mines';

/** A level's course. */
export interface Level {
  /** The level's number, from 1. */
  number: number;
  /** Beacons added to the page's count (its `beacons` setting). */
  extraBeacons: number;
  /** Added to the page's seed, so that each level has a sea and a course of its own, s (any integer; 0 on level 1). */
  seedOffset: number;
  /** How its mines are laid (./mines.ts layMines). */
  mines: Readonly<MineLayout>;
}

/**
 * The levels, easiest first. Level 2: two more beacons, three places for a mine on each leg, the
 * mines 1.5 m nearer the way (8.4 m from it to 11.4 m) and 5 m nearer each other (35 m: at full
 * ahead, 8 m/s, 4.4 s, still warned of, MINE_WARN_TIME 5 s, before the one before is passed).
 * Level 3: four more, the mines 2.5 m nearer the way (7.4 m, to 8.9 m: the hull passes with 3.5 m
 * over its 3.9 m of contact reach) and 30 m apart, 35 m past a beacon (4.4 s at full ahead).
 */
export const LEVELS: readonly Readonly<Level>[] = Object.freeze([
  Object.freeze({ number: 1, extraBeacons: 0, seedOffset: 0, mines: MINE_LAYOUT }),
  Object.freeze({
    number: 2,
    extraBeacons: 2,
    seedOffset: 101,
    mines: Object.freeze({
      clearance: MINE_PATH_CLEARANCE - 1.5,
      room: 3,
      lead: MINE_LEAD - 5,
      gap: MINE_GAP - 5,
      places: Object.freeze([[0.3, 0.42] as const, [0.55, 0.67] as const, [0.78, 0.9] as const]),
    }),
  }),
  Object.freeze({
    number: 3,
    extraBeacons: 4,
    seedOffset: 202,
    mines: Object.freeze({
      clearance: MINE_WAY_CLEARANCE + 0.5,
      room: 1.5,
      lead: MINE_LEAD - 10,
      gap: MINE_GAP - 10,
      places: Object.freeze([[0.28, 0.38] as const, [0.5, 0.6] as const, [0.72, 0.82] as const, [0.86, 0.92] as const]),
    }),
  }),
]);

/** The most beacons a course has (the page's `beacons` setting's top). */
export const MAX_BEACONS = 20;

/**
 * Level `number`'s course on a page whose seed is `seed` and whose beacon count is `beacons`: the
 * seed its sea is laid from, its beacon count (at most `MAX_BEACONS`) and its mines' layout.
 * @throws RangeError when `number` is not an integer from 1 to LEVELS.length, `seed` is not finite
 * or `beacons` is not an integer from 1 to MAX_BEACONS.
 */
export function levelCourse(number: number, seed: number, beacons: number): { seed: number; beacons: number; mines: Readonly<MineLayout> } {
  if (!(Number.isInteger(number) && number >= 1 && number <= LEVELS.length))
    throw new RangeError(`levelCourse: number must be an integer from 1 to ${LEVELS.length}, got ${number}`);
  if (!Number.isFinite(seed)) throw new RangeError(`levelCourse: seed must be finite, got ${seed}`);
  if (!(Number.isInteger(beacons) && beacons >= 1 && beacons <= MAX_BEACONS))
    throw new RangeError(`levelCourse: beacons must be an integer from 1 to ${MAX_BEACONS}, got ${beacons}`);
  const level = LEVELS[number - 1]!;
  return { seed: seed + level.seedOffset, beacons: Math.min(MAX_BEACONS, beacons + level.extraBeacons), mines: level.mines };
}

/** The storage key of the best times: a JSON object of course key (main.ts bestKey) to the best time won, s. */
export const BEST_TIMES_KEY = 'bitphysics.submarine.best';
/** The longest best time kept, s (11.6 days of play): a longer one stored is garbage and reads as none. */
export const MAX_BEST_TIME = 1e6;

/**
 * The best time of each course won, s in [0, MAX_BEST_TIME], kept under BEST_TIMES_KEY in the page's
 * storage (or `options.storage`); an entry outside that range, or not a number, reads as none.
 */
export function bestTimes(options?: StorageOptions): StoredRecord<number> {
  return storedRecord(BEST_TIMES_KEY, numberCheck({ max: MAX_BEST_TIME }), options);
}
