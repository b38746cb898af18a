/**
 * The card at the end of a round or level on a page whose scene is not drawn by pixi (three.js
 * games, a DOM map): an HTML dialog over the stage with a title, optional stars out of N, a big
 * result line, lines of detail and buttons, each with its words, an optional keyboard shortcut
 * and what it does. The pixi counterpart is `createResultCard` (./result-card.ts). DOM only.
 */

import { onButtonPress } from './button-press.js';

/** One button of the card. */
export interface ResultCardButton {
  /** The button's words ('Next round', 'Retry ↺ (R)'); not empty. */
  label: string;
  /** Runs on a press of the button (a tap, a click, Enter or Space on it) and on `key`. */
  onPress: () => void;
  /**
   * The `KeyboardEvent.key` that presses the button while the card shows ('Enter'), listened for by
   * the card; leave it out for a key the game binds itself (R as the shell's reset).
   */
  key?: string;
  /** A key's name shown in small type after the words ('Enter', 'R'); leave it out on a touch screen. */
  keyHint?: string;
  /** The main way on: drawn in the card's primary colours. */
  primary?: boolean;
  /** The accessible name when the words are not enough ('next mission (Enter)'). */
  ariaLabel?: string;
  /** Written to the button's `data-action` (for tests and styles: 'next', 'retry'). */
  action?: string;
}

/** A line of the card with its own class (a game's style or a test's selector). */
export interface ResultCardLine {
  /** The words. */
  text: string;
  /** Classes added to the line's element, space-separated. */
  className?: string;
  /** A line that says the result (rings and time): white, bold and larger than a line of detail. */
  strong?: boolean;
}

/** What the card shows: `show(content)`. */
export interface DomResultCardContent {
  /** The first line, bold, in an h2 ('All 5 pads!', 'Mars reached!'); not empty. */
  title: string;
  /** Stars earned out of a number, drawn as ★ (earned) and ☆ (class `off`); integers, 0 <= earned <= outOf <= 10. */
  stars?: { earned: number; outOf: number };
  /** The result in large gold type ('★★★ 9 moves'); '' or absent for none. */
  big?: string;
  /**
   * Lines under the result, in order: a string is a line of detail (smaller, grey), a ResultCardLine
   * a line with its classes, a Node (a game's own table or chips) is placed as it is. Empty strings
   * are left out.
   */
  lines?: readonly (string | ResultCardLine | Node)[];
  /** The buttons, left to right; may be empty (a card that only says). */
  buttons?: readonly ResultCardButton[];
  /** Whether the round was lost: the edge and title take the `lostColour`. */
  lost?: boolean;
}

/** Options of `createDomResultCard`. */
export interface DomResultCardOptions {
  /** The element's `data-hud` name ('win-banner', 'end'); not empty. */
  name: string;
  /** The dialog's accessible name ('flight result'). Default: none (the title names it). */
  ariaLabel?: string;
  /** Classes added to the card's element (a game's own styles of its lines, a test's selector). */
  className?: string;
  /** CSS `top` of the card's centre in the stage. Default '50%'. */
  top?: string;
  /** CSS `width` of the card. Default 'max-content' (up to the stage's width less 24 px). */
  width?: string;
  /** Edge and title colour, CSS. Default '#ffd166' (gold). */
  accent?: string;
  /** Edge and title colour of a lost round, CSS. Default '#ff8a7a'. */
  lostColour?: string;
  /** Title colour, CSS, won or lost, when it is not the edge's ('#ffffff'). Default the edge's colour. */
  titleColour?: string;
  /** Title size, px, in [12, 48]. Default 20. */
  titleSize?: number;
  /** Background and text colours of the primary button, CSS. Default the accent on near-black text. */
  primaryColours?: { background: string; text: string; border?: string };
  /**
   * Whether pointer events outside the buttons go through to the scene (a drag behind the card still
   * turns the camera). Default false: the card takes them.
   */
  passThrough?: boolean;
  /** Whether `show` moves the keyboard focus to the primary button (given back on `hide`). Default false. */
  focusOnShow?: boolean;
  /**
   * A ✕ button in the top right corner that hides the card (to see the scene under it); `onClose`
   * runs after. `ariaLabel` names it ('hide the result').
   */
  close?: { ariaLabel: string; onClose?: () => void };
}

