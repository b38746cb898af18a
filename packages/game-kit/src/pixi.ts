/**
 * The pixi-specific part of the game shell: the Application sized to the window, and
 * `startPixiGame`, which joins a `WorldRenderer` to the renderer-agnostic shell through
 * `createRenderedShell` (as './three' does for 3D games).
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import { WorldRenderer, type WorldRendererOptions } from '@bitphysics/render-pixi';
import { Application, type ColorSource } from 'pixi.js';
import { createFramePacer, type FramePacer } from './frame-pacer.js';
import { pageLayout } from './layout.js';
import { createRenderedShell, type GameShell, type GameShellOptions } from './shell.js';

export type { PauseOverlay, PauseOverlayOptions } from './pause-overlay.js';
export { createPauseOverlay } from './pause-overlay.js';
export type { ResultCard, ResultCardContent, ResultCardOptions, ResultCardPlace } from './result-card.js';
export { createResultCard } from './result-card.js';

/** Options of `createPixiApp`. */
export interface PixiAppOptions {
  /** Canvas background colour. Default 0x10141c. */
  background?: ColorSource;
  /** Element the canvas fills (it follows the element's size). Default: the page layout's stage (./layout). */
  parent?: HTMLElement;
  /** Device pixel ratio to render at, in (0, 4]. Default min(devicePixelRatio, 2). */
  resolution?: number;
  /**
   * Multisample antialiasing of the canvas. Default false: balls come from a mipmapped texture with
   * smooth edges already, and MSAA costs fill rate (a quarter of the frame rate under software WebGL).
   */
  antialias?: boolean;
}

/**
 * Creates a pixi Application (WebGL) whose canvas fills `parent` (the layout's stage: the window
 * less the page's columns) and follows its size. Its ticker is not started: the game loop renders
 * explicitly with `app.render()` after updating.
 * @throws RangeError if resolution is not in (0, 4]; whatever pixi throws when WebGL is unavailable.
 */
export async function createPixiApp(options: PixiAppOptions = {}): Promise<Application> {
  const resolution = options.resolution ?? Math.min(window.devicePixelRatio || 1, 2);
  if (!(resolution > 0 && resolution <= 4)) throw new RangeError(`createPixiApp: resolution must be in (0, 4], got ${resolution}`);
  const parent = options.parent ?? pageLayout().stage;
  const app = new Application();
  await app.init({
    resizeTo: parent,
    background: options.background ?? 0x10141c,
    antialias: options.antialias ?? false,
    resolution,
    autoDensity: true,
    preference: 'webgl',
    autoStart: false,
    sharedTicker: false,
  });
  app.ticker.stop();
  const canvas = app.canvas;
  canvas.style.display = 'block';
  canvas.style.touchAction = 'none';
  parent.append(canvas);
  // pixi follows window resizes; the stage also changes size when the columns around it do.
  new ResizeObserver(() => app.resize()).observe(parent);
  app.resize();
  return app;
}

/** Options of `startPixiGame`: the shell's options (minus `render`) plus the pixi parts. */
export interface PixiGameOptions extends Omit<GameShellOptions, 'render'> {
  /** Options for the WorldRenderer (its `app` is filled in). */
  renderer?: Omit<WorldRendererOptions, 'app'>;
  /** Options for the Application. */
  app?: PixiAppOptions;
  /** Extra drawing each frame, after the world renderer and before the frame is presented (pointer previews, overlays). */
  onFrame?: (alpha: number, world: PhysicsWorld) => void;
  /**
   * Work each frame before the world renderer places the bodies: move the camera here. The renderer
   * turns metres into pixels with the camera as it is when it places the bodies, so a camera moved in
   * `onFrame` shows the bodies one frame behind the extras drawn there.
   */
  beforeFrame?: (alpha: number, world: PhysicsWorld) => void;
  /**
   * Most frames whose GPU work may still be unfinished when the next is drawn, integer in [1, 8].
   * Default 2. A frame while that many are outstanding is not drawn (the canvas keeps the last one;
   * the world still steps). See ./frame-pacer.
   */
  maxFramesInFlight?: number;
}

