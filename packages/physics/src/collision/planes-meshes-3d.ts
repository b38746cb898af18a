import { BOX3_MAX_X, BOX3_MAX_Y, BOX3_MAX_Z, BOX3_MIN_X, BOX3_MIN_Y, BOX3_MIN_Z, BOX3_STRIDE } from '../math/box-layout-3d.js';
import { M00, M01, M02, M10, M11, M12, M20, M21, M22, MAT3_STRIDE } from '../math/mat3-layout.js';
import { type Mesh3D, meshesOf } from '../shapes/mesh-3d.js';
import { Shape3DKind, type Shape3DStore } from '../shapes/store-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { colB, collider, manifold, scratch } from './colliders-3d.js';
import type { Contact3DState } from './manifolds-3d.js';
import * as ARGS from './narrowphase/box-args-3d.js';
import { planeArgs, planeBox3DAt } from './narrowphase/box-box-3d.js';
import { collidePlane3D } from './narrowphase/collide-3d.js';
import { ColliderKind3D } from './narrowphase/manifold-3d.js';
import { emit } from './pair-manifolds-3d.js';
import { BodyType } from './state.js';

/** Contacts of 3D shapes with static planes, the world's boundary box and triangle meshes. */

/** Every collider against the triangle meshes and the planes. */
export function planesAndMeshes(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState): void {
  const sc = scratch,
    n = sc.n,
    type = world.collision.bodyType;
  const h = world.h;
  const meshList = meshesOf(world);
  if (meshList.length > 0) for (let i = 0; i < n; i++) for (const m of meshList) collideMesh(world, s, st, m, i);
  // Planes and the boundary box's six faces: static, A side.
  const c = world.components;
  const planes = query(world, [c.Plane]);
  const box = world.collision.boundary;
  if (planes.length === 0 && !box.enabled) return;
  const P = c.Plane,
    lo = box.min,
    hi = box.max;
  for (let i = 0; i < n; i++) {
    if (sc.ball[i]) continue; // balls against planes and the boundary are the ball narrowphase's
    if (type[sc.body[i]!] !== BodyType.Dynamic) continue;
    const e = sc.shape[i]!;
    if (s.sensor[e]) continue;
    posed = false;
    const margin = scratch.spec + sc.speed[i]! * h;
    for (let k = 0; k < planes.length; k++) {
      const p = planes[k]!;
      if (collidePlaneAt(world, s, i, P.nx[p]!, P.ny[p]!, P.nz[p]!, P.d[p]!, margin))
        emit(world, s, st, 0, sc.body[i]!, p, e, false, false, p);
    }
    if (!box.enabled) continue;
    // The faces as planes n . x = d with n pointing into the box (solid outside it).
    for (let f = 0; f < 6; f++) {
      const axis = f >> 1,
        sign = (f & 1) === 0 ? 1 : -1;
      const d = sign > 0 ? lo[axis]! : -hi[axis]!;
      const nx = axis === 0 ? sign : 0,
        ny = axis === 1 ? sign : 0,
        nz = axis === 2 ? sign : 0;
      if (collidePlaneAt(world, s, i, nx, ny, nz, d, margin)) emit(world, s, st, 0, sc.body[i]!, 0, e, false, false, 0, BOUNDARY_SUB + f);
    }
  }
}

/**
 * The row `sub` of a boundary face (0 to 5: -x, +x, -y, +y, -z, +z walls' faces, in the order of
 * `planesAndMeshes`), with no shape on the A side: above every mesh triangle's (triangle index + 1,
 * under 2^22 - 6), so a face's warm start never meets a triangle's.
 */
const BOUNDARY_SUB = 4194304 - 6;

/** Whether collider i's pose has been written to `colB` in the current collider's pass over the planes. */
let posed = false;

/**
 * The manifold (in `manifold`) of collider i against the plane n . x = d (solid below), within
 * `margin`; false, without posing the collider, when its bounding sphere is farther than the margin.
 */
