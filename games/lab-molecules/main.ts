/**
 * Lab: molecules (Ramtal and Dobre ch. 11). An elastic gas of discs in a box; every molecule starts
 * at the same speed. The histogram beside the box counts the molecules' speeds and draws the 2D
 * Maxwell-Boltzmann distribution N dv (m v / kT) exp(-m v^2 / 2kT) at the measured temperature
 * kT = mean kinetic energy per molecule; collisions spread the single starting speed into that curve.
 * The chart follows kinetic energy over its starting value (perfectly elastic: it stays 1).
 *
 * Input: click in the box to heat the molecules near the point (their speeds x 1.5). Keys: P pause,
 * N step, R reset. URL: ?count (10-2000), ?speed (0.1-10 m/s), ?radius (0.02-0.3 m).
 */

import { createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createLabDock, createReadout, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import { createPhysicsWorld, kineticEnergy, type PhysicsWorld, step as physicsStep, slotOf } from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { buildGas, GAS_DEFAULTS, type GasHandles, gasWorldOptions, MOLECULE_MASS, maxwellBoltzmann2D, measureSpeeds } from './scene';

const USAGE = 'Accepted: count 10-2000; speed 0.1-10 m/s; radius 0.02-0.3 m.';
const url = readUrlParams(
  () => ({
    count: numberParam('count', { default: GAS_DEFAULTS.count, min: 10, max: 2000, integer: true }),
    speed: numberParam('speed', { default: GAS_DEFAULTS.speed, min: 0.1, max: 10 }),
    radius: numberParam('radius', { default: GAS_DEFAULTS.radius, min: 0.02, max: 0.3 }),
  }),
  USAGE,
);
const params = { ...url, reset: () => shell.reset() };

const BINS = 24;
let handles: GasHandles;
const view: WorldRect = { minX: 0, minY: 0, maxX: 1, maxY: 1 };
/** Live measurements (also on window.game): kT (J), kinetic energy over its start, histogram counts and bin width (m/s). */
const gas = { kT: 0, energyRatio: 1, kinetic0: 0, counts: new Float64Array(BINS), binWidth: 0.1 };

function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(gasWorldOptions({ count: params.count }));
  handles = buildGas(world, { count: params.count, speed: params.speed, radius: params.radius });
  // The box on the left, the histogram (as wide as the box is tall) on the right.
  view.minX = -0.05 * handles.width;
  view.minY = -0.08 * handles.height;
  view.maxX = handles.width * 1.1 + handles.height * 1.2;
  view.maxY = handles.height * 1.05;
  refit?.();
  gas.kinetic0 = kineticEnergy(world);
  plot?.clear();
  measure(world);
  return world;
}

/** Temperature and speed histogram of the molecules now. */
function measure(world: PhysicsWorld): void {
  const ke = kineticEnergy(world);
  gas.energyRatio = gas.kinetic0 > 0 ? ke / gas.kinetic0 : 1;
  const { kT, binWidth } = measureSpeeds(world, handles.molecules, gas.counts);
  gas.kT = kT;
  gas.binWidth = binWidth;
}

function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  measure(world);
  plot?.push(world.time, gas.energyRatio);
}

let refit: (() => void) | null = null;
let plot: ReturnType<typeof createPlot> | null = null;

const game = await startPixiGame({
  title: 'Molecules',
  createWorld,
  step: labStep,
  bodies: () => handles.molecules.length,
  controls: [{ keys: 'Click', action: 'heat the molecules near the point' }],
  renderer: { view, balls: 'sprites', rotation: false },
  onFrame: () => drawOverlay(),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);
refit();

const restart = (): void => shell.reset();
const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'count', label: 'molecules', min: 10, max: 2000, step: 10, onRelease: true, onChange: restart },
    { type: 'slider', key: 'speed', label: 'starting speed (m/s)', min: 0.1, max: 10, step: 0.1, onRelease: true, onChange: restart },
    { type: 'slider', key: 'radius', label: 'radius (m)', min: 0.02, max: 0.3, step: 0.01, onRelease: true, onChange: restart },
    { type: 'button', key: 'reset', label: 'start again (R)' },
  ],
  { title: 'Molecules', container: dock.panelSlot },
);
const readout = createReadout(shell.hud.readout, ['kT (mean KE)', 'most probable speed √(kT/m)', 'KE / KE at start']);
plot = createPlot({
  parent: dock.charts,
  title: 'Kinetic energy',
  yLabel: 'KE / KE₀',
  width: dock.chartWidth,
  height: 180,
  capacity: 1200,
  series: [{ label: 'KE / KE at start', color: '#4cc9f0' }],
});
shell.reset();

