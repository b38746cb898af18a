/**
 * The flight simulator's flight assist: turns the pilot's stick into aileron, elevator and rudder
 * each step, the way a fly-by-wire control law does, so a player who has never flown can steer. The
 * physics stays the aircraft scene's own (lifting surfaces, Euler's equations); the assist only
 * decides where the control surfaces point.
 *
 * - Stick sideways: a turn rate, the one a bank of up to `ASSIST.maxBank` at full stick gives at the
 *   trim speed, held steady as the speed changes (`steadyTurnBank`: the bank follows the speed; the
 *   ailerons roll the aircraft there and hold it, the rudder turning the nose with them); eased off, the bank eases with
 *   it; let go, the wings roll level at once and the turn stops. Only a tap (let go within
 *   `ASSIST.tapTime` of the touch) holds its bank until the touch is `tapTime` old, so that a tap of a
 *   bank key still rolls the aircraft far enough to turn it a little.
 * - Stick forward and back: the stick moves the elevator itself in proportion to its deflection, so
 *   a held climb or dive gets the full response it has without the assist, up to a path of
 *   `ASSIST.maxPath` (45 degrees: no loop, no vertical dive); the rest of the elevator is a path
 *   hold that asks for `ASSIST.maxClimb` times the stick (pulling harder in a bank to keep the
 *   height). Let go, the path hold alone flies the aircraft level.
 * - Rudder: as held, plus what cancels the sideslip (a coordinated turn) and a yaw damper that
 *   steadies the nose once a turn is let go (`ASSIST.yawDamping`).
 * - Throttle: the pilot's alone; the assist never moves it, so the stick steers without changing the
 *   engine (a climb trades speed for height, a dive the other way, as the physics has it).
 * - A wing angle of attack past `ASSIST.alphaLimit` is not asked for: the elevator eases off before
 *   the stall (the aircraft still stalls if it is slowed far enough by a long climb).
 *
 * Without the assist (the panel's switch) the stick moves the control surfaces directly.
 * Headless (no DOM), so its behaviour is tested in node (test/games/flight-simulator-assist.test.ts).
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import { AIRCRAFT, AIRCRAFT_TRIM_SPEED } from '@bitphysics/projects';

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
 * 25: a held key banks the aircraft 30 degrees in 0.8 s and 40 in 1.2 s, brisk enough that the
 * controls do not feel floaty (15 would take 1.4 s to 30).
 */
export const CONTROL_AUTHORITY = 25;

/**
 * Full deflection of the ailerons as a multiple of the control authority (45 degrees at the default
 * 25, all the lifting surfaces take; the page caps a larger authority's there): they roll the
 * aircraft at up to about 1.7 rad/s at 130 m/s (1.5 at 1.6), so a 70 degree bank rolls level within
 * 0.9 s of the key's release and the turn stops there (at 1.2 the roll would be 1 rad/s and a 0.7 s
 * hold would turn 80 % of its heading after the release).
 */
export const AILERON_SCALE = 1.8;

