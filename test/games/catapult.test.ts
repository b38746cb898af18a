/**
 * Catapult rules (games/catapult/scene.ts), headless: castles stand under their own weight, a throw at
 * the angle from sin(2 theta) = g R / v^2 lands at the drag-free range, a weak throw stops on the
 * grass short of the castle, a strong hit on the castle breaks welds and scores, the levels differ
 * in materials and shape, and each can be cleared within its shots (games/catapult/solve.ts).
 */

import { createPhysicsWorld, isSleeping, type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import {
  angleForRange,
  buildLevel,
  cutArc,
  FIRST_PREVIEW_SHARE,
  flightPast,
  HELP_PREVIEW_SHARE,
  hasFallen,
  LAUNCH,
  LEVEL_COUNT,
  launch,
  launchVelocity,
  MISSES_FOR_FULL,
  MISSES_FOR_MORE,
  PREVIEW_DT,
  PROJECTILE_RADIUS,
  PULL,
  previewFlight,
  previewLimit,
  previewShare,
  pullFor,
  SHORT_PREVIEW_SHARE,
  surfaceAt,
  tally,
  worldOptions,
} from '../../games/catapult/scene';
import { LEVEL_SOLUTIONS, playThrows, searchLevel } from '../../games/catapult/solve';

const G = 9.81;
function level(n: number, jointStrength = 400): { w: PhysicsWorld; lv: ReturnType<typeof buildLevel> } {
  const w = createPhysicsWorld(worldOptions({ gravity: G }));
  return { w, lv: buildLevel(w, { level: n, seed: 1, gravity: G, jointStrength }) };
}

describe('catapult rules', () => {
  it('every castle stands for 3 s under its own weight: nothing falls, no weld breaks', () => {
    for (let n = 0; n < LEVEL_COUNT; n++) {
      const { w, lv } = level(n);
      for (let i = 0; i < 180; i++) step(w);
      expect(tally(w, lv)).toEqual({ fallen: 0, broken: 0, score: 0 });
    }
  });

  it('a throw at the computed angle lands at v^2 sin(2 theta) / g and reaches the castle', () => {
    // Empty sky (level 3's rampart starts past 14 m; the range aimed at is 8 m): the landing x where
    // the projectile comes back down through its launch height, interpolated between steps.
    const { w } = level(2);
    const v = 15,
      R = 8,
      theta = angleForRange(R, v, G);
    const [px, py] = pullFor(v, theta);
    const [vx, vy] = launchVelocity(px, py);
    expect(Math.hypot(vx, vy)).toBeCloseTo(v, 12);
    const ball = launch(w, vx, vy, 3);
    const P = w.components.Position,
      s = slotOf(ball);
    let prevX: number = LAUNCH.x,
      prevY: number = LAUNCH.y,
      land = Number.NaN;
    for (let i = 0; i < 600 && Number.isNaN(land); i++) {
      step(w);
      const x = P.x[s]!,
        y = P.y[s]!;
      if (i > 2 && prevY >= LAUNCH.y && y < LAUNCH.y) land = prevX + ((x - prevX) * (prevY - LAUNCH.y)) / (prevY - y);
      prevX = x;
      prevY = y;
    }
    // Drag-free: the time stepping alone differs from the parabola, by O(dt) in the flight time;
    // tolerance: the distance travelled in one step, vx dt (0.24 m here), 2% of the range.
    expect(Math.abs(land - LAUNCH.x - R)).toBeLessThan(vx * w.dt);

    // Aimed at the castle's front (a longer range at 24 m/s), the throw hits it: pieces fall.
    const h = level(0);
    for (let i = 0; i < 60; i++) step(h.w);
    const R2 = h.lv.castleMinX + 0.5 - LAUNCH.x,
      th2 = angleForRange(R2, 24, G);
    launch(h.w, 24 * Math.cos(th2), 24 * Math.sin(th2), 3);
    for (let i = 0; i < 300; i++) step(h.w);
    expect(tally(h.w, h.lv).fallen).toBeGreaterThan(0);
  });

  it('a strong hit breaks welds and scores 100 a fallen piece and 25 a broken weld', () => {
    const { w, lv } = level(0);
    for (let i = 0; i < 60; i++) step(w);
    const R = lv.castleMinX + 0.5 - LAUNCH.x,
      th = angleForRange(R, 26, G);
    launch(w, 26 * Math.cos(th), 26 * Math.sin(th), 8);
    for (let i = 0; i < 300; i++) step(w);
    const t = tally(w, lv);
    expect(t.broken).toBeGreaterThan(0);
    expect(t.fallen).toBeGreaterThan(0);
    expect(t.score).toBe(100 * t.fallen + 25 * t.broken);
  });

  it('a piece that fell stays counted when it is knocked back up: the score never drops', () => {
    // A playtester saw the score fall from 1550 to 1450 as a fallen piece was thrown back up.
    const { w, lv } = level(0);
    const P = w.components.Position;
    const p = lv.pieces[0]!,
      s = slotOf(p.body);
    P.y[s] = p.startY - 1;
    expect(tally(w, lv).fallen).toBe(1);
    P.y[s] = p.startY;
    expect(tally(w, lv)).toEqual({ fallen: 1, broken: 0, score: 100 });
  });

  it('a weak throw that lands short stops on the grass: it does not roll into the castle and score', () => {
    // A playtester scored 650 on level 1 with a short pull: the stone landed 3 m out and rolled on
    // into the tower. A pull of 1 m (7 m/s) at 15 degrees, on three seeds of level 1: drag-free it
    // lands 5.2 m out (from 1.5 m up); it stops within 1.2 m of there, short of the castle (past 6.8 m).
    const a = (15 * Math.PI) / 180,
      vx = 7 * Math.cos(a),
      vy = 7 * Math.sin(a);
    const land = (vx * (vy + Math.sqrt(vy * vy + 2 * G * LAUNCH.y))) / G;
    for (const seed of [1, 2, 3]) {
      const w = createPhysicsWorld(worldOptions({ gravity: G }));
      const lv = buildLevel(w, { level: 0, seed, gravity: G, jointStrength: 400 });
      const ball = launch(w, vx, vy, 3);
      for (let i = 0; i < 300; i++) step(w);
      const s = slotOf(ball);
      expect(tally(w, lv).score).toBe(0);
      expect(w.components.Position.x[s]! - land).toBeLessThan(1.2);
      expect(w.components.Position.x[s]!).toBeLessThan(lv.castleMinX - PROJECTILE_RADIUS);
      expect(Math.abs(w.components.Velocity.x[s]!)).toBeLessThan(0.05);
    }
  });

  it('a level left alone after two throws that missed does not score by itself: two minutes on, nothing has moved', () => {
    // Issue 34: kept awake, the castles crept and scored by themselves (two minutes, no throw: levels
    // 4, 5, 6, 8 and 9 scored 200, 400, 100, 600 and 675; level 1's crown stones rolled 0.28 m). A
    // castle left alone now sleeps a second after its build (measured 0.5 to 1.05 s) and stays put.
    // Here each level settles 1 s, takes a throw that lands short (7 m/s at 15 degrees, 5.2 m out)
    // and one that flies over it (21 m/s at 45 degrees, past the ground's end at 34 m), then 2 minutes
    // of steps. Bound: 1 mm from where each piece stood at the first throw; a sleeping piece does not
    // move at all, and the last settling before the castle sleeps measured under 0.005 mm (kept
    // awake, stones rolled 280 times as far; a piece counts as fallen at FALL_DROP = 0.6 m).
    const a = (15 * Math.PI) / 180;
    for (let n = 0; n < LEVEL_COUNT; n++) {
      const { w, lv } = level(n);
      const P = w.components.Position;
      for (let i = 0; i < 60; i++) step(w);
      const at = lv.pieces.map((p) => [P.x[slotOf(p.body)]!, P.y[slotOf(p.body)]!]);
      launch(w, 7 * Math.cos(a), 7 * Math.sin(a), 3);
      for (let i = 0; i < 120; i++) step(w);
      launch(w, 21 * Math.SQRT1_2, 21 * Math.SQRT1_2, 3);
      for (let i = 0; i < 120 * 60; i++) step(w);
      let moved = 0;
      lv.pieces.forEach((p, k) => {
        const s = slotOf(p.body);
        moved = Math.max(moved, Math.hypot(P.x[s]! - at[k]![0]!, P.y[s]! - at[k]![1]!));
      });
      expect(tally(w, lv), `level ${n + 1}`).toEqual({ fallen: 0, broken: 0, score: 0 });
      expect(moved, `level ${n + 1}`).toBeLessThan(1e-3);
      expect(
        lv.pieces.every((p) => isSleeping(w, p.body)),
        `level ${n + 1}`,
      ).toBe(true);
    }
  });

  it('nine levels of their own: wood, glass and stone in the mix, towers, a hall, a bridge, a hill and a pit', () => {
    // A playtester found the game short and samey (five levels of the same wooden towers).
    expect(LEVEL_COUNT).toBeGreaterThanOrEqual(8);
    const built = Array.from({ length: LEVEL_COUNT }, (_, n) => level(n).lv);
    const names = built.map((lv) => lv.name);
    expect(new Set(names).size).toBe(LEVEL_COUNT);
    const has = (lv: (typeof built)[number], kind: string) => lv.pieces.some((p) => p.kind === kind);
    // Glass in most levels, stone blocks in at least three, wood in every one.
    expect(built.filter((lv) => has(lv, 'block')).length).toBeGreaterThanOrEqual(6);
    expect(built.filter((lv) => has(lv, 'brick')).length).toBeGreaterThanOrEqual(3);
    expect(built.every((lv) => has(lv, 'plank'))).toBe(true);
    // A fort raised on a hill (its pieces standing 2 m up), ramparts of earth before levels 2 and 3, a tower
    // down in a pit (its foot below the ground), the others on flat ground.
    expect(built.filter((lv) => Math.min(...lv.pieces.map((p) => p.startY - p.half[1])) > 1.9).length).toBe(1);
    expect([1, 2].every((n) => built[n]!.terrain.some((t) => t.kind === 'hill' && t.maxX < built[n]!.castleMinX))).toBe(true);
    const pit = built.find((lv) => lv.terrain.some((t) => t.kind === 'pit'))!;
    expect(Math.min(...pit.pieces.map((p) => p.startY - p.half[1]))).toBeLessThan(-1);
    // Shots: never fewer as the levels go on, 3 to 5.
    const shots = built.map((lv) => lv.shots);
    expect(shots.every((s, i) => i === 0 || s >= shots[i - 1]!)).toBe(true);
    expect([shots[0], shots.at(-1)]).toEqual([3, 5]);
  });

  it('every level can be cleared within its shots: the throws found for it bring half its castle down', () => {
    // LEVEL_SOLUTIONS were found by scripts/catapult-levels.mjs (a greedy search over pull angle
    // and power, too slow for a test: a few seconds a level); here they are played again, each
    // 2.5 s after the last, counted 4 s after the last (as the page ends a level). Measured, seed 1:
    // levels 1 to 8 in one throw, level 9 in four. How hard each is (--spread, the castles asleep
    // when the throw lands): 11, 10, 7, 5, 3 and 2 of 36 single throws clear levels 4 to 9 (level 9
    // none since its keep stands behind banks: the next test); levels 1
    // to 3 (--grid, 195 throws, measured when castles were kept awake): 15, 10 and 7 % of throws
    // clear them, and no throw clears two of them.
    expect(LEVEL_SOLUTIONS.length).toBe(LEVEL_COUNT);
    LEVEL_SOLUTIONS.forEach((throws, n) => {
      const r = playThrows(n, 1, throws);
      expect(throws.length, `level ${n + 1}`).toBeLessThanOrEqual(level(n).lv.shots);
      expect(r.fallen, `level ${n + 1}`).toBeGreaterThanOrEqual(Math.ceil(r.pieces / 2));
    });
    // The search itself, on level 1 with a coarse grid: it finds a throw that clears it.
    const found = searchLevel(0, 1, { angles: [10, 20, 30], powers: [0.6, 0.75, 0.9], perThrow: 4 });
    expect(found.cleared).toBe(true);
    expect(found.throws.length).toBeLessThanOrEqual(3);
  });

  it('the last level (the fortress) needs a plan: no single throw that cleared it at one tower pitch clears it now', () => {
    // Measured with scripts/catapult-levels.mjs --grid 9 (195 single throws, 10 to 70 degrees by 5,
    // 30 to 100 % by 5), seed 1: with the towers one pitch apart and no banks 4 cleared it (15 deg
    // 80 %, 20 deg 85 and 90 %, 30 deg 80 %: one tower toppled the next), with the banks none does;
    // the four throws in LEVEL_SOLUTIONS (at the towers in turn) still clear it (test above).
    const last = LEVEL_COUNT - 1;
    for (const [angle, power] of [
      [15, 0.8],
      [20, 0.85],
      [20, 0.9],
      [30, 0.8],
    ] as const) {
      const r = playThrows(last, 1, [{ angle, power }]);
      expect(r.cleared, `${angle} deg ${power * 100} %: ${r.down} of ${r.counted} down`).toBe(false);
    }
    expect(LEVEL_SOLUTIONS[last]!.length).toBeGreaterThan(2);
  });

  it('a post knocked over on the ground has fallen, though it cannot drop: three stars are within reach', () => {
    const { w, lv } = level(0);
    const post = lv.pieces.find((p) => p.kind === 'post' && p.startY < 1)!;
    const s = slotOf(post.body);
    // Turned 80 degrees where it stands (its centre 0.45 m lower: less than FALL_DROP).
    w.components.Angle.value[s] = (80 * Math.PI) / 180;
    w.components.Position.y[s] = post.startY - 0.45;
    expect(hasFallen(w, post)).toBe(true);
    // Turned 20 degrees: still standing (down from TIP_ANGLE, 30 degrees); pushed 1.2 m along the ground: fallen.
    w.components.Angle.value[s] = (20 * Math.PI) / 180;
    w.components.Position.y[s] = post.startY;
    expect(hasFallen(w, post)).toBe(false);
    w.components.Position.x[s] = post.startX + 1.2;
    expect(hasFallen(w, post)).toBe(true);
  });

  it('down is what a player sees: a piece tipped 30 degrees, dropped a third of its height or knocked 0.8 m aside', () => {
    // Strangers saw a stall on level 1 lean and half collapse while the count stayed 3 / 9 (down was a
    // 0.6 m drop, a 60 degree tip or a 1 m knock). Each case here is set on a settled level-1 piece and
    // checked against the piece's own size: a post (1.2 m tall), its roof plank (0.24 m) and a stone.
    const { w, lv } = level(0);
    const P = w.components.Position,
      A = w.components.Angle.value;
    const post = lv.pieces.find((p) => p.kind === 'post')!,
      plank = lv.pieces.find((p) => p.kind === 'plank')!,
      stone = lv.pieces.find((p) => p.kind === 'stone')!;
    /** Whether piece p is down with its pose moved by (dx, dy) m and turned by da degrees from rest (then put back). */
    const downAfter = (p: (typeof lv.pieces)[number], dx: number, dy: number, da: number): boolean => {
      const s = slotOf(p.body);
      const was = [P.x[s]!, P.y[s]!, A[s]!] as const;
      P.x[s] = p.startX + dx;
      P.y[s] = p.startY + dy;
      A[s] = p.startAngle + (da * Math.PI) / 180;
      const down = hasFallen(w, p);
      [P.x[s], P.y[s], A[s]] = was;
      return down;
    };
    // Leaning: 20 degrees stands, 40 (either way) is down; a round stone may roll any amount.
    expect(downAfter(post, 0, 0, 20)).toBe(false);
    expect(downAfter(post, 0, 0, 40)).toBe(true);
    expect(downAfter(post, 0, 0, -40)).toBe(true);
    expect(downAfter(stone, 0, 0, 400)).toBe(false);
    // Sunk: a post's roof plank 0.2 m lower (its posts buckled) is down, 0.05 m is settling; a post
    // 0.5 m lower (over a third of its 1.2 m) is down, 0.3 m not.
    expect(downAfter(plank, 0, -0.2, 0)).toBe(true);
    expect(downAfter(plank, 0, -0.05, 0)).toBe(false);
    expect(downAfter(post, 0, -0.5, 0)).toBe(true);
    expect(downAfter(post, 0, -0.3, 0)).toBe(false);
    // Knocked: a stone rolled 0.9 m along its roof is off its place, 0.5 m is not.
    expect(downAfter(stone, 0.9, 0, 0)).toBe(true);
    expect(downAfter(stone, 0.5, 0, 0)).toBe(false);
    expect(tally(w, lv).fallen).toBe(0);

    // A stall knocked down for real: a throw at 5 degrees and half power (10.5 m/s) into the near
    // stall. 3 s on, its plank has come down below half its height above the ground (a visible
    // collapse, measured here without hasFallen): the plank and both posts count, and none of the far
    // stall's pieces (untouched, more than 3 m behind) does.
    const s = slotOf(plank.body);
    const stall = lv.pieces.filter((p) => Math.abs(p.startX - plank.startX) < 1.5 && p.kind !== 'stone');
    const a = (5 * Math.PI) / 180;
    launch(w, 10.5 * Math.cos(a), 10.5 * Math.sin(a), 3);
    for (let i = 0; i < 180; i++) {
      step(w);
      tally(w, lv);
    }
    expect(P.y[s]!).toBeLessThan(plank.startY / 2);
    expect(stall.length).toBe(3);
    expect(stall.every((p) => p.down)).toBe(true);
    expect(lv.pieces.filter((p) => p.startX > plank.startX + 3).some((p) => p.down)).toBe(false);
  });

  it('a castle only settling is never down: ten seconds untouched, no piece counts on any level', () => {
    // The resting poses are taken once the new castle sleeps (settleLevel); before, a castle's pieces
    // settled by under 5 mm in their first second, far inside DROP_MIN (0.15 m) and TIP_ANGLE.
    for (let n = 0; n < LEVEL_COUNT; n++) {
      const { w, lv } = level(n);
      expect(
        lv.pieces.every((p) => isSleeping(w, p.body)),
        `level ${n + 1} settled`,
      ).toBe(true);
      for (let i = 0; i < 600; i++) {
        step(w);
        if (i % 30 === 0) tally(w, lv);
      }
      expect(tally(w, lv).fallen, `level ${n + 1}`).toBe(0);
      expect(lv.pieces.some((p) => hasFallen(w, p))).toBe(false);
    }
  });

  it('the aim preview ends where the stone first touches something: within 0.25 m on every level', () => {
    // The preview (previewFlight, the game's dotted arc) against the engine's flight of the same
    // throw: the stone's first touch is the step its velocity leaves free flight (vx changes, or vy
    // stops following vy0 - g t), somewhere on that step's segment. A throw that grazes a corner or
    // a top (the preview with the stone 5 cm larger or smaller ends more than 0.3 m elsewhere)
    // may or may not touch there and is left out. Before, the preview ended at a hill's side face
    // 0.3 m late (the hill was tested only from above) and at a box's corner up to 0.12 m early.
    let compared = 0;
    for (let n = 0; n < LEVEL_COUNT; n++) {
      for (const [power, deg] of [
        [0.5, 25],
        [0.58, 40],
        [0.65, 30],
        [0.7, 55],
      ] as const) {
        const { w, lv } = level(n);
        for (let i = 0; i < 30; i++) step(w);
        const a = (deg * Math.PI) / 180,
          d = power * PULL.max;
        const [vx, vy] = launchVelocity(-d * Math.cos(a), -d * Math.sin(a));
        const end = (r: number): [number, number] => {
          const arc = previewFlight(w, lv, vx, vy, G, 6, r);
          return [arc[arc.length - 2]!, arc[arc.length - 1]!];
        };
        const [px, py] = end(PROJECTILE_RADIUS);
        const wide = end(PROJECTILE_RADIUS + 0.05),
          narrow = end(PROJECTILE_RADIUS - 0.05);
        if (Math.hypot(wide[0] - px, wide[1] - py) > 0.3 || Math.hypot(narrow[0] - px, narrow[1] - py) > 0.3) continue;
        const ball = launch(w, vx, vy, 3);
        const s = slotOf(ball),
          P = w.components.Position,
          V = w.components.Velocity;
        const t0 = w.time;
        let gap = Number.POSITIVE_INFINITY;
        for (let i = 0; i < 600 && gap === Number.POSITIVE_INFINITY; i++) {
          const x0 = P.x[s]!,
            y0 = P.y[s]!;
          step(w);
          if (Math.abs(V.x[s]! - vx) < 0.05 && Math.abs(V.y[s]! - (vy - G * (w.time - t0))) < 0.1) continue;
          // Distance from the preview's end to this step's segment of the flight.
          const ex = P.x[s]! - x0,
            ey = P.y[s]! - y0;
          const u = Math.max(0, Math.min(1, ((px - x0) * ex + (py - y0) * ey) / Math.max(1e-12, ex * ex + ey * ey)));
          gap = Math.hypot(x0 + u * ex - px, y0 + u * ey - py);
        }
        expect(
          gap,
          `level ${n + 1}, ${power * 100} % at ${deg}°: preview ends at (${px.toFixed(2)}, ${py.toFixed(2)})`,
        ).toBeLessThanOrEqual(0.25);
        compared++;
      }
    }
    // Grazes are rare: nearly every aim is compared.
    expect(compared).toBeGreaterThanOrEqual(30);
  });

  it("past the preview's first touch, the faint flight goes on through a bank to where it comes down on the grass", () => {
    // Level 2, 80 % level: the preview ends on the earth bank's face (issue 34: a long throw's
    // preview stopped there and the player could not see where it was headed). The faint
    // flight (flightPast) starts at that end and ends where the drag-free parabola brings the stone's
    // bottom down to the grass (y = r), solved here in closed form, to one preview step.
    const { w, lv } = level(1);
    const a = 0,
      v = 0.8 * PULL.max * PULL.gain;
    const vx = v * Math.cos(a),
      vy = v * Math.sin(a);
    const arc = previewFlight(w, lv, vx, vy, G);
    const ex = arc[arc.length - 2]!,
      ey = arc[arc.length - 1]!;
    const hill = lv.terrain.find((t) => t.kind === 'hill')!;
    expect(Math.abs(ex + PROJECTILE_RADIUS - hill.minX)).toBeLessThan(0.01);
    const past = flightPast(lv, vx, vy, G, (ex - LAUNCH.x) / vx);
    expect(Math.hypot(past[0]! - ex, past[1]! - ey)).toBeLessThan(1e-9);
    const rise = LAUNCH.y - PROJECTILE_RADIUS;
    const t = (vy + Math.sqrt(vy * vy + 2 * G * rise)) / G;
    const landX = LAUNCH.x + vx * t;
    expect(landX).toBeGreaterThan(hill.maxX);
    expect(Math.abs(past[past.length - 2]! - landX)).toBeLessThanOrEqual(vx * PREVIEW_DT);
    expect(() => flightPast(lv, vx, vy, G, -1)).toThrow(/flightPast: t0 must be >= 0 s, got -1/);
  });

  it('on the hill fort, the faint flight past a piece on the hill ends on the hill top, never inside it', () => {
    // Level 6 (issue 34): a throw that touches a post or the tower on the 2 m hill first had its faint
    // flight go on down into the hill's earth (the hill was not ground to it). For a sweep of throws
    // whose first touch is at or over the hill's top, no faint point may have the stone's bottom
    // under the surface there (surfaceAt: the hill's top or the grass) by more than 2 mm.
    const { w, lv } = level(5);
    const hill = lv.terrain.find((t) => t.kind === 'hill')!;
    let checked = 0,
      onHill = 0;
    for (let deg = 0; deg <= 60; deg += 4) {
      for (let f = 0.3; f <= 1.001; f += 0.05) {
        const v = f * PULL.max * PULL.gain,
          a = (deg * Math.PI) / 180;
        const vx = v * Math.cos(a),
          vy = v * Math.sin(a);
        const arc = previewFlight(w, lv, vx, vy, G);
        const ex = arc[arc.length - 2]!,
          ey = arc[arc.length - 1]!;
        if (ey - PROJECTILE_RADIUS < hill.maxY - 0.01) continue;
        checked++;
        const past = flightPast(lv, vx, vy, G, (ex - LAUNCH.x) / vx);
        const lastX = past[past.length - 2]!;
        if (lastX >= hill.minX && lastX <= hill.maxX) onHill++;
        for (let i = 0; i < past.length; i += 2) {
          const x = past[i]!,
            y = past[i + 1]!;
          expect(y - PROJECTILE_RADIUS, `${deg} deg, ${f.toFixed(2)} pull, faint point at x=${x.toFixed(2)} m`).toBeGreaterThanOrEqual(
            surfaceAt(lv, x) - 2e-3,
          );
        }
      }
    }
    expect(checked).toBeGreaterThan(10);
    expect(onHill).toBeGreaterThan(3);
  });

  it('the aim preview shows only the start of the flight, never where it comes down, and more after repeated misses', () => {
    // Issue 34: aimed along the whole preview, two in three throws whose dots ended on level 2's keep
    // cleared it, and a stranger whose first level drew the dots into the castle took three stars on
    // both first levels with three throws. Every level shows at most FIRST_PREVIEW_SHARE (level 1) or
    // SHORT_PREVIEW_SHARE (the rest) of the way to the castle's front; after MISSES_FOR_MORE throws
    // that brought nothing down HELP_PREVIEW_SHARE, after MISSES_FOR_FULL the whole flight. On level
    // 2 every throw of a sweep ends on the drag-free parabola
    // y = y0 + x tan(a) - g x^2 / (2 v^2 cos^2 a) (closed form; 1 mm: the cut is interpolated
    // between two 0.01 s steps, an error of g dt^2 / 8 = 0.1 mm), and a throw into the ground before
    // that point keeps its whole flight to the touch.
    const first = level(0);
    const firstLimit = previewLimit(0, first.lv);
    expect(firstLimit).toBeCloseTo(LAUNCH.x + FIRST_PREVIEW_SHARE * (first.lv.castleMinX - LAUNCH.x), 12);
    // Short of the near stall by more than 3 m: the dots end on the rise, not on the stall.
    expect(firstLimit).toBeLessThan(first.lv.castleMinX - 3);
    const { w, lv } = level(1);
    expect(previewLimit(1, lv, true)).toBe(Number.POSITIVE_INFINITY);
    const limit = previewLimit(1, lv);
    expect(limit).toBeCloseTo(LAUNCH.x + SHORT_PREVIEW_SHARE * (lv.castleMinX - LAUNCH.x), 12);
    expect(limit).toBeLessThan(lv.castleMinX - 3);
    // Help grows with misses: the same before MISSES_FOR_MORE, farther (still short of the castle)
    // until MISSES_FOR_FULL, then the whole flight.
    for (const l of [0, 1]) {
      const c = level(l).lv;
      expect(previewLimit(l, c, false, MISSES_FOR_MORE - 1)).toBe(previewLimit(l, c));
      const more = previewLimit(l, c, false, MISSES_FOR_MORE);
      expect(more).toBeGreaterThan(previewLimit(l, c));
      expect(more).toBeLessThan(c.castleMinX);
      expect(previewLimit(l, c, false, MISSES_FOR_FULL - 1)).toBe(more);
      expect(previewLimit(l, c, false, MISSES_FOR_FULL)).toBe(Number.POSITIVE_INFINITY);
    }
    expect(previewShare(1, 2)).toBe(HELP_PREVIEW_SHARE);
    expect(() => previewShare(1, -1)).toThrow(/previewShare: misses must be an integer >= 0, got -1/);
    let cutCount = 0;
    for (let deg = 0; deg <= 70; deg += 5)
      for (let f = 0.3; f <= 1.001; f += 0.1) {
        const v = f * PULL.max * PULL.gain,
          a = (deg * Math.PI) / 180;
        const flight = previewFlight(w, lv, v * Math.cos(a), v * Math.sin(a), G);
        const arc = cutArc(flight, limit);
        const ex = arc[arc.length - 2]!,
          ey = arc[arc.length - 1]!;
        expect(ex).toBeLessThanOrEqual(limit + 1e-12);
        if (arc === flight) {
          // Uncut: it came down before the limit (on the grass: the stone's bottom at y = 0).
          expect(ey - PROJECTILE_RADIUS).toBeLessThan(0.01);
          continue;
        }
        cutCount++;
        expect(ex).toBeCloseTo(limit, 12);
        const x = ex - LAUNCH.x;
        const parabola = LAUNCH.y + x * Math.tan(a) - (G * x * x) / (2 * v * v * Math.cos(a) ** 2);
        expect(Math.abs(ey - parabola)).toBeLessThan(1e-3);
      }
    expect(cutCount).toBeGreaterThan(80);
    expect(() => previewLimit(LEVEL_COUNT, lv)).toThrow(/previewShare: level must be an integer in \[0, \d+\), got \d+/);
  });

  it('rejects a level out of range', () => {
    const w = createPhysicsWorld(worldOptions({ gravity: G }));
    expect(() => buildLevel(w, { level: LEVEL_COUNT, seed: 1, gravity: G, jointStrength: 400 })).toThrow(
      /buildLevel: level must be an integer/,
    );
  });
});
