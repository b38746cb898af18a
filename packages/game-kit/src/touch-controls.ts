/**
 * On-screen controls for touch screens: a bar of hold or tap buttons and a virtual stick, placed in
 * the page layout's controls row under the scene (./layout), so they never cover the scene. Every
 * game that is played with keys uses them to be playable on a phone. DOM only.
 *
 * A button either holds a key (`key`: it sends the key's keydown when pressed and keyup when let go,
 * to `window`, so a game's own key handling runs unchanged) or calls `onPress` / `onRelease` / `onTap`.
 */

import { onButtonPress } from './button-press.js';
import { pageLayout } from './layout.js';

/** Whether the device's main pointer is a finger (CSS `pointer: coarse`). */
export function isTouchDevice(): boolean {
  return typeof matchMedia === 'function' && matchMedia('(pointer: coarse)').matches;
}

/** One on-screen button. */
export interface TouchButton {
  /** Text on the button (an arrow, a word or two). Non-empty. */
  label: string;
  /** Accessible name (and tooltip); default `label`. */
  name?: string;
  /** Key held while the button is pressed (`KeyboardEvent.key`: 'w', 'ArrowUp', '+'). */
  key?: string;
  /** Called when the finger goes down on the button. */
  onPress?: () => void;
  /** Called when the finger leaves the button (lifted, cancelled or moved off). */
  onRelease?: () => void;
  /** Called on a tap (click) of the button. */
  onTap?: () => void;
  /** Highlight colour while pressed or `active`, CSS. Default amber. */
  accent?: string;
  /** Starts hidden (show it with `ButtonBar.show`). Default false. */
  hidden?: boolean;
}

/** Options of `createButtonBar`. */
export interface ButtonBarOptions {
  /** Accessible name of the group ('ballast and screw'). */
  label: string;
  /** Show the bar on touch devices only. Default true. */
  touchOnly?: boolean;
  /** Element to append the bar to. Default: the page layout's controls row. */
  parent?: HTMLElement;
}

/** A row of on-screen buttons. */
export interface ButtonBar {
  /** The bar element. */
  readonly element: HTMLElement;
  /** The button elements, in the order given. */
  readonly buttons: readonly HTMLButtonElement[];
  /** Shows or hides button `index`. @throws RangeError if there is no such button. */
  show(index: number, visible: boolean): void;
  /** Marks button `index` as on (highlighted) or off, as a toggle's state. */
  setActive(index: number, active: boolean): void;
  /** Removes the bar. */
  destroy(): void;
}

const STYLE_ID = 'bp-touch-style';
const CSS = `
.bp-touchbar { display: flex; flex-wrap: wrap; justify-content: center; align-items: center; gap: 6px; touch-action: none; user-select: none;
  -webkit-user-select: none; }
.bp-touchbar button { min-width: 48px; min-height: 44px; padding: 0 10px; font: 600 15px/1.1 system-ui, sans-serif; color: #f2f5f9;
  background: rgba(24, 30, 44, 0.9); border: 1px solid #6b7891; border-radius: 10px; touch-action: none; cursor: pointer; }
.bp-touchbar button.on { background: var(--bp-accent, #c77d12); border-color: #ffd166; color: #111; }
.bp-touchbar button[hidden] { display: none; }
.bp-touchbar button.bp-big { font-size: 17px; padding: 0 18px; background: #1f7a3a; border-color: #7ee2a0; }
.bp-touchbar.bp-action { position: absolute; left: 0; right: 0; bottom: 14px; z-index: 6; pointer-events: none; }
.bp-touchbar.bp-action.bp-at-top { top: 14px; bottom: auto; }
.bp-touchbar.bp-action button { pointer-events: auto; min-height: 52px; box-shadow: 0 4px 14px rgba(0, 0, 0, 0.45); }
.bp-stick { position: relative; width: 112px; height: 112px; border-radius: 50%; background: rgba(24, 30, 44, 0.9);
  border: 1px solid #6b7891; touch-action: none; user-select: none; flex: none; cursor: grab; }
.bp-stick::before, .bp-stick::after { content: ''; position: absolute; background: #3a465c; }
.bp-stick::before { left: 50%; top: 10%; bottom: 10%; width: 1px; }
.bp-stick::after { top: 50%; left: 10%; right: 10%; height: 1px; }
.bp-stick .bp-knob { position: absolute; left: 50%; top: 50%; width: 46px; height: 46px; margin: -23px 0 0 -23px; border-radius: 50%;
  background: #c9d3e3; box-shadow: 0 2px 6px rgba(0, 0, 0, 0.5); z-index: 1; pointer-events: none; }
.bp-stick-label { font: 12px/1.2 system-ui, sans-serif; color: #e8ecf1; text-align: center; }
`;

