/**
 * Marks at the view's leading edge for the hazards ahead that lie beyond it: the live mines and a
 * seabed ridge that rises near the boat's depth, each at its depth and with its distance from the
 * bow, so that a pilot sees what comes before it scrolls into view. On a phone the view shows about
 * 60 m of sea ahead of the bow, some 7 s at full ahead, too little to read a mine and pass it; the
 * marks reach `EDGE_MARK_REACH` m (12.5 s at HELM.topSpeed) on every screen. Headless (no drawing),
 * so which hazards are marked is tested in node.
 */

import { assertFinite } from '@bitphysics/physics/validate';
import { SUBMARINE } from '@bitphysics/projects';
import { HELM } from './helm';

/**
 * How far ahead of the bow the edge marks look, m: 100, 12.5 s at the top speed of 8 m/s (HELM.topSpeed),
 * over twice the mine warning's MINE_WARN_TIME (5 s), so a hazard is seen coming before it is warned of.
 */
export const EDGE_MARK_REACH = 100;
/**
 * A seabed ridge beyond the view is marked when its crest rises to within this of the keel (or
 * above it), m: near enough to the boat's depth that a pilot holding it would have to rise.
 */
export const EDGE_MARK_BED_ROOM = 6;
/** The step at which the seabed beyond the view is sampled for a ridge, m (the bed's own cells are 4 m and wider). */
const BED_STEP = 2;

/** A hazard beyond the view's leading edge: what it is, where (m) and how far ahead of the bow (m). */
export interface EdgeMark {
  /** 'mine' (a live mine's centre) or 'ridge' (the seabed's crest). */
  kind: 'mine' | 'ridge';
  /** Its place, m (world x right, y up). */
  x: number;
  y: number;
  /** How far its x lies ahead of the bow, m. */
  ahead: number;
}

/**
 * The hazards beyond the view's leading edge at `edge` (m, the world x where the clear view ends,
 * the depth gauge left out) of a boat whose hull's centre is at (`hx`, `hy`) m (`hy`: the height it
 * is at, or the lower one it is ordered down to), heading to +x: each
 * live mine (`mines[i]` with `live[i]`) whose centre lies past `edge` and within `reach` m of the bow,
 * nearest first; then the seabed's highest point (`bed`: the bed's height at x, m) between `edge`
 * and `reach` past the bow, when it rises to within EDGE_MARK_BED_ROOM of the keel and above the bed
 * at the edge (a ridge coming, not the floor going on). A boat backing (`heading` -1) looks the
 * other way (the edge is then the view's left edge). `reach` defaults to EDGE_MARK_REACH.
 * @throws RangeError when `edge`, `hx` or `hy` is not finite, or `reach` is not positive.
 */
export function edgeMarks(
  edge: number,
  hx: number,
  hy: number,
  mines: readonly { x: number; y: number }[],
  live: readonly boolean[],
  bed: (x: number) => number,
  heading: 1 | -1 = 1,
  reach: number = EDGE_MARK_REACH,
): EdgeMark[] {
  assertFinite('edgeMarks', 'edge', edge);
  assertFinite('edgeMarks', 'hx', hx);
  assertFinite('edgeMarks', 'hy', hy);
  if (!(reach > 0)) throw new RangeError(`edgeMarks: reach must be > 0 m, got ${reach}`);
  const bow = hx + (heading * SUBMARINE.length) / 2,
    far = bow + heading * reach;
  const beyond = (x: number) => heading * (x - edge) > 0 && heading * (far - x) >= 0;
  const out: EdgeMark[] = [];
  for (let i = 0; i < mines.length; i++) {
    const m = mines[i]!;
    if (live[i] && beyond(m.x)) out.push({ kind: 'mine', x: m.x, y: m.y, ahead: heading * (m.x - bow) });
  }
  out.sort((a, b) => a.ahead - b.ahead);
  if (heading * (far - edge) <= 0) return out;
  let crest = Number.NEGATIVE_INFINITY,
    crestX = edge;
  for (let x = edge + heading * BED_STEP; heading * (far - x) >= 0; x += heading * BED_STEP) {
    const h = bed(x);
    if (h > crest) [crest, crestX] = [h, x];
  }
  const keel = hy - SUBMARINE.height / 2;
  if (crest >= keel - EDGE_MARK_BED_ROOM && crest > bed(edge) + 1)
    out.push({ kind: 'ridge', x: crestX, y: crest, ahead: heading * (crestX - bow) });
  return out;
}

/**
 * The seconds of warning a hazard `ahead` m ahead of the bow gives a boat at full ahead (HELM.topSpeed).
 * @throws RangeError when `ahead` is not finite.
 */
export function warningSeconds(ahead: number): number {
  assertFinite('warningSeconds', 'ahead', ahead);
  return ahead / HELM.topSpeed;
}
