/** A submarine world for the headless submarine tests: a neutral boat on a calm sea over open water. */

import { createPhysicsWorld } from '@bitphysics/physics';
import { SUBMARINE_NEUTRAL_FILL, submarine } from '@bitphysics/projects';
import { createHelmState } from '../../games/submarine/helm';

/**
 * A neutral boat (SUBMARINE_NEUTRAL_FILL, seed 1, no mines) at rest hovering at height `y`, m (negative
 * below the surface), the sea's surface flat at 0 and the seabed 1 km down, its helm holding that depth:
 * the world, the scene's handles, the helm state, the components and the hull's entity.
 */
export function hovering(y: number) {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, y] });
  world.components.FluidRegion.surface.fill(0);
  h.seabed.y.fill(-1000);
  const helm = { ...createHelmState(SUBMARINE_NEUTRAL_FILL), holdY: y, mode: 'holding' as const };
  return { world, h, helm, c: world.components, e: h.hull };
}
