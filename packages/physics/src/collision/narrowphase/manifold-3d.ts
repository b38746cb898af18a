import type { Hull } from '../../shapes/hull-3d.js';
import { boxBox3D, planeBox3D } from './box-box-3d.js';

/**
 * Narrowphase of 3D shapes: contact manifolds of up to four points with feature ids, in world
 * coordinates, for the pairs sphere, capsule and convex polyhedron (box, hull, and cylinder as its
 * hull) against each other and against a plane.
 *
 * - polyhedron-polyhedron: separating axes (the faces of both, and the edge pairs that form a face of
 *   the Minkowski difference, found on the Gauss map: Gregorius, "The Separating Axis Test between
 *   Convex Polyhedra", GDC 2013), then face clipping (Sutherland-Hodgman) of the incident face
 *   against the reference face's side planes, or the closest points of the two edges; faces are
 *   preferred over edges unless an edge axis separates more by 5 % of the tolerance (Box2D's and
 *   Bullet's bias), which keeps a resting box on its four corners;
 * - reduced to four points: the deepest (the first of those within 0.5 % of the margin of it), the
 *   farthest from it, then the two that span the largest areas on either side (Gregorius, "Robust
 *   Contact Creation for Physics Simulations", GDC 2015);
 * - sphere and capsule: closest points to the polyhedron's faces and edges, or between segments;
 *   a capsule against a face keeps both ends (the segment clipped to the face) so it lies still.
 *
 * The normal points from A to B; separation < 0 is overlap; each point is midway between the two
 * surfaces. Pairs farther apart than `margin` (the speculative distance) return no points.
 * A feature id names the features that made a point (reference and incident face, clipped edge, or
 * vertex), so the solver warm-starts a point from the previous step's point with the same id.
 */

/**
 * A shape posed in the world for the narrowphase.
 * @category Collision
 */
export interface Collider3D {
  /** 0 sphere, 1 capsule (segment along the shape's y with half length `hy`), 2 polyhedron (`hull`). */
  kind: number;
  /** Centre, m (world). */
  px: number;
  py: number;
  pz: number;
  /** Rotation of the shape frame into the world, row-major 3 x 3. */
  R: Float64Array;
  radius: number;
  /** Capsule: half length of the segment; box: half extent along y (m). */
  hy: number;
  hull: Hull | null;
  /** 1: a box (a polyhedron with half extents hx, hy, hz, m, collided by collision/narrowphase/box-box-3d.ts); 0 otherwise. */
  box: number;
  hx: number;
  hz: number;
}

/**
 * A manifold: up to four points sharing a normal (unit, A to B).
 * @category Collision
 */
export interface Manifold3D {
  count: number;
  nx: number;
  ny: number;
  nz: number;
  /** Contact points, m (world, midway between the surfaces). */
  x: Float64Array;
  y: Float64Array;
  z: Float64Array;
  /** Separation, m (< 0: overlap). */
  sep: Float64Array;
  /** Feature ids (integers, stable while the same features touch). */
  id: Float64Array;
}

/**
 * A manifold with room for four points.
 * @category Collision
 */
export function createManifold3D(): Manifold3D {
  return {
    count: 0,
    nx: 0,
    ny: 1,
    nz: 0,
    x: new Float64Array(4),
    y: new Float64Array(4),
    z: new Float64Array(4),
    sep: new Float64Array(4),
    id: new Float64Array(4),
  };
}

export const ColliderKind3D = Object.freeze({ Sphere: 0, Capsule: 1, Polyhedron: 2 } as const);

// ---------------------------------------------------------------------------------------------------
// Posed polyhedra (scratch, reused).

interface Posed {
  n: number;
  v: Float64Array;
  fn: Float64Array;
  fd: Float64Array;
  cx: number;
  cy: number;
  cz: number;
  hull: Hull;
}
const posedA: Posed = {
  n: 0,
  v: new Float64Array(192),
  fn: new Float64Array(3 * 130),
  fd: new Float64Array(130),
  cx: 0,
  cy: 0,
  cz: 0,
  hull: null as unknown as Hull,
};
const posedB: Posed = {
  n: 0,
  v: new Float64Array(192),
  fn: new Float64Array(3 * 130),
  fd: new Float64Array(130),
  cx: 0,
  cy: 0,
  cz: 0,
  hull: null as unknown as Hull,
};

