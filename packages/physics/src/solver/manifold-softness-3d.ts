/**
 * This step's soft-constraint coefficients of the 3D manifold rows (Catto, "Soft Constraints", GDC 2011):
 * bias rate (1/s), mass scale and impulse scale of the normal rows (`soft`), and twice as stiff for a row
 * against infinite mass (`rigid`). Written by prepareManifolds3D (solver/manifold-prepare-3d.ts), read by
 * the solve (solver/manifold-solve-3d.ts).
 */
export const soft = new Float64Array(3),
  rigid = new Float64Array(3);
