import type { KernelArray } from '../threads/kernel-types.js';
import { runParallel } from '../threads/parallel.js';
import { reportNonFinite } from '../world/errors.js';
import { fusedForcesOn } from '../world/fused-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import { idleWithout } from '../world/trusted-systems.js';
import { windAt } from './configure.js';
import { allocateStiffStamps, dissipationState, linearDecay, moveFromStart, quadraticDecay, STIFF_RATE } from './dissipation.js';
import type { ForceLaw } from './law.js';

const wind = new Float64Array(3);

/**
 * Whether the world's wind is still air everywhere (then drag uses the body's own velocity).
 * @category Forces
 */
export function calmAir(world: PhysicsWorld): boolean {
  const w = world.laws.wind;
  return (
    w.modes === 0 &&
    w.velocity[0] === 0 &&
    w.velocity[1] === 0 &&
    w.velocity[2] === 0 &&
    w.gust[0] === 0 &&
    w.gust[1] === 0 &&
    w.gust[2] === 0
  );
}

/**
 * Linear drag F = -k (v - u) on every body with `LinearDrag` (k in N s/m, >= 0), u the wind at the
 * body (setWind). Terminal velocity under gravity in still air: m g / k; v(t) = u + (v0 - u) e^(-k t / m)
 * without other forces. Source: Ramtal and Dobre ch. 7, "Drag"; Stokes' law.
 *
 * A force while k h / m < STIFF_RATE; at or above it this law adds nothing and `stiffDragSystem`
 * applies the exact decay v - u <- (v - u) exp(-k h / m) after the integrator, so the drag never
 * reverses or amplifies the velocity at any step size (see forces/dissipation.ts).
 *
 * In a substep that runs the fused force-and-integrate pass (integrators/fused-gate.ts) the integrator
 * applies this law to every body that has it, with the same arithmetic, and this system does nothing.
 * @category Forces
 */
export const linearDragSystem: ForceLaw = (world: PhysicsWorld): void => dragForces(world, false);

/**
 * Quadratic drag F = -k |v - u| (v - u) on every body with `QuadraticDrag` (k in kg/m, >= 0), u the
 * wind at the body. Terminal velocity under gravity in still air: sqrt(m g / k); without other forces
 * |v - u| falls as v0 / (1 + k v0 t / m). Source: Ramtal and Dobre ch. 7, "Drag"; the drag equation
 * F = rho C_d A v^2 / 2.
 *
 * A force while k |v - u| h / m < STIFF_RATE at the state it is evaluated at; otherwise it adds
 * nothing there and `stiffDragSystem` applies the exact update v - u <- (v - u) / (1 + k |v - u| h / m)
 * after the integrator (see forces/dissipation.ts). In a substep that runs the fused pass
 * (integrators/fused-gate.ts) the integrator applies it instead, with the same arithmetic.
 * @category Forces
 */
export const quadraticDragSystem: ForceLaw = (world: PhysicsWorld): void => dragForces(world, true);

/**
 * The force of linear drag (`quadratic` false: c = k) or quadratic drag (true: c = k |v - u|),
 * F = -c (v - u), on every body with the law's component, and the stiff bodies left to
 * `stiffDragSystem` (c / m >= STIFF_RATE / h): linear drag records that some body was stiff, quadratic
 * drag stamps each stiff body. In still air the kernel `velocityDamping` adds the forces, on the world's
 * threads when that pays. Does nothing in a substep that runs the fused pass.
 */
