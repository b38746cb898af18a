/**
 * Which ball a finger's press is on. The heap shifts after every throw, and a finger covers more than
 * the 20 to 35 CSS px balls of a phone's box: a press is taken against where each ball was drawn a
 * moment before as well as where it is now, and within a finger's reach of its centre. No DOM: the
 * tests run it in Node.
 */

/** A ball where it is now: its entity id, centre (x, y), m, and radius, m. */
export interface BallSpot {
  readonly id: number;
  readonly x: number;
  readonly y: number;
  readonly r: number;
}

/**
 * How far from a ball's centre a finger's press still takes it, CSS px (fingerBall): about a
 * fingertip's half-width, so a press in the gap beside a small ball, or at the place it was drawn
 * before the heap shifted, is on it.
 */
export const FINGER_REACH_PX = 22;

/**
 * The ball a finger's press at (x, y), m, is on (its id), or 0: of the balls `now` whose edge, where
 * they are now or where they were drawn a moment before (`seen`, by id; a ball missing there counts
 * where it is), lies within `reach` m of the press, or whose centre lies within `fingerReach` m of it,
 * the one whose edge is nearest (a press inside a ball is on it: its gap is negative).
 * @throws RangeError unless reach and fingerReach are finite and >= 0.
 */
export function fingerBall(
  now: readonly BallSpot[],
  seen: ReadonlyMap<number, readonly [number, number]>,
  x: number,
  y: number,
  reach: number,
  fingerReach: number,
): number {
  if (!(reach >= 0 && fingerReach >= 0 && Number.isFinite(reach) && Number.isFinite(fingerReach)))
    throw new RangeError(`fingerBall: reach and fingerReach must be finite and >= 0 m, got ${reach}, ${fingerReach}`);
  let best = 0,
    bestGap = Number.POSITIVE_INFINITY;
  for (const b of now) {
    const was = seen.get(b.id) ?? [b.x, b.y];
    const d = Math.min(Math.hypot(b.x - x, b.y - y), Math.hypot(was[0] - x, was[1] - y));
    const gap = d - b.r;
    if ((gap <= reach || d <= fingerReach) && gap < bestGap) {
      best = b.id;
      bestGap = gap;
    }
  }
  return best;
}
