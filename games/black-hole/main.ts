/**
 * Black hole: fly the ship from the bottom to the green line at the top past black holes that pull
 * it with Newtonian gravity. Crossing the line scores one point per hole on screen and adds a hole;
 * falling into a hole costs one of three lives; leaving the screen puts the ship back for free.
 * (Ramtal and Dobre, ch. 6; the rules are in ./rules.ts, DOM-free.)
 *
 * Keys: arrow keys thrust (one direction at a time: the last one pressed), Enter restarts after the
 * game is over, P pause, N single step, R reset, F predicted path on / off, V replays the run from its
 * start (./replay.ts: every input is recorded at its step; the replay ends where the run was, bit for bit).
 * Touch: the four arrow buttons under the scene (hold to thrust); tap the message to restart.
 * Levels (./levels.ts): level 1 has one small hole off the straight path, later levels more and
 * bigger holes, drifting holes and a fuel limit; clearing a level shows a summary and waits for
 * Enter (or a tap on the message); the best score is kept in the browser's local storage.
 * URL: ?level=N (start level, default 1), ?holes=N (1..16: the classic endless game with N holes
 * instead of levels), ?seed=S, ?c=C (m/s), ?thrust=A (m/s^2), ?path=0|1.
 *
 * Drawn: each hole as a black disc of its Schwarzschild radius with a glow; the exhaust (particles,
 * additive); the ship; its predicted path for the next second, integrated in a small second world
 * (rules.ts `predictPath`) and drawn as fading dots.
 */

import { createButtonBar, createPanel, flagParam, getSound, isTouchDevice, numberParam, pageLayout, seedParam } from '@bitphysics/game-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { type PhysicsWorld, Rng, slotOf, stateHash } from '@bitphysics/physics';
import { Graphics } from 'pixi.js';
import { canThrust, type LevelRun, startLevel } from './levels';
import { type BlackHoleReplay, createBlackHoleReplay, type GameStepEvent } from './replay';
import {
  type BlackHoleGame,
  C_GAME,
  createBlackHoleGame,
  createPredictor,
  FIELD,
  MAX_HOLES,
  type Predictor,
  predictPath,
  type Thrust,
} from './rules';

const search = new URLSearchParams(location.search);
/** Levels unless ?holes asks for the classic endless game. */
const levels = !search.has('holes');
const firstLevel = numberParam('level', { default: 1, min: 1, max: 99, integer: true });
const BEST_KEY = 'bitphysics.black-hole.best';

/** The best score kept in local storage (0 when none, or storage is unavailable). */
function readBest(): number {
  try {
    const v = Number(localStorage.getItem(BEST_KEY));
    return Number.isFinite(v) && v > 0 ? v : 0;
  } catch {
    return 0;
  }
}
let best = readBest();

/** After each game step (live or replayed): keeps the best score. */
function onGameStep(event: GameStepEvent): void {
  if (event === 'cleared' || event === 'scored' || event === 'over') recordScore(bh.score);
  // Sound (not while a replay plays the run back silently fast).
  if (event === 'scored') sound.chime(880);
  else if (event === 'cleared') sound.chime(1320, 0.6);
  else if (event === 'lost' || event === 'over') sound.explosion(event === 'over' ? 1 : 0.6);
}
const sound = getSound();
/** The ship's engine: hums while thrusting. */
const engine = sound.engine('propeller');

/** Keeps `score` as the best if it beats it. */
function recordScore(score: number): void {
  if (score <= best) return;
  best = score;
  try {
    localStorage.setItem(BEST_KEY, String(score));
  } catch {
    /* private mode: kept for this page only */
  }
}
const params = {
  holes: numberParam('holes', { default: 3, min: 1, max: MAX_HOLES, integer: true }),
  seed: seedParam(),
  gScale: 1,
  c: numberParam('c', { default: C_GAME, min: 2, max: 50 }),
  thrust: numberParam('thrust', { default: 6, min: 0, max: 40 }),
  path: search.has('path') ? flagParam('path') : true,
  restart: () => game.shell.reset(),
};

let bh: BlackHoleGame;
let run: LevelRun | null = null;
let predictor: Predictor;
/** Records every input of the run (V plays it back from the start). */
let replay: BlackHoleReplay;
const PATH_STEPS = 60;
const path = new Float64Array(2 * (PATH_STEPS + 1));
let pathPoints = 0;

/**
 * The field: the default 32 x 24 m on a wide screen; on a phone held upright a tall 20 x 30 m one,
 * which fills the screen (the wide field was a band across its middle).
 */
const PLAY_FIELD = window.innerHeight > 1.2 * window.innerWidth ? { width: 20, height: 30 } : FIELD;

