import type { Hull } from './hull-3d.js';

/**
 * Mass properties of 3D shapes of uniform density (kg/m^3): mass, centre of mass and the inertia
 * tensor about the centre of mass in the shape's own frame, and their combination into a body.
 *
 * Sources:
 * - box, sphere, cylinder: the standard table of moments (e.g. Goldstein, Classical Mechanics);
 * - capsule: a cylinder plus two hemispheres; a solid hemisphere's centroid lies 3 r / 8 from its flat
 *   face and its moment about a diameter of that face is 2 m r^2 / 5, moved to the capsule's centre by
 *   the parallel-axis theorem;
 * - convex hull: tetrahedral decomposition from the origin over the hull's outward triangles. For the
 *   tetrahedron (0, a, b, c) of signed volume V = a . (b x c) / 6, the centroid is (a + b + c) / 4 and
 *   the second moment is  int x x^T dV = V / 20 (a a^T + b b^T + c c^T + s s^T)  with s = a + b + c
 *   (Tonon, "Explicit exact formulas for the 3-D tetrahedron inertia tensor in terms of its vertex
 *   coordinates", J. Math. Stat. 1(1), 2004; Eberly, "Polyhedral Mass Properties (Revisited)", 2002);
 *   the inertia tensor is I = tr(C) E - C of the second moment C;
 * - several shapes: moments moved to the common centre of mass by the parallel-axis theorem,
 *   I = R I_local R^T + m (|d|^2 E - d d^T), then principal axes by cyclic Jacobi rotations (Golub
 *   and Van Loan, Matrix Computations, section 8.5).
 */

/**
 * Mass properties of one shape: mass (kg), centre of mass (m, shape frame) and inertia tensor about it (kg m^2, symmetric, row-major 3 x 3).
 * @category Shapes
 */
export interface MassProperties3D {
  mass: number;
  center: [number, number, number];
  inertia: Float64Array;
}

function diagonal(m: number, a: number, b: number, c: number): MassProperties3D {
  const I = new Float64Array(9);
  I[0] = a;
  I[4] = b;
  I[8] = c;
  return { mass: m, center: [0, 0, 0], inertia: I };
}

/**
 * A solid sphere of radius r: m = rho 4 pi r^3 / 3, I = 2 m r^2 / 5 about every axis.
 * @category Shapes
 */
export function sphereMass(density: number, r: number): MassProperties3D {
  const m = density * (4 / 3) * Math.PI * r * r * r;
  const i = 0.4 * m * r * r;
  return diagonal(m, i, i, i);
}

/**
 * A solid box of half extents (hx, hy, hz): m = 8 rho hx hy hz, I_x = m (hy^2 + hz^2) / 3 (edges 2h: m (b^2 + c^2) / 12), and so on.
 * @category Shapes
 */
export function boxMass(density: number, hx: number, hy: number, hz: number): MassProperties3D {
  const m = density * 8 * hx * hy * hz;
  return diagonal(m, (m * (hy * hy + hz * hz)) / 3, (m * (hx * hx + hz * hz)) / 3, (m * (hx * hx + hy * hy)) / 3);
}

/**
 * A solid cylinder of radius r and half height hh along y: m = rho pi r^2 2 hh, I_y = m r^2 / 2, I_x = I_z = m (3 r^2 + (2 hh)^2) / 12.
 * @category Shapes
 */
export function cylinderMass(density: number, r: number, hh: number): MassProperties3D {
  const m = density * Math.PI * r * r * 2 * hh;
  const side = (m * (3 * r * r + 4 * hh * hh)) / 12;
  return diagonal(m, side, 0.5 * m * r * r, side);
}

/**
 * A capsule along y: a cylinder of radius r and half height hh between two hemispheres of radius r.
 * I_y = m_c r^2 / 2 + 2 m_s r^2 / 5; I_x = I_z = m_c (3 r^2 + 4 hh^2) / 12 + m_s (2 r^2 / 5 + hh^2 + 3 hh r / 4),
 * with m_c the cylinder's mass and m_s the two hemispheres' (see the module's sources).
 * @category Shapes
 */
