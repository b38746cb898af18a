import { amdahlSpeedup, PROJECTED_CORES, serialFraction } from './amdahl.js';
import { THREADED } from './engines/bitphysics.js';
import { OURS } from './engines/index.js';
import type { BenchResult, EngineResult } from './runner.js';
import type { BenchScene, ExtraValue } from './scenes/types.js';
import type { StudyResult } from './studies/types.js';

/** A peer's time ratio against our engine. */
export interface Ratio {
  /** The peer engine. */
  readonly peer: string;
  /** Our median step time divided by the peer's: < 1 means bitphysics is faster. */
  readonly ratio: number;
  /**
   * Our mean step time divided by the peer's over the same timed steps, i.e. our total time of the
   * timed window over the peer's: < 1 means bitphysics is faster over the whole run. Unlike the
   * median it counts the few expensive steps (landing, settling) in scenes that end asleep.
   */
  readonly meanRatio: number;
  /** Our process CPU time a step over the peer's (`EngineResult.cpuMsPerStep`): the whole-run ratio with less of the machine's load in it. */
  readonly cpuRatio: number;
}

/**
 * `threads` on our lines (1 for `bitphysics`, n for `bitphysics-threads`) and, on the threaded line,
 * `speedup`: the single-threaded median step time over the threaded one (> 1: the threads help),
 * `serialFraction`: the Karp-Flatt serial fraction of that speedup, and `amdahl8`, `amdahl16`: the
 * speedups Amdahl's law projects from it to 8 and 16 cores (amdahl.ts).
 */
function threadFields(result: BenchResult, e: EngineResult): Record<string, number> {
  const threads = result.scene.threads ?? 1;
  if (e.engine === OURS) return threads > 1 ? { threads: 1 } : {};
  if (e.engine !== THREADED) return {};
  const ours = result.engines.find((x) => x.engine === OURS);
  if (!ours) return { threads };
  const speedup = ours.msPerStep.median / e.msPerStep.median;
  const f = serialFraction(speedup, threads);
  const fields: Record<string, number> = { threads, speedup: sig(speedup, 4) };
  if (Number.isFinite(f)) {
    fields.serialFraction = sig(f, 3);
    for (const cores of PROJECTED_CORES) fields[`amdahl${cores}`] = sig(amdahlSpeedup(f, cores), 3);
  }
  return fields;
}

/** Ours/peer ratios of median and of mean step times, one per peer, in run order. Empty without ours or peers. */
export function ratios(result: BenchResult): Ratio[] {
  const ours = result.engines.find((e) => e.engine === OURS);
  if (!ours) return [];
  return result.engines
    .filter((e) => e.engine !== OURS)
    .map((e) => ({
      peer: e.engine,
      ratio: ours.msPerStep.median / e.msPerStep.median,
      meanRatio: ours.msPerStep.mean / e.msPerStep.mean,
      cpuRatio: ours.cpuMsPerStep / e.cpuMsPerStep,
    }));
}

/** Rounds to `digits` significant digits (keeps JSON lines short without losing what matters). */
function sig(value: number, digits = 6): number {
  return Number.isFinite(value) && value !== 0 ? Number(value.toPrecision(digits)) : value;
}

/**
 * The JSON objects of a run, one per engine: `scene, engine, count, steps, msPerStep {median, min,
 * max, mean, p90}, contacts`, then `warmup, seed, bodyStepsPerSecond, heapUsedMB, engineMemoryMB,
 * setupMs`, `params` (the scene parameters, e.g. `{ "theta": 0.5 }`, only for scenes that declare
 * any), the engine's and scene's extra fields (e.g. `maxOverlapPercent`), and on each peer's
 * line `ratio` (our median / its median), `ratioMean` (our mean / its mean over the same timed
 * steps: the whole-run time ratio), `ratioCpu` (the same in process CPU time, `cpuMsPerStep` on
 * every line) with `ratioOf` ("bitphysics/<peer>"); with `--threads n`,
 * `threads` on our lines and `speedup` (single-threaded median / threaded median), `serialFraction`
 * (Karp-Flatt) and `amdahl8`, `amdahl16` (projected speedups, amdahl.ts) on the
 * `bitphysics-threads` line; with `times`, every
 * step's milliseconds as `timesMs`.
 */
