import { addComponent, entityExists, hasComponent } from 'bitecs';
import type { PhysicsWorld } from './world.js';
import { addComponentIfMissing } from './world.js';
import { createEntity } from './bodies.js';
import { assertFinite, assertInRange, assertKnownKeys, assertNonNegative, assertPositive, assertVector, describe } from './validate.js';
import { rotateVector, rotateVectorInverse } from './math/quaternion.js';
import { wakeIsland } from './collision/sleep.js';

/**
 * Rigid-body rotation helpers: moments of inertia of standard solids, setting a body's inertia,
 * forces and impulses applied at a point (which produce torque), angular damping, and static planes.
 * Formulas for the moments: any mechanics text, e.g. Goldstein, Classical Mechanics, or the table in
 * Ramtal and Dobre ch. 13.
 */

/** Moment of inertia of a solid sphere about any diameter: 2 m r^2 / 5, kg m^2. @throws RangeError on m or r <= 0. */
export function inertiaOfSolidSphere(mass: number, radius: number): number {
  assertPositive('inertiaOfSolidSphere', 'mass', mass);
  assertPositive('inertiaOfSolidSphere', 'radius', radius);
  return 0.4 * mass * radius * radius;
}

/** Moment of inertia of a thin spherical shell: 2 m r^2 / 3, kg m^2. @throws RangeError on m or r <= 0. */
export function inertiaOfSphericalShell(mass: number, radius: number): number {
  assertPositive('inertiaOfSphericalShell', 'mass', mass);
  assertPositive('inertiaOfSphericalShell', 'radius', radius);
  return (2 / 3) * mass * radius * radius;
}

/**
 * Principal moments of a solid box of edges (a, b, c) along x, y, z: m (b^2 + c^2) / 12, m (a^2 + c^2) / 12,
 * m (a^2 + b^2) / 12, kg m^2. @throws RangeError on non-positive mass or edges.
 */
export function inertiaOfSolidBox(mass: number, size: ArrayLike<number>): [number, number, number] {
  assertPositive('inertiaOfSolidBox', 'mass', mass);
  assertVector('inertiaOfSolidBox', 'size', size, 3);
  for (let i = 0; i < 3; i++) assertPositive('inertiaOfSolidBox', `size[${i}]`, size[i]);
  const a = size[0]!, b = size[1]!, c = size[2]!;
  return [(mass * (b * b + c * c)) / 12, (mass * (a * a + c * c)) / 12, (mass * (a * a + b * b)) / 12];
}

/**
 * Principal moments of a solid cylinder of radius r and height h with its axis along y:
 * about y m r^2 / 2; about x and z m (3 r^2 + h^2) / 12, kg m^2. @throws RangeError on non-positive values.
 */
export function inertiaOfSolidCylinder(mass: number, radius: number, height: number): [number, number, number] {
  assertPositive('inertiaOfSolidCylinder', 'mass', mass);
  assertPositive('inertiaOfSolidCylinder', 'radius', radius);
  assertPositive('inertiaOfSolidCylinder', 'height', height);
  const side = (mass * (3 * radius * radius + height * height)) / 12;
  return [side, 0.5 * mass * radius * radius, side];
}

/** 2D: moment of a solid disc about its centre, m r^2 / 2, kg m^2. @throws RangeError on m or r <= 0. */
export function inertiaOfDisc(mass: number, radius: number): number {
  assertPositive('inertiaOfDisc', 'mass', mass);
  assertPositive('inertiaOfDisc', 'radius', radius);
  return 0.5 * mass * radius * radius;
}

/** 2D: moment of a solid rectangle w x h about its centre, m (w^2 + h^2) / 12, kg m^2. @throws RangeError. */
export function inertiaOfRectangle(mass: number, width: number, height: number): number {
  assertPositive('inertiaOfRectangle', 'mass', mass);
  assertPositive('inertiaOfRectangle', 'width', width);
  assertPositive('inertiaOfRectangle', 'height', height);
  return (mass * (width * width + height * height)) / 12;
}

