/**
 * Lab: a chain of masses and springs (Ramtal and Dobre ch. 8). Balls hang from a fixed anchor, each
 * joined to the one above by a damped Hooke spring (the physics package's Spring entities). The
 * chart shows the total energy (package `totalEnergy`: kinetic + gravity + springs) and its parts;
 * without damping the total stays on the dashed reference line, up to the integrator's error.
 * Dragging a ball pulls it with a stiff mouse spring (an anchor Spring whose anchor follows the
 * pointer), which does work on the chain; the reference is taken again when the ball is let go.
 *
 * Input: drag a ball. Keys: P pause, N step, R reset.
 * URL: ?links (1-40), ?k (1-5000 N/m), ?damping (0-50 N s/m), ?mass (0.01-10 kg), ?angle (deg),
 * ?integrator.
 */

import { choiceParam, createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createLabDock, createReadout, drawnPosition, drawSpring, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import {
  addSpring,
  createPhysicsWorld,
  gravitationalPotentialEnergy,
  INTEGRATOR_NAMES,
  type IntegratorName,
  kineticEnergy,
  type PhysicsWorld,
  step as physicsStep,
  removeBody,
  slotOf,
  springPotentialEnergy,
  totalEnergy,
} from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import {
  BALL_RADIUS,
  buildChain,
  CHAIN_DEFAULTS,
  type ChainHandles,
  chainWorldOptions,
  hangingLength,
  LINK_LENGTH,
  setSpringConstants,
  substepsFor,
} from './scene';

/** Mouse spring stiffness per kilogram of chain, N/m/kg: the grabbed ball sags about g / 150 = 7 cm under the chain's weight. */
const MOUSE_STIFFNESS_PER_KG = 150;
/** Damping ratio of the mouse spring on the grabbed ball. */
const MOUSE_DAMPING_RATIO = 0.7;
/** A ball within this many CSS px of the pointer can be grabbed. */
const GRAB_RADIUS_PX = 28;
const BALL_COLOR = 0x4cc9f0;

const USAGE = `Accepted: links 1-40 (integer); k 1-5000 N/m; damping 0-50 N s/m; mass 0.01-10 kg; angle -180-180 deg; integrator = ${INTEGRATOR_NAMES.join(' | ')}.`;
const url = readUrlParams(
  () => ({
    links: numberParam('links', { default: CHAIN_DEFAULTS.links, min: 1, max: 40, integer: true }),
    stiffness: numberParam('k', { default: CHAIN_DEFAULTS.stiffness, min: 1, max: 5000 }),
    damping: numberParam('damping', { default: CHAIN_DEFAULTS.damping, min: 0, max: 50 }),
    mass: numberParam('mass', { default: CHAIN_DEFAULTS.mass, min: 0.01, max: 10 }),
    angle: numberParam('angle', { default: CHAIN_DEFAULTS.angle, min: -180, max: 180 }),
    integrator: choiceParam('integrator', INTEGRATOR_NAMES, CHAIN_DEFAULTS.integrator),
  }),
  USAGE,
);

const params = { ...url, reset: () => shell.reset() };

let handles: ChainHandles;
const view: WorldRect = { minX: -5, minY: -5, maxX: 5, maxY: 1 };

/** Energy bookkeeping (live object, also on window.game). */
const energy = {
  /** Total energy now, J. */
  total: 0,
  /** Reference: the total at the start, after a parameter change or when a dragged ball is let go, J. */
  reference: 0,
  /** Largest |E - reference| since the reference was taken, J. */
  maxDrift: 0,
};

/** The current grab: ball and mouse-spring entities (0 when none). */
const grab = { ball: 0, spring: 0 };

/** Builds a fresh chain from the params; the shell calls it at start and on R. */
function createWorld(): PhysicsWorld {
  const options = {
    links: params.links,
    stiffness: params.stiffness,
    damping: params.damping,
    mass: params.mass,
    angle: params.angle,
    integrator: params.integrator as IntegratorName,
  };
  const world = createPhysicsWorld(chainWorldOptions(options));
  handles = buildChain(world, options);
  grab.ball = 0;
  grab.spring = 0;
  const R = hangingLength(handles.params) + 0.3;
  view.minX = -R;
  view.maxX = R;
  view.minY = -R * 1.05;
  view.maxY = 0.6;
  refit?.();
  baseline(world);
  return world;
}

/** Takes the energy reference now and restarts the drift measurement. */
function baseline(world: PhysicsWorld): void {
  energy.total = energy.reference = totalEnergy(world);
  energy.maxDrift = 0;
}

/** One step: physics, then the energies (package diagnostics) into the chart. */
function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  const total = totalEnergy(world);
  energy.total = total;
  if (grab.spring === 0) energy.maxDrift = Math.max(energy.maxDrift, Math.abs(total - energy.reference));
  plot?.push(world.time, total, kineticEnergy(world), gravitationalPotentialEnergy(world), springPotentialEnergy(world), energy.reference);
}

