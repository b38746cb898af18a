/**
 * The submarine's helm: turns the pilot's held keys into ballast targets, vertical thrusters and
 * screw thrust each step, the way a small submersible's control system does. The physics stays the
 * scene's own (Archimedes' buoyancy, the tanks' mass, quadratic drag); the helm only decides what
 * the pumps, vents and thrusters do.
 *
 * - Dive / Rise (held): the tanks go heavier / lighter than neutral (enough to carry the boat at
 *   `HELM.diveSpeed` (`HELM.climbSpeed` rising) against drag, more while it is slower than that) and the vertical thrusters
 *   push at once, so the boat starts to move before the water has moved; the bow dips (rises) by
 *   `HELM.diveAngle`. On the surface Dive floods the tanks from empty, the fore tank first. Rise
 *   slows the climb near the surface and blows the tanks dry once the deck is out.
 * - Released under water: depth hold at the depth where the key was let go. The boat's momentum
 *   carries it on (under 8 m from a full-speed dive: the thrusters push at once and the tanks blow
 *   as far as needed), then the helm brings it back to that depth, tanks at neutral, within 8 s.
 *   Released on the surface: the tanks stay blown and the boat floats.
 * - Nose down / up (held): pitch to `HELM.noseAngle` by the thrusters at once and by moving water
 *   between the tanks; meanwhile the thrusters stop the hull sliding across its axis, so with the
 *   screw ahead the boat follows its nose. Released, the hull levels out and the depth is held.
 * - The on-screen stick asks for part of the dive or climb speed and of the throttle, as far as it
 *   is pushed (`HelmInput.heave`, `HelmInput.drive`), so a small push makes a small correction.
 * - Ahead / astern (held): the throttle moves at `HELM.throttleRate`. Released, it winds back to
 *   stop at `HELM.throttleRelease`, so the screw turns while the player holds the key, as a player
 *   expects (a telegraph that stayed at full ahead read as a stuck key).
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import { setBallastTarget, setBodyThrust } from '@bitphysics/physics';
import { SUBMARINE, SUBMARINE_NEUTRAL_FILL, type SubmarineHandles, setSubmarineThrusters } from '@bitphysics/projects';

/** Held controls this step: each true while its key or on-screen button is down. */
export interface HelmInput {
  /** Dive (W, the Dive button). */
  dive: boolean;
  /** Rise (S, the Rise button). */
  rise: boolean;
  /** Nose down (Q). */
  noseDown: boolean;
  /** Nose up (E). */
  noseUp: boolean;
  /** Screw ahead (D, right arrow). */
  ahead: boolean;
  /** Screw astern (A, left arrow). */
  astern: boolean;
  /**
   * How hard Dive or Rise is asked, in (0, 1]: the fraction of `HELM.diveSpeed` (`HELM.climbSpeed`)
   * asked for. Default 1 (a key); the on-screen stick sets it from how far it is pushed.
   */
  heave?: number;
  /**
   * How far Ahead or Astern is asked, in (0, 1]: the throttle the screw runs up to (ahead) or
   * -0.5 times it (astern). Default 1 (a key); the on-screen stick sets it from how far it is pushed.
   */
  drive?: number;
}

/** No control held. */
export const NO_INPUT: Readonly<HelmInput> = Object.freeze({
  dive: false,
  rise: false,
  noseDown: false,
  noseUp: false,
  ahead: false,
  astern: false,
});

/** What the helm keeps between steps and last commanded (read by the gauges). */
export interface HelmState {
  /** Screw throttle, fraction of `SUBMARINE.maxThrust`, in [-0.5, 1]. */
  throttle: number;
  /** Mean tank fill the pumps move towards, in [0, 1]. */
  fill: number;
  /** Half the fore-minus-aft fill difference asked for (positive: nose down), in [-0.5, 0.5]. */
  trim: number;
  /** Depth held, as the hull's y, m (negative under water); NaN while none is held. */
  holdY: number;
  /** Vertical thrusters' push last commanded, N: fore and aft, positive up across the hull. */
  fore: number;
  aft: number;
  /** What the helm is doing: 'surfaced', 'diving', 'rising', 'steering' (a Nose key), 'braking' or 'holding'. */
  mode: 'surfaced' | 'diving' | 'rising' | 'steering' | 'braking' | 'holding';
}

/** A new helm state: screw stopped, tanks empty (the scene's start), no depth held. */
export function createHelmState(fill = 0): HelmState {
  return { throttle: 0, fill, trim: 0, holdY: Number.NaN, fore: 0, aft: 0, mode: 'surfaced' };
}

const DEG = Math.PI / 180;

