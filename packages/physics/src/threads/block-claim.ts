/**
 * Claiming the blocks of a unit of work by flags, and waiting for a unit's turn, for kernels whose
 * threads share a unit's blocks (solver/coloring-kernel.ts, solver/stages-kernel.ts). Kernel helpers
 * (step/kernel-table.ts rules: self-contained; kernels reach them through KERNEL_HELPERS).
 */

/**
 * The next block thread `part` of `threads` takes of a unit of `count` blocks whose claim flags are
 * claim[base .. base + count - 1] (0 free, 1 taken; set with Atomics.compareExchange), or -1 when none
 * is left for it. A thread takes its own share first (the part-th of `threads` equal runs of blocks),
 * in order, then what is left of the others' shares, each from its end backward. In its own share the
 * first block it finds taken ends the share (the others take from its end backward, so the rest is
 * taken too); in another's it passes over taken blocks (another thief's) to the share's start, so
 * every idle thread can help with a slow thread's share, not only the first to reach it.
 * So each thread keeps to the same blocks from unit to unit where the units' blocks correspond (the
 * coloured solve's strips), and a late or slow thread holds up nothing the others can take.
 * `cursor` is the thread's own: [0] the share it is in (0: its own), [1] blocks of it tried; set both
 * to 0 before a unit's first call.
 * @category Threads
 */
export function claimBlock(claim: Int32Array, base: number, count: number, part: number, threads: number, cursor: Int32Array): number {
  let sh = cursor[0]!,
    k = cursor[1]!;
  while (sh < threads) {
    const t = (part + sh) % threads;
    const s0 = Math.floor((count * t) / threads),
      s1 = Math.floor((count * (t + 1)) / threads);
    if (k < s1 - s0) {
      const blk = sh === 0 ? s0 + k : s1 - 1 - k;
      if (Atomics.load(claim, base + blk) === 0 && Atomics.compareExchange(claim, base + blk, 0, 1) === 0) {
        cursor[0] = sh;
        cursor[1] = k + 1;
        return blk;
      }
      if (sh !== 0) {
        k++;
        continue;
      }
    }
    sh++;
    k = 0;
  }
  cursor[0] = sh;
  cursor[1] = 0;
  return -1;
}

/**
 * Waits until `bar[1]` (the blocks done, counted across the units) reaches `base`, the blocks of the
 * units before the one a thread is about to start: it spins, and when `wait` (the thread may block:
 * not a browser's main thread) it blocks in Atomics.wait after `spinMs` milliseconds of spinning,
 * 50 ms at a time, so waking it costs nothing while the others are about to finish and it holds no core
 * for long when they are not. Returns true when they are done, false when `bar[2]` is set (another
 * thread failed: the caller stops).
 * @category Threads
 */
export function awaitBlocks(bar: Int32Array, base: number, wait: boolean, spinMs: number): boolean {
  const clock = (globalThis as { performance?: { now(): number } }).performance;
  let t0 = -1,
    spins = 0;
  for (;;) {
    const done = Atomics.load(bar, 1);
    if (done >= base) return true;
    if (Atomics.load(bar, 2) !== 0) return false;
    if (!wait || (++spins & 255) !== 0) continue;
    const t = clock !== undefined ? clock.now() : 0;
    if (t0 < 0) t0 = t;
    if (clock === undefined || t - t0 >= spinMs) Atomics.wait(bar, 1, done, 50);
  }
}
