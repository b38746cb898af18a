/**
 * Fireworks: a show that runs on its own (the auto-show plays ./show.ts `PROGRAMME`: peonies,
 * chrysanthemums, willows, rings, crossettes, palms, strobes and the book's crackling stars, singly
 * and in salvos), and click (or tap) to launch a shell from the ground towards the pointer; it bursts
 * there about 2 s later (show.ts FUSE) into stars as its recipe says (./recipes.ts), which fall under
 * gravity with quadratic drag and fade over their lifetime. Hold the button longer for a bigger
 * burst (up to three times the stars, 1.44 times the radius, at 1.5 s). A player's launch (click, tap,
 * Space, the panel's button) holds the auto-show for 8 s (show.ts PLAYER_PAUSE), so the player's
 * shells are the only new ones in the sky; a ring marks where each of them will burst. Random
 * colours, additive blending, star trails.
 *
 * Keys: P pause, N single step, R reset, A auto-show on / off, T trails on / off, Space random shell.
 * URL: ?sparks=N (per normal burst, 10..10000), ?generations=1|2|3 (the crackle recipe), ?auto=0|1
 * (auto-show, default on), ?shell=random|peony|chrysanthemum|willow|palm|crossette|ring|strobe|crackle
 * (what a click launches), ?opening=N
 * (shells at start, 0..16), ?trails=0|1, ?seed=S, ?capacity=N (entities, 1000..2000000; default
 * 60000), ?stress (3000 sparks a burst, auto-show, no trails: 50,000 to 60,000 live sparks at
 * the peaks), ?threads=N (1..16: a world with worker threads when the page is cross-origin isolated,
 * as `npm start` serves it; the state is the same as with one thread. The sparks' forces and
 * integration run as one fused pass on the page's thread, which beat the separate passes split over
 * 2 threads at every count measured, so today the threads do not speed this page up).
 *
 * The show itself (scene, launches, bursts, auto-show) is DOM-free in ./show.ts.
 * Sound (@bitphysics/game-kit/sound): a whoosh per launch, a bang per burst, a crackle when sparks burst again.
 */

import { choiceParam, createPanel, flagParam, getSound, numberParam, pageLayout, plural, seedParam } from '@bitphysics/game-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import {
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  type PhysicsWorld,
  Rng,
  slotOf,
  stateHash,
  threadsReady,
} from '@bitphysics/physics';
import { Container, Graphics, Sprite, Texture } from 'pixi.js';
import { RECIPE_NAMES, type RecipeName } from './recipes';
import {
  BURST_SPEED,
  buildFireworks,
  burstScale,
  burstSize,
  type FireworksShow,
  FLASHES,
  FUSE,
  fireworksWorldOptions,
  launchShell,
  MAX_HOLD,
  PLAYER_PAUSE,
  pauseAutoShow,
  SKY,
  setAutoShow,
  setShowDrag,
  setShowGenerations,
  setShowGravity,
  setShowSparks,
  stepFireworks,
} from './show';

const search = new URLSearchParams(location.search);
const stress = flagParam('stress');
const params = {
  gravity: 9.81,
  /** Quadratic drag coefficient of a 1 g spark, g/m (the show takes kg/m: / 1000). */
  drag: 0.05,
  sparks: numberParam('sparks', { default: stress ? 3000 : 300, min: 10, max: 10_000, integer: true }),
  generations: numberParam('generations', { default: 2, min: 1, max: 3, integer: true }),
  // The show runs on its own unless ?auto=0 (clicks and Space still launch).
  autoShow: search.has('auto') ? flagParam('auto') : true,
  /** What a click or Space launches: a recipe of ./recipes.ts, or 'random'. */
  shellType: choiceParam('shell', ['random', ...RECIPE_NAMES] as const, 'random') as 'random' | RecipeName,
  // Trails double the drawing work; the stress show starts without them (T turns them on).
  trails: search.has('trails') ? flagParam('trails') : !stress,
  additive: true,
  seed: seedParam(),
  opening: numberParam('opening', { default: 3, min: 0, max: 16, integer: true }),
  capacity: numberParam('capacity', { default: 60_000, min: 1000, max: 2_000_000, integer: true }),
  threads: numberParam('threads', { default: 1, min: 1, max: 16, integer: true }),
  launch: () => randomLaunch(),
  reset: () => game.shell.reset(),
};

/** Streaks behind the stars: long and bright enough to read as trails on a phone too. */
const TRAILS = { duration: 0.13, width: 0.55, alpha: 0.7 };
/** How long a burst's flash lasts, s. */
const FLASH_SECONDS = 0.25;
/** Bursts whose flash the last frame drew. */
let flashing = 0;

