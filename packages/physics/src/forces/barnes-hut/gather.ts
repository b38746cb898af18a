/**
 * The loops of the Barnes-Hut build (forces/barnes-hut/tree.ts) as thread kernels (step/kernel-table.ts:
 * self-contained functions the worker threads also run as source text): gathering the bodies'
 * positions and masses with their bounding box, the Morton sort (keys, buckets of the first digit,
 * each bucket sorted) with the bodies put into tree order, the nodes' moments, and adding m g to the
 * force accumulators. Each body's and node's arithmetic is the same on any thread, the bounding box
 * is a min and max (exact in any order) and the sorted order is that of a stable sort, so the
 * results do not depend on the number of threads.
 */

import type { KernelArray } from '../../threads/kernel-types.js';

/**
 * Slots of the bounding box a range writes: min x, y, z, max x, y, z, non-finite flag, unused.
 * @category Forces
 */
export const BOX_STRIDE = 8;

/**
 * Gathers body i = ids[i]'s Position and Mass into dense arrays and the range's bounding box.
 * A: px, py, pz, m (component stores), gx, gy, gz, gm (out, index i; gz only in 3D), box (out,
 * BOX_STRIDE slots a range, at `part`), ge (Int32, out: ge[i] = ids[i]). P: 0 dimensions (2 or 3).
 * Writes z = 0 bounds in 2D. Returns 0.
 * @category Forces
 */
