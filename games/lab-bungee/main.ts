/**
 * Lab: bungee jump (Ramtal and Dobre ch. 8). A jumper falls from a bridge on a rope that is the
 * physics package's one-sided spring (addSpring oneSided: true): slack until it is longer than its
 * unstretched length L, then a damped Hooke spring. The chart plots the jumper's height against
 * the exact free-fall curve y = H - g t^2 / 2 (until the rope goes taut) and the lowest point that
 * energy conservation predicts, m g (L + x) = k x^2 / 2 (a line; with damping the jumper stops
 * higher). The dashed red line on the canvas marks the same predicted lowest point.
 *
 * Input: Space or click jumps again; panel changes jump again with the new rope and jumper.
 * Keys: P pause, N step, R reset. URL: ?length (2-50 m), ?k (10-5000 N/m), ?damping (0-1000 N s/m),
 * ?mass (20-200 kg).
 */

import { createPanel, numberParam } from '@bitphysics/game-kit';
import { createLabDock, createReadout, drawDashedLine, drawnPosition, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import { createPhysicsWorld, type PhysicsWorld, step as physicsStep } from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { equilibriumStretch, freeFallHeight, freeFallTime, lowestStretch } from './exact';
import { BRIDGE_HEIGHT, BUNGEE_DEFAULTS, type BungeeHandles, buildBungee, bungeeWorldOptions, GRAVITY, JUMPER_RADIUS } from './scene';

const USAGE = 'Accepted: length 2-50 m; k 10-5000 N/m; damping 0-1000 N s/m; mass 20-200 kg.';
const url = readUrlParams(
  () => ({
    ropeLength: numberParam('length', { default: BUNGEE_DEFAULTS.ropeLength, min: 2, max: 50 }),
    stiffness: numberParam('k', { default: BUNGEE_DEFAULTS.stiffness, min: 10, max: 5000 }),
    damping: numberParam('damping', { default: BUNGEE_DEFAULTS.damping, min: 0, max: 1000 }),
    mass: numberParam('mass', { default: BUNGEE_DEFAULTS.mass, min: 20, max: 200 }),
  }),
  USAGE,
);

const params = { ...url, jump: () => shell.reset() };

let handles: BungeeHandles;
const view: WorldRect = { minX: -24, minY: -3, maxX: 14, maxY: BRIDGE_HEIGHT + 4 };

/** Measurements and predictions of the current jump (live object, also on window.game). */
const jump = {
  /** Predicted lowest height of the jumper's centre, m: H - L - x with x from energy. */
  predictedLowest: 0,
  /** Lowest height reached so far, m, and when, s. */
  lowest: BRIDGE_HEIGHT,
  lowestTime: 0,
  /** Free-fall duration sqrt(2 L / g), s, and the measured time the rope went taut (NaN before). */
  freeFallTime: 0,
  tautTime: Number.NaN,
  /** Largest |y - y_free_fall| during the free-fall phase, m. */
  freeFallError: 0,
  /** Largest speed, m/s, and largest upward acceleration from the rope, in g. */
  maxSpeed: 0,
  maxPull: 0,
  /** Height where the jumper finally hangs, m: H - L - m g / k. */
  equilibrium: 0,
};
let lastVy = 0;

/** Builds a fresh jump from the params; the shell calls it at start and on R. */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(bungeeWorldOptions());
  const { ropeLength, stiffness, damping, mass } = params;
  handles = buildBungee(world, { ropeLength, stiffness, damping, mass });
  const p = handles.params;
  jump.predictedLowest = BRIDGE_HEIGHT - p.ropeLength - lowestStretch(p.mass, GRAVITY, p.stiffness, p.ropeLength);
  jump.equilibrium = BRIDGE_HEIGHT - p.ropeLength - equilibriumStretch(p.mass, GRAVITY, p.stiffness);
  jump.freeFallTime = freeFallTime(GRAVITY, p.ropeLength);
  jump.lowest = BRIDGE_HEIGHT;
  jump.lowestTime = 0;
  jump.tautTime = Number.NaN;
  jump.freeFallError = 0;
  jump.maxSpeed = 0;
  jump.maxPull = 0;
  lastVy = 0;
  plot?.clear();
  return world;
}

