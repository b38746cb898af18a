/**
 * The flight simulator's flight assist: turns the pilot's stick into aileron, elevator and rudder
 * each step, the way a fly-by-wire control law does, so a player who has never flown can steer. The
 * physics stays the aircraft scene's own (lifting surfaces, Euler's equations); the assist only
 * decides where the control surfaces point.
 *
 * - Stick sideways: a bank angle, up to `ASSIST.maxBank` at full stick (the ailerons roll the
 *   aircraft there and hold it, the rudder turning the nose with them); let go, the wings roll
 *   level. A tap holds its bank a moment (`ASSIST.tapTime`), so it turns the aircraft a few
 *   degrees; a longer touch up to `ASSIST.holdFade` holds less for less time (letGoHold).
 * - Stick forward and back: the stick moves the elevator itself in proportion to its deflection, so
 *   a held climb or dive gets the full response it has without the assist, up to a path of
 *   `ASSIST.maxPath` (45 degrees: no loop, no vertical dive); the rest of the elevator is a path
 *   hold that asks for `ASSIST.maxClimb` times the stick (pulling harder in a bank to keep the
 *   height). Let go, the path hold alone flies the aircraft level.
 * - Rudder: as held, plus what cancels the sideslip (a coordinated turn).
 * - Throttle: the pilot's alone; the assist never moves it, so the stick steers without changing the
 *   engine (a climb trades speed for height, a dive the other way, as the physics has it).
 * - A wing angle of attack past `ASSIST.alphaLimit` is not asked for: the elevator eases off before
 *   the stall (the aircraft still stalls if it is slowed far enough by a long climb).
 *
 * Without the assist (the panel's switch) the stick moves the control surfaces directly.
 * Headless (no DOM), so its behaviour is tested in node (test/games/flight-simulator-assist.test.ts).
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import { AIRCRAFT } from '@bitphysics/projects';

const DEG = Math.PI / 180;

/** The pilot's inputs, each in [-1, 1]. */
export interface PilotInput {
  /** Stick sideways: + right. */
  roll: number;
  /** Stick forward and back: + nose up (climb). */
  pitch: number;
  /** Rudder pedals: + nose right. */
  yaw: number;
}

/** Control surface commands, each a fraction of full deflection in [-1, 1]. */
export interface ControlCommand {
  /** + rolls right (the left aileron down, the right one up). */
  aileron: number;
  /** + pitches the nose up (the elevator's trailing edge up). */
  elevator: number;
  /** + yaws the nose right. */
  rudder: number;
}

/** The aircraft's state as the assist and the instruments read it. Angles in rad, speeds in m/s. */
export interface FlightState {
  /** Airspeed |v|, m/s. */
  speed: number;
  /** Bank angle, rad, + right wing down, in (-pi, pi]: atan2(-r_y, u_y) of the body's right and up axes. */
  bank: number;
  /** Pitch of the nose above the horizon, rad, in [-pi/2, pi/2]. */
  pitch: number;
  /** Flight-path angle: the climb of the velocity above the horizon, rad. */
  path: number;
  /** Heading of the nose, rad, in [0, 2 pi): 0 along +x, pi/2 along +z (to the right). */
  heading: number;
  /** The wing's angle of attack, rad: the body's (atan2(-v.u, v.f)) plus the wing's incidence. */
  alpha: number;
  /** Sideslip, rad, + with the air meeting the aircraft from its right: asin(v.r / |v|). */
  sideslip: number;
  /** Body rates, rad/s: roll (+ right wing down), pitch (+ nose up), yaw (+ nose right). */
  rollRate: number;
  pitchRate: number;
  yawRate: number;
}

/**
 * Full deflection of each control surface, degrees (the page's default; its panel can change it).
 * 25: a held key banks the aircraft 30 degrees in 0.8 s and 40 in 1.2 s (with 15 it took 1.4 s
 * to 30: players found it floaty).
 */
export const CONTROL_AUTHORITY = 25;

