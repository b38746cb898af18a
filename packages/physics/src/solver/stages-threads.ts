/**
 * The contact solver's per-body and per-row stages beside the coloured substeps (solver/coloring.ts)
 * and the rows' preparation, each one range kernel (solver/stages-kernel.ts) run on a 2D world's threads
 * when that pays and inline on the calling thread otherwise, and inline in 3D (one code path for both):
 *
 * - `gatherFillStage`: the solver rows of the step's bodies, 2D and 3D (gatherBodies' fill,
 *   solver/contact-solver.ts), a range of bodies a thread;
 * - `approachStage`: measureApproach (2D and 3D), a range of rows a thread;
 * - `finishStage`: finishBodies, 2D and 3D (velocities, positions and angles back to the components; the
 *   deepest overlap left) and containInBoundary, a range of bodies and of rows a thread;
 * - `restitutionStage`: the ball rows' restitution, its passes colour by colour after a coloured solve;
 * - `storeWarmStartOnThreads`: the warm-start table of the step's contacts, built on a worker while
 *   the calling thread finishes the step (the same table).
 *
 * The first three do each body's or row's arithmetic on its own, so the state after a step is the same
 * to the bit whichever thread runs a body or row. The restitution stage takes its coloured path in
 * every step whose substeps ran by colours (on the threads, or inline on one thread without a pool or
 * when the adaptive pool prefers it): its passes then visit the rows colour by colour (rows of one
 * colour share no movable body, so a colour is split over the threads without changing any result)
 * instead of in buffer order, like the coloured substeps. Such a step gives the same bits on 1, 2 or n
 * threads (solver/coloring.ts says when a step takes that path).
 *
 * A stage goes to the threads only in a 2D world with a thread pool, with at least
 * `stageThreading.minPerThread` bodies or rows a thread, every array it touches on shared memory (the
 * collision state's inverse masses, body types and impact corrections, and the contact buffers, are
 * moved there the first time), and when the adaptive pool finds the threads faster (threads/adaptive.ts);
 * otherwise its kernel runs inline over every body or row.
 */

import { type ContactBuffer, reserveWarmStartTable, swapWarmStartRows, warmStartArguments } from '../collision/contacts.js';
import { BodyType, type CollisionState } from '../collision/state.js';
import { nowMs } from '../threads/adaptive.js';
import type { Kernel, KernelArray } from '../threads/kernel-types.js';
import { MAX_POOL_PARTS, runOnPool } from '../threads/parallel.js';
import { isShared, sharedCopy, sharedFloat64, sharedMemoryAvailable, type ThreadPool } from '../threads/pool.js';
import { reportNonFinite } from '../world/errors.js';
import type { PhysicsWorld } from '../world/options.js';
import type { SolverStageScratch } from '../world/scratch.js';
import { IMPACT_STRIDE } from './body-state-layout.js';
import { approachArguments, callerMayWait, coloredPlan, grown, SPIN_MICROSECONDS, shareContactBuffer } from './coloring.js';
import { KERNEL_HELPERS } from './kernel-helpers.js';
import * as APPROACH from './slots/approach.js';
import * as PLAN from './slots/colored-plan.js';
import * as FINISH from './slots/finish-bodies.js';
import * as GATHER from './slots/gather-fill.js';
import * as RESTITUTION from './slots/restitution.js';
import {
  approachSpeeds,
  finishBodies,
  gatherFill,
  restitutionBlocks,
  restitutionColored,
  restitutionRows,
  restitutionTargets,
} from './stages-kernel.js';
import { warmStartTable } from './warm-start-kernel.js';

/**
 * Tuning and counters of the threaded solver stages (every world of the process). `minPerThread`:
 * fewest bodies or contact rows a thread for a stage to go to the threads (integer >= 1; default 8192:
 * these stages do little a body or row, so only large worlds gain from splitting them); tests
 * lower it to run the kernels on small worlds. `runs`: stages run by a kernel (on the threads, or on
 * one thread where the adaptive pool chose so), `bouncing`: rows the restitution kernel found bouncing,
 * both summed since the process started (for tests and the bench).
 * @category Collision
 */
export const stageThreading = { minPerThread: 8192, runs: 0, bouncing: 0 };

