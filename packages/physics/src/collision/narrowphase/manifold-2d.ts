import { type ConvexGeometry, createGeometry } from '../../shapes/geometry-2d.js';
import { widenToDoubles } from '../../world/double-fields.js';
import { markWritable } from '../../world/writable-fields.js';
import { closestFractions } from './segments-3d.js';

/**
 * Contact manifolds of 2D convex shapes: pure functions, no world. A manifold is the contact between
 * two shapes: one unit normal from shape A to shape B and up to two points, each with its
 * separation (m, negative when overlapping) and a feature id that names the pair of features (vertex
 * or edge of A, of B) the point comes from, so the solver can match a point with last step's and warm
 * start it. The points lie midway between the two surfaces.
 *
 * Algorithms (one for every pair of rounded polygons, plus closed forms for round shapes):
 * - polygon-polygon, capsule-polygon, capsule-capsule, and segments against any of them: the
 *   separating-axis test over both shapes' edge normals picks the reference face (of the shape with
 *   the larger separation, preferring A within a small tolerance so the choice does not flicker); the
 *   incident edge of the other shape is the one most anti-parallel to it; the incident edge is
 *   clipped to the reference face's side planes, giving up to two points (Gottschalk's SAT;
 *   Ericson, Real-Time Collision Detection, 2005, 4.4 and 5.2; Catto, "Contact Manifolds", GDC 2007;
 *   Box2D v3 manifold.c). When the shapes are apart and the closest features are two vertices, a
 *   single vertex-vertex point with the normal along their join is used instead, so rounded corners
 *   and capsule ends collide as round;
 * - polygon-circle: the edge of largest separation, or the nearer end vertex when the centre lies
 *   beyond the edge's end (Voronoi regions, Ericson 5.1.2);
 * - capsule-circle and circle-circle: closest points on a segment and between centres;
 * - any shape against a half-plane (a plane or a face of the boundary box): the two vertices of
 *   least separation.
 * A point is kept only if its separation is below `speculative` (m): speculative contacts, which
 * the solver lets close during the step (Catto, "Continuous Collision", GDC 2013).
 * @category Collision
 */
export interface Manifold {
  /** Points in use, 0 to 2. */
  count: number;
  /** Unit normal from A to B, world frame: x. */
  nx: number;
  /** Unit normal from A to B: y. */
  ny: number;
  /** Contact points' x (world frame, m), midway between the surfaces. */
  readonly px: Float64Array;
  /** Contact points' y, m. */
  readonly py: Float64Array;
  /** Separation of each point along the normal, m (< 0: overlap). */
  readonly separation: Float64Array;
  /** Feature id of each point (stable while the same features touch). */
  readonly id: Int32Array;
}

/**
 * An empty manifold (reuse it across calls; the functions overwrite it).
 * @category Collision
 */
export function createManifold(): Manifold {
  const m: Manifold = {
    count: 0,
    nx: 0,
    ny: 1,
    px: new Float64Array(2),
    py: new Float64Array(2),
    separation: new Float64Array(2),
    id: new Int32Array(2),
  };
  // The normal holds fractions (and -0) from the first contact on (world/double-fields.ts); every
  // call writes the count (world/writable-fields.ts).
  widenToDoubles(m, ['nx', 'ny']);
  markWritable(m, ['count']);
  return m;
}

/**
 * Tolerance of the reference-face choice and of "the shapes are apart", m: Box2D's linear slop
 * (0.005 m) times 0.1. A fixed length: shapes far below a millimetre are out of scope.
 */
const FACE_TOLERANCE = 0.0005;

/** Feature id of a point from feature i of A and feature j of B (each < 16). */
function featureId(i: number, j: number): number {
  return (i << 4) | j;
}

const scratchB = createGeometry();

