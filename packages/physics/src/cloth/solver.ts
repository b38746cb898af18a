import { removeEntity } from 'bitecs';
import type { Boundary } from '../collision/state.js';
import type { ClothState } from '../world/cloth-state.js';
import type { Components } from '../world/components.js';
import { currentHandle, isAlive, slotOf } from '../world/handles.js';
import { pushBreak } from '../world/joint-state-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import {
  BEFORE_AT,
  BUFFER_STRIDE,
  PAIR_A,
  PAIR_B,
  PAIR_STRIDE,
  PT_INV_MASS,
  PT_STRIDE,
  PT_X,
  PT_Y,
  SC_GX_H,
  SC_GX_HS,
  SC_GY_H,
  SC_GY_HS,
  SC_HS,
  SC_INV_HS,
  SC_INV_HS2,
  SOLVE_K,
  SOLVE_P,
  SOLVE_STRIDE,
  VELOCITY_AT,
} from './layout.js';

/**
 * The cloth solver (stage 6, `constraints`): every `ClothLink` is a distance constraint solved on
 * positions by XPBD with small steps (Macklin, Mueller and Chentanez, "XPBD", 2016; Macklin et al.,
 * "Small Steps in Physics Simulation", 2019), after the integrate stage has applied the points' forces
 * (drag against the world's wind and turbulence, and gravity):
 *
 * 1. (when the set of links changed) pack the links as pairs of compact point indices and their
 *    distinct points; each step the points are gathered into an interleaved buffer;
 * 2. from the start of the step, `substeps` times with h_s = h / substeps: v += g h_s, x += v h_s;
 *    one Gauss-Seidel pass over the links: for d = x_b - x_a, length L, rest r, C = L - r, inverse
 *    masses w_a, w_b, compliance alpha (alpha~ = alpha / h_s^2): dlambda = -C / (w_a + w_b + alpha~),
 *    x_b += w_b dlambda d / L, x_a -= w_a dlambda d / L; then v = (x - x_before) / h_s. The factor
 *    s = -C / L = r / L - 1 = 1 / sqrt(q) - 1, q = L^2 / r^2, is taken as its [1/1] Pade approximant
 *    about q = 1, s = 2 (1 - q) / (1 + 3 q) = 2 (r^2 - L^2) / (r^2 + 3 L^2) (Baker and Graves-Morris,
 *    "Pade Approximants", 1996), which needs no square root: it is off by (1 - u)^3 / (u (1 + 3 u^2)),
 *    u = L / r, a third-order error (6e-4 of s at 5% strain, so a compliant link keeps Hooke's law to
 *    that), is exact at the rest length and never overshoots (|s| is always a little too small), and
 *    costs less than the square root and division of the exact factor. (Jakobsen's
 *    (r^2 - L^2) / (r^2 + L^2), "Advanced Character Physics", 2001, costs the same but is only
 *    first-order right: 2.5% off at 5% strain.)
 *    Before the links, each soft pin (pinClothPoint with options) pulls its point toward its target: for
 *    C = |x - target|, dlambda = min(C / (w + alpha~), maxForce h_s^2), x moves w dlambda toward it;
 *    After the links, with the world's boundary box on (setBoundary), each point past a wall is put
 *    back on it and its move along the wall in the substep is cut by the box's friction (see
 *    `projectBoundary`);
 * 3. positions and velocities written back;
 * 4. links stretched past their `tearStretch` tear: removed, each reported in `world.joints.breaks`.
 *
 * Small steps converge far better than iterations at the same cost: a 64 x 64 cloth in wind stretched
 * 43% at its corner with 12 iterations of one step, under 5% with 12 substeps of one pass. The
 * integrator's forces other than gravity act as one impulse at the start of the step.
 * @category Cloth
 */
