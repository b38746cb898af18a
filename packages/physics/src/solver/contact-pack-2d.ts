/**
 * The 2D ball contacts' soft-step rows (solver/contact-solver.ts) packed for the coloured solve on the world's
 * threads (solver/coloring.ts): one row of `PACK_STRIDE` numbers a contact in a single shared
 * Float64Array, colour by colour (Box2D v3 keeps its contact constraints packed the same way). Rows
 * that can do nothing (no mass to move, no impulse to warm start: the impact stage took them out) are
 * left out. The one-thread solve keeps the contact buffer's own arrays: packing them for it gains
 * nothing.
 *
 * A row holds only what the passes read or write. Its two bodies' solver state offsets live beside
 * the pack in an Int32 array (`pair`, two a row), and the impulse delivered over the substeps and the
 * row's place in the contact buffer in arrays of their own (`tot`, `row`): the passes stream the pack
 * once a colour, and every number a row carries costs memory traffic on every pass (solver/coloring-kernel.ts).
 */

/** The contact normal x, from A to B (a unit vector). */
export const PK_NX = 0;
/** The contact normal y. */
export const PK_NY = 1;
/** A's radius along the normal to the contact point, m. */
export const PK_RA = 2;
/** B's radius along the normal to the contact point, m. */
export const PK_RB = 3;
/** The separation at the start of the step, m (negative: overlap). */
export const PK_SEPARATION = 4;
/** The normal effective mass, kg. */
export const PK_NORMAL_MASS = 5;
/** The tangent effective mass, kg. */
export const PK_TANGENT_MASS = 6;
/** The friction bound (the friction coefficient in use: static while the contact sticks, else kinetic). */
export const PK_FRICTION = 7;
/** The accumulated normal impulse, N s. */
export const PK_NORMAL_IMPULSE = 8;
/** The accumulated tangent impulse, N s. */
export const PK_TANGENT_IMPULSE = 9;
/** 1 if either body has infinite mass (inverse mass 0 in the solver: static, sleeping or kinematic; solver/rigid-partner.ts), else 0. */
export const PK_A_FIXED = 10;
/** The largest normal impulse of a solve pass, N s (for restitution). */
export const PK_MAX_NORMAL_IMPULSE = 11;
/**
 * Numbers a packed row (the PK_ offsets above).
 * @category Collision
 */
export const PACK_STRIDE = 12;
