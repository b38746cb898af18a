/**
 * Wrecking ball, the time from a tap to the ball's hit, scripted over levels 1 and 2 (the first two
 * layouts; scripts/wrecking-ball-par.mjs plays every level and reports the page's taps' times): a player taps
 * each structure in turn (its standing piece a third of the way up), the next tap 0.5 s after the
 * last swing's moves end (the ball still swinging from the hit, as an eager player leaves it). For
 * each tap: seconds until the ball first touches the tapped piece's structure (a contact begin
 * event), and whether the tapped piece has fallen 2.5 s later.
 */
import { contactEvents, createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import { aimAt, buildWreckingBall, scorePieces, wreckingBallWorldOptions } from '../../games/wrecking-ball/scene';

interface Tap {
  level: number;
  kind: string;
  /** Seconds from the tap to the ball first touching the piece's structure (Infinity: not within 15 s). */
  toHit: number;
  fell: boolean;
  plan: number;
  /** Horizontal distance, m, from the ball to the piece at the plan's end. */
  off: number;
  /** The first piece the ball touched: its kind, distance from the piece tapped, when. */
  first: string;
}

/** Plays level `level` as above: one tap at each structure, then again from the first, four taps in all (the later ones while the ball still swings). */
function play(level: number): Tap[] {
  const world = createPhysicsWorld(wreckingBallWorldOptions());
  const h = buildWreckingBall(world, { level });
  const taps: Tap[] = [];
  // Structures: pieces grouped by their start centre (within 2.5 m).
  const groups: (typeof h.pieces)[] = [];
  for (const p of h.pieces) {
    const g = groups.find((q) => Math.hypot(q[0]!.x0 - p.x0, q[0]!.z0 - p.z0) < 2.5);
    if (g) g.push(p);
    else groups.push([p]);
  }
  for (let k = 0; k < 30; k++) step(world);
  for (const g of [...groups, ...groups].slice(0, 4)) {
    const standing = g.filter((p) => !p.fallen).sort((a, b) => a.y0 - b.y0);
    if (standing.length === 0) continue;
    const piece = standing[Math.floor(standing.length / 3)]!;
    aimAt(world, h, piece.body);
    // The plan's time to the arrival (the follow-through after it not counted).
    const plan = h.controls.moves.reduce((a, m) => a + (m.follow ? 0 : m.duration), 0);
    let t = 0,
      hitAt = Number.POSITIVE_INFINITY,
      idle = 0,
      off = -1,
      first = '';
    while (t < 15) {
      step(world);
      scorePieces(world, h.pieces);
      t += world.dt;
      if (Math.abs(t - plan) < world.dt / 2) {
        const P = world.components.Position;
        off = Math.hypot(P.x[h.ball]! - P.x[piece.body]!, P.z[h.ball]! - P.z[piece.body]!);
      }
      const ev = contactEvents(world).begin;
      for (let i = 0; i < ev.count && hitAt === Number.POSITIVE_INFINITY; i++) {
        const other = ev.bodyA[i] === h.ball ? ev.bodyB[i] : ev.bodyB[i] === h.ball ? ev.bodyA[i] : -1;
        const q = h.pieces.find((q) => q.body === other);
        if (q && first === '')
          first = `${q.kind} ${Math.hypot(q.x0 - piece.x0, q.y0 - piece.y0, q.z0 - piece.z0).toFixed(1)} m away at ${t.toFixed(2)} s`;
        if (g.some((q) => q.body === other)) hitAt = t;
      }
      if (hitAt < Number.POSITIVE_INFINITY && t > hitAt + 2.5 && h.controls.moves.length === 0) break;
    }
    taps.push({ level, kind: piece.kind, toHit: hitAt, fell: piece.fallen, plan, off, first });
    // The next tap 0.5 s after the moves end.
    while (h.controls.moves.length > 0 && idle++ < 600) {
      step(world);
      scorePieces(world, h.pieces);
    }
    for (let k = 0; k < 30; k++) {
      step(world);
      scorePieces(world, h.pieces);
    }
  }
  return taps;
}

describe('wrecking-ball: tap to hit', () => {
  it('measures the time from a tap to the hit over levels 1 and 2', { timeout: 900_000 }, () => {
    const taps = [1, 2].flatMap(play);
    const hit = taps
      .filter((t) => t.toHit < Number.POSITIVE_INFINITY)
      .map((t) => t.toHit)
      .sort((a, b) => a - b);
    const median = hit[Math.floor(hit.length / 2)]!;
    console.log(
      taps
        .map(
          (t) =>
            `L${t.level} ${t.kind.padEnd(6)} ${t.toHit.toFixed(2)} s (plan ${t.plan.toFixed(2)}, off ${t.off.toFixed(2)} m) ${t.fell ? 'fell' : 'stood'} first ${t.first}`,
        )
        .join('\n'),
    );
    console.log(
      `taps ${taps.length}, hit ${hit.length}, fell ${taps.filter((t) => t.fell).length}, median ${median.toFixed(2)} s, max ${hit.at(-1)!.toFixed(2)} s, mean ${(hit.reduce((a, b) => a + b, 0) / hit.length).toFixed(2)} s`,
    );
    // Measured (four taps a level, the swing striking low and following through): 12 taps, 12 hit,
    // 12 tapped pieces fell, median 3.27 s, mean 3.59 s, longest 5.13 s (earlier, 25 taps over the
    // levels' structures: 25 hit, 19 fell, median 3.22 s; before the planned swing, with wind-ups:
    // 23 taps, 15 hit, 13 fell, median 6.87 s, mean 9.34 s, longest 14.18 s).
    // Measured over levels 1 and 5: 8 taps, all hit and fell, median 3.27 s, longest 5.12 s. With
    // the hook no longer halting a substep between timed moves and light chain links (the ball
    // stays on its rope): 7 taps (level 1's tower was down before its second tap), all hit and
    // fell, median 2.82 s, longest 4.65 s. With planned swings at 2.5 times the keys' rates (1.5
    // before): 7 taps, all hit and fell, median 2.58 s (3.33 s), mean 3.13 s (3.60 s).
    // Over levels 1 and 2 once levels 3 to 5 were laid out anew (level 5 with a long wall, whose
    // planned swings from the crane's start took 4.6 and 5.2 s: over levels 1 and 5, 7 taps, median
    // 4.13 s): 7 taps, all hit, 6 fell, median 3.27 s, longest 5.27 s (level 2's wall, as before).
    expect(taps.length).toBeGreaterThan(5);
    expect(hit.length).toBeGreaterThanOrEqual(taps.length - 2);
    expect(median).toBeLessThan(4);
    expect(taps.filter((t) => t.fell).length).toBeGreaterThanOrEqual(Math.ceil(0.6 * taps.length));
  });
});
