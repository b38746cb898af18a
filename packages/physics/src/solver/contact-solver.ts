import { endWokenContacts } from '../collision/events.js';
import { BodyType } from '../collision/state.js';
import { isShared, sharedFloat64, sharedLike } from '../threads/pool.js';
import type { PhysicsWorld } from '../world/options.js';
import * as BS from './body-state-layout.js';
import { withScaledSubsteps } from './contact-scale.js';
import { finishManifolds, gatherManifoldBodies, prepareManifolds } from './manifold-prepare-2d.js';
import {
  accumulateManifoldImpulses,
  applyManifoldRestitution,
  solveManifolds,
  storeManifoldImpulses,
  warmStartManifolds,
} from './manifold-rows-2d.js';
import { type RowFamilies, type RowFamily, rowFamilies, setRowFamily } from './row-families.js';
import { finishStage, gatherFillStage } from './stages-threads.js';

/**
 * Collide stage, part 3: the contact solver, Box2D v3's "soft step" (Catto, "Solver2D", 2024; Box2D
 * v3.0 solver.c and contact_solver.c) with an impact stage before it, fitted to a pipeline where the
 * integrate stage has already run. Its named stages, in order (each stage marked * runs over every row
 * family, solver/row-families.ts: the joints', the ball contacts', the shape contacts', in FAMILY_ORDER):
 *
 * 1. `gatherBodies`: `gather`* gives the moving bodies of the rows solver indices; they go into a
 *    packed solver state (one row per body, kept apart from the components: Box2D's b2BodyState); this
 *    step's gravity is rewound from their velocity (the integrate stage added g h; the substeps add it
 *    back in pieces);
 * 2. `prepareContacts`*: combined material, effective masses, tangent basis, last step's impulses
 *    (warm start);
 * 3. `applyImpacts` (solver/impacts.ts): every contact with restitution e > 0 that closes within the step
 *    faster than its threshold gets an exact pairwise Newton impulse at its time of impact, in order
 *    of impact, with the end position corrected for the time the body kept its old velocity;
 * 4. `measureApproach`: the normal relative velocity left at the start of the step (for restitution);
 * 5. `solverSubsteps` times, with h_s = h / substeps:
 *    `integrateVelocities` (v += g h_s); `warmStart`*; `solve`* with soft bias (non-penetration, then
 *    Coulomb friction |lambda_t| <= mu lambda_n, mu_s while sticking); `integratePositions`
 *    (dx += v h_s), then `integrate`* (the rotation joints owe); relax (`solve`* without bias, so push-out velocity does not survive as kinetic
 *    energy; in 2D a frictionless row with one ball resting on another may hold the lower one, so one
 *    sweep clears a tall column: solver/support.ts). A row that applies an impulse to a body marks it (the `pushed` slot of its packed row);
 * 6. `restitution`*: contacts the impact stage did not resolve (still approaching after its
 *    passes, e.g. deep in a dense pile) bounce, every family by the one definition of
 *    solver/restitution.ts (threshold, target -e v_impact, Poisson's cap, `restitutionIterations` passes);
 * 7. `finishBodies` (finishStage): velocities and positions (with the impact corrections) back to the components;
 *    a body no row pushed during the substeps was in free flight: its position gets -g h h_s / 2, which
 *    makes the substeps' sum of v_k h_s the exact parabola v0 h + g h^2 / 2 (as the integrate stage's);
 *    then `finish`*: the impulses stored for the next step's warm start, touch events;
 * 8. `containInBoundary`: a body the step's impulses sent through a wall of the boundary box that it
 *    had no contact with (a fast ball knocked sideways by another) is put back on the wall with its
 *    outward normal velocity reflected and scaled by the restitution, so nothing leaves the box; the
 *    potential energy it gains by being put back is taken from its kinetic energy, so energy never rises.
 *
 * Separation is tracked linearly: s = s0 + (dx_B - dx_A) . n, with s0 measured where the bodies
 * were at the start of the step. s > 0 is a speculative gap the bodies may close this substep
 * (bias s / h_s); s < 0 is overlap pushed out by a soft constraint (a damped spring of
 * `contactHertz` and `contactDampingRatio`, at most `contactPushSpeed`, both scaled to the balls'
 * size as solver/contact-scale.ts describes). Soft constraints with
 * relaxation are what keeps a deep pile still with few iterations and without adding energy.
 * @category Collision
 */
export function contactSolverSystem(world: PhysicsWorld): void {
  // Small balls take more substeps (solver/contact-scale.ts): the stages below read the count from the settings.
  withScaledSubsteps(world, solveContacts);
}

