import { angularDampingSystem } from '../forces/angular-damping.js';
import { ballastTrimSystem } from '../forces/ballast.js';
import { bodyThrustSystem } from '../forces/body-thrust.js';
import { centralForceSystem } from '../forces/central.js';
import { clearForcesSystem } from '../forces/clear.js';
import { calmAir, liftSystem, linearDragSystem, quadraticDragSystem } from '../forces/drag.js';
import { drivingForceSystem, randomForceSystem } from '../forces/driving.js';
import { coulombSystem, lorentzSystem } from '../forces/electromagnetism.js';
import { buoyancySystem } from '../forces/fluid.js';
import { attractorSystem, gravityScaleSystem, mutualGravitySystem } from '../forces/gravity.js';
import { liftingSurfaceSystem } from '../forces/lifting-surface.js';
import { springSystem } from '../forces/spring.js';
import { thrustSystem } from '../forces/thrust.js';
import { vortexSystem } from '../forces/vortex.js';
import { beginFusedSubstep } from '../world/fused-state.js';
import type { PhysicsWorld, System } from '../world/options.js';
import { query } from '../world/query.js';
import { type ForcesPlan, sameEntries } from '../world/scratch.js';
import { forcedBodies, fusedBareBodies, fusedLinearBodies, fusedQuadraticBodies } from './queries.js';

/**
 * When a substep may fuse stages 2 to 4 for the world's forced bodies: one pass that writes each
 * body's force (linear or quadratic drag, or none) and integrates it (semi-implicit Euler), instead of a
 * pass that clears the accumulators, one per drag law, the forces stage's finiteness check and the
 * integrator's pass. In a world of particles under gravity and drag (fireworks) those were five passes
 * over the same arrays where a hand-written loop makes one.
 *
 * The fused pass is the separate stages' arithmetic, operation for operation (the force starts at the
 * cleared 0 and each law subtracts its term, the stiff regime is decided and stamped the same way), so
 * the state after a step is identical to the bit. It is used only where nothing else can touch a force
 * accumulator between the clear and the integrator, checked at the start of every substep:
 *
 * - the world (2D or 3D) integrates with semi-implicit Euler and its air is calm (no wind: drag then
 *   reads the body's own velocity). A world with worker threads fuses too, on its calling thread: the
 *   one pass does the work of five, so it is faster than the separate stages split over 2 threads, and
 *   the state stays the same to the bit, so results do not depend on the thread count.
 * - the clearForces stage is exactly `clearForcesSystem`, and the integrate stage starts with the
 *   world's integrator (`registerFusedIntegrator`), so no user system reads or writes forces there;
 * - every system of the forces stage is a built-in law: linear drag, quadratic drag and the gravity scale
 *   once each (the pass applies the drags; the gravity scale has no body in the pass), and every other
 *   one with nothing to act on (no springs, attractors, charges, thrusters, ...), or one that writes
 *   torques only. A user's force law, a law added twice, or a law this module does not know turns the
 *   pass off for the substep, and every stage runs as usual;
 * - every body with a force accumulator is a dynamic, awake mover carrying linear drag, quadratic drag
 *   or neither, and no gravity scale (the three fused lists cover the forced bodies, which cover the
 *   bodies with `Force`).
 *
 * Particles stay ordinary entities: a component a user gives a particle that a built-in law acts on
 * (a charge, a thruster) makes that law busy and so turns the pass off; after the step every body's
 * `Force` holds what the laws would have written.
 *
 * A NaN or infinite force is reported as the forces stage's check reports it (Force.x/y/z, stage
 * 'forces', the first such body of the pass), before that body is moved; only the bodies the pass had
 * already moved differ from the separate stages, which move none (integrators/semi-implicit-euler.ts).
 */

/** Laws that write only torques, or forces never: they may run beside the fused pass. */
const TORQUE_ONLY: ReadonlySet<System> = new Set<System>([angularDampingSystem, ballastTrimSystem]);

/** The laws the fused pass applies itself (each must be in the stage exactly once). */
const ABSORBED: readonly System[] = [linearDragSystem, quadraticDragSystem, gravityScaleSystem];

type Components = PhysicsWorld['components'];

/**
 * Built-in laws that may stay in the stage while they have nothing to act on: the terms of the law's
 * own query, and the fewest entities it acts on (2 for the pairwise laws).
 */
const IDLE_WHEN: ReadonlyMap<System, readonly [(c: Components) => object[], number]> = new Map<
  System,
  readonly [(c: Components) => object[], number]
