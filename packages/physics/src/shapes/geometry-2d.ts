import { describe } from '../validation/validate.js';

/**
 * Convex shape geometry in 2D, shared by every shape kind: a shape is a convex core of 1 to 8
 * vertices inflated by a radius (the Minkowski sum of the core and a disc, Box2D v3's "rounded
 * polygon"):
 * - circle: 1 vertex (the centre) and radius r > 0;
 * - capsule: 2 vertices (the centres of its end caps) and radius r > 0;
 * - box and polygon: 3 to 8 vertices in counter-clockwise order, radius r >= 0 (rounded corners).
 * Outward unit normals are stored per edge (edge i runs from vertex i to vertex i + 1); a capsule's
 * two "edges" are its segment both ways, so its normals are opposite. One algorithm then serves
 * every pair (separating axes plus clipping; Ericson, Real-Time Collision Detection, ch. 5; Catto,
 * Box2D v3 manifold.c), and one mass formula every kind (see shapes/mass-2d.ts).
 */

/**
 * Shape kinds as stored in `Components.Shape.kind`.
 * @category Shapes
 */
export const ShapeKind = Object.freeze({ Circle: 0, Capsule: 1, Polygon: 2 } as const);

/**
 * Most vertices a polygon may have.
 * @category Shapes
 */
export const MAX_POLYGON_VERTICES = 8;

/**
 * A convex shape in its own frame (m): `count` vertices (x, y), `count` outward unit edge normals
 * (none meaningful for a circle), and the rounding radius.
 * @category Shapes
 */
export interface ConvexGeometry {
  /** ShapeKind: 0 circle, 1 capsule, 2 polygon. */
  kind: number;
  /** Vertices in use, 1 to 8. */
  count: number;
  /** Rounding radius, m (>= 0; > 0 for circles and capsules). */
  radius: number;
  /** Vertex x coordinates, m (8 slots). */
  vx: Float64Array;
  /** Vertex y coordinates, m (8 slots). */
  vy: Float64Array;
  /** Outward unit normal x of edge i (vertex i to i + 1). */
  nx: Float64Array;
  /** Outward unit normal y of edge i. */
  ny: Float64Array;
}

/**
 * An empty geometry with room for 8 vertices (reused scratch; no allocation per use).
 * @category Shapes
 */
export function createGeometry(): ConvexGeometry {
  const n = MAX_POLYGON_VERTICES;
  return {
    kind: 0,
    count: 0,
    radius: 0,
    vx: new Float64Array(n),
    vy: new Float64Array(n),
    nx: new Float64Array(n),
    ny: new Float64Array(n),
  };
}

/**
 * Fills the outward unit normals of edges i -> i + 1 of a counter-clockwise vertex loop (count >= 2).
 * A 2-vertex loop gets the right-hand normal of a -> b and its opposite.
 * @category Shapes
 */
export function computeNormals(g: ConvexGeometry): void {
  const n = g.count;
  if (n < 2) {
    g.nx[0] = 0;
    g.ny[0] = 1;
    return;
  }
  for (let i = 0; i < n; i++) {
    const j = i + 1 < n ? i + 1 : 0;
    const ex = g.vx[j]! - g.vx[i]!,
      ey = g.vy[j]! - g.vy[i]!;
    const len = Math.sqrt(ex * ex + ey * ey);
    g.nx[i] = ey / len;
    g.ny[i] = -ex / len;
  }
}

/**
 * A circle of `radius` m centred at (cx, cy). @throws RangeError naming `where` if radius <= 0.
 * @category Shapes
 */
export function makeCircle(where: string, radius: number, cx = 0, cy = 0): ConvexGeometry {
  if (!(radius > 0) || !Number.isFinite(radius)) throw new RangeError(`${where}: radius must be > 0, got ${describe(radius)}`);
  const g = createGeometry();
  g.kind = ShapeKind.Circle;
  g.count = 1;
  g.radius = radius;
  g.vx[0] = cx;
  g.vy[0] = cy;
  g.nx[0] = 0;
  g.ny[0] = 1;
  return g;
}

/**
 * A capsule: the segment from (x1, y1) to (x2, y2) (the end-cap centres, m) inflated by `radius` m.
 * @throws RangeError naming `where` if radius <= 0 or the centres coincide (use a circle then).
 * @category Shapes
 */
export function makeCapsule(where: string, x1: number, y1: number, x2: number, y2: number, radius: number): ConvexGeometry {
  if (!(radius > 0) || !Number.isFinite(radius)) throw new RangeError(`${where}: radius must be > 0, got ${describe(radius)}`);
  const len = Math.hypot(x2 - x1, y2 - y1);
  if (!(len > 1e-9 * Math.max(1, radius))) {
    throw new RangeError(
      `${where}: center1 and center2 must differ (a capsule needs a segment; use a circle), got ${describe([x1, y1])} and ${describe([x2, y2])}`,
    );
  }
  const g = createGeometry();
  g.kind = ShapeKind.Capsule;
  g.count = 2;
  g.radius = radius;
  g.vx[0] = x1;
  g.vy[0] = y1;
  g.vx[1] = x2;
  g.vy[1] = y2;
  computeNormals(g);
  return g;
}

/**
 * A box of half extents (hx, hy), m, centred at (cx, cy) and turned by `angle` rad, corners counter-
 * clockwise from the lower left, rounded by `radius` m (default 0).
 * @throws RangeError naming `where` if a half extent is not > 0 or radius < 0.
 * @category Shapes
 */
