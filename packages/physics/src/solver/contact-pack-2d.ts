/**
 * The 2D ball contacts' soft-step rows (solver/contact-solver.ts) packed for the coloured solve on the world's
 * threads (solver/coloring.ts): one row of `PACK_STRIDE` numbers a contact in a single shared
 * Float64Array, colour by colour (Box2D v3 keeps its contact constraints packed the same way). Rows
 * that can do nothing (no mass to move, no impulse to warm start: the impact stage took them out) are
 * left out. The one-thread solve keeps the contact buffer's own arrays: packing them for it measured
 * no faster (20,000 balls, 8 passes over 52,000 rows: 115 ms packed vs 113 ms not, load 16).
 *
 * A row holds only what the passes read or write. Its two bodies' solver state offsets live beside
 * the pack in an Int32 array (`pair`, two a row), and the impulse delivered over the substeps and the
 * row's place in the contact buffer in arrays of their own (`tot`, `row`): the passes stream the pack
 * once a colour, and every number a row carries costs memory traffic on every pass (solver/coloring-kernel.ts).
 */

/**
 * Numbers a packed row: 0 nx, 1 ny, 2 ra, 3 rb (m), 4 start separation (m), 5 normal mass,
 * 6 tangent mass (kg), 7 friction bound, 8 normal impulse, 9 tangent impulse (N s), 10 1 if A has
 * infinite mass, 11 largest normal impulse of a solve pass (N s).
 * @category Collision
 */
export const PACK_STRIDE = 12;
