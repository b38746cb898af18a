/**
 * Catapult's distance marks (games/catapult/distance.ts), headless: every level has at least one
 * mark ("5 m") on flat ground between the catapult and its castle, so the field's scale, which the
 * camera sets per level, reads in metres.
 */

import { createPhysicsWorld } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { DISTANCE_STEP, distanceMarks } from '../../games/catapult/distance';
import { buildLevel, LAUNCH, LEVEL_COUNT, surfaceAt, worldOptions } from '../../games/catapult/scene';

describe('catapult distance marks', () => {
  it('every level: marks every 5 m from the catapult on flat ground, short of the castle, labelled in metres', () => {
    expect(DISTANCE_STEP).toBe(5);
    for (let level = 0; level < LEVEL_COUNT; level++) {
      const w = createPhysicsWorld(worldOptions({ gravity: 9.81 }));
      const lv = buildLevel(w, { level, seed: 1, gravity: 9.81, jointStrength: 400 });
      const marks = distanceMarks(lv);
      // The castles stand 7 to 26 m out: the 5 m mark at least (a hill or pit is further out).
      expect(marks.length, `level ${level + 1}`).toBeGreaterThanOrEqual(1);
      for (const m of marks) {
        const d = m.x - LAUNCH.x;
        expect(d % DISTANCE_STEP, `level ${level + 1}`).toBe(0);
        expect(m.label).toBe(`${d} m`);
        expect(m.x).toBeLessThanOrEqual(lv.castleMinX - 1);
        expect(surfaceAt(lv, m.x)).toBe(0);
      }
    }
  });

  it('no mark on a hill or past the castle', () => {
    const lv = {
      castleMinX: 16,
      terrain: [
        { kind: 'ground', minX: -50, maxX: 50, minY: -1, maxY: 0 },
        { kind: 'hill', minX: 8, maxX: 12, minY: 0, maxY: 2 },
      ],
    } as unknown as Parameters<typeof distanceMarks>[0];
    expect(distanceMarks(lv).map((m) => m.label)).toEqual(['5 m', '15 m']);
  });
});
