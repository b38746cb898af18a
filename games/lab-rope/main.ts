/**
 * Lab: ropes (Ramtal and Dobre ch. 13), as a game: a ball hangs from one to three ropes; cut them so
 * that it falls into the basket, catching the stars on its way (scene.ts: eight levels, each with its own idea). Each rope is a
 * chain of point masses joined by distance joints that only pull (createRope), solved in the contact
 * solver's soft substeps; a cut removes one link, and the two pieces hang and fall as two ropes
 * (view.ts draws each piece as its own cord). While one rope holds the ball, the stars a cut now
 * would fly it through ring gold and the basket's rim glows when it would land there: the cue to cut.
 *
 * Input: swipe across a rope to cut it (cut.ts: every rope the stroke crosses, however fast), or tap
 * on it; drag the ball to push it while a rope still holds it (a mouse joint of limited force; a drag
 * begun on the ball never cuts, however fast). A miss holds the scene until a tap, click or key starts again. Keys: P pause, N step,
 * R retry, L next level (once the level is cleared). URL: ?level (1-8), ?links (links a metre, 2-40), ?gravity (0-30 m/s^2),
 * ?room (auto, wide or upright: a screen wider than tall plays the levels in the wide room,
 * scene.ts WIDE_LEVELS, an upright one in the upright room, LEVELS), ?debug (the frame rate, body
 * and step counts and the largest link error in the side column; a player sees the level, the
 * stars and the cuts there).
 */

