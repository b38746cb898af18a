/**
 * Wrecking ball, the time from letting go of a drag to the ball's first touch of the structure
 * dragged at: a fixed set of gestures over levels 1 and 2 (each from a fresh level, the crane as
 * the page starts it, 0.5 s settled): at each structure a press on its piece a third of the way up,
 * a drag that aims the ball straight from where it hangs, or 40 degrees either side, at full power
 * or at 0.5 (./scene swingSpeed), held 1 or 2 s, then let go. The page draws the ball back while the
 * drag is held (`pullBack`, as its aimDrag does) and lets the line go on release (`letGoPull`, as
 * its swingAt does for a drag).
 */
import { contactEvents, createPhysicsWorld, step } from '@bitphysics/physics';
import { describe, expect, it } from 'vitest';
import {
  buildWreckingBall,
  hookPosition,
  letGoPull,
  pullBack,
  type SwingRequest,
  scorePieces,
  segmentToAxis,
  swingSpeed,
  wreckingBallWorldOptions,
} from '../../games/wrecking-ball/scene';
import { groups } from './wrecking-ball-structures';

interface Gesture {
  level: number;
  structure: number;
  turn: number;
  power: number;
  hold: number;
}

/**
 * The gestures: per structure of levels 1 and 2, three directions at full power and the straight one
 * at half power, each held 1 s (the short holds, where the crane has least time to get there: the
 * slowest to hit; with 2 s holds added, 63 gestures, the median was 1.63 s and p90 5.08 s).
 */
function gestures(): Gesture[] {
  const out: Gesture[] = [];
  for (const level of [1, 2]) {
    const h = buildWreckingBall(createPhysicsWorld(wreckingBallWorldOptions()), { level, openStart: true });
    const n = groups(h.pieces).length;
    for (let structure = 0; structure < n; structure++) {
      for (const turn of [0, 40, -40]) out.push({ level, structure, turn, power: 1, hold: 1 });
      out.push({ level, structure, turn: 0, power: 0.5, hold: 1 });
    }
  }
  return out;
}

/**
 * Plays gesture `g`: seconds from the let-go to the ball's first touch of the structure (Infinity:
 * none within 10 s), whether the piece fell, and how near (m, across the ground) the chain's line
 * from the hook to the ball came to the mast's axis while the tagline held the ball. With `untilSlip`
 * it stops when the line slips (only the contacts counted, `toHit` NaN).
 */
function play(g: Gesture, untilSlip = false): { toHit: number; fell: boolean; mast: number; early: number; slipping: number } {
  const world = createPhysicsWorld(wreckingBallWorldOptions());
  const h = buildWreckingBall(world, { level: g.level, openStart: true });
  for (let k = 0; k < 30; k++) step(world);
  const group = groups(h.pieces)[g.structure]!;
  const standing = group.slice().sort((a, b) => a.y0 - b.y0);
  const piece = standing[Math.floor(standing.length / 3)]!;
  const P = world.components.Position;
  const straight = Math.atan2(P.z[piece.body]! - P.z[h.ball]!, P.x[piece.body]! - P.x[h.ball]!);
  const request: SwingRequest = { direction: straight + (g.turn * Math.PI) / 180, speed: swingSpeed(g.power) };
  pullBack(world, h, piece.body, request);
  let mast = Number.POSITIVE_INFINITY;
  const pieces = new Set(h.pieces.map((q) => q.body));
  /** Contacts begun this step between the ball and any piece. */
  const touches = (): number => {
    const ev = contactEvents(world).begin;
    let n = 0;
    for (let i = 0; i < ev.count; i++) {
      const other = ev.bodyA[i] === h.ball ? ev.bodyB[i]! : ev.bodyB[i] === h.ball ? ev.bodyA[i]! : -1;
      if (pieces.has(other)) n++;
    }
    return n;
  };
  let early = 0,
    slipping = 0;
  const held = (): void => {
    if (h.controls.pull === null) return;
    const [hx, , hz] = hookPosition(h.crane);
    mast = Math.min(mast, segmentToAxis(hx, hz, P.x[h.ball]!, P.z[h.ball]!));
  };
  for (let t = 0; t < g.hold - 1e-9; t += world.dt) {
    step(world);
    early += touches();
    scorePieces(world, h.pieces);
    held();
  }
  letGoPull(h);
  let t = 0;
  while (t < 10) {
    step(world);
    if (h.controls.pull !== null) slipping += touches();
    else if (untilSlip) return { toHit: Number.NaN, fell: piece.fallen, mast, early, slipping };
    held();
    scorePieces(world, h.pieces);
    t += world.dt;
    const ev = contactEvents(world).begin;
    for (let i = 0; i < ev.count; i++) {
      const other = ev.bodyA[i] === h.ball ? ev.bodyB[i] : ev.bodyB[i] === h.ball ? ev.bodyA[i] : -1;
      if (group.some((q) => q.body === other)) return { toHit: t, fell: finish(world, h, piece), mast, early, slipping };
    }
  }
  return { toHit: Number.POSITIVE_INFINITY, fell: piece.fallen, mast, early, slipping };
}

