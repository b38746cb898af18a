/**
 * The layouts of the box narrowphase's argument records (collision/narrowphase/box-box-3d.ts): `boxArgs`,
 * the numbers of box against box (two boxes, each its centre and half extents, then the margin), and
 * `planeArgs`, those of plane against box. A hot caller writes them there instead of passing them, since
 * V8 boxes every double passed to a call it does not inline. A module of numeric constants only, which
 * every build folds into the code that reads it (scripts/build.mjs isConstantModule).
 */

// boxArgs: box A's six numbers at BOX_A, box B's at BOX_B, then the margin.
/** Where box A's numbers start. */
export const BOX_A = 0;
/** Where box B's numbers start. */
export const BOX_B = 6;
/** A box's centre x, m (world), from its start. */
export const BOX_CX = 0;
/** A box's centre y, m. */
export const BOX_CY = 1;
/** A box's centre z, m. */
export const BOX_CZ = 2;
/** A box's half extent along its first axis, m. */
export const BOX_HX = 3;
/** A box's half extent along its second axis, m. */
export const BOX_HY = 4;
/** A box's half extent along its third axis, m. */
export const BOX_HZ = 5;
/** The margin: points farther apart than this are dropped, m. */
export const BOX_MARGIN = 12;
/** Numbers in boxArgs. */
export const BOX_ARGS = 13;

// planeArgs.
/** The plane's unit normal x (out of the plane, towards the box). */
export const PLANE_NX = 0;
/** The plane's unit normal y. */
export const PLANE_NY = 1;
/** The plane's unit normal z. */
export const PLANE_NZ = 2;
/** The plane's offset d (n . p = d on the plane), m. */
export const PLANE_D = 3;
/** The box's centre x, m (world). */
export const PLANE_BOX_CX = 4;
/** The box's centre y, m. */
export const PLANE_BOX_CY = 5;
/** The box's centre z, m. */
export const PLANE_BOX_CZ = 6;
/** The box's half extent along its first axis, m. */
export const PLANE_BOX_HX = 7;
/** The box's half extent along its second axis, m. */
export const PLANE_BOX_HY = 8;
/** The box's half extent along its third axis, m. */
export const PLANE_BOX_HZ = 9;
/** The margin: points farther from the plane than this are dropped, m. */
export const PLANE_MARGIN = 10;
/** Numbers in planeArgs. */
export const PLANE_ARGS = 11;
