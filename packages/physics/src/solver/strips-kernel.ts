/**
 * The strip cut of the coloured solve's plan (solver/coloring.ts) as a thread kernel (step/kernel-table.ts
 * rules: self-contained, the worker threads run its source text), and a helper of the strip plan
 * (solver/strip-plan-kernel.ts), which a worker makes while the calling thread runs the impact stage
 * (solver/coloring.ts startStripPlan, ThreadPool.start). The same function cuts inline on the calling
 * thread, so the cut is the same either way.
 */

import type { KernelArray } from '../threads/kernel-types.js';
import { BS2_INV_INERTIA, BS2_INV_MASS, BS2_STRIDE, BS2_VX, BS2_VY, BS2_W, BX_BASE_X, BX_BASE_Y, BX_STRIDE } from './body-state-layout.js';
import * as CUT from './slots/strip-cut.js';

/**
 * Cuts a step's movable solver bodies into `P[CUT.P_STRIPS]` strips across the longer axis of their spread, each
 * with about as many contact rows as the others: which solver bodies take gravity (dyn: dynamic
 * bodies), the movable bodies' spread (a body is movable unless nothing can change it: no inverse mass
 * or inertia, not dynamic, no velocity), each movable body's bin of `P[CUT.BINS]` along the axis, the rows a
 * bin (by the row's first movable body), each bin's strip at the rows' quantiles (the strip of the
 * bin's middle row: floor(strips * rows before its middle / rows)), and each movable body's strip.
 * The whole cut runs on the thread whose range is not empty (lo < hi); other ranges do nothing.
 * A and P: the CUT slots (solver/slots/strip-cut.ts); the arrays are A[b + slot] for b = P[CUT.BASE] (0
 * when they are A's only arrays; the strip plan, solver/strip-plan-kernel.ts, passes them after its own
 * and calls this as a helper).
 * Returns 0.
 * @category Collision
 */
export function stripCut2D(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, lo: number, hi: number): number {
  if (lo >= hi) return 0;
  const b = P[CUT.BASE]!;
  const sb = A[b + CUT.BODY_STATE] as Float64Array,
    ex = A[b + CUT.BODY_EXTRA] as Float64Array,
    type = A[b + CUT.BODY_TYPE] as Uint8Array,
    list = A[b + CUT.BODIES] as Int32Array;
  const dyn = A[b + CUT.DYN] as Uint8Array,
    strip = A[b + CUT.STRIP] as Uint8Array,
    binOf = A[b + CUT.BIN] as Uint16Array;
  const hist = A[b + CUT.BIN_ROWS] as Int32Array,
    binStrip = A[b + CUT.BIN_STRIP] as Uint8Array;
  const IA = A[b + CUT.IA] as Int32Array,
    IB = A[b + CUT.IB] as Int32Array;
  const bodies = P[CUT.P_BODIES]!,
    n = P[CUT.P_ROWS]!,
    strips = P[CUT.P_STRIPS]!,
    BINS = P[CUT.BINS]!,
    DYNAMIC = P[CUT.P_DYNAMIC]!,
    NO_BIN = P[CUT.NO_BIN]!;
  // Gravity goes to the dynamic solver bodies (as integrateVelocities in solver/contact-solver.ts).
  dyn[0] = 0;
  for (let k = 1; k < bodies; k++) dyn[k] = type[list[k]!] === DYNAMIC ? 1 : 0;
  // The longer axis of the movable bodies' spread.
  let x0 = Infinity,
    x1 = -Infinity,
    y0 = Infinity,
    y1 = -Infinity;
  strip[0] = 255;
  for (let k = 1; k < bodies; k++) {
    const o = k * BS2_STRIDE;
    if (
      !(
        sb[o + BS2_INV_MASS]! > 0 ||
        sb[o + BS2_INV_INERTIA]! > 0 ||
        dyn[k] === 1 ||
        sb[o + BS2_VX] !== 0 ||
        sb[o + BS2_VY] !== 0 ||
        sb[o + BS2_W] !== 0
      )
    ) {
      strip[k] = 255;
      continue;
    }
    strip[k] = 0;
    const x = ex[k * BX_STRIDE + BX_BASE_X]!,
      y = ex[k * BX_STRIDE + BX_BASE_Y]!;
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  const axis = x1 - x0 >= y1 - y0 ? 0 : 1;
  const low = axis === 0 ? x0 : y0,
    span = axis === 0 ? x1 - x0 : y1 - y0;
  const scale = span > 0 && Number.isFinite(span) ? (BINS - 1) / span : 0;
  // Each movable body's bin along the axis, then rows a bin (by the row's first movable body), then
  // the bins' strips at the rows' quantiles.
  binOf[0] = NO_BIN;
  for (let k = 1; k < bodies; k++) {
    if (strip[k] === 255) {
      binOf[k] = NO_BIN;
      continue;
    }
    const bin = Math.floor((ex[k * BX_STRIDE + BX_BASE_X + axis]! - low) * scale);
    binOf[k] = bin >= 0 && bin < BINS ? bin : 0;
  }
  hist.fill(0, 0, BINS);
  for (let i = 0; i < n; i++) {
    const ba = binOf[IA[i]!]!;
    const bin = ba !== NO_BIN ? ba : binOf[IB[i]!]!;
    if (bin !== NO_BIN) hist[bin]++;
  }
  let total = 0;
  for (let j = 0; j < BINS; j++) total += hist[j]!;
  let acc = 0;
  for (let j = 0; j < BINS; j++) {
    const mid = acc + hist[j]! / 2;
    binStrip[j] = total > 0 ? Math.min(strips - 1, Math.floor((strips * mid) / total)) : 0;
    acc += hist[j]!;
  }
  for (let k = 1; k < bodies; k++) if (strip[k] !== 255) strip[k] = binStrip[binOf[k]!]!;
  return 0;
}
