import { type ContactBuffer, ContactKind, findWarmStart, storeWarmStart } from '../collision/contacts.js';
import type { CollisionState } from '../collision/state.js';
import { BodyType } from '../collision/state.js';
import {
  finishJoints,
  gatherJointBodies,
  integrateJointRotations,
  jointsToSolve,
  prepareJoints,
  solveJoints,
  warmStartJoints,
} from '../joints/solver-2d.js';
import { rotateInPlace } from '../math/quaternion.js';
import { KERNEL, type KernelArray } from '../threads/kernels.js';
import { runOnPool } from '../threads/parallel.js';
import { isShared, sharedFloat64, sharedLike } from '../threads/pool.js';
import { reportNonFinite } from '../world/errors.js';
import type { PhysicsWorld } from '../world/options.js';
import { shareContactBuffer, solveColoredSubsteps, startStripPlan, useColoredSolve } from './coloring.js';
import { ballContactHertz, ballContactPushSpeed, ballStickSpeed, contactLength, withScaledSubsteps } from './contact-scale.js';
import { applyImpacts, IMPACT_STRIDE, releaseImpactedRows } from './impacts.js';
import {
  accumulateManifoldImpulses,
  applyManifoldRestitution,
  finishManifolds,
  gatherManifoldBodies,
  prepareManifolds,
  solveManifolds,
  warmStartManifolds,
} from './manifold-rows-2d.js';
import { prepareContacts2D } from './prepare-contacts-kernel.js';
import {
  applyManifold3DRestitution,
  finishJoints3D,
  finishManifolds3D,
  gatherJoint3DBodies,
  gatherManifold3DBodies,
  joints3DToSolve,
  manifolds3DToSolve,
  prepareJoints3D,
  prepareManifolds3D,
  solveJoints3D,
  solveManifolds3D,
  warmStartJoints3D,
  warmStartManifolds3D,
} from './rows-3d.js';
import { approach2DStage, finish2DStage, gatherFill2DStage, restitutionOnThreads, storeWarmStartOnThreads } from './stages-threads.js';
import { downward3Into, downwardInto, heavierAbove, holdsLower, markFirstRelaxRows, SUPPORT_COS } from './support.js';

