/** One line of the on-screen controls legend. */
export interface ControlHint {
  /** The input, shown as a key cap: 'P', 'Click', 'Drag'. */
  keys: string;
  /** What it does: 'pause / resume'. */
  action: string;
}

/** Options of `createHud`. */
export interface HudOptions {
  /** Game title shown at the top of the readout. Non-empty. */
  title: string;
  /** Legend lines, shown bottom-left in this order. */
  controls: readonly ControlHint[];
  /** Element the HUD is appended to. Default document.body. */
  parent?: HTMLElement;
}

/** The heads-up display: readout (fps, bodies, steps, paused), controls legend and an error banner. DOM only, no pixi. */
export interface Hud {
  /** The readout element (top-left). */
  readonly readout: HTMLElement;
  /** The legend element (bottom-left). */
  readonly legend: HTMLElement;
  /**
   * Shows the numbers. @param fps frames per second (>= 0); @param bodies body count; @param steps
   * steps of the current world; @param paused whether paused. Cheap when nothing changed.
   */
  update(fps: number, bodies: number, steps: number, paused: boolean): void;
  /** Replaces the legend lines. */
  setControls(controls: readonly ControlHint[]): void;
  /** Shows `message` in a red banner (simulation errors). */
  showError(message: string): void;
  /** Removes every HUD element. */
  destroy(): void;
}

const STYLE_ID = 'bp-hud-style';
const CSS = `
.bp-hud, .bp-legend, .bp-error { position: fixed; z-index: 10; font: 13px/1.45 ui-monospace, SFMono-Regular, Menlo, Consolas, monospace;
  color: #e8ecf1; background: rgba(16, 20, 28, 0.72); border-radius: 6px; padding: 8px 10px; pointer-events: none; user-select: none; }
.bp-hud { top: 10px; left: 10px; min-width: 180px; }
.bp-hud h1 { font: 600 14px/1.3 system-ui, sans-serif; margin: 0 0 4px; }
.bp-hud .bp-status { color: #ffd166; }
.bp-legend { bottom: 10px; left: 10px; }
.bp-legend div { white-space: nowrap; }
.bp-legend kbd { display: inline-block; min-width: 1.4em; text-align: center; padding: 0 5px; margin-right: 6px; border: 1px solid #8a94a6;
  border-radius: 4px; background: rgba(255, 255, 255, 0.08); font: inherit; }
.bp-error { top: 10px; left: 50%; transform: translateX(-50%); background: rgba(160, 20, 40, 0.92); max-width: 70vw; white-space: pre-wrap; }
`;

function injectStyle(): void {
  if (document.getElementById(STYLE_ID)) return;
  const style = document.createElement('style');
  style.id = STYLE_ID;
  style.textContent = CSS;
  document.head.append(style);
}

/**
 * Creates the HUD: a readout with the title, fps, body count, step count and pause state, and a
 * legend of the controls. Both ignore the pointer, so clicks reach the canvas below.
 * @throws TypeError if `title` is empty or `controls` is not an array.
 */
export function createHud(options: HudOptions): Hud {
  if (typeof options.title !== 'string' || options.title.length === 0) throw new TypeError('createHud: title must be a non-empty string');
  if (!Array.isArray(options.controls)) throw new TypeError('createHud: controls must be an array of { keys, action }');
  injectStyle();
  const parent = options.parent ?? document.body;
  const readout = document.createElement('div');
  readout.className = 'bp-hud';
  const title = document.createElement('h1');
  title.textContent = options.title;
  const fpsLine = document.createElement('div');
  fpsLine.dataset.hud = 'fps';
  const bodiesLine = document.createElement('div');
  bodiesLine.dataset.hud = 'bodies';
  const stepsLine = document.createElement('div');
  stepsLine.dataset.hud = 'steps';
  const status = document.createElement('div');
  status.className = 'bp-status';
  status.dataset.hud = 'status';
  readout.append(title, fpsLine, bodiesLine, stepsLine, status);
  const legend = document.createElement('div');
  legend.className = 'bp-legend';
  legend.setAttribute('aria-label', 'controls');
  let error: HTMLElement | null = null;
  parent.append(readout, legend);

  let shownFps = -1, shownBodies = -1, shownSteps = -1, shownPaused: boolean | null = null;
  const hud: Hud = {
    readout,
    legend,
    update(fps, bodies, steps, paused) {
      const f = Math.round(fps);
      if (f !== shownFps) { shownFps = f; fpsLine.textContent = `${f} fps`; }
      if (bodies !== shownBodies) { shownBodies = bodies; bodiesLine.textContent = `${bodies} bodies`; }
      if (steps !== shownSteps) { shownSteps = steps; stepsLine.textContent = `step ${steps}`; }
      if (paused !== shownPaused) { shownPaused = paused; status.textContent = paused ? 'paused' : ''; }
    },
    setControls(controls) {
      legend.replaceChildren(...controls.map((c) => {
        const line = document.createElement('div');
        const kbd = document.createElement('kbd');
        kbd.textContent = c.keys;
        line.append(kbd, document.createTextNode(c.action));
        return line;
      }));
    },
    showError(message) {
      if (!error) {
        error = document.createElement('div');
        error.className = 'bp-error';
        error.setAttribute('role', 'alert');
        parent.append(error);
      }
      error.textContent = message;
    },
    destroy() {
      readout.remove();
      legend.remove();
      error?.remove();
    },
  };
  hud.setControls(options.controls);
  hud.update(0, 0, 0, false);
  return hud;
}
