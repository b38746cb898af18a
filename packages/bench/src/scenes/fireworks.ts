import { particlesExpired } from '@bitphysics/physics';
import type { BenchScene, ExtraValue } from './types.js';
import { collectGarbage } from '../memory.js';
import { summarize } from '../stats.js';
import { round, sig } from './format.js';

const MB = 2 ** 20;

/** V8 heap in use now, bytes. */
function heapBytes(): number {
  return process.memoryUsage().heapUsed;
}

const num = (digits: number) => (v: ExtraValue): string => (typeof v === 'number' ? v.toFixed(digits) : String(v));

/**
 * Bench side of `fireworks` (2D steady churn: shells burst into sparks that burst into embers, spawn
 * and expiry every step). Besides the step times it measures, on our world, after every timed step
 * and outside the timed interval:
 *
 * - live particles (min / median / max over the timed steps): the world's live entities less the
 *   scene's three emitters;
 * - spawned per step (every emitter's `spawned` counter), expired per step (`particlesExpired`:
 *   lifetimes that ran out) and recycled per step (spawned - expired - change of live: particles the
 *   'recycle-oldest' policy removed because the world was full), means over the timed steps;
 * - the V8 heap at the start of the timed run (after a full garbage collection), at its end (as it
 *   is, and again after a full collection), the retained growth end - start in MB and per 1,000 steps,
 *   and an estimate of what a step allocates: the sum of the heap's rises from one step to the next
 *   (its falls are collections) per step, less what the sampling itself allocates (calibrated before
 *   timing). A flat heap shows as a growth near 0 and an allocation near 0 KB a step.
 *
 * - `stepsWithoutSpawn`, `stepsWithoutExpiry`: timed steps in which nothing was spawned / nothing
 *   expired (0 in steady churn), and `liveStartOfTiming`: live particles when timing began (after warm-up).
 *
 * Steady state takes about 5 s to reach (shells rise ~1 s, sparks live 1-2 s, embers 0.5-1 s after
 * them): at the default 50,000, the live count is ~4,800 after 100 steps, ~42,000 after 200 and
 * ~50,000 from step 300 on, where spawned and expired per step level off at ~990 each. Hence 360
 * warm-up steps (6 s, past the ramp) and 600 timed steps (10 s of steady churn, several shell
 * lifetimes) by default.
 */
