/**
 * The wrecking-ball scene, headless: seeded levels, structures that stand on their own, a crane that
 * moves at its rated speeds, and a swing of the ball through a tower that knocks it down and scores.
 */

import { addBody, addDistanceJoint3D, createPhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import {
  aimAt,
  BALL_RADIUS,
  buildWreckingBall,
  clearTarget,
  fallenCount,
  HOOK_RANGE,
  SLEW_RATE,
  SWING_BUDGET,
  scorePieces,
  swingStars,
  wreckingBallWorldOptions,
} from '../../games/wrecking-ball/scene';

function build(level: number, seed = 1) {
  const world = createPhysicsWorld(wreckingBallWorldOptions());
  return { world, h: buildWreckingBall(world, { level, seed }) };
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
    // bricks, logs and blocks lay where they stood. The target is now 70% of the raised pieces, so
    // the raised pieces alone can clear any level.
    for (let level = 1; level <= 5; level++) {
      const { h } = build(level);
      const onGround = h.pieces.filter((p) => Math.abs(p.y0 - p.half[1]) < 1e-9).length;
      expect(onGround).toBeGreaterThan(0);
      expect(clearTarget(h.pieces)).toBe(Math.ceil(0.7 * (h.pieces.length - onGround)));
    }
    expect(clearTarget(build(1).h.pieces)).toBeLessThan(Math.ceil(0.7 * build(1).h.pieces.length));
  });

  it('keeps every structure standing without a hit, and slews at its rated speed', () => {
    const { world, h } = build(1);
    const P = world.components.Position;
    const start = h.pieces.map((p) => [P.x[p.body]!, P.y[p.body]!, P.z[p.body]!] as const);
    // The ball hangs still, 1.5 m or more from every piece, so nothing may fall: 5 s untouched.
    for (let i = 0; i < 300; i++) {
      step(world);
      scorePieces(world, h.pieces);
    }
    // A piece falls when it drops 0.4 m or tips 60 degrees: none does, and a settling stack moves millimetres.
    expect(fallenCount(h.pieces)).toBe(0);
    let moved = 0;
    h.pieces.forEach((p, i) => {
      moved = Math.max(moved, Math.hypot(P.x[p.body]! - start[i]![0], P.y[p.body]! - start[i]![1], P.z[p.body]! - start[i]![2]));
    });
    // Each piece's centre within 1 cm of where it was built (measured 1.5 mm at most, 27 pieces).
    expect(moved).toBeLessThan(0.01);
    // Then the crane slews: the trolley is kinematic and follows the crane state exactly: 0.5 s at
    // full slew is SLEW_RATE / 2 rad.
    const a0 = h.crane.angle;
    h.controls.slew = 1;
    for (let i = 0; i < 30; i++) {
      step(world);
      scorePieces(world, h.pieces);
    }
    expect(h.crane.angle - a0).toBeCloseTo(SLEW_RATE / 2, 9);
    expect(fallenCount(h.pieces)).toBe(0);
  });

  it('a hard drag does not stretch the chain, and the ball does not pass through the mast', () => {
    // The page drags the ball with a 2 Hz spring (BodyDrag3D: hertz 2, damping 0.3). Pulled toward
    // points 3 to 10 m away, the hook-to-ball distance stays within 2 % of its rest (measured 0.1 to
    // 0.4 %: the chain's rope from hook to ball carries the pull; a tester saw the chain at 1.7 times its
    // length). Pulled at the mast from the far side, the ball stops against it: its centre no closer to
    // the mast's axis than the mast's half width plus the ball's radius (0.95 m; measured 0.949).
    for (const far of [3, 10]) {
      const { world, h } = build(1);
      const P = world.components.Position;
      const b = slotOf(h.ball),
        t = slotOf(h.trolley);
      for (let i = 0; i < 60; i++) step(world);
      const span = () => Math.hypot(P.x[b]! - P.x[t]!, P.y[b]! - P.y[t]!, P.z[b]! - P.z[t]!);
      const rest = span();
      const target = [P.x[b]! + far, P.y[b]! - 1, P.z[b]! + 2];
      const anchor = addBody(world, { position: target, static: true });
      addDistanceJoint3D(world, {
        a: anchor,
        b: h.ball,
        anchorA: target,
        anchorB: [P.x[b]!, P.y[b]!, P.z[b]!],
        length: 0.01,
        minLength: 0,
        hertz: 2,
        dampingRatio: 0.3,
      });
      let most = 0;
      for (let i = 0; i < 180; i++) {
        step(world);
        most = Math.max(most, span());
      }
      expect(most / rest).toBeLessThan(1.02);
    }
    const { world, h } = build(1);
    const P = world.components.Position;
    const b = slotOf(h.ball);
    for (let i = 0; i < 60; i++) step(world);
    const far = [-P.x[b]!, P.y[b]!, -P.z[b]!];
    const anchor = addBody(world, { position: far, static: true });
    addDistanceJoint3D(world, {
      a: anchor,
      b: h.ball,
      anchorA: far,
      anchorB: [P.x[b]!, P.y[b]!, P.z[b]!],
      length: 0.01,
      minLength: 0,
      hertz: 2,
      dampingRatio: 0.3,
    });
    let closest = Infinity;
    for (let i = 0; i < 240; i++) {
      step(world);
      closest = Math.min(closest, Math.max(Math.abs(P.x[b]!), Math.abs(P.z[b]!)));
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
    // winds the crane up (a constant-speed move over whole swing periods), then runs the hook over
    // the piece in half a period, so the ball meets it at up to twice the hook's speed. Measured:
    // 5 of 5 tower blocks down.
    const { world, h } = build(1);
    for (let k = 0; k < 60; k++) step(world);
    const tower = h.pieces.filter((p) => p.kind === 'tower');
    aimAt(world, h, tower[Math.floor(tower.length / 2)]!.body);
    for (let k = 0; k < 60 * 10; k++) {
      step(world);
      scorePieces(world, h.pieces);
    }
    expect(h.controls.moves.length).toBe(0);
    expect(tower.filter((p) => p.fallen).length).toBeGreaterThanOrEqual(Math.ceil(tower.length / 2));
  });

  it('a tap on a brick in the middle of a wall: the ball reaches that brick, not the end of the wall', () => {
    // The swing used to run along the jib's arc, which runs along a wall (walls stand across the
    // swing about the mast): the ball hit the end brick and stopped 0.6 to 2.8 m short of the brick
    // tapped. The run now comes from the side with the fewest pieces in the way. Measured (gap from
    // the ball's surface to the brick's bounding sphere): -0.27, -0.02, -0.01 m (was 0.69, 2.75, 1.86).
    for (const [level, index] of [
      [1, 5],
      [2, 20],
      [3, 17],
    ] as const) {
      const { world, h } = build(level);
      for (let k = 0; k < 30; k++) step(world);
      const brick = h.pieces[index]!;
      expect(brick.kind).toBe('wall');
      aimAt(world, h, brick.body);
      const P = world.components.Position,
        b = h.ball,
        e = brick.body;
      let gap = Number.POSITIVE_INFINITY;
      for (let k = 0; k < 60 * 12; k++) {
        step(world);
        gap = Math.min(gap, Math.hypot(P.x[b]! - P.x[e]!, P.y[b]! - P.y[e]!, P.z[b]! - P.z[e]!) - BALL_RADIUS - Math.max(...brick.half));
      }
      expect(gap, `level ${level} piece ${index}`).toBeLessThan(0.05);
    }
  });

  it('a player tapping standing pieces one after another clears level 1 within 90 s of game time', () => {
    // Each tap aims at a standing piece picked by a fixed stride through them, lowest first (not the
    // best choice: a player aims better), once the last swing is over and 1 s has passed. Measured:
    // level 1 cleared at 47 s (levels 2 to 5 at 40, 63, 142 and 64 s); taps at the lowest pieces
    // only stalled near half.
    for (const level of [1]) {
      const { world, h } = build(level);
      let taps = 0,
        wait = 60,
        clearedAt = -1;
      for (let k = 0; k < 60 * 90 && clearedAt < 0; k++) {
        if (h.controls.moves.length === 0 && --wait <= 0) {
          const standing = h.pieces.filter((p) => !p.fallen).sort((a, b) => a.y0 - b.y0);
          aimAt(world, h, standing[(taps * 7919) % standing.length]!.body);
          taps++;
          wait = 60;
        }
        step(world);
        scorePieces(world, h.pieces);
        if (fallenCount(h.pieces) >= clearTarget(h.pieces)) clearedAt = k / 60;
      }
      expect(clearedAt, `level ${level}`).toBeGreaterThan(0);
    }
  });

  it('stars for a cleared level: 3 in 2 swings or fewer, 2 in 3, 1 in 4 (the budget), none uncleared', () => {
    expect(SWING_BUDGET).toBe(4);
    expect([1, 2, 3, 4].map((n) => swingStars(n, true))).toEqual([3, 3, 2, 1]);
    expect(swingStars(2, false)).toBe(0);
  });
});
