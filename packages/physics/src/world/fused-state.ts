import type { PhysicsWorld } from './options.js';

/**
 * Which world's current substep runs the fused force-and-integrate pass (see integrators/fused-gate.ts
 * for when, and integrators/semi-implicit-euler.ts for the pass). While it is on, the force accumulators
 * of the world's bodies are written by the integrator instead of by `clearForcesSystem`,
 * `linearDragSystem` and `quadraticDragSystem` (which then skip them), and the finiteness check of the
 * forces stage leaves `Force` to the integrator's own check.
 *
 * One world at a time: `step` turns it on at the start of a substep, only built-in systems run until the
 * integrator (the gate refuses any other system in the stages between), and the integrator turns it off
 * once it has run; `evaluateForces` turns it off too (a call outside a step always evaluates every law
 * the ordinary way). So it is never on across steps or for two worlds, and carries no state between
 * steps (nothing for snapshots).
 *
 * A leaf module (no imports but types): the systems that consult the flag import it, and the gate that
 * sets it imports those systems.
 */
/**
 * No world's pass is on: an object, not null, so that `current === world` compares two objects whether
 * the pass is on or off (code compiled while it was on, comparing objects only, is not thrown away when
 * it first meets the off state: --trace-deopt "not a JavaScript object" in clearForcesSystem).
 */
const OFF: object = Object.freeze({});
let current: object = OFF;

/**
 * Whether the fused pass is on for the current substep of `world`.
 * @category Integrators
 */
export function fusedForcesOn(world: PhysicsWorld): boolean {
  return current === world;
}

/**
 * Turns the fused pass of `world` on or off (the integrator and `evaluateForces` call this).
 * @category Integrators
 */
export function setFusedForces(world: PhysicsWorld, value: boolean): void {
  if (value) current = world;
  else if (current === world) current = OFF;
}

/**
 * The start of a substep of `world` (`step`, through the gate): the pass on for it or off, and off for
 * any other world (one whose step threw before its integrator ran is not held on to).
 * @category Integrators
 */
export function beginFusedSubstep(world: PhysicsWorld, value: boolean): void {
  current = value ? world : OFF;
}
