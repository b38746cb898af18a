// onButtonPress (packages/game-kit/src/button-press.ts) on a stand-in element that records its
// listeners: a tap whose click never comes still presses, a tap and its click press once, a click of
// no pointer (keyboard, button.click()) presses, a finger slid off or a disabled button does not.
import { describe, expect, it } from 'vitest';
import { onButtonPress } from '../../packages/game-kit/src/button-press';

type Listener = (e: Record<string, unknown>) => void;

/** A 100 x 40 px button at (10, 20) with addEventListener, dispatch and a disabled flag. */
class FakeButton {
  disabled = false;
  private readonly listeners = new Map<string, Listener[]>();
  addEventListener(type: string, fn: Listener): void {
    this.listeners.set(type, [...(this.listeners.get(type) ?? []), fn]);
  }
  getBoundingClientRect() {
    return { left: 10, top: 20, right: 110, bottom: 60 };
  }
  fire(type: string, e: Record<string, unknown> = {}): void {
    const event = { preventDefault: () => {}, button: 0, pointerId: 1, clientX: 50, clientY: 40, detail: 1, ...e };
    for (const fn of this.listeners.get(type) ?? []) fn(event);
  }
}

type Step = [type: string, event?: Record<string, unknown>];

/** How many times the action ran after `steps` fired in order on a fresh button (disabled if asked). */
function pressed(steps: Step[], disabled = false): number {
  const b = new FakeButton();
  b.disabled = disabled;
  let n = 0;
  onButtonPress(b as unknown as HTMLElement, () => n++);
  for (const [type, e] of steps) b.fire(type, e);
  return n;
}

describe('onButtonPress', () => {
  it('a tap whose click never comes (a busy page) presses once', () => {
    expect(pressed([['pointerdown'], ['pointerup']])).toBe(1);
  });

  it('a tap followed by its click presses once, not twice', () => {
    expect(pressed([['pointerdown'], ['pointerup'], ['click', { detail: 1 }]])).toBe(1);
  });

  it('a click of no pointer (Enter, Space, button.click()) presses', () => {
    expect(pressed([['click', { detail: 0 }]])).toBe(1);
    expect(pressed([['click', { detail: undefined }]])).toBe(1);
  });

  it('a finger slid off the button before lifting, a cancelled pointer, another pointer or button: no press', () => {
    expect(pressed([['pointerdown'], ['pointerup', { clientX: 200 }]])).toBe(0);
    expect(pressed([['pointerdown'], ['pointercancel'], ['pointerup']])).toBe(0);
    expect(pressed([['pointerdown', { pointerId: 2 }], ['pointerup']])).toBe(0);
    expect(pressed([['pointerdown', { button: 2 }], ['pointerup']])).toBe(0);
  });

  it('a disabled button does nothing', () => {
    expect(pressed([['pointerdown'], ['pointerup'], ['click', { detail: 0 }]], true)).toBe(0);
  });

  it('throws a TypeError naming the function for an action that is not a function', () => {
    expect(() => onButtonPress(new FakeButton() as unknown as HTMLElement, 3 as unknown as () => void)).toThrow(
      /onButtonPress: action must be a function, got 3/,
    );
  });
});
