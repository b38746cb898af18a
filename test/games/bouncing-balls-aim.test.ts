// The slingshot's aim assist of bouncing balls (games/bouncing-balls/aim-assist.ts assistAim): over
// pulls swept round a basket's pull from natural starts (reach.ts findBasket) of the wide box (a
// desktop, a mouse's 420 px full pull) and the tall one (a phone held upright, a finger's 138 px), the
// px of pull length and of sideways pull that throw a clean basket (reach.ts cleanBasket: the throw's
// drag-free flight in the scene's default physics goes down through the opening before it touches
// anything), without and with the assist. The baskets are judged by the flight itself, not by the
// assist.
import { describe, expect, it } from 'vitest';
import { AIM_ASSIST, assistAim, basketPull } from '../../games/bouncing-balls/aim-assist';
import { HOOP_SPOTS, HOOP_SPOTS_TALL, type HoopSpot, slingPull, slingSpeed } from '../../games/bouncing-balls/hoop';
import { cleanBasket, findBasket, naturalStarts, type Throw } from '../../games/bouncing-balls/reach';

/** Full pulls, px: a mouse's at 1280 x 800 (main.ts fullPull) and a finger's at 390 x 844 (fingerFullPull: the room under the floor). */
const DESK = 420,
  PHONE = 138;

/** Step of the sweeps, px. */
const STEP = 0.5;

/**
 * The run of pulls that score round basket `t`'s pull, px: along its direction (`length`) and across
 * it at its length (`side`), each followed to 80 px either way, throwing each pull as is (`assisted`
 * false) or as the assist draws it.
 */
function windows(spot: HoopSpot, tall: boolean, t: Throw, full: number, finger: boolean, assisted: boolean) {
  const raw = (px: number, py: number): boolean => {
    const l = Math.hypot(px, py);
    if (l === 0 || l > full) return false;
    return cleanBasket(spot, tall, { x: t.x, y: t.y, angle: (Math.atan2(py, -px) * 180) / Math.PI, speed: slingSpeed(l, full) });
  };
  const thrown = (px: number, py: number): boolean => {
    const a = assisted ? assistAim(px, py, t.x, t.y, spot, { gravity: 9.81, fullPull: full, finger }, raw) : null;
    return a ? raw(a[0], a[1]) : raw(px, py);
  };
  const a = (t.angle * Math.PI) / 180,
    pull = slingPull(t.speed, full);
  const along = (l: number) => thrown(-Math.cos(a) * l, Math.sin(a) * l);
  const across = (s: number) => thrown(-Math.cos(a + s / pull) * pull, Math.sin(a + s / pull) * pull);
  const run = (at: (d: number) => boolean, base: number) => {
    let hi = base,
      lo = base;
    while (hi - base < 80 && at(hi + STEP)) hi += STEP;
    while (base - lo < 80 && at(lo - STEP)) lo -= STEP;
    return hi - lo;
  };
  return { pull, length: run(along, pull), side: run(across, 0) };
}

