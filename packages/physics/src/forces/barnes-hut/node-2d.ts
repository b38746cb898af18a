/**
 * The layout of a 2D node of the Barnes-Hut tree (GravityTree.node, forces/barnes-hut/tree-store.ts):
 * node k's moments at k * STRIDE, about the cell's centre of mass c (forces/barnes-hut/tree.ts), written
 * by treeMoments (forces/barnes-hut/moments.ts) and read by the walk (walk-kernel.ts) and treeField.
 * Imported as `N2` (`F[o + N2.MASS]`). A module of numeric constants only, which every build folds into
 * the code that reads it, the thread kernels included (threads/worker-source.ts).
 */

/** Centre of mass x, m. */
export const CX = 0;
/** Centre of mass y, m. */
export const CY = 1;
/** Mass M of the cell's bodies, kg. */
export const MASS = 2;
/** Second moment S_xx = sum m (x - c_x)^2, kg m^2. */
export const SXX = 3;
/** Second moment S_xy = sum m (x - c_x)(y - c_y), kg m^2. */
export const SXY = 4;
/** Second moment S_yy = sum m (y - c_y)^2, kg m^2. */
export const SYY = 5;
/** b_max: a bound on the distance from c to any of the cell's bodies, m. */
export const RADIUS = 6;
/** Third moment T_xxx = sum m (x - c_x)^3, kg m^3. */
export const TXXX = 7;
/** Third moment T_xxy = sum m (x - c_x)^2 (y - c_y), kg m^3. */
export const TXXY = 8;
/** Third moment T_xyy = sum m (x - c_x)(y - c_y)^2, kg m^3. */
export const TXYY = 9;
/** Third moment T_yyy = sum m (y - c_y)^3, kg m^3. */
export const TYYY = 10;
/** Unused (written 0), so a node's numbers fill STRIDE. */
export const PAD = 11;
/** Numbers a node. */
export const STRIDE = 12;
