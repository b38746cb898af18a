import { type ContactBuffer, ContactKind } from '../collision/contacts.js';
import type { PhysicsWorld } from '../world/options.js';
import { BI_ALONE, BI_CORR_X, BI_CORR_Y, BI_CORR_Z, IMPACT_STRIDE } from './body-state-layout.js';
import { contactState, sweep } from './impact-contact.js';
import { ballMotion, contactRadius, faceMotion, latestImpactTime, motionIO, normalMotion } from './impact-motion.js';
import { impactScalars, impactScratch, markChanged, sweepIO } from './impact-state.js';
import { jointsToSolve } from './row-families.js';

/**
 * The impact stage's separation pass (solver/impacts.ts): after the impacts, which bodies the soft
 * substeps leave alone, and the corrections that keep impacted bodies from ending the step inside
 * their neighbours (balls against balls and faces, swept over the step).
 */

/**
 * Decides, after the passes, which bodies are "clean": every contact of theirs was either resolved
 * by an impact this step or stays apart from the body's latest impact to the end of the step (ball
 * pairs by an exact sweep, boundary faces, planes and segments along their normal with gravity, from
 * the later of the two bodies' latest impacts: their paths before it are not the ones the corrections
 * describe). The soft substeps never touch a clean body (its impacted rows are taken out of them), so:
 * - a clean body keeps its end-position correction, and ends exactly at x0 + v0 t* + v1 (h - t*);
 * - a row between clean bodies that stays apart gets a start separation the soft substeps' linear gap
 *   model cannot close within the step (nor in the one substep the last relax pass looks ahead): that
 *   model underestimates the gap of two balls passing obliquely and looks a substep past the step, and
 *   would otherwise stop the bodies early along the wrong normal (Box2D's speculative contacts do
 *   that), leaving the bounce to the restitution stage, which loses energy when a body has several
 *   such rows (the elastic gas of 500 balls lost 6 % of its energy in 20,000 steps that way).
 * A body with a row the soft substeps will work on (resting in a pile, say) loses its corrections:
 * the substeps' positions must stay consistent with their own rows, so its impulses act as if at the
 * start of the step (Box2D-like), which only ever widens the impacted pair's gap and never adds
 * energy. Such a body makes a clean neighbour unclean too when the linear gap model of the row between
 * them could close within the step (the substeps would push the neighbour), until no more change.
 * Last, every row's start separation takes in the corrections that remain, (c_B - c_A) . n: the
 * substeps move a clean body as if from its start and its correction is added at the end, so their gap
 * at the end of the step is then the true one (a clean body beside an unclean one no longer ends
 * inside it: the elastic pile's worst one-step energy rise went from 3.9e-4 to 7e-8 of the total).
 */
