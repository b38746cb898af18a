/**
 * The per-body loops around the Barnes-Hut tree (barnes-hut.ts) as thread kernels (threads/kernels.ts:
 * self-contained functions the worker threads also run as source text): gathering the bodies'
 * positions and masses with their bounding box, their Morton keys, and adding m g to the force
 * accumulators. Each body's arithmetic is the same on any thread, and the bounding box is a min and
 * max (exact in any order), so the results do not depend on the number of threads.
 */

import type { KernelArray } from '../threads/kernel-types.js';

/** Slots of the bounding box a range writes: min x, y, z, max x, y, z, non-finite flag, unused. */
export const BOX_STRIDE = 8;

/**
 * Gathers body i = ids[i]'s Position and Mass into dense arrays and the range's bounding box.
 * A: px, py, pz, m (component stores), gx, gy, gz, gm (out, index i), box (out, BOX_STRIDE slots a
 * range, at `part`). P: 0 dimensions (2 or 3). Writes z = 0 bounds in 2D. Returns 0.
 */
export function treeGather(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const px = A[0] as Float64Array, py = A[1] as Float64Array, pz = A[2] as Float64Array, m = A[3] as Float64Array;
  const gx = A[4] as Float64Array, gy = A[5] as Float64Array, gz = A[6] as Float64Array, gm = A[7] as Float64Array;
  const box = A[8] as Float64Array;
  const is3D = P[0] === 3, list = ids as Int32Array;
  let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = -Infinity, maxY = -Infinity, maxZ = -Infinity;
  let bad = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const x = px[e]!, y = py[e]!, z = pz[e]!;
    gx[i] = x; gy[i] = y; gz[i] = z; gm[i] = m[e]!;
    if (x < minX) minX = x; if (x > maxX) maxX = x;
    if (y < minY) minY = y; if (y > maxY) maxY = y;
    if (x - x !== 0 || y - y !== 0) bad = 1; // NaN or infinite
    if (is3D) { if (z < minZ) minZ = z; if (z > maxZ) maxZ = z; if (z - z !== 0) bad = 1; }
  }
  if (!is3D) { minZ = 0; maxZ = 0; }
  const o = part * 8;
  box[o] = minX; box[o + 1] = minY; box[o + 2] = minZ; box[o + 3] = maxX; box[o + 4] = maxY; box[o + 5] = maxZ; box[o + 6] = bad;
  return 0;
}

/**
 * Morton (Z-order) keys of bodies lo .. hi - 1 in the root cube: 16 bits per axis interleaved in 2D,
 * 10 in 3D (barnes-hut.ts). A: x, y, z (positions), key (Uint32, out), idx (Int32, out: idx[i] = i).
 * P: 0 x0, 1 y0, 2 z0 (the cube's low corner, m), 3 scale (key units per m), 4 top (largest key
 * coordinate), 5 dimensions. Returns 0.
 */
export function mortonKeys(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[0] as Float64Array, y = A[1] as Float64Array, z = A[2] as Float64Array;
  const key = A[3] as Uint32Array, idx = A[4] as Int32Array;
  const x0 = P[0]!, y0 = P[1]!, z0 = P[2]!, scale = P[3]!, top = P[4]!, is3D = P[5] === 3;
  for (let i = lo; i < hi; i++) {
    let kx = Math.floor((x[i]! - x0) * scale), ky = Math.floor((y[i]! - y0) * scale);
    kx = kx > 0 ? (kx < top ? kx : top) : 0; ky = ky > 0 ? (ky < top ? ky : top) : 0;
    if (is3D) {
      let kz = Math.floor((z[i]! - z0) * scale);
      kz = kz > 0 ? (kz < top ? kz : top) : 0;
      // Spread the low 10 bits of each coordinate to every third bit.
      kx &= 0x3ff; kx = (kx | (kx << 16)) & 0x030000ff; kx = (kx | (kx << 8)) & 0x0300f00f; kx = (kx | (kx << 4)) & 0x030c30c3; kx = (kx | (kx << 2)) & 0x09249249;
      ky &= 0x3ff; ky = (ky | (ky << 16)) & 0x030000ff; ky = (ky | (ky << 8)) & 0x0300f00f; ky = (ky | (ky << 4)) & 0x030c30c3; ky = (ky | (ky << 2)) & 0x09249249;
      kz &= 0x3ff; kz = (kz | (kz << 16)) & 0x030000ff; kz = (kz | (kz << 8)) & 0x0300f00f; kz = (kz | (kz << 4)) & 0x030c30c3; kz = (kz | (kz << 2)) & 0x09249249;
      key[i] = kx | (ky << 1) | (kz << 2);
    } else {
      // Spread the low 16 bits of each coordinate to the even bits.
      kx &= 0xffff; kx = (kx | (kx << 8)) & 0x00ff00ff; kx = (kx | (kx << 4)) & 0x0f0f0f0f; kx = (kx | (kx << 2)) & 0x33333333; kx = (kx | (kx << 1)) & 0x55555555;
      ky &= 0xffff; ky = (ky | (ky << 8)) & 0x00ff00ff; ky = (ky | (ky << 4)) & 0x0f0f0f0f; ky = (ky | (ky << 2)) & 0x33333333; ky = (ky | (ky << 1)) & 0x55555555;
      key[i] = (kx | (ky << 1)) >>> 0;
    }
    idx[i] = i;
  }
  return ids === null ? 0 : 0;
}

