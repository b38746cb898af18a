/**
 * Lab: galaxy (Ramtal and Dobre ch. 12, "a galaxy"; the N-body method of ch. 6 at scale). The
 * physics package's `galaxy` scene: 100,000 stars in an exponential disc around a nucleus of mass
 * 1,000 (G = 1 units), each on the circular orbit about the mass inside its radius, every body
 * pulling every other through mutual gravity summed by Barnes-Hut (a tree of cells whose far groups
 * act through their multipole expansions, opening angle theta) with Plummer softening eps.
 *
 * Drawn with one pixi ParticleContainer (render-pixi's PointLayer), coloured by speed or by distance
 * from the nucleus. The readout shows the wall-clock cost of a physics step (and of its force stage,
 * the tree) next to the frame rate: raise theta and it falls, lower it and the forces get closer to
 * the direct sum.
 *
 * Time scale: the world's step is dt = timeScale / 60 s of simulated time per 1/60 s of real time,
 * so 2 runs the galaxy twice as fast (with a larger, less accurate step). At most one step runs per
 * frame, so a slow step slows the galaxy down instead of stalling the page.
 *
 * Input: wheel zooms about the pointer, drag pans, C switches the colouring, P pause, N step, R reset.
 * URL: ?count (1-200000 stars), ?theta (0.1-2), ?softening (0.01-5), ?timescale (0.05-4),
 * ?color=speed|radius, ?method=barnes-hut|direct (direct only up to 5000 stars), ?seed, ?threads (1-16:
 * worker threads sharing the integration loop; the page must be cross-origin isolated, as `npm start`
 * serves it; otherwise one thread is used and the readout says why).
 */

