/**
 * The renderers draw everything the physics has: springs (between bodies and to an anchor), joints,
 * planes, field regions (a fluid region, uniform electric and magnetic fields) and emitters, in
 * render-pixi's and render-three's debug layers. The page test/browser/fixtures/scenery.ts builds one
 * world holding each, bundled here from the packages' sources and opened in headless Chromium; the
 * layers must count every entity, and drawing them must change the frame.
 */
import { mkdtempSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import * as esbuild from 'esbuild';
import type { Browser } from 'playwright-core';
import { afterAll, beforeAll, describe, expect, it } from 'vitest';
import { acquireSiteLock, launchChromium, repoRoot } from './chromium.mjs';

let dir = '';
let url = '';
let server: esbuild.BuildContext | null = null;
let browser: Browser | null = null;
let releaseLane: (() => void) | undefined;

beforeAll(async () => {
  // One browser test file at a time (./harness).
  releaseLane = await acquireSiteLock({ name: 'browser-lane', timeoutMs: 590_000 });
  dir = mkdtempSync(join(tmpdir(), 'bitphysics-scenery-'));
  await esbuild.build({
    entryPoints: [join(repoRoot, 'test', 'browser', 'fixtures', 'scenery.ts')],
    outfile: join(dir, 'scenery.js'),
    bundle: true,
    format: 'esm',
    target: 'es2022',
    conditions: ['bitphysics-source'],
    logLevel: 'silent',
  });
  writeFileSync(
    join(dir, 'index.html'),
    '<!doctype html><html><head><meta charset="utf-8"><link rel="icon" href="data:,"></head><body style="margin:0"><script type="module" src="./scenery.js"></script></body></html>',
  );
  server = await esbuild.context({ entryPoints: [], logLevel: 'silent' });
  const { port } = await server.serve({ host: '127.0.0.1', port: 0, servedir: dir });
  url = `http://127.0.0.1:${port}/`;
  browser = await launchChromium();
}, 600_000);

afterAll(async () => {
  try {
    await browser?.close();
    await server?.dispose();
    if (dir) rmSync(dir, { recursive: true, force: true });
  } finally {
    releaseLane?.();
  }
});

async function open(d: 2 | 3) {
  const context = await browser!.newContext({ viewport: { width: 640, height: 400 }, deviceScaleFactor: 1, locale: 'en-US' });
  const page = await context.newPage();
  const errors: string[] = [];
  page.on('console', (m) => {
    if (m.type() === 'error') errors.push(m.text());
  });
  page.on('pageerror', (e) => errors.push(e.message));
  await page.goto(`${url}?d=${d}`);
  try {
    await page.waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 15_000 });
  } catch (error) {
    throw new Error(`the scenery page (d=${d}) did not become ready; its errors: ${JSON.stringify(errors)}; ${String(error)}`);
  }
  return { context, page, errors };
}

describe('debug scenery', () => {
  for (const d of [2, 3] as const) {
    it(`${d === 2 ? 'render-pixi' : 'render-three'} draws springs, ${d === 2 ? 'joints, ' : ''}planes, field regions and emitters`, async () => {
      const { context, page, errors } = await open(d);
      const counts = await page.evaluate(() => window.scenery!.counts());
      // The fixture holds 2 springs, 1 joint (2D only), 1 plane, 1 fluid region + 1 electric + 1 magnetic field, 1 emitter.
      expect(counts).toEqual({ springs: 2, joints: d === 2 ? 1 : 0, planes: 1, fields: 3, emitters: 1 });
      // Drawn: the frame with the scenery differs from the bare one in at least 2000 of its 256 000
      // pixels (two springs, a plane across the view, a glyph grid and a fluid fill: far more than that).
      expect(await page.evaluate(() => window.scenery!.changed())).toBeGreaterThan(2000);
      expect(errors).toEqual([]);
      await context.close();
    }, 60_000);
  }
});