/** The recipe of the next click or Space launch. */
function nextRecipe(): RecipeName {
  if (params.shellType !== 'random') return params.shellType;
  return RECIPE_NAMES[Math.floor(Math.random() * RECIPE_NAMES.length)]!;
}

let show!: FireworksShow;

/**
 * The sky for this screen, m, shaped like the stage so no band of it is left black: about 6.2 px a
 * metre across, within [64, 120] m (a phone held upright gets 64 m, so bursts stay large enough to
 * aim at), and as tall as the stage's shape allows within [70, 160] m. Taps land where they aim.
 */
function skyForStage(): { width: number; height: number } {
  const stage = pageLayout().stage;
  const w = stage.clientWidth || innerWidth,
    h = stage.clientHeight || innerHeight;
  if (!(w > 0 && h > 0)) return SKY;
  const width = Math.min(SKY.width, Math.max(64, w / 6.2));
  return { width, height: Math.min(160, Math.max(SKY.height, Math.round(((width * h) / w) * 0.97))) };
}
/** Whether this page may share memory with workers (SharedArrayBuffer needs cross-origin isolation). */
const ISOLATED = (globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated === true;
let previous: PhysicsWorld | null = null;

/** A fresh world and show from the current parameters (at start and on R); the old world's workers stop. */
function createWorld(): PhysicsWorld {
  if (previous !== null) disposeWorld(previous);
  const options = {
    seed: params.seed,
    gravity: params.gravity,
    drag: params.drag / 1000,
    sparks: params.sparks,
    generations: params.generations,
    autoShow: params.autoShow,
    opening: params.opening,
    capacity: params.capacity,
    sky: skyForStage(),
  };
  // ?threads above 1 needs the thread pool, loaded only when asked for.
  if (ISOLATED && params.threads > 1) enableThreads();
  const world = createPhysicsWorld({ ...fireworksWorldOptions(options), threads: ISOLATED ? params.threads : 1 });
  show = buildFireworks(world, options);
  previous = world;
  return world;
}

const game = await startPixiGame({
  title: 'Fireworks',
  createWorld,
  step: (world) => stepFireworks(world, show),
  controls: [
    { keys: 'Click', action: 'launch a shell (hold: bigger burst)' },
    { keys: 'A', action: `auto-show on / off (waits ${PLAYER_PAUSE} s after your shell)` },
    { keys: 'T', action: 'trails on / off' },
    { keys: 'Space', action: 'random shell' },
  ],
  keys: [
    { key: 'a', label: 'auto-show', action: () => setAuto(!params.autoShow) },
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: ' ', label: 'random shell', action: () => randomLaunch(), repeat: true },
  ],
  renderer: {
    view: { minX: 0, minY: 0, maxX: SKY.width, maxY: SKY.height },
    padding: 0,
    particles: { blend: 'add', trails: params.trails ? TRAILS : false, minPixelSize: 1.5 },
  },
  app: { background: 0x03050c },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;
const layer = renderer.particles!;

/** Auto-show on or off (the A key and the panel). */
function setAuto(on: boolean): void {
  params.autoShow = on;
  setAutoShow(show, on);
  panel.refresh();
}

/** Trails on or off (the T key and the panel). */
function setTrails(on: boolean): void {
  params.trails = on;
  layer.setTrails(on ? TRAILS : false);
  panel.refresh();
}

/**
 * Launches a shell at a random point of the upper sky with a random hold: a player's launch (Space,
 * the panel's button), so it holds the auto-show. @returns its id or 0.
 */
function randomLaunch(): number {
  const r = show.rng;
  pauseAutoShow(show);
  return launchShell(
    shell.world,
    show,
    r.range(0.15, 0.85) * show.params.sky.width,
    r.range(0.45, 0.85) * show.params.sky.height,
    r.range(0, MAX_HOLD),
    nextRecipe(),
  );
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
      onChange: (g) => setShowGravity(shell.world, show, g),
    },
    {
      type: 'slider',
      key: 'drag',
      label: 'drag k (g/m, 1 g spark)',
      min: 0,
      max: 0.5,
      step: 0.001,
      onChange: (k) => setShowDrag(shell.world, show, k / 1000),
    },
    {
      type: 'slider',
      key: 'sparks',
      label: 'sparks per burst',
      min: 10,
      max: 5000,
      step: 10,
      onChange: (n) => setShowSparks(show, Math.round(n)),
    },
    { type: 'slider', key: 'generations', min: 1, max: 3, step: 1, onChange: (g) => setShowGenerations(shell.world, show, Math.round(g)) },
    { type: 'checkbox', key: 'autoShow', label: 'auto-show (A)', onChange: (v) => setAuto(v === true) },
    { type: 'choice', key: 'shellType', label: 'shell (click, Space)', options: ['random', ...RECIPE_NAMES] },
    { type: 'checkbox', key: 'trails', label: 'trails (T)', onChange: (v) => setTrails(v === true) },
    { type: 'checkbox', key: 'additive', label: 'additive blending', onChange: (v) => layer.setBlend(v === true ? 'add' : 'normal') },
    {
      type: 'slider',
      key: 'threads',
      label: ISOLATED ? 'threads (rebuilds)' : 'threads (page not isolated: 1)',
      min: 1,
      max: 16,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'button', key: 'launch', label: 'launch a shell (Space)' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Fireworks' },
);

// ---- HUD line: live sparks ---------------------------------------------------------------------

const sparkLine = document.createElement('div');
sparkLine.dataset.hud = 'sparks';
shell.hud.readout.append(sparkLine);
let sparkShown = -1;

// ---- Drawing: sky, ground, shells, the charging ring -------------------------------------------

const skyLayer = new Graphics({ label: 'sky' });
app.stage.addChildAt(skyLayer, 0);
const ground = new Graphics({ label: 'ground' });
const overlay = new Graphics({ label: 'shells-and-pointer' });
app.stage.addChild(ground, overlay);

/** A soft round glow, white at the centre through warm gold to clear at the rim (a 128 px canvas). */
function glowTexture(): Texture {
  const c = document.createElement('canvas');
  c.width = c.height = 128;
  const g = c.getContext('2d')!;
  const grad = g.createRadialGradient(64, 64, 0, 64, 64, 64);
  grad.addColorStop(0, 'rgba(255, 255, 255, 1)');
  grad.addColorStop(0.2, 'rgba(255, 240, 200, 0.85)');
  grad.addColorStop(0.5, 'rgba(255, 190, 90, 0.3)');
  grad.addColorStop(1, 'rgba(255, 160, 60, 0)');
  g.fillStyle = grad;
  g.fillRect(0, 0, 128, 128);
  return Texture.from(c);
}
// The flashes add light to what is under them, one glow sprite per remembered burst.
const flashLayer = new Container({ label: 'flashes' });
const glow = glowTexture();
const flashSprites = Array.from({ length: FLASHES }, () => {
  const sprite = new Sprite({ texture: glow, anchor: 0.5, blendMode: 'add', visible: false });
  flashLayer.addChild(sprite);
  return sprite;
});
app.stage.addChild(flashLayer);
let skyVersion = -1;

/** Faint stars: x, y (fractions of the sky's width and height) and alpha. */
const STARS: [number, number, number][] = (() => {
  const r = new Rng(3);
  const out: [number, number, number][] = [];
  for (let i = 0; i < 160; i++) out.push([r.range(0, 1), r.range(0.25, 1), r.range(0.15, 0.6)]);
  return out;
})();

/** Fits the camera to the show's sky (at the start and after a reset, which may pick a new sky). */
function frameSky(): void {
  const sky = show.params.sky;
  const view = renderer.camera.view;
  if (view && view.maxX === sky.width && view.maxY === sky.height) return;
  renderer.camera.fit({ minX: 0, minY: 0, maxX: sky.width, maxY: sky.height });
}
shell.onWorldChange(() => frameSky());
// The first world was made before the stage had its size: make it again for the stage's shape.
const wanted = skyForStage();
if (wanted.width !== show.params.sky.width || wanted.height !== show.params.sky.height) shell.reset();
frameSky();

/** The horizon's skyline: heights (m) of the ground at x = 0, 8, 16, ... m. */
const SKYLINE = [2.2, 2.6, 3.4, 2.8, 2.4, 4.6, 5.2, 3.1, 2.5, 2.2, 3.8, 4.4, 3.0, 2.4, 2.7, 3.6];

function drawSkyAndGround(): void {
  const cam = renderer.camera;
  if (cam.version === skyVersion) return;
  skyVersion = cam.version;
  const sky = show.params.sky;
  skyLayer.clear();
  // Bands of a night sky, darker upwards, across the whole canvas (no letterbox: the view's aspect
  // is the world's, the canvas's is the window's); above the world the darkest band goes on.
  const bands = 12;
  const bandColor = (i: number): number => {
    const f = 1 - i / bands;
    return (Math.round(6 + 14 * f * f) << 16) | (Math.round(9 + 16 * f * f) << 8) | Math.round(24 + 30 * f * f);
  };
  skyLayer.rect(0, 0, cam.width, cam.height).fill(bandColor(bands - 1));
  for (let i = 0; i < bands; i++) {
    const y0 = (sky.height * i) / bands,
      y1 = (sky.height * (i + 1)) / bands;
    const top = i === bands - 1 ? 0 : cam.toScreenY(y1);
    skyLayer.rect(0, top, cam.width, cam.toScreenY(y0) - top + 1).fill(bandColor(i));
  }
  for (const [x, y, a] of STARS)
    skyLayer.circle(cam.toScreenX(x * sky.width), cam.toScreenY(y * sky.height), 0.8).fill({ color: 0xdfe8ff, alpha: a });
  // The skyline, held level past the world's ends, and the ground to the canvas's bottom.
  ground.clear();
  ground.moveTo(0, cam.height).lineTo(0, cam.toScreenY(SKYLINE[0]!));
  for (let i = 0; i < SKYLINE.length; i++) ground.lineTo(cam.toScreenX((i * sky.width) / (SKYLINE.length - 1)), cam.toScreenY(SKYLINE[i]!));
  ground
    .lineTo(cam.width, cam.toScreenY(SKYLINE[SKYLINE.length - 1]!))
    .lineTo(cam.width, cam.height)
    .closePath()
    .fill(0x020306);
}

/**
 * The charging ring's radius over the burst's fastest star speed, s: the ring is BURST_SPEED x reach x
 * burstSize x this, 11.2 m for a click in a phone's sky, about how far a peony's fastest stars get in
 * their first second (x(t) = ln(1 + k v0 t / m) m / k: 11.8 m at 16 m/s under the default drag).
 */
const PREVIEW_SECONDS = 0.7;
/** The player's shells in flight: entity handle and target (m), for the marker where each will burst. */
const targets: { id: number; x: number; y: number }[] = [];
let pointerId = -1;
let pressedAt = 0;
let pointerX = 0,
  pointerY = 0;

const sound = getSound();
/** Launches and bursts already heard (the show counts them; a reset starts the counts again). */
let heardLaunches = 0,
  heardBursts = 0;

/** A whoosh per new launch; a bang and, with generations >= 2, a crackle per new burst. */
function playShowSounds(): void {
  if (show.launched < heardLaunches || show.bursts < heardBursts) heardLaunches = heardBursts = 0;
  if (show.launched > heardLaunches) sound.launch(0.5);
  for (let n = Math.min(3, show.bursts - heardBursts); n > 0; n--) {
    sound.explosion(0.5);
    if (params.generations >= 2) sound.crackle(20, 1.4);
  }
  heardLaunches = show.launched;
  heardBursts = show.bursts;
}

function drawFrame(alpha: number, world: PhysicsWorld): void {
  playShowSounds();
  drawSkyAndGround();
  const cam = renderer.camera;
  overlay.clear();
  // Shell heads (the shells are bodies, not particles), interpolated like everything else.
  const P = world.components.Position,
    O = world.components.PreviousPosition;
  for (let i = 0; i < show.shellCount; i++) {
    const e = slotOf(show.shellIds[i]!);
    const x = O.x[e]! + (P.x[e]! - O.x[e]!) * alpha,
      y = O.y[e]! + (P.y[e]! - O.y[e]!) * alpha;
    overlay
      .circle(cam.toScreenX(x), cam.toScreenY(y), Math.max(1.5, cam.toScreenLength(0.35 * burstSize(show.shellScale[i]!))))
      .fill({ color: 0xfff3d0 });
  }
  // The flash of a burst: a glow, white at its core and warm at its rim, at the shell's last place that fades in
  // FLASH_SECONDS, so a burst opens from a bright centre (its first frame was a ring of sparks, all at
  // one radius, with nothing inside).
  flashing = 0;
  for (const sprite of flashSprites) sprite.visible = false;
  for (let k = Math.max(0, show.flashCount - FLASHES); k < show.flashCount; k++) {
    const f = 4 * (k % FLASHES),
      age = world.time - show.flashes[f + 2]!;
    if (age < 0 || age >= FLASH_SECONDS) continue;
    flashing++;
    const fade = 1 - age / FLASH_SECONDS,
      x = cam.toScreenX(show.flashes[f]!),
      y = cam.toScreenY(show.flashes[f + 1]!),
      r = cam.toScreenLength(1.6 * show.reach * burstSize(show.flashes[f + 3]!)) * (0.6 + 0.8 * (1 - fade));
    const sprite = flashSprites[k % FLASHES]!;
    sprite.visible = true;
    sprite.position.set(x, y);
    sprite.width = sprite.height = 5 * r;
    sprite.alpha = fade;
  }
  // Charging: a faint ring about as large as the burst the hold would make (it grows while held), and
  // a bright inner ring that fills up to the longest hold.
  if (pointerId !== -1) {
    const hold = (performance.now() - pressedAt) / 1000;
    const s = burstScale(hold);
    const r = cam.toScreenLength(PREVIEW_SECONDS * BURST_SPEED * show.reach * burstSize(s));
    overlay.circle(pointerX, pointerY, r).stroke({ width: 1.5, color: 0xffe8a0, alpha: 0.2 + 0.08 * (s - 1) });
    overlay.circle(pointerX, pointerY, 6 + 10 * ((s - 1) / 2)).stroke({ width: 2.5, color: 0xffe8a0, alpha: 0.9 });
    overlay.circle(pointerX, pointerY, 3).fill({ color: 0xffe8a0, alpha: 0.9 });
  }
  // Where each of the player's shells will burst: a ring that closes in as its fuse burns down.
  let k = 0;
  for (const m of targets) {
    let burstAt = -1;
    for (let i = 0; i < show.shellCount; i++) if (show.shellIds[i] === m.id) burstAt = show.shellBurstTime[i]!;
    if (burstAt < 0) continue;
    targets[k++] = m;
    const left = Math.max(0, Math.min(1, (burstAt - world.time) / FUSE));
    const x = cam.toScreenX(m.x),
      y = cam.toScreenY(m.y);
    overlay.circle(x, y, 5 + 16 * left).stroke({ width: 2, color: 0xffe8a0, alpha: 0.35 + 0.4 * (1 - left) });
    overlay.circle(x, y, 2).fill({ color: 0xffe8a0, alpha: 0.8 });
  }
  targets.length = k;
  const n = layer.stats.particles;
  if (n !== sparkShown) {
    sparkShown = n;
    sparkLine.textContent = plural(n, 'spark', 'sparks');
  }
}

// ---- Pointer: press to charge, release to launch ------------------------------------------------

const canvas = app.canvas;
function local(event: PointerEvent): void {
  const rect = canvas.getBoundingClientRect();
  pointerX = event.clientX - rect.left;
  pointerY = event.clientY - rect.top;
}
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || pointerId !== -1) return;
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  pressedAt = performance.now();
  local(event);
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId === pointerId) local(event);
});
canvas.addEventListener('pointerup', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  local(event);
  const hold = Math.max(0, (performance.now() - pressedAt) / 1000);
  const cam = renderer.camera;
  pauseAutoShow(show);
  const x = cam.toWorldX(pointerX),
    y = cam.toWorldY(pointerY);
  const id = launchShell(shell.world, show, x, y, hold, nextRecipe());
  if (id !== 0) {
    // The marker sits where the shell will burst (launchShell clamps the target into the sky the same way).
    const sky = show.params.sky;
    targets.push({ id, x: Math.min(sky.width - 4, Math.max(4, x)), y: Math.min(sky.height - 3, Math.max(12, y)) });
  }
});
canvas.addEventListener('pointercancel', (event) => {
  if (event.pointerId === pointerId) pointerId = -1;
});

