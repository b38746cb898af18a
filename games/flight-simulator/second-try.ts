/**
 * A second try at a missed ring: the first time a ring is missed it is not lost, it comes round again
 * (the game lays it just ahead, ./course.ts relayAfterMiss, as a go-around), and the try costs
 * MISS_PENALTY s on the course clock but no star; missed again, it is missed for good (a star's share
 * and the time, as every miss: ./course.ts courseStars, courseTime). So one slip is put right by
 * flying it again, as a player expects, while a run of misses still costs the stars. Headless (no
 * DOM), tested in node (test/games/flight-simulator-course.test.ts).
 */

import type { Ring, RingEvent } from './course';

/** What a move did to a ring after the second-try rule: 'again' is a first miss, the ring still ahead. */
export interface TryEvent {
  /** The ring's index. */
  ring: number;
  /** Flown through; missed for good; or missed for the first time and to be flown again. */
  result: 'passed' | 'missed' | 'again';
}

/**
 * Applies the second-try rule to what a move did (`happened`, from ./course.ts flyRings or
 * leaveBehind, in order): the last event, when it is a miss of a ring not in `tried`, becomes
 * 'again': the ring's status goes back to 'ahead' and its index is added to `tried`. A ring skipped
 * (missed because the one after it was crossed first) stays missed: the course has gone past it.
 * Changes `rings` and `tried` in place; returns the events as they count.
 * @throws RangeError on an event whose ring is not in `rings`.
 */
export function secondTry(rings: Ring[], happened: readonly RingEvent[], tried: Set<number>): TryEvent[] {
  const out: TryEvent[] = happened.map((e) => ({ ring: e.ring, result: e.result }));
  const last = out.at(-1);
  if (last?.result !== 'missed' || tried.has(last.ring)) return out;
  const ring = rings[last.ring];
  if (!ring) throw new RangeError(`secondTry: event ring ${last.ring} is not one of the ${rings.length} rings`);
  ring.status = 'ahead';
  tried.add(last.ring);
  last.result = 'again';
  return out;
}