export function separateImpactedBodies(world: PhysicsWorld, buf: ContactBuffer, S: number, candidates: number): void {
  const cs = world.collision;
  const imp = cs.bodyImpact,
    key = cs.impactKey;
  const count = cs.solverBodyCount;
  const n = buf.count;
  const E = buf.restitution,
    S0 = buf.separation,
    IA = buf.ia,
    IB = buf.ib,
    K = buf.kind;
  const h = world.h;
  const reach = h * (1 + 1 / cs.settings.solverSubsteps);
  impactScalars[2] = reach;
  // A row is given the spare gap below if its gap is within the linear model's closure or, in a world
  // with joints, within 1.1 times it: a joint row turns gravity toward the row's normal within the step
  // (a pendulum's string speeds the ball up as it swings down), which the model does not see: a hanging
  // Newton's cradle's lifted ball whose gap is a little wider than the closure would be stopped by the
  // soft substeps' look-ahead a substep before its hit, across the gap, and the chain behind it lost.
  // Without joints the band is not widened: in a pile many rows fall in it (mostly balls falling onto
  // the floor), and they are better left to the substeps.
  const within = jointsToSolve(world) ? 1.1 : 1;
  // First, while BI_TIME still holds each body's latest impact time: which rows stay active, into
  // the spent order array (1 active, 0 not). BI_ALONE of a body's row: 1 clean, 0 not (the static world
  // is clean), marked here as rows are found active; the corrections of unclean bodies are dropped
  // only after this pass (the sweeps read them). A row whose bodies are both unclean already changes
  // nothing below, so it is not swept (marked 1); a row that carried load last step and starts
  // touching is active without a sweep (its bodies were loaded, never impacted: ballsMeet and
  // faceMeets return true at once). In a resting pile that skips nearly every sweep.
  const Q = IMPACT_STRIDE;
  const act = cs.impactOrder;
  // The loaded rows that start touching: carriesLoad from applyImpacts' first pass, whose bodies it
  // marked -1 in BI_ALONE; an impacted row's normal has changed since, so it is asked again (the
  // candidates are still at the front of `act`, the order array, until the pass below).
  for (let k = 0; k < count; k++) imp[k * Q + BI_ALONE] = imp[k * Q + BI_ALONE] === -1 ? 0 : 1;
  const loaded = impactScratch.loaded;
  for (let k = 0; k < candidates; k++) {
    const i = act[k]!;
    if (key[i] !== -1) continue;
    loaded[i] = carriesLoad(world, buf, i) ? 1 : 0;
    if (S0[i]! <= 0 && loaded[i] === 1) {
      imp[IA[i]! * Q + 4] = 0;
      imp[IB[i]! * Q + 4] = 0;
    }
  }
  imp[BI_ALONE] = 1;
  // The rows left inactive, in row order, for the repeated pass below.
  if (impactScratch.idle.length < n) impactScratch.idle = new Int32Array(Math.max(n, 2 * impactScratch.idle.length));
  const idle = impactScratch.idle;
  let idleCount = 0;
  for (let i = 0; i < n; i++) {
    if (S0[i]! <= 0 && loaded[i] === 1) {
      act[i] = 1;
      continue;
    }
    act[i] = 0;
    const ia = IA[i]!,
      ib = IB[i]!;
    if (imp[ib * Q + BI_ALONE] === 0 && (ia === 0 || imp[ia * Q + BI_ALONE] === 0)) {
      act[i] = 1;
      continue;
    }
    const kind = K[i]!;
    let active: boolean;
    if (E[i]! > 0 && key[i] === -1) {
      // Resolved by an impact: active again only if the bodies touch again while approaching before
      // the step ends (a later impact of either body turned them back; the passes left it to the
      // substeps, below the threshold or past the pass cap).
      active = contactState(world, buf, i, S);
      if (active) key[i] = 0;
    } else if (kind === ContactKind.Ball || kind === ContactKind.StaticBall) {
      active = ballsMeet(world, buf, i, S);
    } else {
      active = faceMeets(world, buf, i, S);
    }
    if (active) {
      act[i] = 1;
      if (ia !== 0) imp[ia * Q + BI_ALONE] = 0;
      imp[ib * Q + BI_ALONE] = 0;
    } else idle[idleCount++] = i;
  }
  // An unclean body loses its corrections (the substeps move it from where it was at the start of the step).
  for (let k = 1; k < count; k++) if (imp[k * Q + BI_ALONE] === 0) unclean(imp, k);
  // A clean body with a row to an unclean one becomes unclean too if the substeps' linear gap model
  // of that row could close within the step: the substeps would push it. Repeated until nothing changes.
  // (Only the inactive rows are visited; a row made active leaves the list, which keeps row order.)
  // A body only ever turns unclean here, so a row leaves the list for good once it cannot turn active:
  // both bodies unclean, or one unclean and its gap model not closing (its inputs change only if the
  // clean body turns unclean too). The rows kept, with both bodies clean, see the same bodies' states in
  // the same order, so the outcome is that of visiting every inactive row each time.
  for (let changed = true; changed; ) {
    changed = false;
    let kept = 0;
    for (let k = 0; k < idleCount; k++) {
      const i = idle[k]!;
      const ia = IA[i]!,
        ib = IB[i]!;
      const ca = ia === 0 || imp[ia * Q + BI_ALONE] === 1,
        cb = imp[ib * Q + BI_ALONE] === 1;
      if (ca && cb) {
        idle[kept++] = i;
        continue;
      }
      if (!ca && !cb) continue;
      if (!linearCloses(world, buf, i, S)) continue;
      act[i] = 1;
      unclean(imp, ca ? ia : ib);
      changed = true;
    }
    idleCount = kept;
  }
  for (let i = 0; i < n; i++) {
    // The substeps move a body from where it was at the start of the step and add its correction at
    // the end, so every row's start separation takes the corrections in: the substeps' gap at the end
    // of the step is then the true one, also between a clean body and an unclean one.
    const ua = IA[i] !== 0 && imp[IA[i]! * Q + 4] === 0,
      ub = imp[IB[i]! * Q + 4] === 0;
    if (ub && (ua || IA[i] === 0)) continue; // unclean bodies and the static world have no corrections
    const gap = correctionGap(imp, buf, i),
      was = S0[i]!;
    S0[i] = was + gap;
    if (gap !== 0 || was === 0) markChanged(i); // (-0 + 0 is 0)
    if (ua || ub) continue;
    if (E[i]! > 0 && key[i] === -1) {
      // Impacted rows between clean bodies leave the soft substeps (releaseImpactedRows).
      markChanged(i);
      impactScratch.releasedRows[impactScratch.releasedCount++] = i;
      continue;
    }
    // A row between clean bodies that stays apart through the step gets a start separation the soft
    // substeps' linear gap model cannot close within the step (nor in the one substep the last relax
    // pass looks ahead): the model would otherwise stop the bodies early, along the wrong normal for
    // balls passing obliquely (Box2D's speculative contacts do that), and leave the bounce to the
    // restitution stage, which loses energy when a body has several such rows.
    const s0 = S0[i]!;
    if (!(s0 > 0)) continue;
    const closes = linearClosure(world, buf, i, S);
    // 10 % to spare: other rows (a joint, say) may speed the approach up a little within the step.
    if (s0 <= closes * within) {
      S0[i] = closes * 1.1;
      markChanged(i);
    }
  }
}

