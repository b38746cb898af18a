/**
 * The warm-start cache's hash table (contacts.ts) built by a thread kernel (step/kernel-table.ts rules:
 * self-contained, the worker threads run its source text): storeWarmStart runs it on the calling
 * thread, and a threaded world on a worker while the calling thread finishes the step
 * (solver/stages-threads.ts storeWarmStartOnThreads), so the table is the same either way.
 */

import type { KernelArray } from '../threads/kernel-types.js';
import * as WARM from './slots/warm-start.js';

/**
 * Fills the warm-start table of P[WARM.ROWS] contact rows: slots zeroed, then each row i stored as i + 1 at
 * the first free slot from hashKey(kind, a, b, feature) (contacts.ts: the hash and linear probing that
 * findWarmStart and the preparation kernel read the table with). The whole table is built on the thread whose range is
 * not empty (lo < hi); other ranges do nothing. A and P: the WARM slots (solver/slots/warm-start.ts).
 * Returns 0.
 * @category Collision
 */
export function warmStartTable(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, lo: number, hi: number): number {
  if (lo >= hi) return 0;
  const slots = A[WARM.SLOTS] as Int32Array,
    kind = A[WARM.KIND] as Uint8Array,
    CA = A[WARM.A] as Int32Array,
    CB = A[WARM.B] as Int32Array,
    F = A[WARM.FEATURE] as Int32Array;
  const n = P[WARM.ROWS]!,
    size = P[WARM.SLOT_COUNT]!,
    mask = size - 1;
  slots.fill(0, 0, size);
  for (let i = 0; i < n; i++) {
    let h = Math.imul(CA[i]! ^ (kind[i]! << 28), 0x9e3779b1);
    h ^= Math.imul(CB[i]!, 0x85ebca77);
    h ^= Math.imul(F[i]!, 0xc2b2ae3d);
    h ^= h >>> 15;
    let s = (Math.imul(h, 0x27d4eb2f) >>> 0) & mask;
    while (slots[s] !== 0) s = (s + 1) & mask;
    slots[s] = i + 1;
  }
  return 0;
}