/** What `startPixiGame` returns. */
export interface PixiGame {
  /** The shell (also `window.game`, with `renderer`, `app` and the frame `pacer` exposed on it). */
  shell: GameShell & { renderer: WorldRenderer; app: Application; pacer: FramePacer };
  /** The pixi Application. */
  app: Application;
  /** The world renderer; it follows the shell's world across resets. */
  renderer: WorldRenderer;
  /** Paces `app.render()` to the GPU (frames drawn and skipped). */
  pacer: FramePacer;
  /**
   * Has the next frame drawn even if the pacer would skip it: call after a change the player must
   * see at once (a new level's scenery while paused), which a slow GPU would otherwise show only
   * frames later. One frame past the pacer's limit; use for rare events, not every frame.
   */
  drawNext(): void;
}

/**
 * The WebGL 2 context of a pixi Application's renderer, or null (a WebGPU or canvas renderer, WebGL 1).
 * pixi 8's WebGLRenderer holds its context in `gl`.
 */
function webgl2Of(app: Application): WebGL2RenderingContext | null {
  const gl = (app.renderer as unknown as { gl?: unknown }).gl;
  return typeof WebGL2RenderingContext !== 'undefined' && gl instanceof WebGL2RenderingContext ? gl : null;
}

/**
 * Starts a 2D pixi game: Application, shell (world, loop, keys, HUD, window.game, ready flag) and a
 * WorldRenderer that follows the shell's world across resets. Each frame: the renderer places the
 * display objects for alpha (after `beforeFrame`), `onFrame` draws extras, `app.render()` presents, unless the GPU has not
 * finished `maxFramesInFlight` earlier frames (WebGL 2 fences, ./frame-pacer; never under WebGPU or
 * WebGL 1): then that frame is not drawn and the canvas keeps the last one. The first frame after a
 * pause or resume, after a new world (reset, a level) and after `drawNext()` is always drawn.
 * @throws whatever createPixiApp, createGameShell or the WorldRenderer constructor throws (bad
 *   options); RangeError if maxFramesInFlight is not an integer in [1, 8].
 */
export async function startPixiGame(options: PixiGameOptions): Promise<PixiGame> {
  const { renderer: rendererOptions, app: appOptions, onFrame, beforeFrame, maxFramesInFlight, ...shellOptions } = options;
  const app = await createPixiApp(appOptions);
  const pacer = createFramePacer(webgl2Of(app), maxFramesInFlight ?? 2);
  // Set by drawNext, a pause or resume, and a new world: the next frame is drawn whatever the pacer
  // says. A paused scene does not change, so a skipped frame after the pause would otherwise leave the
  // picture from before it (no pause overlay) until the GPU caught up, seconds on a busy one.
  let forced = false;
  let shellRef: GameShell | null = null;
  let wasPaused: boolean | null = null;
  const draw = (): void => {
    const paused = shellRef?.paused ?? false;
    if (paused !== wasPaused) {
      wasPaused = paused;
      forced = true;
    }
    if (!forced && !pacer.mayDraw()) return;
    forced = false;
    app.render();
    pacer.drew();
  };
  const { shell, renderer: worldRenderer } = createRenderedShell(
    shellOptions,
    (world) => new WorldRenderer(world, { ...rendererOptions, app }),
    draw,
    onFrame,
    beforeFrame,
  );
  shellRef = shell;
  shell.onWorldChange(() => {
    forced = true;
  });
  const exposed = shell.expose({ renderer: worldRenderer, app, pacer });
  shell.start();
  const drawNext = (): void => {
    forced = true;
  };
  return { shell: exposed, app, renderer: worldRenderer, pacer, drawNext };
}
