import { round } from './format.js';
import type { BenchScene, ExtraValue } from './types.js';

/**
 * Bench side of `cloth` (ours only): `--count` is the cloth's side; the probe records the largest link
 * strain (length / rest - 1) over the timed steps, the number of links, and the process's CPU time a
 * step with the involuntary context switches, which tell a slow step of the code from a step that
 * waited for a core another process held; and, after each step (outside its timing), the CPU time of a
 * fixed reference loop that shares no code or data with the solver, whose median over its fastest
 * tells how much slower the core itself ran during the run (on a shared virtual machine it can run at
 * times about 1.7 times slower: the cloth's step then grows with it).
 */
export const clothBench: BenchScene = {
  name: 'cloth',
  maxCount: 512,
  defaults: { steps: 300, warmup: 30 },
  probe(world) {
    let worst = 0;
    let cpu = new Float64Array(0),
      ref = new Float64Array(0),
      k = 0,
      last = 0,
      switches0 = 0,
      switches = 0;
    const cpuNow = (): number => {
      const u = process.cpuUsage();
      return (u.user + u.system) / 1000;
    };
    const work = new Float64Array(4096);
    let sink = 0;
    /** The reference: 16 passes of a multiply-add over 4,096 doubles (32 kB), about 0.1 ms of CPU. */
    const reference = (): void => {
      for (let pass = 0; pass < 16; pass++)
        for (let i = 0; i < work.length; i++) {
          work[i] = work[i]! * 0.5 + i;
          sink += work[i]!;
        }
    };
    return {
      beginTiming(steps: number): void {
        worst = 0;
        cpu = new Float64Array(steps);
        ref = new Float64Array(steps);
        k = 0;
        switches0 = process.resourceUsage().involuntaryContextSwitches;
        last = cpuNow();
      },
      afterStep(): void {
        const t = cpuNow();
        reference();
        const t1 = cpuNow();
        if (k < cpu.length) {
          cpu[k] = t - last;
          ref[k++] = t1 - t;
        }
        last = cpuNow();
        if (world.cloth.maxStretch > worst) worst = world.cloth.maxStretch;
      },
      endTiming(): void {
        switches = process.resourceUsage().involuntaryContextSwitches - switches0;
      },
      extras(): Record<string, ExtraValue> {
        const sorted = cpu.slice(0, k).sort(),
          refs = ref.slice(0, k).sort();
        // The reference's median over the mean of its fastest tenth (a single fastest reading is too coarse).
        let fast = 0;
        const tenth = Math.max(1, Math.floor(k / 10));
        for (let i = 0; i < tenth; i++) fast += refs[i]!;
        return {
          maxStretch: round(worst, 6),
          links: world.cloth.count,
          substeps: world.cloth.substeps,
          cpuMsPerStep: k > 0 ? round(sorted[k >> 1]!, 4) : null,
          preemptions: switches,
          coreSlowdown: k > 0 && fast > 0 && sink !== -1 ? round(refs[k >> 1]! / (fast / tenth), 3) : null,
        };
      },
    };
  },
  columns: [
    { key: 'maxStretch', label: 'max stretch', format: (v) => (typeof v === 'number' ? `${(100 * v).toFixed(2)}%` : String(v)) },
    { key: 'links', label: 'links', format: (v) => String(v) },
    { key: 'cpuMsPerStep', label: 'cpu ms/step', format: (v) => (typeof v === 'number' ? v.toFixed(3) : String(v)) },
  ],
  notes: [
    'cloth: --count is the side (64: 4,096 points, 23,938 links: structural, shear, bending), pinned along the top edge, 4 m/s wind with 1 m/s turbulence.',
    'max stretch: largest link strain (length / rest - 1) after any timed step; 11 XPBD substeps a step (the default).',
    'cpu ms/step: median CPU time of the process a timed step (process.cpuUsage between steps: every thread, the step and the probe); ' +
      'unlike the wall-clock ms it does not grow while another process holds the core. preemptions (JSON): involuntary context switches over the timed steps.',
    'coreSlowdown (JSON): median CPU time of a fixed reference loop run after each step, over the mean of its fastest tenth: 1 when the core ran at one speed throughout; ' +
      "about 1.7 when (on a shared virtual machine) it ran slower for most of the run, and the cloth's ms grow by the same factor.",
  ],
};
