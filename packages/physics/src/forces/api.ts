import { addComponent, entityExists, hasComponent } from 'bitecs';
import type { PhysicsWorld } from '../world.js';
import { addComponentIfMissing } from '../world.js';
import { createEntity } from '../bodies.js';
import {
  assertFinite, assertInteger, assertKnownKeys, assertNonNegative, assertPositive, assertVector, describe,
} from '../validate.js';
import { BuoyancyShape } from './fluid.js';

/**
 * Validated helpers that give bodies force laws and add field and spring entities. Each writes the
 * components documented in components.ts; the force-law systems of the `forces` stage do the rest.
 * Vectors have `world.dimensions` components unless said otherwise.
 */

function assertBody(where: string, world: PhysicsWorld, eid: number, param = 'entity'): void {
  if (typeof eid !== 'number' || !Number.isInteger(eid) || eid < 1 || !entityExists(world, eid)) {
    throw new RangeError(`${where}: ${param} ${describe(eid)} does not exist in this world`);
  }
  if (!hasComponent(world, eid, world.components.Position)) {
    throw new RangeError(`${where}: ${param} ${eid} is not a body (it has no Position)`);
  }
}

function vec3(world: PhysicsWorld, v: ArrayLike<number>): [number, number, number] {
  return [v[0]!, v[1]!, world.dimensions === 3 ? v[2]! : 0];
}

/**
 * Scales the uniform gravity this body feels (1 normal, 0 none, negative upward).
 * @throws RangeError on a missing body or a non-finite scale.
 */
export function setGravityScale(world: PhysicsWorld, eid: number, scale: number): void {
  assertBody('setGravityScale', world, eid);
  assertFinite('setGravityScale', 'scale', scale);
  addComponentIfMissing(world, eid, world.components.GravityScale);
  world.components.GravityScale.value[eid] = scale;
}

/**
 * Makes the body take part in mutual Newtonian gravity (with every other body so marked), using its
 * mass. Constant and softening: `setGravitation`. @throws RangeError on a missing body.
 */
export function enableMutualGravity(world: PhysicsWorld, eid: number): void {
  assertBody('enableMutualGravity', world, eid);
  addComponentIfMissing(world, eid, world.components.MutualGravity);
}

/**
 * Makes the body an attractor of `mass` kg (> 0) that pulls every dynamic body, with softening length
 * `softening` m (>= 0, default 0). @throws TypeError | RangeError on bad values or a missing body.
 */
export function setAttractor(world: PhysicsWorld, eid: number, options: { mass: number; softening?: number }): void {
  const where = 'setAttractor';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['mass', 'softening']);
  assertPositive(where, 'mass', options.mass);
  if (options.softening !== undefined) assertNonNegative(where, 'softening', options.softening);
  const c = world.components;
  addComponentIfMissing(world, eid, c.Attractor);
  c.Attractor.mass[eid] = options.mass;
  c.Attractor.softening[eid] = options.softening ?? 0;
}

/** Sets the body's electric charge, C (finite; 0 removes nothing but exerts nothing). @throws RangeError. */
export function setCharge(world: PhysicsWorld, eid: number, charge: number): void {
  assertBody('setCharge', world, eid);
  assertFinite('setCharge', 'charge', charge);
  addComponentIfMissing(world, eid, world.components.Charge);
  world.components.Charge.value[eid] = charge;
}

/** Options of a uniform field entity: E0 (or B0), and an oscillating part A cos(omega t + phase). */
export interface FieldOptions {
  /** Constant part, V/m (electric) or T (magnetic). In 2D a magnetic field is a number (B_z) or a 3-vector. */
  field?: ArrayLike<number> | number;
  /** Amplitude of the oscillating part, same unit and shape. */
  amplitude?: ArrayLike<number> | number;
  /** Angular frequency, rad/s, >= 0. */
  omega?: number;
  /** Phase, rad. */
  phase?: number;
}

