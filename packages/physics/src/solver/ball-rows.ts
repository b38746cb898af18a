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
import type { KernelArray } from '../threads/kernel-types.js';
import type { PhysicsWorld } from '../world/options.js';
import { measureApproach, prepareContacts } from './ball-prepare.js';
import { solve2D, solve3D, warmStart2D, warmStart3D } from './ball-sweeps.js';
import { BS2_INV_MASS, BS2_STRIDE, BS2_VX, BS2_VY, BS3_INV_MASS, BS3_STRIDE, BS3_VZ } from './body-state-layout.js';
import { solveColoredSubsteps, startStripPlan, useColoredSolve } from './coloring.js';
import { ballContactHertz, ballContactPushSpeed, ballStickSpeed, contactLength } from './contact-scale.js';
import { applyImpacts, releaseImpactedRows } from './impacts.js';
import * as RESTITUTION from './slots/restitution.js';
import { withRoom } from './solver-bodies.js';
import { restitutionTargets } from './stages-kernel.js';
import { restitutionOnThreads, storeWarmStartOnThreads } from './stages-threads.js';
import { downward3Into, downwardInto, markFirstRelaxRows, relaxOrderInto } from './support.js';

/**
 * Stage 1 for the ball rows: gives the bodies of the rows of `buf` solver indices from `count` on (each
 * body once a step, marked with `solverStamp` in `solverMark`, appended to `solverBodies`) and writes
 * each row's indices to `buf.ia` and `buf.ib` (0, the static row, for a wall or segment on side a;
 * side b is always a moving ball). Returns the new solver body count.
 * @category Collision
 */
