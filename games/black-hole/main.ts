/**
 * Black hole: fly the ship from the bottom to the green line at the top past black holes that pull
 * it with Newtonian gravity. Reaching the line scores 100 points times the level's number plus a
 * speed bonus (./levels.ts `levelPoints`; the classic game: one point a hole, and a hole more); the
 * points rise from where the ship crossed. Falling into a hole costs one of three lives; leaving the screen
 * puts the ship back for free. The engine spools up and down (./rules.ts THRUST_RAMP): the ship
 * leans into its thrust and the flame grows with it.
 * (Ramtal and Dobre, ch. 6; the rules are in ./rules.ts, DOM-free.)
 *
 * Keys: arrow keys thrust (two at right angles held together thrust diagonally, ./rules.ts
 * `heldThrust`; of two opposite ones the last pressed wins), Enter restarts after the
 * game is over, P pause, N single step, R reset, F predicted path on / off, V replays the run from its
 * start (./replay.ts: every input is recorded at its step; the replay ends where the run was, bit for bit;
 * waits with the ship parked are skipped; any key, or a tap on the field, leaves it for where the run was).
 * Touch: the four arrow buttons under the scene (hold to thrust, slide to steer; two fingers on two
 * arrows thrust diagonally); tap the message to restart.
 * Levels (./levels.ts): level 1 (practice: a fall costs no life; a coach beside the ship reads the
 * predicted path and says what to hold) has one hole across the straight path
 * (no arrow or two held from the start gets through on any level), levels 2 and 3 a wall of holes
 * with one gap off to the side (level 2's high up, level 3's lower with a hole above its gap), later levels more and
 * bigger holes, drifting holes and a fuel limit; clearing a level shows a summary and a button over
 * the middle of the field, and waits for Enter or a tap; the best score is kept in the browser's
 * local storage, and the game-over card over the field shows the final score and the best.
 * URL: ?level=N (start level, default 1), ?holes=N (1..16: the classic endless game with N holes
 * instead of levels), ?seed=S, ?c=C (m/s), ?thrust=A (m/s^2), ?path=0|1.
 *
 * Drawn: nebulae behind the stars; each hole as a black disc of its Schwarzschild radius with a
 * photon ring, an orange glow and a tilted disc of hot gas whose clumps go round it; the exhaust
 * (particles, additive); the ship with a flame opposite its thrust; its predicted path for the next 3 s on level 1 (the next 1-1.5 s from level 2, the full 3 s again after repeated falls: ./levels.ts `previewSeconds`; after a tap, with the
 * thrust ending where the tap's does), integrated in a small second world
 * (rules.ts `predictPath`) and drawn as fading dots, red where it falls into a hole (a ring) or leaves the
 * field (a cross at the edge: the ship would be lost), blue where it reaches the finish line, grey where it runs on mid-field, undecided (on the pad, before the first thrust, the path holding ↑ would take, 3 s of it).
 */

import {
  createActionButton,
  createButtonBar,
  createPanel,
  flagParam,
  getSound,
  isTouchDevice,
  numberCheck,
  numberParam,
  onButtonPress,
  pageLayout,
  pauseUnderDrawers,
  seedParam,
  storedValue,
} from '@bitphysics/game-kit';
import { createPauseOverlay, startPixiGame } from '@bitphysics/game-kit/pixi';
import { type PhysicsWorld, Rng, slotOf, stateHash } from '@bitphysics/physics';
import { Container, Graphics, Sprite, Text, Texture } from 'pixi.js';
import { canThrust, FULL_PATH_SECONDS, type LevelRun, levelPoints, previewSeconds, RING_RADIUS, startLevel } from './levels';
import { MAX_LEAD_STEPS, pressStartStep, releaseStep, TAP_STEPS } from './press-timing';
import { type BlackHoleReplay, createBlackHoleReplay, type GameStepEvent } from './replay';
import {
  type Arrow,
  type BlackHoleGame,
  C_GAME,
  createBlackHoleGame,
  createPredictor,
  FIELD,
  heldThrust,
  MAX_HOLES,
  type PathEnd,
  type Predictor,
  pathEnd,
  predictPath,
  type Thrust,
} from './rules';
import { velocityTick, viewBeside } from './view';
import { continueWords, nextHappening, pausedWords, type ShipHappening, touchStatusLines, waitWords } from './wait-words';

const search = new URLSearchParams(location.search);
/** Levels unless ?holes asks for the classic endless game. */
const levels = !search.has('holes');

/** The best score kept in local storage: whole points up to 1e9 (0 when none, garbled, or storage is unavailable). */
const bestStore = storedValue('bitphysics.black-hole.best', numberCheck({ max: 1e9, integer: true }), 0);
let best = bestStore.read();
/** The best score when the game in play began: a final score above it is a new best (the game-over card says so). */
let bestAtStart = best;

/** After each game step (live or replayed): keeps the best score, and shows the points a crossing made. */
function onGameStep(event: GameStepEvent): void {
  happening = nextHappening(happening, event);
  if (event === 'lost') showLost();
  if (event === 'cleared' || event === 'scored' || event === 'over') recordScore(bh.score);
  // The emptied field shows in the very next frame, even where a slow GPU has the pacer skip frames.
  if (event === 'cleared') game.drawNext();
  if (event === 'cleared' || event === 'scored') {
    scorePop.points = event === 'cleared' ? (run?.summary?.points ?? 0) : bh.score - scorePop.scoreBefore;
    scorePop.x = lastShip[0]!;
    scorePop.start = performance.now();
    // The kit's touch card (a phone played with keys never touches the stage, which would fade it)
    // sits just under the finish line there, where the "+N" rises: it goes now, the lesson done.
    const card = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
    if (card && !card.classList.contains('bp-gone')) {
      card.classList.add('bp-gone');
      setTimeout(() => card.remove(), 700);
    }
  }
  scorePop.scoreBefore = bh.score;
  // Sound (not while a replay plays the run back silently fast).
  if (event === 'fell' || event === 'over') {
    startSwallow();
    startDeath();
  }
  if (event === 'fell' || event === 'lost') restarted = event;
  if (event === 'scored') sound.chime(880);
  else if (event === 'cleared') sound.chime(1320, 0.6);
  else if (event === 'fell' || event === 'lost' || event === 'over') sound.explosion(event === 'over' ? 1 : event === 'fell' ? 0.8 : 0.6);
}
/**
 * Set by a fall or an exit: the keys and buttons held are let go, so the ship waits at the start
 * (and the message says what happened) until the player thrusts again.
 */
let restarted: 'fell' | 'lost' | '' = '';
/**
 * The last thing that happened to the ship (./wait-words.ts): the words over the field while it waits
 * at the start say this and nothing older. A new world is a new start ('level').
 */
let happening: ShipHappening = 'level';
/** `happening` when a replay began: put back when the replay is left (it stops where it was). */
let happeningBeforeReplay: ShipHappening = 'level';
/** The holes drawn (`shownHoles`) when the replay began: put back when it is left. */
let shownHolesBeforeReplay: number[] = [];
/**
 * The ready beat after a fall, ms of the wall clock: the swallow (SWALLOW_MS) and the ring closing in
 * on the new ship at the start (RESPAWN_MS), while the words say "Get ready…" and the ship is drawn
 * dim. The new ship waits at the start whatever is pressed, and a press begun in the beat (an "ok"
 * after the fall, or a key or finger still down from the flight) is dropped, not kept for later: only
 * a press begun after it thrusts. (Kept and thrust at the beat's end, such a press launched the new
 * ship by accident.) Timed by the wall clock, not by steps: after a slow frame the pacer runs a burst
 * of steps to catch up, and a beat of steps could pass in two or three drawn frames.
 */
const READY_MS = 1600;
/** The ready beat after the ship is lost off the field (no swallow to watch): the ring closing in and a little more, ms. */
const READY_LOST_MS = 1000;
/** performance.now() at which the ready beat ends, ms (0: none). */
let readyEndsAt = 0;
/** Whether the ready beat after a respawn lasts (no thrust yet; presses begun now are dropped). */
const readying = (): boolean => readyEndsAt > 0 && performance.now() < readyEndsAt;
const sound = getSound();
/** The ship's engine: hums while thrusting. */
const engine = sound.engine('propeller');

