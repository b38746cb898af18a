/**
 * The contact solver's per-body and per-row stages (solver/contact-solver.ts gatherBodies' fill,
 * measureApproach, finishBodies with containInBoundary; the restitution stage's targets), 2D and 3D, and
 * its 2D restitution stage by colours, as thread kernels (step/kernel-table.ts rules: self-contained
 * functions the worker threads also run as source text). solver/stages-threads.ts runs them, on the
 * threads or inline on one thread, and says when.
 *
 * The per-body and per-row kernels do each body's or row's arithmetic on its own (they are these
 * stages' only code, in both dimensions), so their results are the same to the bit whichever thread
 * runs a body or row. The restitution kernel visits the rows colour by colour (the coloured solve's
 * colours, solver/coloring.ts), not in buffer order: deterministic, and the same on any number of
 * threads (see solver/stages-threads.ts).
 */

import type { rotateFrom } from '../math/quaternion.js';
import type { awaitBlocks, claimBlock } from '../threads/block-claim.js';
import type { KernelArray, KernelHelper } from '../threads/kernel-types.js';
import * as BS from './body-state-layout.js';
import type { restitutionCap, restitutionTarget } from './restitution.js';
import * as APPROACH from './slots/approach.js';
import * as PLAN from './slots/colored-plan.js';
import * as FINISH from './slots/finish-bodies.js';
import * as GATHER from './slots/gather-fill.js';
import * as RESTITUTION from './slots/restitution.js';

/**
 * Fills the solver rows of solver bodies lo + 1 .. hi (gatherBodies' second loop, solver/contact-solver.ts),
 * one body at a time, of a 2D or a 3D world (P[GATHER.THREE_D]: rows of BS2_STRIDE or BS3_STRIDE): the
 * velocity with this step's gravity rewound, zero displacement, inverse mass and inertia, whether it
 * counts as pushed; in the extra row, where the integrator put it beyond x0 + v h and the rotation
 * still owed. `ids`: the solver bodies' entity ids from solver index 1 (ids[i] is solver body i + 1).
 * A and P: the GATHER slots (solver/slots/gather-fill.ts; a 2D world's z, and turns about x and y, are
 * 0 in the extra rows and not read). Returns 0.
 * @category Collision
 */