/**
 * The smallest load `carriesLoad` counts, dimensionless: LN h / m_eff > LOAD_FLOOR (ra + rb), the
 * relative normal velocity change of the row's warm-start impulse LN (N s) over the step h (s), as a
 * fraction of the pair's lever arms (the radii for balls). Touching balls placed at exactly their
 * radii overlap by ~1e-16 m after a few steps' additions and their soft row pushes that out with
 * ~1e-17 N s; a load that matters is many orders above (the weight a resting ball carries is
 * m g h / substeps, 0.04 N s for 1 kg at 60 Hz; a squeezed gravity-free cluster's push-out is larger).
 */
const LOAD_FLOOR = 1e-9;

/**
 * A gap or a relative normal approach over one step smaller than ROUNDING times the pair's lever arms
 * (ra + rb, the radii for balls) is floating-point noise, dimensionless (positions of order 1 m carry
 * ~1e-16 m of rounding; two touching balls swinging together on parallel strings approach or part at
 * ~1e-17 m/s). See carriesLoad and ballsMeet.
 */
const ROUNDING = 1e-12;

/** A row whose normal is within LEVEL (rad, small) of perpendicular to gravity is level: |n . g| <= LEVEL |g| (see carriesLoad). */
const LEVEL = 1e-9;

/**
 * Whether contact i carried a load last step (a warm-started row: a body resting in a pile or on the
 * floor, or pressed by a joint), which keeps its bodies out of the impact stage. A load counts when
 * it is above LOAD_FLOOR. A smaller one is the push-out of a rounding-level overlap, and it does not
 * count:
 * - without gravity, always: nothing rests there; counting such a push kept both
 *   balls of two touching movers out of the impact stage, and a Newton's cradle hit by them would
 *   lose energy at some phases of the step;
 * - under gravity (the world's, m/s^2), only on a ball-ball row that touches to rounding
 *   (|s0| <= ROUNDING (ra + rb)), whose bodies do not move relative to each other along the normal
 *   (|v_n| h <= ROUNDING (ra + rb), v_n at the start of the step) and whose normal is level (gravity
 *   cannot press it: |n . g| <= LEVEL |g|): exactly touching balls side by side at rest relative to
 *   each other, as a hanging Newton's cradle's or the lifted balls swinging together. Counting their
 *   rounding-level loads left the whole chain to the soft substeps at some lift angles (two or three of
 *   4 to 8 balls lifted: the balls behind the first hit left too, the far ones at 0.3 to 0.8 of the
 *   entering speed). Other rounding-level loads still count under gravity: a pile's rows carry such
 *   loads as balls land (1e-18 to 1e-15 N s, on rows a little apart or moving), and not counting those
 *   changed how an 800-ball pile of balls-in-box settles (fastest ball 0.57 m/s after 300 steps instead
 *   of 0.002, at rest from step 363 instead of 291; over seeds 1 to 8 at rest at least 10 steps later
 *   on average, one not by step 400; test/physics/threads-contact-colors.test.ts asks for under 0.1 m/s
 *   at step 300). So do boundary walls and oblique rows: balls put exactly onto a side wall slide down
 *   it with such loads, and not counting those (or one oblique ball-ball row) raised the 2,000-ball
 *   pile's worst one-step energy rise from 4.8e-7 to 4.4e-6 of the total (test/physics/pile.test.ts
 *   bounds it at 1e-6).
 * A row with m_eff = 0 counts whenever LN > 0.
 */