function assertBody(where: string, world: PhysicsWorld, eid: number): void {
  if (typeof eid !== 'number' || !Number.isInteger(eid) || eid < 1 || !entityExists(world, eid) || !hasComponent(world, eid, world.components.Position)) {
    throw new RangeError(`${where}: entity ${describe(eid)} is not a body in this world`);
  }
}

/**
 * Sets a body's rotational inertia and makes it turn: in 2D a moment about z (kg m^2, > 0); in 3D a
 * number (isotropic, like a ball) or the three principal moments (kg m^2, each >= 0 and at least one
 * > 0; 0 locks that axis) along the body's axes. Adds angular velocity, torque and orientation.
 * @throws TypeError | RangeError on bad values, principal moments in 2D, or a missing body.
 */
export function setInertia(world: PhysicsWorld, eid: number, inertia: number | ArrayLike<number>): void {
  const where = 'setInertia';
  assertBody(where, world, eid);
  const c = world.components;
  addComponentIfMissing(world, eid, c.AngularVelocity);
  addComponentIfMissing(world, eid, c.Torque);
  addComponentIfMissing(world, eid, world.dimensions === 2 ? c.Angle : c.Orientation);
  if (typeof inertia === 'number') {
    assertPositive(where, 'inertia', inertia);
    addComponentIfMissing(world, eid, c.Inertia);
    c.Inertia.value[eid] = inertia;
    c.Inertia.inv[eid] = 1 / inertia;
    return;
  }
  if (world.dimensions === 2) throw new TypeError(`${where}: a 2D body has one moment of inertia (a number), got ${describe(inertia)}`);
  assertVector(where, 'inertia', inertia, 3);
  for (let i = 0; i < 3; i++) assertNonNegative(where, `inertia[${i}]`, inertia[i]);
  if (!(inertia[0]! > 0 || inertia[1]! > 0 || inertia[2]! > 0)) throw new RangeError(`${where}: at least one principal moment must be > 0`);
  addComponentIfMissing(world, eid, c.InertiaTensor);
  const T = c.InertiaTensor;
  T.x[eid] = inertia[0]!; T.y[eid] = inertia[1]!; T.z[eid] = inertia[2]!;
  T.invX[eid] = inertia[0]! > 0 ? 1 / inertia[0]! : 0;
  T.invY[eid] = inertia[1]! > 0 ? 1 / inertia[1]! : 0;
  T.invZ[eid] = inertia[2]! > 0 ? 1 / inertia[2]! : 0;
}

const tmp = new Float64Array(3);

/**
 * Applies force F (N, world frame) at the world point p (m): adds F to the force accumulator and
 * (p - x) x F to the torque accumulator. Call it from a system in the 'forces' stage (accumulators
 * are cleared at the start of each evaluation).
 * @throws TypeError | RangeError on bad vectors or a missing body.
 */
export function applyForceAtPoint(world: PhysicsWorld, eid: number, force: ArrayLike<number>, point: ArrayLike<number>): void {
  const where = 'applyForceAtPoint';
  assertBody(where, world, eid);
  wakeIsland(world, eid);
  const d = world.dimensions;
  assertVector(where, 'force', force, d);
  assertVector(where, 'point', point, d);
  const c = world.components;
  addComponentIfMissing(world, eid, c.Force);
  addComponentIfMissing(world, eid, c.Torque);
  const fx = force[0]!, fy = force[1]!, fz = d === 3 ? force[2]! : 0;
  const rx = point[0]! - c.Position.x[eid]!, ry = point[1]! - c.Position.y[eid]!, rz = d === 3 ? point[2]! - c.Position.z[eid]! : 0;
  c.Force.x[eid] = c.Force.x[eid]! + fx; c.Force.y[eid] = c.Force.y[eid]! + fy; c.Force.z[eid] = c.Force.z[eid]! + fz;
  c.Torque.x[eid] = c.Torque.x[eid]! + (ry * fz - rz * fy);
  c.Torque.y[eid] = c.Torque.y[eid]! + (rz * fx - rx * fz);
  c.Torque.z[eid] = c.Torque.z[eid]! + (rx * fy - ry * fx);
}

