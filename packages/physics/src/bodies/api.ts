import { addComponent, hasComponent, removeEntity } from 'bitecs';
import { installBalls } from '../collision/install-balls.js';
import { writeDrag } from '../forces/api.js';
import { wakeIsland } from '../islands/sleep.js';
import { shapes3DOf } from '../shapes/store-3d.js';
import { createSlot, currentHandle, resolveEntity, resolveKind } from '../world/handles.js';
import { assertTimeStep, type PhysicsWorld } from '../world/options.js';
import { assertMaterial, type MaterialOptions, writeMaterial } from './material.js';
import { checkInertia, setInertiaUnchecked } from './rigid.js';

export { assertRoom, createSlot } from '../world/handles.js';
export type { MaterialOptions } from './material.js';

import * as check from '../validation/validate.js';

/**
 * Adds an empty entity, counting it against the world's capacity. Use it (or `addBody`) instead of
 * bitecs' `addEntity` so that the capacity is enforced where the entity is made and the entity gets
 * a generational handle.
 * @returns the new entity's handle (>= 1; see world/handles.ts: index stores with `slotOf(handle)`).
 * @throws RangeError if the world already holds `capacity` entities.
 * @category Bodies
 */
export function createEntity(world: PhysicsWorld): number {
  return currentHandle(world, createSlot(world, 'createEntity'));
}

/**
 * Options of `addBody`. Vectors have `world.dimensions` components. Unknown fields are rejected.
 * @category Bodies
 */
export interface BodyOptions extends MaterialOptions {
  /** Centre of mass, m. Default origin. */
  position?: ArrayLike<number>;
  /** Linear velocity, m/s. Default 0. */
  velocity?: ArrayLike<number>;
  /** Mass, kg, finite and > 0. Default 1 kg, or from `density` if that is given. Ignored for static and kinematic bodies (infinite mass). */
  mass?: number;
  /** Density, kg/m^2 in 2D (mass = density pi r^2) or kg/m^3 in 3D (mass = density 4/3 pi r^3); needs `radius`. Exclusive with `mass`. */
  density?: number;
  /** Collision radius, m, > 0: the body becomes a ball (circle in 2D, sphere in 3D). Without it the body does not collide (unless given shapes). A 3D ball body takes no shapes (addShape3D throws): give a compound's sphere as a 'sphere' shape. */
  radius?: number;
  /** Never moves; infinite mass. Default false. */
  static?: boolean;
  /** Moves with its velocity only; infinite mass in contacts. Default false. */
  kinematic?: boolean;
  /** Linear drag coefficient k in F = -k v, N s/m, >= 0. */
  linearDrag?: number;
  /** Quadratic drag coefficient k in F = -k |v| v, kg/m, >= 0. */
  quadraticDrag?: number;
  /** Whether a ball turns (friction spins it, it can roll). Default true for dynamic balls. */
  rotates?: boolean;
  /** Initial angular velocity, rad/s: a number (about z) in 2D, a 3-vector in 3D. Needs `rotates`. */
  angularVelocity?: number | ArrayLike<number>;
  /** Initial angle in 2D, rad (counter-clockwise). */
  angle?: number;
  /** Initial orientation in 3D: a quaternion (x, y, z, w), normalised here. Default identity. */
  orientation?: ArrayLike<number>;
  /**
   * Rotational inertia, overriding the ball's: a number (kg m^2; 2D, or isotropic 3D) or, in 3D, the
   * principal moments (Ix, Iy, Iz) along the body axes (see `setInertia`). Makes the body turn.
   */
  inertia?: number | ArrayLike<number>;
}

const BODY_OPTIONS = [
  'position',
  'velocity',
  'mass',
  'density',
  'radius',
  'restitution',
  'friction',
  'staticFriction',
  'static',
  'kinematic',
  'linearDrag',
  'quadraticDrag',
  'rotates',
  'angularVelocity',
  'angle',
  'orientation',
  'inertia',
] as const;

