import type { KernelArray } from '../threads/kernel-types.js';
import { MIN_PARALLEL_PER_THREAD, runOnPool } from '../threads/parallel.js';
import { throwNonFinite } from '../world/errors.js';
import { fusedForcesOn } from '../world/fused-state.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
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

/** The fields a check reads, each with the name the error gives it ('Force.x'). */
type Fields = ReadonlyArray<readonly [string, Float64Array]>;

/** The x, y (and in 3D z) components of the vector store `s`, named `name.x` and so on. */
function vector(name: string, s: { x: Float64Array; y: Float64Array; z: Float64Array }, is2D: boolean): Fields {
  return is2D
    ? [
        [`${name}.x`, s.x],
        [`${name}.y`, s.y],
      ]
    : [
        [`${name}.x`, s.x],
        [`${name}.y`, s.y],
        [`${name}.z`, s.z],
      ];
}

/**
 * The finiteness sum of `fields` over `ents` (0: all finite), by the sum function of their count (1 to
 * 4; six and seven fields are two passes, the first four and the rest).
 */
function sumFields(ents: ArrayLike<number>, dense: boolean, fields: Fields): number {
  const a = fields[0]![1],
    b = fields[fields.length > 1 ? 1 : 0]![1];
  switch (fields.length) {
    case 1:
    case 2:
      return sum2(ents, dense, a, b);
    case 3:
      return sum3(ents, dense, a, b, fields[2]![1]);
    case 4:
      return sum4(ents, dense, a, b, fields[2]![1], fields[3]![1]);
    case 6:
      return sum4(ents, dense, a, b, fields[2]![1], fields[3]![1]) + sum2(ents, dense, fields[4]![1], fields[5]![1]);
    default:
      return sum4(ents, dense, a, b, fields[2]![1], fields[3]![1]) + sum3(ents, dense, fields[4]![1], fields[5]![1], fields[6]![1]);
  }
}

/**
 * Checks `fields` of `ents` after `stage`; `pooled`: a world with threads splits the probe over them
 * (kernel finiteProbe: the same test). Throws a NonFiniteStateError naming the first entity and field
 * that is NaN or infinite, and the stage.
 */
function checkFields(world: PhysicsWorld, stage: StageName, ents: ArrayLike<number>, fields: Fields, pooled: boolean): void {
  if (ents.length === 0) return;
  const dense = ents.length === world.entityIndex.maxId;
  const par =
    !pooled || world.threadPool === null
      ? null
      : runOnPool(
          world.threadPool,
          `${stage} stage finiteness check`,
          finiteProbe,
          fields.map((f) => f[1]),
          EMPTY_PARAMS,
          ents.length,
          dense ? null : ents,
          MIN_PARALLEL_PER_THREAD,
        );
  if ((par ?? sumFields(ents, dense, fields)) !== 0) throwNonFinite(world, stage, ents, fields);
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
  if (stage === 'forces') {
    const F = c.Force,
      T = c.Torque;
    const forced = query(world, [F]);
    if (!fusedForcesOn(world)) checkFields(world, stage, forced, vector('Force', F, is2D), true);
    checkFields(world, stage, query(world, [T]), is2D ? [['Torque.z', T.z]] : vector('Torque', T, false), true);
  }
  if (level === 0) return;
  const P = c.Position,
    V = c.Velocity,
    W = c.AngularVelocity;
  // Velocities first: a NaN velocity makes the position NaN in the same stage, and it is the cause.
  if (level === 2) checkFields(world, stage, query(world, [P, V]), [...vector('Velocity', V, is2D), ...vector('Position', P, is2D)], true);
  if (is2D) {
    checkFields(
      world,
      stage,
      query(world, [W, c.Angle]),
      [
        ['AngularVelocity.z', W.z],
        ['Angle.value', c.Angle.value],
      ],
      false,
    );
  } else {
    const Q = c.Orientation;
    const fields: Fields = [...vector('AngularVelocity', W, false), ...vector('Orientation', Q, false), ['Orientation.w', Q.w]];
    checkFields(world, stage, query(world, [W, Q]), fields, false);
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
  const fields = vector('Force', world.components.Force, world.dimensions === 2);
  if (sumFields(ents, false, fields) !== 0) throwNonFinite(world, 'forces', ents, fields);
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