/**
 * Applies impulse J (N s, world frame) at the world point p (m): v += J / m and
 * w += I_w^-1 ((p - x) x J), with I_w the world-frame inertia (scalar, or R diag(I) R^T for a tensor).
 * For clicks, kicks and hits between steps.
 * @throws TypeError | RangeError on bad vectors or a missing body.
 */
export function applyImpulseAtPoint(world: PhysicsWorld, eid: number, impulse: ArrayLike<number>, point: ArrayLike<number>): void {
  const where = 'applyImpulseAtPoint';
  assertBody(where, world, eid);
  wakeIsland(world, eid);
  const d = world.dimensions;
  assertVector(where, 'impulse', impulse, d);
  assertVector(where, 'point', point, d);
  const c = world.components;
  const im = hasComponent(world, eid, c.Mass) ? c.Mass.inv[eid]! : 0;
  const jx = impulse[0]!, jy = impulse[1]!, jz = d === 3 ? impulse[2]! : 0;
  c.Velocity.x[eid] = c.Velocity.x[eid]! + jx * im;
  c.Velocity.y[eid] = c.Velocity.y[eid]! + jy * im;
  c.Velocity.z[eid] = c.Velocity.z[eid]! + jz * im;
  if (!hasComponent(world, eid, c.AngularVelocity)) return;
  const rx = point[0]! - c.Position.x[eid]!, ry = point[1]! - c.Position.y[eid]!, rz = d === 3 ? point[2]! - c.Position.z[eid]! : 0;
  const Lx = ry * jz - rz * jy, Ly = rz * jx - rx * jz, Lz = rx * jy - ry * jx;
  if (d === 3 && hasComponent(world, eid, c.InertiaTensor)) {
    const q = c.Orientation, T = c.InertiaTensor;
    const qx = q.x[eid]!, qy = q.y[eid]!, qz = q.z[eid]!, qw = q.w[eid]!;
    rotateVectorInverse(qx, qy, qz, qw, Lx, Ly, Lz, tmp);
    rotateVector(qx, qy, qz, qw, tmp[0]! * T.invX[eid]!, tmp[1]! * T.invY[eid]!, tmp[2]! * T.invZ[eid]!, tmp);
    c.AngularVelocity.x[eid] = c.AngularVelocity.x[eid]! + tmp[0]!;
    c.AngularVelocity.y[eid] = c.AngularVelocity.y[eid]! + tmp[1]!;
    c.AngularVelocity.z[eid] = c.AngularVelocity.z[eid]! + tmp[2]!;
    return;
  }
  const ii = hasComponent(world, eid, c.Inertia) ? c.Inertia.inv[eid]! : 0;
  if (d === 3) { c.AngularVelocity.x[eid] = c.AngularVelocity.x[eid]! + Lx * ii; c.AngularVelocity.y[eid] = c.AngularVelocity.y[eid]! + Ly * ii; }
  c.AngularVelocity.z[eid] = c.AngularVelocity.z[eid]! + Lz * ii;
}

/**
 * World-frame angular momentum of one body about its centre of mass, kg m^2/s: I_w w (scalar or tensor).
 * Written into out (length 3) and returned. @throws RangeError if the entity is not a body.
 */
export function spinAngularMomentum(world: PhysicsWorld, eid: number, out: Float64Array = new Float64Array(3)): Float64Array {
  assertBody('spinAngularMomentum', world, eid);
  const c = world.components;
  const wx = c.AngularVelocity.x[eid]!, wy = c.AngularVelocity.y[eid]!, wz = c.AngularVelocity.z[eid]!;
  if (world.dimensions === 3 && hasComponent(world, eid, c.InertiaTensor)) {
    const q = c.Orientation, T = c.InertiaTensor;
    const qx = q.x[eid]!, qy = q.y[eid]!, qz = q.z[eid]!, qw = q.w[eid]!;
    rotateVectorInverse(qx, qy, qz, qw, wx, wy, wz, tmp);
    rotateVector(qx, qy, qz, qw, tmp[0]! * T.x[eid]!, tmp[1]! * T.y[eid]!, tmp[2]! * T.z[eid]!, out);
    return out;
  }
  const I = hasComponent(world, eid, c.Inertia) ? c.Inertia.value[eid]! : 0;
  out[0] = world.dimensions === 3 ? I * wx : 0; out[1] = world.dimensions === 3 ? I * wy : 0; out[2] = I * wz;
  return out;
}