function fieldEntity(world: PhysicsWorld, where: string, F: PhysicsWorld['components']['ElectricField'], options: FieldOptions, magnetic: boolean): number {
  assertKnownKeys(where, options, ['field', 'amplitude', 'omega', 'phase']);
  const read = (name: string, v: ArrayLike<number> | number | undefined): [number, number, number] => {
    if (v === undefined) return [0, 0, 0];
    if (typeof v === 'number') {
      if (!(magnetic && world.dimensions === 2)) throw new TypeError(`${where}: ${name} must be an array of ${world.dimensions} numbers, got ${describe(v)}`);
      assertFinite(where, name, v);
      return [0, 0, v];
    }
    const n = magnetic ? (v.length === 3 ? 3 : world.dimensions) : world.dimensions;
    assertVector(where, name, v, n);
    return [v[0]!, v[1]!, n === 3 ? v[2]! : 0];
  };
  const f = read('field', options.field), a = read('amplitude', options.amplitude);
  if (options.omega !== undefined) assertNonNegative(where, 'omega', options.omega);
  if (options.phase !== undefined) assertFinite(where, 'phase', options.phase);
  const eid = createEntity(world);
  addComponent(world, eid, F);
  F.x[eid] = f[0]; F.y[eid] = f[1]; F.z[eid] = f[2];
  F.ampX[eid] = a[0]; F.ampY[eid] = a[1]; F.ampZ[eid] = a[2];
  F.omega[eid] = options.omega ?? 0; F.phase[eid] = options.phase ?? 0;
  return eid;
}

/**
 * Adds a uniform (optionally oscillating) electric field, V/m, felt by every charged body as q E.
 * @returns the field entity. @throws TypeError | RangeError on bad vectors or values.
 */
export function addElectricField(world: PhysicsWorld, options: FieldOptions): number {
  return fieldEntity(world, 'addElectricField', world.components.ElectricField, options, false);
}

/**
 * Adds a uniform (optionally oscillating) magnetic field, T, felt by every charged body as q v x B.
 * In a 2D world give B_z as a number (out of the screen). @returns the field entity.
 * @throws TypeError | RangeError on bad vectors or values.
 */
export function addMagneticField(world: PhysicsWorld, options: FieldOptions): number {
  return fieldEntity(world, 'addMagneticField', world.components.MagneticField, options, true);
}

/**
 * Gives the body a central force F = k r^(n-1) r_hat about `centre`. k < 0 attracts.
 * @throws TypeError | RangeError on bad values or a missing body.
 */
export function setCentralForce(world: PhysicsWorld, eid: number, options: { centre: ArrayLike<number>; k: number; n: number }): void {
  const where = 'setCentralForce';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['centre', 'k', 'n']);
  assertVector(where, 'centre', options.centre, world.dimensions);
  assertFinite(where, 'k', options.k);
  assertFinite(where, 'n', options.n);
  const c = world.components;
  addComponentIfMissing(world, eid, c.CentralForce);
  const [x, y, z] = vec3(world, options.centre);
  c.CentralForce.cx[eid] = x; c.CentralForce.cy[eid] = y; c.CentralForce.cz[eid] = z;
  c.CentralForce.k[eid] = options.k; c.CentralForce.n[eid] = options.n;
}

/**
 * Sets linear (N s/m) and/or quadratic (kg/m) drag coefficients, both >= 0, against the wind.
 * @throws RangeError on negative or non-finite coefficients, or a missing body.
 */
export function setDrag(world: PhysicsWorld, eid: number, options: { linear?: number; quadratic?: number }): void {
  const where = 'setDrag';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['linear', 'quadratic']);
  const c = world.components;
  if (options.linear !== undefined) {
    assertNonNegative(where, 'linear', options.linear);
    addComponentIfMissing(world, eid, c.LinearDrag);
    c.LinearDrag.k[eid] = options.linear;
  }
  if (options.quadratic !== undefined) {
    assertNonNegative(where, 'quadratic', options.quadratic);
    addComponentIfMissing(world, eid, c.QuadraticDrag);
    c.QuadraticDrag.k[eid] = options.quadratic;
  }
}

/**
 * Gives the body lift k |v_rel| (axis x v_rel): `k` kg/m >= 0; `axis` a unit 3-vector (default z).
 * @throws TypeError | RangeError on bad values or a missing body.
 */
