/**
 * Bouncing balls: the book's bouncing balls grown up. Balls of different sizes and masses fall,
 * bounce off the box, the inclined walls (and their end points) and each other.
 *
 * Input: press on a ball or crate and drag to pull it (a mouse joint); on empty space a click drops a
 * ball at the pointer and a drag throws one (release velocity from the drag).
 * Keys: P pause, N single step, R reset, T trails, D debug overlay.
 * URL: ?count=N (balls, 1..10000), ?seed=S, ?mode=auto|sprites|particles, ?trails=0|1, ?debug.
 * From 1000 balls on (mode auto) the renderer draws with pixi's ParticleContainer.
 */

import {
  choiceParam,
  createPanel,
  flagParam,
  forEachImpact,
  getSound,
  numberParam,
  type SoundMaterial,
  seedParam,
} from '@bitphysics/game-kit';
import { enableMouseDrag } from '@bitphysics/game-kit/drag';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { addBox, createPhysicsWorld, type PhysicsWorld, slotOf, step } from '@bitphysics/physics';
import { Graphics } from 'pixi.js';
import {
  applyDrag,
  applyGravity,
  applyMaterial,
  type BouncingBallsHandles,
  bouncingBallsWorldOptions,
  buildBouncingBalls,
  DRAG_MODES,
  type DragMode,
  isHeavy,
  layoutOf,
  meanRadiusFor,
  removeBall,
  spawnBall,
} from './scene';

/** Colour of the heavy balls (density 4 kg/m^2); the others keep their seeded colours. */
const HEAVY_COLOR = 0x6b7a93;
/** A press that moves less than this, CSS px, is a click (drop), more is a throw. */
const CLICK_SLOP = 6;
/** Release velocity is measured over the pointer's last this-many ms. */
const THROW_WINDOW_MS = 80;
/** Fastest throw, m/s. */
const MAX_THROW_SPEED = 30;

const initialCount = numberParam('count', { default: 40, min: 1, max: 10_000, integer: true });
const params = {
  count: initialCount,
  seed: seedParam(),
  gravity: 9.81,
  restitution: 0.8,
  friction: 0.2,
  drag: 'none' as DragMode,
  dragK: 0.05,
  trails: new URLSearchParams(location.search).has('trails') ? flagParam('trails') : initialCount <= 400,
  debug: flagParam('debug'),
  reset: () => game.shell.reset(),
};
const mode = choiceParam('mode', ['auto', 'sprites', 'particles'] as const, 'auto');

/** A screen taller than wide (a phone held upright) gets the tall box, which fills it. */
const TALL = window.innerHeight > 1.2 * window.innerWidth;
let handles: BouncingBallsHandles;
/** Crates dropped with X (boxes: shapes that tumble among the balls), oldest first. */
let crates: number[] = [];

/** Builds a fresh world with the scene from the current params (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const options = {
    count: params.count,
    seed: params.seed,
    gravity: params.gravity,
    restitution: params.restitution,
    friction: params.friction,
    drag: params.drag,
    dragK: params.dragK,
    tall: TALL,
  };
  const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
  handles = buildBouncingBalls(world, options);
  crates = [];
  return world;
}

/** Drops a crate (a box of about two mean ball diameters, turned a little) near the top of the box. */
function dropCrate(): number {
  const r = handles.meanRadius,
    n = crates.length;
  const { box } = layoutOf(TALL);
  const span = box.max[0] - box.min[0] - 8;
  const crate = addBox(shell.world, {
    position: [box.min[0] + 4 + ((n * 2.7) % span), box.max[1] - 1],
    angle: 0.4 * ((n % 5) - 2),
    halfExtents: [2 * r, 1.4 * r],
    density: 1 / (Math.PI * r * r),
    restitution: params.restitution,
    friction: params.friction,
  });
  crates.push(crate);
  return crate;
}

/** Trail settings: one trail per ball up to 400 balls (36 frames long). */
function trailOptions(count: number) {
  return { length: 36, maxEntities: Math.min(400, Math.max(1, count + 200)) };
}

const sound = getSound();

/** What a body sounds like: a crate wood, a heavy ball metal, the others rubber; walls stone. */
function materialOf(world: PhysicsWorld, body: number): SoundMaterial {
  if (body <= 0) return 'stone';
  if (crates.includes(body)) return 'wood';
  return isHeavy(world, body) ? 'metal' : 'soft';
}