export const fireworksBench: BenchScene = {
  name: 'fireworks',
  maxCount: 10_000_000,
  defaults: { steps: 600, warmup: 360 },
  probe(world, handles) {
    const h = handles as { shells: number; sparks: number; embers: number };
    const emitters = [h.shells, h.sparks, h.embers];
    const spawnedOf = world.components.Emitter.spawned;
    const droppedOf = world.components.Emitter.dropped;
    const others = world.entityIndex.aliveCount; // the emitters: everything alive before the first particle
    const spawnedNow = (): number => spawnedOf[emitters[0]!]! + spawnedOf[emitters[1]!]! + spawnedOf[emitters[2]!]!;
    const droppedNow = (): number => droppedOf[emitters[0]!]! + droppedOf[emitters[1]!]! + droppedOf[emitters[2]!]!;

    let live = new Float64Array(0), spawned = new Float64Array(0), expired = new Float64Array(0);
    let k = 0, lastSpawned = 0, lastExpired = 0, lastHeap = 0, allocated = 0, samplerBytes = 0;
    let liveStart = 0, droppedStart = 0, droppedEnd = 0, maxEntities = 0;
    let heapStart = NaN, heapEnd = NaN, heapEndGc = NaN;
    return {
      beginTiming(steps: number): void {
        live = new Float64Array(steps); spawned = new Float64Array(steps); expired = new Float64Array(steps);
        k = 0;
        lastSpawned = spawnedNow(); lastExpired = particlesExpired(world); droppedStart = droppedNow();
        liveStart = world.entityIndex.aliveCount - others;
        collectGarbage();
        collectGarbage();
        // What one heap sample allocates (process.memoryUsage builds an object), to subtract below.
        const calibrate = 256;
        let rises = 0, prev = heapBytes();
        for (let i = 0; i < calibrate; i++) { const now = heapBytes(); if (now > prev) rises += now - prev; prev = now; }
        samplerBytes = rises / calibrate;
        collectGarbage();
        heapStart = heapBytes();
        lastHeap = heapStart;
        allocated = 0;
      },
      afterStep(): void {
        const now = heapBytes();
        if (now > lastHeap) allocated += now - lastHeap;
        lastHeap = now;
        if (k >= live.length) return;
        const alive = world.entityIndex.aliveCount;
        if (alive > maxEntities) maxEntities = alive;
        live[k] = alive - others;
        const s = spawnedNow();
        spawned[k] = s - lastSpawned; lastSpawned = s;
        const ex = particlesExpired(world);
        expired[k] = ex - lastExpired; lastExpired = ex;
        k++;
      },
      endTiming(): void {
        heapEnd = heapBytes();
        droppedEnd = droppedNow();
        collectGarbage();
        collectGarbage();
        heapEndGc = heapBytes();
      },
      bodies(): number {
        return k > 0 ? summarize(live.subarray(0, k)).median : liveStart;
      },
      extras() {
        const n = Math.max(1, k);
        const liveSummary = k > 0 ? summarize(live.subarray(0, k)) : { min: 0, median: 0, max: 0 };
        let spawnedSum = 0, expiredSum = 0, noSpawn = 0, noExpiry = 0;
        for (let i = 0; i < k; i++) {
          spawnedSum += spawned[i]!; expiredSum += expired[i]!;
          if (spawned[i] === 0) noSpawn++;
          if (expired[i] === 0) noExpiry++;
        }
        const liveEnd = k > 0 ? live[k - 1]! : liveStart;
        const recycled = spawnedSum - expiredSum - (liveEnd - liveStart);
        const growthMB = (heapEndGc - heapStart) / MB;
        return {
          liveMin: liveSummary.min,
          liveMedian: liveSummary.median,
          liveMax: liveSummary.max,
          spawnedPerStep: round(spawnedSum / n, 2),
          expiredPerStep: round(expiredSum / n, 2),
          recycledPerStep: round(recycled / n, 2),
          droppedPerStep: round((droppedEnd - droppedStart) / n, 2),
          stepsWithoutSpawn: noSpawn,
          stepsWithoutExpiry: noExpiry,
          liveStartOfTiming: liveStart,
          capacity: world.capacity,
          maxEntities,
          heapStartMB: round(heapStart / MB, 3),
          heapEndMB: round(heapEnd / MB, 3),
          heapEndAfterGcMB: round(heapEndGc / MB, 3),
          heapGrowthMB: round(growthMB, 3),
          heapGrowthPer1000StepsMB: round((1000 * growthMB) / n, 3),
          allocatedKBPerStep: sig(Math.max(0, allocated / n - samplerBytes) / 1024, 4),
        };
      },
    };
  },
  columns: [
    { key: 'liveMedian', label: 'live (median)', format: num(0) },
    { key: 'spawnedPerStep', label: 'spawned/step', format: num(1) },
    { key: 'expiredPerStep', label: 'expired/step', format: num(1) },
    { key: 'heapStartMB', label: 'heap start MB', format: num(2) },
    { key: 'heapEndAfterGcMB', label: 'heap end MB', format: num(2) },
    { key: 'heapGrowthPer1000StepsMB', label: 'MB/1000 steps', format: num(3) },
    { key: 'allocatedKBPerStep', label: 'alloc KB/step', format: num(2) },
  ],
  notes: [
    'live: particles alive after each timed step (min/median/max in --json); spawned/expired/recycled per step: means over the timed steps ' +
      '(recycled: removed early by the recycle-oldest policy of a full world).',
    'heap: V8 heap used at the start of the timed run and at its end, both after a full garbage collection; MB/1000 steps: their difference ' +
      'per 1,000 steps (flat heap: ~0); alloc KB/step: sum of the heap\'s step-to-step rises per step, less the sampling\'s own allocation.',
  ],
};
