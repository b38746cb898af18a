import type { Hull } from '../../shapes/hull-3d.js';

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
 *
 * This file holds the shapes and the manifold; the pairs are in collide-3d.ts (entry points),
 * polyhedra-3d.ts, round-polyhedron-3d.ts, segments-3d.ts and box-box-3d.ts, the reduction to four
 * points in candidates-3d.ts.
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

export function flip(m: Manifold3D): void {
  m.nx = -m.nx;
  m.ny = -m.ny;
  m.nz = -m.nz;
}

export function addPoint(m: Manifold3D, x: number, y: number, z: number, s: number, id: number): void {
  if (m.count >= 4) return;
  const k = m.count++;
  m.x[k] = x;
  m.y[k] = y;
  m.z[k] = z;
  m.sep[k] = s;
  m.id[k] = id;
}
