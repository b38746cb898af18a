import { type ContactBuffer, ContactKind } from '../collision/contacts.js';
import { BodyType } from '../collision/state.js';
import { jointsToSolve } from '../joints/solver-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { joints3DToSolve } from './rows-3d.js';

/**
 * Row length of `CollisionState.bodyImpact`: the end-position correction (x, y, z), m; the time of the
 * body's latest impact this step, s (-1: the body carried a load and is left to the substeps); and
 * whether the soft substeps leave the body alone (1) or not (0), set by `separateImpactedBodies`.
 * @category Collision
 */
export const IMPACT_STRIDE = 5;

/**
 * Scratch of `applyImpacts` read by `separateImpactedBodies` within the same call: per contact row,
 * 1 if it carried a load (`carriesLoad`) at the start of the stage, else 0. Not world state.
 */
let loadedRows = new Uint8Array(256);

/** Scratch of `separateImpactedBodies`: the indices of the contact rows still inactive, in row order. Not world state. */
let idleRows = new Int32Array(256);

/**
 * Scratch of one `applyImpacts` call: [resting, gh, reach] (m/s, m/s, s; see applyImpacts and
 * separateImpactedBodies), read by the helpers it calls. Doubles reach the helpers through this and
 * `sweepIO`, not as arguments: V8 boxes (allocates) every double passed to or returned from a call it
 * does not inline, which was most of what the step allocated in a large pile. Not world state.
 */
const impactScalars = new Float64Array(3);

/**
 * Scratch of `sweep`: its arguments r (x, y, z), u (x, y, z), R and span, then its result t (slot 8).
 * Not world state.
 */
const sweepIO = new Float64Array(9);

/**
 * Rows the last `applyImpacts` changed a value of that the soft substeps read (normal, start
 * separation), each once, in the order first changed: `changedRows[0 .. changedCount - 1]`, with
 * `changedMark` (1: listed) for the rows of that call. And the impacted rows it takes out of the soft
 * substeps (`releasedRows[0 .. releasedCount - 1]`), whose masses and impulses `releaseImpactedRows`
 * zeroes. Read through impactChangedRows. Not world state.
 */
let changedRows = new Int32Array(256),
  changedMark = new Uint8Array(256),
  releasedRows = new Int32Array(256);
let changedCount = 0,
  releasedCount = 0;

/** Lists row i as changed by the impact stage (once). */
function markChanged(i: number): void {
  if (changedMark[i] === 1) return;
  changedMark[i] = 1;
  changedRows[changedCount++] = i;
}

/**
 * The rows the last `applyImpacts` changed a value of that the soft substeps read (the normal of an
 * impacted row, a start separation that took in corrections or a spare gap; the rows
 * `releaseImpactedRows` zeroes are among them): rows[0 .. count - 1], each once. A coloured solve whose
 * rows were packed while the stage ran packs these again (solver/coloring.ts). Valid until the next call.
 * @category Collision
 */
export function impactChangedRows(): { rows: Int32Array; count: number } {
  return { rows: changedRows, count: changedCount };
}

/**
 * Takes the rows the last `applyImpacts` resolved between clean bodies out of the soft substeps: their
 * normal and tangent masses and impulses become 0 (a row with nothing to move and nothing to warm start
 * does nothing in a pass). Kept apart from `applyImpacts` so the coloured solve can plan its rows from
 * the values before it (solver/coloring.ts: the plan runs on a worker beside the stage). Call it once,
 * after `applyImpacts` and before the substeps.
 * @category Collision
 */
export function releaseImpactedRows(buf: ContactBuffer): void {
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2;
  for (let k = 0; k < releasedCount; k++) {
    const i = releasedRows[k]!;
    NM[i] = 0;
    TM[i] = 0;
    LN[i] = 0;
    L1[i] = 0;
    L2[i] = 0;
  }
  releasedCount = 0;
}

/** Scratch of `sortByKey`: the merge sort's two work arrays. Not world state. */
let sortWork1 = new Int32Array(256),
  sortWork2 = new Int32Array(256);

