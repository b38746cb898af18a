import { removeEntity } from 'bitecs';
import type { PhysicsWorld } from '../world.js';
import { query } from '../query.js';
import { pushBreak } from '../joints/state.js';
import { currentHandle } from '../handles.js';

/**
 * The cloth solver (stage 6, `constraints`): every `ClothLink` is a distance constraint solved on
 * positions by XPBD (Macklin, Mueller and Chentanez, "XPBD: Position-Based Simulation of Compliant
 * Constrained Dynamics", 2016; Mueller et al., "Position Based Dynamics", 2007), after the integrate
 * stage has moved the points by their velocities and forces (gravity, drag against the world's wind
 * and turbulence):
 *
 * 1. (when the set of links changed) pack the links and their distinct points; each step the points
 *    are gathered into an interleaved buffer (x, y, inverse mass) the loop works on;
 * 2. `iterations` Gauss-Seidel passes: for a link of length L, rest r, C = L - r, inverse masses
 *    w_a, w_b and compliance alpha (alpha~ = alpha / h^2):
 *    dlambda = (-C - alpha~ lambda) / (w_a + w_b + alpha~), x_b += w_b dlambda u, x_a -= w_a dlambda u;
 * 3. the points' velocities become (x - x_start) / h;
 * 4. links stretched past their `tearStretch` tear: removed, each reported in `world.joints.breaks`
 *    (force lambda / h^2, its strain).
 *
 * A dedicated loop over packed arrays: a 64 x 64 cloth has about 24,000 links.
 */
