/**
 * Catapult: drag back from the catapult's cup and release to throw a stone at a castle of wooden
 * posts and planks, glass and stone, glued by breakable welds. A dashed arc shows the drag-free
 * path. Score: 100 a fallen piece, 25 a broken weld; a few shots a level, nine seeded levels of
 * their own shapes (towers, a glass hall, a keep on stone, a bridge, a hill fort, a pit, a fortress;
 * see ./scene LEVELS). The last throw leaves a trail of dots and a word on what it did.
 *
 * Input: drag from the cup and release. Keys: L next level, R reset the level, P pause, N step.
 * A "Next level" button under the scene when the level is over (touch and mouse).
 * Sound: a whoosh per throw; impacts as loud as their impulse, wood for posts and planks, glass for
 * glass, stone for stone blocks, stones and the projectile.
 * URL: ?level=1..9, ?seed=S, ?demo (the catapult throws one stone at the castle by itself, at 0.3 s:
 * the gallery's thumbnail shows a hit).
 */

import {
  choiceParam,
  createActionButton,
  createButtonBar,
  createPanel,
  flagParam,
  forEachImpact,
  getSound,
  isTouchDevice,
  numberParam,
  pageLayout,
  pauseUnderDrawers,
  pointerOnCanvas,
  type SoundMaterial,
  seedParam,
} from '@bitphysics/game-kit';
import { createReadout } from '@bitphysics/game-kit/lab-kit';
import { createPauseOverlay, startPixiGame } from '@bitphysics/game-kit/pixi';
import { contactEvents, createPhysicsWorld, isAlive, type PhysicsWorld, Rng, slotOf, step, warmUp } from '@bitphysics/physics';
import { Container, Graphics, Matrix, RenderTexture, Sprite, Text } from 'pixi.js';
import { type Box, placeAimLabel } from './aim-label';
import {
  aimCloseUp,
  type CameraShot,
  cameraShot,
  easeShare,
  type Field,
  OPENING_FRAMES,
  PLAY_SKY,
  PLAY_TOP,
  rockRight as rockRightOf,
  UPRIGHT_GROUND,
  UPRIGHT_WATCH,
  uprightAimView,
  uprightCastleView,
  uprightFollowView,
  uprightOpeningView,
  type View,
  type WideViews,
  wideViews,
} from './camera';
import { distanceMarks } from './distance';
import { type DebrisKind, Effects } from './effects';
import {
  CATAPULT,
  cupAt,
  drawBrick,
  drawCatapult,
  drawGlass,
  drawHill,
  drawMound,
  drawPit,
  drawShot,
  drawStone,
  drawWood,
  mixColor,
  SHOT_COLOR,
} from './look';
import { fullPullPx as fullPullFor, type InsetPlace, insetBesidePull } from './pull';
import {
  angleForRange,
  buildLevel,
  countedDown,
  cutArc,
  FALL_POINTS,
  flightPast,
  LAUNCH,
  LEVEL_COUNT,
  type Level,
  launch,
  launchVelocity,
  MISSES_FOR_FULL,
  MISSES_FOR_MORE,
  type Piece,
  PROJECTILE_RADIUS,
  PULL,
  previewFlight,
  previewLimit,
  ROCK,
  surfaceAt,
  type Tally,
  tally,
  worldOptions,
} from './scene';

const params = {
  level: numberParam('level', { default: 1, min: 1, max: LEVEL_COUNT, integer: true }),
  seed: seedParam(),
  projectileMass: 3,
  gravity: 9.81,
  jointStrength: 400,
  /**
   * The aim preview: 'auto' draws only the start of the flight (scene previewShare: half the way to
   * the castle on the first level, 40 % on the others), reaching farther after repeated misses at a
   * level; 'full' the whole flight on every level (URL `guide=full`: an easier game, and the tests
   * that match the preview to the throw).
   */
  guide: choiceParam('guide', ['auto', 'full'] as const, 'auto'),
  reset: () => game.shell.reset(),
  next: () => nextLevel(),
};

/** The effects of hits (dust, splinters, popups, shake); made once the renderer is up. */
let effects: Effects | null = null;
let lv: Level = {
  name: '',
  pieces: [],
  joints: [],
  jointBodies: [],
  shots: 0,
  castleMinX: 0,
  castleMaxX: 0,
  castleTop: 0,
  ground: 0,
  terrain: [],
  mound: 0,
  rock: 0,
};
let shotsLeft = 0;
/** The stones' mass on the level on screen, kg: the panel's, read when the level starts (a change starts it again). */
let levelMass = params.projectileMass;
let shots: number[] = [];
let best: Tally = { fallen: 0, broken: 0, score: 0 };
let lastShotTime = 0;

/**
 * The last throw, so a player sees what it did: its path (x, y pairs, m) stays on screen as a trail
 * of dots until the next throw, and once it has settled a word over the scene says what it earned
 * ("+450") or why it missed (short of the castle, over it, or too soft to knock anything down).
 */
const lastThrow = {
  body: 0,
  path: [] as number[],
  scoreBefore: 0,
  /** Farthest x (m) the throw reached above the ground's level (where it came down, once it did). */
  farthest: 0,
  /** Launch velocity, m/s. */
  vx: 0,
  vy: 0,
  /** Power (0 to 1) and angle (degrees above level) of the throw, shown beside the next aim's. */
  power: 0,
  angle: 0,
  /** World time of the throw, s. */
  time: 0,
  /** What the throw did ('' until it settles), where to show it (m) and when it was decided (s). */
  verdict: '',
  /** A miss in brief ('long 6 m', 'short 3 m', 'fell in a gap'; '' for a hit or before the verdict), shown with the last throw's numbers while aiming. */
  brief: '',
  good: false,
  at: [0, 0] as [number, number],
  decidedAt: 0,
  /** For a throw judged long, how far past the castle it came down, whole m (the verdict's and the off-screen label's number); else 0. */
  pastBy: 0,
  /** Set when the player starts aiming again: the off-screen marker goes (the trail stays as a guide). */
  hidden: false,
  /**
   * What the throw's stone first touched of the castle and what stands before it: a castle piece's
   * kind, 'hill' for a bank of earth (a hill fort's mound, the earth pillar before a keep), '' while
   * it has touched neither.
   */
  touched: '' as Piece['kind'] | 'hill' | '',
  /**
   * The step in which the stone first touched anything (the ground, the rock, a piece): where it was
   * before and after that step, m [x0, y0, x1, y1]; null until it has.
   */
  touchStep: null as [number, number, number, number] | null,
  /** The body the stone first touched (a piece, the ground, a bank, the rock); 0 until it has. */
  firstBody: 0,
};
/** What the player calls each kind of castle piece and a bank of earth, in a throw's verdict. */
const PIECE_NAME: Record<Piece['kind'] | 'hill', string> = {
  hill: 'the earth bank',
  post: 'a wooden post',
  plank: 'a plank',
  block: 'the glass',
  brick: 'a stone block',
  stone: 'a stone',
};
/**
 * Throws at the level on screen that brought nothing down, over all its tries since the player came
 * to it (a restart keeps the count, another level starts it afresh): the aim preview reaches farther
 * as they add up (scene previewShare).
 */
const misses = { level: 0, count: 0 };
/** A fresh world with the current level (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  // Once a page: the physics code compiled while the page loads, not in the level's first frames.
  warmUp(2);
  const world = createPhysicsWorld(worldOptions(params));
  lv = buildLevel(world, { level: params.level - 1, seed: params.seed, gravity: params.gravity, jointStrength: params.jointStrength });
  levelMass = params.projectileMass;
  // Misses count over a level's tries: a new level starts the count afresh (previewReach).
  if (misses.level !== params.level) {
    misses.level = params.level;
    misses.count = 0;
  }
  shotsLeft = lv.shots;
  shots = [];
  best = { fallen: 0, broken: 0, score: 0 };
  lastShotTime = 0;
  lastThrow.body = 0;
  lastThrow.path.length = 0;
  lastThrow.verdict = '';
  lastThrow.hidden = false;
  levelEnded = false;
  // A fresh try at a level drops what earlier tries on it scored, so Total is back to its value at
  // the level's start and retries cannot pile up points.
  campaign.scores[params.level - 1] = 0;
  campaign.stars[params.level - 1] = 0;
  materials.clear();
  for (const p of lv.pieces)
    materials.set(p.body, p.kind === 'post' || p.kind === 'plank' ? 'wood' : p.kind === 'block' ? 'glass' : 'stone');
  terrainBodies.clear();
  for (const t of lv.terrain) terrainBodies.add(t.body);
  popped.clear();
  celebrated = false;
  weldsHeld.length = 0;
  for (let i = 0; i < lv.joints.length; i++) weldsHeld.push(true);
  effects?.clear();
  arm.angle = CATAPULT.cocked;
  arm.velocity = 0;
  arm.firedAt = Number.NEGATIVE_INFINITY;
  lastDrawTime = 0;
  return world;
}

/**
 * The catapult's arm: its angle (rad, see CATAPULT) and angular velocity (rad/s), and the world time
 * of the last throw (s). It follows the pull while aiming, swings forward to the crossbar on a throw
 * and, RELOAD s later, swings back with the next stone in its cup.
 */
const arm = { angle: CATAPULT.cocked as number, velocity: 0, firedAt: Number.NEGATIVE_INFINITY };
/** Seconds from a throw until the arm swings back to load the next stone. */
const RELOAD = 0.8;
/** World time of the last frame drawn, s (effects and the arm advance by the world's time, so a pause stops them). */
let lastDrawTime = 0;

/** Whether the catapult throws one stone by itself (?demo). */
const DEMO = flagParam('demo');
/** The level's terrain bodies (its ground slabs, hill, pit floor): a hit on them raises dust. */
const terrainBodies = new Set<number>();
/** Sound material of each piece's body; the projectiles and the ground sound as stone. */
const materials = new Map<number, SoundMaterial>();
const sound = getSound();
/** Pieces whose fall has been shown (a popup and a puff), by body handle. */
const popped = new Set<number>();
/** Whether each weld of the level held at the last frame (a break throws splinters once). */
const weldsHeld: boolean[] = [];
/** Debris kind a material's bits are. */
const DEBRIS: Record<SoundMaterial, DebrisKind> = { wood: 'wood', glass: 'glass', stone: 'stone', metal: 'stone', soft: 'dust' };

/**
 * One step, then for each impact a sound (wood over glass over stone, the louder material of the two
 * bodies, as loud as the impulse) and what it throws up where the bodies met: dust where something
 * lands on the grass, splinters, shards or chips of what a stone hits, and a shake of the camera
 * for a hard hit by a thrown stone (its size from the approach speed).
 */
function stepWorld(world: PhysicsWorld): void {
  const flying = lastThrow.body !== 0 && lastThrow.touchStep === null && isAlive(world, lastThrow.body);
  const before = flying ? positionOf(lastThrow.body) : null;
  step(world);
  if (DEMO && shots.length === 0 && world.time > 0.3) {
    // At the castle's front at 19 m/s, the low angle.
    const th = angleForRange(lv.castleMinX + 0.6 - LAUNCH.x, 19, -world.gravity[1]!);
    fire(-(19 / PULL.gain) * Math.cos(th), -(19 / PULL.gain) * Math.sin(th));
  }
  const material = (b: number): SoundMaterial => materials.get(b) ?? 'stone';
  forEachImpact(world, (a, b, impulse) => {
    const ma = material(a),
      mb = material(b);
    const m = ma === 'wood' || mb === 'wood' ? 'wood' : ma === 'glass' || mb === 'glass' ? 'glass' : 'stone';
    sound.impact(impulse, m, { threshold: 2, loud: 60 });
  });
  // The first castle piece the last throw's stone touches: its verdict says it hit that piece, not
  // that it fell short or long of the castle.
  const touch = contactEvents(world).begin;
  for (let i = 0; before && lastThrow.touchStep === null && i < touch.count; i++)
    if (touch.bodyA[i] === lastThrow.body || touch.bodyB[i] === lastThrow.body) {
      lastThrow.touchStep = [...before, ...positionOf(lastThrow.body)];
      lastThrow.firstBody = touch.bodyA[i] === lastThrow.body ? touch.bodyB[i]! : touch.bodyA[i]!;
    }
  for (let i = 0; lastThrow.body !== 0 && lastThrow.touched === '' && i < touch.count; i++) {
    const a = touch.bodyA[i]!,
      b = touch.bodyB[i]!;
    const other = a === lastThrow.body ? b : b === lastThrow.body ? a : 0;
    const piece = other === 0 ? undefined : lv.pieces.find((p) => p.body === other);
    if (piece) lastThrow.touched = piece.kind;
    else if (other !== 0 && lv.terrain.some((t) => t.body === other && t.kind === 'hill')) lastThrow.touched = 'hill';
  }
  if (!effects) return;
  const ev = contactEvents(world).begin;
  for (let i = 0; i < ev.count; i++) {
    const a = ev.bodyA[i]!,
      b = ev.bodyB[i]!,
      v = ev.approachSpeed[i]!,
      x = ev.px[i]!,
      y = ev.py[i]!;
    if (v < 2.5) continue;
    const stoneA = shots.includes(a),
      stoneB = shots.includes(b);
    const ground = terrainBodies.has(a) || terrainBodies.has(b);
    if (ground) effects.burst('dust', x, y, Math.min(12, Math.round(2 + v)), 1.5 + 0.3 * v);
    for (const [body, hitByStone] of [
      [a, stoneB],
      [b, stoneA],
    ] as const) {
      if (!materials.has(body)) continue;
      const n = Math.min(hitByStone ? 9 : 4, Math.round((hitByStone ? 2 : 0) + v / (hitByStone ? 2 : 4)));
      effects.burst(DEBRIS[material(body)], x, y, n, 1 + 0.45 * v, -ev.nx[i]! * (body === a ? 1 : -1), 0.8);
    }
    if (stoneA || stoneB) effects.shake(Math.min(12, 1.2 * v));
  }
}

/**
 * The campaign: each level's best score and stars once it is over, and the total. A level is cleared
 * when at least PASS_SHARE of its pieces fell (one star; two from 75 %, three from 95 %), with
 * SHOT_BONUS points for each shot not thrown when three stars' worth is down; it ends once the
 * shots are spent or three stars' worth is down, 4 s after the last throw. A level not cleared is played again, and after the last level
 * the end screen shows the total.
 */
const PASS_SHARE = 0.5;
const campaign = { scores: new Array<number>(LEVEL_COUNT).fill(0), stars: new Array<number>(LEVEL_COUNT).fill(0) };
const starsOf = (share: number): number => (share >= 0.95 ? 3 : share >= 0.75 ? 2 : share >= PASS_SHARE ? 1 : 0);
const total = (): number => campaign.scores.reduce((a, b) => a + b, 0);
/**
 * Share of the level's pieces that count (`countsTowardStars`: all but a bottom row lying flat on
 * the ground) marked down by the last tally, in [0, 1]: what the stars and the clear are judged on.
 */
const downShare = (): number => {
  const c = countedDown(lv);
  return c.of === 0 ? 1 : c.down / c.of;
};
/**
 * What "down" means, as the player is told, in one short line: the rule of scene.ts hasFallen (a
 * drop of DROP_SHARE of a piece's height, a lean past TIP_ANGLE, a knock of KNOCK_DISTANCE) and
 * countsTowardStars in brief; a piece that counts turns darker, which tells the rest (a flat bottom
 * row, a small knock) as the player plays. The long form named every case and took two lines of the
 * banner and four of a phone's help.
 */
const DOWN_RULE = 'Down: fallen, leaning 30° or knocked aside (it darkens)';
const DOWN_RULE_SHORT = 'Down: fallen or leaning 30° (darkens)';
/** The same rule in the controls' help (after a "Stars" cap): what the stars count, one line on a phone. */
const DOWN_HELP = 'pieces down: fallen or leaning 30°';
/**
 * The banner's type size on an upright phone, px: with the short rules a level's start is two lines
 * on a 390 px phone.
 */
const BANNER_FONT_UPRIGHT = 15;
/**
 * What earns the stars, shown on the level's start hint and its end card (no-break spaces inside each
 * entry: a narrow screen wraps between entries, not inside one), and its short form for a narrow
 * screen (a phone held upright), which fits on one line there.
 */
const STAR_RULE = ['★ half the pieces down', '★★ 75 %', '★★★ 95 %'].map((e) => e.replaceAll(' ', '\u00a0')).join('   ');
const STAR_RULE_SHORT = ['★ 50 %', '★★ 75 %', '★★★ 95 %\u00a0down'].map((e) => e.replaceAll(' ', '\u00a0')).join('  ');

