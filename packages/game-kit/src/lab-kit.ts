/**
 * Lab kit: the page furniture every lab shares, on top of the shell (./shell, ./pixi) and the plots
 * (./plot). Layout, input and drawing only, no physics:
 *
 * - a dock on the right holding the lil-gui panel, a readout box and the uPlot charts
 *   (`createLabDock`), or a column of plots at the bottom right (`createPlotDock`) with a one-line
 *   status at the top (`createStatusLine`);
 * - fitting the camera so a world rectangle lands beside the dock (`fitViewBeside`, `followView`,
 *   `plotReserve`);
 * - URL parameters read behind a clear on-page error (`readUrlParams`, `showPageError`);
 * - readout lines (`createReadout`), number formatting (`fmt`), held keys (`trackHeldKeys`);
 * - interpolated positions, and pixi drawing helpers (springs, dashed lines, polylines from ring
 *   buffers) for what the WorldRenderer does not draw;
 * - plot-axis helpers (`scaleFloor`, `scaleSeries`).
 *
 * The particle labs add ./particle-kit on top of it.
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import type { Camera, Point2, WorldRect } from '@bitphysics/render-pixi';
import type { Application, Graphics } from 'pixi.js';
import { pageLayout } from './layout.js';
import { createPlot, type Plot, type PlotOptions } from './plot.js';

const STYLE_ID = 'bp-lab-style';
const CSS = `
.bp-lab-dock { box-sizing: border-box; display: flex; flex-direction: column; gap: 6px; }
.bp-lab-dock > * { flex-shrink: 0; }
.bp-lab-dock .lil-gui.lil-root { --width: auto; width: auto; }
.bp-lab-info { margin-top: 6px; padding-top: 6px; border-top: 1px solid rgba(255, 255, 255, 0.15); overflow-wrap: anywhere; }
.bp-lab-info > div { margin-bottom: 2px; }
.bp-lab-info .bp-lab-key { color: #98a2b3; }
.bp-lab-info .bp-lab-swatch { display: inline-block; width: 10px; height: 10px; border-radius: 2px; margin-right: 6px; vertical-align: -1px; }
.bp-lab-error { position: fixed; top: 40%; left: 50%; transform: translate(-50%, -50%); z-index: 30; max-width: 80vw;
  background: rgba(160, 20, 40, 0.95); color: #fff; border-radius: 8px; padding: 12px 16px; font: 14px/1.5 system-ui, sans-serif; white-space: pre-wrap; }
`;

function injectStyle(): void {
  if (document.getElementById(STYLE_ID)) return;
  const style = document.createElement('style');
  style.id = STYLE_ID;
  style.textContent = CSS;
  document.head.append(style);
}

/** The right-hand column of a lab page (in the page layout's side column, ./layout). */
export interface LabDock {
  /** The dock element (in the layout's side column). */
  readonly root: HTMLElement;
  /** Where the lil-gui panel goes (`createPanel(..., { container: dock.panelSlot })`). */
  readonly panelSlot: HTMLElement;
  /** Where the charts go (`createPlot({ parent: dock.charts })`). */
  readonly charts: HTMLElement;
  /** Width of the dock, CSS px (the preferred width, capped by the layout, `PageLayout.sideWidth`). */
  readonly width: number;
  /** Width of a chart that fills the dock, CSS px. */
  readonly chartWidth: number;
  /** CSS px of the canvas the scene must leave free on the right: 0, as the dock sits beside the canvas, never over it. */
  reserved(): number;
  /** Removes the dock. */
  destroy(): void;
}

/**
 * Creates the dock: panel slot and chart area, in the page layout's side column (beside the scene
 * on wide windows, a drawer on small ones).
 * @param preferred CSS px, integer in [240, 800]. Default 360. The dock takes this or less (`PageLayout.sideWidth`).
 * @throws RangeError on a width out of range.
 */
export function createLabDock(preferred = 360): LabDock {
  if (!Number.isInteger(preferred) || preferred < 240 || preferred > 800)
    throw new RangeError(`createLabDock: width must be an integer in [240, 800] px, got ${preferred}`);
  injectStyle();
  const layout = pageLayout();
  const width = layout.sideWidth(preferred);
  const root = document.createElement('div');
  root.className = 'bp-lab-dock';
  root.style.width = `${width}px`;
  const panelSlot = document.createElement('div');
  const charts = document.createElement('div');
  charts.style.display = 'flex';
  charts.style.flexDirection = 'column';
  charts.style.gap = '6px';
  root.append(panelSlot, charts);
  layout.side.append(root);
  return {
    root,
    panelSlot,
    charts,
    width,
    chartWidth: width - 16,
    reserved: () => 0,
    destroy: () => root.remove(),
  };
}