export function clothSystem(world: PhysicsWorld): void {
  const cl = world.cloth;
  if (cl.version === 0 || world.dimensions !== 2) return;
  if (cl.built !== cl.version) pack(world);
  const n = cl.count;
  if (n === 0) return;
  const c = world.components;
  const h = world.h,
    S = cl.substeps,
    hs = h / S,
    ihs = 1 / hs,
    ihs2 = ihs * ihs;
  const gx = world.gravity[0]!,
    gy = world.gravity[1]!;
  const k = cl.scalars;
  k[SC_HS] = hs;
  k[SC_INV_HS] = ihs;
  k[SC_GX_HS] = gx * hs;
  k[SC_GY_HS] = gy * hs;
  k[SC_GX_H] = gx * h;
  k[SC_GY_H] = gy * h;
  k[SC_INV_HS2] = ihs2;
  const np = cl.pointCount,
    rigid = cl.rigidCount;
  let massesChanged = false;
  for (let i = 0; i < np; i += CHUNK) if (gatherPoints(cl, c, i, Math.min(np, i + CHUNK))) massesChanged = true;
  // The per-link factors depend on the links, the points' inverse masses and h_s only: most steps reuse them.
  if (massesChanged || cl.preparedVersion !== cl.built || cl.preparedStep !== hs) {
    for (let l = 0; l < n; l += CHUNK) prepareLinks(cl, l, Math.min(n, l + CHUNK));
    cl.preparedVersion = cl.built;
    cl.preparedStep = hs;
  }
  const pins = cl.softPinCount;
  const box = world.collision.boundary;
  for (let sub = 0; sub < S; sub++) {
    for (let i = 0; i < np; i += CHUNK) predictPoints(cl, sub > 0, i, Math.min(np, i + CHUNK));
    if (pins > 0) projectSoftPins(world, cl);
    // Project: inextensible links, then the compliant ones (one pass; their multipliers restart each substep).
    for (let l = 0; l < rigid; l += CHUNK) projectLinks(cl, l, Math.min(rigid, l + CHUNK), false);
    const last = sub === S - 1;
    for (let l = rigid; l < n; l += CHUNK) projectLinks(cl, l, Math.min(n, l + CHUNK), last);
    if (box.enabled) for (let i = 0; i < np; i += CHUNK) projectBoundary(cl, box, i, Math.min(np, i + CHUNK));
  }
  for (let i = 0; i < np; i += CHUNK) scatterPoints(cl, c, i, Math.min(np, i + CHUNK));
  // Strains from squared lengths: q = (L / r)^2, so strain = sqrt(q) - 1 and a link tears when q > (1 + tear)^2.
  let maxQ = 1;
  for (let l = 0; l < n; l += CHUNK) maxQ = largestStretch(cl, l, Math.min(n, l + CHUNK), maxQ);
  cl.maxStretch = Math.sqrt(maxQ) - 1;
  if (maxQ > cl.tearQ) tearLinks(world, ihs2);
}

/**
 * Links, or points, a call of one of the passes below handles. Each pass is its own function, called for
 * one chunk at a time, and ends with its loop: called dozens of times a step, each pass is compiled
 * whole, with the type feedback of all its lines, within the first step. (One function called once a
 * step would have its loops compiled while they run, on-stack replacement, before the code after them
 * has feedback, and that code then gives its compiled version up, a different number of times each
 * run.) The passes read their scalars from `ClothState.scalars` rather than taking them as arguments,
 * so the loops read unboxed doubles. The arithmetic is the same, operation for operation, in the same order:
 * same results to the bit.
 */
const CHUNK = 2048;

/**
 * Gathers points [from, to) into the buffer's sections (see ClothState.buffer). Moving points restart from
 * the start of the step with the integrator's velocity less this step's gravity (g h, added back a substep
 * at a time); fixed points (w = 0: pinned, static, kinematic) stay where they are.
 * @returns whether any of these points' inverse mass differs from the one the buffer held.
 */
function gatherPoints(cl: ClothState, c: Components, from: number, to: number): boolean {
  const P = cl.points,
    xb = cl.buffer,
    U = VELOCITY_AT * cl.pointCount,
    gxh = cl.scalars[SC_GX_H]!,
    gyh = cl.scalars[SC_GY_H]!;
  const { x: px, y: py } = c.Position,
    inv = c.Mass.inv;
  const { x: ox, y: oy } = c.PreviousPosition,
    { x: vx, y: vy } = c.Velocity;
  let changed = false;
  for (let i = from; i < to; i++) {
    const e = P[i]!,
      o = PT_STRIDE * i,
      v = 2 * i,
      w = inv[e]!;
    if (xb[o + PT_INV_MASS] !== w) {
      xb[o + PT_INV_MASS] = w;
      changed = true;
    }
    if (w > 0) {
      xb[o + PT_X] = ox[e]!;
      xb[o + PT_Y] = oy[e]!;
      xb[U + v] = vx[e]! - gxh;
      xb[U + v + 1] = vy[e]! - gyh;
    } else {
      xb[o + PT_X] = px[e]!;
      xb[o + PT_Y] = py[e]!;
      xb[U + v] = 0;
      xb[U + v + 1] = 0;
    }
  }
  return changed;
}

