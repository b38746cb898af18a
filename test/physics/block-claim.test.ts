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
    if (b < 0) done[t] = true; else taken[t]!.push(b);
  }
  expect(Array.from(claim.subarray(0, base))).toEqual([0, 0, 0, 0, 0]);
  expect(Array.from(claim.subarray(base, base + count))).toEqual(new Array(count).fill(1));
  return taken;
}

test('every block of a unit is taken exactly once, each thread from its own share first', () => {
  // Two threads at the same pace: each takes exactly its own half, in order.
  expect(run(16, 2, [0, 1])).toEqual([[0, 1, 2, 3, 4, 5, 6, 7], [8, 9, 10, 11, 12, 13, 14, 15]]);
  // Thread 1 three times as fast: it finishes its half, then takes thread 0's from the end backward,
  // and they meet; no block twice, none left.
  const [a, b] = run(16, 2, [0, 1, 1, 1]);
  expect(a).toEqual([0, 1, 2, 3]);
  expect(b).toEqual([8, 9, 10, 11, 12, 13, 14, 15, 7, 6, 5, 4]);
  // Three threads, one that never runs: the other two take its share between them.
  // Thread 0, done with its own share, finds thread 1's end taken and takes thread 2's from its end;
  // thread 1 then finds that end taken too and stops, and thread 0 takes the rest of it.
  const [p, q, r] = run(9, 3, [0, 1]);
  expect(r).toEqual([]);
  expect(p).toEqual([0, 1, 2, 8, 7, 6]);
  expect(q).toEqual([3, 4, 5]);
});

test('a thread that arrives after the others took everything finds nothing', () => {
  const claim = new Int32Array(new SharedArrayBuffer(4 * 4)).fill(1);
  const cursor = new Int32Array(2);
  expect(claimBlock(claim, 0, 4, 1, 2, cursor)).toBe(-1);
  expect(claimBlock(claim, 0, 4, 1, 2, cursor)).toBe(-1);
  // A unit of no blocks.
  expect(claimBlock(claim, 0, 0, 0, 1, new Int32Array(2))).toBe(-1);
});
