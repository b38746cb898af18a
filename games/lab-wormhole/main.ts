/**
 * Lab: wormhole (Ramtal and Dobre ch. 12). Stars spiral into a black hole (an Attractor), and each
 * one that crosses its horizon comes out of a white hole with the same speed and the reflected
 * direction; the white hole pushes them away with an inverse-square central force (an Attractor
 * cannot push: see scene.ts for how the push is composed). Drag takes away the energy the white hole
 * gives, so the stars loop back: between the holes they trace the field lines of a source and a sink.
 * Trails are velocity streaks drawn by render-pixi's PointLayer, coloured by speed.
 *
 * Input: drag a hole to move it, click elsewhere to add 40 stars, T trails, P pause, N step, R reset.
 * URL: ?count (1-20000 stars), ?bh and ?wh (G M of the holes, m^3/s^2), ?horizon (m), ?drag (1/s), ?seed.
 */

import { createPanel, flagParam, numberParam, plural, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import { createReadout, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { advanceSteps, exposeLive, fmt } from '@bitphysics/game-kit/particle-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import type { PhysicsWorld } from '@bitphysics/physics';
import { type Point2, PointLayer } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import {
  addStar,
  BLACK_HOLE_SOFTENING,
  createWormhole,
  moveHole,
  setBlackHoleMass,
  setHorizon,
  setStarDrag,
  setWhiteHoleStrength,
  stepWormhole,
  type Wormhole,
} from './scene';

/** Stars a click adds, in a disc of this radius (m). */
const CLICK_STARS = 40,
  CLICK_RADIUS = 0.8;
/** A press moving less than this, CSS px, is a click. */
const CLICK_SLOP = 6;

const USAGE =
  'Accepted: count 1-20000 (integer); bh 1-300 and wh 0-300 (m³/s²); horizon 0.35-3 m; drag 0-3 /s; trails 0|1; seed (integer).';
const search = new URLSearchParams(location.search);
const url = readUrlParams(
  () => ({
    count: numberParam('count', { default: 2000, min: 1, max: 20_000, integer: true }),
    blackHole: numberParam('bh', { default: 60, min: 1, max: 300 }),
    whiteHole: numberParam('wh', { default: 30, min: 0, max: 300 }),
    horizon: numberParam('horizon', { default: 0.8, min: 0.35, max: 3 }),
    drag: numberParam('drag', { default: 0.5, min: 0, max: 3 }),
    trails: search.has('trails') ? flagParam('trails') : true,
    seed: seedParam(),
  }),
  USAGE,
);

const params = { ...url, trailLength: 0.12, reset: () => shell.reset() };

let hole: Wormhole;

function createWorld(): PhysicsWorld {
  hole = createWormhole({
    count: params.count,
    blackHole: params.blackHole,
    whiteHole: params.whiteHole,
    horizon: params.horizon,
    drag: params.drag,
    seed: params.seed,
  });
  return hole.world;
}

const game = await startPixiGame({
  title: 'Wormhole',
  createWorld,
  step: () => stepWormhole(hole),
  bodies: () => hole.count,
  controls: [
    { keys: 'Drag', action: 'move a hole' },
    { keys: 'Click', action: `add ${CLICK_STARS} stars` },
    { keys: 'T', action: 'trails on / off' },
  ],
  keys: [{ key: 't', label: 'trails', action: () => setTrails(!params.trails) }],
  renderer: { view: { minX: -17, minY: -10.5, maxX: 17, maxY: 10.5 }, padding: 4 },
  app: { background: 0x03040a },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;

const holes = new Graphics({ label: 'holes' });
const trailOptions = () => ({ duration: params.trailLength, width: 1.6, alpha: 0.55 });
const points = new PointLayer({
  size: 2.5,
  blend: 'add',
  colorBy: 'speed',
  range: [0, 14],
  palette: [0x6a5cff, 0x8fb8ff, 0xffffff, 0xffd36b, 0xff7b39],
  trails: params.trails ? trailOptions() : false,
});
renderer.root.addChild(holes, points.container);

function setTrails(on: boolean): void {
  params.trails = on;
  points.setTrails(on ? trailOptions() : false);
  panel.refresh();
}

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'blackHole',
      label: 'black hole G M (m³/s²)',
      min: 5,
      max: 300,
      step: 1,
      onChange: (v) => setBlackHoleMass(hole, v),
    },
    {
      type: 'slider',
      key: 'whiteHole',
      label: 'white hole push G Mw (m³/s²)',
      min: 0,
      max: 300,
      step: 1,
      onChange: (v) => setWhiteHoleStrength(hole, v),
    },
    { type: 'slider', key: 'horizon', label: 'horizon radius (m)', min: 0.35, max: 3, step: 0.05, onChange: (v) => setHorizon(hole, v) },
    { type: 'slider', key: 'drag', label: 'drag (1/s)', min: 0, max: 3, step: 0.01, onChange: (v) => setStarDrag(hole, v) },
    {
      type: 'slider',
      key: 'count',
      label: 'stars (rebuilds)',
      min: 100,
      max: 10_000,
      step: 100,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'trails', label: 'trails (T)', onChange: (v) => setTrails(v === true) },
    {
      type: 'slider',
      key: 'trailLength',
      label: 'trail length (s)',
      min: 0.02,
      max: 0.5,
      step: 0.01,
      onChange: () => {
        if (params.trails) points.setTrails(trailOptions());
      },
    },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Wormhole' },
);

const info = createReadout(shell.hud.readout, [
  'through the wormhole',
  'last jump',
  're-entered',
  'net far-field G M',
  'black hole',
  'white hole',
]);

// ---- Drawing --------------------------------------------------------------------------------------

let frame = 0;
function drawFrame(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  const P = world.components.Position;
  holes.clear();
  const rh = Math.max(3, cam.toScreenLength(hole.settings.horizon));
  const bx = cam.toScreenX(P.x[hole.blackHole]!),
    by = cam.toScreenY(P.y[hole.blackHole]!);
  holes.circle(bx, by, rh * 2.2).fill({ color: 0xff8a3d, alpha: 0.07 });
  holes.circle(bx, by, rh * 1.35).stroke({ width: 3, color: 0xffa14d, alpha: 0.45 });
  holes.circle(bx, by, rh).fill({ color: 0x000000 }).stroke({ width: 1.5, color: 0xffc680, alpha: 0.9 });
  const wx = cam.toScreenX(P.x[hole.whiteHole]!),
    wy = cam.toScreenY(P.y[hole.whiteHole]!);
  holes.circle(wx, wy, rh * 2.4).fill({ color: 0x9fc4ff, alpha: 0.08 });
  holes.circle(wx, wy, rh * 1.5).fill({ color: 0xd8e6ff, alpha: 0.25 });
  holes.circle(wx, wy, rh).fill({ color: 0xffffff, alpha: 0.9 });
  points.render(world, cam, alpha);
  if (frame++ % 6 === 0) {
    info.set(0, plural(hole.teleports, 'star', 'stars'));
    info.set(1, Number.isNaN(hole.last.speedIn) ? '–' : `${fmt(hole.last.speedIn)} m/s in, ${fmt(hole.last.speedOut)} m/s out`);
    info.set(2, `${plural(hole.respawns, 'star', 'stars')} back into the disc`);
    info.set(3, `${fmt(hole.settings.blackHole - hole.settings.whiteHole)} m³/s² (black − white)`);
    info.set(4, 'Attractor, |F| = G M m r / (r² + ε²)^(3/2) inward');
    info.set(5, 'central force k r^(n−1), n = −1, k = +G Mw m: outward');
  }
}

// ---- Pointer: drag a hole, click to add stars --------------------------------------------------------

const canvas = app.canvas;
const down: Point2 = { x: 0, y: 0 },
  now: Point2 = { x: 0, y: 0 };
let pointerId = -1,
  dragged = false,
  held: 'black' | 'white' | null = null;

/** The hole within reach of screen point (sx, sy), px, or null. */
function holeNear(sx: number, sy: number): 'black' | 'white' | null {
  const cam = renderer.camera;
  const P = shell.world.components.Position;
  const reach = Math.max(14, cam.toScreenLength(hole.settings.horizon) * 1.6);
  for (const which of ['black', 'white'] as const) {
    const e = which === 'black' ? hole.blackHole : hole.whiteHole;
    if (Math.hypot(cam.toScreenX(P.x[e]!) - sx, cam.toScreenY(P.y[e]!) - sy) <= reach) return which;
  }
  return null;
}

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || pointerId !== -1) return;
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  pointerOnCanvas(canvas, event, down);
  dragged = false;
  held = holeNear(down.x, down.y);
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerOnCanvas(canvas, event, now);
  if (Math.hypot(now.x - down.x, now.y - down.y) > CLICK_SLOP) dragged = true;
  if (held && dragged) moveHole(hole, held, renderer.camera.toWorldX(now.x), renderer.camera.toWorldY(now.y));
});
canvas.addEventListener('pointerup', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  if (!held && !dragged) addCluster(renderer.camera.toWorldX(down.x), renderer.camera.toWorldY(down.y));
  held = null;
});
canvas.addEventListener('pointercancel', (event) => {
  if (event.pointerId === pointerId) {
    pointerId = -1;
    held = null;
  }
});

/** Adds up to CLICK_STARS stars at rest in a disc about (x, y), m. @returns how many were added. */
function addCluster(x: number, y: number): number {
  let n = 0;
  for (let i = 0; i < CLICK_STARS; i++) {
    const a = hole.rng.range(0, 2 * Math.PI),
      r = CLICK_RADIUS * Math.sqrt(hole.rng.next());
    if (addStar(hole, x + r * Math.cos(a), y + r * Math.sin(a)) === 0) break;
    n++;
  }
  return n;
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  points,
  /** Runs `n` (integer >= 0) lab steps now (physics, wormhole and re-entry rules). @throws RangeError otherwise. */
  advance: (n: number): void => advanceSteps(n, () => stepWormhole(hole)),
  /** Adds a cluster of stars about (x, y), m. @returns how many were added. */
  addCluster,
  /** Moves a hole to (x, y), m. */
  moveHole: (which: 'black' | 'white', x: number, y: number): void => moveHole(hole, which, x, y),
  /** The black hole's softening, m (its pull is softened inside it). */
  softening: BLACK_HOLE_SOFTENING,
});
exposeLive(shell, {
  /** The running wormhole: ids, settings, counters (`teleports`, `respawns`, `last`). */
  hole: (): Wormhole => hole,
});