import {
  COMPACT_MAX_HEIGHT,
  COMPACT_MAX_WIDTH,
  choiceParam,
  createActionButton,
  createPanel,
  flagParam,
  getSound,
  numberParam,
  pageLayout,
  pointerOnCanvas,
} from '@bitphysics/game-kit';
import { createLabDock, createReadout, createStatusLine, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import { addMouseJoint, isAlive, type PhysicsWorld, step as physicsStep, removeJoint, setMouseTarget, slotOf } from '@bitphysics/physics';
import type { WorldRect } from '@bitphysics/render-pixi';
import { Container, Graphics, Text } from 'pixi.js';
import { clearFit, type PixelRect } from './clear-fit';
import { cutRopes, findCuts, segmentDistance } from './cut';
import {
  BALL_DRAG,
  BALL_RADIUS,
  createRopeScene,
  DEFAULTS,
  LEVELS,
  type Level,
  pathReaches,
  predictFlight,
  RopeGame,
  type RopeScene,
  WIDE_LEVELS,
} from './scene';
import { RopeView } from './view';

const USAGE = `Accepted: level 1-${LEVELS.length}; links 2-40 (a metre); gravity 0-30 m/s²; room auto, wide or upright.`;
const url = readUrlParams(
  () => ({
    level: numberParam('level', { default: 1, min: 1, max: LEVELS.length, integer: true }),
    linksPerMetre: numberParam('links', { default: DEFAULTS.linksPerMetre, min: 2, max: 40 }),
    gravity: numberParam('gravity', { default: DEFAULTS.gravity, min: 0, max: 30 }),
    room: choiceParam('room', ['auto', 'wide', 'upright'] as const, 'auto'),
  }),
  USAGE,
);
/**
 * Whether a new level is built in the wide room (WIDE_LEVELS): ?room=wide, or ?room=auto (the default)
 * on a stage wider than tall by a tenth (a desktop window, a phone on its side). Decided at each level's
 * start (a turned phone gets the other room at its next level or retry).
 */
function wideRoom(): boolean {
  if (url.room !== 'auto') return url.room === 'wide';
  const stage = pageLayout().stage.getBoundingClientRect();
  const w = stage.width || window.innerWidth,
    h = stage.height || window.innerHeight;
  return w > 1.1 * h;
}
/** The level set the level shown belongs to. */
let levels: readonly Level[] = LEVELS;
/** Whether the engineer's numbers show (?debug): frame rate, bodies, steps, the largest link error. */
const debug = flagParam('debug');
const params = {
  ...DEFAULTS,
  linksPerMetre: url.linksPerMetre,
  gravity: url.gravity,
  level: url.level,
  retry: () => shell.reset(),
  next: () => nextLevel(),
};

/** Best stars won on each level (-1: not cleared yet). */
const best = LEVELS.map(() => -1);
/** Tries missed on each level in this visit. */
const misses = LEVELS.map(() => 0);
/**
 * Whether the flight hint shows: a faint dotted path of where the ball would fly if the last rope
 * holding it were cut now (scene.ts predictFlight), so a player sees the timing instead of guessing
 * it. On the first two levels from the start (the second's swing on its last rope is new, and
 * without the dots it was a steep step from the first); on the others once the player has missed
 * there (a level's first try is theirs to read alone). Shown only while exactly one rope holds the
 * ball: with two, a cut does not let it fly.
 */
function flightHintOn(): boolean {
  return game.outcome === 'playing' && game.holding() === 1 && (params.level <= 2 || misses[params.level - 1]! > 0);
}
/** The flight hint's path as last drawn (x, y pairs, m; empty while hidden), and whether it ends in the basket. */
const flight: number[] = [];
let flightInBasket = false;
/**
 * Where the ball would fly if the last rope holding it were cut now (predictFlight from the ball as
 * drawn; x, y pairs, m), while exactly one rope holds it and the level is on; empty otherwise.
 * Worked out on every level whether its dots show or not: the cue to cut comes from it (see `lit`).
 */
const forecast: number[] = [];
let forecastInBasket = false;
/**
 * The cue to cut, on every level: the stars not caught yet that a cut now would fly the ball
 * through glow bright (view.ts), and the basket's rim does once a cut now would land in it. A swing
 * passes the moment when all three stars and the basket light together, and a player sees it
 * coming, instead of guessing a window a tenth of a second wide.
 */
const lit = [false, false, false];
let scene: RopeScene;
let game: RopeGame;
let cuts = 0;
/** Real time (s) at which the level was lost; NaN while playing. */
let lostAt = Number.NaN;
/** World time (s) at which the level was lost, and won; NaN until then. */
let lostWorld = Number.NaN,
  wonWorld = Number.NaN;
/** Real time (s) at which the level was won; NaN until then. */
let wonAt = Number.NaN;
/** Stars of the win's row turned gold so far, and the real time (s) the last one did. */
let revealed = 0,
  revealedAt = 0;
/** Real time (s) each star of the level was caught (its pop: view.ts STAR_POP_S); NaN until caught. */
const caughtAt = [Number.NaN, Number.NaN, Number.NaN];
/**
 * A miss holds the scene until the player taps, clicks or presses a key, so a player looking
 * elsewhere still sees the miss before the level starts again: the scene dims to red, the
 * ball is ringed where it lies and the banner says so in large type on a dark card. The tap counts
 * once this long has passed, s, of real time or of the game's (not the swipe that missed).
 */
const MISS_TAP_AFTER = 0.4;
/** The miss banner's second line: a tap on a touch screen, a click (or Space) elsewhere. */
const MISS_HINT = matchMedia('(pointer: coarse)').matches ? '\ntap to try again' : '\nclick or R to try again';
/** Starts the level again at once after a miss (a tap or key during the pause); false otherwise. */
function retryAfterMiss(): boolean {
  if (game.outcome !== 'lost') return false;
  if (performance.now() / 1000 - lostAt < MISS_TAP_AFTER && shell.world.time - lostWorld < MISS_TAP_AFTER) return false;
  shell.reset();
  return true;
}
/** The push: a mouse joint on the ball while the pointer drags it. */
let push = 0;
/** Sparkles: where (m), when (s), colour. */
const sparkles: { x: number; y: number; vx: number; vy: number; born: number; color: number }[] = [];
let plot: ReturnType<typeof createPlot> | null = null;
const sound = getSound();

function createWorld(): PhysicsWorld {
  levels = wideRoom() ? WIDE_LEVELS : LEVELS;
  scene = createRopeScene(params.level - 1, params, levels);
  game = new RopeGame(scene);
  cuts = 0;
  lostAt = Number.NaN;
  lostWorld = Number.NaN;
  wonWorld = Number.NaN;
  wonAt = Number.NaN;
  caughtAt.fill(Number.NaN);
  revealed = 0;
  push = 0;
  plot?.clear();
  return scene.world;
}

/** The ball's velocity before the last step, m/s (for the thud of a landing). */
const lastV = [0, 0];

function labStep(world: PhysicsWorld): void {
  const b = slotOf(scene.ball),
    Vb = world.components.Velocity;
  lastV[0] = Vb.x[b]!;
  lastV[1] = Vb.y[b]!;
  physicsStep(world);
  // A thud when the loose ball's velocity jumps in one step (it hit the floor, a wall or the basket):
  // loudness from the impulse m |dv|.
  const dv = Math.hypot(Vb.x[b]! - lastV[0]!, Vb.y[b]! - lastV[1]! - world.gravity[1]! * world.dt);
  if (dv > 1 && game.holding() === 0) sound.impact(world.components.Mass.value[b]! * dv, 'wood', { threshold: 1, loud: 12 });
  const before = game.outcome;
  for (const i of game.update()) {
    const [x, y] = scene.level.stars[i]!;
    caughtAt[i] = performance.now() / 1000;
    burst(x, y, 0xffd23f, 14);
    sound.chime(1175 + 220 * game.stars(), 0.3);
  }
  if (before === 'playing' && game.outcome === 'won') {
    best[params.level - 1] = Math.max(best[params.level - 1]!, game.stars());
    wonWorld = world.time;
    wonAt = performance.now() / 1000;
    sound.chime(784, 0.25);
    setTimeout(() => sound.chime(1046, 0.5), 160);
    const e = slotOf(scene.ball);
    // Confetti from the basket: green, gold, coral and sky, 40 pieces.
    for (const color of [0x7ee2a0, 0xffd23f, 0xff8a7a, 0x8ad4ff])
      burst(world.components.Position.x[e]!, world.components.Position.y[e]! + 0.3, color, 10, 1.8);
  }
  if (before === 'playing' && game.outcome === 'lost') {
    lostAt = performance.now() / 1000;
    lostWorld = world.time;
    misses[params.level - 1]!++;
    sound.impact(2, 'soft', { threshold: 0.1, loud: 10 });
    // A falling two-note "no".
    sound.chime(392, 0.22);
    setTimeout(() => sound.chime(294, 0.4), 200);
  }
  const e = slotOf(scene.ball);
  const V = world.components.Velocity;
  plot?.push(world.time, world.components.Position.y[e]!, Math.hypot(V.x[e]!, V.y[e]!));
}

const started = await startPixiGame({
  title: 'Rope',
  createWorld,
  step: labStep,
  controls: [
    { keys: 'Swipe', action: 'across a rope to cut it (or tap it)' },
    { keys: 'Drag ball', action: 'push the ball' },
    { keys: 'L', action: 'next level (once cleared)', touch: '' },
  ],
  keys: [{ key: 'l', label: 'next level', action: () => nextLevel() }],
  renderer: { view: LEVELS[0]!.view },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = started;
const dock = createLabDock();
/**
 * The open drawer's box on the canvas, CSS px (the settings or the menu lying over the scene), or
 * null when none is open.
 */
function drawerCover(): PixelRect | null {
  const page = pageLayout();
  const open = page.root.dataset.open;
  const el = open === 'side' ? page.side : open === 'info' ? page.info : null;
  if (!el) return null;
  const c = app.canvas.getBoundingClientRect(),
    d = el.getBoundingClientRect();
  return { left: d.left - c.left, top: d.top - c.top, right: d.right - c.left, bottom: d.bottom - c.top };
}
/**
 * Frames the level in the part of the canvas the open drawer leaves free (clear-fit.ts): the stars
 * and the basket never lie under the settings. Called at a level's start, on a resize and when a
 * drawer opens or closes.
 */
function refit(): void {
  const cam = renderer.camera;
  cam.fit(clearFit(scene.level.view as WorldRect, cam.width, cam.height, drawerCover()), 0);
}
app.renderer.on('resize', refit);
refit();
new MutationObserver(refit).observe(pageLayout().root, { attributes: true, attributeFilter: ['data-open'] });

/**
 * Goes to the next level (after the last, back to the first) once this one is cleared: won now or
 * earlier in this visit (the legend says "once cleared"; the level slider still goes anywhere).
 */
function nextLevel(): void {
  if (game.outcome !== 'won' && best[params.level - 1]! < 0) return;
  params.level = (params.level % LEVELS.length) + 1;
  shell.reset();
  refit();
}

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'level',
      label: 'level',
      min: 1,
      max: LEVELS.length,
      step: 1,
      onChange: () => {
        shell.reset();
        refit();
      },
    },
    {
      type: 'slider',
      key: 'linksPerMetre',
      label: 'links a metre',
      min: 2,
      max: 40,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'ropeMass',
      label: 'rope mass (kg/m)',
      min: 0.01,
      max: 1,
      step: 0.01,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'ballMass',
      label: 'ball mass (kg)',
      min: 0.1,
      max: 10,
      step: 0.1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'slack', label: 'links only pull (rope), else rods', onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'gravity',
      label: 'gravity g (m/s²)',
      min: 0,
      max: 30,
      step: 0.01,
      onChange: (g) => {
        // The level's own share of it (the Moon's level: scene.ts Level.gravityScale).
        shell.world.gravity[1] = -(g as number) * (scene.level.gravityScale ?? 1);
      },
    },
    { type: 'button', key: 'retry', label: 'retry (R)' },
    { type: 'button', key: 'next', label: 'next level (L)' },
  ],
  { title: 'Rope', container: dock.panelSlot },
);
// What a player reads in the side column: the level, the stars caught, the cuts made and the frame
// rate; the body and step counts and the solver's largest link error are the engineer's (?debug).
for (const line of ['bodies', 'steps']) {
  const el = shell.hud.readout.querySelector<HTMLElement>(`[data-hud="${line}"]`);
  if (el) el.hidden = !debug;
}
const readout = createReadout(shell.hud.readout, debug ? ['level', 'stars', 'cuts', 'largest link error'] : ['level', 'stars', 'cuts']);
/** Shows the side column's numbers for the level now (each frame, and at once on a reset or a new level). */
function showReadout(world: PhysicsWorld): void {
  readout.set(0, `${params.level} of ${LEVELS.length}: ${scene.level.name}`);
  readout.set(1, `${game.stars()} of 3`);
  readout.set(2, String(cuts));
  if (debug) readout.set(3, `${(world.joints.stats.maxError * 1000).toPrecision(3)} mm`);
}
// On a small screen the settings drawer lies over the scene's top: without the chart it ends about
// half way down, leaving the level room to be framed below it (clearFit); with it, a fifth.
{
  const style = document.createElement('style');
  style.textContent = `@media (max-width: ${COMPACT_MAX_WIDTH - 0.02}px), (max-height: ${COMPACT_MAX_HEIGHT - 0.02}px) { .rope-charts { display: none !important; } }`;
  document.head.append(style);
  dock.charts.classList.add('rope-charts');
}
plot = createPlot({
  parent: dock.charts,
  title: 'The ball',
  yLabel: 'm / m/s',
  width: dock.chartWidth,
  height: 200,
  capacity: 1200,
  series: [
    { label: 'height (m)', color: '#4cc9f0' },
    { label: 'speed (m/s)', color: '#f4a261' },
  ],
});

