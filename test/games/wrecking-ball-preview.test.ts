/**
 * Wrecking ball, the drawn aim tells the truth: while a drag is held the page draws the ball's swing
 * in 3D, from where the line will draw it back to where it first meets a piece (./scene swingGoal and
 * swingPath, drawn by main.ts drawSwingPreview). Gestures as wrecking-ball-pull.test.ts makes them
 * (each from a fresh level, the crane as the page starts it, 0.5 s settled): at each structure of
 * levels 1 and 2 a press a third of the way up, a drag straight from where the ball hangs or 40
 * degrees either side at full power, held 2 s (the crane in place), then let go. The preview is
 * taken from the drag's request as the page draws it, before the crane has carried the ball there.
 */
import { contactEvents, createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import {
  buildWreckingBall,
  HANG,
  letGoPull,
  pullBack,
  type SwingRequest,
  swingGoal,
  swingPath,
  swingSpeed,
  wreckingBallWorldOptions,
} from '../../games/wrecking-ball/scene';
import { groups } from './wrecking-ball-structures';

/** One gesture: what the preview said (structure met, ball centre there) and what the swing did. */
interface Outcome {
  label: string;
  /** Index of the structure the preview's swing meets first (-1: none), and the one the ball touched first (-1: none in 8 s). */
  predicted: number;
  touched: number;
  /** The structure aimed at. */
  aimed: number;
  /** Distance, m, between the preview's ball centre where it meets the piece and the ball's centre at its first touch. */
  error: number;
}

/**
 * Plays one drag at structure `s` of level `level`, `turn` degrees off straight from the ball. With
 * `follow`, a player who reads the preview: while it shows the ball meeting another structure or
 * none, they turn the pull 10 degrees at a time (either way, up to 90) until it shows the aimed one.
 */
function play(level: number, s: number, turn: number, follow = false): Outcome {
  const world = createPhysicsWorld(wreckingBallWorldOptions());
  const h = buildWreckingBall(world, { level, openStart: true });
  for (let k = 0; k < 30; k++) step(world);
  const all = groups(h.pieces);
  const group = all[s]!;
  const piece = group.slice().sort((a, b) => a.y0 - b.y0)[Math.floor(group.length / 3)]!;
  const P = world.components.Position;
  const straight = Math.atan2(P.z[piece.body]! - P.z[h.ball]!, P.x[piece.body]! - P.x[h.ball]!);
  const structureOf = (body: number): number => all.findIndex((q) => q.some((p) => p.body === body));
  const path: number[] = [];
  /** The preview as the page draws it for a drag in direction `direction`: the structure its swing meets first (-1: none). */
  const preview = (direction: number): number => {
    const g = swingGoal(world, h, piece.body, { direction, speed: swingSpeed(1) });
    const start = [g.x - g.offset * g.ux, g.height - Math.sqrt(HANG * HANG - g.offset * g.offset), g.z - g.offset * g.uz];
    const meet = swingPath(world, h.pieces, start, [g.x, g.height, g.z], path);
    return meet === 0 ? -1 : structureOf(meet);
  };
  let direction = straight + (turn * Math.PI) / 180;
  if (follow && preview(direction) !== s) {
    const turns = [10, -10, 20, -20, 30, -30, 40, -40, 50, -50, 60, -60, 70, -70, 80, -80, 90, -90];
    const better = turns.find((d) => preview(direction + (d * Math.PI) / 180) === s);
    if (better !== undefined) direction += (better * Math.PI) / 180;
  }
  const request: SwingRequest = { direction, speed: swingSpeed(1) };
  const predicted = preview(direction);
  const end = path.slice(-3);
  pullBack(world, h, piece.body, request);
  for (let t = 0; t < 2; t += world.dt) step(world);
  letGoPull(h);
  const bodies = new Set(h.pieces.map((p) => p.body));
  for (let t = 0; t < 8; t += world.dt) {
    step(world);
    const ev = contactEvents(world).begin;
    for (let i = 0; i < ev.count; i++) {
      const other = ev.bodyA[i] === h.ball ? ev.bodyB[i]! : ev.bodyB[i] === h.ball ? ev.bodyA[i]! : -1;
      if (!bodies.has(other)) continue;
      const error = Math.hypot(P.x[h.ball]! - end[0]!, P.y[h.ball]! - end[1]!, P.z[h.ball]! - end[2]!);
      return { label: `L${level} s${s} ${turn} deg`, predicted, touched: structureOf(other), aimed: s, error };
    }
  }
  return { label: `L${level} s${s} ${turn} deg`, predicted, touched: -1, aimed: s, error: Number.POSITIVE_INFINITY };
}

describe('wrecking-ball: the swing preview', () => {
  it('shows the structure the ball meets, and where, before the crane has carried it there', { timeout: 600_000 }, () => {
    const out: Outcome[] = [];
    for (const level of [1, 2]) {
      const n = groups(buildWreckingBall(createPhysicsWorld(wreckingBallWorldOptions()), { level, openStart: true }).pieces).length;
      for (let s = 0; s < n; s++) for (const turn of [0, 40, -40]) out.push(play(level, s, turn));
    }
    const agree = out.filter((o) => o.predicted === o.touched).length;
    const onTarget = out.filter((o) => o.touched === o.aimed).length;
    // A player who reads the preview turns the drags it shows going elsewhere (the others play as before).
    const followed = out.map((o) => {
      if (o.predicted === o.aimed) return o;
      const [, level, s, turn] = /^L(\d) s(\d) (-?\d+) deg$/.exec(o.label)!.map(Number);
      return play(level!, s!, turn!, true);
    });
    const onTargetFollowed = followed.filter((o) => o.touched === o.aimed).length;
    console.log(
      followed
        .filter((o, i) => o !== out[i])
        .map((o) => `turned: ${o.label}: preview ${o.predicted}, touched ${o.touched} (aimed ${o.aimed})`)
        .join('\n'),
    );
    const errors = out
      .filter((o) => o.predicted === o.touched && o.touched >= 0)
      .map((o) => o.error)
      .sort((a, b) => a - b);
    const median = errors[Math.floor(errors.length / 2)] ?? Number.POSITIVE_INFINITY;
    console.log(
      `${out.map((o) => `${o.label}: preview meets ${o.predicted}, ball touched ${o.touched} (aimed ${o.aimed}), ${o.error.toFixed(2)} m`).join('\n')}\n` +
        `preview names the structure first touched in ${agree}/${out.length}; swings touching the aimed structure first ${onTarget}/${out.length}, ${onTargetFollowed}/${out.length} turned as the preview shows; median miss of the drawn meeting point ${median.toFixed(2)} m`,
    );
    // Bounds: the preview is a pendulum from rest under a still hook, while the ball is let go still
    // settling from the crane's run (READY_NEAR 0.4 m, READY_STILL 1 m/s): the structure it names is
    // the one touched in at least 5 of 6 gestures, and the drawn meeting point is within a ball's
    // diameter (1.1 m) of where the ball first touches, at the median.
    expect(out.length).toBeGreaterThanOrEqual(18);
    expect(agree).toBeGreaterThanOrEqual(Math.ceil((5 / 6) * out.length));
    expect(median).toBeLessThan(1.1);
    // Read, it helps, and it is honest where it was turned: a player who turns each drag the preview
    // shows going elsewhere until it shows the aimed structure sees the ball touch that structure
    // first in all 27 (level 2's structure 3, the end of the wall beside structure 2, included: the
    // line slips only once the ball is drawn back where the preview starts it, or held up there;
    // before, it slipped 0.3 s after the hook was in place with the ball still 2 m and more short of
    // there, and those three turned drags touched structure 2 first, or nothing). The blind drags
    // touch the aimed structure first in 25 of 27. Bounds: every turned drag touches what its preview
    // showed, and the turned drags hit the aimed structure more often than the blind ones
    // (deterministic steps: the same counts every run).
    const turned = followed.filter((o, i) => o !== out[i]);
    expect(turned.length).toBeGreaterThan(0);
    expect(turned.filter((o) => o.predicted !== o.touched).map((o) => o.label)).toEqual([]);
    expect(onTargetFollowed).toBeGreaterThan(onTarget);
  });
});
