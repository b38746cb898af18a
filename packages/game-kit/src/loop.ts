import { createFixedStepLoop, type FixedStepLoop } from '@bitphysics/physics';

/** Options of `createGameLoop`. Unknown fields are rejected. */
export interface GameLoopOptions {
  /** Fixed physics step, s, finite and > 0 (usually `world.dt`). Change later with `setTimeStep`. */
  dt: number;
  /** Runs one physics step (usually `() => step(world)`). Errors thrown here stop the loop and go to `onError`. */
  step: () => void;
  /**
   * Draws a frame. `alpha` in [0, 1] is how far the present lies between the last two steps
   * (1 while paused, so a paused world shows exactly its current state).
   */
  render: (alpha: number) => void;
  /** Longest real frame time fed to the accumulator, s, > 0. Default 0.1 s (a stalled tab slows down instead of spiralling). */
  maxFrameTime?: number;
  /** Most steps run in one frame, integer >= 1. Default 4. */
  maxStepsPerFrame?: number;
  /** Called with the error when `step` or `render` throws; the loop has stopped by then. Default: console.error. */
  onError?: (error: unknown) => void;
  /** Frame scheduler. Default `requestAnimationFrame` (timestamps in ms). */
  requestFrame?: (callback: (timeMs: number) => void) => number;
  /** Cancels a scheduled frame. Default `cancelAnimationFrame`. */
  cancelFrame?: (id: number) => void;
}

const LOOP_OPTIONS = ['dt', 'step', 'render', 'maxFrameTime', 'maxStepsPerFrame', 'onError', 'requestFrame', 'cancelFrame'];

/** A running game loop: real frame time in, whole fixed steps and one render per frame out. */
export interface GameLoop {
  /** Starts requesting frames (no-op if running). */
  start(): void;
  /** Stops requesting frames (no-op if stopped). */
  stop(): void;
  /** Whether frames are being requested. */
  readonly running: boolean;
  /** Paused: frames keep being drawn (alpha 1) but no steps run. Resuming empties the accumulator. */
  paused: boolean;
  /** Runs exactly one step now, paused or not (the single-step key). Errors go to `onError` and stop the loop. */
  stepOnce(): void;
  /**
   * Runs `n` frames now, one after another within this call, each as the animation loop runs a frame
   * that comes `seconds` (s, default the fixed step) after the one before: the whole steps that fit
   * (none while paused), then `render`. A test hook: inputs held meanwhile (keys, a finger) act on
   * these steps as in play, and game time runs on without waiting for the clock. Not counted in `fps`.
   * Stops early if a step or render throws (the error goes to `onError` and stops the loop).
   * @throws RangeError if `n` is not an integer in [0, 100 000] or `seconds` is not finite and >= 0.
   */
  runFrames(n: number, seconds?: number): void;
  /**
   * Empties the accumulator and forgets the last frame's time (after a reset): the new world neither
   * inherits a backlog nor simulates the time before it existed (the old world's last frame to the
   * first frame after the reset, which holds the new level's build); its first frame draws it as
   * built, with no steps, as the loop's first frame does, and the frames after it step as usual.
   */
  resetClock(): void;
  /** Changes the fixed step, s (> 0), e.g. for a rebuilt world. @throws RangeError if not finite and > 0. */
  setTimeStep(dt: number): void;
  /** Frames per second over the last measurement window (about 0.5 s); 0 before the first. */
  readonly fps: number;
  /** Frames drawn since creation. */
  readonly frames: number;
  /** Interpolation factor used for the last frame, [0, 1]. */
  readonly alpha: number;
  /** Registers `callback` to run once after the first frame has been drawn (at once if it already has). */
  afterFirstFrame(callback: () => void): void;
}

/**
 * A fixed-step game loop built on `createFixedStepLoop` from @bitphysics/physics, fed by
 * requestAnimationFrame: each frame adds the real time elapsed since the previous frame, runs the
 * whole steps that fit (Fiedler, "Fix Your Timestep!"), then calls `render(alpha)`.
 * No DOM besides the frame scheduler; no pixi: usable by 2D and 3D games alike.
 * @throws TypeError on unknown options or non-function callbacks; RangeError on dt, maxFrameTime or maxStepsPerFrame out of range.
 */
