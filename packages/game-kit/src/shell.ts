import { type PhysicsWorld, step as physicsStep } from '@bitphysics/physics';
import { exposeGame, type GameHandle, type GameStats, markReady } from './contract.js';
import { type ControlHint, createHud, type Hud } from './hud.js';
import { bindKeys, type KeyBinding } from './keys.js';
import { ICONS, pageLayout } from './layout.js';
import { createGameLoop, type GameLoop } from './loop.js';
import { addMuteButton, getSound, type Sound } from './sound.js';

/** Options of `createGameShell`. */
export interface GameShellOptions {
  /** Title shown in the HUD. Non-empty. */
  title: string;
  /** Builds a fresh world with the game's scene; called once at start and on every reset. */
  createWorld: () => PhysicsWorld;
  /** Draws a frame of `world` at interpolation factor `alpha` in [0, 1] (1 while paused). */
  render: (alpha: number, world: PhysicsWorld) => void;
  /** Runs one step of `world`. Default `step(world)` from @bitphysics/physics; wrap it to add game rules. */
  step?: (world: PhysicsWorld) => void;
  /** Body count for the HUD. Default: every live entity. */
  bodies?: (world: PhysicsWorld) => number;
  /**
   * Legend lines shown after the built-in P / N / R lines. A line with the same keys as a built-in
   * one ('R': what a reset means in this game) takes its place, keeping the built-in's touch hint
   * when it gives none (one line per key, not "reset" and then "new round").
   */
  controls?: readonly ControlHint[];
  /** Extra keys (the built-in P, N and R cannot be rebound). */
  keys?: readonly KeyBinding[];
  /** Start paused. Default false. */
  paused?: boolean;
  /** Longest real frame time fed to the fixed-step loop, s. Default 0.1. */
  maxFrameTime?: number;
  /** Most physics steps per frame. Default 4. */
  maxStepsPerFrame?: number;
  /** Element the HUD goes into. Default: the page layout (./layout), with pause, step and reset buttons in its toolbar. */
  hudParent?: HTMLElement;
}

/**
 * The running shell of a game; it is also `window.game` (the page contract, see contract.ts), so
 * tests can read `world`, toggle `paused` and call `stats()`, `step()`, `reset()`.
 */
export interface GameShell extends GameHandle {
  /** The world shown now; `reset` replaces it. */
  readonly world: PhysicsWorld;
  /** Paused: frames are drawn, no steps run. Settable. @throws TypeError if set to a non-boolean. */
  paused: boolean;
  /** { entities, steps, fps }: live entities and steps of the current world, measured frames per second. */
  stats(): GameStats;
  /** Pauses (if running) and advances exactly one step: the N key. */
  step(): void;
  /** Replaces the world with a fresh one from `createWorld` (pause state kept): the R key. */
  reset(): void;
  /** Flips `paused`: the P key. */
  togglePause(): void;
  /** The frame loop. */
  readonly loop: GameLoop;
  /** The HUD. */
  readonly hud: Hud;
  /** The page's sound (./sound: mute, and how many sounds played). */
  readonly sound: Sound;
  /** Calls `listener` with each new world after a reset. @returns a function that removes the listener. */
  onWorldChange(listener: (world: PhysicsWorld) => void): () => void;
  /**
   * Adds game-specific fields to the shell (and so to `window.game`) and returns it typed with them.
   * @throws TypeError if a field would replace a built-in one.
   */
  expose<E extends object>(extras: E): GameShell & E;
  /** Starts the frame loop. `createGameShell` does not start it (the renderer is usually made after the shell); `startPixiGame` does. */
  start(): void;
  /** Stops the loop, unbinds the keys and removes the HUD. */
  destroy(): void;
}

/** The built-in legend lines. */
export const SHELL_CONTROLS: readonly ControlHint[] = Object.freeze([
  { keys: 'P', action: 'pause / resume', touch: '▮▮ button', card: false },
  { keys: 'N', action: 'single step (pauses)', touch: '▶▮ button', card: false },
  { keys: 'R', action: 'reset', touch: 'top ↺ button', card: false },
]);

