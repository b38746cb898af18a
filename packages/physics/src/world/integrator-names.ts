/**
 * Names of the integration schemes a world can use, chosen with `createPhysicsWorld({ integrator })`
 * (Ramtal and Dobre ch. 14; orders are global errors on smooth problems):
 *
 * - `'explicit-euler'`: x += v h, v += a h, both from the old state. Order 1; gains energy.
 * - `'semi-implicit-euler'` (symplectic Euler, Euler-Cromer): v += a h, then x += v_new h. Order 1; symplectic.
 * - `'implicit-euler'`: v_new = v + a(x_new, v_new) h solved by Newton-Krylov. Order 1; stable on stiff springs; damps.
 * - `'rk2'`: Heun's method. Order 2.
 * - `'rk4'`: classical Runge-Kutta. Order 4; four force evaluations a step.
 * - `'position-verlet'`: Stormer-Verlet, drift-kick-drift. Order 2; symplectic.
 * - `'velocity-verlet'`: kick-drift-kick. Order 2; symplectic.
 * @category Integrators
 */
export const INTEGRATOR_NAMES = [
  'explicit-euler',
  'semi-implicit-euler',
  'implicit-euler',
  'rk2',
  'rk4',
  'position-verlet',
  'velocity-verlet',
] as const;

/**
 * One of `INTEGRATOR_NAMES`.
 * @category Integrators
 */
export type IntegratorName = (typeof INTEGRATOR_NAMES)[number];

/**
 * Global order of accuracy of each scheme on smooth problems (checked by the convergence tests).
 * @category Integrators
 */
export const INTEGRATOR_ORDER: Readonly<Record<IntegratorName, number>> = Object.freeze({
  'explicit-euler': 1,
  'semi-implicit-euler': 1,
  'implicit-euler': 1,
  rk2: 2,
  rk4: 4,
  'position-verlet': 2,
  'velocity-verlet': 2,
});
