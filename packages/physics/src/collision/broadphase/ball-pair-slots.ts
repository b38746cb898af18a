/**
 * The argument slots of ballPairs (collision/broadphase/grid-pairs-kernel.ts): where each array sits in
 * its `A` and each number in its `P`, for the kernel and its caller (collision/broadphase/grid-pairs.ts).
 * A module of numeric constants only, which every build folds into the code (threads/worker-source.ts).
 */

// The output arrays of one range, at BP_OUT + BP_OUT_FIELDS p + slot.
/** First entity of each pair, the smaller id (Int32). */
export const BP_OUT_A = 0;
/** Second entity of each pair (Int32). */
export const BP_OUT_B = 1;
/** The sleeping balls the range met by a moving or kinematic ball, in the order met (Int32; a ball may be named more than once). */
export const BP_OUT_WAKE = 2;
/** Output arrays a range. */
export const BP_OUT_FIELDS = 3;
/** Where the wake requests' counts start in A[BP_COUNTS]. */
export const BP_WAKE_COUNTS = 16;
// ballPairs: A.
/** The grid bodies in grid order (Int32, entity). */
export const BP_SORTED = 0;
/** Each body's cell x (Int32, by entity). */
export const BP_CELL_X = 1;
/** Each body's cell y (Int32). */
export const BP_CELL_Y = 2;
/** Each body's cell z (Int32). */
export const BP_CELL_Z = 3;
/** Where each bucket's bodies start in the sorted list (Int32). */
export const BP_BUCKET_START = 4;
/** PreviousPosition x, m (by entity). */
export const BP_OX = 5;
/** PreviousPosition y, m. */
export const BP_OY = 6;
/** PreviousPosition z, m. */
export const BP_OZ = 7;
/** Ball radius, m (by entity). */
export const BP_RADIUS = 8;
/** Each body's margin, m (by entity). */
export const BP_MARGIN = 9;
/** The body type as the pass began (Uint8, by entity: 0 dynamic, 1 kinematic, 2 static, 3 sleeping). */
export const BP_BODY_TYPE = 10;
/** At `part` the pairs the range found, at BP_WAKE_COUNTS + `part` its wake requests (Int32; -1: a buffer was too small), written. */
export const BP_COUNTS = 11;
/** How long each body has rested, s (by entity; 0: it moves). */
export const BP_REST_TIME = 12;
/** The first range's output arrays; range p's at BP_OUT + BP_OUT_FIELDS p. */
export const BP_OUT = 13;
// ballPairs: P.
/** The hash mask (buckets - 1). */
export const BP_HASH_MASK = 0;
/** 2 or 3. */
export const BP_DIMENSIONS = 1;
/** Rows each output array of a range holds. */
export const BP_CAPACITY = 2;
/** A dense grid's span along x, cells (0: the hash). */
export const BP_SPAN_X = 3;
/** A dense grid's span of an x-z layer, cells. */
export const BP_SPAN_XZ = 4;
/** A dense grid's origin cell x (GridScratch in collision/state.ts: bucket (cx - ox) + (cz - oz) spanX + (oy - cy) spanXZ). */
export const BP_ORIGIN_X = 5;
/** A dense grid's origin cell y. */
export const BP_ORIGIN_Y = 6;
/** A dense grid's origin cell z. */
export const BP_ORIGIN_Z = 7;
