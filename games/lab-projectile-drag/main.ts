/**
 * Lab: projectile with drag (Ramtal and Dobre ch. 7). A ball leaves a cliff edge at an angle with
 * no drag, linear drag (F = -k v) or quadratic drag (F = -k |v| v); the physics package's
 * LinearDrag / QuadraticDrag components and the world's integrator move it. The charts compare its
 * height and vertical velocity with the exact solutions (exact.ts): the parabola without drag, the
 * closed form with linear drag, and, since quadratic drag has no closed form, the terminal velocity
 * -sqrt(m g / k) as a line. Earlier flights stay on screen, faded, for comparison.
 *
 * Input: click sets the launch direction (and launches), Space launches again, C clears old paths.
 * Keys: P pause, N single step, R reset (relaunch).
 * URL: ?law=none|linear|quadratic, ?k (coefficient of that law), ?speed, ?angle, ?mass, ?height,
 * ?g, ?integrator. Bad values stop the page with a message naming the parameter.
 */

import { choiceParam, createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import {
  createLabDock,
  createReadout,
  drawDashedLine,
  drawnPosition,
  fmt,
  followView,
  PathBuffer,
  readUrlParams,
} from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import {
  contactCount,
  createPhysicsWorld,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  step as physicsStep,
} from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { type KinematicState, type Launch, linearDragState, linearTerminalSpeed, noDragState, quadraticTerminalSpeed } from './exact';
import {
  BALL_RADIUS,
  buildProjectile,
  DRAG_LAWS,
  type DragLaw,
  PROJECTILE_DEFAULTS,
  PROJECTILE_RANGES,
  type ProjectileHandles,
  type ProjectileOptions,
  projectileWorldOptions,
} from './scene';

/** Colour of each drag law's path and ball. */
const LAW_COLOR: Record<DragLaw, number> = { none: 0x8ecae6, linear: 0xffb703, quadratic: 0xfb5607 };
/** Flights kept on screen (the current one and the faded earlier ones). */
const KEPT_PATHS = 4;
/** Longest flight recorded, s (at 60 steps/s). */
const MAX_FLIGHT = 40;

const USAGE =
  'Accepted: law = none | linear | quadratic; k = drag coefficient of that law (linear 0-50 N s/m, quadratic 0-5 kg/m); ' +
  `speed 0-100 m/s; angle -90-180 deg; mass 0.01-100 kg; height 1-100 m; g 0.1-50 m/s²; integrator = ${INTEGRATOR_NAMES.join(' | ')}.`;

const url = readUrlParams(() => {
  const law = choiceParam('law', DRAG_LAWS, PROJECTILE_DEFAULTS.law);
  const kMax = law === 'quadratic' ? PROJECTILE_RANGES.quadraticK[1] : PROJECTILE_RANGES.linearK[1];
  const k = numberParam('k', {
    default: law === 'quadratic' ? PROJECTILE_DEFAULTS.quadraticK : PROJECTILE_DEFAULTS.linearK,
    min: 0,
    max: kMax,
  });
  const range = (name: string, key: keyof typeof PROJECTILE_RANGES, fallback: number) =>
    numberParam(name, { default: fallback, min: PROJECTILE_RANGES[key][0], max: PROJECTILE_RANGES[key][1] });
  return {
    law,
    linearK: law === 'linear' ? k : PROJECTILE_DEFAULTS.linearK,
    quadraticK: law === 'quadratic' ? k : PROJECTILE_DEFAULTS.quadraticK,
    speed: range('speed', 'speed', PROJECTILE_DEFAULTS.speed),
    angle: range('angle', 'angle', PROJECTILE_DEFAULTS.angle),
    mass: range('mass', 'mass', PROJECTILE_DEFAULTS.mass),
    height: range('height', 'height', PROJECTILE_DEFAULTS.height),
    gravity: range('g', 'gravity', PROJECTILE_DEFAULTS.gravity),
    integrator: choiceParam('integrator', INTEGRATOR_NAMES, PROJECTILE_DEFAULTS.integrator),
  };
}, USAGE);

const params = {
  ...url,
  launch: () => shell.reset(),
  clearPaths: () => clearOldPaths(),
};

/** The scene options from the current params. */
function sceneOptions(): ProjectileOptions {
  const { law, linearK, quadraticK, speed, angle, mass, height, gravity, integrator } = params;
  return { law, linearK, quadraticK, speed, angle, mass, height, gravity, integrator: integrator as IntegratorName };
}

// ---- Flight state (one flight per world) --------------------------------------------------------

const paths = Array.from({ length: KEPT_PATHS }, () => new PathBuffer(MAX_FLIGHT * 60));
const pathLaw: DragLaw[] = Array.from({ length: KEPT_PATHS }, () => 'none' as DragLaw);
let current = 0;
const exactPath = new PathBuffer(MAX_FLIGHT * 60);
const launch: Launch = { x0: 0, y0: 0, vx0: 0, vy0: 0, g: 9.81 };
const exact: KinematicState = { x: 0, y: 0, vx: 0, vy: 0 };
/** Measurements of the current flight. */
const flight = {
  /** Still in the air (no contact yet). */
  flying: true,
  /** Time of flight, s (NaN while flying). */
  landedTime: Number.NaN,
  /** Horizontal distance from launch to landing, m (NaN while flying). */
  range: Number.NaN,
  /** Largest |y - y_exact| so far, m (NaN for quadratic drag, which has no exact curve). */
  maxDeviation: 0,
  /** Fastest downward speed reached, m/s. */
  maxFallSpeed: 0,
  /** Samples recorded. */
  samples: 0,
};
/** World rectangle the camera shows for this flight, m. */
const view: WorldRect = { minX: -5, minY: -1, maxX: 40, maxY: 20 };
let handles: ProjectileHandles;

/** The exact state at time t for the current law into `exact`; false when there is none (quadratic drag). */
function exactAt(t: number): boolean {
  const p = handles.params;
  if (p.law === 'none') {
    noDragState(launch, t, exact);
    return true;
  }
  if (p.law === 'linear') {
    linearDragState(launch, p.mass, p.linearK, t, exact);
    return true;
  }
  return false;
}

/** Terminal speed of the current law, m/s (NaN without drag). */
function terminalSpeed(): number {
  const p = handles.params;
  if (p.law === 'linear') return linearTerminalSpeed(p.mass, p.gravity, p.linearK);
  if (p.law === 'quadratic') return quadraticTerminalSpeed(p.mass, p.gravity, p.quadraticK);
  return Number.NaN;
}

/**
 * Fits the view to this flight: a scratch world with the same scene is stepped until the ball
 * lands (at most MAX_FLIGHT s), and the box around its path (and the cliff edge) is shown.
 */
function fitFlightView(): void {
  const w = createPhysicsWorld(projectileWorldOptions(sceneOptions()));
  const h = buildProjectile(w, sceneOptions());
  const P = w.components.Position;
  let minX = -4,
    maxX = 4,
    minY = 0,
    maxY = h.y0 + 1;
  for (let i = 0; i < MAX_FLIGHT * 60; i++) {
    physicsStep(w);
    const x = P.x[h.ball]!,
      y = P.y[h.ball]!;
    if (x < minX) minX = x;
    if (x > maxX) maxX = x;
    if (y > maxY) maxY = y;
    if (y < minY) minY = y;
    if (contactCount(w) > 0) break;
  }
  const wx = maxX - minX,
    wy = maxY - minY;
  view.minX = minX - 0.08 * wx;
  view.maxX = maxX + 0.08 * wx;
  view.minY = minY - 0.05 * wy - 0.5;
  view.maxY = maxY + 0.1 * wy + 0.5;
}

/** Builds a fresh world (a new launch) from the params; the shell calls it at start and on R. */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(projectileWorldOptions(sceneOptions()));
  handles = buildProjectile(world, sceneOptions());
  launch.x0 = handles.x0;
  launch.y0 = handles.y0;
  launch.vx0 = handles.vx0;
  launch.vy0 = handles.vy0;
  launch.g = handles.params.gravity;
  flight.flying = true;
  flight.landedTime = Number.NaN;
  flight.range = Number.NaN;
  flight.maxDeviation = handles.params.law === 'quadratic' ? Number.NaN : 0;
  flight.maxFallSpeed = 0;
  flight.samples = 0;
  // The previous flight becomes a faded path; this one starts empty.
  if (paths[current]!.count > 0) current = (current + 1) % KEPT_PATHS;
  paths[current]!.clear();
  pathLaw[current] = handles.params.law;
  paths[current]!.push(handles.x0, handles.y0);
  exactPath.clear();
  if (exactAt(0)) {
    for (let i = 0; i <= MAX_FLIGHT * 60; i++) {
      exactAt(i / 60);
      exactPath.push(exact.x, exact.y);
      if (exact.y < BALL_RADIUS && i > 0) break;
    }
  }
  fitFlightView();
  refit?.();
  plots?.height.clear();
  plots?.velocity.clear();
  return world;
}

