/**
 * Wrecking ball: the farthest the camera may draw back when its framing widens for the ball or for
 * wreckage. Pure (no DOM, no world), so node tests can check it; the page (./main) applies it to
 * each widened or re-homed framing.
 */

/** A point or vector, m (three's Vector3 fits). */
export interface Point3 {
  x: number;
  y: number;
  z: number;
}

/**
 * How many times the site's first framing distance a widened framing may stand from its target: a
 * ball or a brick far off the site is then let go off the screen rather than shrinking the structures
 * to a few px (uncapped, a brick knocked to the site's edge or a ball near the camera drew the camera
 * back until a tower was about 10 px tall).
 */
export const WIDEN_MAX = 1.5;

/**
 * Moves `position` (m, changed in place) along the line from `target` so that it stands no farther
 * than `limit` m from it; a position already within `limit` is left as it is.
 * @returns Whether it was moved.
 */
export function capDistance(position: Point3, target: Point3, limit: number): boolean {
  const dx = position.x - target.x,
    dy = position.y - target.y,
    dz = position.z - target.z;
  const d = Math.hypot(dx, dy, dz);
  if (!(limit > 0) || d <= limit) return false;
  const s = limit / d;
  position.x = target.x + dx * s;
  position.y = target.y + dy * s;
  position.z = target.z + dz * s;
  return true;
}