/** One step: physics, then the measurements against the exact curve and the prediction. */
function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  const e = handles.jumper;
  const y = world.components.Position.y[e]!,
    vy = world.components.Velocity.y[e]!,
    vx = world.components.Velocity.x[e]!;
  const t = world.time;
  const p = handles.params;
  const ff = freeFallHeight(BRIDGE_HEIGHT, GRAVITY, p.ropeLength, t);
  if (!Number.isNaN(ff)) jump.freeFallError = Math.max(jump.freeFallError, Math.abs(y - ff));
  if (y < jump.lowest) {
    jump.lowest = y;
    jump.lowestTime = t;
  }
  if (Number.isNaN(jump.tautTime) && BRIDGE_HEIGHT - y > p.ropeLength) jump.tautTime = t;
  jump.maxSpeed = Math.max(jump.maxSpeed, Math.hypot(vx, vy));
  // Acceleration measured from the velocity change over the step, in g, counted upward from free fall.
  const pull = ((vy - lastVy) / world.dt + GRAVITY) / GRAVITY;
  if (world.steps > 1) jump.maxPull = Math.max(jump.maxPull, pull);
  lastVy = vy;
  plot?.push(t, y, ff, jump.predictedLowest);
}

// ---- Page ------------------------------------------------------------------------------------------

let plot: ReturnType<typeof createPlot> | null = null;

const game = await startPixiGame({
  title: 'Bungee jump',
  createWorld,
  step: labStep,
  bodies: () => 1,
  controls: [
    { keys: 'Space', action: 'jump again' },
    { keys: 'Click', action: 'jump again' },
  ],
  keys: [{ key: ' ', label: 'jump', action: () => shell.reset() }],
  renderer: { view, balls: 'sprites', rotation: false, segmentColor: 0x8d99ae },
  onFrame: (alpha, world) => drawOverlay(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
followView(app, renderer.camera, dock, () => view);
const paint = (): void => renderer.setColor(handles.jumper, 0xff8c42);
paint();
shell.onWorldChange(paint);

const rejump = (): void => shell.reset();
const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'ropeLength', label: 'rope length L (m)', min: 2, max: 40, step: 0.5, onRelease: true, onChange: rejump },
    { type: 'slider', key: 'stiffness', label: 'stiffness k (N/m)', min: 20, max: 1000, step: 1, onRelease: true, onChange: rejump },
    { type: 'slider', key: 'damping', label: 'damping (N s/m)', min: 0, max: 300, step: 1, onRelease: true, onChange: rejump },
    { type: 'slider', key: 'mass', label: 'jumper mass m (kg)', min: 20, max: 200, step: 1, onRelease: true, onChange: rejump },
    { type: 'button', key: 'jump', label: 'jump again (Space)' },
  ],
  { title: 'Bungee', container: dock.panelSlot },
);

const readout = createReadout(shell.hud.readout, [
  'free fall √(2L/g)',
  'rope taut at',
  'max |y − y_free fall|',
  'lowest by energy',
  'lowest reached',
  'hangs at (m g / k)',
  'top speed',
  'peak pull',
]);
plot = createPlot({
  parent: dock.charts,
  title: 'Height of the jumper',
  yLabel: 'y (m)',
  width: dock.chartWidth,
  height: 230,
  capacity: 1800,
  series: [
    { label: 'simulated', color: '#ff8c42' },
    { label: 'free fall (exact)', color: '#e6e9ef', dashed: true },
    { label: 'lowest (energy)', color: '#ef476f', dashed: true },
  ],
});
shell.reset();
app.canvas.addEventListener('pointerdown', (event) => {
  if (event.button === 0) shell.reset();
});

