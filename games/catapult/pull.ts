/**
 * Catapult: how long a drag on the screen a full pull is (PULL.max m of pull, the fastest throw),
 * from the canvas's size, with no DOM. The drag is measured on the screen, not in the scene, so the
 * camera may move while the player pulls.
 */

/** A full pull's drag on a wide screen: this share of the canvas's diagonal, within [FULL_PULL_MIN_PX, FULL_PULL_MAX_PX] px (380 px at 1280 x 800). */
export const FULL_PULL_SHARE = 0.32;
/** The shortest full pull on a wide screen, px. */
export const FULL_PULL_MIN_PX = 240;
/** The longest full pull, px: a desktop's drag long enough to adjust by a few pixels without the landing jumping a metre. */
export const FULL_PULL_MAX_PX = 380;
/**
 * On an upright phone a full pull is this share of the screen's width (195 px on a 390 px phone): a
 * thumb's drag from the screen's middle back towards the catapult, with room to spare. At 0.9 of the
 * width (351 px) a full pull needed a drag to the screen's edge, which a thumb holding the phone
 * cannot make.
 */
export const FULL_PULL_UPRIGHT_SHARE = 0.5;
/** Upright, the shortest full pull, px: on a 320 px phone still 160 px, a pixel of drag under 1 % of power. */
export const FULL_PULL_UPRIGHT_MIN_PX = 160;

/**
 * Screen pixels of drag for a full pull on a `width` x `height` px canvas, `upright` where it is an
 * upright phone's (the page's rule: narrow and taller than wide).
 * @throws RangeError if the canvas's size is not positive.
 */
export function fullPullPx(width: number, height: number, upright: boolean): number {
  if (!(width > 0 && height > 0)) throw new RangeError(`fullPullPx: the canvas must be > 0 px each way, got ${width} x ${height}`);
  if (upright) return Math.min(FULL_PULL_MAX_PX, Math.max(FULL_PULL_UPRIGHT_MIN_PX, FULL_PULL_UPRIGHT_SHARE * width));
  return Math.min(FULL_PULL_MAX_PX, Math.max(FULL_PULL_MIN_PX, FULL_PULL_SHARE * Math.hypot(width, height)));
}
