import { pushEvent } from '../collision/events.js';
import { findPrevious, rotateManifolds } from '../collision/manifolds-2d.js';
import type { CollisionState } from '../collision/state.js';
import { BodyType } from '../collision/state.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * The shape contacts' rows of the contact solver (solver/contact-solver.ts runs these calls next to the ball
 * contacts', in the same substeps, on the same packed body state): Box2D v3's manifold constraint
 * (contact_solver.c), 2D:
 *
 * - each point has fixed anchors r_A, r_B from the centres of mass (where the bodies were at the start
 *   of the step); its separation is tracked as s = s0 + (d_B + dtheta_B x r_B - d_A - dtheta_A x r_A) . n,
 *   with d and dtheta the bodies' displacement and rotation so far in the step (rotation linearised);
 * - normal rows: effective mass 1 / (1/m_A + 1/m_B + (r_A x n)^2 / I_A + (r_B x n)^2 / I_B); the two
 *   rows of a two-point manifold are solved together with their 2 x 2 effective mass (Box2D 2.x's block
 *   solver, a small complementarity problem; soft rows with the soft update written for both rows), so
 *   a face hit, a warm start undone or a heavy load does not spin or tip the body the way one point
 *   after the other does; rows nearly dependent point by point;
 *   speculative (s > 0: bias s / h_s) or soft (s < 0: Box2D's soft constraint, the stiffer softness
 *   against infinite mass, push-out speed capped), accumulated impulse >= 0, warm-started from the
 *   previous step's point with the same feature id;
 * - friction rows along t = (-n_y, n_x): |lambda_t| <= mu lambda_n per point (mu_s while sticking);
 * - a row that carries an impulse marks its bodies as pushed (the `pushed` slot of the packed body,
 *   as ball contacts and joints do), so they do not get the free-flight position correction;
 * - rolling resistance (circles and capsules): a torque row on w_B - w_A bounded by the coefficient
 *   times the rolling radius times the manifold's normal impulse (Box2D v3.1's rolling resistance);
 * - restitution after the substeps (Box2D v3 b2ApplyRestitution): a point that approached faster than
 *   the threshold and carried an impulse leaves with v_n >= -e v_n0;
 * - finally, which pairs touch (a point carried a normal impulse, or overlapped) gives the begin and
 *   end touch events, and the rows become the warm-start cache of the next step.
 */

/**
 * Stiffness of shape contacts, as a fraction of the solver substep rate: the world's `contactHertz`
 * is capped at this fraction (contacts against infinite mass get twice it). Box2D caps contact
 * stiffness at a quarter of the substep rate; with flat, two-point manifolds that is unstable in tall
 * pyramids here (sequential impulses ring and the pile shears), and an eighth is stable: 30 Hz at 4
 * substeps of 1/60 s (Box2D's default contact stiffness), 60 Hz at 8. Measured on the `pyramid`
 * scene, base 40: kinetic energy decays at an eighth and persists at 0.19 and 0.25.
 */
const SHAPE_HERTZ_FRACTION = 0.125;

