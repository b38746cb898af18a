/**
 * The flight simulator's pacing on a slow machine: how much game time a drawn frame may advance, and
 * when the page says it is in slow motion. Headless (no DOM), so it is tested in node
 * (test/games/flight-simulator-pacing.test.ts).
 *
 * At 5 to 10 frames a second a loop that catches up with the clock moves the aircraft 25 to 50 m
 * between two pictures, too far to steer by (a ring comes and goes between frames). Below
 * 1 / FRAME_CAP frames a second the game runs in slow motion instead: each frame advances at most
 * FRAME_CAP s of game time, so the aircraft moves at most FRAME_CAP x its speed between pictures
 * (13 m at 130 m/s), and the page says so (`slowMotion`).
 */

/** Longest game time one drawn frame advances, s: the game keeps pace with the clock down to 10 frames a second. */
export const FRAME_CAP = 0.1;

/** The fixed step the flight is flown at, s (the aircraft scene's world.dt). */
export const FLIGHT_STEP = 1 / 60;

/** Most fixed steps run in one drawn frame: FRAME_CAP / FLIGHT_STEP, so a frame at the cap runs all its steps. */
export const STEPS_PER_FRAME = Math.round(FRAME_CAP / FLIGHT_STEP);

/**
 * Frame rates of the slow-motion notice, frames a second: it shows once the measured rate falls under
 * `on` and goes once it is back over `off` (the gap keeps it from flickering at the edge).
 */
export const SLOW_MOTION_FPS = Object.freeze({ on: 1 / FRAME_CAP - 0.5, off: 1 / FRAME_CAP + 2 });

/**
 * Game time one drawn frame advances, s: the clock's time since the last frame, `frameSeconds` (s,
 * >= 0), up to FRAME_CAP (what the game loop's maxFrameTime does with it).
 * @throws RangeError on a `frameSeconds` that is negative or not finite.
 */
export function gameTimeOfFrame(frameSeconds: number): number {
  if (!(frameSeconds >= 0 && Number.isFinite(frameSeconds)))
    throw new RangeError(`gameTimeOfFrame: frameSeconds must be finite and >= 0, got ${frameSeconds}`);
  return Math.min(frameSeconds, FRAME_CAP);
}

/**
 * Whether the slow-motion notice shows, given whether it `shown` now and the measured frame rate
 * `fps` (frames a second; 0 before the first measurement, which shows nothing): on under
 * SLOW_MOTION_FPS.on, off over SLOW_MOTION_FPS.off, else as it was.
 * @throws RangeError on an `fps` that is negative or not finite.
 */
export function slowMotion(shown: boolean, fps: number): boolean {
  if (!(fps >= 0 && Number.isFinite(fps))) throw new RangeError(`slowMotion: fps must be finite and >= 0, got ${fps}`);
  if (fps === 0) return false;
  if (fps < SLOW_MOTION_FPS.on) return true;
  if (fps > SLOW_MOTION_FPS.off) return false;
  return shown;
}
