import { fusedForcesOn } from '../world/fused-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import type { ClearTerms } from '../world/scratch.js';

/** The two queries' terms, built once per world (`world.scratch.clearTerms`): this runs every substep. */
function clearTerms(world: PhysicsWorld): ClearTerms {
  let t = world.scratch.clearTerms;
  if (t === undefined) {
    const c = world.components;
    t = { force: [c.Force], torque: [c.Torque] };
    world.scratch.clearTerms = t;
  }
  return t;
}

/**
 * Stage 2: zeroes the force accumulator of every body with `Force`, and the torque accumulator of
 * every body with `Torque`. In a substep that runs the fused force-and-integrate pass
 * (integrators/fused-gate.ts) the integrator writes every body's force itself, starting from this 0,
 * and only the torques are cleared here.
 * @category Forces
 */
export function clearForcesSystem(world: PhysicsWorld): void {
  const { Force, Torque } = world.components;
  const { x: fx, y: fy, z: fz } = Force;
  if (!fusedForcesOn(world)) {
    const ents = query(world, clearTerms(world).force);
    if (world.dimensions === 2) {
      for (let i = 0; i < ents.length; i++) {
        const e = ents[i]!;
        fx[e] = 0;
        fy[e] = 0;
      }
    } else {
      for (let i = 0; i < ents.length; i++) {
        const e = ents[i]!;
        fx[e] = 0;
        fy[e] = 0;
        fz[e] = 0;
      }
    }
  }
  const ents = query(world, clearTerms(world).torque);
  const { x: tx, y: ty, z: tz } = Torque;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    tx[e] = 0;
    ty[e] = 0;
    tz[e] = 0;
  }
}
