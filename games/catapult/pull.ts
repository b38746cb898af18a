/**
 * Catapult: how long a drag on the screen a full pull is (PULL.max m of pull, the fastest throw),
 * from the canvas's size, with no DOM. The drag is measured on the screen, not in the scene, so the
 * camera may move while the player pulls. And on an upright phone where the castle's inset stands
 * while a pull is drawn, clear of the pull's band (insetBesidePull).
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

/** Pixels kept between a pull's band (from the press to the finger) and the castle's inset on a phone. */
export const PULL_CLEAR = 14;

/** Where the castle's inset stands: its scale and its top-left corner, px. */
export interface InsetPlace {
  zoom: number;
  bx: number;
  by: number;
}

/** Whether the segment from (ax, ay) to (bx, by) meets the box [x, y, width, height], px. */
export function segmentMeetsBox(ax: number, ay: number, bx: number, by: number, box: [number, number, number, number]): boolean {
  const [x, y, bw, bh] = box;
  // Liang-Barsky: the segment clipped to the box's four sides leaves a part of it, or none.
  let t0 = 0,
    t1 = 1;
  const dx = bx - ax,
    dy = by - ay;
  const sides: Array<[number, number]> = [
    [-dx, ax - x],
    [dx, x + bw - ax],
    [-dy, ay - y],
    [dy, y + bh - ay],
  ];
  for (const [p, q] of sides) {
    if (p === 0) {
      if (q < 0) return false;
    } else if (p < 0) t0 = Math.max(t0, q / p);
    else t1 = Math.min(t1, q / p);
  }
  return t0 <= t1;
}

/**
 * On an upright phone, where the castle's inset (w x h px at scale 1) stands in the earth's band
 * `slot` ([top, bottom] px, on a `width` px screen) while a pull's band `pull` ([x0, y0, x1, y1] px,
 * the press to the finger) is drawn: null where the pull stays PULL_CLEAR px clear of its usual place
 * (centred at the band's top, scale `zoom`). Else `kept` where the pull is clear of it, or the largest
 * of three places: right of the pull, left of it, or under it (a pull runs down and back from the
 * press, so one of them is clear), as large as the place holds (`max` times at most).
 */
export function insetBesidePull(
  pull: [number, number, number, number],
  slot: [number, number],
  width: number,
  w: number,
  h: number,
  zoom: number,
  max: number,
  kept: InsetPlace | null,
): InsetPlace | null {
  const [ax, ay, ex, ey] = pull;
  const crosses = (z: number, bx: number, by: number): boolean =>
    segmentMeetsBox(ax, ay, ex, ey, [bx - PULL_CLEAR, by - PULL_CLEAR, w * z + 2 * PULL_CLEAR, h * z + 2 * PULL_CLEAR]);
  if (!crosses(zoom, Math.round((width - w * zoom) / 2), slot[0])) return null;
  if (kept && !crosses(kept.zoom, kept.bx, kept.by)) return kept;
  const fit = (rw: number, rh: number): number => Math.max(0, Math.min(max, rw / w, rh / h));
  // (2 px more than PULL_CLEAR: a place just PULL_CLEAR away would count as crossed, edge on edge.)
  const gap = PULL_CLEAR + 2;
  const left = Math.min(ax, ex) - gap,
    right = Math.max(ax, ex) + gap,
    under = Math.max(slot[0], Math.ceil(Math.max(ay, ey) + gap));
  const band = slot[1] - slot[0];
  const zr = fit(width - 12 - right, band),
    zl = fit(left - 12, band),
    zu = fit(width - 24, slot[1] - under);
  if (zr >= zl && zr >= zu) return { zoom: zr, bx: width - 12 - Math.round(w * zr), by: slot[0] };
  if (zl >= zu) return { zoom: zl, bx: 12, by: slot[0] };
  return { zoom: zu, bx: Math.round((width - w * zu) / 2), by: under };
}