/**
 * Adds a body: position, velocity, mass and a force accumulator, plus a ball collider with its
 * material if `radius` is given, drag if asked for, and rotation (moment of inertia of a solid disc
 * m r^2 / 2 in 2D or solid sphere 2 m r^2 / 5 in 3D) for dynamic balls.
 *
 * Atomic: every option is checked before anything is created, so a refused call leaves the world as it was.
 * @returns the entity's handle (index stores with `slotOf(handle)`).
 * @throws TypeError on options that are not an object, an unknown option, a null option, a value of the
 *   wrong type (e.g. a 2-vector in a 3D world, `static: "yes"`).
 * @throws RangeError on mass <= 0 or NaN, radius <= 0, restitution outside [0, 1], negative friction or
 *   drag, a bad inertia, both `static` and `kinematic`, both `mass` and `density`, or a full world.
 * @example
 * const ball = addBody(world, { position: [0, 5], radius: 0.5, mass: 2, restitution: 0.8 });
 * @category Bodies
 */
export function addBody(world: PhysicsWorld, options: BodyOptions = {}): number {
  const eid = addBodyAs(world, options, 'addBody', BODY_OPTIONS);
  // A body with a radius is a ball: its collisions install with the first (collision/install-balls.ts).
  if (options.radius !== undefined) installBalls(world);
  return eid;
}

/**
 * Internal: `addBody` for a function built on it (addBox, createRope, createCloth), whose errors name
 * that function (`where`) and list the options it takes (`known`).
 * @category Bodies
 */
export function addBodyAs(world: PhysicsWorld, options: BodyOptions, where: string, known: readonly string[]): number {
  check.assertOptions(where, options, known);
  const d = world.dimensions;
  check.assertOptionalBoolean(where, 'static', options.static);
  check.assertOptionalBoolean(where, 'kinematic', options.kinematic);
  check.assertOptionalBoolean(where, 'rotates', options.rotates);
  if (options.position !== undefined) check.assertVector(where, 'position', options.position, d);
  if (options.velocity !== undefined) check.assertVector(where, 'velocity', options.velocity, d);
  if (options.radius !== undefined) check.assertPositive(where, 'radius', options.radius);
  if (options.mass !== undefined && options.density !== undefined) {
    throw new RangeError(
      `${where}: give mass or density, not both (mass ${check.describe(options.mass)}, density ${check.describe(options.density)})`,
    );
  }
  if (options.mass !== undefined) check.assertPositive(where, 'mass', options.mass);
  if (options.density !== undefined) {
    check.assertPositive(where, 'density', options.density);
    if (options.radius === undefined) throw new RangeError(`${where}: density needs a radius`);
  }
  assertMaterial(where, options);
  if (options.linearDrag !== undefined) check.assertNonNegative(where, 'linearDrag', options.linearDrag);
  if (options.quadraticDrag !== undefined) check.assertNonNegative(where, 'quadraticDrag', options.quadraticDrag);
  if (options.angle !== undefined) check.assertFinite(where, 'angle', options.angle);
  if (options.orientation !== undefined) {
    if (d !== 3) throw new TypeError(`${where}: orientation is for 3D worlds; use angle in 2D`);
    check.assertVector(where, 'orientation', options.orientation, 4);
    if (!(Math.hypot(options.orientation[0]!, options.orientation[1]!, options.orientation[2]!, options.orientation[3]!) > 0)) {
      throw new RangeError(`${where}: orientation must not be the zero quaternion`);
    }
  }
  const isStatic = options.static === true;
  const isKinematic = options.kinematic === true;
  if (isStatic && isKinematic) throw new RangeError(`${where}: a body cannot be both static and kinematic`);
  const rotates = options.rotates ?? ((options.radius !== undefined || options.inertia !== undefined) && !isStatic && !isKinematic);
  if (options.angularVelocity !== undefined) {
    if (d === 2) check.assertFinite(where, 'angularVelocity', options.angularVelocity);
    else check.assertVector(where, 'angularVelocity', options.angularVelocity, 3);
    if (!rotates) throw new RangeError(`${where}: angularVelocity needs rotates: true`);
  }
  if (options.inertia !== undefined) {
    checkInertia(where, d, options.inertia);
    if (!rotates) throw new RangeError(`${where}: inertia needs rotates: true`);
  }

  const eid = createSlot(world, where);
  const c = world.components;
  addComponent(world, eid, c.Position);
  addComponent(world, eid, c.Velocity);
  addComponent(world, eid, c.Mass);
  if (options.position) placeBody(world, eid, options.position);
  if (isStatic) {
    addComponent(world, eid, c.Static);
    setMassUnchecked(world, eid, 0);
  } else {
    if (options.velocity) {
      const v = options.velocity;
      c.Velocity.x[eid] = v[0]!;
      c.Velocity.y[eid] = v[1]!;
      c.Velocity.z[eid] = d === 3 ? v[2]! : 0;
    }
    if (isKinematic) {
      addComponent(world, eid, c.Kinematic);
      setMassUnchecked(world, eid, 0);
    } else {
      addComponent(world, eid, c.Force);
      let mass = options.mass ?? 1;
      if (options.density !== undefined) mass = options.density * ballMeasure(d, options.radius!);
      setMassUnchecked(world, eid, mass);
    }
  }
  if (options.radius !== undefined) {
    addComponent(world, eid, c.Ball);
    c.Ball.radius[eid] = options.radius;
    addComponent(world, eid, c.Material);
    writeMaterial(world, eid, options);
  }
  writeDrag(world, eid, options.linearDrag, options.quadraticDrag);
  if (d === 2) {
    addComponent(world, eid, c.Angle);
    if (options.angle !== undefined) c.Angle.value[eid] = options.angle;
  } else {
    addComponent(world, eid, c.Orientation);
    const q = options.orientation;
    if (q) {
      const n = Math.hypot(q[0]!, q[1]!, q[2]!, q[3]!);
      c.Orientation.x[eid] = q[0]! / n;
      c.Orientation.y[eid] = q[1]! / n;
      c.Orientation.z[eid] = q[2]! / n;
      c.Orientation.w[eid] = q[3]! / n;
    }
  }
  if (rotates) {
    addComponent(world, eid, c.AngularVelocity);
    addComponent(world, eid, c.Torque);
    addComponent(world, eid, c.Inertia);
    if (!isStatic && !isKinematic && options.radius !== undefined) {
      const m = c.Mass.value[eid]!,
        r = options.radius;
      const I = d === 2 ? 0.5 * m * r * r : 0.4 * m * r * r;
      c.Inertia.value[eid] = I;
      c.Inertia.inv[eid] = 1 / I;
    }
    if (options.inertia !== undefined) setInertiaUnchecked(world, eid, options.inertia);
    const w = options.angularVelocity;
    if (w !== undefined) {
      if (typeof w === 'number') c.AngularVelocity.z[eid] = w;
      else {
        c.AngularVelocity.x[eid] = w[0]!;
        c.AngularVelocity.y[eid] = w[1]!;
        c.AngularVelocity.z[eid] = w[2]!;
      }
    }
  }
  return currentHandle(world, eid);
}