/** The next level after a clear, the same one again after a miss, level 1 (a new campaign) after the end. */
function nextLevel(): void {
  // A level cleared with shots to spare ends here, its score and stars counted, when the player moves on.
  if (!levelEnded && clearedEarly(shell.world)) {
    recordLevel(tally(shell.world, lv));
    // After the last level the end screen shows first; the next press starts a new campaign.
    if (params.level === LEVEL_COUNT) return;
  }
  const finished = levelEnded;
  const cleared = finished && campaign.stars[params.level - 1]! > 0;
  if (finished && !cleared) {
    game.shell.reset();
    return;
  }
  if (params.level === LEVEL_COUNT) {
    campaign.scores.fill(0);
    campaign.stars.fill(0);
  }
  params.level = (params.level % LEVEL_COUNT) + 1;
  panel.refresh();
  game.shell.reset();
}

/** Whether the level on screen is over (its score is in the campaign). */
let levelEnded = false;
/** Whether the camera can be framed (its state exists): set once the page's setup has run. */
let framing = false;

/** Sky, grass (the ground slab) and earth (below it). */
const SKY = 0x9fd0f5,
  GRASS = 0x4f8f3a,
  EARTH = 0x6b4a2e;

/** Whether the main pointer is a finger: touch wording, no key hints. */
const touch = isTouchDevice();
/** A panel label with its key (a phone has no keys: the label alone). */
const withKey = (label: string, key: string): string => (touch ? label : `${label} (${key})`);

/** The folder of the panel's physics knobs: its title says what changing one does. */
const PHYSICS_FOLDER = 'Advanced (restarts level)';
/** How a physics knob applies: in PHYSICS_FOLDER, when the slider is let go, by starting the level again. */
const PHYSICS_KNOB = { folder: PHYSICS_FOLDER, onRelease: true, onChange: () => shell.reset() } as const;

// The panel goes in before the game starts (made after, it would narrow the canvas already drawn and
// the scene jump). It sits in the left column under the controls, closed, so the scene has the
// rest of the width (1060 px at 1280 x 800; a right-hand column would leave it 735 px, taller than wide);
// on a phone it is in the menu drawer.
const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'level',
      label: 'level (rebuilds)',
      min: 1,
      max: LEVEL_COUNT,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'button', key: 'reset', label: withKey('reset level', 'R') },
    { type: 'button', key: 'next', label: withKey('next level', 'L') },
    // The physics knobs change the game: in a closed folder saying so, each applied by starting the
    // level again when the slider is let go (gravity changed in flight turned a throw aimed at the
    // castle into one that fell short, and the level's score was no longer the level's).
    { type: 'slider', key: 'gravity', label: 'gravity (m/s²)', min: 1, max: 30, step: 0.01, ...PHYSICS_KNOB },
    { type: 'slider', key: 'projectileMass', label: 'projectile mass (kg)', min: 0.5, max: 20, step: 0.1, ...PHYSICS_KNOB },
    { type: 'slider', key: 'jointStrength', label: 'weld strength (N)', min: 50, max: 3000, step: 10, ...PHYSICS_KNOB },
  ],
  { title: 'Settings', container: pageLayout().info, closed: !pageLayout().compact() },
);

const game = await startPixiGame({
  title: 'Catapult',
  createWorld,
  step: stepWorld,
  bodies: () => lv.pieces.length + shots.length,
  controls: [
    { keys: 'Drag', action: 'pull back (anywhere), release to throw' },
    { keys: 'L', action: 'next level', touch: 'Next level', card: false },
    { keys: 'Enter', action: 'next level after a clear (try again after a miss)' },
    { keys: 'Stars', action: DOWN_HELP, touch: 'Stars' },
  ],
  keys: [
    { key: 'l', label: 'next level', action: () => nextLevel() },
    // Enter presses the on-screen button, and only while it shows (a cleared or ended level).
    { key: 'Enter', label: 'next level after a clear', action: () => nextShown && nextLevel() },
  ],
  renderer: { view: { minX: -4, minY: -1, maxX: 30, maxY: 14 } },
  app: { background: SKY },
  // The camera moves before the bodies are placed, so they and the overlay share it.
  beforeFrame: () => {
    if (framing) frameCamera();
  },
  onFrame: (alpha, world) => draw(world, alpha),
});
const { shell, renderer, app } = game;

/** Colours of the castle's materials (wood posts and planks, glass blocks, stone), the ground and the mound. */
const MATERIAL_COLORS: Record<Level['pieces'][number]['kind'], number> = {
  post: 0x9a6232,
  plank: 0xc08a4e,
  block: 0xa8dcef,
  brick: 0xa39e94,
  stone: 0x8b929c,
};
// A drawer opened over the scene on a small screen pauses a flying stone and a falling castle.
pauseUnderDrawers(shell, { compactOnly: true });

/** Gives the level's bodies the colours of what they are made of. */
function paint(): void {
  for (const p of lv.pieces) if (isAlive(shell.world, p.body)) renderer.setColor(p.body, MATERIAL_COLORS[p.kind]);
  for (const t of lv.terrain) renderer.setColor(t.body, t.kind === 'ground' ? GRASS : EARTH);
  if (lv.mound) renderer.setColor(lv.mound, 0x7a5533);
  if (lv.rock) renderer.setColor(lv.rock, 0x7d776e);
}
paint();
shell.onWorldChange(() => {
  paint();
  shotView = false;
  framedFor = '';
  peeking = false;
  insetHeld = null;
  // Not at rest until a frame has framed the new level (it may open on its castle).
  cameraSettled = false;
  // A level new to the page opens on its castle (upright: ./camera OPENING_FRAMES); the same level
  // again (a retry) opens on the catapult, the castle already known.
  openingFrames = params.level !== openedLevel ? OPENING_FRAMES : 0;
  openedLevel = params.level;
});

/**
 * The camera has two views. The aim view: on a desktop (./camera wideViews) the field view, the
 * catapult and the whole castle with the ground a fifth of the way up (the shot view, the castle
 * and the rock fitted to the play area's height, follows a throw and shows its verdict); on a sideways phone the whole play area, from just behind the
 * catapult to just past the rock, fitted to the screen's width (a drag aims from anywhere). The
 * shot view: after a throw, the castle and the rock with room for debris around them, where it is
 * closer than the aim view or elsewhere: the camera eases to it while the stone flies and back to
 * the aim view once the throw's verdict has faded, or at once when a finger or the mouse goes down to aim.
 * On a wide view the scene is as tall as the castle needs; on a tall one the ground sits GROUND_AT of
 * the way up the screen, earth below it and sky above. The view eases a tenth of the way each step
 * (./camera easeShare: by the steps since the last frame);
 * it jumps when the screen's size changes.
 *
 * On an upright phone (a screen taller than wide) the camera frames the play for the tall screen,
 * the lowest surface UPRIGHT_GROUND of the way up (UPRIGHT_GROUND_CLOSE where the castle's close-up
 * shows in the earth: ./camera uprightGround; the scene in the screen's lower middle, earth
 * under it for the card saying how to play and the next-level button). Which view it heads for is
 * decided in ./camera (cameraShot), and its rectangle there too: a level new to the page opens on
 * its castle, large (./camera OPENING_FRAMES, uprightOpeningView), and pans across the field to the aim view, close on the catapult (./camera uprightAimView: a large stone, band and arc) with the castle in
 * an inset under the ground and an arrow at the screen's edge saying how far it is (the whole field
 * on a 390 px phone was a thin band, a stone 8 to 12 px, under a tall empty sky); on an upright
 * tablet, where the field is large enough, the aim view holds the catapult and the whole castle and
 * the look button shows the castle close while aiming; in between the
 * camera follows the stone from the aim view to the castle's view as it crosses the field (by the
 * farthest it got), keeping it in sight, and goes back to the aim view once the verdict has been
 * read or at the next press.
 */
const cameraView = { minX: -4, minY: -1, maxX: 30, maxY: 14 };
/**
 * The aim in progress: whether a press is pulling, the pull (dx, dy), m (x right, y up), where
 * the press went down on the canvas, px, and whether the pointer has moved since.
 */
const aim = { active: false, dx: 0, dy: 0, x0: 0, y0: 0, moved: false };
/** On a tall screen, where the ground line sits: this fraction of the screen's height from the bottom. */
const GROUND_AT = 0.18;
/** Screens narrower than this (CSS px) get the tighter aim view. */
const NARROW = 600;
/** Screen size the view was framed for; the view jumps (no easing) when it changes. */
let framedFor = '';
/** Every screen size the view has been framed for since the page loaded (one, unless the window was resized). */
const sizesFramed = new Set<string>();
/** Whether the camera shows the shot view (set by a throw, cleared when the player aims again). */
let shotView = false;
/** Whether the screen is an upright phone's: narrower than NARROW and over 1.2 x as tall as wide. */
const upright = (): boolean => renderer.camera.width < NARROW && renderer.camera.height > 1.2 * renderer.camera.width;
/**
 * Screen pixels at the bottom of the scene that the touch hint ("Drag ...") covers while it shows
 * (0 once it has gone): a wide view puts the ground above it, so the hint lies on the earth and not
 * over the catapult or the castle's foot.
 */
function hintReserve(): number {
  const hint = document.querySelector('[data-hud="touch-hint"]');
  if (!hint) return 0;
  const h = hint.getBoundingClientRect(),
    c = app.canvas.getBoundingClientRect();
  return Math.max(0, c.bottom - h.top + 6);
}
/** The view (m) fitted to the screen for a horizontal span [minX, maxX]: as tall as the screen's aspect allows. */
function viewFor(minX: number, maxX: number): View {
  const cam = renderer.camera;
  const W = Math.max(1, cam.width),
    H = Math.max(1, cam.height);
  const aspect = H / W;
  const height = (maxX - minX) * aspect;
  const top = lv.castleTop + 4;
  // The lowest surface (a pit's floor) shows with 0.6 m of earth under it.
  const floor = Math.min(0, ...lv.terrain.map((t) => t.maxY)) - 0.6;
  // Tall (or a screen taller than wide): the ground GROUND_AT (upright UPRIGHT_GROUND) up, earth below it.
  if (aspect > 1.2 || height > 3 * top) {
    // Upright, the lowest surface (a pit's floor, where the stones and the wreck lie) UPRIGHT_GROUND
    // up: under it lie the card saying how to play and the next-level button, which would otherwise
    // hide a pit's floor.
    const low =
      aspect > 1.2 ? Math.min(0, ...lv.terrain.map((t) => t.maxY)) - UPRIGHT_GROUND * height : Math.min(-GROUND_AT * height, floor);
    return { minX, minY: low, maxX, maxY: Math.max(low + height, top) };
  }
  // Wide: from just under the ground up, taller than the castle; the ground above the touch hint
  // while it shows (R px: R m at the width's scale, or, when the castle's height sets the scale,
  // the depth that leaves R px under the ground with the view's top at `top`).
  const R = hintReserve();
  const minY = Math.min(-1, floor, -(R * (maxX - minX)) / W, R > 0 && R < H ? -(R * top) / (H - R) : -1);
  return { minX, minY, maxX, maxY: Math.max(minY + height, top) };
}
/** What of the level on screen the upright views frame (./camera Field). */
function field(): Field {
  return {
    castleMinX: lv.castleMinX,
    castleMaxX: lv.castleMaxX,
    castleTop: lv.castleTop,
    floor: Math.min(0, ...lv.terrain.map((t) => t.maxY)),
    previewTo: previewReach(),
  };
}
/** The farthest x (m) the aim preview draws now (scene previewLimit, with this level's misses). */
function previewReach(): number {
  return previewLimit(params.level - 1, lv, params.guide === 'full', misses.level === params.level ? misses.count : 0);
}
/** The right face of the rock behind the castle, m. */
const rockRight = (): number => rockRightOf(lv.castleMaxX);
/** Whether the screen is a desktop's: wide enough (NARROW) and not taller than 1.2 x its width (an upright tablet keeps the tall views); its views are ./camera wideViews. */
const desktop = (): boolean => renderer.camera.width >= NARROW && renderer.camera.height <= 1.2 * renderer.camera.width;
/**
 * A desktop's views (./camera wideViews): their foot 0.6 m under the lowest surface and at least 1 m
 * under the ground, lower still by the touch hint's height while it shows (at the play area's scale).
 */
function deskViews(): WideViews {
  const cam = renderer.camera;
  const W = Math.max(1, cam.width),
    H = Math.max(1, cam.height);
  let minY = Math.min(-1, Math.min(0, ...lv.terrain.map((t) => t.maxY)) - 0.6);
  const R = hintReserve();
  if (R > 0 && R < H) minY -= (R * (Math.max(lv.castleTop + PLAY_SKY, PLAY_TOP) - minY)) / (H - R);
  return wideViews(field(), W, H, minY);
}
/** The aim view (see above): upright, close on the catapult, or on a tablet the whole field (./camera uprightAimView); on a desktop the whole field (./camera wideViews). */
function aimView(): View {
  if (upright()) return uprightAimView(field(), renderer.camera.width, renderer.camera.height);
  if (desktop()) {
    const v = deskViews();
    // The whole field: the catapult and its target in view for the next throw. (The castle, close,
    // is the shot view, while a throw is followed and its verdict read: resting on it between throws
    // left the catapult off the screen until the next drag.)
    return v.field;
  }
  // Room behind the catapult for its stones where the screen is wide enough.
  const behind = renderer.camera.width < NARROW ? 1.6 : 3.1;
  return viewFor(LAUNCH.x - behind, rockRight() + 0.6);
}
/** Largest magnification of the castle's close-up (drawCloseUp): as wide as the phone's screen for most castles. */
const CLOSE_MAX = 6;
/** The shot view (see above): the castle, the rock and room either side for debris (2.5 m; upright ./camera uprightCastleView; on a desktop 1.2 m and the rock's near half). */
function shotViewRect(): View {
  if (upright()) return uprightCastleView(field(), renderer.camera.width, renderer.camera.height);
  if (renderer.camera.width < NARROW) return viewFor(lv.castleMinX - 2.5, rockRight() + 2.5);
  return deskViews().castle;
}
/** Screen pixels a metre in view `v`, fitted (letterboxed) to the screen. */
function pxPerM(v: View): number {
  const cam = renderer.camera;
  return Math.min(cam.width / (v.maxX - v.minX), cam.height / (v.maxY - v.minY));
}
/**
 * Whether the shot view is used: upright on a phone, and on any other screen where it shows the
 * castle at least 1.25 x as large as the aim view (a desktop's aim view, the whole field fitted to
 * its width, drew the castle as a strip under 80 % of sky after a throw).
 */
const zoomsIn = (): boolean => {
  if (upright()) return true;
  // A desktop follows a throw from the whole field to the castle.
  if (desktop()) return true;
  return pxPerM(shotViewRect()) >= 1.25 * pxPerM(aimView());
};
/**
 * The view while the stone flies: between the aim view (u = 0) and the shot view (u = 1),
 * u the share of the way from the catapult to the castle's front the stone has got (its farthest
 * x), and shifted where needed so the stone stays at least 15 % of the view's width inside it.
 * Upright, close on the stone in flight (./camera uprightFollowView: fitted to the field a phone drew
 * it 7 to 12 px across; the close aim view draws it 22 px, the follow view 24) until its verdict,
 * then the whole castle.
 */
