import type { PhysicsWorld, System } from './options.js';
import type { SystemTrust } from './scratch.js';
import type { StageName } from './stage-names.js';

/** The built-in systems that need no finite-state check after them (they write no body state, or check what they write): marked when their feature installs, read by `step` (step/finite.ts). */

/**
 * What a built-in system checks itself: 'all' it writes, or only its linear state (position, velocity).
 * @category World and step
 */
export type FiniteScope = 'all' | 'linear';

/**
 * How a system is trusted (`trustFiniteOutput`): its scope, and the condition it is trusted under.
 * @category World and step
 */
export type FiniteTrust = SystemTrust<PhysicsWorld>;

// A WeakMap: keyed by a system function, code shared by every world (marked once when its feature installs), not by a world.
const trusted = new WeakMap<System, FiniteTrust>();

/**
 * Counts the changes of the marks below (`trustFiniteOutput`, `idleWithout`): `step` keeps what it
 * resolved of a stage's systems (step/plan.ts) while this and the stage's list stay the same.
 */
let marksVersion = 0;

/**
 * The version of the systems' marks (see `marksVersion`): any call of `trustFiniteOutput` or
 * `idleWithout` changes it.
 * @category World and step
 */
export function systemMarksVersion(): number {
  return marksVersion;
}

/**
 * Marks built-in systems that write no body state, or check what they write and throw
 * NonFiniteStateError themselves. `scope` 'linear': the system checks the positions and velocities it
 * writes but not the angular state (the integrators), so the stage still checks the turning bodies.
 * `idle`: the system is trusted only while idle(world) is true (it then writes nothing, e.g. a
 * collision system for a kind of shape the world has none of).
 * @category World and step
 */
export function trustFiniteOutput(systems: readonly System[], scope: FiniteScope = 'all', idle?: (world: PhysicsWorld) => boolean): void {
  for (const s of systems) trusted.set(s, idle ? { scope, idle } : { scope });
  marksVersion++;
}

/**
 * What `step` must check after a stage ran `systems`: 2 the whole motion state (some system is not
 * trusted), 1 only the angular state (some system checks only its linear state), 0 nothing.
 * @category World and step
 */
export function stageNeedsCheck(world: PhysicsWorld, stage: StageName, systems: readonly System[]): 0 | 1 | 2 {
  if (stage === 'clearForces' || systems.length === 0) return 0;
  let need: 0 | 1 | 2 = 0;
  for (let i = 0; i < systems.length; i++) {
    const level = systemNeedsCheck(world, systems[i]!);
    if (level === 2) return 2;
    if (level === 1) need = 1;
  }
  return need;
}

/**
 * What must be checked after `system` alone: 2 the whole motion state (not trusted, or trusted only
 * while idle and not idle now), 1 only the angular state (it checks its linear state itself), 0 nothing.
 * @category World and step
 */
export function systemNeedsCheck(world: PhysicsWorld, system: System): 0 | 1 | 2 {
  return checkAfter(world, trusted.get(system));
}

/**
 * How `system` is trusted (`trustFiniteOutput`), or undefined: not trusted. Valid while
 * `systemMarksVersion` stays the same.
 * @category World and step
 */
export function finiteTrustOf(system: System): FiniteTrust | undefined {
  return trusted.get(system);
}

/**
 * What must be checked after a system trusted as `t` (`finiteTrustOf`; undefined: not trusted) ran
 * in `world`: as `systemNeedsCheck`.
 * @category World and step
 */
export function checkAfter(world: PhysicsWorld, t: FiniteTrust | undefined): 0 | 1 | 2 {
  if (t === undefined || (t.idle !== undefined && !t.idle(world))) return 2;
  return t.scope === 'linear' ? 1 : 0;
}

/*
 * The fast passes: one fused loop per group of fields, each written out for its number of arrays so
 * the loop stays monomorphic. x * 0 is 0 for every finite x and NaN for NaN and both infinities, so
 * the sum is 0 exactly when every value is finite (a plain sum of huge finite values could overflow).
 * When the query holds every live id (a world of particles), its ids are 1..maxId and the loop runs
 * over that range directly, in memory order.
 */

/** The idle guards of built-in systems (see `idleWithout`): each a function of the world giving lists of query terms, or null. */
// A WeakMap: keyed by a system function, code shared by every world (guarded once when its module loads), not by a world.
const idleGuards = new WeakMap<System, (world: PhysicsWorld) => readonly object[][] | null>();

/**
 * Declares that the built-in `system` has nothing to do in `world` while every query of `terms(world)`
 * (one or more lists of query terms; null: no guard in that world) is empty: it then writes nothing
 * and returns at once, having made its queries only. `step` skips it then without calling it (step/plan.ts): it reads the live arrays of
 * those queries, and commits bitecs' pending removals as the system's own query would have. Each list
 * must be a query the system makes before anything else it does (or one whose emptiness implies the
 * emptiness of such a query), and the system must return when those queries are all empty.
 * @category World and step
 */
export function idleWithout(system: System, terms: (world: PhysicsWorld) => readonly object[][] | null): void {
  idleGuards.set(system, terms);
  marksVersion++;
}

/**
 * The query terms whose emptiness makes `system` idle in `world` (`idleWithout`); null for a system
 * without such a guard there (a user's system always runs).
 * @category World and step
 */
export function idleGuardTerms(system: System, world: PhysicsWorld): readonly object[][] | null {
  return idleGuards.get(system)?.(world) ?? null;
}