function pose(c: Collider3D, out: Posed): Posed {
  const h = c.hull!,
    R = c.R,
    V = h.vertices,
    nv = V.length / 3;
  if (out.fn.length < h.faceNormals.length) {
    out.fn = new Float64Array(h.faceNormals.length);
    out.fd = new Float64Array(h.faceOffsets.length);
  }
  out.hull = h;
  out.n = nv;
  let sx = 0,
    sy = 0,
    sz = 0;
  for (let i = 0; i < nv; i++) {
    const x = V[3 * i]!,
      y = V[3 * i + 1]!,
      z = V[3 * i + 2]!;
    const wx = c.px + R[0]! * x + R[1]! * y + R[2]! * z,
      wy = c.py + R[3]! * x + R[4]! * y + R[5]! * z,
      wz = c.pz + R[6]! * x + R[7]! * y + R[8]! * z;
    out.v[3 * i] = wx;
    out.v[3 * i + 1] = wy;
    out.v[3 * i + 2] = wz;
    sx += wx;
    sy += wy;
    sz += wz;
  }
  out.cx = sx / nv;
  out.cy = sy / nv;
  out.cz = sz / nv;
  const F = h.faceNormals,
    nf = h.faceOffsets.length;
  for (let f = 0; f < nf; f++) {
    const x = F[3 * f]!,
      y = F[3 * f + 1]!,
      z = F[3 * f + 2]!;
    const wx = R[0]! * x + R[1]! * y + R[2]! * z,
      wy = R[3]! * x + R[4]! * y + R[5]! * z,
      wz = R[6]! * x + R[7]! * y + R[8]! * z;
    out.fn[3 * f] = wx;
    out.fn[3 * f + 1] = wy;
    out.fn[3 * f + 2] = wz;
    const a = 3 * h.faceVertices[h.faceStart[f]!]!;
    out.fd[f] = wx * out.v[a]! + wy * out.v[a + 1]! + wz * out.v[a + 2]!;
  }
  return out;
}

// ---------------------------------------------------------------------------------------------------
// Entry points.

/**
 * The manifold of A against B (normal A to B), or count 0 when they are farther apart than `margin`.
 * @category Collision
 */
export function collide3D(A: Collider3D, B: Collider3D, margin: number, out: Manifold3D): void {
  out.count = 0;
  if (A.kind > B.kind) {
    collide3D(B, A, margin, out);
    flip(out);
    return;
  }
  if (A.kind === ColliderKind3D.Sphere) {
    if (B.kind === ColliderKind3D.Polyhedron) spherePolyhedron(A, pose(B, posedB), margin, out, false);
    else segmentSegment(A, B, margin, out);
  } else if (A.kind === ColliderKind3D.Capsule) {
    if (B.kind === ColliderKind3D.Polyhedron) capsulePolyhedron(A, pose(B, posedB), margin, out);
    else segmentSegment(A, B, margin, out);
  } else if (A.box === 1 && B.box === 1) {
    boxBox3D(A.px, A.py, A.pz, A.R, 0, A.hx, A.hy, A.hz, B.px, B.py, B.pz, B.R, 0, B.hx, B.hy, B.hz, margin, out);
  } else {
    polyhedra(pose(A, posedA), pose(B, posedB), margin, out);
  }
}

/**
 * The manifold of a plane n . x = d (A, solid below) against shape B (normal = the plane's).
 * @category Collision
 */
