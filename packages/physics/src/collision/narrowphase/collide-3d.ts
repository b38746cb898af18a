import { boxBox3D, planeBox3D } from './box-box-3d.js';
import { finishCandidates, pushCandidate } from './candidates-3d.js';
import { addPoint, type Collider3D, flip, type Manifold3D } from './manifold-3d.js';
import { polyhedra } from './polyhedra-3d.js';
import { pose, posedA, posedB } from './posed-3d.js';
import { capsulePolyhedron, spherePolyhedron } from './round-polyhedron-3d.js';
import { segmentSegment } from './segments-3d.js';

/**
 * The 3D narrowphase's entry points: a pair of posed shapes, or a shape against a plane, dispatched
 * through a table with one function per pair of collider kinds (ColliderKind3D), looked up once per pair.
 */

/** The manifold of A against B (normal A to B) for one pair of collider kinds, A's kind <= B's. */
type PairFunction = (A: Collider3D, B: Collider3D, margin: number, out: Manifold3D) => void;

/** Sphere or capsule against a polyhedron (B posed here). */
function sphereVsPolyhedron(A: Collider3D, B: Collider3D, margin: number, out: Manifold3D): void {
  spherePolyhedron(A, pose(B, posedB), margin, out, false);
}

function capsuleVsPolyhedron(A: Collider3D, B: Collider3D, margin: number, out: Manifold3D): void {
  capsulePolyhedron(A, pose(B, posedB), margin, out);
}

/** Two polyhedra: two boxes by box-box-3d.ts without posing their hulls, any others by their posed hulls. */
function polyhedronVsPolyhedron(A: Collider3D, B: Collider3D, margin: number, out: Manifold3D): void {
  if (A.box === 1 && B.box === 1)
    boxBox3D(A.px, A.py, A.pz, A.R, 0, A.hx, A.hy, A.hz, B.px, B.py, B.pz, B.R, 0, B.hx, B.hy, B.hz, margin, out);
  else polyhedra(pose(A, posedA), pose(B, posedB), margin, out);
}

/** Kinds in ColliderKind3D. */
const KINDS = 3;

/**
 * PAIRS[KINDS * A.kind + B.kind] for A.kind <= B.kind, rows and columns sphere, capsule, polyhedron;
 * the pairs below the diagonal (null) are collided swapped.
 */
const PAIRS: readonly (PairFunction | null)[] = [
  ...[segmentSegment, segmentSegment, sphereVsPolyhedron],
  ...[null, segmentSegment, capsuleVsPolyhedron],
  ...[null, null, polyhedronVsPolyhedron],
];

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
  PAIRS[KINDS * A.kind + B.kind]!(A, B, margin, out);
}

/** Plane-collider functions: the plane n . x = d (nx, ny, nz, d in `planeAt`), `out`'s normal already n. */
type PlaneFunction = (B: Collider3D, margin: number, out: Manifold3D) => void;

/** The plane of the current collidePlane3D call: nx, ny, nz, d. */
const planeAt = new Float64Array(4);

/** Adds the point of a sphere of radius r at (x, y, z) against the plane in `planeAt`, if within `margin`. */
function planeSpherePoint(x: number, y: number, z: number, r: number, id: number, margin: number, out: Manifold3D): void {
  const nx = planeAt[0]!,
    ny = planeAt[1]!,
    nz = planeAt[2]!;
  const s = nx * x + ny * y + nz * z - planeAt[3]! - r;
  if (s > margin) return;
  addPoint(out, x - nx * (r + s / 2), y - ny * (r + s / 2), z - nz * (r + s / 2), s, id);
}

function planeVsSphere(B: Collider3D, margin: number, out: Manifold3D): void {
  planeSpherePoint(B.px, B.py, B.pz, B.radius, 0, margin, out);
}

/** A capsule: its two end spheres. */
function planeVsCapsule(B: Collider3D, margin: number, out: Manifold3D): void {
  const ax = B.R[1]! * B.hy,
    ay = B.R[4]! * B.hy,
    az = B.R[7]! * B.hy;
  planeSpherePoint(B.px - ax, B.py - ay, B.pz - az, B.radius, 0, margin, out);
  planeSpherePoint(B.px + ax, B.py + ay, B.pz + az, B.radius, 1, margin, out);
}

/** A box by box-box-3d.ts; any other polyhedron: its posed vertices below the margin, reduced to four. */
function planeVsPolyhedron(B: Collider3D, margin: number, out: Manifold3D): void {
  const nx = planeAt[0]!,
    ny = planeAt[1]!,
    nz = planeAt[2]!,
    d = planeAt[3]!;
  if (B.box === 1) {
    planeBox3D(nx, ny, nz, d, B.px, B.py, B.pz, B.R, 0, B.hx, B.hy, B.hz, margin, out);
    return;
  }
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
}

/** PLANES[B.kind]. */
const PLANES: readonly PlaneFunction[] = [planeVsSphere, planeVsCapsule, planeVsPolyhedron];

/**
 * The manifold of a plane n . x = d (A, solid below) against shape B (normal = the plane's).
 * @category Collision
 */
export function collidePlane3D(nx: number, ny: number, nz: number, d: number, B: Collider3D, margin: number, out: Manifold3D): void {
  out.count = 0;
  out.nx = nx;
  out.ny = ny;
  out.nz = nz;
  planeAt[0] = nx;
  planeAt[1] = ny;
  planeAt[2] = nz;
  planeAt[3] = d;
  PLANES[B.kind]!(B, margin, out);
}
