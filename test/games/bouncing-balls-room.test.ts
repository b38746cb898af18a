// The phone's slingshot of bouncing balls (games/bouncing-balls/hoop.ts slingRoom): a simulated player
// in the tall box (a phone held upright) presses at random starts under each hoop's rim and pulls in
// every direction, 1 degree apart; a throw scores when its drag-free flight in the scene's default
// physics goes down through the opening before it touches anything (reach.ts cleanBasket). Measured
// with the box's old slingshot (a full pull throws at MAX_THROW_SPEED, 20 m/s, the power shown is the
// speed's share of it) and with the phone's (slingRoom: straight up, a pull just past nothing rises to
// ROOM_UNDER_RIM under the rim, the full pull to ROOM_OVER_RIM over it; the power shown is the share
// of the full pull, main.ts powerOf).
import { describe, expect, it } from 'vitest';
import {
  HOOP_SPOTS_TALL,
  type HoopSpot,
  hoopSegments,
  MAX_THROW_SPEED,
  SHOT_LINE_GAP,
  type SlingRoom,
  slingPull,
  slingRoom,
  slingSpeed,
} from '../../games/bouncing-balls/hoop';
import { cleanBasket } from '../../games/bouncing-balls/reach';
import { BOX_TALL } from '../../games/bouncing-balls/scene';

const G = 9.81;
/** A finger's full pull at 390 x 844, px (main.ts fingerFullPull); the shares below do not depend on it. */
const FULL = 138;

/** Starts per hoop: random, fixed by the seed; clear of the hoop and the net, under the shot line. */
function starts(spot: HoopSpot, n: number, seed: number): [number, number][] {
  let s = seed;
  const rnd = () => (s = (s * 16807) % 2147483647) / 2147483647;
  const out: [number, number][] = [];
  while (out.length < n) {
    const x = 0.5 + rnd() * (BOX_TALL.max[0] - 1),
      y = 0.5 + rnd() * (spot.y - SHOT_LINE_GAP - 0.5);
    const near = hoopSegments(spot).some(([ax, ay, bx, by]) => {
      const ex = bx - ax,
        ey = by - ay;
      const u = Math.max(0, Math.min(1, ((x - ax) * ex + (y - ay) * ey) / (ex * ex + ey * ey)));
      return Math.hypot(x - ax - u * ex, y - ay - u * ey) < 0.5;
    });
    if (near || (Math.abs(x - spot.x) < 1.1 && y > spot.y - 1.6)) continue;
    out.push([x, y]);
  }
  return out;
}

/** Whether a throw at `speed` from (x, y) scores in some direction 1 degree apart, 20 to 160 degrees. */
function scoresAt(spot: HoopSpot, x: number, y: number, speed: number): boolean {
  for (let angle = 20; angle <= 160; angle++) if (cleanBasket(spot, true, { x, y, angle, speed })) return true;
  return false;
}

/** The slowest clean basket from (x, y), m/s (through the opening's middle or 0.3 m either side, 1 degree apart), or Infinity. */
function slowest(spot: HoopSpot, x: number, y: number): number {
  let best = Number.POSITIVE_INFINITY;
  for (let angle = 20; angle <= 160; angle++) {
    const a = (angle * Math.PI) / 180,
      c = Math.cos(a),
      s = Math.sin(a);
    for (const off of [0, -0.3, 0.3]) {
      const dx = spot.x + off - x,
        lift = dx * (s / c) - (spot.y - y);
      if (Math.abs(c) < 1e-6 || lift <= 0 || dx * c <= 0) continue;
      const v = Math.sqrt((G * dx * dx) / (2 * c * c * lift));
      if (v < best && v <= MAX_THROW_SPEED && cleanBasket(spot, true, { x, y, angle, speed: v })) best = v;
    }
  }
  return best;
}