/** Writes Box2D's soft-constraint coefficients (b2MakeSoft) for `hertz` and damping ratio `zeta` over step `h` into out[0..2]: bias rate, mass scale, impulse scale. */
function makeSoftInto(out: Float64Array, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    out[0] = 0;
    out[1] = 1;
    out[2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  out[0] = omega / a1;
  out[1] = a2 * a3;
  out[2] = a3;
}

/**
 * `list` if it holds `n` entries, else a copy in an array of at least n (twice its length). Growth runs
 * only in a world's first steps, before V8 records type feedback: inside the callers' loops it would
 * be compiled as a deoptimisation that throws the whole loop back to the interpreter in a later world.
 */
function withRoom(list: Int32Array, n: number): Int32Array {
  if (list.length >= n) return list;
  const grown = new Int32Array(Math.max(n, 2 * list.length));
  grown.set(list);
  return grown;
}

/** `a` if it holds `n` numbers, else a new zeroed array of at least n (twice a's length); see withRoom. */
function atLeast(a: Float64Array, n: number): Float64Array {
  return a.length >= n ? a : new Float64Array(Math.max(n, 2 * a.length));
}

/**
 * Gives every moving body of a shape manifold a solver index (continuing the list the ball contacts
 * started, same stamp), writes the rows' indices, and returns the new solver body count.
 * @category Collision
 */
export function gatherManifoldBodies(world: PhysicsWorld, count: number): number {
  const cs = world.collision;
  const buf = cs.shapes.manifolds;
  const n = buf.count;
  if (n === 0) return count;
  const mark = cs.solverMark,
    index = cs.solverIndex,
    stamp = cs.solverStamp,
    type = cs.bodyType;
  // Room for both bodies of every row, made before the loop (see withRoom).
  const list = withRoom(cs.solverBodies, count + 2 * n);
  const A = buf.bodyA,
    B = buf.bodyB,
    IA = buf.ia,
    IB = buf.ib;
  for (let i = 0; i < n; i++) {
    for (let side = 0; side < 2; side++) {
      const e = side === 0 ? A[i]! : B[i]!;
      const t = type[e]!;
      let k = 0;
      if (e !== 0 && (t === BodyType.Dynamic || t === BodyType.Kinematic)) {
        if (mark[e] !== stamp) {
          mark[e] = stamp;
          index[e] = count;
          list[count++] = e;
        }
        k = index[e]!;
      }
      if (side === 0) IA[i] = k;
      else IB[i] = k;
    }
  }
  cs.solverBodies = list;
  return count;
}

/**
 * Material, effective masses, start-of-step velocities and warm start of every manifold.
 * @category Collision
 */
export function prepareManifolds(world: PhysicsWorld): void {
  const cs = world.collision,
    st = cs.shapes,
    buf = st.manifolds;
  const n = buf.count;
  const count = cs.solverBodyCount;
  st.angleBase = atLeast(st.angleBase, count);
  const ex = cs.bodyExtra,
    base = st.angleBase;
  for (let k = 1; k < count; k++) base[k] = ex[k * 6 + 5]!;
  base[0] = 0;
  if (n === 0) return;
  const set = cs.settings;
  const hs = world.h / set.solverSubsteps;
  const hertz = Math.min(set.contactHertz, SHAPE_HERTZ_FRACTION / hs);
  makeSoftInto(st.softness, hertz, set.contactDampingRatio, hs);
  makeSoftInto(st.rigidSoftness, 2 * hertz, set.contactDampingRatio, hs);
  const c = world.components,
    sb = cs.bodyState;
  // Where the solver starts each body (its displacement 0) relative to where the narrowphase measured
  // it (PreviousPosition): separations are corrected by the difference, so the rows agree with
  // whatever base the solver chooses.
  const list = cs.solverBodies,
    ox = c.PreviousPosition.x,
    oy = c.PreviousPosition.y;
  const eM = c.Material.restitution,
    fM = c.Material.friction,
    sM = c.Material.staticFriction;
  const S = c.Shape;
  const box = cs.boundary;
  const stamp = world.spawnStamp;
  const stick = cs.settings.stickSpeed;
  const prev = st.previous;
  for (let i = 0; i < n; i++) {
    const ea = buf.shapeA[i]!,
      eb = buf.shapeB[i]!;
    const oa = buf.ia[i]! * 8,
      ob = buf.ib[i]! * 8;
    const mA = sb[oa + 5]!,
      iA = sb[oa + 6]!,
      mB = sb[ob + 5]!,
      iB = sb[ob + 6]!;
    const nx = buf.nx[i]!,
      ny = buf.ny[i]!;
    // Materials: Box2D's mixing (the bouncier surface wins, friction is the geometric mean).
    let ra: number, fa: number, sa: number;
    if (ea < 0) {
      ra = box.restitution;
      fa = box.friction;
      sa = box.staticFriction;
    } else {
      ra = eM[ea]!;
      fa = fM[ea]!;
      sa = sM[ea]!;
    }
    const mu = Math.sqrt(fa * fM[eb]!),
      mus = Math.sqrt(sa * sM[eb]!);
    buf.friction[i] = mu;
    buf.restitution[i] = Math.max(ra, eM[eb]!);
    // Rolling resistance of round shapes: coefficient times the rolling radius.
    let roll = 0;
    if (ea > 0 && S.body.length > ea && S.body[ea] === buf.bodyA[i] && S.count[ea]! <= 2 && S.count[ea]! > 0)
      roll = S.rollingResistance[ea]! * S.radius[ea]!;
    if (S.body.length > eb && S.body[eb] === buf.bodyB[i] && S.count[eb]! <= 2 && S.count[eb]! > 0)
      roll = Math.max(roll, S.rollingResistance[eb]! * S.radius[eb]!);
    buf.rolling[i] = roll;
    buf.rollingMass[i] = iA + iB > 0 ? 1 / (iA + iB) : 0;
    buf.rollingImpulse[i] = 0;
    buf.stampA[i] = ea > 0 ? stamp[ea]! : 0;
    buf.stampB[i] = stamp[eb]!;
    let j = findPrevious(st, ea, eb);
    if (j >= 0 && (prev.stampA[j] !== buf.stampA[i] || prev.stampB[j] !== buf.stampB[i])) j = -1;
    if (j >= 0) buf.rollingImpulse[i] = prev.rollingImpulse[j]!;
    const vax = sb[oa]!,
      vay = sb[oa + 1]!,
      wa = sb[oa + 2]!,
      vbx = sb[ob]!,
      vby = sb[ob + 1]!,
      wb = sb[ob + 2]!;
    const ka = buf.ia[i]!,
      kb = buf.ib[i]!;
    const ea6 = ka * 6,
      eb6 = kb * 6;
    const offAx = ka === 0 ? 0 : ex[ea6]! - ox[list[ka]!]!,
      offAy = ka === 0 ? 0 : ex[ea6 + 1]! - oy[list[ka]!]!;
    const offBx = kb === 0 ? 0 : ex[eb6]! - ox[list[kb]!]!,
      offBy = kb === 0 ? 0 : ex[eb6 + 1]! - oy[list[kb]!]!;
    let vtMax = 0;
    for (let p = 0, m = buf.pointCount[i]!; p < m; p++) {
      const q = 2 * i + p;
      const rax = buf.rAx[q]!,
        ray = buf.rAy[q]!,
        rbx = buf.rBx[q]!,
        rby = buf.rBy[q]!;
      buf.separation[q] = buf.separation[q]! + (offBx - offAx) * nx + (offBy - offAy) * ny;
      const rnA = rax * ny - ray * nx,
        rnB = rbx * ny - rby * nx;
      const kn = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      buf.normalMass[q] = kn > 0 ? 1 / kn : 0;
      const rtA = rax * nx + ray * ny,
        rtB = rbx * nx + rby * ny; // r x t with t = (-n_y, n_x)
      const kt = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
      buf.tangentMass[q] = kt > 0 ? 1 / kt : 0;
      const dvx = vbx - wb * rby - vax + wa * ray,
        dvy = vby + wb * rbx - vay - wa * rax;
      buf.relativeVelocity[q] = dvx * nx + dvy * ny;
      const vt = Math.abs(-dvx * ny + dvy * nx);
      if (vt > vtMax) vtMax = vt;
      buf.maxNormalImpulse[q] = 0;
      buf.totalNormalImpulse[q] = 0;
      let ln = 0,
        lt = 0;
      if (j >= 0) {
        const id = buf.id[q]!;
        for (let r = 0, pm = prev.pointCount[j]!; r < pm; r++) {
          if (prev.id[2 * j + r] === id) {
            ln = prev.normalImpulse[2 * j + r]!;
            lt = prev.tangentImpulse[2 * j + r]!;
            break;
          }
        }
      }
      buf.normalImpulse[q] = ln;
      buf.tangentImpulse[q] = lt;
    }
    buf.frictionBound[i] = vtMax < stick ? Math.max(mus, mu) : mu;
    // Block solve of two-point manifolds (Catto's block solver of Box2D 2.x): K = J M^-1 J^T over the two normal rows.
    buf.blockValid[i] = 0;
    if (buf.pointCount[i] === 2) {
      const q = 2 * i;
      const rn1A = buf.rAx[q]! * ny - buf.rAy[q]! * nx,
        rn1B = buf.rBx[q]! * ny - buf.rBy[q]! * nx;
      const rn2A = buf.rAx[q + 1]! * ny - buf.rAy[q + 1]! * nx,
        rn2B = buf.rBx[q + 1]! * ny - buf.rBy[q + 1]! * nx;
      const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
      const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
      const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
      const det = k11 * k22 - k12 * k12;
      // Box2D's condition-number guard: the rows must not be nearly parallel.
      if (k11 * k11 < 1000 * det && det > 0) {
        const inv = 1 / det;
        buf.block11[i] = k22 * inv;
        buf.block12[i] = -k12 * inv;
        buf.block22[i] = k11 * inv;
        buf.blockValid[i] = 1;
      }
    }
  }
}

/**
 * Applies every manifold point's accumulated impulses (once per substep).
 * @category Collision
 */
export function warmStartManifolds(cs: CollisionState): void {
  const buf = cs.shapes.manifolds,
    sb = cs.bodyState;
  for (let i = 0, n = buf.count; i < n; i++) {
    const a = buf.ia[i]! * 8,
      b = buf.ib[i]! * 8;
    const mA = sb[a + 5]!,
      iA = sb[a + 6]!,
      mB = sb[b + 5]!,
      iB = sb[b + 6]!;
    const nx = buf.nx[i]!,
      ny = buf.ny[i]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      wa = sb[a + 2]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!,
      wb = sb[b + 2]!;
    for (let p = 0, m = buf.pointCount[i]!; p < m; p++) {
      const q = 2 * i + p;
      const ln = buf.normalImpulse[q]!,
        lt = buf.tangentImpulse[q]!;
      const Px = ln * nx - lt * ny,
        Py = ln * ny + lt * nx;
      wa -= iA * (buf.rAx[q]! * Py - buf.rAy[q]! * Px);
      vax -= mA * Px;
      vay -= mA * Py;
      wb += iB * (buf.rBx[q]! * Py - buf.rBy[q]! * Px);
      vbx += mB * Px;
      vby += mB * Py;
    }
    const lr = buf.rollingImpulse[i]!;
    wa -= iA * lr;
    wb += iB * lr;
    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = wa;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = wb;
    if (pushes(buf, i)) {
      sb[a + 7] = 1;
      sb[b + 7] = 1;
    }
  }
}

/**
 * Whether row i carries an impulse: then its bodies were not in free flight this step, and the contact
 * solver's `pushed` slot (index 7 of a packed body) keeps finishBodies from giving them the free-flight
 * position correction (-g h h_s / 2), which on a resting box is a drop of 0.34 mm a step at 4 substeps
 * of 1/60 s that the contact then pushes back: on a slope, a creep of mm a second.
 */
function pushes(buf: CollisionState['shapes']['manifolds'], i: number): boolean {
  for (let p = 0, m = buf.pointCount[i]!; p < m; p++) {
    const q = 2 * i + p;
    if (buf.normalImpulse[q] !== 0 || buf.tangentImpulse[q] !== 0) return true;
  }
  return buf.rollingImpulse[i] !== 0;
}

/**
 * One pass over the manifolds: normal rows (soft bias if `useBias`), friction, rolling resistance, with
 * the softness `prepareManifolds` chose.
 * @category Collision
 */
export function solveManifolds(cs: CollisionState, hs: number, useBias: boolean): void {
  const buf = cs.shapes.manifolds,
    sb = cs.bodyState,
    ex = cs.bodyExtra,
    base = cs.shapes.angleBase;
  const sd = cs.shapes.softness,
    sr = cs.shapes.rigidSoftness;
  const invH = 1 / hs,
    push = cs.settings.contactPushSpeed;
  const NX = buf.nx,
    NY = buf.ny,
    RAX = buf.rAx,
    RAY = buf.rAy,
    RBX = buf.rBx,
    RBY = buf.rBy,
    S0 = buf.separation;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    LN = buf.normalImpulse,
    LT = buf.tangentImpulse,
    MAXN = buf.maxNormalImpulse;
  for (let i = 0, n = buf.count; i < n; i++) {
    const ia = buf.ia[i]!,
      ib = buf.ib[i]!;
    const a = ia * 8,
      b = ib * 8;
    const mA = sb[a + 5]!,
      iA = sb[a + 6]!,
      mB = sb[b + 5]!,
      iB = sb[b + 6]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      wa = sb[a + 2]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!,
      wb = sb[b + 2]!;
    const dax = sb[a + 3]!,
      day = sb[a + 4]!,
      dbx = sb[b + 3]!,
      dby = sb[b + 4]!;
    const ta = ia === 0 ? 0 : ex[ia * 6 + 5]! - base[ia]!,
      tb = ib === 0 ? 0 : ex[ib * 6 + 5]! - base[ib]!;
    const nx = NX[i]!,
      ny = NY[i]!;
    const rigidPartner = mA === 0 || mB === 0;
    const biasRate = rigidPartner ? sr[0]! : sd[0]!,
      softMass = rigidPartner ? sr[1]! : sd[1]!,
      softImpulse = rigidPartner ? sr[2]! : sd[2]!;
    const m = buf.pointCount[i]!;
    let total = 0;
    let solved = false;
    if (buf.blockValid[i] === 1) {
      // Both points at once, as the linear complementarity problem K x + c = w, x >= 0, w >= 0,
      // x . w = 0 (Box2D 2.x's block solver, its four cases tried in turn), with x the new accumulated
      // impulses and c from each row's own regime: c_i = s_m (v_n,i + bias_i) - (1 - s_i) (K x_old)_i,
      // which is the soft row's update written for both rows (s_m, s_i its mass and impulse scales).
      const q = 2 * i;
      const r1ax = RAX[q]!,
        r1ay = RAY[q]!,
        r1bx = RBX[q]!,
        r1by = RBY[q]!;
      const r2ax = RAX[q + 1]!,
        r2ay = RAY[q + 1]!,
        r2bx = RBX[q + 1]!,
        r2by = RBY[q + 1]!;
      const s1 = S0[q]! + (dbx - tb * r1by - dax + ta * r1ay) * nx + (dby + tb * r1bx - day - ta * r1ax) * ny;
      const s2 = S0[q + 1]! + (dbx - tb * r2by - dax + ta * r2ay) * nx + (dby + tb * r2bx - day - ta * r2ax) * ny;
      let b1 = 0,
        m1 = 1,
        i1 = 0,
        b2 = 0,
        m2 = 1,
        i2 = 0;
      if (s1 > 0) b1 = s1 * invH;
      else if (useBias) {
        b1 = biasRate * s1;
        if (b1 < -push) b1 = -push;
        m1 = softMass;
        i1 = softImpulse;
      }
      if (s2 > 0) b2 = s2 * invH;
      else if (useBias) {
        b2 = biasRate * s2;
        if (b2 < -push) b2 = -push;
        m2 = softMass;
        i2 = softImpulse;
      }
      // Soft rows (overlap with bias) that both push are solved as a block too. One point after the
      // other, a column of light boxes under a heavy one (1 kg boxes, 100 kg on top) tips its boxes a
      // little at every pass, the tilt grows and the column buckles; the block keeps the two points'
      // impulses symmetric, and the column stands.
      const vn1 = (vbx - wb * r1by - vax + wa * r1ay) * nx + (vby + wb * r1bx - vay - wa * r1ax) * ny;
      const vn2 = (vbx - wb * r2by - vax + wa * r2ay) * nx + (vby + wb * r2bx - vay - wa * r2ax) * ny;
      const o1 = LN[q]!,
        o2 = LN[q + 1]!;
      const k11 = buf.block22[i]!,
        k22 = buf.block11[i]!,
        k12 = -buf.block12[i]!; // K from its inverse (scaled by det)
      const det = 1 / (buf.block11[i]! * buf.block22[i]! - buf.block12[i]! * buf.block12[i]!);
      const K11 = k11 * det,
        K22 = k22 * det,
        K12 = k12 * det;
      const c1 = m1 * (vn1 + b1) - (1 - i1) * (K11 * o1 + K12 * o2);
      const c2 = m2 * (vn2 + b2) - (1 - i2) * (K12 * o1 + K22 * o2);
      let n1 = -(buf.block11[i]! * c1 + buf.block12[i]! * c2),
        n2 = -(buf.block12[i]! * c1 + buf.block22[i]! * c2);
      const both = n1 >= 0 && n2 >= 0;
      let ok = both;
      // A point that lets go (one or both impulses 0: an impact undone, a box lifting off an edge).
      if (!both) {
        n1 = -c1 / K11;
        n2 = 0;
        ok = n1 >= 0 && K12 * n1 + c2 >= 0;
      }
      if (!both && !ok) {
        n1 = 0;
        n2 = -c2 / K22;
        ok = n2 >= 0 && K12 * n2 + c1 >= 0;
      }
      if (!both && !ok) {
        n1 = 0;
        n2 = 0;
        ok = c1 >= 0 && c2 >= 0;
      }
      if (ok) {
        const d1 = n1 - o1,
          d2 = n2 - o2;
        LN[q] = n1;
        LN[q + 1] = n2;
        if (d1 > MAXN[q]!) MAXN[q] = d1;
        if (d2 > MAXN[q + 1]!) MAXN[q + 1] = d2;
        total = n1 + n2;
        const P1x = d1 * nx,
          P1y = d1 * ny,
          P2x = d2 * nx,
          P2y = d2 * ny;
        vax -= mA * (P1x + P2x);
        vay -= mA * (P1y + P2y);
        wa -= iA * (r1ax * P1y - r1ay * P1x + r2ax * P2y - r2ay * P2x);
        vbx += mB * (P1x + P2x);
        vby += mB * (P1y + P2y);
        wb += iB * (r1bx * P1y - r1by * P1x + r2bx * P2y - r2by * P2x);
        solved = true;
      }
    }
    for (let p = 0; p < m && !solved; p++) {
      const q = 2 * i + p;
      const rax = RAX[q]!,
        ray = RAY[q]!,
        rbx = RBX[q]!,
        rby = RBY[q]!;
      const s = S0[q]! + (dbx - tb * rby - dax + ta * ray) * nx + (dby + tb * rbx - day - ta * rax) * ny;
      let bias = 0,
        massScale = 1,
        impulseScale = 0;
      if (s > 0) bias = s * invH;
      else if (useBias) {
        bias = biasRate * s;
        massScale = softMass;
        impulseScale = softImpulse;
        if (bias < -push) bias = -push;
      }
      const vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny;
      const old = LN[q]!;
      let next = old - NM[q]! * massScale * (vn + bias) - impulseScale * old;
      if (next < 0) next = 0;
      const dl = next - old;
      LN[q] = next;
      total += next;
      if (dl > MAXN[q]!) MAXN[q] = dl;
      const Px = dl * nx,
        Py = dl * ny;
      vax -= mA * Px;
      vay -= mA * Py;
      wa -= iA * (rax * Py - ray * Px);
      vbx += mB * Px;
      vby += mB * Py;
      wb += iB * (rbx * Py - rby * Px);
    }
    const bound = buf.frictionBound[i]!;
    for (let p = 0; p < m; p++) {
      const q = 2 * i + p;
      const rax = RAX[q]!,
        ray = RAY[q]!,
        rbx = RBX[q]!,
        rby = RBY[q]!;
      const dvx = vbx - wb * rby - vax + wa * ray,
        dvy = vby + wb * rbx - vay - wa * rax;
      const vt = -dvx * ny + dvy * nx;
      const old = LT[q]!,
        maxF = bound * LN[q]!;
      let next = old - TM[q]! * vt;
      next = next < -maxF ? -maxF : next > maxF ? maxF : next;
      const dl = next - old;
      LT[q] = next;
      const Px = -dl * ny,
        Py = dl * nx;
      vax -= mA * Px;
      vay -= mA * Py;
      wa -= iA * (rax * Py - ray * Px);
      vbx += mB * Px;
      vby += mB * Py;
      wb += iB * (rbx * Py - rby * Px);
    }
    const roll = buf.rolling[i]!;
    if (roll > 0) {
      const old = buf.rollingImpulse[i]!,
        maxR = roll * total;
      let next = old - buf.rollingMass[i]! * (wb - wa);
      next = next < -maxR ? -maxR : next > maxR ? maxR : next;
      const dl = next - old;
      buf.rollingImpulse[i] = next;
      wa -= iA * dl;
      wb += iB * dl;
    }
    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = wa;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = wb;
    if (total > 0 || pushes(buf, i)) {
      sb[a + 7] = 1;
      sb[b + 7] = 1;
    }
  }
}

/**
 * Adds each point's substep impulse to its step total (call once per substep, after relaxing).
 * @category Collision
 */
export function accumulateManifoldImpulses(cs: CollisionState): void {
  const buf = cs.shapes.manifolds;
  const LN = buf.normalImpulse,
    TOT = buf.totalNormalImpulse;
  for (let q = 0, n = 2 * buf.count; q < n; q++) TOT[q] = TOT[q]! + LN[q]!;
}

/**
 * Restitution (Box2D v3 b2ApplyRestitution): every point that approached faster than the threshold at
 * the start of the step and carried an impulse gets the normal impulse that makes it leave with
 * v_n = -e v_n0 (the accumulated normal impulse stays >= 0). The two points of a manifold with a valid
 * block (see `prepareManifolds`) that both qualify are solved together, as the 2 x 2 complementarity
 * problem of Box2D 2.x's block solver, so a face-on hit rebounds without spin.
 * @category Collision
 */
export function applyManifoldRestitution(world: PhysicsWorld): void {
  const cs = world.collision,
    buf = cs.shapes.manifolds,
    sb = cs.bodyState;
  const threshold = cs.settings.restitutionThreshold;
  for (let i = 0, n = buf.count; i < n; i++) {
    const e = buf.restitution[i]!;
    if (e === 0) continue;
    const a = buf.ia[i]! * 8,
      b = buf.ib[i]! * 8;
    const mA = sb[a + 5]!,
      iA = sb[a + 6]!,
      mB = sb[b + 5]!,
      iB = sb[b + 6]!;
    const nx = buf.nx[i]!,
      ny = buf.ny[i]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      wa = sb[a + 2]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!,
      wb = sb[b + 2]!;
    const m = buf.pointCount[i]!;
    if (m === 2 && buf.blockValid[i] === 1) {
      // Both points at once (the linear complementarity problem of the block solve, with the target
      // v_n,i = -e v_n0,i), so symmetric points get symmetric impulses: point after point, the first
      // takes the whole rebound, turns the body and leaves the second less to do.
      const q = 2 * i;
      const v1 = buf.relativeVelocity[q]!,
        v2 = buf.relativeVelocity[q + 1]!;
      const on1 = v1 <= -threshold && buf.maxNormalImpulse[q]! > 0,
        on2 = v2 <= -threshold && buf.maxNormalImpulse[q + 1]! > 0;
      if (on1 && on2) {
        const r1ax = buf.rAx[q]!,
          r1ay = buf.rAy[q]!,
          r1bx = buf.rBx[q]!,
          r1by = buf.rBy[q]!,
          r2ax = buf.rAx[q + 1]!,
          r2ay = buf.rAy[q + 1]!,
          r2bx = buf.rBx[q + 1]!,
          r2by = buf.rBy[q + 1]!;
        const vn1 = (vbx - wb * r1by - vax + wa * r1ay) * nx + (vby + wb * r1bx - vay - wa * r1ax) * ny;
        const vn2 = (vbx - wb * r2by - vax + wa * r2ay) * nx + (vby + wb * r2bx - vay - wa * r2ax) * ny;
        const o1 = buf.normalImpulse[q]!,
          o2 = buf.normalImpulse[q + 1]!;
        const B11 = buf.block11[i]!,
          B12 = buf.block12[i]!,
          B22 = buf.block22[i]!;
        // K from its inverse B (K = B^-1).
        const det = 1 / (B11 * B22 - B12 * B12);
        const K11 = B22 * det,
          K22 = B11 * det,
          K12 = -B12 * det;
        // K x + c = w >= 0, x >= 0, x . w = 0, with w_i = v_n,i + e v_n0,i after the impulses x.
        const c1 = vn1 + e * v1 - (K11 * o1 + K12 * o2),
          c2 = vn2 + e * v2 - (K12 * o1 + K22 * o2);
        let n1 = -(B11 * c1 + B12 * c2),
          n2 = -(B12 * c1 + B22 * c2);
        let ok = n1 >= 0 && n2 >= 0;
        if (!ok) {
          n1 = -c1 / K11;
          n2 = 0;
          ok = n1 >= 0 && K12 * n1 + c2 >= 0;
        }
        if (!ok) {
          n1 = 0;
          n2 = -c2 / K22;
          ok = n2 >= 0 && K12 * n2 + c1 >= 0;
        }
        if (!ok) {
          n1 = 0;
          n2 = 0;
          ok = c1 >= 0 && c2 >= 0;
        }
        if (ok) {
          const d1 = n1 - o1,
            d2 = n2 - o2;
          buf.normalImpulse[q] = n1;
          buf.normalImpulse[q + 1] = n2;
          buf.totalNormalImpulse[q] = buf.totalNormalImpulse[q]! + d1;
          buf.totalNormalImpulse[q + 1] = buf.totalNormalImpulse[q + 1]! + d2;
          const P1x = d1 * nx,
            P1y = d1 * ny,
            P2x = d2 * nx,
            P2y = d2 * ny;
          vax -= mA * (P1x + P2x);
          vay -= mA * (P1y + P2y);
          wa -= iA * (r1ax * P1y - r1ay * P1x + r2ax * P2y - r2ay * P2x);
          vbx += mB * (P1x + P2x);
          vby += mB * (P1y + P2y);
          wb += iB * (r1bx * P1y - r1by * P1x + r2bx * P2y - r2by * P2x);
          sb[a] = vax;
          sb[a + 1] = vay;
          sb[a + 2] = wa;
          sb[b] = vbx;
          sb[b + 1] = vby;
          sb[b + 2] = wb;
          continue;
        }
      }
    }
    for (let p = 0; p < m; p++) {
      const q = 2 * i + p;
      const v0 = buf.relativeVelocity[q]!;
      if (v0 > -threshold || buf.maxNormalImpulse[q]! === 0) continue;
      const rax = buf.rAx[q]!,
        ray = buf.rAy[q]!,
        rbx = buf.rBx[q]!,
        rby = buf.rBy[q]!;
      const vn = (vbx - wb * rby - vax + wa * ray) * nx + (vby + wb * rbx - vay - wa * rax) * ny;
      const old = buf.normalImpulse[q]!;
      let next = old - buf.normalMass[q]! * (vn + e * v0);
      if (next < 0) next = 0;
      const dl = next - old;
      buf.normalImpulse[q] = next;
      buf.totalNormalImpulse[q] = buf.totalNormalImpulse[q]! + dl;
      const Px = dl * nx,
        Py = dl * ny;
      vax -= mA * Px;
      vay -= mA * Py;
      wa -= iA * (rax * Py - ray * Px);
      vbx += mB * Px;
      vby += mB * Py;
      wb += iB * (rbx * Py - rby * Px);
    }
    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = wa;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = wb;
  }
}

/**
 * After the solve: marks the manifolds that touch, writes begin and end touch events against the
 * previous step's, and keeps this step's rows as the next step's warm-start cache.
 * @category Collision
 */
export function finishManifolds(world: PhysicsWorld): void {
  const st = world.collision.shapes;
  if (!st.active) return;
  const buf = st.manifolds,
    prev = st.previous,
    ev = st.events;
  if (st.eventStep !== world.steps) {
    st.eventStep = world.steps;
    ev.begin.count = 0;
    ev.end.count = 0;
    ev.sensorBegin.count = 0;
    ev.sensorEnd.count = 0;
  }
  for (let i = 0, n = buf.count; i < n; i++) {
    let touching = 0;
    for (let p = 0, m = buf.pointCount[i]!; p < m; p++) {
      const q = 2 * i + p;
      if (buf.totalNormalImpulse[q]! > 0 || buf.separation[q]! < 0) touching = 1;
    }
    buf.touching[i] = touching;
    if (touching === 0) continue;
    const j = findPrevious(st, buf.shapeA[i]!, buf.shapeB[i]!);
    if (j >= 0 && prev.touching[j] === 1 && prev.stampB[j] === buf.stampB[i] && prev.stampA[j] === buf.stampA[i]) continue;
    const k = pushEvent(world, ev.begin, buf.shapeA[i]!, buf.shapeB[i]!, buf.bodyA[i]!, buf.bodyB[i]!);
    ev.begin.px[k] = buf.px[2 * i]!;
    ev.begin.py[k] = buf.py[2 * i]!;
    ev.begin.nx[k] = buf.nx[i]!;
    ev.begin.ny[k] = buf.ny[i]!;
    let approach = 0;
    for (let p = 0, m = buf.pointCount[i]!; p < m; p++) approach = Math.max(approach, -buf.relativeVelocity[2 * i + p]!);
    ev.begin.approachSpeed[k] = approach;
  }
  rotateManifolds(st);
  // End events: pairs that touched last step and do not now (`previous` is now this step's rows).
  const now = st.previous,
    old = st.manifolds; // old: the buffer just emptied, still holding last step's rows
  for (let i = 0, n = st.lastCount; i < n; i++) {
    if (old.touching[i] !== 1) continue;
    const j = findPrevious(st, old.shapeA[i]!, old.shapeB[i]!);
    if (j >= 0 && now.touching[j] === 1 && now.stampB[j] === old.stampB[i] && now.stampA[j] === old.stampA[i]) continue;
    pushEvent(world, ev.end, old.shapeA[i]!, old.shapeB[i]!, old.bodyA[i]!, old.bodyB[i]!);
  }
}
