import { contact3DStateOf } from '../collision/manifolds-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import * as BS from './body-state-layout.js';
import { bouncingList, boundedImpulse, normalBias, normalImpulse, softRow } from './contact-point.js';
import * as CP from './contact-point-layout.js';
import * as M3 from './manifold-layout-3d.js';
import { restitutionImpulse, restitutionTarget } from './restitution.js';
import { rigidPartner } from './rigid-partner.js';

/** The 3D manifold rows' substep stages (solver/manifold-rows-3d.ts): warm start, the solve (normal rows with their sweeps, the friction patch and twist), and restitution after the substeps. */

/**
 * A manifold's normal rows are swept again (alternating order, at most NORMAL_SWEEPS sweeps) while every
 * row it met was rigid: a speculative row (s > 0) in any pass, or any row in a relax pass; the soft rows
 * of a biased pass take one sweep, as Box2D's soft step is made for. Only a hit sweeps again: the first
 * sweep changed the manifold's impulse by more than HIT_FRACTION of it (a resting contact's warm-started
 * impulse changes by a few per cent, and keeps its one sweep and its cost). The sweeps stop once a
 * sweep's change of impulse (sum of |delta lambda|) is below SWEEP_TOLERANCE of the manifold's impulse,
 * or moves the bodies apart by less than SWEEP_SPEED m/s ((1/m_A + 1/m_B) sum |delta lambda|).
 *
 * Why: one Gauss-Seidel sweep over the four points of a face that meets another flat gives the whole
 * approach to the first point visited, which stops it by turning the box, and the others then push
 * back on the spin. Two 1 m cubes meeting face to face at 1 m/s with zero restitution parted at
 * 0.033 m/s spinning at 0.13 rad/s; a cube dropped flat at 10 m/s onto a static box floor left at
 * 0.16 m/s sideways, 0.13 m/s back up and 0.23 rad/s. The sweeps converge (a manifold's rigid rows form
 * a symmetric positive semi-definite system: projected Gauss-Seidel) to the exact shares: now both stop
 * (below 1e-3 m/s and rad/s).
 */
const NORMAL_SWEEPS = 8;
/** A second sweep only follows a first that changed the impulse by more than this fraction of it (a hit, not a resting contact's correction). */
const HIT_FRACTION = 0.25;
const SWEEP_TOLERANCE = 1e-3;
const SWEEP_SPEED = 1e-3;

/**
 * Warm start: last step's impulses applied again. A manifold's normal impulses are summed over its points
 * (linear sum(ln) n, angular sum(ln I^-1 (r x n))), its friction impulses added, and each body written once.
 * @category Collision
 */
