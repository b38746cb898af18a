/**
 * __TITLE__ in headless Chromium (made from the game template): the page starts with its balls,
 * B and a click each drop one more, P pauses (no steps while paused) and the page logs no error.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness } from './harness';

/** The extras games/__NAME__/main.ts puts on window.game. */
interface TemplateGame {
  ballCount(): number;
  paused: boolean;
  world: { steps: number };
}

const COUNT = 5;

describe('__NAME__', () => {
  let h: Harness;
  let g: GamePage;
  beforeAll(async () => {
    h = await Harness.start();
    g = await h.openGame('__NAME__', { query: { count: COUNT } });
  });
  afterAll(async () => {
    await h?.close();
  });

  const balls = () => g.page.evaluate(() => (window.game as unknown as TemplateGame).ballCount());

  it('starts with ?count balls, draws and steps', async () => {
    expect(await balls()).toBe(COUNT);
    expect(await g.canvasColors()).toBeGreaterThan(4);
    await g.waitFor(() => (window.game as unknown as TemplateGame).world.steps > 2, null);
    expect(g.errors).toEqual([]);
  });

  it('drops a ball on B and on a click', async () => {
    const before = await balls();
    await g.press('b');
    await g.waitFor((n) => (window.game as unknown as TemplateGame).ballCount() === n + 1, before);
    const box = (await g.page.locator('canvas').first().boundingBox())!;
    await g.page.mouse.click(box.x + box.width / 2, box.y + box.height / 3);
    await g.waitFor((n) => (window.game as unknown as TemplateGame).ballCount() === n + 2, before);
    expect(g.errors).toEqual([]);
  });

  it('pauses on P: no steps while paused', async () => {
    await g.press('p');
    await g.waitFor(() => (window.game as unknown as TemplateGame).paused, null);
    const steps = await g.page.evaluate(() => (window.game as unknown as TemplateGame).world.steps);
    await g.frames(5);
    expect(await g.page.evaluate(() => (window.game as unknown as TemplateGame).world.steps)).toBe(steps);
    await g.press('p');
    expect(g.errors).toEqual([]);
  });
});