/**
 * Collide stage, part 3: the contact solver, Box2D v3's "soft step" (Catto, "Solver2D", 2024; Box2D
 * v3.0 solver.c and contact_solver.c) with an impact stage before it, fitted to a pipeline where the
 * integrate stage has already run. Its named stages, in order (other solver rows, such as joints, add
 * their calls next to the contacts' in the stages marked *):
 *
 * 1. `gatherBodies`: the moving bodies that have contacts go into a packed solver state (one row per
 *    body, kept apart from the components: Box2D's b2BodyState); this step's gravity is rewound from
 *    their velocity (the integrate stage added g h; the substeps add it back in pieces);
 * 2. `prepareContacts`*: combined material, effective masses, tangent basis, last step's impulses
 *    (warm start);
 * 3. `applyImpacts` (solver/impacts.ts): every contact with restitution e > 0 that closes within the step
 *    faster than its threshold gets an exact pairwise Newton impulse at its time of impact, in order
 *    of impact, with the end position corrected for the time the body kept its old velocity;
 * 4. `measureApproach`: the normal relative velocity left at the start of the step (for restitution);
 * 5. `solverSubsteps` times, with h_s = h / substeps:
 *    `integrateVelocities` (v += g h_s); `warmStart`*; `solve`* with soft bias (non-penetration, then
 *    Coulomb friction |lambda_t| <= mu lambda_n, mu_s while sticking); `integratePositions`
 *    (dx += v h_s); relax (`solve`* without bias, so push-out velocity does not survive as kinetic
 *    energy; in 2D a frictionless row with one ball resting on another may hold the lower one, so one
 *    sweep clears a tall column: solver/support.ts). A row that applies an impulse to a body marks it (the `pushed` slot of its packed row);
 * 6. `applyRestitution`: contacts the impact stage did not resolve (still approaching after its
 *    passes, e.g. deep in a dense pile) bounce as a small LCP;
 * 7. `finishBodies`: velocities and positions (with the impact corrections) back to the components;
 *    a body no row pushed during the substeps was in free flight: its position gets -g h h_s / 2, which
 *    makes the substeps' sum of v_k h_s the exact parabola v0 h + g h^2 / 2 (as the integrate stage's);
 *    the impulses stored for the next step's warm start;
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

/** The contact solver stage at the step's `settings.solverSubsteps` (see contactSolverSystem). */
function solveContacts(world: PhysicsWorld): void {
  const cs = world.collision;
  const buf = cs.contacts;
  cs.stats.maxOverlap = 0;
  if (
    !jointsToSolve(world) &&
    buf.count === 0 &&
    cs.shapes.manifolds.count === 0 &&
    !manifolds3DToSolve(world) &&
    !joints3DToSolve(world)
  ) {
    cs.contacts = storeWarmStart(cs.cache, buf);
    finishManifolds(world);
    if (world.dimensions === 3) finishManifolds3D(world);
    return;
  }
  gatherBodies(world, buf);
  // The ball contacts' tolerances follow the size of the balls (solver/contact-scale.ts).
  const length = contactLength(buf);
  prepareContacts(world, buf, ballStickSpeed(cs.settings, length));
  prepareManifolds(world);
  if (world.dimensions === 3) prepareManifolds3D(world);
  const is2D = world.dimensions === 2;
  const others = jointsToSolve(world) || cs.shapes.manifolds.count > 0;
  // A threaded 2D world plans and packs the coloured solve's rows on a worker meanwhile (solver/coloring.ts).
  if (is2D) startStripPlan(world, buf, others);
  applyImpacts(world, buf);
  // A threaded 2D world with only ball contacts solves them colour by colour on its threads
  // (solver/coloring.ts), measuring the approach speeds there too.
  const colored = is2D && useColoredSolve(world, buf, others);
  if (!colored) measureApproach(world, buf);

  const st = cs.settings;
  const substeps = st.solverSubsteps;
  const hs = world.h / substeps;
  // Softness (Box2D b2MakeSoft): stiffness from the balls' size, capped at the substep rate
  // (solver/contact-scale.ts); contacts against infinite mass twice as stiff.
  const hertz = ballContactHertz(st, length, hs);
  const push = ballContactPushSpeed(st, length);
  const sp = solveParams;
  sp[0] = hs;
  sp[1] = push;
  makeSoftInto(sp, 4, hertz, st.contactDampingRatio, hs);
  makeSoftInto(sp, 7, 2 * hertz, st.contactDampingRatio, hs);
  prepareJoints(world, hs);
  prepareJoints3D(world, hs);
  // Which way is down, for the support rows of the relax sweep (solver/support.ts).
  downwardInto(world.gravity, sp, 2);
  if (!is2D) downward3Into(world.gravity, sp, 10);
  relaxFirst = markFirstRelaxRows(
    buf.ia,
    buf.ib,
    buf.nx,
    buf.ny,
    is2D ? null : buf.nz,
    buf.count,
    cs.solverBodyCount,
    cs.bodyState,
    stride(world),
    sp,
    is2D ? 2 : 10,
  );
  const TOT = buf.totalNormalImpulse,
    LN = buf.normalImpulse;
  // The coloured solve takes the impacted rows out after it plans (solver/coloring.ts), the others now.
  if (colored) solveColoredSubsteps(world, buf, hs, [sp[4]!, sp[5]!, sp[6]!, sp[7]!, sp[8]!, sp[9]!], push);
  else releaseImpactedRows(buf);
  for (let s = 0; s < (colored ? 0 : substeps); s++) {
    integrateVelocities(world, hs);
    warmStartJoints(world);
    warmStartJoints3D(world);
    if (is2D) warmStart2D(cs, buf);
    else warmStart3D(cs, buf);
    if (is2D) warmStartManifolds(cs);
    else warmStartManifolds3D(world);
    for (let it = 0; it < st.solverIterations; it++) {
      solveJoints(world, hs, true);
      solveJoints3D(world, hs, true);
      if (is2D) solve2D(cs, buf, true);
      else solve3D(cs, buf, true);
      if (is2D) solveManifolds(cs, hs, true);
      else solveManifolds3D(world, hs, true);
    }
    integratePositions(world, hs);
    integrateJointRotations(world, hs);
    for (let it = 0; it < st.relaxIterations; it++) {
      solveJoints(world, hs, false);
      solveJoints3D(world, hs, false);
      if (is2D) solve2D(cs, buf, false);
      else solve3D(cs, buf, false);
      if (is2D) solveManifolds(cs, hs, false);
      else solveManifolds3D(world, hs, false);
    }
    if (is2D) accumulateManifoldImpulses(cs);
    // The accumulated impulse is what this substep delivered (warm start plus corrections).
    for (let i = 0, n = buf.count; i < n; i++) TOT[i] = TOT[i]! + LN[i]!;
  }
  const IMP = buf.impulse;
  for (let i = 0, n = buf.count; i < n; i++) IMP[i] = IMP[i]! + TOT[i]!;
  applyRestitution(world, buf);
  if (is2D) applyManifoldRestitution(world);
  else applyManifold3DRestitution(world);
  finishBodies(world, buf);
  containInBoundary(world);
  finishManifolds(world);
  if (world.dimensions === 3) finishManifolds3D(world);
  finishJoints(world, hs);
  finishJoints3D(world, hs);
  // A threaded 2D world builds the warm-start table on a worker while the step finishes (solver/stages-threads.ts).
  cs.contacts = storeWarmStartOnThreads(world, buf) ?? storeWarmStart(cs.cache, buf);
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

/** Per ball contact row of the step: 1 for the rows the relax sweep takes first (solver/support.ts markFirstRelaxRows). Not world state. */
let relaxFirst: Uint8Array = new Uint8Array(0);

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

/** Row stride of the packed solver state: 8 in 2D, 12 in 3D (see CollisionState.bodyState). */
function stride(world: PhysicsWorld): number {
  return world.dimensions === 2 ? 8 : 12;
}

/**
 * Gives every moving body touched by a contact a solver index (0 is the static world), fills its
 * packed row (velocity with this step's gravity rewound, zero displacement, inverse mass and
 * inertia) and its extra row (where the integrator put it, beyond x0 + v h; the rotation still owed),
 * and writes each contact's solver indices.
 */
function gatherBodies(world: PhysicsWorld, buf: ContactBuffer): void {
  const cs = world.collision;
  const c = world.components;
  const n = buf.count;
  const mark = cs.solverMark,
    index = cs.solverIndex;
  const stamp = ++cs.solverStamp;
  // Room for both bodies of every row, on shared memory in a threaded 2D world: the coloured solve's
  // stages read the list on the workers (solver/coloring.ts startStripPlan, solver/stages-threads.ts).
  const shareList = world.threadPool !== null && world.dimensions === 2;
  let list = cs.solverBodies;
  if (list.length < 2 * n + 1 || (shareList && !isShared(list))) {
    // Doubling: a threaded pool keeps every array it has been given (threads/pool.ts), so the list must
    // not grow a little every step while a pile's rows grow.
    const size = list.length < 2 * n + 1 ? Math.max(2 * n + 1, 2 * list.length) : list.length;
    list = shareList ? sharedLike(list, size) : new Int32Array(size);
  }
  let count = 1;
  list[0] = 0;
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
  count = gatherManifoldBodies(world, count); // the shapes' manifolds join (solver/manifold-rows-2d.ts)
  if (world.dimensions === 3) count = gatherManifold3DBodies(world, count); // and the 3D shapes' (solver/manifold-rows-3d.ts)
  if (world.dimensions === 3) count = gatherJoint3DBodies(world, count); // and the 3D joints' (joints/solver-3d.ts)
  list = cs.solverBodies;
  count = gatherJointBodies(world, count); // the joints' bodies join the contacts'
  list = cs.solverBodies;
  cs.solverBodyCount = count;

  const S = stride(world);
  // A threaded world keeps the solver state on shared memory (the coloured solve, solver/coloring.ts).
  const shared = world.threadPool !== null && world.dimensions === 2;
  if (cs.bodyState.length < count * 12 || (shared && !isShared(cs.bodyState))) {
    const sizeS = Math.max(count * 12, cs.bodyState.length * 2),
      sizeE = Math.max(count * 6, cs.bodyExtra.length * 2);
    cs.bodyState = shared ? sharedFloat64(sizeS) : new Float64Array(sizeS);
    cs.bodyExtra = shared ? sharedFloat64(sizeE) : new Float64Array(sizeE);
  }
  const sb = cs.bodyState,
    ex = cs.bodyExtra;
  sb.fill(0, 0, S);
  const px = c.Position.x,
    py = c.Position.y,
    pz = c.Position.z;
  const vx = c.Velocity.x,
    vy = c.Velocity.y,
    vz = c.Velocity.z;
  const wx = c.AngularVelocity.x,
    wy = c.AngularVelocity.y,
    wz = c.AngularVelocity.z;
  const h = world.h;
  const g = world.gravity;
  const gx = g[0]! * h,
    gy = g[1]! * h,
    gz = g[2]! * h;
  const type = cs.bodyType,
    invMass = cs.invMass,
    invInertia = cs.invInertia;
  const fx = c.Force.x,
    fy = c.Force.y,
    fz = c.Force.z;
  // Joint rows push their bodies without marking them: with joints, no body counts as free flying.
  const pushed = jointsToSolve(world) ? 1 : 0;
  // 2D: the fill is a range kernel, run on the threads or inline (solver/stages-threads.ts).
  if (S === 8) {
    gatherFill2DStage(world, count, pushed);
    return;
  }
  for (let k = 1; k < count; k++) {
    const e = list[k]!;
    const o = k * 12,
      q = k * 6;
    const ii = invInertia[e]!;
    const dynamic = type[e] === BodyType.Dynamic;
    // A kinematic body's spin is part of its surface velocity (v + w x r) that its contacts see; it is not
    // integrated here (its rotation owed stays 0: the integrator already turned it, and it has no inverse inertia).
    const spins = type[e] === BodyType.Kinematic;
    // The integrator moved x by v0 h + g h^2 / 2 (plus anything of its own, e.g. forces); keep that
    // extra as the base. v = v0 + g h here, so the base is x - v h + g h^2 / 2 for dynamic bodies.
    // A body a force acted on was not given the exact free fall (semiImplicitEuler): no gravity base,
    // and it counts as pushed so finishBodies does not give it the free-flight correction either.
    const forced = fx[e] !== 0 || fy[e] !== 0 || fz[e] !== 0;
    const gb = dynamic && !forced ? 0.5 * h : 0;
    const held = forced ? 1 : pushed;
    ex[q] = px[e]! - vx[e]! * h + gx * gb;
    ex[q + 1] = py[e]! - vy[e]! * h + gy * gb;
    ex[q + 2] = pz[e]! - vz[e]! * h + gz * gb;
    // The integrator turned the body by w h; the substeps will turn it by sum w_k h_s instead.
    ex[q + 3] = ii > 0 ? -wx[e]! * h : 0;
    ex[q + 4] = ii > 0 ? -wy[e]! * h : 0;
    ex[q + 5] = ii > 0 ? -wz[e]! * h : 0;
    sb[o] = dynamic ? vx[e]! - gx : vx[e]!;
    sb[o + 1] = dynamic ? vy[e]! - gy : vy[e]!;
    sb[o + 2] = dynamic ? vz[e]! - gz : vz[e]!;
    sb[o + 3] = ii > 0 || spins ? wx[e]! : 0;
    sb[o + 4] = ii > 0 || spins ? wy[e]! : 0;
    sb[o + 5] = ii > 0 || spins ? wz[e]! : 0;
    sb[o + 6] = 0;
    sb[o + 7] = 0;
    sb[o + 8] = 0;
    sb[o + 9] = invMass[e]!;
    sb[o + 10] = ii;
    sb[o + 11] = held;
  }
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
    sb[o] = sb[o]! + gx;
    sb[o + 1] = sb[o + 1]! + gy;
    if (S === 12) sb[o + 2] = sb[o + 2]! + gz;
  }
}

