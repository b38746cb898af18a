/**
 * The kernel table (its index is threads/kernels.ts KERNEL). Loop kernels that worker threads run over a range of a system's loop. Each kernel is the body of a
 * system's hot loop, cut at [lo, hi): the main thread and every worker run the same function (the
 * workers get its source text, see worker-source.ts), on views of the same shared memory, so each
 * entity's arithmetic is exactly the single-threaded one and the results are identical to the bit.
 *
 * Rules for a kernel (its source is sent to the workers as text):
 * - it refers to nothing outside itself but its arguments and JavaScript's globals (Math);
 * - no inner functions (bundlers may wrap them in helpers the worker does not have);
 * - `A` holds the typed arrays in the order its caller documents, `P` the scalar parameters,
 *   `ids` the entity ids of the loop (null: the loop is over the dense ids lo + 1 .. hi);
 * - it returns a number the caller sums over the ranges (a finiteness check or a count);
 * - functions it calls come as its last argument, `helpers` (KERNEL_HELPERS, by index), and follow
 *   these same rules.
 */

import { ballPairs } from '../collision/broadphase/grid-pairs-kernel.js';
import { ballContacts } from '../collision/narrowphase/balls-kernel.js';
import { mortonBucketSort, mortonKeysHist, mortonScatter, treeForces, treeGather, treeMoments } from '../forces/barnes-hut/gather.js';
import { barnesHutWalk2 } from '../forces/barnes-hut/walk-2d.js';
import { barnesHutWalk3 } from '../forces/barnes-hut/walk-3d.js';
import { solveColored2D } from '../solver/coloring-kernel.js';
import { prepareContacts2D } from '../solver/prepare-contacts-kernel.js';
import { approach2D, finishBodies2D, gatherFill2D, restitutionColored2D } from '../solver/stages-kernel.js';
import { stripPlan2D } from '../solver/strip-plan-kernel.js';
import { stripCut2D } from '../solver/strips-kernel.js';
import { warmStartTable } from '../solver/warm-start-kernel.js';
import type { Kernel, KernelArray } from '../threads/kernel-types.js';

/**
 * Semi-implicit Euler for bodies with a force accumulator, 2D (see integrators/semi-implicit-euler.ts).
 * A: px, py, vx, vy, ox, oy, fx, fy, im. P: h, gxh, gyh, hx, hy. Returns the finiteness check sum.
 */
function sieForced2(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array,
    vx = A[2] as Float64Array,
    vy = A[3] as Float64Array;
  const ox = A[4] as Float64Array,
    oy = A[5] as Float64Array,
    fx = A[6] as Float64Array,
    fy = A[7] as Float64Array;
  const im = A[8] as Float64Array;
  const h = P[0]!,
    gxh = P[1]!,
    gyh = P[2]!,
    hx = P[3]!,
    hy = P[4]!;
  const list = ids as Int32Array;
  let check = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const w = im[e]! * h;
    const nvx = vx[e]! + fx[e]! * w + gxh;
    const nvy = vy[e]! + fy[e]! * w + gyh;
    const x = px[e]!,
      y = py[e]!;
    ox[e] = x;
    oy[e] = y;
    vx[e] = nvx;
    vy[e] = nvy;
    const k = fx[e] === 0 && fy[e] === 0 ? 1 : 0;
    px[e] = x + (nvx - k * hx) * h;
    py[e] = y + (nvy - k * hy) * h;
    check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
  }
  return check;
}

/**
 * Semi-implicit Euler for bodies with a force accumulator, 3D.
 * A: px, py, pz, vx, vy, vz, ox, oy, oz, fx, fy, fz, im. P: h, gxh, gyh, gzh, hx, hy, hz.
 */
