/**
 * The loops of the Barnes-Hut build (forces/barnes-hut/tree.ts) as thread kernels (step/kernel-table.ts:
 * self-contained functions the worker threads also run as source text): gathering the bodies'
 * positions and masses with their bounding box, the Morton sort (keys, buckets of the first digit,
 * each bucket sorted) with the bodies put into tree order, and adding m g to the force accumulators
 * (the nodes' moments are in moments.ts). Each body's arithmetic is the same on any thread, the bounding box
 * is a min and max (exact in any order) and the sorted order is that of a stable sort, so the
 * results do not depend on the number of threads.
 */

import type { KernelArray } from '../../threads/kernel-types.js';
import * as BOX from './bounds.js';
import * as SORT from './slots/morton-sort.js';
import * as TREE_FORCES from './slots/tree-forces.js';
import * as TREE_GATHER from './slots/tree-gather.js';

/**
 * Gathers body i = ids[i]'s Position and Mass into dense arrays (index i; z only in 3D) and the
 * range's bounding box (at `part`: forces/barnes-hut/bounds.ts; z = 0 bounds in 2D). A and P:
 * forces/barnes-hut/slots/tree-gather.ts. Returns 0.
 * @category Forces
 */
export function treeGather(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const px = A[TREE_GATHER.PX] as Float64Array,
    py = A[TREE_GATHER.PY] as Float64Array,
    pz = A[TREE_GATHER.PZ] as Float64Array,
    m = A[TREE_GATHER.MASS] as Float64Array;
  const gx = A[TREE_GATHER.GX] as Float64Array,
    gy = A[TREE_GATHER.GY] as Float64Array,
    gz = A[TREE_GATHER.GZ] as Float64Array,
    gm = A[TREE_GATHER.GM] as Float64Array;
  const box = A[TREE_GATHER.BOX] as Float64Array,
    ge = A[TREE_GATHER.ENTS] as Int32Array;
  const is3D = P[TREE_GATHER.DIMENSIONS] === 3,
    list = ids as Int32Array;
  let minX = Infinity,
    minY = Infinity,
    minZ = Infinity,
    maxX = -Infinity,
    maxY = -Infinity,
    maxZ = -Infinity;
  let bad = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const x = px[e]!,
      y = py[e]!;
    gx[i] = x;
    gy[i] = y;
    gm[i] = m[e]!;
    ge[i] = e;
    if (x < minX) minX = x;
    if (x > maxX) maxX = x;
    if (y < minY) minY = y;
    if (y > maxY) maxY = y;
    if (x - x !== 0 || y - y !== 0) bad = 1; // NaN or infinite
    if (is3D) {
      const z = pz[e]!;
      gz[i] = z;
      if (z < minZ) minZ = z;
      if (z > maxZ) maxZ = z;
      if (z - z !== 0) bad = 1;
    }
  }
  if (!is3D) {
    minZ = 0;
    maxZ = 0;
  }
  const o = part * BOX.RANGE_STRIDE;
  box[o + BOX.MIN_X] = minX;
  box[o + BOX.MIN_Y] = minY;
  box[o + BOX.MIN_Z] = minZ;
  box[o + BOX.MAX_X] = maxX;
  box[o + BOX.MAX_Y] = maxY;
  box[o + BOX.MAX_Z] = maxZ;
  box[o + BOX.NON_FINITE] = bad;
  return 0;
}

/**
 * Most bits of the key sort's first (most significant) digit, and its most buckets. The sort takes
 * about log2(n / 8) bits (sortDigitBits), so that a bucket holds a few bodies on average.
 * @category Forces
 */
export const SORT_RADIX_BITS = 16,
  SORT_RADIX = 1 << SORT_RADIX_BITS;

/**
 * Bits of the key sort's first digit for n bodies: about log2(n / 8), within 1 .. SORT_RADIX_BITS.
 * @category Forces
 */
export function sortDigitBits(n: number): number {
  return Math.min(SORT_RADIX_BITS, Math.max(1, Math.ceil(Math.log2(Math.max(2, n / 8)))));
}

/**
 * Morton sort, pass 1: the Morton (Z-order) keys of a part's bodies in the root cube (16 bits per
 * axis interleaved in 2D, 10 in 3D; forces/barnes-hut/tree.ts) and the part's histogram of their first digit
 * (key >>> P[SORT.SHIFT]). A (the KEYS_ slots) and P: forces/barnes-hut/slots/morton-sort.ts. Returns 0.
 * @category Forces
 */
