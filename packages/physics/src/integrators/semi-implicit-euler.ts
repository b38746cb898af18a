import { dissipationState, STIFF_RATE } from '../forces/dissipation.js';
import { markStiffQuadratic } from '../forces/drag.js';
import type { KernelArray } from '../threads/kernel-types.js';
import { runParallel } from '../threads/parallel.js';
import { reportNonFinite, throwNonFinite } from '../world/errors.js';
import { fusedForcesOn, setFusedForces } from '../world/fused-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { forcedBodies, freeBodies, fusedBareBodies, fusedLinearBodies, fusedQuadraticBodies, kinematicBodies } from './queries.js';
import { advanceOrientations, applyTorques } from './rotation.js';
import * as SIE from './slots/semi-implicit-euler.js';

/** The name a worker's error gives the integrator. */
const INTEGRATE = 'integrate (semi-implicit Euler)';

/** The kernels' arguments (the SIE slots), filled by each call of semiImplicitEuler. Not state. */
const sieArrays: KernelArray[] = [];
const sieParams = new Float64Array(SIE.PARAMS);

/**
 * Semi-implicit (symplectic) Euler: v(t+h) = v(t) + a(t) h, then x(t+h) = x(t) + v(t+h) h, with
 * a = F / m + g for bodies with a force accumulator and a = g for free particles. The world's
 * constant gravity is integrated exactly for a body in free flight: a body no force acted on this step
 * (no force accumulator, or one that is exactly zero) moves x(t+h) = x(t) + (v(t+h) - g h / 2) h,
 * i.e. the exact parabola x += v h + g h^2 / 2, v += g h. Without that, every step would lag the
 * parabola by g h^2 / 2 and a bouncing ball would lose height every flight. A body with any force
 * (buoyancy, a spring, drag, thrust) keeps the plain x(t+h) = x(t) + v(t+h) h. The trade-off: a
 * force-balanced body (buoyancy = weight, a spring at its hanging equilibrium) must read v = 0 and not
 * move, which the -g h / 2 correction would break (it would drift g h^2 / 2 a step, 2.45 m in 30 s at
 * dt 1/60); applying the correction with the whole acceleration a = F / m + g instead would keep the
 * balance but is not symplectic (an undamped spring would gain energy by 1 + (omega h)^2 / 2 a step).
 * So a body under other forces loses the exact parabola (its flight lags g h^2 / 2 a step, the plain
 * scheme's first-order error); a body in pure free flight gets it. The contact solver (solver.ts)
 * applies the same rule to the bodies it moves.
 * First order; symplectic, so the energy error of a conservative system stays bounded instead of drifting.
 * Source: Ramtal and Dobre ch. 14 ("Euler-Cromer"); Hairer, Lubich and Wanner, Geometric Numerical
 * Integration (2006), ch. I.1 and II.5 (splitting).
 *
 * Saves each body's position into `PreviousPosition` first. Throws NonFiniteStateError if a body's
 * new velocity or position is NaN or infinite (x * 0 is NaN exactly then, so the positions join the
 * running check without overflowing it).
 *
 * The two body loops are kernels (`sie2` and `sie3`, each for forced bodies or bare particles), run
 * inline or split over the world's threads when that pays: each body's arithmetic is the same either
 * way, so the state is identical to the bit on any thread count.
 *
 * In a substep that runs the fused force-and-integrate pass (integrators/fused-gate.ts says when), the
 * forced bodies' forces are written here, in the same pass that moves them (`fusedForced2`), and a
 * NaN or infinite force is reported (stage 'forces') before its body is moved: no body's position or
 * velocity is made non-finite by it, but the bodies the pass moved before it stay moved.
 * @category Integrators
 */