/** Steps 2.5 s more (the structure falling) and says whether the piece fell. */
function finish(
  world: ReturnType<typeof createPhysicsWorld>,
  h: ReturnType<typeof buildWreckingBall>,
  piece: { fallen: boolean },
): boolean {
  for (let k = 0; k < 150; k++) {
    step(world);
    scorePieces(world, h.pieces);
  }
  return piece.fallen;
}

/** The value at share q of the sorted values (nearest rank). */
function quantile(sorted: number[], q: number): number {
  return sorted[Math.min(sorted.length - 1, Math.ceil(q * sorted.length) - 1)]!;
}

describe('wrecking-ball: drag to hit', () => {
  it('hits soon after a drag held 1 s is let go', { timeout: 900_000 }, () => {
    const all = gestures().map((g) => ({ g, ...play(g) }));
    const times = all.map((r) => r.toHit).sort((a, b) => a - b);
    console.log(
      all
        .map(
          (r) =>
            `L${r.g.level} s${r.g.structure} ${String(r.g.turn).padStart(3)} deg p${r.g.power} hold ${r.g.hold} s: ${r.toHit.toFixed(2)} s ${r.fell ? 'fell' : 'stood'} early ${r.early} slipping ${r.slipping}`,
        )
        .join('\n'),
    );
    console.log(
      `gestures ${all.length}, median ${quantile(times, 0.5).toFixed(2)} s, p90 ${quantile(times, 0.9).toFixed(2)} s; fell ${all.filter((r) => r.fell).length}`,
    );
    const nearMast = Math.min(...all.map((r) => r.mast));
    const early = all.reduce((a, r) => a + r.early, 0);
    console.log(`ball-piece contacts while held ${early}, after let-go before the line slipped ${all.reduce((a, r) => a + r.slipping, 0)}`);
    console.log(`nearest the held chain came to the mast's axis: ${nearMast.toFixed(2)} m`);
    // Measured (36 gestures, all 1 s holds): median 2.68 s, p90 5.40 s, 33 pieces aimed at fell
    // (2.30 s, 5.22 s and 29 before the line braked the held ball and turned it round the hook:
    // the swing waits for the ball to be drawn its way). The same gestures before the ball was drawn
    // back while the drag was held (the crane planning its swing only once let go): median 2.97 s,
    // p90 6.28 s; these bounds fail there. Bounds: as set on the earlier 2.30 s and 5.22 s (0.4 s
    // and 0.6 s over them).
    expect(all.length).toBeGreaterThan(30);
    expect(quantile(times, 0.5)).toBeLessThan(2.7);
    expect(quantile(times, 0.9)).toBeLessThan(5.8);
    expect(all.filter((r) => r.fell).length).toBeGreaterThanOrEqual(Math.ceil(0.75 * all.length));
    // The chain's line from the hook to the held ball never crosses the mast (its corner 0.57 m
    // from the axis, a link's radius more).
    expect(nearMast).toBeGreaterThan(0.64);
    // Nothing is hit while the drag is held: the ball is carried over every structure.
    expect(early).toBe(0);
  });

  it('hits nothing while a drag is held 4 s, nor till the line slips', { timeout: 900_000 }, () => {
    const all = gestures().map((g) => ({ g, ...play({ ...g, hold: 4 }, true) }));
    const early = all.reduce((a, r) => a + r.early, 0);
    const slipping = all.reduce((a, r) => a + r.slipping, 0);
    console.log(`4 s holds: ball-piece contacts while held ${early}, after let-go before the line slipped ${slipping}`);
    // Measured: 2 while held (grazes as the ball, let down as it is drawn back, passes a piece; 1
    // before the line turned the ball round the hook: the turn's arc passes nearer some), 0 after.
    // Before the ball was carried over the pieces: 66 while held (it swept through the structures
    // between), 1 after. Bound: at most two grazes over the 36 gestures while held, and one after
    // the let-go in ten gestures.
    expect(early).toBeLessThanOrEqual(2);
    expect(slipping).toBeLessThanOrEqual(Math.ceil(all.length / 10));
  });
});