/** Advances the solver bodies' displacement (and the rotation owed) by one substep. */
function integratePositions(world: PhysicsWorld, hs: number): void {
  const cs = world.collision;
  const count = cs.solverBodyCount,
    sb = cs.bodyState,
    ex = cs.bodyExtra;
  if (stride(world) === 8) {
    for (let k = 1; k < count; k++) {
      const o = k * 8;
      sb[o + 3] = sb[o + 3]! + sb[o]! * hs;
      sb[o + 4] = sb[o + 4]! + sb[o + 1]! * hs;
      if (sb[o + 6]! > 0) ex[k * 6 + 5] = ex[k * 6 + 5]! + sb[o + 2]! * hs;
    }
    return;
  }
  for (let k = 1; k < count; k++) {
    const o = k * 12;
    sb[o + 6] = sb[o + 6]! + sb[o]! * hs;
    sb[o + 7] = sb[o + 7]! + sb[o + 1]! * hs;
    sb[o + 8] = sb[o + 8]! + sb[o + 2]! * hs;
    if (sb[o + 10]! > 0) {
      const q = k * 6;
      ex[q + 3] = ex[q + 3]! + sb[o + 3]! * hs;
      ex[q + 4] = ex[q + 4]! + sb[o + 4]! * hs;
      ex[q + 5] = ex[q + 5]! + sb[o + 5]! * hs;
    }
  }
}

/**
 * Writes the solver bodies back: velocities; positions (base + displacement) and orientations (turned
 * by the rotation owed) of dynamic bodies. Records the deepest overlap left, measured linearly as in
 * the solve.
 */
function finishBodies(world: PhysicsWorld, buf: ContactBuffer): void {
  // 2D: a range kernel with the boundary box, run on the threads or inline (solver/stages-threads.ts).
  if (world.dimensions === 2) {
    finish2DStage(world, buf);
    return;
  }
  const cs = world.collision;
  const c = world.components;
  const list = cs.solverBodies,
    count = cs.solverBodyCount,
    type = cs.bodyType,
    sb = cs.bodyState,
    ex = cs.bodyExtra;
  const imp = cs.bodyImpact;
  const px = c.Position.x,
    py = c.Position.y,
    pz = c.Position.z;
  const vx = c.Velocity.x,
    vy = c.Velocity.y,
    vz = c.Velocity.z;
  const wx = c.AngularVelocity.x,
    wy = c.AngularVelocity.y,
    wz = c.AngularVelocity.z;
  const q = c.Orientation;
  const g = world.gravity,
    fh = (-0.5 * world.h * world.h) / cs.settings.solverSubsteps;
  const fx = g[0]! * fh,
    fy = g[1]! * fh,
    fz = g[2]! * fh;
  let check = 0;
  for (let k = 1; k < count; k++) {
    const e = list[k]!;
    if (type[e] !== BodyType.Dynamic) continue;
    const o = k * 12,
      r = k * 6;
    const free = sb[o + 11] === 0 ? 1 : 0;
    vx[e] = sb[o]!;
    vy[e] = sb[o + 1]!;
    vz[e] = sb[o + 2]!;
    const x = ex[r]! + sb[o + 6]! + imp[k * IMPACT_STRIDE]! + free * fx,
      y = ex[r + 1]! + sb[o + 7]! + imp[k * IMPACT_STRIDE + 1]! + free * fy;
    const z = ex[r + 2]! + sb[o + 8]! + imp[k * IMPACT_STRIDE + 2]! + free * fz;
    px[e] = x;
    py[e] = y;
    pz[e] = z;
    check += x + y + z + sb[o]! + sb[o + 1]! + sb[o + 2]!;
    if (sb[o + 10]! > 0) {
      wx[e] = sb[o + 3]!;
      wy[e] = sb[o + 4]!;
      wz[e] = sb[o + 5]!;
      rotateInPlace(q.x, q.y, q.z, q.w, e, ex[r + 3]!, ex[r + 4]!, ex[r + 5]!);
    }
  }
  if (check - check !== 0) reportNonFinite(world, list.subarray(1, count), 'collide');
  let deepest = 0;
  const IA = buf.ia,
    IB = buf.ib,
    S0 = buf.separation,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  // The start separations already hold the impact corrections (solver/impacts.ts).
  for (let i = 0, n = buf.count; i < n; i++) {
    const a = IA[i]! * 12 + 6,
      b = IB[i]! * 12 + 6;
    const s = S0[i]! + (sb[b]! - sb[a]!) * NX[i]! + (sb[b + 1]! - sb[a + 1]!) * NY[i]! + (sb[b + 2]! - sb[a + 2]!) * NZ[i]!;
    if (s < deepest) deepest = s;
  }
  cs.stats.maxOverlap = -deepest;
}

