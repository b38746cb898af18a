/**
 * Lab: sparks (Ramtal and Dobre ch. 12). An angle grinder (or a welding torch) follows the mouse and
 * throws a cone of fast sparks that slow down by quadratic drag, bounce off the floor and the wall and
 * fade, drawn with long streak trails and additive blending (see scene.ts for the physics).
 *
 * Input: the mouse moves the tool, Space starts / stops it, W switches grinder / welding,
 * P pause, N step, R reset.
 * URL: ?tool=grinder|welding, ?rate (0-1500 /s), ?angle (deg), ?spread (deg), ?speed (m/s), ?seed.
 */

import { choiceParam, createPanel, numberParam, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import { createReadout, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { advanceSteps, countParticles, exposeLive, hideBallLayer } from '@bitphysics/game-kit/particle-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import type { PhysicsWorld } from '@bitphysics/physics';
import type { Point2 } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import {
  configureSparks,
  createSparks,
  MAX_RATE,
  moveTool,
  SPARK_MASS,
  type Sparks,
  type SparkTool,
  setToolOn,
  stepSparks,
  TOOL_PRESETS,
  WALL_X,
} from './scene';

const VIEW = { minX: WALL_X - 0.3, minY: -0.4, maxX: 9, maxY: 6 };
/** Grinder wheel radius, m (drawn). */
const WHEEL = 0.45;

const USAGE = `Accepted: tool = grinder | welding; rate 0-${MAX_RATE} /s; angle -360..360 deg; spread 0-180 deg; speed 1-40 m/s; seed (integer).`;
const url = readUrlParams(() => {
  const tool = choiceParam('tool', ['grinder', 'welding'] as const, 'grinder') as SparkTool;
  const preset = TOOL_PRESETS[tool];
  return {
    tool,
    rate: numberParam('rate', { default: preset.rate, min: 0, max: MAX_RATE }),
    angle: numberParam('angle', { default: preset.angle, min: -360, max: 360 }),
    spread: numberParam('spread', { default: preset.spread, min: 0, max: 180 }),
    speed: numberParam('speed', { default: preset.speed, min: 1, max: 40 }),
    seed: seedParam(),
  };
}, USAGE);
const TRAILS = { duration: 0.09, width: 0.55, alpha: 0.8 };
const params = {
  ...url,
  /** Quadratic drag of a 0.1 g spark, in mg/m (the scene takes kg/m). */
  drag: 4,
  restitution: 0.45,
  trails: true,
  on: true,
  reset: () => shell.reset(),
};

let sparks: Sparks;
function createWorld(): PhysicsWorld {
  sparks = createSparks({
    tool: params.tool,
    rate: params.rate,
    angle: params.angle,
    spread: params.spread,
    speed: params.speed,
    drag: params.drag * 1e-6,
    restitution: params.restitution,
    seed: params.seed,
  });
  setToolOn(sparks, params.on);
  return sparks.world;
}

const game = await startPixiGame({
  title: 'Sparks',
  createWorld,
  step: () => stepSparks(sparks),
  bodies: (world) => countParticles(world),
  controls: [
    { keys: 'Mouse', action: 'move the tool' },
    { keys: 'Space', action: 'tool on / off' },
    { keys: 'W', action: 'grinder / welding' },
  ],
  keys: [
    { key: ' ', label: 'tool on / off', action: () => setOn(!params.on) },
    { key: 'w', label: 'tool', action: () => setTool(params.tool === 'grinder' ? 'welding' : 'grinder') },
  ],
  renderer: { view: VIEW, padding: 0, segmentColor: 0x6c7486, particles: { blend: 'add', minPixelSize: 1.5, trails: TRAILS } },
  app: { background: 0x0a0b10 },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;
// Sparks have a collider, hence a Ball: the particle layer draws them, the ball layer must not.
hideBallLayer(renderer);
const layer = renderer.particles!;

function setOn(on: boolean): void {
  params.on = on;
  setToolOn(sparks, on);
  panel.refresh();
}

function setTool(tool: SparkTool): void {
  params.tool = tool;
  Object.assign(params, TOOL_PRESETS[tool]);
  configureSparks(sparks, { tool });
  panel.refresh();
}

/** Applies the panel's cone, drag and restitution (the scene replaces the emitter when the cone changes). */
function applyCone(): void {
  configureSparks(sparks, {
    rate: params.rate,
    angle: params.angle,
    spread: params.spread,
    speed: params.speed,
    drag: params.drag * 1e-6,
    restitution: params.restitution,
  });
}

const panel = createPanel(
  params,
  [
    { type: 'choice', key: 'tool', label: 'tool (W)', options: ['grinder', 'welding'], onChange: (t) => setTool(t as SparkTool) },
    { type: 'slider', key: 'rate', label: 'rate (sparks/s)', min: 0, max: MAX_RATE, step: 10, onChange: () => applyCone() },
    { type: 'slider', key: 'angle', label: 'direction (°)', min: 0, max: 360, step: 1, onChange: () => applyCone() },
    { type: 'slider', key: 'spread', label: 'cone half-angle (°)', min: 0, max: 180, step: 1, onChange: () => applyCone() },
    { type: 'slider', key: 'speed', label: 'launch speed (m/s)', min: 1, max: 40, step: 0.5, onChange: () => applyCone() },
    { type: 'slider', key: 'drag', label: 'drag k (mg/m)', min: 0, max: 40, step: 0.5, onChange: () => applyCone() },
    { type: 'slider', key: 'restitution', label: 'floor restitution', min: 0, max: 1, step: 0.01, onChange: () => applyCone() },
    { type: 'checkbox', key: 'trails', label: 'streak trails', onChange: (v) => layer.setTrails(v === true ? TRAILS : false) },
    { type: 'checkbox', key: 'on', label: 'tool on (Space)', onChange: (v) => setOn(v === true) },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Sparks' },
);

const info = createReadout(shell.hud.readout, ['sparks alive', 'bounces', 'terminal fall speed']);

// ---- Drawing: the tool ------------------------------------------------------------------------------

const tool = new Graphics({ label: 'tool' });
renderer.root.addChild(tool);
let frame = 0;
function drawFrame(_alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  const [x, y] = sparks.at;
  const sx = cam.toScreenX(x),
    sy = cam.toScreenY(y);
  const a = (sparks.settings.angle * Math.PI) / 180;
  const dx = Math.cos(a),
    dy = Math.sin(a);
  tool.clear();
  if (sparks.settings.tool === 'grinder') {
    // The wheel touches the work at the emitter; the sparks leave its rim tangentially, so its centre
    // lies off the cone's axis, on the side away from the floor.
    let nx = -dy,
      ny = dx;
    if (ny < 0) {
      nx = -nx;
      ny = -ny;
    }
    const r = cam.toScreenLength(WHEEL);
    const cx = sx + nx * r,
      cy = sy - ny * r;
    tool.circle(cx, cy, r).fill({ color: 0x3a3f4a }).stroke({ width: 3, color: 0x8a93a6 });
    tool
      .moveTo(cx, cy)
      .lineTo(cx + nx * r * 2.2, cy - ny * r * 2.2)
      .stroke({ width: cam.toScreenLength(0.22), color: 0x2d5d8c, cap: 'round' });
  } else {
    // Torch: a nozzle pointing at the weld from up and to the right.
    const len = cam.toScreenLength(1.2);
    tool
      .moveTo(sx + 4, sy - 4)
      .lineTo(sx + len * 0.7, sy - len * 0.7)
      .stroke({ width: cam.toScreenLength(0.12), color: 0x9aa3b5, cap: 'round' });
  }
  if (sparks.on) tool.circle(sx, sy, 4).fill({ color: 0xfff3c0, alpha: 0.9 });
  if (frame++ % 6 === 0) {
    info.set(0, String(countParticles(world)));
    info.set(1, String(sparks.bounces));
    info.set(
      2,
      sparks.settings.drag > 0 ? `${Math.sqrt((SPARK_MASS * 9.81) / sparks.settings.drag).toFixed(1)} m/s (√(m g / k))` : '∞ (no drag)',
    );
  }
}

// ---- Pointer: the tool follows the mouse --------------------------------------------------------------

const canvas = app.canvas;
const at: Point2 = { x: 0, y: 0 };
canvas.addEventListener('pointermove', (event) => {
  pointerOnCanvas(canvas, event, at);
  moveTool(sparks, renderer.camera.toWorldX(at.x), renderer.camera.toWorldY(at.y));
});
canvas.addEventListener('pointerdown', (event) => {
  pointerOnCanvas(canvas, event, at);
  moveTool(sparks, renderer.camera.toWorldX(at.x), renderer.camera.toWorldY(at.y));
});

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  /** Sparks alive now. */
  particleCount: (): number => countParticles(shell.world),
  /** Runs `n` (integer >= 0) steps now. @throws RangeError otherwise. */
  advance: (n: number): void => advanceSteps(n, () => stepSparks(sparks)),
  /** The particle layer (its `stats`: drawn sparks and trails). */
  layer,
});
exposeLive(shell, {
  /** The running sparks: world, emitter, segments, tool position, settings, bounce count. */
  sparks: (): Sparks => sparks,
});