export function setLift(world: PhysicsWorld, eid: number, options: { k: number; axis?: ArrayLike<number> }): void {
  const where = 'setLift';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['k', 'axis']);
  assertNonNegative(where, 'k', options.k);
  let ax = 0, ay = 0, az = 1;
  if (options.axis !== undefined) {
    assertVector(where, 'axis', options.axis, 3);
    const n = Math.hypot(options.axis[0]!, options.axis[1]!, options.axis[2]!);
    if (!(n > 0)) throw new RangeError(`${where}: axis must not be zero, got ${describe(options.axis)}`);
    ax = options.axis[0]! / n; ay = options.axis[1]! / n; az = options.axis[2]! / n;
  }
  const c = world.components;
  addComponentIfMissing(world, eid, c.Lift);
  c.Lift.k[eid] = options.k; c.Lift.axisX[eid] = ax; c.Lift.axisY[eid] = ay; c.Lift.axisZ[eid] = az;
}

/** Options of `setBuoyancy`: a ball of `radius`, or a box of `halfExtents` (x, y[, z]). */
export interface BuoyancyOptions {
  shape: 'ball' | 'box';
  /** Ball radius, m, > 0. */
  radius?: number;
  /** Box half extents, m, each > 0 (2 numbers in 2D, 3 in 3D). */
  halfExtents?: ArrayLike<number>;
  /** Quadratic drag coefficient in the fluid when fully submerged, kg/m, >= 0. Default 0. */
  dragCoefficient?: number;
}

/**
 * Makes the body float: buoyancy and fluid drag in every FluidRegion it dips into.
 * @throws TypeError | RangeError on an unknown shape, missing or non-positive sizes, or a missing body.
 */
export function setBuoyancy(world: PhysicsWorld, eid: number, options: BuoyancyOptions): void {
  const where = 'setBuoyancy';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['shape', 'radius', 'halfExtents', 'dragCoefficient']);
  const c = world.components;
  const B = c.Buoyancy;
  if (options.shape === 'ball') {
    assertPositive(where, 'radius', options.radius);
  } else if (options.shape === 'box') {
    assertVector(where, 'halfExtents', options.halfExtents, world.dimensions);
    for (let i = 0; i < world.dimensions; i++) assertPositive(where, `halfExtents[${i}]`, options.halfExtents![i]);
  } else {
    throw new RangeError(`${where}: shape must be 'ball' or 'box', got ${describe(options.shape)}`);
  }
  if (options.dragCoefficient !== undefined) assertNonNegative(where, 'dragCoefficient', options.dragCoefficient);
  addComponentIfMissing(world, eid, B);
  if (options.shape === 'ball') {
    B.shape[eid] = BuoyancyShape.Ball; B.radius[eid] = options.radius!;
  } else {
    const h = options.halfExtents!;
    B.shape[eid] = BuoyancyShape.Box; B.halfX[eid] = h[0]!; B.halfY[eid] = h[1]!; B.halfZ[eid] = world.dimensions === 3 ? h[2]! : 0.5;
  }
  B.dragCoefficient[eid] = options.dragCoefficient ?? 0;
}

/**
 * Adds a fluid below y = `surface` with `density` (kg/m^3, or kg/m^2 in 2D; > 0), optionally limited
 * to x in `xRange` and z in `zRange`. @returns the region entity. @throws TypeError | RangeError.
 */
export function addFluidRegion(world: PhysicsWorld, options: { surface: number; density: number; xRange?: [number, number]; zRange?: [number, number] }): number {
  const where = 'addFluidRegion';
  assertKnownKeys(where, options, ['surface', 'density', 'xRange', 'zRange']);
  assertFinite(where, 'surface', options.surface);
  assertPositive(where, 'density', options.density);
  for (const key of ['xRange', 'zRange'] as const) {
    const r = options[key];
    if (r === undefined) continue;
    assertVector(where, key, r, 2);
    if (!(r[1] > r[0])) throw new RangeError(`${where}: ${key}[1] must be > ${key}[0], got ${describe(r)}`);
  }
  const eid = createEntity(world);
  const F = world.components.FluidRegion;
  addComponent(world, eid, F);
  F.surface[eid] = options.surface; F.density[eid] = options.density;
  if (options.xRange) { F.minX[eid] = options.xRange[0]; F.maxX[eid] = options.xRange[1]; }
  if (options.zRange) { F.minZ[eid] = options.zRange[0]; F.maxZ[eid] = options.zRange[1]; }
  return eid;
}

