/**
 * The 2D ball contacts' soft substeps on the world's threads, in blocks of rows that share no movable
 * body, as Box2D v3 does with its graph colours (Catto, "Solver2D" and Box2D v3.0 solver.c /
 * constraint_graph.c). A "colour" here is a set of blocks that may run at once; the threads claim
 * blocks and meet only where one colour ends and the next begins. Two ways to cut the rows:
 *
 * - strips (the usual way): the movable solver bodies are cut into `STRIPS` strips across the pile's
 *   longer axis, each holding about as many rows as the others (quantiles of a histogram of the rows'
 *   first movable body). A row belongs to the strip of its lower body; when no row joins bodies more
 *   than one strip apart, the even strips' rows touch disjoint bodies (strip 2j's rows touch strips 2j
 *   and 2j + 1 only), and so do the odd strips': colour 0 is the even strips, colour 1 the odd ones,
 *   each strip one block solved in buffer order, and the few rows that join bodies further apart go to
 *   the overflow colour. A pass then takes two meetings of the threads instead of one a graph colour
 *   (about ten), and the body stages (gravity before the warm start, positions before the relax pass)
 *   run inside the even blocks, for their strip pair's bodies, without a meeting of their own;
 * - graph colours (when the strips leave more than 1/64 of the rows to the overflow colour even at
 *   four strips, e.g. a tall narrow pile of mixed sizes): the rows are coloured greedily, in buffer
 *   order, so that no two rows of one colour share a body that can move under an impulse (a solver body
 *   with inverse mass or inertia; the static world and kinematic bodies are shared freely: rows only
 *   read them). Up to `MAX_COLORS` colours; a row that finds none free goes to an overflow colour that
 *   one thread solves alone. Blocks of 256 rows.
 *
 * Either way the rows are packed colour by colour (solver/contact-pack-2d.ts; within a block in buffer order)
 * and the whole substep loop (gravity, warm start, biased passes, positions, relax passes) runs as one
 * kernel on every thread (solver/coloring-kernel.ts). The strip plan and the packing usually run on a
 * worker while the calling thread runs the impact stage (startStripPlan), which leaves the rows it
 * resolves in the pack with nothing to do and the rows whose values it changes to be packed again.
 *
 * Blocks of one colour touch disjoint movable bodies, and the cut depends on the state alone (not on
 * the number of threads), so which thread runs a block does not change any result. A world without a
 * pool (`threads: 1`), or whose adaptive pool finds the threads slower (threads/adaptive.ts), runs the
 * same kernel inline on the calling thread, over every block: a step gives the same bits on 1, 2 or n
 * threads.
 *
 * Taken in 2D worlds with no joints and no shape manifolds in the step (they solve between the contacts
 * within each pass) and at least `CollisionSettings.coloredSolveMinRows` rows (default 16384), on any
 * thread count; smaller or mixed steps run the buffer-order loops of solver/contact-solver.ts on every
 * thread count.
 */

import type { ContactBuffer } from '../collision/contacts.js';
import { BodyType, type CollisionState } from '../collision/state.js';
import { nowMs } from '../threads/adaptive.js';
import type { KernelArray } from '../threads/kernel-types.js';
import { isShared, sharedCopy, sharedLike, sharedMemoryAvailable, type ThreadPool } from '../threads/pool.js';
import type { PhysicsWorld } from '../world/options.js';
import type { ColorScratch } from '../world/scratch.js';
import { BS2_INV_INERTIA, BS2_INV_MASS, BS2_STRIDE } from './body-state-layout.js';
import { coloredRepack2D, solveColored2D, solveColoredBlocks2D } from './coloring-kernel.js';
import { PACK_STRIDE } from './contact-pack-2d.js';
import { impactChangedRows } from './impact-state.js';
import { releaseImpactedRows } from './impacts.js';
import { KERNEL_HELPERS } from './kernel-helpers.js';
import * as APPROACH from './slots/approach.js';
import * as PLAN from './slots/colored-plan.js';
import * as SOLVE from './slots/colored-solve.js';
import * as CUT from './slots/strip-cut.js';
import * as STRIP_PLAN from './slots/strip-plan.js';
import { stripLayout2D, stripPlan2D } from './strip-plan-kernel.js';
import { downwardInto, SUPPORT_COS } from './support.js';

