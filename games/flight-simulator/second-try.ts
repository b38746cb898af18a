/**
 * A second try at a missed ring: the first time a ring is missed it is not lost, it comes round again
 * (the game lays it just ahead, ./course.ts relayAfterMiss, as a go-around). Flown through on that
 * second try it scores as a pass, with no penalty on the course clock (the go-around has cost its own
 * seconds): a player who comes back for a ring gets it. Missed again, it is missed for good (a star's
 * share and MISS_PENALTY s, as every miss: ./course.ts courseStars, courseTime). The banner says which
 * (`tryBanner`). Headless (no DOM), tested in node (test/games/flight-simulator-course.test.ts).
 */

import { MISS_PENALTY, type Ring, type RingEvent } from './course';

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

/**
 * The banner for `event` (a ring's index, 0-based, and what happened to it): a pass "Ring 3 ✓" ("Last
 * ring!" when `last`), on a second try (`second`) "Ring 3 ✓ on the 2nd try · no penalty"; a first
 * miss "Missed ring 3 · fly it again to score it" (it costs nothing yet: the ring comes round); a miss
 * for good "Missed ring 3 · +10 s", with " · −1 ★" before the time when it takes a star (`starLost`).
 * @throws RangeError on a ring index that is not an integer >= 0.
 */
export function tryBanner(event: TryEvent, opts: { second?: boolean; last?: boolean; starLost?: boolean } = {}): string {
  if (!(Number.isInteger(event.ring) && event.ring >= 0))
    throw new RangeError(`tryBanner: ring must be an integer >= 0, got ${event.ring}`);
  const n = event.ring + 1;
  if (event.result === 'passed') {
    if (opts.second) return `${opts.last ? 'Last ring' : `Ring ${n}`} ✓ on the 2nd try · no penalty`;
    return opts.last ? 'Last ring!' : `Ring ${n} ✓`;
  }
  if (event.result === 'again') return `Missed ring ${n} · fly it again to score it`;
  return `Missed ring ${n}${opts.starLost ? ' · −1 ★' : ''} · +${MISS_PENALTY} s`;
}
