/**
 * The submarine's marks at the view's leading edge (games/submarine/edge-marks.ts, issue 34): on a
 * 390 px phone at full ahead the clear view ends about 54 m ahead of the hull's centre (measured in
 * the page: 4.5 px/m, the view's centre 16.5 m ahead of the hull, the depth gauge's 40 px left out),
 * 48 m ahead of the bow, 6 s at 8 m/s, and a stranger met mines and the seabed coming from off the
 * screen with no time to react. The marks show each hazard beyond that edge up to 100 m ahead of
 * the bow: 12.5 s of warning.
 */

import { describe, expect, it } from 'vitest';
import { EDGE_MARK_BED_ROOM, EDGE_MARK_REACH, edgeMarks, warningSeconds } from '../../games/submarine/edge-marks';

/** The phone's clear view ahead of the hull's centre at full ahead, m (see above). */
const PHONE_EDGE = 54;
/** A flat floor 100 m down. */
const floor = () => -100;

describe('submarine edge marks', () => {
  it('on a phone at full ahead, a mine 90 m ahead of the bow is marked: over 11 s of warning, not 6', () => {
    // Hull at (0, -20): its bow at 6 m. Mines: one in view (no mark: it is seen), one 90 m ahead
    // of the bow, one set off (gone), one past the marks' reach.
    const mines = [
      { x: 40, y: -20 },
      { x: 96, y: -24 },
      { x: 80, y: -20 },
      { x: 6 + EDGE_MARK_REACH + 5, y: -20 },
    ];
    const marks = edgeMarks(PHONE_EDGE, 0, -20, mines, [true, true, false, true], floor);
    expect(marks.map((m) => [m.kind, m.x, m.y])).toEqual([['mine', 96, -24]]);
    expect(marks[0]!.ahead).toBeCloseTo(90, 12);
    // The view alone: 48 m, 6 s; with the marks the nearest hazard shown is seen 11 s or more ahead.
    expect(warningSeconds(PHONE_EDGE - 6)).toBeCloseTo(6, 12);
    expect(warningSeconds(marks[0]!.ahead)).toBeGreaterThan(11);
    expect(warningSeconds(EDGE_MARK_REACH)).toBeCloseTo(12.5, 12);
  });

  it('marks the nearest mine first, and looks behind when backing', () => {
    const mines = [
      { x: 90, y: -30 },
      { x: 70, y: -10 },
      { x: -80, y: -20 },
    ];
    const ahead = edgeMarks(PHONE_EDGE, 0, -20, mines, [true, true, true], floor);
    expect(ahead.map((m) => m.x)).toEqual([70, 90]);
    const behind = edgeMarks(-PHONE_EDGE, 0, -20, mines, [true, true, true], floor, -1);
    expect(behind.map((m) => [m.x, m.ahead])).toEqual([[-80, 74]]);
  });

  it('marks a seabed ridge beyond the view that rises near the keel, not the floor going on', () => {
    // A ridge at x = 90 rising to 25 m down (the hull 20 m down, its keel 21.5 m): in the way.
    const ridge = (x: number) => (Math.abs(x - 90) < 10 ? -25 - Math.abs(x - 90) : -100);
    const marks = edgeMarks(PHONE_EDGE, 0, -20, [], [], ridge);
    expect(marks).toHaveLength(1);
    expect(marks[0]!.kind).toBe('ridge');
    expect(marks[0]!.x).toBeCloseTo(90, 6);
    expect(marks[0]!.y).toBeCloseTo(-25, 6);
    // The same ridge far under the keel (the hull 40 m higher), and the flat floor: no mark.
    expect(edgeMarks(PHONE_EDGE, 0, 20, [], [], ridge)).toEqual([]);
    expect(edgeMarks(PHONE_EDGE, 0, -95 + EDGE_MARK_BED_ROOM, [], [], floor)).toEqual([]);
  });

  it('rejects a non-finite place and a reach that is not positive', () => {
    expect(() => edgeMarks(Number.NaN, 0, 0, [], [], floor)).toThrow(RangeError);
    expect(() => edgeMarks(0, 0, 0, [], [], floor, 1, 0)).toThrow(RangeError);
  });
});
