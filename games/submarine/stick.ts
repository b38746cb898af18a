/**
 * How the on-screen stick's push reads as held controls (DOM-free, tested in node): which way it
 * asks along each axis and how much. A small radial dead zone round the centre swallows a resting
 * thumb's tremble; beyond it each axis answers on its own, in proportion to its push, past a
 * narrow band that keeps a thumb pushing straight along one axis from also asking along the other.
 * A push of 60 px right and 20 px down on a 56 px reach asks for full Ahead and a gentle Dive.
 */

/**
 * The radial dead zone, a fraction of the knob's reach (0.1: under 6 px of a phone's 56 px): inside
 * it the stick asks for nothing along either axis.
 */
export const STICK_DEAD = 0.1;
/**
 * Beyond the dead zone an axis counts once its own push is at least this share of the reach (0.15:
 * about 8 px of 56 px), the wobble of a thumb pushing along the other axis, no more.
 */
export const STICK_AXIS = 0.15;
/** The least share of full speed a counted push asks for (just past `STICK_AXIS`), in (0, 1]. */
export const STICK_MIN_SHARE = 0.2;

const check = (where: string, name: string, v: number) => {
  if (!(Number.isFinite(v) && Math.abs(v) <= 1)) throw new RangeError(`${where}: ${name} must be in [-1, 1], got ${v}`);
};

/**
 * Which way the stick asks along one axis: the sign of its push `v` (in [-1, 1]) when the push as a
 * whole, hypot(`v`, `other`) (`other`: the push along the other axis, in [-1, 1]), is past
 * STICK_DEAD and `v` itself is at least STICK_AXIS; else 0.
 * @throws RangeError when `v` or `other` is not in [-1, 1].
 */
export function stickDirection(v: number, other: number): -1 | 0 | 1 {
  check('stickDirection', 'v', v);
  check('stickDirection', 'other', other);
  if (Math.hypot(v, other) <= STICK_DEAD || Math.abs(v) < STICK_AXIS) return 0;
  return v < 0 ? -1 : 1;
}

/**
 * The share of full Dive / Rise (or screw) the stick's push `v` (in [-1, 1]) along one axis asks
 * for: in proportion to how far past STICK_AXIS it is pushed, (|v| - STICK_AXIS) / (1 - STICK_AXIS),
 * at least STICK_MIN_SHARE and 1 at the rim; 1 while a key of that axis is held (`key`), so the keys
 * always ask for all of it.
 * @throws RangeError when `v` is not in [-1, 1].
 */
export function stickShare(v: number, key: boolean): number {
  check('stickShare', 'v', v);
  if (key) return 1;
  return Math.max(STICK_MIN_SHARE, Math.min(1, (Math.abs(v) - STICK_AXIS) / (1 - STICK_AXIS)));
}