>([
  [mutualGravitySystem, [(c) => [c.MutualGravity, c.Position, c.Mass, c.Force], 2]],
  [attractorSystem, [(c) => [c.Attractor, c.Position], 1]],
  [coulombSystem, [(c) => [c.Charge, c.Position, c.Force], 2]],
  [lorentzSystem, [(c) => [c.Charge, c.Force, c.Velocity], 1]],
  [centralForceSystem, [(c) => [c.CentralForce, c.Position, c.Force], 1]],
  [liftSystem, [(c) => [c.Lift, c.Velocity, c.Force], 1]],
  [buoyancySystem, [(c) => [c.Buoyancy, c.Position, c.Velocity, c.Force], 1]],
  [springSystem, [(c) => [c.Spring], 1]],
  [drivingForceSystem, [(c) => [c.DrivingForce, c.Force], 1]],
  [randomForceSystem, [(c) => [c.RandomForce, c.Force], 1]],
  [thrustSystem, [(c) => [c.Thrust, c.Force, c.Mass], 1]],
  [vortexSystem, [(c) => [c.Vortex, c.Position, c.Force], 1]],
  [bodyThrustSystem, [(c) => [c.BodyThrust, c.Force], 1]],
  [liftingSurfaceSystem, [(c) => [c.LiftingSurface], 1]],
]);

/**
 * The gate's plan of `world`'s forces stage (`world.scratch.forcesPlan`; see ForcesPlan in
 * world/scratch.ts), remade when the stage's systems change. A substep then reads the idle laws' query
 * lengths instead of looking every law up.
 */
function forcesPlan(world: PhysicsWorld, forces: readonly System[]): ForcesPlan<PhysicsWorld> {
  const plan = world.scratch.forcesPlan;
  if (plan !== undefined && sameEntries(plan.forces, forces)) return plan;
  const c = world.components;
  const made: ForcesPlan<PhysicsWorld> = { forces: forces.slice(), allowed: true, idle: [], least: [], force: query(world, [c.Force]) };
  let absorbed = 0;
  for (const s of forces) {
    if (ABSORBED.includes(s)) {
      absorbed++;
      continue;
    }
    if (TORQUE_ONLY.has(s)) continue;
    const idle = IDLE_WHEN.get(s);
    if (idle === undefined) {
      made.allowed = false;
      break;
    }
    made.idle.push(query(world, idle[0](c)));
    made.least.push(idle[1]);
  }
  // Each absorbed law exactly once (counted above; a duplicate would show as one missing).
  if (absorbed !== ABSORBED.length) made.allowed = false;
  for (const s of ABSORBED) if (forces.indexOf(s) !== forces.lastIndexOf(s)) made.allowed = false;
  world.scratch.forcesPlan = made;
  return made;
}

/**
 * Makes the queries of `world`'s forces plan (see forcesPlan: the Force accumulators' and the idle
 * laws' of its forces stage) while it has no entity, so that its first step does not fill them
 * (integrators/queries.ts makeIntegratorQueries). createPhysicsWorld calls it.
 * @category Integrators
 */
export function makeForceLawQueries(world: PhysicsWorld): void {
  const c = world.components;
  query(world, [c.Force]);
  for (const s of world.stages.forces) {
    const idle = IDLE_WHEN.get(s);
    if (idle !== undefined) query(world, idle[0](c));
  }
}

let integrator: System | null = null;

/**
 * Registers the integrate stage's integrator system (integrate.ts does, at load).
 * @category Integrators
 */
export function registerFusedIntegrator(system: System): void {
  integrator = system;
}

/**
 * Whether the current substep of `world` may run the fused pass (the conditions of the module comment).
 * @category Integrators
 */
export function fusedForcesAllowed(world: PhysicsWorld): boolean {
  if (world.integrator !== 'semi-implicit-euler') return false;
  const stages = world.stages;
  const clear = stages.clearForces,
    integrate = stages.integrate,
    forces = stages.forces;
  if (clear.length !== 1 || clear[0] !== clearForcesSystem) return false;
  if (integrate.length === 0 || integrate[0] !== integrator) return false;
  const forced = forcedBodies(world).length;
  if (forced === 0) return false;
  // The plan's live arrays are read after forcedBodies' query committed bitecs' pending removals.
  const plan = forcesPlan(world, forces);
  if (!plan.allowed) return false;
  const idle = plan.idle,
    least = plan.least;
  for (let i = 0; i < idle.length; i++) if (idle[i]!.length >= least[i]!) return false;
  if (!calmAir(world)) return false;
  if (plan.force.length !== forced) return false;
  return fusedBareBodies(world).length + fusedQuadraticBodies(world).length + fusedLinearBodies(world).length === forced;
}

/**
 * Called by `step` at the start of every substep: turns the fused pass on or off for it.
 * @category Integrators
 */
export function armFusedForces(world: PhysicsWorld): void {
  beginFusedSubstep(world, fusedForcesAllowed(world));
}