export function treeGather(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array,
    pz = A[2] as Float64Array,
    m = A[3] as Float64Array;
  const gx = A[4] as Float64Array,
    gy = A[5] as Float64Array,
    gz = A[6] as Float64Array,
    gm = A[7] as Float64Array;
  const box = A[8] as Float64Array,
    ge = A[9] as Int32Array;
  const is3D = P[0] === 3,
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
  const o = part * 8;
  box[o] = minX;
  box[o + 1] = minY;
  box[o + 2] = minZ;
  box[o + 3] = maxX;
  box[o + 4] = maxY;
  box[o + 5] = maxZ;
  box[o + 6] = bad;
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
 * Digits of the passes that sort a large bucket (the bits below the first digit, 8 at a time).
 * @category Forces
 */
export const BUCKET_RADIX = 256;
/**
 * Buckets of at most this many keys are sorted by insertion, larger ones by radix passes.
 * @category Forces
 */
export const BUCKET_INSERTION_MAX = 48;

/**
 * The Morton sort's parameters `P` (the three kernels below share them): 0 x0, 1 y0, 2 z0 (the root
 * cube's low corner, m), 3 scale (key units per m), 4 top (largest key coordinate), 5 dimensions,
 * 6 n (bodies), 7 parts, 8 first digit's shift (key bits - P[9]), 9 first digit's bits (at most
 * SORT_RADIX_BITS; the part's counts and places are 2^P[9] slots at part * 2^P[9]). A call's range
 * [lo, hi) is a range of parts; part p of the first two kernels holds bodies
 * floor(n p / parts) .. floor(n (p + 1) / parts) - 1 (the same in both, so the scatter sees the
 * histogram's bodies); the last kernel's parts are ranges of buckets.
 * @category Forces
 */
export const SORT_PARAMS = 10;

/**
 * Morton sort, pass 1: the Morton (Z-order) keys of a part's bodies in the root cube (16 bits per
 * axis interleaved in 2D, 10 in 3D; forces/barnes-hut/tree.ts) and the part's histogram of their first digit
 * (key >>> P[8]). A: x, y, z (positions, input order), key (Uint32, out, input order), hist (Int32,
 * 2^P[9] counts a part, the part's at p * 2^P[9]). P: SORT_PARAMS. Returns 0.
 * @category Forces
 */
export function mortonKeysHist(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[0] as Float64Array,
    y = A[1] as Float64Array,
    z = A[2] as Float64Array;
  const key = A[3] as Uint32Array,
    hist = A[4] as Int32Array;
  const x0 = P[0]!,
    y0 = P[1]!,
    z0 = P[2]!,
    scale = P[3]!,
    top = P[4]!,
    is3D = P[5] === 3;
  const n = P[6]!,
    parts = P[7]!,
    topShift = P[8]!,
    R = 1 << P[9]!;
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
 * slot. A: fx, fy, fz (Force store), slot (Int32: slot of input body i), m, ax, ay, az (tree order:
 * mass, kg, and field, m/s^2). P unused. Returns 0.
 * @category Forces
 */
export function treeForces(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const fx = A[0] as Float64Array,
    fy = A[1] as Float64Array,
    fz = A[2] as Float64Array,
    slot = A[3] as Int32Array;
  const m = A[4] as Float64Array,
    ax = A[5] as Float64Array,
    ay = A[6] as Float64Array,
    az = A[7] as Float64Array;
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
 * Moments of tree nodes (forces/barnes-hut/tree.ts: centre of mass, mass, second moment, in 2D third moment,
 * b_max, tight box), and slot[perm[s]] = s for the bodies of the leaves. A leaf's are summed over
 * its bodies; a cell's are combined from its children's (parallel-axis theorem), which must be done
 * already. `skip` must be complete (the node after each subtree; k + 1 for a leaf). Part p takes
 * the nodes list[cut[p]] .. list[cut[p + 1] - 1]: with P[1] = 0 each listed node's whole subtree,
 * children before parents (descending node index, so the result is that of one bottom-up pass),
 * with P[1] = 1 each listed node alone, in list order. A: x, y, z, m (tree order), node (moments,
 * stride 12), box (stride 6), start, end, skip (Int32), perm, slot (Int32), list, cut (Int32).
 * P: 0 dimensions, 1 mode. Range over parts. Returns 0.
 * @category Forces
 */
export function treeMoments(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[0] as Float64Array,
    y = A[1] as Float64Array,
    z = A[2] as Float64Array,
    m = A[3] as Float64Array;
  const F = A[4] as Float64Array,
    B = A[5] as Float64Array;
  const start = A[6] as Int32Array,
    end = A[7] as Int32Array,
    skip = A[8] as Int32Array;
  const perm = A[9] as Int32Array,
    slot = A[10] as Int32Array,
    list = A[11] as Int32Array,
    cut = A[12] as Int32Array;
  const is3D = P[0] === 3,
    alone = P[1] === 1;
  for (let part = lo; part < hi; part++) {
    for (let q = cut[part]!, qEnd = cut[part + 1]!; q < qEnd; q++) {
      const root = list[q]!;
      for (let k = alone ? root : skip[root]! - 1; k >= root; k--) {
        // A leaf's moments are sums over its bodies, a cell's are combined from its children's.
        const after = skip[k]!,
          leaf = after === k + 1,
          s0 = start[k]!,
          s1 = end[k]!;
        if (leaf) for (let s = s0; s < s1; s++) slot[perm[s]!] = s;
        if (!is3D) {
          let M = 0,
            X = 0,
            Y = 0,
            minX = Infinity,
            minY = Infinity,
            maxX = -Infinity,
            maxY = -Infinity;
          if (leaf) {
            for (let s = s0; s < s1; s++) {
              const w = m[s]!,
                px = x[s]!,
                py = y[s]!;
              M += w;
              X += w * px;
              Y += w * py;
              if (px < minX) minX = px;
              if (px > maxX) maxX = px;
              if (py < minY) minY = py;
              if (py > maxY) maxY = py;
            }
          } else {
            for (let c = k + 1; c < after; c = skip[c]!) {
              const o = c * 12,
                w = F[o + 2]!,
                b = c * 6;
              M += w;
              X += w * F[o]!;
              Y += w * F[o + 1]!;
              if (B[b]! < minX) minX = B[b]!;
              if (B[b + 1]! < minY) minY = B[b + 1]!;
              if (B[b + 3]! > maxX) maxX = B[b + 3]!;
              if (B[b + 4]! > maxY) maxY = B[b + 4]!;
            }
          }
          let cx: number, cy: number;
          if (M > 0) {
            cx = X / M;
            cy = Y / M;
          } else {
            cx = 0.5 * (minX + maxX);
            cy = 0.5 * (minY + maxY);
          }
          // reach: a cell's farthest child extent, |c_child - c| + b_max(child); a leaf's is not needed.
          let sxx = 0,
            sxy = 0,
            syy = 0,
            txxx = 0,
            txxy = 0,
            txyy = 0,
            tyyy = 0,
            reach = Infinity;
          if (leaf) {
            for (let s = s0; s < s1; s++) {
              const w = m[s]!,
                dx = x[s]! - cx,
                dy = y[s]! - cy;
              const wxx = w * dx * dx,
                wyy = w * dy * dy,
                wxy = w * dx * dy;
              sxx += wxx;
              sxy += wxy;
              syy += wyy;
              txxx += wxx * dx;
              txxy += wxx * dy;
              txyy += wyy * dx;
              tyyy += wyy * dy;
            }
          } else {
            // Parallel-axis theorem, d = c_child - c: S += S_c + M_c d d; T += T_c + 3 sym(d S_c) + M_c d d d.
            reach = 0;
            for (let c = k + 1; c < after; c = skip[c]!) {
              const o = c * 12,
                w = F[o + 2]!,
                dx = F[o]! - cx,
                dy = F[o + 1]! - cy;
              const cxx = F[o + 3]!,
                cxy = F[o + 4]!,
                cyy = F[o + 5]!;
              const wxx = w * dx * dx,
                wxy = w * dx * dy,
                wyy = w * dy * dy;
              sxx += cxx + wxx;
              sxy += cxy + wxy;
              syy += cyy + wyy;
              txxx += F[o + 7]! + 3 * dx * cxx + wxx * dx;
              txxy += F[o + 8]! + 2 * dx * cxy + dy * cxx + wxx * dy;
              txyy += F[o + 9]! + 2 * dy * cxy + dx * cyy + wyy * dx;
              tyyy += F[o + 10]! + 3 * dy * cyy + wyy * dy;
              const r = Math.sqrt(dx * dx + dy * dy) + F[o + 6]!;
              if (r > reach) reach = r;
            }
          }
          const ex = Math.max(cx - minX, maxX - cx),
            ey = Math.max(cy - minY, maxY - cy);
          const o = k * 12;
          F[o] = cx;
          F[o + 1] = cy;
          F[o + 2] = M;
          F[o + 3] = sxx;
          F[o + 4] = sxy;
          F[o + 5] = syy;
          F[o + 6] = Math.min(Math.sqrt(ex * ex + ey * ey), reach);
          F[o + 7] = txxx;
          F[o + 8] = txxy;
          F[o + 9] = txyy;
          F[o + 10] = tyyy;
          F[o + 11] = 0;
          const b = k * 6;
          B[b] = minX;
          B[b + 1] = minY;
          B[b + 2] = 0;
          B[b + 3] = maxX;
          B[b + 4] = maxY;
          B[b + 5] = 0;
        } else {
          let M = 0,
            X = 0,
            Y = 0,
            Z = 0;
          let minX = Infinity,
            minY = Infinity,
            minZ = Infinity,
            maxX = -Infinity,
            maxY = -Infinity,
            maxZ = -Infinity;
          if (leaf) {
            for (let s = s0; s < s1; s++) {
              const w = m[s]!,
                px = x[s]!,
                py = y[s]!,
                pz = z[s]!;
              M += w;
              X += w * px;
              Y += w * py;
              Z += w * pz;
              if (px < minX) minX = px;
              if (px > maxX) maxX = px;
              if (py < minY) minY = py;
              if (py > maxY) maxY = py;
              if (pz < minZ) minZ = pz;
              if (pz > maxZ) maxZ = pz;
            }
          } else {
            for (let c = k + 1; c < after; c = skip[c]!) {
              const o = c * 12,
                w = F[o + 3]!,
                b = c * 6;
              M += w;
              X += w * F[o]!;
              Y += w * F[o + 1]!;
              Z += w * F[o + 2]!;
              if (B[b]! < minX) minX = B[b]!;
              if (B[b + 1]! < minY) minY = B[b + 1]!;
              if (B[b + 2]! < minZ) minZ = B[b + 2]!;
              if (B[b + 3]! > maxX) maxX = B[b + 3]!;
              if (B[b + 4]! > maxY) maxY = B[b + 4]!;
              if (B[b + 5]! > maxZ) maxZ = B[b + 5]!;
            }
          }
          let cx: number, cy: number, cz: number;
          if (M > 0) {
            cx = X / M;
            cy = Y / M;
            cz = Z / M;
          } else {
            cx = 0.5 * (minX + maxX);
            cy = 0.5 * (minY + maxY);
            cz = 0.5 * (minZ + maxZ);
          }
          let sxx = 0,
            syy = 0,
            szz = 0,
            sxy = 0,
            sxz = 0,
            syz = 0,
            reach = Infinity;
          if (leaf) {
            for (let s = s0; s < s1; s++) {
              const w = m[s]!,
                dx = x[s]! - cx,
                dy = y[s]! - cy,
                dz = z[s]! - cz;
              sxx += w * dx * dx;
              syy += w * dy * dy;
              szz += w * dz * dz;
              sxy += w * dx * dy;
              sxz += w * dx * dz;
              syz += w * dy * dz;
            }
          } else {
            reach = 0;
            for (let c = k + 1; c < after; c = skip[c]!) {
              const o = c * 12,
                w = F[o + 3]!,
                dx = F[o]! - cx,
                dy = F[o + 1]! - cy,
                dz = F[o + 2]! - cz;
              sxx += F[o + 4]! + w * dx * dx;
              syy += F[o + 5]! + w * dy * dy;
              szz += F[o + 6]! + w * dz * dz;
              sxy += F[o + 7]! + w * dx * dy;
              sxz += F[o + 8]! + w * dx * dz;
              syz += F[o + 9]! + w * dy * dz;
              const r = Math.sqrt(dx * dx + dy * dy + dz * dz) + F[o + 10]!;
              if (r > reach) reach = r;
            }
          }
          const ex = Math.max(cx - minX, maxX - cx),
            ey = Math.max(cy - minY, maxY - cy),
            ez = Math.max(cz - minZ, maxZ - cz);
          const o = k * 12;
          F[o] = cx;
          F[o + 1] = cy;
          F[o + 2] = cz;
          F[o + 3] = M;
          F[o + 4] = sxx;
          F[o + 5] = syy;
          F[o + 6] = szz;
          F[o + 7] = sxy;
          F[o + 8] = sxz;
          F[o + 9] = syz;
          F[o + 10] = Math.min(Math.sqrt(ex * ex + ey * ey + ez * ez), reach);
          F[o + 11] = 0;
          const b = k * 6;
          B[b] = minX;
          B[b + 1] = minY;
          B[b + 2] = minZ;
          B[b + 3] = maxX;
          B[b + 4] = maxY;
          B[b + 5] = maxZ;
        }
      }
    }
  }
  return ids === null ? 0 : 0;
}

/**
 * Morton sort, pass 2: a part's bodies to their first digit's bucket, in order (so the pass is
 * stable: within a bucket the bodies keep their input order). A: key (Uint32, input order), key2
 * (Uint32, out), idx2 (Int32, out: the input index of each placed key), offset (Int32, 2^P[9]
 * first places a part, the part's at p * 2^P[9], advanced as it goes). P: SORT_PARAMS. The
 * parts must be those of mortonKeysHist. Returns 0.
 * @category Forces
 */
export function mortonScatter(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const key = A[0] as Uint32Array,
    key2 = A[1] as Uint32Array,
    idx2 = A[2] as Int32Array,
    offset = A[3] as Int32Array;
  const n = P[6]!,
    parts = P[7]!,
    topShift = P[8]!,
    R = 1 << P[9]!;
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
 * first digit) sorted by the bits below it, stably (insertion for BUCKET_INSERTION_MAX keys or
 * fewer, else least-significant-digit radix passes of 8 bits, each skipped when all its digits are
 * equal), so the keys end in (key, input index) order, the order of a stable sort of the whole
 * array; then slot s of the bucket gets input body perm[s]'s position and mass.
 * A: key2, idx2 (pass 2's output; also scratch), key (Uint32, out: sorted keys), perm (Int32, out:
 * input index in sorted order, the tree's perm), bucket (Int32: first slot of each bucket, 2^P[9] + 1 entries),
 * group (Int32: part p sorts buckets group[p] .. group[p + 1] - 1), local (Int32, BUCKET_RADIX
 * counts a part), x, y, z, m (input order), tx, ty, tz, tm (out, tree order; tz only in 3D: in 2D
 * it stays 0). P: SORT_PARAMS. Returns 0.
 * @category Forces
 */
export function mortonBucketSort(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const key2 = A[0] as Uint32Array,
    idx2 = A[1] as Int32Array,
    key = A[2] as Uint32Array,
    perm = A[3] as Int32Array;
  const bucket = A[4] as Int32Array,
    group = A[5] as Int32Array,
    local = A[6] as Int32Array;
  const x = A[7] as Float64Array,
    y = A[8] as Float64Array,
    z = A[9] as Float64Array,
    m = A[10] as Float64Array;
  const tx = A[11] as Float64Array,
    ty = A[12] as Float64Array,
    tz = A[13] as Float64Array,
    tm = A[14] as Float64Array;
  const is3D = P[5] === 3,
    topShift = P[8]!;
  for (let part = lo; part < hi; part++) {
    const base = part * 256;
    for (let r = group[part]!, rEnd = group[part + 1]!; r < rEnd; r++) {
      const a = bucket[r]!,
        b = bucket[r + 1]!;
      if (a === b) continue;
      if (b - a <= 48) {
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
          local.fill(0, base, base + 256);
          for (let s = a; s < b; s++) local[base + ((sk[s]! >>> shift) & 255)]!++;
          if (local[base + ((sk[a]! >>> shift) & 255)] === b - a) continue;
          let acc = a;
          for (let d = 0; d < 256; d++) {
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
