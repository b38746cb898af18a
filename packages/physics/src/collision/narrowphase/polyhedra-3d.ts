import { EDGE_LEFT, EDGE_RIGHT, EDGE_STRIDE, EDGE_U, EDGE_V } from '../../shapes/hull-edges-3d.js';
import { CAND, finishCandidates, pushCandidate } from './candidates-3d.js';
import { addPoint, flip, type Manifold3D } from './manifold-3d.js';
import type { Posed } from './posed-3d.js';
import { closestSegmentParams, st } from './segments-3d.js';

/**
 * Polyhedron against polyhedron: separating axes (the faces of both, and the edge pairs that form a
 * face of the Minkowski difference, found on the Gauss map: Gregorius, "The Separating Axis Test
 * between Convex Polyhedra", GDC 2013), then Sutherland-Hodgman clipping of the incident face against
 * the reference face's side planes, or the closest points of the two edges.
 */

/** Deepest face of P against the vertices of Q: writes bestSep[0] and returns the face. */
const bestSep = new Float64Array(1);
function faceQuery(P: Posed, Q: Posed): number {
  const nf = P.hull.faceOffsets.length;
  let best = -Infinity,
    bf = 0;
  for (let f = 0; f < nf; f++) {
    const nx = P.fn[3 * f]!,
      ny = P.fn[3 * f + 1]!,
      nz = P.fn[3 * f + 2]!;
    // Support of Q along -n.
    let m = Infinity;
    for (let i = 0; i < Q.n; i++) {
      const d = nx * Q.v[3 * i]! + ny * Q.v[3 * i + 1]! + nz * Q.v[3 * i + 2]!;
      if (d < m) m = d;
    }
    const s = m - P.fd[f]!;
    if (s > best) {
      best = s;
      bf = f;
    }
  }
  bestSep[0] = best;
  return bf;
}

