/**
 * Bouncing balls: the book's bouncing balls grown up. Balls of different sizes and masses fall,
 * bounce off the box, the inclined walls (and their end points) and each other.
 *
 * The game on top (./hoop.ts): throw balls through the hoop as often as you can in 45 s; the hoop
 * moves after each basket, the clock starts with the first ball, the best score is kept in
 * localStorage; R or the Play-again button starts a new round. The status row above the box says
 * the goal and shows baskets, time and best.
 *
 * Input: press on a ball or crate and drag to pull it (a mouse joint); anywhere else a click drops a
 * ball at the pointer, and a pull throws one slingshot-style from where the press began (opposite to
 * the pull, faster the longer it is, hoop.ts slingVelocity), with a dotted arc of its flight while
 * pulling (hoop.ts throwPath). The player's balls are orange, all the same size (hoop.ts
 * PLAYER_RADIUS). When time is up, the Play-again button floats at the top of the box, clear of the
 * balls piled at its bottom.
 * Keys: P pause, N single step, R reset, T trails, D debug overlay.
 * URL: ?count=N (balls, 1..10000), ?round=S (hoop round, s, 5..600), ?seed=S, ?mode=auto|sprites|particles, ?trails=0|1, ?debug.
 * From 1000 balls on (mode auto) the renderer draws with pixi's ParticleContainer.
 */

import {
  choiceParam,
  createActionButton,
  createPanel,
  createStatusRow,
  flagParam,
  forEachImpact,
  getSound,
  numberParam,
  pageLayout,
  type SoundMaterial,
  seedParam,
} from '@bitphysics/game-kit';
import { enableMouseDrag } from '@bitphysics/game-kit/drag';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { addBox, createPhysicsWorld, type PhysicsWorld, setMaterial as setBodyMaterial, slotOf, step } from '@bitphysics/physics';
import { Graphics, Text } from 'pixi.js';
import {
  addHoop,
  createRound,
  type HoopRound,
  hoopCrossing,
  hoopOpening,
  hoopSpots,
  mayScore,
  PLAYER_RADIUS,
  ROUND_SECONDS,
  removeHoop,
  roundBasket,
  roundShot,
  roundTick,
  slingVelocity,
  throwPath,
} from './hoop';
import {
  applyDrag,
  applyGravity,
  applyMaterial,
  type BouncingBallsHandles,
  bouncingBallsWorldOptions,
  buildBouncingBalls,
  DENSITIES,
  DRAG_MODES,
  type DragMode,
  isHeavy,
  layoutOf,
  meanRadiusFor,
  removeBall,
  spawnBall,
} from './scene';

/** Colour of the heavy balls (density 4 kg/m^2); the others keep their seeded colours. */
const HEAVY_COLOR = 0x6b7a93;
/** A press that moves less than this, CSS px, is a click (drop), more is a throw. */
const CLICK_SLOP = 6;

const initialCount = numberParam('count', { default: 40, min: 1, max: 10_000, integer: true });
const params = {
  count: initialCount,
  seed: seedParam(),
  gravity: 9.81,
  restitution: 0.8,
  friction: 0.2,
  drag: 'none' as DragMode,
  dragK: 0.05,
  trails: new URLSearchParams(location.search).has('trails') ? flagParam('trails') : initialCount <= 400,
  debug: flagParam('debug'),
  reset: () => game.shell.reset(),
};
/** Length of a hoop round, s (?round=S, 5..600). */
const roundSeconds = numberParam('round', { default: ROUND_SECONDS, min: 5, max: 600 });
const mode = choiceParam('mode', ['auto', 'sprites', 'particles'] as const, 'auto');

/** A screen taller than wide (a phone held upright) gets the tall box, which fills it. */
const TALL = window.innerHeight > 1.2 * window.innerWidth;
let handles: BouncingBallsHandles;
/** Crates dropped with X (boxes: shapes that tumble among the balls), oldest first. */
let crates: number[] = [];
/** The hoop game's round (a new one with each world: R restarts the round). */
let round: HoopRound = createRound(roundSeconds);
/** Entity ids of the hoop's backboard and front rim. */
let hoopIds: number[] = [];
/** The player's balls: whether each may score (released below the rim) and its centre after the last step, m. */
let playerBalls = new Map<number, { scores: boolean; x: number; y: number }>();
/** Colour of the player's balls (a basketball's orange), and of those released too high to score. */
const PLAYER_COLOR = 0xff8a2a;
const HIGH_COLOR = 0x9aa4b5;
const BEST_KEY = 'bitphysics.bouncing-balls.best';