export function warmStartManifolds3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const buf = st.current,
    sb = world.collision.bodyState,
    R = st.solveRecord,
    JI = st.jacobiansInv;
  const LN = buf.ln;
  for (let i = 0; i < buf.count; i++) {
    const f1 = buf.ft[3 * i]!,
      f2 = buf.ft[3 * i + 1]!,
      fw = buf.ft[3 * i + 2]!;
    // Sum of the normal impulses and their angular parts on A and B.
    let sn = 0,
      ax = 0,
      ay = 0,
      az = 0,
      bx = 0,
      by = 0,
      bz = 0;
    const iso = buf.iso[i] === 1,
      h = M3.REC_STRIDE * i;
    for (let k = 0, m = buf.points[i]!; k < m; k++) {
      const q = 4 * i + k,
        ln = LN[q]!;
      if (ln === 0) continue;
      // Isotropic: i sum(ln r x n) from the crosses in the record (scaled by i below); else the stored products.
      sn += ln;
      if (iso) {
        const p = h + M3.REC_POINTS + M3.POINT_STRIDE * k;
        ax += ln * R[p + CP.CP_NORMAL_ROW + M3.ROW_AX]!;
        ay += ln * R[p + CP.CP_NORMAL_ROW + M3.ROW_AY]!;
        az += ln * R[p + CP.CP_NORMAL_ROW + M3.ROW_AZ]!;
        bx += ln * R[p + CP.CP_NORMAL_ROW + M3.ROW_BX]!;
        by += ln * R[p + CP.CP_NORMAL_ROW + M3.ROW_BY]!;
        bz += ln * R[p + CP.CP_NORMAL_ROW + M3.ROW_BZ]!;
      } else {
        const o = M3.JAC_STRIDE * q;
        ax += ln * JI[o + M3.ROW_AX]!;
        ay += ln * JI[o + M3.ROW_AY]!;
        az += ln * JI[o + M3.ROW_AZ]!;
        bx += ln * JI[o + M3.ROW_BX]!;
        by += ln * JI[o + M3.ROW_BY]!;
        bz += ln * JI[o + M3.ROW_BZ]!;
      }
    }
    if (sn === 0 && f1 === 0 && f2 === 0 && fw === 0) continue;
    const nx = R[h + M3.HEAD_NX]!,
      ny = R[h + M3.HEAD_NY]!,
      nz = R[h + M3.HEAD_NZ]!,
      t1x = R[h + M3.HEAD_T1X]!,
      t1y = R[h + M3.HEAD_T1Y]!,
      t1z = R[h + M3.HEAD_T1Z]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const px = sn * nx + f1 * t1x + f2 * t2x,
      py = sn * ny + f1 * t1y + f2 * t2y,
      pz = sn * nz + f1 * t1z + f2 * t2z;
    // The friction rows' angular parts (anchor crosses for t1, t2; n for the twist).
    if (iso) {
      const o1 = h + M3.REC_T1,
        o2 = h + M3.REC_T2;
      ax += f1 * R[o1 + M3.ROW_AX]! + f2 * R[o2 + M3.ROW_AX]!;
      ay += f1 * R[o1 + M3.ROW_AY]! + f2 * R[o2 + M3.ROW_AY]!;
      az += f1 * R[o1 + M3.ROW_AZ]! + f2 * R[o2 + M3.ROW_AZ]!;
      bx += f1 * R[o1 + M3.ROW_BX]! + f2 * R[o2 + M3.ROW_BX]!;
      by += f1 * R[o1 + M3.ROW_BY]! + f2 * R[o2 + M3.ROW_BY]!;
      bz += f1 * R[o1 + M3.ROW_BZ]! + f2 * R[o2 + M3.ROW_BZ]!;
      ax += fw * nx;
      ay += fw * ny;
      az += fw * nz;
      bx += fw * nx;
      by += fw * ny;
      bz += fw * nz;
    } else {
      const F = st.frictionInv,
        o = M3.FRICTION_INV_STRIDE * i,
        o1 = o + M3.FRICTION_T1,
        o2 = o + M3.FRICTION_T2,
        w = o + M3.FRICTION_TWIST;
      ax += f1 * F[o1 + M3.ROW_AX]! + f2 * F[o2 + M3.ROW_AX]!;
      ay += f1 * F[o1 + M3.ROW_AY]! + f2 * F[o2 + M3.ROW_AY]!;
      az += f1 * F[o1 + M3.ROW_AZ]! + f2 * F[o2 + M3.ROW_AZ]!;
      bx += f1 * F[o1 + M3.ROW_BX]! + f2 * F[o2 + M3.ROW_BX]!;
      by += f1 * F[o1 + M3.ROW_BY]! + f2 * F[o2 + M3.ROW_BY]!;
      bz += f1 * F[o1 + M3.ROW_BZ]! + f2 * F[o2 + M3.ROW_BZ]!;
      ax += fw * F[w + M3.ROW_AX]!;
      ay += fw * F[w + M3.ROW_AY]!;
      az += fw * F[w + M3.ROW_AZ]!;
      bx += fw * F[w + M3.ROW_BX]!;
      by += fw * F[w + M3.ROW_BY]!;
      bz += fw * F[w + M3.ROW_BZ]!;
    }
    const ka = buf.ia[i]!,
      kb = buf.ib[i]!,
      a = BS.BS3_STRIDE * ka,
      b = BS.BS3_STRIDE * kb;
    if (ka > 0) {
      const mA = sb[a + BS.BS3_INV_MASS]!,
        gA = iso ? R[h + M3.HEAD_INV_IA]! : 1;
      sb[a + BS.BS3_VX] = sb[a + BS.BS3_VX]! - mA * px;
      sb[a + BS.BS3_VY] = sb[a + BS.BS3_VY]! - mA * py;
      sb[a + BS.BS3_VZ] = sb[a + BS.BS3_VZ]! - mA * pz;
      sb[a + BS.BS3_WX] = sb[a + BS.BS3_WX]! - gA * ax;
      sb[a + BS.BS3_WY] = sb[a + BS.BS3_WY]! - gA * ay;
      sb[a + BS.BS3_WZ] = sb[a + BS.BS3_WZ]! - gA * az;
      sb[a + BS.BS3_PUSHED] = 1;
    }
    if (kb > 0) {
      const mB = sb[b + BS.BS3_INV_MASS]!,
        gB = iso ? R[h + M3.HEAD_INV_IB]! : 1;
      sb[b + BS.BS3_VX] = sb[b + BS.BS3_VX]! + mB * px;
      sb[b + BS.BS3_VY] = sb[b + BS.BS3_VY]! + mB * py;
      sb[b + BS.BS3_VZ] = sb[b + BS.BS3_VZ]! + mB * pz;
      sb[b + BS.BS3_WX] = sb[b + BS.BS3_WX]! + gB * bx;
      sb[b + BS.BS3_WY] = sb[b + BS.BS3_WY]! + gB * by;
      sb[b + BS.BS3_WZ] = sb[b + BS.BS3_WZ]! + gB * bz;
      sb[b + BS.BS3_PUSHED] = 1;
    }
  }
}