function sieForced3(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array,
    pz = A[2] as Float64Array;
  const vx = A[3] as Float64Array,
    vy = A[4] as Float64Array,
    vz = A[5] as Float64Array;
  const ox = A[6] as Float64Array,
    oy = A[7] as Float64Array,
    oz = A[8] as Float64Array;
  const fx = A[9] as Float64Array,
    fy = A[10] as Float64Array,
    fz = A[11] as Float64Array;
  const im = A[12] as Float64Array;
  const h = P[0]!,
    gxh = P[1]!,
    gyh = P[2]!,
    gzh = P[3]!,
    hx = P[4]!,
    hy = P[5]!,
    hz = P[6]!;
  const list = ids as Int32Array;
  let check = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const w = im[e]! * h;
    const nvx = vx[e]! + fx[e]! * w + gxh;
    const nvy = vy[e]! + fy[e]! * w + gyh;
    const nvz = vz[e]! + fz[e]! * w + gzh;
    const x = px[e]!,
      y = py[e]!,
      z = pz[e]!;
    ox[e] = x;
    oy[e] = y;
    oz[e] = z;
    vx[e] = nvx;
    vy[e] = nvy;
    vz[e] = nvz;
    const k = fx[e] === 0 && fy[e] === 0 && fz[e] === 0 ? 1 : 0;
    px[e] = x + (nvx - k * hx) * h;
    py[e] = y + (nvy - k * hy) * h;
    pz[e] = z + (nvz - k * hz) * h;
    check += nvx + nvy + nvz + px[e]! * 0 + py[e]! * 0 + pz[e]! * 0;
  }
  return check;
}

/**
 * Semi-implicit Euler for bare particles (a = g), 2D. A: px, py, vx, vy, ox, oy.
 * P: h, gxh, gyh, hx, hy, save (1: keep PreviousPosition). ids null: entities lo + 1 .. hi.
 */
function sieFree2(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array,
    vx = A[2] as Float64Array,
    vy = A[3] as Float64Array;
  const ox = A[4] as Float64Array,
    oy = A[5] as Float64Array;
  const h = P[0]!,
    gxh = P[1]!,
    gyh = P[2]!,
    hx = P[3]!,
    hy = P[4]!,
    save = P[5] === 1;
  let check = 0;
  if (ids === null && save) {
    for (let e = lo + 1; e <= hi; e++) {
      const nvx = vx[e]! + gxh,
        nvy = vy[e]! + gyh;
      const x = px[e]!,
        y = py[e]!;
      ox[e] = x;
      oy[e] = y;
      vx[e] = nvx;
      vy[e] = nvy;
      px[e] = x + (nvx - hx) * h;
      py[e] = y + (nvy - hy) * h;
      check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
    }
  } else if (ids === null) {
    for (let e = lo + 1; e <= hi; e++) {
      const nvx = vx[e]! + gxh,
        nvy = vy[e]! + gyh;
      vx[e] = nvx;
      vy[e] = nvy;
      px[e] = px[e]! + (nvx - hx) * h;
      py[e] = py[e]! + (nvy - hy) * h;
      check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
    }
  } else {
    for (let i = lo; i < hi; i++) {
      const e = ids[i]!;
      const nvx = vx[e]! + gxh,
        nvy = vy[e]! + gyh;
      const x = px[e]!,
        y = py[e]!;
      if (save) {
        ox[e] = x;
        oy[e] = y;
      }
      vx[e] = nvx;
      vy[e] = nvy;
      px[e] = x + (nvx - hx) * h;
      py[e] = y + (nvy - hy) * h;
      check += nvx + nvy + px[e]! * 0 + py[e]! * 0;
    }
  }
  return check;
}

/**
 * Semi-implicit Euler for bare particles, 3D. A: px, py, pz, vx, vy, vz, ox, oy, oz.
 * P: h, gxh, gyh, gzh, hx, hy, hz, save. ids null: entities lo + 1 .. hi.
 */
function sieFree3(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array,
    pz = A[2] as Float64Array;
  const vx = A[3] as Float64Array,
    vy = A[4] as Float64Array,
    vz = A[5] as Float64Array;
  const ox = A[6] as Float64Array,
    oy = A[7] as Float64Array,
    oz = A[8] as Float64Array;
  const h = P[0]!,
    gxh = P[1]!,
    gyh = P[2]!,
    gzh = P[3]!,
    hx = P[4]!,
    hy = P[5]!,
    hz = P[6]!,
    save = P[7] === 1;
  let check = 0;
  for (let i = lo; i < hi; i++) {
    const e = ids === null ? i + 1 : ids[i]!;
    const nvx = vx[e]! + gxh,
      nvy = vy[e]! + gyh,
      nvz = vz[e]! + gzh;
    const x = px[e]!,
      y = py[e]!,
      z = pz[e]!;
    if (save) {
      ox[e] = x;
      oy[e] = y;
      oz[e] = z;
    }
    vx[e] = nvx;
    vy[e] = nvy;
    vz[e] = nvz;
    px[e] = x + (nvx - hx) * h;
    py[e] = y + (nvy - hy) * h;
    pz[e] = z + (nvz - hz) * h;
    check += nvx + nvy + nvz + px[e]! * 0 + py[e]! * 0 + pz[e]! * 0;
  }
  return check;
}

