/**
 * Frame pacing for WebGL pages (three.js through './three', pixi through './pixi'): a page draws a
 * frame only while fewer than a given number of its earlier frames are unfinished on the GPU.
 *
 * Why: a GPU slower than the page's frame rate (software WebGL: SwiftShader in headless Chromium,
 * llvmpipe) otherwise receives frames without bound, and any call that waits for the GPU
 * (readPixels, drawing the canvas elsewhere, a shader's link status, a new page's first frame in the
 * same GPU process) waits for the whole queue: in headless Chromium on a busy 2-core machine a 1x1
 * readPixels can wait seconds, longer the longer a heavy page (balls-3d, lab-cloth) has run. On a
 * real GPU a fence signals within a frame, so pacing never lowers the frame rate there.
 */

/** Keeps a WebGL context from running more than a given number of frames ahead of its GPU. */
export interface FramePacer {
  /**
   * Whether a frame may be drawn now: fewer than the limit of earlier frames unfinished on the GPU.
   * A refusal is counted in `skipped`. Always true without WebGL 2 (WebGL 1, WebGPU, canvas) or
   * with a lost context.
   */
  mayDraw(): boolean;
  /** Marks the end of a drawn frame's commands (a fence the next `mayDraw` calls poll) and counts it in `drawn`. */
  drew(): void;
  /** Deletes the outstanding fences (call when the context is destroyed). */
  clear(): void;
  /** Frames drawn (`drew` calls) since the pacer was made. */
  readonly drawn: number;
  /** `mayDraw` calls that said no. */
  readonly skipped: number;
}

/**
 * A frame pacer for `gl`: one WebGL2 fence sync (SYNC_GPU_COMMANDS_COMPLETE) after each drawn frame,
 * polled with getSyncParameter (which never waits; the browser updates a fence's status between
 * tasks), and at most `maxInFlight` unsignalled. Without a WebGL 2 context (`gl` null, WebGL 1, a
 * WebGPU or canvas renderer) or with a lost context it always allows drawing and only counts frames.
 * @param gl the page's rendering context, or null when it has none (then nothing is paced).
 * @param maxInFlight most unfinished frames, integer in [1, 8] (2: the GPU works on one frame while
 *   the page prepares the next).
 * @throws RangeError if maxInFlight is not an integer in [1, 8].
 */
export function createFramePacer(gl: unknown, maxInFlight = 2): FramePacer {
  if (!(Number.isInteger(maxInFlight) && maxInFlight >= 1 && maxInFlight <= 8)) {
    throw new RangeError(`createFramePacer: maxInFlight must be an integer in [1, 8], got ${maxInFlight}`);
  }
  const gl2 = typeof WebGL2RenderingContext !== 'undefined' && gl instanceof WebGL2RenderingContext ? gl : null;
  const fences: WebGLSync[] = [];
  let drawn = 0;
  let skipped = 0;
  return {
    mayDraw() {
      if (!gl2) return true;
      if (gl2.isContextLost()) {
        fences.length = 0; // gone with the context
        return true;
      }
      while (fences.length > 0 && gl2.getSyncParameter(fences[0]!, gl2.SYNC_STATUS) === gl2.SIGNALED) gl2.deleteSync(fences.shift()!);
      if (fences.length < maxInFlight) return true;
      skipped++;
      return false;
    },
    drew() {
      drawn++;
      if (!gl2 || gl2.isContextLost()) return;
      const fence = gl2.fenceSync(gl2.SYNC_GPU_COMMANDS_COMPLETE, 0);
      if (fence) {
        fences.push(fence);
        // Submit now, so the fence can signal without waiting for the next frame's commands.
        gl2.flush();
      }
    },
    clear() {
      if (gl2 && !gl2.isContextLost()) for (const f of fences) gl2.deleteSync(f);
      fences.length = 0;
    },
    get drawn() {
      return drawn;
    },
    get skipped() {
      return skipped;
    },
  };
}