const status = createStatusLine();
const showNext = createActionButton('Next level ▶', () => nextLevel());
/** The miss card's button: starts the level again (as R, or a tap on the scene, does). */
const showRetry = createActionButton('Try again ↺', () => shell.reset());

// Input: a press on (or near) the ball pushes it; elsewhere a swipe cuts the ropes it crosses, and a
// tap cuts the rope nearest to it.
const canvas = app.canvas;
const at = { x: 0, y: 0 };
const toWorld = (e: PointerEvent): [number, number] => {
  pointerOnCanvas(canvas, e, at);
  return [renderer.camera.toWorldX(at.x), renderer.camera.toWorldY(at.y)];
};
let stroke: { x: number; y: number; sx: number; sy: number; moved: number; id: number; reach: number; cut: Set<number> } | null = null;
/**
 * The pointer pushing the ball (or pressed in the ring round it, see BALL_RING_PX). A press on the
 * ball is a push however fast it then moves: it never cuts (a drag from the ball read as a flick cut
 * the rope where it meets the ball); a swipe begun off the ball cuts.
 */
const pusher = { id: -1 };
const slash: { x: number; y: number; t: number }[] = [];
/** How far from a rope a tap still cuts it, CSS px. */
const TAP_REACH_PX = 26;
/**
 * How far from a rope a swipe still cuts it, CSS px, by pointer: a finger's stroke (about 8 mm wide
 * under the fingertip, on a 3 px cord that swings) cuts a rope it passes within 14 px of; the mouse's
 * within 5 px, so a flick that stops a few pixels short of the cord's exact line still cuts it.
 */
const SWIPE_REACH_PX = { touch: 14, other: 5 } as const;

/**
 * Cuts the ropes the segment (x0, y0)-(x1, y1), m, crosses or passes within `reach` m of (cut.ts), but
 * none in `spare` (the ropes this stroke has cut already: a stroke cuts each rope once, however
 * long it runs beside it); each rope cut is added to `spare`.
 */
function cutBetween(x0: number, y0: number, x1: number, y1: number, reach: number, spare = new Set<number>()): void {
  if (game.outcome !== 'playing') return;
  const open = scene.ropes.flatMap((_, i) => (spare.has(i) ? [] : [i]));
  const made = cutRopes(
    shell.world,
    open.map((i) => scene.ropes[i]!),
    scene.ball,
    x0,
    y0,
    x1,
    y1,
    reach,
  );
  // The cut is drawn in the very next frame, even where the frame pacer would skip it (the readout
  // said "cuts 1" while the canvas still showed the rope whole).
  if (made.length > 0) started.drawNext();
  for (const c of made) {
    spare.add(open[c.rope]!);
    cuts++;
    burst(c.x, c.y, 0xd9b67c, 8);
    snaps++;
  }
}

/** Cuts not heard yet, and when the pointer last went down (ms): see playSnaps. */
let snaps = 0,
  lastInput = 0;
/**
 * Plays a snap for each cut. Until the page's audio runs (the first press starts it, a moment later)
 * the snaps wait, up to 0.4 s, so the first cut is heard too.
 */
function playSnaps(): void {
  if (snaps === 0) return;
  if (sound.running) {
    sound.snap(Math.min(1, 0.5 + 0.2 * snaps));
    snaps = 0;
  } else if (performance.now() - lastInput > 400) snaps = 0;
}

