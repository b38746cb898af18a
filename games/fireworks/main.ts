/**
 * Fireworks, the lantern show (./lanterns.ts; the default, ?play=free for free play): light every
 * lantern in the sky with your bursts in as few shells as you can, over five levels, with one to three
 * stars a level against its par (best stars kept in localStorage). Each level gives a few shells
 * (LanternLevel.shells; on the first two, fewer than lanterns): spent with a lantern still dark, the
 * level is lost and a card offers Try again. A burst that lights two or three lanterns is cheered
 * ("Double!", "Triple!", a chord); a card at each level's end shows its stars, and after the finale
 * every level's. A lantern lights when a burst's
 * hot stars touch it; the charging ring drawn while the button is held shows how far they get (hold
 * longer for a bigger burst, on the levels that allow it); drifting lanterns must be led by the 1.2 s
 * fuse, and a dashed ghost of each, with a dotted trail along its swing, shows where it will be when
 * a shell launched now bursts; each level gives one kind of shell. On a touch screen the row's
 * Free-play button is 44 px tall or more (a finger's target). A lit lantern's glow comes up over half a second; the
 * level shows as lit (the row's banner, the stars, the Next-level button) 1.2 s after its last
 * lantern lit, when every glow is full (./lanterns.ts clearShown). On a phone held upright the levels
 * play their tall layouts, spread over the screen's height. The sky starts dark (no opening salvo)
 * and the auto-show stays off. The status row above the sky says the goal and the level's tally, each
 * line one line on a phone; R restarts the level; the row's Free-play button switches modes. The
 * controls legend (and a phone's gesture card) offers "hold: bigger burst" only where holding does
 * something: on the levels that allow it, and in free play.
 *
 * Free play: a show that runs on its own (the auto-show plays ./show.ts `PROGRAMME`: peonies,
 * chrysanthemums, willows, rings, crossettes, palms, strobes and the book's crackling stars, singly
 * and in salvos), and click (or tap) to launch a shell from the ground towards the pointer; it bursts
 * there 1.2 s later (show.ts FUSE) into stars as its recipe says (./recipes.ts), which fall under
 * gravity with quadratic drag and fade over their lifetime. Hold the button longer for a bigger
 * burst (up to three times the stars, 1.44 times the radius, at 1.5 s). A player's launch (click, tap,
 * Space, the panel's button) holds the auto-show for 8 s (show.ts PLAYER_PAUSE), so the player's
 * shells are the only new ones in the sky; a ring marks where each of them will burst. Random
 * colours, additive blending, star trails.
 *
 * Keys: P pause, N single step, R reset, A auto-show on / off, T trails on / off, Space random shell.
 * URL: ?play=lanterns|free, ?level=N (the lantern show's level to start at, 1..5), ?sparks=N (per
 * normal burst, 10..10000), ?generations=1|2|3 (the crackle recipe), ?auto=0|1
 * (auto-show in free play, default on), ?shell=random|peony|chrysanthemum|willow|palm|crossette|ring|strobe|crackle
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

import {
  choiceParam,
  createActionButton,
  createPanel,
  createStatusRow,
  flagParam,
  getSound,
  numberParam,
  onButtonPress,
  pageLayout,
  plural,
  SHELL_CONTROLS,
  seedParam,
} from '@bitphysics/game-kit';
import { createPauseOverlay, createResultCard, startPixiGame } from '@bitphysics/game-kit/pixi';
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
import { Container, Graphics, Sprite, Text, Texture } from 'pixi.js';
import { gaugeCentre } from './gauge';
import {
  type BurstWatch,
  bestStarsStore,
  clearShown,
  countShell,
  glowOf,
  type LanternRun,
  LEVELS,
  lanternAt,
  lanternRadius,
  lanternsOf,
  lightFromSparks,
  meetCue,
  outOfShells,
  shellsLeft,
  shownLit,
  sparkReach,
  startLevel,
  startWatch,
  watchBursts,
} from './lanterns';
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

/** The legend's lines after the launch (./main.ts launchControls). */
const OTHER_CONTROLS = [
  { keys: 'A', action: `auto-show on / off (waits ${PLAYER_PAUSE} s after your shell)` },
  { keys: 'T', action: 'trails on / off' },
  { keys: 'Space', action: 'random shell' },
];
const stress = flagParam('stress');
/** The lantern show (the default) or free play (?play=free, and the stress show). */
let lanternShow = choiceParam('play', ['lanterns', 'free'] as const, stress ? 'free' : 'lanterns') === 'lanterns';
const params = {
  gravity: 9.81,
  /** Quadratic drag coefficient of a 1 g spark, g/m (the show takes kg/m: / 1000). */
  drag: 0.05,
  sparks: numberParam('sparks', { default: stress ? 3000 : 300, min: 10, max: 10_000, integer: true }),
  generations: numberParam('generations', { default: 2, min: 1, max: 3, integer: true }),
  // In free play the show runs on its own unless ?auto=0 (clicks and Space still launch); the
  // lantern show starts without it (its bursts would light lanterns for you).
  autoShow: search.has('auto') ? flagParam('auto') : !lanternShow,
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
/** How long a burst's front ring takes to race out to its stars' reach, s (world time). */
const BURST_RING_SECONDS = 0.5;
/** The newest burst's front ring as last drawn (tests): its burst scale, the reach it races to and its radius now, px, and its age, s. */
let burstRingShown = { scale: 0, reach: 0, radius: 0, age: Number.NaN };
/** Bursts whose flash the last frame drew. */
let flashing = 0;

/** The recipe of the next click or Space launch. */
function nextRecipe(): RecipeName {
  if (lanternShow) return LEVELS[run.level]!.shell;
  if (params.shellType !== 'random') return params.shellType;
  return RECIPE_NAMES[Math.floor(Math.random() * RECIPE_NAMES.length)]!;
}

let show!: FireworksShow;
/** The lantern show's level (an index into LEVELS; ?level=N starts at level N, 1-based) and its run. */
let level = numberParam('level', { default: 1, min: 1, max: LEVELS.length, integer: true }) - 1;
let run: LanternRun = startLevel(level, 0);
/** A lantern lit: where (m) and when (world time, s), for the ring that widens from it. */
const lightings: { x: number; y: number; time: number; index: number }[] = [];
/** Where the best stars are kept (localStorage, ./lanterns.ts bestStarsStore). */
const starsStore = bestStarsStore();
/** Best stars of each level (0 for a level not yet lit). */
const bestStars = starsStore.read();

/** The lantern show's bursts being watched for what they light (a miss is said near its burst). */
let watch: BurstWatch;
/** Bursts that lit nothing: where (m) and when the miss was known (world time, s), newest last (at most 8). */
const misses: { x: number; y: number; time: number }[] = [];
/** Misses since the level started (tests). */
let missCount = 0;
/** Bursts that lit two lanterns or more: where (m), when the count was reached (world time, s) and how many. */
const combos: { x: number; y: number; time: number; lit: number }[] = [];
/** The watched bursts already cheered, and how many lanterns each had then. */
const cheered = new WeakMap<object, number>();
/** World time the level was lost (its shells spent, a lantern still dark), NaN while it is not. */
let lostAt = Number.NaN;

/**
 * One step of the show, then (lantern show) the lanterns its hot stars touch light up, and a burst
 * whose stars went cold having lit nothing is a miss.
 */
function stepShow(world: PhysicsWorld): void {
  stepFireworks(world, show);
  if (!lanternShow || run.stars !== 0 || !Number.isNaN(lostAt)) return;
  const lit = lightFromSparks(world, show, run);
  const misses0 = watchBursts(watch, show, run, lit, world.time);
  // A burst that lit two or more: "Double!", "Triple!" over it, and a chord a step higher each.
  for (const b of watch.bursts) {
    if (b.lit < 2 || (cheered.get(b) ?? 0) >= b.lit) continue;
    cheered.set(b, b.lit);
    combos.push({ x: b.x, y: b.y, time: world.time, lit: b.lit });
    if (combos.length > 6) combos.shift();
    const base = 523.25 * 2 ** ((b.lit - 2) * 0.25);
    setTimeout(() => sound.chime(base * 1.5, 0.35), 120);
    setTimeout(() => sound.chime(base * 2, 0.6), 240);
  }
  if (run.stars === 0 && outOfShells(run, show.shellCount + watch.bursts.length)) {
    lostAt = world.time;
    // Three falling notes: the level is lost (the Try-again button comes up).
    sound.chime(392, 0.25);
    setTimeout(() => sound.chime(330, 0.25), 160);
    setTimeout(() => sound.chime(262, 0.6), 320);
  }
  for (const m of misses0) {
    misses.push({ x: m.x, y: m.y, time: world.time });
    missCount++;
    if (misses.length > 8) misses.shift();
    // A soft falling pair of notes: not a failure sting, a "not that one".
    sound.chime(330, 0.18);
    setTimeout(() => sound.chime(247, 0.3), 120);
  }
  if (lit.length === 0) return;
  for (const i of lit) {
    const [x, y] = lanternAt(lanternsOf(run.level, show.params.sky)[i]!, show.params.sky, world.time - run.start);
    lightings.push({ x, y, time: world.time, index: i });
  }
  if (lightings.length > 16) lightings.splice(0, lightings.length - 16);
  sound.chime(660 + 110 * Math.min(4, run.lit.filter(Boolean).length));
  if (run.stars > 0) levelLit();
}

/** All lanterns lit: keeps the level's best stars (the level shows as lit, with its chime, CLEAR_DELAY later). */
function levelLit(): void {
  if (run.stars > bestStars[run.level]!) {
    bestStars[run.level] = run.stars;
    starsStore.write(bestStars);
  }
}
/** World time the level was first shown as lit (NaN until then), s. */
let clearShownAt = Number.NaN;
/**
 * Set by a fresh world (a new level, a retry, R): the status row, the card and the action button are
 * written for it with the next frame, not the last frame's lines for the level before, so the old
 * level's card never stays up over the new one.
 */
let freshWorld = false;

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
    autoShow: params.autoShow && !lanternShow,
    // The lantern show starts with a dark sky: every star in it is the player's.
    opening: lanternShow ? 0 : params.opening,
    capacity: params.capacity,
    sky: skyForStage(),
  };
  // ?threads above 1 needs the thread pool, loaded only when asked for.
  if (ISOLATED && params.threads > 1) enableThreads();
  const world = createPhysicsWorld({ ...fireworksWorldOptions(options), threads: ISOLATED ? params.threads : 1 });
  show = buildFireworks(world, options);
  previous = world;
  // A new world restarts the level being played (its lanterns' drift clock is the world's time).
  run = startLevel(level, 0);
  lightings.length = 0;
  clearShownAt = Number.NaN;
  watch = startWatch(show);
  misses.length = 0;
  missCount = 0;
  combos.length = 0;
  lostAt = Number.NaN;
  freshWorld = true;
  return world;
}

