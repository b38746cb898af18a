import type { ContactBuffer } from './contacts.js';
import type { CollisionSettings } from './state.js';

/**
 * Lengths that scale: the ball contacts' tolerances follow the size of the balls, so a 2 cm marble
 * and a 2 m boulder behave alike.
 *
 * A soft contact is a spring of stiffness k = m_eff omega^2 (solver.ts); a column of N balls of mass m
 * presses its lowest contact by about N m g / k = 2 N g / omega^2 whatever the balls' size, so with one
 * frequency for every size small balls squash (a 2 cm Galton board overlapped by 41 % of a radius) and
 * big ones do not. The overlap as a fraction of the radius, 2 N g / (omega^2 r), stays the same at
 * every size if omega^2 r is fixed: omega grows as 1 / sqrt(r). Speeds scale as sqrt(g r) in a scene
 * scaled in length under the same gravity (and times as sqrt(r / g)), so the push-out speed limit and
 * the stick speed of friction scale as sqrt(r). The world's `contactHertz`, `contactPushSpeed` and
 * `stickSpeed` are the values at `CONTACT_LENGTH_UNIT` (1 m); the speculative margin is already at
 * most a quarter of the pair's radii (narrowphase.ts), and the impact stage's resting speed is 2 g h.
 * With those, a scene scaled by L in length and by sqrt(L) in time step behaves exactly alike scaled
 * (test/physics/collision-accuracy.test.ts). The length of a step's ball contacts is the smallest ball
 * radius among them (a scene of mixed sizes gets the stiffness its smallest balls need).
 */

/** The length at which the world's contact tolerances apply as given, m. */
export const CONTACT_LENGTH_UNIT = 1;

/**
 * Highest ball contact frequency, as a fraction of the solver substep rate (Box2D v3 caps at a quarter;
 * with the heavy damping of `contactDampingRatio` 10 the implicit spring stays stable up to the substep
 * rate itself, and the 2 cm balls need it: a 300-ball bin of them overlaps 41 % of a radius at a quarter,
 * 12 % at a half and 3 % at one).
 */
export const BALL_HERTZ_FRACTION = 1;

/**
 * The length scale of a step's ball contacts, m: the smallest ball radius over the rows (ball B of
 * every row, and ball A of ball pairs); Infinity if there are no rows.
 */
export function contactLength(buf: ContactBuffer): number {
  let r = Infinity;
  const RA = buf.ra, RB = buf.rb;
  for (let i = 0, n = buf.count; i < n; i++) {
    const rb = RB[i]!, ra = RA[i]!;
    if (rb < r) r = rb;
    if (ra > 0 && ra < r) r = ra;
  }
  return r;
}

/** sqrt(length / CONTACT_LENGTH_UNIT), the factor speeds scale by; 1 for no contacts (length Infinity) or length <= 0. */
function speedScale(length: number): number {
  return length > 0 && length < Infinity ? Math.sqrt(length / CONTACT_LENGTH_UNIT) : 1;
}

/**
 * Ball contact frequency for contacts of `length` (m) at substep `hs` (s), Hz: contactHertz times
 * sqrt(CONTACT_LENGTH_UNIT / length), at most BALL_HERTZ_FRACTION / hs.
 */
export function ballContactHertz(settings: CollisionSettings, length: number, hs: number): number {
  const s = speedScale(length);
  return Math.min(settings.contactHertz / s, BALL_HERTZ_FRACTION / hs);
}

/** Push-out speed limit for contacts of `length` (m), m/s: contactPushSpeed times sqrt(length / CONTACT_LENGTH_UNIT). */
export function ballContactPushSpeed(settings: CollisionSettings, length: number): number {
  return settings.contactPushSpeed * speedScale(length);
}

/** Stick speed of friction for contacts of `length` (m), m/s: stickSpeed times sqrt(length / CONTACT_LENGTH_UNIT). */
export function ballStickSpeed(settings: CollisionSettings, length: number): number {
  return settings.stickSpeed * speedScale(length);
}
