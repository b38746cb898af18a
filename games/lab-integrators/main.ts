/**
 * Lab: integrators (Ramtal and Dobre ch. 14). The same Kepler orbit in seven worlds, one per entry
 * of the physics package's INTEGRATOR_NAMES, all from the identical initial state and stepped in
 * lockstep. The orbits are drawn on top of each other in seven colours around the exact ellipse
 * (dashed); the chart shows each scheme's relative energy error |E - E0| / |E0| (package
 * `totalEnergy`) as log10 (the shared plot's log axis labels small values as 0, so the values are
 * logged here and the axis is linear), and the readout its error now and its measured cost per step.
 * A scheme whose step throws (a non-finite state; implicit Euler's Newton iteration failing when it
 * has spiralled into the sun) stops and shows when; the others go on.
 *
 * Panel: time step dt and eccentricity (both rebuild the seven worlds), speed-up (steps of every
 * world per frame step). Keys: P pause, N step, R reset, + / - speed-up.
 * URL: ?dt (0.0005-0.2 s), ?e (0-0.95), ?speedup (1-20).
 */

import { createPanel, numberParam } from '@bitphysics/game-kit';
import { createLabDock, createReadout, drawnPosition, fmt, followView, PathBuffer, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import {
  INTEGRATOR_NAMES,
  INTEGRATOR_ORDER,
  type IntegratorName,
  type PhysicsWorld,
  step as physicsStep,
  totalEnergy,
} from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { conicRadius, type OrbitShape } from '../lab-orbits/exact';
import { createKeplerWorld, GM, type KeplerWorld, PERIOD, PLANET_RADIUS, SEMI_MAJOR_AXIS } from './scene';

/** Colour of each scheme, in INTEGRATOR_NAMES order. */
const COLORS: Readonly<Record<IntegratorName, number>> = Object.freeze({
  'explicit-euler': 0xef476f,
  'semi-implicit-euler': 0xffd166,
  'implicit-euler': 0x06d6a0,
  rk2: 0x4cc9f0,
  rk4: 0xf8f9fa,
  'position-verlet': 0xb388eb,
  'velocity-verlet': 0xff8c42,
});
const css = (c: number): string => `#${c.toString(16).padStart(6, '0')}`;
/** The world the shell (and window.game.world) shows: the most accurate scheme. */
const PRIMARY: IntegratorName = 'rk4';
/** Points kept per drawn orbit path. */
const PATH_POINTS = 720;

const USAGE = 'Accepted: dt 0.0005-0.2 s; e (eccentricity) 0-0.95; speedup 1-20 (integer).';
const url = readUrlParams(
  () => ({
    dt: numberParam('dt', { default: 1 / 60, min: 0.0005, max: 0.2 }),
    eccentricity: numberParam('e', { default: 0.5, min: 0, max: 0.95 }),
    speedUp: numberParam('speedup', { default: 1, min: 1, max: 20, integer: true }),
  }),
  USAGE,
);

const params = { ...url, reset: () => shell.reset() };

/** One scheme's world and measurements. */
interface Run {
  readonly name: IntegratorName;
  kw: KeplerWorld;
  /** Energy at the start, J. */
  e0: number;
  /** |E - E0| / |E0| now. */
  error: number;
  /** Largest error so far. */
  maxError: number;
  /** True once a step threw (non-finite state, Newton failure): the world is no longer stepped. */
  diverged: boolean;
  /** Why it stopped: the error's message ('' while running). */
  reason: string;
  /** Measured cost of a step, microseconds (exponential moving average). */
  cost: number;
  readonly path: PathBuffer;
}

const runs: Run[] = INTEGRATOR_NAMES.map((name) => ({
  name,
  kw: null as unknown as KeplerWorld,
  e0: 0,
  error: 0,
  maxError: 0,
  diverged: false,
  reason: '',
  cost: 0,
  path: new PathBuffer(PATH_POINTS),
}));
const primaryIndex = INTEGRATOR_NAMES.indexOf(PRIMARY);
const view: WorldRect = { minX: -8, minY: -5, maxX: 3, maxY: 5 };
const ellipse = new PathBuffer(361);
const shape: OrbitShape = { a: SEMI_MAJOR_AXIS, e: 0, omega: 0 };

/** Builds the seven worlds from the params and returns the primary one (the shell calls it on start and R). */
function createWorld(): PhysicsWorld {
  for (const run of runs) {
    run.kw = createKeplerWorld({ integrator: run.name, eccentricity: params.eccentricity, dt: params.dt });
    run.e0 = totalEnergy(run.kw.world);
    run.error = 0;
    run.maxError = 0;
    run.diverged = false;
    run.reason = '';
    run.cost = 0;
    run.path.clear();
    const P = run.kw.world.components.Position;
    run.path.push(P.x[run.kw.planet]!, P.y[run.kw.planet]!);
  }
  // The exact orbit: r = a (1 - e^2) / (1 + e cos theta), periapsis on +x (see ../lab-orbits/exact.ts).
  shape.e = params.eccentricity;
  ellipse.clear();
  for (let i = 0; i <= 360; i++) {
    const th = (i / 360) * 2 * Math.PI,
      r = conicRadius(shape, th);
    ellipse.push(r * Math.cos(th), r * Math.sin(th));
  }
  const a = SEMI_MAJOR_AXIS,
    e = params.eccentricity,
    b = a * Math.sqrt(1 - e * e);
  view.minX = -a * (1 + e) - 0.15 * a;
  view.maxX = a * (1 - e) + 0.15 * a;
  view.minY = -b - 0.15 * a;
  view.maxY = b + 0.15 * a;
  refit?.();
  plot?.clear();
  return runs[primaryIndex]!.kw.world;
}

/**
 * One frame step: every live world advances `speedUp` steps (a world that throws, e.g. on a
 * non-finite state, is marked diverged and left alone), then the errors are measured and plotted.
 */
function labStep(): void {
  for (let k = 0; k < params.speedUp; k++) {
    for (let i = 0; i < runs.length; i++) {
      const run = runs[i]!;
      if (run.diverged) continue;
      const t0 = performance.now();
      try {
        physicsStep(run.kw.world);
      } catch (error) {
        run.diverged = true;
        run.reason = error instanceof Error ? error.message : String(error);
        continue;
      }
      const us = (performance.now() - t0) * 1000;
      run.cost = run.cost === 0 ? us : run.cost + 0.02 * (us - run.cost);
    }
  }
  for (let i = 0; i < runs.length; i++) {
    const run = runs[i]!;
    const w = run.kw.world,
      p = run.kw.planet;
    if (run.diverged) {
      run.error = Number.NaN;
      continue;
    }
    run.error = Math.abs((totalEnergy(w) - run.e0) / run.e0);
    if (!(run.error <= run.maxError)) run.maxError = run.error;
    run.path.push(w.components.Position.x[p]!, w.components.Position.y[p]!);
  }
  const r = runs;
  plot?.push(
    r[primaryIndex]!.kw.world.time,
    lg(r[0]!.error),
    lg(r[1]!.error),
    lg(r[2]!.error),
    lg(r[3]!.error),
    lg(r[4]!.error),
    lg(r[5]!.error),
    lg(r[6]!.error),
  );
}

/** log10 of an error for the chart (errors below 1e-16 are rounding: shown at -16; NaN stays a gap). */
function lg(error: number): number {
  return Math.log10(Math.max(error, 1e-16));
}

// ---- Page ------------------------------------------------------------------------------------------

let refit: (() => void) | null = null;
let plot: ReturnType<typeof createPlot> | null = null;

const game = await startPixiGame({
  title: 'Integrators',
  createWorld,
  step: () => labStep(),
  bodies: () => runs.length,
  controls: [{ keys: '+ / −', action: 'speed-up (steps per frame step)' }],
  keys: [
    { key: '+', label: 'faster', action: () => setSpeedUp(params.speedUp + 1) },
    { key: '=', label: 'faster', action: () => setSpeedUp(params.speedUp + 1) },
    { key: '-', label: 'slower', action: () => setSpeedUp(params.speedUp - 1) },
  ],
  renderer: { view, balls: 'sprites', rotation: false },
  onFrame: (alpha) => drawOverlay(alpha),
  maxStepsPerFrame: 4,
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);
const paint = (): void => renderer.setColor(runs[primaryIndex]!.kw.planet, COLORS[PRIMARY]);
paint();
shell.onWorldChange(paint);

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'dt',
      label: 'time step dt (s)',
      min: 0.001,
      max: 0.1,
      step: 0.0005,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'eccentricity',
      label: 'eccentricity',
      min: 0,
      max: 0.95,
      step: 0.01,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'slider', key: 'speedUp', label: 'speed-up (steps/frame step)', min: 1, max: 20, step: 1 },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Integrators', container: dock.panelSlot },
);