/** The helm's settings. */
export const HELM = Object.freeze({
  /** Vertical speed asked for while Dive is held, m/s (the boat runs at up to 12.9 m/s ahead). */
  diveSpeed: 7,
  /** Vertical speed asked for while Rise is held, m/s (less than diving: the boat must slow before the surface). */
  climbSpeed: 5.5,
  /** Most tank fill the helm adds or takes away (each tank) to speed the boat up or slow it down. */
  ballastExcess: 0.2,
  /**
   * Most tank fill the helm adds or takes away while holding a depth: all of it, so the tanks blow
   * (flood) as far as the boat's sinking (rising) speed asks, ballastGain per m/s. Stopping 110 t at
   * the dive speed still takes metres (600 kN of thrusters, drag k v^2, and the tanks' weight
   * changing at fillRate x 2 x 20 t x g = 392 kN/s); with only ballastExcess it takes more.
   */
  holdExcess: 1,
  /** Tank fill added per m/s that the boat sinks slower (or rises faster) than asked, s/m. */
  ballastGain: 0.2,
  /** Pitch while a Nose key is held, rad (15 degrees). */
  noseAngle: 15 * DEG,
  /** Pitch diving (bow down) or rising (bow up) adds, rad (5 degrees). */
  diveAngle: 5 * DEG,
  /** Time constant of the vertical speed loop, s: the thrusters push m dv / heaveTime. */
  heaveTime: 0.4,
  /** Depth hold: climb asked per metre of depth error, 1/s (the P of the hold's PD law; the D is the speed loop). */
  holdGain: 0.5,
  /** Vertical speed under which braking after a bounce off the seabed ends and that depth is held, m/s. */
  holdSpeed: 0.3,
  /** Pitch loop of the thrusters: torque per radian of pitch error, N m / rad. */
  pitchGain: 3e6,
  /** Pitch loop of the thrusters: torque per rad/s of pitch rate, N m s / rad. */
  pitchDamping: 1.5e6,
  /** Climb asked for as the deck reaches the surface while Rise is held, m/s (more below: holdGain per metre). */
  surfacingSpeed: 0.6,
  /** A surfaced boat counts as surfaced while its deck bobs less than this under the surface, m. */
  surfaceBand: 1.5,
  /** Throttle change per second while Ahead or Astern is held. */
  throttleRate: 2.5,
  /** Throttle change per second towards stop while neither is held. */
  throttleRelease: 1,
});

const clamp = (v: number, lo: number, hi: number): number => (v < lo ? lo : v > hi ? hi : v);

/**
 * One step of the helm: reads the hull (position, velocity, angle, mass) and the sea's surface,
 * updates `state` from `input` and writes the ballast targets, the vertical thrusters and the screw
 * into the world. Call it before each `step(world)`.
 */
