/**
 * The source text of a pool's worker: the kernels (kernels.ts), written out from the very functions
 * the main thread runs, so both sides execute the same arithmetic, and the worker's loop
 * (worker-main.ts). One module for Node (`new Worker(source, { eval: true })`) and the browser (a Blob
 * URL, which a cross-origin isolated page may start).
 */

import { KERNEL_HELPERS, KERNELS } from './kernels.js';
import { WORKER_MAIN_SOURCE } from './worker-main.js';

let cached: string | null = null;

/**
 * The worker's source text (built once).
 * @category Threads
 */
export function workerSource(): string {
  if (cached !== null) return cached;
  cached = [
    "'use strict';",
    // A bundler keeping names may wrap the kernels' names in a __name helper; the worker has none.
    'var __name = function (f) { return f; };',
    `var KERNELS = [${KERNELS.map((k) => k.toString()).join(',\n')}];`,
    // The kernels' helpers, reached by index (kernels.ts KERNEL_HELPERS), so no name a bundler chose matters.
    `var KERNEL_HELPERS = [${KERNEL_HELPERS.map((k) => k.toString()).join(',\n')}];`,
    WORKER_MAIN_SOURCE,
    "workerMain(KERNELS, KERNEL_HELPERS, typeof require === 'function' ? require('node:worker_threads').parentPort : null);",
  ].join('\n');
  return cached;
}
