/**
 * Wrecking ball: a tower crane swings a 5-tonne steel ball on a chain of capsule links (ball-and-socket
 * joints) into towers, brick walls and plank stacks of 3D boxes. Steer the crane: slew the jib, run the
 * trolley in and out, raise and lower the hook; the ball lags behind and swings, so pump it like a
 * pendulum. Or grab the ball with the mouse, pull it back and let go. Every piece that falls scores
 * (more for pieces that stood high); knock down 75 % of the pieces that stood above the ground on
 * levels 1 to 3, 76 % after (`clearTarget`), within the level's swings (`swingBudget`) to clear it;
 * levels are seeded.
 *
 * Keys: A/D or ←/→ slew, W/S or ↑/↓ trolley out/in, Q/E hook up/down, L next level (once cleared),
 * G debug layer (joints, contacts), P pause, N step, R reset. Mouse: press a target and drag back
 * as with a sling, then let go: the ball swings into it along the arrow shown on the ground, harder
 * the longer the pull; its swing is drawn in 3D over the arrow, from where the ball is drawn back to
 * a red ring where it first meets a piece (drawSwingPreview), and the hint says if that is not the
 * target (while the drag is held the crane takes the hook over the target and a tagline
 * draws the ball back opposite the arrow; let go, the line slips and the ball swings down into the
 * target; one aimed at another target first re-aims that swing, one during the run is swung at
 * next); a click without a drag shows
 * the arrow from where the ball hangs, a second click swings along it (on a touch screen, with a
 * target so marked, a drag from open ground aims at it too: the finger need not cover it). A press
 * on the ground beside a target aims at it, elsewhere sends the hook there; drag the ball to pull it; right-drag orbits,
 * wheel zooms. Once the collapse that clears a level settles its result (swings, stars, score) is
 * final: later swings are for fun.
 * URL: ?level=N, ?seed=S, ?debug, ?demo (the crane swings at the level's first tower by itself: the
 * gallery's thumbnail shows a hit), ?quality=full|lite (how it is drawn; see Quality; ?shadows=0 is lite).
 */

import {
  COMPACT_MAX_HEIGHT,
  COMPACT_MAX_WIDTH,
  choiceParam,
  createActionButton,
  createButtonBar,
  createDomPauseOverlay,
  createPanel,
  flagParam,
  forEachImpact,
  getSound,
  isTouchDevice,
  numberParam,
  pageLayout,
  pauseUnderDrawers,
  seedParam,
} from '@bitphysics/game-kit';
import { isSoftwareWebGL, ORBIT_CONTROLS_RIGHT, startThreeGame } from '@bitphysics/game-kit/three';
import { contactEvents, createPhysicsWorld, isAlive, type PhysicsWorld, step as physicsStep, warmUp } from '@bitphysics/physics';
import { BodyDrag3D } from '@bitphysics/render-three';
import {
  BackSide,
  BoxGeometry,
  BufferAttribute,
  BufferGeometry,
  CanvasTexture,
  CircleGeometry,
  ConeGeometry,
  CylinderGeometry,
  DoubleSide,
  DynamicDrawUsage,
  Group,
  InstancedMesh,
  Line,
  LineBasicMaterial,
  LineSegments,
  type Material,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  PerspectiveCamera,
  Plane,
  PlaneGeometry,
  Quaternion,
  Raycaster,
  RepeatWrapping,
  RingGeometry,
  SphereGeometry,
  SRGBColorSpace,
  TorusGeometry,
  Vector2,
  Vector3,
} from 'three';
import { ScoreTally, SiteEffects } from './effects';
import { bodyHalfExtents, cheaperMaterial, dirtTexture, GroundShadows, pieceGeometry, pieceMaterials, skylineTexture } from './look';
import { missWords, type NearestPass } from './miss';
import {
  aimAt,
  BALL_RADIUS,
  BALL_TONNES,
  buildWreckingBall,
  CHAIN_LINKS,
  type ClearScore,
  clearReached,
  clearScore,
  clearScoreLine,
  clearTarget,
  dropPull,
  FULL_POWER_SHOWN,
  fallenCount,
  HANG,
  hookPosition,
  JIB_HEIGHT,
  LINK_RADIUS,
  letGoPull,
  levelTip,
  pieceOnSwing,
  powerWords,
  pullBack,
  RADIUS_RANGE,
  SHIELD_HALF,
  type SwingRequest,
  scorePieces,
  settleOver,
  starsRule,
  stillFalling,
  structureOf,
  swayAmplitude,
  swingBudget,
  swingGoal,
  swingPar,
  swingPath,
  swingSpeed,
  swingStars,
  type WreckingBallHandles,
  wreckingBallWorldOptions,
} from './scene';
import { clearRuleLine, playStatusLine } from './status';

/** Whether the page is taller than wide (a phone held upright): the camera frames a nearer view. */
const PORTRAIT = window.innerHeight > window.innerWidth;
/** Sky gradient, top to horizon: a clear day. */
const SKY = ['#2f6db5', '#5b9bd5', '#a9d0ef', '#e4f1f8'];
/** Whether the main pointer is a finger: touch wording, no key hints. */
const touch = isTouchDevice();
/** A panel label with its key (a phone has no keys: the label alone). */
const withKey = (label: string, key: string): string => (touch ? label : `${label} (${key})`);

/**
 * How the scene is drawn: 'full' (physically based materials, the sun's 1024 px shadow map) or
 * 'lite' (Lambert and Phong materials and no shadow map, the pieces' shadows flattened onto the ground: a
 * GPU as slow as software WebGL or a low-end phone's drew a frame several times faster). The page
 * starts lite on a small screen under software WebGL, else full, and steps down to lite once if the
 * first seconds are drawn slower than AUTO_LITE_FPS (see watchFrameRate). ?quality=full or lite
 * fixes it (no stepping down), as the settings panel's choice does; ?shadows=0 asks for lite.
 */
type Quality = 'full' | 'lite';
const QUALITIES: readonly Quality[] = ['full', 'lite'];
/** The quality the URL fixes, or null (the page chooses). */
const askedQuality: Quality | null = new URLSearchParams(location.search).has('quality')
  ? choiceParam('quality', QUALITIES, 'full')
  : new URLSearchParams(location.search).has('shadows') && !flagParam('shadows')
    ? 'lite'
    : null;
/** Whether the page is phone-sized (its shorter side under 600 CSS px). */
const SMALL_SCREEN = Math.min(window.innerWidth, window.innerHeight) < 600;

const params = {
  level: numberParam('level', { default: 1, min: 1, max: 20, integer: true }),
  seed: seedParam(),
  /** The ball's mass shown in the panel, t (BALL_TONNES by default: the ball's own density). */
  ballTonnes: BALL_TONNES,
  debug: flagParam('debug'),
  quality: askedQuality ?? (SMALL_SCREEN && isSoftwareWebGL() ? 'lite' : 'full'),
  /** The panel's "next level": as L, only once the level is cleared (else it says what clearing needs). */
  nextLevel: () => {
    if (cleared) nextLevel();
    else notCleared();
  },
  reset: () => game.shell.reset(),
};

let handles: WreckingBallHandles;
/** Score of the levels cleared before this one, and of this level so far. */
let banked = 0;
let levelScore = 0;
let cleared = false;
/**
 * The level's result, fixed when it is cleared: the swings it took, the stars they earned and the
 * score part by part (and
 * whether a target was tapped since: the hint says such swings are for fun). The level counts as
 * cleared once the collapse that reached its target has settled (see gameStep); nothing changes
 * its score after that.
 */
const clearedWith: { swings: number; stars: number; tapped: boolean; score: ClearScore; standing: number } = {
  swings: 0,
  stars: 0,
  tapped: false,
  /** Pieces still standing when the result was given (the banner's last line: fixed, as the result is). */
  standing: 0,
  score: clearScore(0, 0),
};
/** Smoothed step time, ms (exponential average over ~30 steps), and the worst of the last second. */
let stepMs = 0;
let worstMs = 0;
let worstAge = 0;

const COLORS = {
  tower: 0xd1495b,
  wall: 0xc8763c,
  planks: 0xe0b872,
  ball: 0xb8c2d0,
  link: 0x9aa3ad,
  mast: 0xf2b705,
  hook: 0xf2b705,
};

/** `color` (0xRRGGBB) with each channel times `f` in [0, 1]. */
function darken(color: number, f: number): number {
  return (Math.round(((color >> 16) & 255) * f) << 16) | (Math.round(((color >> 8) & 255) * f) << 8) | Math.round((color & 255) * f);
}

function createWorld(): PhysicsWorld {
  // Once a page: the physics code compiled while the page loads, not in the level's first frames.
  warmUp(3);
  const world = createPhysicsWorld(wreckingBallWorldOptions());
  // The jib starts between the structures, its ball clear of them (one hanging in front of the
  // first level's plank stack hid half of it on a phone).
  handles = buildWreckingBall(world, {
    level: params.level,
    seed: params.seed,
    ballWeight: params.ballTonnes / BALL_TONNES,
    openStart: true,
  });
  levelScore = 0;
  cleared = false;
  reachedAt = firstReachedAt = -1;
  falling = movingAt = 0;
  clearedWith.tapped = false;
  return world;
}

/** One step: the physics, then the score. */
/**
 * The swing aimed while the ball was on its run, to begin when the run is over: its piece (0: none)
 * and the request aimed (null: as a tap plans it).
 */
const next: { piece: number; request: SwingRequest | null } = { piece: 0, request: null };
function gameStep(world: PhysicsWorld): void {
  const t0 = performance.now();
  // A held ball is held firmly: it does not turn in the hand, which keeps it on its chain (holdBall).
  if (drag.body !== 0 && drag.body === handles.ball) {
    const W = world.components.AngularVelocity;
    W.x[handles.ball] = W.y[handles.ball] = W.z[handles.ball] = 0;
    holdBall(world);
  }
  physicsStep(world);
  const ms = performance.now() - t0;
  // Sound: the steel ball rings as metal; pieces knocking into each other or the ground as wood.
  forEachImpact(
    world,
    (a, b, impulse) => {
      const steel = a === handles.ball || b === handles.ball;
      sound.impact(impulse, steel ? 'metal' : 'wood', steel ? { threshold: 20, loud: 4000 } : { threshold: 5, loud: 400 });
    },
    3,
  );
  stirUp(world);
  fireNext();
  stepMs = stepMs === 0 ? ms : stepMs + (ms - stepMs) / 30;
  if (ms > worstMs || ++worstAge > 60) {
    worstMs = ms;
    worstAge = 0;
  }
  const gained = scorePieces(world, handles.pieces);
  if (gained > 0) {
    if (!cleared) levelScore += gained;
    if (reachedAt >= 0) reachedAt = world.time;
  }
  falling = stillFalling(world, handles.pieces);
  if (falling > 0) movingAt = world.time;
  const target = clearTarget(handles.pieces, handles.level);
  if (!cleared && reachedAt < 0 && clearReached(fallenCount(handles.pieces), target, pulling())) {
    reachedAt = firstReachedAt = world.time;
    reachedWith = swingsUsed();
  }
  // The result is given (and fixed) once the collapse that cleared the level has settled (./scene
  // settleOver: nothing fell for a second and nothing still moves) or the next swing is let go: given
  // when the count was reached, the end card covered the collapse still going on.
  if (
    !cleared &&
    reachedAt >= 0 &&
    (settleOver(world.time - reachedAt, world.time - movingAt, world.time - firstReachedAt) || swingsUsed() > reachedWith)
  ) {
    cleared = true;
    clearedWith.swings = reachedWith;
    clearedWith.stars = swingStars(clearedWith.swings, true, handles.level);
    clearedWith.standing = handles.pieces.length - fallenCount(handles.pieces);
    sound.chime(1046, 0.6);
    // The clear bonus and one for each star (fewer swings), said part by part in the banner.
    clearedWith.score = clearScore(levelScore, clearedWith.stars);
    levelScore = clearedWith.score.total;
  }
}
/** Whether a drag's tagline holds the ball, or has slipped and its swing's run has not yet begun (is not yet counted). */
function pulling(): boolean {
  const k = handles.controls;
  return k.pull !== null || (k.moves[0]?.release === true && k.moves[0].elapsed === 0);
}
/** World time the clear target was reached or a piece last fell after it (-1: not reached), and the swings used then. */
let reachedAt = -1;
let reachedWith = 0;
/** World time the clear target was first reached (the settling's start). */
let firstReachedAt = -1;
/** Pieces still falling at the last step (./scene stillFalling), and the world time one last was. */
let falling = 0;
let movingAt = 0;

const sound = getSound();

/** Most impacts a step that raise dust (a collapse makes hundreds of contacts). */
const BURSTS_PER_STEP = 4;
/**
 * What the last step's impacts throw up where the bodies met (the 3D contact begin events): dust
 * and chips of the piece where the ball strikes it, dust where a piece lands on the ground, chips
 * where pieces knock together hard. As many as the approach speed is fast.
 */
function stirUp(world: PhysicsWorld): void {
  const ev = contactEvents(world).begin;
  let made = 0;
  for (let i = 0; i < ev.count && made < BURSTS_PER_STEP; i++) {
    const a = ev.bodyA[i]!,
      b = ev.bodyB[i]!,
      v = ev.approachSpeed[i]!;
    if (v < 1.5) continue;
    const ball = a === handles.ball || b === handles.ball;
    const other = a === handles.ball ? b : a;
    const piece = handles.pieces.find((p) => p.body === other) ?? handles.pieces.find((p) => p.body === b);
    const x = ev.px[i]!,
      y = ev.py[i]!,
      z = ev.pz[i]!;
    if (ball && piece)
      effects.burst(x, y, z, Math.min(8, Math.round(2 + v)), 1 + 0.4 * v, 0xd8c8aa, Math.min(10, Math.round(2 * v)), COLORS[piece.kind]);
    else if ((a === 0 || b === 0) && piece) effects.burst(x, Math.max(0.1, y), z, Math.min(6, Math.round(1 + v)), 0.8 + 0.3 * v);
    else if (piece && v > 3) effects.burst(x, y, z, 1, 1, 0xd8c8aa, 3, COLORS[piece.kind]);
    else continue;
    made++;
  }
}

const game = await startThreeGame({
  title: 'Wrecking ball',
  createWorld,
  step: gameStep,
  bodies: () => handles.pieces.length,
  // The one move a level needs first (the scene's hint says it too), then the crane's own controls.
  controls: [
    { keys: 'Drag a target', action: 'aim back, let go to swing', touch: 'Drag a target' },
    { keys: 'A D / ← →', action: 'turn the crane', touch: '⟲ ⟳' },
    { keys: 'W S / ↑ ↓', action: 'hook out / in', touch: 'Out / In' },
    { keys: 'Space', action: 'hold to stop the ball swinging', touch: 'Steady' },
    { keys: 'Q E', action: 'ball up / down', touch: 'Up / Down' },
    { keys: 'Click ground', action: 'send the hook there' },
    { keys: 'Drag ball', action: 'pull the ball, release to swing' },
    { keys: 'L', action: 'next level (once cleared)', touch: 'Next level' },
    ...ORBIT_CONTROLS_RIGHT,
    // G (the debug layer: joints and contacts) is named in the settings panel, at its checkbox.
  ],
  keys: [
    {
      key: 'l',
      label: 'next level',
      action: () => {
        if (cleared) nextLevel();
        else notCleared();
      },
    },
    { key: 'g', label: 'debug', action: () => setDebug(!params.debug) },
  ],
  app: { controls: { leftButton: 'none', minDistance: 4, maxDistance: 60, target: [0, 2, 0] }, cameraPosition: [16, 12, 18] },
  renderer: {
    boundary: 'none',
    // Wide enough that its edges stay out of the steeper phone view.
    planeSize: 90,
    // Grass around the site (the site's packed dirt is its own textured square, see `site`).
    floorColor: 0x6f9a4a,
    debug: params.debug ? debugOptions() : false,
    initialInstances: 128,
    // A 1024 px shadow map over the 26 m site: 2.5 cm a texel, finer than a pixel of the view on a
    // desktop or a phone, at a quarter of the fill of the default 2048 in the shadow pass (which in
    // software WebGL is a large share of the frame's GPU time).
    lights: { shadowMapSize: 1024 },
    shadowBounds: { min: [-13, 0, -13], max: [13, 12, 13] },
  },
  // The camera frames the level's pieces (frameSite, below).
  view: null,
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;
// The kit's card of touch gestures sits over the bottom of a phone's stage for its first seconds,
// where it covered the nearest structure (level 1's plank stack): the hint over the scene's top says
// the one move a level needs first, and the crane's buttons carry captions, so it goes at once.
document.querySelector('[data-hud="touch-hint"]')?.remove();
// A drawer (menu or settings) pauses the swing and the falling tower while it is open.
pauseUnderDrawers(shell);
/** Dust, chips and popups of the hits. */
const effects = new SiteEffects(app.scene, PORTRAIT ? 1.6 : 1);
/** Pieces whose fall has been counted for a popup, by body handle. */
const popped = new Set<number>();
/** The falls being summed into popups: one popup for pieces that fell together. */
const tally = new ScoreTally();
// The site: a square of packed dirt around the crane (the grass beyond is the renderer's floor).
const site = new Mesh(new PlaneGeometry(30, 30), new MeshStandardMaterial({ map: dirtTexture(7), roughness: 0.95 }));
site.rotation.x = -Math.PI / 2;
site.position.y = 0.005;
site.receiveShadow = true;
app.scene.add(site);
// The run-state line under the step count ('paused' or empty) keeps its line's height while empty,
// so pausing does not push the left column down and shrink the site plan at its foot.
const runState = document.querySelector<HTMLElement>('[data-hud="status"]');
if (runState) runState.style.minHeight = '1lh';
app.scene.background = skyTexture();

/**
 * The sky: a vertical gradient from deep blue overhead to a hazy dusk at the horizon, drawn once
 * into a small canvas (SKY colours, top to bottom). Dark enough at the top for the HUD's light text.
 */
function skyTexture(): CanvasTexture {
  const canvas = document.createElement('canvas');
  canvas.width = 2;
  canvas.height = 256;
  const g = canvas.getContext('2d')!;
  const grad = g.createLinearGradient(0, 0, 0, 256);
  for (const [i, c] of SKY.entries()) grad.addColorStop(i / (SKY.length - 1), c);
  g.fillStyle = grad;
  g.fillRect(0, 0, 2, 256);
  const texture = new CanvasTexture(canvas);
  texture.colorSpace = SRGBColorSpace;
  return texture;
}

function debugOptions() {
  return { axes: false, velocities: false, contacts: true, joints: true, normalLength: 0.3 };
}

function setDebug(on: boolean): void {
  params.debug = on;
  renderer.setDebug(on ? debugOptions() : false);
  showStats(on);
  panel.refresh();
}

/** The drawn chain's unit cylinder (see drawChain), also the links' own, hidden, shape. */
const chainGeometry = new CylinderGeometry(1, 1, 1, 10);

/** The pieces' textured materials (brick, plank, painted crate) and the ball's steel. */
const materials = pieceMaterials();
const ballMaterial = new MeshStandardMaterial({ color: 0xa3abb5, metalness: 0.15, roughness: 0.4 });
const ballGeometry = new SphereGeometry(1, 32, 20);
/** The cheaper stand-ins of the physically based materials, made when first drawn lite (see Quality). */
const cheaper = new Map<MeshStandardMaterial, Material>();
/** Material `m` as the quality draws it: itself when full, its cheaper stand-in (look.ts cheaperMaterial) when lite. */
function asDrawn(m: MeshStandardMaterial): Material {
  if (params.quality === 'full') return m;
  let c = cheaper.get(m);
  if (!c) {
    c = cheaperMaterial(m);
    cheaper.set(m, c);
  }
  return c;
}
/**
 * Instance tints: a piece as painted, standing or fallen (the sun on its turned faces shades a fallen
 * one; a grey tint is read as sRGB and made linear, so even a light grey such as 0x8c8c8c would draw
 * it at a quarter of its brightness, near black), the target of a swing lit.
 */
const PIECE_TINT = 0xffffff,
  LIT_TINT = 0xffe08a;
/** Each piece's half extents along its body's axes (for its box geometry), by body handle. */
const bodyHalf = new Map<number, [number, number, number]>();
/** Draws piece `body` in its textured material with tint `color` (0xRRGGBB). */
function tint(body: number, color: number): void {
  const p = handles.pieces.find((q) => q.body === body);
  const half = bodyHalf.get(body);
  if (!p || !half || !isAlive(shell.world, body)) return;
  renderer.setShape(body, { geometry: pieceGeometry(half), material: asDrawn(materials[p.kind]), scale: 1, color });
}

/** Dresses every body of the level (after each reset): textured pieces, a steel ball, the crane's parts. */
function dress(): void {
  const h = handles;
  const O = shell.world.components.Orientation;
  bodyHalf.clear();
  for (const p of h.pieces) {
    const e = p.body;
    const x = O.x[e]!,
      y = O.y[e]!,
      z = O.z[e]!,
      w = O.w[e]!;
    // Column i of the body's rotation matrix: body axis i in the world.
    const axis = (i: number): [number, number, number] =>
      i === 0
        ? [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)]
        : i === 1
          ? [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)]
          : [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)];
    bodyHalf.set(e, bodyHalfExtents(p.half, p.yaw, axis));
    tint(e, PIECE_TINT);
  }
  renderer.setShape(h.ball, { geometry: ballGeometry, material: asDrawn(ballMaterial), scale: 'radius' });
  effects.clear();
  popped.clear();
  tally.clear();
  // The capsule links are drawn by the chain rod (drawChain), not one by one, and the mast's box as
  // a lattice (mastLattice below): both given an empty geometry, which three.js does not draw (as
  // shrunk boxes they cost two draw calls and two more in the shadow pass).
  for (const l of h.links) renderer.setShape(l, { geometry: noGeometry, material: noMaterial, scale: 1 });
  renderer.setShape(h.mast, { geometry: noGeometry, material: noMaterial, scale: 1 });
  renderer.setShape(h.trolley, { geometry: hookGeometry, scale: [0.6, 0.35, 0.6], color: COLORS.hook });
  for (const s of h.shields) renderer.setShape(s, { geometry: shieldGeometry, material: asDrawn(shieldMaterial), scale: 1 });
}
/** A concrete shield (./scene SHIELD_HALF): a plain grey slab, unlike every piece, so it reads as what is not to be knocked down. */
const shieldGeometry = new BoxGeometry(2 * SHIELD_HALF[0], 2 * SHIELD_HALF[1], 2 * SHIELD_HALF[2]);
const shieldMaterial = new MeshStandardMaterial({ color: 0x9c9a94, roughness: 0.95 });
const hookGeometry = new BoxGeometry(1, 1, 1);
/** A geometry with no vertices, for bodies drawn by something else (see dress). */
const noGeometry = new BufferGeometry();
noGeometry.setAttribute('position', new BufferAttribute(new Float32Array(0), 3));
/** Their material (never drawn: there is nothing to draw). */
const noMaterial = new MeshBasicMaterial();
dress();

