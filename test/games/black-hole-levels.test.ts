/**
 * Black hole's levels without a page (games/black-hole/levels.ts): level 1 is practice (a fall costs
 * no life) with one small hole across the straight path up, no thrust held from the start clears a level, levels 2 and 3 put a wall of holes across the field with one gap off to the side (the
 * second lower, pulling harder, with a hole above its gap), later levels grow harder one step at a time (more and
 * bigger holes, slow drift, less fuel), every level can be won by a steering pilot, drifting holes move
 * at their speed and keep r = 2 G M / c^2, fuel runs out, and clearing a level gives a lost life back
 * and a summary and lays out the next one.
 */

import { setEmitterEnabled, setPosition, slotOf } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import {
  BONUS_SECONDS,
  beginLevel,
  canThrust,
  heldFlight,
  heldThrustClears,
  type LevelRun,
  levelPoints,
  levelSpec,
  POINTS_PER_LEVEL,
  padThrust,
  startLevel,
  stepLevel,
  WALL_GAP,
  WALL_GATE_SHARE,
} from '../../games/black-hole/levels';
import { TAP_STEPS } from '../../games/black-hole/press-timing';
import {
  type BlackHoleGame,
  createBlackHoleGame,
  createPredictor,
  FIELD,
  gravitationalConstant,
  LINE_Y,
  MAX_FIELD_HOLES,
  predictPath,
  START,
  setThrust,
  THRUST_DIRECTION,
  type Thrust,
} from '../../games/black-hole/rules';

const shipY = (g: BlackHoleGame) => g.world.components.Position.y[slotOf(g.ship)]!;

/**
 * Plays `run` with the input `thrustAt(step)` for at most `seconds`; stops at a clear or game over.
 * @returns the steps taken and the last event.
 */
/**
 * The holes' pull on the ship waiting at the start, m/s^2: summed from their masses and places
 * (G M / d^2 each, towards the hole), not taken from the game's step.
 */
function pullAtStart(g: BlackHoleGame): number {
  const P = g.world.components.Position,
    G = gravitationalConstant(g);
  let ax = 0,
    ay = 0;
  g.holes.forEach((h, i) => {
    const dx = P.x[slotOf(h)]! - g.start[0],
      dy = P.y[slotOf(h)]! - g.start[1],
      d = Math.hypot(dx, dy);
    ax += (G * g.holeMass[i]! * dx) / d ** 3;
    ay += (G * g.holeMass[i]! * dy) / d ** 3;
  });
  return Math.hypot(ax, ay);
}

function play(g: BlackHoleGame, run: LevelRun, thrustAt: (k: number) => boolean, seconds: number) {
  const steps = Math.round(seconds / g.world.dt);
  for (let k = 0; k < steps; k++) {
    const want = thrustAt(k) && canThrust(g, run) ? 'up' : 'none';
    if (g.thrust !== want) setThrust(g, want);
    const e = stepLevel(g, run);
    if (e === 'cleared' || e === 'over') return { steps: k + 1, event: e };
  }
  return { steps, event: 'timeout' as const };
}

/**
 * The gap of a wall level, found from the holes alone: the widest clear stretch (m) between
 * neighbouring horizons of the lowest row of holes (those within 1 m of the lowest centre) or between
 * a horizon and a field's edge; its centre x and the row's height, m. `others` is the widest of the
 * other stretches.
 */
function wallGap(g: BlackHoleGame): { x: number; y: number; width: number; others: number; edge: number } {
  const P = g.world.components.Position;
  const hs = g.holes.map((h, i) => ({ x: P.x[slotOf(h)]!, y: P.y[slotOf(h)]!, r: g.holeRadius[i]! }));
  const y = Math.min(...hs.map((h) => h.y));
  const row = hs.filter((h) => h.y < y + 1).sort((a, b) => a.x - b.x);
  const stretches: [number, number][] = [];
  let lo = 0;
  for (const h of row) {
    stretches.push([lo, h.x - h.r]);
    lo = h.x + h.r;
  }
  stretches.push([lo, g.field.width]);
  stretches.sort((a, b) => b[1] - b[0] - (a[1] - a[0]));
  const [l, r] = stretches[0]!;
  const x0 = g.start[0];
  return {
    x: (l + r) / 2,
    y,
    width: r - l,
    others: stretches[1]![1] - stretches[1]![0],
    edge: Math.min(Math.abs(l - x0), Math.abs(r - x0)),
  };
}

/**
 * The arrow or pair (of the eight) that best points a push on the distance to `at` (m) braked on the
 * velocity (2 x distance - 2.5 x velocity, m/s^2) from a ship at x, y moving at vx, vy; null when that
 * push is under 1.5 m/s^2 (near enough, slow enough).
 */
function towards(at: readonly [number, number], x: number, y: number, vx: number, vy: number): Thrust | null {
  const ax = 2 * (at[0] - x) - 2.5 * vx,
    ay = 2 * (at[1] - y) - 2.5 * vy;
  if (Math.hypot(ax, ay) <= 1.5) return null;
  let best: Thrust | null = null,
    dot = -Infinity;
  for (const t of ['up', 'down', 'left', 'right', 'up-left', 'up-right', 'down-left', 'down-right'] as const) {
    const d = THRUST_DIRECTION[t][0] * ax + THRUST_DIRECTION[t][1] * ay;
    if (d > dot) [dot, best] = [d, t];
  }
  return best;
}

/**
 * A simple pilot: every 0.1 s it tries thrust up, left, right, down and none in that order and keeps
 * the first whose predicted path (1.5 s, ./rules `predictPath`) neither enters a horizon nor leaves
 * the field by a side or the bottom. While a ring is left it first tries the thrust that takes it to
 * the next ring (`towards`); then, on a wall level, while under the wall, the sideways thrust that
 * takes it to the gap (`wallGap`: it has eyes, as a player does). Plays at most
 * `seconds`; stops at a clear or game over.
 */
