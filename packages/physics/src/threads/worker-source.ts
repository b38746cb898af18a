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
 * A layout constant left as a name in a kernel's text: an offset of solver/body-state-layout.ts (BS2_,
 * BS3_, BX_, BI_) or solver/contact-pack-2d.ts (PK_), a stride, or a slot of a namespace-imported slot
 * module (`GATHER.PX`: an all-capitals name, a dot and an all-capitals name). The build that made this
 * code did not fold the constant modules, and a worker would not know the name.
 */
const UNFOLDED = /(?<![.\w$])((?:BS2|BS3|BX|BI|PK)_[A-Z0-9_]+|[A-Z][A-Z0-9]*_STRIDE|[A-Z][A-Z0-9_]*\.[A-Z][A-Z0-9_]*)\b/;

/**
 * The worker's source text for a kernel table and its helpers (kept for the next pool of the same ones).
 * @throws Error naming the kernel and the constant if a kernel's text still names a layout constant
 *   (the code was bundled without folding constants: scripts/build.mjs `inlineConstantModules` or a
 *   minifying bundler does it).
 * @category Threads
 */
export function workerSource(kernels: readonly Kernel[], helpers: readonly KernelHelper[]): string {
  if (cached !== null && cached.kernels === kernels && cached.helpers === helpers) return cached.source;
  for (const f of [...kernels, ...helpers]) {
    const m = UNFOLDED.exec(f.toString());
    if (m !== null)
      throw new Error(
        `bitphysics threads: kernel ${f.name || '(anonymous)'} names the constant ${m[1]}, which its workers cannot see: ` +
          'bundle the package with its constants folded (an esbuild minify, or scripts/build.mjs inlineConstantModules)',
      );
  }
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