/**
 * Slots of a pair pose (`collideShapesAt`): A's centre and turn, B's, and the speculative distance.
 * The narrowphase reads its doubles from one array, so a call passes no unboxed numbers (V8 boxes
 * each double argument of a call it does not inline: 144 bytes a pair, 0.23 MB a step in a pyramid
 * of 820 boxes).
 */
export const PairPose = Object.freeze({ XA: 0, YA: 1, CA: 2, SA: 3, XB: 4, YB: 5, CB: 6, SB: 7, SPECULATIVE: 8, SIZE: 9 });

const callPose = new Float64Array(PairPose.SIZE);
const flippedPose = new Float64Array(PairPose.SIZE);

/**
 * Manifold of shapes A and B placed at (xa, ya) turned by angle (cos ca, sin sa), and likewise B.
 * Dispatches on the vertex counts: 1 circle, 2 capsule or segment, 3 to 8 polygon.
 * @param out overwritten; its normal points from A to B.
 * @param speculative largest separation kept, m (>= 0).
 * @category Collision
 */
export function collideShapes(
  out: Manifold,
  A: ConvexGeometry,
  xa: number,
  ya: number,
  ca: number,
  sa: number,
  B: ConvexGeometry,
  xb: number,
  yb: number,
  cb: number,
  sb: number,
  speculative: number,
): void {
  const q = callPose;
  q[PairPose.XA] = xa;
  q[PairPose.YA] = ya;
  q[PairPose.CA] = ca;
  q[PairPose.SA] = sa;
  q[PairPose.XB] = xb;
  q[PairPose.YB] = yb;
  q[PairPose.CB] = cb;
  q[PairPose.SB] = sb;
  q[PairPose.SPECULATIVE] = speculative;
  collideShapesAt(out, A, B, q);
}

/**
 * `collideShapes` with the poses and the speculative distance read from `pose` (slots `PairPose`);
 * `pose` is not changed. Dispatches through `PAIRS`, one function per pair of shape classes.
 * @param out overwritten; its normal points from A to B.
 * @category Collision
 */
export function collideShapesAt(out: Manifold, A: ConvexGeometry, B: ConvexGeometry, pose: Float64Array): void {
  out.count = 0;
  PAIRS[3 * shapeClass(A) + shapeClass(B)]!(out, A, B, pose);
}

/** A shape's class for `PAIRS`: 0 circle (1 vertex), 1 capsule or segment (2), 2 polygon (3 to 8). */
function shapeClass(g: ConvexGeometry): number {
  return g.count > 2 ? 2 : g.count - 1;
}

/** The manifold of A against B for one pair of shape classes (`collideShapesAt`'s arguments). */
type PairFunction = (out: Manifold, A: ConvexGeometry, B: ConvexGeometry, pose: Float64Array) => void;

/** World position of a circle's centre (`circleCentre`): x, y. */
const centre = new Float64Array(2);

/** Writes into `centre` the world position of circle g's centre, placed by the pose at `pose[o]` (o: PairPose.XA or XB). */
function circleCentre(g: ConvexGeometry, pose: Float64Array, o: number): void {
  const x = pose[o]!,
    y = pose[o + 1]!,
    c = pose[o + 2]!,
    s = pose[o + 3]!;
  centre[0] = x + c * g.vx[0]! - s * g.vy[0]!;
  centre[1] = y + s * g.vx[0]! + c * g.vy[0]!;
}

/** Two circles, in the world frame. */
function circleCircle(out: Manifold, A: ConvexGeometry, B: ConvexGeometry, pose: Float64Array): void {
  circleCentre(A, pose, PairPose.XA);
  const ax = centre[0]!,
    ay = centre[1]!;
  circleCentre(B, pose, PairPose.XB);
  collideCircles(out, ax, ay, A.radius, centre[0]!, centre[1]!, B.radius, pose[PairPose.SPECULATIVE]!);
}

