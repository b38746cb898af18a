/**
 * The layout of a 3D node of the Barnes-Hut tree (GravityTree.node, forces/barnes-hut/tree-store.ts):
 * node k's moments at k * STRIDE, about the cell's centre of mass c (forces/barnes-hut/tree.ts), written
 * by treeMoments (forces/barnes-hut/moments.ts) and read by the walk (walk-kernel.ts) and treeField.
 * Imported as `N3` (`F[o + N3.MASS]`). A module of numeric constants only, which every build folds into
 * the code that reads it, the thread kernels included (threads/worker-source.ts).
 */

/** Centre of mass x, m. */
export const CX = 0;
/** Centre of mass y, m. */
export const CY = 1;
/** Centre of mass z, m. */
export const CZ = 2;
/** Mass M of the cell's bodies, kg. */
export const MASS = 3;
/** Second moment S_xx = sum m (x - c_x)^2, kg m^2. */
export const SXX = 4;
/** Second moment S_yy = sum m (y - c_y)^2, kg m^2. */
export const SYY = 5;
/** Second moment S_zz = sum m (z - c_z)^2, kg m^2. */
export const SZZ = 6;
/** Second moment S_xy = sum m (x - c_x)(y - c_y), kg m^2. */
export const SXY = 7;
/** Second moment S_xz = sum m (x - c_x)(z - c_z), kg m^2. */
export const SXZ = 8;
/** Second moment S_yz = sum m (y - c_y)(z - c_z), kg m^2. */
export const SYZ = 9;
/** b_max: a bound on the distance from c to any of the cell's bodies, m. */
export const RADIUS = 10;
/** Unused (written 0), so a node's numbers fill STRIDE. */
export const PAD = 11;
/** Numbers a node. */
export const STRIDE = 12;