function createWorld(): PhysicsWorld {
  bh = createBlackHoleGame({
    seed: params.seed,
    holes: params.holes,
    gScale: params.gScale,
    c: params.c,
    thrust: params.thrust,
    field: PLAY_FIELD,
  });
  run = levels ? startLevel(bh, firstLevel) : null;
  predictor = createPredictor(bh);
  replay = createBlackHoleReplay(bh, run, onGameStep);
  return bh.world;
}

const game = await startPixiGame({
  title: 'Black hole',
  createWorld,
  step: () => {
    replay.step();
    if (run && !canThrust(bh, run) && held.length > 0) held.length = 0;
  },
  controls: [
    { keys: '← ↑ → ↓', action: 'thrust (one at a time)', touch: 'hold ← ↑ → ↓' },
    { keys: 'Enter', action: 'next level / play again', touch: 'tap the message' },
    { keys: 'F', action: 'predicted path on / off' },
    { keys: 'V', action: 'replay the run from the start' },
  ],
  keys: [
    { key: 'Enter', label: 'next level / restart', action: () => advance() },
    {
      key: 'f',
      label: 'path',
      action: () => {
        params.path = !params.path;
        panel.refresh();
      },
    },
    {
      key: 'v',
      label: 'replay',
      action: () => {
        replay.play();
        predictor = createPredictor(bh);
        updateStatus(true);
      },
    },
  ],
  renderer: {
    view: { minX: 0, minY: 0, maxX: PLAY_FIELD.width, maxY: PLAY_FIELD.height },
    padding: 8,
    particles: { blend: 'add', minPixelSize: 1.5 },
  },
  app: { background: 0x020308 },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;
shell.onWorldChange(() => {
  applyHeld();
  updateStatus(true);
});

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'holes',
      label: 'holes (new layout)',
      min: 1,
      max: MAX_HOLES,
      step: 1,
      onChange: (n) => {
        params.holes = Math.round(n);
        replay.input('holes', params.holes);
      },
    },
    {
      type: 'slider',
      key: 'gScale',
      label: 'G scale (× 1 m³/kg/s²)',
      min: 0.1,
      max: 5,
      step: 0.01,
      onChange: (s) => replay.input('gScale', s),
    },
    { type: 'slider', key: 'c', label: 'light speed c (m/s)', min: 4, max: 30, step: 0.1, onChange: (c) => replay.input('lightSpeed', c) },
    {
      type: 'slider',
      key: 'thrust',
      label: 'thrust (m/s²)',
      min: 0,
      max: 20,
      step: 0.1,
      onChange: (a) => replay.input('thrustAcceleration', a),
    },
    { type: 'checkbox', key: 'path', label: 'predicted path (F)' },
    { type: 'button', key: 'restart', label: 'restart (R)' },
  ],
  { title: 'Black hole' },
);

// ---- Input: arrow keys and touch buttons, one direction at a time -------------------------------

const KEY_DIR: Record<string, Thrust> = { ArrowUp: 'up', ArrowDown: 'down', ArrowLeft: 'left', ArrowRight: 'right' };
/** Directions held (keys and buttons), most recent last; the thrust is the last one. */
const held: Thrust[] = [];

function applyHeld(): void {
  const allowed = !run || canThrust(bh, run);
  const want = allowed && held.length > 0 ? held[held.length - 1]! : 'none';
  if (want !== bh.thrust) replay.input('thrust', want);
}

/** Enter or a tap on the message: the next level after a clear, a new game after the last life. */
function advance(): void {
  if (bh.over) game.shell.reset();
  else if (run?.waiting) {
    replay.input('beginLevel');
    updateStatus(true);
  }
}
function press(dir: Thrust): void {
  const i = held.indexOf(dir);
  if (i >= 0) held.splice(i, 1);
  held.push(dir);
  applyHeld();
}
function release(dir: Thrust): void {
  const i = held.indexOf(dir);
  if (i >= 0) held.splice(i, 1);
  applyHeld();
}
window.addEventListener('keydown', (e) => {
  const dir = KEY_DIR[e.key];
  if (!dir || e.ctrlKey || e.metaKey || e.altKey) return;
  e.preventDefault();
  if (!e.repeat) press(dir);
});
window.addEventListener('keyup', (e) => {
  const dir = KEY_DIR[e.key];
  if (dir) release(dir);
});
window.addEventListener('blur', () => {
  held.length = 0;
  applyHeld();
});

