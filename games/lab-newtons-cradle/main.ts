/**
 * Lab: Newton's cradle (Ramtal and Dobre ch. 11, collisions). Equal steel balls on strings, perfectly
 * elastic: lift k balls and k balls leave the other end, because only that keeps both momentum and
 * kinetic energy. The charts plot the total energy (kinetic + potential, which a perfectly elastic
 * row keeps) and the horizontal momentum (which swings back and forth with the balls; the strings
 * exchange it with the frame, the impacts never change it).
 *
 * Input: press on a ball and drag sideways to lift it and every ball between it and its end of the
 * row; the hand holds them (the whole row waits at rest, the clock stopped) until you release them. Keys: P pause, N step, R reset (lifts `lift` balls by `angle` again).
 * URL: ?count (2-8), ?lift (1-7), ?angle (5-80 deg).
 */

import { createPanel, forEachImpact, getSound, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createLabDock, createReadout, drawnPosition, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import {
  createPhysicsWorld,
  gravitationalPotentialEnergy,
  kineticEnergy,
  type PhysicsWorld,
  step as physicsStep,
  slotOf,
} from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { BALL_MASS, buildCradle, CRADLE_DEFAULTS, type CradleHandles, cradleWorldOptions, liftBalls } from './scene';

const DEG = 180 / Math.PI;
const USAGE = 'Accepted: count 2-8; lift 1-7; angle 5-80 deg.';
const url = readUrlParams(
  () => ({
    count: numberParam('count', { default: CRADLE_DEFAULTS.count, min: 2, max: 8, integer: true }),
    lift: numberParam('lift', { default: 1, min: 1, max: 7, integer: true }),
    angle: numberParam('angle', { default: 30, min: 5, max: 80 }),
  }),
  USAGE,
);

const params = { ...url, release: () => shell.reset() };
let handles: CradleHandles;
const view: WorldRect = { minX: -1.4, minY: -1.25, maxX: 1.4, maxY: 0.15 };

/** Index of the ball the pointer holds, -1 if none; `heldAngle` its string's angle, rad (negative: left). */
let held = -1,
  heldAngle = 0;

/** Energy and momentum now and at the release (live object, also on window.game). */
const measure = { energy: 0, energy0: 0, momentum: 0, kinetic: 0, moving: 0 };

/** Builds the row and lifts `lift` balls on the left by `angle`; the shell calls it at start and on R. */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(cradleWorldOptions({ count: params.count }));
  held = -1;
  handles = buildCradle(world, { count: params.count });
  const k = Math.min(params.lift, params.count - 1);
  liftBalls(world, handles, 0, k - 1, -params.angle / DEG);
  plot?.clear();
  momentumPlot?.clear();
  measure.energy0 = totalEnergy(world);
  update(world);
  return world;
}

/** Kinetic plus potential energy, J (potential from the balls' lowest point, y = -L). */
function totalEnergy(world: PhysicsWorld): number {
  return (
    kineticEnergy(world) +
    gravitationalPotentialEnergy(world) +
    handles.balls.length * BALL_MASS * world.gravity[1]! * -handles.params.length
  );
}

function update(world: PhysicsWorld): void {
  const V = world.components.Velocity;
  let p = 0,
    moving = 0;
  for (const b of handles.balls) {
    const s = slotOf(b);
    p += BALL_MASS * V.x[s]!;
    if (Math.hypot(V.x[s]!, V.y[s]!) > 0.05) moving++;
  }
  measure.energy = totalEnergy(world);
  measure.kinetic = kineticEnergy(world);
  measure.momentum = p;
  measure.moving = moving;
}

const sound = getSound();

/**
 * One step: physics (with a click for each ball hit), then the energy and momentum charts. While a ball is held the hand keeps the row
 * in its lifted pose at rest instead (no step): the lifted balls must not swing down and strike the
 * row before they are let go, nor leave at whatever speed they had gathered since the last move.
 */
function labStep(world: PhysicsWorld): void {
  if (held >= 0) {
    hold(world);
    return;
  }
  physicsStep(world);
  // The click of steel on steel: a knock for each ball hit, loudness from its impulse (two 1 kg balls
  // meeting at 1 m/s: 0.5 N s).
  forEachImpact(world, (_a, _b, impulse) => sound.impact(impulse, 'metal', { threshold: 0.05, loud: 2 }));
  update(world);
  plot?.push(world.time, measure.energy, measure.kinetic);
  momentumPlot?.push(world.time, measure.momentum);
}

let refit: (() => void) | null = null;
let plot: ReturnType<typeof createPlot> | null = null;
let momentumPlot: ReturnType<typeof createPlot> | null = null;

const game = await startPixiGame({
  title: "Newton's cradle",
  createWorld,
  step: labStep,
  bodies: () => handles.balls.length,
  controls: [{ keys: 'Drag a ball', action: 'lift it (and the balls beyond it); release to let go' }],
  renderer: { view, balls: 'sprites', rotation: false },
  onFrame: (alpha, world) => drawOverlay(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);
refit();

const restart = (): void => shell.reset();
const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'count', label: 'balls', min: 2, max: 8, step: 1, onRelease: true, onChange: restart },
    { type: 'slider', key: 'lift', label: 'balls lifted', min: 1, max: 7, step: 1, onRelease: true, onChange: restart },
    { type: 'slider', key: 'angle', label: 'lift angle (°)', min: 5, max: 80, step: 1, onRelease: true, onChange: restart },
    { type: 'button', key: 'release', label: 'lift and release (R)' },
  ],
  { title: "Newton's cradle", container: dock.panelSlot },
);

