import { addComponent, entityExists, hasComponent, removeEntity } from 'bitecs';
import { ensureShapeState } from '../collision/manifolds-2d.js';
import { type ConvexGeometry, makeBox, makeCapsule, makeCircle, makePolygon, transformGeometry } from '../shapes/geometry-2d.js';
import { shapeMassProperties } from '../shapes/mass-2d.js';
import * as check from '../validation/validate.js';
import { currentHandle, resolveEntity, resolveKind, slotOf } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addComponentIfMissing } from '../world/options.js';
import { ensureShapeStore, SHAPE_STRIDE } from '../world/shape-store-2d.js';
import { addBodyAs, type BodyOptions, createSlot } from './api.js';
import { assertFilter, assertMaterial, type FilterOptions, type MaterialOptions, writeMaterial } from './material.js';
import { unlinkShape } from './shape-list.js';

/**
 * Shapes of 2D bodies: adding them, their filter, and the body's mass from them.
 *
 * Layout (see `Components.Shape`): a body's first shape lives on the body entity itself; each further
 * shape of a compound is its own entity holding its body (a relationship is its own entity), linked in
 * a per-body list, and is removed with the body. Shape geometry is stored in the body frame about the
 * body's centre of mass, so the narrowphase needs only the body's position and angle.
 */

/**
 * Options of `addShape`. Exactly one of `radius` (circle), `halfExtents` (box), `vertices` (polygon) or `center1`/`center2` (capsule, with `radius`) describes the geometry.
 * @category Shapes
 */
export interface ShapeOptions extends MaterialOptions, FilterOptions {
  /** 'circle', 'box', 'polygon' or 'capsule'. */
  type: 'circle' | 'box' | 'polygon' | 'capsule';
  /** Circle or capsule radius, m, > 0; polygon or box corner rounding, m, >= 0 (default 0). */
  radius?: number;
  /** Box half extents (hx, hy), m, each > 0. */
  halfExtents?: ArrayLike<number>;
  /** Polygon vertices, 3 to 8 points [x, y] (m), convex, either winding. */
  vertices?: ArrayLike<ArrayLike<number>>;
  /** Capsule: first end-cap centre, m. */
  center1?: ArrayLike<number>;
  /** Capsule: second end-cap centre, m (must differ from center1). */
  center2?: ArrayLike<number>;
  /** Placement in the body frame: the shape's origin from the body's reference point (its position when created), m. Default (0, 0). */
  offset?: ArrayLike<number>;
  /** Placement: the shape's angle in the body frame, rad. Default 0. */
  angle?: number;
  /** Areal density, kg/m^2, >= 0. Default 1. A dynamic body's mass and inertia become the sum over its shapes. */
  density?: number;
  /** Rolling resistance coefficient (circles and capsules), >= 0: the contact resists rolling with a torque up to coefficient x radius x normal force. Default 0. */
  rollingResistance?: number;
  /** A sensor reports overlaps (sensor events) and pushes nothing. Default false. */
  sensor?: boolean;
}

const SHAPE_OPTIONS = [
  'type',
  'radius',
  'halfExtents',
  'vertices',
  'center1',
  'center2',
  'offset',
  'angle',
  'density',
  'friction',
  'staticFriction',
  'restitution',
  'rollingResistance',
  'sensor',
  'category',
  'mask',
  'group',
] as const;

/** The slot of the live 2D body `body` (a handle), for the shape functions. */
function resolveShapeBody(where: string, world: PhysicsWorld, body: unknown): number {
  return resolveKind(world, body, 'body', where, 'body');
}

/** Builds and checks the geometry of `options` in the shape's own frame. */
function geometryOf(where: string, o: ShapeOptions): ConvexGeometry {
  const forbid = (keys: Array<keyof ShapeOptions>): void => {
    for (const k of keys) if (o[k] !== undefined) throw new TypeError(`${where}: ${k} does not apply to a ${o.type}`);
  };
  switch (o.type) {
    case 'circle':
      forbid(['halfExtents', 'vertices', 'center1', 'center2']);
      check.assertPositive(where, 'radius', o.radius);
      return makeCircle(where, o.radius);
    case 'box': {
      forbid(['vertices', 'center1', 'center2']);
      check.assertVector(where, 'halfExtents', o.halfExtents, 2);
      return makeBox(where, o.halfExtents[0]!, o.halfExtents[1]!, 0, 0, 0, o.radius ?? 0);
    }
    case 'polygon':
      forbid(['halfExtents', 'center1', 'center2']);
      if (!Array.isArray(o.vertices))
        throw new TypeError(`${where}: vertices must be an array of 3 to 8 points [x, y], got ${check.describe(o.vertices)}`);
      return makePolygon(where, o.vertices, o.radius ?? 0);
    case 'capsule':
      forbid(['halfExtents', 'vertices']);
      check.assertVector(where, 'center1', o.center1, 2);
      check.assertVector(where, 'center2', o.center2, 2);
      check.assertPositive(where, 'radius', o.radius);
      return makeCapsule(where, o.center1[0]!, o.center1[1]!, o.center2[0]!, o.center2[1]!, o.radius);
    default:
      throw new RangeError(
        `${where}: type must be one of 'circle', 'box', 'polygon', 'capsule', got ${check.describe((o as { type: unknown }).type)}`,
      );
  }
}

