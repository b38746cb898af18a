// `node scripts/frame-times.mjs <folder>[?query] [--size desktop|phone] [--seconds 3]
//   [--action load|reset|key:K|none] [--runs 1] [--profile] [--save DIR] [--url BASE] [--json]`
// (`--help` for usage): opens a game page in headless Chromium and records its animation frames after
// an action: a fresh page load (`load`: the first level as a player first sees it), a fresh world by
// `window.game.reset()`, a key press (the catapult's L: its next level), or nothing. For each run it
// prints the first frame, the worst frame after the first and how many took over 50 ms (issue 36's
// "no frame over 50 ms after the first" for a fresh level), in three measures:
// - main-thread CPU (the default answer): the thread CPU time of the page's main-thread tasks from a
//   frame's start to the next frame's (a trace of the browser, the DevTools protocol's Tracing), GC
//   pauses apart; the first frame's also counts the tasks from the action on (the page's load, or a
//   level built on a key). On a machine shared with other work a frame lasts far longer than the work
//   in it (the page waits for a core, and software WebGL's drawing, SwiftShader in the GPU process,
//   waits for one too): the CPU time is the part that is the page's own;
// - the frame callbacks' wall time (physics steps, scene update and draw calls; measured by wrapping
//   requestAnimationFrame before the page's scripts load), with the physics steps each frame took;
// - the wall time between frames, and the browser's long animation frames after the first (the Long
//   Animation Frames API: frames whose main-thread span, tasks to the end of rendering, passed 50 ms).
// A run in which the page drew fewer than 10 frames (a machine too busy to draw for seconds) is
// flagged and left out of the medians printed after several runs.
// With --profile a CPU profile (the DevTools protocol's Profiler, 0.2 ms samples) runs through each
// recording, and the first frame and the three costliest after it are broken down by where their
// samples fall: the physics' source folders, the game kit, the renderer, pixi.js, bitecs, the game's
// own files (through the site's source maps), the garbage collector, the browser's own work
// ('(program)', '(native)'). A sample is taken while the thread runs or waits (for the GPU process, for
// GC helper threads), so the samples can exceed the frame's CPU time: they say where, the trace says how much.
import { mkdirSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { parseArgs } from 'node:util';
import { launchChromium, readRegistry, startSite } from '../test/browser/chromium.mjs';

const SIZES = {
  desktop: { viewport: { width: 1280, height: 800 }, hasTouch: false, isMobile: false, deviceScaleFactor: 1 },
  phone: { viewport: { width: 390, height: 844 }, hasTouch: true, isMobile: true, deviceScaleFactor: 2 },
};

const USAGE = `usage: node scripts/frame-times.mjs <folder>[?query] [options]
  Records a game page's animation frames after an action and prints their cost.
  --size desktop|phone   1280x800 with a mouse (scale 1), or 390x844 with touch (scale 2) (default desktop)
  --seconds S            how long to record after the action, s of wall time (default 3)
  --action A             'load' (a fresh page in a new browser context each run, recorded from its first
                         frame: the first level as a player first sees it), 'reset' (window.game.reset():
                         a fresh world), 'key:K' (press key K, e.g. key:l for the catapult's next level;
                         successive runs walk through the levels), or 'none' (default reset)
  --runs N               repeat the action N times (on the same page, but for load), integer 1..20 (default 1)
  --profile              also take a CPU profile of each recording and break the first frame and the three
                         costliest after it down by where their time went (source folder, GC, the browser)
  --save DIR             write each run's trace to DIR/<folder>-<size>-<run>.trace.json and, with --profile,
                         its profile to DIR/<folder>-<size>-<run>.cpuprofile (open either in Chrome
                         DevTools' Performance panel)
  --url BASE             pages from a running server (e.g. http://127.0.0.1:8104/, from scripts/serve.mjs)
                         instead of one this script starts
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
      profile: { type: 'boolean' },
      save: { type: 'string' },
      url: { type: 'string' },
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
if (!(action === 'load' || action === 'reset' || action === 'none' || /^key:.+$/.test(action)))
  fail(`--action must be load, reset, none or key:K, got ${action}`);
if (values.url !== undefined && !/^https?:\/\/.+\/$/.test(values.url))
  fail(`--url must be an http(s) address ending in '/', got ${values.url}`);
const [folder, query = ''] = positionals[0].split(/(?=\?)/);
const registry = await readRegistry();
if (!registry.some((e) => e.folder === folder)) fail(`${folder} is not a registered game`);

/** Frames over this took too long (issue 36), ms. */
const LONG_MS = 50;
/** Fewest frames a run must record to be judged (see `tooFew`). */
const MIN_FRAMES = 10;
/** The CPU profile's sampling interval, µs. */
const SAMPLE_US = 200;

/**
 * Runs in the page before its scripts: times every animation-frame callback, grouped by frame, and
 * keeps the long animation frames the browser reports while recording (from the start for `load`).
 */
function recordFrames(recordFromStart) {
  const raf = window.requestAnimationFrame.bind(window);
  const frames = [];
  const loafs = [];
  let current = null;
  window.__frameLog = { frames, loafs, recording: recordFromStart };
  window.requestAnimationFrame = (callback) =>
    raf((time) => {
      const log = window.__frameLog;
      const t0 = performance.now();
      if (log.recording && (current === null || current.time !== time)) {
        current = { time, start: t0, busy: 0, steps: window.game?.world?.steps ?? -1, physics: 0 };
        frames.push(current);
      }
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
  // The time the action's key reached the page (before the page's own handlers: capture on window).
  window.addEventListener(
    'keydown',
    () => {
      const log = window.__frameLog;
      if (log.recording && log.keyAt === undefined) log.keyAt = performance.now();
    },
    true,
  );
  try {
    new PerformanceObserver((list) => {
      if (!window.__frameLog.recording) return;
      for (const e of list.getEntries()) loafs.push({ start: e.startTime, duration: e.duration });
    }).observe({ type: 'long-animation-frame', buffered: true });
  } catch {
    window.__frameLog.noLoaf = true;
  }
}

const round1 = (x) => Math.round(x * 10) / 10;

function median(xs) {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.floor(s.length / 2)] : 0;
}

// --- Source maps: a generated position -> its original source file and line. ---

const B64 = new Map([...'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/'].map((c, i) => [c, i]));

/** Decodes a source map's `mappings` into, per generated line, [column, source, line] triples sorted by column. */
function decodeMappings(map) {
  const lines = [];
  // Sources and lines are deltas from the previous segment's (columns and names are not needed here).
  let source = 0,
    origLine = 0;
  for (const text of map.mappings.split(';')) {
    const segs = [];
    let col = 0;
    if (text)
      for (const seg of text.split(',')) {
        const fields = [];
        let value = 0,
          shift = 0;
        for (const c of seg) {
          const digit = B64.get(c);
          value += (digit & 31) << shift;
          if (digit & 32) shift += 5;
          else {
            fields.push(value & 1 ? -(value >>> 1) : value >>> 1);
            value = 0;
            shift = 0;
          }
        }
        col += fields[0];
        if (fields.length >= 4) {
          source += fields[1];
          origLine += fields[2];
          segs.push([col, source, origLine]);
        }
      }
    lines.push(segs);
  }
  return { sources: map.sources, lines };
}

const maps = new Map();
/** The source map of script `url` (fetched once; null when it has none). */
async function mapOf(url) {
  if (!maps.has(url)) {
    let decoded = null;
    try {
      const res = await fetch(`${url}.map`);
      if (res.ok) decoded = decodeMappings(await res.json());
    } catch {
      decoded = null;
    }
    maps.set(url, decoded);
  }
  return maps.get(url);
}

/** The original 'path:line' of a generated (0-based) line and column of script `url`, or null. */
async function original(url, line, column) {
  const map = await mapOf(url);
  const segs = map?.lines[line];
  if (!segs?.length) return null;
  let lo = 0,
    hi = segs.length - 1;
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (segs[mid][0] <= column) lo = mid;
    else hi = mid - 1;
  }
  const [, source, origLine] = segs[lo];
  return { path: map.sources[source].replace(/^(\.\.\/)+/, ''), line: origLine + 1 };
}

/** The area a source path belongs to, for the breakdown: a physics folder, a package, the game. */
function areaOf(path) {
  let m = /packages\/physics\/src\/([^/]+)\//.exec(path);
  if (m) return `physics/${m[1]}`;
  if (/packages\/physics\/src\//.test(path)) return 'physics';
  m = /packages\/([^/]+)\//.exec(path);
  if (m) return m[1];
  m = /node_modules\/(@[^/]+\/[^/]+|[^/]+)\//.exec(path);
  if (m) return m[1];
  m = /games\/([^/]+)\//.exec(path);
  if (m) return `game ${m[1]}`;
  return path;
}

/**
 * Where a profile's samples fall: `at(t0, t1)` sums the self time (ms) of the samples between page
 * times t0 and t1 (performance.now(), ms) by area and by function ('path:line name').
 * @param profile the Profiler.stop result's profile; offset: page time minus profile time, ms.
 */
async function profileIndex(profile, offset) {
  const nodes = new Map(profile.nodes.map((n) => [n.id, n]));
  const label = new Map();
  for (const n of profile.nodes) {
    const f = n.callFrame;
    let area, fn;
    if (f.url === '' || f.lineNumber < 0) {
      area = f.functionName === '(garbage collector)' ? 'GC' : f.functionName || '(native)';
      fn = area;
    } else {
      const o = await original(f.url, f.lineNumber, f.columnNumber);
      const path = o ? o.path : f.url.replace(/^https?:\/\/[^/]+\//, '');
      area = areaOf(path);
      fn = `${path.replace(/^.*?(packages|games|node_modules)\//, '')}:${o ? o.line : f.lineNumber + 1} ${f.functionName || '(anonymous)'}`;
    }
    label.set(n.id, { area, fn });
  }
  const times = [];
  let t = profile.startTime;
  for (let i = 0; i < profile.samples.length; i++) {
    t += profile.timeDeltas[i];
    times.push(t / 1000 + offset);
  }
  return {
    nodes,
    at(t0, t1) {
      const areas = new Map(),
        fns = new Map();
      for (let i = 0; i < times.length; i++) {
        if (times[i] < t0 || times[i] > t1) continue;
        // A sample stands for one sampling interval of the thread's running time: a thread the machine
        // does not run takes no samples (the profiler's signal waits for it), so on a loaded machine
        // the sums are about the CPU time the frame's work took, not the wall time the frame lasted.
        const dt = SAMPLE_US / 1000;
        const l = label.get(profile.samples[i]);
        if (l.area === '(idle)') continue;
        areas.set(l.area, (areas.get(l.area) ?? 0) + dt);
        fns.set(l.fn, (fns.get(l.fn) ?? 0) + dt);
      }
      const top = (m, n) =>
        [...m]
          .sort((a, b) => b[1] - a[1])
          .slice(0, n)
          .map(([k, v]) => ({ name: k, ms: Math.round(v * 10) / 10 }));
      let cpu = 0;
      for (const v of areas.values()) cpu += v;
      return { sampledMs: Math.round(cpu), areas: top(areas, 8), functions: top(fns, 8) };
    },
  };
}