/** A card made by `createDomResultCard`. */
export interface DomResultCard {
  /** The card's element (role dialog, `data-hud` = name, class `bp-result`), hidden until `show`. */
  readonly element: HTMLElement;
  /** Whether the card shows. */
  readonly shown: boolean;
  /** Shows `content`, laying the card out again only when its words changed (cheap every frame). */
  show(content: DomResultCardContent): void;
  /** Hides the card. */
  hide(): void;
  /** Removes the card and its key listener; the card is unusable after. */
  destroy(): void;
}

const STYLE_ID = 'bp-result-style';
const CSS = `
.bp-result { position: absolute; left: 50%; top: 50%; transform: translate(-50%, -50%); z-index: 6; box-sizing: border-box;
  width: max-content; max-width: calc(100% - 24px); padding: 14px 16px 12px; border-radius: 14px; text-align: center;
  background: rgb(10, 14, 24); border: 2px solid var(--bp-result-accent); color: #e8ecf4;
  font: 500 15px/1.4 system-ui, sans-serif; box-shadow: 0 8px 28px rgba(0, 0, 0, 0.55); }
.bp-result[hidden] { display: none; }
.bp-result.bp-pass { pointer-events: none; }
.bp-result h2 { margin: 0 0 2px; font: 700 var(--bp-result-title-size)/1.3 system-ui, sans-serif; color: var(--bp-result-title); }
.bp-result.bp-closable h2 { padding: 0 40px; }
.bp-result.bp-lost { border-color: var(--bp-result-lost); }
.bp-result.bp-lost h2 { color: var(--bp-result-title-lost); }
.bp-result-stars { font-size: 34px; line-height: 1.1; color: #ffd166; letter-spacing: 4px; }
.bp-result-stars span { display: inline-block; animation: bp-result-pop 0.35s ease-out backwards; }
.bp-result-stars span.off { color: #8391a8; }
@keyframes bp-result-pop { from { transform: scale(0.2); opacity: 0; } }
.bp-result-big { font-weight: 800; font-size: clamp(22px, 7vw, 36px); line-height: 1.2; color: #ffd166; text-shadow: 0 2px 0 #3a1a02; margin: 2px 0 4px; }
.bp-result-line { color: #c8d0dc; font-size: 14px; }
.bp-result-line.bp-strong { color: #ffffff; font-size: 19px; font-weight: 700; }
.bp-result-buttons { display: flex; flex-wrap: wrap; gap: 8px; justify-content: center; margin-top: 10px; }
.bp-result-buttons:empty { display: none; }
.bp-result button { pointer-events: auto; min-width: 44px; min-height: 44px; padding: 6px 12px; border-radius: 10px; cursor: pointer;
  font: 600 15px system-ui, sans-serif; border: 1px solid #8fa3c4; background: #1d2738; color: #fff; white-space: nowrap; }
.bp-result button.bp-primary { background: var(--bp-result-primary); border-color: var(--bp-result-primary-border); color: var(--bp-result-primary-text); }
.bp-result button:focus-visible { outline: 3px solid #9fd3ff; outline-offset: 2px; }
.bp-result button kbd { font: 600 12px system-ui, sans-serif; opacity: 0.8; margin-left: 6px; }
.bp-result button.bp-result-close { position: absolute; right: 4px; top: 4px; padding: 0; border: none; background: none;
  color: #c3cedf; font-size: 18px; }
`;

/** The text of a line, or null for a Node (told by its nodeType: an <a> has a `text` too). */
function lineText(line: string | ResultCardLine | Node): string | null {
  if (typeof line === 'string') return line;
  return typeof (line as Node).nodeType === 'number' ? null : (line as ResultCardLine).text;
}