/** A circle against a capsule, segment or polygon: collided the other way round, then flipped. */
function circleFirst(out: Manifold, A: ConvexGeometry, B: ConvexGeometry, pose: Float64Array): void {
  // B's pose (slots 4 to 7) and A's (0 to 3) trade places.
  const f = flippedPose;
  for (let k = 0; k < 4; k++) {
    f[PairPose.XA + k] = pose[PairPose.XB + k]!;
    f[PairPose.XB + k] = pose[PairPose.XA + k]!;
  }
  f[PairPose.SPECULATIVE] = pose[PairPose.SPECULATIVE]!;
  collideShapesAt(out, B, A, f);
  flipManifold(out);
}

/** A capsule, segment or polygon A against a circle B, in A's frame. */
function convexCircle(out: Manifold, A: ConvexGeometry, B: ConvexGeometry, pose: Float64Array): void {
  const xa = pose[PairPose.XA]!,
    ya = pose[PairPose.YA]!,
    ca = pose[PairPose.CA]!,
    sa = pose[PairPose.SA]!,
    speculative = pose[PairPose.SPECULATIVE]!;
  // Circle centre in A's frame.
  circleCentre(B, pose, PairPose.XB);
  const wx = centre[0]! - xa,
    wy = centre[1]! - ya;
  const lx = ca * wx + sa * wy,
    ly = -sa * wx + ca * wy;
  if (A.count === 2) collideSegmentCircleLocal(out, A, lx, ly, B.radius, speculative);
  else collidePolygonCircleLocal(out, A, lx, ly, B.radius, speculative);
  toWorld(out, xa, ya, ca, sa);
}

/** Two capsules, segments or polygons: B moved into A's frame, then `collidePolygonsLocal`. */
function convexConvex(out: Manifold, A: ConvexGeometry, B: ConvexGeometry, pose: Float64Array): void {
  const xa = pose[PairPose.XA]!,
    ya = pose[PairPose.YA]!,
    ca = pose[PairPose.CA]!,
    sa = pose[PairPose.SA]!,
    xb = pose[PairPose.XB]!,
    yb = pose[PairPose.YB]!,
    cb = pose[PairPose.CB]!,
    sb = pose[PairPose.SB]!;
  // B in A's frame: p_A = R_A^T (R_B p + x_B - x_A).
  const g = scratchB;
  g.count = B.count;
  g.radius = B.radius;
  g.kind = B.kind;
  const dx = xb - xa,
    dy = yb - ya;
  const c = ca * cb + sa * sb,
    s = ca * sb - sa * cb; // relative rotation R_A^T R_B
  const tx = ca * dx + sa * dy,
    ty = -sa * dx + ca * dy;
  for (let i = 0; i < B.count; i++) {
    const x = B.vx[i]!,
      y = B.vy[i]!;
    g.vx[i] = tx + c * x - s * y;
    g.vy[i] = ty + s * x + c * y;
    const nx = B.nx[i]!,
      ny = B.ny[i]!;
    g.nx[i] = c * nx - s * ny;
    g.ny[i] = s * nx + c * ny;
  }
  collidePolygonsLocal(out, A, g, pose);
  toWorld(out, xa, ya, ca, sa);
}

/** PAIRS[3 * shapeClass(A) + shapeClass(B)]: rows A circle, capsule or segment, polygon; columns B likewise. */
const PAIRS: readonly PairFunction[] = [
  ...[circleCircle, circleFirst, circleFirst],
  ...[convexCircle, convexConvex, convexConvex],
  ...[convexCircle, convexConvex, convexConvex],
];

/**
 * Circle (centre a, radius ra) against circle (b, rb), world frame.
 * @category Collision
 */
export function collideCircles(
  out: Manifold,
  ax: number,
  ay: number,
  ra: number,
  bx: number,
  by: number,
  rb: number,
  speculative: number,
): void {
  out.count = 0;
  const dx = bx - ax,
    dy = by - ay;
  const d = Math.sqrt(dx * dx + dy * dy);
  const sep = d - ra - rb;
  if (sep > speculative) return;
  let nx = 0,
    ny = 1;
  if (d > 1e-12) {
    nx = dx / d;
    ny = dy / d;
  }
  roundPoint(out, ax, ay, ra, bx, by, rb, nx, ny, sep, 0);
}

