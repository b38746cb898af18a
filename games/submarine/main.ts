/**
 * Submarine: the book's submarine (Ramtal and Dobre ch. 16) as a game. Hold Dive or Rise: the depth
 * ordered (a dashed line by the hull and a cyan mark on the depth gauge, with figures, at the scene's right edge)
 * runs down or up at once, the vertical thrusters and (under way) the dive planes push at once and the
 * vents flood or blow the ballast tanks; let go and the boat stops on the ordered depth and holds it
 * (./helm.ts, ./planes.ts), a depth ladder behind the stern sliding past it meanwhile. A held Dive
 * or Rise stops level with the target beacon a moment (./level-stop.ts), and a dashed line at the
 * target's depth runs from its ring back past the hull, green while the boat will pass through the
 * ring (the label then reads "level ✓"). Hold Nose down
 * or up to pitch, and drive the screw ahead or astern (let go, the boat glides about a hull's length
 * and stops). A trail of glowing plankton leads from beacon to beacon round the mines (./trail.ts):
 * each glow caught scores, more for a streak of them (a first-time hint over the scene says how much). The hull floats by Archimedes (its submerged part of a 12 m x 3 m box), drags in proportion
 * to how much of it is under water and bobs in the waves. Collect every beacon before three hits
 * (a scrape on the seabed, or a moored mine laid beside the way between two beacons: ./mines.ts)
 * break the hull, inside the course's par time if you can (the clock starts at the first control held): a won run earns a star for the beacons,
 * one for par and one for an unhurt hull (the best time of each course is kept). Three levels
 * (./levels.ts, ?level=): each later course has more beacons and more mines nearer the way; the
 * status line starts with the level ("L2") and a won run offers the next one. A mine on the
 * boat's course within MINE_WARN_TIME s (at least MINE_LOOK_AHEAD m) is told by the hull: a red
 * arrow from it to the mine, a tag over the sail ("rise over") or under the keel ("dive under") and a low two-note call.
 * Keys: S / W or down / up arrows dive / rise, A / D or left / right arrows astern / ahead, Q / E
 * nose down / up (each press tilts it 5° more and it stays; Dive or Rise levels it), P pause, N step, R reset. Touch: a stick under the scene (down dives, up rises,
 * right ahead, left astern; pushed part way it asks for part of the speed; up or down only keeps the
 * screw running as it was) and Nose buttons.
 * Sound: the screw's hum follows the throttle, a hiss when the vents open or the tanks blow, a sonar
 * ping that quickens as the next beacon nears, a rising chime for each beacon (rings spread from it
 * and a banner counts it), a thump on the seabed, a blast (a flash and bubbles) when a mine goes off.
 * A scrape on the seabed shakes the view a little, a hit more; on a phone each also buzzes.
 */

import {
  createActionButton,
  createButtonBar,
  createPanel,
  createStick,
  getSound,
  isTouchDevice,
  numberParam,
  pageLayout,
  seedParam,
} from '@bitphysics/game-kit';
import { createPauseOverlay, startPixiGame } from '@bitphysics/game-kit/pixi';
import { applyImpulse, createPhysicsWorld, type PhysicsWorld, step } from '@bitphysics/physics';
import { SUBMARINE, SUBMARINE_NEUTRAL_FILL, type SubmarineHandles, seabedHeight, submarine } from '@bitphysics/projects';
import { Graphics, Text } from 'pixi.js';
import {
  BEACON_CATCH,
  BRAKE_HINT_COURSE,
  beaconLabel,
  beaconName,
  catchesBeacon,
  chooseBeacon,
  courseSpeed,
  lastBeacon,
  layCourse,
  letGoHint,
  missWarning,
  missWarningText,
  passedBeacon,
  ridgeInWay,
} from './beacons';
import { drawBoat, HEADLIGHT, inHeadlight } from './boat-drawing';
import { CURRENT_NOTE_LIFE, CURRENT_NOTE_SPEED, currentAt, currentMark, currentNote, drawCurrent, driftInCurrent } from './current';
import { type EdgeMark, edgeMarks } from './edge-marks';
import { FRAME_MARGIN, LEAD_SHARE, leadLimits, PORTRAIT_MIN_WIDTH, PORTRAIT_MIN_ZOOM_UNDER_WAY } from './framing';
import { coastDistance, createHelmState, HELM, type HelmInput, holdFloor, keyHeaveShare, NO_INPUT, noseTrim, steer } from './helm';
import { createLevelStop, LEVEL_BAND, levelStop, levelWith } from './level-stop';
import { bestTimes, LEVELS, levelCourse, MAX_BEACONS, MAX_BEST_TIME } from './levels';
import {
  hullDistance,
  layMines,
  MINE_BLAST_IMPULSE,
  MINE_RADIUS,
  type Mine,
  type MineAhead,
  mineAhead,
  mineOnWay,
  mineWarnHorizon,
  parTime,
  touchesMine,
} from './mines';
import { pauseBandTop } from './pause-band';
import { createHeaveTiming, createPressTiming, releasedOrder } from './release';
import { drawFish } from './sea-life';
import { type BedAhead, bedAhead, DIVE_STOPPED_WORD, helmWord, seabedInput, touchSeabed } from './seabed';
import { stickDirection, stickHeaveDirection, stickOrder, stickShare } from './stick';
import { type Glow, layTrail, touchesGlow } from './trail';

const params = {
  seed: seedParam(),
  beacons: numberParam('beacons', { default: 6, min: 1, max: MAX_BEACONS, integer: true }),
  /** The level (./levels.ts): 1 is the page's course; each later one more beacons and mines, narrower passages. */
  level: numberParam('level', { default: 1, min: 1, max: LEVELS.length, integer: true }),
  waveHeight: numberParam('waves', { default: 1, min: 0, max: 3 }),
  pixelsPerMeter: numberParam('zoom', { default: 8, min: 2, max: 20 }),
  reset: () => shell.reset(),
};

/**
 * Game state beside the physics: the helm's (./helm.ts: throttle, tank targets, depth held),
 * collected beacons, hull damage (hits, the game time until which a bump counts as the last hit, and
 * what the last hit was), the course's par time (s) and the mines set off.
 */
const state = {
  ...createHelmState(),
  collected: 0,
  hits: 0,
  spared: 0,
  touching: false,
  diveStopped: false,
  over: '' as '' | 'won' | 'sunk',
  /** The run's clock, s of game time since the first control was held (0 until then: the help can be read first). */
  time: 0,
  /** Game time the first control was held (the clock's start), s; NaN until then. */
  startedAt: Number.NaN,
  par: 0,
  lastHit: '' as '' | 'seabed' | 'mine',
  minesHit: 0,
  /** Glows of the trail caught, the streak of glows caught one after another without missing one, and the score. */
  glowsCaught: 0,
  streak: 0,
  score: 0,
};
let handles: SubmarineHandles;
let taken: boolean[] = [];
/**
 * What the skip banner and the pointer to a skipped beacon tell to do after "skipped: still counts"
 * (its tag says that much): it scores if collected before the finish, and the boat always faces
 * ahead, so Astern backs it there. Lines short enough for a phone's banner.
 */
const ASTERN_BACK = 'Astern back to it';
/** Beacons passed and left behind uncollected (./beacons.ts passedBeacon): marked missed on the scene and counted in the goal line. */
let missed: boolean[] = [];
/** The target beacon the pointer warns is being left behind (./beacons.ts missWarning), -1 for none: a new warning chimes. */
let missWarned = -1;
/** The course's moored mines (./mines.ts) and whether each is still live (a mine that went off is gone). */
let mines: Mine[] = [];
let mineLive: boolean[] = [];
/** The live mine on the straight way to the pointer's beacon (./mines.ts mineOnWay), -1 for none: drawn ringed. */
let wayMine = -1;
/**
 * The live mine on the boat's course within MINE_WARN_TIME s (./mines.ts mineAhead), null for none:
 * drawn ringed, with a warning by the hull (an arrow from it to the mine and which way to pass).
 */
let ahead: MineAhead | null = null;
/**
 * The seabed on the boat's course within BED_WARN_TIME s (./seabed.ts bedAhead) while no mine is
 * warned of, null for none: told by the hull as a mine is (a ridge to rise over).
 */
let bedWarn: BedAhead | null = null;
/** Within this distance of the hull, m, a mine is drawn with a pulsing warning ring. */
const MINE_WARN_DISTANCE = 25;
/** The course's glow trail (./trail.ts), and each glow's state: 0 to catch, 1 caught, 2 missed (passed by). */
let glows: Glow[] = [];
let glowState = new Uint8Array(0);
/** Glows caught, for the sparkle drawn at each: where (m), when (game time, s) and the points it scored. */
const glowPops: { x: number; y: number; time: number; points: number; times: number }[] = [];
/** How long a caught glow's sparkle lasts, s of game time. */
const GLOW_POP_LIFE = 0.7;
/** Points: a glow (times the streak, up to GLOW_STREAK_MAX), a beacon, and each second a won run beats par by. */
const GLOW_POINTS = 10,
  GLOW_STREAK_MAX = 5,
  BEACON_POINTS = 100,
  PAR_POINTS = 5;
/** What a glow is worth and when it counts, for the controls list and the first-time hint. */
const GLOW_LEGEND = `glow: +${GLOW_POINTS} when touched; in a row ×2, ×3 … ×${GLOW_STREAK_MAX}; pass one and it is ×1 again`;
/** The first-time hint's words: the glows' worth, the beacons' and par's. */
const GLOW_HINT = `● glow +${GLOW_POINTS} when touched, ×2 … ×${GLOW_STREAK_MAX} in a row (pass one: ×1) · ◯ beacon +${BEACON_POINTS} · +${PAR_POINTS} a second under par`;
/** How long the first-time hint stays once a glow is in view, and after the first glow caught, s of game time. */
const GLOW_HINT_LIFE = 8,
  GLOW_HINT_AFTER = 3;
/**
 * The first-time hint: the game time a glow was first in view and the first was caught (NaN: not
 * yet), and whether it has been and gone (it shows once a page, runs again included).
 */
const glowHint = { shown: Number.NaN, caught: Number.NaN, gone: false };
/** A glow the hull's centre has passed by this far along x without catching it is missed (the streak ends), m. */
const GLOW_MISS = 10;
/** The depth gauge's full scale: the deepest seabed of the course and 10 m, rounded up to 10 m. */
let courseDepth = 160;
/**
 * An effect drawn for a while after a moment of the game (a blast, a hit, a banner): where (m) and
 * when (game time, s), and the game time of the first frame that drew it.
 */
interface Shown {
  x: number;
  y: number;
  time: number;
  shownT?: number;
}
/**
 * How long effect `e` has been on the screen at game time `t`, s: the game time since the first frame
 * that drew it (0 on that frame). A loaded machine draws a frame a second with a second of steps in
 * each: counted from the step that made it, a hit's 0.6 s flash was over before any frame showed it
 * and its label showed on one frame at most; counted from its first frame, the flash is seen whole on
 * that frame and the label on the next ones.
 */
function shownAge(e: Shown, t: number): number {
  if (e.shownT === undefined) e.shownT = t;
  return Math.max(0, t - e.shownT);
}
/** Mine blasts, for drawing: where (m) and when (game time, s). */
const blasts: Shown[] = [];
/** How long a blast's flash and bubbles last, s of game time. */
const BLAST_LIFE = 1.6;

/** Game time the pointer last left an uncollected beacon for another, s (its label pulses for AIM_PULSE s). */
let aimSwitchedAt = Number.NEGATIVE_INFINITY;
/**
 * The pointer label's brake hint when the boat comes in on its target (./beacons.ts letGoHint): at
 * which of the label's own "N m ahead" figures to let go of Ahead so that the glide (./helm.ts
 * coastDistance, from the speed and throttle now) stops the hull abeam the beacon (./beacons.ts LET_GO_SHORT), "let go now" there,
 * or "Astern now to stop" once a glide would carry the boat past it.
 */
/** The hint shows while the target is at most this far ahead along the heading, m, ... */
const BRAKE_HINT_RANGE = 40;
/** ... and the boat goes ahead faster than this, m/s, on a course within ./beacons.ts BRAKE_HINT_COURSE of the target. */
const BRAKE_HINT_SPEED = 2.5;
/** Times the hint comes on in a page, at most (one per beacon of a default course: a newcomer's lesson, not a nag). */
const BRAKE_HINT_MAX = 6;
/** Times the brake hint came on, and whether it shows now. */
const brakeHint = { shown: 0, on: false };
/** How long the pointer's label pulses after it switches beacon, s of game time. */
const AIM_PULSE = 1.2;
/**
 * What the pointer shows: the beacon it leads to (index, -1: none left), its distance (m), its
 * offset from the hull (dx, dy, m, y up), the arrow's screen angle (rad, y down; NaN while the
 * beacon is on screen and no arrow is drawn), whether the beacon is on screen, and where the label is drawn.
 */
const aim = {
  index: -1,
  distance: 0,
  dx: 0,
  dy: 0,
  angle: Number.NaN,
  onScreen: false,
  /** The label's box and the hull's (x, y, width, height, px), to check the label stays off the hull. */
  label: [0, 0, 0, 0],
  hull: [0, 0, 0, 0],
  /** Whether the label was moved off the headlight's cone this frame. */
  beam: false,
  /** Whether the label warns that the target is being left behind (./beacons.ts missWarning). */
  missWarn: false,
  /** The arrow's badge while drawn: its box (x, y, width, height, px; zeros while none) and the depth gauge's left edge (px). */
  badge: [0, 0, 0, 0],
  gaugeLeft: 0,
  /** The target's frame (its corner brackets, drawn while it is on screen) as last drawn: x, y, width, height, px (zeros while none). */
  frame: [0, 0, 0, 0],
  /** Whether a ridge to climb lies across the straight way to the target (./beacons.ts ridgeInWay: the label's ridge warning and the crest mark show). */
  ridge: false,
  /** The ridge's crest as last marked: its place (x, y, m), NaN while none is marked. */
  crest: [Number.NaN, Number.NaN],
};

/**
 * Beacons collected or passed, for the effect drawn at each (drawing only): world position (m), the
 * game time it was taken or passed (s), the banner's text ("Beacon 2 of 6", "B passed") and whether
 * it was passed (a banner only: no rings at a beacon left behind).
 */
const pickups: (Shown & { text: string; passed?: boolean })[] = [];
/** How long a pickup's rings and banner last, s of game time. */
const PICKUP_LIFE = 2;
/**
 * Room the framing camera keeps clear between the tip of the hull's headlight (its bow plus
 * HEADLIGHT.reach, ./boat-drawing.ts) and the view's right edge, px: the depth gauge and its tags
 * ("you 30 m", "beacon A 27 m", up to about 105 px in from the edge). With a target behind (backing
 * to it) the boat sits right of centre, and the beam ran off the screen under the "you" tag; the
 * view zooms out instead (`behindFit`) so the beam and the target behind are both in view.
 */
const HULL_GAUGE_ROOM = 120;
/**
 * The framing camera zooms out no further than this, px/m (beyond, the edge arrow leads on): 5 on
 * a wide screen (the 12 m hull 60 px long; at 2 px/m it would shrink to about 35 px at speed), 4 on
 * a small one, where the hull would otherwise shrink under 48 px and the mines to specks.
 */
const FRAME_MIN_ZOOM = pageLayout().compact() ? 3.5 : 5;
/** The camera's zoom now, px/m (eased toward the framing zoom; NaN: set at the next frame). */
let zoom = Number.NaN;
/**
 * The view leads the hull by its velocity along x times this, s (the look-ahead): 24 m at the top
 * speed of 8 m/s (./helm.ts HELM.topSpeed), room to see what lies ahead on the boat's course.
 */
const LEAD_TIME = 3;
/**
 * The view leads the hull by its vertical velocity times this, s: a short look-ahead, so that on a
 * Dive the hull is seen to move down the screen at once (with a look-ahead as long as along x, the
 * view would run ahead of it: the hull would rise up the screen while it dived and sink down it for
 * seconds after it had stopped, which reads as a late answer and an overshoot).
 */
const LEAD_TIME_Y = 0.4;
/** The look-ahead eases toward its target with this time constant, s of game time. */
const LEAD_EASE = 0.8;
/**
 * The same at rest, m: a 390 px phone 60 m (6.5 px/m, the hull 78 px long) once the target is near
 * enough to be framed that close; between rest and `PORTRAIT_SPEED` it eases from this to
 * `PORTRAIT_MIN_WIDTH`. (105 m across at any speed made the hull 42 to 45 px long: hard to see.)
 */
const PORTRAIT_REST_WIDTH = 60;
/**
 * The speed ahead, m/s, from which a portrait view counts as fully under way for its framing (above).
 * Backing does not count: a pilot backs onto a target behind, which the view at rest's zoom keeps framed.
 */
const PORTRAIT_SPEED = 4;
/**
 * The look-ahead along x on a portrait view, s (`LEAD_TIME` elsewhere): longer, so that on a narrow
 * phone the view is already at its full lead (the boat near the trailing edge, about 60 m of sea
 * ahead of the bow) from under 6 m/s, and a mine ahead is in view sooner.
 */
const PORTRAIT_LEAD_TIME = 4;
/**
 * The camera as last drawn: centre (x, y, m), zoom (px/m), the eased look-ahead (leadX, leadY, m,
 * before its limit), the game time it was eased to (s), the shake now (px) and the view's size (px).
 */
const camera = { x: 0, y: 0, zoom: 0, leadX: 0, leadY: 0, time: 0, shake: 0, width: 0, height: 0 };
/**
 * Hits on the hull, for drawing: what hit it ('mine' or 'seabed'), where (m: the mine's centre, or
 * the point of the hull that struck the bed) and when (game time, s).
 */
const hitMarks: (Shown & { kind: 'mine' | 'seabed' })[] = [];
/** How long a hit's label, sand cloud and red flash last, s of game time. */
const HIT_LIFE = 2.4;
/** How long a hit shakes the view, s of game time. */
const HIT_SHAKE_LIFE = 0.6;
/** The shake's amplitude at the moment of a hit, px. */
const SHAKE_PX = 12;

/** The course being run: the level's seed, beacon count and mines' layout (./levels.ts levelCourse). */
let course = levelCourse(params.level, params.seed, params.beacons);
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(submarine.worldOptions());
  // The level's course (./levels.ts): its seed, beacon count and mines.
  course = levelCourse(params.level, params.seed, params.beacons);
  handles = submarine.build(world, { seed: course.seed, count: course.beacons });
  // The game's course: short legs, each open from the beacon before (./beacons.ts layCourse).
  layCourse(handles.beacons, handles.seabed, course.seed);
  Object.assign(state, createHelmState(), {
    collected: 0,
    hits: 0,
    spared: 0,
    touching: false,
    diveStopped: false,
    over: '',
    time: 0,
    startedAt: Number.NaN,
    par: parTime(handles.beacons),
    lastHit: '',
    minesHit: 0,
    glowsCaught: 0,
    streak: 0,
    score: 0,
  });
  taken = new Array(course.beacons).fill(false);
  missed = new Array(course.beacons).fill(false);
  missWarned = -1;
  mines = layMines(handles.beacons, handles.seabed, course.seed, course.mines);
  mineLive = mines.map(() => true);
  wayMine = -1;
  ahead = null;
  bedWarn = null;
  glows = layTrail(handles.beacons, handles.seabed, mines);
  glowState = new Uint8Array(glows.length);
  glowPops.length = 0;
  courseDepth = 10 * Math.ceil((10 - Math.min(...handles.seabed.y)) / 10);
  blasts.length = 0;
  aim.index = -1;
  aimSwitchedAt = Number.NEGATIVE_INFINITY;
  heaveKeySince = Number.NaN;
  zoom = Number.NaN;
  Object.assign(camera, { leadX: 0, leadY: 0, time: 0, shake: 0 });
  hitMarks.length = 0;
  heaveTiming.reset();
  driveTiming.reset();
  Object.assign(levelHold, createLevelStop());
  scrapeAt = Number.NaN;
  pickups.length = 0;
  trim = 0;
  nosePresses.length = 0;
  stickDepth = Number.NaN;
  return world;
}

/** The keys held now (`KeyboardEvent.key`, lower case), each with the order it was pressed in (a later press, a larger number). */
const held = new Map<string, number>();
/** Key presses so far (the order `held` keeps). */
let pressCount = 0;
/**
 * Which of two opposed sets of keys is asked for: -1 (a key of `minus`), 1 (a key of `plus`) or 0
 * (none held). Both held, the one pressed last: a pilot pressing Astern before letting go of Ahead
 * (or a key whose let-go the page never saw) is answered, not left with the two cancelling out.
 */
function keyAxis(minus: readonly string[], plus: readonly string[]): -1 | 0 | 1 {
  let m = 0,
    p = 0;
  for (const k of minus) m = Math.max(m, held.get(k) ?? 0);
  for (const k of plus) p = Math.max(p, held.get(k) ?? 0);
  return m === p ? 0 : m > p ? -1 : 1;
}
/** The on-screen stick (phones): x right (ahead), y up (rise), each in [-1, 1], and whether a finger is on it. */
const stickInput = { x: 0, y: 0, held: false };
/** Whether the game is paused (a let-go then takes no game time); false until the game has started. */
let pausedNow = (): boolean => false;
/** Dive or Rise pressed and let go, timed by the events' timestamps (./release.ts): a let-go holds the order of its moment. */
const heaveTiming = createHeaveTiming();
/** The stop at the target's depth on a held Dive or Rise (./level-stop.ts). */
const levelHold = createLevelStop();
/** Ahead or Astern, timed by the events' timestamps (./release.ts): a press acts for as long as it was held, even inside a stalled frame. */
const driveTiming = createPressTiming();
/** The share of Dive / Rise the press asked for on its last step held (a let-go press runs on at it). */
let lastHeave = 1;
/** The share of the throttle Ahead / Astern asked for on its last step held (a let-go press runs on at it). */
let lastDrive = 1;
/** Dive or Rise as the keys ask for it now: -1 dive, 1 rise, 0 neither (the stick moves its own order: stickHeave). */
function heaveAsked(): -1 | 0 | 1 {
  return keyAxis(['s', 'arrowdown'], ['w', 'arrowup']);
}
/**
 * The stick pushed down (-1) or up (1) to move its depth order (./stick.ts stickOrder), 0 neither; 0
 * while a Dive or Rise key is held, and 0 for a push near the horizontal (./stick.ts stickHeaveDirection).
 */
function stickHeave(): -1 | 0 | 1 {
  return heaveAsked() !== 0 ? 0 : stickHeaveDirection(stickInput.y, stickInput.x);
}
/** The depth the stick orders, as the hull's height, m (./stick.ts stickOrder; NaN while none): the helm takes the boat there and levels on it. */
let stickDepth = Number.NaN;
/** Ahead or Astern as the keys and the stick ask for it now: 1 ahead, -1 astern, 0 neither; a key before the stick. */
function driveAsked(): -1 | 0 | 1 {
  const key = keyAxis(['a', 'arrowleft'], ['d', 'arrowright']);
  return key !== 0 ? key : stickDirection(stickInput.x, stickInput.y);
}
/** Tells the timed controls (./release.ts) what the keys and the stick ask for after an input event at `stamp` (ms). */
function timeControls(stamp: number): void {
  heaveTiming.event(heaveAsked(), stamp, pausedNow());
  driveTiming.event(driveAsked(), stamp, pausedNow());
}
/** Nose presses (Q / E, the Nose buttons) not yet taken by a step: each +1 (up) or -1 (down) steps the trim (./helm.ts noseTrim). */
const nosePresses: (-1 | 1)[] = [];
/** How long a Nose key has been held, s of game time (0 while none is). */
let noseHeldFor = 0;
/** A Nose key held longer than this, s, turns the trim on (./helm.ts NOSE_RATE); a shorter press is a tap: one step. */
const NOSE_HOLD_DELAY = 0.3;
/** The nose trim now, rad (positive: nose up; ./helm.ts noseTrim): the pitch the helm holds, shown on the status line. */
let trim = 0;
addEventListener('keydown', (e) => {
  const k = e.key.toLowerCase();
  if (!held.has(k) && (k === 'q' || k === 'e') && !pausedNow()) nosePresses.push(k === 'e' ? 1 : -1);
  if (!held.has(k)) held.set(k, ++pressCount);
  timeControls(e.timeStamp);
});
addEventListener('keyup', (e) => {
  held.delete(e.key.toLowerCase());
  timeControls(e.timeStamp);
});
addEventListener('blur', (e) => {
  held.clear();
  timeControls(e.timeStamp);
});
/** Game time a Dive or Rise key was first held (s), NaN while none is. */
let heaveKeySince = Number.NaN;

/**
 * The way the boat is going along x for the beacons' skip rules (./beacons.ts passedBeacon,
 * chooseBeacon, courseSpeed), m/s: its speed, but none ahead while Astern is held or the screw runs
 * astern, so a player who turns back on the "skipped in N m" warning keeps the beacon while the
 * Astern brake still slows the boat; and none astern otherwise, so a current carrying the boat back
 * does not turn the target round to a beacon skipped behind it.
 */
