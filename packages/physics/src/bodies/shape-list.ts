/**
 * A body's shapes form a singly linked list: first[body] is its first extra shape, next[shape] the
 * shape after it, 0 the end (the 2D and 3D shape stores both keep their lists so).
 */

/**
 * Takes `shape` out of `body`'s list (first, next: by entity slot); does nothing when the list does
 * not hold it. The shape's own `next` is left for the caller to clear.
 */
export function unlinkShape(first: Int32Array, next: Int32Array, body: number, shape: number): void {
  if (first[body] === shape) {
    first[body] = next[shape]!;
    return;
  }
  for (let e = first[body]!; e !== 0; e = next[e]!)
    if (next[e] === shape) {
      next[e] = next[shape]!;
      return;
    }
}
