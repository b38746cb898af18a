/**
 * A game's status row above the scene: three centred lines, the goal (gold; green once the round or
 * level is done), the numbers (score, time, level, in a monospace font) and a hint, in the page
 * layout's status region (./layout), so it never covers the scene. DOM only.
 */
import { pageLayout } from './layout.js';

/** The three lines of a status row. */
export interface StatusLines {
  /** What to do, or how the round ended: 'Throw balls through the hoop!'. */
  goal: string;
  /** The numbers: 'Baskets 2 · Time 31 s · Best 4'. */
  numbers: string;
  /** How to play, or what to do next: 'Drag and let go to throw'. */
  hint: string;
}

/** Options of `createStatusRow`. */
export interface StatusRowOptions {
  /** The row's `data-hud` name, for tests and scripts ('hoop', 'lanterns'). Non-empty. */
  name: string;
  /** Element the row is appended to. Default: the page layout's status region. */
  parent?: HTMLElement;
}

/** A status row (see `createStatusRow`). */
export interface StatusRow {
  /** The row: role 'status' (screen readers announce its changes), `data-hud` = the name given. */
  readonly element: HTMLElement;
  /** The goal line (`data-hud="goal"`). */
  readonly goal: HTMLElement;
  /** The numbers line (`data-hud="numbers"`). */
  readonly numbers: HTMLElement;
  /** The hint line (`data-hud="hint"`): its text is in its first child, a span; a page may append buttons after it. */
  readonly hint: HTMLElement;
  /**
   * Shows `lines`, and the goal in green when `done` (a round over, a level cleared). Writes the DOM
   * only when something differs from what is shown, so it is cheap to call every frame.
   * @returns whether anything changed.
   */
  set(lines: StatusLines, done?: boolean): boolean;
}

const STYLE_ID = 'bp-status-row-style';
const CSS = `
.bp-status-row { text-align: center; font: 14px/1.4 system-ui, sans-serif; color: #eef3f8; padding: 6px 10px 4px; }
.bp-status-row .bp-status-goal { font-weight: 600; color: #ffd166; }
.bp-status-row .bp-status-numbers { font: 600 15px ui-monospace, Menlo, Consolas, monospace; }
.bp-status-row .bp-status-hint { color: #c9d3e3; font-size: 13px; }
.bp-status-row.bp-done .bp-status-goal { color: #7ee787; }
.bp-status-row button { font: 13px system-ui, sans-serif; color: #e8ecf1; background: rgba(255, 255, 255, 0.08); border: 1px solid #4a5468;
  border-radius: 6px; padding: 2px 10px; margin-left: 8px; cursor: pointer; min-height: 28px; }
@media (pointer: coarse) { .bp-status-row button { min-height: 36px; } }
`;

/**
 * Creates a status row (goal, numbers, hint) in the page layout's status region, or in `parent`.
 * @throws TypeError if `name` is not a non-empty string.
 */
export function createStatusRow(options: StatusRowOptions): StatusRow {
  if (typeof options?.name !== 'string' || options.name.length === 0)
    throw new TypeError(`createStatusRow: name must be a non-empty string, got ${JSON.stringify(options?.name)}`);
  const parent = options.parent ?? pageLayout().status;
  const doc = parent.ownerDocument;
  if (!doc.getElementById(STYLE_ID)) {
    const style = doc.createElement('style');
    style.id = STYLE_ID;
    style.textContent = CSS;
    doc.head.append(style);
  }
  const line = (part: 'goal' | 'numbers' | 'hint'): HTMLElement => {
    const el = doc.createElement('div');
    el.className = `bp-status-${part}`;
    el.dataset.hud = part;
    return el;
  };
  const element = doc.createElement('div');
  element.className = 'bp-status-row';
  element.setAttribute('role', 'status');
  element.dataset.hud = options.name;
  const goal = line('goal'),
    numbers = line('numbers'),
    hint = line('hint');
  const hintText = doc.createElement('span');
  hint.append(hintText);
  element.append(goal, numbers, hint);
  parent.append(element);
  let shown: StatusLines = { goal: '', numbers: '', hint: '' };
  let shownDone = false;
  return {
    element,
    goal,
    numbers,
    hint,
    set(lines, done = false) {
      if (lines.goal === shown.goal && lines.numbers === shown.numbers && lines.hint === shown.hint && done === shownDone) return false;
      shown = { goal: lines.goal, numbers: lines.numbers, hint: lines.hint };
      shownDone = done;
      goal.textContent = lines.goal;
      numbers.textContent = lines.numbers;
      hintText.textContent = lines.hint;
      element.classList.toggle('bp-done', done);
      return true;
    },
  };
}
