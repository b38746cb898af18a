/**
 * Kernel numbers (`KERNEL`), the index of each loop kernel in the kernel table (step/kernel-table.ts,
 * which says what a kernel is and the rules it follows). Systems name their kernels by these numbers;
 * the table itself is handed to a world's thread pool when the pool is made (step/enable-threads.ts), so a
 * program without threads does not bring the kernels in.
 */

export { KERNEL_HELPERS } from '../step/kernel-helpers.js';
export { KERNELS } from '../step/kernel-table.js';
export type { Kernel, KernelArray, KernelHelper } from './kernel-types.js';

/**
 * Kernel numbers: the index of each kernel in `KERNELS`.
 * @category Threads
 */
export const KERNEL = Object.freeze({
  sieForced2: 0,
  sieForced3: 1,
  sieFree2: 2,
  sieFree3: 3,
  gravityScale: 4,
  linearDragCalm: 5,
  test: 6,
  finiteProbe: 7,
  barnesHutWalk2: 8,
  barnesHutWalk3: 9,
  treeGather: 10,
  mortonKeysHist: 11,
  treeForces: 12,
  quadraticDragCalm: 13,
  angularDampingScalar: 14,
  ballPairs: 15,
  ballContacts: 16,
  mortonBucketSort: 17,
  treeMoments: 18,
  mortonScatter: 19,
  centralForce: 20,
  attractors: 21,
  solveColored2D: 22,
  prepareContacts2D: 23,
  gatherFill2D: 24,
  approach2D: 25,
  finishBodies2D: 26,
  restitutionColored2D: 27,
  stripCut2D: 28,
  warmStartTable: 29,
  stripPlan2D: 30,
});
