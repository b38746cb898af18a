import { commitRemovals } from 'bitecs';
import { clearContactEvents } from '../collision/event-lists.js';
import { armFusedForces } from '../integrators/fused-gate.js';
import { assertOptions, describe } from '../validation/validate.js';
import type { PhysicsWorld, System } from '../world/options.js';
import { query } from '../world/query.js';
import { STAGES, type StageName, SUBSTEP_STAGES } from '../world/stage-names.js';
import { checkAfter, systemNeedsCheck } from '../world/trusted-systems.js';
import { checkStageState } from './finite.js';
import { guardIdle, type StagePlans, stagePlan, stagePlans } from './plan.js';

/** The host's clock (`performance` is not in the ES library this package is built against). */
const clock = (globalThis as { performance?: { now(): number } }).performance;
const now: () => number = typeof clock?.now === 'function' ? () => clock.now() : () => Date.now();

/**
 * Runs the systems of one stage, then checks the state it may have written (step/finite.ts):
 * a NaN or infinity stops the step here with a NonFiniteStateError naming the stage, the entity
 * and the field. A system that does not check its own output (a user's, or a collision system for
 * shapes) and is followed by others in the stage is checked as soon as it returns: a later system
 * (the contact solver) would otherwise spread its NaN through the contacts to every body touching
 * the one it wrote, before the end of the stage. A built-in system whose idle guard finds nothing
 * for it to do (step/plan.ts) is not called; bitecs' pending removals are committed in its place, as
 * its own query would have, so the queries of the systems after it see the same lists.
 * `t0` is the clock's reading (ms) when the stage began, the end of the stage before it: the stage's
 * time is added to `world.timings` and the clock's reading at its end returned (`t0` for a stage
 * without systems), one reading a stage.
 */
function runStage(world: PhysicsWorld, plans: StagePlans, stage: StageName, t0: number): number {
  const systems = world.stages[stage];
  const n = systems.length;
  if (n === 0) return t0;
  const plan = stagePlan(world, plans, stage, systems);
  let level: 0 | 1 | 2 = 0;
  for (let i = 0; i < n; i++) {
    const system = systems[i]!;
    // The plan is of the list as the stage began; a system that changed the list leaves the rest unguarded.
    const guard = plan.systems[i] === system ? plan.guards[i]! : null;
    if (guard !== null && guardIdle(guard)) commitRemovals(world);
    else system(world);
    if (stage === 'clearForces') continue;
    const own = plan.systems[i] === system ? checkAfter(world, plan.trust[i]) : systemNeedsCheck(world, system);
    if (own === 2 && i < n - 1) checkStageState(world, stage, 2);
    else if (own > level) level = own;
  }
  if (level !== 0 || stage === 'forces') checkStageState(world, stage, level);
  const t1 = now();
  world.timings[stage] += t1 - t0;
  return t1;
}

/**
 * Advances the world by one fixed step of `world.dt` seconds: `spawn`, then `substeps` times
 * (`clearForces`, `forces`, `integrate`, `collide`, `constraints`) with h = dt / substeps, then
 * `finalize`. `world.time` advances by h after each substep's integrate stage; `world.timings`
 * holds the milliseconds each stage took in this step (the little work between two stages, such as
 * the fused pass's gate at the start of a substep, counts in the stage after it).
 *
 * @throws RangeError if more entities exist than the world's capacity (entities added with bitecs'
 *   own `addEntity` bypass the check of `createEntity`; this catches them before their data is lost).
 * @throws NonFiniteStateError (a RangeError) if a body's state became NaN or infinite: its position,
 *   velocity, angle or orientation, angular velocity, or (after `forces`) force or torque. It is
 *   thrown at the end of the stage that wrote the value, before any later stage runs (or, for a
 *   system that does not check its own output, as soon as it returns, before the next system of the
 *   stage runs); `entity` is the
 *   body's handle, `field` e.g. 'Position.x', `stage` the stage (step/finite.ts). The world is
 *   left as that stage left it. In a substep run by the fused force-and-integrate pass
 *   (integrators/fused-gate.ts) a non-finite force is found before its body moves, but bodies the pass
 *   had already moved with finite forces in that substep stay moved (the separate stages would move none).
 * @category World and step
 */
export function step(world: PhysicsWorld): void {
  if (world.entityIndex.maxId > world.capacity) {
    throw new RangeError(
      `step: entity id ${world.entityIndex.maxId} exceeds the world's capacity ${world.capacity}; ` +
        'create entities with createEntity/addBody, or make the world with a larger capacity',
    );
  }
  const loose = world.collision.looseBall;
  if (loose !== 0) {
    throw new Error(
      `step: entity ${loose} has the Ball component but this world's ball collisions are not installed; ` +
        'make balls with addBody({ radius }), addParticle then setRadius, or an emitter, or call installBalls(world) after addComponent',
    );
  }
  const timings = world.timings;
  for (const s of STAGES) timings[s] = 0;
  clearContactEvents(world.collision.events);
  try {
    runStages(world);
  } finally {
    // Work a worker was left doing while the step finished (the warm-start table,
    // solver/stages-threads.ts) is done before step returns or throws.
    world.threadPool?.join();
  }
  world.steps++;
}

