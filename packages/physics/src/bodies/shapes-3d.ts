import { addComponent, entityExists, hasComponent, removeEntity } from 'bitecs';
import { install3D } from '../collision/install-3d.js';
import { multiplyQuaternions, rotateVector, rotationMatrix } from '../math/quaternion.js';
import { shapeEdits } from '../shapes/edits-3d.js';
import { type Hull, MAX_HULL_INPUT, quickhull } from '../shapes/hull-3d.js';
import {
  addMovedInertia,
  boxMass,
  capsuleMass,
  cylinderMass,
  hullMass,
  type MassProperties3D,
  principalAxes,
  sphereMass,
} from '../shapes/mass-3d.js';
import { Shape3DKind, type Shape3DStore, shapes3DOf } from '../shapes/store-3d.js';
import * as check from '../validation/validate.js';
import { createSlot, currentHandle, resolveEntity, resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { assertFilter, assertMaterial, type FilterOptions } from './material.js';
import { setInertiaUnchecked } from './rigid.js';
import { unlinkShape } from './shape-list.js';

/**
 * Shapes of 3D bodies: adding them (a body with several is a compound), and the body's mass, centre
 * of mass and inertia tensor from them and their densities (kg/m^3; formulas in shapes/mass-3d.ts).
 */

/**
 * Options of `addShape3D`. `type` says which of `radius`, `halfExtents`, `halfHeight` and `vertices` apply.
 * @category Shapes
 */
export interface Shape3DOptions extends FilterOptions {
  /** 'sphere' (radius), 'box' (halfExtents), 'capsule' and 'cylinder' (radius, halfHeight, along the shape's y axis), 'hull' (vertices). */
  type: 'sphere' | 'box' | 'capsule' | 'cylinder' | 'hull';
  /** Sphere, capsule or cylinder radius, m, > 0. */
  radius?: number;
  /** Box half extents (hx, hy, hz), m, each > 0. */
  halfExtents?: ArrayLike<number>;
  /** Capsule or cylinder: half the length of the straight part along y, m, > 0. */
  halfHeight?: number;
  /** Hull: a point cloud, 4 to 1024 points [x, y, z] (m, shape frame); the framework keeps their convex hull (quickhull), which must have at most 64 vertices and a volume. */
  vertices?: ArrayLike<ArrayLike<number>>;
  /** Placement: the shape's centre from the body's reference point (its position when its first shape was added), body frame, m. Default (0, 0, 0). */
  offset?: ArrayLike<number>;
  /** Placement: the shape's rotation in the body frame, quaternion (x, y, z, w), normalised here. Default identity. */
  rotation?: ArrayLike<number>;
  /** Density, kg/m^3, >= 0. Default 1000 (water). A dynamic body's mass and inertia become the sum over its shapes. */
  density?: number;
  /** Friction coefficient, >= 0. Default 0.6. */
  friction?: number;
  /** Restitution in [0, 1]. Default 0. */
  restitution?: number;
  /** A sensor reports overlaps and pushes nothing. Default false. */
  sensor?: boolean;
}

const OPTIONS = [
  'type',
  'radius',
  'halfExtents',
  'halfHeight',
  'vertices',
  'offset',
  'rotation',
  'density',
  'friction',
  'restitution',
  'sensor',
  'category',
  'mask',
  'group',
] as const;
const APPLIES: Record<Shape3DOptions['type'], ReadonlyArray<keyof Shape3DOptions>> = {
  sphere: ['radius'],
  box: ['halfExtents'],
  capsule: ['radius', 'halfHeight'],
  cylinder: ['radius', 'halfHeight'],
  hull: ['vertices'],
};
const GEOMETRY: ReadonlyArray<keyof Shape3DOptions> = ['radius', 'halfExtents', 'halfHeight', 'vertices'];

/** A checked geometry, before it is stored. */
interface Geometry {
  kind: number;
  r: number;
  hx: number;
  hy: number;
  hz: number;
  /** The polyhedron it collides as (null for spheres and capsules), and its key in the store's `hullIndex`. */
  hull: Hull | null;
  key: string;
}

/**
 * The polyhedron of geometry `key`: the world's own when a shape of that geometry was added before
 * (shapes of one geometry share it, see Shape3DStore.hulls), else `make()`'s, stored by `storeHull`
 * once the shape is added.
 */
function sharedHull(s: Shape3DStore | undefined, key: string, make: () => Hull): Hull {
  const i = s?.hullIndex.get(key);
  return i === undefined ? make() : s!.hulls[i]!;
}

/** Index into `s.hulls` of geometry g's polyhedron, stored there (and in `hullIndex`) if new. */
function storeHull(s: Shape3DStore, g: Geometry): number {
  let i = s.hullIndex.get(g.key);
  if (i === undefined) {
    i = s.hulls.length;
    s.hulls.push(g.hull!);
    s.hullIndex.set(g.key, i);
  }
  return i;
}

function geometryOf(where: string, o: Shape3DOptions, s: Shape3DStore | undefined): Geometry {
  const t = o.type;
  if (!(typeof t === 'string' && Object.hasOwn(APPLIES, t)))
    throw new TypeError(`${where}: type must be one of 'sphere', 'box', 'capsule', 'cylinder', 'hull', got ${check.describe(t)}`);
  for (const k of GEOMETRY)
    if (o[k] !== undefined && !APPLIES[t].includes(k)) throw new TypeError(`${where}: ${k} does not apply to a ${t}`);
  switch (t) {
    case 'sphere':
      check.assertPositive(where, 'radius', o.radius);
      return { kind: Shape3DKind.Sphere, r: o.radius, hx: 0, hy: 0, hz: 0, hull: null, key: '' };
    case 'box': {
      check.assertVector(where, 'halfExtents', o.halfExtents, 3);
      const h = o.halfExtents!;
      for (let i = 0; i < 3; i++) check.assertPositive(where, `halfExtents[${i}]`, h[i]);
      const key = `box ${h[0]} ${h[1]} ${h[2]}`;
      const hull = sharedHull(s, key, () => {
        const corners: number[][] = [];
        for (const x of [-h[0]!, h[0]!]) for (const y of [-h[1]!, h[1]!]) for (const z of [-h[2]!, h[2]!]) corners.push([x, y, z]);
        return quickhull(where, corners);
      });
      return { kind: Shape3DKind.Box, r: 0, hx: h[0]!, hy: h[1]!, hz: h[2]!, hull, key };
    }
    case 'capsule':
    case 'cylinder': {
      check.assertPositive(where, 'radius', o.radius);
      check.assertPositive(where, 'halfHeight', o.halfHeight);
      const key = `cylinder ${o.radius} ${o.halfHeight}`;
      return {
        kind: t === 'capsule' ? Shape3DKind.Capsule : Shape3DKind.Cylinder,
        r: o.radius,
        hx: 0,
        hy: o.halfHeight,
        hz: 0,
        hull: t === 'cylinder' ? sharedHull(s, key, () => cylinderHull(where, o.radius!, o.halfHeight!)) : null,
        key: t === 'cylinder' ? key : '',
      };
    }
    case 'hull': {
      if (o.vertices === undefined) throw new TypeError(`${where}: vertices must be given for a hull, got undefined`);
      const v = o.vertices;
      // The key holds the points only once they are known to be an array of arrays (quickhull checks
      // the rest); a cloud that is not one is never shared.
      const key =
        Array.isArray(v) && v.length <= MAX_HULL_INPUT && v.every((p) => Array.isArray(p) || ArrayBuffer.isView(p))
          ? `hull ${v.map((p) => Array.from(p as ArrayLike<number>).join(' ')).join(',')}`
          : '';
      const hull = key === '' ? quickhull(where, v) : sharedHull(s, key, () => quickhull(where, v));
      return { kind: Shape3DKind.Hull, r: 0, hx: 0, hy: 0, hz: 0, hull, key };
    }
  }
}

/**
 * Sides of the prism a cylinder collides as (its mass properties are the exact cylinder's).
 * @category Shapes
 */
export const CYLINDER_SIDES = 16;

/** The prism of CYLINDER_SIDES sides inscribed in a cylinder of radius r and half height hh along y. */
function cylinderHull(where: string, r: number, hh: number): Hull {
  const pts: number[][] = [];
  for (let i = 0; i < CYLINDER_SIDES; i++) {
    const a = (2 * Math.PI * i) / CYLINDER_SIDES;
    pts.push([r * Math.cos(a), -hh, r * Math.sin(a)], [r * Math.cos(a), hh, r * Math.sin(a)]);
  }
  return quickhull(where, pts);
}

/** Mass properties of shape `e` of the store, in its own frame. */
function shapeMass(s: Shape3DStore, e: number): MassProperties3D {
  const rho = s.density[e]!;
  switch (s.kind[e]) {
    case Shape3DKind.Sphere:
      return sphereMass(rho, s.radius[e]!);
    case Shape3DKind.Box:
      return boxMass(rho, s.hx[e]!, s.hy[e]!, s.hz[e]!);
    case Shape3DKind.Capsule:
      return capsuleMass(rho, s.radius[e]!, s.hy[e]!);
    case Shape3DKind.Cylinder:
      return cylinderMass(rho, s.radius[e]!, s.hy[e]!);
    default:
      return hullMass(rho, s.hulls[s.hull[e]!]!);
  }
}

/**
 * Adds a shape to a 3D body and returns the shape's handle (its own entity, removed with its body).
 * Several shapes on one body make a compound. On a dynamic body the mass, centre of mass and inertia
 * tensor are recomputed from all its shapes (`updateMassFromShapes3D`); a static or kinematic body
 * keeps infinite mass.
 * @param body a 3D body's handle (addBody).
 * @throws TypeError | RangeError `addShape3D: <param> must be ...` in a 2D world, on a removed entity or
 *   one that is not a body, a ball body (made with addBody's `radius`: give the sphere as a 'sphere'
 *   shape of a body without radius instead), an unknown type or option, a geometry option that does not apply to the
 *   type, non-positive radius, half height or half extents, a degenerate hull (fewer than 4 points,
 *   all on a plane, or more than 64 hull vertices), negative density or friction, restitution outside
 *   [0, 1], a zero rotation quaternion, filter bits that are not integers of their range, or a full
 *   world. A call that throws changes nothing.
 * @example
 * const crate = addBody(world, { position: [0, 3, 0] });
 * addShape3D(world, crate, { type: 'box', halfExtents: [0.5, 0.5, 0.5], density: 500 });
 * @category Shapes
 */
export function addShape3D(world: PhysicsWorld, body: number, options: Shape3DOptions): number {
  const where = 'addShape3D';
  if (world.dimensions !== 3) throw new TypeError(`${where}: 3D shapes need a 3D world; this world has 2 dimensions`);
  const b = resolveKind(world, body, 'body', where, 'body');
  const balls = world.components.Ball;
  if (hasComponent(world, b, balls) && balls.radius[b]! > 0) {
    // A ball body is a sphere collider of the ball narrowphase with the mass addBody gave it; shapes would
    // replace that mass with theirs while the ball kept colliding. One body, one kind of collider.
    throw new RangeError(
      `${where}: body must be a body without a ball radius (addBody's radius makes it a ball; give the sphere as a shape instead: { type: 'sphere', radius }), got body ${check.describe(body)} with radius ${balls.radius[b]}`,
    );
  }
  check.assertOptions(where, options, OPTIONS);
  check.assertOptionalBoolean(where, 'sensor', options.sensor);
  const g = geometryOf(where, options, shapes3DOf(world));
  let ox = 0,
    oy = 0,
    oz = 0,
    rx = 0,
    ry = 0,
    rz = 0,
    rw = 1;
  if (options.offset !== undefined) {
    check.assertVector(where, 'offset', options.offset, 3);
    ox = options.offset[0]!;
    oy = options.offset[1]!;
    oz = options.offset[2]!;
  }
  if (options.rotation !== undefined) {
    check.assertVector(where, 'rotation', options.rotation, 4);
    const q = options.rotation;
    const l = Math.hypot(q[0]!, q[1]!, q[2]!, q[3]!);
    if (!(l > 0)) throw new RangeError(`${where}: rotation must be a non-zero quaternion (x, y, z, w), got ${check.describe(q)}`);
    rx = q[0]! / l;
    ry = q[1]! / l;
    rz = q[2]! / l;
    rw = q[3]! / l;
  }
  const density = check.optionOr(where, 'density', options.density, 1000, check.assertNonNegative);
  assertMaterial(where, options);
  assertFilter(where, options);
  const friction = options.friction ?? 0.6,
    restitution = options.restitution ?? 0;
  const category = options.category ?? 1,
    mask = options.mask ?? 0xffffffff,
    group = options.group ?? 0;
  for (const v of [ox, oy, oz]) check.assertFinite(where, 'offset', v);

  const e = createSlot(world, where); // throws on a full world before anything changed
  const s = shapes3DOf(world, true);
  shapeEdits.count++;
  if (!s.active) {
    install3D(world);
    s.active = true;
    world.removeHooks.push(removeShapes3DOf);
  }
  const c = world.components;
  if (s.first[b] === 0) {
    s.originX[b] = 0;
    s.originY[b] = 0;
    s.originZ[b] = 0;
    s.refX[b] = 0;
    s.refY[b] = 0;
    s.refZ[b] = 0;
    s.refW[b] = 1;
  }
  // Into the current body frame: p = origin + ref (offset), q = ref * rotation.
  const v = rotate(s.refX[b]!, s.refY[b]!, s.refZ[b]!, s.refW[b]!, ox, oy, oz);
  multiplyQuaternions(s.refX[b]!, s.refY[b]!, s.refZ[b]!, s.refW[b]!, rx, ry, rz, rw, q4);
  s.body[e] = b;
  s.kind[e] = g.kind;
  s.next[e] = 0;
  s.px[e] = s.originX[b]! + v[0];
  s.py[e] = s.originY[b]! + v[1];
  s.pz[e] = s.originZ[b]! + v[2];
  s.qx[e] = q4[0]!;
  s.qy[e] = q4[1]!;
  s.qz[e] = q4[2]!;
  s.qw[e] = q4[3]!;
  s.hx[e] = g.hx;
  s.hy[e] = g.hy;
  s.hz[e] = g.hz;
  s.radius[e] = g.r;
  s.hull[e] = g.hull === null ? -1 : storeHull(s, g);
  let reach = g.r + g.hy;
  if (g.hull !== null) {
    const V = g.hull.vertices;
    for (let i = 0; i < V.length; i += 3) reach = Math.max(reach, Math.hypot(V[i]!, V[i + 1]!, V[i + 2]!));
  }
  s.reach[e] = reach;
  s.density[e] = density;
  s.friction[e] = friction;
  s.restitution[e] = restitution;
  s.category[e] = category;
  s.mask[e] = mask;
  s.group[e] = group;
  s.sensor[e] = options.sensor === true ? 1 : 0;
  if (s.first[b] === 0) s.first[b] = e;
  else {
    let last = s.first[b]!;
    while (s.next[last] !== 0) last = s.next[last]!;
    s.next[last] = e;
  }
  if (!hasComponent(world, b, c.Orientation)) {
    addComponent(world, b, c.Orientation);
    c.Orientation.x[b] = 0;
    c.Orientation.y[b] = 0;
    c.Orientation.z[b] = 0;
    c.Orientation.w[b] = 1;
  }
  if (!hasComponent(world, b, c.Static) && !hasComponent(world, b, c.Kinematic)) updateMassFromShapes3D(world, body);
  return currentHandle(world, e);
}

/**
 * Recomputes a dynamic 3D body's mass, centre of mass and inertia tensor from its shapes (formulas and
 * sources in shapes/mass-3d.ts). The body's `Position` moves to the new centre of mass (its velocity
 * becomes that point's, v + w x d) and its `Orientation` turns to the principal axes of the tensor, so
 * `InertiaTensor` holds the principal moments; the shapes are re-expressed in that frame, and so is the
 * reference point later shapes are placed about. Shapes of zero total mass leave mass and inertia as
 * they were. Called by `addShape3D`.
 * @throws RangeError on a removed entity or one that is not a body.
 * @category Shapes
 */
export function updateMassFromShapes3D(world: PhysicsWorld, body: number): void {
  const b = resolveKind(world, body, 'body', 'updateMassFromShapes3D', 'body');
  const s = shapes3DOf(world);
  if (s === undefined || s.first[b] === 0) return;
  shapeEdits.count++;
  let m = 0,
    sx = 0,
    sy = 0,
    sz = 0;
  const props: Array<[number, MassProperties3D]> = [];
  for (let e = s.first[b]!; e !== 0; e = s.next[e]!) {
    const p = shapeMass(s, e);
    const cw = rotate(s.qx[e]!, s.qy[e]!, s.qz[e]!, s.qw[e]!, p.center[0], p.center[1], p.center[2]);
    const gx = s.px[e]! + cw[0],
      gy = s.py[e]! + cw[1],
      gz = s.pz[e]! + cw[2];
    m += p.mass;
    sx += p.mass * gx;
    sy += p.mass * gy;
    sz += p.mass * gz;
    p.center = [gx, gy, gz];
    props.push([e, p]);
  }
  if (!(m > 0)) return;
  const cx = sx / m,
    cy = sy / m,
    cz = sz / m;
  const I = new Float64Array(9),
    R = new Float64Array(9);
  for (const [e, p] of props) {
    rotationMatrix(s.qx[e]!, s.qy[e]!, s.qz[e]!, s.qw[e]!, R, 0);
    addMovedInertia(I, p.mass, p.inertia, R, p.center[0] - cx, p.center[1] - cy, p.center[2] - cz);
  }
  const values = new Float64Array(3),
    axes = new Float64Array(9);
  principalAxes(I, values, axes);
  const [ax, ay, az, aw] = quaternionOf(axes);
  // Re-express shapes and the reference frame about the centre of mass in the principal frame: p' = A^T (p - c), q' = a^-1 q.
  const reframe = (x: number, y: number, z: number): [number, number, number] => rotate(-ax, -ay, -az, aw, x - cx, y - cy, z - cz);
  for (let e = s.first[b]!; e !== 0; e = s.next[e]!) {
    const p = reframe(s.px[e]!, s.py[e]!, s.pz[e]!);
    s.px[e] = p[0];
    s.py[e] = p[1];
    s.pz[e] = p[2];
    multiplyQuaternions(-ax, -ay, -az, aw, s.qx[e]!, s.qy[e]!, s.qz[e]!, s.qw[e]!, q4);
    s.qx[e] = q4[0]!;
    s.qy[e] = q4[1]!;
    s.qz[e] = q4[2]!;
    s.qw[e] = q4[3]!;
  }
  const o = reframe(s.originX[b]!, s.originY[b]!, s.originZ[b]!);
  s.originX[b] = o[0];
  s.originY[b] = o[1];
  s.originZ[b] = o[2];
  multiplyQuaternions(-ax, -ay, -az, aw, s.refX[b]!, s.refY[b]!, s.refZ[b]!, s.refW[b]!, q4);
  s.refX[b] = q4[0]!;
  s.refY[b] = q4[1]!;
  s.refZ[b] = q4[2]!;
  s.refW[b] = q4[3]!;
  // The body: position to the centre of mass, orientation to the principal frame.
  const c = world.components,
    Q = c.Orientation;
  const bx = Q.x[b]!,
    by = Q.y[b]!,
    bz = Q.z[b]!,
    bw = Q.w[b]!;
  const d = rotate(bx, by, bz, bw, cx, cy, cz);
  c.Position.x[b] = c.Position.x[b]! + d[0];
  c.Position.y[b] = c.Position.y[b]! + d[1];
  c.Position.z[b] = c.Position.z[b]! + d[2];
  c.PreviousPosition.x[b] = c.PreviousPosition.x[b]! + d[0];
  c.PreviousPosition.y[b] = c.PreviousPosition.y[b]! + d[1];
  c.PreviousPosition.z[b] = c.PreviousPosition.z[b]! + d[2];
  if (hasComponent(world, b, c.AngularVelocity)) {
    const W = c.AngularVelocity,
      wx = W.x[b]!,
      wy = W.y[b]!,
      wz = W.z[b]!;
    c.Velocity.x[b] = c.Velocity.x[b]! + wy * d[2] - wz * d[1];
    c.Velocity.y[b] = c.Velocity.y[b]! + wz * d[0] - wx * d[2];
    c.Velocity.z[b] = c.Velocity.z[b]! + wx * d[1] - wy * d[0];
  }
  multiplyQuaternions(bx, by, bz, bw, ax, ay, az, aw, q4);
  Q.x[b] = q4[0]!;
  Q.y[b] = q4[1]!;
  Q.z[b] = q4[2]!;
  Q.w[b] = q4[3]!;
  c.Mass.value[b] = m;
  c.Mass.inv[b] = 1 / m;
  const floor = 1e-12 * Math.max(values[0]!, values[1]!, values[2]!);
  setInertiaUnchecked(world, b, [Math.max(values[0]!, floor), Math.max(values[1]!, floor), Math.max(values[2]!, floor)]);
}

/**
 * The 3D shape handles of a body, in the order added. @throws RangeError on a removed entity or one that is not a body.
 * @category Shapes
 */
export function shapes3DOfBody(world: PhysicsWorld, body: number): number[] {
  const b = resolveKind(world, body, 'body', 'shapes3DOfBody', 'body');
  const s = shapes3DOf(world);
  const out: number[] = [];
  if (s === undefined) return out;
  for (let e = s.first[b]!; e !== 0; e = s.next[e]!) out.push(currentHandle(world, e));
  return out;
}

/**
 * The convex hull a hull shape keeps (vertices in the shape frame); boxes and cylinders answer with the
 * polyhedron they collide as. Shapes of one geometry share one hull object (see Shape3DStore.hulls), so
 * it is to be read, not changed. @throws RangeError on a handle that is not a hull, box or cylinder shape.
 * @category Shapes
 */
export function hullOfShape3D(world: PhysicsWorld, shape: number): Hull {
  const e = resolveEntity(world, shape, 'hullOfShape3D', 'shape');
  const s = shapes3DOf(world);
  if (s === undefined || s.body[e] === 0 || s.hull[e]! < 0)
    throw new RangeError(`hullOfShape3D: shape must be a hull shape, got id ${check.describe(shape)}`);
  return s.hulls[s.hull[e]!]!;
}

/** Removal hook: removing a body removes its 3D shape entities (and a removed shape leaves its body's list). */
function removeShapes3DOf(world: PhysicsWorld, eid: number): void {
  const s = shapes3DOf(world);
  if (s === undefined) return;
  if (s.body[eid] !== 0 && s.first[eid] === 0) {
    // A shape removed on its own: unlink it.
    const b = s.body[eid]!;
    unlinkShape(s.first, s.next, b, eid);
    s.body[eid] = 0;
    s.next[eid] = 0;
    return;
  }
  let e = s.first[eid]!;
  s.first[eid] = 0;
  while (e !== 0) {
    const next = s.next[e]!;
    s.body[e] = 0;
    s.next[e] = 0;
    if (entityExists(world, e)) removeEntity(world, e);
    e = next;
  }
}

const v3 = new Float64Array(3),
  q4 = new Float64Array(4);

/** v rotated by the unit quaternion q (math/quaternion.ts rotateVector), as a tuple. */
function rotate(qx: number, qy: number, qz: number, qw: number, vx: number, vy: number, vz: number): [number, number, number] {
  rotateVector(qx, qy, qz, qw, vx, vy, vz, v3);
  return [v3[0]!, v3[1]!, v3[2]!];
}

/**
 * The unit quaternion of a rotation matrix (row-major, det +1); Shepperd's method (J. Guidance and Control 1(3), 1978).
 * @category Shapes
 */
function quaternionOf(R: Float64Array): [number, number, number, number] {
  const tr = R[0]! + R[4]! + R[8]!;
  let x: number, y: number, z: number, w: number;
  if (tr > 0) {
    const k = 2 * Math.sqrt(tr + 1);
    w = 0.25 * k;
    x = (R[7]! - R[5]!) / k;
    y = (R[2]! - R[6]!) / k;
    z = (R[3]! - R[1]!) / k;
  } else if (R[0]! > R[4]! && R[0]! > R[8]!) {
    const k = 2 * Math.sqrt(1 + R[0]! - R[4]! - R[8]!);
    w = (R[7]! - R[5]!) / k;
    x = 0.25 * k;
    y = (R[1]! + R[3]!) / k;
    z = (R[2]! + R[6]!) / k;
  } else if (R[4]! > R[8]!) {
    const k = 2 * Math.sqrt(1 + R[4]! - R[0]! - R[8]!);
    w = (R[2]! - R[6]!) / k;
    x = (R[1]! + R[3]!) / k;
    y = 0.25 * k;
    z = (R[5]! + R[7]!) / k;
  } else {
    const k = 2 * Math.sqrt(1 + R[8]! - R[0]! - R[4]!);
    w = (R[3]! - R[1]!) / k;
    x = (R[2]! + R[6]!) / k;
    y = (R[5]! + R[7]!) / k;
    z = 0.25 * k;
  }
  const l = Math.hypot(x, y, z, w);
  return [x / l, y / l, z / l, w / l];
}
