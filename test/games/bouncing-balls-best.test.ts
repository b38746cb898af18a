/**
 * bouncing-balls' best score across reloads (games/bouncing-balls/best.ts) with a fake storage: what
 * one page writes the next reads back, one best per court (wide and tall), a bad stored value is 0,
 * and a storage that is missing or throws costs nothing but the keeping.
 */

import { describe, expect, it } from 'vitest';
import { BEST_KEY, BEST_KEY_TALL, type BestStorage, readBest, writeBest } from '../../games/bouncing-balls/best';

/** A Map-backed stand-in for localStorage. */
function fakeStorage(init: Record<string, string> = {}): BestStorage & { data: Map<string, string> } {
  const data = new Map(Object.entries(init));
  return {
    data,
    getItem: (k) => data.get(k) ?? null,
    setItem: (k, v) => {
      data.set(k, v);
    },
  };
}

describe('bouncing-balls best score', () => {
  it("a best written by one page is read by the next (a reload), each court's on its own", () => {
    const storage = fakeStorage();
    expect(readBest(storage, false)).toBe(0);
    writeBest(storage, false, 8);
    // The reload: a fresh read of the same storage.
    expect(readBest(storage, false)).toBe(8);
    expect(storage.data.get(BEST_KEY)).toBe('8');
    // The tall court keeps its own: 3 there leaves the wide court's 8.
    writeBest(storage, true, 3);
    expect(readBest(storage, true)).toBe(3);
    expect(readBest(storage, false)).toBe(8);
    expect(storage.data.get(BEST_KEY_TALL)).toBe('3');
  });

  it('the tall court with no best of its own reads the one kept before the courts had one each', () => {
    expect(readBest(fakeStorage({ [BEST_KEY]: '12' }), true)).toBe(12);
    expect(readBest(fakeStorage({ [BEST_KEY]: '12', [BEST_KEY_TALL]: '5' }), true)).toBe(5);
  });

  it('a bad stored value is no best (0)', () => {
    for (const bad of ['', ' ', 'abc', '-4', '2.5', 'NaN', 'Infinity', '1e400', '0'])
      expect(readBest(fakeStorage({ [BEST_KEY]: bad }), false), JSON.stringify(bad)).toBe(0);
  });

  it('a missing storage, or one that throws, gives 0 and keeps nothing, without throwing', () => {
    const throwing: BestStorage = {
      getItem: () => {
        throw new Error('SecurityError');
      },
      setItem: () => {
        throw new Error('QuotaExceededError');
      },
    };
    expect(readBest(null, false)).toBe(0);
    expect(readBest(throwing, true)).toBe(0);
    expect(() => writeBest(null, false, 3)).not.toThrow();
    expect(() => writeBest(throwing, false, 3)).not.toThrow();
  });
});
