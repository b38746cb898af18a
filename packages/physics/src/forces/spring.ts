import { hasComponent, removeEntity } from 'bitecs';
import { reportNonFinite } from '../world/errors.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import { dissipationState, linearDecay, moveFromStart, STIFF_RATE } from './dissipation.js';
import type { ForceLaw } from './law.js';

/**
 * Hooke springs with damping (Ramtal and Dobre ch. 8): for a spring from a (or its anchor) to b with
 * length L and unit direction u from a to b, the force on b is
 * F = -(stiffness (L - restLength) + damping (v_b - v_a) . u) u, and -F on a. A one-sided spring
 * (bungee) exerts nothing while L <= restLength. Velocity-dependent (the damping).
 *
 * The damping is a force while damping h (1/m_a + 1/m_b) < STIFF_RATE; at or above it the spring
 * leaves it out and `stiffSpringDampingSystem` damps the pair's relative velocity along the spring
 * exactly after the integrator, so it never reverses or amplifies it (see forces/dissipation.ts).
 * @category Forces
 */
export const springSystem: ForceLaw = (world: PhysicsWorld): void => {
  const c = world.components;
  const springs = query(world, [c.Spring]);
  if (springs.length === 0) return;
  const S = c.Spring;
  const inv = c.Mass.inv;
  const limit = STIFF_RATE / world.h;
  let stiff = 0;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: fx, y: fy, z: fz } = c.Force;
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    const a = S.a[s]!,
      b = S.b[s]!;
    const ax = a === 0 ? S.anchorX[s]! : px[a]!,
      ay = a === 0 ? S.anchorY[s]! : py[a]!,
      az = a === 0 ? S.anchorZ[s]! : pz[a]!;
    const dx = px[b]! - ax,
      dy = py[b]! - ay,
      dz = pz[b]! - az;
    const L = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (L === 0) continue;
    const stretch = L - S.restLength[s]!;
    if (S.oneSided[s] === 1 && stretch <= 0) continue;
    const ux = dx / L,
      uy = dy / L,
      uz = dz / L;
    const rv = a === 0 ? vx[b]! * ux + vy[b]! * uy + vz[b]! * uz : (vx[b]! - vx[a]!) * ux + (vy[b]! - vy[a]!) * uy + (vz[b]! - vz[a]!) * uz;
    let damping = S.damping[s]!;
    if (damping * (inv[b]! + (a === 0 ? 0 : inv[a]!)) >= limit) {
      damping = 0;
      stiff++;
    }
    const mag = -(S.stiffness[s]! * stretch + damping * rv);
    const Fx = mag * ux,
      Fy = mag * uy,
      Fz = mag * uz;
    fx[b] = fx[b]! + Fx;
    fy[b] = fy[b]! + Fy;
    fz[b] = fz[b]! + Fz;
    if (a !== 0) {
      fx[a] = fx[a]! - Fx;
      fy[a] = fy[a]! - Fy;
      fz[a] = fz[a]! - Fz;
    }
  }
  if (stiff > 0) {
    const st = dissipationState(world);
    st.springSeen = st.epoch;
  }
};

/** Inverse mass of body e as the stiff update may move it: 0 if static, kinematic or asleep (the integrator left it). */
function movableInverse(world: PhysicsWorld, e: number): number {
  const c = world.components;
  if (e === 0 || hasComponent(world, e, c.Static) || hasComponent(world, e, c.Kinematic) || hasComponent(world, e, c.Sleeping)) return 0;
  return c.Mass.inv[e]!;
}

/**
 * Integrate stage, after the integrator: the stiff regime of spring damping (see
 * forces/dissipation.ts). For each spring whose damping added no force this (sub)step, the relative
 * velocity along the spring's direction u at the end of the step, w = (v_b - v_a) . u, becomes
 * w exp(-c h (1/m_a + 1/m_b)) (the exact solution of the pair under its damping alone) by equal and
 * opposite impulses along u; a static, kinematic or sleeping end does not move (its inverse mass
 * counts as 0). Springs are taken one after another; each only lowers its pair's relative speed and
 * keeps momentum, so the kinetic energy never grows. Moved bodies go from where the (sub)step began
 * with their new velocity: x = x_start + h v.
 * @throws NonFiniteStateError (stage 'integrate') if a position or velocity it writes is not finite.
 * @category Forces
 */
export const stiffSpringDampingSystem = (world: PhysicsWorld): void => {
  const st = dissipationState(world);
  if (st.springSeen !== st.epoch) return;
  const c = world.components;
  const springs = query(world, [c.Spring]);
  const S = c.Spring,
    inv = c.Mass.inv,
    h = world.h;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const is2D = world.dimensions === 2;
  let check = 0;
  const move = (e: number, j: number, ux: number, uy: number, uz: number): void => {
    check += moveFromStart(world, e, h, vx[e]! + j * ux, vy[e]! + j * uy, vz[e]! + j * uz);
  };
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    const a = S.a[s]!,
      b = S.b[s]!,
      cd = S.damping[s]!;
    if (cd * (inv[b]! + (a === 0 ? 0 : inv[a]!)) * h < STIFF_RATE) continue;
    const ax = a === 0 ? S.anchorX[s]! : px[a]!,
      ay = a === 0 ? S.anchorY[s]! : py[a]!,
      az = a === 0 ? S.anchorZ[s]! : pz[a]!;
    const dx = px[b]! - ax,
      dy = py[b]! - ay,
      dz = is2D ? 0 : pz[b]! - az;
    const L = Math.sqrt(dx * dx + dy * dy + dz * dz);
    if (L === 0) continue;
    if (S.oneSided[s] === 1 && L <= S.restLength[s]!) continue;
    const ux = dx / L,
      uy = dy / L,
      uz = dz / L;
    const ib = movableInverse(world, b),
      ia = movableInverse(world, a),
      w = ia + ib;
    if (w === 0) continue;
    const rv = a === 0 ? vx[b]! * ux + vy[b]! * uy + vz[b]! * uz : (vx[b]! - vx[a]!) * ux + (vy[b]! - vy[a]!) * uy + (vz[b]! - vz[a]!) * uz;
    // Impulse per unit inverse mass that takes rv to rv exp(-c h w).
    const j = (rv * linearDecay(cd * h * w) - rv) / w;
    if (ib > 0) move(b, j * ib, ux, uy, uz);
    if (ia > 0) move(a, -j * ia, ux, uy, uz);
  }
  if (check !== 0) {
    const touched: number[] = [];
    for (let i = 0; i < springs.length; i++) {
      const s = springs[i]!;
      touched.push(S.b[s]!);
      if (S.a[s]! !== 0) touched.push(S.a[s]!);
    }
    reportNonFinite(world, touched, 'integrate');
  }
};

/**
 * Removal hook: removes every spring attached to `eid` (so no spring ever pulls a recycled id).
 * @category Forces
 */
export function removeSpringsOf(world: PhysicsWorld, eid: number): void {
  const c = world.components;
  // Most removals (particle churn) meet no spring: return before allocating (the store is allocated with the first spring).
  if (c.Spring.a.length === 0) return;
  const springs = query(world, [c.Spring]);
  if (springs.length === 0) return;
  const doomed: number[] = [];
  for (let i = 0; i < springs.length; i++) {
    const s = springs[i]!;
    if (c.Spring.a[s] === eid || c.Spring.b[s] === eid) doomed.push(s);
  }
  for (const s of doomed) removeEntity(world, s);
}

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(springSystem, (w) => [[w.components.Spring]]);
