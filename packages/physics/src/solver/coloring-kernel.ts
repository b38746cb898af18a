/**
 * The coloured 2D contact substeps (solver/coloring.ts) as a thread kernel (step/kernel-table.ts: a
 * self-contained function the worker threads also run as source text); solver/coloring.ts runs it and
 * says when.
 */

import type { KernelArray, KernelHelper } from '../threads/kernel-types.js';
import * as BS from './body-state-layout.js';
import * as PACK from './contact-pack-2d.js';
import * as APPROACH from './slots/approach.js';
import * as PLAN from './slots/colored-plan.js';
import * as SOLVE from './slots/colored-solve.js';
import type { approachSpeeds, runUnitBlocks, UnitBlocks } from './stages-kernel.js';

/**
 * Thread kernel (step/kernel-table.ts rules: self-contained) of the coloured substeps, run by every
 * thread of the pool at once (or by one thread alone). The work is cut into units, in order: packing
 * the contact buffer's rows (solver/contact-pack-2d.ts layout) group by group into the pack (one block a
 * range of plan[PLAN.PARTS] ranges, each from its own first slot of every group, `offsets`), the approach
 * speeds of the buffer's rows (solver/contact-solver.ts measureApproach, 2,048 rows a block, when P[SOLVE.MEASURE_APPROACH] = 1), then each
 * substep's stages (gravity and positions over the bodies, 1,024 a block; the warm start and every
 * pass colour by colour, a colour's blocks from the block table), then writing the impulses back to
 * the buffer (normal, tangent, largest pass impulse, delivered total). Threads
 * claim a unit's blocks one by one (a flag each, Atomics.compareExchange), each from its own share of
 * the unit first, and start a unit only once every block of the earlier units is done, so a thread
 * the system has not scheduled holds nothing up unless it holds a block (work sharing, as Box2D v3's
 * solver stages), a thread keeps the same strips pass after pass, and which thread runs a block
 * never changes a result: blocks of a colour touch disjoint movable bodies, a block's rows run in pack
 * order. With strips (plan[PLAN.STRIPS] = 1, solver/coloring.ts) the body stages run inside colour 0's blocks
 * instead of as units of their own: gravity before a block's warm start, positions before its first
 * relax pass (when there is one), each block for its strip pair's bodies (`bodyOrder` from
 * bodyBounds[j] to bodyBounds[j + 1] for colour 0's block j), bodies no other block of the colour
 * touches. A thread that finds the next unit not ready spins for up to P[SOLVE.SPIN_US] microseconds, then
 * blocks in Atomics.wait (a browser's main thread, which may not block, spins on).
 * A and P: the SOLVE slots (solver/slots/colored-solve.ts), the plan at A[SOLVE.PLAN] its PLAN slots
 * (solver/slots/colored-plan.ts), and
 * approachSpeeds's arrays from A[SOLVE.APPROACH] (measureApproach of the buffer's rows, run as the unit after
 * the packing when P[SOLVE.MEASURE_APPROACH] = 1); the parts running are 0 .. plan[PLAN.THREADS] - 1.
 * The arithmetic of each row and body is
 * that of solver/contact-solver.ts's buffer-order loops (solve2D, warmStart2D, the body stages), with
 * the support rows of the relax passes for frictionless rows only (solver/support.ts: a frictionless
 * row with one ball resting on another holds the lower ball when that slows the upper one less than
 * the lower); solve2D also holds rows whose upper ball is the heavier and takes some rows first.
 * Returns 0 (-1 if another thread failed and this one stopped).
 * @category Collision
 */