/**
 * One pass over the rows: normal (soft with `useBias`, else relaxing), then the manifold's friction (t1, t2 and twist at its anchor).
 * @category Collision
 */
export function solveManifolds3D(world: PhysicsWorld, hs: number, useBias: boolean): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const cs = world.collision,
    buf = st.current,
    sb = cs.bodyState,
    ex = cs.bodyExtra,
    base = st.rotationBase,
    JI = st.jacobiansInv;
  const push = cs.settings.contactPushSpeed;
  // Points in alternating order from substep to substep (symmetric Gauss-Seidel; the relax pass keeps
  // its substep's order), so the order a manifold's points are solved in leaves no systematic torque.
  st.solveParity ^= useBias ? 1 : 0;
  const backward = st.solveParity === 1;
  // The softness table (solver/contact-point-layout.ts): a row's scales at scaleBase + SN_SOFT_ROW softRow.
  const T = st.softness,
    sBias = T[CP.SN_BIAS]!,
    rBias = T[CP.SN_RIGID_BIAS]!;
  const LN = buf.ln,
    CARRIED = buf.carried,
    FV = st.frictionInv;
  const FT = buf.ft;
  // The manifold's own numbers from its record (HEAD_*, REC_*, POINT_*), one run of memory a manifold.
  const H = st.solveRecord;
  const IA = buf.ia,
    IB = buf.ib,
    PTS = buf.points,
    ISO = buf.iso;
  const invHs = 1 / hs,
    negPush = -push;
  for (let i = 0, count = buf.count; i < count; i++) {
    const ka = IA[i]!,
      kb = IB[i]!,
      a = BS.BS3_STRIDE * ka,
      b = BS.BS3_STRIDE * kb,
      h = M3.REC_STRIDE * i;
    const nx = H[h + M3.HEAD_NX]!,
      ny = H[h + M3.HEAD_NY]!,
      nz = H[h + M3.HEAD_NZ]!;
    // Velocities of both bodies in locals for the manifold's rows (written back once at the end).
    let vax = sb[a + BS.BS3_VX]!,
      vay = sb[a + BS.BS3_VY]!,
      vaz = sb[a + BS.BS3_VZ]!,
      wax = sb[a + BS.BS3_WX]!,
      way = sb[a + BS.BS3_WY]!,
      waz = sb[a + BS.BS3_WZ]!;
    let vbx = sb[b + BS.BS3_VX]!,
      vby = sb[b + BS.BS3_VY]!,
      vbz = sb[b + BS.BS3_VZ]!,
      wbx = sb[b + BS.BS3_WX]!,
      wby = sb[b + BS.BS3_WY]!,
      wbz = sb[b + BS.BS3_WZ]!;
    const mA = sb[a + BS.BS3_INV_MASS]!,
      mB = sb[b + BS.BS3_INV_MASS]!;
    // A static, sleeping or kinematic partner (inverse mass 0): the stiffer softness (solver/rigid-partner.ts).
    const isRigid = rigidPartner(mA, mB) === 1;
    const biasRate = isRigid ? rBias : sBias,
      scaleBase = isRigid ? CP.SN_SCALES + CP.SN_RIGID : CP.SN_SCALES;
    // Displacement along n and rotation of each body so far this step.
    const dn =
      (sb[b + BS.BS3_DX]! - sb[a + BS.BS3_DX]!) * nx +
      (sb[b + BS.BS3_DY]! - sb[a + BS.BS3_DY]!) * ny +
      (sb[b + BS.BS3_DZ]! - sb[a + BS.BS3_DZ]!) * nz;
    let hax = 0,
      hay = 0,
      haz = 0,
      hbx = 0,
      hby = 0,
      hbz = 0;
    if (ka > 0) {
      const e = BS.BX_STRIDE * ka,
        r = 3 * ka;
      hax = ex[e + BS.BX_ROT_X]! - base[r]!;
      hay = ex[e + BS.BX_ROT_Y]! - base[r + 1]!;
      haz = ex[e + BS.BX_ROT_Z]! - base[r + 2]!;
    }
    if (kb > 0) {
      const e = BS.BX_STRIDE * kb,
        r = 3 * kb;
      hbx = ex[e + BS.BX_ROT_X]! - base[r]!;
      hby = ex[e + BS.BX_ROT_Y]! - base[r + 1]!;
      hbz = ex[e + BS.BX_ROT_Z]! - base[r + 2]!;
    }
    const m = PTS[i]!;
    // A speculative manifold that cannot close this substep is skipped, exactly: no impulse yet, and every
    // point's s >= minSep + dn - |theta_A| reach_A - |theta_B| reach_B > 0 with
    // v_n + s / h_s >= (v_B - v_A) . n - |w_A| reach_A - |w_B| reach_B + s_low / h_s >= 0, so each row would
    // compute lambda = max(0 - m (v_n + s / h_s), 0) = 0 and change nothing (friction has no limit then).
    const minSep = H[h + M3.HEAD_MIN_SEP]!;
    if (minSep > 0 && FT[3 * i] === 0 && FT[3 * i + 1] === 0 && FT[3 * i + 2] === 0) {
      let idle = true;
      for (let k = 0; k < m; k++) {
        if (LN[4 * i + k] !== 0) {
          idle = false;
          break;
        }
      }
      if (idle) {
        const rA = H[h + M3.HEAD_REACH_A]!,
          rB = H[h + M3.HEAD_REACH_B]!;
        const sLow = minSep + dn - Math.sqrt(hax * hax + hay * hay + haz * haz) * rA - Math.sqrt(hbx * hbx + hby * hby + hbz * hbz) * rB;
        if (sLow > 0) {
          const vLow =
            (vbx - vax) * nx +
            (vby - vay) * ny +
            (vbz - vaz) * nz -
            Math.sqrt(wax * wax + way * way + waz * waz) * rA -
            Math.sqrt(wbx * wbx + wby * wby + wbz * wbz) * rB;
          if (vLow + sLow * invHs >= 0) continue;
        }
      }
    }
    // Isotropic bodies: I^-1 (r x u) = i (r x u), from the crosses (the stored products are not read).
    const iso = ISO[i] === 1,
      iA = H[h + M3.HEAD_INV_IA]!,
      iB = H[h + M3.HEAD_INV_IB]!;
    let pushed = false;
    // The normal rows change the bodies' linear velocities only along n, by m_A dl and m_B dl: the
    // linear part of v_n, (v_B - v_A) . n, is carried from row to row (it grows by (m_A + m_B) |n|^2 dl),
    // and the velocities themselves take the rows' sum of impulses once the sweeps end.
    let vnLinear = (vbx - vax) * nx + (vby - vay) * ny + (vbz - vaz) * nz,
      sumDl = -0;
    const linearGain = (mA + mB) * (nx * nx + ny * ny + nz * nz);
    // Normal rows swept until a flat hit is shared by the points as the exact solve shares it, not by the
    // order they are visited in (NORMAL_SWEEPS); a soft row ends the sweeps after the first.
    const sweeps = m === 1 ? 1 : NORMAL_SWEEPS;
    let softMet = 0;
    // The sweep count goes up at the top of a sweep, not in a loop update the first sweep never reaches
    // (optimised code compiled before any second sweep was thrown away at the first hit).
    for (let sw = 0; ; ) {
      const odd = (sw & 1) === 1,
        first = sw === 0;
      sw++;
      // -0, a heap number: V8 types both sums as doubles from their first use (from a small-integer 0 it
      // typed them as integers while the first rows added zeros, and deoptimised at the first fraction).
      let change = -0,
        total = -0;
      for (let kk = 0; kk < m; kk++) {
        const k = backward !== odd ? m - 1 - kk : kk;
        const q = 4 * i + k,
          p = h + M3.REC_POINTS + M3.POINT_STRIDE * k;
        const ra0 = H[p + CP.CP_NORMAL_ROW + M3.ROW_AX]!,
          ra1 = H[p + CP.CP_NORMAL_ROW + M3.ROW_AY]!,
          ra2 = H[p + CP.CP_NORMAL_ROW + M3.ROW_AZ]!,
          rb0 = H[p + CP.CP_NORMAL_ROW + M3.ROW_BX]!,
          rb1 = H[p + CP.CP_NORMAL_ROW + M3.ROW_BY]!,
          rb2 = H[p + CP.CP_NORMAL_ROW + M3.ROW_BZ]!;
        // s = s0 + (d_B - d_A) . n + theta_B . (r_B x n) - theta_A . (r_A x n)
        const s = H[p + CP.CP_SEPARATION]! + dn + (hbx * rb0 + hby * rb1 + hbz * rb2 - (hax * ra0 + hay * ra1 + haz * ra2));
        const vn = vnLinear + (wbx * rb0 + wby * rb1 + wbz * rb2 - (wax * ra0 + way * ra1 + waz * ra2));
        const old = LN[q]!;
        let lam: number;
        if (useBias) {
          // The row's regime, bias and scales (solver/contact-point.ts), selected without a branch.
          const soft = softRow(s, 1),
            sel = scaleBase + CP.SN_SOFT_ROW * soft;
          softMet |= soft;
          lam = normalImpulse(old, H[p + CP.CP_NORMAL_MASS]!, T[sel]!, T[sel + 1]!, vn, normalBias(s, invHs, biasRate, negPush, soft));
        } else {
          // A relax pass: no row is soft (its scales are 1 and 0, solver/contact-point-layout.ts), and its
          // bias is s / h_s while speculative, else 0: normalImpulse with those, its zero terms left out.
          lam = Math.max(old - H[p + CP.CP_NORMAL_MASS]! * (vn + +(s > 0) * (s * invHs)), 0);
        }
        const dl = lam - old;
        LN[q] = lam;
        CARRIED[q] = CARRIED[q]! | +(lam > 0);
        // Applied also when dl = 0 (it then adds zeros): a branch on dl !== 0 that the first rows V8 saw
        // never entered was compiled without type feedback, and its first push threw the code away.
        // Body row 0 (the static world) has zero inverse mass and inertia, and is never written back.
        vnLinear += linearGain * dl;
        sumDl += dl;
        if (iso) {
          const ga = iA * dl,
            gb = iB * dl;
          wax -= ga * ra0;
          way -= ga * ra1;
          waz -= ga * ra2;
          wbx += gb * rb0;
          wby += gb * rb1;
          wbz += gb * rb2;
        } else {
          const o = M3.JAC_STRIDE * q;
          wax -= dl * JI[o + M3.ROW_AX]!;
          way -= dl * JI[o + M3.ROW_AY]!;
          waz -= dl * JI[o + M3.ROW_AZ]!;
          wbx += dl * JI[o + M3.ROW_BX]!;
          wby += dl * JI[o + M3.ROW_BY]!;
          wbz += dl * JI[o + M3.ROW_BZ]!;
        }
        pushed = pushed || dl !== 0;
        change += Math.abs(dl);
        total += lam;
      }
      const settled = change <= (first ? HIT_FRACTION : SWEEP_TOLERANCE) * total,
        slow = change * (mA + mB) <= SWEEP_SPEED,
        last = sw >= sweeps;
      if (softMet === 1 || settled || slow || last) break;
    }
    vax -= mA * sumDl * nx;
    vay -= mA * sumDl * ny;
    vaz -= mA * sumDl * nz;
    vbx += mB * sumDl * nx;
    vby += mB * sumDl * ny;
    vbz += mB * sumDl * nz;
    // Friction of the manifold at its anchor (t1, t2, then the twist about n), limited by mu sum(lambda_n).
    let sumLn = 0;
    for (let k = 0; k < m; k++) sumLn += LN[4 * i + k]!;
    const limit = H[h + M3.HEAD_MU]! * sumLn;
    const o1 = FT[3 * i]!,
      o2 = FT[3 * i + 1]!,
      ow = FT[3 * i + 2]!;
    // A manifold that pushes nothing (a speculative one) has no friction to solve.
    if (limit !== 0 || o1 !== 0 || o2 !== 0 || ow !== 0) {
      const t1x = H[h + M3.HEAD_T1X]!,
        t1y = H[h + M3.HEAD_T1Y]!,
        t1z = H[h + M3.HEAD_T1Z]!;
      const t2x = ny * t1z - nz * t1y,
        t2y = nz * t1x - nx * t1z,
        t2z = nx * t1y - ny * t1x;
      // t1 and t2 (the manifold's rows of crosses and of inverse products), both from the same
      // velocities, the impulse (l1, l2) then held within the circle of radius mu sum(lambda_n): the same
      // limit in every direction of sliding (clamping each separately let a diagonal slide take sqrt 2 of it).
      const a10 = H[h + M3.REC_T1 + M3.ROW_AX]!,
        a11 = H[h + M3.REC_T1 + M3.ROW_AY]!,
        a12 = H[h + M3.REC_T1 + M3.ROW_AZ]!,
        b10 = H[h + M3.REC_T1 + M3.ROW_BX]!,
        b11 = H[h + M3.REC_T1 + M3.ROW_BY]!,
        b12 = H[h + M3.REC_T1 + M3.ROW_BZ]!;
      const a20 = H[h + M3.REC_T2 + M3.ROW_AX]!,
        a21 = H[h + M3.REC_T2 + M3.ROW_AY]!,
        a22 = H[h + M3.REC_T2 + M3.ROW_AZ]!,
        b20 = H[h + M3.REC_T2 + M3.ROW_BX]!,
        b21 = H[h + M3.REC_T2 + M3.ROW_BY]!,
        b22 = H[h + M3.REC_T2 + M3.ROW_BZ]!;
      const dvx = vbx - vax,
        dvy = vby - vay,
        dvz = vbz - vaz;
      const vt1 = dvx * t1x + dvy * t1y + dvz * t1z + (wbx * b10 + wby * b11 + wbz * b12 - (wax * a10 + way * a11 + waz * a12));
      const vt2 = dvx * t2x + dvy * t2y + dvz * t2z + (wbx * b20 + wby * b21 + wbz * b22 - (wax * a20 + way * a21 + waz * a22));
      let l1 = o1 - H[h + M3.HEAD_MT1]! * vt1,
        l2 = o2 - H[h + M3.HEAD_MT2]! * vt2;
      const l2sum = l1 * l1 + l2 * l2;
      if (l2sum > limit * limit) {
        const k = limit / Math.sqrt(l2sum);
        l1 *= k;
        l2 *= k;
      }
      FT[3 * i] = l1;
      FT[3 * i + 1] = l2;
      const d1 = l1 - o1,
        d2 = l2 - o2;
      if (d1 !== 0 || d2 !== 0) {
        const px = d1 * t1x + d2 * t2x,
          py = d1 * t1y + d2 * t2y,
          pz = d1 * t1z + d2 * t2z;
        vax -= mA * px;
        vay -= mA * py;
        vaz -= mA * pz;
        vbx += mB * px;
        vby += mB * py;
        vbz += mB * pz;
        if (iso) {
          wax -= iA * (d1 * a10 + d2 * a20);
          way -= iA * (d1 * a11 + d2 * a21);
          waz -= iA * (d1 * a12 + d2 * a22);
          wbx += iB * (d1 * b10 + d2 * b20);
          wby += iB * (d1 * b11 + d2 * b21);
          wbz += iB * (d1 * b12 + d2 * b22);
        } else {
          const p = M3.FRICTION_INV_STRIDE * i;
          wax -= d1 * FV[p + M3.FRICTION_T1 + M3.ROW_AX]! + d2 * FV[p + M3.FRICTION_T2 + M3.ROW_AX]!;
          way -= d1 * FV[p + M3.FRICTION_T1 + M3.ROW_AY]! + d2 * FV[p + M3.FRICTION_T2 + M3.ROW_AY]!;
          waz -= d1 * FV[p + M3.FRICTION_T1 + M3.ROW_AZ]! + d2 * FV[p + M3.FRICTION_T2 + M3.ROW_AZ]!;
          wbx += d1 * FV[p + M3.FRICTION_T1 + M3.ROW_BX]! + d2 * FV[p + M3.FRICTION_T2 + M3.ROW_BX]!;
          wby += d1 * FV[p + M3.FRICTION_T1 + M3.ROW_BY]! + d2 * FV[p + M3.FRICTION_T2 + M3.ROW_BY]!;
          wbz += d1 * FV[p + M3.FRICTION_T1 + M3.ROW_BZ]! + d2 * FV[p + M3.FRICTION_T2 + M3.ROW_BZ]!;
        }
        pushed = true;
      }
      // Twist: relative spin about n, limited by mu arm sum(lambda_n).
      const lw = boundedImpulse(
        ow,
        H[h + M3.HEAD_MTW]!,
        (wbx - wax) * nx + (wby - way) * ny + (wbz - waz) * nz,
        limit * H[h + M3.HEAD_ARM]!,
      );
      FT[3 * i + 2] = lw;
      const dw = lw - ow;
      if (dw !== 0) {
        if (iso) {
          const ga = iA * dw,
            gb = iB * dw;
          wax -= ga * nx;
          way -= ga * ny;
          waz -= ga * nz;
          wbx += gb * nx;
          wby += gb * ny;
          wbz += gb * nz;
        } else {
          const p = M3.FRICTION_INV_STRIDE * i + M3.FRICTION_TWIST;
          wax -= dw * FV[p + M3.ROW_AX]!;
          way -= dw * FV[p + M3.ROW_AY]!;
          waz -= dw * FV[p + M3.ROW_AZ]!;
          wbx += dw * FV[p + M3.ROW_BX]!;
          wby += dw * FV[p + M3.ROW_BY]!;
          wbz += dw * FV[p + M3.ROW_BZ]!;
        }
        pushed = true;
      }
    }
    if (pushed) {
      if (ka > 0) {
        sb[a + BS.BS3_VX] = vax;
        sb[a + BS.BS3_VY] = vay;
        sb[a + BS.BS3_VZ] = vaz;
        sb[a + BS.BS3_WX] = wax;
        sb[a + BS.BS3_WY] = way;
        sb[a + BS.BS3_WZ] = waz;
        sb[a + BS.BS3_PUSHED] = 1;
      }
      if (kb > 0) {
        sb[b + BS.BS3_VX] = vbx;
        sb[b + BS.BS3_VY] = vby;
        sb[b + BS.BS3_VZ] = vbz;
        sb[b + BS.BS3_WX] = wbx;
        sb[b + BS.BS3_WY] = wby;
        sb[b + BS.BS3_WZ] = wbz;
        sb[b + BS.BS3_PUSHED] = 1;
      }
    }
  }
}

