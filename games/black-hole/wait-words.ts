/**
 * The words over the field while the ship waits at the start (DOM-free): they say what put it there,
 * and only that. The page keeps the last thing that happened to the ship (`ShipHappening`); a fall's
 * words must not outlive the fall: after a level begins (a clear, or a new game) or after the ship is
 * lost off the field, the fall before is history, and words left from it contradicted the status line
 * ("Swallowed! 2 lives left" over "Off the field: back to the start").
 */

/**
 * The last thing that happened to the ship: 'fell' into a hole (a life lost, or none on a practice
 * level), 'lost' off the field (no penalty), 'over' (the last life gone), 'level' (a level or a game
 * began: nothing to report), 'flying' (the player thrust since).
 */
export type ShipHappening = 'fell' | 'lost' | 'over' | 'level' | 'flying';

/** What the words need to know: lives left (0 to 3), whether the level is practice, whether the device is touch. */
export interface WaitContext {
  readonly lives: number;
  readonly practice: boolean;
  readonly touch: boolean;
  /** Whether the loss was a flight past the line with a ring left (`LevelRun.missedRing`). Default false. */
  readonly missedRing?: boolean;
  /**
   * Why the attempt ended, when the ship was not lost off the field but stranded
   * (./levels.ts `LevelRun.stranded`: 'orbit', 'stall', 'fuel'); default '' (lost off the field).
   */
  readonly stranded?: '' | 'orbit' | 'stall' | 'fuel';
  /**
   * Whether the ready beat after the respawn lasts (./main.ts READY_MS): a press begun now is dropped,
   * so the last line says "Get ready…" (READY_LINE) instead of how to fly on. Default false.
   */
  readonly ready?: boolean;
}

/** The last line of a fall's or a loss's words during the ready beat after the respawn (`WaitContext.ready`). */
export const READY_LINE = 'Get ready…';

/**
 * The words for `happening`, lines separated by '\n': a fall's ("Swallowed!", the lives left or the
 * practice note, how to go on, or READY_LINE while the ready beat lasts), a loss off the field's ("Off the field", or "Missed the ring" past the
 * line with a ring left; "Caught in orbit", "Caught among the holes" or "Out of fuel" for an attempt
 * ended stranded; no life lost; how to go on), a
 * game over's; '' when there is nothing to say ('level', 'flying').
 * @throws RangeError when `ctx.lives` is not an integer in [0, 99].
 */
export function waitWords(happening: ShipHappening, ctx: WaitContext): string {
  if (!(Number.isInteger(ctx.lives) && ctx.lives >= 0 && ctx.lives <= 99))
    throw new RangeError(`waitWords: ctx.lives must be an integer in [0, 99], got ${String(ctx.lives)}`);
  // ↓ alone on the start pad does nothing (./rules.ts `padThrust`): the words name the arrows that launch.
  // In the ready beat a press is dropped: the words say to wait, and how to fly on once it is over.
  const go = ctx.ready === true ? READY_LINE : ctx.touch ? 'Tap ↑, ← or → to fly on' : 'Press ↑, ← or → to fly on';
  switch (happening) {
    case 'over':
      return 'Swallowed!\nGame over';
    case 'fell':
      return ctx.practice
        ? `Swallowed!\nPractice: no life lost\n${go}`
        : `Swallowed!\n${ctx.lives} ${ctx.lives === 1 ? 'life' : 'lives'} left\n${go}`;
    case 'lost':
      if (ctx.stranded === 'orbit') return `Caught in orbit!\nBack to the start, no life lost\n${go}`;
      if (ctx.stranded === 'stall') return `Caught among the holes!\nBack to the start, no life lost\n${go}`;
      if (ctx.stranded === 'fuel') return `Out of fuel!\nBack to the start, tank full, no life lost\n${go}`;
      return ctx.missedRing === true
        ? `Missed the ring!\nThe line counts after it: back to the start, no life lost\n${go}`
        : `Off the field!\nBack to the start, no life lost\n${go}`;
    default:
      return '';
  }
}

/** What Continue after a game over does to the score, in words: the points do not carry over. */
export const CONTINUE_SCORE = 'score resets to 0';