/** The level the camera was last framed for (a reset of the same level keeps the player's view). */
let framedLevel = 0;
/** The canvas size (CSS px) the site was last framed for, while the player has not moved the camera (null after). */
let framedSize: [number, number] | null = null;
/**
 * The screen a framing may fill, in normalised device coordinates: x from -FRAME_X to FRAME_X, y
 * from FRAME_BOTTOM to FRAME_TOP (the hint over the scene's top keeps the pieces from it).
 */
const FRAME_X = touch && PORTRAIT ? 0.86 : 0.94,
  FRAME_BOTTOM = -0.92,
  FRAME_TOP = PORTRAIT ? 0.78 : 0.84;
/** Elevations, rad, of the views `frameSite` tries (from 15 to 35 degrees over the ground). */
const FRAME_ELEVATIONS = [15, 20, 25, 30, 35].map((d) => (d * Math.PI) / 180);
/**
 * Whether a camera at `p` (m) keeps the jib out of its view of the site: under the jib, or beyond its
 * reach (from above it and near, the jib crossed the view of the site as it slewed).
 */
function clearOfJib(p: Vector3): boolean {
  return p.y < JIB_HEIGHT - 2 || Math.hypot(p.x, p.z) > RADIUS_RANGE[1] + 6;
}
/**
 * Frames the site and the crane: the camera looks at the level's pieces, the mast (footing and top),
 * the hook and the ball from as near as keeps them all inside the screen's FRAME_ bounds
 * (fitPoints: the pieces' own corners, not a box round the site, whose empty corners nearest the
 * camera would take a third of a phone's width and leave bare ground in front), at the tilt of
 * FRAME_ELEVATIONS that draws them largest (of those within 4 % of it, the steepest: the band of
 * pieces the tallest), from a camera the jib does not cross (clearOfJib). A wide screen looks from
 * the side, turned about the vertical so no standing piece is behind the mast (clearOfMast); a tall
 * one from whichever side (every 15 degrees) draws them largest, seeing the jib from its side.
 * Framed again when the canvas changes size by a tenth or more, until the player moves the camera:
 * from the same side (see frameDirection).
 */
function frameSite(): void {
  framedLevel = handles.level;
  framePoints = sitePoints();
  rehomedAt.fill(1e9);
  frameDirection = null;
  frameAgain();
}
/**
 * The side the level is seen from (a unit vector toward the camera) and whether the canvas was
 * taller than wide when it was chosen; null until `frameAgain` chooses it for a new level. A new
 * canvas size keeps it and only brings the camera in or out: the side depends on where the jib
 * points, so choosing it again when a phone's address bar showed or hid during a swing (the canvas
 * 100 px shorter) turned the view 120 degrees round the site and back.
 */
