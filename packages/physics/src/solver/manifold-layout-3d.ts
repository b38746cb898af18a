/** The layout of the 3D manifold rows' per-step arrays (solver/manifold-rows-3d.ts), and the step's soft-constraint coefficients that preparation writes and the solve reads. */

/**
 * Numbers a point keeps in `jacobians` (r_A x n, r_B x n) and in `jacobiansInv` (I_A^-1 (r_A x n),
 * I_B^-1 (r_B x n), only for a manifold whose bodies are not isotropic: a pile of cubes streams the crosses alone).
 */
export const JAC = 6;
/**
 * Numbers a manifold keeps in `frictionJacobians`: r_A x u, r_B x u of the friction anchor for u = t1, t2
 * (at 6 d, d = 0, 1); and in `frictionInv` (not isotropic manifolds only, FI a row): I_A^-1 (r_A x u),
 * I_B^-1 (r_B x u) in the same order, then I_A^-1 n, I_B^-1 n (at TWIST) for the twist row.
 */
export const FJ = 12;
export const FI = 18;
export const TWIST = 12;

/**
 * This step's soft-constraint coefficients (Catto, "Soft Constraints", GDC 2011): bias rate (1/s), mass
 * scale and impulse scale of the normal rows (`soft`), and twice as stiff for a row against infinite
 * mass (`rigid`).
 * Written by prepareManifolds3D, read by the solve.
 */
export const soft = new Float64Array(3),
  rigid = new Float64Array(3);