/** One step, then a knock for each impact: loudness from its impulse, the harder of the two materials. */
function stepWorld(world: PhysicsWorld): void {
  step(world);
  forEachImpact(world, (a, b, impulse) => {
    const ma = materialOf(world, a),
      mb = materialOf(world, b);
    const m = ma === 'metal' || mb === 'metal' ? 'metal' : ma === 'wood' || mb === 'wood' ? 'wood' : ma === 'soft' ? mb : ma;
    sound.impact(impulse, m, { threshold: 0.5, loud: 20 });
  });
}

const game = await startPixiGame({
  title: 'Bouncing balls',
  createWorld,
  step: stepWorld,
  bodies: () => handles.balls.length,
  controls: [
    { keys: 'Drag a body', action: 'pull a ball or crate' },
    { keys: 'Click', action: 'drop a ball (empty space)' },
    { keys: 'Drag', action: 'throw a ball (empty space)' },
    { keys: 'T', action: 'trails on / off' },
    { keys: 'D', action: 'debug: velocities, contacts' },
    { keys: 'X', action: 'drop a crate' },
  ],
  keys: [
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: 'd', label: 'debug', action: () => setDebug(!params.debug) },
    { key: 'x', label: 'crate', action: () => dropCrate() },
  ],
  renderer: {
    view: 'boundary',
    balls: mode,
    trails: params.trails ? trailOptions(params.count) : false,
    debug: params.debug,
  },
  onFrame: () => drawPointer(),
});
const { shell, renderer, app } = game;

/** Gives the heavy balls of `world` their user colour (the others keep their seeded colours). */
function colorHeavy(world: PhysicsWorld): void {
  for (const e of handles.balls) if (isHeavy(world, e)) renderer.setColor(e, HEAVY_COLOR);
}
colorHeavy(shell.world);
shell.onWorldChange((world) => colorHeavy(world));

/** Turns trails on or off (the T key and the panel). */
function setTrails(on: boolean): void {
  params.trails = on;
  renderer.setTrails(on ? trailOptions(params.count) : false);
  panel.refresh();
}

/** Turns the debug overlay on or off (the D key and the panel). */
function setDebug(on: boolean): void {
  params.debug = on;
  renderer.setDebug(on);
  panel.refresh();
}

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'gravity',
      label: 'gravity (m/s²)',
      min: 0,
      max: 30,
      step: 0.01,
      onChange: (g) => applyGravity(shell.world, handles, g),
    },
    {
      type: 'slider',
      key: 'restitution',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (e, p) => applyMaterial(shell.world, handles, e, p.friction),
    },
    {
      type: 'slider',
      key: 'friction',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (mu, p) => applyMaterial(shell.world, handles, p.restitution, mu),
    },
    { type: 'choice', key: 'drag', options: DRAG_MODES, onChange: (m, p) => applyDrag(shell.world, handles, m as DragMode, p.dragK) },
    {
      type: 'slider',
      key: 'dragK',
      label: 'drag k (kg/s | kg/m)',
      min: 0,
      max: 2,
      step: 0.01,
      onChange: (k, p) => applyDrag(shell.world, handles, p.drag, k),
    },
    {
      type: 'slider',
      key: 'count',
      label: 'balls (rebuilds)',
      min: 1,
      max: 6000,
      step: 1,
      onRelease: true,
      onChange: () => {
        shell.reset();
        if (params.trails) renderer.setTrails(trailOptions(params.count));
      },
    },
    { type: 'checkbox', key: 'trails', onChange: (v) => setTrails(v === true) },
    { type: 'checkbox', key: 'debug', label: 'debug overlay', onChange: (v) => setDebug(v === true) },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Bouncing balls' },
);

// ---- Pointer: a press on a body drags it; elsewhere a click drops, a drag throws -----------------

const canvas = app.canvas;
// Registered before the drop/throw listeners, so a press that grabs a body is seen as taken there.
// Reach 1.4 mean radii: a ball grabs within that of its edge, a crate (a box, no radius) within that of its
// centre (its half height), so presses in the open still drop and throw balls.
const drag = enableMouseDrag(
  canvas,
  () => shell.world,
  () => renderer.camera,
  { reach: 1.4 * meanRadiusFor(params.count) },
);

const overlay = new Graphics({ label: 'pointer' });
app.stage.addChild(overlay);
const SAMPLES = 32;
const sampleX = new Float64Array(SAMPLES),
  sampleY = new Float64Array(SAMPLES),
  sampleT = new Float64Array(SAMPLES);
let sampleHead = 0,
  sampleCount = 0;
let pointerId = -1;
let startX = 0,
  startY = 0,
  lastX = 0,
  lastY = 0;
let dragged = false;