/** Keeps `score` as the best if it beats it. */
function recordScore(score: number): void {
  if (score <= best) return;
  best = score;
  bestStore.write(score);
}
const params = {
  holes: numberParam('holes', { default: 3, min: 1, max: MAX_HOLES, integer: true }),
  /** The level a new game starts at (levels only). */
  level: numberParam('level', { default: 1, min: 1, max: 99, integer: true }),
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
/**
 * Steps of the predicted path drawn ahead of the ship at most (in levels, as far as the level shows:
 * ./levels.ts `previewSeconds`, 3 s on level 1 and after repeated falls, less otherwise): 3 s, as long as the pad's. A wall of holes
 * (levels 2 and 3) pulls like a line of mass, harder than the thrust within some 6 m; a pilot that
 * flies up and steers by the path to keep it clear (scripts/black-hole-levels.mjs, reacting every
 * 0.3 s) falls in on level 2 nearly always seeing 1 s ahead, and often seeing 2 s. A 2 s path stops
 * mid-field, short of the wall's gap, and does not say whether the ship will make it; 3 s of it
 * reaches the wall from the pad.
 */
const PATH_STEPS = 180;
/**
 * Steps of the path drawn from the pad before the first thrust (the one holding ↑ would take): 3 s,
 * so on level 1 it reaches the hole across the straight climb and shows red; a 2 s path stops short
 * of that hole and is drawn blue, as if the way straight up were clear.
 */
const PAD_PATH_STEPS = 180;
const path = new Float64Array(2 * (Math.max(PATH_STEPS, PAD_PATH_STEPS) + 1));
let pathPoints = 0;
/** Points round each ring left, twice (its halo and halfway in), that the captions keep off (`drawRings`); room for 8 rings. */
const RING_DOTS = 16;
/**
 * Screen points, px, of what a caption must not cover this frame: every path dot drawn (the pad's side
 * paths too), the rings left and the ship (x0, y0, x1, y1, ...; `dotCount` of them). The coach and the path's "falls in"
 * are placed off them (`placeOffDots`).
 */
const dots = new Float64Array(2 * (PATH_STEPS + 2 * PAD_PATH_STEPS + 16 + 8 * (1 + 2 * RING_DOTS)));
let dotCount = 0;
/** Adds a point, px, to `dots` (ignored once it is full). */
function addDot(x: number, y: number): void {
  if (2 * dotCount + 1 >= dots.length) return;
  dots[2 * dotCount] = x;
  dots[2 * dotCount + 1] = y;
  dotCount++;
}
/** How many of this frame's `dots` lie in the box [l, r] x [t, b], px, widened by `pad` px each way. */
function dotsIn(l: number, t: number, r: number, b: number, pad: number): number {
  let n = 0;
  for (let i = 0; i < dotCount; i++) {
    const x = dots[2 * i]!,
      y = dots[2 * i + 1]!;
    if (x > l - pad && x < r + pad && y > t - pad && y < b + pad) n++;
  }
  return n;
}
/**
 * What covering a hole's drawing counts for in `placeOffDots`, in dots: more than a whole path's, so
 * a caption kept off the holes sits on the path's dots before it sits on a hole.
 */
const HOLE_COVER = 10_000;
/**
 * How many of the holes' drawings of the last frame (`holeExtents`: disc, ring and glow) the box
 * [l, r] x [t, b], px, widened by `pad` px each way, overlaps.
 */
function holesIn(l: number, t: number, r: number, b: number, pad: number): number {
  const cam = renderer.camera;
  let n = 0;
  for (let i = 0; i < bh.holes.length && i < holeExtents.length; i++) {
    const e = holeExtents[i];
    if (!e) continue;
    if (
      cam.toScreenX(e[1]!) > l - pad &&
      cam.toScreenX(e[0]!) < r + pad &&
      cam.toScreenY(e[2]!) > t - pad &&
      cam.toScreenY(e[3]!) < b + pad
    )
      n++;
  }
  return n;
}
/**
 * Moves `text` (its anchor as set, its size as now) to where its box covers the fewest of this frame's
 * `dots` (within 6 px), the nearest such place to (px, py), px, where it is put first: a place in a grid
 * of `step` px over the box [x0, x1] x [y0, y1], px, that holds the whole box. Where (px, py) covers
 * none it stays there. With `holes`, a hole's drawing (`holesIn`, within 6 px) counts as HOLE_COVER
 * dots, so the text goes where it covers no hole if the box has such a place.
 */
function placeOffDots(text: Text, px: number, py: number, x0: number, y0: number, x1: number, y1: number, step = 12, holes = false): void {
  const w = text.width,
    h = text.height,
    ax = text.anchor.x * w,
    ay = text.anchor.y * h;
  const covered = (l: number, t: number): number =>
    dotsIn(l, t, l + w, t + h, 6) + (holes ? HOLE_COVER * holesIn(l, t, l + w, t + h, 6) : 0);
  let bestX = px,
    bestY = py,
    best = covered(px - ax, py - ay) * 1e9;
  if (best > 0)
    for (let l = x0; l + w <= x1; l += step)
      for (let t = y0; t + h <= y1; t += step) {
        const x = l + ax,
          y = t + ay;
        // The distance first: a place farther than the best so far cannot beat it (this runs every frame).
        const far = (x - px) ** 2 + (y - py) ** 2;
        if (far >= best) continue;
        const score = covered(l, t) * 1e9 + far;
        if (score < best) [best, bestX, bestY] = [score, x, y];
      }
  text.position.set(bestX, bestY);
}
/** How the path drawn in the last frame ends (./rules.ts `pathEnd`). */
let pathKind: PathEnd = 'clear';
/**
 * Whether the path drawn in the last frame reaches the finish line. A 'clear' path that does not (it
 * runs its full 3 s mid-field) is undecided, not safe: it may still run into a hole beyond its end, so
 * it is drawn in a neutral grey (PATH_OPEN), and blue (PATH_CLEAR) only when it reaches the line.
 */
let pathReachesLine = false;
/** Colours of the predicted path: falls in or lost; reaches the line; runs on, undecided. */
const PATH_WARN = 0xff5a4a,
  PATH_CLEAR = 0x9fd3ff,
  PATH_OPEN = 0xb4b4b4;

/**
 * The field for the stage's shape: on a wide screen 32 m across and as tall as the stage allows
 * within 24 to 30 m, so the field fills it; on a phone held upright a tall 20 x 30 m one (the wide
 * field would be a band across its middle).
 */
function fieldForStage(): { width: number; height: number } {
  const stage = pageLayout().stage;
  const w = stage.clientWidth || window.innerWidth,
    h = stage.clientHeight || window.innerHeight;
  if (h > 1.2 * w) return { width: 20, height: 30 };
  return { width: FIELD.width, height: Math.min(30, Math.max(FIELD.height, Math.round((2 * FIELD.width * h) / w) / 2)) };
}
let playField = fieldForStage();
/**
 * The level the next world starts at instead of `params.level` (then cleared): set by `advance` after
 * a game over, so the player goes on from the level that ended it (with a score of 0 and three lives)
 * rather than play the levels before it again. R still starts from `params.level`.
 */
let continueLevel: number | null = null;

function createWorld(): PhysicsWorld {
  bh = createBlackHoleGame({
    seed: params.seed,
    holes: params.holes,
    gScale: params.gScale,
    c: params.c,
    thrust: params.thrust,
    // The engine's sideways build-up is the field's (./rules.ts NARROW_SIDE_RAMP on a phone's narrow
    // field: a short hold of ← or → a small nudge there, a long one as strong for its width as here).
    field: playField,
    // The classic game parks the ship on the start pad as the levels do (./levels.ts parks its own):
    // it waits there, and ↓ does not fly it off the bottom of the field.
    park: !levels,
  });
  run = levels ? startLevel(bh, continueLevel ?? params.level) : null;
  continueLevel = null;
  bestAtStart = best;
  readyEndsAt = 0;
  happening = 'level';
  predictor = createPredictor(bh);
  replay = createBlackHoleReplay(bh, run, onGameStep);
  return bh.world;
}

const game = await startPixiGame({
  title: 'Black hole',
  createWorld,
  step: () => {
    lastStepMs = performance.now();
    // A press made between two frames thrusts from its own step (`press`), and a let-go arrow's thrust
    // ends at its step (`release`): here, at a step, so each is recorded there.
    if (!replay.player) {
      startPresses();
      endTaps();
    }
    // The ready beat after a respawn is over: presses begun from now on thrust.
    if (!replay.player && readyEndsAt > 0 && performance.now() >= readyEndsAt) endReady();
    replay.step();
    if (run && !canThrust(bh, run) && held.length > 0) letGo();
    if (restarted) {
      const by = restarted;
      restarted = '';
      // Not while a replay plays: its inputs are the recorded ones.
      if (!replay.player) {
        // Keys and fingers down now were pressed for the ship just lost: they are forgotten (their
        // key-up or lift is ignored, a finger sliding on does not press), and so is every press begun
        // in the ready beat (`press`): only a press begun after it thrusts.
        keysDown.clear();
        padPointers.clear();
        readyEndsAt = performance.now() + (by === 'fell' ? READY_MS : READY_LOST_MS);
        letGo();
        applyHeld();
      }
    }
  },
  controls: [
    // On a phone the card says in one line (it fits above the finish line) what the coach of level 1
    // says (`coachLine`: "Hold ↑ to fly"), that a side arrow is tapped (on the narrow upright field a
    // long hold nears its side) and, in a player's words, the seam: a thumb between a side arrow and ↑
    // holds both (`padDirsAt`), as the coach's "Hold → and ↑" asks.
    isTouchDevice()
      ? { keys: '← ↑ → ↓', action: 'thumb between two: both', touch: 'hold ↑ to fly, tap ← →' }
      : { keys: '← ↑ → ↓', action: 'thrust: a tap nudges, a hold builds up (two at once: diagonal)', touch: 'hold, slide ← ↑ → ↓' },
    { keys: 'Enter', action: 'next level / continue from this level', touch: 'Level ▶ / Continue ↺', card: false },
    {
      keys: 'F',
      action: 'predicted path on / off (red: falls in or lost, blue: reaches the line, grey: undecided)',
      touch: 'the Path button',
      card: false,
    },
    { keys: 'V', action: 'replay this level from its start (a key or a tap leaves it)', touch: 'the Replay button', card: false },
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
        if (replay.player) {
          leaveReplay();
          return;
        }
        happeningBeforeReplay = happening;
        shownHolesBeforeReplay = shownHoles.slice();
        replay.play();
        // The replay starts from the level's start: the last fall's words and effects go at once
        // (its first frame showed "Swallowed! 2 lives left" and how to fly on).
        happening = 'level';
        death.start = -Infinity;
        swallow.active = false;
        predictor = createPredictor(bh);
        updateStatus(true);
      },
    },
  ],
  renderer: {
    view: { minX: 0, minY: 0, maxX: playField.width, maxY: playField.height },
    padding: 8,
    particles: { blend: 'add', minPixelSize: 1.5 },
  },
  app: { background: 0x020308 },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;
// On a small screen the menu and settings drawers lie over the field: the flight waits while one is
// open, and goes on when it closes (unless the player paused it).
pauseUnderDrawers(shell, { compactOnly: true });
shell.onWorldChange(() => {
  // A new world is a new start: the level's title shows again.
  bannerWorld++;
  game.drawNext();
  applyHeld();
  updateStatus(true);
});

const panel = createPanel(
  params,
  [
    // Levels lay out their own holes; the classic game (?holes=N) takes its count from the panel.
    levels
      ? {
          type: 'slider',
          key: 'level',
          label: 'start at level (restarts)',
          min: 1,
          max: 20,
          step: 1,
          onRelease: true,
          onChange: (n) => {
            params.level = Math.round(n);
            game.shell.reset();
          },
        }
      : {
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
      label: 'Gravity strength',
      min: 0.1,
      max: 5,
      step: 0.01,
      onChange: (s) => replay.input('gScale', s),
    },
    { type: 'slider', key: 'c', label: 'Speed limit (light)', min: 4, max: 30, step: 0.1, onChange: (c) => replay.input('lightSpeed', c) },
    {
      type: 'slider',
      key: 'thrust',
      label: 'Engine power',
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
/** The units of the panel's physics knobs, on hover (their labels say in a player's words what they change). */
const PANEL_UNITS: Readonly<Record<string, string>> = {
  gScale: 'G scale, × 1 m³/kg/s²: how hard the holes pull',
  c: 'light speed c, m/s: no ship flies faster; the lower it is, the wider each horizon',
  thrust: "thrust, m/s²: the engine's push",
};
for (const [key, units] of Object.entries(PANEL_UNITS)) panel.controller(key as keyof typeof params).domElement.title = units;

// ---- Input: arrow keys and touch buttons; two at right angles thrust diagonally ------------------

const KEY_DIR: Record<string, Arrow> = { ArrowUp: 'up', ArrowDown: 'down', ArrowLeft: 'left', ArrowRight: 'right' };
/**
 * Arrows held (keys and buttons), most recent last; the thrust is `heldThrust` of them: the latest
 * vertical and the latest horizontal one, a diagonal when both are held.
 */
const held: Arrow[] = [];
/**
 * How many keys and fingers hold each arrow: an arrow is let go when the last of them lifts (a
 * finger slid off ↑ onto → and a second finger put on ↑ hold ↑ and → together).
 */
const holds = new Map<Arrow, number>();
/** The arrow keys down now (a key-up without its key-down, e.g. pressed before the page had focus, is ignored). */
const keysDown = new Set<Arrow>();
/** Lets go of every arrow (after a fall or an exit the player presses again to thrust). */
function letGo(): void {
  held.length = 0;
  holds.clear();
  tapEnds.clear();
  pressStarts.clear();
}

/**
 * Each arrow's last press: the world's step count and performance.now() then, ms. A press thrusts for
 * as long as it was held by the wall clock, a short press a little longer (a tap TAP_STEPS), from the
 * step it began (./press-timing.ts `releaseStep`), so a finger's tap (down and up between two steps) still thrusts,
 * and a press pushes the ship as much on a loaded machine as on a fast one.
 */
const pressedAt = new Map<Arrow, { step: number; ms: number }>();
/** Arrows let go whose thrust runs on (a tap's, or a press's steps not run yet): the step count at which each lets go. */
const tapEnds = new Map<Arrow, number>();
/** performance.now() when the game last resumed from a pause, ms: a press's length counts from it (no game time passes paused). */
let resumedAt = 0;
/** performance.now() when the last game step ran, ms: a press's start step counts from it (`press`). */
let lastStepMs = 0;
/**
 * Arrows pressed between two frames whose thrust begins at a step not run yet (./press-timing.ts
 * `pressStartStep`): the step at which each joins `held`.
 */
const pressStarts = new Map<Arrow, number>();
/** Puts the pressed arrows whose start step has come into `held` (called at the start of every step). */
function startPresses(): void {
  if (pressStarts.size === 0) return;
  for (const [dir, at] of pressStarts) {
    if (bh.world.steps < at && at - bh.world.steps <= MAX_LEAD_STEPS) continue;
    pressStarts.delete(dir);
    const i = held.indexOf(dir);
    if (i >= 0) held.splice(i, 1);
    held.push(dir);
  }
  applyHeld();
}
/** Lets go of the let-go arrows whose steps are up (called at the start of every step). */
function endTaps(): void {
  if (tapEnds.size === 0) return;
  for (const [dir, end] of tapEnds) {
    if (bh.world.steps < end) continue;
    tapEnds.delete(dir);
    letGoOf(dir);
  }
}

/** Ends the ready beat (at the first step after it): presses begun from now on thrust. */
function endReady(): void {
  readyEndsAt = 0;
  applyHeld();
}

/**
 * Steps the thrust now runs on, for the predicted path: where every arrow thrusting is let go (a tap's
 * or a press's tail, `tapEnds`), the steps to the last of their ends, so the path shows what the press
 * will do, not a 3 s hold; Infinity while a key or finger still holds one (the path: held on).
 */
function thrustStepsLeft(): number {
  let last = 0;
  for (const dir of held) {
    const end = tapEnds.get(dir);
    if (end === undefined) return Infinity;
    last = Math.max(last, end);
  }
  return held.length === 0 ? Infinity : Math.max(0, last - bh.world.steps);
}

function applyHeld(): void {
  const allowed = (!run || canThrust(bh, run)) && !readying();
  const want = allowed ? heldThrust(held) : 'none';
  if (want !== bh.thrust) replay.input('thrust', want);
}

/**
 * Enter or a tap on the message: the next level after a clear; after the last life, a new game from
 * the level that ended it (levels) or a new classic game.
 */
function advance(): void {
  if (bh.over) {
    if (run) continueLevel = run.spec.level;
    game.shell.reset();
  } else if (run?.waiting) {
    replay.input('beginLevel');
    // V replays this level from its start, not the run from level 1.
    replay.restart();
    updateStatus(true);
    // The new level's holes are drawn in the next frame, paused or not (the status already counts them).
    game.drawNext();
  }
}
/**
 * The moment of an input event, performance.now() ms: its `timeStamp`, when the key or finger acted,
 * not when the loaded page got round to it (a long frame between a finger's down and up made a 60 ms
 * tap a 0.4 s push); now for an event without one.
 */
const eventMs = (e: Event): number => (e.timeStamp > 0 && e.timeStamp <= performance.now() ? e.timeStamp : performance.now());
/** A key or finger presses arrow `dir` at `ms` (performance.now() ms): it becomes the latest arrow held. */
function press(dir: Arrow, ms: number): void {
  // Begun in the ready beat after a respawn: dropped (its lift finds nothing held, `release`).
  if (readying() && !replay.player) return;
  // A press between two frames thrusts from the step its moment falls in (`pressStartStep`), so it
  // thrusts as at any frame rate.
  const now = bh.world.steps;
  const step = game.shell.paused || replay.player ? now : pressStartStep(now, ms, Math.max(lastStepMs, resumedAt), bh.world.dt);
  pressedAt.set(dir, { step, ms });
  // Pressed again while a tap of it thrusts on: the tap's hold becomes this press's.
  if (!tapEnds.delete(dir)) holds.set(dir, (holds.get(dir) ?? 0) + 1);
  if (step > now) {
    pressStarts.set(dir, step);
    return;
  }
  pressStarts.delete(dir);
  const i = held.indexOf(dir);
  if (i >= 0) held.splice(i, 1);
  held.push(dir);
  applyHeld();
}
/**
 * A key or finger lets go of arrow `dir`: the arrow stays held while another key or finger holds it;
 * the last one let go thrusts on to the step its length asks (`releaseStep`: a tap to TAP_STEPS
 * steps), while the game runs: paused, no game time passes and a key let go lets go at once. A press
 * begun in the ready beat after a respawn was dropped (`press`): its lift lets go of nothing.
 */
function release(dir: Arrow, ms: number): void {
  const at = pressedAt.get(dir);
  if ((holds.get(dir) ?? 0) === 1 && at && (held.includes(dir) || pressStarts.has(dir)) && !replay.player && !game.shell.paused) {
    const end = releaseStep(at.step, Math.max(0, ms - Math.max(at.ms, resumedAt)), bh.world.steps, bh.world.dt);
    if (end > bh.world.steps) {
      tapEnds.set(dir, end);
      return;
    }
  }
  letGoOf(dir);
}
/** Lets go of one hold of arrow `dir` (see `release`). */
function letGoOf(dir: Arrow): void {
  const n = holds.get(dir) ?? 0;
  if (n > 1) holds.set(dir, n - 1);
  else {
    holds.delete(dir);
    pressStarts.delete(dir);
    const i = held.indexOf(dir);
    if (i >= 0) held.splice(i, 1);
  }
  applyHeld();
}
window.addEventListener('keydown', (e) => {
  const dir = KEY_DIR[e.key];
  if (!dir || e.ctrlKey || e.metaKey || e.altKey) return;
  e.preventDefault();
  if (e.repeat || keysDown.has(dir)) return;
  keysDown.add(dir);
  press(dir, eventMs(e));
  previewWhilePaused();
});
/**
 * Leaves the replay playing (any key, a tap or click on the field, the status or the buttons under
 * it): the run is put back where it was when the replay began (./replay.ts `stop`), with nothing held.
 */
function leaveReplay(): void {
  replay.stop();
  happening = happeningBeforeReplay;
  // The dimmed holes of a cleared level are the ones shown before the replay, not the replay's last.
  shownHoles.length = 0;
  shownHoles.push(...shownHolesBeforeReplay);
  predictor = createPredictor(bh);
  keysDown.clear();
  padPointers.clear();
  letGo();
  applyHeld();
  game.drawNext();
  updateStatus(true);
}
/** The pointer whose press left a replay: its lift is not a tap on what lies under it (e.g. the next level). */
let leavingPointer: number | null = null;
// Caught before the game's and the kit's own listeners (capture on window), so the key or tap that
// leaves a replay does nothing else (no pause, no thrust, no next level).
window.addEventListener(
  'keydown',
  (e) => {
    // V is left to its own action, which leaves a replay too: the Replay button's V is sent to window,
    // where this listener may run after the action that began the replay.
    if (!replay.player || e.ctrlKey || e.metaKey || e.altKey || e.key.toLowerCase() === 'v') return;
    e.preventDefault();
    e.stopImmediatePropagation();
    leaveReplay();
  },
  { capture: true },
);
window.addEventListener(
  'pointerdown',
  (e) => {
    if (!replay.player || !(e.target instanceof Node)) return;
    const page = pageLayout();
    if (![page.stage, page.status, page.controls].some((el) => el.contains(e.target as Node))) return;
    e.preventDefault();
    e.stopImmediatePropagation();
    leavingPointer = e.pointerId;
    leaveReplay();
  },
  { capture: true },
);
/** performance.now() until which a click is the leaving press's own (see `leavingPointer`), ms. */
let leavingClickUntil = 0;
for (const type of ['pointerup', 'pointercancel'] as const)
  window.addEventListener(
    type,
    (e) => {
      if (e.pointerId !== leavingPointer) return;
      e.preventDefault();
      e.stopImmediatePropagation();
      leavingPointer = null;
      leavingClickUntil = performance.now() + 500;
    },
    { capture: true },
  );
window.addEventListener(
  'click',
  (e) => {
    if (performance.now() >= leavingClickUntil) return;
    leavingClickUntil = 0;
    e.preventDefault();
    e.stopImmediatePropagation();
  },
  { capture: true },
);
window.addEventListener('keyup', (e) => {
  const dir = KEY_DIR[e.key];
  if (!dir || !keysDown.delete(dir)) return;
  release(dir, eventMs(e));
});
window.addEventListener('blur', () => {
  keysDown.clear();
  padPointers.clear();
  letGo();
  applyHeld();
});

const style = document.createElement('style');
style.textContent = `
.bh-status { text-align: center; font: 13px/1.4 system-ui, sans-serif; color: #e8ecf1; padding: 6px 10px 2px; }
.bh-status .bh-numbers { font: 600 15px ui-monospace, Menlo, Consolas, monospace; white-space: nowrap; overflow: hidden; }
.bh-status .bh-message { color: #ffd166; min-height: 1.4em; }
/* On a phone a message wraps to one or two lines (fitMessage picks a form that fits two): two are
   kept, so the scene under it does not jump. */
@media (max-width: 600px) { .bh-status .bh-message { min-height: 2.8em; } .bh-status .bh-numbers { font-size: 13px; } }
.bh-status.over .bh-message { color: #ff8c8c; cursor: pointer; }
.bh-status.paused .bh-message { color: #fff; font-weight: 700; }
.bh-status.cleared .bh-message { color: #7ee787; cursor: pointer; font-weight: 600; }
.bh-pad button { font-size: 22px; min-width: 56px; }
/* A pressed arrow lights within its rounded corners: no square tap highlight or focus ring past them. */
.bh-pad button, .bh-extras button { -webkit-tap-highlight-color: transparent; }
.bh-pad button:focus:not(:focus-visible) { outline: none; }
/* The next-level / play-again button: over the field (placeActionButton moves it to a band no hole reaches),
   not at the stage's foot, where it covered the start pad and the ship waiting on it. */
body .bp-touchbar.bp-action { top: 40%; bottom: auto; }
/* After a game over the bar holds the game-over card beside its button (no taller than it, so the
   pair fits the band under the holes that the button alone fits), above it where the field is narrow. */
body .bp-touchbar.bp-action.bh-carded { gap: 8px; }
.bh-over-card { pointer-events: none; text-align: center; color: #e8ecf1; font: 14px/1.35 system-ui, sans-serif;
  background: rgba(8, 11, 20, 0.92); border: 1px solid #3a4560; border-radius: 12px; padding: 6px 16px;
  box-shadow: 0 4px 14px rgba(0, 0, 0, 0.45); }
.bh-over-card b { display: block; font-size: 17px; color: #ff8c8c; }
.bh-over-card .bh-final, .bh-over-card .bh-best { display: inline; }
.bh-over-card .bh-final { font-weight: 700; }
.bh-over-card .bh-best::before { content: ' · '; color: #8a94a8; font-weight: 400; }
.bh-over-card .bh-best.bh-new { color: #7ee787; font-weight: 700; }
.bh-over-card .bh-next { color: #ffd166; font-size: 13px; }
/* The touch hint at the top of the stage, over the space above the finish line: at its foot (the
   kit's place) it covered the ship waiting at the start and the path up to the first hole. */
body .bp-touch-hint { top: 6px; bottom: auto; }
/* On a phone in one line, so it fits above the finish line (\`placeTouchHint\` moves it under the
   line where it does not). */
@media (max-width: 600px) { body .bp-touch-hint { font-size: 13px; padding: 6px 10px; } }
/* On a phone a d-pad: ↑ above ↓ in the middle column, ← and → the height of both either side, so a
   thumb slides from any arrow to its neighbours without crossing a third (in one row ← ↑ ↓ →, → to ↑
   crossed ↓); on the seam between a side arrow and ↑ or ↓ it holds both (a diagonal). */
@media (pointer: coarse) {
  .bp-touchbar.bh-pad { flex: 1 1 100%; display: grid; grid-template-columns: 84px 104px 84px;
    grid-template-rows: 54px 54px; grid-template-areas: 'left up right' 'left down right';
    justify-content: center; gap: 6px 8px; padding: 2px 8px 4px; }
  .bp-touchbar.bh-pad button { min-width: 0; min-height: 0; width: 100%; height: 100%; font-size: 28px; border-radius: 14px; }
  .bp-touchbar.bh-pad button[data-dir='left'] { grid-area: left; }
  .bp-touchbar.bh-pad button[data-dir='up'] { grid-area: up; }
  .bp-touchbar.bh-pad button[data-dir='down'] { grid-area: down; }
  .bp-touchbar.bh-pad button[data-dir='right'] { grid-area: right; }
  /* A held side arrow fills from the middle outwards as its push builds up (\`--bh-fill\`, set each frame). */
  .bp-touchbar.bh-pad button.on[data-dir='right'] { background: linear-gradient(to right, #ffd166 var(--bh-fill, 0%), #c77d12 var(--bh-fill, 0%)); }
  .bp-touchbar.bh-pad button.on[data-dir='left'] { background: linear-gradient(to left, #ffd166 var(--bh-fill, 0%), #c77d12 var(--bh-fill, 0%)); }
  /* Path and Replay (F, V) in a column at the pad's right, the pad centred in the rest of the row. */
  .bp-touchbar.bh-pad { flex: 1 1 0; padding-right: 0; }
  .bp-touchbar.bh-extras { flex: 0 0 auto; display: grid; grid-template-rows: 54px 54px; gap: 6px; padding: 2px 8px 4px 0; }
  .bp-touchbar.bh-extras button { min-width: 0; min-height: 0; width: 74px; height: 100%; font-size: 15px; border-radius: 14px; padding: 0; }
}
`;
document.head.append(style);
const DIRS = ['left', 'up', 'down', 'right'] as const;
const pad = createButtonBar(
  DIRS.map((dir) => ({
    label: { left: '←', up: '↑', down: '↓', right: '→' }[dir],
    name: `thrust ${dir}`,
    // The pad's own pointer listeners (below) press and let go; these handlers are empty but make
    // each button capture its pointer, so a finger that leaves the pad still lifts on it.
    onPress: () => {},
    onRelease: () => {},
  })),
  { label: 'thrust buttons', touchOnly: false },
);
pad.element.classList.add('bh-pad');
// The keys' other actions, F (path on / off) and V (replay), as buttons beside the pad (on the
// desktop too, where the keys alone were missed).
const extras = createButtonBar(
  [
    { label: 'Path', name: 'predicted path on / off (F)', key: 'f' },
    { label: 'Replay', name: 'replay the run (V)', key: 'v' },
  ],
  { label: 'path and replay', touchOnly: false },
);
extras.element.classList.add('bh-extras');
/** Whether the Path button last showed the path on (`showPathToggle`), null before the first frame. */
let pathShown: boolean | null = null;
/**
 * Shows on the Path button whether the path is on (lit, aria-pressed), however it was switched (F,
 * the button, the panel's box), and has that frame drawn at once: paused, a slow GPU's pacing left
 * the old picture up, so the switch looked like it did nothing. Called every frame; acts on a change.
 */
function showPathToggle(): void {
  if (pathShown === params.path) return;
  pathShown = params.path;
  extras.setActive(0, params.path);
  extras.buttons[0]!.setAttribute('aria-pressed', String(params.path));
  game.drawNext();
}
for (const [i, dir] of DIRS.entries()) pad.buttons[i]!.dataset.dir = dir;
// A finger (or the mouse) held on the pad slides from arrow to arrow: the thrust follows the arrows
// under it, so the thumb steers without lifting (each button alone keeps its pointer captured and
// would go on thrusting the first way until the finger lifts). `padPointers` keeps each pointer's
// arrows now; lifting it lets them go. Each finger holds its own arrows, so two thumbs on ↑ and →
// thrust diagonally, and so does one thumb on the seam between them.
const padPointers = new Map<number, readonly Arrow[]>();
/** How far past a button's edge a finger still holds it, px: on the seam between ↑ and → it holds both. */
const PAD_SEAM = 10;
/**
 * The pad's arrows at client point (x, y), px: the arrow whose button is under it, or within
 * PAD_SEAM of it; two when the point is near both a side arrow and ↑ or ↓ (a diagonal); of two
 * opposite ones (the gap between ↑ and ↓) the nearer. Empty off the arrows.
 */
function padDirsAt(x: number, y: number): Arrow[] {
  let vertical: Arrow | null = null,
    horizontal: Arrow | null = null,
    vd = Infinity,
    hd = Infinity;
  for (const [i, dir] of DIRS.entries()) {
    const r = pad.buttons[i]!.getBoundingClientRect();
    if (r.width === 0) continue;
    // Distance from the point to the button's rectangle, px (0 inside it).
    const d = Math.hypot(Math.max(r.left - x, 0, x - r.right), Math.max(r.top - y, 0, y - r.bottom));
    if (d > PAD_SEAM) continue;
    if (dir === 'up' || dir === 'down') {
      if (d < vd) [vertical, vd] = [dir, d];
    } else if (d < hd) [horizontal, hd] = [dir, d];
  }
  return [vertical, horizontal].filter((d): d is Arrow => d !== null);
}
/** Whether two lists of arrows hold the same arrows. */
const sameDirs = (a: readonly Arrow[], b: readonly Arrow[]): boolean => a.length === b.length && a.every((d) => b.includes(d));
pad.element.addEventListener('pointerdown', (e) => {
  // The first thrust shows the player has found the controls: the touch hint goes.
  document.querySelector('[data-hud="touch-hint"]')?.classList.add('bp-gone');
  const dirs = padDirsAt(e.clientX, e.clientY);
  // A finger put down in the ready beat after a respawn holds nothing until it lifts (`press`): sliding
  // on after the beat does not launch the ship either.
  if (dirs.length === 0 || padPointers.has(e.pointerId) || (readying() && !replay.player)) return;
  padPointers.set(e.pointerId, dirs);
  for (const d of dirs) press(d, eventMs(e));
});
pad.element.addEventListener('pointermove', (e) => {
  const was = padPointers.get(e.pointerId);
  if (!was) return;
  const dirs = padDirsAt(e.clientX, e.clientY);
  // Off the arrows (between them or past the pad) the finger keeps what it held.
  if (dirs.length === 0 || sameDirs(dirs, was)) return;
  padPointers.set(e.pointerId, dirs);
  for (const d of dirs) if (!was.includes(d)) press(d, eventMs(e));
  for (const d of was) if (!dirs.includes(d)) release(d, eventMs(e));
});
const padLift = (e: PointerEvent): void => {
  const dirs = padPointers.get(e.pointerId);
  if (!dirs) return;
  padPointers.delete(e.pointerId);
  for (const d of dirs) release(d, eventMs(e));
};
pad.element.addEventListener('pointerup', padLift);
pad.element.addEventListener('pointercancel', padLift);
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
onButtonPress(message, () => advance());
/** The big next-level / play-again button over the scene. */
const setAction = createActionButton('Level 2 ▶', () => advance());
let shownAction = '';
let shownNumbers = '',
  shownMessage = '';
/**
 * The pause's words in one line ("Paused: P to resume", the kit's two lines joined as `pausedWords`
 * joins them) while they show, else '': written in the status row's message line above the field
 * (`updateStatus`), clear of the field. Drawn in the band above the finish line, they lay over the
 * top of a path that reaches the line and next to the line itself.
 */
let pauseWords = '';

/**
 * The game-over card, over the field beside the Continue / Play again button (above it on a narrow
 * field; in the button's bar, so `placeActionButton` keeps both off the holes): "Game over", the final score and the best (kept in
 * local storage), or "New best!" when the final score beat the best the game began with.
 */
const overCard = document.createElement('div');
overCard.className = 'bh-over-card';
overCard.dataset.hud = 'over-card';
const overTitle = document.createElement('b'),
  overScore = document.createElement('div'),
  overBest = document.createElement('div'),
  overNext = document.createElement('div');
overScore.className = 'bh-final';
overBest.className = 'bh-best';
overNext.className = 'bh-next';
overCard.append(overTitle, overScore, overBest, overNext);
/** Shows the game-over card while the game is over (see `overCard`), else takes it away. */
function updateOverCard(): void {
  const bar = document.querySelector<HTMLElement>('.bp-touchbar.bp-action');
  if (!bh.over || !bar) {
    if (overCard.isConnected) {
      overCard.parentElement?.classList.remove('bh-carded');
      overCard.remove();
    }
    return;
  }
  const fresh = bh.score > bestAtStart;
  const lines = ['Game over', `Final score ${bh.score}`, fresh ? `New best! (was ${bestAtStart})` : `Best ${Math.max(best, bh.score)}`];
  if (overTitle.textContent !== lines[0]) overTitle.textContent = lines[0]!;
  if (overScore.textContent !== lines[1]) overScore.textContent = lines[1]!;
  if (overBest.textContent !== lines[2]) overBest.textContent = lines[2]!;
  // What Continue does to the score (in levels; the classic game's button says "Play again").
  const next = run ? continueWords(run.spec.level, params.level, touch).card : '';
  if (overNext.textContent !== next) overNext.textContent = next;
  overNext.hidden = next === '';
  overBest.classList.toggle('bh-new', fresh);
  if (overCard.parentElement !== bar) {
    bar.prepend(overCard);
    bar.classList.add('bh-carded');
  }
}

/** The game-over line in levels: Enter goes on from the level lost (`advance`), R starts again from the first. */
function overMessage(m: string): string {
  if (!run || !bh.over) return m;
  return m.replace('Press Enter or R to play again.', continueWords(run.spec.level, params.level, touch).status);
}

/** The status line while a replay plays: what it is and how to leave it, by touch or keys. */
const REPLAY_LINE = {
  touch: 'Replay of your run (waits skipped). Tap to go back to where you were.',
  keys: 'Replay of your run (waits skipped). Any key or a click: back to where you were.',
};

/**
 * Writes the numbers line from `parts` (text, whether it can be left out, and a shorter form if it
 * has one; empty ones skipped) on one line: where it does not fit the status row's width (a phone's,
 * with a replay's clock or the fuel; the desktop's beside the open settings panel), the parts that
 * can go are left out, last first, then the gaps narrowed, then the short forms used, last first. A second line
 * pushed the field down under the pad during a replay.
 */
function fitNumbers(parts: ReadonlyArray<readonly [string, boolean, string?]>): void {
  const kept = parts.filter(([p]) => p !== '');
  const fits = (): boolean => numbers.scrollWidth <= numbers.clientWidth + 1;
  numbers.textContent = kept.map(([p]) => p).join('   ');
  for (let i = kept.length - 1; i >= 0 && !fits(); i--) {
    if (!kept[i]![1]) continue;
    kept.splice(i, 1);
    numbers.textContent = kept.map(([p]) => p).join('   ');
  }
  if (!fits()) numbers.textContent = kept.map(([p]) => p).join('  ');
  const texts = kept.map(([p]) => p);
  for (let i = kept.length - 1; i >= 0 && !fits(); i--) {
    if (kept[i]![2] === undefined) continue;
    texts[i] = kept[i]![2]!;
    numbers.textContent = texts.join('  ');
  }
}

/**
 * Writes the first of `lines` (longest first, ./wait-words.ts `touchStatusLines`) that fits the
 * message row in two lines, else the last: a third line pushed the field's foot under the pad.
 */
function fitMessage(lines: readonly string[]): void {
  const most = 2 * (Number.parseFloat(getComputedStyle(message).lineHeight) || 18) + 1;
  for (const line of lines) {
    message.textContent = line;
    if (message.scrollHeight <= most) return;
  }
}

/**
 * The replay's clock, s of game time: in levels the replayed attempt's own clock (from its first
 * thrust, 0 while the ship waits on the pad; at a clear the time the level's summary gives), so the
 * waits a replay skips are not counted, shown after the attempt's number (`LevelRun.attempts`) so its
 * going back to 0 at a new attempt reads as such; in the classic game (no waits skipped) the steps played.
 */
function replayClock(): number {
  if (!replay.player) return 0;
  if (!run) return replay.player.played * bh.world.dt;
  return run.parked && !run.waiting ? 0 : run.time - run.attemptStart;
}

/** The status row's right padding now, px (`keepStatusOffPanel`). */
let statusPad = -1;
/**
 * Pads the status row's right end clear of the settings panel where the panel lies over it (on the
 * desktop the panel opens over the page's top right corner and hid the end of the numbers line, "Best
 * 6" cut to "Best"): the lines are then fitted to the room left of it. Not where the panel would leave
 * the row less than half its width (a phone's drawer covers the page's width; it pauses the game).
 * @returns whether the padding changed (the lines are to be fitted again).
 */
function keepStatusOffPanel(): boolean {
  const side = pageLayout().side,
    row = status.getBoundingClientRect();
  let pad = 0;
  if (side.offsetWidth > 0) {
    const r = side.getBoundingClientRect();
    if (r.top < row.bottom && row.top < r.bottom && r.left < row.right && r.left > row.left + row.width / 2)
      pad = Math.ceil(row.right - r.left + 8);
  }
  if (pad === statusPad) return false;
  statusPad = pad;
  status.style.paddingRight = pad > 0 ? `${pad}px` : '';
  return true;
}

function updateStatus(force = false): void {
  if (keepStatusOffPanel()) force = true;
  // The classic game's hole count follows the field (a crossing adds a hole).
  if (!levels && params.holes !== bh.holes.length && bh.holes.length > 0) {
    params.holes = bh.holes.length;
    panel.refresh();
  }
  const lives = `Lives ${'♥'.repeat(bh.lives)}${'♡'.repeat(Math.max(0, bh.params.lives - bh.lives))}`;
  // The parts of the numbers line, the ones it can go without (for `fitNumbers`) marked.
  const parts: Array<[string, boolean, string?]> = run
    ? [
        [`Level ${run.spec.level}`, false, `L${run.spec.level}`],
        [lives, replay.player !== null],
        // The holes on the field (none while the next level waits to begin).
        [run.waiting ? '' : `Holes ${bh.holes.length}`, true],
        // The rings flown through (the line counts once all are).
        [run.waiting || run.rings.length === 0 ? '' : `Ring ${run.ringsTaken}/${run.rings.length}`, false],
        [`Score ${bh.score}`, false, `★${bh.score}`],
        [`Best ${Math.max(best, bh.score)}`, true],
        // In a replay the fuel may go (then the lives) so the replay's clock fits a phone's line.
        [Number.isFinite(run.fuelLeft) ? `Fuel ${run.fuelLeft.toFixed(1)} s` : '', replay.player !== null],
      ]
    : [
        [lives, false],
        [`Score ${bh.score} (1 a hole)`, false],
        [`Holes ${bh.holes.length}`, true],
      ];
  if (replay.player) {
    const clock = `${replayClock().toFixed(1)} s`,
      attempt = run ? Math.max(1, run.attempts) : 0;
    parts.push([`▶ Replay ${run ? `attempt ${attempt} · ` : ''}${clock}`, false, `▶ ${run ? `#${attempt} · ` : ''}${clock}`]);
  }
  const n = parts.map(([p]) => p).join('|');
  if (force || n !== shownNumbers) {
    shownNumbers = n;
    fitNumbers(parts);
  }
  // While a replay plays, the line says how to leave it (`leaveReplay`) instead of the run's messages.
  const said = replay.player ? (touch ? REPLAY_LINE.touch : REPLAY_LINE.keys) : pauseWords || bh.message;
  if (force || said !== shownMessage) {
    shownMessage = said;
    status.classList.toggle('paused', pauseWords !== '' && !replay.player);
    // The rules speak of keys; on a touch screen a tap does the same, and a clear's line is shortened
    // as far as it must to keep to the two lines the status row holds (`fitMessage`).
    if (replay.player || pauseWords) message.textContent = said;
    else if (!touch) message.textContent = overMessage(bh.message);
    else fitMessage(touchStatusLines(overMessage(bh.message)));
  }
  status.classList.toggle('over', bh.over);
  status.classList.toggle('cleared', !bh.over && (run?.waiting ?? false));
  // A big button over the scene says what comes next: the next level, or a new game.
  const next = bh.over
    ? run
      ? `Continue from level ${run.spec.level} ↺`
      : 'Play again ↺'
    : run?.waiting
      ? `Level ${run.spec.level} ▶`
      : '';
  if (next !== shownAction) {
    shownAction = next;
    setAction(next !== '', next || undefined);
  }
  updateOverCard();
  // Every frame, not only when the thrust changes: a button also lights and darkens itself under
  // its own finger. Lit: the arrows a key or finger holds now (a diagonal lights both), not a let-go
  // arrow's thrust running on (a tap's): lit after the finger lifted, it looked stuck. A replay lights
  // the thrust it plays.
  const lit = (replay.player ? bh.thrust : heldThrust(held.filter((d) => !tapEnds.has(d)))).split('-');
  for (const [i, dir] of DIRS.entries()) pad.setActive(i, lit.includes(dir));
  // A lit side arrow fills from its inner edge as its push builds up: on a narrow field with a top
  // sideways speed, the share of it the ship flies at along the arrow; else the engine's sideways
  // share of full thrust. Full: nothing more to gain by holding.
  const side = Math.sign(bh.thrustVec[0]);
  const vx = bh.world.components.Velocity.x[slotOf(bh.ship)]!;
  const built =
    bh.params.sideSpeed < Infinity
      ? (side === 0 ? 0 : side * vx) / bh.params.sideSpeed
      : Math.abs(bh.thrustVec[0]) / (bh.params.thrust * bh.params.sideScale || 1);
  for (const [i, dir] of DIRS.entries()) {
    if (dir !== 'left' && dir !== 'right') continue;
    const on = lit.includes(dir) && side === (dir === 'right' ? 1 : -1);
    const fill = on ? Math.round(100 * Math.max(0, Math.min(1, built))) : 0;
    pad.buttons[i]!.style.setProperty('--bh-fill', `${fill}%`);
  }
}

// ---- Drawing --------------------------------------------------------------------------------------

const backdrop = new Graphics({ label: 'backdrop' });
app.stage.addChildAt(backdrop, 0);
/** A soft round glow, white at the centre to clear at the rim (a 128 px canvas), tinted per use. */
function glowTexture(): Texture {
  const c = document.createElement('canvas');
  c.width = c.height = 128;
  const g = c.getContext('2d')!;
  const grad = g.createRadialGradient(64, 64, 0, 64, 64, 64);
  grad.addColorStop(0, 'rgba(255, 255, 255, 1)');
  grad.addColorStop(0.35, 'rgba(255, 255, 255, 0.45)');
  grad.addColorStop(1, 'rgba(255, 255, 255, 0)');
  g.fillStyle = grad;
  g.fillRect(0, 0, 128, 128);
  return Texture.from(c);
}
const glow = glowTexture();
/** Nebulae behind the stars: x, y (fractions of the field), size (m) and colour. */
const NEBULAE: ReadonlyArray<readonly [number, number, number, number]> = [
  [0.22, 0.7, 16, 0x5b3fa0],
  [0.78, 0.35, 20, 0x1f6f8b],
  [0.55, 0.88, 12, 0x8a3f7a],
  [0.15, 0.2, 12, 0x2d4f9a],
];
const nebulaLayer = new Container({ label: 'nebulae' });
const nebulaSprites = NEBULAE.map(([, , , color]) => {
  const sprite = new Sprite({ texture: glow, anchor: 0.5, blendMode: 'add', tint: color, alpha: 0.22 });
  nebulaLayer.addChild(sprite);
  return sprite;
});
app.stage.addChildAt(nebulaLayer, 1);
/** Keeps the nebulae inside the field (they are larger than the gaps around it). */
const nebulaMask = new Graphics({ label: 'nebula-mask' });
app.stage.addChild(nebulaMask);
nebulaLayer.mask = nebulaMask;
/** Each hole's accretion glow (additive, under the disc drawn in holesLayer). */
const holeGlowLayer = new Container({ label: 'hole-glows' });
const holeGlows: Sprite[] = [];
const holesLayer = new Graphics({ label: 'holes' });
const overlay = new Graphics({ label: 'ship-and-path' });
/** The holes, glows and discs, kept inside the field (a wall's holes reach its edges). */
const holeField = new Container({ label: 'hole-field' });
holeField.addChild(holeGlowLayer, holesLayer);
const holeMask = new Graphics({ label: 'hole-mask' });
holeField.mask = holeMask;
app.stage.addChild(holeMask, holeField, overlay);
let backdropVersion = -1;
/** Stars: x, y as fractions of the canvas, alpha (fixed, seeded); those inside the field are brighter. */
const stars = (() => {
  const rng = new Rng(7);
  const out: [number, number, number][] = [];
  for (let i = 0; i < 320; i++) out.push([rng.range(0, 1), rng.range(0, 1), rng.range(0.2, 0.8)]);
  return out;
})();

function drawBackdrop(): void {
  const cam = renderer.camera;
  if (cam.version === backdropVersion) return;
  backdropVersion = cam.version;
  backdrop.clear();
  const W = playField.width,
    H = playField.height;
  // Space beyond the field (dimmer), then the field.
  backdrop.rect(0, 0, cam.width, cam.height).fill(0x03050c);
  const fx0 = cam.toScreenX(0),
    fx1 = cam.toScreenX(W),
    fy0 = cam.toScreenY(H),
    fy1 = cam.toScreenY(0);
  for (const [sx, sy, a] of stars) {
    const px = sx * cam.width,
      py = sy * cam.height;
    const inside = px > fx0 && px < fx1 && py > fy0 && py < fy1;
    if (!inside) backdrop.circle(px, py, 0.8).fill({ color: 0xc8d4ff, alpha: 0.35 * a });
  }
  backdrop.rect(cam.toScreenX(0), cam.toScreenY(H), cam.toScreenLength(W), cam.toScreenLength(H)).fill(0x070a16);
  nebulaMask.clear().rect(cam.toScreenX(0), cam.toScreenY(H), cam.toScreenLength(W), cam.toScreenLength(H)).fill(0xffffff);
  holeMask.clear().rect(cam.toScreenX(0), cam.toScreenY(H), cam.toScreenLength(W), cam.toScreenLength(H)).fill(0xffffff);
  for (let i = 0; i < NEBULAE.length; i++) {
    const [fx, fy, size] = NEBULAE[i]!;
    const sprite = nebulaSprites[i]!;
    sprite.position.set(cam.toScreenX(fx * W), cam.toScreenY(fy * H));
    sprite.width = sprite.height = cam.toScreenLength(size);
  }
  for (const [sx, sy, a] of stars) {
    const px = sx * cam.width,
      py = sy * cam.height;
    if (px > fx0 && px < fx1 && py > fy0 && py < fy1) backdrop.circle(px, py, 0.9).fill({ color: 0xffffff, alpha: a });
  }
  // The field's edge, plain to see: leaving the field puts the ship back at the start.
  backdrop.rect(cam.toScreenX(0), cam.toScreenY(H), cam.toScreenLength(W), cam.toScreenLength(H)).stroke({ width: 3, color: 0x6a83b8 });
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

/**
 * Whether the predicted path's first `n` points fly through every ring left, in order (true without
 * rings).
 */
function ringsOnPath(n: number): boolean {
  if (!run) return true;
  let taken = run.ringsTaken;
  for (let i = 0; i < n && taken < run.rings.length; i++) {
    const [rx, ry] = run.rings[taken]!;
    if (Math.hypot(path[2 * i]! - rx, path[2 * i + 1]! - ry) < RING_RADIUS) taken++;
  }
  return taken >= run.rings.length;
}

/** The rings' colours: the next one to fly through (gold), one taken (green). */
const RING_NEXT = 0xffc845,
  RING_DONE = 0x4cff7a;

/**
 * Draws the level's rings (./levels.ts `LevelSpec.rings`): the next one gold, pulsing, with a soft
 * halo; later ones dimmer; taken ones thin and green. While one is left, the finish line is dimmed
 * (it does not count yet).
 */
function drawRings(): void {
  if (!run || run.waiting || run.rings.length === 0) return;
  const cam = renderer.camera,
    r = cam.toScreenLength(RING_RADIUS),
    pulse = 0.5 + 0.5 * Math.sin(performance.now() / 220);
  for (let i = 0; i < run.rings.length; i++) {
    const [x, y] = run.rings[i]!;
    const sx = cam.toScreenX(x),
      sy = cam.toScreenY(y);
    if (i < run.ringsTaken) {
      overlay.circle(sx, sy, r).stroke({ width: 2, color: RING_DONE, alpha: 0.55 });
      continue;
    }
    const next = i === run.ringsTaken;
    overlay.circle(sx, sy, r + 4).stroke({ width: 8, color: RING_NEXT, alpha: next ? 0.12 + 0.12 * pulse : 0.08 });
    overlay.circle(sx, sy, r).stroke({ width: 3.5, color: RING_NEXT, alpha: next ? 0.75 + 0.25 * pulse : 0.4 });
    // For the captions to keep off (`placeOffDots`): its middle, and points round its halo and halfway in.
    addDot(sx, sy);
    for (let j = 0; j < RING_DOTS; j++) {
      const a = (2 * Math.PI * j) / RING_DOTS;
      addDot(sx + (r + 8) * Math.cos(a), sy + (r + 8) * Math.sin(a));
      addDot(sx + 0.5 * r * Math.cos(a), sy + 0.5 * r * Math.sin(a));
    }
  }
  if (run.ringsTaken < run.rings.length) {
    // The line is closed: its dashes dimmed under a band of the field's colour.
    const ly = cam.toScreenY(bh.lineY);
    overlay.rect(cam.toScreenX(0), ly - 3, cam.toScreenLength(playField.width), 6).fill({ color: 0x070a16, alpha: 0.7 });
  }
}

/** Disc of hot gas around each hole: outer radius (x the horizon's), tilt (minor / major axis), turns a second. */
const DISC = { outer: 2.6, tilt: 0.32, spin: 0.35 } as const;
/** Clumps of gas drawn on each disc, carried round it. */
const CLUMPS = 14;

/** Half an ellipse (centre x, y, radii a, b) from angle t0 to t1, as a polyline, rad. */
function arc(g: Graphics, x: number, y: number, a: number, b: number, t0: number, t1: number): Graphics {
  const n = 24;
  g.moveTo(x + a * Math.cos(t0), y + b * Math.sin(t0));
  for (let i = 1; i <= n; i++) {
    const t = t0 + ((t1 - t0) * i) / n;
    g.lineTo(x + a * Math.cos(t), y + b * Math.sin(t));
  }
  return g;
}

/**
 * How far each hole's drawing reached in the last frame, m: [left, right, bottom, top] of its disc
 * and glow, the holes in order (tests: all inside the field).
 */
const holeExtents: number[][] = [];
/**
 * The same for the cleared level's holes drawn dimmed while the next level waits (none otherwise):
 * the next-level button keeps off them too (`freeBand`).
 */
const ghostExtents: number[][] = [];

/**
 * The holes drawn in the last frame that had any, m: x, y, horizon radius of each in turn. A cleared
 * level takes its holes off the field (./levels.ts) until the next begins; meanwhile these are drawn
 * dimmed (at GHOST_ALPHA) under the level's summary, so the field does not go empty round the ship.
 */
const shownHoles: number[] = [];
/** How strongly the cleared level's holes show while the next level waits (0 to 1). */
const GHOST_ALPHA = 0.3;
/** Whether the last frame drew the cleared level's holes dimmed (no live holes, a level waiting). */
let ghostHoles = false;

/**
 * Each hole, every frame: an orange glow, the far half of a tilted disc of hot gas, the horizon (a
 * black disc of the Schwarzschild radius with a thin bright photon ring), then the near half of the
 * disc across its face. Clumps of gas ride the disc, faster near the hole. The disc and the glow
 * end at the field's edges (a wall's outer holes sit half a metre from them): both shrink to the
 * room between the hole's centre and the nearest edge, so nothing is cut off at the edge.
 */
function drawHoles(world: PhysicsWorld): void {
  const cam = renderer.camera;
  holesLayer.clear();
  const P = world.components.Position;
  const t = world.time;
  if (bh.holes.length > 0) {
    shownHoles.length = 0;
    for (let i = 0; i < bh.holes.length; i++) shownHoles.push(P.x[slotOf(bh.holes[i]!)]!, P.y[slotOf(bh.holes[i]!)]!, bh.holeRadius[i]!);
  } else if (!run?.waiting || bh.over) shownHoles.length = 0;
  ghostHoles = bh.holes.length === 0 && shownHoles.length > 0;
  holeField.alpha = ghostHoles ? GHOST_ALPHA : 1;
  const n = shownHoles.length / 3;
  while (holeGlows.length < n) {
    const sprite = new Sprite({ texture: glow, anchor: 0.5, blendMode: 'add', tint: 0xff7a2a, alpha: 0.75 });
    holeGlows.push(sprite);
    holeGlowLayer.addChild(sprite);
  }
  for (let i = 0; i < holeGlows.length; i++) holeGlows[i]!.visible = i < n;
  holeExtents.length = bh.holes.length;
  ghostExtents.length = ghostHoles ? n : 0;
  for (let i = 0; i < n; i++) {
    const hx = shownHoles[3 * i]!,
      hy = shownHoles[3 * i + 1]!,
      hr = shownHoles[3 * i + 2]!;
    const x = cam.toScreenX(hx),
      y = cam.toScreenY(hy),
      r = cam.toScreenLength(hr);
    // Room to the nearest side edge of the field (the disc is wide and flat: its height is a third).
    const room = Math.max(1.05 * hr, Math.min(hx, playField.width - hx));
    const aM = Math.min(DISC.outer * hr, room),
      glowM = Math.min(3.5 * hr, room, hy, playField.height - hy);
    (ghostHoles ? ghostExtents : holeExtents)[i] = [
      hx - Math.max(aM, glowM),
      hx + Math.max(aM, glowM),
      hy - Math.max(DISC.tilt * aM, glowM),
      hy + Math.max(DISC.tilt * aM, glowM),
    ];
    const sprite = holeGlows[i]!;
    sprite.position.set(x, y);
    // The glow texture fades to nothing at its rim: 2 x glowM across.
    sprite.width = sprite.height = 2 * cam.toScreenLength(glowM);
    const a = cam.toScreenLength(aM),
      b = DISC.tilt * a;
    // Far half of the disc (behind the hole): wide dim band, then a hotter inner edge.
    arc(holesLayer, x, y, a, b, Math.PI, 2 * Math.PI).stroke({ width: 0.9 * r, color: 0xff8a3c, alpha: 0.35 });
    arc(holesLayer, x, y, 0.7 * a, 0.7 * b, Math.PI, 2 * Math.PI).stroke({ width: 0.35 * r, color: 0xffd089, alpha: 0.55 });
    clumps(x, y, a, b, r, t, false);
    holesLayer.circle(x, y, r * 1.08).fill({ color: 0xfff0d0, alpha: 0.9 });
    holesLayer.circle(x, y, r).fill(0x000000);
    // Near half, over the hole's face.
    arc(holesLayer, x, y, a, b, 0, Math.PI).stroke({ width: 0.9 * r, color: 0xff8a3c, alpha: 0.45 });
    arc(holesLayer, x, y, 0.7 * a, 0.7 * b, 0, Math.PI).stroke({ width: 0.35 * r, color: 0xffe2a8, alpha: 0.75 });
    clumps(x, y, a, b, r, t, true);
  }
}

/**
 * The disc's clumps on its near half (screen y below the centre) or far half, at time t, s. A clump at
 * a fraction u of the outer radius goes round in 1 / (DISC.spin u^-1.5) s, as Kepler's third law has it.
 */
function clumps(x: number, y: number, a: number, b: number, r: number, t: number, near: boolean): void {
  for (let k = 0; k < CLUMPS; k++) {
    const u = 0.55 + (0.45 * ((k * 7) % CLUMPS)) / CLUMPS;
    const ang = (2 * Math.PI * k) / CLUMPS + (2 * Math.PI * DISC.spin * t) / (u * Math.sqrt(u));
    const sin = Math.sin(ang);
    if (sin > 0 !== near) continue;
    holesLayer.circle(x + u * a * Math.cos(ang), y + u * b * sin, Math.max(1, 0.1 * r)).fill({ color: 0xfff2d6, alpha: near ? 0.8 : 0.35 });
  }
}

/** How far the ship leans into full sideways thrust, rad (drawn only). */
const LEAN = 0.35;
/** The ship's lean in the last frame, rad (+ clockwise on screen: leaning right). */
let shipLean = 0;

/**
 * Within EDGE_WARN m of a side (or BOTTOM_WARN m of the bottom, under the start's 1.5 m), the edge
 * glows red and a warning shows.
 */
const EDGE_WARN = 2.5,
  BOTTOM_WARN = 1;
const edgeText = new Text({
  text: '⚠ Edge: leaving the field sends you back to the start',
  style: {
    fill: 0xff8c8c,
    fontSize: 16,
    fontFamily: 'sans-serif',
    fontWeight: 'bold',
    stroke: { color: 0x000000, width: 4 },
    align: 'center',
  },
});
edgeText.anchor.set(0.5, 0);
edgeText.visible = false;
app.stage.addChild(edgeText);

/**
 * The level's title at a level's start (`drawLevelBanner`: clear of the holes, fading after
 * BANNER_MS or at the first thrust): "Level N" and its holes, white on a dark outline.
 */
const levelBanner = new Text({
  text: '',
  style: {
    fill: 0xffffff,
    fontSize: 30,
    fontFamily: 'sans-serif',
    fontWeight: 'bold',
    stroke: { color: 0x000000, width: 5 },
    align: 'center',
    lineHeight: 34,
  },
});
levelBanner.anchor.set(0.5, 0);
levelBanner.visible = false;
app.stage.addChild(levelBanner);

/**
 * What a level asks, in a few words, for the banner: its holes (all on the field) and what is new,
 * then what reaching the line is worth.
 */
function levelNews(spec: LevelRun['spec']): string {
  const n = bh.holes.length;
  const holes =
    spec.gate > 0
      ? spec.blockers > 0
        ? 'through the gap, round the hole'
        : 'find the gap in the wall'
      : spec.fork
        ? n === 1
          ? 'steer round the hole'
          : 'steer between the holes'
        : `${n} ${n === 1 ? 'hole' : 'holes'}`;
  const extra = [spec.drift > 0 ? 'drifting' : '', Number.isFinite(spec.fuel) ? `${spec.fuel} s of fuel` : ''].filter(Boolean);
  const ring = spec.rings === 0 ? '' : spec.rings === 1 ? 'through the gold ring, then ' : `through the ${spec.rings} gold rings, then `;
  return `${ring}${holes}${extra.length ? `, ${extra.join(', ')}` : ''}\n${levelPoints(spec.level, 0).level} points at the line`;
}

/** How long the level's title shows at full strength, then how long it takes to fade, ms. */
const BANNER_MS = 2200,
  BANNER_FADE_MS = 600;
/** The level start the banner is showing for (level, falls and the world: a reset is a new start) and since when (performance.now(), ms). */
const bannerShown = { key: '', since: 0 };
let bannerWorld = 0;

/**
 * Shows the banner at a level's start, for BANNER_MS and then fading over BANNER_FADE_MS, or until the
 * first thrust if that comes sooner. It sits centred in the tallest band across the field that no
 * hole's drawing reaches (`freeBand`: on a wall level the open field under the wall, so it never covers
 * the wall's gap), its letters smaller where the band is short (down to 13 px), or, where there is no
 * band at all, under the finish line.
 */
function drawLevelBanner(): void {
  // Not after a loss off the field (no fall, but its own words show: one message at a time).
  const show =
    run?.parked === true && run.attemptStart === 0 && !run.waiting && !bh.over && bh.falls === run.fallsAtStart && happening === 'level';
  if (!show || !run) {
    levelBanner.visible = false;
    bannerShown.key = '';
    return;
  }
  const key = `${bannerWorld}:${run.spec.level}:${run.fallsAtStart}`;
  const now = performance.now();
  if (bannerShown.key !== key) [bannerShown.key, bannerShown.since] = [key, now];
  const age = now - bannerShown.since;
  // Laid out while due even once faded, so the page hooks report its text and place.
  levelBanner.visible = true;
  levelBanner.alpha = age < BANNER_MS ? 1 : Math.max(0, 1 - (age - BANNER_MS) / BANNER_FADE_MS);
  const cam = renderer.camera;
  if (playField.width < FIELD.width) {
    placeCompactBanner(run.spec);
    return;
  }
  const text = `Level ${run.spec.level}\n${levelNews(run.spec)}`;
  if (levelBanner.text !== text) levelBanner.text = text;
  const size = Math.max(18, Math.min(26, cam.toScreenLength(playField.width) / 14));
  const fit = (px: number): number => {
    if (levelBanner.style.fontSize !== px) {
      levelBanner.style.fontSize = px;
      levelBanner.style.lineHeight = 1.2 * px;
    }
    return levelBanner.height;
  };
  // Wrapped to the field (a phone's is narrow).
  levelBanner.style.wordWrap = true;
  levelBanner.style.wordWrapWidth = Math.max(160, cam.toScreenLength(playField.width) - 24);
  const [top, room] = freeBand(Math.min(cam.toScreenY(0.9), cam.toScreenY(lastShip[1]!)) - shipPx - ACTION_GAP);
  let h = fit(size);
  // Smaller where the band is short (a small window), down to 13 px.
  if (room > 0 && h > room) h = fit(Math.max(13, Math.floor((size * room) / h)));
  levelBanner.position.set(cam.toScreenX(playField.width / 2), room > 0 ? top + (room - h) / 2 : cam.toScreenY(bh.lineY) + 8);
}

/**
 * The banner on the narrow upright field (a phone's, `fieldForStage`): one line, "Level N · P points", or two with the level's
 * news where they fit, 14 px (13 px where 14 does not fit the width), in the band between the field's
 * top edge and the finish line, so it never lies over the ship's path up from the pad (four lines of
 * 26 px centred on the field sat right over it). The status line above the field says the level's aim
 * in full.
 */
function placeCompactBanner(spec: LevelRun['spec']): void {
  const cam = renderer.camera;
  const width = cam.toScreenLength(playField.width) - 16;
  const top = cam.toScreenY(playField.height),
    room = cam.toScreenY(bh.lineY) - top - 4;
  const head = `Level ${spec.level} · ${levelPoints(spec.level, 0).level} points`;
  levelBanner.style.wordWrap = false;
  const fit = (text: string, px: number): boolean => {
    if (levelBanner.text !== text) levelBanner.text = text;
    if (levelBanner.style.fontSize !== px) {
      levelBanner.style.fontSize = px;
      levelBanner.style.lineHeight = 1.2 * px;
    }
    return levelBanner.width <= width && levelBanner.height <= room;
  };
  const news = levelNews(spec).split('\n')[0]!;
  const two = `${head}\n${news}`;
  if (!(fit(two, 14) || fit(two, 13) || fit(head, 14))) fit(head, 13);
  levelBanner.position.set(cam.toScreenX(playField.width / 2), top + Math.max(2, (room - levelBanner.height) / 2));
}

/** Draws the edges the ship is within EDGE_WARN m of, brighter the nearer, and shows the warning (off the holes and the path). */
function drawEdgeWarning(x: number, y: number): void {
  const cam = renderer.camera;
  const W = playField.width,
    H = playField.height;
  const near = !bh.over && !run?.waiting ? Math.min(x, W - x, (y * EDGE_WARN) / BOTTOM_WARN) : Infinity;
  edgeText.visible = near < EDGE_WARN;
  if (!edgeText.visible) return;
  const a = 0.5 + 0.5 * (1 - Math.max(0, near) / EDGE_WARN);
  const x0 = cam.toScreenX(0),
    x1 = cam.toScreenX(W),
    y0 = cam.toScreenY(H),
    y1 = cam.toScreenY(0);
  if (x < EDGE_WARN) overlay.moveTo(x0, y0).lineTo(x0, y1);
  if (W - x < EDGE_WARN) overlay.moveTo(x1, y0).lineTo(x1, y1);
  if (y < BOTTOM_WARN) overlay.moveTo(x0, y1).lineTo(x1, y1);
  overlay.stroke({ width: 6, color: 0xff4d4d, alpha: a });
  edgeText.style.wordWrap = true;
  edgeText.style.wordWrapWidth = Math.max(160, x1 - x0 - 24);
  // A quarter of the way down, or the nearest place from there that covers neither the path, the
  // ship, the rings nor a hole (centred there it sat over the hole the path was about to fall into).
  placeOffDots(edgeText, (x0 + x1) / 2, cam.toScreenY(0.75 * H), x0 + 4, y0 + 4, x1 - 4, y1 - 4, 12, true);
}

/**
 * The ship falling into a hole: for SWALLOW_MS it spirals in to the hole's centre, shrinking and
 * reddening, before it shows again at the start. Where it was comes from the last frame drawn (the
 * rules have already put it back at the start when the step reports the fall).
 */
const SWALLOW_MS = 900;
const swallow = { active: false, start: 0, hx: 0, hy: 0, dx: 0, dy: 0 };
/** The ship's position (m) in the last frame drawn. */
const lastShip = [0, 0];

/** How long the points of a crossing rise from the line, ms. */
const SCORE_POP_MS = 1600;
/**
 * The points a crossing made, shown as "+N" rising from where the ship crossed the line: the points,
 * the ship's x there (m), when (performance.now(), ms; -Infinity: none yet) and the score before it.
 */
const scorePop = { points: 0, x: 0, start: -Infinity, scoreBefore: 0 };
const scoreText = new Text({
  text: '',
  style: { fill: 0x7ee787, fontSize: 34, fontFamily: 'sans-serif', fontWeight: 'bold', stroke: { color: 0x000000, width: 5 } },
});
scoreText.anchor.set(0.5, 1);
scoreText.visible = false;
app.stage.addChild(scoreText);

/** Draws the rising "+N" of the last crossing while it lasts. */
function drawScorePop(): void {
  const age = performance.now() - scorePop.start;
  // A level's points go when the next level begins, so they never hang over the next level's wall.
  scoreText.visible = age >= 0 && age < SCORE_POP_MS && scorePop.points > 0 && (!run || run.waiting);
  if (!scoreText.visible) return;
  const cam = renderer.camera;
  const u = age / SCORE_POP_MS;
  const text = `+${scorePop.points}`;
  if (scoreText.text !== text) scoreText.text = text;
  const half = scoreText.width / 2 + 6;
  const x = Math.max(cam.toScreenX(0) + half, Math.min(cam.toScreenX(playField.width) - half, cam.toScreenX(scorePop.x)));
  // It rises 30 px from just above the line; where the line is too near the top of the stage for
  // that (a wide field's), it sinks from just below the line instead, so it is never cut off.
  const rise = 60 * u * (u - 2) * 0.5,
    line = cam.toScreenY(bh.lineY);
  const above = line - 6 - 30 - scoreText.height >= 4;
  scoreText.anchor.set(0.5, above ? 1 : 0);
  scoreText.position.set(x, above ? line - 6 + rise : line + 6 - rise);
  scoreText.alpha = u < 0.7 ? 1 : (1 - u) / 0.3;
}
function startSwallow(): void {
  const P = bh.world.components.Position;
  let best = Infinity;
  for (const h of bh.holes) {
    const d = Math.hypot(P.x[slotOf(h)]! - lastShip[0]!, P.y[slotOf(h)]! - lastShip[1]!);
    if (d < best) {
      best = d;
      swallow.hx = P.x[slotOf(h)]!;
      swallow.hy = P.y[slotOf(h)]!;
    }
  }
  if (best === Infinity) return;
  swallow.dx = lastShip[0]! - swallow.hx;
  swallow.dy = lastShip[1]! - swallow.hy;
  swallow.active = true;
  swallow.start = performance.now();
}

/** The caption at the hole while the ship spirals in ("Swallowed!"), popping up and fading with the swallow. */
const swallowText = new Text({
  text: 'Swallowed!',
  style: { fill: 0xffb070, fontSize: 30, fontFamily: 'sans-serif', fontWeight: 'bold', stroke: { color: 0x000000, width: 5 } },
});
swallowText.anchor.set(0.5, 1);
swallowText.visible = false;
app.stage.addChild(swallowText);

/**
 * Draws the swallow at `u` (0 to 1 of SWALLOW_MS), the ship drawn `k` px tall: the ship spirals in
 * 1.5 turns from at least 2.5 ship heights out (from where it touched the horizon the spiral was
 * hidden by the hole's glow), stretched along its fall and shrinking to nothing, with a fading trail;
 * a white flash at the hole, two shock rings spreading from it, and "Swallowed!" popping up over it.
 */
function drawSwallow(u: number, k: number): void {
  const cam = renderer.camera;
  const hx = cam.toScreenX(swallow.hx),
    hy = cam.toScreenY(swallow.hy);
  const d0 = Math.hypot(swallow.dx, swallow.dy) || 1,
    // Screen px per m of the start offset, widened so the spiral starts 2.5 ship heights out.
    grow = Math.max(1, (2.5 * k) / cam.toScreenLength(d0));
  const at = (v: number): [number, number] => {
    const turn = 3 * Math.PI * v,
      f = (1 - v) * grow;
    const ox = f * (swallow.dx * Math.cos(turn) - swallow.dy * Math.sin(turn)),
      oy = f * (swallow.dx * Math.sin(turn) + swallow.dy * Math.cos(turn));
    return [cam.toScreenX(swallow.hx + ox), cam.toScreenY(swallow.hy + oy)];
  };
  if (u < 0.25) overlay.circle(hx, hy, k * (0.8 + 2 * u)).fill({ color: 0xffffff, alpha: 0.7 * (1 - u / 0.25) });
  for (const lag of [0, 0.18]) {
    const w = (u - lag) / 0.8;
    if (w > 0 && w < 1)
      overlay.circle(hx, hy, k * (0.6 + 4.5 * w)).stroke({ width: 3, color: lag ? 0xffd27a : 0xff7a2a, alpha: 0.9 * (1 - w) });
  }
  // The trail: three fading ships a little behind on the spiral.
  for (const back of [0.09, 0.06, 0.03]) {
    const v = Math.max(0, u - back);
    const [tx, ty] = at(v);
    overlay.circle(tx, ty, Math.max(1, 0.18 * k * (1 - v))).fill({ color: 0xffb070, alpha: 0.5 * (1 - back / 0.1) * (1 - u) });
  }
  const [sx, sy] = at(u);
  drawShip(sx, sy, k * (1 - u) * (1 + 0.3 * Math.sin(Math.PI * Math.min(1, u * 3))), 12 * Math.PI * u, u < 0.5 ? 0xffd0a0 : 0xff6a3c);
  // The caption: pops up (scale 1.5 -> 1 in the first fifth), fades in the last quarter; above the
  // hole, or under it where the field's top is too near.
  swallowText.visible = true;
  death.caption = swallowText.text;
  const pop = u < 0.2 ? 1.5 - 2.5 * u : 1;
  swallowText.scale.set(pop);
  swallowText.alpha = u < 0.75 ? 1 : (1 - u) / 0.25;
  const top = cam.toScreenY(playField.height),
    gap = 2.2 * k;
  const bottom = cam.toScreenY(0);
  const half = swallowText.width / 2 + 4;
  const x = Math.max(cam.toScreenX(0) + half, Math.min(cam.toScreenX(playField.width) - half, hx));
  // Above the hole, or under it where the field's top is too near; and off the continue panel after
  // the last life (faded over it, the caption read as part of the panel): the other side of the hole,
  // else just past the panel's nearer edge.
  const h = swallowText.height,
    panel = actionPanelBox();
  const clear = (t: number): boolean => t >= top + 4 && t + h <= bottom - 4 && (!panel || t + h + 4 <= panel[1]! || t - 4 >= panel[3]!);
  const places = [hy - gap - h, hy + gap];
  if (panel) places.push(panel[1]! - 4 - h, panel[3]! + 4);
  const t = places.find(clear) ?? (hy - gap - h >= top + 4 ? hy - gap - h : hy + gap);
  swallowText.anchor.set(0.5, 0);
  swallowText.position.set(x, t);
}

/**
 * The next-level / continue panel's box while it shows over the field (its button and the game-over
 * card, `.bp-touchbar.bp-action`'s children), px in the canvas [left, top, right, bottom], else null.
 */
function actionPanelBox(): number[] | null {
  const bar = document.querySelector<HTMLElement>('.bp-touchbar.bp-action');
  if (!bar?.isConnected || bar.offsetHeight === 0) return null;
  const c = app.canvas.getBoundingClientRect();
  let box: number[] | null = null;
  for (const el of Array.from(bar.children) as HTMLElement[]) {
    if (el.offsetHeight === 0) continue;
    const r = el.getBoundingClientRect();
    const b = [r.left - c.left, r.top - c.top, r.right - c.left, r.bottom - c.top];
    box = box ? [Math.min(box[0]!, b[0]!), Math.min(box[1]!, b[1]!), Math.max(box[2]!, b[2]!), Math.max(box[3]!, b[3]!)] : b;
  }
  return box;
}

/** How long a fall's red flash lasts, the shake, and the words over the field, ms. */
const DEATH_FLASH_MS = 450,
  DEATH_SHAKE_MS = 400,
  DEATH_TEXT_MS = 1500;
/** The shake's largest offset, px. */
const DEATH_SHAKE_PX = 10;
/** How long the ring round the ship back at the start pulses after a fall (once the swallow is over), ms. */
const RESPAWN_MS = 700;
/**
 * A fall's effect: when it began (performance.now(), ms; -Infinity: none yet), how many have begun,
 * the strongest flash drawn since the last began (0 to 1: a frame drew it) and the caption drawn at
 * the hole since then ('' while none was).
 */
const death = { start: -Infinity, count: 0, flashPeak: 0, caption: '' };
/** Colours of the words over the field: a fall's (red), a loss off the field's (pale blue: no life lost). */
const FALL_WORDS = 0xff8c8c,
  LOST_WORDS = 0x9fd3ff;
/** The words of the last fall or loss (./wait-words.ts `waitWords`), before the pause's line is put in. */
let waitText = '';
/** The field's width, px, and the words the words' size was last fitted to (`drawDeath`). */
let deathFit = '';
/** The red flash over the field (above the holes and the ship, under the words). */
const flashLayer = new Graphics({ label: 'death-flash' });
app.stage.addChild(flashLayer);
/** The words of a fall or a loss over the field: "Swallowed!" and the lives left, or "Off the field!". */
const deathText = new Text({
  text: '',
  style: {
    fill: FALL_WORDS,
    fontSize: 22,
    fontFamily: 'sans-serif',
    fontWeight: 'bold',
    stroke: { color: 0x000000, width: 4 },
    align: 'center',
    lineHeight: 26,
  },
});
deathText.anchor.set(0.5, 0);
deathText.visible = false;
app.stage.addChild(deathText);

/** Starts a fall's effect: a red flash over the field, a shake, the words (the sound is played by `onGameStep`). */
function startDeath(): void {
  // At the swallow's start (when one plays), so the ring at the start can follow the swallow.
  death.start = swallow.active ? swallow.start : performance.now();
  death.count++;
  death.flashPeak = 0;
  death.caption = '';
  setWaitWords(FALL_WORDS);
}

/** Whether the words last put up were the ready beat's (`setWaitWords`): they change when it ends. */
let waitReady = false;
/** The colour the words were last put up in (`setWaitWords`). */
let waitColor = 0xffffff;
/** Puts the words for the last happening (`happening`) over the field, in `color` (default the colour they have). */
function setWaitWords(color = waitColor): void {
  waitReady = readying();
  waitColor = color;
  waitText = waitWords(happening, {
    lives: bh.lives,
    practice: run?.spec.practice === true,
    touch,
    missedRing: run?.missedRing === true,
    stranded: run?.stranded ?? '',
    ready: waitReady,
  });
  deathText.style.fill = color;
  deathText.text = waitText;
}

/**
 * After the ship is lost off the field (levels only: the ship then waits at the start): the words say
 * so, in pale blue (no flash, no shake: nothing was lost but the flight), until the player thrusts.
 */
function showLost(): void {
  lostAt = performance.now();
  if (run) setWaitWords(LOST_WORDS);
}
/** performance.now() of the last loss off the field, ms: its words show DEATH_TEXT_MS from then even if the player flies on at once. */
let lostAt = -Infinity;

/**
 * Whether the words of the last fall or loss stay up: after either, in levels, the new ship waits
 * parked at the start (./levels.ts `LevelRun.parked`) until the player thrusts, and the words say so
 * until then, so a player who looks at the screen late still sees what happened (not faded after
 * DEATH_TEXT_MS). Only while that fall or loss is the last thing that happened (`happening`): a level
 * begun since, or a loss after a fall, has words of its own or none.
 */
const deathWaits = (): boolean =>
  run !== null &&
  !bh.over &&
  run.parked &&
  !run.waiting &&
  bh.thrust === 'none' &&
  !replay.player &&
  (happening === 'fell' || happening === 'lost');

/**
 * Draws a fall's effect for its age: the field flashes red (fading over DEATH_FLASH_MS), the scene
 * shakes (DEATH_SHAKE_PX, dying away over DEATH_SHAKE_MS) and the words show in the field's top band
 * (fading out at the end of DEATH_TEXT_MS).
 */
function drawDeath(): void {
  const cam = renderer.camera;
  const age = performance.now() - death.start;
  flashLayer.clear();
  if (age >= 0 && age < DEATH_FLASH_MS) {
    const a = 0.5 * (1 - age / DEATH_FLASH_MS);
    death.flashPeak = Math.max(death.flashPeak, a);
    flashLayer
      .rect(cam.toScreenX(0), cam.toScreenY(playField.height), cam.toScreenLength(playField.width), cam.toScreenLength(playField.height))
      .fill({ color: 0xff2a2a, alpha: a });
  }
  if (age >= 0 && age < DEATH_SHAKE_MS) {
    const amp = DEATH_SHAKE_PX * (1 - age / DEATH_SHAKE_MS);
    app.stage.position.set(amp * Math.sin(age * 0.09), amp * Math.cos(age * 0.07));
  } else if (app.stage.position.x !== 0 || app.stage.position.y !== 0) app.stage.position.set(0, 0);
  const waits = deathWaits();
  // The ready beat's "Get ready…" becomes how to fly on when it ends.
  if (waits && waitReady !== readying()) setWaitWords();
  const lostAge = performance.now() - lostAt;
  const fresh =
    (age >= 0 && age < DEATH_TEXT_MS && (happening === 'fell' || happening === 'over')) ||
    (run !== null && happening === 'lost' && lostAge >= 0 && lostAge < DEATH_TEXT_MS);
  // Not while the ship spirals in: the caption at the hole says it then (`drawSwallow`).
  deathText.visible = (fresh || waits) && !swallow.active;
  if (!deathText.visible) return;
  // One message at a time: paused, the words say so in their last line (the pause's own words are
  // hidden, `drawFrame`), in place of how to fly on.
  const text = shell.paused ? pausedWords(waitText, pause.text) : waitText;
  if (deathText.text !== text) deathText.text = text;
  // At most DEATH_WORDS_PX, smaller where the field's width asks it (a phone's).
  const room = cam.toScreenLength(playField.width) - 16;
  if (deathFit !== `${room}:${text}`) {
    deathFit = `${room}:${text}`;
    let size = Math.max(14, Math.min(DEATH_WORDS_PX, room / 16));
    deathText.style.fontSize = size;
    if (deathText.width > room) size = Math.max(12, Math.floor((size * room) / deathText.width));
    deathText.style.fontSize = size;
    deathText.style.lineHeight = 1.2 * size;
  }
  deathText.alpha = waits || age < DEATH_TEXT_MS - 400 ? 1 : (DEATH_TEXT_MS - age) / 400;
  // In the top band, from just under the field's top edge down across the line: no hole lies within
  // 3 m under the line, so the words cover neither the holes nor the path up from the start. Under
  // the touch card while it shows (`placeTouchHint` puts it there too).
  let top = cam.toScreenY(playField.height) + 6;
  const card = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
  if (card && card.offsetParent !== null && !card.classList.contains('bp-gone'))
    top = Math.max(top, card.getBoundingClientRect().bottom - app.canvas.getBoundingClientRect().top + 4);
  deathText.position.set(cam.toScreenX(playField.width / 2), top);
}

/** The largest the words of a fall or a loss are drawn, px. */
const DEATH_WORDS_PX = 22;

/** Whether the path drawn in the last frame was the one holding ↑ from the pad would take (the ship parked, no thrust). */
let padPath = false;

/** The ship's drawn height at the least, px (it is 1 m tall where a metre is more). */
const SHIP_MIN_PX = 26;
/** The ship's drawn height in the last frame, px. */
let shipPx = 0;
/** Half the drawn ship's width and its tail below its centre, in ship heights (see `drawShip`). */
const SHIP_HALF_WIDTH = 0.38,
  SHIP_TAIL = 0.45;
/** The ship's arrowhead at screen (sx, sy), k px a metre, turned by `turn` rad. */
function drawShip(sx: number, sy: number, k: number, turn: number, color: number): void {
  const c = Math.cos(turn),
    n = Math.sin(turn);
  const pts = [0, -0.55, SHIP_HALF_WIDTH, SHIP_TAIL, 0, 0.25, -SHIP_HALF_WIDTH, SHIP_TAIL];
  const out: number[] = [];
  for (let i = 0; i < pts.length; i += 2) out.push(sx + k * (c * pts[i]! - n * pts[i + 1]!), sy + k * (n * pts[i]! + c * pts[i + 1]!));
  overlay.poly(out).fill(color);
}

/** The word by the end of a path that stops short: why it stops (on a horizon, or off the field). */
const pathLabel = new Text({
  text: '',
  style: { fill: 0xff6b5b, fontSize: 14, fontFamily: 'sans-serif', fontWeight: 'bold', stroke: { color: 0x000000, width: 4 } },
});
pathLabel.visible = false;
app.stage.addChild(pathLabel);

/**
 * Seconds of predicted path drawn now: in levels the level's after the falls on it (../levels.ts
 * `previewSeconds`: the full path on level 1 and after repeated falls, shorter otherwise), else the full path.
 */
function pathSeconds(): number {
  return run ? previewSeconds(run.spec.level, Math.max(0, bh.falls - run.fallsAtStart)) : FULL_PATH_SECONDS;
}

/** Least gap between two dots of the predicted path drawn, px. */
const PATH_DOT_GAP = 7;
/**
 * The words that say what the dots are, by the end of a path that runs on (grey, or blue to the
 * line): "predicted path, next 3 s" (the seconds the path is drawn for) or "predicted path: reaches the line", in the path's colour. Shown
 * the first times a path runs on, for PATH_HINT_MS of play in all (the page's whole life: a player
 * learns it once), not from the pad (where the pad's paths start at the ship, and level 1's coach says
 * what the dots are).
 */
const pathHint = new Text({
  text: '',
  style: { fill: PATH_OPEN, fontSize: 13, fontFamily: 'sans-serif', fontWeight: 'bold', stroke: { color: 0x000000, width: 4 } },
});
pathHint.visible = false;
app.stage.addChild(pathHint);
/** How long the path's words show in all, ms of frames drawn in play. */
const PATH_HINT_MS = 6000;
/** What is left of PATH_HINT_MS, ms, and the frame it was last counted at (performance.now(), ms). */
const pathHintLeft = { ms: PATH_HINT_MS, at: 0 };

/**
 * Shows `pathHint` by the end of the path drawn this frame (in `color`) while PATH_HINT_MS last, if the
 * path runs on ('clear': the path ends are marked otherwise) and is not the pad's; beside the end, off
 * the path's dots and the ship, inside the field.
 */
function drawPathHint(color: number, fromPad: boolean): void {
  const now = performance.now();
  const show = pathKind === 'clear' && !fromPad && pathHintLeft.ms > 0 && pathPoints >= 3;
  if (show && !shell.paused) pathHintLeft.ms -= Math.min(100, Math.max(0, now - pathHintLeft.at));
  pathHintLeft.at = now;
  pathHint.visible = show;
  if (!show) return;
  const ahead = pathSeconds();
  const text = pathReachesLine ? 'predicted path: reaches the line' : `predicted path, next ${ahead} s`;
  if (pathHint.text !== text) pathHint.text = text;
  if (pathHint.style.fill !== color) pathHint.style.fill = color;
  const cam = renderer.camera;
  const ex = cam.toScreenX(path[2 * pathPoints - 2]!),
    ey = cam.toScreenY(path[2 * pathPoints - 1]!);
  const x0 = cam.toScreenX(0) + 4,
    x1 = cam.toScreenX(playField.width) - 4,
    top = cam.toScreenY(playField.height) + 4,
    bottom = cam.toScreenY(0) - 4;
  const left = ex > cam.toScreenX(playField.width / 2);
  pathHint.anchor.set(left ? 1 : 0, 0.5);
  const at = left ? Math.max(x0 + pathHint.width, ex - 8) : Math.min(x1 - pathHint.width, ex + 8);
  const y = Math.max(top + pathHint.height / 2, Math.min(bottom - pathHint.height / 2, ey));
  placeOffDots(pathHint, at, y, x0, top, x1, bottom, 8, true);
}

/**
 * Marks how the path drawn this frame ends (`pathKind`; its last point lx, ly, m), so the end says
 * why it ends: where it falls in, a ring (dark under red, seen over the hole's orange disc) round the
 * horizon of the hole that takes it, a cross at the point and the words "falls in"; where it leaves
 * the field, a cross on the edge and "lost"; a clear path ends in a small arrowhead along its last
 * stretch (it goes on beyond what is drawn).
 */
function drawPathEnd(lx: number, ly: number, color: number): void {
  const cam = renderer.camera;
  pathLabel.visible = pathKind !== 'clear';
  const cross = (ex: number, ey: number, size: number): void => {
    overlay
      .moveTo(ex - size, ey - size)
      .lineTo(ex + size, ey + size)
      .moveTo(ex + size, ey - size)
      .lineTo(ex - size, ey + size);
    overlay.stroke({ width: 6, color: 0x000000, alpha: 0.7 });
    overlay
      .moveTo(ex - size, ey - size)
      .lineTo(ex + size, ey + size)
      .moveTo(ex + size, ey - size)
      .lineTo(ex - size, ey + size);
    overlay.stroke({ width: 3, color, alpha: 1 });
  };
  let ex = cam.toScreenX(lx),
    ey = cam.toScreenY(ly);
  // How far the ring round the hole reaches from the end, px (0 with no ring).
  let endRing = 0;
  if (pathKind === 'falls') {
    // The hole whose horizon (plus the ship's size) the end is nearest.
    const P = bh.world.components.Position;
    let best = Infinity,
      hx = 0,
      hy = 0,
      hr = 0;
    for (let i = 0; i < bh.holes.length; i++) {
      const h = bh.holes[i]!;
      const d = Math.hypot(P.x[slotOf(h)]! - lx, P.y[slotOf(h)]! - ly) - bh.holeRadius[i]!;
      if (d < best) [best, hx, hy, hr] = [d, P.x[slotOf(h)]!, P.y[slotOf(h)]!, bh.holeRadius[i]!];
    }
    if (best < Infinity) {
      const rr = cam.toScreenLength(hr) + 5;
      endRing = rr + Math.hypot(cam.toScreenX(hx) - ex, cam.toScreenY(hy) - ey);
      overlay.circle(cam.toScreenX(hx), cam.toScreenY(hy), rr).stroke({ width: 6, color: 0x000000, alpha: 0.6 });
      overlay.circle(cam.toScreenX(hx), cam.toScreenY(hy), rr).stroke({ width: 3, color, alpha: 1 });
    }
    cross(ex, ey, 7);
  } else if (pathKind === 'lost') {
    // The cross sits where the path leaves, pulled back onto the field's edge so it is seen.
    ex = cam.toScreenX(Math.min(bh.field.width, Math.max(0, lx)));
    ey = cam.toScreenY(Math.min(bh.field.height, Math.max(0, ly)));
    cross(ex, ey, 7);
  } else if (pathPoints >= 3) {
    // An arrowhead along the last stretch: the path goes on.
    const px = cam.toScreenX(path[2 * pathPoints - 6]!),
      py = cam.toScreenY(path[2 * pathPoints - 5]!);
    const len = Math.hypot(ex - px, ey - py);
    if (len > 0) {
      const ux = (ex - px) / len,
        uy = (ey - py) / len;
      overlay
        .moveTo(ex - 8 * ux + 5 * uy, ey - 8 * uy - 5 * ux)
        .lineTo(ex, ey)
        .lineTo(ex - 8 * ux - 5 * uy, ey - 8 * uy + 5 * ux)
        .stroke({ width: 2, color, alpha: 0.8 });
    }
  }
  if (!pathLabel.visible) return;
  const word = pathKind === 'falls' ? 'falls in' : 'lost';
  if (pathLabel.text !== word) pathLabel.text = word;
  // Beside the cross, on the side towards the field's middle, kept inside the field; and set back
  // from the end towards where the path came from, clear of the ring and the end's surroundings (beside
  // the end on a wall of holes it covered the wall's gap, the way the player looks for).
  const left = ex > cam.toScreenX(playField.width / 2);
  const back = Math.max(0, pathPoints - 31);
  const by = cam.toScreenY(path[2 * back + 1]!);
  const down = by >= ey; // the path came up from below on screen: the label goes below the end
  pathLabel.anchor.set(left ? 1 : 0, down ? 0 : 1);
  const x0 = cam.toScreenX(0) + 4,
    x1 = cam.toScreenX(playField.width) - 4;
  const at = left ? Math.max(x0 + pathLabel.width, ex - 10) : Math.min(x1 - pathLabel.width, ex + 10);
  const off = Math.max(16, endRing + 8);
  const top = cam.toScreenY(playField.height) + 4,
    bottom = cam.toScreenY(0) - 4;
  const ly2 = down ? Math.min(bottom - pathLabel.height, ey + off) : Math.max(top + pathLabel.height, ey - off);
  // Off the path's dots (and the pad's side paths): beside the climb up the middle it would sit on
  // the fainter path holding ↖ or ↗.
  placeOffDots(pathLabel, at, ly2, x0, top, x1, bottom, 10);
}

/**
 * The coach of a practice level (./levels.ts `LevelSpec.practice`, level 1): a line or two beside the
 * ship that say how the predicted path drawn this frame ends and what to hold (`coachLine`), so a
 * newcomer learns to steer by it. Read from the path of the moment (the ship's state and the arrows
 * held now, the game's own prediction), never a fixed route, so it holds whenever the player acts.
 * Every arrow it names is one to hold (the naive player of test/browser/black-hole.test.ts holds them).
 */
const coachText = new Text({
  text: '',
  style: {
    fill: 0xffe08a,
    fontSize: 16,
    fontFamily: 'sans-serif',
    fontWeight: 'bold',
    stroke: { color: 0x000000, width: 4 },
    lineHeight: 20,
    wordWrap: true,
    wordWrapWidth: 240,
  },
});
coachText.visible = false;
app.stage.addChild(coachText);

/** The arrows the coach names for each thrust it may advise toward a ring (`ringAdvice`). */
const THRUST_WORDS: Partial<Record<Thrust, string>> = {
  up: '↑',
  'up-left': '← and ↑',
  'up-right': '→ and ↑',
  left: '←',
  right: '→',
};

/** A path predicted for the coach's trials of held arrows (`ringAdvice`), beside the drawn `path`. */
const trialPath = new Float64Array(path.length);

/**
 * How to fly through the next ring at `ring` (m): "Tap" or "Hold" and the arrows, or null when no
 * arrow does. Tried in an order a player can follow without the advice flipping: the arrows held now
 * (a path through the ring is kept while it lasts), then ↑ alone (tried before a side arrow is let
 * go), then the side towards the ring with ↑, that side alone, the other side with ↑; each first as a
 * tap (TAP_STEPS of thrust, then coasting), then held. A ring near enough for a tap is "Tap": with
 * the ring some 40 px away, "Hold → and ↑" held for half a second flew the ship past it, off the top.
 * Never an arrow with ↓: a late reaction to ↓ overshot a ring below and the advice swung back and forth.
 */
function ringAdvice(ring: readonly [number, number]): string | null {
  const [rx, ry] = ring;
  const toward = rx < path[0]! ? 'left' : 'right',
    away = toward === 'left' ? 'right' : 'left';
  const tries: Thrust[] = [bh.thrust, 'up', `up-${toward}`, toward, `up-${away}`];
  const live = bh.thrust;
  let found: string | null = null;
  for (const t of tries) {
    if (!(t in THRUST_WORDS)) continue;
    bh.thrust = t;
    for (const [verb, thrustSteps] of [
      ['Tap', TAP_STEPS],
      ['Hold', Infinity],
    ] as const) {
      const n = predictPath(bh, predictor, trialPath, PATH_STEPS, run?.holeVx, thrustSteps);
      for (let i = 0; i < n && !found; i++)
        if (Math.hypot(trialPath[2 * i]! - rx, trialPath[2 * i + 1]! - ry) < RING_RADIUS) found = `${verb} ${THRUST_WORDS[t]!}`;
      if (found) break;
    }
    if (found) break;
  }
  bh.thrust = live;
  return found;
}

/**
 * The coach's words for the path drawn this frame (the ship at x, m): how it ends, and the arrows to
 * hold. Red on a hole: the side arrow away from that hole, with ↑ (steer round it); a ring left
 * (../levels.ts `LevelSpec.rings`) that the path misses: the arrows towards it; red off a side: the
 * side arrow back, with ↑; otherwise ↑ (climb). From the pad: ↑ (the path shows where it goes).
 */
function coachLine(x: number): string {
  if (padPath) return 'Hold ↑ to fly.\nThe dots show your way.';
  const lx = path[2 * pathPoints - 2]!,
    ly = path[2 * pathPoints - 1]!;
  // A ring left: the arrows that fly through it (`ringAdvice`), before all else: its path does not fall first.
  const ring = run && run.ringsTaken < run.rings.length ? run.rings[run.ringsTaken]! : null;
  const advice = ring ? ringAdvice(ring) : null;
  if (advice) return `Gold ring first!\n${advice} to fly through it.`;
  if (pathKind === 'falls') {
    // The hole that takes the path: the one whose horizon its end is nearest.
    const P = bh.world.components.Position;
    let best = Infinity,
      hx = x;
    for (let i = 0; i < bh.holes.length; i++) {
      const h = slotOf(bh.holes[i]!);
      const d = Math.hypot(P.x[h]! - lx, P.y[h]! - ly) - bh.holeRadius[i]!;
      if (d < best) [best, hx] = [d, P.x[h]!];
    }
    return `Red: you'd fall in!\nHold ${x < hx ? '←' : '→'} and ↑ to steer round.`;
  }
  // A ring no arrows reach now: the side towards it with ↑ (never ↓, see `ringAdvice`).
  if (ring) {
    const side = ring[0] < x - 0.8 ? '←' : ring[0] > x + 0.8 ? '→' : '';
    return `Gold ring first!\nHold ${side ? `${side} and ` : ''}↑ to fly through it.`;
  }
  if (pathKind === 'lost')
    return lx < 0 || lx > bh.field.width
      ? `Red: you'd leave the field!\nHold ${lx < 0 ? '→' : '←'} and ↑ to come back.`
      : "Red: you'd leave the field!\nHold ↑.";
  return pathReachesLine ? "Blue: you'll reach the line!\nHold ↑." : 'Clear for now.\nHold ↑ to climb.';
}

/**
 * Draws the coach (`coachLine`) beside the ship at screen (sx, sy), px, k px tall: on the side away
 * from where its path ends (else the roomier side), wrapped to the room there. Only on a practice
 * level in play, with the path shown, and neither a fall's words nor the level's title over the field.
 */
function drawCoach(x: number, sx: number, sy: number, k: number): void {
  // Not under the level's title either (in a small window they met over the open field).
  const show =
    run?.spec.practice === true &&
    !run.waiting &&
    !bh.over &&
    !shell.paused &&
    pathPoints > 0 &&
    !deathText.visible &&
    !(levelBanner.visible && levelBanner.alpha > 0);
  coachText.visible = show;
  if (!show) return;
  const text = coachLine(x);
  if (coachText.text !== text) coachText.text = text;
  const cam = renderer.camera;
  const x0 = cam.toScreenX(0) + 6,
    x1 = cam.toScreenX(playField.width) - 6;
  const endX = cam.toScreenX(path[2 * pathPoints - 2]!);
  const gap = 0.6 * k + 10;
  const roomLeft = sx - gap - x0,
    roomRight = x1 - sx - gap;
  // Away from the path's end, unless that side is too narrow for the words (the ship near a wall).
  let right = Math.abs(endX - sx) > 20 ? endX < sx : roomRight >= roomLeft;
  if ((right ? roomRight : roomLeft) < 120 && (right ? roomLeft : roomRight) > (right ? roomRight : roomLeft)) right = !right;
  // Smaller letters on a narrow field (a phone's), where the room beside the ship is some 150 px.
  const size = x1 - x0 < 500 ? 14 : 16;
  if (coachText.style.fontSize !== size) {
    coachText.style.fontSize = size;
    coachText.style.lineHeight = size + 4;
  }
  const width = Math.max(120, Math.min(260, right ? roomRight : roomLeft));
  if (coachText.style.wordWrapWidth !== width) coachText.style.wordWrapWidth = width;
  coachText.anchor.set(right ? 0 : 1, 0.5);
  const top = cam.toScreenY(playField.height) + 4 + coachText.height / 2,
    bottom = cam.toScreenY(0) - 4 - coachText.height / 2;
  // Kept inside the field: a line wider than the room beside the ship slides toward the ship.
  const tx = right ? Math.min(sx + gap, x1 - coachText.width) : Math.max(sx - gap, x0 + coachText.width);
  // Off the path's dots and the ship: beside the ship on the pad it would sit on the path holding ↗ (or ↖);
  // and off the path's "falls in" (near a hole the two met, the label half hidden).
  for (const label of [pathLabel, pathHint])
    if (label.visible) {
      const b = label.getBounds();
      for (let fx = 0; fx <= 1; fx += 0.25) for (const fy of [0, 0.5, 1]) addDot(b.x + fx * b.width, b.y + fy * b.height);
    }
  const fieldTop = cam.toScreenY(playField.height) + 4,
    fieldBottom = cam.toScreenY(0) - 4;
  // And off the holes: each one's disc, ring and glow (beside the pad's path it sat on the hole's ring).
  placeOffDots(coachText, tx, Math.max(top, Math.min(bottom, sy - 0.2 * k)), x0, fieldTop, x1, fieldBottom, 12, true);
}

/**
 * Over the field while paused: the scene dimmed and "Paused", so a pause is not taken for a hang. It
 * lies under the ship, the predicted path and the captions (the path stays bright while the player
 * thinks); its words are written in the status row above the field (`pauseWords`).
 */
const pause = createPauseOverlay({ label: 'paused', shadeAlpha: 0.35 });
app.stage.addChildAt(pause.container, app.stage.getChildIndex(overlay));
pause.words.visible = false;
/** Shows the pause's words (`pauseWords`) when `show`, else none. */
function drawPauseLine(show: boolean): void {
  pauseWords = show ? pause.text.split('\n').join(': ') : '';
}

/** Gap kept between the touch card and the field's frame and the finish line, px. */
const HINT_LINE_GAP = 6;
/**
 * Keeps the kit's touch card (at the top of the stage, by the page's style) inside the field's frame
 * and off the finish line: in the band between the frame's top and the line where it fits, else just
 * under the line (on a phone the band is too short, and the card at the stage's top lay across the
 * frame and the line). Checked every frame while the card is up (the stage and the field can resize).
 */
function placeTouchHint(): void {
  const card = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
  if (!card) return;
  const stage = pageLayout().stage.getBoundingClientRect(),
    canvas = app.canvas.getBoundingClientRect();
  const off = canvas.top - stage.top;
  const line = off + renderer.camera.toScreenY(bh.lineY),
    frame = off + renderer.camera.toScreenY(playField.height);
  const h = card.offsetHeight;
  let top = Math.max(6, frame + HINT_LINE_GAP);
  if (top + h + HINT_LINE_GAP > line) top = line + HINT_LINE_GAP;
  const want = `${Math.round(top)}px`;
  if (card.style.top !== want) card.style.top = want;
}

/** Gap kept between the next-level button (and the level's title) and the holes, the line and the ship, px. */
const ACTION_GAP = 8;

/** The rings left to fly through, drawn with their halo (12 px), as boxes [x0, x1, y0, y1], m (none between levels). */
function ringExtents(): number[][] {
  if (!run || run.waiting) return [];
  const R = RING_RADIUS + 12 / renderer.camera.toScreenLength(1);
  return run.rings.slice(run.ringsTaken).map(([x, y]) => [x - R, x + R, y - R, y + R]);
}
/**
 * The tallest band across the field, between the finish line (after a game over, the canvas's top) and
 * `end` (screen px, y down), that no
 * hole's drawing (disc and glow, `holeExtents` of the last frame, and `ghostExtents`: the cleared
 * level's holes drawn dimmed) nor a ring left (`ringExtents`) reaches within ACTION_GAP px:
 * [top, height], px in the canvas (height < 0 when there is none).
 */
function freeBand(end: number): [number, number] {
  const cam = renderer.camera;
  // Screen bands (px, y down) taken by the holes (or the cleared level's, dimmed), sorted from the top.
  const taken = [...holeExtents.slice(0, bh.holes.length), ...ghostExtents, ...ringExtents()]
    .map((e) => [cam.toScreenY(e[3]!) - ACTION_GAP, cam.toScreenY(e[2]!) + ACTION_GAP] as const)
    .sort((a, b) => a[0] - b[0]);
  // After a game over from the canvas's top: the finish line counts for nothing then, and on a phone's
  // tall narrow field the holes of a level such as the zig-zag leave no band between the line and the pad.
  let from = (bh.over ? 0 : cam.toScreenY(bh.lineY)) + ACTION_GAP;
  let best = -1,
    bestTop = 0;
  for (const [top, bottom] of [...taken, [end, end] as const]) {
    const to = Math.min(top, end);
    if (to - from > best) [best, bestTop] = [to - from, from];
    from = Math.max(from, bottom);
  }
  return [bestTop, best];
}
/**
 * Puts the next-level / continue button (over the field, by the page's style) in the tallest band
 * across the field between the finish line and the start pad that no hole's drawing (disc and glow,
 * `holeExtents`) reaches, centred in it, so it covers no hole (after a game over the holes stay). Where
 * no band fits it, it stays where the style puts it. Between levels (no live hole) it sits just above
 * the start pad instead, the same place on every level. Checked every frame while the button shows.
 */
function placeActionButton(): void {
  const el = document.querySelector<HTMLElement>('.bp-touchbar.bp-action');
  if (!el?.isConnected || el.offsetHeight === 0) return;
  const cam = renderer.camera;
  const stage = pageLayout().stage.getBoundingClientRect(),
    canvas = app.canvas.getBoundingClientRect();
  const off = canvas.top - stage.top;
  // Down to the ship (on its way up), or, where it waits at the line after a clear, to the start pad.
  const above = lastShip[1]! >= bh.lineY - 1;
  const end = (above ? cam.toScreenY(0.9) : Math.min(cam.toScreenY(0.9), cam.toScreenY(lastShip[1]!))) - shipPx - ACTION_GAP;
  const h = el.offsetHeight;
  // Between levels (no live hole) always in one place, just above the start pad, whatever the cleared
  // level's dimmed holes: the button does not jump about from one level's end to the next.
  if (bh.holes.length === 0 && run?.waiting && !bh.over) {
    const want = `${Math.round(off + end - h)}px`;
    if (el.style.top !== want) el.style.top = want;
    return;
  }
  const [bestTop, best] = freeBand(end);
  const want = best >= h ? `${Math.round(off + bestTop + (best - h) / 2)}px` : '';
  if (el.style.top !== want) el.style.top = want;
}

/**
 * An arrow pressed while paused: the paused path becomes the one that arrow (with the others held)
 * would fly, a planning preview, drawn at once; the ship does not move and nothing is applied until
 * the game resumes (a key let go while paused lets go at once, `release`).
 */
function previewWhilePaused(): void {
  if (!shell.paused || replay.player) return;
  const want = (!run || canThrust(bh, run)) && !readying() ? heldThrust(held) : 'none';
  if (want === 'none') return;
  pausedThrust = want;
  pausedGame = bh;
  game.drawNext();
}

/** Whether the last frame was drawn paused, and the thrust when the pause began (the paused path's). */
let wasPaused = false,
  pausedThrust: BlackHoleGame['thrust'] = 'none',
  /** The game the pause's thrust was taken from (a reset while paused makes a new one). */
  pausedGame: BlackHoleGame | null = null;
function drawFrame(alpha: number, world: PhysicsWorld): void {
  if (shell.paused && (!wasPaused || pausedGame !== bh)) {
    pausedThrust = bh.thrust;
    pausedGame = bh;
  }
  if (!shell.paused && wasPaused) resumedAt = performance.now();
  wasPaused = shell.paused;
  keepPanelOffField();
  showPathToggle();
  coachText.visible = false;
  // The overlay stays right under the ship and its path (layers added later go above them).
  if (pause.container.parent === app.stage && app.stage.getChildIndex(pause.container) !== app.stage.getChildIndex(overlay) - 1) {
    app.stage.removeChild(pause.container);
    app.stage.addChildAt(pause.container, app.stage.getChildIndex(overlay));
  }
  pause.draw(shell.paused, app.screen.width, app.screen.height, touch);
  engine.set(bh.thrust === 'none' || bh.over || shell.paused ? 0 : 0.7);
  drawBackdrop();
  drawHoles(world);
  const cam = renderer.camera;
  overlay.clear();
  // What the captions keep off this frame: the rings left, the ship, the path (`dots`).
  dotCount = 0;
  drawRings();
  const s = bh.ship,
    P = world.components.Position,
    O = world.components.PreviousPosition;
  const x = O.x[slotOf(s)]! + (P.x[slotOf(s)]! - O.x[slotOf(s)]!) * alpha,
    y = O.y[slotOf(s)]! + (P.y[slotOf(s)]! - O.y[slotOf(s)]!) * alpha;
  // The ship, for the captions to keep off (its middle and its nose and tail, SHIP_MIN_PX or 1 m apart).
  {
    const half = 0.5 * Math.max(SHIP_MIN_PX, cam.toScreenLength(1));
    for (const f of [-1, 0, 1]) addDot(cam.toScreenX(x), cam.toScreenY(y) + f * half);
  }
  // No path between levels: the ship waits at rest past the line.
  if (params.path && !bh.over && !run?.waiting) {
    // Parked on the pad with no thrust (the ship held at rest there shows no path): the path holding ↑
    // would take, the engine spooling up from rest as in flight, so a newcomer sees the aid before
    // moving. The thrust is set for the prediction only (the field, not setThrust: no exhaust, no
    // input recorded) and put back at once.
    // Paused, the path is the course at the moment of the pause, or the one an arrow pressed while
    // paused would fly (`previewWhilePaused`): the ship does not move meanwhile.
    const liveThrust = bh.thrust;
    if (shell.paused) bh.thrust = pausedThrust;
    const fromPad = (run ? run.parked && canThrust(bh, run) : bh.parked) && bh.thrust === 'none';
    // In levels, as far ahead as the level shows (../levels.ts `previewSeconds`: less on later levels).
    const steps = run ? Math.min(PATH_STEPS, Math.round(pathSeconds() / bh.world.dt)) : fromPad ? PAD_PATH_STEPS : PATH_STEPS;
    if (fromPad) {
      // Only the path holding ↑: the paths of held diagonals are red on every layout (./levels.ts
      // `heldThrustClears` draws again where one clears), so drawn beside it they said nothing a
      // player could read.
      bh.thrust = 'up';
      pathPoints = predictPath(bh, predictor, path, steps, run?.holeVx);
    } else pathPoints = predictPath(bh, predictor, path, steps, run?.holeVx, thrustStepsLeft());
    bh.thrust = liveThrust;
    padPath = fromPad;
    // A path that ends on a horizon is drawn red with a ring where it falls in, so the pull of a wall
    // bending the ship into it shows ahead; one that leaves the field (the ship would be lost) red
    // with a cross where it leaves; one that reaches the line blue; one that runs on mid-field grey.
    const lx = path[2 * pathPoints - 2]!,
      ly = path[2 * pathPoints - 1]!;
    // The line counts for the path only if it flies through the rings left first (../levels.ts
    // `LevelSpec.rings`): else it is drawn flying on past the line and out, red.
    const lineOpen = ringsOnPath(pathPoints);
    bh.lineOpen = lineOpen;
    pathKind = pathEnd(bh, path, pathPoints, steps);
    bh.lineOpen = true;
    pathReachesLine = false;
    // The blue verdict only where the full path shows (level 1, or as help after falls): on a short
    // path it would turn blue just below the line, once the route is flown anyway.
    const full = pathSeconds() >= FULL_PATH_SECONDS;
    for (let i = 0; i < pathPoints && !pathReachesLine && lineOpen && full; i++) pathReachesLine = path[2 * i + 1]! >= bh.lineY;
    const warn = pathKind !== 'clear';
    const color = warn ? PATH_WARN : pathReachesLine ? PATH_CLEAR : PATH_OPEN;
    // Dots fade along the path but stay plain to the end (faded to nothing, a path seemed to stop short).
    // At least PATH_DOT_GAP px apart, so a slow ship's path reads as dots, not as a drawn line; every
    // point is kept off by the captions all the same.
    let lastX = Infinity,
      lastY = Infinity;
    for (let i = 1; i < pathPoints; i++) {
      const dx = cam.toScreenX(path[2 * i]!),
        dy = cam.toScreenY(path[2 * i + 1]!);
      if (i % 2 === 1) addDot(dx, dy);
      if (Math.hypot(dx - lastX, dy - lastY) < PATH_DOT_GAP) continue;
      [lastX, lastY] = [dx, dy];
      overlay.circle(dx, dy, warn ? 2.4 : 1.9).fill({ color, alpha: 0.4 * (1 - i / (steps + 1)) + 0.35 });
    }
    drawPathEnd(lx, ly, color);
    drawPathHint(color, fromPad);
  } else {
    pathPoints = 0;
    pathKind = 'clear';
    pathReachesLine = false;
    padPath = false;
    pathLabel.visible = false;
    pathHint.visible = false;
  }
  // The ship: a small arrowhead, nose up, 1 m tall, with a flame out of the side opposite the thrust.
  // The ship is drawn at least SHIP_MIN_PX tall (on a phone's narrow field it would be under 20 px).
  // Drawn inside the field's frame: the rules lose the ship when its centre leaves the field, so drawn
  // at its centre it crossed the frame half out first (on a phone, where it is drawn over 1 m wide).
  const k = Math.max(SHIP_MIN_PX, cam.toScreenLength(1)),
    inset = SHIP_HALF_WIDTH * k;
  const sx = Math.max(cam.toScreenX(0) + inset, Math.min(cam.toScreenX(playField.width) - inset, cam.toScreenX(x))),
    sy = Math.min(cam.toScreenY(0) - SHIP_TAIL * k, cam.toScreenY(y));
  shipPx = k;
  drawDeath();
  // The words of a fall are not drawn over the path's label ("falls in" under "Swallowed!").
  if (deathText.visible || swallow.active) pathLabel.visible = pathHint.visible = false;
  // One message at a time: paused over a fall's words (which then say it) or the game-over card, the
  // pause's own words are not drawn (the shade still dims the field).
  drawPauseLine(shell.paused && !deathText.visible && !bh.over);
  const age = performance.now() - swallow.start;
  if (swallow.active && age > SWALLOW_MS) swallow.active = false;
  if (swallow.active) {
    // The status first, then the button: after the last life the continue panel shows, placed off the
    // holes, from the swallow's first frame, and the caption at the hole keeps off it.
    updateStatus();
    placeActionButton();
    drawSwallow(age / SWALLOW_MS, k);
    edgeText.visible = false;
    return;
  }
  swallowText.visible = false;
  lastShip[0] = x;
  lastShip[1] = y;
  // Back at the start after a fall: a ring closes in on the ship, so the eye finds it there.
  const back = age - SWALLOW_MS;
  if (!bh.over && back >= 0 && back < RESPAWN_MS && death.start === swallow.start) {
    const u = back / RESPAWN_MS;
    overlay.circle(sx, sy, k * (2.2 - 1.4 * u)).stroke({ width: 3, color: 0x9fd3ff, alpha: 1 - u });
  }
  drawEdgeWarning(x, y);
  drawLevelBanner();
  placeTouchHint();
  placeActionButton();
  drawScorePop();
  drawCoach(x, sx, sy, k);
  // The engine's thrust now (it spools up and down): the flame points against it, as long as it is
  // strong, and the ship leans into it (up to LEAN rad at full sideways thrust).
  const [tx, ty] = bh.thrustVec;
  const full = Math.max(1e-9, bh.params.thrust),
    strength = Math.min(1, Math.hypot(tx, ty) / full);
  shipLean = bh.over ? 0 : (LEAN * tx) / full;
  if (strength > 0.02 && !bh.over) {
    // Screen direction of the flame (x right, y down): away from where the ship is pushed.
    const fx = -tx / (strength * full),
      fy = ty / (strength * full);
    const len = k * strength * (0.75 + 0.25 * Math.sin(world.time * 60));
    const px = -fy,
      py = fx;
    overlay
      .poly([
        sx + fx * 0.3 * k + px * 0.2 * k,
        sy + fy * 0.3 * k + py * 0.2 * k,
        sx + fx * (0.3 * k + len),
        sy + fy * (0.3 * k + len),
        sx + fx * 0.3 * k - px * 0.2 * k,
        sy + fy * 0.3 * k - py * 0.2 * k,
      ])
      .fill({ color: 0xffb347, alpha: 0.9 });
  }
  drawEngineGauge(sx, sy, k, bh.over ? 0 : strength);
  if (!bh.over) drawVelocityTick(sx, sy, k);
  // Dim while the ready beat after a respawn lasts (no press counts yet), bright once it will fly.
  drawShip(sx, sy, k, shipLean, bh.over ? 0x5c677d : readying() ? 0x7d889c : 0xe8ecf1);
  updateStatus();
}

/** The field's fit last made by `keepPanelOffField`: the panel's edge, the stage's size and the field's, as one key. */
let panelFit = '';
/**
 * Keeps the settings panel and the menu off the field (called every frame; acts on a change). On a
 * wide window the settings panel opens over the stage's top right corner while the game runs on: the
 * field is then fitted left of it, smaller (./view.ts `viewBeside`), and back to the whole stage when
 * it closes. On a small screen a drawer covers the field and pauses the game (`pauseUnderDrawers`):
 * resumed (▶ or P) with a drawer open, the drawer closes, so play never goes on under it.
 */
function keepPanelOffField(): void {
  const page = pageLayout();
  if (page.compact()) {
    if (page.root.dataset.open !== undefined && !shell.paused) page.open(null);
  }
  const cam = renderer.camera;
  let right = Number.POSITIVE_INFINITY;
  if (!page.compact() && page.root.dataset.open === 'side' && page.side.offsetWidth > 0)
    right = page.side.getBoundingClientRect().left - app.canvas.getBoundingClientRect().left - 8;
  const key = `${Math.round(right)}:${cam.width}:${cam.height}:${playField.width}:${playField.height}`;
  if (key === panelFit) return;
  panelFit = key;
  const view = viewBeside(playField, cam.width, cam.height, cam.padding, right);
  const v = cam.view;
  if (v && v.minX === 0 && v.minY === 0 && v.maxX === view && v.maxY === playField.height) return;
  cam.fit({ minX: 0, minY: 0, maxX: view, maxY: playField.height });
  game.drawNext();
}

/** The engine's share of full thrust the gauge round the ship showed in the last frame (0: none drawn). */
let gaugeShown = 0;
/**
 * Draws the velocity tick (./view.ts `velocityTick`): a short pale-blue arrow from the ship's edge
 * along its velocity, longer the faster it flies, so the way it drifts shows with the path off (the
 * ship's nose always points up: a stranger drifted left into a hole with the nose up).
 */
function drawVelocityTick(sx: number, sy: number, k: number): void {
  const V = bh.world.components.Velocity,
    s = slotOf(bh.ship);
  const tick = velocityTick(V.x[s]!, V.y[s]!, k);
  if (!tick) return;
  const len = Math.hypot(tick[0], tick[1]),
    ux = tick[0] / len,
    uy = tick[1] / len;
  const x0 = sx + ux * 0.7 * k,
    y0 = sy + uy * 0.7 * k,
    x1 = x0 + tick[0],
    y1 = y0 + tick[1],
    h = 0.3 * k;
  overlay
    .moveTo(x0, y0)
    .lineTo(x1, y1)
    .stroke({ width: Math.max(2, 0.12 * k), color: 0x9fd3ff, alpha: 0.85 });
  overlay
    .poly([x1 + ux * h, y1 + uy * h, x1 - uy * h * 0.6, y1 + ux * h * 0.6, x1 + uy * h * 0.6, y1 - ux * h * 0.6])
    .fill({ color: 0x9fd3ff, alpha: 0.85 });
}

/**
 * The engine gauge round the ship at (sx, sy), px, k px tall: while it thrusts, a faint circle and an
 * arc over it from the top, clockwise, as far round as the engine's `strength` (0 to 1 of full
 * thrust), closing into a bright ring at full. A tap shows a short arc, a hold one that fills in
 * about 0.4 s (./rules.ts THRUST_RAMP), so how far the engine has built up reads at a glance.
 */
function drawEngineGauge(sx: number, sy: number, k: number, strength: number): void {
  gaugeShown = strength > 0.02 ? strength : 0;
  if (gaugeShown === 0) return;
  const r = 0.95 * k,
    full = strength > 0.999;
  overlay.circle(sx, sy, r).stroke({ width: 2, color: 0xffffff, alpha: 0.12 });
  const a0 = -Math.PI / 2;
  overlay
    .moveTo(sx + r * Math.cos(a0), sy + r * Math.sin(a0))
    .arc(sx, sy, r, a0, a0 + 2 * Math.PI * Math.min(1, strength))
    .stroke({ width: full ? 3 : 2.5, color: full ? 0xffe3b0 : 0xffb347, alpha: full ? 0.85 : 0.75 });
}

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  /** How far round the engine gauge was drawn in the last frame: the engine's share of full thrust (0: none drawn). */
  engineGauge: (): number => gaugeShown,
  /** The ship's position, m, and velocity, m/s: [x, y, vx, vy]. */
  ship: (): number[] => {
    const c = bh.world.components;
    return [c.Position.x[slotOf(bh.ship)]!, c.Position.y[slotOf(bh.ship)]!, c.Velocity.x[slotOf(bh.ship)]!, c.Velocity.y[slotOf(bh.ship)]!];
  },
  /** The ship's drawn height in the last frame, px (at least SHIP_MIN_PX). */
  shipPx: (): number => shipPx,
  /** Points of the predicted path drawn in the last frame. */
  pathPoints: (): number => pathPoints,
  /** The last point of the path drawn in the last frame, m ([x, y]; [] when none was drawn). */
  pathTip: (): number[] => (pathPoints > 0 ? [path[2 * pathPoints - 2]!, path[2 * pathPoints - 1]!] : []),
  /** Whether that path was the one holding ↑ from the pad would take (the ship parked, no thrust). */
  padPath: (): boolean => padPath,
  /** How that path ended (./rules.ts `pathEnd`: drawn blue when 'clear', red when it 'falls' or is 'lost'); 'clear' when none was drawn. */
  pathEnd: (): PathEnd => pathKind,
  /**
   * How the path drawn in the last frame reads by its colour: 'warn' (red: falls in or lost), 'clear'
   * (blue: it reaches the finish line), 'open' (grey: it runs on mid-field, undecided), '' when none was drawn.
   */
  pathShade: (): 'warn' | 'clear' | 'open' | '' =>
    pathPoints === 0 ? '' : pathKind !== 'clear' ? 'warn' : pathReachesLine ? 'clear' : 'open',
  /** Whether the last frame drew the cleared level's holes dimmed while the next level waits. */
  ghostHoles: (): boolean => ghostHoles,
  /**
   * The level's title while it is due (at a level's start, until the first thrust; it fades from the
   * screen after BANNER_MS, see `levelBannerAlpha`), else ''.
   */
  levelBanner: (): string => (bannerShown.key !== '' ? levelBanner.text : ''),
  /** How strongly the title shows in the last frame: 1 at first, fading to 0 after BANNER_MS (0 when it is not due). */
  levelBannerAlpha: (): number => (levelBanner.visible ? levelBanner.alpha : 0),
  /** The title's box in the last frame, px in the canvas: [left, top, right, bottom] (while due, faded or not). */
  levelBannerBox: (): number[] => {
    const b = levelBanner.getBounds();
    return [b.x, b.y, b.x + b.width, b.y + b.height];
  },
  /** The rings left to fly through, each with its halo, as screen boxes [left, top, right, bottom], px in the canvas. */
  ringBoxes: (): number[][] => {
    const cam = renderer.camera;
    return ringExtents().map(([x0, x1, y0, y1]) => [cam.toScreenX(x0!), cam.toScreenY(y1!), cam.toScreenX(x1!), cam.toScreenY(y0!)]);
  },
  /** How far each hole's drawing (disc and glow) reached in the last frame, m: [left, right, bottom, top], holes in order. */
  holeExtents: (): number[][] => holeExtents.map((e) => e.slice()),
  /** The same for the cleared level's holes drawn dimmed while the next level waits (none otherwise). */
  ghostExtents: (): number[][] => ghostExtents.map((e) => e.slice()),
  /** The ship's lean in the last frame, rad (+ leaning right, into thrust to the right). */
  shipLean: (): number => shipLean,
  /** The rising "+N" of the last crossing while it shows, else ''. */
  scorePop: (): string => (scoreText.visible ? scoreText.text : ''),
  /** The practice level's coach beside the ship in the last frame (what to hold, read from the path), else ''. */
  coach: (): string => (coachText.visible ? coachText.text : ''),
  /** Why the path drawn in the last frame stops short, by its end ('falls in' or 'lost'), else ''. */
  pathLabel: (): string => (pathLabel.visible ? pathLabel.text : ''),
  /** The words by the end of a path that runs on in the last frame, saying what the dots are (the first times only), else ''. */
  pathHint: (): string => (pathHint.visible ? pathHint.text : ''),
  /** Gives the path's words their PATH_HINT_MS again (shown the first times only: a test that needs them shown calls this). */
  renewPathHint: (): void => {
    pathHintLeft.ms = PATH_HINT_MS;
  },
  /**
   * A text's box in the last frame, px in the canvas [left, top, right, bottom]: 'coach', 'pathHint',
   * 'pathLabel', 'edge' (the edge warning), 'swallow' (the caption at the hole) or 'death' (a fall's words).
   */
  textBox: (name: 'coach' | 'pathHint' | 'pathLabel' | 'edge' | 'swallow' | 'death'): number[] => {
    const b = { coach: coachText, pathHint, pathLabel, edge: edgeText, swallow: swallowText, death: deathText }[name].getBounds();
    return [b.x, b.y, b.x + b.width, b.y + b.height];
  },
  /**
   * The falls' effect: how many have begun, the words of the last one, the strongest red flash
   * drawn for it (0 to 0.5; 0 until a frame drew it), whether the last frame showed the words, and
   * the caption drawn at the hole while the ship spiralled in ('' until a frame drew it).
   */
  deathEffect: (): { count: number; text: string; flashPeak: number; shown: boolean; caption: string } => ({
    count: death.count,
    text: deathText.text,
    flashPeak: death.flashPeak,
    shown: deathText.visible,
    caption: death.caption,
  }),
  /** Wall-clock time left of the ready beat after a respawn, ms (0: none; a press begun before it ends is dropped; ./main.ts READY_MS). */
  readyLeft: (): number => (readyEndsAt > 0 ? Math.max(0, readyEndsAt - performance.now()) : 0),
  /** Whether the swallow effect (the ship spiralling into a hole) plays, and whether the edge warning shows. */
  swallowing: (): boolean => swallow.active,
  edgeWarning: (): boolean => edgeText.visible,
  /** The pause overlay as last drawn: whether it shows, its words, and whether they are drawn (not while another message shows). */
  pauseOverlay: (): { visible: boolean; text: string; words: boolean } => ({
    visible: pause.visible,
    text: pause.text,
    words: pauseWords !== '' && message.textContent === pauseWords,
  }),
  /** The box of the message line that holds the pause's words, px from the canvas's top left: [left, top, right, bottom]. */
  pauseWordsBox: (): number[] => {
    const b = message.getBoundingClientRect(),
      c = app.canvas.getBoundingClientRect();
    return [b.left - c.left, b.top - c.top, b.right - c.left, b.bottom - c.top];
  },
  /** How many of the last frame's path dots and ship points (what captions keep off) lie in the box [l, t, r, b], px in the canvas. */
  dotsIn: (l: number, t: number, r: number, b: number): number => dotsIn(l, t, r, b, 0),
  /** The game-over card's lines while it shows (the final score, the best, and in levels what Continue does), else ''. */
  overCard: (): string =>
    overCard.isConnected
      ? [overTitle, overScore, overBest, overNext]
          .filter((e) => !e.hidden)
          .map((e) => e.textContent)
          .join('\n')
      : '',
  /** The replay's clock, s of game time (`replayClock`: the replayed attempt's, as the status line shows it; 0 when none plays). */
  replayClock: (): number => replayClock(),
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

// The first world was made before the status and the pad took their rows: make it again for the
// stage's final shape, and frame it.
{
  const wanted = fieldForStage();
  if (wanted.width !== playField.width || wanted.height !== playField.height) {
    playField = wanted;
    shell.reset();
    renderer.camera.fit({ minX: 0, minY: 0, maxX: playField.width, maxY: playField.height });
    backdropVersion = -1;
  }
}