/**
 * Full deflection of the ailerons as a multiple of the control authority (40 degrees at the default
 * 25, within the 45 the lifting surfaces take): they roll the aircraft at up to about 1.35 rad/s, so
 * a bank rolls level soon after the key is let go and the turn stops there (at 1.2 the roll was
 * 1 rad/s and a 0.7 s hold turned 80 % of its heading after the release).
 */
export const AILERON_SCALE = 1.6;

/** The assist's settings. */
export const ASSIST = Object.freeze({
  /**
   * Bank at full sideways stick, rad (70 degrees: a 2.9 g level turn, about 14 degrees/s of heading
   * at 110 m/s, so a held key turns half round in about 13 s; the wing stays under `alphaLimit`
   * down to about 95 m/s). With 45 a half turn took 38 s and the turning circle (2 km) was wider
   * than the rings are apart: strangers found it too slow to steer.
   */
  maxBank: 70 * DEG,
  /** Flight-path angle the path hold asks for at full stick forward or back, rad (its share fades as the stick's grows). */
  maxClimb: 20 * DEG,
  /**
   * Steepest flight path the stick's own elevator pitches to, up or down, rad: within `pathFade` of
   * it the stick's share fades to nothing and the path hold takes over (no loop, no vertical dive).
   */
  maxPath: 45 * DEG,
  /** Width of the fade below `maxPath`, rad. */
  pathFade: 10 * DEG,
  /**
   * Aileron per radian of bank error (1/rad): full aileron is asked for until the bank is within 6
   * degrees of the one asked for, so the wings roll level briskly when the stick is let go (with 2.5
   * the last 15 degrees took 1.4 s, and the turn ran on 3 degrees of heading past the release:
   * players overshot).
   */
  bankGain: 10,
  /** Aileron per rad/s of roll rate, s: damps the roll so that it stops at the bank asked for, not past it. */
  rollDamping: 0.6,
  /** Elevator per radian of flight-path error (1/rad). */
  pathGain: 5,
  /** Elevator per radian-second of flight-path error (1/(rad s)): the integral that finds the trim. */
  pathIntegral: 0.8,
  /**
   * Elevator per unit of extra load factor 1 / cos(bank) - 1 (the lift a level turn needs beyond the
   * weight), asked for at once so that a bank does not first lose height while the integral catches up.
   */
  turnElevator: 0.7,
  /** Elevator per rad/s of pitch rate, s: damps the short-period pitching. */
  pitchDamping: 1.5,
  /** Largest wing angle of attack the assist asks for, rad (the wing stalls at 20 degrees). */
  alphaLimit: 14 * DEG,
  /** Elevator taken off per radian of angle of attack past the limit (1/rad). */
  alphaGain: 8,
  /** Rudder per radian of sideslip (1/rad): turns the nose into the air. */
  sideslipGain: 3,
  /**
   * Rudder per unit of aileron: cancels the ailerons' adverse yaw, so the nose swings into the turn
   * as the wings roll (without it the nose first swung 0.6 degrees the other way over 0.4 s).
   */
  aileronRudder: 0.5,
  /** Fastest change of the bank asked for, rad/s (a full stick's bank is reached smoothly). */
  bankRate: 120 * DEG,
  /**
   * How long a tap of the stick sideways holds its bank, s (its age): a tap of a bank key (or a
   * short touch of the phone's stick) rolls the aircraft far enough, for long enough, to turn it
   * about 3 degrees; a touch up to `holdFade` holds less for less time (assist.ts letGoHold), so the
   * heading turned grows with the hold (2.9 degrees at 0.1 s, 3.0 at 0.4, 4.2 at 0.5, 10 at 1 s).
   */
  tapTime: 1.1,
  /**
   * Longest touch of the stick sideways that is a tap, s: one eased off later holds less
   * (letGoHold) and its wings never roll on past the bank they have, so the turn stops where the
   * flight-path marker said. 0.35 s
   * keeps a tap of two frames at 5 frames a second (0.3 s of game time) a tap.
   */
  tapLength: 0.35,
  /**
   * Largest bank a tap holds, rad (32 degrees): a 150 ms tap turns the aircraft about 3 degrees (2.5
   * when it held 31 degrees for 0.9 s).
   */
  tapBank: 32 * DEG,
  /**
   * Age of a touch of the stick sideways, s, from which one let go holds nothing: between
   * `tapLength` and this a touch holds less bank for less time the longer it was (assist.ts letGoHold).
   */
  holdFade: 0.9,
  /** Lead on the roll rate when a short hold is let go, s: it holds the bank where the roll stops, not the one it has. */
  rollLead: 0.2,
});