export function semiImplicitEuler(world: PhysicsWorld, h: number): void {
  const c = world.components;
  const g = world.gravity;
  const gxh = g[0]! * h,
    gyh = g[1]! * h,
    gzh = g[2]! * h;
  const is2D = world.dimensions === 2;
  const A = sieArrays,
    P = sieParams;
  A.length = 0;
  A[SIE.PX] = c.Position.x;
  A[SIE.PY] = c.Position.y;
  A[SIE.PZ] = c.Position.z;
  A[SIE.VX] = c.Velocity.x;
  A[SIE.VY] = c.Velocity.y;
  A[SIE.VZ] = c.Velocity.z;
  A[SIE.OX] = c.PreviousPosition.x;
  A[SIE.OY] = c.PreviousPosition.y;
  A[SIE.OZ] = c.PreviousPosition.z;
  A[SIE.FX] = c.Force.x;
  A[SIE.FY] = c.Force.y;
  A[SIE.FZ] = c.Force.z;
  A[SIE.INV_MASS] = c.Mass.inv;
  P[SIE.H] = h;
  P[SIE.GX_H] = gxh;
  P[SIE.GY_H] = gyh;
  P[SIE.GZ_H] = gzh;
  // Half of this step's gravity velocity, taken off the drift velocity: exact free fall.
  P[SIE.HALF_GX_H] = 0.5 * gxh;
  P[SIE.HALF_GY_H] = 0.5 * gyh;
  P[SIE.HALF_GZ_H] = 0.5 * gzh;

  let ents = forcedBodies(world);
  let check = 0;
  const fused = fusedForcesOn(world);
  if (fused) {
    setFusedForces(world, false);
    if (is2D) fusedForced2(world, h);
    else fusedForced3(world, h);
  } else {
    P[SIE.FORCED] = 1;
    check = runParallel(world, INTEGRATE, is2D ? sie2 : sie3, A, P, ents.length, ents);
  }
  if (check - check !== 0) reportNonFinite(world, ents, 'integrate');

  // Bare particles: a = g. When the query holds every live id (a world of particles), its ids are
  // exactly 1..maxId and the loop runs over that range directly; PreviousPosition is kept only if the
  // world interpolates (nothing collides with a bare particle).
  ents = freeBodies(world);
  const n = ents.length;
  const dense = n > 0 && n === world.entityIndex.maxId;
  P[SIE.SAVE] = world.interpolation ? 1 : 0;
  P[SIE.FORCED] = 0;
  // Bare particles have no force or mass to pass (a world of them may never allocate those stores).
  A.length = SIE.FX;
  check = runParallel(world, INTEGRATE, is2D ? sie2 : sie3, A, P, n, dense ? null : ents);
  if (check - check !== 0) reportNonFinite(world, ents, 'integrate');

  advanceKinematic(world, h);
  applyTorques(world, h);
  advanceOrientations(world, h);
}

/**
 * fusedForced2's pass over the bodies without drag (force 0, exact free fall); returns the running
 * finiteness sum of their new velocities and positions. A loop of its own, with nothing after it but
 * the return: the pass runs once a step, V8 compiles a long loop on the stack (OSR) during its first
 * call, and an operation after the loop that had not run by then would throw that code away at
 * every later call.
 */
function fusedBare2(world: PhysicsWorld, ents: ArrayLike<number>, h: number): number {
  const c = world.components;
  const { x: px, y: py } = c.Position;
  const { x: vx, y: vy } = c.Velocity;
  const { x: ox, y: oy } = c.PreviousPosition;
  const { x: fx, y: fy } = c.Force;
  const im = c.Mass.inv;
  const g = world.gravity;
  const gxh = g[0]! * h,
    gyh = g[1]! * h;
  const hx = 0.5 * gxh,
    hy = 0.5 * gyh;
  let check = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    fx[e] = 0;
    fy[e] = 0;
    const w = im[e]! * h;
    const nvx = vx[e]! + 0 * w + gxh,
      nvy = vy[e]! + 0 * w + gyh;
    const x = px[e]!,
      y = py[e]!;
    ox[e] = x;
    oy[e] = y;
    vx[e] = nvx;
    vy[e] = nvy;
    const nx = x + (nvx - hx) * h,
      ny = y + (nvy - hy) * h;
    px[e] = nx;
    py[e] = ny;
    check += nvx + nvy + nx * 0 + ny * 0;
  }
  return check;
}