export function solveColored2D(
  A: KernelArray[],
  P: Float64Array,
  _ids: Int32Array | null,
  _lo: number,
  _hi: number,
  part: number,
  H: readonly KernelHelper[],
): number {
  const pk = A[SOLVE.PACK] as Float64Array,
    sb = A[SOLVE.BODY_STATE] as Float64Array,
    ex = A[SOLVE.BODY_EXTRA] as Float64Array,
    dyn = A[SOLVE.DYN] as Uint8Array;
  const plan = A[SOLVE.PLAN] as Int32Array,
    bar = A[SOLVE.COUNTERS] as Int32Array;
  const substeps = plan[PLAN.SUBSTEPS]!,
    iters = plan[PLAN.ITERATIONS]!,
    relax = plan[PLAN.RELAX]!,
    C = plan[PLAN.COLORS]!,
    nb = plan[PLAN.BODIES]!,
    parts = plan[PLAN.PARTS]!;
  const np = plan[PLAN.PACKED_ROWS]!,
    fused = plan[PLAN.STRIPS] === 1;
  const wait = part !== 0 || plan[PLAN.MAY_WAIT] === 1;
  const bounds = A[SOLVE.BOUNDS] as Int32Array,
    order = A[SOLVE.BODY_ORDER] as Int32Array,
    bodyBounds = A[SOLVE.BODY_BOUNDS] as Int32Array,
    pair = A[SOLVE.PAIR] as Int32Array;
  const tot = A[SOLVE.TOT] as Float64Array;
  const spinMs = P[SOLVE.SPIN_US]! / 1000;
  // The blocks' loops, each a function of its own (KERNEL_HELPERS, passed in as H): called thousands
  // of times a step, V8 compiles them whole, with every branch's type feedback. Inline in this
  // function, which runs once a step, they would run in code compiled on the stack (OSR) partway
  // through a call, which every branch first reached later throws away, recompiling again and again
  // on the cores the threads need.
  // (Indices of KERNEL_HELPERS, solver/kernel-helpers.ts; the kernel may name nothing outside itself.)
  const packRows = H[0] as typeof coloredPack2D,
    unpackRows = H[1] as typeof coloredUnpack2D;
  const bodyStage = H[2] as typeof coloredBodies2D,
    rowPass = H[3] as typeof coloredRows2D;
  const approachRows = H[12] as typeof approachSpeeds;
  // The approach speeds' blocks (when P[SOLVE.MEASURE_APPROACH] = 1), of APPROACH_ROWS buffer rows (as solveColoredBlocks2D),
  // with approachSpeeds's parameters: gravity, BodyType.Dynamic, where its arrays start in A (31), 2D (THREE_D 0).
  const APPROACH_ROWS = 2048,
    rows = P[SOLVE.ROWS]!,
    approachBlocks = P[SOLVE.MEASURE_APPROACH] === 1 ? Math.ceil(rows / APPROACH_ROWS) : 0;
  const approachParams = new Float64Array(APPROACH.PARAMS);
  approachParams[APPROACH.GX] = P[SOLVE.GX]!;
  approachParams[APPROACH.GY] = P[SOLVE.GY]!;
  approachParams[APPROACH.GZ] = P[SOLVE.GZ]!;
  approachParams[APPROACH.DYNAMIC] = P[SOLVE.DYNAMIC]!;
  approachParams[APPROACH.BASE] = SOLVE.APPROACH;
  // Rows a block of the unpacking, bodies a block of a body stage.
  const RB_ = 256,
    BB = 1024;
  // Stages of a substep: 0 gravity (bodies), 1 warm start, 2 .. 1 + iters biased passes, 2 + iters
  // positions (bodies), then the relax passes.
  const stages = 3 + iters + relax;
  // With strips, gravity always and positions when a relax pass follows run inside colour 0's blocks.
  const bodyUnits = Math.ceil((nb - 1) / BB);
  const gravityUnits = fused ? 0 : bodyUnits,
    positionUnits = fused && relax > 0 ? 0 : bodyUnits;
  // The units in order: the packing (one block a range of `parts`), the approach speeds, then every substep's stages (a
  // body stage one unit, a pass C + 1 units, one a colour, the overflow colour one block), then the
  // unpacking. Blocks are numbered across the units in that order (claim[b] for block b); bar[1]
  // counts finished blocks, so a unit starts once bar[1] reaches its first block.
  const units = 2 + substeps * (2 + (1 + iters + relax) * (C + 1)) + 1;
  // Blocks are claimed by flags (claimBlock, threads/block-claim.ts), each thread (`part` of plan[PLAN.THREADS])
  // from its own share of a unit first: with strips, block j of either colour is strip pair j's, so a
  // thread solves the same strips pass after pass, their bodies and rows in its core's cache.
  const claim = A[SOLVE.CLAIM] as Int32Array,
    threads = plan[PLAN.THREADS]! > 0 ? plan[PLAN.THREADS]! : 1;
  const unit: UnitBlocks = { claim, bar, part, threads, wait, spinMs, cursor: new Int32Array(2), H };
  const runUnit = H[20] as typeof runUnitBlocks;
  let base = 0,
    failed = false;
  let stage = 0,
    u = 0;
  // Which unit runs: kind 0 pack, 5 approach speeds, 1 gravity, 2 positions, 3 a colour's rows (from
  // block `first` of the block table), 4 unpack.
  let kind = 0,
    first = 0;
  const block = (blk: number): void => {
    if (kind === 0) packRows(A, P, blk, parts);
    else if (kind === 5) approachRows(A, approachParams, null, blk * APPROACH_ROWS, Math.min(rows, (blk + 1) * APPROACH_ROWS));
    else if (kind === 1 || kind === 2) {
      const k0 = 1 + blk * BB,
        k1 = Math.min(nb, k0 + BB);
      bodyStage(sb, ex, dyn, order, 0, k0, k1, kind === 1 ? 1 : 2, P);
    } else if (kind === 4) {
      const k0 = blk * RB_,
        k1 = Math.min(np, k0 + RB_);
      unpackRows(A, k0, k1);
    } else {
      // A block of colour u's rows.
      const r0 = bounds[first + blk]!,
        r1 = bounds[first + blk + 1]!;
      // Strips: colour 0's block runs its bodies' stage first (gravity before the warm start,
      // positions before the first relax pass).
      if (fused && u === 0 && (stage === 1 || (stage === 3 + iters && relax > 0))) {
        bodyStage(sb, ex, dyn, order, 1, bodyBounds[blk]!, bodyBounds[blk + 1]!, stage === 1 ? 1 : 2, P);
      }
      // Warm start (mode 0), or a pass: 1 relax, 3 biased, + 4 on the substep's last pass (it
      // adds each row's impulse to what the substep delivered).
      const last = relax === 0 ? stage === 1 + iters : stage === stages - 1;
      const mode = stage === 1 ? 0 : (stage < 2 + iters ? 3 : 1) + (last ? 4 : 0);
      rowPass(pk, sb, pair, tot, P, r0, r1, mode);
    }
  };
  for (let g = 0; g < units; g++) {
    let count: number;
    first = 0;
    if (g === 0) {
      kind = 0;
      count = parts;
    } else if (g === 1) {
      kind = 5;
      count = approachBlocks;
    } else if (g === units - 1) {
      kind = 4;
      count = Math.ceil(np / RB_);
    } else {
      if (stage === 0 || stage === 2 + iters) {
        kind = stage === 0 ? 1 : 2;
        count = stage === 0 ? gravityUnits : positionUnits;
      } else {
        kind = 3;
        first = plan[PLAN.COLOR_BLOCKS + u]!;
        count = plan[PLAN.COLOR_BLOCKS + u + 1]! - first;
      }
    }
    const end = base + count;
    if (count > 0 && !runUnit(unit, base, count, block)) {
      failed = true;
      break;
    }
    base = end;
    // Next unit: advance (stage, colour, substep) past the packing and the approach speeds.
    if (g > 1 && g < units - 1) {
      if (stage === 0 || stage === 2 + iters) {
        stage++;
        u = 0;
      } else if (++u > C) {
        u = 0;
        stage++;
      }
      if (stage === stages) stage = 0;
    }
  }
  return failed ? -1 : 0;
}