/** What the assist keeps between steps: the integral of the flight-path error and the bank asked for. */
export interface AssistState {
  /** Integral of the flight-path error, rad s (kept within what makes full elevator). */
  integral: number;
  /** Bank asked for now, rad (moves towards the stick's at `ASSIST.bankRate`). */
  bankTarget: number;
  /** How long the stick has been off centre sideways, s (0 while it is centred). */
  rollHeld: number;
  /** The largest sideways stick of this touch while it is held, or once let go the stick it holds (0 once past `rollUntil`), signed, in [-1, 1]. */
  rollPeak: number;
  /** Whether this touch has eased off while it still holds a bank (its `rollPeak` is held until `rollUntil`). */
  rollTap: boolean;
  /** The touch's age until which a stick let go is held, s (`ASSIST.tapTime` until it is let go). */
  rollUntil: number;
}

/**
 * The bank a stick let go now would still hold, and for how long (rad, + right; 0 when none, and
 * the time left, s; see letGoHold). `now` is the aircraft's bank, rad, and roll rate, rad/s (what
 * a touch longer than `ASSIST.tapLength` keeps depends on them; default level and still).
 */
export function heldBank(
  state: AssistState,
  now: { bank: number; rollRate: number } = { bank: 0, rollRate: 0 },
): { bank: number; time: number } {
  if (state.rollPeak === 0 || state.rollHeld >= state.rollUntil) return { bank: 0, time: 0 };
  if (state.rollTap) return { bank: ASSIST.maxBank * state.rollPeak, time: state.rollUntil - state.rollHeld };
  const h = letGoHold(state.rollHeld, state.rollPeak, now.bank, now.rollRate);
  return { bank: ASSIST.maxBank * h.stick, time: h.until - state.rollHeld };
}

/**
 * What a touch of the stick `age` s old at its largest `peak` (signed, in [-1, 1]) holds when let
 * go in a bank of `bank` rad rolling at `rollRate` rad/s: the stick held (signed, never more than
 * `peak`, never the other way) and the age until which it is held, s. A tap (`age` up to
 * `ASSIST.tapLength`) holds its bank, at most `ASSIST.tapBank`, until `ASSIST.tapTime`. A longer
 * touch holds less the longer it was, for less time: the share (holdFade - age) / (holdFade -
 * tapLength) of a tap's hold time, at the larger of that share of `tapBank` and the bank where the
 * roll stops (`bank` less `rollRate` x `ASSIST.rollLead`: the ailerons reverse at once, so the wings
 * never roll on past the release); from `ASSIST.holdFade` on, nothing (the wings roll level at once).
 */
function letGoHold(age: number, peak: number, bank: number, rollRate: number): { stick: number; until: number } {
  const A = ASSIST,
    sign = Math.sign(peak),
    size = Math.abs(peak);
  if (age <= A.tapLength) return { stick: sign * Math.min(size, A.tapBank / A.maxBank), until: A.tapTime };
  const share = clamp((A.holdFade - age) / (A.holdFade - A.tapLength), 0, 1);
  if (share === 0) return { stick: 0, until: age };
  const stops = Math.max(0, sign * (bank - rollRate * A.rollLead));
  return { stick: sign * Math.min(size, Math.max(stops, share * A.tapBank) / A.maxBank), until: age + share * (A.tapTime - A.tapLength) };
}