export function mortonKeysHist(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[SORT.KEYS_X] as Float64Array,
    y = A[SORT.KEYS_Y] as Float64Array,
    z = A[SORT.KEYS_Z] as Float64Array;
  const key = A[SORT.KEYS_KEY] as Uint32Array,
    hist = A[SORT.KEYS_HIST] as Int32Array;
  const x0 = P[SORT.X0]!,
    y0 = P[SORT.Y0]!,
    z0 = P[SORT.Z0]!,
    scale = P[SORT.SCALE]!,
    top = P[SORT.TOP]!,
    is3D = P[SORT.DIMENSIONS] === 3;
  const n = P[SORT.COUNT]!,
    parts = P[SORT.PARTS]!,
    topShift = P[SORT.SHIFT]!,
    R = 1 << P[SORT.BITS]!;
  for (let part = lo; part < hi; part++) {
    const b0 = Math.floor((n * part) / parts),
      b1 = Math.floor((n * (part + 1)) / parts),
      base = part * R;
    hist.fill(0, base, base + R);
    for (let i = b0; i < b1; i++) {
      let kx = Math.floor((x[i]! - x0) * scale),
        ky = Math.floor((y[i]! - y0) * scale);
      kx = kx > 0 ? (kx < top ? kx : top) : 0;
      ky = ky > 0 ? (ky < top ? ky : top) : 0;
      let k: number;
      if (is3D) {
        let kz = Math.floor((z[i]! - z0) * scale);
        kz = kz > 0 ? (kz < top ? kz : top) : 0;
        // Spread the low 10 bits of each coordinate to every third bit.
        kx &= 0x3ff;
        kx = (kx | (kx << 16)) & 0x030000ff;
        kx = (kx | (kx << 8)) & 0x0300f00f;
        kx = (kx | (kx << 4)) & 0x030c30c3;
        kx = (kx | (kx << 2)) & 0x09249249;
        ky &= 0x3ff;
        ky = (ky | (ky << 16)) & 0x030000ff;
        ky = (ky | (ky << 8)) & 0x0300f00f;
        ky = (ky | (ky << 4)) & 0x030c30c3;
        ky = (ky | (ky << 2)) & 0x09249249;
        kz &= 0x3ff;
        kz = (kz | (kz << 16)) & 0x030000ff;
        kz = (kz | (kz << 8)) & 0x0300f00f;
        kz = (kz | (kz << 4)) & 0x030c30c3;
        kz = (kz | (kz << 2)) & 0x09249249;
        k = kx | (ky << 1) | (kz << 2);
      } else {
        // Spread the low 16 bits of each coordinate to the even bits.
        kx &= 0xffff;
        kx = (kx | (kx << 8)) & 0x00ff00ff;
        kx = (kx | (kx << 4)) & 0x0f0f0f0f;
        kx = (kx | (kx << 2)) & 0x33333333;
        kx = (kx | (kx << 1)) & 0x55555555;
        ky &= 0xffff;
        ky = (ky | (ky << 8)) & 0x00ff00ff;
        ky = (ky | (ky << 4)) & 0x0f0f0f0f;
        ky = (ky | (ky << 2)) & 0x33333333;
        ky = (ky | (ky << 1)) & 0x55555555;
        k = (kx | (ky << 1)) >>> 0;
      }
      key[i] = k;
      hist[base + (k >>> topShift)]!++;
    }
  }
  return ids === null ? 0 : 0;
}

/**
 * Adds the tree's gravity to the bodies' forces: F_e += m g for e = ids[i], g the field at body i's
 * slot. A: forces/barnes-hut/slots/tree-forces.ts; P unused. Returns 0.
 * @category Forces
 */
export function treeForces(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const fx = A[TREE_FORCES.FX] as Float64Array,
    fy = A[TREE_FORCES.FY] as Float64Array,
    fz = A[TREE_FORCES.FZ] as Float64Array,
    slot = A[TREE_FORCES.SLOT] as Int32Array;
  const m = A[TREE_FORCES.MASS] as Float64Array,
    ax = A[TREE_FORCES.AX] as Float64Array,
    ay = A[TREE_FORCES.AY] as Float64Array,
    az = A[TREE_FORCES.AZ] as Float64Array;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!,
      s = slot[i]!,
      w = m[s]!;
    fx[e] = fx[e]! + w * ax[s]!;
    fy[e] = fy[e]! + w * ay[s]!;
    fz[e] = fz[e]! + w * az[s]!;
  }
  return P.length * 0;
}

/**
 * Morton sort, pass 2: a part's bodies to their first digit's bucket, in order (so the pass is
 * stable: within a bucket the bodies keep their input order). A (the SCATTER_ slots) and P:
 * forces/barnes-hut/slots/morton-sort.ts. The parts must be those of mortonKeysHist. Returns 0.
 * @category Forces
 */