export function gatherBallBodies(world: PhysicsWorld, buf: ContactBuffer, count: number): number {
  const cs = world.collision;
  const n = buf.count;
  const mark = cs.solverMark,
    index = cs.solverIndex,
    stamp = cs.solverStamp;
  // Room for both bodies of every row, made before the loop (solver/solver-bodies.ts withRoom).
  const list = withRoom(cs.solverBodies, count + 2 * n);
  const A = buf.a,
    B = buf.b,
    IA = buf.ia,
    IB = buf.ib;
  for (let i = 0; i < n; i++) {
    const a = A[i]!,
      b = B[i]!;
    if (a === 0) {
      IA[i] = 0;
    } else {
      if (mark[a] !== stamp) {
        mark[a] = stamp;
        index[a] = count;
        list[count++] = a;
      }
      IA[i] = index[a]!;
    }
    if (mark[b] !== stamp) {
      mark[b] = stamp;
      index[b] = count;
      list[count++] = b;
    }
    IB[i] = index[b]!;
  }
  cs.solverBodies = list;
  return count;
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
  if (world.dimensions === 2) solve2D(world.collision, buf, useBias, solveParams, relaxOrder, relaxCount);
  else solve3D(world.collision, buf, useBias, solveParams, relaxOrder, relaxCount);
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
 * Stage 6 for the ball rows: the step's impulses are added up and the rows bounce (applyRestitution).
 * @category Collision
 */
export function ballRestitution(world: PhysicsWorld, buf: ContactBuffer): void {
  const IMP = buf.impulse,
    TOT = buf.totalNormalImpulse;
  for (let i = 0, n = buf.count; i < n; i++) IMP[i] = IMP[i]! + TOT[i]!;
  applyRestitution(world, buf);
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

/**
 * Writes the coefficients of a soft constraint, a spring of frequency `hertz` (Hz, >= 0) and damping
 * ratio `zeta` integrated implicitly over `h` (s), into out[at..at+2]: bias rate (1/s), mass scale and
 * impulse scale (Catto, "Soft Constraints", GDC 2011; Box2D v3 b2MakeSoft); hertz 0 gives 0, 1, 0.
 */
function makeSoftInto(out: Float64Array, at: number, hertz: number, zeta: number, h: number): void {
  if (hertz === 0) {
    out[at] = 0;
    out[at + 1] = 1;
    out[at + 2] = 0;
    return;
  }
  const omega = 2 * Math.PI * hertz;
  const a1 = 2 * zeta + h * omega;
  const a2 = h * omega * a1;
  const a3 = 1 / (1 + a2);
  out[at] = omega / a1;
  out[at + 1] = a2 * a3;
  out[at + 2] = a3;
}

/** Scratch of applyRestitution: the indices of the rows that take part, in row order. Not world state. */
let restitutionRows = new Int32Array(256);

/** Scratch of applyRestitution: restitutionTargets' arrays (the RESTITUTION slots it reads) and numbers. Not world state. */
const targetArgs: KernelArray[] = [];
const targetParams = new Float64Array(RESTITUTION.THREE_D + 1);

/**
 * Restitution, after Box2D v3 b2ApplyRestitution but solved as a small LCP rather than one pass.
 * A contact that approached faster than the threshold and carried an impulse this step must leave
 * with normal speed v_n >= -e v_impact, where v_impact is the approach speed at impact (start-of-step
 * speed plus gravity across the speculative gap); every other contact that carried an impulse must
 * not approach (v_n >= 0). `restitutionIterations` sequential-impulse passes solve these together with
 * a non-negative accumulated impulse, so coupled bounces in a dense pile share the rebound instead of
 * each contact adding its own on top of its neighbours'. A contact's rebound impulse is capped at e
 * times its compression impulse (delivered this step, plus what still stops a residual approach):
 * Poisson's hypothesis (Stronge, Impact Mechanics, 2000, ch. 2), which keeps a perfectly elastic
 * pile from creating energy.
 */
function applyRestitution(world: PhysicsWorld, buf: ContactBuffer): void {
  if (restitutionOnThreads(world, buf)) return; // after a coloured solve: by colours (solver/stages-threads.ts)
  const cs = world.collision;
  const iterations = cs.settings.restitutionIterations;
  const n = buf.count,
    sb = cs.bodyState;
  const S = world.dimensions === 2 ? BS2_STRIDE : BS3_STRIDE,
    is2D = S === BS2_STRIDE,
    im = is2D ? BS2_INV_MASS : BS3_INV_MASS;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  const NM = buf.normalMass,
    RV = buf.relativeVelocity;
  const MAXN = buf.maxNormalImpulse,
    TOT = buf.totalNormalImpulse,
    IMP = buf.impulse;
  // The rows' targets and caps (solver/stages-kernel.ts restitutionTargets, the coloured stage's first
  // unit too): relativeVelocity becomes the target speed (-1: the row takes no part), maxNormalImpulse
  // the rebound's accumulated impulse and totalNormalImpulse its cap (all spent by now). A contact that
  // closed its gap only in the last substep may still be approaching: the impulse to stop that is part
  // of its compression, so it counts toward the cap too.
  const TA = targetArgs;
  TA.length = 0;
  TA[RESTITUTION.BODY_STATE] = sb;
  TA[RESTITUTION.IA] = IA;
  TA[RESTITUTION.IB] = IB;
  TA[RESTITUTION.NX] = NX;
  TA[RESTITUTION.NY] = NY;
  TA[RESTITUTION.NZ] = NZ;
  TA[RESTITUTION.NORMAL_MASS] = NM;
  TA[RESTITUTION.RESTITUTION] = buf.restitution;
  TA[RESTITUTION.RELATIVE_VELOCITY] = RV;
  TA[RESTITUTION.IMPACT_VELOCITY] = buf.impactVelocity;
  TA[RESTITUTION.MAX_NORMAL_IMPULSE] = MAXN;
  TA[RESTITUTION.TOTAL_NORMAL_IMPULSE] = TOT;
  const TP = targetParams;
  TP[RESTITUTION.THRESHOLD] = cs.settings.restitutionThreshold;
  TP[RESTITUTION.ELASTIC_THRESHOLD] = cs.settings.elasticRestitutionThreshold;
  TP[RESTITUTION.THREE_D] = is2D ? 0 : 1;
  const bouncing = restitutionTargets(TA, TP, 0, n);
  if (bouncing === 0) return;
  // The rows that take part (a target >= 0), in row order: the passes below visit only these.
  if (restitutionRows.length < n) restitutionRows = new Int32Array(Math.max(n, 2 * restitutionRows.length));
  const rows = restitutionRows;
  let taking = 0;
  for (let i = 0; i < n; i++) if (RV[i]! >= 0) rows[taking++] = i;
  for (let it = 0; it < iterations; it++) {
    for (let k = 0; k < taking; k++) {
      const i = rows[k]!;
      const target = RV[i]!;
      const a = IA[i]! * S,
        b = IB[i]! * S;
      const nx = NX[i]!,
        ny = NY[i]!,
        nz = NZ[i]!;
      let vn = (sb[b + BS2_VX]! - sb[a + BS2_VX]!) * nx + (sb[b + BS2_VY]! - sb[a + BS2_VY]!) * ny;
      if (!is2D) vn += (sb[b + BS3_VZ]! - sb[a + BS3_VZ]!) * nz;
      const old = MAXN[i]!;
      let acc = old - NM[i]! * (vn - target);
      if (acc < 0) acc = 0;
      if (target > 0 && acc > TOT[i]!) acc = TOT[i]!;
      const dl = acc - old;
      if (dl === 0) continue;
      MAXN[i] = acc;
      IMP[i] = IMP[i]! + dl;
      const ka = sb[a + im]! * dl,
        kb = sb[b + im]! * dl;
      sb[a + BS2_VX] = sb[a + BS2_VX]! - ka * nx;
      sb[a + BS2_VY] = sb[a + BS2_VY]! - ka * ny;
      sb[b + BS2_VX] = sb[b + BS2_VX]! + kb * nx;
      sb[b + BS2_VY] = sb[b + BS2_VY]! + kb * ny;
      if (!is2D) {
        sb[a + BS3_VZ] = sb[a + BS3_VZ]! - ka * nz;
        sb[b + BS3_VZ] = sb[b + BS3_VZ]! + kb * nz;
      }
    }
  }
}
