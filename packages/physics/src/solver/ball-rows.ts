/**
 * The ball contacts' rows of the contact solver (solver/contact-solver.ts): the rows between balls
 * (2D discs and 3D spheres), and between a ball and a segment or the boundary box. Each function here
 * is one of the solver's named stages for these rows; the solver calls them through the table of
 * solver/row-families.ts, where `installBalls` (collision/install-balls.ts) puts them when a program first
 * makes a ball, so a program of shapes and joints only does not bring them into its bundle.
 *
 * Stages, in the solver's order: `gatherBallBodies` (the rows' bodies into the solver's list); `prepareBallRows` (combined material, effective masses, tangent
 * basis, last step's impulses: warm start); `approachBallRows` (the impact stage of solver/impacts.ts,
 * the coloured solve's plan on a threaded 2D world, the approach speeds for restitution, the soft
 * coefficients); `planBallRows` (the relax sweep's first rows, the coloured substeps when they take the
 * step); per substep `warmStartBallRows` and `solveBallRows` (with soft bias, then relaxed) and
 * `endBallSubstep`; `ballRestitution`; `storeBallRows` (the impulses kept for the next step's warm start).
 * The rows' preparation is in solver/ball-prepare.ts, their sweeps in solver/ball-sweeps.ts.
 */

import { type ContactBuffer, storeWarmStart } from '../collision/contacts.js';
import type { PhysicsWorld } from '../world/options.js';
import { measureApproach, prepareContacts } from './ball-prepare.js';
import { solve2D, solve3D, warmStart2D, warmStart3D } from './ball-sweeps.js';
import { BS2_STRIDE, BS3_STRIDE } from './body-state-layout.js';
import { solveColoredSubsteps, startStripPlan, useColoredSolve } from './coloring.js';
import { ballContactHertz, ballContactPushSpeed, ballStickSpeed, contactLength, makeSoftInto } from './contact-scale.js';
import { applyImpacts, releaseImpactedRows } from './impacts.js';
import { joinSolverBodies } from './solver-bodies.js';
import { restitutionStage, storeWarmStartOnThreads } from './stages-threads.js';
import { downward3Into, downwardInto, markFirstRelaxRows, relaxOrderInto } from './support.js';

/**
 * Stage 1 for the ball rows: gives the moving bodies of the rows of `buf` solver indices from `count` on
 * and writes each row's indices to `buf.ia` and `buf.ib` (solver/solver-bodies.ts joinSolverBodies, as
 * every row family: 0, the static row, for a wall, plane or segment on side a; side b is always a
 * moving ball). Returns the new solver body count.
 * @category Collision
 */
export function gatherBallBodies(world: PhysicsWorld, buf: ContactBuffer, count: number): number {
  return joinSolverBodies(world.collision, buf.a, buf.b, buf.ia, buf.ib, buf.count, count);
}

/**
 * Stage 2 for the ball rows: prepares this step's rows (prepareContacts) with the friction stick
 * speed of the balls' size (solver/contact-scale.ts).
 * @category Collision
 */
export function prepareBallRows(world: PhysicsWorld, buf: ContactBuffer): void {
  prepareContacts(world, buf, ballStickSpeed(world.collision.settings, contactLength(world, buf)));
}

/**
 * Stages 3 and 4 for the ball rows, after the other rows are prepared: a threaded 2D world starts
 * planning the coloured solve (solver/coloring.ts), the impact stage runs (solver/impacts.ts), the
 * approach speeds are measured (unless the coloured solve takes the step and measures them on its
 * threads), and the soft coefficients of the substep `hs` (s) are set. `others` is true when joints or
 * shape manifolds share the solve. Returns true when the coloured solve takes the step.
 * @category Collision
 */
export function approachBallRows(world: PhysicsWorld, buf: ContactBuffer, others: boolean, hs: number): boolean {
  const is2D = world.dimensions === 2;
  if (is2D) startStripPlan(world, buf, others);
  applyImpacts(world, buf);
  const colored = is2D && useColoredSolve(world, buf, others);
  if (!colored) measureApproach(world, buf);
  const st = world.collision.settings;
  const length = contactLength(world, buf);
  // Softness (Box2D b2MakeSoft): stiffness from the balls' size, capped at the substep rate
  // (solver/contact-scale.ts); contacts against infinite mass twice as stiff.
  const hertz = ballContactHertz(st, length, hs);
  const sp = solveParams;
  sp[0] = hs;
  sp[1] = ballContactPushSpeed(st, length);
  makeSoftInto(sp, 4, hertz, st.contactDampingRatio, hs);
  makeSoftInto(sp, 7, 2 * hertz, st.contactDampingRatio, hs);
  return colored;
}

/**
 * Stage 5's start for the ball rows, after the joints are prepared: which way is down and which rows
 * the relax sweep takes first (solver/support.ts); then the coloured substeps when `colored`
 * (solver/coloring.ts), else the impacted rows are released (solver/impacts.ts).
 * @category Collision
 */
