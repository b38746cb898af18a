/**
 * A press that always acts: a key or button held for less than a frame (its press and release both
 * come in before the frame's steps run, as a ~200 ms tap does at 5 frames a second) still acts for
 * MIN_PULSE s of game time from the first step that sees it, so no short tap is lost at a low frame
 * rate. Headless (no DOM), so it is tested in node (test/games/flight-simulator-pacing.test.ts).
 */

/**
 * Least game time a press acts for, s: about a tap's length (0.1 to 0.2 s). A tap of a bank key asks
 * for BANK_KEY_RAMP.start at once and so banks the aircraft (./assist.ts); a tap of the climb key
 * ramps to about a fifth of full stick (./assist.ts KEY_RAMP).
 */
export const MIN_PULSE = 0.15;

/** One key's or button's press as the steps see it. */
export interface Pulse {
  /** Whether the key is held now. */
  down: boolean;
  /** Whether a press came that no step has seen yet. */
  fresh: boolean;
  /** Game time of the first step that saw the last press, s (-Infinity before any). */
  since: number;
}

/** A pulse never pressed. */
export function createPulse(): Pulse {
  return { down: false, fresh: false, since: Number.NEGATIVE_INFINITY };
}

/** The key went down (a repeat of a held key changes nothing). */
export function pressPulse(p: Pulse): void {
  if (p.down) return;
  p.down = true;
  p.fresh = true;
}

/** The key came up. */
export function releasePulse(p: Pulse): void {
  p.down = false;
}

/** Forgets any press (a reset): the key acts only while held again. */
export function clearPulse(p: Pulse): void {
  p.down = false;
  p.fresh = false;
  p.since = Number.NEGATIVE_INFINITY;
}

/**
 * Whether the key acts at the step at game time `time` (s): while it is held, and for MIN_PULSE s of
 * game time from the first step that saw its last press, however soon it was let go.
 * @throws RangeError on a `time` that is not finite.
 */
export function pulseOn(p: Pulse, time: number): boolean {
  if (!Number.isFinite(time)) throw new RangeError(`pulseOn: time must be finite, got ${time}`);
  if (p.fresh) {
    p.fresh = false;
    p.since = time;
  }
  return p.down || time - p.since < MIN_PULSE - 1e-9;
}
