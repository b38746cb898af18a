/**
 * The layout of the 3D narrowphase's segment scratch (`seg`, collision/narrowphase/segments-3d.ts): the
 * segment of a sphere or capsule (its end points; a sphere's two are its centre), written by
 * segmentOf at an offset, the first at 0 and the second at SEG_STRIDE. A module of numeric constants
 * only, which every build folds into the code that reads it (scripts/build.mjs isConstantModule).
 */

/** The first end point x, m (world). */
export const SEG_P0X = 0;
/** The first end point y, m. */
export const SEG_P0Y = 1;
/** The first end point z, m. */
export const SEG_P0Z = 2;
/** The second end point x, m. */
export const SEG_P1X = 3;
/** The second end point y, m. */
export const SEG_P1Y = 4;
/** The second end point z, m. */
export const SEG_P1Z = 5;
/** Numbers a segment. */
export const SEG_STRIDE = 6;
