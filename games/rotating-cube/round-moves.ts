/**
 * The room's move count against the stars still in reach, for the status row. The count runs over
 * the whole round (every pad's moves against the sum of the lit pads' pars), so the words say
 * "round": a bare "moves 1 of 5" next to the lit pad's "3 moves to go" read as the pad's own count.
 * Pure (no DOM, no three.js).
 */
import { starText } from './round-end';
import { PAR_SLACK } from './scene';

/**
 * The round's moves against the stars still in reach: "round: 3 of 8 moves for ★★★" (`short`, a
 * phone's narrow row: "round 3/8 ★★★"), where ★★★ takes par + PAR_SLACK[0] moves or fewer and ★★
 * par + PAR_SLACK[1]; past both, "round: 24 moves ★☆☆" ("round 24 ★☆☆").
 * @throws RangeError if `moves` or `par` is not an integer >= 0.
 */
export function roundMovesText(moves: number, par: number, short = false): string {
  if (!Number.isInteger(moves) || moves < 0) throw new RangeError(`roundMovesText: moves must be an integer >= 0, got ${moves}`);
  if (!Number.isInteger(par) || par < 0) throw new RangeError(`roundMovesText: par must be an integer >= 0, got ${par}`);
  for (const [i, slack] of PAR_SLACK.entries())
    if (moves <= par + slack)
      return short ? `round ${moves}/${par + slack} ${starText(3 - i)}` : `round: ${moves} of ${par + slack} moves for ${starText(3 - i)}`;
  return short ? `round ${moves} ${starText(1)}` : `round: ${moves} moves ${starText(1)}`;
}

/**
 * The words a pad's pop adds after "Pad 2 of 5 ✓" for the moves it took against its best (`par`,
 * the fewest from where the cube was when the pad lit): " · Perfect!" for any optimal solution (one
 * label whatever the par, so a best of 2 reads the same as a best of 1), else " · 4 moves, best 2".
 * @throws RangeError if `moves` or `par` is not an integer >= 0.
 */
export function padResultText(moves: number, par: number): string {
  if (!Number.isInteger(moves) || moves < 0) throw new RangeError(`padResultText: moves must be an integer >= 0, got ${moves}`);
  if (!Number.isInteger(par) || par < 0) throw new RangeError(`padResultText: par must be an integer >= 0, got ${par}`);
  return moves <= par ? ' · Perfect!' : ` · ${moves} moves, best ${par}`;
}