/**
 * Adds a convex shape to a 2D body. The first shape goes on the body's entity; later shapes (or any
 * shape of a body that is a ball) get an entity of their own. A dynamic body's mass, centre of mass and
 * moment of inertia are then recomputed from all its shapes with density > 0 (shapes/mass-2d.ts): the
 * body's `Position` moves to the new centre of mass (its reference point stays where it was), and
 * `setMass` / `setInertia` called afterwards override the result. Static and kinematic bodies keep
 * infinite mass.
 *
 * @returns the shape's entity (the body itself for its first shape).
 * @throws TypeError on a 3D world, an unknown option, or a field of the wrong type or kind.
 * @throws RangeError on a missing body, radius <= 0 (circle, capsule) or < 0, zero or negative half
 *   extents, a polygon that is not convex or has fewer than 3 or more than 8 vertices, negative density,
 *   friction or rolling resistance, restitution outside [0, 1], filter bits that are not 32-bit integers,
 *   or a full world. A call that throws changes nothing.
 * @example
 * const crate = addBody(world, { position: [0, 3] });
 * addShape(world, crate, { type: 'box', halfExtents: [0.5, 0.5], density: 2 });
 * @category Shapes
 */
export function addShape(world: PhysicsWorld, body: number, options: ShapeOptions): number {
  const where = 'addShape';
  if (world.dimensions !== 2) throw new TypeError(`${where}: shapes are 2D; this world has 3 dimensions`);
  const b = resolveShapeBody(where, world, body);
  return currentHandle(world, addShapeToSlot(world, b, options, where));
}

/** Checks `addShape`'s options (everything but the body and the world's room). @throws as addShape. */
function checkShapeOptions(where: string, options: ShapeOptions): void {
  check.assertOptions(where, options, SHAPE_OPTIONS);
  check.assertOptionalBoolean(where, 'sensor', options.sensor);
  geometryOf(where, options);
  if (options.offset !== undefined) check.assertVector(where, 'offset', options.offset, 2);
  if (options.angle !== undefined) check.assertFinite(where, 'angle', options.angle);
  if (options.density !== undefined) check.assertNonNegative(where, 'density', options.density);
  assertMaterial(where, options);
  if (options.rollingResistance !== undefined) check.assertNonNegative(where, 'rollingResistance', options.rollingResistance);
  assertFilter(where, options);
}