/** The stages of one step (see step). */
function runStages(world: PhysicsWorld): void {
  const plans = stagePlans(world);
  let clock = runStage(world, plans, 'spawn', now());
  const n = world.substeps;
  const h = world.dt / n;
  world.h = h;
  const t0 = world.time;
  const movers = n > 1 ? snapshotStepStart(world) : null;
  for (let s = 0; s < n; s++) {
    world.time = t0 + s * h;
    world.substepStart = world.time;
    // One pass for the forces and the integrator where nothing else touches forces (integrators/fused-gate.ts).
    armFusedForces(world);
    for (const stage of SUBSTEP_STAGES) {
      clock = runStage(world, plans, stage, clock);
      if (stage === 'integrate') world.time = t0 + (s + 1) * h;
    }
  }
  world.time = t0 + world.dt;
  if (movers) restoreStepStart(world, movers);
  runStage(world, plans, 'finalize', clock);
}

const moverTerms = (world: PhysicsWorld) => [world.components.Position, world.components.Velocity];

/**
 * With substeps, each substep overwrites PreviousPosition (the collision stage needs the start of
 * its own substep), so the start of the whole step is kept here and written back at the end: after
 * `step`, PreviousPosition is always where bodies were when the step began, which is what renderers
 * interpolate from.
 */
function snapshotStepStart(world: PhysicsWorld): ArrayLike<number> {
  const ents = query(world, moverTerms(world));
  let stepStart = world.scratch.stepStart;
  if (!stepStart) {
    const n = world.capacity + 1;
    stepStart = [new Float64Array(n), new Float64Array(n), new Float64Array(n)];
    world.scratch.stepStart = stepStart;
  }
  const P = world.components.Position;
  const [x, y, z] = stepStart;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    x[e] = P.x[e]!;
    y[e] = P.y[e]!;
    z[e] = P.z[e]!;
  }
  return ents;
}

function restoreStepStart(world: PhysicsWorld, ents: ArrayLike<number>): void {
  const O = world.components.PreviousPosition;
  const [x, y, z] = world.scratch.stepStart!;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    O.x[e] = x[e]!;
    O.y[e] = y[e]!;
    O.z[e] = z[e]!;
  }
}

/**
 * Runs `step` `count` times. @throws RangeError unless count is a non-negative integer.
 * @category World and step
 */
export function stepMany(world: PhysicsWorld, count: number): void {
  if (!Number.isInteger(count) || count < 0) {
    throw new RangeError(`stepMany: count must be a non-negative integer, got ${describe(count)}`);
  }
  for (let i = 0; i < count; i++) step(world);
}

/**
 * Where `addSystem` inserts a system within its stage.
 * @category World and step
 */
export interface AddSystemOptions {
  /** Insert just before this system (which must be in the stage). */
  before?: System;
  /** Insert just after this system (which must be in the stage). */
  after?: System;
}

/**
 * Hooks `system` into `stage` of this world, at the end of the stage unless `before` or `after`
 * names a system already there. User force laws go in `'forces'`.
 * @throws RangeError on an unknown stage or a `before`/`after` system that is not in the stage.
 * @throws TypeError if `system` is not a function, or `options` is not an object of known, non-null options.
 * @category World and step
 */
export function addSystem(world: PhysicsWorld, stage: StageName, system: System, options: AddSystemOptions = {}): void {
  if (!(STAGES as readonly string[]).includes(stage)) {
    throw new RangeError(`addSystem: stage must be one of ${STAGES.join(', ')}, got ${describe(stage)}`);
  }
  if (typeof system !== 'function') throw new TypeError(`addSystem: system must be a function, got ${describe(system)}`);
  assertOptions('addSystem', options, ['before', 'after']);
  const list = world.stages[stage];
  const anchor = options.before ?? options.after;
  if (anchor === undefined) {
    list.push(system);
    return;
  }
  const i = list.indexOf(anchor);
  if (i < 0) throw new RangeError(`addSystem: the ${options.before ? 'before' : 'after'} system is not in stage '${stage}'`);
  list.splice(options.before ? i : i + 1, 0, system);
}

/**
 * Removes `system` from `stage`; returns whether it was there.
 * @category World and step
 */
export function removeSystem(world: PhysicsWorld, stage: StageName, system: System): boolean {
  const list = world.stages[stage];
  if (!list) throw new RangeError(`removeSystem: stage must be one of ${STAGES.join(', ')}, got ${describe(stage)}`);
  const i = list.indexOf(system);
  if (i < 0) return false;
  list.splice(i, 1);
  return true;
}
