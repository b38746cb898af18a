/**
 * The argument slots of ballContacts (collision/narrowphase/balls-kernel.ts): where each array sits in
 * its `A` and each number in its `P`, for the kernel and its caller (collision/narrowphase/balls-threads.ts).
 * A module of numeric constants only, which every build folds into the code (threads/worker-source.ts).
 */

// The output arrays of one range, at BC_OUT + BC_OUT_FIELDS p + slot.
/** ContactKind of each contact (Uint8). */
export const BC_OUT_KIND = 0;
/** Contact normal x, from A to B. */
export const BC_OUT_NX = 1;
/** Contact normal y. */
export const BC_OUT_NY = 2;
/** Contact normal z. */
export const BC_OUT_NZ = 3;
/** Separation at the start of the step, m. */
export const BC_OUT_SEPARATION = 4;
/** A's radius, m. */
export const BC_OUT_RA = 5;
/** B's radius, m. */
export const BC_OUT_RB = 6;
/** Entity of body A (Int32). */
export const BC_OUT_A = 7;
/** Entity of body B (Int32). */
export const BC_OUT_B = 8;
/** Feature id (Int32). */
export const BC_OUT_FEATURE = 9;
/** Output arrays a range. */
export const BC_OUT_FIELDS = 10;
// ballContacts: A.
/** Body A of each ball pair (Int32, entity). */
export const BC_PAIR_A = 0;
/** Body B of each ball pair (Int32, entity). */
export const BC_PAIR_B = 1;
/** PreviousPosition x, m (by entity: where the ball was at the start of the step). */
export const BC_OX = 2;
/** PreviousPosition y, m. */
export const BC_OY = 3;
/** PreviousPosition z, m (not read in 2D). */
export const BC_OZ = 4;
/** Velocity x, m/s (by entity). */
export const BC_VX = 5;
/** Velocity y, m/s. */
export const BC_VY = 6;
/** Velocity z, m/s (not read in 2D). */
export const BC_VZ = 7;
/** Ball radius, m (by entity). */
export const BC_RADIUS = 8;
/** The collision state's body type (Uint8, by entity). */
export const BC_BODY_TYPE = 9;
/** The contacts each range made (Int32, at its `part`; -1: its arrays were too small), written. */
export const BC_COUNTS = 10;
/** The first range's output arrays (BC_OUT_ kind .. feature); range p's start at BC_OUT + BC_OUT_FIELDS p. */
export const BC_OUT = 11;
// ballContacts: P.
/** The step h, s. */
export const BC_H = 0;
/** The speculative distance, m: a pair closer than this at the start of the step makes a contact. */
export const BC_SPECULATIVE = 1;
/** BodyType.Static. */
export const BC_STATIC = 2;
/** ContactKind.Ball. */
export const BC_BALL = 3;
/** ContactKind.StaticBall. */
export const BC_STATIC_BALL = 4;
/** Rows each output array of a range p > 0 holds. */
export const BC_CAPACITY = 5;
/** Rows range 0's output arrays (the contact buffer's own) hold. */
export const BC_CAPACITY_0 = 6;
/** 2 or 3 (2: z is not read; a 2D world's z stores hold 0, so the arithmetic is the same). */
export const BC_DIMENSIONS = 7;
/** The row range 0 writes its first contact to (the ranges after it start at row 0). */
export const BC_FIRST_ROW = 8;
/** Where the skip flags (Uint8, one a pair: 1 when a joint keeps the pair apart) sit in A; -1: none. */
export const BC_SKIP = 9;