/**
 * The controls legend for the mode and level being played: a click launches; "hold: bigger burst"
 * only where holding makes one (free play, and the levels that allow it). On a phone the gesture card
 * is made from these too.
 */
function launchControls(): { keys: string; action: string }[] {
  const holds = !lanternShow || LEVELS[level]!.hold;
  return [{ keys: 'Click', action: holds ? 'launch a shell (hold: bigger burst)' : 'launch a shell' }];
}

const game = await startPixiGame({
  title: 'Fireworks',
  createWorld,
  step: (world) => stepShow(world),
  controls: [...launchControls(), ...OTHER_CONTROLS],
  keys: [
    { key: 'a', label: 'auto-show', action: () => setAuto(!params.autoShow) },
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: ' ', label: 'random shell', action: () => void (launchHeld() || randomLaunch()), repeat: true },
    // Enter does what the big button over the card says (next level, try again, play again) while it shows.
    { key: 'Enter', label: 'next level', action: () => actionShown && nextLevel() },
  ],
  renderer: {
    view: { minX: 0, minY: 0, maxX: SKY.width, maxY: SKY.height },
    padding: 0,
    particles: { blend: 'add', trails: params.trails ? TRAILS : false, minPixelSize: 1.5 },
  },
  // The sky's darkest, highest band (0x060918; see skyBandColor): drawSkyAndGround leaves it to the clear.
  app: { background: 0x060918 },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;

/**
 * Whether the player paused the show (the P key or the pause button; cleared once it runs again).
 * Tests that set `paused` to step the show by hand still launch with clicks.
 */
let playerPaused = false;
const shellTogglePause = shell.togglePause.bind(shell);
shell.togglePause = () => {
  shellTogglePause();
  playerPaused = shell.paused;
};
/** Whether a click or tap launches nothing now: the player has paused. */
function launchHeld(): boolean {
  if (!shell.paused) playerPaused = false;
  return playerPaused;
}
const layer = renderer.particles!;

/** The legend as shown now (launchControls' action), to write it again only when it changes. */
let shownControls = launchControls()[0]!.action;
/** Writes the controls legend (and a phone's gesture card) again when the level or mode changes what a hold does. */
function updateControls(): void {
  const c = launchControls();
  if (c[0]!.action === shownControls) return;
  shownControls = c[0]!.action;
  shell.hud.setControls([...SHELL_CONTROLS, ...c, ...OTHER_CONTROLS]);
}
shell.onWorldChange(() => updateControls());

/** Auto-show on or off (the A key and the panel); always off in the lantern show, whose stars would light lanterns. */
function setAuto(on: boolean): void {
  params.autoShow = on && !lanternShow;
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
  return playerLaunch(r.range(0.15, 0.85) * show.params.sky.width, r.range(0.45, 0.85) * show.params.sky.height, r.range(0, MAX_HOLD));
}

/**
 * A player's shell towards (x, y), m, held `hold` s (a quick one on a level without holding):
 * counted by the lantern show. None once the level's shells are spent (`shellsLeft`), nor once every
 * lantern of the level is lit: the next-level button
 * comes up CLEAR_DELAY later where a click would otherwise launch a shell. @returns its id or 0.
 */
function playerLaunch(x: number, y: number, hold: number): number {
  if (lanternShow && (run.stars > 0 || shellsLeft(run) === 0)) return 0;
  const id = launchShell(shell.world, show, x, y, holdCounts() ? hold : 0, nextRecipe());
  if (id !== 0 && lanternShow) countShell(run);
  return id;
}

/** Whether holding makes a bigger burst: always in free play, on the levels that allow it in the lantern show. */
function holdCounts(): boolean {
  return !lanternShow || LEVELS[run.level]!.hold;
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

/** Bands of the night sky (`drawSkyAndGround`). */
const SKY_BANDS = 12;
/** Colour of sky band i (0 the lowest, SKY_BANDS - 1 the highest and darkest), 0xRRGGBB. */
function skyBandColor(i: number): number {
  const f = 1 - i / SKY_BANDS;
  return (Math.round(6 + 14 * f * f) << 16) | (Math.round(9 + 16 * f * f) << 8) | Math.round(24 + 30 * f * f);
}

function drawSkyAndGround(): void {
  const cam = renderer.camera;
  if (cam.version === skyVersion) return;
  skyVersion = cam.version;
  const sky = show.params.sky;
  skyLayer.clear();
  // Bands of a night sky, darker upwards, across the whole canvas (no letterbox: the view's aspect
  // is the world's, the canvas's is the window's); above the world the darkest band goes on. The
  // darkest is the canvas's clear colour (the app's background), so it is not drawn: each pixel of
  // the sky is filled once. Filling the canvas under the bands as well doubled the sky's cost, the
  // largest part of a frame's drawing in software WebGL (SwiftShader), more than a burst's sparks.
  for (let i = 0; i < SKY_BANDS - 1; i++) {
    const y0 = (sky.height * i) / SKY_BANDS,
      y1 = (sky.height * (i + 1)) / SKY_BANDS;
    const top = cam.toScreenY(y1);
    skyLayer.rect(0, top, cam.width, cam.toScreenY(y0) - top + 1).fill(skyBandColor(i));
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
 * Free play's charging ring: radius this x BURST_SPEED x reach x burstSize, s (11.2 m for a click in
 * a phone's sky, about how far a burst's fastest stars get in their first second: x(t) = ln(1 + k v0
 * t / m) m / k, 11.8 m at 16 m/s under the default drag). The lantern show draws its shell's
 * `sparkReach` instead, where the hot stars that light lanterns get.
 */
const FREE_RING_SECONDS = 0.7;
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
  // FLASH_SECONDS, so a burst opens from a bright centre, not a ring of sparks all at one radius with
  // nothing inside.
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
  burstRingShown = { scale: 0, reach: 0, radius: 0, age: Number.NaN };
  // In the lantern show, each new burst's front: a bright ring that races out to where its hot stars
  // will light lanterns (`sparkReach` of its scale) over BURST_RING_SECONDS,
  // easing out as the stars slow, and fades; a held burst's ring is wider and brighter, so a big
  // burst reads as big from its first frames, not as a white ball, like a dud.
  for (let k = lanternShow ? Math.max(0, show.flashCount - FLASHES) : show.flashCount; k < show.flashCount; k++) {
    const f = 4 * (k % FLASHES),
      age = world.time - show.flashes[f + 2]!;
    if (age < 0 || age >= BURST_RING_SECONDS) continue;
    const u = age / BURST_RING_SECONDS,
      scale = show.flashes[f + 3]!,
      x = cam.toScreenX(show.flashes[f]!),
      y = cam.toScreenY(show.flashes[f + 1]!);
    const big = Math.min(1, (scale - 1) / 2);
    const reach = sparkReach(LEVELS[run.level]!.shell, Math.max(1, scale)).side * show.params.sky.width;
    const R = cam.toScreenLength(reach) * (1 - (1 - u) ** 3);
    if (k === show.flashCount - 1) burstRingShown = { scale, reach: cam.toScreenLength(reach), radius: R, age };
    overlay.circle(x, y, R).stroke({ width: 2 + 3 * big, color: big > 0.5 ? 0xfff0c0 : 0xffe08a, alpha: (0.35 + 0.45 * big) * (1 - u) });
    if (big > 0) overlay.circle(x, y, 0.8 * R).stroke({ width: 1.5, color: 0xffb060, alpha: 0.5 * big * (1 - u) });
  }
  drawLanterns(world);
  drawMisses(world);
  drawCombos(world);
  // The status row in both modes, so free play never keeps the lantern show's lines.
  updateStatus();
  drawPause();
  drawCharge();
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

// ---- Charging: what a press shows and sounds from its first frame -----------------------------------

/** Whether the press being charged is a finger's (its gauge is drawn clear of it: ./gauge.ts). */
let pressTouch = false;
/** Charge sounds played for the current press: -1 none yet, 0 the fuse lit, 1 to 3 each third of MAX_HOLD. */
let chargeHeard = -1;
/** Radius of the fuse ring round the pointer, CSS px. */
const FUSE_RING = 20;
/** The label over the fuse ring: what holding does. */
const chargeLabel = new Text({
  text: '',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 13, fontWeight: '600', fill: 0xffe8a0, stroke: { color: 0x03050c, width: 4 } },
});
chargeLabel.anchor.set(0.5, 1);
chargeLabel.visible = false;
app.stage.addChild(chargeLabel);

/**
 * The press being charged, from its first frame: where this burst's stars would get (the reach,
 * growing while held where holding counts; in the lantern show where its hot stars light lanterns,
 * lower than wide, as they droop), a fuse ring round the pointer that pops in and burns once round
 * over MAX_HOLD with a spark at its head (lit at once where holding does nothing), and a label saying
 * what the hold does. Sounds: a fuse's crackle on the press, a rising note at each third of the hold
 * and a higher one when it is full. So the player sees and hears at once that the hold counts.
 */
function drawCharge(): void {
  chargeLabel.visible = false;
  if (pointerId === -1) return;
  const cam = renderer.camera;
  const held = Math.max(0, (performance.now() - pressedAt) / 1000);
  const holds = holdCounts();
  const s = burstScale(holds ? held : 0);
  const burnt = holds ? Math.min(1, held / MAX_HOLD) : 1;
  const stage = holds ? Math.min(3, Math.floor((3 * held) / MAX_HOLD)) : 0;
  if (stage > chargeHeard && sound.running) {
    if (chargeHeard < 0) sound.crackle(6, 0.25);
    sound.chime(stage === 3 ? 1047 : 523 * 2 ** ((4 * stage) / 12), stage === 3 ? 0.3 : 0.1);
    chargeHeard = stage;
  }
  if (lanternShow) {
    // Centred on the aim point, where the shell bursts: half an ellipse up to the stars' reach above
    // it and half down to their (longer, drooping) reach below. One ellipse spanning both would be
    // centred below the aim and read as a burst placed there.
    const reach = sparkReach(LEVELS[run.level]!.shell, s);
    const w = show.params.sky.width;
    const rx = cam.toScreenLength(reach.side * w),
      up = cam.toScreenLength(reach.up * w),
      down = cam.toScreenLength(reach.down * w);
    const n = 48;
    overlay.moveTo(pointerX + rx, pointerY);
    for (let k = 1; k <= n; k++) {
      const a = (2 * Math.PI * k) / n,
        sin = Math.sin(a);
      overlay.lineTo(pointerX + rx * Math.cos(a), pointerY - (sin >= 0 ? up : down) * sin);
    }
    overlay.closePath().fill({ color: 0xffe8a0, alpha: 0.06 }).stroke({ width: 2, color: 0xffe8a0, alpha: 0.55 });
  } else {
    const r = cam.toScreenLength(FREE_RING_SECONDS * BURST_SPEED * show.reach * burstSize(s));
    overlay.circle(pointerX, pointerY, r).stroke({ width: 1.5, color: 0xffe8a0, alpha: 0.25 + 0.08 * (s - 1) });
  }
  // The fuse ring: pops in over 0.15 s (from twice its size), its track dark, the burnt part gold
  // from the top clockwise, a flickering spark at its head; pulsing white-gold once full. Round the
  // pointer, or clear of a finger (above it; ./gauge.ts), where the finger would hide it.
  const [gx, gy] = gaugeCentre(pointerX, pointerY, pressTouch, cam.width, cam.height, FUSE_RING + 6, chargeLabel.height + 12);
  const pop = Math.min(1, held / 0.15);
  const R = FUSE_RING * (2 - pop);
  overlay.circle(gx, gy, R).stroke({ width: 5, color: 0x03050c, alpha: 0.55 * pop });
  overlay.circle(gx, gy, R).stroke({ width: 1.5, color: 0xffe8a0, alpha: 0.35 * pop });
  const full = holds && burnt >= 1;
  const steps = Math.max(1, Math.ceil(48 * burnt));
  overlay.moveTo(gx, gy - R);
  for (let k = 1; k <= steps; k++) {
    const a = -Math.PI / 2 + (2 * Math.PI * burnt * k) / steps;
    overlay.lineTo(gx + R * Math.cos(a), gy + R * Math.sin(a));
  }
  const pulse = full ? 0.75 + 0.25 * Math.sin(performance.now() / 60) : 1;
  overlay.stroke({ width: full ? 5 : 4, color: full ? 0xffd166 : 0xffb040, alpha: pulse * pop });
  if (full) overlay.circle(gx, gy, R + 6).stroke({ width: 2, color: 0xfff6d8, alpha: 0.8 * pulse });
  if (!full) {
    const a = -Math.PI / 2 + 2 * Math.PI * burnt;
    const hx = gx + R * Math.cos(a),
      hy = gy + R * Math.sin(a);
    overlay.circle(hx, hy, 3.5).fill({ color: 0xfff6d8, alpha: pop });
    for (let k = 0; k < 3; k++) {
      const b = Math.random() * 2 * Math.PI,
        l = 4 + 5 * Math.random();
      overlay.moveTo(hx, hy).lineTo(hx + l * Math.cos(b), hy + l * Math.sin(b));
    }
    overlay.stroke({ width: 1.5, color: 0xffd27a, alpha: 0.9 * pop });
  }
  overlay.circle(pointerX, pointerY, 3).fill({ color: 0xffe8a0, alpha: 0.9 });
  // Where holding does nothing to the burst the words say so, and that the shell flies when let go (on
  // the drifting level a player holds to wait for a ghost, then lets go).
  const text = !holds ? 'no bigger burst here · let go to launch' : full ? 'biggest burst · let go' : 'hold: a bigger burst';
  if (chargeLabel.text !== text) chargeLabel.text = text;
  chargeLabel.position.set(
    Math.min(cam.width - chargeLabel.width / 2 - 4, Math.max(chargeLabel.width / 2 + 4, gx)),
    Math.max(chargeLabel.height + 2, gy - FUSE_RING - 10),
  );
  // On the finale's meeting the label under its ring says when to let go; this one would contradict it.
  chargeLabel.visible = !(lanternShow && meetLabel.visible);
}

// ---- Misses: said where the burst was ---------------------------------------------------------------

/** How long a miss is shown, s (world time). */
const MISS_SECONDS = 1.8;
/** The miss labels (made as needed, one per miss on screen). */
const missTexts: Text[] = [];

/** The combo labels (made as needed). */
const comboTexts: Text[] = [];
/** What a burst that lit `n` lanterns is called. */
function comboWord(n: number): string {
  return n >= 3 ? 'Triple!' : 'Double!';
}

/** Writes "Double!" or "Triple!" over each burst that lit two lanterns or more, growing in, rising and fading over MISS_SECONDS. */
function drawCombos(world: PhysicsWorld): void {
  const cam = renderer.camera;
  let k = 0;
  for (const c of combos) {
    const age = world.time - c.time;
    if (age < 0 || age >= MISS_SECONDS) continue;
    if (k === comboTexts.length) {
      const t = new Text({
        text: '',
        style: {
          fontFamily: 'system-ui, sans-serif',
          fontSize: 30,
          fontWeight: '800',
          fill: 0xffe08a,
          stroke: { color: 0x2a1402, width: 5 },
        },
      });
      t.anchor.set(0.5, 0.5);
      app.stage.addChild(t);
      comboTexts.push(t);
    }
    const t = comboTexts[k++]!;
    t.text = comboWord(c.lit);
    t.visible = true;
    const f = age / MISS_SECONDS;
    t.scale.set(age < 0.15 ? 0.6 + (0.4 * age) / 0.15 : 1);
    t.position.set(
      Math.min(cam.width - t.width / 2 - 4, Math.max(t.width / 2 + 4, cam.toScreenX(c.x))),
      Math.max(t.height / 2 + 2, cam.toScreenY(c.y) - 30 - 30 * f),
    );
    t.alpha = Math.min(1, (1 - f) / 0.4);
  }
  for (; k < comboTexts.length; k++) comboTexts[k]!.visible = false;
}

/** Writes "Miss" (and why) over each burst that lit nothing, rising a little and fading over MISS_SECONDS. */
function drawMisses(world: PhysicsWorld): void {
  const cam = renderer.camera;
  let k = 0;
  for (const m of misses) {
    const age = world.time - m.time;
    if (age < 0 || age >= MISS_SECONDS) continue;
    if (k === missTexts.length) {
      const t = new Text({
        text: 'Miss\nno lantern in reach',
        style: {
          fontFamily: 'system-ui, sans-serif',
          fontSize: 20,
          fontWeight: '700',
          fill: 0xffb4a8,
          align: 'center',
          stroke: { color: 0x03050c, width: 4 },
        },
      });
      t.anchor.set(0.5, 0.5);
      app.stage.addChild(t);
      missTexts.push(t);
    }
    const t = missTexts[k++]!;
    t.visible = true;
    const f = age / MISS_SECONDS;
    t.position.set(
      Math.min(cam.width - t.width / 2 - 4, Math.max(t.width / 2 + 4, cam.toScreenX(m.x))),
      Math.max(t.height / 2 + 2, cam.toScreenY(m.y) - 24 * f),
    );
    t.alpha = Math.min(1, (1 - f) / 0.4);
  }
  for (; k < missTexts.length; k++) missTexts[k]!.visible = false;
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
  // While the player has paused, the pause holds (a player studying the frozen sky, the drifting
  // lanterns, taps on it): the press launches nothing and the pause's words pulse to say how to go on
  // (P or the ▶ button); its release is not this press's, so it launches nothing either.
  if (launchHeld()) {
    pausePressedAt = performance.now();
    pausePresses++;
    return;
  }
  pointerId = event.pointerId;
  pressTouch = event.pointerType === 'touch';
  canvas.setPointerCapture(event.pointerId);
  pressedAt = performance.now();
  chargeHeard = -1;
  local(event);
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId === pointerId) local(event);
});
canvas.addEventListener('pointerup', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  local(event);
  if (launchHeld()) return;
  const hold = Math.max(0, (performance.now() - pressedAt) / 1000);
  const cam = renderer.camera;
  pauseAutoShow(show);
  // In the lantern show a second tap on a shell's spot while it still rises (its ring closing in)
  // is taken as the same tap: a player who taps again, unsure the first one took, loses no shell.
  if (lanternShow && targets.some((m) => Math.hypot(cam.toScreenX(m.x) - pointerX, cam.toScreenY(m.y) - pointerY) < SAME_SPOT_PX)) return;
  const x = cam.toWorldX(pointerX),
    y = cam.toWorldY(pointerY);
  const id = playerLaunch(x, y, hold);
  if (id !== 0) {
    // The marker sits where the shell will burst (launchShell clamps the target into the sky the same way).
    const sky = show.params.sky;
    targets.push({ id, x: Math.min(sky.width - 4, Math.max(4, x)), y: Math.min(sky.height - 3, Math.max(12, y)) });
  }
});
canvas.addEventListener('pointercancel', (event) => {
  if (event.pointerId === pointerId) pointerId = -1;
});
/** A tap this close to a rising shell's burst point, CSS px (about a fingertip), launches nothing in the lantern show. */
const SAME_SPOT_PX = 24;