import { choiceParam, createPanel, numberParam, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import { createReadout, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { advanceSteps, createStepTimer, fmt } from '@bitphysics/game-kit/particle-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import {
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  galaxy,
  type PhysicsWorld,
  step as physicsStep,
  setGravitation,
  stateHash,
  threadsReady,
} from '@bitphysics/physics';
import { type Point2, PointLayer } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';

/** Real time a step stands for, s: the loop runs one step per 1/60 s; the world's dt is timeScale times it. */
const REAL_STEP = 1 / 60;
/** Most stars the direct O(N^2) sum is allowed for (above it a step takes seconds). */
const DIRECT_LIMIT = 5000;
/** Half-width of the view at start, m (the disc's scale length is 10 m, truncated at 60 m). */
const VIEW_HALF = 42;

/** Colourings: palette and the value range mapped onto it. */
const COLORINGS = {
  speed: { colorBy: 'speed' as const, range: [0, 24] as [number, number], palette: [0xff5a36, 0xffb347, 0xfff4d6, 0x9fc4ff, 0x4d6bff] },
  radius: { colorBy: 'radius' as const, range: [0, 40] as [number, number], palette: [0xfff3c4, 0xffc96b, 0xd9e4ff, 0x7f9cff, 0x4254d6] },
};
type Coloring = keyof typeof COLORINGS;

const USAGE =
  'Accepted: count 1-200000 (integer); theta 0.1-2; softening 0.01-5 m; timescale 0.05-4; color = speed | radius; method = barnes-hut | direct; seed (integer); threads 1-16 (integer).';
/** Whether this page may share memory with workers (SharedArrayBuffer needs cross-origin isolation). */
const ISOLATED = (globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated === true;
const url = readUrlParams(
  () => ({
    count: numberParam('count', { default: 100_000, min: 1, max: 200_000, integer: true }),
    openingAngle: numberParam('theta', { default: 0.5, min: 0.1, max: 2 }),
    softening: numberParam('softening', { default: 0.3, min: 0.01, max: 5 }),
    timeScale: numberParam('timescale', { default: 1, min: 0.05, max: 4 }),
    color: choiceParam('color', ['speed', 'radius'] as const, 'speed') as Coloring,
    method: choiceParam('method', ['barnes-hut', 'direct'] as const, 'barnes-hut') as 'barnes-hut' | 'direct',
    seed: seedParam(),
    threads: numberParam('threads', { default: 1, min: 1, max: 16, integer: true }),
  }),
  USAGE,
);
if (url.method === 'direct' && url.count > DIRECT_LIMIT) {
  readUrlParams(() => {
    throw new RangeError(`URL parameter method=direct needs count <= ${DIRECT_LIMIT}, got ${url.count}`);
  }, USAGE);
}

const params = {
  ...url,
  pointSize: 2,
  reset: () => shell.reset(),
};

let stars: Uint32Array = new Uint32Array(0);
let nucleus = 0;
const timer = createStepTimer();
/** Why the last method change was refused ('' when it was not). */
let notice = '';

/** A fresh world with the galaxy scene from the params (at start, on R and on a new star count). */
let previous: PhysicsWorld | null = null;
function createWorld(): PhysicsWorld {
  // The old world's workers stop with it.
  if (previous !== null) disposeWorld(previous);
  const threads = ISOLATED ? params.threads : 1;
  // More than one thread needs the thread pool, loaded only when asked for.
  if (threads > 1) enableThreads();
  const world = createPhysicsWorld({ ...galaxy.worldOptions({ count: params.count }), dt: params.timeScale * REAL_STEP, threads });
  previous = world;
  const handles = galaxy.build(world, { count: params.count, seed: params.seed, openingAngle: params.openingAngle, method: params.method });
  setGravitation(world, { softening: params.softening });
  stars = handles.stars;
  nucleus = handles.nucleus;
  timer.reset();
  return world;
}

const game = await startPixiGame({
  title: 'Galaxy',
  createWorld,
  step: (world) => timer.run(physicsStep, world),
  bodies: () => stars.length,
  maxStepsPerFrame: 1,
  controls: [
    { keys: 'Wheel', action: 'zoom' },
    { keys: 'Drag', action: 'pan' },
    { keys: 'C', action: 'colour by speed / radius' },
  ],
  keys: [{ key: 'c', label: 'colouring', action: () => setColoring(params.color === 'speed' ? 'radius' : 'speed') }],
  renderer: { view: { minX: -VIEW_HALF, minY: -VIEW_HALF, maxX: VIEW_HALF, maxY: VIEW_HALF }, padding: 8 },
  app: { background: 0x020308 },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;
// The loop's step is real time; the world's dt (simulated time) is timeScale times it.
shell.loop.setTimeStep(REAL_STEP);
shell.onWorldChange(() => shell.loop.setTimeStep(REAL_STEP));

const glow = new Graphics({ label: 'nucleus' });
/** Star opacity for `count` stars: additive dots saturate to white where they pile up, so the more stars the fainter each. */
const starAlpha = (count: number): number => Math.min(0.85, Math.max(0.3, 0.85 * Math.sqrt(20_000 / count)));
const points = new PointLayer({
  entities: () => stars,
  size: params.pointSize,
  blend: 'add',
  alpha: starAlpha(stars.length),
  ...COLORINGS[params.color],
});
shell.onWorldChange(() => points.setAlpha(starAlpha(stars.length)));
renderer.root.addChild(points.container, glow);

/** Colours the stars by speed or by distance from the nucleus (the C key and the panel). */
function setColoring(mode: Coloring): void {
  params.color = mode;
  points.setColoring(COLORINGS[mode]);
  panel?.refresh();
}

/** Applies a summation method; direct is refused above DIRECT_LIMIT stars (the choice goes back). */
function setMethod(method: 'barnes-hut' | 'direct'): void {
  if (method === 'direct' && stars.length > DIRECT_LIMIT) {
    notice = `direct needs <= ${DIRECT_LIMIT} stars`;
    params.method = 'barnes-hut';
    panel.refresh();
    return;
  }
  notice = '';
  params.method = method;
  setGravitation(shell.world, { method });
  timer.reset();
}

/** Sets the time scale: simulated seconds per real second (the world's dt = timeScale / 60 s). */
function setTimeScale(scale: number): void {
  params.timeScale = scale;
  const world = shell.world;
  world.dt = scale * REAL_STEP;
  world.h = world.dt / world.substeps;
}

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'openingAngle',
      label: 'opening angle θ',
      min: 0.1,
      max: 1.5,
      step: 0.01,
      onChange: (t) => {
        setGravitation(shell.world, { openingAngle: t });
        timer.reset();
      },
    },
    {
      type: 'slider',
      key: 'softening',
      label: 'softening ε (m)',
      min: 0.01,
      max: 3,
      step: 0.01,
      onChange: (e) => setGravitation(shell.world, { softening: e }),
    },
    { type: 'slider', key: 'timeScale', label: 'time scale', min: 0.1, max: 4, step: 0.05, onChange: (s) => setTimeScale(s) },
    {
      type: 'slider',
      key: 'count',
      label: 'stars (rebuilds)',
      min: 1000,
      max: 200_000,
      step: 1000,
      onRelease: true,
      onChange: () => {
        if (params.method === 'direct' && params.count > DIRECT_LIMIT) {
          params.method = 'barnes-hut';
          notice = `direct needs <= ${DIRECT_LIMIT} stars`;
        }
        shell.reset();
        panel.refresh();
      },
    },
    {
      type: 'slider',
      key: 'threads',
      label: 'threads (rebuilds)',
      min: 1,
      max: 16,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'choice',
      key: 'method',
      label: 'gravity sum',
      options: ['barnes-hut', 'direct'],
      onChange: (m) => setMethod(m as 'barnes-hut' | 'direct'),
    },
    { type: 'choice', key: 'color', label: 'colour by', options: ['speed', 'radius'], onChange: (m) => setColoring(m as Coloring) },
    { type: 'slider', key: 'pointSize', label: 'star size (px)', min: 1, max: 4, step: 0.5, onChange: (s) => points.setSize(s) },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Galaxy' },
);

const info = createReadout(shell.hud.readout, ['physics step', 'force stage (tree)', 'sim time', 'draw (CPU)', 'gravity', 'threads']);

// ---- Drawing ------------------------------------------------------------------------------------

let frame = 0;
function drawFrame(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  points.render(world, cam, alpha);
  glow.clear();
  const P = world.components.Position,
    O = world.components.PreviousPosition;
  const x = cam.toScreenX(O.x[nucleus]! + (P.x[nucleus]! - O.x[nucleus]!) * alpha);
  const y = cam.toScreenY(O.y[nucleus]! + (P.y[nucleus]! - O.y[nucleus]!) * alpha);
  const r = Math.max(3, cam.toScreenLength(0.6));
  glow.circle(x, y, r * 3).fill({ color: 0xffd9a0, alpha: 0.12 });
  glow.circle(x, y, r * 1.6).fill({ color: 0xffe8c0, alpha: 0.35 });
  glow.circle(x, y, r).fill({ color: 0xffffff });
  if (frame++ % 6 === 0) {
    info.set(0, Number.isNaN(timer.mean) ? '–' : `${fmt(timer.mean)} ms (last ${fmt(timer.last)} ms)`);
    info.set(1, `${fmt(world.timings.forces)} ms`);
    info.set(2, `${fmt(world.time)} s (dt ${fmt(world.dt * 1000)} ms)`);
    info.set(3, `${fmt(points.stats.cpuMs)} ms, ${points.stats.drawn} drawn`);
    info.set(4, notice || `${params.method}, θ ${fmt(world.laws.openingAngle)}, ε ${fmt(world.laws.gravitySoftening)} m`);
    info.set(5, ISOLATED ? `${world.threads} (integration split; tree on one)` : '1 (page not cross-origin isolated)');
  }
}

// ---- Pointer: wheel zooms about the pointer, drag pans ------------------------------------------

const canvas = app.canvas;
const at: Point2 = { x: 0, y: 0 };
let dragId = -1,
  lastX = 0,
  lastY = 0;
canvas.addEventListener(
  'wheel',
  (event) => {
    event.preventDefault();
    const cam = renderer.camera;
    pointerOnCanvas(canvas, event, at);
    const wx = cam.toWorldX(at.x),
      wy = cam.toWorldY(at.y);
    const ppm = Math.min(400, Math.max(1, cam.pixelsPerMeter * Math.exp(-event.deltaY * 0.0015)));
    // Keep the world point under the pointer where it is.
    const cx = wx - (at.x - cam.width / 2) / ppm,
      cy = wy + (at.y - cam.height / 2) / ppm;
    cam.setPixelsPerMeter(ppm, cx, cy);
  },
  { passive: false },
);
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || dragId !== -1) return;
  dragId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  pointerOnCanvas(canvas, event, at);
  lastX = at.x;
  lastY = at.y;
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== dragId) return;
  pointerOnCanvas(canvas, event, at);
  const cam = renderer.camera;
  const ppm = cam.pixelsPerMeter;
  cam.setPixelsPerMeter(ppm, cam.toWorldX(cam.width / 2) - (at.x - lastX) / ppm, cam.toWorldY(cam.height / 2) + (at.y - lastY) / ppm);
  lastX = at.x;
  lastY = at.y;
});
const endDrag = (event: PointerEvent): void => {
  if (event.pointerId === dragId) dragId = -1;
};
canvas.addEventListener('pointerup', endDrag);
canvas.addEventListener('pointercancel', endDrag);

