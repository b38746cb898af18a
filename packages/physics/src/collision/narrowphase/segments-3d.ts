import { addPoint, type Collider3D, ColliderKind3D, type Manifold3D } from './manifold-3d.js';

/** Segments of spheres and capsules in the 3D narrowphase: their closest points (Ericson, Real-Time Collision Detection, 5.1.9) and the sphere and capsule pairs. */

export const seg = new Float64Array(12);

/** Writes the segment of a sphere or capsule into seg[o..o+5]. */
export function segmentOf(c: Collider3D, o: number): void {
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

export function clamp01(x: number): number {
  return x < 0 ? 0 : x > 1 ? 1 : x;
}

/** Sphere or capsule A against sphere or capsule B: one point, or two for capsules lying side by side. */
export function segmentSegment(A: Collider3D, B: Collider3D, margin: number, out: Manifold3D): void {
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
