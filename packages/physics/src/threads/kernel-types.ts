/**
 * The types of a thread kernel (step/kernel-table.ts), in a module of their own so that kernels kept beside
 * their system (forces/barnes-hut/walk.ts) can name them without importing the kernel table.
 */

/**
 * A typed array a kernel reads or writes.
 * @category Threads
 */
export type KernelArray = Float64Array | Int32Array | Uint32Array | Uint16Array | Uint8Array;

/**
 * The signature every kernel has: `A` the typed arrays in the order its caller documents, `P` the
 * scalar parameters, `ids` the entity ids of the loop (null: dense ids lo + 1 .. hi, or a loop
 * that is not over entities), [lo, hi) the range this thread runs, `part` the index of that range
 * (the thread's index in the pool, 0 for the calling thread), for kernels that write one result a
 * range. Returns a number the caller sums over the ranges.
 * @category Threads
 */
export type Kernel = (
  A: KernelArray[],
  P: Float64Array,
  ids: Int32Array | null,
  lo: number,
  hi: number,
  part: number,
  helpers: readonly KernelHelper[],
) => number;

/**
 * A function a kernel calls (solver/kernel-helpers.ts KERNEL_HELPERS), self-contained like a kernel; every caller of a
 * kernel passes the list as its last argument (the workers their own copies, from source text), so a
 * kernel reaches its helpers by index and names nothing outside itself.
 */
// biome-ignore lint/suspicious/noExplicitAny: helpers take any typed arrays and numbers
export type KernelHelper = (...args: any[]) => unknown;
