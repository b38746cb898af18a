import { M01, M11, M21 } from '../../math/mat3-layout.js';
import { addPoint, type Collider3D, ColliderKind3D, type Manifold3D } from './manifold-3d.js';
import { SEG_P0X, SEG_P0Y, SEG_P0Z, SEG_P1X, SEG_P1Y, SEG_P1Z, SEG_STRIDE } from './segment-layout-3d.js';

/** Segments of spheres and capsules in the 3D narrowphase: their closest points (Ericson, Real-Time Collision Detection, 5.1.9) and the sphere and capsule pairs. */

/** Two segments (collision/narrowphase/segment-layout-3d.ts), at 0 and at SEG_STRIDE. */
export const seg = new Float64Array(2 * SEG_STRIDE);

/** Writes the segment of a sphere or capsule into seg at o. */
export function segmentOf(c: Collider3D, o: number): void {
  const h = c.kind === ColliderKind3D.Capsule ? c.hy : 0;
  // The capsule's axis is its shape y axis, the rotation's column 1.
  const ax = c.R[M01]! * h,
    ay = c.R[M11]! * h,
    az = c.R[M21]! * h;
  seg[o + SEG_P0X] = c.px - ax;
  seg[o + SEG_P0Y] = c.py - ay;
  seg[o + SEG_P0Z] = c.pz - az;
  seg[o + SEG_P1X] = c.px + ax;
  seg[o + SEG_P1Y] = c.py + ay;
  seg[o + SEG_P1Z] = c.pz + az;
}

export const st = new Float64Array(2);

/** Parameters (s, t) in [0, 1] of the closest points of segments P0 P1 and Q0 Q1 (Ericson, Real-Time Collision Detection, 5.1.9). */
export function closestSegmentParams(
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
  closestFractions(
    d1x * d1x + d1y * d1y + d1z * d1z,
    d1x * d2x + d1y * d2y + d1z * d2z,
    d1x * rx + d1y * ry + d1z * rz,
    d2x * d2x + d2y * d2y + d2z * d2z,
    d2x * rx + d2y * ry + d2z * rz,
    1e-24,
    1e-12,
    0.5,
    st,
  );
}

/**
 * Fractions (s, t) in [0, 1] of the closest points p1 + s d1 and p2 + t d2 of two segments in any
 * dimension, from the dot products a = d1.d1, b = d1.d2, c = d1.r, e = d2.d2, f = d2.r with
 * r = p1 - p2 (Ericson, Real-Time Collision Detection, 5.1.9), written to out[0..1]. A segment with
 * a squared length <= `small` (m^2) is a point; segments are parallel when a e - b^2 <= `parallel` a e
 * (a relative tolerance, >= 0), and then s is `parallelS` before t is clamped.
 */
export function closestFractions(
  a: number,
  b: number,
  c: number,
  e: number,
  f: number,
  small: number,
  parallel: number,
  parallelS: number,
  out: Float64Array,
): void {
  let s = 0,
    t = 0;
  if (a <= small && e <= small) {
    out[0] = 0;
    out[1] = 0;
    return;
  }
  if (a <= small) {
    t = clamp01(f / e);
  } else if (e <= small) {
    s = clamp01(-c / a);
  } else {
    const den = a * e - b * b;
    s = den > parallel * a * e ? clamp01((b * f - c * e) / den) : parallelS;
    t = (b * s + f) / e;
    if (t < 0) {
      t = 0;
      s = clamp01(-c / a);
    } else if (t > 1) {
      t = 1;
      s = clamp01((b - c) / a);
    }
  }
  out[0] = s;
  out[1] = t;
}

/** `x` clamped to [0, 1] (a segment parameter; NaN stays NaN). Shared with the 2D segment pair (manifold-2d.ts). */
export function clamp01(x: number): number {
  return x < 0 ? 0 : x > 1 ? 1 : x;
}

/** Sphere or capsule A against sphere or capsule B: one point, or two for capsules lying side by side. */
export function segmentSegment(A: Collider3D, B: Collider3D, margin: number, out: Manifold3D): void {
  segmentOf(A, 0);
  segmentOf(B, SEG_STRIDE);
  const b = SEG_STRIDE;
  const a0x = seg[SEG_P0X]!,
    a0y = seg[SEG_P0Y]!,
    a0z = seg[SEG_P0Z]!,
    a1x = seg[SEG_P1X]!,
    a1y = seg[SEG_P1Y]!,
    a1z = seg[SEG_P1Z]!;
  const b0x = seg[b + SEG_P0X]!,
    b0y = seg[b + SEG_P0Y]!,
    b0z = seg[b + SEG_P0Z]!,
    b1x = seg[b + SEG_P1X]!,
    b1y = seg[b + SEG_P1Y]!,
    b1z = seg[b + SEG_P1Z]!;
  const r = A.radius + B.radius;
  closestSegmentParams(a0x, a0y, a0z, a1x, a1y, a1z, b0x, b0y, b0z, b1x, b1y, b1z);
  const s = st[0]!,
    t = st[1]!;
  const ax = a0x + (a1x - a0x) * s,
    ay = a0y + (a1y - a0y) * s,
    az = a0z + (a1z - a0z) * s;
  const bx = b0x + (b1x - b0x) * t,
    by = b0y + (b1y - b0y) * t,
    bz = b0z + (b1z - b0z) * t;
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
  const ux = a1x - a0x,
    uy = a1y - a0y,
    uz = a1z - a0z;
  const vx = b1x - b0x,
    vy = b1y - b0y,
    vz = b1z - b0z;
  const lu = Math.hypot(ux, uy, uz),
    lv = Math.hypot(vx, vy, vz);
  if (lu > 0 && lv > 0 && Math.abs(ux * vx + uy * vy + uz * vz) > 0.995 * lu * lv) {
    let t0 = ((a0x - b0x) * vx + (a0y - b0y) * vy + (a0z - b0z) * vz) / (lv * lv);
    let t1 = ((a1x - b0x) * vx + (a1y - b0y) * vy + (a1z - b0z) * vz) / (lv * lv);
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
        const qx = b0x + vx * tt,
          qy = b0y + vy * tt,
          qz = b0z + vz * tt;
        // The closest point on A's segment to q.
        const ss = clamp01(((qx - a0x) * ux + (qy - a0y) * uy + (qz - a0z) * uz) / (lu * lu));
        const px = a0x + ux * ss,
          py = a0y + uy * ss,
          pz = a0z + uz * ss;
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
