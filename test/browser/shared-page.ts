/**
 * One page for the tests of a describe block that play the same game page (same size, touch and
 * query) in turn, instead of a page opened (and its scene built, its first frames drawn) for each:
 * opened before the first test and closed after the last; before each test the game is reset
 * (`window.game.reset()`: a new world from the page's parameters), unpaused, and the page's error
 * list emptied, so each test starts from the scene a fresh page starts from. Only for games whose
 * reset rebuilds everything the tests look at.
 */
import { afterAll, beforeAll, beforeEach } from 'vitest';
import { type GamePage, type Harness, type OpenOptions, START_TIMEOUT_MS } from './harness';

/**
 * Registers the hooks (call it inside a describe block, after the hook that starts `harness()`) for
 * the page of the game in games/`folder`/ opened with `options`; `ready(g)`, when given, runs once
 * after it opened (checks of the fresh page). Returns the page's getter, for the tests.
 */
export function sharedPage(
  harness: () => Harness,
  folder: string,
  options: OpenOptions,
  ready?: (g: GamePage) => Promise<void>,
): () => GamePage {
  let page: GamePage | undefined;
  beforeAll(async () => {
    // Opened once more if the first opening fails (a browser too busy to answer in time): a hook is
    // not retried as a test is (vitest's retry), and a test opening its own page would have been.
    try {
      page = await harness().openGame(folder, options);
    } catch (error) {
      console.warn(`[shared-page] opening ${folder} failed, opening it once more: ${String(error)}`);
      page = await harness().openGame(folder, options);
    }
    await ready?.(page);
  }, START_TIMEOUT_MS);
  beforeEach(async () => {
    await page!.evaluate(
      () => {
        const game = window.game as unknown as { reset(): void; paused: boolean };
        game.reset();
        game.paused = false;
      },
      null,
      'resetting the game',
    );
    await page!.frames(2);
    page!.errors.length = 0;
  });
  afterAll(async () => {
    await page?.close();
  });
  return () => page!;
}