function dragForces(world: PhysicsWorld, quadratic: boolean): void {
  if (fusedForcesOn(world)) return;
  const { Velocity, Force, Position, Mass } = world.components;
  const Drag = quadratic ? world.components.QuadraticDrag : world.components.LinearDrag;
  const ents = query(world, [Drag, Velocity, Force]);
  if (ents.length === 0) return;
  const k = Drag.k,
    inv = Mass.inv,
    { x: vx, y: vy, z: vz } = Velocity;
  const { x: fx, y: fy, z: fz } = Force;
  // Stiff when c h / m >= STIFF_RATE, i.e. c / m >= limit.
  const limit = STIFF_RATE / world.h;
  let stiff = 0;
  if (calmAir(world)) {
    stiff = runParallel(
      world,
      quadratic ? 'quadraticDragSystem' : 'linearDragSystem',
      velocityDamping,
      [k, inv, vx, vy, vz, fx, fy, fz],
      [limit, quadratic ? 1 : 0, 1],
      ents.length,
      ents,
    );
    // The kernel adds the force of every body that is not stiff; the stiff quadratic ones are stamped here.
    if (quadratic && stiff > 0) {
      for (let i = 0; i < ents.length; i++) {
        const e = ents[i]!;
        const x = vx[e]!,
          y = vy[e]!,
          z = vz[e]!;
        if (k[e]! * Math.sqrt(x * x + y * y + z * z) * inv[e]! >= limit) markStiffQuadratic(world, e, k[e]!);
      }
    }
  } else {
    const t = world.time,
      { x: px, y: py, z: pz } = Position;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      // Linear drag's stiffness does not depend on the wind: such a body skips the wind.
      if (!quadratic && k[e]! * inv[e]! >= limit) {
        stiff++;
        continue;
      }
      windAt(world, px[e]!, py[e]!, pz[e]!, t, wind);
      const x = vx[e]! - wind[0]!,
        y = vy[e]! - wind[1]!,
        z = vz[e]! - wind[2]!;
      const c = quadratic ? k[e]! * Math.sqrt(x * x + y * y + z * z) : k[e]!;
      if (quadratic && c * inv[e]! >= limit) {
        markStiffQuadratic(world, e, k[e]!);
        continue;
      }
      fx[e] = fx[e]! - c * x;
      fy[e] = fy[e]! - c * y;
      fz[e] = fz[e]! - c * z;
    }
  }
  if (!quadratic && stiff > 0) {
    const s = dissipationState(world);
    s.linearSeen = s.epoch;
  }
}

/**
 * Stamps body e for the exact quadratic-drag update of this (sub)step (the cold path of the law; the fused pass calls it too).
 * @category Forces
 */
export function markStiffQuadratic(world: PhysicsWorld, e: number, k: number): void {
  const st = dissipationState(world);
  allocateStiffStamps(world, st);
  st.quadraticStamp[e] = st.epoch;
  st.quadraticK[e] = k;
  st.quadraticSeen = st.epoch;
}

/**
 * Integrate stage, after the integrator: the stiff regime of linear and quadratic drag (see
 * forces/dissipation.ts). For each dynamic body whose drag added no force this (sub)step, the
 * relative velocity v - u (u the wind at the body's new position, at the end of the (sub)step) is
 * multiplied by exp(-k h / m) (linear) and divided by 1 + k |v - u| h / m (quadratic), and the body is
 * moved from where the (sub)step began with the damped velocity: x = x_start + h v. Both factors lie
 * in [0, 1], so the velocity relative to the air is never reversed or amplified.
 * @throws NonFiniteStateError (stage 'integrate') if a position or velocity it writes is not finite.
 * @category Forces
 */
export const stiffDragSystem = (world: PhysicsWorld): void => {
  const st = dissipationState(world);
  const linear = st.linearSeen === st.epoch,
    quadratic = st.quadraticSeen === st.epoch;
  if (!linear && !quadratic) return;
  const c = world.components;
  const h = world.h,
    t = world.time + h;
  const calm = calmAir(world);
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity,
    inv = c.Mass.inv;
  const is2D = world.dimensions === 2;
  wind[0] = 0;
  wind[1] = 0;
  wind[2] = 0;
  // x * 0 is NaN exactly when x is not finite: the running check of what this system writes.
  let check = 0;
  const damp = (e: number, factor: number): void => {
    if (!calm) windAt(world, px[e]!, py[e]!, pz[e]!, t, wind);
    const ux = wind[0]!,
      uy = wind[1]!,
      uz = wind[2]!;
    check += moveFromStart(world, e, h, ux + (vx[e]! - ux) * factor, uy + (vy[e]! - uy) * factor, uz + (vz[e]! - uz) * factor);
  };
  if (linear) {
    const ents = query(world, [c.LinearDrag, c.Velocity, c.Force, Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)]);
    const k = c.LinearDrag.k;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const lambda = k[e]! * inv[e]! * h;
      if (lambda >= STIFF_RATE) damp(e, linearDecay(lambda));
    }
    if (check !== 0) reportNonFinite(world, ents, 'integrate');
  }
  if (quadratic) {
    const ents = query(world, [c.QuadraticDrag, c.Velocity, c.Force, Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)]);
    const epoch = st.epoch,
      stamp = st.quadraticStamp,
      stiffK = st.quadraticK;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      if (stamp[e] !== epoch) continue;
      if (!calm) windAt(world, px[e]!, py[e]!, pz[e]!, t, wind);
      const x = vx[e]! - wind[0]!,
        y = vy[e]! - wind[1]!,
        z = is2D ? 0 : vz[e]! - wind[2]!;
      damp(e, quadraticDecay(stiffK[e]! * Math.sqrt(x * x + y * y + z * z) * inv[e]! * h));
    }
    if (check !== 0) reportNonFinite(world, ents, 'integrate');
  }
};

