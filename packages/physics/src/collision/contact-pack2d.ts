/**
 * The 2D ball contacts' soft-step rows (solver.ts) packed for the coloured solve on the world's
 * threads (contact-colors.ts): one row of `PACK_STRIDE` numbers a contact in a single shared
 * Float64Array, colour by colour (Box2D v3 keeps its contact constraints packed the same way). Rows
 * that can do nothing (no mass to move, no impulse to warm start: the impact stage took them out) are
 * left out. The one-thread solve keeps the contact buffer's own arrays: packing them for it measured
 * no faster (20,000 balls, 8 passes over 52,000 rows: 115 ms packed vs 113 ms not, load 16).
 */

import type { ContactBuffer } from './contacts.js';

/**
 * Numbers a packed row: 0 body A's offset in the solver state (solver index x 8), 1 body B's,
 * 2 nx, 3 ny, 4 ra, 5 rb (m), 6 start separation (m), 7 normal mass, 8 tangent mass (kg), 9 friction
 * bound, 10 normal impulse, 11 tangent impulse (N s), 12 1 if A has infinite mass, 13 largest normal
 * impulse of a solve pass (N s), 14 normal impulse delivered over the substeps (N s), 15 the row in
 * the contact buffer.
 */
export const PACK_STRIDE = 16;

/**
 * Writes the packed rows' impulses back to `buf`: normal and tangent impulse, the largest normal
 * impulse of a pass, and the substeps' delivered normal impulse (into totalNormalImpulse).
 */
export function unpackContacts2D(buf: ContactBuffer, pack: Float64Array, count: number): void {
  const LN = buf.normalImpulse, LT = buf.tangentImpulse1, MAXN = buf.maxNormalImpulse, TOT = buf.totalNormalImpulse;
  for (let k = 0; k < count; k++) {
    const o = k * PACK_STRIDE, i = pack[o + 15]!;
    LN[i] = pack[o + 10]!; LT[i] = pack[o + 11]!; MAXN[i] = pack[o + 13]!; TOT[i] = pack[o + 14]!;
  }
}