/** Stage 8 of the solver (see contactSolverSystem): keeps the solver's dynamic bodies inside the boundary box. */
function containInBoundary(world: PhysicsWorld): void {
  const cs = world.collision;
  const box = cs.boundary;
  // 2D: done with finishBodies (finish2DStage, solver/stages-threads.ts).
  if (!box.enabled || world.dimensions === 2) return;
  const c = world.components;
  const P = c.Position,
    V = c.Velocity,
    radius = c.Ball.radius,
    eM = c.Material.restitution;
  const list = cs.solverBodies,
    count = cs.solverBodyCount,
    type = cs.bodyType;
  const dims = world.dimensions;
  const g = world.gravity;
  const pos = [P.x, P.y, P.z],
    vel = [V.x, V.y, V.z];
  for (let k = 1; k < count; k++) {
    const e = list[k]!;
    if (type[e] !== BodyType.Dynamic) continue;
    const r = radius[e]!;
    // Potential energy a unit mass gains by being put back (-g . dx), J/kg.
    let gain = 0;
    for (let d = 0; d < dims; d++) {
      const p = pos[d]!,
        v = vel[d]!;
      const lo = box.min[d]! + r,
        hi = box.max[d]! - r;
      const x = p[e]!;
      if (x < lo && lo <= hi) {
        p[e] = lo;
        gain -= g[d]! * (lo - x);
        if (v[e]! < 0) v[e] = -Math.max(box.restitution, eM[e]!) * v[e]!;
      } else if (x > hi && lo <= hi) {
        p[e] = hi;
        gain -= g[d]! * (hi - x);
        if (v[e]! > 0) v[e] = -Math.max(box.restitution, eM[e]!) * v[e]!;
      }
    }
    // Putting a body back up against gravity must not create energy: its kinetic energy pays for the
    // potential energy gained (|v| scaled so |v'|^2 / 2 = |v|^2 / 2 - gain, or stopped if that is < 0).
    if (gain > 0) {
      let v2 = 0;
      for (let d = 0; d < dims; d++) v2 += vel[d]![e]! * vel[d]![e]!;
      const f = v2 > 2 * gain ? Math.sqrt(1 - (2 * gain) / v2) : 0;
      for (let d = 0; d < dims; d++) vel[d]![e] = vel[d]![e]! * f;
    }
  }
}

/**
 * Fewest contact rows a thread for a threaded 2D world to prepare its rows on its threads.
 * @category Collision
 */
export const PREPARE_MIN_PER_THREAD = 4096;

/** Per world: the shared copy of the spawn stamps, the kernel's arrays and parameters (prepare2DStage). */
const prepareScratch = new WeakMap<PhysicsWorld, { stamp: Uint32Array; arrays: KernelArray[]; params: Float64Array }>();

/**
 * prepareContacts of a 2D world (kernel prepareContacts2D: each row on its own), on its threads when it
 * has them and has at least PREPARE_MIN_PER_THREAD rows a thread (and the pool takes it), else inline
 * over every row: one code path, the same rows to the bit either way.
 * @throws Error naming contactSolverSystem if a worker thread failed.
 */
function prepare2DStage(world: PhysicsWorld, buf: ContactBuffer, stick: number): void {
  let pool = world.threadPool;
  const n = buf.count;
  const cs = world.collision,
    c = world.components,
    cache = cs.cache;
  const M = c.Material;
  if (pool !== null && n < PREPARE_MIN_PER_THREAD * pool.threads) pool = null;
  if (pool !== null && (!isShared(M.restitution) || !isShared(M.friction) || !isShared(M.staticFriction) || !isShared(cs.bodyState)))
    pool = null;
  let S = prepareScratch.get(world);
  if (S === undefined) {
    S = { stamp: new Uint32Array(0), arrays: [], params: new Float64Array(8) };
    prepareScratch.set(world, S);
  }
  let stamp = world.spawnStamp;
  if (pool !== null) {
    shareContactBuffer(buf);
    shareContactBuffer(cache.rows);
    if (!isShared(cache.slots)) {
      const slots = sharedLike(cache.slots, cache.slots.length);
      slots.set(cache.slots);
      cache.slots = slots;
    }
    // The workers read a shared copy of the spawn stamps.
    if (S.stamp.length < stamp.length) S.stamp = sharedLike(stamp, stamp.length);
    S.stamp.set(stamp);
    stamp = S.stamp;
  }
  const prev = cache.rows,
    box = cs.boundary;
  const A = S.arrays;
  A.length = 0;
  A.push(
    buf.a,
    buf.b,
    buf.ia,
    buf.ib,
    buf.kind,
    buf.feature,
    buf.nx,
    buf.ny,
    buf.ra,
    buf.rb,
    cs.bodyState,
    M.restitution,
    M.friction,
    M.staticFriction,
    stamp,
    buf.normalMass,
    buf.tangentMass,
    buf.rigidPartner,
    buf.t1x,
    buf.t1y,
    buf.t1z,
    buf.restitution,
    buf.friction,
    buf.frictionBound,
    buf.relativeVelocity,
    buf.totalNormalImpulse,
    buf.impulse,
    buf.normalImpulse,
    buf.tangentImpulse1,
    buf.tangentImpulse2,
    buf.maxNormalImpulse,
    buf.stampA,
    buf.stampB,
    prev.kind,
    prev.a,
    prev.b,
    prev.feature,
    prev.stampA,
    prev.stampB,
    prev.normalImpulse,
    prev.tangentImpulse1,
    prev.tangentImpulse2,
    cache.slots,
  );
  const P = S.params;
  P[0] = stick;
  P[1] = box.restitution;
  P[2] = box.friction;
  P[3] = box.staticFriction;
  P[4] = cache.size === 0 ? 0 : prev.count;
  P[5] = cache.size;
  P[6] = ContactKind.Ball;
  P[7] = ContactKind.Boundary;
  if (pool !== null && runOnPool(pool, 'contactSolverSystem', KERNEL.prepareContacts2D, A, P, n, null, PREPARE_MIN_PER_THREAD) !== null)
    return;
  prepareContacts2D(A, P, null, 0, n);
}

/**
 * Prepares the step's ball contact rows: effective masses, tangent basis, combined material, stick or
 * slip, the predicted approach, and last step's impulses of the same pair (warm start). 2D: a range
 * kernel (prepare2DStage); the loop here is 3D.
 */