window.addEventListener('keydown', (e) => {
  if (e.key === ' ' || e.key === 'Enter') retryAfterMiss();
});
canvas.addEventListener('pointerdown', (e) => {
  if (e.button !== 0) return;
  if (retryAfterMiss()) return;
  lastInput = performance.now();
  const [x, y] = toWorld(e);
  releasePush();
  const w = shell.world,
    b = slotOf(scene.ball),
    P = w.components.Position;
  const px = renderer.camera.toScreenLength(1);
  // How far outside the ball the press is, CSS px.
  const off = Math.hypot(P.x[b]! - x, P.y[b]! - y) * px - BALL_RADIUS * px;
  const reach = e.pointerType === 'touch' ? SWIPE_REACH_PX.touch : SWIPE_REACH_PX.other;
  if (off < BALL_RING_PX && game.holding() > 0 && game.outcome === 'playing') {
    pusher.id = e.pointerId;
    // On the ball: a push at once. In the ring round it: a push unless the move crosses a rope first.
    if (off < BALL_ON_PX) startPush(x, y);
    else ring = { x, y, sx: at.x, sy: at.y, id: e.pointerId, reach };
  } else startStroke(x, y, e.pointerId, reach);
  canvas.setPointerCapture(e.pointerId);
});
/** Starts a push of the ball from (x, y), m: a mouse joint on the ball held there, moved to the pointer. */
function startPush(x: number, y: number): void {
  const w = shell.world,
    b = slotOf(scene.ball);
  // A push of at most 1.2 times the ball's weight: enough to swing it, not to carry it.
  push = addMouseJoint(w, {
    b: scene.ball,
    anchor: [x, y],
    target: [x, y],
    hertz: 3,
    dampingRatio: 0.7,
    maxForce: 1.2 * w.components.Mass.value[b]! * Math.max(1, params.gravity),
  });
}
/** Starts a cutting stroke at (x, y), m (`at` the pointer in CSS px), with `reach` px. */
function startStroke(x: number, y: number, id: number, reach: number): void {
  stroke = { x, y, sx: at.x, sy: at.y, moved: 0, id, reach, cut: new Set() };
  slash.length = 0;
  slash.push({ x: at.x, y: at.y, t: performance.now() / 1000 });
}
/**
 * The ring round the ball, CSS px outside its edge: a press within BALL_ON_PX of the ball is on it
 * and pushes it, however it then moves (a drag from the ball never cuts); one from there out to
 * BALL_RING_PX pushes it too (a finger's grab of a small ball), unless its move, not passing over
 * the ball, crosses or passes within swipe reach of a rope that holds the ball before it has gone
 * RING_DECIDE_PX: then it is a swipe from the press and cuts. A swipe across the rope just above the
 * ball began in the ring and only dragged the ball.
 */
const BALL_ON_PX = 6,
  BALL_RING_PX = 22,
  RING_DECIDE_PX = 30;
/** A press in the ring round the ball not yet a push or a stroke: where (m, and CSS px), its pointer and swipe reach (px). */
let ring: { x: number; y: number; sx: number; sy: number; id: number; reach: number } | null = null;
canvas.addEventListener('pointermove', (e) => {
  const [x, y] = toWorld(e);
  if (ring && e.pointerId === ring.id) {
    const r = ring;
    const open = scene.ropes.filter((_, i) => isAlive(shell.world, scene.ropes[i]!.ballLink));
    const reach = r.reach / renderer.camera.toScreenLength(1);
    const b = slotOf(scene.ball),
      P = shell.world.components.Position;
    // A move over the ball itself is a push (it crosses the rope's last link under the ball).
    const clear = segmentDistance(P.x[b]!, P.y[b]!, r.x, r.y, x, y) >= BALL_RADIUS;
    if (clear && findCuts(shell.world, open, scene.ball, r.x, r.y, x, y, reach).length > 0) {
      ring = null;
      pusher.id = -1;
      const now = { x: at.x, y: at.y };
      at.x = r.sx;
      at.y = r.sy;
      startStroke(r.x, r.y, e.pointerId, r.reach);
      at.x = now.x;
      at.y = now.y;
      strokeTo(x, y);
    } else if (Math.hypot(at.x - r.sx, at.y - r.sy) >= RING_DECIDE_PX) {
      ring = null;
      startPush(r.x, r.y);
      setMouseTarget(shell.world, push, [x, y]);
    }
    return;
  }
  if (push && isAlive(shell.world, push) && e.pointerId === pusher.id) {
    setMouseTarget(shell.world, push, [x, y]);
    return;
  }
  if (!stroke || e.pointerId !== stroke.id) return;
  strokeTo(x, y);
});
/**
 * Carries the stroke on to (x, y), m (the pointer's place now, `at` in CSS px): cuts what the
 * segment from its last place crosses (or, once it has moved 8 px, passes within its reach of),
 * however long the segment (a fast flick moves far between two pointer events), and draws it.
 */
function strokeTo(x: number, y: number): void {
  if (!stroke) return;
  stroke.moved += Math.hypot(at.x - stroke.sx, at.y - stroke.sy);
  stroke.sx = at.x;
  stroke.sy = at.y;
  cutBetween(stroke.x, stroke.y, x, y, stroke.moved >= 8 ? stroke.reach / renderer.camera.toScreenLength(1) : 0, stroke.cut);
  stroke.x = x;
  stroke.y = y;
  slash.push({ x: at.x, y: at.y, t: performance.now() / 1000 });
}
function releasePush(): void {
  if (push && isAlive(shell.world, push)) removeJoint(shell.world, push);
  push = 0;
}
const release = (e: PointerEvent): void => {
  const [x, y] = toWorld(e);
  releasePush();
  pusher.id = -1;
  ring = null;
  if (stroke && e.pointerId === stroke.id) {
    // The last stretch, from the last move to where the pointer left: a flick may send its up event
    // far from its last move, or with no move between down and up at all.
    if (e.type === 'pointerup') strokeTo(x, y);
    // A tap (a press that hardly moved): cut the rope nearest to it, if close enough.
    if (stroke.moved < 8) cutBetween(stroke.x, stroke.y, stroke.x, stroke.y, TAP_REACH_PX / renderer.camera.toScreenLength(1), stroke.cut);
  }
  stroke = null;
};
canvas.addEventListener('pointerup', release);
canvas.addEventListener('pointercancel', release);
shell.onWorldChange(() => {
  push = 0;
  stroke = null;
  ring = null;
  sparkles.length = 0;
  // The panel's level slider and the side column follow a new level or a retry at once, so the
  // slider never shows a level the Next level button has moved on from.
  panel.refresh();
  showReadout(shell.world);
  updateStatus();
});

