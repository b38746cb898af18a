import type { QueryResult } from 'bitecs';
import type { PhysicsWorld, System } from '../world/options.js';
import { query } from '../world/query.js';
import { STAGES, type StageName } from '../world/stage-names.js';
import { type FiniteTrust, finiteTrustOf, idleGuardTerms, systemMarksVersion } from '../world/trusted-systems.js';

/**
 * What `step` resolves once of a stage's systems rather than at every step: for each system, the live
 * query arrays whose emptiness means it has nothing to do (its idle guard, `idleWithout` in
 * world/trusted-systems.ts), so that a world pays nothing for the built-in laws it does not use (a
 * world of one body still has about twenty force systems, each of which would look up its query and
 * return). The plan is remade when the stage's list of systems changes (addSystem, removeSystem, a
 * feature installing its systems, a direct write to `world.stages`) or when the systems' marks do.
 */
export interface StagePlan {
  /** The stage's systems the plan was made for, in order (a copy, compared with the stage's list). */
  readonly systems: System[];
  /** For each system, its idle guard's live query arrays (idle when all are empty), or null: always run. */
  readonly guards: (readonly QueryResult[] | null)[];
  /** For each system, how it is trusted not to write NaN (world/trusted-systems.ts finiteTrustOf). */
  readonly trust: (FiniteTrust | undefined)[];
  /** The marks' version (world/trusted-systems.ts systemMarksVersion) the plan was made at. */
  readonly version: number;
}

/**
 * A world's plans, one a stage (null until the stage first runs).
 * @category World and step
 */
export type StagePlans = Record<StageName, StagePlan | null>;

/** A world's stages record (world.stages): the key of the plans. */
type Stages = PhysicsWorld['stages'];

/**
 * The plans by the world's `stages` record (one a world, for its life): derived from the stages and
 * the queries, so a cache of the code that runs, not world state (snapshots carry none of it).
 */
const plansOf = new WeakMap<Stages, StagePlans>();

/**
 * The plans of `world`'s stages (each null until its stage first runs); one object per world, kept for
 * its life.
 * @category World and step
 */
export function stagePlans(world: PhysicsWorld): StagePlans {
  let plans = plansOf.get(world.stages);
  if (plans === undefined) {
    plans = {} as StagePlans;
    for (const s of STAGES) plans[s] = null;
    plansOf.set(world.stages, plans);
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
  if (plan !== null && plan.version === systemMarksVersion() && plan.systems.length === systems.length) {
    let same = true;
    for (let i = 0; i < systems.length; i++)
      if (plan.systems[i] !== systems[i]) {
        same = false;
        break;
      }
    if (same) return plan;
  }
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
 * Whether every array of `guard` is empty (the system it guards has nothing to do). A live query array
 * may still hold entities whose removal bitecs has not committed; those only make it longer, so an
 * empty array is empty after the commit too.
 * @category World and step
 */
export function guardIdle(guard: readonly QueryResult[]): boolean {
  for (let i = 0; i < guard.length; i++) if (guard[i]!.length !== 0) return false;
  return true;
}
