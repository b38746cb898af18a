/**
 * Lab: the pendulum (Ramtal and Dobre ch. 8). A bob swings on a stiff damped spring to a fixed
 * anchor (why a spring: see scene.ts; the physics package has no rigid rod), with linear drag on
 * the bob as the swing's damping. The chart plots the angle against the small-angle solution
 * theta0 cos(sqrt(g / L) t) (damped when b > 0, see exact.ts), also drawn on the canvas as a faint
 * ghost bob; the readout puts the measured period next to 2 pi sqrt(L / g) and the exact
 * large-amplitude period 2 pi sqrt(L / g) / AGM(1, cos(theta0 / 2)).
 *
 * Input: click places the bob (sets length and amplitude) and releases it. Keys: P pause, N step, R reset.
 * URL: ?length (0.2-20 m), ?amplitude (-179-179 deg), ?g (0.5-30 m/s^2), ?damping (0-5 N s/m).
 */

import { createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createLabDock, createReadout, drawnPosition, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import { createPhysicsWorld, type PhysicsWorld, step as physicsStep } from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { largeAmplitudePeriod, smallAngle, smallAnglePeriod } from './exact';
import { BOB_MASS, buildPendulum, PENDULUM_DEFAULTS, PENDULUM_RANGES, type PendulumHandles, pendulumWorldOptions } from './scene';

const DEG = 180 / Math.PI;
const BOB_COLOR = 0x4cc9f0;

const USAGE = 'Accepted: length 0.2-20 m; amplitude -179-179 deg; g 0.5-30 m/s²; damping 0-5 N s/m.';
const url = readUrlParams(() => {
  const range = (name: string, key: keyof typeof PENDULUM_RANGES, fallback: number) =>
    numberParam(name, { default: fallback, min: PENDULUM_RANGES[key][0], max: PENDULUM_RANGES[key][1] });
  return {
    length: range('length', 'length', PENDULUM_DEFAULTS.length),
    amplitude: range('amplitude', 'amplitude', PENDULUM_DEFAULTS.amplitude),
    gravity: range('g', 'gravity', PENDULUM_DEFAULTS.gravity),
    damping: range('damping', 'damping', PENDULUM_DEFAULTS.damping),
  };
}, USAGE);

const params = { ...url, release: () => shell.reset() };

let handles: PendulumHandles;
const view: WorldRect = { minX: -2.5, minY: -2.5, maxX: 2.5, maxY: 0.6 };

/** Measurements of the current swing (live object, also on window.game). */
const swing = {
  /** Angle from the downward vertical now, rad, and the small-angle solution's, rad. */
  angle: 0,
  exact: 0,
  /** Period measured from the last two zero crossings of the angle (twice their spacing), s; NaN before. */
  measuredPeriod: Number.NaN,
  /** Zero crossings so far. */
  crossings: 0,
  /** 2 pi sqrt(L / g), s, and the exact large-amplitude period, s. */
  smallAnglePeriod: 0,
  exactPeriod: 0,
  /** Largest |theta - theta_small-angle| so far, rad. */
  maxDeviation: 0,
  /** Largest relative stretch of the rod, (|r| - L) / L. */
  maxStretch: 0,
};
let lastAngle = 0,
  lastCrossing = Number.NaN;

/** Builds a fresh pendulum from the params; the shell calls it at start and on R. */
function createWorld(): PhysicsWorld {
  const { length, amplitude, gravity, damping } = params;
  const world = createPhysicsWorld(pendulumWorldOptions({ length, amplitude, gravity, damping }));
  handles = buildPendulum(world, { length, amplitude, gravity, damping });
  const L = length,
    a = amplitude / DEG;
  const up = Math.max(0.35 * L, -L * Math.cos(a) + 0.25 * L);
  view.minX = -1.2 * L;
  view.maxX = 1.2 * L;
  view.minY = -1.2 * L;
  view.maxY = up;
  refit?.();
  swing.angle = swing.exact = a;
  swing.measuredPeriod = Number.NaN;
  swing.crossings = 0;
  swing.maxDeviation = 0;
  swing.maxStretch = 0;
  swing.smallAnglePeriod = smallAnglePeriod(L, gravity);
  swing.exactPeriod = damping === 0 ? largeAmplitudePeriod(L, gravity, a) : Number.NaN;
  lastAngle = a;
  lastCrossing = Number.NaN;
  plot?.clear();
  return world;
}

/** The bob's angle from the downward vertical, rad (counter-clockwise positive). */
function angleOf(world: PhysicsWorld): number {
  const P = world.components.Position,
    b = handles.bob;
  return Math.atan2(P.x[b]! - handles.anchor[0], -(P.y[b]! - handles.anchor[1]));
}

/** One step: physics, then the angle against the small-angle solution and the period from zero crossings. */
function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  const p = handles.params;
  const t = world.time;
  const angle = angleOf(world);
  swing.angle = angle;
  swing.exact = smallAngle(p.amplitude / DEG, p.gravity, p.length, p.damping, BOB_MASS, t);
  swing.maxDeviation = Math.max(swing.maxDeviation, Math.abs(angle - swing.exact));
  const P = world.components.Position;
  const r = Math.hypot(P.x[handles.bob]! - handles.anchor[0], P.y[handles.bob]! - handles.anchor[1]);
  swing.maxStretch = Math.max(swing.maxStretch, Math.abs(r - p.length) / p.length);
  // A sign change of the angle is a zero crossing; its time is interpolated within the step.
  if ((lastAngle > 0 && angle <= 0) || (lastAngle < 0 && angle >= 0)) {
    const tc = t - world.dt + (lastAngle / (lastAngle - angle)) * world.dt;
    if (!Number.isNaN(lastCrossing)) swing.measuredPeriod = 2 * (tc - lastCrossing);
    lastCrossing = tc;
    swing.crossings++;
  }
  lastAngle = angle;
  plot?.push(t, angle * DEG, swing.exact * DEG);
}