/**
 * The fused pass of a 2D semi-implicit Euler substep (integrators/fused-gate.ts): for each forced body,
 * its force as the cleared accumulator and the built-in laws would leave it (0 for a body without drag;
 * 0 - k v for linear drag and 0 - k |v| v for quadratic drag, or 0 and the stiff stamp where the law is
 * stiff, exactly as `linearDragSystem` and `quadraticDragSystem` decide; the z component as they write
 * it), stored in `Force`, then the forced-body update of `semiImplicitEuler` with it. The same
 * operations in the same order per body as the separate stages, so the same bits.
 * @throws NonFiniteStateError naming a force (field 'Force.x' or 'Force.y', stage 'forces') if one
 *   is NaN or infinite, else a velocity or position (stage 'integrate'). Each body's force is tested
 *   before the body is written (one branch a body), so the body with a non-finite force keeps its
 *   position, velocity and PreviousPosition from before the substep (its `Force` holds the non-finite
 *   value, as the forces stage leaves it), and so do the bodies after it in the pass. The bodies
 *   before it were moved with finite forces and stay moved: every forced body without drag (that list
 *   runs first), then those of its own list (quadratic drag, then linear) that precede it. The separate
 *   stages would have moved none (the forces stage throws before the integrator runs); moving them
 *   back would not be exact ((v + a h) - a h need not be v), so they are left, as step/finite.ts
 *   and fused-gate.ts state. A non-finite velocity or position (stage 'integrate') is found by the running sum after
 *   its list has been moved, as in the separate integrator.
 */
function fusedForced2(world: PhysicsWorld, h: number): void {
  const c = world.components;
  const { x: px, y: py } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: ox, y: oy } = c.PreviousPosition;
  const { x: fx, y: fy, z: fz } = c.Force;
  const im = c.Mass.inv;
  const g = world.gravity;
  const gxh = g[0]! * h,
    gyh = g[1]! * h;
  const hx = 0.5 * gxh,
    hy = 0.5 * gyh;
  // The drags' stiffness threshold (forces/drag.ts): k h / m >= STIFF_RATE, i.e. k / m >= limit.
  const limit = STIFF_RATE / world.h;

  // No drag: the cleared force, 0; exact free fall. (The loop is a function of its own, with nothing
  // after it but the return: see fusedBare2.)
  let ents = fusedBareBodies(world);
  let check = fusedBare2(world, ents, h);
  // The force is 0 here: only a velocity or position can be non-finite.
  if (check - check !== 0) reportNonFinite(world, ents, 'integrate');

  // Quadratic drag F = -k |v| v (kind 1), then linear drag F = -k v (kind 2) (forces/drag.ts, calm air).
  const kq = c.QuadraticDrag.k,
    kl = c.LinearDrag.k;
  let stiff = 0;
  for (let kind = 1; kind < 3; kind++) {
    ents = kind === 1 ? fusedQuadraticBodies(world) : fusedLinearBodies(world);
    check = 0;
    // The first body whose force is not finite (-1: none); the pass stops before moving it.
    let bad = -1;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const u = vx[e]!,
        v = vy[e]!,
        z = vz[e]!;
      const inv = im[e]!;
      // F = -cd v: cd = k |v| (quadratic) or k (linear).
      const cd = kind === 1 ? kq[e]! * Math.sqrt(u * u + v * v + z * z) : kl[e]!;
      let fxe = 0,
        fye = 0;
      if (cd * inv >= limit) {
        if (kind === 1) markStiffQuadratic(world, e, kq[e]!);
        else stiff++;
      } else {
        fxe = 0 - cd * u;
        fye = 0 - cd * v;
        // The z component as the law writes it (0 in a 2D world unless set by hand: then unchanged but for a -0).
        if (z !== 0 || 1 / z < 0) fz[e] = fz[e]! - cd * z;
      }
      fx[e] = fxe;
      fy[e] = fye;
      // A NaN or infinite force stops the pass before this body moves (x * 0 is 0 or -0 exactly when x is finite).
      if (fxe * 0 + fye * 0 !== 0) {
        bad = e;
        break;
      }
      const w = inv * h;
      const nvx = u + fxe * w + gxh,
        nvy = v + fye * w + gyh;
      const x = px[e]!,
        y = py[e]!;
      ox[e] = x;
      oy[e] = y;
      vx[e] = nvx;
      vy[e] = nvy;
      const k = fxe === 0 && fye === 0 ? 1 : 0;
      const nx = x + (nvx - k * hx) * h,
        ny = y + (nvy - k * hy) * h;
      px[e] = nx;
      py[e] = ny;
      check += nvx + nvy + nx * 0 + ny * 0;
    }
    if (stiff > 0) stampLinear(world);
    if (bad >= 0) nonFiniteForce(world, bad);
    if (check - check !== 0) reportNonFinite(world, ents, 'integrate');
  }
}