// ---- The lantern show: lanterns, status row, next-level button -----------------------------------

/** The lit lanterns' light: per lantern a halo and a wider, fainter wash, added to the sky under the lantern bodies. */
const lanternGlow = new Container({ label: 'lantern-glow' });
app.stage.addChildAt(lanternGlow, app.stage.getChildIndex(overlay));
/** Halo and wash sprites of lantern i: 2i and 2i + 1 (made as levels need them). */
const glowSprites: Sprite[] = [];
/** How strong each lantern's glow was drawn in the last frame, [0, 1] (tests). */
const glowShown: number[] = [];
function glowSprite(k: number): Sprite {
  while (glowSprites.length <= k) {
    const sprite = new Sprite({ texture: glow, anchor: 0.5, blendMode: 'add', tint: 0xffb060, visible: false });
    lanternGlow.addChild(sprite);
    glowSprites.push(sprite);
  }
  return glowSprites[k]!;
}

/** Dots of the trail from a drifting lantern to its ghost (the last one is the ghost). */
const GHOST_DOTS = 8;

/** A lantern's ghost at (x, y), px, radius r px: its outline in 12 dashes and a cross at its centre, pale. */
function drawGhost(x: number, y: number, r: number): void {
  for (let a = 0; a < 24; a += 2) {
    overlay.moveTo(x + 0.8 * r * Math.cos((a * Math.PI) / 12), y + r * Math.sin((a * Math.PI) / 12));
    for (let b = 1; b <= 3; b++) {
      const u = ((a + b / 3) * Math.PI) / 12;
      overlay.lineTo(x + 0.8 * r * Math.cos(u), y + r * Math.sin(u));
    }
  }
  overlay.stroke({ width: 2, color: 0xffc07a, alpha: 0.75 });
  overlay
    .moveTo(x - 0.3 * r, y)
    .lineTo(x + 0.3 * r, y)
    .moveTo(x, y - 0.3 * r)
    .lineTo(x, y + 0.3 * r);
  overlay.stroke({ width: 1.5, color: 0xffc07a, alpha: 0.6 });
}

