/**
 * The rope lab's levels, headless (games/lab-rope/scene.ts, cut.ts): each level can be won by cutting
 * its ropes at the right times, a cut at a wrong time loses, a swipe cuts each rope it crosses once, a
 * tap cuts the nearest rope within reach, and a cut rope is two chains that no link joins.
 */
import { isAlive, type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { CUT_END_TRIM, cutRopes, trimPolyline } from '../../games/lab-rope/cut';
import { forecastCuts, plansOf, playPlan, widestRun } from '../../games/lab-rope/plans';
import {
  BALL_DRAG,
  BALL_MASS,
  BALL_RADIUS,
  createRopeScene,
  cutRope,
  DEFAULTS,
  LANDED_LOST,
  LEVELS,
  type Level,
  type Outcome,
  predictFlight,
  RopeGame,
  type RopeScene,
  WIDE_LEVELS,
} from '../../games/lab-rope/scene';

/** Cuts rope `rope` at the link `at` of the way from its pin to the ball (0 to 1; default its middle). */
function cutMiddle(s: RopeScene, rope: number, at = 0.5): void {
  const links = s.ropes[rope]!.links;
  cutRope(s.world, s.ropes[rope]!, links[Math.min(links.length - 1, Math.floor(at * links.length))]!);
}

/**
 * Plays level `index`: cuts rope `rope` at time `t` (s) for each entry of `schedule` (the last cut at
 * `at` of the way down its rope, the others at their middles), after giving the ball a sideways push of
 * `push` m/s at the start; at most 12 s. @returns the outcome, stars and the world time it was decided at, s.
 */
function play(
  index: number,
  schedule: readonly (readonly [number, number])[],
  push = 0,
  at = 0.5,
  levels: readonly Level[] = LEVELS,
): { outcome: Outcome; stars: number; time: number } {
  const s = createRopeScene(index, DEFAULTS, levels);
  const g = new RopeGame(s);
  if (push) s.world.components.Velocity.x[slotOf(s.ball)] = push;
  let k = 0;
  for (let i = 0; i < 60 * 12 && g.outcome === 'playing'; i++) {
    while (k < schedule.length && s.world.time >= schedule[k]![0]) {
      cutMiddle(s, schedule[k]![1], k === schedule.length - 1 ? at : 0.5);
      k++;
    }
    step(s.world);
    g.update();
  }
  return { outcome: g.outcome, stars: g.stars(), time: s.world.time };
}

/** The ball's position, m. */
function ballAt(world: PhysicsWorld, ball: number): [number, number] {
  const e = slotOf(ball);
  return [world.components.Position.x[e]!, world.components.Position.y[e]!];
}

describe('lab-rope levels', () => {
  // Cut times found by a search over schedules (every 0.02 to 0.05 s, each cut at a tenth, half and
  // nine tenths of the way down its rope: the same outcome at 97 % to 100 % of the times on each level):
  // each listed schedule won with the stars given, in windows 0.35 s wide or more. Two times inside
  // each window must win, so a small change in the physics (a step's rounding) does not fail the
  // test, while a level that can no longer be won does. The losing times lie well outside the windows.
  const cases: {
    level: number;
    win: (readonly [number, number])[][];
    lose: (readonly [number, number])[];
    push?: number;
    losePush?: number;
    stars: number;
    /** The index of a `win` schedule that wins with fewer stars than `stars`. */
    fewer?: number;
  }[] = [
    // 1: cut as the ball rises to the right end of its first swing or at the end (won 0.6-2.06 s,
    // 3 stars 1.0-1.88 s: a cut at 1.4 s wins them, one at 1.96 s fewer). A cut 2.5 s in, the ball
    // on its way back, throws it to the left of the basket.
    { level: 0, win: [[[1.4, 0]], [[1.96, 0]]], lose: [[2.5, 0]], fewer: 1, stars: 3 },
    // 2: the left rope first, the right one 0.4-1.9 s later (3 stars from 0.85 s later).
    {
      level: 1,
      win: [
        [
          [0.5, 0],
          [1.6, 1],
        ],
        [
          [0.5, 0],
          [2.2, 1],
        ],
      ],
      lose: [
        [0.5, 1],
        [1.5, 0],
      ],
      stars: 3,
    },
    // 3: on the upswing, over the wall (won 0.84-1.48 s, 3 stars 0.82-1.38 s).
    { level: 2, win: [[[1.1, 0]], [[1.25, 0]]], lose: [[0.3, 0]], stars: 3 },
    // 4: right, middle, then the left one on the way back (won 4.25 s on for the last cut, 3 stars).
    {
      level: 3,
      win: [
        [
          [2.03, 2],
          [2.36, 1],
          [4.5, 0],
        ],
        [
          [2.03, 2],
          [2.36, 1],
          [5.0, 0],
        ],
      ],
      lose: [
        [0.3, 0],
        [0.6, 1],
        [0.9, 2],
      ],
      stars: 3,
    },
    // 5: a push of 5 m/s, then a cut at 3.55-4.3 s (3 stars 3.54-4.28 s); without a push the ball only drops short of the basket.
    { level: 4, push: 5, win: [[[3.9, 0]], [[4.05, 0]]], lose: [[1, 0]], losePush: 0, stars: 3 },
  ];
  for (const c of cases)
    it(`level ${c.level + 1} (${LEVELS[c.level]!.name}) is won by cutting at the right times, lost at a wrong one`, () => {
      const results = c.win.map((w) => play(c.level, w, c.push ?? 0));
      for (const r of results) expect(r.outcome).toBe('won');
      expect(Math.max(...results.map((r) => r.stars))).toBe(c.stars);
      expect(play(c.level, c.lose, c.losePush ?? c.push ?? 0).outcome).toBe('lost');
      if (c.fewer !== undefined) expect(results[c.fewer]!.stars).toBeLessThan(c.stars);
    });

  it('where along the rope a cut is made does not change the throw: the same outcome and stars for a cut near the pin, midway and near the ball', () => {
    // Before, the rope below the cut stayed on the ball (a fifth of its mass, whipping): on level 3 a
    // cut 1.2 s in won 3 stars near the ball and fell short of the wall near the pin (the three
    // places agreed at 77 % of the cut times searched; now at all). Level 3 won at 1.2 s, level 1 lost at 2.5 s (its basket
    // moved under the swing's right end, where a cut at 1.5 s now wins).
    for (const [level, t, outcome] of [
      [2, 1.2, 'won'],
      [0, 2.5, 'lost'],
    ] as const) {
      const r = [0.1, 0.5, 0.9].map((at) => play(level, [[t, 0]], 0, at));
      for (const x of r) expect(x, `level ${level + 1}, a cut at ${t} s`).toMatchObject({ outcome, stars: r[0]!.stars });
    }
  });

  it('a ball that drops into the basket stays in it; one rolling on the floor beside it is lost at once', () => {
    // Level 1, a cut 1.94 s in: the ball dropped in fast and bounced out over the far wall's top
    // (between cuts at 1.9 and 2.0 s that won); the basket's lining (NET_TIME) keeps it.
    expect(play(0, [[1.94, 0]]).outcome).toBe('won');
    // A cut 2.3 s in: the ball lands beside the basket and rolls between the walls; the miss was
    // said when it stopped, 16.9 s in; now half a second after it lands (FLOOR_LOST).
    const rolled = play(0, [[2.3, 0]]);
    expect(rolled.outcome).toBe('lost');
    expect(rolled.time).toBeLessThan(5);
  });

  it('a miss is said at most LANDED_LOST s after the ball first comes down beside the basket, however it bounces', () => {
    // Misses that bounced, or lay on a cut rope on the floor, 1.5 to 3.2 s before the miss was said
    // (the ball sitting there with no card): up 1 cut 2.6 s in, up 3 cut 3.3 s in, up 5 pushed and
    // cut 0.8 s in, wide 1 cut 2.6 s in. Now at most LANDED_LOST (1.2 s) after, 0.05 s spare for the step.
    const misses: [readonly Level[], number, number, number][] = [
      [LEVELS, 0, 2.6, 0],
      [LEVELS, 2, 3.3, 0],
      [LEVELS, 4, 0.8, 5],
      [WIDE_LEVELS, 0, 2.6, 0],
    ];
    for (const [levels, index, t, push] of misses) {
      const s = createRopeScene(index, DEFAULTS, levels);
      const g = new RopeGame(s);
      const e = slotOf(s.ball);
      if (push) s.world.components.Velocity.x[e] = push;
      let down = Number.NaN;
      for (let i = 0; i < 60 * 12 && g.outcome === 'playing'; i++) {
        if (s.world.time >= t && g.holding() > 0) for (const r of s.ropes) cutMiddle(s, s.ropes.indexOf(r));
        step(s.world);
        g.update();
        if (Number.isNaN(down) && g.holding() === 0 && s.world.components.Position.y[e]! < BALL_RADIUS + 0.12) down = s.world.time;
      }
      const at = `level ${index + 1}, cut ${t} s in`;
      expect(g.outcome, at).toBe('lost');
      expect(s.world.time - down, at).toBeLessThanOrEqual(LANDED_LOST + 0.05);
    }
  });

  it("the wide room's levels (a desktop window) are lost by wrong cuts", () => {
    // Their wins, with all three stars, are played in 'lab-rope star windows' below.
    const cases: { lose: (readonly [number, number])[]; losePush?: number }[] = [
      // 1: a cut well after the ball turned back drops it left of the basket.
      { lose: [[2.8, 0]] },
      // 2: the right rope first never wins.
      {
        lose: [
          [0.5, 1],
          [1.5, 0],
        ],
      },
      // 3: cut too early, the ball falls on the near side of the wall.
      { lose: [[0.5, 0]] },
      // 4: the left rope first never wins.
      {
        lose: [
          [1.0, 0],
          [1.3, 1],
          [2.0, 2],
        ],
      },
      // 5: unpushed, the ball drops short of the raised basket.
      { lose: [[4.5, 0]], losePush: 0 },
      // 6 (the Moon): cut on the way down, the ball drifts short of the high basket.
      { lose: [[1.0, 0]] },
      // 7: cut at the bottom of the swing, the ball strikes the low wall under the window.
      { lose: [[0.9, 0]] },
      // 8: cut too late, at the top of the swing, the ball drops short of the tall wall.
      { lose: [[2.3, 0]] },
    ];
    cases.forEach((c, i) => {
      expect(play(i, c.lose, c.losePush ?? 0, 0.5, WIDE_LEVELS).outcome, `wide level ${i + 1}`).toBe('lost');
    });
  });

  it("the wide room's first level is won by a cut anywhere in a window over a second wide", () => {
    // A stranger at a desktop window cut level 1 four times on the upswing and never landed it:
    // it was won only 2.0-2.56 s in, from the top of the swing on, and rising cuts flew over the
    // basket or struck its rim. Now the basket reaches the right wall: a cut anywhere from 1.04 s
    // to 2.48 s wins (scripts/lab-rope-cuts.mjs --wide 1), rising or at the top; the stars ask for
    // a throw on the upswing (3 stars 1.42-1.86 s), the way a stranger first cuts.
    const times = [1.12, 1.4, 1.7, 1.9, 2.04, 2.2, 2.4];
    const at = times.map((t) => play(0, [[t, 0]], 0, 0.5, WIDE_LEVELS));
    for (const [i, r] of at.entries()) expect(r.outcome, `a cut at ${times[i]} s`).toBe('won');
    expect(at[2]!.stars).toBe(3);
    expect(at[5]!.stars).toBeLessThan(3);
    // Lost outside the window: before the ball has swung past the bottom, and long after the turn.
    for (const t of [0.8, 2.8]) expect(play(0, [[t, 0]], 0, 0.5, WIDE_LEVELS).outcome, `a cut at ${t} s`).toBe('lost');
  });

  it("the wide room's later levels are each won by a last cut anywhere in a window of at least 0.8 s", () => {
    // Their windows were 0.28-0.45 s (a stranger at a desktop rated the lab 3 for fun): now 0.9 to
    // 1.2 s (scripts/lab-rope-cuts.mjs --wide). Four cuts spread over at least 0.8 s of each window
    // all win; the earlier cuts as in the level's plan.
    const plans: { before: (readonly [number, number])[]; last: number; times: number[]; push?: number }[] = [
      { before: [[0.5, 0]], last: 1, times: [1.5, 1.8, 2.1, 2.35] },
      { before: [], last: 0, times: [1.72, 2.0, 2.3, 2.6] },
      {
        before: [
          [1.0, 2],
          [1.3, 1],
        ],
        last: 0,
        times: [2.2, 2.5, 2.9, 3.2],
      },
      { before: [], last: 0, times: [4.15, 4.45, 4.75, 4.95], push: 5 },
    ];
    plans.forEach((p, i) => {
      expect(p.times.at(-1)! - p.times[0]!).toBeGreaterThanOrEqual(0.8 - 1e-9);
      for (const t of p.times) {
        const r = play(i + 1, [...p.before, [t, p.last]], p.push ?? 0, 0.5, WIDE_LEVELS);
        expect(r.outcome, `wide level ${i + 2}, the last cut at ${t} s`).toBe('won');
      }
    });
  });

  it('predictFlight follows the freed ball: within 6 cm of the engine for 0.6 s, and says whether a throw (off a side wall too) lands in the basket', () => {
    // Wide level 2 after its left rope is cut: the right rope cut at 1.8 s throws the ball into the
    // basket (won, as above), at 1.2 s short of it (lost).
    for (const [t, inBasket] of [
      [1.8, true],
      [1.2, false],
    ] as const) {
      const s = createRopeScene(1, DEFAULTS, WIDE_LEVELS);
      const g = new RopeGame(s);
      const e = slotOf(s.ball);
      const P = s.world.components.Position,
        V = s.world.components.Velocity;
      let path: number[] = [];
      let lands = false;
      let cutAt = -1;
      for (let i = 0; i < 60 * 10 && g.outcome === 'playing'; i++) {
        if (s.world.time >= 0.5 && isAlive(s.world, s.ropes[0]!.ballLink)) cutMiddle(s, 0);
        if (cutAt < 0 && s.world.time >= t) {
          cutMiddle(s, 1);
          path = [];
          lands = predictFlight(s.level, P.x[e]!, P.y[e]!, V.x[e]!, V.y[e]!, 9.81, BALL_DRAG / BALL_MASS, path, 0.1);
          cutAt = i;
        }
        step(s.world);
        g.update();
        // The engine's ball k steps after the cut against the path's point k / 6 (0.1 s a point).
        const k = i + 1 - cutAt;
        if (cutAt >= 0 && k % 6 === 0 && k <= 36 && 2 * (k / 6) + 1 < path.length) {
          const [px, py] = [path[(2 * k) / 6]!, path[(2 * k) / 6 + 1]!];
          expect(Math.hypot(P.x[e]! - px, P.y[e]! - py), `a cut at ${t} s, ${k} steps on`).toBeLessThan(0.06);
        }
      }
      expect(lands, `a cut at ${t} s`).toBe(inBasket);
      expect(g.outcome, `a cut at ${t} s`).toBe(inBasket ? 'won' : 'lost');
    }
    // Off a side wall: the upright level 1 cut 1.2 s in throws the ball at the right wall, and it
    // drops off it into the basket (won); 2.3 s in, on the way back, to the left of it (lost).
    for (const [t, inBasket] of [
      [1.2, true],
      [2.3, false],
    ] as const) {
      const s = createRopeScene(0, DEFAULTS, LEVELS);
      const e = slotOf(s.ball);
      while (s.world.time < t) step(s.world);
      const V = s.world.components.Velocity,
        P = s.world.components.Position;
      const lands = predictFlight(s.level, P.x[e]!, P.y[e]!, V.x[e]!, V.y[e]!, 9.81, BALL_DRAG / BALL_MASS, []);
      expect(lands, `upright level 1, a cut at ${t} s`).toBe(inBasket);
      expect(play(0, [[t, 0]]).outcome, `upright level 1, a cut at ${t} s`).toBe(inBasket ? 'won' : 'lost');
    }
    expect(() => predictFlight(WIDE_LEVELS[0]!, 0, 0, 0, 0, -1, 0, [])).toThrow(/predictFlight: g/);
  });

  it("the upright room's first level (a phone) is won like the wide room's: a cut at the swing's far end drops the ball in", () => {
    // A stranger on a phone cut level 1 at the far end of the swing and missed right (the basket
    // stood left of that end, won only 1.8-2.26 s in, as the ball came back): now the basket is under
    // that end, and a cut on the way up to it or at it wins (scripts/lab-rope-cuts.mjs 1).
    const at = [1.0, 1.4, 1.8].map((t) => play(0, [[t, 0]], 0));
    for (const r of at) expect(r.outcome).toBe('won');
    expect(at.map((r) => r.stars)).toEqual([3, 3, 3]);
  });

  it('no level gives a star before the player acts: 8 s of swinging untouched catches none', () => {
    // Before, the swing alone caught 2 stars on levels 1 and 3 (by 1.4 s) and 1 on level 5 (0.15 s).
    for (const [set, levels] of [
      ['upright', LEVELS],
      ['wide', WIDE_LEVELS],
    ] as const)
      levels.forEach((_, i) => {
        const s = createRopeScene(i, DEFAULTS, levels);
        const g = new RopeGame(s);
        for (let k = 0; k < 60 * 8; k++) {
          step(s.world);
          g.update();
        }
        expect(g.stars(), `${set} level ${i + 1}`).toBe(0);
      });
  });

  it('a swipe cuts each rope it crosses once; a tap cuts the nearest rope within reach, and nothing beyond it', () => {
    const s = createRopeScene(3, DEFAULTS);
    const { world, ropes, ball } = s;
    // A horizontal swipe across the whole room at the height of the ropes' middles crosses all three.
    const y = 7.6;
    const made = cutRopes(world, ropes, ball, -2.6, y, 2.6, y);
    expect(made.map((c) => c.rope).sort()).toEqual([0, 1, 2]);
    // One link cut on each, and the link to the ball (the ball goes free of the piece below the cut).
    for (const r of ropes) {
      expect(r.links.filter((l) => !isAlive(world, l)).length).toBe(2);
      expect(isAlive(world, r.ballLink)).toBe(false);
    }
    // A tap 0.1 m beside the middle of a fresh level 1's rope cuts it within a 0.15 m reach, not within 0.05 m.
    const t = createRopeScene(0, DEFAULTS);
    const mid = t.ropes[0]!.bodies[Math.floor(t.ropes[0]!.bodies.length / 2)]!;
    const [mx, my] = ballAt(t.world, mid);
    expect(cutRopes(t.world, t.ropes, t.ball, mx + 0.1, my, mx + 0.1, my, 0.05)).toEqual([]);
    expect(cutRopes(t.world, t.ropes, t.ball, mx + 0.1, my, mx + 0.1, my, 0.15).length).toBe(1);
  });

  it('a fast swipe cuts a rope it passes within reach of anywhere along a move, not only at its end: one begun on the rope, one past its end', () => {
    // One pointer move of a fast finger (0.6 m: about 40 px on a phone): begun 0.02 m beside the
    // rope's middle and moving straight off it, and passing 0.1 m below the rope's last body past
    // the ball's side. Reach 0.2 m (a finger's 14 px). Measured only from the move's end point (0.6 m
    // off), neither cut (a scripted set of fast finger swipes passing within 14 px of level 1's rope:
    // 13 of 336 cut nothing; now none). Nothing is cut by a move that passes 0.3 m from the rope.
    const swipe = (x0: number, y0: number, x1: number, y1: number) => {
      const t = createRopeScene(0, DEFAULTS);
      const r = t.ropes[0]!;
      const [ax, ay] = r.anchor,
        [bx, by] = ballAt(t.world, t.ball);
      // The rope's line from the anchor to the ball: along it (u) and square to it (v).
      const d = Math.hypot(bx - ax, by - ay),
        ux = (bx - ax) / d,
        uy = (by - ay) / d;
      const at = (s: number, o: number): [number, number] => [ax + s * ux - o * uy, ay + s * uy + o * ux];
      const [px, py] = at(x0 * d, y0),
        [qx, qy] = at(x1 * d, y1);
      return cutRopes(t.world, t.ropes, t.ball, px, py, qx, qy, 0.2).length;
    };
    // From 0.02 m beside the middle straight off it to 0.62 m.
    expect(swipe(0.5, 0.02, 0.5, 0.62)).toBe(1);
    // Along the rope's line, 0.1 m to its side, from the rope's last tenth on past the ball, ending 0.6 m past its centre.
    expect(swipe(0.9, 0.1, 1 + 0.6 / 2.6, 0.1)).toBe(1);
    // The same moves 0.3 m from the rope: no cut.
    expect(swipe(0.5, 0.3, 0.5, 0.9)).toBe(0);
    expect(swipe(0.3, 0.3, 0.7, 0.3)).toBe(0);
  });

  it('a cut rope is two chains: the piece below the cut falls, the other hangs from the anchor', () => {
    const s = createRopeScene(0, DEFAULTS);
    for (let i = 0; i < 30; i++) step(s.world);
    cutMiddle(s, 0);
    const rope = s.ropes[0]!;
    const cut = rope.links.findIndex((l) => !isAlive(s.world, l));
    for (let i = 0; i < 60; i++) step(s.world);
    // The two bodies the cut link joined are now far apart (the rope's links are 0.125 m long): the
    // lower piece fell with the ball, the upper one hangs from the anchor.
    const above = ballAt(s.world, rope.bodies[cut - 1]!),
      below = ballAt(s.world, rope.bodies[cut]!);
    expect(Math.hypot(above[0] - below[0], above[1] - below[1])).toBeGreaterThan(1);
    const anchor = rope.anchor;
    expect(Math.hypot(above[0] - anchor[0], above[1] - anchor[1])).toBeLessThan(rope.links.length * 0.2);
  });
});

describe('lab-rope star windows', () => {
  // A stranger rated the lab 3 for fun at a desktop: a live cut had to fall in a star window a
  // tenth of a second wide (wide level 3: 3 stars only for a cut 1.70-1.78 s in; wide 4
  // 3.25-3.30 s; wide 1 1.90-2.14 s; upright 5 3.83-4.13 s; upright 3 1.00-1.36 s). The stars
  // now hang where a run of neighbouring cuts all carry the ball: each level's plan
  // (games/lab-rope/plans.ts) gives the run of last cuts measured in the engine every 0.02 s to win
  // all three, at least 0.44 s wide. Played here a step (0.02 s) inside each end, so a change of a
  // step's rounding in the physics does not fail the test, while stars moved off the flights do:
  // the two cuts tested are still at least 0.4 s apart.
  for (const [room, levels] of [
    ['upright', LEVELS],
    ['wide', WIDE_LEVELS],
  ] as const)
    for (const [i, level] of levels.entries())
      it(`${room} level ${i + 1} (${level.name}): all three stars for a last cut anywhere in a window at least 0.4 s wide`, () => {
        const [a, b] = plansOf(levels)[i]!.threeStars;
        const first = a + 0.02,
          last = b - 0.02;
        expect(last - first).toBeGreaterThanOrEqual(0.4 - 1e-9);
        for (const t of [first, last])
          expect(playPlan(levels, i, t), `a last cut at ${t.toFixed(2)} s`).toMatchObject({ outcome: 'won', stars: 3 });
      });

  for (const [room, levels] of [
    ['upright', LEVELS],
    ['wide', WIDE_LEVELS],
  ] as const)
    it(`the cue to cut shows in every 3-star window (${room} room): for at least 0.15 s of it a cut now lands and lights all three stars`, () => {
      // The page lights the stars a cut now would fly through and the basket's rim when it would land
      // (main.ts forecastCut: predictFlight from the swing, checked here in one run of the engine a
      // level). predictFlight keeps within 6 cm of the engine's flight, so near a window's edges, where
      // a star is caught by a few centimetres, the cue may stay dark; inside the window it lights all
      // three for 0.18 s (wide level 8) to 1.7 s (upright level 4).
      levels.forEach((level, i) => {
        const [a, b] = plansOf(levels)[i]!.threeStars;
        const within = forecastCuts(levels, i).filter((c) => c.t >= a - 1e-9 && c.t <= b + 1e-9);
        const run = widestRun(within, (c) => c.lands && c.stars.every(Boolean));
        const width = run ? run[1] - run[0] : -1;
        expect(width, `${room} level ${i + 1} (${level.name})`).toBeGreaterThanOrEqual(0.15);
      });
    });
});

describe('lab-rope cut ends', () => {
  it('a cut end is drawn short of its body, so the gap a cut leaves shows at once', () => {
    // A rope of 0.125 m links drawn 8.5 px wide at 100 px a metre (a desktop): the cut leaves 12.5 px
    // between the pieces' bodies, which round caps (4.25 + 1.25 px each) and the fibres (1.1 widths)
    // covered. Trimmed by CUT_END_TRIM widths each, the drawn ends are 12.5 + 4 widths apart.
    const w = 8.5,
      link = 12.5;
    const upper = trimPolyline([0, 0, 0, 12.5, 0, 25], 0, CUT_END_TRIM * w);
    const lower = trimPolyline([0, 25 + link, 0, 50 + link], CUT_END_TRIM * w, 0);
    const gap = lower[1]! - upper[upper.length - 1]!;
    expect(gap).toBeCloseTo(link + 2 * CUT_END_TRIM * w, 9);
    // What still shows past the caps and the fibres: more than a cord's width.
    expect(gap - 2 * (1.1 * w) - (w + 2.5)).toBeGreaterThan(w);
    // Its other end stays; a bend keeps its middle point; a piece shorter than the trims keeps a point.
    expect(upper).toEqual([0, 0, 0, 25 - CUT_END_TRIM * w]);
    expect(trimPolyline([0, 0, 10, 0, 10, 10], 5, 5)).toEqual([5, 0, 10, 0, 10, 5]);
    expect(trimPolyline([0, 0, 4, 0], 3, 1)).toEqual([3, 0, 3, 0]);
  });
});
