/**
 * The argument slots of ballContacts (collision/narrowphase/balls-kernel.ts), filled by
 * collision/narrowphase/balls-threads.ts: where each array sits in the kernel's `A` and each number
 * in its `P`, imported as `CONTACT` (`A[CONTACT.NAME]`) by the kernel and by its caller. A module
 * of numeric constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A range's output arrays, each at A[OUT + OUT_FIELDS p + slot] for range p.
/** ContactKind of each contact (Uint8). */
export const OUT_KIND = 0;
/** Contact normal x, from A to B. */
export const OUT_NX = 1;
/** Contact normal y. */
export const OUT_NY = 2;
/** Contact normal z. */
export const OUT_NZ = 3;
/** Separation at the start of the step, m. */
export const OUT_SEPARATION = 4;
/** A's radius, m. */
export const OUT_RA = 5;
/** B's radius, m. */
export const OUT_RB = 6;
/** Entity of body A (Int32). */
export const OUT_A = 7;
/** Entity of body B (Int32). */
export const OUT_B = 8;
/** Feature id (Int32). */
export const OUT_FEATURE = 9;
/** Output arrays a range. */
export const OUT_FIELDS = 10;
// A: the arrays.
/** Body A of each ball pair (Int32, entity). */
export const PAIR_A = 0;
/** Body B of each ball pair (Int32, entity). */
export const PAIR_B = 1;
/** PreviousPosition x, m (by entity: where the ball was at the start of the step). */
export const OX = 2;
/** PreviousPosition y, m. */
export const OY = 3;
/** PreviousPosition z, m (not read in 2D). */
export const OZ = 4;
/** Velocity x, m/s (by entity). */
export const VX = 5;
/** Velocity y, m/s. */
export const VY = 6;
/** Velocity z, m/s (not read in 2D). */
export const VZ = 7;
/** Ball radius, m (by entity). */
export const RADIUS = 8;
/** The collision state's body type (Uint8, by entity). */
export const BODY_TYPE = 9;
/** The contacts each range made (Int32, at its `part`; -1: its arrays were too small), written. */
export const COUNTS = 10;
/** The first range's output arrays (OUT_KIND .. OUT_FEATURE); range p's start at OUT + OUT_FIELDS p. */
export const OUT = 11;
// P: the numbers.
/** The step h, s. */
export const H = 0;
/** The speculative distance, m: a pair closer than this at the start of the step makes a contact. */
export const SPECULATIVE = 1;
/** BodyType.Static. */
export const STATIC = 2;
/** ContactKind.Ball. */
export const BALL = 3;
/** ContactKind.StaticBall. */
export const STATIC_BALL = 4;
/** Rows each output array of a range p > 0 holds. */
export const CAPACITY = 5;
/** Rows range 0's output arrays (the contact buffer's own) hold. */
export const CAPACITY_0 = 6;
/** 2 or 3 (2: z is not read; a 2D world's z stores hold 0, so the arithmetic is the same). */
export const DIMENSIONS = 7;
/** The row range 0 writes its first contact to (the ranges after it start at row 0). */
export const FIRST_ROW = 8;
/** Where the skip flags (Uint8, one a pair: 1 when a joint keeps the pair apart) sit in A; -1: none. */
export const SKIP = 9;