/** Polyhedron A against polyhedron B. */
export function polyhedra(A: Posed, B: Posed, margin: number, out: Manifold3D): void {
  const fa = faceQuery(A, B),
    sa = bestSep[0]!;
  if (sa > margin) return;
  const fb = faceQuery(B, A),
    sb = bestSep[0]!;
  if (sb > margin) return;
  // Edge pairs that form faces of the Minkowski difference (Gauss map test).
  const EA = A.hull.edges,
    EB = B.hull.edges;
  let se = -Infinity,
    ea = -1,
    eb = -1,
    enx = 0,
    eny = 0,
    enz = 0;
  for (let i = 0; i < EA.length; i += EDGE_STRIDE) {
    const a1 = 3 * EA[i + EDGE_LEFT]!,
      a2 = 3 * EA[i + EDGE_RIGHT]!;
    const ax = A.fn[a1]!,
      ay = A.fn[a1 + 1]!,
      az = A.fn[a1 + 2]!,
      bx = A.fn[a2]!,
      by = A.fn[a2 + 1]!,
      bz = A.fn[a2 + 2]!;
    const u = 3 * EA[i + EDGE_U]!,
      v = 3 * EA[i + EDGE_V]!;
    const e1x = A.v[v]! - A.v[u]!,
      e1y = A.v[v + 1]! - A.v[u + 1]!,
      e1z = A.v[v + 2]! - A.v[u + 2]!;
    for (let j = 0; j < EB.length; j += EDGE_STRIDE) {
      const b1 = 3 * EB[j + EDGE_LEFT]!,
        b2 = 3 * EB[j + EDGE_RIGHT]!;
      const cx_ = -B.fn[b1]!,
        cy_ = -B.fn[b1 + 1]!,
        cz_ = -B.fn[b1 + 2]!,
        dx = -B.fn[b2]!,
        dy = -B.fn[b2 + 1]!,
        dz = -B.fn[b2 + 2]!;
      // bxa = b x a, dxc = d x c (arcs a-b and c-d intersect on the unit sphere).
      const bxax = by * az - bz * ay,
        bxay = bz * ax - bx * az,
        bxaz = bx * ay - by * ax;
      const cba = cx_ * bxax + cy_ * bxay + cz_ * bxaz,
        dba = dx * bxax + dy * bxay + dz * bxaz;
      if (cba * dba >= 0) continue;
      const dxcx = dy * cz_ - dz * cy_,
        dxcy = dz * cx_ - dx * cz_,
        dxcz = dx * cy_ - dy * cx_;
      const adc = ax * dxcx + ay * dxcy + az * dxcz,
        bdc = bx * dxcx + by * dxcy + bz * dxcz;
      if (!(adc * bdc < 0 && cba * bdc > 0)) continue;
      const p = 3 * EB[j + EDGE_U]!,
        q = 3 * EB[j + EDGE_V]!;
      const e2x = B.v[q]! - B.v[p]!,
        e2y = B.v[q + 1]! - B.v[p + 1]!,
        e2z = B.v[q + 2]! - B.v[p + 2]!;
      let nx = e1y * e2z - e1z * e2y,
        ny = e1z * e2x - e1x * e2z,
        nz = e1x * e2y - e1y * e2x;
      const l = Math.hypot(nx, ny, nz);
      if (l < 1e-6 * Math.hypot(e1x, e1y, e1z) * Math.hypot(e2x, e2y, e2z)) continue; // parallel edges: a face axis covers them
      nx /= l;
      ny /= l;
      nz /= l;
      if (nx * (A.v[u]! - A.cx) + ny * (A.v[u + 1]! - A.cy) + nz * (A.v[u + 2]! - A.cz) < 0) {
        nx = -nx;
        ny = -ny;
        nz = -nz;
      }
      const s = nx * (B.v[p]! - A.v[u]!) + ny * (B.v[p + 1]! - A.v[u + 1]!) + nz * (B.v[p + 2]! - A.v[u + 2]!);
      if (s > se) {
        se = s;
        ea = i;
        eb = j;
        enx = nx;
        eny = ny;
        enz = nz;
      }
    }
  }
  if (se > margin) return;
  const faceBest = Math.max(sa, sb);
  const tol = 0.005 * margin + 1e-6;
  if (ea >= 0 && se > faceBest + tol) {
    // Edge-edge: one point midway between the closest points of the two edges.
    const u = 3 * EA[ea + EDGE_U]!,
      v = 3 * EA[ea + EDGE_V]!,
      p = 3 * EB[eb + EDGE_U]!,
      q = 3 * EB[eb + EDGE_V]!;
    closestSegmentParams(
      A.v[u]!,
      A.v[u + 1]!,
      A.v[u + 2]!,
      A.v[v]!,
      A.v[v + 1]!,
      A.v[v + 2]!,
      B.v[p]!,
      B.v[p + 1]!,
      B.v[p + 2]!,
      B.v[q]!,
      B.v[q + 1]!,
      B.v[q + 2]!,
    );
    const s = st[0]!,
      t = st[1]!;
    const x = (A.v[u]! + (A.v[v]! - A.v[u]!) * s + B.v[p]! + (B.v[q]! - B.v[p]!) * t) / 2;
    const y = (A.v[u + 1]! + (A.v[v + 1]! - A.v[u + 1]!) * s + B.v[p + 1]! + (B.v[q + 1]! - B.v[p + 1]!) * t) / 2;
    const z = (A.v[u + 2]! + (A.v[v + 2]! - A.v[u + 2]!) * s + B.v[p + 2]! + (B.v[q + 2]! - B.v[p + 2]!) * t) / 2;
    out.nx = enx;
    out.ny = eny;
    out.nz = enz;
    addPoint(out, x, y, z, se, 2 ** 40 + (ea / EDGE_STRIDE) * 4096 + eb / EDGE_STRIDE);
    return;
  }
  // Face contact: the reference face is A's unless B's separates clearly more.
  if (sb > sa + tol) {
    clipFaces(B, fb, A, margin, out, 1);
    flip(out);
  } else clipFaces(A, fa, B, margin, out, 0);
}

// Clipping scratch: polygons of up to CAND points with their ids.
const pa = new Float64Array(3 * CAND),
  pb = new Float64Array(3 * CAND),
  ia = new Float64Array(CAND),
  ib = new Float64Array(CAND);

