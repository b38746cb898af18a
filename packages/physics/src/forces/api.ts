import { addComponent, hasComponent } from 'bitecs';
import * as check from '../validation/validate.js';
import { createSlot, currentHandle, resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addComponentIfMissing } from '../world/options.js';
import { BuoyancyShape } from './fluid.js';

/**
 * Validated helpers that give bodies force laws and add field and spring entities. Each writes the
 * components documented in world/components.ts; the force-law systems of the `forces` stage do the rest.
 * Vectors have `world.dimensions` components unless said otherwise. Functions take entity handles
 * (see world/handles.ts) and refuse a removed entity or one of the wrong kind; options objects are required
 * unless said otherwise, and unknown or null options are refused.
 */

function vec3(world: PhysicsWorld, v: ArrayLike<number>): [number, number, number] {
  return [v[0]!, v[1]!, world.dimensions === 3 ? v[2]! : 0];
}

/** Writes the world vector `v` (z 0 in a 2D world) into slot `e` of the stores x, y and z. */
function writeVec3(world: PhysicsWorld, v: ArrayLike<number>, x: Float64Array, y: Float64Array, z: Float64Array, e: number): void {
  x[e] = v[0]!;
  y[e] = v[1]!;
  z[e] = world.dimensions === 3 ? v[2]! : 0;
}

/**
 * The slot of body handle `body`, after `options` is checked to hold only the names `keys`.
 * @throws RangeError naming `where` on a removed entity or one that is not a body; TypeError on an
 *   unknown or null option.
 */
function optionsBody(world: PhysicsWorld, body: number, where: string, options: object, keys: readonly string[]): number {
  const eid = resolveKind(world, body, 'body', where);
  check.assertOptions(where, options, keys);
  return eid;
}

/**
 * Scales the uniform gravity this body feels (1 normal, 0 none, negative upward).
 * @throws RangeError on a non-finite scale, a removed entity or one that is not a body.
 * @category Forces
 */
export function setGravityScale(world: PhysicsWorld, body: number, scale: number): void {
  const eid = resolveKind(world, body, 'body', 'setGravityScale');
  check.assertFinite('setGravityScale', 'scale', scale);
  addComponentIfMissing(world, eid, world.components.GravityScale);
  world.components.GravityScale.value[eid] = scale;
}

/**
 * Makes the body take part in mutual Newtonian gravity (with every other body so marked), using its
 * mass. Constant and softening: `setGravitation`. @throws RangeError on a removed entity or one that is not a body.
 * @category Forces
 */
export function enableMutualGravity(world: PhysicsWorld, body: number): void {
  const eid = resolveKind(world, body, 'body', 'enableMutualGravity');
  addComponentIfMissing(world, eid, world.components.MutualGravity);
}

/**
 * Makes the body an attractor of `mass` kg (> 0) that pulls every dynamic body, with softening length
 * `softening` m (>= 0, default 0). @throws TypeError | RangeError on bad values a removed entity or one that is not a body.
 * @category Forces
 */
export function setAttractor(world: PhysicsWorld, body: number, options: { mass: number; softening?: number }): void {
  const where = 'setAttractor';
  const eid = optionsBody(world, body, where, options, ['mass', 'softening']);
  check.assertPositive(where, 'mass', options.mass);
  if (options.softening !== undefined) check.assertNonNegative(where, 'softening', options.softening);
  const c = world.components;
  addComponentIfMissing(world, eid, c.Attractor);
  c.Attractor.mass[eid] = options.mass;
  c.Attractor.softening[eid] = options.softening ?? 0;
}

/**
 * Sets the body's electric charge, C (finite; 0 removes nothing but exerts nothing). @throws RangeError.
 * @category Forces
 */
export function setCharge(world: PhysicsWorld, body: number, charge: number): void {
  const eid = resolveKind(world, body, 'body', 'setCharge');
  check.assertFinite('setCharge', 'charge', charge);
  addComponentIfMissing(world, eid, world.components.Charge);
  world.components.Charge.value[eid] = charge;
}