export function clothSystem(world: PhysicsWorld): void {
  const cl = world.cloth;
  if (cl.version === 0 || world.dimensions !== 2) return;
  if (cl.built !== cl.version) pack(world);
  const n = cl.count;
  if (n === 0) return;
  const c = world.components;
  const px = c.Position.x, py = c.Position.y, inv = c.Mass.inv;
  const h = world.h, ih2 = 1 / (h * h);
  // Gather the points into an interleaved buffer (x, y, w) by compact index.
  const P = cl.points, np = cl.pointCount, xb = cl.buffer;
  for (let i = 0; i < np; i++) { const e = P[i]!, o = 3 * i; xb[o] = px[e]!; xb[o + 1] = py[e]!; xb[o + 2] = inv[e]!; }
  // Per link: rest, alpha~ and 1 / (w_a + w_b + alpha~) for this step's h and masses.
  const I = cl.pair, R = cl.rest, K = cl.compliance, F = cl.solve, lam = cl.lambda;
  for (let l = 0; l < n; l++) {
    const at = K[l]! * ih2;
    const w = xb[I[2 * l]! + 2]! + xb[I[2 * l + 1]! + 2]! + at;
    F[2 * l] = at; F[2 * l + 1] = w > 0 ? 1 / w : 0;
    lam[l] = 0;
  }
  const rigid = cl.rigidCount;
  for (let it = 0; it < cl.iterations; it++) {
    // Inextensible links first (no multiplier to carry), then the compliant ones.
    for (let l = 0; l < rigid; l++) {
      const oa = I[2 * l]!, ob = I[2 * l + 1]!;
      const dx = xb[ob]! - xb[oa]!, dy = xb[ob + 1]! - xb[oa + 1]!;
      const L = Math.sqrt(dx * dx + dy * dy);
      if (L < 1e-12) continue;
      const s = (R[l]! - L) * F[2 * l + 1]! / L, wa = xb[oa + 2]! * s, wb = xb[ob + 2]! * s;
      xb[oa] = xb[oa]! - wa * dx; xb[oa + 1] = xb[oa + 1]! - wa * dy;
      xb[ob] = xb[ob]! + wb * dx; xb[ob + 1] = xb[ob + 1]! + wb * dy;
    }
    for (let l = rigid; l < n; l++) {
      const oa = I[2 * l]!, ob = I[2 * l + 1]!;
      const dx = xb[ob]! - xb[oa]!, dy = xb[ob + 1]! - xb[oa + 1]!;
      const L = Math.sqrt(dx * dx + dy * dy);
      if (L < 1e-12) continue;
      const at = F[2 * l]!;
      const dl = (R[l]! - L - at * lam[l]!) * F[2 * l + 1]!;
      lam[l] = lam[l]! + dl;
      const s = dl / L, wa = xb[oa + 2]! * s, wb = xb[ob + 2]! * s;
      xb[oa] = xb[oa]! - wa * dx; xb[oa + 1] = xb[oa + 1]! - wa * dy;
      xb[ob] = xb[ob]! + wb * dx; xb[ob + 1] = xb[ob + 1]! + wb * dy;
    }
  }
  // Scatter the moving points back; their velocities become (x - x_start) / h.
  const ox = c.PreviousPosition.x, oy = c.PreviousPosition.y, vx = c.Velocity.x, vy = c.Velocity.y;
  const ih = 1 / h;
  for (let i = 0; i < np; i++) {
    const o = 3 * i;
    if (xb[o + 2] === 0) continue;
    const e = P[i]!;
    const x = xb[o]!, y = xb[o + 1]!;
    px[e] = x; py[e] = y;
    vx[e] = (x - ox[e]!) * ih; vy[e] = (y - oy[e]!) * ih;
  }
  let maxStretch = 0;
  let doomed: number[] | null = null;
  const T = cl.tear, E = cl.link;
  for (let l = 0; l < n; l++) {
    const oa = I[2 * l]!, ob = I[2 * l + 1]!;
    const dx = xb[ob]! - xb[oa]!, dy = xb[ob + 1]! - xb[oa + 1]!;
    const strain = (Math.sqrt(dx * dx + dy * dy) - R[l]!) / R[l]!;
    if (strain > maxStretch) maxStretch = strain;
    if (strain > T[l]!) {
      const e = E[l]!;
      (doomed ??= []).push(e);
      pushBreak(world.joints.breaks, currentHandle(world, e), currentHandle(world, c.ClothLink.a[e]!), currentHandle(world, c.ClothLink.b[e]!), Math.abs(lam[l]!) * ih2, 0, strain);
    }
  }
  cl.maxStretch = maxStretch;
  if (doomed) for (const e of doomed) { detachClothLink(world, e); removeEntity(world, e); }
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
    cl.link = new Int32Array(cap); cl.pair = new Int32Array(2 * cap);
    cl.rest = new Float64Array(cap); cl.compliance = new Float64Array(cap); cl.tear = new Float64Array(cap);
    cl.lambda = new Float64Array(cap); cl.solve = new Float64Array(2 * cap);
  }
  if (cl.seen.length < world.capacity + 1) { cl.seen = new Uint32Array(world.capacity + 1); cl.compact = new Int32Array(world.capacity + 1); }
  const seen = cl.seen, compact = cl.compact, stamp = ++cl.seenStamp;
  const points: number[] = [];
  const index = (e: number): number => {
    if (seen[e] !== stamp) { seen[e] = stamp; compact[e] = points.length; points.push(e); }
    return compact[e]! * 3;
  };
  // Inextensible links go first, the compliant ones after (see clothSystem).
  let front = 0, back = n - 1;
  for (let i = 0; i < n; i++) {
    const e = links[i]!;
    const k = L.compliance[e]! === 0 ? front++ : back--;
    cl.link[k] = e; cl.pair[2 * k] = index(L.a[e]!); cl.pair[2 * k + 1] = index(L.b[e]!);
    cl.rest[k] = L.restLength[e]!; cl.compliance[k] = L.compliance[e]!; cl.tear[k] = L.tearStretch[e]!;
  }
  cl.rigidCount = front;
  cl.count = n;
  cl.points = Int32Array.from(points);
  cl.pointCount = points.length;
  if (cl.buffer.length < 3 * points.length) cl.buffer = new Float64Array(3 * points.length);
  cl.built = cl.version;
}

/** Bookkeeping of a cloth link's removal (the caller removes the entity): uncount it from its points, repack. */
export function detachClothLink(world: PhysicsWorld, e: number): void {
  const L = world.components.ClothLink, att = world.joints.attached;
  att[L.a[e]!] = att[L.a[e]!]! - 1; att[L.b[e]!] = att[L.b[e]!]! - 1;
  world.cloth.version++;
}
