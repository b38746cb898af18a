import { expect, test } from 'vitest';
import {
  CLEAR_PROBE_EVERY,
  LoopChooser,
  MAX_AGE,
  MIN_PROBE_PERIOD,
  nextProbePeriod,
  PROBE_EVERY,
  SWITCH_RATIO,
  WINDOW,
} from '../../packages/physics/src/threads/adaptive.js';

// The adaptive choice between a pool's threads and one thread (threads/adaptive.ts). The rule under
// test is counted in calls, not timed, so there is no tolerance: the fake loop's times are given.

/** Runs `calls` calls of one loop whose call i takes time(i, parallel) ms for 1000 elements; which way each ran. */
function simulate(calls: number, time: (i: number, parallel: boolean) => number): { ran: boolean[]; chooser: LoopChooser } {
  const chooser = new LoopChooser();
  const ran: boolean[] = [];
  for (let i = 0; i < calls; i++) {
    const parallel = chooser.choose('loop');
    ran.push(parallel);
    chooser.record('loop', parallel, time(i, parallel), 1000);
  }
  return { ran, chooser };
}

/** The calls that ran on one thread. */
const serialCalls = (ran: boolean[]): number[] => ran.map((p, i) => (p ? -1 : i)).filter((i) => i >= 0);

test('the calls between probes grow while the choice holds: twice up to PROBE_EVERY when close, four times up to CLEAR_PROBE_EVERY when clear', () => {
  expect(MIN_PROBE_PERIOD).toBe(4);
  expect(PROBE_EVERY).toBe(16);
  expect(CLEAR_PROBE_EVERY).toBe(64);
  // Close ways (within CLEAR_RATIO): up to PROBE_EVERY; clear ones: up to CLEAR_PROBE_EVERY.
  expect(nextProbePeriod(4, 1, 1.2)).toBe(8);
  expect(nextProbePeriod(16, 1, 1.2)).toBe(PROBE_EVERY);
  expect(nextProbePeriod(32, 1.2, 1)).toBe(PROBE_EVERY);
  expect(nextProbePeriod(4, 1, 2)).toBe(16);
  expect(nextProbePeriod(32, 1, 2)).toBe(CLEAR_PROBE_EVERY);
  expect(nextProbePeriod(64, 2, 1)).toBe(CLEAR_PROBE_EVERY);
  // The threads twice as fast: calls 3 and 4 are one thread's first two, then probes of one thread
  // 4 and 16 calls apart, then every 64.
  expect(serialCalls(simulate(300, (_, p) => (p ? 0.5 : 1)).ran)).toEqual([3, 4, 8, 24, 88, 152, 216, 280]);
  // One thread a little faster (1 against 1.1 ms): the threads are probed at 8, 16 and 32 (PROBE_EVERY apart from then on).
  const close = simulate(48, (_, p) => (p ? 1.1 : 1)).ran;
  expect(close.map((p, i) => (p && i >= 5 ? i : -1)).filter((i) => i >= 0)).toEqual([8, 16, 32]);
});

test('a noisy early sample of the threads is undone within a few calls', () => {
  // The threads take 0.6 ms for 1000 elements and one thread 1 ms, but other processes delayed the
  // threads' two timed calls of the start (5 ms, then 1.2 ms): the threads look slower, so calls 5
  // to 7 run on one thread; the threads are probed at call 8, MIN_PROBE_PERIOD after the choice was
  // made, found faster and kept; one thread is then probed at 12 and 28 (4 and 16 calls apart).
  const { ran, chooser } = simulate(40, (i, p) => (p ? (i === 1 ? 5 : i === 2 ? 1.2 : 0.6) : 1));
  expect(serialCalls(ran)).toEqual([3, 4, 5, 6, 7, 12, 28]);
  expect(chooser.preference('loop')).toBe(true);
});

