/**
 * How the on-screen stick's push reads as held controls (DOM-free, tested in node): which way it
 * asks along each axis and how much. A thumb that drags the knob a few pixels already moves the boat
 * (a dead zone of a fifth of the reach, 12 px on a phone, swallowed small corrections), and a push
 * mostly along one axis does not also ask along the other for its thumb's wobble.
 */

/**
 * The dead zone along an axis, a fraction of the knob's reach (0.05: under 3 px of a phone's 56 px):
 * a resting thumb's tremble, no more.
 */
export const STICK_DEAD = 0.05;
/**
 * An axis counts only while its push is at least this share of the other axis's (0.5: within about
 * 63 degrees of it), so a thumb pushing straight up wobbles the screw no more than it did with the
 * wide dead zone, and a push along the diagonal asks for both.
 */
export const STICK_CROSS = 0.5;
/** The least share of full speed a counted push asks for (just past the dead zone), in (0, 1]. */
export const STICK_MIN_SHARE = 0.2;

const check = (where: string, name: string, v: number) => {
  if (!(Number.isFinite(v) && Math.abs(v) <= 1)) throw new RangeError(`${where}: ${name} must be in [-1, 1], got ${v}`);
};

/**
 * Which way the stick asks along one axis: the sign of its push `v` (in [-1, 1]) when that is past
 * STICK_DEAD and at least STICK_CROSS times the push `other` along the other axis (in [-1, 1]), else 0.
 * @throws RangeError when `v` or `other` is not in [-1, 1].
 */
export function stickDirection(v: number, other: number): -1 | 0 | 1 {
  check('stickDirection', 'v', v);
  check('stickDirection', 'other', other);
  if (Math.abs(v) <= STICK_DEAD || Math.abs(v) < STICK_CROSS * Math.abs(other)) return 0;
  return v < 0 ? -1 : 1;
}

/**
 * The share of full Dive / Rise (or screw) the stick's push `v` (in [-1, 1]) along one axis asks
 * for: as far as it is pushed, at least STICK_MIN_SHARE (0.5 half way, 1 at the rim); 1 while a key
 * of that axis is held (`key`), so the keys always ask for all of it.
 * @throws RangeError when `v` is not in [-1, 1].
 */
export function stickShare(v: number, key: boolean): number {
  check('stickShare', 'v', v);
  if (key) return 1;
  return Math.max(STICK_MIN_SHARE, Math.min(1, Math.abs(v)));
}