export function jsonRecords(result: BenchResult, options: { times?: boolean } = {}): Array<Record<string, unknown>> {
  const r = new Map(ratios(result).map((x) => [x.peer, x]));
  return result.engines.map((e) => {
    const record: Record<string, unknown> = {
      scene: result.scene.scene,
      engine: e.engine,
      count: result.scene.count,
      steps: result.steps,
      msPerStep: {
        median: sig(e.msPerStep.median),
        min: sig(e.msPerStep.min),
        max: sig(e.msPerStep.max),
        mean: sig(e.msPerStep.mean),
        p90: sig(e.msPerStep.p90),
      },
      cpuMsPerStep: sig(e.cpuMsPerStep),
      contacts: e.contacts,
      warmup: result.warmup,
      seed: result.scene.seed,
      bodyStepsPerSecond: sig(e.bodyStepsPerSecond, 4),
      heapUsedMB: sig(result.heapUsedMB, 4),
      engineMemoryMB: sig(e.engineMemoryMB, 4),
      setupMs: sig(e.setupMs, 4),
      ...threadFields(result, e),
    };
    const params = result.scene.params;
    if (params && Object.keys(params).length > 0) record.params = { ...params };
    for (const [k, v] of Object.entries(e.extra)) if (!(k in record)) record[k] = v;
    const ratio = r.get(e.engine);
    if (ratio !== undefined && e.engine !== THREADED) {
      record.ratio = sig(ratio.ratio, 4);
      record.ratioMean = sig(ratio.meanRatio, 4);
      record.ratioCpu = sig(ratio.cpuRatio, 4);
      record.ratioOf = `${OURS}/${e.engine}`;
    }
    if (options.times) record.timesMs = Array.from(e.times, (t) => sig(t, 4));
    return record;
  });
}

/** Formats a rate with an SI prefix: 1.75e6 -> "1.75 M". */
export function formatRate(value: number): string {
  if (!Number.isFinite(value)) return String(value);
  const units: Array<[number, string]> = [
    [1e9, 'G'],
    [1e6, 'M'],
    [1e3, 'k'],
  ];
  for (const [f, u] of units) if (Math.abs(value) >= f) return `${(value / f).toPrecision(3)} ${u}`;
  return value.toPrecision(3);
}

/** Formats milliseconds with 3 significant digits but at least 3 decimals below 1 ms. */
export function formatMs(ms: number): string {
  return ms >= 100 ? ms.toFixed(1) : ms >= 10 ? ms.toFixed(2) : ms.toFixed(3);
}

/**
 * Lays out rows of cells as a table, columns two spaces apart. `align` gives each column's
 * alignment ('l' left, 'r' right); by default the first column is left-aligned, the rest right.
 */
export function table(rows: readonly (readonly string[])[], align?: readonly ('l' | 'r')[]): string {
  const widths: number[] = [];
  for (const row of rows)
    row.forEach((cell, i) => {
      widths[i] = Math.max(widths[i] ?? 0, cell.length);
    });
  const left = (i: number): boolean => (align ? align[i] === 'l' : i === 0);
  return rows
    .map((row) =>
      row
        .map((cell, i) => (left(i) ? cell.padEnd(widths[i]!) : cell.padStart(widths[i]!)))
        .join('  ')
        .trimEnd(),
    )
    .join('\n');
}

/**
 * The human-readable report of a run: a header, one table row per engine (standard columns, the
 * mean step time beside the median, then the scene's extra columns), the ours/peer ratios of the
 * median and of the mean step (with the load average), the process heap, and notes about each engine's
 * configuration and the scene.
 */