let frameDirection: { dir: Vector3; tall: boolean } | null = null;
/** The points `frameSite` framed (the level as it stood when framed), for a new canvas size. */
let framePoints: Vector3[] = [];
/** Where the ball lay when the site was last framed again for it (once for each place it comes to rest; see rehome). */
const rehomedAt = [1e9, 1e9, 1e9];
/** The points to frame, m: the corners of each piece's box, of the mast's footing and top, of the hook and the ball. */
function sitePoints(): Vector3[] {
  const P = shell.world.components.Position,
    O = shell.world.components.Orientation;
  const pts: Vector3[] = [];
  const box = (cx: number, cy: number, cz: number, ex: number, ey: number, ez: number): void => {
    for (let c = 0; c < 8; c++) pts.push(new Vector3(cx + (c & 1 ? ex : -ex), cy + (c & 2 ? ey : -ey), cz + (c & 4 ? ez : -ez)));
  };
  for (const p of handles.pieces) {
    const x = O.x[p.body]!,
      y = O.y[p.body]!,
      z = O.z[p.body]!,
      w = O.w[p.body]!;
    // The box's half extents across the world's axes: |R| times its own.
    const R = [
      [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
      [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
      [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ];
    const e = R.map((row) => Math.abs(row[0]!) * p.half[0] + Math.abs(row[1]!) * p.half[1] + Math.abs(row[2]!) * p.half[2]);
    box(P.x[p.body]!, P.y[p.body]!, P.z[p.body]!, e[0]!, e[1]!, e[2]!);
  }
  // The crane: its footing, the top of its mast, the hook and the ball.
  box(0, 0.15, 0, 1.2, 0.15, 1.2);
  box(0, JIB_HEIGHT, 0, 0.4, 0.4, 0.4);
  const [hx, hy, hz] = hookPosition(handles.crane);
  box(hx, hy, hz, 0.3, 0.3, 0.3);
  box(P.x[handles.ball]!, P.y[handles.ball]!, P.z[handles.ball]!, BALL_RADIUS, BALL_RADIUS, BALL_RADIUS);
  return pts;
}
/** Frames `framePoints` for the canvas as it is now (see frameSite). */
function frameAgain(): void {
  const pts = framePoints;
  const tall = app.camera.aspect < 1;
  // The level's side already chosen (and the screen not turned between tall and wide): the same side.
  if (frameDirection !== null && frameDirection.tall === tall) {
    applyView(fitPoints(pts, frameDirection.dir));
    return;
  }
  // A wide screen: the side view, turned clear of the mast. A phone: every 15 degrees round that the
  // mast does not hide a piece from.
  const ways: [number, number][] = [];
  // The jib seen from its side, within 40 degrees of square to it (pointing at the camera it would
  // cross the site; pointing away, it and the ball would hide behind the mast).
  const jibX = Math.cos(handles.crane.angle),
    jibZ = -Math.sin(handles.crane.angle);
  if (tall) {
    for (let i = 0; i < 24; i++) {
      const a = (i * Math.PI) / 12;
      const x = Math.sin(a),
        z = Math.cos(a);
      if (!mastHides(x, z) && Math.abs(x * jibX + z * jibZ) < Math.cos((50 * Math.PI) / 180)) ways.push([x, z]);
    }
  }
  if (ways.length === 0) {
    const [x, , z] = clearOfMast(tall ? [0, 0, 1] : [0.85, 0, 1]);
    ways.push([x, z]);
  }
  let best: FittedView | null = null;
  const fits: FittedView[] = [];
  for (const [dx, dz] of ways) {
    for (const elevation of FRAME_ELEVATIONS) {
      const h = Math.hypot(dx, dz);
      const dir = new Vector3((dx / h) * Math.cos(elevation), Math.sin(elevation), (dz / h) * Math.cos(elevation));
      const fit = fitPoints(pts, dir);
      fit.elevation = elevation;
      if (!clearOfJib(fit.position)) continue;
      fits.push(fit);
      if (best === null || fit.distance < best.distance) best = fit;
    }
  }
  if (best === null) return;
  // Of the views within 4 % of the nearest, the steepest (the site's band of pieces the tallest).
  for (const f of fits) if (f.distance < 1.04 * best.distance && f.elevation > best.elevation) best = f;
  frameDirection = { dir: best.position.clone().sub(best.lookAt).normalize(), tall };
  applyView(best);
}
/** A camera placement `fitPoints` found: its position, the point it looks at, its distance from it (m), the view's elevation (rad). */
interface FittedView {
  position: Vector3;
  lookAt: Vector3;
  distance: number;
  elevation: number;
}
const fitCamera = new PerspectiveCamera();
const fitAt = new Vector3(),
  fitRight = new Vector3(),
  fitUp = new Vector3();
/**
 * The camera placement looking along -`dir` (a unit vector toward the camera) from which the points
 * `pts` (m) fill the screen's FRAME_ bounds as nearly as they can: each round projects them,
 * moves the look-at point across the view by the offset of their drawn bounds' middle from the
 * bounds' middle, and the camera in or out by how much more or less than the bounds they fill;
 * a point nearer the camera grows faster than the rest as it comes in, so the steps are damped
 * and repeated (40 rounds at most; they settle to a part in a thousand within about 20).
 */
function fitPoints(pts: readonly Vector3[], dir: Vector3): FittedView {
  fitCamera.fov = app.camera.fov;
  fitCamera.aspect = app.camera.aspect;
  fitCamera.near = 0.1;
  fitCamera.far = 1000;
  fitCamera.updateProjectionMatrix();
  const tanV = Math.tan((fitCamera.fov * Math.PI) / 360),
    tanH = tanV * fitCamera.aspect;
  const c = new Vector3();
  for (const p of pts) c.add(p);
  c.divideScalar(pts.length);
  let d = 60;
  const midY = (FRAME_TOP + FRAME_BOTTOM) / 2,
    halfY = (FRAME_TOP - FRAME_BOTTOM) / 2;
  for (let round = 0; round < 40; round++) {
    fitCamera.position.copy(c).addScaledVector(dir, d);
    fitCamera.lookAt(c);
    fitCamera.updateMatrixWorld();
    let x0 = Number.POSITIVE_INFINITY,
      x1 = Number.NEGATIVE_INFINITY,
      y0 = Number.POSITIVE_INFINITY,
      y1 = Number.NEGATIVE_INFINITY;
    for (const p of pts) {
      fitAt.copy(p).project(fitCamera);
      x0 = Math.min(x0, fitAt.x);
      x1 = Math.max(x1, fitAt.x);
      y0 = Math.min(y0, fitAt.y);
      y1 = Math.max(y1, fitAt.y);
    }
    const mx = (x0 + x1) / 2,
      my = (y0 + y1) / 2 - midY;
    const fill = Math.max((x1 - x0) / 2 / FRAME_X, (y1 - y0) / 2 / halfY);
    fitRight.setFromMatrixColumn(fitCamera.matrixWorld, 0);
    fitUp.setFromMatrixColumn(fitCamera.matrixWorld, 1);
    c.addScaledVector(fitRight, 0.8 * mx * d * tanH).addScaledVector(fitUp, 0.8 * my * d * tanV);
    d *= fill ** 0.7;
    if (Math.abs(mx) < 1e-3 && Math.abs(my) < 1e-3 && Math.abs(fill - 1) < 1e-3) break;
  }
  return { position: fitCamera.position.clone(), lookAt: c.clone(), distance: d, elevation: 0 };
}
/**
 * Puts the camera at `view`, looking where it looks; the orbit target where that line of sight
 * passes nearest the mast (a right-drag turns the view about the site's middle), no lower than 1 m.
 */
function applyView(view: FittedView): void {
  const cam = app.camera;
  cam.position.copy(view.position);
  const target = orbitTarget(view);
  cam.near = Math.max(0.05, view.distance / 200);
  cam.far = view.distance * 200;
  cam.updateProjectionMatrix();
  cam.lookAt(target);
  if (app.controls) {
    app.controls.target.copy(target);
    zoomRange(cam.position.distanceTo(target));
    app.controls.update();
  }
  framedSize = [app.canvas.clientWidth, app.canvas.clientHeight];
  home = { position: cam.position.clone(), target, direction: view.position.clone().sub(view.lookAt).normalize() };
  settleCamera();
}
/** Nearest and farthest zoom, as shares of the framing's distance from its orbit target (see zoomRange). */
const ZOOM_IN = 0.6,
  ZOOM_OUT = 2;
/**
 * A pinch's gain: the camera's distance changes by the fingers' distance ratio to this power (0.5:
 * fingers spread to twice as far apart bring the camera about 1.4 times nearer).
 */
const PINCH_GAIN = 0.5;
/**
 * Keeps the player's zoom to ZOOM_IN..ZOOM_OUT times `distance` (m, the framing's distance from its
 * orbit target), so a pinch or the wheel cannot fill the screen with the ball or shrink the site to
 * a patch; a touch screen's pinch follows the fingers' distance ratio gently (PINCH_GAIN).
 */
function zoomRange(distance: number): void {
  const c = app.controls;
  if (c === null) return;
  c.minDistance = ZOOM_IN * distance;
  c.maxDistance = Math.max(ZOOM_OUT * distance, c.minDistance * 1.01);
  if (touch) c.zoomSpeed = PINCH_GAIN;
}
/** The orbit target of camera placement `view`: where its line of sight passes nearest the mast, no lower than 1 m. */
function orbitTarget(view: FittedView): Vector3 {
  const p = view.position,
    d = view.lookAt.clone().sub(p);
  let t = -(p.x * d.x + p.z * d.z) / Math.max(1e-9, d.x * d.x + d.z * d.z);
  if (d.y < 0) t = Math.min(t, (p.y - 1) / -d.y);
  return p.clone().addScaledVector(d, Math.max(0.2, t));
}
/**
 * The site's framing the camera returns to after following the ball: camera position, orbit target
 * and the unit direction toward the camera (null once the player moves the camera).
 */
let home: { position: Vector3; target: Vector3; direction: Vector3 } | null = null;
/** The framing the camera eases toward while the site's framing is kept (see followAction): where it stands and looks. */
const cameraGoal = { position: new Vector3(), target: new Vector3() };
/** The camera's and its orbit target's velocities, m/s, in the spring (`smoothDamp`). */
const cameraVelocity = new Vector3(),
  targetVelocity = new Vector3();
/**
 * The widened framing: whether the camera is given it rather than the site's (for the rest of the
 * level once it is), the ball's places it takes in (m), when it was last widened (camera seconds, see cameraNow) and
 * how many times it widened for a piece knocked off the screen (`lostPiece`).
 */
const widen = { on: false, balls: [] as Vector3[], at: -1e9, wreckage: 0 };
// The player's own turn or zoom: the camera is theirs (no new framing on a resize, no easing back).
app.controls?.addEventListener('start', () => {
  framedSize = null;
  home = null;
});

/** How near, m, a piece's centre may pass to the line from the camera through the mast before the mast hides it. */
const MAST_SHADOW = 1.8;
/**
 * The view direction `d` (toward the camera) turned about the vertical by the least of 0, ±10°, ...,
 * ±40° that leaves no standing piece behind the mast (farther than the mast from the camera and
 * within MAST_SHADOW of the sight line through it); `d` itself when every turn hides one.
 */
function clearOfMast(d: [number, number, number]): [number, number, number] {
  // First a turn that also keeps the hanging ball clear of the mast on the screen (ballByMast), then
  // one that keeps the pieces clear alone.
  for (const withBall of [true, false])
    for (const deg of [0, 10, -10, 20, -20, 30, -30, 40, -40]) {
      const a = (deg * Math.PI) / 180;
      const x = d[0] * Math.cos(a) + d[2] * Math.sin(a),
        z = -d[0] * Math.sin(a) + d[2] * Math.cos(a);
      if (!mastHides(x, z) && !(withBall && ballByMast(x, z))) return [x, d[1], z];
    }
  return d;
}
/**
 * How near, m, the ball's centre may hang to the line from the camera through the mast before it is
 * drawn on the mast (in front of it or behind): its radius, the mast's half width and a ball's
 * radius of room between them on the screen.
 */
const BALL_BY_MAST = 2 * BALL_RADIUS + 0.41;
/** Whether the ball hangs, seen from a camera in direction (x, z) across the ground, on the mast (see BALL_BY_MAST). */
function ballByMast(x: number, z: number): boolean {
  const P = shell.world.components.Position,
    b = handles.ball;
  const h = Math.hypot(x, z);
  return Math.abs((P.x[b]! * z - P.z[b]! * x) / h) < BALL_BY_MAST;
}
/** Whether the mast hides a standing piece from a camera in direction (x, z) across the ground (see clearOfMast). */
function mastHides(x: number, z: number): boolean {
  const P = shell.world.components.Position;
  const ux = x / Math.hypot(x, z),
    uz = z / Math.hypot(x, z);
  return handles.pieces.some((p) => {
    const px = P.x[p.body]!,
      pz = P.z[p.body]!;
    return px * ux + pz * uz < 0 && Math.abs(px * uz - pz * ux) < MAST_SHADOW;
  });
}
frameSite();
// ?demo: one swing at the middle of the first tower, as a tap would.
if (flagParam('demo'))
  setTimeout(() => {
    const tower = handles.pieces.filter((p) => p.kind === 'tower');
    if (tower.length > 0) swingAt(tower[Math.floor(tower.length / 2)]!.body);
  }, 0);
shell.onWorldChange(() => {
  drag.release();
  swapDue = true;
  lastFrameTime = 0;
  dress();
  if (handles.level !== framedLevel) frameSite();
  aimed = 0;
  lit = 0;
  next.piece = 0;
  runEndedAt = -1;
  hintUntil = -1;
  notice.until = -1;
  slide.at = -1;
  swing.result = '';
  swing.pending = false;
});

/** Next level: bank the score and build the next one. */
function nextLevel(): void {
  banked += levelScore;
  params.level += 1;
  panel.refresh();
  shell.reset();
}

// ---- The crane's jib and cable (drawn only: the physics is the trolley, chain and ball) -------------

/**
 * A lattice: a square frame with one diagonal, drawn into a 64 px canvas and repeated along a box, so
 * the mast and the jib read as a crane's steel truss (see-through, alphaTest) rather than solid bars.
 */
function latticeTexture(repeatAlong: number, alongX: boolean): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = c.height = 64;
  const g = c.getContext('2d')!;
  g.strokeStyle = '#ffffff';
  g.lineWidth = 7;
  g.strokeRect(3.5, 3.5, 57, 57);
  g.beginPath();
  g.moveTo(4, 60);
  g.lineTo(60, 4);
  g.stroke();
  const t = new CanvasTexture(c);
  t.wrapS = t.wrapT = RepeatWrapping;
  t.repeat.set(alongX ? repeatAlong : 1, alongX ? 1 : repeatAlong);
  t.colorSpace = SRGBColorSpace;
  return t;
}
/**
 * The lattices' alpha test (jib, apex, mast). The texture's bars cover about a third of a panel, so
 * its smaller mipmaps average to an alpha near 0.3: at 0.5 a jib seen end-on or far off (drawn from
 * those mipmaps) lost its bars and broke up into loose dots, a see-through ghost of a jib; at 0.25
 * it is drawn whole there (a solid beam, as a far lattice looks) and the near bars are as before.
 */
const LATTICE_ALPHA_TEST = 0.25;
const JIB_LENGTH = RADIUS_RANGE[1] + 4;
/** How far the jib reaches out from the mast, m (it reaches 2 m back). */
const JIB_LENGTH_OUT = JIB_LENGTH - 2;
/**
 * How much the crane's lattice (jib and mast) glows in its own yellow: its faces turned from the sun
 * stay the mast's yellow rather than going olive, so the jib seen from below reads as the same steel
 * as the mast, one crane (unlit, the jib's underside drew dark and read as a second crane).
 */
const CRANE_GLOW = 0.45;
const jibMaterial = new MeshStandardMaterial({
  color: COLORS.mast,
  roughness: 0.6,
  metalness: 0.2,
  map: latticeTexture(JIB_LENGTH / 0.55, true),
  alphaTest: LATTICE_ALPHA_TEST,
  transparent: false,
  side: DoubleSide,
  emissive: COLORS.mast,
  emissiveIntensity: CRANE_GLOW,
});
// Alpha from the texture's own brightness: the lattice's bars opaque, the panels clear.
jibMaterial.alphaMap = jibMaterial.map;
jibMaterial.emissiveMap = jibMaterial.map;
const jib = new Mesh<BoxGeometry, Material>(new BoxGeometry(JIB_LENGTH, 0.55, 0.55), jibMaterial);
jib.castShadow = true;
// Solid whichever way it points and whatever it crosses on the screen: its lattice's open panels
// show the pieces behind it. (Drawn faded where it crossed a standing piece, it read to a stranger
// as a see-through ghost of the jib hanging over the targets.)
app.scene.add(jib);
// The counter-jib's concrete counterweight and the operator's cab at the top of the mast, turning with the jib.
const counterweight = new Mesh(new BoxGeometry(1.2, 1.1, 1.0), new MeshStandardMaterial({ color: 0x8d8f94, roughness: 0.9 }));
// Neither it nor the cab casts a shadow: 11 m up, the sun put their squares 6 m from the crane's
// foot, dark patches on the ground among the targets with nothing over them in the view.
app.scene.add(counterweight);
const cab = new Mesh(new BoxGeometry(0.9, 0.8, 0.9), new MeshStandardMaterial({ color: 0xe8eef4, roughness: 0.5, metalness: 0.1 }));
app.scene.add(cab);
// The mast drawn as a lattice over the physics' box (which the renderer draws in the same colour).
const mastLattice = new Mesh(
  new BoxGeometry(0.82, JIB_HEIGHT, 0.82),
  new MeshStandardMaterial({
    color: COLORS.mast,
    roughness: 0.6,
    metalness: 0.2,
    map: latticeTexture(JIB_HEIGHT / 0.82, false),
    alphaTest: LATTICE_ALPHA_TEST,
    side: DoubleSide,
    emissive: COLORS.mast,
    emissiveIntensity: CRANE_GLOW,
  }),
);
(mastLattice.material as MeshStandardMaterial).alphaMap = (mastLattice.material as MeshStandardMaterial).map;
(mastLattice.material as MeshStandardMaterial).emissiveMap = (mastLattice.material as MeshStandardMaterial).map;
mastLattice.position.set(0, JIB_HEIGHT / 2, 0);
mastLattice.castShadow = true;
app.scene.add(mastLattice);
/**
 * Whether the mast stands between the camera and a body at (x, y, z), m, of radius r, m: the sight
 * line from the camera to it passes within the mast's half width (0.41 m) plus r of the mast's axis
 * (x = z = 0), between the two and below the jib.
 */
function mastBetween(x: number, y: number, z: number, r: number): boolean {
  const c = app.camera.position;
  const dx = x - c.x,
    dz = z - c.z;
  const dd = dx * dx + dz * dz;
  if (dd < 1e-9) return false;
  const u = -(c.x * dx + c.z * dz) / dd;
  if (!(u > 0 && u < 1)) return false;
  const h = c.y + u * (y - c.y);
  return h > 0 && h < JIB_HEIGHT && Math.hypot(c.x + u * dx, c.z + u * dz) < 0.41 + r;
}
// While the mast stands between the camera and the ball: the ball's outline drawn over the mast (a
// pale ring in a dark edge, facing the camera), so a ball hanging or swinging behind the mast's bars
// still shows where it is and reads as behind them.
const ballOutline = new Mesh(
  new RingGeometry(0.92, 1.08, 40),
  new MeshBasicMaterial({ color: 0xf4ead2, depthTest: false, depthWrite: false, transparent: true, opacity: 0.9 }),
);
const ballOutlineEdge = new Mesh(
  new RingGeometry(0.84, 1.16, 40),
  new MeshBasicMaterial({ color: 0x14100a, depthTest: false, depthWrite: false, transparent: true, opacity: 0.6 }),
);
ballOutlineEdge.renderOrder = 8;
ballOutline.renderOrder = 9;
ballOutline.add(ballOutlineEdge);
ballOutlineEdge.position.z = -0.01;
ballOutline.visible = false;
app.scene.add(ballOutline);
/** Shows the ball's outline over the mast while the mast hides the ball drawn at `ball` (m), else hides it. */
function outlineBehindMast(ball: ArrayLike<number>): void {
  ballOutline.visible = mastBetween(ball[0]!, ball[1]!, ball[2]!, BALL_RADIUS);
  if (!ballOutline.visible) return;
  ballOutline.position.set(ball[0]!, ball[1]!, ball[2]!);
  ballOutline.quaternion.copy(app.camera.quaternion);
  ballOutline.scale.setScalar(BALL_RADIUS);
}
// A concrete pad under the mast, drawn only: 5 cm high, under the ball's lowest (its bottom 6 cm up at
// the lowest hook), so neither the ball nor a piece knocked against the mast's foot is drawn sinking
// into it (as it would into a 0.3 m slab; as a static box it would turn the low swings that pass the
// mast aside).
const footing = new Mesh(new BoxGeometry(2.4, 0.05, 2.4), new MeshStandardMaterial({ color: 0x9a9a94, roughness: 0.95 }));
footing.position.set(0, 0.025, 0);
footing.receiveShadow = true;
app.scene.add(footing);
// A city on the horizon: its skyline painted around the inside of an open cylinder standing at the
// grass's edge (one unlit, shadowless draw), so the view past the site is not an empty field.
const skylineMap = skylineTexture();
skylineMap.repeat.set(7, 1);
const skyline = new Mesh(
  new CylinderGeometry(43, 43, 7, 64, 1, true),
  new MeshBasicMaterial({ map: skylineMap, transparent: true, side: BackSide, depthWrite: false, fog: false }),
);
skyline.position.y = 3.5;
app.scene.add(skyline);
// The crane's top: an apex over the mast (a four-sided lattice pyramid turning with the jib) and the
// tie bars from its tip to the jib two thirds out and to the counter-jib's end (drawn each frame).
const APEX_HEIGHT = 2.4;
/**
 * The apex's lattice: one panel a side, three up (the cone's u runs round its 4 sides, v up it). In
 * the jib's material, 27 panels round it, its bars were a few texels wide and most fell under the
 * alpha test once drawn small: a cloud of loose yellow dots over the crane.
 */
const apexMaterial = jibMaterial.clone();
apexMaterial.map = latticeTexture(4, true);
apexMaterial.map.repeat.set(4, 3);
apexMaterial.alphaMap = apexMaterial.map;
apexMaterial.emissiveMap = apexMaterial.map;
const apex = new Mesh(new ConeGeometry(0.55, APEX_HEIGHT, 4, 1, true), apexMaterial);
apex.position.set(0, JIB_HEIGHT + 0.45 + APEX_HEIGHT / 2, 0);
apex.castShadow = true;
app.scene.add(apex);
const tiePositions = new Float32Array(12);
const tieGeometry = new BufferGeometry();
tieGeometry.setAttribute('position', new BufferAttribute(tiePositions, 3));
const ties = new LineSegments(tieGeometry, new LineBasicMaterial({ color: 0x3b3f46 }));
ties.frustumCulled = false;
app.scene.add(ties);
/** Sets the tie bars' ends for the jib's slew angle `a`, rad. */
function placeTies(a: number): void {
  const ca = Math.cos(a),
    sa = Math.sin(a);
  const top = JIB_HEIGHT + 0.45 + APEX_HEIGHT;
  const out = (2 / 3) * JIB_LENGTH_OUT;
  tiePositions.set([0, top, 0, out * ca, JIB_HEIGHT + 0.45, -out * sa, 0, top, 0, -2.6 * ca, JIB_HEIGHT + 0.2, 2.6 * sa]);
  tieGeometry.attributes.position!.needsUpdate = true;
  apex.rotation.set(0, a + Math.PI / 4, 0);
}
const cableGeometry = new BufferGeometry();
const cablePositions = new Float32Array(6);
cableGeometry.setAttribute('position', new BufferAttribute(cablePositions, 3));
const cable = new Line(cableGeometry, new LineBasicMaterial({ color: 0x20242b }));
cable.frustumCulled = false;
app.scene.add(cable);
// The chain, drawn as one: a thin dark core from the hook straight to the top of the ball (see
// drawChain), so it stays whole whatever the links' joints give (the capsule links themselves would
// be drawn apart, with gaps between them, whenever a joint stretches under the swing), threaded with
// LINKS_PER_SEGMENT oval steel rings per segment, each turned a quarter turn from the last, so it
// reads as a chain of links and not as a rod.
const chainMaterial = new MeshStandardMaterial({ color: 0x3a3f46, roughness: 0.6, metalness: 0.5 });
const LINKS_PER_SEGMENT = 2;
const ringGeometry = new TorusGeometry(1, 0.3, 6, 12);
const ringMaterial = new MeshStandardMaterial({ color: 0xb9c0c8, roughness: 0.35, metalness: 0.85 });
/**
 * The chain's rings and core segments, each one instanced mesh (two draw calls, and two in the
 * shadow pass) rather than 54 for 27 separate meshes, most of the page's draw calls. A hidden instance is
 * scaled to nothing; `segmentShown` and `ringShown` say which show (for window.game.chain).
 */
const chainRings = new InstancedMesh(ringGeometry, ringMaterial, (CHAIN_LINKS + 1) * LINKS_PER_SEGMENT);
const chainSegments = new InstancedMesh(chainGeometry, chainMaterial, CHAIN_LINKS + 1);
for (const m of [chainRings, chainSegments]) {
  m.instanceMatrix.setUsage(DynamicDrawUsage);
  m.castShadow = true;
  m.frustumCulled = false;
  app.scene.add(m);
}
const segmentShown = new Array<boolean>(CHAIN_LINKS + 1).fill(false);
const ringShown = new Array<boolean>((CHAIN_LINKS + 1) * LINKS_PER_SEGMENT).fill(false);
/** Where segment i was drawn last: its middle, turn and length, m (for window.game.chain). */
const segmentAt = Array.from({ length: CHAIN_LINKS + 1 }, () => ({ position: new Vector3(), quaternion: new Quaternion(), length: 0 }));
const hiddenMatrix = new Matrix4().makeScale(0, 0, 0);
const quarterTurn = new Quaternion().setFromAxisAngle(new Vector3(0, 1, 0), Math.PI / 2);
const chainFrom = new Vector3(),
  chainTo = new Vector3(),
  chainDir = new Vector3(),
  chainUp = new Vector3(0, 1, 0),
  ballAt = [0, 0, 0],
  ringTurn = new Quaternion(),
  ringPos = new Vector3(),
  partScale = new Vector3(),
  partMatrix = new Matrix4();
/** Places segment `i` of the drawn chain from chainFrom to chainTo (radius a link's, a little thicker). */
function placeSegment(i: number): void {
  chainDir.subVectors(chainTo, chainFrom);
  const length = chainDir.length();
  const shown = length > 1e-6;
  segmentShown[i] = shown;
  for (let j = 0; j < LINKS_PER_SEGMENT; j++) ringShown[i * LINKS_PER_SEGMENT + j] = shown;
  if (!shown) {
    chainSegments.setMatrixAt(i, hiddenMatrix);
    for (let j = 0; j < LINKS_PER_SEGMENT; j++) chainRings.setMatrixAt(i * LINKS_PER_SEGMENT + j, hiddenMatrix);
    return;
  }
  const at = segmentAt[i]!;
  at.position.addVectors(chainFrom, chainTo).multiplyScalar(0.5);
  at.quaternion.setFromUnitVectors(chainUp, chainDir.divideScalar(length));
  at.length = length;
  chainSegments.setMatrixAt(i, partMatrix.compose(at.position, at.quaternion, partScale.set(0.5 * LINK_RADIUS, length, 0.5 * LINK_RADIUS)));
  // The rings: ovals along the segment (the torus's y axis along it), long enough to overlap the next.
  const pitch = length / LINKS_PER_SEGMENT;
  partScale.set(1.6 * LINK_RADIUS, 0.62 * pitch, 1.6 * LINK_RADIUS);
  for (let j = 0; j < LINKS_PER_SEGMENT; j++) {
    const k = i * LINKS_PER_SEGMENT + j;
    ringPos.copy(chainFrom).addScaledVector(chainDir, (j + 0.5) * pitch);
    ringTurn.copy(at.quaternion);
    if (k % 2 === 1) ringTurn.multiply(quarterTurn);
    chainRings.setMatrixAt(k, partMatrix.compose(ringPos, ringTurn, partScale));
  }
}
// The tagline that draws the ball back while a drag is held (./scene pullBack): a taut orange line
// from the ball's far side down to its winch's anchor on the ground behind it, so the pull the
// player makes is seen holding the ball, and gone the moment it slips.
const taglineMaterial = new MeshBasicMaterial({ color: 0xff7a1a });
const tagline = new Mesh(chainGeometry, taglineMaterial);
tagline.visible = false;
app.scene.add(tagline);
/** How far behind the held ball across the ground the tagline's anchor is, m. */
const TAGLINE_BACK = 3;
const taglineFrom = new Vector3(),
  taglineTo = new Vector3();
/** Places the tagline while the ball is drawn back (hidden otherwise). */
function drawTagline(): void {
  const pull = handles.controls.pull;
  tagline.visible = pull !== null && pull.offset > 0;
  if (!tagline.visible || pull === null) return;
  taglineFrom.set(ballAt[0]! - BALL_RADIUS * pull.dx, ballAt[1]!, ballAt[2]! - BALL_RADIUS * pull.dz);
  taglineTo.set(ballAt[0]! - TAGLINE_BACK * pull.dx, 0, ballAt[2]! - TAGLINE_BACK * pull.dz);
  chainDir.subVectors(taglineTo, taglineFrom);
  const length = chainDir.length();
  tagline.position.addVectors(taglineFrom, taglineTo).multiplyScalar(0.5);
  tagline.quaternion.setFromUnitVectors(chainUp, chainDir.divideScalar(length));
  tagline.scale.set(0.035, length, 0.035);
}
/**
 * Draws the chain: CHAIN_LINKS + 1 equal segments on the straight line from the hook to the point of
 * the ball's surface toward it. The rope from the hook to the ball carries the 5.4 t load (see
 * ./scene buildWreckingBall), so the chain hangs taut along it; drawn through the light links'
 * centres it bent where their joints folded and its last segment ran into the ball.
 */
function drawChain(hook: ArrayLike<number>): void {
  if (!renderer.drawnPosition(handles.ball, ballAt)) return;
  const hx = hook[0]!,
    hy = hook[1]!,
    hz = hook[2]!;
  const d = Math.hypot(ballAt[0]! - hx, ballAt[1]! - hy, ballAt[2]! - hz);
  // The end on the ball's surface (the ball's top when the hook is inside it, which it never is).
  const f = d > BALL_RADIUS ? 1 - BALL_RADIUS / d : 0;
  const ex = hx + f * (ballAt[0]! - hx),
    ey = d > BALL_RADIUS ? hy + f * (ballAt[1]! - hy) : ballAt[1]! + BALL_RADIUS,
    ez = hz + f * (ballAt[2]! - hz);
  const n = handles.links.length + 1;
  chainFrom.set(hx, hy, hz);
  for (let i = 0; i < n; i++) {
    const t = (i + 1) / n;
    chainTo.set(hx + t * (ex - hx), hy + t * (ey - hy), hz + t * (ez - hz));
    placeSegment(i);
    chainFrom.copy(chainTo);
  }
  chainSegments.instanceMatrix.needsUpdate = true;
  chainRings.instanceMatrix.needsUpdate = true;
}

// The camera holds still while the ball swings inside the view, so a target a player is about to press
// stays where they saw it (a camera always easing toward the ball moved the targets under the player's
// finger). Once any of the ball would leave the screen (past the site's framing, the view frameSite chose,
// and off the screen's edge), the framing widens to take the ball in as well, seen from the framing's own side (fitPoints:
// every structure stays on the screen, and a jib turned toward the camera or away does not swing the ball
// out of view); it widens again while the ball keeps leaving it, and keeps the widened framing for the
// level (it only grows): going back to the site's framing after a swing moved every target on the
// screen while the player aimed the next one, and out again on the next swing. A ball that comes to rest
// outside the site's framing is framed with it from then on (rehome). The camera eases toward the framing
// it is given as a critically damped spring (`smoothDamp`, settling in about CAMERA_EASE s): its velocity
// never jumps, so a change of framing starts and ends gently (a camera stepped a share of the way each
// frame set off at full speed and stopped dead, which read as a jump). While a press aims a swing or drags
// the ball the camera stops. A player who turns or zooms the camera keeps it: then a ball past FOLLOW_EDGE
// of the view (in normalised device coordinates) draws the view sideways after it (toward between the ball
// and the target of the swing, or between the mast and the ball), with an eased velocity, keeping the
// player's orbit and zoom. The framing draws pieces out to FRAME_X of the view, so the ball striking one
// there is still in view: the edge lies past that.
const FOLLOW_EDGE = 0.92;
/** Time, s, in which the camera's spring closes most of the way to a new framing (its smooth time is half of it). */
const CAMERA_EASE = 0.9;
/** Shortest time, s, between two widenings of the framing (each a fitPoints). */
const WIDEN_EVERY = 0.25;
/** Rate, 1/s, at which a player's camera moves sideways after a ball past the view's edge (times the distance to go). */
const FOLLOW_RATE = 2.4;
/** Time constant, s, with which that sideways velocity eases toward what is asked. */
const FOLLOW_EASE = 0.3;
const followGoal = new Vector3(),
  followWant = new Vector3(),
  followBall = [0, 0, 0],
  followNdc = new Vector3();
/** The camera's clock (`cameraNow`), s, at its last update. */
let cameraTime = -1;
/** The camera's clock, s, and the page's and the world's times, s, at its last reading (page -1: never read). */
const cameraClock = { t: 0, page: -1, world: 0 };
/**
 * The camera's clock, s: it goes by with the world's time while the game runs, so the camera keeps
 * pace with the ball however fast the frames come (a slow machine's dropped time, a test's frames
 * run at once), and with the page's time while the game is paused (the camera still eases to a
 * framing); 0.1 s at most a reading.
 */
function cameraNow(): number {
  const page = performance.now() / 1000;
  const step = shell.paused ? page - cameraClock.page : shell.world.time - cameraClock.world;
  if (cameraClock.page >= 0) cameraClock.t += Math.min(0.1, Math.max(0, step));
  cameraClock.page = page;
  cameraClock.world = shell.world.time;
  return cameraClock.t;
}
/**
 * Moves `current` toward `goal` (m) over `dt` s as a critically damped spring with velocity
 * `velocity` (m/s, updated): smooth time CAMERA_EASE / 2 s, exact for any `dt` >= 0 (the closed
 * form's exponential taken to its third order), so the velocity is continuous whatever the frame rate.
 */
function smoothDamp(current: Vector3, goal: Vector3, velocity: Vector3, dt: number): void {
  const omega = 4 / CAMERA_EASE,
    x = omega * dt;
  const decay = 1 / (1 + x + 0.48 * x * x + 0.235 * x * x * x);
  for (const k of ['x', 'y', 'z'] as const) {
    const change = current[k] - goal[k];
    const temp = (velocity[k] + omega * change) * dt;
    velocity[k] = (velocity[k] - omega * temp) * decay;
    current[k] = goal[k] + (change + temp) * decay;
  }
}
/** Stops the camera's spring where it is: a new framing put in place at once (applyView). */
function settleCamera(): void {
  cameraVelocity.set(0, 0, 0);
  targetVelocity.set(0, 0, 0);
  widen.on = false;
  widen.balls.length = 0;
  widen.wreckage = 0;
  if (home !== null) {
    cameraGoal.position.copy(home.position);
    cameraGoal.target.copy(home.target);
  }
}
/**
 * Whether point `p` (m) is inside the framing seen from `position` looking at `target`: its FRAME_
 * bounds and a hair, or with `screen` the whole screen (normalised device coordinates within ±1).
 */
function inFraming(p: ArrayLike<number>, position: Vector3, target: Vector3, screen = false): boolean {
  fitCamera.fov = app.camera.fov;
  fitCamera.aspect = app.camera.aspect;
  fitCamera.updateProjectionMatrix();
  fitCamera.position.copy(position);
  fitCamera.lookAt(target);
  fitCamera.updateMatrixWorld();
  followNdc.set(p[0]!, p[1]!, p[2]!).project(fitCamera);
  if (screen) return Math.abs(followNdc.x) < 1 && Math.abs(followNdc.y) < 1 && followNdc.z < 1;
  return Math.abs(followNdc.x) < FRAME_X + 0.02 && followNdc.y > FRAME_BOTTOM - 0.02 && followNdc.y < FRAME_TOP + 0.02 && followNdc.z < 1;
}
const ballCorner = [0, 0, 0];
/**
 * Whether the whole ball at `b` (m; the corners of its box) is inside the framing seen from
 * `position` looking at `target`, so a ball swinging past a phone's narrow framing moves the camera
 * before any of it leaves the screen (tested at its centre, it could be half off first).
 */
function ballInFraming(b: ArrayLike<number>, position: Vector3, target: Vector3, screen = false): boolean {
  for (let c = 0; c < 8; c++) {
    ballCorner[0] = b[0]! + (c & 1 ? BALL_RADIUS : -BALL_RADIUS);
    ballCorner[1] = b[1]! + (c & 2 ? BALL_RADIUS : -BALL_RADIUS);
    ballCorner[2] = b[2]! + (c & 4 ? BALL_RADIUS : -BALL_RADIUS);
    if (!inFraming(ballCorner, position, target, screen)) return false;
  }
  return true;
}
/** The corners of a box of half size BALL_RADIUS round (x, y, z), m, added to `pts`. */
function pushBall(pts: Vector3[], x: number, y: number, z: number): void {
  for (let c = 0; c < 8; c++)
    pts.push(
      new Vector3(
        x + (c & 1 ? BALL_RADIUS : -BALL_RADIUS),
        y + (c & 2 ? BALL_RADIUS : -BALL_RADIUS),
        z + (c & 4 ? BALL_RADIUS : -BALL_RADIUS),
      ),
    );
}
/**
 * Frames the site again from the framing's own direction, the ball at `ball` (m) added to its
 * points (for the rest of the level: the framing only grows, it does not sway with the ball); the
 * camera is not moved (followAction eases it there).
 */
function rehome(ball: ArrayLike<number>): void {
  if (home === null) return;
  rehomedAt[0] = ball[0]!;
  rehomedAt[1] = ball[1]!;
  rehomedAt[2] = ball[2]!;
  pushBall(framePoints, ball[0]!, ball[1]!, ball[2]!);
  const fit = fitPoints(framePoints, home.direction);
  home = { position: fit.position, target: orbitTarget(fit), direction: home.direction };
}
/** Widens the framing the camera is given to take in the ball at `ball` (m) too (see followAction). */
function widenFor(ball: ArrayLike<number>, now: number): void {
  if (home === null) return;
  widen.at = now;
  widen.balls.push(new Vector3(ball[0]!, ball[1]!, ball[2]!));
  const pts = framePoints.slice();
  for (const b of widen.balls) pushBall(pts, b.x, b.y, b.z);
  const fit = fitPoints(pts, home.direction);
  cameraGoal.position.copy(fit.position);
  cameraGoal.target.copy(orbitTarget(fit));
  // The widened framing is inside the zoom range the player's pinch keeps to.
  const far = cameraGoal.position.distanceTo(cameraGoal.target);
  if (app.controls !== null && far > app.controls.maxDistance) app.controls.maxDistance = far * 1.05;
}
/** Farthest from the mast, m, a fallen piece may lie for the framing to widen to it (the site's ground is 30 m across). */
const SITE_REACH = 14;
/** Where the piece `lostPiece` found lies, m. */
const lostAt = [0, 0, 0];
/**
 * Whether a fallen piece lies off the screen (its centre outside the view from `position` looking at
 * `target`: the camera's, or the widened framing it eases to), within SITE_REACH of the mast: its
 * centre is put in `lostAt`.
 */
function lostPiece(position: Vector3, target: Vector3): boolean {
  const P = shell.world.components.Position;
  for (const p of handles.pieces) {
    if (!p.fallen || !isAlive(shell.world, p.body)) continue;
    lostAt[0] = P.x[p.body]!;
    lostAt[1] = P.y[p.body]!;
    lostAt[2] = P.z[p.body]!;
    if (Math.hypot(lostAt[0], lostAt[2]) < SITE_REACH && !inFraming(lostAt, position, target, true)) return true;
  }
  return false;
}
/** Eases the camera and its orbit target toward the framing of the site and the ball, or after the ball (see FOLLOW_EDGE). */
function followAction(): void {
  const controls = app.controls;
  const now = cameraNow();
  const dt = cameraTime < 0 ? 0 : now - cameraTime;
  cameraTime = now;
  if (controls === null || !renderer.drawnPosition(handles.ball, followBall)) return;
  // A press aiming a swing, or the ball in the hand: the camera stops, so what is pressed stays put.
  if (aiming.piece !== 0 || drag.body !== 0) {
    cameraVelocity.set(0, 0, 0);
    targetVelocity.set(0, 0, 0);
    return;
  }
  const c = handles.controls;
  if (home !== null) {
    // The view moves only for a ball that would leave the screen: one past the framing's margin but
    // still wholly on the screen leaves every target where the player saw it.
    let inside = ballInFraming(followBall, app.camera.position, controls.target, true);
    // Come to rest outside the framing (past a structure at its edge): framed again, from the same
    // side, with the ball where it lies (the camera eases there).
    if (
      !inside &&
      c.moves.length === 0 &&
      c.goal === null &&
      Math.hypot(followBall[0]! - rehomedAt[0]!, followBall[1]! - rehomedAt[1]!, followBall[2]! - rehomedAt[2]!) > 1 &&
      swayAmplitude(shell.world, handles) < 0.3
    ) {
      rehome(followBall);
      inside = true;
    }
    if (widen.on) {
      // The widened framing stays for the level (it only grows), so the targets hold still on the
      // screen between swings.
      if (!inside && now - widen.at > WIDEN_EVERY && !ballInFraming(followBall, cameraGoal.position, cameraGoal.target, true))
        widenFor(followBall, now);
    } else if (!inside) {
      widen.on = true;
      widenFor(followBall, now);
    }
    // A piece knocked off the screen: the framing widens to take in where it lies (the player sees
    // what the swing did; wreckage flying out of the view looked to vanish).
    if (
      now - widen.at > WIDEN_EVERY &&
      lostPiece(widen.on ? cameraGoal.position : app.camera.position, widen.on ? cameraGoal.target : controls.target)
    ) {
      widen.on = true;
      widen.wreckage++;
      widenFor(lostAt, now);
    }
    if (!widen.on) {
      cameraGoal.position.copy(home.position);
      cameraGoal.target.copy(home.target);
    }
    if (
      app.camera.position.distanceToSquared(cameraGoal.position) + controls.target.distanceToSquared(cameraGoal.target) < 1e-8 &&
      cameraVelocity.lengthSq() + targetVelocity.lengthSq() < 1e-8
    )
      return;
    smoothDamp(app.camera.position, cameraGoal.position, cameraVelocity, dt);
    smoothDamp(controls.target, cameraGoal.target, targetVelocity, dt);
    return;
  }
  // The player's own view: drawn sideways after a ball past its edge, the velocity eased.
  followNdc.set(followBall[0]!, followBall[1]!, followBall[2]!).project(app.camera);
  followWant.set(0, 0, 0);
  if (!(Math.abs(followNdc.x) < FOLLOW_EDGE && Math.abs(followNdc.y) < FOLLOW_EDGE && followNdc.z < 1)) {
    // On a swing at a target, between the ball and the target (toward the mast, a phone's narrow view
    // lost the target as the ball ran at it); else between the mast and the ball.
    if (aimed !== 0 && isAlive(shell.world, aimed)) {
      const P = shell.world.components.Position;
      followGoal.set(0.5 * (followBall[0]! + P.x[aimed]!), 2.5, 0.5 * (followBall[2]! + P.z[aimed]!));
    } else followGoal.set(0.6 * followBall[0]!, 2.5, 0.6 * followBall[2]!);
    followWant.subVectors(followGoal, controls.target).multiplyScalar(FOLLOW_RATE);
  }
  targetVelocity.lerp(followWant, 1 - Math.exp(-dt / FOLLOW_EASE));
  if (targetVelocity.lengthSq() < 1e-8) return;
  controls.target.addScaledVector(targetVelocity, dt);
  app.camera.position.addScaledVector(targetVelocity, dt);
}

// Where a click sent the hook: a ring on the ground until the hook is there.
const goalMarker = new Mesh(new RingGeometry(0.35, 0.5, 32), new MeshBasicMaterial({ color: 0xffd166, transparent: true, opacity: 0.8 }));
goalMarker.rotation.x = -Math.PI / 2;
goalMarker.visible = false;
app.scene.add(goalMarker);
// Over the piece a swing is aimed at: a bobbing arrow pointing down at it, seen from afar.
// Drawn over everything, in a dark edge, as the aim arrow on the ground (see aimMaterial): a mast
// or a taller structure in front of the target would hide it.
const aimArrow = new Mesh(
  new ConeGeometry(0.5, 1.2, 16),
  new MeshBasicMaterial({ color: 0xffd166, depthTest: false, depthWrite: false, transparent: true }),
);
const aimArrowEdge = new Mesh(
  new ConeGeometry(0.66, 1.4, 16),
  new MeshBasicMaterial({ color: 0x14100a, depthTest: false, depthWrite: false, transparent: true, opacity: 0.85 }),
);
aimArrowEdge.renderOrder = 10;
aimArrow.renderOrder = 11;
aimArrow.add(aimArrowEdge);
aimArrow.rotation.x = Math.PI;
aimArrow.visible = false;
app.scene.add(aimArrow);
// Where a re-aimed swing's target was: a ring that fades and shrinks there while the swing's marks
// slide to the new target (MARKS_SLIDE s), so a tap during a wind-up is seen to move the swing.
const oldRing = new Mesh(
  new RingGeometry(0.35, 0.5, 32),
  new MeshBasicMaterial({ color: 0xff7b5c, transparent: true, opacity: 0.8, depthWrite: false }),
);
oldRing.rotation.x = -Math.PI / 2;
oldRing.visible = false;
app.scene.add(oldRing);
/** Seconds the marks take to slide to a new target, and the old target's ring to fade. */
const MARKS_SLIDE = 0.5,
  OLD_RING_FADES = 1.5;
/** Where the marks slide from (m, across the ground) and the world time they left (-1: not sliding). */
const slide = { x: 0, z: 0, at: -1 };
/** Starts the marks' slide from the old target at (x, z), m (see oldRing). */
function dropMarks(x: number, z: number): void {
  slide.x = x;
  slide.z = z;
  slide.at = shell.world.time;
}

// ---- Depth cues: where the ball is over the ground, and where a drag's swing will go ----------------

// Under the ball, always: a dark disc on the ground with a pale rim (fainter the higher the ball),
// so its place over the site reads from any view, not only its place on the screen.
const ballMark = new Mesh(
  new CircleGeometry(1, 32),
  new MeshBasicMaterial({ color: 0x1b140c, transparent: true, opacity: 0.45, depthWrite: false }),
);
ballMark.rotation.x = -Math.PI / 2;
app.scene.add(ballMark);
const ballMarkRim = new Mesh(
  new RingGeometry(0.92, 1, 40),
  new MeshBasicMaterial({ color: 0xf4ead2, transparent: true, opacity: 0.7, depthWrite: false }),
);
ballMarkRim.rotation.x = -Math.PI / 2;
app.scene.add(ballMarkRim);
// While the ball is held: a plumb line from it down to its mark, the swing's track on the ground
// (a dashed band, from under the ball through under the hook to as far the other side; each dash
// bright where the ball passes low enough to hit a wall or a stack, faint where it passes high)
// with a ring where the ball passes lowest and fastest (under the hook), and a red ring round the
// first piece the swing will meet.
const cueMaterial = new MeshBasicMaterial({ color: 0xfff6dc, transparent: true, opacity: 0.9, depthWrite: false });
const plumb = new Mesh(new CylinderGeometry(1, 1, 1, 6), cueMaterial);
plumb.visible = false;
app.scene.add(plumb);
/** Dashes of the swing's track on the ground, and each one's share of a dash period that is drawn. */
const TRACK_DASHES = 16,
  DASH_FILL = 0.6;
/** How much thicker the cues are drawn on an upright phone, whose view of the site is about half as large. */
const CUE_SCALE = PORTRAIT ? 1.8 : 1;
/** Width of the track's dashes, m. */
const TRACK_WIDTH = 0.14 * CUE_SCALE;
/** Height of the ball's bottom, m, up to which a dash of the track is drawn at full brightness; it fades over the next 1.5 m. */
const LOW_SWING = 0.8;
const trackDashes = Array.from({ length: TRACK_DASHES }, () => {
  const m = new Mesh(new PlaneGeometry(1, 1), cueMaterial.clone());
  m.visible = false;
  app.scene.add(m);
  return m;
});
const passRing = new Mesh(new RingGeometry(0.45, 0.6, 40), new MeshBasicMaterial({ color: 0xffd166, transparent: true, opacity: 0.9 }));
passRing.rotation.x = -Math.PI / 2;
passRing.visible = false;
app.scene.add(passRing);
const meetRing = new Mesh(new RingGeometry(0.85, 1.05, 40), new MeshBasicMaterial({ color: 0xff5a4a, transparent: true, opacity: 0.9 }));
meetRing.rotation.x = -Math.PI / 2;
meetRing.visible = false;
app.scene.add(meetRing);
/** Height above the ground the cues lie at, m (over the site's dirt, under the pieces' feet). */
const CUE_Y = 0.02;
/** The piece a held ball's swing would meet first (0: none), for tests. */
let swingMeets = 0;
/** The lowest the held ball's bottom passes on its swing, m (under the hook). */
let swingLow = Number.POSITIVE_INFINITY;
/**
 * Places the depth cues for this frame (see above): the ball's mark always; while the ball is held,
 * its plumb line and its swing as a pendulum let go from rest under a still hook (./scene
 * `pieceOnSwing`): along the line from the ball through the point under the hook to as far past it.
 */
function placeCues(ball: ArrayLike<number>, hook: ArrayLike<number>): void {
  const bx = ball[0]!,
    by = ball[1]!,
    bz = ball[2]!;
  const lift = Math.max(0, by - BALL_RADIUS);
  const s = BALL_RADIUS * (0.85 + 0.05 * lift);
  ballMark.position.set(bx, CUE_Y, bz);
  ballMark.scale.setScalar(s);
  (ballMark.material as MeshBasicMaterial).opacity = 0.45 * Math.max(0.35, 1 - lift / 6);
  ballMarkRim.position.set(bx, CUE_Y + 0.002, bz);
  ballMarkRim.scale.setScalar(s);
  const held = drag.body === handles.ball && drag.body !== 0;
  plumb.visible = passRing.visible = held;
  for (const d of trackDashes) d.visible = held;
  meetRing.visible = false;
  swingMeets = 0;
  if (!held) return;
  const drop = Math.max(0.01, by - BALL_RADIUS - CUE_Y);
  plumb.position.set(bx, CUE_Y + drop / 2, bz);
  plumb.scale.set(0.025 * CUE_SCALE, drop, 0.025 * CUE_SCALE);
  const hx = hook[0]!,
    hy = hook[1]!,
    hz = hook[2]!;
  const ex = bx - hx,
    ez = bz - hz;
  // The dashes from under the ball (f = 1) to as far past the hook (f = -1), flat on the ground,
  // each as bright as the ball passes low over it (its bottom sqrt(HANG^2 - d^2) + BALL_RADIUS under the hook).
  const reach = Math.hypot(ex, ez),
    span = 2 * reach,
    heading = Math.atan2(-ez, ex);
  swingLow = Number.POSITIVE_INFINITY;
  for (let i = 0; i < TRACK_DASHES; i++) {
    const d = trackDashes[i]!;
    const f = 1 - (2 * (i + 0.5)) / TRACK_DASHES;
    d.position.set(hx + f * ex, CUE_Y + 0.003, hz + f * ez);
    d.rotation.set(-Math.PI / 2, 0, heading);
    d.scale.set(Math.max(0.01, (DASH_FILL * span) / TRACK_DASHES), TRACK_WIDTH, 1);
    const bottom = hy - Math.sqrt(Math.max(0, HANG * HANG - f * f * reach * reach)) - BALL_RADIUS;
    swingLow = Math.min(swingLow, bottom);
    (d.material as MeshBasicMaterial).opacity = 0.9 * Math.min(1, Math.max(0.35, 1 - (bottom - LOW_SWING) / 1.5));
  }
  passRing.position.set(hx, CUE_Y + 0.004, hz);
  passRing.scale.setScalar(CUE_SCALE);
  swingMeets = pieceOnSwing(shell.world, handles.pieces, ball, hook);
  if (swingMeets !== 0) {
    const P = shell.world.components.Position;
    meetRing.visible = true;
    meetRing.position.set(P.x[swingMeets]!, CUE_Y + 0.006, P.z[swingMeets]!);
    meetRing.scale.setScalar(Math.sqrt(CUE_SCALE) * (1 + 0.08 * Math.sin(shell.world.time * 8)));
  }
}

// ---- Keys held -------------------------------------------------------------------------------

const held = new Set<string>();
const DRIVE_KEYS = ['a', 'd', 'w', 's', 'q', 'e', ' ', 'arrowleft', 'arrowright', 'arrowup', 'arrowdown'];
function typing(target: EventTarget | null): boolean {
  const el = target as HTMLElement | null;
  return !!el && (el.tagName === 'INPUT' || el.tagName === 'SELECT' || el.tagName === 'TEXTAREA');
}
window.addEventListener('keydown', (event) => {
  const k = event.key.toLowerCase();
  if (!DRIVE_KEYS.includes(k) || typing(event.target) || event.ctrlKey || event.metaKey || event.altKey) return;
  held.add(k);
  handles.controls.goal = null;
  handles.controls.moves = [];
  next.piece = 0;
  aimed = 0;
  event.preventDefault();
});
window.addEventListener('keyup', (event) => held.delete(event.key.toLowerCase()));
window.addEventListener('blur', () => held.clear());

// Touch: the crane's six drives and its anti-sway as hold buttons (the same keys), and "Next level"
// once cleared. Seven buttons fit one row of a 390 px phone with narrower padding and gaps (1 px short at the kit's).
const craneBar = createButtonBar(
  [
    { label: '⟲', name: 'slew the jib left', key: 'a' },
    { label: '⟳', name: 'slew the jib right', key: 'd' },
    { label: 'Out', name: 'trolley out', key: 'w' },
    { label: 'In', name: 'trolley in', key: 's' },
    { label: 'Up', name: 'hook up', key: 'q' },
    { label: 'Down', name: 'hook down', key: 'e' },
    { label: 'Steady', name: 'steady the ball (anti-sway)', key: ' ', accent: '#3fb27f' },
  ],
  { label: 'crane' },
);
craneBar.element.style.gap = '4px';
/**
 * Under each button's symbol, what it moves in a word a player knows, so the bar explains itself once
 * the card saying how to play has gone: the crane turns, the hook runs out and in along the arm,
 * the ball goes up and down, Steady stops its swing.
 */
const CRANE_CAPTIONS = ['turn', 'turn', 'hook', 'hook', 'ball', 'ball', 'stop swing'];
craneBar.buttons.forEach((b, i) => {
  b.style.padding = '0 4px';
  b.style.minWidth = '44px';
  b.style.display = 'inline-flex';
  b.style.flexDirection = 'column';
  b.style.justifyContent = 'center';
  b.style.lineHeight = '1.05';
  const caption = document.createElement('small');
  caption.dataset.caption = '';
  caption.textContent = CRANE_CAPTIONS[i] ?? '';
  caption.style.cssText = 'font-size: 10px; font-weight: 500; opacity: 0.8;';
  b.append(caption);
});
const showNext = createActionButton('Next level ▶', () => {
  if (cleared) nextLevel();
});

function updateControls(): void {
  const c = handles.controls;
  const on = (a: string, b: string): number => (held.has(a) || held.has(b) ? 1 : 0);
  c.slew = on('a', 'arrowleft') - on('d', 'arrowright');
  c.trolley = on('w', 'arrowup') - on('s', 'arrowdown');
  c.hoist = (held.has('q') ? 1 : 0) - (held.has('e') ? 1 : 0);
  c.steady = held.has(' ');
}

// ---- Mouse: click the ground to send the hook; drag the ball ------------------------------------

const canvas = app.canvas;
// Critically damped: a held ball settles where it is pulled instead of bobbing in the hand, so it
// is let go at rest and swings along its chain's arc (bobbing, as at a damping ratio of 0.3, it could
// be let go moving up and fly off the arc, its chain slack).
const drag = new BodyDrag3D(renderer, { hertz: 2, dampingRatio: 1 });
const ndc: [number, number] = [0, 0];
const ground = new Plane(new Vector3(0, 1, 0), 0);
const raycaster = new Raycaster();
const groundHit = new Vector3();
let pressId = -1;

/**
 * A press at (ndcX, ndcY): on the ball, grabs it; on a piece of a target, begins aiming a swing at
 * it (`beginAim`; the swing goes when the press is let go, `releaseAt`); elsewhere, sends the hook
 * to the ground point under the pointer. @returns 'ball', 'aim', 'hook' or 'none'.
 */
function pressAt(ndcX: number, ndcY: number, deferHook = false): 'ball' | 'aim' | 'hook' | 'none' {
  const hit = renderer.pick(ndcX, ndcY, app.camera);
  if (hit && hit.eid === handles.ball) {
    if (outOfSwings()) return 'none';
    drag.grab(ndcX, ndcY, app.camera);
    if (drag.body !== handles.ball) return 'none';
    // The hand takes the ball from the tagline.
    handles.controls.pull = null;
    dragPlane.constant = -drag.target[1];
    const P = shell.world.components.Position;
    grabOffset[0] = drag.target[0] - P.x[handles.ball]!;
    grabOffset[1] = drag.target[1] - P.y[handles.ball]!;
    grabOffset[2] = drag.target[2] - P.z[handles.ball]!;
    const [hx, , hz] = hookPosition(handles.crane);
    dragGoal[0] = P.x[handles.ball]! - hx;
    dragGoal[1] = P.z[handles.ball]! - hz;
    handles.controls.released++;
    return 'ball';
  }
  // A standing piece under the pointer, else the standing piece whose outline is nearest (within
  // NEAR_TAP_PX), else a fallen piece under the pointer (a press on a piece lying on the ground swung
  // at it even with a standing one a pixel away).
  const piece = hit ? handles.pieces.find((p) => p.body === hit.eid) : undefined;
  let target = piece && !piece.fallen ? piece.body : nearPiece(ndcX, ndcY);
  if (target === 0 && piece) target = piece.body;
  raycaster.setFromCamera(new Vector2(ndcX, ndcY), app.camera);
  const onGround = raycaster.ray.intersectPlane(ground, groundHit) !== null;
  if (target === 0 && onGround) target = pieceNearGround(groundHit.x, groundHit.z);
  if (target !== 0) return beginAim(target, ndcX, ndcY);
  // On a touch screen, with a piece armed (tapped once): a press on open ground aims at it from
  // there, so the finger pulls back away from the piece and its arrow instead of covering them.
  if (touch && onGround && aiming.armed !== 0 && isAlive(shell.world, aiming.armed)) {
    aiming.piece = aiming.armed;
    aiming.x0 = ndcX;
    aiming.y0 = ndcY;
    aiming.dragged = false;
    aiming.remote = true;
    aiming.gx = groundHit.x;
    aiming.gz = groundHit.z;
    return 'aim';
  }
  if (!onGround) return 'none';
  if (deferHook) {
    pendingHook = [groundHit.x, groundHit.z];
    return 'hook';
  }
  sendHook(groundHit.x, groundHit.z);
  return 'hook';
}
/**
 * Where a finger's press on open ground sends the hook once it lifts (null: none): a finger may yet
 * be joined by a second one, a pinch of the camera that must leave the hook where it is.
 */
let pendingHook: [number, number] | null = null;
/** Sends the hook to the ground point (x, z), m, dropping any swing planned or saved. */
function sendHook(x: number, z: number): void {
  handles.controls.moves = [];
  handles.controls.pull = null;
  next.piece = 0;
  handles.controls.goal = [x, z];
  aimed = 0;
  hintUntil = shell.world.time + HINT_SHOWN;
}
/** Metres across the ground within which a tap beside a structure swings at it (see pieceNearGround). */
const GROUND_NEAR = 1.8;
/**
 * The standing piece to swing at for a tap on the ground at (x, z), m: of those whose centre is
 * within GROUND_NEAR across the ground, the nearest, counting each metre of height over 1 m as
 * a quarter metre more (a tap at a tower's foot takes a block low in it); 0 when none is near. A tap
 * beside a structure means it (a tap that only sent the hook there would read as a game that did not
 * answer).
 */
function pieceNearGround(x: number, z: number): number {
  const P = shell.world.components.Position;
  let best = 0,
    bestD = Number.POSITIVE_INFINITY;
  for (const p of handles.pieces) {
    if (p.fallen || !isAlive(shell.world, p.body)) continue;
    const across = Math.hypot(P.x[p.body]! - x, P.z[p.body]! - z);
    const d = across + 0.25 * Math.max(0, P.y[p.body]! - 1);
    if (across < GROUND_NEAR && d < bestD) {
      bestD = d;
      best = p.body;
    }
  }
  return best;
}
// ---- Aiming: press a target, drag back, let go ----------------------------------------------------

/**
 * The swing being aimed: the piece pressed (0: none), where the press was (NDC), whether the
 * pointer has moved past TAP_PX since (a drag), and the swing the arrow shows: the direction the ball
 * travels as it reaches the piece (rad, as ./scene SwingRequest) and the pull's power in
 * [MIN_POWER, 1]. `armed` is the piece a tap without a drag marked (a second tap on it swings as shown).
 * `remote`: the press began on open ground at (gx, gz), m, aiming at the armed piece from there
 * (touch only; see pressAt): the pull across the ground from that point sets the direction.
 */
const aiming = { piece: 0, x0: 0, y0: 0, dragged: false, direction: 0, power: 0, armed: 0, remote: false, gx: 0, gz: 0 };
/** CSS px a press must move to be a drag that aims (less is a tap). */
const TAP_PX = 10;
/** CSS px of pull for a full-power swing; the weakest counts as MIN_POWER. */
const FULL_PULL_PX = isTouchDevice() ? 110 : 160;
const MIN_POWER = 0.2;
/**
 * Power of the arrow a tap shows before any drag: full (./scene swingSpeed, FULL_SWING_SPEED, the
 * speed the levels' pars were measured with), so a tap and a second tap swing as hard as the ball
 * swings without a long wind-up.
 */
const TAP_POWER = 1;
/** Fewest CSS px of pull for a full-power swing, where the screen's edge leaves less than FULL_PULL_PX (see fullPull). */
const LEAST_FULL_PULL_PX = 24;
/** CSS px short of the screen's edge at which a pull toward it is full (a finger cannot reach the very edge). */
const EDGE_PX = 6;
/**
 * CSS px of pull for a full-power swing along the screen direction (ux, uy) (unit, y up) from the
 * press being aimed: FULL_PULL_PX, or as far as the screen's edge lets the pull go that way (less
 * EDGE_PX; at least LEAST_FULL_PULL_PX), so a target near the edge of a phone's screen can be given
 * a full swing from any side.
 */
function fullPull(ux: number, uy: number): number {
  const w = canvas.clientWidth,
    h = canvas.clientHeight;
  const sx = ((aiming.x0 + 1) / 2) * w,
    sy = ((1 - aiming.y0) / 2) * h;
  // Down the screen is -uy.
  const tx = ux > 1e-6 ? (w - sx) / ux : ux < -1e-6 ? -sx / ux : Number.POSITIVE_INFINITY;
  const ty = uy > 1e-6 ? sy / uy : uy < -1e-6 ? (h - sy) / -uy : Number.POSITIVE_INFINITY;
  return Math.min(FULL_PULL_PX, Math.max(LEAST_FULL_PULL_PX, Math.min(tx, ty) - EDGE_PX));
}
/** The swing the arrow shows now, for ./scene aimAt. */
function request(): SwingRequest {
  return { direction: aiming.direction, speed: swingSpeed(aiming.power) };
}
/**
 * Begins aiming at piece `piece` from a press at (ndcX, ndcY): the arrow shows on the ground
 * (the ball comes straight from where it hangs at TAP_POWER, or as last shown if the piece is
 * armed) and follows the drag (`aimDrag`). @returns 'aim'.
 */
function beginAim(piece: number, ndcX: number, ndcY: number): 'aim' {
  aiming.piece = piece;
  aiming.x0 = ndcX;
  aiming.y0 = ndcY;
  aiming.dragged = false;
  aiming.remote = false;
  if (aiming.armed !== piece) {
    const P = shell.world.components.Position;
    aiming.direction = Math.atan2(P.z[piece]! - P.z[handles.ball]!, P.x[piece]! - P.x[handles.ball]!);
    aiming.power = TAP_POWER;
  }
  return 'aim';
}
/**
 * The press being aimed moved to (ndcX, ndcY): once it is TAP_PX from where it began, the ball's
 * direction is from the ground point under the pointer through the piece (pull back from a block
 * as a sling: the ball flies the other way) and the power grows with the pull's length on the screen.
 */
function aimDrag(ndcX: number, ndcY: number): void {
  if (aiming.piece === 0) return;
  const px = ((ndcX - aiming.x0) * canvas.clientWidth) / 2,
    py = ((ndcY - aiming.y0) * canvas.clientHeight) / 2;
  const pull = Math.hypot(px, py);
  if (pull < TAP_PX && !aiming.dragged) return;
  aiming.dragged = true;
  raycaster.setFromCamera(new Vector2(ndcX, ndcY), app.camera);
  const P = shell.world.components.Position;
  const tx = P.x[aiming.piece]!,
    tz = P.z[aiming.piece]!;
  // The pull across the ground; over the horizon, the screen's pull turned into the ground's axes.
  // From a press on open ground (remote), the ball flies the way the finger pulled from there.
  const fromX = aiming.remote ? aiming.gx : tx,
    fromZ = aiming.remote ? aiming.gz : tz;
  if (raycaster.ray.intersectPlane(ground, groundHit) !== null && Math.hypot(groundHit.x - fromX, groundHit.z - fromZ) > 0.2)
    aiming.direction = Math.atan2(fromZ - groundHit.z, fromX - groundHit.x);
  aiming.power = Math.min(1, Math.max(MIN_POWER, pull / fullPull(px / pull, py / pull)));
  // While the drag is held the crane takes the hook over the piece and a tagline draws the ball
  // back as the arrow shows, so letting go swings it from there (./scene pullBack): the hit comes
  // about a quarter of the chain's swing after the finger lifts. Not while the ball is on its run
  // (the drag is the next swing, planned once the run is over) or the level's swings are used.
  if (!onRun() && !outOfSwings() && next.piece === 0 && drag.body === 0) pullBack(shell.world, handles, aiming.piece, request());
}
/**
 * The press being aimed let go at (ndcX, ndcY): after a drag, swings along the arrow; a tap on the
 * armed piece swings as its arrow shows; another tap arms the piece (the arrow stays and the hint
 * says to drag). @returns 'swing', 'armed' or 'none' (no press being aimed, or the swing refused).
 */
function releaseAt(ndcX: number, ndcY: number): 'swing' | 'armed' | 'none' {
  const piece = aiming.piece;
  if (piece === 0) return 'none';
  aimDrag(ndcX, ndcY);
  aiming.piece = 0;
  const remote = aiming.remote;
  aiming.remote = false;
  if (remote && !aiming.dragged) {
    // A tap on open ground with a piece armed: the hook goes there, as without one.
    aiming.armed = 0;
    sendHook(aiming.gx, aiming.gz);
    return 'none';
  }
  if (!aiming.dragged && aiming.armed !== piece) {
    aiming.armed = piece;
    light(piece);
    sound.chime(523, 0.08);
    return 'armed';
  }
  aiming.armed = 0;
  const swung = swingAt(piece, request());
  // A drag let go without a swing (refused, or kept as the next one): the tagline pays out.
  if (handles.controls.pull !== null && !handles.controls.pull.letGo) dropPull(handles);
  return swung ? 'swing' : 'none';
}
// The arrow on the ground: from where the ball comes, to the piece; longer and redder the harder.
// Drawn over everything (the mast or a structure in front of it would hide it), in a bright fill
// inside a dark edge, so it reads over brown dirt, red brick, the yellow mast and the sky alike.
const aimMaterial = new MeshBasicMaterial({ color: 0xffd166, depthTest: false, depthWrite: false, transparent: true });
const aimEdgeMaterial = new MeshBasicMaterial({ color: 0x14100a, depthTest: false, depthWrite: false, transparent: true, opacity: 0.85 });
const aimShaft = new Mesh(new BoxGeometry(1, 0.04, 0.4), aimMaterial);
const aimHead = new Mesh(new CircleGeometry(0.8, 3), aimMaterial);
/** How far the dark edge stands out round the arrow's fill, m. */
const AIM_EDGE = 0.12;
const aimShaftEdge = new Mesh(new BoxGeometry(1, 0.04, 0.4 + 2 * AIM_EDGE), aimEdgeMaterial);
// A triangle's edge AIM_EDGE wide all round: its circumradius grows by twice that.
const aimHeadEdge = new Mesh(new CircleGeometry(0.8 + 2 * AIM_EDGE, 3), aimEdgeMaterial);
aimHead.rotation.x = aimHeadEdge.rotation.x = -Math.PI / 2;
aimShaftEdge.renderOrder = aimHeadEdge.renderOrder = 10;
aimShaft.renderOrder = aimHead.renderOrder = 11;
const aimPreview = new Group();
aimPreview.add(aimShaftEdge, aimHeadEdge, aimShaft, aimHead);
aimPreview.visible = false;
app.scene.add(aimPreview);
/** Largest |x| and |y|, in normalised device coordinates, of the aim arrow's corners: inside the screen's edge. */
const ARROW_EDGE = 0.94;
/** Shortest the aim arrow's shaft is drawn, m, however near the screen's edge its target stands. */
const ARROW_SHORTEST = 0.6;
/** Places the aim arrow (shown while a press aims or a piece is armed). */
function drawAim(): void {
  const piece = aiming.piece || aiming.armed || next.piece;
  aimPreview.visible = piece !== 0 && isAlive(shell.world, piece);
  if (!aimPreview.visible) return;
  const P = shell.world.components.Position;
  // Its local +x along the ball's travel, its head 0.5 m short of the piece's centre. On a touch
  // screen it is drawn ahead of the piece instead, its tail ARROW_AHEAD past the piece's centre and
  // its head farthest on: the finger pulls back behind the piece, and an arrow drawn there lay under
  // the thumb. Kept on the screen (a target near a phone's edge put the arrow off it): shortened
  // while any corner would be off; drawn behind the piece when no length ahead fits; scaled down
  // (ARROW_SMALLEST) when neither does.
  const full = 1.2 + 3.5 * aiming.power;
  const ux = Math.cos(aiming.direction),
    uz = Math.sin(aiming.direction);
  const x0 = P.x[piece]!,
    z0 = P.z[piece]!;
  let length = full,
    shift = 0,
    scale = 1;
  fit: for (const ahead of touch ? [true, false] : [false]) {
    for (const s of [1, ARROW_SMALLEST]) {
      for (let len = full; ; len = Math.max(ARROW_SHORTEST, 0.8 * len)) {
        const sh = ahead ? ARROW_AHEAD + len + 1.2 : 0;
        if (arrowFits(x0, z0, ux, uz, sh, len, s) || (!ahead && s < 1 && len === ARROW_SHORTEST)) {
          length = len;
          shift = sh;
          scale = s;
          break fit;
        }
        if (len === ARROW_SHORTEST) break;
      }
    }
  }
  aimPreview.scale.setScalar(scale);
  aimPreview.position.set(P.x[piece]!, 0.08, P.z[piece]!);
  aimPreview.rotation.y = -aiming.direction;
  aimShaft.scale.x = length;
  aimShaft.position.x = shift - 1.2 - length / 2;
  aimShaftEdge.scale.x = length + AIM_EDGE;
  aimShaftEdge.position.x = aimShaft.position.x - AIM_EDGE / 2;
  aimHead.position.x = shift - 0.9;
  // (The edge's triangle centred AIM_EDGE back of the fill's: its tip AIM_EDGE past the fill's.)
  aimHeadEdge.position.x = shift - 0.9 - AIM_EDGE;
  aimMaterial.color.setHSL(0.13 * (1 - aiming.power), 1, 0.55);
}
/** On a touch screen, how far past the piece's centre along the ball's travel the aim arrow's tail is drawn, m. */
const ARROW_AHEAD = 0.7;
/** The aim arrow's scale when it fits on the screen at no length at full size. */
const ARROW_SMALLEST = 0.6;
/**
 * The aim arrow's outline with its dark edge, in its own frame (+x along the travel, m, before its
 * shift), as [along, across, whether the shaft's length is taken off along]: its shaft's tail
 * corners, its head's tip and back corners.
 */
const ARROW_OUTLINE: ReadonlyArray<readonly [number, number, boolean]> = [
  [-1.2 - AIM_EDGE, 0.2 + AIM_EDGE, true],
  [-1.2 - AIM_EDGE, -0.2 - AIM_EDGE, true],
  [-0.9 - AIM_EDGE + (0.8 + 2 * AIM_EDGE), 0, false],
  [-0.9 - AIM_EDGE - (0.8 + 2 * AIM_EDGE) / 2, 0.87 * (0.8 + 2 * AIM_EDGE), false],
  [-0.9 - AIM_EDGE - (0.8 + 2 * AIM_EDGE) / 2, -0.87 * (0.8 + 2 * AIM_EDGE), false],
];
const arrowCorner = new Vector3();
/**
 * Whether the aim arrow drawn at the piece at (x0, z0) along the unit direction (ux, uz), moved
 * `shift` m along it, its shaft `length` m and the whole scaled by `scale` about the piece, lies
 * within ARROW_EDGE of the screen's middle (normalised device coordinates) and in front of the camera.
 */
function arrowFits(x0: number, z0: number, ux: number, uz: number, shift: number, length: number, scale: number): boolean {
  for (const [ax, side, tail] of ARROW_OUTLINE) {
    const along = scale * (shift + ax - (tail ? length : 0)),
      across = scale * side;
    arrowCorner.set(x0 + along * ux - across * uz, 0.08, z0 + along * uz + across * ux).project(app.camera);
    if (!(Math.abs(arrowCorner.x) < ARROW_EDGE && Math.abs(arrowCorner.y) < ARROW_EDGE && arrowCorner.z < 1)) return false;
  }
  return true;
}
// ---- The swing drawn in 3D: where the ball will go and where it will hit -----------------------------

// While a swing is aimed (a press or drag on a target, an armed target, or a drag let go until the
// ball's run begins): the ball's path as a pendulum from where the line draws it back, at the height
// it will swing at (./scene swingGoal, swingPath), a bright dashed tube in a dark edge drawn over
// everything (a structure or the mast in front would hide it); a faint ghost ball in a pale ring
// where the swing starts (green once the held ball is there); a red ghost ball with a ring facing
// the camera where the ball first meets a piece, and a thin line from it down to the ground. The arrow on the ground stays as its shadow. The ball's place
// on the screen at the hit, not only across the ground, reads at once (strangers could not tell
// where a swing drawn on the ground would go).
/** Dashes of the drawn path (every other of the swing's samples is a gap). */
const PATH_DASHES = 24;
/** Radius, m, of the path's fill and of its dark edge (thicker on an upright phone, see CUE_SCALE). */
const PATH_RADIUS = 0.1 * CUE_SCALE,
  PATH_EDGE = 0.17 * CUE_SCALE;
const pathFillMaterial = new MeshBasicMaterial({ color: 0xffe08a, depthTest: false, depthWrite: false, transparent: true });
const pathEdgeMaterial = new MeshBasicMaterial({ color: 0x14100a, depthTest: false, depthWrite: false, transparent: true, opacity: 0.8 });
const pathFill = new InstancedMesh(chainGeometry, pathFillMaterial, PATH_DASHES);
const pathEdge = new InstancedMesh(chainGeometry, pathEdgeMaterial, PATH_DASHES);
pathEdge.renderOrder = 12;
pathFill.renderOrder = 13;
pathFill.frustumCulled = pathEdge.frustumCulled = false;
const startGhost = new Mesh(
  ballGeometry,
  new MeshBasicMaterial({ color: 0xfff6dc, transparent: true, opacity: 0.45, depthWrite: false, depthTest: false }),
);
startGhost.scale.setScalar(BALL_RADIUS);
startGhost.renderOrder = 12;
const hitGhost = new Mesh(
  ballGeometry,
  new MeshBasicMaterial({ color: 0xff4a3a, transparent: true, opacity: 0.45, depthWrite: false, depthTest: false }),
);
hitGhost.scale.setScalar(BALL_RADIUS);
hitGhost.renderOrder = 12;
/** The ring round the ghost ball at the hit, facing the camera: red in a dark edge. */
const hitRing = new Mesh(
  new RingGeometry(1.05, 1.3, 40),
  new MeshBasicMaterial({ color: 0xff3b2b, depthTest: false, depthWrite: false, transparent: true, side: DoubleSide }),
);
const hitRingEdge = new Mesh(
  new RingGeometry(0.95, 1.4, 40),
  new MeshBasicMaterial({ color: 0x14100a, depthTest: false, depthWrite: false, transparent: true, opacity: 0.8, side: DoubleSide }),
);
hitRingEdge.renderOrder = 13;
hitRing.renderOrder = 14;
hitRing.add(hitRingEdge);
hitRingEdge.position.z = -0.01;
/** A pale ring round the ghost ball where the swing starts, facing the camera, in a dark edge. */
const startRing = new Mesh(
  new RingGeometry(0.95, 1.12, 40),
  new MeshBasicMaterial({ color: 0xfff6dc, depthTest: false, depthWrite: false, transparent: true, opacity: 0.9, side: DoubleSide }),
);
const startRingEdge = new Mesh(
  new RingGeometry(0.88, 1.2, 40),
  new MeshBasicMaterial({ color: 0x14100a, depthTest: false, depthWrite: false, transparent: true, opacity: 0.6, side: DoubleSide }),
);
startRingEdge.renderOrder = 12;
startRing.renderOrder = 13;
startRing.add(startRingEdge);
startRingEdge.position.z = -0.01;
const hitDrop = new Mesh(chainGeometry, new MeshBasicMaterial({ color: 0xff3b2b, transparent: true, opacity: 0.7, depthWrite: false }));
const swingPreview = new Group();
swingPreview.add(pathEdge, pathFill, startGhost, startRing, hitGhost, hitRing, hitDrop);
swingPreview.visible = false;
app.scene.add(swingPreview);
/** The previewed swing's samples (./scene swingPath: the ball's centre, x y z in turn, m) and the piece it meets first (0: none). */
const preview = { path: [] as number[], meet: 0, ready: false };
/** How near, m, the held ball's centre must be to the previewed swing's start for its ring to show it ready (./scene READY_NEAR). */
const READY_SHOWN = 0.4;
const dashMatrix = new Matrix4();
const dashFrom = new Vector3(),
  dashTo = new Vector3(),
  dashMid = new Vector3(),
  dashQuat = new Quaternion(),
  dashScale = new Vector3();
const yAxis = new Vector3(0, 1, 0);
/** The swing to preview now (its goal as ./scene swingGoal gives it), or null: see above. */
function previewGoal(): ReturnType<typeof swingGoal> | null {
  const piece = aiming.piece || aiming.armed || next.piece;
  if (piece !== 0 && isAlive(shell.world, piece) && drag.body === 0) return swingGoal(shell.world, handles, piece, request());
  const pull = handles.controls.pull;
  if (pull?.letGo && pull.offset > 0) return pull;
  return null;
}
/** Places the swing's 3D preview (see above), or hides it. */
function drawSwingPreview(): void {
  const goal = previewGoal();
  swingPreview.visible = goal !== null;
  if (goal === null) {
    preview.meet = 0;
    preview.ready = false;
    preview.path.length = 0;
    return;
  }
  const down = Math.sqrt(Math.max(0, HANG * HANG - goal.offset * goal.offset));
  const start = [goal.x - goal.offset * goal.ux, goal.height - down, goal.z - goal.offset * goal.uz];
  const path = preview.path;
  preview.meet = swingPath(shell.world, handles.pieces, start, [goal.x, goal.height, goal.z], path);
  const n = path.length / 3;
  startGhost.position.set(start[0]!, start[1]!, start[2]!);
  // Green once the held ball is there: let go now and it swings at once (before, it is still on its
  // way and the swing waits for it).
  preview.ready =
    handles.controls.pull !== null && Math.hypot(ballAt[0]! - start[0]!, ballAt[1]! - start[1]!, ballAt[2]! - start[2]!) < READY_SHOWN;
  (startRing.material as MeshBasicMaterial).color.setHex(preview.ready ? 0x6dff7a : 0xfff6dc);
  startRing.position.copy(startGhost.position);
  startRing.quaternion.copy(app.camera.quaternion);
  startRing.scale.setScalar(BALL_RADIUS);
  // The dashes: from sample 2k to 2k + 1, drawn from the start toward the hit.
  let shown = 0;
  for (let k = 0; k < PATH_DASHES && 2 * k + 1 < n; k++) {
    dashFrom.fromArray(path, 6 * k);
    dashTo.fromArray(path, 6 * k + 3);
    dashMid.addVectors(dashFrom, dashTo).multiplyScalar(0.5);
    dashTo.sub(dashFrom);
    const len = dashTo.length();
    if (len < 1e-6) continue;
    dashQuat.setFromUnitVectors(yAxis, dashTo.divideScalar(len));
    pathFill.setMatrixAt(shown, dashMatrix.compose(dashMid, dashQuat, dashScale.set(PATH_RADIUS, len, PATH_RADIUS)));
    pathEdge.setMatrixAt(shown, dashMatrix.compose(dashMid, dashQuat, dashScale.set(PATH_EDGE, len + PATH_EDGE - PATH_RADIUS, PATH_EDGE)));
    shown++;
  }
  pathFill.count = pathEdge.count = shown;
  pathFill.instanceMatrix.needsUpdate = pathEdge.instanceMatrix.needsUpdate = true;
  pathFillMaterial.color.setHSL(0.13 * (1 - aiming.power), 1, 0.6);
  const hit = preview.meet !== 0;
  hitGhost.visible = hitRing.visible = hitDrop.visible = hit;
  if (!hit) return;
  const hx = path[path.length - 3]!,
    hy = path[path.length - 2]!,
    hz = path[path.length - 1]!;
  hitGhost.position.set(hx, hy, hz);
  hitRing.position.set(hx, hy, hz);
  hitRing.quaternion.copy(app.camera.quaternion);
  // Pulsing a little, so the eye finds it.
  hitRing.scale.setScalar(BALL_RADIUS * Math.sqrt(CUE_SCALE) * (1 + 0.08 * Math.sin(shell.world.time * 8)));
  const drop = Math.max(0.01, hy - BALL_RADIUS);
  hitDrop.position.set(hx, drop / 2, hz);
  hitDrop.scale.set(0.03 * CUE_SCALE, drop, 0.03 * CUE_SCALE);
}
/** The piece the last swing was aimed at (marked with a ring and an arrow while the swing runs), or 0. */
let aimed = 0;
/**
 * The standing pieces when the last swing was aimed (to count what it brought down), the ball's
 * speed it was aimed at (m/s; 0 for a swing planned without a pull), and what it did.
 */
const swing = { downBefore: 0, speed: 0, result: '', resultAt: 0, pending: false, direction: 0 };
/** Where the ball came nearest the aimed piece during the swing that is pending, and how near (m, centre to centre). */
const nearest: { pass: NearestPass | null; distance: number } = { pass: null, distance: Number.POSITIVE_INFINITY };
const cameraRight = new Vector3();
/** While a swing is pending: notes the ball's nearest pass by the piece aimed at (for the words of a miss). */
function trackNearest(): void {
  if (!swing.pending || aimed === 0 || !isAlive(shell.world, aimed)) return;
  const P = shell.world.components.Position;
  const b = handles.ball;
  const d = Math.hypot(P.x[b]! - P.x[aimed]!, P.y[b]! - P.y[aimed]!, P.z[b]! - P.z[aimed]!);
  if (d >= nearest.distance) return;
  const piece = handles.pieces.find((p) => p.body === aimed);
  if (!piece) return;
  const across = Math.max(...piece.half.filter((_, i) => i !== piece.upAxis));
  cameraRight.setFromMatrixColumn(app.camera.matrixWorld, 0);
  const r = Math.hypot(cameraRight.x, cameraRight.z) || 1;
  nearest.distance = d;
  nearest.pass = {
    ball: [P.x[b]!, P.y[b]!, P.z[b]!],
    target: [P.x[aimed]!, P.y[aimed]!, P.z[aimed]!],
    half: [across, piece.half[piece.upAxis]!, across],
    radius: BALL_RADIUS,
    direction: swing.direction,
    right: [cameraRight.x / r, cameraRight.z / r],
  };
}
/**
 * Distance, CSS px, from a standing piece's drawn outline within which a press that misses every
 * piece still takes it: a finger's width on a touch screen, a mouse's slip on a desktop.
 */
const NEAR_TAP_PX = isTouchDevice() ? 30 : 12;
const nearAt = new Vector3();
/**
 * The standing piece drawn nearest the point (ndcX, ndcY), if its outline (the screen rectangle
 * round its box's corners, drawn where it is) comes within NEAR_TAP_PX of it, else 0; a point
 * inside several outlines takes the piece whose centre is nearest. A tower's block 0.7 m wide is
 * about 20 px on a desktop and 15 on a phone: measured from the block's centre (10 px on a
 * desktop) a click just off its edge sent the hook to the ground behind it instead.
 */
function nearPiece(ndcX: number, ndcY: number): number {
  const w = canvas.clientWidth / 2,
    hgt = canvas.clientHeight / 2;
  const px = ndcX * w,
    py = ndcY * hgt;
  const O = shell.world.components.Orientation;
  let best = 0,
    bestD = NEAR_TAP_PX,
    bestC = Number.POSITIVE_INFINITY;
  for (const p of handles.pieces) {
    if (p.fallen || !renderer.drawnPosition(p.body, followBall)) continue;
    // The box's half extents across the world's axes: |R| times its own.
    const x = O.x[p.body]!,
      y = O.y[p.body]!,
      z = O.z[p.body]!,
      q = O.w[p.body]!;
    const R = [
      [1 - 2 * (y * y + z * z), 2 * (x * y - q * z), 2 * (x * z + q * y)],
      [2 * (x * y + q * z), 1 - 2 * (x * x + z * z), 2 * (y * z - q * x)],
      [2 * (x * z - q * y), 2 * (y * z + q * x), 1 - 2 * (x * x + y * y)],
    ];
    const e = R.map((row) => Math.abs(row[0]!) * p.half[0] + Math.abs(row[1]!) * p.half[1] + Math.abs(row[2]!) * p.half[2]);
    let x0 = Number.POSITIVE_INFINITY,
      x1 = Number.NEGATIVE_INFINITY,
      y0 = Number.POSITIVE_INFINITY,
      y1 = Number.NEGATIVE_INFINITY,
      behind = false;
    for (let c = 0; c < 8; c++) {
      nearAt
        .set(
          followBall[0]! + (c & 1 ? e[0]! : -e[0]!),
          followBall[1]! + (c & 2 ? e[1]! : -e[1]!),
          followBall[2]! + (c & 4 ? e[2]! : -e[2]!),
        )
        .project(app.camera);
      if (nearAt.z > 1) behind = true;
      x0 = Math.min(x0, nearAt.x * w);
      x1 = Math.max(x1, nearAt.x * w);
      y0 = Math.min(y0, nearAt.y * hgt);
      y1 = Math.max(y1, nearAt.y * hgt);
    }
    if (behind) continue;
    const d = Math.hypot(Math.max(0, x0 - px, px - x1), Math.max(0, y0 - py, py - y1));
    const centre = Math.hypot((x0 + x1) / 2 - px, (y0 + y1) / 2 - py);
    if (d < bestD || (d === 0 && centre < bestC)) {
      bestD = d;
      bestC = centre;
      best = p.body;
    }
  }
  return best;
}
/** The piece drawn lit as the target of a swing (0 when none). */
let lit = 0;
/** Lights piece `piece` (0: none) as the swing's target; the one lit before gets its own colour back. */
function light(piece: number): void {
  const before = handles.pieces.find((p) => p.body === lit);
  lit = piece;
  if (before && isAlive(shell.world, before.body)) tint(before.body, PIECE_TINT);
  if (piece !== 0) tint(piece, LIT_TINT);
}
/** Whether the last tap re-aimed a swing still winding up (the status line says so). */
let retargeted = false;
/** Swings used on this level (runs at targets begun, drags of the ball), out of its `swingBudget`. */
function swingsUsed(): number {
  return handles.controls.released;
}
/** The cleared level's result, as the banner says it: "Level N cleared in S swings! ★★☆". */
function clearedLine(): string {
  const { swings, stars } = clearedWith;
  return `Level ${handles.level} cleared in ${swings} ${swings === 1 ? 'swing' : 'swings'}! ${'★'.repeat(stars)}${'☆'.repeat(3 - stars)}`;
}
/**
 * The banner under the result: where the score's jump at the clear came from, how the stars
 * are earned ("blocks 396 + clear 500 + ★★ 500 = 1396" and "★★★ in 2 swings · ★★ in 3 · ★ in 4–5"),
 * and what the clear asked, with the pieces left standing (./status clearRuleLine).
 */
function clearedBanner(): string {
  const rule = clearRuleLine(handles.level, clearTarget(handles.pieces, handles.level), clearedWith.standing);
  return `${clearedLine()}\n${clearScoreLine(clearedWith.score, clearedWith.stars)}\n${starsRule(handles.level)}\n${rule}`;
}
/** Whether the level's swings are all used and it is not cleared (a swing is refused). */
function outOfSwings(): boolean {
  return !cleared && swingsUsed() >= swingBudget(handles.level);
}
/** What a piece is, for the hint: "the tower", "the wall", "the plank stack". */
function pieceName(piece: number): string {
  const kind = handles.pieces.find((p) => p.body === piece)?.kind;
  return kind === 'planks' ? 'the plank stack' : `the ${kind ?? 'block'}`;
}
/** Whether pieces `a` and `b` (bodies) stand in one structure (./scene structureOf). */
function sameStructure(a: number, b: number): boolean {
  const pa = handles.pieces.find((p) => p.body === a);
  return pa !== undefined && structureOf(handles.pieces, pa).some((q) => q.body === b);
}
/** Whether the ball is on its run at a target now (the swing can no longer be re-aimed). */
function onRun(): boolean {
  const moves = handles.controls.moves;
  return aimed !== 0 && moves.length > 0 && moves[0]!.run === true;
}
/**
 * Swings the ball at piece `piece`: the crane's moves, the marks on it, a chime; false (and a low
 * tone) when out of swings. A tap while a swing winds up re-aims that swing (the marks slide from
 * the old target to the new, the hint says so; no swing is used until the ball is let go into its
 * run); a tap while the ball is on its run is kept as the next swing (`next`, begun by `fireNext`
 * when the run is over; the hint says so): it uses a swing only then.
 */
/**
 * Begins the saved next swing (`next`) once the ball's run is over (the crane has no moves left),
 * from wherever the ball is swinging then (./scene aimAt plans from the ball's state). A target
 * fallen meanwhile is let go. Called every step.
 */
function fireNext(): void {
  if (next.piece === 0 || handles.controls.moves.length > 0 || handles.controls.pull !== null) return;
  const piece = next.piece;
  const request = next.request;
  next.piece = 0;
  next.request = null;
  if (!isAlive(shell.world, piece) || handles.pieces.find((p) => p.body === piece)?.fallen) {
    say(`The next swing's target fell already: aim again (no swing used)`);
    return;
  }
  swingAt(piece, request ?? undefined);
}
function swingAt(piece: number, aim?: SwingRequest): boolean {
  const running = onRun();
  const moves = handles.controls.moves;
  if (outOfSwings() || (running && !cleared && swingsUsed() + 1 > swingBudget(handles.level))) {
    sound.chime(220, 0.2);
    say(running ? 'That was the last swing: no swings left for another' : 'No swings left');
    return false;
  }
  if (running) {
    // A swing on its run cannot be re-aimed: the drag is kept as the next swing, planned from
    // wherever the ball is once this run (hit and follow-through) is over (`fireNext`), so the
    // player aims again at once instead of waiting for the run. It uses a swing when it is let go.
    next.piece = piece;
    next.request = aim ?? null;
    light(piece);
    sound.chime(587, 0.1);
    say(`Next swing: ${pieceName(piece)}, as soon as this one has hit`);
    return true;
  }
  const before = aimed;
  // A tap during a wind-up re-aims that swing.
  retargeted = before !== 0 && (moves.length > 0 || handles.controls.pull?.again === true);
  if (retargeted && before !== piece && isAlive(shell.world, before)) {
    const P = shell.world.components.Position;
    dropMarks(P.x[before]!, P.z[before]!);
    say(`New target: ${pieceName(piece)} instead of ${pieceName(before)} (same swing)`);
  } else if (retargeted) say(`Still swinging at ${pieceName(piece)}`);
  // A swing whose result was not counted yet (its run over, the dust settling; or a next swing
  // begun the moment the run ended) is counted now.
  if (runEndedAt >= 0 || (swing.pending && !retargeted)) countResult();
  // A drag held at this piece drew the ball back (aimDrag): letting go swings it from there; else
  // the crane plans the swing (a tap, or a swing kept for after a run).
  const pull = handles.controls.pull;
  if (pull !== null && pull.piece === piece && !pull.letGo && aim !== undefined) {
    pullBack(shell.world, handles, piece, aim);
    letGoPull(handles);
  } else aimAt(shell.world, handles, piece, aim);
  light(piece);
  aimed = piece;
  swing.downBefore = fallenCount(handles.pieces);
  swing.speed = aim?.speed ?? 0;
  swing.result = '';
  swing.pending = true;
  {
    const P = shell.world.components.Position;
    swing.direction = aim?.direction ?? Math.atan2(P.z[piece]! - P.z[handles.ball]!, P.x[piece]! - P.x[handles.ball]!);
  }
  nearest.pass = null;
  nearest.distance = Number.POSITIVE_INFINITY;
  if (cleared) clearedWith.tapped = true;
  sound.chime(retargeted && before !== piece ? 880 : 660, 0.15);
  return true;
}

/** The pointers down on the canvas now (fingers on a touch screen), by pointerId. */
const pointersDown = new Set<number>();
/**
 * Whether a second pointer came down since none was: the gesture is a pinch or turn of the camera
 * (the orbit controls take two fingers), so nothing aims, swings or sends the hook until all lift.
 */
let pinching = false;
/**
 * Cancels the press in progress as a second finger joins it: its aim (no swing), its grab of the
 * ball (the swing the grab counted is given back) and the hook it would send on lifting.
 */
function cancelPress(): void {
  if (pressId === -1) return;
  pressId = -1;
  aiming.piece = 0;
  aiming.remote = false;
  pendingHook = null;
  if (handles.controls.pull !== null && !handles.controls.pull.letGo) dropPull(handles);
  if (drag.body === handles.ball && drag.body !== 0) {
    drag.release();
    handles.controls.released = Math.max(0, handles.controls.released - 1);
  }
}
canvas.addEventListener('pointerdown', (event) => {
  // A primary pointer comes down with no other of its kind down: none is left from before (a lift
  // the page never heard of would otherwise make every later touch a pinch).
  if (event.isPrimary) {
    pointersDown.clear();
    pinching = false;
  }
  pointersDown.add(event.pointerId);
  if (pointersDown.size > 1) {
    pinching = true;
    cancelPress();
    return;
  }
  if (pinching || event.button !== 0) return;
  app.toNdc(event.clientX, event.clientY, ndc);
  // A finger's press on open ground sends the hook when it lifts (it may turn into a pinch); a mouse's at once.
  const pressed = pressAt(ndc[0], ndc[1], event.pointerType === 'touch');
  if (pressed === 'ball' || pressed === 'aim' || (pressed === 'hook' && pendingHook !== null)) {
    pressId = event.pointerId;
    canvas.setPointerCapture(event.pointerId);
  }
});
// A pointer is up wherever it lifts (off the canvas too): the pinch ends when the last one does.
const pointerGone = (event: PointerEvent): void => {
  pointersDown.delete(event.pointerId);
  if (pointersDown.size === 0) pinching = false;
};
window.addEventListener('pointerup', pointerGone, true);
window.addEventListener('pointercancel', pointerGone, true);
/** Farthest the hand may take a held ball from under the hook, across the ground, m. */
const PULL_REACH = 4;
/** The horizontal plane at the height the ball was grabbed: a held ball follows the pointer over the ground. */
const dragPlane = new Plane(new Vector3(0, 1, 0), 0);
const dragAt = new Vector3();
/**
 * Where the hand holds the ball, from its centre, m (the grab point when grabbed; the ball does not
 * turn in the hand, see gameStep).
 */
const grabOffset = [0, 0, 0];
/** Where the pointer asks the held ball's centre to go, from under the hook across the ground, m (x, z). */
const dragGoal = [0, 0];
/**
 * Sets where the held ball's centre is to go: over the ground point where the pointer's ray meets
 * the horizontal plane through the grab point (drawn up the screen, the ball goes away from the
 * camera; down, toward it), at most PULL_REACH from under the hook. A ray that misses the plane
 * (over the horizon) leaves it. The hand follows in `holdBall`.
 */
function dragOverGround(ndcX: number, ndcY: number): void {
  raycaster.setFromCamera(new Vector2(ndcX, ndcY), app.camera);
  if (raycaster.ray.intersectPlane(dragPlane, dragAt) === null) return;
  pullBall(dragAt.x - grabOffset[0]!, dragAt.z - grabOffset[2]!);
}
/** Sets where the held ball's centre is pulled to across the ground (x, z, m), at most PULL_REACH from under the hook. */
function pullBall(x: number, z: number): void {
  const [hx, , hz] = hookPosition(handles.crane);
  let dx = x - hx,
    dz = z - hz;
  const d = Math.hypot(dx, dz);
  if (d > PULL_REACH) {
    dx *= PULL_REACH / d;
    dz *= PULL_REACH / d;
  }
  dragGoal[0] = dx;
  dragGoal[1] = dz;
}
/**
 * Before each step while the ball is held: the hand at the grab point of a ball whose centre is at
 * `dragGoal` across the ground, at the height its taut chain holds the ball where it is now
 * (sqrt(HANG^2 - d^2) under the hook at d across the ground), so the hand pulls the ball along its
 * chain's reach and never up off it: a hand held at the grab's height lifted the ball, its chain
 * buckled and held it up, and a swing let go from there ran level instead of down through the pieces.
 */
function holdBall(world: PhysicsWorld): void {
  const P = world.components.Position,
    b = handles.ball;
  const [hx, hy, hz] = hookPosition(handles.crane);
  const d = Math.min(HANG - 0.01, Math.hypot(P.x[b]! - hx, P.z[b]! - hz));
  const y = hy - Math.sqrt(HANG * HANG - d * d);
  drag.moveTo([hx + dragGoal[0]! + grabOffset[0]!, y + grabOffset[1]!, hz + dragGoal[1]! + grabOffset[2]!]);
}
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pressId) return;
  app.toNdc(event.clientX, event.clientY, ndc);
  if (aiming.piece !== 0) aimDrag(ndc[0], ndc[1]);
  else dragOverGround(ndc[0], ndc[1]);
});
const up = (event: PointerEvent): void => {
  if (event.pointerId !== pressId) return;
  pressId = -1;
  const hook = pendingHook;
  pendingHook = null;
  if (event.type === 'pointercancel') {
    aiming.piece = 0;
    if (handles.controls.pull !== null && !handles.controls.pull.letGo) dropPull(handles);
  } else if (hook) sendHook(hook[0], hook[1]);
  if (aiming.piece !== 0) {
    app.toNdc(event.clientX, event.clientY, ndc);
    releaseAt(ndc[0], ndc[1]);
  }
  drag.release();
};
canvas.addEventListener('pointerup', up);
canvas.addEventListener('pointercancel', up);

