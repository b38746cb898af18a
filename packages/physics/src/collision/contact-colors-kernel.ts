/**
 * The coloured 2D contact substeps (contact-colors.ts) as a thread kernel (threads/kernels.ts: a
 * self-contained function the worker threads also run as source text); contact-colors.ts runs it and
 * says when.
 */

import type { KernelArray } from '../threads/kernel-types.js';

/**
 * Thread kernel (threads/kernels.ts rules: self-contained) of the coloured substeps; thread `part` of
 * plan[3]. First each thread packs its range of the contact buffer's rows (contact-pack2d.ts layout)
 * into the pack, colour by colour, from its own first slot of each colour (`offsets`), then the
 * threads meet; after the substeps each writes the impulses of its range of packed rows back to the
 * buffer (normal, tangent, largest pass impulse, delivered total), as unpackContacts2D.
 * A: 0 pack (contact-pack2d.ts rows, colour by colour), 1 solver state (rows of 8), 2 solver
 * extra (rows of 6: slot 5 the rotation owed), 3 dyn (Uint8, 1: the solver body takes gravity), 4 plan
 * (Int32: 0 substeps, 1 biased passes, 2 relax passes, 3 threads, 4 colours C, 5 solver bodies,
 * 6 the calling thread may block in Atomics.wait, 8 .. 8 + C + 1 the colours' first rows, the
 * overflow colour's rows from plan[8 + C] to plan[9 + C]), 5 barrier (Int32: arrived, generation,
 * abort), 6 each row's colour (Uint8: 0 .. P[12] - 2, P[12] - 1 the overflow colour, 255 not packed),
 * 7 offsets (Int32, P[12] a thread: the thread's next pack slot of each colour; advanced as it packs),
 * the contact buffer's 8 ia, 9 ib (Int32), 10 nx, 11 ny, 12 ra, 13 rb, 14 separation, 15 normalMass,
 * 16 tangentMass, 17 frictionBound, 18 normalImpulse, 19 tangentImpulse1, 20 rigidPartner (Uint8),
 * 21 maxNormalImpulse, 22 totalNormalImpulse. P: 0 1 / h_s, 1-3 dynamic softness, 4-6 rigid softness,
 * 7 push-out speed, 8 h_s, 9-10 gravity times h_s, 11 the buffer's rows, 12 colour slots a thread in
 * offsets. The arithmetic of each row and body is that of solver.ts's one-thread loops. Returns 0
 * (-1 if another thread failed and this one stopped).
 */