/** The world's kernel argument lists and parameters and deepest-overlap slots (world/scratch.ts), made on first use. */
function scratch(world: PhysicsWorld): SolverStageScratch {
  let s = world.scratch.solverStages;
  if (s === undefined) {
    const deepest = sharedMemoryAvailable() ? sharedFloat64(MAX_POOL_PARTS) : new Float64Array(MAX_POOL_PARTS);
    s = { arrays: [], params: new Float64Array(24), deepest };
    world.scratch.solverStages = s;
  }
  return s;
}

/** Moves the collision state's per-entity arrays the kernels read onto shared memory. */
function shareState(cs: CollisionState): void {
  cs.bodyType = sharedCopy(cs.bodyType);
  cs.invMass = sharedCopy(cs.invMass);
  cs.invInertia = sharedCopy(cs.invInertia);
  cs.bodyImpact = sharedCopy(cs.bodyImpact);
}

/**
 * The world's stage scratch (`scratch`) with its argument list emptied, for a per-body or per-row stage
 * run on `pool` (null: on the calling thread): with a pool, the collision state's arrays and `buf`'s
 * rows (when not null) are first moved onto shared memory, where the workers can read them.
 */
function stageScratch(world: PhysicsWorld, pool: ThreadPool | null, buf: ContactBuffer | null): SolverStageScratch {
  if (pool !== null) {
    shareState(world.collision);
    if (buf !== null) shareContactBuffer(buf);
  }
  const s = scratch(world);
  s.arrays.length = 0;
  return s;
}

/** The world's pool if a 2D stage of `n` elements may go to its threads (see the file's header), else null. */
function poolFor(world: PhysicsWorld, n: number): ThreadPool | null {
  const pool = world.threadPool;
  if (pool === null || world.dimensions !== 2 || n < stageThreading.minPerThread * pool.threads) return null;
  if (!isShared(world.collision.bodyState) || !isShared(world.collision.bodyExtra)) return null;
  return pool;
}

/** Whether a runOnPool call ran its kernel (not null); counts it. */
function ran(result: number | null): result is number {
  if (result === null) return false;
  stageThreading.runs++;
  return true;
}

/** Whether every array of `arrays` is on shared memory (a component store may not be, e.g. not allocated yet). */
function allShared(arrays: readonly KernelArray[]): boolean {
  for (let i = 0; i < arrays.length; i++) if (!isShared(arrays[i]!)) return false;
  return true;
}

/**
 * Runs `kernel` over `n` elements on `pool`'s threads when the pool takes it (runOnPool: enough
 * elements a thread, every array shared, the adaptive choice), else inline on the calling thread over
 * all of them (range 0 .. n, part 0): the same kernel either way. Returns its result.
 */
function runStage(pool: ThreadPool | null, kernel: Kernel, A: KernelArray[], P: Float64Array, n: number, ids: Int32Array | null): number {
  if (pool !== null && allShared(A)) {
    const result = runOnPool(pool, 'contactSolverSystem', kernel, A, P, n, ids, stageThreading.minPerThread);
    if (ran(result)) return result;
  }
  return kernel(A, P, ids, 0, n, 0, KERNEL_HELPERS);
}

/**
 * Puts the bodies' motion arrays into a stage kernel's arrays `A` at a slot module's places, which both
 * such modules (slots/gather-fill.ts, slots/finish-bodies.ts) keep in this order: position x and y,
 * velocity x and y, angular velocity z from slot `xy` on, and position z, velocity z, angular velocity
 * x and y from slot `z` on.
 */
function motionArrays(world: PhysicsWorld, A: KernelArray[], xy: number, z: number): void {
  const c = world.components;
  A[xy] = c.Position.x;
  A[xy + 1] = c.Position.y;
  A[xy + 2] = c.Velocity.x;
  A[xy + 3] = c.Velocity.y;
  A[xy + 4] = c.AngularVelocity.z;
  A[z] = c.Position.z;
  A[z + 1] = c.Velocity.z;
  A[z + 2] = c.AngularVelocity.x;
  A[z + 3] = c.AngularVelocity.y;
}

/**
 * gatherBodies' fill of the solver rows of solver bodies 1 .. count - 1 (solver/contact-solver.ts;
 * kernel gatherFill, 2D or 3D), on a 2D world's threads when it pays, else on the calling thread; `pushed` 1
 * when joints are in the step (every body counts as pushed).
 * @throws Error naming contactSolverSystem if a worker thread failed.
 * @category Collision
 */