/**
 * Writes the one-point manifold between a round surface of radius ra (m) about (qx, qy) and one of
 * radius rb about (cx, cy): unit normal (nx, ny) from the first to the second, the point midway between
 * the surface points q + ra n and c - rb n, separation `sep` (m) and feature id `id`.
 */
function roundPoint(
  out: Manifold,
  qx: number,
  qy: number,
  ra: number,
  cx: number,
  cy: number,
  rb: number,
  nx: number,
  ny: number,
  sep: number,
  id: number,
): void {
  out.nx = nx;
  out.ny = ny;
  out.px[0] = 0.5 * (qx + ra * nx + cx - rb * nx);
  out.py[0] = 0.5 * (qy + ra * ny + cy - rb * ny);
  out.separation[0] = sep;
  out.id[0] = id;
  out.count = 1;
}

/** Swaps the roles of A and B: reverses the normal and the feature halves of each id. */
function flipManifold(out: Manifold): void {
  out.nx = -out.nx;
  out.ny = -out.ny;
  for (let i = 0; i < out.count; i++) {
    const id = out.id[i]!;
    out.id[i] = ((id & 15) << 4) | (id >> 4);
  }
}

/** Moves a manifold computed in A's frame into the world frame. */
function toWorld(out: Manifold, xa: number, ya: number, ca: number, sa: number): void {
  const nx = out.nx,
    ny = out.ny;
  out.nx = ca * nx - sa * ny;
  out.ny = sa * nx + ca * ny;
  for (let i = 0; i < out.count; i++) {
    const x = out.px[i]!,
      y = out.py[i]!;
    out.px[i] = xa + ca * x - sa * y;
    out.py[i] = ya + sa * x + ca * y;
  }
}

/** Capsule or segment A (2 vertices, radius) against a circle at (cx, cy) of radius rb, all in A's frame. */
function collideSegmentCircleLocal(out: Manifold, A: ConvexGeometry, cx: number, cy: number, rb: number, speculative: number): void {
  const x1 = A.vx[0]!,
    y1 = A.vy[0]!,
    ex = A.vx[1]! - x1,
    ey = A.vy[1]! - y1;
  const len2 = ex * ex + ey * ey;
  let t = len2 > 0 ? ((cx - x1) * ex + (cy - y1) * ey) / len2 : 0;
  t = t < 0 ? 0 : t > 1 ? 1 : t;
  const qx = x1 + t * ex,
    qy = y1 + t * ey;
  const dx = cx - qx,
    dy = cy - qy;
  const d = Math.sqrt(dx * dx + dy * dy);
  const ra = A.radius;
  const sep = d - ra - rb;
  out.count = 0;
  if (sep > speculative) return;
  let nx = A.nx[0]!,
    ny = A.ny[0]!;
  if (d > 1e-12) {
    nx = dx / d;
    ny = dy / d;
  }
  roundPoint(out, qx, qy, ra, cx, cy, rb, nx, ny, sep, featureId(t <= 0 ? 0 : t >= 1 ? 1 : 2, 0));
}