/**
 * The blocks of every unit of solveColored2D for `plan` (its layout, the colours' first blocks
 * filled), over `rows` buffer rows (its P[SOLVE.ROWS]), measuring the approach speeds if `approach` (its P[SOLVE.MEASURE_APPROACH] = 1):
 * the size its claim array needs.
 * @category Collision
 */
export function solveColoredBlocks2D(plan: Int32Array, rows: number, approach: boolean): number {
  const substeps = plan[PLAN.SUBSTEPS]!,
    iters = plan[PLAN.ITERATIONS]!,
    relax = plan[PLAN.RELAX]!,
    C = plan[PLAN.COLORS]!,
    nb = plan[PLAN.BODIES]!,
    parts = plan[PLAN.PARTS]!;
  const np = plan[PLAN.PACKED_ROWS]!,
    fused = plan[PLAN.STRIPS] === 1;
  const bodyUnits = Math.ceil((nb - 1) / 1024);
  const bodies = (fused ? 0 : bodyUnits) + (fused && relax > 0 ? 0 : bodyUnits);
  const colorBlocks = plan[PLAN.COLOR_BLOCKS + C + 1]! - plan[PLAN.COLOR_BLOCKS]!;
  const approachBlocks = approach ? Math.ceil(rows / 2048) : 0;
  return parts + approachBlocks + substeps * (bodies + (1 + iters + relax) * colorBlocks) + Math.ceil(np / 256);
}

