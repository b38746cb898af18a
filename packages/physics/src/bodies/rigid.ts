import { addComponent, hasComponent } from 'bitecs';
import { wakeIsland } from '../islands/sleep.js';
import { rotateVector, rotateVectorInverse } from '../math/quaternion.js';
import * as check from '../validation/validate.js';
import { createSlot, currentHandle, resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addComponentIfMissing } from '../world/options.js';
import { assertMaterial, type MaterialOptions, writeMaterial } from './material.js';

/**
 * Rigid-body rotation helpers: moments of inertia of standard solids, setting a body's inertia,
 * forces and impulses applied at a point (which produce torque), angular damping, and static planes.
 * Formulas for the moments: any mechanics text, e.g. Goldstein, Classical Mechanics, or the table in
 * Ramtal and Dobre ch. 13.
 */

/**
 * Moment of inertia of a solid sphere about any diameter: 2 m r^2 / 5, kg m^2. @throws RangeError on m or r <= 0.
 * @category Bodies
 */
export function inertiaOfSolidSphere(mass: number, radius: number): number {
  check.assertPositive('inertiaOfSolidSphere', 'mass', mass);
  check.assertPositive('inertiaOfSolidSphere', 'radius', radius);
  return 0.4 * mass * radius * radius;
}

/**
 * Moment of inertia of a thin spherical shell: 2 m r^2 / 3, kg m^2. @throws RangeError on m or r <= 0.
 * @category Bodies
 */
export function inertiaOfSphericalShell(mass: number, radius: number): number {
  check.assertPositive('inertiaOfSphericalShell', 'mass', mass);
  check.assertPositive('inertiaOfSphericalShell', 'radius', radius);
  return (2 / 3) * mass * radius * radius;
}

/**
 * Principal moments of a solid box of edges (a, b, c) along x, y, z: m (b^2 + c^2) / 12, m (a^2 + c^2) / 12,
 * m (a^2 + b^2) / 12, kg m^2. @throws RangeError on non-positive mass or edges.
 * @category Bodies
 */
export function inertiaOfSolidBox(mass: number, size: ArrayLike<number>): [number, number, number] {
  check.assertPositive('inertiaOfSolidBox', 'mass', mass);
  check.assertVector('inertiaOfSolidBox', 'size', size, 3);
  for (let i = 0; i < 3; i++) check.assertPositive('inertiaOfSolidBox', `size[${i}]`, size[i]);
  const a = size[0]!,
    b = size[1]!,
    c = size[2]!;
  return [(mass * (b * b + c * c)) / 12, (mass * (a * a + c * c)) / 12, (mass * (a * a + b * b)) / 12];
}

/**
 * Principal moments of a solid cylinder of radius r and height h with its axis along y:
 * about y m r^2 / 2; about x and z m (3 r^2 + h^2) / 12, kg m^2. @throws RangeError on non-positive values.
 * @category Bodies
 */
export function inertiaOfSolidCylinder(mass: number, radius: number, height: number): [number, number, number] {
  check.assertPositive('inertiaOfSolidCylinder', 'mass', mass);
  check.assertPositive('inertiaOfSolidCylinder', 'radius', radius);
  check.assertPositive('inertiaOfSolidCylinder', 'height', height);
  const side = (mass * (3 * radius * radius + height * height)) / 12;
  return [side, 0.5 * mass * radius * radius, side];
}

/**
 * 2D: moment of a solid disc about its centre, m r^2 / 2, kg m^2. @throws RangeError on m or r <= 0.
 * @category Bodies
 */
export function inertiaOfDisc(mass: number, radius: number): number {
  check.assertPositive('inertiaOfDisc', 'mass', mass);
  check.assertPositive('inertiaOfDisc', 'radius', radius);
  return 0.5 * mass * radius * radius;
}

/**
 * 2D: moment of a solid rectangle w x h about its centre, m (w^2 + h^2) / 12, kg m^2. @throws RangeError.
 * @category Bodies
 */
export function inertiaOfRectangle(mass: number, width: number, height: number): number {
  check.assertPositive('inertiaOfRectangle', 'mass', mass);
  check.assertPositive('inertiaOfRectangle', 'width', width);
  check.assertPositive('inertiaOfRectangle', 'height', height);
  return (mass * (width * width + height * height)) / 12;
}

/**
 * Checks a moment of inertia without touching the world: in 2D a number > 0 (kg m^2); in 3D a number
 * > 0 or three principal moments, each >= 0 and at least one > 0.
 * @param where the function the user called (addBody, setInertia).
 * @throws TypeError | RangeError naming `where` and the value.
 * @category Bodies
 */