/** `addShape` on the body in slot `body` (already resolved); returns the shape's slot. */
function addShapeToSlot(world: PhysicsWorld, body: number, options: ShapeOptions, where: string): number {
  checkShapeOptions(where, options);
  const g = geometryOf(where, options);
  let ox = 0,
    oy = 0,
    angle = 0;
  if (options.offset !== undefined) {
    ox = options.offset[0]!;
    oy = options.offset[1]!;
  }
  if (options.angle !== undefined) angle = options.angle;
  const density = options.density ?? 1,
    rolling = options.rollingResistance ?? 0;
  const category = options.category ?? 1,
    mask = options.mask ?? 0xffffffff,
    group = options.group ?? 0;

  const c = world.components;
  const onBody = !hasComponent(world, body, c.Shape) && !hasComponent(world, body, c.Ball);
  const e = onBody ? body : createSlot(world, where); // throws on a full world before anything changed
  const st = world.collision.shapes;
  ensureShapeStore(c.Shape, world.capacity);
  if (st.firstShape.length === 0) {
    ensureShapeState(st, world.capacity);
    world.removeHooks.push(removeShapesOf);
  }
  if (!hasComponent(world, body, c.Shape) && !hasShapes(world, body)) {
    st.originX[body] = 0;
    st.originY[body] = 0;
  }
  st.active = true;

  // Into the body frame about the centre of mass: placement, then the body's reference point.
  transformGeometry(g, ox + st.originX[body]!, oy + st.originY[body]!, angle);
  const S = c.Shape;
  addComponent(world, e, c.Shape);
  S.body[e] = body;
  S.kind[e] = g.kind;
  S.count[e] = g.count;
  S.radius[e] = g.radius;
  const o = SHAPE_STRIDE * e;
  for (let i = 0; i < SHAPE_STRIDE; i++) {
    S.vx[o + i] = i < g.count ? g.vx[i]! : 0;
    S.vy[o + i] = i < g.count ? g.vy[i]! : 0;
    S.nx[o + i] = i < g.count ? g.nx[i]! : 0;
    S.ny[o + i] = i < g.count ? g.ny[i]! : 0;
  }
  S.category[e] = category;
  S.mask[e] = mask;
  S.group[e] = group;
  S.sensor[e] = options.sensor === true ? 1 : 0;
  S.density[e] = density;
  S.rollingResistance[e] = rolling;
  S.next[e] = 0;
  addComponentIfMissing(world, e, c.Material);
  writeMaterial(world, e, options);
  if (!onBody) {
    // Append to the body's list of extra shapes.
    let last = st.firstShape[body]!;
    if (last === 0) st.firstShape[body] = e;
    else {
      while (S.next[last]! !== 0) last = S.next[last]!;
      S.next[last] = e;
    }
  }
  if (!hasComponent(world, body, c.Static) && !hasComponent(world, body, c.Kinematic)) massFromShapes(world, body);
  else {
    // Static and kinematic bodies still turn with their angle (and kinematic ones with their angular velocity).
    addComponentIfMissing(world, body, c.Angle);
  }
  return e;
}

function hasShapes(world: PhysicsWorld, body: number): boolean {
  const st = world.collision.shapes;
  return st.firstShape.length > 0 && st.firstShape[body]! !== 0;
}

/**
 * Recomputes a dynamic body's mass, centre of mass and moment of inertia from its shapes (density
 * kg/m^2; formulas in shapes/mass-2d.ts; moments combined about the common centre of mass by the
 * parallel-axis theorem). The body moves so that `Position` is the new centre of mass and its shapes
 * are re-expressed about it; its velocity becomes that of the new centre (v + w x d). Shapes of zero
 * total mass leave mass and inertia as they were. Called by `addShape`.
 * @param body a 2D body's handle.
 * @throws RangeError on a removed entity or one that is not a body.
 * @category Shapes
 */
export function updateMassFromShapes(world: PhysicsWorld, body: number): void {
  massFromShapes(world, resolveShapeBody('updateMassFromShapes', world, body));
}

/** `updateMassFromShapes` on the body in slot `body`. */
function massFromShapes(world: PhysicsWorld, body: number): void {
  const c = world.components,
    S = c.Shape,
    st = world.collision.shapes;
  const g = scratchGeometry;
  let m = 0,
    sx = 0,
    sy = 0,
    J = 0;
  forEachShape(world, body, (e) => {
    readGeometry(S, e, g);
    const p = shapeMassProperties(g, S.density[e]!);
    m += p.mass;
    sx += p.mass * p.cx;
    sy += p.mass * p.cy;
    J += p.inertia + p.mass * (p.cx * p.cx + p.cy * p.cy);
  });
  if (!(m > 0)) return;
  const cx = sx / m,
    cy = sy / m;
  const I = J - m * (cx * cx + cy * cy);
  // Shift the shapes so the body frame's origin is the centre of mass.
  if (cx !== 0 || cy !== 0) {
    forEachShape(world, body, (e) => {
      const o = SHAPE_STRIDE * e;
      for (let i = 0; i < S.count[e]!; i++) {
        S.vx[o + i] = S.vx[o + i]! - cx;
        S.vy[o + i] = S.vy[o + i]! - cy;
      }
    });
    st.originX[body] = st.originX[body]! - cx;
    st.originY[body] = st.originY[body]! - cy;
    const a = hasComponent(world, body, c.Angle) ? c.Angle.value[body]! : 0;
    const ca = Math.cos(a),
      sa = Math.sin(a);
    const dx = ca * cx - sa * cy,
      dy = sa * cx + ca * cy;
    c.Position.x[body] = c.Position.x[body]! + dx;
    c.Position.y[body] = c.Position.y[body]! + dy;
    c.PreviousPosition.x[body] = c.PreviousPosition.x[body]! + dx;
    c.PreviousPosition.y[body] = c.PreviousPosition.y[body]! + dy;
    if (hasComponent(world, body, c.AngularVelocity)) {
      const w = c.AngularVelocity.z[body]!;
      c.Velocity.x[body] = c.Velocity.x[body]! - w * dy;
      c.Velocity.y[body] = c.Velocity.y[body]! + w * dx;
    }
  }
  c.Mass.value[body] = m;
  c.Mass.inv[body] = 1 / m;
  addComponentIfMissing(world, body, c.AngularVelocity);
  addComponentIfMissing(world, body, c.Torque);
  addComponentIfMissing(world, body, c.Angle);
  addComponentIfMissing(world, body, c.Inertia);
  if (I > 0) {
    c.Inertia.value[body] = I;
    c.Inertia.inv[body] = 1 / I;
  }
}

