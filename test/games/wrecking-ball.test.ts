/**
 * The wrecking-ball scene, headless: seeded levels, structures that stand on their own, a crane that
 * moves at its rated speeds, and a swing of the ball through a tower that knocks it down and scores.
 */

import {
  addBody,
  addDistanceJoint3D,
  contactEvents,
  createPhysicsWorld,
  isSleeping,
  removeBody,
  removeJoint3D,
  slotOf,
  step,
} from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { ScoreTally, TALLY_TIME } from '../../games/wrecking-ball/effects';
import {
  aimAt,
  BALL_RADIUS,
  BALL_TONNES,
  buildWreckingBall,
  clearShare,
  clearTarget,
  FULL_SWING_SPEED,
  fallenCount,
  HANG,
  HIT_SPEED,
  HOOK_RANGE,
  pieceOnSwing,
  powerWords,
  SLEW_RATE,
  STRIKE_SHARE,
  scorePieces,
  swayAmplitude,
  swingBudget,
  swingPar,
  swingSpeed,
  swingStars,
  wreckingBallWorldOptions,
} from '../../games/wrecking-ball/scene';

function build(level: number, seed = 1) {
  const world = createPhysicsWorld(wreckingBallWorldOptions());
  return { world, h: buildWreckingBall(world, { level, seed }) };
}

/**
 * Level `level` built, settled for 0.5 s with the ball hanging still and swung at piece `index`: the
 * planned swing (`aimAt`) takes under `most` s (default 5; measured 4.4 s at level 1's tower) from
 * the tap to the hit.
 */
function tapped(level: number, index: number, most = 5) {
  const { world, h } = build(level);
  for (let k = 0; k < 30; k++) step(world);
  aimAt(world, h, h.pieces[index]!.body);
  // Time to the arrival (the follow-through after it not counted).
  const time = h.controls.moves.reduce((t, m) => t + (m.follow ? 0 : m.duration), 0);
  expect(time).toBeLessThan(most);
  expect(h.controls.moves.at(-1)!.run).toBe(true);
  return { world, h, time };
}