export function gatherFillStage(world: PhysicsWorld, count: number, pushed: number): void {
  const pool = poolFor(world, count - 1);
  const cs = world.collision,
    c = world.components;
  const s = stageScratch(world, pool, null),
    A = s.arrays,
    P = s.params;
  motionArrays(world, A, GATHER.PX, GATHER.PZ);
  A[GATHER.FX] = c.Force.x;
  A[GATHER.FY] = c.Force.y;
  A[GATHER.FZ] = c.Force.z;
  A[GATHER.BODY_TYPE] = cs.bodyType;
  A[GATHER.INV_MASS] = cs.invMass;
  A[GATHER.INV_INERTIA] = cs.invInertia;
  A[GATHER.BODY_STATE] = cs.bodyState;
  A[GATHER.BODY_EXTRA] = cs.bodyExtra;
  const h = world.h,
    g = world.gravity;
  P[GATHER.H] = h;
  P[GATHER.GX_H] = g[0]! * h;
  P[GATHER.GY_H] = g[1]! * h;
  P[GATHER.GZ_H] = g[2]! * h;
  P[GATHER.THREE_D] = world.dimensions === 3 ? 1 : 0;
  P[GATHER.PUSHED] = pushed;
  P[GATHER.DYNAMIC] = BodyType.Dynamic;
  P[GATHER.KINEMATIC] = BodyType.Kinematic;
  runStage(pool, gatherFill, A, P, count - 1, cs.solverBodies.subarray(1, count));
}

/**
 * measureApproach of the world's contact rows (solver/ball-prepare.ts; kernel approachSpeeds, 2D or 3D),
 * on the world's threads when it pays (2D), else on the calling thread.
 * @throws Error naming contactSolverSystem if a worker thread failed.
 * @category Collision
 */
export function approachStage(world: PhysicsWorld, buf: ContactBuffer): void {
  const n = buf.count;
  const pool = poolFor(world, n);
  const cs = world.collision;
  const s = stageScratch(world, pool, buf),
    A = s.arrays,
    P = s.params;
  approachArguments(cs, buf, A);
  const g = world.gravity;
  P[APPROACH.GX] = g[0]!;
  P[APPROACH.GY] = g[1]!;
  P[APPROACH.GZ] = g[2]!;
  P[APPROACH.DYNAMIC] = BodyType.Dynamic;
  P[APPROACH.BASE] = 0;
  P[APPROACH.THREE_D] = world.dimensions === 3 ? 1 : 0;
  runStage(pool, approachSpeeds, A, P, n, null);
}

/**
 * storeWarmStart (contacts.ts) of a 2D world's contact rows with the hash table built on a worker
 * (ThreadPool.start, kernel warmStartTable: the same table to the slot) while the calling thread
 * finishes the step: the rows are swapped into the cache at once, and the table is complete once the
 * pool joins, which its next run or start does, prepareContacts does before it reads the table, and
 * `step` does before it returns. Returns the buffer to fill next (as storeWarmStart), or null when the
 * stage stays on one thread (too few rows, no usable worker; the caller's storeWarmStart then runs).
 * @category Collision
 */
export function storeWarmStartOnThreads(world: PhysicsWorld, buf: ContactBuffer): ContactBuffer | null {
  const n = buf.count;
  const pool = poolFor(world, n);
  if (pool === null || pool.threads < 2 || !pool.usable()) return null;
  const cache = world.collision.cache;
  shareContactBuffer(buf);
  pool.join(); // nothing may still be writing the table it replaces
  reserveWarmStartTable(cache, n, true);
  const s = scratch(world),
    A = s.arrays,
    P = s.params;
  warmStartArguments(cache, buf, A, P);
  pool.start('contactSolverSystem', warmStartTable, A, P, 1);
  stageThreading.runs++;
  return swapWarmStartRows(cache, buf);
}

