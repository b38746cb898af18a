/**
 * Lab: rigid bodies (Ramtal and Dobre ch. 13), five demos picked in the panel: a board tilting under a
 * tall and a wide box (the tall one tips when tan(angle) > width / height, the wide one slides when
 * tan(angle) > mu), a block bouncing on its corner (restitution 0.4), two blocks colliding, a block
 * turned by a torque against angular damping (w -> torque / k), a wind turbine on a pin.
 *
 * Input: click drops a crate at the pointer; B drops one at the top. Keys: P pause, N single step,
 * R reset. URL: ?scene (incline, bouncing, colliding, torque, turbine), ?seed=S.
 */

import { choiceParam, createPanel, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import { createReadout, fmt } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPhysicsWorld, type PhysicsWorld, setGravity, slotOf } from '@bitphysics/physics';
import { buildScene, SCENE_NAMES, type SceneHandles, type SceneName, STAGE, spawnBox, worldOptions } from './scene';

const params = {
  scene: choiceParam('scene', SCENE_NAMES, 'incline') as SceneName,
  seed: seedParam(),
  gravity: 9.81,
  friction: 0.6,
  tiltRate: 0.08,
  torque: 4,
  damping: 2,
  reset: () => game.shell.reset(),
};

let handles: SceneHandles = { boxes: [] };

/** A fresh world with the scene from the current params (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(worldOptions(params));
  handles = buildScene(world, params);
  return world;
}

const game = await startPixiGame({
  title: 'Rigid bodies',
  createWorld,
  bodies: () => handles.boxes.length,
  controls: [
    { keys: 'Click', action: 'drop a crate' },
    { keys: 'B', action: 'drop a crate at the top' },
  ],
  keys: [{ key: 'b', label: 'crate', action: () => spawnBox(game.shell.world, handles, STAGE.width / 2, STAGE.height - 1) }],
  renderer: { view: 'boundary' },
  onFrame: (_alpha, world) => show(world),
});
const { shell, renderer, app } = game;

const panel = createPanel(
  params,
  [
    { type: 'choice', key: 'scene', label: 'demo', options: SCENE_NAMES, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'gravity',
      label: 'gravity (m/s²)',
      min: 0,
      max: 30,
      step: 0.01,
      onChange: (g) => setGravity(shell.world, [0, -g]),
    },
    {
      type: 'slider',
      key: 'friction',
      label: 'friction μ (rebuilds)',
      min: 0,
      max: 1.5,
      step: 0.01,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'tiltRate',
      label: 'incline tilt rate (rad/s, rebuilds)',
      min: 0.01,
      max: 0.3,
      step: 0.01,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'torque',
      label: 'torque / wind (N m, rebuilds)',
      min: 0,
      max: 20,
      step: 0.1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'damping',
      label: 'angular damping k (N m s, rebuilds)',
      min: 0.1,
      max: 10,
      step: 0.1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Rigid bodies' },
);

const readout = createReadout(shell.hud.readout, [
  'demo',
  'incline angle',
  'tan(angle)',
  'tips when tan >',
  'slides when tan >',
  'spin w',
  'w limit torque / k',
]);

/** Fills the readout from the world. */
function show(world: PhysicsWorld): void {
  const c = world.components;
  readout.set(0, params.scene);
  if (handles.board !== undefined) {
    const a = c.Angle.value[slotOf(handles.board)]!;
    readout.set(1, `${fmt((a * 180) / Math.PI)}°`);
    readout.set(2, fmt(Math.tan(a)));
    readout.set(3, fmt(handles.tallRatio!));
    readout.set(4, fmt(params.friction));
  } else for (let i = 1; i < 5; i++) readout.set(i, '-');
  if (handles.spinner !== undefined) {
    readout.set(5, `${fmt(c.AngularVelocity.z[slotOf(handles.spinner)]!)} rad/s`);
    readout.set(6, params.scene === 'torque' ? `${fmt(params.torque / params.damping)} rad/s` : '-');
  } else {
    readout.set(5, '-');
    readout.set(6, '-');
  }
}

const pointer = { x: 0, y: 0 };
app.canvas.addEventListener('pointerdown', (event) => {
  pointerOnCanvas(app.canvas, event, pointer);
  spawnBox(shell.world, handles, renderer.camera.toWorldX(pointer.x), renderer.camera.toWorldY(pointer.y));
});

// window.game: the shell (stats, pause, step, reset) plus what tests and the console need.
shell.expose({
  params,
  panel,
  /** Boxes in the scene. */
  boxCount: (): number => handles.boxes.length,
  /** The scene's handles. */
  ids: () => ({ ...handles }),
  /** Steps the world n times (tests). */
  advance: (n: number) => {
    for (let i = 0; i < n; i++) shell.step();
  },
});