/**
 * Draws the level's lanterns. Unlit: dark red paper with a thin orange rim. Lit: the paper glows
 * from a white-hot core through gold to orange, with a flickering warm halo and a faint wash of light
 * on the sky around it; a just-lit lantern flares and a ring widens from it.
 */
function drawLanterns(world: PhysicsWorld): void {
  for (const sprite of glowSprites) sprite.visible = false;
  meetLabel.visible = false;
  if (!lanternShow) return;
  const cam = renderer.camera;
  const sky = show.params.sky;
  const r = cam.toScreenLength(lanternRadius(sky.width));
  const t = world.time;
  for (const [i, l] of lanternsOf(run.level, sky).entries()) {
    const [wx, wy] = lanternAt(l, sky, t - run.start);
    const x = cam.toScreenX(wx),
      y = cam.toScreenY(wy);
    // The string it hangs from.
    overlay
      .moveTo(x, y - r)
      .lineTo(x, y - 2.2 * r)
      .stroke({ width: 1, color: 0x8a6a4a, alpha: 0.6 });
    if (run.lit[i]) {
      const lit = lightings.find((g) => g.index === i);
      const flare = lit ? Math.max(0, 1 - (t - lit.time) / 0.6) : 0;
      const flicker = 0.86 + 0.08 * Math.sin(9 * t + 1.7 * i) + 0.06 * Math.sin(23 * t + i);
      // The glow comes up over GLOW_RISE (./lanterns.ts glowOf): the level shows as lit once it is full.
      const up = glowOf(run, i, t);
      glowShown[i] = up;
      const halo = glowSprite(2 * i),
        wash = glowSprite(2 * i + 1);
      halo.visible = wash.visible = true;
      halo.position.set(x, y);
      wash.position.set(x, y);
      halo.width = halo.height = r * (6 + 4 * flare);
      halo.alpha = Math.min(1, up * flicker + flare);
      wash.width = wash.height = r * 16;
      wash.alpha = up * 0.22 * flicker + 0.3 * flare;
      overlay.ellipse(x, y, 0.8 * r, r).fill({ color: 0xff8a2a });
      overlay.ellipse(x, y + 0.06 * r, 0.64 * r, 0.8 * r).fill({ color: 0xffc45a });
      overlay.ellipse(x, y + 0.12 * r, 0.38 * r, 0.5 * r).fill({ color: 0xfff2c8, alpha: 0.7 + 0.3 * flicker });
      overlay.ellipse(x, y, 0.4 * r, r).stroke({ width: 1, color: 0xd0601c, alpha: 0.35 });
    } else {
      glowShown[i] = 0;
      // The level lost: a pulsing coral ring round each lantern left dark, the ones that were missed.
      if (!Number.isNaN(lostAt)) {
        const pulse = 0.5 + 0.5 * Math.sin(5 * performance.now() * 1e-3);
        overlay.circle(x, y, (1.7 + 0.25 * pulse) * r).stroke({ width: 3, color: 0xff8a7a, alpha: 0.6 + 0.35 * pulse });
      }
      overlay
        .ellipse(x, y, 0.8 * r, r)
        .fill({ color: 0x6a2a12, alpha: 0.9 })
        .stroke({ width: 2, color: 0xff9a4a, alpha: 0.85 });
      overlay.ellipse(x, y, 0.4 * r, r).stroke({ width: 1, color: 0xb0502a, alpha: 0.5 });
    }
    // Top and bottom caps, and a tassel.
    overlay.rect(x - 0.45 * r, y - 1.08 * r, 0.9 * r, 0.16 * r).fill({ color: 0x3a2a1a });
    overlay.rect(x - 0.45 * r, y + 0.92 * r, 0.9 * r, 0.16 * r).fill({ color: 0x3a2a1a });
    overlay
      .moveTo(x, y + 1.08 * r)
      .lineTo(x, y + 1.45 * r)
      .stroke({ width: 2, color: run.lit[i] ? 0xffb040 : 0x8a3a1a });
  }
  // Where each unlit drifting lantern will be when a shell launched now bursts (FUSE later): a dotted
  // trail along its swing to a dashed ghost there, so leading it by the fuse can be seen and learnt.
  for (const [i, l] of lanternsOf(run.level, sky).entries()) {
    if (run.lit[i] || !l.drift || run.stars !== 0) continue;
    for (let k = 1; k <= GHOST_DOTS; k++) {
      const [px, py] = lanternAt(l, sky, t - run.start + (FUSE * k) / GHOST_DOTS);
      const x = cam.toScreenX(px),
        y = cam.toScreenY(py);
      if (k < GHOST_DOTS) overlay.circle(x, y, 1.6).fill({ color: 0xffc07a, alpha: 0.25 + (0.35 * k) / GHOST_DOTS });
      else drawGhost(x, y, r);
    }
  }
  drawMeeting(t, r);
  for (const g of lightings) {
    const age = t - g.time;
    if (age < 0 || age > 0.9) continue;
    const f = age / 0.9;
    overlay.circle(cam.toScreenX(g.x), cam.toScreenY(g.y), r * (1.2 + 3 * f)).stroke({ width: 3, color: 0xffe08a, alpha: 1 - f });
  }
}

