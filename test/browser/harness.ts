/**
 * Browser test harness: the run's one built site (scripts/serve.mjs on a free port) and one headless
 * Chromium (SwiftShader WebGL), both started by ./global-setup and shared by every test file (each
 * page in its own browser context), and helpers to open pages, collect their errors, wait
 * for the page contract (`document.body.dataset.ready === 'true'`, `window.game`), read stats, check
 * the canvas is not blank, and send keys, clicks and drags.
 *
 * Every wait has a bound (PAGE_TIMEOUT_MS unless given) and fails with the page's errors and last
 * console lines, so a page that never becomes ready fails in seconds with its reason, not at
 * vitest's hook timeout.
 *
 * Browser test files run one at a time (a cross-process lock taken in `Harness.start`; vitest.config.ts
 * orders them after the headless files); the site is built once a run, or reused from the last run
 * when no source changed since.
 *
 * @example
 * let h: Harness;
 * beforeAll(async () => { h = await Harness.start(); }, START_TIMEOUT_MS);
 * afterAll(async () => { await h?.close(); });
 * it('plays', async () => {
 *   const g = await h.openGame('bouncing-balls', { query: { count: 8 } });
 *   expect((await g.stats()).entities).toBeGreaterThan(0);
 *   expect(await g.canvasColors()).toBeGreaterThan(8);
 *   expect(g.errors).toEqual([]);
 * });
 */

import type { GameStats } from '@bitphysics/game-kit';
import type { Browser, BrowserContext, Page } from 'playwright-core';
import { inject, onTestFinished } from 'vitest';
import { acquireSiteLock, connectChromium, launchChromium, type RegistryEntry, readRegistry, startSite } from './chromium.mjs';
import { decodePng, distinctColors } from './png';

export { type RegistryEntry, readRegistry };

declare module 'vitest' {
  export interface ProvidedContext {
    /** URL of the site served for this run by ./global-setup, ending with '/'. */
    bitphysicsSiteUrl: string;
    /** WebSocket endpoint of the run's shared Chromium (playwright's BrowserServer), from ./global-setup. */
    bitphysicsBrowserWs: string;
  }
}

/** Viewport of pages opened by the harness unless given: small, so software WebGL stays quick. */
export const DEFAULT_VIEWPORT = Object.freeze({ width: 800, height: 500 });

/** `T` without its falsy members: what `GamePage.waitFor` resolves to. */
export type Truthy<T> = Exclude<T, null | undefined | false | 0 | ''>;

/** How `GamePage.runUntil` / `runFrames` run the game's time: its frames, drawn (the default). */
export interface DrawnFrames {
  /** Each of the game's frames its steps and then its drawing (`window.game.loop.runFrames`). Default true. */
  draw?: true;
  /** Game time of each frame, s (>= 0). Default 1/60. */
  seconds?: number;
  /** Unpause a paused game for the frames and pause it again after. Default true; false runs them as its pause has them. */
  unpause?: boolean;
}

/** How `GamePage.runUntil` / `runFrames` run the game's time: its steps (`window.game.step()`), not drawn. */
export interface BareSteps {
  /** Each `window.game.step()`, the N key's single step: the game paused, nothing drawn. */
  draw: false;
  /** Let the game run on afterwards (unpause). Default true; false leaves it paused, as the steps do. */
  resume?: boolean;
}

/** `DrawnFrames` or `BareSteps`. */
export type RunMode = DrawnFrames | BareSteps;

/** When `GamePage.runUntil` gives up. */
export interface RunLimits {
  /** Most frames or steps to run (integer >= 0). Default 3 600 with `draw`, none without. */
  maxFrames?: number;
  /** Most game time to run, s of `window.game.world.time` (> 0). Default none with `draw`, 30 without. */
  maxSeconds?: number;
}

