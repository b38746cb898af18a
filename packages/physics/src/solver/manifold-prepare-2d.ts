import { findDormant, pruneDormant } from '../collision/dormant-manifolds-2d.js';
import type { ContactEventList } from '../collision/event-lists.js';
import { keepWhileAsleep, pushEvent, resumeAfterSleep } from '../collision/events.js';
import { MAX_MANIFOLDS } from '../collision/manifold-limits-2d.js';
import { findPrevious, type ManifoldBuffer, rotateManifolds, type ShapeCollisionState } from '../collision/manifolds-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import * as BS from './body-state-layout.js';
import { effectiveMass, prepareContactSoftness } from './contact-point.js';
import { CP_NORMAL_MASS, CP_SEPARATION } from './contact-point-layout.js';
import * as M2 from './manifold-layout-2d.js';
import { atLeast } from './manifold-rows-2d.js';
import { joinSolverBodies } from './solver-bodies.js';

/**
 * The shape contacts' rows before and after the substeps (solver/manifold-rows-2d.ts describes the rows
 * and runs the substeps' stages): each manifold's bodies join the solver's packed body list, its
 * material, effective masses, start-of-step velocities and warm-start impulses are worked out and
 * packed into the solver rows, and after the solve its touch events are written and it becomes the
 * next step's warm-start cache.
 */

/**
 * The previous step's row of shape pair (a, b), or -1: row `guess` if it holds that pair, else the
 * one findPrevious finds in the hash. A pair is in a step's rows once, so both give the same row; the
 * pairs come in nearly the same order every step, and most often the previous row of the next pair
 * lies as far from its own row as the last one's did: found without a hash probe (a cache miss each
 * in a large pile), and read in sequence.
 */
function previousRow(st: ShapeCollisionState, guess: number, a: number, b: number): number {
  const prev = st.previous;
  const inRange = guess >= 0 && guess < prev.count;
  // Row `guess` is read and compared (row 0 when out of range) before the range test: a world's first
  // step has no rows before it, and code compiled then would lack these loads and comparisons (V8
  // records no type feedback for code that never ran) and be thrown away in the second step.
  const k = inRange ? guess : 0;
  const sameA = prev.shapeA[k] === a,
    sameB = prev.shapeB[k] === b;
  if (inRange && sameA && sameB) return guess;
  return findPrevious(st, a, b);
}

/**
 * The point of row j of `src` with feature id `id`, as its index 2 j + k in the point arrays, or -1
 * (j < 0: -1, row 0 read instead). The point slots are read and compared whatever the row's point
 * count (at most 2), and row 0 for no row: the warm start of a world's first step finds no row, and
 * code compiled then would lack these loads and comparisons (V8 records no type feedback for code
 * that never ran) and be thrown away in the second step.
 */
function samePoint(src: ManifoldBuffer, j: number, id: number): number {
  const q = 2 * Math.max(j, 0),
    q1 = q + 1;
  const pm = src.pointCount[q >> 1]!;
  const at0 = pm > 0,
    at1 = pm > 1,
    same0 = src.id[q] === id,
    same1 = src.id[q1] === id;
  return j < 0 ? -1 : at0 && same0 ? q : at1 && same1 ? q1 : -1;
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
  return joinSolverBodies(cs, buf.bodyA, buf.bodyB, buf.ia, buf.ib, n, count);
}

/**
 * Material, effective masses, start-of-step velocities and warm start of every manifold, written into
 * its packed solver row (solver/manifold-layout-2d.ts); the manifold buffer keeps what the touch
 * events and the contact queries read (separations corrected to the solver's start, approach speeds,
 * spawn stamps).
 * @category Collision
 */
