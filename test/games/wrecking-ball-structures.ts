/** Test helper of the wrecking-ball node tests: a level's pieces grouped into its structures. */

/** Pieces grouped by their start centre (within 2.5 m of a group's first piece): the level's structures, in the order first met. */
export function groups<T extends { x0: number; z0: number }>(pieces: T[]): T[][] {
  const out: T[][] = [];
  for (const p of pieces) {
    const g = out.find((q) => Math.hypot(q[0]!.x0 - p.x0, q[0]!.z0 - p.z0) < 2.5);
    if (g) g.push(p);
    else out.push([p]);
  }
  return out;
}