/** Clips I's face most opposed to R's face `rf` against that face's side planes; normal out of R. */
function clipFaces(R: Posed, rf: number, I: Posed, margin: number, out: Manifold3D, flipped: number): void {
  const nx = R.fn[3 * rf]!,
    ny = R.fn[3 * rf + 1]!,
    nz = R.fn[3 * rf + 2]!,
    d = R.fd[rf]!;
  const hI = I.hull,
    hR = R.hull;
  let inc = 0,
    m = Infinity;
  for (let f = 0, nf = hI.faceOffsets.length; f < nf; f++) {
    const dot = I.fn[3 * f]! * nx + I.fn[3 * f + 1]! * ny + I.fn[3 * f + 2]! * nz;
    if (dot < m) {
      m = dot;
      inc = f;
    }
  }
  let n = 0;
  let src = pa,
    dst = pb,
    sid = ia,
    did = ib;
  for (let k = hI.faceStart[inc]!, e = hI.faceStart[inc + 1]!; k < e; k++) {
    const v = 3 * hI.faceVertices[k]!;
    src[3 * n] = I.v[v]!;
    src[3 * n + 1] = I.v[v + 1]!;
    src[3 * n + 2] = I.v[v + 2]!;
    sid[n] = hI.faceVertices[k]!;
    n++;
  }
  const fs = hR.faceStart[rf]!,
    fe = hR.faceStart[rf + 1]!;
  for (let k = fs; k < fe && n > 0; k++) {
    const a = 3 * hR.faceVertices[k]!,
      b = 3 * hR.faceVertices[k + 1 < fe ? k + 1 : fs]!;
    const ex = R.v[b]! - R.v[a]!,
      ey = R.v[b + 1]! - R.v[a + 1]!,
      ez = R.v[b + 2]! - R.v[a + 2]!;
    const sx = ey * nz - ez * ny,
      sy = ez * nx - ex * nz,
      sz = ex * ny - ey * nx;
    const so = sx * R.v[a]! + sy * R.v[a + 1]! + sz * R.v[a + 2]!;
    let m2 = 0;
    for (let i = 0; i < n; i++) {
      const j = i + 1 < n ? i + 1 : 0;
      const di = sx * src[3 * i]! + sy * src[3 * i + 1]! + sz * src[3 * i + 2]! - so;
      const dj = sx * src[3 * j]! + sy * src[3 * j + 1]! + sz * src[3 * j + 2]! - so;
      if (di <= 0 && m2 < CAND) {
        dst[3 * m2] = src[3 * i]!;
        dst[3 * m2 + 1] = src[3 * i + 1]!;
        dst[3 * m2 + 2] = src[3 * i + 2]!;
        did[m2] = sid[i]!;
        m2++;
      }
      if (di <= 0 !== dj <= 0 && m2 < CAND) {
        const t = di / (di - dj);
        dst[3 * m2] = src[3 * i]! + (src[3 * j]! - src[3 * i]!) * t;
        dst[3 * m2 + 1] = src[3 * i + 1]! + (src[3 * j + 1]! - src[3 * i + 1]!) * t;
        dst[3 * m2 + 2] = src[3 * i + 2]! + (src[3 * j + 2]! - src[3 * i + 2]!) * t;
        // A clipped point: the incident edge (its first vertex id) cut by reference side k.
        did[m2] = 64 + (sid[i]! % 64) * 64 + (k - fs) + (di <= 0 ? 0 : 65536);
        m2++;
      }
    }
    const tp = src;
    src = dst;
    dst = tp;
    const ti = sid;
    sid = did;
    did = ti;
    n = m2;
  }
  out.nx = nx;
  out.ny = ny;
  out.nz = nz;
  const base = ((flipped * 256 + rf) * 256 + inc) * 2 ** 20;
  for (let i = 0; i < n; i++) {
    const x = src[3 * i]!,
      y = src[3 * i + 1]!,
      z = src[3 * i + 2]!;
    pushCandidate(nx * x + ny * y + nz * z - d, x, y, z, base + sid[i]!, margin, nx, ny, nz);
  }
  finishCandidates(out, nx, ny, nz, margin);
}
