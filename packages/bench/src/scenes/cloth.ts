import type { BenchScene, ExtraValue } from './types.js';
import { round } from './format.js';

/**
 * Bench side of `cloth` (ours only): `--count` is the cloth's side; the probe records the largest link
 * strain (length / rest - 1) over the timed steps, the number of links, and the process's CPU time a
 * step with the involuntary context switches, which tell a slow step of the code from a step that
 * waited for a core another process held.
 */
export const clothBench: BenchScene = {
  name: 'cloth',
  maxCount: 512,
  defaults: { steps: 300, warmup: 30 },
  probe(world) {
    let worst = 0;
    let cpu = new Float64Array(0), k = 0, last = 0, switches0 = 0, switches = 0;
    const cpuNow = (): number => { const u = process.cpuUsage(); return (u.user + u.system) / 1000; };
    return {
      beginTiming(steps: number): void {
        worst = 0; cpu = new Float64Array(steps); k = 0;
        switches0 = process.resourceUsage().involuntaryContextSwitches;
        last = cpuNow();
      },
      afterStep(): void {
        const t = cpuNow();
        if (k < cpu.length) cpu[k++] = t - last;
        last = t;
        if (world.cloth.maxStretch > worst) worst = world.cloth.maxStretch;
      },
      endTiming(): void { switches = process.resourceUsage().involuntaryContextSwitches - switches0; },
      extras(): Record<string, ExtraValue> {
        const sorted = cpu.slice(0, k).sort();
        return {
          maxStretch: round(worst, 6), links: world.cloth.count, substeps: world.cloth.substeps,
          cpuMsPerStep: k > 0 ? round(sorted[k >> 1]!, 4) : null, preemptions: switches,
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
    'cpu ms/step: median CPU time of the process a timed step (process.cpuUsage between steps: every thread, the step and the probe); '
      + 'unlike the wall-clock ms it does not grow while another process holds the core. preemptions (JSON): involuntary context switches over the timed steps.',
  ],
};