function goingX(): number {
  const vx = shell.world.components.Velocity.x[handles.hull]!;
  return courseSpeed(vx, asternHeld || state.throttle < 0);
}
/** Whether the last step had Astern held (and not Ahead): the boat is being turned back (goingX). */
let asternHeld = false;

/** The boat's horizontal speed now, m/s (positive ahead): a held Dive or Rise key asks for more under way (./helm.ts keyHeaveShare). */
function speedAhead(): number {
  return shell.world.components.Velocity.x[handles.hull]!;
}

/**
 * The controls held now, at game time `now` (s): keys, the on-screen buttons, which send the same
 * keys, and the stick; the screw as `drive` says (-1 astern, 1 ahead: driveTiming's step).
 */
function heldInput(now: number, drive: -1 | 0 | 1): HelmInput {
  const heaveKey = held.has('s') || held.has('w') || held.has('arrowdown') || held.has('arrowup');
  if (!heaveKey) heaveKeySince = Number.NaN;
  else if (Number.isNaN(heaveKeySince)) heaveKeySince = now;
  const heave = heaveAsked();
  return {
    dive: heave < 0,
    rise: heave > 0,
    noseDown: false,
    noseUp: false,
    ahead: drive > 0,
    astern: drive < 0,
    // The stick grades the dive or climb up to what a key asks for (./helm.ts keyHeaveShare) and no
    // further, so a thumb at the rim and a held key take the boat down alike.
    // Let go, the boat goes on to the stick's order at what a key asks for.
    heave: heaveKey
      ? keyHeaveShare(heaveKeySince, now, speedAhead())
      : Math.min(stickHeave() !== 0 ? stickShare(stickInput.y, false) : 1, keyHeaveShare(now, now, speedAhead())),
    drive: stickShare(stickInput.x, held.has('a') || held.has('d') || held.has('arrowleft') || held.has('arrowright')),
    // The stick pushed up or down only keeps the screw as it is (pushing it straight up to rise does
    // not stop the screw); a thumb lifted or resting at the centre lets the screw wind down as a key
    // let go does (a thumb eased back from a push ahead is a let-go); pushed sideways, it drives the screw.
    keepThrottle:
      stickInput.held && stickDirection(stickInput.x, stickInput.y) === 0 && stickHeaveDirection(stickInput.y, stickInput.x) !== 0,
  };
}

/**
 * Whether any of a grid of points of the screen box `box` (left, top, width, height, px; at most 8
 * px apart) lies in the
 * headlight's cone (./boat-drawing.ts inHeadlight) of the hull at `hull` (x, y, m, and its angle,
 * rad), drawn by `sx`, `sy` (world m to screen px) at `k` px/m.
 */
function boxInBeam(
  box: readonly number[],
  hull: readonly number[],
  sx: (x: number) => number,
  sy: (y: number) => number,
  k: number,
): boolean {
  const [left = 0, top = 0, width = 0, height = 0] = box,
    [hx = 0, hy = 0, angle = 0] = hull;
  const hc = Math.cos(angle),
    hs = Math.sin(angle);
  // At most 8 px apart (in eighths of the width, halves of the height at least): the cone's edge
  // crosses a long label between points further apart, and its tip fits between them.
  const cols = 8 * Math.max(1, Math.ceil(width / 64)),
    rows = 2 * Math.max(1, Math.ceil(height / 16));
  for (let i = 0; i <= cols; i++)
    for (let j = 0; j <= rows; j++) {
      const wx = hx + (left + (width * i) / cols - sx(hx)) / k,
        wy = hy - (top + (height * j) / rows - sy(hy)) / k;
      if (inHeadlight((wx - hx) * hc + (wy - hy) * hs, -(wx - hx) * hs + (wy - hy) * hc, SUBMARINE.length)) return true;
    }
  return false;
}
/** Where the hull last touched the seabed (m), filled by touchSeabed. */
const seabedContact = { x: 0, y: 0 };
/** Game time the newest scrape on the seabed began (a contact that costs no hit), s; NaN before any. */
let scrapeAt = Number.NaN;
/** A scrape's shake of the view: its amplitude, px, and how long it lasts, s of game time. */
const SCRAPE_SHAKE_PX = 4,
  SCRAPE_SHAKE_LIFE = 0.35;
/** How long a phone buzzes at a scrape, a seabed hit and a mine, ms. */
const SCRAPE_BUZZ_MS = 25,
  HIT_BUZZ_MS = 140,
  MINE_BUZZ_MS = 260;
/**
 * Buzzes a phone for `ms` ms (navigator.vibrate), where it can and once the page has been touched
 * (browsers refuse it before); nothing elsewhere.
 */
function buzz(ms: number): void {
  const nav = navigator as Navigator & { userActivation?: { hasBeenActive: boolean } };
  if (typeof nav.vibrate === 'function' && nav.maxTouchPoints > 0 && nav.userActivation?.hasBeenActive) nav.vibrate(ms);
}
/** The vertical command last step (-1 dive, 1 rise, 0 none): a hiss when it starts. */
let lastVertical = 0;
/** Game time of the last sonar ping, s. */
let lastPing = 0;

function stepWorld(world: PhysicsWorld): void {
  // The seabed stops a dive until Dive is let go (./seabed.ts). After the end (won or sunk) the
  // controls are let go: the boat glides to a stop on its order, whatever keys are still held.
  // Dive or Rise timed by its events (./release.ts): a press let go before the steps caught up runs
  // on to its own length; one the steps ran past holds the order of the moment it was let go.
  const timed = heaveTiming.step(world.time);
  // Ahead or Astern likewise (./release.ts createPressTiming): a press acts for as long as it was
  // held, even one pressed and let go while the browser drew no frame; let go, at the share it asked.
  const timedDrive = driveTiming.step(world.time);
  const drive = driveAsked() || timedDrive;
  const asked = heldInput(world.time, drive);
  if (timed.dir !== 0 && !asked.dive && !asked.rise) Object.assign(asked, { dive: timed.dir < 0, rise: timed.dir > 0, heave: lastHeave });
  else if (asked.dive !== asked.rise) lastHeave = asked.heave ?? 1;
  if (drive !== 0 && driveAsked() === 0) asked.drive = lastDrive;
  else if (drive !== 0) lastDrive = asked.drive ?? 1;
  // The nose trim: each press steps it, a key held on turns it on; Dive or Rise (or the end) clears it.
  // A Nose key held on past NOSE_HOLD_DELAY turns the trim on; a tap is its step alone.
  const noseHeld = keyAxis(['q'], ['e']);
  noseHeldFor = noseHeld === 0 ? 0 : noseHeldFor + world.dt;
  trim = noseTrim(trim, nosePresses.shift() ?? 0, noseHeldFor > NOSE_HOLD_DELAY ? noseHeld : 0, world.dt);
  const byStick = state.over ? 0 : stickHeave();
  if (asked.dive || asked.rise || timed.dir !== 0 || byStick !== 0 || state.over) trim = 0;
  asked.nose = trim;
  // The stick's depth order (./stick.ts stickOrder): pushed, it moves (never into the seabed nor
  // above the surface); let go, the helm takes the boat to it. A key, the nose or the end clear it.
  const c0 = world.components,
    hull = handles.hull;
  if (asked.dive || asked.rise || timed.dir !== 0 || trim !== 0 || state.over) stickDepth = Number.NaN;
  else if (byStick !== 0) {
    const surface = c0.FluidRegion.surface[handles.sea]!;
    stickDepth = stickOrder(
      stickDepth,
      byStick,
      stickShare(stickInput.y, false),
      world.dt,
      c0.Position.y[hull]!,
      state.holdY,
      holdFloor(handles.seabed, c0.Position.x[hull]!, 0),
      surface - SUBMARINE.height / 2 + 0.5,
    );
  }
  let input = state.over ? NO_INPUT : seabedInput(state, asked);
  asternHeld = input.astern && !input.ahead;
  if (!Number.isNaN(timed.letGoAt) && (state.mode === 'diving' || state.mode === 'rising'))
    state.holdY = releasedOrder(state.holdY, heaveTiming.orderAt(timed.letGoAt), state.mode);
  // The target's depth stops a held Dive or Rise, or the stick's order (./level-stop.ts): the boat
  // holds level with the beacon a moment, so a player who lets go on seeing it there stops on it.
  if (
    levelStop(levelHold, {
      dir: input.dive === input.rise ? byStick : input.dive ? -1 : 1,
      now: world.time,
      beacon: aim.index,
      beaconY: aim.index >= 0 ? handles.beacons[2 * aim.index + 1]! : Number.NaN,
      order: input.dive === input.rise && byStick !== 0 ? stickDepth : state.holdY,
      y: c0.Position.y[hull]!,
      vy: c0.Velocity.y[hull]!,
      warned: ahead !== null || bedWarn !== null,
    })
  ) {
    state.holdY = handles.beacons[2 * aim.index + 1]!;
    if (Number.isFinite(stickDepth)) stickDepth = state.holdY;
    input = { ...input, dive: false, rise: false };
  }
  if (Number.isFinite(stickDepth) && !state.over) input = { ...input, orderY: stickDepth };
  const vertical = input.dive === input.rise ? 0 : input.dive ? -1 : 1;
  if (vertical !== 0 && vertical !== lastVertical) sound.launch(0.25);
  lastVertical = vertical;
  // The level's current at the hull's depth (./current.ts): the helm steers through the water, and
  // the hull's drag acts on its velocity through it.
  const water = currentAt(params.level, world.components.Position.y[handles.hull]!);
  steer(world, handles, input, state, water);
  driftInCurrent(world, handles, water);
  if (state.mode === 'diving' || state.mode === 'rising') heaveTiming.note(world.time, state.holdY);
  // The stick's order reached (the boat level on it) or the boat afloat: the helm holds on alone.
  const reached = Math.abs(c0.Position.y[hull]! - state.holdY) < 0.3 && Math.abs(c0.Velocity.y[hull]!) < 0.3;
  if (byStick === 0 && (state.mode === 'surfaced' || reached)) stickDepth = Number.NaN;
  // Waves: the sea's surface bobs (the hull rides it).
  const sea = world.components.FluidRegion;
  sea.surface[handles.sea] = params.waveHeight * 0.5 * Math.sin(0.9 * world.time);
  step(world);
  heaveTiming.clock(world.time, performance.now());
  driveTiming.clock(world.time, performance.now());
  if (state.over) return;
  // The clock starts with the first control held, not when the page loads.
  const anyHeld = input.dive || input.rise || (input.nose ?? 0) !== 0 || input.ahead || input.astern;
  if (Number.isNaN(state.startedAt) && anyHeld) state.startedAt = world.time;
  const before = state.time;
  state.time = Number.isNaN(state.startedAt) ? 0 : world.time - state.startedAt;
  // The clock passing par is told once, on the banner in the hits' red-orange: the par bonus is gone.
  if (before <= state.par && state.time > state.par && state.par > 0)
    pickups.push({ x: 0, y: 0, time: world.time, text: `Par ${clock(state.par)} passed\nno par bonus now`, passed: true });
  // Sonar: a ping towards the next beacon, quicker the nearer it is (every 0.7 s near, 2.5 s far),
  // under water only.
  const next = aim.index;
  if (next >= 0 && world.components.Position.y[handles.hull]! < -SUBMARINE.height) {
    const d = Math.hypot(
      handles.beacons[2 * next]! - world.components.Position.x[handles.hull]!,
      handles.beacons[2 * next + 1]! - world.components.Position.y[handles.hull]!,
    );
    if (world.time - lastPing > Math.min(2.5, Math.max(0.7, d / 50))) {
      lastPing = world.time;
      sound.chime(d < 40 ? 1568 : 1175, 0.22);
    }
  }
  // The seabed (./seabed.ts): an impulse contact; an impact faster than SEABED.hitSpeed costs a hit.
  const c = world.components,
    e = handles.hull;
  const wasTouching = state.touching;
  const contact = touchSeabed(world, handles, state, world.time, input.dive, seabedContact);
  if (contact !== '') {
    // The helm brakes and holds the depth it stops at, above the contact.
    state.holdY = Number.NaN;
    stickDepth = Number.NaN;
    if (!wasTouching || contact === 'hit') {
      sound.impact(contact === 'hit' ? 20 : 6, 'metal');
      buzz(contact === 'hit' ? HIT_BUZZ_MS : SCRAPE_BUZZ_MS);
      if (contact === 'touch') scrapeAt = world.time;
    }
    if (contact === 'hit') {
      state.hits++;
      state.lastHit = 'seabed';
      hitMarks.push({ kind: 'seabed', x: seabedContact.x, y: seabedContact.y, time: world.time });
      // The hit's first frame (its label) is drawn even when a busy GPU makes the pacer skip frames.
      game.drawNext();
      if (state.hits >= 3) state.over = 'sunk';
    }
  }
  // Mines: touching one sets it off. It costs a hit and its blast throws the hull away from it
  // (an impulse at the hull's centre; the physics carries it from there).
  const angle = c.Angle.value[e]!;
  for (let i = 0; i < mines.length; i++) {
    const m = mines[i]!;
    if (!mineLive[i] || !touchesMine(c.Position.x[e]!, c.Position.y[e]!, angle, m.x, m.y)) continue;
    mineLive[i] = false;
    state.hits++;
    state.minesHit++;
    state.lastHit = 'mine';
    state.spared = world.time + 2;
    const dx = c.Position.x[e]! - m.x,
      dy = c.Position.y[e]! - m.y,
      r = Math.max(1e-6, Math.hypot(dx, dy));
    applyImpulse(world, e, [(MINE_BLAST_IMPULSE * dx) / r, (MINE_BLAST_IMPULSE * dy) / r]);
    blasts.push({ x: m.x, y: m.y, time: world.time });
    hitMarks.push({ kind: 'mine', x: m.x, y: m.y, time: world.time });
    game.drawNext();
    sound.explosion(0.9);
    buzz(MINE_BUZZ_MS);
    if (state.hits >= 3) state.over = 'sunk';
  }
  if (state.over) {
    ahead = null;
    bedWarn = null;
    return;
  }
  // The course ahead (./mines.ts mineAhead): toward the ordered depth, and while Dive or Rise is
  // held on at the speed it asks for too, at least MINE_LOOK_AHEAD m ahead at a slow speed. A new
  // warning sounds a low two-note call.
  const was = ahead?.index ?? -1;
  ahead = mineAhead(c.Position.x[e]!, c.Position.y[e]!, c.Velocity.x[e]!, c.Velocity.y[e]!, state.holdY, mines, mineLive, handles.seabed, {
    horizon: mineWarnHorizon(c.Velocity.x[e]!),
    prefer: ahead,
    heaving: state.mode === 'diving' || state.mode === 'rising',
    heave: Math.max(0.01, Math.min(1, input.heave ?? 1)),
  });
  if (ahead && ahead.index !== was) {
    sound.chime(330, 0.18);
    setTimeout(() => sound.chime(262, 0.25), 150);
  }
  // The seabed on the course (./seabed.ts bedAhead), told by the hull as a mine is while no mine is
  // (a ridge ahead in time to rise over it): a new warning sounds one low note.
  const hadBed = bedWarn !== null;
  bedWarn = ahead
    ? null
    : bedAhead(
        c.Position.x[e]!,
        c.Position.y[e]!,
        c.Velocity.x[e]!,
        c.Velocity.y[e]!,
        state.holdY,
        handles.seabed,
        HELM.climbSpeed,
        HELM.diveSpeed,
        {
          heaving: state.mode === 'diving' || state.mode === 'rising',
          heave: Math.max(0.01, Math.min(1, input.heave ?? 1)),
        },
      );
  if (bedWarn && !hadBed && !state.touching) sound.chime(294, 0.2);
  catchGlows(world);
  for (let i = 0; i < taken.length; i++) {
    if (taken[i]) continue;
    // Any part of the hull inside the beacon's ring (./beacons.ts catchesBeacon) collects it.
    if (catchesBeacon(c.Position.x[e]!, c.Position.y[e]!, angle, handles.beacons[2 * i]!, handles.beacons[2 * i + 1]!)) {
      taken[i] = true;
      missed[i] = false;
      state.collected++;
      state.score += BEACON_POINTS;
      const last = i === lastBeacon(handles.beacons);
      // The target moves on to the next beacon along the course (./beacons.ts chooseBeacon), which the banner names.
      const target = aim.index;
      aim.index = chooseBeacon(handles.beacons, taken, c.Position.x[e]!, c.Position.y[e]!, aim.index, i, goingX());
      if (aim.index >= 0 && aim.index !== target) aimSwitchedAt = world.time;
      pickups.push({
        x: handles.beacons[2 * i]!,
        y: handles.beacons[2 * i + 1]!,
        time: world.time,
        text: last
          ? state.collected === taken.length
            ? `All ${taken.length} beacons!`
            : `Finish! ${state.collected} of ${taken.length} beacons`
          : `Beacon ${state.collected} of ${taken.length}\nnext: ${beaconName(aim.index)}`,
      });
      // A rising two-note chime (a fifth apart); the last beacon a third note and a crackle.
      sound.chime(last ? 1047 : 784, 0.3);
      setTimeout(() => sound.chime(last ? 1568 : 1175, 0.45), 110);
      if (last) {
        setTimeout(() => sound.chime(2093, 0.6), 230);
        sound.crackle(14, 0.9);
      }
      // The last beacon along the course is the finish; beacons passed and left are missed (no
      // points, no par bonus, no best time: those are for a full course).
      if (last) {
        state.over = 'won';
        if (state.collected === taken.length) {
          state.score += PAR_POINTS * Math.max(0, Math.floor(state.par - state.time));
          recordWin(state.time);
        } else newBest = firstWin = false;
        return;
      }
    }
  }
  // The target left far behind (./beacons.ts passedBeacon) hands over to the next one ahead, and the
  // banner says so: a skipped beacon costs its points, not minutes of backing.
  const target = aim.index;
  if (target >= 0 && !taken[target] && passedBeacon(handles.beacons, target, c.Position.x[e]!, goingX())) {
    aim.index = chooseBeacon(handles.beacons, taken, c.Position.x[e]!, c.Position.y[e]!, target, -1, goingX());
    // A beacon skipped before (backed towards, then left again) is not announced twice.
    if (aim.index !== target && missed[target]) aimSwitchedAt = world.time;
    else if (aim.index !== target) {
      missed[target] = true;
      aimSwitchedAt = world.time;
      pickups.push({
        x: handles.beacons[2 * target]!,
        y: handles.beacons[2 * target + 1]!,
        time: world.time,
        text: `Beacon ${beaconName(target)} skipped: still counts\n${ASTERN_BACK}, or on to ${beaconName(aim.index)}`,
        passed: true,
      });
      // A falling two-note call: a loss, not a gain.
      sound.chime(523, 0.25);
      setTimeout(() => sound.chime(392, 0.3), 140);
      game.drawNext();
    }
  }
}

/**
 * The glows the hull touches (./trail.ts) are caught: each scores GLOW_POINTS times the streak (up
 * to GLOW_STREAK_MAX) and chimes a note higher the longer the streak; one the hull has passed by
 * GLOW_MISS m along x uncaught is missed and ends the streak (it can still be caught, turning back).
 */
function catchGlows(world: PhysicsWorld): void {
  const c = world.components,
    e = handles.hull;
  const x = c.Position.x[e]!,
    y = c.Position.y[e]!,
    a = c.Angle.value[e]!;
  for (let i = 0; i < glows.length; i++) {
    if (glowState[i] === 1) continue;
    const gl = glows[i]!;
    if (Math.abs(gl.x - x) > 20 || !touchesGlow(x, y, a, gl.x, gl.y)) {
      // Passed by: missed (it can still be caught, but the streak is over).
      if (glowState[i] === 0 && x - gl.x > GLOW_MISS) {
        glowState[i] = 2;
        state.streak = 0;
      }
      continue;
    }
    glowState[i] = 1;
    state.glowsCaught++;
    state.streak++;
    const points = GLOW_POINTS * Math.min(GLOW_STREAK_MAX, state.streak);
    state.score += points;
    glowPops.push({ x: gl.x, y: gl.y, time: world.time, points, times: Math.min(GLOW_STREAK_MAX, state.streak) });
    if (Number.isNaN(glowHint.caught)) glowHint.caught = world.time;
    // Up a major scale from C6 as the streak grows (C D E G A C).
    const scale = [1047, 1175, 1319, 1568, 1760, 2093];
    sound.chime(scale[Math.min(scale.length - 1, state.streak - 1)]!, 0.12);
  }
}

const sound = getSound();
const engine = sound.engine('screw');

const game = await startPixiGame({
  title: 'Submarine',
  createWorld,
  step: stepWorld,
  bodies: () => 1,
  // The game's time keeps pace with the clock down to 1 frame a second (60 steps of 1/60 s a
  // frame, frames up to 1 s; by default at most 4 and 0.1 s): a loaded machine draws 2 to 15 fps
  // with frames of a second or more now and then, and with less a held key or stick would run in
  // slow motion (the boat going less far than the gauge's speed says). A step of the one
  // hull costs well under a millisecond, so 60 of them never make the next frame later still.
  maxFrameTime: 1,
  maxStepsPerFrame: 60,
  controls: [
    { keys: '↓ ↑ / S W', action: 'dive / rise (let go: stop at the line)', touch: 'stick ↓ ↑' },
    { keys: '← → / A D', action: 'screw astern / ahead', touch: 'stick ← →' },
    { keys: 'Q / E', action: 'tilt 5° a tap', touch: 'Nose ↘ / ↗' },
    { keys: 'mouse', action: 'press and drag on the sea: steer like a stick', touch: '' },
    { keys: '◯', action: 'beacon: touch its yellow ring with any part of the boat to collect it', touch: '◯' },
    { keys: '●', action: GLOW_LEGEND, touch: '●' },
  ],
  app: { background: 0x0b2340, antialias: true },
  renderer: { pixelsPerMeter: params.pixelsPerMeter },
  onFrame: () => draw(),
});
const { shell, app } = game;
pausedNow = () => shell.paused;

// ---- Drawing: sky, sea, seabed, beacons, hull and gauges (the world renderer draws nothing here) --

const g = new Graphics();
app.stage.addChild(g);
/** The beacon pointer's label: distance and depth of the beacon it leads to, beside its arrow at the screen's edge (or over the beacon in view). */
const pointer = new Text({
  text: '',
  style: { fill: 0xffe066, fontSize: 15, fontWeight: '700', fontFamily: 'system-ui, sans-serif' },
});
pointer.anchor.set(0.5);
app.stage.addChild(pointer);
/** The banner at the top of the scene when a beacon is collected ("Beacon 2 of 6"), fading out. */
const banner = new Text({
  text: '',
  style: {
    fill: 0xffe066,
    fontSize: 26,
    align: 'center',
    fontWeight: '800',
    fontFamily: 'system-ui, sans-serif',
    stroke: { color: 0x06213a, width: 5 },
    dropShadow: { color: 0x000000, alpha: 0.5, blur: 6, distance: 0 },
  },
});
banner.anchor.set(0.5);
banner.visible = false;
app.stage.addChild(banner);
/** Whether the page is laid out for a phone (the readout's lines are shorter). */
const compact = pageLayout().compact();
// The gauges: a text block in the status row above the scene (on its dark backing, never cut off).
const gauge = document.createElement('div');
gauge.className = 'sub-gauges';
gauge.dataset.hud = 'gauges';
// On a phone 6 px at the sides (not 10), in 14 px type (10 to 12 px read small there), on two lines
// (the goal, then the readout): the longest figures of a run do not fit one line of 390 px at 14 px,
// and two lines always keep the scene's height put.
gauge.style.cssText = `font: ${compact ? 14 : 13}px/1.35 system-ui, sans-serif; color: #e8f4ff; padding: 4px ${compact ? 6 : 10}px;`;
const goal = document.createElement('div');
goal.dataset.hud = 'goal';
goal.style.cssText = 'font-weight: 700; color: #ffe066;';
/** The goal's words up to the clock ("L1 · ◯ 2/6 · 0:42"), and the course's par after it (" · par 2:20"). */
const goalText = document.createElement('span');
/**
 * The par after the clock, in lighter type (in the line's 14 px on a phone too): a target to beat,
 * not a limit the clock counts towards ("0:42/2:20" read as one).
 */
const goalPar = document.createElement('span');
goalPar.style.cssText = 'font-weight: 400;';
goal.append(goalText, goalPar);
const readout = document.createElement('div');
readout.dataset.hud = 'readout';
const readoutText = document.createElement('span');
/** The hull gauge: a bar a third each, lit red and pulsing at a hit, so the cost of a hit is seen. */
const hullGauge = document.createElement('span');
hullGauge.dataset.hud = 'hull';
hullGauge.style.cssText = `display: inline-block; padding: 0 ${compact ? 3 : 5}px; border-radius: 5px; font-weight: 700; white-space: nowrap; transform-origin: left center;`;
readout.append(readoutText, hullGauge);
const instruments = document.createElement('div');
instruments.dataset.hud = 'instruments';
// #c8d6e4 on the columns' dark backing: a contrast of about 12:1 (at least 4.5:1 for small text).
instruments.style.cssText = 'white-space: pre-line; color: #c8d6e4; margin: 6px 0;';
// The seabed's depth is for the pilot; the helm's workings (climb, pitch, screw, tanks, helm mode)
// go in the HUD's "physics details" fold (closed until opened, under the body and step counts), so
// the column reads as a game's.
const seabedLine = document.createElement('div');
const physicsText = document.createElement('div');
physicsText.dataset.hud = 'helm-details';
physicsText.style.whiteSpace = 'pre-line';
shell.hud.details.append(physicsText);
instruments.append(seabedLine);
// The status row is one short line (on a phone two), the goal then the numbers a player needs (three
// lines, the third small and grey, were too dense); on a desktop the instruments (seabed, climb, pitch, screw,
// tanks, helm) go in the info column, a line each, and on a phone they are left out.
goal.style.display = 'inline';
readout.style.display = compact ? 'block' : 'inline';
if (compact) instruments.style.display = 'none';
else pageLayout().info.append(instruments);
gauge.append(goal, readout);
if (!compact) goal.after(Object.assign(document.createElement('span'), { textContent: ' · ' }));
pageLayout().status.append(gauge);