function pilot(g: BlackHoleGame, run: LevelRun, seconds: number) {
  const pred = createPredictor(g);
  const path = new Float64Array(2 * 91);
  const steps = Math.round(seconds / g.world.dt);
  const gap = run.spec.gate > 0 ? wallGap(g) : null;
  const P = g.world.components.Position,
    V = g.world.components.Velocity;
  for (let k = 0; k < steps; k++) {
    let want: Thrust = g.thrust;
    if (k % 6 === 0 && canThrust(g, run)) {
      want = 'none';
      let first: Thrust = 'up';
      const s = slotOf(g.ship);
      const ring = run.rings[run.ringsTaken];
      if (ring) first = towards(ring, P.x[s]!, P.y[s]!, V.x[s]!, V.y[s]!) ?? first;
      else if (gap && P.y[s]! < gap.y) {
        // Towards the gap: a sideways push on the distance, braked on the sideways speed.
        const ax = 2 * (gap.x - P.x[s]!) - 2.5 * V.x[s]!;
        if (Math.abs(ax) > 1.5) first = ax > 0 ? 'right' : 'left';
      }
      for (const t of [first, 'up', 'left', 'right', 'down', 'none'] as const) {
        setThrust(g, t);
        const n = predictPath(g, pred, path, 90);
        const x = path[2 * n - 2]!,
          y = path[2 * n - 1]!;
        if (x < 0 || x > g.field.width || y < 0) continue;
        if (n === 91 || y > g.field.height) {
          want = t;
          break;
        }
      }
    }
    if (!canThrust(g, run)) want = 'none';
    if (g.thrust !== want) setThrust(g, want);
    const e = stepLevel(g, run);
    if (e === 'cleared' || e === 'over') return { steps: k + 1, event: e };
  }
  return { steps, event: 'timeout' as const };
}