/**
 * Adds the impulse `dl` (N s) along the normal n to the body at packed state offset `s` and marks it pushed; its spin
 * change is dl `invI` L[at..at + 2] (isotropic inverse inertia times r x n) if `iso`, else dl L[at..at + 2] (I^-1 (r x n)).
 */
function pushAlongNormal(
  sb: Float64Array,
  s: number,
  dl: number,
  nx: number,
  ny: number,
  nz: number,
  iso: boolean,
  invI: number,
  L: Float32Array | Float64Array,
  at: number,
): void {
  const f = sb[s + BS.BS3_INV_MASS]! * dl,
    g = iso ? invI * dl : dl;
  sb[s + BS.BS3_VX] = sb[s + BS.BS3_VX]! + f * nx;
  sb[s + BS.BS3_VY] = sb[s + BS.BS3_VY]! + f * ny;
  sb[s + BS.BS3_VZ] = sb[s + BS.BS3_VZ]! + f * nz;
  sb[s + BS.BS3_WX] = sb[s + BS.BS3_WX]! + g * L[at]!;
  sb[s + BS.BS3_WY] = sb[s + BS.BS3_WY]! + g * L[at + 1]!;
  sb[s + BS.BS3_WZ] = sb[s + BS.BS3_WZ]! + g * L[at + 2]!;
  sb[s + BS.BS3_PUSHED] = 1;
}

