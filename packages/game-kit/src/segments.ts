/**
 * Whether the segments from (a0x, a0y) to (a1x, a1y) and from (b0x, b0y) to (b1x, b1y) cross, any
 * length unit: both intersection parameters t and u of a0 + t (a1 - a0) = b0 + u (b1 - b0) lie in
 * [0, 1] (Cramer's rule on the 2 x 2 system, e.g. Ericson, Real-Time Collision Detection, 5.1.9.1).
 * Parallel segments (zero cross product) never cross, collinear overlapping ones included. A game's
 * cut (a pointer stroke against a rope link or a cloth link) is the usual use.
 */
export function segmentsCross(
  a0x: number,
  a0y: number,
  a1x: number,
  a1y: number,
  b0x: number,
  b0y: number,
  b1x: number,
  b1y: number,
): boolean {
  const rx = a1x - a0x,
    ry = a1y - a0y,
    sx = b1x - b0x,
    sy = b1y - b0y;
  const d = rx * sy - ry * sx;
  if (d === 0) return false;
  const qx = b0x - a0x,
    qy = b0y - a0y;
  const t = (qx * sy - qy * sx) / d,
    u = (qx * ry - qy * rx) / d;
  return t >= 0 && t <= 1 && u >= 0 && u <= 1;
}
