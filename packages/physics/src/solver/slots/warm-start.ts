/**
 * The argument slots of warmStartTable (solver/warm-start-kernel.ts), filled by warmStartArguments
 * (collision/contacts.ts): where each array sits in the kernel's `A` and each number in its `P`,
 * imported as `WARM` (`A[WARM.NAME]`) by the kernel and by its caller. A module of numeric
 * constants only, which every build folds into the code (threads/worker-source.ts).
 */

// A: the arrays.
/**
 * The hash slots (Int32, written: row + 1, 0 empty; P[WARM.SLOT_COUNT] of them, a power of two above
 * twice the rows).
 */
export const SLOTS = 0;
/** ContactKind of each row (Uint8). */
export const KIND = 1;
/** Entity of body A of each row (Int32). */
export const A = 2;
/** Entity of body B (Int32). */
export const B = 3;
/** Feature id of each row (Int32). */
export const FEATURE = 4;
// P: the numbers.
/** Contact rows. */
export const ROWS = 0;
/** Hash slots. */
export const SLOT_COUNT = 1;
