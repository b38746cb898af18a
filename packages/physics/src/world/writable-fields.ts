/**
 * Fields writable from an object's creation on.
 *
 * V8 treats a field written only when its object was made as constant, and optimised code may rely
 * on that (it reads the field once and keeps the value). The first other write to the field marks
 * it writable and throws away every optimised function that relied on it, to be interpreted and
 * compiled again. For the state of a world that a step writes (counts, buffers grown or swapped,
 * caches filled on first use), that first write happens in the world's first step, while that step
 * compiles the code that reads it: the code compiled early in the step was thrown away late in it
 * (--trace-deopt: "marking dependent code ... reason: code dependencies") and the next steps ran
 * it in the interpreter again. Written once more where the object is made, before anything is
 * compiled against it, the field is writable from the start.
 */

import { describe } from '../validation/validate.js';

/**
 * Writes into each of `keys` of `target` another value of the same kind (a number, a boolean, an
 * empty typed array of the field's type, an empty Set or Map; null for undefined and back), then the
 * field's value back, so that V8 treats the fields as writable from here on (see the top of
 * writable-fields.ts). The values are unchanged.
 * @param target - The object whose fields a later step writes.
 * @param keys - Its fields to mark writable.
 * @throws TypeError if a field holds another kind of value (a plain object or array: swap it with
 *   one of its kind instead, as createShapeCollisionState does).
 */
export function markWritable<T extends object>(target: T, keys: readonly (keyof T & string)[]): void {
  const o = target as Record<string, unknown>;
  for (const k of keys) {
    const v = o[k];
    o[k] = standIn(v, k);
    o[k] = v;
  }
}

/** An empty typed array of each typed-array type standIn has met, keyed by its constructor. */
const EMPTY = new Map<new (n: number) => ArrayBufferView, ArrayBufferView>();

/** A value of the same kind as `v` that is not `v` (markWritable). */
function standIn(v: unknown, key: string): unknown {
  if (typeof v === 'number') return v === 0 ? 1 : 0;
  if (typeof v === 'boolean') return !v;
  if (v === undefined) return null;
  if (v === null) return undefined;
  if (ArrayBuffer.isView(v) && !(v instanceof DataView)) {
    // One empty array of each type, made once: it stands in only until the field is written back.
    const type = v.constructor as new (n: number) => ArrayBufferView;
    let empty = EMPTY.get(type);
    if (empty === undefined) EMPTY.set(type, (empty = new type(0)));
    return empty;
  }
  if (v instanceof Set) return new Set();
  if (v instanceof Map) return new Map();
  throw new TypeError(`markWritable: field ${key} holds ${describe(v)}, not a number, boolean, typed array, Set, Map, undefined or null`);
}
