/**
 * When and how a system splits its loop over the world's threads. A loop goes parallel only if the
 * world has a pool, its workers have started, the loop is long enough to pay for waking them
 * (`MIN_PARALLEL_PER_THREAD` entities a thread: below it one thread is faster, so small worlds fall
 * back to one thread by themselves) and every array it touches is shared. Past that, an adaptive
 * pool (the default) times the loop both ways and keeps to one thread while the threads have not been
 * faster (adaptive.ts), so a loop the threads do not help, or a machine whose other cores are busy,
 * costs at most the occasional probe.
 */

import { nowMs } from './adaptive.js';
import type { Kernel, KernelArray, KernelHelper } from './kernel-types.js';
import { isShared, type ThreadPool } from './pool.js';

/**
 * Fewest entities per thread for a loop to run on several threads. Waking a worker and waiting for
 * it costs some tens of microseconds; the cheapest kernel (free particles) does about 4,000 entities
 * in that time on one core. Since the workers spin a while between loops (pool.ts idleSpin) and the
 * ranges follow each thread's speed (balance.ts), 8,192 a thread pays (a 20,000-ball world's
 * integration then splits over 2 threads); an adaptive pool still keeps a loop that does not pay to one
 * thread.
 * @category Threads
 */
export const MIN_PARALLEL_PER_THREAD = 8192;

/**
 * Runs `kernel` over n entities: on the world's threads when that pays (see the file's header), else
 * inline on the calling thread over [0, n) as range 0. It is the same function either way, so a
 * kernel that treats each entity alone gives the same state on any thread count. Returns the summed
 * kernel result. `world` is any object with the world's pool (`PhysicsWorld` is); `system` names the
 * system in a worker's error.
 * @throws Error naming `system` if a worker's range threw.
 * @category Threads
 */
export function runParallel(
  world: { readonly threadPool: ThreadPool | null },
  system: string,
  kernel: Kernel,
  arrays: KernelArray[],
  params: ArrayLike<number>,
  n: number,
  ids: ArrayLike<number> | null,
): number {
  const pool = world.threadPool;
  const result = runOnPool(pool, system, kernel, arrays, params, n, ids, MIN_PARALLEL_PER_THREAD);
  if (result !== null) return result;
  return kernel(arrays, params as Float64Array, ids as Int32Array | null, 0, n, 0, pool === null ? NO_HELPERS : pool.helpers);
}

/** The helper list of a kernel run inline without a pool (the kernels that call helpers pass their own). */
const NO_HELPERS: readonly KernelHelper[] = Object.freeze([]);

/**
 * Runs `kernel` (a function of the pool's kernel table) over n entities on the pool's threads when
 * that pays: n at least `minPerThread` times the pool's threads, every array shared and the workers
 * started; an adaptive pool may still run it inline over [0, n) when that has been faster
 * (threads/adaptive.ts). Returns the summed kernel result, or null when the pool (null: none) did not
 * take the loop, for a caller that then runs the kernel itself (runParallel does).
 * @throws Error naming `system` if a worker's range threw.
 * @category Threads
 */
export function runOnPool(
  pool: ThreadPool | null,
  system: string,
  kernel: Kernel,
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
  const site = `${system}#${pool.indexOf(kernel)}`;
  const parallel = pool.chooser.choose(site);
  const t0 = nowMs();
  const result = parallel
    ? pool.run(system, kernel, arrays, params, n, ids)
    : kernel(arrays, params as Float64Array, ids as Int32Array | null, 0, n, 0, pool.helpers);
  pool.chooser.record(site, parallel, nowMs() - t0, n);
  return result;
}

/**
 * Most threads a per-range result array (such as a bounding box a range) is sized for.
 * @category Threads
 */
export const MAX_POOL_PARTS = 64;