/**
 * Moves every typed array of a contact buffer that is not on a SharedArrayBuffer onto one (same
 * contents), so the pool's workers can read and write it (the solver and its threaded stages).
 * @category Collision
 */
export function shareContactBuffer(buf: ContactBuffer): void {
  const rec = buf as unknown as Record<string, unknown>;
  for (const key of Object.keys(rec)) {
    const a = rec[key];
    if (!ArrayBuffer.isView(a) || a instanceof DataView) continue;
    rec[key] = sharedCopy(a as KernelArray);
  }
}

/**
 * Colours before the overflow colour (bits of a 32-bit mask a body).
 * @category Collision
 */
export const MAX_COLORS = 32;

/**
 * Strips the movable bodies are first cut into (even, at most MAX_COLORS: a strip is a packing group);
 * fewer (halved down to 4) when too many rows join bodies more than one strip apart.
 * @category Collision
 */
export const STRIPS = 32;

/** Rows a block of a graph colour. */
const BLOCK_ROWS = 256;

/**
 * Int32 slots of the plan before the colours' first blocks (see solveColored2D).
 * @category Collision
 */
export const PLAN_HEAD = 12;

/**
 * Microseconds a thread of the coloured solve spins, waiting for the next colour, before it blocks in
 * Atomics.wait: waking a blocked thread takes some tens of microseconds, about what the threads' ends
 * of a colour differ by, so a short spin saves that wake-up without holding a core for long.
 * @category Collision
 */
export const SPIN_MICROSECONDS = 50;

/** Histogram bins of the strips' quantiles. */
const BINS = 4096;

/** A fixed body's bin (stripCut2D): in none. */
const NO_BIN = 0xffff;

/**
 * A buffer of `bytes` bytes for the coloured solve's scratch: shared memory where there is any (the
 * pool's workers read it), else a plain ArrayBuffer (a one-thread world in a page that is not
 * cross-origin isolated runs the kernel inline).
 */
function buffer(bytes: number): ArrayBufferLike {
  return sharedMemoryAvailable() ? new SharedArrayBuffer(bytes) : new ArrayBuffer(bytes);
}

/**
 * A typed array of the same type as `like` and `n` elements, on shared memory where there is any (a
 * plain one otherwise, for a one-thread world whose page is not cross-origin isolated).
 * @category Collision
 */
export function grown<T extends KernelArray>(like: T, n: number): T {
  if (sharedMemoryAvailable()) return sharedLike(like, n);
  const C = like.constructor as { new (n: number): T };
  return new C(n);
}

