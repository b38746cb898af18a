/**
 * The rules of the black-hole game without a page (games/black-hole/rules.ts): falling into a hole
 * (the ship's size touching its horizon) costs a life, crossing the line scores the number of holes and adds one, leaving the field resets
 * without penalty, zero lives ends the game; every hole's drawn radius is its Schwarzschild radius;
 * thrust, exhaust and the predicted path.
 */

import { setPosition, setVelocity, slotOf } from '@bitphysics/physics';
import { query } from 'bitecs';
import { describe, expect, test } from 'vitest';
import {
  type BlackHoleGame,
  C_GAME,
  createBlackHoleGame,
  createPredictor,
  FIELD,
  G_GAME,
  gravitationalConstant,
  heldThrust,
  holeHit,
  LINE_Y,
  layoutHoles,
  MAX_HOLES,
  NARROW_SIDE_RAMP,
  NARROW_SIDE_SPEED,
  pathEnd,
  predictPath,
  rampThrust,
  resetShip,
  resolveBlackHoleOptions,
  restart,
  SHIP_RADIUS,
  SIDE_TAP_KICK,
  SOFT_WALL,
  START,
  schwarzschildMass,
  schwarzschildRadius,
  setGScale,
  setLightSpeed,
  setThrust,
  stepBlackHole,
  THRUST_RAMP,
} from '../../games/black-hole/rules';

const shipAt = (g: BlackHoleGame) => [g.world.components.Position.x[slotOf(g.ship)]!, g.world.components.Position.y[slotOf(g.ship)]!];
const place = (g: BlackHoleGame, x: number, y: number, vx = 0, vy = 0) => {
  setPosition(g.world, g.ship, [x, y]);
  setVelocity(g.world, g.ship, [vx, vy]);
};
/** Every hole satisfies r = 2 G M / c^2 with the world's G and the game's c, and the attractor mass is M. */
const expectSchwarzschild = (g: BlackHoleGame) => {
  const G = g.world.laws.gravitationalConstant,
    c = g.params.c;
  expect(G).toBe(gravitationalConstant(g));
  for (let i = 0; i < g.holes.length; i++) {
    const M = g.world.components.Attractor.mass[slotOf(g.holes[i]!)]!;
    expect(M).toBe(g.holeMass[i]);
    expect(g.holeRadius[i]! / ((2 * G * M) / (c * c))).toBeCloseTo(1, 12);
  }
};

/**
 * The speed (m/s) an engine of thrust `a` m/s^2 gives from rest in `t` s held, from THRUST_RAMP's
 * definition (not from rampThrust): the thrust grows evenly to trim x a in `gentle` s, then evenly
 * to a by `up` s, then stays; the area under that curve.
 */
function rampGain(a: number, t: number): number {
  const { trim, gentle, up } = THRUST_RAMP;
  const slow = (trim * a) / gentle,
    fast = ((1 - trim) * a) / (up - gentle);
  if (t <= gentle) return (slow * t * t) / 2;
  const u = Math.min(t, up) - gentle;
  return (trim * a * gentle) / 2 + trim * a * u + (fast * u * u) / 2 + a * Math.max(0, t - up);
}

describe('Schwarzschild holes', () => {
  test('M = c^2 r / 2G and back; at the horizon the escape speed is c', () => {
    expect(schwarzschildMass(1, 10, 1)).toBe(50);
    expect(schwarzschildRadius(50, 10, 1)).toBe(1);
    const r = 0.73,
      c = 7,
      G = 2.5;
    const M = schwarzschildMass(r, c, G);
    expect(schwarzschildRadius(M, c, G)).toBeCloseTo(r, 14);
    expect(Math.sqrt((2 * G * M) / r)).toBeCloseTo(c, 12);
    expect(() => schwarzschildMass(0, 10, 1)).toThrow(/radius, c and G must be finite and > 0, got 0, 10, 1/);
    expect(() => schwarzschildRadius(1, 10, Number.NaN)).toThrow(RangeError);
  });

  test('every hole of every layout, and after changing G and c, has its drawn radius as its Schwarzschild radius', () => {
    const g = createBlackHoleGame({ seed: 3, holes: 5 });
    expect(g.world.laws.gravitationalConstant).toBe(G_GAME);
    expect(g.params.c).toBe(C_GAME);
    expectSchwarzschild(g);
    for (let n = 1; n <= MAX_HOLES; n++) {
      layoutHoles(g, n);
      expect(g.holes.length).toBe(n);
      expectSchwarzschild(g);
    }
    const masses = [...g.holeMass];
    setGScale(g, 2.5);
    expectSchwarzschild(g);
    expect(g.holeMass).toEqual(masses); // masses kept, horizons grew
    setLightSpeed(g, 14);
    expectSchwarzschild(g);
    // The pull of a hole of radius r at distance d is c^2 r / (2 d^2), whatever G is.
    const h = g.holes[0]!,
      P = g.world.components.Position;
    place(g, P.x[slotOf(h)]! + 3 * g.holeRadius[0]!, P.y[slotOf(h)]!);
    const v0 = g.world.components.Velocity.x[slotOf(g.ship)]!;
    stepBlackHole(g);
    // Only this hole matters much at 3 radii: compare with the sum over all holes.
    let ax = 0;
    for (let i = 0; i < g.holes.length; i++) {
      const dx = P.x[slotOf(g.holes[i]!)]! - (P.x[slotOf(h)]! + 3 * g.holeRadius[0]!),
        dy = P.y[slotOf(g.holes[i]!)]! - P.y[slotOf(h)]!;
      const d = Math.hypot(dx, dy);
      ax += ((14 * 14 * g.holeRadius[i]!) / (2 * d * d)) * (dx / d);
    }
    expect((g.world.components.Velocity.x[slotOf(g.ship)]! - v0) / g.world.dt).toBeCloseTo(ax, 9);
  });

  test('layouts keep the holes inside the band, apart, and away from the start', () => {
    for (let seed = 1; seed <= 20; seed++) {
      const g = createBlackHoleGame({ seed, holes: 8 });
      const P = g.world.components.Position;
      for (let i = 0; i < g.holes.length; i++) {
        const x = P.x[slotOf(g.holes[i]!)]!,
          y = P.y[slotOf(g.holes[i]!)]!,
          r = g.holeRadius[i]!;
        expect(x - r).toBeGreaterThan(0);
        expect(x + r).toBeLessThan(FIELD.width);
        expect(y + r).toBeLessThan(LINE_Y);
        expect(Math.hypot(x - START[0], y - START[1]) - r).toBeGreaterThanOrEqual(4);
        for (let j = 0; j < i; j++) {
          expect(Math.hypot(x - P.x[slotOf(g.holes[j]!)]!, y - P.y[slotOf(g.holes[j]!)]!) - r - g.holeRadius[j]!).toBeGreaterThanOrEqual(3);
        }
      }
    }
  });
});