/** Sets the speed-up, clamped to [1, 20]. */
function setSpeedUp(n: number): void {
  params.speedUp = Math.max(1, Math.min(20, Math.round(n)));
  panel.refresh();
}

const readout = createReadout(
  shell.hud.readout,
  ['orbits (t / T)', ...INTEGRATOR_NAMES.map((n) => `${n} (order ${INTEGRATOR_ORDER[n]})`)],
  ['', ...INTEGRATOR_NAMES.map((n) => css(COLORS[n]))],
);
plot = createPlot({
  parent: dock.charts,
  title: 'Relative energy error |E − E₀| / |E₀|',
  yLabel: 'log₁₀ error',
  width: dock.chartWidth,
  height: 230,
  capacity: 1200,
  series: INTEGRATOR_NAMES.map((n) => ({ label: n, color: css(COLORS[n]) })),
});

// ---- Drawing ------------------------------------------------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
renderer.root.addChildAt(overlay, 1);
const at: Point2 = { x: 0, y: 0 };

/** The sun, the exact ellipse (dashed), each scheme's path and planet. */
function drawOverlay(alpha: number): void {
  const cam = renderer.camera;
  overlay.clear();
  const sx = cam.toScreenX(0),
    sy = cam.toScreenY(0);
  overlay.circle(sx, sy, Math.max(5, cam.toScreenLength(0.3))).fill({ color: 0xffd166 });
  ellipse.draw(overlay, cam, 1.5, 0xe6e9ef, 0.5, true);
  const r = Math.max(3, cam.toScreenLength(PLANET_RADIUS));
  for (let i = 0; i < runs.length; i++) {
    const run = runs[i]!;
    const color = COLORS[run.name];
    drawnPosition(run.kw.world, run.kw.planet, run.diverged ? 1 : alpha, at);
    run.path.draw(overlay, cam, 1.5, color, 0.75, false, at.x, at.y);
    if (i !== primaryIndex) overlay.circle(cam.toScreenX(at.x), cam.toScreenY(at.y), r).fill({ color });
  }
  updateReadout();
}