/**
 * Options of a uniform field entity: E(t) = E0 + A cos(omega t + phase) (or B(t) likewise), the same
 * at every point. `addElectricField` / `addMagneticField` start omitted fields at 0; `setElectricField`
 * / `setMagneticField` keep their current value.
 * @category Forces
 */
export interface FieldOptions {
  /** Constant part E0 or B0: V/m (electric) or T (magnetic), finite. In 2D a magnetic field is a number (B_z, out of the screen) or a 3-vector. */
  field?: ArrayLike<number> | number;
  /** Amplitude A of the oscillating part, same unit and shape as `field`. */
  amplitude?: ArrayLike<number> | number;
  /** Angular frequency omega, rad/s, finite and >= 0. */
  omega?: number;
  /** Phase, rad, finite. */
  phase?: number;
}

const FIELD_OPTIONS = ['field', 'amplitude', 'omega', 'phase'] as const;

/** Checks field options without touching the world; returns the vectors as (x, y, z) or null where omitted. */
function checkField(
  world: PhysicsWorld,
  where: string,
  options: FieldOptions,
  magnetic: boolean,
): { f: number[] | null; a: number[] | null } {
  check.assertOptions(where, options, FIELD_OPTIONS);
  const read = (name: string, v: ArrayLike<number> | number | undefined): number[] | null => {
    if (v === undefined) return null;
    if (typeof v === 'number') {
      if (!(magnetic && world.dimensions === 2))
        throw new TypeError(`${where}: ${name} must be an array of ${world.dimensions} numbers, got ${check.describe(v)}`);
      check.assertFinite(where, name, v);
      return [0, 0, v];
    }
    const n = magnetic && world.dimensions === 2 && (v as ArrayLike<number>).length === 3 ? 3 : world.dimensions;
    check.assertVector(where, name, v, n);
    return [v[0]!, v[1]!, n === 3 ? v[2]! : 0];
  };
  const f = read('field', options.field),
    a = read('amplitude', options.amplitude);
  if (options.omega !== undefined) check.assertNonNegative(where, 'omega', options.omega);
  if (options.phase !== undefined) check.assertFinite(where, 'phase', options.phase);
  return { f, a };
}

function writeField(
  F: PhysicsWorld['components']['ElectricField'],
  eid: number,
  options: FieldOptions,
  f: number[] | null,
  a: number[] | null,
): void {
  if (f) {
    F.x[eid] = f[0]!;
    F.y[eid] = f[1]!;
    F.z[eid] = f[2]!;
  }
  if (a) {
    F.ampX[eid] = a[0]!;
    F.ampY[eid] = a[1]!;
    F.ampZ[eid] = a[2]!;
  }
  if (options.omega !== undefined) F.omega[eid] = options.omega;
  if (options.phase !== undefined) F.phase[eid] = options.phase;
}

function fieldEntity(
  world: PhysicsWorld,
  where: string,
  F: PhysicsWorld['components']['ElectricField'],
  options: FieldOptions,
  magnetic: boolean,
): number {
  const { f, a } = checkField(world, where, options, magnetic);
  const eid = createSlot(world, where);
  addComponent(world, eid, F); // the observer zeroes every field
  writeField(F, eid, options, f, a);
  return currentHandle(world, eid);
}

/**
 * Adds a uniform (optionally oscillating) electric field, V/m, felt by every charged body as q E.
 * Change it later with `setElectricField`. @returns the field's handle. Atomic.
 * @throws TypeError | RangeError on missing, unknown or null options, bad vectors or values, a full world.
 * @category Forces
 */
export function addElectricField(world: PhysicsWorld, options: FieldOptions): number {
  return fieldEntity(world, 'addElectricField', world.components.ElectricField, options, false);
}

/**
 * Adds a uniform (optionally oscillating) magnetic field, T, felt by every charged body as q v x B.
 * In a 2D world give B_z as a number (out of the screen). Change it later with `setMagneticField`.
 * @returns the field's handle. Atomic.
 * @throws TypeError | RangeError on missing, unknown or null options, bad vectors or values, a full world.
 * @category Forces
 */
export function addMagneticField(world: PhysicsWorld, options: FieldOptions): number {
  return fieldEntity(world, 'addMagneticField', world.components.MagneticField, options, true);
}

