// `node scripts/frame-times.mjs <folder>[?query] [--size desktop|phone] [--seconds 3] [--action reset|key:K|none]
//   [--runs 1] [--json]` (`--help` for usage): opens a game page in headless Chromium, waits for its ready flag,
// then (after the action: a fresh world by `window.game.reset()`, a key press, or nothing) records every
// animation frame for --seconds: the time the page's frame callbacks ran (physics steps, scene update and
// draw calls; measured by wrapping requestAnimationFrame before the page's scripts load), the physics steps
// taken, and the gap since the previous frame. It prints the first frame, the worst frame after the
// first, the median and how many frames took over 50 ms (issue 36's "no frame over 50 ms after the
// first" for a fresh level). Software WebGL (SwiftShader) draws on the CPU, so the gaps include drawing
// that a GPU would take; the callback time is the part the page's own script decides.
import { parseArgs } from 'node:util';
import { launchChromium, readRegistry, startSite } from '../test/browser/chromium.mjs';

const SIZES = {
  desktop: { viewport: { width: 1280, height: 800 }, hasTouch: false, isMobile: false },
  phone: { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true },
};

const USAGE = `usage: node scripts/frame-times.mjs <folder>[?query] [options]
  Records a game page's animation frames after an action and prints their cost.
  --size desktop|phone   1280x800 with a mouse, or 390x844 with touch (default desktop)
  --seconds S            how long to record after the action, s of wall time (default 3)
  --action A             'reset' (window.game.reset(): a fresh world, as a new level), 'key:K' (press key K,
                         e.g. key:l for the catapult's next level), or 'none' (default reset)
  --runs N               repeat the action N times on the same page, integer 1..20 (default 1)
  --json                 print one JSON object per run instead of text
  -h, --help             this text`;

let parsed;
try {
  parsed = parseArgs({
    allowPositionals: true,
    options: {
      size: { type: 'string', default: 'desktop' },
      seconds: { type: 'string', default: '3' },
      action: { type: 'string', default: 'reset' },
      runs: { type: 'string', default: '1' },
      json: { type: 'boolean' },
      help: { type: 'boolean', short: 'h' },
    },
  });
} catch (error) {
  console.error(`frame-times: ${error.message}\n${USAGE}`);
  process.exit(2);
}
const { values, positionals } = parsed;
if (values.help) {
  console.log(USAGE);
  process.exit(0);
}
const fail = (message) => {
  console.error(`frame-times: ${message}\n${USAGE}`);
  process.exit(2);
};
if (positionals.length !== 1) fail(`name exactly one game folder, got ${positionals.length}`);
const size = SIZES[values.size];
if (!size) fail(`--size must be desktop or phone, got ${values.size}`);
const seconds = Number(values.seconds);
if (!(seconds > 0 && seconds <= 120)) fail(`--seconds must be a number in (0, 120], got ${values.seconds}`);
const runs = Number(values.runs);
if (!(Number.isInteger(runs) && runs >= 1 && runs <= 20)) fail(`--runs must be an integer 1..20, got ${values.runs}`);
const action = values.action;
if (!(action === 'reset' || action === 'none' || /^key:.+$/.test(action))) fail(`--action must be reset, none or key:K, got ${action}`);
const [folder, query = ''] = positionals[0].split(/(?=\?)/);
const registry = await readRegistry();
if (!registry.some((e) => e.folder === folder)) fail(`${folder} is not a registered game`);

/** Runs in the page before its scripts: times every animation-frame callback, grouped by frame. */
function recordFrames() {
  const raf = window.requestAnimationFrame.bind(window);
  const frames = [];
  let current = null;
  window.__frameLog = { frames, recording: false };
  window.requestAnimationFrame = (callback) =>
    raf((time) => {
      const log = window.__frameLog;
      if (log.recording && (current === null || current.time !== time)) {
        current = { time, busy: 0, steps: -1, physics: 0 };
        frames.push(current);
        current.steps = window.game?.world?.steps ?? 0;
      }
      const t0 = performance.now();
      try {
        callback(time);
      } finally {
        if (log.recording && current) {
          current.busy += performance.now() - t0;
          // The last step's stage times (world.timings, ms), when this callback stepped the world.
          const world = window.game?.world;
          if (world && world.steps !== current.steps) {
            let sum = 0;
            for (const k in world.timings) sum += world.timings[k];
            current.physics = sum;
          }
        }
      }
    });
}

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : 0;
}