const scratchGeometry: ConvexGeometry = {
  kind: 0,
  count: 0,
  radius: 0,
  vx: new Float64Array(8),
  vy: new Float64Array(8),
  nx: new Float64Array(8),
  ny: new Float64Array(8),
};

/**
 * Copies shape entity `e`'s stored geometry (body frame) into `g`.
 * @category Shapes
 */
function readGeometry(S: PhysicsWorld['components']['Shape'], e: number, g: ConvexGeometry): void {
  const n = S.count[e]!,
    o = SHAPE_STRIDE * e;
  g.kind = S.kind[e]!;
  g.count = n;
  g.radius = S.radius[e]!;
  for (let i = 0; i < n; i++) {
    g.vx[i] = S.vx[o + i]!;
    g.vy[i] = S.vy[o + i]!;
    g.nx[i] = S.nx[o + i]!;
    g.ny[i] = S.ny[o + i]!;
  }
}

/**
 * Calls `fn` with every shape entity of `body` (its own shape first, then the extra ones).
 * @category Shapes
 */
function forEachShape(world: PhysicsWorld, body: number, fn: (shape: number) => void): void {
  const c = world.components,
    st = world.collision.shapes;
  if (hasComponent(world, body, c.Shape)) fn(body);
  if (st.firstShape.length === 0) return;
  for (let e = st.firstShape[body]!; e !== 0; e = c.Shape.next[e]!) fn(e);
}

/**
 * The handles of a 2D body's shapes, in order (its own shape first: the body's handle).
 * @throws RangeError on a removed entity or one that is not a body.
 * @category Shapes
 */
export function shapesOf(world: PhysicsWorld, body: number): number[] {
  const b = resolveShapeBody('shapesOf', world, body);
  const out: number[] = [];
  if (world.dimensions !== 2 || world.components.Shape.body.length === 0) return out;
  forEachShape(world, b, (e) => out.push(currentHandle(world, e)));
  return out;
}

/**
 * Removal hook: removing a body removes its extra shape entities; removing an extra shape on its own
 * (removeBody on the shape's handle) unlinks it from its body's list, so the body never reaches a slot
 * that a later entity took.
 */
function removeShapesOf(world: PhysicsWorld, eid: number): void {
  const st = world.collision.shapes;
  if (st.firstShape.length === 0) return;
  const S = world.components.Shape;
  if (hasComponent(world, eid, S) && S.body[eid] !== eid) {
    const b = S.body[eid]!;
    unlinkShape(st.firstShape, S.next, b, eid);
    S.next[eid] = 0;
    // A dynamic body's mass follows its remaining shapes.
    const c = world.components;
    if (!hasComponent(world, b, c.Static) && !hasComponent(world, b, c.Kinematic)) massFromShapes(world, b);
  }
  let e = st.firstShape[eid]!;
  st.firstShape[eid] = 0;
  while (e !== 0) {
    const next = S.next[e]!;
    S.next[e] = 0;
    if (entityExists(world, e) && hasComponent(world, e, S) && S.body[e] === eid) removeEntity(world, e);
    e = next;
  }
}

/**
 * Sets a shape's collision filter. Two shapes collide when (category_A & mask_B) != 0 and
 * (category_B & mask_A) != 0, unless they share a non-zero group: then they always collide if the
 * group is > 0 and never if it is < 0 (Box2D's rule; a ragdoll's limbs share a negative group).
 * Shapes of the same body never collide.
 * @param shape a shape's handle (addShape, addBox, shapesOf).
 * @throws TypeError if `filter` is not an object or has unknown or null fields; RangeError on a removed
 *   entity, one that is not a 2D shape, or bits that are not integers in range.
 * @category Shapes
 */