export function mortonScatter(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const key = A[SORT.SCATTER_KEY] as Uint32Array,
    key2 = A[SORT.SCATTER_KEY2] as Uint32Array,
    idx2 = A[SORT.SCATTER_IDX2] as Int32Array,
    offset = A[SORT.SCATTER_OFFSET] as Int32Array;
  const n = P[SORT.COUNT]!,
    parts = P[SORT.PARTS]!,
    topShift = P[SORT.SHIFT]!,
    R = 1 << P[SORT.BITS]!;
  for (let part = lo; part < hi; part++) {
    const b0 = Math.floor((n * part) / parts),
      b1 = Math.floor((n * (part + 1)) / parts),
      base = part * R;
    for (let i = b0; i < b1; i++) {
      const k = key[i]!,
        d = offset[base + (k >>> topShift)]!++;
      key2[d] = k;
      idx2[d] = i;
    }
  }
  return ids === null ? 0 : 0;
}

/**
 * Morton sort, pass 3, and the bodies into tree order: each bucket of a part (its bodies share the
 * first digit) sorted by the bits below it, stably (insertion for SORT.BUCKET_INSERTION_MAX keys or
 * fewer, else least-significant-digit radix passes of 8 bits (SORT.BUCKET_RADIX digits), each skipped when all its digits are
 * equal), so the keys end in (key, input index) order, the order of a stable sort of the whole
 * array; then slot s of the bucket gets input body perm[s]'s position and mass.
 * A (the BUCKETS_ slots) and P: forces/barnes-hut/slots/morton-sort.ts. Returns 0.
 * @category Forces
 */
export function mortonBucketSort(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const key2 = A[SORT.BUCKETS_KEY2] as Uint32Array,
    idx2 = A[SORT.BUCKETS_IDX2] as Int32Array,
    key = A[SORT.BUCKETS_KEY] as Uint32Array,
    perm = A[SORT.BUCKETS_PERM] as Int32Array;
  const bucket = A[SORT.BUCKETS_FIRST] as Int32Array,
    group = A[SORT.BUCKETS_GROUP] as Int32Array,
    local = A[SORT.BUCKETS_LOCAL] as Int32Array;
  const x = A[SORT.BUCKETS_X] as Float64Array,
    y = A[SORT.BUCKETS_Y] as Float64Array,
    z = A[SORT.BUCKETS_Z] as Float64Array,
    m = A[SORT.BUCKETS_MASS] as Float64Array;
  const tx = A[SORT.BUCKETS_TX] as Float64Array,
    ty = A[SORT.BUCKETS_TY] as Float64Array,
    tz = A[SORT.BUCKETS_TZ] as Float64Array,
    tm = A[SORT.BUCKETS_TM] as Float64Array;
  const is3D = P[SORT.DIMENSIONS] === 3,
    topShift = P[SORT.SHIFT]!;
  for (let part = lo; part < hi; part++) {
    const base = part * SORT.BUCKET_RADIX;
    for (let r = group[part]!, rEnd = group[part + 1]!; r < rEnd; r++) {
      const a = bucket[r]!,
        b = bucket[r + 1]!;
      if (a === b) continue;
      if (b - a <= SORT.BUCKET_INSERTION_MAX) {
        // Insertion into key, perm (strictly larger keys move up: stable).
        for (let s = a; s < b; s++) {
          const k = key2[s]!,
            v = idx2[s]!;
          let j = s;
          while (j > a && key[j - 1]! > k) {
            key[j] = key[j - 1]!;
            perm[j] = perm[j - 1]!;
            j--;
          }
          key[j] = k;
          perm[j] = v;
        }
      } else {
        // LSD radix passes over the bits below the first digit, between (key2, idx2) and (key, perm).
        let inKey2 = true;
        for (let shift = 0; shift < topShift; shift += 8) {
          const sk = inKey2 ? key2 : key,
            si = inKey2 ? idx2 : perm,
            dk = inKey2 ? key : key2,
            di = inKey2 ? perm : idx2;
          local.fill(0, base, base + SORT.BUCKET_RADIX);
          for (let s = a; s < b; s++) local[base + ((sk[s]! >>> shift) & 255)]!++;
          if (local[base + ((sk[a]! >>> shift) & 255)] === b - a) continue;
          let acc = a;
          for (let d = 0; d < SORT.BUCKET_RADIX; d++) {
            const c = local[base + d]!;
            local[base + d] = acc;
            acc += c;
          }
          for (let s = a; s < b; s++) {
            const k = sk[s]!,
              d = local[base + ((k >>> shift) & 255)]!++;
            dk[d] = k;
            di[d] = si[s]!;
          }
          inKey2 = !inKey2;
        }
        if (inKey2)
          for (let s = a; s < b; s++) {
            key[s] = key2[s]!;
            perm[s] = idx2[s]!;
          }
      }
      for (let s = a; s < b; s++) {
        const i = perm[s]!;
        tx[s] = x[i]!;
        ty[s] = y[i]!;
        tm[s] = m[i]!;
        if (is3D) tz[s] = z[i]!;
      }
    }
  }
  return ids === null ? 0 : 0;
}
