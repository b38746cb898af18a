// Bouncing balls: the aiming label says "no shot from under the hoop" (reach.ts noShotWords) exactly
// for the starts from which no pull of the slingshot scores. Checked against a brute-force sweep of
// a player's pulls: every direction 1 degree apart and every pull length 2 px apart of a full pull
// of 138 px (a finger's at 390 x 844; the phone's curve, hoop.ts slingRoom, in the tall box, the
// 20 m/s curve in the wide one), each flown drag-free (reach.ts cleanBasket). The starts are rows
// across each first hoop, past the front rim's end and under the hoop, where the answer changes.
import { describe, expect, it } from 'vitest';
import { HOOP_SPOTS, HOOP_SPOTS_TALL, type HoopSpot, MAX_THROW_SPEED, slingRoom, slingSpeed } from '../../games/bouncing-balls/hoop';
import { anyBasket, cleanBasket, noShotWords } from '../../games/bouncing-balls/reach';

const G = 9.81,
  FULL = 138;

/** The slingshot's speeds from height y: the phone's room in the tall box, 0 to 20 m/s in the wide one. */
function speeds(spot: HoopSpot, tall: boolean, y: number): { low: number; top: number } {
  return tall ? slingRoom(y, spot.y, G) : { low: 0, top: MAX_THROW_SPEED };
}

/** Whether some pull (1 degree, 2 px apart) scores from (x, y). */
function bruteScores(spot: HoopSpot, tall: boolean, x: number, y: number): boolean {
  const room = tall ? slingRoom(y, spot.y, G) : undefined;
  for (let p = 2; p <= FULL; p += 2) {
    const v = slingSpeed(p, FULL, room);
    for (let angle = 1; angle < 180; angle++) {
      const a = (angle * Math.PI) / 180,
        vx = v * Math.cos(a),
        vy = v * Math.sin(a);
      // Only flown when its drag-free parabola comes down through the rim's line within 0.2 m of
      // the opening (the others cannot score; the margin is wide of the flight's exact parabola).
      const disc = vy * vy - 2 * G * (spot.y - y);
      if (disc < 0) continue;
      const cross = x + (vx * (vy + Math.sqrt(disc))) / G;
      if (cross < spot.x - 1.2 || cross > spot.x + 1.2) continue;
      if (cleanBasket(spot, tall, { x, y, angle, speed: v })) return true;
    }
  }
  return false;
}

describe('bouncing-balls no-shot label', () => {
  const cases: [boolean, number, number[]][] = [
    // Tall box, hoop at (7.8, 9), board right: x 5 scores, 5.5..6 beside the front rim do not, 6.5.. under it.
    [true, 1, [5, 5.5, 6.5, 9.5]],
    // Wide box, hoop at (13, 6), board right.
    [false, 1, [10.5, 11.5, 13]],
  ];
  for (const [tall, y, xs] of cases)
    it(`${tall ? 'phone (tall)' : 'desktop (wide)'} box, starts at y ${y} m: said exactly where no pull scores`, () => {
      const spot = (tall ? HOOP_SPOTS_TALL : HOOP_SPOTS)[0]!;
      const said: string[] = [],
        none: boolean[] = [];
      for (const x of xs) {
        const { low, top } = speeds(spot, tall, y);
        const words = noShotWords(spot, tall, x, y, low, top);
        said.push(words);
        none.push(!bruteScores(spot, tall, x, y));
        expect(anyBasket(spot, tall, x, y, low, top)).toBe(!none.at(-1));
      }
      // Exact: the label shows for a start iff the sweep finds no pull that scores there.
      expect(said.map((w) => w !== '')).toEqual(none);
      // Both kinds of start are in each row (the test can tell them apart), and those under the
      // hoop name it.
      expect(none).toContain(true);
      expect(none).toContain(false);
      expect(said.at(-1)).toBe('no shot from under the hoop: start further out');
    }, 20_000);

  it('no word above the shot line (the page says "too high" there) or from a start that scores', () => {
    const spot = HOOP_SPOTS_TALL[0]!;
    expect(noShotWords(spot, true, 9, 8.9, 0, 20)).toBe('');
    expect(noShotWords(spot, true, 3, 1.5, slingRoom(1.5, spot.y, G).low, slingRoom(1.5, spot.y, G).top)).toBe('');
    expect(() => anyBasket(spot, true, Number.NaN, 1, 0, 20)).toThrow(RangeError);
  });
});
