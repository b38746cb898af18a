/**
 * How much of a throw's aiming arc bouncing balls shows, and when it says whether the throw scores.
 * In normal play the dots show only the first part of the flight (to its top, or half the way across
 * to the hoop, whichever comes first) and no verdict: the player judges the rest, so the aim is theirs
 * (a full arc that turned green on a basket let a player wiggle the pull until it did, with no skill).
 * After AIM_HELP_MISSES misses in a row the whole arc and its verdict ("on target", "hits the hoop",
 * ...) come back as help until the next basket, so a player who cannot find a basket is not left
 * stuck. No DOM: the page's drawPointer and the node tests call it.
 */

/** Misses in a row after which the aiming arc shows the whole flight and its verdict (aimHelp). */
export const AIM_HELP_MISSES = 3;

/** Whether the aiming arc shows the whole flight and its verdict after `missesInARow` misses in a row (or always, with `always`). */
export function aimHelp(missesInARow: number, always = false): boolean {
  return always || missesInARow >= AIM_HELP_MISSES;
}

/** The fewest points a short aiming arc keeps (its start and a few dots), so a throw straight at the hoop still shows its way. */
export const SHORT_ARC_POINTS = 6;

/**
 * The first part of aiming arc `path` (flat x, y pairs, m, y up) shown without help: up to its top
 * (the last point before it comes down) or to half the way across from its start to the hoop at
 * `hoopX`, m, whichever comes first, and at least SHORT_ARC_POINTS points (all of them when it has
 * fewer). A new array.
 */
export function shortArc(path: readonly number[], hoopX: number): number[] {
  const n = path.length / 2;
  if (n <= SHORT_ARC_POINTS) return path.slice();
  const x0 = path[0]!;
  const half = x0 + 0.5 * (hoopX - x0);
  const dir = Math.sign(hoopX - x0);
  let end = n;
  for (let i = 1; i < n; i++) {
    const past = dir !== 0 && (path[2 * i]! - half) * dir > 0;
    if (path[2 * i + 1]! < path[2 * i - 1]! || past) {
      end = i;
      break;
    }
  }
  return path.slice(0, 2 * Math.max(SHORT_ARC_POINTS, end));
}