/** Area of a disc (2D) or volume of a ball (3D) of radius r, m^2 or m^3. */
function ballMeasure(d: 2 | 3, r: number): number {
  return d === 2 ? Math.PI * r * r : (4 / 3) * Math.PI * r * r * r;
}

/**
 * Options of `addParticle`.
 * @category Bodies
 */
export interface ParticleOptions {
  /** Position, m. Default origin. */
  position?: ArrayLike<number>;
  /** Velocity, m/s. Default 0. */
  velocity?: ArrayLike<number>;
}

/**
 * Adds a bare particle: position and velocity only. It feels the world's uniform gravity and
 * nothing else until given more components (any force-law component brings a force accumulator and
 * a 1 kg mass). The cheapest thing a world can move: use it for large particle counts.
 * @returns the particle's handle. Atomic: a refused call leaves the world as it was.
 * @throws TypeError | RangeError on options that are not an object, unknown or null options, bad vectors or a full world.
 * @category Bodies
 */
export function addParticle(world: PhysicsWorld, options: ParticleOptions = {}): number {
  const where = 'addParticle';
  check.assertOptions(where, options, ['position', 'velocity']);
  const d = world.dimensions;
  if (options.position !== undefined) check.assertVector(where, 'position', options.position, d);
  if (options.velocity !== undefined) check.assertVector(where, 'velocity', options.velocity, d);
  const eid = createSlot(world, where);
  const c = world.components;
  addComponent(world, eid, c.Position);
  addComponent(world, eid, c.Velocity);
  const p = options.position,
    v = options.velocity;
  if (p) placeBody(world, eid, p);
  if (v) {
    c.Velocity.x[eid] = v[0]!;
    c.Velocity.y[eid] = v[1]!;
    c.Velocity.z[eid] = d === 3 ? v[2]! : 0;
  }
  return currentHandle(world, eid);
}

