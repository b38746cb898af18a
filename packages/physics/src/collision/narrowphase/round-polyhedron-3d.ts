import { EDGE_LEFT, EDGE_RIGHT, EDGE_STRIDE, EDGE_U, EDGE_V } from '../../shapes/hull-edges-3d.js';
import { addPoint, type Collider3D, type Manifold3D } from './manifold-3d.js';
import type { Posed } from './posed-3d.js';
import { SEG_P0X, SEG_P0Y, SEG_P0Z, SEG_P1X, SEG_P1Y, SEG_P1Z } from './segment-layout-3d.js';
import { clamp01, closestSegmentParams, seg, segmentOf, st } from './segments-3d.js';

/** Sphere and capsule against a convex polyhedron: closest points to its faces and edges; a capsule on a face keeps both ends (the segment clipped to the face) so it lies still. */

/** Sphere A against polyhedron P (normal A to P; `fromPoly` true: P is A). */
export function spherePolyhedron(S: Collider3D, P: Posed, margin: number, out: Manifold3D, fromPoly: boolean): void {
  const h = P.hull,
    nf = h.faceOffsets.length,
    r = S.radius;
  const x = S.px,
    y = S.py,
    z = S.pz;
  let best = -Infinity,
    bf = 0;
  for (let f = 0; f < nf; f++) {
    const s = P.fn[3 * f]! * x + P.fn[3 * f + 1]! * y + P.fn[3 * f + 2]! * z - P.fd[f]!;
    if (s > best) {
      best = s;
      bf = f;
    }
  }
  if (best - r > margin) return;
  let qx: number, qy: number, qz: number, id: number, nx: number, ny: number, nz: number, dist: number;
  if (best <= 0) {
    nx = P.fn[3 * bf]!;
    ny = P.fn[3 * bf + 1]!;
    nz = P.fn[3 * bf + 2]!;
    qx = x - nx * best;
    qy = y - ny * best;
    qz = z - nz * best;
    id = bf;
    dist = best;
  } else {
    // Outside: the closest point of the surface, on a face's interior or on an edge.
    dist = Infinity;
    qx = x;
    qy = y;
    qz = z;
    id = 0;
    for (let f = 0; f < nf; f++) {
      const fnx = P.fn[3 * f]!,
        fny = P.fn[3 * f + 1]!,
        fnz = P.fn[3 * f + 2]!;
      const s = fnx * x + fny * y + fnz * z - P.fd[f]!;
      if (s <= 0) continue;
      const px = x - fnx * s,
        py = y - fny * s,
        pz = z - fnz * s;
      let inside = true;
      for (let k = h.faceStart[f]!, e = h.faceStart[f + 1]!; k < e; k++) {
        const a = 3 * h.faceVertices[k]!,
          b = 3 * h.faceVertices[k + 1 < e ? k + 1 : h.faceStart[f]!]!;
        const ex = P.v[b]! - P.v[a]!,
          ey = P.v[b + 1]! - P.v[a + 1]!,
          ez = P.v[b + 2]! - P.v[a + 2]!;
        const wx = px - P.v[a]!,
          wy = py - P.v[a + 1]!,
          wz = pz - P.v[a + 2]!;
        if (fnx * (ey * wz - ez * wy) + fny * (ez * wx - ex * wz) + fnz * (ex * wy - ey * wx) < 0) {
          inside = false;
          break;
        }
      }
      if (inside && s < dist) {
        dist = s;
        qx = px;
        qy = py;
        qz = pz;
        id = f;
      }
    }
    const E = h.edges;
    for (let k = 0; k < E.length; k += EDGE_STRIDE) {
      const a = 3 * E[k + EDGE_U]!,
        b = 3 * E[k + EDGE_V]!;
      const ex = P.v[b]! - P.v[a]!,
        ey = P.v[b + 1]! - P.v[a + 1]!,
        ez = P.v[b + 2]! - P.v[a + 2]!;
      const t = clamp01(((x - P.v[a]!) * ex + (y - P.v[a + 1]!) * ey + (z - P.v[a + 2]!) * ez) / (ex * ex + ey * ey + ez * ez));
      const px = P.v[a]! + ex * t,
        py = P.v[a + 1]! + ey * t,
        pz = P.v[a + 2]! + ez * t;
      const d = Math.hypot(x - px, y - py, z - pz);
      if (d < dist) {
        dist = d;
        qx = px;
        qy = py;
        qz = pz;
        id = 1000 + (t === 0 ? 2000 + E[k + EDGE_U]! : t === 1 ? 2000 + E[k + EDGE_V]! : k / EDGE_STRIDE);
      }
    }
    if (dist - r > margin) return;
    nx = (x - qx) / dist;
    ny = (y - qy) / dist;
    nz = (z - qz) / dist;
  }
  // Normal from the polyhedron to the sphere; A is the sphere unless fromPoly.
  const sep = dist - r;
  const mx = qx + (nx * sep) / 2,
    my = qy + (ny * sep) / 2,
    mz = qz + (nz * sep) / 2;
  if (fromPoly) {
    out.nx = nx;
    out.ny = ny;
    out.nz = nz;
  } else {
    out.nx = -nx;
    out.ny = -ny;
    out.nz = -nz;
  }
  addPoint(out, mx, my, mz, sep, id);
}