describe('bouncing-balls aim assist', () => {
  it('desktop (a mouse): widens the pulls that score 2 times and more, within its reach', () => {
    const median = (v: number[]) => [...v].sort((p, q) => p - q)[Math.floor(v.length / 2)]!;
    const rows: { before: ReturnType<typeof windows>; after: ReturnType<typeof windows> }[] = [];
    for (const spot of HOOP_SPOTS) {
      // Every twelfth natural start (reach.ts: the lower part of the box, over the pile).
      const starts = naturalStarts(spot, false);
      for (let k = 0; k < starts.length; k += 24) {
        const t = findBasket(spot, false, starts[k]!, starts[k + 1]!);
        if (t) rows.push({ before: windows(spot, false, t, DESK, false, false), after: windows(spot, false, t, DESK, false, true) });
      }
    }
    expect(rows.length).toBeGreaterThanOrEqual(8);
    for (const { before, after } of rows) {
      // Never narrower (the assist only draws a pull to one that scores); no wider than its reach
      // either side of the basket: twice 10 % of the pull along it (20 % for the pulls along a
      // slanted run of baskets), across it twice the reach of each of the three aim points (the
      // throws through the hoop's middle run slantwise across the pull), with a step to spare.
      expect(after.length).toBeGreaterThanOrEqual(before.length);
      expect(after.side).toBeGreaterThanOrEqual(before.side);
      expect(after.length).toBeLessThanOrEqual(before.length + 4 * AIM_ASSIST.share * after.pull + 2 * STEP);
      const reachSide = after.pull * Math.tan((AIM_ASSIST.degrees * Math.PI) / 180);
      expect(after.side).toBeLessThanOrEqual(before.side + 6 * reachSide + 2 * STEP);
    }
    // Medians: before some 20 px long and 13 across (a shaky hand's few px); after at least twice that.
    const [bl, bs] = [median(rows.map((r) => r.before.length)), median(rows.map((r) => r.before.side))];
    const [al, as] = [median(rows.map((r) => r.after.length)), median(rows.map((r) => r.after.side))];
    expect(bl).toBeLessThan(30);
    expect(bs).toBeLessThan(20);
    expect(al).toBeGreaterThanOrEqual(2 * bl);
    expect(as).toBeGreaterThanOrEqual(2 * bs);
  }, 60_000);

  it('phone (a finger): the pulls that score across the pull widen, and a pull a third too long still misses', () => {
    const spot = HOOP_SPOTS_TALL[0]!;
    // The standard start of the phone's pull tests (bouncing-balls-assist.test.ts).
    const t = findBasket(spot, true, 3, 3)!;
    const before = windows(spot, true, t, PHONE, true, false);
    const after = windows(spot, true, t, PHONE, true, true);
    expect(after.side).toBeGreaterThanOrEqual(2 * before.side);
    expect(after.length).toBeGreaterThanOrEqual(2 * before.length);
    // Not every pull: one a third longer than the basket's (far past its 14 px finger reach) is left alone.
    const a = (t.angle * Math.PI) / 180,
      l = (4 / 3) * after.pull;
    const scores = () => true;
    expect(
      assistAim(-Math.cos(a) * l, Math.sin(a) * l, t.x, t.y, spot, { gravity: 9.81, fullPull: PHONE, finger: true }, scores),
    ).toBeNull();
  }, 60_000);

  it('basketPull: the drag-free throw at that pull comes down through the aim point', () => {
    const g = 9.81,
      full = 420;
    for (const [x, y, angle, ax, ay] of [
      [2, 2, 60, 12, 6],
      [14, 2, 120, 4, 7],
      [3, 3, 80, 6, 9],
    ] as const) {
      const a = (angle * Math.PI) / 180;
      const l = basketPull(x, y, a, ax, ay, g, full)!;
      expect(l).toBeGreaterThan(0);
      const v = slingSpeed(l, full),
        vx = v * Math.cos(a),
        vy = v * Math.sin(a);
      const time = (ax - x) / vx;
      expect(y + vy * time - 0.5 * g * time * time).toBeCloseTo(ay, 6);
      expect(vy - g * time).toBeLessThan(0);
    }
    // Behind the throw, above its line, or past the top speed: none.
    expect(basketPull(5, 2, Math.PI / 3, 2, 3, g, full)).toBeNull();
    expect(basketPull(2, 2, Math.PI / 6, 4, 8, g, full)).toBeNull();
    expect(basketPull(0, 0, Math.PI / 4, 1000, 0, g, full)).toBeNull();
  });

  it('rejects a non-finite pull, naming the function', () => {
    const opts = { gravity: 9.81, fullPull: DESK, finger: false };
    expect(() => assistAim(Number.NaN, 1, 2, 2, HOOP_SPOTS[0]!, opts, () => true)).toThrow(/assistAim/);
    expect(assistAim(0, 0, 2, 2, HOOP_SPOTS[0]!, opts, () => true)).toBeNull();
  });
});
