/**
 * The 2D ball contacts' soft substeps on the world's threads, by graph colouring (Box2D v3's approach,
 * Catto, "Solver2D" and Box2D v3.0 solver.c / constraint_graph.c).
 *
 * The step's contact rows are coloured greedily, in buffer order, so that no two rows of one colour
 * share a body that can move under an impulse (a solver body with inverse mass or inertia; the static
 * world and kinematic bodies are shared freely: rows only read them). Up to `MAX_COLORS` colours; a row
 * that finds none free goes to an overflow colour that one thread solves alone. The rows are packed
 * colour by colour (contact-pack2d.ts, buffer order within a colour) and the whole substep loop
 * (gravity, warm start, biased passes, positions, relax passes) runs as one kernel on every thread:
 * each colour's rows are split into one contiguous range a thread, the bodies into ranges for the
 * per-body stages, and the threads meet at a barrier (Atomics) after every colour and stage.
 *
 * Rows of one colour touch disjoint movable bodies, so how a colour is split does not change any
 * result: the coloured solve gives the same bits on 1, 2 or n threads, and the adaptive pool may run
 * it on one thread when the threads do not pay (threads/adaptive.ts) without changing the state. Its
 * impulse order (colour by colour) differs from the one-thread world's (buffer order), so a world
 * made with `threads: n > 1` whose step takes this path follows a slightly different trajectory than
 * the same world with `threads: 1`: both are deterministic, and equal for a given thread count.
 *
 * Taken only in 2D worlds with a thread pool, no joints and no shape manifolds in the step (they
 * solve between the contacts within each pass), and at least `CollisionSettings.coloredSolveMinRows` rows (default 16384).
 */

import type { PhysicsWorld } from '../world.js';
import type { ContactBuffer } from './contacts.js';
import { BodyType, type CollisionState } from './state.js';
import type { KernelArray } from '../threads/kernel-types.js';
import { solveColored2D } from './contact-colors-kernel.js';
import { KERNEL } from '../threads/kernels.js';
import { nowMs } from '../threads/adaptive.js';
import { isShared, sharedLike } from '../threads/pool.js';
import { PACK_STRIDE } from './contact-pack2d.js';

/**
 * Moves every typed array of a contact buffer that is not on a SharedArrayBuffer onto one (same
 * contents), so the pool's workers can read and write it (the solver and its threaded stages).
 */
export function shareContactBuffer(buf: ContactBuffer): void {
  const rec = buf as unknown as Record<string, unknown>;
  for (const key of Object.keys(rec)) {
    const a = rec[key];
    if (!ArrayBuffer.isView(a) || a instanceof DataView || isShared(a)) continue;
    const copy = sharedLike(a as KernelArray, (a as KernelArray).length);
    copy.set(a as never);
    rec[key] = copy;
  }
}

/** Colours before the overflow colour (bits of a 32-bit mask a body). */
export const MAX_COLORS = 32;

/** Int32 slots of the plan before the colour starts (see solveColored2D). */
const PLAN_HEAD = 8;

interface ColorScratch {
  pack: Float64Array; dyn: Uint8Array; plan: Int32Array; bar: Int32Array; params: Float64Array;
  color: Uint8Array; mask: Uint32Array; arrays: KernelArray[];
  /** Each thread's first pack slot of every colour (MAX_COLORS + 1 a thread; the packing stage's cursors). */
  offsets: Int32Array;
  /** Rows a colour, the colours' first rows, the next free row of each (MAX_COLORS + 2 each). */
  counts: Int32Array; start: Int32Array; next: Int32Array;
  /** Whether this step's substeps ran by colours and the restitution stage has not used the plan yet. */
  pending: boolean;
}

const scratchOf = new WeakMap<CollisionState, ColorScratch>();

function scratch(cs: CollisionState, rows: number, bodies: number): ColorScratch {
  let s = scratchOf.get(cs);
  if (s === undefined) {
    s = {
      pack: new Float64Array(new SharedArrayBuffer(8 * PACK_STRIDE * 1024)), dyn: new Uint8Array(new SharedArrayBuffer(1024)),
      plan: new Int32Array(new SharedArrayBuffer(4 * (PLAN_HEAD + MAX_COLORS + 2))), bar: new Int32Array(new SharedArrayBuffer(4 * 4)),
      params: new Float64Array(16), color: new Uint8Array(new SharedArrayBuffer(1024)), mask: new Uint32Array(1024), arrays: [],
      offsets: new Int32Array(new SharedArrayBuffer(4 * (MAX_COLORS + 1) * 16)),
      counts: new Int32Array(MAX_COLORS + 2), start: new Int32Array(MAX_COLORS + 2), next: new Int32Array(MAX_COLORS + 2),
      pending: false,
    };
    scratchOf.set(cs, s);
  }
  if (s.pack.length < rows * PACK_STRIDE) s.pack = sharedLike(s.pack, Math.max(rows * PACK_STRIDE, 2 * s.pack.length));
  if (s.color.length < rows) s.color = sharedLike(s.color, Math.max(rows, 2 * s.color.length));
  if (s.dyn.length < bodies) s.dyn = sharedLike(s.dyn, Math.max(bodies, 2 * s.dyn.length));
  if (s.mask.length < bodies) s.mask = new Uint32Array(Math.max(bodies, 2 * s.mask.length));
  return s;
}