/**
 * The end of a run over the scene: won or sunk, the time, the hull, the best, and a button to go again.
 * Opaque: the gauge's tags, the target's label and the boat drawn under it showed through a 0.88 one,
 * and still as ghosts through a 0.97 one, and mixed with its lines.
 */
const endCard = document.createElement('div');
endCard.dataset.sceneOverlay = '';
endCard.dataset.hud = 'end';
endCard.style.cssText =
  'position: absolute; z-index: 4; left: 50%; top: 26%; transform: translate(-50%, -50%); width: min(88%, 400px); box-sizing: border-box;' +
  'padding: 12px 16px; border-radius: 14px; background: rgb(4, 16, 30); color: #e8f4ff; font: 16px/1.45 system-ui, sans-serif;' +
  'text-align: center; pointer-events: none; display: none;';
pageLayout().stage.append(endCard);
/** The first-time hint over the top of the scene: what a glow, a beacon and par are worth. */
const glowNote = document.createElement('div');
glowNote.dataset.sceneOverlay = '';
glowNote.dataset.hud = 'glow-hint';
glowNote.textContent = GLOW_HINT;
glowNote.style.cssText =
  // Centred in the band left of the depth gauge and its tags ("you 100 m" reaches 82 px from the
  // right edge; on a phone the card's own width brings it there).
  `position: absolute; z-index: 4; left: 10px; right: ${compact ? 90 : 70}px; top: 8px; width: fit-content; margin: 0 auto;` +
  'box-sizing: border-box; padding: 5px 12px; border-radius: 10px; background: rgba(4, 16, 30, 0.82); color: #b8ffe9;' +
  `font: 600 ${compact ? 13 : 14}px/1.35 system-ui, sans-serif; text-align: center; pointer-events: none; display: none;`;
pageLayout().stage.append(glowNote);
/** The note over the bottom of the scene the first time the level's current pushes the boat (./current.ts currentNote). */
const currentNoteEl = document.createElement('div');
currentNoteEl.dataset.sceneOverlay = '';
currentNoteEl.dataset.hud = 'current-note';
currentNoteEl.style.cssText =
  `position: absolute; z-index: 4; left: 10px; right: ${compact ? 90 : 70}px; bottom: 10px; width: fit-content; margin: 0 auto;` +
  'box-sizing: border-box; padding: 5px 12px; border-radius: 10px; background: rgba(4, 16, 30, 0.82); color: #cfeeff;' +
  `font: 600 ${compact ? 13 : 14}px/1.35 system-ui, sans-serif; text-align: center; pointer-events: none; display: none;`;
pageLayout().stage.append(currentNoteEl);
/** Game time the current's note came up, s (NaN until the current first pushes the boat under way; once a page). */
const currentSeen = { shown: Number.NaN };
/**
 * Brings up the current's note at game time `t` (s) the first time the water at the hull, `u` m/s,
 * runs at CURRENT_NOTE_SPEED or more once the run has started, and keeps it up CURRENT_NOTE_LIFE s,
 * telling the water at the hull as it is now: the same figure as the status line's "current ▶1.5 m/s".
 */
function showCurrentNote(t: number, u: number): void {
  if (Number.isNaN(currentSeen.shown) && !state.over && Number.isFinite(state.startedAt) && Math.abs(u) >= CURRENT_NOTE_SPEED)
    currentSeen.shown = t;
  const display = !state.over && t - currentSeen.shown < CURRENT_NOTE_LIFE ? 'block' : 'none';
  if (display === 'block') {
    const text = currentNote(u);
    if (currentNoteEl.textContent !== text) currentNoteEl.textContent = text;
  }
  if (currentNoteEl.style.display !== display) currentNoteEl.style.display = display;
}
/**
 * Shows the first-time hint from the moment a glow is first in view (`inView`) at game time `t`, s,
 * for GLOW_HINT_LIFE s, and at least GLOW_HINT_AFTER s after the first glow caught when that comes
 * while it shows; once a page: gone, it never comes back (a first glow caught later, often after the
 * first beacon, brought it back over the top third of a phone's water).
 */
function showGlowHint(t: number, inView: boolean): void {
  if (inView && Number.isNaN(glowHint.shown)) glowHint.shown = t;
  const caughtWhileShown = Number.isFinite(glowHint.caught) && glowHint.caught < glowHint.shown + GLOW_HINT_LIFE;
  const on =
    !glowHint.gone &&
    !state.over &&
    Number.isFinite(glowHint.shown) &&
    (t - glowHint.shown < GLOW_HINT_LIFE || (caughtWhileShown && t - glowHint.caught < GLOW_HINT_AFTER));
  if (!on && Number.isFinite(glowHint.shown)) glowHint.gone = true;
  const display = on ? 'block' : 'none';
  if (glowNote.style.display !== display) glowNote.style.display = display;
}
/**
 * The end card's button: "Next level" after a won run below the last level (the R key or the reset
 * button plays the level again), else "Play again" / "Try again" (the same level). The run it
 * starts runs: a pause the player made before (or on the end card) is lifted, as the button says play.
 */
const showAgain = createActionButton('Play again ▶', () => {
  if (state.over === 'won' && params.level < LEVELS.length) {
    params.level++;
    panel.refresh();
    // The address keeps the level, so a reload plays it again.
    const url = new URL(location.href);
    url.searchParams.set('level', String(params.level));
    history.replaceState(history.state, '', url);
  }
  shell.reset();
  shell.paused = false;
});
/** Best time of each course (seed and beacon count) that was won, s, in localStorage (./levels.ts bestTimes). */
const bests = bestTimes();
/** The best time of this course, s, or null when none is kept. */
function bestTime(): number | null {
  return bests.get(bestKey()) ?? null;
}
/** The course's key in the best times: the seed and beacon count, and the level from level 2 on. */
function bestKey(): string {
  return params.level === 1 ? `${params.seed}/${params.beacons}` : `${params.seed}/${params.beacons}/L${params.level}`;
}
/** Whether the last win set a new best (shown on the end card); not on the first win, with nothing to beat. */
let newBest = false;
/** Whether the last win was the course's first (kept as its best, with nothing beaten; shown on the end card). */
let firstWin = false;
/** The best time the last win beat, s (NaN: none beaten). */
let beaten = Number.NaN;
/** Keeps `time` as the best of this course if it is one (the first win always is). */
function recordWin(time: number): void {
  const best = bestTime();
  newBest = best !== null && time < best;
  firstWin = best === null;
  beaten = newBest && best !== null ? best : Number.NaN;
  if (best !== null && !newBest) return;
  // A time past MAX_BEST_TIME would read back as none: not kept.
  if (time <= MAX_BEST_TIME) bests.set(bestKey(), time);
}
/** m:ss of `t` seconds. */
function clock(t: number): string {
  const s = Math.floor(t);
  return `${Math.floor(s / 60)}:${String(s % 60).padStart(2, '0')}`;
}
/** Shows or hides the end card for the state now. */
function showEnd(): void {
  if (!state.over) {
    endCard.style.display = 'none';
    showAgain(false);
    return;
  }
  const won = state.over === 'won',
    hull = 3 - state.hits;
  const best = bestTime();
  endCard.style.display = 'block';
  endCard.replaceChildren();
  const levelLine = document.createElement('div');
  levelLine.dataset.hud = 'level';
  levelLine.style.cssText = 'font-size: 13px; color: #b8c8d8; letter-spacing: 1px;';
  levelLine.textContent = `LEVEL ${params.level} OF ${LEVELS.length}`;
  endCard.append(levelLine);
  const title = document.createElement('div');
  title.style.cssText = `font: 800 24px system-ui, sans-serif; color: ${won ? '#ffe066' : '#ff8a7a'};`;
  const all = state.collected === taken.length;
  title.textContent = won
    ? taken.length === 1
      ? 'Beacon collected!'
      : all
        ? `All ${taken.length} beacons!`
        : `Course run: ${state.collected} of ${taken.length} beacons`
    : 'Hull breached!';
  const line = document.createElement('div');
  if (won) {
    // Three stars to earn: every beacon, inside par, the hull unhurt; each line says which were earned.
    const stars = runStars();
    const starRow = document.createElement('div');
    starRow.dataset.hud = 'stars';
    starRow.style.cssText = 'font-size: 30px; line-height: 1.1; letter-spacing: 4px; color: #ffe066;';
    starRow.textContent = `${'★'.repeat(stars)}${'☆'.repeat(3 - stars)}`;
    const inPar = all && state.time <= state.par;
    const missed = taken.flatMap((t, i) => (t ? [] : [beaconName(i)])).join(', ');
    line.style.cssText = 'font-size: 15px;';
    // Each item kept on one line (no-break spaces inside it), so a mark never wraps away from its words.
    line.textContent = [
      all ? `✓ ${taken.length === 1 ? 'the beacon' : `all ${taken.length} beacons`}` : `✗ ${missed} missed`,
      `${inPar ? '✓' : '✗'} ${clock(state.time)} (par ${clock(state.par)}${all ? '' : ', every beacon'})`,
      `${hull === 3 ? '✓' : '✗'} hull ${hull}/3`,
    ]
      .map((item) => item.replaceAll(' ', '\u00a0'))
      .join(' · ');
    endCard.append(title, starRow);
  } else {
    line.textContent = `${state.collected} of ${taken.length} beacons, then ${state.lastHit === 'mine' ? 'a mine' : 'the seabed'} broke the hull.`;
    endCard.append(title);
  }
  const bestLine = document.createElement('div');
  bestLine.style.cssText = 'color: #b8c8d8; font-size: 14px;';
  bestLine.textContent =
    won && newBest
      ? `A new best time for this sea! (was ${clock(beaten)})`
      : won && firstWin
        ? `${clock(state.time)}: the time to beat on this sea next run.`
        : best !== null
          ? `Best: ${clock(best)}`
          : 'Mines and the seabed each cost a third of the hull.';
  endCard.append(line, scoreLine(), bestLine);
  const next = won && params.level < LEVELS.length;
  showAgain(true, next ? `Next level ${params.level + 1} ▶` : won ? 'Play again ▶' : 'Try again ↺');
}
/** The end card's line of the score and the glows caught ("Score 1,240 · 42 of 58 glows"). */
function scoreLine(): HTMLElement {
  const el = document.createElement('div');
  el.dataset.hud = 'score';
  el.style.cssText = 'font-size: 17px; font-weight: 700; color: #b8ffe9;';
  el.textContent = `Score ${state.score.toLocaleString('en-US')} · ${state.glowsCaught} of ${glows.length} glows`;
  return el;
}
/**
 * Stars of a finished run, 0 to 3: one for every beacon collected, one for a time inside par with
 * every beacon (a course cut short by skipping beacons is not a par run), one for an unhurt hull.
 */
function runStars(): number {
  const all = state.collected === taken.length;
  return Number(all) + Number(all && state.time <= state.par) + Number(state.hits === 0);
}
let gaugeFrame = 0;
/** How long the hull gauge stays lit after a hit, s of game time. */
const GAUGE_FLASH = 1.4;
/** The hull gauge's flash now, in [0, 1] (0: not lit). */
let gaugeFlash = 0;
/** Writes the hull gauge: a bar for each third left, hollow for each lost, and n/3; red once two are lost. */
function showHull(): void {
  const left = Math.max(0, 3 - state.hits);
  // The bars alone (the status line is kept short; a bar is a third).
  hullGauge.textContent = `hull ${'▮'.repeat(left)}${'▯'.repeat(3 - left)}`;
  hullGauge.style.color = left <= 1 ? '#ff8a7a' : '';
}
/** The hit's signs as last drawn (tests): the label's pill box (x, y, width, height, px) and the view's red tint (alpha). */
const hitShown = { pill: [0, 0, 0, 0], tint: 0 };
/** The red pill under the hit's label (drawHitPill), drawn where the label ends up once the words are placed. */
const hitPill = new Graphics();
app.stage.addChild(hitPill);
/** The label at a hit: what hit the hull and its cost ("MINE HIT!", "−1 hull · 2/3 left"), white on hitPill. */
const hitLabel = new Text({
  text: '',
  style: {
    fill: 0xffffff,
    fontSize: compact ? 20 : 24,
    fontWeight: '800',
    fontFamily: 'system-ui, sans-serif',
    align: 'center',
    lineHeight: compact ? 24 : 29,
  },
});
hitLabel.anchor.set(0.5);
hitLabel.visible = false;
app.stage.addChild(hitLabel);
/** Draws the hit label's pill round the label where it is now (after `declutter`): red, white-edged, fading with it. */
function drawHitPill(): void {
  hitPill.clear();
  hitShown.pill = [0, 0, 0, 0];
  if (!hitLabel.visible || hitLabel.alpha <= 0) return;
  const [x, y, w, h] = boxOf(hitLabel);
  hitShown.pill = [x - 12, y - 5, w + 24, h + 10];
  hitPill
    .roundRect(x - 12, y - 5, w + 24, h + 10, 12)
    .fill({ color: 0xc8261c, alpha: 0.94 * hitLabel.alpha })
    .stroke({ color: 0xffffff, width: 2, alpha: 0.9 * hitLabel.alpha });
}
/** The warning by the hull of a mine on its course (drawMineWarning): which way to pass it, white on a red pill. */
const mineTag = new Text({
  text: '',
  style: { fill: 0xffffff, fontSize: 14, fontWeight: '800', fontFamily: 'system-ui, sans-serif' },
});
mineTag.anchor.set(0.5);
mineTag.visible = false;
app.stage.addChild(mineTag);
/**
 * Over the scene while paused (drawPause): the scene dimmed lightly and the word with how to resume
 * on a band at the top or bottom edge, away from the boat, so a pause is not mistaken for a hang and
 * a pilot pausing to think still sees the mines and beacons ahead.
 */
const pause = createPauseOverlay({ shadeAlpha: 0.15, fontSize: 22 });
/** The pause words' band (drawPause): a pill under the words, centred across the scene. */
const pauseBand = new Graphics();
pause.container.addChildAt(pauseBand, 1);
app.stage.addChild(pause.container);
/** Height of the pause band, px: the two lines of words and a margin. */
const PAUSE_BAND = 64;
/** Room on each side of the pause words in their band, px: the band is as wide as the words and this. */
const PAUSE_PAD = 18;
const touch = isTouchDevice();
/** Whether the pause overlay showed in the last frame drawn by drawPause. */
let pauseShown = false;
/** The pause band as last drawn: x, y, width, height, px (zeros while hidden). */
const pauseBandBox = [0, 0, 0, 0];
/**
 * Shows or hides the pause overlay over a `W` x `H` px scene, on top of everything drawn on the stage:
 * its words on a band as wide as they are (PAUSE_PAD each side), centred at the bottom edge, or at the top edge while the boat (at `boatY` px from the
 * top) would be under the bottom band, so the band stays put as the boat dives (it moved between
 * the edges as the boat crossed the middle of the scene). The band keeps clear of the cards over the
 * scene's edges (the first-time hint, the touch hint, the current's note) and, where there is room
 * clear of the hull, of the target's label.
 * The frame where it comes or goes is drawn whatever the frame pacer says: on a busy GPU the pacer
 * skips most frames, and a paused game draws nothing new that would make up for a skipped one.
 */
function drawPause(W: number, H: number, boatY: number): void {
  const on = shell.paused && !state.over;
  if (on !== pauseShown) {
    pauseShown = on;
    game.drawNext();
  }
  // Pools of labels are added to the stage as they are needed: kept under the overlay.
  if (on && app.stage.children[app.stage.children.length - 1] !== pause.container) app.stage.addChild(pause.container);
  pause.draw(on, W, H, touch);
  pauseBandBox.fill(0);
  if (on) {
    // Clear of the cards over the scene's edges (the first-time hint at the top, the touch hint and
    // the current's note at the bottom) while they show.
    const scene = app.canvas.getBoundingClientRect();
    let upper = 0,
      lower = H;
    for (const card of document.querySelectorAll<HTMLElement>(
      '[data-hud="glow-hint"], [data-hud="touch-hint"], [data-hud="current-note"]',
    )) {
      const r = card.getBoundingClientRect();
      if (r.height === 0) continue;
      if (r.top - scene.top < H / 2) upper = Math.max(upper, r.bottom - scene.top + 4);
      else lower = Math.min(lower, r.top - scene.top - 4);
    }
    // The bottom edge, or the top one while the boat is near the bottom, clear of the target's label (./pause-band.ts).
    const top = pauseBandTop(upper, lower, PAUSE_BAND, boatY, pointer.visible ? [aim.label[1]!, aim.label[3]!] : null);
    // A pill round the words, not a band across the scene: the band hid the whole bottom strip (the
    // seabed and the helm dial) from a pilot pausing to look ahead.
    const bw = Math.min(W, Math.ceil(pause.words.width) + 2 * PAUSE_PAD),
      bx = (W - bw) / 2;
    pauseBand.clear().roundRect(bx, top, bw, PAUSE_BAND, 12).fill({ color: 0x050a14, alpha: 0.6 });
    pause.words.position.set(W / 2, top + PAUSE_BAND / 2);
    pauseBandBox.splice(0, 4, bx, top, bw, PAUSE_BAND);
  }
}
/** The warning's words for each side to pass the mine on (placeMineTag adds how far ahead the mine is: "MINE 40 m"). */
const MINE_TAG_TEXT = { over: '⚠ MINE: rise over ▲', under: '⚠ MINE: dive under ▼' } as const;
/** The seabed warning's words (placeMineTag adds how far ahead a ridge is: "RIDGE 40 m"). */
const BED_TAG_TEXT = { ridge: '⚠ RIDGE: rise ▲', floor: '⚠ SEABED: rise ▲' } as const;
/**
 * The warning by the hull as last drawn (tests): what of ('mine', 'seabed', '' while none), its
 * words, the tag's box and the arrow's tip and tail (px).
 */
const mineWarning: { kind: '' | 'mine' | 'seabed'; text: string; box: number[]; tip: number[]; tail: number[] } = {
  kind: '',
  text: '',
  box: [0, 0, 0, 0],
  tip: [0, 0],
  tail: [0, 0],
};
/**
 * Places the tag of the warning of a mine on the boat's course (`ahead`) by the hull at screen
 * (`hx`, `hy`, px), `k` px a metre, in a view `W` x `H` px: on the side to pass, over the sail (rise
 * over it) or under the keel (dive under it), inside the view. Hidden while there is none. Placed
 * before the beacon pointer's label, which keeps clear of it.
 */
function placeMineTag(k: number, hx: number, hy: number, W: number, H: number): void {
  mineTag.visible = (ahead !== null || bedWarn !== null) && !state.over;
  mineWarning.text = '';
  mineWarning.box = [0, 0, 0, 0];
  mineWarning.kind = '';
  if ((!ahead && !bedWarn) || state.over) return;
  const hullX = shell.world.components.Position.x[handles.hull]!;
  let side: 'over' | 'under' = 'over';
  if (ahead) {
    // How far ahead the mine is, along x to its near side, so an early warning reads as early.
    const m = mines[ahead.index]!,
      away = Math.max(0, Math.abs(m.x - hullX) - SUBMARINE.length / 2 - MINE_RADIUS);
    mineTag.text = MINE_TAG_TEXT[ahead.side].replace('MINE', `MINE ${away.toFixed(0)} m`);
    side = ahead.side;
    mineWarning.kind = 'mine';
  } else if (bedWarn) {
    // A ridge: how far ahead (to where the bow meets it); the floor below: just the word.
    const away = Math.max(0, Math.abs(bedWarn.x - hullX));
    mineTag.text = bedWarn.ridge ? BED_TAG_TEXT.ridge.replace('RIDGE', `RIDGE ${away.toFixed(0)} m`) : BED_TAG_TEXT.floor;
    mineWarning.kind = 'seabed';
  }
  const w = mineTag.width + 16,
    h = mineTag.height + 6;
  const off = (SUBMARINE.height / 2) * k + (side === 'over' ? 1.6 * k + 6 : 6) + h / 2;
  mineTag.x = Math.max(w / 2 + 4, Math.min(W - GAUGE_WIDTH - w / 2 - 4, hx));
  mineTag.y = Math.max(h / 2 + 4, Math.min(H - h / 2 - 4, side === 'over' ? hy - off : hy + off));
  // Clear of the beacon arrow's badge at the view's edge (as last drawn): moved along x past it,
  // toward the view's middle (on a phone, with the boat near the left edge, the two overlapped).
  const [bx, by, bw, bh] = aim.badge as [number, number, number, number];
  if (bw > 0 && Math.abs(mineTag.x - (bx + bw / 2)) < (w + bw) / 2 + 4 && Math.abs(mineTag.y - (by + bh / 2)) < (h + bh) / 2 + 4)
    mineTag.x = bx + bw / 2 < W / 2 ? bx + bw + w / 2 + 4 : bx - w / 2 - 4;
  mineWarning.text = mineTag.text;
  mineWarning.box = [mineTag.x - w / 2, mineTag.y - h / 2, w, h];
  // A points label ("+30") over a glow just caught that would cross the tag moves on past it, away
  // from the hull, so the two are never drawn over each other.
  for (const label of popLabels) {
    if (!label.visible) continue;
    const lw = label.width / 2 + 3,
      lh = label.height / 2 + 3;
    if (Math.abs(label.x - mineTag.x) < w / 2 + lw && Math.abs(label.y - mineTag.y) < h / 2 + lh)
      label.y = side === 'over' ? Math.max(lh, mineTag.y - h / 2 - lh) : Math.min(H - lh, mineTag.y + h / 2 + lh);
  }
}
/**
 * Draws the warning of a mine on the boat's course (`ahead`) by the hull at (`hxw`, `hyw`, m), at
 * game time `t`, `k` px a metre, through `sx`, `sy`: a red arrow from just off the hull to the mine
 * (over its pulsing ring, drawMines), and the tag's red pill (placeMineTag), pulsing faster in the
 * last 2 s before contact.
 */
function drawMineWarning(t: number, k: number, sx: (x: number) => number, sy: (y: number) => number, hxw: number, hyw: number): void {
  if ((!ahead && !bedWarn) || state.over) return;
  // Toward the mine, or toward the seabed where the course meets it (orange: a ridge, not a mine).
  const [tx, ty, time] = ahead ? [mines[ahead.index]!.x, mines[ahead.index]!.y, ahead.time] : [bedWarn!.x, bedWarn!.bed, bedWarn!.time];
  const [red, pill] = ahead ? [0xff3b30, 0xc62a20] : [0xff8a3d, 0xb8561a];
  const hx = sx(hxw),
    hy = sy(hyw),
    dx = sx(tx) - hx,
    dy = sy(ty) - hy,
    d = Math.max(1e-6, Math.hypot(dx, dy));
  const ux = dx / d,
    uy = dy / d;
  const pulse = 0.5 + 0.5 * Math.sin(2 * Math.PI * (time < 2 ? 4 : 2) * t);
  // The arrow: from just off the hull toward the mine (short of its ring) or the bed.
  const r0 = Math.max((SUBMARINE.length / 2) * k * Math.abs(ux) + (SUBMARINE.height / 2) * k * Math.abs(uy) + 8, 28),
    r1 = Math.max(r0 + 18, Math.min(d - (ahead ? MINE_RADIUS + 2 : 1) * k, r0 + Math.max(40, 4 * k)));
  const tail: [number, number] = [hx + ux * r0, hy + uy * r0],
    tip: [number, number] = [hx + ux * r1, hy + uy * r1];
  const head = 11,
    wide = 8;
  const base: [number, number] = [tip[0] - ux * head, tip[1] - uy * head];
  for (const [width, color] of [
    [7, 0x1a0606],
    [3.5, red],
  ] as const)
    g.moveTo(...tail)
      .lineTo(...base)
      .stroke({ color, width, alpha: 0.75 + 0.25 * pulse, cap: 'round' });
  g.poly([...tip, base[0] - uy * wide, base[1] + ux * wide, base[0] + uy * wide, base[1] - ux * wide])
    .fill({ color: red, alpha: 0.8 + 0.2 * pulse })
    .stroke({ color: 0x1a0606, width: 2 });
  const [bx, by, bw, bh] = mineWarning.box as [number, number, number, number];
  g.roundRect(bx, by, bw, bh, bh / 2)
    .fill({ color: pill, alpha: 0.8 + 0.2 * pulse })
    .stroke({ color: 0xffd0c8, width: 1.5, alpha: 0.9 });
  mineWarning.tip = tip;
  mineWarning.tail = tail;
}
/** The label's text for each cause of a hit. */
const HIT_TEXT = { mine: 'MINE HIT!', seabed: 'SEABED HIT!' } as const;
/** The hit label's words: the cause, then the cost and the hull left ("MINE HIT!\n−1 hull · 2/3 left"). */
function hitText(kind: keyof typeof HIT_TEXT, hits: number): string {
  const left = Math.max(0, 3 - hits);
  return `${HIT_TEXT[kind]}\n−1 hull · ${left > 0 ? `${left}/3 left` : 'breached'}`;
}
/**
 * Draws the newest hit's signs at game time `t` (s), `k` px a metre, through `sx`, `sy` (world m to
 * screen px) in a `W` x `H` px view: a red ring spreading from the place, a cloud of sand and a fan
 * of sparks there for a seabed scrape (a mine's blast is drawn by drawMines), a red frame round the
 * view (the whole view tinted red for 0.4 s, its frame for 0.9 s), and the label naming the cause and
 * the hull left over the place, rising and fading over HIT_LIFE s (its red pill: drawHitPill).
 */
