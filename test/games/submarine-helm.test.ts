/**
 * The submarine's helm (games/submarine/helm.ts), headless on a calm sea: how soon the boat answers
 * Dive, Rise and Ahead, how deep it gets in a held dive, the depth hold (how far the boat runs on
 * past the depth let go at, and how soon it is back), surfacing and steering by the nose. The
 * bounds are what a player reads as an immediate answer: moving within half a second, metres within
 * two seconds.
 */

import { createPhysicsWorld, type PhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE, SUBMARINE_NEUTRAL_FILL, SUBMARINE_WATER_DENSITY, type SubmarineHandles, submarine } from '@bitphysics/projects';
import { describe, expect, it } from 'vitest';
import { BRAKE_HINT_COURSE, catchesBeacon, LET_GO_SHORT, letGoHint } from '../../games/submarine/beacons';
import {
  coastBrake,
  coastDistance,
  createHelmState,
  HELM,
  type HelmInput,
  type HelmState,
  KEY_HEAVE_FULL_SPEED,
  KEY_HEAVE_SHARE,
  KEY_HEAVE_SHARE_FAST,
  keyHeaveShare,
  NO_INPUT,
  NOSE_RATE,
  NOSE_STEP,
  noseTrim,
  screwPush,
  steer,
  stopping,
} from '../../games/submarine/helm';
import { divePlanes, PLANES, planeLift } from '../../games/submarine/planes';
import { stickShare } from '../../games/submarine/stick';

const DEG = Math.PI / 180;

interface Boat {
  world: PhysicsWorld;
  h: SubmarineHandles;
  helm: HelmState;
}

/** The scene on a calm sea: floating (fill 0) or hovering at `y` with neutral tanks, held there. */
function boat(y?: number): Boat {
  const world = createPhysicsWorld(submarine.worldOptions());
  const h =
    y === undefined
      ? submarine.build(world, { seed: 1, count: 0 })
      : submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, y] });
  world.components.FluidRegion.surface.fill(0);
  // Open water: the seabed out of reach. These cases test the helm alone (no seabed contact is
  // resolved); a held depth is raised over the seabed ahead (helm.ts holdFloor), tested in
  // submarine-seabed.test.ts.
  h.seabed.y.fill(-1000);
  const helm = createHelmState(y === undefined ? 0 : SUBMARINE_NEUTRAL_FILL);
  const b = { world, h, helm };
  run(b, {}, 2); // settle: afloat, or holding the hover depth
  return b;
}

/** Holds `input` for `seconds` (the helm steers before every step). `each` sees every step. */
function run(b: Boat, input: Partial<HelmInput>, seconds: number, each?: (t: number) => void): void {
  const n = Math.round(seconds / b.world.dt);
  for (let i = 1; i <= n; i++) {
    steer(b.world, b.h, { ...NO_INPUT, ...input }, b.helm);
    step(b.world);
    each?.(i * b.world.dt);
  }
}

const y = (b: Boat) => b.world.components.Position.y[b.h.hull]!;
const vy = (b: Boat) => b.world.components.Velocity.y[b.h.hull]!;
const angle = (b: Boat) => b.world.components.Angle.value[b.h.hull]!;

/** Seconds of `input` until the boat moves at 0.2 m/s and until it is 2 m away, in direction `sign` (-1 down). */
function response(b: Boat, input: Partial<HelmInput>, sign: number): { speed: number; twoMetres: number; pitch1deg: number } {
  const y0 = y(b),
    a0 = angle(b);
  const r = { speed: Number.NaN, twoMetres: Number.NaN, pitch1deg: Number.NaN };
  run(b, input, 10, (t) => {
    if (Number.isNaN(r.speed) && sign * vy(b) >= 0.2) r.speed = t;
    if (Number.isNaN(r.twoMetres) && sign * (y(b) - y0) >= 2) r.twoMetres = t;
    if (Number.isNaN(r.pitch1deg) && Math.abs(angle(b) - a0) >= DEG) r.pitch1deg = t;
  });
  return r;
}