/**
 * Per link of [from, to), once a step: p = r^2 / 3 and k = (2/3) / (w_a + w_b + alpha~), so that a
 * projection takes one division: s = (3 p - L^2) / (p + L^2) and x_a -= w_a k s d, x_b += w_b k s d (the
 * header's step).
 */
function prepareLinks(cl: ClothState, from: number, to: number): void {
  const xb = cl.buffer,
    I = cl.pair,
    R = cl.rest,
    K = cl.compliance,
    F = cl.solve,
    ihs2 = cl.scalars[SC_INV_HS2]!;
  for (let l = from; l < to; l++) {
    const d = xb[I[PAIR_STRIDE * l + PAIR_A]! + PT_INV_MASS]! + xb[I[PAIR_STRIDE * l + PAIR_B]! + PT_INV_MASS]! + K[l]! * ihs2,
      r = R[l]!;
    F[SOLVE_STRIDE * l + SOLVE_P] = (r * r) / 3;
    F[SOLVE_STRIDE * l + SOLVE_K] = d > 0 ? 2 / (3 * d) : 0;
  }
}

/** Points [from, to): velocities from the last substep's moves (when `after`: from the second substep on), then predict: v += g h_s, x += v h_s. */
function predictPoints(cl: ClothState, after: boolean, from: number, to: number): void {
  const xb = cl.buffer,
    np = cl.pointCount,
    Q = BEFORE_AT * np,
    U = VELOCITY_AT * np,
    k = cl.scalars;
  const hs = k[SC_HS]!,
    ihs = k[SC_INV_HS]!,
    dvx = k[SC_GX_HS]!,
    dvy = k[SC_GY_HS]!;
  for (let i = from; i < to; i++) {
    const o = PT_STRIDE * i;
    if (xb[o + PT_INV_MASS] === 0) continue;
    const v = 2 * i,
      x = xb[o + PT_X]!,
      y = xb[o + PT_Y]!;
    let v1: number, v2: number;
    if (after) {
      v1 = (x - xb[Q + v]!) * ihs + dvx;
      v2 = (y - xb[Q + v + 1]!) * ihs + dvy;
    } else {
      v1 = xb[U + v]! + dvx;
      v2 = xb[U + v + 1]! + dvy;
    }
    xb[Q + v] = x;
    xb[Q + v + 1] = y;
    xb[o + PT_X] = x + v1 * hs;
    xb[o + PT_Y] = y + v2 * hs;
  }
}

/**
 * The soft pins' pass of a substep (see pinClothPoint): each pin of a live, moving, packed point moves it
 * toward its target by w dlambda, dlambda = min(C / (w + alpha / h_s^2), maxForce h_s^2), C its distance
 * from the target, and records the force dlambda / h_s^2 (N); other pins record 0.
 */
function projectSoftPins(world: PhysicsWorld, cl: ClothState): void {
  const xb = cl.buffer,
    hs = cl.scalars[SC_HS]!,
    ihs2 = cl.scalars[SC_INV_HS2]!,
    T = cl.softPinTarget,
    F = cl.softPinForce;
  for (let i = 0; i < cl.softPinCount; i++) {
    F[i] = 0;
    const h = cl.softPinHandle[i]!;
    if (!isAlive(world, h)) continue;
    const e = slotOf(h);
    if (cl.seen[e] !== cl.seenStamp) continue;
    const o = PT_STRIDE * cl.compact[e]!,
      w = xb[o + PT_INV_MASS]!;
    if (w === 0) continue;
    const dx = xb[o + PT_X]! - T[2 * i]!,
      dy = xb[o + PT_Y]! - T[2 * i + 1]!,
      C = Math.sqrt(dx * dx + dy * dy);
    if (C === 0) continue;
    const dl = Math.min(C / (w + cl.softPinCompliance[i]! * ihs2), cl.softPinMaxForce[i]! * hs * hs),
      s = (w * dl) / C;
    xb[o + PT_X] = xb[o + PT_X]! - s * dx;
    xb[o + PT_Y] = xb[o + PT_Y]! - s * dy;
    F[i] = dl * ihs2;
  }
}