/** Options of `addSpring`. Exactly one of `a` and `anchor` is given. */
export interface SpringOptions {
  /** First body (entity id). */
  a?: number;
  /** Fixed anchor point instead of a first body, m. */
  anchor?: ArrayLike<number>;
  /** Second body (entity id). */
  b: number;
  /** Stiffness, N/m, >= 0. */
  stiffness: number;
  /** Rest length, m, >= 0. Default: the current distance. */
  restLength?: number;
  /** Damping along the spring, N s/m, >= 0. Default 0. */
  damping?: number;
  /** Bungee: pulls only while stretched. Default false. */
  oneSided?: boolean;
}

/**
 * Adds a spring entity joining two bodies, or a body and a fixed anchor. The bodies get force
 * accumulators. Removing either body removes the spring.
 * @returns the spring entity.
 * @throws TypeError on unknown options; RangeError on a missing body (e.g. a spring to a removed
 *   entity), both or neither of a and anchor, a = b, or negative stiffness, damping or rest length.
 */
export function addSpring(world: PhysicsWorld, options: SpringOptions): number {
  const where = 'addSpring';
  assertKnownKeys(where, options, ['a', 'anchor', 'b', 'stiffness', 'restLength', 'damping', 'oneSided']);
  if ((options.a === undefined) === (options.anchor === undefined)) {
    throw new RangeError(`${where}: give exactly one of a (a body) and anchor (a point)`);
  }
  assertBody(where, world, options.b, 'b');
  if (options.a !== undefined) {
    assertBody(where, world, options.a, 'a');
    if (options.a === options.b) throw new RangeError(`${where}: a and b are the same entity ${options.a}`);
  } else {
    assertVector(where, 'anchor', options.anchor, world.dimensions);
  }
  assertNonNegative(where, 'stiffness', options.stiffness);
  if (options.damping !== undefined) assertNonNegative(where, 'damping', options.damping);
  if (options.restLength !== undefined) assertNonNegative(where, 'restLength', options.restLength);
  const c = world.components;
  const P = c.Position;
  const b = options.b;
  const [ax, ay, az] = options.a !== undefined ? [P.x[options.a]!, P.y[options.a]!, P.z[options.a]!] : vec3(world, options.anchor!);
  const length = Math.hypot(P.x[b]! - ax, P.y[b]! - ay, P.z[b]! - az);
  for (const e of [options.a, b]) if (e !== undefined && !hasComponent(world, e, c.Static) && !hasComponent(world, e, c.Kinematic)) addComponentIfMissing(world, e, c.Force);
  const s = createEntity(world);
  addComponent(world, s, c.Spring);
  const S = c.Spring;
  S.a[s] = options.a ?? 0; S.b[s] = b;
  S.anchorX[s] = ax; S.anchorY[s] = ay; S.anchorZ[s] = az;
  S.stiffness[s] = options.stiffness;
  S.restLength[s] = options.restLength ?? length;
  S.damping[s] = options.damping ?? 0;
  S.oneSided[s] = options.oneSided ? 1 : 0;
  return s;
}

/**
 * Periodic driving force F = F0 cos(omega t + phase). @throws TypeError | RangeError on bad values.
 */
export function setDrivingForce(world: PhysicsWorld, eid: number, options: { amplitude: ArrayLike<number>; omega: number; phase?: number }): void {
  const where = 'setDrivingForce';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['amplitude', 'omega', 'phase']);
  assertVector(where, 'amplitude', options.amplitude, world.dimensions);
  assertNonNegative(where, 'omega', options.omega);
  if (options.phase !== undefined) assertFinite(where, 'phase', options.phase);
  const c = world.components;
  addComponentIfMissing(world, eid, c.DrivingForce);
  const [x, y, z] = vec3(world, options.amplitude);
  const D = c.DrivingForce;
  D.x[eid] = x; D.y[eid] = y; D.z[eid] = z; D.omega[eid] = options.omega; D.phase[eid] = options.phase ?? 0;
}

/**
 * Seeded random driving force: components in [-magnitude, magnitude] N, smooth over
 * `correlationTime` s (> 0). `seed` an integer (default: the world's generator draws one).
 * @throws TypeError | RangeError on bad values.
 */