function prepareContacts(world: PhysicsWorld, buf: ContactBuffer, stick: number): void {
  // The warm-start table may still be building on a worker (storeWarmStartOnThreads).
  world.threadPool?.join();
  if (world.dimensions === 2) {
    prepare2DStage(world, buf, stick);
    return;
  }
  const c = world.components;
  const cs = world.collision;
  const n = buf.count;
  const sb = cs.bodyState;
  const eM = c.Material.restitution,
    fM = c.Material.friction,
    sM = c.Material.staticFriction;
  const box = cs.boundary;
  const cache = cs.cache;
  const prev = cache.rows;
  const stamp = world.spawnStamp;
  const A = buf.a,
    B = buf.b,
    IA = buf.ia,
    IB = buf.ib,
    K = buf.kind,
    F = buf.feature;
  const NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const RA = buf.ra,
    RB = buf.rb;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    RP = buf.rigidPartner;
  const E = buf.restitution,
    MU = buf.friction,
    FB = buf.frictionBound,
    RV = buf.relativeVelocity;
  const TOT = buf.totalNormalImpulse,
    IMP = buf.impulse;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2,
    MAXN = buf.maxNormalImpulse;
  const SA = buf.stampA,
    SB = buf.stampB;
  const pN = prev.normalImpulse,
    p1 = prev.tangentImpulse1,
    p2 = prev.tangentImpulse2;
  const pK = prev.kind,
    pA = prev.a,
    pB = prev.b,
    pF = prev.feature,
    pSA = prev.stampA,
    pSB = prev.stampB;
  const prevCount = cache.size === 0 ? 0 : prev.count;
  let next = 0;

  for (let i = 0; i < n; i++) {
    const a = A[i]!,
      b = B[i]!,
      kind = K[i]!,
      f = F[i]!;
    const oa = IA[i]! * 12,
      ob = IB[i]! * 12;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const imA = sb[oa + 9]!,
      imB = sb[ob + 9]!;
    const iiA = sb[oa + 10]!,
      iiB = sb[ob + 10]!;
    const ra = RA[i]!,
      rb = RB[i]!;
    const k = imA + imB;
    NM[i] = k > 0 ? 1 / k : 0;
    const kt = k + iiA * ra * ra + iiB * rb * rb;
    TM[i] = kt > 0 ? 1 / kt : 0;
    RP[i] = imA === 0 || imB === 0 ? 1 : 0;

    // Tangent basis: t1 stored, t2 = n x t1 recomputed where needed.
    let t1x: number, t1y: number, t1z: number;
    if (Math.abs(nx) < 0.57735) {
      const inv = 1 / Math.sqrt(ny * ny + nz * nz);
      t1x = 0;
      t1y = nz * inv;
      t1z = -ny * inv;
    } else {
      const inv = 1 / Math.sqrt(nx * nx + ny * ny);
      t1x = ny * inv;
      t1y = -nx * inv;
      t1z = 0;
    }
    T1X[i] = t1x;
    T1Y[i] = t1y;
    T1Z[i] = t1z;

    // Combined material (Box2D's mixing rules: the bouncier surface wins, friction is the geometric mean).
    let e: number, mu: number, mus: number;
    if (kind === ContactKind.Ball) {
      e = Math.max(eM[a]!, eM[b]!);
      mu = Math.sqrt(fM[a]! * fM[b]!);
      mus = Math.sqrt(sM[a]! * sM[b]!);
    } else if (kind === ContactKind.Boundary) {
      e = Math.max(box.restitution, eM[b]!);
      mu = Math.sqrt(box.friction * fM[b]!);
      mus = Math.sqrt(box.staticFriction * sM[b]!);
    } else {
      e = Math.max(eM[f]!, eM[b]!);
      mu = Math.sqrt(fM[f]! * fM[b]!);
      mus = Math.sqrt(sM[f]! * sM[b]!);
    }
    E[i] = e;
    MU[i] = mu;

    // Tangential speed at the start of the step (gravity rewound): stick or slip.
    const dvx = sb[ob]! - sb[oa]!,
      dvy = sb[ob + 1]! - sb[oa + 1]!,
      dvz = sb[ob + 2]! - sb[oa + 2]!;
    // Contact-point velocity: v + w x r with r_A = ra n, r_B = -rb n.
    const sx = -rb * sb[ob + 3]! - ra * sb[oa + 3]!,
      sy = -rb * sb[ob + 4]! - ra * sb[oa + 4]!,
      sz = -rb * sb[ob + 5]! - ra * sb[oa + 5]!;
    const cx = dvx + sy * nz - sz * ny,
      cy = dvy + sz * nx - sx * nz,
      cz = dvz + sx * ny - sy * nx;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const u1 = cx * t1x + cy * t1y + cz * t1z,
      u2 = cx * t2x + cy * t2y + cz * t2z;
    const vt = Math.sqrt(u1 * u1 + u2 * u2);
    // Predicted approach for the impact stage's ordering (measureApproach recomputes it after).
    RV[i] = (sb[ob]! - sb[oa]!) * nx + (sb[ob + 1]! - sb[oa + 1]!) * ny + (sb[ob + 2]! - sb[oa + 2]!) * nz;
    TOT[i] = 0;
    IMP[i] = 0;
    FB[i] = vt < stick ? Math.max(mus, mu) : mu;

    // Warm start from last step's impulses of the same pair.
    const sA = stamp[kind === ContactKind.Ball ? a : kind === ContactKind.Boundary ? 0 : f]!;
    const sB = stamp[b]!;
    SA[i] = sA;
    SB[i] = sB;
    MAXN[i] = 0;
    // The contacts come in much the same order every step: the row after last step's previous match
    // is tried first (one comparison, read in order) before the hash table (the same row: keys are unique).
    let j = next;
    if (j < prevCount && pK[j] === kind && pA[j] === a && pB[j] === b && pF[j] === f) j = pSA[j] === sA && pSB[j] === sB ? j : -1;
    else j = findWarmStart(cache, kind, a, b, f, sA, sB);
    if (j >= 0) {
      next = j + 1;
      LN[i] = pN[j]!;
      L1[i] = p1[j]!;
      L2[i] = p2[j]!;
    } else {
      LN[i] = 0;
      L1[i] = 0;
      L2[i] = 0;
    }
  }
}

/**
 * Normal relative velocity of each contact at the start of the step after the impact stage (gravity
 * rewound), m/s, into `relativeVelocity`; and the speed at impact into `impactVelocity`:
 * v^2 = v0^2 - 2 a_n s across a gap s > 0 with the relative normal acceleration a_n of gravity. A
 * row the impact stage bounced (impulse > 0) that now separates keeps the approach speed that stage
 * recorded at its time of impact (restitution leaves separating rows alone).
 */