/**
 * Collide stage, solver stage "impacts": the bouncing contacts of a step, resolved as a sequence of
 * pairwise impacts at their times of impact before the soft substeps run.
 *
 * A contact takes part if its combined restitution e > 0 and neither body carried a load last step
 * (a warm-started contact: a body resting in a pile or on the floor is left to the soft substeps and
 * the restitution stage, which keep piles still; a rounding-level load is not counted without
 * gravity, nor under it between exactly touching bodies at rest relative to each other, such as the
 * balls of a hanging Newton's cradle: see `carriesLoad`). For each, the time of impact t* in
 * [t_start, h] is found from the bodies' motion within the step: t_start is the latest earlier impact of
 * either body this step; ball-ball and ball-static-ball pairs by an exact sphere sweep (Ericson,
 * Real-Time Collision Detection, 5.5.7) along their current relative velocity (with the relative
 * acceleration of gravity, refined once), so the normal is the line of centres where the balls touch;
 * boundary faces, planes and segments along the contact's normal, s(t) = s0 + v_n t + a_n t^2 / 2.
 * If the normal approach speed at t* exceeds the contact's restitution threshold (see
 * `CollisionSettings.restitutionThreshold` and `elasticRestitutionThreshold`), the pair receives
 * the Newton impulse J = -(1 + e) v_n m_eff along the normal (Ramtal and Dobre ch. 11; any mechanics
 * text) and a Coulomb friction impulse |J_t| <= mu J at the contact point. A pairwise impulse conserves
 * momentum exactly and, for e = 1 and no friction, kinetic energy exactly, so an elastic gas or a
 * Newton's cradle keeps its energy however many contacts share a step.
 *
 * The velocity change dv of an impact at t* is applied to the whole step's velocity, and the body's
 * end position is corrected by -dv t* (it moved with the old velocity until t*): the body ends where
 * the exact piecewise motion puts it, never bouncing across a gap. The corrections are kept per solver
 * body (see `CollisionState.bodyImpact`) and added when the solver writes positions back, for the
 * bodies the soft substeps leave alone (see `separateImpactedBodies`).
 *
 * Contacts are visited in order of their predicted time of impact, in passes, until a pass applies
 * no impulse or `impactIterations` passes have run (a chain like Newton's cradle needs one pass in
 * that order; the cap bounds the work in dense piles). What is left approaching falls to the soft
 * substeps and the restitution stage.

 *
 * Then `separateImpactedBodies` sorts the bodies into those the soft substeps leave alone (they keep
 * their exact end positions) and the rest.
 * @category Collision
 */
export function applyImpacts(world: PhysicsWorld, buf: ContactBuffer): void {
  const cs = world.collision;
  const st = cs.settings;
  const n = buf.count;
  const E = buf.restitution;
  // Candidates: every contact with e > 0; those whose bodies approach fast enough to impact this step
  // (the seeds) first, sorted by the time of impact their start state predicts.
  if (cs.impactOrder.length < n) {
    cs.impactOrder = new Int32Array(Math.max(n, 2 * cs.impactOrder.length));
    cs.impactKey = new Float64Array(cs.impactOrder.length);
  }
  const order = cs.impactOrder,
    key = cs.impactKey;
  const h = world.h;
  const g = world.gravity;
  const gh = Math.sqrt(g[0]! * g[0]! + g[1]! * g[1]! + g[2]! * g[2]!) * h;
  // Slower approaches are resting contacts (what gravity adds in two steps), left to the substeps.
  const resting = 2 * gh;
  impactScalars[0] = resting;
  impactScalars[1] = gh;
  const S0 = buf.separation,
    RV = buf.relativeVelocity;
  const count = cs.solverBodyCount;
  const S = world.dimensions === 2 ? 8 : 12;
  // cs.bodyImpact holds a zeroed row for each solver body (solver/contact-solver.ts clearBodyImpacts).
  // Bodies that carried a load last step (a warm-started contact: resting in a pile, on the floor)
  // are left to the soft substeps and the restitution stage; slot 3 (time of the latest impact)
  // marks them -1 until the passes are done.
  const imp = cs.bodyImpact,
    IA = buf.ia,
    IB = buf.ib;
  // Each row's carriesLoad at the start of the stage, kept for separateImpactedBodies (1 loaded, 0
  // not): only an impacted row's normal changes in between, and that one is recomputed there.
  if (loadedRows.length < n) loadedRows = new Uint8Array(Math.max(n, 2 * loadedRows.length));
  const loaded = loadedRows;
  if (changedMark.length < n) {
    const len = Math.max(n, 2 * changedMark.length);
    changedMark = new Uint8Array(len);
    changedRows = new Int32Array(len);
    releasedRows = new Int32Array(len);
  }
  for (let k = 0; k < changedCount; k++) changedMark[changedRows[k]!] = 0;
  changedCount = 0;
  releasedCount = 0;
  for (let i = 0; i < n; i++) {
    if (!carriesLoad(world, buf, i)) {
      loaded[i] = 0;
      continue;
    }
    loaded[i] = 1;
    const qa = IA[i]! * IMPACT_STRIDE,
      qb = IB[i]! * IMPACT_STRIDE;
    if (qa !== 0) imp[qa + 3] = -1;
    imp[qb + 3] = -1;
    // A loaded row that starts touching makes its bodies unclean in separateImpactedBodies: marked
    // here in slot 4 (-1; nothing reads slot 4 before separateImpactedBodies).
    if (S0[i]! <= 0) {
      if (qa !== 0) imp[qa + 4] = -1;
      imp[qb + 4] = -1;
    }
  }
  // One pass picks the candidates: seeds (fast enough) from the front of `order`, the others from its
  // back (in reverse), then moved behind the seeds in row order.
  const sb = cs.bodyState;
  const lim = resting - gh,
    lim2 = lim * lim,
    is2D = S === 8;
  let m = 0,
    back = n;
  for (let i = 0; i < n; i++) {
    key[i] = 0;
    if (!(E[i]! > 0)) continue;
    const ia = IA[i]!,
      ib = IB[i]!;
    if (imp[ib * IMPACT_STRIDE + 3] === -1 || (ia !== 0 && imp[ia * IMPACT_STRIDE + 3] === -1)) continue;
    // fastEnough, inline.
    let fast = true;
    if (resting !== 0 && lim > 0) {
      const oa = ia * S,
        ob = ib * S;
      const wx = sb[ob]! - sb[oa]!,
        wy = sb[ob + 1]! - sb[oa + 1]!,
        wz = is2D ? 0 : sb[ob + 2]! - sb[oa + 2]!;
      fast = wx * wx + wy * wy + wz * wz > lim2;
    }
    if (!fast) {
      order[--back] = i;
      continue;
    }
    const s0 = S0[i]!,
      rv = RV[i]!;
    key[i] = s0 <= 0 ? 0 : rv < 0 ? s0 / -rv : 2 * h + s0;
    order[m++] = i;
  }
  const seeds = m;
  if (seeds === 0) {
    imp.fill(0, 0, count * IMPACT_STRIDE);
    return;
  }
  // The others, stored reversed in [back, n): put back in row order, then moved behind the seeds
  // (copyWithin copies as if through a buffer, so the ranges may overlap).
  for (let lo = back, hi = n - 1; lo < hi; lo++, hi--) {
    const t = order[lo]!;
    order[lo] = order[hi]!;
    order[hi] = t;
  }
  order.copyWithin(seeds, back, n);
  m += n - back;
  if (seeds > 1) sortByKey(order, key, seeds);

  const iterations = st.impactIterations;
  for (let pass = 0; pass < iterations; pass++) {
    let applied = 0;
    for (let k = 0; k < m; k++) {
      const i = order[k]!;
      if (!fastEnough(cs.bodyState, buf, i, S)) continue;
      if (impact(world, buf, i, S)) {
        applied++;
        key[i] = -1;
      }
    }
    if (applied === 0) break;
  }
  separateImpactedBodies(world, buf, S, m);
}