export function prepareManifolds(world: PhysicsWorld): void {
  const cs = world.collision,
    st = cs.shapes,
    buf = st.manifolds;
  const n = Math.min(buf.count, MAX_MANIFOLDS);
  const count = cs.solverBodyCount;
  st.angleBase = atLeast(st.angleBase, count);
  const ex = cs.bodyExtra,
    base = st.angleBase;
  for (let k = 1; k < count; k++) base[k] = ex[k * BS.BX_STRIDE + BS.BX_ROT_Z]!;
  base[0] = 0;
  if (n === 0) return;
  const set = cs.settings;
  const hs = world.h / set.solverSubsteps;
  prepareContactSoftness(st.softness, set, hs);
  const R = atLeast(st.solverRows, n * M2.MR_STRIDE);
  st.solverRows = R;
  prepareRows(world, R, n);
  pruneDormant(world);
}

/**
 * The rolling resistance of manifold i of `buf` between shapes ea (< 0: a boundary face) and eb: of
 * its round shapes (a circle or capsule: at most two vertices), the largest coefficient times rolling
 * radius (m); 0 when neither is round.
 */
function rollingOf(S: PhysicsWorld['components']['Shape'], buf: ManifoldBuffer, i: number, ea: number, eb: number): number {
  let roll = 0;
  if (ea > 0 && S.body.length > ea && S.body[ea] === buf.bodyA[i] && S.count[ea]! <= 2 && S.count[ea]! > 0)
    roll = S.rollingResistance[ea]! * S.radius[ea]!;
  if (S.body.length > eb && S.body[eb] === buf.bodyB[i] && S.count[eb]! <= 2 && S.count[eb]! > 0)
    roll = Math.max(roll, S.rollingResistance[eb]! * S.radius[eb]!);
  return roll;
}

