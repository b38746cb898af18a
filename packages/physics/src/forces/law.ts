import type { PhysicsWorld } from '../world/options.js';

/**
 * A force-law system: a System that may declare whether it reads velocities. The Verlet schemes
 * spend an extra force evaluation only when some law in the world is velocity-dependent; a law that
 * does not say is assumed to be.
 * @category Forces
 */
export interface ForceLaw {
  (world: PhysicsWorld): void;
  /** false if the law reads only positions, time and constants. */
  velocityDependent?: boolean;
}
