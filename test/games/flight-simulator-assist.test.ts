/**
 * The flight simulator's flight assist (games/flight-simulator/assist.ts), headless: the aircraft
 * scene flown by the assist's control law as the game flies it (CONTROL_AUTHORITY, 25 degrees of
 * control authority, the ailerons AILERON_SCALE times that, the control surfaces set every 1/60 s step). A bank left alone rolls level, a
 * held key banks and turns briskly, full stick holds a 70 degree bank in a level turn at the rate a
 * coordinated turn has, full stick back climbs steeply without a stall or a loop, and a held climb or
 * dive changes height as fast as without the assist.
 */

import { createPhysicsWorld, type PhysicsWorld, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';
import { AIRCRAFT, AIRCRAFT_TRIM_SPEED, type AircraftHandles, aircraft, aircraftLevelDrag } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import {
  AILERON_SCALE,
  ASSIST,
  approach,
  assist,
  BANK_KEY_RAMP,
  CONTROL_AUTHORITY,
  createAssistState,
  type FlightState,
  flightState,
  floorPath,
  GROUND_FLOOR,
  heldBank,
  KEY_RAMP,
  type PilotInput,
  rampKey,
  STICK_AXIS_SNAP,
  STICK_DEAD_ZONE,
  STICK_SMOOTHING,
  SURFACE_RATE,
  smoothStick,
  steadyTurnBank,
  stickResponse,
  throttleStep,
} from '../../games/flight-simulator/assist';
import { pathThroughRing, predictThroughRing, RING_RADIUS, type Ring } from '../../games/flight-simulator/course';
import { FRAME_CAP } from '../../games/flight-simulator/pacing';

const DEG = Math.PI / 180;
const FULL = CONTROL_AUTHORITY * DEG;

interface Flight {
  world: PhysicsWorld;
  h: AircraftHandles;
  state: ReturnType<typeof createAssistState>;
}

/** The aircraft level at 900 m and its trim speed, banked `bank` rad to the right. */
function start(bank = 0): Flight {
  const world = createPhysicsWorld(aircraft.worldOptions());
  const h = aircraft.build(world, { altitude: 900 });
  world.components.Orientation.x[h.body] = Math.sin(bank / 2);
  world.components.Orientation.w[h.body] = Math.cos(bank / 2);
  return { world, h, state: createAssistState() };
}

/**
 * Flies `seconds` with `input` through the assist; the throttle is `throttle` (a fraction; the
 * trim's by default). `each` sees the state after every step.
 */
function fly(
  f: Flight,
  input: Partial<PilotInput>,
  seconds: number,
  opts: { throttle?: number } = {},
  each?: (s: FlightState, t: number) => void,
): void {
  const pilot = { roll: 0, pitch: 0, yaw: 0, ...input };
  const n = Math.round(seconds / f.world.dt);
  for (let i = 1; i <= n; i++) {
    const s = flightState(f.world, f.h.body);
    const c = assist(s, pilot, f.state, f.world.dt);
    setControlDeflection(f.world, f.h.surfaces.tail, -c.elevator * FULL);
    setControlDeflection(f.world, f.h.surfaces.leftWing, c.aileron * FULL * AILERON_SCALE);
    setControlDeflection(f.world, f.h.surfaces.rightWing, -c.aileron * FULL * AILERON_SCALE);
    setControlDeflection(f.world, f.h.surfaces.fin, -c.rudder * FULL);
    const throttle = opts.throttle ?? aircraftLevelDrag(AIRCRAFT_TRIM_SPEED) / AIRCRAFT.maxThrust;
    setBodyThrust(f.world, f.h.body, [throttle * AIRCRAFT.maxThrust, 0, 0]);
    step(f.world);
    each?.(flightState(f.world, f.h.body), i * f.world.dt);
  }
}

const height = (f: Flight): number => f.world.components.Position.y[f.h.body]!;

describe('flight assist', () => {
  it('reads the state: level at trim, the wing at its incidence, a bank as set', () => {
    const s = flightState(start(30 * DEG).world, 1);
    expect(s.bank).toBeCloseTo(30 * DEG, 12);
    expect(s.pitch).toBeCloseTo(0, 12);
    expect(s.alpha).toBeCloseTo(AIRCRAFT.incidence, 12); // body level, air along the body x axis
    expect(s.speed).toBeCloseTo(AIRCRAFT_TRIM_SPEED, 9);
  });

  it('let go in a 40 degree bank: the wings roll level within 3 s, the height kept within 5 m', () => {
    const f = start(40 * DEG);
    let lowest = 0;
    fly(f, {}, 3, {}, (s) => {
      lowest = Math.min(lowest, s.bank);
    });
    const s = flightState(f.world, f.h.body);
    expect(Math.abs(s.bank)).toBeLessThan(3 * DEG);
    expect(lowest).toBeGreaterThan(-5 * DEG); // no swing through to the other side
    expect(Math.abs(height(f) - 900)).toBeLessThan(5);
  });

  it('a held key banks briskly: 30 degrees within 1 s, 40 within 2 s, the heading 9 degrees round within 3 s', () => {
    // Players found the aircraft floaty with 15 degrees of authority and the key ramped to full over
    // 1.25 s (1.4 s to 30 degrees, 10 degrees of heading in 3 s); then hard to aim with a 70 degree
    // full bank (a held key overshot every ring: scripts/flight-simulator-pilots.mjs, the keys pilot).
    // Measured with the bank gain 2.5: 0.92 s, 1.63 s, 10.9 degrees; with 6, about 0.8 s to 30 degrees.
    const f = start();
    const h0 = flightState(f.world, f.h.body).heading;
    let key = 0,
      t30 = Infinity,
      t40 = Infinity;
    for (let i = 1; i <= 180; i++) {
      key = rampKey(key, 1, 1 / 60);
      fly(f, { roll: key }, 1 / 60);
      const bank = flightState(f.world, f.h.body).bank;
      if (bank > 30 * DEG) t30 = Math.min(t30, i / 60);
      if (bank > 40 * DEG) t40 = Math.min(t40, i / 60);
    }
    expect(t30).toBeLessThan(1);
    expect(t40).toBeLessThan(2);
    expect(flightState(f.world, f.h.body).heading - h0).toBeGreaterThan(9 * DEG);
  });

  it('full stick right: the full bank (ASSIST.maxBank, 70 degrees) within 4 s and a level turn at the rate g tan(bank) / V', () => {
    const f = start();
    fly(f, { roll: 1 }, 4);
    expect(Math.abs(flightState(f.world, f.h.body).bank - ASSIST.maxBank)).toBeLessThan(3 * DEG);
    // Held 6 s more: the heading swings at the rate of a level coordinated turn, omega = g tan(bank) / V
    // (the lift's horizontal part m g tan(bank) pulls the path round at V omega). 10 % for the
    // bank and speed still settling and the small sideslip.
    const h0 = flightState(f.world, f.h.body).heading,
      y0 = height(f);
    let rate = 0,
      count = 0;
    fly(f, { roll: 1 }, 6, {}, (s) => {
      rate += (9.81 * Math.tan(s.bank)) / s.speed;
      count++;
    });
    const turned = flightState(f.world, f.h.body).heading - h0;
    expect(turned / 6 / (rate / count)).toBeGreaterThan(0.9);
    expect(turned / 6 / (rate / count)).toBeLessThan(1.1);
    // The assist pulls for the turn: at 1.4 g it loses a little height.
    expect(Math.abs(height(f) - y0)).toBeLessThan(35);
  });

  /**
   * Flies from level at the trim speed with the game's starting throttle (130 m/s's) with the bank key (BANK_KEY_RAMP) held while
   * `held(t, turned)` says so, for `seconds`; returns the heading turned, degrees, at each step.
   */
  function bankKey(held: (t: number, turned: number) => boolean, seconds: number): number[] {
    const f = start();
    const e = f.h.body;
    const throttle = aircraftLevelDrag(130) / AIRCRAFT.maxThrust;
    const h0 = flightState(f.world, e).heading;
    let key = 0,
      turned = 0,
      last = h0;
    const out: number[] = [];
    for (let i = 0; i < Math.round(seconds * 60); i++) {
      key = rampKey(key, held(i / 60, turned) ? 1 : 0, 1 / 60, BANK_KEY_RAMP);
      fly(f, { roll: key }, 1 / 60, { throttle });
      const h = flightState(f.world, e).heading;
      turned += (((h - last + 3 * Math.PI) % (2 * Math.PI)) - Math.PI) / DEG;
      last = h;
      out.push(turned);
    }
    return out;
  }

  it('steering: a held key turns half round within 15 s; a 150 ms tap turns under 2 degrees; let go at a heading, the turn runs on under 4 degrees', () => {
    // Strangers took 35 s for a half turn with the 45 degree full bank (measured 38 s from 130 m/s):
    // now 14.1 s (the bank keys grow over 1.1 s to full stick, so a short hold is a small turn). A tap is a small correction (measured 0.8 degrees); it held its bank for 1.1 s and
    // turned 3 degrees, and strangers found the aircraft stayed banked after the key was let go.
    const half = bankKey((_, turned) => turned < 180, 20).findIndex((x) => x >= 180);
    expect(half).toBeGreaterThan(0);
    expect(half / 60).toBeLessThan(15);
    const tap = bankKey((t) => t < 0.15, 8);
    expect(tap[tap.length - 1]).toBeGreaterThan(0.3);
    expect(tap[tap.length - 1]).toBeLessThan(2);
    for (const target of [30, 90]) {
      let released = false;
      const run = bankKey((_, turned) => !(released ||= turned >= target), 25);
      expect(Math.abs(run[run.length - 1]! - target), `${target}`).toBeLessThan(4);
    }
  });

  it('let go after a turn, the nose settles on its heading: from 1 s after the release it swings under 2 degrees over 3 s (the yaw damper)', () => {
    // Without ASSIST.yawDamping the nose swung back and forth 4.2 to 4.7 degrees about its new heading
    // over the next 3 s once the wings were level (the compass and the cockpit view with it); with it,
    // measured 0.9 and 1.4.
    for (const target of [45, 90]) {
      let released = -1;
      const run = bankKey((t, turned) => {
        if (released < 0 && turned >= target) released = t;
        return released < 0;
      }, 12);
      const from = Math.round((released + 1) * 60);
      const late = run.slice(from, from + 180);
      const swing = Math.max(...late) - Math.min(...late);
      expect(swing, `${target}`).toBeLessThan(2);
    }
  });

  it('a held bank key steers gently: 0.7 s of ← turns the heading 0.8 to 3 degrees in all, 1.2 s at least twice that', () => {
    // A stranger held ← 0.7 s for ring 2 (5 degrees off to the left) and it swung off the view's
    // right: the keys started at 0.45 of full stick and were full after 0.23 s, so the wings reached
    // 55 degrees and the hold turned 5.5 degrees (scripts/flight-simulator-steering.mjs). Measured
    // now 1.6 degrees for 0.7 s and 5.2 for 1.2 s; the floor keeps a short hold a visible correction.
    const turnedBy = (hold: number) => bankKey((t) => t < hold, hold + 1.5).at(-1)!;
    const short = turnedBy(0.7);
    expect(short).toBeGreaterThan(0.8);
    expect(short).toBeLessThan(3);
    expect(turnedBy(1.2)).toBeGreaterThan(2 * short);
  });

  it('a held bank key answers in its first second: the heading turns 3.5 degrees or more in 1 s, and not a slow start then a whip', () => {
    // A stranger found the keys slow: held, the ring hardly moved for a second (2.8 degrees turned in
    // 1 s, 5.5 degrees/s at 1 s), then swung (18 degrees/s at 2 s, 0.30 of it at 1 s). The ramp now
    // grows more evenly from the same press (BANK_KEY_RAMP): measured 4.1 degrees in 1 s, 8.7
    // degrees/s at 1 s, 0.51 of the rate at 2 s, while 0.7 s still turns under 3 (the test above).
    const held = bankKey(() => true, 2.2);
    const rate = (t: number) => (held[Math.round(t * 60)]! - held[Math.round(t * 60) - 6]!) * 10;
    expect(held[59]!).toBeGreaterThan(3.5);
    expect(rate(1) / rate(2)).toBeGreaterThan(0.45);
  });

  it('let go, the wings roll level at once: 1 s after a release of the bank key (0.15 to 2 s held) the bank is under 3 degrees; the heading turned grows with the hold', () => {
    // A tap held its bank until it was 1.1 s old and a touch up to 0.9 s held part of it: a 150 ms
    // tap was still 28 degrees banked 1 s after the release, a 0.5 s hold 38 degrees 0.5 s after
    // (scripts/flight-simulator-steering.mjs). Measured now: 0.1, 0.4, 0.8 and 1.1 degrees.
    const lengths = [0.15, 0.25, 0.5, 1, 2];
    const turned: number[] = [];
    for (const hold of lengths) {
      const f = start();
      const throttle = aircraftLevelDrag(130) / AIRCRAFT.maxThrust;
      const h0 = flightState(f.world, f.h.body).heading;
      let key = 0;
      const n = Math.round((hold + 1) * 60);
      for (let i = 0; i < n; i++) {
        key = rampKey(key, i < hold * 60 ? 1 : 0, 1 / 60, BANK_KEY_RAMP);
        fly(f, { roll: key }, 1 / 60, { throttle });
      }
      const s = flightState(f.world, f.h.body);
      expect(Math.abs(s.bank), `${hold} s`).toBeLessThan(3 * DEG);
      turned.push((s.heading - h0) / DEG);
    }
    const said = turned.map((x, i) => `${lengths[i]} s: ${x.toFixed(1)}`).join(', ');
    for (let i = 1; i < turned.length; i++) expect(turned[i]!, said).toBeGreaterThan(turned[i - 1]!);
  });

  it('a tap let go holds its bank (at most tapBank) until it is tapTime old; a touch let go later, or eased off, holds nothing', () => {
    const s: FlightState = {
      speed: 110,
      bank: 0,
      pitch: 0,
      path: 0,
      heading: 0,
      alpha: 0,
      sideslip: 0,
      rollRate: 0,
      pitchRate: 0,
      yawRate: 0,
    };
    /** The assist's state after stick `roll` for `held` s, then `then` for `after` s (steps of 1/60 s). */
    const touch = (roll: number, held: number, then: number, after: number) => {
      const state = createAssistState();
      for (let i = 0; i < Math.round(held * 60); i++) assist(s, { roll, pitch: 0, yaw: 0 }, state, 1 / 60);
      for (let i = 0; i < Math.round(after * 60); i++) assist(s, { roll: then, pitch: 0, yaw: 0 }, state, 1 / 60);
      return { held: heldBank(state), target: state.bankTarget };
    };
    // A 0.1 s tap of full stick: the bank held is tapBank, for the rest of tapTime from the touch.
    const tap = touch(1, 0.1, 0, 0.1);
    expect(tap.held.bank).toBeCloseTo(ASSIST.tapBank, 12);
    expect(tap.held.time).toBeCloseTo(ASSIST.tapTime - 0.2, 6);
    // A small tap holds its own bank, less than tapBank.
    expect(touch(0.2, 0.1, 0, 0.05).held.bank).toBeCloseTo(0.2 * ASSIST.maxBank, 12);
    // Once tapTime old, nothing is held and the bank asked for unwinds.
    expect(touch(1, 0.1, 0, ASSIST.tapTime).held).toEqual({ bank: 0, time: 0 });
    // Let go after tapTime: nothing held, the bank asked for falls at bankRate at once.
    const late = touch(1, ASSIST.tapTime + 0.1, 0, 1 / 60);
    expect(late.held).toEqual({ bank: 0, time: 0 });
    // Eased off to half: the stick's half bank is asked for, not the peak (within one step's bankRate),
    // as the bank that turns at its rate at 110 m/s (steadyTurnBank: tan scales with the speed over the trim's).
    const eased = touch(1, 2, 0.5, 1);
    expect(eased.target).toBeCloseTo(Math.atan((Math.tan(0.5 * ASSIST.maxBank) * 110) / AIRCRAFT_TRIM_SPEED), 12);
    expect(eased.held).toEqual({ bank: 0, time: 0 });
  });

  it('a held bank turns at a steady rate: full and half stick held 30 s turn within 10 % of g tan(stick bank) / trim speed in every 2 s from 6 s on', () => {
    // With the stick's bank itself, the full bank's turn sped up from 13.5 to 15.7 degrees a second
    // as the turn bled the speed from 113 to 94 m/s (a level turn's rate is g tan(bank) / V); the
    // assist now banks less as the speed falls (steadyTurnBank). Measured: full stick 12.5 to 13.6
    // degrees a second against 13.6, half stick 3.4 against 3.5.
    for (const roll of [1, 0.5]) {
      const f = start();
      const throttle = aircraftLevelDrag(130) / AIRCRAFT.maxThrust;
      const aimed = (9.81 * Math.tan(roll * ASSIST.maxBank)) / AIRCRAFT_TRIM_SPEED;
      fly(f, { roll }, 6, { throttle });
      let last = flightState(f.world, f.h.body).heading;
      for (let k = 0; k < 12; k++) {
        fly(f, { roll }, 2, { throttle });
        const h = flightState(f.world, f.h.body).heading;
        const rate = (((h - last + 3 * Math.PI) % (2 * Math.PI)) - Math.PI) / 2;
        last = h;
        expect(Math.abs(rate / aimed - 1), `stick ${roll}, ${6 + 2 * k} to ${8 + 2 * k} s: ${rate / DEG} deg/s`).toBeLessThan(0.1);
      }
    }
    // Faster than the trim speed the bank steepens to keep the rate, up to steepestBank; at the trim speed it is the stick's.
    expect(steadyTurnBank(0.5 * ASSIST.maxBank, AIRCRAFT_TRIM_SPEED)).toBeCloseTo(0.5 * ASSIST.maxBank, 12);
    expect(steadyTurnBank(-ASSIST.maxBank, 2 * AIRCRAFT_TRIM_SPEED)).toBeCloseTo(-ASSIST.steepestBank, 12);
    expect(() => steadyTurnBank(0.1, -1)).toThrow(/steadyTurnBank: speed/);
  });

  it('the phone stick is progressive: nothing in the dead zone, gentle near the centre, full at the rim, its direction kept, a wander off its axis dropped', () => {
    expect(stickResponse(STICK_DEAD_ZONE - 0.01, 0)).toEqual({ x: 0, y: 0 });
    expect(stickResponse(0, 0)).toEqual({ x: 0, y: 0 });
    const at = (d: number) => stickResponse(d, 0).x;
    expect(at(1)).toBeCloseTo(1, 12);
    // Half a push asks for a fifth of full (linear: half; the stranger found 0.3 twitchy), a fifth
    // of a push for about a hundredth.
    expect(at(0.5)).toBeLessThan(0.22);
    expect(at(0.5)).toBeGreaterThan(0.12);
    expect(at(0.2)).toBeLessThan(0.01);
    expect(at(0.2)).toBeGreaterThan(0);
    // Growing with the push, never falling.
    for (let d = STICK_DEAD_ZONE + 0.01; d < 1; d += 0.02) expect(at(d + 0.02)).toBeGreaterThan(at(d));
    // Diagonal: the direction is kept, and beyond the rim it is full.
    const diag = stickResponse(0.6, -0.6);
    expect(diag.x).toBeCloseTo(-diag.y, 12);
    expect(Math.hypot(stickResponse(1, 1).x, stickResponse(1, 1).y)).toBeCloseTo(1, 12);
    // Pushed sideways with a wander up under STICK_AXIS_SNAP of it: a bank alone, the push's full size.
    const wander = stickResponse(0.8, 0.8 * STICK_AXIS_SNAP * 0.9);
    expect(wander.y).toBe(0);
    expect(wander.x).toBeCloseTo(stickResponse(Math.hypot(0.8, 0.8 * STICK_AXIS_SNAP * 0.9), 0).x, 12);
    expect(() => stickResponse(Number.NaN, 0)).toThrow(/stickResponse: x and y must be finite/);
  });

  it('the phone stick is smoothed: a jump to full eases in over STICK_SMOOTHING.push, a release falls back over the shorter ease, to 0 exactly', () => {
    /** The smoothed input after `seconds` at 60 steps a second towards `target` from `value`. */
    const run = (value: number, target: number, seconds: number): number => {
      for (let i = 0; i < Math.round(seconds * 60); i++) value = smoothStick(value, target, 1 / 60);
      return value;
    };
    // The closed form 1 - e^(-t / tau), to the 1e-3 snap.
    expect(run(0, 1, 0.1)).toBeCloseTo(1 - Math.exp(-0.1 / STICK_SMOOTHING.push), 9);
    expect(run(0, -1, 0.1)).toBeCloseTo(-(1 - Math.exp(-0.1 / STICK_SMOOTHING.push)), 9);
    expect(run(1, 0, 0.05)).toBeCloseTo(Math.exp(-0.05 / STICK_SMOOTHING.ease), 9);
    // Released: at 0 exactly within a third of a second; a reversal falls at the shorter ease first.
    expect(run(1, 0, 0.35)).toBe(0);
    expect(run(0.8, -0.8, 1 / 60)).toBeCloseTo(0.8 - 1.6 * (1 - Math.exp(-1 / 60 / STICK_SMOOTHING.ease)), 9);
    expect(() => smoothStick(2, 0, 0.1)).toThrow(/smoothStick: value and target must be in \[-1, 1\], got 2, 0/);
    expect(() => smoothStick(0, 0, -1)).toThrow(/smoothStick: dt must be >= 0 s, got -1/);
  });

  it('full stick back: climbs past 17 degrees within 3 s, never past the 45 degree path (no loop); at idle it slows but does not stall', () => {
    const f = start();
    fly(f, { pitch: 1 }, 3);
    expect(flightState(f.world, f.h.body).path).toBeGreaterThan(17 * DEG);
    let steepest = 0;
    fly(f, { pitch: 1 }, 9, {}, (s) => {
      steepest = Math.max(steepest, s.path);
    });
    expect(steepest).toBeGreaterThan(30 * DEG);
    expect(steepest).toBeLessThan(ASSIST.maxPath);
    // Held for 25 s with the engine at idle: the climb bleeds the speed away; the wing's angle of
    // attack stays under the stall angle (20 degrees) all the while.
    const idle = start();
    let alpha = 0;
    fly(idle, { pitch: 1 }, 25, { throttle: 0 }, (s) => {
      alpha = Math.max(alpha, s.alpha);
    });
    expect(flightState(idle.world, idle.h.body).speed).toBeLessThan(90);
    expect(alpha).toBeLessThan(AIRCRAFT.stallAngle);
  });
});

describe('held climb and dive: the assist does not fight them', () => {
  /**
   * Height gained in `seconds` with the climb key (dir 1) or dive key (-1) held from level flight at
   * the trim speed, flown as the page flies it: the key ramped (rampKey), the surfaces moved towards
   * the assist's command or, without the assist, the stick's input at SURFACE_RATE.
   */
  function heldKey(withAssist: boolean, dir: 1 | -1, seconds: number): number {
    const f = start();
    const dt = f.world.dt;
    const throttle = aircraftLevelDrag(AIRCRAFT_TRIM_SPEED) / AIRCRAFT.maxThrust;
    let key = 0,
      elevator = 0,
      aileron = 0,
      rudder = 0;
    for (let i = 0; i < Math.round(seconds / dt); i++) {
      key = rampKey(key, dir, dt);
      const pilot = { roll: 0, pitch: key, yaw: 0 };
      const c = withAssist ? assist(flightState(f.world, f.h.body), pilot, f.state, dt) : { elevator: key, aileron: 0, rudder: 0 };
      const rate = withAssist ? SURFACE_RATE.assist : SURFACE_RATE.direct;
      elevator = approach(elevator, c.elevator, rate, dt);
      aileron = approach(aileron, c.aileron, rate, dt);
      rudder = approach(rudder, c.rudder, rate, dt);
      setControlDeflection(f.world, f.h.surfaces.tail, -elevator * FULL);
      setControlDeflection(f.world, f.h.surfaces.leftWing, aileron * FULL * AILERON_SCALE);
      setControlDeflection(f.world, f.h.surfaces.rightWing, -aileron * FULL * AILERON_SCALE);
      setControlDeflection(f.world, f.h.surfaces.fin, -rudder * FULL);
      setBodyThrust(f.world, f.h.body, [throttle * AIRCRAFT.maxThrust, 0, 0]);
      step(f.world);
    }
    return height(f) - 900;
  }

  it('held 5 s, the climb key gains 180 m (the dive key loses 230 m), at least 80 % of what the bare stick does', () => {
    // The issue this answers: the levelling assist slowed height changes (it asked for a 20 degree
    // path at most: 115 m in 5 s against 140 m without it, 0.83, with 15 degrees of authority). With
    // 25 degrees the bare elevator pitches on past the assist's 45 degree path limit (no loop):
    // measured 212 m against 234 m climbing, 265 m against 312 m diving.
    for (const dir of [1, -1] as const) {
      const on = dir * heldKey(true, dir, 5),
        off = dir * heldKey(false, dir, 5);
      expect(off, `dir ${dir}`).toBeGreaterThan(100);
      expect(on, `dir ${dir}`).toBeGreaterThan(dir > 0 ? 180 : 230);
      expect(on / off, `dir ${dir}: ${on.toFixed(0)} m against ${off.toFixed(0)} m`).toBeGreaterThan(0.8);
    }
  });
});

describe('keyboard ramp (rampKey)', () => {
  /** The key's input after holding `direction` for `seconds` from `value`, in 1/60 s steps. */
  const hold = (value: number, direction: number, seconds: number): number => {
    for (let i = 0; i < Math.round(seconds * 60); i++) value = rampKey(value, direction, 1 / 60);
    return value;
  };

  it('a press asks at once for a quarter of full stick, a held key grows faster to full stick in 0.23 s; released, it is back to 0 in 1/6 s', () => {
    // The held input against its closed form (start + from) e^(rise t) - from, stepped at 60 Hz (exact per step).
    const grown = (t: number) => (KEY_RAMP.start + KEY_RAMP.from) * Math.exp(KEY_RAMP.rise * t) - KEY_RAMP.from;
    expect(hold(0, 1, 0.1)).toBeCloseTo(grown(0.1), 12);
    expect(hold(0, 1, 0.2)).toBeCloseTo(grown(0.2), 12);
    // At once: the first step already asks for a quarter of full stick (the climb felt slow when it
    // started from nothing: a 0.1 s tap was 0.12 of full stick and lifted the path 0.2 degrees).
    expect(hold(0, 1, 1 / 60)).toBeGreaterThan(0.25);
    // Then faster: the second tenth of a second adds more than the first's growth past the start.
    expect(hold(0, 1, 0.2) - hold(0, 1, 0.1)).toBeGreaterThan(hold(0, 1, 0.1) - KEY_RAMP.start);
    const full = Math.log((1 + KEY_RAMP.from) / (KEY_RAMP.start + KEY_RAMP.from)) / KEY_RAMP.rise;
    expect(full).toBeCloseTo(0.229, 3);
    expect(hold(0, -1, full - 0.05)).toBeGreaterThan(-1);
    expect(hold(0, -1, full + 0.02)).toBe(-1);
    expect(hold(1, 0, 1 / KEY_RAMP.fall - 1 / 60)).toBeGreaterThan(0);
    expect(hold(1, 0, 1 / KEY_RAMP.fall + 1 / 60)).toBe(0);
    // Reversed: through 0 at the return rate, then on the other way within the same step, from the start.
    expect(rampKey(0.05, -1, 0.02)).toBeCloseTo(-grown(0.02 - 0.05 / KEY_RAMP.fall), 12);
    expect(rampKey(0.3, 0, 0)).toBe(0.3);
  });

  it('flown: ↑ held lifts the flight path 5 degrees within 0.65 s (0.70 s when the ramp started from nothing), and let go it flies level again', () => {
    // scripts/flight-simulator-pitch.mjs measures 0.55 s (the surfaces there follow at SURFACE_RATE.assist).
    const f = start();
    fly(f, {}, 1);
    let key = 0,
      t5 = Infinity,
      top = -Infinity;
    const n = Math.round(6 * 60);
    for (let i = 1; i <= n; i++) {
      key = rampKey(key, i <= 60 ? 1 : 0, 1 / 60);
      fly(f, { pitch: key }, 1 / 60);
      const path = flightState(f.world, f.h.body).path;
      if (path > 5 * DEG) t5 = Math.min(t5, i / 60);
      top = Math.max(top, path);
    }
    expect(t5).toBeLessThan(0.65);
    // Stable: no zoom past 25 degrees, and level within 3 degrees 5 s after the release.
    expect(top).toBeLessThan(25 * DEG);
    expect(Math.abs(flightState(f.world, f.h.body).path)).toBeLessThan(3 * DEG);
  });

  it('bad input is refused with the function and parameter named', () => {
    expect(() => rampKey(2, 0, 0.1)).toThrow(/rampKey: value must be in \[-1, 1\], got 2/);
    expect(() => rampKey(0, 0.5, 0.1)).toThrow(/rampKey: direction must be -1, 0 or 1, got 0.5/);
    expect(() => rampKey(0, 1, -1)).toThrow(/rampKey: dt must be >= 0 s, got -1/);
  });

  it('flown: climb held 1 s then let go climbs on by half a ring at most (measured 31 m; the radius is 65 m)', () => {
    /** Climbs with up held for `seconds`, then lets go: metres gained after the release (to the top). */
    const climbAfterRelease = (seconds: number, ramped: boolean): number => {
      const f = start();
      let key = 0,
        atRelease = 900,
        top = 900;
      const n = Math.round(12 * 60);
      for (let i = 0; i < n; i++) {
        const held = i < seconds * 60 ? 1 : 0;
        key = ramped ? rampKey(key, held, 1 / 60) : held;
        fly(f, { pitch: key }, 1 / 60);
        if (held) atRelease = height(f);
        top = Math.max(top, height(f));
      }
      return top - atRelease;
    };
    const ramped = climbAfterRelease(1, true),
      instant = climbAfterRelease(1, false);
    // Under half a ring's radius; the ramp's release (neutral in 1/6 s) adds at most 3 m to an
    // instant key's run-on (measured 30.7 m against 29.1 m).
    expect(ramped).toBeLessThan(0.5 * RING_RADIUS);
    expect(ramped).toBeLessThan(instant + 3);
    // A 0.1 s tap is a small correction: a few metres at most.
    const tap = climbAfterRelease(0.1, true);
    expect(tap).toBeGreaterThan(0.1);
    expect(tap).toBeLessThan(4);
  });
});

describe('the flight-path marker (course.ts predictThroughRing) against the flown path', () => {
  /**
   * Flies as the game does (keys ramped, the surfaces following the assist at SURFACE_RATE.assist)
   * with `roll` and `pitch` keys held for `hold` s, then let go. At the release a ring plane is put
   * `distance` m ahead across the path; returns how far from the point the aircraft then crosses it
   * the marker's prediction and a straight line from the velocity were, m, and how far the heading
   * ran on after the release, rad.
   */
  function release(roll: number, pitch: number, hold: number, distance: number): { predicted: number; straight: number; runOn: number } {
    const f = start();
    const c = f.world.components,
      e = f.h.body;
    const surface = { aileron: 0, elevator: 0, rudder: 0 };
    const keys = { roll: 0, pitch: 0 };
    let ring: Ring | null = null,
      guess: [number, number, number] = [0, 0, 0],
      line: [number, number, number] = [0, 0, 0],
      crossed: number[] | null = null,
      headingAtRelease = 0;
    const dt = f.world.dt;
    for (let i = 0; i < 20 * 60 && !crossed; i++) {
      const on = i < Math.round(hold * 60);
      keys.roll = rampKey(keys.roll, on ? roll : 0, dt, BANK_KEY_RAMP);
      keys.pitch = rampKey(keys.pitch, on ? pitch : 0, dt);
      const s = flightState(f.world, e);
      const cmd = assist(s, { roll: keys.roll, pitch: keys.pitch, yaw: 0 }, f.state, dt);
      for (const k of ['aileron', 'elevator', 'rudder'] as const) surface[k] = approach(surface[k], cmd[k], SURFACE_RATE.assist, dt);
      setControlDeflection(f.world, f.h.surfaces.tail, -surface.elevator * FULL);
      setControlDeflection(f.world, f.h.surfaces.leftWing, surface.aileron * FULL * AILERON_SCALE);
      setControlDeflection(f.world, f.h.surfaces.rightWing, -surface.aileron * FULL * AILERON_SCALE);
      setControlDeflection(f.world, f.h.surfaces.fin, -surface.rudder * FULL);
      setBodyThrust(f.world, e, [(aircraftLevelDrag(130) / AIRCRAFT.maxThrust) * AIRCRAFT.maxThrust, 0, 0]);
      const a = [c.Position.x[e]!, c.Position.y[e]!, c.Position.z[e]!];
      step(f.world);
      const after = flightState(f.world, e);
      const b = [c.Position.x[e]!, c.Position.y[e]!, c.Position.z[e]!];
      const v = [c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!];
      if (!ring && i + 1 === Math.round(hold * 60)) {
        const across = Math.hypot(v[0]!, v[2]!);
        const nx = v[0]! / across,
          nz = v[2]! / across;
        ring = { x: b[0]! + distance * nx, y: b[1]!, z: b[2]! + distance * nz, nx, ny: 0, nz, status: 'ahead' };
        guess = predictThroughRing(
          ring,
          {
            position: b,
            velocity: v,
            bank: after.bank,
            rollRate: after.rollRate,
            pathRate: (after.path - s.path) / dt,
            held: heldBank(f.state),
          },
          true,
        ).point;
        line = pathThroughRing(ring, b, v).point;
        headingAtRelease = after.heading;
      } else if (ring) {
        const da = (a[0]! - ring.x) * ring.nx + (a[2]! - ring.z) * ring.nz,
          db = (b[0]! - ring.x) * ring.nx + (b[2]! - ring.z) * ring.nz;
        if (da < 0 && db >= 0) crossed = a.map((x, k) => x + (da / (da - db)) * (b[k]! - x));
      }
    }
    if (!crossed) throw new Error('the plane was not crossed');
    const gap = (p: readonly number[]) => Math.hypot(p[0]! - crossed![0]!, p[1]! - crossed![1]!, p[2]! - crossed![2]!);
    return { predicted: gap(guess), straight: gap(line), runOn: flightState(f.world, f.h.body).heading - headingAtRelease };
  }

  it('a turn let go: the marker is within 16 m of where the aircraft crosses a ring 300 to 1,000 m on (measured 11.0 at most); the straight line missed by up to 160 m', () => {
    // With the 45 degree full bank it was within 5 m (measured under 3); the turn is three times as
    // fast now and a key let go within ASSIST.tapTime holds its bank a moment (heldBank). Since the
    // wings roll back to level at once on the release (the turn stops within a degree of where it was
    // let go), LET_GO's roll-out model is fitted less closely: the worst case (let go after 0.8 s or
    // 1.5 s, 1,000 m on) is 15 m, under a quarter of the ring's radius (it was 6 m with the slower
    // roll-out, which ran the turn on 2 to 3 degrees past the release). With the ailerons at 45
    // degrees, reversing in a tenth of a second, and no bank held after a touch past
    // ASSIST.tapTime (LET_GO refitted), the worst is a 1.5 s hold seen 1,000 m on: 11 m.
    let worst = 0,
      worstLine = 0;
    for (const hold of [0.3, 0.8, 1.5, 3])
      for (const distance of [300, 600, 1000]) {
        const r = release(1, 0, hold, distance);
        worst = Math.max(worst, r.predicted);
        worstLine = Math.max(worstLine, r.straight);
      }
    expect(worst).toBeLessThan(16);
    // The straight line (the marker before) was off by most of a ring's radius: the test can tell them apart.
    expect(worstLine).toBeGreaterThan(0.6 * RING_RADIUS);
  });

  it('a climb, a dive or a climbing turn let go: the marker within half the ring radius at 300 and 600 m (measured 27 m at most)', () => {
    // Within a third (measured 11 m) with the 45 degree full bank; the climbing turn into a 70 degree
    // bank pulls round faster than the marker's level-turn rate g tan(bank) / V has it.
    let worst = 0;
    for (const [roll, pitch] of [
      [0, 1],
      [0, -1],
      [1, 1],
    ] as const)
      for (const hold of [0.3, 0.8, 1.5])
        for (const distance of [300, 600]) worst = Math.max(worst, release(roll, pitch, hold, distance).predicted);
    expect(worst).toBeLessThan(RING_RADIUS / 2);
  });

  it('predictThroughRing: a ring behind is never met; bad input is refused with the function and parameter named', () => {
    const ring: Ring = { x: -500, y: 900, z: 0, nx: 1, ny: 0, nz: 0, status: 'ahead' };
    const motion = { position: [0, 900, 0], velocity: [130, 0, 0], bank: 0, rollRate: 0, pathRate: 0 };
    expect(predictThroughRing(ring, motion, true).offset).toBe(Infinity);
    // Level and straight, it agrees with the straight line.
    const ahead = { ...ring, x: 600, y: 930 };
    expect(predictThroughRing(ahead, motion, true).offset).toBeCloseTo(pathThroughRing(ahead, motion.position, motion.velocity).offset, 6);
    expect(() => predictThroughRing(ring, { ...motion, velocity: [Number.NaN, 0, 0] }, true)).toThrow(
      /predictThroughRing: velocity must be 3 finite numbers/,
    );
    expect(() => predictThroughRing(ring, { ...motion, bank: Infinity }, false)).toThrow(
      /predictThroughRing: bank, rollRate and pathRate must be finite/,
    );
  });

  it('release stops the turn: a bank key let go after 0.7, 1 or 2 s rolls no more than 4 degrees further, the wings level within 1.2 s, the nose turns on under 1 degree after a 2 s hold', () => {
    // A stranger held ← 0.7 s and the turn went on after the release: the bank asked for was still
    // 20 degrees ahead of the aircraft's and the key fell back over 0.25 s, so the wings rolled on
    // 7 degrees into the turn after the release and took 1.4 to 1.7 s to level (measured now: 3, 0
    // and 0 degrees further, level in 0.87, 1.03 and 1.08 s); a 2 s hold's nose ran on 3.2 degrees.
    for (const hold of [0.7, 1, 2]) {
      const f = start();
      const e = f.h.body;
      const throttle = aircraftLevelDrag(130) / AIRCRAFT.maxThrust;
      const release = Math.round(hold * 60);
      let key = 0,
        bankAtRelease = 0,
        headingAtRelease = 0,
        further = 0,
        level = Infinity;
      for (let i = 0; i < release + 4 * 60; i++) {
        const s = flightState(f.world, e);
        if (i === release) {
          bankAtRelease = s.bank;
          headingAtRelease = s.heading;
        }
        if (i >= release) {
          further = Math.max(further, s.bank - bankAtRelease);
          if (level === Infinity && Math.abs(s.bank) < 3 * DEG) level = (i - release) / 60;
        }
        key = rampKey(key, i < release ? 1 : 0, 1 / 60, BANK_KEY_RAMP);
        fly(f, { roll: key }, 1 / 60, { throttle });
      }
      // Let go well banked (the gentle keys have the wings at 27 degrees after 0.7 s).
      expect(bankAtRelease, `${hold}`).toBeGreaterThan(20 * DEG);
      expect(further, `${hold}`).toBeLessThan(4 * DEG);
      expect(level, `${hold}`).toBeLessThan(1.2);
      if (hold === 2) expect(Math.abs(flightState(f.world, e).heading - headingAtRelease)).toBeLessThan(1 * DEG);
    }
  });

  it('→ and ↓ held together 8 s (what a tip asks): the bank stays within ASSIST.steepestBank + 3 degrees, grows at most 14 degrees in any 0.1 s (a slow frame: FRAME_CAP), and rolls level within 1.2 s of the release', () => {
    // A stranger at 3 frames a second held both and saw the aircraft roll steeply off the ring; the
    // bank is built per game second (each step reads the ramped keys) and a drawn frame advances at
    // most FRAME_CAP (0.1 s) of it, so a key held over a slow frame banks no faster.
    const f = start();
    const keys = { roll: 0, pitch: 0 };
    const banks: number[] = [];
    let t = 0;
    for (; t < 8; t += f.world.dt) {
      keys.roll = rampKey(keys.roll, 1, f.world.dt, BANK_KEY_RAMP);
      keys.pitch = rampKey(keys.pitch, -1, f.world.dt);
      fly(f, keys, f.world.dt);
      banks.push(flightState(f.world, f.h.body).bank);
    }
    const steps = Math.round(FRAME_CAP / f.world.dt);
    let jump = 0;
    for (let k = steps; k < banks.length; k++) jump = Math.max(jump, Math.abs(banks[k]! - banks[k - steps]!));
    expect(Math.max(...banks.map(Math.abs))).toBeLessThan(ASSIST.steepestBank + 3 * DEG); // measured 72.7 degrees
    expect(jump).toBeLessThan(14 * DEG); // measured 11.1 (the ailerons' roll rate, about 1.9 rad/s)
    // Let go: level (under 3 degrees) within 1.2 s.
    let level = Number.POSITIVE_INFINITY;
    for (let u = 0; u < 3; u += f.world.dt) {
      keys.roll = rampKey(keys.roll, 0, f.world.dt, BANK_KEY_RAMP);
      keys.pitch = rampKey(keys.pitch, 0, f.world.dt);
      fly(f, keys, f.world.dt);
      if (Math.abs(flightState(f.world, f.h.body).bank) < 3 * DEG) {
        level = u;
        break;
      }
    }
    expect(level).toBeLessThan(1.2); // measured 0.77 s
  });

  it('a held key let go after 1.5 s, still rolling into a 70 degree bank: the wings level briskly, the heading stays within 3 degrees of where it was let go (measured -0.3)', () => {
    // The ailerons (45 degrees: AILERON_SCALE times the authority) roll the 70 degree bank level in
    // about 0.9 s and the rudder stops the nose with them: the heading ends within a degree of the
    // release's (with 40 degree ailerons and the bank held a moment after a touch it ran on 5).
    const { runOn } = release(1, 0, 1.5, 1000);
    expect(Math.abs(runOn)).toBeLessThan(3 * DEG);
  });
});

describe('throttleStep', () => {
  it('a press of Faster or Slower steps the throttle to the next tenth at least 5 % away, within [0, 1]', () => {
    // The game's start (28 %) goes to 40 % with Faster, 20 % with Slower: a change the readout shows.
    expect(throttleStep(0.28, 1)).toBeCloseTo(0.4, 12);
    expect(throttleStep(0.28, -1)).toBeCloseTo(0.2, 12);
    // On a tenth it goes a whole tenth; within 5 % of the next tenth, it goes to that tenth.
    expect(throttleStep(0.3, 1)).toBeCloseTo(0.4, 12);
    expect(throttleStep(0.4, -1)).toBeCloseTo(0.3, 12);
    expect(throttleStep(0.35, 1)).toBeCloseTo(0.4, 12);
    expect(throttleStep(0.36, 1)).toBeCloseTo(0.5, 12);
    // Ten presses from idle reach full, never past it; and back.
    let t = 0;
    for (let k = 0; k < 12; k++) t = throttleStep(t, 1);
    expect(t).toBe(1);
    for (let k = 0; k < 12; k++) t = throttleStep(t, -1);
    expect(t).toBe(0);
    expect(() => throttleStep(1.2, 1)).toThrow(/throttleStep: throttle must be in \[0, 1\], got 1.2/);
    expect(() => throttleStep(0.5, 0)).toThrow(/throttleStep: direction must be 1 or -1, got 0/);
  });
});

describe('the ground floor (floorPath): a held dive goes down and levels over the ground', () => {
  it('floorPath: level at the floor, a climb under it, a dive far above; a hill ahead raises it; bad input refused', () => {
    const flat = () => 100;
    const v = [130, 0, 0];
    const at = (above: number) => floorPath([0, 100 + above, 0], v, flat);
    expect(at(GROUND_FLOOR.height)).toBeCloseTo(0, 12);
    expect(at(GROUND_FLOOR.height - 20)).toBeCloseTo(Math.atan2(20, 130 * GROUND_FLOOR.time), 12);
    expect(at(GROUND_FLOOR.height + 500)).toBeCloseTo(-Math.atan2(500, 130 * GROUND_FLOOR.time), 12);
    // A 200 m hill 260 m ahead (2 s): the floor over it, already.
    const hill = (x: number) => (x >= 250 && x <= 270 ? 300 : 100);
    expect(floorPath([0, 400, 0], v, hill)).toBeCloseTo(Math.atan2(300 + GROUND_FLOOR.height - 400, 130 * GROUND_FLOOR.time), 12);
    // Beyond GROUND_FLOOR.ahead s of flight it is not looked at yet.
    const far = (x: number) => (x > 130 * (GROUND_FLOOR.ahead + 0.5) ? 900 : 100);
    expect(floorPath([0, 400, 0], v, far)).toBeCloseTo(Math.atan2(100 + GROUND_FLOOR.height - 400, 130 * GROUND_FLOOR.time), 12);
    expect(() => floorPath([0, Number.NaN, 0], v, flat)).toThrow(/floorPath: position must be 3 finite numbers/);
  });

  it('↓ held from 150, 300 and 600 m over flat ground: the nose goes down (the path past 10 degrees down) and the aircraft levels over 40 m up, the assist saying it holds it', () => {
    // Without the floor a held dive from 300 m flew into the ground in 6.3 s (scripts/flight-simulator-steering.mjs, FLOOR=0).
    for (const above of [150, 300, 600]) {
      const f = start();
      const c = f.world.components,
        e = f.h.body;
      const ground = () => 900 - above;
      let key = 0,
        steepest = 0,
        lowest = Infinity,
        held = false;
      for (let i = 0; i < 20 * 60; i++) {
        key = rampKey(key, -1, 1 / 60);
        const s = flightState(f.world, e);
        const floor = floorPath(
          [c.Position.x[e]!, c.Position.y[e]!, c.Position.z[e]!],
          [c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!],
          ground,
        );
        const cmd = assist(s, { roll: 0, pitch: key, yaw: 0 }, f.state, 1 / 60, floor);
        setControlDeflection(f.world, f.h.surfaces.tail, -cmd.elevator * FULL);
        setControlDeflection(f.world, f.h.surfaces.leftWing, cmd.aileron * FULL * AILERON_SCALE);
        setControlDeflection(f.world, f.h.surfaces.rightWing, -cmd.aileron * FULL * AILERON_SCALE);
        setControlDeflection(f.world, f.h.surfaces.fin, -cmd.rudder * FULL);
        step(f.world);
        steepest = Math.min(steepest, flightState(f.world, e).path);
        lowest = Math.min(lowest, c.Position.y[e]! - ground());
        held ||= f.state.floorHold;
      }
      expect(steepest, `${above} m`).toBeLessThan(-10 * DEG);
      expect(lowest, `${above} m`).toBeGreaterThan(40);
      expect(held, `${above} m`).toBe(true);
      // Still held up at the end, close over the floor.
      expect(c.Position.y[e]! - ground(), `${above} m`).toBeLessThan(GROUND_FLOOR.height + 40);
      expect(f.state.floorHold).toBe(true);
    }
  });
});