/**
 * The 3D manifolds' restitution stage, by the one definition of solver/restitution.ts: a point that
 * carried an impulse and approached faster than its threshold at the start of the step bounces; its
 * accumulated normal impulse is moved toward the target v_n = -e v_n0 by `restitutionIterations`
 * sequential-impulse passes, kept >= 0. (Velocities written out in place.)
 *
 * Without Poisson's cap (solver/restitution.ts restitutionCap: a point's rebound at most e times that
 * point's compression), which the ball rows (one point a row) and the 2D manifolds apply. Up to four
 * points here share a face's load in whatever split the sequential passes reach: the support is
 * statically indeterminate (every split with the same total and moment holds the body), so a cap per
 * point would clip the rebound by an arbitrary split. Tried: a cube landing flat at 4.25 m/s with e = 0.5
 * then rebounded at 0.33 of its impact speed and spun at 1.4 rad/s; uncapped it rebounds at 0.5 within
 * 1e-5 without spin (test/physics/flat-bounce.test.ts). The 2D pair is solved as one 2 x 2 problem
 * (the block), which fixes its split, so there the cap per point is sound. The same law for a 3D
 * manifold is a cap on its whole rebound, e times its whole compression; tried as a budget the points
 * share within these sequential passes, it clipped the same drop too (0.37, 0.95 rad/s): the first
 * point spends the budget on a rebound the later points' turns would have taken back. It needs the
 * points solved together, as the 2D block.
 * @category Collision
 */