export function checkInertia(where: string, dimensions: 2 | 3, inertia: unknown): void {
  if (typeof inertia === 'number') {
    check.assertPositive(where, 'inertia', inertia);
    return;
  }
  if (dimensions === 2)
    throw new TypeError(`${where}: inertia must be a number in 2D (one moment about z, kg m^2), got ${check.describe(inertia)}`);
  check.assertVector(where, 'inertia', inertia, 3);
  for (let i = 0; i < 3; i++) check.assertNonNegative(where, `inertia[${i}]`, inertia[i]);
  if (!(inertia[0]! > 0 || inertia[1]! > 0 || inertia[2]! > 0))
    throw new RangeError(`${where}: inertia must have at least one principal moment > 0, got ${check.describe(inertia)}`);
}

/**
 * Internal: sets an inertia already checked with `checkInertia` on the body in `slot`.
 * @category Bodies
 */
export function setInertiaUnchecked(world: PhysicsWorld, slot: number, inertia: number | ArrayLike<number>): void {
  const c = world.components;
  addComponentIfMissing(world, slot, c.AngularVelocity);
  addComponentIfMissing(world, slot, c.Torque);
  addComponentIfMissing(world, slot, world.dimensions === 2 ? c.Angle : c.Orientation);
  if (typeof inertia === 'number') {
    addComponentIfMissing(world, slot, c.Inertia);
    c.Inertia.value[slot] = inertia;
    c.Inertia.inv[slot] = 1 / inertia;
    return;
  }
  addComponentIfMissing(world, slot, c.InertiaTensor);
  const T = c.InertiaTensor;
  T.x[slot] = inertia[0]!;
  T.y[slot] = inertia[1]!;
  T.z[slot] = inertia[2]!;
  T.invX[slot] = inertia[0]! > 0 ? 1 / inertia[0]! : 0;
  T.invY[slot] = inertia[1]! > 0 ? 1 / inertia[1]! : 0;
  T.invZ[slot] = inertia[2]! > 0 ? 1 / inertia[2]! : 0;
}

/**
 * Sets a body's rotational inertia and makes it turn: in 2D a moment about z (kg m^2, > 0); in 3D a
 * number (isotropic, like a ball) or the three principal moments (kg m^2, each >= 0 and at least one
 * > 0; 0 locks that axis) along the body's axes. Adds angular velocity, torque and orientation.
 * @param eid a body's handle.
 * @throws TypeError | RangeError on bad values, principal moments in 2D, a removed entity or one that is not a body.
 * @category Bodies
 */
export function setInertia(world: PhysicsWorld, eid: number, inertia: number | ArrayLike<number>): void {
  const where = 'setInertia';
  const slot = resolveKind(world, eid, 'body', where);
  checkInertia(where, world.dimensions, inertia);
  setInertiaUnchecked(world, slot, inertia);
}

const tmp = new Float64Array(3);

/**
 * R diag(dx, dy, dz) R^T v for the 3D body in slot `e` (R its orientation): a matrix diagonal in the
 * body's principal frame (its inertia tensor or the inverse) applied to the world vector v; the
 * result into out[0..2]. `out` may be `tmp`.
 */
function bodyDiagonal(
  world: PhysicsWorld,
  e: number,
  dx: number,
  dy: number,
  dz: number,
  vx: number,
  vy: number,
  vz: number,
  out: Float64Array,
): void {
  const q = world.components.Orientation;
  const qx = q.x[e]!,
    qy = q.y[e]!,
    qz = q.z[e]!,
    qw = q.w[e]!;
  rotateVectorInverse(qx, qy, qz, qw, vx, vy, vz, tmp);
  rotateVector(qx, qy, qz, qw, tmp[0]! * dx, tmp[1]! * dy, tmp[2]! * dz, out);
}

/**
 * The checks of a load applied at a point (applyForceAtPoint, applyImpulseAtPoint): body `eid` must
 * be a live body, `load` (named `name`) and `point` vectors of `world.dimensions` finite numbers.
 * Wakes the body's island. @returns the body's slot.
 * @throws TypeError | RangeError naming `where` on a bad vector, a removed entity or one that is not a body.
 */