/*
 * The coloured kernel's block loops (KERNEL_HELPERS 0 to 3, solver/kernel-helpers.ts), self-contained like a
 * kernel; the arithmetic of each row and body is the one the kernel had inline.
 */

/**
 * Packs the contact buffer's rows of packing range `blk` (of `parts`) into the pack, each at its group's
 * next slot (solveColored2D's A and P layout: A 0 pack, 6 groups, 7 offsets, 8 to 20 the buffer's
 * arrays, 26 pair; P 11 rows, 12 group slots a range). With `again` (coloredRepack2D), packs
 * again[0 .. parts - 1] instead, each into the pack row it was given before (A[SOLVE.SLOT]; `blk` and P
 * unused): one row's packing, either way.
 * @category Collision
 */
export function coloredPack2D(A: KernelArray[], P: Float64Array, blk: number, parts: number, again: Int32Array | null = null): void {
  const pk = A[SOLVE.PACK] as Float64Array,
    color = A[SOLVE.GROUP] as Uint8Array,
    offsets = A[SOLVE.OFFSETS] as Int32Array;
  const IA = A[SOLVE.IA] as Int32Array,
    IB = A[SOLVE.IB] as Int32Array,
    NX = A[SOLVE.NX] as Float64Array,
    NY = A[SOLVE.NY] as Float64Array;
  const RA = A[SOLVE.RA] as Float64Array,
    RB = A[SOLVE.RB] as Float64Array,
    S0 = A[SOLVE.SEPARATION] as Float64Array,
    NM = A[SOLVE.NORMAL_MASS] as Float64Array;
  const TM = A[SOLVE.TANGENT_MASS] as Float64Array,
    FB = A[SOLVE.FRICTION_BOUND] as Float64Array,
    LN = A[SOLVE.NORMAL_IMPULSE] as Float64Array,
    LT = A[SOLVE.TANGENT_IMPULSE] as Float64Array;
  const RP = A[SOLVE.RIGID_PARTNER] as Uint8Array,
    pair = A[SOLVE.PAIR] as Int32Array,
    tot = A[SOLVE.TOT] as Float64Array,
    row = A[SOLVE.ROW] as Int32Array;
  const slot = A[SOLVE.SLOT] as Int32Array;
  const first = again === null;
  const rows = first ? P[SOLVE.ROWS]! : parts,
    W = first ? P[SOLVE.GROUP_SLOTS]! : 0;
  const lo = first ? Math.floor((rows * blk) / parts) : 0,
    hi = first ? Math.floor((rows * (blk + 1)) / parts) : parts,
    o0 = blk * W;
  for (let j = lo; j < hi; j++) {
    const i = first ? j : again[j]!;
    const c = color[i]!;
    if (c === 255) continue;
    let k = 0;
    if (first) {
      k = offsets[o0 + c]!;
      offsets[o0 + c] = k + 1;
      pair[2 * k] = IA[i]! * BS.BS2_STRIDE;
      pair[2 * k + 1] = IB[i]! * BS.BS2_STRIDE;
      tot[k] = 0;
      row[k] = i;
      slot[i] = k;
    } else k = slot[i]!;
    const o = k * PACK.PACK_STRIDE;
    pk[o + PACK.PK_NX] = NX[i]!;
    pk[o + PACK.PK_NY] = NY[i]!;
    pk[o + PACK.PK_RA] = RA[i]!;
    pk[o + PACK.PK_RB] = RB[i]!;
    pk[o + PACK.PK_SEPARATION] = S0[i]!;
    pk[o + PACK.PK_NORMAL_MASS] = NM[i]!;
    pk[o + PACK.PK_TANGENT_MASS] = TM[i]!;
    pk[o + PACK.PK_FRICTION] = FB[i]!;
    pk[o + PACK.PK_NORMAL_IMPULSE] = LN[i]!;
    pk[o + PACK.PK_TANGENT_IMPULSE] = LT[i]!;
    pk[o + PACK.PK_A_FIXED] = RP[i]!;
    pk[o + PACK.PK_MAX_NORMAL_IMPULSE] = 0;
  }
}

