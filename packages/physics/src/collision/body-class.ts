import { type EcsInternals, ecsOf } from '../world/ecs-internals.js';
import type { PhysicsWorld } from '../world/options.js';
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
  const c = world.components,
    ecs = ecsOf(world);
  lookUpBit(ecs, STATIC, c.Static);
  lookUpBit(ecs, KINEMATIC, c.Kinematic);
  lookUpBit(ecs, SLEEPING, c.Sleeping);
  lookUpBit(ecs, INERTIA, c.Inertia);
  lookUpBit(ecs, SPIN, c.AngularVelocity);
  lookUpBit(ecs, ANGLE, c.Angle);
  lookUpBit(ecs, SHAPE, c.Shape);
  lookUpBit(ecs, INERTIA_TENSOR, c.InertiaTensor);
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
 * Writes body `b`'s class for this step into the collision state and returns it (a BodyType): static,
 * kinematic or sleeping (ranked in that order; inverse mass and inertia 0), else dynamic
 * (classifyDynamic). Needs lookUpBodyBits(world) earlier in the pass.
 * @category Collision
 */
export function classifyBody(world: PhysicsWorld, b: number): number {
  const cs = world.collision;
  let t: number;
  if (hasBit(STATIC, b)) t = BodyType.Static;
  else if (hasBit(KINEMATIC, b)) t = BodyType.Kinematic;
  else if (hasBit(SLEEPING, b)) t = BodyType.Sleeping;
  else return classifyDynamic(world, b);
  cs.invMass[b] = 0;
  cs.invInertia[b] = 0;
  cs.bodyType[b] = t;
  return t;
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