/**
 * Options of `addSegment`.
 * @category Bodies
 */
export interface SegmentOptions extends MaterialOptions {
  /** First end point, m. */
  a: ArrayLike<number>;
  /** Second end point, m. */
  b: ArrayLike<number>;
  /** Thickness radius, m, >= 0 (a capsule). Default 0. */
  radius?: number;
}

/**
 * Adds a static line segment (an inclined wall, ramp or floor) that balls collide with, end points
 * included. @returns its handle. Atomic: a refused call leaves the world as it was.
 * @throws TypeError | RangeError on missing options, unknown or null options, bad end points, negative
 * radius, restitution outside [0, 1], negative friction, or a full world.
 * @category Bodies
 */
export function addSegment(world: PhysicsWorld, options: SegmentOptions): number {
  const where = 'addSegment';
  check.assertOptions(where, options, ['a', 'b', 'radius', 'restitution', 'friction', 'staticFriction']);
  const d = world.dimensions;
  check.assertVector(where, 'a', options.a, d);
  check.assertVector(where, 'b', options.b, d);
  if (options.radius !== undefined) check.assertNonNegative(where, 'radius', options.radius);
  assertMaterial(where, options);
  const eid = createSlot(world, where);
  const c = world.components;
  addComponent(world, eid, c.Segment);
  addComponent(world, eid, c.Static);
  addComponent(world, eid, c.Material);
  const S = c.Segment;
  S.ax[eid] = options.a[0]!;
  S.ay[eid] = options.a[1]!;
  S.az[eid] = d === 3 ? options.a[2]! : 0;
  S.bx[eid] = options.b[0]!;
  S.by[eid] = options.b[1]!;
  S.bz[eid] = d === 3 ? options.b[2]! : 0;
  S.radius[eid] = options.radius ?? 0;
  writeMaterial(world, eid, options);
  return currentHandle(world, eid);
}

/**
 * Options of `setBoundary`.
 * @category Bodies
 */
export interface BoundaryOptions extends MaterialOptions {
  /** Inner corner with the smallest coordinates, m. */
  min: ArrayLike<number>;
  /** Inner corner with the largest coordinates, m; each component > min's. */
  max: ArrayLike<number>;
}

/**
 * Encloses the world in an axis-aligned box: balls and 2D shapes collide with its inside faces (walls,
 * floor and ceiling; in 3D also front and back), and 2D cloth points are kept inside it (inelastically,
 * with its friction: see cloth/solver.ts). Replaces any previous boundary.
 * @throws TypeError | RangeError on missing, unknown or null options, bad corners (max must exceed min on
 *   every axis) or material values.
 * @category Bodies
 */
export function setBoundary(world: PhysicsWorld, options: BoundaryOptions): void {
  const where = 'setBoundary';
  check.assertOptions(where, options, ['min', 'max', 'restitution', 'friction', 'staticFriction']);
  const d = world.dimensions;
  check.assertVector(where, 'min', options.min, d);
  check.assertVector(where, 'max', options.max, d);
  for (let i = 0; i < d; i++) {
    if (!(options.max[i]! > options.min[i]!)) {
      throw new RangeError(
        `${where}: max[${i}] must be > min[${i}], got min ${check.describe(options.min)}, max ${check.describe(options.max)}`,
      );
    }
  }
  assertMaterial(where, options);
  const box = world.collision.boundary;
  box.enabled = true;
  for (let i = 0; i < 3; i++) {
    box.min[i] = i < d ? options.min[i]! : 0;
    box.max[i] = i < d ? options.max[i]! : 0;
  }
  box.restitution = options.restitution ?? 0;
  box.friction = options.friction ?? 0.6;
  box.staticFriction = options.staticFriction ?? box.friction;
}

/**
 * Removes the boundary box.
 * @category Bodies
 */
export function clearBoundary(world: PhysicsWorld): void {
  world.collision.boundary.enabled = false;
}

