/**
 * Fitting a press and the finger's power ring to the screen: a press on the frame round the box taken
 * as one inside it, the ring kept inside the canvas. No DOM: the tests run it in Node.
 */

/**
 * Where a press at (x, y), m (y up), counts in a box from `min` to `max`, m: moved in onto the box's
 * side walls or its top when it is beside or over the box (on the steel frame), else where it is. A
 * press under the floor stays there (the court's stand, where a press throws the heap's top ball).
 */
export function pressInBox(x: number, y: number, min: readonly number[], max: readonly number[]): [number, number] {
  return [Math.min(max[0]!, Math.max(min[0]!, x)), Math.min(max[1]!, y)];
}

/**
 * Where to centre a ring of radius `r` drawn round (x, y) in a canvas `width` x `height`, px: at
 * (x, y), moved just enough to lie wholly inside with `pad` px to spare (centred on an axis the
 * canvas is too small for). A finger pulling back at the screen's edge keeps its power ring in view.
 */
export function ringInside(x: number, y: number, r: number, width: number, height: number, pad = 2): [number, number] {
  const clamp = (v: number, size: number) => (2 * (r + pad) >= size ? size / 2 : Math.min(size - r - pad, Math.max(r + pad, v)));
  return [clamp(x, width), clamp(y, height)];
}