const site = values.url ? { url: values.url, stop: async () => undefined } : await startSite();
const browser = await launchChromium();
let code = 0;
const errors = [];
const summary = [];

/** A new page on `context` recording frames (from its start when `fromStart`), with page errors collected. */
async function openPage(context, fromStart) {
  const page = await context.newPage();
  page.on('pageerror', (e) => errors.push(e.message));
  await page.addInitScript(recordFrames, fromStart);
  return page;
}

/** Main-thread events the trace keeps: its tasks, GC, and the user-timing mark that dates it. */
const TRACE_CATEGORIES = 'toplevel,devtools.timeline,blink.user_timing';
/** GC pauses on the main thread (the outermost of nested ones count). */
const GC_EVENTS = new Set(['MinorGC', 'MajorGC', 'V8.GC_MC_INCREMENTAL', 'V8.GC_MC_INCREMENTAL_FINALIZE']);

/**
 * The page's main thread in a trace: its tasks' and GC pauses' spans in page time (ms) with their
 * thread CPU time (ms), found through the user-timing mark `__frameTimesTrace` the page set at a
 * known performance.now() time (null when the trace lacks it).
 */
function mainThreadOf(events) {
  const mark = events.find((e) => e.name === '__frameTimesTrace' && e.args?.data?.startTime !== undefined);
  if (!mark) return null;
  const offset = mark.args.data.startTime - mark.ts / 1000;
  const spans = (keep) => {
    const out = [];
    let end = Number.NEGATIVE_INFINITY;
    for (const e of events.filter((x) => x.pid === mark.pid && x.tid === mark.tid && x.ph === 'X' && keep(x)).sort((a, b) => a.ts - b.ts)) {
      if (e.ts < end) continue;
      end = e.ts + (e.dur ?? 0);
      out.push({ t0: e.ts / 1000 + offset, t1: end / 1000 + offset, cpu: (e.tdur ?? e.dur ?? 0) / 1000 });
    }
    return out;
  };
  const tasks = spans((e) => e.name === 'ThreadControllerImpl::RunTask');
  const gcs = spans((e) => GC_EVENTS.has(e.name));
  const sum = (list, t0, t1) => list.reduce((s, x) => (x.t0 >= t0 && x.t0 < t1 ? s + x.cpu : s), 0);
  return {
    /** Page time minus trace time, ms. */
    offset,
    /** Main-thread CPU time (ms) of the tasks that began in [t0, t1), and of the GC pauses in them. */
    cpu: (t0, t1) => ({ cpu: sum(tasks, t0, t1), gc: sum(gcs, t0, t1) }),
  };
}