function followView(): View {
  // (On a desktop from the drag view, where the throw was aimed.)
  const a = desktop() ? deskViews().field : aimView(),
    s = shotViewRect();
  const x = lastThrow.farthest;
  const u = Math.min(1, Math.max(0, (x - LAUNCH.x) / Math.max(1, lv.castleMinX - 1 - LAUNCH.x)));
  const w = a.maxX - a.minX + u * (s.maxX - s.minX - (a.maxX - a.minX));
  let c = (a.minX + a.maxX) / 2 + u * ((s.minX + s.maxX) / 2 - (a.minX + a.maxX) / 2);
  c = Math.min(Math.max(c, x - 0.35 * w), x + 0.35 * w);
  // Never past the shot view's right edge: a long throw is followed to the rock, and the arrow at the
  // screen's edge points on at it (followed on, the view left the castle for the ground's bare end).
  c = Math.min(c, s.maxX - w / 2);
  // A desktop's: its foot too goes from the field view's to the castle view's.
  if (desktop()) {
    const foot = a.minY + u * (s.minY - a.minY);
    return { minX: c - w / 2, minY: foot, maxX: c + w / 2, maxY: foot + (w * renderer.camera.height) / renderer.camera.width };
  }
  if (!upright()) return viewFor(c - w / 2, c + w / 2);
  // Upright, close on the stone (./camera uprightFollowView) until its verdict, then the whole castle.
  if (lastThrow.verdict !== '' || !isAlive(shell.world, lastThrow.body)) return shotViewRect();
  const [bx, by] = positionOf(lastThrow.body);
  return uprightFollowView(field(), bx, by, renderer.camera.width, renderer.camera.height);
}
function frameCamera(): void {
  const cam = renderer.camera;
  // Back to the aim view once the verdict has been up for VERDICT_READ seconds (upright UPRIGHT_WATCH:
  // the castle is small from there, and what fell is watched to the end) or the level ended,
  // or at once when a press goes down to aim.
  const read = shell.world.time - lastThrow.decidedAt > (upright() ? Math.max(VERDICT_READ, UPRIGHT_WATCH) : VERDICT_READ);
  if (shotView && lastThrow.verdict && (read || levelEnded)) shotView = false;
  // Whether this frame is the level's opening look at the castle (read once: the count runs down below).
  const opens = opening();
  // A level over: the wreck stays in view with its result (on a phone the shot view, not the catapult).
  shot = cameraShot({
    upright: upright(),
    peeking,
    shotView,
    wreck: levelEnded && shots.length > 0,
    zoomsIn: zoomsIn(),
    opening: opens,
  });
  if (openingFrames > 0) openingFrames--;
  // The look button while aiming (not while a throw is followed): the castle close, where the aim
  // view is the whole field (an upright tablet). (Not where the aim view is close on the catapult
  // and the castle's inset shows in the earth, drawCloseUp: it is the look.)
  showLook(upright() && !levelEnded && !shotView && (peeking || (shot === 'aim' && !aimCloseUp(field(), cam.width, cam.height))));
  // (The opening look: the castle large, ./camera uprightOpeningView; then the pan to the catapult.)
  const target =
    shot === 'castle'
      ? opens && !peeking
        ? uprightOpeningView(field(), cam.width, cam.height)
        : shotViewRect()
      : shot === 'follow'
        ? followView()
        : aimView();
  const size = `${cam.width}x${cam.height}`;
  // Eased by the physics steps since the last frame (./camera easeShare), not a tenth a frame: a slow
  // page's camera keeps up with a stone in game time.
  const world = shell.world;
  const steps = Math.round((world.time - framedAt) / world.dt);
  framedAt = world.time;
  const k = size === framedFor ? easeShare(steps) : 1;
  if (size !== framedFor) sizesFramed.add(size);
  framedFor = size;
  cameraView.minX += k * (target.minX - cameraView.minX);
  cameraView.maxX += k * (target.maxX - cameraView.maxX);
  cameraView.minY += k * (target.minY - cameraView.minY);
  cameraView.maxY += k * (target.maxY - cameraView.maxY);
  cam.fit(cameraView, 0);
  const off = Math.max(
    Math.abs(target.minX - cameraView.minX),
    Math.abs(target.maxX - cameraView.maxX),
    Math.abs(target.minY - cameraView.minY),
    Math.abs(target.maxY - cameraView.maxY),
  );
  // (Not at rest while the opening holds the castle: the pan to the catapult is still to come.)
  cameraSettled = off < 0.01 && !opens;
}
/** Whether the camera is at rest (not panning or following): the cup stays where it is on screen. */
let cameraSettled = false;
/** The world's time (s) at the last frame the camera was framed for (frameCamera: how far it eases). */
let framedAt = 0;
/** The view the camera heads for (camera.ts cameraShot), decided at the last frame. */
let shot: CameraShot = 'overview';
/** Whether the player asked to look at the castle (the look button, upright only). */
let peeking = false;
/** The level the page last opened (its opening look at the castle shown): a retry does not show it again. */
let openedLevel = params.level;
/** Frames left of the level's opening look at the castle (./camera OPENING_FRAMES; 0 once the player touches or throws). */
let openingFrames = OPENING_FRAMES;
/** Whether the level's opening look at the castle is under way: upright where the aim view is close on the catapult. */
const opening = (): boolean =>
  openingFrames > 0 && upright() && !levelEnded && shots.length === 0 && aimCloseUp(field(), renderer.camera.width, renderer.camera.height);
/** The look button's words: what a tap shows, said in words (an arrow alone in a corner says nothing). */
const LOOK_CASTLE = '🔍 Zoom to castle';
/** The look button's words while the castle shows: back to the catapult. */
const LOOK_BACK = '◂ Back to catapult';
/**
 * Upright where the aim view is the whole field (a tablet), a button at the bottom right that shows
 * the castle close while aiming (the field draws it smaller), and back; a press to aim goes back too.
 */
const lookBar = createButtonBar(
  [
    {
      label: LOOK_CASTLE,
      onTap: () => {
        peeking = !peeking;
      },
    },
  ],
  { label: 'look at the castle', touchOnly: false, parent: document.createElement('div') },
);
lookBar.element.remove();
lookBar.element.dataset.hud = 'look';
Object.assign(lookBar.element.style, { position: 'absolute', right: '10px', bottom: '14px', zIndex: '6' });
/** Shows or hides the look button, its label saying where a tap goes. */
function showLook(visible: boolean): void {
  const b = lookBar.buttons[0]!;
  const text = peeking ? LOOK_BACK : LOOK_CASTLE;
  if (b.textContent !== text) {
    b.textContent = text;
    b.setAttribute('aria-label', peeking ? 'look at the catapult' : 'look at the castle');
  }
  if (visible && !lookBar.element.isConnected) pageLayout().stage.append(lookBar.element);
  else if (!visible && lookBar.element.isConnected) lookBar.element.remove();
  // Over the card saying how to play while it shows (beside it, the button covered its end).
  const bottom = `${14 + Math.round(hintReserve())}px`;
  if (visible && lookBar.element.style.bottom !== bottom) lookBar.element.style.bottom = bottom;
}
framing = true;
// Framed now, not at the first frame: the camera holds the aim view from the start.
frameCamera();

/** The how-to line over the scene until the first throw (see HOW_TO). */
const howTo = document.createElement('div');
/**
 * What a first-time player needs to start, in the sky over the field until their first throw of the
 * page: the kit's card (on a phone) goes at the first touch, which a player spends finding out, and
 * the legend is behind the menu button on a phone. Over the empty sky, under the level's banner,
 * letting touches through.
 */
const HOW_TO = 'Drag back anywhere, let go to throw';
howTo.textContent = HOW_TO;
howTo.dataset.hud = 'how-to';
howTo.dataset.sceneOverlay = '';
Object.assign(howTo.style, {
  position: 'absolute',
  left: '50%',
  top: '17%',
  transform: 'translateX(-50%)',
  maxWidth: 'calc(100% - 24px)',
  width: 'max-content',
  boxSizing: 'border-box',
  padding: '6px 14px',
  borderRadius: '18px',
  background: 'rgba(12, 16, 26, 0.72)',
  color: '#ffe08a',
  // One line on a 390 px phone (15.6 px type there), 17 px on a wide screen.
  font: '600 clamp(14px, 4vw, 17px)/1.3 system-ui, sans-serif',
  textAlign: 'center',
  pointerEvents: 'none',
  zIndex: '4',
  transition: 'opacity 0.6s',
});
pageLayout().stage.append(howTo);
/** Takes the how-to line away (the first throw). */
function hideHowTo(): void {
  if (!howTo.isConnected || howTo.style.opacity === '0') return;
  howTo.style.opacity = '0';
  setTimeout(() => howTo.remove(), 700);
}

const readout = createReadout(shell.hud.readout, ['level', 'shots left', 'score', 'total', 'pieces down']);
/** The engine's count of broken welds, in the HUD's closed 'physics details' fold (a player counts pieces, not welds). */
const weldReadout = createReadout(shell.hud.details, ['welds broken']);

// Aiming: press anywhere, drag back, release: the pull is the drag, measured on the screen. A full
// pull (PULL.max) is a drag of FULL_PULL_SHARE of the canvas's diagonal (kept within
// [FULL_PULL_MIN_PX, FULL_PULL_MAX_PX]): 380 px at 1280 x 800 (an upright phone's: half its width;
// see ./pull), so the throws that reach the castle (10 to 14 m/s, half to two thirds of the range) take a hand
// movement long enough to adjust by a few pixels without the landing jumping a metre. It does not
// depend on the camera's zoom, so the view may ease out while the player pulls.
const pointer = { x: 0, y: 0 };
/** Screen pixels of drag for a full pull (PULL.max m), from the canvas's size (./pull). */
const fullPullPx = (): number => fullPullFor(renderer.camera.width, renderer.camera.height, upright());
/** Screen pixels per metre of pull. */
const aimScale = (): number => fullPullPx() / PULL.max;
app.canvas.addEventListener('pointerdown', (e) => {
  // No aim where no throw can follow: paused, out of shots, or the level over (its result showing).
  if (shell.paused || shotsLeft <= 0 || levelEnded || (e.pointerType === 'mouse' && e.button !== 0)) return;
  pointerOnCanvas(app.canvas, e, pointer);
  shotView = false;
  peeking = false;
  openingFrames = 0;
  lastThrow.hidden = true;
  aim.active = true;
  aim.x0 = pointer.x;
  aim.y0 = pointer.y;
  aim.dx = aim.dy = 0;
  aim.moved = false;
  app.canvas.setPointerCapture(e.pointerId);
  showAimDom();
  // The aim shows in the next frame even when the GPU is behind (the pacer would skip it), so even a
  // quick drag shows its band and arc.
  game.drawNext();
});
/** Sets the pull from the pointer's position in `e` (the drag from where it went down). */
function pullTo(e: PointerEvent): void {
  pointerOnCanvas(app.canvas, e, pointer);
  aim.dx = (pointer.x - aim.x0) / aimScale();
  aim.dy = -(pointer.y - aim.y0) / aimScale();
  showAimDom();
}
app.canvas.addEventListener('pointermove', (e) => {
  if (!aim.active) return;
  pullTo(e);
  // The first move's pull too (the press alone draws no arc).
  if (!aim.moved) game.drawNext();
  aim.moved = true;
});
const release = (e: PointerEvent): void => {
  if (!aim.active) return;
  // The throw takes the pull where the pointer came up: the browser may merge or drop the moves
  // just before a release (a busy page gets fewer), so the last move can lag the hand.
  pullTo(e);
  aim.active = false;
  showAimDom();
  // Paused mid-drag: the pull is dropped, not thrown.
  if (!shell.paused) fire(aim.dx, aim.dy);
};
app.canvas.addEventListener('pointerup', release);
app.canvas.addEventListener('pointercancel', () => {
  aim.active = false;
  showAimDom();
});

/** Throws with the pull (dx, dy), m, if the level is on, shots are left and the pull is long enough (0.3 m). */
function fire(dx: number, dy: number): number {
  if (levelEnded || shotsLeft <= 0 || Math.hypot(dx, dy) < 0.3) return 0;
  const [vx, vy] = launchVelocity(dx, dy);
  const ball = launch(shell.world, vx, vy, levelMass);
  renderer.setColor(ball, SHOT_COLOR);
  shots.push(ball);
  if (!DEMO) hideHowTo();
  shotsLeft--;
  lastShotTime = shell.world.time;
  lastThrow.body = ball;
  lastThrow.hidden = false;
  lastThrow.path.length = 0;
  lastThrow.path.push(LAUNCH.x, LAUNCH.y);
  lastThrow.scoreBefore = tally(shell.world, lv).score;
  lastThrow.time = shell.world.time;
  lastThrow.verdict = '';
  lastThrow.brief = '';
  lastThrow.touched = '';
  lastThrow.touchStep = null;
  lastThrow.firstBody = 0;
  lastThrow.pastBy = 0;
  lastThrow.farthest = LAUNCH.x;
  lastThrow.vx = vx;
  lastThrow.vy = vy;
  lastThrow.power = Math.min(1, Math.hypot(dx, dy) / PULL.max);
  lastThrow.angle = (Math.atan2(vy, vx) * 180) / Math.PI;
  shotView = true;
  peeking = false;
  arm.firedAt = shell.world.time;
  arm.velocity = -(8 + 22 * Math.min(1, Math.hypot(dx, dy) / PULL.max));
  sound.launch(Math.min(1, Math.hypot(dx, dy) / PULL.max));
  return ball;
}

/** Trail: a dot every this many metres of flight, for at most TRAIL_TIME seconds. */
const TRAIL_SPACING = 0.5,
  TRAIL_TIME = 4;
/** The verdict comes this long after the throw (s), or as soon as the projectile is nearly at rest. */
const VERDICT_AFTER = 2.5;
/** How long the verdict shows, s. */
const VERDICT_SHOWN = 2.5;
/** How long after the verdict the camera goes back from the shot view to the aim view (once it has faded), s. */
const VERDICT_READ = VERDICT_SHOWN;

/** Extends the last throw's trail and decides its verdict once it has settled. */
function followThrow(world: PhysicsWorld, t: Tally): void {
  const b = lastThrow.body;
  if (!b) return;
  const since = world.time - lastThrow.time;
  const alive = isAlive(world, b);
  let x = lastThrow.path[lastThrow.path.length - 2]!,
    y = lastThrow.path[lastThrow.path.length - 1]!;
  let speed = 0;
  if (alive) {
    const s = slotOf(b);
    const P = world.components.Position,
      V = world.components.Velocity;
    const px = P.x[s]!,
      py = P.y[s]!;
    speed = Math.hypot(V.x[s]!, V.y[s]!);
    if (py >= 0) lastThrow.farthest = Math.max(lastThrow.farthest, px);
    if (since < TRAIL_TIME && Math.hypot(px - x, py - y) >= TRAIL_SPACING) lastThrow.path.push(px, py);
    x = px;
    y = py;
  }
  if (lastThrow.verdict || !(since > VERDICT_AFTER || (since > 0.6 && speed < 0.3))) return;
  const gained = t.score - lastThrow.scoreBefore;
  lastThrow.decidedAt = world.time;
  lastThrow.good = gained > 0;
  // (A throw that brought nothing down counts toward the aim preview's help, previewReach.)
  if (gained <= 0 && misses.level === params.level) misses.count++;
  if (gained > 0) {
    lastThrow.verdict = `+${gained}`;
    lastThrow.at = [(lv.castleMinX + lv.castleMaxX) / 2, lv.castleTop + 0.8];
    return;
  }
  // Where the projectile first reached the castle's span under its top, or else came down to the
  // ground (a hill's top, a pit's floor), tells short from long. (The first point under the
  // castle's top on the way down would be the throw's top for a low throw: "short by 8 m" for a
  // stone that came down 1 m short.)
  const path = lastThrow.path;
  let landX = x;
  for (let i = 2; i < path.length; i += 2) {
    const px = path[i]!,
      py = path[i + 1]!;
    const down = py < path[i - 1]! && py < surfaceAt(lv, px) + PROJECTILE_RADIUS + 0.3;
    if ((px >= lv.castleMinX - 0.3 && py < lv.castleTop) || down) {
      landX = px;
      break;
    }
  }
  // By how far: short, from where the throw would have come down on open ground (drag-free) or came
  // down, to the castle's near end; long, from the castle's far end to where it first came down past
  // it (on the path), or on open ground when the path ends before it does; in whole metres (at least
  // 1). A throw that got past the rock is long whatever it touched on its way (one that bounced on a
  // hill fort's top and flew on read "No damage: throw harder" beside "17 m past").
  const g = -world.gravity[1]!,
    vy = lastThrow.vy;
  const ground = LAUNCH.x + (lastThrow.vx * (vy + Math.sqrt(vy * vy + 2 * g * LAUNCH.y))) / g;
  const by = (d: number): number => Math.max(1, Math.round(d));
  // Long too when the stone first came down past the castle or on the rock behind it, whatever it
  // touched after: a stone that flew over the castle and bounced off the rock onto a post read
  // "Hit a wooden post, nothing fell: throw harder".
  const first = lastThrow.touchStep,
    firstPast =
      first !== null &&
      !lv.pieces.some((p) => p.body === lastThrow.firstBody) &&
      (lastThrow.firstBody === lv.rock || first[2] > lv.castleMaxX + 0.3);
  const long = landX > lv.castleMaxX + 0.3 || lastThrow.farthest > rockRight() + 0.3 || firstPast,
    short = !long && landX < lv.castleMinX - 0.3;
  let landed = Math.max(ground, lastThrow.farthest);
  if (firstPast && first) landed = Math.min(landed, first[2]);
  for (let i = 2; long && !firstPast && i < path.length; i += 2) {
    const px = path[i]!,
      py = path[i + 1]!;
    if (px > lv.castleMaxX + 0.3 && py < path[i - 1]! && py < surfaceAt(lv, px) + PROJECTILE_RADIUS + 0.3) {
      landed = px;
      break;
    }
  }
  // A stone that touched a piece of the castle hit it, whatever its path did after: it was neither
  // short nor long (one that glanced off a post and rolled back read "Short by 4 m").
  const hit = lastThrow.touched !== '' && !long;
  const bank = lastThrow.touched === 'hill';
  const d = hit ? 0 : short ? by(lv.castleMinX - Math.min(ground, landX)) : long ? by(landed - lv.castleMaxX) : 0;
  lastThrow.pastBy = !hit && long ? d : 0;
  lastThrow.verdict = hit
    ? bank
      ? 'Hit the earth bank in front: throw higher or harder'
      : `Hit ${PIECE_NAME[lastThrow.touched as Piece['kind']]}, nothing fell: throw harder`
    : short
      ? `Short by ${d} m: pull further back`
      : long
        ? `Long by ${d} m: pull less, or aim lower`
        : 'No damage: it fell through a gap, aim at a piece';
  lastThrow.brief = hit ? (bank ? 'hit the bank' : 'hit, none fell') : short ? `short ${d} m` : long ? `long ${d} m` : 'fell in a gap';
  lastThrow.at = [Math.min(Math.max(x, lv.castleMinX - 4), lv.castleMaxX), Math.max(y, 0) + 2.2];
}