/**
 * Whether the step's 2D ball contacts go through the coloured solve (see the file's header): a pool,
 * no joints or manifolds (`others` true when there are), shared solver state, enough rows.
 */
export function useColoredSolve(world: PhysicsWorld, buf: ContactBuffer, others: boolean): boolean {
  // A plan left by a step that stopped before its restitution stage is not this step's.
  const old = scratchOf.get(world.collision);
  if (old !== undefined) old.pending = false;
  const pool = world.threadPool;
  if (pool === null || others || world.dimensions !== 2 || pool.threads > 16) return false;
  const cs = world.collision;
  // The same threshold for every thread count, so worlds with 2, 3 or n threads take the same path
  // each step and end in the same state.
  if (!(buf.count >= cs.settings.coloredSolveMinRows)) return false;
  return isShared(cs.bodyState) && isShared(cs.bodyExtra);
}

/**
 * Colours the rows of `buf` (solver indices, masses and impulses prepared) greedily in buffer order;
 * fills the plan's colour starts and, for the kernel's packing stage, each of `parts` row ranges'
 * first pack slot of every colour (`offsets`, MAX_COLORS + 1 a range: the range's rows of a colour
 * follow the previous ranges' rows of that colour, so the pack is in buffer order within each colour
 * however many threads pack it). Returns the rows to pack.
 */
