/**
 * Small page helpers shared by the labs of Part II (floating, balloon and parachute, electric field,
 * cyclotron, rocket) that games/shared does not offer (yet): a dock for live plots at the bottom
 * right, a visible banner for bad URL parameters, held-key tracking, and dashed lines for pixi
 * Graphics. DOM and pixi only; no physics.
 */
import type { Graphics } from 'pixi.js';
import { createPlot, type Plot, type PlotOptions } from '../shared/plot';

/**
 * Runs `read` (which reads URL parameters with numberParam / choiceParam / flagParam) and returns its
 * result. If it throws, the message is shown in a red banner on the page (so a bad `?param=` is
 * visible, not only in the console) and the error is rethrown.
 * @throws whatever `read` throws (RangeError naming the parameter for the shared param readers).
 */
export function readUrlParams<T>(read: () => T): T {
  try {
    return read();
  } catch (error) {
    const banner = document.createElement('div');
    banner.setAttribute('role', 'alert');
    banner.className = 'lab-param-error';
    banner.style.cssText = 'position:fixed;top:10px;left:50%;transform:translateX(-50%);z-index:20;max-width:70vw;' +
      'padding:8px 12px;border-radius:6px;background:rgba(160,20,40,0.92);color:#fff;font:13px/1.45 system-ui,sans-serif;white-space:pre-wrap';
    banner.textContent = `Bad URL parameter: ${error instanceof Error ? error.message : String(error)}`;
    document.body.append(banner);
    throw error;
  }
}

/** A column of plots fixed at the bottom right of the window. */
export interface PlotDock {
  /** The dock element. */
  readonly element: HTMLElement;
  /**
   * Adds a live plot (see games/shared/plot.ts) sized to the window: width min(420, 45% of the
   * window), height split between `rows` plots in about 62% of the window's height; 600 samples
   * kept, redrawn every 10 (long dashed polylines are costly to draw under software WebGL).
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
  const element = document.createElement('div');
  element.className = 'lab-plots';
  element.style.cssText = 'position:fixed;right:10px;bottom:10px;z-index:10;display:flex;flex-direction:column;gap:6px;pointer-events:none';
  document.body.append(element);
  const width = Math.round(Math.max(240, Math.min(420, window.innerWidth * 0.45)));
  // The plots take at most 62% of the window's height; each adds about 62 px of title and legend to
  // uPlot's height (which holds the drawing area and the axes).
  const height = Math.round(Math.max(110, Math.min(220, (window.innerHeight * 0.62) / rows - 62)));
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
    return !!el && (el.tagName === 'TEXTAREA' || el.tagName === 'SELECT' || (el.tagName === 'INPUT' && (el as HTMLInputElement).type === 'text'));
  };
  const onDown = (e: KeyboardEvent): void => {
    const k = e.key.toLowerCase();
    if (!watched.has(k) || e.ctrlKey || e.metaKey || e.altKey || typing(e.target)) return;
    e.preventDefault();
    down.add(k);
  };
  const onUp = (e: KeyboardEvent): void => { down.delete(e.key.toLowerCase()); };
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
  const ux = (x1 - x0) / len, uy = (y1 - y0) / len;
  for (let s = 0; s < len; s += dash + gap) {
    const e = Math.min(len, s + dash);
    g.moveTo(x0 + ux * s, y0 + uy * s).lineTo(x0 + ux * e, y0 + uy * e);
  }
  return g;
}

/**
 * A one-line status readout at the top of the window, between the HUD (top left) and the panel (top
 * right); DOM text, so updating it costs no texture upload. @returns `set(text)` (cheap when unchanged).
 */
export function createStatusLine(): { element: HTMLElement; set(text: string): void } {
  const element = document.createElement('div');
  element.className = 'lab-status';
  element.setAttribute('aria-live', 'polite');
  element.style.cssText = 'position:fixed;top:10px;left:220px;right:265px;z-index:10;text-align:center;pointer-events:none;' +
    'font:13px/1.4 system-ui,sans-serif;color:#e8ecf1;text-shadow:0 1px 2px #000';
  document.body.append(element);
  let shown = '';
  return {
    element,
    set(text: string) {
      if (text !== shown) { shown = text; element.textContent = text; }
    },
  };
}

/**
 * A plot series that keeps the y axis from zooming into rounding noise: games/shared/plot.ts has no
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
 * Width, CSS px, that a lab should keep free at the right of its scene for the plot dock: the dock's
 * width plus a margin on windows at least 900 px wide, 0 on narrower ones (there the plot overlaps
 * the scene rather than shrink it to nothing; thumbnails, taken at 640 px, show the whole scene).
 * Read once at start (views are laid out then).
 */
export function plotReserve(): number {
  if (typeof window === 'undefined' || window.innerWidth < 900) return 0;
  return Math.round(Math.max(240, Math.min(420, window.innerWidth * 0.45))) + 30;
}
