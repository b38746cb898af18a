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
import { PACK_STRIDE, PK_NORMAL_MASS, PK_NX, PK_NY } from './contact-pack-2d.js';

/**
 * Fills the 2D solver rows of solver bodies lo + 1 .. hi (gatherBodies' second loop, solver/contact-solver.ts), one
 * body at a time. `ids`: the solver bodies' entity ids from solver index 1 (ids[i] is solver body
 * i + 1). A: 0-2 Position x, y, z, 3-5 Velocity x, y, z, 6-8 AngularVelocity x, y, z, 9-11 Force x, y,
 * z, 12 bodyType (Uint8), 13 invMass, 14 invInertia, 15 solver state (rows of BS2_STRIDE, body-state-layout.ts), 16 solver extra (rows
 * of 6); of the components, x and y and the spin about z are read (slots 2 to 4 of the extra rows, z
 * and the turn about x and y, are 0 in 2D). P: 0 h (s), 1-3 g h (m/s), 4 pushed (1: joints in the step,
 * every body counts as pushed), 5 BodyType.Dynamic, 6 BodyType.Kinematic. Returns 0.
 * @category Collision
 */
export function gatherFill2D(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array;
  const vx = A[3] as Float64Array,
    vy = A[4] as Float64Array,
    wz = A[8] as Float64Array;
  const fx = A[9] as Float64Array,
    fy = A[10] as Float64Array,
    fz = A[11] as Float64Array;
  const type = A[12] as Uint8Array,
    invMass = A[13] as Float64Array,
    invInertia = A[14] as Float64Array;
  const sb = A[15] as Float64Array,
    ex = A[16] as Float64Array;
  const h = P[0]!,
    gx = P[1]!,
    gy = P[2]!,
    pushed = P[4]!,
    DYNAMIC = P[5]!,
    KINEMATIC = P[6]!;
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
 * impact stage and the speed at impact across a closing gap. A: 0 ia, 1 ib, 2 a, 3 b (Int32), 4 nx,
 * 5 ny, 6 nz, 7 relativeVelocity (out), 8 impactVelocity (out), 9 separation, 10 impulse, 11 bodyType
 * (Uint8), 12 solver state (rows of 8), each at A[b + j] for b = P[4] (0 when these are A's only
 * arrays; the coloured solve, solver/coloring-kernel.ts, passes them after its own). P: 0-2 gravity
 * (m/s^2), 3 BodyType.Dynamic, 4 b. Returns 0.
 * @category Collision
 */
export function approach2D(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, lo: number, hi: number): number {
  const b0 = P[4]!;
  const IA = A[b0] as Int32Array,
    IB = A[b0 + 1] as Int32Array,
    CA = A[b0 + 2] as Int32Array,
    CB = A[b0 + 3] as Int32Array;
  const NX = A[b0 + 4] as Float64Array,
    NY = A[b0 + 5] as Float64Array,
    NZ = A[b0 + 6] as Float64Array;
  const RV = A[b0 + 7] as Float64Array,
    IV = A[b0 + 8] as Float64Array,
    S0 = A[b0 + 9] as Float64Array,
    IMP = A[b0 + 10] as Float64Array;
  const type = A[b0 + 11] as Uint8Array,
    sb = A[b0 + 12] as Float64Array;
  const gx = P[0]!,
    gy = P[1]!,
    gz = P[2]!,
    DYNAMIC = P[3]!;
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
 * contact rows (rows floor(m lo / nb) .. floor(m hi / nb) - 1, m = P[12] rows, nb = P[13] bodies), as
 * min(0, min s) into out[part] (m). `ids`: the solver bodies' entity ids from solver index 1. A: 0
 * Position x, 1 y, 2 Velocity x, 3 y, 4 AngularVelocity z, 5 Angle, 6 bodyType (Uint8), 7 solver state
 * (rows of 8), 8 solver extra (rows of 6), 9 bodyImpact (rows of P[3]), 10 Ball radius, 11 Material
 * restitution, 12 out (one slot a thread), 13 ia, 14 ib (Int32), 15 separation, 16 nx, 17 ny. P: 0-1
 * the free-flight correction -g h h_s / 2 (m), 2 BodyType.Dynamic, 3 the impact row stride, 4 contain
 * (1: the boundary box is on), 5-6 the box's min x, y, 7-8 max x, y (m), 9 its restitution, 10-11
 * gravity (m/s^2), 12 contact rows, 13 solver bodies - 1. Returns the sum of the positions and
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
  if (P[4] === 1) (H[5] as typeof containBodies2D)(A, P, ids as Int32Array, lo, hi);
  (A[12] as Float64Array)[part] = (H[6] as typeof deepestRow2D)(A, P, lo, hi);
  return check;
}

/**
 * finishBodies2D's first loop (velocities, positions and angles back to the components, bodies lo + 1 .. hi); returns the finiteness sum. A and P as finishBodies2D's.
 * @category Collision
 */
export function finishBodyRows2D(A: KernelArray[], P: Float64Array, list: Int32Array, lo: number, hi: number): number {
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array,
    vx = A[2] as Float64Array,
    vy = A[3] as Float64Array;
  const wz = A[4] as Float64Array,
    angle = A[5] as Float64Array,
    type = A[6] as Uint8Array;
  const sb = A[7] as Float64Array,
    ex = A[8] as Float64Array,
    imp = A[9] as Float64Array;
  const fx = P[0]!,
    fy = P[1]!,
    DYNAMIC = P[2]!,
    Q = P[3]!;
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
  const px = A[0] as Float64Array,
    py = A[1] as Float64Array,
    vx = A[2] as Float64Array,
    vy = A[3] as Float64Array;
  const type = A[6] as Uint8Array,
    radius = A[10] as Float64Array,
    eM = A[11] as Float64Array;
  const DYNAMIC = P[2]!,
    boxE = P[9]!,
    g0 = P[10]!,
    g1 = P[11]!;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    if (type[e] !== DYNAMIC) continue;
    const rad = radius[e]!;
    let gain = 0;
    for (let d = 0; d < 2; d++) {
      const p = d === 0 ? px : py,
        v = d === 0 ? vx : vy,
        g = d === 0 ? g0 : g1;
      const wlo = P[5 + d]! + rad,
        whi = P[7 + d]! - rad;
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
  const sb = A[7] as Float64Array;
  const IA = A[13] as Int32Array,
    IB = A[14] as Int32Array,
    S0 = A[15] as Float64Array,
    NX = A[16] as Float64Array,
    NY = A[17] as Float64Array;
  const m = P[12]!,
    nb = P[13]!;
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
 * A: 0 pack (solver/contact-pack-2d.ts rows, colour by colour), 1 plan (Int32, solver/coloring-kernel.ts: 4
 * threads running the kernel (parts 0 .. plan[3] - 1), 4 colours C, 12 + c colour c's first block, c =
 * 0 .. C + 1), 2 counters (Int32, 0 on entry: 0 unused, 1 blocks done, 2 abort, 3 bouncing rows), 3 solver state (rows of 8), 4 ia, 5 ib (Int32),
 * 6 nx, 7 ny, 8 normalMass, 9 restitution, 10 relativeVelocity, 11 impactVelocity, 12
 * maxNormalImpulse, 13 totalNormalImpulse, 14 impulse, 15 bounds (Int32: block j is pack rows
 * bounds[j] .. bounds[j + 1] - 1), 16 pair (Int32, two a pack row: its bodies' solver state
 * offsets), 17 row (Int32, a pack row: its row in the contact buffer), 18 claim (Int32, 0 on entry:
 * a flag a block, numbered across the units; restitutionBlocks2D of them). P: 0 contact rows, 1 restitutionThreshold (m/s), 2
 * elasticRestitutionThreshold (m/s), 3 restitutionIterations, 4 the calling thread may block in
 * Atomics.wait (1), 5 spin before blocking (microseconds). Returns 0 (-1 if another thread failed and
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
  const plan = A[1] as Int32Array,
    bar = A[2] as Int32Array,
    bounds = A[15] as Int32Array;
  const n = P[0]!,
    iterations = P[3]!,
    spinMs = P[5]! / 1000;
  const C = plan[4]!;
  const wait = part !== 0 || P[4] === 1;
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
  const claim = A[18] as Int32Array,
    threads = plan[3]! > 0 ? plan[3]! : 1;
  const claimNext = H[9] as typeof claimBlock,
    cursor = new Int32Array(2);
  for (let u = 0; u < units; u++) {
    const c = u === 0 ? -1 : (u - 1) % (C + 1);
    const first = c < 0 ? 0 : plan[12 + c]!;
    const count = c < 0 ? Math.ceil(n / FIRST) : plan[13 + c]! - first;
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
  const C = plan[4]!;
  return Math.ceil(n / 1024) + iterations * (plan[12 + C + 1]! - plan[12]!);
}

/**
 * restitutionColored2D's first unit over rows [lo, hi): each row's target and cap (A and P as the kernel's); returns how many rows bounce.
 * @category Collision
 */
export function restitutionTargets2D(A: KernelArray[], P: Float64Array, lo: number, hi: number): number {
  const sb = A[3] as Float64Array,
    IA = A[4] as Int32Array,
    IB = A[5] as Int32Array,
    NX = A[6] as Float64Array,
    NY = A[7] as Float64Array;
  const NM = A[8] as Float64Array,
    E = A[9] as Float64Array,
    RV = A[10] as Float64Array,
    IV = A[11] as Float64Array;
  const MAXN = A[12] as Float64Array,
    TOT = A[13] as Float64Array;
  const threshold = P[1]!,
    elasticThreshold = P[2]!;
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
  const pk = A[0] as Float64Array,
    sb = A[3] as Float64Array,
    RV = A[10] as Float64Array;
  const MAXN = A[12] as Float64Array,
    TOT = A[13] as Float64Array,
    IMP = A[14] as Float64Array;
  const pair = A[16] as Int32Array,
    row = A[17] as Int32Array;
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
