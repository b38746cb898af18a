/**
 * The argument slots of warmStartTable (solver/warm-start-kernel.ts), which collision/contacts.ts
 * `warmStartArguments` fills. A module of numeric constants only, which every build folds into the
 * code (threads/worker-source.ts).
 */

// warmStartTable: A.
/** The hash slots (Int32, written: row + 1, 0 empty; P[WS_SLOT_COUNT] of them, a power of two above twice the rows). */
export const WS_SLOTS = 0;
/** ContactKind of each row (Uint8). */
export const WS_KIND = 1;
/** Entity of body A of each row (Int32). */
export const WS_A = 2;
/** Entity of body B (Int32). */
export const WS_B = 3;
/** Feature id of each row (Int32). */
export const WS_FEATURE = 4;
// warmStartTable: P.
/** Contact rows. */
export const WS_ROWS = 0;
/** Hash slots. */
export const WS_SLOT_COUNT = 1;