export function collidePlane3D(nx: number, ny: number, nz: number, d: number, B: Collider3D, margin: number, out: Manifold3D): void {
  out.count = 0;
  out.nx = nx;
  out.ny = ny;
  out.nz = nz;
  const push = (x: number, y: number, z: number, r: number, id: number): void => {
    const s = nx * x + ny * y + nz * z - d - r;
    if (s > margin) return;
    addPoint(out, x - nx * (r + s / 2), y - ny * (r + s / 2), z - nz * (r + s / 2), s, id);
  };
  if (B.kind === ColliderKind3D.Polyhedron && B.box === 1) {
    planeBox3D(nx, ny, nz, d, B.px, B.py, B.pz, B.R, 0, B.hx, B.hy, B.hz, margin, out);
    return;
  }
  if (B.kind === ColliderKind3D.Polyhedron) {
    const P = pose(B, posedB);
    for (let i = 0; i < P.n; i++)
      pushCandidate(
        nx * P.v[3 * i]! + ny * P.v[3 * i + 1]! + nz * P.v[3 * i + 2]! - d,
        P.v[3 * i]!,
        P.v[3 * i + 1]!,
        P.v[3 * i + 2]!,
        i,
        margin,
        nx,
        ny,
        nz,
      );
    finishCandidates(out, nx, ny, nz, margin);
    return;
  }
  if (B.kind === ColliderKind3D.Sphere) {
    push(B.px, B.py, B.pz, B.radius, 0);
    return;
  }
  const ax = B.R[1]! * B.hy,
    ay = B.R[4]! * B.hy,
    az = B.R[7]! * B.hy;
  push(B.px - ax, B.py - ay, B.pz - az, B.radius, 0);
  push(B.px + ax, B.py + ay, B.pz + az, B.radius, 1);
}

function flip(m: Manifold3D): void {
  m.nx = -m.nx;
  m.ny = -m.ny;
  m.nz = -m.nz;
}

function addPoint(m: Manifold3D, x: number, y: number, z: number, s: number, id: number): void {
  if (m.count >= 4) return;
  const k = m.count++;
  m.x[k] = x;
  m.y[k] = y;
  m.z[k] = z;
  m.sep[k] = s;
  m.id[k] = id;
}

// Candidate points before the reduction to four (scratch).
const CAND = 160;
const cx = new Float64Array(CAND),
  cy = new Float64Array(CAND),
  cz = new Float64Array(CAND),
  cs = new Float64Array(CAND),
  cid = new Float64Array(CAND);
let cn = 0;

