/**
 * The ball a finger's press is on (games/bouncing-balls/finger-pick.ts): the heap shifts after every
 * throw, and a finger covers more than a phone's small balls.
 */
import { expect, test } from 'vitest';
import { fingerBall } from '../../games/bouncing-balls/finger-pick';

test('a finger pressing where a ball was drawn a moment before takes that ball, not the neighbour that rolled under it', () => {
  // The issue this answers: "I pressed where the gold ball had been and threw a blue one". Gold (1,
  // radius 0.3 m) rolled 0.45 m right after a throw; blue (2) rolled into the place it was drawn.
  const now = [
    { id: 1, x: 1.45, y: 0.3, r: 0.3 },
    { id: 2, x: 1.0, y: 0.32, r: 0.25 },
  ];
  const seen = new Map<number, readonly [number, number]>([
    [1, [1.0, 0.3]],
    [2, [0.55, 0.3]],
  ]);
  // At gold's old centre the finger is inside blue now (gap -0.25 m) and on gold's old place (-0.3 m).
  expect(fingerBall(now, seen, 1.0, 0.3, 0.1, 0.4)).toBe(1);
  // With nothing seen before, where the balls are now decides (blue).
  expect(fingerBall(now, new Map(), 1.0, 0.3, 0.1, 0.4)).toBe(2);
});

test("a finger's press within its reach of a small ball's centre takes it; farther off, none", () => {
  // A ball 0.2 m across, the finger's reach 0.5 m (some 22 px on a phone): 0.45 m from its centre it
  // is taken though 0.35 m off its edge (over three times the drag's 0.1 m reach), 0.55 m off not.
  const now = [{ id: 7, x: 0, y: 0, r: 0.1 }];
  expect(fingerBall(now, new Map(), 0.45, 0, 0.1, 0.5)).toBe(7);
  expect(fingerBall(now, new Map(), 0.55, 0, 0.1, 0.5)).toBe(0);
  expect(() => fingerBall(now, new Map(), 0, 0, -1, 0.5)).toThrow(RangeError);
});
