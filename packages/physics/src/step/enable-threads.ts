/**
 * Turning threads on: `enableThreads` hands `createPhysicsWorld` the thread pool and the physics
 * kernel table (step/kernel-table.ts), so a world made with `threads` > 1 gets a pool of workers. A
 * program that never calls it does not bundle the pool, the workers' source or the kernels.
 */

import { KERNEL_HELPERS } from '../solver/kernel-helpers.js';
import { createThreadPool } from '../threads/pool.js';
import { setThreadPoolMaker } from '../threads/pool-maker.js';
import { KERNELS } from './kernel-table.js';

/**
 * Lets worlds run on several threads: after this call, `createPhysicsWorld({ threads: n })` with n > 1
 * makes a pool of n - 1 workers running the physics kernels. Call it once, before making such a
 * world (calling it again does nothing more). Without it, `threads` > 1 throws an Error that names this
 * function; a program that never calls it does not bundle the pool.
 * @example
 * import { createPhysicsWorld, enableThreads } from '@bitphysics/physics';
 * enableThreads();
 * const world = createPhysicsWorld({ capacity: 100_000, threads: 4 });
 * @category Threads
 */
export function enableThreads(): void {
  setThreadPoolMaker((where, threads) => createThreadPool(where, threads, KERNELS, KERNEL_HELPERS));
}