/**
 * Points [from, to) against the world's boundary box (setBoundary), after a substep's links: a moving
 * point past a wall is put back on it, which takes the normal part out of its velocity (the velocity is
 * the substep's move over h_s: the box's restitution does not apply to cloth), and its move along that
 * wall in the substep is cut by friction against the depth d it was pushed back: cancelled when
 * under staticFriction d, else shortened by friction d (position-based friction: Macklin, Mueller,
 * Chentanez and Kim, "Unified Particle Physics for Real-Time Applications", SIGGRAPH 2014, sec. 6.1).
 */
function projectBoundary(cl: ClothState, box: Boundary, from: number, to: number): void {
  const xb = cl.buffer,
    Q = BEFORE_AT * cl.pointCount;
  const x0 = box.min[0]!,
    y0 = box.min[1]!,
    x1 = box.max[0]!,
    y1 = box.max[1]!,
    mu = box.friction,
    mus = box.staticFriction;
  for (let i = from; i < to; i++) {
    const o = PT_STRIDE * i;
    if (xb[o + PT_INV_MASS] === 0) continue;
    let x = xb[o + PT_X]!,
      y = xb[o + PT_Y]!;
    if (x >= x0 && x <= x1 && y >= y0 && y <= y1) continue;
    const px = xb[Q + 2 * i]!,
      py = xb[Q + 2 * i + 1]!;
    if (y < y0 || y > y1) {
      const wall = y < y0 ? y0 : y1;
      x = alongWall(x, px, Math.abs(wall - y), mu, mus);
      y = wall;
    }
    if (x < x0 || x > x1) {
      const wall = x < x0 ? x0 : x1;
      y = alongWall(y, py, Math.abs(wall - x), mu, mus);
      x = wall;
    }
    xb[o + PT_X] = x;
    xb[o + PT_Y] = y;
  }
}

/** A coordinate along a wall after friction: `at` moved from `from` this substep, pushed back from the wall by `depth` (see projectBoundary). */
function alongWall(at: number, from: number, depth: number, mu: number, mus: number): number {
  const move = at - from,
    size = Math.abs(move);
  if (size <= mus * depth) return from;
  return at - (Math.min(size, mu * depth) * move) / size;
}

/**
 * One Gauss-Seidel pass over the packed links [from, to); with `record`, also keeps each link's
 * multiplier in `lambda` (the last substep's, for break forces).
 */
function projectLinks(cl: ClothState, from: number, to: number, record: boolean): void {
  const xb = cl.buffer,
    I = cl.pair,
    F = cl.solve,
    lam = cl.lambda;
  for (let l = from; l < to; l++) {
    const oa = I[PAIR_STRIDE * l + PAIR_A]!,
      ob = I[PAIR_STRIDE * l + PAIR_B]!;
    const ax = xb[oa + PT_X]!,
      ay = xb[oa + PT_Y]!,
      bx = xb[ob + PT_X]!,
      by = xb[ob + PT_Y]!;
    const dx = bx - ax,
      dy = by - ay;
    const p = F[SOLVE_STRIDE * l + SOLVE_P]!,
      d2 = dx * dx + dy * dy;
    const ks = F[SOLVE_STRIDE * l + SOLVE_K]! * ((3 * p - d2) / (p + d2)),
      sa = xb[oa + PT_INV_MASS]! * ks,
      sb = xb[ob + PT_INV_MASS]! * ks;
    // The multiplier of this projection: dlambda = -C / D = (r - L) / D = (s / D) L, with s / D = ks.
    if (record) lam[l] = ks * Math.sqrt(d2);
    xb[oa + PT_X] = ax - sa * dx;
    xb[oa + PT_Y] = ay - sa * dy;
    xb[ob + PT_X] = bx + sb * dx;
    xb[ob + PT_Y] = by + sb * dy;
  }
}