describe('wrecking-ball scene', () => {
  it('builds the same level from the same seed and another from another level', () => {
    const a = build(2),
      b = build(2),
      c = build(3);
    const at = (x: ReturnType<typeof build>) =>
      x.h.pieces.map((p) => [x.world.components.Position.x[p.body], x.world.components.Position.z[p.body]]);
    expect(at(a)).toEqual(at(b));
    expect(at(c)).not.toEqual(at(a));
    expect(() => build(0)).toThrow(/level must be an integer >= 1, got 0/);
  });

  it('the clear target counts the pieces that stood above the ground, not the bottom row', () => {
    // A playtester flattened level 1 and stayed at 16 of the 19 then needed (70% of 27): its lowest
    // bricks, logs and blocks lay where they stood. The target is a share of the raised pieces, so
    // the raised pieces alone can clear any level: 75% on levels 1 to 3 (at 45% a careless swing
    // cleared level 1 for three stars, at 50% a swing aimed at the plank stack did, at 65% a
    // stranger's first drag did), then 76% (see clearShare, swingPar).
    expect([1, 2, 3, 4, 5, 9].map(clearShare)).toEqual([0.75, 0.75, 0.75, 0.76, 0.76, 0.76]);
    expect(() => clearShare(0)).toThrow(/level must be an integer >= 1, got 0/);
    for (let level = 1; level <= 5; level++) {
      const { h } = build(level);
      const onGround = h.pieces.filter((p) => Math.abs(p.y0 - p.half[1]) < 1e-9).length;
      expect(onGround).toBeGreaterThan(0);
      expect(clearTarget(h.pieces, level)).toBe(Math.ceil(clearShare(level) * (h.pieces.length - onGround)));
    }
    // Level 1: 27 pieces, 6 of them on the ground; 16 of the 21 raised clear it.
    expect(clearTarget(build(1).h.pieces, 1)).toBe(16);
  });

  it('keeps every structure standing without a hit, and slews with the mass of a crane: a ramp up, a coast, a brake', () => {
    const { world, h } = build(1);
    const P = world.components.Position;
    const start = h.pieces.map((p) => [P.x[p.body]!, P.y[p.body]!, P.z[p.body]!] as const);
    // The ball hangs still, 1.5 m or more from every piece, so nothing may fall. Untouched, every
    // piece comes to rest and sleeps (skipped by the solver until something wakes it), within 2 s
    // (measured: all asleep after 31 steps): from then on nothing can move on its own.
    let steps = 0;
    while (steps < 120 && !h.pieces.every((p) => isSleeping(world, p.body))) {
      step(world);
      scorePieces(world, h.pieces);
      steps++;
    }
    expect(h.pieces.every((p) => isSleeping(world, p.body))).toBe(true);
    // A piece falls when it drops 0.4 m or tips 60 degrees: none does, and a settling stack moves millimetres.
    expect(fallenCount(h.pieces)).toBe(0);
    let moved = 0;
    h.pieces.forEach((p, i) => {
      moved = Math.max(moved, Math.hypot(P.x[p.body]! - start[i]![0], P.y[p.body]! - start[i]![1], P.z[p.body]! - start[i]![2]));
    });
    // Each piece's centre within 1 cm of where it was built (measured 1.5 mm at most, 27 pieces).
    expect(moved).toBeLessThan(0.01);
    // Then the crane slews: the trolley is kinematic and follows the crane state exactly. The jib
    // has mass: from rest it speeds up evenly to SLEW_RATE in 0.5 s (turning SLEW_RATE / 4, the
    // area under the ramp), then turns at SLEW_RATE (0.5 s more: SLEW_RATE / 2); let go, it coasts
    // to a stop in 0.7 s (SLEW_RATE * 0.7 / 2 more) and stays; driven back, it brakes from full
    // speed to rest in 0.25 s. Each within a substep's turn at full rate (the ramp steps once a
    // substep, 1/240 s).
    const a0 = h.crane.angle;
    const tol = SLEW_RATE / 240;
    const turn = (steps: number): number => {
      const before = h.crane.angle;
      for (let i = 0; i < steps; i++) {
        step(world);
        scorePieces(world, h.pieces);
      }
      return h.crane.angle - before;
    };
    h.controls.slew = 1;
    expect(Math.abs(turn(30) - SLEW_RATE / 4)).toBeLessThan(tol);
    expect(Math.abs(turn(30) - SLEW_RATE / 2)).toBeLessThan(tol);
    expect(h.drive.slew).toBeCloseTo(SLEW_RATE, 9);
    h.controls.slew = 0;
    expect(Math.abs(turn(42) - (SLEW_RATE * 0.7) / 2)).toBeLessThan(tol);
    expect(Math.abs(h.drive.slew)).toBeLessThan(1e-12);
    expect(Math.abs(turn(2))).toBeLessThan(1e-12);
    h.controls.slew = 1;
    turn(30);
    expect(h.drive.slew).toBeCloseTo(SLEW_RATE, 9);
    h.controls.slew = -1;
    expect(Math.abs(turn(15) - (SLEW_RATE * 0.25) / 2)).toBeLessThan(tol);
    expect(h.drive.slew).toBeLessThanOrEqual(0);
    expect(h.crane.angle).not.toBe(a0);
    expect(fallenCount(h.pieces)).toBe(0);
  });

  it('holding Steady (anti-sway) stops the swing a slew leaves: the hook catches the ball', () => {
    // The player slews at full rate for 1 s and lets go (the ball swings on), taps a tower block and
    // taps two others during the wind-up. Each tap re-aims the same swing: `released` counts only the
    // ball let go into its run, once (a swing counted at each tap left the player 2 of 4 here).
    const { world, h } = build(1);
    for (const p of h.pieces) removeBody(world, p.body);
    const P = world.components.Position,
      t = h.trolley;
    const amplitude = () => swayAmplitude(world, h);
    h.controls.slew = 1;
    for (let i = 0; i < 60; i++) step(world);
    h.controls.slew = 0;
    const left = amplitude(),
      x0 = P.x[t]!,
      z0 = P.z[t]!;
    h.controls.steady = true;
    for (let i = 0; i < 120; i++) step(world);
    expect(left).toBeGreaterThan(1.5);
    expect(amplitude() / left).toBeLessThan(0.35);
    expect(Math.hypot(P.x[t]! - x0, P.z[t]! - z0)).toBeLessThan(3);
  });

  it('a hard drag does not stretch the chain, and the ball does not pass through the mast', () => {
    // The page drags the ball with a 2 Hz spring (BodyDrag3D: hertz 2, damping 1). Pulled toward
    // points 3 to 10 m away for 1 s, the hook-to-ball distance stays within 2 % of its rest
    // (measured with damping 0.3: 0.1 to 0.4 %, at its most 6 to 8 steps into the pull: the chain's
    // rope from hook to ball carries the pull; a tester saw the chain at 1.7 times its length).
    // Pulled at the mast from the far side for 1 s, the ball stops against it: its centre no closer
    // to the mast's axis than the mast's half width plus the ball's radius (0.95 m; measured 0.949,
    // 11 steps in, damping 0.3).
    // One world, the level's pieces taken away (the pulls are about the chain and the mast), pulled
    // three times in turn (at the mast first, from rest), each pull's spring removed before the next.
    const { world, h } = build(1);
    for (const p of h.pieces) removeBody(world, p.body);
    const P = world.components.Position;
    const b = slotOf(h.ball),
      t = slotOf(h.trolley);
    const span = () => Math.hypot(P.x[b]! - P.x[t]!, P.y[b]! - P.y[t]!, P.z[b]! - P.z[t]!);
    const rest = span();
    /** Pulls the ball toward `target` with the page's spring for 1 s, calling `each` after every step. */
    const pull = (target: number[], each: () => void): void => {
      const anchor = addBody(world, { position: target, static: true });
      const spring = addDistanceJoint3D(world, {
        a: anchor,
        b: h.ball,
        anchorA: target,
        anchorB: [P.x[b]!, P.y[b]!, P.z[b]!],
        length: 0.01,
        minLength: 0,
        hertz: 2,
        dampingRatio: 1,
      });
      for (let i = 0; i < 60; i++) {
        step(world);
        each();
      }
      removeJoint3D(world, spring);
      removeBody(world, anchor);
    };
    // The mast first, from rest.
    let closest = Infinity;
    pull([-P.x[b]!, P.y[b]!, -P.z[b]!], () => {
      closest = Math.min(closest, Math.max(Math.abs(P.x[b]!), Math.abs(P.z[b]!)));
    });
    for (const far of [3, 10]) {
      let most = 0;
      pull([P.x[b]! + far, P.y[b]! - 1, P.z[b]! + 2], () => {
        most = Math.max(most, span());
      });
      expect(most / rest).toBeLessThan(1.02);
    }
    expect(closest).toBeGreaterThan(0.4 + 0.55 - 0.02);
  });

  it('a swing through the tower knocks it down and scores', () => {
    const probe = build(1);
    const P0 = probe.world.components.Position;
    const first = probe.h.pieces.find((p) => p.kind === 'tower')!.body;
    const angle = Math.atan2(-P0.z[first]!, P0.x[first]!),
      radius = Math.hypot(P0.x[first]!, P0.z[first]!);
    // The crane starts 0.6 rad before the tower at its radius, the hook all the way down; it slews through it.
    const world = createPhysicsWorld(wreckingBallWorldOptions());
    const h = buildWreckingBall(world, { level: 1, crane: { angle: angle - 0.6, radius, height: HOOK_RANGE[0] } });
    const tower = h.pieces.filter((p) => p.kind === 'tower');
    h.controls.slew = 1;
    let score = 0;
    for (let i = 0; i < 130; i++) {
      step(world);
      score += scorePieces(world, h.pieces);
    }
    // The 5.4 t ball (on the hook's path, lagging behind it) sweeps the tower's lower blocks out.
    const down = tower.filter((p) => p.fallen).length;
    expect(down).toBeGreaterThanOrEqual(Math.ceil(tower.length / 2));
    expect(score).toBeGreaterThan(10 * down);
  });

  it('a tap on a piece swings the ball into it: one swing at the tower of level 1 brings most of it down', () => {
    // The playtester's complaint: sending the hook with a click knocked nothing down in 30 s. aimAt
    // plans the hook's legs so the ball reaches the piece at HIT_SPEED with the hook over it.
    // Measured: 5 of 5 tower blocks down.
    const index = build(1).h.pieces.findIndex((p) => p.kind === 'tower') + 2;
    const { world, h } = tapped(1, index);
    const tower = h.pieces.filter((p) => p.kind === 'tower');
    expect(h.pieces[index]!.kind).toBe('tower');
    // Up to 10 s, until the swing is over and half the tower is down.
    for (let k = 0; k < 60 * 10; k++) {
      step(world);
      scorePieces(world, h.pieces);
      if (h.controls.moves.length === 0 && tower.filter((p) => p.fallen).length >= Math.ceil(tower.length / 2)) break;
    }
    expect(h.controls.moves.length).toBe(0);
    expect(tower.filter((p) => p.fallen).length).toBeGreaterThanOrEqual(Math.ceil(tower.length / 2));
  });

  it('a tap on the top plank of level 1 (the stack), as the hint says: the ball swings through the stack and comes to rest past it', () => {
    // A playtester tapped the plank stack of level 1 as the hint says: the ball came to rest on the
    // stack (its top two layers knocked off, the hook left over it) and lost the level. The swing now
    // strikes low in the stack (STRIKE_SHARE of its height) and the hook follows through past it.
    // Measured: 10 of 12 planks down, the ball never nearer the stack's middle than 2.0 m once the
    // moves are over (before: 4 of 12, the ball 0.6 m from the middle, 2.7 m up: on the stack).
    const { world, h } = build(1);
    for (let k = 0; k < 30; k++) step(world);
    const stack = h.pieces.filter((p) => p.kind === 'planks');
    const top = stack.reduce((a, b) => (b.y0 > a.y0 ? b : a));
    const mx = stack.reduce((a, p) => a + p.x0, 0) / stack.length,
      mz = stack.reduce((a, p) => a + p.z0, 0) / stack.length;
    aimAt(world, h, top.body);
    // Until the swing's moves are over and 2 s more (at most 12 s): how near the stack's middle the
    // ball comes in those 2 s.
    const P = world.components.Position,
      b = h.ball;
    let after = 0,
      nearest = Number.POSITIVE_INFINITY;
    for (let k = 0; k < 60 * 12 && after < 120; k++) {
      step(world);
      scorePieces(world, h.pieces);
      if (h.controls.moves.length > 0) continue;
      after++;
      nearest = Math.min(nearest, Math.hypot(P.x[b]! - mx, P.z[b]! - mz));
    }
    const down = stack.filter((p) => p.fallen).length;
    // Most of the stack down: as many as the level's clearing share of its raised layers.
    expect(down).toBeGreaterThanOrEqual(Math.ceil(0.7 * (stack.length - 2)));
    // The ball swings clear of where the stack stood: its sides are 1.2 m from its middle (the
    // planks' half length; 1.6 m at its corners).
    expect(nearest).toBeGreaterThan(1.2 + BALL_RADIUS);
  });

  it('a tap on a brick in the middle of a wall: the ball reaches that brick, not the end of the wall', () => {
    // The swing used to run along the jib's arc, which runs along a wall (walls stand across the
    // swing about the mast): the ball hit the end brick and stopped 0.6 to 2.8 m short of the brick
    // tapped. The ball now comes from the side with the fewest pieces in the way, and reaches the
    // brick's place in the wall by the plan's end and a second: its centre, across the ground, within
    // 0.1 m of touching the face of the brick where it stood (the ball strikes low in the wall, at
    // most STRIKE_SHARE of its height, so the brick's own height is not the measure). A ball stopped
    // at the wall's end, 0.6 m or more along it, is 0.25 m or more short of that.
    for (const [level, index] of [
      [1, 5],
      [2, 20],
      [4, 14],
    ] as const) {
      // A wall across the site from the crane's start: up to 6 s (measured 4.8 s).
      const { world, h, time } = tapped(level, index, 6);
      const brick = h.pieces[index]!;
      expect(brick.kind).toBe('wall');
      const P = world.components.Position,
        b = h.ball;
      // Up to the plan's end and a second, until the ball reaches the brick's place: the gap across
      // the ground from the ball's surface to the brick's face (its half thickness from its centre).
      let gap = Number.POSITIVE_INFINITY;
      for (let k = 0; k < 60 * (time + 1) && gap >= 0.1; k++) {
        step(world);
        gap = Math.min(gap, Math.hypot(P.x[b]! - brick.x0, P.z[b]! - brick.z0) - BALL_RADIUS - brick.half[2]);
      }
      expect(gap, `level ${level} piece ${index}`).toBeLessThan(0.1);
    }
  });

  // Up to 30 s of play: a minute and more on a loaded machine (the default 60 s timed out there).
  it('a first-time player tapping the top of each structure in turn clears level 1 within its swings', { timeout: 300_000 }, () => {
    // Each tap aims at the highest standing piece of the next structure (pieces whose start centres
    // lie within 2.5 m of each other) that still has one, 2 s after the last swing's moves are over
    // (once the count has settled): what the eye goes to, not the best plan. At 70% of the raised
    // pieces (15) this took 5 swings (5, 11, 11, 14, 15 down), one more than the level allowed: a
    // first-time player lost level 1 twice. At 45% (10) the script's way of this
    // (scripts/wrecking-ball-par.mjs, first taps a few steps apart) takes 2 swings: 5 down, then 14 to 16.
    // At 75% (16, with 5 swings) the script's way takes 4: 2, 10, 15, 25 down. Each swing is the
    // page's (a request: struck at the block's own height, see aimAt), not one planned to strike low.
    const { world, h } = build(1);
    const groups: (typeof h.pieces)[] = [];
    for (const p of h.pieces) {
      const g = groups.find((q) => Math.hypot(q[0]!.x0 - p.x0, q[0]!.z0 - p.z0) < 2.5);
      if (g) g.push(p);
      else groups.push([p]);
    }
    let swings = 0,
      wait = 30,
      clearedAt = -1;
    for (let k = 0; k < 60 * 30 && clearedAt < 0; k++) {
      if (h.controls.moves.length === 0 && --wait <= 0 && swings < swingBudget(1)) {
        const live = groups.filter((g) => g.some((p) => !p.fallen));
        const top = live[swings % live.length]!.filter((p) => !p.fallen).reduce((a, b) => (b.y0 > a.y0 ? b : a));
        // As the page swings at a block tapped twice: from where the ball hangs, at the tap's power.
        const P = world.components.Position;
        const direction = Math.atan2(P.z[top.body]! - P.z[h.ball]!, P.x[top.body]! - P.x[h.ball]!);
        aimAt(world, h, top.body, { direction, speed: 0.8 * HIT_SPEED });
        swings++;
        wait = 120;
      }
      step(world);
      scorePieces(world, h.pieces);
      if (fallenCount(h.pieces) >= clearTarget(h.pieces, 1)) clearedAt = k / 60;
    }
    expect(clearedAt).toBeGreaterThan(0);
    expect(swings).toBeLessThanOrEqual(swingBudget(1));
  });

  it('the swing of a held ball, let go: it meets the tower its line reaches, and nothing when pulled short', () => {
    // The drag's red ring (pieceOnSwing): a hook 2 m from level 1's tower, toward the mast, its
    // height putting the ball's lowest point 0.6 m up (the tower's blocks are 0.7 m cubes). Pulled
    // 2.5 m back from under the hook, the ball swings on past it at speed (SWING_REACH of 2.5 m:
    // 1.9 m) into the tower's foot, whose face is 1.65 m past the hook; pulled 1 m, it turns back
    // 1 m past the hook, short of the block by more than the ball's 0.55 m radius.
    const { world, h } = build(1);
    const tower = h.pieces.filter((p) => p.kind === 'tower');
    const foot = tower.reduce((a, b) => (b.y0 < a.y0 ? b : a));
    const n = Math.hypot(foot.x0, foot.z0),
      ux = -foot.x0 / n,
      uz = -foot.z0 / n;
    const hook = [foot.x0 + 2 * ux, HANG + 0.6, foot.z0 + 2 * uz];
    const pulled = (d: number) => [hook[0]! + d * ux, hook[1]! - Math.sqrt(HANG * HANG - d * d), hook[2]! + d * uz];
    expect(tower.map((p) => p.body)).toContain(pieceOnSwing(world, h.pieces, pulled(2.5), hook));
    expect(pieceOnSwing(world, h.pieces, pulled(1), hook)).toBe(0);
  });

  it('pieces that fall together score one popup: a collapsing tower shows its sum once, not a pile of labels', () => {
    // A tower's five blocks fall within 0.4 s of each other, a wall's brick 6 m away at the same
    // time, and a block of the tower again 1 s later. Before, each fall had its own label: on a phone
    // the tower's five stacked into one unreadable pile.
    const tally = new ScoreTally();
    for (let i = 0; i < 5; i++) tally.add(4 + 0.3 * i, 1 + 0.7 * i, 2, 10 + 7 * i, 0.1 * i);
    tally.add(-2, 0.5, 2, 15, 0.2);
    expect(tally.due(0.3)).toEqual([]);
    const due = tally.due(0.1 * 4 + TALLY_TIME);
    expect(due.map((t) => [t.points, t.pieces])).toEqual([
      [10 + 17 + 24 + 31 + 38, 5],
      [15, 1],
    ]);
    // Over the highest of the tower's blocks.
    expect(due[0]!.y).toBeCloseTo(1 + 0.7 * 4, 12);
    tally.add(4, 0.4, 2, 10, 1.5);
    expect(tally.due(1.5 + TALLY_TIME).map((t) => t.points)).toEqual([10]);
    expect(() => tally.add(0, 0, 0, -1, 0)).toThrow(/points must be >= 0, got -1/);
  });

  it('swings and stars by layout: budgets 5, 6, 6, 6, 8 (3 stars in 2, 2, 3, 3, 3), one more each 5 levels; none uncleared', () => {
    // Pars of 3 on level 3 and 4 on level 4 (the old layouts) gave careless games of
    // scripts/wrecking-ball-par.mjs three stars in 6 and 9 of 9; a par of 1 on level 1 gave a
    // stranger three stars for the first swing. The later layouts' budgets are the most swings the
    // script's careless games take (6, 5, 5 and 8 on levels 2 to 5: a star for any of them), the
    // later pars what its careful player takes (3, 3 and 3 on levels 3 to 5; see swingPar).
    expect([1, 2, 3, 4, 5, 6, 10, 12].map(swingBudget)).toEqual([5, 6, 6, 6, 8, 6, 9, 8]);
    expect([1, 2, 3, 4, 5, 6, 10, 12].map(swingPar)).toEqual([2, 2, 3, 3, 3, 3, 4, 4]);
    expect([1, 2, 3, 4].map((n) => swingStars(n, true, 1))).toEqual([3, 3, 2, 1]);
    expect([1, 2, 3, 4, 5, 6].map((n) => swingStars(n, true, 2))).toEqual([3, 3, 2, 1, 1, 1]);
    expect([1, 2, 3, 4, 5, 6].map((n) => swingStars(n, true, 3))).toEqual([3, 3, 3, 2, 1, 1]);
    expect([1, 2, 3, 4, 5, 6].map((n) => swingStars(n, true, 4))).toEqual([3, 3, 3, 2, 1, 1]);
    expect([3, 4, 8].map((n) => swingStars(n, true, 5))).toEqual([3, 2, 1]);
    expect(swingStars(2, false, 1)).toBe(0);
    expect(() => swingBudget(1.5)).toThrow(/swingBudget: level must be an integer >= 1, got 1.5/);
  });
});