function colorRows(cs: CollisionState, buf: ContactBuffer, s: ColorScratch, parts: number): number {
  const n = buf.count, bodies = cs.solverBodyCount;
  const IA = buf.ia, IB = buf.ib, NM = buf.normalMass, TM = buf.tangentMass, LN = buf.normalImpulse, LT = buf.tangentImpulse1;
  const sb = cs.bodyState, mask = s.mask, color = s.color, plan = s.plan;
  const W = MAX_COLORS + 1, partCounts = s.offsets;
  mask.fill(0, 0, bodies);
  partCounts.fill(0, 0, parts * W);
  const counts = s.counts;
  counts.fill(0);
  for (let p = 0; p < parts; p++) {
    const lo = Math.floor((n * p) / parts), hi = Math.floor((n * (p + 1)) / parts), base = p * W;
    for (let i = lo; i < hi; i++) {
      if (NM[i] === 0 && TM[i] === 0 && LN[i] === 0 && LT[i] === 0) { color[i] = 255; continue; } // a row that can do nothing
      const a = IA[i]!, b = IB[i]!;
      // Only bodies an impulse can move take a colour's slot (the static world and kinematic bodies are read only).
      const ma = a !== 0 && (sb[a * 8 + 5]! > 0 || sb[a * 8 + 6]! > 0);
      const mb = sb[b * 8 + 5]! > 0 || sb[b * 8 + 6]! > 0;
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
  // Colour starts (the overflow colour last), then rows in buffer order within each colour.
  let used = 0;
  for (let c = 0; c < MAX_COLORS; c++) if (counts[c]! > 0) used = c + 1;
  const start = s.start;
  start.fill(0);
  let at = 0;
  for (let c = 0; c < used; c++) { start[c] = at; at += counts[c]!; }
  start[used] = at; at += counts[MAX_COLORS]!; start[used + 1] = at;
  plan[4] = used;
  for (let c = 0; c <= used + 1; c++) plan[PLAN_HEAD + c] = start[c]!;
  // Each range's first slot of each colour (slot MAX_COLORS: the overflow colour, packed after colour used - 1).
  const next = s.next;
  next.set(start);
  next[MAX_COLORS] = start[used]!;
  for (let p = 0; p < parts; p++) {
    const base = p * W;
    for (let c = 0; c < W; c++) {
      const k = partCounts[base + c]!;
      partCounts[base + c] = next[c]!;
      next[c] = next[c]! + k;
    }
  }
  // Gravity goes to the dynamic solver bodies (as integrateVelocities in solver.ts).
  const list = cs.solverBodies, type = cs.bodyType, dyn = s.dyn;
  dyn[0] = 0;
  for (let k = 1; k < bodies; k++) dyn[k] = type[list[k]!] === BodyType.Dynamic ? 1 : 0;
  return at;
}

/** Colours used by the last coloured solve of `cs` (0: none ran), for tests and the bench. */
export function lastColorCount(cs: CollisionState): number {
  const s = scratchOf.get(cs);
  return s === undefined ? 0 : s.plan[4]!;
}

/**
 * Checks the last coloured solve of `cs` (a test of the colouring, not of physics): the number of times
 * a movable solver body (inverse mass or inertia > 0) appears in two rows of one colour (the overflow
 * colour, solved by one thread, excepted), and the rows in the overflow colour. 0 conflicts is the
 * colouring's promise.
 */
export function coloringConflicts(cs: CollisionState): { conflicts: number; overflow: number; rows: number } {
  const s = scratchOf.get(cs);
  if (s === undefined) return { conflicts: 0, overflow: 0, rows: 0 };
  const plan = s.plan, C = plan[4]!, pk = s.pack, sb = cs.bodyState;
  const seen = new Map<number, number>();
  let conflicts = 0;
  for (let c = 0; c < C; c++) {
    for (let k = plan[PLAN_HEAD + c]!; k < plan[PLAN_HEAD + c + 1]!; k++) {
      for (const off of [pk[k * PACK_STRIDE]!, pk[k * PACK_STRIDE + 1]!]) {
        if (!(sb[off + 5]! > 0 || sb[off + 6]! > 0)) continue;
        if (seen.get(off) === c) conflicts++;
        seen.set(off, c);
      }
    }
  }
  return { conflicts, overflow: plan[PLAN_HEAD + C + 1]! - plan[PLAN_HEAD + C]!, rows: plan[PLAN_HEAD + C + 1]! };
}

/** Whether this thread may block in Atomics.wait (not a browser's main thread); cached. */
let mainMayWait: boolean | null = null;
function mayWait(): boolean {
  if (mainMayWait === null) {
    try { Atomics.wait(new Int32Array(new SharedArrayBuffer(4)), 0, 1, 0); mainMayWait = true; } catch { mainMayWait = false; }
  }
  return mainMayWait;
}

/**
 * Runs the step's substeps for the 2D ball contacts of `buf` by colours on the world's threads (or on
 * one thread when the adaptive pool prefers it; the same results either way), then writes the impulses
 * back to `buf` (normal, tangent, largest pass impulse, delivered total), as the one-thread loop of
 * solver.ts leaves them. `soft`: dynamic bias rate, mass scale, impulse scale, then the rigid ones.
 * @throws Error naming contactSolverSystem if a worker thread failed.
 */
export function solveColoredSubsteps(
  world: PhysicsWorld, buf: ContactBuffer, hs: number, soft: readonly number[], push: number,
): void {
  const cs = world.collision, pool = world.threadPool!;
  const st = cs.settings;
  const s = scratch(cs, buf.count, cs.solverBodyCount);
  shareContactBuffer(buf);
  const np = colorRows(cs, buf, s, pool.threads);
  const plan = s.plan, P = s.params, g = world.gravity;
  plan[0] = st.solverSubsteps; plan[1] = st.solverIterations; plan[2] = st.relaxIterations;
  plan[5] = cs.solverBodyCount; plan[6] = mayWait() ? 1 : 0; plan[7] = pool.threads;
  P[0] = 1 / hs;
  for (let k = 0; k < 6; k++) P[1 + k] = soft[k]!;
  P[7] = push; P[8] = hs; P[9] = g[0]! * hs; P[10] = g[1]! * hs; P[11] = buf.count; P[12] = MAX_COLORS + 1;
  const A = s.arrays;
  A.length = 0;
  A.push(s.pack, cs.bodyState, cs.bodyExtra, s.dyn, plan, s.bar, s.color, s.offsets,
    buf.ia, buf.ib, buf.nx, buf.ny, buf.ra, buf.rb, buf.separation, buf.normalMass, buf.tangentMass, buf.frictionBound,
    buf.normalImpulse, buf.tangentImpulse1, buf.rigidPartner, buf.maxNormalImpulse, buf.totalNormalImpulse);
  const site = 'contactSolverSystem#colors';
  const parallel = pool.usable() && (!pool.adaptive || pool.chooser.choose(site));
  const t0 = nowMs();
  s.bar[0] = 0; s.bar[1] = 0; s.bar[2] = 0;
  if (parallel) {
    plan[3] = pool.threads;
    pool.run('contactSolverSystem', KERNEL.solveColored2D, A, P, pool.threads, null);
  } else {
    plan[3] = 1;
    solveColored2D(A, P, null, 0, 1, 0);
  }
  if (pool.adaptive) pool.chooser.record(site, parallel, nowMs() - t0, np);
  s.pending = true;
}

/** The colours of this step's coloured substeps, for the restitution stage (solver-stages-threads.ts). */
export interface ColoredPlan {
  /** The packed rows, colour by colour (contact-pack2d.ts), shared. */
  pack: Float64Array;
  /** The plan (solveColored2D's layout: 3 threads, 4 colours, 8.. the colours' first rows), shared. */
  plan: Int32Array;
  /** The barrier's four Int32 slots, shared (slot 3 free for the restitution stage's count). */
  bar: Int32Array;
}

/**
 * The plan of this step's coloured substeps, once (the next call returns null), or null when this
 * step's substeps did not run by colours.
 */
export function coloredPlan(cs: CollisionState): ColoredPlan | null {
  const s = scratchOf.get(cs);
  if (s === undefined || !s.pending) return null;
  s.pending = false;
  return s;
}

/** Whether the calling thread may block in Atomics.wait (not a browser's main thread). */
export function callerMayWait(): boolean {
  return mayWait();
}
