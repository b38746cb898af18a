/**
 * Names of the integration schemes a world can use, chosen with `createPhysicsWorld({ integrator })`.
 *
 * - `'semi-implicit-euler'` (symplectic Euler): v += a h, then x += v h. First order, symplectic.
 *   Source: Ramtal and Dobre ch. 14; Hairer, Lubich and Wanner, Geometric Numerical Integration, ch. I.1.
 */
export const INTEGRATOR_NAMES = ['semi-implicit-euler'] as const;

/** One of `INTEGRATOR_NAMES`. */
export type IntegratorName = (typeof INTEGRATOR_NAMES)[number];