/** An empty parameter list, for coloredRepack2D's call of coloredPack2D (which then reads no parameter). */
const NO_PARAMS = /* @__PURE__ */ new Float64Array(0);

/**
 * Packs rows[0 .. count - 1] of the contact buffer again, each into the pack row coloredPack2D gave it
 * (A[SOLVE.SLOT]), from the buffer's values now (A as coloredPack2D's): for rows whose values changed
 * after they were packed (solver/impacts.ts impactChangedRows). Rows left out of the pack (group 255) stay out.
 * @category Collision
 */
export function coloredRepack2D(A: KernelArray[], rows: Int32Array, count: number): void {
  coloredPack2D(A, NO_PARAMS, 0, count, rows);
}

/**
 * Writes pack rows [k0, k1)'s impulses back to the contact buffer (normal, tangent, largest pass impulse, delivered total; A as coloredPack2D, 21 and 22 the last two).
 * @category Collision
 */
export function coloredUnpack2D(A: KernelArray[], k0: number, k1: number): void {
  const pk = A[SOLVE.PACK] as Float64Array,
    LN = A[SOLVE.NORMAL_IMPULSE] as Float64Array,
    LT = A[SOLVE.TANGENT_IMPULSE] as Float64Array,
    MAXN = A[SOLVE.MAX_NORMAL_IMPULSE] as Float64Array,
    TOT = A[SOLVE.TOTAL_NORMAL_IMPULSE] as Float64Array;
  const tot = A[SOLVE.TOT] as Float64Array,
    row = A[SOLVE.ROW] as Int32Array;
  for (let k = k0; k < k1; k++) {
    const o = k * PACK.PACK_STRIDE,
      i = row[k]!;
    LN[i] = pk[o + PACK.PK_NORMAL_IMPULSE]!;
    LT[i] = pk[o + PACK.PK_TANGENT_IMPULSE]!;
    MAXN[i] = pk[o + PACK.PK_MAX_NORMAL_IMPULSE]!;
    TOT[i] = tot[k]!;
  }
}

/**
 * A body stage over solver bodies [q0, q1) (`ordered` 1: the bodies order[q0 .. q1 - 1], a strip pair's;
 * 0: the solver indices themselves): `stage` 1 gravity (dynamic bodies: v += g h_s, P 9-10), 2 positions
 * (x += v h_s, and the rotation owed, P 8).
 * @category Collision
 */
export function coloredBodies2D(
  sb: Float64Array,
  ex: Float64Array,
  dyn: Uint8Array,
  order: Int32Array,
  ordered: number,
  q0: number,
  q1: number,
  stage: number,
  P: Float64Array,
): void {
  if (stage === 1) {
    const gx = P[SOLVE.GX_HS]!,
      gy = P[SOLVE.GY_HS]!;
    for (let q = q0; q < q1; q++) {
      const k = ordered === 1 ? order[q]! : q;
      if (dyn[k] !== 1) continue;
      const o = k * BS.BS2_STRIDE;
      sb[o + BS.BS2_VX] = sb[o + BS.BS2_VX]! + gx;
      sb[o + BS.BS2_VY] = sb[o + BS.BS2_VY]! + gy;
    }
  } else {
    const hs = P[SOLVE.HS]!;
    for (let q = q0; q < q1; q++) {
      const k = ordered === 1 ? order[q]! : q,
        o = k * BS.BS2_STRIDE;
      sb[o + BS.BS2_DX] = sb[o + BS.BS2_DX]! + sb[o + BS.BS2_VX]! * hs;
      sb[o + BS.BS2_DY] = sb[o + BS.BS2_DY]! + sb[o + BS.BS2_VY]! * hs;
      if (sb[o + BS.BS2_INV_INERTIA]! > 0)
        ex[k * BS.BX_STRIDE + BS.BX_ROT_Z] = ex[k * BS.BX_STRIDE + BS.BX_ROT_Z]! + sb[o + BS.BS2_W]! * hs;
    }
  }
}

