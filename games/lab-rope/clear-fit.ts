/**
 * The rope lab's framing around an open drawer: the settings drawer (sliders and chart) lies over the
 * scene, on a desktop over its right third and on a phone over its top; a stranger found the stars
 * under it. `clearFit` frames the level in the largest part of the canvas the drawer leaves free
 * (left of it, right of it, above or below it), so the stars and the basket stay in sight.
 */

/** A rectangle in world metres, y up. */
export interface MetreRect {
  readonly minX: number;
  readonly minY: number;
  readonly maxX: number;
  readonly maxY: number;
}

/** A rectangle on the canvas, CSS px from its top-left corner, y down. */
export interface PixelRect {
  readonly left: number;
  readonly top: number;
  readonly right: number;
  readonly bottom: number;
}

/**
 * The world rectangle (m) with the canvas's aspect that, fitted to the whole `width` x `height` px
 * canvas, shows `view` as large as it fits, centred, with `padding` px round it, inside the largest
 * free band the drawer `cover` (px on the canvas, or null: none open) leaves: left, right, above or
 * below it. A cover that leaves no band of at least 80 px frames the whole canvas (as if none).
 * @param padding px, >= 0 (shrunk to a quarter of a small band).
 * @throws RangeError on a canvas or view without area.
 */
export function clearFit(view: MetreRect, width: number, height: number, cover: PixelRect | null, padding = 24): MetreRect {
  const w = view.maxX - view.minX,
    h = view.maxY - view.minY;
  if (!(width > 0 && height > 0 && w > 0 && h > 0))
    throw new RangeError(`clearFit: canvas ${width} x ${height} px and view ${w} x ${h} m need area`);
  const bands: PixelRect[] = [{ left: 0, top: 0, right: width, bottom: height }];
  if (cover && cover.right > 0 && cover.left < width && cover.bottom > 0 && cover.top < height) {
    bands.length = 0;
    bands.push(
      { left: 0, top: 0, right: cover.left, bottom: height },
      { left: cover.right, top: 0, right: width, bottom: height },
      { left: 0, top: 0, right: width, bottom: cover.top },
      { left: 0, top: cover.bottom, right: width, bottom: height },
    );
  }
  let best: { band: PixelRect; ppm: number } | null = null;
  for (const band of bands) {
    const bw = band.right - band.left,
      bh = band.bottom - band.top;
    if (bw < 80 || bh < 80) continue;
    const pad = Math.min(padding, bw / 4, bh / 4);
    const ppm = Math.min((bw - 2 * pad) / w, (bh - 2 * pad) / h);
    if (!best || ppm > best.ppm) best = { band, ppm };
  }
  if (!best) return clearFit(view, width, height, null, padding);
  const { band, ppm } = best;
  // The band's centre on screen shows the view's centre.
  const minX = (view.minX + view.maxX) / 2 - (band.left + band.right) / 2 / ppm,
    maxY = (view.minY + view.maxY) / 2 + (band.top + band.bottom) / 2 / ppm;
  return { minX, minY: maxY - height / ppm, maxX: minX + width / ppm, maxY };
}
