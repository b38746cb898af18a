/**
 * The 2D contact solver's per-body and per-row stages (solver/contact-solver.ts gatherBodies' fill, measureApproach,
 * finishBodies) and its restitution stage by colours, as thread kernels (step/kernel-table.ts rules:
 * self-contained functions the worker threads also run as source text). solver/stages-threads.ts
 * runs them, on the threads or inline on one thread, and says when.
 *
 * The per-body and per-row kernels do each body's or row's arithmetic on its own (these are the 2D
 * stages' only code: solver/contact-solver.ts keeps the 3D loops), so their results are the same to the
 * bit whichever thread runs a body or row. The restitution kernel visits the rows colour by colour (the
 * coloured solve's colours, solver/coloring.ts), not in buffer order: deterministic, and the same on
 * any number of threads (see solver/stages-threads.ts).
 */

import type { claimBlock } from '../threads/block-claim.js';
import type { KernelArray, KernelHelper } from '../threads/kernel-types.js';
import {
  BS2_DX,
  BS2_DY,
  BS2_INV_INERTIA,
  BS2_INV_MASS,
  BS2_PUSHED,
  BS2_STRIDE,
  BS2_VX,
  BS2_VY,
  BS2_W,
  BX_BASE_X,
  BX_BASE_Y,
  BX_BASE_Z,
  BX_ROT_X,
  BX_ROT_Y,
  BX_ROT_Z,
  BX_STRIDE,
} from './body-state-layout.js';
import { PL_COLOR_BLOCKS, PL_COLORS, PL_THREADS } from './colored-slots-2d.js';
import { PACK_STRIDE, PK_NORMAL_MASS, PK_NX, PK_NY } from './contact-pack-2d.js';
import {
  AP_A,
  AP_B,
  AP_BASE,
  AP_BODY_STATE,
  AP_BODY_TYPE,
  AP_DYNAMIC,
  AP_GX,
  AP_GY,
  AP_GZ,
  AP_IA,
  AP_IB,
  AP_IMPACT_VELOCITY,
  AP_IMPULSE,
  AP_NX,
  AP_NY,
  AP_NZ,
  AP_RELATIVE_VELOCITY,
  AP_SEPARATION,
  FB_ANGLE,
  FB_BODIES,
  FB_BODY_EXTRA,
  FB_BODY_IMPACT,
  FB_BODY_STATE,
  FB_BODY_TYPE,
  FB_BOX_RESTITUTION,
  FB_CONTAIN,
  FB_DEEPEST,
  FB_DYNAMIC,
  FB_FREE_X,
  FB_FREE_Y,
  FB_GX,
  FB_GY,
  FB_IA,
  FB_IB,
  FB_IMPACT_STRIDE,
  FB_MAX_X,
  FB_MIN_X,
  FB_NX,
  FB_NY,
  FB_PX,
  FB_PY,
  FB_RADIUS,
  FB_RESTITUTION,
  FB_ROWS,
  FB_SEPARATION,
  FB_VX,
  FB_VY,
  FB_WZ,
  GF_BODY_EXTRA,
  GF_BODY_STATE,
  GF_BODY_TYPE,
  GF_DYNAMIC,
  GF_FX,
  GF_FY,
  GF_FZ,
  GF_GX_H,
  GF_GY_H,
  GF_H,
  GF_INV_INERTIA,
  GF_INV_MASS,
  GF_KINEMATIC,
  GF_PUSHED,
  GF_PX,
  GF_PY,
  GF_VX,
  GF_VY,
  GF_WZ,
  RC_BODY_STATE,
  RC_BOUNDS,
  RC_CLAIM,
  RC_COUNTERS,
  RC_ELASTIC_THRESHOLD,
  RC_IA,
  RC_IB,
  RC_IMPACT_VELOCITY,
  RC_IMPULSE,
  RC_ITERATIONS,
  RC_MAX_NORMAL_IMPULSE,
  RC_MAY_WAIT,
  RC_NORMAL_MASS,
  RC_NX,
  RC_NY,
  RC_PACK,
  RC_PAIR,
  RC_PLAN,
  RC_RELATIVE_VELOCITY,
  RC_RESTITUTION,
  RC_ROW,
  RC_ROWS,
  RC_SPIN_US,
  RC_THRESHOLD,
  RC_TOTAL_NORMAL_IMPULSE,
} from './stage-slots-2d.js';

