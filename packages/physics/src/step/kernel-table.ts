/**
 * The kernel table: every loop kernel that worker threads run over a range of a system's loop, handed
 * to a world's thread pool when it is made (step/enable-threads.ts). Each kernel lives beside its
 * system and is the body of that system's hot loop, cut at [lo, hi): the system passes the function
 * itself to threads/parallel.ts, which runs it over the whole loop on the calling thread or splits it
 * over the pool, whose workers get its source text (threads/worker-source.ts) and run it on views of
 * the same shared memory. One function either way, so each entity's arithmetic is the same on any
 * thread count and the results are identical to the bit.
 *
 * Rules for a kernel (its source is sent to the workers as text):
 * - it refers to nothing outside itself but its arguments, JavaScript's globals (Math) and the
 *   numeric constants of constant modules (solver/body-state-layout.ts, solver/contact-pack-2d.ts),
 *   which every build folds into its text (threads/worker-source.ts refuses a kernel that still names one);
 * - no inner functions (bundlers may wrap them in helpers the worker does not have);
 * - `A` holds the typed arrays in the order its caller documents, `P` the scalar parameters,
 *   `ids` the entity ids of the loop (null: the loop is over the dense ids lo + 1 .. hi);
 * - it returns a number the caller sums over the ranges (a finiteness check or a count);
 * - functions it calls come as its last argument, `helpers` (KERNEL_HELPERS, by index), and follow
 *   these same rules.
 */

import { ballPairs } from '../collision/broadphase/grid-pairs-kernel.js';
import { ballContacts } from '../collision/narrowphase/balls-kernel.js';
import { mortonBucketSort, mortonKeysHist, mortonScatter, treeForces, treeGather } from '../forces/barnes-hut/gather.js';
import { treeMoments } from '../forces/barnes-hut/moments.js';
import { barnesHutWalk } from '../forces/barnes-hut/walk-kernel.js';
import { centralForce } from '../forces/central.js';
import { velocityDamping } from '../forces/drag.js';
import { attractors, gravityScale } from '../forces/gravity.js';
import { sie2, sie3 } from '../integrators/semi-implicit-euler.js';
import { solveColored2D } from '../solver/coloring-kernel.js';
import { prepareContactRows } from '../solver/prepare-contacts-kernel.js';
import { approachSpeeds, finishBodies, gatherFill, restitutionColored } from '../solver/stages-kernel.js';
import { stripPlan2D } from '../solver/strip-plan-kernel.js';
import { stripCut2D } from '../solver/strips-kernel.js';
import { warmStartTable } from '../solver/warm-start-kernel.js';
import type { Kernel, KernelArray } from '../threads/kernel-types.js';
import { finiteProbe } from './finite.js';

/**
 * A kernel for tests of the pool itself: A: out (Float64Array). Writes out[i] = i * P[0] over the
 * range and throws an Error when the range holds the index P[1] (P[1] < 0: never), so a test can
 * see a worker's error reach the main thread.
 */
export function testKernel(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const out = A[0] as Float64Array;
  const bad = P[1]!;
  let sum = 0;
  for (let i = lo; i < hi; i++) {
    if (i === bad) throw new Error(`test kernel: index ${i} is the bad index`);
    out[i] = i * P[0]!;
    sum += i;
  }
  return ids === null ? sum : sum;
}

/**
 * Every kernel a world's thread pool can run; the pool tells its workers a kernel by its place here.
 * @category Threads
 */
export const KERNELS: readonly Kernel[] = /* @__PURE__ */ Object.freeze([
  sie2,
  sie3,
  gravityScale,
  velocityDamping,
  testKernel,
  finiteProbe,
  barnesHutWalk,
  treeGather,
  mortonKeysHist,
  treeForces,
  ballPairs,
  ballContacts,
  mortonBucketSort,
  treeMoments,
  mortonScatter,
  centralForce,
  attractors,
  solveColored2D,
  prepareContactRows,
  gatherFill,
  approachSpeeds,
  finishBodies,
  restitutionColored,
  stripCut2D,
  warmStartTable,
  stripPlan2D,
]);
