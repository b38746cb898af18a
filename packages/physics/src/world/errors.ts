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
