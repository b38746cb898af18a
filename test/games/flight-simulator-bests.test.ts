/**
 * The flight simulator's best result per course across reloads (games/flight-simulator/course.ts
 * courseBests) with a Map-backed storage: the record the game kept before the game kit's
 * storedRecord reads back unchanged, a new best leaves the other courses', and a garbled entry reads
 * as none (so compareWithBest never gets one).
 */
import type { KeyValueStorage } from '@bitphysics/game-kit';
import { describe, expect, it } from 'vitest';
import { BEST_KEY, courseBests } from '../../games/flight-simulator/course';

/** A Map-backed stand-in for localStorage. */
function memory(init: Record<string, string> = {}): KeyValueStorage & { data: Map<string, string> } {
  const data = new Map(Object.entries(init));
  return { data, getItem: (k) => data.get(k) ?? null, setItem: (k, v) => void data.set(k, v) };
}

describe('flight simulator course bests', () => {
  it('reads the record as the game always kept it, and a new best leaves the other courses', () => {
    expect(BEST_KEY).toBe('bitphysics.flight-simulator.best');
    const storage = memory({ [BEST_KEY]: '{"1/10":{"passed":10,"time":95.5},"2/5":{"passed":3,"time":140}}' });
    const bests = courseBests({ storage });
    expect(bests.get('1/10')).toEqual({ passed: 10, time: 95.5 });
    expect(bests.set('2/5', { passed: 5, time: 88 })).toBe(true);
    expect(JSON.parse(storage.data.get(BEST_KEY)!)).toEqual({ '1/10': { passed: 10, time: 95.5 }, '2/5': { passed: 5, time: 88 } });
  });

  it('an entry not of the shape, or out of range, is none', () => {
    const bad = [
      '{"passed":10}',
      '{"passed":-1,"time":9}',
      '{"passed":2.5,"time":9}',
      '{"passed":3,"time":"9"}',
      '[3,9]',
      '5',
      '{"passed":3,"time":1e300}',
    ];
    const storage = memory({ [BEST_KEY]: `{${bad.map((v, i) => `"c${i}":${v}`).join(',')}}` });
    const bests = courseBests({ storage });
    for (let i = 0; i < bad.length; i++) expect(bests.get(`c${i}`), bad[i]).toBeUndefined();
    expect(courseBests({ storage: null }).get('1/10')).toBeUndefined();
  });
});
