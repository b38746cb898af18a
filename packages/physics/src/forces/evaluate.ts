import { setFusedForces } from '../world/fused-state.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Evaluates every force law at the world's current state: clears the accumulators and runs the
 * `forces` stage. Multi-stage integrators call it at each trial state, which is why every force
 * law must be a pure function of the state arrays it reads.
 * @category World and step
 */
export function evaluateForces(world: PhysicsWorld): void {
  setFusedForces(world, false);
  const clear = world.stages.clearForces;
  for (let i = 0; i < clear.length; i++) clear[i]!(world);
  const forces = world.stages.forces;
  for (let i = 0; i < forces.length; i++) forces[i]!(world);
}
