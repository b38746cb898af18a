import type { ContactBuffer } from './contacts.js';
import type { CollisionSettings } from './state.js';
import type { PhysicsWorld } from '../world.js';

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
 *
 * The frequency a substep can hold is bounded (BALL_HERTZ_FRACTION of the substep rate), and at a fixed
 * step a small ball's own time scale sqrt(r / g) holds fewer substeps than a big one's: a 2 cm ball at
 * dt 1/60 with 4 substeps is a 0.5 m ball at dt 1/12. So when the step's ball contacts need a frequency
 * above the substep rate, the step takes more solver substeps (`solverSubstepsFor`; at most
 * MAX_AUTO_SUBSTEPS): every ball contact then gets its full stiffness. At dt 1/60 and contactHertz 60
 * this starts below a radius of 6.25 cm (2 cm: 8 substeps; 1 cm: 10; 5 mm: 15). Measured on the
 * bench's Galton board of 2,000 balls of 2 cm (`--scene galton`, seeds 1, 2, 3): deepest overlap
 * 8.4 / 10.6 / 15.2 % of a radius with 4 substeps, 4.1 / 1.9 / 1.8 % with 8; the solver's time grows
 * about in proportion to the substeps (the board's median step 1.6 times the 4-substep one). Big
 * balls (balls-in-box's 0.5 m) keep the world's count. `CollisionSettings.autoSubsteps` false keeps
 * exactly `solverSubsteps` (the stiffness is then capped at the substep rate, as before).
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

/** Most solver substeps the automatic choice takes in a step (the world option's own upper bound). */
export const MAX_AUTO_SUBSTEPS = 16;

/**
 * Solver substeps for a step of `h` (s) whose ball contacts have `length` (m, see `contactLength`):
 * `settings.solverSubsteps`, or more if `settings.autoSubsteps` and the contacts' frequency
 * contactHertz sqrt(CONTACT_LENGTH_UNIT / length) exceeds BALL_HERTZ_FRACTION of that substep rate:
 * then ceil(h f / BALL_HERTZ_FRACTION), at most MAX_AUTO_SUBSTEPS (never fewer than the setting).
 * A scene scaled by L in length and sqrt(L) in time step gets the same count.
 */
export function solverSubstepsFor(settings: CollisionSettings, length: number, h: number): number {
  const base = settings.solverSubsteps;
  if (!settings.autoSubsteps || !(length > 0 && length < Infinity) || !(h > 0)) return base;
  // 1e-9 absorbs rounding (2 cm at dt 1/60 needs 7.07 substeps; 6.25 cm exactly 4).
  const need = Math.ceil((h * settings.contactHertz) / speedScale(length) / BALL_HERTZ_FRACTION - 1e-9);
  return need > base ? Math.min(need, Math.max(base, MAX_AUTO_SUBSTEPS)) : base;
}

/**
 * Runs `solve` (the contact solver stage) with `settings.solverSubsteps` set, for its duration, to
 * the count `solverSubstepsFor` chooses for the step's ball contacts (`world.collision.contacts`),
 * so every stage of the solver (contacts, shape manifolds, joints, impacts, the free-flight
 * correction) sees the same count; the setting is restored afterwards, also if `solve` throws.
 */
export function withScaledSubsteps(world: PhysicsWorld, solve: (world: PhysicsWorld) => void): void {
  const settings = world.collision.settings, base = settings.solverSubsteps;
  const count = settings.autoSubsteps ? solverSubstepsFor(settings, contactLength(world.collision.contacts), world.h) : base;
  if (count === base) { solve(world); return; }
  settings.solverSubsteps = count;
  try { solve(world); } finally { settings.solverSubsteps = base; }
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