// ---- Test and console hooks on window.game ----------------------------------------------------

shell.expose({
  params,
  panel,
  /** Launches a shell towards (x, y), m, as if the button had been held `hold` s. @returns its id, or 0 if too many are in flight. */
  launch: (x: number, y: number, hold = 0, recipe: RecipeName = 'crackle'): number => launchShell(shell.world, show, x, y, hold, recipe),
  /** Particles drawn by the particle layer's last frame (live sparks, crackles, tails). */
  particleCount: (): number => layer.stats.particles,
  /** The particle layer's statistics of the last frame. */
  particleStats: () => ({ ...layer.stats }),
  /** Whether the page is cross-origin isolated (threads > 1 possible). */
  isolated: ISOLATED,
  /** Resolves once the world's worker threads have started. */
  threadsReady: (): Promise<void> => threadsReady(shell.world),
  /** Fingerprint of the world's state (stateHash). */
  stateHash: (): string => stateHash(shell.world),
  /** Bursts whose flash the last frame drew (younger than FLASH_SECONDS). */
  flashing: (): number => flashing,
  /** Markers drawn where the player's shells in flight will burst: their targets, m. */
  targetMarkers: (): { x: number; y: number }[] => targets.map((m) => ({ x: m.x, y: m.y })),
  /** Turns the auto-show on or off. */
  setAutoShow: (on: boolean): void => setAuto(on),
});
// The running show (shells in flight, emitters, counters): a getter, so it follows resets (expose
// copies values, which would keep the first show).
Object.defineProperty(shell, 'show', { get: (): FireworksShow => show, enumerable: true });