/**
 * Changes an electric field made by `addElectricField` at run time: any of `field` (E0, V/m), `amplitude`
 * (V/m), `omega` (rad/s, >= 0) and `phase` (rad); omitted options keep their value.
 * @example setElectricField(world, e, { field: [0, -200] }) // point it down, 200 V/m
 * @throws TypeError | RangeError on missing, unknown or null options, bad vectors or values, a removed
 *   entity or one that is not an electric field. A refused call changes nothing.
 * @category Forces
 */
export function setElectricField(world: PhysicsWorld, field: number, options: FieldOptions): void {
  const where = 'setElectricField';
  const eid = resolveKind(world, field, 'electric-field', where);
  const { f, a } = checkField(world, where, options, false);
  writeField(world.components.ElectricField, eid, options, f, a);
}

/**
 * Changes a magnetic field made by `addMagneticField` at run time: any of `field` (B0, T; in 2D a number
 * B_z or a 3-vector), `amplitude` (T), `omega` (rad/s, >= 0) and `phase` (rad); omitted options keep
 * their value.
 * @example setMagneticField(world, b, { field: -2 }) // in 2D: B_z = -2 T, the field flipped
 * @throws TypeError | RangeError on missing, unknown or null options, bad vectors or values, a removed
 *   entity or one that is not a magnetic field. A refused call changes nothing.
 * @category Forces
 */
export function setMagneticField(world: PhysicsWorld, field: number, options: FieldOptions): void {
  const where = 'setMagneticField';
  const eid = resolveKind(world, field, 'magnetic-field', where);
  const { f, a } = checkField(world, where, options, true);
  writeField(world.components.MagneticField, eid, options, f, a);
}

/**
 * Gives the body a central force F = k r^(n-1) r_hat about `centre`. k < 0 attracts.
 * @throws TypeError | RangeError on bad values a removed entity or one that is not a body.
 * @category Forces
 */
export function setCentralForce(world: PhysicsWorld, body: number, options: { centre: ArrayLike<number>; k: number; n: number }): void {
  const where = 'setCentralForce';
  const eid = optionsBody(world, body, where, options, ['centre', 'k', 'n']);
  check.assertVector(where, 'centre', options.centre, world.dimensions);
  check.assertFinite(where, 'k', options.k);
  check.assertFinite(where, 'n', options.n);
  const c = world.components;
  addComponentIfMissing(world, eid, c.CentralForce);
  writeVec3(world, options.centre, c.CentralForce.cx, c.CentralForce.cy, c.CentralForce.cz, eid);
  c.CentralForce.k[eid] = options.k;
  c.CentralForce.n[eid] = options.n;
}

/**
 * Sets linear (N s/m) and/or quadratic (kg/m) drag coefficients, both >= 0, against the wind.
 * @throws RangeError on negative or non-finite coefficients, a removed entity or one that is not a body.
 * @category Forces
 */
export function setDrag(world: PhysicsWorld, body: number, options: { linear?: number; quadratic?: number }): void {
  const where = 'setDrag';
  const eid = optionsBody(world, body, where, options, ['linear', 'quadratic']);
  if (options.linear !== undefined) check.assertNonNegative(where, 'linear', options.linear);
  if (options.quadratic !== undefined) check.assertNonNegative(where, 'quadratic', options.quadratic);
  writeDrag(world, eid, options.linear, options.quadratic);
}

/**
 * Gives body `eid` (a slot) the drag coefficients that are defined, already checked (>= 0): linear k in
 * F = -k v (N s/m, the LinearDrag component) and quadratic k in F = -k |v| v (kg/m, QuadraticDrag),
 * adding the components it lacks. An undefined coefficient leaves that drag as it is.
 */
export function writeDrag(world: PhysicsWorld, eid: number, linear: number | undefined, quadratic: number | undefined): void {
  const c = world.components;
  if (linear !== undefined) {
    addComponentIfMissing(world, eid, c.LinearDrag);
    c.LinearDrag.k[eid] = linear;
  }
  if (quadratic !== undefined) {
    addComponentIfMissing(world, eid, c.QuadraticDrag);
    c.QuadraticDrag.k[eid] = quadratic;
  }
}

