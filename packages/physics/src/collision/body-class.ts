import { type EcsInternals, ecsOf } from '../world/ecs-internals.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { BodyType } from './state.js';

/**
 * The class of a collider's or joint's body for the step (static, kinematic, sleeping or dynamic) and
 * the inverse mass and inertia the solver reads for it (CollisionState.bodyType, invMass, invInertia),
 * one rule for the 2D and 3D shape passes and the 3D joints. Component membership is read from bitecs'
 * masks (`lookUpBodyBits` once a pass, then `hasBit`), not with hasComponent, which looks the
 * component up in a Map at every call (four to seven calls a body a step, most of a step's time in a
 * pile asleep).
 */

/** hasBit's first argument (an index into `bits`) for the components that give a body's class. */
export const STATIC = 0,
  KINEMATIC = 1,
  SLEEPING = 2;
/** hasBit's first argument for the components that say whether and how a body turns (angular velocity, scalar or principal inertia). */
export const INERTIA = 3,
  SPIN = 4,
  INERTIA_TENSOR = 7;
/** hasBit's first argument for a 2D body's angle and for a shape body. */
export const ANGLE = 5,
  SHAPE = 6;
/** Per component above: its masks in bitecs (`NO_MASKS` if no entity ever had it) and its bit (1 then). */
const bits = { masks: [] as ArrayLike<number>[], flag: new Int32Array(8) };
const NO_MASKS: ArrayLike<number> = new Int32Array(0);

/** Fills `bits` for `world` (bitecs' masks and each component's place in them); call it before a pass's first hasBit. */
export function lookUpBodyBits(world: PhysicsWorld): void {
  const ecs = ecsOf(world),
    components = bodyComponents(world);
  for (let k = 0; k < components.length; k++) lookUpBit(ecs, k, components[k]!);
}

/** The components of `world` hasBit tests for, at their hasBit index. */
function bodyComponents(world: PhysicsWorld): object[] {
  const c = world.components;
  return [c.Static, c.Kinematic, c.Sleeping, c.Inertia, c.AngularVelocity, c.Angle, c.Shape, c.InertiaTensor];
}

function lookUpBit(ecs: EcsInternals, k: number, component: object): void {
  const d = ecs.componentMap.get(component);
  bits.masks[k] = d === undefined ? NO_MASKS : ecs.entityMasks[d.generationId]!;
  bits.flag[k] = d === undefined ? 1 : d.bitflag;
}

/** hasComponent(world, e, component k) for the world lookUpBodyBits last filled `bits` for. */
export function hasBit(k: number, e: number): boolean {
  const f = bits.flag[k]!;
  return ((bits.masks[k]![e] ?? 0) & f) === f;
}

/**
 * The classes a body can have besides dynamic, highest rank first, as hasBit indices (RANKED) and
 * BodyTypes (RANKED_TYPE): a body with the components of several takes the first one's class. Static
 * outranks kinematic (a fixed body is not driven); kinematic outranks sleeping (the sleep stage never
 * puts a kinematic body to sleep, so a Sleeping tag on one is stale, and waking it would hand it to the
 * dynamic integration and gravity).
 */
const RANKED = [STATIC, KINEMATIC, SLEEPING] as const;
const RANKED_TYPE = [BodyType.Static, BodyType.Kinematic, BodyType.Sleeping] as const;

/**
 * Writes body `b`'s class for this step into the collision state and returns it (a BodyType): the
 * first class of RANKED it has (static, kinematic or sleeping; inverse mass and inertia 0), else
 * dynamic (classifyDynamic). Needs lookUpBodyBits(world) earlier in the pass.
 * @category Collision
 */
export function classifyBody(world: PhysicsWorld, b: number): number {
  for (let k = 0; k < RANKED.length; k++) {
    if (!hasBit(RANKED[k]!, b)) continue;
    const cs = world.collision,
      t = RANKED_TYPE[k]!;
    cs.invMass[b] = 0;
    cs.invInertia[b] = 0;
    cs.bodyType[b] = t;
    return t;
  }
  return classifyDynamic(world, b);
}

/** rankedLists' answer: live query results, lowest rank first. */
const lists: ArrayLike<number>[] = [];

/**
 * classifyBody's classes for a pass over many bodies, most of them dynamic, that reads only the others:
 * the bodies with every component of `terms` that are sleeping, kinematic or static, one live query
 * result a class, lowest rank first (reused array; list k's class is `rankedListType(k)`). Giving each
 * list's bodies its class in turn leaves every body the class classifyBody gives it; the last list is
 * the static bodies.
 * @category Collision
 */
export function rankedLists(world: PhysicsWorld, terms: readonly object[]): readonly ArrayLike<number>[] {
  const components = bodyComponents(world);
  for (let k = 0; k < RANKED.length; k++) lists[RANKED.length - 1 - k] = query(world, [...terms, components[RANKED[k]!]!]);
  return lists;
}

/** The BodyType of rankedLists' list k (0 to 2). */
export function rankedListType(k: number): number {
  return RANKED_TYPE[RANKED.length - 1 - k]!;
}

/**
 * rankedLists' bodies' class into the collision state, as classifyBody writes it (BodyType, inverse
 * mass and inertia 0). Returns the static ones (a live query result).
 * @category Collision
 */
export function classifyRanked(world: PhysicsWorld, terms: readonly object[]): ArrayLike<number> {
  const cs = world.collision,
    invMass = cs.invMass,
    invInertia = cs.invInertia,
    type = cs.bodyType,
    ranked = rankedLists(world, terms);
  for (let k = 0; k < ranked.length; k++) {
    const list = ranked[k]!,
      t = rankedListType(k);
    for (let i = 0; i < list.length; i++) {
      const e = list[i]!;
      invMass[e] = 0;
      invInertia[e] = 0;
      type[e] = t;
    }
  }
  return ranked[ranked.length - 1]!;
}

/**
 * classifyBody's last case, for a body known to be dynamic: its inverse mass (1/kg) and an inverse
 * inertia (1/(kg m^2)) that is > 0 exactly when it turns (it has an angular velocity): in 3D the
 * largest principal one of its inertia tensor, else its scalar one (2D bodies, balls), 0 without.
 * Returns BodyType.Dynamic. Needs lookUpBodyBits(world) earlier in the pass.
 * @category Collision
 */
export function classifyDynamic(world: PhysicsWorld, b: number): number {
  const c = world.components,
    cs = world.collision,
    T = c.InertiaTensor;
  cs.invMass[b] = c.Mass.inv[b]!;
  cs.invInertia[b] = !hasBit(SPIN, b)
    ? 0
    : world.dimensions === 3 && hasBit(INERTIA_TENSOR, b)
      ? Math.max(T.invX[b]!, T.invY[b]!, T.invZ[b]!)
      : hasBit(INERTIA, b)
        ? c.Inertia.inv[b]!
        : 0;
  cs.bodyType[b] = BodyType.Dynamic;
  return BodyType.Dynamic;
}