// ---- Drawing quality (see Quality) -------------------------------------------------------------

/** The sun's shadows on the ground without a shadow map (lite quality only; look.ts GroundShadows). */
const groundShadows = new GroundShadows(256, renderer.lights?.options.direction ?? [0.45, 1, 0.3]);
groundShadows.visible = false;
app.scene.add(groundShadows.boxes, groundShadows.ball);
const shadowAt = [0, 0, 0];
/** Places this frame's ground shadows: each piece's and the ball's where they are drawn, and the mast's. */
function placeGroundShadows(): void {
  const O = shell.world.components.Orientation;
  groundShadows.begin();
  for (const p of handles.pieces) {
    const half = bodyHalf.get(p.body);
    if (!half || !renderer.drawnPosition(p.body, shadowAt)) continue;
    groundShadows.add(shadowAt[0]!, shadowAt[1]!, shadowAt[2]!, O.x[p.body]!, O.y[p.body]!, O.z[p.body]!, O.w[p.body]!, half);
  }
  // The mast, narrower than its box (a lattice lets light through). Not the jib: flattened as a solid
  // strip its shadow would be a thin dark line 15 m long across the site, read as a cable on the
  // ground (its lattice lets most of the light through); nor the counterweight and the cab (see
  // their meshes: square dark patches among the targets).
  groundShadows.add(0, JIB_HEIGHT / 2, 0, 0, 0, 0, 1, MAST_SHADOW_HALF);
  const ball = renderer.drawnPosition(handles.ball, shadowAt);
  if (ball) groundShadows.end(shadowAt[0]!, shadowAt[1]!, shadowAt[2]!, BALL_RADIUS);
  else groundShadows.end(0, -100, 0, 0);
}
/** Half extents, m, of the mast's shadow-casting box (see placeGroundShadows). */
const MAST_SHADOW_HALF: [number, number, number] = [0.22, JIB_HEIGHT / 2, 0.22];
/** The pixel ratio the app chose (0.5 under software WebGL, else the device's up to 2). */
const startPixelRatio = app.renderer.getPixelRatio();
/**
 * The pixel ratio of a small screen drawn lite: between the kit's 0.5 under software WebGL (a blur
 * of big pixels on a phone) and 1 (about four times the pixels to fill, each frame 4 to 6 times
 * dearer in SwiftShader); lite's materials and shadows keep each pixel cheap. Never above the
 * device's own.
 */
