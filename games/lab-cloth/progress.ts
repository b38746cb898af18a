/**
 * The cloth lab's progress, headless: the best stars won on each sheet, kept in the browser's storage
 * over a reload, and the stars a sheet needs to be passed. Storage may be missing (a locked-down
 * browser) or throw (private mode, a full quota, a blocked origin): then the progress lasts as long
 * as the page, and nothing fails (the game kit's storedValue).
 */

import { type KeyValueStorage, listCheck, numberCheck, pageStorage, type StoredValue, storedValue } from '@bitphysics/game-kit';

/** The storage key of the best stars per sheet (a JSON array of integers, -1: not finished). */
export const PROGRESS_KEY = 'bitphysics.lab-cloth.best';

/** What the progress needs of a storage (the browser's localStorage): its getItem and setItem. */
export type ProgressStore = KeyValueStorage;

/**
 * Stars a sheet of `targets` targets needs to be passed, of 3 per target: two per target on average,
 * less one (5 of 9 for three shapes, 7 of 12 for the window's panes, 1 of 3 for the peg bag: in
 * the basket). @throws RangeError if `targets` is not an integer >= 1.
 */
export function passMark(targets: number): number {
  if (!(Number.isInteger(targets) && targets >= 1)) throw new RangeError(`passMark: targets must be an integer >= 1, got ${targets}`);
  return 2 * targets - 1;
}

/** The browser's localStorage, or null where there is none or reading it throws. */
export function browserStore(): ProgressStore | null {
  return pageStorage();
}

/** The progress of `levels` sheets kept in `store` (none: null): each an integer in [-1, 99], -1 where missing or bad. */
function progressIn(store: ProgressStore | null, levels: number): StoredValue<number[]> {
  const perSheet = listCheck(numberCheck({ min: -1, max: 99, integer: true }), levels, -1);
  return storedValue(
    PROGRESS_KEY,
    perSheet,
    Array.from({ length: levels }, () => -1),
    { storage: store },
  );
}

/**
 * The best stars per sheet saved in `store` for `levels` sheets (an integer from 0 to 3 per target,
 * or -1: not finished), -1 for each sheet whatever is missing, unreadable or not such an integer.
 * @throws RangeError if `levels` is not an integer >= 1.
 */
export function loadProgress(store: ProgressStore | null, levels: number): number[] {
  if (!(Number.isInteger(levels) && levels >= 1)) throw new RangeError(`loadProgress: levels must be an integer >= 1, got ${levels}`);
  return progressIn(store, levels).read();
}

/**
 * Saves the best stars per sheet `best` (as loadProgress returns them) in `store`. @returns whether it was saved.
 * @throws RangeError if an entry of `best` is not an integer in [-1, 99].
 */
export function saveProgress(store: ProgressStore | null, best: readonly number[]): boolean {
  return progressIn(store, best.length).write(best.slice());
}

/**
 * Records `won` stars on sheet `i` in `best` (as loadProgress returns them) if the sheet was passed
 * (`passed`) with more stars than its best so far: a failure is never a best (a stranger who
 * failed the window saw "Best 0/12 ★"). @returns whether `best` changed (then save it).
 */
export function recordBest(best: number[], i: number, won: number, passed: boolean): boolean {
  if (!passed || !(won > best[i]!)) return false;
  best[i] = won;
  return true;
}