/**
 * `fusedForced2` for a 3D world: the same forces (every component written, as the cleared accumulator
 * and the drag laws leave it) and the 3D forced-body update of `semiImplicitEuler`.
 * @throws NonFiniteStateError as `fusedForced2` (Force.z too); the same bodies have moved.
 */
function fusedForced3(world: PhysicsWorld, h: number): void {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: ox, y: oy, z: oz } = c.PreviousPosition;
  const { x: fx, y: fy, z: fz } = c.Force;
  const im = c.Mass.inv;
  const g = world.gravity;
  const gxh = g[0]! * h,
    gyh = g[1]! * h,
    gzh = g[2]! * h;
  const hx = 0.5 * gxh,
    hy = 0.5 * gyh,
    hz = 0.5 * gzh;
  const limit = STIFF_RATE / world.h;
  const kq = c.QuadraticDrag.k,
    kl = c.LinearDrag.k;
  let stiff = 0;
  // 0: no drag, 1: quadratic, 2: linear.
  for (let kind = 0; kind < 3; kind++) {
    const ents = kind === 0 ? fusedBareBodies(world) : kind === 1 ? fusedQuadraticBodies(world) : fusedLinearBodies(world);
    let check = 0,
      bad = -1;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const u = vx[e]!,
        v = vy[e]!,
        s = vz[e]!;
      const inv = im[e]!;
      let fxe = 0,
        fye = 0,
        fze = 0;
      if (kind === 1) {
        const cq = kq[e]! * Math.sqrt(u * u + v * v + s * s);
        if (cq * inv >= limit) markStiffQuadratic(world, e, kq[e]!);
        else {
          fxe = 0 - cq * u;
          fye = 0 - cq * v;
          fze = 0 - cq * s;
        }
      } else if (kind === 2) {
        const cl = kl[e]!;
        if (cl * inv >= limit) stiff++;
        else {
          fxe = 0 - cl * u;
          fye = 0 - cl * v;
          fze = 0 - cl * s;
        }
      }
      fx[e] = fxe;
      fy[e] = fye;
      fz[e] = fze;
      if (fxe * 0 + fye * 0 + fze * 0 !== 0) {
        bad = e;
        break;
      }
      const w = inv * h;
      const nvx = u + fxe * w + gxh,
        nvy = v + fye * w + gyh,
        nvz = s + fze * w + gzh;
      const x = px[e]!,
        y = py[e]!,
        z = pz[e]!;
      ox[e] = x;
      oy[e] = y;
      oz[e] = z;
      vx[e] = nvx;
      vy[e] = nvy;
      vz[e] = nvz;
      const k = fxe === 0 && fye === 0 && fze === 0 ? 1 : 0;
      const nx = x + (nvx - k * hx) * h,
        ny = y + (nvy - k * hy) * h,
        nz = z + (nvz - k * hz) * h;
      px[e] = nx;
      py[e] = ny;
      pz[e] = nz;
      check += nvx + nvy + nvz + nx * 0 + ny * 0 + nz * 0;
    }
    if (bad >= 0) {
      if (stiff > 0) stampLinear(world);
      nonFiniteForce(world, bad);
    }
    if (check - check !== 0) reportNonFinite(world, ents, 'integrate');
  }
  if (stiff > 0) stampLinear(world);
}

/** Records that linear drag was stiff for some body this (sub)step, as `linearDragSystem` does. */
function stampLinear(world: PhysicsWorld): void {
  const st = dissipationState(world);
  st.linearSeen = st.epoch;
}

/**
 * The fused pass found body `e`'s force NaN or infinite, before moving it: throws what the forces
 * stage's check would (as step/finite.ts `reportNonFiniteForces`: Force.x, Force.y or Force.z, stage
 * 'forces', this body). Called after the loop has stopped at the body, so the loop's only cost is
 * one well-predicted branch a body.
 * @throws NonFiniteStateError always.
 */
