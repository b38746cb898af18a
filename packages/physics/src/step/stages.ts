import { clothSystem } from '../cloth/solver.js';
import { broadphaseSystem } from '../collision/broadphase/grid.js';
import { continuousCollisionSystem } from '../collision/continuous-2d.js';
import { narrowphaseSystem } from '../collision/narrowphase/balls.js';
import { shapeCollisionSystem } from '../collision/shapes-2d.js';
import { shape3DCollisionSystem } from '../collision/shapes-3d.js';
import { angularDampingSystem, stiffAngularDampingSystem } from '../forces/angular-damping.js';
import { ballastFillSystem, ballastTrimSystem } from '../forces/ballast.js';
import { bodyThrustSystem } from '../forces/body-thrust.js';
import { centralForceSystem } from '../forces/central.js';
import { clearForcesSystem } from '../forces/clear.js';
import { liftSystem, linearDragSystem, quadraticDragSystem, stiffDragSystem } from '../forces/drag.js';
import { drivingForceSystem, randomForceSystem } from '../forces/driving.js';
import { coulombSystem, lorentzSystem } from '../forces/electromagnetism.js';
import { buoyancySystem, stiffFluidDragSystem } from '../forces/fluid.js';
import { attractorSystem, gravityScaleSystem, mutualGravitySystem } from '../forces/gravity.js';
import { liftingSurfaceSystem } from '../forces/lifting-surface.js';
import { springSystem, stiffSpringDampingSystem } from '../forces/spring.js';
import { burnFuelSystem, thrustSystem } from '../forces/thrust.js';
import { vortexSystem } from '../forces/vortex.js';
import { integrateSystem } from '../integrators/integrate.js';
import { sleepSystem, wakeSystem } from '../islands/sleep.js';
import { emitterSystem, lifetimeSystem } from '../particles/emitter.js';
import { shapes3DOf } from '../shapes/store-3d.js';
import { contactSolverSystem } from '../solver/contact-solver.js';
import type { System } from '../world/options.js';
import { query } from '../world/query.js';
import { trustFiniteOutput } from './finite.js';
import type { StageName } from './stage-names.js';

export type { System } from '../world/options.js';
export { STAGES, type StageName, SUBSTEP_STAGES } from './stage-names.js';

/**
 * The default pipeline: every stage with its built-in systems, in run order. A world starts with a
 * copy of it in `world.stages`; hook in with `addSystem`.
 * @category World and step
 */
export const PIPELINE: ReadonlyArray<{ readonly stage: StageName; readonly systems: readonly System[] }> = Object.freeze([
  { stage: 'spawn', systems: [wakeSystem, lifetimeSystem, emitterSystem] },
  { stage: 'clearForces', systems: [clearForcesSystem] },
  {
    stage: 'forces',
    systems: [
      gravityScaleSystem,
      mutualGravitySystem,
      attractorSystem,
      coulombSystem,
      lorentzSystem,
      centralForceSystem,
      linearDragSystem,
      quadraticDragSystem,
      liftSystem,
      buoyancySystem,
      springSystem,
      drivingForceSystem,
      randomForceSystem,
      thrustSystem,
      angularDampingSystem,
      vortexSystem,
      bodyThrustSystem,
      liftingSurfaceSystem,
      ballastTrimSystem,
    ],
  },
  {
    stage: 'integrate',
    systems: [
      integrateSystem,
      stiffDragSystem,
      stiffFluidDragSystem,
      stiffAngularDampingSystem,
      stiffSpringDampingSystem,
      burnFuelSystem,
      ballastFillSystem,
    ],
  },
  {
    stage: 'collide',
    systems: [
      broadphaseSystem,
      narrowphaseSystem,
      shapeCollisionSystem,
      shape3DCollisionSystem,
      contactSolverSystem,
      continuousCollisionSystem,
    ],
  },
  { stage: 'constraints', systems: [clothSystem] },
  { stage: 'finalize', systems: [sleepSystem] },
]);

// Built-in systems that write no body state (force laws write forces, which `step` checks after the
// forces stage; broadphase and narrowphase write contacts; fuel and ballast write masses), or check
// what they write (spawned particles, zeroed velocities of sleeping bodies, the contact solver's
// bodies; the integrators and the stiff drag updates their positions and velocities, so after
// `integrate` only the turning bodies are checked). Shape collisions (2D and 3D) and cloth are trusted
// only in a world without such shapes or cloth links, where they write nothing (step/finite.ts), so a
// world with nothing to collide pays nothing for its collide stage.
trustFiniteOutput([
  wakeSystem,
  lifetimeSystem,
  emitterSystem,
  broadphaseSystem,
  narrowphaseSystem,
  contactSolverSystem,
  sleepSystem,
  burnFuelSystem,
  ballastFillSystem,
  ...PIPELINE.find((p) => p.stage === 'forces')!.systems,
]);
trustFiniteOutput([integrateSystem, stiffDragSystem, stiffFluidDragSystem, stiffAngularDampingSystem, stiffSpringDampingSystem], 'linear');
trustFiniteOutput([shapeCollisionSystem, continuousCollisionSystem], 'all', (world) => query(world, [world.components.Shape]).length === 0);
trustFiniteOutput([shape3DCollisionSystem], 'all', (world) => world.dimensions !== 3 || shapes3DOf(world)?.active !== true);
trustFiniteOutput([clothSystem], 'all', (world) => query(world, [world.components.ClothLink]).length === 0);

/**
 * A fresh copy of the default systems of every stage.
 * @category World and step
 */
export function createStages(): Record<StageName, System[]> {
  const stages = {} as Record<StageName, System[]>;
  for (const { stage, systems } of PIPELINE) stages[stage] = [...systems];
  return stages;
}
