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
import { emitterSystem, lifetimeSystem } from '../particles/emitter-systems.js';
import { contactSolverSystem } from '../solver/contact-solver.js';
import { PIPELINE_ORDER } from '../world/install.js';
import type { System } from '../world/options.js';
import { query } from '../world/query.js';
import { STAGES, type StageName } from '../world/stage-names.js';
import { trustFiniteOutput } from '../world/trusted-systems.js';

export type { System } from '../world/options.js';
export { STAGES, type StageName, SUBSTEP_STAGES } from '../world/stage-names.js';

/** The core's built-in systems by name (world/install.ts PIPELINE_ORDER): every world starts with these. */
const CORE: Readonly<Record<string, System>> = {
  wake: wakeSystem,
  lifetime: lifetimeSystem,
  clearForces: clearForcesSystem,
  gravityScale: gravityScaleSystem,
  mutualGravity: mutualGravitySystem,
  attractor: attractorSystem,
  coulomb: coulombSystem,
  lorentz: lorentzSystem,
  centralForce: centralForceSystem,
  linearDrag: linearDragSystem,
  quadraticDrag: quadraticDragSystem,
  lift: liftSystem,
  buoyancy: buoyancySystem,
  spring: springSystem,
  drivingForce: drivingForceSystem,
  randomForce: randomForceSystem,
  thrust: thrustSystem,
  angularDamping: angularDampingSystem,
  vortex: vortexSystem,
  bodyThrust: bodyThrustSystem,
  liftingSurface: liftingSurfaceSystem,
  ballastTrim: ballastTrimSystem,
  integrate: integrateSystem,
  stiffDrag: stiffDragSystem,
  stiffFluidDrag: stiffFluidDragSystem,
  stiffAngularDamping: stiffAngularDampingSystem,
  stiffSpringDamping: stiffSpringDampingSystem,
  burnFuel: burnFuelSystem,
  ballastFill: ballastFillSystem,
  shapes2D: shapeCollisionSystem,
  contactSolver: contactSolverSystem,
  continuous: continuousCollisionSystem,
  sleep: sleepSystem,
};

/**
 * The default pipeline: every stage with all its built-in systems, in run order (world/install.ts
 * PIPELINE_ORDER). A world starts with the core ones in `world.stages` and installs the others (the
 * emitters', 3D shapes' and cloth's systems) at their place here when the feature is first used;
 * hook in with `addSystem`. Referencing this list brings every built-in system into a bundle.
 * @category World and step
 */
export const PIPELINE: ReadonlyArray<{ readonly stage: StageName; readonly systems: readonly System[] }> = /* @__PURE__ */ Object.freeze([
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

let coreTrusted = false;

/**
 * Marks the core's systems whose output `step` need not check for NaN (step/finite.ts), once.
 * Built-in systems that write no body state (force laws write forces, which `step` checks after the
 * forces stage; broadphase and narrowphase write contacts; fuel and ballast write masses), or check
 * what they write (zeroed velocities of sleeping bodies, the contact solver's bodies; the integrators
 * and the stiff drag updates their positions and velocities, so after `integrate` only the turning
 * bodies are checked). Shape collisions are trusted only in a world without shapes, where they write
 * nothing, so a world with nothing to collide pays nothing for its collide stage. The installed
 * features mark their own (installEmitters, install3D, installCloth).
 */
function trustCore(): void {
  if (coreTrusted) return;
  coreTrusted = true;
  const forces = PIPELINE_ORDER.forces.map((name) => CORE[name]!);
  trustFiniteOutput([wakeSystem, lifetimeSystem, contactSolverSystem, sleepSystem, burnFuelSystem, ballastFillSystem, ...forces]);
  trustFiniteOutput(
    [integrateSystem, stiffDragSystem, stiffFluidDragSystem, stiffAngularDampingSystem, stiffSpringDampingSystem],
    'linear',
  );
  trustFiniteOutput(
    [shapeCollisionSystem, continuousCollisionSystem],
    'all',
    (world) => query(world, [world.components.Shape]).length === 0,
  );
}

/**
 * A new world's stages: the core's built-in systems of every stage, in run order, each recorded by
 * name in `builtins` (the world's map of installed built-ins, see world/install.ts).
 * @category World and step
 */
export function createStages(builtins: Map<string, System>): Record<StageName, System[]> {
  trustCore();
  const stages = {} as Record<StageName, System[]>;
  for (const stage of STAGES) {
    stages[stage] = [];
    for (const name of PIPELINE_ORDER[stage]) {
      const system = CORE[name];
      if (system === undefined) continue;
      stages[stage].push(system);
      builtins.set(name, system);
    }
  }
  return stages;
}