/** One step: physics, then the measurements (path, deviation from the exact curve, landing). */
function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  const e = handles.ball;
  const x = world.components.Position.x[e]!,
    y = world.components.Position.y[e]!,
    vy = world.components.Velocity.y[e]!;
  const t = world.time;
  if (t <= MAX_FLIGHT) paths[current]!.push(x, y);
  if (!flight.flying) return;
  flight.samples++;
  if (-vy > flight.maxFallSpeed) flight.maxFallSpeed = -vy;
  const hasExact = exactAt(t);
  if (hasExact) flight.maxDeviation = Math.max(flight.maxDeviation, Math.abs(y - exact.y));
  const vt = terminalSpeed();
  plots?.height.push(t, y, hasExact ? exact.y : Number.NaN);
  plots?.velocity.push(t, vy, hasExact ? exact.vy : Number.NaN, Number.isFinite(vt) ? -vt : Number.NaN);
  if (contactCount(world) > 0) {
    flight.flying = false;
    flight.landedTime = t;
    flight.range = x - handles.x0;
    plots?.height.redraw();
    plots?.velocity.redraw();
  }
}

// ---- Page ------------------------------------------------------------------------------------------

let refit: (() => void) | null = null;
let plots: { height: ReturnType<typeof createPlot>; velocity: ReturnType<typeof createPlot> } | null = null;