/**
 * Fills the 2D solver rows of solver bodies lo + 1 .. hi (gatherBodies' second loop, solver/contact-solver.ts), one
 * body at a time. `ids`: the solver bodies' entity ids from solver index 1 (ids[i] is solver body
 * i + 1). A and P: the GF_ slots of solver/stage-slots-2d.ts (slots z, and the turns about x and y,
 * of the extra rows are 0 in 2D). Returns 0.
 * @category Collision
 */
export function gatherFill2D(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[GF_PX] as Float64Array,
    py = A[GF_PY] as Float64Array;
  const vx = A[GF_VX] as Float64Array,
    vy = A[GF_VY] as Float64Array,
    wz = A[GF_WZ] as Float64Array;
  const fx = A[GF_FX] as Float64Array,
    fy = A[GF_FY] as Float64Array,
    fz = A[GF_FZ] as Float64Array;
  const type = A[GF_BODY_TYPE] as Uint8Array,
    invMass = A[GF_INV_MASS] as Float64Array,
    invInertia = A[GF_INV_INERTIA] as Float64Array;
  const sb = A[GF_BODY_STATE] as Float64Array,
    ex = A[GF_BODY_EXTRA] as Float64Array;
  const h = P[GF_H]!,
    gx = P[GF_GX_H]!,
    gy = P[GF_GY_H]!,
    pushed = P[GF_PUSHED]!,
    DYNAMIC = P[GF_DYNAMIC]!,
    KINEMATIC = P[GF_KINEMATIC]!;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const k = i + 1,
      e = list[i]!;
    const o = k * BS2_STRIDE,
      q = k * BX_STRIDE;
    const ii = invInertia[e]!;
    const dynamic = type[e] === DYNAMIC;
    const spins = type[e] === KINEMATIC;
    const forced = fx[e] !== 0 || fy[e] !== 0 || fz[e] !== 0;
    const gb = dynamic && !forced ? 0.5 * h : 0;
    const held = forced ? 1 : pushed;
    // Slots 2 to 4 (z, and the turn about x and y) are not read in 2D, nor their stores here.
    ex[q + BX_BASE_X] = px[e]! - vx[e]! * h + gx * gb;
    ex[q + BX_BASE_Y] = py[e]! - vy[e]! * h + gy * gb;
    ex[q + BX_BASE_Z] = 0;
    ex[q + BX_ROT_X] = 0;
    ex[q + BX_ROT_Y] = 0;
    ex[q + BX_ROT_Z] = ii > 0 ? -wz[e]! * h : 0;
    sb[o + BS2_VX] = dynamic ? vx[e]! - gx : vx[e]!;
    sb[o + BS2_VY] = dynamic ? vy[e]! - gy : vy[e]!;
    sb[o + BS2_W] = ii > 0 || spins ? wz[e]! : 0;
    sb[o + BS2_DX] = 0;
    sb[o + BS2_DY] = 0;
    sb[o + BS2_INV_MASS] = invMass[e]!;
    sb[o + BS2_INV_INERTIA] = ii;
    sb[o + BS2_PUSHED] = held;
  }
  return 0;
}

/**
 * measureApproach (solver/contact-solver.ts) of 2D contact rows lo .. hi - 1: the normal relative velocity after the
 * impact stage and the speed at impact across a closing gap. A and P: the AP_ slots of
 * solver/stage-slots-2d.ts, the arrays from A[P[AP_BASE]] on (0 when they are A's only arrays; the
 * coloured solve, solver/coloring-kernel.ts, passes them after its own). Returns 0.
 * @category Collision
 */
