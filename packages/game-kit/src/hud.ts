import { pageLayout } from './layout.js';

/** One line of the on-screen controls legend. */
export interface ControlHint {
  /** The input, shown as a key cap: 'P', 'Click', 'Drag'. */
  keys: string;
  /** What it does: 'pause / resume'. */
  action: string;
  /**
   * The gesture on a touch device, shown instead of `keys` there: 'Tap', 'Drag', 'pad ↑'. '' hides
   * the line on touch devices. Default: 'Tap' for a 'Click', the same text for 'Drag' (and other
   * pointer words), and the line hidden for keyboard keys.
   */
  touch?: string;
  /**
   * Whether the phone's hint card (the gestures shown over the stage until the first touch) lists
   * this line. Default true. false for a control the player sees already: a toolbar or on-screen
   * button ('▮▮ button', 'Jump'), so the card's few lines name the gestures that have no button.
   */
  card?: boolean;
}

/** The gesture shown for `hint` on a touch device, or '' to leave the line out (see ControlHint.touch). */
export function touchGesture(hint: ControlHint): string {
  if (hint.touch !== undefined) return hint.touch;
  const keys = hint.keys.trim();
  if (/^(click|tap)$/i.test(keys)) return 'Tap';
  if (/^(drag|click or drag|touch|pinch|swipe)\b/i.test(keys)) return keys.replace(/click/i, 'Tap');
  if (/click/i.test(keys) && !/right|shift|ctrl|alt/i.test(keys)) return keys.replace(/[A-Z] \/ /, '').replace(/click/i, 'Tap');
  return '';
}

/** Options of `createHud`. */
export interface HudOptions {
  /** Game title shown at the top of the readout. Non-empty. */
  title: string;
  /** Legend lines, in this order (their touch gestures on touch devices, see `ControlHint.touch`). */
  controls: readonly ControlHint[];
  /**
   * Element the readout and legend are appended to. Default: the page layout's info column
   * (./layout), with the title in its toolbar.
   */
  parent?: HTMLElement;
}

/**
 * The heads-up display: readout (fps and paused; bodies and steps in a closed 'physics details'
 * fold), controls legend and an error banner. DOM only, no pixi.
 */