/** Capsule C (A) against polyhedron P (B): a face clips the segment (two points), else the closest points to the nearest edge. */
export function capsulePolyhedron(C: Collider3D, P: Posed, margin: number, out: Manifold3D): void {
  segmentOf(C, 0);
  const h = P.hull,
    nf = h.faceOffsets.length,
    r = C.radius;
  const p0x = seg[SEG_P0X]!,
    p0y = seg[SEG_P0Y]!,
    p0z = seg[SEG_P0Z]!,
    p1x = seg[SEG_P1X]!,
    p1y = seg[SEG_P1Y]!,
    p1z = seg[SEG_P1Z]!;
  let faceSep = -Infinity,
    bf = 0;
  for (let f = 0; f < nf; f++) {
    const nx = P.fn[3 * f]!,
      ny = P.fn[3 * f + 1]!,
      nz = P.fn[3 * f + 2]!;
    const s = Math.min(nx * p0x + ny * p0y + nz * p0z, nx * p1x + ny * p1y + nz * p1z) - P.fd[f]! - r;
    if (s > faceSep) {
      faceSep = s;
      bf = f;
    }
  }
  if (faceSep > margin) return;
  const dx = p1x - p0x,
    dy = p1y - p0y,
    dz = p1z - p0z;
  let edgeSep = -Infinity,
    be = -1;
  const E = h.edges;
  for (let k = 0; k < E.length; k += EDGE_STRIDE) {
    const n1 = 3 * E[k + EDGE_LEFT]!,
      n2 = 3 * E[k + EDGE_RIGHT]!;
    const d1 = P.fn[n1]! * dx + P.fn[n1 + 1]! * dy + P.fn[n1 + 2]! * dz,
      d2 = P.fn[n2]! * dx + P.fn[n2 + 1]! * dy + P.fn[n2 + 2]! * dz;
    if (d1 * d2 >= 0) continue; // not a face of the Minkowski difference
    const a = 3 * E[k + EDGE_U]!,
      b = 3 * E[k + EDGE_V]!;
    const ex = P.v[b]! - P.v[a]!,
      ey = P.v[b + 1]! - P.v[a + 1]!,
      ez = P.v[b + 2]! - P.v[a + 2]!;
    let ax = dy * ez - dz * ey,
      ay = dz * ex - dx * ez,
      az = dx * ey - dy * ex;
    const l = Math.hypot(ax, ay, az);
    if (l < 1e-9 * Math.hypot(dx, dy, dz) * Math.hypot(ex, ey, ez) || l === 0) continue;
    ax /= l;
    ay /= l;
    az /= l;
    if (ax * (P.v[a]! - P.cx) + ay * (P.v[a + 1]! - P.cy) + az * (P.v[a + 2]! - P.cz) < 0) {
      ax = -ax;
      ay = -ay;
      az = -az;
    }
    const s = ax * (p0x - P.v[a]!) + ay * (p0y - P.v[a + 1]!) + az * (p0z - P.v[a + 2]!) - r;
    if (s > edgeSep) {
      edgeSep = s;
      be = k;
    }
  }
  if (edgeSep > margin) return;
  if (be < 0 || edgeSep <= faceSep + 0.005 * r) {
    // Face contact: clip the segment to the face's side planes.
    const nx = P.fn[3 * bf]!,
      ny = P.fn[3 * bf + 1]!,
      nz = P.fn[3 * bf + 2]!;
    let t0 = 0,
      t1 = 1;
    for (let k = h.faceStart[bf]!, e = h.faceStart[bf + 1]!; k < e; k++) {
      const a = 3 * h.faceVertices[k]!,
        b = 3 * h.faceVertices[k + 1 < e ? k + 1 : h.faceStart[bf]!]!;
      const ex = P.v[b]! - P.v[a]!,
        ey = P.v[b + 1]! - P.v[a + 1]!,
        ez = P.v[b + 2]! - P.v[a + 2]!;
      const sx = ey * nz - ez * ny,
        sy = ez * nx - ex * nz,
        sz = ex * ny - ey * nx; // outward side normal e x n
      const f0 = sx * (p0x - P.v[a]!) + sy * (p0y - P.v[a + 1]!) + sz * (p0z - P.v[a + 2]!);
      const f1 = sx * (p1x - P.v[a]!) + sy * (p1y - P.v[a + 1]!) + sz * (p1z - P.v[a + 2]!);
      if (f0 > 0 && f1 > 0) {
        t0 = 1;
        t1 = 0;
        break;
      }
      if (f0 > 0) t0 = Math.max(t0, f0 / (f0 - f1));
      else if (f1 > 0) t1 = Math.min(t1, f0 / (f0 - f1));
    }
    if (t0 <= t1) {
      out.nx = -nx;
      out.ny = -ny;
      out.nz = -nz;
      for (const [t, id] of (t1 - t0 > 1e-9
        ? [
            [t0, 0],
            [t1, 1],
          ]
        : [[t0, 0]]) as Array<[number, number]>) {
        const x = p0x + dx * t,
          y = p0y + dy * t,
          z = p0z + dz * t;
        const s = nx * x + ny * y + nz * z - P.fd[bf]! - r;
        if (s <= margin) addPoint(out, x - nx * (r + s / 2), y - ny * (r + s / 2), z - nz * (r + s / 2), s, bf * 4 + id);
      }
      return;
    }
    if (be < 0) return;
  }
  // Edge contact: closest points of the segment and the edge.
  const a = 3 * E[be + EDGE_U]!,
    b = 3 * E[be + EDGE_V]!;
  closestSegmentParams(p0x, p0y, p0z, p1x, p1y, p1z, P.v[a]!, P.v[a + 1]!, P.v[a + 2]!, P.v[b]!, P.v[b + 1]!, P.v[b + 2]!);
  const s = st[0]!,
    t = st[1]!;
  const qx = p0x + dx * s,
    qy = p0y + dy * s,
    qz = p0z + dz * s;
  const ex = P.v[a]! + (P.v[b]! - P.v[a]!) * t,
    ey = P.v[a + 1]! + (P.v[b + 1]! - P.v[a + 1]!) * t,
    ez = P.v[a + 2]! + (P.v[b + 2]! - P.v[a + 2]!) * t;
  let nx = qx - ex,
    ny = qy - ey,
    nz = qz - ez;
  const d = Math.hypot(nx, ny, nz);
  if (d < 1e-12) return;
  nx /= d;
  ny /= d;
  nz /= d;
  const sep = d - r;
  if (sep > margin) return;
  out.nx = -nx;
  out.ny = -ny;
  out.nz = -nz;
  addPoint(out, ex + (nx * sep) / 2, ey + (ny * sep) / 2, ez + (nz * sep) / 2, sep, 10000 + be / EDGE_STRIDE);
}
