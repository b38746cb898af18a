/**
 * The hull against the seabed: an impulse contact (Newton's law of restitution along the bed's
 * normal, Coulomb friction along it) and the rule for when a contact damages the hull. Headless (no
 * drawing or sound), so it is tested in node.
 *
 * A contact costs a hit only when the hull comes in faster than `SEABED.hitSpeed` along the bed's
 * normal, and at most one per `SEABED.cooldown`: a boat resting on the bed, or bumping along it after
 * an impact, is not hurt again.
 */

import { applyImpulse, type PhysicsWorld } from '@bitphysics/physics';
import { SUBMARINE, type SubmarineHandles, seabedHeight } from '@bitphysics/projects';

/** The seabed contact's settings. */
export const SEABED = Object.freeze({
  /** Coefficient of restitution of the hull on the bed (sand and mud over rock), in [0, 1]. */
  restitution: 0.3,
  /** Coulomb friction coefficient of the hull sliding on the bed. */
  friction: 0.3,
  /** Approach speed along the bed's normal above which a contact damages the hull, m/s. */
  hitSpeed: 1.5,
  /** After a hit, further contacts cost nothing for this long, s. */
  cooldown: 2,
  /**
   * Speed at which the contact pushes a hull that has sunk into the bed back out, m/s per m of
   * penetration (Baumgarte stabilisation: the contact's impulses alone let a resting heavy hull creep
   * in by its acceleration times dt^2 each step).
   */
  pushOutRate: 5,
  /** Most speed the push-out gives, m/s. */
  pushOutMax: 0.5,
});

/** What the contact keeps between steps. */
export interface SeabedState {
  /** Whether the hull touched the bed last step. */
  touching: boolean;
  /** Game time until which contacts cost no hit, s. */
  spared: number;
  /**
   * Whether the bed stopped a dive: set when the hull touches it with Dive held; until Dive is let
   * go the helm is not told to dive (`seabedInput`), so it holds the depth there instead of driving
   * the hull down the bed's slope into the next kink.
   */
  diveStopped: boolean;
}

/**
 * The helm's input with the seabed's stop applied: `input` without Dive while `state.diveStopped`.
 * Letting Dive go clears the stop, so pressing it again dives again.
 */
export function seabedInput<T extends { dive: boolean }>(state: SeabedState, input: T): T {
  if (!input.dive) state.diveStopped = false;
  return state.diveStopped ? { ...input, dive: false } : input;
}

/** One step's contact: '' none, 'touch' a contact that costs nothing, 'hit' one that costs a hit. */
export type SeabedContact = '' | 'touch' | 'hit';

/**
 * Resolves the hull's contact with the seabed after a step: finds the deepest of the bow, stern and
 * keel centre under the bed and, if the hull moves into the bed there, applies the impulse that
 * leaves it moving out at `restitution` times its approach speed (or at the push-out speed, if
 * larger), plus friction along the bed up to `friction` times that impulse. Updates `state` (a
 * contact while `diving`, Dive held, sets `state.diveStopped`) and says
 * whether the contact costs a hit (approach speed over `SEABED.hitSpeed`, and the game time `time`,
 * s, past `state.spared`; a hit sets `state.spared` to `time + SEABED.cooldown`). On a contact,
 * `at` (if given) is set to the point of the hull that is deepest in the bed (bow, stern or keel
 * centre; x, y, m), where the hull struck it.
 */
export function touchSeabed(
  world: PhysicsWorld,
  handles: SubmarineHandles,
  state: SeabedState,
  time: number,
  diving = false,
  at?: { x: number; y: number },
): SeabedContact {
  const c = world.components,
    e = handles.hull;
  const x = c.Position.x[e]!,
    y = c.Position.y[e]!,
    a = c.Angle.value[e]!;
  const co = Math.cos(a),
    s = Math.sin(a),
    L = SUBMARINE.length / 2,
    H = SUBMARINE.height / 2;
  // Bow, stern and keel centre; the deepest under the bed is the contact.
  let depth = 0,
    px = x,
    py = y;
  for (const [qx, qy] of [
    [x + L * co, y + L * s],
    [x - L * co, y - L * s],
    [x + H * s, y - H * co],
  ] as const) {
    const d = seabedHeight(handles.seabed, qx) - qy;
    if (d > depth) {
      depth = d;
      px = qx;
      py = qy;
    }
  }
  state.touching = depth > 0;
  if (!state.touching) return '';
  if (at) {
    at.x = px;
    at.y = py;
  }
  if (diving) state.diveStopped = true;
  // The bed's normal from its local slope (central difference over 1 m).
  const slope = seabedHeight(handles.seabed, px + 0.5) - seabedHeight(handles.seabed, px - 0.5);
  const norm = Math.hypot(slope, 1),
    nx = -slope / norm,
    ny = 1 / norm;
  const vx = c.Velocity.x[e]!,
    vy = c.Velocity.y[e]!;
  const vn = vx * nx + vy * ny; // negative: into the bed
  const out = Math.max(-SEABED.restitution * vn, Math.min(SEABED.pushOutMax, SEABED.pushOutRate * depth));
  if (vn < out) {
    const m = c.Mass.value[e]!;
    const jn = m * (out - vn);
    // Friction: the tangential impulse that would stop the sliding, at most friction x jn.
    const tx = ny,
      ty = -nx,
      vt = vx * tx + vy * ty;
    const jt = -Math.sign(vt) * Math.min(m * Math.abs(vt), SEABED.friction * jn);
    applyImpulse(world, e, [jn * nx + jt * tx, jn * ny + jt * ty]);
  }
  if (-vn > SEABED.hitSpeed && time >= state.spared) {
    state.spared = time + SEABED.cooldown;
    return 'hit';
  }
  return 'touch';
}