/** `n` sparkles of `color` flying out from (x, y), m, at 1 to 3 m/s times `speed`. */
function burst(x: number, y: number, color: number, n: number, speed = 1): void {
  const now = performance.now() / 1000;
  for (let i = 0; i < n; i++) {
    const a = (2 * Math.PI * i) / n + Math.random() * 0.5,
      s = speed * (1 + Math.random() * 2);
    sparkles.push({ x, y, vx: s * Math.cos(a), vy: s * Math.sin(a) + 1, born: now, color });
  }
}

// Drawing.
const view = new RopeView();
for (const child of renderer.root.children) child.visible = false;
renderer.root.addChild(view.container);
const overlay = new Graphics({ label: 'overlay' });
renderer.root.addChild(overlay);
const banner = new Text({
  text: '',
  style: {
    fill: 0xffffff,
    fontSize: 30,
    fontFamily: 'sans-serif',
    fontWeight: 'bold',
    align: 'center',
    stroke: { color: 0x101828, width: 6 },
    wordWrap: true,
    wordWrapWidth: 360,
  },
});
banner.anchor.set(0.5);
renderer.root.addChild(banner);
/**
 * The stars of the try under the banner: a gold star for each caught, an outlined one (dark fill, a
 * light rim) for each missed, so both read on the blue wall (a '☆' in the banner's dark stroke does not).
 */
const starRow = new Container({ label: 'stars' });
/** The star row as last shown: [gold, of] ([0, 0] while hidden). */
let starsShown: [number, number] = [0, 0];
const STAR_SIZE = 34;
for (let i = 0; i < 3; i++) {
  const star = new Text({ text: '★', style: { fontSize: STAR_SIZE, fontFamily: 'sans-serif', fill: 0xffd23f } });
  star.anchor.set(0.5);
  star.x = (i - 1) * STAR_SIZE * 1.1;
  starRow.addChild(star);
}
renderer.root.addChild(starRow);
/**
 * Shows the star row centred at (x, y) px with `got` of `of` stars gold, drawn `scale` times their
 * size (> 0); hides it when `of` is 0.
 */
function showStars(x: number, y: number, got: number, of: number, alpha: number, scale = 1): void {
  starsShown = of > 0 && alpha > 0 ? [got, of] : [0, 0];
  starRow.visible = of > 0 && alpha > 0;
  starRow.position.set(x, y);
  starRow.scale.set(scale);
  starRow.alpha = alpha;
  starRow.children.forEach((child, i) => {
    const star = child as Text;
    star.visible = i < of;
    star.x = (i - (of - 1) / 2) * STAR_SIZE * 1.1;
    const on = i < got;
    star.scale.set(1);
    star.style.fill = on ? 0xffd23f : 0x22324a;
    star.style.stroke = on ? { color: 0x5a3a00, width: 3 } : { color: 0xe8eef5, width: 3 };
  });
}

let lastFrame = performance.now() / 1000;
function draw(alpha: number, world: PhysicsWorld): void {
  const now = performance.now() / 1000;
  const dt = Math.min(0.05, now - lastFrame);
  lastFrame = now;
  const cam = renderer.camera;
  forecastCut(world, alpha);
  view.update(
    world,
    scene.level,
    scene.ropes,
    scene.ball,
    game.caught,
    cam,
    alpha,
    now,
    app.screen.width,
    app.screen.height,
    caughtAt,
    lit,
  );
  overlay.clear();
  drawBasketCue(now);
  // The swipe: the last 0.25 s of the stroke, fading.
  while (slash.length > 0 && now - slash[0]!.t > 0.25) slash.shift();
  for (let i = 1; i < slash.length; i++) {
    const a = slash[i - 1]!,
      b = slash[i]!;
    const fade = 1 - (now - b.t) / 0.25;
    overlay
      .moveTo(a.x, a.y)
      .lineTo(b.x, b.y)
      .stroke({ width: 8 * fade + 1, color: 0xffffff, alpha: 0.2 * fade, cap: 'round' });
    overlay
      .moveTo(a.x, a.y)
      .lineTo(b.x, b.y)
      .stroke({ width: 2.5, color: 0xffffff, alpha: 0.9 * fade, cap: 'round' });
  }
  drawFlight(now);
  // The push: a band from the ball to the pointer.
  if (push && isAlive(world, push)) {
    const e = slotOf(scene.ball);
    const P = world.components.Position;
    overlay.moveTo(cam.toScreenX(P.x[e]!), cam.toScreenY(P.y[e]!)).lineTo(at.x, at.y).stroke({ width: 3, color: 0xffd166, alpha: 0.8 });
    overlay.circle(at.x, at.y, 10).stroke({ width: 2, color: 0xffd166 });
  }
  for (let i = sparkles.length - 1; i >= 0; i--) {
    const s = sparkles[i]!;
    const age = now - s.born;
    if (age > 0.8) {
      sparkles.splice(i, 1);
      continue;
    }
    s.x += s.vx * dt;
    s.y += s.vy * dt;
    s.vy -= 6 * dt;
    overlay
      .circle(cam.toScreenX(s.x), cam.toScreenY(s.y), Math.max(2, cam.toScreenLength(0.05)) * (1 - age))
      .fill({ color: s.color, alpha: 1 - age / 0.8 });
  }
  drawBanner(now);
  updateStatus();
  playSnaps();
  showReadout(world);
}

/** Works out `forecast` and `lit` for the frame at interpolation factor `alpha`. */
function forecastCut(world: PhysicsWorld, alpha: number): void {
  forecast.length = 0;
  forecastInBasket = false;
  lit.fill(false);
  if (game.outcome !== 'playing' || game.holding() !== 1) return;
  const e = slotOf(scene.ball),
    P = world.components.Position,
    O = world.components.PreviousPosition,
    V = world.components.Velocity;
  forecastInBasket = predictFlight(
    scene.level,
    O.x[e]! + (P.x[e]! - O.x[e]!) * alpha,
    O.y[e]! + (P.y[e]! - O.y[e]!) * alpha,
    V.x[e]!,
    V.y[e]!,
    -world.gravity[1]!,
    BALL_DRAG / world.components.Mass.value[e]!,
    forecast,
    0.04,
  );
  scene.level.stars.forEach(([sx, sy], i) => {
    lit[i] = !game.caught[i] && pathReaches(forecast, sx, sy);
  });
}