function measureApproach(world: PhysicsWorld, buf: ContactBuffer): void {
  // 2D: a range kernel, run on the threads or inline (solver/stages-threads.ts).
  if (world.dimensions === 2) {
    approach2DStage(world, buf);
    return;
  }
  const cs = world.collision;
  const sb = cs.bodyState,
    type = cs.bodyType;
  const g = world.gravity;
  const gx = g[0]!,
    gy = g[1]!,
    gz = g[2]!;
  const A = buf.a,
    B = buf.b,
    IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  const RV = buf.relativeVelocity,
    IV = buf.impactVelocity,
    S0 = buf.separation,
    IMP = buf.impulse;
  for (let i = 0, n = buf.count; i < n; i++) {
    const oa = IA[i]! * 12,
      ob = IB[i]! * 12;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const rv = (sb[ob]! - sb[oa]!) * nx + (sb[ob + 1]! - sb[oa + 1]!) * ny + (sb[ob + 2]! - sb[oa + 2]!) * nz;
    RV[i] = rv;
    // A row the impact stage bounced and that now separates keeps the approach speed of its impact.
    if (IMP[i]! > 0 && rv >= 0) continue;
    const gap = S0[i]!;
    if (!(rv < 0 && gap > 0)) {
      IV[i] = rv;
      continue;
    } // no gap to fall across: -sqrt(rv^2) = rv
    const a = A[i]!,
      b = B[i]!;
    const an = ((type[b] === BodyType.Dynamic ? 1 : 0) - (a !== 0 && type[a] === BodyType.Dynamic ? 1 : 0)) * (gx * nx + gy * ny + gz * nz);
    const v2 = rv * rv - 2 * an * gap;
    IV[i] = v2 > 0 ? -Math.sqrt(v2) : rv;
  }
}

/** Applies every contact's accumulated impulse (Box2D v3 warm start, once per substep), 2D. */
function warmStart2D(cs: CollisionState, buf: ContactBuffer): void {
  const n = buf.count,
    sb = cs.bodyState;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    RA = buf.ra,
    RB = buf.rb;
  const LN = buf.normalImpulse,
    LT = buf.tangentImpulse1;
  for (let i = 0; i < n; i++) {
    const ln = LN[i]!,
      lt = LT[i]!;
    if (ln === 0 && lt === 0) continue;
    const a = IA[i]! * 8,
      b = IB[i]! * 8;
    sb[a + 7] = 1;
    sb[b + 7] = 1;
    const nx = NX[i]!,
      ny = NY[i]!;
    const Px = ln * nx - lt * ny,
      Py = ln * ny + lt * nx;
    const imA = sb[a + 5]!,
      imB = sb[b + 5]!;
    sb[a] = sb[a]! - imA * Px;
    sb[a + 1] = sb[a + 1]! - imA * Py;
    sb[b] = sb[b]! + imB * Px;
    sb[b + 1] = sb[b + 1]! + imB * Py;
    sb[a + 2] = sb[a + 2]! - sb[a + 6]! * RA[i]! * lt;
    sb[b + 2] = sb[b + 2]! - sb[b + 6]! * RB[i]! * lt;
  }
}

/** Applies every contact's accumulated impulse, 3D. Angular: dw_A = -I_A^-1 (ra n x P), dw_B = I_B^-1 (-rb n x P). */
function warmStart3D(cs: CollisionState, buf: ContactBuffer): void {
  const n = buf.count,
    sb = cs.bodyState;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz,
    RA = buf.ra,
    RB = buf.rb;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2;
  for (let i = 0; i < n; i++) {
    const ln = LN[i]!,
      l1 = L1[i]!,
      l2 = L2[i]!;
    if (ln === 0 && l1 === 0 && l2 === 0) continue;
    const a = IA[i]! * 12,
      b = IB[i]! * 12;
    sb[a + 11] = 1;
    sb[b + 11] = 1;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!,
      t1x = T1X[i]!,
      t1y = T1Y[i]!,
      t1z = T1Z[i]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const Px = ln * nx + l1 * t1x + l2 * t2x,
      Py = ln * ny + l1 * t1y + l2 * t2y,
      Pz = ln * nz + l1 * t1z + l2 * t2z;
    const imA = sb[a + 9]!,
      imB = sb[b + 9]!;
    sb[a] = sb[a]! - imA * Px;
    sb[a + 1] = sb[a + 1]! - imA * Py;
    sb[a + 2] = sb[a + 2]! - imA * Pz;
    sb[b] = sb[b]! + imB * Px;
    sb[b + 1] = sb[b + 1]! + imB * Py;
    sb[b + 2] = sb[b + 2]! + imB * Pz;
    const cx = ny * Pz - nz * Py,
      cy = nz * Px - nx * Pz,
      cz = nx * Py - ny * Px;
    const ka = sb[a + 10]! * RA[i]!,
      kb = sb[b + 10]! * RB[i]!;
    sb[a + 3] = sb[a + 3]! - ka * cx;
    sb[a + 4] = sb[a + 4]! - ka * cy;
    sb[a + 5] = sb[a + 5]! - ka * cz;
    sb[b + 3] = sb[b + 3]! - kb * cx;
    sb[b + 4] = sb[b + 4]! - kb * cy;
    sb[b + 5] = sb[b + 5]! - kb * cz;
  }
}

/**
 * One Gauss-Seidel sweep over the 2D ball contacts: with soft bias if `useBias`, else the relax sweep,
 * which takes the rows against static bodies first and last and solves the support rows (frictionless,
 * or with the heavier ball above) with the lower ball held when that only slows the upper one
 * (solver/support.ts; (downX, downY) is the unit vector along gravity, (0, 0) without). The substep,
 * push-out cap, down vector and soft coefficients are read from `solveParams`.
 */