/** Writes points [from, to) that move back to the stores: positions, and velocities from their last substep's move. */
function scatterPoints(cl: ClothState, c: Components, from: number, to: number): void {
  const P = cl.points,
    xb = cl.buffer,
    Q = BEFORE_AT * cl.pointCount,
    ihs = cl.scalars[SC_INV_HS]!;
  const { x: px, y: py } = c.Position,
    { x: vx, y: vy } = c.Velocity;
  for (let i = from; i < to; i++) {
    const o = PT_STRIDE * i;
    if (xb[o + PT_INV_MASS] === 0) continue;
    const e = P[i]!,
      v = 2 * i;
    px[e] = xb[o + PT_X]!;
    py[e] = xb[o + PT_Y]!;
    vx[e] = (xb[o + PT_X]! - xb[Q + v]!) * ihs;
    vy[e] = (xb[o + PT_Y]! - xb[Q + v + 1]!) * ihs;
  }
}

/** Packed link l's stretch q = (L / r)^2: its length over its rest length, squared (SOLVE_P holds r^2 / 3). */
function stretchOf(cl: ClothState, l: number): number {
  const xb = cl.buffer,
    I = cl.pair;
  const oa = I[PAIR_STRIDE * l + PAIR_A]!,
    ob = I[PAIR_STRIDE * l + PAIR_B]!;
  const dx = xb[ob + PT_X]! - xb[oa + PT_X]!,
    dy = xb[ob + PT_Y]! - xb[oa + PT_Y]!;
  return (dx * dx + dy * dy) / (3 * cl.solve[SOLVE_STRIDE * l + SOLVE_P]!);
}

/** The larger of `maxQ` and the largest stretch q = (L / r)^2 of links [from, to). */
function largestStretch(cl: ClothState, from: number, to: number, maxQ: number): number {
  for (let l = from; l < to; l++) {
    const q = stretchOf(cl, l);
    if (q > maxQ) maxQ = q;
  }
  return maxQ;
}

/** Tears the links past their tear strain: reports each in `world.joints.breaks` (in link order), then removes them. */
function tearLinks(world: PhysicsWorld, ihs2: number): void {
  const cl = world.cloth,
    c = world.components,
    n = cl.count,
    rigid = cl.rigidCount;
  const T = cl.tear,
    E = cl.link,
    lam = cl.lambda;
  const doomed: number[] = [];
  for (let l = 0; l < n; l++) {
    const q = stretchOf(cl, l),
      t1 = 1 + T[l]!;
    if (q > t1 * t1) {
      const strain = Math.sqrt(q) - 1;
      const e = E[l]!;
      doomed.push(e);
      // Force: the link's tension k strain for a compliant link, else the last substep's correction impulse.
      const force = l >= rigid ? Math.abs(lam[l]!) * ihs2 : 0;
      pushBreak(
        world.joints.breaks,
        currentHandle(world, e),
        currentHandle(world, c.ClothLink.a[e]!),
        currentHandle(world, c.ClothLink.b[e]!),
        force,
        0,
        strain,
      );
    }
  }
  for (const e of doomed) {
    detachClothLink(world, e);
    removeEntity(world, e);
  }
}

/** Packs the cloth links (as pairs of compact point offsets) and their distinct points. */
function pack(world: PhysicsWorld): void {
  const cl = world.cloth;
  const c = world.components;
  const L = c.ClothLink;
  const links = query(world, [L]);
  const n = links.length;
  if (cl.rest.length < n) {
    const cap = Math.max(16, n * 2);
    cl.link = new Int32Array(cap);
    cl.pair = new Int32Array(PAIR_STRIDE * cap);
    cl.rest = new Float64Array(cap);
    cl.compliance = new Float64Array(cap);
    cl.tear = new Float64Array(cap);
    cl.lambda = new Float64Array(cap);
    cl.solve = new Float64Array(SOLVE_STRIDE * cap);
  }
  if (cl.seen.length < world.capacity + 1) {
    cl.seen = new Uint32Array(world.capacity + 1);
    cl.compact = new Int32Array(world.capacity + 1);
  }
  const seen = cl.seen,
    compact = cl.compact,
    stamp = ++cl.seenStamp;
  const points: number[] = [];
  const index = (e: number): number => {
    if (seen[e] !== stamp) {
      seen[e] = stamp;
      compact[e] = points.length;
      points.push(e);
    }
    return compact[e]! * PT_STRIDE;
  };
  // Inextensible links go first, the compliant ones after (see clothSystem).
  let front = 0,
    back = n - 1,
    tearQ = Infinity;
  for (let i = 0; i < n; i++) {
    const e = links[i]!;
    const k = L.compliance[e]! === 0 ? front++ : back--;
    cl.link[k] = e;
    cl.pair[PAIR_STRIDE * k + PAIR_A] = index(L.a[e]!);
    cl.pair[PAIR_STRIDE * k + PAIR_B] = index(L.b[e]!);
    cl.rest[k] = L.restLength[e]!;
    cl.compliance[k] = L.compliance[e]!;
    cl.tear[k] = L.tearStretch[e]!;
    const t1 = 1 + L.tearStretch[e]!;
    if (t1 * t1 < tearQ) tearQ = t1 * t1;
  }
  // Points that lost every link (torn free, or their links removed) stay cloth points while they live:
  // the solver still moves them, so the boundary box holds them like the rest of the sheet.
  const linked = points.length;
  const old = cl.pointHandles;
  for (let i = 0; i < old.length; i++) if (isAlive(world, old[i]!)) index(slotOf(old[i]!));
  colourOrder(cl, 0, front, linked);
  colourOrder(cl, front, n, linked);
  cl.rigidCount = front;
  cl.tearQ = tearQ;
  cl.count = n;
  cl.points = Int32Array.from(points);
  cl.pointCount = points.length;
  cl.pointHandles = Float64Array.from(points, (e) => currentHandle(world, e));
  if (cl.buffer.length < BUFFER_STRIDE * points.length) cl.buffer = new Float64Array(BUFFER_STRIDE * points.length);
  cl.built = cl.version;
}