export function humanReport(result: BenchResult, scene: BenchScene): string {
  const { scene: s } = result;
  const lines: string[] = [];
  // --count is not always the number of bodies (pyramid's is its base): the header says both then.
  const bodies = result.engines[0]?.bodies;
  const size = bodies === undefined || bodies === s.count ? `${s.count} bodies` : `count ${s.count} (${bodies} bodies)`;
  lines.push(
    `${s.scene}: ${size}, ${result.steps} timed steps after ${result.warmup} warm-up, seed ${s.seed}` +
      formatParams(s.params) +
      (result.engines.length > 1 ? `, engines alternating every ${result.block} steps` : ''),
    '',
  );
  const columns = scene.columns ?? [];
  const header = [
    'engine',
    'median ms',
    'mean ms',
    'cpu ms',
    'min ms',
    'max ms',
    'body-steps/s',
    'contacts',
    'setup ms',
    'mem MB',
    ...columns.map((c) => c.label),
  ];
  const rows: string[][] = [header];
  for (const e of result.engines) {
    rows.push([
      e.engine,
      formatMs(e.msPerStep.median),
      formatMs(e.msPerStep.mean),
      formatMs(e.cpuMsPerStep),
      formatMs(e.msPerStep.min),
      formatMs(e.msPerStep.max),
      formatRate(e.bodyStepsPerSecond),
      e.contacts === null ? '-' : String(e.contacts),
      e.setupMs.toFixed(0),
      e.engineMemoryMB.toFixed(1),
      ...columns.map((c) => (c.key in e.extra ? c.format(e.extra[c.key] as ExtraValue) : '-')),
    ]);
  }
  lines.push(table(rows));
  const threaded = result.engines.find((e) => e.engine === THREADED);
  const single = result.engines.find((e) => e.engine === OURS);
  const r = ratios(result).filter((x) => x.peer !== THREADED);
  if (r.length > 0) {
    lines.push(
      '',
      `time ratio ours/peer (< 1: bitphysics is faster; median step, mean step = whole timed run of ${result.steps} steps, ` +
        `and process CPU time of that run; load average ${result.load.start.toFixed(2)} at start, ${result.load.end.toFixed(2)} at end, ${result.load.cpus} cpus):`,
    );
    lines.push(
      table([
        ['', 'median', 'mean', 'cpu'],
        ...r.map((x) => [`  ${OURS}/${x.peer}`, x.ratio.toFixed(3), x.meanRatio.toFixed(3), x.cpuRatio.toFixed(3)]),
      ]),
    );
  }
  if (threaded && single) {
    const threads = result.scene.threads ?? 1;
    const speedup = single.msPerStep.median / threaded.msPerStep.median;
    lines.push(
      '',
      `speedup with threads: ${threads}: ${speedup.toFixed(3)} ` +
        `(single-threaded median / threaded median; load average ${result.load.start.toFixed(2)} at start, ${result.load.end.toFixed(2)} at end, ${result.load.cpus} cpus)`,
    );
    const f = serialFraction(speedup, threads);
    if (Number.isFinite(f)) {
      lines.push(
        `serial fraction ${f.toFixed(3)} (Karp-Flatt: (1/speedup - 1/${threads}) / (1 - 1/${threads}), overheads included); ` +
          `Amdahl projection 1 / (f + (1 - f) / N): ${PROJECTED_CORES.map((n) => `${amdahlSpeedup(f, n).toFixed(2)}x on ${n} cores`).join(', ')}`,
      );
    }
  }
  lines.push('', `heap used: ${result.heapUsedMB.toFixed(1)} MB (V8 heap of the whole process after timing)`);
  const extras = otherExtras(result.engines, new Set(columns.map((c) => c.key)));
  if (extras.length > 0) lines.push(...extras);
  const notes = [...result.engines.flatMap((e) => e.notes), ...(scene.notes ?? [])];
  if (result.engines.some((e) => e.engine === 'matter')) {
    notes.push(
      'matter-js is not SI (pixels, milliseconds): it ran at 100 px/m with its gravity scaled to 10 m/s^2; its results are converted back to metres.',
    );
  }
  if (notes.length > 0) lines.push('', 'notes:', ...notes.map((n) => `  ${n}`));
  return lines.join('\n');
}

/** Lines for extra fields that have no column, one per engine that has any. */
function otherExtras(engines: readonly EngineResult[], shown: ReadonlySet<string>): string[] {
  const out: string[] = [];
  for (const e of engines) {
    const fields = Object.entries(e.extra).filter(([k]) => !shown.has(k));
    if (fields.length > 0) out.push(`${e.engine}: ${fields.map(([k, v]) => `${k} ${typeof v === 'number' ? sig(v, 6) : v}`).join(', ')}`);
  }
  return out;
}

/** ", theta 0.5, orbits 100" for the header line; "" without parameters. */
function formatParams(params: Readonly<Record<string, number>> | undefined): string {
  if (!params) return '';
  return Object.entries(params)
    .map(([k, v]) => `, ${k} ${v}`)
    .join('');
}

/**
 * The human-readable report of a study (`integrators`, `forces`): a header with what ran, the
 * study's table (first column left-aligned, numbers right-aligned, a last text column left-aligned
 * when it has one) and its notes.
 */
export function studyReport(
  scene: string,
  result: StudyResult,
  run: { count: number; steps: number; warmup: number; seed: number; params: Readonly<Record<string, number>> },
): string {
  const width = result.header.length;
  const align = result.header.map((h, i): 'l' | 'r' => (i === 0 || (i === width - 1 && /^(world|description)$/.test(h)) ? 'l' : 'r'));
  return [
    `${scene}: ${run.count} bodies in the timed worlds, ${run.steps} timed steps after ${run.warmup} warm-up, seed ${run.seed}${formatParams(run.params)}`,
    '',
    table([result.header, ...result.rows], align),
    '',
    'notes:',
    ...result.notes.map((n) => `  ${n}`),
  ].join('\n');
}