export function gatherFill(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  const px = A[GATHER.PX] as Float64Array,
    py = A[GATHER.PY] as Float64Array,
    pz = A[GATHER.PZ] as Float64Array;
  const vx = A[GATHER.VX] as Float64Array,
    vy = A[GATHER.VY] as Float64Array,
    vz = A[GATHER.VZ] as Float64Array;
  const wx = A[GATHER.WX] as Float64Array,
    wy = A[GATHER.WY] as Float64Array,
    wz = A[GATHER.WZ] as Float64Array;
  const fx = A[GATHER.FX] as Float64Array,
    fy = A[GATHER.FY] as Float64Array,
    fz = A[GATHER.FZ] as Float64Array;
  const type = A[GATHER.BODY_TYPE] as Uint8Array,
    invMass = A[GATHER.INV_MASS] as Float64Array,
    invInertia = A[GATHER.INV_INERTIA] as Float64Array;
  const sb = A[GATHER.BODY_STATE] as Float64Array,
    ex = A[GATHER.BODY_EXTRA] as Float64Array;
  const h = P[GATHER.H]!,
    gx = P[GATHER.GX_H]!,
    gy = P[GATHER.GY_H]!,
    gz = P[GATHER.GZ_H]!,
    pushed = P[GATHER.PUSHED]!,
    DYNAMIC = P[GATHER.DYNAMIC]!,
    KINEMATIC = P[GATHER.KINEMATIC]!;
  const is3D = P[GATHER.THREE_D] === 1,
    S = is3D ? BS.BS3_STRIDE : BS.BS2_STRIDE;
  const list = ids as Int32Array;
  for (let i = lo; i < hi; i++) {
    const k = i + 1,
      e = list[i]!;
    const o = k * S,
      q = k * BS.BX_STRIDE;
    const ii = invInertia[e]!;
    const dynamic = type[e] === DYNAMIC;
    // A kinematic body's spin is part of its surface velocity (v + w x r) that its contacts see; it is
    // not integrated here (its rotation owed stays 0: the integrator already turned it).
    const spins = type[e] === KINEMATIC;
    // The integrator moved x by v0 h + g h^2 / 2 (plus anything of its own, e.g. forces); keep that
    // extra as the base: x - v h + g h^2 / 2 for a dynamic body, since v = v0 + g h here. A body a
    // force acted on was not given the exact free fall: no gravity base, and it counts as pushed so
    // finishBodies does not give it the free-flight correction either.
    const forced = fx[e] !== 0 || fy[e] !== 0 || fz[e] !== 0;
    const gb = dynamic && !forced ? 0.5 * h : 0;
    const held = forced ? 1 : pushed;
    ex[q + BS.BX_BASE_X] = px[e]! - vx[e]! * h + gx * gb;
    ex[q + BS.BX_BASE_Y] = py[e]! - vy[e]! * h + gy * gb;
    // The integrator turned the body by w h; the substeps will turn it by sum w_k h_s instead.
    ex[q + BS.BX_ROT_Z] = ii > 0 ? -wz[e]! * h : 0;
    // vx and vy sit at the same offsets in both layouts.
    sb[o + BS.BS2_VX] = dynamic ? vx[e]! - gx : vx[e]!;
    sb[o + BS.BS2_VY] = dynamic ? vy[e]! - gy : vy[e]!;
    if (is3D) {
      ex[q + BS.BX_BASE_Z] = pz[e]! - vz[e]! * h + gz * gb;
      ex[q + BS.BX_ROT_X] = ii > 0 ? -wx[e]! * h : 0;
      ex[q + BS.BX_ROT_Y] = ii > 0 ? -wy[e]! * h : 0;
      sb[o + BS.BS3_VZ] = dynamic ? vz[e]! - gz : vz[e]!;
      sb[o + BS.BS3_WX] = ii > 0 || spins ? wx[e]! : 0;
      sb[o + BS.BS3_WY] = ii > 0 || spins ? wy[e]! : 0;
      sb[o + BS.BS3_WZ] = ii > 0 || spins ? wz[e]! : 0;
      sb[o + BS.BS3_DX] = 0;
      sb[o + BS.BS3_DY] = 0;
      sb[o + BS.BS3_DZ] = 0;
      sb[o + BS.BS3_INV_MASS] = invMass[e]!;
      sb[o + BS.BS3_INV_INERTIA] = ii;
      sb[o + BS.BS3_PUSHED] = held;
    } else {
      ex[q + BS.BX_BASE_Z] = 0;
      ex[q + BS.BX_ROT_X] = 0;
      ex[q + BS.BX_ROT_Y] = 0;
      sb[o + BS.BS2_W] = ii > 0 || spins ? wz[e]! : 0;
      sb[o + BS.BS2_DX] = 0;
      sb[o + BS.BS2_DY] = 0;
      sb[o + BS.BS2_INV_MASS] = invMass[e]!;
      sb[o + BS.BS2_INV_INERTIA] = ii;
      sb[o + BS.BS2_PUSHED] = held;
    }
  }
  return 0;
}

/**
 * measureApproach (solver/ball-prepare.ts) of contact rows lo .. hi - 1, 2D or 3D (P[APPROACH.THREE_D]): the normal
 * relative velocity after the impact stage, and the speed at impact across a closing gap,
 * v^2 = v0^2 - 2 a_n s with the relative normal acceleration a_n of gravity (a row the impact stage
 * bounced that now separates keeps the speed that stage recorded). A and P: the APPROACH slots
 * (solver/slots/approach.ts), the arrays from A[P[APPROACH.BASE]] on (0 when they are A's only arrays; the
 * coloured solve, solver/coloring-kernel.ts, passes them after its own). Returns 0.
 * @category Collision
 */
