import type { IntegratorName } from '../world/integrator-names.js';
import type { PhysicsWorld } from '../world/options.js';
import { registerFusedIntegrator } from './fused-gate.js';
import { implicitEuler } from './implicit-euler.js';
import { explicitEuler, positionVerlet, rk2, rk4, velocityVerlet } from './schemes.js';
import { semiImplicitEuler } from './semi-implicit-euler.js';

/**
 * An integration scheme: advances every moving body of the world by h seconds.
 * @category Integrators
 */
export type Integrator = (world: PhysicsWorld, h: number) => void;

/**
 * The scheme behind each name of `INTEGRATOR_NAMES`.
 * @category Integrators
 */
export const INTEGRATORS: Readonly<Record<IntegratorName, Integrator>> = Object.freeze({
  'explicit-euler': explicitEuler,
  'semi-implicit-euler': semiImplicitEuler,
  'implicit-euler': implicitEuler,
  rk2,
  rk4,
  'position-verlet': positionVerlet,
  'velocity-verlet': velocityVerlet,
});

/**
 * Stage 4: advances the world by `world.h` with the world's chosen scheme.
 * @category Integrators
 */
export function integrateSystem(world: PhysicsWorld): void {
  INTEGRATORS[world.integrator](world, world.h);
}
registerFusedIntegrator(integrateSystem);
