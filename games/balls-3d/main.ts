/**
 * Balls 3D: the book's chapter 15 bouncing balls in a glass box, grown up. Balls of three sizes
 * bounce off the box and each other; throw more from the camera.
 *
 * Input: left drag aims (a dotted arc previews the throw; a longer drag throws harder) and release
 * throws a ball from where the aim ray enters the box; Space throws one straight ahead.
 * Right drag orbits the camera (Shift: pan), the wheel zooms.
 * Keys: P pause, N single step, R reset, T trails, D debug layer, Space throw.
 * URL: ?count=N (1..10000), ?seed=S, ?trails=0|1, ?debug, ?shadows=0|1, ?aa=0|1 (antialiasing; default
 * on unless WebGL runs in software).
 * Every ball is one instance of a single InstancedMesh (one draw call, one more for the shadow map).
 */

import { createPanel, flagParam, numberParam, seedParam } from '@bitphysics/game-kit';
import { ORBIT_CONTROLS_RIGHT, startThreeGame } from '@bitphysics/game-kit/three';
import { createPhysicsWorld, type PhysicsWorld } from '@bitphysics/physics';
import { BufferAttribute, BufferGeometry, Line, LineDashedMaterial, Mesh, MeshBasicMaterial, SphereGeometry, Vector3 } from 'three';
import {
  applyGravity,
  applyMaterial,
  type Balls3DHandles,
  BOX,
  balls3DWorldOptions,
  buildBalls3D,
  rayEntersBox,
  removeBall,
  spawnBall,
} from './scene';

/** A press that moves less than this, CSS px, still throws (at the lowest speed). */
const FULL_POWER_DRAG = 260;
/** Slowest throw, m/s. */
const MIN_THROW_SPEED = 2;
/** Points of the previewed arc. */
const ARC_POINTS = 64;

const search = new URLSearchParams(location.search);
const initialCount = numberParam('count', { default: 300, min: 1, max: 10_000, integer: true });
const params = {
  count: initialCount,
  seed: seedParam(),
  gravity: 9.81,
  restitution: 0.6,
  friction: 0.3,
  throwSpeed: 12,
  trails: search.has('trails') ? flagParam('trails') : initialCount <= 400,
  debug: flagParam('debug'),
  shadows: search.has('shadows') ? flagParam('shadows') : true,
  reset: () => game.shell.reset(),
};

let handles: Balls3DHandles;

/** Builds a fresh world with the scene from the current params (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const options = {
    count: params.count,
    seed: params.seed,
    gravity: params.gravity,
    restitution: params.restitution,
    friction: params.friction,
  };
  const world = createPhysicsWorld(balls3DWorldOptions(options));
  handles = buildBalls3D(world, options);
  return world;
}

/** Trail settings: up to 400 trails, 40 points each. */
function trailOptions(count: number) {
  return { length: 40, maxEntities: Math.min(400, count + 100), alpha: 0.5 };
}

const game = await startThreeGame({
  title: 'Balls 3D',
  createWorld,
  bodies: () => handles.balls.length,
  controls: [
    { keys: 'Drag', action: 'aim, release to throw (longer: harder)' },
    { keys: 'Space', action: 'throw straight ahead' },
    ...ORBIT_CONTROLS_RIGHT,
    { keys: 'T', action: 'trails on / off' },
    { keys: 'D', action: 'debug: axes, velocities, contacts' },
  ],
  keys: [
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: 'd', label: 'debug', action: () => setDebug(!params.debug) },
    { key: ' ', label: 'throw', action: () => throwAt(0, 0, 0.5 * (MIN_THROW_SPEED + params.throwSpeed)), repeat: true },
  ],
  app: {
    controls: { leftButton: 'none', minDistance: 1, maxDistance: 40, target: [0, 1, 0] },
    shadows: params.shadows,
    ...(search.has('aa') ? { antialias: flagParam('aa') } : {}),
  },
  renderer: {
    sphereSegments: initialCount > 2000 ? 12 : initialCount > 500 ? 16 : 24,
    trails: params.trails ? trailOptions(params.count) : false,
    debug: params.debug,
    shadows: params.shadows,
    lights: { shadows: params.shadows },
    initialInstances: initialCount + 64,
  },
  view: 'boundary',
  viewDirection: [0.85, 0.75, 1.3],
  onFrame: () => drawAim(),
});
const { shell, renderer, app } = game;

