import type { ConvexGeometry } from './geometry-2d.js';

/**
 * Mass properties of a 2D shape of uniform areal density rho (kg/m^2): mass m = rho A, centroid c and
 * moment of inertia about the centroid (kg m^2).
 *
 * Every shape is a convex core inflated by a radius r (see shapes/geometry-2d.ts), and the inflated region
 * splits exactly into three parts, each with a textbook formula:
 * 1. the core polygon (n >= 3): a fan of triangles (O, v_i, v_i+1) about the origin O; each has
 *    area a = (v_i x v_i+1) / 2, centroid (v_i + v_i+1) / 3 and second moment about O
 *    rho a (|v_i|^2 + v_i . v_i+1 + |v_i+1|^2) / 6 (the polar moment of a triangle with a vertex at
 *    the origin; e.g. Eberly, "Polygonal Mass Properties", Geometric Tools, 2009);
 * 2. one rectangle of length L = |v_i+1 - v_i| and width r on the outside of each edge: mass rho L r,
 *    centroid at the edge midpoint + (r / 2) n_i, moment about its centroid m (L^2 + r^2) / 12;
 * 3. one circular sector of radius r at each vertex, spanning the turn theta_i between the normals of
 *    the edges meeting there (the sectors add up to one full disc): mass rho theta r^2 / 2, moment
 *    about the vertex m r^2 / 2, centroid on the bisector at 4 r sin(theta / 2) / (3 theta) from the
 *    vertex (the centroid of a circular sector; any table of centroids, e.g. Meriam and Kraige,
 *    Engineering Mechanics: Statics, appendix D).
 * Moments are moved between points with the parallel-axis theorem (Steiner): about a point P,
 * I_P = I_c + m |c - P|^2. A circle (n = 1) is one sector of 2 pi: m = rho pi r^2, I = m r^2 / 2; a
 * capsule (n = 2) is two rectangles of width r on either side of its segment (2r x L) and two
 * half discs; a box of w x h gives m (w^2 + h^2) / 12. The split is exact, so rounded boxes and
 * capsules need no approximation.
 * @category Shapes
 */
export interface MassProperties {
  /** Mass, kg. */
  mass: number;
  /** Centroid x in the shape's frame, m. */
  cx: number;
  /** Centroid y in the shape's frame, m. */
  cy: number;
  /** Moment of inertia about the centroid, kg m^2. */
  inertia: number;
  /** Area, m^2. */
  area: number;
}

/**
 * Mass, centroid and central moment of inertia of `g` at areal density `density` kg/m^2 (>= 0; 0
 * gives zero mass and inertia with the centroid of the area). Formulas in the module comment.
 * @category Shapes
 */
export function shapeMassProperties(g: ConvexGeometry, density: number): MassProperties {
  const n = g.count,
    r = g.radius;
  const vx = g.vx,
    vy = g.vy,
    nx = g.nx,
    ny = g.ny;
  // Accumulate area A, first moment (Sx, Sy) and polar second moment J about the origin, per unit density.
  let A = 0,
    Sx = 0,
    Sy = 0,
    J = 0;
  if (n >= 3) {
    for (let i = 0; i < n; i++) {
      const j = i + 1 < n ? i + 1 : 0;
      const x1 = vx[i]!,
        y1 = vy[i]!,
        x2 = vx[j]!,
        y2 = vy[j]!;
      const a = 0.5 * (x1 * y2 - x2 * y1);
      A += a;
      Sx += (a * (x1 + x2)) / 3;
      Sy += (a * (y1 + y2)) / 3;
      J += (a * (x1 * x1 + y1 * y1 + x1 * x2 + y1 * y2 + x2 * x2 + y2 * y2)) / 6;
    }
  }
  if (r > 0) {
    if (n >= 2) {
      for (let i = 0; i < n; i++) {
        const j = i + 1 < n ? i + 1 : 0;
        // Edge rectangle.
        const ex = vx[j]! - vx[i]!,
          ey = vy[j]! - vy[i]!;
        const L = Math.sqrt(ex * ex + ey * ey);
        const a = L * r;
        const cx = 0.5 * (vx[i]! + vx[j]!) + 0.5 * r * nx[i]!,
          cy = 0.5 * (vy[i]! + vy[j]!) + 0.5 * r * ny[i]!;
        A += a;
        Sx += a * cx;
        Sy += a * cy;
        J += (a * (L * L + r * r)) / 12 + a * (cx * cx + cy * cy);
        // Sector at vertex j, between the normals of edges i and j.
        const n1x = nx[i]!,
          n1y = ny[i]!,
          n2x = nx[j]!,
          n2y = ny[j]!;
        const theta = Math.atan2(n1x * n2y - n1y * n2x, n1x * n2x + n1y * n2y);
        const t = theta > 0 ? theta : theta + 2 * Math.PI; // a capsule's end turns by pi
        // The sector's bisector: n_i turned counter-clockwise by half the turn.
        const hc = Math.cos(0.5 * t),
          hs = Math.sin(0.5 * t);
        addSector(vx[j]!, vy[j]!, hc * n1x - hs * n1y, hs * n1x + hc * n1y, t, r);
      }
    } else {
      addSector(vx[0]!, vy[0]!, 1, 0, 2 * Math.PI, r);
    }
  }
  const mass = density * A;
  const cx = A > 0 ? Sx / A : vx[0]!,
    cy = A > 0 ? Sy / A : vy[0]!;
  const inertia = density * (J - A * (cx * cx + cy * cy));
  return { mass, cx, cy, inertia: inertia > 0 ? inertia : 0, area: A };

  function addSector(px: number, py: number, bx: number, by: number, theta: number, rad: number): void {
    // (bx, by): unit bisector of the sector.
    const a = 0.5 * theta * rad * rad;
    const d = (4 * rad * Math.sin(0.5 * theta)) / (3 * theta);
    const cx = px + d * bx,
      cy = py + d * by;
    A += a;
    Sx += a * cx;
    Sy += a * cy;
    // About the vertex: a r^2 / 2; moved to the origin through the centroid (Steiner twice).
    J += (a * rad * rad) / 2 - a * d * d + a * (cx * cx + cy * cy);
  }
}