/**
 * Adds the tree's gravity to the bodies' forces: F_e += m g for e = ids[i], g the field at body i's
 * slot. A: fx, fy, fz (Force store), slot (Int32: slot of input body i), m, ax, ay, az (tree order:
 * mass, kg, and field, m/s^2). P unused. Returns 0.
 */
export function treeForces(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const fx = A[0] as Float64Array, fy = A[1] as Float64Array, fz = A[2] as Float64Array, slot = A[3] as Int32Array;
  const m = A[4] as Float64Array, ax = A[5] as Float64Array, ay = A[6] as Float64Array, az = A[7] as Float64Array;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!, s = slot[i]!, w = m[s]!;
    fx[e] = fx[e]! + w * ax[s]!; fy[e] = fy[e]! + w * ay[s]!; fz[e] = fz[e]! + w * az[s]!;
  }
  return P.length * 0;
}

/**
 * Puts the bodies into tree order after the key sort: slot s gets input body idx[s]'s position and
 * mass, and perm[s] = idx[s]. A: x, y, z, m (input order), idx (Int32, sorted order), tx, ty, tz, tm
 * (out, tree order), perm (Int32, out). P: 0 dimensions (z is 0 in 2D). Range over slots. Returns 0.
 */
export function treeOrder(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[0] as Float64Array, y = A[1] as Float64Array, z = A[2] as Float64Array, m = A[3] as Float64Array;
  const idx = A[4] as Int32Array;
  const bx = A[5] as Float64Array, by = A[6] as Float64Array, bz = A[7] as Float64Array, bm = A[8] as Float64Array;
  const perm = A[9] as Int32Array;
  const is3D = P[0] === 3;
  for (let s = lo; s < hi; s++) {
    const i = idx[s]!;
    bx[s] = x[i]!; by[s] = y[i]!; bz[s] = is3D ? z[i]! : 0; bm[s] = m[i]!; perm[s] = i;
  }
  return ids === null ? 0 : 0;
}

/**
 * Moments of the leaves among nodes lo .. hi - 1 (barnes-hut.ts: centre of mass, mass, second
 * moment, in 2D third moment, b_max, tight box), and slot[perm[s]] = s for their bodies. A node is a
 * leaf when the next node is not its first child. A: x, y, z, m (tree order), node (moments, stride
 * 12), box (stride 6), start, end, parent (Int32), perm, slot (Int32). P: 0 dimensions, 1 node count.
 * Range over nodes. Returns 0.
 */
