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
 * A push within this angle of the horizontal, rad (14 degrees), asks for no Dive or Rise
 * (`stickHeaveDirection`): the stick's depth order moves for as long as the push lasts, so a thumb
 * held on Ahead 10 degrees low (0.18 of the reach down at the rim) ran the order down 1.6 m/s, 32 m
 * in 20 s, and the boat read as drifting off the depth it was levelled at. 60 px right and 20 px
 * down (18 degrees) still dives.
 */
export const STICK_LEVEL_ANGLE = (14 * Math.PI) / 180;

/**
 * Which way the stick asks its depth order to move: `stickDirection(y, x)` (`y` the push up, `x`
 * ahead, each in [-1, 1]), but 0 while the push lies within STICK_LEVEL_ANGLE of the horizontal.
 * @throws RangeError when `y` or `x` is not in [-1, 1].
 */
export function stickHeaveDirection(y: number, x: number): -1 | 0 | 1 {
  const dir = stickDirection(y, x);
  return Math.abs(y) <= Math.tan(STICK_LEVEL_ANGLE) * Math.abs(x) ? 0 : dir;
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

/**
 * How fast the stick at its rim moves the depth it orders, m/s (in proportion to `stickShare` below
 * that): 8, faster than the boat at rest dives (5 m/s), so the order mark runs ahead of the boat
 * (3 m more each second held) and shows where it will level off.
 */
export const STICK_ORDER_SPEED = 8;
/**
 * How far the stick's order may run ahead of the boat, m: 25, what a phone's view shows above and
 * below the hull at rest, so the mark stays in sight by the boat.
 */
export const STICK_ORDER_LEAD = 25;

/**
 * The depth the stick orders (`HelmInput.orderY`): pushed down or up it moves at STICK_ORDER_SPEED
 * times its share, from the boat's own depth order (or the hull), at most STICK_ORDER_LEAD m ahead of
 * the hull and within [`floor`, `ceiling`] (m, heights: the lowest the helm may hold over the seabed
 * and the surface); let go it stays, and the helm takes the boat to it and levels there. `order`:
 * the order now (NaN: none yet), `dir`: -1 down, 1 up, 0 neither; `share`: in (0, 1]; `y`: the
 * hull's height; `held`: the helm's depth order (NaN: none), m. Returns the new order, m.
 * @throws RangeError when `dt`, `y`, `floor` or `ceiling` is not finite or `share` is not in [0, 1].
 */
export function stickOrder(
  order: number,
  dir: -1 | 0 | 1,
  share: number,
  dt: number,
  y: number,
  held: number,
  floor: number,
  ceiling: number,
): number {
  for (const [name, v] of [
    ['dt', dt],
    ['y', y],
    ['floor', floor],
    ['ceiling', ceiling],
  ] as const)
    if (!Number.isFinite(v)) throw new RangeError(`stickOrder: ${name} must be finite, got ${v}`);
  if (!(share >= 0 && share <= 1)) throw new RangeError(`stickOrder: share must be in [0, 1], got ${share}`);
  if (dir === 0) return order;
  // From the order already set (the stick's, else the helm's), or half a metre past the hull (the
  // helm's order lead, so the boat starts at once); never behind the hull the way it is pushed.
  const from0 = Number.isFinite(order) ? order : Number.isFinite(held) ? held : y + dir * 0.5;
  const from = dir < 0 ? Math.min(from0, y + dir * 0.5) : Math.max(from0, y + dir * 0.5);
  const to = from + dir * STICK_ORDER_SPEED * share * dt;
  const lead = dir < 0 ? Math.max(to, y - STICK_ORDER_LEAD) : Math.min(to, y + STICK_ORDER_LEAD);
  return Math.min(ceiling, Math.max(floor, lead));
}