describe('bouncing-balls phone slingshot (tall box)', () => {
  it('a full pull scores from nearly every start that can score; a low start scores at well under full power', () => {
    const old = { full: 0, low: [] as number[] },
      now = { full: 0, low: [] as number[] };
    let can = 0;
    for (const [i, spot] of HOOP_SPOTS_TALL.entries()) {
      for (const [x, y] of starts(spot, 16, 11 + i)) {
        const v = slowest(spot, x, y);
        if (!Number.isFinite(v)) continue;
        can++;
        const room: SlingRoom = slingRoom(y, spot.y, G);
        if (scoresAt(spot, x, y, slingSpeed(FULL, FULL))) old.full++;
        if (scoresAt(spot, x, y, slingSpeed(FULL, FULL, room))) now.full++;
        // Low: a ball of the heap or a press just over it, up to 2 m over the floor.
        if (y <= 2) {
          old.low.push(v / MAX_THROW_SPEED);
          now.low.push(v <= room.top ? slingPull(v, FULL, room) / FULL : Number.POSITIVE_INFINITY);
        }
      }
    }
    const median = (a: number[]) => [...a].sort((p, q) => p - q)[Math.floor(a.length / 2)]!;
    // Measured: of 80 random starts, 54 can score at all; the old full pull (20 m/s) scores from
    // none of them (to the ceiling or flat into the wall), the phone's from 51 (94 %). Low starts
    // (13): the least power shown for a clean basket, median 60 % (old: share of 20 m/s; the most
    // 69 %) -> 50 % (share of the full pull; the most 96 %: one far low start needs nearly all).
    // Tolerance: the full pulls' share 4 points under the measured one (a few starts); the low
    // starts' median 5 points over it, and every low start reachable with a full pull.
    expect(can).toBeGreaterThanOrEqual(40);
    expect(old.full).toBe(0);
    expect(now.full / can).toBeGreaterThanOrEqual(0.9);
    expect(now.low.length).toBeGreaterThanOrEqual(8);
    expect(median(now.low)).toBeLessThan(0.55);
    expect(median(now.low)).toBeLessThan(median(old.low) - 0.05);
    expect(Math.max(...now.low)).toBeLessThanOrEqual(1);
  }, 20_000);

  it('the phone curve: 0 for no pull, low just past it, top at the full pull and beyond; slingPull is its inverse', () => {
    const room = slingRoom(1.5, 9, G);
    // Straight up, the full pull reaches ROOM_OVER_RIM (3.5 m) over the rim: v^2 = 2 g (9 + 3.5 - 1.5).
    expect(room.top).toBeCloseTo(Math.sqrt(2 * G * 11), 9);
    // Just past no pull, straight up to ROOM_UNDER_RIM (1 m) under the rim.
    expect(room.low).toBeCloseTo(Math.sqrt(2 * G * 6.5), 9);
    expect(slingRoom(8.5, 9, G).low).toBe(0);
    expect(slingSpeed(0, FULL, room)).toBe(0);
    // (A pull of 1e-12 px: the height grows as the pull's share to the power ROOM_PULL_CURVE, steep at 0.)
    expect(slingSpeed(1e-12, FULL, room)).toBeCloseTo(room.low, 6);
    expect(slingSpeed(FULL, FULL, room)).toBeCloseTo(room.top, 9);
    expect(slingSpeed(2 * FULL, FULL, room)).toBeCloseTo(room.top, 9);
    for (const l of [10, 50, 100, 137]) expect(slingPull(slingSpeed(l, FULL, room), FULL, room)).toBeCloseTo(l, 6);
    // Higher starts get less: the same lob over the rim.
    expect(slingRoom(6, 9, G).top).toBeLessThan(room.top);
    expect(() => slingRoom(Number.NaN, 9, G)).toThrow(RangeError);
  });

  it("the phone curve spends most of a thumb's pull on the strong throws, where a low start scores", () => {
    // The issue this answers: a stranger on a phone found the power too sensitive (some 80 px of the
    // 138 px full pull at 68 %, 140 px at 100 %). The upper half of the height a throw reaches (from
    // halfway between room.low's and room.top's straight-up heights to the top: where a low start's
    // baskets are) took half the pull; now over two thirds of it. Tolerance: exact but for rounding.
    const room = slingRoom(1.5, 9, G);
    const half = Math.sqrt((room.low ** 2 + room.top ** 2) / 2);
    const upper = FULL - slingPull(half, FULL, room);
    expect(upper / FULL).toBeGreaterThan(2 / 3);
    // And the full pull still throws at room.top, the pull growing with the speed all the way.
    let last = 0;
    for (let l = 1; l <= FULL; l++) {
      const v = slingSpeed(l, FULL, room);
      expect(v).toBeGreaterThan(last);
      last = v;
    }
    expect(last).toBeCloseTo(room.top, 9);
  });
});
