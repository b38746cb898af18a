import { addComponent, entityExists, hasComponent, removeEntity } from 'bitecs';
import * as check from '../validation/validate.js';
import { createSlot, currentHandle, resolveEntity, resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';
import { addComponentIfMissing } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';

/**
 * Lifting surfaces of a rigid 3D body: wings, tailplanes, fins and their control surfaces (ailerons,
 * elevator, rudder), the aerodynamics of the book's flight simulator (Ramtal and Dobre ch. 16) with
 * the angle of attack and the stall it leaves out. Each surface is its own entity holding its body,
 * so an aircraft is a body plus a handful of surfaces, each acting at its own point.
 *
 * At the surface's point p = x + R o (o its body-frame offset) the air moves at v_p = v + w x (R o)
 * relative to the surface (still air), so a turning body meets its own motion as extra angle of
 * attack: the roll, pitch and yaw damping of a real aircraft come from here, not from a damping term.
 * With the normal n = R n_body, the chord c = the body's x axis made perpendicular to n (so a surface
 * set at an incidence meets air along the body x axis at that angle) and the span s = c x n:
 *   angle of attack   alpha = atan2(-v_p . n, v_p . c)  (in the plane of chord and normal),
 *   lift coefficient  C_L = a alpha + k delta            for |alpha| <= alpha_stall (thin-aerofoil slope a),
 *                     C_L = sin(2 alpha) + k delta        past the stall (flat plate, C_N = 2 sin alpha),
 *   drag coefficient  C_D = C_D0 + K C_L^2               attached (parabolic polar),
 *                     C_D = C_D0 + 2 sin^2(alpha)         past the stall (flat plate),
 *   lift  L = q A C_L (s x v_p) / |s x v_p|,  drag  D = -q A C_D v_perp / |v_perp|,
 * with v_perp the part of v_p across the span and q = rho |v_perp|^2 / 2 its dynamic pressure; the
 * force L + D acts at p (torque (R o) x (L + D)). Sources: Anderson, Fundamentals of Aerodynamics
 * (lift slope, drag polar); Hoerner, Fluid-Dynamic Drag and Fluid-Dynamic Lift (flat plate past the
 * stall); Stevens and Lewis, Aircraft Control and Simulation (surfaces at points, damping).
 */

/**
 * Options of `addLiftingSurface`. Vectors are body-frame 3-vectors. Unknown fields are rejected.
 * @category Forces
 */
export interface LiftingSurfaceOptions {
  /** The body (entity id) the surface belongs to: a dynamic 3D body. */
  body: number;
  /** Where the force acts, m, body frame (x forward, y up, z right). Default the centre of mass. */
  offset?: ArrayLike<number>;
  /** Surface normal, body frame, normalised here; must not be along x (the chord). Default (0, 1, 0): a wing. */
  normal?: ArrayLike<number>;
  /** Planform area, m^2, > 0. */
  area: number;
  /** Lift slope a = dC_L/d(alpha), 1/rad, >= 0. Default 2 pi / (1 + 2 / 6): a wing of aspect ratio 6 (Anderson's finite-wing slope). */
  liftSlope?: number;
  /** Stall angle, rad, in (0, pi/2). Default 20 degrees. */
  stallAngle?: number;
  /** Zero-lift drag coefficient C_D0, >= 0. Default 0.02. */
  dragZero?: number;
  /** Induced drag factor K = 1 / (pi e AR), >= 0. Default 0.06. */
  inducedDrag?: number;
  /** Lift coefficient per radian of control deflection, >= 0. Default 0 (no control surface). */
  controlPower?: number;
  /** Air density, kg/m^3, > 0. Default 1.225 (sea level, ISA). */
  airDensity?: number;
}

const KNOWN = ['body', 'offset', 'normal', 'area', 'liftSlope', 'stallAngle', 'dragZero', 'inducedDrag', 'controlPower', 'airDensity'];

/**
 * Default lift slope: 2 pi / (1 + 2 / AR) at aspect ratio 6, 1/rad.
 * @category Forces
 */
export const DEFAULT_LIFT_SLOPE = (2 * Math.PI) / (1 + 2 / 6);

/**
 * Adds a lifting surface to a dynamic 3D body that turns (it needs an inertia: `setInertia`).
 * @returns the surface's handle (removing the body removes its surfaces).
 * @throws TypeError on unknown options or malformed vectors; RangeError on a 2D world, a missing,
 *   static or non-rotating body, a zero normal or one along the chord, or values out of range.
 * @category Forces
 */
export function addLiftingSurface(world: PhysicsWorld, options: LiftingSurfaceOptions): number {
  const where = 'addLiftingSurface';
  if (world.dimensions !== 3) throw new RangeError(`${where}: lifting surfaces need a 3D world, got dimensions ${world.dimensions}`);
  check.assertOptions(where, options, KNOWN);
  const c = world.components;
  const b = resolveKind(world, options.body, 'body', where, 'body');
  if (hasComponent(world, b, c.Static) || hasComponent(world, b, c.Kinematic) || !hasComponent(world, b, c.AngularVelocity)) {
    throw new RangeError(`${where}: body ${options.body} must be dynamic and turn (give it an inertia with setInertia)`);
  }
  const offset = options.offset ?? [0, 0, 0];
  check.assertVector(where, 'offset', offset, 3);
  const normal = options.normal ?? [0, 1, 0];
  const unit = check.unitVector(where, 'normal', normal, 3);
  if (Math.hypot(unit[1], unit[2]) < 1e-6)
    throw new RangeError(`${where}: normal must not lie along the chord (body x), got ${check.describe(normal)}`);
  check.assertPositive(where, 'area', options.area);
  const slope = check.optionOr(where, 'liftSlope', options.liftSlope, DEFAULT_LIFT_SLOPE, check.assertNonNegative);
  const stall = options.stallAngle ?? (20 * Math.PI) / 180;
  check.assertInRange(where, 'stallAngle', stall, 1e-6, Math.PI / 2 - 1e-6);
  const cd0 = check.optionOr(where, 'dragZero', options.dragZero, 0.02, check.assertNonNegative);
  const k = check.optionOr(where, 'inducedDrag', options.inducedDrag, 0.06, check.assertNonNegative);
  const power = check.optionOr(where, 'controlPower', options.controlPower, 0, check.assertNonNegative);
  const rho = check.optionOr(where, 'airDensity', options.airDensity, 1.225, check.assertPositive);
  addComponentIfMissing(world, b, c.Force);
  addComponentIfMissing(world, b, c.Torque);
  if (!world.removeHooks.includes(removeSurfacesOf)) world.removeHooks.push(removeSurfacesOf);
  const s = createSlot(world, where);
  addComponent(world, s, c.LiftingSurface);
  const L = c.LiftingSurface;
  L.body[s] = b;
  L.offsetX[s] = offset[0]!;
  L.offsetY[s] = offset[1]!;
  L.offsetZ[s] = offset[2]!;
  L.normalX[s] = unit[0];
  L.normalY[s] = unit[1];
  L.normalZ[s] = unit[2];
  L.area[s] = options.area;
  L.liftSlope[s] = slope;
  L.stallAngle[s] = stall;
  L.dragZero[s] = cd0;
  L.inducedDrag[s] = k;
  L.controlPower[s] = power;
  L.deflection[s] = 0;
  L.airDensity[s] = rho;
  return currentHandle(world, s);
}

/**
 * Removal hook: removes the lifting surfaces of a removed body, so none acts on a recycled id.
 * @category Forces
 */
export function removeSurfacesOf(world: PhysicsWorld, eid: number): void {
  const L = world.components.LiftingSurface;
  const surfaces = query(world, [L]);
  const doomed: number[] = [];
  for (let i = 0; i < surfaces.length; i++) if (L.body[surfaces[i]!] === eid) doomed.push(surfaces[i]!);
  for (const s of doomed) removeEntity(world, s);
}

/**
 * Sets a surface's control deflection, rad, in [-pi/4, pi/4] (positive: more lift along its normal,
 * a trailing edge turned down). @throws RangeError on an entity that is not a lifting surface or a
 * deflection out of range.
 * @category Forces
 */
export function setControlDeflection(world: PhysicsWorld, surface: number, deflection: number): void {
  const where = 'setControlDeflection';
  const L = world.components.LiftingSurface;
  const slot = resolveEntity(world, surface, where, 'surface');
  if (!hasComponent(world, slot, L))
    throw new RangeError(`${where}: surface must be a lifting surface (addLiftingSurface makes one), got entity ${surface}`);
  check.assertFinite(where, 'deflection', deflection);
  check.assertInRange(where, 'deflection', deflection, -Math.PI / 4, Math.PI / 4);
  L.deflection[slot] = deflection;
}

/**
 * The lift coefficient of a surface at angle of attack `alpha` (rad) and control term `control`
 * (k delta): a alpha + control while |alpha| <= stall, sin(2 alpha) + control past it (see the header).
 * @category Forces
 */
export function liftCoefficient(alpha: number, slope: number, stall: number, control: number): number {
  return (alpha <= stall && alpha >= -stall ? slope * alpha : Math.sin(2 * alpha)) + control;
}

/**
 * The drag coefficient at `alpha` with lift coefficient `cl`: C_D0 + K C_L^2 attached, C_D0 + 2 sin^2(alpha) stalled.
 * @category Forces
 */
export function dragCoefficient(alpha: number, cl: number, stall: number, cd0: number, k: number): number {
  if (alpha <= stall && alpha >= -stall) return cd0 + k * cl * cl;
  const s = Math.sin(alpha);
  return cd0 + 2 * s * s;
}

const rot = new Float64Array(9);

/**
 * Stage 3 law: the lift and drag of every lifting surface, at its point, on its body (header formulas).
 * Surfaces whose body was removed are skipped. Velocity-dependent.
 * @category Forces
 */
export const liftingSurfaceSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.LiftingSurface]);
  if (ents.length === 0) return;
  const L = c.LiftingSurface,
    O = c.Orientation,
    P = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: wx, y: wy, z: wz } = c.AngularVelocity;
  const { x: fx, y: fy, z: fz } = c.Force,
    { x: tx, y: ty, z: tz } = c.Torque;
  for (let i = 0; i < ents.length; i++) {
    const s = ents[i]!;
    const b = L.body[s]!;
    if (!entityExists(world, b) || !hasComponent(world, b, P) || !hasComponent(world, b, c.Torque)) continue;
    // Rotation matrix of the body (columns: body x, y, z in world axes).
    const qx = O.x[b]!,
      qy = O.y[b]!,
      qz = O.z[b]!,
      qw = O.w[b]!;
    rot[0] = 1 - 2 * (qy * qy + qz * qz);
    rot[1] = 2 * (qx * qy + qz * qw);
    rot[2] = 2 * (qx * qz - qy * qw);
    rot[3] = 2 * (qx * qy - qz * qw);
    rot[4] = 1 - 2 * (qx * qx + qz * qz);
    rot[5] = 2 * (qy * qz + qx * qw);
    rot[6] = 2 * (qx * qz + qy * qw);
    rot[7] = 2 * (qy * qz - qx * qw);
    rot[8] = 1 - 2 * (qx * qx + qy * qy);
    const ox = L.offsetX[s]!,
      oy = L.offsetY[s]!,
      oz = L.offsetZ[s]!;
    const rx = rot[0]! * ox + rot[3]! * oy + rot[6]! * oz,
      ry = rot[1]! * ox + rot[4]! * oy + rot[7]! * oz,
      rz = rot[2]! * ox + rot[5]! * oy + rot[8]! * oz;
    const bnx = L.normalX[s]!,
      bny = L.normalY[s]!,
      bnz = L.normalZ[s]!;
    const nx = rot[0]! * bnx + rot[3]! * bny + rot[6]! * bnz,
      ny = rot[1]! * bnx + rot[4]! * bny + rot[7]! * bnz,
      nz = rot[2]! * bnx + rot[5]! * bny + rot[8]! * bnz;
    // Chord: the body's x axis made perpendicular to the normal (a surface set at an incidence).
    const bx = rot[0]!,
      by = rot[1]!,
      bz = rot[2]!,
      bn = bx * nx + by * ny + bz * nz;
    let cx = bx - bn * nx,
      cy = by - bn * ny,
      cz = bz - bn * nz;
    const cl0 = Math.sqrt(cx * cx + cy * cy + cz * cz);
    cx /= cl0;
    cy /= cl0;
    cz /= cl0;
    // Span s = c x n (unit: c and n are perpendicular unit vectors).
    const sx = cy * nz - cz * ny,
      sy = cz * nx - cx * nz,
      sz = cx * ny - cy * nx;
    // Air velocity over the surface: v + w x r (still air).
    const ax = vx[b]! + (wy[b]! * rz - wz[b]! * ry),
      ay = vy[b]! + (wz[b]! * rx - wx[b]! * rz),
      az = vz[b]! + (wx[b]! * ry - wy[b]! * rx);
    const along = ax * sx + ay * sy + az * sz;
    const px = ax - along * sx,
      py = ay - along * sy,
      pz = az - along * sz;
    const v2 = px * px + py * py + pz * pz;
    if (!(v2 > 1e-12)) continue;
    const v = Math.sqrt(v2);
    const alpha = Math.atan2(-(px * nx + py * ny + pz * nz), px * cx + py * cy + pz * cz);
    const stall = L.stallAngle[s]!;
    const cl = liftCoefficient(alpha, L.liftSlope[s]!, stall, L.controlPower[s]! * L.deflection[s]!);
    const cd = dragCoefficient(alpha, cl, stall, L.dragZero[s]!, L.inducedDrag[s]!);
    const qa = 0.5 * L.airDensity[s]! * v2 * L.area[s]!;
    // Lift along s x v_perp / |v_perp| (unit: s is perpendicular to v_perp); drag along -v_perp / |v_perp|.
    const kl = (qa * cl) / v,
      kd = (qa * cd) / v;
    const Fx = kl * (sy * pz - sz * py) - kd * px;
    const Fy = kl * (sz * px - sx * pz) - kd * py;
    const Fz = kl * (sx * py - sy * px) - kd * pz;
    fx[b] = fx[b]! + Fx;
    fy[b] = fy[b]! + Fy;
    fz[b] = fz[b]! + Fz;
    tx[b] = tx[b]! + (ry * Fz - rz * Fy);
    ty[b] = ty[b]! + (rz * Fx - rx * Fz);
    tz[b] = tz[b]! + (rx * Fy - ry * Fx);
  }
};

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(liftingSurfaceSystem, (w) => [[w.components.LiftingSurface]]);
