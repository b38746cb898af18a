/**
 * The hook through which `createPhysicsWorld` makes a thread pool: empty until `enableThreads`
 * (step/enable-threads.ts) fills it, so the world's assembly does not import the pool and its kernels.
 */
import type { ThreadPool } from './pool.js';

/**
 * Makes a pool of `threads` threads for the function named `where` (its errors start with it).
 * @category Threads
 */
export type ThreadPoolMaker = (where: string, threads: number) => ThreadPool;

let maker: ThreadPoolMaker | null = null;

/**
 * Sets how worlds with `threads` > 1 make their pool (enableThreads sets the physics pool).
 * @category Threads
 */
export function setThreadPoolMaker(make: ThreadPoolMaker): void {
  maker = make;
}

/**
 * A pool of `threads` threads for a world made by `where`.
 * @throws Error `<where>: threads: <n> needs enableThreads() ...` if threads were never enabled, and
 *   the pool's own errors (no SharedArrayBuffer, no workers).
 * @category Threads
 */
export function makeThreadPool(where: string, threads: number): ThreadPool {
  if (maker === null) {
    throw new Error(
      `${where}: threads: ${threads} needs the thread pool, which a program loads by calling enableThreads() once before making the world (import { enableThreads } from '@bitphysics/physics')`,
    );
  }
  return maker(where, threads);
}