test('one delayed call does not switch a loop; WINDOW slow calls in a row do', () => {
  // The threads take 0.5 ms for 1000 elements and one thread 1 ms. Calls 10 and 20 of the threads
  // are delayed to 8 ms (a worker the system did not schedule): the estimate is the least of the last
  // WINDOW times, so the loop stays on the threads. From call 33 on, the threads' loop really costs
  // 3 ms: after WINDOW calls at that cost the loop runs on one thread.
  expect(WINDOW).toBe(3);
  const { ran, chooser } = simulate(40, (i, p) => (p ? (i === 10 || i === 20 ? 8 : i >= 33 ? 3 : 0.5) : 1));
  // Calls 3 and 4 are one thread's first two; 8 and 24 are probes.
  expect(serialCalls(ran).filter((i) => i < 33)).toEqual([3, 4, 8, 24]);
  // Calls 33, 34 and 35 run on the threads at 3 ms; 36 to 38 on one thread, and 39 probes the
  // threads (MIN_PROBE_PERIOD after the switch), which are still slower.
  expect(ran.slice(33, 36)).toEqual([true, true, true]);
  expect(ran.slice(36)).toEqual([false, false, false, true]);
  expect(chooser.preference('loop')).toBe(false);
});

test('WINDOW delayed calls in a row switch a loop for a few calls, not for CLEAR_PROBE_EVERY', () => {
  // The threads take 0.5 ms and one thread 1 ms, but calls 70 to 72 of the threads are delayed to
  // 8 ms (a burst of other processes). Calls 73 to 75 then run on one thread, call 76 probes the
  // threads, finds them fast again and goes back to them; one thread is probed again 4 and 20 calls
  // later. (With a fixed period, the loop stayed on one thread until call 128, 55 calls at twice the
  // time.)
  const { ran, chooser } = simulate(160, (i, p) => (p ? (i >= 70 && i < 73 ? 8 : 0.5) : 1));
  expect(serialCalls(ran)).toEqual([3, 4, 8, 24, 73, 74, 75, 80, 96]);
  expect(chooser.preference('loop')).toBe(true);
});

test('the other way takes over only when it looks more than 10 % faster (SWITCH_RATIO)', () => {
  expect(SWITCH_RATIO).toBe(0.9);
  // One thread takes 1.05 ms for 1000 elements. The threads take 1 ms for calls 0 to 29, then 1.1 ms
  // (within 10 % of one thread: they stay preferred, probed at 48 and 64), then from call 60 1.3 ms:
  // after WINDOW calls at that cost one thread takes over at call 63, and the threads are probed 4
  // and 8 calls later (66, 74). Without the margin the loop went to one thread at call 34 already.
  const ran = simulate(80, (i, p) => (p ? (i < 30 ? 1 : i < 60 ? 1.1 : 1.3) : 1.05)).ran;
  expect(serialCalls(ran).filter((i) => i < 63)).toEqual([3, 4, 8, 16, 32, 48]);
  expect(ran.slice(63)).toEqual(ran.slice(63).map((_, k) => k + 63 === 66 || k + 63 === 74));
});

test('a loop whose work grows on both ways (a pile forming) stays on the faster way: the way not preferred runs only as single probes', () => {
  // The threads take half of one thread's time throughout, and both grow by 5 % of the first call's
  // time a call (four times as long by call 60). One thread runs only as probes, up to
  // CLEAR_PROBE_EVERY calls apart; its estimate is its newest probe (older times than MAX_AGE calls do
  // not count), and by call 81 the threads' own calls look slower than that: the call instead runs one
  // thread as a probe, which finds it still twice as slow. Before, the least of the last WINDOW probes
  // (calls 4 to 24) switched the loop: one thread ran calls 37 and 38 and again 112 and 113, each pair
  // at twice the threads' time.
  expect(MAX_AGE).toBe(PROBE_EVERY);
  const ran = simulate(300, (i, p) => (p ? 0.5 : 1) * (1 + 0.05 * i)).ran;
  expect(serialCalls(ran)).toEqual([3, 4, 8, 24, 81, 145, 209, 273]);
  // And one thread twice as fast as the threads, both growing: the threads only ever run as single probes.
  const rev = simulate(300, (i, p) => (p ? 1 : 0.5) * (1 + 0.05 * i)).ran;
  const threadCalls = rev.map((p, i) => (p && i >= 3 ? i : -1)).filter((i) => i >= 0);
  for (let k = 1; k < threadCalls.length; k++) expect(threadCalls[k]! - threadCalls[k - 1]!).toBeGreaterThan(1);
});