export function capsuleMass(density: number, r: number, hh: number): MassProperties3D {
  const mc = density * Math.PI * r * r * 2 * hh;
  const ms = density * (4 / 3) * Math.PI * r * r * r;
  const side = (mc * (3 * r * r + 4 * hh * hh)) / 12 + ms * (0.4 * r * r + hh * hh + 0.75 * hh * r);
  return diagonal(mc + ms, side, 0.5 * mc * r * r + 0.4 * ms * r * r, side);
}

/**
 * A convex hull by tetrahedral decomposition (see the module's sources). Its centre of mass is returned in the hull's frame.
 * @category Shapes
 */
export function hullMass(density: number, hull: Hull): MassProperties3D {
  const V = hull.vertices,
    T = hull.triangles;
  let vol = 0,
    cx = 0,
    cy = 0,
    cz = 0;
  const C = new Float64Array(9);
  // Origin of the decomposition: the vertex mean (inside a convex hull), for accuracy far from 0.
  let ox = 0,
    oy = 0,
    oz = 0;
  const nv = V.length / 3;
  for (let i = 0; i < nv; i++) {
    ox += V[3 * i]!;
    oy += V[3 * i + 1]!;
    oz += V[3 * i + 2]!;
  }
  ox /= nv;
  oy /= nv;
  oz /= nv;
  for (let t = 0; t < T.length; t += 3) {
    const a = 3 * T[t]!,
      b = 3 * T[t + 1]!,
      c = 3 * T[t + 2]!;
    const ax = V[a]! - ox,
      ay = V[a + 1]! - oy,
      az = V[a + 2]! - oz;
    const bx = V[b]! - ox,
      by = V[b + 1]! - oy,
      bz = V[b + 2]! - oz;
    const qx = V[c]! - ox,
      qy = V[c + 1]! - oy,
      qz = V[c + 2]! - oz;
    const v6 = ax * (by * qz - bz * qy) - ay * (bx * qz - bz * qx) + az * (bx * qy - by * qx);
    const v = v6 / 6;
    vol += v;
    const sx = ax + bx + qx,
      sy = ay + by + qy,
      sz = az + bz + qz;
    cx += (v * sx) / 4;
    cy += (v * sy) / 4;
    cz += (v * sz) / 4;
    const k = v / 20;
    const p = [ax, ay, az],
      q = [bx, by, bz],
      r = [qx, qy, qz],
      s = [sx, sy, sz];
    for (let i = 0; i < 3; i++)
      for (let j = 0; j < 3; j++) C[3 * i + j] = C[3 * i + j]! + k * (p[i]! * p[j]! + q[i]! * q[j]! + r[i]! * r[j]! + s[i]! * s[j]!);
  }
  const m = density * vol;
  const gx = cx / vol,
    gy = cy / vol,
    gz = cz / vol;
  // Second moment about the centroid (mass-weighted), then I = tr(C) E - C.
  const g = [gx, gy, gz];
  for (let i = 0; i < 9; i++) C[i] = density * C[i]!;
  for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) C[3 * i + j] = C[3 * i + j]! - m * g[i]! * g[j]!;
  const tr = C[0]! + C[4]! + C[8]!;
  const I = new Float64Array(9);
  for (let i = 0; i < 9; i++) I[i] = -C[i]!;
  I[0] = I[0]! + tr;
  I[4] = I[4]! + tr;
  I[8] = I[8]! + tr;
  return { mass: m, center: [gx + ox, gy + oy, gz + oz], inertia: I };
}

/**
 * Volume of a hull, m^3 (the tetrahedral decomposition's sum).
 * @category Shapes
 */
export function hullVolume(hull: Hull): number {
  return hullMass(1, hull).mass;
}