const game = await startPixiGame({
  title: 'Projectile with drag',
  createWorld,
  step: labStep,
  bodies: () => 1,
  controls: [
    { keys: 'Click', action: 'aim: sets the launch direction, launches' },
    { keys: 'Space', action: 'launch again' },
    { keys: 'C', action: 'clear old paths' },
  ],
  keys: [
    { key: ' ', label: 'launch', action: () => shell.reset() },
    { key: 'c', label: 'clear paths', action: () => clearOldPaths() },
  ],
  renderer: { view, balls: 'sprites' },
  onFrame: (alpha, world) => drawOverlay(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);

const relaunch = (): void => shell.reset();
const panel = createPanel(
  params,
  [
    { type: 'choice', key: 'law', label: 'drag law', options: DRAG_LAWS, onChange: relaunch },
    { type: 'slider', key: 'linearK', label: 'linear k (N s/m)', min: 0, max: 5, step: 0.01, onRelease: true, onChange: relaunch },
    { type: 'slider', key: 'quadraticK', label: 'quadratic k (kg/m)', min: 0, max: 0.5, step: 0.001, onRelease: true, onChange: relaunch },
    { type: 'slider', key: 'speed', label: 'launch speed (m/s)', min: 0, max: 60, step: 0.1, onRelease: true, onChange: relaunch },
    { type: 'slider', key: 'angle', label: 'angle (°)', min: -90, max: 180, step: 0.5, onRelease: true, onChange: relaunch },
    { type: 'slider', key: 'mass', label: 'mass (kg)', min: 0.05, max: 20, step: 0.01, onRelease: true, onChange: relaunch },
    { type: 'slider', key: 'height', label: 'launch height (m)', min: 1, max: 60, step: 0.5, onRelease: true, onChange: relaunch },
    { type: 'slider', key: 'gravity', label: 'gravity (m/s²)', min: 0.5, max: 30, step: 0.01, onRelease: true, onChange: relaunch },
    { type: 'choice', key: 'integrator', options: INTEGRATOR_NAMES, onChange: relaunch },
    { type: 'button', key: 'launch', label: 'launch (Space)' },
    { type: 'button', key: 'clearPaths', label: 'clear old paths (C)' },
  ],
  { title: 'Projectile', container: dock.panelSlot },
);

const readout = createReadout(shell.hud.readout, ['terminal speed v_t', 'time of flight', 'range', 'max |y − y_exact|', 'fastest fall']);
plots = {
  height: createPlot({
    parent: dock.charts,
    title: 'Height',
    yLabel: 'y (m)',
    width: dock.chartWidth,
    height: 150,
    capacity: MAX_FLIGHT * 60,
    series: [
      { label: 'simulated', color: '#ffb703' },
      { label: 'exact', color: '#e6e9ef', dashed: true },
    ],
  }),
  velocity: createPlot({
    parent: dock.charts,
    title: 'Vertical velocity',
    yLabel: 'v_y (m/s)',
    width: dock.chartWidth,
    height: 150,
    capacity: MAX_FLIGHT * 60,
    series: [
      { label: 'simulated', color: '#ffb703' },
      { label: 'exact', color: '#e6e9ef', dashed: true },
      { label: '−v_t (terminal)', color: '#ef476f', dashed: true },
    ],
  }),
};
// The first flight started before the charts existed: show it from its start.
shell.reset();
clearOldPaths();

/** Forgets every flight but the current one. */
function clearOldPaths(): void {
  for (let i = 0; i < KEPT_PATHS; i++) if (i !== current) paths[i]!.clear();
}

// ---- Pointer: click aims and launches -----------------------------------------------------------

const canvas = app.canvas;
const pointer: Point2 = { x: 0, y: 0 };
let hover = false;
canvas.addEventListener('pointermove', (event) => {
  pointerOnCanvas(canvas, event, pointer);
  hover = true;
});
canvas.addEventListener('pointerleave', () => {
  hover = false;
});
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  pointerOnCanvas(canvas, event, pointer);
  aimAt(renderer.camera.toWorldX(pointer.x), renderer.camera.toWorldY(pointer.y));
});

