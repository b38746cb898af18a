import { boxBox3D, planeBox3D } from './box-box-3d.js';
import { finishCandidates, pushCandidate } from './candidates-3d.js';
import { addPoint, type Collider3D, ColliderKind3D, flip, type Manifold3D } from './manifold-3d.js';
import { polyhedra } from './polyhedra-3d.js';
import { pose, posedA, posedB } from './posed-3d.js';
import { capsulePolyhedron, spherePolyhedron } from './round-polyhedron-3d.js';
import { segmentSegment } from './segments-3d.js';

/** The 3D narrowphase's entry points: a pair of posed shapes, or a shape against a plane, dispatched by their kinds to the pair functions. */

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