/**
 * Adds to `acc` (inertia about the origin of the body's frame, row-major 3 x 3) the tensor of a shape
 * of mass m whose own tensor about its centre is I_local, turned by the rotation matrix R (row-major)
 * and centred at d: R I_local R^T + m (|d|^2 E - d d^T) (parallel-axis theorem).
 * @category Shapes
 */
export function addMovedInertia(
  acc: Float64Array,
  m: number,
  local: Float64Array,
  R: Float64Array,
  dx: number,
  dy: number,
  dz: number,
): void {
  const d = [dx, dy, dz];
  const d2 = dx * dx + dy * dy + dz * dz;
  for (let i = 0; i < 3; i++) {
    for (let j = 0; j < 3; j++) {
      let s = 0;
      for (let k = 0; k < 3; k++) for (let l = 0; l < 3; l++) s += R[3 * i + k]! * local[3 * k + l]! * R[3 * j + l]!;
      acc[3 * i + j] = acc[3 * i + j]! + s + m * ((i === j ? d2 : 0) - d[i]! * d[j]!);
    }
  }
}

/**
 * Principal moments and axes of a symmetric 3 x 3 tensor A (row-major) by cyclic Jacobi rotations:
 * writes the eigenvalues into `values` and the axes as the columns of `axes` (row-major, a proper
 * rotation: det = +1), so A = axes diag(values) axes^T. A diagonal A gives the identity.
 * @category Shapes
 */
export function principalAxes(A: Float64Array, values: Float64Array, axes: Float64Array): void {
  const a = Float64Array.from(A);
  axes.fill(0);
  axes[0] = 1;
  axes[4] = 1;
  axes[8] = 1;
  for (let sweep = 0; sweep < 50; sweep++) {
    const off = a[1]! * a[1]! + a[2]! * a[2]! + a[5]! * a[5]!;
    const scale = a[0]! * a[0]! + a[4]! * a[4]! + a[8]! * a[8]!;
    if (off <= 1e-30 * scale || off === 0) break;
    for (const [p, q] of [
      [0, 1],
      [0, 2],
      [1, 2],
    ] as const) {
      const apq = a[3 * p + q]!;
      if (apq === 0) continue;
      const app = a[3 * p + p]!,
        aqq = a[3 * q + q]!;
      const theta = (aqq - app) / (2 * apq);
      const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
      const c = 1 / Math.sqrt(t * t + 1),
        s = t * c;
      // a <- J^T a J with J the rotation in the (p, q) plane.
      for (let k = 0; k < 3; k++) {
        const akp = a[3 * k + p]!,
          akq = a[3 * k + q]!;
        a[3 * k + p] = c * akp - s * akq;
        a[3 * k + q] = s * akp + c * akq;
      }
      for (let k = 0; k < 3; k++) {
        const apk = a[3 * p + k]!,
          aqk = a[3 * q + k]!;
        a[3 * p + k] = c * apk - s * aqk;
        a[3 * q + k] = s * apk + c * aqk;
      }
      for (let k = 0; k < 3; k++) {
        const vkp = axes[3 * k + p]!,
          vkq = axes[3 * k + q]!;
        axes[3 * k + p] = c * vkp - s * vkq;
        axes[3 * k + q] = s * vkp + c * vkq;
      }
    }
  }
  values[0] = a[0]!;
  values[1] = a[4]!;
  values[2] = a[8]!;
  const det =
    axes[0]! * (axes[4]! * axes[8]! - axes[5]! * axes[7]!) -
    axes[1]! * (axes[3]! * axes[8]! - axes[5]! * axes[6]!) +
    axes[2]! * (axes[3]! * axes[7]! - axes[4]! * axes[6]!);
  if (det < 0) {
    axes[2] = -axes[2]!;
    axes[5] = -axes[5]!;
    axes[8] = -axes[8]!;
  }
}