/** A new assist state: no integral, wings level asked for. */
export function createAssistState(): AssistState {
  return { integral: 0, bankTarget: 0, rollHeld: 0, rollPeak: 0, rollTap: false, rollUntil: ASSIST.tapTime };
}

const clamp = (v: number, lo: number, hi: number): number => (v < lo ? lo : v > hi ? hi : v);

/** Reads the flight state of `body` (a 3D body with an orientation) from the world. */
export function flightState(world: PhysicsWorld, body: number): FlightState {
  const c = world.components;
  const qx = c.Orientation.x[body]!,
    qy = c.Orientation.y[body]!,
    qz = c.Orientation.z[body]!,
    qw = c.Orientation.w[body]!;
  // The body's axes in world coordinates (the rotation matrix's columns): forward f, up u, right r.
  const fx = 1 - 2 * (qy * qy + qz * qz),
    fy = 2 * (qx * qy + qz * qw),
    fz = 2 * (qx * qz - qy * qw);
  const ux = 2 * (qx * qy - qz * qw),
    uy = 1 - 2 * (qx * qx + qz * qz),
    uz = 2 * (qy * qz + qx * qw);
  const rx = 2 * (qx * qz + qy * qw),
    ry = 2 * (qy * qz - qx * qw),
    rz = 1 - 2 * (qx * qx + qy * qy);
  const vx = c.Velocity.x[body]!,
    vy = c.Velocity.y[body]!,
    vz = c.Velocity.z[body]!;
  const speed = Math.hypot(vx, vy, vz);
  const wx = c.AngularVelocity.x[body]!,
    wy = c.AngularVelocity.y[body]!,
    wz = c.AngularVelocity.z[body]!;
  const vf = vx * fx + vy * fy + vz * fz,
    vu = vx * ux + vy * uy + vz * uz,
    vr = vx * rx + vy * ry + vz * rz;
  return {
    speed,
    bank: Math.atan2(-ry, uy),
    pitch: Math.asin(clamp(fy, -1, 1)),
    path: speed > 0 ? Math.asin(clamp(vy / speed, -1, 1)) : 0,
    heading: (Math.atan2(fz, fx) + 2 * Math.PI) % (2 * Math.PI),
    alpha: Math.atan2(-vu, vf) + AIRCRAFT.incidence,
    sideslip: speed > 0 ? Math.asin(clamp(vr / speed, -1, 1)) : 0,
    rollRate: wx * fx + wy * fy + wz * fz,
    pitchRate: wx * rx + wy * ry + wz * rz,
    // A rotation about the body's up axis turns the nose to the left: nose right is its negative.
    yawRate: -(wx * ux + wy * uy + wz * uz),
  };
}

/**
 * One step of the assist: the control surfaces that fly the aircraft in `s` where the pilot's
 * `input` asks (see the header), over a step of `dt` s (> 0). Updates `state`.
 */
