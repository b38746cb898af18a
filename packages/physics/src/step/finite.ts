import type { KernelArray } from '../threads/kernel-types.js';
import { MIN_PARALLEL_PER_THREAD, runOnPool } from '../threads/parallel.js';
import { throwNonFinite } from '../world/errors.js';
import { fusedForcesOn } from '../world/fused-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import type { CheckTerms } from '../world/scratch.js';
import type { StageName } from '../world/stage-names.js';

/**
 * The finiteness check `step` runs at the end of each stage: a NaN or infinity in a body's state is
 * reported by the stage that wrote it, naming the entity and the field, before the next stage can
 * spread it to another body (the collision solver couples bodies; a force law reads other bodies).
 *
 * After `forces`: the force and torque accumulators. After every stage (`forces` included) that ran
 * a system not marked `trustFiniteOutput`: Velocity and Position of every entity that has both, and
 * the angular state of every entity that turns (2D: AngularVelocity.z and Angle.value; 3D: the three
 * components of AngularVelocity and the four of Orientation).
 * Built-in systems that write no body state (force laws write only forces; broadphase and narrowphase
 * only contacts) or check what they write themselves (the integrators' running sums over their
 * bodies' positions and velocities, the contact solver's over its bodies, emitters, sleeping) are
 * marked, so a stage made only of them is not checked again (after `integrate` only the turning
 * bodies are); a user system added with `addSystem` is always checked after, and at once when another system follows
 * it in its stage (step/step.ts), so a NaN it writes before the contact solver does not spread.
 * In 2D the z components of the linear state are not part of the motion and are not checked;
 * `clearForces` writes zeros and is never checked. In a substep that runs the fused force-and-integrate
 * pass (integrators/fused-gate.ts) the forces are written by the integrator, which checks them itself
 * and reports a non-finite one as this check would (field 'Force.x', 'Force.y' or 'Force.z', stage 'forces').
 * It tests each body's force before it writes that body's velocity and position, so the body named and
 * every body after it in the pass keep their motion state from before the substep, and no position or
 * velocity is made non-finite by the force. One difference from the separate stages remains: the bodies
 * the pass moved before it (with finite forces) stay moved, where the forces stage would have thrown
 * before any body moved; integrators/semi-implicit-euler.ts (`fusedForced2`) lists which.
 *
 * Cost: one fused pass over the moving bodies (and one over the turning ones), a multiply and an add
 * per field, and a second pass to name the culprit only when the first finds one.
 */

/**
 * The finiteness sum of arrays `a` and `b` over `ents` (`dense`: ents are the ids 1..n): the sum of
 * x * 0 over their values, 0 (or -0) when every value is finite, NaN when one is not.
 */
function sum2(ents: ArrayLike<number>, dense: boolean, a: Float64Array, b: Float64Array): number {
  let s = 0;
  const n = ents.length;
  if (dense) {
    // The last id first, then the ids in pairs (id n twice when n is even: a check, not a sum). Nothing
    // follows the loops but the return: a function run once a step has its loop compiled on the
    // stack (OSR) in its first call, and an operation after the loop that had not run by then threw
    // that code away at every later call (140 times in 100 steps of a threaded balls-in-box).
    if (n > 0) s = a[n]! * 0 + b[n]! * 0;
    for (let e = 1; e < n; e += 2) s += a[e]! * 0 + b[e]! * 0 + (a[e + 1]! * 0 + b[e + 1]! * 0);
  } else
    for (let i = 0; i < n; i++) {
      const e = ents[i]!;
      s += a[e]! * 0 + b[e]! * 0;
    }
  return s;
}

/** `sum2` over three arrays. */
function sum3(ents: ArrayLike<number>, dense: boolean, a: Float64Array, b: Float64Array, c: Float64Array): number {
  let s = 0;
  const n = ents.length;
  if (dense) {
    if (n > 0) s = a[n]! * 0 + b[n]! * 0 + c[n]! * 0;
    for (let e = 1; e < n; e += 2) s += a[e]! * 0 + b[e]! * 0 + c[e]! * 0 + (a[e + 1]! * 0 + b[e + 1]! * 0 + c[e + 1]! * 0);
  } else
    for (let i = 0; i < n; i++) {
      const e = ents[i]!;
      s += a[e]! * 0 + b[e]! * 0 + c[e]! * 0;
    }
  return s;
}