/**
 * finishBodies (solver/contact-solver.ts; kernel finishBodies, 2D or 3D) with containInBoundary
 * when the boundary box is on: the solver bodies' velocities, positions and angles (3D: orientations)
 * back to the components and the bodies put back in the box, a range of bodies a thread, and the
 * deepest overlap left into `cs.stats.maxOverlap`, a range of rows a thread; on a 2D world's threads
 * when it pays, else on the calling thread.
 * @throws NonFiniteStateError (stage 'collide') if a written position or velocity is not finite (the
 *   bodies are then already put back in the box).
 * @throws Error naming contactSolverSystem if a worker thread failed.
 * @category Collision
 */
export function finishStage(world: PhysicsWorld, buf: ContactBuffer): void {
  const cs = world.collision,
    count = cs.solverBodyCount;
  const pool = poolFor(world, count - 1);
  const c = world.components;
  const s = stageScratch(world, pool, buf),
    A = s.arrays,
    P = s.params,
    out = s.deepest;
  out.fill(0);
  motionArrays(world, A, FINISH.PX, FINISH.PZ);
  A[FINISH.ANGLE] = c.Angle.value;
  A[FINISH.BODY_TYPE] = cs.bodyType;
  A[FINISH.BODY_STATE] = cs.bodyState;
  A[FINISH.BODY_EXTRA] = cs.bodyExtra;
  A[FINISH.BODY_IMPACT] = cs.bodyImpact;
  A[FINISH.RADIUS] = c.Ball.radius;
  A[FINISH.RESTITUTION] = c.Material.restitution;
  A[FINISH.DEEPEST] = out;
  A[FINISH.IA] = buf.ia;
  A[FINISH.IB] = buf.ib;
  A[FINISH.SEPARATION] = buf.separation;
  A[FINISH.NX] = buf.nx;
  A[FINISH.NY] = buf.ny;
  A[FINISH.QX] = c.Orientation.x;
  A[FINISH.QY] = c.Orientation.y;
  A[FINISH.QZ] = c.Orientation.z;
  A[FINISH.QW] = c.Orientation.w;
  A[FINISH.NZ] = buf.nz;
  const list = cs.solverBodies,
    box = cs.boundary;
  const fh = (-0.5 * world.h * world.h) / cs.settings.solverSubsteps,
    g = world.gravity;
  P[FINISH.FREE_X] = g[0]! * fh;
  P[FINISH.FREE_Y] = g[1]! * fh;
  P[FINISH.FREE_Z] = g[2]! * fh;
  P[FINISH.DYNAMIC] = BodyType.Dynamic;
  P[FINISH.IMPACT_STRIDE] = IMPACT_STRIDE;
  P[FINISH.CONTAIN] = box.enabled ? 1 : 0;
  P[FINISH.MIN_X] = box.min[0]!;
  P[FINISH.MIN_Y] = box.min[1]!;
  P[FINISH.MAX_X] = box.max[0]!;
  P[FINISH.MAX_Y] = box.max[1]!;
  P[FINISH.MIN_Z] = box.min[2]!;
  P[FINISH.MAX_Z] = box.max[2]!;
  P[FINISH.BOX_RESTITUTION] = box.restitution;
  P[FINISH.GX] = g[0]!;
  P[FINISH.GY] = g[1]!;
  P[FINISH.GZ] = g[2]!;
  P[FINISH.THREE_D] = world.dimensions === 3 ? 1 : 0;
  P[FINISH.ROWS] = buf.count;
  P[FINISH.BODIES] = count - 1;
  const check = runStage(pool, finishBodies, A, P, count - 1, list.subarray(1, count));
  if (check - check !== 0) reportNonFinite(world, list.subarray(1, count), 'collide');
  // The deepest overlap left: one slot a thread, the least of them (0 where a thread had no rows).
  let deepest = 0;
  for (let k = 0; k < out.length; k++) if (out[k]! < deepest) deepest = out[k]!;
  cs.stats.maxOverlap = -deepest;
}

/** restitutionStage's scratch in buffer order: the rows that take part, in row order. Not world state. */
let inOrder = new Int32Array(0);

/**
 * The ball rows' restitution stage (solver/ball-rows.ts), by the kernels restitutionTargets and
 * restitutionRows (solver/stages-kernel.ts): in a 2D world whose substeps of this step ran by colours
 * (solver/coloring.ts), restitutionColored runs its passes colour by colour on the world's threads (or
 * inline on the calling thread without a pool, or when the adaptive pool prefers it: the same results
 * either way; see the file's header); otherwise its passes run inline over the rows that take part, in
 * buffer order.
 * @throws Error naming contactSolverSystem if a worker thread failed.
 * @category Collision
 */