/**
 * Fits world rectangle `rect` (m) into the part of the screen left of the dock (the whole screen
 * when the dock floats over it), centred, aspect kept, `padding` px free around it. The camera ends
 * up fitted to a larger rectangle with the screen's aspect, so later resizes keep the scale until
 * this is called again (`followView` does that).
 * @param reservedPx CSS px kept free on the right (the dock, `LabDock.reserved()`), >= 0; ignored
 *   when less than 80 px plus padding would be left for the scene.
 * @param padding CSS px kept free around `rect`, >= 0 (shrunk on tiny screens). Default 24.
 * @throws RangeError (from the camera) on a bad rectangle.
 */
export function fitViewBeside(camera: Camera, rect: WorldRect, reservedPx: number, padding = 24): void {
  const W = camera.width,
    H = camera.height;
  let free = W - reservedPx;
  if (free - 2 * padding < 80) free = W;
  const w = rect.maxX - rect.minX,
    h = rect.maxY - rect.minY;
  const pad = Math.min(padding, free / 4, H / 4);
  const ppm = Math.min((free - 2 * pad) / w, (H - 2 * pad) / h);
  const cx = (rect.minX + rect.maxX) / 2,
    cy = (rect.minY + rect.maxY) / 2;
  const minX = cx - free / 2 / ppm,
    minY = cy - H / 2 / ppm;
  camera.fit({ minX, minY, maxX: minX + W / ppm, maxY: minY + H / ppm }, 0);
}

/**
 * Keeps `view()` (m) fitted beside the dock: now and after every resize of the app's renderer.
 * Call the returned function to refit (after the view changed).
 * @param padding CSS px kept free around the view (fitViewBeside's `padding`), >= 0, read at each
 *   refit. Default 24.
 */
export function followView(
  app: Application,
  camera: Camera,
  dock: LabDock,
  view: () => WorldRect,
  padding: () => number = () => 24,
): () => void {
  const refit = (): void => fitViewBeside(camera, view(), dock.reserved(), padding());
  app.renderer.on('resize', refit);
  refit();
  return refit;
}

/**
 * Shows `message` in a red box in the middle of the page (bad URL parameters and other errors that
 * stop a lab before it starts). The box has `role="alert"` and `data-lab="error"`.
 */
export function showPageError(message: string): void {
  injectStyle();
  const box = document.createElement('div');
  box.className = 'bp-lab-error lab-param-error';
  box.setAttribute('role', 'alert');
  box.dataset.lab = 'error';
  box.textContent = message;
  document.body.append(box);
}

/**
 * Runs `read` (which reads URL parameters with numberParam / choiceParam / flagParam) and returns its
 * value. If it throws, 'Bad URL parameter: <message>' is shown on the page (`showPageError`),
 * followed by `usage` (the accepted values) when given, and the error is rethrown so the page stops
 * (and tests see it).
 * @throws whatever `read` throws (RangeError naming the parameter for the shared param readers).
 */
export function readUrlParams<T>(read: () => T, usage?: string): T {
  try {
    return read();
  } catch (error) {
    const message = error instanceof Error ? error.message : String(error);
    showPageError(`Bad URL parameter: ${message}${usage ? `\n\n${usage}` : ''}`);
    throw error;
  }
}

/** A box of labelled readout lines that rewrites only the lines whose text changed. */
export interface Readout {
  /** Sets line `i`'s value text. @throws RangeError if i is not a line index. */
  set(i: number, text: string): void;
  /** Current value text of line `i`. */
  get(i: number): string;
}

/**
 * Appends a block of lines ('label value') to `parent`, usually the HUD's readout
 * (`shell.hud.readout`), under its fps line and its physics fold, or that fold (`shell.hud.details`,
 * closed at start) for numbers only someone looking into the engine reads. `swatches` optionally
 * gives a CSS colour per line (a coloured square before the label, for legends). The block has
 * `data-lab="info"`.
 * @throws TypeError if labels is empty.
 */