export function assist(s: FlightState, input: PilotInput, state: AssistState, dt: number): ControlCommand {
  const A = ASSIST;
  // Bank: towards the stick's bank at a limited rate, the ailerons on the error and the roll rate.
  // A touch of the stick let go holds a bank a moment (letGoHold: a tap turns).
  let roll = clamp(input.roll, -1, 1);
  const reversed = state.rollPeak !== 0 && Math.sign(roll) === -Math.sign(state.rollPeak);
  if (roll !== 0 && (state.rollHeld === 0 || reversed)) {
    state.rollHeld = 0;
    state.rollPeak = 0;
    state.rollTap = false;
    state.rollUntil = ASSIST.tapTime;
  }
  if (roll !== 0 || state.rollPeak !== 0) {
    state.rollHeld += dt;
    if (state.rollHeld > state.rollUntil) state.rollPeak = 0;
    else if (Math.abs(roll) >= Math.abs(state.rollPeak)) state.rollPeak = roll;
    else {
      // Eased off: a tap or a short hold keeps a bank a while (letGoHold), so a tap turns a few
      // degrees and a longer touch never turns less than a shorter one.
      if (!state.rollTap) {
        const h = letGoHold(state.rollHeld, state.rollPeak, s.bank, s.rollRate);
        state.rollPeak = h.stick;
        state.rollUntil = h.until;
        state.rollTap = true;
      }
      if (state.rollPeak !== 0 && state.rollHeld <= state.rollUntil) roll = state.rollPeak;
      else state.rollPeak = 0;
    }
  }
  if (roll === 0) {
    state.rollHeld = 0;
    state.rollTap = false;
    state.rollUntil = ASSIST.tapTime;
  }
  const wanted = A.maxBank * roll;
  // Eased off or let go: the bank asked for never lies beyond the bank the aircraft has (nor short
  // of the stick's), so the wings stop rolling into the turn at once and roll back from where they
  // are, and the turn stops soon after the release (a target still 20 degrees ahead of the bank
  // rolled the aircraft on into the turn for 0.3 s after the key was let go).
  if (
    Math.abs(wanted) < Math.abs(state.bankTarget) &&
    Math.sign(s.bank) === Math.sign(state.bankTarget) &&
    Math.abs(s.bank) < Math.abs(state.bankTarget)
  )
    state.bankTarget = Math.sign(s.bank) * Math.max(Math.abs(s.bank), Math.sign(s.bank) * wanted);
  state.bankTarget += clamp(wanted - state.bankTarget, -A.bankRate * dt, A.bankRate * dt);
  const aileron = clamp(A.bankGain * (state.bankTarget - s.bank) - A.rollDamping * s.rollRate, -1, 1);
  // The stick's own share of the elevator: its deflection |pitch|, faded out over `pathFade` as the
  // path nears `maxPath` the way the stick pushes (no loop, no vertical dive).
  const stick = clamp(input.pitch, -1, 1);
  const share = Math.abs(stick) * clamp((A.maxPath - Math.sign(stick) * s.path) / A.pathFade, 0, 1);
  // Flight path: proportional, integral and pitch-rate damping. The integral finds the elevator the
  // trim needs (more in a bank, where the lift must also carry the turn) and winds no further than
  // full elevator. It rests while the stick has the elevator (no wind-up against a held climb) and
  // while the hold asks for full elevator the way the error pushes (no wind-up while it pulls out of
  // a steep climb or dive, which would carry the path past level for seconds after).
  const error = A.maxClimb * stick - s.path;
  const limit = 1 / A.pathIntegral;
  const turn = 1 / Math.max(0.3, Math.cos(s.bank)) - 1;
  const others = A.pathGain * error + A.turnElevator * turn - A.pitchDamping * s.pitchRate;
  const before = others + A.pathIntegral * state.integral;
  const saturated = Math.abs(before) >= 1 && Math.sign(error) === Math.sign(before);
  if (!saturated) state.integral = clamp(state.integral + (1 - share) * error * dt, -limit, limit);
  const hold = others + A.pathIntegral * state.integral;
  let elevator = share * stick + (1 - share) * hold;
  // Angle of attack limit: past it, nose-up elevator is taken off (never beyond what brings it back).
  if (s.alpha > A.alphaLimit) elevator = Math.min(elevator, -A.alphaGain * (s.alpha - A.alphaLimit));
  elevator = clamp(elevator, -1, 1);
  const rudder = clamp(input.yaw + A.sideslipGain * s.sideslip + A.aileronRudder * aileron, -1, 1);
  return { aileron, elevator, rudder };
}

/**
 * How fast the control surfaces move towards what they are asked, fraction of full deflection per
 * second: to the assist's command (12: the ailerons reverse in a sixth of a second when a bank key
 * is let go; at 6 the aircraft rolled on into the turn meanwhile), and (without the assist) to the
 * stick's input.
 */
export const SURFACE_RATE = Object.freeze({ assist: 12, direct: 3 });