export function steer(world: PhysicsWorld, handles: SubmarineHandles, input: HelmInput, state: HelmState): void {
  const c = world.components,
    e = handles.hull,
    dt = world.dt,
    S = SUBMARINE;
  const heaveAsked = clamp(input.heave ?? 1, 0, 1),
    driveAsked = clamp(input.drive ?? 1, 0, 1);
  // The throttle runs at throttleRate toward the one asked for (drive ahead, -drive / 2 astern) and
  // winds back at throttleRelease toward it when it is past it (a stick eased back) or to stop.
  const asked = input.ahead === input.astern ? 0 : input.ahead ? driveAsked : -0.5 * driveAsked;
  const pushing = (asked > 0 && state.throttle < asked) || (asked < 0 && state.throttle > asked);
  const rate = (pushing ? HELM.throttleRate : HELM.throttleRelease) * dt;
  state.throttle = state.throttle < asked ? Math.min(asked, state.throttle + rate) : Math.max(asked, state.throttle - rate);

  const y = c.Position.y[e]!,
    vy = c.Velocity.y[e]!,
    angle = c.Angle.value[e]!,
    spin = c.AngularVelocity.z[e]!,
    mass = c.Mass.value[e]!;
  const surface = c.FluidRegion.surface[handles.sea]!;
  const top = y + S.height / 2; // the deck's height (level hull), m
  const dive = input.dive && !input.rise,
    rise = input.rise && !input.dive;
  const neutral = SUBMARINE_NEUTRAL_FILL;

  // Vertical: the speed asked for (NaN: none asked) and the tanks' mean target.
  let vCmd = Number.NaN;
  if (dive) {
    state.mode = 'diving';
    vCmd = -HELM.diveSpeed * heaveAsked;
  } else if (top > surface || (state.mode === 'surfaced' && top > surface - HELM.surfaceBand)) {
    // On the surface and not told to dive: tanks blown, the boat floats (Rise there does the same).
    // It stays surfaced while it bobs within surfaceBand of the surface.
    state.mode = 'surfaced';
  } else if (rise) {
    state.mode = 'rising';
    // Slower near the surface, so the boat comes up to it gently instead of leaping out.
    vCmd = Math.min(HELM.climbSpeed * heaveAsked, HELM.surfacingSpeed + HELM.holdGain * (surface - top));
  } else if (input.noseDown !== input.noseUp) {
    // Steering by the nose: no depth held, so with the screw ahead the boat follows its nose.
    state.mode = 'steering';
  } else {
    // Let go: hold the depth where the key was released (the boat's momentum carries it on a few
    // metres, then the helm brings it back). After a bounce off the seabed (holdY cleared while
    // braking or holding) the helm brakes first and holds where the boat stops instead.
    if (state.mode !== 'braking' && state.mode !== 'holding') state.holdY = y;
    if (Number.isNaN(state.holdY) && Math.abs(vy) < HELM.holdSpeed) state.holdY = y;
    state.mode = Number.isNaN(state.holdY) ? 'braking' : 'holding';
    vCmd = Number.isNaN(state.holdY) ? 0 : clamp(HELM.holdGain * (state.holdY - y), -HELM.climbSpeed, HELM.climbSpeed);
  }
  if (state.mode !== 'braking' && state.mode !== 'holding') state.holdY = Number.NaN;
  if (state.mode === 'surfaced') state.fill = 0;
  else if (Number.isNaN(vCmd)) state.fill = neutral;
  else {
    // The weight that carries the boat at vCmd against drag (k v^2 = 2 capacity g df), and more
    // while the boat is slower or faster than asked (heavier while it rises too fast).
    const carry = (-Math.sign(vCmd) * S.dragCoefficient * vCmd * vCmd) / (2 * S.tankCapacity * 9.81);
    const hold = state.mode === 'holding' || state.mode === 'braking';
    const excess = hold ? HELM.holdExcess : HELM.ballastExcess;
    state.fill = clamp(neutral + carry + clamp(HELM.ballastGain * (vy - vCmd), -excess, excess), 0, 1);
  }
  // The thrusters push across the hull. Steering by the nose, they stop the hull sliding across its
  // own axis (the speed v_n = -vx sin(angle) + vy cos(angle)), so it goes where it points, as a moving
  // boat does with its hydroplanes; otherwise they chase the vertical speed asked for.
  const vn = -c.Velocity.x[e]! * Math.sin(angle) + vy * Math.cos(angle);
  const heave = state.mode === 'steering' ? (-mass * vn) / HELM.heaveTime : Number.isNaN(vCmd) ? 0 : (mass * (vCmd - vy)) / HELM.heaveTime;

  // Pitch: the angle asked for (positive: nose up), by the thrusters now and by the water for good.
  const pitch =
    HELM.noseAngle * (Number(input.noseUp) - Number(input.noseDown)) +
    HELM.diveAngle * (Number(state.mode === 'rising') - Number(state.mode === 'diving'));
  // Static trim (forces/ballast.ts): arm capacity (f_fore - f_aft) g cos = -M g GM sin, so the
  // half difference is -tan(pitch) M GM / (2 arm capacity).
  // Limited so that both tanks stay within [0, 1] around the mean (the thrusters give the rest).
  const room = Math.min(state.fill, 1 - state.fill);
  state.trim = clamp((-Math.tan(pitch) * mass * S.metacentricHeight) / (2 * S.tankArm * S.tankCapacity), -room, room);
  const fore = clamp(state.fill + state.trim, 0, 1),
    aft = clamp(state.fill - state.trim, 0, 1);
  setBallastTarget(world, e, fore, aft);

  // Thrusters: the pitch torque gets up to half of each one's push, the heave the rest.
  const T = S.thrusterForce,
    a = S.thrusterArm;
  const torque = clamp(HELM.pitchGain * (pitch - angle) - HELM.pitchDamping * spin, -T * a, T * a);
  const tPart = torque / (2 * a),
    left = T - Math.abs(tPart);
  const hPart = clamp(heave / 2, -left, left);
  state.fore = hPart + tPart;
  state.aft = hPart - tPart;
  // At the surface with nothing asked the thrusters rest (they would only churn the water).
  if (state.mode === 'surfaced' && pitch === 0) state.fore = state.aft = 0;
  setSubmarineThrusters(handles, state.fore, state.aft);
  setBodyThrust(world, e, [state.throttle * S.maxThrust, 0]);
}
