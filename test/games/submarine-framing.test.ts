/**
 * The submarine's framing on a portrait phone under way (games/submarine/framing.ts): at cruising
 * speed the view leads the hull so far that the sea ahead of the bow covers what a pilot needs to
 * see (aheadNeeded: the mine warning's reach and the time to spot a mine, at that speed), with the
 * hull still large and its stern off the trailing edge. Issue 34: a stranger on a phone saw too
 * little ahead of a tiny boat.
 */

import { SUBMARINE } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import {
  aheadNeeded,
  CRUISE_SPEED,
  fullLead,
  HULL_SIDE_ROOM,
  LEAD_SHARE,
  leadLimits,
  PORTRAIT_LEAD_SHARE,
  PORTRAIT_MIN_WIDTH,
  PORTRAIT_MIN_ZOOM_UNDER_WAY,
} from '../../games/submarine/framing';
import { MINE_RADIUS, MINE_REACTION, MINE_WARN_TIME } from '../../games/submarine/mines';

describe('submarine framing', () => {
  it('needs the mine warning reach and 1.5 s to spot it at cruising speed: 54.4 m ahead of the bow at 8 m/s', () => {
    expect(aheadNeeded(CRUISE_SPEED)).toBeCloseTo(8 * (MINE_WARN_TIME + MINE_REACTION + 0.5) + MINE_RADIUS, 9);
    expect(aheadNeeded(CRUISE_SPEED)).toBeCloseTo(54.4, 9);
    expect(() => aheadNeeded(-1)).toThrow(/aheadNeeded: speed/);
  });

  it('a 390 px phone at cruise (4.5 to 4.53 px/m) shows that much ahead of the bow, the hull 54 px long with its stern 60 px in (it showed 49 m)', () => {
    // Under way on a portrait view the zoom lies between the least under way and the view at least
    // PORTRAIT_MIN_WIDTH across (main.ts draw); the view at its full lead (the look-ahead eased in).
    const W = 390;
    for (const k of [PORTRAIT_MIN_ZOOM_UNDER_WAY, W / PORTRAIT_MIN_WIDTH]) {
      const { hullX, ahead } = fullLead(W, k, true);
      console.log(
        `390 px phone at ${k.toFixed(2)} px/m: hull ${(SUBMARINE.length * k).toFixed(0)} px, centre ${((100 * hullX) / W).toFixed(0)}% in, ${ahead.toFixed(1)} m ahead of the bow`,
      );
      expect(ahead).toBeGreaterThanOrEqual(aheadNeeded(CRUISE_SPEED));
      expect(SUBMARINE.length * k).toBeGreaterThanOrEqual(54 - 0.5); // the hull readable: 43 px read as tiny
      expect(hullX - (SUBMARINE.length / 2) * k).toBeGreaterThanOrEqual(HULL_SIDE_ROOM); // stern off the edge
    }
    // The lead's limits: a share of the way to the margin, and the stern's room.
    const l = leadLimits(W, 4.5, true);
    expect(l.share).toBe(PORTRAIT_LEAD_SHARE);
    expect(l.reach).toBeCloseTo((PORTRAIT_LEAD_SHARE * (195 - 60)) / 4.5, 9);
    expect(l.hull).toBeCloseTo((195 - 87) / 4.5, 9);
    expect(leadLimits(1280, 8, false).share).toBe(LEAD_SHARE);
    expect(() => leadLimits(0, 4, true)).toThrow(/leadLimits: W/);
  });
});