/** Turns trails on or off (the T key and the panel). */
function setTrails(on: boolean): void {
  params.trails = on;
  renderer.setTrails(on ? trailOptions(params.count) : false);
  panel.refresh();
}

/** Turns the debug layer on or off (the D key and the panel). */
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
    { type: 'slider', key: 'throwSpeed', label: 'throw speed (m/s)', min: 3, max: 30, step: 0.5 },
    {
      type: 'slider',
      key: 'count',
      label: 'balls (rebuilds)',
      min: 1,
      max: 5000,
      step: 1,
      onRelease: true,
      onChange: () => {
        shell.reset();
        if (params.trails) renderer.setTrails(trailOptions(params.count));
      },
    },
    { type: 'checkbox', key: 'trails', onChange: (v) => setTrails(v === true) },
    { type: 'checkbox', key: 'debug', label: 'debug layer', onChange: (v) => setDebug(v === true) },
    {
      type: 'checkbox',
      key: 'shadows',
      onChange: (v) => {
        const on = v === true;
        renderer.setShadows(on);
        if (renderer.lights) renderer.lights.sun.castShadow = on;
      },
    },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Balls 3D' },
);

// ---- Throwing: drag to aim, release to throw -------------------------------------------------

const canvas = app.canvas;
const ndc: [number, number] = [0, 0];
const aim = { active: false, pointerId: -1, startX: 0, startY: 0, x: 0, y: 0 };
const origin = new Float64Array(3),
  dir = new Float64Array(3),
  spawnAt = new Float64Array(3),
  velocity = new Float64Array(3);
const rayPoint = new Vector3();

/**
 * Computes a throw through the screen point (ndcX, ndcY) at `speed` m/s: the ball starts where the
 * camera ray enters the box (a mean radius inside it), or, if the ray misses the box, at the point of
 * the ray nearest the box centre; its velocity is speed along the ray. Fills spawnAt and velocity.
 */
function planThrow(ndcX: number, ndcY: number, speed: number): void {
  const cam = app.camera;
  const k = renderer.unitsPerMeter;
  cam.updateMatrixWorld();
  origin[0] = cam.position.x / k;
  origin[1] = cam.position.y / k;
  origin[2] = cam.position.z / k;
  const v = rayPoint.set(ndcX, ndcY, 0.5).unproject(cam).sub(cam.position).normalize();
  dir[0] = v.x;
  dir[1] = v.y;
  dir[2] = v.z;
  const margin = 1.6 * handles.meanRadius;
  let t = rayEntersBox(origin, dir, margin);
  if (t < 0) {
    // Nearest point of the ray to the box centre (spawnBall clamps it inside the box).
    const cx = 0.5 * (BOX.min[0] + BOX.max[0]),
      cy = 0.5 * (BOX.min[1] + BOX.max[1]),
      cz = 0.5 * (BOX.min[2] + BOX.max[2]);
    t = Math.max(0, (cx - origin[0]) * dir[0] + (cy - origin[1]) * dir[1] + (cz - origin[2]) * dir[2]);
  }
  for (let i = 0; i < 3; i++) {
    spawnAt[i] = Math.min(BOX.max[i]! - margin, Math.max(BOX.min[i]! + margin, origin[i]! + dir[i]! * t));
    velocity[i] = dir[i]! * speed;
  }
}

/** Throws a ball through the screen point (ndcX, ndcY) at `speed` m/s. @returns its entity id. */
function throwAt(ndcX: number, ndcY: number, speed: number): number {
  planThrow(ndcX, ndcY, speed);
  return spawnBall(shell.world, handles, spawnAt, velocity);
}