/** The best score kept in local storage (0 when none, or storage is unavailable). */
function readBest(): number {
  try {
    const v = Number(localStorage.getItem(BEST_KEY));
    return Number.isInteger(v) && v > 0 ? v : 0;
  } catch {
    return 0;
  }
}
let best = readBest();
/** A basket's pop: where (m) and the world time (s) it was scored, for the flash and the +1. */
let lastBasket = { x: 0, y: 0, time: -10 };

/** Builds a fresh world with the scene from the current params (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const options = {
    count: params.count,
    seed: params.seed,
    gravity: params.gravity,
    restitution: params.restitution,
    friction: params.friction,
    drag: params.drag,
    dragK: params.dragK,
    tall: TALL,
  };
  const world = createPhysicsWorld(bouncingBallsWorldOptions(options));
  handles = buildBouncingBalls(world, options);
  crates = [];
  round = createRound(roundSeconds);
  playerBalls = new Map();
  lastBasket = { x: 0, y: 0, time: -10 };
  hoopIds = addHoop(world, hoopSpots(TALL)[0]!, params.restitution, params.friction);
  return world;
}

/** Drops a crate (a box of about two mean ball diameters, turned a little) near the top of the box. */
function dropCrate(): number {
  const r = handles.meanRadius,
    n = crates.length;
  const { box } = layoutOf(TALL);
  const span = box.max[0] - box.min[0] - 8;
  const crate = addBox(shell.world, {
    position: [box.min[0] + 4 + ((n * 2.7) % span), box.max[1] - 1],
    angle: 0.4 * ((n % 5) - 2),
    halfExtents: [2 * r, 1.4 * r],
    density: 1 / (Math.PI * r * r),
    restitution: params.restitution,
    friction: params.friction,
  });
  crates.push(crate);
  return crate;
}

/** Trail settings: one trail per ball up to 400 balls (36 frames long). */
function trailOptions(count: number) {
  return { length: 36, maxEntities: Math.min(400, Math.max(1, count + 200)) };
}

const sound = getSound();

/** What a body sounds like: a crate wood, a heavy ball metal, the others rubber; walls stone. */
function materialOf(world: PhysicsWorld, body: number): SoundMaterial {
  if (body <= 0) return 'stone';
  if (crates.includes(body)) return 'wood';
  return isHeavy(world, body) ? 'metal' : 'soft';
}

/**
 * The hoop game after a step: a player's ball whose centre went down through the hoop's opening is a
 * basket (the ball is taken out, the hoop moves on); then the clock runs. Keeps the best score.
 */
function playHoop(world: PhysicsWorld): void {
  const P = world.components.Position;
  const spots = hoopSpots(TALL);
  let opening = hoopOpening(spots[round.spot]!);
  for (const [e, b] of playerBalls) {
    if (!handles.balls.includes(e)) {
      playerBalls.delete(e);
      continue;
    }
    const x = P.x[slotOf(e)]!,
      y = P.y[slotOf(e)]!;
    const crossing = hoopCrossing(opening, b.x, b.y, x, y);
    if (crossing === 1 && b.scores) {
      // Up through the hoop from below: no basket when it comes back down.
      b.scores = false;
      renderer.setColor(e, HIGH_COLOR);
      tooHighAt = performance.now();
      hintReason = 'below';
    }
    if (b.scores && crossing === -1 && roundBasket(round, spots.length)) {
      lastBasket = { x: opening.minX + 0.5 * (opening.maxX - opening.minX), y: opening.y, time: world.time };
      playerBalls.delete(e);
      removeBall(world, handles, e);
      removeHoop(world, hoopIds);
      hoopIds = addHoop(world, spots[round.spot]!, handles.params.restitution, handles.params.friction);
      opening = hoopOpening(spots[round.spot]!);
      sound.chime(660 + 60 * Math.min(10, round.score));
      keepBest();
      continue;
    }
    b.x = x;
    b.y = y;
  }
  if (roundTick(round, world.dt)) {
    keepBest();
    sound.chime(440, 0.6);
  }
}