let readoutFrame = 0;
/** Refreshes the readout (every 8th frame). */
function updateReadout(): void {
  if (readoutFrame++ % 8 !== 0) return;
  readout.set(0, fmt(runs[primaryIndex]!.kw.world.time / PERIOD, 3));
  for (let i = 0; i < runs.length; i++) {
    const run = runs[i]!;
    readout.set(
      i + 1,
      run.diverged ? `stopped at t = ${fmt(run.kw.world.time, 3)} s` : `${fmt(run.error, 2).padEnd(8)} ${fmt(run.cost, 2)} µs/step`,
    );
  }
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** G M of the sun, m^3/s^2. */
  gm: GM,
  /** A snapshot of every scheme: name, error now and largest, diverged, time, planet position. */
  runs: () =>
    runs.map((r) => {
      const P = r.kw.world.components.Position;
      return {
        name: r.name,
        error: r.error,
        maxError: r.maxError,
        diverged: r.diverged,
        reason: r.reason,
        time: r.kw.world.time,
        steps: r.kw.world.steps,
        x: P.x[r.kw.planet]!,
        y: P.y[r.kw.planet]!,
      };
    }),
  /** Runs `n` (integer >= 0) frame steps now (each `speedUp` steps of every world). @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep();
  },
  setSpeedUp,
});
