/**
 * Where the next ring's label goes so that it keeps clear of the boxes over the scene (the warning,
 * the banner, the lesson tip), so a ring above the view keeps its label readable rather than hidden
 * behind the tip at the top, and of the flight-path marker ⊕ (`clearOfBox`), which is drawn over it.
 * Headless (no DOM), tested in node
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

/**
 * The label's centre (px) moved the least way (up, down, left or right) that keeps its box,
 * centred at (`x`, `y`) and `halfW` x `halfH` px in half size, `gap` px clear of `box` (the
 * flight-path marker as drawn), inside the scene (`sceneW` x `sceneH` px, `margin` px from each
 * edge) and clear of each of `avoid` (the messages over the scene); a move that leaves the scene or
 * lands on one of `avoid` is not taken. `[x, y]` as it is when the label is already clear of `box`,
 * or when no move is open (the label then stays where it was placed).
 * @throws RangeError on a half size, gap or margin that is negative or not finite, or a box whose width or height is negative.
 */
export function clearOfBox(
  x: number,
  y: number,
  halfW: number,
  halfH: number,
  box: ScreenBox,
  gap: number,
  scene: { w: number; h: number; margin: number; avoid?: readonly ScreenBox[] },
): [number, number] {
  for (const [name, v] of [
    ['halfW', halfW],
    ['halfH', halfH],
    ['gap', gap],
    ['margin', scene.margin],
  ] as const)
    if (!(v >= 0 && Number.isFinite(v))) throw new RangeError(`clearOfBox: ${name} must be finite and >= 0, got ${v}`);
  const avoid = scene.avoid ?? [];
  for (const b of [box, ...avoid])
    if (!(b[2] >= 0 && b[3] >= 0)) throw new RangeError(`clearOfBox: a box's width and height must be >= 0, got [${b.join(', ')}]`);
  const hits = (b: ScreenBox, cx: number, cy: number, g: number) =>
    cx - halfW < b[0] + b[2] + g && b[0] - g < cx + halfW && cy - halfH < b[1] + b[3] + g && b[1] - g < cy + halfH;
  if (!hits(box, x, y, gap)) return [x, y];
  const [bx, by, bw, bh] = box;
  const moves: [number, number][] = [
    [x, by - gap - halfH],
    [x, by + bh + gap + halfH],
    [bx - gap - halfW, y],
    [bx + bw + gap + halfW, y],
  ];
  const inside = ([cx, cy]: [number, number]) =>
    cx - halfW >= scene.margin - 1e-9 &&
    cx + halfW <= scene.w - scene.margin + 1e-9 &&
    cy - halfH >= scene.margin - 1e-9 &&
    cy + halfH <= scene.h - scene.margin + 1e-9;
  const open = moves.filter((m) => inside(m) && !avoid.some((b) => hits(b, m[0], m[1], 0)));
  open.sort((a, b) => Math.hypot(a[0] - x, a[1] - y) - Math.hypot(b[0] - x, b[1] - y));
  return open[0] ?? [x, y];
}