export function createReadout(parent: HTMLElement, labels: readonly string[], swatches?: readonly string[]): Readout {
  if (labels.length === 0) throw new TypeError('createReadout: labels must not be empty');
  injectStyle();
  const values: HTMLElement[] = [];
  const texts: string[] = [];
  const block = document.createElement('div');
  block.className = 'bp-lab-info';
  block.dataset.lab = 'info';
  parent.append(block);
  labels.forEach((label, i) => {
    const line = document.createElement('div');
    if (swatches?.[i]) {
      const sw = document.createElement('span');
      sw.className = 'bp-lab-swatch';
      sw.style.background = swatches[i]!;
      line.append(sw);
    }
    const key = document.createElement('span');
    key.className = 'bp-lab-key';
    key.textContent = `${label} `;
    const value = document.createElement('span');
    value.dataset.readout = String(i);
    line.append(key, value);
    block.append(line);
    values.push(value);
    texts.push('');
  });
  return {
    set(i, text) {
      const el = values[i];
      if (!el) throw new RangeError(`Readout.set: no line ${i} (there are ${values.length})`);
      if (texts[i] !== text) {
        texts[i] = text;
        el.textContent = text;
      }
    },
    get(i) {
      return texts[i] ?? '';
    },
  };
}

/** Formats a number with `digits` significant digits, or '–' when it is NaN. */
export function fmt(value: number, digits = 4): string {
  if (Number.isNaN(value)) return '–';
  if (!Number.isFinite(value)) return value > 0 ? '∞' : '-∞';
  return Number(value.toPrecision(digits)).toString();
}

/**
 * Where body `eid` is drawn at interpolation factor `alpha` in [0, 1], m, into `out`: the same
 * PreviousPosition -> Position blend the WorldRenderer uses, so overlays line up with the balls.
 */
export function drawnPosition(world: PhysicsWorld, eid: number, alpha: number, out: Point2): Point2 {
  const P = world.components.Position,
    O = world.components.PreviousPosition;
  out.x = O.x[eid]! + (P.x[eid]! - O.x[eid]!) * alpha;
  out.y = O.y[eid]! + (P.y[eid]! - O.y[eid]!) * alpha;
  return out;
}

/**
 * Draws a coil spring (zigzag) from screen point (x1, y1) to (x2, y2), px, with `coils` teeth (integer
 * >= 1) of half-width `amplitude` px, straight leads of `lead` px at both ends. Appends a path to `g`
 * and strokes it.
 */
export function drawSpring(
  g: Graphics,
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  coils: number,
  amplitude: number,
  width: number,
  color: number,
  alpha = 1,
): void {
  const dx = x2 - x1,
    dy = y2 - y1;
  const len = Math.sqrt(dx * dx + dy * dy);
  if (len < 1e-6) return;
  const ux = dx / len,
    uy = dy / len,
    nx = -uy,
    ny = ux;
  const lead = Math.min(6, len * 0.1);
  const body = len - 2 * lead;
  g.moveTo(x1, y1).lineTo(x1 + ux * lead, y1 + uy * lead);
  const n = coils * 2;
  for (let i = 0; i < n; i++) {
    const s = lead + ((i + 0.5) / n) * body;
    const side = i % 2 === 0 ? amplitude : -amplitude;
    g.lineTo(x1 + ux * s + nx * side, y1 + uy * s + ny * side);
  }
  g.lineTo(x2 - ux * lead, y2 - uy * lead)
    .lineTo(x2, y2)
    .stroke({ width, color, alpha });
}

/** Draws a dashed straight line from (x1, y1) to (x2, y2), px, and strokes it: dashes of `dash` px, gaps of `gap` px (`dashedLine`). */
export function drawDashedLine(
  g: Graphics,
  x1: number,
  y1: number,
  x2: number,
  y2: number,
  width: number,
  color: number,
  alpha = 1,
  dash = 8,
  gap = 6,
): void {
  if (x1 === x2 && y1 === y2) return;
  dashedLine(g, x1, y1, x2, y2, dash, gap).stroke({ width, color, alpha });
}

/**
 * A polyline of world points (m) kept in a fixed ring buffer: `push` costs nothing, `draw` strokes
 * the points oldest to newest through the camera. For paths, trajectories and exact curves.
 */
export class PathBuffer {
  /** Points held. */
  count = 0;
  private readonly xs: Float64Array;
  private readonly ys: Float64Array;
  private head = 0;

