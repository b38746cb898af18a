import { setFlagsFromString } from 'node:v8';
import { runInNewContext } from 'node:vm';

let gcFunction: (() => void) | null | undefined;

/**
 * Runs a full garbage collection if the runtime allows it (with --expose-gc, or by enabling the
 * flag at run time); returns whether it ran. Used between setup and timing, never inside timing.
 */
export function collectGarbage(): boolean {
  if (gcFunction === undefined) {
    const g = (globalThis as { gc?: () => void }).gc;
    if (typeof g === 'function') gcFunction = g;
    else {
      try {
        setFlagsFromString('--expose-gc');
        gcFunction = runInNewContext('gc') as () => void;
      } catch {
        gcFunction = null;
      }
    }
  }
  if (!gcFunction) return false;
  gcFunction();
  return true;
}

/** Memory of the process, MB (1 MB = 2^20 bytes). */
export interface MemorySample {
  /** V8 heap in use. */
  readonly heapUsed: number;
  /** Memory outside the V8 heap held by JS objects: typed-array buffers, WASM memories. */
  readonly external: number;
}

/** Samples the process's memory now. */
export function sampleMemory(): MemorySample {
  const m = process.memoryUsage();
  return { heapUsed: m.heapUsed / 2 ** 20, external: m.external / 2 ** 20 };
}

/**
 * Memory an engine instance holds, MB: the growth of V8 heap plus external memory (typed-array
 * buffers, SharedArrayBuffers, WASM memories) from `before` (sampled after a full collection, right
 * before the engine built its scene) to `after` (after the build and a full collection), less
 * `benchBytes`, what the bench adapter itself keeps beside the engine (its copy of the body id list),
 * so that the figure is the engine's and the scene's alone and compares with a bare loop's arrays.
 */
export function engineMemoryMB(before: MemorySample, after: MemorySample, benchBytes = 0): number {
  return after.heapUsed + after.external - before.heapUsed - before.external - benchBytes / 2 ** 20;
}