/** The basket's rim lit (see `lit`): a soft green band along its walls' tops and its opening, pulsing at `now` s. */
function drawBasketCue(now: number): void {
  if (!forecastInBasket) return;
  const cam = renderer.camera;
  const [bx, by] = scene.level.basket,
    half = scene.level.basketWidth / 2 + 0.05,
    top = by + scene.level.basketDepth;
  const a = 0.55 + 0.25 * Math.sin(8 * now);
  overlay
    .moveTo(cam.toScreenX(bx - half), cam.toScreenY(top))
    .lineTo(cam.toScreenX(bx + half), cam.toScreenY(top))
    .stroke({ width: Math.max(5, cam.toScreenLength(0.12)), color: 0x9ff0b8, alpha: a, cap: 'round' });
}

/**
 * The flight hint (see flightHintOn): dots along the forecast path from the ball as drawn, fading
 * along the way, every 0.08 s of flight; a small ring where it ends.
 */
function drawFlight(now: number): void {
  flight.length = 0;
  flightInBasket = false;
  hintCaption.visible = false;
  if (!flightHintOn() || forecast.length === 0) return;
  const cam = renderer.camera;
  flight.push(...forecast);
  flightInBasket = forecastInBasket;
  const n = flight.length / 2;
  const dot = Math.max(2, cam.toScreenLength(0.045));
  for (let i = 2; i < n; i += 2) {
    const a = 0.5 * (1 - (0.6 * i) / n);
    overlay.circle(cam.toScreenX(flight[2 * i]!), cam.toScreenY(flight[2 * i + 1]!), dot).fill({ color: 0xffffff, alpha: a });
  }
  if (n > 1)
    overlay
      .circle(cam.toScreenX(flight[2 * n - 2]!), cam.toScreenY(flight[2 * n - 1]!), cam.toScreenLength(BALL_RADIUS))
      .stroke({ width: 2, color: 0xffffff, alpha: 0.3 });
  drawHintCaption(cam, now);
}

/** How long the flight hint's caption shows once the hint first appears on a level, s (the last second fading). */
const HINT_CAPTION_S = 6;
/** Real time (s) the flight hint first showed on each level in this visit; NaN until it has. */
const hintShownAt = LEVELS.map(() => Number.NaN);
/**
 * The flight hint's caption: says what the dots mean the first time they show on a level, at the
 * top of the scene (on a later level, where they appear only after a miss, it says the hint is
 * unlocked).
 */
const hintCaption = new Text({
  text: '',
  style: {
    fill: 0xffffff,
    fontSize: 15,
    fontFamily: 'sans-serif',
    stroke: { color: 0x101828, width: 4 },
    align: 'center',
    wordWrap: true,
    wordWrapWidth: 360,
  },
});
hintCaption.visible = false;
renderer.root.addChild(hintCaption);
/** Shows the caption while the hint is new on this level (see hintCaption); `now` in s. */
function drawHintCaption(cam: typeof renderer.camera, now: number): void {
  const n = flight.length / 2;
  if (n < 2) return;
  const k = params.level - 1;
  if (Number.isNaN(hintShownAt[k]!)) hintShownAt[k] = now;
  const age = now - hintShownAt[k]!;
  if (age >= HINT_CAPTION_S) return;
  const text = `${params.level <= 2 ? '' : 'Hint unlocked! '}• • • dots: where the ball flies if you cut now`;
  if (hintCaption.text !== text) hintCaption.text = text;
  hintCaption.style.wordWrapWidth = Math.max(160, cam.width - 24);
  // Centred at the top of the scene, over the beam, where no star, rope or basket lies (beside the
  // moving path it covered a star on a phone).
  hintCaption.x = (cam.width - hintCaption.width) / 2;
  hintCaption.y = 8;
  hintCaption.alpha = Math.min(1, HINT_CAPTION_S - age);
  hintCaption.visible = true;
}

/** Heights the banner may stand at, m, in order of preference: mid-scene first. */
const BANNER_HEIGHTS = [3.4, 4.1, 2.6, 4.8, 1.8, 5.6, 6.4];
/** A star's drawn glow reaches this far from its centre, m (view.ts: 0.22 m x 1.6, pulsing 8%). */
const STAR_GLOW = 0.38;
/**
 * The gap, CSS px, the banner's box keeps beyond a star's glow: the text's dark stroke and the
 * glyphs' overhang reach past the measured box, and a title ending a few px from a glow read as
 * covering the star.
 */
const STAR_GAP_PX = 24;
/**
 * The first of BANNER_HEIGHTS (m) at which the banner's box (with the star row under it and the
 * miss card's margin once the level is over) stays clear of every star not caught yet (so the
 * banner never hides one) and, once the level is over, of the basket and the ball (a miss card over
 * them would hide why the ball missed); the first height clear of the stars if none is clear of all, the
 * first height if none is clear of the stars. Clear means STAR_GAP_PX beyond each glow if some height
 * allows it (a narrow phone may not), else just beyond the glow.
 */