/**
 * What Continue after a game over does, in words (it plays level `level` again with the lives of a
 * new game and a score of 0: ./main.ts `advance`): `card`, the game-over card's last line beside the
 * Continue button; `status`, the status line's end (a tap on a touch screen; Enter, and R to start
 * again from level `first`, with keys). Continue used to reset the score with no word of it.
 * @throws RangeError unless level and first are integers >= 1.
 */
export function continueWords(level: number, first: number, touch: boolean): { card: string; status: string } {
  if (!(Number.isInteger(level) && level >= 1 && Number.isInteger(first) && first >= 1))
    throw new RangeError(`continueWords: level and first must be integers >= 1, got ${level}, ${first}`);
  return {
    card: `Continue: level ${level} again, ${CONTINUE_SCORE}`,
    status: touch
      ? `Tap to continue from level ${level} (${CONTINUE_SCORE}).`
      : `Enter: continue from level ${level} (${CONTINUE_SCORE}). R: start again from level ${first}.`,
  };
}

/**
 * The happening after a game step's event `event` (./replay.ts `GameStepEvent`) when the last one was
 * `last`: a fall, a loss, a game over replace it; a clear ends the attempt ('level': the next level's
 * start has nothing to report); other events keep it.
 */
export function nextHappening(last: ShipHappening, event: string): ShipHappening {
  if (event === 'fell' || event === 'lost' || event === 'over') return event;
  if (event === 'cleared' || event === 'scored') return 'level';
  return last;
}

/**
 * `words` while the game is paused: their last line, how to fly on, becomes the pause's own words in
 * one line ("Paused: P to resume", from `pauseText` "Paused\nP to resume"), so the field shows one
 * message, not the pause's stacked over the fall's; words without such a line get it added.
 * `words` unchanged when either is ''.
 */
export function pausedWords(words: string, pauseText: string): string {
  if (words === '' || pauseText === '') return words;
  const pause = pauseText.split('\n').join(': ');
  const lines = words.split('\n');
  if (/ to fly on$/.test(lines[lines.length - 1]!)) lines.pop();
  return [...lines, pause].join('\n');
}

/**
 * The status line `message` (the rules' words, for keys) as a touch screen says it, in the order to
 * try, longest first: a tap for Enter; then, for the phone's two-line status row, shorter forms of a
 * clear's line: without the time in all and the falls, then with the speed bonus named in one word
 * ("+129 (100 + 29 bonus)"), then without how the points were made; and of a level's opening line
 * and a fall's: without "more if fast", then the goal in fewer words ("Level 1: through the gold
 * ring, then the green line: 100 points."; "falls cost no life"), then a wall's note shorter
 * ("Find the gap, then round the hole."). The page shows the first that fits (a third line pushed the field under the
 * pad, and the field jumped as the line changed length), so a phone keeps the breakdown a desktop
 * shows wherever it fits. Each form appears once (a line with no such parts gives one).
 */
export function touchStatusLines(message: string): string[] {
  const tapped = message.replace('Press Enter or R to play again.', 'Tap to play again.').replace('Press Enter for level', 'Tap for level');
  const noFalls = tapped.replace(/ \(\d+\.\d s in all, \d+ falls?\)/, '');
  const shortBonus = noFalls.replace(/ \((\d+) \+ (\d+) speed bonus\)/, ' ($1 + $2 bonus)');
  const noBonus = shortBonus.replace(/ \(\d+ \+ \d+ bonus\)/, '');
  // A level's opening line and a fall's: the goal said in fewer words, then a wall's note shorter.
  const noFast = noBonus.replace(', more if fast.', '.');
  const shortGoal = noFast
    .replace(/fly through the (.+?), then reach the green line for (\d+) points/, 'through the $1, then the green line: $2 points')
    .replace(/reach the green line for (\d+) points/, 'the green line: $1 points')
    .replace(/falling in costs no life (here|on this level)\./, 'falls cost no life.');
  const shortNotes = shortGoal.replace(
    'Find the gap in the wall, then steer round the hole above it.',
    'Find the gap, then round the hole.',
  );
  return [...new Set([tapped, noFalls, shortBonus, noBonus, noFast, shortGoal, shortNotes])];
}
