/**
 * How long an arrow press thrusts, in game steps (DOM-free): as long as it was held by the wall clock,
 * at least TAP_STEPS, counted from the step at which it began. The page runs the game in fixed steps
 * and, on a slow machine, several of them in a burst at each drawn frame; a key or a finger is let go
 * between frames, where the step count lags the wall clock by up to a frame. Letting go at the step
 * count of that moment made the thrust a whole number of frames long: at 10 frames a second a 120 ms
 * press thrust 0.15 or 0.2 s, a 400 ms one 0.4 or 0.5 s. Counted from its own length instead, a press
 * gives the same thrust, and so the same push, at any frame rate.
 */

/**
 * Steps a tap thrusts at the least (0.25 s at 60 steps a second): from rest a nudge of about
 * 0.4 m/s (./rules.ts THRUST_RAMP: 0.15 s gave 0.16 m/s, a drift of 1 m in 6 s, which looked like
 * nothing), however short the press and however many steps a slow frame runs meanwhile.
 */
export const TAP_STEPS = 15;
/**
 * The most steps a press thrusts on after the moment it is let go (0.5 s): a tap's TAP_STEPS, and for a
 * longer press the steps the game has not run yet (the pacer's lag, a frame or two); a longer wait (a
 * stall the pacer does not make up) is not thrust after the fact.
 */
export const MAX_TAIL_STEPS = 30;

/**
 * The step count at which the thrust of a press ends: `pressStep` (the step at which it began) plus
 * its length `heldMs` (wall clock, ms) in steps of `dt` s, rounded, at least TAP_STEPS; not before
 * `stepsNow` (the steps run when it was let go: a step run cannot be taken back) and at most
 * MAX_TAIL_STEPS after it.
 * @throws RangeError unless the steps are integers >= 0, heldMs >= 0 and dt > 0 are finite.
 */
export function releaseStep(pressStep: number, heldMs: number, stepsNow: number, dt: number): number {
  if (!(Number.isInteger(pressStep) && pressStep >= 0 && Number.isInteger(stepsNow) && stepsNow >= 0))
    throw new RangeError(`releaseStep: pressStep and stepsNow must be integers >= 0, got ${pressStep}, ${stepsNow}`);
  if (!(heldMs >= 0 && Number.isFinite(heldMs) && dt > 0 && Number.isFinite(dt)))
    throw new RangeError(`releaseStep: heldMs must be >= 0 and dt > 0, got ${heldMs}, ${dt}`);
  const end = pressStep + Math.max(TAP_STEPS, Math.round(heldMs / (1000 * dt)));
  return Math.min(stepsNow + MAX_TAIL_STEPS, Math.max(stepsNow, end));
}