/**
 * Where the last throw is when it is off the screen (over the top, past the right edge, or fallen off
 * the ground's end): an arrow at the screen's edge pointing at it, and how far it is past the rock
 * when it went long, until the next throw, so a shot that left the screen is not lost from sight.
 */
function drawOffscreen(world: PhysicsWorld): void {
  offscreenText.visible = false;
  const b = lastThrow.body;
  if (!b || lastThrow.hidden || !isAlive(world, b)) return;
  const cam = renderer.camera;
  const [x, y] = positionOf(b);
  const px = cam.toScreenX(x),
    py = cam.toScreenY(y),
    W = cam.width,
    H = cam.height;
  const m = 18;
  if (px >= 0 && px <= W && py >= 0 && py <= H) return;
  // Lying at the castle or the rock while the castle is off the screen: the castle's own marker points there.
  if (px > W && x <= rockRight() + 0.5 && y < 2 * ROCK.hy + 1) return;
  // The arrow's tip on the screen's edge, on the line from the screen's centre to the stone.
  // Past the right edge, the arrow and its label sit above the castle and the rock, not over them.
  const top = px > W ? Math.min(cam.toScreenY(Math.max(lv.castleTop, 2 * ROCK.hy) + 1.2), H - m) : H - m;
  const ax = Math.min(Math.max(px, m), W - m),
    ay = Math.max(Math.min(py, top), m + 56);
  const ang = Math.atan2(py - ay, px - ax);
  const c = Math.cos(ang),
    sn = Math.sin(ang);
  const tip = (d: number, side: number): [number, number] => [ax + c * d - sn * side, ay + sn * d + c * side];
  overlay
    .poly([...tip(10, 0), ...tip(-10, 9), ...tip(-5, 0), ...tip(-10, -9)])
    .fill({ color: 0xffe066 })
    .stroke({ width: 2, color: 0x000000 });
  // Once a long throw's verdict is out, the verdict's number (the two agree); before it, how far the
  // stone has got.
  const past = lastThrow.pastBy > 0 ? lastThrow.pastBy : lastThrow.farthest - lv.castleMaxX;
  if (px <= W || past < 1) return;
  // A verdict other than long (points, short, no damage) has no distance past the castle to show.
  if (lastThrow.verdict !== '' && lastThrow.pastBy === 0) return;
  offscreenText.visible = true;
  const label = `${Math.round(past)} m past ▸`;
  if (offscreenText.text !== label) offscreenText.text = label;
  offscreenText.x = W - m - 14;
  offscreenText.y = ay;
}

/**
 * While the castle is off the screen to the right (the close aim view on an upright phone), an arrow
 * at the right edge, level with the castle's middle, and how far the castle's front is from the
 * catapult, so the player knows where to throw.
 */
function drawCastleMarker(): void {
  const cam = renderer.camera;
  const W = cam.width;
  // (From 0.6 m short of the castle's front: the inset's left edge, drawCloseUp, which would otherwise
  // show the arrow at its edge as the camera following a throw nears the castle.)
  castleText.visible = cam.toScreenX(lv.castleMinX - 0.6) > W && !offscreenText.visible && !levelEnded;
  if (!castleText.visible) return;
  const m = 14,
    y = Math.max(cam.toScreenY(lv.castleTop / 2), 90);
  overlay
    .poly([W - m + 8, y, W - m - 8, y - 10, W - m - 4, y, W - m - 8, y + 10])
    .fill({ color: 0xffe066 })
    .stroke({ width: 2, color: 0x000000 });
  const label = `castle ${Math.round(lv.castleMinX - LAUNCH.x)} m`;
  if (castleText.text !== label) castleText.text = label;
  castleText.x = W - m - 14;
  castleText.y = y;
}

/** Position of a body by handle, m. */
function positionOf(h: number): [number, number] {
  const P = shell.world.components.Position,
    s = slotOf(h);
  return [P.x[s]!, P.y[s]!];
}

/**
 * Draws the last throw's trail and its verdict: a hit's points for VERDICT_SHOWN seconds; a miss's
 * hint ("Long by 6 m: pull less, or aim lower") until the player presses to aim again, so a player
 * who looks back at the castle after a miss still finds the hint there.
 */
function drawThrow(world: PhysicsWorld): void {
  const cam = renderer.camera;
  // The trail stays while the player aims the next throw (a guide: higher or lower than that one).
  const path = lastThrow.path;
  trailDots = Math.max(0, path.length / 2 - 1);
  // While aiming it is the ghost to correct from: larger, and ringed so it reads over the pale sky.
  const r = aim.active ? 3 : 2.5;
  for (let i = 2; i < path.length; i += 2) {
    const dot = overlay
      .circle(cam.toScreenX(path[i]!), cam.toScreenY(path[i + 1]!), r)
      .fill({ color: 0xffffff, alpha: aim.active ? 0.75 : 0.6 });
    if (aim.active) dot.stroke({ width: 1, color: 0x000000, alpha: 0.3 });
  }
  drawOffscreen(world);
  drawCastleMarker();
  const age = world.time - lastThrow.decidedAt;
  const gone = lastThrow.good ? age > VERDICT_SHOWN : lastThrow.hidden || levelEnded;
  if (!lastThrow.verdict || gone) {
    verdictText.visible = false;
    return;
  }
  verdictText.visible = true;
  if (verdictText.text !== lastThrow.verdict) verdictText.text = lastThrow.verdict;
  verdictText.style.fill = lastThrow.good ? 0xffe066 : 0xffffff;
  verdictText.style.fontSize = lastThrow.good ? 34 : app.screen.width < 600 ? 16 : 20;
  // Wrapped to the screen's width less a margin, so on a phone a long hint stays on the screen.
  verdictText.style.wordWrapWidth = Math.max(120, app.screen.width - 24);
  // A hit's points shrink away in their last third rather than fade: a faded popup would let the
  // confetti of a cleared level show through it, as if drawn over it. Opaque, it stays over the confetti.
  verdictText.scale.set(lastThrow.good ? Math.max(0, Math.min(1, 3 * (1 - age / VERDICT_SHOWN))) : 1);
  const half = verdictText.width / 2 + 8;
  verdictText.x = Math.min(Math.max(cam.toScreenX(lastThrow.at[0]), half), app.screen.width - half);
  // A hit's points rise as they shrink; a miss's hint rises for its first second, then holds.
  const rise = lastThrow.good ? age : Math.min(age, 1);
  verdictText.y = Math.max(cam.toScreenY(lastThrow.at[1]) - 18 * rise, 70);
  // Clear of the off-screen marker's label ("12 m past ▸") at the right edge: a verdict that starts
  // under the label stops rising under it, one that starts level with or over it stays over it.
  if (offscreenText.visible) {
    const o = offscreenText,
      oTop = o.y - o.height / 2 - 4,
      oBottom = o.y + o.height / 2 + 4;
    if (verdictText.x + verdictText.width / 2 > o.x - o.width - 4) {
      const under = cam.toScreenY(lastThrow.at[1]) - verdictText.height > o.y;
      verdictText.y = under ? Math.max(verdictText.y, oBottom + verdictText.height) : Math.min(verdictText.y, oTop);
    }
  }
  keepVerdictOffScene();
}

/**
 * The screen boxes (left, top, right, bottom, px) the verdict keeps off: the catapult with its mound
 * and stacked stones (x -3.0 to 1.2 m, up to 2.4 m: its arm up), and the castle with the rock behind
 * it (from the lowest surface to 0.3 m over the castle's top or the rock's, 0.2 m either side).
 */
function sceneBoxes(): [number, number, number, number][] {
  const cam = renderer.camera,
    floor = Math.min(0, ...lv.terrain.map((t) => t.maxY));
  const box = (x0: number, y0: number, x1: number, y1: number): [number, number, number, number] => [
    cam.toScreenX(x0),
    cam.toScreenY(y1),
    cam.toScreenX(x1),
    cam.toScreenY(y0),
  ];
  return [
    box(-3.0, 0, 1.2, 2.4),
    box(lv.castleMinX - 0.2, floor, lv.castleMaxX + 0.2, lv.castleTop + 0.3),
    box(rockRight() - 2 * ROCK.hx - 0.2, floor, rockRight() + 0.2, 2 * ROCK.hy + 0.3),
  ];
}

/**
 * Moves the verdict (anchored at its bottom middle) off the castle, the rock and the catapult
 * (sceneBoxes): up to 6 px over the top of one it covers, and over the off-screen marker's label if
 * that move puts it on it, never above the banner's panel (8 px under it). A verdict still on the
 * castle there (a tall castle filling a phone's view) goes beside it: into the gap before it, or
 * past the rock, where the text fits, at the castle's middle height.
 */
function keepVerdictOffScene(): void {
  const t = verdictText,
    w = t.width,
    h = t.height;
  const top = banner.text !== '' ? banner.y + banner.height + 8 : 8;
  const boxOf = (): [number, number, number, number] => [t.x - w / 2, t.y - h, t.x + w / 2, t.y];
  const hits = (a: readonly number[], b: readonly number[]) =>
    a[0]! < b[2]! + 4 && b[0]! < a[2]! + 4 && a[1]! < b[3]! + 4 && b[1]! < a[3]! + 4;
  const boxes = sceneBoxes();
  const marker = offscreenText.visible
    ? [
        offscreenText.x - offscreenText.width - 4,
        offscreenText.y - offscreenText.height / 2 - 4,
        offscreenText.x + 4,
        offscreenText.y + offscreenText.height / 2 + 4,
      ]
    : null;
  for (let n = 0; n < 4; n++) {
    const on = boxes.find((b) => hits(boxOf(), b)) ?? (marker && hits(boxOf(), marker) ? marker : undefined);
    if (!on) return;
    const y = Math.max(top + h, on[1]! - 6);
    if (y >= t.y) break;
    t.y = y;
  }
  if (!boxes.some((b) => hits(boxOf(), b))) return;
  // Beside the castle: before it (between the catapult and the castle), else past the rock.
  const [, cTop = 0, , cBottom = 0] = boxes[1]!;
  const gaps: [number, number][] = [
    [boxes[0]![2]! + 6, boxes[1]![0]! - 6],
    [boxes[2]![2]! + 6, app.screen.width - 6],
  ];
  for (const [x0, x1] of gaps)
    if (x1 - x0 >= w) {
      t.x = Math.min(Math.max((x0 + x1) / 2, x0 + w / 2), x1 - w / 2);
      t.y = Math.max(top + h, (cTop + cBottom) / 2 + h / 2);
      return;
    }
}

/** Dots of the last throw's trail drawn in the last frame. */
let trailDots = 0;
/** The level score the readout shows (the banner showed it in the frame drawn before). */
let shownScore = 0;
/**
 * The readout's rows (and level score) computed in the last frame, and the frames drawn before it
 * (the pacer's count). They are written once that frame has been drawn: a frame the GPU was too
 * busy for is skipped and the canvas keeps the one before, and the readout must not run ahead of the
 * banner (saying "score 50" beside a banner's "Score 0"). Where every frame is drawn the readout
 * follows one frame behind.
 */
let pendingRows: { score: number; rows: string[] } | null = null;
let pendingDrawn = -1;
/** Writes the last frame's rows to the readout if that frame was drawn, and keeps this frame's. */
function writeReadout(score: number, rows: string[]): void {
  const drawn = game.pacer.drawn;
  if (pendingRows && drawn !== pendingDrawn) {
    shownScore = pendingRows.score;
    // Rows 0 to 4 go to the readout, row 5 (welds broken) to the physics fold's.
    for (const [k, r] of pendingRows.rows.entries()) {
      if (k < 5) readout.set(k, r);
      else weldReadout.set(k - 5, r);
    }
  }
  pendingRows = { score, rows };
  pendingDrawn = drawn;
}

/** The on-screen "Next level" button, shown when a level is over. */
const showNextButton = createActionButton('Next level ▶', () => nextLevel());
/** Whether the "Next level" button shows (Enter presses it then). */
let nextShown = false;
/**
 * The button asked for in the last frame and the frames drawn before it (the pacer's count): like
 * the readout's rows (writeReadout) it goes on only once that frame, whose banner names the button
 * and gives the level's result, has been drawn. Put on at once, a GPU too busy to draw kept the
 * canvas's last frame ("1 shot left", no result) under a "Level 2 ▶" button for seconds. It goes
 * off at once: a button left up a frame after a tap could be tapped again and skip a level.
 */
let pendingNext: { visible: boolean; text: string | undefined; drawn: number } | null = null;
/** Once a frame: shows (once this frame has been drawn) or hides (at once) the "Next level" button, with `text` on it. */
const showNext = (visible: boolean, text?: string): void => {
  const drawn = game.pacer.drawn;
  const same = pendingNext?.visible === visible && pendingNext.text === text;
  if (!same) pendingNext = { visible, text, drawn };
  applyNext(visible && same && drawn !== pendingNext?.drawn, text);
};
/** Shows or hides the "Next level" button, with `text` on it, now. */
const applyNext = (visible: boolean, text?: string): void => {
  nextShown = visible;
  showNextButton(visible, text);
  const bar = visible ? pageLayout().stage.querySelector<HTMLElement>('.bp-action') : null;
  if (!bar) return;
  // Not upright, the strip under the ground is thin and the button at the bottom would sit over the wreck:
  // it goes in the sky just under the banner that names it ("the button below"). Upright it stays in
  // the earth under the scene.
  const top = upright() ? '' : `${Math.round(banner.y + banner.height + 14)}px`;
  if (bar.style.top !== top) {
    bar.style.top = top;
    bar.style.bottom = top === '' ? '' : 'auto';
  }
};

const overlay = new Graphics({ label: 'catapult' });
/** The distance marks' labels ("5 m", "10 m", ...), one per mark of the level (./distance). */
const distanceLayer = new Container({ label: 'distance marks' });
const banner = new Text({
  text: '',
  style: {
    fill: 0xffffff,
    fontSize: 22,
    fontFamily: 'sans-serif',
    align: 'center',
    stroke: { color: 0x000000, width: 4, join: 'round' },
    wordWrap: true,
    wordWrapWidth: 600,
  },
});
banner.anchor.set(0.5, 0);
/**
 * A dark panel behind the banner (black at BANNER_PANEL_ALPHA): white type over the pale sun or a
 * cloud read at under 2:1; over the panel the sky's palest (the sun's disc) is 0.38 x white, and
 * white type on that is about 5.9:1 (WCAG contrast, at least 4.5:1).
 */
const bannerPanel = new Graphics({ label: 'banner panel' });
const BANNER_PANEL_ALPHA = 0.62;
const verdictText = new Text({
  text: '',
  style: {
    fill: 0xffffff,
    fontSize: 20,
    fontFamily: 'sans-serif',
    fontWeight: 'bold',
    stroke: { color: 0x000000, width: 5, join: 'round' },
    wordWrap: true,
    wordWrapWidth: 600,
    align: 'center',
  },
});
verdictText.anchor.set(0.5, 1);
verdictText.visible = false;
/** The yellow outlined style of the labels at the screen's edge (off-screen throw, castle marker). */
const EDGE_LABEL_STYLE = {
  fill: 0xffe066,
  fontSize: 15,
  fontFamily: 'sans-serif',
  fontWeight: 'bold',
  stroke: { color: 0x000000, width: 4, join: 'round' },
} as const;
/** How far past the castle an off-screen throw came down (see drawOffscreen). */
const offscreenText = new Text({
  text: '',
  style: EDGE_LABEL_STYLE,
});
offscreenText.anchor.set(1, 0.5);
offscreenText.visible = false;
/** Where the castle is while it is off the screen (see drawCastleMarker). */
const castleText = new Text({
  text: '',
  style: EDGE_LABEL_STYLE,
});
castleText.anchor.set(1, 0.5);
castleText.visible = false;
/** Over the play area while paused: a dimmed scene and the word, so a pause is not mistaken for a hang. */
const pause = createPauseOverlay();
const popupLayer = new Container({ label: 'popups' });
effects = new Effects(popupLayer);
// Past the ground's ends (no surface) bits fall on out of sight.
effects.surface = (x) => Math.max(-50, surfaceAt(lv, x));
renderer.root.addChild(
  overlay,
  distanceLayer,
  effects.graphics,
  popupLayer,
  bannerPanel,
  banner,
  verdictText,
  offscreenText,
  castleText,
  pause.container,
);

/** Whether a stone sits in the cup: shots are left and the arm is back from its last throw. */
function loaded(): boolean {
  return shotsLeft > 0 && shell.world.time - arm.firedAt > RELOAD && arm.angle > CATAPULT.cocked - 0.35;
}

