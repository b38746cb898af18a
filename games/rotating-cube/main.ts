/**
 * Rotating cube: rigid-body rotation in 3D. By default (mode 'room') a 1 m cube falls tipped into a
 * room, square to the camera (so each roll key rolls it the way its arrow points), and collides with the floor and the walls (a box collider and 3D box contacts): it lands,
 * tumbles, slides and bounces off them. The challenge: rest it on five glowing pads in turn, the last
 * four with a given face on top and reached by a roll (a slide keeps the top face, so the player slides
 * to the side of the pad from which a roll brings that face up), each pad smaller than the one before;
 * stars by moves (★★★ in the round's par, scene.ts `padMovePar` per pad, plus PAR_SLACK[0] or fewer). A click or tap on the floor pushes the cube towards that point, just hard enough that
 * sliding on a face it stops there (`slideSpeed`); a click on the cube flicks it away from the point
 * clicked at a fixed speed (a finger: a drag from the cube flicks it the way the finger went, a plain
 * tap on it does nothing, controls.ts `touchPress`); W A S D roll it over its edges in the screen's directions and Q E turn it
 * (a couple of forces from `applyForceAtPoint` in a forces-stage system, which stops pushing once it
 * turns at ROLL_SPIN_MAX); Space makes it jump. A pad reached chimes, flashes and pops its number.
 * Arrows show its angular momentum L (`spinAngularMomentum`, yellow) and angular velocity w (magenta)
 * on the pivot (and in the room when ticked in the panel).
 *
 * Mode 'cube' takes gravity away and holds the cube at its centre of mass on a frictionless pivot:
 * it tumbles slowly in place, and with no torque L stays fixed while w moves whenever the body is not
 * spinning about a principal axis. Mode 'flip' spins a box with three distinct moments about its
 * intermediate axis on the pivot: it flips over again and again (the Dzhanibekov effect); the plot
 * shows w in the body frame. The challenge: 10 flips within 20 s with the spin in FLIP_BAND; the pivot's
 * drag (scene.ts FLIP_DRAG) slows it, so the player keeps it up with the yaw key (a tap adds about
 * 1 rad/s) while it flips; stars by the time taken (scene.ts FLIP_STAR_TIMES; none without the player's input).
 * Keys: room: W A S D roll the cube away, left, towards the viewer, right; Q E turn it a quarter about the
 * vertical; pivot: W/S, A/D, Q/E torque about the camera's up, right and viewing axes (free spin: W/S
 * push ω's tip up/down on screen, A/D left/right, Q/E toward/away; flip: about right, up, view). X stops the
 * spin; Space jump (room); M switches mode (room, cube on a pivot, flip); P pause, N single step, R reset.
 * Click: room: the floor, a push there; the cube, a flick away from the point; pivot: an impulse at the
 * point of the face clicked along the ray. Drag: orbit.
 * Challenges: room: rest the cube on five pads in turn, the last four rolled onto with a given face up,
 * the third and fourth across a bed of tiles a slide stops at, the last across a floor of them (no
 * slide stops anywhere: a route of rolls planned from the pad before; stars by moves against par:
 * roll-puzzle.ts); cube on the pivot: steer ω onto three target spins and hold each (spin-challenge.ts),
 * with guides (spin-look.ts): a ghost cube turning at the target spin, the gap from ω's tip to the
 * target's, the torque at ω's tip coloured by how it meets the gap, a ring filling over the hold and a
 * closeness meter in the status row; flip: 10 flips in 20 s, counted only while the spin is within FLIP_BAND.
 * A new round (page load, or Next at its end) lays the pads out afresh from a seed (scene.ts `padLayout`);
 * R (and Retry) plays the same pads again. The face net at the top left of the stage shows which colour
 * each roll key brings on top, the pads card at the top right each pad's colour to land with on top
 * (the rules behind its "?"), and the status row the fewest moves left from where the cube rests
 * (to-go.ts). The round's clock runs only while the cube is still (scene.ts `PadChallenge`). The lit
 * pad's rim lights while the cube's centre is near enough to count (scene.ts PAD_GRACE); resting there
 * with the wrong face up (or slid on) the pop says why it does not count. A round's end shows a banner
 * with the result, Next (Enter) and Retry (R) (game-kit's createDomResultCard, round-end.ts).
 * The scenery (room-look.ts): a plank floor in stone walls (those on the camera's side see-through), a
 * terrace with props, a skyline against a dusk sky, the lit pad's halo and beam; the pivot modes stand
 * on the same deck.
 * URL: ?mode=room|cube|flip (default room), ?spin=rad/s (flip), ?seed=N (the same pad layout every run).
 */

import {
  choiceParam,
  createButtonBar,
  createDomResultCard,
  createPanel,
  createStatusRow,
  forEachImpact,
  getSound,
  numberParam,
  pageLayout,
} from '@bitphysics/game-kit';
import type { Plot } from '@bitphysics/game-kit/plot';
import { isSoftwareWebGL, ORBIT_CONTROLS, startThreeGame } from '@bitphysics/game-kit/three';
import {
  addPlane,
  addSystem,
  applyImpulse,
  applyImpulseAtPoint,
  createPhysicsWorld,
  type PhysicsWorld,
  step as physicsStep,
  rayCastAll3D,
  rotateVectorInverse,
  spinAngularMomentum,
  spinKineticEnergy,
} from '@bitphysics/physics';
import { VectorArrow } from '@bitphysics/render-three';
import {
  BoxGeometry,
  CanvasTexture,
  CircleGeometry,
  Color,
  CylinderGeometry,
  DoubleSide,
  Float32BufferAttribute,
  Group,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  PlaneGeometry,
  RepeatWrapping,
  RingGeometry,
  SphereGeometry,
  SRGBColorSpace,
  Vector3,
} from 'three';
import { cubeControls, RollQueue, TAP_SLOP, touchPress } from './controls';
import { createHintMark } from './hint-mark';
import { bedSnap, edgeCells } from './roll-puzzle';
import { buildRoomLook } from './room-look';
import { type RoundEndContent, roundEnd, starText } from './round-end';
import { padResultText, roundMovesText } from './round-moves';
import {
  BUMP_SPIN,
  buildRotatingCube,
  CELL_REACH,
  cubeStill,
  FACES,
  FLIP_BAND,
  FLIP_GOAL,
  FLIP_PUSH,
  FLIP_STAR_TIMES,
  FLIP_TIME,
  FlipChallenge,
  flipSpin,
  JUMP_IMPULSE,
  MODES,
  type Mode,
  PAD_COUNT,
  PAD_GRACE,
  PAD_HALF,
  PAR_SLACK,
  PadChallenge,
  type PadLayout,
  padLayout,
  padMovePar,
  padMoveRoute,
  padPuzzle,
  padStars,
  ROLL_SPIN_MAX,
  ROLL_TORQUE,
  ROOM_FRICTION,
  ROOM_HALF,
  ROOM_PUSH,
  type RotatingCubeHandles,
  rollBlocked,
  rollSettle,
  rollStart,
  rotatingCubeWorldOptions,
  SLID_ON_MOVES,
  slideSpeed,
  topFace,
  torqueCouple,
  WALL_HALF_THICKNESS,
  WALL_HEIGHT,
  YawKeeper,
} from './scene';
import {
  closenessBar,
  SPIN_HOLD,
  SPIN_RATE,
  SPIN_STAR_TIMES,
  SPIN_TARGETS,
  SPIN_TOLERANCE,
  SpinChallenge,
  spinCloseness,
  spinTargets,
} from './spin-challenge';
import { SpinLook } from './spin-look';
import { ToGoMeter } from './to-go';

/** A mouse press that moves more than this, CSS px, is a camera drag, not a click (a finger: controls.ts TAP_SLOP). */
const CLICK_SLOP = 5;
/**
 * Room mode: how long a reached pad's pop ("Pad 2 of 5 ✓ · Perfect!") stays before it fades, ms: a
 * beat the player sees while already making the next move (the pop takes no input).
 */
const PAD_POP_MS = 2600;
/** Whether the pop has said this page visit that a quarter turn counts as a move (said on the first one). */
let turnSaid = false;
/** On the pivot: the height of the floor under it, m (the pivot's post stands on it; it catches the shadow). */
const PIVOT_FLOOR_Y = -1.6;
/** Length of the angular-velocity arrow at the starting spin (or at 1 rad/s if slower), m. */
const ARROW_LENGTH = 1.6;

const params = {
  mode: choiceParam('mode', MODES, 'room') as Mode,
  torque: 0.5,
  impulse: 0.3,
  spin: numberParam('spin', { default: 6, min: 0.5, max: 30 }),
  // The arrows explain the pivot modes; in the room they would cover the pads.
  showL: choiceParam('mode', MODES, 'room') !== 'room',
  showOmega: choiceParam('mode', MODES, 'room') !== 'room',
  // The debug layer: on the pivot the body's axes; in the room (contact points, red squares at the
  // cube's corners that read as a fault to a player) off until ticked in the panel.
  axes: choiceParam('mode', MODES, 'room') !== 'room',
  stop: () => stopSpin(),
  reset: () => game.shell.reset(),
};

let handles: RotatingCubeHandles;
/** ?seed=N: every run lays out the same pads; without it each run (load or R) draws a new seed. */
const fixedSeed = new URLSearchParams(location.search).has('seed') ? numberParam('seed', { default: 1, min: 0, max: 2 ** 31 }) : null;
/** The pads of this round (`padLayout` of a fresh seed for a new round; a retry, R, keeps them). */
let layout: PadLayout = padLayout(fixedSeed ?? Math.floor(Math.random() * 2 ** 31));
/** Whether the next world lays out a new round of pads (the page's first world and Next do; R retries the same pads). */
let freshLayout = true;
/** The moves left on the lit pad from where the cube rests, and whether the last move brought it closer (to-go.ts). */
const toGo = new ToGoMeter();
/** The pad `toGo` counts for (-1: none yet): a new pad lit starts its count afresh. */
let toGoPad = -1;
/** Room mode's challenge (the pads) and flip mode's (flips in FLIP_TIME); reset with the world. */
const pads = new PadChallenge(),
  flips = new FlipChallenge();
/** Free-spin mode's challenge: steer ω onto three target spins in turn (spin-challenge.ts); its targets set per world from the camera's axes. */
const spins = new SpinChallenge(spinTargets([1, 0, 0], [0, 1, 0]));
/** Targets reached and not yet celebrated (their indices). */
const spinsReached: number[] = [];
/** Best round of this page visit: fewest moves in a pad round, fastest free-spin round (s), and most flips. */
let bestSpinTime = Infinity;
let bestMoves = Infinity,
  bestFlips = 0,
  /** The fastest FLIP_GOAL flips of this visit, s (Infinity: none yet). */
  bestFlipTime = Infinity;
/** Arrow length per rad/s of angular velocity, m: set per world so the starting spin shows as ARROW_LENGTH. */
let omegaScale = 1;
/**
 * Flip mode: how long a tap of a torque key torques, s of world time. At the default key torque
 * (0.5 N m, times FLIP_PUSH) about the box's intermediate axis (0.34 kg m^2) it adds about 1 rad/s to
 * its spin; one frame's torque (1/60 s) added 0.05 rad/s, which the readout (0.1 rad/s) hardly showed.
 */
const FLIP_TAP_TIME = 0.35;
/** Flip mode: the world time, s, until which each tapped torque key still counts as held. */
const tapUntil = new Map<string, number>();
/** Torque the keys ask for now, N m, world frame (read by the forces-stage system). */
const keyTorque = new Float64Array(3);
/** Room mode: the unit axis the roll keys turn the cube about (world frame), or zero when no roll runs. */
const rollAxis = new Float64Array(3);
/** Torque handed to the forces stage each step, N m (keyTorque, or in the room the governed roll torque). */
const stepTorque = new Float64Array(3);
/**
 * Room mode: keeps the cube square to the grid of the heading it was dropped at (the camera's: so to
 * the roll keys' screen directions, and with the default view to the walls and the pads) and turns it
 * a quarter at a time for Q and E (scene.ts `YawKeeper`).
 */
const yawKeeper = new YawKeeper();
/**
 * The torque of this step, N m, world frame: on the pivot keyTorque; in the room ROLL_TORQUE (times
 * the panel's key torque over its default) about rollAxis while the cube turns about that axis slower
 * than ROLL_SPIN_MAX, else none (a roll turns at a steady pace), plus the yaw keeper's torque
 * about the vertical, at most as large.
 */
function torqueNow(world: PhysicsWorld): Float64Array {
  if (params.mode !== 'room') return keyTorque;
  const W = world.components.AngularVelocity,
    e = handles.body;
  const along = W.x[e]! * rollAxis[0]! + W.y[e]! * rollAxis[1]! + W.z[e]! * rollAxis[2]!;
  const most = (ROLL_TORQUE * params.torque) / 0.5;
  const T = along < ROLL_SPIN_MAX ? most : 0;
  stepTorque[0] = T * rollAxis[0]!;
  stepTorque[1] = T * rollAxis[1]! + yawKeeper.torque(world, e, most);
  stepTorque[2] = T * rollAxis[2]!;
  return stepTorque;
}
/**
 * Room mode: a roll key pressed keeps rolling the cube until it has turned ROLL_LATCH_ANGLE (past
 * its tipping point, 45 degrees, from where it falls onto the next face by itself) or for
 * ROLL_LATCH_TIME s, so a short tap rolls it over one edge instead of rocking it back.
 */
const ROLL_LATCH_ANGLE = (55 * Math.PI) / 180,
  ROLL_LATCH_TIME = 1.5;
/** The latched roll: its axis (a level unit vector), the orientation at the press and the world time it ends; on while `latchUntil` > now. */
/**
 * Room mode: whether a roll key's roll has begun since the last push or jump: once the roll is over
 * (no roll key held, the latch done) the cube's landing settles quickly (scene.ts `rollSettle`).
 */
let settleArmed = false;
const latchAxis = new Float64Array(3),
  latchQ = new Float64Array(4);
let latchUntil = -1;
/** Room mode: a roll key pressed while the cube is busy waits here for it to rest (controls.ts `RollQueue`). */
const rollQueue = new RollQueue();
/** Pads reached and not yet celebrated: the pad's index, the world time, s, the miss from its centre, m, and the moves it took against its par. */
const padsReached: { pad: number; time: number; miss: number; moves: number; par: number }[] = [];

/** The three.js app once the game has started (null while `startThreeGame` builds the first world). */
let threeApp: { camera: { matrixWorld: { extractBasis(x: Vector3, y: Vector3, z: Vector3): unknown } } } | null = null;
/** The mode the camera was last framed for (null before the start): a world of another mode takes that mode's default view. */
let framedMode: Mode | null = null;
/**
 * The camera's heading about the vertical, rad: the angle from +z to the level part of its view from
 * the target (the default view's before the game has started). The room's cube is dropped at it
 * (scene.ts `heading`), so its edges run along the screen's left-right and up-down and each roll key
 * rolls it the way its arrow points.
 */
function cameraHeading(): number {
  let bx: number, bz: number;
  if (threeApp && framedMode === params.mode) {
    const x = new Vector3(),
      y = new Vector3(),
      z = new Vector3();
    threeApp.camera.matrixWorld.extractBasis(x, y, z);
    bx = z.x;
    bz = z.z;
  } else [bx, , bz] = viewDirectionOf(params.mode);
  const heading = Math.hypot(bx, bz) > 1e-6 ? Math.atan2(bx, bz) : 0;
  // The room's cube stays square to the room (the pads' grid of cells): the nearest quarter turn.
  return params.mode === 'room' ? (Math.PI / 2) * Math.round(heading / (Math.PI / 2)) : heading;
}

/**
 * The camera's right and up, unit vectors, world frame (the default view's before the game has
 * started, or when it was framed for another mode): the free-spin targets are set along them, so the
 * torque keys' axes (pitch about right, yaw about up) line up with them.
 */
function cameraAxes(): [number[], number[]] {
  if (threeApp && framedMode === params.mode) {
    const x = new Vector3(),
      y = new Vector3(),
      z = new Vector3();
    threeApp.camera.matrixWorld.extractBasis(x, y, z);
    return [x.normalize().toArray(), y.normalize().toArray()];
  }
  // three.js's lookAt: right = world up x back, up = back x right (back: from the target to the camera).
  const back = new Vector3(...viewDirectionOf(params.mode)).normalize();
  const right = new Vector3(0, 1, 0).cross(back).normalize();
  return [right.toArray(), back.clone().cross(right).normalize().toArray()];
}

/** A fresh world with the body of the current mode (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(rotatingCubeWorldOptions(params.mode));
  const heading = cameraHeading();
  // Flip mode: the pivot drags the box only while the round runs (it keeps its spin while the goal is read, and after the end).
  handles = buildRotatingCube(world, {
    mode: params.mode,
    spin: params.spin,
    heading,
    dragWhile: () => flips.startedAt >= 0 && !flips.over(world),
  });
  yawKeeper.reset(heading);
  const w = world.components.AngularVelocity,
    e = handles.body;
  // On the free-spin pivot the targets' spin (SPIN_RATE) shows as ARROW_LENGTH.
  omegaScale = ARROW_LENGTH / Math.max(1, Math.hypot(w.x[e]!, w.y[e]!, w.z[e]!), params.mode === 'cube' ? SPIN_RATE : 0);
  addSystem(
    world,
    'forces',
    torqueCouple(handles.body, () => torqueNow(world)),
  );
  settleArmed = false;
  if (params.mode === 'room')
    addSystem(
      world,
      'forces',
      rollSettle(handles.body, () => settleArmed && rollAxis[0] === 0 && rollAxis[2] === 0),
    );
  // The challenges are checked after every step (a system at the end of the step), so they count
  // the same whether the page runs, single-steps or is stepped by a test.
  if (freshLayout) layout = padLayout(fixedSeed ?? Math.floor(Math.random() * 2 ** 31));
  freshLayout = false;
  pads.reset(layout);
  toGo.reset();
  toGoPad = -1;
  // A won flip round's time joins the visit's best as the next round starts (its banner compared against the best before it).
  if (flips.wonAt >= 0) bestFlipTime = Math.min(bestFlipTime, flips.time(flips.wonAt));
  flips.reset();
  spins.reset(spinTargets(...cameraAxes()));
  spinsReached.length = 0;
  padsReached.length = 0;
  latchUntil = -1;
  rollQueue.clear();
  addSystem(world, 'finalize', (w) => {
    if (params.mode === 'room') {
      const spot = layout.pads[pads.pad],
        movesBefore = pads.movesAtLight;
      if (spot && pads.update(w, handles.body)) {
        const P = w.components.Position;
        const miss = Math.hypot(P.x[handles.body]! - spot[0], P.z[handles.body]! - spot[1]);
        const k = pads.pad - 1;
        padsReached.push({ pad: k, time: w.time, miss, moves: pads.movesAtLight - movesBefore, par: pads.pars[k] ?? 0 });
      }
    } else if (params.mode === 'flip') flips.update(w, handles.body);
    else if (spins.update(w, handles.body)) spinsReached.push(spins.target - 1);
  });
  // Held at its pivot, the box has no collider: a floor far below only catches the shadow. The room has its own floor.
  if (params.mode !== 'room') addPlane(world, { normal: [0, 1, 0], point: [0, PIVOT_FLOOR_Y, 0] });
  return world;
}

// Read by frame() and the step, which the shell may call before this module's code after `startThreeGame` has run.
/** The page's sound (impacts, pushes, the pads' chimes). */
const sound = getSound();
const L = new Float64Array(3),
  wb = new Float64Array(3);