/**
 * `value` moved towards `target` by at most `rate` x `dt` (a control surface over a step).
 * @throws RangeError on a rate or dt that is negative or not finite.
 */
export function approach(value: number, target: number, rate: number, dt: number): number {
  if (!(rate >= 0 && dt >= 0 && Number.isFinite(rate * dt)))
    throw new RangeError(`approach: rate and dt must be finite and >= 0, got ${rate}, ${dt}`);
  return value + clamp(target - value, -rate * dt, rate * dt);
}

/**
 * How the keyboard's climb / dive and bank keys move their input (`rampKey`): a held key's input
 * grows as from (e^(rise t) - 1), slowly at first and then faster, the way a keyboard-flown sim
 * moves its control surface, so a tap asks for a small correction and a held key for full stick.
 */
export const KEY_RAMP: KeyRamp = Object.freeze({
  /**
   * Growth rate of a held key's input, 1/s: with `from` 0.25 it is full after ln 5 / 4 = 0.40 s of
   * holding (as the straight ramp was, so a held key banks as briskly), 0.12 after a 0.1 s tap and
   * 0.31 after 0.2 s. (A straight ramp to full in 0.4 s gave
   * 0.25 for a 0.1 s tap: strangers found the bank all or nothing; one to full in 1.25 s felt sluggish.)
   */
  rise: 4,
  /** Where the growth starts from (added to the input's size), fraction of full stick. */
  from: 0.25,
  /** Rate a released key's input returns to 0, and a reversed one crosses 0, 1/s: neutral in 0.25 s. */
  fall: 4,
  /** Input a press starts at, fraction of full stick. */
  start: 0,
});

/** A key ramp (`rampKey`): growth rate `rise` 1/s from `from`, release rate `fall` 1/s, a press starting at `start` in [0, 1). */
export interface KeyRamp {
  readonly rise: number;
  readonly from: number;
  readonly fall: number;
  readonly start: number;
}

/**
 * How the bank keys move their input (`rampKey`): a press asks at once for `start` (0.3 of full
 * stick, a bank of 21 degrees, which the assist holds for `ASSIST.tapTime`, so a 150 ms tap turns
 * the aircraft about 2.4 degrees), full stick after ln(1.25 / 0.55) / 1.5 = 0.55 s held; released,
 * neutral in 1/12 s, so that the wings start back to level at once (in 0.25 s they first rolled on).
 */
export const BANK_KEY_RAMP: KeyRamp = Object.freeze({ rise: 1.5, from: 0.25, fall: 12, start: 0.3 });

/**
 * One step of a keyboard axis on `ramp` (default KEY_RAMP; the bank keys use BANK_KEY_RAMP):
 * `value` (the input now, in [-1, 1]) moved over `dt` s (>= 0) towards `direction` (-1, 0 or 1:
 * the key held, or none): back towards 0 at `ramp.fall` per second (released, or held the other way
 * while still on the first side), else on towards the key held, from at least `ramp.start`, its
 * size growing as |v| + from = (max(|v0|, start) + from) e^(rise dt) (exact for any dt).
 * A key is not a stick: it is all or nothing, so a tap ramped this way asks for a small correction
 * (KEY_RAMP: a 0.1 s tap is 0.12 of full stick) and only a key held 0.4 s asks for the full climb.
 * @returns the new input, in [-1, 1].
 * @throws RangeError on a value outside [-1, 1], a direction not in {-1, 0, 1} or a negative dt.
 */
