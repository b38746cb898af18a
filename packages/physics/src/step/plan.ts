import type { QueryResult } from 'bitecs';
import type { PhysicsWorld, System } from '../world/options.js';
import { query } from '../world/query.js';
import { type StagePlan as StagePlanOf, type StagePlans as StagePlansOf, sameEntries } from '../world/scratch.js';
import { STAGES, type StageName } from '../world/stage-names.js';
import { finiteTrustOf, idleGuardTerms, systemMarksVersion } from '../world/trusted-systems.js';

/*
 * What `step` resolves once of a stage's systems rather than at every step: for each system, the live
 * query arrays whose emptiness means it has nothing to do (its idle guard, `idleWithout` in
 * world/trusted-systems.ts), so that a world pays nothing for the built-in laws it does not use (a
 * world of one body still has about twenty force systems, each of which would look up its query and
 * return). The plans live in `world.scratch.stagePlans` (the types in world/scratch.ts): derived from
 * the stages and the queries, a cache of the code that runs, not world state, so snapshots carry none
 * of it. A plan is remade when the stage's list of systems changes (addSystem, removeSystem, a feature
 * installing its systems, a direct write to `world.stages`) or when the systems' marks do.
 */

/**
 * What `step` resolved of one stage's systems (see StagePlan in world/scratch.ts).
 * @category World and step
 */
export type StagePlan = StagePlanOf<PhysicsWorld>;

/**
 * A world's plans, one a stage (null until the stage first runs).
 * @category World and step
 */
export type StagePlans = StagePlansOf<PhysicsWorld>;

/**
 * The plans of `world`'s stages (each null until its stage first runs); one object per world, kept for
 * its life.
 * @category World and step
 */
export function stagePlans(world: PhysicsWorld): StagePlans {
  let plans = world.scratch.stagePlans;
  if (plans === undefined) {
    plans = {} as StagePlans;
    for (const s of STAGES) plans[s] = null;
    world.scratch.stagePlans = plans;
  }
  return plans;
}

/**
 * The plan of `stage` for its current list `systems`: the one in `plans` if it was made for the same
 * systems in the same order at the current marks, else a new one (stored in `plans`).
 * @category World and step
 */
export function stagePlan(world: PhysicsWorld, plans: StagePlans, stage: StageName, systems: readonly System[]): StagePlan {
  const plan = plans[stage];
  if (plan !== null && plan.version === systemMarksVersion() && sameEntries(plan.systems, systems)) return plan;
  return makePlan(world, plans, stage, systems);
}

/** A new plan of `stage` (see `stagePlan`), stored in `plans`. */
function makePlan(world: PhysicsWorld, plans: StagePlans, stage: StageName, systems: readonly System[]): StagePlan {
  const guards = systems.map((system) => {
    const terms = idleGuardTerms(system, world);
    return terms === null ? null : terms.map((t) => query(world, t as object[]));
  });
  const plan: StagePlan = { systems: systems.slice(), guards, trust: systems.map(finiteTrustOf), version: systemMarksVersion() };
  plans[stage] = plan;
  return plan;
}

/**
 * Makes the queries of the idle guards of `world`'s systems in every stage (see `makePlan`) while it has
 * no entity, so that its first step does not fill them (integrators/queries.ts makeIntegratorQueries).
 * createPhysicsWorld calls it; the plans themselves are made by the first step, from these queries.
 * @category World and step
 */
export function makeGuardQueries(world: PhysicsWorld): void {
  for (const stage of STAGES)
    for (const system of world.stages[stage]) {
      const terms = idleGuardTerms(system, world);
      if (terms !== null) for (const t of terms) query(world, t as object[]);
    }
}

/**
 * Whether every array of `guard` is empty (the system it guards has nothing to do). A live query array
 * may still hold entities whose removal bitecs has not committed; those only make it longer, so an
 * empty array is empty after the commit too.
 * @category World and step
 */
export function guardIdle(guard: readonly QueryResult[]): boolean {
  for (let i = 0; i < guard.length; i++) if (guard[i]!.length !== 0) return false;
  return true;
}