function drawHits(t: number, k: number, sx: (x: number) => number, sy: (y: number) => number, W: number, H: number, hullTop: number): void {
  for (let i = hitMarks.length - 1; i >= 0; i--) if (t < hitMarks[i]!.time) hitMarks.splice(i, 1);
  const m = hitMarks[hitMarks.length - 1];
  const age = m ? shownAge(m, t) : Number.POSITIVE_INFINITY,
    u = age / HIT_LIFE;
  // Once the run is over the end card's title says what the last hit did ("Hull breached!"): the
  // label is not drawn over or beside it (the flash and the rings still are).
  hitLabel.visible = m !== undefined && u < 1 && !state.over;
  hitShown.tint = 0;
  if (!m || u >= 1) return;
  const x = sx(m.x),
    y = sy(m.y),
    fade = 1 - u;
  g.circle(x, y, (1.5 + 10 * Math.sqrt(u)) * k).stroke({ color: 0xff3b30, alpha: 0.9 * fade, width: 3 });
  if (m.kind === 'seabed') {
    const h0 = Math.floor(m.time * 1000);
    for (let j = 0; j < 18; j++) {
      const h = speckHash(j, h0),
        a = Math.PI * (0.1 + 0.8 * ((h & 0xff) / 255)),
        r = (0.5 + (3 + (4 * ((h >>> 8) & 0xff)) / 255) * Math.sqrt(u)) * k;
      g.circle(x + r * Math.cos(a), y - r * Math.sin(a) * 0.6, Math.max(2, (0.5 + 1.4 * u) * k * (0.6 + ((h >>> 16) & 3) * 0.2))).fill({
        color: j % 3 === 0 ? 0xc9ad7a : 0x8a7350,
        alpha: 0.75 * fade,
      });
    }
    if (u < 0.3)
      for (let j = 0; j < 8; j++) {
        const a = Math.PI * (0.15 + (0.7 * j) / 7),
          r0 = (0.5 + 6 * u) * k,
          r1 = r0 + 1.5 * k;
        g.moveTo(x + r0 * Math.cos(a), y - r0 * Math.sin(a))
          .lineTo(x + r1 * Math.cos(a), y - r1 * Math.sin(a))
          .stroke({ color: 0xfff0b0, alpha: 1 - u / 0.3, width: 2 });
      }
  }
  // The whole view flashes red at the hit (fading over 0.4 s) inside a red frame (over 0.9 s).
  const flash = Math.max(0, 1 - age / 0.4),
    frame = Math.max(0, 1 - age / 0.9);
  hitShown.tint = 0.3 * flash * flash;
  if (flash > 0) g.rect(0, 0, W, H).fill({ color: 0xff3b30, alpha: hitShown.tint });
  if (frame > 0) g.rect(0, 0, W, H).stroke({ color: 0xff3b30, width: 18, alpha: 0.6 * frame, alignment: 1 });
  hitLabel.text = hitText(m.kind, state.hits);
  hitLabel.alpha = u < 0.7 ? 1 : (1 - u) / 0.3;
  // It comes in large and settles (over the first 0.15 s), so the eye is drawn to it.
  hitLabel.scale.set(u < 0.08 ? 1.4 - 0.4 * (u / 0.08) : 1);
  // Over the place and the hull (above whichever is higher), rising; under the hull instead if it
  // would cover the beacon pointer's label or leave the view.
  const lw = hitLabel.width,
    lh = hitLabel.height;
  // Kept inside the view with its pill (12 px wider each side than the words, 5 px taller).
  const lx = Math.max(lw / 2 + 20, Math.min(W - GAUGE_WIDTH - lw / 2 - 14, x));
  let ly = Math.min(y, hullTop) - lh / 2 - 6 - 24 * u;
  const [px, py, pw, ph] = aim.label as [number, number, number, number];
  const overPointer = pointer.visible && Math.abs(lx - (px + pw / 2)) < (lw + pw) / 2 && Math.abs(ly - (py + ph / 2)) < (lh + ph) / 2;
  if (overPointer || ly < lh / 2 + 13) ly = Math.max(y, hullTop + (SUBMARINE.height + 5) * k) + lh / 2 + 11 + 24 * u;
  hitLabel.position.set(lx, Math.max(lh / 2 + 13, Math.min(H - lh / 2 - 13, ly)));
}
/**
 * Marks the crest of the seabed between the hull at x = `hx` and the target at x = `bx` (m): an
 * orange dashed line 5 m over its highest point, 30 m long, and an orange warning triangle on the
 * crest, pulsing, at game time `t` (s), through `sx`, `sy`. Sets `aim.crest`.
 */
function drawRidgeCrest(hx: number, bx: number, sx: (x: number) => number, sy: (y: number) => number, t: number): void {
  let cx = hx,
    cy = Number.NEGATIVE_INFINITY;
  const n = Math.max(1, Math.ceil(Math.abs(bx - hx)));
  for (let i = 0; i <= n; i++) {
    const x = hx + ((bx - hx) * i) / n,
      y = seabedHeight(handles.seabed, x);
    if (y > cy) {
      cx = x;
      cy = y;
    }
  }
  aim.crest = [cx, cy];
  const pulse = 0.6 + 0.4 * Math.sin(4 * t);
  const lineY = sy(cy + 5);
  for (let u = -15; u < 15; u += 3)
    g.moveTo(sx(cx + u), lineY)
      .lineTo(sx(cx + u + 1.8), lineY)
      .stroke({ color: 0xff8a3d, width: 2.5, alpha: 0.9 });
  const px = sx(cx),
    py = sy(cy) - 4,
    size = 14;
  g.poly([px, py - size, px - size * 0.6, py, px + size * 0.6, py])
    .fill({ color: 0xff8a3d, alpha: pulse })
    .stroke({ color: 0x1a0a02, width: 2 });
  g.rect(px - 1.2, py - size * 0.72, 2.4, size * 0.4).fill(0x1a0a02);
  g.circle(px, py - size * 0.18, 1.4).fill(0x1a0a02);
}
/** The "beacon" tags under beacons in view other than the pointer's (a pool, hidden when unused). */
const tags: Text[] = [];
/** How many tags are shown this frame. */
let otherTags = 0;

// Touch: a stick (up rise, down dive, right ahead, left astern, diagonals both) and two buttons
// for the nose (hold them as the Q and E keys).
const stick = createStick({
  label: 'stick: dive, rise, ahead, astern',
  onChange: (x, y) => {
    stickInput.x = x;
    stickInput.y = y;
  },
});
// Whether a finger is on the stick (its own events report only where the knob is).
stick.element.addEventListener('pointerdown', () => {
  stickInput.held = true;
});
for (const type of ['pointerup', 'pointercancel', 'lostpointercapture'])
  stick.element.addEventListener(type, () => {
    stickInput.held = false;
  });
// Dive or Rise by the stick, timed by its events (after the stick's own listeners have moved it).
for (const type of ['pointerdown', 'pointermove', 'pointerup', 'pointercancel', 'lostpointercapture'])
  stick.element.addEventListener(type, (e) => timeControls(e.timeStamp));
// On a phone a larger stick (136 px, the knob's reach 56 px): the thumb grades its push over more
// of its travel, and the rim is easier to find without looking.
if (compact) stick.element.style.cssText += 'width: 136px; height: 136px;';
// Its caption in 13 px type on a phone (game-kit's 12 px read small under the thumb), on one line
// (at 14 px it took two and pushed the Nose buttons onto two rows).
const stickCaption = stick.wrapper.querySelector<HTMLElement>('.bp-stick-label');
if (compact && stickCaption) stickCaption.style.cssText = 'font-size: 13px; white-space: nowrap;';
/**
 * A mouse pressed on the scene and dragged steers as the stick does: the drag from the press point,
 * MOUSE_STICK_REACH px to the rim (right ahead, left astern, up rise, down dive; further is the
 * rim), drawn as a ring round the press point and a knob (drawMouseStick). Let go, it centres.
 */
const MOUSE_STICK_REACH = 70;
/** The mouse stick: the pointer dragging it (-1: none), its press point and where it is now, px on the scene. */
const mouseStick = { id: -1, x0: 0, y0: 0, x: 0, y: 0 };
const mouseStickRing = new Graphics();
app.stage.addChild(mouseStickRing);
app.canvas.style.cursor = 'crosshair';
/** Where pointer event `e` lies on the scene, px. */
function scenePoint(e: PointerEvent): [number, number] {
  const r = app.canvas.getBoundingClientRect();
  return [
    ((e.clientX - r.left) * app.screen.width) / Math.max(1, r.width),
    ((e.clientY - r.top) * app.screen.height) / Math.max(1, r.height),
  ];
}
app.canvas.addEventListener('pointerdown', (e) => {
  if (e.pointerType === 'touch' || e.button !== 0 || mouseStick.id >= 0) return;
  [mouseStick.x0, mouseStick.y0] = scenePoint(e);
  [mouseStick.x, mouseStick.y] = [mouseStick.x0, mouseStick.y0];
  mouseStick.id = e.pointerId;
  app.canvas.setPointerCapture(e.pointerId);
  app.canvas.style.cursor = 'grabbing';
  Object.assign(stickInput, { x: 0, y: 0, held: true });
  timeControls(e.timeStamp);
});
app.canvas.addEventListener('pointermove', (e) => {
  if (e.pointerId !== mouseStick.id) return;
  [mouseStick.x, mouseStick.y] = scenePoint(e);
  const dx = (mouseStick.x - mouseStick.x0) / MOUSE_STICK_REACH,
    dy = -(mouseStick.y - mouseStick.y0) / MOUSE_STICK_REACH,
    r = Math.max(1, Math.hypot(dx, dy));
  stickInput.x = dx / r;
  stickInput.y = dy / r;
  timeControls(e.timeStamp);
});
for (const type of ['pointerup', 'pointercancel', 'lostpointercapture'] as const)
  app.canvas.addEventListener(type, (e) => {
    if (e.pointerId !== mouseStick.id) return;
    mouseStick.id = -1;
    app.canvas.style.cursor = 'crosshair';
    Object.assign(stickInput, { x: 0, y: 0, held: false });
    timeControls(e.timeStamp);
  });
/** The helm dial's radius, px, and its centre's room from the scene's left and bottom edges, px. */
const HELM_DIAL = { r: 30, inset: 44 };
/** The helm dial's caption ("helm"): what the dial is. */
const helmCaption = new Text({
  text: 'helm',
  style: { fill: 0xe8f4ff, fontSize: 13, fontWeight: '700', fontFamily: 'system-ui, sans-serif', stroke: { color: 0x06213a, width: 3 } },
});
helmCaption.anchor.set(0.5, 1);
helmCaption.visible = false;
app.stage.addChild(helmCaption);
/** What the helm dial showed as last drawn (tests): the knob's push (x ahead, y rise, each in [-1, 1]), the screw's throttle, and whether it is drawn. */
const helmShown = { x: 0, y: 0, throttle: 0, visible: false };
/**
 * Draws the helm dial in the scene's bottom-left corner where there is no stick under the scene (a
 * desktop): a stick's base and knob that shows what the keys or the mouse ask for now (the knob
 * pushed right for Ahead, up for Rise; a key, all the way), so steering with the mouse or the keys
 * is seen on a control as a thumb on a phone's stick is, and under it a bar of the screw's throttle
 * (right of centre ahead, left astern, green while it turns). On `m`, the mouse stick's layer.
 */
function drawHelmDial(m: Graphics): void {
  helmShown.visible = helmCaption.visible = !touch;
  if (touch) return;
  const H = app.screen.height,
    { r, inset } = HELM_DIAL,
    x0 = inset,
    y0 = H - inset - 8;
  const keyX = keyAxis(['a', 'arrowleft'], ['d', 'arrowright']),
    keyY = keyAxis(['s', 'arrowdown'], ['w', 'arrowup']);
  let x = keyX !== 0 ? keyX : stickInput.x,
    y = keyY !== 0 ? keyY : stickInput.y;
  const len = Math.hypot(x, y);
  if (len > 1) [x, y] = [x / len, y / len];
  Object.assign(helmShown, { x, y, throttle: state.throttle });
  const on = x !== 0 || y !== 0;
  m.circle(x0, y0, r)
    .fill({ color: 0x0b1a2e, alpha: 0.78 })
    .stroke({ color: on ? 0xffe066 : 0x8fb8d8, width: 1.5, alpha: 0.9 });
  m.moveTo(x0 - r + 6, y0)
    .lineTo(x0 + r - 6, y0)
    .moveTo(x0, y0 - r + 6)
    .lineTo(x0, y0 + r - 6)
    .stroke({ color: 0x8fb8d8, width: 1, alpha: 0.5 });
  const kx = x0 + x * (r - 11),
    ky = y0 - y * (r - 11);
  if (on) m.moveTo(x0, y0).lineTo(kx, ky).stroke({ color: 0xffe066, width: 2, alpha: 0.8 });
  m.circle(kx, ky, 10).fill(on ? 0xffe066 : 0xcfd8e3);
  // The screw: a bar under the dial, filled from its middle as far as the throttle runs.
  const bw = 2 * r,
    by = y0 + r + 6,
    t = Math.max(-1, Math.min(1, state.throttle));
  m.roundRect(x0 - r, by, bw, 6, 3)
    .fill({ color: 0x0b1a2e, alpha: 0.78 })
    .stroke({ color: 0x8fb8d8, width: 1, alpha: 0.6 });
  if (Math.abs(t) > 0.01) m.rect(t > 0 ? x0 : x0 + t * r, by + 1, Math.abs(t) * r, 4).fill(t > 0 ? 0x6dff9e : 0xff9e8a);
  helmCaption.position.set(x0, y0 - r - 3);
}
/** Draws the mouse stick while it is dragged: its reach as a ring round the press point, a knob where the stick is; and the helm dial. */
function drawMouseStick(): void {
  const m = mouseStickRing;
  m.clear();
  drawHelmDial(m);
  if (mouseStick.id < 0) return;
  const kx = mouseStick.x0 + stickInput.x * MOUSE_STICK_REACH,
    ky = mouseStick.y0 - stickInput.y * MOUSE_STICK_REACH;
  m.circle(mouseStick.x0, mouseStick.y0, MOUSE_STICK_REACH)
    .fill({ color: 0x0b1a2e, alpha: 0.25 })
    .stroke({ color: 0xe8ecf1, width: 1.5, alpha: 0.55 });
  m.moveTo(mouseStick.x0, mouseStick.y0).lineTo(kx, ky).stroke({ color: 0xe8ecf1, width: 2, alpha: 0.5 });
  m.circle(kx, ky, 12).fill({ color: 0xe8ecf1, alpha: 0.7 });
}
// The touch hint (game-kit's card of gestures over the bottom of the scene, where the seabed is)
// fades at the first touch anywhere, the stick and Nose buttons under the scene included, not only
// at a touch on the scene.
function dismissTouchHint(): void {
  removeEventListener('pointerdown', dismissTouchHint, true);
  const hint = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
  if (!hint) return;
  hint.classList.add('bp-gone');
  setTimeout(() => hint.remove(), 700);
}
addEventListener('pointerdown', dismissTouchHint, true);
// The touch hint made small and put low at the scene's left, over the seabed and clear of the depth
// ruler and its figures (52 px: GAUGE_WIDTH and its tags; game-kit's 14 px card, centred, covered the bottom fifth of a phone's sea, the ruler's
// figures included), its type still 13 px.
const touchHintStyle = document.createElement('style');
touchHintStyle.textContent =
  'body .bp-touch-hint { font: 13px/1.3 system-ui, sans-serif; padding: 4px 8px; bottom: 3px; left: 3px; transform: none;' +
  ' max-width: calc(100% - 52px); border-radius: 8px; }';
document.head.append(touchHintStyle);
createButtonBar(
  [
    { label: 'Nose ↘', name: 'nose down', key: 'q' },
    { label: 'Nose ↗', name: 'nose up', key: 'e' },
  ],
  { label: 'trim' },
);

/**
 * Draws the live mines between `left` and `right` (m, world x) and the blasts of those set off, at
 * game time `t` (s), `k` px a metre, through `sx` and `sy` (world m to screen px), the hull at
 * (`hx`, `hy`, m) turned by `ha` rad. A mine: its cable (light, so it reads on the dark water) down
 * to an anchor block on the seabed, a red-orange halo, a grey sphere ringed in light grey with
 * contact horns, and a red lamp on top that blinks once a second (so a mine reads as a danger, not
 * as a rock, in the dark of the deep). Within MINE_WARN_DISTANCE of the hull, and the one on the
 * way to the pointer's beacon, it gets a pulsing red ring at the distance where the hull sets it
 * off. A blast: a white-orange flash and a ring of rising bubbles, over `BLAST_LIFE` s.
 */
/** The live mines drawn this frame: each one's halo as a box on the screen (x, y, width, height, px), for the gauge's tags to keep off. */
const mineBoxes: [number, number, number, number][] = [];
function drawMines(
  t: number,
  k: number,
  sx: (x: number) => number,
  sy: (y: number) => number,
  left: number,
  right: number,
  hx: number,
  hy: number,
  ha: number,
): void {
  const R = MINE_RADIUS * 0.7;
  mineBoxes.length = 0;
  for (let i = 0; i < mines.length; i++) {
    const m = mines[i]!;
    if (!mineLive[i] || m.x < left - 5 || m.x > right + 5) continue;
    const x = sx(m.x),
      y = sy(m.y),
      halo = Math.max(9, 1.9 * MINE_RADIUS * k);
    mineBoxes.push([x - halo, y - halo, 2 * halo, 2 * halo]);
    // The cable, in links every 1.5 m, and the anchor block it holds to.
    const links = Math.max(1, Math.floor((m.y - R - m.anchor) / 1.5));
    g.moveTo(x, y + R * k)
      .lineTo(x, sy(m.anchor))
      .stroke({ color: 0x8fa3b0, width: Math.max(1.5, 0.25 * k), alpha: 0.85 });
    if (k >= 4) for (let j = 1; j < links; j++) g.circle(x, sy(m.y - R - 1.5 * j), 0.18 * k).stroke({ color: 0xb8c6d0, width: 1 });
    g.rect(x - 0.9 * k, sy(m.anchor) - 0.7 * k, 1.8 * k, 0.9 * k).fill(0x5a6570);
    // A warm halo, so the sphere stands out of the blue at any zoom.
    g.circle(x, y, halo).fill({ color: 0xff5a36, alpha: 0.16 });
    // Near the hull (or on the way to the beacon): a pulsing ring where contact begins.
    const near = hullDistance(hx, hy, ha, m.x, m.y);
    if (near < MINE_WARN_DISTANCE || i === wayMine || i === ahead?.index) {
      const pulse = 0.5 + 0.5 * Math.sin(2 * Math.PI * 2 * t),
        close = Math.max(0, 1 - near / MINE_WARN_DISTANCE);
      g.circle(x, y, Math.max(12, (MINE_RADIUS + 1.5) * k)).stroke({
        color: 0xff3b30,
        width: 2 + 2 * close,
        alpha: 0.45 + 0.45 * Math.max(close, pulse * 0.6),
      });
    }
    // Horns: six stubs round the sphere, each with a bright tip.
    for (let j = 0; j < 6; j++) {
      const a = (j / 6) * 2 * Math.PI + Math.PI / 2;
      const x1 = x + Math.cos(a) * MINE_RADIUS * k,
        y1 = y - Math.sin(a) * MINE_RADIUS * k;
      g.moveTo(x + Math.cos(a) * R * k, y - Math.sin(a) * R * k)
        .lineTo(x1, y1)
        .stroke({ color: 0xaab6be, width: Math.max(1.5, 0.3 * k) });
      g.circle(x1, y1, Math.max(1.5, 0.2 * k)).fill(0xffd0c0);
    }
    g.circle(x, y, Math.max(4, R * k))
      .fill(0x56636e)
      .stroke({ color: 0xd8e2e8, width: Math.max(1.5, 0.15 * k), alpha: 0.95 });
    // A highlight, so the sphere reads round.
    g.circle(x - 0.3 * R * k, y - 0.3 * R * k, Math.max(1.5, 0.3 * R * k)).fill({ color: 0xe8f0f4, alpha: 0.45 });
    const on = (t + i * 0.37) % 1 < 0.5;
    g.circle(x, y - R * k * 0.55, Math.max(2, 0.22 * k)).fill({ color: on ? 0xff3b30 : 0x6a1a16, alpha: 1 });
    if (on) g.circle(x, y - R * k * 0.55, Math.max(5, 0.7 * k)).fill({ color: 0xff3b30, alpha: 0.25 });
  }
  for (let i = blasts.length - 1; i >= 0; i--) if (shownAge(blasts[i]!, t) > BLAST_LIFE || t < blasts[i]!.time) blasts.splice(i, 1);
  for (const b of blasts) {
    const u = shownAge(b, t) / BLAST_LIFE,
      x = sx(b.x),
      y = sy(b.y);
    if (u < 0.3) {
      g.circle(x, y, (2 + 14 * u) * k).fill({ color: 0xffb347, alpha: 0.8 * (1 - u / 0.3) });
      g.circle(x, y, (1 + 8 * u) * k).fill({ color: 0xfff3d6, alpha: 0.9 * (1 - u / 0.3) });
    }
    g.circle(x, y, (3 + 12 * Math.sqrt(u)) * k).stroke({ color: 0xe8f6ff, alpha: 0.7 * (1 - u), width: 2 });
    for (let j = 0; j < 14; j++) {
      const h = speckHash(j, Math.floor(b.time * 1000)),
        a = (j / 14) * 2 * Math.PI,
        r = (2 + 9 * Math.sqrt(u) * (0.6 + ((h & 0xff) / 255) * 0.8)) * k;
      g.circle(x + r * Math.cos(a), y - r * Math.sin(a) - 6 * u * k, Math.max(1.5, (0.3 + ((h >>> 8) & 3) * 0.15) * k)).stroke({
        color: 0xe8f6ff,
        alpha: 0.8 * (1 - u),
        width: 1.2,
      });
    }
  }
}

/**
 * Draws the glows of the trail between `left` and `right` (m, world x) at game time `t` (s), `k` px
 * a metre, through `sx` and `sy`: a small sea-green light in a soft halo, pulsing (those missed
 * dimmer), and a burst of sparks with the points scored at each one caught, fading over GLOW_POP_LIFE s.
 */
function drawGlows(t: number, k: number, sx: (x: number) => number, sy: (y: number) => number, left: number, right: number): void {
  for (let i = 0; i < glows.length; i++) {
    const gl = glows[i]!;
    if (glowState[i] === 1 || gl.x < left - 2 || gl.x > right + 2) continue;
    const x = sx(gl.x),
      y = sy(gl.y),
      pulse = 0.5 + 0.5 * Math.sin(3 * t + i * 1.7),
      dim = glowState[i] === 2 ? 0.45 : 1;
    g.circle(x, y, Math.max(7, (1.1 + 0.25 * pulse) * k)).fill({ color: 0x5cf2c8, alpha: 0.16 * dim });
    g.circle(x, y, Math.max(3.5, 0.55 * k)).fill({ color: 0xb8ffe9, alpha: (0.75 + 0.25 * pulse) * dim });
  }
  for (let i = glowPops.length - 1; i >= 0; i--) if (t - glowPops[i]!.time > GLOW_POP_LIFE || t < glowPops[i]!.time) glowPops.splice(i, 1);
  let shown = 0;
  for (const p of glowPops) {
    const u = (t - p.time) / GLOW_POP_LIFE,
      x = sx(p.x),
      y = sy(p.y);
    g.circle(x, y, (0.6 + 3 * Math.sqrt(u)) * k).stroke({ color: 0x9dffe0, alpha: 0.9 * (1 - u), width: 2 });
    for (let r = 0; r < 6; r++) {
      const ang = (r / 6) * 2 * Math.PI + p.time,
        r0 = (0.8 + 3 * u) * k,
        r1 = r0 + 0.9 * k * (1 - u);
      g.moveTo(x + r0 * Math.cos(ang), y + r0 * Math.sin(ang))
        .lineTo(x + r1 * Math.cos(ang), y + r1 * Math.sin(ang))
        .stroke({ color: 0xe8fff6, alpha: 1 - u, width: 1.5 });
    }
    let label = popLabels[shown];
    if (!label) {
      label = new Text({
        text: '',
        style: {
          fill: 0xb8ffe9,
          fontSize: 13,
          fontWeight: '700',
          fontFamily: 'system-ui, sans-serif',
          stroke: { color: 0x06213a, width: 3 },
        },
      });
      label.anchor.set(0.5);
      popLabels.push(label);
      app.stage.addChild(label);
    }
    label.visible = true;
    label.text = p.times > 1 ? `+${p.points} ×${p.times}` : `+${p.points}`;
    label.position.set(x, y - (1.5 + 2.5 * u) * k - 8);
    label.alpha = 1 - u * u;
    shown++;
  }
  for (let i = shown; i < popLabels.length; i++) popLabels[i]!.visible = false;
}
/** The points labels over glows just caught (a pool, hidden when unused). */
const popLabels: Text[] = [];

