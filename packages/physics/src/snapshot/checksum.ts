/**
 * The checksum of a snapshot: a 64-bit hash (16 hex digits) of its header (as JSON, without the
 * checksum field) and the first `bytes` bytes of its buffer, written by `snapshot` and checked by
 * `restore` before anything else is read. It detects damage (bytes overwritten, a truncated or
 * extended buffer, a header field edited): any change of the covered data changes the hash except
 * with probability about 2^-64. It is not a signature: whoever edits a snapshot on purpose can compute
 * it again, which is why restore also checks the values it restores (snapshot/checks.ts).
 *
 * Hash: two independent 32-bit lanes of MurmurHash3's block mix (Appleby, public domain), each fed the
 * data's 32-bit words (JSON as UTF-16 code units, two a word), with MurmurHash3's finaliser per lane.
 * Four words a loop iteration, alternating lanes, so the multiplies of the two lanes overlap.
 */

const C1 = 0xcc9e2d51;
const C2 = 0x1b873593;

/** The lanes' state, carried from one feed to the next. */
interface Lanes {
  h1: number;
  h2: number;
  /** Words fed so far (for the finaliser). */
  n: number;
}

function mix(h: number, k: number): number {
  k = Math.imul(k, C1);
  k = (k << 15) | (k >>> 17);
  k = Math.imul(k, C2);
  h ^= k;
  h = (h << 13) | (h >>> 19);
  return (Math.imul(h, 5) + 0xe6546b64) | 0;
}

function fmix(h: number): number {
  h ^= h >>> 16;
  h = Math.imul(h, 0x85ebca6b);
  h ^= h >>> 13;
  h = Math.imul(h, 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}

/** Feeds the 32-bit words `w[0 .. n)` into the lanes. */
function feedWords(s: Lanes, w: Int32Array, n: number): void {
  let h1 = s.h1,
    h2 = s.h2,
    i = 0;
  for (; i + 4 <= n; i += 4) {
    h1 = mix(h1, w[i]!);
    h2 = mix(h2, w[i + 1]!);
    h1 = mix(h1, w[i + 2]!);
    h2 = mix(h2, w[i + 3]!);
  }
  for (; i < n; i++) {
    if ((i & 1) === 0) h1 = mix(h1, w[i]!);
    else h2 = mix(h2, w[i]!);
  }
  s.h1 = h1;
  s.h2 = h2;
  s.n += n;
}

/** Feeds bytes `u8[0 .. n)`: whole 32-bit words where aligned, the last 1 to 3 bytes as one word. */
function feedBytes(s: Lanes, u8: Uint8Array, n: number): void {
  const whole = n >> 2;
  if ((u8.byteOffset & 3) === 0) feedWords(s, new Int32Array(u8.buffer, u8.byteOffset, whole), whole);
  else {
    const copy = new Int32Array(whole);
    new Uint8Array(copy.buffer).set(u8.subarray(0, 4 * whole));
    feedWords(s, copy, whole);
  }
  if ((n & 3) !== 0) {
    let k = 0;
    for (let i = 4 * whole; i < n; i++) k |= u8[i]! << (8 * (i - 4 * whole));
    feedWords(s, Int32Array.of(k, n), 2);
  }
}

/** Feeds a string's UTF-16 code units, two a word, and its length. */
function feedString(s: Lanes, text: string): void {
  const n = text.length;
  const w = new Int32Array((n + 1) >> 1);
  for (let i = 0; i + 1 < n; i += 2) w[i >> 1] = text.charCodeAt(i) | (text.charCodeAt(i + 1) << 16);
  if ((n & 1) !== 0) w[n >> 1] = text.charCodeAt(n - 1);
  feedWords(s, w, w.length);
  feedWords(s, Int32Array.of(n), 1);
}

/**
 * The checksum of a snapshot's header `fields` (every field but the checksum, as `JSON.stringify`
 * writes them: the same after a trip through JSON, which keeps key order and numbers exactly) and
 * of `buffer`'s first `bytes` bytes. @returns 16 lower-case hex digits.
 * @category Snapshots
 */
export function snapshotChecksum(fields: object, buffer: ArrayBuffer, bytes: number): string {
  const s: Lanes = { h1: 0x9747b28c, h2: 0x5bd1e995, n: 0 };
  feedString(s, JSON.stringify(fields));
  feedBytes(s, new Uint8Array(buffer, 0, bytes), bytes);
  const h1 = fmix(s.h1 ^ s.n),
    h2 = fmix(s.h2 ^ Math.imul(s.n, 0x9e3779b9));
  return h1.toString(16).padStart(8, '0') + h2.toString(16).padStart(8, '0');
}