let lastPlotted = -1,
  frames = 0,
  /** Whether `fitBesideDrawer` may run: what it reads is defined further down this module (set once it is, before the first frame). */
  framingReady = false,
  /** Frames drawn in the room on a tall stage before `fitBesideDrawer` could frame it (it would move the room once it could). */
  unframedFrames = 0;

/**
 * The pixel ratio to render at: the kit's default (the device's, at most 2; SOFTWARE_PIXEL_RATIO, a
 * quarter of the pixels, under software WebGL), except on a phone under software WebGL, where it is 1:
 * at the kit's 0.5 a 390 px wide stage would be drawn 195 px wide and blown up four times, too blurry
 * to read the cube's faces; at 1 a frame fills about as many pixels as the desktop's at 0.5 (390 x 536
 * against 1060 x 734 CSS px), so it costs about as much.
 */
function pixelRatio(): number | undefined {
  return isSoftwareWebGL() && pageLayout().touch() ? 1 : undefined;
}

const game = await startThreeGame({
  title: 'Rotating cube',
  createWorld,
  bodies: () => 1,
  // Every step's impacts of the cube on the floor and the walls knock, louder the harder.
  step: (world) => {
    // Keys pressed since the last frame act from this frame's first step: read only after the steps
    // (in `frame`), a tap on ▲ waited a whole frame before the cube began to tip.
    if (pressed.size > 0) updateKeyTorque();
    physicsStep(world);
    if (params.mode === 'room')
      forEachImpact(world, (a, b, impulse) => {
        if (a === handles.body || b === handles.body) sound.impact(impulse, 'wood', { threshold: 0.4, loud: 6 });
      });
  },
  // The legend and the phone's touch card speak of the mode shown (`setMode` swaps the legend).
  controls: [...cubeControls(params.mode, pageLayout().touch()), ...ORBIT_CONTROLS],
  keys: [
    { key: 'x', label: 'stop', action: () => stopSpin() },
    { key: 'm', label: 'mode', action: () => setMode(MODES[(MODES.indexOf(params.mode) + 1) % MODES.length]!) },
    { key: ' ', label: 'jump', action: () => jump() },
  ],
  app: { background: 0x1a2232, controls: { minDistance: 1.5, maxDistance: 30 }, pixelRatio: pixelRatio() },
  renderer: {
    debug: params.axes ? debugOptions() : false,
    planeSize: 14,
    boundary: 'none',
    floorColor: 0x3c4660,
    // A warm low sun from the back left (the cube's shadow falls towards the viewer, on the floor in
    // sight) under a cool dusk sky; its shadows softened below (shadow radius).
    lights: {
      color: 0xffe4c0,
      intensity: 2.6,
      hemisphereIntensity: 1.1,
      skyColor: 0xcad6ff,
      groundColor: 0x6a5242,
      direction: [-0.45, 1, -0.5],
      shadowMapSize: 1024,
    },
  },
  view: viewOf(params.mode),
  viewDirection: viewDirectionOf(params.mode),
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;
threeApp = app;
// Soft shadow edges: PCF filtering over a wider disc of the shadow map (a 1024 px map blurred reads
// as soft daylight, and costs a software renderer a quarter of the default 2048 px one).
if (renderer.lights) renderer.lights.sun.shadow.radius = 4;
framedMode = params.mode;
clampOrbit();

/**
 * Whether the stage is a tall one (a phone held upright): there the room is seen from the front and
 * high up, framed by its floor, so it fills the width of the screen (seen from a corner, it framed its
 * diagonal and filled half the screen, the cube some 40 px).
 */
function tallStage(): boolean {
  const stage = pageLayout().stage;
  const w = stage.clientWidth || window.innerWidth,
    h = stage.clientHeight || window.innerHeight;
  return h > 1.2 * w;
}

/** What the camera frames in each mode, m: the room with its walls (on a tall stage its floor), or the box on its pivot. */
function viewOf(mode: Mode): { min: [number, number, number]; max: [number, number, number] } {
  if (mode !== 'room') return { min: [-1.3, -1.3, -1.3], max: [1.3, 1.8, 1.3] };
  const edge = tallStage() ? ROOM_HALF - 0.3 : ROOM_HALF;
  return { min: [-edge, 0, -edge], max: [edge, tallStage() ? 1 : WALL_HEIGHT, edge] };
}

/**
 * Direction the camera looks from in each mode: the room from the front (square to its walls, so the
 * cube, dropped square to the camera, is square to the walls and the pads too) and from high up
 * (about 65 degrees: a cube against the near wall stays in sight over it, and the cube's top face
 * lies mostly over the square it stands on, not over the one behind as at a lower angle); the pivot
 * from a little above.
 */
function viewDirectionOf(mode: Mode): [number, number, number] {
  return mode === 'room' ? [0, 2.2, 1] : [1, 0.7, 1.4];
}

/**
 * Keeps the orbiting camera above the floor: in the room at most 80 degrees from straight down onto
 * the target (it stays over the walls' feet), on the pivot at most 100 degrees (the floor is 1.6 m below).
 */
function clampOrbit(): void {
  if (!app.controls) return;
  app.controls.maxPolarAngle = ((params.mode === 'room' ? 80 : 100) * Math.PI) / 180;
  app.controls.update();
}

/**
 * Debug layer: on the pivot the body's axes; in the room the contact points instead (the layer draws
 * axes for every body, 1.5 times its size: the walls' would cross the whole room). Never the planes'
 * normals: the floor's would stand unlabelled in the middle of the scene.
 */
function debugOptions() {
  const room = params.mode === 'room';
  return { axes: !room, velocities: false, contacts: room, joints: false, planes: false };
}

/** Room mode: the key torque and click impulse scale. */
function push(): number {
  return params.mode === 'room' ? ROOM_PUSH : 1;
}

/** The first input of a round starts its clock: the pads' in the room, the flips' in flip mode. */
function startClock(): void {
  if (params.mode === 'room') pads.start(shell.world.time);
  else if (params.mode === 'flip') flips.input(shell.world.time);
  else spins.start(shell.world.time);
}

/** Space: in room mode, a jump (an impulse up at the centre of mass). */
function jump(): void {
  if (params.mode !== 'room') return;
  pads.start(shell.world.time);
  pads.jumped();
  settleArmed = false;
  applyImpulse(shell.world, handles.body, [0, JUMP_IMPULSE, 0]);
}

// The body: a unit box with one colour per face, six hues a player names at a glance (red, yellow,
// green, purple, blue, white: no two tints of one hue), scaled by the renderer to the body's
// equivalent-inertia box.
const faceColors = [0xe53935, 0xfdd835, 0x43a047, 0xb05cd6, 0x1e88e5, 0xf5f5f5];
/** The faces' colours in words, in the order of FACES (+x red, -x yellow, +y green, -y purple, +z blue, -z white). */
const FACE_NAMES = ['red', 'yellow', 'green', 'purple', 'blue', 'white'];
/** CSS colour of face `f`. */
const faceCss = (f: number): string => `#${faceColors[f]!.toString(16).padStart(6, '0')}`;
/** The glow of a pad that takes any face (cyan: none of the faces' hues). */
const ANY_COLOR = 0x22d3ee;
const boxGeometry = new BoxGeometry(1, 1, 1);
{
  // Vertex colours are linear in three.js; Color converts from sRGB hex.
  const colors: number[] = [];
  const color = new Color();
  for (let f = 0; f < 6; f++) {
    color.setHex(faceColors[f]!);
    for (let v = 0; v < 4; v++) colors.push(color.r, color.g, color.b);
  }
  boxGeometry.setAttribute('color', new Float32BufferAttribute(colors, 3));
}
/**
 * A `size` px square texture (sRGB) filled with `fill` and framed at its border by a `stroke` line
 * `lineWidth` px wide (half of it inside the square): the cube's rim and the floor's tiles.
 */
function framedSquare(size: number, fill: string, stroke: string, lineWidth: number): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = c.height = size;
  const g = c.getContext('2d')!;
  g.fillStyle = fill;
  g.fillRect(0, 0, size, size);
  g.strokeStyle = stroke;
  g.lineWidth = lineWidth;
  g.strokeRect(0, 0, size, size);
  const texture = new CanvasTexture(c);
  texture.colorSpace = SRGBColorSpace;
  return texture;
}
/**
 * The faces' rim: white with a darker band at each face's border (multiplying its vertex colour), so the
 * cube's twelve edges show as lines and its faces read as one box, not slabs stacked (edges drawn at a
 * low pixel ratio step by a pixel where they run nearly straight up the screen).
 */
const edgeTexture = framedSquare(64, '#ffffff', '#6e6e6e', 6);
const boxMaterial = new MeshStandardMaterial({ vertexColors: true, map: edgeTexture, roughness: 0.55, metalness: 0.05 });
/** The room's scenery (room-look.ts): floor, stone walls, terrace, props, skyline, the lit pad's glow. */
const look = buildRoomLook(app.scene, ROOM_HALF, WALL_HEIGHT, WALL_HALF_THICKNESS);
const dress = (): void => {
  renderer.setShape(handles.body, { geometry: boxGeometry, material: boxMaterial, scale: 'inertia' });
  // The walls in scene.ts buildRoom's order (+x, -x, +z, -z), each drawn in the look's stone.
  const t = WALL_HALF_THICKNESS,
    h = WALL_HEIGHT / 2,
    l = ROOM_HALF + 2 * t;
  handles.walls.forEach((wall, i) => {
    renderer.setShape(wall, i < 2 ? look.wallShape(i, t, h, l) : look.wallShape(i, l, h, t));
  });
};
dress();
shell.onWorldChange(() => {
  tapUntil.clear();
  dress();
  plot?.clear();
});

// The room's pads (drawn only; the physics knows nothing of them): the lit one a glowing square, the
// ones to come outlined, the ones reached a dim grey tick; a ring bursts from a pad when it is reached.
/** The tint of a finished pad's tick while the round runs (sRGB hex): a grey, no face's colour. */
const PAD_DONE_GREY = 0x9aa3b2;
/**
 * A pad's picture, white on clear (a material's colour tints it): a rounded square, filled or a frame,
 * with a soft edge PAD_TEX_MARGIN px wide inside a PAD_TEX px texture. Drawn in a texture (filtered and
 * mipmapped), its edges stay smooth where a box's or a line's would be drawn in stair steps (a
 * software renderer draws without antialiasing, at half the pixels).
 */
const PAD_TEX = 256,
  PAD_TEX_MARGIN = 16;
function padTexture(filled: boolean): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = c.height = PAD_TEX;
  const g = c.getContext('2d')!;
  const m = PAD_TEX_MARGIN,
    size = PAD_TEX - 2 * m,
    inset = filled ? 0 : 10;
  // A thin glow only: a wide one blurred the pad's edge into the floor.
  g.shadowColor = '#fff';
  g.shadowBlur = 3;
  g.fillStyle = g.strokeStyle = '#fff';
  g.beginPath();
  g.roundRect(m + inset, m + inset, size - 2 * inset, size - 2 * inset, 20);
  if (filled) g.fill();
  else {
    g.lineWidth = 16;
    g.stroke();
  }
  const texture = new CanvasTexture(c);
  texture.colorSpace = SRGBColorSpace;
  texture.anisotropy = 4;
  return texture;
}
/**
 * A finished pad's mark: a faint square with a tick in its middle (white, tinted by the material), so
 * a pad already reached reads as done, not as another coloured target.
 */
function padTickTexture(): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = c.height = PAD_TEX;
  const g = c.getContext('2d')!;
  const m = PAD_TEX_MARGIN,
    size = PAD_TEX - 2 * m;
  g.fillStyle = 'rgba(255, 255, 255, 0.18)';
  g.beginPath();
  g.roundRect(m, m, size, size, 20);
  g.fill();
  g.strokeStyle = '#fff';
  g.lineWidth = size * 0.1;
  g.lineCap = g.lineJoin = 'round';
  g.beginPath();
  g.moveTo(m + size * 0.28, m + size * 0.52);
  g.lineTo(m + size * 0.44, m + size * 0.68);
  g.lineTo(m + size * 0.74, m + size * 0.34);
  g.stroke();
  const texture = new CanvasTexture(c);
  texture.colorSpace = SRGBColorSpace;
  texture.anisotropy = 4;
  return texture;
}
/**
 * The floor's tiles: 1 m cells with a thin light seam at their edges, a picture repeated over the
 * room's floor and shifted so its cells are the puzzle's (centred on the lit pad; `placeTiles`).
 */
const floorTiles = (() => {
  const t = framedSquare(128, 'rgba(255, 255, 255, 0.035)', 'rgba(210, 225, 255, 0.30)', 3);
  t.anisotropy = 8;
  t.wrapS = t.wrapT = RepeatWrapping;
  t.repeat.set(2 * ROOM_HALF, 2 * ROOM_HALF);
  const mesh = new Mesh(
    new PlaneGeometry(2 * ROOM_HALF, 2 * ROOM_HALF).rotateX(-Math.PI / 2),
    new MeshBasicMaterial({ map: t, transparent: true, depthWrite: false }),
  );
  mesh.position.y = 0.003;
  mesh.renderOrder = -1;
  app.scene.add(mesh);
  return mesh;
})();
/** Shifts the floor's tiles so their cells are centred on (x, z), m (the lit pad's centre). */
function placeTiles(x: number, z: number): void {
  const map = (floorTiles.material as MeshBasicMaterial).map!;
  // The picture's u runs along +x from the floor's -x edge and v along -z from its +z edge, one tile a metre.
  map.offset.set(-(x + 0.5 + ROOM_HALF) - Math.floor(-(x + 0.5 + ROOM_HALF)), z + 0.5 - ROOM_HALF - Math.floor(z + 0.5 - ROOM_HALF));
}
/** A flat square on the floor carrying a pad picture: 2 PAD_HALF across the picture's square, wider by its margin. */
const padPlane = new PlaneGeometry(
  (2 * PAD_HALF * PAD_TEX) / (PAD_TEX - 2 * PAD_TEX_MARGIN),
  (2 * PAD_HALF * PAD_TEX) / (PAD_TEX - 2 * PAD_TEX_MARGIN),
).rotateX(-Math.PI / 2);
const padFill = padTexture(true),
  padFrame = padTexture(false);
const padMesh = new Mesh(
  padPlane,
  new MeshStandardMaterial({
    color: 0x0c8f52,
    map: padFill,
    emissive: 0x12c46e,
    emissiveMap: padFill,
    emissiveIntensity: 0.9,
    roughness: 0.4,
    transparent: true,
    // The floor's boards show through: the lit pad reads as a mark on the floor, not a block's top.
    opacity: 0.6,
    depthWrite: false,
  }),
);
padMesh.receiveShadow = true;
app.scene.add(padMesh);
/**
 * The lit pad's rim: a white frame as wide as the pad's counting square (its half edge plus
 * PAD_GRACE), shown while the cube's centre is over that square, so the player sees when it counts.
 */
const padRim = new Mesh(padPlane, new MeshBasicMaterial({ color: 0xffffff, map: padFrame, transparent: true, depthWrite: false }));
padRim.visible = false;
app.scene.add(padRim);
/**
 * Room mode: the cube's footprint, a bright square outline on the floor around the 1 m square the cube
 * stands on, following it as it rolls. From the default camera's slant the cube's top face reads as
 * the square behind the one it stands on; the outline's front edge, in front of the cube, shows the
 * square. Drawn once in front of the pads and tiles, and once faintly through the cube (depth test
 * off), so its whole square shows from any view.
 */
const footprintRing = new RingGeometry(0.5 * Math.SQRT2, 0.58 * Math.SQRT2, 4, 1, Math.PI / 4).rotateX(-Math.PI / 2);
const footprint = new Mesh(
  footprintRing,
  new MeshBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.95, side: DoubleSide, depthWrite: false }),
);
const footprintThrough = new Mesh(
  footprintRing,
  new MeshBasicMaterial({ color: 0xffffff, transparent: true, opacity: 0.25, side: DoubleSide, depthWrite: false, depthTest: false }),
);
footprint.renderOrder = 2;
footprintThrough.renderOrder = 3;
app.scene.add(footprint, footprintThrough);
/** Finished pads: a dim grey tick while the round runs (no colour a target could have), all gold once it is won. */
const padDoneMaterial = new MeshBasicMaterial({
  color: PAD_DONE_GREY,
  map: padTickTexture(),
  transparent: true,
  opacity: 0.55,
  depthWrite: false,
});
const padMarks = Array.from({ length: PAD_COUNT }, () => {
  const outline = new Mesh(
    padPlane,
    new MeshBasicMaterial({ color: ANY_COLOR, map: padFrame, transparent: true, opacity: 0.9, depthWrite: false }),
  );
  const done = new Mesh(padPlane, padDoneMaterial);
  app.scene.add(outline, done);
  return { outline, done };
});
/** Places the pads' marks for this run's layout: each outlined in the colour of the face it wants (cyan: any face), sized to its pad. */
function placePadMarks(): void {
  padMarks.forEach((mark, i) => {
    const [x, z] = layout.pads[i]!,
      want = layout.faces[i]!,
      k = layout.halves[i]! / PAD_HALF;
    (mark.outline.material as MeshBasicMaterial).color.setHex(want >= 0 ? faceColors[want]! : ANY_COLOR);
    mark.outline.position.set(x, 0.015, z);
    mark.outline.scale.set(k, 1, k);
    mark.done.position.set(x, 0.012, z);
    mark.done.scale.set(k, 1, k);
  });
}
placePadMarks();
shell.onWorldChange(placePadMarks);
/**
 * A roll-only tile's picture, white on clear (the material tints it): a rounded square, see-through
 * inside, with a dashed rim, and in its middle a circular arrow over the word ROLL, so a player reads
 * on the tile itself what it takes (the legend in the pads card says the same in words). The word
 * reads upright from the default view (the picture's top towards -z, the far side).
 */