const readout = createReadout(shell.hud.readout, ['energy E', 'E / E at release', 'momentum pₓ', 'balls moving']);
plot = createPlot({
  parent: dock.charts,
  title: 'Energy',
  yLabel: 'E (J)',
  width: dock.chartWidth,
  height: 180,
  capacity: 1200,
  series: [
    { label: 'kinetic + potential', color: '#4cc9f0' },
    { label: 'kinetic', color: '#f4a261' },
  ],
});
momentumPlot = createPlot({
  parent: dock.charts,
  title: 'Momentum',
  yLabel: 'pₓ (kg m/s)',
  width: dock.chartWidth,
  height: 160,
  capacity: 1200,
  series: [{ label: 'Σ m vₓ', color: '#90be6d' }],
});
shell.reset();

// ---- Pointer: press on a ball and drag to lift it and the balls beyond it ----------------------------

const canvas = app.canvas;
const pointer: Point2 = { x: 0, y: 0 };
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  pointerOnCanvas(canvas, event, pointer);
  const x = renderer.camera.toWorldX(pointer.x),
    y = renderer.camera.toWorldY(pointer.y);
  const P = shell.world.components.Position;
  let best = -1,
    bestD = Infinity;
  handles.balls.forEach((b, i) => {
    const d = Math.hypot(P.x[slotOf(b)]! - x, P.y[slotOf(b)]! - y);
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  });
  if (best < 0 || bestD > 3 * handles.params.radius) return;
  held = best;
  // Grabbing stops the row: the held ball (and those beyond it) at its present angle, the rest hanging.
  liftTo(held, P.x[slotOf(handles.balls[best]!)]!, P.y[slotOf(handles.balls[best]!)]!);
  canvas.setPointerCapture?.(event.pointerId);
});
canvas.addEventListener('pointermove', (event) => {
  if (held < 0) return;
  pointerOnCanvas(canvas, event, pointer);
  liftTo(held, renderer.camera.toWorldX(pointer.x), renderer.camera.toWorldY(pointer.y));
});
const letGo = (): void => {
  if (held < 0) return;
  held = -1;
  measure.energy0 = totalEnergy(shell.world);
  plot?.clear();
  momentumPlot?.clear();
};
canvas.addEventListener('pointerup', letGo);
canvas.addEventListener('pointercancel', letGo);
canvas.addEventListener('lostpointercapture', letGo);

/** Puts the row back in the held pose (ball `held` and those beyond it at `heldAngle`), all at rest. */
function hold(world: PhysicsWorld): void {
  const n = handles.balls.length;
  if (held < n / 2) liftBalls(world, handles, 0, held, heldAngle);
  else liftBalls(world, handles, held, n - 1, heldAngle);
  update(world);
}

/**
 * Lifts ball `index` toward world point (x, y), m: the angle of its string (limited to 80° outwards),
 * and every ball between it and its end of the row to the same angle, all at rest.
 * @returns the angle, degrees (negative: left).
 */
function liftTo(index: number, x: number, y: number): number {
  const n = handles.balls.length;
  const left = index < n / 2;
  const [ax, ay] = handles.anchors[index]!;
  let a = Math.atan2(x - ax, -(y - ay));
  a = left ? Math.min(0, Math.max(-80 / DEG, a)) : Math.max(0, Math.min(80 / DEG, a));
  if (left) liftBalls(shell.world, handles, 0, index, a);
  else liftBalls(shell.world, handles, index, n - 1, a);
  if (index === held) heldAngle = a;
  update(shell.world);
  return a * DEG;
}

// ---- Drawing ------------------------------------------------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
renderer.root.addChildAt(overlay, 0);
const at: Point2 = { x: 0, y: 0 };

function drawOverlay(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  overlay.clear();
  const x0 = cam.toScreenX(handles.anchors[0]![0] - 0.3),
    x1 = cam.toScreenX(handles.anchors[handles.anchors.length - 1]![0] + 0.3);
  overlay.rect(x0, cam.toScreenY(0) - 6, x1 - x0, 6).fill({ color: 0x8d99ae });
  handles.balls.forEach((b, i) => {
    const [ax, ay] = handles.anchors[i]!;
    drawnPosition(world, b, alpha, at);
    overlay
      .moveTo(cam.toScreenX(ax), cam.toScreenY(ay))
      .lineTo(cam.toScreenX(at.x), cam.toScreenY(at.y))
      .stroke({ width: 1.5, color: 0xd0d6e0, alpha: 0.8 });
  });
  updateReadout();
}

let readoutFrame = 0;
function updateReadout(): void {
  if (readoutFrame++ % 8 !== 0) return;
  readout.set(0, `${fmt(measure.energy, 4)} J`);
  readout.set(1, measure.energy0 > 0 ? fmt(measure.energy / measure.energy0, 4) : '–');
  readout.set(2, `${fmt(measure.momentum, 3)} kg m/s`);
  readout.set(3, String(measure.moving));
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  momentumPlot,
  /** Energy and momentum (live object). */
  measure,
  /** Ball handles, left to right. */
  balls: (): number[] => handles.balls.slice(),
  liftTo,
  /** Index of the ball the pointer holds (it and the balls beyond it wait lifted), -1 if none. */
  held: (): number => held,
  /** Runs `n` (integer >= 0) lab steps now. @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