/** Keeps the round's score as the best if it beats it (in localStorage when it can). */
function keepBest(): void {
  if (round.score <= best) return;
  best = round.score;
  try {
    localStorage.setItem(BEST_KEY, String(best));
  } catch {
    /* private mode: kept for this page only */
  }
}

/** One step, then a knock for each impact: loudness from its impulse, the harder of the two materials. */
function stepWorld(world: PhysicsWorld): void {
  step(world);
  playHoop(world);
  forEachImpact(world, (a, b, impulse) => {
    const ma = materialOf(world, a),
      mb = materialOf(world, b);
    const m = ma === 'metal' || mb === 'metal' ? 'metal' : ma === 'wood' || mb === 'wood' ? 'wood' : ma === 'soft' ? mb : ma;
    sound.impact(impulse, m, { threshold: 0.5, loud: 20 });
  });
}

const game = await startPixiGame({
  title: 'Bouncing balls',
  createWorld,
  step: stepWorld,
  bodies: () => handles.balls.length,
  controls: [
    { keys: 'Drag', action: 'pull back and let go: throw a ball (through the hoop scores)' },
    { keys: 'Click', action: 'drop a ball (empty space)' },
    { keys: 'Drag a body', action: 'pull a ball or crate' },
    { keys: 'R', action: 'new round (and reset)' },
    { keys: 'T', action: 'trails on / off' },
    { keys: 'D', action: 'debug: velocities, contacts' },
    { keys: 'X', action: 'drop a crate' },
  ],
  keys: [
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: 'd', label: 'debug', action: () => setDebug(!params.debug) },
    { key: 'x', label: 'crate', action: () => dropCrate() },
  ],
  renderer: {
    view: 'boundary',
    balls: mode,
    trails: params.trails ? trailOptions(params.count) : false,
    debug: params.debug,
  },
  onFrame: () => {
    drawPointer();
    drawHoop();
  },
});
const { shell, renderer, app } = game;

/** Gives the heavy balls of `world` their user colour (the others keep their seeded colours). */
function colorHeavy(world: PhysicsWorld): void {
  for (const e of handles.balls) if (isHeavy(world, e)) renderer.setColor(e, HEAVY_COLOR);
}
colorHeavy(shell.world);
shell.onWorldChange((world) => colorHeavy(world));

/** Sets restitution and friction of the scene and of the hoop (the panel). */
function setMaterial(restitution: number, friction: number): void {
  applyMaterial(shell.world, handles, restitution, friction);
  for (const e of hoopIds) setBodyMaterial(shell.world, e, { restitution, friction });
}

/** Turns trails on or off (the T key and the panel). */
function setTrails(on: boolean): void {
  params.trails = on;
  renderer.setTrails(on ? trailOptions(params.count) : false);
  panel.refresh();
}

/** Turns the debug overlay on or off (the D key and the panel). */
function setDebug(on: boolean): void {
  params.debug = on;
  renderer.setDebug(on);
  panel.refresh();
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
      onChange: (g) => applyGravity(shell.world, handles, g),
    },
    {
      type: 'slider',
      key: 'restitution',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (e, p) => setMaterial(e, p.friction),
    },
    {
      type: 'slider',
      key: 'friction',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (mu, p) => setMaterial(p.restitution, mu),
    },
    { type: 'choice', key: 'drag', options: DRAG_MODES, onChange: (m, p) => applyDrag(shell.world, handles, m as DragMode, p.dragK) },
    {
      type: 'slider',
      key: 'dragK',
      label: 'drag k (kg/s | kg/m)',
      min: 0,
      max: 2,
      step: 0.01,
      onChange: (k, p) => applyDrag(shell.world, handles, p.drag, k),
    },
    {
      type: 'slider',
      key: 'count',
      label: 'balls (rebuilds)',
      min: 1,
      max: 6000,
      step: 1,
      onRelease: true,
      onChange: () => {
        shell.reset();
        if (params.trails) renderer.setTrails(trailOptions(params.count));
      },
    },
    { type: 'checkbox', key: 'trails', onChange: (v) => setTrails(v === true) },
    { type: 'checkbox', key: 'debug', label: 'debug overlay', onChange: (v) => setDebug(v === true) },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Bouncing balls' },
);

