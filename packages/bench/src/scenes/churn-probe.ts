import { type PhysicsWorld, particlesExpired, slotOf } from '@bitphysics/physics';
import { collectGarbage } from '../memory.js';
import { summarize } from '../stats.js';
import { round, sig } from './format.js';
import type { ExtraColumn, ExtraValue, SceneProbe } from './types.js';

const MB = 2 ** 20;

/** V8 heap in use now, bytes. */
function heapBytes(): number {
  return process.memoryUsage().heapUsed;
}

const num =
  (digits: number) =>
  (v: ExtraValue): string =>
    typeof v === 'number' ? v.toFixed(digits) : String(v);

/**
 * The measurements of a particle churn scene (fireworks, fountain) on our world, taken after every
 * timed step and outside the timed interval, over the emitters `emitters` (handles):
 *
 * - live particles (min / median / max over the timed steps): the world's live entities less those
 *   alive when the probe was made (the scene's emitters);
 * - spawned per step (the emitters' `Emitter.spawned`), expired per step (`particlesExpired`:
 *   lifetimes that ran out) and recycled per step (spawned - expired - change of live: particles the
 *   'recycle-oldest' policy removed because the world was full), dropped per step (`Emitter.dropped`),
 *   means over the timed steps;
 * - the V8 heap at the start of the timed run (after a full garbage collection), at its end (as it
 *   is, and again after a full collection), the retained growth end - start in MB and per 1,000 steps,
 *   and an estimate of what a step allocates: the sum of the heap's rises from one step to the next
 *   (its falls are collections) per step, less what the sampling itself allocates (calibrated before
 *   timing). A flat heap shows as a growth near 0 and an allocation near 0 KB a step;
 * - `stepsWithoutSpawn`, `stepsWithoutExpiry`: timed steps in which nothing was spawned / nothing
 *   expired (0 in steady churn), and `liveStartOfTiming`: live particles when timing began (after warm-up).
 */
export function churnProbe(world: PhysicsWorld, emitters: readonly number[]): SceneProbe {
  const others = world.entityIndex.aliveCount; // the emitters: everything alive before the first particle
  const slots = emitters.map(slotOf);
  const sum = (of: Float64Array): number => {
    let s = 0;
    for (let i = 0; i < slots.length; i++) s += of[slots[i]!]!;
    return s;
  };
  const spawnedNow = (): number => sum(world.components.Emitter.spawned);
  const droppedNow = (): number => sum(world.components.Emitter.dropped);

  let live = new Float64Array(0),
    spawned = new Float64Array(0),
    expired = new Float64Array(0);
  let k = 0,
    lastSpawned = 0,
    lastExpired = 0,
    lastHeap = 0,
    allocated = 0,
    samplerBytes = 0;
  let liveStart = 0,
    droppedStart = 0,
    droppedEnd = 0,
    maxEntities = 0;
  let heapStart = NaN,
    heapEnd = NaN,
    heapEndGc = NaN;
  return {
    beginTiming(steps: number): void {
      live = new Float64Array(steps);
      spawned = new Float64Array(steps);
      expired = new Float64Array(steps);
      k = 0;
      lastSpawned = spawnedNow();
      lastExpired = particlesExpired(world);
      droppedStart = droppedNow();
      liveStart = world.entityIndex.aliveCount - others;
      collectGarbage();
      collectGarbage();
      // What one heap sample allocates (process.memoryUsage builds an object), to subtract below.
      const calibrate = 256;
      let rises = 0,
        prev = heapBytes();
      for (let i = 0; i < calibrate; i++) {
        const now = heapBytes();
        if (now > prev) rises += now - prev;
        prev = now;
      }
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
      spawned[k] = s - lastSpawned;
      lastSpawned = s;
      const ex = particlesExpired(world);
      expired[k] = ex - lastExpired;
      lastExpired = ex;
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
      let spawnedSum = 0,
        expiredSum = 0,
        noSpawn = 0,
        noExpiry = 0;
      for (let i = 0; i < k; i++) {
        spawnedSum += spawned[i]!;
        expiredSum += expired[i]!;
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
}

/** Table columns of a churn scene (the fields `churnProbe` adds). */
export const CHURN_COLUMNS: readonly ExtraColumn[] = [
  { key: 'liveMedian', label: 'live (median)', format: num(0) },
  { key: 'spawnedPerStep', label: 'spawned/step', format: num(1) },
  { key: 'expiredPerStep', label: 'expired/step', format: num(1) },
  { key: 'heapStartMB', label: 'heap start MB', format: num(2) },
  { key: 'heapEndAfterGcMB', label: 'heap end MB', format: num(2) },
  { key: 'heapGrowthPer1000StepsMB', label: 'MB/1000 steps', format: num(3) },
  { key: 'allocatedKBPerStep', label: 'alloc KB/step', format: num(2) },
];

/** Notes printed under the table of a churn scene. */
export const CHURN_NOTES: readonly string[] = [
  'live: particles alive after each timed step (min/median/max in --json); spawned/expired/recycled per step: means over the timed steps ' +
    '(recycled: removed early by the recycle-oldest policy of a full world).',
  'heap: V8 heap used at the start of the timed run and at its end, both after a full garbage collection; MB/1000 steps: their difference ' +
    "per 1,000 steps (flat heap: ~0); alloc KB/step: sum of the heap's step-to-step rises per step, less the sampling's own allocation.",
];