describe('rules', () => {
  test('entering a hole costs a life and puts the ship back at the start', () => {
    const g = createBlackHoleGame({ seed: 1 });
    const P = g.world.components.Position,
      h = g.holes[0]!;
    place(g, P.x[slotOf(h)]! + g.holeRadius[0]! + 0.05, P.y[slotOf(h)]!, -3, 0);
    let event = 'none';
    for (let i = 0; i < 10 && event === 'none'; i++) event = stepBlackHole(g);
    expect(event).toBe('fell');
    expect(g.lives).toBe(2);
    expect(g.over).toBe(false);
    expect(shipAt(g)).toEqual([...START]);
    expect(g.message).toMatch(/Swallowed by a black hole! 2 lives left/);
  });

  test('a fast ship cannot jump over a horizon within one step (swept test)', () => {
    const g = createBlackHoleGame({ seed: 1 });
    const P = g.world.components.Position,
      h = g.holes[0]!,
      r = g.holeRadius[0]!;
    // From 1.2 r left of the centre to 1.2 r right of it in one step: both ends outside the horizon.
    expect(holeHit(g, P.x[slotOf(h)]! - 1.2 * r, P.y[slotOf(h)]!, P.x[slotOf(h)]! + 1.2 * r, P.y[slotOf(h)]!)).toBe(0);
    // The ship has a size: passing SHIP_RADIUS m over the horizon (less 5 %) touches it; 5 % more does not.
    const pass = (above: number) =>
      holeHit(g, P.x[slotOf(h)]! - 2 * r, P.y[slotOf(h)]! + above, P.x[slotOf(h)]! + 2 * r, P.y[slotOf(h)]! + above);
    expect(pass(r + 0.95 * SHIP_RADIUS)).toBe(0);
    expect(pass(r + 1.05 * SHIP_RADIUS)).toBe(-1);
    place(g, P.x[slotOf(h)]! - 1.2 * r, P.y[slotOf(h)]!, (2.4 * r) / g.world.dt, 0);
    expect(stepBlackHole(g)).toBe('fell');
  });

  test('crossing the line scores the number of holes, adds a hole and lays them out again', () => {
    const g = createBlackHoleGame({ seed: 2, holes: 3 });
    const P = g.world.components.Position;
    const before = g.holes.map((h) => [P.x[slotOf(h)], P.y[slotOf(h)]]);
    // Straight up a column with no hole in it would take long; put the ship just below the line.
    place(g, 1, LINE_Y - 0.05, 0, 5);
    expect(stepBlackHole(g)).toBe('scored');
    expect(g.score).toBe(3);
    expect(g.holes.length).toBe(4);
    expect(g.holes.map((h) => [P.x[slotOf(h)], P.y[slotOf(h)]])).not.toEqual(before.concat([[0, 0]]));
    expect(shipAt(g)).toEqual([...START]);
    expect(g.lives).toBe(3);
    expectSchwarzschild(g);
    place(g, 1, LINE_Y - 0.05, 0, 5);
    expect(stepBlackHole(g)).toBe('scored');
    expect(g.score).toBe(3 + 4);
    expect(g.holes.length).toBe(5);
  });

  test('leaving the field puts the ship back without penalty, on every side', () => {
    const g = createBlackHoleGame({ seed: 4 });
    for (const [x, y, vx, vy] of [
      [0.02, 10, -5, 0],
      [FIELD.width - 0.02, 10, 5, 0],
      [10, 0.02, 0, -5],
    ] as const) {
      place(g, x, y, vx, vy);
      const e = stepBlackHole(g);
      expect(e).toBe('lost');
      expect(shipAt(g)).toEqual([...START]);
      expect(g.world.components.Velocity.x[slotOf(g.ship)]).toBe(0);
    }
    expect(g.lives).toBe(3);
    expect(g.score).toBe(0);
    expect(g.message).toMatch(/no penalty/);
  });

  test('zero lives ends the game: thrust ignored, the ship waits, restart brings everything back', () => {
    const g = createBlackHoleGame({ seed: 5, lives: 3 });
    const P = g.world.components.Position;
    const events: string[] = [];
    for (let k = 0; k < 3; k++) {
      const h = g.holes[0]!;
      place(g, P.x[slotOf(h)]!, P.y[slotOf(h)]! + 0.5 * g.holeRadius[0]!);
      events.push(stepBlackHole(g));
    }
    expect(events).toEqual(['fell', 'fell', 'over']);
    expect(g.lives).toBe(0);
    expect(g.over).toBe(true);
    expect(g.message).toMatch(/Game over/);
    setThrust(g, 'up');
    expect(g.thrust).toBe('none');
    for (let i = 0; i < 120; i++) expect(stepBlackHole(g)).toBe('none');
    expect(shipAt(g)).toEqual([...START]);
    restart(g);
    expect([g.lives, g.score, g.over, g.holes.length]).toEqual([3, 0, false, 3]);
  });
});