export function setRandomForce(world: PhysicsWorld, eid: number, options: { magnitude: number; correlationTime: number; seed?: number }): void {
  const where = 'setRandomForce';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['magnitude', 'correlationTime', 'seed']);
  assertNonNegative(where, 'magnitude', options.magnitude);
  assertPositive(where, 'correlationTime', options.correlationTime);
  if (options.seed !== undefined) assertInteger(where, 'seed', options.seed, -2147483648, 4294967295);
  const c = world.components;
  addComponentIfMissing(world, eid, c.RandomForce);
  c.RandomForce.magnitude[eid] = options.magnitude;
  c.RandomForce.correlationTime[eid] = options.correlationTime;
  c.RandomForce.seed[eid] = options.seed ?? world.rng.nextUint32();
}

/**
 * Rocket engine: exhaust velocity (m/s, > 0), mass flow rate (kg/s, >= 0), fuel (kg, >= 0, less than
 * the body's mass), direction (unit vector, world frame; normalised here). The body's mass includes
 * the fuel and drops as it burns. @throws TypeError | RangeError on bad values, fuel not less than the
 * mass, or a missing or massless body.
 */
export function setThrust(world: PhysicsWorld, eid: number, options: { exhaustVelocity: number; massFlowRate: number; fuel: number; direction: ArrayLike<number> }): void {
  const where = 'setThrust';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['exhaustVelocity', 'massFlowRate', 'fuel', 'direction']);
  assertPositive(where, 'exhaustVelocity', options.exhaustVelocity);
  assertNonNegative(where, 'massFlowRate', options.massFlowRate);
  assertNonNegative(where, 'fuel', options.fuel);
  assertVector(where, 'direction', options.direction, world.dimensions);
  const c = world.components;
  if (!hasComponent(world, eid, c.Mass) || !(c.Mass.value[eid]! > 0)) throw new RangeError(`${where}: entity ${eid} has no positive mass`);
  if (!(options.fuel < c.Mass.value[eid]!)) {
    throw new RangeError(`${where}: fuel (${options.fuel} kg) must be less than the body's mass (${c.Mass.value[eid]} kg), which includes it`);
  }
  const [x, y, z] = vec3(world, options.direction);
  const n = Math.hypot(x, y, z);
  if (!(n > 0)) throw new RangeError(`${where}: direction must not be zero`);
  addComponentIfMissing(world, eid, c.Thrust);
  const T = c.Thrust;
  T.exhaustVelocity[eid] = options.exhaustVelocity; T.massFlowRate[eid] = options.massFlowRate; T.fuel[eid] = options.fuel;
  T.dirX[eid] = x / n; T.dirY[eid] = y / n; T.dirZ[eid] = z / n;
}

/**
 * Gives the body a vortex force F = k r^(n-1) (axis x r_hat) about the axis through `centre`
 * (axis unit 3-vector, default z). @throws TypeError | RangeError on bad values or a missing body.
 */
export function setVortex(world: PhysicsWorld, eid: number, options: { centre: ArrayLike<number>; k: number; n?: number; axis?: ArrayLike<number> }): void {
  const where = 'setVortex';
  assertBody(where, world, eid);
  assertKnownKeys(where, options, ['centre', 'k', 'n', 'axis']);
  assertVector(where, 'centre', options.centre, world.dimensions);
  assertFinite(where, 'k', options.k);
  if (options.n !== undefined) assertFinite(where, 'n', options.n);
  let ax = 0, ay = 0, az = 1;
  if (options.axis !== undefined) {
    assertVector(where, 'axis', options.axis, 3);
    const len = Math.hypot(options.axis[0]!, options.axis[1]!, options.axis[2]!);
    if (!(len > 0)) throw new RangeError(`${where}: axis must not be zero`);
    ax = options.axis[0]! / len; ay = options.axis[1]! / len; az = options.axis[2]! / len;
  }
  const c = world.components;
  addComponentIfMissing(world, eid, c.Vortex);
  const [x, y, z] = vec3(world, options.centre);
  const V = c.Vortex;
  V.cx[eid] = x; V.cy[eid] = y; V.cz[eid] = z; V.axisX[eid] = ax; V.axisY[eid] = ay; V.axisZ[eid] = az;
  V.k[eid] = options.k; V.n[eid] = options.n ?? 1;
}
