/**
 * Lab: cloth (Ramtal and Dobre ch. 13). A grid of point masses joined by structural, shear and
 * bending links (createCloth; the XPBD cloth solver in small steps), pinned along its top edge, in
 * the world's wind with turbulence (drag on each point against the wind). Drawn as a textured mesh
 * (ClothLayer); torn cells disappear.
 *
 * Input: press on the cloth and drag: the point under the pointer follows it, and links stretched
 * past the tear strain break. Keys: P pause, N step, R reset. URL: ?size (4-64 points a side),
 * ?wind (0-20 m/s), ?tear (0.05-2).
 */

import { createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createLabDock, createReadout, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import {
  type Cloth,
  createCloth,
  createPhysicsWorld,
  type PhysicsWorld,
  step as physicsStep,
  pinClothPoint,
  query,
  removeBody,
  setWind,
  slotOf,
} from '@bitphysics/physics';
import { ClothLayer, type WorldRect } from '@bitphysics/render-pixi';

const USAGE = 'Accepted: size 4-64 points a side; wind 0-20 m/s; tear 0.05-2 (strain).';
const url = readUrlParams(
  () => ({
    size: numberParam('size', { default: 32, min: 4, max: 64, integer: true }),
    wind: numberParam('wind', { default: 7, min: 0, max: 20 }),
    tear: numberParam('tear', { default: 0.25, min: 0.05, max: 2 }),
  }),
  USAGE,
);
const params = { ...url, turbulence: 1.5, substeps: 12, reset: () => shell.reset() };

const SIDE = 4; // m
const view: WorldRect = { minX: -1, minY: -1.5, maxX: SIDE + 3, maxY: SIDE + 0.6 };
let cloth: Cloth;
let torn = 0;
let stepMs = 0;

function applyWind(world: PhysicsWorld): void {
  setWind(world, { velocity: [params.wind, 0], turbulence: { intensity: params.turbulence, lengthScale: 1.5, timeScale: 0.8, seed: 3 } });
}

function createWorld(): PhysicsWorld {
  const n = params.size;
  const world = createPhysicsWorld({ gravity: [0, -9.81], capacity: 7 * n * n + 64 });
  cloth = createCloth(world, {
    columns: n,
    rows: n,
    width: SIDE,
    height: SIDE,
    origin: [0, SIDE],
    mass: 0.6,
    tearStretch: params.tear,
    // Air drag a point, N s/m, by its share of the sheet (20 N s/m over it; it was 0.04 n, 1.3 N s/m at
    // 32 points a side, and a 4 m/s wind moved the hem 3 cm): the default 7 m/s wind sways the hem
    // about 0.7 m sideways in 3 s, and a 10 m/s gale tears the sheet from its pins.
    drag: 20 / (n * n),
  });
  world.cloth.substeps = params.substeps;
  applyWind(world);
  torn = 0;
  plot?.clear();
  return world;
}

let plot: ReturnType<typeof createPlot> | null = null;

function labStep(world: PhysicsWorld): void {
  const t0 = performance.now();
  physicsStep(world);
  stepMs = performance.now() - t0;
  torn += world.joints.breaks.count;
  plot?.push(world.time, world.cloth.maxStretch * 100, stepMs);
}

const game = await startPixiGame({
  title: 'Cloth',
  createWorld,
  step: labStep,
  controls: [{ keys: 'Drag', action: 'pull the cloth (tears past the strain)' }],
  renderer: { view },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
followView(app, renderer.camera, dock, () => view);

createPanel(
  params,
  [
    { type: 'slider', key: 'size', label: 'points a side', min: 4, max: 64, step: 1, onRelease: true, onChange: () => shell.reset() },
    { type: 'slider', key: 'wind', label: 'wind (m/s)', min: 0, max: 20, step: 0.1, onChange: () => applyWind(shell.world) },
    { type: 'slider', key: 'turbulence', label: 'turbulence (m/s RMS)', min: 0, max: 5, step: 0.1, onChange: () => applyWind(shell.world) },
    {
      type: 'slider',
      key: 'tear',
      label: 'tears at strain',
      min: 0.05,
      max: 2,
      step: 0.01,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'substeps',
      label: 'solver substeps',
      min: 1,
      max: 30,
      step: 1,
      onChange: (v) => {
        shell.world.cloth.substeps = v as number;
      },
    },
    { type: 'button', key: 'reset', label: 'new cloth (R)' },
  ],
  { title: 'Cloth', container: dock.panelSlot },
);
const readout = createReadout(shell.hud.readout, ['points', 'links', 'torn', 'largest stretch', 'step time']);
plot = createPlot({
  parent: dock.charts,
  title: 'Stretch and step time',
  yLabel: '% / ms',
  width: dock.chartWidth,
  height: 200,
  capacity: 1200,
  series: [
    { label: 'largest stretch (%)', color: '#e76f51' },
    { label: 'step (ms)', color: '#98a2b3' },
  ],
});

// Drag: the cloth point nearest the press follows the pointer (held like a pin) until release.
const canvas = app.canvas;
const at = { x: 0, y: 0 };
let held = 0;
const pointerWorld = (e: PointerEvent): [number, number] => {
  pointerOnCanvas(canvas, e, at);
  return [renderer.camera.toWorldX(at.x), renderer.camera.toWorldY(at.y)];
};
canvas.addEventListener('pointerdown', (e) => {
  if (e.button !== 0) return;
  const [x, y] = pointerWorld(e);
  held = grab(x, y);
  if (held) canvas.setPointerCapture(e.pointerId);
});
canvas.addEventListener('pointermove', (e) => {
  if (held) pinClothPoint(shell.world, held, pointerWorld(e));
});
const release = (): void => {
  if (held) {
    pinClothPoint(shell.world, held, null);
    held = 0;
  }
};
canvas.addEventListener('pointerup', release);
canvas.addEventListener('pointercancel', release);
shell.onWorldChange(() => {
  held = 0;
});

/** Grabs the moving cloth point nearest (x, y) within 0.3 m. @returns its handle, or 0. */
function grab(x: number, y: number): number {
  const P = shell.world.components.Position,
    inv = shell.world.components.Mass.inv;
  let best = 0,
    bestD = 0.3;
  for (let i = 0; i < cloth.points.length; i++) {
    const h = cloth.points[i]!,
      e = slotOf(h);
    if (!(inv[e]! > 0)) continue;
    const d = Math.hypot(P.x[e]! - x, P.y[e]! - y);
    if (d < bestD) {
      bestD = d;
      best = h;
    }
  }
  if (best) pinClothPoint(shell.world, best, [x, y]);
  return best;
}

let layer: ClothLayer | null = null;
let layerWorld: PhysicsWorld | null = null;
function draw(alpha: number, world: PhysicsWorld): void {
  if (layerWorld !== world) {
    layer?.destroy();
    layer = new ClothLayer(world, cloth);
    renderer.root.addChildAt(layer.mesh, 0);
    layerWorld = world;
  }
  layer!.update(renderer.camera, alpha);
  readout.set(0, String(cloth.points.length));
  readout.set(1, String(query(world, [world.components.ClothLink]).length));
  readout.set(2, String(torn));
  readout.set(3, `${fmt(world.cloth.maxStretch * 100)} %`);
  readout.set(4, `${fmt(stepMs)} ms`);
}

shell.expose({
  params,
  plot,
  /** The cloth's point and link handles. */
  cloth: () => cloth,
  /** Links left, and links torn since the reset. */
  links: () => query(shell.world, [shell.world.components.ClothLink]).length,
  torn: () => torn,
  /** Triangles the cloth layer draws (see ClothLayer.triangles). */
  triangles: () => layer?.triangles ?? 0,
  /** Tears one link (a link handle of `cloth().links`) as a strain past the tear would (tests). */
  removeLink: (h: number) => removeBody(shell.world, h),
  /** Runs the lab's step n times (tests). */
  advance: (n: number) => {
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
