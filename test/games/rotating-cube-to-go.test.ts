/**
 * rotating-cube's "best: N more moves" count (roll-puzzle.ts `movePar`, read after every slide and
 * roll) is one count over the whole room: one roll changes it by at most one, wherever the cube rests.
 * Before, a cell beyond the tiles' edge counted as "away", where rolls lead nowhere: slid two cells
 * from a pad the count stayed at 4, and the next roll onto the edge showed 2.
 */

import { describe, expect, it } from 'vitest';
import { GRID_IDENTITY, type GridOrientation, movePar, ROLL_DIRECTIONS, rollOrientation } from '../../games/rotating-cube/roll-puzzle';
import { CELL_REACH, PAD_COUNT, padLayout, padPuzzle } from '../../games/rotating-cube/scene';

/** The 24 orientations of the grid cube, reached from the identity by rolls. */
function allOrientations(): GridOrientation[] {
  const seen = new Map<string, GridOrientation>([[GRID_IDENTITY.join(), GRID_IDENTITY]]);
  let frontier: GridOrientation[] = [GRID_IDENTITY];
  while (frontier.length > 0) {
    const next: GridOrientation[] = [];
    for (const o of frontier)
      for (const d of ROLL_DIRECTIONS) {
        const q = rollOrientation(o, d);
        if (!seen.has(q.join())) {
          seen.set(q.join(), q);
          next.push(q);
        }
      }
    frontier = next;
  }
  return [...seen.values()];
}

/** Cell step (x, z) of a roll along each of ROLL_DIRECTIONS (+x, -x, +z, -z). */
const STEPS: Record<number, [number, number]> = { 0: [1, 0], 1: [-1, 0], 4: [0, 1], 5: [0, -1] };

describe('rotating-cube moves to go', () => {
  it('a roll between two cells of the room changes the count by at most one (every pad of 2 seeded rounds, every orientation)', () => {
    const orientations = allOrientations();
    expect(orientations).toHaveLength(24);
    let checked = 0;
    for (const seed of [1, 2]) {
      const layout = padLayout(seed);
      for (let k = 0; k < PAD_COUNT; k++) {
        const p = padPuzzle(layout, k);
        const fits = (i: number, j: number) => Math.abs(p.pad[0] + i) <= CELL_REACH + 1e-9 && Math.abs(p.pad[1] + j) <= CELL_REACH + 1e-9;
        // Cells two beyond the tiles' edge (bed + 3), where a slide stops and a roll or two leads in.
        const r = p.bed + 3;
        for (let i = -r; i <= r; i++)
          for (let j = -r; j <= r; j++) {
            if (!fits(i, j)) continue;
            for (const o of orientations) {
              const here = movePar(p, [i, j], o);
              for (const d of ROLL_DIRECTIONS) {
                const [si, sj] = STEPS[d]!;
                if (!fits(i + si, j + sj)) continue;
                const there = movePar(p, [i + si, j + sj], rollOrientation(o, d));
                // The roll is a move: from here it takes at most one more than from where it lands.
                expect(here, `seed ${seed} pad ${k} cell ${i},${j} roll ${d}`).toBeLessThanOrEqual(there + 1);
                checked++;
              }
            }
          }
      }
    }
    expect(checked).toBeGreaterThan(1000);
  });
});