/**
 * Gives the body lift k |v_rel| (axis x v_rel): `k` kg/m >= 0; `axis` a unit 3-vector (default z).
 * @throws TypeError | RangeError on bad values a removed entity or one that is not a body.
 * @category Forces
 */
export function setLift(world: PhysicsWorld, body: number, options: { k: number; axis?: ArrayLike<number> }): void {
  const where = 'setLift';
  const eid = optionsBody(world, body, where, options, ['k', 'axis']);
  check.assertNonNegative(where, 'k', options.k);
  const [ax, ay, az] = options.axis === undefined ? [0, 0, 1] : check.unitVector(where, 'axis', options.axis, 3);
  const c = world.components;
  addComponentIfMissing(world, eid, c.Lift);
  c.Lift.k[eid] = options.k;
  c.Lift.axisX[eid] = ax;
  c.Lift.axisY[eid] = ay;
  c.Lift.axisZ[eid] = az;
}

/**
 * Options of `setBuoyancy`: a ball of `radius`, or a box of `halfExtents` (x, y[, z]).
 * @category Forces
 */
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
 * @throws TypeError | RangeError on an unknown shape, missing or non-positive sizes, a removed entity or one that is not a body.
 * @category Forces
 */
export function setBuoyancy(world: PhysicsWorld, body: number, options: BuoyancyOptions): void {
  const where = 'setBuoyancy';
  const eid = optionsBody(world, body, where, options, ['shape', 'radius', 'halfExtents', 'dragCoefficient']);
  const c = world.components;
  const B = c.Buoyancy;
  check.assertOneOf(where, 'shape', options.shape, ['ball', 'box']);
  if (options.shape === 'ball') {
    check.assertPositive(where, 'radius', options.radius);
  } else {
    check.assertVector(where, 'halfExtents', options.halfExtents, world.dimensions);
    for (let i = 0; i < world.dimensions; i++) check.assertPositive(where, `halfExtents[${i}]`, options.halfExtents![i]);
  }
  if (options.dragCoefficient !== undefined) check.assertNonNegative(where, 'dragCoefficient', options.dragCoefficient);
  addComponentIfMissing(world, eid, B);
  if (options.shape === 'ball') {
    B.shape[eid] = BuoyancyShape.Ball;
    B.radius[eid] = options.radius!;
  } else {
    const h = options.halfExtents!;
    B.shape[eid] = BuoyancyShape.Box;
    B.halfX[eid] = h[0]!;
    B.halfY[eid] = h[1]!;
    B.halfZ[eid] = world.dimensions === 3 ? h[2]! : 0.5;
  }
  B.dragCoefficient[eid] = options.dragCoefficient ?? 0;
}

/**
 * Options of `addFluidRegion` and `setFluidRegion`: a fluid filling everything below the horizontal
 * surface y = `surface`, optionally only for x in `xRange` (and z in `zRange` in 3D).
 * @category Forces
 */
export interface FluidRegionOptions {
  /** Height of the free surface, m, finite. */
  surface?: number;
  /** Fluid density, kg/m^3 (kg/m^2 in 2D), finite and > 0 (water 1000, air 1.2). */
  density?: number;
  /** [min, max] of x the fluid spans, m, max > min. Default unbounded. */
  xRange?: [number, number];
  /** [min, max] of z the fluid spans (3D), m, max > min. Default unbounded. */
  zRange?: [number, number];
}

const FLUID_OPTIONS = ['surface', 'density', 'xRange', 'zRange'] as const;

function checkFluid(where: string, options: FluidRegionOptions): void {
  check.assertOptions(where, options, FLUID_OPTIONS);
  if (options.surface !== undefined) check.assertFinite(where, 'surface', options.surface);
  if (options.density !== undefined) check.assertPositive(where, 'density', options.density);
  for (const key of ['xRange', 'zRange'] as const) {
    const r = options[key];
    if (r === undefined) continue;
    check.assertVector(where, key, r, 2);
    if (!(r[1] > r[0])) throw new RangeError(`${where}: ${key}[1] must be > ${key}[0], got ${check.describe(r)}`);
  }
}