/** prepareManifolds, per manifold: its bodies, normal, material, warm start, points and block (prepareBlock). */
function prepareRows(world: PhysicsWorld, R: Float64Array, n: number): void {
  const cs = world.collision,
    st = cs.shapes,
    buf = st.manifolds;
  const c = world.components,
    sb = cs.bodyState,
    ex = cs.bodyExtra;
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
  const prev = st.previous,
    dormant = st.dormant;
  const shapeA = buf.shapeA,
    shapeB = buf.shapeB,
    IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    points = buf.pointCount,
    stampA = buf.stampA,
    stampB = buf.stampB,
    RAX = buf.rAx,
    RAY = buf.rAy,
    RBX = buf.rBx,
    RBY = buf.rBy,
    SEP = buf.separation,
    VN = buf.relativeVelocity,
    ID = buf.id;
  // The last pair's previous row less its own row (see previousRow).
  let shift = 0;
  for (let i = 0; i < n; i++) {
    const r = i * M2.MR_STRIDE;
    const ea = shapeA[i]!,
      eb = shapeB[i]!;
    const ka = IA[i]!,
      kb = IB[i]!;
    const oa = ka * BS.BS2_STRIDE,
      ob = kb * BS.BS2_STRIDE;
    const mA = sb[oa + BS.BS2_INV_MASS]!,
      iA = sb[oa + BS.BS2_INV_INERTIA]!,
      mB = sb[ob + BS.BS2_INV_MASS]!,
      iB = sb[ob + BS.BS2_INV_INERTIA]!;
    const nx = NX[i]!,
      ny = NY[i]!;
    const m = points[i]!;
    R[r + M2.MR_BODY_A] = ka;
    R[r + M2.MR_BODY_B] = kb;
    R[r + M2.MR_NX] = nx;
    R[r + M2.MR_NY] = ny;
    R[r + M2.MR_POINT_COUNT] = m;
    // Materials: Box2D's mixing (the bouncier surface wins, friction is the geometric mean).
    const ra = ea < 0 ? box.restitution : eM[ea]!,
      fa = ea < 0 ? box.friction : fM[ea]!,
      sa = ea < 0 ? box.staticFriction : sM[ea]!;
    const mu = Math.sqrt(fa * fM[eb]!),
      mus = Math.sqrt(sa * sM[eb]!);
    R[r + M2.MR_RESTITUTION] = Math.max(ra, eM[eb]!);
    R[r + M2.MR_ROLLING] = rollingOf(S, buf, i, ea, eb);
    R[r + M2.MR_ROLLING_MASS] = effectiveMass(iA + iB);
    stampA[i] = ea > 0 ? stamp[ea]! : 0;
    stampB[i] = stamp[eb]!;
    let j = previousRow(st, i + shift, ea, eb);
    const step = j - i;
    if (j >= 0) shift = step;
    // The warm start: last step's row, or for a pair that just woke the row it fell asleep with.
    let src = prev;
    if (j < 0 && dormant.count > 0) {
      j = findDormant(st, ea, eb);
      src = dormant;
    }
    // Row j's stamps and rolling impulse are read and compared (row 0's when there is none) before
    // the test: see samePoint.
    const js = j >= 0 ? j : 0;
    const spawnedA = src.stampA[js] === stampA[i],
      spawnedB = src.stampB[js] === stampB[i],
      rolled = src.rollingImpulse[js]!;
    if (j >= 0 && !(spawnedA && spawnedB)) j = -1;
    R[r + M2.MR_ROLLING_IMPULSE] = j >= 0 ? rolled : 0;
    const vax = sb[oa + BS.BS2_VX]!,
      vay = sb[oa + BS.BS2_VY]!,
      wa = sb[oa + BS.BS2_W]!,
      vbx = sb[ob + BS.BS2_VX]!,
      vby = sb[ob + BS.BS2_VY]!,
      wb = sb[ob + BS.BS2_W]!;
    const ea6 = ka * BS.BX_STRIDE,
      eb6 = kb * BS.BX_STRIDE;
    const offAx = ka === 0 ? 0 : ex[ea6 + BS.BX_BASE_X]! - ox[list[ka]!]!,
      offAy = ka === 0 ? 0 : ex[ea6 + BS.BX_BASE_Y]! - oy[list[ka]!]!;
    const offBx = kb === 0 ? 0 : ex[eb6 + BS.BX_BASE_X]! - ox[list[kb]!]!,
      offBy = kb === 0 ? 0 : ex[eb6 + BS.BX_BASE_Y]! - oy[list[kb]!]!;
    let vtMax = 0;
    for (let p = 0; p < m; p++) {
      const q = 2 * i + p,
        o = r + M2.MR_POINT0 + p * M2.MP_STRIDE;
      const rax = RAX[q]!,
        ray = RAY[q]!,
        rbx = RBX[q]!,
        rby = RBY[q]!;
      const sep = SEP[q]! + (offBx - offAx) * nx + (offBy - offAy) * ny;
      SEP[q] = sep;
      const rnA = rax * ny - ray * nx,
        rnB = rbx * ny - rby * nx;
      const kn = mA + mB + iA * rnA * rnA + iB * rnB * rnB;
      const rtA = rax * nx + ray * ny,
        rtB = rbx * nx + rby * ny; // r x t with t = (-n_y, n_x)
      const kt = mA + mB + iA * rtA * rtA + iB * rtB * rtB;
      const dvx = vbx - wb * rby - vax + wa * ray,
        dvy = vby + wb * rbx - vay - wa * rax;
      const vn = dvx * nx + dvy * ny;
      VN[q] = vn;
      const vt = Math.abs(-dvx * ny + dvy * nx);
      // Math.max, not a comparison: a world's first step, its bodies at rest, has every vt 0, and a
      // comparison compiled then for small integers would be thrown away at the first fraction.
      vtMax = Math.max(vtMax, vt);
      // Warm start: the impulses of the warm-start row's point with the same feature id.
      const w = samePoint(src, j, ID[q]!);
      const wq = w >= 0 ? w : 0;
      const ln0 = src.normalImpulse[wq]!,
        lt0 = src.tangentImpulse[wq]!;
      const ln = w >= 0 ? ln0 : 0,
        lt = w >= 0 ? lt0 : 0;
      R[o + M2.MP_RNA] = rnA;
      R[o + M2.MP_RNB] = rnB;
      R[o + M2.MP_RTA] = rtA;
      R[o + M2.MP_RTB] = rtB;
      R[o + CP_SEPARATION] = sep;
      R[o + CP_NORMAL_MASS] = effectiveMass(kn);
      R[o + M2.MP_TANGENT_MASS] = effectiveMass(kt);
      R[o + M2.MP_NORMAL_IMPULSE] = ln;
      R[o + M2.MP_TANGENT_IMPULSE] = lt;
      R[o + M2.MP_MAX_NORMAL_IMPULSE] = 0;
      R[o + M2.MP_TOTAL_NORMAL_IMPULSE] = 0;
      R[o + M2.MP_RELATIVE_VELOCITY] = vn;
    }
    R[r + M2.MR_FRICTION_BOUND] = vtMax < stick ? Math.max(mus, mu) : mu;
    if (m === 2) prepareBlock(R, r, mA, iA, mB, iB);
    else R[r + M2.MR_BLOCK_VALID] = 0;
  }
}

