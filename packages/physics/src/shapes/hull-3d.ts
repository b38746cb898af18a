import { describe } from '../validation/validate.js';

/**
 * Convex hulls of 3D point clouds by quickhull (Barber, Dobkin and Huhdanpaa, "The Quickhull
 * Algorithm for Convex Hulls", ACM TOMS 22(4), 1996): start from a tetrahedron of extreme points,
 * then repeatedly take the point farthest outside any face, delete the faces it sees and close the
 * hole with a fan of new faces from the point to the horizon edges, until no point is outside by more
 * than the tolerance. Point clouds here are small (at most `MAX_HULL_INPUT` points), so each round
 * scans every point instead of keeping conflict lists.
 */

/**
 * Most vertices a hull may keep (the framework's limit on a convex shape).
 * @category Shapes
 */
export const MAX_HULL_VERTICES = 64;

/**
 * Most points a point cloud given to `quickhull` may hold.
 * @category Shapes
 */
export const MAX_HULL_INPUT = 1024;

/**
 * A convex hull: its vertices and its faces, triangles wound counter-clockwise seen from outside
 * (so (b - a) x (c - a) is the outward normal), and its polygonal faces (coplanar triangles merged)
 * for face clipping.
 * @category Shapes
 */
export interface Hull {
  /** Vertex coordinates, m, packed (x, y, z) per vertex; 4 to MAX_HULL_VERTICES vertices. */
  vertices: Float64Array;
  /** Triangles: three vertex indices each, counter-clockwise from outside. */
  triangles: Int32Array;
  /** Polygonal faces: `faceStart[f]` .. `faceStart[f + 1]` index `faceVertices` (counter-clockwise from outside). */
  faceStart: Int32Array;
  faceVertices: Int32Array;
  /** Outward unit normal (x, y, z) and plane offset d (n . p = d on the face) of each polygonal face. */
  faceNormals: Float64Array;
  faceOffsets: Float64Array;
  /** Edges between polygonal faces: (u, v, left, right) per edge, u < v, `left` the face holding u -> v counter-clockwise, `right` the other (layout: shapes/hull-edges-3d.ts). */
  edges: Int32Array;
}

interface Face {
  a: number;
  b: number;
  c: number;
  nx: number;
  ny: number;
  nz: number;
  d: number;
  alive: boolean;
}

/**
 * The convex hull of `points` (each [x, y, z], m).
 * @param where the function the user called, for messages.
 * @throws TypeError | RangeError `<where>: vertices must ...` on fewer than 4 or more than MAX_HULL_INPUT
 *   points, a non-finite coordinate, points that span no volume (all on one plane, line or point, to a
 *   tolerance of 1e-9 times the cloud's size), or a hull of more than MAX_HULL_VERTICES vertices.
 * @category Shapes
 */
export function quickhull(where: string, points: ArrayLike<ArrayLike<number>>): Hull {
  const P = hullPoints(where, points);
  const n = P.length / 3;
  // Scale of the cloud for the tolerance.
  let scale = 0;
  for (let i = 0; i < 3 * n; i++) scale = Math.max(scale, Math.abs(P[i]!));
  const eps = 1e-9 * Math.max(scale, 1e-300) * 3;
  const { faces, simplex } = initialSimplex(where, P, eps);
  const addFace = (a: number, b: number, c: number): void => {
    faces.push({ a, b, c, ...plane(P, a, b, c), alive: true });
  };
  const used = new Uint8Array(n);
  for (const i of simplex) used[i] = 1;
  // Expand: the point farthest outside any face, until none is outside. That point is the cloud's
  // extreme in the face's normal direction, so it is a vertex of the final hull: once more than
  // MAX_HULL_VERTICES have been added the hull is too big, and the cloud is refused at once instead of
  // after building a hull of up to MAX_HULL_INPUT vertices.
  let added = 4;
  for (let guard = 0; guard < 4 * n + 16; guard++) {
    let far = -1,
      farD = eps * 10;
    for (const f of faces) {
      if (!f.alive) continue;
      for (let i = 0; i < n; i++) {
        if (used[i]) continue;
        const d = f.nx * P[3 * i]! + f.ny * P[3 * i + 1]! + f.nz * P[3 * i + 2]! - f.d;
        if (d > farD) {
          farD = d;
          far = i;
        }
      }
    }
    if (far < 0) break;
    used[far] = 1;
    if (++added > MAX_HULL_VERTICES)
      throw new RangeError(
        `${where}: vertices must have a convex hull of at most ${MAX_HULL_VERTICES} vertices, got more than ${MAX_HULL_VERTICES}`,
      );
    const px = P[3 * far]!,
      py = P[3 * far + 1]!,
      pz = P[3 * far + 2]!;
    // Faces the point sees; the horizon is their directed edges whose twin belongs to a face it does not see.
    const edges = new Map<number, [number, number]>();
    for (const f of faces) {
      if (!f.alive || f.nx * px + f.ny * py + f.nz * pz - f.d <= eps) continue;
      f.alive = false;
      for (const [a, b] of [
        [f.a, f.b],
        [f.b, f.c],
        [f.c, f.a],
      ] as const) {
        const twin = b * n + a;
        if (edges.has(twin)) edges.delete(twin);
        else edges.set(a * n + b, [a, b]);
      }
    }
    for (const [a, b] of edges.values()) addFace(a, b, far);
    // Drop the faces the point buried, so each round scans the live hull only.
    let live = 0;
    for (const f of faces) if (f.alive) faces[live++] = f;
    faces.length = live;
  }
  return buildHull(
    where,
    P,
    faces.filter((f) => f.alive),
    eps,
  );
}