// ---- Pointer: a press on a body drags it; elsewhere a click drops, a drag throws -----------------

const canvas = app.canvas;
// Registered before the drop/throw listeners, so a press that grabs a body is seen as taken there.
// Reach 0.6 mean radii: a ball grabs within that of its edge, a crate (a box, no radius) within that of
// its centre, so a press between the balls (a phone's box is crowded with them) throws rather than grabs.
const drag = enableMouseDrag(
  canvas,
  () => shell.world,
  () => renderer.camera,
  { reach: 0.6 * meanRadiusFor(params.count) },
);

const overlay = new Graphics({ label: 'pointer' });
app.stage.addChild(overlay);
let pointerId = -1;
/** Where the press began (the ball's spot) and where the pointer is now, CSS px on the canvas. */
let startX = 0,
  startY = 0,
  lastX = 0,
  lastY = 0;
let dragged = false;

/** The pointer position in CSS px relative to the canvas' top-left corner. */
function local(event: PointerEvent): [number, number] {
  const rect = canvas.getBoundingClientRect();
  return [event.clientX - rect.left, event.clientY - rect.top];
}

/**
 * The pull, px, that throws at full speed (MAX_THROW_SPEED): 30 % of the canvas' shorter side, within
 * [110, 220] px, so a phone's thumb reaches it without leaving the screen.
 */
function fullPull(): number {
  return Math.min(220, Math.max(110, 0.3 * Math.min(canvas.clientWidth || innerWidth, canvas.clientHeight || innerHeight)));
}

/** The throw the pointer would make now: start (m) and velocity (m/s) of the slingshot. */
function currentThrow(): { x: number; y: number; vx: number; vy: number } {
  const cam = renderer.camera;
  const [vx, vy] = slingVelocity(lastX - startX, lastY - startY, fullPull());
  return { x: cam.toWorldX(startX), y: cam.toWorldY(startY), vx, vy };
}

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || pointerId !== -1 || drag.joint !== 0) return;
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  [startX, startY] = local(event);
  lastX = startX;
  lastY = startY;
  dragged = false;
});

canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pointerId) return;
  [lastX, lastY] = local(event);
  if (Math.hypot(lastX - startX, lastY - startY) > CLICK_SLOP) dragged = true;
});

/** Pointer released: a click drops a ball where it was pressed; a pull throws one from there, slingshot-style. */
function release(event: PointerEvent, cancelled: boolean): void {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  if (cancelled) return;
  [lastX, lastY] = local(event);
  const t = currentThrow();
  if (!dragged) shoot(t.x, t.y, 0, 0);
  else shoot(t.x, t.y, t.vx, t.vy);
}

/**
 * A player's ball at (x, y), m, with velocity (vx, vy), m/s: orange if released below the rim (it may
 * score), grey if not; starts the round's clock. @returns its id.
 */
function shoot(x: number, y: number, vx: number, vy: number): number {
  const e = spawnBall(shell.world, handles, x, y, vx, vy, PLAYER_RADIUS);
  const P = shell.world.components.Position;
  const bx = P.x[slotOf(e)]!,
    by = P.y[slotOf(e)]!;
  const scores = mayScore(hoopSpots(TALL)[round.spot]!, by);
  playerBalls.set(e, { scores, x: bx, y: by });
  renderer.setColor(e, scores ? PLAYER_COLOR : HIGH_COLOR);
  if (round.phase !== 'over') {
    roundShot(round);
    if (!scores) {
      tooHighAt = performance.now();
      hintReason = 'high';
    }
  }
  return e;
}
canvas.addEventListener('pointerup', (event) => release(event, false));
canvas.addEventListener('pointercancel', (event) => release(event, true));

/** The dotted arc of the throw the pointer would make now: its points, m (flat x, y pairs), or [] when not pulling. */
function aimPath(): number[] {
  if (pointerId === -1 || !dragged) return [];
  const t = currentThrow();
  const p = handles.params;
  return throwPath(t.x, t.y, t.vx, t.vy, {
    gravity: p.gravity,
    drag: p.drag,
    k: p.dragK,
    mass: Math.PI * PLAYER_RADIUS * PLAYER_RADIUS * DENSITIES.normal,
    radius: PLAYER_RADIUS,
    box: layoutOf(TALL).box,
  });
}

