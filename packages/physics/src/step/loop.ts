import { assertInteger, assertOptions, assertPositive, optionOr } from '../validation/validate.js';

/**
 * Options of `createFixedStepLoop`.
 * @category World and step
 */
export interface FixedStepLoopOptions {
  /** The fixed step, s, > 0 (usually `world.dt`). */
  dt: number;
  /** Runs one fixed step (usually `() => step(world)`). */
  step: () => void;
  /**
   * Longest frame time fed into the accumulator, s (> 0). A longer frame (a tab in the background,
   * a breakpoint) is clamped so the simulation slows down instead of spiralling. Default 0.25 s.
   */
  maxFrameTime?: number;
  /** Most steps run for one frame (integer >= 1); the rest of the backlog is dropped. Default 8. */
  maxStepsPerFrame?: number;
}

/**
 * What one `advance` call did.
 * @category World and step
 */
export interface FrameResult {
  /** Whole steps run. */
  steps: number;
  /** Interpolation factor in [0, 1): how far the present lies between the last two steps. */
  alpha: number;
  /** Simulated seconds dropped by the backlog clamp this frame. */
  dropped: number;
}

/**
 * A fixed-timestep loop: feed it real frame time, it runs whole steps.
 * @category World and step
 */
export interface FixedStepLoop {
  /**
   * Adds `frameSeconds` of real time and runs as many whole steps as fit.
   * @throws RangeError if frameSeconds is negative or not finite.
   */
  advance(frameSeconds: number): FrameResult;
  /** Unspent time, s, in [0, dt). */
  readonly accumulator: number;
  /** Empties the accumulator (after a pause, say). */
  reset(): void;
}

/**
 * Creates a fixed-timestep loop (Fiedler, "Fix Your Timestep!", 2004): real frame time goes into an
 * accumulator, whole steps of `dt` are taken out, the backlog is clamped, and the remainder gives
 * the renderer an interpolation factor alpha = accumulator / dt. No timers inside: call `advance`
 * from requestAnimationFrame in a page, or from any loop in Node.
 * @throws TypeError on a missing options object, unknown or null options; RangeError on dt <= 0, maxFrameTime <= 0, maxStepsPerFrame < 1.
 * @category World and step
 */
export function createFixedStepLoop(options: FixedStepLoopOptions): FixedStepLoop {
  const where = 'createFixedStepLoop';
  assertOptions(where, options, ['dt', 'step', 'maxFrameTime', 'maxStepsPerFrame']);
  assertPositive(where, 'dt', options.dt);
  if (typeof options.step !== 'function') throw new TypeError(`${where}: step must be a function`);
  const maxFrameTime = optionOr(where, 'maxFrameTime', options.maxFrameTime, 0.25, assertPositive);
  const maxSteps = optionOr(where, 'maxStepsPerFrame', options.maxStepsPerFrame, 8, assertInteger, 1, 1_000_000);
  const dt = options.dt;
  const stepFn = options.step;
  let acc = 0;
  const result: FrameResult = { steps: 0, alpha: 0, dropped: 0 };
  return {
    advance(frameSeconds: number): FrameResult {
      if (!(frameSeconds >= 0) || !Number.isFinite(frameSeconds)) {
        throw new RangeError(`FixedStepLoop.advance: frameSeconds must be finite and >= 0, got ${frameSeconds}`);
      }
      let dropped = 0;
      if (frameSeconds > maxFrameTime) {
        dropped += frameSeconds - maxFrameTime;
        frameSeconds = maxFrameTime;
      }
      acc += frameSeconds;
      let steps = 0;
      while (acc >= dt && steps < maxSteps) {
        stepFn();
        acc -= dt;
        steps++;
      }
      if (acc >= dt) {
        const keep = acc % dt;
        dropped += acc - keep;
        acc = keep;
      }
      result.steps = steps;
      result.alpha = acc / dt;
      result.dropped = dropped;
      return result;
    },
    get accumulator() {
      return acc;
    },
    reset() {
      acc = 0;
    },
  };
}
