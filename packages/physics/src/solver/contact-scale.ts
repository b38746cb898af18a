import type { ContactBuffer } from '../collision/contacts.js';
import type { CollisionSettings } from '../collision/state.js';
import { describe } from '../validation/validate.js';
import { registerExternalWorldState } from '../world/external-state.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Lengths that scale: the ball contacts' tolerances follow the size of the balls, so a 2 cm marble
 * and a 2 m boulder behave alike.
 *
 * A soft contact is a spring of stiffness k = m_eff omega^2 (solver/contact-solver.ts); a column of N balls of mass m
 * presses its lowest contact by about N m g / k = 2 N g / omega^2 whatever the balls' size, so with one
 * frequency for every size small balls squash (a 2 cm Galton board overlapped by 41 % of a radius) and
 * big ones do not. The overlap as a fraction of the radius, 2 N g / (omega^2 r), stays the same at
 * every size if omega^2 r is fixed: omega grows as 1 / sqrt(r). Speeds scale as sqrt(g r) in a scene
 * scaled in length under the same gravity (and times as sqrt(r / g)), so the push-out speed limit and
 * the stick speed of friction scale as sqrt(r). The world's `contactHertz`, `contactPushSpeed` and
 * `stickSpeed` are the values at `CONTACT_LENGTH_UNIT` (1 m); the speculative margin is already at
 * most a quarter of the pair's radii (collision/narrowphase/balls.ts), and the impact stage's resting speed is 2 g h.
 * With those, a scene scaled by L in length and by sqrt(L) in time step behaves exactly alike scaled
 * (test/physics/collision-accuracy.test.ts). The length of a step's ball contacts is the smallest ball
 * radius among them (a scene of mixed sizes gets the stiffness its smallest balls need).
 *
 * The frequency a substep can hold is bounded (BALL_HERTZ_FRACTION of the substep rate), and at a fixed
 * step a small ball's own time scale sqrt(r / g) holds fewer substeps than a big one's: a 2 cm ball at
 * dt 1/60 with 4 substeps is a 0.5 m ball at dt 1/12. So when the step's ball contacts need a frequency
 * f above AUTO_HERTZ_FRACTION of the substep rate, the step takes more solver substeps
 * (`solverSubstepsFor`, at most MAX_AUTO_SUBSTEPS): every ball contact then gets its full stiffness,
 * at f h_s <= 0.6, where piles settle. At dt 1/60 and contactHertz 60 this starts below a radius of
 * 17.4 cm (10 cm: 6 substeps; 4 cm: 9; 2 cm: 12; 1.1 cm and less: 16). Small balls then overlap
 * far less (a Galton board of 2 cm balls: a few percent of a radius instead of about ten), at a step
 * cost that grows with the contact solver's share.
 * Big balls (balls-in-box's 0.5 m: 3 would do) keep the world's count. `CollisionSettings.autoSubsteps`
 * false keeps exactly `solverSubsteps` (the stiffness then capped at the substep rate).
 * The length moves toward a new smallest radius gradually (LENGTH_RAMP), so a scene whose smallest
 * ball comes and goes does not jolt the contacts of the others.
 */

/**
 * The length at which the world's contact tolerances apply as given, m.
 * @category Collision
 */
export const CONTACT_LENGTH_UNIT = 1;

/**
 * Highest ball contact frequency, as a fraction of the solver substep rate (Box2D v3 caps at a quarter;
 * with the heavy damping of `contactDampingRatio` 10 the implicit spring holds up to the substep rate
 * itself: a 300-ball bin of 2 cm balls overlaps 41 % of a radius at a quarter, 12 % at a half and 3 %
 * at one). Dense piles near the cap do not settle, though (see AUTO_HERTZ_FRACTION), which is why the
 * automatic substeps aim lower; the cap binds only with `autoSubsteps` false or past MAX_AUTO_SUBSTEPS.
 * @category Collision
 */
export const BALL_HERTZ_FRACTION = 1;

/**
 * The smallest ball radius over the rows of `buf` (ball B of every row, and ball A of ball pairs), m;
 * Infinity if there are no rows.
 * @category Collision
 */
export function smallestBallRadius(buf: ContactBuffer): number {
  let r = Infinity;
  const RA = buf.ra,
    RB = buf.rb;
  for (let i = 0, n = buf.count; i < n; i++) {
    const rb = RB[i]!,
      ra = RA[i]!;
    if (rb < r) r = rb;
    if (ra > 0 && ra < r) r = ra;
  }
  return r;
}

/**
 * The length scale of the ball contacts in `buf`, one of `world`'s contact buffers
 * (`world.collision.contacts` during a step, `world.collision.cache.rows` after it), m: the length the
 * step of `world` that solved (or is solving) them used, which `withScaledSubsteps` moves toward their
 * smallest ball radius at most LENGTH_RAMP times a step (kept in `world.scratch.contactLengths`); for a
 * buffer no step of `world` has used, their smallest ball radius (Infinity if no rows).
 * @throws TypeError if `world` is not a physics world (the call before was `contactLength(buf)`).
 * @category Collision
 */
export function contactLength(world: PhysicsWorld, buf: ContactBuffer): number {
  const lengths = world?.scratch?.contactLengths;
  if (lengths === undefined)
    throw new TypeError(`contactLength: world must be a physics world (contactLength(world, buf)), got ${describe(world)}`);
  return lengths.get(buf) ?? smallestBallRadius(buf);
}

/**
 * Most the contact length of a world changes from one step to the next, as a factor (the stiffness,
 * proportional to 1 / sqrt(length), by at most its square root, 1.22). A pile of 0.5 m balls rests
 * at its 85 Hz overlap; when a 2 cm ball lands on it the step's contacts jump to 424 Hz, and the
 * sudden push-out threw the big balls up at 0.8 m/s (2.3 m/s at a fixed 12 substeps; 0.06 m/s at the
 * old 240 Hz cap); ramped over about 8 steps they move at most 0.09 m/s (a 2 cm ball resting there
 * from the start: 0.02 m/s).
 * @category Collision
 */
export const LENGTH_RAMP = 1.5;

/**
 * Most solver substeps the automatic choice takes in a step (the world option's own upper bound).
 * @category Collision
 */
export const MAX_AUTO_SUBSTEPS = 16;

/**
 * Highest ball contact frequency the automatic substep choice aims at, as a fraction of the substep
 * rate. Below BALL_HERTZ_FRACTION, because piles at the cap do not settle: 300 balls of 2 cm in a bin
 * 9 radii wide kept moving at 0.5 sqrt(g r) and more with f h_s between 0.64 and 0.88 (8, 9 and 11
 * substeps at 424 Hz), and came to rest with f h_s <= 0.6 (also 0.1 m and 0.065 m balls, which boil
 * with the world's 4 substeps: f h_s 0.79 and 0.98). That holds for rows with friction, whose tangent
 * rows damp a column; a frictionless column is stable with one relax sweep only up to f h_s ~ 0.27
 * (the exact equilibrium of 120 balls of 2 cm zigzagging between walls 5 r apart grew unstable at 26
 * substeps, f h_s 0.27, and held at 28); at 0.6 the relax sweep's support rows (solver/support.ts) bring
 * such columns to rest from a Galton-bin start, not from every start.
 * @category Collision
 */
export const AUTO_HERTZ_FRACTION = 0.6;

/**
 * Solver substeps for a step of `h` (s) whose ball contacts have `length` (m, see `contactLength`):
 * `settings.solverSubsteps`, or more if `settings.autoSubsteps` and the contacts' frequency
 * f = contactHertz sqrt(CONTACT_LENGTH_UNIT / length) exceeds AUTO_HERTZ_FRACTION of that substep
 * rate: then ceil(h f / AUTO_HERTZ_FRACTION), at most MAX_AUTO_SUBSTEPS (never fewer than the
 * setting). A scene scaled by L in length and sqrt(L) in time step gets the same count.
 * @category Collision
 */
export function solverSubstepsFor(settings: CollisionSettings, length: number, h: number): number {
  const base = settings.solverSubsteps;
  if (!settings.autoSubsteps || !(length > 0 && length < Infinity) || !(h > 0)) return base;
  // 1e-9 absorbs rounding (2 cm at dt 1/60 needs 11.8 substeps; 17.4 cm exactly 4).
  const need = Math.ceil((h * settings.contactHertz) / speedScale(length) / AUTO_HERTZ_FRACTION - 1e-9);
  return need > base ? Math.min(need, Math.max(base, MAX_AUTO_SUBSTEPS)) : base;
}

/** A world's contact scale state (`world.features['contact-scale']`): the solver substeps its last step took (0 before the first) and its contact length, m (Infinity before the first); made when `create` is true. */
function scaleStateOf(world: PhysicsWorld, create: boolean): { substeps: number; length: number } | undefined {
  let state = world.features['contact-scale'] as { substeps: number; length: number } | undefined;
  if (state === undefined && create) {
    state = { substeps: 0, length: Infinity };
    world.features['contact-scale'] = state;
  }
  return state;
}

registerExternalWorldState({
  name: 'contact-scale',
  get: (world, create) => scaleStateOf(world, create),
  clear: (world) => {
    world.features['contact-scale'] = undefined;
  },
});

/**
 * Runs `solve` (the contact solver stage) for the step's ball contacts (`world.collision.contacts`):
 * 1. their length (`contactLength`, which the solver reads for stiffness, push-out and stick speeds):
 *    their smallest ball radius, reached from the last step's length by at most a factor LENGTH_RAMP
 *    (the first step with ball contacts takes it at once; a step without any keeps the last);
 * 2. `settings.solverSubsteps` set, for the duration of `solve`, to the count `solverSubstepsFor`
 *    chooses for that length, so every stage of the solver (contacts, shape manifolds, joints,
 *    impacts, the free-flight correction) sees the same count; restored afterwards, also if `solve`
 *    throws. A step without ball contacts takes the setting as it is.
 * The ball contacts' warm-start impulses are impulses per substep: when the count differs from the
 * last step's they are scaled by last / new. Shape manifolds and joints keep theirs, which their
 * first substep corrects.
 * @category Collision
 */
export function withScaledSubsteps(world: PhysicsWorld, solve: (world: PhysicsWorld) => void): void {
  const cs = world.collision,
    settings = cs.settings,
    base = settings.solverSubsteps,
    buf = cs.contacts;
  const state = scaleStateOf(world, true)!;
  const target = smallestBallRadius(buf);
  if (target < Infinity) {
    const last = state.length;
    state.length = last === Infinity ? target : Math.min(Math.max(target, last / LENGTH_RAMP), last * LENGTH_RAMP);
  }
  const length = target < Infinity ? state.length : Infinity;
  world.scratch.contactLengths.set(buf, length);
  const count = settings.autoSubsteps ? solverSubstepsFor(settings, length, world.h) : base;
  if (state.substeps !== count) {
    if (state.substeps > 0) scaleWarmStart(cs.cache.rows, state.substeps / count);
    state.substeps = count;
  }
  if (count === base) {
    solve(world);
    return;
  }
  settings.solverSubsteps = count;
  try {
    solve(world);
  } finally {
    settings.solverSubsteps = base;
  }
}

/** Multiplies the warm-start impulses (normal and both tangents) of the cached rows by `k`. */
function scaleWarmStart(rows: ContactBuffer, k: number): void {
  const LN = rows.normalImpulse,
    L1 = rows.tangentImpulse1,
    L2 = rows.tangentImpulse2;
  for (let i = 0, n = rows.count; i < n; i++) {
    LN[i] = LN[i]! * k;
    L1[i] = L1[i]! * k;
    L2[i] = L2[i]! * k;
  }
}

/** sqrt(length / CONTACT_LENGTH_UNIT), the factor speeds scale by; 1 for no contacts (length Infinity) or length <= 0. */
function speedScale(length: number): number {
  return length > 0 && length < Infinity ? Math.sqrt(length / CONTACT_LENGTH_UNIT) : 1;
}

/**
 * Ball contact frequency for contacts of `length` (m) at substep `hs` (s), Hz: contactHertz times
 * sqrt(CONTACT_LENGTH_UNIT / length), at most BALL_HERTZ_FRACTION / hs.
 * @category Collision
 */
export function ballContactHertz(settings: CollisionSettings, length: number, hs: number): number {
  const s = speedScale(length);
  return Math.min(settings.contactHertz / s, BALL_HERTZ_FRACTION / hs);
}

/**
 * Push-out speed limit for contacts of `length` (m), m/s: contactPushSpeed times sqrt(length / CONTACT_LENGTH_UNIT).
 * @category Collision
 */
export function ballContactPushSpeed(settings: CollisionSettings, length: number): number {
  return settings.contactPushSpeed * speedScale(length);
}

/**
 * Stick speed of friction for contacts of `length` (m), m/s: stickSpeed times sqrt(length / CONTACT_LENGTH_UNIT).
 * @category Collision
 */
export function ballStickSpeed(settings: CollisionSettings, length: number): number {
  return settings.stickSpeed * speedScale(length);
}

/**
 * Stiffness of shape contacts (2D and 3D), as a fraction of the solver substep rate: the world's
 * `contactHertz` is capped at this fraction (contacts against infinite mass get twice it). Box2D caps
 * contact stiffness at a quarter of the substep rate; with flat, two-point manifolds that is unstable in
 * tall pyramids here (sequential impulses ring and the pile shears), and an eighth is stable: 30 Hz at
 * 4 substeps of 1/60 s (Box2D's default contact stiffness), 60 Hz at 8.
 * @category Collision
 */
export const SHAPE_HERTZ_FRACTION = 0.125;

/**
 * Shape contact frequency at substep `hs` (s), Hz: the world's contactHertz, at most
 * SHAPE_HERTZ_FRACTION / hs.
 * @category Collision
 */
export function shapeContactHertz(settings: CollisionSettings, hs: number): number {
  return Math.min(settings.contactHertz, SHAPE_HERTZ_FRACTION / hs);
}

/**
 * Writes the coefficients of a soft constraint, a spring of frequency `hertz` (Hz, >= 0) and damping
 * ratio `zeta` integrated implicitly over `h` (s), into out[at..at+2]: bias rate (1/s), mass scale and
 * impulse scale (Catto, "Soft Constraints", GDC 2011; Box2D v3 b2MakeSoft, in its arithmetic); hertz 0
 * gives 0, 1, 0. The contact rows' softness, once a step (joints/softness.ts `soft` is the joints').
 * @category Collision
 */
export function makeSoftInto(out: Float64Array, at: number, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    out[at] = 0;
    out[at + 1] = 1;
    out[at + 2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  out[at] = omega / a1;
  out[at + 1] = a2 * a3;
  out[at + 2] = a3;
}
