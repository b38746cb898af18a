import type { QueryResult } from 'bitecs';
import type { PhysicsWorld } from '../world/options.js';
import { Not, query } from '../world/query.js';
import type { MoverTerms } from '../world/scratch.js';

/**
 * The terms of the integrators' queries, built once per world (`world.scratch.moverTerms`): these run
 * every substep, and a list built at each call (with its `Not` look-ups) would be most of their cost in
 * a world of a few bodies.
 */
function moverTermsOf(world: PhysicsWorld): MoverTerms {
  let t = world.scratch.moverTerms;
  if (t === undefined) {
    const c = world.components;
    t = {
      forced: [c.Position, c.Velocity, c.Force, Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)],
      free: [c.Position, c.Velocity, Not(c.Force), Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)],
      kinematic: [c.Position, c.Velocity, c.Kinematic, Not(c.Static)],
      torqued: [c.AngularVelocity, c.Inertia, c.Torque, Not(c.InertiaTensor), Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)],
      tensor: [c.AngularVelocity, c.InertiaTensor, c.Orientation, Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)],
      spinning2D: [c.AngularVelocity, c.Angle, Not(c.Static), Not(c.Sleeping)],
      spinning3D: [c.AngularVelocity, c.Orientation, Not(c.Static), Not(c.Sleeping)],
      simpleSpinning3D: [c.AngularVelocity, c.Orientation, Not(c.InertiaTensor), Not(c.Static), Not(c.Sleeping)],
    };
    world.scratch.moverTerms = t;
  }
  return t;
}

/**
 * Dynamic bodies with a force accumulator (and so a mass): they feel force laws and gravity.
 * Every integrator moves these with a = F / m + g.
 * @category Integrators
 */
export function forcedBodies(world: PhysicsWorld): QueryResult {
  return query(world, moverTermsOf(world).forced);
}

/**
 * Dynamic bodies without a force accumulator (plain particles): they feel the world's gravity only, a = g.
 * @category Integrators
 */
export function freeBodies(world: PhysicsWorld): QueryResult {
  return query(world, moverTermsOf(world).free);
}

/**
 * Kinematic bodies: x += v h, nothing changes their velocity.
 * @category Integrators
 */
export function kinematicBodies(world: PhysicsWorld): QueryResult {
  return query(world, moverTermsOf(world).kinematic);
}

/**
 * Bodies that turn under torque with a scalar moment of inertia: angular velocity, inertia, a torque accumulator.
 * @category Integrators
 */
export function torquedBodies(world: PhysicsWorld): QueryResult {
  return query(world, moverTermsOf(world).torqued);
}

/**
 * 3D bodies with a principal inertia tensor: they turn by Euler's equations, torque or not.
 * @category Integrators
 */
export function tensorBodies(world: PhysicsWorld): QueryResult {
  return query(world, moverTermsOf(world).tensor);
}

/**
 * Bodies whose orientation follows their angular velocity: 2D `Angle` or 3D `Orientation`.
 * @category Integrators
 */
export function spinningBodies(world: PhysicsWorld): QueryResult {
  const t = moverTermsOf(world);
  return query(world, world.dimensions === 2 ? t.spinning2D : t.spinning3D);
}

/**
 * Spinning bodies whose orientation the semi-implicit scheme advances with w h: all of them but the
 * 3D inertia-tensor bodies (the rigid-body splitting turns those itself).
 * @category Integrators
 */
export function simpleSpinningBodies(world: PhysicsWorld): QueryResult {
  const t = moverTermsOf(world);
  return query(world, world.dimensions === 2 ? t.spinning2D : t.simpleSpinning3D);
}

/*
 * The fused force-and-integrate pass (integrators/fused-gate.ts) splits the forced bodies by the drag
 * they carry; the three lists below are disjoint, and together they are every forced body exactly when
 * none carries a GravityScale or both drags (the gate checks this by their lengths).
 */

/** The terms of the three lists, built once per world (`world.scratch.fusedTerms`): these run every substep. */
function fusedTermsOf(world: PhysicsWorld): readonly [object[], object[], object[]] {
  let t = world.scratch.fusedTerms;
  if (t === undefined) {
    const c = world.components;
    const mover = [c.Position, c.Velocity, c.Force, Not(c.Static), Not(c.Kinematic), Not(c.Sleeping)];
    t = [
      [...mover, Not(c.LinearDrag), Not(c.QuadraticDrag), Not(c.GravityScale)],
      [...mover, c.QuadraticDrag, Not(c.LinearDrag), Not(c.GravityScale)],
      [...mover, c.LinearDrag, Not(c.QuadraticDrag), Not(c.GravityScale)],
    ];
    world.scratch.fusedTerms = t;
  }
  return t;
}

/**
 * Forced bodies with no drag and no gravity scale: no built-in law writes their force (fused pass).
 * @category Integrators
 */
export function fusedBareBodies(world: PhysicsWorld): QueryResult {
  return query(world, fusedTermsOf(world)[0]);
}

/**
 * Forced bodies with quadratic drag only (no linear drag, no gravity scale): the fused pass.
 * @category Integrators
 */
export function fusedQuadraticBodies(world: PhysicsWorld): QueryResult {
  return query(world, fusedTermsOf(world)[1]);
}

/**
 * Forced bodies with linear drag only (no quadratic drag, no gravity scale): the fused pass.
 * @category Integrators
 */
export function fusedLinearBodies(world: PhysicsWorld): QueryResult {
  return query(world, fusedTermsOf(world)[2]);
}

/**
 * Makes the integrators' queries of `world` (the lists above, of its dimension), for a world that has
 * no entity yet: bitecs then keeps each list as bodies are added, where a query first asked by the
 * first step, with the scene built, is filled by a pass over every entity in that step.
 * createPhysicsWorld calls it. @category Integrators
 */
export function makeIntegratorQueries(world: PhysicsWorld): void {
  forcedBodies(world);
  freeBodies(world);
  kinematicBodies(world);
  torquedBodies(world);
  spinningBodies(world);
  simpleSpinningBodies(world);
  if (world.dimensions === 3) tensorBodies(world);
  fusedBareBodies(world);
  fusedQuadraticBodies(world);
  fusedLinearBodies(world);
}