/**
 * The points as a flat array (x0, y0, z0, x1, ...).
 * @throws TypeError | RangeError as quickhull, on the count, a point's shape or a coordinate.
 */
function hullPoints(where: string, points: ArrayLike<ArrayLike<number>>): Float64Array {
  if (points === null || typeof points !== 'object' || typeof points.length !== 'number') {
    throw new TypeError(`${where}: vertices must be an array of [x, y, z] points, got ${describe(points)}`);
  }
  const n = points.length;
  if (n < 4 || n > MAX_HULL_INPUT) throw new RangeError(`${where}: vertices must hold 4 to ${MAX_HULL_INPUT} points, got ${n}`);
  const P = new Float64Array(3 * n);
  for (let i = 0; i < n; i++) {
    const p = points[i];
    if (p === null || typeof p !== 'object' || p.length !== 3)
      throw new TypeError(`${where}: vertices[${i}] must be [x, y, z], got ${describe(p)}`);
    for (let k = 0; k < 3; k++) {
      const v = p[k];
      if (typeof v !== 'number' || !Number.isFinite(v))
        throw new RangeError(`${where}: vertices[${i}][${k}] must be a finite number, got ${describe(v)}`);
      P[3 * i + k] = v;
    }
  }
  return P;
}

/**
 * The starting tetrahedron: the extreme points along x, then the point farthest from their line, then
 * the one farthest from their plane; its four faces wound outward, and its four points.
 * @throws RangeError as quickhull, when the points span no volume (to `eps`, m).
 */
function initialSimplex(where: string, P: Float64Array, eps: number): { faces: Face[]; simplex: number[] } {
  const n = P.length / 3;
  const degenerate = (): RangeError =>
    new RangeError(`${where}: vertices must span a volume (not all on one plane, line or point), got ${n} points that do not`);
  let i0 = 0,
    i1 = 0;
  for (let i = 1; i < n; i++) {
    if (P[3 * i]! < P[3 * i0]!) i0 = i;
    if (P[3 * i]! > P[3 * i1]!) i1 = i;
  }
  if (i0 === i1 || dist2(P, i0, i1) <= eps * eps) {
    // All share x: take the farthest pair from point 0.
    i0 = 0;
    let best = -1;
    for (let i = 1; i < n; i++) {
      const d = dist2(P, 0, i);
      if (d > best) {
        best = d;
        i1 = i;
      }
    }
    if (best <= eps * eps) throw degenerate();
  }
  let i2 = -1,
    best = 0;
  const ux = P[3 * i1]! - P[3 * i0]!,
    uy = P[3 * i1 + 1]! - P[3 * i0 + 1]!,
    uz = P[3 * i1 + 2]! - P[3 * i0 + 2]!;
  for (let i = 0; i < n; i++) {
    const wx = P[3 * i]! - P[3 * i0]!,
      wy = P[3 * i + 1]! - P[3 * i0 + 1]!,
      wz = P[3 * i + 2]! - P[3 * i0 + 2]!;
    const cx = uy * wz - uz * wy,
      cy = uz * wx - ux * wz,
      cz = ux * wy - uy * wx;
    const d = cx * cx + cy * cy + cz * cz;
    if (d > best) {
      best = d;
      i2 = i;
    }
  }
  const ulen = Math.sqrt(ux * ux + uy * uy + uz * uz);
  if (i2 < 0 || Math.sqrt(best) / ulen <= eps) throw degenerate();
  const base = plane(P, i0, i1, i2);
  let i3 = -1;
  best = 0;
  for (let i = 0; i < n; i++) {
    const d = Math.abs(base.nx * P[3 * i]! + base.ny * P[3 * i + 1]! + base.nz * P[3 * i + 2]! - base.d);
    if (d > best) {
      best = d;
      i3 = i;
    }
  }
  if (i3 < 0 || best <= eps) throw degenerate();
  const faces: Face[] = [];
  const above = base.nx * P[3 * i3]! + base.ny * P[3 * i3 + 1]! + base.nz * P[3 * i3 + 2]! - base.d > 0;
  const addFace = (a: number, b: number, c: number): void => {
    faces.push({ a, b, c, ...plane(P, a, b, c), alive: true });
  };
  if (above) {
    addFace(i0, i2, i1);
    addFace(i0, i1, i3);
    addFace(i1, i2, i3);
    addFace(i2, i0, i3);
  } else {
    addFace(i0, i1, i2);
    addFace(i0, i3, i1);
    addFace(i1, i3, i2);
    addFace(i2, i3, i0);
  }
  return { faces, simplex: [i0, i1, i2, i3] };
}