export interface Hud {
  /** The readout element (top of the info column). */
  readonly readout: HTMLElement;
  /**
   * The 'physics details' fold in the readout (a `<details>` element, closed at start): the body and
   * step counts, and whatever a page appends there (an engine's numbers a player need not read).
   */
  readonly details: HTMLElement;
  /** The legend element (bottom of the info column). */
  readonly legend: HTMLElement;
  /**
   * Shows the numbers. @param fps frames per second (>= 0; 0, not measured yet, shows a dash); @param bodies body count; @param steps
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
.bp-hud, .bp-legend, .bp-error { font: 12px/1.45 ui-monospace, SFMono-Regular, Menlo, Consolas, monospace;
  color: #e8ecf1; border-radius: 6px; user-select: none; }
.bp-hud h1 { font: 600 14px/1.3 system-ui, sans-serif; margin: 0 0 4px; }
.bp-hud .bp-run-state { color: #ffd166; min-height: 1.45em; }
.bp-hud .bp-physics summary { cursor: pointer; color: #9aa4b5; }
.bp-hud .bp-physics[open] summary { margin-bottom: 2px; }
.bp-legend div { display: flex; gap: 6px; align-items: baseline; margin-bottom: 2px; }
.bp-legend kbd { flex: none; display: inline-block; min-width: 1.4em; text-align: center; padding: 0 5px; border: 1px solid #8a94a6;
  border-radius: 4px; background: rgba(255, 255, 255, 0.08); font: inherit; white-space: nowrap; }
.bp-touch-hint { position: absolute; z-index: 5; left: 50%; bottom: 16px; transform: translateX(-50%); width: max-content; max-width: calc(100% - 24px); box-sizing: border-box;
  padding: 8px 12px; background: rgba(12, 16, 26, 0.82); border: 1px solid #6b7891; border-radius: 10px; pointer-events: none;
  font: 14px/1.45 system-ui, sans-serif; color: #f2f5f9; transition: opacity 0.6s; }
.bp-touch-hint.bp-gone { opacity: 0; }
.bp-touch-hint div { display: flex; gap: 8px; align-items: baseline; }
.bp-touch-hint b { flex: none; color: #ffd166; }
.bp-error { position: fixed; z-index: 40; top: 10px; left: 50%; transform: translateX(-50%); padding: 8px 10px;
  background: rgba(160, 20, 40, 0.92); max-width: 80vw; white-space: pre-wrap; font-family: system-ui, sans-serif; }
`;

function injectStyle(): void {
  if (document.getElementById(STYLE_ID)) return;
  const style = document.createElement('style');
  style.id = STYLE_ID;
  style.textContent = CSS;
  document.head.append(style);
}

/** One line of a controls list: the keys or gesture in a `tag` element, then what it does. */
function controlLine(tag: 'kbd' | 'b', keys: string, action: string): HTMLElement {
  const line = document.createElement('div');
  const k = document.createElement(tag);
  k.textContent = keys;
  const a = document.createElement('span');
  a.textContent = action;
  line.append(k, a);
  return line;
}

/** Most lines on the phone's hint card. */
const TOUCH_CARD_LINES = 4;

/**
 * The lines of the phone's hint card, in order: each of `controls` with a touch gesture (see
 * `touchGesture`) and not declared `card: false`, up to four. Decided by those fields alone, never
 * by the words of a line.
 */
export function touchCardLines(controls: readonly ControlHint[]): { gesture: string; action: string }[] {
  const out: { gesture: string; action: string }[] = [];
  for (const c of controls) {
    const gesture = touchGesture(c);
    if (gesture !== '' && c.card !== false && out.length < TOUCH_CARD_LINES) out.push({ gesture, action: c.action });
  }
  return out;
}

/** How long the touch hint stays up without input, ms. */
const TOUCH_HINT_MS = 9000;

/**
 * On a phone the legend sits in a drawer behind the toolbar's menu button, so a first-time player
 * would not see how to play. This shows the game's touch gestures (up to four; not the lines marked
 * `card: false`, the buttons in view) in a card over the bottom of
 * the stage that lets touches through and fades at the first touch on the stage or after
 * TOUCH_HINT_MS. Marked `data-scene-overlay`: it is transient, not page furniture covering the scene.
 */
function showTouchHint(stage: HTMLElement, controls: readonly ControlHint[]): void {
  stage.querySelector('.bp-touch-hint')?.remove();
  const lines = touchCardLines(controls).map((c) => controlLine('b', c.gesture, c.action));
  if (lines.length === 0) return;
  const hint = document.createElement('div');
  hint.className = 'bp-touch-hint';
  hint.dataset.sceneOverlay = '';
  hint.dataset.hud = 'touch-hint';
  hint.append(...lines);
  stage.append(hint);
  const hide = (): void => {
    hint.classList.add('bp-gone');
    setTimeout(() => hint.remove(), 700);
    stage.removeEventListener('pointerdown', hide, true);
  };
  stage.addEventListener('pointerdown', hide, true);
  setTimeout(hide, TOUCH_HINT_MS);
}

/** `n` and the noun in singular or plural: `plural(1, 'body', 'bodies')` is '1 body'. */
export function plural(n: number, one: string, many: string): string {
  return `${n} ${n === 1 ? one : many}`;
}

/**
 * Creates the HUD: the title (in the layout's toolbar), a readout with fps and pause state and a
 * closed 'physics details' fold with the body and step counts (`Hud.details`), and a legend of the
 * controls (touch gestures on touch devices), in the layout's info column unless `parent` is given.
 * @throws TypeError if `title` is empty or `controls` is not an array.
 */
export function createHud(options: HudOptions): Hud {
  if (typeof options.title !== 'string' || options.title.length === 0) throw new TypeError('createHud: title must be a non-empty string');
  if (!Array.isArray(options.controls)) throw new TypeError('createHud: controls must be an array of { keys, action }');
  injectStyle();
  const layout = options.parent ? null : pageLayout();
  const parent = options.parent ?? layout!.info;
  const readout = document.createElement('div');
  readout.className = 'bp-hud';
  const title = document.createElement('h1');
  title.textContent = options.title;
  if (layout) {
    layout.setTitle(options.title);
    title.hidden = true;
  }
  const fpsLine = document.createElement('div');
  fpsLine.dataset.hud = 'fps';
  const bodiesLine = document.createElement('div');
  bodiesLine.dataset.hud = 'bodies';
  const stepsLine = document.createElement('div');
  stepsLine.dataset.hud = 'steps';
  // The pause line keeps its height while empty (CSS min-height), so the legend under it stays put.
  const status = document.createElement('div');
  status.className = 'bp-run-state';
  status.dataset.hud = 'status';
  // The engine's numbers go in a fold, closed: a player reads the frame rate and whether the game is
  // paused; the body and step counts are for whoever looks into the physics (one click opens them).
  const details = document.createElement('details');
  details.className = 'bp-physics';
  details.dataset.hud = 'physics';
  const summary = document.createElement('summary');
  summary.textContent = 'physics details';
  details.append(summary, bodiesLine, stepsLine);
  readout.append(title, fpsLine, status, details);
  const legend = document.createElement('div');
  legend.className = 'bp-legend';
  legend.setAttribute('aria-label', 'controls');
  let error: HTMLElement | null = null;
  if (layout) {
    layout.info.prepend(readout);
    layout.help.append(legend);
  } else {
    parent.append(readout, legend);
  }
  const touch = layout ? layout.touch() : false;

  let shownFps = -1,
    shownBodies = -1,
    shownSteps = -1,
    shownPaused: boolean | null = null;
  const hud: Hud = {
    readout,
    details,
    legend,
    update(fps, bodies, steps, paused) {
      const f = Math.round(fps);
      if (f !== shownFps) {
        shownFps = f;
        // 0 until the loop has measured its first half second: a dash, not a "0 fps" that reads as a
        // stalled page.
        fpsLine.textContent = f > 0 ? `${f} fps` : '– fps';
      }
      if (bodies !== shownBodies) {
        shownBodies = bodies;
        bodiesLine.textContent = plural(bodies, 'body', 'bodies');
      }
      if (steps !== shownSteps) {
        shownSteps = steps;
        stepsLine.textContent = `step ${steps}`;
      }
      if (paused !== shownPaused) {
        shownPaused = paused;
        status.textContent = paused ? 'paused' : '';
      }
    },
    setControls(controls) {
      const lines: HTMLElement[] = [];
      for (const c of controls) {
        const keys = touch ? touchGesture(c) : c.keys;
        if (keys === '') continue;
        lines.push(controlLine('kbd', keys, c.action));
      }
      legend.replaceChildren(...lines);
      if (layout && touch && layout.compact()) showTouchHint(layout.stage, controls);
    },
    showError(message) {
      if (!error) {
        error = document.createElement('div');
        error.className = 'bp-error';
        error.setAttribute('role', 'alert');
        document.body.append(error);
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