function bannerHeight(): number {
  const h = bannerHeightWithGap(STAR_GAP_PX);
  return Number.isNaN(h) ? bannerHeightWithGap(0) : h;
}
/** bannerHeight with `gap` px beyond each star's glow; NaN if no height keeps clear of the stars. */
function bannerHeightWithGap(gap: number): number {
  const cam = renderer.camera;
  const over = game.outcome !== 'playing';
  // With the star row under it (the outcome's banner) the box reaches a row lower; the miss card
  // (drawn in the update) reaches 24 px beyond the text each side and 14 px above and below.
  const row = over ? STAR_SIZE * 1.2 : 0;
  const halfW = banner.width / 2 + (over ? 24 : 0),
    halfH = banner.height / 2 + row / 2 + (over ? 14 : 0);
  /** Whether the box centred at screen y `by` keeps `r` px from the screen point (x, y). */
  const apart = (by: number, x: number, y: number, r: number): boolean => {
    const dx = Math.max(0, Math.abs(x - cam.width / 2) - halfW),
      dy = Math.max(0, Math.abs(y - by) - halfH);
    return dx * dx + dy * dy > r * r;
  };
  const [bx] = scene.level.basket,
    half = scene.level.basketWidth / 2 + 0.15;
  const e = slotOf(scene.ball),
    P = shell.world.components.Position;
  let fallback = -1;
  for (const y of BANNER_HEIGHTS) {
    const by = cam.toScreenY(y) + row / 2;
    const clear = scene.level.stars.every(
      ([sx, sy], i) => game.caught[i] || apart(by, cam.toScreenX(sx), cam.toScreenY(sy), cam.toScreenLength(STAR_GLOW) + gap),
    );
    if (!clear) continue;
    if (!over) return y;
    if (fallback < 0) fallback = y;
    // The basket (its walls and rim) and the ball with its ring.
    const rimY = cam.toScreenY(scene.level.basketDepth + 0.1),
      floorY = cam.toScreenY(0);
    const basketClear =
      by + halfH < Math.min(rimY, floorY) ||
      by - halfH > Math.max(rimY, floorY) ||
      cam.width / 2 + halfW < Math.min(cam.toScreenX(bx - half), cam.toScreenX(bx + half)) ||
      cam.width / 2 - halfW > Math.max(cam.toScreenX(bx - half), cam.toScreenX(bx + half));
    if (basketClear && apart(by, cam.toScreenX(P.x[e]!), cam.toScreenY(P.y[e]!), cam.toScreenLength(2 * BALL_RADIUS))) return y;
  }
  if (fallback >= 0) return fallback;
  return gap > 0 ? Number.NaN : BANNER_HEIGHTS[0]!;
}

/**
 * Puts the action button shown ("Next level" after a win, "Try again" after a miss) in the middle of
 * the scene, its top `top` px under the canvas's top (just under the win banner's row of stars, or
 * under the miss card): the outcome reads as one card, the button under the message in reach of a
 * thumb (in a bottom corner, away from the basket, a stranger on a phone took it for part of the
 * floor and missed the win). The banner stands clear of the basket.
 */
function placeNext(top: number): void {
  const bar = document.querySelector<HTMLElement>('.bp-action');
  if (!bar) return;
  const canvas = document.querySelector('canvas')?.getBoundingClientRect();
  const stage = pageLayout().stage.getBoundingClientRect();
  const at = `${Math.round(top + (canvas ? canvas.top - stage.top : 0))}px`;
  if (bar.style.top !== at) {
    bar.style.top = at;
    bar.style.bottom = 'auto';
    bar.style.justifyContent = 'center';
  }
}

/** The miss card's star row is drawn this times STAR_SIZE. */
const MISS_STAR_SCALE = 0.75;
/** The miss card as drawn: left, top, width, height, CSS px on the canvas; null while none is shown. */
let missCard: [number, number, number, number] | null = null;
/**
 * The top (px) of the miss card `h` px tall: 8 px under the top of the canvas, over the beam, unless
 * the ball or a star not caught lies in its rows there; then just under the lowest of those (or, if
 * that leaves no room on the canvas, at the top after all).
 */
function missCardTop(h: number): number {
  const cam = renderer.camera;
  const e = slotOf(scene.ball),
    P = shell.world.components.Position;
  // Each as its screen rows (centre y, reach px), whatever its x: the card spans the scene's middle.
  const things = [[P.y[e]!, 2 * BALL_RADIUS], ...scene.level.stars.flatMap(([, y], i) => (game.caught[i] ? [] : [[y, STAR_GLOW]]))].map(
    ([y, r]) => [cam.toScreenY(y!), cam.toScreenLength(r!)] as const,
  );
  let top = 8;
  for (let k = 0; k < things.length; k++) for (const [y, r] of things) if (y + r > top && y - r < top + h) top = y + r + 6;
  return top + h <= cam.height ? top : 8;
}

/** The banner in the middle of the scene: the level's name at its start, then the outcome. */
function drawBanner(now: number): void {
  const cam = renderer.camera;
  banner.style.wordWrapWidth = Math.max(200, cam.width - 40);
  banner.x = cam.width / 2;
  banner.y = cam.toScreenY(bannerHeight());
  const starsY = banner.y + banner.height / 2 + STAR_SIZE * 0.6;
  if (game.outcome === 'won') {
    const s = game.stars();
    const last = params.level === LEVELS.length;
    setBanner(last ? 'All levels done!' : 'In the basket!', 0x9ff0b8, 1);
    // The stars won turn gold one at a time, each with a chime a step higher, swelling as it lands:
    // on game time, or on the page's time where that is ahead (a game paused at the win still shows them).
    const since = Math.max(shell.world.time - wonWorld, now - wonAt);
    const due = Math.max(0, Math.min(s, Math.floor((since - STAR_REVEAL_FIRST) / STAR_REVEAL_S) + 1));
    if (due > revealed) {
      revealed = due;
      revealedAt = now;
      sound.chime(880 * 1.26 ** (revealed - 1), 0.35);
    }
    showStars(banner.x, starsY, revealed, scene.level.stars.length, 1);
    const swell = now - revealedAt;
    if (revealed > 0 && swell < 0.25) starRow.children[revealed - 1]!.scale.set(1 + 0.45 * (1 - swell / 0.25));
    showRetry(false);
    showNext(true, last ? 'Play again ▶' : 'Next level ▶');
    placeNext(starsY + STAR_SIZE * 0.6 + 12);
    return;
  }
  showNext(false);
  if (game.outcome === 'lost') {
    // Held until a tap or a key (see MISS_TAP_AFTER): the scene dimmed red, the ball ringed, and a
    // small card at the top of the scene (over the beam) with the stars this try caught beside the
    // text, so the stars, the ball and the basket stay in sight (a card mid-scene would cover them).
    const since = now - lostAt;
    const fade = Math.min(1, since / 0.3);
    overlay.rect(0, 0, cam.width, cam.height).fill({ color: 0x5a0b0b, alpha: 0.38 * fade });
    const e = slotOf(scene.ball),
      P = shell.world.components.Position;
    const bx = cam.toScreenX(P.x[e]!),
      by = cam.toScreenY(P.y[e]!),
      r = cam.toScreenLength(BALL_RADIUS);
    overlay.circle(bx, by, r * (1.7 + 0.15 * Math.sin(since * 6))).stroke({ width: 4, color: 0xff6b5a, alpha: fade });
    setBanner(`Missed!${MISS_HINT}`, 0xffb4a2, 1, cam.width < 500 ? 22 : 28);
    const n = scene.level.stars.length,
      rowW = n * STAR_SIZE * MISS_STAR_SCALE * 1.1;
    const w = banner.width + 16 + rowW + 40,
      h = banner.height + 20;
    missCard = [(cam.width - w) / 2, missCardTop(h), w, h];
    const [x0, y0] = missCard;
    banner.x = x0 + 20 + banner.width / 2;
    banner.y = y0 + h / 2;
    overlay
      .roundRect(x0, y0, w, h, 14)
      .fill({ color: 0x101828, alpha: 0.85 * fade })
      .stroke({ width: 3, color: 0xff6b5a, alpha: fade });
    showStars(x0 + w - 20 - rowW / 2, banner.y, game.stars(), n, 1, MISS_STAR_SCALE);
    // The button under the card, or over it where the card reaches the canvas's foot.
    showRetry(true);
    placeNext(y0 + h + 70 <= cam.height ? y0 + h + 10 : Math.max(0, y0 - 62));
    return;
  }
  showRetry(false);
  missCard = null;
  showStars(0, 0, 0, 0, 0);
  const t = shell.world.time;
  setBanner(`Level ${params.level}: ${scene.level.name}`, 0xffffff, t < 1 ? 1 : Math.max(0, 1 - (t - 1) * 2));
}
/** Seconds from the win to its first star turning gold, and between the next ones. */
const STAR_REVEAL_FIRST = 0.25,
  STAR_REVEAL_S = 0.3;