const LITE_PHONE_PIXEL_RATIO = Math.min(window.devicePixelRatio || 1, 0.75);
/** The physically based materials a lite quality swapped out of the scene's meshes, by their stand-in. */
const swappedOut = new Map<Material, Material>();
/**
 * Draws the scene at quality `q`: the sun's shadow map on or off, every physically based material in
 * the scene (crane, site, floor, chain) swapped for its cheaper stand-in or back, the pieces and the
 * ball drawn again in theirs (tinted as they were), the flattened ground shadows shown when lite.
 */
function setQuality(q: Quality): void {
  if (!QUALITIES.includes(q)) throw new RangeError(`setQuality: quality must be one of ${QUALITIES.join(', ')}, got ${JSON.stringify(q)}`);
  params.quality = q;
  const full = q === 'full';
  renderer.setShadows(full);
  if (renderer.lights) renderer.lights.sun.castShadow = full;
  app.renderer.setPixelRatio(!full && SMALL_SCREEN ? LITE_PHONE_PIXEL_RATIO : startPixelRatio);
  swapMaterials();
  for (const p of handles.pieces) tint(p.body, p.body === lit ? LIT_TINT : PIECE_TINT);
  renderer.setShape(handles.ball, { geometry: ballGeometry, material: asDrawn(ballMaterial), scale: 'radius' });
  groundShadows.visible = !full;
  if (!full) placeGroundShadows();
  panel.refresh();
}
/**
 * Swaps the physically based material of every mesh in the scene but the pieces and the ball (set
 * by body, see setQuality) for its cheaper stand-in when lite, or back when full. Again after the
 * world renderer makes meshes of its own (its floor, on the first frame of a world: see frame).
 */
