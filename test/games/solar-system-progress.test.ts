/**
 * The solar system's progress across reloads (games/solar-system/missions.ts missionProgress) with a
 * Map-backed storage: the stars, scores and last mission the game kept before the game kit's
 * storedValue read back unchanged and are written in the same form; a garbled entry reads as 0.
 */
import type { KeyValueStorage } from '@bitphysics/game-kit';
import { describe, expect, it } from 'vitest';
import { LAST_MISSION_KEY, MISSIONS, missionProgress, SCORES_KEY, STARS_KEY } from '../../games/solar-system/missions';

/** A Map-backed stand-in for localStorage. */
function memory(init: Record<string, string> = {}): KeyValueStorage & { data: Map<string, string> } {
  const data = new Map(Object.entries(init));
  return { data, getItem: (k) => data.get(k) ?? null, setItem: (k, v) => void data.set(k, v) };
}

describe('solar system progress', () => {
  it('reads stars, scores and the last mission as the game always kept them', () => {
    expect([STARS_KEY, SCORES_KEY, LAST_MISSION_KEY]).toEqual([
      'bitphysics.solar-system.stars',
      'bitphysics.solar-system.scores',
      'bitphysics.solar-system.mission',
    ]);
    expect(MISSIONS.length).toBe(7);
    const storage = memory({ [STARS_KEY]: '[3,2,0,1,2,0,0]', [SCORES_KEY]: '[1210,980,0,640,700,0,0]', [LAST_MISSION_KEY]: '4' });
    const p = missionProgress({ storage });
    expect(p.stars.read()).toEqual([3, 2, 0, 1, 2, 0, 0]);
    expect(p.scores.read()).toEqual([1210, 980, 0, 640, 700, 0, 0]);
    expect(p.last.read()).toBe(4);
    expect(p.last.write(5)).toBe(true);
    expect(storage.data.get(LAST_MISSION_KEY)).toBe('5');
    expect(p.stars.write([3, 3, 0, 1, 2, 0, 0])).toBe(true);
    expect(storage.data.get(STARS_KEY)).toBe('[3,3,0,1,2,0,0]');
  });

  it('a garbled entry reads as 0, and so does a mission index out of range', () => {
    const storage = memory({ [STARS_KEY]: '[4,-1,2.5,"3",2]', [SCORES_KEY]: '[-5,1e300,12.5,300]', [LAST_MISSION_KEY]: '7' });
    const p = missionProgress({ storage });
    expect(p.stars.read()).toEqual([0, 0, 0, 0, 2, 0, 0]);
    expect(p.scores.read()).toEqual([0, 0, 0, 300, 0, 0, 0]);
    expect(p.last.read()).toBe(0);
    for (const v of ['-1', '2.5', 'abc', ''])
      expect(missionProgress({ storage: memory({ [LAST_MISSION_KEY]: v }) }).last.read(), v).toBe(0);
  });
});
