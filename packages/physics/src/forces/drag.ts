import { query } from '../query.js';
import type { PhysicsWorld } from '../world.js';
import type { ForceLaw } from './law.js';
import { windAt } from './settings.js';

const wind = new Float64Array(3);

/** Whether the world's wind is still air everywhere (then drag uses the body's own velocity). */
export function calmAir(world: PhysicsWorld): boolean {
  const w = world.laws.wind;
  return w.modes === 0 && w.velocity[0] === 0 && w.velocity[1] === 0 && w.velocity[2] === 0 &&
    w.gust[0] === 0 && w.gust[1] === 0 && w.gust[2] === 0;
}

/**
 * Linear drag F = -k (v - u) on every body with `LinearDrag`, u the wind at the body (setWind).
 * Source: Ramtal and Dobre ch. 7, "Drag"; Stokes' law.
 */
export const linearDragSystem: ForceLaw = (world: PhysicsWorld): void => {
  const { LinearDrag, Velocity, Force, Position } = world.components;
  const ents = query(world, [LinearDrag, Velocity, Force]);
  if (ents.length === 0) return;
  const k = LinearDrag.k, vx = Velocity.x, vy = Velocity.y, vz = Velocity.z;
  const fx = Force.x, fy = Force.y, fz = Force.z;
  if (calmAir(world)) {
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const c = k[e]!;
      fx[e] = fx[e]! - c * vx[e]!; fy[e] = fy[e]! - c * vy[e]!; fz[e] = fz[e]! - c * vz[e]!;
    }
    return;
  }
  const t = world.time, px = Position.x, py = Position.y, pz = Position.z;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    windAt(world, px[e]!, py[e]!, pz[e]!, t, wind);
    const c = k[e]!;
    fx[e] = fx[e]! - c * (vx[e]! - wind[0]!); fy[e] = fy[e]! - c * (vy[e]! - wind[1]!); fz[e] = fz[e]! - c * (vz[e]! - wind[2]!);
  }
};

/**
 * Quadratic drag F = -k |v - u| (v - u) on every body with `QuadraticDrag`, u the wind at the body.
 * Terminal velocity in still air under gravity: sqrt(m g / k).
 * Source: Ramtal and Dobre ch. 7, "Drag"; the drag equation F = rho C_d A v^2 / 2.
 */
export const quadraticDragSystem: ForceLaw = (world: PhysicsWorld): void => {
  const { QuadraticDrag, Velocity, Force, Position } = world.components;
  const ents = query(world, [QuadraticDrag, Velocity, Force]);
  if (ents.length === 0) return;
  const k = QuadraticDrag.k, vx = Velocity.x, vy = Velocity.y, vz = Velocity.z;
  const fx = Force.x, fy = Force.y, fz = Force.z;
  const calm = calmAir(world);
  const t = world.time, px = Position.x, py = Position.y, pz = Position.z;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    let x = vx[e]!, y = vy[e]!, z = vz[e]!;
    if (!calm) { windAt(world, px[e]!, py[e]!, pz[e]!, t, wind); x -= wind[0]!; y -= wind[1]!; z -= wind[2]!; }
    const c = k[e]! * Math.sqrt(x * x + y * y + z * z);
    fx[e] = fx[e]! - c * x; fy[e] = fy[e]! - c * y; fz[e] = fz[e]! - c * z;
  }
};

/**
 * Lift F = k |v_rel| (axis x v_rel), perpendicular to the velocity relative to the wind; in 2D with
 * the default axis z it points 90 degrees to the left of the motion. Source: Ramtal and Dobre ch. 7.
 */
export const liftSystem: ForceLaw = (world: PhysicsWorld): void => {
  const { Lift, Velocity, Force, Position } = world.components;
  const ents = query(world, [Lift, Velocity, Force]);
  if (ents.length === 0) return;
  const calm = calmAir(world);
  const t = world.time, px = Position.x, py = Position.y, pz = Position.z;
  const vx = Velocity.x, vy = Velocity.y, vz = Velocity.z, fx = Force.x, fy = Force.y, fz = Force.z;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    let x = vx[e]!, y = vy[e]!, z = vz[e]!;
    if (!calm) { windAt(world, px[e]!, py[e]!, pz[e]!, t, wind); x -= wind[0]!; y -= wind[1]!; z -= wind[2]!; }
    const k = Lift.k[e]! * Math.sqrt(x * x + y * y + z * z);
    const ax = Lift.axisX[e]!, ay = Lift.axisY[e]!, az = Lift.axisZ[e]!;
    fx[e] = fx[e]! + k * (ay * z - az * y);
    fy[e] = fy[e]! + k * (az * x - ax * z);
    fz[e] = fz[e]! + k * (ax * y - ay * x);
  }
};
