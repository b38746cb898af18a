/**
 * Moves component stores onto SharedArrayBuffer, so worker threads can hold views of the same
 * memory. Used by `createPhysicsWorld` when `threads > 1`, for the stores made at creation and for
 * each lazily allocated store when it gets its arrays.
 */

import type { KernelArray } from './kernel-types.js';
import { sharedCopy } from './pool.js';

/**
 * Replaces every per-entity typed array of `store` (a field of length `capacity + 1`) by a copy on a
 * SharedArrayBuffer; fields of other lengths (empty lazy arrays, packed stores) stay as they are.
 * @category Threads
 */
export function shareStore(store: object, capacity: number): void {
  const rec = store as Record<string, unknown>;
  for (const key of Object.keys(rec)) {
    const a = rec[key];
    if (!ArrayBuffer.isView(a) || a instanceof DataView) continue;
    const arr = a as KernelArray;
    if (arr.length !== capacity + 1) continue;
    rec[key] = sharedCopy(arr);
  }
}

/**
 * `shareStore` on every store of `components`.
 * @category Threads
 */
export function shareStores(components: object, capacity: number): void {
  for (const store of Object.values(components as Record<string, unknown>)) {
    if (store !== null && typeof store === 'object' && !ArrayBuffer.isView(store)) shareStore(store, capacity);
  }
}