/** The assist's settings. */
export const ASSIST = Object.freeze({
  /**
   * Bank at full sideways stick, rad (70 degrees: a 2.9 g level turn, about 14 degrees/s of heading
   * at 110 m/s, so a held key turns half round in about 13 s; the wing stays under `alphaLimit`
   * down to about 95 m/s), so the turning circle is tighter than the rings are apart (with 45 a
   * half turn would take 38 s and the circle, 2 km, be wider than that gap).
   */
  maxBank: 70 * DEG,
  /**
   * Steepest bank the assist asks for, rad (75 degrees): full stick at a speed over the trim speed
   * asks for more than `maxBank` to keep its turn rate (`steadyTurnBank`), up to this.
   */
  steepestBank: 75 * DEG,
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
   * degrees of the one asked for, so the wings roll level briskly when the stick is let go and the
   * turn stops where it is released (with 2.5 the last 15 degrees would take 1.4 s, and the turn run
   * on 3 degrees of heading past the release).
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
   * Rudder per rad/s of yaw rate beyond a coordinated turn's (g sin(bank) cos(pitch) / V), s: a yaw
   * damper. As a turn is let go the wings roll level and the nose would swing back and forth about
   * its new heading, 4.5 degrees on the compass over 2 s (the cockpit view's whole scene with it);
   * with it, under 1.5. It fades out while a rudder key is held, so it never fights the pedals.
   */
  yawDamping: 4,
  /**
   * Rudder per unit of aileron: cancels the ailerons' adverse yaw, so the nose swings into the turn
   * as the wings roll (without it the nose first swung 0.6 degrees the other way over 0.4 s).
   */
  aileronRudder: 0.5,
  /**
   * Fastest change of the bank asked for, rad/s (a full stick's bank is reached smoothly; faster than
   * the ailerons roll the aircraft, so they are not held back by it).
   */
  bankRate: 180 * DEG,
  /**
   * Age of a touch of the stick sideways, s, up to which one let go is a tap: its bank (at most
   * `tapBank`) is held until the touch is this old, then the wings roll level. A tap of a bank key
   * (0.15 s) then banks the aircraft about 20 degrees and turns it about a degree; a touch let go
   * later is let go at once, so the aircraft does not stay banked after the key is let go (a tap held
   * to 1.1 s would leave a 150 ms tap still 28 degrees banked 1 s after the release).
   */
  tapTime: 0.35,
  /** Largest bank a tap holds, rad (25 degrees). */
  tapBank: 25 * DEG,
});

/**
 * The bank that turns the aircraft at `speed` (m/s) at the rate the stick's bank `stickBank` (rad,
 * + right) turns it at the trim speed: a level coordinated turn's rate is g tan(bank) / V, so
 * tan(bank) = tan(stickBank) V / AIRCRAFT_TRIM_SPEED, at most `ASSIST.steepestBank` either way. A
 * held stick then holds a steady turn rate as the turn bleeds the speed, so a steady turn is easy to
 * hold (with the stick's bank itself, a held full bank would turn 13.5 to 15.7 degrees a second as
 * the speed fell from 113 to 94 m/s).
 * @throws RangeError on a stickBank that is not finite or a speed that is negative or not finite.
 */
export function steadyTurnBank(stickBank: number, speed: number): number {
  if (!Number.isFinite(stickBank)) throw new RangeError(`steadyTurnBank: stickBank must be finite, got ${stickBank}`);
  if (!(speed >= 0 && Number.isFinite(speed))) throw new RangeError(`steadyTurnBank: speed must be finite and >= 0 m/s, got ${speed}`);
  if (stickBank === 0) return 0;
  const bank = Math.atan((Math.tan(Math.min(Math.abs(stickBank), ASSIST.maxBank)) * speed) / AIRCRAFT_TRIM_SPEED);
  return Math.sign(stickBank) * Math.min(bank, ASSIST.steepestBank);
}

/** What the assist keeps between steps: the integral of the flight-path error and the bank asked for. */
export interface AssistState {
  /** Integral of the flight-path error, rad s (kept within what makes full elevator). */
  integral: number;
  /** Bank asked for now, rad (moves towards the stick's at `ASSIST.bankRate`). */
  bankTarget: number;
  /** Age of the touch of the stick sideways, s (0 while it is centred and no tap is held). */
  rollHeld: number;
  /** The largest sideways stick of this touch, signed, in [-1, 1]; once a tap is let go, the stick it holds (0: none). */
  rollPeak: number;
  /** Whether the ground floor (`assist`'s `floor`) held the aircraft up against the stick at the last step. */
  floorHold: boolean;
}

/**
 * The bank a touch of the stick sideways let go now would hold, and for how long (rad, + right, at
 * most `ASSIST.tapBank`, and s; { bank: 0, time: 0 } once the touch is `ASSIST.tapTime` old, or
 * with none): see `ASSIST.tapTime`.
 */
export function heldBank(state: AssistState): { bank: number; time: number } {
  if (state.rollPeak === 0 || state.rollHeld >= ASSIST.tapTime) return { bank: 0, time: 0 };
  const bank = Math.sign(state.rollPeak) * Math.min(Math.abs(state.rollPeak) * ASSIST.maxBank, ASSIST.tapBank);
  return { bank, time: ASSIST.tapTime - state.rollHeld };
}

/** A new assist state: no integral, wings level asked for. */
export function createAssistState(): AssistState {
  return { integral: 0, bankTarget: 0, rollHeld: 0, rollPeak: 0, floorHold: false };
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
 * Refuses a `position` or `velocity` that is not 3 finite numbers (more are ignored), naming the
 * function `where` and the parameter.
 * @throws RangeError naming `where`, the parameter and its values.
 */
export function assertMotion(where: string, position: readonly number[], velocity: readonly number[]): void {
  for (const [name, v] of [
    ['position', position],
    ['velocity', velocity],
  ] as const)
    if (v.length < 3 || !v.slice(0, 3).every(Number.isFinite))
      throw new RangeError(`${where}: ${name} must be 3 finite numbers, got ${v.join(', ')}`);
}

/**
 * The ground floor the assist keeps the aircraft above (`floorPath`): a held dive goes down as far as
 * `height` m above the ground (or the sea) and levels there, easing out of the dive over about `time`
 * s, so a dive key held near the ground with the assist on never flies the aircraft into it.
 */
export const GROUND_FLOOR = Object.freeze({
  /** Height above the ground the floor lies at, m (under the 85 m to a ring's lowest edge: RING_CLEARANCE less its radius). */
  height: 60,
  /** Time constant of the approach to the floor, s: the path may fall no steeper than towards the floor `time` s ahead. */
  time: 2,
  /** How far ahead the ground is looked at, s of flight, and how often, s. */
  ahead: 4,
  every: 0.5,
});

/**
 * The least flight-path angle (rad, in (-pi/2, pi/2)) that keeps the aircraft at `position` (m,
 * world, y up) flying at `velocity` (m/s) above the floor GROUND_FLOOR.height over the ground
 * `ground(x, z)` (m): atan2(floor - y, v GROUND_FLOOR.time), the floor over the highest ground on
 * the track GROUND_FLOOR.ahead s ahead (level at this speed, looked at every GROUND_FLOOR.every s)
 * and v the horizontal speed (at least 1 m/s). The path falls to the floor no faster than over
 * `time` s, easing out as it nears it: far above the ground it is steep (no limit), at the floor
 * level, under it a climb; a hill ahead raises it before the aircraft is over it.
 * @throws RangeError on a position or velocity that is not 3 finite numbers.
 */
export function floorPath(position: readonly number[], velocity: readonly number[], ground: (x: number, z: number) => number): number {
  assertMotion('floorPath', position, velocity);
  const F = GROUND_FLOOR;
  const vx = velocity[0]!,
    vz = velocity[2]!;
  let highest = Number.NEGATIVE_INFINITY;
  for (let t = 0; t <= F.ahead + 1e-9; t += F.every) highest = Math.max(highest, ground(position[0]! + vx * t, position[2]! + vz * t));
  return Math.atan2(highest + F.height - position[1]!, Math.max(1, Math.hypot(vx, vz)) * F.time);
}

/**
 * One step of the assist: the control surfaces that fly the aircraft in `s` where the pilot's
 * `input` asks (see the header), over a step of `dt` s (> 0), no steeper down than the flight path
 * `floor` (rad; `floorPath`: the ground floor; default none). Updates `state` (its `floorHold` says
 * whether the floor holds the aircraft up against the stick).
 */
export function assist(s: FlightState, input: PilotInput, state: AssistState, dt: number, floor = -Math.PI / 2): ControlCommand {
  const A = ASSIST;
  // Bank: towards the stick's bank at a limited rate, the ailerons on the error and the roll rate.
  // A tap let go holds its bank until it is `tapTime` old (a tap turns a little); anything else
  // follows the stick.
  let roll = clamp(input.roll, -1, 1);
  if (roll !== 0) {
    // A new touch, or one turned the other way, starts afresh.
    if (state.rollHeld === 0 || Math.sign(roll) === -Math.sign(state.rollPeak)) state.rollPeak = 0;
    if (Math.abs(roll) >= Math.abs(state.rollPeak)) state.rollPeak = roll;
    state.rollHeld += dt;
  } else if (state.rollPeak !== 0 && state.rollHeld > 0 && state.rollHeld < A.tapTime) {
    roll = Math.sign(state.rollPeak) * Math.min(Math.abs(state.rollPeak), A.tapBank / A.maxBank);
    state.rollPeak = roll;
    state.rollHeld += dt;
  } else {
    state.rollHeld = 0;
    state.rollPeak = 0;
  }
  const wanted = steadyTurnBank(A.maxBank * roll, s.speed);
  // Eased off or let go: the bank asked for never lies beyond the bank the aircraft has (nor short
  // of the stick's), so the wings stop rolling into the turn at once and roll back from where they
  // are, and the turn stops soon after the release (a target still 20 degrees ahead of the bank
  // would roll the aircraft on into the turn for 0.3 s after the key is let go).
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
  // A dive's share fades out too as the path nears the ground floor's (`floorPath`).
  const stick = clamp(input.pitch, -1, 1);
  const floorFade = stick < 0 ? clamp((s.path - floor) / A.pathFade, 0, 1) : 1;
  const share = Math.abs(stick) * clamp((A.maxPath - Math.sign(stick) * s.path) / A.pathFade, 0, 1) * floorFade;
  // The path asked for: the stick's, raised to the floor's (no steeper than `maxPath` up).
  const asked = Math.max(A.maxClimb * stick, Math.min(floor, A.maxPath));
  state.floorHold = asked > A.maxClimb * stick || floorFade < 1;
  // Flight path: proportional, integral and pitch-rate damping. The integral finds the elevator the
  // trim needs (more in a bank, where the lift must also carry the turn) and winds no further than
  // full elevator. It rests while the stick has the elevator (no wind-up against a held climb) and
  // while the hold asks for full elevator the way the error pushes (no wind-up while it pulls out of
  // a steep climb or dive, which would carry the path past level for seconds after).
  const error = asked - s.path;
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
  const yaw = clamp(input.yaw, -1, 1);
  const coordinated = s.speed > 1 ? (9.81 * Math.sin(s.bank) * Math.cos(s.pitch)) / s.speed : 0;
  const damper = A.yawDamping * (1 - Math.abs(yaw)) * (s.yawRate - coordinated);
  const rudder = clamp(yaw + A.sideslipGain * s.sideslip + A.aileronRudder * aileron - damper, -1, 1);
  return { aileron, elevator, rudder };
}

/**
 * How fast the control surfaces move towards what they are asked, fraction of full deflection per
 * second: to the assist's command (20: the ailerons reverse in a tenth of a second when a bank key
 * is let go, so that a bank rolling in at 1.7 rad/s rolls on about 4 degrees; at 12 it rolled on
 * 5.6, at 6 further still), and (without the assist) to the stick's input.
 */
export const SURFACE_RATE = Object.freeze({ assist: 20, direct: 3 });

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
 * How the keyboard's climb / dive keys move their input (`rampKey`): a press asks at once for
 * `start`, then a held key's input grows as (start + from) e^(rise t) - from, faster and faster, the
 * way a keyboard-flown sim moves its control surface, so a tap asks for a correction and a held key
 * for full stick soon after. (Grown from nothing, the climb felt slow: the flight path was 2 degrees
 * up 0.52 s after the press, and a 0.1 s tap lifted it 0.2 degrees; now 0.37 s and 1.1 degrees:
 * scripts/flight-simulator-pitch.mjs.)
 */
export const KEY_RAMP: KeyRamp = Object.freeze({
  /**
   * Growth rate of a held key's input, 1/s: from `start` 0.25 with `from` 0.25 it is full after
   * ln 2.5 / 4 = 0.23 s of holding, 0.50 after a 0.1 s tap.
   */
  rise: 4,
  /** Where the growth starts from (added to the input's size), fraction of full stick. */
  from: 0.25,
  /** Rate a released key's input returns to 0, and a reversed one crosses 0, 1/s: neutral in 1/6 s (the climb held 1 s runs on 31 m after the release, under half a ring's radius). */
  fall: 6,
  /** Input a press starts at, fraction of full stick. */
  start: 0.25,
});

/** A key ramp (`rampKey`): growth rate `rise` 1/s from `from`, release rate `fall` 1/s, a press starting at `start` in [0, 1). */
export interface KeyRamp {
  readonly rise: number;
  readonly from: number;
  readonly fall: number;
  readonly start: number;
}

/**
 * How the bank keys move their input (`rampKey`): a press asks at once for `start` (0.2 of full
 * stick, a bank of 14 degrees, of which the assist holds it until the touch is `ASSIST.tapTime` old,
 * so a 150 ms tap turns the aircraft about half a degree), then the input grows about evenly (`from`
 * 0.2: its size plus 0.2 grows as e^t): 0.31 at 0.25 s, 0.46 at 0.5 s, 0.61 at 0.7 s, full after
 * ln 3 = 1.1 s. A held key turns the heading 4.1 degrees in its first second, 8.7 degrees/s at 1 s
 * (grown slowly at first, as e^(2 t) from 0.08, it turned 2.8, 5.5 degrees/s, and the ring hardly
 * moved for a second, then swung at 18 degrees/s by 2 s), and a 0.7 s hold about 2.5 degrees in all
 * (a press starting at 0.45 and full after 0.23 s would have the wings at 55 degrees by then and turn
 * 6 degrees, swinging a ring 5 degrees to one side past the other side); a turn held longer still
 * reaches the full bank. Released, neutral in 1/12 s, so that the wings start back to level at once
 * (in 0.25 s they would first roll on).
 */
export const BANK_KEY_RAMP: KeyRamp = Object.freeze({ rise: 1, from: 0.2, fall: 12, start: 0.2 });

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
 * `rate` per second would move it 3 % in a short tap, or not at all when the press and release come
 * in one frame); held past `hold` s it goes on at `rate` per second.
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

/**
 * Dead zone of the phone's stick (`stickResponse`), a share of its full travel: a finger resting near
 * the centre, or put down a little off it, asks for nothing (6 px of the 44 px travel), so the stick
 * is not twitchy (at 0.05, 2 px, it is).
 */
export const STICK_DEAD_ZONE = 0.14;
/** Exponent of the phone's stick response past the dead zone (`stickResponse`): above 1, gentle near the centre and full at the rim. */
export const STICK_EXPONENT = 2;
/**
 * Share of the stick's larger axis under which its other axis counts for nothing (`stickResponse`):
 * a push sideways that wanders a little up or down banks without climbing, and the other way round.
 */
export const STICK_AXIS_SNAP = 0.3;

/**
 * The phone stick's response: its deflection `x` (right), `y` (up), each in [-1, 1], turned into the
 * pilot's input. An axis under STICK_AXIS_SNAP of the other counts for nothing; the size d of what
 * is left (its length, at most 1) is mapped to ((d - STICK_DEAD_ZONE) / (1 - STICK_DEAD_ZONE)) ^
 * STICK_EXPONENT along the same direction: 0 inside the dead zone, a fifth of full at half travel (a
 * fine correction), full at the rim. Linear, half a push asked for half the bank (35 degrees) and
 * swung a ring off the phone's narrow view.
 * @throws RangeError on an `x` or `y` that is not finite.
 */
export function stickResponse(x: number, y: number): { x: number; y: number } {
  if (!Number.isFinite(x) || !Number.isFinite(y)) throw new RangeError(`stickResponse: x and y must be finite, got ${x}, ${y}`);
  const d = Math.min(1, Math.hypot(x, y));
  if (d <= STICK_DEAD_ZONE) return { x: 0, y: 0 };
  const sx = Math.abs(x) < STICK_AXIS_SNAP * Math.abs(y) ? 0 : x,
    sy = Math.abs(y) < STICK_AXIS_SNAP * Math.abs(x) ? 0 : y;
  const k = ((d - STICK_DEAD_ZONE) / (1 - STICK_DEAD_ZONE)) ** STICK_EXPONENT / Math.hypot(sx, sy);
  return { x: sx * k, y: sy * k };
}

/**
 * Time constants of the phone stick's smoothing (`smoothStick`), s: towards a larger input (a finger's
 * jitter and a jump where it lands are eased over `push`) and back towards 0 (`ease`, shorter, so
 * that letting go still levels the wings at once).
 */
export const STICK_SMOOTHING = Object.freeze({ push: 0.12, ease: 0.04 });

/**
 * One step of the phone stick's smoothing: `value` (the input the assist is given now, in [-1, 1])
 * moved over `dt` s (>= 0) towards `target` (the stick's response now, in [-1, 1]) by the share
 * 1 - e^(-dt / tau), tau STICK_SMOOTHING.push when `target` is farther from 0 the same way, else
 * STICK_SMOOTHING.ease; within 1e-3 of `target` it is `target` (a released stick reads 0 exactly).
 * @throws RangeError on a value or target outside [-1, 1], or a negative dt.
 */
export function smoothStick(value: number, target: number, dt: number): number {
  if (!(value >= -1 && value <= 1 && target >= -1 && target <= 1))
    throw new RangeError(`smoothStick: value and target must be in [-1, 1], got ${value}, ${target}`);
  if (!(dt >= 0)) throw new RangeError(`smoothStick: dt must be >= 0 s, got ${dt}`);
  const out = Math.abs(target) > Math.abs(value) && Math.sign(target) * Math.sign(value) >= 0;
  const next = value + (target - value) * (1 - Math.exp(-dt / (out ? STICK_SMOOTHING.push : STICK_SMOOTHING.ease)));
  return Math.abs(next - target) < 1e-3 ? target : next;
}