export function approach2D(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, lo: number, hi: number): number {
  const b0 = P[AP_BASE]!;
  const IA = A[b0 + AP_IA] as Int32Array,
    IB = A[b0 + AP_IB] as Int32Array,
    CA = A[b0 + AP_A] as Int32Array,
    CB = A[b0 + AP_B] as Int32Array;
  const NX = A[b0 + AP_NX] as Float64Array,
    NY = A[b0 + AP_NY] as Float64Array,
    NZ = A[b0 + AP_NZ] as Float64Array;
  const RV = A[b0 + AP_RELATIVE_VELOCITY] as Float64Array,
    IV = A[b0 + AP_IMPACT_VELOCITY] as Float64Array,
    S0 = A[b0 + AP_SEPARATION] as Float64Array,
    IMP = A[b0 + AP_IMPULSE] as Float64Array;
  const type = A[b0 + AP_BODY_TYPE] as Uint8Array,
    sb = A[b0 + AP_BODY_STATE] as Float64Array;
  const gx = P[AP_GX]!,
    gy = P[AP_GY]!,
    gz = P[AP_GZ]!,
    DYNAMIC = P[AP_DYNAMIC]!;
  for (let i = lo; i < hi; i++) {
    const oa = IA[i]! * BS2_STRIDE,
      ob = IB[i]! * BS2_STRIDE;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const rv = (sb[ob + BS2_VX]! - sb[oa + BS2_VX]!) * nx + (sb[ob + BS2_VY]! - sb[oa + BS2_VY]!) * ny;
    RV[i] = rv;
    if (IMP[i]! > 0 && rv >= 0) continue;
    const gap = S0[i]!;
    if (!(rv < 0 && gap > 0)) {
      IV[i] = rv;
      continue;
    }
    const a = CA[i]!,
      b = CB[i]!;
    const an = ((type[b] === DYNAMIC ? 1 : 0) - (a !== 0 && type[a] === DYNAMIC ? 1 : 0)) * (gx * nx + gy * ny + gz * nz);
    const v2 = rv * rv - 2 * an * gap;
    IV[i] = v2 > 0 ? -Math.sqrt(v2) : rv;
  }
  return 0;
}

/**
 * finishBodies (solver/contact-solver.ts) of 2D solver bodies lo + 1 .. hi: velocities, positions (base +
 * displacement + impact correction, free flight's -g h h_s / 2) and angles back to the components;
 * then, if P[4] = 1, containInBoundary (solver/contact-solver.ts) of the same bodies (put back on a wall of the box
 * they went through, the outward normal velocity reflected and scaled by the restitution, the potential
 * energy gained taken from the kinetic); and the deepest overlap left over this thread's share of the
 * contact rows (rows floor(m lo / nb) .. floor(m hi / nb) - 1, m rows, nb bodies), as min(0, min s)
 * into A[FB_DEEPEST][part] (m). `ids`: the solver bodies' entity ids from solver index 1. A and P: the
 * FB_ slots of solver/stage-slots-2d.ts. Returns the sum of the positions and
 * velocities finishBodies wrote (finite exactly when they all are: the caller's check).
 * @category Collision
 */
export function finishBodies2D(
  A: KernelArray[],
  P: Float64Array,
  ids: Int32Array | null,
  lo: number,
  hi: number,
  part: number,
  H: readonly KernelHelper[],
): number {
  // The three loops are functions of their own (KERNEL_HELPERS 4 to 6, solver/kernel-helpers.ts): this
  // kernel runs once a step, and inline, its later loops and the code between them first ran after V8
  // had compiled the first loop on the stack (OSR), throwing that code away at every step.
  const check = (H[4] as typeof finishBodyRows2D)(A, P, ids as Int32Array, lo, hi);
  if (P[FB_CONTAIN] === 1) (H[5] as typeof containBodies2D)(A, P, ids as Int32Array, lo, hi);
  (A[FB_DEEPEST] as Float64Array)[part] = (H[6] as typeof deepestRow2D)(A, P, lo, hi);
  return check;
}