function rollTileTexture(): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = c.height = 256;
  const g = c.getContext('2d')!;
  g.fillStyle = 'rgba(255, 255, 255, 0.2)';
  g.strokeStyle = 'rgba(255, 255, 255, 0.85)';
  g.beginPath();
  g.roundRect(10, 10, 236, 236, 22);
  g.fill();
  g.lineWidth = 7;
  g.setLineDash([22, 12]);
  g.stroke();
  g.setLineDash([]);
  // A circular arrow (three quarters of a turn, its head at the end): a roll over an edge.
  g.strokeStyle = g.fillStyle = 'rgba(255, 255, 255, 0.95)';
  g.lineWidth = 14;
  g.lineCap = 'round';
  g.beginPath();
  g.arc(128, 100, 44, Math.PI * 0.85, Math.PI * 2.35);
  g.stroke();
  const hx = 128 + 44 * Math.cos(Math.PI * 2.35),
    hy = 100 + 44 * Math.sin(Math.PI * 2.35);
  g.beginPath();
  g.moveTo(hx + 26, hy - 8);
  g.lineTo(hx - 12, hy - 20);
  g.lineTo(hx - 4, hy + 22);
  g.closePath();
  g.fill();
  g.font = '800 54px system-ui, sans-serif';
  g.textAlign = 'center';
  g.textBaseline = 'middle';
  g.fillText('ROLL', 128, 196);
  const texture = new CanvasTexture(c);
  texture.colorSpace = SRGBColorSpace;
  texture.anisotropy = 4;
  return texture;
}
/**
 * The lit pad's bed (scene.ts PAD_BEDS): a roll-only tile (`rollTileTexture`) on each 1 m cell around
 * the pad that the cube fits in, so the player sees the cells to roll across (a slide stops at the
 * tiles' edge) and counts the rolls.
 */
const bedMaterial = new MeshBasicMaterial({ color: 0xc4d2ee, map: rollTileTexture(), transparent: true, opacity: 0.75, depthWrite: false });
const bedPlane = new PlaneGeometry(0.92, 0.92).rotateX(-Math.PI / 2);
const bedTiles = Array.from({ length: 36 }, () => {
  const tile = new Mesh(bedPlane, bedMaterial);
  tile.visible = false;
  app.scene.add(tile);
  return tile;
});
/** Lays the bed's tiles around pad `k` (none for a pad without a bed, or once the round is over) and words the legend for them. */
function placeBed(k: number): void {
  let n = 0;
  const bed = layout.beds[k] ?? -1,
    spot = layout.pads[k];
  if (spot && bed > 0 && params.mode === 'room')
    for (let i = -bed; i <= bed; i++)
      for (let j = -bed; j <= bed; j++) {
        const x = spot[0] + i,
          z = spot[1] + j;
        if ((i === 0 && j === 0) || Math.max(Math.abs(x), Math.abs(z)) > CELL_REACH + 1e-9 || n >= bedTiles.length) continue;
        bedTiles[n++]!.position.set(x, 0.008, z);
      }
  bedTiles.forEach((tile, i) => {
    tile.visible = i < n;
  });
  // The legend's words follow the tiles drawn (set only when they change: this runs every frame).
  const words =
    n > 0 && rollOnly()
      ? 'ROLL tiles: a slide stops at their edge; this pad has them over the whole floor: no slides, plan your rolls'
      : 'ROLL tiles: a slide stops at their edge, roll across them';
  if (bedWords.textContent !== words) bedWords.textContent = words;
}
const burst = new Mesh(
  new RingGeometry(0.85, 1, 48).rotateX(-Math.PI / 2),
  new MeshBasicMaterial({ color: 0xffe27a, transparent: true, side: DoubleSide, depthWrite: false }),
);
burst.visible = false;
app.scene.add(burst);
/** performance.now() of the last pad reached, ms (the burst and the pop run from it). */
let burstAt = -Infinity;
/** A burst lasts this long, ms. */
const BURST_MS = 1100;

/** A square outline picture for a 1 m cell: a white rim with rounded corners, transparent inside. */
function outlineTexture(): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = c.height = 128;
  const g = c.getContext('2d')!;
  g.strokeStyle = 'rgba(255, 255, 255, 0.95)';
  g.lineWidth = 7;
  g.beginPath();
  g.roundRect(8, 8, 112, 112, 12);
  g.stroke();
  const t = new CanvasTexture(c);
  t.colorSpace = SRGBColorSpace;
  t.anisotropy = 4;
  return t;
}

// Room mode: where a click would push the cube (an arrow on the floor from the cube) and the point aimed at.
const aimArrow = new VectorArrow({ color: 0x7fe3ff, radius: 0.035, headLength: 0.22 });
const aimRing = new Mesh(
  new RingGeometry(0.12, 0.18, 32).rotateX(-Math.PI / 2),
  new MeshBasicMaterial({ color: 0x7fe3ff, transparent: true, opacity: 0.9, side: DoubleSide, depthWrite: false }),
);
aimRing.visible = false;
/** The floor cell under the pointer: a 1 m square outline (a picture, so its edges are smooth). */
const cellMark = new Mesh(
  new PlaneGeometry(1, 1).rotateX(-Math.PI / 2),
  new MeshBasicMaterial({ map: outlineTexture(), transparent: true, depthWrite: false }),
);
cellMark.visible = false;
/** The cell under the finger of the last tap that pushed (its centre, x and z, m). */
const tappedCell: [number, number] = [0, 0];
/** A red ring flashed on a clicked cell the cube cannot slide to (its own cell, or a pad's ROLL tiles): "can't go there". */
const refuseMark = new Mesh(
  new RingGeometry(0.3, 0.42, 40).rotateX(-Math.PI / 2),
  new MeshBasicMaterial({ color: 0xff4a3d, transparent: true, opacity: 0.95, side: DoubleSide, depthWrite: false }),
);
refuseMark.visible = false;
refuseMark.renderOrder = 4;
/** How long the red ring of a refused click shows, fading, ms. */
const REFUSE_MS = 900;
/** performance.now() of the last refused click (-Infinity: none), and refused clicks since the page loaded (a test reads it). */
let refusedAt = -Infinity,
  refusals = 0;
app.scene.add(aimArrow.object, aimRing, cellMark, refuseMark);
aimArrow.hide();
/** performance.now() until which the aim of the last tap stays shown (touch has no hover), ms. */
let aimUntil = 0;

// The pop over the scene when a pad is reached ("Pad 2 of 5 · 6.4 s", "Perfect!").
const pop = document.createElement('div');
pop.dataset.hud = 'pad-pop';
pop.setAttribute('aria-live', 'polite');
// Over the face net and the rules card (z-index 5); on a phone at the stage's foot, under the room's
// front wall (the net and the card fill the stage's top there, and in the middle the pop hid the
// floor's back row, pads and all, while it faded); a long line wraps inside the stage and the screen (on a phone the stage may be
// wider than the screen), and its pop-in swells it only a little so the swell stays on screen too.
pop.style.cssText =
  `position: absolute; left: 50%; top: ${pageLayout().touch() ? '95%' : '22%'}; transform: translate(-50%, -50%); pointer-events: none; opacity: 0;` +
  'font: 700 clamp(18px, 5.5vw, 28px) system-ui, sans-serif; color: #ffe27a; text-shadow: 0 2px 6px #000, 0 0 2px #000; text-align: center;' +
  'z-index: 5; width: max-content; max-width: min(calc(100% - 24px), calc(100vw - 24px)); box-sizing: border-box; overflow-wrap: break-word; transition: opacity 0.25s, transform 0.9s ease-out;' +
  // On a dark plate: over the room's pale back wall the yellow alone read faint (contrast under 2:1).
  'background: rgba(10, 15, 30, 0.88); padding: 4px 14px; border-radius: 10px';
{
  const stage = app.canvas.parentElement ?? document.body;
  if (getComputedStyle(stage).position === 'static') stage.style.position = 'relative';
  stage.append(pop);
}
let popHideTimer = 0;
/** Pops shown since the page loaded (a test reads it: a pop lasts about a second, gone before a loaded machine looks). */
let popsShown = 0;
/** Shows `text` in the pop (in CSS colour `color`), rising and fading after `ms` ms. */
function showPop(text: string, ms = 1100, color = '#ffe27a'): void {
  popsShown++;
  pop.textContent = text;
  pop.style.color = color;
  pop.style.transition = 'none';
  pop.style.opacity = '1';
  pop.style.transform = 'translate(-50%, -50%) scale(1.04)';
  void pop.offsetWidth;
  pop.style.transition = 'opacity 0.4s, transform 0.9s ease-out';
  pop.style.transform = 'translate(-50%, -90%) scale(1)';
  clearTimeout(popHideTimer);
  popHideTimer = window.setTimeout(() => {
    pop.style.opacity = '0';
  }, ms);
}
/** The chimes of pads 1 to 5 (a rising C major arpeggio, Hz); the round's end rings the octave above. */
const PAD_PITCHES = [523, 659, 784, 988, 1175];

/** The reason (PadChallenge `blocked`) the last pop said a resting cube did not count, or '' (none said since it last moved). */
let blockedSaid: '' | 'face' | 'slide' = '';
/**
 * Says once, in the pop, why the cube resting on the lit pad does not count: another face on top than
 * the pad wants, or the wanted face slid on instead of rolled on.
 */
function sayBlocked(): void {
  // The wrong face is said only once the cube has settled on the pad with it (a resting step between two
  // rolls or in a landing's bounce read as a false alarm); a slide onto a pad is said as it rests.
  const why = params.mode !== 'room' ? '' : pads.blocked === 'slide' ? 'slide' : pads.settledBlocked;
  if (why === blockedSaid) return;
  blockedSaid = why;
  const want = FACE_NAMES[layout.faces[pads.pad] ?? -1];
  if (why === 'face' && want) showPop(`✗ This pad needs ${want} on top`, 1800, '#ffb4a8');
  // The rule a slide breaks is new to a player: held long enough to read (a stranger lost it at 2.2 s).
  else if (why === 'slide') showPop(slidOnWords(), 3500, '#ffb4a8');
}

/** What the pop says when a slide rests the cube on a pad that takes only a roll on. */
function slidOnWords(): string {
  const roll = pageLayout().touch() ? '▲◀▼▶' : 'W A S D';
  return `✗ Slides don't take this pad: roll onto it (${roll})`;
}

/** Flip mode: the flips counted and missed (out of the band) that `celebrateFlips` has answered; reset with the world. */
let flipsAnswered = 0,
  missesAnswered = 0;
/**
 * Flip mode: a flip counted since the last frame rings a chime a step higher each (a C major scale
 * from C5) and pops "Flip 3 of 10 ✓"; a flip made out of the band pops why it did not count (the
 * status row's ✗ alone was missed while watching the box). The last flip is left to the banner.
 */
function celebrateFlips(): void {
  const { count, missed } = flips.counter;
  if (count < flipsAnswered || missed < missesAnswered) [flipsAnswered, missesAnswered] = [0, 0];
  if (count > flipsAnswered && count < FLIP_GOAL) {
    const scale = [523, 587, 659, 698, 784, 880, 988, 1047, 1175];
    sound.chime(scale[(count - 1) % scale.length]!, 0.3);
    showPop(`Flip ${count} of ${FLIP_GOAL} ✓`, 700);
  } else if (missed > missesAnswered && flips.startedAt >= 0 && !flips.over(shell.world)) {
    const spin = flipSpin(Math.hypot(...spinAngularMomentum(shell.world, handles.body, new Float64Array(3))));
    const [lo, hi] = FLIP_BAND;
    showPop(`✗ Not counted: spin ${spin.toFixed(1)}, ${spin < lo ? `under ${lo}` : `over ${hi}`}`, 1100, '#ffb4a8');
  }
  flipsAnswered = count;
  missesAnswered = missed;
}

/** Celebrates the pads reached (chime, burst ring, pop) and the free-spin targets reached (chime, pop) since the last frame; in flip mode the flips (`celebrateFlips`). */
function celebrate(): void {
  if (params.mode === 'flip') celebrateFlips();
  while (spinsReached.length > 0) {
    const k = spinsReached.shift()!;
    const last = k === SPIN_TARGETS - 1;
    sound.chime(PAD_PITCHES[k * 2] ?? 880, 0.35);
    if (last) window.setTimeout(() => sound.chime(1568, 0.8), 180);
    showPop(
      last
        ? `All ${SPIN_TARGETS} spins! ${spins.time(shell.world.time).toFixed(1)} s ${stars(spins.stars())}`
        : `Spin ${k + 1} of ${SPIN_TARGETS} ✓`,
      last ? BANNER_DELAY_MS : 1100,
    );
  }
  while (padsReached.length > 0) {
    const r = padsReached.shift()!;
    const last = r.pad === layout.pads.length - 1;
    const spot = layout.pads[r.pad]!;
    burst.position.set(spot[0], 0.03, spot[1]);
    burstAt = performance.now();
    sound.chime(PAD_PITCHES[r.pad] ?? 880, last ? 0.3 : 0.35);
    if (last) window.setTimeout(() => sound.chime(1568, 0.8), 180);
    // A pad's pop stays PAD_POP_MS, long enough to read as a beat of play (it takes no input: pointer-events none).
    showPop(
      last
        ? `All ${layout.pads.length} pads! ${pads.moves} moves ${stars(padStars(pads.moves, pads.par))}`
        : `Pad ${r.pad + 1} of ${layout.pads.length} ✓${padResultText(r.moves, r.par)}`,
      last ? BANNER_DELAY_MS : PAD_POP_MS,
    );
  }
}

// Free spin: the lit target spin, an arrow from the pivot on ω's scale, and a see-through ball at its
// tip as large as the tolerance (ω's tip inside it counts).
const targetArrow = new VectorArrow({ color: 0x22d3ee, radius: 0.03, headLength: 0.16 });
const targetBall = new Mesh(
  new SphereGeometry(1, 24, 16),
  new MeshBasicMaterial({ color: 0x22d3ee, transparent: true, opacity: 0.22, depthWrite: false }),
);
app.scene.add(targetArrow.object, targetBall);
/**
 * The free-spin guides (spin-look.ts): a ghost cube turning at the target spin beside the pivot (on a
 * phone's narrow stage above it), the gap from ω's tip to the target's, the torque at ω's tip and the
 * hold ring round the ball.
 */
const spinLook = new SpinLook(app.scene, faceColors, pageLayout().touch() ? [0.75, 1.2] : [1.55, 0.75]);
/** World time of the last `drawSpinTarget`, s (the ghost turns by the world time between two frames, so it stops with a pause). */
let spinLookTime = -1;
/** Whether ω's tip was in the lit target's ball at the last frame (entering it rings a chime). */
let wasInBall = false;
/**
 * Draws the lit free-spin target and its guides (`spinLook`; hidden in the other modes and once the
 * round is won); the ball brightens while ω's tip is in it, and a chime rings as the tip enters it.
 */
function drawSpinTarget(): void {
  const aim = spins.targets[spins.target];
  const t = shell.world.time,
    dt = spinLookTime >= 0 ? Math.max(0, t - spinLookTime) : 0;
  spinLookTime = t;
  if (params.mode !== 'cube' || spins.won || !aim) {
    targetArrow.hide();
    targetBall.visible = false;
    spinLook.hide();
    wasInBall = false;
    return;
  }
  const W = shell.world.components.AngularVelocity,
    e = handles.body;
  omegaNow[0] = W.x[e]!;
  omegaNow[1] = W.y[e]!;
  omegaNow[2] = W.z[e]!;
  app.camera.updateMatrixWorld();
  spinLook.update({ pivot: handles.pivot, omega: omegaNow, aim, torque: keyTorque, held: spins.held, scale: omegaScale, dt }, app.camera);
  const inBall = spins.held > 0;
  if (inBall && !wasInBall) sound.chime(880, 0.08);
  wasInBall = inBall;
  const o = handles.pivot;
  targetArrow.set(o[0], o[1], o[2], aim[0], aim[1], aim[2], omegaScale);
  targetBall.visible = true;
  targetBall.position.set(o[0] + aim[0] * omegaScale, o[1] + aim[1] * omegaScale, o[2] + aim[2] * omegaScale);
  targetBall.scale.setScalar(SPIN_TOLERANCE * omegaScale);
  (targetBall.material as MeshBasicMaterial).opacity = spins.held > 0 ? 0.5 : 0.22;
}

/** ω now, rad/s, world frame (for the spin guides). */
const omegaNow = new Float64Array(3);

const lArrow = new VectorArrow({ color: 0xffd166, radius: 0.025, headLength: 0.14 });
const wArrow = new VectorArrow({ color: 0xff5ce1, radius: 0.035, headLength: 0.16 });
app.scene.add(lArrow.object, wArrow.object);
/**
 * A dot in a ring at ω's tip, facing the camera and drawn over everything: an arrow pointing at the
 * camera (or away, behind the cube) shows as next to no shaft, but its tip still shows where it is.
 */
const wTip = new Group();
{
  const tipMaterial = new MeshBasicMaterial({ color: 0xff5ce1, depthTest: false, transparent: true, side: DoubleSide });
  wTip.add(new Mesh(new CircleGeometry(0.045, 20), tipMaterial), new Mesh(new RingGeometry(0.1, 0.135, 32), tipMaterial));
  wTip.renderOrder = 5;
  for (const m of wTip.children) m.renderOrder = 5;
  wTip.visible = false;
  app.scene.add(wTip);
}
/**
 * L is drawn this much shorter than w on the same scale (and thicker): where the two are parallel (a
 * cube, always; the box, before it flips) w's magenta tip shows past L's yellow head instead of
 * hiding inside it.
 */
