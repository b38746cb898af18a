// `npm run thumbnails [-- folder[?query] ...] [--seconds 1.5]` (`--help` for usage): opens each registered game (or the
// named folders, each with the URL query given after it, e.g. `black-hole?level=4` for a level with
// more to see; without one, the "thumbnailQuery" of the game's game.json, if any) in headless
// Chromium at 640x400, waits for its ready flag plus 1.5 s of simulated play, and writes a
// screenshot of its canvas (HUD and panels hidden) to games/<folder>/thumbnail.png.
import { readFileSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import { launchChromium, readRegistry, repoRoot, startSite } from '../test/browser/chromium.mjs';

const WIDTH = 640;
const HEIGHT = 400;

const USAGE = `usage: npm run thumbnails -- [folder[?query] ...] [--seconds 1.5]
  Writes games/<folder>/thumbnail.png for each named game (every registered game if none is named):
  the canvas at ${WIDTH}x${HEIGHT} after its ready flag and --seconds of simulated play (default 1.5).
  -h, --help  this text (nothing is written)`;

let parsed;
try {
  parsed = parseArgs({
    allowPositionals: true,
    options: { seconds: { type: 'string', default: '1.5' }, help: { type: 'boolean', short: 'h' } },
  });
} catch (error) {
  console.error(`thumbnails: ${error.message}\n${USAGE}`);
  process.exit(2);
}
if (parsed.values.help) {
  console.log(USAGE);
  process.exit(0);
}
const seconds = Number(parsed.values.seconds);
if (!(seconds >= 0 && Number.isFinite(seconds))) {
  console.error(`thumbnails: --seconds must be a number >= 0, got ${parsed.values.seconds}\n${USAGE}`);
  process.exit(2);
}
const registry = await readRegistry();
const named = parsed.positionals;
const wanted = named.map((a) => a.split('?')[0]);
const queryOf = new Map(named.map((a) => [a.split('?')[0], a.includes('?') ? a.slice(a.indexOf('?')) : '']));
// A game whose time waits for the player (the solar system while aiming) names a query that plays.
for (const { folder } of registry)
  if (!queryOf.get(folder)) {
    const { thumbnailQuery } = JSON.parse(readFileSync(join(repoRoot, 'games', folder, 'game.json'), 'utf8'));
    if (typeof thumbnailQuery === 'string') queryOf.set(folder, thumbnailQuery);
  }
for (const folder of wanted) {
  if (!registry.some((e) => e.folder === folder)) {
    console.error(`${folder} is not a registered game (games/${folder}/ needs main.ts, index.html and game.json)`);
    process.exit(1);
  }
}
const entries = wanted.length ? registry.filter((e) => wanted.includes(e.folder)) : registry;

const site = await startSite();
const browser = await launchChromium();
let failed = false;
try {
  for (const entry of entries) {
    const context = await browser.newContext({ viewport: { width: WIDTH, height: HEIGHT }, deviceScaleFactor: 1, locale: 'en-US' });
    const page = await context.newPage();
    const errors = [];
    page.on('console', (m) => {
      if (m.type() === 'error') errors.push(m.text());
    });
    page.on('pageerror', (e) => errors.push(e.message));
    try {
      await page.goto(`${site.url}${entry.folder}/${queryOf.get(entry.folder) ?? ''}`);
      await page.waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 60_000 });
      // A three.js page draws at half resolution under software WebGL (game-kit SOFTWARE_PIXEL_RATIO),
      // as headless Chromium is: a thumbnail is drawn once, so at full resolution.
      await page.evaluate(() => {
        const renderer = window.game?.app?.renderer;
        if (renderer && typeof renderer.setPixelRatio === 'function' && renderer.getPixelRatio?.() < 1) {
          renderer.setPixelRatio(1);
          window.dispatchEvent(new Event('resize'));
        }
      });
      // Play `seconds` of simulated time (independent of how fast software WebGL draws).
      await page.waitForFunction((s) => (window.game?.world?.time ?? 0) >= s, seconds, { timeout: 120_000 });
      // Hide every overlay but keep the canvas: it sits inside the page layout's stage, so its
      // ancestors stay in the flow (hidden, not removed) and only the canvas is shown.
      await page.addStyleTag({ content: 'body * { visibility: hidden !important; } canvas { visibility: visible !important; }' });
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      const png = await page.locator('canvas').first().screenshot();
      const file = join(repoRoot, 'games', entry.folder, 'thumbnail.png');
      writeFileSync(file, png);
      const kb = statSync(file).size / 1024;
      console.log(`${entry.folder}: ${file} (${kb.toFixed(1)} KB)${kb > 150 ? '  WARNING: larger than 150 KB' : ''}`);
      if (errors.length) {
        failed = true;
        console.error(`${entry.folder}: page errors:\n  ${errors.join('\n  ')}`);
      }
    } catch (error) {
      failed = true;
      console.error(`${entry.folder}: ${error instanceof Error ? error.message : String(error)}`);
    } finally {
      await context.close();
    }
  }
} finally {
  await browser.close();
  await site.stop();
}
process.exit(failed ? 1 : 0);
