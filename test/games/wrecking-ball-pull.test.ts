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
  HANG,
  hookPosition,
  letGoPull,
  pullBack,
  type SwingRequest,
  scorePieces,
  segmentToAxis,
  swingGoal,
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

/**
 * Steps up to 2.5 s more (the structure falling) and says whether the piece fell. It stops at the
 * step the piece is scored fallen: `scorePieces` never sets a piece standing again, so the steps
 * after that could not change the answer.
 */
function finish(
  world: ReturnType<typeof createPhysicsWorld>,
  h: ReturnType<typeof buildWreckingBall>,
  piece: { fallen: boolean },
): boolean {
  for (let k = 0; k < 150 && !piece.fallen; k++) {
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
    // Measured (36 gestures, all 1 s holds): median 2.25 s, p90 4.63 s, 32 pieces aimed at fell.
    // Before the hook carried the ball faster and the line drew it back over the run's last 3.5 m
    // (not 2 m), slipping only once the ball was there or held up: median 2.68 s, p90 5.40 s, 33
    // fell (the line slipped 0.3 s after the hook was in place with the ball still on its way, and
    // such a swing went off its arc: 7.8 s to hit at level 1's tower 40 degrees off). Bounds: 0.25 s
    // and 0.37 s over the measured figures (below those before).
    expect(all.length).toBeGreaterThan(30);
    expect(quantile(times, 0.5)).toBeLessThan(2.5);
    expect(quantile(times, 0.9)).toBeLessThan(5);
    expect(all.filter((r) => r.fell).length).toBeGreaterThanOrEqual(Math.ceil(0.75 * all.length));
    // The chain's line from the hook to the held ball never crosses the mast (its corner 0.57 m
    // from the axis, a link's radius more).
    expect(nearMast).toBeGreaterThan(0.64);
    // Nothing is hit while the drag is held: the ball is carried over every structure.
    expect(early).toBe(0);
  });

  it('carries the held ball to where its swing is drawn from within 2.55 s', () => {
    // Level 1's wall, dragged straight from where the ball hangs at full power and held: seconds
    // until the ball's centre is within 0.4 m (the page's ring turns green there, READY_SHOWN) of
    // where the preview starts the swing (./scene swingGoal). Measured 2.22 s; before the hook ran
    // faster, the hoist let the ball down faster and the line drew it back over the run's last 3.5 m:
    // 2.88 s (over level 1 and 2's 27 straight and 40-degree drags the median went 3.15 s -> 2.35 s).
    // Bound: midway (deterministic steps: the same every run).
    const carry = (structure: number): number => {
      const world = createPhysicsWorld(wreckingBallWorldOptions());
      const h = buildWreckingBall(world, { level: 1, openStart: true });
      for (let k = 0; k < 30; k++) step(world);
      const group = groups(h.pieces)[structure]!;
      const piece = group.slice().sort((a, b) => a.y0 - b.y0)[Math.floor(group.length / 3)]!;
      const P = world.components.Position;
      const direction = Math.atan2(P.z[piece.body]! - P.z[h.ball]!, P.x[piece.body]! - P.x[h.ball]!);
      const request: SwingRequest = { direction, speed: swingSpeed(1) };
      for (let t = 0; t < 6; t += world.dt) {
        pullBack(world, h, piece.body, request);
        const g = swingGoal(world, h, piece.body, request);
        step(world);
        const sy = g.height - Math.sqrt(HANG * HANG - g.offset * g.offset);
        const off = Math.hypot(P.x[h.ball]! - (g.x - g.offset * g.ux), P.y[h.ball]! - sy, P.z[h.ball]! - (g.z - g.offset * g.uz));
        if (off < 0.4) return t + world.dt;
      }
      return Number.POSITIVE_INFINITY;
    };
    const time = carry(1);
    console.log(`carried to the swing's start in ${time.toFixed(2)} s`);
    expect(time).toBeLessThan(2.55);
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
