/**
 * The source text of a pool's worker: the kernels (step/kernel-table.ts), written out from the very functions
 * the main thread runs, so both sides execute the same arithmetic, and the worker's loop
 * (worker-main.ts). One module for Node (`new Worker(source, { eval: true })`) and the browser (a Blob
 * URL, which a cross-origin isolated page may start).
 */

import type { Kernel, KernelHelper } from './kernel-types.js';
import { WORKER_MAIN_SOURCE } from './worker-main.js';

/** The last source built, with the table and helpers it was built from. */
let cached: { kernels: readonly Kernel[]; helpers: readonly KernelHelper[]; source: string } | null = null;

/**
 * The worker's source text for a kernel table and its helpers (kept for the next pool of the same ones).
 * @category Threads
 */
export function workerSource(kernels: readonly Kernel[], helpers: readonly KernelHelper[]): string {
  if (cached !== null && cached.kernels === kernels && cached.helpers === helpers) return cached.source;
  const source = [
    "'use strict';",
    // A bundler keeping names may wrap the kernels' names in a __name helper; the worker has none.
    'var __name = function (f) { return f; };',
    `var KERNELS = [${kernels.map((k) => k.toString()).join(',\n')}];`,
    // The kernels' helpers, reached by index (solver/kernel-helpers.ts KERNEL_HELPERS), so no name a bundler chose matters.
    `var KERNEL_HELPERS = [${helpers.map((k) => k.toString()).join(',\n')}];`,
    WORKER_MAIN_SOURCE,
    "workerMain(KERNELS, KERNEL_HELPERS, typeof require === 'function' ? require('node:worker_threads').parentPort : null);",
  ].join('\n');
  cached = { kernels, helpers, source };
  return source;
}
