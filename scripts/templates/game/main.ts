/**
 * __TITLE__: made from the game template (`npm run new-game -- __NAME__`).
 *
 * Input: click drops a ball at the pointer; B drops one at the top. Keys: P pause, N single step,
 * R reset. URL: ?count=N (balls at the start, 0..500), ?seed=S.
 */

import { createPanel, numberParam, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPhysicsWorld, type PhysicsWorld, setGravity } from '@bitphysics/physics';
import { BOX, buildScene, type SceneHandles, spawnBall, worldOptions } from './scene';

const params = {
  count: numberParam('count', { default: 20, min: 0, max: 500, integer: true }),
  seed: seedParam(),
  gravity: 9.81,
  restitution: 0.7,
  reset: () => game.shell.reset(),
};

let handles: SceneHandles = { balls: [] };

/** A fresh world with the scene from the current params (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const options = { count: params.count, seed: params.seed, gravity: params.gravity, restitution: params.restitution };
  const world = createPhysicsWorld(worldOptions(options));
  handles = buildScene(world, options);
  return world;
}

const game = await startPixiGame({
  title: '__TITLE__',
  createWorld,
  bodies: () => handles.balls.length,
  controls: [
    { keys: 'Click', action: 'drop a ball' },
    { keys: 'B', action: 'drop a ball at the top' },
  ],
  keys: [
    { key: 'b', label: 'ball', action: () => spawnBall(game.shell.world, handles, BOX.width / 2, BOX.height - 1, params.restitution) },
  ],
  renderer: { view: 'boundary' },
});
const { shell, renderer, app } = game;

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
      onChange: (g) => setGravity(shell.world, [0, -g]),
    },
    { type: 'slider', key: 'restitution', label: 'restitution (new balls)', min: 0, max: 1, step: 0.01 },
    { type: 'slider', key: 'count', label: 'balls (rebuilds)', min: 0, max: 500, step: 1, onRelease: true, onChange: () => shell.reset() },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: '__TITLE__' },
);

const pointer = { x: 0, y: 0 };
app.canvas.addEventListener('pointerdown', (event) => {
  pointerOnCanvas(app.canvas, event, pointer);
  spawnBall(shell.world, handles, renderer.camera.toWorldX(pointer.x), renderer.camera.toWorldY(pointer.y), params.restitution);
});

// window.game: the shell (stats, pause, step, reset) plus what tests and the console need.
shell.expose({
  params,
  panel,
  /** Balls in the scene. */
  ballCount: (): number => handles.balls.length,
});
