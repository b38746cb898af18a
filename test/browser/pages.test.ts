/**
 * Opens every page of the gallery registry (games/<folder>/game.json) in headless Chromium and
 * checks the page contract: no console errors, page errors or failed requests; the ready flag;
 * window.game.stats(); a canvas that is not blank; no error box. The gallery itself must list every entry.
 *
 * Every page runs twice: with the language 'en-US@posix' (what Chromium reports under LANG=C.UTF-8;
 * Intl rejects the tag, and uPlot's module used to throw on it) and with 'de-DE' (comma decimals).
 * One browser and one server for all of them.
 */
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { Harness, readRegistry } from './harness';

const registry = await readRegistry();

/** The browser languages every page must start under. */
const LOCALES = ['en-US@posix', 'de-DE'] as const;

describe('every registered page', () => {
  let h: Harness;
  beforeAll(async () => {
    h = await Harness.start();
  });
  afterAll(async () => {
    await h?.close();
  });

  it('the registry has at least one game', () => {
    expect(registry.length).toBeGreaterThan(0);
  });

  it('the gallery loads without errors and links every registry entry', async () => {
    const g = await h.open('');
    const links = await g.page.$$eval('#gallery a', (as) => as.map((a) => a.getAttribute('href')));
    expect(links.sort()).toEqual(registry.map((e) => `./${e.folder}/`).sort());
    const titles = await g.page.$$eval('#gallery a h3', (hs) => hs.map((x) => x.textContent));
    expect(titles.sort()).toEqual(registry.map((e) => e.title).sort());
    // Every thumbnail must load (a missing thumbnail.png would show up as an HTTP 404 error).
    await g.page.evaluate(async () => {
      for (const img of Array.from(document.images)) {
        img.loading = 'eager';
        await img.decode();
      }
    });
    expect(g.errors).toEqual([]);
    await g.close();
  });

  for (const entry of registry) for (const locale of LOCALES) {
    it(`${entry.folder} (${locale}): ready, window.game, canvas drawn, no errors`, async () => {
      const g = await h.openGame(entry.folder, { locale });
      expect(await g.page.evaluate(() => navigator.language)).toBe(locale === 'de-DE' ? 'de-DE' : 'en-US');
      const stats = await g.stats();
      expect(Number.isInteger(stats.entities) && stats.entities > 0).toBe(true);
      expect(Number.isInteger(stats.steps) && stats.steps >= 0).toBe(true);
      expect(typeof stats.fps).toBe('number');
      expect(await g.page.evaluate(() => typeof window.game?.paused === 'boolean' && typeof window.game?.world === 'object')).toBe(true);
      // A blank canvas has one colour; a drawn scene has many.
      expect(await g.canvasColors()).toBeGreaterThan(16);
      await g.frames(5);
      expect(await g.page.locator('[data-page-error], [role="alert"]').allInnerTexts()).toEqual([]);
      expect(g.errors).toEqual([]);
      await g.close();
    });
  }
});