// ---- Page ------------------------------------------------------------------------------------------

let refit: (() => void) | null = null;
let plot: ReturnType<typeof createPlot> | null = null;

const game = await startPixiGame({
  title: 'Spring chain',
  createWorld,
  step: labStep,
  bodies: () => handles.balls.length,
  controls: [{ keys: 'Drag', action: 'pull a ball (mouse spring)' }],
  renderer: { view, balls: 'sprites', rotation: false },
  onFrame: (alpha, world) => drawOverlay(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);
const paint = (): void => {
  for (const b of handles.balls) renderer.setColor(b, BALL_COLOR);
};
paint();
shell.onWorldChange(paint);

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'stiffness', label: 'stiffness k (N/m)', min: 5, max: 2000, step: 1, onChange: () => applySprings() },
    { type: 'slider', key: 'damping', label: 'damping (N s/m)', min: 0, max: 5, step: 0.01, onChange: () => applySprings() },
    { type: 'slider', key: 'links', label: 'links (rebuilds)', min: 1, max: 40, step: 1, onRelease: true, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'mass',
      label: 'mass per ball (kg, rebuilds)',
      min: 0.02,
      max: 2,
      step: 0.01,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'choice',
      key: 'integrator',
      options: INTEGRATOR_NAMES,
      onChange: (name) => {
        shell.world.integrator = name as IntegratorName;
        baseline(shell.world);
      },
    },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Spring chain', container: dock.panelSlot },
);

/** Applies the panel's stiffness and damping to the running chain and takes a new energy reference. */
function applySprings(): void {
  setSpringConstants(shell.world, handles, params.stiffness, params.damping);
  if (grab.spring !== 0) shell.world.substeps = Math.max(shell.world.substeps, mouseSubsteps());
  baseline(shell.world);
}

const readout = createReadout(shell.hud.readout, ['total energy E', 'reference E₀', 'max |E − E₀|', 'substeps', 'dragging']);
plot = createPlot({
  parent: dock.charts,
  title: 'Energy',
  yLabel: 'E (J)',
  width: dock.chartWidth,
  height: 220,
  capacity: 1200,
  series: [
    { label: 'total', color: '#f8f9fa' },
    { label: 'kinetic', color: '#4cc9f0' },
    { label: 'gravity', color: '#06d6a0' },
    { label: 'springs', color: '#ff8c42' },
    { label: 'reference', color: '#ffd166', dashed: true },
  ],
});
shell.reset();

// ---- Pointer: drag a ball on a mouse spring -------------------------------------------------------

const canvas = app.canvas;
const pointer: Point2 = { x: 0, y: 0 };
const at: Point2 = { x: 0, y: 0 };
let pointerId = -1;

/** Substeps the mouse spring needs on one ball (omega h <= 0.5, as `substepsFor`). */
function mouseSubsteps(): number {
  const m = handles.params.mass;
  const k = MOUSE_STIFFNESS_PER_KG * m * handles.balls.length;
  return Math.min(64, Math.ceil((Math.sqrt(k / m) * shell.world.dt) / 0.5));
}

/**
 * Grabs ball index `i` (0 = top) with a mouse spring anchored at world point (x, y), m.
 * @throws RangeError if i is not a ball index.
 */
function grabBall(i: number, x: number, y: number): void {
  const ball = handles.balls[i];
  if (ball === undefined) throw new RangeError(`grabBall: ball index must be in [0, ${handles.balls.length - 1}], got ${i}`);
  release();
  const world = shell.world;
  const m = handles.params.mass;
  const k = MOUSE_STIFFNESS_PER_KG * m * handles.balls.length;
  const c = 2 * MOUSE_DAMPING_RATIO * Math.sqrt(k * m);
  grab.ball = ball;
  grab.spring = addSpring(world, { anchor: [x, y], b: ball, stiffness: k, restLength: 0, damping: c });
  world.substeps = Math.max(world.substeps, mouseSubsteps());
}

/** Moves the mouse spring's anchor to world point (x, y), m (the Spring component's anchor). */
function dragTo(x: number, y: number): void {
  if (grab.spring === 0) return;
  const S = shell.world.components.Spring;
  S.anchorX[slotOf(grab.spring)] = x;
  S.anchorY[slotOf(grab.spring)] = y;
}

/** Lets go of the grabbed ball (removes the mouse spring) and takes a new energy reference. */
function release(): void {
  if (grab.spring === 0) return;
  removeBody(shell.world, grab.spring);
  grab.ball = 0;
  grab.spring = 0;
  shell.world.substeps = substepsFor(handles.params.stiffness, handles.params.mass, shell.world.dt);
  baseline(shell.world);
}

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || pointerId !== -1) return;
  pointerOnCanvas(canvas, event, pointer);
  const cam = renderer.camera;
  let best = -1,
    bestD = GRAB_RADIUS_PX;
  for (let i = 0; i < handles.balls.length; i++) {
    drawnPosition(shell.world, handles.balls[i]!, 1, at);
    const d = Math.hypot(cam.toScreenX(at.x) - pointer.x, cam.toScreenY(at.y) - pointer.y);
    if (d < bestD) {
      bestD = d;
      best = i;
    }
  }
  if (best < 0) return;
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  grabBall(best, cam.toWorldX(pointer.x), cam.toWorldY(pointer.y));
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerOnCanvas(canvas, event, pointer);
  dragTo(renderer.camera.toWorldX(pointer.x), renderer.camera.toWorldY(pointer.y));
});
const up = (event: PointerEvent): void => {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  release();
};
canvas.addEventListener('pointerup', up);
canvas.addEventListener('pointercancel', up);
// A reset drops the old world's grab (its entities are gone with it).
shell.onWorldChange(() => {
  pointerId = -1;
});