/** The world's coloured-solve scratch (world/scratch.ts), made on first use and grown to `rows` contact rows and `bodies` solver bodies. */
function scratch(world: PhysicsWorld, rows: number, bodies: number): ColorScratch {
  let s = world.scratch.coloring;
  if (s === undefined) {
    s = {
      pack: new Float64Array(buffer(8 * PACK_STRIDE * 1024)),
      pair: new Int32Array(buffer(4 * 2 * 1024)),
      tot: new Float64Array(buffer(8 * 1024)),
      row: new Int32Array(buffer(4 * 1024)),
      dyn: new Uint8Array(buffer(1024)),
      plan: new Int32Array(buffer(4 * (PLAN_HEAD + MAX_COLORS + 2))),
      bar: new Int32Array(buffer(4 * 4)),
      params: new Float64Array(24),
      claim: new Int32Array(buffer(4 * 1024)),
      color: new Uint8Array(buffer(1024)),
      mask: new Uint32Array(1024),
      arrays: [],
      offsets: new Int32Array(buffer(4 * (MAX_COLORS + 1) * 16)),
      counts: new Int32Array(buffer(4 * (MAX_COLORS + 2))),
      start: new Int32Array(buffer(4 * (MAX_COLORS + 2))),
      next: new Int32Array(buffer(4 * (MAX_COLORS + 2))),
      slot: new Int32Array(buffer(4 * 1024)),
      bounds: new Int32Array(buffer(4 * 1024)),
      bodyOrder: new Int32Array(buffer(4 * 1024)),
      bodyBounds: new Int32Array(buffer(4 * (MAX_COLORS + 2))),
      strip: new Uint8Array(buffer(1024)),
      bin: new Uint16Array(buffer(2 * 1024)),
      hist: new Int32Array(buffer(4 * BINS)),
      binStrip: new Uint8Array(buffer(BINS)),
      pending: false,
      cut: 0,
      planArrays: [],
      planParams: new Float64Array(PLAN_PARAMS),
    };
    world.scratch.coloring = s;
  }
  if (s.pack.length < rows * PACK_STRIDE) s.pack = grown(s.pack, Math.max(rows * PACK_STRIDE, 2 * s.pack.length));
  if (s.pair.length < 2 * rows) s.pair = grown(s.pair, Math.max(2 * rows, 2 * s.pair.length));
  if (s.tot.length < rows) s.tot = grown(s.tot, Math.max(rows, 2 * s.tot.length));
  if (s.row.length < rows) s.row = grown(s.row, Math.max(rows, 2 * s.row.length));
  if (s.color.length < rows) s.color = grown(s.color, Math.max(rows, 2 * s.color.length));
  if (s.slot.length < rows) s.slot = grown(s.slot, Math.max(rows, 2 * s.slot.length));
  const blocks = Math.ceil(rows / BLOCK_ROWS) + MAX_COLORS + 2;
  if (s.bounds.length < blocks) s.bounds = grown(s.bounds, Math.max(blocks, 2 * s.bounds.length));
  if (s.dyn.length < bodies) s.dyn = grown(s.dyn, Math.max(bodies, 2 * s.dyn.length));
  if (s.bodyOrder.length < bodies) s.bodyOrder = grown(s.bodyOrder, Math.max(bodies, 2 * s.bodyOrder.length));
  if (s.mask.length < bodies) s.mask = new Uint32Array(Math.max(bodies, 2 * s.mask.length));
  if (s.strip.length < bodies) s.strip = grown(s.strip, Math.max(bodies, 2 * s.strip.length));
  if (s.bin.length < bodies) s.bin = grown(s.bin, Math.max(bodies, 2 * s.bin.length));
  return s;
}

/**
 * Whether the step's 2D ball contacts go through the coloured solve (see the file's header): a 2D
 * world, no joints or manifolds (`others` true when there are), enough rows. The same answer for
 * every thread count (a world without a pool runs the kernel inline), so worlds on 1, 2 or n threads
 * take the same path each step and end in the same state.
 * @category Collision
 */
export function useColoredSolve(world: PhysicsWorld, buf: ContactBuffer, others: boolean): boolean {
  // A plan left by a step that stopped before its restitution stage is not this step's.
  const old = world.scratch.coloring;
  if (old !== undefined) old.pending = false;
  return colored(world, buf, others);
}

/** Whether the step's 2D ball contacts go through the coloured solve (useColoredSolve). */
function colored(world: PhysicsWorld, buf: ContactBuffer, others: boolean): boolean {
  return !others && world.dimensions === 2 && buf.count >= world.collision.settings.coloredSolveMinRows;
}

/**
 * The world's pool if the coloured solve's kernels may run on its workers (at most 16 threads, the
 * solver state on shared memory), else null (they run inline on the calling thread).
 */
function coloredPool(world: PhysicsWorld): ThreadPool | null {
  const pool = world.threadPool,
    cs = world.collision;
  if (pool === null || pool.threads > 16) return null;
  return isShared(cs.bodyState) && isShared(cs.bodyExtra) ? pool : null;
}

/** Whether a row can do nothing (no mass to move, no impulse to warm start): it is left out of the pack. */
function idle(NM: Float64Array, TM: Float64Array, LN: Float64Array, LT: Float64Array, i: number): boolean {
  return NM[i] === 0 && TM[i] === 0 && LN[i] === 0 && LT[i] === 0;
}

/**
 * Colours the rows of `buf` (solver indices, masses and impulses prepared) greedily in buffer order
 * into `s.color` (255: not packed, MAX_COLORS: the overflow colour) and counts them per colour
 * (`s.counts`) and per packing range (`s.offsets`, MAX_COLORS + 1 a range). Returns the colours used.
 */