/**
 * Moves the arm by `dt` s: toward the pull while aiming (a stiff spring), forward to the crossbar
 * after a throw (its launch speed, bouncing off the bar), and back to cocked RELOAD s later if a
 * shot is left (a soft spring). Integrated in 1/240 s steps (the springs are stiff).
 */
function swingArm(dt: number): void {
  const since = shell.world.time - arm.firedAt;
  let target: number = CATAPULT.cocked,
    k = 60,
    c = 2 * Math.sqrt(60);
  if (since < RELOAD || shotsLeft === 0) {
    target = CATAPULT.stop;
    k = 250;
    c = 8;
  } else if (aim.active) {
    target = CATAPULT.cocked + CATAPULT.fullPull * Math.min(1, Math.hypot(aim.dx, aim.dy) / PULL.max);
    k = 500;
    c = 2 * Math.sqrt(500);
  }
  for (let left = dt; left > 1e-9; left -= 1 / 240) {
    const h = Math.min(left, 1 / 240);
    arm.velocity += (-k * (arm.angle - target) - c * arm.velocity) * h;
    arm.angle += arm.velocity * h;
    if (arm.angle < CATAPULT.stop) {
      arm.angle = CATAPULT.stop;
      arm.velocity = -0.3 * arm.velocity;
    }
  }
}

/** The stone in the cup (when loaded) and the stones left beside the catapult, stacked. */
function drawAmmo(): void {
  const cam = renderer.camera;
  const inCup = loaded();
  if (inCup) {
    const [, , x, y] = cupAt(arm.angle, PROJECTILE_RADIUS);
    drawShot(overlay, cam, x, y, 0.6, PROJECTILE_RADIUS);
  }
  const pile = shotsLeft - (inCup ? 1 : 0);
  for (let k = 0; k < pile; k++) {
    const row = k < 3 ? 0 : 1,
      col = row === 0 ? k : k - 3;
    drawShot(overlay, cam, -1.75 - 0.5 * col - 0.25 * row, 0.24 + 0.42 * row, 1.3 * k, 0.24);
  }
}

/**
 * Draws the castle's pieces (wood, glass, stones) over their plain shapes, where and as turned as the
 * renderer draws them this frame, and the thrown stones; a piece that has just fallen gets its
 * popup ("+100") and a puff of dust.
 */
function drawPieces(world: PhysicsWorld, alpha: number): void {
  const cam = renderer.camera;
  const A = world.components.Angle.value,
    W = world.components.AngularVelocity.z,
    P = world.components.Position,
    O = world.components.PreviousPosition;
  const back = (1 - alpha) * world.dt;
  const at = { x: 0, y: 0 };
  // Where and as turned as the renderer draws a body this frame: its position interpolated from the
  // last step's by alpha, its angle taken back by the rest of the step's turn.
  const place = (b: number): boolean => {
    if (!isAlive(world, b)) return false;
    const s = slotOf(b);
    at.x = O.x[s]! + (P.x[s]! - O.x[s]!) * alpha;
    at.y = O.y[s]! + (P.y[s]! - O.y[s]!) * alpha;
    return true;
  };
  const angleOf = (b: number): number => {
    const s = slotOf(b);
    return A[s]! - W[s]! * back;
  };
  for (const p of lv.pieces) {
    if (!place(p.body)) continue;
    const a = angleOf(p.body),
      color = renderer.colorOf(p.body),
      down = p.down === true;
    if (p.kind === 'stone') drawStone(overlay, cam, at.x, at.y, a, p.half[0], down ? mixColor(color, 0x000000, 0.4) : color);
    else if (p.kind === 'block') drawGlass(overlay, cam, at.x, at.y, a, p.half[0], p.half[1], color, down);
    else if (p.kind === 'brick') drawBrick(overlay, cam, at.x, at.y, a, p.half[0], p.half[1], color, down);
    else drawWood(overlay, cam, at.x, at.y, a, p.half[0], p.half[1], color, down);
    if (down && !popped.has(p.body)) {
      popped.add(p.body);
      // Pieces falling together share one popup (near: a popup's width and more, 80 px, in metres).
      effects!.popup(at.x, at.y + 0.4, `+${FALL_POINTS}`, undefined, 80 / cam.toScreenLength(1));
      effects!.burst('dust', at.x, Math.max(0.1, at.y - p.half[1]), 5, 1.6);
    }
  }
  for (const b of shots) {
    if (!place(b)) continue;
    drawShot(overlay, cam, at.x, at.y, angleOf(b), PROJECTILE_RADIUS);
  }
}

/** Splinters and a crack for each weld that broke since the last frame. */
function showBreaks(world: PhysicsWorld): void {
  const P = world.components.Position;
  for (let i = 0; i < lv.joints.length; i++) {
    if (!weldsHeld[i] || isAlive(world, lv.joints[i]!)) continue;
    weldsHeld[i] = false;
    const [a, b] = lv.jointBodies[i]!;
    if (!isAlive(world, a) || !isAlive(world, b)) continue;
    const sa = slotOf(a),
      sb = slotOf(b);
    effects!.burst('wood', (P.x[sa]! + P.x[sb]!) / 2, (P.y[sa]! + P.y[sb]!) / 2, 6, 3);
    sound.impact(25, 'wood', { threshold: 2, loud: 60 });
  }
}

/**
 * The arc preview: the stone's flight from the cup to where it first touches the ground, a bank of
 * earth, the rock or a castle piece as it stands now (previewFlight, at most PREVIEW_TIME s; only
 * its start unless the player keeps missing, previewReach), drawn as dots in the page over the canvas (aimDom)
 * on every pointer move and every frame, so the arc follows the finger even on a slow page: drawn on
 * the canvas at the frame's pace, a page at 3 fps would show the arc of an earlier pull while the
 * stone flies by the latest one.
 */
const PREVIEW_TIME = 6;
/** Least distance between two dots of the arc preview on the screen, px. */
const PREVIEW_GAP = 11;
/**
 * What the aim shows (tests): power (0 to 1) and angle (degrees above level) as the page shows them
 * now, the preview's dots on the screen now (and in the phone's close-up), the faint dots past its
 * first touch (flightPast), its farthest x, m, and its end, the point (m) where the stone first
 * touches something, or where the drawn start of the flight ends (previewLimit).
 */
const aimShown = { power: 0, angle: 0, dots: 0, closeDots: 0, ghost: 0, reach: 0, end: [0, 0] as [number, number] };

/** Once a frame: the aim in the page (showAimDom) placed for the camera of this frame. */
function drawAim(): void {
  showAimDom();
}

const SVG_NS = 'http://www.w3.org/2000/svg';
/** An SVG element `tag` with attributes `attrs`. */
function svgChild(tag: string, attrs: Record<string, string | number>): SVGElement {
  const e = document.createElementNS(SVG_NS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
  return e;
}
/**
 * The aim's band, ring and power bar with its numbers, in the page over the canvas (not drawn on
 * it): they change on every pointer move, at once, whether or not a frame is drawn. The kit's frame
 * pacer draws no frame while the GPU has two unfinished (software WebGL: often for a whole quick
 * drag), and a drawn label read "6 %" at the release of a 59 % throw.
 */
const aimDom = (() => {
  const svg = svgChild('svg', { 'data-hud': 'aim-band', 'aria-hidden': 'true' }) as SVGSVGElement;
  svg.style.cssText = 'position:absolute;left:0;top:0;width:100%;height:100%;pointer-events:none;overflow:visible;display:none';
  // Arcs of the full pull's and half a pull's circles round the press, across the pull (see RING_SPAN).
  const ring = svgChild('path', {
    'data-hud': 'aim-ring',
    fill: 'none',
    stroke: '#fff',
    'stroke-opacity': 0.45,
    'stroke-width': 2,
    'stroke-linecap': 'round',
  });
  const half = svgChild('path', {
    'data-hud': 'aim-ring-half',
    fill: 'none',
    stroke: '#fff',
    'stroke-opacity': 0.3,
    'stroke-width': 1.5,
    'stroke-linecap': 'round',
  });
  const shade = svgChild('line', { stroke: '#000', 'stroke-opacity': 0.35, 'stroke-width': 5, 'stroke-linecap': 'round' });
  const band = svgChild('line', { 'stroke-width': 3, 'stroke-linecap': 'round' });
  const press = svgChild('circle', { r: 4, fill: '#fff', 'fill-opacity': 0.8 });
  const end = svgChild('circle', { r: 9, stroke: '#000', 'stroke-opacity': 0.6, 'stroke-width': 2 });
  // The arc preview's dots on the scene, and on an upright phone in the castle's close-up too.
  const dots = svgChild('g', { 'data-hud': 'aim-arc' });
  const closeDots = svgChild('g', { 'data-hud': 'aim-arc-close' });
  // The faint flight past the preview's first touch (drawArc).
  const ghost = svgChild('g', { 'data-hud': 'aim-arc-past' });
  svg.append(ghost, dots, closeDots, ring, half, shade, band, press, end);
  const box = document.createElement('div');
  box.dataset.hud = 'aim';
  box.setAttribute('aria-live', 'off');
  box.style.cssText =
    'position:absolute;pointer-events:none;display:none;font:bold 16px/1.25 sans-serif;color:#fff;text-align:center;white-space:pre;' +
    'text-shadow:0 0 3px #000,1px 1px 0 #000,-1px -1px 0 #000,1px -1px 0 #000,-1px 1px 0 #000';
  const label = document.createElement('div');
  label.style.cssText = 'position:absolute;bottom:100%;margin-bottom:4px;left:0';
  const bar = document.createElement('div');
  bar.style.cssText = 'height:10px;padding:2px;border-radius:5px;background:rgba(0,0,0,0.55)';
  const fill = document.createElement('div');
  fill.style.cssText = 'height:10px;border-radius:4px';
  bar.append(fill);
  box.append(label, bar);
  pageLayout().stage.append(svg, box);
  return { svg, dots, closeDots, ghost, ring, half, shade, band, press, end, box, label, bar, fill };
})();

/**
 * Half the angle of the arcs marking a full pull and half a pull, rad, either side of the pull's
 * direction: they show how far the pull can go where the finger is, not as whole circles (a full
 * pull's circle, 760 px across on a desktop, crossed the banner and the clouds).
 */
const RING_SPAN = 0.3,
  HALF_RING_SPAN = 0.25;
/** An SVG path of the arc of radius r, px, round (cx, cy), from angle a - span to a + span, rad (screen angles: y down). */
function arcPath(cx: number, cy: number, r: number, a: number, span: number): string {
  const p = (t: number): string => `${(cx + r * Math.cos(t)).toFixed(1)} ${(cy + r * Math.sin(t)).toFixed(1)}`;
  return `M ${p(a - span)} A ${r.toFixed(1)} ${r.toFixed(1)} 0 0 1 ${p(a + span)}`;
}
/** Sets an SVG element's attributes. */
function setAttrs(e: SVGElement, attrs: Record<string, number | string>): void {
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, String(v));
}
/** The aim's colour: green to yellow at half power, to red at full. */
const powerColor = (power: number): number =>
  power < 0.5 ? mixColor(0x5cd65c, 0xffd23b, 2 * power) : mixColor(0xffd23b, 0xff5040, 2 * power - 1);
/**
 * Shows the aim in the page (see aimDom) while a press pulls, else hides it: the band from the
 * press to the finger, arcs of a full pull's and half a pull's circles across its end (so the player
 * sees how much further the pull can go), and over the catapult (or where the band leaves room, see
 * ./aim-label) a power bar with the power and the angle in numbers (and the last throw's over them),
 * so a throw can be repeated or changed by a little. Called on every
 * pointer move and every frame.
 */
function showAimDom(): void {
  const d = aimDom;
  const on = aim.active && !shell.paused;
  const display = on ? '' : 'none';
  if (d.svg.style.display !== display) d.svg.style.display = d.box.style.display = display;
  if (!on) {
    aimShown.dots = aimShown.closeDots = aimShown.ghost = 0;
    return;
  }
  const cam = renderer.camera;
  const [vx, vy] = launchVelocity(aim.dx, aim.dy);
  const power = Math.min(1, Math.hypot(aim.dx, aim.dy) / PULL.max);
  const color = `#${powerColor(power).toString(16).padStart(6, '0')}`;
  aimShown.power = power;
  aimShown.angle = (Math.atan2(vy, vx) * 180) / Math.PI;
  const R = fullPullPx();
  const [ex, ey] = aimEnd();
  // Along the pull (down and to the left, the usual throw's, before the pull is long enough to have one).
  const across = Math.hypot(ex - aim.x0, ey - aim.y0) > 4 ? Math.atan2(ey - aim.y0, ex - aim.x0) : Math.atan2(1, -2);
  setAttrs(d.ring, { d: arcPath(aim.x0, aim.y0, R, across, RING_SPAN) });
  setAttrs(d.half, { d: arcPath(aim.x0, aim.y0, R / 2, across, HALF_RING_SPAN) });
  setAttrs(d.shade, { x1: aim.x0, y1: aim.y0, x2: ex, y2: ey });
  setAttrs(d.band, { x1: aim.x0, y1: aim.y0, x2: ex, y2: ey, stroke: color });
  setAttrs(d.press, { cx: aim.x0, cy: aim.y0 });
  setAttrs(d.end, { cx: ex, cy: ey, fill: color });
  drawArc(vx, vy);
  // The power bar centred on the press (where the pull starts: the same place on every level, by
  // the finger), kept on the screen AIM_EDGE px from its edges.
  const w = Math.max(90, cam.toScreenLength(2));
  const x = Math.min(Math.max(AIM_EDGE, aim.x0 - w / 2), cam.width - w - AIM_EDGE);
  d.bar.style.width = `${w}px`;
  d.fill.style.width = `${Math.max(2, w * power)}px`;
  d.fill.style.background = color;
  // Over this throw's numbers the last throw's: the player corrects from them ("long: a little less").
  // With a miss's brief: what that throw did, while the hint over the scene is gone.
  const brief = lastThrow.brief ? `: ${lastThrow.brief}` : '';
  const last = lastThrow.body ? `last ${Math.round(100 * lastThrow.power)} %  ${Math.round(lastThrow.angle)}°${brief}\n` : '';
  const note = aimNote();
  const text = `${note}${last}${Math.round(100 * power)} %  ${Math.round(aimShown.angle)}°`;
  if (d.label.textContent !== text) d.label.textContent = text;
  // Centred over the bar, and all on the screen (the last throw's line is wider than the bar).
  const lw = d.label.offsetWidth,
    lh = d.label.offsetHeight;
  const centre = Math.min(Math.max(x + w / 2, lw / 2 + AIM_EDGE), cam.width - lw / 2 - AIM_EDGE);
  d.label.style.left = `${centre - lw / 2 - (x - 2)}px`;
  // The numbers and bar (the bar's top at y) AIM_OVER_PRESS px over the press (a pull goes down and
  // back from it), else as far under it, else over the band: the first clear of the band and its
  // knob (placeAimLabel) and on the screen. (Placed by the catapult and the ground, they sat over
  // the catapult on one level and under the ground on the next.)
  const boxAt = (y: number): Box => {
    const left = Math.min(x, centre - lw / 2);
    return { x: left, y: y - 6 - lh, w: Math.max(x + w, centre + lw / 2) - left, h: lh + 6 + AIM_BAR_H };
  };
  // (Under the banner's foot at the top, 56 px; not under the press while the castle's close-up is
  // in the earth, drawCloseUp.)
  const over = Math.max(aim.y0 - AIM_OVER_PRESS - AIM_BAR_H, 62 + lh);
  const places = [over, aim.y0 + AIM_OVER_PRESS + 6 + lh, Math.min(aim.y0, ey) - 24 - AIM_BAR_H].filter(
    (y, k) => k === 0 || (boxAt(y).y >= 56 && y + AIM_BAR_H <= cam.height - AIM_EDGE && !(k === 1 && closeWhileAiming)),
  );
  const y = places[placeAimLabel(places.map(boxAt), [aim.x0, aim.y0, ex, ey], AIM_CLEARANCE)]!;
  aimLabelBox = boxAt(y);
  d.box.style.left = `${x - 2}px`;
  d.box.style.top = `${y - 2}px`;
}
/**
 * A line over the aim's numbers about the arc preview (previewReach): on the first two levels' first
 * aim that the dots show only the throw's start (so a short arc reads as the rule, not a fault), and
 * while the misses at a level have just brought more of it (scene MISSES_FOR_MORE, MISSES_FOR_FULL)
 * that it now reaches farther; else ''.
 */
