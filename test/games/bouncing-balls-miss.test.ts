// What the page says of a miss (games/bouncing-balls/hoop.ts missWords): every miss is said, with why.
// On the phone's tall box a full-power throw from a ball low on the heap reaches the ceiling and falls
// back onto the heap some 2.5 s later; with no streak to break that miss said nothing, and read as a
// throw that never happened.
import { describe, expect, it } from 'vitest';
import { HOOP_SPOTS_TALL, MAX_THROW_SPEED, missWords, PLAYER_RADIUS, throwPath } from '../../games/bouncing-balls/hoop';
import { layoutOf } from '../../games/bouncing-balls/scene';

const { box } = layoutOf(true);
/** The highest a ball's centre goes under the tall box's top, m. */
const ceiling = box.max[1] - PLAYER_RADIUS;

/** The highest point of a drag-free throw's centre from (x, y), m, at `angle` degrees and `speed` m/s, to its first touch of the box. */
function peak(x: number, y: number, angle: number, speed: number): number {
  const a = (angle * Math.PI) / 180,
    h = 1 / 120;
  const path = throwPath(x, y, speed * Math.cos(a), speed * Math.sin(a), {
    gravity: 9.81,
    drag: 'none',
    k: 0,
    mass: 1,
    radius: PLAYER_RADIUS,
    box,
    every: h,
    step: h,
    seconds: 3,
    bounces: 0,
    walls: [],
  });
  let top = y;
  for (let i = 1; i < path.length; i += 2) top = Math.max(top, path[i]!);
  return top;
}

describe('bouncing-balls missWords', () => {
  it('says a miss with no streak to break, and why: off the ceiling, short of the rim', () => {
    const spot = HOOP_SPOTS_TALL[0]!;
    expect(missWords(false, ceiling, ceiling, spot)).toBe('Missed: off the ceiling');
    expect(missWords(false, spot.y - 1, ceiling, spot)).toBe('Missed: short of the rim');
    expect(missWords(false, spot.y + 1, ceiling, spot)).toBe('Missed');
    expect(missWords(true, spot.y + 1, ceiling, spot)).toBe('Missed · streak over');
  });
  it('calls every steep full-power throw from a low heap ball on the phone "off the ceiling"', () => {
    // Starts 1 m over the floor in the box's middle, throws 80 to 100 degrees (a full pull straight
    // down and up to 10 degrees aside; flatter ones may hit a side wall first): the 0.3 m tolerance of
    // missWords covers the path's last step short of the touch (< 20 m/s x 1/120 s).
    let n = 0;
    for (let x = 4; x <= 6; x += 1)
      for (let angle = 80; angle <= 100; angle += 5) {
        expect(missWords(false, peak(x, 1, angle, MAX_THROW_SPEED), ceiling, HOOP_SPOTS_TALL[0]!)).toBe('Missed: off the ceiling');
        n++;
      }
    expect(n).toBe(15);
  });
});