const L_DRAWN = 0.7;
/** A label at each arrow's tip, in its colour: "L" and "ω" (on the pivot, where the arrows show). */
const arrowLabels = [
  { text: 'L', color: '#ffd166' },
  { text: 'ω', color: '#ff5ce1' },
].map(({ text, color }) => {
  const label = document.createElement('div');
  label.textContent = text;
  label.dataset.hud = text === 'L' ? 'label-l' : 'label-omega';
  label.dataset.sceneOverlay = '';
  label.style.cssText =
    'position: absolute; left: 0; top: 0; z-index: 3; pointer-events: none; display: none;' +
    `font: 700 18px system-ui, sans-serif; color: ${color}; text-shadow: 0 1px 3px #000, 0 0 2px #000`;
  (app.canvas.parentElement ?? document.body).append(label);
  return label;
});
const labelAt = new Vector3();
/** Shows label `i` (0: L, 1: w) a little past the tip of the arrow from `o` along (vx, vy, vz) times `scale` (m), or hides it when `show` is false. */
function placeArrowLabel(i: number, show: boolean, o: ArrayLike<number>, vx: number, vy: number, vz: number, scale: number): void {
  const label = arrowLabels[i]!;
  const k = scale * 1.12;
  if (!show || !(Math.hypot(vx, vy, vz) * scale > 0.05)) {
    label.style.display = 'none';
    return;
  }
  labelAt.set(o[0]! + vx * k, o[1]! + vy * k, o[2]! + vz * k).project(app.camera);
  const c = app.canvas.getBoundingClientRect(),
    st = (app.canvas.parentElement ?? document.body).getBoundingClientRect();
  label.style.display = 'block';
  label.style.transform = `translate(${c.left - st.left + ((labelAt.x + 1) / 2) * c.width}px, ${c.top - st.top + ((1 - labelAt.y) / 2) * c.height}px) translate(-50%, -50%)`;
}

// On the pivot: the pivot drawn as a post from the floor to the box's centre (a frictionless ball
// joint at its centre of mass holds it there), on a foot.
const pivotPost = new Mesh(
  new CylinderGeometry(0.035, 0.05, 1.6, 16).translate(0, -0.8, 0),
  new MeshStandardMaterial({ color: 0xa7b1c2, metalness: 0.5, roughness: 0.35 }),
);
const pivotFoot = new Mesh(
  new CylinderGeometry(0.28, 0.32, 0.06, 32).translate(0, -1.57, 0),
  new MeshStandardMaterial({ color: 0x6b7891, metalness: 0.3, roughness: 0.5 }),
);
pivotPost.castShadow = pivotFoot.receiveShadow = true;
app.scene.add(pivotPost, pivotFoot);

// ---- Keys held: in the room the cube rolls in the screen's directions; on the pivot torque about the camera's axes

const held = new Set<string>();
/** Keys pressed since the last frame (a press and release between two frames still counts once). */
const pressed = new Set<string>();
/** Keys in `pressed` only by a held key's repeat: in the room the game repeats a held roll key itself (RollQueue `take`). */
const repeated = new Set<string>();
const TORQUE_KEYS = ['w', 's', 'a', 'd', 'q', 'e'];
const ROLL_KEYS = ['w', 'a', 's', 'd'];
/**
 * Room mode, before the keys are read: of the roll keys pressed since the last frame, in the order
 * they went down, the first acts if the cube is free (still, no roll's latch running) and nothing
 * waits; the rest wait in `rollQueue` and are taken out of `pressed`, as are a held key's repeats.
 * Once the cube is free with no press acting, the oldest waiting key is pressed, or else the last roll
 * key to go down of those still held (so a held key rolls one cell after another).
 */
function queueRolls(): void {
  const world = shell.world;
  let busy = latchUntil > world.time || !cubeStill(world, handles.body),
    acted = false;
  for (const k of [...pressed]) {
    if (!ROLL_KEYS.includes(k)) continue;
    if (repeated.has(k) || !rollQueue.press(k, busy)) pressed.delete(k);
    else acted = busy = true;
  }
  repeated.clear();
  if (acted) return;
  const next = rollQueue.take(
    busy,
    [...held].filter((k) => ROLL_KEYS.includes(k)),
  );
  if (next) pressed.add(next);
}
function typing(target: EventTarget | null): boolean {
  const el = target as HTMLElement | null;
  return !!el && (el.tagName === 'INPUT' || el.tagName === 'SELECT' || el.tagName === 'TEXTAREA');
}
window.addEventListener('keydown', (event) => {
  const k = event.key.toLowerCase();
  if (!TORQUE_KEYS.includes(k) || typing(event.target) || event.ctrlKey || event.metaKey || event.altKey) return;
  // In the room a press while the game is paused is dropped, not kept to act on resume (a stranger's
  // paused presses rolled the cube the moment play went on). On the pivot a key held while paused
  // still turns the box under single steps (N), frame by frame.
  if (shell.paused && params.mode === 'room') {
    event.preventDefault();
    return;
  }
  // The round's clock starts with the player's first move; a roll or spin leaves the last aim stale.
  startClock();
  clearAim();
  if (k !== 'q' && k !== 'e') hideRules();
  held.add(k);
  // A held key's repeats keep a flip torque on (queueRolls drops them in the room); a quarter turn
  // (Q, E) is one a press, and goes on by itself while held.
  if (!event.repeat || (k !== 'q' && k !== 'e')) pressed.add(k);
  if (event.repeat) repeated.add(k);
  event.preventDefault();
});
window.addEventListener('keyup', (event) => held.delete(event.key.toLowerCase()));
window.addEventListener('blur', () => held.clear());

// Touch: the turn keys as hold buttons (in the room arrows that roll the cube, on the pivot the
// torques' names), and stop, jump and mode (the same keys). The four arrows make a d-pad: ▲ over ▼ in
// the middle, ◀ and ▶ the height of both either side (a thumb finds each by where it is, as the arrow
// points); the spins, Stop, Jump and Mode in a block of their own at its right.
const dpad = createButtonBar(
  [
    { label: '▲', name: 'turn forward', key: 'w' },
    { label: '▼', name: 'turn back', key: 's' },
    { label: '◀', name: 'turn left', key: 'a' },
    { label: '▶', name: 'turn right', key: 'd' },
  ],
  { label: 'roll arrows' },
);
dpad.element.classList.add('rc-dpad');
const extras = createButtonBar(
  [
    { label: '⟲', name: 'spin left', key: 'q' },
    { label: '⟳', name: 'spin right', key: 'e' },
    { label: 'Jump', name: 'jump (room mode)', key: ' ' },
    { label: 'Stop', name: 'stop spinning', key: 'x' },
    { label: 'Mode', name: 'mode: room / pivot / flip', key: 'm' },
  ],
  { label: 'spins and modes' },
);
extras.element.classList.add('rc-extras');
for (const [i, dir] of ['up', 'down', 'left', 'right'].entries()) dpad.buttons[i]!.dataset.dir = dir;
{
  const style = document.createElement('style');
  style.textContent = `
.bp-touchbar.rc-dpad { flex: 0 0 auto; display: grid; grid-template-columns: 56px 66px 56px; grid-template-rows: 50px 50px;
  grid-template-areas: 'left up right' 'left down right'; gap: 6px; padding: 2px 0 4px; }
.bp-touchbar.rc-dpad button, .bp-touchbar.rc-extras button { min-width: 0; min-height: 0; width: 100%; height: 100%; padding: 0; border-radius: 12px; }
.bp-touchbar.rc-dpad button { font-size: 24px; }
.bp-touchbar.rc-dpad button[data-dir='up'] { grid-area: up; }
.bp-touchbar.rc-dpad button[data-dir='down'] { grid-area: down; }
.bp-touchbar.rc-dpad button[data-dir='left'] { grid-area: left; }
.bp-touchbar.rc-dpad button[data-dir='right'] { grid-area: right; }
.bp-touchbar.rc-extras { flex: 0 0 auto; display: grid; grid-template-columns: repeat(3, 48px); grid-template-rows: 50px 50px; gap: 6px;
  padding: 2px 0 4px 12px; }
.bp-touchbar.rc-extras button { font-size: 14px; }
.bp-touchbar.rc-extras button:nth-child(-n + 2) { font-size: 20px; }
/* On the pivot the turn buttons carry words (Pitch ▲, Roll ⟲): a smaller type that fits their width. */
.bp-touchbar.rc-pivot button, .bp-touchbar.rc-extras.rc-pivot button:nth-child(-n + 2) { font-size: 14px; }
/* The round's end on the pivot: a sheet at the stage's foot, leaving the box on its stand in sight. */
.bp-result.rc-sheet { top: auto; bottom: 10px; transform: translateX(-50%); }
@media (max-width: 520px) {
  .bp-result.rc-sheet { width: calc(100% - 16px); max-width: none; bottom: 6px; padding: 10px 12px 10px; }
  .bp-result.rc-sheet .bp-result-big { margin: 0 0 2px; }
  .bp-result.rc-sheet .bp-result-line { font-size: 13px; line-height: 1.3; }
  .bp-result.rc-sheet .bp-result-buttons { margin-top: 6px; }
}
/* The touch card, two lines in a smaller type at the stage's foot, so it leaves the front of the floor in sight. */
body .bp-touch-hint { font-size: 13px; padding: 6px 10px; bottom: 6px; }
`;
  document.head.append(style);
}
// The kit's touch card (up to four lines over the stage's foot, fading at the first touch or after
// 9 s) covered the front of the room's floor. In the room it is swapped for a copy of its first two
// lines (tap, arrows), in a smaller type, that stays until the player's first touch, on the stage or
// on a button (a newcomer reading the goal first still finds it there).
{
  const kitCard = document.querySelector<HTMLElement>('[data-hud="touch-hint"]');
  if (kitCard && params.mode === 'room') {
    const card = kitCard.cloneNode(true) as HTMLElement;
    kitCard.replaceWith(card);
    [...card.children].slice(2).forEach((line) => {
      line.remove();
    });
    const arrows = card.children[1]?.lastElementChild;
    if (arrows) arrows.textContent = 'roll the cube';
    // The room's framing does not change when the card goes (fitBesideDrawer keeps the floor clear of
    // it all along), so nothing the player aims at moves.
    const hide = (): void => {
      card.classList.add('bp-gone');
      window.setTimeout(() => card.remove(), 700);
    };
    (app.canvas.parentElement ?? document.body).addEventListener('pointerdown', hide, { capture: true, once: true });
    for (const bar of [dpad.element, extras.element]) bar.addEventListener('pointerdown', hide, { once: true });
  }
}
/** The six turn buttons in the order of TURN_LABELS: the d-pad's four arrows and the two spins. */
const turnButtons = [...dpad.buttons, extras.buttons[0]!, extras.buttons[1]!];
/** Labels of the six turn buttons in the room and on the pivot. */
const TURN_LABELS = {
  room: ['▲', '▼', '◀', '▶', '⟲', '⟳'],
  pivot: ['Pitch ▲', 'Pitch ▼', 'Yaw ◀', 'Yaw ▶', 'Roll ⟲', 'Roll ⟳'],
  /** Free spin: the buttons push ω's tip on screen (up, down, left, right, toward the camera, away). */
  spin: ['▲', '▼', '◀', '▶', 'Near', 'Far'],
};
/** Labels the turn buttons for the current mode. */
function labelTurnButtons(): void {
  const labels = params.mode === 'room' ? TURN_LABELS.room : params.mode === 'cube' ? TURN_LABELS.spin : TURN_LABELS.pivot;
  for (const bar of [dpad.element, extras.element]) bar.classList.toggle('rc-pivot', params.mode !== 'room');
  labels.forEach((label, i) => {
    turnButtons[i]!.textContent = label;
  });
  // Jump does something only in the room: elsewhere its button keeps its place in the grid, hidden.
  const jumpButton = extras.buttons[2]!;
  jumpButton.disabled = params.mode !== 'room';
  jumpButton.style.visibility = params.mode === 'room' ? '' : 'hidden';
}
labelTurnButtons();

const right = new Vector3(),
  up = new Vector3(),
  back = new Vector3();
/** snapToEdge's answer: a level unit axis (x, y = 0, z) and 1, or 0 in [3] when there is none. */
const snapped = new Float64Array(4);
/** The cube's body axes x, y, z in the world: the columns of its orientation's rotation matrix (unit vectors). */
function bodyAxes(): number[][] {
  const q = shell.world.components.Orientation,
    e = handles.body;
  const x = q.x[e]!,
    y = q.y[e]!,
    z = q.z[e]!,
    w = q.w[e]!;
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
    [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
    [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)],
  ];
}

/**
 * Into `snapped`: of the cube's three body axes (the columns of its rotation matrix) those lying
 * within 30 degrees of level, the one (either way) most nearly along the level direction (ax, 0, az),
 * flattened to level and made unit; snapped[3] = 0 if no axis lies that level (the cube on an edge
 * or a corner: the axis is then used as it is).
 */
function snapToEdge(ax: number, az: number): void {
  const cols = bodyAxes();
  let best = 0;
  snapped[3] = 0;
  for (const c of cols) {
    if (Math.abs(c[1]!) > 0.5) continue;
    const l = Math.hypot(c[0]!, c[2]!);
    const dot = (c[0]! * ax + c[2]! * az) / l;
    if (Math.abs(dot) <= best) continue;
    best = Math.abs(dot);
    const sign = dot < 0 ? -1 : 1;
    snapped[0] = (sign * c[0]!) / l;
    snapped[2] = (sign * c[2]!) / l;
    snapped[3] = 1;
  }
}

/**
 * Room mode, on a roll key's press with rollAxis set: when a wall blocks that roll (scene.ts
 * `rollBlocked`), the resting cube only bumps towards the wall and falls back (`BUMP_SPIN`), no
 * torque and no latch, so the face on top stays and no move is counted; a pop says so.
 * @returns whether the roll was blocked (then rollAxis is cleared).
 */
function bumpWall(): boolean {
  const P = shell.world.components.Position,
    e = handles.body;
  // The travel d = axis x y = (-az, 0, ax).
  if (!rollBlocked(P.x[e]!, P.z[e]!, -rollAxis[2]!, rollAxis[0]!)) return false;
  rollStart(shell.world, e, rollAxis[0]!, rollAxis[2]!, BUMP_SPIN);
  rollAxis.fill(0);
  latchUntil = -1;
  settleArmed = true;
  showPop('Wall: no roll, no move', 1200, '#ffd7a8');
  return true;
}

/**
 * Room mode, after rollAxis is set from the roll keys pressed this frame: on a new roll key press (`fresh`) latches the
 * level part of rollAxis and sets a cube at rest turning over its edge (scene.ts `rollStart`); on the frames after the press (`rolling` false) while the latch is on, rolls on
 * about the latched axis until the cube has turned ROLL_LATCH_ANGLE since the press or
 * ROLL_LATCH_TIME s have passed (against a wall it may never turn that far).
 */
function latchRoll(fresh: boolean, rolling: boolean): void {
  const q = shell.world.components.Orientation,
    e = handles.body,
    t = shell.world.time;
  if (fresh && rolling) {
    const l = Math.hypot(rollAxis[0]!, rollAxis[2]!);
    latchAxis[0] = rollAxis[0]! / l;
    latchAxis[1] = 0;
    latchAxis[2] = rollAxis[2]! / l;
    latchQ[0] = q.x[e]!;
    latchQ[1] = q.y[e]!;
    latchQ[2] = q.z[e]!;
    latchQ[3] = q.w[e]!;
    latchUntil = t + ROLL_LATCH_TIME;
    settleArmed = true;
    // A cube at rest starts turning over its edge at once (scene.ts rollStart): the torque alone left it
    // barely moving for the first tenth of a second after the press.
    rollStart(shell.world, e, latchAxis[0]!, latchAxis[2]!);
  }
  if (rolling || t >= latchUntil) return;
  const dot = Math.abs(latchQ[0]! * q.x[e]! + latchQ[1]! * q.y[e]! + latchQ[2]! * q.z[e]! + latchQ[3]! * q.w[e]!);
  if (2 * Math.acos(Math.min(1, dot)) >= ROLL_LATCH_ANGLE) {
    latchUntil = -1;
    return;
  }
  rollAxis[0] = latchAxis[0]!;
  rollAxis[1] = 0;
  rollAxis[2] = latchAxis[2]!;
}

/**
 * Updates keyTorque (pivot) and rollAxis (room) from the keys held and the camera's axes (called every
 * frame). In the room W A S D roll the cube towards the screen's up, left, down and right along the
 * floor: about the axis y x d (d the direction of travel on the floor, the camera's right and its view
 * flattened onto the floor), so the top goes that way, snapped to the cube's nearest level edge
 * (`snapToEdge`: it goes over the edge facing most nearly that way); Q E turn it by quarter turns
 * about the vertical (`yawKeeper`).
 */
