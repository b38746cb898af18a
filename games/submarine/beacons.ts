/**
 * The beacon pointer's choice: which beacon the arrow at the screen's edge leads to (the target).
 * It holds one beacon until that one is collected, however near the others pass (a stranger who
 * saw the target flip between beacons as the boat went by them never knew which to chase), and then
 * takes the nearest one left. Headless (no drawing), so the rule is tested in node.
 */

import { assertFinite } from '@bitphysics/physics/validate';

/**
 * A beacon is collected when the hull's centre comes within this of it, m. Drawn round each beacon
 * as a faint disc, so a player sees how near is near enough (only the 1 to 3 m lamp and its pulse
 * showed, and a stranger on a phone steered for the lamp itself). 8 m: the hull's 12 m length
 * passing within 2 m of the lamp.
 */
export const BEACON_CATCH = 8;

/**
 * The beacon the pointer leads to from the hull at (x, y), m: `current` while it is uncollected (it
 * is held, however near another one comes); with no current one (-1, out of range or collected),
 * the nearest uncollected one. -1 when all are collected.
 * @param beacons (x, y) pairs, m.
 * @param taken Whether each beacon has been collected.
 */
export function chooseBeacon(beacons: ArrayLike<number>, taken: readonly boolean[], x: number, y: number, current: number): number {
  if (current >= 0 && current < taken.length && !taken[current]) return current;
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
  return nearest;
}

/** What the pointer's label adds when the seabed rises between the hull and its beacon. */
export const RIDGE_WARNING = 'ridge ahead: climb';

/**
 * What the pointer's label adds when a live mine lies on the straight way to its beacon
 * (./mines.ts `mineOnWay`): which side to pass it.
 */
export const MINE_WARNING = Object.freeze({ over: '⚠ mine on the way: pass over it', under: '⚠ mine on the way: pass under it' });

/**
 * Throws unless the segment from (x0, y0) to (x1, y1), m, has finite ends; `where` names the caller.
 * @throws RangeError naming the first coordinate that is not finite.
 */
export function assertSegment(where: string, x0: number, y0: number, x1: number, y1: number): void {
  assertFinite(where, 'x0', x0);
  assertFinite(where, 'y0', y0);
  assertFinite(where, 'x1', x1);
  assertFinite(where, 'y1', y1);
}

/**
 * Whether the straight line from the hull at (x0, y0) to the beacon at (x1, y1), m (y up), passes
 * below the seabed anywhere: sampled every metre or less along x, and true where the line is under
 * `bedAt(x)` (the seabed's height there, m). Going straight for the beacon would then run into a ridge.
 * @throws RangeError when a coordinate is not finite.
 */
export function seabedBetween(x0: number, y0: number, x1: number, y1: number, bedAt: (x: number) => number): boolean {
  assertSegment('seabedBetween', x0, y0, x1, y1);
  const n = Math.max(1, Math.ceil(Math.abs(x1 - x0)));
  for (let i = 0; i <= n; i++) {
    const u = i / n;
    if (y0 + u * (y1 - y0) < bedAt(x0 + u * (x1 - x0))) return true;
  }
  return false;
}

/**
 * The pointer's label: how far ahead or behind the beacon lies (along the hull's heading, so "ahead"
 * means "keep the screw ahead") and how far down or up, each when it is 3 m or more, e.g.
 * "beacon 85 m ahead, 30 m down". The boat moves nearly twice as fast ahead as it dives, so the depth
 * to make up is the part a player must start on early. `dx`, `dy`: the beacon's position minus the
 * hull's, m (y up); `angle`: the hull's pitch, rad; `ridge`: the seabed rises across the straight way
 * to it (`seabedBetween`), which adds `RIDGE_WARNING` on a second line; `mine`: a live mine lies on
 * that way (./mines.ts `mineOnWay`) and on which side to pass it, which adds `MINE_WARNING` there
 * instead when there is no ridge; `name`: the beacon's name (`beaconName`), put first as
 * "target C: 85 m ahead" (the one beacon to steer for, held until collected), so a change of target
 * is seen; without a name the label starts "beacon".
 */
export function beaconLabel(dx: number, dy: number, angle = 0, ridge = false, mine: '' | 'over' | 'under' = '', name = ''): string {
  const along = dx * Math.cos(angle) + dy * Math.sin(angle);
  const parts: string[] = [];
  if (Math.abs(along) >= 3) parts.push(`${Math.abs(along).toFixed(0)} m ${along > 0 ? 'ahead' : 'behind'}`);
  if (Math.abs(dy) >= 3) parts.push(`${Math.abs(dy).toFixed(0)} m ${dy < 0 ? 'down' : 'up'}`);
  const warning = ridge ? RIDGE_WARNING : mine ? MINE_WARNING[mine] : '';
  return `${name ? `target ${name}: ` : 'beacon '}${parts.length > 0 ? parts.join(', ') : 'here'}${warning ? `\n${warning}` : ''}`;
}

/**
 * The name of beacon `index` (0-based, an integer >= 0) on the page: a letter A to Z, then A2, B2...
 * (letters, so that it is not read as the count of "Beacon 2 of 6").
 * @throws RangeError on an index that is not an integer >= 0.
 */
export function beaconName(index: number): string {
  if (!(Number.isInteger(index) && index >= 0)) throw new RangeError(`beaconName: index must be an integer >= 0, got ${index}`);
  const letter = String.fromCharCode(65 + (index % 26));
  return index < 26 ? letter : `${letter}${Math.floor(index / 26) + 1}`;
}