/**
 * Sets the launch angle to point from the launch point at world point (x, y), m, clamped to
 * [-90, 180] degrees, and launches. @returns the angle, degrees.
 */
function aimAt(x: number, y: number): number {
  const deg = (Math.atan2(y - launch.y0, x - launch.x0) * 180) / Math.PI;
  params.angle = Math.round(Math.min(180, Math.max(-90, deg)) * 10) / 10;
  panel.refresh();
  shell.reset();
  return params.angle;
}

// ---- Drawing ------------------------------------------------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
// Above the walls and under the ball.
renderer.root.addChildAt(overlay, 2);
const at: Point2 = { x: 0, y: 0 };

/** Paths (current, earlier, exact), the launch arrow, the aim line, and a marker on the ball. */
function drawOverlay(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  overlay.clear();
  for (let k = 1; k < KEPT_PATHS; k++) {
    const i = (current + k) % KEPT_PATHS;
    paths[i]!.draw(overlay, cam, 2, LAW_COLOR[pathLaw[i]!], 0.35);
  }
  if (exactPath.count > 1) exactPath.draw(overlay, cam, 2, 0xe6e9ef, 0.7, true);
  drawnPosition(world, handles.ball, alpha, at);
  paths[current]!.draw(overlay, cam, 2.5, LAW_COLOR[handles.params.law], 0.95, false, at.x, at.y);
  // Launch arrow: direction and (scaled) speed.
  const sx = cam.toScreenX(launch.x0),
    sy = cam.toScreenY(launch.y0);
  const s = handles.params.speed > 0 ? 40 / handles.params.speed : 0;
  overlay
    .moveTo(sx, sy)
    .lineTo(sx + launch.vx0 * s, sy - launch.vy0 * s)
    .stroke({ width: 2, color: 0xffffff, alpha: 0.8 });
  if (hover) drawDashedLine(overlay, sx, sy, pointer.x, pointer.y, 1.5, 0xffffff, 0.35);
  // The ball may be under a pixel at large scales: mark it.
  const r = Math.max(4, cam.toScreenLength(BALL_RADIUS));
  overlay.circle(cam.toScreenX(at.x), cam.toScreenY(at.y), r + 2).stroke({ width: 1.5, color: LAW_COLOR[handles.params.law], alpha: 0.9 });
  updateReadout();
}

let readoutFrame = 0;
/** Refreshes the readout box (every 8th frame). */
function updateReadout(): void {
  if (readoutFrame++ % 8 !== 0) return;
  const vt = terminalSpeed();
  readout.set(0, Number.isFinite(vt) ? `${fmt(vt)} m/s` : handles.params.law === 'none' ? 'none (no drag)' : '∞ (k = 0)');
  readout.set(1, flight.flying ? 'in flight' : `${fmt(flight.landedTime)} s`);
  readout.set(2, flight.flying ? 'in flight' : `${fmt(flight.range)} m`);
  readout.set(3, Number.isNaN(flight.maxDeviation) ? 'no closed form (quadratic)' : `${fmt(flight.maxDeviation, 3)} m`);
  readout.set(4, `${fmt(flight.maxFallSpeed)} m/s`);
}

// Repaint the ball in its law's colour on every new world.
const paint = (): void => renderer.setColor(handles.ball, LAW_COLOR[handles.params.law]);
paint();
shell.onWorldChange(paint);

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plots,
  /** Measurements of the current flight (live object). */
  flight,
  /** Entity id of the ball. */
  ball: (): number => handles.ball,
  /** Runs `n` (integer >= 0) lab steps now, measurements included. @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
  /** Aims at world point (x, y), m, and launches; returns the angle, degrees. */
  aimAt,
});