function updateKeyTorque(): void {
  const t = shell.world.time;
  // Flip mode: a press turns its key on for at least FLIP_TAP_TIME, so a tap steps the spin visibly.
  if (params.mode === 'flip') for (const k of pressed) tapUntil.set(k, t + FLIP_TAP_TIME);
  const on = (k: string): boolean => {
    if (held.has(k) || pressed.has(k)) return true;
    // Still within its tap's time (a time further ahead than that is left from a world since replaced).
    const left = (tapUntil.get(k) ?? t) - t;
    return left > 0 && left <= FLIP_TAP_TIME;
  };
  if (params.mode === 'room') queueRolls();
  else repeated.clear();
  const newRoll = pressed.has('w') || pressed.has('a') || pressed.has('s') || pressed.has('d');
  // In the room a roll key acts by its press (fresh, waiting or repeated by queueRolls) and the
  // roll's latch, not by being held: a held key's torque rolled the cube on past its cell.
  const rollOn = (k: string): boolean => (params.mode === 'room' ? pressed.has(k) : on(k));
  const pitch = (rollOn('s') ? 1 : 0) - (rollOn('w') ? 1 : 0);
  const yaw = (rollOn('d') ? 1 : 0) - (rollOn('a') ? 1 : 0);
  const roll = (on('q') ? 1 : 0) - (on('e') ? 1 : 0);
  // Room: Q and E turn the cube a quarter turn a press, and on while held (the next quarter once the turn is near its end).
  if (params.mode === 'room' && roll !== 0 && (pressed.has('q') || pressed.has('e') || !yawKeeper.turning)) {
    yawKeeper.turn(roll);
    if (!pads.done && !turnSaid) {
      turnSaid = true;
      showPop('A quarter turn counts as a move: it changes what each roll brings up', 2400, '#bfe9ff');
    }
    pads.turned();
  }
  pressed.clear();
  app.camera.matrixWorld.extractBasis(right, up, back);
  if (params.mode === 'room') {
    // Travel d = yaw right_flat - pitch forward_flat (forward = -back); axis = y x d = (d.z, 0, -d.x).
    const rl = Math.hypot(right.x, right.z) || 1,
      bl = Math.hypot(back.x, back.z) || 1;
    const dx = (yaw * right.x) / rl + (pitch * back.x) / bl,
      dz = (yaw * right.z) / rl + (pitch * back.z) / bl;
    let ax = dz,
      ay = 0,
      az = -dx;
    // A cube rolls cleanly only over an edge: turn about the near-level body axis nearest that axis.
    if (ax !== 0 || az !== 0) snapToEdge(ax, az);
    else snapped[3] = 0;
    if (snapped[3]! > 0) {
      ax = snapped[0]!;
      az = snapped[2]!;
    }
    const n = Math.hypot(ax, ay, az);
    if (n > 0) {
      ax /= n;
      ay /= n;
      az /= n;
    }
    rollAxis[0] = ax;
    rollAxis[1] = ay;
    rollAxis[2] = az;
    keyTorque.fill(0);
    if (newRoll && (pitch !== 0 || yaw !== 0) && bumpWall()) return;
    latchRoll(newRoll, pitch !== 0 || yaw !== 0);
    return;
  }
  rollAxis.fill(0);
  const T = params.torque * push() * (params.mode === 'flip' ? FLIP_PUSH : 1);
  if (params.mode === 'cube') {
    // The free-spin cube's inertia is the same about every axis, so a torque moves ω's tip along it:
    // D/A push the tip to the screen's right/left (±right), W/S up/down (±up), Q/E toward/away (±back).
    keyTorque[0] = T * (yaw * right.x - pitch * up.x + roll * back.x);
    keyTorque[1] = T * (yaw * right.y - pitch * up.y + roll * back.y);
    keyTorque[2] = T * (yaw * right.z - pitch * up.z + roll * back.z);
    return;
  }
  keyTorque[0] = T * (pitch * right.x + yaw * up.x + roll * back.x);
  keyTorque[1] = T * (pitch * right.y + yaw * up.y + roll * back.y);
  keyTorque[2] = T * (pitch * right.z + yaw * up.z + roll * back.z);
}

// ---- Clicks: in the room a push towards the floor point clicked (or away from the cube's face); on the pivot an impulse at the face

const canvas = app.canvas;
const ndc: [number, number] = [0, 0];
let downX = 0,
  downY = 0,
  downId = -1,
  /** Whether the finger's press (room mode) went down on the cube: a drag from there flicks it, the camera stays. */
  downOnCube = false;
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  downId = event.pointerId;
  downX = event.clientX;
  downY = event.clientY;
  downOnCube = false;
  if (event.pointerType !== 'mouse' && params.mode === 'room') {
    app.toNdc(event.clientX, event.clientY, ndc);
    downOnCube = rayHitsCube(ndc[0], ndc[1]);
    if (downOnCube && app.controls) app.controls.enabled = false;
  }
});
canvas.addEventListener('pointercancel', (event) => {
  if (event.pointerId !== downId) return;
  downId = -1;
  if (app.controls) app.controls.enabled = true;
});
canvas.addEventListener('pointerup', (event) => {
  if (event.pointerId !== downId) return;
  downId = -1;
  if (app.controls) app.controls.enabled = true;
  const moved = Math.hypot(event.clientX - downX, event.clientY - downY);
  if (event.pointerType !== 'mouse' && params.mode === 'room') {
    const does = touchPress(downOnCube, moved);
    if (does === 'flick') flickAlong(downX, downY, event.clientX, event.clientY);
    if (does !== 'push') return;
  } else if (moved > (event.pointerType === 'mouse' ? CLICK_SLOP : TAP_SLOP)) return;
  app.toNdc(event.clientX, event.clientY, ndc);
  // After a push its aim shows briefly (until the cube gets there, or a roll), then only a new hover shows one.
  if (clickAt(ndc[0], ndc[1])) {
    hover = false;
    aimUntil = performance.now() + 600;
  } else if (!rollToTapped()) sayWhyNot();
});
// A mouse shows where a click would push the cube; a finger (no hover) sees it after its tap.
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerType !== 'mouse' || downId !== -1) return;
  app.toNdc(event.clientX, event.clientY, ndc);
  hover = aimAt(ndc[0], ndc[1]) !== null || aimWhy !== '';
  if (hover) aimUntil = Infinity;
});
canvas.addEventListener('pointerleave', () => {
  hover = false;
  aimUntil = 0;
});
/** Whether the mouse hovers over a point a click would push the cube to. */
let hover = false;
/** Hides the aim marker (the arrow and the ring) until the mouse moves again: a roll makes it stale. */
function clearAim(): void {
  hover = false;
  aimUntil = 0;
}

const rayDir = new Vector3();

/** Points `rayDir` (unit) from the camera through the view point (ndcX, ndcY) (normalised device coordinates). */
function aimRay(ndcX: number, ndcY: number): void {
  rayDir.set(ndcX, ndcY, 0.5).unproject(app.camera).sub(app.camera.position).normalize();
}

/**
 * Where the camera's ray along `rayDir` meets the floor (y = 0), [x, z] m, or null (at or above the
 * horizon): the point under the pointer, where the pads and tiles are drawn. (Meeting the height of
 * the cube's centre instead put the point 0.5 m / tan(elevation) nearer the camera than the floor
 * under the pointer: a metre and more at the grazing angles near the back wall.)
 */
function rayAtFloor(): [number, number] | null {
  if (!(rayDir.y < -1e-6)) return null;
  const cam = app.camera.position;
  const t = -cam.y / rayDir.y;
  return [cam.x + rayDir.x * t, cam.z + rayDir.z * t];
}
/** What a room click at a point does: a push of the cube at `speed` m/s along (dx, dz) (unit), aiming at (x, z). */
interface Push {
  kind: 'floor' | 'cube';
  dx: number;
  dz: number;
  speed: number;
  x: number;
  z: number;
}
const aim: Push = { kind: 'floor', dx: 0, dz: 0, speed: 0, x: 0, z: 0 };
/** The last push given (for tests and the console), or null. */
let lastPush: Push | null = null;
const origin = new Float64Array(3),
  span = new Float64Array(3);
/** Why the last `aimAt` gave no push: '' (it gave one), 'here' (the cell is the cube's own), 'bed' (the cell is in the lit pad's bed of ROLL tiles, where no slide stops). */
let aimWhy: '' | 'here' | 'bed' = '';
/** The cell under the pointer of the last `aimAt` (its centre, x and z, m), drawn outlined while the mouse hovers. */
const hoverCell: [number, number] = [0, 0];

/**
 * Room mode: the centre of the floor cell that holds (x, z), m: the puzzle's cells are 1 m squares
 * centred on the lit pad (the last pad once the round is over; roll-puzzle.ts), and a cell is one
 * the cube fits in (centre within CELL_REACH of the room's middle). @returns [x, z], m.
 */
function cellAt(x: number, z: number): [number, number] {
  const pad = layout.pads[Math.min(pads.pad, layout.pads.length - 1)]!;
  const axis = (v: number, c: number): number => {
    const lo = Math.ceil(-CELL_REACH - c - 1e-9),
      hi = Math.floor(CELL_REACH - c + 1e-9);
    return c + Math.max(lo, Math.min(hi, Math.round(v - c)));
  };
  return [axis(x, pad[0]), axis(z, pad[1])];
}

/** Whether the ray through (ndcX, ndcY) hits the cube first (a ray cast through the physics that looks past the see-through walls). */
function rayHitsCube(ndcX: number, ndcY: number): boolean {
  aimRay(ndcX, ndcY);
  const cam = app.camera.position;
  origin[0] = cam.x;
  origin[1] = cam.y;
  origin[2] = cam.z;
  span[0] = rayDir.x * 200;
  span[1] = rayDir.y * 200;
  span[2] = rayDir.z * 200;
  return rayCastAll3D(shell.world, origin, span).some((h) => h.body === handles.body);
}

/**
 * Room mode: what a click at (ndcX, ndcY) would do, into `aim`: a push towards the centre of the
 * floor cell under the pointer (`cellAt` of where the ray meets the floor, whatever it passes
 * through first, the cube included: the cell drawn under the pointer is the one aimed at), at
 * `slideSpeed` of the distance, so the cube sliding on a face stops on that cell.
 * @returns `aim`, or null when the click would do nothing (not the room, the ray misses the floor,
 * the cell is in the lit pad's bed of tiles (`snapToBed`), or the cube already rests there: `aimWhy` says which).
 */
function aimAt(ndcX: number, ndcY: number): Push | null {
  aimWhy = '';
  if (params.mode !== 'room') return null;
  aimRay(ndcX, ndcY);
  const P = shell.world.components.Position,
    e = handles.body;
  const cx = P.x[e]!,
    cz = P.z[e]!;
  const level = rayAtFloor();
  if (level === null) return null;
  const [hx, hz] = cellAt(level[0], level[1]);
  hoverCell[0] = hx;
  hoverCell[1] = hz;
  // A cell in the lit pad's bed of ROLL tiles (the pad too) is one no slide stops on: the cube stays,
  // and the pop says to roll onto it (a slide to the bed's nearest edge cell went wherever that was,
  // often away from the cell clicked).
  const [x, z] = snapToBed(hx, hz);
  if (x !== hx || z !== hz || rollOnly()) {
    aimWhy = 'bed';
    return null;
  }
  const dist = Math.hypot(x - cx, z - cz);
  if (!(dist > 0.05)) {
    aimWhy = 'here';
    return null;
  }
  Object.assign(aim, { kind: 'floor', dx: (x - cx) / dist, dz: (z - cz) / dist, speed: slideSpeed(dist), x, z });
  return aim;
}

/**
 * Room mode, after a click or tap that `aimAt` refused for the lit pad's ROLL tiles (`aimWhy` 'bed'):
 * when the cell clicked is next to the cube's own (across a side, not a corner), presses the roll key
 * towards it (`rollKeyOf`; a key event, as the arrow buttons send), so a tap on a ROLL tile beside the
 * cube rolls it there instead of only saying to roll. @returns whether it did.
 */
function rollToTapped(): boolean {
  if (aimWhy !== 'bed' || params.mode !== 'room') return false;
  const P = shell.world.components.Position,
    e = handles.body;
  const [cx, cz] = cellAt(P.x[e]!, P.z[e]!);
  const di = Math.round(hoverCell[0] - cx),
    dj = Math.round(hoverCell[1] - cz);
  if (Math.abs(di) + Math.abs(dj) !== 1) return false;
  const key = rollKeyOf(di > 0 ? 0 : di < 0 ? 1 : dj > 0 ? 4 : 5);
  for (const type of ['keydown', 'keyup'] as const) window.dispatchEvent(new KeyboardEvent(type, { key, bubbles: true, cancelable: true }));
  return true;
}

/** Says in the pop why the click just made (`aimWhy`) moved nothing, and flashes a red ring on the cell clicked. */
function sayWhyNot(): void {
  const roll = pageLayout().touch() ? '▲◀▼▶' : 'W A S D';
  if (aimWhy === '') return;
  refusals++;
  refusedAt = performance.now();
  refuseMark.position.set(hoverCell[0], 0.04, hoverCell[1]);
  sound.chime(220, 0.12);
  if (aimWhy === 'here') showPop(`✗ The cube is on that cell: pick another, or roll it (${roll})`, 1600, '#ffb4a8');
  else if (rollOnly()) showPop(`✗ No slides to this pad: plan a route and roll all the way (${roll})`, 2200, '#ffb4a8');
  else showPop(`✗ Can't slide there: roll onto it (${roll})`, 1800, '#ffb4a8');
}

/**
 * Room mode: a flick of the cube along level direction (hx, hz) (any length), into `aim`: at
 * params.impulse ROOM_PUSH / m m/s, or slower to stop at the lit pad's bed's edge.
 * @returns `aim`, or null when (hx, hz) has no direction.
 */
function flickAim(hx: number, hz: number): Push | null {
  const P = shell.world.components.Position,
    e = handles.body;
  const cx = P.x[e]!,
    cz = P.z[e]!;
  const l = Math.hypot(hx, hz);
  if (!(l > 1e-9)) return null;
  if (rollOnly()) {
    aimWhy = 'bed';
    sayWhyNot();
    return null;
  }
  const speed = (params.impulse * ROOM_PUSH) / shell.world.components.Mass.value[e]!;
  Object.assign(aim, { kind: 'cube', dx: hx / l, dz: hz / l, speed });
  const d = speed ** 2 / (2 * ROOM_FRICTION * 9.81);
  const ux = cx + aim.dx * d,
    uz = cz + aim.dz * d;
  const [x, z] = snapToBed(ux, uz);
  const dist = Math.hypot(x - cx, z - cz);
  // A flick that would stop in the lit pad's bed stops at its edge instead (scene.ts PAD_BEDS).
  if ((x !== ux || z !== uz) && dist > 0.05) Object.assign(aim, { dx: (x - cx) / dist, dz: (z - cz) / dist, speed: slideSpeed(dist) });
  aim.x = x;
  aim.z = z;
  return aim;
}

/** Where the ray through CSS pixel (clientX, clientY) meets the floor, [x, z] m, or null (at or above the horizon). */
function levelPoint(clientX: number, clientY: number): [number, number] | null {
  app.toNdc(clientX, clientY, ndc);
  aimRay(ndc[0], ndc[1]);
  return rayAtFloor();
}

/** Room mode, a finger's drag from the cube, CSS px (x0, y0) to (x1, y1): flicks the cube the way the finger went across the floor. */
function flickAlong(x0: number, y0: number, x1: number, y1: number): void {
  const a = levelPoint(x0, y0),
    b = levelPoint(x1, y1);
  const p = a && b ? flickAim(b[0] - a[0], b[1] - a[1]) : null;
  if (!p) return;
  pushCube(p);
  hover = false;
  aimUntil = performance.now() + 600;
}

/**
 * Room mode: where a slide aimed at (x, z), m, stops: a point in the lit pad's bed of tiles or its edge
 * row moves to the nearest cell at the bed's edge (roll-puzzle.ts `bedSnap`), so the cube crosses the
 * bed by rolls; elsewhere, and once the round is over, (x, z) itself. @returns [x, z], m.
 */
function snapToBed(x: number, z: number): [number, number] {
  if (params.mode !== 'room' || pads.done) return [x, z];
  return bedSnap(padPuzzle(layout, pads.pad), x, z);
}

/** Room mode: whether the lit pad's ROLL tiles cover the whole floor (scene.ts ROLL_ONLY_BED): no slide or flick stops anywhere. */
function rollOnly(): boolean {
  return params.mode === 'room' && !pads.done && edgeCells(padPuzzle(layout, pads.pad)).length === 0 && (layout.beds[pads.pad] ?? -1) > 0;
}

/**
 * A click at (ndcX, ndcY). Room: the push of `aimAt`, an impulse at the centre of mass that sets the
 * cube's horizontal velocity to the push's (whatever it had: the same click always does the same
 * thing). Pivot: if the ray hits the body, an impulse of params.impulse N s along it at the point hit.
 * @returns whether the cube was pushed.
 */
function clickAt(ndcX: number, ndcY: number): boolean {
  const e = handles.body;
  if (params.mode === 'room') {
    const p = aimAt(ndcX, ndcY);
    if (!p) return false;
    pushCube(p);
    return true;
  }
  const hit = renderer.pick(ndcX, ndcY, app.camera);
  if (!hit || hit.eid !== e) return false;
  aimRay(ndcX, ndcY);
  const J = params.impulse * push();
  startClock();
  applyImpulseAtPoint(shell.world, e, [rayDir.x * J, rayDir.y * J, rayDir.z * J], hit.point);
  flash = 12;
  return true;
}
let flash = 0;

/** Room mode: gives the cube push `p`, an impulse at its centre of mass that sets its horizontal velocity to p's (a move of the round). */
function pushCube(p: Push): void {
  const e = handles.body;
  const c = shell.world.components,
    m = c.Mass.value[e]!;
  pads.start(shell.world.time);
  settleArmed = false;
  // A slide keeps the top face: the next pad that wants a face must be rolled onto after it.
  pads.slid();
  // A slide aimed at the lit pad with the face it wants on top: say at once that only a roll takes it.
  const spot = layout.pads[pads.pad],
    want = layout.faces[pads.pad] ?? -1;
  if (
    !pads.done &&
    spot &&
    want >= 0 &&
    topFace(shell.world, e) === want &&
    Math.abs(p.x - spot[0]) < 0.5 &&
    Math.abs(p.z - spot[1]) < 0.5
  ) {
    showPop(slidOnWords(), 2200, '#ffb4a8');
    blockedSaid = 'slide';
  }
  applyImpulse(shell.world, e, [m * (p.dx * p.speed - c.Velocity.x[e]!), 0, m * (p.dz * p.speed - c.Velocity.z[e]!)]);
  lastPush = { ...p };
  tappedCell[0] = hoverCell[0];
  tappedCell[1] = hoverCell[1];
  sound.launch(0.25 + (0.5 * p.speed) / 7);
  flash = 12;
}

/** Zeroes the body's angular velocity (X key, panel button). */
function stopSpin(): void {
  tapUntil.clear();
  const w = shell.world.components.AngularVelocity;
  w.x[handles.body] = 0;
  w.y[handles.body] = 0;
  w.z[handles.body] = 0;
}