/** Checks `content`, throwing an error that names `show` and the field. */
function check(content: DomResultCardContent): void {
  if (!content || typeof content.title !== 'string' || content.title === '')
    throw new TypeError(`createDomResultCard show: content.title must be a non-empty string, got ${String(content?.title)}`);
  const s = content.stars;
  if (s && !(Number.isInteger(s.earned) && Number.isInteger(s.outOf) && s.earned >= 0 && s.earned <= s.outOf && s.outOf <= 10))
    throw new RangeError(
      `createDomResultCard show: content.stars must be integers with 0 <= earned <= outOf <= 10, got ${s.earned} of ${s.outOf}`,
    );
  for (const b of content.buttons ?? []) {
    if (typeof b.label !== 'string' || b.label === '')
      throw new TypeError(`createDomResultCard show: a button's label must be a non-empty string, got ${String(b.label)}`);
    if (typeof b.onPress !== 'function')
      throw new TypeError(`createDomResultCard show: button '${b.label}' needs an onPress function, got ${String(b.onPress)}`);
  }
}

/**
 * Makes a result card, hidden, in `parent` (the stage: positioned), centred horizontally at
 * `options.top`. Buttons are at least 44 x 44 px (touch targets); the text colours on the card's
 * near-black ground are at least 4.5:1 (WCAG AA). A pointer press on a button does not reach the
 * scene behind it. While the card shows, a button's `key` (no Ctrl, Meta or Alt, not a repeat) runs
 * its `onPress` once and goes no further (a focused button is not clicked by it as well).
 * @param parent - The element the card is placed over (the scene's stage).
 * @param options - See DomResultCardOptions.
 * @returns the card.
 * @throws TypeError if `parent` has no ownerDocument (not a DOM element) or `options.name` is empty,
 *   RangeError if `options.titleSize` is outside [12, 48];
 *   `show` throws TypeError on an empty title or button label or a missing onPress, RangeError on stars out of range.
 */