/** The 2D shape contacts' rows (solver/manifold-prepare-2d.ts, solver/manifold-rows-2d.ts) as a row family. */
const manifolds2D: RowFamily = {
  dimensions: 2,
  pushesUnmarked: false,
  toSolve: (world) => world.collision.shapes.manifolds.count > 0,
  gather: gatherManifoldBodies,
  prepare: (world) => prepareManifolds(world),
  warmStart: (world) => warmStartManifolds(world.collision),
  // After the substep's last pass over the manifolds, their impulses are added to the step's totals.
  solve: (world, hs, useBias, last) => {
    solveManifolds(world.collision, hs, useBias);
    if (last) accumulateManifoldImpulses(world.collision);
  },
  integrate: () => {},
  // Without relax passes (whose last adds them), the substep's impulses are added to the step's totals here.
  endSubstep: (world) => {
    if (world.collision.settings.relaxIterations === 0) accumulateManifoldImpulses(world.collision);
  },
  restitution: (world) => {
    applyManifoldRestitution(world);
    storeManifoldImpulses(world.collision);
  },
  finish: (world) => finishManifolds(world),
};
setRowFamily('manifolds2D', manifolds2D);

/** The contact solver stage at the step's `settings.solverSubsteps` (see contactSolverSystem). */
function solveContacts(world: PhysicsWorld): void {
  const cs = world.collision;
  const buf = cs.contacts;
  // The row families of this world's dimension (solver/row-families.ts), in the order every stage runs
  // them; the ball rows (null until the program makes a ball) also have stages of their own.
  const families = rowFamilies(world.dimensions);
  const { list, balls } = families;
  cs.stats.maxOverlap = 0;
  // Whether joints or shape contacts share the solve (each family is asked: the 2D joints' check also
  // clears last step's break events).
  let others = false;
  for (const f of list) if (f !== balls && f.toSolve(world)) others = true;
  if (!others && buf.count === 0) {
    if (balls !== null) {
      balls.events(world, buf, false);
      cs.contacts = balls.store(world, buf, false);
    }
    for (const f of list) f.finish(world, world.h);
    endWokenContacts(world);
    return;
  }
  const st = cs.settings;
  const substeps = st.solverSubsteps;
  const hs = world.h / substeps;
  gatherBodies(world, families);
  clearBodyImpacts(world);
  for (const f of list) f.prepare(world, hs);
  // A threaded 2D world with only ball contacts solves them colour by colour on its threads
  // (solver/coloring.ts): then the substeps below do not run.
  const colored = balls?.approach(world, buf, others, hs) === true;
  balls?.plan(world, buf, colored, hs);
  for (let s = 0; s < (colored ? 0 : substeps); s++) {
    integrateVelocities(world, hs);
    for (const f of list) f.warmStart(world);
    for (let it = 0; it < st.solverIterations; it++) for (const f of list) f.solve(world, hs, true, false);
    integratePositions(world, hs);
    for (const f of list) f.integrate(world, hs);
    for (let it = 0; it < st.relaxIterations; it++) {
      const last = it === st.relaxIterations - 1;
      for (const f of list) f.solve(world, hs, false, last);
    }
    for (const f of list) f.endSubstep(world);
  }
  for (const f of list) f.restitution(world);
  // Stages 7 and 8: range kernels, on a 2D world's threads or inline (solver/stages-threads.ts).
  finishStage(world, buf);
  for (const f of list) f.finish(world, hs);
  if (balls !== null) {
    balls.events(world, buf, true);
    // A threaded 2D world builds the warm-start table on a worker while the step finishes (solver/stages-threads.ts).
    cs.contacts = balls.store(world, buf, true);
  }
  endWokenContacts(world);
}

/**
 * Sizes the solver bodies' impact rows (CollisionState.bodyImpact, solver/impacts.ts IMPACT_STRIDE
 * numbers a body) and zeroes them: the impact stage of the ball rows writes its end-position
 * corrections there, and finishBodies adds them (0 in a step without impacts).
 */
function clearBodyImpacts(world: PhysicsWorld): void {
  const cs = world.collision;
  const count = cs.solverBodyCount;
  if (cs.bodyImpact.length < count * BS.IMPACT_STRIDE)
    cs.bodyImpact = new Float64Array(Math.max(count * BS.IMPACT_STRIDE, cs.bodyImpact.length * 2));
  cs.bodyImpact.fill(0, 0, count * BS.IMPACT_STRIDE);
}

/** Row stride of the packed solver state: 8 in 2D, 12 in 3D (see CollisionState.bodyState). */
function stride(world: PhysicsWorld): number {
  return world.dimensions === 2 ? BS.BS2_STRIDE : BS.BS3_STRIDE;
}

/**
 * Gives every moving body of this step's rows a solver index (0 is the static world): each family's
 * `gather`, in FAMILY_ORDER, continues the list (and writes its rows' solver indices); then fills each
 * body's packed row (velocity with this step's gravity rewound, zero displacement, inverse mass and
 * inertia) and its extra row (where the integrator put it, beyond x0 + v h; the rotation still owed).
 */
