/**
 * Lab: attractors (Ramtal and Dobre ch. 12, "particles in force fields"). Thousands of particles move
 * in the summed field of several softened attractors, optionally stirred by a vortex about the
 * origin and slowed by drag; their velocity streaks (render-pixi's PointLayer) show the flow,
 * coloured by speed. See scene.ts for the physics.
 *
 * Input: click adds an attractor (up to 8), drag one to move it, right-click or shift-click one to
 * remove it; V vortex on / off, T trails, P pause, N step, R reset.
 * URL: ?count (1-50000 particles), ?mass (G M, m^3/s^2), ?softening (m), ?drag (N s/m), ?vortex=0|1,
 * ?strength (vortex, N), ?seed.
 */

import { createPanel, flagParam, numberParam, plural, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import { createReadout, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { advanceSteps, exposeLive } from '@bitphysics/game-kit/particle-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { type Point2, PointLayer } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import {
  type AttractorField,
  addAttractor,
  attractorNear,
  createAttractorField,
  MAX_ATTRACTORS,
  moveAttractor,
  removeAttractor,
  START_AREA,
  setAttractorField,
  setParticleDrag,
  setVortexOn,
  stepAttractors,
} from './scene';

/** A press moving less than this, CSS px, is a click. */
const CLICK_SLOP = 6;
/** How close to an attractor a press must be to grab it, CSS px. */
const REACH_PX = 18;

const USAGE =
  'Accepted: count 1-50000 (integer); mass 1-500 m³/s²; softening 0-3 m; drag 0-2 N s/m; vortex 0|1; strength -10..10 N; trails 0|1; seed (integer).';
const search = new URLSearchParams(location.search);
const url = readUrlParams(
  () => ({
    count: numberParam('count', { default: 3000, min: 1, max: 50_000, integer: true }),
    mass: numberParam('mass', { default: 40, min: 1, max: 500 }),
    softening: numberParam('softening', { default: 0.4, min: 0, max: 3 }),
    drag: numberParam('drag', { default: 0.05, min: 0, max: 2 }),
    vortex: search.has('vortex') ? flagParam('vortex') : false,
    vortexStrength: numberParam('strength', { default: 2, min: -10, max: 10 }),
    trails: search.has('trails') ? flagParam('trails') : true,
    seed: seedParam(),
  }),
  USAGE,
);
const params = { ...url, reset: () => shell.reset(), clear: () => clearAttractors() };

let field: AttractorField;
function createWorld(): PhysicsWorld {
  field = createAttractorField({
    count: params.count,
    mass: params.mass,
    softening: params.softening,
    drag: params.drag,
    vortex: params.vortex,
    vortexStrength: params.vortexStrength,
    seed: params.seed,
  });
  return field.world;
}

const game = await startPixiGame({
  title: 'Attractors',
  createWorld,
  step: () => stepAttractors(field),
  bodies: () => field.particles.length,
  controls: [
    { keys: 'Click', action: `add an attractor (up to ${MAX_ATTRACTORS})` },
    { keys: 'Drag', action: 'move an attractor' },
    { keys: 'Right-click', action: 'remove an attractor (or Shift+click)' },
    { keys: 'V', action: 'vortex on / off' },
    { keys: 'T', action: 'trails on / off' },
  ],
  keys: [
    { key: 'v', label: 'vortex', action: () => setVortex(!params.vortex) },
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
  ],
  renderer: { view: { minX: -START_AREA.w, minY: -START_AREA.h, maxX: START_AREA.w, maxY: START_AREA.h }, padding: 4 },
  app: { background: 0x05060c },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;

const TRAILS = { duration: 0.1, width: 1.4, alpha: 0.5 };
const points = new PointLayer({
  size: 2,
  blend: 'add',
  colorBy: 'speed',
  range: [0, 12],
  palette: [0x2f4cff, 0x39c6ff, 0xb8ffd9, 0xffe66b, 0xff5e3a],
  trails: params.trails ? TRAILS : false,
});
const marks = new Graphics({ label: 'attractors' });
renderer.root.addChild(points.container, marks);

function setTrails(on: boolean): void {
  params.trails = on;
  points.setTrails(on ? TRAILS : false);
  panel.refresh();
}

function setVortex(on: boolean): void {
  params.vortex = on;
  setVortexOn(field, on, params.vortexStrength);
  panel.refresh();
}

/** Removes every attractor. */
function clearAttractors(): void {
  while (field.attractorCount > 0) removeAttractor(field, field.attractors[0]!);
}

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'mass',
      label: 'attractor G M (m³/s²)',
      min: 1,
      max: 200,
      step: 1,
      onChange: (m, p) => setAttractorField(field, m, p.softening),
    },
    {
      type: 'slider',
      key: 'softening',
      label: 'softening (m)',
      min: 0,
      max: 3,
      step: 0.01,
      onChange: (s, p) => setAttractorField(field, p.mass, s),
    },
    { type: 'slider', key: 'drag', label: 'drag (N s/m)', min: 0, max: 2, step: 0.01, onChange: (k) => setParticleDrag(field, k) },
    { type: 'checkbox', key: 'vortex', label: 'vortex (V)', onChange: (v) => setVortex(v === true) },
    {
      type: 'slider',
      key: 'vortexStrength',
      label: 'vortex strength (N)',
      min: -10,
      max: 10,
      step: 0.1,
      onChange: (k) => setVortexOn(field, params.vortex, k),
    },
    {
      type: 'slider',
      key: 'count',
      label: 'particles (rebuilds)',
      min: 100,
      max: 30_000,
      step: 100,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'trails', label: 'trails (T)', onChange: (v) => setTrails(v === true) },
    { type: 'button', key: 'clear', label: 'remove every attractor' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Attractors' },
);

const info = createReadout(shell.hud.readout, ['attractors', 'vortex', 'escaped and put back']);

// ---- Drawing --------------------------------------------------------------------------------------

let frame = 0;
function drawFrame(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  points.render(world, cam, alpha);
  marks.clear();
  const P = world.components.Position;
  const r = Math.max(5, cam.toScreenLength(0.15 + 0.03 * Math.sqrt(field.settings.mass)));
  for (let i = 0; i < field.attractorCount; i++) {
    const e = field.attractors[i]!;
    const x = cam.toScreenX(P.x[slotOf(e)]!),
      y = cam.toScreenY(P.y[slotOf(e)]!);
    const soft = cam.toScreenLength(field.settings.softening);
    if (soft > 2) marks.circle(x, y, soft).stroke({ width: 1, color: 0xffd08a, alpha: 0.35 });
    marks.circle(x, y, r * 2).fill({ color: 0xffb347, alpha: 0.12 });
    marks.circle(x, y, r).fill({ color: 0xfff1cf }).stroke({ width: 2, color: 0xffa033 });
  }
  if (params.vortex) {
    // A swirl mark at the vortex centre, turning the way the vortex pushes.
    const cx = cam.toScreenX(0),
      cy = cam.toScreenY(0),
      s = params.vortexStrength >= 0 ? -1 : 1;
    for (let k = 0; k < 3; k++) {
      const a0 = (k * 2 * Math.PI) / 3;
      marks
        .moveTo(cx + 14 * Math.cos(a0), cy + 14 * Math.sin(a0))
        .arc(cx, cy, 14, a0, a0 + s * 1.6, s < 0)
        .stroke({ width: 2, color: 0x7fd1ff, alpha: 0.7 });
    }
  }
  if (frame++ % 6 === 0) {
    info.set(0, `${field.attractorCount} of ${MAX_ATTRACTORS}`);
    info.set(
      1,
      params.vortex
        ? `${params.vortexStrength} N (steady swirl ${params.drag > 0 ? (params.vortexStrength / params.drag).toFixed(1) : '∞'} m/s)`
        : 'off',
    );
    info.set(2, plural(field.returns, 'particle', 'particles'));
  }
}

// ---- Pointer: click adds, drag moves, right-click / shift-click removes --------------------------------

const canvas = app.canvas;
const down: Point2 = { x: 0, y: 0 },
  now: Point2 = { x: 0, y: 0 };
let pointerId = -1,
  dragged = false,
  held = 0;
canvas.addEventListener('contextmenu', (event) => event.preventDefault());

/** The attractor under screen point (sx, sy), px, or 0. */
function attractorAt(sx: number, sy: number): number {
  const cam = renderer.camera;
  return attractorNear(field, cam.toWorldX(sx), cam.toWorldY(sy), REACH_PX / cam.pixelsPerMeter);
}

canvas.addEventListener('pointerdown', (event) => {
  pointerOnCanvas(canvas, event, down);
  if (event.button === 2 || (event.button === 0 && event.shiftKey)) {
    const e = attractorAt(down.x, down.y);
    if (e !== 0) removeAttractor(field, e);
    return;
  }
  if (event.button !== 0 || pointerId !== -1) return;
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  dragged = false;
  held = attractorAt(down.x, down.y);
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerOnCanvas(canvas, event, now);
  if (Math.hypot(now.x - down.x, now.y - down.y) > CLICK_SLOP) dragged = true;
  if (held !== 0 && dragged) moveAttractor(field, held, renderer.camera.toWorldX(now.x), renderer.camera.toWorldY(now.y));
});
canvas.addEventListener('pointerup', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  if (held === 0 && !dragged) addAttractor(field, renderer.camera.toWorldX(down.x), renderer.camera.toWorldY(down.y));
  held = 0;
});
canvas.addEventListener('pointercancel', (event) => {
  if (event.pointerId === pointerId) {
    pointerId = -1;
    held = 0;
  }
});

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  points,
  /** Attractor ids in use (a copy). */
  attractorIds: (): number[] => Array.from(field.attractors.subarray(0, field.attractorCount)),
  /** Runs `n` (integer >= 0) steps now. @throws RangeError otherwise. */
  advance: (n: number): void => advanceSteps(n, () => stepAttractors(field)),
  /** Adds an attractor at (x, y), m. @returns its id, or 0 when there are already MAX_ATTRACTORS. */
  addAttractor: (x: number, y: number): number => addAttractor(field, x, y),
});
exposeLive(shell, {
  /** The running field: particles, attractors, settings, returns. */
  field: (): AttractorField => field,
});