function pointLoadBody(
  world: PhysicsWorld,
  where: string,
  eid: number,
  name: string,
  load: ArrayLike<number>,
  point: ArrayLike<number>,
): number {
  const slot = resolveKind(world, eid, 'body', where);
  const d = world.dimensions;
  check.assertVector(where, name, load, d);
  check.assertVector(where, 'point', point, d);
  wakeIsland(world, slot);
  return slot;
}

/**
 * Applies force F (N, world frame) at the world point p (m): adds F to the force accumulator and
 * (p - x) x F to the torque accumulator. Call it from a system in the 'forces' stage (accumulators
 * are cleared at the start of each evaluation).
 * @param eid a body's handle.
 * @throws TypeError | RangeError on bad vectors, a removed entity or one that is not a body.
 * @category Bodies
 */
export function applyForceAtPoint(world: PhysicsWorld, eid: number, force: ArrayLike<number>, point: ArrayLike<number>): void {
  const slot = pointLoadBody(world, 'applyForceAtPoint', eid, 'force', force, point);
  const d = world.dimensions;
  const c = world.components;
  addComponentIfMissing(world, slot, c.Force);
  addComponentIfMissing(world, slot, c.Torque);
  const fx = force[0]!,
    fy = force[1]!,
    fz = d === 3 ? force[2]! : 0;
  const rx = point[0]! - c.Position.x[slot]!,
    ry = point[1]! - c.Position.y[slot]!,
    rz = d === 3 ? point[2]! - c.Position.z[slot]! : 0;
  c.Force.x[slot] = c.Force.x[slot]! + fx;
  c.Force.y[slot] = c.Force.y[slot]! + fy;
  c.Force.z[slot] = c.Force.z[slot]! + fz;
  c.Torque.x[slot] = c.Torque.x[slot]! + (ry * fz - rz * fy);
  c.Torque.y[slot] = c.Torque.y[slot]! + (rz * fx - rx * fz);
  c.Torque.z[slot] = c.Torque.z[slot]! + (rx * fy - ry * fx);
}

/**
 * Applies impulse J (N s, world frame) at the world point p (m): v += J / m and
 * w += I_w^-1 ((p - x) x J), with I_w the world-frame inertia (scalar, or R diag(I) R^T for a tensor).
 * For clicks, kicks and hits between steps.
 * @param eid a body's handle.
 * @throws TypeError | RangeError on bad vectors, a removed entity or one that is not a body.
 * @category Bodies
 */
export function applyImpulseAtPoint(world: PhysicsWorld, eid: number, impulse: ArrayLike<number>, point: ArrayLike<number>): void {
  const slot = pointLoadBody(world, 'applyImpulseAtPoint', eid, 'impulse', impulse, point);
  const d = world.dimensions;
  const c = world.components;
  const im = hasComponent(world, slot, c.Mass) ? c.Mass.inv[slot]! : 0;
  const jx = impulse[0]!,
    jy = impulse[1]!,
    jz = d === 3 ? impulse[2]! : 0;
  c.Velocity.x[slot] = c.Velocity.x[slot]! + jx * im;
  c.Velocity.y[slot] = c.Velocity.y[slot]! + jy * im;
  c.Velocity.z[slot] = c.Velocity.z[slot]! + jz * im;
  if (!hasComponent(world, slot, c.AngularVelocity)) return;
  const rx = point[0]! - c.Position.x[slot]!,
    ry = point[1]! - c.Position.y[slot]!,
    rz = d === 3 ? point[2]! - c.Position.z[slot]! : 0;
  const Lx = ry * jz - rz * jy,
    Ly = rz * jx - rx * jz,
    Lz = rx * jy - ry * jx;
  if (d === 3 && hasComponent(world, slot, c.InertiaTensor)) {
    const T = c.InertiaTensor;
    bodyDiagonal(world, slot, T.invX[slot]!, T.invY[slot]!, T.invZ[slot]!, Lx, Ly, Lz, tmp);
    c.AngularVelocity.x[slot] = c.AngularVelocity.x[slot]! + tmp[0]!;
    c.AngularVelocity.y[slot] = c.AngularVelocity.y[slot]! + tmp[1]!;
    c.AngularVelocity.z[slot] = c.AngularVelocity.z[slot]! + tmp[2]!;
    return;
  }
  const ii = hasComponent(world, slot, c.Inertia) ? c.Inertia.inv[slot]! : 0;
  if (d === 3) {
    c.AngularVelocity.x[slot] = c.AngularVelocity.x[slot]! + Lx * ii;
    c.AngularVelocity.y[slot] = c.AngularVelocity.y[slot]! + Ly * ii;
  }
  c.AngularVelocity.z[slot] = c.AngularVelocity.z[slot]! + Lz * ii;
}