/**
 * Per-body gravity scale (forces/gravity.ts): F += (s - 1) m g. A: s, m, fx, fy, fz. P: gx, gy, gz. Returns 0.
 */
function gravityScale(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const s = A[0] as Float64Array,
    m = A[1] as Float64Array;
  const fx = A[2] as Float64Array,
    fy = A[3] as Float64Array,
    fz = A[4] as Float64Array;
  const gx = P[0]!,
    gy = P[1]!,
    gz = P[2]!;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const k = (s[e]! - 1) * m[e]!;
    fx[e] = fx[e]! + k * gx;
    fy[e] = fy[e]! + k * gy;
    fz[e] = fz[e]! + k * gz;
  }
  return 0;
}

/**
 * Linear drag in still air (forces/drag.ts): F -= k v unless k / m >= limit (then the body is stiff and
 * left to the exact decay). A: k, inv, vx, vy, vz, fx, fy, fz. P: limit. Returns the count of stiff bodies.
 */
function linearDragCalm(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const k = A[0] as Float64Array,
    inv = A[1] as Float64Array;
  const vx = A[2] as Float64Array,
    vy = A[3] as Float64Array,
    vz = A[4] as Float64Array;
  const fx = A[5] as Float64Array,
    fy = A[6] as Float64Array,
    fz = A[7] as Float64Array;
  const limit = P[0]!;
  const list = ids as Int32Array;
  let stiff = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const c = k[e]!;
    if (c * inv[e]! >= limit) {
      stiff++;
      continue;
    }
    fx[e] = fx[e]! - c * vx[e]!;
    fy[e] = fy[e]! - c * vy[e]!;
    fz[e] = fz[e]! - c * vz[e]!;
  }
  return stiff;
}

/**
 * Quadratic drag in still air (forces/drag.ts): F -= k |v| v unless k |v| / m >= limit (then the body
 * is stiff: no force here; the caller stamps it for the exact update). A: k, inv, vx, vy, vz, fx, fy,
 * fz. P: limit. Returns the count of stiff bodies.
 */
function quadraticDragCalm(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const k = A[0] as Float64Array,
    inv = A[1] as Float64Array;
  const vx = A[2] as Float64Array,
    vy = A[3] as Float64Array,
    vz = A[4] as Float64Array;
  const fx = A[5] as Float64Array,
    fy = A[6] as Float64Array,
    fz = A[7] as Float64Array;
  const limit = P[0]!;
  const list = ids as Int32Array;
  let stiff = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const x = vx[e]!,
      y = vy[e]!,
      z = vz[e]!;
    const c = k[e]! * Math.sqrt(x * x + y * y + z * z);
    if (c * inv[e]! >= limit) {
      stiff++;
      continue;
    }
    fx[e] = fx[e]! - c * x;
    fy[e] = fy[e]! - c * y;
    fz[e] = fz[e]! - c * z;
  }
  return stiff;
}

/**
 * Angular damping with a scalar moment of inertia (forces/angular-damping.ts, 2D): tau -= k w unless
 * k h / I >= the stiff rate. A: k, inv (Inertia.inv), wx, wy, wz, tx, ty, tz. P: h, stiff rate.
 * Returns the count of stiff bodies.
 */
function angularDampingScalar(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const k = A[0] as Float64Array,
    inv = A[1] as Float64Array;
  const wx = A[2] as Float64Array,
    wy = A[3] as Float64Array,
    wz = A[4] as Float64Array;
  const tx = A[5] as Float64Array,
    ty = A[6] as Float64Array,
    tz = A[7] as Float64Array;
  const h = P[0]!,
    rate = P[1]!;
  const list = ids as Int32Array;
  let stiff = 0;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const d = k[e]!;
    if (d * inv[e]! * h >= rate) {
      stiff++;
      continue;
    }
    tx[e] = tx[e]! - d * wx[e]!;
    ty[e] = ty[e]! - d * wy[e]!;
    tz[e] = tz[e]! - d * wz[e]!;
  }
  return stiff;
}

/**
 * Central force (forces/central.ts): F += k r^(n-2) (x - c), skipped at r = 0. A: cx, cy, cz, k, n
 * (CentralForce), px, py, pz, fx, fy, fz. P unused. Returns 0.
 */