function swapMaterials(): void {
  const full = params.quality === 'full';
  const own = [materials.tower, materials.wall, materials.planks, ballMaterial];
  const dressed = new Set<Material | undefined>([...own, ...own.map((m) => cheaper.get(m))]);
  app.scene.traverse((o) => {
    if (!(o instanceof Mesh) || Array.isArray(o.material) || dressed.has(o.material)) return;
    if (full) {
      const before = swappedOut.get(o.material);
      if (before) o.material = before;
    } else if (o.material instanceof MeshStandardMaterial) {
      const stand = asDrawn(o.material);
      swappedOut.set(stand, o.material);
      o.material = stand;
    }
  });
  // The jib's material as the quality draws it.
  jib.material = asDrawn(jibMaterial);
}
/** Frames a second under which a page drawing at full quality steps down to lite by itself. */
const AUTO_LITE_FPS = 20;
/** Whether the quality was fixed (by the URL or the settings panel): the page no longer changes it. */
let qualityChosen = askedQuality !== null;
/**
 * Steps down to lite once if the page draws fewer than AUTO_LITE_FPS frames a second over the
 * WATCH_FOR s that begin WATCH_FROM s after the page is ready (the first frames compile shaders);
 * a page hidden meanwhile (its frames stop) is watched again when it shows.
 */