// ---- Drawing ------------------------------------------------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
renderer.root.addChildAt(overlay, 1);
const at: Point2 = { x: 0, y: 0 };

/** River, bridge pier, the predicted lowest point, and the rope (sagging while slack). */
function drawOverlay(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  overlay.clear();
  const left = 0,
    right = cam.width;
  const y0 = cam.toScreenY(0);
  overlay.rect(left, y0, right, cam.height - y0).fill({ color: 0x1d3557, alpha: 0.9 });
  const deckY = cam.toScreenY(BRIDGE_HEIGHT),
    pierX = cam.toScreenX(-12);
  overlay.rect(pierX - cam.toScreenLength(1.5), deckY, cam.toScreenLength(3), y0 - deckY).fill({ color: 0x3a4253 });
  const low = cam.toScreenY(jump.predictedLowest);
  drawDashedLine(overlay, cam.toScreenX(-10), low, cam.toScreenX(10), low, 2, 0xef476f, 0.85);
  const eq = cam.toScreenY(jump.equilibrium);
  drawDashedLine(overlay, cam.toScreenX(-4), eq, cam.toScreenX(4), eq, 1, 0x98a2b3, 0.6, 4, 4);
  // The rope: straight while taut, a sagging curve of the same length (drawn only) while slack.
  drawnPosition(world, handles.jumper, alpha, at);
  const ax = cam.toScreenX(handles.anchor[0]),
    ay = cam.toScreenY(handles.anchor[1]);
  const jx = cam.toScreenX(at.x),
    jy = cam.toScreenY(at.y);
  const L = handles.params.ropeLength;
  const d = Math.hypot(at.x - handles.anchor[0], at.y - handles.anchor[1]);
  if (d >= L) {
    overlay.moveTo(ax, ay).lineTo(jx, jy).stroke({ width: 3, color: 0xffd166 });
  } else {
    const sag = cam.toScreenLength(Math.sqrt(L * L - d * d) / 2);
    overlay
      .moveTo(ax, ay)
      .quadraticCurveTo((ax + jx) / 2 + sag * 0.9, (ay + jy) / 2 + sag * 0.6, jx, jy)
      .stroke({ width: 2, color: 0xffd166, alpha: 0.8 });
  }
  overlay.circle(ax, ay, 3).fill({ color: 0xffffff });
  // The jumper is a few pixels wide at this scale: ring it.
  overlay.circle(jx, jy, Math.max(7, cam.toScreenLength(JUMPER_RADIUS) + 3)).stroke({ width: 2, color: 0xff8c42 });
  updateReadout();
}

let readoutFrame = 0;
/** Refreshes the readout (every 8th frame). */
function updateReadout(): void {
  if (readoutFrame++ % 8 !== 0) return;
  readout.set(0, `${fmt(jump.freeFallTime)} s`);
  readout.set(1, Number.isNaN(jump.tautTime) ? 'falling freely' : `${fmt(jump.tautTime)} s`);
  readout.set(2, `${fmt(jump.freeFallError, 3)} m`);
  readout.set(3, `${fmt(jump.predictedLowest)} m${jump.predictedLowest < JUMPER_RADIUS ? ' (hits the water!)' : ''}`);
  readout.set(4, `${fmt(jump.lowest)} m at ${fmt(jump.lowestTime, 3)} s`);
  readout.set(5, `${fmt(jump.equilibrium)} m`);
  readout.set(6, `${fmt(jump.maxSpeed, 3)} m/s`);
  readout.set(7, `${fmt(jump.maxPull, 3)} g`);
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** Measurements and predictions of the current jump (live object). */
  jump,
  /** Entity ids: jumper and rope. */
  ids: (): { jumper: number; rope: number } => ({ jumper: handles.jumper, rope: handles.rope }),
  /** Runs `n` (integer >= 0) lab steps now. @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
