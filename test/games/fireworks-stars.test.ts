/**
 * Fireworks' best stars per level across reloads (games/fireworks/lanterns.ts bestStarsStore) with a
 * Map-backed storage: the list the game kept before the game kit's storedValue reads back unchanged,
 * and a garbled entry reads as a level not yet lit.
 */
import type { KeyValueStorage } from '@bitphysics/game-kit';
import { describe, expect, it } from 'vitest';
import { bestStarsStore, LEVELS, STARS_KEY } from '../../games/fireworks/lanterns';

/** A Map-backed stand-in for localStorage. */
function memory(init: Record<string, string> = {}): KeyValueStorage & { data: Map<string, string> } {
  const data = new Map(Object.entries(init));
  return { data, getItem: (k) => data.get(k) ?? null, setItem: (k, v) => void data.set(k, v) };
}

describe('fireworks best stars', () => {
  it('reads the list as the game always kept it, and writes it in the same form', () => {
    expect(STARS_KEY).toBe('bitphysics.fireworks.stars');
    expect(LEVELS.length).toBe(5);
    const storage = memory({ [STARS_KEY]: '[3,0,2,0,0]' });
    const stars = bestStarsStore({ storage });
    const best = stars.read();
    expect(best).toEqual([3, 0, 2, 0, 0]);
    best[1] = 1;
    expect(stars.write(best)).toBe(true);
    // The browser test (particles-games.test.ts) reads this exact text.
    expect(storage.data.get(STARS_KEY)).toBe('[3,1,2,0,0]');
  });

  it('a garbled entry is a level not lit; a garbled list, none lit', () => {
    expect(bestStarsStore({ storage: memory({ [STARS_KEY]: '[4,-1,2.5,"3",2,3]' }) }).read()).toEqual([0, 0, 0, 0, 2]);
    expect(bestStarsStore({ storage: memory({ [STARS_KEY]: '[1]' }) }).read()).toEqual([1, 0, 0, 0, 0]);
    for (const junk of ['{', '3', '{"0":3}', 'null'])
      expect(bestStarsStore({ storage: memory({ [STARS_KEY]: junk }) }).read()).toEqual([0, 0, 0, 0, 0]);
    expect(bestStarsStore({ storage: null }).read()).toEqual([0, 0, 0, 0, 0]);
  });
});