/**
 * Width of the depth gauge at the scene's right edge, px: its bar, depth figures and the boat's
 * depth pointer (the beacon label, tags and badge keep clear of it). Narrow and see-through, so a
 * mine coming into view at the right edge shows (a 36 px opaque gauge hid the edge on a phone).
 */
const GAUGE_WIDTH = 26;
/** A beacon's lamp this far inside the scene's left, top and bottom edges (and up to 6 px from the depth gauge) is on screen, px: its label shows, not the edge arrow. */
const ON_SCREEN_MARGIN = 14;
/** The depth gauge's figures: one every 50 m of the scale ("0", "50", ...), a pool hidden when unused. */
const gaugeMarks: Text[] = [];
/** The boat's depth in figures by its pointer on the gauge ("53 m"). */
let gaugeDepth: Text | undefined;
/** The target beacon's name and depth by its dot on the gauge ("B 62 m"). */
let gaugeTarget: Text | undefined;
/** The target beacon's name as the gauge writes it (set in draw). */
let targetName = '';
/** A small gauge figure: light, stroked dark to read over bright water, right-aligned at its anchor. */
function gaugeText(size: number): Text {
  const text = new Text({
    text: '',
    style: {
      fill: 0xe8f4ff,
      fontSize: size,
      fontWeight: '700',
      fontFamily: 'system-ui, sans-serif',
      stroke: { color: 0x06213a, width: 3 },
    },
  });
  text.anchor.set(1, 0.5);
  app.stage.addChild(text);
  return text;
}
/**
 * Draws the depth gauge at the right edge of a `W` x `H` px scene: a thin see-through scale from the
 * surface (top) to the course's deepest seabed (`courseDepth`, bottom) with a tick every 10 m and a
 * figure every 50 m, the seabed under the boat (brown below it), the target beacon (a yellow dot
 * with its name and depth), the boat's depth (a yellow pointer with its depth in metres beside it)
 * and the depth ordered (a cyan bar, joined to the boat's pointer while the boat has yet to get
 * there), so the
 * player reads the depth and sees the order move at once and the boat answer it.
 */
function drawDepthGauge(W: number, H: number, depth: number, order: number, bed: number, beacon: number): void {
  const w = 6,
    x0 = W - w - 3,
    top = 14,
    bottom = H - 14;
  const at = (d: number) => top + (bottom - top) * Math.max(0, Math.min(1, d / courseDepth));
  g.rect(x0, top, w, bottom - top).fill({ color: 0x0e4a7a, alpha: 0.45 });
  g.rect(x0, at(bed), w, bottom - at(bed)).fill({ color: 0x5b4a32, alpha: 0.7 });
  for (let d = 10; d < courseDepth; d += 10)
    g.rect(x0 - (d % 50 === 0 ? 4 : 0), at(d) - 0.5, d % 50 === 0 ? w + 4 : w / 2, 1).fill({ color: 0xcfe6ff, alpha: 0.6 });
  g.rect(x0, top, w, bottom - top).stroke({ color: 0x8fb8d8, width: 1, alpha: 0.6 });
  if (Number.isFinite(beacon))
    g.circle(x0 + w / 2, at(beacon), 5)
      .fill(0xffe066)
      .stroke({ color: 0x06213a, width: 1.5 });
  const yb = at(depth);
  // The target's name and depth by its dot ("B 62 m"), hidden where the boat's depth is written
  // and where the pointer's badge or label at the view's edge is drawn.
  if (!gaugeTarget) {
    gaugeTarget = gaugeText(compact ? 14 : 12);
    gaugeTarget.style.fill = 0xffe066;
  }
  gaugeTarget.visible = Number.isFinite(beacon) && Math.abs(at(beacon) - yb) > 14;
  if (gaugeTarget.visible) {
    gaugeTarget.text = `beacon ${targetName} ${Math.max(0, beacon).toFixed(0)} m`;
    gaugeTarget.position.set(x0 - 9, Math.max(top + 6, Math.min(bottom - 6, at(beacon))));
    const tw = gaugeTarget.width,
      th = gaugeTarget.height,
      tx = gaugeTarget.x - tw,
      ty = gaugeTarget.y - th / 2;
    for (const [bx, by, bw, bh] of [aim.badge, aim.label] as [number, number, number, number][])
      if (pointer.visible && bw > 0 && tx < bx + bw + 2 && bx < tx + tw + 2 && ty < by + bh + 2 && by < ty + th + 2)
        gaugeTarget.visible = false;
  }
  if (Number.isFinite(order)) {
    const yo = at(order);
    if (Math.abs(yo - yb) > 1.5) g.rect(x0 - 3.5, Math.min(yo, yb), 3, Math.abs(yo - yb)).fill({ color: 0x7fe3ff, alpha: 0.9 });
    g.roundRect(x0 - 4, yo - 2.5, w + 7, 5, 2)
      .fill({ color: 0x7fe3ff })
      .stroke({ color: 0x06213a, width: 1 });
  }
  g.poly([x0 - 1, yb, x0 - 11, yb - 6, x0 - 11, yb + 6])
    .fill(0xffe066)
    .stroke({ color: 0x06213a, width: 1.5 });
  // The figures: every 50 m left of the bar, hidden where the boat's depth is written.
  let n = 0;
  for (let d = 0; d < courseDepth; d += 50, n++) {
    const mark = gaugeMarks[n] ?? gaugeText(compact ? 13 : 10);
    gaugeMarks[n] = mark;
    mark.text = String(d);
    mark.position.set(x0 - 5, Math.max(top + 5, at(d)));
    mark.alpha = 0.8;
    mark.visible = Math.abs(mark.y - yb) > 14;
  }
  for (let i = n; i < gaugeMarks.length; i++) gaugeMarks[i]!.visible = false;
  // The ruler's left edge: its widest figure (shown or not, so the edge holds still as they hide) and the ticks.
  gauge_.rulerLeft = Math.min(x0 - 4, ...gaugeMarks.slice(0, n).map((m) => m.x - m.width)) - 3;
  if (!gaugeDepth) {
    gaugeDepth = gaugeText(compact ? 14 : 12);
    gaugeDepth.style.fill = 0xffe066;
  }
  // Named, so that it never reads as the beacon's depth when the beacon's tag hides near it.
  gaugeDepth.text = `you ${Math.max(0, depth).toFixed(0)} m`;
  // Shown again each frame: hidden below only while it has nowhere to go off the target's frame.
  gaugeDepth.visible = true;
  gaugeDepth.position.set(x0 - 13, Math.max(top + 6, Math.min(bottom - 6, yb)));
  // Off the target's frame (its brackets reach the gauge when the beacon is near the right edge,
  // and on a phone the tags would be drawn over them): each tag moves just above or below the frame,
  // whichever is nearer and inside the gauge; a figure of the scale there is hidden.
  const frame = aim.frame as [number, number, number, number];
  if (frame[2] > 0) {
    for (const tag of [gaugeDepth, gaugeTarget]) if (tag.visible) offFrame(tag, frame, top, bottom);
    for (const mark of gaugeMarks) if (mark.visible && overlaps(textBox(mark), frame, 2)) mark.visible = false;
    // Moved, the target's tag may now cross the boat's: the boat's depth is kept.
    if (gaugeTarget.visible && overlaps(textBox(gaugeTarget), textBox(gaugeDepth), 2)) gaugeTarget.visible = false;
  }
  // Off the pointer's label pill and badge at the view's edge (on a phone the label would run into
  // the scale's figures): the boat's depth moves above or below them, a figure of the scale there is hidden.
  for (const [bx, by, bw, bh] of [aim.label, aim.badge] as [number, number, number, number][]) {
    if (!pointer.visible || bw <= 0) continue;
    const box = [bx - 7, by - 2, bw + 14, bh + 4];
    if (gaugeDepth.visible) offFrame(gaugeDepth, box, top, bottom);
    // The target's tag too (its pill is drawn here, so hiding it later would leave the pill under the label).
    if (gaugeTarget.visible) offFrame(gaugeTarget, box, top, bottom);
    if (gaugeTarget.visible && (overlaps(textBox(gaugeTarget), box, 2) || overlaps(textBox(gaugeTarget), textBox(gaugeDepth), 2)))
      gaugeTarget.visible = false;
    for (const mark of gaugeMarks) if (mark.visible && overlaps(textBox(mark), box, 2)) mark.visible = false;
  }
  // Moved off the label, the boat's depth may lie on the frame again (a label beside the target's
  // ring): off whichever it crosses, a few times; still on one, it is hidden (the status row has it).
  const labelBoxes = [aim.label, aim.badge]
    .filter((b) => pointer.visible && b[2]! > 0)
    .map(([bx = 0, by = 0, bw = 0, bh = 0]) => [bx - 7, by - 2, bw + 14, bh + 4]);
  const depthTag = gaugeDepth;
  const crossed = () =>
    (frame[2] > 0 && overlaps(textBox(depthTag), frame, 2) ? frame : undefined) ??
    labelBoxes.find((box) => overlaps(textBox(depthTag), box, 2));
  for (let n = 0; n < 3 && depthTag.visible; n++) {
    const box = crossed();
    if (!box) break;
    offFrame(depthTag, box, top, bottom);
  }
  if (depthTag.visible && crossed()) depthTag.visible = false;
  // Off the live mines in view (on a phone the boat's depth would be written over a mine near the edge).
  for (const box of mineBoxes) {
    for (const tag of [gaugeDepth, gaugeTarget]) if (tag.visible) offFrame(tag, box, top, bottom);
    for (const mark of gaugeMarks) if (mark.visible && overlaps(textBox(mark), box, 2)) mark.visible = false;
  }
  // Each tag on a dark see-through pill, so it reads over the seabed as over the water.
  for (const tag of [gaugeDepth, gaugeTarget])
    if (tag.visible) {
      const [x, y, w, h] = textBox(tag);
      g.roundRect(x - 4, y, w + 6, h, h / 2).fill({ color: 0x06213a, alpha: 0.7 });
    }
  gauge_.depth = gaugeDepth.visible ? textBox(gaugeDepth) : [0, 0, 0, 0];
  gauge_.target = gaugeTarget.visible ? textBox(gaugeTarget) : [0, 0, 0, 0];
}

/** A text's box on the screen (x, y, width, height, px). */
function boxOf(t: Text): [number, number, number, number] {
  const b = t.getBounds();
  return [b.x, b.y, b.width, b.height];
}
/** The names of the words drawn on a backing over the seabed in the last frame (backOverSeabed). */
const backedLabels: string[] = [];
/**
 * Puts a dark pill (the beacon pointer's, 0x06213a at 0.85) under each of the scene's small words
 * that lies over the seabed: the other beacons' tags, the gauge's and the ladder's figures, the
 * target's depth, the depth order and the glows' points. Over the bed's light rim and rocks they
 * read at under 3:1 (the beacons' yellow on the rim's tan); on the pill at over 10:1. A `W` px wide
 * view centred on x = `cx` (m) at `k` px a metre, `sy` world height to screen px. Call it after
 * `declutter`, which hides some of them.
 */
function backOverSeabed(W: number, cx: number, k: number, sy: (y: number) => number): void {
  backedLabels.length = 0;
  const overBed = ([x0, y0, w, h]: readonly number[]): boolean => {
    for (let px = Math.max(0, x0!); ; px = Math.min(x0! + w!, px + 4)) {
      if (sy(seabedHeight(handles.seabed, cx + (px - W / 2) / k)) < y0! + h! + 2) return true;
      if (px >= x0! + w!) return false;
    }
  };
  const small: [string, Text | undefined][] = [
    ['target depth', gaugeTarget],
    ['order', orderTag],
    ...ladderMarks.map((m): [string, Text] => ['ladder', m]),
    ...tags.slice(0, otherTags).map((t): [string, Text] => ['beacon tag', t]),
    ...popLabels.map((t): [string, Text] => ['glow points', t]),
    ...gaugeMarks.map((t): [string, Text] => ['gauge figure', t]),
  ];
  for (const [name, t] of small) {
    if (!t?.visible || t.alpha <= 0 || t.text === '') continue;
    const [x, y, w, h] = boxOf(t);
    if (w <= 0 || !overBed([x, y, w, h])) continue;
    g.roundRect(x - 4, y - 1, w + 8, h + 2, Math.min(8, h / 2 + 1)).fill({ color: 0x06213a, alpha: 0.85 * t.alpha });
    backedLabels.push(name);
  }
}
/**
 * The words over the scene as last drawn, after `declutter` (tests): each shown one's name and box
 * (x, y, width, height, px).
 */
const shownLabels: { name: string; box: number[] }[] = [];
/**
 * Keeps the words over a scene `H` px high off each other, once everything is drawn. First what the
 * player acts on: the mine warning's tag, the beacon pointer's label and its badge, the boat's depth
 * on the gauge. Then the messages, in one area: the first-time hint at the scene's top, the pickup
 * banner under it on a phone (in the scene's upper part on a desktop), each moved down past anything
 * it would cover; the hit's label stays over its place, moved up or down past what it would cover.
 * Last the tags that only add to what the scene shows (the target's depth on the gauge, the gauge's
 * and the ladder's figures, the other beacons' tags, the glows' points), each hidden where it would
 * cover anything placed before it or the hull's box `hull` (x, y, width, height, px), so on a phone
 * nothing is drawn on anything else (the banner over the mine's tag, the ladder's figures through
 * the hint and the hull).
 */
/**
 * The end card's box over the scene while it shows (x, y, width, height, px, in the scene's
 * coordinates), null while it is hidden: the words over the scene keep off it.
 */
function endCardBox(): number[] | null {
  if (endCard.style.display === 'none') return null;
  const stage = app.canvas.getBoundingClientRect(),
    b = endCard.getBoundingClientRect();
  return b.height > 0 ? [b.left - stage.left, b.top - stage.top, b.width, b.height] : null;
}
function declutter(H: number, hull: readonly number[]): void {
  const taken: number[][] = [];
  shownLabels.length = 0;
  const take = (name: string, box: number[]) => {
    taken.push(box);
    shownLabels.push({ name, box: [...box] });
  };
  // The end card first: the scene's minor figures under it (the gauge's tags, the ladder's) are left out.
  const card = endCardBox();
  if (card) take('end card', card);
  const clear = (box: readonly number[]) => !taken.some((b) => overlaps(box, b, 2));
  if (mineTag.visible && mineWarning.text) take(mineWarning.kind === 'seabed' ? 'seabed warning' : 'mine warning', mineWarning.box);
  if (pointer.visible && pointer.text) {
    take('pointer', [pointer.x - pointer.width / 2 - 7, pointer.y - pointer.height / 2 - 2, pointer.width + 14, pointer.height + 4]);
    if (aim.badge[2]! > 0) take('badge', aim.badge);
  }
  if (gaugeDepth?.visible) take('depth', boxOf(gaugeDepth));
  if (orderTag.visible && clear(boxOf(orderTag))) take('order', boxOf(orderTag));
  else orderTag.visible = false;
  for (const [name, note] of [
    ['glow hint', glowNote],
    ['current note', currentNoteEl],
  ] as const) {
    if (note.style.display === 'none') continue;
    const stage = app.canvas.getBoundingClientRect(),
      b = note.getBoundingClientRect();
    take(name, [b.left - stage.left, b.top - stage.top, b.width, b.height]);
  }
  // A text moved down (or up: `dir` -1) past every box it covers, inside the scene.
  const slide = (t: Text, dir: number) => {
    for (let n = 0; n < 8; n++) {
      const box = boxOf(t),
        hit = taken.find((b) => overlaps(box, b, 2));
      if (!hit) return;
      const to = dir > 0 ? hit[1]! + hit[3]! + 6 + box[3] / 2 : hit[1]! - 6 - box[3] / 2;
      if (to < box[3] / 2 + 4 || to > H - box[3] / 2 - 4) return;
      t.y = to;
    }
  };
  if (banner.visible) {
    // The banner sits at the top of the scene with the other messages, under the hint, not over the
    // sea ahead of the boat that the player steers into.
    banner.y = 8 + banner.height / 2;
    slide(banner, 1);
    take('banner', boxOf(banner));
  }
  if (hitLabel.visible && hitLabel.alpha > 0) {
    const y0 = hitLabel.y;
    slide(hitLabel, -1);
    if (!clear(boxOf(hitLabel))) {
      hitLabel.y = y0;
      slide(hitLabel, 1);
    }
    take('hit', boxOf(hitLabel));
  }
  const minor: [string, Text][] = [];
  taken.push([...hull]);
  if (gaugeTarget) minor.push(['target depth', gaugeTarget]);
  for (const m of ladderMarks) minor.push(['ladder', m]);
  for (let i = 0; i < otherTags; i++) minor.push(['beacon tag', tags[i]!]);
  for (const l of popLabels) minor.push(['glow points', l]);
  for (const m of gaugeMarks) minor.push(['gauge figure', m]);
  for (const [name, t] of minor) {
    if (!t.visible || t.alpha <= 0) continue;
    const box = boxOf(t);
    if (box[2] <= 0 || !clear(box)) t.visible = false;
    else take(name, box);
  }
}

/** The edge marks as last drawn (tests): each hazard's kind, place (m), metres ahead of the bow, words and box (x, y, width, height, px). */
const edgeShown: (EdgeMark & { text: string; box: number[] })[] = [];
/** The edge marks' words ("62 m"), a pool hidden when unused. */
const edgeTexts: Text[] = [];
/**
 * Draws a mark at the view's leading edge (left of the depth gauge) for each hazard beyond it
 * (./edge-marks.ts edgeMarks: the live mines and a seabed ridge near the boat's depth, up to
 * EDGE_MARK_REACH m ahead of the bow), at its depth on the screen (kept inside the scene's top and
 * bottom), so a pilot sees a mine or a ridge coming seconds before it scrolls into view: a mine as a
 * red disc with horns, a ridge as a sand-coloured peak, each with an arrow pointing off the screen
 * and its distance ahead ("62 m"). Marks are kept off each other, the gauge's tags, the target's
 * frame and the pointer's label. `W` x `H`:
 * the scene, px; `k`: px/m; `cx`: the view's centre x, m; `sy`: world y to screen px; (`hx`, `hy`):
 * the hull, m; `vx`: its speed along x, m/s (backing, the marks are at the left edge).
 */
function drawEdgeMarks(W: number, H: number, k: number, cx: number, sy: (y: number) => number, hx: number, hy: number, vx: number): void {
  const heading: 1 | -1 = vx < -0.5 ? -1 : 1;
  const edge = heading > 0 ? cx + (W / 2 - GAUGE_WIDTH - ON_SCREEN_MARGIN) / k : cx - (W / 2 - ON_SCREEN_MARGIN) / k;
  // A ridge is measured against the deeper of the boat's depth and the depth ordered (the boat diving to a beacon low over the bed meets it there).
  const low = Number.isFinite(state.holdY) ? Math.min(hy, state.holdY) : hy;
  const marks = state.over ? [] : edgeMarks(edge, hx, low, mines, mineLive, (x) => seabedHeight(handles.seabed, x), heading);
  edgeShown.length = 0;
  const size = compact ? 14 : 13,
    top = 14 + size,
    bottom = H - 14 - size;
  // Taken: the gauge's tags, the target's frame, the pointer's label and badge, then each mark placed.
  const taken = [
    gauge_.depth,
    gauge_.target,
    aim.frame,
    ...(pointer.visible ? [aim.label, aim.badge] : []),
    ...(mineTag.visible ? [mineWarning.box] : []),
  ].filter((b) => b[2]! > 0);
  for (const [n, m] of marks.entries()) {
    const text =
      edgeTexts[n] ??
      new Text({ text: '', style: { fill: 0xffffff, fontSize: size, fontWeight: '700', fontFamily: 'system-ui, sans-serif' } });
    if (!edgeTexts[n]) {
      edgeTexts[n] = text;
      app.stage.addChild(text);
    }
    text.visible = true;
    text.text = `${m.kind === 'ridge' ? 'ridge ' : ''}${Math.max(0, m.ahead).toFixed(0)} m`;
    text.style.fill = m.kind === 'mine' ? 0xffc2b3 : 0xf3dcae;
    // The arrow's tip at the edge, the icon inside it, the words inside the icon.
    // Ahead, the tip stops short of the ruler's figures (the chips drawn over "50", "100" on a phone).
    const tip = heading > 0 ? Math.min(W - GAUGE_WIDTH, gauge_.rulerLeft) - 6 : 6,
      icon = tip - heading * 22,
      w = text.width + 38,
      h = Math.max(24, text.height + 8);
    const want = Math.max(top, Math.min(bottom, sy(m.y)));
    const boxAt = (yy: number) => [heading > 0 ? tip - w - 6 : tip, yy - h / 2, w + 6, h];
    // At its depth, or else just above or below one of the boxes taken, whichever clear place is
    // nearest its depth; none clear (on a phone the pointer's label and the gauge's tags can fill the
    // edge), it is not drawn: a chip over the target's words hid them (issue 34).
    const places = [want, ...taken.flatMap((b) => [b[1]! - h / 2 - 3, b[1]! + b[3]! + h / 2 + 3])]
      .filter((yy) => yy >= top && yy <= bottom && !taken.some((b) => overlaps(boxAt(yy), b, 2)))
      .sort((a, b) => Math.abs(a - want) - Math.abs(b - want));
    if (places.length === 0) {
      text.visible = false;
      continue;
    }
    const y = places[0]!;
    const box = boxAt(y);
    taken.push(box);
    const red = m.kind === 'mine';
    g.roundRect(box[0]!, box[1]!, box[2]!, box[3]!, h / 2)
      .fill({ color: 0x06213a, alpha: 0.82 })
      .stroke({ color: red ? 0xff6b4a : 0xd9b77a, width: 1.5 });
    g.poly([tip, y, tip - heading * 9, y - 7, tip - heading * 9, y + 7]).fill(red ? 0xff6b4a : 0xd9b77a);
    if (red) {
      for (let j = 0; j < 4; j++) {
        const a = (j * Math.PI) / 2 + Math.PI / 4;
        g.moveTo(icon, y)
          .lineTo(icon + 8 * Math.cos(a), y + 8 * Math.sin(a))
          .stroke({ color: 0xd8dde3, width: 1.5 });
      }
      g.circle(icon, y, 5.5).fill(0xc3ccd6).stroke({ color: 0xff6b4a, width: 1.5 });
    } else g.poly([icon - 8, y + 6, icon - 2, y - 6, icon + 1, y - 1, icon + 3, y - 4, icon + 8, y + 6]).fill(0xd9b77a);
    text.anchor.set(heading > 0 ? 1 : 0, 0.5);
    text.position.set(icon - heading * 14, y);
    edgeShown.push({ ...m, text: text.text, box: [...box] });
  }
  for (let i = marks.length; i < edgeTexts.length; i++) edgeTexts[i]!.visible = false;
}

/** The depth gauge's tags as last drawn (tests): the boat's depth and the target's, each x, y, width, height, px (zeros while hidden). */
const gauge_ = { depth: [0, 0, 0, 0], target: [0, 0, 0, 0], rulerLeft: Number.POSITIVE_INFINITY };

/** The box of a gauge figure or tag (anchored at its right middle): x, y, width, height, px. */
function textBox(text: Text): [number, number, number, number] {
  return [text.x - text.width, text.y - text.height / 2, text.width, text.height];
}

/** The beacon pointer's pill keeps at least this far under the view's top edge, px. */
const LABEL_TOP = 4;
/** How far the beacon pointer's pill is kept above the seabed under it, px. */
const LABEL_BED_CLEAR = 6;

/**
 * Lifts the beacon pointer's label (`pointer`, its pill 7 px wider and 2 px taller each side than the
 * text) off the seabed: while its pill comes within LABEL_BED_CLEAR px of the bed under any part of it
 * (sampled every 4 px across the pill), or it crosses the hull's box `hull` (x, y, width, height, px),
 * the target's frame (aim.frame, while the beacon is in view), the headlight's cone of the hull at
 * `beam` (x, y, m, and its angle, rad; null while the light is off) or a live mine's ring, it moves up
 * 4 px, never past the view's top. A label clear of the bed is left where it is. The view is `W` x `H`
 * px, centred on x = `cx` (m) at `k` px a metre, `sx`, `sy` world m to screen px.
 */