/**
 * SHELL_CONTROLS then `extra`, a line of `extra` with a built-in line's keys in that line's place
 * (see GameShellOptions.controls); a replacing line without a touch gesture keeps the built-in's
 * gesture and its `card`.
 */
function legendLines(extra: readonly ControlHint[]): ControlHint[] {
  const own = new Map(extra.map((c) => [c.keys, c]));
  const builtIn = SHELL_CONTROLS.map((c) => {
    const mine = own.get(c.keys);
    if (!mine) return c;
    return mine.touch === undefined && c.touch !== undefined
      ? { ...mine, touch: c.touch, ...(c.card === undefined ? {} : { card: c.card }) }
      : mine;
  });
  return [...builtIn, ...extra.filter((c) => !SHELL_CONTROLS.some((b) => b.keys === c.keys))];
}

/**
 * Creates a game shell: world lifecycle, fixed-step loop on requestAnimationFrame, P / N / R keys,
 * HUD (fps, bodies, steps, legend), `window.game` and the ready flag (`document.body.dataset.ready`
 * becomes 'true' after the first drawn frame). Renderer-agnostic: the game supplies `render`.
 * The loop is not started: call `start()` once the renderer is in place.
 * @throws TypeError if title is empty or createWorld/render is not a function; whatever
 *   `createWorld` throws.
 */
export function createGameShell(options: GameShellOptions): GameShell {
  const where = 'createGameShell';
  if (typeof options.createWorld !== 'function') throw new TypeError(`${where}: createWorld must be a function`);
  if (typeof options.render !== 'function') throw new TypeError(`${where}: render must be a function`);
  const stepWorld = options.step ?? physicsStep;
  const bodies = options.bodies ?? ((w: PhysicsWorld) => w.entityIndex.aliveCount);
  const render = options.render;
  const hud = createHud({
    title: options.title,
    controls: legendLines(options.controls ?? []),
    ...(options.hudParent ? { parent: options.hudParent } : {}),
  });
  let world = options.createWorld();
  const listeners = new Set<(w: PhysicsWorld) => void>();
  let lastHud = -Infinity;

  let pauseButton: HTMLButtonElement | null = null;
  const updateHud = (): void => {
    hud.update(loop.fps, bodies(world), world.steps, loop.paused);
    if (pauseButton && pauseButton.dataset.paused !== String(loop.paused)) {
      pauseButton.dataset.paused = String(loop.paused);
      pauseButton.innerHTML = loop.paused ? ICONS.play : ICONS.pause;
      pauseButton.setAttribute('aria-pressed', String(loop.paused));
    }
  };

  const loop = createGameLoop({
    dt: world.dt,
    step: () => stepWorld(world),
    render: (alpha) => {
      render(alpha, world);
      const now = performance.now();
      if (now - lastHud >= 250) {
        lastHud = now;
        updateHud();
      }
    },
    ...(options.maxFrameTime !== undefined ? { maxFrameTime: options.maxFrameTime } : {}),
    ...(options.maxStepsPerFrame !== undefined ? { maxStepsPerFrame: options.maxStepsPerFrame } : {}),
    onError: (error) => {
      console.error(error);
      hud.showError(`The simulation stopped: ${error instanceof Error ? error.message : String(error)}`);
    },
  });
  loop.paused = options.paused ?? false;

  const builtIn = new Set([
    'world',
    'paused',
    'stats',
    'step',
    'reset',
    'togglePause',
    'loop',
    'hud',
    'sound',
    'onWorldChange',
    'expose',
    'start',
    'destroy',
  ]);

  const shell: GameShell = {
    get world() {
      return world;
    },
    get paused() {
      return loop.paused;
    },
    set paused(value: boolean) {
      loop.paused = value;
      updateHud();
    },
    stats() {
      return { entities: world.entityIndex.aliveCount, steps: world.steps, fps: loop.fps };
    },
    step() {
      loop.paused = true;
      loop.stepOnce();
      updateHud();
    },
    reset() {
      world = options.createWorld();
      loop.setTimeStep(world.dt);
      loop.resetClock();
      for (const l of listeners) l(world);
      updateHud();
    },
    togglePause() {
      shell.paused = !loop.paused;
    },
    loop,
    hud,
    sound: getSound(),
    onWorldChange(listener) {
      listeners.add(listener);
      return () => listeners.delete(listener);
    },
    expose<E extends object>(extras: E): GameShell & E {
      for (const key of Object.keys(extras)) {
        if (builtIn.has(key)) throw new TypeError(`GameShell.expose: ${JSON.stringify(key)} is a built-in field of the shell`);
      }
      return Object.assign(shell, extras);
    },
    start() {
      loop.start();
    },
    destroy() {
      loop.stop();
      unbind();
      hud.destroy();
      if (window.game === shell) delete window.game;
    },
  };

  const extraKeys = options.keys ?? [];
  for (const k of extraKeys) {
    if (['p', 'n', 'r'].includes(k.key.toLowerCase()))
      throw new TypeError(`${where}: key ${JSON.stringify(k.key)} is built in (P pause, N step, R reset)`);
  }
  const unbind = bindKeys([
    { key: 'p', label: 'pause / resume', action: () => shell.togglePause() },
    { key: 'n', label: 'single step', action: () => shell.step(), repeat: true },
    { key: 'r', label: 'reset', action: () => shell.reset() },
    ...extraKeys,
  ]);

  if (!options.hudParent) {
    // The same three actions as P, N and R, for touch screens and mice.
    const layout = pageLayout();
    pauseButton = layout.addButton('pause', 'pause / resume (P)', () => shell.togglePause());
    layout.addButton('step', 'single step (N)', () => shell.step());
    layout.addButton('reset', 'reset (R)', () => shell.reset());
    addMuteButton(layout.addButton);
  }

  exposeGame(shell);
  loop.afterFirstFrame(() => {
    updateHud();
    markReady();
  });
  return shell;
}

