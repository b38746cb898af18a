/**
 * The argument slots of ballPairs (collision/broadphase/grid-pairs-kernel.ts), filled by
 * collision/broadphase/grid-pairs.ts: where each array sits in the kernel's `A` and each number in
 * its `P`, imported as `PAIRS` (`A[PAIRS.NAME]`) by the kernel and by its caller. A module of
 * numeric constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A range's output arrays, each at A[OUT + OUT_FIELDS p + slot] for range p.
/** First entity of each pair, the smaller id (Int32). */
export const OUT_A = 0;
/** Second entity of each pair (Int32). */
export const OUT_B = 1;
/**
 * The sleeping balls the range met by a moving or kinematic ball, in the order met (Int32; a ball
 * may be named more than once).
 */
export const OUT_WAKE = 2;
/** Output arrays a range. */
export const OUT_FIELDS = 3;
/** Where the wake requests' counts start in A[PAIRS.COUNTS]. */
export const WAKE_COUNTS = 16;
// A: the arrays.
/** The grid bodies in grid order (Int32, entity). */
export const SORTED = 0;
/** Each body's cell x (Int32, by entity). */
export const CELL_X = 1;
/** Each body's cell y (Int32). */
export const CELL_Y = 2;
/** Each body's cell z (Int32). */
export const CELL_Z = 3;
/** Where each bucket's bodies start in the sorted list (Int32). */
export const BUCKET_START = 4;
/** PreviousPosition x, m (by entity). */
export const OX = 5;
/** PreviousPosition y, m. */
export const OY = 6;
/** PreviousPosition z, m. */
export const OZ = 7;
/** Ball radius, m (by entity). */
export const RADIUS = 8;
/** Each body's margin, m (by entity). */
export const MARGIN = 9;
/** The body type as the pass began (Uint8, by entity: 0 dynamic, 1 kinematic, 2 static, 3 sleeping). */
export const BODY_TYPE = 10;
/**
 * At `part` the pairs the range found, at PAIRS.WAKE_COUNTS + `part` its wake requests (Int32; -1: a
 * buffer was too small), written.
 */
export const COUNTS = 11;
/** How long each body has rested, s (by entity; 0: it moves). */
export const REST_TIME = 12;
/** The first range's output arrays; range p's at PAIRS.OUT + PAIRS.OUT_FIELDS p. */
export const OUT = 13;
// P: the numbers.
/** The hash mask (buckets - 1). */
export const HASH_MASK = 0;
/** 2 or 3. */
export const DIMENSIONS = 1;
/** Rows each output array of a range holds. */
export const CAPACITY = 2;
/** A dense grid's span along x, cells (0: the hash). */
export const SPAN_X = 3;
/** A dense grid's span of an x-z layer, cells. */
export const SPAN_XZ = 4;
/**
 * A dense grid's origin cell x (GridScratch in collision/state.ts: bucket (cx - ox) + (cz - oz)
 * spanX + (oy - cy) spanXZ).
 */
export const ORIGIN_X = 5;
/** A dense grid's origin cell y. */
export const ORIGIN_Y = 6;
/** A dense grid's origin cell z. */
export const ORIGIN_Z = 7;