/**
 * finishBodies2D's first loop (velocities, positions and angles back to the components, bodies lo + 1 .. hi); returns the finiteness sum. A and P as finishBodies2D's.
 * @category Collision
 */
export function finishBodyRows2D(A: KernelArray[], P: Float64Array, list: Int32Array, lo: number, hi: number): number {
  const px = A[FB_PX] as Float64Array,
    py = A[FB_PY] as Float64Array,
    vx = A[FB_VX] as Float64Array,
    vy = A[FB_VY] as Float64Array;
  const wz = A[FB_WZ] as Float64Array,
    angle = A[FB_ANGLE] as Float64Array,
    type = A[FB_BODY_TYPE] as Uint8Array;
  const sb = A[FB_BODY_STATE] as Float64Array,
    ex = A[FB_BODY_EXTRA] as Float64Array,
    imp = A[FB_BODY_IMPACT] as Float64Array;
  const fx = P[FB_FREE_X]!,
    fy = P[FB_FREE_Y]!,
    DYNAMIC = P[FB_DYNAMIC]!,
    Q = P[FB_IMPACT_STRIDE]!;
  let check = 0;
  for (let i = lo; i < hi; i++) {
    const k = i + 1,
      e = list[i]!;
    if (type[e] !== DYNAMIC) continue;
    const o = k * BS2_STRIDE,
      r = k * BX_STRIDE;
    const free = sb[o + BS2_PUSHED] === 0 ? 1 : 0;
    vx[e] = sb[o + BS2_VX]!;
    vy[e] = sb[o + BS2_VY]!;
    const x = ex[r + BX_BASE_X]! + sb[o + BS2_DX]! + imp[k * Q]! + free * fx,
      y = ex[r + BX_BASE_Y]! + sb[o + BS2_DY]! + imp[k * Q + 1]! + free * fy;
    px[e] = x;
    py[e] = y;
    check += x + y + sb[o + BS2_VX]! + sb[o + BS2_VY]!;
    if (sb[o + BS2_INV_INERTIA]! > 0) {
      wz[e] = sb[o + BS2_W]!;
      angle[e] = angle[e]! + ex[r + BX_ROT_Z]!;
    }
  }
  return check;
}

/**
 * finishBodies2D's containInBoundary over bodies lo + 1 .. hi (A and P as finishBodies2D's).
 * @category Collision
 */
export function containBodies2D(A: KernelArray[], P: Float64Array, list: Int32Array, lo: number, hi: number): void {
  const px = A[FB_PX] as Float64Array,
    py = A[FB_PY] as Float64Array,
    vx = A[FB_VX] as Float64Array,
    vy = A[FB_VY] as Float64Array;
  const type = A[FB_BODY_TYPE] as Uint8Array,
    radius = A[FB_RADIUS] as Float64Array,
    eM = A[FB_RESTITUTION] as Float64Array;
  const DYNAMIC = P[FB_DYNAMIC]!,
    boxE = P[FB_BOX_RESTITUTION]!,
    g0 = P[FB_GX]!,
    g1 = P[FB_GY]!;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    if (type[e] !== DYNAMIC) continue;
    const rad = radius[e]!;
    let gain = 0;
    for (let d = 0; d < 2; d++) {
      const p = d === 0 ? px : py,
        v = d === 0 ? vx : vy,
        g = d === 0 ? g0 : g1;
      const wlo = P[FB_MIN_X + d]! + rad,
        whi = P[FB_MAX_X + d]! - rad;
      const x = p[e]!;
      if (x < wlo && wlo <= whi) {
        p[e] = wlo;
        gain -= g * (wlo - x);
        if (v[e]! < 0) v[e] = -Math.max(boxE, eM[e]!) * v[e]!;
      } else if (x > whi && wlo <= whi) {
        p[e] = whi;
        gain -= g * (whi - x);
        if (v[e]! > 0) v[e] = -Math.max(boxE, eM[e]!) * v[e]!;
      }
    }
    if (gain > 0) {
      let v2 = 0;
      v2 += vx[e]! * vx[e]!;
      v2 += vy[e]! * vy[e]!;
      const f = v2 > 2 * gain ? Math.sqrt(1 - (2 * gain) / v2) : 0;
      vx[e] = vx[e]! * f;
      vy[e] = vy[e]! * f;
    }
  }
}