/** `sum2` over four arrays. */
function sum4(ents: ArrayLike<number>, dense: boolean, a: Float64Array, b: Float64Array, c: Float64Array, d: Float64Array): number {
  let s = 0;
  const n = ents.length;
  if (dense) {
    if (n > 0) s = a[n]! * 0 + b[n]! * 0 + (c[n]! * 0 + d[n]! * 0);
    for (let e = 1; e < n; e += 2) {
      s += a[e]! * 0 + b[e]! * 0 + (c[e]! * 0 + d[e]! * 0) + (a[e + 1]! * 0 + b[e + 1]! * 0 + (c[e + 1]! * 0 + d[e + 1]! * 0));
    }
  } else
    for (let i = 0; i < n; i++) {
      const e = ents[i]!;
      s += a[e]! * 0 + b[e]! * 0 + (c[e]! * 0 + d[e]! * 0);
    }
  return s;
}

const EMPTY_PARAMS: ArrayLike<number> = [];

/** What the probes hold between checks: nothing of any world. */
const NONE = new Float64Array(0);

/**
 * The arrays of each check, by their count: set just before the check, emptied (`NONE`) just after,
 * so a check allocates nothing and holds on to no world's stores (the stores' arrays themselves are
 * read anew each time: a lazy store gets its arrays on first use, a restore may replace them).
 */
const probes: Float64Array[][] = [[], [NONE], [NONE, NONE], [NONE, NONE, NONE], [NONE, NONE, NONE, NONE], [], [], []];
for (const n of [5, 6, 7]) for (let i = 0; i < n; i++) probes[n]!.push(NONE);

// The names the error gives the arrays of each check, in their order (a 2D force check uses the first two).
const FORCE = ['Force.x', 'Force.y', 'Force.z'];
const TORQUE = ['Torque.x', 'Torque.y', 'Torque.z'];
const TORQUE_2D = ['Torque.z'];
const LINEAR_2D = ['Velocity.x', 'Velocity.y', 'Position.x', 'Position.y'];
const LINEAR_3D = ['Velocity.x', 'Velocity.y', 'Velocity.z', 'Position.x', 'Position.y', 'Position.z'];
const ANGULAR_2D = ['AngularVelocity.z', 'Angle.value'];
const ANGULAR_3D = [
  'AngularVelocity.x',
  'AngularVelocity.y',
  'AngularVelocity.z',
  'Orientation.x',
  'Orientation.y',
  'Orientation.z',
  'Orientation.w',
];

/** The probe of `n` arrays (see `probes`). */
function probeOf(n: number): Float64Array[] {
  return probes[n]!;
}

/** Puts the x, y (and in 3D z) arrays of the vector store `s` into `A` from index `at`; returns the next index. */
function putVector(A: Float64Array[], at: number, s: { x: Float64Array; y: Float64Array; z: Float64Array }, is2D: boolean): number {
  A[at] = s.x;
  A[at + 1] = s.y;
  if (is2D) return at + 2;
  A[at + 2] = s.z;
  return at + 3;
}

/**
 * The finiteness sum of `arrays` over `ents` (0: all finite), by the sum function of their count (1 to
 * 4; six and seven arrays are two passes, the first four and the rest).
 */
function sumFields(ents: ArrayLike<number>, dense: boolean, arrays: readonly Float64Array[]): number {
  const a = arrays[0]!,
    b = arrays[arrays.length > 1 ? 1 : 0]!;
  switch (arrays.length) {
    case 1:
    case 2:
      return sum2(ents, dense, a, b);
    case 3:
      return sum3(ents, dense, a, b, arrays[2]!);
    case 4:
      return sum4(ents, dense, a, b, arrays[2]!, arrays[3]!);
    case 6:
      return sum4(ents, dense, a, b, arrays[2]!, arrays[3]!) + sum2(ents, dense, arrays[4]!, arrays[5]!);
    default:
      return sum4(ents, dense, a, b, arrays[2]!, arrays[3]!) + sum3(ents, dense, arrays[4]!, arrays[5]!, arrays[6]!);
  }
}

/**
 * Checks the arrays `A` (a probe, named `names`, in order) over `ents` after `stage`, then empties the
 * probe; `pooled`: a world with threads splits the check over them (kernel finiteProbe: the same test).
 * Throws a NonFiniteStateError naming the first entity and field that is NaN or infinite, and the stage.
 */
function checkFields(
  world: PhysicsWorld,
  stage: StageName,
  ents: ArrayLike<number>,
  A: Float64Array[],
  names: readonly string[],
  pooled: boolean,
): void {
  const dense = ents.length === world.entityIndex.maxId;
  const par =
    ents.length === 0 || !pooled || world.threadPool === null
      ? null
      : runOnPool(
          world.threadPool,
          `${stage} stage finiteness check`,
          finiteProbe,
          A,
          EMPTY_PARAMS,
          ents.length,
          dense ? null : ents,
          MIN_PARALLEL_PER_THREAD,
        );
  const bad = ents.length > 0 && (par ?? sumFields(ents, dense, A)) !== 0;
  const fields = bad ? A.map((a, i) => [names[i]!, a] as const) : null;
  A.fill(NONE);
  if (fields !== null) throwNonFinite(world, stage, ents, fields);
}