/** Polygon A (3+ vertices, radius) against a circle at (cx, cy) of radius rb, in A's frame. */
function collidePolygonCircleLocal(out: Manifold, A: ConvexGeometry, cx: number, cy: number, rb: number, speculative: number): void {
  out.count = 0;
  const n = A.count,
    vx = A.vx,
    vy = A.vy,
    nxs = A.nx,
    nys = A.ny;
  const radius = A.radius + rb;
  let best = -Infinity,
    edge = 0;
  for (let i = 0; i < n; i++) {
    const s = nxs[i]! * (cx - vx[i]!) + nys[i]! * (cy - vy[i]!);
    if (s > best) {
      best = s;
      edge = i;
    }
  }
  if (best - radius > speculative) return;
  const j = edge + 1 < n ? edge + 1 : 0;
  const x1 = vx[edge]!,
    y1 = vy[edge]!,
    x2 = vx[j]!,
    y2 = vy[j]!;
  const u1 = (cx - x1) * (x2 - x1) + (cy - y1) * (y2 - y1);
  const u2 = (cx - x2) * (x1 - x2) + (cy - y2) * (y1 - y2);
  let nx: number, ny: number, sep: number, qx: number, qy: number, id: number;
  if ((u1 < 0 || u2 < 0) && best > FACE_TOLERANCE) {
    // Vertex region: the normal runs from the vertex to the centre.
    qx = u1 < 0 ? x1 : x2;
    qy = u1 < 0 ? y1 : y2;
    id = u1 < 0 ? edge : j;
    const dx = cx - qx,
      dy = cy - qy;
    const d = Math.sqrt(dx * dx + dy * dy);
    sep = d - radius;
    if (sep > speculative) return;
    nx = dx / d;
    ny = dy / d;
  } else {
    nx = nxs[edge]!;
    ny = nys[edge]!;
    sep = best - radius;
    id = 8 + edge;
    qx = cx - best * nx;
    qy = cy - best * ny;
  }
  roundPoint(out, qx, qy, A.radius, cx, cy, rb, nx, ny, sep, featureId(id, 0));
}

/** Largest separation of poly2's vertices from poly1's edges: writes [edge, separation] to `res`. */
function maxSeparation(poly1: ConvexGeometry, poly2: ConvexGeometry, res: Float64Array): void {
  const n1 = poly1.count,
    n2 = poly2.count;
  let bestEdge = 0,
    best = -Infinity;
  for (let i = 0; i < n1; i++) {
    const nx = poly1.nx[i]!,
      ny = poly1.ny[i]!,
      x = poly1.vx[i]!,
      y = poly1.vy[i]!;
    let si = Infinity;
    for (let j = 0; j < n2; j++) {
      const s = nx * (poly2.vx[j]! - x) + ny * (poly2.vy[j]! - y);
      if (s < si) si = s;
    }
    if (si > best) {
      best = si;
      bestEdge = i;
    }
  }
  res[0] = bestEdge;
  res[1] = best;
}

const sepA = new Float64Array(2),
  sepB = new Float64Array(2);

/**
 * Two rounded polygons (2 to 8 vertices each) in A's frame; see the module comment. The speculative
 * distance (m) comes as pose[PairPose.SPECULATIVE], not as a number: this call is not inlined, and a
 * number argument would go as a heap number, 16 bytes of garbage for every pair in every step.
 * @category Collision
 */