export function approachSpeeds(A: KernelArray[], P: Float64Array, _ids: Int32Array | null, lo: number, hi: number): number {
  const b0 = P[APPROACH.BASE]!;
  const IA = A[b0 + APPROACH.IA] as Int32Array,
    IB = A[b0 + APPROACH.IB] as Int32Array,
    CA = A[b0 + APPROACH.A] as Int32Array,
    CB = A[b0 + APPROACH.B] as Int32Array;
  const NX = A[b0 + APPROACH.NX] as Float64Array,
    NY = A[b0 + APPROACH.NY] as Float64Array,
    NZ = A[b0 + APPROACH.NZ] as Float64Array;
  const RV = A[b0 + APPROACH.RELATIVE_VELOCITY] as Float64Array,
    IV = A[b0 + APPROACH.IMPACT_VELOCITY] as Float64Array,
    S0 = A[b0 + APPROACH.SEPARATION] as Float64Array,
    IMP = A[b0 + APPROACH.IMPULSE] as Float64Array;
  const type = A[b0 + APPROACH.BODY_TYPE] as Uint8Array,
    sb = A[b0 + APPROACH.BODY_STATE] as Float64Array;
  const gx = P[APPROACH.GX]!,
    gy = P[APPROACH.GY]!,
    gz = P[APPROACH.GZ]!,
    DYNAMIC = P[APPROACH.DYNAMIC]!;
  // vx and vy sit at the same offsets in both layouts.
  const is3D = P[APPROACH.THREE_D] === 1,
    S = is3D ? BS.BS3_STRIDE : BS.BS2_STRIDE;
  for (let i = lo; i < hi; i++) {
    const oa = IA[i]! * S,
      ob = IB[i]! * S;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    let rv = (sb[ob + BS.BS2_VX]! - sb[oa + BS.BS2_VX]!) * nx + (sb[ob + BS.BS2_VY]! - sb[oa + BS.BS2_VY]!) * ny;
    if (is3D) rv += (sb[ob + BS.BS3_VZ]! - sb[oa + BS.BS3_VZ]!) * nz;
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
 * finishBodies (solver/contact-solver.ts) of solver bodies lo + 1 .. hi of a 2D or a 3D world
 * (P[FINISH.THREE_D]): velocities, positions (base + displacement + impact correction, free flight's
 * -g h h_s / 2) and angles (3D: orientations, turned by the rotation owed) back to the components;
 * then, if P[FINISH.CONTAIN] = 1, containInBoundary (solver/contact-solver.ts) of the same bodies (put back on a wall of the box
 * they went through, the outward normal velocity reflected and scaled by the restitution, the potential
 * energy gained taken from the kinetic); and the deepest overlap left over this thread's share of the
 * contact rows (rows floor(m lo / nb) .. floor(m hi / nb) - 1, m rows, nb bodies), as min(0, min s)
 * into A[FINISH.DEEPEST][part] (m). `ids`: the solver bodies' entity ids from solver index 1. A and P: the
 * FINISH slots (solver/slots/finish-bodies.ts). Returns the sum of the positions and
 * velocities finishBodies wrote (finite exactly when they all are: the caller's check).
 * @category Collision
 */
export function finishBodies(
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
  const check = (H[4] as typeof finishBodyRows)(A, P, ids as Int32Array, lo, hi, H);
  if (P[FINISH.CONTAIN] === 1) (H[5] as typeof containBodies)(A, P, ids as Int32Array, lo, hi);
  (A[FINISH.DEEPEST] as Float64Array)[part] = (H[6] as typeof deepestRow)(A, P, lo, hi);
  return check;
}

/**
 * finishBodies' first loop (velocities, positions and angles or orientations back to the components,
 * bodies lo + 1 .. hi); returns the finiteness sum. A and P as finishBodies'; H the kernel helpers
 * (15: math/quaternion.ts rotateFrom, which turns a 3D body's orientation).
 * @category Collision
 */
export function finishBodyRows(
  A: KernelArray[],
  P: Float64Array,
  list: Int32Array,
  lo: number,
  hi: number,
  H: readonly KernelHelper[],
): number {
  const px = A[FINISH.PX] as Float64Array,
    py = A[FINISH.PY] as Float64Array,
    pz = A[FINISH.PZ] as Float64Array;
  const vx = A[FINISH.VX] as Float64Array,
    vy = A[FINISH.VY] as Float64Array,
    vz = A[FINISH.VZ] as Float64Array;
  const wx = A[FINISH.WX] as Float64Array,
    wy = A[FINISH.WY] as Float64Array,
    wz = A[FINISH.WZ] as Float64Array,
    angle = A[FINISH.ANGLE] as Float64Array;
  const qx = A[FINISH.QX] as Float64Array,
    qy = A[FINISH.QY] as Float64Array,
    qz = A[FINISH.QZ] as Float64Array,
    qw = A[FINISH.QW] as Float64Array;
  const type = A[FINISH.BODY_TYPE] as Uint8Array,
    sb = A[FINISH.BODY_STATE] as Float64Array,
    ex = A[FINISH.BODY_EXTRA] as Float64Array,
    imp = A[FINISH.BODY_IMPACT] as Float64Array;
  const fx = P[FINISH.FREE_X]!,
    fy = P[FINISH.FREE_Y]!,
    fz = P[FINISH.FREE_Z]!,
    DYNAMIC = P[FINISH.DYNAMIC]!,
    Q = P[FINISH.IMPACT_STRIDE]!;
  const rotate = H[15] as typeof rotateFrom;
  // The solver state's layout: vx and vy sit at the same offsets in both, dy follows dx.
  const is3D = P[FINISH.THREE_D] === 1,
    S = is3D ? BS.BS3_STRIDE : BS.BS2_STRIDE,
    DX = is3D ? BS.BS3_DX : BS.BS2_DX,
    PUSHED = is3D ? BS.BS3_PUSHED : BS.BS2_PUSHED;
  let check = 0;
  for (let i = lo; i < hi; i++) {
    const k = i + 1,
      e = list[i]!;
    if (type[e] !== DYNAMIC) continue;
    const o = k * S,
      r = k * BS.BX_STRIDE;
    const free = sb[o + PUSHED] === 0 ? 1 : 0;
    vx[e] = sb[o + BS.BS2_VX]!;
    vy[e] = sb[o + BS.BS2_VY]!;
    const x = ex[r + BS.BX_BASE_X]! + sb[o + DX]! + imp[k * Q]! + free * fx,
      y = ex[r + BS.BX_BASE_Y]! + sb[o + DX + 1]! + imp[k * Q + 1]! + free * fy;
    px[e] = x;
    py[e] = y;
    if (is3D) {
      vz[e] = sb[o + BS.BS3_VZ]!;
      const z = ex[r + BS.BX_BASE_Z]! + sb[o + BS.BS3_DZ]! + imp[k * Q + 2]! + free * fz;
      pz[e] = z;
      check += x + y + z + sb[o + BS.BS3_VX]! + sb[o + BS.BS3_VY]! + sb[o + BS.BS3_VZ]!;
      if (sb[o + BS.BS3_INV_INERTIA]! > 0) {
        wx[e] = sb[o + BS.BS3_WX]!;
        wy[e] = sb[o + BS.BS3_WY]!;
        wz[e] = sb[o + BS.BS3_WZ]!;
        rotate(qx, qy, qz, qw, e, qx[e]!, qy[e]!, qz[e]!, qw[e]!, ex[r + BS.BX_ROT_X]!, ex[r + BS.BX_ROT_Y]!, ex[r + BS.BX_ROT_Z]!);
      }
    } else {
      check += x + y + sb[o + BS.BS2_VX]! + sb[o + BS.BS2_VY]!;
      if (sb[o + BS.BS2_INV_INERTIA]! > 0) {
        wz[e] = sb[o + BS.BS2_W]!;
        angle[e] = angle[e]! + ex[r + BS.BX_ROT_Z]!;
      }
    }
  }
  return check;
}

/**
 * finishBodies' containInBoundary over bodies lo + 1 .. hi, 2D or 3D (A and P as finishBodies'): a body
 * the step's impulses sent through a wall of the box is put back on it, its outward normal velocity
 * reflected and scaled by the restitution; the potential energy a unit mass gains by being put back
 * (-g . dx, J/kg) is taken from its kinetic energy (|v| scaled, or the body stopped), so energy never rises.
 * @category Collision
 */
export function containBodies(A: KernelArray[], P: Float64Array, list: Int32Array, lo: number, hi: number): void {
  const px = A[FINISH.PX] as Float64Array,
    py = A[FINISH.PY] as Float64Array,
    pz = A[FINISH.PZ] as Float64Array;
  const vx = A[FINISH.VX] as Float64Array,
    vy = A[FINISH.VY] as Float64Array,
    vz = A[FINISH.VZ] as Float64Array;
  const type = A[FINISH.BODY_TYPE] as Uint8Array,
    radius = A[FINISH.RADIUS] as Float64Array,
    eM = A[FINISH.RESTITUTION] as Float64Array;
  const DYNAMIC = P[FINISH.DYNAMIC]!,
    boxE = P[FINISH.BOX_RESTITUTION]!;
  const is3D = P[FINISH.THREE_D] === 1,
    dims = is3D ? 3 : 2;
  for (let i = lo; i < hi; i++) {
    const e = list[i]!;
    if (type[e] !== DYNAMIC) continue;
    const rad = radius[e]!;
    let gain = 0;
    for (let d = 0; d < dims; d++) {
      const p = d === 0 ? px : d === 1 ? py : pz,
        v = d === 0 ? vx : d === 1 ? vy : vz,
        g = P[FINISH.GX + d]!;
      const wlo = P[FINISH.MIN_X + d]! + rad,
        whi = P[FINISH.MAX_X + d]! - rad;
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
      if (is3D) v2 += vz[e]! * vz[e]!;
      const f = v2 > 2 * gain ? Math.sqrt(1 - (2 * gain) / v2) : 0;
      vx[e] = vx[e]! * f;
      vy[e] = vy[e]! * f;
      if (is3D) vz[e] = vz[e]! * f;
    }
  }
}

/**
 * finishBodies' deepest overlap over its share of the contact rows (floor(m lo / nb) .. floor(m hi / nb) - 1), 2D or 3D: min(0, min s), m.
 * @category Collision
 */
export function deepestRow(A: KernelArray[], P: Float64Array, lo: number, hi: number): number {
  const sb = A[FINISH.BODY_STATE] as Float64Array;
  const IA = A[FINISH.IA] as Int32Array,
    IB = A[FINISH.IB] as Int32Array,
    S0 = A[FINISH.SEPARATION] as Float64Array,
    NX = A[FINISH.NX] as Float64Array,
    NY = A[FINISH.NY] as Float64Array,
    NZ = A[FINISH.NZ] as Float64Array;
  const m = P[FINISH.ROWS]!,
    nb = P[FINISH.BODIES]!;
  const is3D = P[FINISH.THREE_D] === 1,
    S = is3D ? BS.BS3_STRIDE : BS.BS2_STRIDE,
    DX = is3D ? BS.BS3_DX : BS.BS2_DX;
  const r0 = Math.floor((m * lo) / nb),
    r1 = Math.floor((m * hi) / nb);
  let deepest = 0;
  for (let i = r0; i < r1; i++) {
    const a = IA[i]! * S,
      b = IB[i]! * S;
    // The start separations already hold the impact corrections (solver/impacts.ts).
    let s = S0[i]! + (sb[b + DX]! - sb[a + DX]!) * NX[i]! + (sb[b + DX + 1]! - sb[a + DX + 1]!) * NY[i]!;
    if (is3D) s += (sb[b + BS.BS3_DZ]! - sb[a + BS.BS3_DZ]!) * NZ[i]!;
    if (s < deepest) deepest = s;
  }
  return deepest;
}

/**
 * The ball rows' restitution stage (solver/stages-threads.ts restitutionStage), run by every thread of
 * the pool at once (or by one thread alone), 2D or 3D (P[RESTITUTION.THREE_D]). First the rows' targets
 * and caps (restitutionTargets, blocks of 1,024 rows); then, if any row bounces, `restitutionIterations`
 * sequential-impulse passes (restitutionRows) colour by colour: the blocks of a colour share no movable
 * body (solver/coloring.ts: strips or graph colours; the overflow colour one block), so they may go to any thread. Threads claim blocks by flags, each from its own
 * share of a unit first, and start a unit (the first stage, or a colour of a pass) once every block of
 * the earlier units is done, as solveColored2D (spinning up to P[RESTITUTION.SPIN_US] microseconds, then blocking).
 * A and P: the RESTITUTION slots (solver/slots/restitution.ts). Returns 0 (-1 if another thread failed and
 * this one stopped).
 * @category Collision
 */
export function restitutionColored(
  A: KernelArray[],
  P: Float64Array,
  _ids: Int32Array | null,
  _lo: number,
  _hi: number,
  part: number,
  H: readonly KernelHelper[],
): number {
  const plan = A[RESTITUTION.PLAN] as Int32Array,
    bar = A[RESTITUTION.COUNTERS] as Int32Array,
    bounds = A[RESTITUTION.BOUNDS] as Int32Array;
  const n = P[RESTITUTION.ROWS]!,
    iterations = P[RESTITUTION.ITERATIONS]!,
    spinMs = P[RESTITUTION.SPIN_US]! / 1000;
  const C = plan[PLAN.COLORS]!;
  const wait = part !== 0 || P[RESTITUTION.MAY_WAIT] === 1;
  const FIRST = 1024;
  // Unit 0: the rows' targets and caps; then `iterations` passes of C + 1 colours each.
  const units = 1 + iterations * (C + 1);
  let base = 0,
    failed = false;
  // Blocks are claimed by flags, each thread from its own share of a unit first (claimBlock,
  // threads/block-claim.ts), as solveColored2D: with strips a thread keeps the strips, and their
  // bodies, it solved in the substeps.
  const claim = A[RESTITUTION.CLAIM] as Int32Array,
    threads = plan[PLAN.THREADS]! > 0 ? plan[PLAN.THREADS]! : 1;
  const unit: UnitBlocks = { claim, bar, part, threads, wait, spinMs, cursor: new Int32Array(2), H };
  // The block loops are kernel helpers (KERNEL_HELPERS 7 and 8, solver/kernel-helpers.ts): this kernel
  // runs once a step, and inline they were compiled on the stack partway through a call.
  let c = -1,
    first = 0;
  const block = (blk: number): void => {
    if (c < 0) {
      const lo = blk * FIRST,
        hi = Math.min(n, lo + FIRST);
      const bouncing = (H[7] as typeof restitutionTargets)(A, P, lo, hi, H);
      if (bouncing > 0) Atomics.add(bar, 3, bouncing);
    } else (H[8] as typeof restitutionRows)(A, P, bounds[first + blk]!, bounds[first + blk + 1]!);
  };
  for (let u = 0; u < units; u++) {
    c = u === 0 ? -1 : (u - 1) % (C + 1);
    first = c < 0 ? 0 : plan[PLAN.COLOR_BLOCKS + c]!;
    const count = c < 0 ? Math.ceil(n / FIRST) : plan[PLAN.COLOR_BLOCKS + c + 1]! - first;
    // From unit 1 on: nothing to do unless some row bounces (known once unit 0 is done).
    if (u === 1) {
      if (!(H[16] as typeof awaitBlocks)(bar, base, wait, spinMs)) {
        failed = true;
        break;
      }
      if (Atomics.load(bar, 3) === 0) break;
    }
    if (count > 0 && !(H[20] as typeof runUnitBlocks)(unit, base, count, block)) {
      failed = true;
      break;
    }
    base += count;
  }
  return failed ? -1 : 0;
}

/**
 * What runUnitBlocks needs of a block-claimed kernel's call (solveColored2D, restitutionColored), made once
 * a call: the claim flags and counters (`bar`: [1] blocks done, [2] a thread failed), this thread's
 * `part` of `threads`, whether it may block and how long it spins first, its claim cursor, the kernel helpers.
 */
export interface UnitBlocks {
  claim: Int32Array;
  bar: Int32Array;
  part: number;
  threads: number;
  wait: boolean;
  spinMs: number;
  cursor: Int32Array;
  H: readonly KernelHelper[];
}

/**
 * This thread's share of one unit of a block-claimed kernel (KERNEL_HELPERS 20): waits until every block of
 * the earlier units is done (`base` blocks, threads/block-claim.ts awaitBlocks, KERNEL_HELPERS 16), then
 * claims the unit's `count` blocks one by one (claimBlock, KERNEL_HELPERS 9) and runs `block` on each,
 * counting it done in bar[1]; the unit's last block wakes the threads waiting to start the next. If
 * `block` throws, lets the other threads out of their waits (bar[2] = 1) and throws again. Returns false
 * if another thread failed (the caller stops).
 * @category Threads
 */
export function runUnitBlocks(run: UnitBlocks, base: number, count: number, block: (blk: number) => void): boolean {
  const claim = run.claim,
    bar = run.bar,
    part = run.part,
    threads = run.threads,
    cursor = run.cursor;
  const claimNext = run.H[9] as typeof claimBlock;
  if (!(run.H[16] as typeof awaitBlocks)(bar, base, run.wait, run.spinMs)) return false;
  const end = base + count;
  cursor[0] = 0;
  cursor[1] = 0;
  for (
    let blk = claimNext(claim, base, count, part, threads, cursor);
    blk >= 0;
    blk = claimNext(claim, base, count, part, threads, cursor)
  ) {
    try {
      block(blk);
    } catch (e) {
      Atomics.store(bar, 2, 1);
      Atomics.notify(bar, 1);
      throw e;
    }
    if (Atomics.add(bar, 1, 1) + 1 === end) Atomics.notify(bar, 1);
  }
  return true;
}

/**
 * The blocks of every unit of restitutionColored over `n` rows with `plan` (the colours' layout) and `iterations` passes: the size its claim array needs.
 * @category Collision
 */
export function restitutionBlocks(plan: Int32Array, n: number, iterations: number): number {
  const C = plan[PLAN.COLORS]!;
  return Math.ceil(n / 1024) + iterations * (plan[PLAN.COLOR_BLOCKS + C + 1]! - plan[PLAN.COLOR_BLOCKS]!);
}

/**
 * The targets and caps of ball rows [lo, hi) (restitutionColored's first unit), 2D or 3D, by solver/restitution.ts
 * (KERNEL_HELPERS 17 and 18 in `H`): a row that carried no impulse takes no part (target -1), one that bounces gets
 * its target and cap, the rest the target 0. Each row's relative velocity, largest pass impulse and delivered total
 * are spent by now and hold the target, the rebound's impulse (0) and the cap. Returns how many rows bounce.
 * @category Collision
 */
export function restitutionTargets(A: KernelArray[], P: Float64Array, lo: number, hi: number, H: readonly KernelHelper[]): number {
  const sb = A[RESTITUTION.BODY_STATE] as Float64Array,
    IA = A[RESTITUTION.IA] as Int32Array,
    IB = A[RESTITUTION.IB] as Int32Array,
    NX = A[RESTITUTION.NX] as Float64Array,
    NY = A[RESTITUTION.NY] as Float64Array,
    NZ = A[RESTITUTION.NZ] as Float64Array;
  const NM = A[RESTITUTION.NORMAL_MASS] as Float64Array,
    E = A[RESTITUTION.RESTITUTION] as Float64Array,
    RV = A[RESTITUTION.RELATIVE_VELOCITY] as Float64Array,
    IV = A[RESTITUTION.IMPACT_VELOCITY] as Float64Array;
  const MAXN = A[RESTITUTION.MAX_NORMAL_IMPULSE] as Float64Array,
    TOT = A[RESTITUTION.TOTAL_NORMAL_IMPULSE] as Float64Array;
  const threshold = P[RESTITUTION.THRESHOLD]!,
    elasticThreshold = P[RESTITUTION.ELASTIC_THRESHOLD]!;
  const targetOf = H[17] as typeof restitutionTarget,
    capOf = H[18] as typeof restitutionCap;
  // vx and vy sit at the same offsets in both layouts.
  const is3D = P[RESTITUTION.THREE_D] === 1,
    S = is3D ? BS.BS3_STRIDE : BS.BS2_STRIDE;
  let bouncing = 0;
  for (let i = lo; i < hi; i++) {
    if (MAXN[i] === 0) {
      RV[i] = -1;
      continue;
    }
    MAXN[i] = 0;
    const e = E[i]!;
    const target = targetOf(e, RV[i]!, IV[i]!, threshold, elasticThreshold);
    if (target < 0) {
      RV[i] = 0;
      continue;
    }
    RV[i] = target;
    const a = IA[i]! * S,
      bb = IB[i]! * S;
    let vn = (sb[bb + BS.BS2_VX]! - sb[a + BS.BS2_VX]!) * NX[i]! + (sb[bb + BS.BS2_VY]! - sb[a + BS.BS2_VY]!) * NY[i]!;
    if (is3D) vn += (sb[bb + BS.BS3_VZ]! - sb[a + BS.BS3_VZ]!) * NZ[i]!;
    TOT[i] = capOf(e, TOT[i]!, vn < 0 ? -NM[i]! * vn : 0);
    bouncing++;
  }
  return bouncing;
}

/**
 * One block of a restitution pass over the ball rows ROW[r0 .. r1) (buffer rows; A and P as
 * restitutionColored's, 2D or 3D by P[RESTITUTION.THREE_D]): each row that takes part moves its
 * rebound impulse toward its target as restitutionImpulse (solver/restitution.ts) does,
 * capped for a bouncing row, and its bodies' velocities by the change.
 * @category Collision
 */
export function restitutionRows(A: KernelArray[], P: Float64Array, r0: number, r1: number): void {
  const sb = A[RESTITUTION.BODY_STATE] as Float64Array,
    IA = A[RESTITUTION.IA] as Int32Array,
    IB = A[RESTITUTION.IB] as Int32Array,
    NX = A[RESTITUTION.NX] as Float64Array,
    NY = A[RESTITUTION.NY] as Float64Array,
    NZ = A[RESTITUTION.NZ] as Float64Array,
    NM = A[RESTITUTION.NORMAL_MASS] as Float64Array,
    RV = A[RESTITUTION.RELATIVE_VELOCITY] as Float64Array;
  const MAXN = A[RESTITUTION.MAX_NORMAL_IMPULSE] as Float64Array,
    TOT = A[RESTITUTION.TOTAL_NORMAL_IMPULSE] as Float64Array,
    IMP = A[RESTITUTION.IMPULSE] as Float64Array,
    row = A[RESTITUTION.ROW] as Int32Array;
  const is3D = P[RESTITUTION.THREE_D] === 1,
    S = is3D ? BS.BS3_STRIDE : BS.BS2_STRIDE,
    im = is3D ? BS.BS3_INV_MASS : BS.BS2_INV_MASS;
  for (let k = r0; k < r1; k++) {
    const i = row[k]!;
    const target = RV[i]!;
    if (target < 0) continue;
    const a = IA[i]! * S,
      bb = IB[i]! * S;
    const nx = NX[i]!,
      ny = NY[i]!;
    let vn = (sb[bb + BS.BS2_VX]! - sb[a + BS.BS2_VX]!) * nx + (sb[bb + BS.BS2_VY]! - sb[a + BS.BS2_VY]!) * ny;
    if (is3D) vn += (sb[bb + BS.BS3_VZ]! - sb[a + BS.BS3_VZ]!) * NZ[i]!;
    const old = MAXN[i]!;
    // solver/restitution.ts restitutionImpulse, written out: a helper call per row and pass is not inlined here.
    let acc = old - NM[i]! * (vn - target);
    if (acc < 0) acc = 0;
    if (target > 0 && acc > TOT[i]!) acc = TOT[i]!;
    const dl = acc - old;
    if (dl === 0) continue;
    MAXN[i] = acc;
    IMP[i] = IMP[i]! + dl;
    const ka = sb[a + im]! * dl,
      kb = sb[bb + im]! * dl;
    sb[a + BS.BS2_VX] = sb[a + BS.BS2_VX]! - ka * nx;
    sb[a + BS.BS2_VY] = sb[a + BS.BS2_VY]! - ka * ny;
    sb[bb + BS.BS2_VX] = sb[bb + BS.BS2_VX]! + kb * nx;
    sb[bb + BS.BS2_VY] = sb[bb + BS.BS2_VY]! + kb * ny;
    if (is3D) {
      const nz = NZ[i]!;
      sb[a + BS.BS3_VZ] = sb[a + BS.BS3_VZ]! - ka * nz;
      sb[bb + BS.BS3_VZ] = sb[bb + BS.BS3_VZ]! + kb * nz;
    }
  }
}
