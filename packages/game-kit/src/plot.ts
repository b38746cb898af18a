// The locale guard must run before uPlot's module reads navigator.language (see ./locale-guard).
import './locale-guard.js';
import uPlot from 'uplot';
import uplotCss from 'uplot/dist/uPlot.min.css' with { type: 'text' };

/**
 * Live time-series plots for the labs, on uPlot: a measured quantity next to its exact curve where
 * one exists. Samples go into fixed-size ring buffers (no growth, no allocation per sample); the chart
 * redraws at most every `redrawEvery` pushes so a 60 fps page spends little time plotting.
 */

let cssInjected = false;
function injectCss(): void {
  if (cssInjected || typeof document === 'undefined') return;
  const style = document.createElement('style');
  style.textContent = `${uplotCss}
.bp-plot { background: rgba(14, 17, 22, 0.85); border-radius: 8px; padding: 6px 8px; color: #e6e9ef; font: 12px system-ui, sans-serif; }
.bp-plot .u-legend { color: #e6e9ef; }
.bp-plot .u-title { font-size: 13px; font-weight: 600; white-space: normal; height: auto; line-height: 1.3; padding: 2px 4px; }
.bp-plot .u-title .bp-plot-unit { display: block; font-weight: 400; color: #98a2b3; font-size: 12px; }
.bp-plot .u-legend { white-space: normal; }`;
  document.head.append(style);
  cssInjected = true;
}

/** One line of a plot. */
export interface PlotSeries {
  /** Legend label, with unit, e.g. 'height (m)'. */
  label: string;
  /** CSS colour. */
  color: string;
  /** Dashed line (use it for exact / analytic curves). */
  dashed?: boolean;
}

/** Options of `createPlot`. */
export interface PlotOptions {
  /** Element the chart goes into. */
  parent: HTMLElement;
  /** Title over the chart. */
  title: string;
  /** Label of the x axis, e.g. 'time (s)'. */
  xLabel?: string;
  /** Label of the y axis. */
  yLabel?: string;
  /** The lines, in the order their values are pushed. */
  series: PlotSeries[];
  /** Chart size in CSS pixels. Defaults 420 x 220. */
  width?: number;
  height?: number;
  /** Samples kept (older ones scroll out). Default 1200. */
  capacity?: number;
  /** Redraw after this many pushes. Default 6. */
  redrawEvery?: number;
  /** Logarithmic y axis (for errors). Default false. */
  logY?: boolean;
}

/** A live plot. */
export interface Plot {
  /** Adds one sample: x (usually time, s) and one value per series (NaN leaves a gap). */
  push(x: number, ...values: number[]): void;
  /** Forgets every sample. */
  clear(): void;
  /** Redraws now. */
  redraw(): void;
  /** Number of samples held. */
  readonly length: number;
  /** The newest value of series i (NaN if empty). */
  last(i: number): number;
  /** Removes the chart. */
  destroy(): void;
}

/**
 * Creates a live plot.
 * @throws TypeError if `parent` is not an element or `series` is empty; RangeError on non-positive sizes.
 */
export function createPlot(options: PlotOptions): Plot {
  if (!(options.parent instanceof HTMLElement)) throw new TypeError('createPlot: parent must be an HTMLElement');
  if (!Array.isArray(options.series) || options.series.length === 0) throw new TypeError('createPlot: series must list at least one line');
  const capacity = options.capacity ?? 1200;
  const redrawEvery = options.redrawEvery ?? 6;
  for (const [name, v] of [
    ['capacity', capacity],
    ['redrawEvery', redrawEvery],
    ['width', options.width ?? 1],
    ['height', options.height ?? 1],
  ] as const) {
    if (!Number.isInteger(v) || v <= 0) throw new RangeError(`createPlot: ${name} must be a positive integer, got ${v}`);
  }
  injectCss();
  const wrap = document.createElement('div');
  wrap.className = 'bp-plot';
  options.parent.append(wrap);
  const n = options.series.length;
  // Ring buffers, and ordered views handed to uPlot on redraw.
  const ring = Array.from({ length: n + 1 }, () => new Float64Array(capacity));
  const view = Array.from({ length: n + 1 }, () => new Array<number | null>(0));
  let head = 0,
    count = 0,
    pending = 0;
  // A y label longer than the axis (uPlot draws it rotated along the plot's height) would be cut
  // off: it goes under the title instead.
  const height = options.height ?? 220;
  const yLabel = options.yLabel ?? '';
  const yLabelFits = yLabel.length * 7.5 <= height - 70;
  const chart = new uPlot(
    {
      title: options.title,
      width: options.width ?? 420,
      height: options.height ?? 220,
      scales: { x: { time: false }, y: options.logY ? { distr: 3 } : {} },
      axes: [
        { label: options.xLabel ?? 'time (s)', stroke: '#98a2b3', grid: { stroke: '#252b36' } },
        { label: yLabelFits ? yLabel : '', stroke: '#98a2b3', grid: { stroke: '#252b36' } },
      ],
      series: [
        {},
        ...options.series.map((s) => ({
          label: s.label,
          stroke: s.color,
          width: 1.5,
          dash: s.dashed ? [6, 4] : undefined,
          spanGaps: false,
        })),
      ],
      legend: { live: false },
      cursor: { show: false },
    },
    [[], ...options.series.map(() => [])] as unknown as uPlot.AlignedData,
    wrap,
  );
  if (!yLabelFits) {
    const unit = document.createElement('span');
    unit.className = 'bp-plot-unit';
    unit.textContent = `y: ${yLabel}`;
    wrap.querySelector('.u-title')?.append(unit);
  }
  const redraw = (): void => {
    const start = (head - count + capacity) % capacity;
    for (let k = 0; k <= n; k++) {
      const v = view[k]!,
        r = ring[k]!;
      v.length = count;
      for (let i = 0; i < count; i++) {
        const x = r[(start + i) % capacity]!;
        v[i] = Number.isNaN(x) || (options.logY && k > 0 && !(x > 0)) ? null : x;
      }
    }
    chart.setData(view as unknown as uPlot.AlignedData);
    pending = 0;
  };
  return {
    push(x: number, ...values: number[]) {
      ring[0]![head] = x;
      for (let k = 0; k < n; k++) ring[k + 1]![head] = values[k] ?? Number.NaN;
      head = (head + 1) % capacity;
      if (count < capacity) count++;
      if (++pending >= redrawEvery) redraw();
    },
    clear() {
      head = 0;
      count = 0;
      redraw();
    },
    redraw,
    get length() {
      return count;
    },
    last(i: number) {
      return count === 0 ? Number.NaN : ring[i + 1]![(head - 1 + capacity) % capacity]!;
    },
    destroy() {
      chart.destroy();
      wrap.remove();
    },
  };
}
