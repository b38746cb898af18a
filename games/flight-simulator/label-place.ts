/**
 * Where the next ring's label goes so that it keeps clear of the boxes over the scene (the warning,
 * the banner, the lesson tip), so a ring above the view keeps its label readable rather than hidden
 * behind the tip at the top. Headless (no DOM), tested in node
 * (test/games/flight-simulator-pacing.test.ts).
 */

/** A box on the screen: left, top, width, height, px (width and height >= 0). */
export type ScreenBox = readonly [number, number, number, number];

/**
 * The label's centre height (px) moved clear of `boxes`, `gap` px from each: the label is centred at
 * (`x`, `y`), `halfW` x `halfH` px in half size. A box in the scene's upper half (its centre above
 * `sceneH` / 2) pushes the label below its bottom edge, one in the lower half above its top edge;
 * the upper boxes are taken from the top down and the lower from the bottom up, so a stacked column
 * of boxes pushes the label past the whole column. A box the label does not overlap (gap included)
 * leaves it. `y` is returned as it is when no box is overlapped.
 * @throws RangeError on a half size or gap that is negative or not finite, or a box whose width or height is negative.
 */
export function labelClearOf(
  x: number,
  y: number,
  halfW: number,
  halfH: number,
  boxes: readonly ScreenBox[],
  sceneH: number,
  gap: number,
): number {
  for (const [name, v] of [
    ['halfW', halfW],
    ['halfH', halfH],
    ['gap', gap],
  ] as const)
    if (!(v >= 0 && Number.isFinite(v))) throw new RangeError(`labelClearOf: ${name} must be finite and >= 0, got ${v}`);
  for (const b of boxes)
    if (!(b[2] >= 0 && b[3] >= 0)) throw new RangeError(`labelClearOf: a box's width and height must be >= 0, got [${b.join(', ')}]`);
  const upper = boxes.filter((b) => b[1] + b[3] / 2 < sceneH / 2).sort((a, b) => a[1] - b[1]);
  const lower = boxes.filter((b) => b[1] + b[3] / 2 >= sceneH / 2).sort((a, b) => b[1] - a[1]);
  const overlaps = (b: ScreenBox, cy: number) =>
    x - halfW < b[0] + b[2] + gap && b[0] - gap < x + halfW && cy - halfH < b[1] + b[3] + gap && b[1] - gap < cy + halfH;
  let cy = y;
  for (const b of upper) if (overlaps(b, cy)) cy = b[1] + b[3] + gap + halfH;
  for (const b of lower) if (overlaps(b, cy)) cy = b[1] - gap - halfH;
  return cy;
}