// ---- Page ------------------------------------------------------------------------------------------

let refit: (() => void) | null = null;
let plot: ReturnType<typeof createPlot> | null = null;

const game = await startPixiGame({
  title: 'Pendulum',
  createWorld,
  step: labStep,
  bodies: () => 1,
  controls: [{ keys: 'Click', action: 'place the bob there and let go' }],
  renderer: { view, balls: 'sprites', rotation: false },
  onFrame: (alpha, world) => drawOverlay(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);
const paint = (): void => renderer.setColor(handles.bob, BOB_COLOR);
paint();
shell.onWorldChange(paint);

const restart = (): void => shell.reset();
const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'length', label: 'length L (m)', min: 0.2, max: 10, step: 0.01, onRelease: true, onChange: restart },
    { type: 'slider', key: 'amplitude', label: 'amplitude θ₀ (°)', min: -179, max: 179, step: 0.5, onRelease: true, onChange: restart },
    { type: 'slider', key: 'gravity', label: 'gravity g (m/s²)', min: 0.5, max: 30, step: 0.01, onRelease: true, onChange: restart },
    { type: 'slider', key: 'damping', label: 'damping b (N s/m)', min: 0, max: 5, step: 0.01, onRelease: true, onChange: restart },
    { type: 'button', key: 'release', label: 'release again (R)' },
  ],
  { title: 'Pendulum', container: dock.panelSlot },
);

const readout = createReadout(shell.hud.readout, [
  'angle θ',
  '2π√(L/g)',
  'exact, any amplitude',
  'measured period',
  'measured / 2π√(L/g)',
  'max |θ − θ_small|',
  'rod stretch (max)',
]);
plot = createPlot({
  parent: dock.charts,
  title: 'Angle',
  yLabel: 'θ (°)',
  width: dock.chartWidth,
  height: 220,
  capacity: 1200,
  series: [
    { label: 'simulated', color: '#4cc9f0' },
    { label: 'small-angle θ₀ cos(√(g/L) t)', color: '#e6e9ef', dashed: true },
  ],
});
shell.reset();

// ---- Pointer: click places the bob ------------------------------------------------------------------

const canvas = app.canvas;
const pointer: Point2 = { x: 0, y: 0 };
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  pointerOnCanvas(canvas, event, pointer);
  placeAt(renderer.camera.toWorldX(pointer.x), renderer.camera.toWorldY(pointer.y));
});

