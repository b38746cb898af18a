/**
 * The layout of an axis-aligned box stored in a packed array: its smallest corner, then its largest, a box
 * BOX3_STRIDE numbers (a mesh's triangle boxes, Mesh3D.bounds in shapes/mesh-3d.ts). A module of numeric
 * constants only, which every build folds into the code that reads it (scripts/build.mjs isConstantModule).
 */

/** The smallest x, m. */
export const BOX3_MIN_X = 0;
/** The smallest y, m. */
export const BOX3_MIN_Y = 1;
/** The smallest z, m. */
export const BOX3_MIN_Z = 2;
/** The largest x, m. */
export const BOX3_MAX_X = 3;
/** The largest y, m. */
export const BOX3_MAX_Y = 4;
/** The largest z, m. */
export const BOX3_MAX_Z = 5;
/** Numbers a box. */
export const BOX3_STRIDE = 6;