/**
 * finishBodies2D's deepest overlap over its share of the contact rows (floor(m lo / nb) .. floor(m hi / nb) - 1): min(0, min s), m.
 * @category Collision
 */
export function deepestRow2D(A: KernelArray[], P: Float64Array, lo: number, hi: number): number {
  const sb = A[FB_BODY_STATE] as Float64Array;
  const IA = A[FB_IA] as Int32Array,
    IB = A[FB_IB] as Int32Array,
    S0 = A[FB_SEPARATION] as Float64Array,
    NX = A[FB_NX] as Float64Array,
    NY = A[FB_NY] as Float64Array;
  const m = P[FB_ROWS]!,
    nb = P[FB_BODIES]!;
  const r0 = Math.floor((m * lo) / nb),
    r1 = Math.floor((m * hi) / nb);
  let deepest = 0;
  for (let i = r0; i < r1; i++) {
    const a = IA[i]! * BS2_STRIDE,
      b = IB[i]! * BS2_STRIDE;
    const s = S0[i]! + (sb[b + BS2_DX]! - sb[a + BS2_DX]!) * NX[i]! + (sb[b + BS2_DY]! - sb[a + BS2_DY]!) * NY[i]!;
    if (s < deepest) deepest = s;
  }
  return deepest;
}

/**
 * The restitution stage of a 2D world whose substeps ran by colours (applyRestitution in solver/contact-solver.ts, with
 * its sequential passes visiting the rows colour by colour), run by every thread of the pool at once
 * (or by one thread alone). First, per row (blocks of 1,024 rows, each row on its own as in solver/contact-solver.ts):
 * a row that carried no impulse takes no part (target -1); one that approached faster than its
 * threshold gets the target -e v_impact and the cap of Poisson's hypothesis; the rest the target 0.
 * Then, if any row bounces, `restitutionIterations` sequential-impulse passes, colour by colour: the
 * blocks of a colour share no movable body (solver/coloring.ts: strips or graph colours; the overflow
 * colour one block), so they may go to any thread. Threads claim blocks by flags, each from its own
 * share of a unit first, and start a unit (the first stage, or a colour of a pass) once every block of
 * the earlier units is done, as solveColored2D (spinning up to P[5] microseconds, then blocking).
 * A and P: the RC_ slots of solver/stage-slots-2d.ts. Returns 0 (-1 if another thread failed and
 * this one stopped).
 * @category Collision
 */