export function applyManifold3DRestitution(world: PhysicsWorld): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const cs = world.collision,
    buf = st.current,
    sb = cs.bodyState,
    R = st.solveRecord,
    JI = st.jacobiansInv,
    T = st.invInertia;
  const threshold = cs.settings.restitutionThreshold,
    elasticThreshold = cs.settings.elasticRestitutionThreshold;
  const VN0 = buf.vn0,
    CARRIED = buf.carried,
    LN = buf.ln;
  // Which points bounce (approach past the threshold, impulse carried) does not change from pass to
  // pass: the first pass visits every manifold and lists those with such a point, the others only those
  // (in the same order, so the same impulses; a settled pile's thousands of manifolds are read once).
  const list = bouncingList(buf.count);
  let listed = 0;
  for (let pass = 0, passes = cs.settings.restitutionIterations; pass < passes; pass++) {
    const all = pass === 0;
    for (let r = 0, count = all ? buf.count : listed; r < count; r++) {
      const i = all ? r : list[r]!;
      const e = buf.restitution[i]!;
      if (e === 0) continue;
      const ka = buf.ia[i]!,
        kb = buf.ib[i]!,
        a = BS.BS3_STRIDE * ka,
        b = BS.BS3_STRIDE * kb;
      // Isotropic: I^-1 (r x n) = i (r x n), from the crosses; else the stored products.
      const iso = buf.iso[i] === 1,
        iA = iso ? T[BS.II3_STRIDE * ka + BS.II3_XX]! : 0,
        iB = iso ? T[BS.II3_STRIDE * kb + BS.II3_XX]! : 0;
      const nx = buf.nx[i]!,
        ny = buf.ny[i]!,
        nz = buf.nz[i]!;
      let bounces = false;
      for (let k = 0, m = buf.points[i]!; k < m; k++) {
        const q = 4 * i + k;
        if (CARRIED[q] === 0) continue;
        const target = restitutionTarget(e, VN0[q]!, VN0[q]!, threshold, elasticThreshold);
        if (target < 0) continue;
        bounces = true;
        const p = M3.REC_STRIDE * i + M3.REC_POINTS + M3.POINT_STRIDE * k;
        const vn =
          (sb[b + BS.BS3_VX]! - sb[a + BS.BS3_VX]!) * nx +
          (sb[b + BS.BS3_VY]! - sb[a + BS.BS3_VY]!) * ny +
          (sb[b + BS.BS3_VZ]! - sb[a + BS.BS3_VZ]!) * nz +
          sb[b + BS.BS3_WX]! * R[p + CP.CP_NORMAL_ROW + M3.ROW_BX]! +
          sb[b + BS.BS3_WY]! * R[p + CP.CP_NORMAL_ROW + M3.ROW_BY]! +
          sb[b + BS.BS3_WZ]! * R[p + CP.CP_NORMAL_ROW + M3.ROW_BZ]! -
          sb[a + BS.BS3_WX]! * R[p + CP.CP_NORMAL_ROW + M3.ROW_AX]! -
          sb[a + BS.BS3_WY]! * R[p + CP.CP_NORMAL_ROW + M3.ROW_AY]! -
          sb[a + BS.BS3_WZ]! * R[p + CP.CP_NORMAL_ROW + M3.ROW_AZ]!;
        const old = LN[q]!;
        const lam = restitutionImpulse(old, R[p + CP.CP_NORMAL_MASS]!, vn, target, Number.POSITIVE_INFINITY);
        const dl = lam - old;
        LN[q] = lam;
        if (dl === 0) continue;
        // Body row 0 (the static world) is never written.
        const o = M3.JAC_STRIDE * q;
        if (ka > 0) pushAlongNormal(sb, a, -dl, nx, ny, nz, iso, iA, iso ? R : JI, iso ? p + CP.CP_NORMAL_ROW + M3.ROW_AX : o + M3.ROW_AX);
        if (kb > 0) pushAlongNormal(sb, b, dl, nx, ny, nz, iso, iB, iso ? R : JI, iso ? p + CP.CP_NORMAL_ROW + M3.ROW_BX : o + M3.ROW_BX);
      }
      if (all && bounces) list[listed++] = i;
    }
    if (listed === 0) break;
  }
}