/**
 * Draws the pointer preview: the ball to be dropped; while pulling, the ball at its spot (orange if
 * it may score, grey if above the rim's line), the slingshot's band to the pointer, and a dotted arc
 * of where the ball will fly, its dots fading along it.
 */
function drawPointer(): void {
  overlay.clear();
  if (pointerId === -1) return;
  const cam = renderer.camera;
  const r = cam.toScreenLength(PLAYER_RADIUS);
  const scores = mayScore(hoopSpots(TALL)[round.spot]!, cam.toWorldY(startY));
  const color = scores ? PLAYER_COLOR : HIGH_COLOR;
  if (!dragged) {
    overlay.circle(startX, startY, r).stroke({ width: 2, color: 0xffffff, alpha: 0.6 });
    return;
  }
  overlay.moveTo(startX, startY).lineTo(lastX, lastY).stroke({ width: 3, color: 0xffffff, alpha: 0.6 });
  overlay.circle(lastX, lastY, 5).fill({ color: 0xffffff, alpha: 0.5 });
  const path = aimPath();
  const n = path.length / 2;
  for (let i = 1; i < n; i++) {
    const f = i / n;
    overlay
      .circle(cam.toScreenX(path[2 * i]!), cam.toScreenY(path[2 * i + 1]!), Math.max(3, 0.32 * r * (1 - 0.4 * f)))
      .fill({ color, alpha: 1 - 0.55 * f })
      .stroke({ width: 1.5, color: 0x0b0f16, alpha: 0.8 - 0.4 * f });
  }
  overlay.circle(startX, startY, r).fill({ color, alpha: 0.85 }).stroke({ width: 2, color: 0xffffff, alpha: 0.9 });
}

// ---- The hoop game: net, shot line, basket pop, status row and the play-again button -------------

const hoopLayer = new Graphics({ label: 'hoop' });
app.stage.addChild(hoopLayer);
const popText = new Text({ text: '+1', style: { fontFamily: 'system-ui, sans-serif', fontSize: 28, fontWeight: '700', fill: 0xffd166 } });
popText.anchor.set(0.5, 1);
popText.visible = false;
app.stage.addChild(popText);
/** When a ball was last released too high to score (performance.now() ms), for the status row's reminder. */
let tooHighAt = -1e9;
/** Why the last ball cannot score: released above the line, or went up through the hoop from below. */
let hintReason: 'high' | 'below' = 'high';

/** Draws the net under the rim, the rim's opening, the dashed shot line at rim height and a basket's pop. */
function drawHoop(): void {
  const cam = renderer.camera;
  const world = shell.world;
  const spot = hoopSpots(TALL)[round.spot]!;
  const o = hoopOpening(spot);
  const { box } = layoutOf(TALL);
  hoopLayer.clear();
  // The shot line: balls released below it may score.
  const yLine = cam.toScreenY(o.y);
  const dash = 10;
  for (let x = cam.toScreenX(box.min[0]); x < cam.toScreenX(box.max[0]); x += 2 * dash)
    hoopLayer.moveTo(x, yLine).lineTo(Math.min(x + dash, cam.toScreenX(box.max[0])), yLine);
  hoopLayer.stroke({ width: 1, color: 0xff8a2a, alpha: 0.35 });
  // The net: strings from the rim down to a narrower bottom, 1.1 m below, and two cross rows.
  const depth = 1.1,
    narrow = 0.3;
  const L = o.minX,
    R = o.maxX;
  for (let k = 0; k <= 4; k++) {
    const t = k / 4;
    const xTop = L + t * (R - L),
      xBottom = L + narrow + t * (R - L - 2 * narrow);
    hoopLayer.moveTo(cam.toScreenX(xTop), cam.toScreenY(o.y)).lineTo(cam.toScreenX(xBottom), cam.toScreenY(o.y - depth));
  }
  for (const f of [0.5, 1]) {
    const inset = narrow * f;
    hoopLayer
      .moveTo(cam.toScreenX(L + inset), cam.toScreenY(o.y - depth * f))
      .lineTo(cam.toScreenX(R - inset), cam.toScreenY(o.y - depth * f));
  }
  hoopLayer.stroke({ width: 1.5, color: 0xf2f5f9, alpha: 0.7 });
  // The rim across the opening (drawn only: balls pass through it).
  hoopLayer.moveTo(cam.toScreenX(L), cam.toScreenY(o.y)).lineTo(cam.toScreenX(R), cam.toScreenY(o.y)).stroke({ width: 3, color: 0xff6a1a });
  // A basket: a ring that widens and fades over 0.8 s, and a rising +1.
  const age = world.time - lastBasket.time;
  popText.visible = age >= 0 && age < 0.8;
  if (popText.visible) {
    const f = age / 0.8;
    const x = cam.toScreenX(lastBasket.x),
      y = cam.toScreenY(lastBasket.y);
    hoopLayer.circle(x, y, cam.toScreenLength(0.6 + 1.6 * f)).stroke({ width: 3, color: 0xffd166, alpha: 1 - f });
    popText.position.set(x, y - 10 - 40 * f);
    popText.alpha = 1 - f;
  }
  updateStatus();
}