function nonFiniteForce(world: PhysicsWorld, e: number): never {
  const F = world.components.Force;
  const fields: Array<readonly [string, Float64Array]> = [
    ['Force.x', F.x],
    ['Force.y', F.y],
  ];
  if (world.dimensions === 3) fields.push(['Force.z', F.z]);
  for (const [, values] of fields) if (!Number.isFinite(values[e]!)) throwNonFinite(world, 'forces', [e], fields);
  throw new Error(`bitphysics: fusedForced: the force of entity ${e} failed the finiteness test yet every component is finite`);
}

/**
 * Moves kinematic bodies with their own velocity (shared by every scheme: their velocity is given).
 * @category Integrators
 */
export function advanceKinematic(world: PhysicsWorld, h: number): void {
  const c = world.components;
  const { x: px, y: py, z: pz } = c.Position;
  const { x: vx, y: vy, z: vz } = c.Velocity;
  const { x: ox, y: oy, z: oz } = c.PreviousPosition;
  const ents = kinematicBodies(world);
  let check = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    const x = px[e]!,
      y = py[e]!,
      z = pz[e]!;
    ox[e] = x;
    oy[e] = y;
    oz[e] = z;
    px[e] = x + vx[e]! * h;
    py[e] = y + vy[e]! * h;
    pz[e] = z + vz[e]! * h;
    check += px[e]! + py[e]! + pz[e]!;
  }
  if (check - check !== 0) reportNonFinite(world, ents, 'integrate');
}

/**
 * Semi-implicit Euler, 2D (see integrators/semi-implicit-euler.ts): with P[SIE.FORCED] = 1 the bodies
 * with a force accumulator (a = F / m + g; ids required), else bare particles (a = g; ids null:
 * entities lo + 1 .. hi). A and P: the SIE slots (integrators/slots/semi-implicit-euler.ts). Returns
 * the finiteness check sum. The bare particles' dense cases have loops of their own, without the
 * per-particle id choice and save branch that sie3's one loop takes: a world of bare 2D particles
 * spends its step here, and the single loop is slower on it.
 */
export function sie2(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[SIE.PX] as Float64Array,
    py = A[SIE.PY] as Float64Array,
    vx = A[SIE.VX] as Float64Array,
    vy = A[SIE.VY] as Float64Array;
  const ox = A[SIE.OX] as Float64Array,
    oy = A[SIE.OY] as Float64Array;
  const h = P[SIE.H]!,
    gxh = P[SIE.GX_H]!,
    gyh = P[SIE.GY_H]!,
    hx = P[SIE.HALF_GX_H]!,
    hy = P[SIE.HALF_GY_H]!,
    save = P[SIE.SAVE] === 1;
  let check = 0;
  if (P[SIE.FORCED] === 1) {
    const fx = A[SIE.FX] as Float64Array,
      fy = A[SIE.FY] as Float64Array,
      im = A[SIE.INV_MASS] as Float64Array;
    const list = ids as Int32Array;
    for (let i = lo; i < hi; i++) {
      const e = list[i]!;
      const w = im[e]! * h;
      const nvx = vx[e]! + fx[e]! * w + gxh;
      const nvy = vy[e]! + fy[e]! * w + gyh;
      const x = px[e]!,
        y = py[e]!;
      ox[e] = x;
      oy[e] = y;
      vx[e] = nvx;
      vy[e] = nvy;
      const k = fx[e] === 0 && fy[e] === 0 ? 1 : 0;
      px[e] = x + (nvx - k * hx) * h;
      py[e] = y + (nvy - k * hy) * h;
      check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
    }
  } else if (ids === null && save) {
    for (let e = lo + 1; e <= hi; e++) {
      const nvx = vx[e]! + gxh,
        nvy = vy[e]! + gyh;
      const x = px[e]!,
        y = py[e]!;
      ox[e] = x;
      oy[e] = y;
      vx[e] = nvx;
      vy[e] = nvy;
      px[e] = x + (nvx - hx) * h;
      py[e] = y + (nvy - hy) * h;
      check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
    }
  } else if (ids === null) {
    for (let e = lo + 1; e <= hi; e++) {
      const nvx = vx[e]! + gxh,
        nvy = vy[e]! + gyh;
      vx[e] = nvx;
      vy[e] = nvy;
      px[e] = px[e]! + (nvx - hx) * h;
      py[e] = py[e]! + (nvy - hy) * h;
      check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
    }
  } else {
    for (let i = lo; i < hi; i++) {
      const e = ids[i]!;
      const nvx = vx[e]! + gxh,
        nvy = vy[e]! + gyh;
      const x = px[e]!,
        y = py[e]!;
      if (save) {
        ox[e] = x;
        oy[e] = y;
      }
      vx[e] = nvx;
      vy[e] = nvy;
      px[e] = x + (nvx - hx) * h;
      py[e] = y + (nvy - hy) * h;
      check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
    }
  }
  return check;
}

