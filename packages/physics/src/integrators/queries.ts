import { Not, query, type QueryResult } from 'bitecs';
import type { PhysicsWorld } from '../world';

/**
 * Dynamic bodies with a force accumulator (and so a mass): they feel force laws and gravity.
 * Every integrator moves these with a = F / m + g.
 */
export function forcedBodies(world: PhysicsWorld): QueryResult {
  const c = world.components;
  return query(world, [c.Position, c.Velocity, c.Force, Not(c.Static), Not(c.Kinematic)]);
}

/** Dynamic bodies without a force accumulator (plain particles): they feel the world's gravity only, a = g. */
export function freeBodies(world: PhysicsWorld): QueryResult {
  const c = world.components;
  return query(world, [c.Position, c.Velocity, Not(c.Force), Not(c.Static), Not(c.Kinematic)]);
}

/** Kinematic bodies: x += v h, nothing changes their velocity. */
export function kinematicBodies(world: PhysicsWorld): QueryResult {
  const c = world.components;
  return query(world, [c.Position, c.Velocity, c.Kinematic, Not(c.Static)]);
}

/** Bodies that turn under torque: angular velocity, inertia and a torque accumulator. */
export function torquedBodies(world: PhysicsWorld): QueryResult {
  const c = world.components;
  return query(world, [c.AngularVelocity, c.Inertia, c.Torque, Not(c.Static), Not(c.Kinematic)]);
}

/** Bodies whose orientation follows their angular velocity: 2D `Angle` or 3D `Orientation`. */
export function spinningBodies(world: PhysicsWorld): QueryResult {
  const c = world.components;
  return world.dimensions === 2
    ? query(world, [c.AngularVelocity, c.Angle, Not(c.Static)])
    : query(world, [c.AngularVelocity, c.Orientation, Not(c.Static)]);
}