function liftOffSeabed(
  W: number,
  H: number,
  cx: number,
  k: number,
  sx: (x: number) => number,
  sy: (y: number) => number,
  hull: readonly number[],
  beam: readonly number[] | null,
): void {
  const pill = (): number[] => [
    pointer.x - pointer.width / 2 - 7,
    pointer.y - pointer.height / 2 - 2,
    pointer.width + 14,
    pointer.height + 4,
  ];
  const onBed = (): boolean => {
    const [x0, y0, w, h] = pill() as [number, number, number, number];
    for (let px = x0; ; px = Math.min(x0 + w, px + 4)) {
      if (sy(seabedHeight(handles.seabed, cx + (px - W / 2) / k)) < y0 + h + LABEL_BED_CLEAR) return true;
      if (px >= x0 + w) return false;
    }
  };
  if (!onBed()) return;
  const blocked = (): boolean => {
    const box = pill();
    if (onBed() || overlaps(box, hull, 2) || (aim.onScreen && overlaps(box, aim.frame, 2))) return true;
    if (beam && boxInBeam(box, beam, sx, sy, k)) return true;
    for (let i = 0; i < mines.length; i++) {
      if (!mineLive[i]) continue;
      const r = MINE_RADIUS * k + 6;
      if (overlaps(box, [sx(mines[i]!.x) - r, sy(mines[i]!.y) - r, 2 * r, 2 * r], 0)) return true;
    }
    return false;
  };
  const top = pointer.height / 2 + 4;
  for (let n = 0; n < H / 4 && blocked() && pointer.y > top; n++) pointer.y -= 4;
  pointer.y = Math.max(top, pointer.y);
}

/** Whether boxes `a` and `b` (x, y, width, height, px) overlap, or come within `pad` px of each other. */
function overlaps(a: readonly number[], b: readonly number[], pad: number): boolean {
  return a[0]! < b[0]! + b[2]! + pad && b[0]! < a[0]! + a[2]! + pad && a[1]! < b[1]! + b[3]! + pad && b[1]! < a[1]! + a[3]! + pad;
}

/**
 * Moves the gauge tag `tag` (anchored at its right middle) off the box `frame` (x, y, width, height,
 * px): just above or below it, 4 px clear, whichever is nearer its place and between `top` and
 * `bottom` (px); hidden if neither fits.
 */
function offFrame(tag: Text, frame: readonly number[], top: number, bottom: number): void {
  if (!overlaps(textBox(tag), frame, 3)) return;
  const h = tag.height,
    above = frame[1]! - h / 2 - 4,
    below = frame[1]! + frame[3]! + h / 2 + 4;
  const fitsAbove = above >= top + h / 2,
    fitsBelow = below <= bottom - h / 2;
  if (!fitsAbove && !fitsBelow) tag.visible = false;
  else tag.y = fitsAbove && (!fitsBelow || tag.y - above < below - tag.y) ? above : below;
}