export function restitutionStage(world: PhysicsWorld, buf: ContactBuffer): void {
  const cs = world.collision,
    pool = world.threadPool,
    n = buf.count;
  const plan2D = coloredPlan(world);
  const colored = world.dimensions === 2 ? plan2D : null;
  if (colored !== null && pool !== null) shareContactBuffer(buf);
  const st = cs.settings;
  const s = scratch(world),
    A = s.arrays,
    P = s.params;
  A.length = 0;
  A[RESTITUTION.BODY_STATE] = cs.bodyState;
  A[RESTITUTION.IA] = buf.ia;
  A[RESTITUTION.IB] = buf.ib;
  A[RESTITUTION.NX] = buf.nx;
  A[RESTITUTION.NY] = buf.ny;
  A[RESTITUTION.NORMAL_MASS] = buf.normalMass;
  A[RESTITUTION.RESTITUTION] = buf.restitution;
  A[RESTITUTION.RELATIVE_VELOCITY] = buf.relativeVelocity;
  A[RESTITUTION.IMPACT_VELOCITY] = buf.impactVelocity;
  A[RESTITUTION.MAX_NORMAL_IMPULSE] = buf.maxNormalImpulse;
  A[RESTITUTION.TOTAL_NORMAL_IMPULSE] = buf.totalNormalImpulse;
  A[RESTITUTION.IMPULSE] = buf.impulse;
  A[RESTITUTION.NZ] = buf.nz;
  P[RESTITUTION.ROWS] = n;
  P[RESTITUTION.THRESHOLD] = st.restitutionThreshold;
  P[RESTITUTION.ELASTIC_THRESHOLD] = st.elasticRestitutionThreshold;
  P[RESTITUTION.ITERATIONS] = st.restitutionIterations;
  P[RESTITUTION.THREE_D] = world.dimensions === 2 ? 0 : 1;
  if (colored === null) {
    if (restitutionTargets(A, P, 0, n, KERNEL_HELPERS) === 0) return;
    if (inOrder.length < n) inOrder = new Int32Array(Math.max(n, 2 * inOrder.length));
    const RV = buf.relativeVelocity;
    let taking = 0;
    for (let i = 0; i < n; i++) if (RV[i]! >= 0) inOrder[taking++] = i;
    A[RESTITUTION.ROW] = inOrder;
    for (let it = 0; it < st.restitutionIterations; it++) restitutionRows(A, P, 0, taking);
    return;
  }
  const blocks = restitutionBlocks(colored.plan, n, st.restitutionIterations);
  if (colored.claim.length < blocks) colored.claim = grown(colored.claim, Math.max(blocks, 2 * colored.claim.length));
  A[RESTITUTION.PLAN] = colored.plan;
  A[RESTITUTION.COUNTERS] = colored.bar;
  A[RESTITUTION.BOUNDS] = colored.bounds;
  A[RESTITUTION.ROW] = colored.row;
  A[RESTITUTION.CLAIM] = colored.claim;
  P[RESTITUTION.MAY_WAIT] = callerMayWait() ? 1 : 0;
  P[RESTITUTION.SPIN_US] = SPIN_MICROSECONDS;
  const bar = colored.bar,
    plan = colored.plan;
  const site = 'contactSolverSystem#restitution';
  const parallel = pool !== null && pool.threads <= 16 && pool.usable() && (!pool.adaptive || pool.chooser.choose(site));
  const t0 = nowMs();
  bar.fill(0);
  colored.claim.fill(0, 0, blocks);
  if (parallel) {
    plan[PLAN.THREADS] = pool.threads;
    pool.run('contactSolverSystem', restitutionColored, A, P, pool.threads, null);
  } else {
    plan[PLAN.THREADS] = 1;
    restitutionColored(A, P, null, 0, 1, 0, KERNEL_HELPERS);
  }
  if (pool?.adaptive === true) pool.chooser.record(site, parallel, nowMs() - t0, n);
  stageThreading.runs++;
  stageThreading.bouncing += bar[3]!;
}