export function planBallRows(world: PhysicsWorld, buf: ContactBuffer, colored: boolean, hs: number): void {
  const cs = world.collision;
  const is2D = world.dimensions === 2;
  const sp = solveParams;
  downwardInto(world.gravity, sp, 2);
  if (!is2D) downward3Into(world.gravity, sp, 10);
  const first = markFirstRelaxRows(
    buf.ia,
    buf.ib,
    buf.nx,
    buf.ny,
    is2D ? null : buf.nz,
    buf.count,
    cs.solverBodyCount,
    cs.bodyState,
    is2D ? BS2_STRIDE : BS3_STRIDE,
    sp,
    is2D ? 2 : 10,
  );
  if (relaxOrder.length < 2 * buf.count) relaxOrder = new Int32Array(Math.max(2 * buf.count, 2 * relaxOrder.length));
  relaxCount = relaxOrderInto(first, buf.ia, buf.count, relaxOrder);
  // The coloured solve takes the impacted rows out after it plans (solver/coloring.ts), the others now.
  if (colored) solveColoredSubsteps(world, buf, hs, [sp[4]!, sp[5]!, sp[6]!, sp[7]!, sp[8]!, sp[9]!], sp[1]!);
  else releaseImpactedRows(buf);
}

/**
 * Applies every ball row's accumulated impulse (Box2D v3 warm start, once per substep).
 * @category Collision
 */
export function warmStartBallRows(world: PhysicsWorld, buf: ContactBuffer): void {
  if (world.dimensions === 2) warmStart2D(world.collision, buf);
  else warmStart3D(world.collision, buf);
}

/**
 * One Gauss-Seidel sweep over the ball rows: with soft bias if `useBias`, else the relax sweep.
 * @category Collision
 */
export function solveBallRows(world: PhysicsWorld, buf: ContactBuffer, useBias: boolean): void {
  if (world.dimensions === 2) solve2D(world.collision.bodyState, buf, useBias, solveParams, relaxOrder, relaxCount);
  else solve3D(world.collision.bodyState, buf, useBias, solveParams, relaxOrder, relaxCount);
}

/**
 * End of a substep for the ball rows: each row's accumulated impulse is what this substep delivered
 * (warm start plus corrections), added to its total.
 * @category Collision
 */
export function endBallSubstep(buf: ContactBuffer): void {
  const TOT = buf.totalNormalImpulse,
    LN = buf.normalImpulse;
  for (let i = 0, n = buf.count; i < n; i++) TOT[i] = TOT[i]! + LN[i]!;
}

/**
 * Stage 6 for the ball rows: the step's impulses are added up and the rows bounce, by the one
 * definition of solver/restitution.ts (solver/stages-threads.ts restitutionStage): a row that carried an
 * impulse takes part; one that bounces must leave with v_n >= -e v_impact (v_impact: the start-of-step
 * speed plus gravity across the speculative gap), the others must not approach; `restitutionIterations`
 * passes solve these together (coupled bounces in a dense pile share the rebound), each rebound within
 * Poisson's cap.
 * @category Collision
 */
export function ballRestitution(world: PhysicsWorld, buf: ContactBuffer): void {
  const IMP = buf.impulse,
    TOT = buf.totalNormalImpulse;
  for (let i = 0, n = buf.count; i < n; i++) IMP[i] = IMP[i]! + TOT[i]!;
  restitutionStage(world, buf);
}

/**
 * Keeps the step's ball rows for the next step's warm start, if `onThreads` on a worker of a threaded
 * 2D world while the step finishes (solver/stages-threads.ts); returns the contact buffer the next step fills.
 * @category Collision
 */
export function storeBallRows(world: PhysicsWorld, buf: ContactBuffer, onThreads: boolean): ContactBuffer {
  return (onThreads ? storeWarmStartOnThreads(world, buf) : null) ?? storeWarmStart(world.collision.cache, buf);
}

/**
 * Scratch of one contact solve (solveContacts), read by solve2D and solve3D: [0] the substep hs (s),
 * [1] the push-out speed cap (m/s), [2, 3] the unit vector along gravity (2D support rows; (0, 0)
 * without gravity), [4, 5, 6] the soft coefficients of contacts between movable bodies (bias rate
 * 1/s, mass scale, impulse scale), [7, 8, 9] those of contacts against infinite mass, [10, 11, 12]
 * the unit vector along gravity in 3D ((0, 0, 0) without gravity). The doubles pass
 * through this, not as arguments or object fields: V8 boxed (allocated) every double passed to a
 * sweep it did not inline, and each step made two coefficient objects and a direction array. Not world state.
 */
const solveParams = new Float64Array(13);

/** The relax sweep's row order of the step, its first `relaxCount` entries (solver/support.ts relaxOrderInto). Not world state. */
let relaxOrder = new Int32Array(64);
/** The length of the step's relax order. Not world state. */
let relaxCount = 0;