const style = document.createElement('style');
style.textContent = `
.bh-status { text-align: center; font: 13px/1.4 system-ui, sans-serif; color: #e8ecf1; padding: 6px 10px 2px; }
.bh-status .bh-numbers { font: 600 15px ui-monospace, Menlo, Consolas, monospace; }
.bh-status .bh-message { color: #ffd166; }
.bh-status.over .bh-message { color: #ff8c8c; cursor: pointer; }
.bh-status.cleared .bh-message { color: #7ee787; cursor: pointer; font-weight: 600; }
.bh-pad button { font-size: 22px; min-width: 56px; }
`;
document.head.append(style);
const DIRS = ['left', 'up', 'down', 'right'] as const;
const pad = createButtonBar(
  DIRS.map((dir) => ({
    label: { left: '←', up: '↑', down: '↓', right: '→' }[dir],
    name: `thrust ${dir}`,
    onPress: () => press(dir),
    onRelease: () => release(dir),
  })),
  { label: 'thrust buttons', touchOnly: false },
);
pad.element.classList.add('bh-pad');
for (const [i, dir] of DIRS.entries()) pad.buttons[i]!.dataset.dir = dir;
const touch = isTouchDevice();
// On a touch screen, a tap on the scene after the game is over (or a level is cleared) goes on.
app.canvas.addEventListener('pointerup', () => {
  if (touch && (bh.over || run?.waiting)) advance();
});

// ---- Status: lives, score, holes, last message -----------------------------------------------

const status = document.createElement('div');
status.className = 'bh-status';
status.setAttribute('role', 'status');
const numbers = document.createElement('div');
numbers.className = 'bh-numbers';
numbers.dataset.hud = 'numbers';
const message = document.createElement('div');
message.className = 'bh-message';
message.dataset.hud = 'message';
status.append(numbers, message);
pageLayout().status.append(status);
message.addEventListener('click', () => advance());
let shownNumbers = '',
  shownMessage = '',
  shownThrust: Thrust | '' = '';

function updateStatus(force = false): void {
  // The panel's hole count follows the field: a level lays out its own number of holes.
  if (params.holes !== bh.holes.length && bh.holes.length > 0) {
    params.holes = bh.holes.length;
    panel.refresh();
  }
  const lives = `Lives ${'♥'.repeat(bh.lives)}${'♡'.repeat(Math.max(0, bh.params.lives - bh.lives))}`;
  const n = run
    ? `Level ${run.spec.level}   ${lives}   Score ${bh.score}   Best ${Math.max(best, bh.score)}` +
      (Number.isFinite(run.fuelLeft) ? `   Fuel ${run.fuelLeft.toFixed(1)} s` : '')
    : `${lives}   Score ${bh.score}   Holes ${bh.holes.length}`;
  const playing = replay.player ? `   ▶ Replay ${replay.player.played} steps` : '';
  if (force || n + playing !== shownNumbers) {
    shownNumbers = n + playing;
    numbers.textContent = n + playing;
  }
  if (force || bh.message !== shownMessage) {
    shownMessage = bh.message;
    // The rules speak of keys; on a touch screen a tap does the same.
    message.textContent = touch
      ? bh.message.replace('Press Enter or R to play again.', 'Tap to play again.').replace('Tap here or press Enter', 'Tap')
      : bh.message;
  }
  status.classList.toggle('over', bh.over);
  status.classList.toggle('cleared', !bh.over && (run?.waiting ?? false));
  if (force || bh.thrust !== shownThrust) {
    shownThrust = bh.thrust;
    for (const [i, dir] of DIRS.entries()) pad.setActive(i, dir === bh.thrust);
  }
}

// ---- Drawing --------------------------------------------------------------------------------------

const backdrop = new Graphics({ label: 'backdrop' });
app.stage.addChildAt(backdrop, 0);
const holesLayer = new Graphics({ label: 'holes' });
const overlay = new Graphics({ label: 'ship-and-path' });
app.stage.addChild(holesLayer, overlay);
let backdropVersion = -1,
  holesVersion = -1,
  holesCamera = -1;
const stars = (() => {
  const rng = new Rng(7);
  const out: [number, number, number][] = [];
  for (let i = 0; i < 220; i++) out.push([rng.range(0, PLAY_FIELD.width), rng.range(0, PLAY_FIELD.height), rng.range(0.2, 0.8)]);
  return out;
})();

function drawBackdrop(): void {
  const cam = renderer.camera;
  if (cam.version === backdropVersion) return;
  backdropVersion = cam.version;
  backdrop.clear();
  const W = PLAY_FIELD.width,
    H = PLAY_FIELD.height;
  backdrop.rect(cam.toScreenX(0), cam.toScreenY(H), cam.toScreenLength(W), cam.toScreenLength(H)).fill(0x070a16);
  for (const [x, y, a] of stars) backdrop.circle(cam.toScreenX(x), cam.toScreenY(y), 0.9).fill({ color: 0xffffff, alpha: a });
  backdrop.rect(cam.toScreenX(0), cam.toScreenY(H), cam.toScreenLength(W), cam.toScreenLength(H)).stroke({ width: 1, color: 0x3a4560 });
  // The finish line, dashed.
  const y = cam.toScreenY(bh.lineY),
    dash = 12;
  for (let x = cam.toScreenX(0); x < cam.toScreenX(W); x += 2 * dash) {
    backdrop.moveTo(x, y).lineTo(Math.min(x + dash, cam.toScreenX(W)), y);
  }
  backdrop.stroke({ width: 3, color: 0x4cff7a, alpha: 0.8 });
  // Start pad.
  backdrop.rect(cam.toScreenX(W / 2 - 1.2), cam.toScreenY(0.9), cam.toScreenLength(2.4), 3).fill({ color: 0x8d99ae, alpha: 0.7 });
}