describe('thrust, exhaust, prediction', () => {
  test('thrust accelerates the ship at `thrust` m/s^2 in one direction at a time; the exhaust runs only while thrusting', () => {
    const g = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6 });
    // The hole's pull is nearly the same along the three short paths: compare each with no thrust.
    const run = (dir: 'none' | 'right' | 'up') => {
      const h = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6 });
      setThrust(h, dir);
      for (let i = 0; i < 30; i++) stepBlackHole(h);
      return {
        v: [h.world.components.Velocity.x[h.ship]!, h.world.components.Velocity.y[h.ship]!],
        particles: query(h.world, [h.world.components.Particle]).length,
      };
    };
    const none = run('none'),
      right = run('right'),
      up = run('up');
    // 0.5 s held: the engine's spool-up, gentle then quick (within a step's 0.1 m/s).
    const gained = rampGain(6, 0.5);
    expect(Math.abs(right.v[0] - none.v[0] - gained)).toBeLessThan(0.1);
    expect(right.v[1] - none.v[1]).toBeCloseTo(0, 2);
    expect(Math.abs(up.v[1] - none.v[1] - gained)).toBeLessThan(0.1);
    expect(up.v[0] - none.v[0]).toBeCloseTo(0, 2);
    expect(none.particles).toBe(0);
    expect(right.particles).toBeGreaterThan(40);
    // Exhaust leaves against the thrust: thrusting right, the particles move left relative to the ship.
    setThrust(g, 'right');
    for (let i = 0; i < 20; i++) stepBlackHole(g);
    const V = g.world.components.Velocity;
    const ids = Array.from(query(g.world, [g.world.components.Particle]));
    const rel = ids.reduce((s, e) => s + V.x[e]!, 0) / ids.length - V.x[slotOf(g.ship)]!;
    expect(rel).toBeLessThan(-3);
    setThrust(g, 'none');
    for (let i = 0; i < 60; i++) stepBlackHole(g);
    expect(query(g.world, [g.world.components.Particle]).length).toBe(0);
    expect(() => setThrust(g, 'sideways' as never)).toThrow(/thrust must be one of none, up, down, left, right/);
  });

  test('two arrows at right angles thrust diagonally at the same `thrust` m/s^2 as one; opposite arrows: the later wins', () => {
    expect(heldThrust([])).toBe('none');
    expect(heldThrust(['up'])).toBe('up');
    expect(heldThrust(['up', 'right'])).toBe('up-right');
    expect(heldThrust(['left', 'down'])).toBe('down-left');
    expect(heldThrust(['left', 'up', 'right'])).toBe('up-right');
    expect(heldThrust(['up', 'down'])).toBe('down');
    expect(() => heldThrust(['north' as never])).toThrow(/heldThrust: held must hold only up, down, left, right, got "north"/);
    // Far from the holes (none within 4 m of the start), the velocity gained in 0.5 s with up-right
    // held points at 45 degrees and is as large as with up held (the pull differs by < 0.05 m/s).
    const gain = (dir: 'none' | 'up' | 'up-right') => {
      const h = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6 });
      setThrust(h, dir);
      for (let i = 0; i < 30; i++) stepBlackHole(h);
      return [h.world.components.Velocity.x[slotOf(h.ship)]!, h.world.components.Velocity.y[slotOf(h.ship)]!] as const;
    };
    const none = gain('none'),
      up = gain('up'),
      diag = gain('up-right');
    const dx = diag[0] - none[0],
      dy = diag[1] - none[1];
    expect(Math.abs(Math.hypot(dx, dy) - (up[1] - none[1]))).toBeLessThan(0.05);
    expect(Math.abs(Math.atan2(dy, dx) - Math.PI / 4)).toBeLessThan(0.01);
  });

  test('the engine spools up and down: gently at first, then quickly to full thrust; a new arrow swings the thrust over', () => {
    // The issue this answers: a 0.15 s tap of up sent the ship on level 1 into its middle hole (the
    // engine reached full thrust in 0.25 s at an even rate: the tap gained 0.45 m/s). It now builds to
    // trim x thrust in THRUST_RAMP.gentle s, then to full by THRUST_RAMP.up.
    const dt = 1 / 60;
    const { trim, gentle, up, down } = THRUST_RAMP;
    const v: [number, number] = [0, 0];
    rampThrust(v, 0, 6, 6, dt);
    expect(v[1]).toBeCloseTo((trim * 6 * dt) / gentle, 12);
    let n = 1;
    while (v[1] < trim * 6 - 1e-9) {
      rampThrust(v, 0, 6, 6, dt);
      n++;
    }
    expect(n).toBe(Math.round(gentle / dt));
    while (v[1] < 6) {
      rampThrust(v, 0, 6, 6, dt);
      n++;
    }
    expect(n).toBe(Math.round(up / dt));
    // Up to right: the thrust swings over at the quick rate (it stays above trim), never more than
    // full, and gets there in sqrt(2) x 6 / quick s.
    const quick = ((1 - trim) * 6) / (up - gentle);
    for (n = 0; v[0] !== 6 || v[1] !== 0; n++) {
      rampThrust(v, 6, 0, 6, dt);
      expect(Math.hypot(v[0], v[1])).toBeLessThanOrEqual(6 + 1e-12);
    }
    expect(n).toBe(Math.ceil((Math.SQRT2 * 6) / quick / dt - 1e-9));
    // Right to left (a reversal): it dies at the quick rate, then starts gently as a fresh press (the
    // quick step that passes through nothing can carry it up to a quick step's worth into the gentle
    // stretch, which saves up to quick / slow gentle steps).
    const slow = (trim * 6) / gentle;
    for (n = 0; Number(v[0]) !== -6; n++) {
      rampThrust(v, -6, 0, 6, dt);
      expect(v[1]).toBe(0);
    }
    expect(n).toBeLessThanOrEqual(Math.ceil((6 / quick + up) / dt));
    expect(n).toBeGreaterThanOrEqual(Math.floor((6 / quick + up) / dt - quick / slow));
    // Let go: gone in THRUST_RAMP.down.
    for (n = 0; Math.hypot(v[0], v[1]) > 0; n++) rampThrust(v, 0, 0, 6, dt);
    expect(n).toBe(Math.round(down / dt));
    expect(() => rampThrust(v, 0, 0, 6, 0)).toThrow(/rampThrust: dt must be > 0, full >= 0 and sideUp >= 0.4, got 0, 6, 0.4/);
    // In the game: a 0.15 s (9-step) tap of up changes the speed by slow x dt^2 x (1 + ... + 9) while
    // held (0.15 m/s), and by what is left of the 1.8 m/s^2 as it dies at 6 / down m/s^3 after
    // (0.8 m/s^2 for one step: 0.013 m/s); a 1 s hold by rampGain(6, 1) = 4.68 m/s. (Before: a tap
    // of 0.38 m/s, a hold of 5.25 m/s.) Compared with the same steps and no thrust (the hole's pull, made
    // 25 times weaker by c = 2 m/s: the pull is c^2 r / 2 d^2, and the 1 s hold flies 2 m).
    const speedUp = (steps: number, held: number) => {
      const h = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6, c: 2 });
      for (let i = 0; i < steps; i++) {
        setThrust(h, i < held ? 'up' : 'none');
        stepBlackHole(h);
      }
      return h.world.components.Velocity.y[slotOf(h.ship)]!;
    };
    let release = 0;
    for (let a = slow * 9 * dt - (6 / down) * dt; a > 0; a -= (6 / down) * dt) release += a * dt;
    expect(speedUp(30, 9) - speedUp(30, 0)).toBeCloseTo(slow * dt * dt * 45 + release, 4);
    expect(Math.abs(speedUp(60, 60) - speedUp(60, 0) - rampGain(6, 1))).toBeLessThan(0.1);
  });

  test('a gentler sideways engine (sideRamp): past the gentle start the sideways part grows at most at thrust / sideRamp; up is as before', () => {
    // A 0.5 s (30-step) press of right from rest. The default engine starts gently (to trim x 6 m/s^2
    // in THRUST_RAMP.gentle s) and reaches 6 m/s^2 by THRUST_RAMP.up; the phone's (sideRamp 0.6) x
    // part grows at 6 / 0.6 = 10 m/s^3 all the way (the engine's own rates, gentle and quick, are
    // both above that), reaching 5 m/s^2 at 0.5 s. The speed gained by then: rampGain(6, 0.5) =
    // 1.68 m/s, and 10 x 0.5^2 / 2 = 1.25 m/s.
    const pressSpeed = (sideRamp: number, dir: 'right' | 'up', press: boolean) => {
      const h = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6, sideRamp });
      setThrust(h, press ? dir : 'none');
      for (let i = 0; i < 30; i++) stepBlackHole(h);
      const V = h.world.components.Velocity;
      return dir === 'right' ? V.x[slotOf(h.ship)]! : V.y[slotOf(h.ship)]!;
    };
    expect(
      Math.abs(pressSpeed(THRUST_RAMP.up, 'right', true) - pressSpeed(THRUST_RAMP.up, 'right', false) - rampGain(6, 0.5)),
    ).toBeLessThan(0.1);
    const { trim, gentle, up } = THRUST_RAMP;
    expect(Math.min((trim * 6) / gentle, ((1 - trim) * 6) / (up - gentle))).toBeGreaterThan(10);
    const phone = (10 * 0.5 ** 2) / 2;
    expect(Math.abs(pressSpeed(0.6, 'right', true) - pressSpeed(0.6, 'right', false) - phone)).toBeLessThan(0.1);
    // Up is not sideways: the same with any sideRamp.
    expect(pressSpeed(0.6, 'up', true)).toBe(pressSpeed(THRUST_RAMP.up, 'up', true));
    expect(() => createBlackHoleGame({ sideRamp: 0.1 })).toThrow(/sideRamp must be in \[0.4, 2\] s, got 0.1/);
  });

  test('a narrow field (a phone’s) builds its sideways thrust over NARROW_SIDE_RAMP s, after the press’s SIDE_TAP_KICK', () => {
    // A 0.5 s (30-step) hold of → from rest, then let go until the engine has died away. On a field
    // narrower than FIELD the x part grows at 6 / NARROW_SIDE_RAMP m/s^3 (under the engine's own
    // rates), so at the let-go it is 6 x 0.5 / 0.9 = 3.33 m/s^2 and the speed gained 6 / 0.9 x 0.5^2 / 2
    // = 0.83 m/s, and dying away at 6 / THRUST_RAMP.down m/s^3 it adds 3.33^2 / (2 x 60) = 0.09 m/s;
    // on FIELD the same hold gains rampGain(6, 0.5) = 1.68 m/s and 0.3 m/s more dying away from 6.
    // The narrow field's press also kicks the ship SIDE_TAP_KICK sideways at once; the wide one's does not.
    const hold = (field: { width: number; height: number }, dir: 'right' | 'up', sideRamp?: number) => {
      const h = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6, field, ...(sideRamp ? { sideRamp } : {}) });
      const V = h.world.components.Velocity;
      const v0 = dir === 'right' ? V.x[slotOf(h.ship)]! : V.y[slotOf(h.ship)]!;
      setThrust(h, dir);
      for (let i = 0; i < 30; i++) stepBlackHole(h);
      setThrust(h, 'none');
      for (let i = 0; i < 12; i++) stepBlackHole(h);
      return [h.params.sideRamp, (dir === 'right' ? V.x[slotOf(h.ship)]! : V.y[slotOf(h.ship)]!) - v0];
    };
    const phone = { width: 20, height: 30 };
    const [ramp, narrow] = hold(phone, 'right');
    expect(ramp).toBe(NARROW_SIDE_RAMP);
    const a = (6 * 0.5) / NARROW_SIDE_RAMP;
    expect(Math.abs(narrow! - SIDE_TAP_KICK - (a * 0.5) / 2 - a ** 2 / (2 * (6 / THRUST_RAMP.down)))).toBeLessThan(0.05);
    const [wideRamp, wide] = hold(FIELD, 'right');
    expect(wideRamp).toBe(THRUST_RAMP.up);
    expect(Math.abs(wide! - rampGain(6, 0.5) - (6 * THRUST_RAMP.down) / 2)).toBeLessThan(0.1);
    expect(narrow! - SIDE_TAP_KICK).toBeLessThan(0.5 * wide!);
    // Up is not sideways: on the narrow field the same with its default and with the wide field's
    // engine given (sideRamp given wins over the field's default).
    expect(hold(phone, 'up', THRUST_RAMP.up)).toEqual([THRUST_RAMP.up, hold(phone, 'up')[1]]);
  });

  test('a narrow field’s side press is proportional: a tap nudges 0.8-1 m/s, longer holds build up to NARROW_SIDE_SPEED; the wide field has no kick', () => {
    // Mid-field, out of the holes' reach, a press of → held n steps (a finger's tap is at least the
    // page's 15, ./press-timing.ts TAP_STEPS), then let go for 0.5 s: the sideways speed gained. It is
    // the kick (SIDE_TAP_KICK, at once) plus the ramped thrust's gain, never above the top speed.
    const gain = (field: { width: number; height: number }, n: number) => {
      const h = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6, field });
      for (const hole of h.holes) setPosition(h.world, hole, [1000, 1000]);
      setPosition(h.world, h.ship, [field.width / 2, 10]);
      const V = h.world.components.Velocity;
      setThrust(h, 'right');
      for (let i = 0; i < n; i++) stepBlackHole(h);
      setThrust(h, 'none');
      for (let i = 0; i < 30; i++) stepBlackHole(h);
      return V.x[slotOf(h.ship)]!;
    };
    const phone = { width: 20, height: 30 };
    const [tap, third, hold, long] = [15, 18, 36, 60].map((n) => gain(phone, n));
    // The 15-step ramp alone (the wide field's engine less its kick) gives 0.25 m/s; the kick brings a tap to 0.8-1 m/s.
    expect(tap).toBeGreaterThanOrEqual(0.8);
    expect(tap).toBeLessThanOrEqual(1);
    expect(tap! - SIDE_TAP_KICK).toBeLessThan(0.35);
    // Each longer hold gains more, by at least 0.1 m/s, up to the top speed (within its fade band).
    expect(third! - tap!).toBeGreaterThan(0.05);
    expect(hold! - third!).toBeGreaterThan(0.5);
    expect(long! - hold!).toBeGreaterThan(0.5);
    expect(long!).toBeLessThanOrEqual(NARROW_SIDE_SPEED + 0.05);
    // The kick never passes the top speed: already flying right at it, a new press of → adds nothing at once.
    const h = createBlackHoleGame({ seed: 6, holes: 1, field: phone });
    for (const hole of h.holes) setPosition(h.world, hole, [1000, 1000]);
    setPosition(h.world, h.ship, [10, 10]);
    setVelocity(h.world, h.ship, [NARROW_SIDE_SPEED, 0]);
    setThrust(h, 'right');
    stepBlackHole(h);
    expect(h.world.components.Velocity.x[slotOf(h.ship)]!).toBeLessThanOrEqual(NARROW_SIDE_SPEED + 1e-5);
    // The wide field: no kick, a 15-step tap gains the ramp's few tenths.
    expect(gain(FIELD, 15)).toBeLessThan(0.5);
    expect(createBlackHoleGame({ field: FIELD }).params.sideKick).toBe(0);
    expect(() => createBlackHoleGame({ sideKick: 4 })).toThrow(/sideKick must be in \[0, 3\] m\/s, got 4/);
  });

  test("a narrow field's soft side walls turn a coasting ship back within the bound its energy sets; a held arrow still leaves; the wide field has none", () => {
    // The ship coasting at 3 m/s towards the left edge from 6 m in, at the start's height (the holes,
    // c = 2 m/s, pull 25 times less than by default). The wall's spring alone, push q / w at q m into
    // its last w m, stops it q m in where v^2 / 2 = push q^2 / (2 w): q = v sqrt(w / push) = 1.39 m for
    // the default 3 m and 14 m/s^2; its damping only shortens that.
    const coast = (field: { width: number; height: number }, thrust: 'none' | 'left') => {
      const g = createBlackHoleGame({ seed: 3, holes: 1, c: 2, field });
      const s = slotOf(g.ship);
      setPosition(g.world, g.ship, [6, g.start[1]]);
      setVelocity(g.world, g.ship, [-3, 0]);
      setThrust(g, thrust);
      let minX = Infinity,
        lost = false;
      for (let i = 0; i < 300 && !lost; i++) {
        lost = stepBlackHole(g) === 'lost';
        if (!lost) minX = Math.min(minX, g.world.components.Position.x[s]!);
      }
      return { minX, lost, vx: g.world.components.Velocity.x[s]!, params: g.params };
    };
    const phone = coast({ width: 20, height: 30 }, 'none');
    expect(phone.params.softWall).toBe(SOFT_WALL.width);
    const q = 3 * Math.sqrt(SOFT_WALL.width / SOFT_WALL.push);
    expect(q).toBeCloseTo(3 * Math.sqrt(3 / 14), 9);
    expect(phone.lost).toBe(false);
    expect(phone.minX).toBeGreaterThan(SOFT_WALL.width - q - 0.02);
    // The damping does stop it sooner than the spring alone would (by more than the steps' rounding).
    expect(phone.minX).toBeGreaterThan(SOFT_WALL.width - q + 0.2);
    // Turned back: after 5 s it flies away from the edge.
    expect(phone.vx).toBeGreaterThan(0);
    // Holding ← (the engine thrusting towards the edge) the wall gives way: the ship leaves.
    expect(coast({ width: 20, height: 30 }, 'left').lost).toBe(true);
    // The wide field: no wall, the same drift is lost.
    const wide = coast(FIELD, 'none');
    expect(wide.params.softWall).toBe(0);
    expect(wide.lost).toBe(true);
  });

  test('park: the ship waits on the start pad until an arrow other than ↓ thrusts, and ↓ there never takes it off the field; without it ↓ does', () => {
    const hold = (park: boolean, thrust: 'down' | 'down-right' | 'none', seconds: number) => {
      const g = createBlackHoleGame({ seed: 4, holes: 5, park });
      const s = slotOf(g.ship),
        P = g.world.components.Position;
      setThrust(g, thrust);
      const events = new Set<string>();
      let minY = Infinity;
      for (let k = 0; k < seconds * 60; k++) {
        events.add(stepBlackHole(g));
        minY = Math.min(minY, P.y[s]!);
      }
      return { g, events, minY, at: [P.x[s]!, P.y[s]!] };
    };
    // 3 s of ↓ (it leaves the bottom, 1.5 m down, in 0.7 s at 6 m/s^2 without the pad): it stays put.
    const down = hold(true, 'down', 3);
    expect(down.events).toEqual(new Set(['none']));
    expect(down.at).toEqual([...down.g.start]);
    expect(down.g.parked).toBe(true);
    expect(hold(false, 'down', 3).events.has('lost')).toBe(true);
    // Waiting with nothing held, the holes' pull does not move it (it would drift without the pad).
    expect(hold(true, 'none', 5).at).toEqual([...down.g.start]);
    expect(hold(false, 'none', 5).at).not.toEqual([...down.g.start]);
    // ↘ from the pad is →: it leaves the pad sideways, never below the pad's height.
    const side = hold(true, 'down-right', 1);
    expect(side.g.parked).toBe(false);
    expect(side.g.thrust).toBe('right');
    expect(side.at[0]).toBeGreaterThan(side.g.start[0] + 1);
    expect(side.minY).toBeGreaterThanOrEqual(side.g.start[1] - 1e-9);
    // A fall, an exit or a crossing (resetShip) parks it again; the option is checked.
    resetShip(side.g);
    expect(side.g.parked).toBe(true);
    expect(() => createBlackHoleGame({ park: 1 as unknown as boolean })).toThrow(/park must be a boolean, got 1/);
  });

  test("a narrow field's side arrow alone builds at most NARROW_SIDE_SPEED: a hold of 1 s or more stays 2 m inside the field, a 0.6 s hold still dodges", () => {
    // From rest in the middle of the phone's 20 m field, → held for `hold` s, then let go and coasting
    // for 8 s; the one hole sits at the top middle (its pull at the ship, under 0.1 m/s^2, is
    // negligible). With no limit a hold's speed grows by the sideways thrust, 6 x 0.8125 = 4.9 m/s^2,
    // every second past the ramp; the walls' spring and damping stop a ship coasting at 3 m/s within
    // q = 3 sqrt(width / push) m of their inner edge (the test above), so it stays more than
    // width - q = 1.6 m from the field's edge.
    const fly = (hold: number, field = { width: 20, height: 30 }, thrust: 'right' | 'up-right' = 'right') => {
      const g = createBlackHoleGame({ seed: 3, holes: 1, field });
      setPosition(g.world, g.holes[0]!, [field.width / 2, field.height - 0.5]);
      g.version++;
      const s = slotOf(g.ship),
        P = g.world.components.Position,
        V = g.world.components.Velocity;
      const x0 = P.x[s]!;
      setThrust(g, thrust);
      let maxX = x0,
        topV = 0,
        lost = false,
        after1 = 0;
      for (let k = 0; k < (hold + 8) * 60 && !lost; k++) {
        if (k === Math.round(hold * 60)) setThrust(g, 'none');
        lost = stepBlackHole(g) === 'lost';
        maxX = Math.max(maxX, P.x[s]!);
        topV = Math.max(topV, V.x[s]!);
        if (k === Math.round((hold + 1) * 60)) after1 = P.x[s]! - x0;
      }
      return { edge: field.width - maxX, topV, lost, after1, params: g.params };
    };
    for (const hold of [1, 1.5, 3]) {
      const f = fly(hold);
      expect(f.params.sideSpeed).toBe(NARROW_SIDE_SPEED);
      expect(f.lost, `${hold} s`).toBe(false);
      expect(f.topV, `${hold} s`).toBeLessThan(NARROW_SIDE_SPEED + 0.05);
      expect(f.edge, `${hold} s`).toBeGreaterThan(SOFT_WALL.width - 3 * Math.sqrt(SOFT_WALL.width / SOFT_WALL.push));
    }
    // A 0.6 s hold is untouched by the limit (it gains 1.2 m/s): the ship moves 1.5 m aside within a
    // second of the let-go, clear of a hole of the largest radius (1.4 m) ahead.
    expect(fly(0.6).after1).toBeGreaterThan(1.5);
    // A 1 s hold flies 3 m aside within that second (some 4 m).
    expect(fly(1).after1).toBeGreaterThan(3);
    // A diagonal is not limited (a held one leaves the narrow field, as the levels' layout check asks).
    expect(fly(3, { width: 20, height: 30 }, 'up-right').topV).toBeGreaterThan(NARROW_SIDE_SPEED + 2);
    // The wide field has no limit: 1.5 s of → there goes faster than 3 m/s.
    const wide = fly(1.5, FIELD);
    expect(wide.params.sideSpeed).toBe(Infinity);
    expect(wide.topV).toBeGreaterThan(NARROW_SIDE_SPEED + 2);
    expect(() => createBlackHoleGame({ sideSpeed: 0.5 })).toThrow(/sideSpeed must be in \[1, Infinity\] m\/s, got 0.5/);
  });

  test("a narrow field's sideways thrust is (1 + its width's share) / 2 of the thrust; up keeps the full thrust", () => {
    const held = (thrust: 'right' | 'up' | 'up-right') => {
      const g = createBlackHoleGame({ seed: 6, holes: 1, thrust: 6, field: { width: 20, height: 30 } });
      setThrust(g, thrust);
      for (let i = 0; i < 120; i++) stepBlackHole(g);
      return [...g.thrustVec];
    };
    // 2 s: long past the ramp (NARROW_SIDE_RAMP), the engine at its target a_T (s d_x, d_y), s = (1 + 20 / 32) / 2.
    const s = (1 + 20 / 32) / 2;
    expect(held('right')[0]).toBeCloseTo(6 * s, 9);
    expect(held('up')[1]).toBeCloseTo(6, 9);
    const d = held('up-right');
    expect(d[0]).toBeCloseTo(6 * Math.SQRT1_2 * s, 9);
    expect(d[1]).toBeCloseTo(6 * Math.SQRT1_2, 9);
    expect(resolveBlackHoleOptions({}).sideScale).toBe(1);
    expect(() => createBlackHoleGame({ sideScale: 0.1 })).toThrow(/sideScale must be in \[0.3, 1\], got 0.1/);
    expect(() => createBlackHoleGame({ softWall: -1 })).toThrow(/softWall must be in \[0, 5\] m, got -1/);
  });

  test('exhaust that crosses a horizon is swallowed', () => {
    const g = createBlackHoleGame({ seed: 7, holes: 1 });
    const P = g.world.components.Position,
      h = g.holes[0]!;
    // Park the ship right above the hole (kept there each step) and fire downwards into it.
    setThrust(g, 'up');
    let inside = 0;
    for (let i = 0; i < 40; i++) {
      place(g, P.x[slotOf(h)]!, P.y[slotOf(h)]! + g.holeRadius[0]! + 0.6);
      g.world.components.Emitter.dirX[slotOf(g.ship)] = 0;
      g.world.components.Emitter.dirY[slotOf(g.ship)] = -1;
      stepBlackHole(g);
      for (const e of query(g.world, [g.world.components.Particle])) {
        if (Math.hypot(P.x[e]! - P.x[slotOf(h)]!, P.y[e]! - P.y[slotOf(h)]!) < g.holeRadius[0]!) inside++;
      }
    }
    expect(inside).toBe(0);
    expect(g.world.components.Emitter.spawned[slotOf(g.ship)]!).toBeGreaterThan(100);
  });

  test('the predicted path is the path the ship then takes with the input held', () => {
    const g = createBlackHoleGame({ seed: 8, holes: 4 });
    const pred = createPredictor(g);
    place(g, 8, 4, 2.5, 3);
    setThrust(g, 'right');
    const out = new Float64Array(2 * 61);
    const n = predictPath(g, pred, out, 60);
    expect(n).toBeGreaterThan(10);
    const P = g.world.components.Position;
    expect([out[0], out[1]]).toEqual([8, 4]);
    for (let i = 1; i < n; i++) {
      expect(stepBlackHole(g)).toBe('none');
      expect(P.x[slotOf(g.ship)]).toBe(out[2 * i]);
      expect(P.y[slotOf(g.ship)]).toBe(out[2 * i + 1]);
    }
    // After a new layout the predictor follows the new holes.
    layoutHoles(g, 6);
    place(g, 8, 4, 2.5, 3);
    const m = predictPath(g, pred, out, 60);
    expect(pred.holes.length).toBe(6);
    for (let i = 1; i < m; i++) {
      stepBlackHole(g);
      expect(P.x[slotOf(g.ship)]).toBe(out[2 * i]);
    }
    expect(() => predictPath(g, pred, out, 0)).toThrow(/steps must be an integer in \[1, 10000\], got 0/);
  });

  test('a predicted tap: the thrust held for thrustSteps steps and then let go is the path the ship takes', () => {
    // A tap's 15 steps (./press-timing.ts TAP_STEPS) of ↑ from rest, then let go: the game step by step
    // against the predictor told the let-go step; and the path held throughout goes farther up.
    const g = createBlackHoleGame({ seed: 8, holes: 4 });
    const pred = createPredictor(g);
    place(g, 8, 4, 0, 0);
    setThrust(g, 'up');
    const out = new Float64Array(2 * 121),
      held = new Float64Array(2 * 121);
    const n = predictPath(g, pred, out, 120, undefined, 15);
    const m = predictPath(g, pred, held, 120);
    expect(n).toBe(121);
    const P = g.world.components.Position;
    for (let i = 1; i < n; i++) {
      if (i === 16) setThrust(g, 'none');
      expect(stepBlackHole(g)).toBe('none');
      expect(P.x[slotOf(g.ship)]).toBe(out[2 * i]);
      expect(P.y[slotOf(g.ship)]).toBe(out[2 * i + 1]);
    }
    // Held for the whole 2 s the ship climbs metres farther than after a tap (which gains about 0.4 m/s).
    expect(held[2 * m - 1]! - out[2 * n - 1]!).toBeGreaterThan(3);
    expect(() => predictPath(g, pred, out, 60, undefined, 1.5)).toThrow(/thrustSteps must be an integer >= 0 or Infinity, got 1.5/);
  });

  test('the prediction stops at a horizon', () => {
    const g = createBlackHoleGame({ seed: 9, holes: 1 });
    const pred = createPredictor(g);
    const P = g.world.components.Position,
      h = g.holes[0]!;
    place(g, P.x[slotOf(h)]! + g.holeRadius[0]! + 1, P.y[slotOf(h)]!, -4, 0);
    const out = new Float64Array(2 * 61);
    const n = predictPath(g, pred, out, 60);
    expect(n).toBeLessThan(30);
    const x = out[2 * (n - 1)]!,
      y = out[2 * (n - 1) + 1]!;
    // Where the ship (SHIP_RADIUS round its centre) touches the horizon.
    expect(Math.hypot(x - P.x[slotOf(h)]!, y - P.y[slotOf(h)]!)).toBeLessThan(g.holeRadius[0]! + SHIP_RADIUS);
  });

  test('a predicted path that leaves the field ends lost, as the game then loses the ship', () => {
    const g = createBlackHoleGame({ seed: 9, holes: 1 });
    const pred = createPredictor(g);
    // Near the left edge, low (holes lie 5 m up or more), moving out.
    place(g, 1, 2.5, -4, 0);
    const out = new Float64Array(2 * 61);
    const n = predictPath(g, pred, out, 60);
    expect(n).toBeLessThan(61);
    expect(pathEnd(g, out, n, 60)).toBe('lost');
    // The game's own rule, step by step: the ship is lost on the path's last step.
    const events: string[] = [];
    for (let i = 1; i < n; i++) events.push(stepBlackHole(g));
    expect(events.at(-1)).toBe('lost');
    expect(events.slice(0, -1).every((e) => e === 'none')).toBe(true);
  });

  test('pathEnd: on a horizon falls, past the line or full length clear, off the field lost', () => {
    const g = createBlackHoleGame({ seed: 9, holes: 1 });
    const pred = createPredictor(g);
    const P = g.world.components.Position,
      h = g.holes[0]!;
    place(g, P.x[slotOf(h)]! + g.holeRadius[0]! + 1, P.y[slotOf(h)]!, -4, 0);
    const out = new Float64Array(2 * 61);
    expect(pathEnd(g, out, predictPath(g, pred, out, 60), 60)).toBe('falls');
    // Hand-made paths (x, y, m) of 3 points asked for 2 steps, on the 32 x 24 field with the line at 22.
    const path = (...xy: number[]) => Float64Array.from(xy);
    expect(pathEnd(g, path(16, 1.5, 16, 2, 16, 2.5), 3, 2)).toBe('clear');
    expect(pathEnd(g, path(31, 3, 31.8, 3, 32.2, 3), 3, 2)).toBe('lost');
    expect(pathEnd(g, path(16, 1, 16, 0.4, 16, -0.1), 3, 2)).toBe('lost');
    // Past the line first, then off the top: the ship scores before it could be lost.
    expect(pathEnd(g, path(16, 21.5, 16, 22.5, 16, 24.5), 3, 2)).toBe('clear');
    expect(() => pathEnd(g, path(16, 1), 2, 1)).toThrow(/pathEnd: n must be an integer in \[1, 1\], got 2/);
  });

  test('bad options are rejected by name', () => {
    expect(() => resolveBlackHoleOptions({ holes: 0 })).toThrow(/holes must be an integer in \[1, 16\], got 0/);
    expect(() => resolveBlackHoleOptions({ c: 1 })).toThrow(/c must be in \[2, 50\] m\/s, got 1/);
    expect(() => resolveBlackHoleOptions({ gravity: 1 } as never)).toThrow(/unknown option "gravity"/);
    const g = createBlackHoleGame();
    expect(() => setGScale(g, 0)).toThrow(/gScale must be in \[0.1, 10\], got 0/);
    expect(() => layoutHoles(g, 17)).toThrow(/count must be an integer in \[1, 16\], got 17/);
  });
});