describe('levels', () => {
  test("level 1 is one small hole across the straight path up (the fork's first), practice: a fall there costs no life", () => {
    // The issue this answers: on the fork (that hole and one across each diagonal, every held thrust
    // red from the pad) a stranger lost three lives in 30 s without seeing a way through. One hole
    // with open field either side, and falls that cost nothing, teach steering by the path first.
    // (No held thrust clearing it is checked below, with the other levels.)
    for (const field of [FIELD, { width: 20, height: 30 }]) {
      for (let seed = 1; seed <= 3; seed++) {
        const g = createBlackHoleGame({ seed, field });
        const run = startLevel(g, 1);
        expect(g.holes.length).toBe(1);
        const P = g.world.components.Position;
        expect(Math.abs(P.x[slotOf(g.holes[0]!)]! - g.start[0])).toBeLessThan(0.3 * g.holeRadius[0]! + 1e-9);
        // Held up it falls in; the life is given back, however many falls (the game is never over).
        for (let fall = 1; fall <= 4; fall++) {
          setThrust(g, 'up');
          let e = '';
          for (let k = 0; k < 600 && e !== 'fell' && e !== 'over'; k++) e = stepLevel(g, run);
          expect(e).toBe('fell');
          expect([g.falls, g.lives, g.over]).toEqual([fall, 3, false]);
        }
        expect(g.message).toBe('Swallowed by a black hole! Practice: falling in costs no life on this level. Steer round the red path.');
      }
    }
    // Level 2 on counts its falls in lives.
    const g = createBlackHoleGame({ seed: 1 });
    expect([levelSpec(1).practice, levelSpec(2).practice, levelSpec(5).practice]).toEqual([true, false, false]);
    const run = startLevel(g, 4);
    setThrust(g, 'up');
    let e = '';
    for (let k = 0; k < 600 && e !== 'fell'; k++) e = stepLevel(g, run);
    expect([e, g.lives]).toEqual(['fell', 2]);
  });

  test('level 1 leaves a newcomer time: its holes pull the waiting ship at under 0.5 m/s^2, and after a tap of up (TAP_STEPS, as the page taps) it drifts 5.5 s or more before it falls in', () => {
    // The issue this answers: a stranger's 0.15 s tap of up sent the ship into level 1's middle hole
    // within 4 s (the fork pulled the start at 0.65 to 0.77 m/s^2). The pull is summed from the holes'
    // masses and places (G M / d^2 each, towards the hole), not taken from the game's step; the drift
    // is played in the game.
    for (const field of [FIELD, { width: 32, height: 30 }, { width: 20, height: 30 }])
      for (let seed = 1; seed <= 4; seed++) {
        const where = `${field.width}x${field.height} seed ${seed}`;
        const g = createBlackHoleGame({ seed, field });
        const run = startLevel(g, 1);
        expect(pullAtStart(g), where).toBeLessThan(0.5);
        let e = 'none',
          k = 0;
        for (; k < 5.5 / g.world.dt && e === 'none'; k++) {
          setThrust(g, k < TAP_STEPS ? 'up' : 'none');
          e = stepLevel(g, run);
        }
        expect(e, where).toBe('none');
        // And it did leave the pad: it is on its way up.
        expect(shipY(g), where).toBeGreaterThan(g.start[1] + 2);
      }
  });

  test('no arrow, nor two at right angles, held from the start clears a level of each kind on either field (played in the game, not predicted)', () => {
    // The fork, a wall, blockers with holes on the diagonals, drifting holes, a fuel limit. Only the
    // thrusts with some up in them are played: the others leave the field by a side or the bottom.
    const thrusts: Thrust[] = ['up', 'up-left', 'up-right'];
    const cleared: string[] = [];
    for (const field of [FIELD, { width: 32, height: 30 }, { width: 20, height: 30 }])
      for (const level of [1, 2, 4, 6, 8]) {
        // The layout check agrees (it predicts; the loop below plays).
        const g0 = createBlackHoleGame({ seed: 1, field });
        expect(heldThrustClears(g0, startLevel(g0, level)), `level ${level}`).toBe(null);
        for (const t of thrusts) {
          const g = createBlackHoleGame({ seed: 1, field });
          const run = startLevel(g, level);
          setThrust(g, t);
          let e = 'none';
          for (let k = 0; k < 8 / g.world.dt && e === 'none'; k++) e = stepLevel(g, run);
          if (e === 'cleared') cleared.push(`${field.width}x${field.height} level ${level} ${t}`);
        }
      }
    expect(cleared).toEqual([]);
    // And the check can tell: a level of no holes but one far off to the side is cleared by holding up.
    const g = createBlackHoleGame({ seed: 1 });
    const run = startLevel(g, 1);
    const P = g.world.components.Position;
    for (const h of g.holes) {
      P.x[slotOf(h)] = 2;
      P.y[slotOf(h)] = 12;
    }
    g.version++;
    // The ring is off the straight path up: held up misses it, so the line does not count.
    expect(heldThrustClears(g, run)).toBe(null);
    // Put on the straight path, it is flown through and the line counts.
    run.rings[0] = [g.start[0], 10];
    expect(heldThrustClears(g, run)).toBe('up');
  }, 120_000);

  test("levels 2 and 3 on every field the page makes (32 x 24 to 32 x 30 m, and the phone's 20 x 30 m): no held thrust clears them on seeds 1 to 8", () => {
    // The issue this answers: on the 32 x 30 m desktop field every one of the 30 layouts of level 2
    // drawn on some seeds let a held diagonal up through the wall's gap.
    const found: string[] = [];
    for (const field of [FIELD, { width: 32, height: 27 }, { width: 32, height: 30 }, { width: 20, height: 30 }])
      for (const level of [2, 3])
        for (let seed = 1; seed <= 8; seed++) {
          const g = createBlackHoleGame({ seed, field });
          const t = heldThrustClears(g, startLevel(g, level));
          if (t !== null) found.push(`${field.width}x${field.height} level ${level} seed ${seed}: ${t}`);
        }
    expect(found).toEqual([]);
  }, 120_000);

  test('a level has one layout per seed: reached by clearing the levels before it, or started anew (a retry after a game over), on either field', () => {
    // The holes (x, y, r) of level `level` in a game of `seed`, started directly, as the page does for
    // ?level=N and for "Continue from level N" after a game over.
    const holesOf = (g: BlackHoleGame): number[] =>
      g.holes.flatMap((h, i) => [g.world.components.Position.x[slotOf(h)]!, g.world.components.Position.y[slotOf(h)]!, g.holeRadius[i]!]);
    for (const field of [FIELD, { width: 20, height: 30 }])
      for (const seed of [1, 2, 5]) {
        const where = `${field.width}x${field.height} seed ${seed}`;
        const g = createBlackHoleGame({ seed, field, lives: 9 });
        const run = startLevel(g, 1);
        for (const level of [2, 3, 4]) {
          // Clear the level in play: the rings taken, the ship put just under the line, moving up.
          run.ringsTaken = run.rings.length;
          g.world.components.Position.x[slotOf(g.ship)] = g.start[0];
          g.world.components.Position.y[slotOf(g.ship)] = g.lineY - 0.01;
          g.world.components.Velocity.y[slotOf(g.ship)] = 2;
          setThrust(g, 'up');
          stepLevel(g, run);
          expect(run.waiting, `${where} level ${level - 1} cleared`).toBe(true);
          beginLevel(g, run);
          const fresh = createBlackHoleGame({ seed, field, lives: 9 });
          startLevel(fresh, level);
          expect(holesOf(g), `${where} level ${level}`).toEqual(holesOf(fresh));
          // Another seed lays it out otherwise (the layouts are drawn, not fixed).
          const other = createBlackHoleGame({ seed: seed + 100, field, lives: 9 });
          startLevel(other, level);
          expect(holesOf(other), `${where} level ${level}`).not.toEqual(holesOf(fresh));
        }
      }
  });

  test("level 2's wall is of small holes, light, so its gap shows wide between their discs", () => {
    // The issue this answers: level 2 (after an easy level 1) cost a stranger three lives; its wall's
    // holes, grown to fit the old cap of 16, drew discs (2.6 radii across each side, main.ts DISC)
    // that left about 70 px of the 6 m gap in sight. The wall's mass per metre, summed from the holes'
    // masses, is what pulls a ship near it (a line of mass): level 2's is the lighter.
    const perMetre = (g: BlackHoleGame) => g.holeMass.reduce((a, m) => a + m, 0) / g.field.width;
    for (const field of [FIELD, { width: 32, height: 30 }, { width: 20, height: 30 }])
      for (let seed = 1; seed <= 3; seed++) {
        const where = `${field.width}x${field.height} seed ${seed}`;
        const g2 = createBlackHoleGame({ seed, field });
        startLevel(g2, 2);
        // Drawn at 0.2 to 0.25 m, each stretch's holes then scaled a little to fill it exactly.
        const r = Math.max(...g2.holeRadius);
        expect(r, where).toBeLessThanOrEqual(0.3);
        const gap = wallGap(g2);
        // Clear of the discs drawn round the holes either side: 6 m or more on a desktop field, 4.5 on a phone's.
        expect(gap.width - 2 * 2.6 * r, where).toBeGreaterThanOrEqual(field.width < 32 ? 4.5 : 6);
        // Under 0.8 of the 18 kg/m of the lower wall of 0.45 to 0.55 m holes that level 3 once was.
        expect(perMetre(g2), where).toBeLessThan(0.8 * 18);
      }
  });

  test("level 2's wall is far enough up that its pull on the ship waiting at the start is under a third of the thrust", () => {
    // The issue this answers: a newcomer's taps barely moved the ship against the wall's pull (about
    // half the thrust at the start), which drew it up into the wall. The pull is summed here from the
    // holes' masses and places (G M / d^2 each, towards the hole), not taken from the game's step.
    for (const field of [FIELD, { width: 32, height: 30 }, { width: 20, height: 30 }])
      for (let seed = 1; seed <= 4; seed++) {
        const g = createBlackHoleGame({ seed, field });
        startLevel(g, 2);
        expect(pullAtStart(g), `${field.width}x${field.height} seed ${seed}`).toBeLessThan(g.params.thrust / 3);
        // And it is a wall still: eight holes or more in a row (ten on the phone's field).
        expect(g.holes.length).toBeGreaterThanOrEqual(8);
      }
  });

  test("level 2 leaves a newcomer time: after a tap (up, a side, or down on the pad) the ship drifts 4 s or more before the wall takes it (7 s on the phone's field)", () => {
    // The issue this answers: a stranger's side tap, or a tap of down on the pad, left the ship to
    // the wall's pull, which took it within 3.6 s of the tap (16.5 to 17.5 m up).
    for (const field of [FIELD, { width: 32, height: 30 }, { width: 20, height: 30 }])
      for (const tap of ['up', 'left', 'right', 'down'] as const)
        for (let seed = 1; seed <= 4; seed++) {
          const where = `${field.width}x${field.height} ${tap} seed ${seed}`;
          const g = createBlackHoleGame({ seed, field });
          const run = startLevel(g, 2);
          const least = field.width < FIELD.width ? 7 : 4;
          let e = 'none',
            k = 0;
          for (; k < least / g.world.dt && e === 'none'; k++) {
            setThrust(g, k < TAP_STEPS ? tap : 'none');
            e = stepLevel(g, run);
          }
          expect(e, where).toBe('none');
          // And it did leave the pad, but for ↓, which the pad under the ship takes (it stays parked).
          if (tap === 'down') expect([shipY(g), run.parked], where).toEqual([g.start[1], true]);
          else expect(shipY(g), where).toBeGreaterThan(g.start[1] + 2);
        }
  });

  test('on a level of drifting holes the predicted path is the path the ship then takes, to the step it falls in', () => {
    // The issue this answers: the path drawn in flight was not where the ship went. The prediction
    // held the holes still while the level drifts them (levels 6 on), and tested a horizon at each
    // step's end while the game tests the whole step's segment (`holeHit`).
    let compared = 0,
      fell = 0;
    for (const seed of [1, 2, 3, 4])
      for (const t of ['up', 'up-left', 'up-right'] as const) {
        const g = createBlackHoleGame({ seed });
        const run = startLevel(g, 8);
        const pred = createPredictor(g);
        const out = new Float64Array(2 * 601);
        setThrust(g, t);
        const n = predictPath(g, pred, out, 600, run.holeVx);
        const P = g.world.components.Position;
        let e = 'none';
        for (let i = 1; i < n; i++) {
          e = stepLevel(g, run);
          if (e !== 'none') {
            // The game's event comes on the path's last point, not before.
            expect(i, `seed ${seed} ${t}`).toBe(n - 1);
            break;
          }
          // Within 1e-9 m: the copy sums the holes' pulls in its own order, so the two paths may part by
          // a rounding (1e-15 m seen); a copy whose holes stood still parts by millimetres in a second.
          const dx = Math.abs(P.x[slotOf(g.ship)]! - out[2 * i]!),
            dy = Math.abs(P.y[slotOf(g.ship)]! - out[2 * i + 1]!);
          expect(Math.max(dx, dy), `seed ${seed} ${t} step ${i}`).toBeLessThan(1e-9);
          compared++;
        }
        const x = out[2 * n - 2]!,
          y = out[2 * n - 1]!;
        // Ended short inside the field, below the line: the game's ship fell in on that step.
        if (n < 601 && y < g.lineY && x >= 0 && x <= g.field.width && y >= 0) {
          expect(e, `seed ${seed} ${t}`).toBe('fell');
          fell++;
        }
      }
    expect(compared).toBeGreaterThan(500);
    expect(fell).toBeGreaterThan(0);
    // Without the holes' speeds the copy holds them still, and the path parts from the ship's.
    const g = createBlackHoleGame({ seed: 1 });
    const run = startLevel(g, 8);
    const pred = createPredictor(g);
    const out = new Float64Array(2 * 121);
    setThrust(g, 'up');
    const n = predictPath(g, pred, out, 120);
    let apart = 0;
    for (let i = 1; i < n; i++) {
      if (stepLevel(g, run) !== 'none') break;
      const P = g.world.components.Position;
      apart = Math.max(apart, Math.hypot(P.x[slotOf(g.ship)]! - out[2 * i]!, P.y[slotOf(g.ship)]! - out[2 * i + 1]!));
    }
    expect(apart).toBeGreaterThan(1e-6);
  });

  test("a held flight (the layout check's) is the game's own flight: the same path, ended by the same event", () => {
    // heldFlight integrates the ship without a physics world; the game steps its world. Every held
    // thrust on a level of each kind (the fork, a wall, drifting holes, a fuel limit; drifting holes
    // on the phone's narrower field too), and a field the straight climb clears: the paths agree to 1e-9 m a step (they are the same
    // operations; only the order in which the world sums the holes' pulls could differ, by rounding),
    // and the game ends the flight at the same step with the same event, or falls in earlier (the
    // game tests the ship's whole step against a horizon, the check its end point: the check never
    // misses a clear the game makes).
    const path = new Float64Array(2 * 1000);
    const ends = new Set<string>();
    const flyBoth = (g: BlackHoleGame, run: LevelRun, t: Thrust, where: string) => {
      const f = heldFlight(g, run, t, path);
      ends.add(f.end);
      setThrust(g, t);
      // The exhaust's particles pull nothing; off, the game's steps cost far less.
      setEmitterEnabled(g.world, g.ship, false);
      const P = g.world.components.Position,
        s = slotOf(g.ship);
      let e: string = 'none',
        k = 0;
      for (; k < f.steps; k++) {
        e = stepLevel(g, run);
        if (e !== 'none') break;
        expect(Math.abs(P.x[s]! - path[2 * k]!), where).toBeLessThanOrEqual(1e-9);
        expect(Math.abs(P.y[s]! - path[2 * k + 1]!), where).toBeLessThanOrEqual(1e-9);
      }
      if (e === 'fell' && k + 1 < f.steps) return;
      expect([e, e === 'none' ? k : k + 1], where).toEqual([
        { cleared: 'cleared', fell: 'fell', left: 'lost', timeout: 'none' }[f.end],
        f.steps,
      ]);
    };
    for (const [field, levels] of [
      [FIELD, [1, 2, 6, 8]],
      [{ width: 20, height: 30 }, [1, 6]],
    ] as const)
      for (const level of levels)
        for (const t of ['up', 'up-left', 'up-right', 'left', 'right', 'down', 'down-left', 'down-right'] as const) {
          const g = createBlackHoleGame({ seed: 2, field, lives: 9 });
          flyBoth(g, startLevel(g, level), t, `${field.width}x${field.height} level ${level} ${t}`);
        }
    // Level 1 with its holes moved off to the side, 12 m up: holding up clears it.
    const g = createBlackHoleGame({ seed: 2 });
    const run = startLevel(g, 1);
    const P = g.world.components.Position;
    for (const h of g.holes) {
      P.x[slotOf(h)] = 3;
      P.y[slotOf(h)] = 12;
    }
    // Without its ring the line counts at once (the ring's rule: test 'a ring ...').
    run.rings.length = 0;
    flyBoth(g, run, 'up', 'holes moved aside');
    // Flights ended every way a held flight can; the only one timing out is ↓, which leaves the ship
    // parked on the pad (none that flies hovers for 12 s).
    expect([...ends].sort()).toEqual(['cleared', 'fell', 'left', 'timeout']);
  });

  test('points: 100 times the level plus a point for every whole second under 30 s, the same on every field', () => {
    expect(levelPoints(3, 12.4)).toEqual({ level: 3 * POINTS_PER_LEVEL, bonus: 17, total: 317 });
    expect(levelPoints(13, BONUS_SECONDS + 1)).toEqual({ level: 1300, bonus: 0, total: 1300 });
    // Each level is worth more than the one before (counted 10 a hole, level 2's wall made it worth
    // more than levels 3 to 8, and half as much on a phone's narrower field as on a desktop's).
    for (let n = 1; n < 12; n++) expect(levelPoints(n + 1, 0).level).toBeGreaterThan(levelPoints(n, 0).level);
    for (const field of [FIELD, { width: 20, height: 30 }]) {
      const g = createBlackHoleGame({ seed: 2, field });
      const run = startLevel(g, 2);
      expect(g.message).toBe(
        'Level 2: fly through the gold ring, then reach the green line for 200 points, more if fast. Find the gap in the wall.',
      );
      expect(pilot(g, run, 60).event, `${field.width} m field`).toBe('cleared');
      expect(run.summary!.levelPoints).toBe(200);
    }
    expect(() => levelPoints(0, 1)).toThrow(/levelPoints: level must be an integer >= 1, got 0/);
    expect(() => levelPoints(1, Number.NaN)).toThrow(/levelPoints: time must be finite and >= 0 s, got NaN/);
  });

  test("a cleared level reports the winning attempt's time, and a thrust after a fall clears the fall's message", () => {
    const g = createBlackHoleGame({ seed: 1 });
    const run = startLevel(g, 1);
    setThrust(g, 'up');
    let e = '';
    while (e !== 'fell') e = stepLevel(g, run);
    setThrust(g, 'none');
    for (let k = 0; k < 60; k++) stepLevel(g, run);
    expect(g.message).toMatch(/^Swallowed/);
    const lost = run.time;
    // The next thrust starts the winning attempt and brings back the level's opening line.
    setThrust(g, 'left');
    stepLevel(g, run);
    expect(g.message).toBe(
      'Level 1: fly through the gold ring, then reach the green line for 100 points, more if fast. Practice: falling in costs no life here.',
    );
    const r = pilot(g, run, 30);
    expect(r.event).toBe('cleared');
    const k = r.steps + 1;
    expect(run.summary!.time).toBeCloseTo(k * g.world.dt, 9);
    expect(run.summary!.totalTime).toBeCloseTo(lost + k * g.world.dt, 9);
    expect(g.message).toMatch(/^Level 1 cleared in \d+\.\d s \(\d+\.\d s in all, 1 fall\): \+\d+ \(100 \+ \d+ speed bonus\)/);
  });

  test('level 3: three holes up the straight path, each to the other side of the start than the one below', () => {
    // Measured from the holes' places alone: the three nearest the start's x, sorted by height, sit
    // within 2 m of it, on alternate sides, each 2.5 m or more above the one below.
    for (const field of [FIELD, { width: 20, height: 30 }])
      for (let seed = 1; seed <= 4; seed++) {
        const g = createBlackHoleGame({ seed, field });
        startLevel(g, 3);
        const P = g.world.components.Position;
        const hs = g.holes
          .map((h) => ({ dx: P.x[slotOf(h)]! - g.start[0], y: P.y[slotOf(h)]! }))
          .sort((a, b) => Math.abs(a.dx) - Math.abs(b.dx))
          .slice(0, 3)
          .sort((a, b) => a.y - b.y);
        const where = `${field.width}x${field.height} seed ${seed}`;
        for (const h of hs) expect(Math.abs(h.dx), where).toBeLessThan(2);
        // Off the straight path by 0.3 m or more (ZIGZAG_OFFSET, 0.5 m, less a fifth of a radius): so
        // close that a climb straight up, held or let go to coast, falls in, but still to one side.
        for (const h of hs) expect(Math.abs(h.dx), where).toBeGreaterThan(0.3);
        expect(Math.sign(hs[0]!.dx) * Math.sign(hs[1]!.dx), where).toBe(-1);
        expect(Math.sign(hs[1]!.dx) * Math.sign(hs[2]!.dx), where).toBe(-1);
        expect(hs[1]!.y - hs[0]!.y, where).toBeGreaterThan(2.5);
        expect(hs[2]!.y - hs[1]!.y, where).toBeGreaterThan(2.5);
      }
  });

  test('level 2: a wall across the field, closed but for one gap off to the side', () => {
    // The issue this answers: levels 1 to 3 were cleared in seconds (a nudge, then up). The wall is
    // measured from the holes alone (wallGap): its widest stretch is the level's gap, every other one
    // (between holes, and at the field's edges) at most WALL_GAP, and the gap's near edge 2 m or more
    // to the side of the start. It is closed elsewhere: of the ships that thrust sideways for 0 to
    // 1.2 s (either way) and then up, every one that clears crossed the wall's height inside the gap.
    let cleared = 0,
      tries = 0;
    for (const field of [FIELD, { width: 20, height: 30 }]) {
      for (const level of [2]) {
        for (const seed of field === FIELD ? [1, 2] : [3]) {
          const g = createBlackHoleGame({ seed, field });
          const spec = startLevel(g, level).spec;
          const gap = wallGap(g);
          expect(gap.width, `level ${level} seed ${seed}`).toBeCloseTo(Math.min(spec.gate, WALL_GATE_SHARE * field.width), 9);
          expect(gap.others).toBeLessThanOrEqual(WALL_GAP + 1e-9);
          expect(gap.edge).toBeGreaterThanOrEqual(2 - 1e-9);
          // A wall of small holes needs more than the classic game's MAX_HOLES: the cap is the predictor's.
          expect(g.holes.length).toBeLessThanOrEqual(MAX_FIELD_HOLES);
          // No hole above the wall.
          const P = g.world.components.Position;
          expect(g.holes.filter((h) => P.y[slotOf(h)]! > gap.y + 2).length).toBe(0);
          for (const side of ['left', 'right'] as const) {
            for (const nudge of [0, 0.4, 0.8, 1.2]) {
              if (nudge === 0 && side === 'right') continue;
              const g2 = createBlackHoleGame({ seed, field });
              const run2 = startLevel(g2, level);
              const S = g2.world.components.Position;
              let crossedAt = Number.NaN,
                event = '';
              for (let k = 0; k < 8 / g2.world.dt && event !== 'cleared' && event !== 'fell' && event !== 'lost'; k++) {
                const want: Thrust = k * g2.world.dt < nudge ? side : 'up';
                if (g2.thrust !== want) setThrust(g2, want);
                const y = S.y[slotOf(g2.ship)]!;
                event = stepLevel(g2, run2);
                if (y < gap.y && S.y[slotOf(g2.ship)]! >= gap.y) crossedAt = S.x[slotOf(g2.ship)]!;
              }
              tries++;
              if (event !== 'cleared') continue;
              cleared++;
              expect(Math.abs(crossedAt - gap.x), `level ${level} seed ${seed}: ${side} ${nudge} s`).toBeLessThan(gap.width / 2);
            }
          }
        }
      }
    }
    // A few of those simple ways find the gap, most do not (measured with gaps of 7 and 5.5 m: 7 of 42).
    expect(cleared).toBeGreaterThan(0);
    expect(cleared).toBeLessThan(tries / 3);
  });

  test('every level from 1 to 5 can be won: a steering pilot clears it without a fall on the default field, the tallest desktop one and a phone held upright', () => {
    // Fields: the default 32 x 24 m (two seeds), the tallest desktop one (32 x 30 m, a squarer stage)
    // and the phone's (20 x 30 m) (a seed a level). Levels 4 and 5 (holes at random, two across the
    // path) on the default field.
    const fields = [FIELD, { width: 32, height: 30 }, { width: 20, height: 30 }];
    for (const field of fields) {
      for (let level = 1; level <= (field === FIELD ? 5 : 3); level++) {
        for (const seed of field === FIELD ? [1, 2] : [level + 2]) {
          const g = createBlackHoleGame({ seed, field });
          const r = pilot(g, startLevel(g, level), 30);
          expect(r.event, `${field.width} x ${field.height}: level ${level} seed ${seed}`).toBe('cleared');
          expect(g.falls, `${field.width} x ${field.height}: level ${level} seed ${seed}`).toBe(0);
        }
      }
    }
    expect(() => createBlackHoleGame({ field: { width: 8, height: 30 } })).toThrow(/field.width must be in \[12, 64\] m, got 8/);
  });

  test("steering keeps up with the pull step by step: the reach of the holes' grip grows from level 4 to 8, starting near level 1's", () => {
    // A hole of mass M grips the ship (pulls harder than the thrust a) within d = sqrt(G M / a) of its
    // centre. Mean over seeds 1-8 on the default field of the widest grip on the field, from the holes
    // the level lays out (their masses, the game's G and thrust). Level 4 had 1.1 m horizons where level 1
    // has 0.6 m: its grip was 1.35 times level 1's and steering lost to the pull there.
    const grip = (level: number): number => {
      let sum = 0;
      for (let seed = 1; seed <= 8; seed++) {
        const g = createBlackHoleGame({ seed });
        startLevel(g, level);
        const G = gravitationalConstant(g);
        sum += Math.max(...g.holeMass.map((M) => Math.sqrt((G * M) / g.params.thrust)));
      }
      return sum / 8;
    };
    const [one, ...later] = [1, 4, 5, 6, 7, 8].map(grip);
    expect(later[0]! / one!).toBeLessThan(1.25);
    // Each level's no narrower than the last (5 % for the draw of radii over 8 seeds), and level 8's wider than level 4's.
    for (let i = 1; i < later.length; i++) expect(later[i]!, `level ${i + 4}`).toBeGreaterThan(0.95 * later[i - 1]!);
    expect(later[4]!).toBeGreaterThan(1.1 * later[0]!);
  });

  test('from level 4 holding thrust up falls in: holes lie across the straight path', () => {
    for (let level = 4; level <= 5; level++) {
      for (let seed = 1; seed <= 4; seed++) {
        const g = createBlackHoleGame({ seed });
        const run = startLevel(g, level);
        expect(Math.min(...g.holes.map((h) => Math.abs(g.world.components.Position.x[slotOf(h)]! - START[0])))).toBeLessThan(1);
        play(g, run, () => true, 10);
        expect(g.falls, `level ${level} seed ${seed}`).toBeGreaterThan(0);
      }
    }
  });

  test('the ship waits at the start until the player thrusts, at the level start and after a fall', () => {
    // The issue this answers: on level 6 a drifting hole reached the respawned ship and took a life
    // with no input. A parked ship stays at the start at rest however long the player waits.
    const g = createBlackHoleGame({ seed: 2 });
    const run = startLevel(g, 6);
    const P = g.world.components.Position;
    for (let k = 0; k < 1200; k++) expect(stepLevel(g, run)).toBe('none');
    expect([P.x[slotOf(g.ship)], P.y[slotOf(g.ship)], g.falls]).toEqual([START[0], START[1], 0]);
    // Level 4: thrust up into the lower blocker until it falls in; then the ship waits again.
    const g4 = createBlackHoleGame({ seed: 2 });
    const run4 = startLevel(g4, 4);
    setThrust(g4, 'up');
    for (let k = 0; k < 600 && g4.falls === 0; k++) stepLevel(g4, run4);
    expect(g4.falls).toBe(1);
    setThrust(g4, 'none');
    for (let k = 0; k < 600; k++) stepLevel(g4, run4);
    const P4 = g4.world.components.Position;
    expect([P4.x[slotOf(g4.ship)], P4.y[slotOf(g4.ship)], g4.falls]).toEqual([START[0], START[1], 1]);
  });

  test('difficulty grows one step at a time: levels 1 to 3 each ask more, then holes and radius never fall, drift starts slow at level 6, fuel from level 8', () => {
    // Levels 1 to 3: one hole across the straight path (the fork's first); a wall with a gap, high up (its pull at the start weak);
    // a zig-zag of holes up the straight path (no wall). None drifts or has a fuel limit.
    const [one, two, three] = [levelSpec(1), levelSpec(2), levelSpec(3)];
    expect([one.gate, one.holes, one.fork]).toEqual([0, 1, true]);
    expect([two.gate > 0, two.blockers]).toEqual([true, 0]);
    expect([three.gate, three.zigzag, two.zigzag, one.zigzag, levelSpec(4).zigzag]).toEqual([0, true, false, false, false]);
    for (const s of [one, two, three]) expect([s.drift, s.fuel]).toEqual([0, Infinity]);
    let prev = levelSpec(4);
    expect(prev.gate).toBe(0);
    for (let n = 5; n <= 20; n++) {
      const s = levelSpec(n);
      expect(s.gate).toBe(0);
      expect(s.holes).toBeGreaterThanOrEqual(prev.holes);
      expect(s.radius[1]).toBeGreaterThanOrEqual(prev.radius[1]);
      expect(s.drift).toBeGreaterThanOrEqual(prev.drift);
      expect(s.fuel).toBeLessThanOrEqual(prev.fuel);
      expect(s.corridor).toBeLessThanOrEqual(prev.corridor);
      // One new kind of difficulty a level at most: a hole more, a second blocker, the first drift, the
      // first fuel limit (the issue this answers: level 5 ended a newcomer's game).
      const news = [
        s.holes > prev.holes,
        s.blockers > prev.blockers,
        s.drift > 0 && prev.drift === 0,
        Number.isFinite(s.fuel) && !Number.isFinite(prev.fuel),
      ];
      expect(news.filter(Boolean).length, `level ${n}`).toBeLessThanOrEqual(1);
      // Drift speeds up gently: at most 0.35 m/s a level.
      expect(s.drift - prev.drift, `level ${n}`).toBeLessThanOrEqual(0.35 + 1e-12);
      expect(s.holes - prev.holes).toBeLessThanOrEqual(1);
      prev = s;
    }
    expect([levelSpec(5).drift, levelSpec(6).drift > 0, levelSpec(6).drift <= 0.4]).toEqual([0, true, true]);
    expect([Number.isFinite(levelSpec(7).fuel), Number.isFinite(levelSpec(8).fuel)]).toEqual([false, true]);
    expect(levelSpec(8).fuel).toBeGreaterThanOrEqual(15);
    expect(levelSpec(20).holes).toBeGreaterThan(levelSpec(4).holes);
    expect(() => levelSpec(0)).toThrow(/level must be an integer >= 1, got 0/);
  });

  test('drifting holes move at the level speed, turn back inside the field and keep r = 2 G M / c^2', () => {
    const g = createBlackHoleGame({ seed: 4 });
    const run = startLevel(g, 6);
    const P = g.world.components.Position;
    const x0 = g.holes.map((h) => P.x[slotOf(h)]!);
    const y0 = g.holes.map((h) => P.y[slotOf(h)]!);
    stepLevel(g, run);
    for (let i = 0; i < g.holes.length; i++) {
      // One step moves a hole by drift * dt unless it turned back at an edge this step.
      const moved = Math.abs(P.x[slotOf(g.holes[i]!)]! - x0[i]!);
      expect(moved).toBeLessThanOrEqual(run.spec.drift * g.world.dt + 1e-12);
      expect(P.y[slotOf(g.holes[i]!)]).toBe(y0[i]);
    }
    for (let k = 0; k < 600; k++) stepLevel(g, run);
    const G = gravitationalConstant(g),
      c = g.params.c;
    for (let i = 0; i < g.holes.length; i++) {
      const x = P.x[slotOf(g.holes[i]!)]!,
        r = g.holeRadius[i]!;
      expect(x).toBeGreaterThanOrEqual(1.5 + r - 1e-9);
      expect(x).toBeLessThanOrEqual(FIELD.width - 1.5 - r + 1e-9);
      expect(r / ((2 * G * g.holeMass[i]!) / (c * c))).toBeCloseTo(1, 12);
    }
  });

  test('fuel burns only while thrusting and at zero the thrust stops', () => {
    const g = createBlackHoleGame({ seed: 2 });
    const run = startLevel(g, 8);
    expect(run.fuelLeft).toBe(levelSpec(8).fuel);
    for (let k = 0; k < 30; k++) stepLevel(g, run);
    expect(run.fuelLeft).toBe(levelSpec(8).fuel);
    // Sideways (↓ on the pad would not thrust), the ship held on a slow climb up from the start so the
    // attempt does not end (an attempt that ends, or stalls, refills the tank for the next:
    // test/games/black-hole-stranded.test.ts).
    setThrust(g, 'left');
    const steps = Math.ceil(run.fuelLeft / g.world.dt) + 5;
    for (let k = 0; k < steps && g.thrust !== 'none'; k++) {
      setPosition(g.world, g.ship, [g.start[0], g.start[1] + 0.15 * k * g.world.dt]);
      stepLevel(g, run);
    }
    expect(run.fuelLeft).toBe(0);
    expect(g.thrust).toBe('none');
    expect(canThrust(g, run)).toBe(false);
  });

  test('clearing a level: a summary, 100 points a level and the speed bonus, a lost life back, an empty field and no steps until the next level begins', () => {
    const g = createBlackHoleGame({ seed: 3 });
    const run = startLevel(g, 4);
    // One fall first: thrust straight up into the blocker.
    setThrust(g, 'up');
    while (g.falls === 0) stepLevel(g, run);
    setThrust(g, 'none');
    expect(g.lives).toBe(2);
    const r = pilot(g, run, 60);
    expect(r.event).toBe('cleared');
    expect(g.falls).toBe(1);
    // The clear gives the lost life back (never above the three the game starts with).
    const s = run.summary!;
    const bonus = Math.max(0, Math.floor(BONUS_SECONDS - s.time));
    expect(s).toMatchObject({ level: 4, holes: 4, levelPoints: 400, bonus, points: 400 + bonus, lives: 3, falls: 1 });
    expect(g.lives).toBe(3);
    expect(g.message).toContain(
      `1 fall): +${400 + bonus}${bonus > 0 ? ` (400 + ${bonus} speed bonus)` : ''}. A life back for clearing it: 3 lives.`,
    );
    expect(g.score).toBe(400 + bonus);
    expect(run.waiting).toBe(true);
    expect(run.spec.level).toBe(5);
    // No hole on the field while it waits: level 5's holes come when it begins.
    expect(g.holes.length).toBe(0);
    // The ship waits where it crossed, at or past the line (it was put back at the start, below it).
    const y = shipY(g);
    expect(y).toBeGreaterThanOrEqual(LINE_Y);
    expect(stepLevel(g, run)).toBe('waiting');
    expect(shipY(g)).toBe(y);
    beginLevel(g, run);
    expect(run.waiting).toBe(false);
    expect(g.holes.length).toBe(levelSpec(5).holes);
    expect(g.message).toBe('Level 5: fly through the gold ring, then reach the green line for 500 points, more if fast.');
    expect(shipY(g)).toBeLessThan(LINE_Y);
    // A clear at full lives keeps three.
    const g2 = createBlackHoleGame({ seed: 3 });
    const run2 = startLevel(g2, 4);
    expect(pilot(g2, run2, 60).event).toBe('cleared');
    expect([g2.falls, g2.lives, run2.summary!.lives]).toEqual([0, 3, 3]);
    expect(g2.message).not.toMatch(/life back/);
  });

  test('a player who reads before the first press loses nothing: the parked ship stays at the start, 15 s on levels 1 to 4', () => {
    // A stranger read level 2's title and the wall: no life may go meanwhile (the wall pulls 2 to
    // 3 m/s^2 at the start, a fall within seconds were the ship not held there).
    for (const field of [FIELD, { width: 20, height: 30 }]) {
      for (let level = 1; level <= 4; level++) {
        const g = createBlackHoleGame({ seed: 5, field });
        const run = startLevel(g, level);
        const events = new Set<string>();
        for (let k = 0; k < 900; k++) events.add(stepLevel(g, run));
        expect([...events], `level ${level}`).toEqual(['none']);
        const s = slotOf(g.ship);
        expect([g.falls, g.lives, run.parked], `level ${level}`).toEqual([0, 3, true]);
        expect(g.world.components.Position.x[s], `level ${level}`).toBeCloseTo(g.start[0], 9);
        expect(g.world.components.Position.y[s], `level ${level}`).toBeCloseTo(g.start[1], 9);
      }
    }
  });
  test('↓ on the start pad is harmless: the parked ship stays put, burns no fuel and is never lost; ↙ is ←; flight elsewhere keeps ↓', () => {
    // A stranger's first key was ↓: from 1.5 m up at 6 m/s^2 the ship left the field's foot in under
    // 1 s ("Lost in space"). The pad is under the ship: its downward part is dropped while parked.
    for (const level of [1, 2, 8]) {
      const g = createBlackHoleGame({ seed: 5 });
      const run = startLevel(g, level);
      const fuel = run.fuelLeft,
        resets = g.resets;
      setThrust(g, 'down');
      const events = new Set<string>();
      for (let k = 0; k < 180; k++) events.add(stepLevel(g, run)); // 3 s at 60 Hz
      const s = slotOf(g.ship);
      expect([...events], `level ${level}`).toEqual(['none']);
      expect([run.parked, run.fuelLeft, g.resets, g.thrust], `level ${level}`).toEqual([true, fuel, resets, 'none']);
      expect(g.world.components.Position.y[s], `level ${level}`).toBeCloseTo(g.start[1], 9);
      expect(g.world.components.Velocity.y[s], `level ${level}`).toBe(0);
    }
    // ↙ from the pad flies exactly as ← does (bit for bit: the same thrust from the first step).
    const flown = (t: Thrust): number[] => {
      const g = createBlackHoleGame({ seed: 5 });
      const run = startLevel(g, 1);
      setThrust(g, t);
      for (let k = 0; k < 30; k++) stepLevel(g, run);
      const s = slotOf(g.ship);
      return [g.world.components.Position.x[s]!, g.world.components.Position.y[s]!];
    };
    expect(flown('down-left')).toEqual(flown('left'));
    expect(flown('left')[0]).toBeLessThan(START[0] - 0.05);
    // Off the pad ↓ thrusts as before: after 1 s of ↑, 0.8 s of ↓ (the engine turns round in
    // 2 a_T / 18 m/s^3 = 0.67 s, `rampThrust`) has the engine pushing straight down at full a_T.
    const g = createBlackHoleGame({ seed: 5 });
    const run = startLevel(g, 1);
    setThrust(g, 'up');
    const events = new Set<string>();
    for (let k = 0; k < 60; k++) events.add(stepLevel(g, run));
    setThrust(g, 'down');
    for (let k = 0; k < 48; k++) events.add(stepLevel(g, run));
    expect([[...events], run.parked, g.thrust]).toEqual([['none'], false, 'down']);
    expect(g.thrustVec[0]).toBe(0);
    expect(g.thrustVec[1]).toBeCloseTo(-g.params.thrust, 12);
    expect([padThrust('down'), padThrust('down-right'), padThrust('up-left'), padThrust('none')]).toEqual([
      'none',
      'right',
      'up-left',
      'none',
    ]);
    expect(() => padThrust('sideways' as Thrust)).toThrow(/padThrust: thrust must be a Thrust, got "sideways"/);
  });
});
