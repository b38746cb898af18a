import type { KernelArray } from '../../threads/kernel-types.js';

/** The 2D dual-tree walk and downward pass of the Barnes-Hut evaluation (see walk.ts), a thread kernel. */

/**
 * Dual-tree walk and downward pass, 2D (order 4); see walk.ts's header and forces/barnes-hut/tree.ts.
 * @category Forces
 */
export function barnesHutWalk2(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const X = A[0] as Float64Array,
    Y = A[1] as Float64Array,
    Mb = A[3] as Float64Array,
    F = A[4] as Float64Array;
  const start = A[5] as Int32Array,
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
    addForces = P[8] === 1;
  const fa = P[9]!,
    FX = A[fa] as Float64Array,
    FY = A[fa + 1] as Float64Array,
    perm = A[fa + 3] as Int32Array,
    ents = A[fa + 4] as Int32Array;
  const NF = 12,
    NL = 14,
    third = 1 / 3;
  let st = new Int32Array(4096);
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
    // Zero the part's accumulators: the nodes holding some of its slots, and its slots.
    for (let k = 0; k < nodeCount; ) {
      if (start[k]! < s1 && end[k]! > s0) {
        L.fill(0, k * NL, k * NL + NL);
        k++;
      } else k = skip[k]!;
    }
    L.fill(0, offX + s0, offX + s1);
    L.fill(0, offY + s0, offY + s1);
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
      if (sp + 80 > st.length) {
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
        Ry = F[ob + 1]! - F[oa + 1]!;
      const u = Rx * Rx + Ry * Ry;
      const ra = F[oa + 6]!,
        rb = F[ob + 6]!,
        rs = ra + rb;
      const leafA = skip[a] === a + 1,
        leafB = skip[b] === b + 1;
      // Two cells of many bodies: expanded when far apart, else the larger cell (or the one not a
      // leaf) split; otherwise, and for a small cell with itself, the direct sum below.
      const many = !self && na * nb > 16,
        far = u > rs * rs * f;
      if (many && far) {
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
            l = (side === 0 ? a : b) * NL,
            sg = side === 0 ? -1 : 1;
          const sxx = F[o + 3]!,
            sxy = F[o + 4]!,
            syy = F[o + 5]!;
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
          const txxx = F[o + 7]!,
            txxy = F[o + 8]!,
            txyy = F[o + 9]!,
            tyyy = F[o + 10]!;
          const s3x = txxx * x2 + 2 * txxy * xy + txyy * y2,
            s3y = txxy * x2 + 2 * txyy * xy + tyyy * y2;
          const vx = txxx + txyy,
            vy = txxy + tyyy;
          const c3 = D4 * (X1 * s3x + Y1 * s3y) + 3 * D3 * (vx * X1 + vy * Y1);
          const ox = (X1 * c3 + 3 * D3 * s3x + 3 * D2 * vx) / 6,
            oy = (Y1 * c3 + 3 * D3 * s3y + 3 * D2 * vy) / 6;
          const M = F[o + 2]!,
            Ms = sg * M;
          L[l] = L[l]! + (sg * (M * t1x + qx) - ox);
          L[l + 1] = L[l + 1]! + (sg * (M * t1y + qy) - oy);
          L[l + 2] = L[l + 2]! + M * t2xx + pxx;
          L[l + 3] = L[l + 3]! + M * t2xy + pxy;
          L[l + 4] = L[l + 4]! + M * t2yy + pyy;
          L[l + 5] = L[l + 5]! + Ms * t3xxx;
          L[l + 6] = L[l + 6]! + Ms * t3xxy;
          L[l + 7] = L[l + 7]! + Ms * t3xyy;
          L[l + 8] = L[l + 8]! + Ms * t3yyy;
          L[l + 9] = L[l + 9]! + M * t4xxxx;
          L[l + 10] = L[l + 10]! + M * t4xxxy;
          L[l + 11] = L[l + 11]! + M * t4xxyy;
          L[l + 12] = L[l + 12]! + M * t4xyyy;
          L[l + 13] = L[l + 13]! + M * t4yyyy;
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
      const o = k * NF,
        l = k * NL;
      const cx = F[o]!,
        cy = F[o + 1]!;
      const a0x = L[l]!,
        a0y = L[l + 1]!,
        jxx = L[l + 2]!,
        jxy = L[l + 3]!,
        jyy = L[l + 4]!;
      const kxxx = L[l + 5]!,
        kxxy = L[l + 6]!,
        kxyy = L[l + 7]!,
        kyyy = L[l + 8]!;
      const h0 = L[l + 9]!,
        h1 = L[l + 10]!,
        h2 = L[l + 11]!,
        h3 = L[l + 12]!,
        h4 = L[l + 13]!;
      if (sk === k + 1) {
        for (let s = start[k]!, e = end[k]!; s < e; s++) {
          const dx = X[s]! - cx,
            dy = Y[s]! - cy;
          // K1 = K + H d / 3, J1 = J + K1 d / 2, a = a0 + J1 d.
          const k0 = kxxx + third * (h0 * dx + h1 * dy),
            k1 = kxxy + third * (h1 * dx + h2 * dy);
          const k2 = kxyy + third * (h2 * dx + h3 * dy),
            k3 = kyyy + third * (h3 * dx + h4 * dy);
          const j0 = jxx + 0.5 * (k0 * dx + k1 * dy),
            j1 = jxy + 0.5 * (k1 * dx + k2 * dy),
            j2 = jyy + 0.5 * (k2 * dx + k3 * dy);
          const gx = G * (L[offX + s]! + a0x + j0 * dx + j1 * dy),
            gy = G * (L[offY + s]! + a0y + j1 * dx + j2 * dy);
          OX[s] = gx;
          OY[s] = gy;
          OZ[s] = 0;
          if (addForces) {
            // F += m g on the body's entity (no z: a 2D field has none).
            const e = ents[perm[s]!]!,
              w = Mb[s]!;
            FX[e] = FX[e]! + w * gx;
            FY[e] = FY[e]! + w * gy;
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
          dy = F[oc + 1]! - cy;
        // Hd, then K' = K + Hd, J' = J + (K + Hd / 2) d, a0' = a0 + (J + (K + Hd / 3) d / 2) d.
        const hd0 = h0 * dx + h1 * dy,
          hd1 = h1 * dx + h2 * dy,
          hd2 = h2 * dx + h3 * dy,
          hd3 = h3 * dx + h4 * dy;
        let k0 = kxxx + third * hd0,
          k1 = kxxy + third * hd1,
          k2 = kxyy + third * hd2,
          k3 = kyyy + third * hd3;
        const j0 = jxx + 0.5 * (k0 * dx + k1 * dy),
          j1 = jxy + 0.5 * (k1 * dx + k2 * dy),
          j2 = jyy + 0.5 * (k2 * dx + k3 * dy);
        L[lc] = L[lc]! + a0x + j0 * dx + j1 * dy;
        L[lc + 1] = L[lc + 1]! + a0y + j1 * dx + j2 * dy;
        k0 = kxxx + 0.5 * hd0;
        k1 = kxxy + 0.5 * hd1;
        k2 = kxyy + 0.5 * hd2;
        k3 = kyyy + 0.5 * hd3;
        L[lc + 2] = L[lc + 2]! + jxx + k0 * dx + k1 * dy;
        L[lc + 3] = L[lc + 3]! + jxy + k1 * dx + k2 * dy;
        L[lc + 4] = L[lc + 4]! + jyy + k2 * dx + k3 * dy;
        L[lc + 5] = L[lc + 5]! + kxxx + hd0;
        L[lc + 6] = L[lc + 6]! + kxxy + hd1;
        L[lc + 7] = L[lc + 7]! + kxyy + hd2;
        L[lc + 8] = L[lc + 8]! + kyyy + hd3;
        L[lc + 9] = L[lc + 9]! + h0;
        L[lc + 10] = L[lc + 10]! + h1;
        L[lc + 11] = L[lc + 11]! + h2;
        L[lc + 12] = L[lc + 12]! + h3;
        L[lc + 13] = L[lc + 13]! + h4;
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
