/**
 * The beacon pointer's choice: which beacon the arrow at the screen's edge leads to. It keeps one
 * beacon until that one is collected, and moves to another only when the other is clearly nearer
 * (`BEACON_SWITCH`), so it does not flip between two beacons at about the same distance while the
 * boat moves. Headless (no drawing), so the rule is tested in node.
 */

/**
 * The pointer leaves its beacon for another one only when that one is nearer than this fraction
 * of the distance to its own (0.6: a beacon at 45 m takes over from one at 80 m, one at 60 m does not).
 */
export const BEACON_SWITCH = 0.6;

/**
 * The beacon the pointer leads to from the hull at (x, y), m: `current` while it is uncollected,
 * unless another uncollected one is nearer than `BEACON_SWITCH` times its distance; with no current
 * one (-1 or collected), the nearest uncollected. -1 when all are collected.
 * @param beacons (x, y) pairs, m.
 * @param taken Whether each beacon has been collected.
 */
export function chooseBeacon(beacons: ArrayLike<number>, taken: readonly boolean[], x: number, y: number, current: number): number {
  let nearest = -1,
    best = Infinity;
  for (let i = 0; i < taken.length; i++) {
    if (taken[i]) continue;
    const d = Math.hypot(beacons[2 * i]! - x, beacons[2 * i + 1]! - y);
    if (d < best) {
      best = d;
      nearest = i;
    }
  }
  if (current < 0 || current >= taken.length || taken[current] || nearest === current) return nearest;
  const own = Math.hypot(beacons[2 * current]! - x, beacons[2 * current + 1]! - y);
  return best < BEACON_SWITCH * own ? nearest : current;
}

/**
 * The pointer's label: the straight-line distance, and how far down or up the beacon lies when that
 * is more than 5 m (the boat moves about twice as fast ahead as it dives, so a beacon far below
 * is easily passed over while the distance alone is shown). `dy` is the beacon's y minus the hull's, m.
 */
export function beaconLabel(distance: number, dy: number): string {
  const vertical = Math.abs(dy) > 5 ? ` · ${Math.abs(dy).toFixed(0)} m ${dy < 0 ? 'down' : 'up'}` : '';
  return `beacon ${distance.toFixed(0)} m${vertical}`;
}
