/** The impact stage's scratch (solver/impacts.ts; its row of `CollisionState.bodyImpact` is laid out in body-state-layout.ts): its per-row marks and lists, and the arrays that carry doubles to its helpers. */

/**
 * Scratch of the impact stage (not world state):
 * - `loaded`: per contact row, 1 if it carried a load (`carriesLoad`) at the start of `applyImpacts`,
 *   else 0, read by `separateImpactedBodies` within the same call;
 * - `idle`: the indices of the contact rows still inactive, in row order (`separateImpactedBodies`);
 * - the rows the last `applyImpacts` changed a value of that the soft substeps read (normal, start
 *   separation), each once, in the order first changed: `changedRows[0 .. changedCount - 1]`, with
 *   `changedMark` (1: listed) for the rows of that call; and the impacted rows it takes out of the
 *   soft substeps (`releasedRows[0 .. releasedCount - 1]`), whose masses and impulses
 *   `releaseImpactedRows` zeroes. Read through impactChangedRows.
 */
export const impactScratch = {
  loaded: new Uint8Array(256),
  idle: new Int32Array(256),
  changedRows: new Int32Array(256),
  changedMark: new Uint8Array(256),
  releasedRows: new Int32Array(256),
  changedCount: 0,
  releasedCount: 0,
};

/**
 * Scratch of one `applyImpacts` call: [resting, gh, reach] (m/s, m/s, s; see applyImpacts and
 * separateImpactedBodies), read by the helpers it calls. Doubles reach the helpers through this and
 * `sweepIO`, not as arguments: V8 boxes (allocates) every double passed to or returned from a call it
 * does not inline, which was most of what the step allocated in a large pile. Not world state.
 */
export const impactScalars = new Float64Array(3);

/**
 * Scratch of `sweep`: its arguments r (x, y, z), u (x, y, z), R and span, then its result t (slot 8).
 * Not world state.
 */
export const sweepIO = new Float64Array(9);

/** Lists row i as changed by the impact stage (once). */
export function markChanged(i: number): void {
  if (impactScratch.changedMark[i] === 1) return;
  impactScratch.changedMark[i] = 1;
  impactScratch.changedRows[impactScratch.changedCount++] = i;
}

/**
 * The rows the last `applyImpacts` changed a value of that the soft substeps read (the normal of an
 * impacted row, a start separation that took in corrections or a spare gap; the rows
 * `releaseImpactedRows` zeroes are among them): rows[0 .. count - 1], each once. A coloured solve whose
 * rows were packed while the stage ran packs these again (solver/coloring.ts). Valid until the next call.
 * @category Collision
 */
export function impactChangedRows(): { rows: Int32Array; count: number } {
  return { rows: impactScratch.changedRows, count: impactScratch.changedCount };
}
