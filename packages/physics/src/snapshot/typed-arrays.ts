/** Typed-array helpers of the snapshot format: the array types it stores, how much of an array is in use, and fast zero and uniformity tests. */

export type TypedArray =
  | Float64Array
  | Float32Array
  | Int32Array
  | Uint32Array
  | Int16Array
  | Uint16Array
  | Int8Array
  | Uint8Array
  | Uint8ClampedArray;
export const TYPED: Record<string, new (b: ArrayBuffer | number | ArrayLike<number>) => TypedArray> = {
  Float64Array,
  Float32Array,
  Int32Array,
  Uint32Array,
  Int16Array,
  Uint16Array,
  Int8Array,
  Uint8Array,
  Uint8ClampedArray,
};

/**
 * Length of `a`'s first `end` elements up to the last one whose bits are not all zero (so -0 and NaN
 * count as values). The trailing zeros are found by `zeroTail64` (64-bit words; BigInt64Array
 * compares compile without allocating, about twice as fast as OR-ing 32-bit words here) or
 * `zeroTail32` as the array's alignment allows; the bytes past the last whole word and within the last
 * non-zero word are judged by their bits. Each scan loop is a small function of its own that every call
 * runs, so it never lacks type feedback when optimised (one scan with all the branches inline fell into
 * a deoptimisation loop in a 100,000-ball world, and unoptimised BigInt reads allocate).
 */
export function usedLength(a: TypedArray, end: number): number {
  // Where the host has a native byte comparison (Node's Buffer.compare, a memcmp, several times the
  // speed of the word loops below), whole blocks of trailing zeros are dropped with it first; the loops
  // then scan at most one block.
  const bytesPer = a.BYTES_PER_ELEMENT;
  if (nativeCompare !== undefined && end * bytesPer > ZERO_BLOCK.length) {
    const u8 = new Uint8Array(a.buffer, a.byteOffset, end * bytesPer);
    let hi = u8.length;
    while (hi > 0) {
      const lo = Math.max(0, hi - ZERO_BLOCK.length);
      if (nativeCompare(u8.subarray(lo, hi), hi - lo === ZERO_BLOCK.length ? ZERO_BLOCK : ZERO_BLOCK.subarray(0, hi - lo)) !== 0) break;
      hi = lo;
    }
    end = hi / bytesPer; // blocks are whole elements (the block length is a multiple of 8)
  }
  return usedLengthScan(a, end);
}

/**
 * A native comparison of two byte arrays (memcmp: negative, 0 or positive) where the host has one
 * (Node's `Buffer.compare`, which takes Uint8Arrays); undefined elsewhere (a page), where the
 * snapshot's scans use the JS loops alone. Only equality is used, so the result is the same either way.
 */
export const nativeCompare: ((a: Uint8Array, b: Uint8Array) => number) | undefined = (() => {
  const B = (globalThis as { Buffer?: { compare?: unknown } }).Buffer;
  return typeof B?.compare === 'function' ? (B.compare as (a: Uint8Array, b: Uint8Array) => number) : undefined;
})();
/** Zeros compared against by `usedLength` (64 kB: a multiple of every element size). */
const ZERO_BLOCK = new Uint8Array(nativeCompare !== undefined ? 65536 : 0);

/**
 * Makes elements `from` .. `to`-1 of `a` zero (all bits: +0). Where the host compares natively (see
 * nativeCompare), only the 64 kB blocks that are not all zero already are written: restore zeroes
 * ~14 MB of per-entity stores past their stored part in a 100,000-ball world, most of it zero already
 * (forces, torques, z components), and reading it is cheaper than writing it.
 */
export function zeroFill(a: TypedArray, from: number, to: number): void {
  const bytes = a.BYTES_PER_ELEMENT;
  if (nativeCompare === undefined || (to - from) * bytes <= ZERO_BLOCK.length) {
    a.fill(0, from, to);
    return;
  }
  const u8 = new Uint8Array(a.buffer, a.byteOffset + from * bytes, (to - from) * bytes);
  const B = ZERO_BLOCK.length;
  for (let lo = 0; lo < u8.length; lo += B) {
    const hi = Math.min(u8.length, lo + B);
    if (nativeCompare(u8.subarray(lo, hi), hi - lo === B ? ZERO_BLOCK : ZERO_BLOCK.subarray(0, hi - lo)) !== 0) u8.fill(0, lo, hi);
  }
}

/** Whether elements 1 .. n-1 of `a` have the same bits, by the native comparison (false without one, or for n < 3: then the caller writes). */
export function sameFrom1Native(a: TypedArray, n: number): boolean {
  if (nativeCompare === undefined || n < 3) return false;
  const bytes = a.BYTES_PER_ELEMENT;
  const u8 = new Uint8Array(a.buffer, a.byteOffset, n * bytes);
  return nativeCompare(u8.subarray(bytes, (n - 1) * bytes), u8.subarray(2 * bytes, n * bytes)) === 0;
}