/**
 * Lift F = k |v_rel| (axis x v_rel), perpendicular to the velocity relative to the wind; in 2D with
 * the default axis z it points 90 degrees to the left of the motion. Source: Ramtal and Dobre ch. 7.
 * @category Forces
 */
export const liftSystem: ForceLaw = (world: PhysicsWorld): void => {
  const { Lift, Velocity, Force, Position } = world.components;
  const ents = query(world, [Lift, Velocity, Force]);
  if (ents.length === 0) return;
  const calm = calmAir(world);
  const t = world.time,
    { x: px, y: py, z: pz } = Position;
  const { x: vx, y: vy, z: vz } = Velocity,
    { x: fx, y: fy, z: fz } = Force;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    let x = vx[e]!,
      y = vy[e]!,
      z = vz[e]!;
    if (!calm) {
      windAt(world, px[e]!, py[e]!, pz[e]!, t, wind);
      x -= wind[0]!;
      y -= wind[1]!;
      z -= wind[2]!;
    }
    const k = Lift.k[e]! * Math.sqrt(x * x + y * y + z * z);
    const ax = Lift.axisX[e]!,
      ay = Lift.axisY[e]!,
      az = Lift.axisZ[e]!;
    fx[e] = fx[e]! + k * (ay * z - az * y);
    fy[e] = fy[e]! + k * (az * x - ax * z);
    fz[e] = fz[e]! + k * (ax * y - ay * x);
  }
};

/**
 * Damping proportional to a velocity, the one kernel of drag in still air (forces/drag.ts: F -= c v,
 * inv = 1 / m, scale 1, limit STIFF_RATE / h) and of 2D angular damping (forces/angular-damping.ts:
 * tau -= k w, inv = 1 / I, scale h, limit STIFF_RATE): c = k (linear, P[1] = 0) or c = k |v|
 * (quadratic, P[1] = 1); the body is stiff when c inv scale >= limit (then no force here: it is left
 * to the exact update, quadratic bodies stamped by the caller). A: k, inv, vx, vy, vz, fx, fy, fz.
 * P: limit, quadratic, scale. Returns the count of stiff bodies.
 */
export function velocityDamping(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const k = A[0] as Float64Array,
    inv = A[1] as Float64Array;
  const vx = A[2] as Float64Array,
    vy = A[3] as Float64Array,
    vz = A[4] as Float64Array;
  const fx = A[5] as Float64Array,
    fy = A[6] as Float64Array,
    fz = A[7] as Float64Array;
  const limit = P[0]!,
    quadratic = P[1] === 1,
    scale = P[2]!;
  const list = ids as Int32Array;
  let stiff = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const x = vx[e]!,
      y = vy[e]!,
      z = vz[e]!;
    const c = quadratic ? k[e]! * Math.sqrt(x * x + y * y + z * z) : k[e]!;
    if (c * inv[e]! * scale >= limit) {
      stiff++;
      continue;
    }
    fx[e] = fx[e]! - c * x;
    fy[e] = fy[e]! - c * y;
    fz[e] = fz[e]! - c * z;
  }
  return stiff;
}

// What makes each system of this module idle (world/trusted-systems.ts idleWithout): its first query.
idleWithout(linearDragSystem, (w) => [[w.components.LinearDrag, w.components.Velocity, w.components.Force]]);
idleWithout(quadraticDragSystem, (w) => [[w.components.QuadraticDrag, w.components.Velocity, w.components.Force]]);
idleWithout(liftSystem, (w) => [[w.components.Lift, w.components.Velocity, w.components.Force]]);