function aimNote(): string {
  if (params.guide === 'full') return '';
  const n = misses.level === params.level ? misses.count : 0;
  if (n === MISSES_FOR_FULL) return 'Help: the dots show the whole throw\n';
  if (n === MISSES_FOR_MORE) return 'Help: the dots reach farther\n';
  return params.level <= 2 && shots.length === 0 && n === 0 ? 'The dots show only the start\n' : '';
}
/** Gap, px, between the press (where a pull starts) and the aim's numbers and bar over it (or under it). */
const AIM_OVER_PRESS = 28;
/** Least margin, px, between the aim's numbers and bar and the screen's edges (at 4 px they read as jammed against the page's sidebar). */
const AIM_EDGE = 14;
/** The power bar's height with its padding, px. */
const AIM_BAR_H = 14;
/** Least gap, px, between the aim's numbers and the pull's band: the knob's radius (9 px) and 6 px. */
const AIM_CLEARANCE = 15;
/** The aim's numbers and bar on the screen in the last frame, px. */
let aimLabelBox: Box = { x: 0, y: 0, w: 0, h: 0 };

/**
 * Sets `n` dots (SVG circles, made as needed) in `group`, hiding the rest: `at(i)` gives dot i's
 * centre (px) and radius, its fill and outline opacity.
 */
function placeDots(group: SVGElement, n: number, at: (i: number) => [number, number, number, number]): void {
  while (group.childElementCount < n) group.append(svgChild('circle', { fill: '#fff', stroke: '#000', 'stroke-width': 1.5 }));
  for (let i = 0; i < group.childElementCount; i++) {
    const c = group.children[i] as SVGElement;
    if (i >= n) {
      if (c.getAttribute('display') !== 'none') c.setAttribute('display', 'none');
      continue;
    }
    const [x, y, r, fade] = at(i);
    setAttrs(c, {
      display: 'inline',
      cx: x.toFixed(1),
      cy: y.toFixed(1),
      r,
      'fill-opacity': (0.45 + 0.5 * fade).toFixed(2),
      'stroke-opacity': (0.35 + 0.35 * fade).toFixed(2),
    });
  }
}

/**
 * The arc preview for a throw at (vx, vy), m/s (see PREVIEW_TIME): only the flight's start
 * (previewReach: a short aiming arc, where it comes down judged by the player), all dots alike,
 * at least PREVIEW_GAP px apart (a small scene, an upright phone's, crowded them into a rope); where
 * it shows the whole flight (guide=full, or after repeated misses), dots fading along it to its first
 * touch, the last one (the touch) larger, and past the touch faint hollow dots where the throw was
 * headed had nothing stood in its way (flightPast), to the grass. While the castle's close-up
 * shows (an upright phone), the same flight's dots where it crosses the close-up, at its scale.
 */
function drawArc(vx: number, vy: number): void {
  const world = shell.world;
  const cam = renderer.camera;
  const flight = previewFlight(world, lv, vx, vy, -world.gravity[1]!, PREVIEW_TIME);
  // Only the flight's start (previewReach): where it comes down is the player's judgement.
  const arc = cutArc(flight, previewReach());
  const cut = arc !== flight;
  const n = arc.length / 2;
  aimShown.reach = arc[arc.length - 2]!;
  aimShown.end = [arc[arc.length - 2]!, arc[arc.length - 1]!];
  const dotR = cam.width < NARROW ? 3.5 : 4.5;
  /** Dots (screen px x, y, radius, fade) of the flight mapped by `map`, inside `keep`. */
  const dotsOf = (map: (x: number, y: number) => [number, number], keep: (x: number, y: number) => boolean): number[][] => {
    const out: number[][] = [];
    let lastX = Number.NEGATIVE_INFINITY,
      lastY = 0;
    for (let i = 1; i < n; i++) {
      const [px, py] = map(arc[2 * i]!, arc[2 * i + 1]!);
      // The touch (the flight's last point) always shows, larger; a cut flight's end is a dot like the rest.
      const end = i === n - 1 && !cut;
      if (!keep(px, py) || (!end && Math.hypot(px - lastX, py - lastY) < PREVIEW_GAP)) continue;
      lastX = px;
      lastY = py;
      out.push([px, py, end ? dotR + 1.5 : dotR, 1 - i / n]);
    }
    return out;
  };
  const main = dotsOf(
    (x, y) => [cam.toScreenX(x), cam.toScreenY(y)],
    () => true,
  );
  placeDots(aimDom.dots, main.length, (i) => main[i] as [number, number, number, number]);
  aimShown.dots = main.length;
  // Past the first touch, faint and hollow: where the throw was headed, so a long throw's preview
  // does not stop at the bank or the tower in front without showing where the throw would go.
  const [endX, endY] = aimShown.end;
  const ghost: number[][] = [];
  // (None for a throw that comes down on the grass or a pit's floor: it has landed.)
  const past = vx > 0.1 && !cut ? flightPast(lv, vx, vy, -world.gravity[1]!, (endX - LAUNCH.x) / vx, GHOST_TIME) : [];
  if (past.length > 4) {
    let lastX = cam.toScreenX(endX),
      lastY = cam.toScreenY(endY);
    for (let i = 2; i < past.length; i += 2) {
      const px = cam.toScreenX(past[i]!),
        py = cam.toScreenY(past[i + 1]!);
      if (Math.hypot(px - lastX, py - lastY) < PREVIEW_GAP) continue;
      lastX = px;
      lastY = py;
      ghost.push([px, py]);
    }
  }
  placeGhost(ghost, dotR);
  aimShown.ghost = ghost.length;
  let close: number[][] = [];
  if (closeShown) {
    const [bx, by, bw, bh] = closeShown.box,
      [sx, sy] = closeShown.src,
      z = closeShown.zoom;
    close = dotsOf(
      (x, y) => [bx + (cam.toScreenX(x) - sx) * z, by + (cam.toScreenY(y) - sy) * z],
      (x, y) => x >= bx && x <= bx + bw && y >= by && y <= by + bh,
    );
  }
  placeDots(aimDom.closeDots, close.length, (i) => close[i] as [number, number, number, number]);
  aimShown.closeDots = close.length;
}

/** Longest stretch of the faint flight past the preview's first touch (flightPast), s. */
const GHOST_TIME = 2;
/** Shows the faint hollow dots past the preview's first touch at screen points `at` (px), radius r - 1 px; hides the rest. */
function placeGhost(at: number[][], r: number): void {
  const group = aimDom.ghost;
  while (group.childElementCount < at.length)
    group.append(svgChild('circle', { fill: 'none', stroke: '#fff', 'stroke-width': 1.5, 'stroke-opacity': 0.55 }));
  for (let i = 0; i < group.childElementCount; i++) {
    const c = group.children[i] as SVGElement;
    const p = at[i];
    if (p === undefined) {
      if (c.getAttribute('display') !== 'none') c.setAttribute('display', 'none');
      continue;
    }
    setAttrs(c, { display: 'inline', cx: p[0]!.toFixed(1), cy: p[1]!.toFixed(1), r: r - 1 });
  }
}

/** The screen end of the pull's band (px): the finger, or a full pull's length from the press along the pull. */
function aimEnd(): [number, number] {
  const pull = Math.hypot(aim.dx, aim.dy);
  const k = (Math.min(pull, PULL.max) * aimScale()) / Math.max(pull, 1e-9);
  return [aim.x0 + aim.dx * k, aim.y0 - aim.dy * k];
}

/** Shows or hides the pause overlay. */
function drawPause(): void {
  pause.draw(shell.paused, app.screen.width, app.screen.height, touch);
}

/**
 * On an upright phone, once a throw stopped short with the castle off the screen (the camera
 * following it stopped before the castle), a close-up of the castle: the same scene CLOSE_MAX times
 * as large or less, as wide as the screen allows, framed and labelled, in the earth under the
 * ground or in the sky. Where the aim view is close on the catapult (./camera aimCloseUp: every
 * level on a phone), the castle's inset whenever the castle is not wholly on the screen (from the
 * opening's pan to the catapult, while aiming, and through a throw's flight at its size and place
 * from the aim, until the camera has the whole castle on the screen): as large as the
 * earth under the ground holds it (CLOSE_MAX times the scene's scale at most, smaller where a wide
 * castle needs), labelled with its distance, with the arc preview's dots where they cross it; it
 * stands for the look button and stays while a pull's band crosses it (the band is drawn over it).
 * Hidden when the level is over, and on other screens.
 *
 * The close-up's texture has one texel per CSS pixel whatever the screen's pixel ratio: at a phone's
 * ratio of 2 it would hold four times the texels, and under software WebGL (SwiftShader) rendering
 * that into a texture every few frames can hold the GPU process up for seconds with no frame drawn.
 */
let closeTexture = RenderTexture.create({ width: 16, height: 16, resolution: 1 });
const closeSprite = new Sprite(closeTexture);
const closeFrame = new Graphics({ label: 'close-up frame' });
const closeLabel = new Text({
  text: 'castle, close up',
  style: {
    fill: 0xffffff,
    fontSize: 13,
    fontFamily: 'sans-serif',
    fontWeight: 'bold',
    stroke: { color: 0x000000, width: 3, join: 'round' },
  },
});
closeSprite.visible = closeFrame.visible = closeLabel.visible = false;
app.stage.addChild(closeSprite, closeFrame, closeLabel);
/** The smallest magnification of the close-up worth showing (its largest: CLOSE_MAX). */
const CLOSE_MIN = 1.4;
/** Sky over the castle's top in its inset while aiming where the arc preview shows the whole flight (guide=full, or after repeated misses), m: room for its dots coming down on the castle (elsewhere 0.8 m). */
const CLOSE_SKY_AIMING = 2;
/** Pixels between the close-up's foot and the top of the castle on the screen. */
const CLOSE_GAP = 36;
/** Pixels over the aim's power bar (3.2 m up) kept clear for its two lines of numbers. */
const AIM_LABEL_ROOM = 64;
/** The close-up's box on the screen (px: x, y, width, height) and its magnification; null while hidden. */
let closeShown: { box: [number, number, number, number]; zoom: number; src: [number, number] } | null = null;
/** How many times the close-up's texture has been drawn since the page loaded. */
let closeDraws = 0;
/** Whether the close-up shows in the earth while the player aims (drawAim then keeps the aim's numbers out of the earth). */
let closeWhileAiming = false;
/** The castle's inset's width, left and top while the player last aimed, px: kept while a throw is followed (drawCloseUp). */
let insetHeld: { bw: number; bx: number; by: number } | null = null;
/** Where the inset stands aside from the pull being made (pullInset), px; null when no pull moved it. */
let insetAside: InsetPlace | null = null;
/**
 * While a pull is under way, where the castle's inset (w x h px at scale 1, usually at scale `zoom`)
 * stands in the earth's band `slot` clear of the pull's band (./pull insetBesidePull); null where
 * no pull is under way or it does not cross the inset's usual place. Kept while the pull does not
 * cross it, so a moving finger does not resize the inset every frame.
 */
function pullInset(slot: [number, number], w: number, h: number, zoom: number): InsetPlace | null {
  if (!aim.active) return (insetAside = null);
  const [ex, ey] = aimEnd();
  insetAside = insetBesidePull([aim.x0, aim.y0, ex, ey], slot, renderer.camera.width, w, h, zoom, CLOSE_MAX, insetAside);
  return insetAside;
}
/** Whether the close-up sits in the earth under the ground (out of a pull's way), not in the sky. */
let closeLow = false;
/**
 * What the close-up showed when it was last drawn (its box, zoom and the camera; each piece's and
 * stone's place and turn; the trail's length and look, larger while aiming), compared each frame by closeChanged: the texture is
 * drawn again only when one of them moved by more than a fraction of a close-up pixel, or while
 * bits of debris or popups are in the air, and then at most every CLOSE_EVERY frames. While the
 * player aims at a castle at rest it is drawn once; under software WebGL a render to a texture every
 * few frames held the GPU process up for seconds with no frame drawn.
 */
const closeSeen: number[] = [];
const CLOSE_EVERY = 3;
/** Frames since the close-up was last drawn. */
let closeAge = CLOSE_EVERY;
/** Whether the close-up must be drawn again (see closeSeen); takes the new state when it must. */
function closeChanged(box: [number, number, number, number], zoom: number, tolerance: number): boolean {
  const now: number[] = [
    ...box,
    zoom,
    cameraView.minX,
    cameraView.minY,
    cameraView.maxX,
    cameraView.maxY,
    lastThrow.path.length + (aim.active ? 0.5 : 0),
  ];
  const world = shell.world;
  const P = world.components.Position,
    A = world.components.Angle.value;
  for (const list of [lv.pieces.map((p) => p.body), shots]) {
    for (const b of list) {
      if (!isAlive(world, b)) {
        now.push(Number.NaN, Number.NaN, Number.NaN);
        continue;
      }
      const k = slotOf(b);
      now.push(P.x[k]!, P.y[k]!, A[k]!);
    }
  }
  let changed = now.length !== closeSeen.length || effects!.bitCount > 0 || effects!.popupCount > 0;
  for (let i = 0; !changed && i < now.length; i++) {
    const a = now[i]!,
      b = closeSeen[i]!;
    // Box and camera to a tenth of a pixel or metre; places to `tolerance` m; turns to a hundredth of a radian.
    const tol = i < 5 ? 0.1 : i < 9 ? 1e-4 : i === 9 ? 0 : (i - 10) % 3 === 2 ? 0.01 : tolerance;
    if (Number.isNaN(a) !== Number.isNaN(b) || Math.abs(a - b) > tol) changed = true;
  }
  if (changed) {
    closeSeen.length = 0;
    closeSeen.push(...now);
  }
  return changed;
}
/** Draws the close-up (see above) for this frame, or hides it. */
function drawCloseUp(): void {
  const cam = renderer.camera;
  // In the shot view too once a throw that stopped short has settled with the castle off the screen.
  const castleOff = cam.toScreenX(lv.castleMaxX) > cam.width && lastThrow.verdict !== '';
  // Where the aim view is close on the catapult (every level on a phone), whenever the castle is not
  // wholly on the screen: while inset, while the camera pans between the castle and the catapult,
  // and while a throw is followed to it (hidden from the throw until the castle came into view, the
  // player lost sight of the target for the flight's first seconds).
  const close = upright() && !levelEnded && aimCloseUp(field(), cam.width, cam.height);
  const castleAway = cam.toScreenX(lv.castleMinX) < 0 || cam.toScreenX(lv.castleMaxX) > cam.width;
  const inset = close && !peeking && shot !== 'castle' && castleAway;
  const show = upright() && !levelEnded && ((shotView && castleOff) || inset);
  closeShown = null;
  if (show) {
    // The castle with room round it for what falls, from the ground (or a pit's floor) up.
    const floor = Math.min(0, ...lv.terrain.map((t) => t.maxY));
    const x0 = lv.castleMinX - 0.6,
      x1 = lv.castleMaxX + 0.6,
      y0 = floor - 0.3,
      y1 = lv.castleTop + (inset && previewReach() === Infinity ? CLOSE_SKY_AIMING : 0.8);
    const sx = cam.toScreenX(x0),
      sy = cam.toScreenY(y1),
      w = cam.toScreenLength(x1 - x0),
      h = cam.toScreenLength(y1 - y0);
    // Two places: in the earth under the ground, over the card saying how to play while it shows;
    // and in the sky, the band from the banner's foot to CLOSE_GAP px over the castle's top or, lower,
    // the catapult's arm (3.2 m up). The earth's (a third of the screen of plain earth, while the
    // sky is where the stone flies), unless a pull's band crosses it and not the sky's or it has
    // too little room: the close-up moves out of the aim's way, never hiding the band being pulled.
    const ground = cam.toScreenY(floor);
    const sky: [number, number] = [
      (banner.text !== '' ? banner.y + banner.height : 0) + 14,
      Math.min(sy - CLOSE_GAP, cam.toScreenY(3.2) - AIM_LABEL_ROOM),
    ];
    // (While a finger pulls, the card saying how to play is on its way out.)
    const earth: [number, number] = [ground + 12, cam.height - (aim.active ? 8 : Math.max(8, hintReserve()))];
    const crosses = (band: [number, number]): boolean => {
      if (!aim.active) return false;
      const ey = aimEnd()[1];
      return Math.max(aim.y0, ey) + 12 > band[0] && Math.min(aim.y0, ey) - 12 < band[1];
    };
    const zoomIn = (band: [number, number]): number => Math.min(CLOSE_MAX, (cam.width - 24) / w, (band[1] - band[0]) / h);
    // The place where it is the larger (the sky's when they are alike: a wide, low castle's close-up
    // there fills the sky over the field), unless a pull crosses it and not the other.
    const skyFirst = zoomIn(sky) >= 0.98 * zoomIn(earth);
    const slot = inset
      ? earth
      : crosses(skyFirst ? sky : earth) && !crosses(skyFirst ? earth : sky)
        ? skyFirst
          ? earth
          : sky
        : skyFirst
          ? sky
          : earth;
    closeLow = slot === earth;
    const [top, bottom] = slot;
    // While a throw is followed the inset keeps its size and place from the aim (the follow view rises
    // with a high stone, which would shrink the earth's band and the inset with it, frame by frame).
    const held = inset && shotView ? insetHeld : null;
    // While a pull's band crosses the inset, it moves beside or under the band (pullInset).
    const moved = inset && !held ? pullInset(slot, w, h, zoomIn(slot)) : null;
    const zoom = held ? held.bw / w : moved ? moved.zoom : zoomIn(slot);
    // Shown when it magnifies enough, or whenever the castle is off the screen (upright, the aim view
    // frames the catapult: the close-up is where the castle shows).
    if (inset ? zoom > 0 : zoom >= CLOSE_MIN || (zoom > 0.5 && sx + w > cam.width)) {
      const bw = Math.round(w * zoom),
        bh = Math.round(h * zoom);
      closeAge++;
      if (closeTexture.width !== bw || closeTexture.height !== bh) {
        // A new texture of the new size (a texture resized under the sprite left the sprite showing
        // its old size's corner of the new picture).
        const old = closeTexture;
        closeTexture = RenderTexture.create({ width: bw, height: bh, resolution: 1 });
        closeSprite.texture = closeTexture;
        old.destroy(true);
        closeSeen.length = 0;
        closeAge = CLOSE_EVERY;
      }
      // A quarter of a close-up pixel in metres: smaller moves are not drawn.
      const tolerance = 0.25 / Math.max(1e-6, zoom * cam.toScreenLength(1));
      if (closeAge >= CLOSE_EVERY && closeChanged([sx, sy, bw, bh], zoom, tolerance)) {
        closeAge = 0;
        closeDraws++;
        // The screen-space words over the scene and the drifting clouds are not part of the close-up.
        const words = [banner, bannerPanel, verdictText, offscreenText, castleText, pause.container, cloudLayer];
        const was = words.map((o) => o.visible);
        for (const o of words) o.visible = false;
        app.renderer.render({
          container: renderer.root,
          target: closeTexture,
          clear: true,
          // The sky behind the castle where the backdrop (drawn for the screen) does not reach.
          clearColor: SKY,
          transform: new Matrix().translate(-sx, -sy).scale(zoom, zoom),
        });
        words.forEach((o, k) => {
          o.visible = was[k]!;
        });
      }
      // Next to the ground: low in the sky's band (at the band's top it would hang under the banner
      // with a screen of empty sky between it and the castle), high in the earth's (it stays put when the
      // card under it goes).
      const bx = held ? held.bx : moved ? moved.bx : Math.round((cam.width - bw) / 2),
        by = held ? held.by : moved ? moved.by : Math.round(closeLow ? top : Math.max(top, bottom - bh));
      if (inset && !shotView) insetHeld = { bw, bx, by };
      closeSprite.position.set(bx, by);
      closeFrame
        .clear()
        .roundRect(bx - 1, by - 1, bw + 2, bh + 2, 6)
        .stroke({ width: 2, color: 0xffffff, alpha: 0.9 });
      closeLabel.position.set(bx + 6, by + 4);
      // While inset the castle is off the screen: the inset says how far it is (as the arrow at the edge).
      const words = inset ? `castle ${Math.round(lv.castleMinX - LAUNCH.x)} m ahead ▸` : 'castle, close up';
      if (closeLabel.text !== words) closeLabel.text = words;
      closeShown = { box: [bx, by, bw, bh], zoom, src: [sx, sy] };
    }
  }
  if (closeShown === null) {
    closeAge = CLOSE_EVERY;
    closeSeen.length = 0;
  }
  closeSprite.visible = closeFrame.visible = closeLabel.visible = closeShown !== null;
  closeWhileAiming = inset && closeShown !== null;
}

