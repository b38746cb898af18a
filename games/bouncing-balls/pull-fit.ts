/**
 * Fitting the finger's power ring to the screen: kept inside the canvas. No DOM: the tests run it in
 * Node.
 */

/**
 * Where to centre a ring of radius `r` drawn round (x, y) in a canvas `width` x `height`, px: at
 * (x, y), moved just enough to lie wholly inside with `pad` px to spare (centred on an axis the
 * canvas is too small for). A finger pulling back at the screen's edge keeps its power ring in view.
 */
export function ringInside(x: number, y: number, r: number, width: number, height: number, pad = 2): [number, number] {
  const clamp = (v: number, size: number) => (2 * (r + pad) >= size ? size / 2 : Math.min(size - r - pad, Math.max(r + pad, v)));
  return [clamp(x, width), clamp(y, height)];
}
