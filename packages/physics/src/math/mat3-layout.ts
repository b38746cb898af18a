/**
 * The layout of a 3 x 3 matrix stored in a packed array, row-major: element (r, c) at offset 3 r + c from
 * the matrix's start, a matrix MAT3_STRIDE numbers (a collider's rotation in the 3D collision scratch,
 * collision/colliders-3d.ts, maps its shape frame to the world: its columns are the shape's axes). Column c
 * of a matrix at o is R[o + M00 + c], R[o + M10 + c], R[o + M20 + c]. A module of numeric constants only,
 * which every build folds into the code that reads it (scripts/build.mjs isConstantModule).
 */

/** Row 0, column 0. */
export const M00 = 0;
/** Row 0, column 1. */
export const M01 = 1;
/** Row 0, column 2. */
export const M02 = 2;
/** Row 1, column 0. */
export const M10 = 3;
/** Row 1, column 1. */
export const M11 = 4;
/** Row 1, column 2. */
export const M12 = 5;
/** Row 2, column 0. */
export const M20 = 6;
/** Row 2, column 1. */
export const M21 = 7;
/** Row 2, column 2. */
export const M22 = 8;
/** Numbers a matrix. */
export const MAT3_STRIDE = 9;