  /** @param capacity points kept, integer >= 2 (older ones are dropped). @throws RangeError otherwise. */
  constructor(readonly capacity: number) {
    if (!Number.isInteger(capacity) || capacity < 2) throw new RangeError(`PathBuffer: capacity must be an integer >= 2, got ${capacity}`);
    this.xs = new Float64Array(capacity);
    this.ys = new Float64Array(capacity);
  }

  /** Appends world point (x, y), m. */
  push(x: number, y: number): void {
    this.xs[this.head] = x;
    this.ys[this.head] = y;
    this.head = (this.head + 1) % this.capacity;
    if (this.count < this.capacity) this.count++;
  }

  /** Forgets every point. */
  clear(): void {
    this.count = 0;
    this.head = 0;
  }

  /** The newest point, m, into `out`; false if empty. */
  last(out: Point2): boolean {
    if (this.count === 0) return false;
    const i = (this.head - 1 + this.capacity) % this.capacity;
    out.x = this.xs[i]!;
    out.y = this.ys[i]!;
    return true;
  }

  /**
   * Strokes the points as one polyline, oldest to newest, through `camera`; with `dashed`, runs of
   * 4 segments alternate drawn and skipped. Ends at world point (endX, endY) when given (solid only).
   */
  draw(g: Graphics, camera: Camera, width: number, color: number, alpha = 1, dashed = false, endX = Number.NaN, endY = Number.NaN): void {
    if (this.count < 2 && Number.isNaN(endX)) return;
    const start = (this.head - this.count + this.capacity) % this.capacity;
    const cap = this.capacity;
    let px = 0,
      py = 0;
    for (let k = 0; k < this.count; k++) {
      const i = (start + k) % cap;
      const sx = camera.toScreenX(this.xs[i]!),
        sy = camera.toScreenY(this.ys[i]!);
      if (k === 0) g.moveTo(sx, sy);
      else if (!dashed) g.lineTo(sx, sy);
      else if (((k - 1) >> 2) % 2 === 0) g.moveTo(px, py).lineTo(sx, sy);
      px = sx;
      py = sy;
    }
    if (!dashed && !Number.isNaN(endX)) g.lineTo(camera.toScreenX(endX), camera.toScreenY(endY));
    g.stroke({ width, color, alpha });
  }
}

/** Converts 0xRRGGBB to a CSS colour string. */
export function cssColor(color: number): string {
  return `#${color.toString(16).padStart(6, '0')}`;
}

/** A column of plots in the page layout's side column (./layout). */
export interface PlotDock {
  /** The dock element. */
  readonly element: HTMLElement;
  /**
   * Adds a live plot (see plot.ts) sized to the side column: width up to 420 px
   * (`PageLayout.sideWidth`), height split between `rows` plots in about 70% of the window's height;
   * 600 samples kept, redrawn every 10 (long dashed polylines are costly to draw under software WebGL).
   * @throws whatever createPlot throws (empty series, bad sizes).
   */
  add(options: Omit<PlotOptions, 'parent'>): Plot;
}

/**
 * Creates the plot dock for `rows` (1 to 3) stacked plots.
 * @throws RangeError unless rows is 1, 2 or 3.
 */
export function createPlotDock(rows = 1): PlotDock {
  if (!(rows === 1 || rows === 2 || rows === 3)) throw new RangeError(`createPlotDock: rows must be 1, 2 or 3, got ${rows}`);
  const layout = pageLayout();
  const element = document.createElement('div');
  element.className = 'lab-plots';
  element.style.cssText = 'display:flex;flex-direction:column;gap:6px';
  layout.side.append(element);
  // The plot's box adds 16 px of padding to uPlot's width.
  const width = layout.sideWidth(420) - 16;
  // The plots take at most 70% of the window's height; each adds about 62 px of title and legend to
  // uPlot's height (which holds the drawing area and the axes).
  const height = Math.round(Math.max(110, Math.min(220, (window.innerHeight * 0.7) / rows - 62)));
  return {
    element,
    add(options) {
      return createPlot({ width, height, capacity: 600, redrawEvery: 10, ...options, parent: element });
    },
  };
}

/**
 * Tracks which of `keys` are held down (keydown / keyup on window, case-insensitive, ignored while
 * typing in a text field or with Ctrl, Meta or Alt). Released all at once when the window loses focus.
 * @returns `held(key)` and `dispose()`. @throws TypeError if `keys` is empty.
 */