function colorRows(cs: CollisionState, buf: ContactBuffer, s: ColorScratch, parts: number): number {
  const n = buf.count,
    bodies = cs.solverBodyCount;
  const IA = buf.ia,
    IB = buf.ib,
    NM = buf.normalMass,
    TM = buf.tangentMass,
    LN = buf.normalImpulse,
    LT = buf.tangentImpulse1;
  const sb = cs.bodyState,
    mask = s.mask,
    color = s.color;
  const W = MAX_COLORS + 1,
    partCounts = s.offsets;
  mask.fill(0, 0, bodies);
  partCounts.fill(0, 0, parts * W);
  const counts = s.counts;
  counts.fill(0);
  for (let p = 0; p < parts; p++) {
    const lo = Math.floor((n * p) / parts),
      hi = Math.floor((n * (p + 1)) / parts),
      base = p * W;
    for (let i = lo; i < hi; i++) {
      if (idle(NM, TM, LN, LT, i)) {
        color[i] = 255;
        continue;
      }
      const a = IA[i]!,
        b = IB[i]!;
      // Only bodies an impulse can move take a colour's slot (the static world and kinematic bodies are read only).
      const ma = a !== 0 && (sb[a * BS2_STRIDE + BS2_INV_MASS]! > 0 || sb[a * BS2_STRIDE + BS2_INV_INERTIA]! > 0);
      const mb = sb[b * BS2_STRIDE + BS2_INV_MASS]! > 0 || sb[b * BS2_STRIDE + BS2_INV_INERTIA]! > 0;
      const used = (ma ? mask[a]! : 0) | (mb ? mask[b]! : 0);
      const free = ~used;
      let c = MAX_COLORS;
      if (free !== 0) {
        c = 31 - Math.clz32(free & -free);
        const bit = 1 << c;
        if (ma) mask[a] = mask[a]! | bit;
        if (mb) mask[b] = mask[b]! | bit;
      }
      color[i] = c;
      counts[c] = counts[c]! + 1;
      partCounts[base + c] = partCounts[base + c]! + 1;
    }
  }
  let used = 0;
  for (let c = 0; c < MAX_COLORS; c++) if (counts[c]! > 0) used = c + 1;
  return used;
}

/** Length of stripPlan2D's parameters. */
const PLAN_PARAMS = 16;

/**
 * stripPlan2D's arrays for `buf`'s rows (solver/strip-plan-kernel.ts: solveColored2D's 0 to 30, then
 * stripCut2D's, then the layout's own), in `s.planArrays`. The arrays must be sized (scratch) first.
 */
function planArguments(cs: CollisionState, buf: ContactBuffer, s: ColorScratch): KernelArray[] {
  const A = solveArguments(cs, buf, s, s.planArrays);
  A[STRIP_PLAN.CUT_ARRAYS + CUT.BODY_STATE] = cs.bodyState;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.BODY_EXTRA] = cs.bodyExtra;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.BODY_TYPE] = cs.bodyType;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.BODIES] = cs.solverBodies;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.DYN] = s.dyn;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.STRIP] = s.strip;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.BIN] = s.bin;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.BIN_ROWS] = s.hist;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.BIN_STRIP] = s.binStrip;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.IA] = buf.ia;
  A[STRIP_PLAN.CUT_ARRAYS + CUT.IB] = buf.ib;
  A[STRIP_PLAN.COUNTS] = s.counts;
  A[STRIP_PLAN.START] = s.start;
  A[STRIP_PLAN.NEXT] = s.next;
  return A;
}

