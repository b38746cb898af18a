import type { BallsInBoxLayout } from '@bitphysics/physics';

/** An axis-aligned static wall: centre and half extents, m. */
export interface WallBox {
  /** Centre, m. */
  readonly cx: number;
  readonly cy: number;
  /** Half width and half height, m. */
  readonly hx: number;
  readonly hy: number;
}

/**
 * The closed box of `balls-in-box` as four static walls for peers that have no boundary box:
 * floor, ceiling, left and right, each `thickness` m thick, lying outside the inner box
 * [min, max] so their inner faces are exactly the box's faces; floor and ceiling overlap the
 * side walls at the corners so nothing leaks there.
 */
export function boxWalls(layout: BallsInBoxLayout, thickness = 2): WallBox[] {
  const [x0, y0] = layout.min, [x1, y1] = layout.max;
  const t = thickness / 2;
  const cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const hx = (x1 - x0) / 2 + thickness, hy = (y1 - y0) / 2 + thickness;
  return [
    { cx, cy: y0 - t, hx, hy: t },
    { cx, cy: y1 + t, hx, hy: t },
    { cx: x0 - t, cy, hx: t, hy },
    { cx: x1 + t, cy, hx: t, hy },
  ];
}
