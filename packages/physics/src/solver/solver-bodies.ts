import { BodyType, type CollisionState } from '../collision/state.js';
import { isShared, sharedLike } from '../threads/pool.js';

/**
 * The solver's body list (`CollisionState.solverBodies`): every store of rows (ball contacts, 2D and
 * 3D manifolds, joints) gives the moving bodies of its rows a solver index, continuing the list.
 */

/**
 * `list` if it holds `n` entries, else a copy in an array of at least n (twice its length), on shared
 * memory if `list` is (a threaded 2D world's list, which its workers read: solver/coloring.ts). Callers grow
 * the list before their loops: growth runs only in a world's first steps, before V8 records type
 * feedback, and inside a loop it would be compiled as a deoptimisation that throws the whole loop back
 * to the interpreter in a later world.
 */
export function withRoom(list: Int32Array, n: number): Int32Array {
  if (list.length >= n) return list;
  const size = Math.max(n, 2 * list.length);
  const grown = isShared(list) ? sharedLike(list, size) : new Int32Array(size);
  grown.set(list);
  return grown;
}

/**
 * Gives the moving bodies (dynamic or kinematic in `cs.bodyType`) of the first `n` body pairs (A[i],
 * B[i]) a solver index, each body once a step (marked with `cs.solverStamp`), appended to
 * `cs.solverBodies` from `count` on, and writes each pair's indices to IA[i] and IB[i] (0, the static
 * row, for the world and fixed bodies). Returns the new count.
 */
export function joinSolverBodies(
  cs: CollisionState,
  A: Int32Array,
  B: Int32Array,
  IA: Int32Array,
  IB: Int32Array,
  n: number,
  count: number,
): number {
  // Room for both bodies of every pair, made before the loop (see withRoom).
  const list = withRoom(cs.solverBodies, count + 2 * n);
  cs.solverBodies = list;
  return joinRange(cs.solverMark, cs.solverIndex, cs.solverStamp, cs.bodyType, list, A, B, IA, IB, n, count);
}

/**
 * joinSolverBodies' loop (see there), on the arrays it passes; nothing is read before the loop: a
 * function called once a step runs its first call's first lines before V8 gives it type feedback, and
 * code compiled while that call's loop ran lacked feedback for them and was thrown away at the next
 * step's call.
 */
function joinRange(
  mark: Float64Array,
  index: Int32Array,
  stamp: number,
  type: Uint8Array,
  list: Int32Array,
  A: Int32Array,
  B: Int32Array,
  IA: Int32Array,
  IB: Int32Array,
  n: number,
  count: number,
): number {
  for (let i = 0; i < n; i++) {
    for (let side = 0; side < 2; side++) {
      const e = side === 0 ? A[i]! : B[i]!;
      const t = type[e]!;
      // Dynamic (0) or kinematic (1) in one comparison: with two, a short-circuit left the second without
      // type feedback while a pile's bodies were all dynamic, and the code compiled then was thrown away
      // when the first slept.
      let k = 0;
      if (e !== 0 && t <= BodyType.Kinematic) {
        if (mark[e] !== stamp) {
          mark[e] = stamp;
          index[e] = count;
          list[count++] = e;
        }
        k = index[e]!;
      }
      if (side === 0) IA[i] = k;
      else IB[i] = k;
    }
  }
  return count;
}
