/**
 * Wrecking ball's status line while a level is played: the level's numbers (swings left, the three
 * stars' par, blocks down toward the clear target) and what the swing is doing. Pure, so the node
 * tests check it without a page.
 */

/** What the status line says while the level is played (not yet settling or cleared). */
export interface PlayStatus {
  /** The level, integer >= 1. */
  level: number;
  /** The total score, or null where the side column shows it (a large screen). */
  score: number | null;
  /** Swings left and the level's budget of them. */
  left: number;
  budget: number;
  /** Swings that clear the level for three stars. */
  par: number;
  /** Pieces down now, and how many clear the level (`clearTarget`). */
  fallen: number;
  target: number;
  /**
   * The rest, most pressing first, each with its leading ' · ' (the swing's phase, its result, out
   * of swings, how to steady the ball); '' where there is none.
   */
  extras: readonly string[];
}

/**
 * Most of `extras` a compact (phone) status line says: one. Its numbers take two of the three
 * lines it is kept to (see main.ts `status`), the one thing more the third; with all of them, a
 * swing's phase, its result and the steadying tip ran to four and five lines, more than the bar
 * holds.
 */
export const COMPACT_EXTRAS = 1;

/**
 * The status line: 'Level N · swings left L/B (★★★ in P) · down F of T to clear' ('down F, T clear
 * it' once F passes T; the score after the level on a compact screen), then the extras: all of them on a large screen, the first
 * COMPACT_EXTRAS that are not '' on a compact one. The blocks down count toward the clear target,
 * not the level's whole count of pieces: 'down 16/27' with the level cleared read as a level half
 * standing, where 'down 16 of 16 to clear' says what the clear asks.
 */
export function playStatusLine(s: PlayStatus, compact: boolean): string {
  const score = s.score === null ? '' : ` · score ${s.score}`;
  const extras = s.extras.filter((e) => e !== '');
  const said = compact ? extras.slice(0, COMPACT_EXTRAS) : extras;
  const down = s.fallen <= s.target ? `down ${s.fallen} of ${s.target} to clear` : `down ${s.fallen}, ${s.target} clear it`;
  return `Level ${s.level}${score} · swings left ${s.left}/${s.budget} (★★★ in ${s.par}) · ${down}${said.join('')}`;
}

/**
 * The cleared banner's last line: how many down the clear asked and how many pieces still stand, so
 * a level cleared with a tower left standing reads as cleared by its rule ('16 down clears level 1:
 * the 6 still standing are spare'), not as a count gone wrong; with none standing, the rule alone.
 * @throws RangeError on counts that are not integers >= 0 or a level not an integer >= 1.
 */
export function clearRuleLine(level: number, target: number, standing: number): string {
  if (!Number.isInteger(level) || level < 1) throw new RangeError(`clearRuleLine: level must be an integer >= 1, got ${level}`);
  for (const [name, n] of [
    ['target', target],
    ['standing', standing],
  ] as const)
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`clearRuleLine: ${name} must be an integer >= 0, got ${n}`);
  const rule = `${target} down clears level ${level}`;
  if (standing === 0) return rule;
  return `${rule}: the ${standing} still standing ${standing === 1 ? 'is' : 'are'} spare`;
}
