/**
 * The bouncing-balls court leaves the way from the heap to the hoop open (issue 34: on a phone the
 * right ramp's end stood under the first hoop and a bar hung over the heap, so most throws from the
 * heap ran into a ramp, and balls rolled under the low ramps where no throw got out). Checked against
 * the layouts' geometry and against reach.ts's search for clean baskets (throwPath, independent of
 * the page): from the top of the heap in front of the first hoop, most starts have a clean basket
 * (the layouts before had one from 4 of 12 such starts on the phone, 15 of 23 on a desktop).
 */
import { describe, expect, it } from 'vitest';
import { BACKBOARD, hoopSpots, MAX_THROW_SPEED, PLAYER_RADIUS } from '../../games/bouncing-balls/hoop';
import { cleanBasket } from '../../games/bouncing-balls/reach';
import { layoutOf, SEGMENT_RADIUS } from '../../games/bouncing-balls/scene';

/** Height of the top of the starting heap, m (about 2 m for the phone's 20 balls, 2.5 m for 40: the page's settled heaps). */
const HEAP_TOP = { tall: 2, wide: 2.5 };

describe('bouncing balls court: the ramps leave the heap a clear way to the hoops', () => {
  for (const tall of [true, false]) {
    const name = tall ? 'tall' : 'wide';
    it(`${name}: every ramp lies above every hoop's backboard, and far over the heap (no pocket under a ramp a heap ball rolls into)`, () => {
      const { segments } = layoutOf(tall);
      const top = Math.max(...hoopSpots(tall).map((s) => s.y + BACKBOARD.above));
      for (const [, ay, , by] of segments) {
        const low = Math.min(ay, by) - SEGMENT_RADIUS;
        expect(low).toBeGreaterThan(top);
        // Room for three balls stacked on the heap's top below it.
        expect(low - HEAP_TOP[name]).toBeGreaterThan(6 * PLAYER_RADIUS);
      }
    });

    it(`${name}: from the heap's top in front of the first hoop, three starts in four have a clean basket`, () => {
      const spot = hoopSpots(tall)[0]!;
      const { box } = layoutOf(tall);
      const y = HEAP_TOP[name] + PLAYER_RADIUS;
      let starts = 0,
        open = 0;
      // In front of the hoop (its backboard's other side), not under it: its net stops a ball thrown up into it.
      for (let x = box.min[0] + 0.5; x <= box.max[0] - 0.5 + 1e-9; x += 0.5) {
        if ((x - spot.x) * spot.side > -1.5) continue;
        starts++;
        let found = false;
        for (let angle = 20; angle <= 160 && !found; angle += 2)
          for (let speed = 4; speed <= MAX_THROW_SPEED && !found; speed += 0.5) found = cleanBasket(spot, tall, { x, y, angle, speed });
        if (found) open++;
      }
      expect(open / starts, `${open} of ${starts}`).toBeGreaterThanOrEqual(0.75);
    });
  }
});