/** A well-mixed 32-bit hash of a cell (i, j) of the marine snow: its speck's offset, size and brightness. */
function speckHash(i: number, j: number): number {
  let h = Math.imul(i, 0x27d4eb2d) ^ Math.imul(j, 0x165667b1);
  h = Math.imul(h ^ (h >>> 15), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}

/** Bubbles and spray (drawing only): world position (m), age and life (s), radius (m). */
const bubbles: { x: number; y: number; age: number; life: number; r: number }[] = [];
let bubbleTime = 0;
/** The screw's turn for drawing, rad. */
let screwPhase = 0;

/** The depth ladder by the boat (drawDepthLadder): its figures, a pool hidden when unused. */
const ladderMarks: Text[] = [];
/** The depth ladder's opacity in [0, 1] and the game time it was last eased at, s. */
const ladder = { alpha: 0, time: 0 };
/** How far the depth ladder reaches above and below the boat and its order, m. */
const LADDER_REACH = 10;
/** Seconds the depth ladder takes to fade in or out. */
const LADDER_FADE = 0.4;
/**
 * Draws the depth ladder fixed in the water behind the boat's stern while it dives or rises or has
 * yet to reach the depth ordered: a tick every 2 m, a longer one with its depth ("30 m") every
 * 10 m, and the order's depth in cyan, so the ticks slide past the hull as it changes depth and the
 * player sees how far it has gone and has to go. Fades in and out over LADDER_FADE s of game time
 * `t`; `sx` / `sy` map world x / y (m) to screen px, (hxw, hyw) is the hull's centre, m.
 */
/** The depth the boat will level at, by the ladder's cyan bar ("level 18 m"): shown while it is over a metre off the boat. */
const orderTag = gaugeText(compact ? 14 : 12);
orderTag.style.fill = 0x7fe3ff;
function drawDepthLadder(t: number, sx: (x: number) => number, sy: (y: number) => number, hxw: number, hyw: number): void {
  const c = shell.world.components,
    vy = c.Velocity.y[handles.hull]!;
  const order = state.holdY;
  const moving =
    state.mode === 'diving' || state.mode === 'rising' || (Number.isFinite(order) && Math.abs(order - hyw) > 0.5) || Math.abs(vy) > 0.6;
  const dt = Math.max(0, Math.min(0.1, t - ladder.time));
  ladder.time = t;
  ladder.alpha = Math.max(0, Math.min(1, ladder.alpha + ((moving ? 1 : -1) * dt) / LADDER_FADE));
  let used = 0;
  if (ladder.alpha > 0) {
    // Kept far enough in from the view's left edge for its widest figure ("100 m", 11 px bold, about
    // 36 px, measured: mark.width) left of the longer ticks, and the view's shake at a hit (SHAKE_PX),
    // so on a phone with the boat near the edge no figure is cut off.
    const widest = Math.max(40, ...ladderMarks.map((m) => m.width + 4));
    const x = hxw - SUBMARINE.length / 2 - 3,
      px = Math.max(sx(x), 9 + 3 + widest + SHAKE_PX),
      to = Number.isFinite(order) ? order : hyw;
    const hi = Math.min(-1, Math.max(hyw, to) + LADDER_REACH),
      lo = Math.min(hyw, to) - LADDER_REACH;
    g.moveTo(px, sy(hi))
      .lineTo(px, sy(lo))
      .stroke({ color: 0xcfe6ff, width: 1, alpha: 0.35 * ladder.alpha });
    for (let d = Math.ceil(-hi / 2) * 2; d <= -lo; d += 2) {
      const y = -d,
        // Faded towards the ladder's ends, so it reads as a scale round the boat, not a wall.
        near = Math.max(0, 1 - Math.max(0, Math.max(y - Math.max(hyw, to), Math.min(hyw, to) - y)) / LADDER_REACH),
        big = d % 10 === 0,
        len = big ? 9 : 5,
        a = ladder.alpha * near;
      if (a <= 0.02) continue;
      g.moveTo(px - len, sy(y))
        .lineTo(px + len, sy(y))
        .stroke({ color: 0xe8f4ff, width: big ? 2 : 1.2, alpha: 0.75 * a });
      if (big) {
        const mark = ladderMarks[used] ?? gaugeText(compact ? 13 : 11);
        ladderMarks[used++] = mark;
        mark.text = `${d} m`;
        mark.position.set(px - len - 3, sy(y));
        mark.alpha = 0.9 * a;
        mark.visible = true;
      }
    }
    if (Number.isFinite(order) && Math.abs(order - hyw) > 0.3) {
      g.roundRect(px - 11, sy(order) - 2, 22, 4, 2)
        .fill({ color: 0x7fe3ff, alpha: ladder.alpha })
        .stroke({ color: 0x06213a, width: 1, alpha: ladder.alpha });
      // Where the boat will level: a dashed cyan line at the order's depth along the hull's length,
      // and its depth beside the ladder ("level 18 m"), so the mark the stick moves reads at a glance.
      const oy = sy(order),
        // (Inside the view: a hull put far off it would have the dashes run on for millions of px.)
        bow = Math.min(app.screen.width, sx(hxw + SUBMARINE.length / 2));
      for (let x0 = px + 12; x0 < bow; x0 += 10) g.moveTo(x0, oy).lineTo(Math.min(bow, x0 + 6), oy);
      g.stroke({ color: 0x7fe3ff, width: 2, alpha: 0.8 * ladder.alpha });
      if (Math.abs(order - hyw) > 1) {
        orderTag.text = `level ${Math.max(0, -order).toFixed(0)} m`;
        // Left of the ladder, or past the bow where that would run off the view's left edge.
        const left = px - 14 - orderTag.width >= 4;
        orderTag.anchor.set(left ? 1 : 0, 0.5);
        orderTag.position.set(left ? px - 14 : bow + 6, oy);
        orderTag.alpha = ladder.alpha;
        orderTag.visible = true;
      }
    }
  }
  if (!(ladder.alpha > 0 && Number.isFinite(order) && Math.abs(order - hyw) > 1)) orderTag.visible = false;
  for (let i = used; i < ladderMarks.length; i++) ladderMarks[i]!.visible = false;
}
let lastFill = [0, 0];

/**
 * Moves the bubbles on (they rise at 1.2 m/s; spray above the water falls back) and adds new ones
 * where the vents or the thrusters work: air out of a tank's top while it floods, out of its bottom
 * while it blows, and at each thruster in proportion to its push. `angle` is the hull's, rad.
 * Bubbles keep world coordinates so the camera does not drag them along.
 */
function spawnBubbles(world: PhysicsWorld, angle: number): void {
  const c = world.components,
    e = handles.hull;
  const dt = Math.max(0, Math.min(0.1, world.time - bubbleTime));
  bubbleTime = world.time;
  const surface = c.FluidRegion.surface[handles.sea]!;
  for (let i = bubbles.length - 1; i >= 0; i--) {
    const b = bubbles[i]!;
    b.age += dt;
    b.y += (b.y < surface ? 1.2 : -2) * dt;
    if (b.age >= b.life) bubbles.splice(i, 1);
  }
  if (dt === 0) return;
  const x = c.Position.x[e]!,
    y = c.Position.y[e]!,
    co = Math.cos(angle),
    s = Math.sin(angle);
  const at = (u: number, v: number): [number, number] => [x + u * co - v * s, y + u * s + v * co];
  const B = c.Ballast;
  const tanks = [B.fore[e]!, B.aft[e]!];
  for (let i = 0; i < 2; i++) {
    const change = (tanks[i]! - lastFill[i]!) / dt; // fill per second: + flooding, - blowing
    const u = (i === 0 ? 1 : -1) * SUBMARINE.tankArm;
    const count = Math.abs(change) * dt * 40;
    for (let j = 0, m = Math.floor(count + Math.random()); j < m; j++) {
      const [bx, by] = at(u + (Math.random() - 0.5) * 2.5, change > 0 ? SUBMARINE.height / 2 : -SUBMARINE.height / 2);
      bubbles.push({ x: bx, y: by, age: 0, life: 0.8 + Math.random(), r: 0.15 + 0.2 * Math.random() });
    }
  }
  lastFill = tanks;
  for (const [u, f] of [
    [SUBMARINE.thrusterArm, state.fore],
    [-SUBMARINE.thrusterArm, state.aft],
  ] as const) {
    const count = (Math.abs(f) / SUBMARINE.thrusterForce) * dt * 12;
    for (let j = 0, m = Math.floor(count + Math.random()); j < m; j++) {
      const [bx, by] = at(u + (Math.random() - 0.5), -Math.sign(f) * (SUBMARINE.height / 2 + 1 + 2 * Math.random()));
      bubbles.push({ x: bx, y: by, age: 0, life: 0.6 + 0.6 * Math.random(), r: 0.1 + 0.15 * Math.random() });
    }
  }
  // The screw's wash behind the stern (ahead) or before it (astern).
  const wash = Math.abs(state.throttle) * dt * 14;
  for (let j = 0, m = Math.floor(wash + Math.random()); j < m; j++) {
    const [bx, by] = at(-SUBMARINE.length / 2 - (state.throttle > 0 ? 0.5 + 3 * Math.random() : -1), (Math.random() - 0.5) * 1.2);
    bubbles.push({ x: bx, y: by, age: 0, life: 0.5 + 0.8 * Math.random(), r: 0.1 + 0.2 * Math.random() });
  }
  if (bubbles.length > 400) bubbles.splice(0, bubbles.length - 400);
}

/** The colour of "level with the target": its guide line and brackets (./level-stop.ts levelWith). */
const LEVEL_COLOR = 0x6dff9e;
/**
 * Where the boat will pass to the target beacon's depth, as last drawn (./level-stop.ts levelWith):
 * the target (-1: none), its side (0 level, 1 over, -1 under) and the metres to the band's edge.
 */
const aimLevel = { index: -1, side: 1 as -1 | 0 | 1, off: Number.NaN };

/**
 * The target's depth carried to the boat: a dashed line at the beacon's depth from its ring back past
 * the hull's stern (clipped to the scene left of the depth gauge), yellow, in a faint lane as high as
 * the depths that pass through its ring (./level-stop.ts LEVEL_BAND); green while the boat is going
 * to pass level with it (`aimLevel`). So the player sees at the hull, not across the screen, whether
 * the depth line (the boat's order) will take it through the ring.
 */
function drawLevelGuide(sx: (x: number) => number, sy: (y: number) => number, W: number, hxw: number): void {
  levelGuide.shown = false;
  if (aim.index < 0 || state.over) return;
  const wx = handles.beacons[2 * aim.index]!,
    wy = handles.beacons[2 * aim.index + 1]!;
  const L = SUBMARINE.length,
    dir = wx >= hxw ? 1 : -1;
  // From the hull's far side to the ring's near edge, within the scene.
  const x0 = Math.max(0, Math.min(sx(hxw - dir * L), sx(wx - dir * BEACON_CATCH))),
    x1 = Math.min(W - GAUGE_WIDTH, Math.max(sx(hxw - dir * L), sx(wx - dir * BEACON_CATCH)));
  const y = sy(wy);
  if (x1 - x0 < 4 || y < 0 || y > app.screen.height) return;
  const level = aimLevel.side === 0,
    color = level ? LEVEL_COLOR : 0xffe066;
  // The lane to the ring: the depths from which the ring is reached going straight on.
  const top = sy(wy + LEVEL_BAND),
    bottom = sy(wy - LEVEL_BAND);
  g.rect(x0, top, x1 - x0, bottom - top).fill({ color, alpha: level ? 0.09 : 0.05 });
  const dash = Math.max(6, 1.4 * zoom),
    gap = Math.max(5, zoom);
  for (let x = x0; x < x1; x += dash + gap)
    g.moveTo(x, y)
      .lineTo(Math.min(x1, x + dash), y)
      .stroke({ color, width: 2, alpha: level ? 0.8 : 0.55 });
  Object.assign(levelGuide, { shown: true, y, from: x0, to: x1, level });
}
/** The level guide as last drawn (drawLevelGuide): whether shown, its height and ends on the screen (px), and whether green. */
const levelGuide = { shown: false, y: 0, from: 0, to: 0, level: false };

function draw(): void {
  drawMouseStick();
  const world = shell.world,
    c = world.components,
    e = handles.hull;
  const W = app.screen.width,
    H = app.screen.height;
  const hxw = c.Position.x[e]!,
    hyw = c.Position.y[e]!;
  const before = aim.index;
  aim.index = chooseBeacon(handles.beacons, taken, hxw, hyw, aim.index, -1, goingX());
  // A new target (the last one collected): its label pulses (drawBeacons).
  if (before >= 0 && aim.index >= 0 && aim.index !== before) aimSwitchedAt = world.time;
  // Where the boat will pass to the target's depth (./level-stop.ts): level with it, over or under.
  const wasLevel = aimLevel.side === 0 && aimLevel.index === aim.index;
  Object.assign(aimLevel, { index: aim.index, side: 1, off: Number.NaN });
  if (aim.index >= 0) Object.assign(aimLevel, levelWith(state.holdY, hyw, handles.beacons[2 * aim.index + 1]!));
  // Coming level with it: a short high tick.
  if (aimLevel.side === 0 && !wasLevel && aim.index >= 0 && !state.over) sound.chime(1760, 0.08);
  // The camera frames the hull and the beacon the pointer leads to: it centres between them and
  // zooms out (down to FRAME_MIN_ZOOM px/m) until both fit inside FRAME_MARGIN px of the edges, so
  // the player sees where to go instead of steering by an arrow to a point off screen.
  const fx = aim.index >= 0 ? handles.beacons[2 * aim.index]! : hxw,
    fy = aim.index >= 0 ? handles.beacons[2 * aim.index + 1]! : hyw;
  // A target behind the hull: the hull, its beam and the gauge's room on the right, the target inside the margin on the left.
  const behindFit =
    fx < hxw ? (W - HULL_GAUGE_ROOM - FRAME_MARGIN) / (hxw - fx + SUBMARINE.length / 2 + HEADLIGHT.reach) : Number.POSITIVE_INFINITY;
  const fit = Math.min(
    params.pixelsPerMeter,
    behindFit,
    (W - 2 * FRAME_MARGIN) / Math.max(1e-6, Math.abs(fx - hxw) + SUBMARINE.length),
    (H - 2 * FRAME_MARGIN) / Math.max(1e-6, Math.abs(fy - hyw) + SUBMARINE.length),
  );
  // A portrait view is narrow: it shows PORTRAIT_REST_WIDTH m across at least at rest, easing to
  // PORTRAIT_MIN_WIDTH under way, and leads further, so the boat sits nearer the trailing edge with
  // more of the way ahead in view. Under way it zooms out no further than PORTRAIT_MIN_ZOOM_UNDER_WAY
  // (the hull larger), at rest to FRAME_MIN_ZOOM, so a target further off is framed.
  const portrait = W < H;
  const going = portrait ? Math.min(1, Math.max(0, c.Velocity.x[e]! / PORTRAIT_SPEED)) : 0;
  const widest = portrait ? W / (PORTRAIT_REST_WIDTH + (PORTRAIT_MIN_WIDTH - PORTRAIT_REST_WIDTH) * going) : Number.POSITIVE_INFINITY;
  const least = FRAME_MIN_ZOOM + (PORTRAIT_MIN_ZOOM_UNDER_WAY - FRAME_MIN_ZOOM) * going;
  const target = Math.max(Math.min(least, params.pixelsPerMeter), Math.min(fit, widest));
  // Eased (a new beacon or a collected one does not make the view jump).
  zoom = Number.isFinite(zoom) ? zoom + (target - zoom) * 0.1 : target;
  const k = zoom;
  // Centred between them, moved toward the hull as far as needed to keep the hull FRAME_MARGIN
  // inside the view when both do not fit; never more sky than the top 15% of the view.
  // The hull's centre itself keeps HULL_SIDE_ROOM past its half length from the left side (./framing.ts leadLimits).
  // Right of centre the hull's headlight keeps HULL_GAUGE_ROOM (hullReachRight), clear of the depth gauge's tags.
  const lead = leadLimits(W, k, portrait),
    hullReachX = lead.hull,
    hullReachRight =
      Math.max(0, W / 2 - Math.max(FRAME_MARGIN, (SUBMARINE.length / 2 + HEADLIGHT.reach) * k + HULL_GAUGE_ROOM)) / k ||
      // A view too narrow for the beam too (a phone): the bow alone keeps the room.
      Math.max(0, W / 2 - Math.max(FRAME_MARGIN, (SUBMARINE.length / 2) * k + HULL_GAUGE_ROOM)) / k,
    reachY = Math.max(0, H / 2 - FRAME_MARGIN) / k;
  // Look-ahead: the view leads the hull by LEAD_TIME s (PORTRAIT_LEAD_TIME on a portrait view) of its velocity along x (LEAD_TIME_Y s across), at most LEAD_SHARE of the way
  // to the framing margin, eased over about LEAD_EASE s of game time (a bump or a blast does not jerk
  // the view). Under way, the view's centre is at least that far ahead of the hull, so what lies
  // ahead is in view even when the beacon framed is behind.
  const dtCam = Math.max(0, Math.min(0.1, world.time - camera.time));
  camera.time = world.time;
  const ease = 1 - Math.exp(-dtCam / LEAD_EASE);
  camera.leadX += ((portrait ? PORTRAIT_LEAD_TIME : LEAD_TIME) * c.Velocity.x[e]! - camera.leadX) * ease;
  camera.leadY += (LEAD_TIME_Y * c.Velocity.y[e]! - camera.leadY) * ease;
  const leadX = Math.max(-lead.reach, Math.min(lead.reach, camera.leadX)),
    leadY = Math.max(-LEAD_SHARE * reachY, Math.min(LEAD_SHARE * reachY, camera.leadY));
  const atLeast = (framed: number, hull: number, lead: number) =>
    lead > 0 ? Math.max(framed, hull + lead) : lead < 0 ? Math.min(framed, hull + lead) : framed;
  // A target ahead keeps its ring left of the depth gauge's ruler where the hull's room allows (on a
  // phone at the start the ring lay half under it).
  const ringClear = fx > hxw ? fx + BEACON_CATCH - (W / 2 - GAUGE_WIDTH - ON_SCREEN_MARGIN) / k : Number.NEGATIVE_INFINITY;
  // On a portrait view under way, the framing of a target far ahead leads the hull no further than
  // the look-ahead's limit, so the hull is not pressed into the trailing edge; at rest (the eased
  // look-ahead near 0) the target's ring is framed as far as the hull's room allows, easing between.
  const underWay = portrait ? Math.min(1, Math.abs(camera.leadX) / Math.max(1e-9, lead.reach)) : 0;
  const leadMost = hullReachX - underWay * Math.max(0, hullReachX - lead.reach);
  const cx = Math.max(hxw - hullReachRight, Math.min(hxw + leadMost, atLeast(Math.max((hxw + fx) / 2, ringClear), hxw, leadX))),
    cy = Math.min(-H / k / 2 + (0.15 * H) / k, Math.max(hyw - reachY, Math.min(hyw + reachY, atLeast((hyw + fy) / 2, hyw, leadY))));
  camera.x = cx;
  camera.y = cy;
  camera.zoom = k;
  camera.width = W;
  camera.height = H;
  // A hit shakes the view (drawing only): SHAKE_PX px at the hit, decaying over HIT_SHAKE_LIFE s.
  const lastMark = hitMarks[hitMarks.length - 1];
  const shakeAge = lastMark ? shownAge(lastMark, world.time) : Number.POSITIVE_INFINITY;
  // A scrape (a contact that costs nothing) shakes it a little, so the bed is felt before it hurts.
  const scrapeAge = world.time - scrapeAt;
  const shake = Math.max(
    shakeAge >= 0 && shakeAge < HIT_SHAKE_LIFE ? SHAKE_PX * (1 - shakeAge / HIT_SHAKE_LIFE) ** 2 : 0,
    scrapeAge >= 0 && scrapeAge < SCRAPE_SHAKE_LIFE ? SCRAPE_SHAKE_PX * (1 - scrapeAge / SCRAPE_SHAKE_LIFE) ** 2 : 0,
  );
  camera.shake = shake;
  const shakeX = shake * Math.sin(97 * world.time),
    shakeY = shake * Math.cos(71 * world.time);
  const sx = (x: number) => W / 2 + (x - cx) * k + shakeX,
    sy = (y: number) => H / 2 - (y - cy) * k + shakeY;
  g.clear();
  g.rect(0, 0, W, Math.max(0, sy(0))).fill(0x8fc3ea);
  // Sea surface with waves.
  const t = world.time,
    surface = c.FluidRegion.surface[handles.sea]!;
  // Each outline runs to the right edge itself (px = W), so no strip is left unfilled there.
  g.moveTo(0, H);
  for (let px = 0; ; px = Math.min(W, px + 8)) {
    const x = cx + (px - W / 2) / k;
    g.lineTo(px, sy(surface + params.waveHeight * 0.3 * Math.sin(0.15 * x - 1.3 * t)));
    if (px >= W) break;
  }
  g.lineTo(W, H).closePath().fill({ color: 0x0e4a7a, alpha: 0.95 });
  // The deep is darker: a band every 5 m, each a little darker, to 0.65 black at 150 m.
  for (let d = 5; d < 160; d += 5) {
    const top = Math.max(0, sy(surface - d)),
      bottom = Math.min(H, sy(surface - d - 5));
    if (bottom > top) g.rect(0, top, W, bottom - top).fill({ color: 0x020a14, alpha: Math.min(0.65, (0.65 * d) / 150) });
  }
  // Sunlight: shafts slanting down from the surface, fixed in the water every 16 m (some cells have
  // none), swaying and flickering slowly, each fading out in six steps by 45 m down.
  const rayCell = 16,
    reach = 45;
  if (sy(surface - reach) > 0)
    for (let i = Math.floor((cx - W / 2 / k - reach) / rayCell); i <= Math.ceil((cx + W / 2 / k) / rayCell); i++) {
      const h = speckHash(i, 7919);
      if ((h & 3) === 0) continue;
      const x = (i + ((h >>> 4) & 0xff) / 256) * rayCell,
        w = 1.5 + ((h >>> 12) & 7) * 0.5,
        slant = 0.35 + 0.1 * Math.sin(0.15 * t + (h & 0xff)),
        glow = 0.05 + 0.025 * Math.sin(0.7 * t + ((h >>> 16) & 0xff));
      for (let part = 0; part < 6; part++) {
        const d0 = (part * reach) / 6,
          d1 = ((part + 1) * reach) / 6,
          spread0 = w * (1 + d0 / 20),
          spread1 = w * (1 + d1 / 20);
        g.poly([
          sx(x + slant * d0),
          sy(surface - d0),
          sx(x + slant * d0 + spread0),
          sy(surface - d0),
          sx(x + slant * d1 + spread1),
          sy(surface - d1),
          sx(x + slant * d1),
          sy(surface - d1),
        ]).fill({ color: 0xbfe6ff, alpha: glow * (1 - (part + 0.5) / 6) });
      }
    }
  // Marine snow: specks fixed in the water, one to each 6 m cell, so the boat is seen to move past them.
  const cell = 6;
  const x0 = Math.floor((cx - W / 2 / k) / cell),
    x1 = Math.ceil((cx + W / 2 / k) / cell),
    y0 = Math.floor((cy - H / 2 / k) / cell),
    y1 = Math.min(-1, Math.ceil((cy + H / 2 / k) / cell));
  for (let i = x0; i <= x1; i++)
    for (let j = y0; j <= y1; j++) {
      const h = speckHash(i, j);
      const wx = (i + (h & 0xff) / 256) * cell + 0.3 * Math.sin(0.4 * t + h),
        wy = (j + ((h >>> 8) & 0xff) / 256) * cell;
      if (wy > surface - 0.5) continue;
      g.circle(sx(wx), sy(wy), 0.8 + ((h >>> 16) & 3) * 0.35).fill({ color: 0xcfe6ff, alpha: 0.25 + ((h >>> 20) & 7) * 0.04 });
    }
  // Seabed. Its outline is kept inside the view (at most H): where the bed dips below the view's
  // bottom an outline below H folded the polygon over itself, and its fill drew dark wedges.
  g.moveTo(0, H);
  for (let px = 0; ; px = Math.min(W, px + 6)) {
    g.lineTo(px, Math.min(H, sy(seabedHeight(handles.seabed, cx + (px - W / 2) / k))));
    if (px >= W) break;
  }
  g.lineTo(W, H).closePath().fill(0x5b4a32);
  // Its detail, every 3 m cell fixed to the bed (drawing only): a darker layer 3 m down, a lighter
  // sand line on top, stones and swaying weed.
  const bedAt = (x: number) => seabedHeight(handles.seabed, x);
  const left = cx - W / 2 / k,
    right = cx + W / 2 / k;
  if (sy(bedAt(cx)) < H + 40 * k) {
    g.moveTo(0, H);
    for (let px = 0; ; px = Math.min(W, px + 12)) {
      g.lineTo(px, Math.min(H, sy(bedAt(cx + (px - W / 2) / k) - 3)));
      if (px >= W) break;
    }
    g.lineTo(W, H).closePath().fill({ color: 0x2e2418, alpha: 0.6 });
    for (let px = 0; ; px = Math.min(W, px + 6)) {
      const y = sy(bedAt(cx + (px - W / 2) / k));
      if (px === 0) g.moveTo(px, y);
      else g.lineTo(px, y);
      if (px >= W) break;
    }
    g.stroke({ color: 0xa58d5f, width: 2, alpha: 0.8 });
    const bedCell = 3;
    for (let i = Math.floor(left / bedCell) - 1; i <= Math.ceil(right / bedCell) + 1; i++) {
      const h = speckHash(i, 104729),
        x = (i + (h & 0xff) / 256) * bedCell,
        y = bedAt(x),
        kind = (h >>> 8) & 15;
      if (kind < 3) {
        // A stone half sunk in the bed.
        const r = 0.4 + ((h >>> 12) & 7) * 0.15;
        g.ellipse(sx(x), sy(y), 1.5 * r * k, r * k).fill(kind === 0 ? 0x6f6656 : 0x5e5546);
      } else if (kind < 6) {
        // Weed: a stalk of five segments, swaying with a period of about 5 s.
        const tall = 2.5 + ((h >>> 12) & 7) * 0.8,
          phase = (h >>> 16) & 0xff;
        g.moveTo(sx(x), sy(y));
        for (let j = 1; j <= 5; j++) {
          const f = j / 5;
          g.lineTo(sx(x + f * f * 0.9 * Math.sin(1.2 * t + phase)), sy(y + f * tall));
        }
        g.stroke({ color: kind === 3 ? 0x3f7a4a : 0x2f6a5a, width: Math.max(1.5, 0.35 * k), alpha: 0.9 });
      }
    }
  }
  // The level's current (./current.ts): specks drifting with the water, streaked the way it flows.
  drawCurrent(g, params.level, left, right, cy - H / k / 2, cy + H / k / 2, t, k, sx, sy, bedAt);
  drawFish(g, left, right, t, k, sx, sy, bedAt, hxw, hyw);
  drawGlows(t, k, sx, sy, left, right);
  showGlowHint(
    t,
    glows.some((gl, i) => glowState[i] === 0 && gl.x > left && gl.x < right && sy(gl.y) > 0 && sy(gl.y) < H),
  );
  showCurrentNote(t, currentAt(params.level, hyw));
  drawMines(t, k, sx, sy, left, right, hxw, hyw, c.Angle.value[e]!);
  // Beacons: a lamp (at least 5 px, however far the camera zooms out) in a soft pulsing glow, inside
  // its one ring, the catch radius (BEACON_CATCH: any part of the hull inside it collects; the help
  // tells the player to touch it), drawn solid round a faint disc with the stroke's outer edge on the catch
  // radius (so the boat touching the line drawn is inside it), brighter as the hull nears it; each one
  // on screen but the pointer's is tagged "beacon" under it, so a yellow light elsewhere in the view
  // reads as another beacon to collect, not as something unexplained.
  let tagged = 0;
  aim.frame = [0, 0, 0, 0];
  for (let i = 0; i < taken.length; i++) {
    if (taken[i]) continue;
    const bx = sx(handles.beacons[2 * i]!),
      by = sy(handles.beacons[2 * i + 1]!);
    // The target (the pointer's beacon) bright, in four corner brackets round its catch disc that
    // close in and open out; the others dimmer, so the one to steer for stands out.
    const dim = i === aim.index ? 1 : 0.55;
    const rk = BEACON_CATCH * k,
      near = Math.max(0, 1 - Math.hypot(handles.beacons[2 * i]! - hxw, handles.beacons[2 * i + 1]! - hyw) / (4 * BEACON_CATCH));
    g.circle(bx, by, rk).fill({ color: 0xffe066, alpha: (0.08 + 0.08 * near) * dim });
    const ringWidth = 2.5 + near;
    g.circle(bx, by, Math.max(1, rk - ringWidth / 2)).stroke({ color: 0xffe066, alpha: (0.6 + 0.4 * near) * dim, width: ringWidth });
    // The lamp's glow: filled discs (no second ring to mistake for the one to touch).
    g.circle(bx, by, Math.max(9, (2 + Math.sin(3 * t)) * k)).fill({ color: 0xffe066, alpha: 0.14 * dim });
    g.circle(bx, by, Math.max(5, 1.2 * k)).fill({ color: 0xffe066, alpha: dim * (0.9 + 0.1 * Math.sin(4 * t)) });
    // A beacon passed and left (missed): crossed out in red over its lamp, and its tag says so.
    if (missed[i]) {
      const r = Math.max(8, 2 * k);
      for (const [width, color] of [
        [6, 0x06213a],
        [3, 0xff5a4a],
      ] as const)
        g.moveTo(bx - r, by - r)
          .lineTo(bx + r, by + r)
          .moveTo(bx + r, by - r)
          .lineTo(bx - r, by + r)
          .stroke({ color, width, cap: 'round' });
    }
    if (i === aim.index && aim.onScreen) {
      const r = Math.max(14, BEACON_CATCH * k) + 6 + 3 * Math.sin(3 * t),
        arm = Math.max(6, 0.35 * r);
      // The frame's box at its widest (the brackets open out to 9 px past the ring, 2.5 px of stroke).
      const out = Math.max(14, BEACON_CATCH * k) + 9 + 2.5;
      aim.frame = [bx - out, by - out, 2 * out, 2 * out];
      for (const [ux, uy] of [
        [-1, -1],
        [1, -1],
        [1, 1],
        [-1, 1],
      ] as const)
        for (const [width, color] of [
          [5, 0x06213a],
          [2.5, aimLevel.side === 0 ? LEVEL_COLOR : 0xffe066],
        ] as const)
          g.moveTo(bx + ux * r, by + uy * (r - arm))
            .lineTo(bx + ux * r, by + uy * r)
            .lineTo(bx + ux * (r - arm), by + uy * r)
            .stroke({ color, width, cap: 'round', join: 'round' });
    }
    if (i === aim.index || bx < 0 || bx > W || by < 0 || by > H) continue;
    let tag = tags[tagged];
    if (!tag) {
      tag = new Text({
        text: 'beacon',
        style: { fill: 0xffe066, fontSize: compact ? 14 : 12, fontWeight: '600', fontFamily: 'system-ui, sans-serif' },
      });
      tag.anchor.set(0.5, 0);
      tags.push(tag);
      app.stage.addChild(tag);
    }
    tag.visible = true;
    tag.text = missed[i] ? `${beaconName(i)} skipped: still counts` : `beacon ${beaconName(i)}`;
    tag.style.fill = missed[i] ? 0xff9e8a : 0xffe066;
    // Under its beacon, kept clear of the depth gauge (which would cut a tag under it to "beac"); off
    // the headlight's cone where it shows (a tag on the lit water reads as part of the beam): over
    // the lamp, else under or over the ring.
    const tx = Math.max(tag.width / 2 + 4, Math.min(W - GAUGE_WIDTH - tag.width / 2 - 4, bx)),
      lamp = Math.max(11, 3 * k);
    const lit = (y: number) =>
      hyw < -HEADLIGHT.fromDepth && boxInBeam([tx - tag!.width / 2, y, tag!.width, tag!.height], [hxw, hyw, c.Angle.value[e]!], sx, sy, k);
    // Nor across the ring's line: a tag pushed in from the edge beside a beacon there would be cut by it.
    const ring = BEACON_CATCH * k;
    const onRing = (y: number) => {
      const x0 = tx - tag!.width / 2,
        x1 = tx + tag!.width / 2,
        y1 = y + tag!.height;
      const near = Math.hypot(Math.max(x0 - bx, 0, bx - x1), Math.max(y - by, 0, by - y1));
      const far = Math.hypot(Math.max(Math.abs(x0 - bx), Math.abs(x1 - bx)), Math.max(Math.abs(y - by), Math.abs(y1 - by)));
      return near < ring + 2 && far > ring - 2;
    };
    const spots = [by + lamp, by - lamp - tag.height, by + Math.max(lamp, ring) + 4, by - Math.max(lamp, ring) - 4 - tag.height];
    tag.position.set(tx, spots.find((y) => !lit(y) && !onRing(y)) ?? spots.find((y) => !lit(y)) ?? spots[0]!);
    tagged++;
  }
  for (let i = tagged; i < tags.length; i++) tags[i]!.visible = false;
  otherTags = tagged;
  // Collected beacons: a flash, two rings expanding from the beacon and rays, fading over
  // PICKUP_LIFE s of game time; the banner shows the newest one.
  for (let i = pickups.length - 1; i >= 0; i--) if (shownAge(pickups[i]!, t) > PICKUP_LIFE || t < pickups[i]!.time) pickups.splice(i, 1);
  for (const p of pickups) {
    if (p.passed) continue;
    const u = shownAge(p, t) / PICKUP_LIFE,
      px = sx(p.x),
      py = sy(p.y),
      fade = 1 - u;
    if (u < 0.25) g.circle(px, py, (1.2 + 8 * u) * k).fill({ color: 0xfff6c0, alpha: 0.7 * (1 - u / 0.25) });
    for (const lag of [0, 0.18]) {
      const v = u - lag;
      if (v > 0) g.circle(px, py, (1.5 + 16 * Math.sqrt(v)) * k).stroke({ color: 0xffe066, alpha: 0.8 * (1 - v), width: 3 * (1 - v) + 1 });
    }
    for (let r = 0; r < 10; r++) {
      const ang = (r / 10) * 2 * Math.PI + 0.3,
        r0 = (2 + 10 * u) * k,
        r1 = r0 + 2.5 * k * fade;
      g.moveTo(px + r0 * Math.cos(ang), py + r0 * Math.sin(ang))
        .lineTo(px + r1 * Math.cos(ang), py + r1 * Math.sin(ang))
        .stroke({ color: 0xfff6c0, alpha: 0.9 * fade, width: 2 });
    }
  }
  const newest = pickups[pickups.length - 1];
  // The end card takes over from the banner once the run is over.
  // Hidden while paused: the pause overlay's words are the only ones in the middle then.
  banner.visible = newest !== undefined && !state.over && !shell.paused;
  if (newest) {
    const u = shownAge(newest, t) / PICKUP_LIFE;
    banner.text = newest.text;
    // A missed beacon's banner in the hits' red-orange, a collected one's in the beacons' yellow.
    banner.style.fill = newest.passed ? 0xff9e8a : 0xffe066;
    banner.x = W / 2;
    banner.y = 8 + banner.height / 2;
    banner.alpha = u < 0.7 ? 1 : (1 - u) / 0.3;
    banner.scale.set(u < 0.08 ? 0.6 + 0.4 * (u / 0.08) + 0.15 * Math.sin((Math.PI * u) / 0.08) : 1);
  }
  // The pointer: an arrow at the screen's edge leading to the target beacon (./beacons.ts: held until
  // it is collected) while it is off screen, with its distance and depth.
  placeMineTag(k, sx(hxw), sy(hyw), W, H);
  // Once the run is over the end card says where it ended: no target is led to (its label would run
  // under the card).
  pointer.visible = aim.index >= 0 && !state.over;
  if (pointer.visible) {
    const wx = handles.beacons[2 * aim.index]!,
      wy = handles.beacons[2 * aim.index + 1]!;
    const best = Math.hypot(wx - hxw, wy - hyw);
    const bx = sx(wx),
      by = sy(wy);
    const m = 40;
    aim.distance = best;
    // Only a ridge still to climb: not one far under the keel, nor one the boat is going away from.
    const ridge = ridgeInWay(hxw, hyw, wx, wy, (x) => seabedHeight(handles.seabed, x), hyw - SUBMARINE.height / 2, c.Velocity.x[e]!);
    aim.crest = [Number.NaN, Number.NaN];
    const onWay = mineOnWay(hxw, hyw, wx, wy, mines, mineLive);
    wayMine = onWay ? onWay.index : -1;
    // A mine on the way is ringed where it is, and a mine on the boat's course is told by the hull
    // (drawMineWarning), where the player looks: the pointer at the screen's edge tells only the ridge.
    // "level ✓" for the depth while the boat is going to pass level with the target and the hull is
    // already within its band; further off, the metres still to go.
    const level = aimLevel.side === 0 && Math.abs(wy - hyw) <= LEVEL_BAND;
    pointer.text = beaconLabel(wx - hxw, wy - hyw, ridge, '', beaconName(aim.index), level);
    // Heading for the finish with beacons skipped: collecting it ends the run, so the label says
    // which are still to fetch (backing to them first keeps every beacon in reach).
    const behind = taken.flatMap((t, i) => (t || i === aim.index ? [] : [beaconName(i)]));
    // A skipped beacon backed to: it still counts.
    if (missed[aim.index]) pointer.text += `\nskipped: still counts, ${ASTERN_BACK}`;
    if (aim.index === lastBeacon(handles.beacons) && behind.length > 0)
      pointer.text += `\n⚠ finish ends the run: ${behind.join(', ')} left behind`;
    // Coming in fast with the target near ahead and on the course (no ridge line to show): the brake hint as the
    // label's second line, each time it starts until it has come on BRAKE_HINT_MAX times.
    const ca = Math.cos(c.Angle.value[e]!),
      sa = Math.sin(c.Angle.value[e]!);
    const along = (wx - hxw) * ca + (wy - hyw) * sa,
      vAlong = c.Velocity.x[e]! * ca + c.Velocity.y[e]! * sa;
    const vx = c.Velocity.x[e]!,
      vy = c.Velocity.y[e]!,
      speed = Math.hypot(vx, vy);
    // How far the target lies off the course: the distance from it to the velocity's line.
    const offCourse = speed > 0 ? Math.abs((wx - hxw) * vy - (wy - hyw) * vx) / speed : Number.POSITIVE_INFINITY;
    // The words from the glide the boat would make if let go now: while the screw drives, when to let
    // go; gliding already, only a glide that would carry past the beacon is told (Astern).
    const words = letGoHint(
      Math.max(0, along),
      coastDistance(c.Mass.value[e]!, Math.max(0, vAlong), state.throttle, world.dt),
      Math.abs(wx - hxw),
    );
    // The hint is level 1's lesson only: later levels leave the judging of the glide to the pilot
    // (and their currents carry a boat let go on, ./current.ts).
    const fast =
      params.level === 1 &&
      !ridge &&
      !state.over &&
      along > 0 &&
      along < BRAKE_HINT_RANGE &&
      vAlong > BRAKE_HINT_SPEED &&
      offCourse < BRAKE_HINT_COURSE &&
      (state.throttle > 0 || words.startsWith('Astern'));
    if (!fast) brakeHint.on = false;
    else if (!brakeHint.on && brakeHint.shown < BRAKE_HINT_MAX) {
      brakeHint.on = true;
      brakeHint.shown++;
    }
    if (brakeHint.on) pointer.text += `\n${words}`;
    // Moving away from the target left behind: how far on it counts as missed, with a low call once.
    const left = state.over ? Number.NaN : missWarning(handles.beacons, aim.index, hxw, goingX());
    if (!Number.isNaN(left)) {
      pointer.text += `\n${missWarningText(left)}`;
      if (missWarned !== aim.index) sound.chime(392, 0.2);
    }
    missWarned = Number.isNaN(left) ? -1 : aim.index;
    aim.missWarn = !Number.isNaN(left);
    aim.dx = wx - hxw;
    aim.dy = wy - hyw;
    // The right margin leaves the depth gauge clear too (on a phone the badge would sit over it). A beacon
    // whose lamp is in view (ON_SCREEN_MARGIN inside the edges, 6 px from the gauge) counts as on screen:
    // with the badge's margin, on a phone the badge would be drawn over the very beacon it points to.
    const right = W - GAUGE_WIDTH - m;
    const inside = ON_SCREEN_MARGIN;
    // At the right, a lamp up to the gauge's edge is in view (on a phone at the start beacon A can lie
    // a few px inside the gauge, and a badge pointing to it would be drawn over it).
    aim.onScreen = bx >= inside && bx <= W - GAUGE_WIDTH - 6 && by >= inside && by <= H - inside;
    // From the hull's place on screen toward the beacon, stopped at the margin.
    const hx = sx(hxw),
      hy = sy(hyw);
    let px = bx,
      py = by;
    if (!aim.onScreen) {
      const dx = bx - hx,
        dy = by - hy;
      const t = Math.min(
        dx > 0 ? (right - hx) / dx : dx < 0 ? (m - hx) / dx : Infinity,
        dy > 0 ? (H - m - hy) / dy : dy < 0 ? (m - hy) / dy : Infinity,
      );
      px = hx + dx * t;
      py = hy + dy * t;
      // Slid along its edge off any live mine in view (a badge drawn over a mine hid it): away from
      // the mine, by the badge's half size (30 px) plus the mine's halo and 4 px.
      const side = px >= right - 1 || px <= m + 1;
      for (let i = 0; i < mines.length; i++) {
        if (!mineLive[i]) continue;
        const mx = sx(mines[i]!.x),
          my = sy(mines[i]!.y),
          clear = 30 + Math.max(12, 1.9 * MINE_RADIUS * k) + 4;
        if (Math.abs(mx - px) >= clear || Math.abs(my - py) >= clear) continue;
        // The way off it that stays inside the view (the other way when that one leaves it).
        if (side) {
          const to = my + (py >= my ? clear : -clear);
          py = to >= m && to <= H - m ? to : my + (py >= my ? -clear : clear);
        } else {
          const to = mx + (px >= mx ? clear : -clear);
          px = to >= m && to <= right ? to : mx + (px >= mx ? -clear : clear);
        }
      }
      const ang = Math.atan2(dy, dx),
        ca = Math.cos(ang),
        sa = Math.sin(ang);
      aim.angle = ang;
      // A badge: a dark disc ringed in the beacons' yellow, drawn out to a point toward the beacon,
      // with a long arrow (shaft and head) in it: a short broad triangle read as pointing either way.
      const along = (u: number, v: number): [number, number] => [px + u * ca - v * sa, py + u * sa + v * ca];
      const corners = [along(28, 0), along(10, 15), along(-14, 14), along(-20, 0), along(-14, -14), along(10, -15)];
      const xs = corners.map((p) => p[0]),
        ys = corners.map((p) => p[1]);
      aim.badge = [Math.min(...xs), Math.min(...ys), Math.max(...xs) - Math.min(...xs), Math.max(...ys) - Math.min(...ys)];
      aim.gaugeLeft = W - GAUGE_WIDTH;
      g.poly([...along(28, 0), ...along(10, 15), ...along(-14, 14), ...along(-20, 0), ...along(-14, -14), ...along(10, -15)])
        .fill({ color: 0x06213a, alpha: 0.9 })
        .stroke({ color: 0xffe066, width: 2 });
      g.poly([
        ...along(-12, -2.5),
        ...along(4, -2.5),
        ...along(4, -8),
        ...along(19, 0),
        ...along(4, 8),
        ...along(4, 2.5),
        ...along(-12, 2.5),
      ]).fill(0xffe066);
      // The label on the badge's far side from the beacon, clear of it.
      pointer.x = px - (pointer.width / 2 + 30) * ca;
      pointer.y = py - (pointer.height / 2 + 28) * sa;
    } else {
      aim.angle = Number.NaN;
      aim.badge = [0, 0, 0, 0];
      // Above the catch disc's rim and the target's brackets (drawn at least 14 px and up to 9 px
      // more out from the beacon), so the label covers neither.
      pointer.x = bx;
      pointer.y = by - Math.max(14, BEACON_CATCH * k) - 12 - pointer.height / 2 - 4;
      // A beacon near the view's top: under the ring instead (above, the label ran off the top,
      // under the status bar).
      if (pointer.y - pointer.height / 2 - 2 < LABEL_TOP) pointer.y = by + Math.max(14, BEACON_CATCH * k) + 12 + pointer.height / 2 + 4;
    }
    // Kept inside the view (a long label beside a badge at a side edge).
    // (its pill is 7 px wider each side than the text and the switch's ring 3 px more; 5 px more
    // keep it off the depth gauge).
    pointer.x = Math.max(pointer.width / 2 + 15, Math.min(W - GAUGE_WIDTH - pointer.width / 2 - 15, pointer.x));
    // Pushed in from the edge, a long label (on a phone) runs into its badge: then it goes just
    // under the badge, or over it where under leaves the view.
    if (!aim.onScreen) {
      const [, bTop = 0, , bH = 0] = aim.badge;
      const pill = [pointer.x - pointer.width / 2 - 7, pointer.y - pointer.height / 2 - 2, pointer.width + 14, pointer.height + 4];
      if (overlaps(pill, aim.badge, 2)) {
        const under = bTop + bH + pointer.height / 2 + 6;
        pointer.y = under + pointer.height / 2 + 4 <= H ? under : bTop - pointer.height / 2 - 6;
      }
    }
    // Kept off the hull: a label that would cross the hull's box (its sail and a margin included)
    // moves above or below it, whichever is nearer and inside the view.
    const hr = Math.max(SUBMARINE.length / 2, SUBMARINE.height / 2 + 2) * k + 6,
      hx0 = sx(hxw),
      hy0 = sy(hyw);
    const onHull = () => Math.abs(pointer.x - hx0) < hr + pointer.width / 2 + 7 && Math.abs(pointer.y - hy0) < hr + pointer.height / 2 + 2;
    // Under the beacon first (the label stays with it), else above or below the hull.
    if (onHull() && aim.onScreen) pointer.y = by + Math.max(14, BEACON_CATCH * k) + 12 + pointer.height / 2 + 4;
    if (onHull()) {
      const above = hy0 - hr - pointer.height / 2 - 4,
        below = hy0 + hr + pointer.height / 2 + 4;
      pointer.y = (pointer.y < hy0 && above > pointer.height) || below > H - pointer.height ? above : below;
    }
    // Clear of the headlight's cone (boat-drawing.ts), where it shows: a label across it (a beacon's
    // label over the lit water ahead of the bow) moves up or down, away from the cone's axis, until
    // none of its points is in the cone.
    aim.beam = false;
    const offBeam = () => {
      if (hyw >= -HEADLIGHT.fromDepth) return;
      const ha = c.Angle.value[e]!;
      // The label's pill: its text and 7 px, 2 px of padding round it.
      const lit = () =>
        boxInBeam(
          [pointer.x - pointer.width / 2 - 7, pointer.y - pointer.height / 2 - 2, pointer.width + 14, pointer.height + 4],
          [hxw, hyw, ha],
          sx,
          sy,
          k,
        );
      if (lit()) {
        aim.beam = true;
        // Up if the label is above the axis where it is, else down; the other way if it would leave the view.
        const axisY = hy0 - (pointer.x - hx0) * Math.tan(ha);
        let dir = pointer.y < axisY ? -1 : 1;
        const start = pointer.y;
        for (let n = 0; n < 60 && lit(); n++) pointer.y += dir * 4;
        if (pointer.y < pointer.height || pointer.y > H - pointer.height) {
          dir = -dir;
          pointer.y = start;
          for (let n = 0; n < 60 && lit(); n++) pointer.y += dir * 4;
        }
      }
    };
    offBeam();
    // Clear of the live mines in view: a label across one (on a phone the label of a beacon behind
    // spans most of the width at the boat's depth, over the mines ahead) moves past it, away from the hull.
    const offMines = () => {
      for (let i = 0; i < mines.length; i++) {
        if (!mineLive[i]) continue;
        const mx = sx(mines[i]!.x),
          my = sy(mines[i]!.y),
          r = MINE_RADIUS * k + 6;
        if (Math.abs(pointer.x - mx) < pointer.width / 2 + 7 + r && Math.abs(pointer.y - my) < pointer.height / 2 + 2 + r) {
          const below = my + r + pointer.height / 2 + 4,
            above = my - r - pointer.height / 2 - 4;
          pointer.y = (my > hy0 && below < H - pointer.height) || above < pointer.height ? below : above;
        }
      }
    };
    offMines();
    // Clear of the mine warning's tag by the hull too (placeMineTag): moved on past it, away from the hull.
    const [tx, ty, tw, th] = mineWarning.box as [number, number, number, number];
    if (
      mineWarning.text &&
      Math.abs(pointer.x - (tx + tw / 2)) < (pointer.width + 14 + tw) / 2 + 2 &&
      Math.abs(pointer.y - (ty + th / 2)) < (pointer.height + 4 + th) / 2 + 2
    )
      pointer.y = pointer.y < ty + th / 2 ? ty - pointer.height / 2 - 6 : ty + th + pointer.height / 2 + 6;
    // Never over the target's ring and brackets (moved off the hull, the beam or a mine onto it):
    // beside it instead, right of it where that stays in view, else left, else over or under it.
    const ringCrossed = () =>
      aim.onScreen &&
      overlaps(
        [pointer.x - pointer.width / 2 - 7, pointer.y - pointer.height / 2 - 2, pointer.width + 14, pointer.height + 4],
        aim.frame,
        2,
      );
    // Off a mine and the ring in turn, a few times: moved off one, the label may land on the other.
    for (let n = 0; n < 3 && ringCrossed(); n++) {
      const half = aim.frame[2]! / 2,
        rightX = bx + half + pointer.width / 2 + 12;
      const leftX = bx - half - pointer.width / 2 - 12;
      pointer.y = by;
      if (rightX + pointer.width / 2 + 15 <= W - GAUGE_WIDTH) pointer.x = rightX;
      else if (leftX - pointer.width / 2 - 7 >= 0) pointer.x = leftX;
      else {
        // Neither side fits (a phone): over the brackets, or under them where over leaves the view.
        const over = aim.frame[1]! - pointer.height / 2 - 6;
        pointer.y = over - pointer.height / 2 - 2 >= LABEL_TOP ? over : aim.frame[1]! + aim.frame[3]! + pointer.height / 2 + 6;
      }
      offMines();
      // Beside the ring it may lie in the headlight's tip: moved up or down off it (clear of the ring beside it).
      offBeam();
    }
    // Never on the seabed (under a beacon near the bed the moves above put it on the rock, dark on
    // dark): lifted in 4 px steps until its pill clears the bed under it by LABEL_BED_CLEAR px and
    // crosses neither the hull, the target's frame, the headlight's cone nor a live mine.
    liftOffSeabed(
      W,
      H,
      cx,
      k,
      sx,
      sy,
      [hx0 - hr, hy0 - hr, 2 * hr, 2 * hr],
      hyw < -HEADLIGHT.fromDepth ? [hxw, hyw, c.Angle.value[e]!] : null,
    );
    // Last, never over the mine or ridge warning's tag (the moves off the ring and the bed may have put
    // it back there): above the tag, or below it where above leaves the view.
    const labelPill = [pointer.x - pointer.width / 2 - 7, pointer.y - pointer.height / 2 - 2, pointer.width + 14, pointer.height + 4];
    if (mineWarning.text && overlaps(labelPill, mineWarning.box, 4)) {
      const [, ty, , th] = mineWarning.box as [number, number, number, number];
      const above = ty - pointer.height / 2 - 8;
      pointer.y = above >= pointer.height / 2 + 4 ? above : ty + th + pointer.height / 2 + 8;
    }
    // Whatever moved it, its pill stays inside the view (LABEL_TOP px under the top).
    pointer.y = Math.min(H - pointer.height / 2 - 4, Math.max(LABEL_TOP + pointer.height / 2 + 2, pointer.y));
    pointer.x = Math.max(pointer.width / 2 + 8, Math.min(W - pointer.width / 2 - 8, pointer.x));
    aim.label = [pointer.x - pointer.width / 2, pointer.y - pointer.height / 2, pointer.width, pointer.height];
    aim.hull = [hx0 - hr, hy0 - hr, 2 * hr, 2 * hr];
    // The pickup banner ("Beacon 3 of 6") off the label's pill (on a phone it would be drawn over it):
    // moved just above the pill, or below it where above leaves the view.
    if (banner.visible) {
      const pill = [pointer.x - pointer.width / 2 - 7, pointer.y - pointer.height / 2 - 2, pointer.width + 14, pointer.height + 4];
      const bb = [banner.x - banner.width / 2, banner.y - banner.height / 2, banner.width, banner.height];
      if (overlaps(bb, pill, 4)) {
        const above = pill[1]! - banner.height / 2 - 6;
        banner.y = above >= banner.height / 2 + 4 ? above : pill[1]! + pill[3]! + banner.height / 2 + 6;
      }
    }
    // The label on a dark pill, readable over the bright surface water and the sky.
    const pw = pointer.width + 14,
      ph = pointer.height + 4;
    const radius = Math.min(ph / 2, 12);
    g.roundRect(pointer.x - pw / 2, pointer.y - ph / 2, pw, ph, radius).fill({ color: 0x06213a, alpha: 0.85 });
    // A ridge in the way: the warning's line (the label's second) on an orange band, and the crest
    // marked on the seabed (drawRidgeCrest), so the warning is seen, not only read.
    if (ridge) {
      g.roundRect(pointer.x - pw / 2, pointer.y, pw, ph / 2, radius).fill({ color: 0xb8430f, alpha: 0.95 });
      drawRidgeCrest(hxw, wx, sx, sy, t);
    }
    aim.ridge = ridge;
    // Just switched to another beacon: the pill blinks a yellow ring for AIM_PULSE s, so the new
    // name and distance are noticed, not read as "52 m ahead" becoming "157 m ahead" unexplained.
    const since = t - aimSwitchedAt;
    if (since >= 0 && since < AIM_PULSE)
      g.roundRect(pointer.x - pw / 2 - 3, pointer.y - ph / 2 - 3, pw + 6, ph + 6, ph / 2 + 3).stroke({
        color: 0xffe066,
        width: 3,
        alpha: (1 - since / AIM_PULSE) * (0.6 + 0.4 * Math.cos(4 * Math.PI * since)),
      });
  }
  drawLevelGuide(sx, sy, W, hxw);
  // The boat (./boat-drawing.ts), turned by the hull's angle; the screw's blades turn with the throttle.
  const a = c.Angle.value[e]!,
    co = Math.cos(a),
    s = Math.sin(a);
  const Hh = SUBMARINE.height / 2;
  const pt = (u: number, v: number): [number, number] => [sx(hxw + u * co - v * s), sy(hyw + u * s + v * co)];
  const B = c.Ballast;
  screwPhase += state.throttle * 0.5;
  drawBoat(g, {
    length: SUBMARINE.length,
    height: SUBMARINE.height,
    pt,
    scale: k,
    angle: a,
    tanks: [B.fore[e]!, B.aft[e]!],
    tankArm: SUBMARINE.tankArm,
    screwPhase,
    throttle: state.throttle,
    depth: -hyw,
    touching: state.touching,
    planes: state.planes,
  });
  // The vertical thrusters' wash: water thrown opposite to each one's push, as long as it is strong.
  const n = SUBMARINE.thrusterForce;
  for (const [u, f] of [
    [SUBMARINE.thrusterArm, state.fore],
    [-SUBMARINE.thrusterArm, state.aft],
  ] as const) {
    if (Math.abs(f) < 0.05 * n) continue;
    const dir = -Math.sign(f),
      len = 1.2 + 3 * (Math.abs(f) / n);
    const v0 = dir * Hh,
      v1 = dir * (Hh + len);
    g.poly([pt(u - 0.45, v0), pt(u + 0.45, v0), pt(u + 0.9, v1), pt(u - 0.9, v1)].flat()).fill({
      color: 0xd8f0ff,
      alpha: 0.25 + 0.35 * (Math.abs(f) / n),
    });
  }
  // The depth ordered (./helm.ts): a dashed line across the hull's place, where the boat is going
  // and will stop, while it is more than 0.3 m from there.
  if (Number.isFinite(state.holdY) && Math.abs(state.holdY - hyw) > 0.3) {
    const yo = sy(state.holdY);
    for (let u = -SUBMARINE.length; u < SUBMARINE.length; u += 2.4) {
      g.moveTo(sx(hxw + u), yo)
        .lineTo(sx(hxw + u + 1.4), yo)
        .stroke({ color: 0x7fe3ff, width: 2, alpha: 0.85 });
    }
    // Chevrons from the hull toward it.
    const dir = Math.sign(state.holdY - hyw),
      cxh = sx(hxw + SUBMARINE.length / 2 + 2.5);
    for (let j = 0; j < 2; j++) {
      const yc = sy(hyw + dir * (1 + 1.2 * j));
      g.moveTo(cxh - 5, yc + 4 * dir)
        .lineTo(cxh, yc - 2 * dir)
        .lineTo(cxh + 5, yc + 4 * dir)
        .stroke({ color: 0x7fe3ff, width: 2, alpha: 0.6 - 0.2 * j });
    }
  }
  drawDepthLadder(t, sx, sy, hxw, hyw);
  drawMineWarning(t, k, sx, sy, hxw, hyw);
  spawnBubbles(world, a);
  for (const b of bubbles) {
    const life = 1 - b.age / b.life;
    g.circle(sx(b.x), sy(b.y), Math.max(1.5, b.r * k)).stroke({ color: 0xe8f6ff, alpha: 0.7 * life, width: 1.2 });
  }
  // Gauges.
  const depth = -c.Position.y[e]!;
  const floor = seabedHeight(handles.seabed, cx);
  engine.set(state.over ? 0 : Math.abs(state.throttle));
  targetName = aim.index >= 0 ? beaconName(aim.index) : '';
  drawDepthGauge(
    W,
    H,
    depth,
    -state.holdY,
    -seabedHeight(handles.seabed, hxw),
    aim.index >= 0 ? -handles.beacons[2 * aim.index + 1]! : Number.NaN,
  );
  drawEdgeMarks(W, H, k, cx, sy, hxw, hyw, c.Velocity.x[e]!);
  drawHits(t, k, sx, sy, W, H, sy(hyw) - (Hh + 2.5) * k);
  // The hull's box on the screen (level, its sail included): the tags that only add are kept off it.
  const hr = Math.max(SUBMARINE.length / 2, SUBMARINE.height / 2 + 2) * k;
  declutter(H, [sx(hxw) - (SUBMARINE.length / 2) * k, sy(hyw) - hr / 2, SUBMARINE.length * k, hr]);
  backOverSeabed(W, cx, k, sy);
  drawHitPill();
  drawPause(W, H, sy(hyw));
  // The hull gauge at a hit: red and enlarged, fading over GAUGE_FLASH s of game time.
  const hitAge = hitMarks.length > 0 ? shownAge(hitMarks[hitMarks.length - 1]!, t) : Number.POSITIVE_INFINITY;
  const flashNow = hitAge >= 0 && hitAge < GAUGE_FLASH ? 1 - hitAge / GAUGE_FLASH : 0;
  if (flashNow > 0 || gaugeFlash > 0) {
    gaugeFlash = flashNow;
    if (hullGauge.dataset.hits !== String(state.hits)) {
      hullGauge.dataset.hits = String(state.hits);
      showHull();
    }
    hullGauge.style.background = flashNow > 0 ? `rgba(255, 59, 48, ${(0.9 * flashNow).toFixed(3)})` : '';
    hullGauge.style.transform = flashNow > 0 ? `scale(${(1 + 0.3 * flashNow ** 2).toFixed(3)})` : '';
  }
  if (gaugeFrame++ % 6 !== 0) return;
  const end =
    state.over === 'won'
      ? state.collected === taken.length
        ? `All ${taken.length} beacons in ${clock(state.time)}!`
        : `Finish · ${state.collected}/${taken.length} in ${clock(state.time)}`
      : state.over === 'sunk'
        ? `Hull breached · ${state.collected}/${taken.length}`
        : '';
  showEnd();
  const helm = helmWord(state.mode, state.holdY, state.diveStopped);
  // A held Dive the seabed stops is said on the readout too, where the eye is.
  const stopped = state.diveStopped ? ` · ${DIVE_STOPPED_WORD}` : '';
  // The depth, and the depth ordered while the boat is a metre or more from it ("depth 30 → 34 m").
  const ordered = Number.isFinite(state.holdY) && Math.abs(state.holdY + depth) >= 1 ? ` → ${(-state.holdY).toFixed(0)}` : '';
  const streak = state.streak > 1 ? ` ×${Math.min(GLOW_STREAK_MAX, state.streak)}` : '';
  // One short line: the level ("L2"), the beacons (◯, as in the controls list), the clock and par ("0:42 · par 2:20", on a phone "◯ 2/6 0:42 par 2:20", par in lighter type; red once past par), the depth
  // (and the depth ordered), the speed ahead or astern, the score and the hull. The depth's rate,
  // the tanks, pitch and helm go in the desktop's info column (the depth gauge shows the order);
  // on a phone it keeps to 390 px: the speed as a mark ("▶4") after the depth ("82→87 m ▶4"), the
  // score without "pts", no skipped names, "stopped by the seabed" shortened; the goal and the readout a line each, in 14 px type.
  const missedNames = missed.flatMap((m, i) => (m ? [beaconName(i)] : []));
  const missedText = missedNames.length > 0 && !compact ? ` (${missedNames.join(', ')} skipped)` : '';
  const goalWords =
    end ||
    `L${params.level}${compact ? '' : ' ·'} ◯ ${state.collected}/${taken.length}${missedText}${compact ? ' ' : ' · '}${clock(state.time)}`;
  const parWords = end ? '' : `${compact ? '' : ' ·'} par ${clock(state.par)}`;
  if (goalText.textContent !== goalWords) goalText.textContent = goalWords;
  if (goalPar.textContent !== parWords) goalPar.textContent = parWords;
  // The clock turns red once par has passed (it keeps counting: par is a target, not a limit).
  goal.style.color = !state.over && state.time > state.par ? '#ff9e8a' : '#ffe066';
  // The speed is over the ground (the hull's own velocity); the water's, where it flows, beside it
  // ("current ◀2.4 m/s", as the current's note tells it), so a boat held back by the current is seen to be, not only felt.
  const water = currentMark(currentAt(params.level, c.Position.y[e]!));
  // The nose trim (./helm.ts noseTrim) while set: which way and how far, so every Nose tap shows.
  const nose = Math.round((trim * 180) / Math.PI);
  const noseMark = nose === 0 ? '' : `${nose < 0 ? '↘' : '↗'}${Math.abs(nose)}°`;
  readoutText.textContent = compact
    ? `${Math.max(0, depth).toFixed(0)}${ordered.replace(/ /g, '')} m ${speedMark(c.Velocity.x[e]!)}${noseMark ? ` ${noseMark}` : ''}${water ? ` ${water.replace('current ', '≋')}` : ''}${stopped ? ' · seabed' : ''} · ${state.score} · `
    : `${Math.max(0, depth).toFixed(0)}${ordered} m${stopped} · ${speedWords(c.Velocity.x[e]!)}${water ? ` over ground, ${water}` : ''}${noseMark ? ` · nose ${noseMark}` : ''} · ${state.score} pts${streak} · `;
  showHull();
  seabedLine.textContent = `seabed ${(-floor).toFixed(0)} m`;
  physicsText.textContent = [
    `climb ${c.Velocity.y[e]!.toFixed(1)} m/s`,
    `pitch ${((a * 180) / Math.PI).toFixed(0)}°`,
    `screw ${(state.throttle * 100).toFixed(0)}%`,
    `tanks ${(B.fore[e]! * 100).toFixed(0)}/${(B.aft[e]! * 100).toFixed(0)}% (neutral ${(SUBMARINE_NEUTRAL_FILL * 100).toFixed(0)}%)`,
    `helm: ${helm}`,
  ].join('\n');
}

/**
 * The boat's speed along x for the phone's status line, signed by an arrow: "▶4" ahead, "◀2" astern
 * (m/s; a tenth under 1 m/s), "■" under 0.2 m/s. `vx`: m/s, positive ahead.
 */
function speedMark(vx: number): string {
  const v = Math.abs(vx);
  if (v < 0.2) return '■';
  return `${vx > 0 ? '▶' : '◀'}${v < 1 ? v.toFixed(1) : v.toFixed(0)}`;
}

/**
 * The boat's speed along x for the status line, signed by its words: "ahead 6 m/s", "astern 2 m/s"
 * (a tenth of a m/s under 1 m/s), "stopped" under 0.2 m/s. `vx`: m/s, positive ahead.
 */
function speedWords(vx: number): string {
  const v = Math.abs(vx);
  if (v < 0.2) return 'stopped';
  return `${vx > 0 ? 'ahead' : 'astern'} ${v < 1 ? v.toFixed(1) : v.toFixed(0)} m/s`;
}

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'level', min: 1, max: LEVELS.length, step: 1, onChange: () => shell.reset() },
    { type: 'slider', key: 'beacons', min: 1, max: MAX_BEACONS, step: 1, onChange: () => shell.reset() },
    { type: 'slider', key: 'waveHeight', label: 'wave height (m)', min: 0, max: 3, step: 0.1 },
    { type: 'slider', key: 'pixelsPerMeter', label: 'zoom (px/m)', min: 2, max: 20, step: 0.5 },
    { type: 'slider', key: 'seed', min: 0, max: 1000, step: 1, onChange: () => shell.reset() },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Submarine' },
);