describe('submarine helm', () => {
  it('Dive on the surface: sinking at 0.2 m/s within 0.5 s, 2 m down within 2 s, 20 m within 6 s', () => {
    const r = response(boat(), { dive: true }, -1);
    // The bow dips as the fore tank floods first.
    expect(r.speed).toBeLessThan(0.5);
    expect(r.twoMetres).toBeLessThan(2);
    expect(r.pitch1deg).toBeLessThan(1);
    // Held on (10 s in all): at the dive speed, 20 m down well within the 10 s.
    const c = boat();
    const y0 = y(c);
    let twenty = Number.NaN;
    run(c, { dive: true }, 10, (t) => {
      if (Number.isNaN(twenty) && y(c) <= y0 - 20) twenty = t;
    });
    expect(twenty).toBeLessThan(6);
    expect(vy(c)).toBeLessThan(-0.95 * HELM.diveSpeed);
  });

  it('Dive and Rise from a hover at 30 m: 0.2 m/s within 0.4 s, 2 m within 2 s', () => {
    const dive = response(boat(-30), { dive: true }, -1);
    const rise = response(boat(-30), { rise: true }, 1);
    // The thrusters push from the first step.
    for (const r of [dive, rise]) {
      expect(r.speed).toBeLessThan(0.4);
      expect(r.twoMetres).toBeLessThan(2);
      expect(r.pitch1deg).toBeLessThan(1);
    }
  });

  it('Dive and Rise held from a hover reach 70 % of the asked speed within 1.5 s, 10 m within 2.05 s (a full stick push asks the same)', () => {
    // The thrusters (2 x 300 kN on 110 t) and the tanks take the boat to most of the asked speed in
    // about 1.5 s, so a held key answers like the stick pushed to its rim (both ask heave 1). A
    // beacon 15 to 28 m down (the first one) is then a couple of seconds of Dive away.
    for (const [input, speed, sign] of [
      [{ dive: true }, HELM.diveSpeed, -1],
      [{ rise: true }, HELM.climbSpeed, 1],
      [{ dive: true, heave: 1 }, HELM.diveSpeed, -1],
    ] as const) {
      const b = boat(-40);
      const y0 = y(b);
      let ten = Number.NaN;
      run(b, input, 2.5, (t) => {
        if (Math.abs(t - 1.5) < 1e-9) expect(sign * vy(b)).toBeGreaterThan(0.7 * speed);
        if (Number.isNaN(ten) && sign * (y(b) - y0) >= 10) ten = t;
      });
      expect(ten).toBeLessThan(2.05);
    }
  });

  it('at cruise speed on the surface, Dive held until the order reaches a beacon 60 m ahead and 26 m down passes within 7 m of it', () => {
    const b = boat();
    run(b, { ahead: true }, 8);
    const vx = b.world.components.Velocity.x[b.h.hull]!;
    expect(vx).toBeGreaterThan(0.95 * HELM.topSpeed); // cruising at the top speed
    const bx = b.world.components.Position.x[b.h.hull]! + 60,
      by = -26;
    let nearest = Infinity;
    // Ahead held, and Dive until the depth order (the gauge's line) is at the beacon's depth, as the
    // key help says ("let go: stop at the line"), until the boat is 10 m past the beacon; 7 m is
    // the pickup radius of games/submarine/main.ts.
    for (let t = 0; t < 10 && b.world.components.Position.x[b.h.hull]! < bx + 10; t += b.world.dt) {
      const dive = !(b.helm.holdY <= by);
      run(b, { ahead: true, dive }, b.world.dt);
      nearest = Math.min(nearest, Math.hypot(b.world.components.Position.x[b.h.hull]! - bx, y(b) - by));
    }
    expect(nearest).toBeLessThan(7);
  });

  it('Ahead from a hover: 5 m/s within 4 s; let go at full speed, the boat glides 2 to 8 m and stops; Astern stops it shorter', () => {
    // Let go, the screw winds down (HELM.throttleRelease) and the coasting brake (coastBrake) takes
    // over, on top of the drag k v^2: the boat glides a short way (issue 34: gliding 20 to 30 m past
    // every beacon was the strangers' worst complaint; an earlier stranger asked for some glide), never
    // backs, and slows smoothly (never harder than a hit would feel, 1.5 g). Held Astern (the brake),
    // it stops in a shorter distance.
    const b = boat(-30);
    let five = Number.NaN;
    run(b, { ahead: true }, 20, (t) => {
      if (Number.isNaN(five) && b.world.components.Velocity.x[b.h.hull]! >= 5) five = t;
    });
    expect(five).toBeLessThan(4);
    expect(b.helm.throttle).toBe(1);
    const glide = (m: Boat, input: Partial<HelmInput>) => {
      const vx = () => m.world.components.Velocity.x[m.h.hull]!;
      const x0 = m.world.components.Position.x[m.h.hull]!;
      let last = vx(),
        least = last,
        hardest = 0,
        stopped = Number.NaN;
      run(m, input, 5, (t) => {
        hardest = Math.max(hardest, (last - vx()) / m.world.dt);
        last = vx();
        least = Math.min(least, last);
        if (Number.isNaN(stopped) && last < 0.2) stopped = t;
      });
      return { distance: m.world.components.Position.x[m.h.hull]! - x0, least, hardest, stopped };
    };
    expect(b.world.components.Velocity.x[b.h.hull]!).toBeGreaterThan(0.95 * HELM.topSpeed); // full speed
    const free = glide(b, {});
    expect(b.helm.throttle).toBe(0); // the screw never backs on its own
    expect(free.distance).toBeGreaterThan(2); // some glide
    expect(free.distance).toBeLessThan(8); // a player can stop near a beacon
    expect(free.stopped).toBeLessThan(2.5);
    expect(free.least).toBeGreaterThan(-0.05); // never pushed backwards
    expect(free.hardest).toBeLessThan(1.5 * 9.81);
    // Astern held from the same speed: a shorter stop.
    const c = boat(-30);
    run(c, { ahead: true }, 20);
    const astern = glide(c, { astern: true });
    expect(astern.stopped).toBeLessThan(free.stopped);
    expect(astern.distance).toBeLessThan(free.distance - 1);
  });

  it('coastBrake: against the motion along the hull, in proportion below HELM.coastFade, none while the screw pushes at full', () => {
    expect(coastBrake(1e5, 0, 0)).toBeCloseTo(0, 9);
    expect(coastBrake(1e5, 10, 0)).toBeCloseTo(-1e5 * HELM.coastBrake, 6);
    expect(coastBrake(1e5, -10, 0)).toBeCloseTo(1e5 * HELM.coastBrake, 6);
    expect(coastBrake(1e5, HELM.coastFade / 2, 0)).toBeCloseTo((-1e5 * HELM.coastBrake) / 2, 6);
    expect(coastBrake(1e5, 10, 1)).toBeCloseTo(0, 9);
    expect(coastBrake(1e5, 10, -0.5)).toBeCloseTo(-1.5e5 * HELM.coastBrake, 6);
    // Backing: none with the screw at full astern (it must not fight the screw), all of it with the
    // screw stopped (let go, the backing stops too), more with the screw ahead.
    expect(coastBrake(1e5, -10, -HELM.asternShare)).toBeCloseTo(0, 9);
    expect(coastBrake(1e5, -HELM.coastFade / 2, 0)).toBeCloseTo((1e5 * HELM.coastBrake) / 2, 6);
    expect(coastBrake(1e5, -10, 0.25)).toBeCloseTo((1 + 0.25 / HELM.asternShare) * 1e5 * HELM.coastBrake, 6);
    expect(() => coastBrake(0, 1, 0)).toThrow(/coastBrake: mass/);
    expect(() => coastBrake(1e5, Number.NaN, 0)).toThrow(/coastBrake: u/);
    expect(() => coastBrake(1e5, 1, Number.POSITIVE_INFINITY)).toThrow(/coastBrake: throttle/);
  });

  it('screwPush: all of the screw until the asked speed, then the drag k v^2 there; astern the other way; none at zero throttle', () => {
    const m = 1e5,
      k = SUBMARINE.dragCoefficient,
      v = HELM.topSpeed;
    expect(screwPush(m, 0, 1)).toBeCloseTo(SUBMARINE.maxThrust, 6); // from rest: all of it
    expect(screwPush(m, v, 1)).toBeCloseTo(k * v * v, 6); // at the top speed: the drag there
    expect(screwPush(m, v / 2, 0.5)).toBeCloseTo((k * v * v) / 4, 6);
    expect(screwPush(m, 2 * v, 1)).toBe(0); // too fast: no push, never a pull
    expect(screwPush(m, 0, -0.5)).toBeCloseTo(-0.5 * SUBMARINE.maxThrust, 6);
    expect(screwPush(m, -v / 2, -0.5)).toBeCloseTo((-k * v * v) / 4, 6);
    expect(screwPush(m, 3, 0)).toBe(0);
    // Diving at 6 m/s the hull drags k |v| v_x ahead; pitched 10 degrees the push along it is 1 / cos more.
    expect(screwPush(m, v, 1, -6)).toBeCloseTo(k * v * Math.hypot(v, 6), 6);
    expect(screwPush(m, v / 2, 0.5, 0, -10 * DEG)).toBeCloseTo((k * v * v) / 4 / Math.cos(10 * DEG), 6);
    expect(() => screwPush(m, 0, 1, Number.NaN)).toThrow(/screwPush: vy/);
    expect(() => screwPush(-1, 0, 1)).toThrow(/screwPush: mass/);
    expect(() => screwPush(m, Number.NaN, 1)).toThrow(/screwPush: u/);
    expect(() => screwPush(m, 0, Number.NaN)).toThrow(/screwPush: throttle/);
  });

  it('1.5 s of full ahead and Dive from the surface, then let go: never over the top speed, stopped within 12 m; Astern from full ahead stops within 5 m', () => {
    // A stranger held full ahead and Dive for 1.5 s toward the first beacon and passed it by 231 m at
    // 12.9 m/s. The boat now tops out at HELM.topSpeed (8 m/s, 15.5 knots) and glides a short way.
    const b = boat();
    const c = b.world.components,
      e = b.h.hull;
    let fastest = 0;
    run(b, { ahead: true, dive: true }, 1.5, () => {
      fastest = Math.max(fastest, c.Velocity.x[e]!);
    });
    const x0 = c.Position.x[e]!;
    run(b, {}, 6, () => {
      fastest = Math.max(fastest, c.Velocity.x[e]!);
    });
    expect(fastest).toBeLessThan(HELM.topSpeed);
    expect(c.Position.x[e]! - x0).toBeLessThan(12);
    expect(Math.abs(c.Velocity.x[e]!)).toBeLessThan(0.1);
    // Full ahead until the speed is steady (within 5 % of the top speed), then Astern: the brake.
    run(b, { ahead: true }, 10);
    expect(c.Velocity.x[e]!).toBeGreaterThan(0.95 * HELM.topSpeed);
    expect(c.Velocity.x[e]!).toBeLessThan(1.05 * HELM.topSpeed);
    const x1 = c.Position.x[e]!;
    let stopped = Number.NaN;
    run(b, { astern: true }, 3, (t) => {
      if (Number.isNaN(stopped) && c.Velocity.x[e]! <= 0) stopped = t;
    });
    expect(stopped).toBeLessThan(1.2);
    expect(c.Position.x[e]! - x1).toBeLessThan(5);
  });

  it('keepThrottle (the stick pushed up or down only): the screw keeps its throttle under way while the boat rises; without it the screw stops', () => {
    const b = boat(-40);
    run(b, { ahead: true }, 6);
    run(b, { rise: true, keepThrottle: true }, 2);
    expect(b.helm.throttle).toBe(1);
    // Under way still (measured 6.8 m/s along x: the hull climbs pitched up, part of its speed upward).
    expect(b.world.components.Velocity.x[b.h.hull]!).toBeGreaterThan(0.75 * HELM.topSpeed);
    run(b, { rise: true }, 2);
    expect(b.helm.throttle).toBe(0);
    expect(b.world.components.Velocity.x[b.h.hull]!).toBeLessThan(0.5);
  });

  it('Astern from a hover backs the boat: 3 m/s within 2.5 s, 25 m within 10 s; let go, it stops within 8 m', () => {
    // The boat always faces ahead, so backing is how a player recovers a beacon overshot (a
    // stranger backed at 0.2 m/s when the coasting brake fought the screw: 3 m in 18 s).
    const b = boat(-30);
    const x = () => b.world.components.Position.x[b.h.hull]!,
      vx = () => b.world.components.Velocity.x[b.h.hull]!;
    const x0 = x();
    let three = Number.NaN;
    run(b, { astern: true }, 10, (t) => {
      if (Number.isNaN(three) && vx() <= -3) three = t;
    });
    expect(three).toBeLessThan(2.5);
    expect(x0 - x()).toBeGreaterThan(25);
    const x1 = x();
    run(b, {}, 5);
    expect(Math.abs(vx())).toBeLessThan(0.2);
    expect(x1 - x()).toBeLessThan(8);
    expect(x1 - x()).toBeGreaterThan(0); // it glides on backwards, never lurches ahead
  });

  it('Rise while diving at full speed turns the boat up within 4.5 s', () => {
    const b = boat(-80);
    run(b, { dive: true }, 7);
    expect(vy(b)).toBeLessThan(-0.9 * HELM.diveSpeed); // at speed
    const r = response(b, { rise: true }, 1);
    // The momentum of 110 t at 10 m/s against 600 kN of thrusters, the drag k v^2 and the water
    // blown out of the tanks: a few seconds to turn (honest: no instant stop). The bow comes up 1
    // degree within a second.
    expect(r.speed).toBeLessThan(4.5);
    expect(r.pitch1deg).toBeLessThan(1);
  });

  it('let go under water, the helm brakes and holds the depth with the tanks at neutral', () => {
    const b = boat(-30);
    run(b, { dive: true }, 3);
    run(b, {}, 8);
    expect(b.helm.mode).toBe('holding');
    const held = y(b);
    let drift = 0;
    run(b, {}, 20, () => {
      drift = Math.max(drift, Math.abs(y(b) - held));
    });
    // Tanks at neutral: by Archimedes there is nothing left for the thrusters to hold.
    expect(drift).toBeLessThan(0.3);
    const B = b.world.components.Ballast;
    expect(Math.abs(B.fore[b.h.hull]! - SUBMARINE_NEUTRAL_FILL)).toBeLessThan(0.01);
    expect(Math.abs(B.aft[b.h.hull]! - SUBMARINE_NEUTRAL_FILL)).toBeLessThan(0.01);
    expect(Math.abs(b.helm.fore) + Math.abs(b.helm.aft)).toBeLessThan(0.05 * SUBMARINE.thrusterForce);
  });

  it('full Dive: 0.5 m down within 0.47 s (0.42 s under way); let go at full speed, the boat stops on the depth order', () => {
    // The time from a full Dive to 0.5 m of depth change, and how far the boat passes the depth it
    // ends at once let go at the full 10 m/s, from a hover at 60 m and under way (8 s of full ahead,
    // 12.6 m/s). Measured before the depth order and the dive planes: 0.43 s and 0.45 s; let go, it
    // ran on 3.7 m (3.5 m under way) past the depth it was let go at and took 6 s to climb back to
    // it. Now: 0.43 s (the 600 kN of thrusters on 110 t: 5.5 m/s^2 at most) and 0.38 s (the planes
    // add up to 470 kN at speed); let go at 7 m/s, it ran on 4.3 m (3.3 m under way) to the order,
    // at 10 m/s 8.8 m (6.8 m), the order going down at the dive speed from the first step and kept the boat's stopping distance ahead, passes it
    // by 0.00 m and is within 0.2 m of it 1.2 s (1.1 s) after. Bounds: 10% over the times, 0.2 m.
    for (const ahead of [false, true]) {
      const b = boat(-60);
      if (ahead) run(b, { ahead }, 8);
      const y0 = y(b);
      let half = Number.NaN,
        lead = Number.NaN;
      run(b, { dive: true, ahead }, 3, (t) => {
        if (Number.isNaN(lead)) lead = y(b) - b.helm.holdY;
        if (Number.isNaN(half) && y0 - y(b) >= 0.5) half = t;
      });
      expect(lead).toBeGreaterThan(0.9 * HELM.diveSpeed * b.world.dt); // the order answers at the first step
      expect(half).toBeLessThan(ahead ? 0.42 : 0.47);
      expect(vy(b)).toBeLessThan(-0.95 * HELM.diveSpeed);
      const order = b.helm.holdY;
      // Ahead of the boat by its stopping distance, up to HELM.orderLead more (less the step the
      // boat has made since the helm set it, and the speed gained meanwhile). Under way the helm
      // brakes harder by its share of the planes' lift at full angle.
      const step = HELM.diveSpeed * b.world.dt;
      const u = b.world.components.Velocity.x[b.h.hull]!;
      const brake = HELM.brake + (HELM.planesShare * planeLift(PLANES.maxAngle, u, 1)) / b.world.components.Mass.value[b.h.hull]!;
      expect(y(b) - order).toBeGreaterThanOrEqual(stopping(vy(b), brake) - 1.5 * step);
      expect(y(b) - order).toBeLessThanOrEqual(stopping(vy(b)) + HELM.orderLead);
      let past = 0,
        settled = Number.NaN;
      run(b, { ahead }, 6, (t) => {
        past = Math.max(past, order - y(b));
        if (Math.abs(y(b) - order) > 0.2) settled = Number.NaN;
        else if (Number.isNaN(settled)) settled = t;
      });
      expect(b.helm.mode).toBe('holding');
      expect(b.helm.holdY).toBe(order); // the gauge's order stays where it was let go
      expect(past).toBeLessThan(0.2);
      expect(settled).toBeLessThan(2);
    }
  });

  it('Rise to the surface comes up gently, blows the tanks and floats at the draft rho L d = m', () => {
    const b = boat(-20);
    let top = -Infinity;
    run(b, { rise: true }, 15, () => {
      top = Math.max(top, y(b));
    });
    let sum = 0,
      count = 0;
    run(b, {}, 20, (t) => {
      top = Math.max(top, y(b));
      if (t > 11) {
        sum += y(b);
        count++;
      }
    });
    expect(b.helm.mode).toBe('surfaced');
    const B = b.world.components.Ballast;
    expect(B.fore[b.h.hull]).toBe(0);
    expect(B.aft[b.h.hull]).toBe(0);
    // Floating empty: the draft d = m / (rho L) puts the centre at H/2 - d (Archimedes, 2D box). The
    // hull still heaves +-0.13 m with a 3 s period (the scene's quadratic drag hardly damps it), so
    // the mean over the last 9 s (three periods, error under 0.02 m) is compared.
    const float = SUBMARINE.height / 2 - SUBMARINE.dryMass / (SUBMARINE_WATER_DENSITY * SUBMARINE.length);
    expect(Math.abs(sum / count - float)).toBeLessThan(0.05);
    // No leap out of the water on the way up (blowing at depth took the old boat up at up to 9 m/s).
    expect(top - float).toBeLessThan(0.5);
  });

  it('Nose down with the screw ahead pitches 10 degrees within 2 s and takes the boat down without Dive', () => {
    const b = boat(-30);
    let tilted = Number.NaN;
    run(b, { noseDown: true, ahead: true }, 8, (t) => {
      if (Number.isNaN(tilted) && angle(b) < -10 * DEG) tilted = t;
    });
    expect(tilted).toBeLessThan(2);
    expect(b.helm.mode).toBe('steering');
    expect(y(b)).toBeLessThan(-32); // the screw pushes along the tilted hull
    // Let go: the hull levels out and the depth is held again.
    run(b, { ahead: true }, 6);
    expect(Math.abs(angle(b))).toBeLessThan(DEG);
    expect(b.helm.mode).toBe('holding');
  });
});