/** Switches mode, rebuilds the world and frames it. */
function setMode(mode: Mode): void {
  params.mode = mode;
  params.showL = params.showOmega = params.axes = mode !== 'room';
  labelTurnButtons();
  const onTouch = pageLayout().touch();
  shell.hud.setControls([...cubeControls(mode, onTouch), ...ORBIT_CONTROLS]);
  // On a phone the kit shows its touch card again with new controls: the player switching modes has played already.
  if (onTouch) document.querySelector('[data-hud="touch-hint"]')?.remove();
  panel.refresh();
  shell.reset();
  const v = viewOf(mode);
  app.frame(v.min, v.max, viewDirectionOf(mode));
  framedMode = mode;
  clampOrbit();
  fitBesideDrawer();
  renderer.setDebug(params.axes ? debugOptions() : false);
}

const panel = createPanel(
  params,
  [
    {
      type: 'choice',
      key: 'mode',
      options: {
        'pads (roll the cube in a room)': 'room',
        'spin the cube (on a pivot)': 'cube',
        'flipping box (the Dzhanibekov effect)': 'flip',
      },
      onChange: (m) => setMode(m as Mode),
    },
    { type: 'slider', key: 'torque', label: 'key torque (N m)', min: 0.05, max: 3, step: 0.05 },
    { type: 'slider', key: 'impulse', label: 'click impulse (N s)', min: 0.02, max: 2, step: 0.02 },
    {
      type: 'slider',
      key: 'spin',
      label: 'flip spin (rad/s, rebuilds)',
      min: 0.5,
      max: 30,
      step: 0.5,
      onRelease: true,
      onChange: () => {
        if (params.mode === 'flip') shell.reset();
      },
    },
    { type: 'checkbox', key: 'showL', label: 'angular momentum L' },
    { type: 'checkbox', key: 'showOmega', label: 'angular velocity ω' },
    {
      type: 'checkbox',
      key: 'axes',
      label: 'contacts (room) / body axes (pivot)',
      onChange: (v) => renderer.setDebug(v === true ? debugOptions() : false),
    },
    { type: 'button', key: 'stop', label: 'stop spinning (X)' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Rotating cube' },
);

// ---- The challenge's status row (above the scene, on every screen) ---------------------------------

const status = createStatusRow({ name: 'challenge' });
const touch = pageLayout().touch();
// On a phone the row keeps its height: the goal and the numbers one line each (a longer text ends in
// an ellipsis), the hint two (a row that grew with a longer hint would shrink the stage and move the view).
if (touch)
  for (const line of [status.goal, status.numbers, status.hint]) {
    const one = line !== status.hint;
    line.style.cssText += one ? ';white-space: nowrap; overflow: hidden; text-overflow: ellipsis' : '';
    line.style.minHeight = one ? '1.4em' : '2.8em';
    line.style.boxSizing = 'border-box';
  }
const stars = starText;

// ---- The round's end: a banner with the result, Next (Enter) and Retry (R, the game's reset) --------

// The banner lets a drag outside its buttons through, so the scene behind it still turns.
const banner = createDomResultCard(app.canvas.parentElement ?? document.body, {
  name: 'win-banner',
  passThrough: true,
  titleColour: '#ffffff',
});
/**
 * Shows the round's end `end` (round-end.ts) in the banner: Retry (R, the game's reset) and Next (Enter).
 * On the pivot (the spins, the flipping box) it is a sheet at the stage's foot (`rc-sheet`), under
 * the box on its stand: in the middle it hid the box the round was about.
 */
function showBanner(end: RoundEndContent): void {
  banner.element.classList.toggle('rc-sheet', params.mode !== 'room');
  banner.show({
    title: end.title,
    big: end.big,
    lines: [end.detail],
    lost: !end.won,
    buttons: [
      { label: end.retry, keyHint: touch ? undefined : 'R', action: 'retry', onPress: () => shell.reset() },
      { label: end.next, keyHint: touch ? undefined : 'Enter', key: 'Enter', action: 'next', primary: true, onPress: () => nextRound() },
    ],
  });
}
shell.onWorldChange(() => banner.hide());
/** How long the banner waits after the round's end, ms: the last pad's chime, burst and pop come first. */
const BANNER_DELAY_MS = 1000;
/** performance.now() when the round's end was first seen (-1 while a round runs). */
let overSeenAt = -1;
/** The round after a finished one: in the room new pads; on the pivot the next mode (spins, then the flipping box, then the pads). */
function nextRound(): void {
  banner.hide();
  if (params.mode === 'room') {
    freshLayout = true;
    shell.reset();
  } else setMode(params.mode === 'cube' ? 'flip' : 'room');
}
/** Shows the banner once the mode's round is over (round-end.ts) and BANNER_DELAY_MS has passed; hides it otherwise. */
function updateBanner(): void {
  const now = performance.now();
  const end = roundEnd(params.mode, { pads, spins, flips }, shell.world, bestMoves, {
    kick: touch ? 'the Pitch ▲ ▼ buttons' : 'W or S',
    spinUp: touch ? 'Yaw ▶' : 'D',
    bestFlipTime,
  });
  if (!end) {
    overSeenAt = -1;
    banner.hide();
    return;
  }
  if (overSeenAt < 0) overSeenAt = now;
  if (now - overSeenAt >= BANNER_DELAY_MS) showBanner(end);
}

/**
 * Room mode: moves on a pad past its par after which the status row shows a shortest way on from where
 * the cube rests (`routeHint`): a newcomer stuck on a bed still clears the round, and by then three
 * stars (par + PAR_SLACK[0] over the round) are out of reach.
 */
const HINT_AFTER = 3;
/** The first slide of the route the status row shows (x, z, m), ringed on the floor; null when none shows. */
let hintSpot: [number, number] | null = null;
/** The ring on that tile and the pin over it (hint-mark.ts): the pin shows over a cube standing in front of the tile. */
const hintMark = createHintMark(0xffe27a);
app.scene.add(hintMark.group);
/** The key (on a phone the arrow) that rolls the cube along level world direction `d` (0 +x, 1 -x, 4 +z, 5 -z) with the camera where it is. */
function rollKey(d: number): string {
  const key = rollKeyOf(d);
  const arrows: Record<string, string> = { w: '▲', s: '▼', a: '◀', d: '▶' };
  return touch ? arrows[key]! : key.toUpperCase();
}
/** The roll key ('w', 'a', 's' or 'd') that rolls the cube along level world direction `d` (0 +x, 1 -x, 4 +z, 5 -z) with the camera where it is. */
function rollKeyOf(d: number): string {
  app.camera.matrixWorld.extractBasis(right, up, back);
  const tx = d === 0 ? 1 : d === 1 ? -1 : 0,
    tz = d === 4 ? 1 : d === 5 ? -1 : 0;
  // Each key's travel on the floor: W away from the viewer (-back), S towards, A left (-right), D right.
  const keys: [string, number, number][] = [
    ['w', -back.x, -back.z],
    ['s', back.x, back.z],
    ['a', -right.x, -right.z],
    ['d', right.x, right.z],
  ];
  let best = keys[0]!;
  for (const k of keys) if (k[1] * tx + k[2] * tz > best[1] * tx + best[2] * tz) best = k;
  return best[0];
}
/**
 * Whether this page visit has won a pad that wants a face (the first such pad of the first round
 * shows its way from the start, `routeHint`: a newcomer rolled WASD anywhere and slid onto it, which
 * does not count, before the rule "slide beside it, roll on" clicked).
 */
let rolledOntoFacePad = false;
/**
 * Room mode: once the moves on the lit pad (one that wants a face) pass its par by HINT_AFTER and the
 * cube rests, a shortest way on from there (scene.ts `padMoveRoute`) in keys ("slide to the ringed
 * tile, then D W W"), its first slide's tile ringed (`hintSpot`); on the visit's first pad that wants
 * a face, the same from its first move ("How: click the ringed tile, then W"), until one is won; else ''.
 */
function routeHint(): string {
  hintSpot = null;
  const firstFacePad = layout.faces.findIndex((f) => f >= 0);
  if (pads.pad > firstFacePad && firstFacePad >= 0) rolledOntoFacePad = true;
  const teach = !rolledOntoFacePad && pads.pad === firstFacePad;
  if (pads.done || (layout.faces[pads.pad] ?? -1) < 0 || (!teach && pads.padMoves < pads.padPar + HINT_AFTER)) return '';
  const c = shell.world.components,
    e = handles.body;
  if (Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!) > 0.05) return '';
  if (Math.hypot(c.AngularVelocity.x[e]!, c.AngularVelocity.y[e]!, c.AngularVelocity.z[e]!) > 0.1) return '';
  const route = padMoveRoute(shell.world, e, layout, pads.pad);
  if (!route || route.length === 0) return '';
  const spot = layout.pads[pads.pad]!;
  const words = route.map((m) => {
    if (m.kind === 'roll') return rollKey(m.direction);
    if (m.kind === 'turn') return touch ? (m.direction === 1 ? '⟲' : '⟳') : m.direction === 1 ? 'Q' : 'E';
    if (!m.to) return 'slide off the tiles,';
    if (!hintSpot) hintSpot = [spot[0] + m.to[0], spot[1] + m.to[1]];
    return `${touch ? 'tap' : 'click'} the ringed tile,`;
  });
  // The first slide's words end in a comma: the rolls after it are what lands the face on top.
  if (teach) return `How: ${words.join(' ').replace(/,$/, '').replace(/, /, ', then ')} to roll onto the pad`;
  return `Stuck? A shortest way from here: ${words.join(' ')}`;
}

/**
 * Room mode: while the cube rests flat and still (scene.ts `cubeStill`), counts the moves left on the
 * lit pad from there (scene.ts `padMovePar`, or SLID_ON_MOVES when slid on) into `toGo`; a new pad lit
 * forgets the last count (a trend across two pads would mean nothing).
 */
function readToGo(): void {
  if (pads.done) return;
  if (toGoPad !== pads.pad) {
    toGo.reset();
    toGoPad = pads.pad;
  }
  const e = handles.body;
  if (!cubeStill(shell.world, e) || shell.world.components.Position.y[e]! > 0.55) return;
  // Slid onto a pad that wants a face, with that face on top: the grid route sees it as there (0),
  // but only a roll on counts, and the fewest moves are a roll off and the same roll back.
  toGo.update(pads.blocked === 'slide' ? SLID_ON_MOVES : padMovePar(shell.world, e, layout, pads.pad));
}

/** The lit pad the status row last showed (-1 before any). */
let statusPad = -1;
/** Writes the status row: the mode's goal, its numbers (the key readout) and how to play. */
function updateStatus(wx: number, wy: number, wz: number): void {
  // Flip mode's spin: |L| over the intermediate moment, steady while the box flips (|ω| swings).
  const spin = flipSpin(Math.hypot(L[0]!, L[1]!, L[2]!));
  const world = shell.world,
    t = world.time,
    w = Math.hypot(wx, wy, wz);
  if (params.mode === 'room') {
    const want = layout.faces[pads.pad] ?? -1,
      name = FACE_NAMES[want];
    const par = pads.par;
    readToGo();
    // One short line each (on a phone each fits the width): the rules in full are behind the pads card's "?".
    let hint = touch ? 'Tap a cell: the cube slides there · ▲◀▼▶ roll it' : 'Click a cell: the cube slides there · W A S D roll it';
    if (want >= 0)
      hint = touch
        ? `ROLL onto the pad (▲◀▼▶) so ${name} lands on top`
        : `ROLL onto the pad (W A S D) so ${name} lands on top · the net shows what each roll brings up`;
    hint = routeHint() || hint;
    const time = pads.time();
    if (pads.done) {
      if (pads.moves < bestMoves) bestMoves = pads.moves;
      status.set(
        {
          goal: `All ${layout.pads.length} pads in ${pads.moves} moves ${stars(padStars(pads.moves, par))}`,
          numbers: `par ${par} · best ${bestMoves} moves · ${time.toFixed(1)} s`,
          hint: touch ? 'Next: new pads · ↻: the same pads again' : 'Enter: new pads · R: the same pads again',
        },
        true,
      );
    } else
      status.set({
        goal: touch
          ? `To the glowing pad, ${want >= 0 ? `${name} on top` : 'any face up'} (${pads.pad + 1} of ${layout.pads.length})`
          : `Land the cube on the glowing pad${want >= 0 ? ` with ${name} on top` : ', any face up'} (${pads.pad + 1} of ${layout.pads.length})`,
        // The lit pad's moves to go once counted (nothing before: "moves left: …" read as another count).
        numbers: [toGo.text(touch), roundMovesText(pads.moves, par, touch), touch ? '' : `${time.toFixed(1)} s`]
          .filter((part) => part !== '')
          .join(' · '),
        hint,
      });
  } else if (params.mode === 'flip') {
    const n = flips.counter.count;
    const over = flips.over(world);
    if (over && n > bestFlips) bestFlips = n;
    // The banner shows the best time before this round's (roundEnd takes the lower of the two), so it is kept here once the banner is up.
    const wonIn = flips.wonAt >= 0 ? flips.time(t) : Infinity;
    const [lo, hi] = FLIP_BAND;
    const inBand = spin >= lo && spin <= hi;
    // On a phone the numbers line has no room for the band (it ends in an ellipsis past the width), so the hint names it.
    const band =
      spin < lo
        ? touch
          ? `too slow: hold Yaw ▶ to spin it up to ${lo}–${hi}`
          : 'too slow: hold D to spin it up'
        : spin > hi
          ? `too fast: hold ${touch ? 'Yaw ◀' : 'A'} to brake`
          : touch
            ? 'in the band ✓ · it slows: tap Yaw ▶ · Pitch ▲ ▼ flips it sooner'
            : 'in the band ✓ · it slows down: tap D to keep it up · a kick (W or S) makes it flip sooner';
    status.set(
      over
        ? {
            goal:
              flips.wonAt >= 0
                ? `${FLIP_GOAL} flips in ${flips.time(t).toFixed(1)} s ${stars(flips.stars())}`
                : `Time! ${n} flips ${stars(flips.stars())}`,
            numbers: `best ${Number.isFinite(Math.min(bestFlipTime, wonIn)) ? `${Math.min(bestFlipTime, wonIn).toFixed(1)} s` : `${bestFlips} flips`} · ★★★ within ${FLIP_STAR_TIMES[0]} s, ★★ ${FLIP_STAR_TIMES[1]} s`,
            hint: touch ? 'Next: back to the pads · ↻: try again' : 'Enter: back to the pads · R: try again',
          }
        : {
            goal: touch
              ? `Flip the box over ${FLIP_GOAL} times in ${FLIP_TIME} s`
              : `Make the box flip over ${FLIP_GOAL} times in ${FLIP_TIME} s (★★★ within ${FLIP_STAR_TIMES[0]} s), spinning at ${lo} to ${hi} rad/s`,
            numbers: `Flips ${n}/${FLIP_GOAL} · ${(FLIP_TIME - flips.time(t)).toFixed(1)} s${touch ? '' : ' left'} · spin ${spin.toFixed(1)} ${inBand ? '✓' : '✗'}`,
            hint:
              flips.startedAt < 0
                ? `Clock starts at your first ${touch ? 'tap' : 'key'} · ${band}`
                : touch
                  ? band
                  : `Flips count only in the band: ${band}`,
          },
      over && flips.wonAt >= 0,
    );
  } else if (spins.won) {
    const time = spins.time(t);
    if (time < bestSpinTime) bestSpinTime = time;
    status.set(
      {
        goal: `All ${SPIN_TARGETS} spins in ${time.toFixed(1)} s ${stars(spins.stars())}`,
        numbers: `best ${bestSpinTime.toFixed(1)} s · ★★★ within ${SPIN_STAR_TIMES[0]} s, ★★ ${SPIN_STAR_TIMES[1]} s`,
        hint: touch ? 'Next: a box that flips over · ↻: again' : 'Enter: a box that flips over · R: again',
      },
      true,
    );
  } else {
    // A cube's inertia is the same about every axis, so its ω stays along L and a torque moves ω's tip the way it points.
    const off =
      spins.startedAt < 0 ? Math.hypot(wx - spins.targets[0]![0], wy - spins.targets[0]![1], wz - spins.targets[0]![2]) : spins.off;
    // A phone's numbers line is one line of about 40 characters: its short form keeps the tolerance and the clock in sight.
    // The meter: ten cells, eight of them filled at the ball's edge (spin-challenge.ts `spinCloseness`).
    const bar = closenessBar(spinCloseness(off));
    const how =
      spins.held > 0
        ? `${bar} holding ${spins.held.toFixed(1)} of ${SPIN_HOLD} s ✓`
        : touch
          ? `${bar} off ${off.toFixed(1)}`
          : `${bar} off by ${off.toFixed(2)} rad/s (in the ball: under ${SPIN_TOLERANCE})`;
    status.set({
      goal: touch
        ? `Magenta arrow onto cyan, hold ${SPIN_HOLD} s (${spins.target + 1} of ${SPIN_TARGETS})`
        : `Turn the magenta spin arrow onto the cyan one and hold it ${SPIN_HOLD} s (${spins.target + 1} of ${SPIN_TARGETS})`,
      numbers: `${how}${touch ? '' : ` · spin ${w.toFixed(2)} rad/s`} · ${spins.time(t).toFixed(1)} s`,
      hint: touch
        ? 'Torque (green arrow) moves ω along it: aim it down the white gap, let go early: the spin keeps going'
        : "W/S A/D Q/E torque: the green arrow moves ω's tip; aim it down the white gap, let go before the ball: L is kept, it coasts on",
    });
  }
}

// ---- The face net (top left of the stage): which colour each roll brings on top ------------------

/**
 * A cross of six small squares over the stage's top left corner: in the middle the face on top now,
 * around it the face each roll key would bring on top (▲/W: the face towards the viewer, ▼/S: the one
 * facing away, ◀/A: the one on the right, ▶/D: the one on the left: a cube rolls over the edge it
 * tips towards), and under ▼ the face underneath, captioned '2 rolls' (two rolls the same way). The face the lit pad wants wears
 * a ring, so the player plans the rolls before making them. Room mode only.
 */
const net = document.createElement('div');
net.dataset.hud = 'face-net';
// Part of the scene's drawing (like a label on it), not page furniture covering the scene.
net.dataset.sceneOverlay = '';
net.setAttribute('aria-label', 'faces of the cube');
net.style.cssText =
  'position: absolute; left: 8px; top: 8px; z-index: 4; pointer-events: none; display: grid; gap: 3px;' +
  'grid-template-columns: repeat(3, var(--cell)); grid-template-rows: auto repeat(4, var(--cell)); --cell: clamp(28px, 7vmin, 34px);' +
  'padding: 6px; border-radius: 8px; background: rgba(8, 12, 20, 0.78); font: 600 11px system-ui, sans-serif; color: #e8ecf1;';
const netTitle = document.createElement('div');
netTitle.style.cssText = 'grid-column: 1 / 4; text-align: center; white-space: nowrap; padding-bottom: 2px';
netTitle.textContent = 'rolls bring up';
net.append(netTitle);
/** The net's cells: top (on top now), and the faces ▲ ▼ ◀ ▶ would bring up, and the bottom. */
const NET_CELLS = [
  { name: 'w', row: 2, col: 2, key: touch ? '▲' : 'W' },
  { name: 'a', row: 3, col: 1, key: touch ? '◀' : 'A' },
  { name: 'top', row: 3, col: 2, key: '' },
  { name: 'd', row: 3, col: 3, key: touch ? '▶' : 'D' },
  { name: 's', row: 4, col: 2, key: touch ? '▼' : 'S' },
  { name: 'bottom', row: 5, col: 2, key: touch ? '▼▼' : 'S S' },
] as const;
const netCells = NET_CELLS.map((c) => {
  const cell = document.createElement('div');
  cell.dataset.cell = c.name;
  cell.style.cssText =
    `grid-row: ${c.row}; grid-column: ${c.col}; border-radius: 4px; display: flex; align-items: center; justify-content: center;` +
    'font: 700 10px system-ui, sans-serif; box-sizing: border-box; border: 2px solid rgba(0, 0, 0, 0.5)';
  // The key on a dark chip: legible on every face colour (WCAG AA), light or dark.
  if (c.key !== '') {
    const chip = document.createElement('span');
    chip.textContent = c.key;
    chip.style.cssText = 'background: #0b0f18; color: #fff; border-radius: 3px; padding: 0 3px; line-height: 1.3';
    cell.append(chip);
  }
  net.append(cell);
  return cell;
});
{
  // Beside the bottom face: it takes two rolls the same way to bring up.
  const caption = document.createElement('div');
  caption.textContent = '2 rolls';
  caption.style.cssText =
    'grid-row: 5; grid-column: 3; display: flex; align-items: center; font: 600 9px/1.1 system-ui, sans-serif; color: #c8d0dc';
  net.append(caption);
  const stage = app.canvas.parentElement ?? document.body;
  stage.append(net);
}
/** The faces in the net's cells last drawn (index into FACES per cell), for `faces()` and to skip redraws. */
const netFaces: number[] = NET_CELLS.map(() => -1);
let netWant = -2;
/** Of the cube's six faces, the one whose outward normal points most nearly along level (dx, 0, dz). */
function faceToward(cols: number[][], dx: number, dz: number): number {
  let best = 0,
    bestDot = -Infinity;
  for (let f = 0; f < FACES.length; f++) {
    const c = cols[f >> 1]!,
      sign = f & 1 ? -1 : 1;
    const dot = sign * (c[0]! * dx + c[2]! * dz);
    if (dot > bestDot) [best, bestDot] = [f, dot];
  }
  return best;
}
/** Redraws the net from the cube's orientation and the camera (every few frames). */
function updateNet(): void {
  const room = params.mode === 'room';
  net.style.display = room ? 'grid' : 'none';
  if (!room) return;
  // The body's axes in the world: the columns of its rotation matrix.
  const cols = bodyAxes();
  app.camera.matrixWorld.extractBasis(right, up, back);
  const rl = Math.hypot(right.x, right.z) || 1,
    bl = Math.hypot(back.x, back.z) || 1;
  const rx = right.x / rl,
    rz = right.z / rl,
    bx = back.x / bl,
    bz = back.z / bl;
  const top = topFace(shell.world, handles.body);
  // W rolls away: the face towards the viewer comes up; S the far one; A (left) the right one; D the left one.
  const faces = [faceToward(cols, bx, bz), faceToward(cols, rx, rz), top, faceToward(cols, -rx, -rz), faceToward(cols, -bx, -bz), top ^ 1];
  const want = pads.done ? -1 : (layout.faces[pads.pad] ?? -1);
  if (faces.every((f, i) => f === netFaces[i]) && want === netWant) return;
  netWant = want;
  faces.forEach((f, i) => {
    netFaces[i] = f;
    const cell = netCells[i]!;
    cell.style.background = faceCss(f);
    cell.style.outline = f === want ? '3px solid #fff' : 'none';
    cell.style.outlineOffset = '1px';
    cell.title = FACE_NAMES[f]!;
  });
  netCells[2]!.style.border = '2px solid #fff';
}

// ---- The pads card (top right of the stage): the round's pads in turn, the rules behind its "?" ----

/**
 * A small card over the stage's top right in the room: the five pads in turn as chips in the colour
 * that must be on top there (the first: any face), the ones reached ticked and the lit one ringed, and
 * a "?" button that opens the rules in a few lines (closed at the start, so a player is not met by a
 * wall of rules before playing; the status row says the one thing to do now). The rules close again at the first
 * roll key (W A S D, ▲◀▼▶) or a second press of "?". Room mode only, while the round runs.
 */
const rules = document.createElement('div');
rules.dataset.hud = 'pad-rules';
rules.dataset.sceneOverlay = '';
rules.style.cssText =
  'position: absolute; right: 8px; top: 8px; z-index: 4; pointer-events: none; box-sizing: border-box;' +
  `width: ${touch ? 'min(236px, calc(100% - 128px))' : '260px'}; padding: 6px 8px; border-radius: 8px;` +
  'background: rgba(8, 12, 20, 0.82); color: #e8ecf1; font: 500 12px/1.35 system-ui, sans-serif';
const rulesRow = document.createElement('div');
rulesRow.style.cssText = 'display: flex; gap: 5px; align-items: center';
const rulesChips = document.createElement('div');
rulesChips.style.cssText = 'display: flex; gap: 5px; flex: 1 1 auto';
const rulesToggle = document.createElement('button');
rulesToggle.type = 'button';
rulesToggle.textContent = '?';
rulesToggle.setAttribute('aria-label', 'how to play');
rulesToggle.setAttribute('aria-expanded', 'false');
// A finger's target: 44 px on a touch screen (the usual minimum), smaller beside a mouse.
rulesToggle.style.cssText =
  `pointer-events: auto; flex: 0 0 auto; width: ${touch ? 44 : 30}px; height: ${touch ? 44 : 30}px; border-radius: 50%; cursor: pointer;` +
  'border: 2px solid #8fa3c4; background: #1d2738; color: #fff; font: 700 16px system-ui, sans-serif; padding: 0';
rulesRow.append(rulesChips, rulesToggle);
const rulesText = document.createElement('div');
rulesText.style.cssText = 'margin-top: 6px; display: none';
/**
 * The legend of the roll-only tiles (the lit pad's bed), under the chips while that pad has a bed: a
 * small tile as drawn on the floor (dashed rim, circular arrow) and what it means.
 */
const bedLegend = document.createElement('div');
bedLegend.dataset.hud = 'bed-legend';
bedLegend.style.cssText = 'margin-top: 6px; display: none; align-items: center; gap: 7px; font: 600 12px/1.25 system-ui, sans-serif';
/** The legend's words: what the lit pad's tiles ask (`markChips` says more when they cover the floor). */
const bedWords = document.createElement('span');
{
  const swatch = document.createElement('span');
  swatch.textContent = '⟳';
  swatch.setAttribute('aria-hidden', 'true');
  swatch.style.cssText =
    'flex: 0 0 auto; width: 24px; height: 24px; box-sizing: border-box; border: 2px dashed #dbe5f7; border-radius: 5px;' +
    'background: rgba(196, 210, 238, 0.3); color: #fff; display: flex; align-items: center; justify-content: center; font: 700 15px system-ui, sans-serif';
  bedLegend.append(swatch, bedWords);
}
rules.append(rulesRow, bedLegend, rulesText);
(app.canvas.parentElement ?? document.body).append(rules);
/** Whether the rules (behind "?") are open. */
let rulesShown = false;
rulesToggle.addEventListener('pointerdown', (e) => e.stopPropagation());
rulesToggle.addEventListener('click', () => (rulesShown ? hideRules() : openRules()));
/** Opens the rules under the chips. */
function openRules(): void {
  rulesShown = true;
  rulesText.style.display = 'block';
  rulesToggle.setAttribute('aria-expanded', 'true');
}
/** Fills the pads card for this round's layout (room mode) with its rules closed. */
function showRules(): void {
  rulesChips.replaceChildren(
    ...layout.faces.map((f, i) => {
      const chip = document.createElement('div');
      chip.dataset.face = f >= 0 ? FACE_NAMES[f]! : 'any';
      chip.title = f >= 0 ? `pad ${i + 1}: ${FACE_NAMES[f]} on top` : `pad ${i + 1}: any face`;
      chip.style.cssText =
        'flex: 1 1 0; height: 26px; border-radius: 5px; display: flex; align-items: center; justify-content: center; box-sizing: border-box;' +
        (f >= 0 ? `background: ${faceCss(f)}; border: 2px solid rgba(0, 0, 0, 0.5)` : 'border: 2px dashed #22d3ee');
      const label = document.createElement('span');
      label.textContent = f >= 0 ? `${i + 1}` : `${i + 1} any`;
      label.style.cssText =
        'background: #0b0f18; color: #fff; border-radius: 3px; padding: 0 4px; font: 700 11px system-ui, sans-serif; white-space: nowrap';
      chip.append(label);
      return chip;
    }),
  );
  const three = `${stars(3)}: par + ${PAR_SLACK[0]} moves or fewer.`;
  rulesText.textContent = touch
    ? `Land on the pads in turn. From pad 2, ROLL on with the chip's colour on top (a slide keeps the top face); from pad 3 slides stop at the ROLL tiles round the pad; pad 5 has them over the whole floor: roll all the way there. Every slide, roll and turn is a move; "best: N more moves" counts the fewest left. The clock runs only while the cube is still. ${three}`
    : `Land on the pads in turn. From pad 2, ROLL on (W A S D) with the chip's colour on top: a slide keeps the top face. From pad 3 slides stop at the ROLL tiles round the pad, so the route across them decides the face; pad 5 has them over the whole floor, so plan a route of rolls from pad 4: the net at the left shows what each roll brings up, and "best: N more moves" counts the fewest left. Every slide, roll and quarter turn (Q E) is a move. The clock runs only while the cube is still. ${three}`;
  hideRules();
  markChips();
}
/** Ticks the chips of the pads reached and rings the lit one (the card hides once the round is over, or out of the room). */
function markChips(): void {
  rules.style.display = params.mode === 'room' && !pads.done ? 'block' : 'none';
  bedLegend.style.display = (layout.beds[pads.pad] ?? -1) > 0 ? 'flex' : 'none';
  [...rulesChips.children].forEach((chip, i) => {
    const el = chip as HTMLElement;
    el.style.opacity = i < pads.pad ? '0.45' : '1';
    el.style.outline = i === pads.pad ? '2px solid #fff' : 'none';
    el.style.outlineOffset = '1px';
    const label = el.firstElementChild as HTMLElement | null;
    if (label) label.textContent = i < pads.pad ? '✓' : layout.faces[i]! >= 0 ? `${i + 1}` : `${i + 1} any`;
  });
}
/** Closes the rules (the player's first roll, or "?" again). */
function hideRules(): void {
  rulesShown = false;
  rulesText.style.display = 'none';
  rulesToggle.setAttribute('aria-expanded', 'false');
}
showRules();
shell.onWorldChange(showRules);

// ---- Readout and plot (bottom right) -------------------------------------------------------------

const box = document.createElement('div');
box.style.cssText = 'display: flex; flex-direction: column; gap: 6px';
const readout = document.createElement('div');
readout.className = 'bp-hud';
readout.style.cssText = 'position: static; min-width: 240px';
readout.dataset.hud = 'rotation';
const lines = Array.from({ length: 6 }, () => readout.appendChild(document.createElement('div')));
box.append(readout);
pageLayout().side.append(box);
// The plot is optional: uPlot throws while loading when the browser reports a locale Intl rejects
// (headless Chromium under LANG=C.UTF-8 says 'en-US@posix'), so it is loaded lazily and skipped then.
// Not awaited: the rest of this module (the phone's framing of the room, the hooks) is in place
// before the first frame is drawn, so the room does not jump once the plot's code has arrived.
let plot: Plot | null = null;
import('@bitphysics/game-kit/plot')
  .then(({ createPlot }) => {
    plot = createPlot({
      parent: box,
      title: 'ω in the body frame (rad/s)',
      xLabel: 'time (s)',
      width: 340,
      height: 170,
      capacity: 900,
      redrawEvery: 10,
      series: [
        { label: 'ω_x', color: '#ff5a5f' },
        { label: 'ω_y', color: '#5fd068' },
        { label: 'ω_z', color: '#4d8dff' },
      ],
    });
  })
  .catch((error: unknown) => {
    console.warn('rotating-cube: no plot:', error instanceof Error ? error.message : error);
  });

/** Per frame: key torque, arrows, readout, plot. */
function frame(): void {
  updateKeyTorque();
  const world = shell.world,
    e = handles.body;
  const c = world.components;
  spinAngularMomentum(world, e, L);
  const wx = c.AngularVelocity.x[e]!,
    wy = c.AngularVelocity.y[e]!,
    wz = c.AngularVelocity.z[e]!;
  // L is drawn on the same scale as w: L / I_mid (rad/s) times omegaScale.
  const I = handles.inertia;
  const iMid = Math.max(Math.min(I[0], I[1]), Math.min(Math.max(I[0], I[1]), I[2]));
  const P = c.Position;
  const o = params.mode === 'room' ? [P.x[e]!, P.y[e]!, P.z[e]!] : handles.pivot;
  if (params.showL) lArrow.set(o[0], o[1], o[2], L[0]!, L[1]!, L[2]!, (L_DRAWN * omegaScale) / iMid);
  else lArrow.hide();
  if (params.showOmega) wArrow.set(o[0], o[1], o[2], wx, wy, wz, omegaScale);
  else wArrow.hide();
  wTip.visible = params.mode === 'cube' && params.showOmega && Math.hypot(wx, wy, wz) * omegaScale > 0.02;
  wTip.position.set(o[0] + wx * omegaScale, o[1] + wy * omegaScale, o[2] + wz * omegaScale);
  wTip.quaternion.copy(app.camera.quaternion);
  // The labels are page elements over the canvas: under a round's end card they would cover its words.
  const card = banner.shown;
  placeArrowLabel(0, params.showL && !card, o, L[0]!, L[1]!, L[2]!, (L_DRAWN * omegaScale) / iMid);
  placeArrowLabel(1, params.showOmega && !card, o, wx, wy, wz, omegaScale);
  pivotPost.visible = pivotFoot.visible = params.mode !== 'room';
  if (world.steps !== lastPlotted) {
    lastPlotted = world.steps;
    const q = c.Orientation;
    rotateVectorInverse(q.x[e]!, q.y[e]!, q.z[e]!, q.w[e]!, wx, wy, wz, wb);
    plot?.push(world.time, wb[0]!, wb[1]!, wb[2]!);
  }
  if (frames++ % 10 === 0) {
    lines[0]!.textContent = `|ω| ${Math.hypot(wx, wy, wz).toFixed(3)} rad/s`;
    lines[1]!.textContent = `|L| ${Math.hypot(L[0]!, L[1]!, L[2]!).toFixed(4)} kg m²/s`;
    lines[2]!.textContent = `E_rot ${spinKineticEnergy(world, e).toFixed(4)} J`;
    lines[3]!.textContent =
      flash > 0
        ? 'impulse!'
        : params.mode === 'room'
          ? `height ${P.y[e]!.toFixed(2)} m · speed ${Math.hypot(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!).toFixed(2)} m/s`
          : `I = ${handles.inertia.map((v) => v.toFixed(3)).join(', ')} kg m²`;
    lines[4]!.textContent = `arrows: L yellow (shorter), ω magenta; ω 1 rad/s = ${omegaScale.toFixed(2)} m`;
    // For a cube (equal moments) L stays parallel to w; for other boxes it does not.
    const lw = Math.hypot(L[0]!, L[1]!, L[2]!) * Math.hypot(wx, wy, wz);
    const angle = lw > 0 ? (Math.acos(Math.min(1, (L[0]! * wx + L[1]! * wy + L[2]! * wz) / lw)) * 180) / Math.PI : 0;
    lines[5]!.textContent = `angle between L and ω ${angle.toFixed(1)}°`;
  }
  // Every 5th frame, and at once when a pad is reached (at a phone's few frames a second the row
  // still named the reached pad while its pop said it was done).
  if (frames % 5 === 0 || statusPad !== pads.pad) {
    statusPad = pads.pad;
    updateStatus(wx, wy, wz);
  }
  drawSpinTarget();
  // On a phone the room's framing follows the camera (it eases into its view after a load, and the player orbits it).
  if (tallStage() && params.mode === 'room') {
    if (framingReady) fitBesideDrawer();
    else unframedFrames++;
  }
  if (frames % 3 === 0) updateNet();
  // The lit pad glows (pulsing) while the room's round runs; the ones to come are outlined, the ones reached gold.
  const room = params.mode === 'room';
  const padLit = room && !pads.done;
  padMesh.visible = padLit;
  const now = performance.now();
  if (padLit) {
    const spot = layout.pads[pads.pad]!,
      k = layout.halves[pads.pad]! / PAD_HALF;
    padMesh.scale.set(k, 1, k);
    padMesh.position.set(spot[0], 0.02, spot[1]);
    // A pad that takes any face glows cyan; one that wants a face glows in that face's colour
    const material = padMesh.material as MeshStandardMaterial,
      want = layout.faces[pads.pad]!;
    // (a face colour glows faintly, so the pad reads as the same colour as the face, not washed out).
    material.color.setHex(want >= 0 ? faceColors[want]! : ANY_COLOR);
    material.emissive.setHex(want >= 0 ? faceColors[want]! : ANY_COLOR);
    // Brighter, steady, with its rim drawn, while the cube's centre is over the counting square.
    material.emissiveIntensity = pads.over ? 0.9 : 0.3 + 0.15 * Math.sin(now / 250);
    const rim = (layout.halves[pads.pad]! + PAD_GRACE) / PAD_HALF;
    padRim.scale.set(rim, 1, rim);
    padRim.position.set(spot[0], 0.025, spot[1]);
  }
  padRim.visible = padLit && pads.over;
  {
    // The look's ground at the room's floor, or on the pivot at the plane under it (PIVOT_FLOOR_Y);
    // the renderer's plain floor plane is hidden under the look's floor and terrace.
    look.setShown(true, room ? 0 : PIVOT_FLOOR_Y);
    const plane = app.scene.getObjectByName('planes');
    if (plane) plane.visible = false;
    const spot = layout.pads[pads.pad],
      want = layout.faces[pads.pad] ?? -1;
    const glow = padLit && spot ? (pads.over ? 1 : 0.65 + 0.25 * Math.sin(now / 250)) : 0;
    look.update(
      app.camera.position,
      spot?.[0] ?? 0,
      spot?.[1] ?? 0,
      layout.halves[pads.pad] ?? PAD_HALF,
      want >= 0 ? faceColors[want]! : ANY_COLOR,
      glow,
    );
  }
  // The footprint follows the cube's centre while it is near the floor (not high in a jump), square to its grid.
  footprint.visible = footprintThrough.visible = room && P.y[e]! < 0.9;
  footprint.position.set(P.x[e]!, 0.03, P.z[e]!);
  footprintThrough.position.copy(footprint.position);
  {
    // The heading of the body's most nearly level axis (atan2(x, z)): the outline turns with the cube's sides.
    const q = c.Orientation,
      qx = q.x[e]!,
      qy = q.y[e]!,
      qz = q.z[e]!,
      qw = q.w[e]!;
    const axes = [
      [1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + qw * qz), 2 * (qx * qz - qw * qy)],
      [2 * (qx * qz + qw * qy), 2 * (qy * qz - qw * qx), 1 - 2 * (qx * qx + qy * qy)],
    ];
    const level = Math.abs(axes[0]![1]!) < Math.abs(axes[1]![1]!) ? axes[0]! : axes[1]!;
    footprint.rotation.y = footprintThrough.rotation.y = Math.atan2(level[0]!, level[2]!);
  }
  hintMark.place(padLit ? hintSpot : null, now / 1000, app.camera.quaternion);
  placeBed(padLit ? pads.pad : -1);
  {
    const tilesPad = layout.pads[Math.min(pads.pad, layout.pads.length - 1)]!;
    floorTiles.visible = room;
    placeTiles(tilesPad[0], tilesPad[1]);
  }
  padMarks.forEach((mark, i) => {
    mark.outline.visible = room && i > pads.pad;
    mark.done.visible = room && i < pads.pad;
  });
  // The round won: every pad, the last one too, glows gold (pulsing) until the next round; while it
  // runs the pads reached are a dim grey tick, so the lit pad (and a yellow one) stands out.
  padDoneMaterial.color.setHex(pads.done ? 0xffd34d : PAD_DONE_GREY);
  padDoneMaterial.opacity = pads.done ? 0.75 + 0.25 * Math.sin(now / 220) : 0.55;
  if (frames % 5 === 0) markChips();
  celebrate();
  updateBanner();
  sayBlocked();
  const refuseAge = (now - refusedAt) / REFUSE_MS;
  refuseMark.visible = room && refuseAge >= 0 && refuseAge < 1;
  // Two blinks, then a fade.
  if (refuseMark.visible)
    (refuseMark.material as MeshBasicMaterial).opacity = refuseAge < 0.4 && refuseAge % 0.2 > 0.1 ? 0.25 : 0.95 * (1 - refuseAge ** 2);
  const age = (now - burstAt) / BURST_MS;
  burst.visible = room && age >= 0 && age < 1;
  if (burst.visible) {
    burst.scale.setScalar(PAD_HALF * (1 + 1.6 * age));
    (burst.material as MeshBasicMaterial).opacity = 1 - age;
  }
  // The aim: an arrow on the floor from the cube the way a click would push it, to the point it would stop.
  let aimed = room && now < aimUntil && (hover ? aimWhy === '' && aim : lastPush);
  // The cell under the pointer, outlined (a mouse's hover, or a finger's tap for a moment after it).
  cellMark.visible = room && now < aimUntil && (hover || aimed !== false);
  if (cellMark.visible) cellMark.position.set(hover ? hoverCell[0] : tappedCell[0], 0.036, hover ? hoverCell[1] : tappedCell[1]);
  // A push's aim goes once the cube has got there.
  if (aimed && !hover && Math.hypot(P.x[e]! - aimed.x, P.z[e]! - aimed.z) < 0.3) {
    aimUntil = 0;
    aimed = false;
  }
  if (aimed) {
    const ox = P.x[e]!,
      oz = P.z[e]!;
    aimArrow.set(ox, 0.06, oz, aimed.x - ox, 0, aimed.z - oz, 1);
    aimRing.position.set(aimed.x, 0.03, aimed.z);
    aimRing.visible = true;
  } else {
    aimArrow.hide();
    aimRing.visible = false;
  }
  if (flash > 0) flash--;
}