export function carriesLoad(world: PhysicsWorld, buf: ContactBuffer, i: number): boolean {
  const h = world.h,
    g = world.gravity;
  const ln = buf.normalImpulse[i]!;
  if (!(ln > 0)) return false;
  const len = buf.ra[i]! + buf.rb[i]!;
  if (ln * h > LOAD_FLOOR * len * buf.normalMass[i]!) return true;
  const g2 = g[0]! * g[0]! + g[1]! * g[1]! + g[2]! * g[2]!;
  if (!(g2 > 0)) return false;
  if (buf.kind[i] !== ContactKind.Ball) return true;
  const tiny = ROUNDING * len;
  const gn = g[0]! * buf.nx[i]! + g[1]! * buf.ny[i]! + g[2]! * buf.nz[i]!;
  return !(Math.abs(buf.separation[i]!) <= tiny && Math.abs(buf.relativeVelocity[i]!) * h <= tiny && gn * gn <= LEVEL * LEVEL * g2);
}

/** Marks solver body k unclean (BI_ALONE = 0) and drops its end-position corrections; the static world stays clean. */
function unclean(imp: Float64Array, k: number): void {
  if (k === 0) return;
  const q = k * IMPACT_STRIDE;
  imp[q + BI_CORR_X] = 0;
  imp[q + BI_CORR_Y] = 0;
  imp[q + BI_CORR_Z] = 0;
  imp[q + BI_ALONE] = 0;
}

/**
 * How far the soft substeps' linear gap model of contact i can close within reach (`impactScalars[2]`:
 * the step plus the substep the last relax pass looks ahead, s) at the current solver velocities, m (>= 0): the normal
 * approach and gravity's relative normal acceleration, each counted only when it closes the gap.
 */
function linearClosure(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): number {
  const reach = impactScalars[2]!;
  normalMotion(world, buf, i, S);
  const vn = motionIO[1]!,
    an = motionIO[2]!;
  return (vn < 0 ? -vn * reach : 0) + (an < 0 ? -an * reach * reach : 0);
}

/**
 * Whether the soft substeps' linear gap model of contact i closes within the reach (see linearClosure),
 * from the start separation opened by the bodies' corrections (those of unclean bodies are zero).
 */
function linearCloses(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  return buf.separation[i]! + correctionGap(world.collision.bodyImpact, buf, i) <= linearClosure(world, buf, i, S);
}

/** (c_B - c_A) . n of contact i: how much the bodies' end-position corrections open its gap, m. */
function correctionGap(imp: Float64Array, buf: ContactBuffer, i: number): number {
  const qa = buf.ia[i]! * IMPACT_STRIDE,
    qb = buf.ib[i]! * IMPACT_STRIDE;
  return (
    (imp[qb + BI_CORR_X]! - imp[qa + BI_CORR_X]!) * buf.nx[i]! +
    (imp[qb + BI_CORR_Y]! - imp[qa + BI_CORR_Y]!) * buf.ny[i]! +
    (imp[qb + BI_CORR_Z]! - imp[qa + BI_CORR_Z]!) * buf.nz[i]!
  );
}

/**
 * Whether the balls of contact i touch at their latest impact this step (t0, or the start of the step)
 * or before the step ends, at the current solver velocities: an exact sweep from t0 with
 * the relative acceleration of gravity refined once. The path before t0 is not the bodies' (the
 * position corrections make x0 + dx + v t exact only after the latest impact), so it is not swept.
 */