function injectStyle(): void {
  if (document.getElementById(STYLE_ID)) return;
  const style = document.createElement('style');
  style.id = STYLE_ID;
  style.textContent = CSS;
  document.head.append(style);
}

/** Keeps the pointer's events on `el` while it is down (a finger sliding off still releases there); synthetic pointers cannot be captured. */
function capture(el: HTMLElement, pointerId: number): void {
  try {
    el.setPointerCapture(pointerId);
  } catch {
    /* not an active pointer (a synthetic event): no capture needed */
  }
}

/** Sends a synthetic key event for `key` to window (what a held button stands for). */
function sendKey(type: 'keydown' | 'keyup', key: string): void {
  window.dispatchEvent(new KeyboardEvent(type, { key, bubbles: true, cancelable: true }));
}

/**
 * Creates a bar of on-screen buttons in the controls row under the scene (on touch devices only,
 * unless `touchOnly` is false). A button with `key` holds that key while pressed; `onPress` /
 * `onRelease` run on finger down / up; `onTap` on a tap or click (`onButtonPress`: a tap counts even
 * when a busy page gets no click of it).
 * @throws TypeError if a button has an empty label.
 */
export function createButtonBar(buttons: readonly TouchButton[], options: ButtonBarOptions): ButtonBar {
  injectStyle();
  const bar = document.createElement('div');
  bar.className = 'bp-touchbar';
  bar.setAttribute('role', 'group');
  bar.setAttribute('aria-label', options.label);
  const els = buttons.map((spec) => {
    if (typeof spec.label !== 'string' || spec.label.length === 0)
      throw new TypeError(`createButtonBar: label must be a non-empty string, got ${JSON.stringify(spec.label)}`);
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = spec.label;
    b.title = spec.name ?? spec.label;
    b.setAttribute('aria-label', spec.name ?? spec.label);
    if (spec.hidden) b.hidden = true;
    if (spec.accent) b.style.setProperty('--bp-accent', spec.accent);
    let down = false;
    const release = (): void => {
      if (!down) return;
      down = false;
      b.classList.remove('on');
      if (spec.key) sendKey('keyup', spec.key);
      spec.onRelease?.();
    };
    if (spec.key || spec.onPress || spec.onRelease) {
      b.addEventListener('pointerdown', (e) => {
        e.preventDefault();
        capture(b, e.pointerId);
        if (down) return;
        down = true;
        b.classList.add('on');
        if (spec.key) sendKey('keydown', spec.key);
        spec.onPress?.();
      });
      b.addEventListener('pointerup', release);
      b.addEventListener('pointercancel', release);
      b.addEventListener('lostpointercapture', release);
      b.addEventListener('contextmenu', (e) => e.preventDefault());
    }
    if (spec.onTap) onButtonPress(b, spec.onTap);
    return b;
  });
  bar.append(...els);
  const visible = options.touchOnly === false || isTouchDevice();
  if (visible) (options.parent ?? pageLayout().controls).append(bar);
  const at = (index: number): HTMLButtonElement => {
    const b = els[index];
    if (!b) throw new RangeError(`ButtonBar: no button ${index} (the bar has ${els.length})`);
    return b;
  };
  return {
    element: bar,
    buttons: els,
    show(index, on) {
      at(index).hidden = !on;
    },
    setActive(index, active) {
      at(index).classList.toggle('on', active);
    },
    destroy() {
      bar.remove();
    },
  };
}

/** Options of `createStick`. */
export interface StickOptions {
  /** Accessible name and caption ('drag to steer'). */
  label: string;
  /** Called whenever the stick moves, with x right and y up, each in [-1, 1] (0, 0 when let go). */
  onChange: (x: number, y: number) => void;
  /** Show on touch devices only. Default true. */
  touchOnly?: boolean;
  /** Element to append the stick to. Default: the page layout's controls row. */
  parent?: HTMLElement;
}

/** A virtual joystick. */
export interface Stick {
  /** The stick's element (the round base; the caption is a sibling in `wrapper`). */
  readonly element: HTMLElement;
  /** The base and its caption. */
  readonly wrapper: HTMLElement;
  /** The current deflection: x right, y up, each in [-1, 1]. */
  readonly x: number;
  readonly y: number;
  /** Removes the stick. */
  destroy(): void;
}