/** The label over the meeting's ring: when to press, and when to let go. */
const meetLabel = new Text({
  text: '',
  style: { fontFamily: 'system-ui, sans-serif', fontSize: 15, fontWeight: '700', fill: 0xffe08a, stroke: { color: 0x03050c, width: 4 } },
});
meetLabel.anchor.set(0.5, 0);
meetLabel.visible = false;
app.stage.addChild(meetLabel);
/** The meeting cue as drawn last frame (tests): how near a shell let go now bursts to the meeting (0: no ring), the burst point, m, and the label ('' none). */
let meetShown = { release: 0, x: 0, y: 0, label: '' };
/**
 * The meeting cue's release (how near a shell let go then bursts to the meeting, 1 at the closest)
 * in the frame its label first said "let go now!" for the current press or meeting, NaN before (tests).
 */
let letGoRelease = Number.NaN;
/** World time the meeting cue was last drawn, s: the frame's step, by which the cue looks ahead. */
let meetDrawnAt = Number.NaN;
/**
 * How far ahead the meeting's "let go now!" looks, s (world time), besides a frame's step: a
 * player's reaction, so the word comes before the moment to let go, not as it passes.
 */
const MEET_REACTION = 0.25;

/**
 * When the finale's next meeting ring shows (`meetCue` non-null), world time, s, looking up to a
 * swing ahead of `t` (the level's clock) in 0.05 s steps; NaN if none (the pair is lit).
 */
function nextMeeting(t: number): number {
  if (nextMeetCache.run === run && nextMeetCache.at > t) return nextMeetCache.at;
  let at = Number.NaN;
  for (let u = t; u < t + 12; u += 0.05)
    if (meetCue(run.level, show.params.sky, u, run.lit)) {
      at = u;
      break;
    }
  nextMeetCache = { run, at };
  return at;
}
/** The last `nextMeeting` found, for the run it was found in (it holds until that time comes). */
let nextMeetCache: { run: LanternRun | null; at: number } = { run: null, at: Number.NaN };