/** Throw speed for a drag of `pixels` CSS px: from MIN_THROW_SPEED up to params.throwSpeed at FULL_POWER_DRAG. */
function speedFor(pixels: number): number {
  const f = Math.min(1, pixels / FULL_POWER_DRAG);
  return MIN_THROW_SPEED + (Math.max(MIN_THROW_SPEED, params.throwSpeed) - MIN_THROW_SPEED) * f;
}

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || aim.active) return;
  aim.active = true;
  aim.pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  aim.startX = aim.x = event.clientX;
  aim.startY = aim.y = event.clientY;
});
canvas.addEventListener('pointermove', (event) => {
  if (!aim.active || event.pointerId !== aim.pointerId) return;
  aim.x = event.clientX;
  aim.y = event.clientY;
});
function release(event: PointerEvent, cancelled: boolean): void {
  if (!aim.active || event.pointerId !== aim.pointerId) return;
  aim.active = false;
  aim.pointerId = -1;
  if (cancelled) return;
  aim.x = event.clientX;
  aim.y = event.clientY;
  app.toNdc(aim.x, aim.y, ndc);
  throwAt(ndc[0], ndc[1], speedFor(Math.hypot(aim.x - aim.startX, aim.y - aim.startY)));
}
canvas.addEventListener('pointerup', (event) => release(event, false));
canvas.addEventListener('pointercancel', (event) => release(event, true));

// The aim preview: the arc the ball would fly (gravity only, until it leaves the box) and the ball.
const arcPositions = new Float32Array(ARC_POINTS * 3);
const arcGeometry = new BufferGeometry();
arcGeometry.setAttribute('position', new BufferAttribute(arcPositions, 3));
const arc = new Line(
  arcGeometry,
  new LineDashedMaterial({ color: 0xffffff, dashSize: 0.08, gapSize: 0.06, transparent: true, opacity: 0.8 }),
);
arc.frustumCulled = false;
arc.visible = false;
const ghost = new Mesh(
  new SphereGeometry(1, 16, 12),
  new MeshBasicMaterial({ color: 0xffffff, wireframe: true, transparent: true, opacity: 0.5 }),
);
ghost.visible = false;
app.scene.add(arc, ghost);

/** Draws the aim preview while a drag is under way. */
function drawAim(): void {
  if (!aim.active) {
    arc.visible = false;
    ghost.visible = false;
    return;
  }
  app.toNdc(aim.x, aim.y, ndc);
  planThrow(ndc[0], ndc[1], speedFor(Math.hypot(aim.x - aim.startX, aim.y - aim.startY)));
  const k = renderer.unitsPerMeter,
    g = shell.world.gravity;
  const T = 1.5,
    dt = T / (ARC_POINTS - 1);
  let used = 0;
  for (let i = 0; i < ARC_POINTS; i++) {
    const t = i * dt;
    const x = spawnAt[0]! + velocity[0]! * t + 0.5 * g[0]! * t * t;
    const y = spawnAt[1]! + velocity[1]! * t + 0.5 * g[1]! * t * t;
    const z = spawnAt[2]! + velocity[2]! * t + 0.5 * g[2]! * t * t;
    arcPositions[3 * i] = x * k;
    arcPositions[3 * i + 1] = y * k;
    arcPositions[3 * i + 2] = z * k;
    used = i + 1;
    if (x < BOX.min[0] || x > BOX.max[0] || y < BOX.min[1] || y > BOX.max[1] || z < BOX.min[2] || z > BOX.max[2]) break;
  }
  arcGeometry.setDrawRange(0, used);
  arcGeometry.attributes.position!.needsUpdate = true;
  arc.computeLineDistances();
  arc.visible = true;
  ghost.visible = true;
  ghost.position.set(spawnAt[0]! * k, spawnAt[1]! * k, spawnAt[2]! * k);
  ghost.scale.setScalar(handles.meanRadius * k);
}

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  /** Entity ids of the balls, oldest first (a copy). */
  ballIds: (): number[] => handles.balls.slice(),
  /** Throws a ball through the screen point (ndcX, ndcY) at `speed` m/s, as a drag would; returns its id. */
  throwAt: (ndcX: number, ndcY: number, speed = 8): number => throwAt(ndcX, ndcY, speed),
  /** Adds a ball at `position` (m) with `velocity` (m/s) and optional radius (m); returns its id. */
  spawn: (position: number[], velocity: number[] = [0, 0, 0], radius?: number): number =>
    spawnBall(shell.world, handles, position, velocity, radius),
  /** Removes ball `eid`. @throws RangeError if it is not a ball of the scene. */
  remove: (eid: number): void => removeBall(shell.world, handles, eid),
  /** Draw calls, triangles and GPU resources of the last frame. */
  frameInfo: () => app.info(),
});
