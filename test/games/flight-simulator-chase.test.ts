/**
 * The flight simulator's chase framing (games/flight-simulator/chase-view.ts): a ring below the
 * aircraft ahead shows above it on the screen, not behind its fin and tail. With the camera 18 m up
 * (17 degrees over the axis), a ring 40 m below, 150 to 300 m ahead, showed 1.7 to 8.0 degrees above
 * the aircraft's centre (its fin and tail reach about 4 degrees over it); 24 m up, 5.4 to 12.3.
 */
import { describe, expect, it } from 'vitest';
import { CHASE_LOOK, CHASE_OFFSET, chaseAngleBelow } from '../../games/flight-simulator/chase-view';

describe('flight-simulator chase view', () => {
  it('keeps the aircraft 16 degrees under the middle (its lower third) and a level ring ahead near the middle', () => {
    for (const scale of [1, 1.8]) {
      // Within a degree of 16: 0.45 of the 32 degree half height, the aircraft low in the frame.
      expect(Math.abs(chaseAngleBelow(0, 0, scale) - 16)).toBeLessThan(1);
      // A ring at the aircraft's height 400 m on: within 4 degrees of the middle.
      expect(Math.abs(chaseAngleBelow(400, 0, scale))).toBeLessThan(4);
    }
    expect(CHASE_OFFSET[0]).toBeLessThan(0);
    expect(CHASE_LOOK[0]).toBeGreaterThan(0);
  });
  it('shows a ring 40 m below, 150 m ahead, at least 4 degrees above the aircraft (it showed 1.4 to 1.7), and more further on', () => {
    for (const scale of [1, 1.8]) {
      const plane = chaseAngleBelow(0, 0, scale);
      const above = [150, 200, 300].map((d) => plane - chaseAngleBelow(d, 40, scale));
      // 4 degrees: about the fin's and the tail's height over the aircraft's centre on the screen.
      expect(above[0]).toBeGreaterThan(4);
      expect(above[1]).toBeGreaterThan(7);
      expect(above[2]).toBeGreaterThan(10);
    }
  });
});
