/**
 * The DOM pause overlay of a three.js game (game-kit's createDomPauseOverlay, data-hud="paused"), read
 * by the browser tests: waited for once the game is paused and the overlay shows, and waited away.
 */
import type { GamePage } from './harness';

/** What the paused overlay shows: its words, and its box and the canvas's, [left, top, width, height] px. */
export interface PauseShade {
  text: string;
  box: number[];
  stage: number[];
}

/** Waits until `g`'s game is paused and its overlay shows; @returns the overlay as shown. */
export function pausedShade(g: GamePage): Promise<PauseShade> {
  return g.waitFor(() => {
    const el = document.querySelector<HTMLElement>('[data-hud="paused"]');
    if (!window.game!.paused || !el || el.style.display === 'none') return null;
    const box = el.getBoundingClientRect(),
      stage = document.querySelector('canvas')!.getBoundingClientRect();
    return {
      text: el.innerText,
      box: [box.left, box.top, box.width, box.height],
      stage: [stage.left, stage.top, stage.width, stage.height],
    };
  }, null);
}

/** Waits until `g`'s game runs and its overlay is hidden. */
export async function resumedShade(g: GamePage): Promise<void> {
  await g.waitFor(() => !window.game!.paused && document.querySelector<HTMLElement>('[data-hud="paused"]')!.style.display === 'none', null);
}
