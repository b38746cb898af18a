import type { KernelArray } from '../../threads/kernel-types.js';
import * as BOX from './bounds.js';
import * as N2 from './node-2d.js';
import * as N3 from './node-3d.js';
import * as MOMENTS from './slots/moments.js';

/**
 * The moments of the Barnes-Hut tree's nodes (forces/barnes-hut/tree.ts), the last pass of the build
 * (treeMomentsAll, forces/barnes-hut/tree-build.ts), as one thread kernel for 2D and 3D (step/kernel-table.ts:
 * a self-contained function the worker threads also run as source text). Each node's
 * moments come from its own bodies or its children's moments alone, so they do not depend on how the
 * nodes are shared out.
 */

/**
 * Moments of the tree nodes (forces/barnes-hut/tree.ts: centre of mass, mass, second moment, in 2D the
 * third moment, b_max, tight box) in the layout of forces/barnes-hut/node-2d.ts or node-3d.ts by
 * P[MOMENTS.DIMENSIONS] (2 or 3), and slot[perm[s]] = s for the bodies of the leaves. A leaf's are
 * summed over its bodies; a cell's are combined from its children's (parallel-axis theorem), which must
 * be done already. `skip` must be complete (the node after each subtree; k + 1 for a leaf). Part p takes
 * the nodes list[cut[p]] .. list[cut[p + 1] - 1]: with P[MOMENTS.ALONE] = 0 each listed node's whole
 * subtree, children before parents (descending node index, so the result is that of one bottom-up
 * pass), with 1 each listed node alone, in list order. A leaf's sums run over its
 * bodies (j a slot), a cell's over its children (j a node), in one loop for both. The x and y arithmetic
 * is written once; z (3D) and the third moments (2D) are a branch on the dimension, and a 2D node's z
 * terms are exact zeros (its z bounds are written 0). A and P: forces/barnes-hut/slots/moments.ts; the boxes in the layout of
 * bounds.ts. Range over parts. Returns 0.
 * @category Forces
 */