// ---- Drawing ------------------------------------------------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
renderer.root.addChildAt(overlay, 1);
const pa: Point2 = { x: 0, y: 0 },
  pb: Point2 = { x: 0, y: 0 };

/** Spring colour from its strain (L - L0) / L0: blue compressed, grey at rest, red stretched. */
function strainColor(strain: number): number {
  const s = Math.max(-1, Math.min(1, strain * 4));
  const r = s > 0 ? 160 + 95 * s : 160 + 60 * s,
    g = 170 - 90 * Math.abs(s),
    b = s < 0 ? 170 - 85 * s : 170 - 90 * s;
  return (Math.round(r) << 16) | (Math.round(g) << 8) | Math.round(Math.min(255, b));
}

/** The anchor, every spring as a coil coloured by strain, and the mouse spring. */
function drawOverlay(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  overlay.clear();
  const ax = cam.toScreenX(handles.anchor[0]),
    ay = cam.toScreenY(handles.anchor[1]);
  overlay.rect(ax - 30, ay - 6, 60, 6).fill({ color: 0x8d99ae });
  for (let k = -3; k <= 3; k++) overlay.moveTo(ax + k * 9, ay - 6).lineTo(ax + k * 9 + 6, ay - 13);
  overlay.stroke({ width: 1.5, color: 0x8d99ae });
  const amp = Math.max(3, Math.min(8, cam.toScreenLength(0.06)));
  for (let i = 0; i < handles.balls.length; i++) {
    if (i === 0) {
      pa.x = handles.anchor[0];
      pa.y = handles.anchor[1];
    } else drawnPosition(world, handles.balls[i - 1]!, alpha, pa);
    drawnPosition(world, handles.balls[i]!, alpha, pb);
    const L = Math.hypot(pb.x - pa.x, pb.y - pa.y);
    drawSpring(
      overlay,
      cam.toScreenX(pa.x),
      cam.toScreenY(pa.y),
      cam.toScreenX(pb.x),
      cam.toScreenY(pb.y),
      6,
      amp,
      1.5,
      strainColor((L - LINK_LENGTH) / LINK_LENGTH),
    );
  }
  if (grab.spring !== 0) {
    const S = world.components.Spring;
    drawnPosition(world, grab.ball, alpha, pb);
    const bx = cam.toScreenX(pb.x),
      by = cam.toScreenY(pb.y);
    overlay
      .moveTo(cam.toScreenX(S.anchorX[slotOf(grab.spring)]!), cam.toScreenY(S.anchorY[slotOf(grab.spring)]!))
      .lineTo(bx, by)
      .stroke({ width: 2, color: 0xffffff, alpha: 0.6 });
    overlay.circle(bx, by, Math.max(6, cam.toScreenLength(BALL_RADIUS)) + 3).stroke({ width: 2, color: 0xffffff });
  }
  updateReadout(world);
}

let readoutFrame = 0;
/** Refreshes the readout (every 8th frame). */
function updateReadout(world: PhysicsWorld): void {
  if (readoutFrame++ % 8 !== 0) return;
  readout.set(0, `${fmt(energy.total, 6)} J`);
  readout.set(1, `${fmt(energy.reference, 6)} J`);
  readout.set(2, `${fmt(energy.maxDrift, 3)} J`);
  readout.set(3, `${world.substeps} (h = ${fmt((world.dt / world.substeps) * 1000, 3)} ms)`);
  readout.set(4, grab.spring === 0 ? 'no' : `ball ${handles.balls.indexOf(grab.ball)}`);
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** Energy bookkeeping (live object). */
  energy,
  /** The grab (live object: ball and mouse-spring entity ids, 0 when none). */
  grab,
  /** Ball ids, top to bottom (a copy). */
  balls: (): number[] => handles.balls.slice(),
  /** Spring ids, top to bottom (a copy). */
  springs: (): number[] => handles.springs.slice(),
  /** Where ball index `i` is drawn, CSS px from the canvas' top-left corner, or null. */
  ballOnScreen: (i: number): Point2 | null => {
    const b = handles.balls[i];
    return b === undefined ? null : renderer.drawnPosition(b);
  },
  grabBall,
  dragTo,
  release,
  /** Runs `n` (integer >= 0) lab steps now. @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