export function makeBox(where: string, hx: number, hy: number, cx = 0, cy = 0, angle = 0, radius = 0): ConvexGeometry {
  if (!(hx > 0) || !Number.isFinite(hx)) throw new RangeError(`${where}: halfExtents[0] must be > 0, got ${describe(hx)}`);
  if (!(hy > 0) || !Number.isFinite(hy)) throw new RangeError(`${where}: halfExtents[1] must be > 0, got ${describe(hy)}`);
  if (!(radius >= 0) || !Number.isFinite(radius)) throw new RangeError(`${where}: radius must be >= 0, got ${describe(radius)}`);
  const g = createGeometry();
  g.kind = ShapeKind.Polygon;
  g.count = 4;
  g.radius = radius;
  const c = Math.cos(angle),
    s = Math.sin(angle);
  const lx = [-hx, hx, hx, -hx],
    ly = [-hy, -hy, hy, hy];
  for (let i = 0; i < 4; i++) {
    g.vx[i] = cx + c * lx[i]! - s * ly[i]!;
    g.vy[i] = cy + s * lx[i]! + c * ly[i]!;
  }
  computeNormals(g);
  return g;
}

/**
 * A convex polygon from 3 to 8 vertices (m) given in either winding (clockwise input is reversed),
 * optionally rounded by `radius` m >= 0. Vertices are used as given: no hull is computed, so a
 * non-convex outline is an error rather than silently replaced.
 * @throws RangeError naming `where`, the parameter and the value on: fewer than 3 or more than 8
 *   vertices; a non-finite coordinate; two consecutive vertices closer than 1e-6 m (relative to the
 *   polygon's size); three collinear consecutive vertices or zero area; a reflex corner (not convex).
 * @category Shapes
 */
export function makePolygon(where: string, points: ArrayLike<ArrayLike<number>>, radius = 0): ConvexGeometry {
  const n = points.length;
  if (!(n >= 3 && n <= MAX_POLYGON_VERTICES)) {
    throw new RangeError(`${where}: vertices must hold 3 to ${MAX_POLYGON_VERTICES} points, got ${n}`);
  }
  if (!(radius >= 0) || !Number.isFinite(radius)) throw new RangeError(`${where}: radius must be >= 0, got ${describe(radius)}`);
  const xs: number[] = [],
    ys: number[] = [];
  let size = 0;
  for (let i = 0; i < n; i++) {
    const p = points[i]!;
    if (p?.length !== 2 || !Number.isFinite(p[0]) || !Number.isFinite(p[1])) {
      throw new RangeError(`${where}: vertices[${i}] must be a point [x, y] of finite numbers, got ${describe(p)}`);
    }
    xs.push(p[0]!);
    ys.push(p[1]!);
    size = Math.max(size, Math.abs(p[0]!), Math.abs(p[1]!));
  }
  // Shoelace formula: twice the signed area; its sign is the winding.
  let area2 = 0;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    area2 += xs[i]! * ys[j]! - xs[j]! * ys[i]!;
  }
  if (area2 < 0) {
    xs.reverse();
    ys.reverse();
    area2 = -area2;
  }
  const tol = 1e-6 * Math.max(1, size);
  if (!(area2 > tol * tol)) throw new RangeError(`${where}: vertices must enclose a non-zero area, got ${describe(points)}`);
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    if (Math.hypot(xs[j]! - xs[i]!, ys[j]! - ys[i]!) < tol) {
      throw new RangeError(`${where}: vertices must be distinct, got two at ${describe([xs[i], ys[i]])} (in ${describe(points)})`);
    }
  }
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n,
      k = (i + 2) % n;
    const ex = xs[j]! - xs[i]!,
      ey = ys[j]! - ys[i]!;
    const fx = xs[k]! - xs[j]!,
      fy = ys[k]! - ys[j]!;
    const cross = ex * fy - ey * fx;
    if (!(cross > tol * Math.hypot(ex, ey))) {
      const what = Math.abs(cross) <= tol * Math.hypot(ex, ey) ? 'has three collinear vertices' : 'is not convex';
      throw new RangeError(
        `${where}: vertices must form a convex polygon, got one that ${what} at ${describe([xs[j], ys[j]])} (in ${describe(points)})`,
      );
    }
  }
  const g = createGeometry();
  g.kind = ShapeKind.Polygon;
  g.count = n;
  g.radius = radius;
  for (let i = 0; i < n; i++) {
    g.vx[i] = xs[i]!;
    g.vy[i] = ys[i]!;
  }
  computeNormals(g);
  return g;
}

/**
 * Turns `g` by `angle` rad about the origin, then moves it by (dx, dy), in place (vertices and normals).
 * @category Shapes
 */
export function transformGeometry(g: ConvexGeometry, dx: number, dy: number, angle: number): void {
  const c = Math.cos(angle),
    s = Math.sin(angle);
  for (let i = 0; i < g.count; i++) {
    const x = g.vx[i]!,
      y = g.vy[i]!;
    g.vx[i] = dx + c * x - s * y;
    g.vy[i] = dy + s * x + c * y;
    const nx = g.nx[i]!,
      ny = g.ny[i]!;
    g.nx[i] = c * nx - s * ny;
    g.ny[i] = s * nx + c * ny;
  }
}
