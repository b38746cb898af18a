/**
 * The submarine's best times across reloads (games/submarine/levels.ts bestTimes) with a Map-backed
 * storage: a record the game kept before the game kit's storedRecord reads back unchanged, a new
 * best keeps the other courses', and a garbled entry reads as no best.
 */
import type { KeyValueStorage } from '@bitphysics/game-kit';
import { describe, expect, it } from 'vitest';
import { BEST_TIMES_KEY, bestTimes } from '../../games/submarine/levels';

/** A Map-backed stand-in for localStorage. */
function memory(init: Record<string, string> = {}): KeyValueStorage & { data: Map<string, string> } {
  const data = new Map(Object.entries(init));
  return { data, getItem: (k) => data.get(k) ?? null, setItem: (k, v) => void data.set(k, v) };
}

describe('submarine best times', () => {
  it('reads the record as the game always kept it, and a new best leaves the other courses', () => {
    // As the game wrote it: JSON of course key ('seed/beacons', '/L<level>' from level 2) to seconds.
    const storage = memory({ [BEST_TIMES_KEY]: '{"7/5":83.25,"7/7/L2":140.5}' });
    expect(BEST_TIMES_KEY).toBe('bitphysics.submarine.best');
    const bests = bestTimes({ storage });
    expect(bests.get('7/5')).toBe(83.25);
    expect(bests.get('7/7/L2')).toBe(140.5);
    expect(bests.get('8/5')).toBeUndefined();
    expect(bests.set('7/5', 80)).toBe(true);
    expect(JSON.parse(storage.data.get(BEST_TIMES_KEY)!)).toEqual({ '7/5': 80, '7/7/L2': 140.5 });
  });

  it('a garbled or absurd entry is no best; a storage that throws is none', () => {
    const storage = memory({ [BEST_TIMES_KEY]: '{"a":-3,"b":"80","c":null,"d":1e300,"e":12}' });
    const bests = bestTimes({ storage });
    expect(['a', 'b', 'c', 'd'].map((k) => bests.get(k))).toEqual([undefined, undefined, undefined, undefined]);
    expect(bests.get('e')).toBe(12);
    expect(bestTimes({ storage: memory({ [BEST_TIMES_KEY]: '{' }) }).get('e')).toBeUndefined();
    const throwing: KeyValueStorage = {
      getItem: () => {
        throw new Error('SecurityError');
      },
      setItem: () => {
        throw new Error('QuotaExceededError');
      },
    };
    expect(bestTimes({ storage: throwing }).get('e')).toBeUndefined();
    expect(bestTimes({ storage: throwing }).set('e', 10)).toBe(false);
  });
});
