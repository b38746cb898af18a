import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import type { ForceLaw } from './law.js';

/**
 * Rocket thrust: while fuel lasts, F = ve mdot (m_s / m(t)) d, with d the thrust direction, ve the
 * exhaust velocity, mdot the mass flow rate, m_s the mass at the start of the (sub)step (what the
 * integrator divides by) and m(t) = m_s - mdot (t - t_s) the mass at the evaluation time t. The
 * acceleration F / m_s is then exactly ve mdot / m(t), the rocket equation m dv/dt = ve mdot, at
 * every stage of every integrator, so integrating it reproduces Tsiolkovsky's dv = ve ln(m0 / m1)
 * to the scheme's order. Thrust stops when the fuel burnt since t_s exceeds the fuel left.
 * Position-only (a function of time). Source: Ramtal and Dobre ch. 6, "rockets".
 * @category Forces
 */
export const thrustSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const ents = query(world, [c.Thrust, c.Force, c.Mass]);
  if (ents.length === 0) return;
  const T = c.Thrust,
    m = c.Mass.value;
  const elapsed = world.time - world.substepStart;
  const { x: fx, y: fy, z: fz } = c.Force;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const mdot = T.massFlowRate[e]!;
    const burnt = mdot * elapsed;
    // Burns until the fuel is gone; the relative slack keeps the thrust on at the very end of the step
    // in which the fuel runs out exactly (where rounding makes burnt and fuel differ by 1e-16).
    const fuel = T.fuel[e]!;
    if (mdot <= 0 || fuel <= 0 || burnt > fuel * (1 + 1e-9)) continue;
    const ms = m[e]!;
    const f = (T.exhaustVelocity[e]! * mdot * ms) / (ms - burnt);
    fx[e] = fx[e]! + f * T.dirX[e]!;
    fy[e] = fy[e]! + f * T.dirY[e]!;
    fz[e] = fz[e]! + f * T.dirZ[e]!;
  }
};
thrustSystem.velocityDependent = false;

/**
 * Burns fuel after each integration: the mass drops by mdot h (at most the fuel left), the fuel with
 * it, and the inverse mass is recomputed, so mass and inverse mass stay consistent. Runs in the
 * integrate stage right after the scheme.
 * @category Forces
 */
export function burnFuelSystem(world: PhysicsWorld): void {
  const c = world.components;
  const ents = query(world, [c.Thrust, c.Mass]);
  if (ents.length === 0) return;
  const T = c.Thrust,
    M = c.Mass;
  const h = world.h;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const full = T.massFlowRate[e]! * h;
    let burn = Math.min(full, T.fuel[e]!);
    if (!(burn > 0)) continue;
    // Fuel and mass are decremented separately, so rounding can leave a residue of ~1e-12 kg of fuel
    // after the last full burn; burning it as a step of its own would fire the engine at full thrust
    // for part of a step. A residue below a millionth of a step's burn is burnt now.
    if (T.fuel[e]! - burn < 1e-6 * full) burn = T.fuel[e]!;
    const mass = M.value[e]! - burn;
    T.fuel[e] = T.fuel[e]! - burn;
    M.value[e] = mass;
    M.inv[e] = 1 / mass;
  }
}

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(thrustSystem, (w) => [[w.components.Thrust, w.components.Force, w.components.Mass]]);
idleWithout(burnFuelSystem, (w) => [[w.components.Thrust, w.components.Mass]]);
