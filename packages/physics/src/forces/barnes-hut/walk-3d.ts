import type { KernelArray } from '../../threads/kernel-types.js';

/** The 3D dual-tree walk and downward pass of the Barnes-Hut evaluation (see walk.ts), a thread kernel. */

/**
 * Dual-tree walk and downward pass, 3D (order 3); see walk.ts's header and forces/barnes-hut/tree.ts.
 * @category Forces
 */
export function barnesHutWalk3(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const X = A[0] as Float64Array,
    Y = A[1] as Float64Array,
    Z = A[2] as Float64Array,
    Mb = A[3] as Float64Array;
  const F = A[4] as Float64Array,
    start = A[5] as Int32Array,
    end = A[6] as Int32Array,
    skip = A[7] as Int32Array;
  const OX = A[8] as Float64Array,
    OY = A[9] as Float64Array,
    OZ = A[10] as Float64Array;
  const cut = A[11] as Int32Array,
    info = A[12] as Float64Array;
  const G = P[0]!,
    eps2 = P[1]!,
    f = P[2]!,
    nodeCount = P[3]!,
    offX = P[5]!,
    offY = P[6]!,
    offZ = P[7]!,
    addForces = P[8] === 1;
  const fa = P[9]!,
    FX = A[fa] as Float64Array,
    FY = A[fa + 1] as Float64Array,
    FZ = A[fa + 2] as Float64Array;
  const perm = A[fa + 3] as Int32Array,
    ents = A[fa + 4] as Int32Array;
  const NF = 12,
    NL = 19;
  let st = new Int32Array(8192);
  for (let part = lo; part < hi; part++) {
    const L = A[13 + part] as Float64Array;
    const s0 = cut[part]!,
      s1 = cut[part + 1]!;
    let cellPairs = 0,
      bodyPairs = 0,
      visits = 0,
      work = 0;
    if (s0 >= s1) {
      info[part * 4] = 0;
      info[part * 4 + 1] = 0;
      info[part * 4 + 2] = 0;
      info[part * 4 + 3] = 0;
      continue;
    }
    for (let k = 0; k < nodeCount; ) {
      if (start[k]! < s1 && end[k]! > s0) {
        L.fill(0, k * NL, k * NL + NL);
        k++;
      } else k = skip[k]!;
    }
    L.fill(0, offX + s0, offX + s1);
    L.fill(0, offY + s0, offY + s1);
    L.fill(0, offZ + s0, offZ + s1);
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
      work += 1;
      if (sp + 160 > st.length) {
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
      const oa = a * NF,
        ob = b * NF;
      const Rx = F[ob]! - F[oa]!,
        Ry = F[ob + 1]! - F[oa + 1]!,
        Rz = F[ob + 2]! - F[oa + 2]!;
      const u = Rx * Rx + Ry * Ry + Rz * Rz;
      const ra = F[oa + 10]!,
        rb = F[ob + 10]!,
        rs = ra + rb;
      const leafA = skip[a] === a + 1,
        leafB = skip[b] === b + 1;
      // Two cells of many bodies: expanded when far apart, else the larger cell (or the one not a
      // leaf) split; otherwise, and for a small cell with itself, the direct sum below.
      const many = !self && na * nb > 16,
        far = u > rs * rs * f;
      if (many && far) {
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
            l = (side === 0 ? a : b) * NL,
            sg = side === 0 ? -1 : 1;
          const sxx = F[o + 4]!,
            syy = F[o + 5]!,
            szz = F[o + 6]!,
            sxy = F[o + 7]!,
            sxz = F[o + 8]!,
            syz = F[o + 9]!;
          const srx = sxx * X1 + sxy * Y1 + sxz * Z1,
            sry = sxy * X1 + syy * Y1 + syz * Z1,
            srz = sxz * X1 + syz * Y1 + szz * Z1;
          const kk = D3 * (X1 * srx + Y1 * sry + Z1 * srz) + D2 * (sxx + syy + szz);
          const qx = 0.5 * (X1 * kk + 2 * D2 * srx),
            qy = 0.5 * (Y1 * kk + 2 * D2 * sry),
            qz = 0.5 * (Z1 * kk + 2 * D2 * srz);
          const M = F[o + 3]!,
            Ms = sg * M;
          L[l] = L[l]! + sg * (M * t1x + qx);
          L[l + 1] = L[l + 1]! + sg * (M * t1y + qy);
          L[l + 2] = L[l + 2]! + sg * (M * t1z + qz);
          L[l + 3] = L[l + 3]! + M * t2xx;
          L[l + 4] = L[l + 4]! + M * t2yy;
          L[l + 5] = L[l + 5]! + M * t2zz;
          L[l + 6] = L[l + 6]! + M * t2xy;
          L[l + 7] = L[l + 7]! + M * t2xz;
          L[l + 8] = L[l + 8]! + M * t2yz;
          L[l + 9] = L[l + 9]! + Ms * t3xxx;
          L[l + 10] = L[l + 10]! + Ms * t3xxy;
          L[l + 11] = L[l + 11]! + Ms * t3xxz;
          L[l + 12] = L[l + 12]! + Ms * t3xyy;
          L[l + 13] = L[l + 13]! + Ms * t3xyz;
          L[l + 14] = L[l + 14]! + Ms * t3xzz;
          L[l + 15] = L[l + 15]! + Ms * t3yyy;
          L[l + 16] = L[l + 16]! + Ms * t3yyz;
          L[l + 17] = L[l + 17]! + Ms * t3yzz;
          L[l + 18] = L[l + 18]! + Ms * t3zzz;
        }
        if (mine) cellPairs++;
        work += 8;
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
      const np = self ? ((hi1 - lo1) * (hi1 - lo1 - 1)) >> 1 : na * nb;
      if (mine) bodyPairs += np;
      work += np;
    }
    for (let k = 0; k < nodeCount; ) {
      const sk = skip[k]!;
      if (!(start[k]! < s1 && end[k]! > s0)) {
        k = sk;
        continue;
      }
      const o = k * NF,
        l = k * NL;
      const cx = F[o]!,
        cy = F[o + 1]!,
        cz = F[o + 2]!;
      const a0x = L[l]!,
        a0y = L[l + 1]!,
        a0z = L[l + 2]!;
      const jxx = L[l + 3]!,
        jyy = L[l + 4]!,
        jzz = L[l + 5]!,
        jxy = L[l + 6]!,
        jxz = L[l + 7]!,
        jyz = L[l + 8]!;
      const kxxx = L[l + 9]!,
        kxxy = L[l + 10]!,
        kxxz = L[l + 11]!,
        kxyy = L[l + 12]!,
        kxyz = L[l + 13]!;
      const kxzz = L[l + 14]!,
        kyyy = L[l + 15]!,
        kyyz = L[l + 16]!,
        kyzz = L[l + 17]!,
        kzzz = L[l + 18]!;
      if (sk === k + 1) {
        for (let s = start[k]!, e = end[k]!; s < e; s++) {
          const dx = X[s]! - cx,
            dy = Y[s]! - cy,
            dz = Z[s]! - cz;
          const kdxx = kxxx * dx + kxxy * dy + kxxz * dz,
            kdyy = kxyy * dx + kyyy * dy + kyyz * dz;
          const kdzz = kxzz * dx + kyzz * dy + kzzz * dz,
            kdxy = kxxy * dx + kxyy * dy + kxyz * dz;
          const kdxz = kxxz * dx + kxyz * dy + kxzz * dz,
            kdyz = kxyz * dx + kyyz * dy + kyzz * dz;
          const gx = G * (L[offX + s]! + a0x + jxx * dx + jxy * dy + jxz * dz + 0.5 * (kdxx * dx + kdxy * dy + kdxz * dz));
          const gy = G * (L[offY + s]! + a0y + jxy * dx + jyy * dy + jyz * dz + 0.5 * (kdxy * dx + kdyy * dy + kdyz * dz));
          const gz = G * (L[offZ + s]! + a0z + jxz * dx + jyz * dy + jzz * dz + 0.5 * (kdxz * dx + kdyz * dy + kdzz * dz));
          OX[s] = gx;
          OY[s] = gy;
          OZ[s] = gz;
          if (addForces) {
            const e = ents[perm[s]!]!,
              w = Mb[s]!;
            FX[e] = FX[e]! + w * gx;
            FY[e] = FY[e]! + w * gy;
            FZ[e] = FZ[e]! + w * gz;
          }
        }
        work += (end[k]! - start[k]!) >> 1;
        k = sk;
        continue;
      }
      for (let c = k + 1; c < sk; c = skip[c]!) {
        if (!(start[c]! < s1 && end[c]! > s0)) continue;
        const oc = c * NF,
          lc = c * NL;
        const dx = F[oc]! - cx,
          dy = F[oc + 1]! - cy,
          dz = F[oc + 2]! - cz;
        const kdxx = kxxx * dx + kxxy * dy + kxxz * dz,
          kdyy = kxyy * dx + kyyy * dy + kyyz * dz;
        const kdzz = kxzz * dx + kyzz * dy + kzzz * dz,
          kdxy = kxxy * dx + kxyy * dy + kxyz * dz;
        const kdxz = kxxz * dx + kxyz * dy + kxzz * dz,
          kdyz = kxyz * dx + kyyz * dy + kyzz * dz;
        L[lc] = L[lc]! + a0x + jxx * dx + jxy * dy + jxz * dz + 0.5 * (kdxx * dx + kdxy * dy + kdxz * dz);
        L[lc + 1] = L[lc + 1]! + a0y + jxy * dx + jyy * dy + jyz * dz + 0.5 * (kdxy * dx + kdyy * dy + kdyz * dz);
        L[lc + 2] = L[lc + 2]! + a0z + jxz * dx + jyz * dy + jzz * dz + 0.5 * (kdxz * dx + kdyz * dy + kdzz * dz);
        L[lc + 3] = L[lc + 3]! + jxx + kdxx;
        L[lc + 4] = L[lc + 4]! + jyy + kdyy;
        L[lc + 5] = L[lc + 5]! + jzz + kdzz;
        L[lc + 6] = L[lc + 6]! + jxy + kdxy;
        L[lc + 7] = L[lc + 7]! + jxz + kdxz;
        L[lc + 8] = L[lc + 8]! + jyz + kdyz;
        for (let q = 9; q < NL; q++) L[lc + q] = L[lc + q]! + L[l + q]!;
      }
      k++;
    }
    info[part * 4] = cellPairs;
    info[part * 4 + 1] = bodyPairs;
    info[part * 4 + 2] = visits;
    info[part * 4 + 3] = work;
  }
  return ids === null ? 0 : 0;
}