export function treeMoments(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
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
  const alone = P[MOMENTS.ALONE] === 1,
    three = P[MOMENTS.DIMENSIONS] === 3;
  // N2 and N3 have the centre at the same offsets, PAD and the stride alike; the rest sits apart.
  const oM = three ? N3.MASS : N2.MASS,
    oXX = three ? N3.SXX : N2.SXX,
    oXY = three ? N3.SXY : N2.SXY,
    oYY = three ? N3.SYY : N2.SYY,
    oR = three ? N3.RADIUS : N2.RADIUS;
  for (let part = lo; part < hi; part++) {
    for (let q = cut[part]!, qEnd = cut[part + 1]!; q < qEnd; q++) {
      const root = list[q]!;
      for (let k = alone ? root : skip[root]! - 1; k >= root; k--) {
        const leaf = skip[k] === k + 1,
          j0 = leaf ? start[k]! : k + 1,
          j1 = leaf ? end[k]! : skip[k]!;
        if (leaf) for (let s = j0; s < j1; s++) slot[perm[s]!] = s;
        let M = 0,
          X = 0,
          Y = 0,
          Z = 0;
        let minX = Infinity,
          minY = Infinity,
          minZ = three ? Infinity : 0,
          maxX = -Infinity,
          maxY = -Infinity,
          maxZ = three ? -Infinity : 0;
        for (let j = j0; j < j1; j = leaf ? j + 1 : skip[j]!) {
          const o = j * N3.STRIDE,
            w = leaf ? m[j]! : F[o + oM]!,
            px = leaf ? x[j]! : F[o + N3.CX]!,
            py = leaf ? y[j]! : F[o + N3.CY]!;
          M += w;
          X += w * px;
          Y += w * py;
          const lx = leaf ? px : B[j * BOX.NODE_STRIDE + BOX.MIN_X]!,
            ly = leaf ? py : B[j * BOX.NODE_STRIDE + BOX.MIN_Y]!,
            hx = leaf ? px : B[j * BOX.NODE_STRIDE + BOX.MAX_X]!,
            hy = leaf ? py : B[j * BOX.NODE_STRIDE + BOX.MAX_Y]!;
          if (lx < minX) minX = lx;
          if (hx > maxX) maxX = hx;
          if (ly < minY) minY = ly;
          if (hy > maxY) maxY = hy;
          if (three) {
            const pz = leaf ? z[j]! : F[o + N3.CZ]!,
              lz = leaf ? pz : B[j * BOX.NODE_STRIDE + BOX.MIN_Z]!,
              hz = leaf ? pz : B[j * BOX.NODE_STRIDE + BOX.MAX_Z]!;
            Z += w * pz;
            if (lz < minZ) minZ = lz;
            if (hz > maxZ) maxZ = hz;
          }
        }
        const cx = M > 0 ? X / M : 0.5 * (minX + maxX),
          cy = M > 0 ? Y / M : 0.5 * (minY + maxY),
          cz = M > 0 ? Z / M : 0.5 * (minZ + maxZ);
        // Parallel-axis theorem, d = c_child - c (a body: S_c = 0): S += S_c + M_c d d; in 2D also
        // T += T_c + 3 sym(d S_c) + M_c d d d. reach: a cell's farthest child extent, |d| + b_max(child).
        let sxx = 0,
          sxy = 0,
          syy = 0,
          szz = 0,
          sxz = 0,
          syz = 0,
          txxx = 0,
          txxy = 0,
          txyy = 0,
          tyyy = 0,
          reach = leaf ? Infinity : 0;
        for (let j = j0; j < j1; j = leaf ? j + 1 : skip[j]!) {
          const o = j * N3.STRIDE,
            w = leaf ? m[j]! : F[o + oM]!,
            dx = (leaf ? x[j]! : F[o + N3.CX]!) - cx,
            dy = (leaf ? y[j]! : F[o + N3.CY]!) - cy,
            dz = three ? (leaf ? z[j]! : F[o + N3.CZ]!) - cz : 0;
          const cxx = leaf ? 0 : F[o + oXX]!,
            cxy = leaf ? 0 : F[o + oXY]!,
            cyy = leaf ? 0 : F[o + oYY]!;
          const wxx = w * dx * dx,
            wxy = w * dx * dy,
            wyy = w * dy * dy;
          sxx += cxx + wxx;
          sxy += cxy + wxy;
          syy += cyy + wyy;
          if (!leaf) {
            const r = Math.sqrt(dx * dx + dy * dy + dz * dz) + F[o + oR]!;
            if (r > reach) reach = r;
          }
          if (three) {
            szz += (leaf ? 0 : F[o + N3.SZZ]!) + w * dz * dz;
            sxz += (leaf ? 0 : F[o + N3.SXZ]!) + w * dx * dz;
            syz += (leaf ? 0 : F[o + N3.SYZ]!) + w * dy * dz;
          } else if (leaf) {
            txxx += wxx * dx;
            txxy += wxx * dy;
            txyy += wyy * dx;
            tyyy += wyy * dy;
          } else {
            txxx += F[o + N2.TXXX]! + 3 * dx * cxx + wxx * dx;
            txxy += F[o + N2.TXXY]! + 2 * dx * cxy + dy * cxx + wxx * dy;
            txyy += F[o + N2.TXYY]! + 2 * dy * cxy + dx * cyy + wyy * dx;
            tyyy += F[o + N2.TYYY]! + 3 * dy * cyy + wyy * dy;
          }
        }
        const ex = Math.max(cx - minX, maxX - cx),
          ey = Math.max(cy - minY, maxY - cy),
          ez = Math.max(cz - minZ, maxZ - cz);
        const o = k * N3.STRIDE;
        F[o + N3.CX] = cx;
        F[o + N3.CY] = cy;
        F[o + oM] = M;
        F[o + oXX] = sxx;
        F[o + oXY] = sxy;
        F[o + oYY] = syy;
        F[o + oR] = Math.min(Math.sqrt(ex * ex + ey * ey + ez * ez), reach);
        if (three) {
          F[o + N3.CZ] = cz;
          F[o + N3.SZZ] = szz;
          F[o + N3.SXZ] = sxz;
          F[o + N3.SYZ] = syz;
        } else {
          F[o + N2.TXXX] = txxx;
          F[o + N2.TXXY] = txxy;
          F[o + N2.TXYY] = txyy;
          F[o + N2.TYYY] = tyyy;
        }
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
