/**
 * The page contract of every page of the gallery registry (games/<folder>/game.json) in headless
 * Chromium (`checkPageContract`): no console errors, page errors or failed requests; the ready flag;
 * window.game.stats(); a canvas that is not blank; no error box; the layout (./layout-check: the
 * scene's box, the renderer's view rectangle, is inside the canvas and the window, so the world is
 * framed, not cropped; no text or panel covers it; nothing is cut off), WCAG AA contrast of the
 * page's text (./contrast-check), and a screenshot to dist/screenshots/<folder>-<phone|desktop>.png.
 * The gallery itself must list every entry.
 *
 * A page runs as a phone (390 x 844, touch) with the language 'en-US@posix' (what Chromium reports
 * under LANG=C.UTF-8; Intl rejects the tag, and uPlot's module used to throw on it), or on a desktop
 * (1280 x 800) with 'de-DE' (comma decimals): `RUNS`, `contractOptions`.
 *
 * Each page is checked at least one way, on one page load. Where a game's own browser test file
 * already loads the page at a contract size, that file opens it with the contract's locale and calls
 * `checkPageContract` right after the load (`OWN_LOADS`, checked by a case here):
 *   pages.test.ts (its cases are in this file): bouncing-balls (phone), submarine, lab-pendulum (desktop);
 *   catapult.test.ts: catapult (desktop); black-hole.test.ts: black-hole (phone);
 *   labs-cloth-rope.test.ts: lab-rope (phone), lab-cloth (desktop);
 *   particles-games.test.ts: fireworks (desktop); projects.test.ts: flight-simulator, solar-system (desktop);
 *   labs-1.test.ts: lab-integrators, lab-bungee (desktop);
 *   labs-2.test.ts: lab-floating, lab-electric-field, lab-rocket (desktop);
 *   labs-collisions.test.ts: lab-newtons-cradle, lab-molecules (desktop);
 *   particle-labs.test.ts: lab-smoke, lab-fire, lab-sparks (desktop).
 * Every other page gets a load of its own here, phone and desktop alternating down the registry
 * (16 pages: wrecking-ball, earth-moon, balls-3d and rotating-cube, whose own loads turn shadows
 * off, shrink the texture or the ball count, change the mode or run at 800 x 500, and the labs whose
 * own files load them only at 800 x 500 or with a query that changes the scene or the particle
 * count). With BITPHYSICS_PAGES=all every page also runs here each way its own file does not check.
 * These loads are split over three test files (pages.test.ts, pages-2.test.ts, pages-3.test.ts, each
 * calling `describePages` with its shard); the gallery and the phone toolbar are checked by the first.
 */
import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Page } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { repoRoot } from './chromium.mjs';
import { lowContrastText } from './contrast-check';
import { type GamePage, Harness, readRegistry, START_TIMEOUT_MS } from './harness';
import { checkLayout } from './layout-check';

const registry = await readRegistry();

/** A way of running a page for the contract: as a phone or on a desktop. */
export type ContractRun = 'phone' | 'desktop';

/**
 * The two ways a page is checked: a phone (390 x 844 CSS px, touch) under 'en-US@posix', a desktop
 * (1280 x 800 CSS px, mouse) under 'de-DE'. `language` is what navigator.language then reports.
 */
export const RUNS = {
  phone: { name: 'phone', locale: 'en-US@posix', language: 'en-US', viewport: { width: 390, height: 844 }, touch: true },
  desktop: { name: 'desktop', locale: 'de-DE', language: 'de-DE', viewport: { width: 1280, height: 800 }, touch: false },
} as const;

/**
 * The `Harness.open` options of a contract run: its locale, viewport and touch. A game's test file
 * that has the contract checked on its own load opens the page with these (plus its query).
 */
export function contractOptions(run: ContractRun): { locale: string; viewport: { width: number; height: number }; touch: boolean } {
  const r = RUNS[run];
  if (!r) throw new Error(`contractOptions: run must be 'phone' or 'desktop', not ${JSON.stringify(run)}`);
  return { locale: r.locale, viewport: { ...r.viewport }, touch: r.touch };
}