/**
 * Removes an entity of any kind (body, wall, field, spring, emitter) and everything that references it
 * (springs and joints attached to it, cached contacts), so no force ever acts on a recycled slot. Its
 * handle is refused by every API function from then on, even after its slot is reused.
 * @param eid the entity's handle.
 * @throws RangeError if `eid` is not an entity of this world or was already removed.
 * @category Bodies
 */
export function removeBody(world: PhysicsWorld, eid: number): void {
  const slot = resolveEntity(world, eid, 'removeBody');
  for (const hook of world.removeHooks) hook(world, slot);
  removeEntity(world, slot);
}

function setMassUnchecked(world: PhysicsWorld, eid: number, mass: number): void {
  world.components.Mass.value[eid] = mass;
  world.components.Mass.inv[eid] = mass > 0 ? 1 / mass : 0;
}

/**
 * Sets a dynamic body's mass and inverse mass together (and rescales its moment of inertia, or in 3D
 * its principal moments, if it has them, keeping the mass distribution: I' = I m' / m).
 * @param eid a body's handle (addBody, addParticle).
 * @param mass kg, finite and > 0.
 * @throws RangeError on mass <= 0, NaN or infinite, on a static or kinematic body (infinite mass), on a
 *   removed entity or one that is not a body.
 * @category Bodies
 */
export function setMass(world: PhysicsWorld, eid: number, mass: number): void {
  const slot = resolveKind(world, eid, 'body', 'setMass');
  check.assertPositive('setMass', 'mass', mass);
  const c = world.components;
  if (hasComponent(world, slot, c.Static) || hasComponent(world, slot, c.Kinematic)) {
    throw new RangeError(`setMass: entity ${eid} is static or kinematic and has infinite mass`);
  }
  if (!hasComponent(world, slot, c.Mass)) addComponent(world, slot, c.Mass);
  const old = c.Mass.value[slot]!;
  setMassUnchecked(world, slot, mass);
  if (hasComponent(world, slot, c.Inertia) && c.Inertia.value[slot]! > 0 && old > 0) {
    const I = c.Inertia.value[slot]! * (mass / old);
    c.Inertia.value[slot] = I;
    c.Inertia.inv[slot] = 1 / I;
  }
  // A 3D body's principal moments (shapes, setInertia with three moments) scale with the mass too.
  if (hasComponent(world, slot, c.InertiaTensor) && old > 0) {
    const T = c.InertiaTensor,
      f = mass / old;
    T.x[slot] = T.x[slot]! * f;
    T.y[slot] = T.y[slot]! * f;
    T.z[slot] = T.z[slot]! * f;
    T.invX[slot] = T.invX[slot]! / f;
    T.invY[slot] = T.invY[slot]! / f;
    T.invZ[slot] = T.invZ[slot]! / f;
  }
}

/**
 * Sets the surface material of a body, segment or plane.
 * @param eid the handle of a body, segment or plane.
 * @throws TypeError on a missing or non-object `material`, unknown or null fields; RangeError on restitution
 *   outside [0, 1], negative friction, a removed entity or one that is not a body, segment or plane.
 * @category Bodies
 */
export function setMaterial(world: PhysicsWorld, eid: number, material: MaterialOptions): void {
  const where = 'setMaterial';
  const slot = resolveKind(world, eid, 'collider', where);
  check.assertOptions(where, material, ['restitution', 'friction', 'staticFriction']);
  assertMaterial(where, material);
  const c = world.components;
  if (!hasComponent(world, slot, c.Material)) addComponent(world, slot, c.Material);
  writeMaterial(world, slot, material);
}

/**
 * Sets a body's collision radius, m (> 0), making it a ball if it was not, and rescales its moment of
 * inertia if it has one.
 * @param eid a body's handle.
 * @throws RangeError on radius <= 0 or NaN, a removed entity, one that is not a body, or a 3D body with
 *   shapes (addShape3D). A call that throws changes nothing.
 * @category Bodies
 */
