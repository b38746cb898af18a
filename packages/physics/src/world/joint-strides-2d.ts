/**
 * The strides of the joint solver's packed arrays (world/joint-state-2d.ts): numbers a row, a point
 * link and a pin keep, and the impulses kept a joint for warm starting. A module of constants only,
 * folded into the code that reads them when the packages are built (scripts/build.mjs).
 */

/**
 * Floats per solver row (see the offsets in joints/layout-2d.ts).
 * @category Joints and ropes
 */
export const ROW_FLOATS = 40;
/**
 * Floats and integers per point link (see JointState.links).
 * @category Joints and ropes
 */
export const LINK_FLOATS = 6;
export const LINK_INTS = 3;
/**
 * Floats and integers per pin (see JointState.pins).
 * @category Joints and ropes
 */
export const PIN_FLOATS = 8;
export const PIN_INTS = 3;
/**
 * Integers per solver row: joint entity, solver index of A, of B, type.
 * @category Joints and ropes
 */
export const ROW_INTS = 4;
/**
 * Accumulated impulses kept per joint entity for warm starting (linear x, y, angular, spring, motor, lower, upper).
 * @category Joints and ropes
 */
export const IMPULSES = 7;