describe('wrecking-ball wind-up', () => {
  it('taps on other targets during a wind-up re-aim the same swing: one swing is counted, when its run begins', () => {
    // The player slews at full rate for 1 s and lets go (the ball swings on), taps a tower block and
    // taps two others during the wind-up. Each tap re-aims the same swing: `released` counts only the
    // ball let go into its run, once (a swing counted at each tap left the player 2 of 4 here).
    const { world, h } = build(1);
    h.controls.slew = 1;
    for (let i = 0; i < 60; i++) step(world);
    h.controls.slew = 0;
    expect(swayAmplitude(world, h)).toBeGreaterThan(1.5);
    const tower = h.pieces.filter((p) => p.kind === 'tower');
    aimAt(world, h, tower[0]!.body);
    for (let i = 0; i < 30; i++) step(world);
    aimAt(world, h, tower[1]!.body);
    for (let i = 0; i < 30; i++) step(world);
    aimAt(world, h, tower[2]!.body);
    expect(h.controls.released).toBe(0);
    let steps = 0;
    while (steps < 600 && h.controls.moves.length > 0 && h.controls.moves[0]!.run !== true) {
      step(world);
      steps++;
    }
    expect(h.controls.moves[0]?.run).toBe(true);
    step(world);
    expect(h.controls.released).toBe(1);
  });
});