shell.expose({
  /** The beacon pointer: the beacon it leads to (-1: none), distance (m), offset (m), arrow angle, whether it is on screen, its label text and how many times the brake hint came on. */
  beaconPointer: () => ({ ...aim, visible: pointer.visible, text: pointer.text, zoom, otherTags, brakeHints: brakeHint.shown }),
  /** The first-time hint of the glows' worth: its words and whether it shows. */
  glowHint: () => ({ text: glowNote.textContent ?? '', visible: glowNote.style.display !== 'none' }),
  /**
   * The target's depth by the boat as last drawn (./level-stop.ts): the line's place (px), whether the
   * boat is going to pass level with it (0), over (1) or under (-1) it, and whether the stop at its
   * depth holds a Dive or Rise now.
   */
  levelGuide: () => ({ ...levelGuide, side: aimLevel.side, stopping: !Number.isNaN(levelHold.since) && !levelHold.done }),
  /** The depth ladder by the boat as last drawn: its opacity in [0, 1] and the figures shown ("30 m"). */
  depthLadder: () => ({ alpha: ladder.alpha, marks: ladderMarks.filter((m) => m.visible).map((m) => m.text) }),
  /** The words over the scene as last drawn, kept off each other: each shown one's name and box (x, y, width, height, px). */
  labels: () => shownLabels.map((l) => ({ name: l.name, box: [...l.box] })),
  /** The names of the small words drawn on a backing pill over the seabed in the last frame (backOverSeabed). */
  labelBacks: () => [...backedLabels],
  /**
   * The depth gauge's tags as last drawn: the boat's depth and the target's, each x, y, width,
   * height, px (zeros while hidden), and their words ("you 31 m", "beacon A 27 m"; '' while hidden).
   */
  gaugeTags: () => ({
    depth: [...gauge_.depth],
    target: [...gauge_.target],
    depthText: gaugeDepth?.visible ? gaugeDepth.text : '',
    targetText: gaugeTarget?.visible ? gaugeTarget.text : '',
    /** The live mines in view: each one's halo box (x, y, width, height, px), which the tags keep off. */
    mines: mineBoxes.map((b) => [...b]),
    /** The depth ruler's left edge with its figures, px (the edge marks keep left of it). */
    rulerLeft: gauge_.rulerLeft,
  }),
  /** The words drawn on the scene now (the gauge's, the ladder's, the tags, the marks): each one's text and type size, CSS px. */
  sceneTexts: () =>
    app.stage.children.flatMap((t) =>
      t instanceof Text && t.visible && t.text !== '' ? [{ text: t.text, size: Number(t.style.fontSize) }] : [],
    ),
  /** The helm dial as last drawn (desktop): the knob's push (x ahead, y rise, in [-1, 1]), the screw's throttle and whether it is drawn. */
  helmDial: () => ({ ...helmShown }),
  /** The camera as last drawn: centre (x, y, m), zoom (px/m), look-ahead (m, before its limit) and shake (px). */
  camera: () => ({ ...camera }),
  /** The marks at the view's leading edge as last drawn (./edge-marks.ts): each hazard's kind, place (m), metres ahead of the bow, words and box (px). */
  edgeMarks: () => edgeShown.map((m) => ({ ...m, box: [...m.box] })),
  /**
   * The newest hit's signs: its cause ('' before any), place (m), the label shown ('' once faded)
   * and its screen box (x, y, width, height, px), its red pill's box (px, zeros while none), the
   * red tint over the whole view (its alpha, 0 once gone), and the hull gauge's text and running animations.
   */
  hitEffect: () => {
    const m = hitMarks[hitMarks.length - 1];
    return {
      kind: m?.kind ?? '',
      x: m?.x ?? Number.NaN,
      y: m?.y ?? Number.NaN,
      label: hitLabel.visible ? hitLabel.text : '',
      box: [hitLabel.x - hitLabel.width / 2, hitLabel.y - hitLabel.height / 2, hitLabel.width, hitLabel.height],
      pill: [...hitShown.pill],
      tint: hitShown.tint,
      shake: camera.shake,
      gauge: hullGauge.textContent ?? '',
      gaugeFlash,
    };
  },
  /** The collect effect: pickups still drawn (rings at the beacons) and the banner over the scene. */
  pickupEffect: () => ({ count: pickups.length, banner: banner.visible ? banner.text : '', alpha: banner.alpha }),
  params,
  panel,
  state,
  /** The hull entity. */
  hull: () => handles.hull,
  /** The glow trail: each glow's place (m), leg and state ('open', 'caught' or 'missed'). */
  glows: () => glows.map((gl, i) => ({ ...gl, state: (['open', 'caught', 'missed'] as const)[glowState[i]!]! })),
  /**
   * The mine on the boat's course (./mines.ts mineAhead: index, side to pass, seconds to contact; null
   * for none) and its warning by the hull as last drawn: words, tag box, arrow tip and tail (px).
   */
  mineAhead: () => (ahead ? { ...ahead, ...mineWarning } : null),
  /**
   * The seabed on the boat's course (./seabed.ts bedAhead: seconds to it, where, the bed's height,
   * whether a ridge; null for none, or while a mine is warned of) and its warning by the hull as last
   * drawn: words, tag box, arrow tip and tail (px).
   */
  bedAhead: () => (bedWarn ? { ...bedWarn, ...mineWarning } : null),
  /** The course's mines: centre (x, y, m), anchor height (m) and whether each is still live. */
  mines: () => mines.map((m, i) => ({ ...m, live: mineLive[i]! })),
  /** The scene's handles: hull, sea, seabed, beacons (x, y pairs, m) and vertical thrusters. */
  handles: () => handles,
  /** Sets the stick as the on-screen one does: x right (ahead), y up (rise), each clamped to [-1, 1]; (0, 0) lets it go (no finger on it). */
  setStick: (x: number, y: number): void => {
    stickInput.x = Math.max(-1, Math.min(1, x));
    stickInput.y = Math.max(-1, Math.min(1, y));
    stickInput.held = x !== 0 || y !== 0;
    timeControls(performance.now());
  },
  /** Whether the pause overlay shows, its words and its band's box (x, y, width, height, px; zeros while hidden). */
  pauseOverlay: () => ({ visible: pause.visible, text: pause.text, band: [...pauseBandBox] }),
  /** The end card's text ('' while the run goes on). */
  endText: (): string => (endCard.style.display === 'none' ? '' : (endCard.textContent ?? '')),
  /** Sets the screw's throttle directly, in [-HELM.asternShare, 1] (the helm sets the tanks and thrusters each step). */
  setControls: (controls: { throttle?: number }): void => {
    if (controls.throttle !== undefined) state.throttle = Math.min(1, Math.max(-HELM.asternShare, controls.throttle));
  },
});