export function createDomResultCard(parent: HTMLElement, options: DomResultCardOptions): DomResultCard {
  const doc = parent?.ownerDocument;
  if (!doc) throw new TypeError(`createDomResultCard: parent must be a DOM element, got ${String(parent)}`);
  if (typeof options?.name !== 'string' || options.name === '')
    throw new TypeError(`createDomResultCard: options.name must be a non-empty string, got ${String(options?.name)}`);
  const titleSize = options.titleSize ?? 20;
  if (!(titleSize >= 12 && titleSize <= 48))
    throw new RangeError(`createDomResultCard: options.titleSize must be in [12, 48] px, got ${titleSize}`);
  if (!doc.getElementById(STYLE_ID)) {
    const style = doc.createElement('style');
    style.id = STYLE_ID;
    style.textContent = CSS;
    doc.head.append(style);
  }
  const element = doc.createElement('section');
  element.className = ['bp-result', options.passThrough ? 'bp-pass' : '', options.close ? 'bp-closable' : '', options.className ?? '']
    .filter(Boolean)
    .join(' ');
  element.dataset.hud = options.name;
  // Over the scene on purpose, only at a round's end: a page check for furniture over the scene passes it by.
  element.dataset.sceneOverlay = '';
  element.setAttribute('role', 'dialog');
  element.setAttribute('aria-live', 'polite');
  if (options.ariaLabel) element.setAttribute('aria-label', options.ariaLabel);
  const accent = options.accent ?? '#ffd166';
  const primary = options.primaryColours ?? { background: accent, text: '#1a1206' };
  const vars: [string, string][] = [
    ['--bp-result-accent', accent],
    ['--bp-result-lost', options.lostColour ?? '#ff8a7a'],
    ['--bp-result-title', options.titleColour ?? accent],
    ['--bp-result-title-lost', options.titleColour ?? options.lostColour ?? '#ff8a7a'],
    ['--bp-result-title-size', `${titleSize}px`],
    ['--bp-result-primary', primary.background],
    ['--bp-result-primary-text', primary.text],
    ['--bp-result-primary-border', primary.border ?? primary.background],
  ];
  for (const [k, v] of vars) element.style.setProperty(k, v);
  if (options.top) element.style.top = options.top;
  if (options.width) element.style.width = options.width;
  element.hidden = true;
  parent.append(element);

  let key = '';
  let buttons: readonly ResultCardButton[] = [];
  let primaryEl: HTMLButtonElement | null = null;
  let focusBefore: Element | null = null;
  const put = (into: HTMLElement, tag: string, cls: string, text: string): HTMLElement => {
    const e = doc.createElement(tag);
    if (cls) e.className = cls;
    e.textContent = text;
    into.append(e);
    return e;
  };
  const button = (into: HTMLElement, cls: string, words: string, run: () => void): HTMLButtonElement => {
    const b = put(into, 'button', cls, words) as HTMLButtonElement;
    b.type = 'button';
    // A press on a button is not a press on the scene behind it (no camera drag, no aim).
    b.addEventListener('pointerdown', (e) => e.stopPropagation());
    onButtonPress(b, run);
    return b;
  };
  const layOut = (content: DomResultCardContent): void => {
    element.replaceChildren();
    element.classList.toggle('bp-lost', content.lost === true);
    if (options.close) {
      const { ariaLabel, onClose } = options.close;
      const x = button(element, 'bp-result-close', '✕', () => {
        card.hide();
        onClose?.();
      });
      x.setAttribute('aria-label', ariaLabel);
    }
    put(element, 'h2', '', content.title);
    if (content.stars) {
      const row = put(element, 'div', 'bp-result-stars', '');
      row.setAttribute('aria-label', `${content.stars.earned} of ${content.stars.outOf} stars`);
      for (let i = 0; i < content.stars.outOf; i++) {
        const on = i < content.stars.earned;
        put(row, 'span', on ? '' : 'off', on ? '★' : '☆');
      }
    }
    if (content.big) put(element, 'div', 'bp-result-big', content.big);
    for (const line of content.lines ?? []) {
      const text = lineText(line);
      if (text === null) element.append(line as Node);
      else if (text !== '') {
        const l: Partial<ResultCardLine> = typeof line === 'string' ? {} : (line as ResultCardLine);
        put(element, 'div', ['bp-result-line', l.strong ? 'bp-strong' : '', l.className ?? ''].filter(Boolean).join(' '), text);
      }
    }
    const row = put(element, 'div', 'bp-result-buttons', '');
    primaryEl = null;
    (content.buttons ?? []).forEach((b, i) => {
      // The press runs the handler of the content last shown (show may skip the layout).
      const el = button(row, b.primary ? 'bp-primary' : '', b.label, () => buttons[i]?.onPress());
      if (b.keyHint) put(el, 'kbd', '', b.keyHint);
      if (b.ariaLabel) el.setAttribute('aria-label', b.ariaLabel);
      if (b.action) el.dataset.action = b.action;
      if (b.primary && !primaryEl) primaryEl = el;
    });
  };
  const onKey = (e: KeyboardEvent): void => {
    if (element.hidden || e.repeat || e.ctrlKey || e.metaKey || e.altKey) return;
    const b = buttons.find((x) => x.key === e.key);
    if (!b) return;
    e.preventDefault();
    e.stopPropagation();
    b.onPress();
  };
  const win = doc.defaultView;
  win?.addEventListener('keydown', onKey, { capture: true });

  const card: DomResultCard = {
    element,
    get shown() {
      return !element.hidden;
    },
    show(content) {
      check(content);
      buttons = content.buttons ?? [];
      const wasHidden = element.hidden;
      element.hidden = false;
      // A Node line cannot be compared: the card is laid out again each time it is given one.
      const nodes = (content.lines ?? []).some((l) => lineText(l) === null);
      const k = nodes ? '' : JSON.stringify(content);
      if (k === '' || k !== key) {
        key = k;
        layOut(content);
      }
      if (wasHidden && options.focusOnShow && primaryEl) {
        focusBefore = doc.activeElement;
        primaryEl.focus();
      }
    },
    hide() {
      if (element.hidden) return;
      element.hidden = true;
      key = '';
      // A hidden button keeps no focus: it goes back where it was before `show`, else nowhere.
      if (element.contains(doc.activeElement)) {
        if (focusBefore) (focusBefore as HTMLElement).focus?.();
        else (doc.activeElement as HTMLElement).blur?.();
      }
      focusBefore = null;
    },
    destroy() {
      win?.removeEventListener('keydown', onKey, { capture: true });
      element.remove();
    },
  };
  return card;
}