describe('wrecking-ball: a drag-aimed swing', () => {
  /**
   * Steps `world` until the ball begins a contact with one of `pieces` (at most `most` s): the
   * seconds that took, or Infinity when it did not.
   */
  function untilBallTouches(
    world: ReturnType<typeof build>['world'],
    ball: number,
    pieces: readonly { body: number }[],
    most: number,
  ): number {
    for (let t = 0; t < most; t += world.dt) {
      step(world);
      const ev = contactEvents(world).begin;
      for (let i = 0; i < ev.count; i++) {
        const other = ev.bodyA[i] === ball ? ev.bodyB[i] : ev.bodyB[i] === ball ? ev.bodyA[i] : -1;
        if (pieces.some((q) => q.body === other)) return t + world.dt;
      }
    }
    return Number.POSITIVE_INFINITY;
  }

  /**
   * Level `level` (its default seed) settled for 0.5 s, then a swing aimed as a drag aims it (power
   * `power`, the page's speed: swingSpeed) at the piece a third of the way up
   * structure `index` (pieces grouped by start centre within 2.5 m), from straight where the ball
   * hangs, turned `turn` rad. Returns the seconds to the ball's first touch of that structure (within
   * 12 s) and the angle, rad, between the ball's horizontal velocity then and the direction asked.
   */
  function dragSwing(level: number, index: number, power: number, turn: number): { toHit: number; off: number } {
    const world = createPhysicsWorld(wreckingBallWorldOptions());
    const h = buildWreckingBall(world, { level });
    for (let k = 0; k < 30; k++) step(world);
    const groups: (typeof h.pieces)[] = [];
    for (const p of h.pieces) {
      const g = groups.find((q) => Math.hypot(q[0]!.x0 - p.x0, q[0]!.z0 - p.z0) < 2.5);
      if (g) g.push(p);
      else groups.push([p]);
    }
    const g = groups[index % groups.length]!;
    const piece = [...g].sort((a, b) => a.y0 - b.y0)[Math.floor(g.length / 3)]!;
    const P = world.components.Position,
      V = world.components.Velocity;
    const direction = Math.atan2(P.z[piece.body]! - P.z[h.ball]!, P.x[piece.body]! - P.x[h.ball]!) + turn;
    aimAt(world, h, piece.body, { direction, speed: swingSpeed(power) });
    const toHit = untilBallTouches(world, h.ball, g, 12);
    if (toHit === Number.POSITIVE_INFINITY) return { toHit, off: Math.PI };
    const along = Math.atan2(V.z[h.ball]!, V.x[h.ball]!);
    return { toHit, off: Math.abs(Math.atan2(Math.sin(along - direction), Math.cos(along - direction))) };
  }

  /** Level `level` from the page's start (openStart), settled `wait` steps; its structures (start centres within 2.5 m) and each one's piece a third of the way up. */
  function thirds(level: number, wait: number) {
    const world = createPhysicsWorld(wreckingBallWorldOptions());
    const h = buildWreckingBall(world, { level, openStart: true });
    for (let k = 0; k < wait; k++) step(world);
    const groups: (typeof h.pieces)[] = [];
    for (const p of h.pieces) {
      const g = groups.find((q) => Math.hypot(q[0]!.x0 - p.x0, q[0]!.z0 - p.z0) < 2.5);
      if (g) g.push(p);
      else groups.push([p]);
    }
    const targets = groups.map((g) => [...g].sort((a, b) => a.y0 - b.y0)[Math.floor(g.length / 3)]!);
    /** Aims a swing at `piece` as a drag straight from the ball would, at `speed` m/s; returns the plan's seconds to the hit. */
    const swingAt = (piece: (typeof h.pieces)[number], speed: number): number => {
      const P = world.components.Position;
      const direction = Math.atan2(P.z[piece.body]! - P.z[h.ball]!, P.x[piece.body]! - P.x[h.ball]!);
      aimAt(world, h, piece.body, { direction, speed });
      return h.controls.moves.reduce((t, m) => t + (m.follow ? 0 : m.duration), 0);
    };
    return { world, h, targets, swingAt };
  }

  it("a full pull winds up quickly: its plan is about half the old full pull's", () => {
    // A stranger pulled to full power and waited: at the old full pull's 6.9 m/s the ball had to be
    // pumped a whole swing of its chain (4.6 s). At FULL_SWING_SPEED the plans to each structure of
    // levels 1 and 2, the ball at rest, straight from it, take a median under 3 s; the same plans at
    // 6.9 m/s over 4 s (the measure tells them apart). Measured: see the console line.
    const plans = (speed: number) =>
      [1, 2]
        .flatMap((level) => {
          const { targets, swingAt } = thirds(level, 30);
          return targets.map((p) => swingAt(p, speed));
        })
        .sort((a, b) => a - b);
    const full = plans(swingSpeed(1)),
      old = plans(6.9);
    const median = (v: number[]) => v[Math.floor(v.length / 2)]!;
    console.log(
      `plans at ${swingSpeed(1)} m/s: ${full.map((t) => t.toFixed(1)).join(' ')}; at 6.9 m/s: ${old.map((t) => t.toFixed(1)).join(' ')}`,
    );
    expect(swingSpeed(1)).toBe(FULL_SWING_SPEED);
    expect(median(full)).toBeLessThan(3);
    expect(median(old)).toBeGreaterThan(4);
    expect(() => swingSpeed(1.1)).toThrow(/swingSpeed: power must be in \[0, 1\], got 1.1/);
  });

  it('the same swing brings down the same count: a full pull at the plank stack from three moments of rest', () => {
    // A stranger saw one swing bring down 1 and the same swing 11. The swing is the same whenever it
    // is let go from the ball at rest (the level settled 0.5, 0.6 or 0.7 s): the same count within 1.
    const counts = [30, 36, 42].map((wait) => {
      const { world, h, targets, swingAt } = thirds(1, wait);
      const stack = targets.find((p) => p.kind === 'planks')!;
      const plan = swingAt(stack, swingSpeed(1));
      for (let t = 0; t < plan + 3; t += world.dt) {
        step(world);
        scorePieces(world, h.pieces);
      }
      return fallenCount(h.pieces);
    });
    console.log(`plank stack, full pull: ${counts.join(' ')} down`);
    expect(Math.max(...counts) - Math.min(...counts)).toBeLessThanOrEqual(1);
    // Measured: 10 down each time (the stack has 12 planks).
    expect(Math.min(...counts)).toBeGreaterThanOrEqual(8);
  });

  it('strikes the piece the player aimed at at its own height: the wall top row at the top row, a swing planned for them lower', () => {
    // A swing planned for the player struck a tapped top brick at STRIKE_SHARE of the wall's height
    // (as low as a careful aim would), so where a stranger aimed did not matter. The player's swing
    // (a request) now strikes at the brick aimed at; one planned without a request still strikes low.
    const { world, h } = build(1);
    for (let k = 0; k < 30; k++) step(world);
    const wall = h.pieces.filter((p) => p.kind === 'wall');
    const brick = wall.reduce((a, b) => (b.y0 > a.y0 ? b : a));
    const P = world.components.Position;
    const direction = Math.atan2(P.z[brick.body]! - P.z[h.ball]!, P.x[brick.body]! - P.x[h.ball]!);
    aimAt(world, h, brick.body);
    const planned = h.controls.swing!.height - HANG;
    aimAt(world, h, brick.body, { direction, speed: 0.8 * HIT_SPEED });
    const aimed = h.controls.swing!.height - HANG;
    const top = brick.y0 + brick.half[1];
    expect(planned).toBeLessThanOrEqual(STRIKE_SHARE * top + 1e-9);
    // (Where the brick is now, settled a hair below where it was built.)
    expect(aimed).toBeCloseTo(P.y[brick.body]!, 9);
    // The ball's centre, where it first touches the wall, within a brick's height (0.6 m) of the top row's middle.
    expect(untilBallTouches(world, h.ball, wall, 8)).toBeLessThan(8);
    expect(Math.abs(P.y[h.ball]! - brick.y0)).toBeLessThan(0.6);
  });

  it('takes the quicker of the directions beside the arrow: light drags at a tower and a turned drag at a wall hit within 4 s, the ball within 30 degrees of the arrow', {
    timeout: 300_000,
  }, () => {
    // Held to the approach direction nearest the arrow (of 24), these took 6.3 s (level 5's tower,
    // power 0.2), 6.3 s (level 4's) and 7.3 s (level 2's wall, turned 0.6 rad); the direction one step
    // beside it, 2.5, 2.5 and 2.4 s.
    for (const [level, index, power, turn] of [
      [5, 7, 0.2, 0],
      [4, 6, 0.2, 0],
      [2, 7, 0.45, 0.6],
    ] as const) {
      const swing = dragSwing(level, index, power, turn);
      expect(swing.toHit, `level ${level}`).toBeLessThan(4);
      expect(swing.off, `level ${level}`).toBeLessThan((30 * Math.PI) / 180);
    }
  });
});

