/**
 * The submarine's hull as a box for what it touches: mines, beacons' rings, the trail's marks.
 * Headless, so the rule is tested in node.
 */

import { SUBMARINE } from '@bitphysics/projects';

/**
 * Distance, m, from the point (px, py) to the hull, a box `SUBMARINE.length` x `SUBMARINE.height`
 * centred at (x, y) m and turned by `angle` rad (0 inside it): the point taken into the hull's frame
 * (u along, v across), then to the nearest point of the box.
 */
export function hullDistance(x: number, y: number, angle: number, px: number, py: number): number {
  const dx = px - x,
    dy = py - y,
    co = Math.cos(angle),
    s = Math.sin(angle);
  const u = dx * co + dy * s,
    v = -dx * s + dy * co;
  const nu = Math.max(-SUBMARINE.length / 2, Math.min(SUBMARINE.length / 2, u)),
    nv = Math.max(-SUBMARINE.height / 2, Math.min(SUBMARINE.height / 2, v));
  return Math.hypot(u - nu, v - nv);
}