/** solveColored2D's arrays for `buf`'s rows (solver/coloring-kernel.ts, 0 to 30), into `A` (emptied first). */
function solveArguments(cs: CollisionState, buf: ContactBuffer, s: ColorScratch, A: KernelArray[]): KernelArray[] {
  A.length = 0;
  A[SOLVE.PACK] = s.pack;
  A[SOLVE.BODY_STATE] = cs.bodyState;
  A[SOLVE.BODY_EXTRA] = cs.bodyExtra;
  A[SOLVE.DYN] = s.dyn;
  A[SOLVE.PLAN] = s.plan;
  A[SOLVE.COUNTERS] = s.bar;
  A[SOLVE.GROUP] = s.color;
  A[SOLVE.OFFSETS] = s.offsets;
  A[SOLVE.IA] = buf.ia;
  A[SOLVE.IB] = buf.ib;
  A[SOLVE.NX] = buf.nx;
  A[SOLVE.NY] = buf.ny;
  A[SOLVE.RA] = buf.ra;
  A[SOLVE.RB] = buf.rb;
  A[SOLVE.SEPARATION] = buf.separation;
  A[SOLVE.NORMAL_MASS] = buf.normalMass;
  A[SOLVE.TANGENT_MASS] = buf.tangentMass;
  A[SOLVE.FRICTION_BOUND] = buf.frictionBound;
  A[SOLVE.NORMAL_IMPULSE] = buf.normalImpulse;
  A[SOLVE.TANGENT_IMPULSE] = buf.tangentImpulse1;
  A[SOLVE.RIGID_PARTNER] = buf.rigidPartner;
  A[SOLVE.MAX_NORMAL_IMPULSE] = buf.maxNormalImpulse;
  A[SOLVE.TOTAL_NORMAL_IMPULSE] = buf.totalNormalImpulse;
  A[SOLVE.BOUNDS] = s.bounds;
  A[SOLVE.BODY_ORDER] = s.bodyOrder;
  A[SOLVE.BODY_BOUNDS] = s.bodyBounds;
  A[SOLVE.PAIR] = s.pair;
  A[SOLVE.TOT] = s.tot;
  A[SOLVE.ROW] = s.row;
  A[SOLVE.CLAIM] = s.claim;
  A[SOLVE.SLOT] = s.slot;
  return A;
}

/**
 * Appends approachSpeeds's arrays for `buf`'s rows (the APPROACH slots of solver/slots/approach.ts, from
 * A.length on) to `A`; returns `A`.
 * @category Collision
 */
export function approachArguments(cs: CollisionState, buf: ContactBuffer, A: KernelArray[]): KernelArray[] {
  const b = A.length;
  A[b + APPROACH.IA] = buf.ia;
  A[b + APPROACH.IB] = buf.ib;
  A[b + APPROACH.A] = buf.a;
  A[b + APPROACH.B] = buf.b;
  A[b + APPROACH.NX] = buf.nx;
  A[b + APPROACH.NY] = buf.ny;
  A[b + APPROACH.NZ] = buf.nz;
  A[b + APPROACH.RELATIVE_VELOCITY] = buf.relativeVelocity;
  A[b + APPROACH.IMPACT_VELOCITY] = buf.impactVelocity;
  A[b + APPROACH.SEPARATION] = buf.separation;
  A[b + APPROACH.IMPULSE] = buf.impulse;
  A[b + APPROACH.BODY_TYPE] = cs.bodyType;
  A[b + APPROACH.BODY_STATE] = cs.bodyState;
  return A;
}

/**
 * stripPlan2D's parameters, in `s.planParams`: a plan by `strips` strips (cut first if `cut`) over
 * `parts` packing ranges, packed there if `pack`.
 */
function planParameters(
  cs: CollisionState,
  buf: ContactBuffer,
  s: ColorScratch,
  strips: number,
  parts: number,
  pack: boolean,
  cut: boolean,
): Float64Array {
  const P = s.planParams;
  P[CUT.P_BODIES] = cs.solverBodyCount;
  P[CUT.P_ROWS] = buf.count;
  P[CUT.P_STRIPS] = strips;
  P[CUT.BINS] = BINS;
  P[CUT.P_DYNAMIC] = BodyType.Dynamic;
  P[CUT.NO_BIN] = NO_BIN;
  P[CUT.BASE] = STRIP_PLAN.CUT_ARRAYS;
  P[STRIP_PLAN.PARTS] = parts;
  P[STRIP_PLAN.PACK] = pack ? 1 : 0;
  P[STRIP_PLAN.CUT_HERE] = cut ? 1 : 0;
  P[STRIP_PLAN.MAX_OVERFLOW] = Math.max(64, buf.count >> 6);
  P[SOLVE.ROWS] = buf.count;
  P[SOLVE.GROUP_SLOTS] = MAX_COLORS + 1;
  P[STRIP_PLAN.PLAN_HEAD] = PLAN_HEAD;
  P[STRIP_PLAN.MAX_COLORS] = MAX_COLORS;
  P[STRIP_PLAN.BLOCK_ROWS] = BLOCK_ROWS;
  return P;
}