export function setShapeFilter(world: PhysicsWorld, shape: number, filter: FilterOptions): void {
  const where = 'setShapeFilter';
  const e = resolveEntity(world, shape, where, 'shape');
  if (world.dimensions !== 2 || !hasComponent(world, e, world.components.Shape)) {
    throw new RangeError(
      `${where}: shape must be a shape of a 2D body (a handle from addShape, addBox or shapesOf), got ${check.describe(shape)}`,
    );
  }
  check.assertOptions(where, filter, ['category', 'mask', 'group'], 'filter');
  assertFilter(where, filter);
  const S = world.components.Shape;
  if (filter.category !== undefined) S.category[e] = filter.category;
  if (filter.mask !== undefined) S.mask[e] = filter.mask;
  if (filter.group !== undefined) S.group[e] = filter.group;
}

/**
 * Options of `addBox`: those of `addBody` (no `radius`, `mass` or `density`) plus the box's.
 * @category Shapes
 */
export interface BoxOptions extends Omit<BodyOptions, 'radius' | 'mass' | 'density'>, FilterOptions {
  /** Half extents (hx, hy), m, each > 0. */
  halfExtents: ArrayLike<number>;
  /** Corner rounding, m, >= 0. Default 0. */
  radius?: number;
  /** Areal density, kg/m^2, >= 0. Default 1. */
  density?: number;
  /** A sensor box: reports overlaps, pushes nothing. Default false. */
  sensor?: boolean;
}

/** The body options `addBox` takes (addBody's, less the ball's: radius, mass, density and the material, which are the box's). */
const BOX_BODY_OPTIONS = [
  'position',
  'velocity',
  'static',
  'kinematic',
  'linearDrag',
  'quadraticDrag',
  'rotates',
  'angularVelocity',
  'angle',
  'inertia',
] as const;

/** Every option `addBox` takes. */
const BOX_OPTIONS = [
  ...BOX_BODY_OPTIONS,
  'halfExtents',
  'radius',
  'density',
  'friction',
  'staticFriction',
  'restitution',
  'category',
  'mask',
  'group',
  'sensor',
] as const;

/**
 * Adds a body with one box shape: `addBody` with the body options, then `addShape` with the box's.
 * Dynamic boxes turn (their inertia comes from the box: m (w^2 + h^2) / 12).
 * @returns the body's handle (which is also its shape's handle).
 * @throws TypeError | RangeError `addBox: <param> must be ...` on options that are not an object, an
 *   unknown option (a ball's `mass`, say: the list of valid ones is in the message), a null option, or
 *   any value `addBody` or `addShape` refuses; nothing is added.
 * @category Shapes
 */
export function addBox(world: PhysicsWorld, options: BoxOptions): number {
  const where = 'addBox';
  if (world.dimensions !== 2) throw new TypeError(`${where}: shapes are 2D; this world has 3 dimensions`);
  check.assertOptions(where, options, BOX_OPTIONS);
  const { halfExtents, radius, density, friction, staticFriction, restitution, category, mask, group, sensor, ...bodyOptions } = options;
  if (halfExtents === undefined) throw new TypeError(`${where}: halfExtents must be an array of 2 numbers, got undefined`);
  const shape: ShapeOptions = { type: 'box', halfExtents };
  if (radius !== undefined) shape.radius = radius;
  if (density !== undefined) shape.density = density;
  if (friction !== undefined) shape.friction = friction;
  if (staticFriction !== undefined) shape.staticFriction = staticFriction;
  if (restitution !== undefined) shape.restitution = restitution;
  if (category !== undefined) shape.category = category;
  if (mask !== undefined) shape.mask = mask;
  if (group !== undefined) shape.group = group;
  if (sensor !== undefined) shape.sensor = sensor;
  // Check the box first and the body next (addBodyAs checks everything before it creates), so a bad
  // box adds nothing; the shape then goes on the body's own entity, which cannot fail.
  checkShapeOptions(where, shape);
  check.assertOptionalBoolean(where, 'static', bodyOptions.static);
  check.assertOptionalBoolean(where, 'kinematic', bodyOptions.kinematic);
  const dynamic = bodyOptions.static !== true && bodyOptions.kinematic !== true;
  const body = addBodyAs(world, { ...bodyOptions, rotates: bodyOptions.rotates ?? dynamic }, where, BOX_BODY_OPTIONS);
  addShapeToSlot(world, slotOf(body), shape, where);
  return body;
}
