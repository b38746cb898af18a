import { addPoint, type Manifold3D } from './manifold-3d.js';

/**
 * Contact candidates of the 3D narrowphase before the reduction to four points: the deepest, the
 * farthest from it, then the two that span the largest areas on either side (Gregorius, "Robust
 * Contact Creation for Physics Simulations", GDC 2015).
 */

// Candidate points before the reduction to four (scratch).
export const CAND = 160;
export const cx = new Float64Array(CAND),
  cy = new Float64Array(CAND),
  cz = new Float64Array(CAND),
  cs = new Float64Array(CAND),
  cid = new Float64Array(CAND);
let cn = 0;

/** Adds a candidate on the incident surface at (x, y, z) with separation s, if s <= margin; its midpoint goes back along -n by s / 2. */
export function pushCandidate(
  s: number,
  x: number,
  y: number,
  z: number,
  id: number,
  margin: number,
  nx: number,
  ny: number,
  nz: number,
): void {
  if (s > margin || cn >= CAND) return;
  cx[cn] = x - (nx * s) / 2;
  cy[cn] = y - (ny * s) / 2;
  cz[cn] = z - (nz * s) / 2;
  cs[cn] = s;
  cid[cn] = id;
  cn++;
}

/**
 * Candidates whose separation is within DEPTH_TIE margin + 1e-6 m of the deepest count as equally deep
 * when the reduction picks its first point (the tolerance the reference-face choice uses too: 1e-4 m at
 * the default 0.02 m margin, 2 % of a linear slop; m / m). It must cover the ~5e-5 m the corners of a
 * settling box differ by (below it, the deepest corner goes round the octagon step by step and the
 * kept four switch each step, which keeps the rock going), and stays far below what the solver resolves.
 */
const DEPTH_TIE = 0.005;

/** Reduces the candidates to at most four (see the module's note) into `out`, and clears them; `margin`: the speculative distance, m. */
export function finishCandidates(out: Manifold3D, nx: number, ny: number, nz: number, margin: number): void {
  const n = cn;
  cn = 0;
  if (n <= 4) {
    for (let i = 0; i < n; i++) addPoint(out, cx[i]!, cy[i]!, cz[i]!, cs[i]!, cid[i]!);
    return;
  }
  // The first point: the first candidate (in clipping order, which is fixed while the same features
  // touch) within the tie tolerance of the deepest. Equally deep corners (a box turned 45 degrees on
  // another: an octagon whose corners agree to ~1e-8 m) would otherwise be picked by rounding noise,
  // and the four kept would alternate between the two interleaved sets, each switch starting the new
  // points without warm start (the cube would sink and be kicked a little every switch).
  let a = 0;
  for (let i = 1; i < n; i++) if (cs[i]! < cs[a]!) a = i;
  const tie = cs[a]! + DEPTH_TIE * margin + 1e-6;
  for (let i = 0; i < a; i++)
    if (cs[i]! <= tie) {
      a = i;
      break;
    }
  let b = -1,
    best = -1;
  for (let i = 0; i < n; i++) {
    const d = (cx[i]! - cx[a]!) ** 2 + (cy[i]! - cy[a]!) ** 2 + (cz[i]! - cz[a]!) ** 2;
    if (d > best) {
      best = d;
      b = i;
    }
  }
  const area = (i: number): number => {
    const ux = cx[b]! - cx[a]!,
      uy = cy[b]! - cy[a]!,
      uz = cz[b]! - cz[a]!;
    const vx = cx[i]! - cx[a]!,
      vy = cy[i]! - cy[a]!,
      vz = cz[i]! - cz[a]!;
    return nx * (uy * vz - uz * vy) + ny * (uz * vx - ux * vz) + nz * (ux * vy - uy * vx);
  };
  let c = -1,
    d = -1,
    maxA = 0,
    minA = 0;
  for (let i = 0; i < n; i++) {
    const s = area(i);
    if (s > maxA) {
      maxA = s;
      c = i;
    }
    if (s < minA) {
      minA = s;
      d = i;
    }
  }
  for (const i of [a, b, c, d]) if (i >= 0) addPoint(out, cx[i]!, cy[i]!, cz[i]!, cs[i]!, cid[i]!);
}
