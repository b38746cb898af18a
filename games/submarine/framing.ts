/**
 * How far the submarine's framing camera lets the view lead the hull along x (DOM-free, tested in
 * node: test/games/submarine-framing.test.ts). The page (./main.ts draw) eases the look-ahead toward
 * the hull's speed times a lead time and holds it within these limits; on a portrait phone the view
 * leads further, so under way the boat sits left of centre with the sea ahead of it in view.
 */

import { SUBMARINE } from '@bitphysics/projects';
import { MINE_RADIUS, MINE_WARN_TIME } from './mines';

/** The framing camera: the hull and the next beacon are kept this far inside the view's edges, px. */
export const FRAME_MARGIN = 60;
/**
 * Room the framing camera keeps clear between the hull's ends and the view's left and right edges,
 * px: the depth ladder and its figures ("30 m", about 36 px) are drawn left of the stern, so on a
 * phone leading ahead the boat never sits at the edge with its tail cut off and the figures on it.
 */
export const HULL_SIDE_ROOM = 60;
/** The look-ahead is at most this share of the distance from the view's centre to the framing margin. */
export const LEAD_SHARE = 0.6;
/**
 * The look-ahead's share of the way to the framing margin (`LEAD_SHARE`) on a portrait view, and
 * there the most the view's centre leads the hull even toward a target far ahead: 0.75, so under way
 * the hull's centre sits about 24% of the view in from its trailing edge, its stern still
 * HULL_SIDE_ROOM (60 px) in, and about 59 m of sea ahead of the bow on a 390 px phone (at 0.55, 30%
 * in, 49 m: a stranger found too little warning of the mines and the seabed ahead).
 */
export const PORTRAIT_LEAD_SHARE = 0.75;
/**
 * On a portrait view under way the framing camera shows at least this much sea across, m: a 390 px
 * phone 86 m (4.5 px/m, the 12 m hull 54 px long). At 80 m the hull was 58 px but the bow saw 5 m less.
 */
export const PORTRAIT_MIN_WIDTH = 86;
/**
 * The least zoom of a portrait view under way, px/m: 4.5 (the hull 54 px long). At rest it is
 * ./main.ts FRAME_MIN_ZOOM (3.5), so a target up to about 65 m away is framed while the pilot sets off (the
 * first one at the start); between rest and `PORTRAIT_SPEED` it eases from one to the other. Under way
 * a target further than about 50 m is shown by the edge arrow until it comes into view.
 */
export const PORTRAIT_MIN_ZOOM_UNDER_WAY = 4.5;
/**
 * A pilot's time to see a hazard come into view and answer it, s: the game's MINE_REACTION (1 s) and
 * half a second to notice it at the view's edge.
 */
export const SEE_AND_REACT = 1.5;
/** The boat's cruising speed, m/s: full ahead (./helm.ts HELM's top speed). */
export const CRUISE_SPEED = 8;

/**
 * The sea a pilot needs in view ahead of the bow at `speed` m/s, m: the mine warning's reach
 * (MINE_WARN_TIME s, the time it gives to rise over or dive under a mine, the turn) and
 * SEE_AND_REACT s, at that speed, and the mine's radius: the mine the game warns of is on the screen
 * before the warning, with time to spot it. At cruising speed (8 m/s) 54.4 m.
 * @throws RangeError when `speed` is not finite and >= 0.
 */
export function aheadNeeded(speed: number): number {
  if (!(Number.isFinite(speed) && speed >= 0)) throw new RangeError(`aheadNeeded: speed must be finite and >= 0 m/s, got ${speed}`);
  return speed * (MINE_WARN_TIME + SEE_AND_REACT) + MINE_RADIUS;
}

/**
 * The limits of the look-ahead along x on a `W` px wide view at `k` px/m, m: `reach` the most any
 * look-ahead moves the view's centre from the hull (its share, `LEAD_SHARE` or on a `portrait` view
 * `PORTRAIT_LEAD_SHARE`, of the way to FRAME_MARGIN), and `hull` the most before the hull's stern
 * comes within HULL_SIDE_ROOM of the trailing edge.
 * @throws RangeError when `W` or `k` is not finite and > 0.
 */
export function leadLimits(W: number, k: number, portrait: boolean): { reach: number; hull: number; share: number } {
  if (!(Number.isFinite(W) && W > 0)) throw new RangeError(`leadLimits: W must be finite and > 0 px, got ${W}`);
  if (!(Number.isFinite(k) && k > 0)) throw new RangeError(`leadLimits: k must be finite and > 0 px/m, got ${k}`);
  const share = portrait ? PORTRAIT_LEAD_SHARE : LEAD_SHARE;
  return {
    reach: (share * Math.max(0, W / 2 - FRAME_MARGIN)) / k,
    hull: Math.max(0, W / 2 - Math.max(FRAME_MARGIN, (SUBMARINE.length / 2) * k + HULL_SIDE_ROOM)) / k,
    share,
  };
}

/**
 * The view at its full lead (`leadLimits`, the smaller of the two) on a `W` px wide view at `k`
 * px/m: the hull's centre from the trailing edge (px) and the sea from the bow to the leading edge (m).
 */
export function fullLead(W: number, k: number, portrait: boolean): { hullX: number; ahead: number } {
  const { reach, hull } = leadLimits(W, k, portrait);
  const hullX = W / 2 - Math.min(reach, hull) * k;
  return { hullX, ahead: (W - hullX) / k - SUBMARINE.length / 2 };
}