function collidePlaneAt(
  world: PhysicsWorld,
  s: Shape3DStore,
  i: number,
  nx: number,
  ny: number,
  nz: number,
  d: number,
  margin: number,
): boolean {
  const sc = scratch,
    e = sc.shape[i]!;
  // Cheap reject: the bounding sphere above the plane by more than the margin.
  if (nx * sc.px[i]! + ny * sc.py[i]! + nz * sc.pz[i]! - d - s.reach[e]! > margin) return false;
  if (s.kind[e] === Shape3DKind.Box) {
    const g = planeArgs;
    g[ARGS.PLANE_NX] = nx;
    g[ARGS.PLANE_NY] = ny;
    g[ARGS.PLANE_NZ] = nz;
    g[ARGS.PLANE_D] = d;
    g[ARGS.PLANE_BOX_CX] = sc.px[i]!;
    g[ARGS.PLANE_BOX_CY] = sc.py[i]!;
    g[ARGS.PLANE_BOX_CZ] = sc.pz[i]!;
    g[ARGS.PLANE_BOX_HX] = s.hx[e]!;
    g[ARGS.PLANE_BOX_HY] = s.hy[e]!;
    g[ARGS.PLANE_BOX_HZ] = s.hz[e]!;
    g[ARGS.PLANE_MARGIN] = margin;
    planeBox3DAt(sc.R, MAT3_STRIDE * i, manifold);
  } else {
    if (!posed) {
      collider(world, s, i, colB);
      posed = true;
    }
    collidePlane3D(nx, ny, nz, d, colB, margin, manifold);
  }
  return manifold.count > 0;
}

const triQ = new Float64Array(3);

/** Closest point of triangle a b c to p into triQ (Ericson, Real-Time Collision Detection, 5.1.5). */
function closestOnTriangle(V: Float64Array, a: number, b: number, c: number, px: number, py: number, pz: number): void {
  const ax = V[a]!,
    ay = V[a + 1]!,
    az = V[a + 2]!;
  const abx = V[b]! - ax,
    aby = V[b + 1]! - ay,
    abz = V[b + 2]! - az,
    acx = V[c]! - ax,
    acy = V[c + 1]! - ay,
    acz = V[c + 2]! - az;
  const apx = px - ax,
    apy = py - ay,
    apz = pz - az;
  const d1 = abx * apx + aby * apy + abz * apz,
    d2 = acx * apx + acy * apy + acz * apz;
  const set = (u: number, v: number): void => {
    triQ[0] = ax + abx * u + acx * v;
    triQ[1] = ay + aby * u + acy * v;
    triQ[2] = az + abz * u + acz * v;
  };
  if (d1 <= 0 && d2 <= 0) {
    set(0, 0);
    return;
  }
  const bpx = px - V[b]!,
    bpy = py - V[b + 1]!,
    bpz = pz - V[b + 2]!;
  const d3 = abx * bpx + aby * bpy + abz * bpz,
    d4 = acx * bpx + acy * bpy + acz * bpz;
  if (d3 >= 0 && d4 <= d3) {
    set(1, 0);
    return;
  }
  const vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    set(d1 / (d1 - d3), 0);
    return;
  }
  const cpx = px - V[c]!,
    cpy = py - V[c + 1]!,
    cpz = pz - V[c + 2]!;
  const d5 = abx * cpx + aby * cpy + abz * cpz,
    d6 = acx * cpx + acy * cpy + acz * cpz;
  if (d6 >= 0 && d5 <= d6) {
    set(0, 1);
    return;
  }
  const vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    set(0, d2 / (d2 - d6));
    return;
  }
  const va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
    const w = (d4 - d3) / (d4 - d3 + d5 - d6);
    set(1 - w, w);
    return;
  }
  const den = 1 / (va + vb + vc);
  set(vb * den, vc * den);
}