export function solveColored2D(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, _lo: number, _hi: number, part: number): number {
  const pk = A[0] as Float64Array, sb = A[1] as Float64Array, ex = A[2] as Float64Array, dyn = A[3] as Uint8Array;
  const plan = A[4] as Int32Array, bar = A[5] as Int32Array;
  const substeps = plan[0]!, iters = plan[1]!, relax = plan[2]!, T = plan[3]!, C = plan[4]!, nb = plan[5]!;
  const wait = part !== 0 || plan[6] === 1;
  const invH = P[0]!, dBias = P[1]!, dMass = P[2]!, dImp = P[3]!, rBias = P[4]!, rMass = P[5]!, rImp = P[6]!, push = P[7]!;
  const hs = P[8]!, gx = P[9]!, gy = P[10]!, rows = P[11]!, W = P[12]!;
  const color = A[6] as Uint8Array, offsets = A[7] as Int32Array;
  // Stages of a substep: 0 gravity (bodies), 1 warm start, 2 .. 1 + iters biased passes, 2 + iters
  // positions (bodies), then the relax passes.
  const stages = 3 + iters + relax;
  const b0 = 1 + Math.floor(((nb - 1) * part) / T), b1 = 1 + Math.floor(((nb - 1) * (part + 1)) / T);
  let failed = false;
  // Stage -1: pack this thread's range of the buffer's rows.
  {
    const IA = A[8] as Int32Array, IB = A[9] as Int32Array, NX = A[10] as Float64Array, NY = A[11] as Float64Array;
    const RA = A[12] as Float64Array, RB = A[13] as Float64Array, S0 = A[14] as Float64Array, NM = A[15] as Float64Array;
    const TM = A[16] as Float64Array, FB = A[17] as Float64Array, LN = A[18] as Float64Array, LT = A[19] as Float64Array;
    const RP = A[20] as Uint8Array;
    const lo = Math.floor((rows * part) / T), hi = Math.floor((rows * (part + 1)) / T), base = part * W;
    try {
      for (let i = lo; i < hi; i++) {
        const c = color[i]!;
        if (c === 255) continue;
        const k = offsets[base + c]!;
        offsets[base + c] = k + 1;
        const o = k * 16;
        pk[o] = IA[i]! * 8; pk[o + 1] = IB[i]! * 8; pk[o + 2] = NX[i]!; pk[o + 3] = NY[i]!;
        pk[o + 4] = RA[i]!; pk[o + 5] = RB[i]!; pk[o + 6] = S0[i]!; pk[o + 7] = NM[i]!; pk[o + 8] = TM[i]!;
        pk[o + 9] = FB[i]!; pk[o + 10] = LN[i]!; pk[o + 11] = LT[i]!; pk[o + 12] = RP[i]!; pk[o + 13] = 0;
        pk[o + 14] = 0; pk[o + 15] = i;
      }
    } catch (e) {
      Atomics.store(bar, 2, 1);
      Atomics.add(bar, 1, 1);
      Atomics.notify(bar, 1);
      throw e;
    }
    if (T > 1) {
      const gen = Atomics.load(bar, 1);
      if (Atomics.add(bar, 0, 1) === T - 1) {
        Atomics.store(bar, 0, 0);
        Atomics.add(bar, 1, 1);
        Atomics.notify(bar, 1);
      } else {
        let spins = 0;
        while (Atomics.load(bar, 1) === gen && Atomics.load(bar, 2) === 0) {
          if (++spins > 200 && wait) Atomics.wait(bar, 1, gen, 50);
        }
      }
      if (Atomics.load(bar, 2) !== 0) return -1;
    }
  }
  outer:
  for (let s = 0; s < substeps; s++) {
    for (let stage = 0; stage < stages; stage++) {
      const bodyStage = stage === 0 || stage === 2 + iters;
      const units = bodyStage ? 1 : C + 1;
      for (let u = 0; u < units; u++) {
        // A colour without rows (the overflow colour, usually) needs no pass and no barrier.
        if (!bodyStage && plan[9 + u] === plan[8 + u]) continue;
        try {
          if (stage === 0) {
            for (let k = b0; k < b1; k++) {
              if (dyn[k] !== 1) continue;
              const o = k * 8;
              sb[o] = sb[o]! + gx; sb[o + 1] = sb[o + 1]! + gy;
            }
          } else if (bodyStage) {
            for (let k = b0; k < b1; k++) {
              const o = k * 8;
              sb[o + 3] = sb[o + 3]! + sb[o]! * hs; sb[o + 4] = sb[o + 4]! + sb[o + 1]! * hs;
              if (sb[o + 6]! > 0) ex[k * 6 + 5] = ex[k * 6 + 5]! + sb[o + 2]! * hs;
            }
          } else {
            // Colour u's rows, this thread's share (the overflow colour, u = C, on thread 0 alone).
            const first = plan[8 + u]!, last = plan[9 + u]!, len = last - first;
            const r0 = u === C ? (part === 0 ? first : last) : first + Math.floor((len * part) / T);
            const r1 = u === C ? last : first + Math.floor((len * (part + 1)) / T);
            if (stage === 1) {
              for (let k = r0; k < r1; k++) {
                const o = k * 16;
                const ln = pk[o + 10]!, lt = pk[o + 11]!;
                if (ln === 0 && lt === 0) continue;
                const a = pk[o]!, b = pk[o + 1]!;
                sb[a + 7] = 1; sb[b + 7] = 1;
                const nx = pk[o + 2]!, ny = pk[o + 3]!;
                const Px = ln * nx - lt * ny, Py = ln * ny + lt * nx;
                const imA = sb[a + 5]!, imB = sb[b + 5]!;
                sb[a] = sb[a]! - imA * Px; sb[a + 1] = sb[a + 1]! - imA * Py;
                sb[b] = sb[b]! + imB * Px; sb[b + 1] = sb[b + 1]! + imB * Py;
                sb[a + 2] = sb[a + 2]! - sb[a + 6]! * pk[o + 4]! * lt;
                sb[b + 2] = sb[b + 2]! - sb[b + 6]! * pk[o + 5]! * lt;
              }
            } else {
              const useBias = stage < 2 + iters;
              // The substep's last pass adds each row's impulse to what the substep delivered.
              const total = relax === 0 ? stage === 1 + iters : stage === stages - 1;
              for (let k = r0; k < r1; k++) {
                const o = k * 16;
                const a = pk[o]!, b = pk[o + 1]!;
                const nx = pk[o + 2]!, ny = pk[o + 3]!;
                const imA = sb[a + 5]!, imB = sb[b + 5]!;
                let vax = sb[a]!, vay = sb[a + 1]!, vbx = sb[b]!, vby = sb[b + 1]!;
                const sep = pk[o + 6]! + (sb[b + 3]! - sb[a + 3]!) * nx + (sb[b + 4]! - sb[a + 4]!) * ny;
                let bias = 0, massScale = 1, impulseScale = 0;
                if (sep > 0) {
                  bias = sep * invH;
                } else if (useBias) {
                  if (pk[o + 12] === 1) { bias = rBias * sep; massScale = rMass; impulseScale = rImp; }
                  else { bias = dBias * sep; massScale = dMass; impulseScale = dImp; }
                  if (bias < -push) bias = -push;
                }
                const vn = (vbx - vax) * nx + (vby - vay) * ny;
                const oldN = pk[o + 10]!;
                let lambda = -pk[o + 7]! * massScale * (vn + bias) - impulseScale * oldN;
                let newN = oldN + lambda;
                if (newN < 0) newN = 0;
                lambda = newN - oldN;
                pk[o + 10] = newN;
                if (lambda > pk[o + 13]!) pk[o + 13] = lambda;
                if (total) pk[o + 14] = pk[o + 14]! + newN;
                let Px = lambda * nx, Py = lambda * ny;
                vax -= imA * Px; vay -= imA * Py; vbx += imB * Px; vby += imB * Py;
                const ra = pk[o + 4]!, rb = pk[o + 5]!;
                let wa = sb[a + 2]!, wb = sb[b + 2]!;
                const vt = (vbx - vax) * -ny + (vby - vay) * nx - wb * rb - wa * ra;
                lambda = -pk[o + 8]! * vt;
                const maxF = pk[o + 9]! * newN;
                const oldT = pk[o + 11]!;
                let newT = oldT + lambda;
                newT = newT < -maxF ? -maxF : newT > maxF ? maxF : newT;
                lambda = newT - oldT;
                pk[o + 11] = newT;
                Px = -lambda * ny; Py = lambda * nx;
                vax -= imA * Px; vay -= imA * Py; vbx += imB * Px; vby += imB * Py;
                wa -= sb[a + 6]! * ra * lambda; wb -= sb[b + 6]! * rb * lambda;
                sb[a] = vax; sb[a + 1] = vay; sb[a + 2] = wa;
                sb[b] = vbx; sb[b + 1] = vby; sb[b + 2] = wb;
                if (newN !== 0 || newT !== 0) { sb[a + 7] = 1; sb[b + 7] = 1; }
              }
            }
          }
        } catch (e) {
          // Let the other threads out of their barrier, then report this one's error.
          Atomics.store(bar, 2, 1);
          Atomics.add(bar, 1, 1);
          Atomics.notify(bar, 1);
          throw e;
        }
        // Barrier: every thread finishes this colour or stage before any starts the next.
        if (T > 1) {
          if (Atomics.load(bar, 2) !== 0) { failed = true; break outer; }
          const gen = Atomics.load(bar, 1);
          if (Atomics.add(bar, 0, 1) === T - 1) {
            Atomics.store(bar, 0, 0);
            Atomics.add(bar, 1, 1);
            Atomics.notify(bar, 1);
          } else {
            // A short spin (the other threads are usually a few rows behind), then sleep until notified.
            let spins = 0;
            while (Atomics.load(bar, 1) === gen && Atomics.load(bar, 2) === 0) {
              if (++spins > 200 && wait) Atomics.wait(bar, 1, gen, 50);
            }
          }
          if (Atomics.load(bar, 2) !== 0) { failed = true; break outer; }
        }
      }
    }
  }
  if (failed) return -1;
  // Unpack: this thread's range of the packed rows' impulses back to the buffer (rows are disjoint).
  const LN = A[18] as Float64Array, LT = A[19] as Float64Array, MAXN = A[21] as Float64Array, TOT = A[22] as Float64Array;
  const np = plan[9 + C]!;
  const k0 = Math.floor((np * part) / T), k1 = Math.floor((np * (part + 1)) / T);
  for (let k = k0; k < k1; k++) {
    const o = k * 16, i = pk[o + 15]!;
    LN[i] = pk[o + 10]!; LT[i] = pk[o + 11]!; MAXN[i] = pk[o + 13]!; TOT[i] = pk[o + 14]!;
  }
  return 0;
}