function solve2D(cs: CollisionState, buf: ContactBuffer, useBias: boolean): void {
  const sp = solveParams;
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[2]!,
    downY = sp[3]!;
  const n = buf.count,
    sb = cs.bodyState;
  const invH = 1 / hs;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    RA = buf.ra,
    RB = buf.rb,
    S0 = buf.separation;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    FB = buf.frictionBound,
    RP = buf.rigidPartner;
  const LN = buf.normalImpulse,
    LT = buf.tangentImpulse1,
    MAXN = buf.maxNormalImpulse;
  const dBias = sp[4]!,
    dMass = sp[5]!,
    dImp = sp[6]!;
  const rBias = sp[7]!,
    rMass = sp[8]!,
    rImp = sp[9]!;

  // The sweep with bias takes the rows in order. The relax sweep takes first the touching rows that
  // hold a ball under a heavier one against a static body (solver/support.ts markFirstRelaxRows), so that ball
  // is at rest when the support row above it is relaxed and may hold it, taking the heavy ball's
  // push-out speed away; then the rows between two balls; then the rows against static bodies (walls,
  // floor, segments), which take out what the others pushed into them.
  const first = relaxFirst;
  const end = useBias ? n : 3 * n;
  for (let k = 0; k < end; k++) {
    const i = k < n ? k : k < 2 * n ? k - n : k - 2 * n;
    if (!useBias && (k < n ? first[i] === 0 : k < 2 * n === (IA[i] === 0))) continue;
    const a = IA[i]! * 8,
      b = IB[i]! * 8;
    const nx = NX[i]!,
      ny = NY[i]!;
    const imA = sb[a + 5]!,
      imB = sb[b + 5]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!;
    // The normal impulse's inverse masses and effective mass: a support row of the relax sweep, one
    // without friction or one whose upper ball is the heavier, may hold its lower ball (solver/support.ts).
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny);
      if ((up > SUPPORT_COS || up < -SUPPORT_COS) && (FB[i] === 0 || (up > 0 ? heavierAbove(imA, imB) : heavierAbove(imB, imA)))) {
        const va = Math.abs(vax * nx + vay * ny),
          vb = Math.abs(vbx * nx + vby * ny);
        if (up > 0 ? holdsLower(va, vb) : holdsLower(vb, va)) {
          if (up > 0) jmA = 0;
          else jmB = 0;
          nm = 1 / (jmA + jmB);
        }
      }
    }

    // Non-penetration, soft when overlapping and useBias, speculative when apart.
    const s = S0[i]! + (sb[b + 3]! - sb[a + 3]!) * nx + (sb[b + 4]! - sb[a + 4]!) * ny;
    let bias = 0,
      massScale = 1,
      impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      if (RP[i] === 1) {
        bias = rBias * s;
        massScale = rMass;
        impulseScale = rImp;
      } else {
        bias = dBias * s;
        massScale = dMass;
        impulseScale = dImp;
      }
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny;
    const oldN = LN[i]!;
    // A speculative row with no impulse whose gap stays open this substep does nothing (every impulse below is 0).
    if (s > 0 && oldN === 0 && vn + bias >= 0 && LT[i] === 0) continue;
    let lambda = -nm * massScale * (vn + bias) - impulseScale * oldN;
    let newN = oldN + lambda;
    if (newN < 0) newN = 0;
    lambda = newN - oldN;
    LN[i] = newN;
    if (lambda > MAXN[i]!) MAXN[i] = lambda;
    let Px = lambda * nx,
      Py = lambda * ny;
    vax -= jmA * Px;
    vay -= jmA * Py;
    vbx += jmB * Px;
    vby += jmB * Py;

    // Coulomb friction along t = (-ny, nx) at the contact point.
    const ra = RA[i]!,
      rb = RB[i]!;
    let wa = sb[a + 2]!,
      wb = sb[b + 2]!;
    const vt = (vbx - vax) * -ny + (vby - vay) * nx - wb * rb - wa * ra;
    lambda = -TM[i]! * vt;
    const maxF = FB[i]! * newN;
    const oldT = LT[i]!;
    let newT = oldT + lambda;
    newT = newT < -maxF ? -maxF : newT > maxF ? maxF : newT;
    lambda = newT - oldT;
    LT[i] = newT;
    Px = -lambda * ny;
    Py = lambda * nx;
    vax -= imA * Px;
    vay -= imA * Py;
    vbx += imB * Px;
    vby += imB * Py;
    wa -= sb[a + 6]! * ra * lambda;
    wb -= sb[b + 6]! * rb * lambda;

    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = wa;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = wb;
    if (newN !== 0 || newT !== 0) {
      sb[a + 7] = 1;
      sb[b + 7] = 1;
    }
  }
}

/**
 * One Gauss-Seidel sweep over the 3D ball contacts (with soft bias if `useBias`); parameters from
 * `solveParams` as solve2D, and its relax sweep as solve2D's: static rows first and last, support rows
 * (frictionless or with the heavier ball above) holding their lower ball when that only slows the upper.
 */