export function collidePolygonsLocal(out: Manifold, A: ConvexGeometry, B: ConvexGeometry, pose: Float64Array): void {
  const speculative = pose[PairPose.SPECULATIVE]!;
  out.count = 0;
  maxSeparation(A, B, sepA);
  maxSeparation(B, A, sepB);
  const radius = A.radius + B.radius;
  let flip: boolean, poly1: ConvexGeometry, poly2: ConvexGeometry, edge1: number, separation: number;
  if (sepB[1]! > FACE_TOLERANCE + sepA[1]!) {
    flip = true;
    poly1 = B;
    poly2 = A;
    edge1 = sepB[0]!;
    separation = sepB[1]!;
  } else {
    flip = false;
    poly1 = A;
    poly2 = B;
    edge1 = sepA[0]!;
    separation = sepA[1]!;
  }
  if (separation - radius > speculative) return;
  const n1 = poly1.count,
    n2 = poly2.count;
  const i11 = edge1,
    i12 = edge1 + 1 < n1 ? edge1 + 1 : 0;
  const rnx = poly1.nx[i11]!,
    rny = poly1.ny[i11]!;
  // Incident edge: the edge of poly2 whose normal is most anti-parallel to the reference normal.
  let i21 = 0,
    minDot = Infinity;
  for (let i = 0; i < n2; i++) {
    const d = rnx * poly2.nx[i]! + rny * poly2.ny[i]!;
    if (d < minDot) {
      minDot = d;
      i21 = i;
    }
  }
  const i22 = i21 + 1 < n2 ? i21 + 1 : 0;
  const x11 = poly1.vx[i11]!,
    y11 = poly1.vy[i11]!,
    x12 = poly1.vx[i12]!,
    y12 = poly1.vy[i12]!;
  const x21 = poly2.vx[i21]!,
    y21 = poly2.vy[i21]!,
    x22 = poly2.vx[i22]!,
    y22 = poly2.vy[i22]!;
  const r1 = poly1.radius,
    r2 = poly2.radius;

  if (separation > FACE_TOLERANCE) {
    // Apart: if the closest features of the two edges are both vertices, one round contact between them.
    segmentFractions(x11, y11, x12, y12, x21, y21, x22, y22, fr);
    const f1 = fr[0]!,
      f2 = fr[1]!;
    if ((f1 === 0 || f1 === 1) && (f2 === 0 || f2 === 1)) {
      const vax = f1 === 0 ? x11 : x12,
        vay = f1 === 0 ? y11 : y12;
      const vbx = f2 === 0 ? x21 : x22,
        vby = f2 === 0 ? y21 : y22;
      const dx = vbx - vax,
        dy = vby - vay;
      const d = Math.sqrt(dx * dx + dy * dy);
      const sep = d - radius;
      if (sep > speculative || d < 1e-12) return;
      const nx = dx / d,
        ny = dy / d;
      const ia = f1 === 0 ? i11 : i12,
        ib = f2 === 0 ? i21 : i22;
      roundPoint(out, vax, vay, r1, vbx, vby, r2, nx, ny, sep, featureId(ia, ib));
      if (flip) {
        out.nx = -nx;
        out.ny = -ny;
        out.id[0] = featureId(ib, ia);
      }
      return;
    }
  }
  // Clip the incident edge (v21 -> v22, running against the reference edge) to the reference edge's span.
  let tx = x12 - x11,
    ty = y12 - y11;
  const tl = Math.sqrt(tx * tx + ty * ty);
  tx /= tl;
  ty /= tl;
  const lower1 = 0,
    upper1 = (x12 - x11) * tx + (y12 - y11) * ty;
  const upper2 = (x21 - x11) * tx + (y21 - y11) * ty,
    lower2 = (x22 - x11) * tx + (y22 - y11) * ty;
  const span = upper2 - lower2;
  let lx = x22,
    ly = y22,
    ux = x21,
    uy = y21;
  if (lower2 < lower1 && span > 1e-12) {
    const f = (lower1 - lower2) / span;
    lx = x22 + f * (x21 - x22);
    ly = y22 + f * (y21 - y22);
  }
  if (upper2 > upper1 && span > 1e-12) {
    const f = (upper1 - lower2) / span;
    ux = x22 + f * (x21 - x22);
    uy = y22 + f * (y21 - y22);
  }
  const sepL = (lx - x11) * rnx + (ly - y11) * rny;
  const sepU = (ux - x11) * rnx + (uy - y11) * rny;
  // Midway between the surfaces: the reference surface lies r1 out along n, the incident one r2 back.
  const kL = 0.5 * (r1 - r2 - sepL),
    kU = 0.5 * (r1 - r2 - sepU);
  lx += kL * rnx;
  ly += kL * rny;
  ux += kU * rnx;
  uy += kU * rny;
  // Normal and feature ids from A to B: a flipped pair's reversed, its points in the other order.
  if (!flip) {
    out.nx = rnx;
    out.ny = rny;
    const count = keepPoint(out, 0, lx, ly, sepL - radius, featureId(i11, i22), speculative);
    out.count = keepPoint(out, count, ux, uy, sepU - radius, featureId(i12, i21), speculative);
  } else {
    out.nx = -rnx;
    out.ny = -rny;
    const count = keepPoint(out, 0, ux, uy, sepU - radius, featureId(i21, i12), speculative);
    out.count = keepPoint(out, count, lx, ly, sepL - radius, featureId(i22, i11), speculative);
  }
}