/** The pointer position in CSS px relative to the canvas' top-left corner. */
function local(event: PointerEvent): [number, number] {
  const rect = canvas.getBoundingClientRect();
  return [event.clientX - rect.left, event.clientY - rect.top];
}

/** Records a pointer sample (px, px, ms) in the ring used for the throw velocity. */
function sample(x: number, y: number, t: number): void {
  sampleX[sampleHead] = x;
  sampleY[sampleHead] = y;
  sampleT[sampleHead] = t;
  sampleHead = (sampleHead + 1) % SAMPLES;
  if (sampleCount < SAMPLES) sampleCount++;
}

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || pointerId !== -1 || drag.joint !== 0) return;
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  [startX, startY] = local(event);
  lastX = startX;
  lastY = startY;
  dragged = false;
  sampleHead = 0;
  sampleCount = 0;
  sample(startX, startY, event.timeStamp);
});

canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pointerId) return;
  [lastX, lastY] = local(event);
  if (Math.hypot(lastX - startX, lastY - startY) > CLICK_SLOP) dragged = true;
  sample(lastX, lastY, event.timeStamp);
});

/** Pointer released: a click drops a ball where it was pressed, a drag throws one from where it was let go. */
function release(event: PointerEvent, cancelled: boolean): void {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  if (cancelled) return;
  [lastX, lastY] = local(event);
  sample(lastX, lastY, event.timeStamp);
  const cam = renderer.camera;
  if (!dragged) {
    spawnBall(shell.world, handles, cam.toWorldX(startX), cam.toWorldY(startY));
    return;
  }
  // Release velocity: pointer displacement over the last THROW_WINDOW_MS, px/s -> m/s (y flipped).
  const newest = (sampleHead - 1 + SAMPLES) % SAMPLES;
  let oldest = newest;
  for (let k = 1; k < sampleCount; k++) {
    const i = (newest - k + SAMPLES) % SAMPLES;
    oldest = i;
    if (sampleT[newest]! - sampleT[i]! >= THROW_WINDOW_MS) break;
  }
  const dt = Math.max(1e-3, (sampleT[newest]! - sampleT[oldest]!) / 1000);
  let vx = (sampleX[newest]! - sampleX[oldest]!) / dt / cam.pixelsPerMeter;
  let vy = -(sampleY[newest]! - sampleY[oldest]!) / dt / cam.pixelsPerMeter;
  const speed = Math.hypot(vx, vy);
  if (speed > MAX_THROW_SPEED) {
    vx *= MAX_THROW_SPEED / speed;
    vy *= MAX_THROW_SPEED / speed;
  }
  spawnBall(shell.world, handles, cam.toWorldX(lastX), cam.toWorldY(lastY), vx, vy);
}
canvas.addEventListener('pointerup', (event) => release(event, false));
canvas.addEventListener('pointercancel', (event) => release(event, true));

/** Draws the pointer preview: the ball to be dropped, or the throw line while dragging. */
function drawPointer(): void {
  overlay.clear();
  if (pointerId === -1) return;
  const r = renderer.camera.toScreenLength(handles.meanRadius);
  if (dragged) {
    overlay.moveTo(startX, startY).lineTo(lastX, lastY).stroke({ width: 2, color: 0xffffff, alpha: 0.35 });
    overlay.circle(lastX, lastY, r).stroke({ width: 2, color: 0xffffff, alpha: 0.8 });
  } else {
    overlay.circle(startX, startY, r).stroke({ width: 2, color: 0xffffff, alpha: 0.6 });
  }
}

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  /** The pointer's mouse-joint drag: `joint` (0 when nothing is held) and `body`. */
  drag,
  /** Entity ids of the balls, oldest first (a copy). */
  ballIds: (): number[] => handles.balls.slice(),
  /** Entity ids of the crates dropped with X, oldest first (a copy). */
  crateIds: (): number[] => crates.slice(),
  /** Ball positions, m, flat [x0, y0, x1, y1, ...] in `ballIds` order. */
  positions: (): number[] => {
    const P = shell.world.components.Position;
    const out: number[] = [];
    for (const e of handles.balls) out.push(P.x[slotOf(e)]!, P.y[slotOf(e)]!);
    return out;
  },
  /** Adds a ball at (x, y) m with velocity (vx, vy) m/s; returns its id. */
  spawn: (x: number, y: number, vx = 0, vy = 0): number => spawnBall(shell.world, handles, x, y, vx, vy),
  /** Removes ball `eid`. @throws RangeError if it is not a ball of the scene. */
  remove: (eid: number): void => removeBall(shell.world, handles, eid),
});