/**
 * Starts this step's strip plan (solver/strip-plan-kernel.ts stripPlan2D: the cut into STRIPS strips,
 * the rows' groups, the blocks, and every row packed) on a worker of the world's pool when the step's 2D
 * ball contacts will go through the coloured solve (useColoredSolve; `others` as there), so it runs
 * while the calling thread runs the impact stage (ThreadPool.start). What the plan reads that the
 * impact stage writes:
 * - the movable bodies' velocities and the angle corrections: the cut reads velocities only of
 *   bodies without inverse mass or inertia, and base positions;
 * - the start separations and normals of the rows it changes: solveColoredSubsteps packs those rows
 *   again after it joins (solver/impacts.ts impactChangedRows);
 * - the masses and impulses that decide whether a row is packed: the stage leaves them to
 *   releaseImpactedRows, which runs after the plan.
 * So the plan and pack are the ones the calling thread would make after the stage. solveColoredSubsteps
 * joins it; when it did not plan (too many rows overflow at STRIPS strips) or did not start, the plan is
 * made there, on the calling thread.
 * @category Collision
 */
export function startStripPlan(world: PhysicsWorld, buf: ContactBuffer, others: boolean): void {
  const cs = world.collision;
  const old = world.scratch.coloring;
  if (old !== undefined) {
    old.cut = 0;
    old.plan[PLAN.PACKED] = 0;
  }
  const pool = colored(world, buf, others) ? coloredPool(world) : null;
  if (pool === null || pool.threads < 2 || !isShared(cs.solverBodies) || !pool.usable()) return;
  // The body types go to shared memory here if no threaded stage has moved them yet (the same values).
  cs.bodyType = sharedCopy(cs.bodyType);
  shareContactBuffer(buf);
  const s = scratch(world, buf.count, cs.solverBodyCount);
  pool.start('contactSolverSystem', stripPlan2D, planArguments(cs, buf, s), planParameters(cs, buf, s, STRIPS, 1, true, true), 1);
  s.cut = STRIPS;
}

/**
 * Plans the coloured solve of `buf`'s rows on the calling thread: strips (stripPlan2D) when they leave
 * at most 1/64 of the rows (and at least 64) to the overflow colour at some strip count from STRIPS down
 * to 4, else graph colours (see the file's header), over `parts` packing ranges (the solve packs).
 * Fills the pack layout, the blocks, the plan's colours (slot 9: 1 for strips, whose even blocks also
 * run their strip pair's body stages: `s.bodyOrder`, `s.bodyBounds`), and the bodies that take gravity
 * (`s.dyn`). Returns the rows to pack.
 */
function planRows(cs: CollisionState, buf: ContactBuffer, s: ColorScratch, parts: number): number {
  const A = planArguments(cs, buf, s);
  for (let strips = STRIPS; strips >= 4; strips >>= 1) {
    const P = planParameters(cs, buf, s, strips, parts, false, s.cut !== strips);
    s.cut = strips;
    if (stripPlan2D(A, P, null, 0, 1, 0, KERNEL_HELPERS) > 0) return s.plan[PLAN.PACKED_ROWS]!;
  }
  const used = colorRows(cs, buf, s, parts);
  s.plan[PLAN.STRIPS] = 0;
  return stripLayout2D(A, planParameters(cs, buf, s, used, parts, false, false), used, 0);
}

/**
 * Colours used by the last coloured solve of `world` (0: none ran), for tests and the bench.
 * @category Collision
 */
export function lastColorCount(world: PhysicsWorld): number {
  const s = world.scratch.coloring;
  return s === undefined ? 0 : s.plan[PLAN.COLORS]!;
}