/**
 * The backdrop behind the castle: a sky shading from deep blue overhead to a pale horizon, the sun,
 * two ranges of hills and drifting clouds. The hills and clouds are scenery at a distance: they move
 * by a fraction of the camera's pan (parallax: far hills 0.3, near 0.6, clouds 0.15), so a pan to the
 * castle and back reads as depth. The sky is drawn again only when the screen's size or the horizon
 * moves, and each range of hills is one shape built once (in metres) and only moved and scaled, so a
 * frame does not cut the hills into triangles again; the clouds, which drift, are drawn every frame.
 */
const backdrop = new Container({ label: 'backdrop' });
const skyLayer = new Graphics({ label: 'sky' });
const cloudLayer = new Graphics({ label: 'clouds' });
const SKY_TOP = 0x3d7ccc,
  SKY_HORIZON = 0xd8eefb;
/** Clouds: x (m along their band, which repeats every CLOUD_SPAN), height (m), size (m). */
const CLOUDS: ReadonlyArray<readonly [number, number, number]> = [
  [2, 11, 1.6],
  [11, 14, 2.2],
  [19, 9.5, 1.3],
  [27, 13, 1.9],
  [36, 10.5, 2.4],
  [45, 15, 1.5],
];
const CLOUD_SPAN = 54;
/** Where the hills' shapes run along their band, m: wider than any view plus its parallax shift. */
const HILLS_FROM = -30,
  HILLS_TO = 110;
/**
 * A range of hills at parallax `p` (0 far, 1 near): height `amp` m above the ground, in `color`, as
 * a shape in metres along its band (x) and up from the ground (-y), placed each frame by placeHills.
 */
function hillShape(amp: number, seed: number, color: number): Graphics {
  const g = new Graphics({ label: 'hills' });
  g.moveTo(HILLS_FROM, 0);
  for (let u = HILLS_FROM; u <= HILLS_TO; u += 0.25) {
    const h = amp * (0.55 + 0.25 * Math.sin(0.21 * u + seed) + 0.2 * Math.sin(0.53 * u + 2 * seed));
    g.lineTo(u, -h);
  }
  g.lineTo(HILLS_TO, 0).closePath().fill(color);
  return g;
}
const HILLS: ReadonlyArray<{ p: number; g: Graphics }> = [
  { p: 0.3, g: hillShape(3.4, 0.7, 0x9cc3d2) },
  { p: 0.6, g: hillShape(1.9, 2.1, 0x79ad73) },
];
backdrop.addChild(skyLayer, cloudLayer, ...HILLS.map((h) => h.g));
renderer.root.addChildAt(backdrop, 0);
/** Screen width and horizon (px) the sky was drawn for. */
let skyFor = '';

/** The sun's disc and glow radii, px. */
const SUN_RADIUS = 30,
  SUN_GLOW = 84;
/**
 * Upright, the sun's height under the screen's top, a share of the horizon's: under the banner's
 * panel (at 0.2 a phone's four-line banner covered it), over the castle's top.
 */
const SUN_UPRIGHT = 0.36;
/** Where the sun was drawn: centre x, y, disc and glow radii, px. */
let sunAt: [number, number, number, number] = [0, 0, SUN_RADIUS, SUN_GLOW];

function drawBackdrop(world: PhysicsWorld): void {
  const cam = renderer.camera;
  const W = cam.width,
    horizon = Math.min(cam.height, cam.toScreenY(0));
  const key = `${W} ${Math.round(horizon)}`;
  if (key !== skyFor) {
    skyFor = key;
    skyLayer.clear();
    const bands = 40;
    for (let i = 0; i < bands; i++) {
      const y0 = (horizon * i) / bands;
      skyLayer.rect(0, y0, W, horizon / bands + 1).fill(mixColor(SKY_TOP, SKY_HORIZON, (i + 0.5) / bands));
    }
    // Upright, lower: under the banner (its four lines at most on a phone reach about 100 px).
    const sunX = W * 0.82,
      sunY = Math.max(70, horizon * (upright() ? SUN_UPRIGHT : 0.2));
    sunAt = [sunX, sunY, SUN_RADIUS, SUN_GLOW];
    for (let r = SUN_GLOW; r > SUN_RADIUS + 4; r -= 10) skyLayer.circle(sunX, sunY, r).fill({ color: 0xfff4cc, alpha: 0.07 });
    skyLayer.circle(sunX, sunY, SUN_RADIUS).fill(0xfff6d8);
  }
  const scale = cam.toScreenLength(1),
    left = cam.toWorldX(0);
  cloudLayer.clear();
  for (const [x, y, r] of CLOUDS) {
    const u = (((x + 0.35 * world.time - 0.15 * left) % CLOUD_SPAN) + CLOUD_SPAN) % CLOUD_SPAN;
    const cx = (u - 6) * scale,
      cy = cam.toScreenY(y),
      k = r * scale;
    if (cx < -4 * k || cx > W + 4 * k) continue;
    cloudLayer.ellipse(cx, cy, 1.6 * k, 0.55 * k).fill({ color: 0xffffff, alpha: 0.85 });
    cloudLayer.circle(cx - 0.55 * k, cy - 0.25 * k, 0.55 * k).fill({ color: 0xffffff, alpha: 0.9 });
    cloudLayer.circle(cx + 0.25 * k, cy - 0.45 * k, 0.7 * k).fill({ color: 0xffffff, alpha: 0.9 });
  }
  // A hill's band point u is at screen x (u - p * left) * scale (see hillShape).
  for (const { p, g } of HILLS) {
    g.position.set(-p * left * scale, cam.toScreenY(0));
    g.scale.set(scale);
  }
}

/** The level is over when no shots are left and 4 s passed since the last, or everything (or everything that counts) fell. */
function levelOver(world: PhysicsWorld, t: Tally): boolean {
  // Three stars' worth down (nothing more to win but the unused shots' bonus) ends it too, so the
  // player need not throw the shots left after the castle is down.
  const settled = world.time - lastShotTime > 4;
  const c = countedDown(lv);
  return t.fallen === lv.pieces.length || c.down === c.of || (settled && (shotsLeft === 0 || starsOf(downShare()) === 3));
}

/**
 * Points for each shot not thrown when a level ends with three stars (fewer shots, more points). Only
 * for three stars: paid on any clear, it made moving on after a rough first clear ("+300 for shots
 * left if you move on now") worth more than throwing them for more stars.
 */
const SHOT_BONUS = 150;

/**
 * Pebbles and buried stones in the earth under the ground: x, y and radius, m (fixed, from a seeded
 * generator): small near the grass, up to half a metre deeper down, so the earth a phone shows under
 * the scene (about 40 % of its height) reads as ground, not a plain brown panel.
 */
const PEBBLES: number[] = (() => {
  const r = new Rng(11);
  const out: number[] = [];
  for (let i = 0; i < 240; i++) {
    const y = r.range(-16, -1.3);
    out.push(r.range(-12, 40), y, r.range(0.08, 0.22 + 0.02 * Math.min(14, -y)));
  }
  return out;
})();
/** Roots under the grass: x, m, length, m, and lean (fixed, seeded). */
const ROOTS: number[] = (() => {
  const r = new Rng(5);
  const out: number[] = [];
  for (let i = 0; i < 70; i++) out.push(r.range(-12, 40), r.range(0.2, 0.45), r.range(-0.4, 0.4));
  return out;
})();
/**
 * Draws the earth's layers under the ground slab, `span` px wide: strata with wavy tops, darker with
 * depth, roots under the grass, and pebbles and stones with a lit top.
 */
function drawEarth(span: number): void {
  const cam = renderer.camera,
    sx = (x: number) => cam.toScreenX(x),
    sy = (y: number) => cam.toScreenY(y);
  for (let k = 1; k <= 4; k++) {
    const base = -1 - 1.5 * k;
    if (sy(base + 0.3) >= cam.height) break;
    const pts: number[] = [0, cam.height];
    for (let px = 0; px <= span + 40; px += 40) {
      const x = cam.toWorldX(px);
      pts.push(px, sy(base + 0.25 * Math.sin(0.7 * x + 1.9 * k) + 0.12 * Math.sin(2.3 * x + k)));
    }
    pts.push(span + 40, cam.height);
    overlay.poly(pts).fill({ color: 0x2a1a0c, alpha: 0.13 });
  }
  for (let i = 0; i < ROOTS.length; i += 3) {
    const x = ROOTS[i]!,
      len = ROOTS[i + 1]!,
      lean = ROOTS[i + 2]!;
    overlay
      .moveTo(sx(x), sy(-1))
      .quadraticCurveTo(sx(x + lean * 0.2), sy(-1 - len * 0.6), sx(x + lean * len), sy(-1 - len))
      .stroke({ width: Math.max(1, cam.toScreenLength(0.035)), color: 0x3b2714, alpha: 0.6 });
  }
  for (let i = 0; i < PEBBLES.length; i += 3) {
    const x = sx(PEBBLES[i]!),
      y = sy(PEBBLES[i + 1]!),
      r = cam.toScreenLength(PEBBLES[i + 2]!);
    if (y - r > cam.height || x + r < 0 || x - r > span) continue;
    overlay.ellipse(x, y, r, 0.6 * r).fill({ color: 0x9a8468, alpha: 0.55 });
    if (r > 4) overlay.ellipse(x - 0.2 * r, y - 0.22 * r, 0.55 * r, 0.25 * r).fill({ color: 0xc8b594, alpha: 0.45 });
  }
}

/** The rock's outline around its box, in units of its half extents (x, y pairs from the bottom left). */
const ROCK_OUTLINE = [-1.25, -1, -1.15, 0.6, -1.0, 1.1, -0.3, 1.25, 0.5, 1.2, 1.1, 1.05, 1.25, 0.3, 1.3, -1];
/** Draws the rock past the castle as a boulder with a lit face, over its box. */
function drawRock(): void {
  if (!lv.rock || !isAlive(shell.world, lv.rock)) return;
  const cam = renderer.camera;
  const cx = lv.castleMaxX + ROCK.gap + ROCK.hx,
    cy = ROCK.hy;
  const pts = ROCK_OUTLINE.map((v, i) => (i % 2 === 0 ? cam.toScreenX(cx + v * ROCK.hx) : cam.toScreenY(cy + v * ROCK.hy)));
  overlay.poly(pts).fill(0x7d776e).stroke({ width: 1.5, color: 0x4f4a43 });
  const lit = [-1.15, 0.6, -1.0, 1.1, -0.3, 1.25, -0.1, 0.3, -0.6, -0.4].map((v, i) =>
    i % 2 === 0 ? cam.toScreenX(cx + v * ROCK.hx) : cam.toScreenY(cy + v * ROCK.hy),
  );
  overlay.poly(lit).fill({ color: 0xb3ab9e, alpha: 0.7 });
}

/**
 * Draws the level's distance marks (./distance distanceMarks): a pale tick on the grass's edge and
 * by it how far out it stands, at 11 px (13 on a wide screen): in the grass where it is 24 px deep or
 * more and the castle's inset is not under it (a phone's, while aiming), else over the tick.
 */
function drawDistances(): void {
  const cam = renderer.camera;
  const marks = distanceMarks(lv);
  const depth = cam.toScreenY(-1) - cam.toScreenY(0);
  const size = cam.width < NARROW ? 11 : 13;
  while (distanceLayer.children.length < marks.length)
    distanceLayer.addChild(
      new Text({
        text: '',
        style: {
          fill: 0xffffff,
          fontSize: size,
          fontFamily: 'sans-serif',
          fontWeight: 'bold',
          stroke: { color: 0x000000, width: 3, join: 'round' },
        },
      }),
    );
  distanceLayer.children.forEach((c, i) => {
    const label = c as Text,
      m = marks[i];
    label.visible = m !== undefined;
    if (!m) return;
    const x = cam.toScreenX(m.x),
      y = cam.toScreenY(0),
      // (Over the grass while the castle's inset lies under it, drawCloseUp: it would hide them.)
      inGrass = depth >= 24 && !closeWhileAiming;
    overlay.rect(x - 1, y - 6, 2, inGrass ? 6 + depth * 0.25 : 6).fill({ color: 0xffffff, alpha: 0.7 });
    if (label.text !== m.label) label.text = m.label;
    if (label.style.fontSize !== size) label.style.fontSize = size;
    label.alpha = 0.85;
    label.anchor.set(0.5, inGrass ? 0.5 : 1);
    label.position.set(x, inGrass ? y + depth * 0.55 : y - 7);
  });
}

