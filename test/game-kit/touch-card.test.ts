// The phone's hint card (packages/game-kit/src/hud.ts touchCardLines) picks its lines by their
// declared fields (`touch`, `card`), not by their words.
import { describe, expect, it } from 'vitest';
import { type ControlHint, touchCardLines } from '../../packages/game-kit/src/hud';
import { SHELL_CONTROLS } from '../../packages/game-kit/src/shell';

describe('touch card lines', () => {
  it('leaves out exactly the lines declared card: false or with no touch gesture, up to four', () => {
    const controls: ControlHint[] = [
      ...SHELL_CONTROLS,
      { keys: 'Click', action: 'aim' },
      // Named like a button and like its action, but not declared off the card: it shows.
      { keys: 'J', action: 'jump', touch: 'Jump button' },
      { keys: 'L', action: 'next level', touch: 'Next level', card: false },
      { keys: 'Space', action: 'fire' },
      { keys: 'X', action: 'no touch gesture', touch: '' },
      { keys: 'Drag', action: 'pull' },
      { keys: 'Tap', action: 'fifth line', touch: 'Tap twice' },
    ];
    expect(touchCardLines(controls)).toEqual([
      { gesture: 'Tap', action: 'aim' },
      { gesture: 'Jump button', action: 'jump' },
      { gesture: 'Drag', action: 'pull' },
      { gesture: 'Tap twice', action: 'fifth line' },
    ]);
  });

  it("the shell's pause, step and reset lines (their buttons are in the toolbar) are off the card", () => {
    expect(touchCardLines(SHELL_CONTROLS)).toEqual([]);
  });
});