/**
 * Places the bob at world point (x, y), m: length and amplitude from its distance and angle to the
 * anchor (clamped to the panel's ranges), then releases it. @returns the new length (m) and amplitude (deg).
 */
function placeAt(x: number, y: number): { length: number; amplitude: number } {
  const dx = x - handles.anchor[0],
    dy = y - handles.anchor[1];
  params.length = Math.round(Math.min(10, Math.max(0.2, Math.hypot(dx, dy))) * 100) / 100;
  params.amplitude = Math.round(Math.min(179, Math.max(-179, Math.atan2(dx, -dy) * DEG)) * 2) / 2;
  panel.refresh();
  shell.reset();
  return { length: params.length, amplitude: params.amplitude };
}

// ---- Drawing ------------------------------------------------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
renderer.root.addChildAt(overlay, 1);
const at: Point2 = { x: 0, y: 0 };

/** Anchor, the swing's arc, the ghost of the small-angle solution, and the rod. */
function drawOverlay(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  overlay.clear();
  const p = handles.params;
  const ax = cam.toScreenX(handles.anchor[0]),
    ay = cam.toScreenY(handles.anchor[1]);
  const Lpx = cam.toScreenLength(p.length);
  // Arc of the starting amplitude (both sides), faint.
  const a0 = Math.abs(p.amplitude) / DEG;
  overlay.arc(ax, ay, Lpx, Math.PI / 2 - a0, Math.PI / 2 + a0).stroke({ width: 1, color: 0x98a2b3, alpha: 0.35 });
  // Ghost: where the small-angle solution puts the bob now.
  const gx = ax + Lpx * Math.sin(swing.exact),
    gy = ay + Lpx * Math.cos(swing.exact);
  const br = Math.max(4, cam.toScreenLength(handles.bobRadius));
  overlay.moveTo(ax, ay).lineTo(gx, gy).stroke({ width: 1, color: 0xe6e9ef, alpha: 0.3 });
  overlay.circle(gx, gy, br).stroke({ width: 1.5, color: 0xe6e9ef, alpha: 0.55 });
  // The rod (the spring, drawn straight: it stretches by about a millimetre).
  drawnPosition(world, handles.bob, alpha, at);
  overlay.moveTo(ax, ay).lineTo(cam.toScreenX(at.x), cam.toScreenY(at.y)).stroke({ width: 2.5, color: 0xd0d6e0 });
  overlay.rect(ax - 24, ay - 5, 48, 5).fill({ color: 0x8d99ae });
  for (let k = -2; k <= 2; k++) overlay.moveTo(ax + k * 9, ay - 5).lineTo(ax + k * 9 + 6, ay - 12);
  overlay.stroke({ width: 1.5, color: 0x8d99ae });
  overlay.circle(ax, ay, 3).fill({ color: 0xffffff });
  updateReadout();
}

let readoutFrame = 0;
/** Refreshes the readout (every 8th frame). */
function updateReadout(): void {
  if (readoutFrame++ % 8 !== 0) return;
  readout.set(0, `${fmt(swing.angle * DEG, 3)}°`);
  readout.set(1, `${fmt(swing.smallAnglePeriod, 5)} s`);
  readout.set(2, Number.isNaN(swing.exactPeriod) ? 'undamped only' : `${fmt(swing.exactPeriod, 5)} s`);
  readout.set(3, Number.isNaN(swing.measuredPeriod) ? 'after two zero crossings' : `${fmt(swing.measuredPeriod, 5)} s`);
  readout.set(4, Number.isNaN(swing.measuredPeriod) ? '–' : fmt(swing.measuredPeriod / swing.smallAnglePeriod, 5));
  readout.set(5, `${fmt(swing.maxDeviation * DEG, 3)}°`);
  readout.set(6, `${fmt(swing.maxStretch * 100, 2)} %`);
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** Measurements of the current swing (live object). */
  swing,
  /** Entity ids: bob and rod. */
  ids: (): { bob: number; rod: number } => ({ bob: handles.bob, rod: handles.rod }),
  placeAt,
  /** Runs `n` (integer >= 0) lab steps now. @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
