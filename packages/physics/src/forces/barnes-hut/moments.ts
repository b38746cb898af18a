import type { KernelArray } from '../../threads/kernel-types.js';
import * as BOX from './bounds.js';
import * as N2 from './node-2d.js';
import * as N3 from './node-3d.js';
import * as MOMENTS from './slots/moments.js';

/**
 * The moments of the Barnes-Hut tree's nodes (forces/barnes-hut/tree.ts), the last pass of the build
 * (treeMomentsAll, forces/barnes-hut/tree-build.ts), as thread kernels (step/kernel-table.ts:
 * self-contained functions the worker threads also run as source text), one a dimension. Each node's
 * moments come from its own bodies or its children's moments alone, so they do not depend on how the
 * nodes are shared out.
 */

/**
 * Moments of 2D tree nodes (forces/barnes-hut/tree.ts: centre of mass, mass, second moment, third moment,
 * b_max, tight box), and slot[perm[s]] = s for the bodies of the leaves. A leaf's are summed over
 * its bodies; a cell's are combined from its children's (parallel-axis theorem), which must be done
 * already. `skip` must be complete (the node after each subtree; k + 1 for a leaf). Part p takes
 * the nodes list[cut[p]] .. list[cut[p + 1] - 1]: with P[MOMENTS.ALONE] = 0 each listed node's whole
 * subtree, children before parents (descending node index, so the result is that of one bottom-up
 * pass), with 1 each listed node alone, in list order. A and P: forces/barnes-hut/slots/moments.ts;
 * the moments in the layout of forces/barnes-hut/node-2d.ts, the boxes of bounds.ts. Range over parts.
 * Returns 0.
 * @category Forces
 */
export function treeMoments2(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[MOMENTS.X] as Float64Array,
    y = A[MOMENTS.Y] as Float64Array,
    m = A[MOMENTS.MASS] as Float64Array;
  const F = A[MOMENTS.NODE] as Float64Array,
    B = A[MOMENTS.BOX] as Float64Array;
  const start = A[MOMENTS.START] as Int32Array,
    end = A[MOMENTS.END] as Int32Array,
    skip = A[MOMENTS.SKIP] as Int32Array;
  const perm = A[MOMENTS.PERM] as Int32Array,
    slot = A[MOMENTS.SLOT] as Int32Array,
    list = A[MOMENTS.LIST] as Int32Array,
    cut = A[MOMENTS.CUT] as Int32Array;
  const alone = P[MOMENTS.ALONE] === 1;
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
            const o = c * N2.STRIDE,
              w = F[o + N2.MASS]!,
              b = c * BOX.NODE_STRIDE;
            M += w;
            X += w * F[o + N2.CX]!;
            Y += w * F[o + N2.CY]!;
            if (B[b + BOX.MIN_X]! < minX) minX = B[b + BOX.MIN_X]!;
            if (B[b + BOX.MIN_Y]! < minY) minY = B[b + BOX.MIN_Y]!;
            if (B[b + BOX.MAX_X]! > maxX) maxX = B[b + BOX.MAX_X]!;
            if (B[b + BOX.MAX_Y]! > maxY) maxY = B[b + BOX.MAX_Y]!;
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
            const o = c * N2.STRIDE,
              w = F[o + N2.MASS]!,
              dx = F[o + N2.CX]! - cx,
              dy = F[o + N2.CY]! - cy;
            const cxx = F[o + N2.SXX]!,
              cxy = F[o + N2.SXY]!,
              cyy = F[o + N2.SYY]!;
            const wxx = w * dx * dx,
              wxy = w * dx * dy,
              wyy = w * dy * dy;
            sxx += cxx + wxx;
            sxy += cxy + wxy;
            syy += cyy + wyy;
            txxx += F[o + N2.TXXX]! + 3 * dx * cxx + wxx * dx;
            txxy += F[o + N2.TXXY]! + 2 * dx * cxy + dy * cxx + wxx * dy;
            txyy += F[o + N2.TXYY]! + 2 * dy * cxy + dx * cyy + wyy * dx;
            tyyy += F[o + N2.TYYY]! + 3 * dy * cyy + wyy * dy;
            const r = Math.sqrt(dx * dx + dy * dy) + F[o + N2.RADIUS]!;
            if (r > reach) reach = r;
          }
        }
        const ex = Math.max(cx - minX, maxX - cx),
          ey = Math.max(cy - minY, maxY - cy);
        const o = k * N2.STRIDE;
        F[o + N2.CX] = cx;
        F[o + N2.CY] = cy;
        F[o + N2.MASS] = M;
        F[o + N2.SXX] = sxx;
        F[o + N2.SXY] = sxy;
        F[o + N2.SYY] = syy;
        F[o + N2.RADIUS] = Math.min(Math.sqrt(ex * ex + ey * ey), reach);
        F[o + N2.TXXX] = txxx;
        F[o + N2.TXXY] = txxy;
        F[o + N2.TXYY] = txyy;
        F[o + N2.TYYY] = tyyy;
        F[o + N2.PAD] = 0;
        const b = k * BOX.NODE_STRIDE;
        B[b + BOX.MIN_X] = minX;
        B[b + BOX.MIN_Y] = minY;
        B[b + BOX.MIN_Z] = 0;
        B[b + BOX.MAX_X] = maxX;
        B[b + BOX.MAX_Y] = maxY;
        B[b + BOX.MAX_Z] = 0;
      }
    }
  }
  return ids === null ? 0 : 0;
}

