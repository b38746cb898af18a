import { describe, expect, it } from 'vitest';
import { AIM_HELP_MISSES, aimHelp, SHORT_ARC_POINTS, shortArc } from '../../games/bouncing-balls/preview';

/** A drag-free arc from (x0, y0) at (vx, vy) m/s under 9.81 m/s^2, every 1/60 s for `seconds`: flat x, y pairs. */
function arc(x0: number, y0: number, vx: number, vy: number, seconds: number): number[] {
  const out: number[] = [];
  for (let t = 0; t <= seconds + 1e-9; t += 1 / 60) out.push(x0 + vx * t, y0 + vy * t - 4.905 * t * t);
  return out;
}

describe('bouncing balls aiming preview (preview.ts)', () => {
  it('shows no verdict or whole arc in normal play, and both after 3 misses in a row (help for a struggling player)', () => {
    expect(AIM_HELP_MISSES).toBe(3);
    expect([0, 1, 2].map((m) => aimHelp(m))).toEqual([false, false, false]);
    expect([3, 4, 23].map((m) => aimHelp(m))).toEqual([true, true, true]);
    expect(aimHelp(0, true)).toBe(true);
  });

  it('a lob shows its way up to its top only, a flat throw half the way to the hoop only', () => {
    // A lob from x = 0 at (3, 9) m/s: its top at 0.92 s (x 2.75 m), the hoop 6 m away.
    const lob = arc(0, 1, 3, 9, 2);
    const short = shortArc(lob, 6);
    const top = short.length / 2 - 1;
    // Ends at the top within one 1/60 s step (the tolerance of the sampling), never past it going down.
    expect(Math.abs(top / 60 - 9 / 9.81)).toBeLessThanOrEqual(1 / 60 + 1e-9);
    for (let i = 1; i <= top; i++) expect(short[2 * i + 1]!).toBeGreaterThanOrEqual(short[2 * i - 1]!);
    expect(short.length).toBeLessThan(lob.length / 2);
    // A flat throw (8, 5) m/s at a hoop 4 m away: up to x = 2 m (its top, at x 4.1 m, is further).
    const flat = shortArc(arc(0, 1, 8, 5, 1), 4);
    expect(flat.at(-2)!).toBeLessThanOrEqual(2);
    expect(flat.at(-2)!).toBeGreaterThan(2 - 8 / 60 - 1e-9);
    // Towards a hoop on the left too.
    const left = shortArc(arc(0, 1, -8, 5, 1), -4);
    expect(left.at(-2)!).toBeGreaterThanOrEqual(-2);
  });

  it(`keeps at least ${SHORT_ARC_POINTS} points, and a path that short whole`, () => {
    // Thrown straight down: its top is its start, yet its first dots show.
    expect(shortArc(arc(0, 5, 0.1, -3, 1), 3).length).toBe(2 * SHORT_ARC_POINTS);
    const tiny = arc(0, 1, 1, 1, 3 / 60);
    expect(shortArc(tiny, 5)).toEqual(tiny);
  });
});