/** Options of `Harness.open` / `Harness.openGame`. */
export interface OpenOptions {
  /** Query string: '?count=8' / 'count=8', or an object ({ count: 8, debug: true }). */
  query?: string | Record<string, string | number | boolean>;
  /** Page size, CSS px. Default DEFAULT_VIEWPORT. */
  viewport?: { width: number; height: number };
  /** Wait for the ready flag before returning. Default true. */
  waitReady?: boolean;
  /** How long to wait for the ready flag, ms. Default 30 000. */
  readyTimeoutMs?: number;
  /**
   * The browser's language (navigator.language, Intl's default locale), e.g. 'de-DE' (comma
   * decimals) or 'en-US@posix' (what Chromium reports under LANG=C.UTF-8, a tag Intl rejects).
   * Default 'en-US'.
   */
  locale?: string;
  /** A touch device (a phone): touch events, `pointer: coarse`, mobile viewport. Default false. */
  touch?: boolean;
}

/**
 * Timeout for the `beforeAll` hook that calls `Harness.start`, ms: a file waits for the browser
 * test file before it to finish (or, without the shared setup, for the site lock's holder). Pass it
 * as beforeAll's second argument; the lock itself gives up 10 s earlier with a message naming the holder.
 */
export const START_TIMEOUT_MS = 600_000;

/** Longest wait for anything the harness asks of a page without a timeout of its own (frames, evaluations), ms. */
export const PAGE_TIMEOUT_MS = 30_000;

/**
 * A page not ready this long after its response whose main thread then does not answer a CDP
 * evaluation within 3 s is stuck: `Harness.open` closes it and opens it once more, in a new context.
 * Seen in headless Chromium 143 with SwiftShader about once in 6 to 20 openings of balls-3d with
 * 3,000 balls right after another WebGL page closed (2026-11-22, load 13 to 20), and in full browser
 * lanes once a run for a 2D page (lab-projectile-drag after earth-moon closed; bouncing-balls with
 * 1,200 balls beside an open one): the new page's main
 * thread waited without end in a synchronous call to the GPU process, whose main thread and
 * VizCompositorThread both sat in condition-variable waits using no CPU (gdb: SwiftShader's queue
 * and worker threads idle) for minutes, past any timeout of the test. The same page opened again in
 * a new context was ready in 0.6 to 4 s (the test's retry, twice). ms.
 */
export const STUCK_MS = 15_000;

/**
 * With the environment variable BITPHYSICS_TEST_LOG=1 the harness prints how long each page took to
 * open and each bounded wait took (one line each, UTC time first), to find where a slow run spends its time.
 */
const LOG = process.env.BITPHYSICS_TEST_LOG === '1';

/**
 * With the environment variable BITPHYSICS_CPU_THROTTLE=<rate> (a number > 1) every page's main thread
 * runs that many times slower (CDP Emulation.setCPUThrottlingRate), to imitate a loaded machine when
 * looking for a case that fails only under load.
 */
const CPU_THROTTLE = Number(process.env.BITPHYSICS_CPU_THROTTLE ?? 1);

function log(line: string): void {
  console.log(`[harness ${new Date().toISOString().slice(11, 23)}] ${line}`);
}

/**
 * Resolves or rejects as `work` does, unless `ms` pass first: then rejects with an Error saying what
 * was awaited (`what`) plus `detail()` (the page's errors), instead of hanging the test until vitest's
 * hook timeout.
 */
export async function withTimeout<T>(work: Promise<T>, ms: number, what: string, detail: () => string): Promise<T> {
  const t0 = Date.now();
  if (LOG)
    work.then(
      () => log(`${what}: ${Date.now() - t0} ms`),
      () => undefined,
    );
  let timer: ReturnType<typeof setTimeout> | undefined;
  const timeout = new Promise<never>((_, reject) => {
    timer = setTimeout(() => reject(new Error(`${what}: no answer in ${ms} ms; ${detail()}`)), ms);
  });
  try {
    return await Promise.race([work, timeout]);
  } finally {
    clearTimeout(timer);
  }
}

function toQuery(query: OpenOptions['query']): string {
  if (query === undefined) return '';
  if (typeof query === 'string') return query === '' ? '' : query.startsWith('?') ? query : `?${query}`;
  const params = new URLSearchParams();
  for (const [k, v] of Object.entries(query)) params.set(k, v === true ? '1' : v === false ? '0' : String(v));
  const text = params.toString();
  return text ? `?${text}` : '';
}

