/**
 * The cloth lab's progress, headless (games/lab-cloth/progress.ts): the best stars per sheet kept in
 * a storage over a reload, and nothing fails where the storage is missing or throws; the pass mark.
 */
import { describe, expect, it } from 'vitest';
import { loadProgress, PROGRESS_KEY, type ProgressStore, passMark, recordBest, saveProgress } from '../../games/lab-cloth/progress';

/** A storage in memory, as localStorage. */
function memory(): ProgressStore & { data: Map<string, string> } {
  const data = new Map<string, string>();
  return { data, getItem: (k) => data.get(k) ?? null, setItem: (k, v) => void data.set(k, v) };
}

/** A storage whose every call throws, as a blocked localStorage. */
const throwing: ProgressStore = {
  getItem: () => {
    throw new Error('SecurityError');
  },
  setItem: () => {
    throw new Error('QuotaExceededError');
  },
};

describe('lab-cloth progress', () => {
  it('keeps the best stars per sheet over a reload', () => {
    const store = memory();
    expect(loadProgress(store, 4)).toEqual([-1, -1, -1, -1]);
    expect(saveProgress(store, [7, -1, 3, -1])).toBe(true);
    expect(JSON.parse(store.data.get(PROGRESS_KEY)!)).toEqual([7, -1, 3, -1]);
    // A new page reads them back.
    expect(loadProgress(store, 4)).toEqual([7, -1, 3, -1]);
  });

  it('without a storage, or with one that throws or holds garbage, every sheet is unfinished and nothing throws', () => {
    expect(loadProgress(null, 3)).toEqual([-1, -1, -1]);
    expect(saveProgress(null, [1, 2, 3])).toBe(false);
    expect(loadProgress(throwing, 3)).toEqual([-1, -1, -1]);
    expect(saveProgress(throwing, [1, 2, 3])).toBe(false);
    const store = memory();
    for (const junk of ['{', '"x"', '{"0": 5}', 'null']) {
      store.data.set(PROGRESS_KEY, junk);
      expect(loadProgress(store, 2)).toEqual([-1, -1]);
    }
    // Bad entries are dropped one by one; a shorter list leaves the rest unfinished.
    store.data.set(PROGRESS_KEY, JSON.stringify([5, 'x', -3, 2.5]));
    expect(loadProgress(store, 5)).toEqual([5, -1, -1, -1, -1]);
    expect(() => loadProgress(store, 0)).toThrow(/loadProgress: levels must be an integer >= 1, got 0/);
  });

  it('a sheet is passed with two stars a target on average, less one', () => {
    expect([1, 3, 4].map(passMark)).toEqual([1, 5, 7]);
    expect(() => passMark(0)).toThrow(/passMark: targets must be an integer >= 1, got 0/);
    expect(() => passMark(1.5)).toThrow(RangeError);
  });

  it('a sheet finished short of its pass mark is not recorded as a best; a pass above the best is', () => {
    const best = [-1, 5, -1, -1];
    // The window (12 stars, 7 to pass) failed with 0 stars: no "Best 0/12 ★".
    expect(recordBest(best, 1, 0, false)).toBe(false);
    expect(recordBest(best, 2, 0, false)).toBe(false);
    expect(recordBest(best, 2, 6, false)).toBe(false);
    expect(best).toEqual([-1, 5, -1, -1]);
    expect(recordBest(best, 2, 8, true)).toBe(true);
    expect(recordBest(best, 1, 5, true)).toBe(false);
    expect(recordBest(best, 1, 7, true)).toBe(true);
    expect(best).toEqual([-1, 7, 8, -1]);
  });
});