/** Adds a candidate on the incident surface at (x, y, z) with separation s, if s <= margin; its midpoint goes back along -n by s / 2. */
function pushCandidate(s: number, x: number, y: number, z: number, id: number, margin: number, nx: number, ny: number, nz: number): void {
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
function finishCandidates(out: Manifold3D, nx: number, ny: number, nz: number, margin: number): void {
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
  // points without warm start (issue 9: the cube dropped ~5 um and was kicked at ~5.6e-5 m/s).
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

// ---------------------------------------------------------------------------------------------------
// Spheres and capsules (segments with a radius; a sphere is a segment of length 0).

const seg = new Float64Array(12);

/** Writes the segment of a sphere or capsule into seg[o..o+5]. */
function segmentOf(c: Collider3D, o: number): void {
  const h = c.kind === ColliderKind3D.Capsule ? c.hy : 0;
  const ax = c.R[1]! * h,
    ay = c.R[4]! * h,
    az = c.R[7]! * h;
  seg[o] = c.px - ax;
  seg[o + 1] = c.py - ay;
  seg[o + 2] = c.pz - az;
  seg[o + 3] = c.px + ax;
  seg[o + 4] = c.py + ay;
  seg[o + 5] = c.pz + az;
}

const st = new Float64Array(2);

/** Parameters (s, t) in [0, 1] of the closest points of segments P0 P1 and Q0 Q1 (Ericson, Real-Time Collision Detection, 5.1.9). */
function closestSegmentParams(
  p0x: number,
  p0y: number,
  p0z: number,
  p1x: number,
  p1y: number,
  p1z: number,
  q0x: number,
  q0y: number,
  q0z: number,
  q1x: number,
  q1y: number,
  q1z: number,
): void {
  const d1x = p1x - p0x,
    d1y = p1y - p0y,
    d1z = p1z - p0z,
    d2x = q1x - q0x,
    d2y = q1y - q0y,
    d2z = q1z - q0z;
  const rx = p0x - q0x,
    ry = p0y - q0y,
    rz = p0z - q0z;
  const a = d1x * d1x + d1y * d1y + d1z * d1z,
    e = d2x * d2x + d2y * d2y + d2z * d2z,
    f = d2x * rx + d2y * ry + d2z * rz;
  let s = 0,
    t = 0;
  if (a <= 1e-24 && e <= 1e-24) {
    st[0] = 0;
    st[1] = 0;
    return;
  }
  if (a <= 1e-24) {
    t = clamp01(f / e);
  } else {
    const c = d1x * rx + d1y * ry + d1z * rz;
    if (e <= 1e-24) {
      s = clamp01(-c / a);
    } else {
      const b = d1x * d2x + d1y * d2y + d1z * d2z,
        den = a * e - b * b;
      s = den > 1e-12 * a * e ? clamp01((b * f - c * e) / den) : 0.5;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = clamp01(-c / a);
      } else if (t > 1) {
        t = 1;
        s = clamp01((b - c) / a);
      }
    }
  }
  st[0] = s;
  st[1] = t;
}

function clamp01(x: number): number {
  return x < 0 ? 0 : x > 1 ? 1 : x;
}

/** Sphere or capsule A against sphere or capsule B: one point, or two for capsules lying side by side. */
function segmentSegment(A: Collider3D, B: Collider3D, margin: number, out: Manifold3D): void {
  segmentOf(A, 0);
  segmentOf(B, 6);
  const r = A.radius + B.radius;
  closestSegmentParams(seg[0]!, seg[1]!, seg[2]!, seg[3]!, seg[4]!, seg[5]!, seg[6]!, seg[7]!, seg[8]!, seg[9]!, seg[10]!, seg[11]!);
  const s = st[0]!,
    t = st[1]!;
  const ax = seg[0]! + (seg[3]! - seg[0]!) * s,
    ay = seg[1]! + (seg[4]! - seg[1]!) * s,
    az = seg[2]! + (seg[5]! - seg[2]!) * s;
  const bx = seg[6]! + (seg[9]! - seg[6]!) * t,
    by = seg[7]! + (seg[10]! - seg[7]!) * t,
    bz = seg[8]! + (seg[11]! - seg[8]!) * t;
  let nx = bx - ax,
    ny = by - ay,
    nz = bz - az;
  const dist = Math.sqrt(nx * nx + ny * ny + nz * nz);
  if (dist - r > margin) return;
  if (dist > 1e-12) {
    nx /= dist;
    ny /= dist;
    nz /= dist;
  } else {
    nx = 0;
    ny = 1;
    nz = 0;
  }
  out.nx = nx;
  out.ny = ny;
  out.nz = nz;
  // Two capsules nearly parallel: both ends of the overlap of A's segment projected onto B's line.
  const ux = seg[3]! - seg[0]!,
    uy = seg[4]! - seg[1]!,
    uz = seg[5]! - seg[2]!;
  const vx = seg[9]! - seg[6]!,
    vy = seg[10]! - seg[7]!,
    vz = seg[11]! - seg[8]!;
  const lu = Math.hypot(ux, uy, uz),
    lv = Math.hypot(vx, vy, vz);
  if (lu > 0 && lv > 0 && Math.abs(ux * vx + uy * vy + uz * vz) > 0.995 * lu * lv) {
    let t0 = ((seg[0]! - seg[6]!) * vx + (seg[1]! - seg[7]!) * vy + (seg[2]! - seg[8]!) * vz) / (lv * lv);
    let t1 = ((seg[3]! - seg[6]!) * vx + (seg[4]! - seg[7]!) * vy + (seg[5]! - seg[8]!) * vz) / (lv * lv);
    if (t0 > t1) {
      const x = t0;
      t0 = t1;
      t1 = x;
    }
    t0 = clamp01(t0);
    t1 = clamp01(t1);
    if (t1 - t0 > 1e-3) {
      for (const [tt, id] of [
        [t0, 2],
        [t1, 3],
      ] as const) {
        const qx = seg[6]! + vx * tt,
          qy = seg[7]! + vy * tt,
          qz = seg[8]! + vz * tt;
        // The closest point on A's segment to q.
        const ss = clamp01(((qx - seg[0]!) * ux + (qy - seg[1]!) * uy + (qz - seg[2]!) * uz) / (lu * lu));
        const px = seg[0]! + ux * ss,
          py = seg[1]! + uy * ss,
          pz = seg[2]! + uz * ss;
        const sep = (qx - px) * nx + (qy - py) * ny + (qz - pz) * nz - r;
        if (sep <= margin)
          addPoint(
            out,
            (px + qx) / 2 + (nx * (A.radius - B.radius)) / 2,
            (py + qy) / 2 + (ny * (A.radius - B.radius)) / 2,
            (pz + qz) / 2 + (nz * (A.radius - B.radius)) / 2,
            sep,
            id,
          );
      }
      if (out.count === 2) return;
      out.count = 0;
    }
  }
  const sep = dist - r;
  addPoint(
    out,
    (ax + bx) / 2 + (nx * (A.radius - B.radius)) / 2,
    (ay + by) / 2 + (ny * (A.radius - B.radius)) / 2,
    (az + bz) / 2 + (nz * (A.radius - B.radius)) / 2,
    sep,
    0,
  );
}

/** Sphere A against polyhedron P (normal A to P; `fromPoly` true: P is A). */
function spherePolyhedron(S: Collider3D, P: Posed, margin: number, out: Manifold3D, fromPoly: boolean): void {
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
    for (let k = 0; k < E.length; k += 4) {
      const a = 3 * E[k]!,
        b = 3 * E[k + 1]!;
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
        id = 1000 + (t === 0 ? 2000 + E[k]! : t === 1 ? 2000 + E[k + 1]! : k / 4);
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
function capsulePolyhedron(C: Collider3D, P: Posed, margin: number, out: Manifold3D): void {
  segmentOf(C, 0);
  const h = P.hull,
    nf = h.faceOffsets.length,
    r = C.radius;
  const p0x = seg[0]!,
    p0y = seg[1]!,
    p0z = seg[2]!,
    p1x = seg[3]!,
    p1y = seg[4]!,
    p1z = seg[5]!;
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
  for (let k = 0; k < E.length; k += 4) {
    const n1 = 3 * E[k + 2]!,
      n2 = 3 * E[k + 3]!;
    const d1 = P.fn[n1]! * dx + P.fn[n1 + 1]! * dy + P.fn[n1 + 2]! * dz,
      d2 = P.fn[n2]! * dx + P.fn[n2 + 1]! * dy + P.fn[n2 + 2]! * dz;
    if (d1 * d2 >= 0) continue; // not a face of the Minkowski difference
    const a = 3 * E[k]!,
      b = 3 * E[k + 1]!;
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
  const a = 3 * E[be]!,
    b = 3 * E[be + 1]!;
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
  addPoint(out, ex + (nx * sep) / 2, ey + (ny * sep) / 2, ez + (nz * sep) / 2, sep, 10000 + be / 4);
}

// ---------------------------------------------------------------------------------------------------
// Polyhedra.

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
function polyhedra(A: Posed, B: Posed, margin: number, out: Manifold3D): void {
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
  for (let i = 0; i < EA.length; i += 4) {
    const a1 = 3 * EA[i + 2]!,
      a2 = 3 * EA[i + 3]!;
    const ax = A.fn[a1]!,
      ay = A.fn[a1 + 1]!,
      az = A.fn[a1 + 2]!,
      bx = A.fn[a2]!,
      by = A.fn[a2 + 1]!,
      bz = A.fn[a2 + 2]!;
    const u = 3 * EA[i]!,
      v = 3 * EA[i + 1]!;
    const e1x = A.v[v]! - A.v[u]!,
      e1y = A.v[v + 1]! - A.v[u + 1]!,
      e1z = A.v[v + 2]! - A.v[u + 2]!;
    for (let j = 0; j < EB.length; j += 4) {
      const b1 = 3 * EB[j + 2]!,
        b2 = 3 * EB[j + 3]!;
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
      const p = 3 * EB[j]!,
        q = 3 * EB[j + 1]!;
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
    const u = 3 * EA[ea]!,
      v = 3 * EA[ea + 1]!,
      p = 3 * EB[eb]!,
      q = 3 * EB[eb + 1]!;
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
    addPoint(out, x, y, z, se, 2 ** 40 + (ea / 4) * 4096 + eb / 4);
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