/**
 * Creates a virtual joystick: a round base whose knob follows a finger (or mouse) dragged from it,
 * within the base's radius, and springs back to the centre when let go. Reports the deflection
 * through `onChange` (x right, y up, in [-1, 1], clamped to the unit disc).
 */
export function createStick(options: StickOptions): Stick {
  injectStyle();
  const wrapper = document.createElement('div');
  wrapper.style.cssText = 'display: flex; flex-direction: column; align-items: center; gap: 2px;';
  const base = document.createElement('div');
  base.className = 'bp-stick';
  base.setAttribute('role', 'slider');
  base.setAttribute('aria-label', options.label);
  base.setAttribute('aria-valuetext', 'centred');
  const knob = document.createElement('div');
  knob.className = 'bp-knob';
  base.append(knob);
  const caption = document.createElement('div');
  caption.className = 'bp-stick-label';
  caption.textContent = options.label;
  wrapper.append(base, caption);
  let pointer: number | null = null;
  const state = { x: 0, y: 0 };
  const set = (x: number, y: number): void => {
    const r = Math.hypot(x, y);
    if (r > 1) {
      x /= r;
      y /= r;
    }
    state.x = x;
    state.y = y;
    // The knob stays inside the base (its own radius, 23 px, and 2 px in from the rim): pushed to the
    // rim it covered the caption under the base.
    const radius = Math.max(0, base.clientWidth / 2 - 25);
    knob.style.transform = `translate(${(x * radius).toFixed(1)}px, ${(-y * radius).toFixed(1)}px)`;
    base.setAttribute('aria-valuetext', `x ${x.toFixed(2)}, y ${y.toFixed(2)}`);
    options.onChange(x, y);
  };
  const move = (e: PointerEvent): void => {
    const rect = base.getBoundingClientRect();
    const radius = rect.width / 2 - 12;
    set((e.clientX - rect.left - rect.width / 2) / radius, -(e.clientY - rect.top - rect.height / 2) / radius);
  };
  base.addEventListener('pointerdown', (e) => {
    e.preventDefault();
    pointer = e.pointerId;
    capture(base, e.pointerId);
    move(e);
  });
  base.addEventListener('pointermove', (e) => {
    if (e.pointerId === pointer) move(e);
  });
  const end = (e: PointerEvent): void => {
    if (e.pointerId !== pointer) return;
    pointer = null;
    set(0, 0);
  };
  base.addEventListener('pointerup', end);
  base.addEventListener('pointercancel', end);
  base.addEventListener('lostpointercapture', end);
  const visible = options.touchOnly === false || isTouchDevice();
  if (visible) (options.parent ?? pageLayout().controls).append(wrapper);
  return {
    element: base,
    wrapper,
    get x() {
      return state.x;
    },
    get y() {
      return state.y;
    },
    destroy() {
      wrapper.remove();
    },
  };
}

/** Options of `createActionButton`. */
export interface ActionButtonOptions {
  /**
   * Where the button floats: over the bottom of the stage (default), or over its top, for a scene
   * whose bottom holds the play (a pile of balls).
   */
  at?: 'bottom' | 'top';
}

/**
 * Shows a big on-screen action button (a "Next level" or "Play again") while `visible`, on every
 * device, floating over the bottom (or, with `at: 'top'`, the top) of the stage, so the scene does
 * not move when it appears; a tap runs `onTap`. @returns a function that sets its visibility and label.
 * @throws TypeError if `at` is neither 'bottom' nor 'top'.
 */
export function createActionButton(
  label: string,
  onTap: () => void,
  options: ActionButtonOptions = {},
): (visible: boolean, text?: string) => void {
  const at = options.at ?? 'bottom';
  if (at !== 'bottom' && at !== 'top') throw new TypeError(`createActionButton: at must be 'bottom' or 'top', got ${JSON.stringify(at)}`);
  const bar = createButtonBar([{ label, onTap }], { label, touchOnly: false, parent: document.createElement('div') });
  const b = bar.buttons[0]!;
  b.classList.add('bp-big');
  bar.element.classList.add('bp-action');
  if (at === 'top') bar.element.classList.add('bp-at-top');
  bar.element.remove();
  return (visible, text) => {
    // The tooltip (title) follows the label too: a 'Try again' button hovered must not say 'Next level'.
    if (text !== undefined && b.textContent !== text) {
      b.textContent = text;
      b.title = text;
      b.setAttribute('aria-label', text);
    }
    // Out of the page while hidden.
    if (visible && !bar.element.isConnected) pageLayout().stage.append(bar.element);
    else if (!visible && bar.element.isConnected) bar.element.remove();
  };
}