function writeFluid(world: PhysicsWorld, eid: number, options: FluidRegionOptions): void {
  const F = world.components.FluidRegion;
  if (options.surface !== undefined) F.surface[eid] = options.surface;
  if (options.density !== undefined) F.density[eid] = options.density;
  if (options.xRange) {
    F.minX[eid] = options.xRange[0];
    F.maxX[eid] = options.xRange[1];
  }
  if (options.zRange) {
    F.minZ[eid] = options.zRange[0];
    F.maxZ[eid] = options.zRange[1];
  }
}

/**
 * Adds a fluid below y = `surface` (required) with `density` (required; kg/m^3, or kg/m^2 in 2D; > 0),
 * optionally limited to x in `xRange` and z in `zRange`. Bodies given `setBuoyancy` float in it.
 * Change it later with `setFluidRegion`. @returns the region's handle. Atomic.
 * @throws TypeError | RangeError on missing, unknown or null options, bad values, or a full world.
 * @category Forces
 */
export function addFluidRegion(world: PhysicsWorld, options: FluidRegionOptions & { surface: number; density: number }): number {
  const where = 'addFluidRegion';
  checkFluid(where, options);
  check.assertFinite(where, 'surface', options.surface);
  check.assertPositive(where, 'density', options.density);
  const eid = createSlot(world, where);
  addComponent(world, eid, world.components.FluidRegion);
  writeFluid(world, eid, options);
  return currentHandle(world, eid);
}

/**
 * Changes a fluid region made by `addFluidRegion` at run time (a rising tide, a denser liquid): any of
 * `surface` (m), `density` (kg/m^3, > 0), `xRange`, `zRange` (m); omitted options keep their value.
 * @throws TypeError | RangeError on missing, unknown or null options, bad values, a removed entity or one
 *   that is not a fluid region. A refused call changes nothing.
 * @category Forces
 */
export function setFluidRegion(world: PhysicsWorld, region: number, options: FluidRegionOptions): void {
  const where = 'setFluidRegion';
  const eid = resolveKind(world, region, 'fluid-region', where);
  checkFluid(where, options);
  writeFluid(world, eid, options);
}

/**
 * Options of `addSpring`. Exactly one of `a` and `anchor` is given.
 * @category Forces
 */
export interface SpringOptions {
  /** First body (its handle). */
  a?: number;
  /** Fixed anchor point instead of a first body, m. */
  anchor?: ArrayLike<number>;
  /** Second body (its handle). */
  b: number;
  /** Stiffness, N/m, finite and >= 0. */
  stiffness: number;
  /** Rest length, m, >= 0. Default: the current distance. */
  restLength?: number;
  /** Damping along the spring, N s/m, >= 0. Default 0. */
  damping?: number;
  /** Bungee: pulls only while stretched (a boolean). Default false. */
  oneSided?: boolean;
}

/**
 * Adds a spring entity joining two bodies, or a body and a fixed anchor. The bodies get force
 * accumulators. Removing either body removes the spring. Change it later with `setSpring`.
 * Atomic: every option is checked, and room for the spring made sure of, before anything changes.
 * @returns the spring's handle.
 * @throws TypeError on missing, unknown or null options, or a non-boolean oneSided; RangeError on a
 *   removed body, an entity that is not a body, both or neither of a and anchor, a = b, negative
 *   stiffness, damping or rest length, or a full world.
 * @category Forces
 */