function drawHoles(world: PhysicsWorld): void {
  const cam = renderer.camera;
  if (bh.version === holesVersion && cam.version === holesCamera) return;
  holesVersion = bh.version;
  holesCamera = cam.version;
  holesLayer.clear();
  const P = world.components.Position;
  for (let i = 0; i < bh.holes.length; i++) {
    const h = bh.holes[i]!;
    const x = cam.toScreenX(P.x[slotOf(h)]!),
      y = cam.toScreenY(P.y[slotOf(h)]!),
      r = cam.toScreenLength(bh.holeRadius[i]!);
    // Glow outside the horizon (the photon sphere is at 1.5 r), then the horizon itself.
    for (let k = 6; k >= 1; k--) holesLayer.circle(x, y, r * (1 + 0.12 * k)).fill({ color: 0xff8a3c, alpha: 0.05 });
    holesLayer.circle(x, y, r * 1.5).stroke({ width: 1, color: 0xffc080, alpha: 0.25 });
    holesLayer.circle(x, y, r).fill(0x000000).stroke({ width: 1.5, color: 0xffb060, alpha: 0.9 });
  }
}

function drawFrame(alpha: number, world: PhysicsWorld): void {
  engine.set(bh.thrust === 'none' || bh.over ? 0 : 0.7);
  drawBackdrop();
  drawHoles(world);
  const cam = renderer.camera;
  overlay.clear();
  const s = bh.ship,
    P = world.components.Position,
    O = world.components.PreviousPosition;
  const x = O.x[slotOf(s)]! + (P.x[slotOf(s)]! - O.x[slotOf(s)]!) * alpha,
    y = O.y[slotOf(s)]! + (P.y[slotOf(s)]! - O.y[slotOf(s)]!) * alpha;
  if (params.path && !bh.over) {
    pathPoints = predictPath(bh, predictor, path, PATH_STEPS);
    for (let i = 1; i < pathPoints; i += 2) {
      overlay
        .circle(cam.toScreenX(path[2 * i]!), cam.toScreenY(path[2 * i + 1]!), 1.6)
        .fill({ color: 0x9fd3ff, alpha: 0.45 * (1 - i / (PATH_STEPS + 1)) + 0.08 });
    }
  } else {
    pathPoints = 0;
  }
  // The ship: a small arrowhead, nose up, 1 m tall.
  const sx = cam.toScreenX(x),
    sy = cam.toScreenY(y),
    k = cam.toScreenLength(1);
  overlay
    .poly([sx, sy - 0.55 * k, sx + 0.38 * k, sy + 0.45 * k, sx, sy + 0.25 * k, sx - 0.38 * k, sy + 0.45 * k])
    .fill(bh.over ? 0x5c677d : 0xe8ecf1);
  updateStatus();
}

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  /** The ship's position, m, and velocity, m/s: [x, y, vx, vy]. */
  ship: (): number[] => {
    const c = bh.world.components;
    return [c.Position.x[slotOf(bh.ship)]!, c.Position.y[slotOf(bh.ship)]!, c.Velocity.x[slotOf(bh.ship)]!, c.Velocity.y[slotOf(bh.ship)]!];
  },
  /** Points of the predicted path drawn in the last frame. */
  pathPoints: (): number => pathPoints,
  /** Particles drawn in the last frame (exhaust). */
  particleCount: (): number => renderer.particles!.stats.particles,
});
// The live game state (lives, score, holes, message, thrust) and the level run (null in the classic
// game): getters, so they follow resets (expose copies values, which would keep the first game).
Object.defineProperty(shell, 'bh', { get: (): BlackHoleGame => bh, enumerable: true });
Object.defineProperty(shell, 'level', { get: (): LevelRun | null => run, enumerable: true });
Object.defineProperty(shell, 'best', { get: (): number => best, enumerable: true });
/** The run's recorder and player (V plays the recording back), and the world's state fingerprint. */
Object.defineProperty(shell, 'replay', { get: (): BlackHoleReplay => replay, enumerable: true });
Object.defineProperty(shell, 'stateHash', { value: (): string => stateHash(bh.world), enumerable: true });
/** Enter: the next level after a clear, a new game after the last life. */
Object.defineProperty(shell, 'advance', { value: advance, enumerable: true });
updateStatus(true);