/**
 * Pack rows [r0, r1) of one block: `mode` 0 the warm start; else a pass, 1 relax or 3 biased, plus 4
 * on the substep's last pass (each row's impulse is added to what the substep delivered). P as
 * solveColored2D's.
 * @category Collision
 */
export function coloredRows2D(
  pk: Float64Array,
  sb: Float64Array,
  pair: Int32Array,
  tot: Float64Array,
  P: Float64Array,
  r0: number,
  r1: number,
  mode: number,
): void {
  if (mode === 0) {
    for (let k = r0; k < r1; k++) {
      const o = k * PACK.PACK_STRIDE;
      const ln = pk[o + PACK.PK_NORMAL_IMPULSE]!,
        lt = pk[o + PACK.PK_TANGENT_IMPULSE]!;
      if (ln === 0 && lt === 0) continue;
      const a = pair[2 * k]!,
        bb = pair[2 * k + 1]!;
      sb[a + BS.BS2_PUSHED] = 1;
      sb[bb + BS.BS2_PUSHED] = 1;
      const nx = pk[o + PACK.PK_NX]!,
        ny = pk[o + PACK.PK_NY]!;
      const Px = ln * nx - lt * ny,
        Py = ln * ny + lt * nx;
      const imA = sb[a + BS.BS2_INV_MASS]!,
        imB = sb[bb + BS.BS2_INV_MASS]!;
      sb[a + BS.BS2_VX] = sb[a + BS.BS2_VX]! - imA * Px;
      sb[a + BS.BS2_VY] = sb[a + BS.BS2_VY]! - imA * Py;
      sb[bb + BS.BS2_VX] = sb[bb + BS.BS2_VX]! + imB * Px;
      sb[bb + BS.BS2_VY] = sb[bb + BS.BS2_VY]! + imB * Py;
      sb[a + BS.BS2_W] = sb[a + BS.BS2_W]! - sb[a + BS.BS2_INV_INERTIA]! * pk[o + PACK.PK_RA]! * lt;
      sb[bb + BS.BS2_W] = sb[bb + BS.BS2_W]! - sb[bb + BS.BS2_INV_INERTIA]! * pk[o + PACK.PK_RB]! * lt;
    }
    return;
  }
  const invH = P[SOLVE.INV_HS]!,
    dBias = P[SOLVE.SOFT_BIAS]!,
    dMass = P[SOLVE.SOFT_MASS]!,
    dImp = P[SOLVE.SOFT_IMPULSE]!,
    rBias = P[SOLVE.RIGID_BIAS]!,
    rMass = P[SOLVE.RIGID_MASS]!,
    rImp = P[SOLVE.RIGID_IMPULSE]!,
    push = P[SOLVE.PUSH_SPEED]!;
  const downX = P[SOLVE.DOWN_X]!,
    downY = P[SOLVE.DOWN_Y]!,
    supportCos = P[SOLVE.SUPPORT_COS]!;
  const useBias = (mode & 2) !== 0,
    total = (mode & 4) !== 0;
  for (let k = r0; k < r1; k++) {
    const o = k * PACK.PACK_STRIDE;
    const a = pair[2 * k]!,
      bb = pair[2 * k + 1]!;
    const nx = pk[o + PACK.PK_NX]!,
      ny = pk[o + PACK.PK_NY]!;
    const imA = sb[a + BS.BS2_INV_MASS]!,
      imB = sb[bb + BS.BS2_INV_MASS]!;
    let vax = sb[a + BS.BS2_VX]!,
      vay = sb[a + BS.BS2_VY]!,
      vbx = sb[bb + BS.BS2_VX]!,
      vby = sb[bb + BS.BS2_VY]!;
    // The normal impulse's inverse masses and effective mass: a frictionless support row of
    // a relax pass may hold its lower ball (solver/support.ts's holdsLower: lower speed <= upper).
    let jmA = imA,
      jmB = imB,
      nm = pk[o + PACK.PK_NORMAL_MASS]!;
    if (!useBias && pk[o + PACK.PK_FRICTION] === 0 && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny);
      if (up > supportCos || up < -supportCos) {
        const va = Math.abs(vax * nx + vay * ny),
          vb = Math.abs(vbx * nx + vby * ny);
        if (up > 0 ? va <= vb : vb <= va) {
          if (up > 0) jmA = 0;
          else jmB = 0;
          nm = 1 / (jmA + jmB);
        }
      }
    }
    const sep =
      pk[o + PACK.PK_SEPARATION]! + (sb[bb + BS.BS2_DX]! - sb[a + BS.BS2_DX]!) * nx + (sb[bb + BS.BS2_DY]! - sb[a + BS.BS2_DY]!) * ny;
    let bias = 0,
      massScale = 1,
      impulseScale = 0;
    if (sep > 0) {
      bias = sep * invH;
    } else if (useBias) {
      if (pk[o + PACK.PK_A_FIXED] === 1) {
        bias = rBias * sep;
        massScale = rMass;
        impulseScale = rImp;
      } else {
        bias = dBias * sep;
        massScale = dMass;
        impulseScale = dImp;
      }
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny;
    const oldN = pk[o + PACK.PK_NORMAL_IMPULSE]!;
    // A speculative row with no impulse whose gap stays open this substep does nothing (every impulse
    // below is 0), as in solver/contact-solver.ts's solve2D: a fifth of the pass's time in a settled pile.
    if (sep > 0 && oldN === 0 && vn + bias >= 0 && pk[o + PACK.PK_TANGENT_IMPULSE] === 0) continue;
    let lambda = -nm * massScale * (vn + bias) - impulseScale * oldN;
    let newN = oldN + lambda;
    if (newN < 0) newN = 0;
    lambda = newN - oldN;
    pk[o + PACK.PK_NORMAL_IMPULSE] = newN;
    if (lambda > pk[o + PACK.PK_MAX_NORMAL_IMPULSE]!) pk[o + PACK.PK_MAX_NORMAL_IMPULSE] = lambda;
    if (total) tot[k] = tot[k]! + newN;
    let Px = lambda * nx,
      Py = lambda * ny;
    vax -= jmA * Px;
    vay -= jmA * Py;
    vbx += jmB * Px;
    vby += jmB * Py;
    const ra = pk[o + PACK.PK_RA]!,
      rb = pk[o + PACK.PK_RB]!;
    let wa = sb[a + BS.BS2_W]!,
      wb = sb[bb + BS.BS2_W]!;
    const vt = (vbx - vax) * -ny + (vby - vay) * nx - wb * rb - wa * ra;
    lambda = -pk[o + PACK.PK_TANGENT_MASS]! * vt;
    const maxF = pk[o + PACK.PK_FRICTION]! * newN;
    const oldT = pk[o + PACK.PK_TANGENT_IMPULSE]!;
    let newT = oldT + lambda;
    newT = newT < -maxF ? -maxF : newT > maxF ? maxF : newT;
    lambda = newT - oldT;
    pk[o + PACK.PK_TANGENT_IMPULSE] = newT;
    Px = -lambda * ny;
    Py = lambda * nx;
    vax -= imA * Px;
    vay -= imA * Py;
    vbx += imB * Px;
    vby += imB * Py;
    wa -= sb[a + BS.BS2_INV_INERTIA]! * ra * lambda;
    wb -= sb[bb + BS.BS2_INV_INERTIA]! * rb * lambda;
    sb[a + BS.BS2_VX] = vax;
    sb[a + BS.BS2_VY] = vay;
    sb[a + BS.BS2_W] = wa;
    sb[bb + BS.BS2_VX] = vbx;
    sb[bb + BS.BS2_VY] = vby;
    sb[bb + BS.BS2_W] = wb;
    if (newN !== 0 || newT !== 0) {
      sb[a + BS.BS2_PUSHED] = 1;
      sb[bb + BS.BS2_PUSHED] = 1;
    }
  }
}