/**
 * Semi-implicit Euler, 3D: sie2's two cases (P[SIE.FORCED]) in three dimensions. A and P: the SIE
 * slots (integrators/slots/semi-implicit-euler.ts). Returns the finiteness check sum.
 */
export function sie3(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[SIE.PX] as Float64Array,
    py = A[SIE.PY] as Float64Array,
    pz = A[SIE.PZ] as Float64Array;
  const vx = A[SIE.VX] as Float64Array,
    vy = A[SIE.VY] as Float64Array,
    vz = A[SIE.VZ] as Float64Array;
  const ox = A[SIE.OX] as Float64Array,
    oy = A[SIE.OY] as Float64Array,
    oz = A[SIE.OZ] as Float64Array;
  const h = P[SIE.H]!,
    gxh = P[SIE.GX_H]!,
    gyh = P[SIE.GY_H]!,
    gzh = P[SIE.GZ_H]!,
    hx = P[SIE.HALF_GX_H]!,
    hy = P[SIE.HALF_GY_H]!,
    hz = P[SIE.HALF_GZ_H]!,
    save = P[SIE.SAVE] === 1;
  let check = 0;
  if (P[SIE.FORCED] === 1) {
    const fx = A[SIE.FX] as Float64Array,
      fy = A[SIE.FY] as Float64Array,
      fz = A[SIE.FZ] as Float64Array,
      im = A[SIE.INV_MASS] as Float64Array;
    const list = ids as Int32Array;
    for (let i = lo; i < hi; i++) {
      const e = list[i]!;
      const w = im[e]! * h;
      const nvx = vx[e]! + fx[e]! * w + gxh;
      const nvy = vy[e]! + fy[e]! * w + gyh;
      const nvz = vz[e]! + fz[e]! * w + gzh;
      const x = px[e]!,
        y = py[e]!,
        z = pz[e]!;
      ox[e] = x;
      oy[e] = y;
      oz[e] = z;
      vx[e] = nvx;
      vy[e] = nvy;
      vz[e] = nvz;
      const k = fx[e] === 0 && fy[e] === 0 && fz[e] === 0 ? 1 : 0;
      px[e] = x + (nvx - k * hx) * h;
      py[e] = y + (nvy - k * hy) * h;
      pz[e] = z + (nvz - k * hz) * h;
      check += nvx + nvy + nvz + px[e]! * 0 + py[e]! * 0 + pz[e]! * 0;
    }
  } else {
    for (let i = lo; i < hi; i++) {
      const e = ids === null ? i + 1 : ids[i]!;
      const nvx = vx[e]! + gxh,
        nvy = vy[e]! + gyh,
        nvz = vz[e]! + gzh;
      const x = px[e]!,
        y = py[e]!,
        z = pz[e]!;
      if (save) {
        ox[e] = x;
        oy[e] = y;
        oz[e] = z;
      }
      vx[e] = nvx;
      vy[e] = nvy;
      vz[e] = nvz;
      px[e] = x + (nvx - hx) * h;
      py[e] = y + (nvy - hy) * h;
      pz[e] = z + (nvz - hz) * h;
      check += nvx + nvy + nvz + px[e]! * 0 + py[e]! * 0 + pz[e]! * 0;
    }
  }
  return check;
}
