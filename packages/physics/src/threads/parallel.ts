/**
 * When and how a system splits its loop over the world's threads. A loop goes parallel only if the
 * world has a pool, its workers have started, the loop is long enough to pay for waking them
 * (`MIN_PARALLEL_PER_THREAD` entities a thread: below it one thread is faster, so small worlds fall
 * back to one thread by themselves) and every array it touches is shared. Past that, an adaptive
 * pool (the default) times the loop both ways and keeps to one thread while the threads have not been
 * faster (adaptive.ts), so a loop the threads do not help, or a machine whose other cores are busy,
 * costs at most the occasional probe.
 */

import type { PhysicsWorld } from '../world/options.js';
import { nowMs } from './adaptive.js';
import type { KernelArray } from './kernels.js';
import { isShared, type ThreadPool } from './pool.js';

/**
 * Fewest entities per thread for a loop to run on several threads. Waking a worker and waiting for
 * it costs some tens of microseconds; the cheapest kernel (free particles) does about 4,000 entities
 * in that time on one core. Since the workers spin a while between loops (pool.ts idleSpin) and the
 * ranges follow each thread's speed (balance.ts), 8,192 a thread pays: balls-in-box at 20,000 balls
 * on 2 threads, whose integration then splits, ran 2.4 to 7 % faster a step than at 16,384
 * (alternate steps in one process); an adaptive pool still keeps a loop that does not pay to one thread.
 * @category Threads
 */
export const MIN_PARALLEL_PER_THREAD = 8192;

/**
 * Runs kernel `kernel` over n entities on the world's threads when that pays (see the file's
 * header) and returns the summed kernel result; returns null when the caller should run its own
 * single-threaded loop instead. `system` names the system in a worker's error.
 * @throws Error naming `system` if a worker's range threw.
 * @category Threads
 */
export function runParallel(
  world: PhysicsWorld,
  system: string,
  kernel: number,
  arrays: KernelArray[],
  params: ArrayLike<number>,
  n: number,
  ids: ArrayLike<number> | null,
): number | null {
  return runOnPool(world.threadPool, system, kernel, arrays, params, n, ids, MIN_PARALLEL_PER_THREAD);
}

/**
 * runParallel on a given pool (null: none) with its own threshold: the loop goes parallel when n is
 * at least `minPerThread` times the pool's threads, every array is shared and the workers have
 * started; returns null otherwise (the caller runs its own single-threaded loop).
 * @throws Error naming `system` if a worker's range threw.
 * @category Threads
 */
export function runOnPool(
  pool: ThreadPool | null,
  system: string,
  kernel: number,
  arrays: KernelArray[],
  params: ArrayLike<number>,
  n: number,
  ids: ArrayLike<number> | null,
  minPerThread: number,
): number | null {
  if (pool === null || pool.threads > MAX_POOL_PARTS || n < minPerThread * pool.threads) return null;
  for (let i = 0; i < arrays.length; i++) if (!isShared(arrays[i]!)) return null;
  if (!pool.usable()) return null;
  if (!pool.adaptive) return pool.run(system, kernel, arrays, params, n, ids);
  // Threads or this thread alone, whichever has been faster for this loop (threads/adaptive.ts); the
  // same kernel either way, so the result does not depend on the choice.
  const site = `${system}#${kernel}`;
  const parallel = pool.chooser.choose(site);
  const t0 = nowMs();
  const result = parallel
    ? pool.run(system, kernel, arrays, params, n, ids)
    : pool.kernels[kernel]!(arrays, params as Float64Array, ids as Int32Array | null, 0, n, 0, pool.helpers);
  pool.chooser.record(site, parallel, nowMs() - t0, n);
  return result;
}

/**
 * Most threads a per-range result array (such as a bounding box a range) is sized for.
 * @category Threads
 */
export const MAX_POOL_PARTS = 64;