function centralForce(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const cx = A[0] as Float64Array,
    cy = A[1] as Float64Array,
    cz = A[2] as Float64Array,
    K = A[3] as Float64Array,
    N = A[4] as Float64Array;
  const px = A[5] as Float64Array,
    py = A[6] as Float64Array,
    pz = A[7] as Float64Array;
  const fx = A[8] as Float64Array,
    fy = A[9] as Float64Array,
    fz = A[10] as Float64Array;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    const dx = px[e]! - cx[e]!,
      dy = py[e]! - cy[e]!,
      dz = pz[e]! - cz[e]!;
    const r2 = dx * dx + dy * dy + dz * dz;
    if (r2 === 0) continue;
    const n = N[e]!;
    const k = K[e]! * (n === 2 ? 1 : r2 ** (0.5 * (n - 2)));
    fx[e] = fx[e]! + k * dx;
    fy[e] = fy[e]! + k * dy;
    fz[e] = fz[e]! + k * dz;
  }
  return P.length * 0;
}

/**
 * Attractors (forces/gravity.ts): each body gets -G M m (x - x_a) / (r^2 + eps^2)^(3/2) from every
 * source a in the sources' order (itself excepted). A: sources (Float64, 6 slots a source: entity
 * id, x, y, z (m), G M (m^3 s^-2), eps^2 (m^2)), px, py, pz, m, fx, fy, fz. P: 0 source count.
 * Returns 0.
 */
function attractors(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const S = A[0] as Float64Array;
  const px = A[1] as Float64Array,
    py = A[2] as Float64Array,
    pz = A[3] as Float64Array,
    m = A[4] as Float64Array;
  const fx = A[5] as Float64Array,
    fy = A[6] as Float64Array,
    fz = A[7] as Float64Array;
  const ns = P[0]!;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const b = list[i]!;
    for (let s = 0; s < ns; s++) {
      const o = s * 6;
      if (b === S[o]) continue;
      const dx = px[b]! - S[o + 1]!,
        dy = py[b]! - S[o + 2]!,
        dz = pz[b]! - S[o + 3]!;
      const r2 = dx * dx + dy * dy + dz * dz + S[o + 5]!;
      if (r2 === 0) continue;
      const k = (-S[o + 4]! * m[b]!) / (r2 * Math.sqrt(r2));
      fx[b] = fx[b]! + k * dx;
      fy[b] = fy[b]! + k * dy;
      fz[b] = fz[b]! + k * dz;
    }
  }
  return 0;
}

/**
 * Finiteness probe of the step's stage checks (step/finite.ts): the sum of a[e] * 0 over every
 * array of A and every entity of the range; 0 when all are finite, NaN as soon as one is not (the
 * order of the sum cannot change that). P unused.
 */
function finiteProbe(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  let s = P.length * 0;
  for (let j = 0; j < A.length; j++) {
    const a = A[j] as Float64Array;
    if (ids === null) for (let e = lo + 1; e <= hi; e++) s += a[e]! * 0;
    else for (let i = lo; i < hi; i++) s += a[ids[i]!]! * 0;
  }
  return s;
}

/**
 * A kernel for tests of the pool itself: A: out (Float64Array). Writes out[i] = i * P[0] over the
 * range and throws an Error when the range holds the index P[1] (P[1] < 0: never), so a test can
 * see a worker's error reach the main thread.
 */
function testKernel(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const out = A[0] as Float64Array;
  const bad = P[1]!;
  let sum = 0;
  for (let i = lo; i < hi; i++) {
    if (i === bad) throw new Error(`test kernel: index ${i} is the bad index`);
    out[i] = i * P[0]!;
    sum += i;
  }
  return ids === null ? sum : sum;
}

/**
 * Every kernel, indexed by `KERNEL`.
 * @category Threads
 */
export const KERNELS: readonly Kernel[] = /* @__PURE__ */ Object.freeze([
  sieForced2,
  sieForced3,
  sieFree2,
  sieFree3,
  gravityScale,
  linearDragCalm,
  testKernel,
  finiteProbe,
  barnesHutWalk2,
  barnesHutWalk3,
  treeGather,
  mortonKeysHist,
  treeForces,
  quadraticDragCalm,
  angularDampingScalar,
  ballPairs,
  ballContacts,
  mortonBucketSort,
  treeMoments,
  mortonScatter,
  centralForce,
  attractors,
  solveColored2D,
  prepareContacts2D,
  gatherFill2D,
  approach2D,
  finishBodies2D,
  restitutionColored2D,
  stripCut2D,
  warmStartTable,
  stripPlan2D,
]);