/**
 * World-frame angular momentum of one body about its centre of mass, kg m^2/s: I_w w (scalar or tensor).
 * Written into out (length 3) and returned. @throws RangeError if the entity is not a body.
 * @category Bodies
 */
export function spinAngularMomentum(world: PhysicsWorld, eid: number, out: Float64Array = new Float64Array(3)): Float64Array {
  return spinMomentumOf(world, resolveKind(world, eid, 'body', 'spinAngularMomentum'), out);
}

/** Internal: spinAngularMomentum of the body in slot `eid`. */
function spinMomentumOf(world: PhysicsWorld, eid: number, out: Float64Array): Float64Array {
  const c = world.components;
  const wx = c.AngularVelocity.x[eid]!,
    wy = c.AngularVelocity.y[eid]!,
    wz = c.AngularVelocity.z[eid]!;
  if (world.dimensions === 3 && hasComponent(world, eid, c.InertiaTensor)) {
    const T = c.InertiaTensor;
    bodyDiagonal(world, eid, T.x[eid]!, T.y[eid]!, T.z[eid]!, wx, wy, wz, out);
    return out;
  }
  const I = hasComponent(world, eid, c.Inertia) ? c.Inertia.value[eid]! : 0;
  out[0] = world.dimensions === 3 ? I * wx : 0;
  out[1] = world.dimensions === 3 ? I * wy : 0;
  out[2] = I * wz;
  return out;
}

const spinL = new Float64Array(3);

/**
 * Rotational kinetic energy of one body, J: w . (I_w w) / 2. @throws RangeError if the entity is not a body.
 * @category Bodies
 */
export function spinKineticEnergy(world: PhysicsWorld, eid: number): number {
  const slot = resolveKind(world, eid, 'body', 'spinKineticEnergy');
  const L = spinMomentumOf(world, slot, spinL);
  const c = world.components;
  return 0.5 * (L[0]! * c.AngularVelocity.x[slot]! + L[1]! * c.AngularVelocity.y[slot]! + L[2]! * c.AngularVelocity.z[slot]!);
}

/**
 * Sets angular damping, torque -k w with k in N m s (>= 0). @throws RangeError on bad k or a missing body.
 * @category Bodies
 */
export function setAngularDamping(world: PhysicsWorld, eid: number, k: number): void {
  const slot = resolveKind(world, eid, 'body', 'setAngularDamping');
  check.assertNonNegative('setAngularDamping', 'k', k);
  const c = world.components;
  addComponentIfMissing(world, slot, c.AngularDamping);
  c.AngularDamping.k[slot] = k;
}

/**
 * Options of `addPlane`.
 * @category Bodies
 */
export interface PlaneOptions extends MaterialOptions {
  /** Normal pointing out of the solid side (normalised here; 2 components in 2D, 3 in 3D). */
  normal: ArrayLike<number>;
  /** A point on the plane, m. Default origin. */
  point?: ArrayLike<number>;
}

/**
 * Adds a static infinite plane (a line in 2D) that balls rest on, roll on and bounce off.
 * @returns its handle. Atomic: a refused call leaves the world as it was.
 * @throws TypeError | RangeError on missing, unknown or null options, a zero or malformed normal, bad
 *   material values, or a full world.
 * @category Bodies
 */
export function addPlane(world: PhysicsWorld, options: PlaneOptions): number {
  const where = 'addPlane';
  check.assertOptions(where, options, ['normal', 'point', 'restitution', 'friction', 'staticFriction']);
  const d = world.dimensions;
  const [nx, ny, nz] = check.unitVector(where, 'normal', options.normal, d);
  if (options.point !== undefined) check.assertVector(where, 'point', options.point, d);
  assertMaterial(where, options);
  const p = options.point;
  const dist = p ? nx * p[0]! + ny * p[1]! + (d === 3 ? nz * p[2]! : 0) : 0;
  check.assertFinite(where, 'offset', dist);
  const eid = createSlot(world, where);
  const c = world.components;
  addComponent(world, eid, c.Plane);
  addComponent(world, eid, c.Static);
  addComponent(world, eid, c.Material);
  c.Plane.nx[eid] = nx;
  c.Plane.ny[eid] = ny;
  c.Plane.nz[eid] = nz;
  c.Plane.d[eid] = dist;
  writeMaterial(world, eid, options);
  return currentHandle(world, eid);
}