/**
 * Reorders the packed links [from, to) by colour: a greedy colouring gives each link the smallest colour
 * that neither of its points has yet, and the links are then laid out colour by colour (in their old
 * order within a colour). Consecutive links of one colour share no point, so a projection need not wait
 * for the one before it to store its point: the solver's pass runs several at once. Each point still
 * sees its links in one fixed order (Gauss-Seidel).
 */
function colourOrder(cl: ClothState, from: number, to: number, pointCount: number): void {
  const m = to - from;
  if (m < 2) return;
  const used = new Uint32Array(pointCount * 2); // per point: a bit for each of colours 0..63 taken
  const colour = new Int32Array(m);
  let colours = 0;
  for (let k = 0; k < m; k++) {
    const a = cl.pair[PAIR_STRIDE * (from + k) + PAIR_A]! / PT_STRIDE,
      b = cl.pair[PAIR_STRIDE * (from + k) + PAIR_B]! / PT_STRIDE;
    let c = 0;
    for (; c < 64; c++) {
      const word = c >> 5,
        bit = 1 << (c & 31);
      if (((used[2 * a + word]! | used[2 * b + word]!) & bit) === 0) break;
    }
    if (c < 64) {
      const word = c >> 5,
        bit = 1 << (c & 31);
      used[2 * a + word]! |= bit;
      used[2 * b + word]! |= bit;
    } else c = 63; // more than 63 links at a point: the rest share the last colour (still correct, only slower)
    colour[k] = c;
    if (c + 1 > colours) colours = c + 1;
  }
  const start = new Int32Array(colours + 1);
  for (let k = 0; k < m; k++) start[colour[k]! + 1]!++;
  for (let c = 0; c < colours; c++) start[c + 1]! += start[c]!;
  const link = cl.link.slice(from, to),
    pair = cl.pair.slice(PAIR_STRIDE * from, PAIR_STRIDE * to);
  const rest = cl.rest.slice(from, to),
    comp = cl.compliance.slice(from, to),
    tear = cl.tear.slice(from, to);
  for (let k = 0; k < m; k++) {
    const j = from + start[colour[k]!]!++;
    cl.link[j] = link[k]!;
    cl.pair[PAIR_STRIDE * j + PAIR_A] = pair[PAIR_STRIDE * k + PAIR_A]!;
    cl.pair[PAIR_STRIDE * j + PAIR_B] = pair[PAIR_STRIDE * k + PAIR_B]!;
    cl.rest[j] = rest[k]!;
    cl.compliance[j] = comp[k]!;
    cl.tear[j] = tear[k]!;
  }
}

/**
 * Bookkeeping of a cloth link's removal (the caller removes the entity): uncount it from its points, repack.
 * @category Cloth
 */
export function detachClothLink(world: PhysicsWorld, e: number): void {
  const L = world.components.ClothLink,
    att = world.joints.attached;
  att[L.a[e]!] = att[L.a[e]!]! - 1;
  att[L.b[e]!] = att[L.b[e]!]! - 1;
  world.cloth.version++;
}
