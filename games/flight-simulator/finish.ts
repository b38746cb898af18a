/**
 * The flight simulator's finish screen: what the card says at the end of the course (the time with
 * the misses' penalties, the stars, how it compares with the best) and the two ways on, Retry (R) and
 * Next course (Enter), each a button on the card, so the end of the course always offers a way on.
 * Headless (no DOM), tested in node (test/games/flight-simulator-course.test.ts).
 */

import { type BestResult, courseStars, courseTime, MISS_PENALTY } from './course';

/** The panel's seed slider's largest seed, and the number of courses: course n is seed n (1 to LAST_SEED); Next course after the last goes back to 1. */
export const LAST_SEED = 1000;

/**
 * The course's name for seed `seed`: "Course 2 of 1000" for a seed in 1 to LAST_SEED (the courses
 * Next course goes through), "Course 1234" for one outside them (from the address, ?seed=); with
 * `short`, "Course 2" either way (a phone's header).
 * @throws RangeError on a seed that is not an integer.
 */
export function courseName(seed: number, short = false): string {
  if (!Number.isInteger(seed)) throw new RangeError(`courseName: seed must be an integer, got ${seed}`);
  return short || seed < 1 || seed > LAST_SEED ? `Course ${seed}` : `Course ${seed} of ${LAST_SEED}`;
}

/** How a finished course went (`finishCard`). */
export interface CourseResult {
  /** Rings passed and the course's ring count (integers, 0 <= passed <= total, total >= 1). */
  passed: number;
  total: number;
  /** Rings missed for good (integer >= 0). */
  missed: number;
  /** Rings passed on their second try after a first miss (./second-try.ts; integer >= 0, default 0): scored, no penalty. */
  again?: number;
  /** Time flown, s of game time (>= 0), without the misses' penalties. */
  flown: number;
  /** How the run compared with the best kept before it (./course.ts compareWithBest), and that best (null: none). */
  vsBest: 'first' | 'better' | 'not';
  best: BestResult | null;
  /** Whether the page is used by touch (no key names on the buttons). */
  touch: boolean;
  /** The course's seed (integer; course n is seed n: `courseName`). */
  seed: number;
}

/** What the finish card shows. */
export interface FinishCard {
  /** 'Course 2 complete!' (every ring passed) or 'Course 2 over'. */
  title: string;
  /** The result: rings passed (and how many on a second try), missed for good, the course time (m:ss, penalties in) and the stars: "9 of 10 rings passed (1 on a 2nd try) · 1 missed · 1:40  ★★☆". */
  result: string;
  /** The time's sum when a ring was missed for good ('' otherwise): "Time 1:33 + 50 s penalty (5 misses × 10 s) = 2:23"; and the comparison with the best. */
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
 * The finish card for `r` (see CourseResult): the course time is `flown` plus MISS_PENALTY s per ring
 * missed for good (./course.ts courseTime); a ring passed on its second try is a pass, with no penalty,
 * named in the result; the stars count the misses for good.
 * @throws RangeError on counts that are not whole numbers in range, or a flown time that is negative or not finite.
 */
export function finishCard(r: CourseResult): FinishCard {
  if (!(Number.isInteger(r.total) && r.total >= 1 && Number.isInteger(r.passed) && r.passed >= 0 && r.passed <= r.total))
    throw new RangeError(
      `finishCard: passed and total must be whole numbers with 0 <= passed <= total and total >= 1, got ${r.passed}, ${r.total}`,
    );
  const again = r.again ?? 0;
  if (!(Number.isInteger(again) && again >= 0 && again <= r.passed))
    throw new RangeError(`finishCard: again must be an integer in [0, passed], got ${again}`);
  const total = courseTime(r.flown, r.missed);
  const stars = courseStars(r.missed);
  const starText = '★'.repeat(stars) + '☆'.repeat(3 - stars);
  const keys = !r.touch;
  const course = courseName(r.seed, true);
  const penalty = `${MISS_PENALTY * r.missed} s penalty (${r.missed} miss${r.missed === 1 ? '' : 'es'} × ${MISS_PENALTY} s)`;
  // Rings passed on a second try are named, so that a first miss seen in the banner is accounted for.
  const second = again > 0 ? ` (${again} on a 2nd try)` : '';
  // Passed and missed counted as the readout counts them (rings, not misses).
  const lost = r.missed > 0 ? ` · ${r.missed} missed` : '';
  return {
    title: r.passed === r.total ? `${course} complete!` : `${course} over`,
    result: `${r.passed} of ${r.total} rings passed${second}${lost} · ${clockText(total)}  ${starText}`,
    // The penalty is whole seconds, so the floored times add up.
    detail: r.missed > 0 ? `Time ${clockText(r.flown)} + ${penalty} = ${clockText(total)}` : '',
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
      { action: 'next', label: `Next: course ${nextSeed(r.seed)} ▶${keys ? ' (Enter)' : ''}` },
    ],
  };
}

/**
 * The seed of the course after `seed` (Next course): seed + 1, back to 1 past LAST_SEED (the panel's
 * slider's range) or below 1.
 * @throws RangeError on a seed that is not an integer.
 */
export function nextSeed(seed: number): number {
  if (!Number.isInteger(seed)) throw new RangeError(`nextSeed: seed must be an integer, got ${seed}`);
  return seed >= LAST_SEED || seed < 1 ? 1 : seed + 1;
}