/**
 * Moments of 3D tree nodes (forces/barnes-hut/tree.ts: centre of mass, mass, second moment,
 * b_max, tight box), and slot[perm[s]] = s for the bodies of the leaves. A leaf's are summed over
 * its bodies; a cell's are combined from its children's (parallel-axis theorem), which must be done
 * already. `skip` must be complete (the node after each subtree; k + 1 for a leaf). Part p takes
 * the nodes list[cut[p]] .. list[cut[p + 1] - 1]: with P[MOMENTS.ALONE] = 0 each listed node's whole
 * subtree, children before parents (descending node index, so the result is that of one bottom-up
 * pass), with 1 each listed node alone, in list order. A and P: forces/barnes-hut/slots/moments.ts;
 * the moments in the layout of forces/barnes-hut/node-3d.ts, the boxes of bounds.ts. Range over parts.
 * Returns 0.
 * @category Forces
 */
export function treeMoments3(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const x = A[MOMENTS.X] as Float64Array,
    y = A[MOMENTS.Y] as Float64Array,
    z = A[MOMENTS.Z] as Float64Array,
    m = A[MOMENTS.MASS] as Float64Array;
  const F = A[MOMENTS.NODE] as Float64Array,
    B = A[MOMENTS.BOX] as Float64Array;
  const start = A[MOMENTS.START] as Int32Array,
    end = A[MOMENTS.END] as Int32Array,
    skip = A[MOMENTS.SKIP] as Int32Array;
  const perm = A[MOMENTS.PERM] as Int32Array,
    slot = A[MOMENTS.SLOT] as Int32Array,
    list = A[MOMENTS.LIST] as Int32Array,
    cut = A[MOMENTS.CUT] as Int32Array;
  const alone = P[MOMENTS.ALONE] === 1;
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
            const o = c * N3.STRIDE,
              w = F[o + N3.MASS]!,
              b = c * BOX.NODE_STRIDE;
            M += w;
            X += w * F[o + N3.CX]!;
            Y += w * F[o + N3.CY]!;
            Z += w * F[o + N3.CZ]!;
            if (B[b + BOX.MIN_X]! < minX) minX = B[b + BOX.MIN_X]!;
            if (B[b + BOX.MIN_Y]! < minY) minY = B[b + BOX.MIN_Y]!;
            if (B[b + BOX.MIN_Z]! < minZ) minZ = B[b + BOX.MIN_Z]!;
            if (B[b + BOX.MAX_X]! > maxX) maxX = B[b + BOX.MAX_X]!;
            if (B[b + BOX.MAX_Y]! > maxY) maxY = B[b + BOX.MAX_Y]!;
            if (B[b + BOX.MAX_Z]! > maxZ) maxZ = B[b + BOX.MAX_Z]!;
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
            const o = c * N3.STRIDE,
              w = F[o + N3.MASS]!,
              dx = F[o + N3.CX]! - cx,
              dy = F[o + N3.CY]! - cy,
              dz = F[o + N3.CZ]! - cz;
            sxx += F[o + N3.SXX]! + w * dx * dx;
            syy += F[o + N3.SYY]! + w * dy * dy;
            szz += F[o + N3.SZZ]! + w * dz * dz;
            sxy += F[o + N3.SXY]! + w * dx * dy;
            sxz += F[o + N3.SXZ]! + w * dx * dz;
            syz += F[o + N3.SYZ]! + w * dy * dz;
            const r = Math.sqrt(dx * dx + dy * dy + dz * dz) + F[o + N3.RADIUS]!;
            if (r > reach) reach = r;
          }
        }
        const ex = Math.max(cx - minX, maxX - cx),
          ey = Math.max(cy - minY, maxY - cy),
          ez = Math.max(cz - minZ, maxZ - cz);
        const o = k * N3.STRIDE;
        F[o + N3.CX] = cx;
        F[o + N3.CY] = cy;
        F[o + N3.CZ] = cz;
        F[o + N3.MASS] = M;
        F[o + N3.SXX] = sxx;
        F[o + N3.SYY] = syy;
        F[o + N3.SZZ] = szz;
        F[o + N3.SXY] = sxy;
        F[o + N3.SXZ] = sxz;
        F[o + N3.SYZ] = syz;
        F[o + N3.RADIUS] = Math.min(Math.sqrt(ex * ex + ey * ey + ez * ez), reach);
        F[o + N3.PAD] = 0;
        const b = k * BOX.NODE_STRIDE;
        B[b + BOX.MIN_X] = minX;
        B[b + BOX.MIN_Y] = minY;
        B[b + BOX.MIN_Z] = minZ;
        B[b + BOX.MAX_X] = maxX;
        B[b + BOX.MAX_Y] = maxY;
        B[b + BOX.MAX_Z] = maxZ;
      }
    }
  }
  return ids === null ? 0 : 0;
}
