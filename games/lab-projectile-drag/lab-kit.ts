/**
 * Lab kit: the page furniture the six labs of Part II share (lab-projectile-drag, lab-orbits,
 * lab-integrators, lab-spring-chain, lab-bungee, lab-pendulum), on top of games/shared. The particle
 * labs use its readout, `fmt` and URL-parameter error box too (games/lab-galaxy/particle-kit.ts).
 *
 * - a dock on the right holding the lil-gui panel, a readout box and the uPlot charts;
 * - fitting the camera so a world rectangle lands beside the dock;
 * - URL parameters read behind a clear on-page error;
 * - interpolated positions, and pixi drawing helpers (springs, dashed lines, polylines from ring
 *   buffers) for what the WorldRenderer does not draw.
 *
 * It lives in this folder because the lab folders are what the labs own; it belongs in
 * games/shared (see the labs' report). No physics in here: only layout, input and drawing.
 */
import type { Application, Graphics } from 'pixi.js';
import type { PhysicsWorld } from '@bitphysics/physics';
import type { Camera, Point2, WorldRect } from '@bitphysics/render-pixi';

const STYLE_ID = 'bp-lab-style';
const CSS = `
.bp-lab-dock { position: fixed; top: 0; right: 0; z-index: 20; box-sizing: border-box; max-height: 100vh; overflow-y: auto;
  display: flex; flex-direction: column; gap: 6px; padding: 6px; }
.bp-lab-dock > * { flex-shrink: 0; }
.bp-lab-dock .lil-gui.lil-root { --width: auto; width: auto; }
.bp-lab-info { margin-top: 6px; padding-top: 6px; border-top: 1px solid rgba(255, 255, 255, 0.15); white-space: pre; }
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

/** Narrowest window, CSS px, at which the dock sits beside the scene instead of over it. */
export const DOCK_BESIDE_MIN_WIDTH = 720;

/** The right-hand column of a lab page. */
export interface LabDock {
  /** The dock element (a direct child of body, after the canvas). */
  readonly root: HTMLElement;
  /** Where the lil-gui panel goes (`createPanel(..., { container: dock.panelSlot })`). */
  readonly panelSlot: HTMLElement;
  /** Where the charts go (`createPlot({ parent: dock.charts })`). */
  readonly charts: HTMLElement;
  /** Width of the dock, CSS px. */
  readonly width: number;
  /** Width of a chart that fills the dock, CSS px. */
  readonly chartWidth: number;
  /** CSS px of the window the scene must leave free on the right: the dock's width when it sits beside the scene, else 0. */
  reserved(): number;
  /** Removes the dock. */
  destroy(): void;
}

/**
 * Creates the dock: panel slot and chart area, fixed to the right edge of the window.
 * Call it after the pixi canvas is in the page, so the canvas stays the page's first canvas
 * (uPlot draws into canvases of its own).
 * @param width CSS px, integer in [240, 800]. Default 360.
 * @throws RangeError on a width out of range.
 */
export function createLabDock(width = 360): LabDock {
  if (!Number.isInteger(width) || width < 240 || width > 800) throw new RangeError(`createLabDock: width must be an integer in [240, 800] px, got ${width}`);
  injectStyle();
  const root = document.createElement('div');
  root.className = 'bp-lab-dock';
  root.style.width = `${width}px`;
  const panelSlot = document.createElement('div');
  const charts = document.createElement('div');
  charts.style.display = 'flex';
  charts.style.flexDirection = 'column';
  charts.style.gap = '6px';
  root.append(panelSlot, charts);
  document.body.append(root);
  return {
    root, panelSlot, charts, width,
    chartWidth: width - 12 - 16,
    reserved: () => (window.innerWidth >= DOCK_BESIDE_MIN_WIDTH ? width : 0),
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
  const W = camera.width, H = camera.height;
  let free = W - reservedPx;
  if (free - 2 * padding < 80) free = W;
  const w = rect.maxX - rect.minX, h = rect.maxY - rect.minY;
  const pad = Math.min(padding, free / 4, H / 4);
  const ppm = Math.min((free - 2 * pad) / w, (H - 2 * pad) / h);
  const cx = (rect.minX + rect.maxX) / 2, cy = (rect.minY + rect.maxY) / 2;
  const minX = cx - free / 2 / ppm, minY = cy - H / 2 / ppm;
  camera.fit({ minX, minY, maxX: minX + W / ppm, maxY: minY + H / ppm }, 0);
}

/**
 * Keeps `view()` (m) fitted beside the dock: now and after every resize of the app's renderer.
 * Call the returned function to refit (after the view changed).
 */
export function followView(app: Application, camera: Camera, dock: LabDock, view: () => WorldRect): () => void {
  const refit = (): void => fitViewBeside(camera, view(), dock.reserved());
  app.renderer.on('resize', refit);
  refit();
  return refit;
}

/**
 * Shows `message` in a red box in the middle of the page (bad URL parameters and other errors that
 * stop a lab before it starts).
 */
export function showPageError(message: string): void {
  injectStyle();
  const box = document.createElement('div');
  box.className = 'bp-lab-error';
  box.setAttribute('role', 'alert');
  box.dataset.lab = 'error';
  box.textContent = message;
  document.body.append(box);
}

/**
 * Runs `read` (which reads URL parameters with numberParam / choiceParam) and returns its value. If
 * it throws, the message is shown on the page with the accepted values, and the error is rethrown
 * so the page stops (and tests see it).
 */
export function readUrlParams<T>(read: () => T, usage: string): T {
  try {
    return read();
  } catch (error) {
    const message = error instanceof Error ? error.message : String(error);
    showPageError(`${message}\n\n${usage}`);
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
 * (`shell.hud.readout`), under its fps and step lines. `swatches` optionally gives a CSS colour per
 * line (a coloured square before the label, for legends). The block has `data-lab="info"`.
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
      if (texts[i] !== text) { texts[i] = text; el.textContent = text; }
    },
    get(i) { return texts[i] ?? ''; },
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
  const P = world.components.Position, O = world.components.PreviousPosition;
  out.x = O.x[eid]! + (P.x[eid]! - O.x[eid]!) * alpha;
  out.y = O.y[eid]! + (P.y[eid]! - O.y[eid]!) * alpha;
  return out;
}

/**
 * Draws a coil spring (zigzag) from screen point (x1, y1) to (x2, y2), px, with `coils` teeth (integer
 * >= 1) of half-width `amplitude` px, straight leads of `lead` px at both ends. Appends a path to `g`
 * and strokes it.
 */
export function drawSpring(g: Graphics, x1: number, y1: number, x2: number, y2: number, coils: number, amplitude: number, width: number, color: number, alpha = 1): void {
  const dx = x2 - x1, dy = y2 - y1;
  const len = Math.sqrt(dx * dx + dy * dy);
  if (len < 1e-6) return;
  const ux = dx / len, uy = dy / len, nx = -uy, ny = ux;
  const lead = Math.min(6, len * 0.1);
  const body = len - 2 * lead;
  g.moveTo(x1, y1).lineTo(x1 + ux * lead, y1 + uy * lead);
  const n = coils * 2;
  for (let i = 0; i < n; i++) {
    const s = lead + ((i + 0.5) / n) * body;
    const side = i % 2 === 0 ? amplitude : -amplitude;
    g.lineTo(x1 + ux * s + nx * side, y1 + uy * s + ny * side);
  }
  g.lineTo(x2 - ux * lead, y2 - uy * lead).lineTo(x2, y2).stroke({ width, color, alpha });
}

/** Draws a dashed straight line from (x1, y1) to (x2, y2), px: dashes of `dash` px, gaps of `gap` px. */
export function drawDashedLine(g: Graphics, x1: number, y1: number, x2: number, y2: number, width: number, color: number, alpha = 1, dash = 8, gap = 6): void {
  const dx = x2 - x1, dy = y2 - y1;
  const len = Math.sqrt(dx * dx + dy * dy);
  if (len < 1e-6) return;
  const ux = dx / len, uy = dy / len;
  for (let s = 0; s < len; s += dash + gap) {
    const e = Math.min(len, s + dash);
    g.moveTo(x1 + ux * s, y1 + uy * s).lineTo(x1 + ux * e, y1 + uy * e);
  }
  g.stroke({ width, color, alpha });
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
    let px = 0, py = 0;
    for (let k = 0; k < this.count; k++) {
      const i = (start + k) % cap;
      const sx = camera.toScreenX(this.xs[i]!), sy = camera.toScreenY(this.ys[i]!);
      if (k === 0) g.moveTo(sx, sy);
      else if (!dashed) g.lineTo(sx, sy);
      else if (((k - 1) >> 2) % 2 === 0) g.moveTo(px, py).lineTo(sx, sy);
      px = sx; py = sy;
    }
    if (!dashed && !Number.isNaN(endX)) g.lineTo(camera.toScreenX(endX), camera.toScreenY(endY));
    g.stroke({ width, color, alpha });
  }
}

/** Converts 0xRRGGBB to a CSS colour string. */
export function cssColor(color: number): string {
  return `#${color.toString(16).padStart(6, '0')}`;
}