/**
 * The pages whose contract is checked on a load their own test file already makes (it calls
 * `checkPageContract(page, folder, run)` right after that load, before its own interactions), with
 * the way that load runs, its test file and the query it loads with ('' for none; a query that
 * changes neither the page's layout nor its text). This file loads these pages only with
 * BITPHYSICS_PAGES=all, the other way; every other page it loads itself.
 */
export const OWN_LOADS: Readonly<Record<string, { run: ContractRun; file: string; query: string }>> = {
  catapult: { run: 'desktop', file: 'catapult.test.ts', query: 'level=1' },
  'black-hole': { run: 'phone', file: 'black-hole.test.ts', query: 'level=1' },
  fireworks: { run: 'desktop', file: 'particles-games.test.ts', query: 'opening=0&sparks=60&generations=1' },
  submarine: { run: 'desktop', file: 'pages.test.ts', query: '' },
  'flight-simulator': { run: 'desktop', file: 'projects.test.ts', query: '' },
  'bouncing-balls': { run: 'phone', file: 'pages.test.ts', query: '' },
  'solar-system': { run: 'desktop', file: 'projects.test.ts', query: 'rate=0' },
  'lab-rope': { run: 'phone', file: 'labs-cloth-rope.test.ts', query: 'level=1' },
  'lab-cloth': { run: 'desktop', file: 'labs-cloth-rope.test.ts', query: '' },
  'lab-pendulum': { run: 'desktop', file: 'pages.test.ts', query: '' },
  'lab-integrators': { run: 'desktop', file: 'labs-1.test.ts', query: '' },
  'lab-bungee': { run: 'desktop', file: 'labs-1.test.ts', query: '' },
  'lab-floating': { run: 'desktop', file: 'labs-2.test.ts', query: '' },
  'lab-electric-field': { run: 'desktop', file: 'labs-2.test.ts', query: '' },
  'lab-rocket': { run: 'desktop', file: 'labs-2.test.ts', query: '' },
  'lab-newtons-cradle': { run: 'desktop', file: 'labs-collisions.test.ts', query: '' },
  'lab-molecules': { run: 'desktop', file: 'labs-collisions.test.ts', query: '' },
  'lab-smoke': { run: 'desktop', file: 'particle-labs.test.ts', query: '' },
  'lab-fire': { run: 'desktop', file: 'particle-labs.test.ts', query: '' },
  'lab-sparks': { run: 'desktop', file: 'particle-labs.test.ts', query: '' },
};

/**
 * Whether every page runs both ways (environment BITPHYSICS_PAGES=all). By default each page runs one
 * way, phone and desktop alternating down the registry, so both are checked on half the pages each
 * and the suite stays within its time (a page load in software-rendered Chromium takes 2 to 3 s).
 */
const BOTH_RUNS = process.env.BITPHYSICS_PAGES === 'all';

const shots = join(repoRoot, 'dist', 'screenshots');
mkdirSync(shots, { recursive: true });

/**
 * The gallery's cards whose line of text is cut off (its text overflows the paragraph's box, as a
 * clamp to a few lines does): 'folder: w x h in w x h'. Empty when every line is shown whole.
 */
function cutCardLines(page: Page): Promise<string[]> {
  return page.$$eval('#gallery a.card p', (ps) =>
    ps
      .filter((p) => p.scrollWidth > p.clientWidth + 1 || p.scrollHeight > p.clientHeight + 1)
      .map(
        (p) =>
          `${(p.closest('a') as HTMLElement).dataset.folder}: ${p.scrollWidth}x${p.scrollHeight} in ${p.clientWidth}x${p.clientHeight}`,
      ),
  );
}

