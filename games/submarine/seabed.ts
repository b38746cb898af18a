/**
 * The hull against the seabed: an impulse contact (Newton's law of restitution along the bed's
 * normal, Coulomb friction along it) and the rule for when a contact damages the hull. Headless (no
 * drawing or sound), so it is tested in node.
 *
 * One rule for damage: a contact costs a hit when the hull comes in faster than `SEABED.hitSpeed`
 * along the bed's normal, or when it has scraped along the bed (sliding faster than
 * `SEABED.scrapeSpeed`) for `SEABED.cooldown` since the last hit or since the scrape began; and at
 * most one hit per `SEABED.cooldown`. A boat resting on the bed is not hurt again; one driven on
 * along it loses a hull bar every `SEABED.cooldown` s until it rises off.
 *
 * Also the warning of the seabed on the boat's course (`bedAhead`), told by the hull as the mines are.
 */

import { applyImpulse, type PhysicsWorld } from '@bitphysics/physics';
import { SUBMARINE, type SubmarineHandles, seabedHeight } from '@bitphysics/projects';
import { HELM, holdFloor } from './helm';

/** The seabed contact's settings. */
export const SEABED = Object.freeze({
  /** Coefficient of restitution of the hull on the bed (sand and mud over rock), in [0, 1]. */
  restitution: 0.3,
  /** Coulomb friction coefficient of the hull sliding on the bed. */
  friction: 0.3,
  /** Approach speed along the bed's normal above which a contact damages the hull, m/s. */
  hitSpeed: 1.5,
  /** After a hit, contacts cost nothing for this long, s; scraping on along the bed costs a hit each time this long passes. */
  cooldown: 2,
  /** Sliding speed along the bed above which a contact scrapes the hull, m/s (below it the boat rests or creeps on the bed). */
  scrapeSpeed: 1,
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
  /** Game time until which contacts cost no hit, s (a contact before it renews it). */
  spared: number;
  /**
   * Whether the bed stopped a dive: set when the hull touches it with Dive held; until Dive is let
   * go the helm is not told to dive (`seabedInput`), so it holds the depth there instead of driving
   * the hull down the bed's slope into the next kink.
   */
  diveStopped: boolean;
  /** Game time the hull began scraping along the bed (or took its last hit while scraping), s; NaN or absent while it is not. */
  scrapeSince?: number;
}

/**
 * The helm's input with the seabed's stop applied: `input` without Dive while `state.diveStopped`.
 * Letting Dive go clears the stop, so pressing it again dives again.
 */
export function seabedInput<T extends { dive: boolean }>(state: SeabedState, input: T): T {
  if (!input.dive) state.diveStopped = false;
  return state.diveStopped ? { ...input, dive: false } : input;
}

/** What the gauges say while the seabed stops a held Dive (`SeabedState.diveStopped`). */
export const DIVE_STOPPED_WORD = 'seabed: no deeper';

/**
 * The helm's word on the gauges: "holding 30 m" (the order's depth, `holdY` the hull's y, m) while
 * holding, "stopping" while braking, the mode's name otherwise; `DIVE_STOPPED_WORD` while the
 * seabed stops a held Dive (`diveStopped`), which would otherwise read "holding" with Dive held, as
 * if the key were ignored.
 */
export function helmWord(mode: string, holdY: number, diveStopped: boolean): string {
  if (diveStopped) return DIVE_STOPPED_WORD;
  if (mode === 'holding') return `holding ${(-holdY).toFixed(0)} m`;
  return mode === 'braking' ? 'stopping' : mode;
}

/** One step's contact: '' none, 'touch' a contact that costs nothing, 'hit' one that costs a hit. */
export type SeabedContact = '' | 'touch' | 'hit';

/**
 * Resolves the hull's contact with the seabed after a step: finds the deepest of the bow, stern and
 * keel centre under the bed and, if the hull moves into the bed there, applies the impulse that
 * leaves it moving out at `restitution` times its approach speed (or at the push-out speed, if
 * larger), plus friction along the bed up to `friction` times that impulse. Updates `state` (a
 * contact while `diving`, Dive held, sets `state.diveStopped`) and says
 * whether the contact costs a hit (approach speed over `SEABED.hitSpeed`, or sliding along the bed
 * faster than `SEABED.scrapeSpeed` for `SEABED.cooldown` s, with the game time `time`, s, past
 * `state.spared`; a hit sets `state.spared` to `time + SEABED.cooldown` and restarts the scrape's
 * clock, so scraping on costs a hit every cooldown). On a contact,
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
  if (!state.touching) {
    state.scrapeSince = Number.NaN;
    return '';
  }
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
  // Sliding along the bed faster than scrapeSpeed: the scrape's clock runs from its start.
  const sliding = Math.abs(vx * ny - vy * nx) > SEABED.scrapeSpeed;
  if (!sliding) state.scrapeSince = Number.NaN;
  else if (!Number.isFinite(state.scrapeSince ?? Number.NaN)) state.scrapeSince = time;
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
  // Within the cooldown of the last hit: no hit.
  if (time < state.spared) return 'touch';
  if (-vn > SEABED.hitSpeed || (sliding && time - state.scrapeSince! >= SEABED.cooldown)) {
    state.spared = time + SEABED.cooldown;
    if (sliding) state.scrapeSince = time;
    return 'hit';
  }
  return 'touch';
}

/** How far ahead the seabed warning looks along the boat's course, s (`bedAhead`): as far as a held depth looks (HELM.bedLookAhead). */
export const BED_WARN_TIME = HELM.bedLookAhead;
/** The seabed warning's room under the keel, m: a course that takes the keel nearer the bed than this is warned of. */
export const BED_WARN_MARGIN = 0.5;

/**
 * How far ahead the warning looks along a course held on at its vertical speed while Dive or Rise is held, s: a dive stops in about a second at the helm's brake, so 2 s tells of the floor
 * in time without calling every dive toward a deep beacon a danger.
 */
export const BED_HEAVE_TIME = 2;
/**
 * The same for a ridge (the bed rising 1 m or more over the bed under the hull), s: a rising bed
 * ahead meets a diving boat sooner than its speed down says, and rising over it takes the boat's
 * stop and a climb, so it is told a second earlier.
 */
export const BED_RIDGE_HEAVE_TIME = 3;

/** The seabed on the boat's course (`bedAhead`). */
export interface BedAhead {
  /** In how long the course reaches the bed (with `BED_WARN_MARGIN` to spare), s. */
  time: number;
  /** Where: x, m, the hull's centre then. */
  x: number;
  /** The highest seabed under the hull there, m (y up). */
  bed: number;
  /** Whether the bed there stands 1 m or more over the bed under the hull now (a ridge ahead, not the floor below). */
  ridge: boolean;
}

/**
 * When the seabed comes within `BED_WARN_MARGIN` of the keel of a level hull on its course within
 * `options.horizon` s (default `BED_WARN_TIME`), so the pilot is told while there is time to rise:
 * from its centre at (x, y), m (y up), along x at its speed `vx` (m/s), and in depth on toward the
 * ordered depth `holdY` (m; NaN: none; raised over the bed ahead as the helm raises it, ./helm.ts
 * holdFloor) at up to the helm's climb or dive speed (`climb`, `dive`,
 * m/s) and, while Dive or Rise is held (`options.heaving`, at the share `options.heave` of those
 * speeds, in (0, 1], default 1, from the first moment) or no depth is ordered, on at its vertical
 * speed `vy` (m/s; held Dive or Rise only for `BED_HEAVE_TIME` s): the first contact on either
 * course. Null when the course is clear.
 * @throws RangeError when x, y, vx, vy, climb or dive is not finite, `horizon` is not positive or
 * `heave` is not in (0, 1].
 */
export function bedAhead(
  x: number,
  y: number,
  vx: number,
  vy: number,
  holdY: number,
  seabed: SubmarineHandles['seabed'],
  climb: number,
  dive: number,
  options: { readonly horizon?: number; readonly heaving?: boolean; readonly heave?: number } = {},
): BedAhead | null {
  for (const [name, v] of [
    ['x', x],
    ['y', y],
    ['vx', vx],
    ['vy', vy],
    ['climb', climb],
    ['dive', dive],
  ] as const)
    if (!Number.isFinite(v)) throw new RangeError(`bedAhead: ${name} must be finite, got ${v}`);
  const horizon = options.horizon ?? BED_WARN_TIME;
  if (!(horizon > 0)) throw new RangeError(`bedAhead: options.horizon must be > 0 s, got ${horizon}`);
  const share = options.heave ?? 1;
  if (!(share > 0 && share <= 1)) throw new RangeError(`bedAhead: options.heave must be in (0, 1], got ${share}`);
  const L = SUBMARINE.length / 2,
    H = SUBMARINE.height / 2;
  const bedUnder = (cx: number): number => Math.max(seabedHeight(seabed, cx - L), seabedHeight(seabed, cx), seabedHeight(seabed, cx + L));
  const now = bedUnder(x);
  const toOrder = !Number.isNaN(holdY),
    onAsGoing = options.heaving === true || !toOrder;
  const dt = 0.05;
  for (let t = dt; t <= horizon + 1e-9; t += dt) {
    const cx = x + vx * t,
      bed = bedUnder(cx);
    let hit = false;
    // Toward the order, which the helm raises over the bed ahead as it goes (./helm.ts holdFloor).
    if (toOrder) {
      const order = Math.max(holdY, holdFloor(seabed, cx, vx));
      hit = y + Math.max(-dive * t, Math.min(climb * t, order - y)) - H < bed + BED_WARN_MARGIN;
    }
    // Held Dive or Rise (within `BED_HEAVE_TIME`, a ridge within `BED_RIDGE_HEAVE_TIME`: a dive toward a deep beacon is not warned of the
    // floor while there is room to stop over it), or no order: on as it goes.
    if (!hit && onAsGoing && (!options.heaving || t <= (bed >= now + 1 ? BED_RIDGE_HEAVE_TIME : BED_HEAVE_TIME))) {
      const v = options.heaving ? (vy >= 0 ? Math.max(vy, share * climb) : Math.min(vy, -share * dive)) : vy;
      hit = y + v * t - H < bed + BED_WARN_MARGIN;
    }
    if (hit) return { time: t, x: cx, bed, ridge: bed >= now + 1 };
  }
  return null;
}
