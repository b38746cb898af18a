import type { KernelArray } from '../../threads/kernel-types.js';
import * as L2 from './field-2d.js';
import * as L3 from './field-3d.js';
import * as N2 from './node-2d.js';
import * as N3 from './node-3d.js';
import * as WALK from './walk.js';

/**
 * The dual-tree walk and downward pass of the Barnes-Hut evaluation (see walk.ts), one thread kernel
 * for 2D (expansions to order 4: forces/barnes-hut/node-2d.ts and field-2d.ts) and 3D (order 3:
 * node-3d.ts and field-3d.ts) by P[WALK.DIMENSIONS] (2 or 3). The walk itself (parts, the pair
 * stack, when to expand, split or sum directly, the counts, the order of the downward pass) is
 * written once; each dimension has its own cell-cell expansion, direct sum and node step of the
 * downward pass, a branch on the dimension taken once a cell pair, a leaf pair or a node. A and P:
 * walk.ts. Returns 0.
 * @category Forces
 */
export function barnesHutWalk(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const X = A[WALK.X] as Float64Array,
    Y = A[WALK.Y] as Float64Array,
    Z = A[WALK.Z] as Float64Array,
    Mb = A[WALK.MASS] as Float64Array;
  const F = A[WALK.NODE] as Float64Array,
    start = A[WALK.START] as Int32Array,
    end = A[WALK.END] as Int32Array,
    skip = A[WALK.SKIP] as Int32Array;
  const OX = A[WALK.AX] as Float64Array,
    OY = A[WALK.AY] as Float64Array,
    OZ = A[WALK.AZ] as Float64Array;
  const cut = A[WALK.CUT] as Int32Array,
    info = A[WALK.INFO] as Float64Array;
  const G = P[WALK.G]!,
    eps2 = P[WALK.EPS2]!,
    f = P[WALK.OPEN]!,
    nodeCount = P[WALK.NODE_COUNT]!,
    offX = P[WALK.ACC_X]!,
    offY = P[WALK.ACC_Y]!,
    offZ = P[WALK.ACC_Z]!,
    addForces = P[WALK.ADD_FORCES] === 1;
  const fa = P[WALK.FORCES_AT]!,
    FX = A[fa + WALK.FORCE_X] as Float64Array,
    FY = A[fa + WALK.FORCE_Y] as Float64Array,
    FZ = A[fa + WALK.FORCE_Z] as Float64Array;
  const perm = A[fa + WALK.PERM] as Int32Array,
    ents = A[fa + WALK.ENTS] as Int32Array;
  const three = P[WALK.DIMENSIONS] === 3,
    radius = three ? N3.RADIUS : N2.RADIUS,
    fieldStride = three ? L3.STRIDE : L2.STRIDE,
    margin = three ? 160 : 80;
  const third = 1 / 3;
  let st = new Int32Array(three ? 8192 : 4096);
  for (let part = lo; part < hi; part++) {
    const L = A[WALK.SCRATCH + part] as Float64Array;
    const s0 = cut[part]!,
      s1 = cut[part + 1]!;
    let cellPairs = 0,
      bodyPairs = 0,
      visits = 0,
      work = 0;
    if (s0 >= s1) {
      info[part * WALK.INFO_STRIDE + WALK.INFO_CELL_PAIRS] = 0;
      info[part * WALK.INFO_STRIDE + WALK.INFO_BODY_PAIRS] = 0;
      info[part * WALK.INFO_STRIDE + WALK.INFO_VISITS] = 0;
      info[part * WALK.INFO_STRIDE + WALK.INFO_WORK] = 0;
      continue;
    }
    // Zero the part's accumulators: the nodes holding some of its slots, and its slots.
    for (let k = 0; k < nodeCount; ) {
      if (start[k]! < s1 && end[k]! > s0) {
        L.fill(0, k * fieldStride, k * fieldStride + fieldStride);
        k++;
      } else k = skip[k]!;
    }
    L.fill(0, offX + s0, offX + s1);
    L.fill(0, offY + s0, offY + s1);
    if (three) L.fill(0, offZ + s0, offZ + s1);
    let sp = 0;
    st[sp++] = 0;
    st[sp++] = 0;
    while (sp > 0) {
      const b = st[--sp]!,
        a = st[--sp]!;
      const lo1 = start[a]!,
        hi1 = end[a]!,
        lo2 = start[b]!,
        hi2 = end[b]!;
      if (!(lo1 < s1 && hi1 > s0) && !(lo2 < s1 && hi2 > s0)) continue;
      const mine = lo1 >= s0 && lo1 < s1;
      if (mine) visits++;
      work += WALK.WORK_VISIT;
      if (sp + margin > st.length) {
        const grown = new Int32Array(2 * st.length);
        grown.set(st);
        st = grown;
      }
      const self = a === b;
      if (self && !(skip[a] === a + 1 || hi1 - lo1 <= 8)) {
        // The cell with itself: its children with themselves and each other.
        const sa = skip[a]!;
        for (let c = a + 1; c < sa; c = skip[c]!) {
          st[sp++] = c;
          st[sp++] = c;
          for (let d = skip[c]!; d < sa; d = skip[d]!) {
            st[sp++] = c;
            st[sp++] = d;
          }
        }
        continue;
      }
      const na = hi1 - lo1,
        nb = hi2 - lo2;
      // N2 and N3 have the centre at the same offsets and the same stride.
      const oa = a * N3.STRIDE,
        ob = b * N3.STRIDE;
      const Rx = F[ob + N3.CX]! - F[oa + N3.CX]!,
        Ry = F[ob + N3.CY]! - F[oa + N3.CY]!,
        Rz = three ? F[ob + N3.CZ]! - F[oa + N3.CZ]! : 0;
      const u = Rx * Rx + Ry * Ry + Rz * Rz;
      const ra = F[oa + radius]!,
        rb = F[ob + radius]!,
        rs = ra + rb;
      const leafA = skip[a] === a + 1,
        leafB = skip[b] === b + 1;
      // Two cells of many bodies: expanded when far apart, else the larger cell (or the one not a
      // leaf) split; otherwise, and for a small cell with itself, the direct sum below.
      const many = !self && na * nb > 16,
        far = u > rs * rs * f;
      if (many && far) {
        if (three) {
          // Mutual cell-cell expansion to order 3 (see forces/barnes-hut/tree.ts).
          const X1 = Rx,
            Y1 = Ry,
            Z1 = Rz;
          const g2 = 1 / (u + eps2),
            g = Math.sqrt(g2);
          const D1 = -g * g2,
            D2 = -3 * D1 * g2,
            D3 = -5 * D2 * g2;
          const t1x = X1 * D1,
            t1y = Y1 * D1,
            t1z = Z1 * D1;
          const t2xx = X1 * X1 * D2 + D1,
            t2yy = Y1 * Y1 * D2 + D1,
            t2zz = Z1 * Z1 * D2 + D1;
          const t2xy = X1 * Y1 * D2,
            t2xz = X1 * Z1 * D2,
            t2yz = Y1 * Z1 * D2;
          const x2 = X1 * X1,
            y2 = Y1 * Y1,
            z2 = Z1 * Z1;
          const t3xxx = X1 * (x2 * D3 + 3 * D2),
            t3xxy = Y1 * (x2 * D3 + D2),
            t3xxz = Z1 * (x2 * D3 + D2);
          const t3xyy = X1 * (y2 * D3 + D2),
            t3xyz = X1 * Y1 * Z1 * D3,
            t3xzz = X1 * (z2 * D3 + D2);
          const t3yyy = Y1 * (y2 * D3 + 3 * D2),
            t3yyz = Z1 * (y2 * D3 + D2),
            t3yzz = Y1 * (z2 * D3 + D2);
          const t3zzz = Z1 * (z2 * D3 + 3 * D2);
          // Side 0: cell a's polynomial from cell b's moments; side 1: cell b's from cell a's (the odd
          // terms change sign with the direction R).
          for (let side = 0; side < 2; side++) {
            const o = side === 0 ? ob : oa,
              l = (side === 0 ? a : b) * L3.STRIDE,
              sg = side === 0 ? -1 : 1;
            const sxx = F[o + N3.SXX]!,
              syy = F[o + N3.SYY]!,
              szz = F[o + N3.SZZ]!,
              sxy = F[o + N3.SXY]!,
              sxz = F[o + N3.SXZ]!,
              syz = F[o + N3.SYZ]!;
            const srx = sxx * X1 + sxy * Y1 + sxz * Z1,
              sry = sxy * X1 + syy * Y1 + syz * Z1,
              srz = sxz * X1 + syz * Y1 + szz * Z1;
            const kk = D3 * (X1 * srx + Y1 * sry + Z1 * srz) + D2 * (sxx + syy + szz);
            const qx = 0.5 * (X1 * kk + 2 * D2 * srx),
              qy = 0.5 * (Y1 * kk + 2 * D2 * sry),
              qz = 0.5 * (Z1 * kk + 2 * D2 * srz);
            const M = F[o + N3.MASS]!,
              Ms = sg * M;
            L[l + L3.A0X] = L[l + L3.A0X]! + sg * (M * t1x + qx);
            L[l + L3.A0Y] = L[l + L3.A0Y]! + sg * (M * t1y + qy);
            L[l + L3.A0Z] = L[l + L3.A0Z]! + sg * (M * t1z + qz);
            L[l + L3.JXX] = L[l + L3.JXX]! + M * t2xx;
            L[l + L3.JYY] = L[l + L3.JYY]! + M * t2yy;
            L[l + L3.JZZ] = L[l + L3.JZZ]! + M * t2zz;
            L[l + L3.JXY] = L[l + L3.JXY]! + M * t2xy;
            L[l + L3.JXZ] = L[l + L3.JXZ]! + M * t2xz;
            L[l + L3.JYZ] = L[l + L3.JYZ]! + M * t2yz;
            L[l + L3.KXXX] = L[l + L3.KXXX]! + Ms * t3xxx;
            L[l + L3.KXXY] = L[l + L3.KXXY]! + Ms * t3xxy;
            L[l + L3.KXXZ] = L[l + L3.KXXZ]! + Ms * t3xxz;
            L[l + L3.KXYY] = L[l + L3.KXYY]! + Ms * t3xyy;
            L[l + L3.KXYZ] = L[l + L3.KXYZ]! + Ms * t3xyz;
            L[l + L3.KXZZ] = L[l + L3.KXZZ]! + Ms * t3xzz;
            L[l + L3.KYYY] = L[l + L3.KYYY]! + Ms * t3yyy;
            L[l + L3.KYYZ] = L[l + L3.KYYZ]! + Ms * t3yyz;
            L[l + L3.KYZZ] = L[l + L3.KYZZ]! + Ms * t3yzz;
            L[l + L3.KZZZ] = L[l + L3.KZZZ]! + Ms * t3zzz;
          }
        } else {
          // Mutual cell-cell expansion to order 4 (see forces/barnes-hut/tree.ts).
          const X1 = Rx,
            Y1 = Ry;
          const g2 = 1 / (u + eps2),
            g = Math.sqrt(g2);
          const D1 = -g * g2,
            D2 = -3 * D1 * g2,
            D3 = -5 * D2 * g2,
            D4 = -7 * D3 * g2;
          const x2 = X1 * X1,
            y2 = Y1 * Y1,
            xy = X1 * Y1;
          const t1x = X1 * D1,
            t1y = Y1 * D1;
          const t2xx = x2 * D2 + D1,
            t2xy = xy * D2,
            t2yy = y2 * D2 + D1;
          const t3xxx = X1 * (x2 * D3 + 3 * D2),
            t3xxy = Y1 * (x2 * D3 + D2),
            t3xyy = X1 * (y2 * D3 + D2),
            t3yyy = Y1 * (y2 * D3 + 3 * D2);
          const t4xxxx = x2 * (x2 * D4 + 6 * D3) + 3 * D2,
            t4xxxy = xy * (x2 * D4 + 3 * D3);
          const t4xxyy = x2 * y2 * D4 + (x2 + y2) * D3 + D2,
            t4xyyy = xy * (y2 * D4 + 3 * D3),
            t4yyyy = y2 * (y2 * D4 + 6 * D3) + 3 * D2;
          // Side 0: cell a's polynomial from cell b's moments; side 1: cell b's from cell a's (the odd
          // terms change sign with the direction R).
          for (let side = 0; side < 2; side++) {
            const o = side === 0 ? ob : oa,
              l = (side === 0 ? a : b) * L2.STRIDE,
              sg = side === 0 ? -1 : 1;
            const sxx = F[o + N2.SXX]!,
              sxy = F[o + N2.SXY]!,
              syy = F[o + N2.SYY]!;
            const srx = sxx * X1 + sxy * Y1,
              sry = sxy * X1 + syy * Y1,
              rsr = X1 * srx + Y1 * sry,
              tr = sxx + syy;
            const c0 = D3 * rsr + D2 * tr,
              c1 = D4 * rsr + D3 * tr;
            const qx = 0.5 * X1 * c0 + D2 * srx,
              qy = 0.5 * Y1 * c0 + D2 * sry;
            const pxx = 0.5 * (x2 * c1 + c0) + 2 * D3 * X1 * srx + D2 * sxx;
            const pxy = 0.5 * xy * c1 + D3 * (srx * Y1 + X1 * sry) + D2 * sxy;
            const pyy = 0.5 * (y2 * c1 + c0) + 2 * D3 * Y1 * sry + D2 * syy;
            const txxx = F[o + N2.TXXX]!,
              txxy = F[o + N2.TXXY]!,
              txyy = F[o + N2.TXYY]!,
              tyyy = F[o + N2.TYYY]!;
            const s3x = txxx * x2 + 2 * txxy * xy + txyy * y2,
              s3y = txxy * x2 + 2 * txyy * xy + tyyy * y2;
            const vx = txxx + txyy,
              vy = txxy + tyyy;
            const c3 = D4 * (X1 * s3x + Y1 * s3y) + 3 * D3 * (vx * X1 + vy * Y1);
            const ox = (X1 * c3 + 3 * D3 * s3x + 3 * D2 * vx) / 6,
              oy = (Y1 * c3 + 3 * D3 * s3y + 3 * D2 * vy) / 6;
            const M = F[o + N2.MASS]!,
              Ms = sg * M;
            L[l + L2.A0X] = L[l + L2.A0X]! + (sg * (M * t1x + qx) - ox);
            L[l + L2.A0Y] = L[l + L2.A0Y]! + (sg * (M * t1y + qy) - oy);
            L[l + L2.JXX] = L[l + L2.JXX]! + M * t2xx + pxx;
            L[l + L2.JXY] = L[l + L2.JXY]! + M * t2xy + pxy;
            L[l + L2.JYY] = L[l + L2.JYY]! + M * t2yy + pyy;
            L[l + L2.KXXX] = L[l + L2.KXXX]! + Ms * t3xxx;
            L[l + L2.KXXY] = L[l + L2.KXXY]! + Ms * t3xxy;
            L[l + L2.KXYY] = L[l + L2.KXYY]! + Ms * t3xyy;
            L[l + L2.KYYY] = L[l + L2.KYYY]! + Ms * t3yyy;
            L[l + L2.HXXXX] = L[l + L2.HXXXX]! + M * t4xxxx;
            L[l + L2.HXXXY] = L[l + L2.HXXXY]! + M * t4xxxy;
            L[l + L2.HXXYY] = L[l + L2.HXXYY]! + M * t4xxyy;
            L[l + L2.HXYYY] = L[l + L2.HXYYY]! + M * t4xyyy;
            L[l + L2.HYYYY] = L[l + L2.HYYYY]! + M * t4yyyy;
          }
        }
        if (mine) cellPairs++;
        work += WALK.WORK_CELL_PAIR;
        continue;
      }
      if (many && !(leafA && leafB)) {
        if (!leafA && (leafB || ra >= rb)) {
          const sa = skip[a]!;
          for (let c = a + 1; c < sa; c = skip[c]!) {
            st[sp++] = c;
            st[sp++] = b;
          }
        } else {
          const sb = skip[b]!;
          for (let c = b + 1; c < sb; c = skip[c]!) {
            st[sp++] = a;
            st[sp++] = c;
          }
        }
        continue;
      }
      // Direct sum over the body pairs, both bodies of each: within the cell (each pair once) or
      // between the two cells.
      if (three) {
        for (let i = lo1, iEnd = self ? hi1 - 1 : hi1; i < iEnd; i++) {
          const xi = X[i]!,
            yi = Y[i]!,
            zi = Z[i]!,
            mi = Mb[i]!;
          let sx = 0,
            sy = 0,
            sz = 0;
          for (let j = self ? i + 1 : lo2; j < hi2; j++) {
            const dx = X[j]! - xi,
              dy = Y[j]! - yi,
              dz = Z[j]! - zi;
            const r2 = dx * dx + dy * dy + dz * dz + eps2;
            if (r2 > 0) {
              const w = 1 / (r2 * Math.sqrt(r2)),
                wx = w * dx,
                wy = w * dy,
                wz = w * dz,
                mj = Mb[j]!;
              sx += mj * wx;
              sy += mj * wy;
              sz += mj * wz;
              L[offX + j] = L[offX + j]! - mi * wx;
              L[offY + j] = L[offY + j]! - mi * wy;
              L[offZ + j] = L[offZ + j]! - mi * wz;
            }
          }
          L[offX + i] = L[offX + i]! + sx;
          L[offY + i] = L[offY + i]! + sy;
          L[offZ + i] = L[offZ + i]! + sz;
        }
      } else {
        for (let i = lo1, iEnd = self ? hi1 - 1 : hi1; i < iEnd; i++) {
          const xi = X[i]!,
            yi = Y[i]!,
            mi = Mb[i]!;
          let sx = 0,
            sy = 0;
          for (let j = self ? i + 1 : lo2; j < hi2; j++) {
            const dx = X[j]! - xi,
              dy = Y[j]! - yi;
            const r2 = dx * dx + dy * dy + eps2;
            if (r2 > 0) {
              const w = 1 / (r2 * Math.sqrt(r2)),
                wx = w * dx,
                wy = w * dy,
                mj = Mb[j]!;
              sx += mj * wx;
              sy += mj * wy;
              L[offX + j] = L[offX + j]! - mi * wx;
              L[offY + j] = L[offY + j]! - mi * wy;
            }
          }
          L[offX + i] = L[offX + i]! + sx;
          L[offY + i] = L[offY + i]! + sy;
        }
      }
      const np = self ? ((hi1 - lo1) * (hi1 - lo1 - 1)) >> 1 : na * nb;
      if (mine) bodyPairs += np;
      work += np;
    }
    // Downward pass over the nodes holding slots of the part: shift each cell's polynomial
    // a(d) = a0 + J d + K d d / 2 + H d d d / 6 to its children, evaluate it at the part's bodies.
    for (let k = 0; k < nodeCount; ) {
      const sk = skip[k]!;
      if (!(start[k]! < s1 && end[k]! > s0)) {
        k = sk;
        continue;
      }
      const leaf = sk === k + 1;
      if (three) {
        const o = k * N3.STRIDE,
          l = k * L3.STRIDE;
        const cx = F[o + N3.CX]!,
          cy = F[o + N3.CY]!,
          cz = F[o + N3.CZ]!;
        const a0x = L[l + L3.A0X]!,
          a0y = L[l + L3.A0Y]!,
          a0z = L[l + L3.A0Z]!;
        const jxx = L[l + L3.JXX]!,
          jyy = L[l + L3.JYY]!,
          jzz = L[l + L3.JZZ]!,
          jxy = L[l + L3.JXY]!,
          jxz = L[l + L3.JXZ]!,
          jyz = L[l + L3.JYZ]!;
        const kxxx = L[l + L3.KXXX]!,
          kxxy = L[l + L3.KXXY]!,
          kxxz = L[l + L3.KXXZ]!,
          kxyy = L[l + L3.KXYY]!,
          kxyz = L[l + L3.KXYZ]!;
        const kxzz = L[l + L3.KXZZ]!,
          kyyy = L[l + L3.KYYY]!,
          kyyz = L[l + L3.KYYZ]!,
          kyzz = L[l + L3.KYZZ]!,
          kzzz = L[l + L3.KZZZ]!;
        // Leaf: the polynomial at each body j; cell: shifted to each child j holding slots of the part.
        for (let j = leaf ? start[k]! : k + 1, jEnd = leaf ? end[k]! : sk; j < jEnd; j = leaf ? j + 1 : skip[j]!) {
          if (!leaf && !(start[j]! < s1 && end[j]! > s0)) continue;
          const oc = j * N3.STRIDE,
            lc = j * L3.STRIDE;
          const dx = (leaf ? X[j]! : F[oc + N3.CX]!) - cx,
            dy = (leaf ? Y[j]! : F[oc + N3.CY]!) - cy,
            dz = (leaf ? Z[j]! : F[oc + N3.CZ]!) - cz;
          const kdxx = kxxx * dx + kxxy * dy + kxxz * dz,
            kdyy = kxyy * dx + kyyy * dy + kyyz * dz;
          const kdzz = kxzz * dx + kyzz * dy + kzzz * dz,
            kdxy = kxxy * dx + kxyy * dy + kxyz * dz;
          const kdxz = kxxz * dx + kxyz * dy + kxzz * dz,
            kdyz = kxyz * dx + kyyz * dy + kyzz * dz;
          // a = a0 + J d + K d d / 2, added to the body's direct sum or the child's a0.
          const ax =
            (leaf ? L[offX + j]! : L[lc + L3.A0X]!) + a0x + jxx * dx + jxy * dy + jxz * dz + 0.5 * (kdxx * dx + kdxy * dy + kdxz * dz);
          const ay =
            (leaf ? L[offY + j]! : L[lc + L3.A0Y]!) + a0y + jxy * dx + jyy * dy + jyz * dz + 0.5 * (kdxy * dx + kdyy * dy + kdyz * dz);
          const az =
            (leaf ? L[offZ + j]! : L[lc + L3.A0Z]!) + a0z + jxz * dx + jyz * dy + jzz * dz + 0.5 * (kdxz * dx + kdyz * dy + kdzz * dz);
          if (leaf) {
            const gx = G * ax,
              gy = G * ay,
              gz = G * az;
            OX[j] = gx;
            OY[j] = gy;
            OZ[j] = gz;
            if (addForces) {
              const e = ents[perm[j]!]!,
                w = Mb[j]!;
              FX[e] = FX[e]! + w * gx;
              FY[e] = FY[e]! + w * gy;
              FZ[e] = FZ[e]! + w * gz;
            }
          } else {
            L[lc + L3.A0X] = ax;
            L[lc + L3.A0Y] = ay;
            L[lc + L3.A0Z] = az;
            L[lc + L3.JXX] = L[lc + L3.JXX]! + jxx + kdxx;
            L[lc + L3.JYY] = L[lc + L3.JYY]! + jyy + kdyy;
            L[lc + L3.JZZ] = L[lc + L3.JZZ]! + jzz + kdzz;
            L[lc + L3.JXY] = L[lc + L3.JXY]! + jxy + kdxy;
            L[lc + L3.JXZ] = L[lc + L3.JXZ]! + jxz + kdxz;
            L[lc + L3.JYZ] = L[lc + L3.JYZ]! + jyz + kdyz;
            for (let q = L3.KXXX; q < L3.STRIDE; q++) L[lc + q] = L[lc + q]! + L[l + q]!;
          }
        }
      } else {
        const o = k * N2.STRIDE,
          l = k * L2.STRIDE;
        const cx = F[o + N2.CX]!,
          cy = F[o + N2.CY]!;
        const a0x = L[l + L2.A0X]!,
          a0y = L[l + L2.A0Y]!,
          jxx = L[l + L2.JXX]!,
          jxy = L[l + L2.JXY]!,
          jyy = L[l + L2.JYY]!;
        const kxxx = L[l + L2.KXXX]!,
          kxxy = L[l + L2.KXXY]!,
          kxyy = L[l + L2.KXYY]!,
          kyyy = L[l + L2.KYYY]!;
        const h0 = L[l + L2.HXXXX]!,
          h1 = L[l + L2.HXXXY]!,
          h2 = L[l + L2.HXXYY]!,
          h3 = L[l + L2.HXYYY]!,
          h4 = L[l + L2.HYYYY]!;
        // Leaf: the polynomial at each body j; cell: shifted to each child j holding slots of the part.
        for (let j = leaf ? start[k]! : k + 1, jEnd = leaf ? end[k]! : sk; j < jEnd; j = leaf ? j + 1 : skip[j]!) {
          if (!leaf && !(start[j]! < s1 && end[j]! > s0)) continue;
          const oc = j * N2.STRIDE,
            lc = j * L2.STRIDE;
          const dx = (leaf ? X[j]! : F[oc + N2.CX]!) - cx,
            dy = (leaf ? Y[j]! : F[oc + N2.CY]!) - cy;
          // Hd, K1 = K + Hd / 3, J1 = J + K1 d / 2, a = a0 + J1 d (added to the body's direct sum or
          // the child's a0); a child also gets K' = K + Hd, J' = J + (K + Hd / 2) d and H.
          const hd0 = h0 * dx + h1 * dy,
            hd1 = h1 * dx + h2 * dy,
            hd2 = h2 * dx + h3 * dy,
            hd3 = h3 * dx + h4 * dy;
          const k0 = kxxx + third * hd0,
            k1 = kxxy + third * hd1,
            k2 = kxyy + third * hd2,
            k3 = kyyy + third * hd3;
          const j0 = jxx + 0.5 * (k0 * dx + k1 * dy),
            j1 = jxy + 0.5 * (k1 * dx + k2 * dy),
            j2 = jyy + 0.5 * (k2 * dx + k3 * dy);
          const ax = (leaf ? L[offX + j]! : L[lc + L2.A0X]!) + a0x + j0 * dx + j1 * dy,
            ay = (leaf ? L[offY + j]! : L[lc + L2.A0Y]!) + a0y + j1 * dx + j2 * dy;
          if (leaf) {
            const gx = G * ax,
              gy = G * ay;
            OX[j] = gx;
            OY[j] = gy;
            OZ[j] = 0;
            if (addForces) {
              // F += m g on the body's entity (no z: a 2D field has none).
              const e = ents[perm[j]!]!,
                w = Mb[j]!;
              FX[e] = FX[e]! + w * gx;
              FY[e] = FY[e]! + w * gy;
            }
          } else {
            L[lc + L2.A0X] = ax;
            L[lc + L2.A0Y] = ay;
            const m0 = kxxx + 0.5 * hd0,
              m1 = kxxy + 0.5 * hd1,
              m2 = kxyy + 0.5 * hd2,
              m3 = kyyy + 0.5 * hd3;
            L[lc + L2.JXX] = L[lc + L2.JXX]! + jxx + m0 * dx + m1 * dy;
            L[lc + L2.JXY] = L[lc + L2.JXY]! + jxy + m1 * dx + m2 * dy;
            L[lc + L2.JYY] = L[lc + L2.JYY]! + jyy + m2 * dx + m3 * dy;
            L[lc + L2.KXXX] = L[lc + L2.KXXX]! + kxxx + hd0;
            L[lc + L2.KXXY] = L[lc + L2.KXXY]! + kxxy + hd1;
            L[lc + L2.KXYY] = L[lc + L2.KXYY]! + kxyy + hd2;
            L[lc + L2.KYYY] = L[lc + L2.KYYY]! + kyyy + hd3;
            L[lc + L2.HXXXX] = L[lc + L2.HXXXX]! + h0;
            L[lc + L2.HXXXY] = L[lc + L2.HXXXY]! + h1;
            L[lc + L2.HXXYY] = L[lc + L2.HXXYY]! + h2;
            L[lc + L2.HXYYY] = L[lc + L2.HXYYY]! + h3;
            L[lc + L2.HYYYY] = L[lc + L2.HYYYY]! + h4;
          }
        }
      }
      if (leaf) {
        work += (end[k]! - start[k]!) >> 1;
        k = sk;
      } else k++;
    }
    info[part * WALK.INFO_STRIDE + WALK.INFO_CELL_PAIRS] = cellPairs;
    info[part * WALK.INFO_STRIDE + WALK.INFO_BODY_PAIRS] = bodyPairs;
    info[part * WALK.INFO_STRIDE + WALK.INFO_VISITS] = visits;
    info[part * WALK.INFO_STRIDE + WALK.INFO_WORK] = work;
  }
  return ids === null ? 0 : 0;
}