/**
 * The finale's cue (./lanterns.ts meetCue), `t` s world time, lantern radius `r` px: from a hold and a
 * fuse before the low pair meets until it has, a gold line joins their ghosts and a pulsing ring marks
 * where to burst (over the middle of the pair and the lantern above, then), brighter as they close.
 * Before that, a faint ring where the next meeting's ring will come up, "hold here in N s" under it.
 * Under the ring "press and hold here" while a press held fully would burst as they meet ("keep
 * holding…" while pressed), then "let go now!" from MEET_REACTION and a frame's step before a shell
 * let go would burst as they meet, or as soon as the press has grown its biggest burst while a
 * shell let go then still bursts in the ring's time; while they are meeting, a line joins the
 * lanterns themselves.
 */
function drawMeeting(t: number, r: number): void {
  const cam = renderer.camera;
  const frameStep = Number.isNaN(meetDrawnAt) ? 0 : Math.min(0.5, Math.max(0, t - meetDrawnAt));
  meetDrawnAt = t;
  const lead = MEET_REACTION + frameStep;
  const meet = LEVELS[run.level]!.meet;
  const sky = show.params.sky;
  const level = t - run.start;
  const cue = run.stars === 0 ? meetCue(run.level, sky, level, run.lit) : null;
  const ahead = cue ? meetCue(run.level, sky, level + lead, run.lit) : null;
  const pressed = pointerId !== -1;
  const full = pressed && (performance.now() - pressedAt) / 1000 >= MAX_HOLD;
  const letGo = !!ahead && (ahead.release >= 0.5 || (full && ahead.release > 0));
  const label = !cue ? '' : letGo ? 'let go now!' : pressed ? 'keep holding…' : 'press and hold here';
  if (label === 'let go now!' && meetShown.label !== 'let go now!') letGoRelease = cue!.release;
  meetShown = { release: cue?.release ?? 0, x: cue?.x ?? 0, y: cue?.y ?? 0, label };
  if (!cue) {
    // The ring to come: where it will show, and in how long, so the finale's tip names something seen.
    const next = run.stars === 0 && meet && !run.lit[meet.pair[0]] && !run.lit[meet.pair[1]] ? nextMeeting(level) : Number.NaN;
    const soon = Number.isNaN(next) ? null : meetCue(run.level, sky, next, run.lit);
    meetLabel.visible = !!soon;
    if (!soon) return;
    const x = cam.toScreenX(soon.x),
      y = cam.toScreenY(soon.y);
    overlay.circle(x, y, r * 1.3).stroke({ width: 2, color: 0xffe08a, alpha: 0.35 });
    const text = `hold here in ${Math.max(1, Math.ceil(next - level))} s`;
    if (meetLabel.text !== text) meetLabel.text = text;
    meetLabel.alpha = 0.75;
    meetLabel.position.set(x, y + r * 1.6 + 4);
    meetShown.label = text;
    return;
  }
  meetLabel.visible = true;
  meetLabel.alpha = 1;
  if (meetLabel.text !== label) meetLabel.text = label;
  const gold = 0xffe08a,
    k = Math.max(cue.release, 0.4 * cue.press);
  const [ax, ay, bx, by] = cue.ghosts;
  overlay.moveTo(cam.toScreenX(ax), cam.toScreenY(ay)).lineTo(cam.toScreenX(bx), cam.toScreenY(by));
  overlay.stroke({ width: 2, color: gold, alpha: 0.25 + 0.5 * k });
  if (cue.meetingNow) {
    const ls = lanternsOf(run.level, show.params.sky);
    const meet = LEVELS[run.level]!.meet!;
    const [px, py] = lanternAt(ls[meet.pair[0]]!, show.params.sky, t - run.start),
      [qx, qy] = lanternAt(ls[meet.pair[1]]!, show.params.sky, t - run.start);
    overlay.moveTo(cam.toScreenX(px), cam.toScreenY(py)).lineTo(cam.toScreenX(qx), cam.toScreenY(qy));
    overlay.stroke({ width: 3, color: 0xffb060, alpha: 0.55 });
  }
  const pulse = 0.5 + 0.5 * Math.sin((cue.release >= 0.5 ? 14 : 7) * t);
  const x = cam.toScreenX(cue.x),
    y = cam.toScreenY(cue.y);
  overlay.circle(x, y, r * (1.3 + 0.25 * pulse)).stroke({ width: 3, color: gold, alpha: (0.45 + 0.45 * pulse) * (0.4 + 0.6 * k) });
  overlay.circle(x, y, 4).fill({ color: gold, alpha: 0.5 + 0.5 * k });
  // Under the ring: the lantern above it sits close over it in a phone's sky.
  meetLabel.position.set(x, y + r * 1.6 + 4);
}

const status = createStatusRow({ name: 'lanterns' });
const modeButton = document.createElement('button');
modeButton.type = 'button';
onButtonPress(modeButton, () => setLanternShow(!lanternShow));
status.hint.append(modeButton);
const touch = pageLayout().touch();
// A finger's target: 44 x 44 px at least on a touch screen (game-kit's row buttons are 36 px tall there).
if (touch) {
  modeButton.style.minHeight = '44px';
  modeButton.style.minWidth = '44px';
}
/** The big Next-level (or Play-again) button over the sky once a level is lit. */
const setAction = createActionButton('Next level ▶', () => nextLevel());

/** '★★☆' for `n` of 3 stars. */
function starText(n: number): string {
  return '★'.repeat(n) + '☆'.repeat(3 - n);
}

// ---- The card at a level's end: its stars (or why it was lost) and, after the finale, the show's --------

// Near opaque, so no lit lantern and its glow show through the card on a phone (as at 0.86).
const card = createResultCard(app.stage, { label: 'level-card', bigSize: 48, background: 0x060914, backgroundAlpha: 0.97 });
/** Room left under the card for the big action button at the stage's bottom, CSS px. */
const CARD_BOTTOM = 96;
/** Where the card was placed (its top, CSS px) for what it says and the screen's size (`key`). */
const cardPlaced = { key: '', top: 0 };
/** The screen boxes (px: x0, y0, x1, y1, string and tassel included) of the level's lanterns still dark (`all`: every one). */
function lanternBoxes(all: boolean): [number, number, number, number][] {
  const cam = renderer.camera;
  const sky = show.params.sky;
  const r = cam.toScreenLength(lanternRadius(sky.width));
  const out: [number, number, number, number][] = [];
  for (const [i, l] of lanternsOf(run.level, sky).entries()) {
    if (run.lit[i] && !all) continue;
    const [wx, wy] = lanternAt(l, sky, shell.world.time - run.start);
    const x = cam.toScreenX(wx),
      y = cam.toScreenY(wy);
    out.push([x - 1.6 * r, y - 2.2 * r, x + 1.6 * r, y + 1.8 * r]);
  }
  return out;
}
/** Font size of the pause's words, CSS px: small, as they sit in a band at the sky's top. */
const PAUSE_FONT = 26;
/** Font size of the pause's words on a touch screen, CSS px. */
const PAUSE_FONT_TOUCH = 20;
/** Gap between the pause's words and the sky's top edge, CSS px. */
const PAUSE_BAND_GAP = 12;
/**
 * Over the sky while the player has paused: the sky dimmed, "Paused" and how to go on (P, or the ▶
 * button on a touch screen). A tap or click on the paused sky leaves it paused and launches nothing;
 * it is answered by the words pulsing (PAUSE_PULSE_MS) and the toolbar's ▶ button lighting up.
 */