describe('wrecking ball aiming hint', () => {
  it('calls a pull full from 99 % shown, and asks no more of it; below, the rounded percentage', () => {
    // Exact strings: what the player reads at each power.
    expect(powerWords(1)).toBe('full power');
    expect(powerWords(0.99)).toBe('full power');
    expect(powerWords(0.985)).toBe('full power');
    expect(powerWords(0.984)).toBe('power 98 %');
    expect(powerWords(0.5)).toBe('power 50 %');
    expect(powerWords(0.2)).toBe('power 20 %');
    // No power below FULL_POWER_SHOWN reads as 99 % or 100 %.
    for (let p = 0.2; p < 0.985; p += 0.001) expect(powerWords(p)).not.toMatch(/^power (99|100) %$/);
    expect(() => powerWords(1.5)).toThrow(/powerWords: power/);
    expect(() => powerWords(Number.NaN)).toThrow(/powerWords: power/);
  });
});

describe('wrecking ball settings: ball mass in tonnes', () => {
  it('BALL_TONNES is the built ball mass to 0.1 t, and the slider value over it scales the mass', () => {
    for (const tonnes of [BALL_TONNES, 10.8]) {
      const world = createPhysicsWorld(wreckingBallWorldOptions());
      const h = buildWreckingBall(world, { ballWeight: tonnes / BALL_TONNES });
      const kg = world.components.Mass.value[slotOf(h.ball)]!;
      // The slider reads tonnes rounded to 0.1 t at the default: within 0.05 t of the body's mass, times the scale.
      expect(Math.abs(kg / 1000 - tonnes)).toBeLessThan(0.05 * (tonnes / BALL_TONNES) + 1e-9);
    }
    expect(BALL_TONNES).toBe(5.4);
  });
});