/** `usedLength` by JS loops alone (see there). */
function usedLengthScan(a: TypedArray, end: number): number {
  const bytes = a.BYTES_PER_ELEMENT;
  const total = end * bytes;
  if ((a.byteOffset & 3) !== 0) {
    let n = end;
    while (n > 0 && a[n - 1] === 0 && !Object.is(a[n - 1], -0)) n--;
    return n;
  }
  const whole = total & ~3;
  // The bytes past the last whole 4-byte word (1- and 2-byte elements), by their bits.
  if (whole !== total) {
    const tail = new Uint8Array(a.buffer, a.byteOffset + whole, total - whole);
    for (let k = tail.length - 1; k >= 0; k--) if (tail[k] !== 0) return Math.ceil((whole + k + 1) / bytes);
  }
  let used: number; // bytes
  if ((a.byteOffset & 7) === 0) {
    const w8 = whole & ~7;
    used =
      w8 !== whole && new Int32Array(a.buffer, a.byteOffset + w8, 1)[0] !== 0
        ? whole
        : 8 * zeroTail64(new BigInt64Array(a.buffer, a.byteOffset, w8 >> 3), w8 >> 3);
  } else {
    used = 4 * zeroTail32(new Int32Array(a.buffer, a.byteOffset, whole >> 2), whole >> 2);
  }
  if (bytes < 8 && used > 0) {
    // Smaller elements: up to the last non-zero byte of the last non-zero word (else a store of one
    // repeated value would gain a 0 and lose its repeat encoding).
    const k0 = Math.min(8, used);
    const last = new Uint8Array(a.buffer, a.byteOffset + used - k0, k0);
    let k = k0;
    while (k > 1 && last[k - 1] === 0) k--;
    used -= k0 - k;
  }
  return Math.ceil(used / bytes);
}

/** How many of the first `n` 64-bit words of `w` remain when its trailing zero words are dropped. */
function zeroTail64(w: BigInt64Array, n: number): number {
  while (n > 0 && w[n - 1] === 0n) n--;
  return n;
}

/** How many of the first `n` 32-bit words of `w` remain when its trailing zero words are dropped (eight OR-ed a step, then one). */
function zeroTail32(w: Int32Array, n: number): number {
  while (n >= 8 && (w[n - 1]! | w[n - 2]! | w[n - 3]! | w[n - 4]! | w[n - 5]! | w[n - 6]! | w[n - 7]! | w[n - 8]!) === 0) n -= 8;
  while (n > 0 && w[n - 1] === 0) n--;
  return n;
}

/**
 * Whether elements 1 .. n-1 of `a` have the same bits (and are not NaN, whose payload a fill could
 * change). Compares 32-bit words XOR-ed against the pattern and OR-ed four at a time, or 64-bit words
 * (see usedLength). Arrays of 1- and 2-byte elements are not checked (false).
 */
export function uniformFrom1(a: TypedArray, n: number): boolean {
  const bytes = a.BYTES_PER_ELEMENT;
  if (bytes < 4 || (a.byteOffset & 3) !== 0) return false;
  const v = a[1]!;
  if (v !== v) return false;
  // Natively (see nativeCompare): elements 1 .. n-2 equal elements 2 .. n-1 exactly when 1 .. n-1 are all the same.
  if (nativeCompare !== undefined && n >= 3) {
    const u8 = new Uint8Array(a.buffer, a.byteOffset, n * bytes);
    return nativeCompare(u8.subarray(bytes, (n - 1) * bytes), u8.subarray(2 * bytes, n * bytes)) === 0;
  }
  const words = new Int32Array(a.buffer, a.byteOffset, (n * bytes) >> 2);
  if (bytes === 4) {
    const w = words[1]!;
    let i = 2;
    for (; i + 4 <= n; i += 4) if (((words[i]! ^ w) | (words[i + 1]! ^ w) | (words[i + 2]! ^ w) | (words[i + 3]! ^ w)) !== 0) return false;
    for (; i < n; i++) if (words[i] !== w) return false;
    return true;
  }
  // 8-byte elements: as 64-bit words where aligned (see usedLength), else element k is words 2k and 2k + 1.
  if ((a.byteOffset & 7) === 0) return sameFrom64(new BigInt64Array(a.buffer, a.byteOffset, n), n);
  const lo = words[2]!,
    hi = words[3]!;
  const m = 2 * n;
  let i = 4;
  for (; i + 4 <= m; i += 4)
    if (((words[i]! ^ lo) | (words[i + 1]! ^ hi) | (words[i + 2]! ^ lo) | (words[i + 3]! ^ hi)) !== 0) return false;
  for (; i < m; i += 2) if (words[i] !== lo || words[i + 1] !== hi) return false;
  return true;
}

/** Whether 64-bit words 2 .. n-1 of `w` equal word 1. */
function sameFrom64(w: BigInt64Array, n: number): boolean {
  const first = w[1]!;
  for (let i = 2; i < n; i++) if (w[i] !== first) return false;
  return true;
}

/** 1, 2, ..., at least the largest capacity restored into so far (see readIdLists, countingTo). */
export let counting = new Int32Array(0);

/** The shared list 1, 2, ..., at least `n` long (grown by doubling; its elements are never written elsewhere). */
export function countingTo(n: number): Int32Array {
  if (counting.length < n) {
    const next = new Int32Array(Math.max(n, 2 * counting.length));
    for (let k = 0; k < next.length; k++) next[k] = k + 1;
    counting = next;
  }
  return counting;
}

/**
 * Whether element i of `a` is i for i = 1 .. n-1 (n <= a.length): natively, elements 1 .. n-1
 * against the shared list 1, 2, ... (see countingTo), where the host compares natively; else a loop.
 */
export function iotaFrom1(a: Int32Array, n: number): boolean {
  if (n < 2 || a[1] !== 1 || a[n - 1] !== n - 1) return n < 2;
  if (nativeCompare !== undefined) {
    const ones = countingTo(n - 1);
    const x = new Uint8Array(a.buffer, a.byteOffset + 4, 4 * (n - 1));
    const y = new Uint8Array(ones.buffer, ones.byteOffset, 4 * (n - 1));
    return nativeCompare(x, y) === 0;
  }
  for (let i = 2; i < n - 1; i++) if (a[i] !== i) return false;
  return true;
}