/**
 * Checks the page contract on `g`, the page of games/`folder`/ just opened with
 * `contractOptions(run)` (and at most a query that changes neither layout nor text): the browser's
 * language, viewport and touch are the run's; window.game answers (stats with whole entity and step
 * counts, `paused`, `world`); the canvas is drawn (more than 8 colours); after three frames of play
 * no error box and no console error, page error or failed request since the load; the layout
 * (./layout-check: nothing covers the scene, nothing is cut off, the world framed to fit, the canvas
 * most of the window) and WCAG AA contrast (./contrast-check); a screenshot to
 * dist/screenshots/<folder>-<run>.png. Call it right after the load, before the test's own input:
 * the layout is the start's, and the errors are counted from the load. The page runs three frames;
 * its pause state is restored at the end.
 * @throws Error (a failed expectation, its message starting 'page contract (<folder>, <run>)') when
 *   the page breaks the contract; Error when `run` is not 'phone' or 'desktop'.
 */
export async function checkPageContract(g: GamePage, folder: string, run: ContractRun): Promise<void> {
  const r = RUNS[run];
  if (!r) throw new Error(`checkPageContract: run must be 'phone' or 'desktop', not ${JSON.stringify(run)}`);
  const what = `page contract (${folder}, ${run})`;
  // Paused while the page is read (it keeps drawing), so that a page whose physics fills its
  // frames (lab-galaxy's thousands of stars) answers each read at once instead of a frame or
  // more later; it runs again for three frames below.
  const pause = (paused: boolean) =>
    g.page.evaluate((p) => {
      window.game!.paused = p;
    }, paused);
  const wasPaused = await g.page.evaluate(() => window.game?.paused === true);
  await pause(true);
  const device = await g.page.evaluate(() => ({
    language: navigator.language,
    width: window.innerWidth,
    height: window.innerHeight,
    touch: navigator.maxTouchPoints > 0,
  }));
  expect(device, `${what}: the browser's language, window and touch`).toEqual({
    language: r.language,
    width: r.viewport.width,
    height: r.viewport.height,
    touch: r.touch,
  });
  const stats = await g.stats();
  expect(Number.isInteger(stats.entities) && stats.entities > 0, `${what}: stats().entities ${stats.entities}`).toBe(true);
  expect(Number.isInteger(stats.steps) && stats.steps >= 0, `${what}: stats().steps ${stats.steps}`).toBe(true);
  expect(typeof stats.fps, `${what}: stats().fps`).toBe('number');
  expect(
    await g.page.evaluate(() => typeof window.game?.paused === 'boolean' && typeof window.game?.world === 'object'),
    `${what}: window.game.paused and .world`,
  ).toBe(true);
  // A blank canvas has one colour (two or three with a frame); a drawn scene has more. Sparse
  // scenes of flat shapes (lab-rigid-bodies' tilting board: two boxes, a board, the frame) draw
  // about a dozen, so the bar is 8.
  expect(await g.canvasColors(), `${what}: colours on the canvas (a blank one has 1 to 3)`).toBeGreaterThan(8);
  await pause(false);
  await g.frames(3);
  await pause(true);
  expect(await g.page.locator('[data-page-error], [role="alert"]').allInnerTexts(), `${what}: error boxes`).toEqual([]);
  expect(g.errors, `${what}: errors since the load`).toEqual([]);
  const layout = await checkLayout(g.page);
  writeFileSync(join(shots, `${folder}-${run}.png`), await g.page.screenshot());
  expect(layout.overlays, `${what}: covering the scene ${JSON.stringify(layout.scene)}`).toEqual([]);
  expect(layout.clipped, `${what}: cut off`).toEqual([]);
  // The page's text is legible: WCAG AA contrast against what is behind it (./contrast-check).
  expect(await lowContrastText(g.page), `${what}: text below 4.5:1 contrast`).toEqual([]);
  // The world is framed to fit: it spans the canvas one way, less the camera's padding (a wide
  // world on a tall phone is letterboxed above and below), and the canvas is most of the window.
  expect(layout.sceneFill, `${what}: how fully the scene spans the canvas`).toBeGreaterThan(0.8);
  const canvas = await g.canvasBox();
  expect(canvas.width * canvas.height, `${what}: the canvas' area, px²`).toBeGreaterThan(0.4 * r.viewport.width * r.viewport.height);
  await pause(wasPaused);
}

