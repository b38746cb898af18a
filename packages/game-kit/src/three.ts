/**
 * The three.js part of the game shell (the 3D counterpart of './pixi'): `createThreeApp` makes a
 * WebGL renderer whose canvas fills the layout's stage (./layout), a scene, a perspective camera with orbit controls
 * (three's own OrbitControls addon) and resize handling; `startThreeGame` joins a `WorldRenderer3D`
 * to the renderer-agnostic shell (page contract, fixed-step loop, P / N / R keys, HUD) through
 * `createRenderedShell`, as './pixi' does.
 * 2D games never load this file, so they never load three.js.
 */

import type { PhysicsWorld } from '@bitphysics/physics';
import { createOrbitControls, frameBox, type OrbitOptions, WorldRenderer3D, type WorldRenderer3DOptions } from '@bitphysics/render-three';
import { ACESFilmicToneMapping, Color, PCFShadowMap, PerspectiveCamera, Scene, SRGBColorSpace, WebGLRenderer } from 'three';
import type { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { createFramePacer, type FramePacer } from './frame-pacer.js';
import type { ControlHint } from './hud.js';
import { pageLayout } from './layout.js';
import { createRenderedShell, type GameShell, type GameShellOptions } from './shell.js';

/** Options of `createThreeApp`. Every field optional; unknown fields are rejected. */
export interface ThreeAppOptions {
  /** Background colour, 0xRRGGBB. Default 0x10141c. */
  background?: number;
  /** Element the canvas fills (it follows its size). Default: the page layout's stage (./layout). */
  parent?: HTMLElement;
  /**
   * Device pixel ratio to render at, in (0, 4]. Default min(devicePixelRatio, 2), or
   * SOFTWARE_PIXEL_RATIO (0.5) under a software WebGL implementation (`isSoftwareWebGL`).
   */
  pixelRatio?: number;
  /**
   * Multisample antialiasing. Default: on, except under a software WebGL implementation
   * (SwiftShader, llvmpipe), where it costs most of the frame (`isSoftwareWebGL`).
   */
  antialias?: boolean;
  /** Shadow maps (PCF filtered). Default true. */
  shadows?: boolean;
  /** Vertical field of view, degrees, in (0, 180). Default 50. */
  fov?: number;
  /** Camera position, scene units. Default (6, 4.5, 8). */
  cameraPosition?: ArrayLike<number>;
  /** Orbit controls options, or false for none. Default {} (three's defaults: left drag orbits). */
  controls?: OrbitOptions | false;
  /**
   * Most frames whose GPU work may still be unfinished when `render` draws another, integer in
   * [1, 8]. Default 2. A `render` while that many are outstanding draws nothing (see `ThreeApp.render`).
   */
  maxFramesInFlight?: number;
}

const APP_OPTIONS = [
  'background',
  'parent',
  'pixelRatio',
  'antialias',
  'shadows',
  'fov',
  'cameraPosition',
  'controls',
  'maxFramesInFlight',
];

/**
 * The pixel ratio a three.js page renders at by default under software WebGL (SwiftShader, llvmpipe:
 * a machine without a GPU, or headless Chromium): 0.5, a quarter of the pixels. There the frame's cost
 * is the pixels it fills, and a page drawn at full size runs at one or two frames a second; at 0.5 a
 * frame of the wrecking ball, flight simulator, balls-3d and rigid-body lab pages takes 2 to 4 times
 * less time (SwiftShader in headless Chromium, 1280 x 800). A page that passes `pixelRatio` keeps it.
 */
export const SOFTWARE_PIXEL_RATIO = 0.5;

let softwareGL: boolean | null = null;

/**
 * Whether WebGL runs in software (SwiftShader, llvmpipe, "Software" renderers, as in headless
 * Chromium): asks a throwaway context for its unmasked renderer string (WEBGL_debug_renderer_info).
 * Cached after the first call; false when the string is not available.
 */
export function isSoftwareWebGL(): boolean {
  if (softwareGL !== null) return softwareGL;
  softwareGL = false;
  try {
    const gl = document.createElement('canvas').getContext('webgl2') ?? document.createElement('canvas').getContext('webgl');
    if (gl) {
      const ext = gl.getExtension('WEBGL_debug_renderer_info');
      const name = ext ? String(gl.getParameter(ext.UNMASKED_RENDERER_WEBGL)) : String(gl.getParameter(gl.RENDERER));
      softwareGL = /swiftshader|llvmpipe|software|softpipe/i.test(name);
      gl.getExtension('WEBGL_lose_context')?.loseContext();
    }
  } catch {
    softwareGL = false;
  }
  return softwareGL;
}

/** What the WebGL renderer did in the last frame (`WebGLRenderer.info`). */
export interface FrameInfo {
  /** Draw calls, shadow passes included. */
  calls: number;
  /** Triangles drawn. */
  triangles: number;
  /** Line segments drawn. */
  lines: number;
  /** Points drawn. */
  points: number;
  /** Geometries and textures held on the GPU. */
  geometries: number;
  textures: number;
  /** Frames drawn by `ThreeApp.render` since the app was created. */
  framesDrawn: number;
  /** Calls of `ThreeApp.render` that drew nothing because the GPU had not finished the frames before (see `render`). */
  framesSkipped: number;
}

/** A three.js page: renderer, scene, camera, controls, sized to the window. */
export interface ThreeApp {
  /** The WebGL renderer. */
  readonly renderer: WebGLRenderer;
  /** The scene. */
  readonly scene: Scene;
  /** The camera (its aspect follows the window). */
  readonly camera: PerspectiveCamera;
  /** The orbit controls, or null when turned off. */
  readonly controls: OrbitControls | null;
  /** The canvas. */
  readonly canvas: HTMLCanvasElement;
  /** The frame pacer of `render` (frames drawn and skipped; see ./frame-pacer). */
  readonly pacer: FramePacer;
  /**
   * Updates the controls (damping) and draws the scene, unless the GPU has not yet finished
   * `maxFramesInFlight` earlier frames (WebGL2 fence syncs, polled without waiting): then it draws
   * nothing and the canvas keeps its last frame. This paces the page to the GPU. Without it a
   * GPU slower than the frame rate (software WebGL: SwiftShader, llvmpipe) queues frames without
   * bound, and any call that waits for the GPU (readPixels, drawing the canvas elsewhere, a shader's
   * link status) blocks the page for the whole queue: 16 s after 25 s of balls-3d with 3,000 balls
   * in headless Chromium on a busy machine, growing for as long as the page runs.
   * @returns whether a frame was drawn.
   */
  render(): boolean;
  /** Draw calls, triangles and GPU resources of the last `render`. */
  info(): FrameInfo;
  /**
   * Converts a pointer position (clientX, clientY, CSS px) to normalised device coordinates
   * (-1..1, y up) of the canvas, written into `out` (allocated if omitted).
   */
  toNdc(clientX: number, clientY: number, out?: [number, number]): [number, number];
  /**
   * Frames the camera on the box (min, max), scene units (see render-three's `frameBox`), and frames
   * it again whenever the canvas changes size (a phone turned, the layout settling), until the
   * player moves the camera with the orbit controls.
   */
  frame(min: ArrayLike<number>, max: ArrayLike<number>, direction?: ArrayLike<number>): void;
  /** Stops following resizes, disposes the controls and the renderer, removes the canvas. */
  destroy(): void;
}

/**
 * Creates the WebGL renderer (sRGB output, ACES tone mapping, PCF-filtered shadows), a scene with a
 * background colour, a perspective camera and orbit controls; the canvas fills `parent` and
 * follows its resizes. Nothing is drawn until `render`.
 * @throws TypeError on an unknown option; RangeError on pixelRatio outside (0, 4] or fov outside (0, 180);
 *   whatever three.js throws when WebGL is unavailable.
 */
export function createThreeApp(options: ThreeAppOptions = {}): ThreeApp {
  const where = 'createThreeApp';
  for (const key of Object.keys(options)) {
    if (!APP_OPTIONS.includes(key))
      throw new TypeError(`${where}: unknown option ${JSON.stringify(key)}; known options are ${APP_OPTIONS.join(', ')}`);
  }
  const pixelRatio = options.pixelRatio ?? (isSoftwareWebGL() ? SOFTWARE_PIXEL_RATIO : Math.min(window.devicePixelRatio || 1, 2));
  if (!(pixelRatio > 0 && pixelRatio <= 4)) throw new RangeError(`${where}: pixelRatio must be in (0, 4], got ${pixelRatio}`);
  const fov = options.fov ?? 50;
  if (!(fov > 0 && fov < 180)) throw new RangeError(`${where}: fov must be in (0, 180) degrees, got ${fov}`);
  const cameraPosition = options.cameraPosition ?? [6, 4.5, 8];
  if (cameraPosition.length !== 3 || !Array.from(cameraPosition).every(Number.isFinite)) {
    throw new RangeError(`${where}: cameraPosition must be 3 finite numbers, got ${JSON.stringify(Array.from(cameraPosition))}`);
  }
  const maxInFlight = options.maxFramesInFlight ?? 2;
  if (!(Number.isInteger(maxInFlight) && maxInFlight >= 1 && maxInFlight <= 8)) {
    throw new RangeError(`${where}: maxFramesInFlight must be an integer in [1, 8], got ${maxInFlight}`);
  }
  const parent = options.parent ?? pageLayout().stage;
  const renderer = new WebGLRenderer({ antialias: options.antialias ?? !isSoftwareWebGL(), powerPreference: 'high-performance' });
  renderer.setPixelRatio(pixelRatio);
  renderer.outputColorSpace = SRGBColorSpace;
  renderer.toneMapping = ACESFilmicToneMapping;
  renderer.toneMappingExposure = 1;
  renderer.shadowMap.enabled = options.shadows ?? true;
  renderer.shadowMap.type = PCFShadowMap;
  const canvas = renderer.domElement;
  canvas.style.display = 'block';
  canvas.style.touchAction = 'none';
  parent.append(canvas);
  const scene = new Scene();
  scene.background = new Color(options.background ?? 0x10141c);
  const camera = new PerspectiveCamera(fov, 1, 0.01, 1000);
  camera.position.set(cameraPosition[0]!, cameraPosition[1]!, cameraPosition[2]!);
  const controls = options.controls === false ? null : createOrbitControls(camera, canvas, options.controls ?? {});
  const pacer = createFramePacer(renderer.getContext(), maxInFlight);
  // The box `frame` last fitted, kept while the player has not moved the camera: a new aspect fits it again.
  let framed: { min: number[]; max: number[]; options: { direction?: number[] } } | null = null;
  controls?.addEventListener('start', () => {
    framed = null;
  });

  const resize = (): void => {
    const w = Math.max(1, parent === document.body ? window.innerWidth : parent.clientWidth);
    const h = Math.max(1, parent === document.body ? window.innerHeight : parent.clientHeight);
    renderer.setSize(w, h, true);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    if (framed !== null) frameBox(camera, controls, framed.min, framed.max, framed.options);
    // A new size clears the canvas: draw the scene again at once, or the page shows a black frame
    // until the next animation frame (as when a page's header grows a line).
    renderer.render(scene, camera);
  };
  resize();
  window.addEventListener('resize', resize);
  // The layout's stage also changes size when the columns around it do.
  const observer = new ResizeObserver(resize);
  observer.observe(parent);

  return {
    renderer,
    scene,
    camera,
    controls,
    canvas,
    pacer,
    render() {
      controls?.update();
      if (!pacer.mayDraw()) return false;
      renderer.render(scene, camera);
      pacer.drew();
      return true;
    },
    info() {
      const i = renderer.info;
      return {
        calls: i.render.calls,
        triangles: i.render.triangles,
        lines: i.render.lines,
        points: i.render.points,
        geometries: i.memory.geometries,
        textures: i.memory.textures,
        framesDrawn: pacer.drawn,
        framesSkipped: pacer.skipped,
      };
    },
    toNdc(clientX, clientY, out = [0, 0]) {
      const rect = canvas.getBoundingClientRect();
      out[0] = ((clientX - rect.left) / Math.max(1, rect.width)) * 2 - 1;
      out[1] = -(((clientY - rect.top) / Math.max(1, rect.height)) * 2 - 1);
      return out;
    },
    frame(min, max, direction) {
      const options = direction ? { direction: Array.from(direction) } : {};
      frameBox(camera, controls, min, max, options);
      framed = { min: Array.from(min), max: Array.from(max), options };
    },
    destroy() {
      pacer.clear();
      window.removeEventListener('resize', resize);
      observer.disconnect();
      controls?.dispose();
      renderer.dispose();
      canvas.remove();
    },
  };
}

/** Legend lines for the default orbit controls. */
export const ORBIT_CONTROLS: readonly ControlHint[] = Object.freeze([
  { keys: 'Drag', action: 'orbit the camera' },
  { keys: 'Wheel', action: 'zoom' },
  { keys: 'Right-drag', action: 'pan' },
]);

/** Legend lines for orbit controls with the left button left to the game (`leftButton: 'none'`). */
export const ORBIT_CONTROLS_RIGHT: readonly ControlHint[] = Object.freeze([
  { keys: 'Right-drag', action: 'orbit the camera (Shift: pan)' },
  { keys: 'Wheel', action: 'zoom' },
]);

/** Options of `startThreeGame`: the shell's options (minus `render`) plus the three.js parts. */
export interface ThreeGameOptions extends Omit<GameShellOptions, 'render'> {
  /** Options for the WorldRenderer3D (its `scene` is filled in). */
  renderer?: Omit<WorldRenderer3DOptions, 'scene'>;
  /** Options for the app (renderer, camera, controls). */
  app?: ThreeAppOptions;
  /**
   * What the camera frames at start: the world's boundary box (`'boundary'`, the default), a box
   * { min, max } in metres, or null to keep `app.cameraPosition`.
   */
  view?: 'boundary' | { min: ArrayLike<number>; max: ArrayLike<number> } | null;
  /** Direction from the framed box's centre to the camera. Default (0.9, 0.65, 1.25). */
  viewDirection?: ArrayLike<number>;
  /** Extra work each frame after the world renderer placed its instances and before the frame is drawn (arrows, labels, camera follow). */
  onFrame?: (alpha: number, world: PhysicsWorld) => void;
}

/** What `startThreeGame` returns. */
export interface ThreeGame {
  /** The shell (also `window.game`, with `renderer`, `app` and the app's frame `pacer` exposed on it). */
  shell: GameShell & { renderer: WorldRenderer3D; app: ThreeApp; pacer: FramePacer };
  /** The three.js app. */
  app: ThreeApp;
  /** The world renderer; it follows the shell's world across resets. */
  renderer: WorldRenderer3D;
}

/**
 * Starts a 3D game: app (WebGL renderer, scene, camera, orbit controls), shell (world, loop, keys,
 * HUD, window.game, ready flag) and a WorldRenderer3D that follows the shell's world across resets.
 * Each frame: the world renderer places the instances for alpha, `onFrame` runs, the app draws.
 * Async like `startPixiGame`, so games start the same way.
 * @throws whatever createThreeApp, createGameShell or the WorldRenderer3D constructor throws (bad options, no WebGL).
 */
export async function startThreeGame(options: ThreeGameOptions): Promise<ThreeGame> {
  const { renderer: rendererOptions, app: appOptions, onFrame, view, viewDirection, ...shellOptions } = options;
  const app = createThreeApp(appOptions);
  const { shell, renderer: worldRenderer } = createRenderedShell(
    shellOptions,
    (world) => new WorldRenderer3D(world, { ...rendererOptions, scene: app.scene }),
    () => app.render(),
    onFrame,
  );
  const v = view === undefined ? 'boundary' : view;
  if (v !== null) {
    const k = worldRenderer.unitsPerMeter;
    const box = shell.world.collision.boundary;
    const min = v === 'boundary' ? (box.enabled ? box.min : null) : v.min;
    const max = v === 'boundary' ? (box.enabled ? box.max : null) : v.max;
    if (min && max) {
      app.frame([min[0]! * k, min[1]! * k, min[2]! * k], [max[0]! * k, max[1]! * k, max[2]! * k], viewDirection);
    }
  }
  const exposed = shell.expose({ renderer: worldRenderer, app, pacer: app.pacer });
  shell.start();
  return { shell: exposed, app, renderer: worldRenderer };
}
