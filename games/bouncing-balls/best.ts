/**
 * The hoop game's best score, kept in the browser's storage across reloads, one per court layout
 * (the wide court and a phone's tall one put the hoop in different spots, so their scores differ).
 * Storage may be missing or throw (private modes, blocked cookies): then the best lasts the page's
 * life (the game kit's storedValue). Pure apart from the storage passed in (no DOM).
 */

import { type KeyValueStorage, pageStorage as kitPageStorage, numberCheck, type StoredValue, storedValue } from '@bitphysics/game-kit';

/** The storage this needs: localStorage's getItem and setItem. */
export type BestStorage = KeyValueStorage;

/** The most points a best may be: far over a round's reach, so a higher stored one is garbage. */
export const MAX_BEST = 1e9;

/** The wide court's key (the one the game has always used, so a best kept before stays). */
export const BEST_KEY = 'bitphysics.bouncing-balls.best-points';
/** The tall (phone) court's key. */
export const BEST_KEY_TALL = `${BEST_KEY}.tall`;

/** The key of the best for the tall (phone) court or the wide one. */
export function bestKey(tall: boolean): string {
  return tall ? BEST_KEY_TALL : BEST_KEY;
}

/** The best kept under `key` in `storage`: whole points in [0, MAX_BEST], 0 where missing, garbled, negative or fractional. */
function bestUnder(storage: BestStorage | null, key: string): StoredValue<number> {
  return storedValue(key, numberCheck({ max: MAX_BEST, integer: true }), 0, { storage });
}

/**
 * The best kept for the court (`tall` or wide) in `storage`, 0 when none, unreadable or not a whole
 * number of points in [0, MAX_BEST]. The tall court with no best of its own takes the wide key's: a
 * phone's best was kept there before the courts had one each.
 */
export function readBest(storage: BestStorage | null, tall: boolean): number {
  const own = bestUnder(storage, bestKey(tall)).read();
  return own > 0 || !tall ? own : bestUnder(storage, BEST_KEY).read();
}

/**
 * Writes `best` points as the court's best in `storage`; a missing or failing storage is ignored.
 * @throws RangeError if `best` is not a whole number in [0, MAX_BEST].
 */
export function writeBest(storage: BestStorage | null, tall: boolean, best: number): void {
  bestUnder(storage, bestKey(tall)).write(best);
}

/** The page's localStorage, or null where reading it throws (some private modes) or there is none. */
export const pageStorage: () => BestStorage | null = kitPageStorage;