/**
 * Sorts order[0, n) by key[order[k]] ascending (key: impact times, s), with the permutation of V8's
 * order.subarray(0, n).sort((x, y) => key[x] - key[y]), which this replaced: V8 sorts a typed array
 * with a comparator by a stable top-down merge sort (into a copy, halving at from + (to - from) / 2,
 * taking the left element unless the comparison is > 0, a NaN comparison counting as 0), so ties and
 * even NaN keys come out in the same order. Without the closure and the boxed number each of its
 * calls returned (~250 kB a step at 20,000 balls) and the builtin's two work arrays. n >= 0 and
 * n <= order.length; order's entries index key. Exported for its test (impact-order.test.ts).
 * @category Collision
 */
export function sortByKey(order: Int32Array, key: Float64Array, n: number): void {
  if (n < 2) return;
  if (sortWork1.length < n) {
    const len = Math.max(n, 2 * sortWork1.length);
    sortWork1 = new Int32Array(len);
    sortWork2 = new Int32Array(len);
  }
  const w1 = sortWork1,
    w2 = sortWork2;
  for (let k = 0; k < n; k++) {
    const v = order[k]!;
    w1[k] = v;
    w2[k] = v;
  }
  mergeSortRange(w2, 0, n, w1, key);
  for (let k = 0; k < n; k++) order[k] = w1[k]!;
}

/**
 * Merge sort of [from, to) (to - from >= 2) into `target`, `source` holding the same elements there on
 * entry and used as the work array (the halves are sorted into it, then merged into target).
 */