function gatherBodies(world: PhysicsWorld, families: RowFamilies): void {
  const cs = world.collision;
  // A threaded 2D world keeps the body list and the solver state on shared memory: the coloured solve's
  // stages read them on the workers (solver/coloring.ts, solver/stages-threads.ts); growth keeps the
  // list there (solver/solver-bodies.ts withRoom).
  const shared = world.threadPool !== null && world.dimensions === 2;
  // The families mark their bodies with this stamp (solverMark).
  cs.solverStamp++;
  if (shared && !isShared(cs.solverBodies)) cs.solverBodies = sharedLike(cs.solverBodies, cs.solverBodies.length);
  cs.solverBodies[0] = 0;
  let count = 1;
  const rows = families.list;
  for (const f of rows) count = f.gather(world, count);
  cs.solverBodyCount = count;

  const S = stride(world);
  if (cs.bodyState.length < count * BS.BS3_STRIDE || (shared && !isShared(cs.bodyState))) {
    const sizeS = Math.max(count * BS.BS3_STRIDE, cs.bodyState.length * 2),
      sizeE = Math.max(count * BS.BX_STRIDE, cs.bodyExtra.length * 2);
    cs.bodyState = shared ? sharedFloat64(sizeS) : new Float64Array(sizeS);
    cs.bodyExtra = shared ? sharedFloat64(sizeE) : new Float64Array(sizeE);
  }
  cs.bodyState.fill(0, 0, S);
  // Joint rows push their bodies without marking them: with joints, no body counts as free flying.
  let pushed = 0;
  for (const f of rows) if (f.pushesUnmarked && f.toSolve(world)) pushed = 1;
  // The fill is a range kernel, run on a 2D world's threads or inline (solver/stages-threads.ts).
  gatherFillStage(world, count, pushed);
}

/** Adds one substep of gravity to the dynamic solver bodies. */
function integrateVelocities(world: PhysicsWorld, hs: number): void {
  const cs = world.collision;
  const list = cs.solverBodies,
    count = cs.solverBodyCount,
    type = cs.bodyType,
    sb = cs.bodyState;
  const S = stride(world);
  const g = world.gravity;
  const gx = g[0]! * hs,
    gy = g[1]! * hs,
    gz = g[2]! * hs;
  for (let k = 1; k < count; k++) {
    if (type[list[k]!] !== BodyType.Dynamic) continue;
    const o = k * S;
    // vx and vy sit at the same offsets in both dimensions.
    sb[o + BS.BS2_VX] = sb[o + BS.BS2_VX]! + gx;
    sb[o + BS.BS2_VY] = sb[o + BS.BS2_VY]! + gy;
    if (S === BS.BS3_STRIDE) sb[o + BS.BS3_VZ] = sb[o + BS.BS3_VZ]! + gz;
  }
}

/** Advances the solver bodies' displacement (and the rotation owed) by one substep. */
function integratePositions(world: PhysicsWorld, hs: number): void {
  const cs = world.collision;
  const count = cs.solverBodyCount,
    sb = cs.bodyState,
    ex = cs.bodyExtra;
  if (stride(world) === BS.BS2_STRIDE) {
    for (let k = 1; k < count; k++) {
      const o = k * BS.BS2_STRIDE;
      sb[o + BS.BS2_DX] = sb[o + BS.BS2_DX]! + sb[o + BS.BS2_VX]! * hs;
      sb[o + BS.BS2_DY] = sb[o + BS.BS2_DY]! + sb[o + BS.BS2_VY]! * hs;
      if (sb[o + BS.BS2_INV_INERTIA]! > 0)
        ex[k * BS.BX_STRIDE + BS.BX_ROT_Z] = ex[k * BS.BX_STRIDE + BS.BX_ROT_Z]! + sb[o + BS.BS2_W]! * hs;
    }
    return;
  }
  for (let k = 1; k < count; k++) {
    const o = k * BS.BS3_STRIDE;
    sb[o + BS.BS3_DX] = sb[o + BS.BS3_DX]! + sb[o + BS.BS3_VX]! * hs;
    sb[o + BS.BS3_DY] = sb[o + BS.BS3_DY]! + sb[o + BS.BS3_VY]! * hs;
    sb[o + BS.BS3_DZ] = sb[o + BS.BS3_DZ]! + sb[o + BS.BS3_VZ]! * hs;
    if (sb[o + BS.BS3_INV_INERTIA]! > 0) {
      const q = k * BS.BX_STRIDE;
      ex[q + BS.BX_ROT_X] = ex[q + BS.BX_ROT_X]! + sb[o + BS.BS3_WX]! * hs;
      ex[q + BS.BX_ROT_Y] = ex[q + BS.BX_ROT_Y]! + sb[o + BS.BS3_WY]! * hs;
      ex[q + BS.BX_ROT_Z] = ex[q + BS.BX_ROT_Z]! + sb[o + BS.BS3_WZ]! * hs;
    }
  }
}