/** What `createRenderedShell` needs of a world renderer (render-pixi's WorldRenderer, render-three's WorldRenderer3D). */
export interface WorldView {
  /** Places the world's display objects for interpolation factor `alpha` in [0, 1]. */
  render(alpha: number): void;
  /** Shows `world` from now on (after a reset). */
  setWorld(world: PhysicsWorld): void;
}

/**
 * The part `startPixiGame` and `startThreeGame` share: a shell whose frames are drawn by the world
 * renderer `createRenderer(shell.world)` makes. Each frame `beforeFrame` runs (a camera that moves
 * moves here, so the bodies and the extras are placed with the same camera), the renderer places its
 * objects for alpha, `onFrame` draws extras, `present()` shows the frame (frames before the renderer exists draw nothing);
 * after a reset the renderer follows the new world. Neither exposed nor started: the caller adds its
 * fields with `shell.expose` and calls `shell.start()`.
 * @throws whatever createGameShell or `createRenderer` throws.
 */
export function createRenderedShell<R extends WorldView>(
  options: Omit<GameShellOptions, 'render'>,
  createRenderer: (world: PhysicsWorld) => R,
  present: () => void,
  onFrame?: (alpha: number, world: PhysicsWorld) => void,
  beforeFrame?: (alpha: number, world: PhysicsWorld) => void,
): { shell: GameShell; renderer: R } {
  let renderer: R | null = null;
  const shell = createGameShell({
    ...options,
    render: (alpha, world) => {
      if (!renderer) return;
      beforeFrame?.(alpha, world);
      renderer.render(alpha);
      onFrame?.(alpha, world);
      present();
    },
  });
  const worldRenderer = createRenderer(shell.world);
  renderer = worldRenderer;
  shell.onWorldChange((world) => worldRenderer.setWorld(world));
  return { shell, renderer: worldRenderer };
}
