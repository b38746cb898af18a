import type { Hull } from '../../shapes/hull-3d.js';
import type { Collider3D } from './manifold-3d.js';

/** Polyhedra posed in the world for the 3D narrowphase: a hull's vertices, face normals and face offsets turned and moved into world coordinates (two reused scratch poses, A and B). */

export interface Posed {
  n: number;
  v: Float64Array;
  fn: Float64Array;
  fd: Float64Array;
  cx: number;
  cy: number;
  cz: number;
  hull: Hull;
}
/** An empty scratch pose: room for a hull's 64 vertices and 130 faces (`pose` grows the face arrays of a larger hull). */
function emptyPose(): Posed {
  return {
    n: 0,
    v: new Float64Array(192),
    fn: new Float64Array(3 * 130),
    fd: new Float64Array(130),
    cx: 0,
    cy: 0,
    cz: 0,
    hull: null as unknown as Hull,
  };
}
export const posedA: Posed = emptyPose();
export const posedB: Posed = emptyPose();

export function pose(c: Collider3D, out: Posed): Posed {
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
