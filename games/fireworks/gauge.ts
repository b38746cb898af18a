/**
 * Where the hold gauge (the fuse ring a press charges, games/fireworks/main.ts `drawCharge`) is drawn
 * for a press at a point of the stage. A mouse pointer is small: the ring goes round it. A finger
 * covers about FINGER_PX round where it touches and the hand lies below it, so on a touch screen the
 * ring is lifted TOUCH_LIFT px above the finger, or, where that would leave the stage's top, set
 * TOUCH_LIFT px to the side with more room. Pure geometry: no DOM, no pixi.
 */

/** How far round its contact point a fingertip hides the screen, CSS px (a fingertip is 16 to 20 mm; about 45 px on a phone). */
export const FINGER_PX = 45;

/** How far from a finger the gauge's centre is drawn, CSS px: the ring's radius and more clear of FINGER_PX. */
export const TOUCH_LIFT = 80;

/**
 * The gauge's centre, CSS px [x, y], for a press at (x, y) on a `width` x `height` stage (CSS px,
 * y down), by touch or not: (x, y) itself for a mouse or pen; for a touch, TOUCH_LIFT above it while
 * the ring (radius `ring` px, plus `room` px over it for its label) stays on the stage, else
 * TOUCH_LIFT to the left or right (whichever side has more room) at the finger's height.
 * @throws RangeError unless x, y are finite, width, height > 0 and ring, room >= 0 finite.
 */
export function gaugeCentre(
  x: number,
  y: number,
  touch: boolean,
  width: number,
  height: number,
  ring: number,
  room: number,
): [number, number] {
  if (
    !(
      Number.isFinite(x) &&
      Number.isFinite(y) &&
      width > 0 &&
      height > 0 &&
      ring >= 0 &&
      room >= 0 &&
      Number.isFinite(width + height + ring + room)
    )
  )
    throw new RangeError(
      `gaugeCentre: x, y must be finite, width and height > 0, ring and room >= 0; got ${x}, ${y}, ${width}, ${height}, ${ring}, ${room}`,
    );
  if (!touch) return [x, y];
  if (y - TOUCH_LIFT - ring - room >= 0) return [x, y - TOUCH_LIFT];
  return [x < width / 2 ? x + TOUCH_LIFT : x - TOUCH_LIFT, y];
}
