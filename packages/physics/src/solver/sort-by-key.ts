/** A stable merge sort of indices by a key array (the impact stage's order of contacts by time of impact). */

/** Scratch of `sortByKey`: the merge sort's two work arrays. Not world state. */
let sortWork1 = new Int32Array(256),
  sortWork2 = new Int32Array(256);

/**
 * Sorts order[0, n) by key[order[k]] ascending (key: impact times, s), with the permutation of V8's
 * order.subarray(0, n).sort((x, y) => key[x] - key[y]), which this replaced: V8 sorts a typed array
 * with a comparator by a stable top-down merge sort (into a copy, halving at from + (to - from) / 2,
 * taking the left element unless the comparison is > 0, a NaN comparison counting as 0), so ties and
 * even NaN keys come out in the same order. Without the closure and the boxed number each of its
 * calls returned (~250 kB a step at 20,000 balls) and the builtin's two work arrays. n >= 0 and
 * n <= order.length; order's entries index key. Exported for its test (impact-order.test.ts).
 * @category Collision
 */
export function sortByKey(order: Int32Array, key: Float64Array, n: number): void {
  if (n < 2) return;
  if (sortWork1.length < n) {
    const len = Math.max(n, 2 * sortWork1.length);
    sortWork1 = new Int32Array(len);
    sortWork2 = new Int32Array(len);
  }
  const w1 = sortWork1,
    w2 = sortWork2;
  for (let k = 0; k < n; k++) {
    const v = order[k]!;
    w1[k] = v;
    w2[k] = v;
  }
  mergeSortRange(w2, 0, n, w1, key);
  for (let k = 0; k < n; k++) order[k] = w1[k]!;
}

/**
 * Merge sort of [from, to) (to - from >= 2) into `target`, `source` holding the same elements there on
 * entry and used as the work array (the halves are sorted into it, then merged into target).
 */
function mergeSortRange(source: Int32Array, from: number, to: number, target: Int32Array, key: Float64Array): void {
  const middle = from + ((to - from) >>> 1);
  if (middle - from > 1) mergeSortRange(target, from, middle, source, key);
  if (to - middle > 1) mergeSortRange(target, middle, to, source, key);
  let left = from,
    right = middle;
  for (let k = from; k < to; k++) {
    if (left < middle && right >= to) target[k] = source[left++]!;
    else if (left < middle) {
      const l = source[left]!,
        r = source[right]!;
      if (!(key[l]! - key[r]! > 0)) {
        target[k] = l;
        left++;
      } else {
        target[k] = r;
        right++;
      }
    } else target[k] = source[right++]!;
  }
}