/** The query terms of the checks, made once per world (`world.scratch.checkTerms`): no allocation a step. */
function termsOf(world: PhysicsWorld): CheckTerms {
  let t = world.scratch.checkTerms;
  if (t === undefined) {
    const c = world.components;
    t = {
      force: [c.Force],
      torque: [c.Torque],
      linear: [c.Position, c.Velocity],
      angular: world.dimensions === 2 ? [c.AngularVelocity, c.Angle] : [c.AngularVelocity, c.Orientation],
    };
    world.scratch.checkTerms = t;
  }
  return t;
}

/**
 * Makes the checks' queries of `world` (see termsOf) while it has no entity, so that the first step
 * does not fill them (integrators/queries.ts makeIntegratorQueries). createPhysicsWorld calls it.
 * @category World and step
 */
export function makeCheckQueries(world: PhysicsWorld): void {
  const t = termsOf(world);
  query(world, t.force);
  query(world, t.torque);
  query(world, t.linear);
  query(world, t.angular);
}

/**
 * Checks what `stage` may have written (see the module comment): the force and torque accumulators
 * after `forces`, the angular state if `level` >= 1 and the linear state if `level` is 2. Throws a NonFiniteStateError naming the first
 * entity (its handle) and field that is NaN or infinite, and the stage.
 * @category World and step
 */
export function checkStageState(world: PhysicsWorld, stage: StageName, level: 0 | 1 | 2): void {
  const c = world.components;
  const is2D = world.dimensions === 2;
  const terms = termsOf(world);
  if (stage === 'forces') {
    const F = c.Force,
      T = c.Torque;
    const forced = query(world, terms.force);
    if (!fusedForcesOn(world)) {
      const A = probeOf(is2D ? 2 : 3);
      putVector(A, 0, F, is2D);
      checkFields(world, stage, forced, A, FORCE, true);
    }
    const A = probeOf(is2D ? 1 : 3);
    if (is2D) A[0] = T.z;
    else putVector(A, 0, T, false);
    checkFields(world, stage, query(world, terms.torque), A, is2D ? TORQUE_2D : TORQUE, true);
  }
  if (level === 0) return;
  const P = c.Position,
    V = c.Velocity,
    W = c.AngularVelocity;
  // Velocities first: a NaN velocity makes the position NaN in the same stage, and it is the cause.
  if (level === 2) {
    const A = probeOf(is2D ? 4 : 6);
    putVector(A, putVector(A, 0, V, is2D), P, is2D);
    checkFields(world, stage, query(world, terms.linear), A, is2D ? LINEAR_2D : LINEAR_3D, true);
  }
  if (is2D) {
    const A = probeOf(2);
    A[0] = W.z;
    A[1] = c.Angle.value;
    checkFields(world, stage, query(world, terms.angular), A, ANGULAR_2D, false);
  } else {
    const Q = c.Orientation;
    const A = probeOf(7);
    putVector(A, 0, W, false);
    A[3] = Q.x;
    A[4] = Q.y;
    A[5] = Q.z;
    A[6] = Q.w;
    checkFields(world, stage, query(world, terms.angular), A, ANGULAR_3D, false);
  }
}

/**
 * For the fused force-and-integrate pass (integrators/semi-implicit-euler.ts), after its running check
 * failed: throws the NonFiniteStateError this module's check of the forces stage would have thrown (the
 * first of `ents` whose force is NaN or infinite: Force.x, Force.y, and in 3D Force.z; stage 'forces');
 * returns if every force is finite (the caller then names the position or velocity).
 * @category World and step
 */
export function reportNonFiniteForces(world: PhysicsWorld, ents: ArrayLike<number>): void {
  const is2D = world.dimensions === 2;
  const A = probeOf(is2D ? 2 : 3);
  putVector(A, 0, world.components.Force, is2D);
  checkFields(world, 'forces', ents, A, FORCE, false);
}

/**
 * Finiteness probe of the step's stage checks (step/finite.ts): the sum of a[e] * 0 over every
 * array of A and every entity of the range; 0 when all are finite, NaN as soon as one is not (the
 * order of the sum cannot change that). P unused.
 */
export function finiteProbe(A: KernelArray[], P: Float64Array, ids: Int32Array | null, lo: number, hi: number): number {
  let s = P.length * 0;
  for (let j = 0; j < A.length; j++) {
    const a = A[j] as Float64Array;
    if (ids === null) for (let e = lo + 1; e <= hi; e++) s += a[e]! * 0;
    else for (let i = lo; i < hi; i++) s += a[ids[i]!]! * 0;
  }
  return s;
}