/** One server and one browser, shared by the tests of a file. */
export class Harness {
  /** Base URL of the site, ending with '/'. */
  readonly url: string;
  /** The browser. */
  readonly browser: Browser;
  private readonly stopServer: () => Promise<void>;
  private readonly pages = new Set<GamePage>();

  private constructor(url: string, browser: Browser, stopServer: () => Promise<void>) {
    this.url = url;
    this.browser = browser;
    this.stopServer = stopServer;
  }

  /**
   * Connects to the run's site and browser (started once by ./global-setup for every browser test
   * file), or, when the run has no such setup, builds and serves the site and launches Chromium for
   * this file alone. Call in beforeAll.
   */
  static async start(): Promise<Harness> {
    const url = inject('bitphysicsSiteUrl');
    const ws = inject('bitphysicsBrowserWs');
    if (url && ws) {
      // One browser test file at a time: pages side by side in one software-rendered Chromium ran
      // about four times slower each (the run's headless files use the other workers meanwhile).
      const release = await acquireSiteLock({ name: 'browser-lane', timeoutMs: START_TIMEOUT_MS - 10_000 });
      try {
        return new Harness(url, await connectChromium(ws), async () => release());
      } catch (error) {
        release();
        throw error;
      }
    }
    const site = await startSite({ lockTimeoutMs: START_TIMEOUT_MS - 10_000 });
    try {
      const browser = await launchChromium();
      return new Harness(site.url, browser, site.stop);
    } catch (error) {
      await site.stop();
      throw error;
    }
  }

  /**
   * Opens `path` (relative to the site root, '' for the gallery) in a fresh browser context and,
   * unless `waitReady` is false, waits for the ready flag.
   * @throws Error (with the page's errors) if the ready flag is not set in time.
   */
  async open(path: string, options: OpenOptions = {}): Promise<GamePage> {
    return this.openPage(path, options, true);
  }

  /** `open` without the second try of a stuck page. */
  private openOnce(path: string, options: OpenOptions): Promise<GamePage> {
    return this.openPage(path, options, false);
  }

