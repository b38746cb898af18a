/**
 * The argument slots of treeForces (forces/barnes-hut/gather.ts), filled by treeFieldsWith
 * (forces/barnes-hut/tree.ts): where each array sits in the kernel's `A`, imported as `TREE_FORCES`
 * (`A[TREE_FORCES.FX]`) by the kernel and by its caller. The kernel reads no number. A module of
 * numeric constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays.
/** Force x, N (Float64, by entity, added to). */
export const FX = 0;
/** Force y, N. */
export const FY = 1;
/** Force z, N. */
export const FZ = 2;
/** The slot of each input body (Int32). */
export const SLOT = 3;
/** Bodies' mass in tree order, kg (Float64). */
export const MASS = 4;
/** The field x at each slot, m/s^2 (Float64, tree order). */
export const AX = 5;
/** The field y at each slot, m/s^2. */
export const AY = 6;
/** The field z at each slot, m/s^2. */
export const AZ = 7;
