import { addComponent, entityExists } from 'bitecs';
import {
  assertInRange,
  assertInteger,
  assertNonNegative,
  assertOptions,
  assertPositive,
  assertVector,
  describe,
} from '../validation/validate.js';
import { registerExternalWorldState } from '../world/external-state.js';
import { createSlot, currentHandle } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Static triangle meshes and height fields for ground and level geometry in 3D (a ramp, a terrain).
 * A mesh is its own static entity (with a `Material`), its triangles one-sided: the front is where
 * the vertices run counter-clockwise, and shapes collide with it from the front (collision/shapes-3d.ts:
 * spheres by the closest point of each triangle, Ericson 5.1.5; capsules by their end spheres;
 * polyhedra by their vertices over each triangle, with the triangle's normal). A shape pressed through
 * a triangle by more than its own size is let go rather than pushed out the back.
 */

/**
 * A static triangle mesh (world coordinates).
 * @category Collision
 */
export interface Mesh3D {
  /** The mesh's entity (slot). */
  entity: number;
  /** Vertices, m, packed (x, y, z). */
  vertices: Float64Array;
  /** Triangles: three vertex indices each, counter-clockwise seen from the front. */
  triangles: Int32Array;
  /** Per triangle: unit normal (x, y, z) and the bounding box (min x, y, z, max x, y, z, m: math/box-layout-3d.ts). */
  normals: Float64Array;
  bounds: Float64Array;
}

/** The world's mesh list (`world.features.meshes3d`), made on first use when `create` is true. */
function meshListOf(world: PhysicsWorld, create: boolean): { list: Mesh3D[] } | undefined {
  let m = world.features.meshes3d as { list: Mesh3D[] } | undefined;
  if (m === undefined && create) {
    m = { list: [] };
    world.features.meshes3d = m;
  }
  return m;
}

/**
 * The world's meshes (live ones; removed entities are dropped).
 * @category Collision
 */
export function meshesOf(world: PhysicsWorld): Mesh3D[] {
  const m = meshListOf(world, false);
  if (m === undefined) return [];
  if (m.list.some((x) => !entityExists(world, x.entity))) m.list = m.list.filter((x) => entityExists(world, x.entity));
  return m.list;
}

registerExternalWorldState({
  name: 'meshes3d',
  get: (world, create) => meshListOf(world, create),
  clear: (world) => {
    world.features.meshes3d = undefined;
  },
});

/**
 * Options of `addTriangleMesh3D`.
 * @category Collision
 */
export interface TriangleMeshOptions {
  /** Vertices [x, y, z], m; at least 3. */
  vertices: ArrayLike<ArrayLike<number>>;
  /** Triangles [i, j, k] indexing `vertices`, counter-clockwise seen from the front; at least 1, none of zero area. */
  triangles: ArrayLike<ArrayLike<number>>;
  /** Friction coefficient, >= 0. Default 0.6. */
  friction?: number;
  /** Restitution in [0, 1]. Default 0. */
  restitution?: number;
}

/**
 * Adds a static triangle mesh (3D) and returns its handle.
 * @throws TypeError | RangeError `addTriangleMesh3D: <param> must be ...` in a 2D world, on unknown
 *   options, fewer than 3 vertices or no triangles, non-finite coordinates, an index out of range or not
 *   an integer, a triangle of zero area, negative friction, restitution outside [0, 1], or a full world.
 * @category Collision
 */
export function addTriangleMesh3D(world: PhysicsWorld, options: TriangleMeshOptions): number {
  return addMesh('addTriangleMesh3D', world, options);
}

function addMesh(where: string, world: PhysicsWorld, options: TriangleMeshOptions): number {
  if (world.dimensions !== 3) throw new TypeError(`${where}: needs a 3D world, got dimensions ${world.dimensions}`);
  if (options === null || typeof options !== 'object') throw new TypeError(`${where}: options must be an object, got ${describe(options)}`);
  assertOptions(where, options, ['vertices', 'triangles', 'friction', 'restitution']);
  const V = options.vertices,
    T = options.triangles;
  if (V === null || typeof V !== 'object' || !(V.length >= 3))
    throw new RangeError(`${where}: vertices must hold at least 3 points, got ${describe(V)}`);
  if (T === null || typeof T !== 'object' || !(T.length >= 1))
    throw new RangeError(`${where}: triangles must hold at least 1 triangle, got ${describe(T)}`);
  const friction = options.friction ?? 0.6,
    restitution = options.restitution ?? 0;
  assertNonNegative(where, 'friction', friction);
  assertInRange(where, 'restitution', restitution, 0, 1);
  const verts = new Float64Array(3 * V.length);
  for (let i = 0; i < V.length; i++) {
    assertVector(where, `vertices[${i}]`, V[i], 3);
    verts[3 * i] = V[i]![0]!;
    verts[3 * i + 1] = V[i]![1]!;
    verts[3 * i + 2] = V[i]![2]!;
  }
  const tris = new Int32Array(3 * T.length),
    normals = new Float64Array(3 * T.length),
    bounds = new Float64Array(6 * T.length);
  for (let t = 0; t < T.length; t++) {
    const tri = T[t];
    if (tri === null || typeof tri !== 'object' || tri.length !== 3)
      throw new TypeError(`${where}: triangles[${t}] must be [i, j, k], got ${describe(tri)}`);
    for (let k = 0; k < 3; k++) {
      assertInteger(where, `triangles[${t}][${k}]`, tri[k], 0, V.length - 1);
      tris[3 * t + k] = tri[k]!;
    }
    const a = 3 * tris[3 * t]!,
      b = 3 * tris[3 * t + 1]!,
      c = 3 * tris[3 * t + 2]!;
    const ux = verts[b]! - verts[a]!,
      uy = verts[b + 1]! - verts[a + 1]!,
      uz = verts[b + 2]! - verts[a + 2]!;
    const vx = verts[c]! - verts[a]!,
      vy = verts[c + 1]! - verts[a + 1]!,
      vz = verts[c + 2]! - verts[a + 2]!;
    const nx = uy * vz - uz * vy,
      ny = uz * vx - ux * vz,
      nz = ux * vy - uy * vx,
      l = Math.hypot(nx, ny, nz);
    if (!(l > 1e-12 * (ux * ux + uy * uy + uz * uz + vx * vx + vy * vy + vz * vz)))
      throw new RangeError(`${where}: triangles[${t}] must have a non-zero area, got vertices ${tri[0]}, ${tri[1]}, ${tri[2]}`);
    normals[3 * t] = nx / l;
    normals[3 * t + 1] = ny / l;
    normals[3 * t + 2] = nz / l;
    for (let k = 0; k < 3; k++) {
      bounds[6 * t + k] = Math.min(verts[a + k]!, verts[b + k]!, verts[c + k]!);
      bounds[6 * t + 3 + k] = Math.max(verts[a + k]!, verts[b + k]!, verts[c + k]!);
    }
  }
  const e = createSlot(world, where);
  const c = world.components;
  addComponent(world, e, c.Static);
  addComponent(world, e, c.Material);
  c.Material.friction[e] = friction;
  c.Material.staticFriction[e] = friction;
  c.Material.restitution[e] = restitution;
  meshListOf(world, true)!.list.push({ entity: e, vertices: verts, triangles: tris, normals, bounds });
  return currentHandle(world, e);
}

/**
 * Options of `addHeightField3D`.
 * @category Collision
 */
export interface HeightFieldOptions {
  /** Heights, m: rows along z, each a row of columns along x (at least 2 x 2, all rows the same length). */
  heights: ArrayLike<ArrayLike<number>>;
  /** Spacing of the columns (x) and rows (z), m, each > 0. */
  spacing: ArrayLike<number>;
  /** World position of heights[0][0]'s grid point (its y is added to the heights), m. Default (0, 0, 0). */
  origin?: ArrayLike<number>;
  /** Friction coefficient, >= 0. Default 0.6. */
  friction?: number;
  /** Restitution in [0, 1]. Default 0. */
  restitution?: number;
}

/**
 * Most grid points a height field may have (rows x columns): 65,536, a 256 x 256 grid (130,050
 * triangles). Larger fields are refused before any work (a 1,000 x 1,000 field took 28 s and 570 MB);
 * split a larger terrain into tiles.
 * @category Collision
 */
export const MAX_HEIGHT_FIELD_POINTS = 65_536;

/**
 * Adds a static height field (y up) as a triangle mesh, two triangles a grid cell, facing up; returns
 * its handle. @throws TypeError | RangeError `addHeightField3D: <param> must be ...` on a grid smaller
 * than 2 x 2 or of more than MAX_HEIGHT_FIELD_POINTS points, ragged rows, non-finite heights,
 * non-positive spacing, or the mesh's errors.
 * @category Collision
 */
export function addHeightField3D(world: PhysicsWorld, options: HeightFieldOptions): number {
  const where = 'addHeightField3D';
  if (options === null || typeof options !== 'object') throw new TypeError(`${where}: options must be an object, got ${describe(options)}`);
  assertOptions(where, options, ['heights', 'spacing', 'origin', 'friction', 'restitution']);
  const H = options.heights;
  if (H === null || typeof H !== 'object' || !(H.length >= 2))
    throw new RangeError(`${where}: heights must have at least 2 rows, got ${describe(H)}`);
  const cols = H[0]?.length ?? 0;
  if (!(cols >= 2)) throw new RangeError(`${where}: heights must have at least 2 columns, got ${cols}`);
  if (H.length * cols > MAX_HEIGHT_FIELD_POINTS) {
    throw new RangeError(
      `${where}: heights must have at most ${MAX_HEIGHT_FIELD_POINTS} points (rows x columns; split larger terrain into tiles), got ${H.length} x ${cols}`,
    );
  }
  assertVector(where, 'spacing', options.spacing, 2);
  assertPositive(where, 'spacing[0]', options.spacing[0]);
  assertPositive(where, 'spacing[1]', options.spacing[1]);
  let o = [0, 0, 0];
  if (options.origin !== undefined) {
    assertVector(where, 'origin', options.origin, 3);
    o = [options.origin[0]!, options.origin[1]!, options.origin[2]!];
  }
  const vertices: number[][] = [],
    triangles: number[][] = [];
  for (let r = 0; r < H.length; r++) {
    const row = H[r]!;
    if (row === null || typeof row !== 'object' || row.length !== cols)
      throw new RangeError(`${where}: heights[${r}] must have ${cols} columns like heights[0], got ${describe(row)}`);
    for (let k = 0; k < cols; k++) {
      const y = row[k];
      if (typeof y !== 'number' || !Number.isFinite(y))
        throw new RangeError(`${where}: heights[${r}][${k}] must be a finite number, got ${describe(y)}`);
      vertices.push([o[0]! + k * options.spacing[0]!, o[1]! + y, o[2]! + r * options.spacing[1]!]);
    }
  }
  for (let r = 0; r + 1 < H.length; r++) {
    for (let k = 0; k + 1 < cols; k++) {
      const i = r * cols + k,
        j = i + 1,
        p = i + cols,
        q = p + 1;
      // Counter-clockwise seen from above (+y): x to the right, z towards the viewer.
      triangles.push([i, p, j], [j, p, q]);
    }
  }
  const opts: TriangleMeshOptions = { vertices, triangles };
  if (options.friction !== undefined) opts.friction = options.friction;
  if (options.restitution !== undefined) opts.restitution = options.restitution;
  return addMesh(where, world, opts);
}