export function trackHeldKeys(keys: readonly string[]): { held(key: string): boolean; dispose(): void } {
  if (!Array.isArray(keys) || keys.length === 0) throw new TypeError('trackHeldKeys: keys must be a non-empty array');
  const watched = new Set(keys.map((k) => k.toLowerCase()));
  const down = new Set<string>();
  const typing = (t: EventTarget | null): boolean => {
    const el = t as HTMLElement | null;
    return (
      !!el && (el.tagName === 'TEXTAREA' || el.tagName === 'SELECT' || (el.tagName === 'INPUT' && (el as HTMLInputElement).type === 'text'))
    );
  };
  const onDown = (e: KeyboardEvent): void => {
    const k = e.key.toLowerCase();
    if (!watched.has(k) || e.ctrlKey || e.metaKey || e.altKey || typing(e.target)) return;
    e.preventDefault();
    down.add(k);
  };
  const onUp = (e: KeyboardEvent): void => {
    down.delete(e.key.toLowerCase());
  };
  const onBlur = (): void => down.clear();
  window.addEventListener('keydown', onDown);
  window.addEventListener('keyup', onUp);
  window.addEventListener('blur', onBlur);
  return {
    held: (key: string) => down.has(key.toLowerCase()),
    dispose() {
      window.removeEventListener('keydown', onDown);
      window.removeEventListener('keyup', onUp);
      window.removeEventListener('blur', onBlur);
    },
  };
}

/**
 * Adds a dashed line from (x0, y0) to (x1, y1), CSS px, to `g`'s current path (call `stroke` after):
 * dashes of `dash` px separated by `gap` px (both > 0; a non-positive value draws a solid line).
 */
export function dashedLine(g: Graphics, x0: number, y0: number, x1: number, y1: number, dash = 6, gap = 4): Graphics {
  const len = Math.hypot(x1 - x0, y1 - y0);
  if (!(dash > 0 && gap > 0) || len === 0) return g.moveTo(x0, y0).lineTo(x1, y1);
  const ux = (x1 - x0) / len,
    uy = (y1 - y0) / len;
  for (let s = 0; s < len; s += dash + gap) {
    const e = Math.min(len, s + dash);
    g.moveTo(x0 + ux * s, y0 + uy * s).lineTo(x0 + ux * e, y0 + uy * e);
  }
  return g;
}

/**
 * A one-line status readout in the page layout's status row, above the scene; DOM text, so updating
 * it costs no texture upload. @returns `set(text)` (cheap when unchanged).
 */
export function createStatusLine(): { element: HTMLElement; set(text: string): void } {
  const element = document.createElement('div');
  element.className = 'lab-status';
  element.setAttribute('aria-live', 'polite');
  element.style.cssText = 'padding:6px 10px 2px;text-align:center;font:13px/1.4 system-ui,sans-serif;color:#e8ecf1';
  pageLayout().status.append(element);
  let shown = '';
  return {
    element,
    set(text: string) {
      if (text !== shown) {
        shown = text;
        element.textContent = text;
      }
    },
  };
}

/**
 * A plot series that keeps the y axis from zooming into rounding noise: plot.ts has no
 * y-range option, and uPlot autoscales to the data, so a measured value that agrees with its exact
 * value to 1e-6 would fill the chart with noise. Push `scaleFloor(exact, fraction, sample)` into an
 * extra series drawn with `SCALE_SERIES` (invisible): it alternates between exact (1 + fraction) and
 * exact (1 - fraction) (|exact| fraction either side), so the axis always spans at least that band.
 * NaN while `exact` is not finite.
 */
export function scaleFloor(exact: number, fraction: number, sample: number): number {
  if (!Number.isFinite(exact)) return Number.NaN;
  const d = Math.abs(exact) * fraction || fraction;
  return sample % 2 === 0 ? exact + d : exact - d;
}

/** The invisible series that carries `scaleFloor` values (its legend entry names the band). */
export function scaleSeries(fraction: number): { label: string; color: string } {
  return { label: `(axis spans ±${Math.round(fraction * 100)}%)`, color: 'rgba(0,0,0,0)' };
}

/**
 * Width, CSS px, that a lab should keep free at the right of its canvas for the plot dock: 0, as the
 * page layout puts the plots beside the canvas (or in a drawer), never over it.
 */
export function plotReserve(): number {
  return 0;
}