/**
 * Defines the page checks of shard `shard` (0-based) of `shards`: page runs number k with
 * k % shards === shard, and, in shard 0, the gallery and the phone toolbar.
 */
export function describePages(shard: number, shards: number): void {
  describe(`every registered page (shard ${shard + 1} of ${shards})`, () => {
    let h: Harness;
    beforeAll(async () => {
      h = await Harness.start();
    }, START_TIMEOUT_MS);
    afterAll(async () => {
      await h?.close();
    });

    if (shard === 0) {
      it('the registry has at least one game', () => {
        expect(registry.length).toBeGreaterThan(0);
      });

      it("every page checked on its own test file's load is in the registry, and that file calls checkPageContract for it that way", () => {
        const folders = registry.map((e) => e.folder);
        const missing: string[] = [];
        for (const [folder, { run, file }] of Object.entries(OWN_LOADS)) {
          if (!folders.includes(folder)) missing.push(`${folder}: not in the registry`);
          // The cases of pages.test.ts are written in this file.
          const source = readFileSync(join(repoRoot, 'test', 'browser', file === 'pages.test.ts' ? 'page-contract.ts' : file), 'utf8');
          // The call names the page and the run, or a helper that calls it is given both on one line.
          const named = source.split('\n').some((line) => line.includes(`'${folder}'`) && line.includes(`'${run}'`));
          if (!source.includes('checkPageContract(') || !named)
            missing.push(`${folder}: no checkPageContract(page, '${folder}', '${run}') in ${file}`);
        }
        expect(missing).toEqual([]);
      });

      it('the gallery loads without errors and links every registry entry', async () => {
        const g = await h.open('');
        // The server's registry (the games its build holds; folders other work adds while the tests run
        // may be newer than this file's list) must hold every game listed when this file started.
        const served = (await (await fetch(`${h.url}registry.json`)).json()) as typeof registry;
        expect(served.map((e) => e.folder)).toEqual(expect.arrayContaining(registry.map((e) => e.folder)));
        const links = await g.page.$$eval('#gallery a', (as) => as.map((a) => a.getAttribute('href')));
        expect(links.sort()).toEqual(served.map((e) => `./${e.folder}/`).sort());
        const titles = await g.page.$$eval('#gallery a h3', (hs) => hs.map((x) => x.textContent));
        expect(titles.sort()).toEqual(served.map((e) => e.title).sort());
        // Every thumbnail must load (a missing thumbnail.png would show up as an HTTP 404 error).
        const undecodable = await g.page.evaluate(async () => {
          const bad: string[] = [];
          for (const img of Array.from(document.images)) {
            img.loading = 'eager';
            await img.decode().catch(() => bad.push(img.src));
          }
          return bad;
        });
        expect(undecodable, 'thumbnails that are not pictures').toEqual([]);
        // Every card shows its whole screenshot: one wider than the card's 16:10 lost its sides under
        // object-fit cover, and the words drawn there ("target A: 67 m ahead, 27 m do…"). The bands
        // round one of another shape take its edge colours (gallery.ts matchEdges), not black bars.
        await g.page.waitForFunction(() =>
          Array.from(document.querySelectorAll<HTMLImageElement>('#gallery a.card img')).every(
            (i) => Math.abs(i.naturalWidth / i.naturalHeight - 1.6) < 0.02 || i.style.background !== '',
          ),
        );
        const cropped = await g.page.$$eval('#gallery a.card img', (imgs) =>
          (imgs as HTMLImageElement[])
            .map((i) => {
              const box = i.getBoundingClientRect();
              const shown =
                getComputedStyle(i).objectFit === 'cover'
                  ? Math.min(box.width / box.height, i.naturalWidth / i.naturalHeight) /
                    Math.max(box.width / box.height, i.naturalWidth / i.naturalHeight)
                  : 1;
              return { src: i.src, shown };
            })
            .filter((x) => x.shown < 0.98),
        );
        expect(cropped, 'thumbnails cropped by their card').toEqual([]);
        expect(await cutCardLines(g.page), 'card lines cut off on a desktop').toEqual([]);
        expect(g.errors).toEqual([]);
        await g.close();
      });

      it('the gallery leads with the games, says what each page lets you do without formulas, and lists two cards a row on a phone', async () => {
        const g = await h.open('', { viewport: { width: 390, height: 844 }, touch: true });
        await g.page.waitForFunction(() => document.body.dataset.ready === 'true');
        const page = await g.page.evaluate(() => {
          const sections = Array.from(document.querySelectorAll('#gallery section')).map((s) => (s as HTMLElement).dataset.category);
          const lines = Array.from(document.querySelectorAll('#gallery a.card p')).map((p) => p.textContent ?? '');
          // Rows of the second grid of games: cards whose tops are level share a row.
          const cards = Array.from(document.querySelectorAll('#gallery section .grid:not(.featured-grid) a.card')).slice(0, 6);
          const tops = new Set(cards.map((c) => Math.round(c.getBoundingClientRect().top)));
          return { sections, lines, cards: cards.length, rows: tops.size, text: document.body.innerText };
        });
        expect(page.sections[0]).toBe('Games');
        // No equations (=, roots, powers, Greek letters, ln) on any card, no developer's note up top.
        expect(page.lines.filter((l) => /[=√²³πθωτμ]|\bln\s*\(/.test(l))).toEqual([]);
        expect(page.text).not.toMatch(/npm run|built from components/);
        expect(page.rows).toBe(Math.ceil(page.cards / 2));
        expect(await cutCardLines(g.page), 'card lines cut off on a phone').toEqual([]);
        expect(g.errors).toEqual([]);
        await g.close();
      });

      it('on a phone the toolbar opens the info and settings drawers, the help shows touch gestures, and its buttons pause and step', async () => {
        const g = await h.openGame('bouncing-balls', contractOptions('phone'));
        await checkPageContract(g, 'bouncing-balls', 'phone');
        const info = g.page.locator('.bp-info');
        const side = g.page.locator('.bp-side');
        expect(await info.isVisible()).toBe(false);
        expect(await side.isVisible()).toBe(false);
        await g.page.getByRole('button', { name: 'information and controls' }).tap();
        expect(await info.isVisible()).toBe(true);
        const help = await g.page.locator('.bp-legend').textContent();
        expect(help).toContain('Tap');
        expect(help).not.toContain('trails on / off'); // a keyboard-only control (T) is left out on touch
        await g.page.getByRole('button', { name: 'parameters and charts' }).tap();
        expect(await side.isVisible()).toBe(true);
        expect(await info.isVisible()).toBe(false);
        expect(await g.page.locator('.bp-side .lil-gui.lil-root').first().isVisible()).toBe(true);
        await g.page.getByRole('button', { name: 'parameters and charts' }).tap();
        expect(await side.isVisible()).toBe(false);
        // Every page's title is read whole beside the six toolbar buttons (the most a page has), which
        // keep their 44 x 44 px and stay in the window: each registry title in turn in this toolbar.
        const toolbar = await g.page.evaluate(
          (titles) => {
            const title = document.querySelector('.bp-title') as HTMLElement;
            const own = title.textContent;
            const bad: string[] = [];
            for (const t of titles) {
              title.textContent = t;
              const buttons = Array.from(document.querySelectorAll('.bp-toolbar button'))
                .map((b) => b.getBoundingClientRect())
                .filter((b) => b.width > 0);
              if (buttons.length !== 6) bad.push(`${t}: ${buttons.length} buttons shown, not 6`);
              if (title.scrollWidth > title.clientWidth + 1 || title.scrollHeight > title.clientHeight + 1)
                bad.push(`${t}: cut off (${title.scrollWidth}x${title.scrollHeight} in ${title.clientWidth}x${title.clientHeight})`);
              const tb = title.getBoundingClientRect();
              for (const b of buttons) {
                if (b.width < 44 || b.height < 44 || b.x < 0 || b.right > window.innerWidth)
                  bad.push(`${t}: a button at ${b.x},${b.y} ${b.width}x${b.height}`);
                if (Math.min(tb.right, b.right) > Math.max(tb.x, b.x) && Math.min(tb.bottom, b.bottom) > Math.max(tb.y, b.y))
                  bad.push(`${t}: under a button`);
              }
            }
            title.textContent = own;
            return bad;
          },
          registry.map((e) => e.title),
        );
        expect(toolbar, 'titles not shown whole in the phone toolbar').toEqual([]);
        await g.page.getByRole('button', { name: 'pause / resume (P)' }).tap();
        expect(await g.page.evaluate(() => window.game!.paused)).toBe(true);
        const steps = (await g.stats()).steps;
        await g.page.getByRole('button', { name: 'single step (N)' }).tap();
        expect((await g.stats()).steps).toBe(steps + 1);
        expect(g.errors).toEqual([]);
        await g.close();
      });

      it('a game page on a desktop keeps its settings in a drawer: the scene takes the width, the toolbar button opens and closes them', async () => {
        const g = await h.openGame('submarine', contractOptions('desktop'));
        await checkPageContract(g, 'submarine', 'desktop');
        const side = g.page.locator('.bp-side');
        const button = g.page.getByRole('button', { name: 'parameters and charts' });
        // Closed at start: nothing right of the scene, which runs from the 220 px info column to the edge.
        expect(await side.isVisible()).toBe(false);
        const stage = await g.page.locator('.bp-stage').boundingBox();
        expect(stage!.x).toBeCloseTo(220, 0);
        expect(stage!.x + stage!.width).toBeCloseTo(1280, 0);
        await button.click();
        expect(await side.isVisible()).toBe(true);
        expect(await g.page.locator('.bp-side .lil-gui.lil-root').first().isVisible()).toBe(true);
        expect(await button.getAttribute('aria-pressed')).toBe('true');
        await button.click();
        expect(await side.isVisible()).toBe(false);
        expect(g.errors).toEqual([]);
        // Closed before the lab opens: a running game beside it slowed the lab's load and contract
        // (its drawn-frame wait and screenshot) on a loaded machine.
        await g.close();
        // A lab keeps its side column open beside the scene.
        const lab = await h.openGame('lab-pendulum', contractOptions('desktop'));
        await checkPageContract(lab, 'lab-pendulum', 'desktop');
        expect(await lab.page.locator('.bp-side').isVisible()).toBe(true);
        expect(await lab.page.getByRole('button', { name: 'parameters and charts' }).isVisible()).toBe(false);
        expect(lab.errors).toEqual([]);
        await lab.close();
        // Two page loads and two contract checks: twice the one-page cases' time (vitest.config.ts testTimeout).
      }, 120_000);
    }

    let k = -1;
    for (const [index, entry] of registry.entries()) {
      const own = OWN_LOADS[entry.folder];
      for (const [r, run] of Object.values(RUNS).entries()) {
        // A page whose own test file checks it one way is loaded here only for the other way, and
        // only with BITPHYSICS_PAGES=all; any other page one way (alternating down the registry), or both.
        if (own ? !BOTH_RUNS || own.run === run.name : !BOTH_RUNS && r !== index % 2) continue;
        if (++k % shards !== shard) continue;
        it(`${entry.folder} (${run.name}, ${run.locale}): ready, window.game, canvas drawn, scene clear and whole, no errors`, async () => {
          const g = await h.openGame(entry.folder, contractOptions(run.name));
          await checkPageContract(g, entry.folder, run.name);
          await g.close();
        });
      }
    }
  });
}