export function restitutionColored2D(
  A: KernelArray[],
  P: Float64Array,
  _ids: Int32Array | null,
  _lo: number,
  _hi: number,
  part: number,
  H: readonly KernelHelper[],
): number {
  const plan = A[RC_PLAN] as Int32Array,
    bar = A[RC_COUNTERS] as Int32Array,
    bounds = A[RC_BOUNDS] as Int32Array;
  const n = P[RC_ROWS]!,
    iterations = P[RC_ITERATIONS]!,
    spinMs = P[RC_SPIN_US]! / 1000;
  const C = plan[PL_COLORS]!;
  const wait = part !== 0 || P[RC_MAY_WAIT] === 1;
  const clock = (globalThis as { performance?: { now(): number } }).performance;
  const FIRST = 1024;
  // Unit 0: the rows' targets and caps; then `iterations` passes of C + 1 colours each.
  const units = 1 + iterations * (C + 1);
  let base = 0,
    failed = false;
  // Waits until every block of the units before the current one (`base` blocks) is done; false if
  // another thread failed.
  const earlierDone = (): boolean => {
    let spins = 0,
      t0 = -1;
    for (;;) {
      const done = Atomics.load(bar, 1);
      if (done >= base) return true;
      if (Atomics.load(bar, 2) !== 0) return false;
      if (!wait || (++spins & 255) !== 0) continue;
      const t = clock !== undefined ? clock.now() : 0;
      if (t0 < 0) t0 = t;
      if (clock === undefined || t - t0 >= spinMs) Atomics.wait(bar, 1, done, 50);
    }
  };
  // Blocks are claimed by flags, each thread from its own share of a unit first (claimBlock,
  // threads/block-claim.ts), as solveColored2D: with strips a thread keeps the strips, and their
  // bodies, it solved in the substeps.
  const claim = A[RC_CLAIM] as Int32Array,
    threads = plan[PL_THREADS]! > 0 ? plan[PL_THREADS]! : 1;
  const claimNext = H[9] as typeof claimBlock,
    cursor = new Int32Array(2);
  for (let u = 0; u < units; u++) {
    const c = u === 0 ? -1 : (u - 1) % (C + 1);
    const first = c < 0 ? 0 : plan[PL_COLOR_BLOCKS + c]!;
    const count = c < 0 ? Math.ceil(n / FIRST) : plan[PL_COLOR_BLOCKS + c + 1]! - first;
    const end = base + count;
    // From unit 1 on: nothing to do unless some row bounces (known once unit 0 is done).
    if (u === 1) {
      if (!earlierDone()) {
        failed = true;
        break;
      }
      if (Atomics.load(bar, 3) === 0) break;
    }
    if (count > 0) {
      if (!earlierDone()) {
        failed = true;
        break;
      }
      cursor[0] = 0;
      cursor[1] = 0;
      for (
        let blk = claimNext(claim, base, count, part, threads, cursor);
        blk >= 0;
        blk = claimNext(claim, base, count, part, threads, cursor)
      ) {
        try {
          // The block loops are kernel helpers (KERNEL_HELPERS 7 and 8, solver/kernel-helpers.ts): this kernel
          // runs once a step, and inline they were compiled on the stack partway through a call.
          if (c < 0) {
            const lo = blk * FIRST,
              hi = Math.min(n, lo + FIRST);
            const bouncing = (H[7] as typeof restitutionTargets2D)(A, P, lo, hi);
            if (bouncing > 0) Atomics.add(bar, 3, bouncing);
          } else (H[8] as typeof restitutionRows2D)(A, bounds[first + blk]!, bounds[first + blk + 1]!);
        } catch (e) {
          Atomics.store(bar, 2, 1);
          Atomics.notify(bar, 1);
          throw e;
        }
        if (Atomics.add(bar, 1, 1) + 1 === end) Atomics.notify(bar, 1);
      }
    }
    base = end;
  }
  return failed ? -1 : 0;
}

/**
 * The blocks of every unit of restitutionColored2D over `n` rows with `plan` (the colours' layout) and `iterations` passes: the size its claim array needs.
 * @category Collision
 */
export function restitutionBlocks2D(plan: Int32Array, n: number, iterations: number): number {
  const C = plan[PL_COLORS]!;
  return Math.ceil(n / 1024) + iterations * (plan[PL_COLOR_BLOCKS + C + 1]! - plan[PL_COLOR_BLOCKS]!);
}

/**
 * restitutionColored2D's first unit over rows [lo, hi): each row's target and cap (A and P as the kernel's); returns how many rows bounce.
 * @category Collision
 */