const pause = createPauseOverlay({ fontSize: touch ? PAUSE_FONT_TOUCH : PAUSE_FONT });
app.stage.addChild(pause.container);
/** How long the pause's words pulse after a press on the paused sky, ms. */
const PAUSE_PULSE_MS = 450;
/** How much larger the pause's words grow at the pulse's height (1 + this), dimensionless. */
const PAUSE_PULSE_GROWTH = 0.22;
/** performance.now() of the last press on the paused sky, ms (-Infinity: none yet). */
let pausePressedAt = Number.NEGATIVE_INFINITY;
/** Presses on the paused sky since the page loaded (tests). */
let pausePresses = 0;
/** The toolbar's pause / resume button (lit while the words pulse), or null without the page layout's toolbar. */
const pauseButton = document.querySelector<HTMLButtonElement>('button[aria-label="pause / resume (P)"]');
/** Shows the pause overlay while the player has paused (P or the pause button), on top of everything. */
function drawPause(): void {
  const cam = renderer.camera;
  pause.draw(shell.paused && playerPaused, cam.width, cam.height, touch);
  // The words in a band at the sky's top, not in its middle: a player pauses to study the drifting
  // lanterns and their ghosts, which fill the sky below (two lines of about 1.25 font sizes each;
  // the sky's foot holds the tap hint on a phone).
  const fontSize = touch ? PAUSE_FONT_TOUCH : PAUSE_FONT;
  pause.words.position.set(cam.width / 2, PAUSE_BAND_GAP + 1.25 * fontSize);
  // The pulse: the words grow and shrink back over PAUSE_PULSE_MS (half a sine), the ▶ button outlined meanwhile.
  const t = (performance.now() - pausePressedAt) / PAUSE_PULSE_MS;
  const pulsing = pause.visible && t >= 0 && t < 1;
  pause.words.scale.set(pulsing ? 1 + PAUSE_PULSE_GROWTH * Math.sin(Math.PI * t) : 1);
  if (pauseButton) pauseButton.style.outline = pulsing ? '3px solid #ffd166' : '';
  const top = app.stage.children.length - 1;
  if (pause.visible && app.stage.getChildIndex(pause.container) !== top) app.stage.setChildIndex(pause.container, top);
}

/**
 * The card over the sky when a level is shown as lit or is lost (`f`): lit, its stars, the shells it
 * took against par and what three stars take; after the finale, every level's stars and the total;
 * lost, how many lanterns lit and the level's tip.
 */
function drawCard(f: StatusFrame): void {
  if (!(lanternShow && (f.cleared || f.lost))) {
    card.hide();
    return;
  }
  const lv = LEVELS[run.level]!;
  const total = bestStars.reduce((a, b) => a + b, 0);
  let title: string, big: string, lines: string[];
  if (f.lost) {
    title = `Out of shells · ${lv.name}`;
    big = `${run.lit.filter(Boolean).length} of ${run.lit.length} lit`;
    const advice = lv.shells < run.lit.length ? 'light two at once' : 'make every shell count';
    lines = [`${plural(lv.shells, 'shell', 'shells')}, ${run.lit.length} lanterns: ${advice}`, `Tip: ${touch ? 'tap' : 'click'} ${lv.tip}`];
  } else {
    title = f.last ? 'Show complete!' : `Level ${run.level + 1} lit! · ${lv.name}`;
    big = starText(run.stars);
    lines = [`${plural(run.shells, 'shell', 'shells')} · par ${lv.par}${run.stars < 3 ? ` · 3 stars take ${lv.par}` : ' · perfect!'}`];
    if (f.last)
      lines.push(LEVELS.map((_, i) => `${i + 1} ${starText(bestStars[i]!)}`).join('  '), `Stars ${total} of ${3 * LEVELS.length}`);
  }
  const cam = renderer.camera;
  const content = { title, big, lines, edge: f.lost ? 0xff8a7a : 0xffd166 };
  const wrap = { cx: cam.width / 2, maxWidth: cam.width - 24, wrapWidth: Math.min(520, cam.width - 56) };
  // Low in the sky, just over the big button at the stage's bottom, where it covers the fewest of the
  // lanterns it is about (the lowest such place): a lost level's dark ones, so the player sees which
  // was missed, and a lit level's every one, its glow the reward (a fixed low place would cover a
  // lantern on a phone). Chosen once for what it says and the screen's size.
  const key = `${JSON.stringify(content)} ${cam.width}x${cam.height}`;
  if (key !== cardPlaced.key) {
    card.show(content, { ...wrap, bottom: cam.height - CARD_BOTTOM });
    const h = card.box.height;
    const low = card.box.y;
    let best = low;
    {
      const dark = lanternBoxes(!f.lost);
      const covered = (top: number) =>
        dark.filter(([x0, y0, x1, y1]) => x1 > card.box.x && x0 < card.box.x + card.box.width && y1 > top && y0 < top + h).length;
      // Tops from the low place up to the sky's top (8 px), 4 px apart and the top itself: the
      // lowest that covers the fewest.
      let fewest = covered(low);
      for (let top = low - 4; top >= 4 && fewest > 0; top -= 4) {
        const n = covered(Math.max(8, top));
        if (n < fewest) {
          fewest = n;
          best = Math.max(8, top);
        }
      }
    }
    cardPlaced.key = key;
    cardPlaced.top = best;
  }
  card.show(content, { ...wrap, top: cardPlaced.top });
  // Above everything in the sky, labels made after the card included.
  const top = app.stage.children.length - 1;
  if (app.stage.getChildIndex(card.container) !== top) app.stage.setChildIndex(card.container, top);
}

/** Goes on to the next level (or back to the first after the last) with a fresh sky. */
function nextLevel(): void {
  level = run.stars > 0 ? (run.level + 1) % LEVELS.length : run.level;
  // The card and its button go at once, before the new level's world is built and drawn.
  card.hide();
  setAction(false);
  actionShown = false;
  shell.reset();
}

/** Switches between the lantern show and free play (the status row's button): a fresh sky either way; free play turns the auto-show on. */
function setLanternShow(on: boolean): void {
  lanternShow = on;
  setAuto(!on);
  shell.reset();
}

/** How long after a miss the hint line says why, s (world time). */
const MISS_HINT_SECONDS = 3;
/** How long after the level was lost the row and the card say so, s (world time): the last burst fades first. */
const LOST_DELAY = 0.6;

/** The status row's lines for one frame, and what goes with them. */
interface StatusFrame {
  goal: string;
  numbers: string;
  hint: string;
  /** The level shown as lit (the banner, the Next-level button). */
  cleared: boolean;
  last: boolean;
  /** The level lost (its shells spent, a lantern still dark): the Try-again button. */
  lost: boolean;
}
/**
 * The lines computed in the last frame, and the frames drawn before it (the pacer's count). They are
 * written once that frame has been drawn: a frame the GPU was too busy for is skipped and the canvas
 * keeps the one before, and the row must not run ahead of the sky (saying "Lit 4/4" while the canvas
 * still shows the shell rising). Where every frame is drawn the row follows one frame behind.
 */
let pendingStatus: StatusFrame | null = null;
let pendingDrawn = -1;