/** Shows `text` in the banner in colour `color` (0xRRGGBB) at opacity `alpha` in [0, 1], in `size` px type. */
function setBanner(text: string, color: number, alpha: number, size = 30): void {
  if (banner.text !== text) banner.text = text;
  if (banner.style.fontSize !== size) banner.style.fontSize = size;
  banner.style.fill = color;
  banner.alpha = alpha;
  banner.visible = alpha > 0;
}

function updateStatus(): void {
  const total = best.reduce((s, b) => s + Math.max(0, b), 0);
  const cleared = best.filter((b) => b >= 0).length;
  // On a phone the count goes in front, short ("Level 2/5 · ★ 2 — "), and every hint leaves room
  // for it in two lines, so a clear does not grow the status by a line and push the scene down.
  if (pageLayout().compact()) {
    status.set(`Level ${params.level}/${LEVELS.length}${cleared > 0 ? ` · ★ ${total}` : ''} — ${scene.level.hint}`);
    return;
  }
  const tail = cleared > 0 ? ` · cleared ${cleared} of ${LEVELS.length}, ★ ${total}` : '';
  status.set(`Level ${params.level} of ${LEVELS.length}: ${scene.level.hint}${tail}`);
}

shell.expose({
  params,
  plot,
  /** The level's handles: the ball, and per rope its bodies and links (anchor to ball). */
  ids: () => ({
    ball: scene.ball,
    ropes: scene.ropes.map((r) => ({ anchor: [...r.anchor], bodies: [...r.bodies], links: [...r.links] })),
  }),
  /** Ropes that still hold the ball, cuts made, stars caught, and the level's outcome. */
  holding: () => game.holding(),
  cuts: () => cuts,
  stars: () => game.stars(),
  outcome: () => game.outcome,
  /** The level shown (1-based), and the best stars of each level (-1: not cleared). */
  level: () => params.level,
  /** The room the level is built in: 'wide' (WIDE_LEVELS) or 'upright' (LEVELS). */
  room: () => (levels === WIDE_LEVELS ? 'wide' : 'upright'),
  /** The level's basket: centre of its floor (x, y, m) and inner width and wall height, m. */
  basket: () => ({ at: [...scene.level.basket], width: scene.level.basketWidth, depth: scene.level.basketDepth }),
  best: () => [...best],
  /** Tries missed on each level in this visit. */
  misses: () => [...misses],
  /**
   * The flight hint as last drawn: its path (x, y pairs, m; empty while hidden) and whether it ends
   * in the basket's opening.
   */
  flight: () => ({ path: [...flight], inBasket: flightInBasket }),
  /** The cue to cut as last drawn: which stars glow (a cut now would fly through them) and whether the basket's rim does. */
  cue: () => ({ stars: [...lit], basket: forecastInBasket }),
  /** The flight hint's caption as last drawn ('' while hidden). */
  hintCaption: () => (hintCaption.visible ? hintCaption.text : ''),
  /**
   * The banner over the scene: its text ('' while hidden), box (x, y, width, height, px) and the star
   * row under it ([gold, of]; [0, 0] while hidden).
   */
  banner: () => ({
    text: banner.visible ? banner.text : '',
    stars: [...starsShown],
    box: [banner.x - banner.width / 2, banner.y - banner.height / 2, banner.width, banner.height],
    /** The miss card round the banner and its star row (left, top, width, height, px), or null. */
    card: missCard ? [...missCard] : null,
  }),
  /** The level's stars (x, y, m) and whether each is caught. */
  starsAt: () => scene.level.stars.map(([x, y], i) => ({ x, y, caught: game.caught[i]! })),
  /** Rope pieces drawn in the last frame (one a whole rope; each cut adds one). */
  ropePieces: () => view.pieces,
  /**
   * The drawing order over the ball as last drawn: the layers drawn after the ball's sprite (by
   * label), the basket front's box (x, y, width, height, canvas px) and the ball's drawn centre (px).
   */
  overBall: () => {
    const layers = view.container.children;
    const ballAt = layers.findIndex((c) => c.label === 'ball');
    const sprite = layers[ballAt];
    return {
      above: layers.slice(ballAt + 1).map((c) => c.label),
      front: [...view.frontBox],
      ball: sprite ? [sprite.x, sprite.y] : [Number.NaN, Number.NaN],
    };
  },
  /** Goes to level n (1-based). */
  goTo: (n: number) => {
    params.level = Math.min(LEVELS.length, Math.max(1, Math.round(n)));
    shell.reset();
    refit();
  },
  /** Runs the lab's step n times (tests). */
  advance: (n: number) => {
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