const site = await startSite();
const browser = await launchChromium();
let code = 0;
try {
  const context = await browser.newContext({ ...size, deviceScaleFactor: 1, locale: 'en-US' });
  const page = await context.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(e.message));
  await page.addInitScript(recordFrames);
  await page.goto(`${site.url}${folder}/${query}`);
  await page.waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 60_000 });
  // Let the page's start settle (its first frames are not the ones measured).
  await page.waitForTimeout(1000);
  for (let run = 0; run < runs; run++) {
    await page.evaluate(() => {
      window.__frameLog.frames.length = 0;
      window.__frameLog.recording = true;
    });
    let actionMs = 0;
    if (action === 'reset')
      actionMs = await page.evaluate(() => {
        const t0 = performance.now();
        window.game.reset();
        return performance.now() - t0;
      });
    else if (action.startsWith('key:')) await page.keyboard.press(action.slice(4));
    await page.waitForTimeout(seconds * 1000);
    const frames = await page.evaluate(() => {
      window.__frameLog.recording = false;
      return window.__frameLog.frames.map((f) => ({ ...f }));
    });
    // steps taken in a frame: the world's step count at the next frame's start minus this one's (a reset
    // in between makes it negative: the new world's count is then the steps).
    const rows = frames.map((f, i) => {
      const next = frames[i + 1];
      const steps = next ? (next.steps >= f.steps ? next.steps - f.steps : next.steps) : 0;
      return { busy: f.busy, gap: i ? f.time - frames[i - 1].time : 0, steps, physics: f.physics };
    });
    const later = rows.slice(1);
    const worst = later.reduce((w, r) => (r.busy > w.busy ? r : w), { busy: 0, gap: 0, steps: 0, physics: 0 });
    const result = {
      folder,
      size: values.size,
      action,
      run: run + 1,
      frames: rows.length,
      actionMs,
      worstGapMs: later.reduce((w, r) => Math.max(w, r.gap), 0),
      firstMs: rows[0]?.busy ?? 0,
      worstAfterFirstMs: worst.busy,
      worstAt: later.indexOf(worst) + 1,
      worstSteps: worst.steps,
      worstPhysicsMs: worst.physics,
      maxPhysicsMs: later.reduce((w, r) => Math.max(w, r.physics), 0),
      medianMs: median(later.map((r) => r.busy)),
      over50: later.filter((r) => r.busy > 50).length,
      medianGapMs: median(later.map((r) => r.gap)),
      firstTen: rows.slice(0, 10).map((r) => Math.round(r.busy * 10) / 10),
    };
    if (values.json) console.log(JSON.stringify(result));
    else
      console.log(
        `${folder}${query} ${values.size} ${action} run ${run + 1}: ${action === 'reset' ? `reset ${actionMs.toFixed(1)} ms; ` : ''}${rows.length} frames; callback time first ${result.firstMs.toFixed(1)} ms, ` +
          `worst after the first ${result.worstAfterFirstMs.toFixed(1)} ms (frame ${result.worstAt}: ${worst.steps} steps, last one ${worst.physics.toFixed(1)} ms), median ${result.medianMs.toFixed(1)} ms, ` +
          `${result.over50} over 50 ms; slowest step ${result.maxPhysicsMs.toFixed(1)} ms; gaps median ${result.medianGapMs.toFixed(1)} ms, worst ${result.worstGapMs.toFixed(1)} ms; first ten: ${result.firstTen.join(' ')}`,
      );
  }
  if (errors.length) {
    code = 1;
    console.error(`frame-times: page errors:\n  ${errors.join('\n  ')}`);
  }
  await context.close();
} catch (error) {
  code = 1;
  console.error(`frame-times: ${error instanceof Error ? error.message : String(error)}`);
} finally {
  await browser.close();
  await site.stop();
}
process.exit(code);
