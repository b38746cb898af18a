/**
 * The names and order of a step's stages: data at the bottom of the package, read by the world's
 * context (world/options.ts) and by the default pipeline's assembly (step/stages.ts).
 */

/**
 * The stages of a step, in order (docs/architecture.md, "The step"):
 * 1. `spawn`: waking, then lifetimes and emitters (once per step);
 * 2. `clearForces`: zero the force and torque accumulators;
 * 3. `forces`: one system per force law, user forces too;
 * 4. `integrate`: the world's integration scheme (multi-stage schemes re-run 2 and 3 at trial states),
 *    then the exact decay of drag and damping too stiff to be forces this step (forces/dissipation.ts);
 * 5. `collide`: broadphase, narrowphase (balls; then shapes: collision/shapes-2d.ts, 3D shapes: collision/shapes-3d.ts), contact solver (impulses, restitution, friction, position correction);
 * 6. `constraints`: position-based links (cloth);
 * 7. `finalize`: sleeping islands (once per step).
 * Stages 2 to 6 run once per substep.
 * @category World and step
 */
export const STAGES = ['spawn', 'clearForces', 'forces', 'integrate', 'collide', 'constraints', 'finalize'] as const;

/**
 * One of `STAGES`.
 * @category World and step
 */
export type StageName = (typeof STAGES)[number];

/**
 * The stages that run once per substep, in order.
 * @category World and step
 */
export const SUBSTEP_STAGES: readonly StageName[] = ['clearForces', 'forces', 'integrate', 'collide', 'constraints'];
