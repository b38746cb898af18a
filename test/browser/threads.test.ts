/**
 * Worker threads in the page: `npm start` serves the gallery cross-origin isolated (COOP same-origin,
 * COEP require-corp), so SharedArrayBuffer exists and a world made with `threads: 2` runs its
 * integration loop on a Web Worker beside the page's thread. The reference is the same lab with one
 * thread: after the same steps from the same start, the two states hash the same (stateHash covers
 * every bit of every body; the tolerance is zero).
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Harness, START_TIMEOUT_MS } from './harness';

type ThreadedLab = {
  paused: boolean;
  reset(): void;
  /** Timed steps (the labs); other games step with `step()`. */
  advance?(n: number): void;
  step(): void;
  isolated: boolean;
  threadsReady(): Promise<void>;
  parallelRuns?(): number;
  stateHash(): string;
  world: { threads: number; steps: number };
};

let h: Harness;
beforeAll(async () => {
  h = await Harness.start();
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

/** Opens `folder` with `query`, pauses it, starts over, waits for its workers and runs `steps` steps; returns what the page saw. */
async function run(folder: string, query: Record<string, string | number>, steps: number) {
  const g = await h.openGame(folder, { query });
  try {
    return await g.page.evaluate(async (n) => {
      const w = window.game as unknown as ThreadedLab;
      w.paused = true;
      w.reset();
      await w.threadsReady();
      if (w.advance) w.advance(n);
      else for (let i = 0; i < n; i++) w.step();
      return {
        isolated: w.isolated,
        coi: (globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated === true,
        threads: w.world.threads,
        steps: w.world.steps,
        runs: w.parallelRuns?.() ?? 0,
        hash: w.stateHash(),
      };
    }, steps);
  } finally {
    await g.close();
  }
}

describe('threads in the browser', () => {
  it('lab-galaxy with threads=2 is cross-origin isolated, uses its worker and matches one thread to the bit', async () => {
    // 40,000 stars: above 2 x MIN_PARALLEL_PER_THREAD, so the worker takes half the integration.
    const query = { count: 40_000, theta: 1 };
    const two = await run('lab-galaxy', { ...query, threads: 2 }, 3);
    const one = await run('lab-galaxy', { ...query, threads: 1 }, 3);
    expect(two.coi).toBe(true);
    expect(two.isolated).toBe(true);
    expect(two.threads).toBe(2);
    expect(two.steps).toBe(3);
    expect(two.runs).toBeGreaterThan(0);
    expect(one.threads).toBe(1);
    expect(two.hash).toBe(one.hash);
  }, 180_000);

  it('fireworks takes ?threads: the world has 2 threads and the same state as with 1', async () => {
    // Free play: its opening salvo's shells and tails fill the 90 steps (the lantern show starts with a dark sky).
    const two = await run('fireworks', { play: 'free', threads: 2, seed: 5 }, 90);
    const one = await run('fireworks', { play: 'free', threads: 1, seed: 5 }, 90);
    expect(two.threads).toBe(2);
    expect(one.threads).toBe(1);
    expect(two.hash).toBe(one.hash);
  }, 180_000);
});
