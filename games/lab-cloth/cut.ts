/**
 * Scissors, headless: a stroke of the pointer cuts every cloth link it crosses.
 *
 * Every kind of link is cut (structural, shear and bending), so the two sides of a cut are no longer
 * joined by anything and part at once; the solver repacks its links at the next step.
 */
import { handleOf, type PhysicsWorld, query, removeJoint } from '@bitphysics/physics';

/**
 * Whether segment a (a0 -> a1) and segment b (b0 -> b1) cross (m): both parameters of the crossing
 * point in [0, 1]. Parallel segments never cross.
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

/**
 * Cuts the world's cloth links that the stroke from (x0, y0) to (x1, y1), m, crosses at their current
 * positions. @returns the midpoints of the cut links, m (x, y interleaved; empty if none was cut).
 */
export function cutAlong(world: PhysicsWorld, x0: number, y0: number, x1: number, y1: number): number[] {
  const L = world.components.ClothLink,
    P = world.components.Position;
  const minX = Math.min(x0, x1),
    maxX = Math.max(x0, x1),
    minY = Math.min(y0, y1),
    maxY = Math.max(y0, y1);
  const doomed: number[] = [];
  const at: number[] = [];
  for (const e of query(world, [L])) {
    const a = L.a[e]!,
      b = L.b[e]!;
    const ax = P.x[a]!,
      ay = P.y[a]!,
      bx = P.x[b]!,
      by = P.y[b]!;
    // Cheap rejection by the boxes before the crossing test.
    if (Math.max(ax, bx) < minX || Math.min(ax, bx) > maxX || Math.max(ay, by) < minY || Math.min(ay, by) > maxY) continue;
    if (!segmentsCross(x0, y0, x1, y1, ax, ay, bx, by)) continue;
    doomed.push(handleOf(world, e));
    at.push((ax + bx) / 2, (ay + by) / 2);
  }
  for (const h of doomed) removeJoint(world, h);
  return at;
}
