/**
 * Black hole in headless Chromium, level 1: the score says what it counts; the level's title shows
 * until the first thrust; holding ↑ flies into the hole across the path, which plays the swallow
 * effect and says so; the next thrust clears that message; flying at a side edge warns before the
 * ship leaves the field.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { type GamePage, Harness, START_TIMEOUT_MS } from './harness';

interface BlackHolePage {
  bh: { falls: number; message: string };
  levelBanner(): string;
  swallowing(): boolean;
  edgeWarning(): boolean;
}

let h: Harness;
let g: GamePage;
beforeAll(async () => {
  h = await Harness.start();
  g = await h.openGame('black-hole', { query: { level: 1 } });
}, START_TIMEOUT_MS);
afterAll(async () => {
  await h?.close();
});

describe('black hole', () => {
  it('labels the score; a fall spirals the ship in; the next thrust clears the message; the edge warns', async () => {
    expect(await g.page.locator('[data-hud="numbers"]').textContent()).toContain('Score 0 (holes passed)');
    // The level's title shows over the field until the first thrust.
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).levelBanner())).toBe('Level 1\n1 hole');
    await g.page.keyboard.down('ArrowUp');
    await g.waitFor(() => (window.game as unknown as BlackHolePage).levelBanner() === '', null);
    await g.waitFor(() => (window.game as unknown as BlackHolePage).swallowing(), null);
    await g.page.keyboard.up('ArrowUp');
    expect(await g.page.evaluate(() => (window.game as unknown as BlackHolePage).bh.falls)).toBe(1);
    expect(await g.page.locator('[data-hud="message"]').textContent()).toMatch(/^Swallowed/);
    await g.page.keyboard.down('ArrowLeft');
    await g.waitFor(() => !(window.game as unknown as BlackHolePage).bh.message.startsWith('Swallowed'), null);
    await g.waitFor(() => (window.game as unknown as BlackHolePage).edgeWarning(), null);
    await g.page.keyboard.up('ArrowLeft');
    expect(g.errors).toEqual([]);
  });
});