/** Collider i against the triangles of mesh m whose boxes meet its box: a manifold per triangle touched. */
function collideMesh(world: PhysicsWorld, s: Shape3DStore, st: Contact3DState, m: Mesh3D, i: number): void {
  const sc = scratch,
    b = sc.body[i]!;
  if (world.collision.bodyType[b] !== BodyType.Dynamic) return;
  const e = sc.shape[i]!;
  if (!sc.ball[i] && s.sensor[e]) return;
  const Bd = m.bounds,
    N = m.normals,
    V = m.vertices,
    T = m.triangles;
  const margin = scratch.spec + sc.speed[i]! * world.h;
  // The triangles' boxes are not fattened: the collider's box takes the other half of its speculative distance here.
  const g = 0.5 * scratch.spec;
  collider(world, s, i, colB);
  const reach = sc.ball[i] ? colB.radius : s.reach[e]!;
  const out = manifold;
  for (let t = 0, nt = T.length / 3; t < nt; t++) {
    const o = BOX3_STRIDE * t;
    if (
      Bd[o + BOX3_MIN_X]! > sc.maxX[i]! + g ||
      Bd[o + BOX3_MAX_X]! < sc.minX[i]! - g ||
      Bd[o + BOX3_MIN_Y]! > sc.maxY[i]! + g ||
      Bd[o + BOX3_MAX_Y]! < sc.minY[i]! - g ||
      Bd[o + BOX3_MIN_Z]! > sc.maxZ[i]! + g ||
      Bd[o + BOX3_MAX_Z]! < sc.minZ[i]! - g
    )
      continue;
    const nx = N[3 * t]!,
      ny = N[3 * t + 1]!,
      nz = N[3 * t + 2]!;
    const a = 3 * T[3 * t]!,
      bb = 3 * T[3 * t + 1]!,
      c = 3 * T[3 * t + 2]!;
    const d = nx * V[a]! + ny * V[a + 1]! + nz * V[a + 2]!;
    // Behind the triangle by more than the shape's size: pushed through, let go.
    const centre = nx * colB.px + ny * colB.py + nz * colB.pz - d;
    if (centre < -reach || centre - reach > margin) continue;
    out.count = 0;
    out.nx = nx;
    out.ny = ny;
    out.nz = nz;
    if (colB.kind !== ColliderKind3D.Polyhedron) {
      // Sphere or capsule: each end sphere against the triangle's closest point.
      const hy = colB.kind === ColliderKind3D.Capsule ? colB.hy : 0,
        r = colB.radius;
      for (let end = 0; end < (hy > 0 ? 2 : 1); end++) {
        const sgn = end === 0 ? -1 : 1;
        // The capsule's axis is its shape y axis, the rotation's column 1.
        const px = colB.px + sgn * colB.R[M01]! * hy,
          py = colB.py + sgn * colB.R[M11]! * hy,
          pz = colB.pz + sgn * colB.R[M21]! * hy;
        closestOnTriangle(V, a, bb, c, px, py, pz);
        let ux = px - triQ[0]!,
          uy = py - triQ[1]!,
          uz = pz - triQ[2]!;
        const dist = Math.hypot(ux, uy, uz);
        if (dist - r > margin || nx * ux + ny * uy + nz * uz < 0) continue;
        if (dist > 1e-12) {
          ux /= dist;
          uy /= dist;
          uz /= dist;
        } else {
          ux = nx;
          uy = ny;
          uz = nz;
        }
        if (out.count === 0) {
          out.nx = ux;
          out.ny = uy;
          out.nz = uz;
        }
        const sep = dist - r;
        const k = out.count++;
        out.x[k] = triQ[0]! + (ux * sep) / 2;
        out.y[k] = triQ[1]! + (uy * sep) / 2;
        out.z[k] = triQ[2]! + (uz * sep) / 2;
        out.sep[k] = sep;
        out.id[k] = end;
      }
    } else {
      // Polyhedron: its vertices over the triangle, below the margin.
      const h = colB.hull!,
        HV = h.vertices,
        R = colB.R;
      let best = -1;
      for (let v = 0, nv = HV.length / 3; v < nv; v++) {
        const lx = HV[3 * v]!,
          ly = HV[3 * v + 1]!,
          lz = HV[3 * v + 2]!;
        const wx = colB.px + R[M00]! * lx + R[M01]! * ly + R[M02]! * lz,
          wy = colB.py + R[M10]! * lx + R[M11]! * ly + R[M12]! * lz,
          wz = colB.pz + R[M20]! * lx + R[M21]! * ly + R[M22]! * lz;
        const sep = nx * wx + ny * wy + nz * wz - d;
        if (sep > margin) continue;
        // Inside the triangle's prism (barycentric signs of the projection).
        let inside = true;
        for (const [p, q] of [
          [a, bb],
          [bb, c],
          [c, a],
        ] as const) {
          const ex = V[q]! - V[p]!,
            ey = V[q + 1]! - V[p + 1]!,
            ez = V[q + 2]! - V[p + 2]!;
          const qx = wx - V[p]!,
            qy = wy - V[p + 1]!,
            qz = wz - V[p + 2]!;
          if (nx * (ey * qz - ez * qy) + ny * (ez * qx - ex * qz) + nz * (ex * qy - ey * qx) < 0) {
            inside = false;
            break;
          }
        }
        if (!inside) continue;
        if (out.count < 4) {
          const k = out.count++;
          out.x[k] = wx - (nx * sep) / 2;
          out.y[k] = wy - (ny * sep) / 2;
          out.z[k] = wz - (nz * sep) / 2;
          out.sep[k] = sep;
          out.id[k] = v;
        } else {
          // Keep the four deepest.
          best = 0;
          for (let k = 1; k < 4; k++) if (out.sep[k]! > out.sep[best]!) best = k;
          if (sep < out.sep[best]!) {
            out.x[best] = wx - (nx * sep) / 2;
            out.y[best] = wy - (ny * sep) / 2;
            out.z[best] = wz - (nz * sep) / 2;
            out.sep[best] = sep;
            out.id[best] = v;
          }
        }
      }
    }
    if (out.count > 0) emit(world, s, st, 0, b, m.entity, e, false, sc.ball[i] === 1, m.entity, t + 1);
  }
}
