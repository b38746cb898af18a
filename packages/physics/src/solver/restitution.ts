/**
 * The restitution stage's one definition, which every contact row family's restitution pass uses (ball
 * rows: solver/stages-kernel.ts restitutionTargets and restitutionRows; 2D manifold points:
 * solver/manifold-rows-2d.ts; 3D: solver/manifold-solve-3d.ts). After Box2D v3's b2ApplyRestitution,
 * run after the substeps' relax passes, with `restitutionIterations` sequential-impulse passes (coupled
 * bounces share the rebound, a small LCP) and Poisson's cap on each rebound (Stronge, Impact Mechanics,
 * 2000, ch. 2: at most e times the compression impulse, so an elastic pile creates no energy). The
 * functions follow the kernel rules (step/kernel-table.ts): kernels reach the first two as KERNEL_HELPERS 17 and 18.
 */

/**
 * The normal relative velocity (m/s, >= 0) a row must leave with, or -1 if it does not bounce: -e
 * `impact` when e > 0 and the row approached (`approach` < 0, m/s) faster than its threshold
 * (`elasticThreshold` when e >= 1, else `threshold`, both m/s >= 0). `impact` is the approach speed at
 * impact (m/s, < 0; the start-of-step speed where nothing better is known).
 * @category Collision
 */
export function restitutionTarget(e: number, approach: number, impact: number, threshold: number, elasticThreshold: number): number {
  return e > 0 && approach < -(e >= 1 ? elasticThreshold : threshold) ? -e * impact : -1;
}

/**
 * The most rebound impulse (N s) Poisson's hypothesis allows a bouncing row of restitution `e` (0..1)
 * that delivered `delivered` (N s, >= 0) over the step's substeps and needs `stop` (N s, >= 0) more to
 * stop its remaining approach: the stop plus e times the whole compression impulse.
 * @category Collision
 */
export function restitutionCap(e: number, delivered: number, stop: number): number {
  return stop + e * (delivered + stop);
}

/**
 * One sequential-impulse step of a restitution row: its accumulated impulse `acc` (N s) moved by `normalMass` (kg)
 * times the miss (`target` - `vn`, m/s), clamped to [0, `cap`] (N s, Infinity: no cap). Returns the new impulse.
 * @category Collision
 */
export function restitutionImpulse(acc: number, normalMass: number, vn: number, target: number, cap: number): number {
  const next = acc - normalMass * (vn - target);
  return next < 0 ? 0 : next > cap ? cap : next;
}