export function setRadius(world: PhysicsWorld, eid: number, radius: number): void {
  const slot = resolveKind(world, eid, 'body', 'setRadius');
  check.assertPositive('setRadius', 'radius', radius);
  const shapes = shapes3DOf(world);
  if (shapes !== undefined && shapes.first[slot] !== 0) {
    throw new RangeError(
      `setRadius: eid must be a body without 3D shapes (its shapes give its size and mass; add a 'sphere' shape instead), got body ${check.describe(eid)}`,
    );
  }
  const c = world.components;
  if (!hasComponent(world, slot, c.Ball)) addComponent(world, slot, c.Ball);
  installBalls(world);
  const old = c.Ball.radius[slot]!;
  c.Ball.radius[slot] = radius;
  if (hasComponent(world, slot, c.Inertia) && c.Inertia.value[slot]! > 0 && old > 0) {
    const I = (c.Inertia.value[slot]! * (radius * radius)) / (old * old);
    c.Inertia.value[slot] = I;
    c.Inertia.inv[slot] = 1 / I;
  }
}

/**
 * Moves a body or an emitter to `position` (m) without sweeping through what lies between: its
 * previous position is set too, so nothing collides along the jump and a renderer does not
 * interpolate across it.
 * @param eid the handle of a body or an emitter.
 * @throws TypeError | RangeError on a bad vector, a removed entity, or one that has no position.
 * @category Bodies
 */
export function setPosition(world: PhysicsWorld, eid: number, position: ArrayLike<number>): void {
  const where = 'setPosition';
  const slot = resolveEntity(world, eid, where);
  const c = world.components;
  if (!hasComponent(world, slot, c.Position)) resolveKind(world, eid, 'body', where);
  check.assertVector(where, 'position', position, world.dimensions);
  wakeIsland(world, slot);
  placeBody(world, slot, position);
}

/**
 * Puts entity `slot` at `p` (m; z = 0 in a 2D world) with no motion since the last step: Position
 * and PreviousPosition both p. `p` must be checked already.
 */
function placeBody(world: PhysicsWorld, slot: number, p: ArrayLike<number>): void {
  const c = world.components;
  const z = world.dimensions === 3 ? p[2]! : 0;
  c.Position.x[slot] = p[0]!;
  c.Position.y[slot] = p[1]!;
  c.Position.z[slot] = z;
  c.PreviousPosition.x[slot] = p[0]!;
  c.PreviousPosition.y[slot] = p[1]!;
  c.PreviousPosition.z[slot] = z;
}

/**
 * Sets the velocity of a body or an emitter, m/s. A standalone emitter that had none starts moving
 * as a kinematic body (as if made with addEmitter's `velocity`).
 * @param eid the handle of a body or an emitter.
 * @throws TypeError | RangeError on a bad vector, a removed entity, or one that is neither a body nor an emitter.
 * @category Bodies
 */
export function setVelocity(world: PhysicsWorld, eid: number, velocity: ArrayLike<number>): void {
  const where = 'setVelocity';
  const slot = resolveEntity(world, eid, where);
  const c = world.components;
  const emitter = hasComponent(world, slot, c.Emitter) && hasComponent(world, slot, c.Position);
  if (!emitter) resolveKind(world, eid, 'body', where);
  check.assertVector(where, 'velocity', velocity, world.dimensions);
  if (emitter && !hasComponent(world, slot, c.Velocity)) {
    addComponent(world, slot, c.Velocity);
    addComponent(world, slot, c.Kinematic);
  }
  wakeIsland(world, slot);
  c.Velocity.x[slot] = velocity[0]!;
  c.Velocity.y[slot] = velocity[1]!;
  c.Velocity.z[slot] = world.dimensions === 3 ? velocity[2]! : 0;
}

/**
 * Applies an impulse J (N s) at the centre of mass: v += J / m. For throws, kicks and explosions.
 * @param eid a body's handle.
 * @throws TypeError | RangeError on a bad vector, a removed entity or one that is not a body.
 * @category Bodies
 */
export function applyImpulse(world: PhysicsWorld, eid: number, impulse: ArrayLike<number>): void {
  const slot = resolveKind(world, eid, 'body', 'applyImpulse');
  check.assertVector('applyImpulse', 'impulse', impulse, world.dimensions);
  wakeIsland(world, slot);
  const c = world.components;
  const im = hasComponent(world, slot, c.Mass) ? c.Mass.inv[slot]! : 0;
  c.Velocity.x[slot] = c.Velocity.x[slot]! + impulse[0]! * im;
  c.Velocity.y[slot] = c.Velocity.y[slot]! + impulse[1]! * im;
  if (world.dimensions === 3) c.Velocity.z[slot] = c.Velocity.z[slot]! + impulse[2]! * im;
}

