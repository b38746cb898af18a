import { expect, test } from 'vitest';
import { CLEAR_PROBE_EVERY, EARLY_CALLS, EARLY_PROBE_EVERY, LoopChooser, PROBE_EVERY, probePeriod, WINDOW } from '../../packages/physics/src/threads/adaptive.js';

// The adaptive choice between a pool's threads and one thread (threads/adaptive.ts). The rule under
// test is counted in calls, not timed, so there is no tolerance: the fake loop's times are given.

test('a noisy early sample of the threads is undone within a few calls, not sixteen', () => {
  const c = new LoopChooser();
  const site = 'loop';
  const ran: boolean[] = [];
  // The threads take 0.6 ms for 1000 elements and one thread 1 ms, but other processes delayed the
  // threads' two timed calls of the start (5 ms, then 1.2 ms): the threads look 1.2 times slower,
  // a close call, so they are probed again at call 8 (EARLY_PROBE_EVERY), found faster and kept;
  // one thread is then 1.67 times slower, a clear call, probed every PROBE_EVERY calls while young.
  for (let i = 0; i < 40; i++) {
    const parallel = c.choose(site);
    ran.push(parallel);
    c.record(site, parallel, parallel ? (i === 1 ? 5 : i === 2 ? 1.2 : 0.6) : 1, 1000);
  }
  const serialCalls = ran.map((p, i) => (p ? -1 : i)).filter((i) => i >= 0);
  expect(EARLY_PROBE_EVERY).toBe(4);
  expect(PROBE_EVERY).toBe(16);
  expect(serialCalls).toEqual([3, 4, 5, 6, 7, 16, 32]);
  expect(c.preference(site)).toBe(true);
});

test('probe periods: often while young and close, rarely once clear', () => {
  expect(probePeriod(10, 1, 1.2)).toBe(EARLY_PROBE_EVERY);
  expect(probePeriod(10, 1, 2)).toBe(PROBE_EVERY);
  expect(probePeriod(EARLY_CALLS, 1.2, 1)).toBe(PROBE_EVERY);
  expect(probePeriod(EARLY_CALLS, 2, 1)).toBe(CLEAR_PROBE_EVERY);
  // A close call: the slower way is still probed every EARLY_PROBE_EVERY calls while young.
  const c = new LoopChooser();
  const ran: boolean[] = [];
  for (let i = 0; i < 48; i++) {
    const parallel = c.choose('close');
    ran.push(parallel);
    c.record('close', parallel, parallel ? 1.1 : 1, 1000);
  }
  expect(ran.map((p, i) => (p && i >= 5 ? i : -1)).filter((i) => i >= 0)).toEqual([8, 12, 16, 20, 24, 28, 32, 36, 40, 44]);
});

test('one delayed call does not switch a loop; WINDOW slow calls in a row do', () => {
  // The threads take 0.5 ms for 1000 elements and one thread 1 ms. Calls 10 and 20 of the threads
  // are delayed to 8 ms (a worker the system did not schedule): the estimate is the least of the last
  // WINDOW times, so the loop stays on the threads (the average this replaced switched it to one
  // thread until the next probe). From call 33 on, the threads' loop really costs 3 ms: after WINDOW
  // calls at that cost the loop runs on one thread.
  expect(WINDOW).toBe(3);
  const c = new LoopChooser();
  const ran: boolean[] = [];
  for (let i = 0; i < 40; i++) {
    const parallel = c.choose('loop');
    ran.push(parallel);
    c.record('loop', parallel, parallel ? (i === 10 || i === 20 ? 8 : i >= 33 ? 3 : 0.5) : 1, 1000);
  }
  // Calls 3 and 4 are one thread's first two; 16 and 32 are probes (PROBE_EVERY while young and clear).
  expect(ran.map((p, i) => (p ? -1 : i)).filter((i) => i >= 0 && i < 33)).toEqual([3, 4, 16, 32]);
  // Calls 33, 34 and 35 run on the threads at 3 ms; from 36 on, one thread.
  expect(ran.slice(33, 36)).toEqual([true, true, true]);
  expect(ran.slice(36)).toEqual([false, false, false, false]);
  expect(c.preference('loop')).toBe(false);
});
