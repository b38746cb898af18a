/**
 * Catapult: where the aim's numbers and power bar go on the screen, with no DOM. Over the catapult
 * unless the pull's band or its knob lies there (a finger pulled down and to the left often ends
 * over the catapult on a phone, and the numbers covered the knob), then the next place clear of it.
 */

/** A box on the screen, px: its top-left corner, width and height (>= 0). */
export interface Box {
  x: number;
  y: number;
  w: number;
  h: number;
}

/**
 * Least distance, px, from the segment (x0, y0)-(x1, y1) to the box `b` (0 where they meet): the
 * least over the segment's points of the distance to the box (a point's distance to a box is the
 * length of its offset outside the box on each axis).
 */
export function segmentBoxDistance(x0: number, y0: number, x1: number, y1: number, b: Box): number {
  const dist = (x: number, y: number): number => Math.hypot(Math.max(b.x - x, 0, x - (b.x + b.w)), Math.max(b.y - y, 0, y - (b.y + b.h)));
  // The distance along the segment is convex (a convex box): a ternary search finds its least, and
  // 60 halvings of two thirds leave the parameter within 1e-10 of it.
  let lo = 0,
    hi = 1;
  for (let i = 0; i < 60; i++) {
    const a = lo + (hi - lo) / 3,
      c = hi - (hi - lo) / 3;
    if (dist(x0 + a * (x1 - x0), y0 + a * (y1 - y0)) <= dist(x0 + c * (x1 - x0), y0 + c * (y1 - y0))) hi = c;
    else lo = a;
  }
  const u = (lo + hi) / 2;
  return Math.min(dist(x0, y0), dist(x1, y1), dist(x0 + u * (x1 - x0), y0 + u * (y1 - y0)));
}

/**
 * Which of `boxes` (in order of preference) the aim's numbers go in: the first at least `clearance`
 * px from the pull's band `band` [x0, y0, x1, y1] (px: the press and the knob), else the one
 * farthest from it.
 * @returns an index into boxes.
 * @throws RangeError if boxes is empty or clearance is negative.
 */
export function placeAimLabel(boxes: readonly Box[], band: readonly [number, number, number, number], clearance: number): number {
  if (boxes.length === 0) throw new RangeError('placeAimLabel: boxes must not be empty');
  if (!(clearance >= 0)) throw new RangeError(`placeAimLabel: clearance must be >= 0 px, got ${clearance}`);
  let best = 0,
    bestD = Number.NEGATIVE_INFINITY;
  for (const [i, b] of boxes.entries()) {
    const d = segmentBoxDistance(band[0], band[1], band[2], band[3], b);
    if (d >= clearance) return i;
    if (d > bestD) {
      best = i;
      bestD = d;
    }
  }
  return best;
}
