/**
 * Lab: a rope (Ramtal and Dobre ch. 13). A chain of point masses joined by distance joints that only
 * pull (createRope), pinned at the top, with a ball as its bob. The joints are solved in the contact
 * solver's soft substeps; the rope is drawn as one smooth line (RopeLayer).
 *
 * Input: drag the bob (or any rope point) to swing it (a mouse joint); click the rope to cut the link
 * there; the pieces fall to the floor. Keys: P pause, N step, R reset. URL: ?segments (2-200), ?length (1-20 m), ?mass (0.1-20 kg).
 */

import { createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { enableMouseDrag } from '@bitphysics/game-kit/drag';
import { createLabDock, createReadout, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import {
  addBody,
  addBox,
  addDistanceJoint,
  createPhysicsWorld,
  createRope,
  isAlive,
  type PhysicsWorld,
  step as physicsStep,
  type Rope,
  removeJoint,
  slotOf,
} from '@bitphysics/physics';
import { RopeLayer, type WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';

const USAGE = 'Accepted: segments 2-200; length 1-20 m; mass 0.1-20 kg.';
const url = readUrlParams(
  () => ({
    segments: numberParam('segments', { default: 30, min: 2, max: 200, integer: true }),
    length: numberParam('length', { default: 5, min: 1, max: 20 }),
    mass: numberParam('mass', { default: 1, min: 0.1, max: 20 }),
  }),
  USAGE,
);
const params = { ...url, bobMass: 2, slack: true, gravity: 9.81, reset: () => shell.reset() };

const PIN: [number, number] = [0, 3];
/** The floor's top, m: a cut rope and its bob land on it (they fell for ever). */
const FLOOR_Y = -2.9;
/** What the camera shows: 12 m wide, or 10 m on a tall screen (a phone upright), where the rope is then drawn larger. */
const WIDE_VIEW: WorldRect = { minX: -6, minY: -3.2, maxX: 6, maxY: 3.6 };
const TALL_VIEW: WorldRect = { minX: -5, minY: -3.2, maxX: 5, maxY: 3.6 };
const view = (): WorldRect => (app.canvas.clientHeight > app.canvas.clientWidth ? TALL_VIEW : WIDE_VIEW);
/** The rope's colour (RopeLayer's default). */
const ROPE_COLOR = 0xd9b38c;
let rope: Rope;
let bob = 0;
let bobLink = 0;
let cuts = 0;

/** Builds the rope: pinned at PIN, laid out 60 degrees from the vertical so it swings at once. */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld({ gravity: [0, -params.gravity], capacity: 1000 });
  const L = params.length,
    a = Math.PI / 3;
  const end: [number, number] = [PIN[0] + L * Math.sin(a), PIN[1] - L * Math.cos(a)];
  // The links have a radius so the rope lies on the floor; a rope 8 m long reaches it.
  rope = createRope(world, {
    start: PIN,
    end,
    segments: params.segments,
    mass: params.mass,
    slack: params.slack,
    drag: 0.01,
    radius: 0.03,
  });
  addBox(world, { position: [0, FLOOR_Y - 0.2], halfExtents: [30, 0.2], static: true, friction: 0.6 });
  const last = rope.bodies[rope.bodies.length - 1]!;
  bob = addBody(world, {
    position: [end[0] + 0.3 * Math.sin(a), end[1] - 0.3 * Math.cos(a)],
    mass: params.bobMass,
    radius: 0.25,
    restitution: 0.3,
  });
  bobLink = addDistanceJoint(world, { a: last, b: bob, ...(params.slack ? { minLength: 0 } : {}) });
  cuts = 0;
  plot?.clear();
  return world;
}

let plot: ReturnType<typeof createPlot> | null = null;

function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  const b = slotOf(bob);
  plot?.push(world.time, world.components.Position.y[b]!, world.joints.stats.maxError * 1000);
}

const game = await startPixiGame({
  title: 'Rope',
  createWorld,
  step: labStep,
  controls: [
    { keys: 'Drag', action: 'swing the bob or rope' },
    { keys: 'Click', action: 'cut the rope there' },
  ],
  renderer: { view: WIDE_VIEW, balls: 'sprites' },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
followView(app, renderer.camera, dock, view);

createPanel(
  params,
  [
    { type: 'slider', key: 'segments', label: 'segments', min: 2, max: 200, step: 1, onRelease: true, onChange: () => shell.reset() },
    { type: 'slider', key: 'length', label: 'length (m)', min: 1, max: 8, step: 0.1, onRelease: true, onChange: () => shell.reset() },
    { type: 'slider', key: 'mass', label: 'rope mass (kg)', min: 0.1, max: 20, step: 0.1, onRelease: true, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'bobMass',
      label: 'bob mass (kg)',
      min: 0.1,
      max: 50,
      step: 0.1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'slack', label: 'links only pull (rope), else rods', onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'gravity',
      label: 'gravity g (m/s²)',
      min: 0,
      max: 30,
      step: 0.01,
      onChange: (g) => {
        shell.world.gravity[1] = -(g as number);
      },
    },
    { type: 'button', key: 'reset', label: 'new rope (R)' },
  ],
  { title: 'Rope', container: dock.panelSlot },
);
const readout = createReadout(shell.hud.readout, ['links', 'cuts', 'largest link error', 'bob speed', 'tension at the pin']);
plot = createPlot({
  parent: dock.charts,
  title: 'Bob height and link error',
  yLabel: 'y (m) / error (mm)',
  width: dock.chartWidth,
  height: 200,
  capacity: 1200,
  series: [
    { label: 'bob height (m)', color: '#4cc9f0' },
    { label: 'largest link error (mm)', color: '#f4a261' },
  ],
});

// Cut: a click near the rope (not on the bob) removes the nearest link; otherwise the press drags.
const canvas = app.canvas;
const at = { x: 0, y: 0 };
canvas.addEventListener('pointerdown', (e) => {
  if (e.button !== 0) return;
  pointerOnCanvas(canvas, e, at);
  const x = renderer.camera.toWorldX(at.x),
    y = renderer.camera.toWorldY(at.y);
  if (cutAt(x, y)) e.stopImmediatePropagation();
});
const drag = enableMouseDrag(
  canvas,
  () => shell.world,
  () => renderer.camera,
  { reach: 0.4 },
);

/**
 * Removes the rope link nearest to world point (x, y) if it is within 0.15 m and the point is not on
 * the bob. @returns whether a link was cut.
 */
function cutAt(x: number, y: number): boolean {
  const world = shell.world,
    P = world.components.Position;
  const b = slotOf(bob);
  if (Math.hypot(P.x[b]! - x, P.y[b]! - y) < 0.4) return false;
  const J = world.components.Joint;
  let best = 0,
    bestD = 0.15;
  for (const h of [...rope.joints, bobLink]) {
    if (!isAlive(world, h)) continue;
    const j = slotOf(h);
    const a = J.a[j]!,
      bb = J.b[j]!;
    const ax = a === 0 ? J.localAx[j]! : P.x[a]!,
      ay = a === 0 ? J.localAy[j]! : P.y[a]!;
    const d = segmentDistance(x, y, ax, ay, P.x[bb]!, P.y[bb]!);
    if (d < bestD) {
      bestD = d;
      best = h;
    }
  }
  if (!best) return false;
  removeJoint(world, best);
  cuts++;
  return true;
}

function segmentDistance(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const dx = bx - ax,
    dy = by - ay,
    l2 = dx * dx + dy * dy;
  const t = l2 > 0 ? Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / l2)) : 0;
  return Math.hypot(px - ax - t * dx, py - ay - t * dy);
}

/** The support the rope hangs from: a short beam at PIN, hatched on top as a fixed support is drawn. */
const support = new Graphics({ label: 'support' });
renderer.root.addChild(support);
function drawSupport(): void {
  const cam = renderer.camera;
  const x = cam.toScreenX(PIN[0]),
    y = cam.toScreenY(PIN[1]),
    half = Math.max(18, cam.toScreenLength(0.45)),
    h = Math.max(6, cam.toScreenLength(0.12));
  support.clear();
  support.rect(x - half, y - h, 2 * half, h).fill(0x8a94a6);
  for (let i = -half; i < half; i += 8) support.moveTo(x + i, y - h).lineTo(x + i + 8, y - h - 8);
  support.stroke({ width: 2, color: 0x8a94a6 });
  support.circle(x, y, Math.max(3, cam.toScreenLength(0.06))).fill(0xe8ecf1);
}

const line = new RopeLayer(shell.world, [], { width: 0.06 });
let layer = line;
let layerWorld: PhysicsWorld | null = null;
function draw(alpha: number, world: PhysicsWorld): void {
  if (layerWorld !== world) {
    layer.destroy();
    layer = new RopeLayer(world, [...rope.bodies, bob], { start: PIN, width: 0.06, links: [...rope.joints, bobLink], color: ROPE_COLOR });
    // The links' colliders are drawn in the rope's colour, so the rope reads as one line.
    for (const b of rope.bodies) renderer.setColor(b, ROPE_COLOR);
    renderer.root.addChildAt(layer.graphics, 0);
    layerWorld = world;
  }
  layer.update(renderer.camera, alpha);
  drawSupport();
  const links = [...rope.joints, bobLink].filter((h) => isAlive(world, h)).length;
  const V = world.components.Velocity,
    b = slotOf(bob);
  readout.set(0, String(links));
  readout.set(1, String(cuts));
  readout.set(2, `${fmt(world.joints.stats.maxError * 1000)} mm`);
  readout.set(3, `${fmt(Math.hypot(V.x[b]!, V.y[b]!))} m/s`);
  const pin = rope.joints[0]!;
  readout.set(4, isAlive(world, pin) ? `${fmt(world.components.Joint.force[slotOf(pin)]!)} N` : 'cut');
}

shell.expose({
  params,
  plot,
  drag,
  /** The rope's body and joint handles, and the bob's. */
  ids: () => ({ bodies: Array.from(rope.bodies), joints: Array.from(rope.joints), bob, bobLink }),
  /** Live links of the rope (joints still alive). */
  links: () => [...rope.joints, bobLink].filter((h) => isAlive(shell.world, h)).length,
  cuts: () => cuts,
  /** Pieces the rope was drawn in at the last frame (1 whole, 2 after a cut). */
  ropePieces: () => layer.pieces,
  /** Runs the lab's step n times (tests). */
  advance: (n: number) => {
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
