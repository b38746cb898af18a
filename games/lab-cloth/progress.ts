/**
 * The cloth lab's progress, headless: the best stars won on each sheet, kept in the browser's storage
 * over a reload, and the stars a sheet needs to be passed. Storage may be missing (a locked-down
 * browser) or throw (private mode, a full quota, a blocked origin): then the progress lasts as long
 * as the page, and nothing fails.
 */

/** The storage key of the best stars per sheet (a JSON array of integers, -1: not finished). */
export const PROGRESS_KEY = 'bitphysics.lab-cloth.best';

/** What the progress needs of a storage (the browser's localStorage). */
export interface ProgressStore {
  getItem(key: string): string | null;
  setItem(key: string, value: string): void;
}

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
  try {
    return typeof localStorage === 'undefined' ? null : localStorage;
  } catch {
    return null;
  }
}

/**
 * The best stars per sheet saved in `store` for `levels` sheets (an integer from 0 to 3 per target,
 * or -1: not finished), -1 for each sheet whatever is missing, unreadable or not such an integer.
 * @throws RangeError if `levels` is not an integer >= 1.
 */
export function loadProgress(store: ProgressStore | null, levels: number): number[] {
  if (!(Number.isInteger(levels) && levels >= 1)) throw new RangeError(`loadProgress: levels must be an integer >= 1, got ${levels}`);
  const out = Array.from({ length: levels }, () => -1);
  let saved: unknown = null;
  try {
    const text = store?.getItem(PROGRESS_KEY);
    saved = text ? JSON.parse(text) : null;
  } catch {
    return out;
  }
  if (!Array.isArray(saved)) return out;
  for (let i = 0; i < levels; i++) {
    const v = saved[i];
    if (Number.isInteger(v) && v >= 0 && v <= 99) out[i] = v;
  }
  return out;
}

/** Saves the best stars per sheet `best` (as loadProgress returns them) in `store`. @returns whether it was saved. */
export function saveProgress(store: ProgressStore | null, best: readonly number[]): boolean {
  if (!store) return false;
  try {
    store.setItem(PROGRESS_KEY, JSON.stringify(best));
    return true;
  } catch {
    return false;
  }
}