describe('submarine helm, the stick pushed part way', () => {
  it('every Nose tap turns the boat 5 degrees more and it stays so; under way it follows its nose down; Dive levels it (issue 34)', () => {
    // A stranger tapped Nose and saw nothing: a 0.1 s press held the nose only while pressed and
    // turned the boat 1.1 degrees before it levelled. Now each press steps the trim (noseTrim) and
    // the helm holds it. Tolerance: within 1 degree of the trim after 3 s (the pitch loop settles).
    expect(noseTrim(0, -1, 0, 1 / 60)).toBeCloseTo(-NOSE_STEP, 12);
    expect(noseTrim(-NOSE_STEP, -1, 0, 1 / 60)).toBeCloseTo(-2 * NOSE_STEP, 12);
    expect(noseTrim(-2 * NOSE_STEP, -1, -1, 10)).toBe(-HELM.noseAngle);
    // A tap the other way levels a trim of a step or less, never tilting past level.
    expect(noseTrim(-0.5 * NOSE_STEP, 1, 0, 1 / 60)).toBe(0);
    expect(noseTrim(0, 0, 1, 0.5)).toBeCloseTo(0.5 * NOSE_RATE, 12);
    expect(() => noseTrim(Number.NaN, 0, 0, 0.1)).toThrow(/noseTrim: trim/);
    const b = boat(-40);
    const one = noseTrim(0, -1, 0, b.world.dt);
    run(b, { nose: one }, 3);
    expect(Math.abs(angle(b) - one) / DEG).toBeLessThan(1);
    const two = noseTrim(one, -1, 0, b.world.dt);
    run(b, { nose: two }, 3);
    expect(Math.abs(angle(b) - two) / DEG).toBeLessThan(1);
    // Under way at 10 degrees nose down the boat goes down (8 m/s x sin 10 deg = 1.4 m/s): over 3 m in 4 s.
    const y0 = y(b);
    run(b, { nose: two, ahead: true }, 4);
    console.log(`two Nose taps: pitch ${(angle(b) / DEG).toFixed(1)} deg; 4 s ahead: ${(y0 - y(b)).toFixed(1)} m down`);
    expect(y0 - y(b)).toBeGreaterThan(3);
  });

  it('the stick pushed 45 degrees (ahead and down) makes 95 % of the speed ahead it asks for while it dives', () => {
    // Issue 34: a stranger's diagonal push dived but made 4.3 to 4.6 m/s ahead of the 5.24 asked:
    // the screw's governor held the speed along the bow-down hull (vx cos + vy sin), which the dive
    // fed. It now holds the speed ahead through the water. Measured after 4 s from a hover at 30 m:
    // 4.55 m/s before, 5.20 m/s now (5.23 at 6 s); the dive 6.5 m/s either way. Bound 95 %: the
    // governor's proportional term leaves a few per cent to the diving hull's extra drag.
    const s = stickShare(Math.SQRT1_2, false);
    const b = boat(-30);
    const c = b.world.components,
      e = b.h.hull;
    run(b, { dive: true, ahead: true, drive: s, heave: s }, 4);
    expect(c.Velocity.x[e]!).toBeGreaterThan(0.95 * s * HELM.topSpeed);
    expect(c.Velocity.x[e]!).toBeLessThan(1.02 * s * HELM.topSpeed);
    expect(vy(b)).toBeLessThan(-0.95 * s * HELM.diveSpeed);
  });

  it('a third of the way down asks for part of the dive speed; half ahead runs the screw to half', () => {
    // The stick's share (games/submarine/main.ts) of 0.3 asks for 0.3 x 7 = 2.1 m/s; a key asks for 7.
    const b = boat(-40);
    run(b, { dive: true, heave: 0.3 }, 6);
    expect(vy(b)).toBeGreaterThan(-0.3 * HELM.diveSpeed * 1.15);
    expect(vy(b)).toBeLessThan(-0.3 * HELM.diveSpeed * 0.85);
    const r = boat(-40);
    run(r, { rise: true, heave: 0.5 }, 6);
    expect(Math.abs(vy(r) - 0.5 * HELM.climbSpeed)).toBeLessThan(0.15 * 0.5 * HELM.climbSpeed);
    // Half ahead: the throttle climbs to 0.5 and stays; eased back to 0.2, it winds down to it.
    const d = boat(-40);
    run(d, { ahead: true, drive: 0.5 }, 2);
    expect(d.helm.throttle).toBe(0.5);
    run(d, { ahead: true, drive: 0.2 }, 1);
    expect(d.helm.throttle).toBeCloseTo(0.2, 9);
    // Astern from half ahead falls at the full throttle rate (2.5 / s): to full astern (-HELM.asternShare) within 0.5 s.
    run(d, { astern: true }, 0.5);
    expect(d.helm.throttle).toBe(-HELM.asternShare);
  });
});