// ---- Pointer: a click heats the molecules near it ---------------------------------------------------

const canvas = app.canvas;
const pointer: Point2 = { x: 0, y: 0 };
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  pointerOnCanvas(canvas, event, pointer);
  heatAt(renderer.camera.toWorldX(pointer.x), renderer.camera.toWorldY(pointer.y));
});

/** Multiplies the speed of every molecule within a fifth of the box height of (x, y) by 1.5. @returns how many. */
function heatAt(x: number, y: number): number {
  const w = shell.world,
    P = w.components.Position,
    V = w.components.Velocity;
  const reach = 0.2 * handles.height;
  let n = 0;
  for (const e of handles.molecules) {
    const s = slotOf(e);
    if (Math.hypot(P.x[s]! - x, P.y[s]! - y) > reach) continue;
    V.x[s] = 1.5 * V.x[s]!;
    V.y[s] = 1.5 * V.y[s]!;
    n++;
  }
  gas.kinetic0 = kineticEnergy(w);
  measure(w);
  return n;
}

// ---- Drawing: the speed histogram against Maxwell-Boltzmann ------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
renderer.root.addChild(overlay);

function drawOverlay(): void {
  const cam = renderer.camera;
  overlay.clear();
  const W = handles.width,
    H = handles.height;
  // Histogram frame: x from 1.1 W to 1.1 W + 1.1 H (speed), y from 0 to H (count).
  const x0 = 1.1 * W,
    span = 1.05 * H;
  const N = handles.molecules.length;
  // Tallest expected bar: N dv f(v_p) at the most probable speed, times 1.6 for fluctuations.
  const vp = Math.sqrt(gas.kT / MOLECULE_MASS);
  const peak = N * gas.binWidth * maxwellBoltzmann2D(vp, gas.kT) * 1.6;
  const sx = (v: number): number => cam.toScreenX(x0 + (v / (BINS * gas.binWidth)) * span);
  const sy = (c: number): number => cam.toScreenY((c / peak) * H);
  for (let k = 0; k < BINS; k++) {
    const c = gas.counts[k]!;
    if (c === 0) continue;
    const left = sx(k * gas.binWidth),
      right = sx((k + 1) * gas.binWidth);
    overlay.rect(left + 1, sy(c), right - left - 2, sy(0) - sy(c)).fill({ color: 0x4cc9f0, alpha: 0.75 });
  }
  overlay.moveTo(sx(0), sy(0));
  for (let i = 0; i <= 96; i++) {
    const v = (i / 96) * BINS * gas.binWidth;
    overlay.lineTo(sx(v), sy(N * gas.binWidth * maxwellBoltzmann2D(v, gas.kT)));
  }
  overlay.stroke({ width: 2, color: 0xf4a261 });
  overlay
    .moveTo(sx(0), sy(0))
    .lineTo(sx(BINS * gas.binWidth), sy(0))
    .stroke({ width: 1, color: 0xd0d6e0 });
  overlay.rect(cam.toScreenX(0), cam.toScreenY(H), cam.toScreenLength(W), cam.toScreenLength(H)).stroke({ width: 1.5, color: 0x8d99ae });
  updateReadout();
}

let readoutFrame = 0;
function updateReadout(): void {
  if (readoutFrame++ % 8 !== 0) return;
  readout.set(0, `${fmt(gas.kT, 4)} J`);
  readout.set(1, `${fmt(Math.sqrt(gas.kT / MOLECULE_MASS), 4)} m/s`);
  readout.set(2, fmt(gas.energyRatio, 6));
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** Temperature, energy ratio and speed histogram (live object). */
  gas,
  heatAt,
  /** Box size, m. */
  box: (): { width: number; height: number } => ({ width: handles.width, height: handles.height }),
  /** Runs `n` (integer >= 0) lab steps now. @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
