import { expect, test } from 'vitest';
import { claimBlock } from '../../packages/physics/src/threads/block-claim.js';

// claimBlock (threads/block-claim.ts) hands out a unit's blocks to threads by flags. The rule is
// counted, not timed: threads are simulated by interleaving their calls in a given order, so there
// is no tolerance.

/** Runs `threads` simulated threads over a unit of `count` blocks, thread `order[i % order.length]` calling at step i. */
function run(count: number, threads: number, order: number[]): number[][] {
  const claim = new Int32Array(new SharedArrayBuffer(4 * (count + 8)));
  const base = 5; // flags before the unit's belong to earlier units
  const cursors = Array.from({ length: threads }, () => new Int32Array(2));
  const taken: number[][] = Array.from({ length: threads }, () => []);
  // Threads that never appear in `order` never run (a worker the system did not schedule).
  const done = Array.from({ length: threads }, (_, t) => !order.includes(t));
  for (let i = 0; done.some((d) => !d); i++) {
    const t = order[i % order.length]!;
    if (done[t]) continue;
    const b = claimBlock(claim, base, count, t, threads, cursors[t]!);
    if (b < 0) done[t] = true;
    else taken[t]!.push(b);
  }
  expect(Array.from(claim.subarray(0, base))).toEqual([0, 0, 0, 0, 0]);
  expect(Array.from(claim.subarray(base, base + count))).toEqual(new Array(count).fill(1));
  return taken;
}

test('every block of a unit is taken exactly once, each thread from its own share first', () => {
  // Two threads at the same pace: each takes exactly its own half, in order.
  expect(run(16, 2, [0, 1])).toEqual([
    [0, 1, 2, 3, 4, 5, 6, 7],
    [8, 9, 10, 11, 12, 13, 14, 15],
  ]);
  // Thread 1 three times as fast: it finishes its half, then takes thread 0's from the end backward,
  // and they meet; no block twice, none left.
  const [a, b] = run(16, 2, [0, 1, 1, 1]);
  expect(a).toEqual([0, 1, 2, 3]);
  expect(b).toEqual([8, 9, 10, 11, 12, 13, 14, 15, 7, 6, 5, 4]);
  // Three threads, one that never runs: the other two take its share between them.
  // Thread 0, done with its own share, finds thread 1's share taken and takes thread 2's from its end;
  // thread 1 passes over that taken end and takes the next, and so on until they meet.
  const [p, q, r] = run(9, 3, [0, 1]);
  expect(r).toEqual([]);
  expect(p).toEqual([0, 1, 2, 8, 6]);
  expect(q).toEqual([3, 4, 5, 7]);
});

test("every idle thread helps with a slow thread's share, not only the first to reach it", () => {
  // Four threads, thread 3 never running: threads 0, 1 and 2 finish their own shares together, then
  // all three take thread 3's share from its end, each passing over the blocks the others took.
  // (Before, a thief stopped at the first taken block, so thread 0 alone took 15, 14, 13 and 12.)
  const [p, q, r, s] = run(16, 4, [0, 1, 2]);
  expect(s).toEqual([]);
  expect(p).toEqual([0, 1, 2, 3, 15, 12]);
  expect(q).toEqual([4, 5, 6, 7, 14]);
  expect(r).toEqual([8, 9, 10, 11, 13]);
});

test('a thread that arrives after the others took everything finds nothing', () => {
  const claim = new Int32Array(new SharedArrayBuffer(4 * 4)).fill(1);
  const cursor = new Int32Array(2);
  expect(claimBlock(claim, 0, 4, 1, 2, cursor)).toBe(-1);
  expect(claimBlock(claim, 0, 4, 1, 2, cursor)).toBe(-1);
  // A unit of no blocks.
  expect(claimBlock(claim, 0, 0, 0, 1, new Int32Array(2))).toBe(-1);
});
