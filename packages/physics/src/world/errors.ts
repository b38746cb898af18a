import { currentHandle } from './handles.js';
import type { PhysicsWorld } from './options.js';

/**
 * Thrown by `step` when a body's state becomes NaN or infinite. It is a RangeError so callers that
 * catch bad input catch it too. The step stops at the stage that found it, so the NaN does not reach
 * the collision solver or any other body. `entity`, `field` and `stage` say where.
 * @category Utilities
 */
export class NonFiniteStateError extends RangeError {
  /** The entity whose state is not finite: its handle (see world/handles.ts; equal to its slot on the slot's first life). */
  readonly entity: number;
  /** The field, e.g. 'Velocity.y'. */
  readonly field: string;
  /** The stage that found it. */
  readonly stage: string;
  constructor(entity: number, field: string, value: number, stage: string, detail: string) {
    super(
      `bitphysics: entity ${entity} has a non-finite ${field} (${value}) after stage '${stage}'. ${detail} ` +
        'A NaN or infinity was written into a component, or a force law divided by zero (add softening), or the step is unstable (smaller dt or more substeps).',
    );
    this.name = 'NonFiniteStateError';
    this.entity = entity;
    this.field = field;
    this.stage = stage;
  }
}

/**
 * Finds the first entity of `ents` (slots) with a non-finite position, velocity or angular velocity
 * and throws a NonFiniteStateError naming it by its handle. Called by systems whose cheap running check (a sum that
 * turned NaN) failed; returns quietly if nothing is non-finite (the sum overflowed on huge but
 * finite values).
 * @category Utilities
 */
export function reportNonFinite(world: PhysicsWorld, ents: ArrayLike<number>, stage: string): void {
  const c = world.components;
  // Velocities first: a NaN velocity makes the position NaN in the same step, and the velocity is the cause.
  const fields: Array<[string, Float64Array]> = [
    ['Velocity.x', c.Velocity.x],
    ['Velocity.y', c.Velocity.y],
    ['Velocity.z', c.Velocity.z],
    ['Position.x', c.Position.x],
    ['Position.y', c.Position.y],
    ['Position.z', c.Position.z],
    ['AngularVelocity.z', c.AngularVelocity.z],
    ['AngularVelocity.x', c.AngularVelocity.x],
    ['AngularVelocity.y', c.AngularVelocity.y],
  ];
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    for (const [name, arr] of fields) {
      if (e >= arr.length) continue; // a store not allocated yet (world/components.ts): no entity has it
      const v = arr[e]!;
      if (!Number.isFinite(v)) {
        const f = (a: Float64Array) => (e < a.length ? a[e] : 'none');
        const detail =
          `Its inputs: previous position (${f(c.PreviousPosition.x)}, ${f(c.PreviousPosition.y)}, ${f(c.PreviousPosition.z)}), ` +
          `force (${f(c.Force.x)}, ${f(c.Force.y)}, ${f(c.Force.z)}) N, inverse mass ${f(c.Mass.inv)} 1/kg.`;
        throw new NonFiniteStateError(currentHandle(world, e), name, v, stage, detail);
      }
    }
  }
}

/**
 * The slow pass of a finiteness check (step/finite.ts), run once a fast pass found a non-finite value:
 * throws a NonFiniteStateError naming the first entity of `ents` (slots) and the first of `fields`
 * ([name, values] pairs) that is not finite, found by `stage`.
 * @throws NonFiniteStateError, or an Error when no value of the fields is non-finite.
 * @category Utilities
 */
export function throwNonFinite(
  world: PhysicsWorld,
  stage: string,
  ents: ArrayLike<number>,
  fields: ReadonlyArray<readonly [string, Float64Array]>,
): never {
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    for (const [field, values] of fields) {
      const v = values[e]!;
      if (Number.isFinite(v)) continue;
      const c = world.components;
      const at = (a: Float64Array) => a[e];
      throw new NonFiniteStateError(
        currentHandle(world, e),
        field,
        v,
        stage,
        `Its state: position (${at(c.Position.x)}, ${at(c.Position.y)}, ${at(c.Position.z)}) m, ` +
          `velocity (${at(c.Velocity.x)}, ${at(c.Velocity.y)}, ${at(c.Velocity.z)}) m/s, ` +
          `force (${at(c.Force.x)}, ${at(c.Force.y)}, ${at(c.Force.z)}) N, inverse mass ${at(c.Mass.inv)} 1/kg.`,
      );
    }
  }
  throw new Error(`bitphysics: the finiteness check of stage '${stage}' found a non-finite value it could not name`);
}
