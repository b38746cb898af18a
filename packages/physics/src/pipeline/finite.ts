import type { PhysicsWorld } from '../world.js';
import { NonFiniteStateError } from '../errors.js';
import { query } from '../query.js';
import { currentHandle } from '../handles.js';
import type { StageName, System } from './stages.js';

/**
 * The finiteness check `step` runs at the end of each stage: a NaN or infinity in a body's state is
 * reported by the stage that wrote it, naming the entity and the field, before the next stage can
 * spread it to another body (the collision solver couples bodies; a force law reads other bodies).
 *
 * After `forces`: the force and torque accumulators. After every stage (`forces` included) that ran
 * a system not marked `trustFiniteOutput`: Velocity, Position, and the angular state (2D:
 * AngularVelocity.z and Angle.value; 3D: the three components of each and the four of Orientation).
 * Built-in systems that write no body state (force laws write only forces; broadphase and narrowphase
 * only contacts) or check what they write themselves (emitters, sleeping) are marked, so a stage made
 * only of them is not checked again; a user system added with `addSystem` is always checked after.
 * In 2D the z components of the linear state are not part of the motion and are not checked;
 * `clearForces` writes zeros and is never checked.
 *
 * Cost: one pass over the bodies that have each checked component, a multiply and an add per field
 * (x * 0 is NaN exactly when x is NaN or infinite), and a second pass to name the culprit only when
 * the first finds one.
 */

const trusted = new WeakSet<System>();

/**
 * Marks built-in systems that write no body state, or check what they write and throw
 * NonFiniteStateError themselves: a stage made only of such systems is not checked again.
 */
export function trustFiniteOutput(...systems: System[]): void {
  for (const s of systems) trusted.add(s);
}

/** Whether a stage that ran `systems` may have written body state `step` has not checked yet. */
export function stageNeedsCheck(stage: StageName, systems: readonly System[]): boolean {
  if (stage === 'clearForces' || systems.length === 0) return false;
  for (let i = 0; i < systems.length; i++) if (!trusted.has(systems[i]!)) return true;
  return false;
}

type Field = readonly [name: string, values: Float64Array];

function fieldsOf(world: PhysicsWorld, stage: 'forces' | 'state'): Array<readonly [components: object[], fields: Field[]]> {
  const c = world.components;
  const is2D = world.dimensions === 2;
  if (stage === 'forces') {
    return is2D
      ? [[[c.Force], [['Force.x', c.Force.x], ['Force.y', c.Force.y]]], [[c.Torque], [['Torque.z', c.Torque.z]]]]
      : [[[c.Force], [['Force.x', c.Force.x], ['Force.y', c.Force.y], ['Force.z', c.Force.z]]],
          [[c.Torque], [['Torque.x', c.Torque.x], ['Torque.y', c.Torque.y], ['Torque.z', c.Torque.z]]]];
  }
  // Velocities first: a NaN velocity makes the position NaN in the same stage, and it is the cause.
  return is2D
    ? [
        [[c.Velocity], [['Velocity.x', c.Velocity.x], ['Velocity.y', c.Velocity.y]]],
        [[c.Position], [['Position.x', c.Position.x], ['Position.y', c.Position.y]]],
        [[c.AngularVelocity], [['AngularVelocity.z', c.AngularVelocity.z]]],
        [[c.Angle], [['Angle.value', c.Angle.value]]],
      ]
    : [
        [[c.Velocity], [['Velocity.x', c.Velocity.x], ['Velocity.y', c.Velocity.y], ['Velocity.z', c.Velocity.z]]],
        [[c.Position], [['Position.x', c.Position.x], ['Position.y', c.Position.y], ['Position.z', c.Position.z]]],
        [[c.AngularVelocity], [['AngularVelocity.x', c.AngularVelocity.x], ['AngularVelocity.y', c.AngularVelocity.y], ['AngularVelocity.z', c.AngularVelocity.z]]],
        [[c.Orientation], [['Orientation.x', c.Orientation.x], ['Orientation.y', c.Orientation.y], ['Orientation.z', c.Orientation.z], ['Orientation.w', c.Orientation.w]]],
      ];
}

const plans = new WeakMap<PhysicsWorld, Map<'forces' | 'state', ReturnType<typeof fieldsOf>>>();

function planOf(world: PhysicsWorld, stage: 'forces' | 'state'): ReturnType<typeof fieldsOf> {
  let m = plans.get(world);
  if (!m) { m = new Map(); plans.set(world, m); }
  let p = m.get(stage);
  if (!p) { p = fieldsOf(world, stage); m.set(stage, p); }
  return p;
}

/** Sum of x * 0 over the entities: 0 if every value is finite, NaN otherwise. */
function probe(ents: ArrayLike<number>, a: Float64Array, b: Float64Array | undefined, c: Float64Array | undefined, d: Float64Array | undefined): number {
  let acc = 0;
  const n = ents.length;
  if (d) for (let i = 0; i < n; i++) { const e = ents[i]!; acc += a[e]! * 0 + b![e]! * 0 + c![e]! * 0 + d[e]! * 0; }
  else if (c) for (let i = 0; i < n; i++) { const e = ents[i]!; acc += a[e]! * 0 + b![e]! * 0 + c[e]! * 0; }
  else if (b) for (let i = 0; i < n; i++) { const e = ents[i]!; acc += a[e]! * 0 + b[e]! * 0; }
  else for (let i = 0; i < n; i++) acc += a[ents[i]!]! * 0;
  return acc;
}

/**
 * Checks what `stage` may have written (see the module comment): the force and torque accumulators
 * after `forces`, and the motion state if `state`. Throws a NonFiniteStateError naming the first
 * entity (its handle) and field that is NaN or infinite, and the stage.
 */
export function checkStageState(world: PhysicsWorld, stage: StageName, state: boolean): void {
  if (stage === 'forces') checkFields(world, stage, planOf(world, 'forces'));
  if (state) checkFields(world, stage, planOf(world, 'state'));
}

function checkFields(world: PhysicsWorld, stage: StageName, plan: ReturnType<typeof fieldsOf>): void {
  for (let g = 0; g < plan.length; g++) {
    const [components, fields] = plan[g]!;
    const ents = query(world, components);
    if (ents.length === 0) continue;
    const acc = probe(ents, fields[0]![1], fields[1]?.[1], fields[2]?.[1], fields[3]?.[1]);
    if (acc === 0) continue;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      for (const [name, values] of fields) {
        const v = values[e]!;
        if (Number.isFinite(v)) continue;
        const c = world.components;
        const at = (a: Float64Array) => a[e];
        throw new NonFiniteStateError(currentHandle(world, e), name, v, stage,
          `Its state: position (${at(c.Position.x)}, ${at(c.Position.y)}, ${at(c.Position.z)}) m, ` +
            `velocity (${at(c.Velocity.x)}, ${at(c.Velocity.y)}, ${at(c.Velocity.z)}) m/s, ` +
            `force (${at(c.Force.x)}, ${at(c.Force.y)}, ${at(c.Force.z)}) N, inverse mass ${at(c.Mass.inv)} 1/kg.`);
      }
    }
  }
}
