import { createPhysicsWorld, step } from '@bitphysics/physics';
import { collectGarbage, sampleMemory } from './memory.js';
import { resolveScene } from './scenes/index.js';
import { median } from './stats.js';

/** Options of a soak run. */
export interface SoakOptions {
  readonly scene: string;
  readonly count: number;
  readonly seed: number;
  /** Steps in all (`--steps`; the soak's default is 100,000). */
  readonly steps: number;
  /** Steps between reports. */
  readonly every: number;
  /** Receives each report line (and the closing one). */
  readonly print: (line: string) => void;
}

/**
 * One report: steps done, the median step (ms, wall clock) of the last block, the process CPU time a
 * step over the block (ms: user + system of every thread, garbage collection included; unlike the wall
 * clock it does not grow when other processes take the cores), the heap after a full collection (MB).
 */
export interface SoakSample {
  readonly steps: number;
  readonly medianMs: number;
  readonly cpuMs: number;
  readonly heapMB: number;
}

/**
 * The soak test (`--soak`): steps our world of `scene` for `steps` steps and reports, every `every`
 * steps, the median step time of the block, the CPU time a step over the block and the V8 heap after
 * a full garbage collection, so a slow leak (heap growth) or a slowdown over a long run shows. Goal:
 * the heap flat (growth under 1 MB) and the step time flat (on a shared machine, read the CPU column).
 * @returns the samples, the first taken after the first block.
 */
export function runSoak(options: SoakOptions): SoakSample[] {
  const resolved = resolveScene(options.scene);
  if (!resolved) throw new RangeError(`soak: unknown scene ${JSON.stringify(options.scene)}`);
  const { definition, bench } = resolved;
  const sceneOptions = {
    ...(bench.sceneOptions?.({ scene: options.scene, count: options.count, seed: options.seed }) ?? {}),
    count: options.count,
    seed: options.seed,
  };
  const world = createPhysicsWorld({ ...definition.worldOptions(sceneOptions), seed: options.seed });
  definition.build(world, sceneOptions);
  const times = new Float64Array(options.every);
  const samples: SoakSample[] = [];
  options.print(`soak: ${options.scene}, ${options.count} bodies, ${options.steps} steps, a report every ${options.every}`);
  options.print('steps      median ms  cpu ms/step  heap MB (after GC)');
  for (let done = 0; done < options.steps; ) {
    const n = Math.min(options.every, options.steps - done);
    const cpu0 = process.cpuUsage();
    for (let i = 0; i < n; i++) {
      const t = performance.now();
      step(world);
      times[i] = performance.now() - t;
    }
    const cpu = process.cpuUsage(cpu0);
    done += n;
    collectGarbage();
    const sample = {
      steps: done,
      medianMs: median(times.subarray(0, n)),
      cpuMs: (cpu.user + cpu.system) / 1000 / n,
      heapMB: sampleMemory().heapUsed,
    };
    samples.push(sample);
    options.print(
      `${String(done).padEnd(10)} ${sample.medianMs.toFixed(3).padStart(9)}  ${sample.cpuMs.toFixed(3).padStart(11)}  ${sample.heapMB.toFixed(2).padStart(8)}`,
    );
  }
  if (samples.length > 1) {
    const first = samples[0]!,
      last = samples[samples.length - 1]!;
    options.print(
      `heap growth from the first report to the last: ${(last.heapMB - first.heapMB).toFixed(2)} MB (goal < 1 MB); ` +
        `median step ${first.medianMs.toFixed(3)} -> ${last.medianMs.toFixed(3)} ms, CPU a step ${first.cpuMs.toFixed(3)} -> ${last.cpuMs.toFixed(3)} ms`,
    );
  }
  return samples;
}
