/**
 * The flight simulator's finish screen: what the card says at the end of the course (the time with
 * the misses' penalties, the stars, how it compares with the best) and the two ways on, Retry (R) and
 * Next course (Enter), each a button on the card, so the end of the course always offers a way on.
 * Headless (no DOM), tested in node (test/games/flight-simulator-course.test.ts).
 */

import { type BestResult, courseStars, courseTime, MISS_PENALTY } from './course';

/** The panel's seed slider's largest seed: Next course after it goes back to 0. */
export const LAST_SEED = 1000;

/** How a finished course went (`finishCard`). */
export interface CourseResult {
  /** Rings passed and the course's ring count (integers, 0 <= passed <= total, total >= 1). */
  passed: number;
  total: number;
  /** Rings missed for good (integer >= 0). */
  missed: number;
  /** Rings missed once and flown again (./second-try.ts; integer >= 0, default 0): time, no star. */
  again?: number;
  /** Time flown, s of game time (>= 0), without the misses' penalties. */
  flown: number;
  /** How the run compared with the best kept before it (./course.ts compareWithBest), and that best (null: none). */
  vsBest: 'first' | 'better' | 'not';
  best: BestResult | null;
  /** Whether the page is used by touch (no key names on the buttons). */
  touch: boolean;
}

/** What the finish card shows. */
export interface FinishCard {
  /** 'Course complete!' (every ring passed) or 'Course over'. */
  title: string;
  /** The result: rings passed, the course time (m:ss, penalties in) and the stars. */
  result: string;
  /** The time's make-up when a ring was missed ('' otherwise), and the comparison with the best. */
  detail: string;
  best: string;
  /** The stars earned, 0 to 3 (./course.ts courseStars). */
  stars: number;
  /** The buttons, in order: what each does ('retry' flies this course again, 'next' the next seed's) and its label. */
  actions: readonly { action: 'retry' | 'next'; label: string }[];
}

/** m:ss of `t` seconds (whole seconds, rounded down). */
export function clockText(t: number): string {
  const s = Math.floor(t);
  return `${Math.floor(s / 60)}:${String(s % 60).padStart(2, '0')}`;
}

/**
 * The finish card for `r` (see CourseResult): the course time is `flown` plus MISS_PENALTY s per
 * miss, a second try's first miss included (./course.ts courseTime); the stars count the misses for
 * good only.
 * @throws RangeError on counts that are not whole numbers in range, or a flown time that is negative or not finite.
 */
export function finishCard(r: CourseResult): FinishCard {
  if (!(Number.isInteger(r.total) && r.total >= 1 && Number.isInteger(r.passed) && r.passed >= 0 && r.passed <= r.total))
    throw new RangeError(
      `finishCard: passed and total must be whole numbers with 0 <= passed <= total and total >= 1, got ${r.passed}, ${r.total}`,
    );
  const again = r.again ?? 0;
  if (!(Number.isInteger(again) && again >= 0)) throw new RangeError(`finishCard: again must be an integer >= 0, got ${again}`);
  const total = courseTime(r.flown, r.missed + again);
  const stars = courseStars(r.missed);
  const slips = [r.missed > 0 ? `${r.missed} missed` : '', again > 0 ? `${again} flown again` : ''].filter(Boolean).join(', ');
  const starText = '★'.repeat(stars) + '☆'.repeat(3 - stars);
  const keys = !r.touch;
  return {
    title: r.passed === r.total ? 'Course complete!' : 'Course over',
    result: `${r.passed} of ${r.total} rings in ${clockText(total)}  ${starText}`,
    detail: slips ? `${clockText(r.flown)} flown + ${MISS_PENALTY * (r.missed + again)} s for ${slips}` : '',
    best:
      r.vsBest === 'better'
        ? 'A new best for this course!'
        : r.vsBest === 'first'
          ? 'Your first run on this course: the result to beat next time.'
          : r.best
            ? `Best: ${r.best.passed} of ${r.total} rings in ${clockText(r.best.time)}`
            : '',
    stars,
    actions: [
      { action: 'retry', label: keys ? 'Retry ↺ (R)' : 'Retry ↺' },
      { action: 'next', label: keys ? 'Next course ▶ (Enter)' : 'Next course ▶' },
    ],
  };
}

/**
 * The seed of the course after `seed` (Next course): seed + 1, back to 0 past LAST_SEED (the panel's
 * slider's range) or below 0.
 * @throws RangeError on a seed that is not an integer.
 */
export function nextSeed(seed: number): number {
  if (!Number.isInteger(seed)) throw new RangeError(`nextSeed: seed must be an integer, got ${seed}`);
  return seed >= LAST_SEED || seed < 0 ? 0 : seed + 1;
}