describe('submarine depth keys', () => {
  it('under way a held Dive key asks for more: from the rest share at rest to all of it at full speed, so 1.5 s of Dive at full ahead goes over 6 m down, 1 m down for 2 ahead', () => {
    expect(keyHeaveShare(0, 0, 0)).toBe(KEY_HEAVE_SHARE);
    expect(keyHeaveShare(0, 0, KEY_HEAVE_FULL_SPEED)).toBe(KEY_HEAVE_SHARE_FAST);
    expect(keyHeaveShare(0, 0, 2 * KEY_HEAVE_FULL_SPEED)).toBe(KEY_HEAVE_SHARE_FAST);
    // In proportion to the speed, ahead or astern alike.
    expect(keyHeaveShare(0, 0, -KEY_HEAVE_FULL_SPEED / 2)).toBeCloseTo((KEY_HEAVE_SHARE + KEY_HEAVE_SHARE_FAST) / 2, 12);
    expect(() => keyHeaveShare(0, 0, Number.NaN)).toThrow(/keyHeaveShare: u must be finite/);
    // The real helm and physics: full ahead at 31 m for 15 s, then Dive held as the page's key does
    // (at the boat's speed) for 1.5 s. Measured: 6.6 m down while 12 m ahead (at the earlier top
    // speed of 12.9 m/s, 7.6 m down while 19 m ahead, a dive a stranger found slow to answer).
    const b = boat(-31);
    run(b, { ahead: true }, 15);
    const y0 = y(b),
      x0 = b.world.components.Position.x[b.h.hull]!;
    let half = 0;
    const c = b.world.components,
      e = b.h.hull;
    for (let i = 1; i <= Math.round(1.5 / b.world.dt); i++) {
      steer(b.world, b.h, { ...NO_INPUT, ahead: true, dive: true, heave: keyHeaveShare(0, 0, c.Velocity.x[e]!) }, b.helm);
      step(b.world);
      if (i === Math.round(0.5 / b.world.dt)) half = y0 - y(b);
    }
    expect(y0 - y(b)).toBeGreaterThan(6);
    expect((y0 - y(b)) / (b.world.components.Position.x[b.h.hull]! - x0)).toBeGreaterThan(0.5);
    expect(half).toBeGreaterThan(0.7);
    // The bow shows the dive: pitched down further than the rest's HELM.diveAngle (measured 6.4
    // degrees, on its way to 9.9 at this speed).
    expect(angle(b)).toBeLessThan(-1.2 * HELM.diveAngle);
  });

  it('a held Dive key gives a depth that grows steadily with the time held; a 0.25 s tap moves the boat a visible half metre or more', () => {
    expect(keyHeaveShare(3, 3)).toBe(KEY_HEAVE_SHARE);
    expect(keyHeaveShare(3, 10)).toBe(KEY_HEAVE_SHARE);
    expect(() => keyHeaveShare(Number.NaN, 1)).toThrow(/keyHeaveShare: since/);
    // The real helm and physics, hovering at 40 m: hold Dive as the page's key does for `held` s,
    // let go, and let the boat stop on its order. How far it went down, m.
    const dive = (held: number): number => {
      const b = boat(-40);
      const y0 = y(b);
      let t = 0;
      const n = Math.round(held / b.world.dt);
      for (let i = 0; i < n; i++, t += b.world.dt) {
        steer(b.world, b.h, { ...NO_INPUT, dive: true, heave: keyHeaveShare(0, t) }, b.helm);
        step(b.world);
      }
      run(b, {}, 6);
      return y0 - y(b);
    };
    const holds = [1, 2, 3, 4],
      depths = holds.map(dive);
    // Measured: 4.6, 9.8, 14.8, 19.8 m (at 6 m/s, 5.0, 11.7, 17.7, 23.7; a key that ramped up from a
    // tenth gave 2.9, 10.5, 22.3, 33.0).
    // Monotone, and each further second adds about the same depth: within 25% of the mean rate
    // (the ramped key's seconds added 7.6, 11.8, 10.7 m; the first one 2.9).
    for (let i = 1; i < depths.length; i++) expect(depths[i]!).toBeGreaterThan(depths[i - 1]!);
    const rate = (depths[3]! - depths[0]!) / 3;
    for (let i = 0; i < depths.length; i++) {
      const step = i === 0 ? depths[0]! : depths[i]! - depths[i - 1]!;
      expect(Math.abs(step - rate)).toBeLessThan(0.25 * rate);
    }
    // The depth is about proportional to the time held: 1 s gives over a fifth of 4 s.
    expect(depths[0]!).toBeGreaterThan(0.18 * depths[3]!);
    const tap = dive(0.25);
    expect(tap).toBeGreaterThan(0.5);
    expect(tap).toBeLessThan(1.5);
  });

  it('a held Dive key at rest is brisk and stops where the gauge said: 90 % of its speed within 1 s; let go, on 2.6 m at most, stopped within 1.25 s', () => {
    // Issue 34: a stranger found the key's dive at rest sluggish and then overshooting. Hovering at
    // 40 m, Dive held 3 s as the page's key does, then let go. Measured with the key asking 6 m/s
    // (KEY_HEAVE_SHARE 0.6): 90 % of it after 1.05 s; let go, 3.2 m further down, stopped (under
    // 0.1 m/s) 1.43 s later. Asking 5 m/s: 0.88 s, 2.2 m, 1.08 s (the thrusters' 5.5 m/s^2 reach a
    // lower speed sooner and brake from it in less: v^2 / 2a). Bounds about 15 % over the measures.
    const b = boat(-40);
    const y0 = y(b),
      share = keyHeaveShare(0, 0);
    let fast = Number.NaN;
    run(b, { dive: true, heave: share }, 3, (t) => {
      if (Number.isNaN(fast) && -vy(b) >= 0.9 * share * HELM.diveSpeed) fast = t;
    });
    const letGo = y(b),
      order = b.helm.holdY;
    let stopped = Number.NaN,
      deepest = letGo;
    run(b, {}, 6, (t) => {
      deepest = Math.min(deepest, y(b));
      if (Number.isNaN(stopped) && Math.abs(vy(b)) < 0.1) stopped = t;
    });
    expect(fast).toBeLessThan(1);
    expect(letGo - deepest).toBeLessThan(2.6);
    expect(stopped).toBeLessThan(1.25);
    // Where the gauge's order said, within 0.2 m, and never past it by more.
    expect(Math.abs(y(b) - order)).toBeLessThan(0.2);
    expect(order - deepest).toBeLessThan(0.2);
    expect(y0 - y(b)).toBeGreaterThan(13); // 3 s of Dive still goes a good way down (measured 14.8 m)
  });
});

