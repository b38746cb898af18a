/**
 * Where black hole's field is drawn while the settings panel is open beside it (DOM-free): on a wide
 * window the panel opens over the stage's top right corner, where it hid the finish line, the right
 * end of level 2's wall and the ship's path there. The page then fits a wider view into the stage
 * (the field at its left end, empty space to its right), so the field is drawn smaller, left of the
 * panel. The camera (packages/render-pixi/src/camera.ts `Camera.fit`) fits a view of `view` m wide and
 * the field's height into the stage, centred, aspect kept, `padding` px clear round it.
 */

/**
 * The x, px from the stage's left, of the field's right edge when a view `view` m wide (from x = 0)
 * and `height` m tall is fitted into a stage `stageWidth` x `stageHeight` px with `padding` px free
 * round it, the field `fieldWidth` m wide at the view's left (as `Camera.fit` places it).
 */
export function fieldRightPx(
  fieldWidth: number,
  height: number,
  view: number,
  stageWidth: number,
  stageHeight: number,
  padding: number,
): number {
  const pad = stageWidth - 2 * padding <= 0 || stageHeight - 2 * padding <= 0 ? 0 : padding;
  const scale = Math.min((stageWidth - 2 * pad) / view, (stageHeight - 2 * pad) / height);
  return stageWidth / 2 + scale * (fieldWidth - view / 2);
}

/** The widest view `viewBeside` gives, in field widths: past it the field would be drawn too small to play. */
export const MOST_VIEW = 3;

/**
 * The width, m, of the view (from x = 0, the field's height tall) whose fit into the stage draws the
 * field `field` (m) with its right edge at or left of `right` px from the stage's left: the field's
 * own width when it already is (or `right` is Infinity: no panel open), else the least wider view that
 * does it (to 0.01 m), at most MOST_VIEW field widths.
 * @throws RangeError unless the sizes are finite and > 0 and padding >= 0.
 */
export function viewBeside(
  field: { readonly width: number; readonly height: number },
  stageWidth: number,
  stageHeight: number,
  padding: number,
  right: number,
): number {
  if (
    !(
      field.width > 0 &&
      field.height > 0 &&
      stageWidth > 0 &&
      stageHeight > 0 &&
      padding >= 0 &&
      Number.isFinite(stageWidth + stageHeight + padding)
    )
  )
    throw new RangeError(
      `viewBeside: sizes must be finite and > 0, padding >= 0, got ${JSON.stringify(field)}, ${stageWidth}, ${stageHeight}, ${padding}`,
    );
  const at = (view: number): number => fieldRightPx(field.width, field.height, view, stageWidth, stageHeight, padding);
  if (!(right < at(field.width))) return field.width;
  let lo = field.width,
    hi = MOST_VIEW * field.width;
  if (at(hi) > right) return hi;
  // The field's right edge moves left as the view widens: bisect for the least view that puts it at `right`.
  while (hi - lo > 0.01) {
    const mid = (lo + hi) / 2;
    if (at(mid) > right) lo = mid;
    else hi = mid;
  }
  return hi;
}

/** Speeds under this, m/s, draw no velocity tick (the ship parked or hanging still). */
export const TICK_MIN_SPEED = 0.3;

/**
 * The velocity tick drawn from the ship (DOM-free): the screen vector, px (x right, y down), of a
 * short arrow along the ship's velocity (vx, vy), m/s (y up), for a ship drawn `k` px tall. It grows
 * with speed, from 0.8 k at TICK_MIN_SPEED to 2.4 k at 10 m/s and over, so its length reads as speed
 * and its direction as the way the ship drifts (the ship's nose always points up); null under
 * TICK_MIN_SPEED or for a non-finite velocity.
 */
export function velocityTick(vx: number, vy: number, k: number): [number, number] | null {
  const speed = Math.hypot(vx, vy);
  if (!(Number.isFinite(speed) && speed >= TICK_MIN_SPEED && k > 0)) return null;
  const len = k * (0.8 + 1.6 * Math.min(1, (speed - TICK_MIN_SPEED) / (10 - TICK_MIN_SPEED)));
  return [(len * vx) / speed, (-len * vy) / speed];
}
