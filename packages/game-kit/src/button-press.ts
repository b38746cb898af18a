/**
 * A button's press, not left to the click the browser makes of a tap: on a busy page (frames of a
 * second under software WebGL and load) Chromium sometimes delivers a tap's pointerdown and pointerup
 * together and never a click, so a button listening for clicks ignores the tap.
 */

/**
 * Runs `action` when `button` is pressed: when the primary pointer that went down on it comes up
 * inside its box, or on a click that no pointer made (Enter or Space on the focused button,
 * `button.click()`, a dispatched click event). A pointer's own click (`detail` >= 1) is the press its pointerup already ran,
 * so one press runs `action` once. Nothing runs while the button is disabled. The click's default
 * action is prevented.
 * @param button - The button (any element that gets pointer events and clicks).
 * @param action - Called with no arguments on each press.
 * @throws TypeError if `action` is not a function.
 */
export function onButtonPress(button: HTMLElement, action: () => void): void {
  if (typeof action !== 'function') throw new TypeError(`onButtonPress: action must be a function, got ${String(action)}`);
  const enabled = (): boolean => !(button as HTMLButtonElement).disabled;
  let down: number | null = null;
  button.addEventListener('pointerdown', (e) => {
    if (e.button === 0) down = e.pointerId;
  });
  button.addEventListener('pointerup', (e) => {
    if (down !== e.pointerId) return;
    down = null;
    // A touch is captured by the element it began on: a finger slid off before lifting is no press.
    const r = button.getBoundingClientRect();
    const inside = e.clientX >= r.left && e.clientX <= r.right && e.clientY >= r.top && e.clientY <= r.bottom;
    if (inside && enabled()) action();
  });
  button.addEventListener('pointercancel', (e) => {
    if (down === e.pointerId) down = null;
  });
  button.addEventListener('click', (e) => {
    e.preventDefault();
    // A plain `new Event('click')` has no detail: a click of no pointer too.
    if (!((e as MouseEvent).detail >= 1) && enabled()) action();
  });
}