/**
 * prepareManifolds, the block of the two-point manifold whose packed row starts at `r` (Catto's block
 * solver of Box2D 2.x), of inverse masses mA, mB (1/kg) and inverse inertias iA, iB (1/(kg m^2)):
 * K = J M^-1 J^T over the two normal rows, its inverse, and K again as the inverse of that inverse
 * (what the solve reads), if the rows are not nearly parallel; else the row's block is marked invalid.
 */
function prepareBlock(R: Float64Array, r: number, mA: number, iA: number, mB: number, iB: number): void {
  R[r + M2.MR_BLOCK_VALID] = 0;
  const o1 = r + M2.MR_POINT0,
    o2 = o1 + M2.MP_STRIDE;
  const rn1A = R[o1 + M2.MP_RNA]!,
    rn1B = R[o1 + M2.MP_RNB]!;
  const rn2A = R[o2 + M2.MP_RNA]!,
    rn2B = R[o2 + M2.MP_RNB]!;
  const k11 = mA + mB + iA * rn1A * rn1A + iB * rn1B * rn1B;
  const k22 = mA + mB + iA * rn2A * rn2A + iB * rn2B * rn2B;
  const k12 = mA + mB + iA * rn1A * rn2A + iB * rn1B * rn2B;
  const det = k11 * k22 - k12 * k12;
  // Box2D's condition-number guard: the rows must not be nearly parallel.
  if (k11 * k11 < 1000 * det && det > 0) {
    const inv = 1 / det;
    const b11 = k22 * inv,
      b12 = -k12 * inv,
      b22 = k11 * inv;
    const back = 1 / (b11 * b22 - b12 * b12);
    R[r + M2.MR_BLOCK_VALID] = 1;
    R[r + M2.MR_B11] = b11;
    R[r + M2.MR_B12] = b12;
    R[r + M2.MR_B22] = b22;
    R[r + M2.MR_K11] = b22 * back;
    R[r + M2.MR_K12] = -b12 * back;
    R[r + M2.MR_K22] = b11 * back;
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
  const ev = world.collision.events;
  beginTouches(world, st, ev.begin, st.manifolds, st.previous, st.manifolds.count);
  rotateManifolds(st);
  const old = st.manifolds,
    n = st.lastCount;
  if (endedRows.length < n) endedRows = new Int32Array(Math.max(n, 2 * endedRows.length));
  const ended = endedRows;
  const count = endTouches(st, st.previous, old, n, ended);
  for (let k = 0; k < count; k++) {
    const i = ended[k]!;
    if (keepWhileAsleep(world, old.shapeA[i]!, old.shapeB[i]!, old.bodyA[i]!, old.bodyB[i]!)) continue;
    pushEvent(world, ev.end, old.shapeA[i]!, old.shapeB[i]!, old.bodyA[i]!, old.bodyB[i]!);
  }
}

/** The rows of last step's manifolds whose touch ended this step, from endTouches; grown as needed. */
let endedRows = new Int32Array(64);

/**
 * The begin events of finishManifolds, before rotateManifolds: marks the `n` rows of `buf` (this
 * step's) that touch, and writes `begins` for those that did not touch in `prev` (last step's rows).
 * The loop's own function, its lists and buffers as arguments, and the calls after it in
 * finishManifolds: a world's first step compiles it while the loop runs, before V8 keeps type
 * feedback for the function, and code outside the loop would lack it.
 */
function beginTouches(
  world: PhysicsWorld,
  st: ShapeCollisionState,
  begins: ContactEventList,
  buf: ManifoldBuffer,
  prev: ManifoldBuffer,
  n: number,
): void {
  let shift = 0; // see previousRow
  for (let i = 0; i < n; i++) {
    let touching = 0;
    for (let p = 0, m = buf.pointCount[i]!; p < m; p++) {
      const q = 2 * i + p;
      if (buf.totalNormalImpulse[q]! > 0 || buf.separation[q]! < 0) touching = 1;
    }
    buf.touching[i] = touching;
    if (touching === 0) continue;
    const j = previousRow(st, i + shift, buf.shapeA[i]!, buf.shapeB[i]!);
    const step = j - i;
    if (j >= 0) shift = step;
    // Row j is read and compared (row 0 when there is none) before the test: see samePoint.
    const js = j >= 0 ? j : 0;
    const held = prev.touching[js] === 1,
      spawnedB = prev.stampB[js] === buf.stampB[i],
      spawnedA = prev.stampA[js] === buf.stampA[i];
    if (j >= 0 && held && spawnedB && spawnedA) continue;
    if (resumeAfterSleep(world, buf.shapeA[i]!, buf.shapeB[i]!)) continue;
    const k = pushEvent(world, begins, buf.shapeA[i]!, buf.shapeB[i]!, buf.bodyA[i]!, buf.bodyB[i]!);
    begins.px[k] = buf.px[2 * i]!;
    begins.py[k] = buf.py[2 * i]!;
    begins.nx[k] = buf.nx[i]!;
    begins.ny[k] = buf.ny[i]!;
    let approach = 0,
      impulse = 0;
    for (let p = 0, m = buf.pointCount[i]!; p < m; p++) {
      approach = Math.max(approach, -buf.relativeVelocity[2 * i + p]!);
      impulse += buf.totalNormalImpulse[2 * i + p]!;
    }
    begins.approachSpeed[k] = approach;
    begins.impulse[k] = impulse;
  }
}

/**
 * The ends of touch for finishManifolds, after rotateManifolds: writes to `ended` the rows of `old`
 * (last step's `n` rows, in the buffer just emptied) that touched and do not touch in `now` (this
 * step's rows), in order, and returns their count; finishManifolds then writes their end events (or
 * keeps them for sleeping bodies). A function of its own: a world's first step has no rows of a step
 * before, so this loop runs first in the second step, and inside finishManifolds (compiled during the
 * first step) its first run threw the compiled code away. The buffers come as arguments and nothing
 * is read before the loop: its first runs are compiled while its loop runs, before V8 keeps type
 * feedback for it, and loads before the loop would lack it. No call is made for an ended row: the
 * first ended touch comes steps after V8 compiled the loop, and a call there, never run before, had
 * no type feedback and threw the code away.
 */
function endTouches(st: ShapeCollisionState, now: ManifoldBuffer, old: ManifoldBuffer, n: number, ended: Int32Array): number {
  let shift = 0; // see previousRow
  let count = 0;
  for (let i = 0; i < n; i++) {
    if (old.touching[i] !== 1) continue;
    const j = previousRow(st, i + shift, old.shapeA[i]!, old.shapeB[i]!);
    const step = j - i;
    if (j >= 0) shift = step;
    const held = j >= 0 && now.touching[j] === 1 && now.stampB[j] === old.stampB[i] && now.stampA[j] === old.stampA[i];
    ended[count] = i;
    count += held ? 0 : 1;
  }
  return count;
}