function watchFrameRate(): void {
  const WATCH_FROM = 1000,
    WATCH_FOR = 2000;
  setTimeout(() => {
    if (qualityChosen || params.quality !== 'full') return;
    const drawn = app.pacer.drawn,
      t0 = performance.now();
    setTimeout(() => {
      if (qualityChosen || params.quality !== 'full') return;
      if (document.hidden) {
        document.addEventListener('visibilitychange', watchFrameRate, { once: true });
        return;
      }
      const fps = ((app.pacer.drawn - drawn) * 1000) / (performance.now() - t0);
      if (fps < AUTO_LITE_FPS) setQuality('lite');
    }, WATCH_FOR);
  }, WATCH_FROM);
}

// ---- Panel and status line ---------------------------------------------------------------------

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'level', label: 'level (restarts)', min: 1, max: 20, step: 1, onRelease: true, onChange: () => shell.reset() },
    { type: 'slider', key: 'seed', label: 'layout (restarts)', min: 1, max: 999, step: 1, onRelease: true, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'ballTonnes',
      label: 'ball mass, t (restarts)',
      min: 0.5,
      max: 16,
      step: 0.1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'debug', label: withKey('show physics', 'G'), onChange: (v) => setDebug(v === true) },
    {
      type: 'choice',
      key: 'quality',
      label: 'drawing',
      options: { 'full (shadows)': 'full', 'lite (faster)': 'lite' },
      onChange: (v) => {
        qualityChosen = true;
        setQuality(v as Quality);
      },
    },
    { type: 'button', key: 'nextLevel', label: withKey('next level', 'L') },
    { type: 'button', key: 'reset', label: withKey('reset level', 'R') },
  ],
  // In the left column under the controls, closed, so the scene has the rest of the width; on a
  // phone in the menu drawer.
  { title: 'Settings', container: pageLayout().info, closed: !pageLayout().compact() },
);

const status = document.createElement('div');
status.className = 'bp-hud';
status.dataset.hud = 'wrecking-ball';
// As tall as its longest text (three lines on an upright phone, two on a desktop: a swing winding up
// with its steadying tip wraps there) whatever it says now, so a longer line does not move the
// stage under the player's pointer (a stranger's aim jumped 19 px when the line wrapped).
status.style.cssText = `position: static; padding: 4px 8px; min-height: ${PORTRAIT ? 3 : 2}lh`;
pageLayout().status.append(status);
// The side column's numbers: the score for a player; with the debug layer (G, ?debug) also the
// step time and the kit's frame rate, body and step counts.
const readout = document.createElement('div');
readout.className = 'bp-hud';
readout.dataset.hud = 'score';
readout.style.cssText = 'position: static; margin-top: 8px';
pageLayout().info.prepend(readout);
/** Shows or hides the engineer's numbers (the kit's bodies and steps lines; the frame rate always shows). */
function showStats(on: boolean): void {
  for (const line of ['bodies', 'steps']) {
    const el = shell.hud.readout.querySelector<HTMLElement>(`[data-hud="${line}"]`);
    if (el) el.hidden = !on;
  }
}
showStats(params.debug);
setQuality(params.quality);
watchFrameRate();

// ---- Site plan: the left column's foot (it stood empty, 230 px at 1280 x 800) ------------------

/**
 * A plan of the site seen from above, under the controls' legend: the jib's reach, the jib, the
 * hook and the ball, every piece in its colour (fallen ones dark), the concrete shields in grey and
 * the target of a swing ringed.
 * A click on a piece's mark swings the ball at it; elsewhere inside the reach sends the hook there.
 */
const PLAN_PX = 180;
/** Metres from the mast to the plan's edge. */
const PLAN_HALF = 13;
const planBox = document.createElement('figure');
// As tall as the column has room for under the legend, from 120 to PLAN_PX px, square.
planBox.style.cssText = `margin: 0; flex: 1 1 ${PLAN_PX}px; min-height: 120px; max-height: ${PLAN_PX}px; display: flex`;
// An SVG, not a canvas: tests and the thumbnail script take the page's first canvas for the scene.
const plan = document.createElement('div');
plan.dataset.hud = 'site-plan';
plan.setAttribute('role', 'img');
plan.setAttribute('aria-label', 'site plan: click a piece to swing the ball at it');
plan.style.cssText = 'height: 100%; aspect-ratio: 1; border-radius: 6px; cursor: pointer; background: #4a4033; overflow: hidden';
plan.title = 'Site plan: click a piece to swing at it';
planBox.append(plan);
pageLayout().info.append(planBox);
const planScale = PLAN_PX / (2 * PLAN_HALF);
const hexColor = (c: number): string => `#${c.toString(16).padStart(6, '0')}`;
/** Draws the site plan (see above). */
function drawPlan(): void {
  const cx = PLAN_PX / 2;
  const X = (x: number): string => (cx + x * planScale).toFixed(1),
    Z = (z: number): string => (cx + z * planScale).toFixed(1);
  // A block SVG: an inline one sits on a text line whose descent overflowed the plan by a few pixels.
  const out: string[] = [`<svg width="100%" height="100%" viewBox="0 0 ${PLAN_PX} ${PLAN_PX}" style="display: block" aria-hidden="true">`];
  for (const r of RADIUS_RANGE)
    out.push(`<circle cx="${cx}" cy="${cx}" r="${r * planScale}" fill="none" stroke="rgba(255,255,255,0.25)" stroke-dasharray="4 4"/>`);
  const P = shell.world.components.Position;
  for (const p of handles.pieces) {
    if (!isAlive(shell.world, p.body)) continue;
    const fill = p.body === lit ? '#ffe08a' : hexColor(p.fallen ? darken(COLORS[p.kind], 0.45) : COLORS[p.kind]);
    const size = p.fallen ? 3 : 5;
    out.push(
      `<rect x="${X(P.x[p.body]! - size / 2 / planScale)}" y="${Z(P.z[p.body]! - size / 2 / planScale)}" width="${size}" height="${size}" fill="${fill}"/>`,
    );
  }
  // The concrete shields: grey bars their length.
  const O = shell.world.components.Orientation;
  for (const b of handles.shields) {
    const yaw = 2 * Math.atan2(O.y[b]!, O.w[b]!),
      ex = SHIELD_HALF[0] * Math.cos(yaw),
      ez = -SHIELD_HALF[0] * Math.sin(yaw);
    out.push(
      `<line x1="${X(P.x[b]! - ex)}" y1="${Z(P.z[b]! - ez)}" x2="${X(P.x[b]! + ex)}" y2="${Z(P.z[b]! + ez)}" stroke="#9c9a94" stroke-width="3"/>`,
    );
  }
  const c = handles.crane;
  out.push(
    `<line x1="${X(-2.6 * Math.cos(c.angle))}" y1="${Z(2.6 * Math.sin(c.angle))}" x2="${X(JIB_LENGTH_OUT * Math.cos(c.angle))}" y2="${Z(-JIB_LENGTH_OUT * Math.sin(c.angle))}" stroke="${hexColor(COLORS.mast)}" stroke-width="3"/>`,
    `<rect x="${cx - 4}" y="${cx - 4}" width="8" height="8" fill="#9a9a94"/>`,
  );
  const [hx, , hz] = hookPosition(c);
  out.push(`<rect x="${X(hx - 3 / planScale)}" y="${Z(hz - 3 / planScale)}" width="6" height="6" fill="${hexColor(COLORS.hook)}"/>`);
  out.push(
    `<circle cx="${X(P.x[handles.ball]!)}" cy="${Z(P.z[handles.ball]!)}" r="${BALL_RADIUS * planScale + 1}" fill="${hexColor(COLORS.ball)}"/>`,
  );
  if (aimed !== 0 && isAlive(shell.world, aimed))
    out.push(`<circle cx="${X(P.x[aimed]!)}" cy="${Z(P.z[aimed]!)}" r="8" fill="none" stroke="#ffd166" stroke-width="2"/>`);
  const aimPiece = aiming.piece || aiming.armed;
  if (aimPiece !== 0 && isAlive(shell.world, aimPiece)) {
    const length = 1.2 + 3.5 * aiming.power,
      ux = Math.cos(aiming.direction),
      uz = Math.sin(aiming.direction);
    const tx = P.x[aimPiece]!,
      tz = P.z[aimPiece]!;
    out.push(
      `<line x1="${X(tx - (length + 0.9) * ux)}" y1="${Z(tz - (length + 0.9) * uz)}" x2="${X(tx - 0.5 * ux)}" y2="${Z(tz - 0.5 * uz)}" stroke="#ffd166" stroke-width="3"/>`,
      `<circle cx="${X(tx)}" cy="${Z(tz)}" r="6" fill="none" stroke="#ffd166" stroke-width="2"/>`,
    );
  }
  out.push('</svg>');
  plan.innerHTML = out.join('');
}
plan.addEventListener('click', (event) => {
  const box = plan.getBoundingClientRect();
  const perM = (planScale * box.width) / PLAN_PX;
  const x = (event.clientX - box.left - box.width / 2) / perM,
    z = (event.clientY - box.top - box.height / 2) / perM;
  const P = shell.world.components.Position;
  let best = 0,
    bestD = 1.2;
  for (const p of handles.pieces) {
    if (p.fallen || !isAlive(shell.world, p.body)) continue;
    const d = Math.hypot(P.x[p.body]! - x, P.z[p.body]! - z);
    if (d < bestD) {
      bestD = d;
      best = p.body;
    }
  }
  // As a tap on the piece in the scene: the first arms it, a second swings along its arrow.
  if (best !== 0) {
    beginAim(best, 0, 0);
    releaseAt(0, 0);
  } else if (Math.hypot(x, z) <= RADIUS_RANGE[1]) {
    handles.controls.moves = [];
    next.piece = 0;
    handles.controls.goal = [x, z];
    aimed = 0;
  }
});

// A plain hint over the scene of what a tap does: shown until the level's first swing, and for
// HINT_SHOWN s after a tap on open ground (which moves the hook, not the ball).
const hint = document.createElement('div');
hint.dataset.hud = 'tap-hint';
hint.dataset.sceneOverlay = '';
hint.setAttribute('role', 'status');
hint.style.cssText =
  'position: absolute; left: 0; right: 0; top: 10px; margin: 0 auto; width: fit-content; max-width: 90%; padding: 6px 12px; border-radius: 16px; background: rgba(16, 20, 28, 0.78); color: #ffe08a; font: 600 15px/1.3 system-ui, sans-serif; text-align: center; pointer-events: none; z-index: 2';
pageLayout().stage.append(hint);

/**
 * Over the scene while paused: a dimmed view and the word (game-kit's), so a pause is not missed. It
 * lets pointer events through: a swing may still be aimed while paused (P or ▶ resumes).
 */
const pauseOverlay = createDomPauseOverlay(pageLayout().stage);

/**
 * The legend led by the moves that matter (dragging a target, turning the crane, steadying the
 * ball), the rest (the shell's P, N, R, the hook's and the camera's controls) folded under a
 * summary that says what is in it: a newcomer reads three lines, not twelve, and the crane's keys
 * are shown too, not hidden behind the drag alone.
 */
function foldLegend(): void {
  const legend = shell.hud.legend;
  const lines = [...legend.children].filter((e): e is HTMLElement => e instanceof HTMLElement && e.tagName === 'DIV');
  const lead = [/drag a target/i, /turn the crane/i, /stop the ball swinging/i].flatMap((re) => {
    const line = lines.find((e) => re.test(e.textContent ?? ''));
    return line ? [line] : [];
  });
  if (lead.length === 0) return;
  const more = document.createElement('details');
  more.dataset.hud = 'more-controls';
  const summary = document.createElement('summary');
  summary.textContent = 'more: hook, camera, pause';
  summary.style.cssText = 'cursor: pointer; margin: 4px 0 2px; color: #cfd8e6;';
  more.append(summary);
  for (const e of lines) if (!lead.includes(e)) more.append(e);
  legend.prepend(...lead);
  legend.append(more);
}
foldLegend();
const compactStyle = document.createElement('style');
compactStyle.textContent =
  '[data-hud="tap-hint"].compact { top: 4px !important; padding: 2px 8px !important; font-size: 12px !important; line-height: 1.25 !important; max-width: 80% !important; border-radius: 10px !important; }' +
  '[data-hud="tap-hint"].one-line { white-space: nowrap; overflow: hidden; text-overflow: ellipsis; }' +
  // On a desktop the status line (swings left, blocks down) reads at a glance, where the kit's 12 px
  // monospace in its thin bar goes unnoticed; a phone keeps the small type its three lines need. The
  // bar keeps its height (19 px of text + 6 of padding): the scene's framing is measured on it.
  `@media (min-width: ${COMPACT_MAX_WIDTH}px) and (min-height: ${COMPACT_MAX_HEIGHT}px) { [data-hud="wrecking-ball"] { font: 600 16px/1.2 system-ui, sans-serif; padding: 3px 10px !important; } }`;
document.head.append(compactStyle);
/** A short message over the scene saying what a tap did (re-aimed or refused), until world time `until`. */
const notice = { text: '', until: -1 };
/** Seconds a notice stays. */
const NOTICE_SHOWN = 2.5;
/** Says `text` over the scene for NOTICE_SHOWN s. */
function say(text: string): void {
  notice.text = text;
  notice.until = shell.world.time + NOTICE_SHOWN;
}
/** L before the level is cleared: a low tone, and the hint says what clearing it needs. */
function notCleared(): void {
  sound.chime(220, 0.2);
  if (reachedAt >= 0) say('Level cleared: its score is being counted as the last blocks fall');
  else say(`Clear the level first: ${clearTarget(handles.pieces, handles.level) - fallenCount(handles.pieces)} more down needed`);
}
/** Seconds a hint after a tap on open ground stays. */
const HINT_SHOWN = 3;
/** World time until which the open-ground hint shows. */
let hintUntil = -1;
const tapWord = touch ? 'Tap' : 'Click';
/**
 * Whether the intro is drawn compact within the strip over the scene's top the framing keeps clear
 * of the site (FRAME_TOP: 11 % of the height, 74 px of a 390 x 844 phone's scene): a phone held
 * upright. Its full two sentences in the hint's large type took four lines (100 px) and covered
 * the mast's top and the jib.
 */
function introRoom(): boolean {
  return touch && SMALL_SCREEN && PORTRAIT;
}
/** The intro's first words (a phone's whole intro after INTRO_FULL s). */
const INTRO_LEAD = 'Drag back from a block and let go';
/** Seconds of a level's world time the full intro shows on a phone before it shrinks to one line (see hintText). */
const INTRO_FULL = 6;
/** The pull being aimed in words: its power and the ball's speed at the piece it gives (./scene swingSpeed). */
function pullWords(): string {
  return `${powerWords(aiming.power)}, ${swingSpeed(aiming.power).toFixed(1)} m/s`;
}
/**
 * Whether the hint says a held drag's aim in one short line: on a phone, where the full sentences
 * took three lines of large type over the top of the scene the player aims into.
 */
function aimInOneLine(): boolean {
  return touch && SMALL_SCREEN && aimHint(true) !== null;
}
/**
 * The hint while a drag is held (the ball pulled by hand, or a swing being aimed at a piece), or
 * null with none held; in a few words when `short` (one line of a phone's compact hint), else the
 * full sentences with the pull's power and speed.
 */
function aimHint(short: boolean): string | null {
  if (drag.body !== 0 && drag.body === handles.ball) {
    if (swingMeets !== 0) return short ? 'Let go: into the red ring' : 'Let go: the ball swings along the dashes into the red ring';
    // Swinging over everything: the hook is too high for the ball to pass low.
    if (swingLow > LOW_SWING + 0.6)
      return short
        ? 'Swings high: lower the hook (Down)'
        : `The ball swings high: lower the hook (${touch ? 'Down' : 'E'}) to swing it low`;
    return short ? 'Pull so the dashes cross a block' : 'Pull so the bright dashes cross a block, then let go';
  }
  if (aiming.piece === 0 || !aiming.dragged || cleared) return null;
  if (onRun()) return short ? 'Let go: next swing after this one' : 'Let go to aim the next swing: it goes as soon as this one has hit';
  if (handles.controls.moves.length > 0 && aimed !== 0)
    return short ? 'Let go to re-aim (no swing used)' : `Winding up… let go to re-aim this swing (no swing used): ${pullWords()}`;
  // What the swing drawn in 3D shows (drawSwingPreview): a miss, or another structure in the way,
  // said before the swing is used.
  if (preview.meet === 0)
    return short ? 'Would miss: pull another way' : `The ball would miss: its dashes reach no block. Pull another way (${pullWords()})`;
  if (!sameStructure(preview.meet, aiming.piece))
    return short
      ? `Meets ${pieceName(preview.meet)} first (red ring)`
      : `The ball meets ${pieceName(preview.meet)} first (red ring): let go to hit it, or pull another way`;
  if (short) return `Let go: ${pullWords()}`;
  return `Let go: the ball swings along the dashes into the red ring: ${pullWords()}${aiming.power >= FULL_POWER_SHOWN ? '' : ', pull longer for more'}`;
}
/** The hint's text now ('' hides it); once the level is cleared, the level's end in large type. */
function hintText(): string {
  const c = handles.controls;
  const aim = aimHint(aimInOneLine());
  if (aim !== null) return aim;
  if (cleared) {
    // The level's end, over the scene as the other games say it (the status line says it small);
    // once the player swings on, that those swings are for fun and the result stands.
    if (swingsUsed() > clearedWith.swings || clearedWith.tapped)
      return `${clearedBanner()}\nSwinging for fun: the result stands. ${touch ? 'Tap' : 'Press L or'} Level ${handles.level + 1} ▶`;
    return clearedBanner();
  }
  if (shell.world.time < notice.until) return notice.text;
  // Settling: the count goes on as the wreckage comes down; the end card waits for it.
  if (reachedAt >= 0)
    return `Target reached! ${fallenCount(handles.pieces)} down${falling > 0 ? ` · settling: ${falling} still moving` : ' · settled'}`;
  if (outOfSwings()) return '';
  if (aiming.armed !== 0)
    return touch
      ? `Drag back from ${pieceName(aiming.armed)} or from any open ground to aim: the ball flies along the arrow. Tap it again to swing as shown`
      : `Drag back from ${pieceName(aiming.armed)} to aim: the ball flies along the arrow, harder the longer the pull. ${tapWord} it again to swing as shown`;
  if (shell.world.time < hintUntil) return `That moves the hook. Drag back from a block and let go to swing the ball at it`;
  // With how three stars are earned: the clear target in par swings, which no single structure
  // holds (level 1, layout 1: 16 down, its structures 5, 10 and 12 pieces), so each swing has to topple one of the big ones.
  if (c.released === 0 && c.moves.length === 0 && aimed === 0) {
    // On a phone the intro is three compact lines over the sky the framing leaves (see introRoom):
    // after INTRO_FULL s it shrinks to one line.
    if (PORTRAIT && shell.world.time > INTRO_FULL) return INTRO_LEAD;
    const stars = `★★★: ${clearTarget(handles.pieces, handles.level)} down in ${swingPar(handles.level)} swings: ${levelTip(handles.level)}`;
    if (introRoom()) return `${INTRO_LEAD}\n${stars}`;
    return `${INTRO_LEAD}: the ball swings into it along the arrow\n${stars}`;
  }
  return '';
}

