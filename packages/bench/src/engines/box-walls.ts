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
  const [x0, y0] = layout.min,
    [x1, y1] = layout.max;
  const t = thickness / 2;
  const cx = (x0 + x1) / 2,
    cy = (y0 + y1) / 2;
  const hx = (x1 - x0) / 2 + thickness,
    hy = (y1 - y0) / 2 + thickness;
  return [
    { cx, cy: y0 - t, hx, hy: t },
    { cx, cy: y1 + t, hx, hy: t },
    { cx: x0 - t, cy, hx: t, hy },
    { cx: x1 + t, cy, hx: t, hy },
  ];
}

/** An axis-aligned static wall in 3D: centre and half extents, m. */
export interface WallBox3 {
  /** Centre, m. */
  readonly cx: number;
  readonly cy: number;
  readonly cz: number;
  /** Half extents along x, y and z, m. */
  readonly hx: number;
  readonly hy: number;
  readonly hz: number;
}

/**
 * The closed box [min, max] (inner corners, m) of a 3D scene such as `spheres-in-box` as six static
 * slabs for peers that have no boundary box: floor, ceiling and four sides, each `thickness` m thick,
 * lying outside the box so their inner faces are exactly its faces; every slab reaches `thickness`
 * past the box's edges, so the slabs overlap at the edges and corners and nothing leaks there.
 */
export function boxWalls3d(min: readonly number[], max: readonly number[], thickness = 2): WallBox3[] {
  const [x0, y0, z0] = min as [number, number, number],
    [x1, y1, z1] = max as [number, number, number];
  const t = thickness / 2;
  const cx = (x0 + x1) / 2,
    cy = (y0 + y1) / 2,
    cz = (z0 + z1) / 2;
  const hx = (x1 - x0) / 2 + thickness,
    hy = (y1 - y0) / 2 + thickness,
    hz = (z1 - z0) / 2 + thickness;
  return [
    { cx, cy: y0 - t, cz, hx, hy: t, hz },
    { cx, cy: y1 + t, cz, hx, hy: t, hz },
    { cx: x0 - t, cy, cz, hx: t, hy, hz },
    { cx: x1 + t, cy, cz, hx: t, hy, hz },
    { cx, cy, cz: z0 - t, hx, hy, hz: t },
    { cx, cy, cz: z1 + t, hx, hy, hz: t },
  ];
}