  private async openPage(path: string, options: OpenOptions, mayRetry: boolean): Promise<GamePage> {
    const t0 = Date.now();
    const where = `opening ${path}${toQuery(options.query)}`;
    // A fixed locale: headless Chromium under LANG=C.UTF-8 reports 'en-US@posix', which Intl (and uPlot) reject.
    const context = await withTimeout(
      this.browser.newContext({
        viewport: options.viewport ?? DEFAULT_VIEWPORT,
        deviceScaleFactor: 1,
        locale: options.locale ?? 'en-US',
        ...(options.touch ? { hasTouch: true, isMobile: true } : {}),
      }),
      PAGE_TIMEOUT_MS,
      `${where}: a new browser context`,
      () => 'the browser did not answer',
    );
    const page = await withTimeout(context.newPage(), PAGE_TIMEOUT_MS, `${where}: a new page`, () => 'the browser did not answer').catch(
      async (error: unknown) => {
        await context.close().catch(() => undefined);
        throw error;
      },
    );
    // Every playwright wait (goto, locators, waitForFunction) gives up with a message after this long.
    page.setDefaultTimeout(PAGE_TIMEOUT_MS);
    if (CPU_THROTTLE > 1) {
      const cdp = await context.newCDPSession(page);
      await cdp.send('Emulation.setCPUThrottlingRate', { rate: CPU_THROTTLE });
    }
    const gp = new GamePage(context, page);
    this.pages.add(gp);
    // A page opened inside a test is closed when that test ends, passed, failed or timed out: a page
    // left running (a failed test skips its own close) would draw on the one software GPU that every
    // later page shares, through the retry and the rest of the file. Pages opened in beforeAll (no
    // current test: onTestFinished throws) stay open until `close`.
    try {
      onTestFinished(() => gp.close());
    } catch {
      /* not inside a test */
    }
    // Only until the response arrives: the ready flag (below) is the page's own "loaded", and a page
    // parsing a large bundle on a busy machine should fail with its errors there, not in goto.
    await page.goto(this.url + path.replace(/^\//, '') + toQuery(options.query), { waitUntil: 'commit' });
    if (LOG) log(`${where}: response after ${Date.now() - t0} ms`);
    if (
      options.waitReady !== false &&
      (await gp.readyOrStuck(options.readyTimeoutMs ?? 30_000, mayRetry ? STUCK_MS : Infinity)) === 'stuck'
    ) {
      // See STUCK_MS: close it and open the page once more, in a new context.
      console.warn(
        `[harness] ${page.url()}: not ready after ${STUCK_MS} ms and its main thread does not answer; closing it and opening it again once`,
      );
      await gp.close();
      this.pages.delete(gp);
      return this.openOnce(path, { ...options, readyTimeoutMs: Math.max(10_000, (options.readyTimeoutMs ?? 30_000) - (Date.now() - t0)) });
    }
    if (LOG) log(`open ${path}${toQuery(options.query)}: ${Date.now() - t0} ms`);
    return gp;
  }

  /** Opens the game in games/<folder>/ (served at /<folder>/). See `open`. */
  openGame(folder: string, options: OpenOptions = {}): Promise<GamePage> {
    return this.open(`${folder}/`, options);
  }

  /** Closes every page and the browser (a shared browser is only disconnected), and a server of this file's own. */
  async close(): Promise<void> {
    for (const p of this.pages) await p.close();
    this.pages.clear();
    try {
      await this.browser.close();
    } finally {
      await this.stopServer();
    }
  }
}

/** A page opened by the harness, with the errors it produced and helpers for the game contract. */
export class GamePage {
  /** The playwright page. */
  readonly page: Page;
  /**
   * Everything that went wrong on the page so far: console errors, uncaught exceptions, and
   * responses with HTTP status >= 400 or failed requests. Tests usually expect it to stay empty.
   */
  readonly errors: string[] = [];
  /** The page's last 40 console lines of any type ('[type] text'), for failure messages. */
  readonly consoleTail: string[] = [];
  private readonly context: BrowserContext;

  /** Wraps `page` (in its own `context`) and starts collecting its errors. Made by `Harness.open`. */
  constructor(context: BrowserContext, page: Page) {
    this.context = context;
    this.page = page;
    page.on('console', (m) => {
      if (m.type() === 'error') this.errors.push(`console.error: ${m.text()}`);
      this.consoleTail.push(`[${m.type()}] ${m.text()}`);
      if (this.consoleTail.length > 40) this.consoleTail.shift();
    });
    page.on('crash', () => this.errors.push('page crashed'));
    page.on('pageerror', (e) => this.errors.push(`page error: ${e.message}`));
    page.on('response', (r) => {
      if (r.status() >= 400) this.errors.push(`HTTP ${r.status()}: ${r.url()}`);
    });
    page.on('requestfailed', (r) => this.errors.push(`request failed: ${r.url()} (${r.failure()?.errorText ?? 'unknown'})`));
  }

  /**
   * Waits until `document.body.dataset.ready === 'true'`.
   * @throws Error naming the page and listing its errors when `timeoutMs` (default 30 000) passes first.
   */
  async waitReady(timeoutMs = 30_000): Promise<void> {
    const outcome = await this.readyOrStuck(timeoutMs, Infinity);
    if (outcome === 'stuck') throw new Error(`${this.page.url()} did not become ready in ${timeoutMs} ms; ${this.describe()}`);
  }

  /**
   * Waits until the ready flag is set ('ready'), or, when `stuckMs` pass without it and the page's
   * main thread then does not answer within 3 s (`snapshot`), gives up at once ('stuck'; see
   * STUCK_MS). The wait is bounded here (a timer in Node), not only by playwright's timeout, which
   * a page whose main thread never returns does not end.
   * @throws Error naming the page and listing its errors when the page shows an error box, or
   *   `timeoutMs` passes while its main thread still answers.
   */
  async readyOrStuck(timeoutMs: number, stuckMs: number): Promise<'ready' | 'stuck'> {
    const started = Date.now();
    // With BITPHYSICS_TEST_LOG=1, every 10 s without the flag: what the page is doing (over CDP, 3 s at most).
    const watch = LOG
      ? setInterval(() => void this.snapshot().then((state) => log(`${this.page.url()} not ready yet: ${state}`)), 10_000)
      : undefined;
    // Ready, or an error box (the page stopped: no point waiting out the timeout).
    const flag = this.page
      .waitForFunction(
        () => {
          if (document.body?.dataset.ready === 'true') return 'ready';
          const box = document.querySelector('[data-page-error], [data-lab="error"], .bp-error');
          return box ? `error box: ${box.textContent ?? ''}` : false;
        },
        null,
        { timeout: timeoutMs, polling: 50 },
      )
      .then(async (handle) => String(await handle.jsonValue()));
    flag.catch(() => undefined); // it may settle after this wait gave up
    try {
      let checked = false;
      for (;;) {
        const left = timeoutMs - (Date.now() - started);
        const next = checked || !Number.isFinite(stuckMs) ? left : Math.min(left, stuckMs - (Date.now() - started));
        let timer: ReturnType<typeof setTimeout> | undefined;
        const outcome = await Promise.race([
          flag,
          new Promise<null>((r) => {
            timer = setTimeout(() => r(null), Math.max(0, next));
          }),
        ]).finally(() => clearTimeout(timer));
        if (outcome === 'ready') return 'ready';
        if (outcome !== null) throw new Error(`${this.page.url()} stopped before it was ready: ${outcome}; ${this.describe()}`);
        if (Date.now() - started >= timeoutMs)
          throw new Error(`${this.page.url()} did not become ready in ${timeoutMs} ms; ${this.describe()}`);
        checked = true;
        const state = await this.snapshot();
        if (state.startsWith('its main thread did not answer')) return 'stuck';
        if (LOG) log(`${this.page.url()} not ready after ${stuckMs} ms but answering: ${state}`);
      }
    } catch (error) {
      if (error instanceof Error && error.message.startsWith(this.page.url())) throw error;
      throw new Error(`${this.page.url()} did not become ready in ${timeoutMs} ms; ${this.describe()}; ${String(error)}`);
    } finally {
      clearInterval(watch);
    }
  }

  /**
   * What the page is doing, for logs: its document state, ready flag, whether window.game exists, the
   * resources it has loaded (name: end time, ms), or that its main thread did not answer in 3 s.
   */
  async snapshot(): Promise<string> {
    try {
      const cdp = await this.context.newCDPSession(this.page);
      try {
        const expression = `JSON.stringify({ state: document.readyState, ready: document.body?.dataset.ready ?? null, game: !!window.game, now: Math.round(performance.now()),
          loaded: performance.getEntriesByType('resource').map((e) => e.name.split('/').pop() + ':' + Math.round(e.responseEnd)).join(' ') })`;
        const answer = cdp.send('Runtime.evaluate', { expression, returnByValue: true }).then((r) => String(r.result.value));
        return await Promise.race([answer, new Promise<string>((r) => setTimeout(() => r('its main thread did not answer in 3 s'), 3000))]);
      } finally {
        void cdp.detach().catch(() => undefined);
      }
    } catch (error) {
      return `no snapshot: ${String(error)}`;
    }
  }

  /** The page's errors and its last console lines, for failure messages. */
  describe(): string {
    return `page errors: ${JSON.stringify(this.errors)}; last console lines: ${JSON.stringify(this.consoleTail.slice(-10))}`;
  }

  /** `page.evaluate(fn, arg)`, failing with the page's errors after `timeoutMs` (default PAGE_TIMEOUT_MS) instead of hanging. */
  evaluate<A, R>(fn: (arg: A) => R | Promise<R>, arg: A, what: string, timeoutMs = PAGE_TIMEOUT_MS): Promise<R> {
    const work = this.page.evaluate(fn as (arg: unknown) => R | Promise<R>, arg as unknown) as Promise<R>;
    return withTimeout(work, timeoutMs, `${this.page.url()}: ${what}`, () => this.describe());
  }

  /**
   * `window.game.stats()`.
   * @throws Error if the page has no window.game, or (with the page's errors) if it does not answer within PAGE_TIMEOUT_MS.
   */
  stats(): Promise<GameStats> {
    return this.evaluate(
      () => {
        if (!window.game) throw new Error('window.game is missing');
        return window.game.stats();
      },
      null,
      'window.game.stats()',
    );
  }

  /**
   * Polls `predicate` in the page (every animation frame) until it returns a truthy value and
   * returns that value. @throws Error (playwright TimeoutError) after `timeoutMs` (default 10 000).
   */
  async waitFor<A, R>(predicate: (arg: A) => R, arg: A, timeoutMs = 10_000): Promise<Truthy<R>> {
    // The predicate is serialised and run in the page; playwright's generic "unboxed" argument type
    // does not line up with a plain generic, hence the widening.
    try {
      const handle = await this.page.waitForFunction(predicate as (arg: unknown) => R, arg as unknown, { timeout: timeoutMs });
      return (await handle.jsonValue()) as Truthy<R>;
    } catch (error) {
      throw new Error(`${this.page.url()}: waitFor(${predicate.toString().slice(0, 120)}) failed; ${this.describe()}; ${String(error)}`);
    }
  }

  /** Waits for `n` (>= 1) animation frames in the page. */
  async frames(n = 1): Promise<void> {
    await this.evaluate(
      async (count) => {
        for (let i = 0; i < count; i++) await new Promise<number>((r) => requestAnimationFrame(r));
      },
      n,
      `waiting for ${n} animation frames`,
    );
  }

  /**
   * Runs `n` (>= 0) of the game's frames, or with `draw: false` its steps, now, in the page, as
   * `runUntil` runs them (see there), with no predicate: all `n` of them.
   */
  async runFrames(n: number, options: RunMode = {}): Promise<void> {
    if (n <= 0) return;
    await this.run(null, null, { ...options, maxFrames: n });
  }

  /**
   * Runs the game's time on now, in the page, one frame or step at a time, until `predicate(arg)`,
   * run in the page (a function of the calling test's own, passed as its source), returns a truthy
   * value, and returns that value (the page as that frame or step left it). `arg` is the one object
   * the predicate may change between calls. Nothing waits for the clock or for the software
   * renderer's frame rate; a key or a finger held meanwhile acts on the steps as in play.
   *
   * With `draw` (the default) each is one of the game's frames as its animation loop runs them
   * (`window.game.loop.runFrames(1, seconds)`, packages/game-kit/src/loop.ts: the steps its
   * `seconds` hold, default 1/60 s, then the drawing), so game time goes by at `seconds` a frame
   * whatever the machine's load, and the predicate is first read after the first frame. With
   * `unpause` (default true) a paused game is unpaused for these frames and paused again after; with
   * `unpause: false` they run as the game's pause has them (paused: drawn only, the camera and labels
   * easing; a game that pauses itself, as for a tip, stops stepping there).
   *
   * With `draw: false` each is `window.game.step()`, the N key's single step (the same step a frame
   * runs, without the drawing): the game is paused first, as the N key pauses it, the predicate is
   * read before the first step and after each, and unless `resume` is false the game runs on
   * afterwards. The HUD and the sprites are drawn from the state on the animation frames after: wait
   * for them (`GamePage.frames`) before reading them.
   *
   * @throws Error naming the predicate, the game time at the start and reached, and the limits, when
   *   it is still falsy after `maxFrames` frames or steps (default 3 600 with `draw`, a minute of game
   *   time; no limit without) or `maxSeconds` of game time (default none with `draw`, 30 s without).
   */
  async runUntil<A, R>(predicate: (arg: A) => R, arg: A, options: RunMode & RunLimits = {}): Promise<Truthy<R>> {
    return (await this.run(predicate.toString(), arg, options)) as Truthy<R>;
  }

  /** `runUntil` with `source` the predicate's source, or `null` for none (then it runs all `maxFrames`). */
  private async run(source: string | null, arg: unknown, options: RunMode & RunLimits): Promise<unknown> {
    const mode =
      options.draw === false
        ? { draw: false, seconds: 0, unpause: false, resume: options.resume ?? true }
        : { draw: true, seconds: options.seconds ?? 1 / 60, unpause: options.unpause ?? true, resume: false };
    const draw = mode.draw;
    const limits = {
      maxFrames: options.maxFrames ?? (draw ? 3600 : null),
      // No predicate: `maxFrames` of them, however much game time that is.
      maxSeconds: source === null ? null : (options.maxSeconds ?? (draw ? null : 30)),
    };
    const out = await this.evaluate(
      ({ source, arg, draw, maxFrames, maxSeconds, seconds, unpause, resume }) => {
        const game = window.game as unknown as {
          paused: boolean;
          step(): void;
          world: { time: number };
          loop: { runFrames(n: number, s?: number): void };
        };
        const test = source === null ? null : (new Function(`return (${source});`)() as (a: unknown) => unknown);
        const start = game.world.time;
        const end = start + (maxSeconds ?? Number.POSITIVE_INFINITY);
        const most = maxFrames ?? Number.POSITIVE_INFINITY;
        const repause = draw && unpause && game.paused;
        if (repause) game.paused = false;
        if (!draw) game.paused = true;
        let value: unknown = !draw && test ? test(arg) : null;
        let frames = 0;
        try {
          while (!value && frames < most && game.world.time < end) {
            if (draw) game.loop.runFrames(1, seconds);
            else game.step();
            frames++;
            if (test) value = test(arg);
          }
        } finally {
          if (repause) game.paused = true;
          if (!draw && resume) game.paused = false;
        }
        return { ok: test === null || !!value, value, start, time: game.world.time, frames };
      },
      {
        source,
        arg,
        ...mode,
        ...limits,
      },
      `${draw ? 'running frames' : 'stepping the game'} ${source === null ? `${limits.maxFrames} times` : `until ${source.slice(0, 80)}`}`,
    );
    if (!out.ok) {
      const most = [
        limits.maxFrames === null ? '' : `${limits.maxFrames} ${draw ? 'frames' : 'steps'}`,
        limits.maxSeconds === null ? '' : `${limits.maxSeconds} s of game time`,
      ];
      throw new Error(
        `${this.page.url()}: runUntil(${source}) still falsy after ${out.frames} ${draw ? 'frames' : 'steps'} (at most ${most.filter(Boolean).join(' or ')}), game time ${out.start} s to ${out.time} s; ${this.describe()}`,
      );
    }
    return out.value;
  }

  /**
   * Distinct colours (RGB) drawn on the first canvas matching `selector` (default 'canvas'): 1 for a
   * blank canvas, hundreds for a drawn scene. Reads the canvas in the page right after the game's
   * next animation frame (drawImage onto a 2D canvas: fast; for a game with a frame pacer, its next
   * frame that drew, see packages/game-kit/src/frame-pacer.ts); if that comes back blank or nearly (at
   * most 3 colours: a canvas not drawn from requestAnimationFrame, whose buffer was already presented,
   * or a buffer read mid-frame on a loaded machine, which gave lab-fire's scene 3 colours once in a
   * clean-clone CI) it falls back to an element screenshot, decoded in Node, which always shows what
   * is on screen.
   * @throws Error if there is no such canvas.
   */
  async canvasColors(selector = 'canvas'): Promise<number> {
    const inPage = await this.evaluate(
      async (sel: string) => {
        const canvas = document.querySelector(sel);
        if (!(canvas instanceof HTMLCanvasElement)) throw new Error(`no canvas matches ${sel}`);
        // A game paces its frames to the GPU (packages/game-kit/src/frame-pacer.ts): an animation frame in which
        // it drew nothing leaves a presented, blank buffer to read. Its pacer counts drawn frames, so
        // wait (20 s at most) for an animation frame in which the count moved: the game's callback,
        // requested earlier, runs before this one in the same frame.
        const drawn = (): number | undefined => (window.game as unknown as { pacer?: { drawn?: number } } | undefined)?.pacer?.drawn;
        let last = drawn();
        const until = performance.now() + 20_000;
        for (;;) {
          await new Promise<number>((r) => requestAnimationFrame(r));
          const now = drawn();
          if (now === undefined || now !== last || performance.now() > until) break;
          last = now;
        }
        const w = canvas.width,
          h = canvas.height;
        const copy = new OffscreenCanvas(w, h).getContext('2d');
        if (!copy || w === 0 || h === 0) return 0;
        copy.drawImage(canvas, 0, 0);
        const data = copy.getImageData(0, 0, w, h).data;
        const seen = new Set<number>();
        for (let i = 0; i < data.length; i += 4) seen.add((data[i]! << 16) | (data[i + 1]! << 8) | data[i + 2]!);
        return seen.size;
      },
      selector,
      `reading the colours of ${selector}`,
    );
    if (inPage > 3) return inPage;
    return this.screenshotColors(selector);
  }

  /**
   * Distinct colours in an element screenshot of the first element matching `selector`, taken with
   * every other element hidden (so HUD text drawn over a blank canvas cannot pass for a scene).
   */
  async screenshotColors(selector = 'canvas'): Promise<number> {
    const target = this.page.locator(selector).first();
    await target.evaluate((el) => {
      el.setAttribute('data-harness-shot', '');
      const style = document.createElement('style');
      style.id = 'harness-shot-style';
      style.textContent = '* { visibility: hidden !important; } [data-harness-shot] { visibility: visible !important; }';
      document.head.append(style);
    });
    try {
      return distinctColors(decodePng(await target.screenshot()));
    } finally {
      await target.evaluate((el) => {
        el.removeAttribute('data-harness-shot');
        document.getElementById('harness-shot-style')?.remove();
      });
    }
  }

  /** Presses `key` (a playwright key name: 'p', 'N', 'Space'). */
  async press(key: string): Promise<void> {
    await this.page.keyboard.press(key);
  }

  /** The canvas' box in CSS px. @throws Error if there is no visible canvas. */
  async canvasBox(selector = 'canvas'): Promise<{ x: number; y: number; width: number; height: number }> {
    const box = await this.page.locator(selector).first().boundingBox();
    if (!box) throw new Error(`no visible ${selector} on ${this.page.url()}`);
    return box;
  }

  /** Clicks the canvas at fractions (fx, fy) of its width and height (0.5, 0.5 is the centre). */
  async clickCanvas(fx = 0.5, fy = 0.5): Promise<void> {
    const b = await this.canvasBox();
    await this.page.mouse.click(b.x + b.width * fx, b.y + b.height * fy);
  }

  /**
   * Page position (CSS px) of world point (x, y), m, through the 2D renderer's camera
   * (`window.game.renderer.camera`, whose screen is the canvas) and the canvas' place on the page.
   * @throws Error if the page has no such camera or no visible canvas.
   */
  async worldToPage(x: number, y: number): Promise<{ x: number; y: number }> {
    const box = await this.canvasBox();
    const s = await this.page.evaluate(
      ([wx, wy]) => {
        const cam = (window.game as unknown as { renderer?: { camera?: { toScreenX(v: number): number; toScreenY(v: number): number } } })
          .renderer?.camera;
        if (!cam) throw new Error('window.game.renderer.camera is missing');
        return { x: cam.toScreenX(wx!), y: cam.toScreenY(wy!) };
      },
      [x, y],
    );
    return { x: box.x + s.x, y: box.y + s.y };
  }

  /** Clicks world point (x, y), m (see `worldToPage`). */
  async clickWorld(x: number, y: number): Promise<void> {
    const p = await this.worldToPage(x, y);
    await this.page.mouse.click(p.x, p.y);
  }

  /** Drags on the canvas from fractions `from` to `to` in `steps` mouse moves (>= 1). */
  async dragCanvas(from: [number, number], to: [number, number], steps = 8): Promise<void> {
    const b = await this.canvasBox();
    const m = this.page.mouse;
    await m.move(b.x + b.width * from[0], b.y + b.height * from[1]);
    await m.down();
    await m.move(b.x + b.width * to[0], b.y + b.height * to[1], { steps });
    await m.up();
  }

  /** Closes the page and its context. */
  async close(): Promise<void> {
    await this.context.close().catch(() => undefined);
  }
}