/**
 * Shows `text` in the hint over the scene ('' hides it): each line ('\n') a line of its own, the
 * first in large type when `big` (the level's end), the others at the hint's size (smaller on a
 * small screen at the level's end).
 */
function showHint(text: string, big: boolean): void {
  hint.style.display = text ? '' : 'none';
  if (hint.dataset.text === text && hint.dataset.big === String(big)) return;
  hint.dataset.text = text;
  hint.dataset.big = String(big);
  hint.replaceChildren(
    ...text.split('\n').map((line, i) => {
      const el = document.createElement('div');
      el.textContent = line;
      if (i === 0 && big) el.style.fontSize = '24px';
      // The score's breakdown and the stars' rule each on one line of a phone's narrow banner.
      else if (big && SMALL_SCREEN) el.style.fontSize = '13px';
      return el;
    }),
  );
}

let frames = 0;
/** Whether the next frame swaps the scene's materials for the quality (see swapMaterials): the first, and the first of each world. */
let swapDue = true;
/** World time the last swing's run ended (the result is counted 1.5 s later), or -1. */
let runEndedAt = -1;
/** Height, m, of a block's centre above which a swing at it that brings down 2 or fewer says to aim lower. */
const HIGH_AIM = 1.2;
/** Counts the last swing's result ("Hit at S m/s! N down" or a miss) for the status line; its marks go. */
function countResult(): void {
  const down = fallenCount(handles.pieces) - swing.downBefore;
  // A swing struck high (the ball strikes the block aimed at, see ./scene aimAt) that brought down
  // little: the line says where the skill lies.
  const high = aimed !== 0 && isAlive(shell.world, aimed) && (handles.pieces.find((p) => p.body === aimed)?.y0 ?? 0) > HIGH_AIM;
  const at = swing.speed > 0 ? ` at ${swing.speed.toFixed(1)} m/s` : '';
  const missed = nearest.pass !== null ? missWords(nearest.pass, pieceName(aimed), touch ? 'Down' : 'E') : 'Missed: tap it again';
  // The status line keeps a miss's first sentence; the whole, with its hint, is said over the
  // scene (in the status line alone a miss went unseen).
  swing.result = down > 0 ? `Hit${at}! ${down} down${down <= 2 && high ? ': aim lower to topple more' : ''}` : missed.split('. ')[0]!;
  if (down === 0) say(missed);
  swing.resultAt = shell.world.time;
  swing.pending = false;
  runEndedAt = -1;
  aimed = 0;
}
/** How long a swing's result stays in the status line, s. */
const RESULT_SHOWN = 3;
const hookAt = new Float64Array(3);
/** World time of the last frame, s (effects advance by the world's time, so a pause stops them). */
let lastFrameTime = 0;
function frame(): void {
  updateControls();
  pauseOverlay.update(shell.paused, touch);
  if (swapDue) {
    swapDue = false;
    swapMaterials();
  }
  // A new canvas size (a phone turned, a window resized), framed again unless the player moved the
  // camera; not for a few pixels (the status line wrapping onto another line), which would shift the
  // view under the player's finger.
  if (
    framedSize !== null &&
    (Math.abs(app.canvas.clientWidth - framedSize[0]) > 0.1 * framedSize[0] ||
      Math.abs(app.canvas.clientHeight - framedSize[1]) > 0.1 * framedSize[1])
  )
    frameAgain();
  const dt = Math.min(0.1, Math.max(0, shell.world.time - lastFrameTime));
  lastFrameTime = shell.world.time;
  // Pieces that have just fallen: the points of those that fell together rise over them as one popup.
  const P = shell.world.components.Position;
  for (const p of handles.pieces) {
    if (!p.fallen || popped.has(p.body) || !isAlive(shell.world, p.body)) continue;
    popped.add(p.body);
    tally.add(P.x[p.body]!, P.y[p.body]! + 0.9, P.z[p.body]!, p.points, shell.world.time);
  }
  for (const t of tally.due(shell.world.time)) effects.popup(t.x, t.y, t.z, `+${t.points}`);
  effects.update(dt, app.camera);
  const c = handles.crane;
  // Jib: along the slew direction through the mast top, reaching RADIUS_RANGE[1] + 2 out and 2 back.
  const ca = Math.cos(c.angle),
    sa = Math.sin(c.angle);
  const mid = (RADIUS_RANGE[1] + 2 - 2) / 2;
  jib.position.set(mid * ca, JIB_HEIGHT + 0.2, -mid * sa);
  jib.rotation.set(0, c.angle, 0);
  counterweight.position.set(-2.6 * ca, JIB_HEIGHT - 0.35, 2.6 * sa);
  counterweight.rotation.set(0, c.angle, 0);
  placeTies(c.angle);
  cab.position.set(0.2 * ca, JIB_HEIGHT - 0.6, -0.2 * sa);
  cab.rotation.set(0, c.angle, 0);
  if (groundShadows.visible) placeGroundShadows();
  const hp = renderer.drawnPosition(handles.trolley, hookAt) ?? hookPosition(c);
  drawChain(hp);
  drawTagline();
  if (renderer.drawnPosition(handles.ball, ballAt)) {
    placeCues(ballAt, hp);
    outlineBehindMast(ballAt);
  }
  followAction();
  cablePositions[0] = hp[0]!;
  cablePositions[1] = JIB_HEIGHT;
  cablePositions[2] = hp[2]!;
  cablePositions[3] = hp[0]!;
  cablePositions[4] = hp[1]! + 0.2;
  cablePositions[5] = hp[2]!;
  cableGeometry.attributes.position!.needsUpdate = true;
  const goal = handles.controls.goal;
  // (A swing let go while the tagline still draws the ball back is on its way too.)
  const swinging =
    (handles.controls.moves.length > 0 || handles.controls.pull?.letGo === true) && aimed !== 0 && isAlive(shell.world, aimed);
  goalMarker.visible = goal !== null || swinging;
  // A swing's ring is wide enough to show round the foot of a tower or a crib.
  goalMarker.scale.setScalar(goal === null && swinging ? 2.6 : 1);
  aimArrow.visible = swinging;
  if (!swinging && lit !== 0 && lit !== aiming.armed) light(0);
  drawAim();
  drawSwingPreview();
  if (goal !== null) goalMarker.position.set(goal[0], 0.02, goal[1]);
  else if (swinging) {
    const P = shell.world.components.Position;
    // Over the top of whatever stands on the piece (an arrow at a tower's middle block would be inside it).
    const tx = P.x[aimed]!,
      tz = P.z[aimed]!;
    let top = 0;
    for (const q of handles.pieces)
      if (Math.hypot(P.x[q.body]! - tx, P.z[q.body]! - tz) < 1.3) top = Math.max(top, P.y[q.body]! + Math.max(...q.half));
    // Sliding from a re-aimed swing's old target (eased), else on the target.
    const f = slide.at < 0 ? 1 : Math.min(1, (shell.world.time - slide.at) / MARKS_SLIDE);
    const e = f * f * (3 - 2 * f);
    const ax = slide.x + e * (tx - slide.x),
      az = slide.z + e * (tz - slide.z);
    goalMarker.position.set(ax, 0.02, az);
    aimArrow.position.set(ax, top + 0.8 + 0.2 * Math.sin(shell.world.time * 6), az);
  }
  const faded = slide.at < 0 ? 1 : (shell.world.time - slide.at) / OLD_RING_FADES;
  oldRing.visible = faded < 1;
  if (oldRing.visible) {
    oldRing.position.set(slide.x, 0.03, slide.z);
    oldRing.scale.setScalar(2.6 * (1 - 0.4 * faded));
    (oldRing.material as MeshBasicMaterial).opacity = 0.85 * (1 - faded);
  } else slide.at = -1;
  // Once a swing's run is over, what it did: how many pieces it brought down, said for RESULT_SHOWN s.
  if (aimed !== 0 && handles.controls.moves.length === 0 && handles.controls.pull === null && swing.pending && runEndedAt < 0)
    runEndedAt = shell.world.time;
  trackNearest();
  if (runEndedAt >= 0 && shell.world.time - runEndedAt > 1.5) countResult();
  if (frames++ % 6 === 0) {
    const f = fallenCount(handles.pieces);
    const budget = swingBudget(handles.level);
    const used = swingsUsed(),
      left = budget - used;
    status.textContent = cleared
      ? `${clearedLine()} · final score ${banked + levelScore} · ${touch ? 'tap' : 'press L or'} Level ${handles.level + 1} ▶`
      : reachedAt >= 0
        ? `Level ${handles.level} · target reached! · down ${f}, ${clearTarget(handles.pieces, handles.level)} clear it · score ${banked + levelScore} (counting the fall${falling > 0 ? `: ${falling} still moving` : ''})`
        : playStatusLine(
            {
              level: handles.level,
              score: pageLayout().compact() ? banked + levelScore : null,
              left,
              budget,
              par: swingPar(handles.level),
              fallen: f,
              target: clearTarget(handles.pieces, handles.level),
              extras: [
                swingPhase(),
                swing.result && shell.world.time - swing.resultAt < RESULT_SHOWN ? ` · ${swing.result}` : '',
                left <= 0 && handles.controls.moves.length === 0 ? ` · out of swings: ${touch ? 'tap ↻' : 'press R'} to retry` : '',
                swayHint(),
              ],
            },
            pageLayout().compact(),
          );
    showNext(cleared, `Level ${handles.level + 1} ▶`);
    const text = hintText();
    showHint(text, cleared);
    // On a phone the intro, and every hint after the first swing, is compact, so it leaves the top
    // of the scene in sight (the intro within the strip the framing keeps clear: introRoom).
    const intro = text.startsWith(INTRO_LEAD);
    // While a drag is held on a phone, its aim in one compact line (aimInOneLine), clear of the scene's top.
    const oneLine = aimInOneLine();
    hint.classList.toggle('compact', touch && SMALL_SCREEN && (swingsUsed() > 0 || (introRoom() && intro) || oneLine) && !cleared);
    hint.classList.toggle('one-line', oneLine);
    drawPlan();
    readout.textContent = params.debug
      ? `score ${banked + levelScore} · step ${stepMs.toFixed(1)} ms (worst ${worstMs.toFixed(1)}) · ${handles.pieces.length} pieces`
      : `score ${banked + levelScore}`;
  }
}

/** Swing amplitude, m, over which the status line tells a player driving the crane how to stop it. */
const SWAY_HINT = 0.6;
/** While the player drives (no swing running) and the ball swings more than SWAY_HINT: how to steady it. */
function swayHint(): string {
  const c = handles.controls;
  if (c.moves.length > 0 || c.steady || (swing.result && shell.world.time - swing.resultAt < RESULT_SHOWN)) return '';
  if (swayAmplitude(shell.world, handles) < SWAY_HINT) return '';
  return touch ? ' · hold Steady to stop the swing' : ' · hold Space to steady the ball';
}

/**
 * What the crane is doing for a swing at a target, for the status line. From the release the crane
 * is already swinging the ball back to build up its swing (the hook moves at once): the line says so
 * and counts down to the hit, to a tenth of a second, rather than "winding up, swing in 2 s", which
 * read as a wait between the release and the swing.
 */
function swingPhase(): string {
  const moves = handles.controls.moves;
  // Let go while the tagline draws the ball back: the line slips as soon as the ball is in place.
  if (moves.length === 0 && handles.controls.pull?.letGo === true && handles.controls.pull.offset > 0)
    return ` · ${retargeted ? 'new target, same swing' : 'drawing the ball back'}…`;
  if (moves.length === 0) return '';
  if (moves[0]!.run) {
    retargeted = false;
    return ' · swinging!';
  }
  return ` · ${retargeted ? 'new target, same swing' : 'swinging back'}… hit in ${timeToHit(moves).toFixed(1)} s`;
}

/** Seconds until the ball reaches its target on timed moves `moves`: what is left of those before the follow-through. */
function timeToHit(moves: readonly { duration: number; elapsed: number; follow?: boolean }[]): number {
  let left = 0;
  for (const m of moves) if (!m.follow) left += m.duration - m.elapsed;
  return Math.max(0, left);
}

// ---- window.game ---------------------------------------------------------------------------

shell.expose({
  /**
   * Whether the jib is drawn solid (opaque, writing depth), as it is whichever way it points and
   * whatever it crosses on the screen: its lattice's open panels show what lies behind it.
   */
  jibSolid: (): boolean => !jib.material.transparent && jib.material.opacity === 1 && jib.material.depthWrite,
  /** Whether the jib's lattice bars are drawn at all: their alpha (1) times the material's opacity passes its alpha test. */
  jibShows: (): boolean => jib.material.opacity > jib.material.alphaTest,
  /**
   * How many boxes cast the lite quality's flattened ground shadows this frame (placeGroundShadows):
   * the pieces and the mast; 0 while drawn full (the sun's shadow map instead).
   */
  groundShadowBoxes: (): number => (groundShadows.visible ? groundShadows.boxes.count : 0),
  /** The camera's orbit target, m (it follows the ball; see followAction). */
  cameraTarget: (): number[] => (app.controls ? app.controls.target.toArray() : []),
  /** The orbit target of the site's framing the camera returns to, m (null once the player has moved the camera). */
  framing: (): number[] | null => (home ? home.target.toArray() : null),
  /** The drawn chain: its visible segments and the gap, m, between its end and the ball's surface (0 when whole). */
  chain: () => {
    const end = segmentAt[segmentAt.length - 1]!;
    const tip = new Vector3(0, 0.5, 0).applyQuaternion(end.quaternion).multiplyScalar(end.length);
    const low = end.position.clone().add(tip);
    renderer.drawnPosition(handles.ball, ballAt);
    const gap = Math.abs(Math.hypot(low.x - ballAt[0]!, low.y - ballAt[1]!, low.z - ballAt[2]!) - BALL_RADIUS);
    return { segments: segmentShown.filter(Boolean).length, rings: ringShown.filter(Boolean).length, gap };
  },
  params,
  panel,
  drag,
  /** The scene's handles (trolley, links, ball, pieces, crane state, controls). */
  handles: (): WreckingBallHandles => handles,
  /** Total score (levels cleared plus this one). */
  score: (): number => banked + levelScore,
  /** Swings used on this level (once cleared, those that cleared it: later swings are for fun), the budget, the stars earned (0 until cleared). */
  swings: () => ({
    used: cleared ? clearedWith.swings : swingsUsed(),
    budget: swingBudget(handles.level),
    stars: cleared ? clearedWith.stars : 0,
  }),
  /** Whether this level is cleared. */
  cleared: (): boolean => cleared,
  /** Smoothed step time, ms. */
  stepTime: (): number => stepMs,
  /** A press at (ndcX, ndcY) as the mouse would: 'ball' (grabbed), 'aim' (on a piece), 'hook' (sent there) or 'none'. */
  pressAt,
  /** The press being aimed moved to (ndcX, ndcY), as the mouse would. */
  aimDrag,
  /** The press let go at (ndcX, ndcY) as the mouse would: 'swing' (along the arrow), 'armed' (a tap: the arrow shown) or 'none'. */
  releaseAt,
  /** The aim: the piece pressed or armed (0: none), whether its arrow shows, the ball's direction (rad) and the power in [0.2, 1]. */
  aim: (): { piece: number; arrow: boolean; direction: number; power: number } => ({
    piece: aiming.piece || aiming.armed,
    arrow: aimPreview.visible,
    direction: aiming.direction,
    power: aiming.power,
  }),
  /**
   * The drawn aim arrow's extent on the screen: the largest |x| and |y| (normalised device
   * coordinates) of its outline's vertices as drawn (null while it is hidden).
   */
  aimExtent: (): { x: number; y: number } | null => {
    if (!aimPreview.visible) return null;
    aimPreview.updateMatrixWorld(true);
    let x = 0,
      y = 0;
    const v = new Vector3();
    for (const mesh of [aimShaftEdge, aimHeadEdge]) {
      const pos = mesh.geometry.getAttribute('position');
      for (let i = 0; i < pos.count; i++) {
        v.fromBufferAttribute(pos, i).applyMatrix4(mesh.matrixWorld).project(app.camera);
        x = Math.max(x, Math.abs(v.x));
        y = Math.max(y, Math.abs(v.y));
      }
    }
    return { x, y };
  },
  /**
   * The swing drawn in 3D (see drawSwingPreview): whether it shows, the piece its path meets first
   * (0: none), the ball's centre where it meets it (the red ghost ball; null when it meets none),
   * where the swing starts (the pale ghost ball), m, and whether the held ball is there.
   */
  swingPreview: () => ({
    shown: swingPreview.visible,
    meet: preview.meet,
    hit: swingPreview.visible && hitGhost.visible ? hitGhost.position.toArray() : null,
    start: swingPreview.visible ? startGhost.position.toArray() : null,
    /** Whether the held ball is at the start (its ring drawn green): let go now and it swings at once. */
    ready: preview.ready,
  }),
  /** The piece the running swing is aimed at (0 when none), and whether its arrow shows. */
  aimed: (): { piece: number; arrow: boolean } => ({ piece: aimed, arrow: aimArrow.visible }),
  /**
   * While the ball is held: pulls its centre toward (x, z) across the ground, m, as a drag of the
   * pointer over the ground does (at most PULL_REACH from under the hook; the hand keeps it on its chain).
   */
  pullBall,
  /** While the ball is held: the piece its swing would meet first (ringed red), 0 when none or not held. */
  swingMeets: (): number => swingMeets,
  /** Whether the depth cues show: the ball's ground mark, and (while held) its plumb line and swing track. */
  cues: () => ({ mark: ballMark.visible, plumb: plumb.visible, track: trackDashes[0]!.visible, meets: meetRing.visible }),
  /**
   * The swing's marks now: where its ring stands (m, x and z; null when hidden) and whether the
   * re-aimed swing's old target still shows its fading ring.
   */
  marks: () => ({
    ring: goalMarker.visible ? [goalMarker.position.x, goalMarker.position.z] : null,
    old: oldRing.visible,
  }),
  /** What the last swing did, once counted ('Hit at S m/s! N down', 'Hit! N down' for a planned swing, or 'Missed: tap it again'; '' before). */
  swingResult: (): string => swing.result,
  /** The effects showing now: dust and chips in the air, score popups. */
  effects: () => effects.counts(),
  /** Shows score popup `text` rising from (x, y, z), m, as a fall does (tests). */
  popup: (x: number, y: number, z: number, text: string): void => effects.popup(x, y, z, text),
  /** The visible popups' label boxes on the screen (see SiteEffects.popupBoxes). */
  popupBoxes: () => effects.popupBoxes(),
  /** The level's end: whether the clear target is reached (settling or cleared) and how many pieces still move (./scene stillFalling). */
  settling: () => ({ reached: reachedAt >= 0, falling, cleared }),
  /** Whether a fallen piece within the site lies off the screen now (see lostPiece). */
  pieceOffScreen: (): boolean => app.controls !== null && lostPiece(app.camera.position, app.controls.target),
  /** How many times this level's framing widened to take in a piece knocked off the screen. */
  wreckageWidenings: (): number => widen.wreckage,
  /** Goes to the next level (banks the score). */
  nextLevel,
  /** The drawing quality now ('full' or 'lite'; see Quality). */
  quality: (): Quality => params.quality,
  /** Whether the ball's outline is drawn over the mast (while the mast stands between the camera and the ball). */
  ballOutlined: (): boolean => ballOutline.visible,
  /** Whether the mast stands between the camera and the ball now (see mastBetween). */
  mastHidesBall: (): boolean => {
    const P = shell.world.components.Position,
      b = handles.ball;
    return mastBetween(P.x[b]!, P.y[b]!, P.z[b]!, BALL_RADIUS);
  },
  /**
   * Whether the mast is drawn solid (opaque, writing depth) as it always is: the ball, its chain and
   * the pieces behind it show through its lattice's open panels and pass behind its bars (drawn
   * faint while the ball is behind it, they would be drawn over it and look to pass through it).
   */
  mastSolid: (): boolean => {
    const m = mastLattice.material as Material;
    return !m.transparent && m.opacity === 1 && m.depthWrite;
  },
  /** Draws at quality 'full' or 'lite' from now on (as the settings panel's choice: the page no longer changes it). */
  setQuality: (q: Quality): void => {
    qualityChosen = true;
    setQuality(q);
  },
});

// ---- Back to the site's framing ------------------------------------------------------------------

/**
 * A small "⌂ view" button over the scene's bottom right corner: puts the camera back on the site's
 * framing (the level framed afresh from its side) after the player turned, panned or zoomed it.
 */
const viewButton = document.createElement('button');
viewButton.type = 'button';
viewButton.dataset.hud = 'reset-view';
// Drawn over the scene's corner on purpose (the page contract's scene-overlay mark).
viewButton.dataset.sceneOverlay = '';
viewButton.textContent = '⌂ view';
viewButton.title = 'Back to the default view';
viewButton.style.cssText =
  'position: absolute; right: 8px; bottom: 8px; z-index: 5; padding: 4px 10px; font: 600 13px system-ui, sans-serif; color: #fff; background: rgba(20, 16, 10, 0.6); border: 1px solid rgba(255, 255, 255, 0.35); border-radius: 6px; cursor: pointer; touch-action: manipulation';
// For a finger, at least 44 px tall (the touch target guidelines' least; 25 px with the text's own height).
if (touch) viewButton.style.minHeight = '44px';
viewButton.addEventListener('click', (event) => {
  event.stopPropagation();
  frameAgain();
});
{
  const host = app.canvas.parentElement ?? document.body;
  if (getComputedStyle(host).position === 'static') host.style.position = 'relative';
  host.append(viewButton);
}