/**
 * Starts recording on `page`: a trace of the browser (its main thread's tasks with their CPU time)
 * and, with --profile, a CPU profile. `finish()` stops both and returns { main, profile, offset }.
 */
async function startRecording(page) {
  const cdp = await page.context().newCDPSession(page);
  const events = [];
  cdp.on('Tracing.dataCollected', (e) => events.push(...e.value));
  const complete = new Promise((resolve) => cdp.once('Tracing.tracingComplete', resolve));
  await cdp.send('Tracing.start', { categories: TRACE_CATEGORIES, transferMode: 'ReportEvents' });
  if (values.profile) {
    await cdp.send('Profiler.enable');
    await cdp.send('Profiler.setSamplingInterval', { interval: SAMPLE_US });
    await cdp.send('Profiler.start');
  }
  return {
    async finish() {
      await page.evaluate(() => performance.mark('__frameTimesTrace'));
      const profile = values.profile ? (await cdp.send('Profiler.stop')).profile : null;
      await cdp.send('Tracing.end');
      await complete;
      await cdp.detach();
      // The profile's clock is the trace's (µs of the same monotonic clock), so the trace dates both.
      const main = mainThreadOf(events);
      return { main, profile, offset: main ? main.offset : null, events };
    },
  };
}

try {
  let context = null,
    page = null;
  const url = `${site.url}${folder}/${query}`;
  const load = action === 'load';
  if (!load) {
    context = await browser.newContext({ ...size, locale: 'en-US' });
    page = await openPage(context, false);
    await page.goto(url);
    await page.waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 60_000 });
    // Let the page's start settle (its first frames are not the ones measured).
    await page.waitForTimeout(1000);
  }
  for (let run = 0; run < runs; run++) {
    let actionMs = 0,
      profiler = null,
      // Page time the action began (the first frame's CPU counts from here; a fresh page's from its start).
      actionAt = Number.NEGATIVE_INFINITY;
    if (load) {
      context = await browser.newContext({ ...size, locale: 'en-US' });
      page = await openPage(context, true);
      // about:blank first, so that the profile (its session is per page) covers the game page's load.
      await page.goto('about:blank');
      profiler = await startRecording(page);
      await page.goto(url);
      await page.waitForFunction(() => document.body.dataset.ready === 'true', null, { timeout: 60_000 });
    } else {
      profiler = await startRecording(page);
      actionAt = await page.evaluate(() => {
        window.__frameLog.frames.length = 0;
        window.__frameLog.loafs.length = 0;
        window.__frameLog.recording = true;
        window.__frameLog.keyAt = undefined;
        return performance.now();
      });
      if (action === 'reset') {
        const span = await page.evaluate(() => {
          const t0 = performance.now();
          window.game.reset();
          return [t0, performance.now()];
        });
        actionAt = span[0];
        actionMs = span[1] - span[0];
      } else if (action.startsWith('key:')) {
        await page.keyboard.press(action.slice(4));
        // When the page's key handler ran (recorded by recordFrames' keydown listener).
        actionAt = await page.evaluate(() => window.__frameLog.keyAt ?? Number.NEGATIVE_INFINITY);
      }
    }
    await page.waitForTimeout(seconds * 1000);
    const log = await page.evaluate(() => {
      window.__frameLog.recording = false;
      return {
        frames: window.__frameLog.frames.map((f) => ({ ...f })),
        loafs: [...window.__frameLog.loafs],
        noLoaf: !!window.__frameLog.noLoaf,
      };
    });
    const recorded = await profiler.finish();
    const prof = recorded.profile ? recorded : null;
    if (!recorded.main) console.error("frame-times: the trace lacks the page's main thread; no CPU times");
    const level = await page.evaluate(() => {
      try {
        return window.game?.level?.().name ?? '';
      } catch {
        return '';
      }
    });
    const { loafs } = log;
    // A fresh page's frames before the game's shell existed (a library's own frame callbacks) are not
    // its frames; after a key or a reset, the frames that began before the action are the old world's.
    const frames = load
      ? log.frames.slice(
          Math.max(
            0,
            log.frames.findIndex((f) => f.steps >= 0),
          ),
        )
      : log.frames.filter((f) => f.start >= actionAt);
    // steps taken in a frame: the world's step count at the next frame's start minus this one's (a reset
    // in between makes it negative: the new world's count is then the steps).
    const rows = frames.map((f, i) => {
      const next = frames[i + 1];
      const steps = next ? (next.steps >= f.steps ? next.steps - f.steps : next.steps) : 0;
      return { start: f.start, busy: f.busy, gap: i ? f.time - frames[i - 1].time : 0, steps, physics: f.physics };
    });
    const main = recorded.main;
    // Each frame's main-thread CPU: the tasks that began from its start to the next frame's start (the
    // first frame also has the tasks from the action on: the load, or the action's task such as a level
    // built on a key).
    rows.forEach((r, i) => {
      const t0 = i === 0 ? actionAt : r.start,
        t1 = i + 1 < rows.length ? rows[i + 1].start : Number.POSITIVE_INFINITY;
      r.window = [t0, t1];
      const c = main ? main.cpu(t0, t1) : { cpu: Number.NaN, gc: Number.NaN };
      r.cpu = c.cpu;
      r.gc = c.gc;
    });
    // The last frame's window runs on into the script's own calls that end the recording: not counted.
    const later = rows.slice(1, -1);
    const worst = later.reduce((w, r) => (r.busy > w.busy ? r : w), { busy: 0, gap: 0, steps: 0, physics: 0 });
    const byCpu = [...later].sort((x, y) => y.cpu - x.cpu);
    // The first frame's end: a long frame that began by then is the first frame (the load or the
    // action's task and the frame that drew its result).
    const firstEnd = rows[0] ? rows[0].start + rows[0].busy : Number.POSITIVE_INFINITY;
    const long = loafs.filter((l) => l.start > firstEnd && l.duration > LONG_MS);
    if (prof && prof.offset !== null) prof.index = await profileIndex(prof.profile, prof.offset);
    if (values.save) {
      mkdirSync(values.save, { recursive: true });
      const base = join(values.save, `${folder}-${values.size}-${run + 1}`);
      writeFileSync(`${base}.trace.json`, JSON.stringify({ traceEvents: recorded.events }));
      if (prof) writeFileSync(`${base}.cpuprofile`, JSON.stringify(prof.profile));
    }
    const round = (x) => Math.round(x * 10) / 10;
    const describeFrame = (r) => ({
      frame: rows.indexOf(r),
      cpuMs: round(r.cpu),
      gcMs: round(r.gc),
      callbackMs: round(r.busy),
      steps: r.steps,
      ...(prof?.index ? prof.index.at(r.window[0], r.window[1]) : {}),
    });
    const result = {
      folder,
      size: values.size,
      action,
      run: run + 1,
      level,
      frames: rows.length,
      actionMs,
      first: rows[0] ? describeFrame(rows[0]) : null,
      worstCpuAfterFirstMs: round(byCpu[0]?.cpu ?? 0),
      cpuOver50AfterFirst: later.filter((r) => r.cpu > LONG_MS).length,
      costliest: byCpu.slice(0, 3).map(describeFrame),
      worstCallbackAfterFirstMs: round(worst.busy),
      callbackOver50AfterFirst: later.filter((r) => r.busy > LONG_MS).length,
      medianCallbackMs: round(median(later.map((r) => r.busy))),
      medianCpuMs: round(median(later.map((r) => r.cpu))),
      slowestStepMs: round(later.reduce((w, r) => Math.max(w, r.physics), 0)),
      medianGapMs: round(median(later.map((r) => r.gap))),
      worstGapMs: round(later.reduce((w, r) => Math.max(w, r.gap), 0)),
      longFramesAfterFirst: log.noLoaf ? null : long.length,
      worstLongFrameMs: long.length ? Math.round(Math.max(...long.map((l) => l.duration))) : 0,
    };
    // A run whose page drew fewer frames than this (a machine too busy to draw: no animation frames
    // for seconds) says nothing about the frames' cost: flagged, and left out of the medians.
    result.tooFew = rows.length < MIN_FRAMES;
    summary.push(result);
    if (values.json) console.log(JSON.stringify(result));
    else {
      const f = result.first;
      if (result.tooFew)
        console.log(
          `${folder}${query} ${values.size} ${action} run ${run + 1}: only ${rows.length} frames in ${seconds} s (the machine drew too few to judge; left out of the medians)`,
        );
      else
        console.log(
          `${folder}${query} ${values.size} ${action} run ${run + 1}${level ? ` (${level})` : ''}: ${rows.length} frames; main-thread CPU: the first frame ${f?.cpuMs} ms (GC ${f?.gcMs}, ${f?.steps} steps), ` +
            `after it worst ${result.worstCpuAfterFirstMs} ms, median ${result.medianCpuMs}, ${result.cpuOver50AfterFirst} over 50 ms; ` +
            `frame callbacks: first ${f?.callbackMs} ms, after it worst ${result.worstCallbackAfterFirstMs}, median ${result.medianCallbackMs}, ${result.callbackOver50AfterFirst} over 50 ms (slowest step ${result.slowestStepMs}); ` +
            `wall: gaps median ${result.medianGapMs} ms, worst ${result.worstGapMs}; ${result.longFramesAfterFirst ?? '?'} long animation frames after the first (worst ${result.worstLongFrameMs} ms)`,
        );
      const show = (name, d) => {
        console.log(`  ${name} (frame ${d.frame}): CPU ${d.cpuMs} ms, GC ${d.gcMs}, callbacks ${d.callbackMs} ms, ${d.steps} steps`);
        if (d.areas) console.log(`    profile samples ${d.sampledMs} ms: ${d.areas.map((x) => `${x.name} ${x.ms}`).join(', ')}`);
        if (d.functions) console.log(`    functions: ${d.functions.map((x) => `${x.name} ${x.ms}`).join('; ')}`);
      };
      if (prof) {
        if (f) show('first frame', f);
        for (const d of result.costliest) show('costly frame', d);
      }
    }
    if (load) {
      await context.close();
      context = null;
    }
  }
  const judged = summary.filter((r) => !r.tooFew);
  if (!values.json && judged.length > 1) {
    const med = (get) => round1(median(judged.map(get)));
    console.log(
      `median of ${judged.length} runs${judged.length < runs ? ` (${runs - judged.length} with too few frames left out)` : ''}: main-thread CPU of the first frame ${med((r) => r.first?.cpuMs ?? 0)} ms; after it worst ${med((r) => r.worstCpuAfterFirstMs)} ms, ` +
        `${med((r) => r.cpuOver50AfterFirst)} over 50 ms; frame callbacks after the first worst ${med((r) => r.worstCallbackAfterFirstMs)} ms, ${med((r) => r.callbackOver50AfterFirst)} over 50 ms; ` +
        `long animation frames after the first ${med((r) => r.longFramesAfterFirst ?? 0)}`,
    );
  }
  if (context) await context.close();
  if (errors.length) {
    code = 1;
    console.error(`frame-times: page errors:\n  ${errors.join('\n  ')}`);
  }
} catch (error) {
  code = 1;
  console.error(`frame-times: ${error instanceof Error ? error.message : String(error)}`);
} finally {
  await browser.close();
  await site.stop();
}
process.exit(code);