// ---- The settings drawer: on a wide window it opens over the stage's right, so the room moves aside

const corner = new Vector3();
/**
 * Fits the room's box (floor and walls) into the part of the stage the overlays leave free, by the
 * camera's view offset and zoom (its position and the orbit stay as they are): with the settings
 * drawer open over the stage (a wide window: the game arrangement's drawer) the part left of it,
 * shifted left and zoomed out when it would not fit; on a tall stage (a phone) the room's floor
 * between the face net and the touch card (TOUCH_CARD_SPACE above the stage's foot), as large as
 * that band and the width allow (the floor's width and TALL_SIDE_MARGIN, zoomed at most
 * TALL_ZOOM_MAX; the walls' thickness and the back wall's top may run past the sides and under the
 * net) and as low as that leaves it (centred between the net and ROOM_FOOT_SPACE above the foot, so
 * the front wall's foot sits just above the buttons rather than over an empty strip). The same
 * framing holds whether the touch card shows or not: the room does not move when it goes.
 * Otherwise, and on the pivot, the camera's own framing.
 */
/** On a tall stage, the height kept clear of the room's floor above the stage's foot, CSS px: the touch card's (two lines). */
const TOUCH_CARD_SPACE = 80;
/** On a tall stage, the height above the stage's foot that the room is centred above when that leaves the floor clear of the touch card, CSS px. */
const ROOM_FOOT_SPACE = 8;
/** On a tall stage, how far past the floor's side edges the width fitted reaches, m (a strip of the walls' feet: the floor's edge reads as the room's). */
const TALL_SIDE_MARGIN = 0.1;
/** On a tall stage, the most the room is magnified past the camera's own framing of it (the room's box with walls 1 m high). */
const TALL_ZOOM_MAX = 1.3;
function fitBesideDrawer(): void {
  const cam = app.camera;
  cam.clearViewOffset();
  cam.zoom = 1;
  cam.updateProjectionMatrix();
  const open = pageLayout().root.dataset.open === 'side';
  const c = app.canvas.getBoundingClientRect(),
    d = pageLayout().side.getBoundingClientRect();
  const covered = open && d.width > 0 ? Math.max(0, c.right - d.left + 8) : 0;
  const below = tallStage() && !open ? Math.max(0, net.getBoundingClientRect().bottom - c.top + 6) : 0;
  if (params.mode !== 'room' || (covered === 0 && below === 0) || covered > 0.7 * c.width || below > 0.5 * c.height) return;
  cam.updateMatrixWorld();
  // The box's extent on the screen, in normalised device coordinates: x in [ax, bx], y in [ay, by].
  let ax = Infinity,
    bx = -Infinity,
    ay = Infinity,
    by = -Infinity;
  for (const x of [-ROOM_HALF, ROOM_HALF])
    for (const y of below > 0 ? [0] : [0, WALL_HEIGHT])
      for (const z of [-ROOM_HALF, ROOM_HALF]) {
        corner.set(x, y, z).project(cam);
        ax = Math.min(ax, corner.x);
        bx = Math.max(bx, corner.x);
        ay = Math.min(ay, corner.y);
        by = Math.max(by, corner.y);
      }
  // Under the net (a phone held upright) the height is the floor's, and the width the floor's with
  // TALL_SIDE_MARGIN of the walls' feet: the whole floor stays in sight, as large as the phone's width
  // lets it be, while the walls' thickness and their tops, leaning out towards the camera, may run
  // past the screen's sides (fitting the walls' outer feet kept the floor to 85% of the width, the
  // cube some 50 px; fitting their tops too left the room a third of the phone's height).
  let wx = 0;
  if (below > 0) {
    const outer = ROOM_HALF + TALL_SIDE_MARGIN;
    for (const x of [-outer, outer]) for (const z of [-outer, outer]) wx = Math.max(wx, Math.abs(corner.set(x, 0, z).project(cam).x));
  }
  if (covered > 0) {
    // The free part of the stage in normalised device x: [-1, r].
    const r = 1 - (2 * covered) / c.width;
    const k = Math.min(1, (0.96 * (r + 1)) / (bx - ax));
    const shift = (r - 1) / 2 - (k * (ax + bx)) / 2;
    cam.zoom = k;
    cam.setViewOffset(c.width, c.height, (-shift * c.width) / 2, 0, c.width, c.height);
  } else {
    // The free part of the stage in normalised device y: [l, r] (below the net, above the touch card);
    // the room is centred on [foot, r] unless that puts the floor's near edge under l.
    const r = 1 - (2 * below) / c.height,
      l = -1 + (2 * TOUCH_CARD_SPACE) / c.height,
      foot = -1 + (2 * ROOM_FOOT_SPACE) / c.height;
    const k = Math.min(TALL_ZOOM_MAX, (0.98 * (r - l)) / (by - ay), 0.98 / wx);
    const shift = Math.max((r + foot) / 2 - (k * (ay + by)) / 2, l + 0.01 * (r - l) - k * ay);
    cam.zoom = k;
    cam.setViewOffset(c.width, c.height, 0, (shift * c.height) / 2, c.width, c.height);
  }
  cam.updateProjectionMatrix();
}
new MutationObserver(fitBesideDrawer).observe(pageLayout().root, { attributes: true, attributeFilter: ['data-open'] });
window.addEventListener('resize', fitBesideDrawer);
// A new stage size (the touch bars and the status row taking their room after the first layout):
// the kit's observer, older so called first, sizes the canvas and draws it again at once; framed
// again here and drawn once more, the frame shown at the new size has the room where it stays.
new ResizeObserver(() => {
  fitBesideDrawer();
  app.renderer.render(app.scene, app.camera);
}).observe(app.canvas.parentElement ?? document.body);
fitBesideDrawer();
framingReady = true;

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  /** The body's entity id. */
  body: (): number => handles.body,
  /** Angular velocity, rad/s, world frame. */
  angularVelocity: (): number[] => {
    const w = shell.world.components.AngularVelocity,
      e = handles.body;
    return [w.x[e]!, w.y[e]!, w.z[e]!];
  },
  /** Angular momentum about the centre of mass, kg m^2/s, world frame. */
  angularMomentum: (): number[] => Array.from(spinAngularMomentum(shell.world, handles.body, new Float64Array(3))),
  /** The ω arrow: where it starts (the pivot, or the cube's centre in the room; m, world frame) and its length per rad/s (m). */
  omegaArrow: () => ({ from: Array.from(params.mode === 'room' ? [NaN, NaN, NaN] : handles.pivot), scale: omegaScale }),
  /** The body's y axis in the world frame (a unit vector): flips sign in flip mode. */
  bodyUp: (): number[] => {
    const q = shell.world.components.Orientation,
      e = handles.body,
      out = new Float64Array(3);
    // Rotating (0, 1, 0) by q is the inverse of rotating by its conjugate.
    rotateVectorInverse(-q.x[e]!, -q.y[e]!, -q.z[e]!, q.w[e]!, 0, 1, 0, out);
    return Array.from(out);
  },
  /**
   * The challenge's state: room: the lit pad's index (the pads' count when the round is over), the
   * face on top and the face the lit pad wants, the world time the round ended (s, -1 while it runs),
   * the round's clock, the layout's seed, the pads' centres (x, z, m), wanted faces and half edges (m);
   * flip: the flips counted and the time the goal was reached (s, -1 if not yet).
   */
  challenge: () => ({
    mode: params.mode,
    pad: pads.pad,
    /** The face of the cube on top now and the one the lit pad wants (indices into FACES; -1: any). */
    face: topFace(shell.world, handles.body),
    wants: layout.faces[pads.pad] ?? -1,
    padsDoneAt: pads.doneAt,
    /** The round's clock, s (0 until the first input starts it). */
    padTime: pads.time(),
    seed: layout.seed,
    pads: layout.pads.map((p) => [p[0], p[1]]),
    faces: [...layout.faces],
    halves: [...layout.halves],
    /**
     * Rolls made in the round (changes of the face on top), moves (rolls, slides, turns, jumps), the
     * round's par so far and the lit pad's (scene.ts `padMovePar`), and whether the cube rolled since its last slide.
     */
    rolls: pads.rolls,
    moves: pads.moves,
    par: pads.par,
    padPar: pads.padPar,
    beds: [...layout.beds],
    rolled: pads.rolled,
    flips: flips.counter.count,
    flipsWonAt: flips.wonAt,
    /** Free spin: the lit target's index (SPIN_TARGETS once won), the targets (rad/s, world frame), how long ω has held on it (s), how far off it is (rad/s), and when the round was won (s, -1 if not yet). */
    spin: { target: spins.target, targets: spins.targets.map((v) => [...v]), held: spins.held, off: spins.off, wonAt: spins.wonAt },
  }),
  /**
   * Free spin: the guides as last drawn (spin-look.ts): the gap from ω to the target (rad/s, world
   * frame), the torque's alignment with it (a cosine), the hold ring's fill in [0, 1], whether the
   * torque arrow and the ghost show, and the meter's closeness of that gap (spin-challenge.ts `spinCloseness`).
   */
  spinLook: () => ({ ...spinLook.shown, gap: [...spinLook.shown.gap], closeness: spinCloseness(Math.hypot(...spinLook.shown.gap)) }),
  /** Starts the round's clock (the pads' or the flips'), as the player's first input does. */
  startClock,
  /** Clicks at (ndcX, ndcY) as the mouse would; returns whether the cube was pushed (on the pivot: hit). */
  clickAt,
  /**
   * Room mode: the last push of a click or tap: 'floor' (towards the point clicked) or 'cube' (away
   * from the face), its unit direction (dx, dz), speed (m/s) and the point it aims at (x, z, m); or null.
   */
  lastPush: (): Push | null => (lastPush ? { ...lastPush } : null),
  /** Frames drawn in the room on a tall stage (a phone) before it was framed there: 0, or the room moved after the load. */
  unframedFrames: (): number => unframedFrames,
  /**
   * The lit pad's state: whether the cube's centre is over its counting square (its rim drawn), and
   * why a cube resting there does not count ('face', 'slide'; '' when it does or does not rest there);
   * and the opacity of the pads reached, in [0, 1] (0.55 while the round runs, pulsing 0.5 to 1 once won).
   */
  padState: () => ({ over: pads.over, rim: padRim.visible, blocked: pads.blocked, goldOpacity: padDoneMaterial.opacity }),
  /**
   * The pads card: whether it shows, whether its rules (behind "?") are open, whether the roll-only
   * tiles' legend shows (while the lit pad has a bed) and its words, and the face each pad wants as
   * its chips name it (a colour name or 'any').
   */
  rules: () => ({
    shown: rules.style.display !== 'none',
    open: rulesShown,
    legend: bedLegend.style.display !== 'none',
    legendText: bedLegend.textContent ?? '',
    bedTiles: bedTiles.filter((t) => t.visible).length,
    chips: [...rulesChips.children].map((c) => (c as HTMLElement).dataset.face ?? ''),
  }),
  /** The ring on the floor tile the status row's route starts with (its centre x, z, m), or null when none is drawn. */
  hintRing: (): number[] | null => (hintMark.group.visible ? [hintMark.group.position.x, hintMark.group.position.z] : null),
  /** The hint's pin over the ringed tile: its tip (x, y, z, m), or null when no tile is ringed. */
  hintPin: (): number[] | null =>
    hintMark.group.visible ? [hintMark.group.position.x, hintMark.pin.position.y, hintMark.group.position.z] : null,
  /** Whether the aim marker (the arrow from the cube and the ring where a push would stop it) is drawn. */
  aimShown: (): boolean => aimRing.visible,
  /**
   * The pop over the scene: the text it shows or last showed, whether it shows now, and how many pops
   * have been shown since the page loaded (a pop fades after 1.1 to 2.6 s of the clock).
   */
  pop: () => ({ text: pop.textContent ?? '', shown: pop.style.opacity === '1', count: popsShown }),
  /** Room clicks refused (a cell the cube cannot slide to) since the page loaded, and whether the red ring shows now. */
  refused: () => ({ count: refusals, shown: refuseMark.visible }),
  /** Sounds played so far (the pads' chimes, pushes, impacts; 0 until the first input starts the audio). */
  soundsPlayed: (): number => sound.played,
  /**
   * The face net: the face on top ('top'), the face each roll key would bring up ('w', 'a', 'd', 's')
   * and the one underneath ('bottom'), as colour names (FACE_NAMES), as last drawn.
   */
  faceNet: (): Record<string, string> =>
    Object.fromEntries(NET_CELLS.map((c, i) => [c.name, netFaces[i]! >= 0 ? FACE_NAMES[netFaces[i]!]! : ''])),
  /** Switches mode ('room', 'cube' or 'flip') and rebuilds. @throws RangeError on an unknown mode. */
  setMode: (mode: Mode): void => {
    if (!MODES.includes(mode)) throw new RangeError(`setMode: mode must be one of ${MODES.join(', ')}, got ${String(mode)}`);
    setMode(mode);
  },
});