function mergeSortRange(source: Int32Array, from: number, to: number, target: Int32Array, key: Float64Array): void {
  const middle = from + ((to - from) >>> 1);
  if (middle - from > 1) mergeSortRange(target, from, middle, source, key);
  if (to - middle > 1) mergeSortRange(target, middle, to, source, key);
  let left = from,
    right = middle;
  for (let k = from; k < to; k++) {
    if (left < middle && right >= to) target[k] = source[left++]!;
    else if (left < middle) {
      const l = source[left]!,
        r = source[right]!;
      if (!(key[l]! - key[r]! > 0)) {
        target[k] = l;
        left++;
      } else {
        target[k] = r;
        right++;
      }
    } else target[k] = source[right++]!;
  }
}

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
function separateImpactedBodies(world: PhysicsWorld, buf: ContactBuffer, S: number, candidates: number): void {
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
  // (a pendulum's string speeds the ball up as it swings down), which the model does not see. A hanging
  // Newton's cradle's lifted ball whose gap was 0.14 % wider than the closure was stopped by the soft
  // substeps' look-ahead a substep before its hit, across the gap, and the chain behind it was lost.
  // Without joints the band is not widened: in a pile many rows fall in it (mostly balls falling onto
  // the floor), and taking them from the substeps changed how an 800-ball pile settles.
  const within = jointsToSolve(world) || joints3DToSolve(world) ? 1.1 : 1;
  // First, while slot 3 still holds each body's latest impact time: which rows stay active, into
  // the spent order array (1 active, 0 not). Slot 4 of a body's row: 1 clean, 0 not (the static world
  // is clean), marked here as rows are found active; the corrections of unclean bodies are dropped
  // only after this pass (the sweeps read them). A row whose bodies are both unclean already changes
  // nothing below, so it is not swept (marked 1); a row that carried load last step and starts
  // touching is active without a sweep (its bodies were loaded, never impacted: ballsMeet and
  // faceMeets return true at once). In a resting pile that skips nearly every sweep.
  const Q = IMPACT_STRIDE;
  const act = cs.impactOrder;
  // The loaded rows that start touching: carriesLoad from applyImpacts' first pass, whose bodies it
  // marked -1 in slot 4; an impacted row's normal has changed since, so it is asked again (the
  // candidates are still at the front of `act`, the order array, until the pass below).
  for (let k = 0; k < count; k++) imp[k * Q + 4] = imp[k * Q + 4] === -1 ? 0 : 1;
  const loaded = loadedRows;
  for (let k = 0; k < candidates; k++) {
    const i = act[k]!;
    if (key[i] !== -1) continue;
    loaded[i] = carriesLoad(world, buf, i) ? 1 : 0;
    if (S0[i]! <= 0 && loaded[i] === 1) {
      imp[IA[i]! * Q + 4] = 0;
      imp[IB[i]! * Q + 4] = 0;
    }
  }
  imp[4] = 1;
  // The rows left inactive, in row order, for the repeated pass below.
  if (idleRows.length < n) idleRows = new Int32Array(Math.max(n, 2 * idleRows.length));
  const idle = idleRows;
  let idleCount = 0;
  for (let i = 0; i < n; i++) {
    if (S0[i]! <= 0 && loaded[i] === 1) {
      act[i] = 1;
      continue;
    }
    act[i] = 0;
    const ia = IA[i]!,
      ib = IB[i]!;
    if (imp[ib * Q + 4] === 0 && (ia === 0 || imp[ia * Q + 4] === 0)) {
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
      if (ia !== 0) imp[ia * Q + 4] = 0;
      imp[ib * Q + 4] = 0;
    } else idle[idleCount++] = i;
  }
  // An unclean body loses its corrections (the substeps move it from where it was at the start of the step).
  for (let k = 1; k < count; k++) if (imp[k * Q + 4] === 0) unclean(imp, k);
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
      const ca = ia === 0 || imp[ia * Q + 4] === 1,
        cb = imp[ib * Q + 4] === 1;
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
      releasedRows[releasedCount++] = i;
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
 *   balls of two touching movers out of the impact stage, and a Newton's cradle hit by them lost 15
 *   to 30 % of its energy at some phases of the step (issue 13);
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
function carriesLoad(world: PhysicsWorld, buf: ContactBuffer, i: number): boolean {
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

/** Marks solver body k unclean (slot 4 = 0) and drops its end-position corrections; the static world stays clean. */
function unclean(imp: Float64Array, k: number): void {
  if (k === 0) return;
  const q = k * IMPACT_STRIDE;
  imp[q] = 0;
  imp[q + 1] = 0;
  imp[q + 2] = 0;
  imp[q + 4] = 0;
}

/**
 * How far the soft substeps' linear gap model of contact i can close within reach (`impactScalars[2]`:
 * the step plus the substep the last relax pass looks ahead, s) at the current solver velocities, m (>= 0): the normal
 * approach and gravity's relative normal acceleration, each counted only when it closes the gap.
 */
function linearClosure(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): number {
  const reach = impactScalars[2]!;
  const cs = world.collision;
  const sb = cs.bodyState,
    type = cs.bodyType,
    g = world.gravity;
  const oa = buf.ia[i]! * S,
    ob = buf.ib[i]! * S;
  const nx = buf.nx[i]!,
    ny = buf.ny[i]!,
    nz = buf.nz[i]!;
  let vn = (sb[ob]! - sb[oa]!) * nx + (sb[ob + 1]! - sb[oa + 1]!) * ny;
  if (S !== 8) vn += (sb[ob + 2]! - sb[oa + 2]!) * nz;
  const a = buf.a[i]!,
    b = buf.b[i]!;
  const an =
    ((type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0)) * (g[0]! * nx + g[1]! * ny + g[2]! * nz);
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
  return (imp[qb]! - imp[qa]!) * buf.nx[i]! + (imp[qb + 1]! - imp[qa + 1]!) * buf.ny[i]! + (imp[qb + 2]! - imp[qa + 2]!) * buf.nz[i]!;
}

/**
 * Whether the balls of contact i touch at their latest impact this step (t0, or the start of the step)
 * or before the step ends, at the current solver velocities: an exact sweep from t0 with
 * the relative acceleration of gravity refined once. The path before t0 is not the bodies' (the
 * position corrections make x0 + dx + v t exact only after the latest impact), so it is not swept.
 */
function ballsMeet(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  const span = world.h;
  const cs = world.collision;
  const c = world.components;
  const sb = cs.bodyState,
    imp = cs.bodyImpact,
    type = cs.bodyType;
  const ia = buf.ia[i]!,
    ib = buf.ib[i]!;
  const oa = ia * S,
    ob = ib * S,
    qa = ia * IMPACT_STRIDE,
    qb = ib * IMPACT_STRIDE;
  const a = buf.a[i]!,
    b = buf.b[i]!,
    kind = buf.kind[i]!;
  const is2D = S === 8;
  const P = c.PreviousPosition,
    radius = c.Ball.radius;
  const f = kind === ContactKind.Ball ? a : buf.feature[i]!;
  const pa = kind === ContactKind.Ball ? P : c.Position;
  const R = radius[f]! + radius[b]!;
  const still = imp[qa] === 0 && imp[qa + 1] === 0 && imp[qa + 2] === 0 && imp[qb] === 0 && imp[qb + 1] === 0 && imp[qb + 2] === 0;
  const s0 = buf.separation[i]!;
  const g = world.gravity;
  const gr = (type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0);
  if (still && s0 <= 0) {
    // Touching: active if it carries load (warm start), overlaps, approaches (closing more than a
    // rounding-level length within the step), or gravity presses it.
    if (carriesLoad(world, buf, i) || s0 < -1e-6 * R) return true;
    const nx = buf.nx[i]!,
      ny = buf.ny[i]!,
      nz = buf.nz[i]!;
    let vn = (sb[ob]! - sb[oa]!) * nx + (sb[ob + 1]! - sb[oa + 1]!) * ny;
    if (!is2D) vn += (sb[ob + 2]! - sb[oa + 2]!) * nz;
    return vn * world.h < -ROUNDING * R || gr * (g[0]! * nx + g[1]! * ny + g[2]! * nz) < 0;
  }
  // Relative position and velocity at t0, the later of the bodies' latest impacts (0 if none).
  const ta = imp[qa + 3]!,
    tb = imp[qb + 3]!;
  const t0 = ta > tb ? (ta > 0 ? ta : 0) : tb > 0 ? tb : 0;
  const ax = gr * g[0]!,
    ay = gr * g[1]!,
    az = is2D ? 0 : gr * g[2]!;
  const wx = sb[ob]! - sb[oa]! + ax * t0,
    wy = sb[ob + 1]! - sb[oa + 1]! + ay * t0,
    wz = is2D ? 0 : sb[ob + 2]! - sb[oa + 2]! + az * t0;
  const rx = P.x[b]! + imp[qb]! - pa.x[f]! - imp[qa]! + (sb[ob]! - sb[oa]!) * t0 + 0.5 * ax * t0 * t0;
  const ry = P.y[b]! + imp[qb + 1]! - pa.y[f]! - imp[qa + 1]! + (sb[ob + 1]! - sb[oa + 1]!) * t0 + 0.5 * ay * t0 * t0;
  const rz = is2D ? 0 : P.z[b]! + imp[qb + 2]! - pa.z[f]! - imp[qa + 2]! + (sb[ob + 2]! - sb[oa + 2]!) * t0 + 0.5 * az * t0 * t0;
  const rest = span - t0;
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
  // Mean velocity over the first half of the span and over all of it: either meeting counts.
  const io = sweepIO;
  io[0] = rx;
  io[1] = ry;
  io[2] = rz;
  io[6] = R;
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
  const cs = world.collision;
  const sb = cs.bodyState,
    imp = cs.bodyImpact,
    type = cs.bodyType;
  const ia = buf.ia[i]!,
    ib = buf.ib[i]!;
  const oa = ia * S,
    ob = ib * S,
    qa = ia * IMPACT_STRIDE,
    qb = ib * IMPACT_STRIDE;
  const a = buf.a[i]!,
    b = buf.b[i]!;
  const g = world.gravity,
    h = world.h;
  const nx = buf.nx[i]!,
    ny = buf.ny[i]!,
    nz = buf.nz[i]!;
  let vn = (sb[ob]! - sb[oa]!) * nx + (sb[ob + 1]! - sb[oa + 1]!) * ny;
  if (S !== 8) vn += (sb[ob + 2]! - sb[oa + 2]!) * nz;
  const an =
    ((type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0)) * (g[0]! * nx + g[1]! * ny + g[2]! * nz);
  const ta = imp[qa + 3]!,
    tb = imp[qb + 3]!;
  const t0 = ta > tb ? (ta > 0 ? ta : 0) : tb > 0 ? tb : 0;
  const s =
    buf.separation[i]! +
    (imp[qb]! - imp[qa]!) * nx +
    (imp[qb + 1]! - imp[qa + 1]!) * ny +
    (imp[qb + 2]! - imp[qa + 2]!) * nz +
    vn * t0 +
    0.5 * an * t0 * t0;
  if (s <= 0) return true;
  const v = vn + an * t0,
    rest = h - t0;
  // Smallest s over [t0, h]: at the end, or where v + a_n t = 0 if that falls inside.
  const tm = an > 0 && v < 0 ? Math.min(-v / an, rest) : rest;
  return s + v * tm + 0.5 * an * tm * tm <= 0 || s + v * rest + 0.5 * an * rest * rest <= 0;
}

/**
 * Cheap test before the sweep: whether the bodies of contact i move apart fast enough, relative to
 * each other, that they could hit at more than the resting speed floor (`impactScalars[0]`, m/s)
 * within the step (|w| + g h > floor, g h = `impactScalars[1]`).
 */
function fastEnough(sb: Float64Array, buf: ContactBuffer, i: number, S: number): boolean {
  const floor = impactScalars[0]!,
    gh = impactScalars[1]!;
  if (floor === 0) return true;
  const oa = buf.ia[i]! * S,
    ob = buf.ib[i]! * S;
  const wx = sb[ob]! - sb[oa]!,
    wy = sb[ob + 1]! - sb[oa + 1]!,
    wz = S === 8 ? 0 : sb[ob + 2]! - sb[oa + 2]!;
  const lim = floor - gh;
  return lim <= 0 || wx * wx + wy * wy + wz * wz > lim * lim;
}

/** Scratch of `contactState`: time of impact, normal, relative normal velocity at t*. */
const hit = new Float64Array(5);

/**
 * Time of impact of contact i at the bodies' current solver state: writes [t*, nx, ny, nz, v_n(t*)]
 * into `hit` and returns true if the bodies touch within the step while approaching.
 */
function contactState(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  const cs = world.collision;
  const c = world.components;
  const sb = cs.bodyState,
    imp = cs.bodyImpact,
    type = cs.bodyType;
  const h = world.h;
  const ia = buf.ia[i]!,
    ib = buf.ib[i]!;
  const oa = ia * S,
    ob = ib * S,
    qa = ia * IMPACT_STRIDE,
    qb = ib * IMPACT_STRIDE;
  const a = buf.a[i]!,
    b = buf.b[i]!,
    kind = buf.kind[i]!;
  const is2D = S === 8;
  const g = world.gravity;
  const dynA = a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0,
    dynB = type[b] === BodyType.Dynamic ? 1 : 0;
  const gr = dynB - dynA;
  const ax = gr * g[0]!,
    ay = gr * g[1]!,
    az = is2D ? 0 : gr * g[2]!;
  const wx = sb[ob]! - sb[oa]!,
    wy = sb[ob + 1]! - sb[oa + 1]!,
    wz = is2D ? 0 : sb[ob + 2]! - sb[oa + 2]!;
  const t0 = Math.max(imp[qa + 3]!, imp[qb + 3]!);
  if (t0 > h) return false;
  if (kind === ContactKind.Ball || kind === ContactKind.StaticBall) {
    const P = c.PreviousPosition,
      radius = c.Ball.radius;
    const f = kind === ContactKind.Ball ? a : buf.feature[i]!;
    const pa = kind === ContactKind.Ball ? P : c.Position;
    const R = radius[f]! + radius[b]!;
    // Relative position at t0: r = r0 + d_offsets + w t0 + a t0^2 / 2.
    let rx = P.x[b]! + imp[qb]! - pa.x[f]! - imp[qa]! + wx * t0 + 0.5 * ax * t0 * t0;
    let ry = P.y[b]! + imp[qb + 1]! - pa.y[f]! - imp[qa + 1]! + wy * t0 + 0.5 * ay * t0 * t0;
    let rz = is2D ? 0 : P.z[b]! + imp[qb + 2]! - pa.z[f]! - imp[qa + 2]! + wz * t0 + 0.5 * az * t0 * t0;
    let ux = wx + ax * t0,
      uy = wy + ay * t0,
      uz = wz + az * t0;
    const c0 = rx * rx + ry * ry + rz * rz - R * R;
    let t = 0;
    if (c0 > 0) {
      const span = h - t0;
      const io = sweepIO;
      io[0] = rx;
      io[1] = ry;
      io[2] = rz;
      io[6] = R;
      io[7] = span;
      io[3] = ux;
      io[4] = uy;
      io[5] = uz;
      sweep();
      t = io[8]!;
      if (t < 0 && (ax !== 0 || ay !== 0 || az !== 0)) {
        // Gravity bends the relative path: sweep again with the velocity at the middle of the span.
        io[3] = ux + 0.5 * ax * span;
        io[4] = uy + 0.5 * ay * span;
        io[5] = uz + 0.5 * az * span;
        sweep();
        t = io[8]!;
      } else if (t >= 0 && (ax !== 0 || ay !== 0 || az !== 0)) {
        // Refine with the mean velocity over [0, t].
        io[3] = ux + 0.5 * ax * t;
        io[4] = uy + 0.5 * ay * t;
        io[5] = uz + 0.5 * az * t;
        sweep();
        const t2 = io[8]!;
        if (t2 >= 0) t = t2;
      }
      if (t < 0) return false;
      rx += ux * t + 0.5 * ax * t * t;
      ry += uy * t + 0.5 * ay * t * t;
      rz += uz * t + 0.5 * az * t * t;
      ux += ax * t;
      uy += ay * t;
      uz += az * t;
    }
    const d = Math.sqrt(rx * rx + ry * ry + rz * rz);
    if (!(d > 1e-12 * R)) return false;
    const nx = rx / d,
      ny = ry / d,
      nz = rz / d;
    const vn = ux * nx + uy * ny + uz * nz;
    if (!(vn < 0)) return false;
    hit[0] = t0 + t;
    hit[1] = nx;
    hit[2] = ny;
    hit[3] = nz;
    hit[4] = vn;
    return true;
  }
  // Fixed normal: boundary face, plane, segment.
  const nx = buf.nx[i]!,
    ny = buf.ny[i]!,
    nz = buf.nz[i]!;
  const an = ax * nx + ay * ny + az * nz;
  const vn0 = wx * nx + wy * ny + wz * nz;
  const s0 = buf.separation[i]! + (imp[qb]! - imp[qa]!) * nx + (imp[qb + 1]! - imp[qa + 1]!) * ny + (imp[qb + 2]! - imp[qa + 2]!) * nz;
  const s = s0 + vn0 * t0 + 0.5 * an * t0 * t0;
  const v = vn0 + an * t0;
  let t = 0;
  if (s > 0) {
    const disc = v * v - 2 * an * s;
    if (disc < 0) return false;
    const den = -v + Math.sqrt(disc);
    if (!(den > 0)) return false;
    t = (2 * s) / den;
    if (t0 + t > h) return false;
  }
  const vn = v + an * t;
  if (!(vn < 0)) return false;
  hit[0] = t0 + t;
  hit[1] = nx;
  hit[2] = ny;
  hit[3] = nz;
  hit[4] = vn;
  return true;
}

/**
 * Smallest t in [0, span] with |r + u t| = R for r outside the sphere, or -1: r, u, R and span read
 * from `sweepIO` (slots 0-7), t written to its slot 8; returns whether t >= 0.
 */
function sweep(): boolean {
  const io = sweepIO;
  const rx = io[0]!,
    ry = io[1]!,
    rz = io[2]!,
    ux = io[3]!,
    uy = io[4]!,
    uz = io[5]!,
    R = io[6]!,
    span = io[7]!;
  io[8] = -1;
  const cc = rx * rx + ry * ry + rz * rz - R * R;
  const bb = rx * ux + ry * uy + rz * uz;
  if (bb >= 0) return false;
  const aa = ux * ux + uy * uy + uz * uz;
  const disc = bb * bb - aa * cc;
  if (disc < 0) return false;
  // Stable root: t = c / (-b + sqrt(disc)).
  const t = cc / (-bb + Math.sqrt(disc));
  if (!(t <= span)) return false;
  io[8] = t;
  return t >= 0;
}

/**
 * Applies contact i's impact if it happens this step above its threshold (at least the resting speed,
 * `impactScalars[0]`); returns whether it did.
 */
function impact(world: PhysicsWorld, buf: ContactBuffer, i: number, S: number): boolean {
  if (!contactState(world, buf, i, S)) return false;
  const resting = impactScalars[0]!;
  const cs = world.collision;
  const st = cs.settings;
  const e = buf.restitution[i]!;
  const vn = hit[4]!;
  const threshold = Math.max(e >= 1 ? st.elasticRestitutionThreshold : st.restitutionThreshold, resting);
  if (!(vn < -threshold)) return false;
  const nm = buf.normalMass[i]!;
  if (!(nm > 0)) return false;
  const t = hit[0]!,
    nx = hit[1]!,
    ny = hit[2]!,
    nz = hit[3]!;
  const sb = cs.bodyState,
    imp = cs.bodyImpact,
    ex = cs.bodyExtra;
  const ia = buf.ia[i]!,
    ib = buf.ib[i]!;
  const oa = ia * S,
    ob = ib * S;
  const is2D = S === 8;
  const im = is2D ? 5 : 9,
    iI = is2D ? 6 : 10;
  const imA = sb[oa + im]!,
    imB = sb[ob + im]!,
    iiA = sb[oa + iI]!,
    iiB = sb[ob + iI]!;
  const ra = buf.ra[i]!,
    rb = buf.rb[i]!;
  const J = -(1 + e) * vn * nm;
  // The row's first impact this step records its approach speed (measureApproach keeps it for a row
  // that separates afterwards, so `impactVelocity` reports the hit, not the rebound).
  if (buf.impulse[i] === 0) buf.impactVelocity[i] = vn;
  let Px = J * nx,
    Py = J * ny,
    Pz = J * nz;
  // Coulomb friction at the contact point, bounded by mu J (contact-point velocity v + w x r, r_A = ra n, r_B = -rb n).
  const mu = buf.frictionBound[i]!;
  let dwa0 = 0,
    dwa1 = 0,
    dwa2 = 0,
    dwb0 = 0,
    dwb1 = 0,
    dwb2 = 0;
  if (mu > 0 && buf.tangentMass[i]! > 0) {
    const tm = buf.tangentMass[i]!;
    const maxF = mu * J;
    if (is2D) {
      const vt = (sb[ob]! - sb[oa]!) * -ny + (sb[ob + 1]! - sb[oa + 1]!) * nx - sb[ob + 2]! * rb - sb[oa + 2]! * ra;
      let lt = -tm * vt;
      lt = lt < -maxF ? -maxF : lt > maxF ? maxF : lt;
      Px += -lt * ny;
      Py += lt * nx;
      dwa2 = -iiA * ra * lt;
      dwb2 = -iiB * rb * lt;
    } else {
      let t1x: number, t1y: number, t1z: number;
      if (Math.abs(nx) < 0.57735) {
        const inv = 1 / Math.sqrt(ny * ny + nz * nz);
        t1x = 0;
        t1y = nz * inv;
        t1z = -ny * inv;
      } else {
        const inv = 1 / Math.sqrt(nx * nx + ny * ny);
        t1x = ny * inv;
        t1y = -nx * inv;
        t1z = 0;
      }
      const t2x = ny * t1z - nz * t1y,
        t2y = nz * t1x - nx * t1z,
        t2z = nx * t1y - ny * t1x;
      const sx = -rb * sb[ob + 3]! - ra * sb[oa + 3]!,
        sy = -rb * sb[ob + 4]! - ra * sb[oa + 4]!,
        sz = -rb * sb[ob + 5]! - ra * sb[oa + 5]!;
      const ux = sb[ob]! - sb[oa]! + sy * nz - sz * ny,
        uy = sb[ob + 1]! - sb[oa + 1]! + sz * nx - sx * nz,
        uz = sb[ob + 2]! - sb[oa + 2]! + sx * ny - sy * nx;
      let l1 = -tm * (ux * t1x + uy * t1y + uz * t1z),
        l2 = -tm * (ux * t2x + uy * t2y + uz * t2z);
      const mag2 = l1 * l1 + l2 * l2;
      if (mag2 > maxF * maxF) {
        const q = maxF / Math.sqrt(mag2);
        l1 *= q;
        l2 *= q;
      }
      const Tx = l1 * t1x + l2 * t2x,
        Ty = l1 * t1y + l2 * t2y,
        Tz = l1 * t1z + l2 * t2z;
      Px += Tx;
      Py += Ty;
      Pz += Tz;
      const cx = ny * Tz - nz * Ty,
        cy = nz * Tx - nx * Tz,
        cz = nx * Ty - ny * Tx;
      dwa0 = -iiA * ra * cx;
      dwa1 = -iiA * ra * cy;
      dwa2 = -iiA * ra * cz;
      dwb0 = -iiB * rb * cx;
      dwb1 = -iiB * rb * cy;
      dwb2 = -iiB * rb * cz;
    }
  }
  const qa = ia * IMPACT_STRIDE,
    qb = ib * IMPACT_STRIDE;
  const xa = ia * 6,
    xb = ib * 6;
  // Velocity changes; positions corrected by -dv t (the bodies kept the old velocity until t).
  sb[oa] = sb[oa]! - imA * Px;
  sb[oa + 1] = sb[oa + 1]! - imA * Py;
  sb[ob] = sb[ob]! + imB * Px;
  sb[ob + 1] = sb[ob + 1]! + imB * Py;
  imp[qa] = imp[qa]! + imA * Px * t;
  imp[qa + 1] = imp[qa + 1]! + imA * Py * t;
  imp[qb] = imp[qb]! - imB * Px * t;
  imp[qb + 1] = imp[qb + 1]! - imB * Py * t;
  if (is2D) {
    if (iiA > 0) {
      sb[oa + 2] = sb[oa + 2]! + dwa2;
      ex[xa + 5] = ex[xa + 5]! - dwa2 * t;
    }
    if (iiB > 0) {
      sb[ob + 2] = sb[ob + 2]! + dwb2;
      ex[xb + 5] = ex[xb + 5]! - dwb2 * t;
    }
  } else {
    sb[oa + 2] = sb[oa + 2]! - imA * Pz;
    sb[ob + 2] = sb[ob + 2]! + imB * Pz;
    imp[qa + 2] = imp[qa + 2]! + imA * Pz * t;
    imp[qb + 2] = imp[qb + 2]! - imB * Pz * t;
    if (iiA > 0) {
      sb[oa + 3] = sb[oa + 3]! + dwa0;
      sb[oa + 4] = sb[oa + 4]! + dwa1;
      sb[oa + 5] = sb[oa + 5]! + dwa2;
      ex[xa + 3] = ex[xa + 3]! - dwa0 * t;
      ex[xa + 4] = ex[xa + 4]! - dwa1 * t;
      ex[xa + 5] = ex[xa + 5]! - dwa2 * t;
    }
    if (iiB > 0) {
      sb[ob + 3] = sb[ob + 3]! + dwb0;
      sb[ob + 4] = sb[ob + 4]! + dwb1;
      sb[ob + 5] = sb[ob + 5]! + dwb2;
      ex[xb + 3] = ex[xb + 3]! - dwb0 * t;
      ex[xb + 4] = ex[xb + 4]! - dwb1 * t;
      ex[xb + 5] = ex[xb + 5]! - dwb2 * t;
    }
  }
  if (ia !== 0 && imA > 0) imp[qa + 3] = t;
  if (imB > 0) imp[qb + 3] = t;
  buf.nx[i] = nx;
  buf.ny[i] = ny;
  buf.nz[i] = nz;
  markChanged(i);
  buf.impulse[i] = buf.impulse[i]! + J;
  return true;
}