/** The status row's lines now: the goal, the level's tally (lanterns counted lit once their glow is full), a tip or why the last burst missed. */
function statusFrame(): StatusFrame {
  const lv = LEVELS[run.level]!;
  const time = shell.world.time;
  // Shown as lit only once every glow is full (CLEAR_DELAY after the last lantern lit).
  const cleared = lanternShow && clearShown(run, time);
  const last = run.level === LEVELS.length - 1;
  const total = bestStars.reduce((a, b) => a + b, 0);
  const missed = misses.length > 0 && time - misses[misses.length - 1]!.time < MISS_HINT_SECONDS;
  // Lost once its last burst has faded a moment (LOST_DELAY), so the player sees what it did.
  const lost = lanternShow && !Number.isNaN(lostAt) && time - lostAt >= LOST_DELAY;
  const left = shellsLeft(run);
  let goal: string, numbers: string, hint: string;
  if (!lanternShow) {
    goal = 'Free play: launch fireworks anywhere';
    numbers = `${plural(show.launched, 'shell', 'shells')} launched`;
    hint = `${touch ? 'Tap' : 'Click'} the sky · hold: bigger burst`;
  } else if (cleared) {
    goal = last ? `Show complete! ${starText(run.stars)}` : `All lanterns lit! ${starText(run.stars)}`;
    numbers = `${plural(run.shells, 'shell', 'shells')} (par ${lv.par}) · Stars ${total}/${3 * LEVELS.length}`;
    // Which levels can still earn a star, so the last card never asks for stars already won.
    const short = bestStars.flatMap((stars, i) => (stars < 3 ? [i + 1] : []));
    if (!last) hint = run.stars === 3 ? 'Perfect: every lantern at par' : 'Fewer shells, more stars';
    else if (short.length === 0) hint = 'A perfect show: 3 stars on every level';
    else hint = `Play again: ${short.length === 1 ? 'level' : 'levels'} ${short.join(', ')} can still earn stars`;
  } else {
    // The shells still to launch count down in the numbers (one line on a phone); the goal says how many the level gives.
    // Every lantern lit, their glow coming up (CLEAR_DELAY before the card): the goal line says so at
    // once, with the count at n/n (the card's "All lanterns lit!" can come seconds later when frames
    // are slow).
    goal = lost
      ? `Out of shells! ${shownLit(run, time)} of ${run.lit.length} lit`
      : run.stars > 0
        ? last
          ? 'Show complete!'
          : 'All lanterns lit!'
        : `Light ${run.lit.length} lanterns with ${plural(lv.shells, 'shell', 'shells')} · ${lv.name}`;
    numbers = `Level ${run.level + 1}/${LEVELS.length} · Lit ${shownLit(run, time)}/${run.lit.length} · Shells ${left} · Par ${lv.par}`;
    hint =
      run.stars > 0
        ? `Lit with ${plural(run.shells, 'shell', 'shells')} · par ${lv.par}`
        : missed && !lost
          ? left === 1
            ? 'Missed · last shell!'
            : 'Missed · a lantern must be inside the ring'
          : `${touch ? 'Tap' : 'Click'} ${lv.tip}`;
  }
  return { goal, numbers, hint, cleared, last, lost };
}

/** Colour of the goal line once a level is lost: the lost card's edge (not the row's green, which means lit). */
const LOST_GOAL_COLOR = '#ff8a7a';

/** Writes `f` to the status row when it changed, and shows the Next-level button (with its chime) once the level is lit. */
function writeStatus(f: StatusFrame): void {
  if (f.cleared && Number.isNaN(clearShownAt)) {
    clearShownAt = shell.world.time;
    sound.chime(1320, 0.6);
  }
  const mode = lanternShow ? 'Free play' : 'Lantern show';
  if (modeButton.textContent !== mode) modeButton.textContent = mode;
  // Green (the row's done colour) only for a level lit; a lost one says so in the card's coral.
  if (status.set({ goal: f.goal, numbers: f.numbers, hint: f.hint }, f.cleared)) status.goal.style.color = f.lost ? LOST_GOAL_COLOR : '';
  drawCard(f);
  // The button comes up once a frame has drawn the card over it (on the canvas, a frame later than
  // the page's button: at a few frames a second the button stood alone under an empty sky).
  const up = card.container.visible;
  const drawn = game.pacer.drawn;
  if (!up) cardUpDrawn = -1;
  else if (cardUpDrawn < 0) cardUpDrawn = drawn;
  actionShown = up && drawn > cardUpDrawn;
  setAction(actionShown, f.lost ? 'Try again ▶' : f.last ? 'Play again ▶' : 'Next level ▶');
}
/** Whether the big action button (Next level, Try again, Play again) shows: Enter presses it then. */
let actionShown = false;
/** The count of drawn frames (game.pacer.drawn) when the level's card was put up, -1 while it is down. */
let cardUpDrawn = -1;

/**
 * Each frame: writes the lines computed in the frame before if that frame was drawn, and computes
 * this frame's (written at once when `now`: the page's start).
 */
function updateStatus(now = false): void {
  const drawn = game.pacer.drawn;
  if (freshWorld) {
    // A new world's lines at once: the last frame's were the level before's.
    freshWorld = false;
    pendingStatus = null;
    now = true;
  }
  if (pendingStatus && drawn !== pendingDrawn) writeStatus(pendingStatus);
  pendingStatus = statusFrame();
  pendingDrawn = drawn;
  if (now) writeStatus(pendingStatus);
}
updateStatus(true);

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
  /**
   * The level's result card as last drawn: whether it shows, its box on the canvas (px) and the frames
   * drawn since it went up (-1 while down).
   */
  resultCard: () => ({
    visible: card.container.visible,
    box: { ...card.box },
    drawnSince: cardUpDrawn < 0 ? -1 : game.pacer.drawn - cardUpDrawn,
  }),
  /** The screen boxes (canvas px: x0, y0, x1, y1) of the level's lanterns, lit or not. */
  lanternBoxes: () => lanternBoxes(true),
  /** Whether the pause overlay showed in the last frame (the player paused with P or the pause button). */
  pauseShown: (): boolean => pause.visible,
  /** The pause overlay's words as last drawn ('' before the first pause). */
  pauseText: (): string => pause.text,
  /** Presses on the paused sky so far (each leaves the pause and pulses its words), and the words' scale as last drawn. */
  pausePresses: (): { count: number; scale: number } => ({ count: pausePresses, scale: pause.words.scale.x }),
  /** The finale's meeting cue as drawn last frame: release (how near a shell let go now bursts to the meeting, 0 none), burst point (m), label, and the release when the label last turned to "let go now!" (NaN never). */
  meeting: () => ({ ...meetShown, letGoRelease }),
  /** The newest burst's front ring as drawn last frame: burst scale (0: none drawn), the reach it races out to and its radius now, CSS px, its age, s. */
  burstRing: () => ({ ...burstRingShown }),
  /** The lantern show: mode, level (0-based), lit lanterns, shells, stars (0 while playing), best stars per level, lantern positions (m). */
  lanterns: () => ({
    on: lanternShow,
    level: run.level,
    lit: run.lit.slice(),
    shells: run.shells,
    stars: run.stars,
    best: bestStars.slice(),
    positions: lanternsOf(run.level, show.params.sky).map((l) => lanternAt(l, show.params.sky, shell.world.time - run.start)),
    /** World time each lantern lit (NaN while unlit), the time the level was shown as lit (NaN until then), s, and each glow as drawn last. */
    litAt: run.litAt.slice(),
    clearShownAt,
    glow: glowShown.slice(0, run.lit.length),
    /** Lanterns the row counts as lit now (lit, their glow coming up or full), and the bursts that lit nothing since the level started. */
    shownLit: shownLit(run, shell.world.time),
    misses: missCount,
    /** Shells the level has left to launch, whether it is lost (its shells spent, a lantern dark) and the bursts that lit two or more. */
    shellsLeft: shellsLeft(run),
    lost: !Number.isNaN(lostAt),
    combos: combos.map((c) => c.lit),
  }),
  /**
   * The press being charged: whether a press is down, the charge sounds played for it (-1 none, 0 the
   * fuse lit, 1 to 3 each third of the longest hold) and the label over its fuse ring ('' when none).
   */
  charge: () => ({ pressed: pointerId !== -1, heard: chargeHeard, label: chargeLabel.visible ? chargeLabel.text : '' }),
  /** Starts level `i` (0-based) of the lantern show with a fresh sky. @throws RangeError on an unknown level. */
  playLevel: (i: number): void => {
    if (!(Number.isInteger(i) && i >= 0 && i < LEVELS.length))
      throw new RangeError(`playLevel: level must be an integer in [0, ${LEVELS.length - 1}], got ${i}`);
    level = i;
    if (!lanternShow) setLanternShow(true);
    else shell.reset();
  },
  /** Switches to the lantern show (true) or free play (false), with a fresh sky. */
  setLanternShow: (on: boolean): void => setLanternShow(on),
  /** Goes to the next level once this one is lit (else restarts it), as the Next-level button. */
  nextLevel: (): void => nextLevel(),
  /** The status row's text. */
  statusText: (): string => status.element.innerText,
  /** Turns the auto-show on or off. */
  setAutoShow: (on: boolean): void => setAuto(on),
});
// The running show (shells in flight, emitters, counters): a getter, so it follows resets (expose
// copies values, which would keep the first show).
Object.defineProperty(shell, 'show', { get: (): FireworksShow => show, enumerable: true });