/**
 * Sets the world's uniform gravitational acceleration, m/s^2 (`world.dimensions` numbers).
 * @throws TypeError | RangeError on a vector of the wrong length or with non-finite entries.
 * @category Bodies
 */
export function setGravity(world: PhysicsWorld, gravity: ArrayLike<number>): void {
  check.assertVector('setGravity', 'gravity', gravity, world.dimensions);
  for (let i = 0; i < 3; i++) world.gravity[i] = i < world.dimensions ? gravity[i]! : 0;
}

/**
 * Changes the world's fixed step (s, > 0 and at most MAX_TIME_STEP = 1e6) and optionally its
 * substeps (integer in [1, 64]).
 * @throws TypeError | RangeError on bad values.
 * @category Bodies
 */
export function setTimeStep(world: PhysicsWorld, dt: number, substeps?: number): void {
  assertTimeStep('setTimeStep', dt);
  if (substeps !== undefined) {
    if (!Number.isInteger(substeps) || substeps < 1 || substeps > 64) {
      throw new RangeError(`setTimeStep: substeps must be an integer in [1, 64], got ${check.describe(substeps)}`);
    }
    world.substeps = substeps;
  }
  world.dt = dt;
  world.h = dt / world.substeps;
}

/**
 * Sets a body's angular velocity, rad/s: a number (about z) in 2D, a 3-vector (world frame) in 3D.
 * @param eid a body's handle.
 * @throws TypeError | RangeError on a bad value, a removed entity or one that is not a body.
 * @category Bodies
 */
export function setAngularVelocity(world: PhysicsWorld, eid: number, angularVelocity: number | ArrayLike<number>): void {
  const where = 'setAngularVelocity';
  const slot = resolveKind(world, eid, 'body', where);
  if (world.dimensions === 2) check.assertFinite(where, 'angularVelocity', angularVelocity);
  else check.assertVector(where, 'angularVelocity', angularVelocity, 3);
  wakeIsland(world, slot);
  const c = world.components;
  if (!hasComponent(world, slot, c.AngularVelocity)) addComponent(world, slot, c.AngularVelocity);
  if (world.dimensions === 2) {
    c.AngularVelocity.z[slot] = angularVelocity as number;
    return;
  }
  const w = angularVelocity as ArrayLike<number>;
  c.AngularVelocity.x[slot] = w[0]!;
  c.AngularVelocity.y[slot] = w[1]!;
  c.AngularVelocity.z[slot] = w[2]!;
}

/**
 * Sets a body's orientation: the angle (rad) in 2D, or a quaternion (x, y, z, w), normalised here, in 3D.
 * @param eid a body's handle.
 * @throws TypeError | RangeError on a bad value, a zero quaternion, a removed entity or one that is not a body.
 * @category Bodies
 */
export function setOrientation(world: PhysicsWorld, eid: number, orientation: number | ArrayLike<number>): void {
  const where = 'setOrientation';
  const slot = resolveKind(world, eid, 'body', where);
  const c = world.components;
  if (world.dimensions === 2) {
    check.assertFinite(where, 'orientation', orientation);
    wakeIsland(world, slot);
    if (!hasComponent(world, slot, c.Angle)) addComponent(world, slot, c.Angle);
    c.Angle.value[slot] = orientation as number;
    return;
  }
  check.assertVector(where, 'orientation', orientation, 4);
  const q = orientation as ArrayLike<number>;
  const n = Math.hypot(q[0]!, q[1]!, q[2]!, q[3]!);
  if (!(n > 0)) throw new RangeError(`${where}: orientation must not be the zero quaternion`);
  wakeIsland(world, slot);
  if (!hasComponent(world, slot, c.Orientation)) addComponent(world, slot, c.Orientation);
  c.Orientation.x[slot] = q[0]! / n;
  c.Orientation.y[slot] = q[1]! / n;
  c.Orientation.z[slot] = q[2]! / n;
  c.Orientation.w[slot] = q[3]! / n;
}
