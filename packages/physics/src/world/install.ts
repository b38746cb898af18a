/**
 * Installing a feature's systems into a world's pipeline when the feature is first used: the stages of
 * a new world hold only the core systems (step/stages.ts createStages); the API that makes a feature's
 * first entity (addShape3D, a 3D joint, addEmitter, createCloth, ...) puts the feature's systems into
 * `world.stages` at their fixed place in `PIPELINE_ORDER`, so a program that never calls a feature
 * never reaches its code, and a bundler leaves it out. The order is the default pipeline's, so a
 * world runs the same systems in the same order as one made with every system installed.
 */
import type { PhysicsWorld, System } from './options.js';
import type { StageName } from './stage-names.js';

/**
 * Every built-in system's name, stage by stage, in run order: the order of the default pipeline
 * (`PIPELINE`). Installing a built-in puts it after the installed built-ins that come before it here
 * and before those that come after it.
 * @category World and step
 */
export const PIPELINE_ORDER: Readonly<Record<StageName, readonly string[]>> = /* @__PURE__ */ Object.freeze({
  spawn: ['wake', 'lifetime', 'emitter'],
  clearForces: ['clearForces'],
  forces: [
    'gravityScale',
    'mutualGravity',
    'attractor',
    'coulomb',
    'lorentz',
    'centralForce',
    'linearDrag',
    'quadraticDrag',
    'lift',
    'buoyancy',
    'spring',
    'drivingForce',
    'randomForce',
    'thrust',
    'angularDamping',
    'vortex',
    'bodyThrust',
    'liftingSurface',
    'ballastTrim',
  ],
  integrate: ['integrate', 'stiffDrag', 'stiffFluidDrag', 'stiffAngularDamping', 'stiffSpringDamping', 'burnFuel', 'ballastFill'],
  collide: ['broadphase', 'narrowphase', 'shapes2D', 'shapes3D', 'contactSolver', 'continuous'],
  constraints: ['cloth'],
  finalize: ['sleep'],
});

/**
 * Puts the built-in system `name` (one of `PIPELINE_ORDER[stage]`) into the world's `stage` at its
 * place: just before the first installed built-in that follows it in `PIPELINE_ORDER`, else just after
 * the last one that precedes it, else first in the stage (user systems added with `addSystem` keep
 * their place relative to the built-ins). Does nothing if the world ever had it installed: a built-in
 * a user took out with `removeSystem` stays out.
 * @throws RangeError if `name` is not a built-in of `stage` (a bug of the package, not of its user).
 * @category World and step
 */
export function installSystem(world: PhysicsWorld, stage: StageName, name: string, system: System): void {
  const builtins = world.builtins;
  if (builtins.has(name)) return;
  const order = PIPELINE_ORDER[stage];
  const rank = order.indexOf(name);
  if (rank < 0) throw new RangeError(`installSystem: '${name}' is not a built-in system of stage '${stage}'`);
  const list = world.stages[stage];
  let at = -1;
  for (let r = rank + 1; r < order.length && at < 0; r++) {
    const s = builtins.get(order[r]!);
    if (s !== undefined) at = list.indexOf(s);
  }
  for (let r = rank - 1; r >= 0 && at < 0; r--) {
    const s = builtins.get(order[r]!);
    const i = s === undefined ? -1 : list.indexOf(s);
    if (i >= 0) at = i + 1;
  }
  list.splice(Math.max(at, 0), 0, system);
  builtins.set(name, system);
}
