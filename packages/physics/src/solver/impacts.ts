import type { ContactBuffer } from '../collision/contacts.js';
import type { PhysicsWorld } from '../world/options.js';
import { BI_ALONE, BI_TIME, BS2_STRIDE, BS2_VX, BS2_VY, BS3_STRIDE, BS3_VZ, IMPACT_STRIDE } from './body-state-layout.js';
import { fastEnough, impact } from './impact-contact.js';
import { carriesLoad, separateImpactedBodies } from './impact-separation.js';
import { impactScalars, impactScratch } from './impact-state.js';
import { sortByKey } from './sort-by-key.js';

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
  for (let k = 0; k < impactScratch.releasedCount; k++) {
    const i = impactScratch.releasedRows[k]!;
    NM[i] = 0;
    TM[i] = 0;
    LN[i] = 0;
    L1[i] = 0;
    L2[i] = 0;
  }
  impactScratch.releasedCount = 0;
}

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
  const S = world.dimensions === 2 ? BS2_STRIDE : BS3_STRIDE;
  // cs.bodyImpact holds a zeroed row for each solver body (solver/contact-solver.ts clearBodyImpacts).
  // Bodies that carried a load last step (a warm-started contact: resting in a pile, on the floor)
  // are left to the soft substeps and the restitution stage; BI_TIME (time of the latest impact)
  // marks them -1 until the passes are done.
  const imp = cs.bodyImpact,
    IA = buf.ia,
    IB = buf.ib;
  // Each row's carriesLoad at the start of the stage, kept for separateImpactedBodies (1 loaded, 0
  // not): only an impacted row's normal changes in between, and that one is recomputed there.
  if (impactScratch.loaded.length < n) impactScratch.loaded = new Uint8Array(Math.max(n, 2 * impactScratch.loaded.length));
  const loaded = impactScratch.loaded;
  if (impactScratch.changedMark.length < n) {
    const len = Math.max(n, 2 * impactScratch.changedMark.length);
    impactScratch.changedMark = new Uint8Array(len);
    impactScratch.changedRows = new Int32Array(len);
    impactScratch.releasedRows = new Int32Array(len);
  }
  for (let k = 0; k < impactScratch.changedCount; k++) impactScratch.changedMark[impactScratch.changedRows[k]!] = 0;
  impactScratch.changedCount = 0;
  impactScratch.releasedCount = 0;
  for (let i = 0; i < n; i++) {
    if (!carriesLoad(world, buf, i)) {
      loaded[i] = 0;
      continue;
    }
    loaded[i] = 1;
    const qa = IA[i]! * IMPACT_STRIDE,
      qb = IB[i]! * IMPACT_STRIDE;
    if (qa !== 0) imp[qa + BI_TIME] = -1;
    imp[qb + BI_TIME] = -1;
    // A loaded row that starts touching makes its bodies unclean in separateImpactedBodies: marked
    // here in BI_ALONE (-1; nothing reads it before separateImpactedBodies).
    if (S0[i]! <= 0) {
      if (qa !== 0) imp[qa + BI_ALONE] = -1;
      imp[qb + BI_ALONE] = -1;
    }
  }
  // One pass picks the candidates: seeds (fast enough) from the front of `order`, the others from its
  // back (in reverse), then moved behind the seeds in row order.
  const sb = cs.bodyState;
  const lim = resting - gh,
    lim2 = lim * lim,
    is2D = S === BS2_STRIDE;
  let m = 0,
    back = n;
  for (let i = 0; i < n; i++) {
    key[i] = 0;
    if (!(E[i]! > 0)) continue;
    const ia = IA[i]!,
      ib = IB[i]!;
    if (imp[ib * IMPACT_STRIDE + BI_TIME] === -1 || (ia !== 0 && imp[ia * IMPACT_STRIDE + BI_TIME] === -1)) continue;
    // fastEnough, inline.
    let fast = true;
    if (resting !== 0 && lim > 0) {
      const oa = ia * S,
        ob = ib * S;
      const wx = sb[ob + BS2_VX]! - sb[oa + BS2_VX]!,
        wy = sb[ob + BS2_VY]! - sb[oa + BS2_VY]!,
        wz = is2D ? 0 : sb[ob + BS3_VZ]! - sb[oa + BS3_VZ]!;
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
