/**
 * How long an arrow press thrusts, in game steps (DOM-free): as long as it was held by the wall clock
 * (a short one a little longer: `pressSteps`), counted from the step at which it began. The page runs
 * the game in fixed steps and, on a slow machine, several of them in a burst at each drawn frame; a key or a finger is let go
 * between frames, where the step count lags the wall clock by up to a frame. Letting go at the step
 * count of that moment made the thrust a whole number of frames long: at 10 frames a second a 120 ms
 * press thrust 0.15 or 0.2 s, a 400 ms one 0.4 or 0.5 s. Counted from its own length instead, a press
 * gives the same thrust, and so the same push, at any frame rate.
 */

/**
 * Steps a tap thrusts (0.22 s at 60 steps a second), however short the press and however many steps a
 * slow frame runs meanwhile: from rest a nudge of about 0.34 m/s (./rules.ts THRUST_RAMP; 0.15 s gave
 * 0.16 m/s, a drift of 1 m in 6 s, which looked like nothing). `pressSteps` of a press of no length.
 */
export const TAP_STEPS = 13;
/**
 * Held for this many steps (0.43 s; twice TAP_STEPS, so the count never falls) or longer, a press
 * thrusts just as long as it was held; a shorter one thrusts on a little after it is let go
 * (`pressSteps`).
 */
export const TAP_BLEND_STEPS = 26;

/**
 * How many steps a press held `held` steps (>= 0, a fraction where the wall clock says so) thrusts:
 * held + TAP_STEPS x (1 - held / TAP_BLEND_STEPS)^2 below TAP_BLEND_STEPS, else held. The extra
 * shrinks smoothly to nothing, so each longer press thrusts longer (the count never falls as `held`
 * grows) and the push grows steadily from a tap's nudge to a hold's full thrust. A flat least length
 * (every press under 0.25 s thrust 15 steps, then its own length) gave the same push to any press up
 * to 0.25 s and three times that to one of 0.4 s: a tap and a hold felt like two engines.
 */
export function pressSteps(held: number): number {
  const short = Math.max(0, 1 - held / TAP_BLEND_STEPS);
  return held + TAP_STEPS * short * short;
}

/**
 * The most steps a press thrusts on after the moment it is let go (0.5 s): a tap's TAP_STEPS, and for a
 * longer press the steps the game has not run yet (the pacer's lag, a frame or two); a longer wait (a
 * stall the pacer does not make up) is not thrust after the fact.
 */
export const MAX_TAIL_STEPS = 30;

/**
 * The step count at which the thrust of a press ends: `pressStep` (the step at which it began) plus
 * `pressSteps` of its length `heldMs` (wall clock, ms) in steps of `dt` s, rounded; not before
 * `stepsNow` (the steps run when it was let go: a step run cannot be taken back) and at most
 * MAX_TAIL_STEPS after it.
 * @throws RangeError unless the steps are integers >= 0, heldMs >= 0 and dt > 0 are finite.
 */
export function releaseStep(pressStep: number, heldMs: number, stepsNow: number, dt: number): number {
  if (!(Number.isInteger(pressStep) && pressStep >= 0 && Number.isInteger(stepsNow) && stepsNow >= 0))
    throw new RangeError(`releaseStep: pressStep and stepsNow must be integers >= 0, got ${pressStep}, ${stepsNow}`);
  if (!(heldMs >= 0 && Number.isFinite(heldMs) && dt > 0 && Number.isFinite(dt)))
    throw new RangeError(`releaseStep: heldMs must be >= 0 and dt > 0, got ${heldMs}, ${dt}`);
  const end = pressStep + Math.round(pressSteps(heldMs / (1000 * dt)));
  return Math.min(stepsNow + MAX_TAIL_STEPS, Math.max(stepsNow, end));
}

/**
 * The most steps a press's start is put after the steps run when it came: the steps of one frame's
 * burst at 15 frames a second. A press that comes longer after the last step (a stall the pacer does
 * not make up) starts no later than this.
 */
export const MAX_LEAD_STEPS = 4;

/**
 * The step at which the thrust of a press made at `eventMs` (wall clock, ms) begins: `stepsNow` (the
 * steps run) plus the whole steps of `dt` s from `stepMs` (the wall clock when the last of them ran,
 * ms) to the press, at most MAX_LEAD_STEPS. The pacer runs the steps of a frame in a burst, so a press
 * made between two frames of a slow page came that many steps after the last one run; begun at
 * `stepsNow` it thrust up to a frame early, by a different amount each time, and the same key timings
 * flew a different path at 20, 30 or 60 frames a second.
 * @throws RangeError unless stepsNow is an integer >= 0, eventMs and stepMs are finite and dt > 0 is finite.
 */
export function pressStartStep(stepsNow: number, eventMs: number, stepMs: number, dt: number): number {
  if (
    !(Number.isInteger(stepsNow) && stepsNow >= 0 && Number.isFinite(eventMs) && Number.isFinite(stepMs) && dt > 0 && Number.isFinite(dt))
  )
    throw new RangeError(
      `pressStartStep: stepsNow must be an integer >= 0, the times finite and dt > 0, got ${stepsNow}, ${eventMs}, ${stepMs}, ${dt}`,
    );
  const lead = Math.floor((eventMs - stepMs) / (1000 * dt) + 1e-9);
  return stepsNow + Math.min(MAX_LEAD_STEPS, Math.max(0, lead));
}