export function leafMoments(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[0] as Float64Array, y = A[1] as Float64Array, z = A[2] as Float64Array, m = A[3] as Float64Array;
  const F = A[4] as Float64Array, B = A[5] as Float64Array;
  const start = A[6] as Int32Array, end = A[7] as Int32Array, parent = A[8] as Int32Array;
  const perm = A[9] as Int32Array, slot = A[10] as Int32Array;
  const is3D = P[0] === 3, nodeCount = P[1]!;
  for (let k = lo; k < hi; k++) {
    if (k + 1 < nodeCount && parent[k + 1] === k) continue; // has children: not a leaf
    const s0 = start[k]!, s1 = end[k]!;
    for (let s = s0; s < s1; s++) slot[perm[s]!] = s;
    if (!is3D) {
      let M = 0, X = 0, Y = 0, minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
      for (let s = s0; s < s1; s++) {
        const w = m[s]!, px = x[s]!, py = y[s]!;
        M += w; X += w * px; Y += w * py;
        if (px < minX) minX = px; if (px > maxX) maxX = px;
        if (py < minY) minY = py; if (py > maxY) maxY = py;
      }
      let cx: number, cy: number;
      if (M > 0) { cx = X / M; cy = Y / M; } else { cx = 0.5 * (minX + maxX); cy = 0.5 * (minY + maxY); }
      let sxx = 0, sxy = 0, syy = 0, txxx = 0, txxy = 0, txyy = 0, tyyy = 0;
      for (let s = s0; s < s1; s++) {
        const w = m[s]!, dx = x[s]! - cx, dy = y[s]! - cy;
        const wxx = w * dx * dx, wyy = w * dy * dy, wxy = w * dx * dy;
        sxx += wxx; sxy += wxy; syy += wyy;
        txxx += wxx * dx; txxy += wxx * dy; txyy += wyy * dx; tyyy += wyy * dy;
      }
      const ex = Math.max(cx - minX, maxX - cx), ey = Math.max(cy - minY, maxY - cy);
      const o = k * 12;
      F[o] = cx; F[o + 1] = cy; F[o + 2] = M; F[o + 3] = sxx; F[o + 4] = sxy; F[o + 5] = syy;
      F[o + 6] = Math.sqrt(ex * ex + ey * ey);
      F[o + 7] = txxx; F[o + 8] = txxy; F[o + 9] = txyy; F[o + 10] = tyyy; F[o + 11] = 0;
      const b = k * 6;
      B[b] = minX; B[b + 1] = minY; B[b + 2] = 0; B[b + 3] = maxX; B[b + 4] = maxY; B[b + 5] = 0;
    } else {
      let M = 0, X = 0, Y = 0, Z = 0;
      let minX = Infinity, minY = Infinity, minZ = Infinity, maxX = -Infinity, maxY = -Infinity, maxZ = -Infinity;
      for (let s = s0; s < s1; s++) {
        const w = m[s]!, px = x[s]!, py = y[s]!, pz = z[s]!;
        M += w; X += w * px; Y += w * py; Z += w * pz;
        if (px < minX) minX = px; if (px > maxX) maxX = px;
        if (py < minY) minY = py; if (py > maxY) maxY = py;
        if (pz < minZ) minZ = pz; if (pz > maxZ) maxZ = pz;
      }
      let cx: number, cy: number, cz: number;
      if (M > 0) { cx = X / M; cy = Y / M; cz = Z / M; }
      else { cx = 0.5 * (minX + maxX); cy = 0.5 * (minY + maxY); cz = 0.5 * (minZ + maxZ); }
      let sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;
      for (let s = s0; s < s1; s++) {
        const w = m[s]!, dx = x[s]! - cx, dy = y[s]! - cy, dz = z[s]! - cz;
        sxx += w * dx * dx; syy += w * dy * dy; szz += w * dz * dz;
        sxy += w * dx * dy; sxz += w * dx * dz; syz += w * dy * dz;
      }
      const ex = Math.max(cx - minX, maxX - cx), ey = Math.max(cy - minY, maxY - cy), ez = Math.max(cz - minZ, maxZ - cz);
      const o = k * 12;
      F[o] = cx; F[o + 1] = cy; F[o + 2] = cz; F[o + 3] = M;
      F[o + 4] = sxx; F[o + 5] = syy; F[o + 6] = szz; F[o + 7] = sxy; F[o + 8] = sxz; F[o + 9] = syz;
      F[o + 10] = Math.sqrt(ex * ex + ey * ey + ez * ez); F[o + 11] = 0;
      const b = k * 6;
      B[b] = minX; B[b + 1] = minY; B[b + 2] = minZ; B[b + 3] = maxX; B[b + 4] = maxY; B[b + 5] = maxZ;
    }
  }
  return ids === null ? 0 : 0;
}

/** Bits a pass of the key sort takes (barnes-hut.ts RADIX_BITS), and its digit count. */
export const SORT_RADIX_BITS = 11, SORT_RADIX = 1 << SORT_RADIX_BITS;

/**
 * One pass of the parallel key sort, first half: the range's histogram of the digit at `shift`.
 * A: key (Uint32), hist (Int32, SORT_RADIX counts a range, the range's at `part`). P: 0 shift.
 * Range over the keys. Returns 0.
 */
export function radixHistogram(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const key = A[0] as Uint32Array, hist = A[1] as Int32Array;
  const shift = P[0]!, base = part * 2048;
  hist.fill(0, base, base + 2048);
  for (let i = lo; i < hi; i++) hist[base + ((key[i]! >>> shift) & 2047)]!++;
  return ids === null ? 0 : 0;
}

/**
 * Second half: the range's keys and indices to their places, in order (so the sort stays stable).
 * A: key, idx (in), key2, idx2 (out), offset (Int32, SORT_RADIX first places a range, the range's at
 * `part`, advanced as it goes). P: 0 shift. The ranges must be those of radixHistogram. Returns 0.
 */
export function radixScatter(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number, part: number): number {
  const key = A[0] as Uint32Array, idx = A[1] as Int32Array, key2 = A[2] as Uint32Array, idx2 = A[3] as Int32Array;
  const offset = A[4] as Int32Array;
  const shift = P[0]!, base = part * 2048;
  for (let i = lo; i < hi; i++) {
    const k = key[i]!, d = offset[base + ((k >>> shift) & 2047)]!++;
    key2[d] = k; idx2[d] = idx[i]!;
  }
  return ids === null ? 0 : 0;
}