function draw(world: PhysicsWorld, alpha: number): void {
  drawBackdrop(world);
  const cam = renderer.camera,
    sx = (x: number) => cam.toScreenX(x),
    sy = (y: number) => cam.toScreenY(y);
  overlay.clear();
  // Earth under the ground slab, to the bottom of the screen, and on past its right edge to beyond the
  // rock: a phone's castle inset (drawCloseUp) draws the castle from off the screen.
  const span = Math.max(cam.width, sx(rockRight() + 2));
  overlay.rect(0, sy(-1), span, Math.max(0, cam.height - sy(-1))).fill(EARTH);
  // Strata, roots and stones: earth, not a flat brown panel.
  drawEarth(span);
  drawRock();
  // The grass's top edge, lit, over the ground slab.
  overlay.rect(0, sy(0) - 1, span, Math.max(2, cam.toScreenLength(0.12))).fill(0x76b852);
  drawDistances();
  // The level's hill or pit over the flat ground.
  for (const t of lv.terrain) {
    if (t.kind === 'hill') drawHill(overlay, cam, t.minX, t.maxX, t.minY, t.maxY, 0x8a6238, 0x76b852);
    else if (t.kind === 'pit') drawPit(overlay, cam, t.minX, t.maxX, t.maxY, EARTH);
  }
  drawMound(overlay, cam, 0x7a5533, 0x5e9c45);
  const dt = Math.min(0.1, Math.max(0, world.time - lastDrawTime));
  lastDrawTime = world.time;
  swingArm(dt);
  drawCatapult(overlay, cam, arm.angle);
  drawAmmo();
  const t = tally(world, lv);
  if (t.score > best.score) best = t;
  showBreaks(world);
  drawPieces(world, alpha);
  followThrow(world, t);
  // A good throw's points keep counting what falls after it was decided.
  if (lastThrow.good && lastThrow.verdict) lastThrow.verdict = `+${t.score - lastThrow.scoreBefore}`;
  drawThrow(world);
  drawAim();
  effects!.update(dt, -world.gravity[1]!);
  effects!.draw(cam);
  drawPause();
  if (!levelEnded && levelOver(world, t)) recordLevel(t);
  if (!celebrated && (levelEnded ? campaign.stars[params.level - 1]! > 0 : clearedEarly(world))) celebrate();
  // One level score everywhere (banner and readout): the live tally while the level is on; once it is
  // over, the score it counted (with the bonus for shots left), which later debris no longer changes.
  const i = params.level - 1;
  const score = levelEnded ? campaign.scores[i]! : t.score;
  const runningTotal = total() - (levelEnded ? 0 : campaign.scores[i]!) + (levelEnded ? 0 : score);
  writeReadout(score, [
    `${params.level} / ${LEVEL_COUNT} ${lv.name}`,
    String(shotsLeft),
    String(score),
    String(runningTotal),
    `${countedDown(lv).down} / ${countedDown(lv).of}`,
    `${t.broken} / ${lv.joints.length}`,
  ]);
  banner.x = app.screen.width / 2;
  banner.y = 16;
  // Narrow screens: smaller type, wrapped inside the canvas; an upright phone's (`brief`) smaller
  // still and fewer words (see BANNER_FONT_UPRIGHT): four lines or more covered the sun and a third
  // of the sky there.
  const narrow = app.screen.width < 600,
    brief = upright();
  const fontSize = brief ? BANNER_FONT_UPRIGHT : narrow ? 17 : 22;
  if (banner.style.wordWrapWidth !== app.screen.width - 24 || banner.style.fontSize !== fontSize) {
    banner.style.wordWrapWidth = app.screen.width - 24;
    banner.style.fontSize = fontSize;
  }
  const starRule = narrow ? STAR_RULE_SHORT : STAR_RULE;
  if (levelEnded) {
    const earned = campaign.stars[i]!;
    const bonus = earned === 3 ? shotsLeft * SHOT_BONUS : 0;
    const stars = '★'.repeat(earned) + '☆'.repeat(3 - earned);
    const last = params.level === LEVEL_COUNT;
    const starsWon = campaign.stars.reduce((a, b) => a + b, 0);
    if (earned === 0) {
      const keys = touch ? 'Tap the button below to try again' : 'Enter, L or the button below: try again';
      const c = countedDown(lv);
      // Upright: no star rule or keys (the button says "Try again ↺"); what counts as down stays.
      banner.text = brief
        ? `Level ${params.level} not cleared  ${stars}\n${c.down} of ${c.of} down: bring down half to pass\n${DOWN_RULE_SHORT}`
        : `Level ${params.level} not cleared  ${stars}\n${c.down} of ${c.of} pieces down: bring down half to pass\n${DOWN_RULE}\n${starRule}\n${keys}`;
      showNext(true, 'Try again ↺');
    } else if (last) {
      // Levels skipped (L before a clear, the level slider or ?level) have no stars: the end screen
      // names them rather than claiming every castle fell.
      const skipped = campaign.stars.flatMap((s, k) => (s > 0 ? [] : [k + 1]));
      const head =
        skipped.length === 0
          ? `All ${LEVEL_COUNT} castles down!`
          : `${LEVEL_COUNT - skipped.length} of ${LEVEL_COUNT} castles down (${skipped.length === 1 ? 'level' : 'levels'} ${skipped.join(', ')} not cleared)`;
      banner.text = brief
        ? `${head}  ${stars}\nTotal score ${total()}   Stars ${starsWon} / ${3 * LEVEL_COUNT}`
        : `${head}  ${stars}\nTotal score ${total()}   Stars ${starsWon} / ${3 * LEVEL_COUNT}\n${starRule}\n${touch ? 'Tap below to play again' : 'Enter, L or the button below: play again'}`;
      showNext(true, 'Play again from level 1 ▶');
    } else {
      const keys = touch
        ? 'Tap the button below for the next level, ↺ to try again'
        : 'Enter, L or the button below: next level   R: try again';
      // In a player's words: the pieces that count for the stars, knocked down of all of them (not
      // "9 down (darker), 4 welds broke": a weld is the engine's word, and the darker pieces are seen).
      const c = countedDown(lv);
      const knocked = `${c.down} of ${c.of} pieces knocked down`;
      const extra = bonus > 0 ? ` + ${bonus} for ${shotsLeft} ${shotsLeft === 1 ? 'shot' : 'shots'} left` : '';
      // Upright: the score's parts in brief, no star rule (the stars earned are on the first line),
      // and of the keys only the retry (the button names the next level).
      banner.text = brief
        ? `Level ${params.level} cleared  ${stars}  Score ${score}\n${knocked}${bonus > 0 ? `, +${bonus} for shots left` : ''}\nTotal ${total()}   ${touch ? '↺ to try again' : 'R: try again'}`
        : `Level ${params.level} cleared  ${stars}\nScore ${score}: ${knocked}${extra}   Total ${total()}\n${starRule}\n${keys}`;
      showNext(true, `Level ${params.level + 1} ▶`);
    }
  } else {
    // The total counts this level's score as it grows; before the first throw, the star rule.
    // Before the first throw the level's name stands where its score (0) will be.
    // Two short lines: the level and its shots, then the star rule. What counts as down is in the
    // controls' help (the card saying how to play on a phone), and the pieces down darken.
    const rule = shots.length === 0 ? `\n${brief ? '' : 'Stars: '}${starRule}` : '';
    const head = shots.length === 0 ? `Level ${params.level}: ${lv.name}` : `Score ${score}`;
    // "shots left", not "shots": "shots 2" reads as the shots thrown. Upright, no "Total 0" (one line, not two).
    const totalPart = brief && runningTotal === 0 ? '' : `  Total ${runningTotal}`;
    const running = `${head}${totalPart}  ${shotsLeft} ${shotsLeft === 1 ? 'shot' : 'shots'} left${rule}`;
    if (clearedEarly(world)) {
      // Cleared with shots to spare: the player may move on now or throw again for more stars (the
      // shots left score a bonus only with three stars, so throwing them is never worth less).
      const earned = starsOf(downShare());
      const stars = '★'.repeat(earned) + '☆'.repeat(3 - earned);
      // Plain words: what a throw does and what the button (or Enter) does ("Throw for ★ or move
      // on" was hard to parse).
      const button = params.level === LEVEL_COUNT ? 'Finish ▶' : `Level ${params.level + 1} ▶`;
      const bonus = touch
        ? `Throw again for more stars, or tap ${button}`
        : `Throw again for more stars, or press Enter: ${params.level === LEVEL_COUNT ? 'finish' : 'next level'}`;
      banner.text = `Cleared with ${stars}!  ${bonus}\n${running}`;
      showNext(true, button);
    } else {
      // Once a throw's verdict is in, what to do next: the camera is back on the catapult.
      const again =
        shots.length > 0 && lastThrow.verdict !== '' && !aim.active ? `\n${touch ? 'Drag back anywhere' : 'Drag back'} to throw again` : '';
      banner.text = running + again;
      showNext(false);
    }
  }
  // The panel behind the banner: the text's box with 8 px (6 on a phone) round it.
  const pad = narrow ? 6 : 8,
    bw = banner.width,
    bh = banner.height;
  bannerPanel.clear();
  if (banner.text !== '' && bw > 0)
    bannerPanel
      .roundRect(banner.x - bw / 2 - pad, banner.y - pad / 2, bw + 2 * pad, bh + pad, 8)
      .fill({ color: 0x000000, alpha: BANNER_PANEL_ALPHA });
  drawCloseUp();
}

/**
 * Whether the level on screen is cleared (a star's worth down) while shots are left, 4 s after the
 * last throw: the player may move on before throwing them.
 */
function clearedEarly(world: PhysicsWorld): boolean {
  if (levelEnded || shots.length === 0 || world.time - lastShotTime <= 4) return false;
  tally(world, lv);
  return starsOf(downShare()) > 0;
}

/** Whether this level's clear has been celebrated (once a level). */
let celebrated = false;
/** A level cleared: a rising three-note chime and confetti over the castle. */
function celebrate(): void {
  celebrated = true;
  for (const [k, pitch] of [523, 659, 784].entries()) setTimeout(() => sound.chime(pitch, 0.35), 140 * k);
  effects!.burst('confetti', (lv.castleMinX + lv.castleMaxX) / 2, lv.castleTop + 1.5, 60, 7);
}

/** Ends the level on screen: its score (with the unused shots' bonus for three stars) and stars count, once and only its best try. */
function recordLevel(t: Tally): void {
  const earned = starsOf(downShare());
  const score = t.score + (earned === 3 ? shotsLeft * SHOT_BONUS : 0);
  const i = params.level - 1;
  levelEnded = true;
  // A drag under way when the level ended throws nothing: its aim goes.
  aim.active = false;
  if (score > campaign.scores[i]!) campaign.scores[i] = score;
  if (earned > campaign.stars[i]!) campaign.stars[i] = earned;
}

// window.game: the shell (stats, pause, step, reset) plus what tests and the console need.
shell.expose({
  params,
  panel,
  /** The campaign: each level's best score and stars (0 to 3) once it was over. */
  campaign,
  /** Whether the level on screen is over. */
  levelEnded: (): boolean => levelEnded,
  /** Share of the pieces that count (all but a flat bottom row on the ground) down, in [0, 1]: what the stars are judged on. */
  downShare: (): number => downShare(),
  /** What the last throw did once it settled ('' before): '+N' points, or why it missed. */
  lastVerdict: (): string => lastThrow.verdict,
  /** The verdict's words over the scene in the last frame ('' while hidden). */
  verdictShown: (): string => (verdictText.visible ? verdictText.text : ''),
  /** The aim's numbers and power bar on the screen (px: left, top, width, height), and the pull's band [x0, y0, x1, y1] (px), while aiming. */
  aimLabelAt: (): { box: Box; band: [number, number, number, number] } => ({
    box: { ...aimLabelBox },
    band: [aim.x0, aim.y0, ...aimEnd()],
  }),
  /** The aim's numbers over the catapult in the last frame ('' while not aiming). */
  aimLabel: (): string => (aimDom.box.style.display === 'none' ? '' : (aimDom.label.textContent ?? '')),
  /** The effects now: bits of debris in flight, score popups showing, the points they add up to and their boxes (px: left, top, right, bottom). */
  effects: (): { bits: number; popups: number; points: number; boxes: number[][] } => ({
    bits: effects!.bitCount,
    popups: effects!.popupCount,
    points: effects!.popupPoints,
    boxes: effects!.popupBoxes(),
  }),
  /** The least height (m) of a chip or bit of confetti over the ground under it (Infinity when none; see Effects.lowestOverGround). */
  debrisOverGround: (): number => effects!.lowestOverGround(),
  /** The catapult's arm angle, rad (see CATAPULT in ./look: cocked at pi, upright at pi / 2). */
  armAngle: (): number => arm.angle,
  /** Screen pixels a metre of pull (a drag this many px long pulls 1 m; PULL.max m is a full pull). */
  aimPxPerM: aimScale,
  /** Where the last throw's stone was before and after the step it first touched anything in, m [x0, y0, x1, y1]; null until it has. */
  firstTouch: (): [number, number, number, number] | null => lastThrow.touchStep,
  /** The last throw's launch velocity [vx, vy], m/s ([0, 0] before a throw). */
  lastLaunch: (): [number, number] => (lastThrow.body ? [lastThrow.vx, lastThrow.vy] : [0, 0]),
  /** Whether the camera is at rest (tests aim at the cup once it is). */
  cameraSettled: (): boolean => cameraSettled,
  /** The view the camera heads for: 'overview', 'aim', 'follow' or 'castle' (camera.ts cameraShot). */
  cameraShot: (): CameraShot => shot,
  /** Makes the camera jump to the view it heads for at the next frame, not ease there (tests). */
  jumpCamera: (): void => {
    framedFor = '';
  },
  /** Ends the level's opening look at the castle now, as a player's first touch does (tests that frame each level's aim view). */
  endOpening: (): void => {
    openingFrames = 0;
  },
  /** The level's tally now. */
  tally: (): Tally => tally(shell.world, lv),
  /** Shots left, and the thrown projectiles' handles. */
  shotsLeft: (): number => shotsLeft,
  shots: (): number[] => [...shots],
  /** The level (pieces, joints, castle extent). */
  level: (): Level => lv,
  /** Throws with a pull (dx, dy), m (tests). @returns the projectile's handle, or 0 if none was thrown. */
  fire,
  /** The castle's close-up on an upright phone (see drawCloseUp): its box (px), magnification and whether it sits low (in the earth), or null while hidden. */
  closeUp: () => (closeShown ? { ...closeShown, low: closeLow } : null),
  /** How many times the close-up's texture has been drawn since the page loaded (it is drawn only when its scene changed). */
  closeDraws: (): number => closeDraws,
  /** The screen sizes (CSS px, 'WxH') the camera has framed since the page loaded. */
  sizesFramed: (): string[] => [...sizesFramed],
  /** Position of a body by handle, m (tests). */
  positionOf,
  /** Whether the camera shows (or eases to) the shot view, close on the castle after a throw. */
  shotView: (): boolean => shotView && zoomsIn(),
  /** The off-screen marker's distance while it shows ('N m past ▸'), else ''. */
  offscreen: (): string => (offscreenText.visible ? offscreenText.text : ''),
  /** The castle's arrow at the screen's edge while the castle is off the screen (drawCastleMarker): its label and its label's box (px: left, top, right, bottom); null while hidden. */
  castleMarker: (): { text: string; box: number[] } | null => {
    if (!castleText.visible) return null;
    const b = castleText.getBounds();
    return { text: castleText.text, box: [b.minX, b.minY, b.maxX, b.maxY] };
  },
  /** The off-screen marker's screen y, px (its label's middle). */
  offscreenY: (): number => offscreenText.y,
  /** Dots of the last throw's trail drawn in the last frame. */
  trailDots: (): number => trailDots,
  /**
   * Boxes (px: left, top, right, bottom) of the verdict and the off-screen marker's label in the
   * last frame, each null while hidden.
   */
  wordBoxes: (): { verdict: number[] | null; offscreen: number[] | null } => {
    const box = (t: Text): number[] | null => {
      if (!t.visible) return null;
      const b = t.getBounds();
      return [b.minX, b.minY, b.maxX, b.maxY];
    };
    return { verdict: box(verdictText), offscreen: box(offscreenText) };
  },
  /**
   * What the aim shows now: power (0 to 1), angle (degrees above level), dots of the arc preview on
   * the scene and in the phone's close-up (0 when not aiming), the preview's farthest x, m, and its
   * end (m), where the stone will first touch something.
   */
  aimShown: (): { power: number; angle: number; dots: number; closeDots: number; reach: number; end: [number, number] } => ({
    ...aimShown,
  }),
  /** Screen pixels of drag for a full pull. */
  fullPullPx,
  /** The level score shown in the last frame, and the running total. */
  shownScore: (): number => shownScore,
  total,
  /** The banner's text and whether the pause overlay shows. */
  bannerText: (): string => banner.text,
  /** The sun's centre x, y and its disc and glow radii, px. */
  sunAt: (): [number, number, number, number] => [...sunAt],
  /** The banner's size on the screen and its type size, px (its lines: about height / (1.2 fontSize)). */
  bannerSize: (): { width: number; height: number; fontSize: number } => ({
    width: banner.width,
    height: banner.height,
    fontSize: banner.style.fontSize,
  }),
  pauseShown: (): boolean => pause.visible,
  /**
   * The dark panel behind the banner in the last frame: its box on the screen, px, and its opacity
   * (0 to 1), and the banner's box; null while the banner is empty.
   */
  bannerPanel: (): { panel: [number, number, number, number]; alpha: number; text: [number, number, number, number] } | null => {
    if (banner.text === '') return null;
    const b = bannerPanel.getLocalBounds();
    return {
      panel: [b.minX, b.minY, b.maxX, b.maxY],
      alpha: BANNER_PANEL_ALPHA,
      text: [banner.x - banner.width / 2, banner.y, banner.x + banner.width / 2, banner.y + banner.height],
    };
  },
  /** Steps the world n times (tests). */
  advance: (n: number) => {
    for (let i = 0; i < n; i++) shell.step();
  },
});