export function createGameLoop(options: GameLoopOptions): GameLoop {
  const where = 'createGameLoop';
  if (options === null || typeof options !== 'object') throw new TypeError(`${where}: options must be an object`);
  for (const key of Object.keys(options)) {
    if (!LOOP_OPTIONS.includes(key))
      throw new TypeError(`${where}: unknown option ${JSON.stringify(key)}; known options are ${LOOP_OPTIONS.join(', ')}`);
  }
  if (typeof options.step !== 'function') throw new TypeError(`${where}: step must be a function, got ${typeof options.step}`);
  if (typeof options.render !== 'function') throw new TypeError(`${where}: render must be a function, got ${typeof options.render}`);
  const maxFrameTime = options.maxFrameTime ?? 0.1;
  const maxStepsPerFrame = options.maxStepsPerFrame ?? 4;
  const stepFn = options.step;
  const renderFn = options.render;
  const onError = options.onError ?? ((error: unknown) => console.error(error));
  const requestFrame = options.requestFrame ?? ((cb: (t: number) => void) => requestAnimationFrame(cb));
  const cancelFrame = options.cancelFrame ?? ((id: number) => cancelAnimationFrame(id));

  const makeFixed = (dt: number): FixedStepLoop => createFixedStepLoop({ dt, step: stepFn, maxFrameTime, maxStepsPerFrame });
  // createFixedStepLoop validates dt, maxFrameTime and maxStepsPerFrame (RangeError naming the option).
  let fixed = makeFixed(options.dt);
  /** The fixed step now, s (`setTimeStep` changes it). */
  let dt = options.dt;
  let running = false;
  let paused = false;
  let frameId = 0;
  let last = -1;
  let frames = 0;
  let alpha = 1;
  let fps = 0;
  let windowStart = -1;
  let windowFrames = 0;
  const firstFrameCallbacks: Array<() => void> = [];

  const fail = (error: unknown): void => {
    loop.stop();
    onError(error);
  };

  /** One frame's work, `seconds` after the last: its steps (none while paused) and its drawing. @returns false if it threw (the loop stopped). */
  const runFrame = (seconds: number): boolean => {
    try {
      if (paused) {
        alpha = 1;
      } else {
        alpha = fixed.advance(seconds).alpha;
      }
      renderFn(alpha);
    } catch (error) {
      fail(error);
      return false;
    }
    frames++;
    if (frames === 1) {
      const callbacks = firstFrameCallbacks.splice(0);
      for (const cb of callbacks) cb();
    }
    return true;
  };

  const frame = (timeMs: number): void => {
    if (!running) return;
    frameId = requestFrame(frame);
    const seconds = last < 0 ? 0 : Math.max(0, (timeMs - last) / 1000);
    last = timeMs;
    if (!runFrame(seconds)) return;
    if (windowStart < 0) windowStart = timeMs;
    windowFrames++;
    const elapsed = timeMs - windowStart;
    if (elapsed >= 500) {
      fps = ((windowFrames - 1) * 1000) / elapsed;
      windowStart = timeMs;
      windowFrames = 1;
    }
  };

  const loop: GameLoop = {
    start() {
      if (running) return;
      running = true;
      last = -1;
      windowStart = -1;
      windowFrames = 0;
      frameId = requestFrame(frame);
    },
    stop() {
      if (!running) return;
      running = false;
      cancelFrame(frameId);
    },
    get running() {
      return running;
    },
    get paused() {
      return paused;
    },
    set paused(value: boolean) {
      if (typeof value !== 'boolean') throw new TypeError(`GameLoop.paused must be a boolean, got ${typeof value}`);
      if (paused && !value) fixed.reset();
      paused = value;
    },
    stepOnce() {
      try {
        stepFn();
      } catch (error) {
        fail(error);
      }
    },
    runFrames(n: number, seconds = dt) {
      if (!Number.isInteger(n) || n < 0 || n > 100_000)
        throw new RangeError(`GameLoop.runFrames: n must be an integer in [0, 100000], got ${n}`);
      if (!Number.isFinite(seconds) || seconds < 0)
        throw new RangeError(`GameLoop.runFrames: seconds must be finite and >= 0, got ${seconds}`);
      for (let i = 0; i < n; i++) if (!runFrame(seconds)) return;
    },
    resetClock() {
      fixed.reset();
      last = -1;
    },
    setTimeStep(step: number) {
      fixed = makeFixed(step);
      dt = step;
    },
    get fps() {
      return fps;
    },
    get frames() {
      return frames;
    },
    get alpha() {
      return alpha;
    },
    afterFirstFrame(callback: () => void) {
      if (frames > 0) callback();
      else firstFrameCallbacks.push(callback);
    },
  };
  return loop;
}
