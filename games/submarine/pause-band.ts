/**
 * Where the submarine's pause band goes (DOM-free, tested in node): a band across the scene with
 * "Paused" and how to resume, at the bottom edge, or the top edge while the boat would be under the
 * bottom one, so the band stays put as the boat dives; and clear of the target's label where there
 * is room clear of the hull.
 */

/** Room kept between the boat's centre and the band, px: the hull (up to 24 px high at the closest zoom) and a margin. */
export const PAUSE_HULL_ROOM = 40;

/**
 * The top of the pause band, px from the top of the scene: `height` px high between `upper` and
 * `lower` (px: the cards over the scene's top and bottom edges end there), with the boat's centre
 * at `boatY` px. The bottom edge (`lower - height`) while the boat is `PAUSE_HULL_ROOM` clear of it,
 * else the top one (`upper`). Where that band would cover the target's label (`label`: its top and
 * height, px; null while none shows), the first of the bottom edge, the top edge, just under the
 * label and just over it that covers neither the label nor the boat and lies between the cards.
 */
export function pauseBandTop(upper: number, lower: number, height: number, boatY: number, label: readonly [number, number] | null): number {
  const bottom = lower - height;
  const onLabel = (y: number) => label !== null && label[0] < y + height && y < label[0] + label[1];
  const onHull = (y: number) => boatY > y - PAUSE_HULL_ROOM && boatY < y + height + PAUSE_HULL_ROOM;
  const first = boatY < bottom - PAUSE_HULL_ROOM ? bottom : upper;
  if (!label || !onLabel(first)) return first;
  const clear = [bottom, upper, label[0] + label[1] + 4, label[0] - height - 4].find(
    (y) => y >= upper && y <= bottom && !onLabel(y) && !onHull(y),
  );
  return clear ?? first;
}