export function rampKey(value: number, direction: number, dt: number, ramp: KeyRamp = KEY_RAMP): number {
  if (!(value >= -1 && value <= 1)) throw new RangeError(`rampKey: value must be in [-1, 1], got ${value}`);
  if (direction !== -1 && direction !== 0 && direction !== 1)
    throw new RangeError(`rampKey: direction must be -1, 0 or 1, got ${direction}`);
  if (!(dt >= 0)) throw new RangeError(`rampKey: dt must be >= 0 s, got ${dt}`);
  // Back towards 0 first when released or reversed; then on towards the key held.
  if (value !== 0 && Math.sign(value) !== direction) {
    const back = Math.max(0, Math.abs(value) - ramp.fall * dt);
    if (back > 0 || direction === 0) return Math.sign(value) * back;
    // Crossed 0 within the step: the rest of the step ramps the other way.
    dt -= Math.abs(value) / ramp.fall;
    value = 0;
  }
  if (direction === 0) return value;
  const size = (Math.max(Math.abs(value), ramp.start) + ramp.from) * Math.exp(ramp.rise * dt) - ramp.from;
  return direction * Math.min(1, size);
}

/**
 * The throttle's response to Faster / Slower, fraction of full thrust: a press steps it at once to
 * the next multiple of `step` at least `least` away (28 % goes to 40 %, 35 % to 40 %), so a tap on
 * the phone's button changes the engine by a figure the readout shows (a held button moving it at
 * `rate` per second moved it 3 % in a short tap, or not at all when the press and release came in
 * one frame); held past `hold` s it goes on at `rate` per second.
 */
export const THROTTLE_KEY = Object.freeze({ step: 0.1, least: 0.05, hold: 0.35, rate: 0.4 });

/**
 * The throttle after one press of Faster (`direction` 1) or Slower (-1) from `throttle`: the next
 * multiple of THROTTLE_KEY.step that way, at least THROTTLE_KEY.least away, within [0, 1].
 * @param throttle the throttle now, fraction of full thrust, in [0, 1].
 * @param direction 1 (Faster) or -1 (Slower).
 * @returns the new throttle, in [0, 1].
 * @throws RangeError on a throttle outside [0, 1] or a direction not 1 or -1.
 */
export function throttleStep(throttle: number, direction: number): number {
  if (!(throttle >= 0 && throttle <= 1)) throw new RangeError(`throttleStep: throttle must be in [0, 1], got ${throttle}`);
  if (direction !== 1 && direction !== -1) throw new RangeError(`throttleStep: direction must be 1 or -1, got ${direction}`);
  const { step, least } = THROTTLE_KEY;
  // In whole steps, rounded to 1e-9 so that 0.3 + 0.1 lands on 4 steps, not just past it.
  const k = (throttle + direction * least) / step;
  const n = direction > 0 ? Math.ceil(k - 1e-9) : Math.floor(k + 1e-9);
  return Math.min(1, Math.max(0, Math.round(n * step * 1e9) / 1e9));
}

/** Dead zone of the phone's stick (`stickResponse`), a share of its full travel: a finger resting near the centre asks for nothing. */
export const STICK_DEAD_ZONE = 0.05;
/** Exponent of the phone's stick response past the dead zone (`stickResponse`): above 1, gentle near the centre and full at the rim. */
export const STICK_EXPONENT = 1.7;

/**
 * The phone stick's response: its deflection `x` (right), `y` (up), each in [-1, 1], turned into the
 * pilot's input along the same direction, its size d (the deflection's length, at most 1) mapped to
 * ((d - STICK_DEAD_ZONE) / (1 - STICK_DEAD_ZONE)) ^ STICK_EXPONENT: 0 inside the dead zone, a
 * quarter of full at half travel (a fine correction), full at the rim. Linear, half a push asked
 * for half the bank (35 degrees) and swung a ring off the phone's narrow view.
 * @throws RangeError on an `x` or `y` that is not finite.
 */
export function stickResponse(x: number, y: number): { x: number; y: number } {
  if (!Number.isFinite(x) || !Number.isFinite(y)) throw new RangeError(`stickResponse: x and y must be finite, got ${x}, ${y}`);
  const d = Math.min(1, Math.hypot(x, y));
  if (d <= STICK_DEAD_ZONE) return { x: 0, y: 0 };
  const k = ((d - STICK_DEAD_ZONE) / (1 - STICK_DEAD_ZONE)) ** STICK_EXPONENT / Math.hypot(x, y);
  return { x: x * k, y: y * k };
}
