/**
 * The flight simulator's chase camera: where it sits behind the aircraft and where it looks, and the
 * angle under the view's middle at which a point ahead of the aircraft is seen (level flight), so the
 * framing can be measured headless (test/games/flight-simulator-chase.test.ts).
 */

/**
 * Where the chase camera sits in the aircraft's frame, m: behind, above. Far enough that the 30 m
 * wing spans about a third of a landscape view (at 30 m behind, 9 up it would fill the lower middle
 * and hide the rings below the nose), and 22.5 degrees above the aircraft's axis: a ring 40 m below
 * the aircraft and 150 to 300 m ahead shows 7 degrees and more above it on the screen (at 18 m up,
 * 17 degrees, it showed 3 to 5 degrees above it, under the fin and the tail).
 */
export const CHASE_OFFSET = [-58, 24] as const;
/**
 * The point the chase camera looks at in the aircraft's frame, m (ahead, above): the view's axis
 * 6.5 degrees below the aircraft's, so the path ahead (the next ring) is near the middle of the scene
 * and the aircraft in its lower third (16 degrees under the middle, 0.45 of the half height at the
 * 64 degree field of view).
 */
export const CHASE_LOOK = [42, 12.6] as const;

/**
 * The angle, degrees, under the middle of the chase view (camera at CHASE_OFFSET, looking at
 * CHASE_LOOK, both times `scale`) at which the point `ahead` m in front of the aircraft and `below` m
 * under it is seen, in level flight (positive: under the middle).
 * @param scale the chase scale (main.ts `chaseScale`: 1, or more on a screen taller than wide), >= 1.
 */
export function chaseAngleBelow(ahead: number, below: number, scale = 1): number {
  const [bx, by] = [scale * CHASE_OFFSET[0], scale * CHASE_OFFSET[1]];
  const axis = Math.atan2(by - scale * CHASE_LOOK[1], scale * CHASE_LOOK[0] - bx);
  const point = Math.atan2(by + below, ahead - bx);
  return ((point - axis) * 180) / Math.PI;
}