function solve3D(cs: CollisionState, buf: ContactBuffer, useBias: boolean): void {
  const sp = solveParams;
  const hs = sp[0]!,
    push = sp[1]!,
    downX = sp[10]!,
    downY = sp[11]!,
    downZ = sp[12]!;
  const n = buf.count,
    sb = cs.bodyState;
  const invH = 1 / hs;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz,
    RA = buf.ra,
    RB = buf.rb,
    S0 = buf.separation;
  const T1X = buf.t1x,
    T1Y = buf.t1y,
    T1Z = buf.t1z;
  const NM = buf.normalMass,
    TM = buf.tangentMass,
    FB = buf.frictionBound,
    RP = buf.rigidPartner;
  const LN = buf.normalImpulse,
    L1 = buf.tangentImpulse1,
    L2 = buf.tangentImpulse2,
    MAXN = buf.maxNormalImpulse;

  // Row order as in solve2D: the relax sweep takes the rows under heavier balls, the ball pairs, the static rows.
  const first = relaxFirst;
  const end = useBias ? n : 3 * n;
  for (let k = 0; k < end; k++) {
    const i = k < n ? k : k < 2 * n ? k - n : k - 2 * n;
    if (!useBias && (k < n ? first[i] === 0 : k < 2 * n === (IA[i] === 0))) continue;
    const a = IA[i]! * 12,
      b = IB[i]! * 12;
    const nx = NX[i]!,
      ny = NY[i]!,
      nz = NZ[i]!;
    const imA = sb[a + 9]!,
      imB = sb[b + 9]!;
    let vax = sb[a]!,
      vay = sb[a + 1]!,
      vaz = sb[a + 2]!,
      vbx = sb[b]!,
      vby = sb[b + 1]!,
      vbz = sb[b + 2]!;
    // A support row of the relax sweep may hold its lower ball (solver/support.ts), as in solve2D.
    let jmA = imA,
      jmB = imB,
      nm = NM[i]!;
    if (!useBias && imA > 0 && imB > 0 && nm > 0) {
      const up = -(downX * nx + downY * ny + downZ * nz);
      if ((up > SUPPORT_COS || up < -SUPPORT_COS) && (FB[i] === 0 || (up > 0 ? heavierAbove(imA, imB) : heavierAbove(imB, imA)))) {
        const va = Math.abs(vax * nx + vay * ny + vaz * nz),
          vb = Math.abs(vbx * nx + vby * ny + vbz * nz);
        if (up > 0 ? holdsLower(va, vb) : holdsLower(vb, va)) {
          if (up > 0) jmA = 0;
          else jmB = 0;
          nm = 1 / (jmA + jmB);
        }
      }
    }

    const s = S0[i]! + (sb[b + 6]! - sb[a + 6]!) * nx + (sb[b + 7]! - sb[a + 7]!) * ny + (sb[b + 8]! - sb[a + 8]!) * nz;
    let bias = 0,
      massScale = 1,
      impulseScale = 0;
    if (s > 0) {
      bias = s * invH;
    } else if (useBias) {
      const at = RP[i] === 1 ? 7 : 4;
      bias = sp[at]! * s;
      massScale = sp[at + 1]!;
      impulseScale = sp[at + 2]!;
      if (bias < -push) bias = -push;
    }
    const vn = (vbx - vax) * nx + (vby - vay) * ny + (vbz - vaz) * nz;
    const oldN = LN[i]!;
    let newN = oldN - nm * massScale * (vn + bias) - impulseScale * oldN;
    if (newN < 0) newN = 0;
    const dl = newN - oldN;
    LN[i] = newN;
    if (dl > MAXN[i]!) MAXN[i] = dl;
    vax -= jmA * dl * nx;
    vay -= jmA * dl * ny;
    vaz -= jmA * dl * nz;
    vbx += jmB * dl * nx;
    vby += jmB * dl * ny;
    vbz += jmB * dl * nz;

    // Friction in the tangent plane, clamped to the Coulomb cone.
    const ra = RA[i]!,
      rb = RB[i]!;
    let wax = sb[a + 3]!,
      way = sb[a + 4]!,
      waz = sb[a + 5]!,
      wbx = sb[b + 3]!,
      wby = sb[b + 4]!,
      wbz = sb[b + 5]!;
    let ux = vbx - vax,
      uy = vby - vay,
      uz = vbz - vaz;
    const sx = -rb * wbx - ra * wax,
      sy = -rb * wby - ra * way,
      sz = -rb * wbz - ra * waz;
    ux += sy * nz - sz * ny;
    uy += sz * nx - sx * nz;
    uz += sx * ny - sy * nx;
    const t1x = T1X[i]!,
      t1y = T1Y[i]!,
      t1z = T1Z[i]!;
    const t2x = ny * t1z - nz * t1y,
      t2y = nz * t1x - nx * t1z,
      t2z = nx * t1y - ny * t1x;
    const tm = TM[i]!;
    const o1 = L1[i]!,
      o2 = L2[i]!;
    let n1 = o1 - tm * (ux * t1x + uy * t1y + uz * t1z);
    let n2 = o2 - tm * (ux * t2x + uy * t2y + uz * t2z);
    const maxF = FB[i]! * newN;
    const mag2 = n1 * n1 + n2 * n2;
    if (mag2 > maxF * maxF) {
      const k = maxF / Math.sqrt(mag2);
      n1 *= k;
      n2 *= k;
    }
    const d1 = n1 - o1,
      d2 = n2 - o2;
    L1[i] = n1;
    L2[i] = n2;
    if (d1 !== 0 || d2 !== 0) {
      const Px = d1 * t1x + d2 * t2x,
        Py = d1 * t1y + d2 * t2y,
        Pz = d1 * t1z + d2 * t2z;
      vax -= imA * Px;
      vay -= imA * Py;
      vaz -= imA * Pz;
      vbx += imB * Px;
      vby += imB * Py;
      vbz += imB * Pz;
      const cx = ny * Pz - nz * Py,
        cy = nz * Px - nx * Pz,
        cz = nx * Py - ny * Px;
      const ka = sb[a + 10]! * ra,
        kb = sb[b + 10]! * rb;
      wax -= ka * cx;
      way -= ka * cy;
      waz -= ka * cz;
      wbx -= kb * cx;
      wby -= kb * cy;
      wbz -= kb * cz;
    }
    sb[a] = vax;
    sb[a + 1] = vay;
    sb[a + 2] = vaz;
    sb[a + 3] = wax;
    sb[a + 4] = way;
    sb[a + 5] = waz;
    sb[b] = vbx;
    sb[b + 1] = vby;
    sb[b + 2] = vbz;
    sb[b + 3] = wbx;
    sb[b + 4] = wby;
    sb[b + 5] = wbz;
    if (newN !== 0 || n1 !== 0 || n2 !== 0) {
      sb[a + 11] = 1;
      sb[b + 11] = 1;
    }
  }
}

/** Scratch of applyRestitution: the indices of the rows that take part, in row order. Not world state. */
let restitutionRows = new Int32Array(256);

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
  const threshold = cs.settings.restitutionThreshold,
    elasticThreshold = cs.settings.elasticRestitutionThreshold;
  const iterations = cs.settings.restitutionIterations;
  const n = buf.count,
    sb = cs.bodyState;
  const S = stride(world),
    is2D = S === 8,
    im = is2D ? 5 : 9;
  const IA = buf.ia,
    IB = buf.ib,
    NX = buf.nx,
    NY = buf.ny,
    NZ = buf.nz;
  const NM = buf.normalMass,
    E = buf.restitution,
    RV = buf.relativeVelocity,
    IV = buf.impactVelocity;
  const MAXN = buf.maxNormalImpulse,
    TOT = buf.totalNormalImpulse,
    IMP = buf.impulse;
  // Reuse relativeVelocity as the target speed, maxNormalImpulse as the rebound's accumulated impulse
  // and totalNormalImpulse as its cap (all spent by now); a negative target marks a contact that
  // takes no part. A contact that closed its gap only in the last substep may still be approaching:
  // the impulse to stop that is part of its compression, so it counts toward the cap too.
  // The rows that take part, in row order (the passes below visit only these).
  if (restitutionRows.length < n) restitutionRows = new Int32Array(Math.max(n, 2 * restitutionRows.length));
  const rows = restitutionRows;
  let taking = 0;
  let bouncing = 0;
  for (let i = 0; i < n; i++) {
    const e = E[i]!;
    if (MAXN[i] === 0) {
      RV[i] = -1;
      continue;
    }
    rows[taking++] = i;
    MAXN[i] = 0;
    if (e > 0 && RV[i]! < -(e >= 1 ? elasticThreshold : threshold)) {
      RV[i] = -e * IV[i]!;
      const a = IA[i]! * S,
        b = IB[i]! * S;
      let vn = (sb[b]! - sb[a]!) * NX[i]! + (sb[b + 1]! - sb[a + 1]!) * NY[i]!;
      if (!is2D) vn += (sb[b + 2]! - sb[a + 2]!) * NZ[i]!;
      const stop = vn < 0 ? -NM[i]! * vn : 0;
      TOT[i] = stop + e * (TOT[i]! + stop);
      bouncing++;
    } else RV[i] = 0;
  }
  if (bouncing === 0) return;
  for (let it = 0; it < iterations; it++) {
    for (let k = 0; k < taking; k++) {
      const i = rows[k]!;
      const target = RV[i]!;
      const a = IA[i]! * S,
        b = IB[i]! * S;
      const nx = NX[i]!,
        ny = NY[i]!,
        nz = NZ[i]!;
      let vn = (sb[b]! - sb[a]!) * nx + (sb[b + 1]! - sb[a + 1]!) * ny;
      if (!is2D) vn += (sb[b + 2]! - sb[a + 2]!) * nz;
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
      sb[a] = sb[a]! - ka * nx;
      sb[a + 1] = sb[a + 1]! - ka * ny;
      sb[b] = sb[b]! + kb * nx;
      sb[b + 1] = sb[b + 1]! + kb * ny;
      if (!is2D) {
        sb[a + 2] = sb[a + 2]! - ka * nz;
        sb[b + 2] = sb[b + 2]! + kb * nz;
      }
    }
  }
}