/**
 * Checks the last coloured solve of `world` (a test of the cut, not of physics): the number of times a
 * movable solver body (inverse mass or inertia > 0) appears in rows of two blocks of one colour (blocks
 * of a colour run at once on different threads; the overflow colour is one block), the rows in the
 * overflow colour, the rows packed, and whether the rows were cut into strips. 0 conflicts is the
 * cut's promise.
 * @category Collision
 */
export function coloringConflicts(world: PhysicsWorld): { conflicts: number; overflow: number; rows: number; strips: boolean } {
  const cs = world.collision;
  const s = world.scratch.coloring;
  if (s === undefined) return { conflicts: 0, overflow: 0, rows: 0, strips: false };
  const plan = s.plan,
    C = plan[PLAN.COLORS]!,
    pair = s.pair,
    sb = cs.bodyState,
    bounds = s.bounds;
  const seen = new Map<number, number>();
  let conflicts = 0;
  for (let c = 0; c < C; c++) {
    for (let j = plan[PLAN_HEAD + c]!; j < plan[PLAN_HEAD + c + 1]!; j++) {
      for (let k = bounds[j]!; k < bounds[j + 1]!; k++) {
        for (const off of [pair[2 * k]!, pair[2 * k + 1]!]) {
          if (!(sb[off + BS2_INV_MASS]! > 0 || sb[off + BS2_INV_INERTIA]! > 0)) continue;
          const key = c * 1e9 + off,
            was = seen.get(key);
          if (was !== undefined && was !== j) conflicts++;
          seen.set(key, j);
        }
      }
    }
  }
  const o0 = plan[PLAN_HEAD + C]!,
    o1 = plan[PLAN_HEAD + C + 1]!;
  return { conflicts, overflow: bounds[o1]! - bounds[o0]!, rows: plan[PLAN.PACKED_ROWS]!, strips: plan[PLAN.STRIPS] === 1 };
}

/** Whether this thread may block in Atomics.wait (not a browser's main thread); cached. */
let mainMayWait: boolean | null = null;
function mayWait(): boolean {
  if (!sharedMemoryAvailable()) return false; // no workers to wait for
  if (mainMayWait === null) {
    try {
      Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 1, 0);
      mainMayWait = true;
    } catch {
      mainMayWait = false;
    }
  }
  return mainMayWait;
}

/**
 * Runs the step's substeps for the 2D ball contacts of `buf` by colours on the world's threads (or on
 * the calling thread alone without a pool, or when the adaptive pool prefers it: the same results
 * either way), then writes the impulses back to `buf` (normal, tangent, largest pass impulse,
 * delivered total), as the buffer-order loop of solver/contact-solver.ts leaves them. `soft`: dynamic bias rate, mass scale, impulse scale, then the rigid ones.
 * @throws Error naming contactSolverSystem if a worker thread failed.
 * @category Collision
 */