function ballsMeet(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  const imp = world.collision.bodyImpact;
  const qa = buf.ia[i]! * IMPACT_STRIDE,
    qb = buf.ib[i]! * IMPACT_STRIDE;
  const still =
    imp[qa + BI_CORR_X] === 0 &&
    imp[qa + BI_CORR_Y] === 0 &&
    imp[qa + BI_CORR_Z] === 0 &&
    imp[qb + BI_CORR_X] === 0 &&
    imp[qb + BI_CORR_Y] === 0 &&
    imp[qb + BI_CORR_Z] === 0;
  const s0 = buf.separation[i]!;
  if (still && s0 <= 0) {
    // Touching: active if it carries load (warm start), overlaps, approaches (closing more than a
    // rounding-level length within the step), or gravity presses it.
    const R = contactRadius(world, buf, i);
    if (carriesLoad(world, buf, i) || s0 < -1e-6 * R) return true;
    normalMotion(world, buf, i, S);
    return motionIO[1]! * world.h < -ROUNDING * R || motionIO[2]! < 0;
  }
  // Relative position and velocity at t0, the later of the bodies' latest impacts (0 if none).
  const t0 = latestImpactTime(imp, qa, qb);
  ballMotion(world, buf, i, S, t0);
  const io = sweepIO;
  const rx = io[0]!,
    ry = io[1]!,
    rz = io[2]!,
    wx = io[3]!,
    wy = io[4]!,
    wz = io[5]!,
    R = io[6]!;
  const ax = motionIO[0]!,
    ay = motionIO[1]!,
    az = motionIO[2]!;
  const rest = world.h - t0;
  const r2 = rx * rx + ry * ry + rz * rz;
  if (r2 <= R * R * (1 + 1e-9)) {
    // Overlapping (the substeps push them apart), or touching and approaching at t0 or by the end, by
    // more than ROUNDING R over a step (two touching balls swinging together on parallel strings
    // approach or part at rounding-level speeds; counted, that left both to the soft substeps, whose
    // look-ahead stopped the pair's hit on the next ball a substep early, across a gap, and then the
    // chain as if resting).
    if (r2 < R * R * (1 - 1e-6)) return true;
    const lim = (-ROUNDING * R * R) / world.h;
    return rx * wx + ry * wy + rz * wz < lim || rx * (wx + ax * rest) + ry * (wy + ay * rest) + rz * (wz + az * rest) < lim;
  }
  if (!(rest > 0)) return false;
  const hx = 0.25 * ax * rest,
    hy = 0.25 * ay * rest,
    hz = 0.25 * az * rest;
  // The gap cannot close faster than |w| + |a| t.
  const gap = Math.sqrt(rx * rx + ry * ry + rz * rz) - R;
  if (Math.sqrt(wx * wx + wy * wy + wz * wz) * rest + 2 * Math.sqrt(hx * hx + hy * hy + hz * hz) * rest < gap) return false;
  // Mean velocity over the first half of the span and over all of it: either meeting counts (r and R
  // are in sweepIO from ballMotion).
  io[7] = rest;
  io[3] = wx + hx;
  io[4] = wy + hy;
  io[5] = wz + hz;
  if (sweep()) return true;
  io[3] = wx + 2 * hx;
  io[4] = wy + 2 * hy;
  io[5] = wz + 2 * hz;
  return sweep();
}

/**
 * Whether ball B of a fixed-normal contact i (boundary face, plane, segment) overlaps or touches the
 * face at t0 (the later of the bodies' latest impacts this step, or the start) or reaches it before the
 * step ends: s(t) = s(t0) + v_n (t - t0) + a_n (t - t0)^2 / 2 along the contact's normal, exact for a
 * face that does not turn (a segment's end point is treated as its tangent line, which can only
 * see a touch that is not there).
 */
function faceMeets(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  const imp = world.collision.bodyImpact;
  const t0 = latestImpactTime(imp, buf.ia[i]! * IMPACT_STRIDE, buf.ib[i]! * IMPACT_STRIDE);
  faceMotion(world, buf, i, S, t0);
  const s = motionIO[0]!,
    v = motionIO[1]!,
    an = motionIO[2]!;
  if (s <= 0) return true;
  const rest = world.h - t0;
  // Smallest s over [t0, h]: at the end, or where v + a_n t = 0 if that falls inside.
  const tm = an > 0 && v < 0 ? Math.min(-v / an, rest) : rest;
  return s + v * tm + 0.5 * an * tm * tm <= 0 || s + v * rest + 0.5 * an * rest * rest <= 0;
}