const spinL = new Float64Array(3);

/**
 * Rotational kinetic energy of one body, J: w . (I_w w) / 2. @throws RangeError if the entity is not a body.
 */
export function spinKineticEnergy(world: PhysicsWorld, eid: number): number {
  const L = spinAngularMomentum(world, eid, spinL);
  const c = world.components;
  return 0.5 * (L[0]! * c.AngularVelocity.x[eid]! + L[1]! * c.AngularVelocity.y[eid]! + L[2]! * c.AngularVelocity.z[eid]!);
}

/** Sets angular damping, torque -k w with k in N m s (>= 0). @throws RangeError on bad k or a missing body. */
export function setAngularDamping(world: PhysicsWorld, eid: number, k: number): void {
  assertBody('setAngularDamping', world, eid);
  assertNonNegative('setAngularDamping', 'k', k);
  const c = world.components;
  addComponentIfMissing(world, eid, c.AngularDamping);
  c.AngularDamping.k[eid] = k;
}

/** Options of `addPlane`. */
export interface PlaneOptions {
  /** Normal pointing out of the solid side (normalised here; 2 components in 2D, 3 in 3D). */
  normal: ArrayLike<number>;
  /** A point on the plane, m. Default origin. */
  point?: ArrayLike<number>;
  /** Restitution in [0, 1]. Default 0. */
  restitution?: number;
  /** Kinetic friction coefficient >= 0. Default 0.6. */
  friction?: number;
  /** Static friction coefficient >= 0. Default equal to friction. */
  staticFriction?: number;
}

/**
 * Adds a static infinite plane (a line in 2D) that balls rest on, roll on and bounce off.
 * @returns its entity. @throws TypeError | RangeError on a zero or malformed normal, bad material values.
 */
export function addPlane(world: PhysicsWorld, options: PlaneOptions): number {
  const where = 'addPlane';
  if (options === undefined) throw new TypeError(`${where}: options with a normal are required`);
  assertKnownKeys(where, options, ['normal', 'point', 'restitution', 'friction', 'staticFriction']);
  const d = world.dimensions;
  assertVector(where, 'normal', options.normal, d);
  if (options.point !== undefined) assertVector(where, 'point', options.point, d);
  if (options.restitution !== undefined) assertInRange(where, 'restitution', options.restitution, 0, 1);
  if (options.friction !== undefined) assertNonNegative(where, 'friction', options.friction);
  if (options.staticFriction !== undefined) assertNonNegative(where, 'staticFriction', options.staticFriction);
  const nx0 = options.normal[0]!, ny0 = options.normal[1]!, nz0 = d === 3 ? options.normal[2]! : 0;
  const len = Math.hypot(nx0, ny0, nz0);
  if (!(len > 0)) throw new RangeError(`${where}: normal must not be zero, got ${describe(options.normal)}`);
  const nx = nx0 / len, ny = ny0 / len, nz = nz0 / len;
  const p = options.point;
  const dist = p ? nx * p[0]! + ny * p[1]! + (d === 3 ? nz * p[2]! : 0) : 0;
  assertFinite(where, 'offset', dist);
  const eid = createEntity(world);
  const c = world.components;
  addComponent(world, eid, c.Plane);
  addComponent(world, eid, c.Static);
  addComponent(world, eid, c.Material);
  c.Plane.nx[eid] = nx; c.Plane.ny[eid] = ny; c.Plane.nz[eid] = nz; c.Plane.d[eid] = dist;
  if (options.restitution !== undefined) c.Material.restitution[eid] = options.restitution;
  if (options.friction !== undefined) { c.Material.friction[eid] = options.friction; c.Material.staticFriction[eid] = options.friction; }
  if (options.staticFriction !== undefined) c.Material.staticFriction[eid] = options.staticFriction;
  return eid;
}