/**
 * Writes point (x, y) (m), its separation (m) and feature id into slot `count` of `out` when the
 * separation is at most `speculative` (m); returns the number of points then written.
 */
function keepPoint(out: Manifold, count: number, x: number, y: number, separation: number, id: number, speculative: number): number {
  if (!(separation <= speculative)) return count;
  out.px[count] = x;
  out.py[count] = y;
  out.separation[count] = separation;
  out.id[count] = id;
  return count + 1;
}

const fr = new Float64Array(2);

/**
 * Fractions (s, t) in [0, 1] of the closest points p1 + s (q1 - p1) and p2 + t (q2 - p2) of two
 * segments (Ericson, Real-Time Collision Detection, 5.1.9), written to `res`.
 * @category Collision
 */
export function segmentFractions(
  p1x: number,
  p1y: number,
  q1x: number,
  q1y: number,
  p2x: number,
  p2y: number,
  q2x: number,
  q2y: number,
  res: Float64Array,
): void {
  const d1x = q1x - p1x,
    d1y = q1y - p1y,
    d2x = q2x - p2x,
    d2y = q2y - p2y;
  const rx = p1x - p2x,
    ry = p1y - p2y;
  closestFractions(
    d1x * d1x + d1y * d1y,
    d1x * d2x + d1y * d2y,
    d1x * rx + d1y * ry,
    d2x * d2x + d2y * d2y,
    d2x * rx + d2y * ry,
    1e-18,
    0,
    0,
    res,
  );
}

/**
 * Shape B (placed at (xb, yb), cos cb, sin sb) against the half-plane n . x <= d (its solid side),
 * with (nx, ny) the unit normal pointing out of the solid: up to two points at the vertices of least
 * separation, normal n (from the half-plane, A, to the shape, B). Feature ids are `idBase` + vertex.
 * @category Collision
 */
export function collideHalfPlane(
  out: Manifold,
  nx: number,
  ny: number,
  d: number,
  B: ConvexGeometry,
  xb: number,
  yb: number,
  cb: number,
  sb: number,
  speculative: number,
  idBase: number,
): void {
  out.count = 0;
  out.nx = nx;
  out.ny = ny;
  const r = B.radius;
  let s0 = Infinity,
    s1 = Infinity,
    i0 = -1,
    i1 = -1;
  for (let i = 0; i < B.count; i++) {
    const x = xb + cb * B.vx[i]! - sb * B.vy[i]!,
      y = yb + sb * B.vx[i]! + cb * B.vy[i]!;
    const s = nx * x + ny * y - d - r;
    if (s < s0) {
      s1 = s0;
      i1 = i0;
      s0 = s;
      i0 = i;
    } else if (s < s1) {
      s1 = s;
      i1 = i;
    }
  }
  let count = 0;
  for (let k = 0; k < 2; k++) {
    const i = k === 0 ? i0 : i1,
      s = k === 0 ? s0 : s1;
    if (i < 0 || s > speculative) continue;
    const x = xb + cb * B.vx[i]! - sb * B.vy[i]!,
      y = yb + sb * B.vx[i]! + cb * B.vy[i]!;
    // Midway between the shape's surface (x - r n) and the plane (x - (s + r) n).
    const back = r + 0.5 * s;
    out.px[count] = x - back * nx;
    out.py[count] = y - back * ny;
    out.separation[count] = s;
    out.id[count] = idBase + i;
    count++;
  }
  out.count = count;
}