export function addSpring(world: PhysicsWorld, options: SpringOptions): number {
  const where = 'addSpring';
  check.assertOptions(where, options, ['a', 'anchor', 'b', 'stiffness', 'restLength', 'damping', 'oneSided']);
  if ((options.a === undefined) === (options.anchor === undefined)) {
    throw new RangeError(`${where}: give exactly one of a (a body) and anchor (a point)`);
  }
  const b = resolveKind(world, options.b, 'body', where, 'b');
  let a = 0;
  if (options.a !== undefined) {
    a = resolveKind(world, options.a, 'body', where, 'a');
    if (a === b) throw new RangeError(`${where}: a and b are the same entity ${options.a}`);
  } else {
    check.assertVector(where, 'anchor', options.anchor, world.dimensions);
  }
  check.assertNonNegative(where, 'stiffness', options.stiffness);
  if (options.damping !== undefined) check.assertNonNegative(where, 'damping', options.damping);
  if (options.restLength !== undefined) check.assertNonNegative(where, 'restLength', options.restLength);
  check.assertOptionalBoolean(where, 'oneSided', options.oneSided);
  const c = world.components;
  const P = c.Position;
  const [ax, ay, az] = a !== 0 ? [P.x[a]!, P.y[a]!, P.z[a]!] : vec3(world, options.anchor!);
  const length = Math.hypot(P.x[b]! - ax, P.y[b]! - ay, P.z[b]! - az);
  const s = createSlot(world, where);
  for (const e of [a, b])
    if (e !== 0 && !hasComponent(world, e, c.Static) && !hasComponent(world, e, c.Kinematic)) addComponentIfMissing(world, e, c.Force);
  addComponent(world, s, c.Spring);
  const S = c.Spring;
  S.a[s] = a;
  S.b[s] = b;
  S.anchorX[s] = ax;
  S.anchorY[s] = ay;
  S.anchorZ[s] = az;
  S.stiffness[s] = options.stiffness;
  S.restLength[s] = options.restLength ?? length;
  S.damping[s] = options.damping ?? 0;
  S.oneSided[s] = options.oneSided === true ? 1 : 0;
  return currentHandle(world, s);
}

/**
 * Options of `setSpring`; omitted options keep their value.
 * @category Forces
 */
export interface SpringSettings {
  /** Stiffness, N/m, finite and >= 0. */
  stiffness?: number;
  /** Rest length, m, finite and >= 0. */
  restLength?: number;
  /** Damping along the spring, N s/m, finite and >= 0. */
  damping?: number;
  /** Bungee: pulls only while stretched (a boolean). */
  oneSided?: boolean;
  /** Where the fixed end is, m (only for a spring made with `anchor`). */
  anchor?: ArrayLike<number>;
}

/**
 * Changes a spring made by `addSpring` at run time (stiffen it, shorten it, move its anchor).
 * @throws TypeError | RangeError on missing, unknown or null options, bad values, an anchor for a spring
 *   between two bodies, a removed entity or one that is not a spring. A refused call changes nothing.
 * @category Forces
 */
export function setSpring(world: PhysicsWorld, spring: number, options: SpringSettings): void {
  const where = 'setSpring';
  const s = resolveKind(world, spring, 'spring', where);
  check.assertOptions(where, options, ['stiffness', 'restLength', 'damping', 'oneSided', 'anchor']);
  if (options.stiffness !== undefined) check.assertNonNegative(where, 'stiffness', options.stiffness);
  if (options.restLength !== undefined) check.assertNonNegative(where, 'restLength', options.restLength);
  if (options.damping !== undefined) check.assertNonNegative(where, 'damping', options.damping);
  check.assertOptionalBoolean(where, 'oneSided', options.oneSided);
  const S = world.components.Spring;
  if (options.anchor !== undefined) {
    check.assertVector(where, 'anchor', options.anchor, world.dimensions);
    if (S.a[s] !== 0) throw new RangeError(`${where}: anchor is only for a spring with a fixed end; spring ${spring} joins two bodies`);
  }
  if (options.stiffness !== undefined) S.stiffness[s] = options.stiffness;
  if (options.restLength !== undefined) S.restLength[s] = options.restLength;
  if (options.damping !== undefined) S.damping[s] = options.damping;
  if (options.oneSided !== undefined) S.oneSided[s] = options.oneSided ? 1 : 0;
  if (options.anchor !== undefined) {
    writeVec3(world, options.anchor, S.anchorX, S.anchorY, S.anchorZ, s);
  }
}

/**
 * Periodic driving force F = F0 cos(omega t + phase). @throws TypeError | RangeError on bad values.
 * @category Forces
 */