describe('submarine dive planes', () => {
  it('at 10 degrees and 10 m/s ahead they lift the hull by 1/2 rho A a delta u^2 (112 kN); at rest by nothing', () => {
    // Two boats alike, hovering level at 30 m and moving ahead at u, one with its planes at 10
    // degrees: the difference of their climb after one step is the lift times dt / m. The lift by
    // thin-aerofoil theory with the aspect-ratio correction: 1/2 x 1025 kg/m^3 x 4 m^2 x
    // (2 pi 2 / (2 + 2)) / rad x 0.1745 rad x (10 m/s)^2 = 112.4 kN. Tolerance 1%.
    for (const [u, expected] of [
      [10, 0.5 * 1025 * 4 * ((2 * Math.PI * 2) / 4) * 10 * DEG * 100],
      [0, 0],
    ] as const) {
      const climb = [0, 10 * DEG].map((delta) => {
        const world = createPhysicsWorld(submarine.worldOptions());
        const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [0, -30] });
        world.components.FluidRegion.surface.fill(0);
        world.components.Velocity.x[h.hull] = u;
        divePlanes(world, h)[0] = delta;
        step(world);
        return { vy: world.components.Velocity.y[h.hull]!, m: world.components.Mass.value[h.hull]!, dt: world.dt };
      });
      const lift = ((climb[1]!.vy - climb[0]!.vy) * climb[0]!.m) / climb[0]!.dt;
      expect(Math.abs(lift - expected)).toBeLessThanOrEqual(0.01 * expected);
    }
  });

  it('coastDistance: the glide the sea and the helm give, within 0.5 m, let go at 3 to 8 m/s', () => {
    // The physics world (the scene's buoyancy, drag and the helm's brake, stepped in full) against
    // the model stepped alone.
    for (const drive of [0.4, 0.7, 1]) {
      const b = boat(-30);
      run(b, { ahead: true, drive }, 15);
      const c = b.world.components,
        e = b.h.hull;
      const predicted = coastDistance(c.Mass.value[e]!, c.Velocity.x[e]!, b.helm.throttle, b.world.dt);
      const x0 = c.Position.x[e]!;
      run(b, {}, 8);
      const glide = c.Position.x[e]! - x0;
      expect(Math.abs(glide - predicted), `drive ${drive}: glide ${glide} m, predicted ${predicted} m`).toBeLessThan(0.5);
    }
    expect(coastDistance(1e5, 0, 0)).toBe(0);
    expect(() => coastDistance(0, 1, 0)).toThrow(/coastDistance: mass/);
    expect(() => coastDistance(1e5, Number.NaN, 0)).toThrow(/coastDistance: u/);
  });

  it('the brake hint\'s "let go now" stops the boat within 3 m of its aim (the bow on the beacon) and collects it, from a hover 25 to 90 m short', () => {
    // Issue 34: told "let go early" at 30 m, a stranger stopped 24 m short. Here Ahead is held until
    // the hint says "let go now" (./beacons.ts letGoHint), then let go; the beacon lies level ahead.
    for (const [short, drive] of [
      [25, 1],
      [50, 1],
      [90, 1],
      [60, 0.6],
    ] as const) {
      const b = boat(-30);
      const c = b.world.components,
        e = b.h.hull;
      const bx = c.Position.x[e]! + short,
        by = c.Position.y[e]!;
      let released = Number.NaN;
      for (let i = 0; i < 60 * 40 && Number.isNaN(released); i++) {
        const words = letGoHint(bx - c.Position.x[e]!, coastDistance(c.Mass.value[e]!, c.Velocity.x[e]!, b.helm.throttle, b.world.dt));
        if (words === 'let go now') released = c.Position.x[e]!;
        else run(b, { ahead: true, drive }, b.world.dt);
      }
      expect(released, `${short} m`).toBeLessThan(bx);
      run(b, {}, 8);
      const x = c.Position.x[e]!;
      expect(Math.abs(bx - LET_GO_SHORT - x), `${short} m at drive ${drive}: stopped at ${bx - x} m short`).toBeLessThan(3);
      expect(catchesBeacon(x, c.Position.y[e]!, c.Angle.value[e]!, bx, by)).toBe(true);
    }
  });

  it('"let go at N m ahead": let go when the label\'s figure reads N, the boat stops within 3 m of its aim and collects the beacon, at 3 to 8 m/s', () => {
    // Issue 34: the label read "target B: 33 m ahead / let go in 21 m"; the stranger let go at
    // "21 m ahead" (12 m on) and stopped 16 m short. Now the hint names the label's own figure. The
    // player reads N once, 38 m short (the hint's range is 40 m), holds Ahead until the label's
    // figure (the level distance, rounded as the page shows it) reads N, then lets go. Tolerance
    // 3 m, as for "let go now": N is where "let go now" comes on, up to LET_GO_EARLY (2 m) short of
    // the aim, plus half a metre of the figure's rounding and the glide model's 0.5 m.
    const report: string[] = [];
    for (const drive of [0.4, 0.7, 1]) {
      const b = boat(-30);
      const c = b.world.components,
        e = b.h.hull;
      run(b, { ahead: true, drive }, 10);
      const bx = c.Position.x[e]! + 45,
        by = c.Position.y[e]!;
      let n = Number.NaN,
        oldN = Number.NaN;
      while (Number.isNaN(n)) {
        const along = bx - c.Position.x[e]!;
        if (along < 38) {
          const coast = coastDistance(c.Mass.value[e]!, c.Velocity.x[e]!, b.helm.throttle, b.world.dt);
          const m = /^let go at (\d+) m ahead$/.exec(letGoHint(along, coast));
          expect(m, `drive ${drive}`).not.toBeNull();
          n = Number(m![1]);
          // The old words, "let go in M m" (metres still to go), read as the label's figure.
          oldN = Math.ceil(along - LET_GO_SHORT - coast - 2);
        } else run(b, { ahead: true, drive }, b.world.dt);
      }
      const speed = c.Velocity.x[e]!;
      const glide = (at: number) => {
        const world = createPhysicsWorld(submarine.worldOptions());
        const h = submarine.build(world, { seed: 1, count: 0, fill: SUBMARINE_NEUTRAL_FILL, position: [c.Position.x[e]!, by] });
        world.components.FluidRegion.surface.fill(0);
        h.seabed.y.fill(-1000);
        const twin = { world, h, helm: { ...b.helm } };
        world.components.Velocity.x[h.hull] = speed;
        while (Math.round(bx - world.components.Position.x[h.hull]!) > at) run(twin, { ahead: true, drive }, world.dt);
        run(twin, {}, 8);
        const x = world.components.Position.x[h.hull]!;
        return {
          short: bx - LET_GO_SHORT - x,
          caught: catchesBeacon(x, world.components.Position.y[h.hull]!, world.components.Angle.value[h.hull]!, bx, by),
        };
      };
      const now = glide(n),
        before = glide(oldN);
      report.push(
        `${speed.toFixed(1)} m/s: let go at ${n} m ahead, stopped ${now.short.toFixed(1)} m short of the aim ` +
          `(old "let go in ${oldN} m" read as the figure: ${before.short.toFixed(1)} m short, caught ${before.caught})`,
      );
      expect(Math.abs(now.short), report.at(-1)).toBeLessThan(3);
      expect(now.caught, report.at(-1)).toBe(true);
    }
    console.log(report.join('\n'));
  });

  it('a let-go at the hint\'s "N m ahead" ends with the hull in the ring for a beacon up to BRAKE_HINT_COURSE above or below the course', async () => {
    // Issue 34: the hint was given on courses up to 12 m off the beacon and aimed the bow on it; a
    // boat passing 10 m above or below stopped 13 m from the beacon's centre, its hull 0.8 m outside
    // the ring. The boat holds its depth, Ahead at `drive`, lets go when the label's figure (the level
    // distance, rounded) reads N, and glides to a stop; any touch of the ring on the way collects.
    // Tolerance: none on the catch; the stop's hull distance (from the ring's 8 m) is reported.
    const report: string[] = [];
    expect(BRAKE_HINT_COURSE).toBeGreaterThan(8);
    for (const [off, drive] of [
      [BRAKE_HINT_COURSE - 0.1, 1],
      [-(BRAKE_HINT_COURSE - 0.1), 1],
      [-(BRAKE_HINT_COURSE - 0.1), 0.6],
      [6, 0.4],
    ] as const) {
      const b = boat(-30);
      const c = b.world.components,
        e = b.h.hull;
      run(b, { ahead: true, drive }, 10);
      const bx = c.Position.x[e]! + 45,
        by = c.Position.y[e]! + off;
      let n = Number.NaN,
        caught = false;
      const touch = () => {
        if (catchesBeacon(c.Position.x[e]!, c.Position.y[e]!, c.Angle.value[e]!, bx, by)) caught = true;
      };
      while (Number.isNaN(n) || Math.round(bx - c.Position.x[e]!) > n) {
        const coast = coastDistance(c.Mass.value[e]!, c.Velocity.x[e]!, b.helm.throttle, b.world.dt);
        const m = /^let go at (\d+) m ahead$/.exec(letGoHint(bx - c.Position.x[e]!, coast));
        if (m) n = Number(m[1]);
        expect(bx - c.Position.x[e]!, `off ${off}: no hint`).toBeGreaterThan(0);
        run(b, { ahead: true, drive }, b.world.dt, touch);
      }
      run(b, {}, 8, touch);
      const d = Math.hypot(bx - c.Position.x[e]!, by - c.Position.y[e]!);
      report.push(
        `off ${off.toFixed(1)} m at drive ${drive}: let go at ${n} m ahead, stopped ${d.toFixed(1)} m from the beacon, caught ${caught}`,
      );
      expect(caught, report.at(-1)).toBe(true);
    }
    console.log(report.join('\n'));
  });
});