// ---- Test and console hooks on window.game ------------------------------------------------------

shell.expose({
  params,
  panel,
  /** The star layer (its `stats`: points given, drawn, CPU ms of the last frame). */
  points,
  /** Step timing, ms: `mean` (moving average), `last`, `count`. */
  timer,
  /** Number of stars. */
  starCount: (): number => stars.length,
  /** Entity id of the nucleus. */
  nucleus: (): number => nucleus,
  /** Runs `n` (integer >= 0) timed physics steps now. @throws RangeError otherwise. */
  advance: (n: number): void => advanceSteps(n, () => timer.run(physicsStep, shell.world)),
  /** Whether the page is cross-origin isolated (threads > 1 possible). */
  isolated: ISOLATED,
  /** Resolves once the world's worker threads have started (loops run on one thread until then). */
  threadsReady: (): Promise<void> => threadsReady(shell.world),
  /** Loops the world's workers have shared so far (0 with one thread). */
  parallelRuns: (): number => shell.world.threadPool?.runs ?? 0,
  /** Fingerprint of the world's state (stateHash): equal for any thread count after the same steps. */
  stateHash: (): string => stateHash(shell.world),
  /** Why the last change of summation method was refused ('' if it was not). */
  notice: (): string => notice,
  /** Sets the time scale (simulated seconds per real second), in (0, 4]. */
  setTimeScale: (s: number): void => {
    if (!(s > 0 && s <= 4)) throw new RangeError(`setTimeScale: scale must be in (0, 4], got ${s}`);
    setTimeScale(s);
    panel.refresh();
  },
});