export function restitutionTargets2D(A: KernelArray[], P: Float64Array, lo: number, hi: number): number {
  const sb = A[RC_BODY_STATE] as Float64Array,
    IA = A[RC_IA] as Int32Array,
    IB = A[RC_IB] as Int32Array,
    NX = A[RC_NX] as Float64Array,
    NY = A[RC_NY] as Float64Array;
  const NM = A[RC_NORMAL_MASS] as Float64Array,
    E = A[RC_RESTITUTION] as Float64Array,
    RV = A[RC_RELATIVE_VELOCITY] as Float64Array,
    IV = A[RC_IMPACT_VELOCITY] as Float64Array;
  const MAXN = A[RC_MAX_NORMAL_IMPULSE] as Float64Array,
    TOT = A[RC_TOTAL_NORMAL_IMPULSE] as Float64Array;
  const threshold = P[RC_THRESHOLD]!,
    elasticThreshold = P[RC_ELASTIC_THRESHOLD]!;
  let bouncing = 0;
  for (let i = lo; i < hi; i++) {
    const e = E[i]!;
    if (MAXN[i] === 0) {
      RV[i] = -1;
      continue;
    }
    MAXN[i] = 0;
    if (e > 0 && RV[i]! < -(e >= 1 ? elasticThreshold : threshold)) {
      RV[i] = -e * IV[i]!;
      const a = IA[i]! * BS2_STRIDE,
        bb = IB[i]! * BS2_STRIDE;
      const vn = (sb[bb + BS2_VX]! - sb[a + BS2_VX]!) * NX[i]! + (sb[bb + BS2_VY]! - sb[a + BS2_VY]!) * NY[i]!;
      const stop = vn < 0 ? -NM[i]! * vn : 0;
      TOT[i] = stop + e * (TOT[i]! + stop);
      bouncing++;
    } else RV[i] = 0;
  }
  return bouncing;
}

/**
 * One block of a restitution pass: pack rows [r0, r1) (A as restitutionColored2D's).
 * @category Collision
 */
export function restitutionRows2D(A: KernelArray[], r0: number, r1: number): void {
  const pk = A[RC_PACK] as Float64Array,
    sb = A[RC_BODY_STATE] as Float64Array,
    RV = A[RC_RELATIVE_VELOCITY] as Float64Array;
  const MAXN = A[RC_MAX_NORMAL_IMPULSE] as Float64Array,
    TOT = A[RC_TOTAL_NORMAL_IMPULSE] as Float64Array,
    IMP = A[RC_IMPULSE] as Float64Array;
  const pair = A[RC_PAIR] as Int32Array,
    row = A[RC_ROW] as Int32Array;
  for (let k = r0; k < r1; k++) {
    const o = k * PACK_STRIDE;
    const i = row[k]!;
    const target = RV[i]!;
    if (target < 0) continue;
    const a = pair[2 * k]!,
      bb = pair[2 * k + 1]!;
    const nx = pk[o + PK_NX]!,
      ny = pk[o + PK_NY]!;
    const vn = (sb[bb + BS2_VX]! - sb[a + BS2_VX]!) * nx + (sb[bb + BS2_VY]! - sb[a + BS2_VY]!) * ny;
    const old = MAXN[i]!;
    let acc = old - pk[o + PK_NORMAL_MASS]! * (vn - target);
    if (acc < 0) acc = 0;
    if (target > 0 && acc > TOT[i]!) acc = TOT[i]!;
    const dl = acc - old;
    if (dl === 0) continue;
    MAXN[i] = acc;
    IMP[i] = IMP[i]! + dl;
    const ka = sb[a + BS2_INV_MASS]! * dl,
      kb = sb[bb + BS2_INV_MASS]! * dl;
    sb[a + BS2_VX] = sb[a + BS2_VX]! - ka * nx;
    sb[a + BS2_VY] = sb[a + BS2_VY]! - ka * ny;
    sb[bb + BS2_VX] = sb[bb + BS2_VX]! + kb * nx;
    sb[bb + BS2_VY] = sb[bb + BS2_VY]! + kb * ny;
  }
}