export function solveColoredSubsteps(world: PhysicsWorld, buf: ContactBuffer, hs: number, soft: readonly number[], push: number): void {
  const cs = world.collision,
    pool = coloredPool(world);
  const st = cs.settings;
  const s = scratch(world, buf.count, cs.solverBodyCount);
  if (pool !== null) {
    shareContactBuffer(buf);
    pool.join(); // the strip plan startStripPlan left on a worker
  }
  const plan = s.plan;
  const packed = plan[PLAN.PACKED] === 1;
  const parts = pool === null ? 1 : pool.threads;
  const np = packed ? plan[PLAN.PACKED_ROWS]! : planRows(cs, buf, s, parts);
  // Planned from the masses and impulses before the impact stage took its resolved rows out: they stay
  // in the pack with nothing to do (no mass, no impulse: every pass changes nothing by them).
  releaseImpactedRows(buf);
  // measureApproach (solver/contact-solver.ts) of the rows, as the solve's unit after the packing.
  const A = approachArguments(cs, buf, solveArguments(cs, buf, s, s.arrays));
  // Rows packed on the worker whose values the impact stage changed meanwhile are packed again.
  if (packed) {
    const changed = impactChangedRows();
    coloredRepack2D(A, changed.rows, changed.count);
  }
  const P = s.params,
    g = world.gravity;
  plan[PLAN.SUBSTEPS] = st.solverSubsteps;
  plan[PLAN.ITERATIONS] = st.solverIterations;
  plan[PLAN.RELAX] = st.relaxIterations;
  plan[PLAN.BODIES] = cs.solverBodyCount;
  plan[PLAN.MAY_WAIT] = mayWait() ? 1 : 0;
  plan[PLAN.PARTS] = packed ? 0 : parts;
  P[SOLVE.INV_HS] = 1 / hs;
  for (let k = 0; k < 6; k++) P[SOLVE.SOFT_BIAS + k] = soft[k]!;
  P[SOLVE.PUSH_SPEED] = push;
  P[SOLVE.HS] = hs;
  P[SOLVE.GX_HS] = g[0]! * hs;
  P[SOLVE.GY_HS] = g[1]! * hs;
  P[SOLVE.ROWS] = buf.count;
  P[SOLVE.GROUP_SLOTS] = MAX_COLORS + 1;
  P[SOLVE.SPIN_US] = SPIN_MICROSECONDS;
  // The relax passes' support rows (solver/support.ts): which way is down, and the cosine past which a row is one.
  downwardInto(g, P, SOLVE.DOWN_X);
  P[SOLVE.SUPPORT_COS] = SUPPORT_COS;
  P[SOLVE.GX] = g[0]!;
  P[SOLVE.GY] = g[1]!;
  P[SOLVE.GZ] = g[2]!;
  P[SOLVE.DYNAMIC] = BodyType.Dynamic;
  P[SOLVE.MEASURE_APPROACH] = 1;
  const blocks = solveColoredBlocks2D(plan, buf.count, true);
  if (s.claim.length < blocks) s.claim = grown(s.claim, Math.max(blocks, 2 * s.claim.length));
  A[SOLVE.CLAIM] = s.claim;
  const site = 'contactSolverSystem#colors';
  const parallel = pool?.usable() === true && (!pool.adaptive || pool.chooser.choose(site));
  const t0 = nowMs();
  s.bar[0] = 0;
  s.bar[1] = 0;
  s.bar[2] = 0;
  s.claim.fill(0, 0, blocks);
  if (parallel) {
    plan[PLAN.THREADS] = pool.threads;
    pool.run('contactSolverSystem', solveColored2D, A, P, pool.threads, null);
  } else {
    plan[PLAN.THREADS] = 1;
    solveColored2D(A, P, null, 0, 1, 0, KERNEL_HELPERS);
  }
  if (pool?.adaptive === true) pool.chooser.record(site, parallel, nowMs() - t0, np);
  s.pending = true;
}

/**
 * The colours of this step's coloured substeps, for the restitution stage (solver/stages-threads.ts).
 * @category Collision
 */
export interface ColoredPlan {
  /** The packed rows, colour by colour (solver/contact-pack-2d.ts), shared. */
  pack: Float64Array;
  /** The plan (solveColored2D's layout: 3 threads, 4 colours C, 8 rows packed, PLAN_HEAD + c colour c's first block), shared. */
  plan: Int32Array;
  /** The blocks' first pack rows (block j: bounds[j] .. bounds[j + 1] - 1), shared. */
  bounds: Int32Array;
  /** Each pack row's two bodies' solver state offsets (two a row), shared. */
  pair: Int32Array;
  /** Each pack row's row in the contact buffer, shared. */
  row: Int32Array;
  /** The barrier's four Int32 slots, shared (slot 3 free for the restitution stage's count). */
  bar: Int32Array;
  /** Claim flags, a block each (shared; the restitution stage may grow it, and zeroes what it uses). */
  claim: Int32Array;
}

/**
 * The plan of this step's coloured substeps, once (the next call returns null), or null when this
 * step's substeps did not run by colours.
 * @category Collision
 */
export function coloredPlan(world: PhysicsWorld): ColoredPlan | null {
  const s = world.scratch.coloring;
  if (s === undefined || !s.pending) return null;
  s.pending = false;
  return s;
}

/**
 * Whether the calling thread may block in Atomics.wait (not a browser's main thread).
 * @category Collision
 */
export function callerMayWait(): boolean {
  return mayWait();
}
