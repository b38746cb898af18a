import { registerFeatureState } from '../world/external-state.js';
import type { PhysicsWorld } from '../world/options.js';
import type { Hull } from './hull-3d.js';

/**
 * Kinds of 3D shapes (the `kind` field of Shape3DStore).
 * @category Shapes
 */
export const Shape3DKind = Object.freeze({ Sphere: 0, Box: 1, Capsule: 2, Cylinder: 3, Hull: 4 } as const);

/**
 * The 3D shapes of a world, indexed by shape entity (slot), structure of arrays. Each shape is its own
 * entity holding its body (a relationship is its own entity), linked in a per-body list, and removed
 * with its body. Placement is in the body frame, which is the principal frame of the body's inertia
 * about its centre of mass (`updateMassFromShapes3D` keeps it so), so a shape's world pose is the
 * body's `Position` and `Orientation` composed with it. Arrays are empty until the first shape.
 * @category Shapes
 */
export interface Shape3DStore {
  /** True once the world has a 3D shape. */
  active: boolean;
  /** The shape's body (slot). */
  body: Int32Array;
  /** Shape3DKind. */
  kind: Uint8Array;
  /** Next shape of the same body (0 ends the list); `first[body]` starts it. */
  next: Int32Array;
  first: Int32Array;
  /** Placement: the shape's centre in the body frame, m. */
  px: Float64Array;
  py: Float64Array;
  pz: Float64Array;
  /** Placement: the shape frame's rotation into the body frame, unit quaternion (x, y, z, w). */
  qx: Float64Array;
  qy: Float64Array;
  qz: Float64Array;
  qw: Float64Array;
  /** Box half extents, m (> 0); capsule and cylinder: `hy` is the half height of the straight part along the shape's y axis. */
  hx: Float64Array;
  hy: Float64Array;
  hz: Float64Array;
  /** Sphere, capsule and cylinder radius, m (> 0); 0 for boxes and hulls. */
  radius: Float64Array;
  /** Bounding radius about the shape's centre, m. */
  reach: Float64Array;
  /** Index into `hulls` of the polyhedron a hull, box or cylinder collides as (-1 for spheres and capsules). Hull vertices are in the shape frame. */
  hull: Int32Array;
  /**
   * The distinct polyhedra of the world's shapes, each kept once: shapes of one geometry (boxes of the
   * same half extents, cylinders of the same radius and half height, hulls of the same point cloud)
   * share one entry, so the list grows with the geometries used, not with the shapes added and removed.
   */
  hulls: Hull[];
  /** Index into `hulls` of each geometry's polyhedron, by its key (bodies/shapes-3d.ts hullKey). */
  hullIndex: Map<string, number>;
  /** Density, kg/m^3 (>= 0). */
  density: Float64Array;
  /** Friction coefficient (>= 0) and restitution ([0, 1]). */
  friction: Float64Array;
  restitution: Float64Array;
  /** Collision filter: category and mask bits (32-bit), group (same non-zero group: > 0 always collide, < 0 never). */
  category: Uint32Array;
  mask: Uint32Array;
  group: Int32Array;
  /** 1: a sensor (reports overlaps, pushes nothing). */
  sensor: Uint8Array;
  /**
   * Per body: where the reference point the user placed shapes about (the body's position when its
   * first shape was added) lies in the current body frame, m, and the rotation from the user's body
   * frame (the orientation then) into the current one, so later shapes are placed where meant.
   */
  originX: Float64Array;
  originY: Float64Array;
  originZ: Float64Array;
  refX: Float64Array;
  refY: Float64Array;
  refZ: Float64Array;
  refW: Float64Array;
}

function createStore(capacity: number): Shape3DStore {
  const n = capacity + 1;
  const f = (): Float64Array => new Float64Array(n);
  const hull = new Int32Array(n).fill(-1);
  return {
    active: false,
    body: new Int32Array(n),
    kind: new Uint8Array(n),
    next: new Int32Array(n),
    first: new Int32Array(n),
    px: f(),
    py: f(),
    pz: f(),
    qx: f(),
    qy: f(),
    qz: f(),
    qw: f(),
    hx: f(),
    hy: f(),
    hz: f(),
    radius: f(),
    reach: f(),
    hull,
    hulls: [],
    hullIndex: new Map(),
    density: f(),
    friction: f(),
    restitution: f(),
    category: new Uint32Array(n),
    mask: new Uint32Array(n),
    group: new Int32Array(n),
    sensor: new Uint8Array(n),
    originX: f(),
    originY: f(),
    originZ: f(),
    refX: f(),
    refY: f(),
    refZ: f(),
    refW: f(),
  };
}

/**
 * The world's 3D shape store, made on first use when `create` is true (else undefined for a world without 3D shapes).
 * @category Shapes
 */
export function shapes3DOf(world: PhysicsWorld, create: true): Shape3DStore;
export function shapes3DOf(world: PhysicsWorld, create?: boolean): Shape3DStore | undefined;
export function shapes3DOf(world: PhysicsWorld, create = false): Shape3DStore | undefined {
  return shapes3D(world, create);
}

/** The world's 3D shape store, registered for snapshots under `shapes3d`. */
const shapes3D = registerFeatureState('shapes3d', (world) => createStore(world.capacity));