function dist2(P: Float64Array, i: number, j: number): number {
  const x = P[3 * i]! - P[3 * j]!,
    y = P[3 * i + 1]! - P[3 * j + 1]!,
    z = P[3 * i + 2]! - P[3 * j + 2]!;
  return x * x + y * y + z * z;
}

function plane(P: Float64Array, a: number, b: number, c: number): { nx: number; ny: number; nz: number; d: number } {
  const ax = P[3 * a]!,
    ay = P[3 * a + 1]!,
    az = P[3 * a + 2]!;
  const ux = P[3 * b]! - ax,
    uy = P[3 * b + 1]! - ay,
    uz = P[3 * b + 2]! - az;
  const vx = P[3 * c]! - ax,
    vy = P[3 * c + 1]! - ay,
    vz = P[3 * c + 2]! - az;
  let nx = uy * vz - uz * vy,
    ny = uz * vx - ux * vz,
    nz = ux * vy - uy * vx;
  const l = Math.sqrt(nx * nx + ny * ny + nz * nz);
  if (l > 0) {
    nx /= l;
    ny /= l;
    nz /= l;
  }
  return { nx, ny, nz, d: nx * ax + ny * ay + nz * az };
}

/** Compacts the vertices, checks the vertex limit, and merges coplanar triangles into polygonal faces. */
function buildHull(where: string, P: Float64Array, faces: Face[], eps: number): Hull {
  const remap = new Map<number, number>();
  const verts: number[] = [];
  const id = (i: number): number => {
    let k = remap.get(i);
    if (k === undefined) {
      k = remap.size;
      remap.set(i, k);
      verts.push(P[3 * i]!, P[3 * i + 1]!, P[3 * i + 2]!);
    }
    return k;
  };
  const tris: number[] = [];
  for (const f of faces) tris.push(id(f.a), id(f.b), id(f.c));
  const nv = remap.size;
  if (nv > MAX_HULL_VERTICES)
    throw new RangeError(`${where}: vertices must have a convex hull of at most ${MAX_HULL_VERTICES} vertices, got ${nv}`);
  const vertices = new Float64Array(verts);
  // Group triangles by plane (normals within 1e-6 rad and offsets within the tolerance).
  const groups: number[][] = [];
  const gn: Array<[number, number, number, number]> = [];
  for (let t = 0; t < faces.length; t++) {
    const f = faces[t]!;
    let g = -1;
    for (let k = 0; k < gn.length; k++) {
      const q = gn[k]!;
      if (f.nx * q[0] + f.ny * q[1] + f.nz * q[2] > 1 - 1e-9 && Math.abs(f.d - q[3]) <= 100 * eps) {
        g = k;
        break;
      }
    }
    if (g < 0) {
      g = gn.length;
      gn.push([f.nx, f.ny, f.nz, f.d]);
      groups.push([]);
    }
    groups[g]!.push(t);
  }
  const faceStart: number[] = [0];
  const faceVertices: number[] = [];
  const faceNormals: number[] = [];
  const faceOffsets: number[] = [];
  for (let g = 0; g < groups.length; g++) {
    // The polygon's boundary: directed triangle edges whose twin is not in the group, chained.
    const next = new Map<number, number>();
    const inGroup = new Set<number>();
    for (const t of groups[g]!) for (let k = 0; k < 3; k++) inGroup.add(tris[3 * t + k]! * 1024 + tris[3 * t + ((k + 1) % 3)]!);
    for (const e of inGroup) {
      const a = Math.floor(e / 1024),
        b = e % 1024;
      if (!inGroup.has(b * 1024 + a)) next.set(a, b);
    }
    const start = next.keys().next().value as number;
    let v = start,
      guard = 0;
    do {
      faceVertices.push(v);
      v = next.get(v)!;
    } while (v !== start && ++guard < 256);
    faceStart.push(faceVertices.length);
    const q = gn[g]!;
    faceNormals.push(q[0], q[1], q[2]);
    faceOffsets.push(q[3]);
  }
  const owner = new Map<number, number>();
  for (let f = 0; f + 1 < faceStart.length; f++) {
    for (let k = faceStart[f]!; k < faceStart[f + 1]!; k++) {
      const u = faceVertices[k]!,
        v = faceVertices[k + 1 < faceStart[f + 1]! ? k + 1 : faceStart[f]!]!;
      owner.set(u * 1024 + v, f);
    }
  }
  const edges: number[] = [];
  for (const [key, f] of owner) {
    const u = Math.floor(key / 1024),
      v = key % 1024;
    if (u < v) edges.push(u, v, f, owner.get(v * 1024 + u) ?? f);
  }
  return {
    edges: new Int32Array(edges),
    vertices,
    triangles: new Int32Array(tris),
    faceStart: new Int32Array(faceStart),
    faceVertices: new Int32Array(faceVertices),
    faceNormals: new Float64Array(faceNormals),
    faceOffsets: new Float64Array(faceOffsets),
  };
}
