/**
 * Lab: cloth (Ramtal and Dobre ch. 13). A grid of point masses joined by structural, shear and
 * bending links (createCloth; the XPBD cloth solver in small steps), pinned along its top edge, in
 * the world's wind with turbulence (drag on each point against the wind). Drawn as a textured mesh
 * (ClothLayer); torn cells disappear, and torn pieces fall to the floor of the room (the world's
 * boundary box), where the wind drives them to the right wall.
 *
 * Input: press on the cloth and drag: the hand grips the patch under the pointer softly (scene.ts'
 * ClothGrab: a spring of bounded force on each point within 0.35 m), so a gentle pull stretches and
 * swings the sheet, and a hard or fast one tears links stretched past the tear strain. Keys: P pause,
 * N step, R reset. URL: ?size (4-64 points a side), ?wind (0-20 m/s), ?tear (0.05-2).
 */

import { createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createLabDock, createReadout, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import { type Cloth, type PhysicsWorld, step as physicsStep, query, removeBody, slotOf } from '@bitphysics/physics';
import { ClothLayer, type WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { applyWind as applySceneWind, CLOTH_SUBSTEPS, ClothGrab, createClothScene, gripFor, ROOM, SIDE } from './scene';

const USAGE = 'Accepted: size 4-64 points a side; wind 0-20 m/s; tear 0.05-2 (strain).';
const url = readUrlParams(
  () => ({
    size: numberParam('size', { default: 32, min: 4, max: 64, integer: true }),
    wind: numberParam('wind', { default: 7, min: 0, max: 20 }),
    // 0.3: at 24 substeps the default wind stretches the upwind top corner 9% and a 12 m/s gale 15%;
    // a slow 1.25 m pull tears nothing (at 0.2 it tore up to 369 links), a 2.4 m pull or a fast yank
    // tears the sheet (scene.ts GRAB).
    tear: numberParam('tear', { default: 0.3, min: 0.05, max: 2 }),
  }),
  USAGE,
);
const params = { ...url, turbulence: 1.5, substeps: CLOTH_SUBSTEPS, reset: () => shell.reset() };

const view: WorldRect = { minX: ROOM.minX, minY: ROOM.minY - 0.3, maxX: ROOM.maxX, maxY: SIDE + 0.6 };
let cloth: Cloth;
/** The hand's grip while the pointer holds the cloth. */
let grab: ClothGrab | null = null;
let torn = 0;
let stepMs = 0;

function applyWind(world: PhysicsWorld): void {
  applySceneWind(world, params);
}

function createWorld(): PhysicsWorld {
  const scene = createClothScene(params);
  cloth = scene.cloth;
  grab = null;
  torn = 0;
  plot?.clear();
  return scene.world;
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
  controls: [{ keys: 'Drag', action: 'pull the cloth (a hard or fast pull tears it)' }],
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

// Drag: the hand grips the cloth around the press (ClothGrab) and follows the pointer until release.
const canvas = app.canvas;
const at = { x: 0, y: 0 };
const pointerWorld = (e: PointerEvent): [number, number] => {
  pointerOnCanvas(canvas, e, at);
  return [renderer.camera.toWorldX(at.x), renderer.camera.toWorldY(at.y)];
};
canvas.addEventListener('pointerdown', (e) => {
  if (e.button !== 0) return;
  const [x, y] = pointerWorld(e);
  grab?.release();
  grab = ClothGrab.at(shell.world, cloth, x, y, gripFor(params.size));
  if (grab) canvas.setPointerCapture(e.pointerId);
});
canvas.addEventListener('pointermove', (e) => {
  if (grab) grab.moveTo(...pointerWorld(e));
});
const release = (): void => {
  grab?.release();
  grab = null;
};
canvas.addEventListener('pointerup', release);
canvas.addEventListener('pointercancel', release);
shell.onWorldChange(() => {
  grab = null;
});

/** The hand: a ring at the pointer and a cord to the middle of the held patch, brighter the harder it pulls. */
const hand = new Graphics({ label: 'hand' });
function drawHand(world: PhysicsWorld): void {
  hand.clear();
  if (!grab) return;
  const cam = renderer.camera,
    P = world.components.Position;
  let x = 0,
    y = 0;
  for (let i = 0; i < grab.points.length; i++) {
    const e = slotOf(grab.points[i]!);
    x += grab.weights[i]! * P.x[e]!;
    y += grab.weights[i]! * P.y[e]!;
  }
  const pull = Math.min(1, grab.force() / grab.options.maxForce);
  const hx = cam.toScreenX(grab.hand[0]),
    hy = cam.toScreenY(grab.hand[1]);
  hand
    .moveTo(cam.toScreenX(x), cam.toScreenY(y))
    .lineTo(hx, hy)
    .stroke({ width: 2, color: 0xffd166, alpha: 0.35 + 0.6 * pull });
  hand.circle(cam.toScreenX(x), cam.toScreenY(y), 3).fill({ color: 0xffd166, alpha: 0.8 });
  hand.circle(hx, hy, 9).stroke({ width: 2, color: 0xffd166, alpha: 0.9 });
}

/** The floor the torn pieces land on (the boundary box's, scene.ts ROOM) and the rod the sheet is pinned to, drawn below the sheet. */
const floor = new Graphics({ label: 'floor' });
function drawFloor(): void {
  const cam = renderer.camera;
  const x0 = cam.toScreenX(ROOM.minX - 50),
    x1 = cam.toScreenX(ROOM.maxX + 50),
    top = cam.toScreenY(ROOM.minY),
    bottom = cam.toScreenY(ROOM.minY - 50);
  floor.clear();
  floor.rect(x0, top, x1 - x0, bottom - top).fill({ color: 0x2b2f36 });
  floor.moveTo(x0, top).lineTo(x1, top).stroke({ width: 2, color: 0x5c6370 });
  const rodY = cam.toScreenY(SIDE);
  floor
    .moveTo(cam.toScreenX(-0.25), rodY)
    .lineTo(cam.toScreenX(SIDE + 0.25), rodY)
    .stroke({ width: 6, color: 0x8a8f98, cap: 'round' });
}

let layer: ClothLayer | null = null;
let layerWorld: PhysicsWorld | null = null;
function draw(alpha: number, world: PhysicsWorld): void {
  if (layerWorld !== world) {
    layer?.destroy();
    layer = new ClothLayer(world, cloth);
    renderer.root.addChildAt(layer.mesh, 0);
    if (!floor.parent) renderer.root.addChildAt(floor, 0);
    if (!hand.parent) renderer.root.addChild(hand);
    layerWorld = world;
  }
  layer!.update(renderer.camera, alpha);
  drawFloor();
  drawHand(world);
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
  /** The hand's grip while the pointer holds the cloth, else null. */
  grab: () => grab,
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