export function setDrivingForce(
  world: PhysicsWorld,
  body: number,
  options: { amplitude: ArrayLike<number>; omega: number; phase?: number },
): void {
  const where = 'setDrivingForce';
  const eid = optionsBody(world, body, where, options, ['amplitude', 'omega', 'phase']);
  check.assertVector(where, 'amplitude', options.amplitude, world.dimensions);
  check.assertNonNegative(where, 'omega', options.omega);
  if (options.phase !== undefined) check.assertFinite(where, 'phase', options.phase);
  const c = world.components;
  addComponentIfMissing(world, eid, c.DrivingForce);
  const D = c.DrivingForce;
  writeVec3(world, options.amplitude, D.x, D.y, D.z, eid);
  D.omega[eid] = options.omega;
  D.phase[eid] = options.phase ?? 0;
}

/**
 * Seeded random driving force: components in [-magnitude, magnitude] N, smooth over
 * `correlationTime` s (> 0). `seed` an integer (default: the world's generator draws one).
 * @throws TypeError | RangeError on bad values.
 * @category Forces
 */
export function setRandomForce(
  world: PhysicsWorld,
  body: number,
  options: { magnitude: number; correlationTime: number; seed?: number },
): void {
  const where = 'setRandomForce';
  const eid = optionsBody(world, body, where, options, ['magnitude', 'correlationTime', 'seed']);
  check.assertNonNegative(where, 'magnitude', options.magnitude);
  check.assertPositive(where, 'correlationTime', options.correlationTime);
  if (options.seed !== undefined) check.assertInteger(where, 'seed', options.seed, -2147483648, 4294967295);
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
 * @category Forces
 */
export function setThrust(
  world: PhysicsWorld,
  body: number,
  options: { exhaustVelocity: number; massFlowRate: number; fuel: number; direction: ArrayLike<number> },
): void {
  const where = 'setThrust';
  const eid = optionsBody(world, body, where, options, ['exhaustVelocity', 'massFlowRate', 'fuel', 'direction']);
  check.assertPositive(where, 'exhaustVelocity', options.exhaustVelocity);
  check.assertNonNegative(where, 'massFlowRate', options.massFlowRate);
  check.assertNonNegative(where, 'fuel', options.fuel);
  const [dx, dy, dz] = check.unitVector(where, 'direction', options.direction, world.dimensions);
  const c = world.components;
  if (!hasComponent(world, eid, c.Mass) || !(c.Mass.value[eid]! > 0)) throw new RangeError(`${where}: entity ${eid} has no positive mass`);
  if (!(options.fuel < c.Mass.value[eid]!)) {
    throw new RangeError(
      `${where}: fuel (${options.fuel} kg) must be less than the body's mass (${c.Mass.value[eid]} kg), which includes it`,
    );
  }
  addComponentIfMissing(world, eid, c.Thrust);
  const T = c.Thrust;
  T.exhaustVelocity[eid] = options.exhaustVelocity;
  T.massFlowRate[eid] = options.massFlowRate;
  T.fuel[eid] = options.fuel;
  T.dirX[eid] = dx;
  T.dirY[eid] = dy;
  T.dirZ[eid] = dz;
}

/**
 * Gives the body a vortex force F = k r^(n-1) (axis x r_hat) about the axis through `centre`
 * (axis unit 3-vector, default z). @throws TypeError | RangeError on bad values a removed entity or one that is not a body.
 * @category Forces
 */
export function setVortex(
  world: PhysicsWorld,
  body: number,
  options: { centre: ArrayLike<number>; k: number; n?: number; axis?: ArrayLike<number> },
): void {
  const where = 'setVortex';
  const eid = optionsBody(world, body, where, options, ['centre', 'k', 'n', 'axis']);
  check.assertVector(where, 'centre', options.centre, world.dimensions);
  check.assertFinite(where, 'k', options.k);
  if (options.n !== undefined) check.assertFinite(where, 'n', options.n);
  const [ax, ay, az] = options.axis === undefined ? [0, 0, 1] : check.unitVector(where, 'axis', options.axis, 3);
  const c = world.components;
  addComponentIfMissing(world, eid, c.Vortex);
  const V = c.Vortex;
  writeVec3(world, options.centre, V.cx, V.cy, V.cz, eid);
  V.axisX[eid] = ax;
  V.axisY[eid] = ay;
  V.axisZ[eid] = az;
  V.k[eid] = options.k;
  V.n[eid] = options.n ?? 1;
}