const status = createStatusRow({ name: 'hoop' });
const touch = pageLayout().touch();
/** The big Play-again button when time is up: over the top of the box, clear of the balls piled at its bottom. */
const setAction = createActionButton('Play again ▶', () => shell.reset(), { at: 'top' });

/** Writes the status row (goal, baskets, time, best, a hint) when it changed, and shows Play again when time is up. */
function updateStatus(): void {
  const secs = Math.ceil(round.timeLeft);
  const over = round.phase === 'over';
  const goal = over
    ? `Time! ${round.score} ${round.score === 1 ? 'basket' : 'baskets'}${round.score > 0 && round.score >= best ? ' — best yet!' : ''}`
    : `Throw balls through the hoop! ${round.seconds} s`;
  const numbers = `Baskets ${round.score} · Time ${secs} s · Best ${best}`;
  const throwHow = touch ? 'Press, pull back and let go to throw' : 'Press, drag back and let go to throw';
  const hint = over
    ? `${touch ? 'Tap' : 'R or'} Play again for a new round`
    : performance.now() - tooHighAt < 2500
      ? hintReason === 'high'
        ? 'Too high: throw from below the orange line to score'
        : 'Up through the net does not count: drop it in from above'
      : round.phase === 'ready'
        ? `${throwHow} from below the orange line · the clock starts with your first ball`
        : `${throwHow} · the hoop moves after each basket`;
  if (status.set({ goal, numbers, hint }, over)) setAction(over);
}

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  /** The pointer's mouse-joint drag: `joint` (0 when nothing is held) and `body`. */
  drag,
  /** Entity ids of the balls, oldest first (a copy). */
  ballIds: (): number[] => handles.balls.slice(),
  /** Entity ids of the crates dropped with X, oldest first (a copy). */
  crateIds: (): number[] => crates.slice(),
  /** Ball positions, m, flat [x0, y0, x1, y1, ...] in `ballIds` order. */
  positions: (): number[] => {
    const P = shell.world.components.Position;
    const out: number[] = [];
    for (const e of handles.balls) out.push(P.x[slotOf(e)]!, P.y[slotOf(e)]!);
    return out;
  },
  /** Adds a ball at (x, y) m with velocity (vx, vy) m/s; returns its id. */
  spawn: (x: number, y: number, vx = 0, vy = 0): number => spawnBall(shell.world, handles, x, y, vx, vy),
  /** The hoop game's round (a copy): phase, score, timeLeft (s), spot index, shots. */
  round: (): HoopRound => ({ ...round }),
  /** The best score kept (localStorage). */
  best: (): number => best,
  /** The hoop's opening now: rim height y and the x range, m. */
  hoop: () => hoopOpening(hoopSpots(TALL)[round.spot]!),
  /** A player's ball at (x, y) m with velocity (vx, vy) m/s, as a throw releases it (counts for the hoop). @returns its id. */
  shoot: (x: number, y: number, vx = 0, vy = 0): number => shoot(x, y, vx, vy),
  /** The dotted arc drawn while pulling a throw: its points, m (flat x, y pairs), or [] when not pulling. */
  aimPath: (): number[] => aimPath(),
  /** The status row's text (goal, numbers, hint). */
  statusText: (): string => status.element.innerText,
  /** Removes ball `eid`. @throws RangeError if it is not a ball of the scene. */
  remove: (eid: number): void => removeBall(shell.world, handles, eid),
});
