/**
 * Flight simulator: the book's aircraft (Ramtal and Dobre ch. 16; the `aircraft` scene) flown over
 * seeded hills through a course of rings. Lift and drag come from each surface's angle of attack
 * (wing halves with dihedral and ailerons, tailplane with the elevator, fin with the rudder), with a
 * stall past 20 degrees; the controls act where the surfaces are, so they turn the aircraft through
 * Euler's equations. The flight assist (./assist.ts, on by default) turns the stick into a bank (let
 * go, the wings roll level at once) and gives a held climb or dive the elevator's full response,
 * flying level when the stick is let go; a held dive goes down to its ground floor (GROUND_FLOOR,
 * 60 m over the ground ahead) and levels there, saying so ("ASSIST HOLDS YOU UP"); it leaves the
 * throttle to the pilot. Without it the stick moves the surfaces directly.
 * Fly through every ring (./course.ts) as fast as you can; a ring flown past to the side, left
 * behind, is missed (./course.ts leaveBehind; one laid ahead after a miss is laid ahead again
 * instead, so one over-correction costs one star); after a miss the course moves on (the
 * next ring is laid just ahead: ./course.ts relayAfterMiss); a ring's first miss lays it ahead again
 * to be scored with no penalty (./second-try.ts); each ring missed for good adds MISS_PENALTY (10)
 * s to the course clock and every second miss costs a star (three to start with, shown on the goal
 * line: ./course.ts courseStars), said in the banner and by the goal line's flash the moment it
 * is missed. A ring the flight-path marker showed green is passed (./course.ts flyRings
 * `promised`); do not hit the ground. P (or the
 * toolbar's button) pauses: the scene dims and says so (game-kit's createDomPauseOverlay).
 * Guidance: thick bright rings, a chain of beads through the next two, an outline round the next one
 * on the screen (at least OUTLINE_LEAST px in radius, so a ring far off or edge on still reads), a label
 * above it (clear of the ring and of the marker; an edge arrow when it is out of view), and a flight-path
 * marker where the aircraft's path, curved by its turn and climb, meets the next ring's plane if the
 * pilot lets go now (green when it is inside the ring); while a bank is held, "Let go of ← now"
 * under it when letting go then ends the turn on the ring (./let-go.ts), and in the cockpit view the
 * compass has a bug at the ring's heading. The flight waits for the pilot's first input
 * at the start and while the first lesson's tip (ring 2: a plane turns by banking) is read (on a
 * phone the stick glows meanwhile); the later lessons' tips (rings 3, 4) show while it flies on, and
 * from ring 5 to the last the coach (./coach.ts) says where each ring lies and what to do. A ring
 * spanning most of the view fades (./ring-fade.ts), so the one flown through does not cover it.
 * The end of the course shows a finish card (./finish.ts): the result, the stars, Retry (R) and
 * Next course (Enter). Under 10 frames a second the flight goes in slow motion and says so
 * (./pacing.ts); a tap of a key, a button or the stick shorter than a frame acts for MIN_PULSE s
 * (./tap-latch.ts). The cockpit view (C) has a canopy frame and an instrument panel (./cockpit.ts: airspeed,
 * altimeter, heading, vertical speed, throttle) with the attitude indicator in its middle. The chase
 * camera sits close behind and widens its view with speed, so the speed shows.
 * Keys: arrows or W/S/A/D: climb / dive and bank (with "pilot's pitch" in the panel, down pulls up),
 * ramped (./assist.ts rampKey: a tap is a small correction; climb and dive grow slowly at first to full
 * stick after 0.4 s held, the bank keys start at 0.2 of full stick (BANK_KEY_RAMP) and grow about evenly to full after 1.1 s);
 * Q / E: rudder; X / Z (or Shift, + / -): faster / slower (the throttle: the only input that moves it;
 * a press steps it a tenth at once, held it goes on: ./assist.ts throttleStep; no Ctrl, which with W
 * closes the browser's tab);
 * C: camera (chase / cockpit); P pause, N step, R reset.
 * Touch: a stick under the scene (up climbs, sideways banks; a dead zone, a gentle centre and smoothing:
 * ./assist.ts stickResponse, smoothStick), buttons for speed, rudder and camera.
 * A crash flashes the scene and draws a fireball, flung pieces and smoke (./crash.ts), then its card.
 * Sound: the engine follows the throttle; chimes for rings, a low tone for a miss, a stall horn,
 * a ground warning and the crash.
 * URL: ?seed=n, ?rings=n (1..30), ?assist=0.
 */

import {
  createActionButton,
  createButtonBar,
  createDomPauseOverlay,
  createDomResultCard,
  createPanel,
  createStick,
  flagParam,
  getSound,
  numberParam,
  pageLayout,
  pauseUnderDrawers,
  seedParam,
} from '@bitphysics/game-kit';
import { isSoftwareWebGL, SOFTWARE_PIXEL_RATIO, startThreeGame } from '@bitphysics/game-kit/three';
import { createPhysicsWorld, type PhysicsWorld, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';
import { AIRCRAFT, type AircraftHandles, aircraft, aircraftLevelDrag, terrainHeight } from '@bitphysics/projects';
import {
  DoubleSide,
  HemisphereLight,
  InstancedMesh,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  OctahedronGeometry,
  Quaternion,
  TorusGeometry,
  Vector3,
} from 'three';
import { aircraftGeometry } from './aircraft-model';
import {
  AILERON_SCALE,
  approach,
  assist,
  BANK_KEY_RAMP,
  CONTROL_AUTHORITY,
  createAssistState,
  type FlightState,
  flightState,
  floorPath,
  GROUND_FLOOR,
  heldBank,
  rampKey,
  SURFACE_RATE,
  smoothStick,
  stickResponse,
  THROTTLE_KEY,
  throttleStep,
} from './assist';
import { createAttitudeIndicator } from './attitude-indicator';
import { CHASE_LOOK, CHASE_OFFSET } from './chase-view';
import { courseTipText, LESSON_RINGS, markerBearing } from './coach';
import { createCockpit } from './cockpit';
import {
  type BestResult,
  clearThrough,
  compareWithBest,
  courseBests,
  courseStars,
  courseTime,
  faceRing,
  flyRings,
  LEFT_BEHIND_SPEED,
  LEFT_BEHIND_TIME,
  layCourse,
  leaveBehind,
  lessonTipText,
  MAX_BEST_TIME,
  MISS_PENALTY,
  nextRing,
  nextRingText,
  outOfReach,
  PASS_RADIUS,
  predictThroughRing,
  RING_RADIUS,
  RING_TUBE,
  RING_WAYS,
  type Ring,
  type RingWay,
  recedingSpeed,
  relayAfterMiss,
  relayText,
  ringBearing,
  ringWay,
} from './course';
import { createCrash } from './crash';
import { clockText, courseName, finishCard, LAST_SEED, nextSeed } from './finish';
import { clearOfBox, labelClearOf, type ScreenBox } from './label-place';
import { bearingAfterLetGo, letGoCue, runOnTurn } from './let-go';
import { FRAME_CAP, STEPS_PER_FRAME, slowMotion } from './pacing';
import { nearFade } from './ring-fade';
import { offScreenLabel } from './ring-pointer';
import { createScenery, HORIZON_COLOUR, SCENERY_DETAIL, SUN_DIRECTION } from './scenery';
import { secondTry, tryBanner } from './second-try';
import { clearPulse, createPulse, type Pulse, pressPulse, pulseOn, releasePulse } from './tap-latch';

const params = {
  seed: seedParam(),
  rings: numberParam('rings', { default: 10, min: 1, max: 30, integer: true }),
  /** The flight assist: the stick asks for a bank and a climb; the throttle stays the pilot's. */
  assist: new URLSearchParams(location.search).has('assist') ? flagParam('assist') : true,
  /** Pilot's pitch: stick back (down arrow, stick down) pulls the nose up, as in an aircraft. */
  pilotPitch: flagParam('pilotPitch'),
  /** Full deflection of each control, degrees. */
  authority: CONTROL_AUTHORITY,
  reset: () => shell.reset(),
};

/** Height the aircraft starts at, m. */
const START_ALTITUDE = 900;
/** Speed whose level drag the starting throttle balances, m/s (the aircraft starts at its trim speed and gathers speed towards it). */
const START_SPEED = 130;
/** Sea level of the scenery, m: below it is water, which ends the flight as the ground does. */
const SEA_LEVEL = 60;

/** The cue said while the assist's ground floor holds the aircraft up against a held dive (./assist.ts GROUND_FLOOR). */
const FLOOR_CUE = 'ASSIST HOLDS YOU UP';
/** How long the floor's cue stays after the floor last held the aircraft up, s of game time (it does not flicker). */
const FLOOR_CUE_TIME = 1;
/** Game time the ground floor last held the aircraft up, s. */
let floorHeldAt = -Infinity;
/** The ground's (or the sea's) height at (x, z), m: what ends the flight, and what the floor keeps above. */
const groundAt = (x: number, z: number): number => Math.max(SEA_LEVEL, terrainHeight(handles.terrain, x, z));

/** Controls and game state beside the physics. */
const state = {
  /** Throttle, fraction of the largest thrust, [0, 1]: moved only by Faster / Slower. */
  throttle: 0,
  /** Control surfaces, fractions of full deflection in [-1, 1]: + roll right, + nose up, + nose right. */
  elevator: 0,
  aileron: 0,
  rudder: 0,
  /**
   * Rings passed and missed (for good), rings missed once and given a second try, and rings passed on
   * that second try (./second-try.ts: scored with no penalty).
   */
  score: 0,
  missed: 0,
  again: 0,
  secondPassed: 0,
  /** 'flying', then 'crashed' (into the ground or the sea) or 'done' (no ring left). */
  phase: 'flying' as 'flying' | 'crashed' | 'done',
  /** Time since the start, s of game time; stops when the course is done. */
  time: 0,
  camera: 'chase' as 'chase' | 'cockpit',
  stalled: false,
  /** Warnings shown now: the wing near or past the stall, the ground coming up fast, the assist holding the aircraft above the ground. */
  warning: '' as '' | 'STALL' | 'PULL UP' | typeof FLOOR_CUE,
};
let handles!: AircraftHandles;
let rings: Ring[] = [];
const assistState = createAssistState();

function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(aircraft.worldOptions());
  handles = aircraft.build(world, { seed: params.seed, altitude: START_ALTITUDE });
  Object.assign(state, {
    throttle: aircraftLevelDrag(START_SPEED) / AIRCRAFT.maxThrust,
    elevator: 0,
    aileron: 0,
    rudder: 0,
    score: 0,
    missed: 0,
    again: 0,
    secondPassed: 0,
    phase: 'flying',
    time: 0,
    stalled: false,
    warning: '',
  });
  Object.assign(assistState, createAssistState());
  keyInput.pitch = keyInput.roll = keyInput.yaw = 0;
  stickFlown.x = stickFlown.y = 0;
  // A tap before the reset does not carry over; a key still held goes on acting.
  for (const pulse of [...keyPulses.values(), stickPulse]) pulse.since = Number.NEGATIVE_INFINITY;
  rings = layCourse({ terrain: handles.terrain, seed: params.seed + 7, count: params.rings, start: [0, START_ALTITUDE, 0] });
  events.length = 0;
  doneAt.clear();
  movedAhead = -1;
  promise.ring = -1;
  promise.at = -Infinity;
  missedAt = -Infinity;
  tried.clear();
  crashReadings = null;
  floorHeldAt = -Infinity;
  awayFor = 0;
  // Where the aircraft is now (the marker, the ring's distance), before the first step.
  const P = world.components.Position,
    e = handles.body;
  now[0] = prev[0] = P.x[e]!;
  now[1] = prev[1] = P.y[e]!;
  now[2] = prev[2] = P.z[e]!;
  Object.assign(motion, { bank: 0, rollRate: 0, pathRate: 0 });
  // A new flight waits for the pilot (`waitForPilot`).
  holding = true;
  return world;
}

/** The aircraft's bank (rad), its rate and the flight path's rate (rad/s) after the last step: the marker's prediction starts from them. */
const motion = { bank: 0, rollRate: 0, pathRate: 0 };

/**
 * Whether the flight waits for the pilot: at the start and after a reset, and when the first lesson's
 * tip (ring 2) first shows (`showTip`), the game pauses until the pilot's first flight key or touch of the stick
 * (or P), so the tip is read before the ring comes rather than while the aircraft flies on past it.
 */
let holding = true;
/** Whether `shell` is set (a key pressed while the page loads finds none). */
let shellReady = false;
/** Keys that fly the aircraft: any of them ends a wait (`holding`). */
const FLIGHT_KEYS = new Set([
  'arrowup',
  'arrowdown',
  'arrowleft',
  'arrowright',
  'w',
  'a',
  's',
  'd',
  'q',
  'e',
  'x',
  'z',
  ' ',
  'enter',
  'shift',
  '+',
  '-',
  '=',
]);
/** Ends a wait for the pilot (`holding`): the game runs on. */
function pilotGoes(): void {
  if (!holding || !shellReady) return;
  holding = false;
  shell.paused = false;
  if (compact || nextRing(rings) === 0) tipGoneAt = shell.world.time + TIP_LINGER;
}

/** Whether the pilot holds a flight key or the stick now. */
function steering(): boolean {
  for (const key of held) if (FLIGHT_KEYS.has(key)) return true;
  return stickInput.x !== 0 || stickInput.y !== 0;
}

const held = new Set<string>();
/** The keys (and the phone's Faster / Slower buttons, '+' and '-') that open and close the throttle. */
const FASTER_KEYS = new Set(['x', 'shift', '+', '=']),
  SLOWER_KEYS = new Set(['z', '-']);
/** Game time of the last press of Faster or Slower, s: the held ramp starts THROTTLE_KEY.hold s after it. */
let throttlePressedAt = -Infinity;
/** When the throttle last moved by Faster or Slower, ms (performance.now): its note shows THROTTLE_NOTE_MS after. */
let throttleShownAt = -Infinity;
/**
 * Every step's [game time s, bank degrees (right +), keys' bank input, stick's bank input] while a
 * test traces the bank (`window.game.traceBank`), else null: a let-go is read to the step, whatever
 * the frame rate.
 */
let bankTrace: [number, number, number, number][] | null = null;
/** The on-screen stick's input (x right, y up, in [-1, 1]): its deflection through ./assist.ts stickResponse. */
const stickInput = { x: 0, y: 0 };
/** The stick's input as the steps fly it: `stickInput` smoothed step by step (./assist.ts smoothStick). */
const stickFlown = { x: 0, y: 0 };
/** The climb / dive and bank keys (./assist.ts rampKey ramps them step by step). */
const AXIS_KEYS = new Set(['arrowup', 'arrowdown', 'arrowleft', 'arrowright', 'w', 's', 'a', 'd']);
/**
 * The axis keys' presses and releases not yet seen by the steps, oldest first: the key, pressed or
 * released, and when (ms, the clock of performance.now). The steps of a frame run together after
 * the frame's events came in; each step takes the events up to its own moment of the frame's span
 * (`axisKeysAt`), so at a low frame rate a key let go stops its input where it was let go, not up to
 * a frame later, and a tap shorter than a frame still ramps.
 */
const axisEvents: { key: string; down: boolean; time: number }[] = [];
/** The axis keys held as the steps see them (`axisEvents` applied up to the step's moment). */
const axisHeld = new Set<string>();
/** The span of the clock the steps running now stand for, ms: from the last batch's end to this one's. */
const batch = { start: 0, end: 0, step: 0, lastWall: -Infinity };
/**
 * Brings `axisHeld` to the moment of the frame's span this step stands for: the steps of a frame
 * (run back to back, less than 4 ms apart) share its span, at most FRAME_CAP s (the loop's maxFrameTime),
 * evenly. A key released in the step it was pressed in is released in the next step.
 */
function axisKeysAt(dt: number): void {
  const wall = performance.now();
  if (wall - batch.lastWall > 4) {
    batch.start = Math.max(batch.end, wall - 1000 * FRAME_CAP);
    batch.end = wall;
    batch.step = 0;
  }
  batch.lastWall = wall;
  const n = Math.max(1, Math.min(STEPS_PER_FRAME, Math.round((batch.end - batch.start) / (1000 * dt))));
  batch.step++;
  const upTo = batch.step >= n ? Number.POSITIVE_INFINITY : batch.start + (batch.step * (batch.end - batch.start)) / n;
  const pressed = new Set<string>();
  while (axisEvents.length > 0 && axisEvents[0]!.time <= upTo) {
    const ev = axisEvents[0]!;
    if (!ev.down && pressed.has(ev.key)) break;
    axisEvents.shift();
    if (ev.down) {
      axisHeld.add(ev.key);
      pressed.add(ev.key);
      pressPulse(pulseOf(ev.key));
    } else {
      axisHeld.delete(ev.key);
      releasePulse(pulseOf(ev.key));
    }
  }
}
/**
 * Each flying key's press as the steps see it (./tap-latch.ts): the axis keys' as `axisKeysAt` brings
 * them to the step's moment, the rudder's (Q, E) as they come. A tap acts for at least MIN_PULSE s.
 */
const keyPulses = new Map<string, Pulse>();
/** The pulse of `key`, made at its first use. */
function pulseOf(key: string): Pulse {
  let p = keyPulses.get(key);
  if (!p) keyPulses.set(key, (p = createPulse()));
  return p;
}
/** The rudder's keys (the phone's Rudder buttons send them too). */
const RUDDER_KEYS = new Set(['q', 'e']);
/** The on-screen stick's press (./tap-latch.ts) and the largest input of that press: a flick shorter than a frame still acts. */
const stickPulse = createPulse();
const stickLatched = { x: 0, y: 0 };
/** Forgets every press (a reset, the page losing the focus). */
function clearPulses(): void {
  for (const p of keyPulses.values()) clearPulse(p);
  clearPulse(stickPulse);
  stickLatched.x = stickLatched.y = 0;
}
addEventListener('keydown', (e) => {
  const key = e.key.toLowerCase();
  if (AXIS_KEYS.has(key) && !e.repeat) axisEvents.push({ key, down: true, time: e.timeStamp });
  if (RUDDER_KEYS.has(key)) pressPulse(pulseOf(key));
  held.add(key);
  if (e.key === 'Shift' || e.key.startsWith('Arrow') || e.key === ' ') e.preventDefault();
  if (FLIGHT_KEYS.has(key)) pilotGoes();
  // A press of Faster or Slower steps the throttle at once (./assist.ts throttleStep); held, it
  // goes on after THROTTLE_KEY.hold s (stepWorld).
  const way = FASTER_KEYS.has(key) ? 1 : SLOWER_KEYS.has(key) ? -1 : 0;
  if (way !== 0 && !e.repeat && !e.ctrlKey && !e.metaKey && shellReady && state.phase === 'flying') {
    state.throttle = throttleStep(state.throttle, way);
    throttlePressedAt = shell.world.time;
    throttleShownAt = performance.now();
  }
});
addEventListener('keyup', (e) => {
  const key = e.key.toLowerCase();
  if (AXIS_KEYS.has(key)) axisEvents.push({ key, down: false, time: e.timeStamp });
  if (RUDDER_KEYS.has(key)) releasePulse(pulseOf(key));
  held.delete(key);
});
addEventListener('blur', () => {
  held.clear();
  clearPulses();
  axisEvents.length = 0;
  axisHeld.clear();
});

const clamp1 = (x: number): number => Math.max(-1, Math.min(1, x));

/** The keyboard's climb / dive and bank inputs, ramped while a key is held (./assist.ts `rampKey`), in [-1, 1]. */
const keyInput = { pitch: 0, roll: 0, yaw: 0 };

/**
 * Moves the keyboard's ramped inputs over a step of `dt` s at game time `time` (s) towards the keys
 * acting now (held, or tapped less than MIN_PULSE s ago: ./tap-latch.ts), and the stick's towards its
 * input (or, for a flick already let go, the flick's latched input while its pulse lasts).
 */
function rampKeys(dt: number, time: number): void {
  axisKeysAt(dt);
  // Every key's pulse is read at every step (no short cut), so that a press starts its pulse at the first step after it.
  const on = (a: string, b: string): number => Number(pulseOn(pulseOf(a), time)) | Number(pulseOn(pulseOf(b), time));
  const up = on('arrowup', 'w'),
    down = on('arrowdown', 's'),
    right = on('arrowright', 'd'),
    left = on('arrowleft', 'a');
  keyInput.pitch = rampKey(keyInput.pitch, up - down, dt);
  keyInput.roll = rampKey(keyInput.roll, right - left, dt, BANK_KEY_RAMP);
  const flick = pulseOn(stickPulse, time) && stickInput.x === 0 && stickInput.y === 0;
  stickFlown.x = smoothStick(stickFlown.x, flick ? stickLatched.x : stickInput.x, dt);
  stickFlown.y = smoothStick(stickFlown.y, flick ? stickLatched.y : stickInput.y, dt);
  keyInput.yaw = Number(pulseOn(pulseOf('e'), time)) - Number(pulseOn(pulseOf('q'), time));
}

/**
 * Sets the stick's input `r` (after its response curve): pressed while it is off the centre, its
 * largest input latched for a flick shorter than a frame (`rampKeys`).
 */
function setStickInput(r: { x: number; y: number }): void {
  stickInput.x = r.x;
  stickInput.y = r.y;
  if (r.x === 0 && r.y === 0) {
    releasePulse(stickPulse);
    return;
  }
  if (!stickPulse.down) stickLatched.x = stickLatched.y = 0;
  pressPulse(stickPulse);
  if (Math.hypot(r.x, r.y) >= Math.hypot(stickLatched.x, stickLatched.y)) {
    stickLatched.x = r.x;
    stickLatched.y = r.y;
  }
}

/** The pilot's inputs now, keys (ramped) and stick added: roll + right, pitch + nose up, yaw + nose right. */
function pilotInput(): { roll: number; pitch: number; yaw: number } {
  // Up climbs, as most players expect; with the pilot's pitch, down (stick back) pulls up.
  const sign = params.pilotPitch ? -1 : 1;
  return {
    roll: clamp1(keyInput.roll + stickFlown.x),
    pitch: clamp1(sign * (keyInput.pitch + stickFlown.y)),
    yaw: keyInput.yaw,
  };
}

/**
 * When each ring was passed or missed, ms (performance.now; absent while it is ahead): it fades out
 * over RING_FADE_MS from then (`paintRings`).
 */
const doneAt = new Map<number, number>();
/**
 * Game events for the banner and the sounds, newest last: text, colour, game time, and for a ring
 * laid ahead after a miss that ring (`relaid`, 0-based), or for the ring next after a pass that ring
 * (`next`): its banner says where it lies in words worked out each frame, as the lesson tip's are
 * (./course.ts relayText, nextRingText), so the two agree.
 */
const events: { text: string; colour: string; time: number; relaid?: number; next?: number }[] = [];
const sound = getSound();
const engine = sound.engine('propeller');
/** Game time of the last warning beep, s. */
let lastBeep = 0;

const prev = [0, 0, 0],
  now = [0, 0, 0];

function stepWorld(world: PhysicsWorld): void {
  if (state.phase === 'crashed') return;
  if (holding) {
    // Waiting for the pilot: the game pauses (its pause button and readout say so) until a flight input.
    shell.paused = true;
    return;
  }
  const dt = world.dt,
    e = handles.body;
  rampKeys(dt, world.time);
  // After the course the assist flies on level by itself under the finish card (the keys are the card's).
  const input = state.phase === 'done' ? { roll: 0, pitch: 0, yaw: 0 } : pilotInput();
  const s = flightState(world, e);
  // Held past THROTTLE_KEY.hold s after its press (which stepped it), Faster or Slower moves the throttle on.
  const ramping = world.time - throttlePressedAt >= THROTTLE_KEY.hold;
  const faster = ramping && [...FASTER_KEYS].some((k) => held.has(k)),
    slower = ramping && [...SLOWER_KEYS].some((k) => held.has(k));
  if (params.assist) {
    // The ground floor: a held dive goes down to GROUND_FLOOR.height over the ground and levels there.
    const V = world.components.Velocity,
      P0 = world.components.Position;
    const floor = floorPath([P0.x[e]!, P0.y[e]!, P0.z[e]!], [V.x[e]!, V.y[e]!, V.z[e]!], groundAt);
    const c = assist(s, input, assistState, dt, floor);
    if (assistState.floorHold) floorHeldAt = world.time;
    state.aileron = approach(state.aileron, c.aileron, SURFACE_RATE.assist, dt);
    state.elevator = approach(state.elevator, c.elevator, SURFACE_RATE.assist, dt);
    state.rudder = approach(state.rudder, c.rudder, SURFACE_RATE.assist, dt);
  } else {
    // Stick inputs spring back to neutral.
    state.elevator = approach(state.elevator, input.pitch, SURFACE_RATE.direct, dt);
    state.aileron = approach(state.aileron, input.roll, SURFACE_RATE.direct, dt);
    state.rudder = approach(state.rudder, input.yaw, SURFACE_RATE.direct, dt);
  }
  // The throttle stays where the pilot puts it, with or without the assist: the stick never moves it.
  if (faster) state.throttle = Math.min(1, state.throttle + THROTTLE_KEY.rate * dt);
  if (slower) state.throttle = Math.max(0, state.throttle - THROTTLE_KEY.rate * dt);
  if (faster || slower) throttleShownAt = performance.now();
  const full = (params.authority * Math.PI) / 180;
  const surfaces = handles.surfaces;
  // Nose up: the elevator's trailing edge up, less tail lift.
  setControlDeflection(world, surfaces.tail, -state.elevator * full);
  // Roll right: the left aileron down (more lift), the right one up; never past the 45 degrees a
  // surface takes (the panel's authority goes to 30 degrees, times AILERON_SCALE).
  const aileron = Math.max(-Math.PI / 4, Math.min(Math.PI / 4, state.aileron * full * AILERON_SCALE));
  setControlDeflection(world, surfaces.leftWing, aileron);
  setControlDeflection(world, surfaces.rightWing, -aileron);
  // Right rudder: the fin's force to the left at the tail swings the nose right.
  setControlDeflection(world, surfaces.fin, -state.rudder * full);
  setBodyThrust(world, e, [state.throttle * AIRCRAFT.maxThrust, 0, 0]);
  const P = world.components.Position;
  prev[0] = P.x[e]!;
  prev[1] = P.y[e]!;
  prev[2] = P.z[e]!;
  step(world);
  now[0] = P.x[e]!;
  now[1] = P.y[e]!;
  now[2] = P.z[e]!;
  if (state.phase === 'flying') {
    state.time += dt;
    timeAway(world, dt);
    checkRings(world.time);
  }
  const ground = groundAt(now[0]!, now[2]!);
  if (now[1]! < ground + 2 && state.phase === 'flying') {
    // The readouts stop at the values of the moment of the crash.
    crashReadings = instruments(world);
    crashWall = performance.now();
    crashInto = terrainHeight(handles.terrain, now[0]!, now[2]!) < SEA_LEVEL ? 'sea' : 'ground';
    state.phase = 'crashed';
    state.warning = '';
    sound.explosion(1);
    // The kit's card of touch gestures, if still up, goes: the crash's card and its button take the scene.
    layout.stage.querySelector('.bp-touch-hint')?.classList.add('bp-gone');
    events.push({ text: 'Crashed!', colour: '#ff6b5a', time: world.time });
    return;
  }
  // Warnings: the wing within 3 degrees of the stall, or the ground less than 8 s away at this sink rate.
  const after = flightState(world, e);
  if (bankTrace) bankTrace.push([world.time, (after.bank * 180) / Math.PI, keyInput.roll, stickFlown.x]);
  motion.bank = after.bank;
  motion.rollRate = after.rollRate;
  motion.pathRate = (after.path - s.path) / dt;
  state.stalled = Math.abs(after.alpha) > AIRCRAFT.stallAngle;
  const sink = -world.components.Velocity.y[e]!;
  const agl = now[1]! - ground;
  // With the assist the floor holds the aircraft up (said by its own cue while it does); PULL UP only
  // if it is let down under half the floor's height all the same (a hill too steep to climb).
  const sinking = sink > 0 && agl < sink * 8 && (!params.assist || agl < GROUND_FLOOR.height / 2);
  const holdingUp = params.assist && world.time - floorHeldAt < FLOOR_CUE_TIME;
  state.warning =
    Math.abs(after.alpha) > AIRCRAFT.stallAngle - (3 * Math.PI) / 180 ? 'STALL' : sinking ? 'PULL UP' : holdingUp ? FLOOR_CUE : '';
  if ((state.warning === 'STALL' || state.warning === 'PULL UP') && world.time - lastBeep > 0.45) {
    lastBeep = world.time;
    sound.chime(state.warning === 'STALL' ? 1250 : 660, 0.12);
  }
}

/** Passes or misses rings (./course.ts flyRings) on the move from `prev` to `now`: counts, banners, sounds. */
function checkRings(time: number): void {
  const before = nextRing(rings);
  // A ring flown through or its plane crossed; else one left behind (./course.ts leaveBehind: flown
  // past to the side, it never counts, and turning back to it takes about a minute).
  let happened = flyRings(rings, prev, now, promisedRing(time));
  // A ring laid ahead after a miss and left behind before it was reached (the pilot still turning
  // hard, over-correcting) is laid ahead again, with no miss: one over-correction costs one star,
  // not a star every few seconds as each new ring falls behind a held turn.
  const again = happened.length === 0 && before >= 0 && before === movedAhead && awayFor >= LEFT_BEHIND_TIME;
  if (happened.length === 0 && !again) happened = leaveBehind(rings, awayFor);
  // A ring's first miss gives it a second try (./second-try.ts): it comes round again, laid ahead below.
  const counted = secondTry(rings, happened, tried);
  // The next ring starts afresh.
  if (happened.length > 0 || again) awayFor = 0;
  for (const { ring, result } of counted) {
    doneAt.set(ring, performance.now());
    if (result === 'passed') {
      state.score++;
      const last = nextRing(rings) < 0;
      // Passed on its second try: a pass like any other, no penalty, said so (./second-try.ts).
      const second = tried.has(ring);
      if (second) state.secondPassed++;
      events.push({ text: tryBanner({ ring, result }, { second, last }), colour: '#7dff9a', time });
      // Then, once the tick is read, which way the next ring lies: the turn to it is seen coming.
      if (!last) events.push({ text: '', colour: '#ffd166', time: time + NEXT_AFTER, next: nextRing(rings) });
      sound.chime(880, 0.18);
      setTimeout(() => sound.chime(1320, 0.3), 110);
    } else if (result === 'again') {
      // A first miss: no time, no star yet; the ring comes round again to be scored.
      state.again++;
      missedAt = time;
      events.push({ text: tryBanner({ ring, result }), colour: '#ff8a5a', time });
      sound.chime(220, 0.4);
    } else {
      // A miss costs a star and time on the course clock, said at once in the banner and by the
      // flash of the goal line, where the stars and the clock are.
      state.missed++;
      missedAt = time;
      // The star is named only when this miss takes one (every second miss does: ./course.ts courseStars).
      const starLost = courseStars(state.missed) < courseStars(state.missed - 1);
      events.push({ text: tryBanner({ ring, result }, { starLost }), colour: '#ff8a5a', time });
      sound.chime(220, 0.4);
    }
  }
  const next = nextRing(rings);
  // After a miss the course moves on: the next ring (and the rest of the course with it) is laid
  // just ahead, where the aircraft is heading, so that a miss costs a star and not a long turn back.
  if (next >= 0 && (again || happened.at(-1)?.result === 'missed')) {
    relayAfterMiss(rings, next, now, Math.atan2(now[2]! - prev[2]!, now[0]! - prev[0]!), handles.terrain);
    movedAhead = next;
    rings.forEach((r, k) => {
      if (k < next) return;
      ringMeshes[k]?.position.set(r.x, r.y, r.z);
      ringMeshes[k]?.quaternion.setFromUnitVectors(zAxis, ringNormal.set(r.nx, r.ny, r.nz));
    });
    // Said once the miss's banner has been read (at once when no miss came with it).
    events.push({ text: `Ring ${next + 1} is now ahead`, colour: '#ffd166', time: again ? time : time + 1.4, relaid: next });
  }
  // Recovering from a miss: the ring now next turns to face the aircraft (a ring met at an angle
  // was seen edge on), and so does one whose plane the aircraft crossed far off (beyond MISS_RANGE:
  // neither passed nor missed) once it comes back towards it, so that it flies through it the way it
  // comes. Flying on away from it, it is left as it is: past its plane, it is missed (timeAway).
  if (next >= 0) {
    const r = rings[next]!;
    const V = shell.world.components.Velocity,
      e = handles.body;
    const behind =
      (r.x - now[0]!) * r.nx + (r.y - now[1]!) * r.ny + (r.z - now[2]!) * r.nz <= 0 &&
      recedingSpeed(r, now, [V.x[e]!, V.y[e]!, V.z[e]!]) <= 0;
    if ((next !== before && rings[next - 1]?.status === 'missed') || behind) {
      faceRing(r, now);
      ringMeshes[next]?.quaternion.setFromUnitVectors(zAxis, ringNormal.set(r.nx, r.ny, r.nz));
    }
  }
  if (next < 0) finish(time);
  // The first lesson's ring next (ring 2, the first turn: a plane turns by banking): the flight
  // waits while its tip is read, unless the pilot is flying it already (a key or the stick held: no
  // key would come to go on with). The later lessons' tips show while the flight goes on, so a
  // pause at every lesson ring does not break the flow.
  else if (next !== before && next === 1 && !steering()) {
    // Paused at once, not at the next step: the tip and the pause show in the same frame.
    holding = true;
    shell.paused = true;
  }
}
/** Game time of the last miss, s (the clock flashes for a while after it). */
let missedAt = -Infinity;
/** Rings given their second try this run (./second-try.ts): missed again, they are missed for good. */
const tried = new Set<number>();
/** When the aircraft crashed, ms (performance.now), and what it hit. */
let crashWall = Number.NaN,
  crashInto: 'ground' | 'sea' = 'ground';
/** How long after a crash its card shows, ms (the flash and the fireball first). */
const CRASH_CARD_MS = 900;
/** The instruments read at the moment of the crash (the readouts then stay at them), or null. */
let crashReadings: ReturnType<typeof instruments> | null = null;
/** How long the next ring has fallen behind without a break, s (./course.ts leaveBehind). */
let awayFor = 0;
/** The ring last laid ahead after a miss (./course.ts relayAfterMiss), -1 for none: left behind, it is laid ahead again with no miss. */
let movedAhead = -1;
/** Adds a step of `dt` s to `awayFor` while the aircraft draws away from the next ring faster than LEFT_BEHIND_SPEED and it is out of reach (./course.ts outOfReach), else clears it. */
function timeAway(world: PhysicsWorld, dt: number): void {
  const n = nextRing(rings);
  if (n < 0) {
    awayFor = 0;
    return;
  }
  const V = world.components.Velocity,
    e = handles.body;
  // Not while the marker shows the aircraft passing inside it: a ring met at a slant in a turn may
  // draw away from its centre for a while before its plane is crossed, inside.
  // Nor while it is still in reach (./course.ts outOfReach): a ring ahead under a climb, or off to the
  // side outside the tightest turn, can still be flown to, and is not called missed until its plane is passed.
  const velocity = [V.x[e]!, V.y[e]!, V.z[e]!];
  const receding = recedingSpeed(rings[n]!, now, velocity) > LEFT_BEHIND_SPEED && outOfReach(rings[n]!, now, velocity);
  awayFor = receding && promisedRing(world.time) !== n ? awayFor + dt : 0;
}

/**
 * How long the flight-path marker's promise holds, s of game time: a ring the marker last showed
 * the aircraft passing inside (green) no longer ago than this is passed when its plane is crossed
 * (./course.ts flyRings `promised`). Long enough to span the frames a loaded machine leaves undrawn.
 */
const PROMISE_TIME = 0.5;
/** The ring the marker showed green on its last drawn frame (-1 for none) and the game time of that frame, s. */
const promise = { ring: -1, at: -Infinity };
/** The ring the marker promises now (`promise`, within PROMISE_TIME of game time `time`, s), or -1. */
function promisedRing(time: number): number {
  return promise.ring >= 0 && promise.ring === nextRing(rings) && time - promise.at <= PROMISE_TIME ? promise.ring : -1;
}

/** Best result of each course (seed and ring count) in localStorage (./course.ts courseBests): rings passed, then the shorter course time (misses' penalties in). */
const bests = courseBests();
/** The best result kept for this course, or null when none is. */
function bestOf(): BestResult | null {
  return bests.get(`${params.seed}/${params.rings}`) ?? null;
}
/** How the last finish compared with the course's best kept before it (./course.ts compareWithBest). */
let lastVsBest: 'first' | 'better' | 'not' = 'not';

function finish(time: number): void {
  state.phase = 'done';
  const best = bestOf();
  const total = courseTime(state.time, state.missed);
  lastVsBest = compareWithBest(best, state.score, total);
  // The first run is kept as the best to beat, but only a run that beats a kept best is praised.
  // A time past MAX_BEST_TIME would read back as none: not kept.
  if (lastVsBest !== 'not' && total <= MAX_BEST_TIME) bests.set(`${params.seed}/${params.rings}`, { passed: state.score, time: total });
  events.push({ text: state.score === rings.length ? 'Course complete!' : 'Course over', colour: '#ffd166', time });
  const notes = [1047, 1319, 1568, 2093];
  for (let k = 0; k < notes.length; k++) setTimeout(() => sound.chime(notes[k], 0.35), 120 * k);
}

const game = await startThreeGame({
  title: 'Flight simulator',
  createWorld,
  step: stepWorld,
  bodies: () => 1,
  // The game's time keeps pace with the clock down to 10 frames a second; slower, it goes in slow
  // motion and says so (./pacing.ts): the aircraft moves no more than FRAME_CAP s of flight between
  // two pictures. A step costs about 0.2 ms; the handling stays the fixed step's whatever the frame rate.
  maxFrameTime: FRAME_CAP,
  maxStepsPerFrame: STEPS_PER_FRAME,
  // The flight waits for the pilot's first input (`holding`).
  paused: true,
  controls: [
    { keys: '↑ ↓ / W S', action: 'climb / dive', touch: 'stick ↑ ↓' },
    { keys: '← → / A D', action: 'bank left / right', touch: 'stick ← →' },
    { keys: 'X / Z', action: 'engine power up / down', touch: 'Faster / Slower buttons', card: false },
    { keys: 'Q / E', action: 'yaw the nose left / right', touch: '◀ Rudder ▶ buttons', card: false },
    { keys: 'C', action: 'chase / cockpit view', touch: 'Camera' },
  ],
  keys: [
    {
      key: 'c',
      label: 'camera',
      action: () => {
        state.camera = state.camera === 'chase' ? 'cockpit' : 'chase';
      },
    },
  ],
  // A phone's screen (3 device pixels a CSS pixel) is drawn at 1.5 at most: the frame's cost is its pixels.
  app: {
    background: HORIZON_COLOUR,
    shadows: false,
    controls: false,
    fov: 64,
    pixelRatio: isSoftwareWebGL() ? SOFTWARE_PIXEL_RATIO : Math.min(devicePixelRatio || 1, pageLayout().compact() ? 1.5 : 2),
  },
  renderer: {
    unitsPerMeter: 1,
    boundary: 'none',
    shadows: false,
    lights: { direction: [...SUN_DIRECTION], intensity: 2.2, hemisphereIntensity: 0.6, ambientIntensity: 0.2, shadows: false },
  },
  view: null,
  onFrame: (alpha) => frame(alpha),
});
const { shell, renderer, app } = game;
shellReady = true;
// On a phone the menu and settings drawers cover the sky: the flight waits while one is open.
pauseUnderDrawers(shell, { compactOnly: true });
app.camera.near = 1;
app.camera.far = 40_000;
app.camera.updateProjectionMatrix();
app.scene.add(new HemisphereLight(0xcfe6ff, 0x4a5a3a, 0.4));
/**
 * The scenery's detail (./scenery.ts SCENERY_DETAIL): light on a phone (a narrow screen, `compact`),
 * full on a desktop; ?detail=full or ?detail=light chooses.
 */
const sceneryDetail: keyof typeof SCENERY_DETAIL = ((d) => (d === 'full' || d === 'light' ? d : pageLayout().compact() ? 'light' : 'full'))(
  new URLSearchParams(location.search).get('detail'),
);
const scenery = createScenery(app.scene, SCENERY_DETAIL[sceneryDetail]);
scenery.setTerrain(handles.terrain, params.seed);

// ---- The aircraft's looks (./aircraft-model.ts) ---------------------------------------------------

const planeMaterial = new MeshStandardMaterial({ vertexColors: true, roughness: 0.45, metalness: 0.15 });
const planeGeometry = aircraftGeometry();
function dress(): void {
  renderer.setShape(handles.body, { geometry: planeGeometry, material: planeMaterial, scale: 1 });
}
dress();
shell.onWorldChange(() => {
  dress();
  scenery.setTerrain(handles.terrain, params.seed);
  placeRings();
  smoothReady = false;
});

// ---- Rings ----------------------------------------------------------------------------------------

// The next ring: a thick tube (6 m) in flat bright yellow, so it still reads as a ring 2 km off on a
// phone. The rings after it: a thin (2.5 m) pale tube, faint, so the chain of them toward the
// horizon does not read as rings to fly through now, nor as the way to go while the next ring is
// off to the side.
const ringGeometry = new TorusGeometry(RING_RADIUS, RING_TUBE, 10, 48);
const laterGeometry = new TorusGeometry(RING_RADIUS, 2.5, 6, 48);
const haloGeometry = new TorusGeometry(RING_RADIUS + 12, 2.5, 6, 48);
const materials = {
  next: new MeshBasicMaterial({ color: 0xffd21f, fog: false }),
  halo: new MeshBasicMaterial({ color: 0xfff6b0, transparent: true, opacity: 0.6, side: DoubleSide, fog: false }),
  ahead: new MeshBasicMaterial({ color: 0xe4eef8, transparent: true, opacity: 0.45 }),
  passed: new MeshBasicMaterial({ color: 0x50e070, transparent: true, opacity: 0.35 }),
  missed: new MeshBasicMaterial({ color: 0xff5a4a, transparent: true, opacity: 0.3 }),
};
let ringMeshes: Mesh[] = [];
/** Each passed or missed ring's own material while it fades (a copy of its status's), by ring index. */
const fadeMaterials = new Map<number, MeshBasicMaterial>();
/**
 * How long a ring passed or missed takes to fade out and go, ms of the clock (it fades while the
 * flight waits too). Drawn on, the ring just flown through lay as a big green arc across the chase
 * view, and over the whole wait for the next lesson's tip.
 */
const RING_FADE_MS = 600;
const halo = new Mesh(haloGeometry, materials.halo);
app.scene.add(halo);
const zAxis = new Vector3(0, 0, 1),
  ringNormal = new Vector3();
function placeRings(): void {
  for (const m of ringMeshes) app.scene.remove(m);
  for (const m of fadeMaterials.values()) m.dispose();
  fadeMaterials.clear();
  ringMeshes = rings.map((ring) => {
    const m = new Mesh(ringGeometry, materials.ahead);
    m.position.set(ring.x, ring.y, ring.z);
    // The torus lies in its x-y plane: turn its axis (z) to the ring's normal.
    m.quaternion.setFromUnitVectors(zAxis, ringNormal.set(ring.nx, ring.ny, ring.nz));
    app.scene.add(m);
    return m;
  });
}
placeRings();

/**
 * The guide: a chain of bright beads from just ahead of the aircraft to the next ring and on to the
 * one after, so the way through the course shows in the scene itself (a ring far off or behind a
 * hill still has its chain). One instanced mesh; a bead every GUIDE_SPACING m, at most GUIDE_BEADS.
 */
const GUIDE_SPACING = 70,
  GUIDE_BEADS = 80;
const guide = new InstancedMesh(new OctahedronGeometry(2.6, 0), new MeshBasicMaterial({ color: 0xffe35a }), GUIDE_BEADS);
guide.frustumCulled = false;
app.scene.add(guide);
const beadMatrix = new Matrix4(),
  beadAt = new Vector3(),
  beadTo = new Vector3(),
  beadStep = new Vector3();

/**
 * Lays the guide's beads from `from` (the aircraft, m) through the next ring to the one after it; in
 * the cockpit view from the next ring on only: seen from the aircraft, the beads to the next ring
 * lie on the line of sight to it, and the nearest (5 m across, 50 m off) would cover a ring 2 km away
 * (130 m across) whole, so that it would show only as its outline.
 */
function drawGuide(from: Vector3): void {
  const i = nextRing(rings);
  guide.visible = i >= 0 && state.phase === 'flying';
  if (!guide.visible) return;
  let n = 0;
  // From 60 m ahead of the aircraft (clear of the model) to the next ring, then from it to the one after.
  beadAt.copy(from);
  const cockpitView = state.camera === 'cockpit';
  for (const ring of [rings[i]!, rings[i + 1]]) {
    if (!ring) break;
    if (cockpitView && ring === rings[i]) {
      beadAt.set(ring.x, ring.y, ring.z);
      continue;
    }
    beadTo.set(ring.x, ring.y, ring.z);
    const length = beadAt.distanceTo(beadTo);
    beadStep.subVectors(beadTo, beadAt).normalize();
    for (let d = n === 0 ? 60 : GUIDE_SPACING; d < length - RING_RADIUS && n < GUIDE_BEADS; d += GUIDE_SPACING) {
      beadMatrix.makeTranslation(beadAt.x + beadStep.x * d, beadAt.y + beadStep.y * d, beadAt.z + beadStep.z * d);
      guide.setMatrixAt(n++, beadMatrix);
    }
    beadAt.copy(beadTo);
  }
  guide.count = n;
  guide.instanceMatrix.needsUpdate = true;
}
/** The guide's beads drawn now, each centre (m, world; tests). */
function guideBeads(): [number, number, number][] {
  if (!guide.visible) return [];
  return Array.from({ length: guide.count }, (_, k) => {
    guide.getMatrixAt(k, beadMatrix);
    beadAt.setFromMatrixPosition(beadMatrix);
    return [beadAt.x, beadAt.y, beadAt.z];
  });
}

/**
 * Colours the rings by their status, the next one brightest with a pulsing halo; a ring passed or
 * missed fades out over RING_FADE_MS and goes. A ring spanning most of the view is faint
 * (./ring-fade.ts nearFade), so the one flown through does not cover the scene.
 */
function paintRings(t: number): void {
  const i = nextRing(rings);
  const wall = performance.now();
  // The tangent of half the view's narrower angle: a ring near the camera fades (./ring-fade.ts).
  const tanV = Math.tan((app.camera.fov * Math.PI) / 360);
  const tanHalf = tanV * Math.min(1, app.camera.aspect);
  const near = (k: number): number => nearFade(RING_OUTER, ringMeshes[k]!.position.distanceTo(app.camera.position), tanHalf);
  let nextFade = 1;
  rings.forEach((ring, k) => {
    const m = ringMeshes[k]!;
    m.geometry = k === i ? ringGeometry : laterGeometry;
    if (ring.status === 'ahead') {
      m.visible = true;
      m.material = k === i ? materials.next : materials.ahead;
      if (k === i) {
        nextFade = near(k);
        // Opaque (drawn with the scene) until it fades.
        materials.next.transparent = nextFade < 1;
        materials.next.opacity = nextFade;
      }
      return;
    }
    const left = 1 - (wall - (doneAt.get(k) ?? -Infinity)) / RING_FADE_MS;
    m.visible = left > 0;
    if (!m.visible) return;
    const base = materials[ring.status];
    let own = fadeMaterials.get(k);
    if (!own || own.color.getHex() !== base.color.getHex()) {
      own?.dispose();
      own = base.clone();
      fadeMaterials.set(k, own);
    }
    own.opacity = base.opacity * left * near(k);
    m.material = own;
  });
  halo.visible = i >= 0 && state.phase !== 'crashed';
  if (i >= 0) {
    halo.position.copy(ringMeshes[i]!.position);
    halo.quaternion.copy(ringMeshes[i]!.quaternion);
    halo.scale.setScalar(1 + 0.06 * Math.sin(5 * t));
    materials.halo.opacity = (0.35 + 0.3 * (0.5 + 0.5 * Math.sin(5 * t))) * nextFade;
  }
}

// ---- The crash: a flash, a fireball, pieces and smoke where the aircraft hit (./crash.ts) ---------

/** When the crash was seen, ms (performance.now), or NaN while flying; the heading then, rad (+x 0, +z pi/2). */
let crashedAt = Number.NaN,
  crashHeading = 0;

/** Starts the crash's drawing (./crash.ts) at the drawn aircraft on the first frame after it, and draws it; hides it while flying. */
function drawCrash(): void {
  if (state.phase !== 'crashed') {
    if (!Number.isNaN(crashedAt)) crash.hide();
    crashedAt = Number.NaN;
    planeMaterial.visible = true;
    return;
  }
  if (Number.isNaN(crashedAt)) {
    crashedAt = performance.now();
    const V = shell.world.components.Velocity,
      e = handles.body;
    crash.start(at, [V.x[e]!, V.y[e]!, V.z[e]!], groundAt, crashedAt);
    crashHeading = flightState(shell.world, handles.body).heading;
  }
  planeMaterial.visible = false;
  crash.update(performance.now());
}

// ---- HUD: the goal and readout above the scene, instruments beside it, banner, warnings, end card ---

const layout = pageLayout();
const compact = layout.compact();
const crash = createCrash(app.scene, layout.stage);
const statusEl = document.createElement('div');
statusEl.dataset.hud = 'flight-status';
statusEl.style.cssText = `font: ${compact ? 13 : 14}px/1.4 system-ui, sans-serif; color: #eef3f8; padding: 4px 10px;`;
const goalLine = document.createElement('div');
goalLine.dataset.hud = 'goal';
// One line each, whatever they say: the header keeps its two lines (a phone's goal line wrapped to
// two after a miss added its penalty, and pushed the scene down); on a phone the words are shorter.
const ONE_LINE = 'white-space: nowrap; overflow: hidden; text-overflow: ellipsis;';
goalLine.style.cssText = `font-weight: 700; color: #ffd166; ${ONE_LINE}`;
const readLine = document.createElement('div');
readLine.dataset.hud = 'readout';
// A phone's readout a pixel smaller than its goal line: its four figures fit the 390 px width with misses too.
readLine.style.cssText = `${ONE_LINE}${compact ? ' font-size: 12px;' : ''}`;
statusEl.append(goalLine, readLine);
layout.status.append(statusEl);

/** The full instruments, in the side column on wide screens (the status row has the essentials). */
const panelEl = document.createElement('div');
panelEl.className = 'bp-hud';
panelEl.dataset.hud = 'instruments';
panelEl.style.cssText = 'white-space: pre; padding: 6px 4px;';
if (!compact) layout.side.append(panelEl);

/** Text over the scene: dark pills, so it reads over the bright sky and the dark hills alike. */
function overlay(css: string): HTMLDivElement {
  const el = document.createElement('div');
  el.dataset.sceneOverlay = '';
  el.style.cssText = `position: absolute; z-index: 6; pointer-events: none; transform: translate(-50%, -50%); ${css}`;
  layout.stage.append(el);
  return el;
}
/**
 * The widest a message over the scene (banner, engine's note, tip) may be: it wraps inside the scene
 * with a 12 px margin each side, so the phone's banner never runs past the edges of the screen.
 */
const MESSAGE_WIDTH = 'calc(100% - 24px)';
const banner = overlay(
  `left: 50%; top: ${compact ? 27 : 24}%; width: max-content; max-width: ${MESSAGE_WIDTH}; box-sizing: border-box; padding: ${compact ? '3px 12px' : '6px 18px'}; border-radius: 14px; background: rgba(8, 12, 20, 0.78); font: 800 ${compact ? 18 : 26}px/1.25 system-ui, sans-serif; text-align: center; display: none;`,
);
banner.dataset.hud = 'banner';
/**
 * The warning (STALL, PULL UP): one fixed place, the scene's top middle, over every other overlay,
 * so the next ring's label never covers it and it does not move with the message column between the
 * top and the bottom. It flashes by its visibility, so that the column under it keeps still.
 */
const warningEl = overlay(
  `left: 50%; top: ${compact ? 6 : 8}px; transform: translate(-50%, 0px); z-index: 8; padding: 4px 16px; border-radius: 10px; background: rgba(120, 10, 10, 0.92); color: #fff; font: 800 22px system-ui, sans-serif; letter-spacing: 2px; white-space: nowrap; display: none;`,
);
warningEl.dataset.hud = 'warning';
/** The end card (game-kit's result card): the finish screen, or what the crash hit. Drags outside its buttons still reach the scene. */
const endCard = createDomResultCard(layout.stage, {
  name: 'end',
  top: '28%',
  width: 'min(88%, 420px)',
  passThrough: true,
  titleSize: 26,
  lostColour: '#ff6b5a',
});
const showAgain = createActionButton('Fly again ▶', () => shell.reset());
/** The pause overlay (game-kit's, over the stage): a tap on it resumes. */
const pauseOverlay = createDomPauseOverlay(layout.stage, {
  onResume: () => {
    shell.paused = false;
  },
});
// "Paused" low in the scene, under the aircraft: off the middle, where the next ring, its label and
// the path marker are, and off the top, where the banners and tips are.
pauseOverlay.element.style.justifyContent = 'flex-end';
pauseOverlay.element.style.paddingBottom = '2%';
/**
 * "Slow motion" in the scene's bottom left corner while the frame rate is under 10 a second
 * (./pacing.ts slowMotion): the flight then runs slower than the clock, so the pilot keeps control.
 */
const slowNote = overlay(
  `left: 8px; bottom: 8px; transform: none; padding: 2px 10px; border-radius: 10px; background: rgba(8, 12, 20, 0.8); color: #ffd166; font: 700 ${compact ? 12 : 14}px system-ui, sans-serif; white-space: nowrap; display: none;`,
);
slowNote.dataset.hud = 'slow-motion';
/** Whether the slow-motion note shows (tests). */
let slowShown = false;
/** Shows or hides the slow-motion note for the loop's measured frame rate. */
function showSlowMotion(): void {
  slowShown = slowMotion(slowShown, shell.loop.fps) && state.phase === 'flying' && !shell.paused;
  const fps = Math.round(shell.loop.fps);
  const text = `Slow motion: only ${fps} frame${fps === 1 ? '' : 's'} a second`;
  if (slowShown && slowNote.textContent !== text) slowNote.textContent = text;
  const display = slowShown ? 'block' : 'none';
  if (slowNote.style.display !== display) slowNote.style.display = display;
}
/** How long a banner stays, s of game time. */
const BANNER_LIFE = 2;
/** How long after a ring's tick the banner says where the next ring lies, s of game time. */
const NEXT_AFTER = 1.2;

/** m:ss of `t` seconds (./finish.ts clockText). */
const clock = clockText;

/** A distance as the HUD says it, `d` m: metres under 1 km, else km to 0.1. */
function distanceText(d: number): string {
  return d >= 1000 ? `${(d / 1000).toFixed(1)} km` : `${d.toFixed(0)} m`;
}

/**
 * The goal line above the scene, every frame: the next ring with its distance from the drawn
 * aircraft (`at`), as the ring's own label says it, and the course clock.
 */
function updateGoal(): void {
  const n = nextRing(rings);
  const total = rings.length;
  // The course clock: the time flown plus the penalties of the rings missed for good, said beside it.
  const penalty = state.missed > 0 ? ` (+${MISS_PENALTY * state.missed} s)` : '';
  const stars = courseStars(state.missed);
  const courseClock = `${clock(courseTime(state.time, state.missed))}${penalty} · ${'★'.repeat(stars)}${'☆'.repeat(3 - stars)}`;
  const distance = n < 0 ? '' : distanceText(Math.hypot(rings[n]!.x - at.x, rings[n]!.y - at.y, rings[n]!.z - at.z));
  // A ring missed once comes round again (./second-try.ts): the line says so while it is next, so the
  // ring number not moving on reads as the second try it is.
  const retry = n >= 0 && tried.has(n);
  const text =
    state.phase === 'crashed'
      ? `Crashed · ${state.score} of ${total} rings`
      : n < 0
        ? `${compact ? 'Done' : 'Course done'} · ${state.score} of ${total} rings passed · ${courseClock}`
        : compact
          ? // The course's number while the flight waits at its start (the line has no room for it in flight).
            `${state.time === 0 ? `${courseName(params.seed, true)} · ` : ''}Ring ${n + 1}${retry ? ' (2nd try)' : ` of ${total}`} · ${distance} · ${courseClock}`
          : `${courseName(params.seed)} · Fly through ring ${n + 1} of ${total}${retry ? ' (second try)' : ''} · ${distance} · ${courseClock}`;
  if (goalLine.textContent !== text) goalLine.textContent = text;
  // Red for 2 s after a miss: the time it cost shows where the clock is.
  goalLine.style.color = shell.world.time - missedAt < 2 ? '#ff8a5a' : '#ffd166';
}

/** What the end card says now ('' while flying): it is built again only when this changes. */
let shownCard = '';
/** The readout, the side panel and the end card for the readings `i`, every frame, so that they agree with the goal line and the banner. */
function updateHud(i: ReturnType<typeof instruments>): void {
  const total = rings.length;
  const speed = `${i.speed.toFixed(0)} m/s`;
  // The rings counted one way everywhere (the end card too: ./finish.ts finishCard): passed, missed
  // for good and still to fly, which add up to the course's rings. A first miss is not a ring missed
  // (it comes round again: ./second-try.ts); the goal line says "second try".
  const toGo = rings.filter((r) => r.status === 'ahead').length;
  const missedNote = state.missed > 0 ? ` · ${state.missed} missed` : '';
  // The height above the ground (or the sea) under the aircraft, what keeps it off the hills: "alt"
  // counts from sea level, and a pilot reading it alone flew into a hill. Never below 0 (a crash).
  const aboveGround = `${Math.max(0, i.agl).toFixed(0)} m above ground`;
  // On a phone the line has room for the height above the ground (what keeps the aircraft off the
  // hills), the rings and the misses (a first miss said nowhere else was unexplained) and the engine;
  // the speed and the sea-level altitude are the cockpit's gauges.
  const read = compact
    ? `${aboveGround} · ${state.score} passed${missedNote} · engine ${(state.throttle * 100).toFixed(0)}%`
    : `${speed} · alt ${i.altitude.toFixed(0)} m · ${aboveGround} · throttle ${(state.throttle * 100).toFixed(0)}% · rings: ${state.score} passed${missedNote} · ${toGo} to go`;
  if (readLine.textContent !== read) readLine.textContent = read;
  if (!compact) {
    const text = [
      `airspeed  ${i.speed.toFixed(0).padStart(4)} m/s  ${(i.speed * 1.944).toFixed(0).padStart(4)} kt`,
      `altitude  ${i.altitude.toFixed(0).padStart(5)} m (sea level)`,
      `          ${aboveGround}`,
      `climb     ${i.climb.toFixed(1).padStart(6)} m/s`,
      `pitch ${i.pitch.toFixed(1).padStart(6)}°  bank ${i.roll.toFixed(1).padStart(6)}°`,
      `heading   ${i.heading.toFixed(0).padStart(4)}°`,
      `AoA (wing) ${i.aoa.toFixed(1).padStart(5)}°  ${state.stalled ? 'STALL' : `stall at ${((AIRCRAFT.stallAngle * 180) / Math.PI).toFixed(0)}°`}`,
      `throttle  ${(state.throttle * 100).toFixed(0).padStart(4)}%`,
      `assist    ${params.assist ? 'on' : 'off'}`,
    ].join('\n');
    if (panelEl.textContent !== text) panelEl.textContent = text;
  }
  // The end card and its button (built again only when what it says changes).
  // After a crash the card waits CRASH_CARD_MS, so that the explosion is seen first.
  const waiting = state.phase === 'crashed' && performance.now() - crashWall < CRASH_CARD_MS;
  const card =
    state.phase === 'flying' || waiting
      ? ''
      : `${state.phase} ${state.score} ${state.missed} ${state.secondPassed} ${state.time} ${lastVsBest}`;
  if (card === shownCard) return;
  shownCard = card;
  if (card === '') {
    endCard.hide();
    showAgain(false);
  } else if (state.phase === 'done') {
    showFinish();
  } else {
    // Crashed.
    const best = bestOf();
    endCard.show({
      title: 'Crashed!',
      lost: true,
      lines: [
        {
          text: `You hit the ${crashInto} at ${(crashReadings?.speed ?? 0).toFixed(0)} m/s · ${state.score} of ${total} rings.`,
          strong: true,
        },
        best
          ? `Best: ${best.passed} of ${total} rings in ${clock(best.time)}`
          : // A phone's readout gives only the height above the ground, not the sea-level "alt".
            compact
            ? 'Watch the height above ground: the hills reach 700 m.'
            : 'Watch the height above ground: alt counts from sea level, and the hills reach 700 m.',
      ],
    });
    showAgain(true, 'Try again ↺');
  }
}

/** Flies the next course (./finish.ts nextSeed): a new seed, the panel's slider following. */
function nextCourse(): void {
  params.seed = nextSeed(params.seed);
  panel.refresh();
  shell.reset();
}
/** Fills the end card with the finish screen (./finish.ts finishCard): the result, the stars, the best, Retry and Next course. */
function showFinish(): void {
  const card = finishCard({
    passed: state.score,
    total: rings.length,
    missed: state.missed,
    again: state.secondPassed,
    flown: state.time,
    vsBest: lastVsBest,
    best: bestOf(),
    touch: touchFirst,
    seed: params.seed,
  });
  showAgain(false);
  // Retry is R (the shell's reset) as well; Next course is Enter, which the card listens for while it shows.
  const press = { retry: () => shell.reset(), next: () => nextCourse() };
  endCard.show({
    title: card.title,
    lines: [{ text: card.result, strong: true }, card.detail, card.best],
    buttons: card.actions.map(({ action, label }) => ({
      label,
      action,
      primary: action === 'next',
      key: action === 'next' ? 'Enter' : undefined,
      onPress: press[action],
    })),
  });
}

/** Shows the newest event due in the banner for BANNER_LIFE s. */
function updateBanner(t: number): void {
  // The newest event already due (a note may be queued to follow the one on show).
  let last: (typeof events)[number] | undefined;
  for (let k = events.length - 1; k >= Math.max(0, events.length - 4); k--) {
    const ev = events[k]!;
    // A note of where the next ring lies goes once that ring is no longer next.
    if (ev.next !== undefined && ev.next !== nextRing(rings)) continue;
    if (ev.time <= t && (!last || ev.time > last.time)) last = ev;
  }
  const age = last ? t - last.time : Infinity;
  // On a phone the banner gives way to a tip the flight waits on (the two would cover the top third).
  if (last && age >= 0 && age < BANNER_LIFE && state.phase === 'flying' && !(compact && holding && tipText)) {
    banner.style.display = 'block';
    const text =
      last.relaid !== undefined
        ? relayText(last.relaid, spokenWay(last.relaid), compact)
        : last.next !== undefined
          ? nextRingText(last.next, spokenWay(last.next), compact)
          : last.text;
    if (banner.textContent !== text) banner.textContent = text;
    banner.style.color = last.colour;
    banner.style.opacity = String(age < 1.4 ? 1 : (BANNER_LIFE - age) / 0.6);
  } else banner.style.display = 'none';
}

/**
 * Shows the warning (flashing) while there is one, in its fixed place; on drawn frames, before the
 * ring label is placed, which keeps clear of it.
 */
function showWarning(t: number): void {
  const warned = state.warning !== '' && state.phase === 'flying';
  const display = warned ? 'block' : 'none';
  if (warningEl.style.display !== display) warningEl.style.display = display;
  // The floor's cue is steady and amber (the assist has it in hand); the warnings flash red.
  const cue = state.warning === FLOOR_CUE;
  const visibility = cue || Math.floor(t * 3) % 2 === 0 ? 'visible' : 'hidden';
  if (warningEl.style.visibility !== visibility) warningEl.style.visibility = visibility;
  const background = cue ? 'rgba(150, 95, 0, 0.92)' : 'rgba(120, 10, 10, 0.92)';
  if (warningEl.style.background !== background) warningEl.style.background = background;
  if (warningEl.textContent !== state.warning) warningEl.textContent = state.warning;
}

// ---- The attitude indicator (cockpit view), drawn at the top of the scene -------------------------

const attitudeSize = compact ? 120 : 150;
const horizon = createAttitudeIndicator(layout.stage, attitudeSize);
/** What the indicator showed last: pitch and roll, degrees (tests read them). */
const shownAttitude = { pitch: 0, roll: 0, visible: false };
/** The cockpit view's canopy frame and instrument panel; the attitude indicator sits in the panel's middle. */
const cockpit = createCockpit(layout.stage, attitudeSize);

/**
 * Puts "Paused" and the end's button (Fly again, Try again) above the cockpit's panel, whose top is
 * `panelTop` CSS px from the stage's top (0: no panel, they go back to the scene's bottom): low in
 * the scene they would sit on the attitude indicator.
 */
function liftOffPanel(panelTop: number): void {
  const lift = panelTop > 0 ? app.canvas.clientHeight - panelTop + PANEL_RIM : 0;
  const pad = lift > 0 ? `${lift + 8}px` : '2%';
  if (pauseOverlay.element.style.paddingBottom !== pad) pauseOverlay.element.style.paddingBottom = pad;
  const again = layout.stage.querySelector<HTMLElement>('.bp-action');
  const bottom = lift > 0 ? `${lift + 10}px` : '';
  if (again && again.style.bottom !== bottom) again.style.bottom = bottom;
}

/** Shows the cockpit view's frame and panel (or hides them) and draws the gauges for `i`. */
function drawCockpit(on: boolean, i: ReturnType<typeof instruments>): void {
  cockpit.show(on);
  horizon.show(on);
  shownAttitude.visible = on;
  liftOffPanel(on ? cockpit.panelTop() : 0);
  if (!on) return;
  // The heading to the next ring from the aircraft (the compass's bug), degrees in [0, 360).
  const n = nextRing(rings);
  const ring = n < 0 ? undefined : ((Math.atan2(rings[n]!.z - now[2]!, rings[n]!.x - now[0]!) * 180) / Math.PI + 360) % 360;
  cockpit.draw({ speed: i.speed, altitude: i.altitude, heading: i.heading, ring, climb: i.climb, throttle: state.throttle });
  const slot = cockpit.attitudeSlot();
  horizon.canvas.style.left = `${slot.x}px`;
  horizon.canvas.style.top = `${slot.y - slot.size / 2}px`;
  shownAttitude.pitch = i.pitch;
  shownAttitude.roll = i.roll;
  horizon.draw(i.pitch, i.roll);
}

// ---- Guidance: where the next ring is -----------------------------------------------------------

/**
 * A marker for the next ring: a label under it with its number and distance while it is in view,
 * else an arrow at the edge of the scene pointing the way to turn. The label is kept wholly inside
 * the scene.
 */
const ringPointer = overlay(
  `padding: 2px 8px; border-radius: 10px; background: rgba(10, 14, 22, 0.85); color: #ffcf5a; font: 700 ${compact ? 15 : 16}px system-ui, sans-serif; white-space: nowrap;`,
);
ringPointer.dataset.hud = 'ring-pointer';
/**
 * An outline round the next ring on the screen, drawn while it is in view: a circle at the ring's
 * projected centre, the ring's outer edge on the screen (RING_OUTER) but never smaller than
 * OUTLINE_LEAST px, so that a ring far off or seen edge on (a thin line a few px long on a phone)
 * still reads where it is. It fades as the ring grows on the screen, where the ring reads itself.
 */
const ringOutline = overlay(
  'box-sizing: border-box; border: 3px solid #ffd21f; border-radius: 50%; box-shadow: 0 0 0 1.5px rgba(10, 14, 22, 0.8), inset 0 0 0 1.5px rgba(10, 14, 22, 0.8); display: none;',
);
ringOutline.dataset.hud = 'ring-outline';
/** Least radius of the next ring's outline on the screen, px. */
const OUTLINE_LEAST = compact ? 13 : 15;
const ringAt = new Vector3(),
  rimAt = new Vector3(),
  camUp = new Vector3();
/**
 * What the pointer shows (tests): the ring's index (-1: none left), whether it is in view, the text,
 * its box in the stage (px: left, top, width, height) and, in view, the ring's circle on the screen
 * (px: centre x, y and the radius of its outer edge, halo included).
 */
const ringAim = { index: -1, inView: false, text: '', box: [0, 0, 0, 0], ring: [0, 0, 0] };
function pointToNextRing(): void {
  const i = nextRing(rings);
  ringAim.index = i;
  ringPointer.style.display = i < 0 || state.phase !== 'flying' ? 'none' : 'block';
  ringOutline.style.display = 'none';
  if (i < 0 || state.phase !== 'flying') return;
  const ring = rings[i]!;
  ringAt.set(ring.x, ring.y, ring.z);
  const d = ringAt.distanceTo(at);
  const w = app.canvas.clientWidth,
    h = app.canvas.clientHeight;
  ringAt.project(app.camera);
  const ahead = ringAt.z < 1;
  let x = ((ringAt.x + 1) / 2) * w,
    y = ((1 - ringAt.y) / 2) * h;
  // In the cockpit view the panel covers the stage's bottom: the label stays above it.
  const bottom = state.camera === 'cockpit' ? cockpit.panelTop() || h : h;
  ringAim.inView = ahead && x > 0 && x < w && y > 0 && y < bottom;
  const distance = distanceText(d);
  if (ringAim.inView) {
    ringAim.text = `ring ${i + 1} · ${distance}`;
    // Above the ring, clear of it (its radius on screen to the halo's outer edge, from a point on it
    // at the camera's up) and so of the flight-path marker inside it (not under the centre, under the
    // marker's crosshair); else below it, beside it or at a corner.
    rimAt.set(ring.x, ring.y, ring.z).addScaledVector(camUp.set(0, 1, 0).applyQuaternion(app.camera.quaternion), RING_OUTER);
    rimAt.project(app.camera);
    const rPx = Math.hypot(((rimAt.x - ringAt.x) / 2) * w, ((rimAt.y - ringAt.y) / 2) * h);
    ringAim.ring = [x, y, rPx];
    // The outline's outer edge is the pass test's radius (./course.ts PASS_RADIUS), not the halo's: the
    // marker inside the outline is green and the tip says "in it" (with the halo's, a marker between the
    // two sat inside the outline, orange, under a tip still saying "until ⊕ is in it").
    const r = Math.max(OUTLINE_LEAST, (rPx * PASS_RADIUS) / RING_OUTER);
    ringOutline.style.display = 'block';
    ringOutline.style.left = `${x}px`;
    ringOutline.style.top = `${y}px`;
    ringOutline.style.width = ringOutline.style.height = `${2 * r}px`;
    // The cockpit's panel is in front of the world: the outline is cut off at its top edge, as the
    // ring is, never drawn over the instruments.
    const cut = Math.max(0, y + r - bottom);
    const clip = cut > 0 ? `inset(-4px -4px ${cut}px -4px)` : '';
    if (ringOutline.style.clipPath !== clip) ringOutline.style.clipPath = clip;
    ringOutline.style.opacity = String(Math.max(0.3, Math.min(1, 1 - (rPx - 40) / 120)));
    ringPointer.textContent = ringAim.text;
    const bw = ringPointer.offsetWidth / 2,
      bh = ringPointer.offsetHeight / 2;
    const half = bh + LABEL_GAP,
      halfW = bw + LABEL_GAP,
      d = rPx * Math.SQRT1_2;
    const places: [number, number][] = [
      [x, y - rPx - half],
      [x, y + rPx + half],
      [x - rPx - halfW, y],
      [x + rPx + halfW, y],
      [x - d - halfW, y - d - half],
      [x + d + halfW, y - d - half],
      [x - d - halfW, y + d + half],
      [x + d + halfW, y + d + half],
    ].map(([px, py]) => keepInScene(px!, py!, w, bottom));
    // Whether the label at (px, py) covers the ring (its box reaches inside the ring's outer edge: a
    // far ring is small, and the label held inside the scene slid over it), or the marker.
    const coversRing = ([px, py]: [number, number]) =>
      Math.hypot(Math.max(Math.abs(px - x) - bw, 0), Math.max(Math.abs(py - y) - bh, 0)) < rPx + 2;
    const coversMarker = ([px, py]: [number, number]) =>
      marker.style.display !== 'none' &&
      Math.abs(px - pathAim.x) <= halfW + MARKER_HALF[0] + MARKER_PAD &&
      Math.abs(py - pathAim.y) <= half + MARKER_HALF[1] + MARKER_PAD;
    // Or the aircraft (its box on the screen in the chase view, `planeBox`): a label over the tail
    // hides the aircraft and reads as the aircraft's own.
    const [p0, q0, pw, ph] = planeBox;
    const coversPlane = ([px, py]: [number, number]) =>
      pw > 0 && px + halfW > p0 && px - halfW < p0 + pw && py + half > q0 && py - half < q0 + ph;
    [x, y] =
      places.find((p) => !coversRing(p) && !coversMarker(p) && !coversPlane(p)) ??
      places.find((p) => !coversRing(p) && !coversPlane(p)) ??
      places.find((p) => !coversRing(p) && !coversMarker(p)) ??
      places.find((p) => !coversRing(p)) ??
      places.find((p) => !coversMarker(p)) ??
      places[0]!;
  } else if (ahead && bottom < h && x > 0 && x < w && y >= bottom && y < h) {
    // Ahead but under the cockpit's panel (a ring below the nose): the label points down at it from
    // just above the panel and says where it is (a small ▼ at the scene's edge goes unseen).
    y = bottom;
    ringAim.text = `▼ ring ${i + 1} · ${distance} · under the panel`;
  } else {
    // Behind the camera the projection is mirrored: point the other way.
    let dx = x - w / 2,
      dy = y - h / 2;
    if (!ahead) {
      dx = -dx;
      dy = -dy;
    }
    const k = Math.min((w / 2 - 70) / Math.max(1e-6, Math.abs(dx)), (h / 2 - 24) / Math.max(1e-6, Math.abs(dy)));
    x = w / 2 + dx * k;
    y = h / 2 + dy * k;
    // Out of view: the label says which way the ring lies and how to turn to it (./ring-pointer.ts).
    const V = shell.world.components.Velocity,
      e = handles.body;
    const { bearing, elevation } = ringBearing(ring, [at.x, at.y, at.z], [V.x[e]!, V.y[e]!, V.z[e]!]);
    ringAim.text = offScreenLabel({
      ring: i + 1,
      distance,
      dx,
      dy,
      halfW: w / 2,
      halfH: h / 2,
      behind: !ahead,
      touch: touchFirst,
      bearing,
      elevation,
    }).text;
  }
  // Out of view, the label is the only sign of the ring: larger and edged, so it is not missed.
  const lost = !ringAim.inView ? 'true' : 'false';
  if (ringPointer.dataset.lost !== lost) {
    ringPointer.dataset.lost = lost;
    ringPointer.style.fontSize = ringAim.inView ? '' : `${compact ? 16 : 18}px`;
    ringPointer.style.boxShadow = ringAim.inView ? '' : 'inset 0 0 0 2px #ffcf5a';
  }
  if (ringPointer.textContent !== ringAim.text) ringPointer.textContent = ringAim.text;
  [x, y] = keepInScene(x, y, w, bottom);
  // Never under the marker, which is drawn over it (a label at the scene's edge, wide on a phone,
  // reached over the marker in the middle; a ring's every place round it could): moved the least way
  // clear of it, inside the scene and off the messages.
  const hw = ringPointer.offsetWidth / 2 + 4,
    hh = ringPointer.offsetHeight / 2 + 4;
  if (marker.style.display !== 'none')
    [x, y] = clearOfBox(x, y, hw - 4, hh - 4, markerDrawnBox(), LABEL_GAP, { w, h: bottom, margin: EDGE_MARGIN, avoid: shownBoxes() });
  ringPointer.style.left = `${x}px`;
  ringPointer.style.top = `${y}px`;
  ringAim.box = [x - hw + 4, y - hh + 4, 2 * hw - 8, 2 * hh - 8];
}

/**
 * The ring label's centre (px) moved inside the scene `w` px wide, `bottom` px high (above the
 * cockpit's panel), its box EDGE_MARGIN px from each edge (never touching the phone's edge), and
 * clear of the warning, the banner and the tip (./label-place.ts labelClearOf), so a ring above the
 * view keeps its label readable, not hidden behind the tip at the scene's top.
 */
function keepInScene(x: number, y: number, w: number, bottom: number): [number, number] {
  const hw = ringPointer.offsetWidth / 2 + EDGE_MARGIN,
    hh = ringPointer.offsetHeight / 2 + EDGE_MARGIN;
  const cx = Math.max(hw, Math.min(w - hw, x));
  const cy = Math.max(hh, Math.min(bottom - hh, y));
  return [cx, labelClearOf(cx, cy, hw - EDGE_MARGIN, hh - EDGE_MARGIN, shownBoxes(), app.canvas.clientHeight, EDGE_MARGIN)];
}
/**
 * The boxes over the scene the ring label keeps clear of (px in the stage: left, top, width, height):
 * the warning while it is on, and the banner, the engine's note and the tip as last placed and shown.
 */
function shownBoxes(): ScreenBox[] {
  const boxes: ScreenBox[] = [];
  for (const el of [warningEl, banner, throttleNote, tip])
    if (el.style.display !== 'none') boxes.push([el.offsetLeft - el.offsetWidth / 2, el.offsetTop, el.offsetWidth, el.offsetHeight]);
  return boxes;
}
/** Least gap between the ring label and the scene's edges, px. */
const EDGE_MARGIN = 10;
/**
 * Half the flight-path marker's box, px (wide, high): its drawing (34 x 20 units) scaled 1.5 on a
 * desktop, 1.35 on a phone, so that it is seen at a glance.
 */
const MARKER_HALF: readonly [number, number] = compact ? [23, 13.5] : [25.5, 15];
/**
 * How far the marker's drawing reaches past its box, px: its black outline (5.5 units wide, round
 * caps) past the wing tips and the tick on top (2.75 units: 4 px at its scale) and its drop shadow
 * (3 px).
 */
const MARKER_PAD = 7;
/** The flight-path marker's box as drawn (MARKER_HALF round its point and MARKER_PAD), px: left, top, width, height. */
function markerDrawnBox(): ScreenBox {
  const [hx, hy] = [MARKER_HALF[0] + MARKER_PAD, MARKER_HALF[1] + MARKER_PAD];
  return [pathAim.x - hx, pathAim.y - hy, 2 * hx, 2 * hy];
}
/** Gap between the ring label and the ring it labels, px. */
const LABEL_GAP = 6;
/** The next ring's outer edge from its centre, m: the pulsing halo's (RING_RADIUS + 12, tube 2.5, pulse 6 %). */
const RING_OUTER = (RING_RADIUS + 12 + 2.5) * 1.06;

// ---- Lessons: what the first rings ask for, in plain words ----------------------------------------

/**
 * A tip over the scene's top while the next ring is one of the lessons (./course.ts LESSONS: ring 2
 * a turn, ring 3 a climb or a dive, ring 4 a turn the other way): which way it lies and what to do,
 * in words for someone who has never flown: ring 2's tip says that an aeroplane turns by tipping its
 * wings (banking), which a newcomer may not know.
 */
const tip = overlay(
  `left: 50%; width: max-content; max-width: min(${MESSAGE_WIDTH}, 560px); box-sizing: border-box; padding: 5px 14px; border-radius: 12px; background: rgba(8, 12, 20, 0.8); color: #eef3f8; font: 600 ${compact ? 13 : 16}px/1.3 system-ui, sans-serif; text-align: center; display: none;`,
);
tip.dataset.hud = 'tip';
const tipWords = document.createElement('div'),
  tipWaitEl = document.createElement('div');
tipWaitEl.dataset.hud = 'tip-wait';
tipWaitEl.style.cssText = `color: #ffd166; font-size: ${compact ? 13 : 15}px; margin-top: 2px;`;
tip.append(tipWords, tipWaitEl);
/** The tip's second line now ('' when the flight is not waiting). */
let tipWait = '';
/** Game time after which the tip for `tipRing` goes (Infinity: it stays while its ring is next). */
let tipGoneAt = Infinity;
/** How long a tip stays after the pilot acts on it, s of game time: on a phone, and ring 1's start tip. */
const TIP_LINGER = 3;
/**
 * How long a lesson tip the flight does not wait for (rings 3 and 4) stays on a phone, s of game
 * time from when it shows: long enough to read two lines, and then the sky is clear again for the
 * rest of the way to the ring, as after a tip that waited (TIP_LINGER).
 */
const TIP_READ = 5;
/** Whether the page is used by touch first (a phone): the tips name the stick, not the keys. */
const touchFirst = matchMedia('(pointer: coarse)').matches;
/** What the tip shows now ('' when none; tests). */
let tipText = '';
/**
 * The lesson ring the tip is for (-1: none), and which ways it lies from the line flown now
 * (./course.ts ringBearing, ringWay: right or left, higher or lower, and how much), worked out every
 * frame from where the aircraft is and flies, not written per ring (which could say "higher" while
 * the ring lies to the left).
 */
let tipRing = -1,
  tipWay: RingWay = { side: 0, up: 0, sideAmount: '', upAmount: '' };

/** Which ways ring `i` lies from the line flown now (./course.ts ringWay): the tip and the banner both read it. */
function wayOf(i: number): RingWay {
  const V = shell.world.components.Velocity,
    e = handles.body;
  return ringWay(ringBearing(rings[i]!, now, [V.x[e]!, V.y[e]!, V.z[e]!]));
}

/**
 * Which ways ring `i` lies as the words over the scene say it: for the coach's rings (from
 * LESSON_RINGS on) while the marker shows the next one, from the marker's point (./coach.ts
 * markerBearing; straight ahead while it is green), so the words agree with the screen; else from the
 * line flown (`wayOf`). The coach's tip and the banner over it both read this, so the two never say
 * different ways.
 */
function spokenWay(i: number): RingWay {
  if (!(i >= LESSON_RINGS && i === nextRing(rings) && markedAt)) return wayOf(i);
  // With the marker green the aircraft goes through as it flies: "straight ahead", as the tip's
  // "let go" (not "Next, ring 6: a little right" over it, the marker's point 30 m off the centre).
  return pathAim.inside && pathAim.ring === i
    ? { side: 0, up: 0, sideAmount: '', upAmount: '' }
    : ringWay(markerBearing(rings[i]!, markedAt));
}

/** The key that climbs (up, or down with the pilot's pitch) or dives, for `up` +1 or -1. */
function climbKey(up: number): string {
  return up > 0 !== params.pilotPitch ? '↑' : '↓';
}

/** The tip for the next ring now (a lesson's, then the coach's), or '' (once the flight is over). */
function lessonTip(): string {
  const i = nextRing(rings);
  if (state.phase !== 'flying' || i < 0) {
    tipRing = -1;
    return '';
  }
  if (tipRing !== i) {
    tipGoneAt = compact && !holding && i >= 2 ? shell.world.time + TIP_READ : Infinity;
    tipRing = i;
  }
  // The ways are worked out afresh every frame from where the aircraft is and flies now: a tip
  // kept from when it first showed could say "Ring 2 is to the left" with the ring already to the right.
  tipWay = wayOf(i);
  // Ring 1's tip is the start's, up while the flight waits; on a phone each tip goes a little after
  // the pilot has acted on it (TIP_LINGER), so it does not cover the sky all the way to its ring.
  if ((i === 0 && !holding) || shell.world.time >= tipGoneAt) return '';
  const reader = { touch: touchFirst, compact, pilotPitch: params.pilotPitch };
  // After the lessons the coach says where each ring lies and what to do, to the last (./coach.ts).
  if (i >= LESSON_RINGS)
    return courseTipText(i, rings.length, spokenWay(i), reader, pathAim.visible && pathAim.inside ? pathAim.offset : Infinity);
  // A lesson's "straight ahead: let go" only when letting go flies the aircraft through (the line
  // flown now can point at the ring while the turn still in it carries the path off: then the
  // marker's way, which names where to steer).
  const through = !tipWay.side && !tipWay.up && markedAt && !pathAim.inside;
  return lessonTipText(i, through ? ringWay(markerBearing(rings[i]!, markedAt!)) : tipWay, reader);
}

/** What to touch on a phone, and where: the round stick under the scene, at its left. */
const STICK_WHERE = 'Drag the stick at bottom left';

/** What the tip's second line asks while the flight waits for the pilot (`holding`): the input that goes on. */
function waitLine(): string {
  if (!holding) return '';
  // The stick is named with its place: "move the stick" alone leaves a newcomer looking for one.
  if (tipRing === 0) return touchFirst ? `${STICK_WHERE} to start.` : 'Press an arrow key to start.';
  const key = tipWay.side ? (tipWay.side > 0 ? '→' : '←') : tipWay.up ? climbKey(tipWay.up) : 'an arrow key';
  return touchFirst ? 'Paused: drag the stick to fly on.' : `Paused: press ${key} to fly on.`;
}

/**
 * The phone's stick glows while the flight waits for it (`holding`): the tip says "drag the stick at
 * bottom left" and the glow shows which one.
 */
const stickGlow = document.createElement('style');
stickGlow.textContent =
  '@keyframes flight-stick-glow { 50% { box-shadow: 0 0 0 6px rgba(255, 209, 102, 0.9), 0 0 18px 6px rgba(255, 209, 102, 0.6); } } .flight-wait .bp-stick { animation: flight-stick-glow 1.2s ease-in-out infinite; }';
document.head.append(stickGlow);

/** Shows the lesson tip for the next ring, if any (its place: `placeMessages`), and the stick's glow while the flight waits. */
function showTip(): void {
  const text = lessonTip();
  const wait = text ? waitLine() : '';
  const glow = holding && touchFirst;
  if (document.body.classList.contains('flight-wait') !== glow) document.body.classList.toggle('flight-wait', glow);
  if (text !== tipText || wait !== tipWait) {
    tipText = text;
    tipWait = wait;
    tipWords.textContent = text;
    tipWaitEl.textContent = wait;
    tipWaitEl.style.display = wait ? 'block' : 'none';
    tip.style.display = text ? 'block' : 'none';
  }
}

// ---- A ring behind the aircraft: the aircraft stays solid, the ring's outline and label show it ----

/**
 * Whether the next ring's centre lies behind the drawn aircraft on the screen now (chase view; within
 * half the ring's radius of the aircraft's box; tests). The aircraft, nearer, stays solid in front of
 * the ring (faded see-through, the ring would show through it as if in front: a depth error to the eye);
 * the ring's outline and label, drawn over the scene, say where it is.
 */
let ringBehindPlane = false;
/** The aircraft's box on the screen as last drawn (px: left, top, width, height; tests). */
const planeBox: [number, number, number, number] = [0, 0, 0, 0];
const corner = new Vector3();
planeGeometry.computeBoundingBox();
const modelBox = planeGeometry.boundingBox!;
/**
 * The model's outermost points (body frame, m): nose, tail, fin top, keel and the wing tips, so
 * that the box round them on the screen is the aircraft's (the corners of its 3D bounding box, most
 * of them empty air, made a box twice as tall that faded the aircraft in a bank with the ring well above it).
 */
const PLANE_POINTS: readonly (readonly [number, number, number])[] = [
  [modelBox.max.x, 0, 0],
  [modelBox.min.x, 0, 0],
  [modelBox.min.x, modelBox.max.y, 0],
  [0, modelBox.min.y, 0],
  [0, 0, modelBox.max.z],
  [0, 0, modelBox.min.z],
];
/**
 * Finds the aircraft's box on the screen (`planeBox`; chase view while flying, else all 0), before the
 * ring label is placed: the label keeps off the aircraft.
 */
function measurePlane(): void {
  planeBox.fill(0);
  if (state.camera === 'chase' && state.phase === 'flying') {
    let x0 = Infinity,
      y0 = Infinity,
      x1 = -Infinity,
      y1 = -Infinity;
    const w = app.canvas.clientWidth,
      h = app.canvas.clientHeight;
    for (const [px, py, pz] of PLANE_POINTS) {
      corner.set(px, py, pz).applyQuaternion(drawnQ).add(at).project(app.camera);
      const x = ((corner.x + 1) / 2) * w,
        y = ((1 - corner.y) / 2) * h;
      x0 = Math.min(x0, x);
      x1 = Math.max(x1, x);
      y0 = Math.min(y0, y);
      y1 = Math.max(y1, y);
    }
    planeBox.splice(0, 4, x0, y0, x1 - x0, y1 - y0);
  }
}
/** Finds whether the next ring is behind the aircraft's box on the screen (`ringBehindPlane`; chase view). */
function findRingBehindPlane(): void {
  const [x0, y0, pw, ph] = planeBox;
  let behind = false;
  if (pw > 0 && ringAim.inView) {
    const [cx, cy, r] = ringAim.ring as [number, number, number];
    behind = cx > x0 - r / 2 && cx < x0 + pw + r / 2 && cy > y0 - r / 2 && cy < y0 + ph + r / 2;
  }
  ringBehindPlane = behind;
}

// ---- The engine's note and the message lane ------------------------------------------------------

/**
 * A note of the engine's setting for THROTTLE_NOTE_MS after Faster or Slower moved it ("Engine 40 %"
 * and a bar of tenths): a tap of the phone's Faster button shows what it did where the eye is.
 */
const throttleNote = overlay(
  `left: 50%; width: max-content; max-width: ${MESSAGE_WIDTH}; box-sizing: border-box; padding: 2px 12px; border-radius: 10px; background: rgba(8, 12, 20, 0.8); color: #8fe3ff; font: 700 ${compact ? 15 : 17}px/1.25 system-ui, sans-serif; text-align: center; display: none;`,
);
throttleNote.dataset.hud = 'throttle-note';
const throttleWords = document.createElement('span'),
  throttleBar = document.createElement('span'),
  throttleFill = document.createElement('span');
throttleBar.style.cssText = `display: inline-block; vertical-align: middle; margin-left: 8px; width: ${compact ? 70 : 90}px; height: 8px; border-radius: 4px; background: rgba(143, 227, 255, 0.25); overflow: hidden;`;
throttleFill.style.cssText = 'display: block; height: 100%; background: #8fe3ff;';
throttleBar.append(throttleFill);
throttleNote.append(throttleWords, throttleBar);
/** How long the engine's note stays after the throttle last moved, ms. */
const THROTTLE_NOTE_MS = 1500;
/** Shows the engine's note while the throttle moved by Faster or Slower less than THROTTLE_NOTE_MS ago. */
function showThrottleNote(): void {
  const on = state.phase === 'flying' && performance.now() - throttleShownAt < THROTTLE_NOTE_MS;
  // The word the readout uses for it (a desktop's "throttle", a phone's "engine").
  const text = on ? `${compact ? 'Engine' : 'Throttle'} ${(state.throttle * 100).toFixed(0)} %` : '';
  if (throttleWords.textContent !== text) throttleWords.textContent = text;
  const fill = `${(state.throttle * 100).toFixed(0)}%`;
  if (throttleFill.style.width !== fill) throttleFill.style.width = fill;
  const display = on ? 'block' : 'none';
  if (throttleNote.style.display !== display) throttleNote.style.display = display;
}

/**
 * Every message over the scene but the warning (the banner, the engine's note and the lesson tip,
 * in that order) sits in one column, one under the other, never on each other: at the
 * scene's top, or in its low lane (above the cockpit's instrument panel in that view, so the gauges
 * stay clear) while the top one would cover the next ring, its label or the flight-path marker and
 * the low one would not, and back up once the top is clear by LANE_RETURN px (the margin keeps the
 * column from jumping back and forth as the ring moves). The warning keeps one place at the scene's
 * top, over everything; while it is on, the top lane starts under it. A fixed place for each would put
 * the banner over the ring ahead, or the warning over the cockpit's gauges.
 */
let messagesLow = false;
/** Gap between the messages, and between them and the scene's edge or the cockpit's panel, px. */
const LANE_GAP = compact ? 6 : 8;
/** How far clear of the ring, its label and the marker the top lane must be for the messages to go back up to it, px. */
const LANE_RETURN = 40;
/** How far over the cockpit's panel top its rim and the figures on it reach, px. */
const PANEL_RIM = 18;
/** Where the messages sat last (tests): in the low lane or not, and each shown one's name and box (px in the stage: left, top, width, height). */
const messageLayout = {
  low: false,
  boxes: [] as { hud: string; box: [number, number, number, number] }[],
  /** The warning's box while it is on (px in the stage: left, top, width, height), else null. */
  warning: null as [number, number, number, number] | null,
};
/** What the messages must not cover, as boxes (px: left, top, width, height) and the ring's circle. */
function coveredBy(box: readonly number[], pad = 0): number {
  const [x0, y0, w0, h0] = box as [number, number, number, number];
  const x = x0 - pad,
    y = y0 - pad,
    bw = w0 + 2 * pad,
    bh = h0 + 2 * pad;
  let n = 0;
  const boxHit = (o: readonly number[]) => x < o[0]! + o[2]! && o[0]! < x + bw && y < o[1]! + o[3]! && o[1]! < y + bh;
  if (ringAim.inView && ringPointer.style.display !== 'none') {
    const [cx, cy, r] = ringAim.ring as [number, number, number];
    const dx = Math.max(x - cx, 0, cx - (x + bw)),
      dy = Math.max(y - cy, 0, cy - (y + bh));
    if (Math.hypot(dx, dy) < r) n++;
    if (boxHit(ringAim.box)) n++;
  }
  if (marker.style.display !== 'none')
    if (boxHit([pathAim.x - MARKER_HALF[0], pathAim.y - MARKER_HALF[1], 2 * MARKER_HALF[0], 2 * MARKER_HALF[1]])) n++;
  return n;
}
/** Places the messages shown now in their lane (`messagesLow`), after the ring's label and the marker are placed. */
function placeMessages(): void {
  const items = [banner, throttleNote, tip].filter((el) => el.style.display !== 'none');
  // The warning keeps its own place at the top: while it is on, the top lane starts under it.
  const warned = warningEl.style.display !== 'none';
  const topLane = warned ? warningEl.offsetTop + warningEl.offsetHeight + LANE_GAP : LANE_GAP;
  messageLayout.warning = warned
    ? [warningEl.offsetLeft - warningEl.offsetWidth / 2, warningEl.offsetTop, warningEl.offsetWidth, warningEl.offsetHeight]
    : null;
  const w = app.canvas.clientWidth,
    h = app.canvas.clientHeight;
  // In the cockpit view the lane ends over the panel's rim (the phone's heading figure sits on it).
  const cockpitOn = state.camera === 'cockpit' && state.phase !== 'crashed' && cockpit.panelTop() > 0;
  const bottom = cockpitOn ? cockpit.panelTop() - LANE_GAP - PANEL_RIM : h - LANE_GAP;
  const sizes = items.map((el) => [el.offsetWidth, el.offsetHeight] as const);
  const total = sizes.reduce((sum, [, bh]) => sum + bh + LANE_GAP, -LANE_GAP);
  const boxesAt = (low: boolean): [number, number, number, number][] => {
    let y = low ? Math.max(topLane, bottom - total) : topLane;
    return sizes.map(([bw, bh]) => {
      const box: [number, number, number, number] = [w / 2 - bw / 2, y, bw, bh];
      y += bh + LANE_GAP;
      return box;
    });
  };
  const covers = (low: boolean, pad = 0) => boxesAt(low).reduce((n, b) => n + coveredBy(b, pad), 0);
  if (items.length > 0) {
    const here = covers(messagesLow);
    // Back to the top once it is clear by LANE_RETURN px (the low lane covers the aircraft in the chase view).
    if ((here > 0 && covers(!messagesLow) < here) || (messagesLow && covers(false, LANE_RETURN) === 0)) {
      messagesLow = !messagesLow;
      // On a phone the kit's card of touch gestures (game-kit hud.ts showTouchHint) may still be up
      // over the scene's bottom for a few seconds: it goes now, as it does at a touch on the scene.
      if (messagesLow) layout.stage.querySelector('.bp-touch-hint')?.classList.add('bp-gone');
    }
  }
  const boxes = boxesAt(messagesLow);
  messageLayout.low = messagesLow;
  messageLayout.boxes = items.map((el, k) => ({ hud: el.dataset.hud ?? '', box: boxes[k]! }));
  items.forEach((el, k) => {
    const top = `${boxes[k]![1]}px`;
    if (el.style.top !== top) el.style.top = top;
    if (el.style.transform !== 'translate(-50%, 0px)') el.style.transform = 'translate(-50%, 0px)';
  });
}

// ---- The flight-path marker: where the aircraft is going, at the next ring's distance ------------

/**
 * A small circle with wings drawn where the aircraft's path meets the next ring's plane, the path
 * curved by the turn and the climb it is in (./course.ts predictThroughRing): with the assist, the
 * path flown if the pilot lets go now (the wings and the path roll level as the assist brings them),
 * so holding a turn until the marker is in the ring and letting go flies through it; without the
 * assist, the turn held as it is. (A straight line from the velocity would ignore the turn: a pilot
 * banking towards a ring would see the marker at its edge and miss it by far.) Orange when it is outside
 * the ring (not the ring's yellow: on the tube it must not read as in), green when the whole aircraft goes through (./course.ts clearThrough), each over a thick black outline so that it shows on sky, cloud,
 * ground and the yellow ring alike (a thin white one is lost against the sky and the clouds);
 * hidden when the ring's plane is not met.
 */
const marker = overlay(`width: ${2 * MARKER_HALF[0]}px; height: ${2 * MARKER_HALF[1]}px; display: none;`);
marker.dataset.hud = 'path-marker';
{
  const shape = '<circle r="5.5"/><path d="M-15 0H-6M6 0H15M0 -6V-10"/>';
  marker.innerHTML = `<svg viewBox="-17 -10 34 20" width="${2 * MARKER_HALF[0]}" height="${2 * MARKER_HALF[1]}" style="overflow: visible"><g fill="none" stroke-linecap="round"><g stroke="#000" stroke-width="5.5">${shape}</g><g stroke="currentColor" stroke-width="2.6">${shape}</g></g></svg>`;
}
/**
 * What the marker shows (tests): visible, inside the next ring, its offset from the ring's centre
 * (m), its place (px), the game time of the drawn frame that placed it last (s; frames the pacer
 * does not draw leave it where it was) and the ring it was placed for.
 */
const pathAim = { visible: false, inside: false, offset: Infinity, x: 0, y: 0, drawnAt: -1, ring: -1 };
const markAt = new Vector3();
/** Where the marker shows the aircraft passing the next ring's plane (m, world), or null when it shows none. */
let markedAt: readonly number[] | null = null;
function markPath(): void {
  const i = nextRing(rings);
  const world = shell.world,
    e = handles.body,
    V = world.components.Velocity;
  pathAim.drawnAt = world.time;
  const through =
    i >= 0 && state.phase === 'flying'
      ? predictThroughRing(
          rings[i]!,
          { position: now, velocity: [V.x[e]!, V.y[e]!, V.z[e]!], ...motion, held: heldBank(assistState) },
          params.assist,
        )
      : null;
  pathAim.visible = !!through && Number.isFinite(through.offset);
  markedAt = pathAim.visible && through ? through.point : null;
  marker.style.display = pathAim.visible ? 'block' : 'none';
  promise.ring = -1;
  // Green stays green while it holds (./course.ts CLEAR_MARGIN), for the same ring only.
  const was = pathAim.inside && pathAim.ring === i;
  pathAim.ring = i;
  pathAim.inside = false;
  if (!through || !pathAim.visible) return;
  pathAim.offset = through.offset;
  // Green, and a promise kept (`promise`), only where the whole aircraft goes through (./course.ts
  // clearThrough: the ring less half the wingspan), as the coach's "let go" (a marker green on the
  // tube, with a wing through it, drifted out as the path settled and the ring was missed).
  pathAim.inside = clearThrough(through.offset, was);
  if (pathAim.inside) {
    promise.ring = i;
    promise.at = world.time;
  }
  // Drawn from the drawn aircraft (the same offset as the physics' path, from where it is drawn).
  markAt.set(through.point[0] - now[0]! + at.x, through.point[1] - now[1]! + at.y, through.point[2] - now[2]! + at.z).project(app.camera);
  pathAim.x = ((markAt.x + 1) / 2) * app.canvas.clientWidth;
  pathAim.y = ((1 - markAt.y) / 2) * app.canvas.clientHeight;
  const shown = markAt.z < 1 && pathAim.x > 0 && pathAim.x < app.canvas.clientWidth && pathAim.y > 0 && pathAim.y < app.canvas.clientHeight;
  marker.style.display = shown ? 'block' : 'none';
  marker.style.left = `${pathAim.x}px`;
  marker.style.top = `${pathAim.y}px`;
  marker.style.color = pathAim.inside ? '#5dff8a' : '#ff9a4a';
  marker.style.filter = 'drop-shadow(0 0 3px rgba(0, 0, 0, 0.7))';
}

/**
 * "Let go now" under the path marker (./let-go.ts): shown while a held bank, let go now, would end
 * the turn on the next ring (the wings roll level but the turn runs on meanwhile, about 6 degrees
 * from a steep bank: let go when the ring is straight ahead and the aircraft swings past it).
 */
const letGoEl = overlay(
  'display: none; padding: 2px 10px; border-radius: 10px; background: rgba(10, 36, 18, 0.88); color: #5dff8a; font: 700 15px system-ui, sans-serif; white-space: nowrap;',
);
letGoEl.dataset.hud = 'let-go';
/** Whether the "let go now" cue shows now (tests). */
let letGoShown = false;

/** Shows or hides the "let go now" cue for the frame (./let-go.ts letGoCue), under the marker or, with it off screen, mid-scene. */
function cueLetGo(): void {
  const i = nextRing(rings);
  const world = shell.world,
    e = handles.body,
    V = world.components.Velocity;
  const speed = Math.hypot(V.x[e]!, V.y[e]!, V.z[e]!);
  let on = false;
  if (i >= 0 && state.phase === 'flying' && params.assist && speed > 1 && !holding) {
    const r = rings[i]!;
    const runOn = runOnTurn(motion.bank, motion.rollRate, speed);
    const after = bearingAfterLetGo(r.x - now[0]!, r.z - now[2]!, Math.atan2(V.z[e]!, V.x[e]!), runOn);
    // The stick's own deflection (not its smoothed input, which eases out after the finger lifts), or
    // a bank key's ramped input: the cue goes the moment the pilot lets go.
    on = letGoCue(after, runOn, clamp1(keyInput.roll + stickInput.x));
  }
  letGoShown = on;
  letGoEl.style.display = on ? 'block' : 'none';
  if (!on) return;
  // Named for what is held: a bank key's arrow (a climb key may stay held), or the stick.
  const text = stickInput.x !== 0 ? 'Let go now' : `Let go of ${keyInput.roll > 0 ? '→' : '←'} now`;
  if (letGoEl.textContent !== text) letGoEl.textContent = text;
  const atMarker = marker.style.display === 'block';
  letGoEl.style.left = `${atMarker ? pathAim.x : app.canvas.clientWidth / 2}px`;
  letGoEl.style.top = `${atMarker ? pathAim.y + MARKER_HALF[1] + 14 : app.canvas.clientHeight / 2}px`;
}

// ---- Camera, every frame ------------------------------------------------------------------------

const p3 = [0, 0, 0],
  q4 = [0, 0, 0, 1];
const drawnQ = new Quaternion(),
  at = new Vector3(),
  look = new Vector3(),
  chaseOffset = new Vector3(),
  nose = new Vector3(),
  smoothOffset = new Vector3();
let smoothReady = false;
/** Game time drawn by the last frame, s (the chase camera's smoothing is per second of game time, not per frame). */
let lastFrame = 0;
/** The chase camera's distance from the drawn aircraft now, m (tests; 0 in the other views). */
let chaseDistance = 0;
/** Time constant of the chase camera's swing round behind the aircraft, s. */
const CHASE_LAG = 0.25;
/**
 * How much farther the chase camera sits on a screen narrower than 1.2 (a phone held upright: its
 * narrow view was half filled by the wings): the offset and the look point times 1.2 / aspect, so
 * the aircraft keeps its place in the frame and spans about a third of its width.
 */
function chaseScale(): number {
  const aspect = app.canvas.clientWidth / Math.max(1, app.canvas.clientHeight);
  return Math.max(1, 1.2 / Math.max(0.3, aspect));
}
/** The chase camera's offset now, m (behind, above): CHASE_OFFSET times `chaseScale`. */
function chaseOffsetNow(): [number, number] {
  const k = chaseScale();
  return [k * CHASE_OFFSET[0], k * CHASE_OFFSET[1]];
}
/** The camera's field of view, degrees: `base`, widened by up to `fast` more between `from` and `to` m/s (speed shows). */
const FOV = Object.freeze({ base: 64, fast: 10, from: 110, to: 170 });

function frame(alpha = 1): void {
  const world = shell.world;
  // Everything here is what the frame shows: the camera, the labels and tips over the scene, the
  // HUD. The frame pacer skips drawing while the GPU is behind (often several frames in a row on a
  // software GPU); HTML labels placed for a frame the canvas never shows would sit 100 px and more
  // from their ring. So a frame that will not be drawn changes nothing but the banner and the tip's
  // words (a ring's pass or miss, and what the next ring asks, are said at once).
  // Paused by the pilot (P, the toolbar's button): the scene dims and says so. A wait for the pilot
  // (`holding`) is said by the tip instead, over the ring it is about. The end card, once up, wins:
  // it says what to do next, and the pause's dimming and words over it would hide that.
  pauseOverlay.update(shell.paused && !holding && shownCard === '', touchFirst);
  showSlowMotion();
  if (!app.pacer.mayDraw()) {
    updateBanner(world.time);
    updateGoal();
    // The ring label is placed on drawn frames only: once its ring is passed or missed (the banner
    // and the goal already say so) it goes at once, not after the next drawn frame.
    if (ringAim.index !== nextRing(rings) && ringPointer.style.display !== 'none') {
      ringPointer.style.display = 'none';
      ringAim.index = nextRing(rings);
      ringAim.inView = false;
      ringAim.text = '';
    }
    // The readouts too: every figure over and beside the scene says the same moment (the readout
    // kept every 6th drawn frame could say "rings 0/10" under the banner's "Ring 1 ✓").
    updateHud(crashReadings ?? instruments(world));
    // The warning too (it sits in a fixed place, nothing to project), so a loaded machine that draws
    // no frame between "PULL UP" and the ground still shows it.
    showWarning(world.time);
    showTip();
    showThrottleNote();
    placeMessages();
    return;
  }
  if (!renderer.drawnPosition(handles.body, p3) || !renderer.drawnOrientation(handles.body, q4)) return;
  at.set(p3[0]!, p3[1]!, p3[2]!);
  drawnQ.set(q4[0]!, q4[1]!, q4[2]!, q4[3]!);
  if (state.phase === 'crashed' && !Number.isNaN(crashedAt)) {
    // After a crash: a slow circle round the crash point, well above the ground.
    // It starts closer and draws back as the smoke rises; the view shakes for a moment at first;
    // the crash sits low in the view, under the end card, with the smoke column over it.
    const wall = performance.now();
    const u = (wall - crashedAt) / 1000,
      a = crashHeading + Math.PI + 0.12 * u,
      far = 170 - 60 * Math.exp(-u / 1.5);
    const centre = crash.centre;
    const cx = centre.x + far * Math.cos(a),
      cz = centre.z + far * Math.sin(a);
    chaseDistance = 0;
    const jolt = crash.shake(wall);
    app.camera.position.set(
      cx + jolt * Math.sin(wall * 0.09),
      Math.max(terrainHeight(handles.terrain, cx, cz) + 60, centre.y + 70) + jolt * Math.sin(wall * 0.13),
      cz,
    );
    app.camera.up.set(0, 1, 0);
    look.copy(centre).y += 45;
    app.camera.lookAt(look);
  } else if (state.camera === 'chase') {
    // Behind and above the aircraft in its own frame. The offset from the aircraft (not the eye's
    // place in the world) swings round smoothly and keeps its length, so in a turn the camera stays
    // at the same distance behind instead of trailing off (a lerp of the world position lags by
    // speed x frame time, more the slower the frames come).
    // The offsets are along the aircraft's nose and the world's up, not the aircraft's up: a bank
    // does not swing the camera sideways (with the aircraft's up, the look point would swing to the
    // side of the bank at once while the camera lags, so the scene and the path marker would first
    // slide the wrong way and a turn show late).
    // The nose's pitch, but the flight path's heading: as a bank starts, the rudder swings the nose
    // into the turn before the path turns (about 3 degrees in 0.4 s), and a camera that followed the
    // nose would slide the scene and the path marker the wrong way first.
    const [back, up] = chaseOffsetNow();
    nose.set(1, 0, 0).applyQuaternion(drawnQ);
    const V = world.components.Velocity,
      e = handles.body;
    const level = Math.hypot(nose.x, nose.z),
      track = Math.hypot(V.x[e]!, V.z[e]!);
    if (track > 1 && level > 1e-6) {
      nose.x = (level * V.x[e]!) / track;
      nose.z = (level * V.z[e]!) / track;
    }
    chaseOffset.copy(nose).multiplyScalar(back).y += up;
    // Its length is the offset's whatever the pitch (the sum of the two is not).
    chaseOffset.setLength(Math.hypot(back, up));
    // Smoothed over the game time drawn (the interpolated state's), not the clock's: the aircraft
    // moves by game time, so on uneven frames a clock-timed lag would swing the camera, and the path
    // marker with it, by a different share each frame (a jitter in a held bank).
    const t = world.time - world.dt * (1 - alpha);
    const dt = Math.min(0.2, Math.max(0, t - lastFrame));
    lastFrame = t;
    if (!smoothReady) {
      smoothOffset.copy(chaseOffset);
      smoothReady = true;
    }
    smoothOffset.lerp(chaseOffset, 1 - Math.exp(-dt / CHASE_LAG)).setLength(chaseOffset.length());
    app.camera.position.copy(at).add(smoothOffset);
    chaseDistance = smoothOffset.length();
    app.camera.up.set(0, 1, 0);
    const k = chaseScale();
    look
      .copy(nose)
      .multiplyScalar(k * CHASE_LOOK[0])
      .add(at).y += k * CHASE_LOOK[1];
    app.camera.lookAt(look);
  } else {
    chaseDistance = 0;
    // From the canopy, over the nose.
    app.camera.position.set(11.5, 2.1, 0).applyQuaternion(drawnQ).add(at);
    app.camera.up.set(0, 1, 0).applyQuaternion(drawnQ);
    look.set(100, 0.8, 0).applyQuaternion(drawnQ).add(at);
    app.camera.lookAt(look);
  }
  app.camera.updateMatrixWorld();
  scenery.update(app.camera.position, at, app.camera);
  paintRings(world.time);
  drawGuide(at);
  markPath();
  cueLetGo();
  showWarning(world.time);
  measurePlane();
  pointToNextRing();
  findRingBehindPlane();
  showTip();
  engine.set(state.phase === 'crashed' ? 0 : 0.25 + 0.75 * state.throttle);
  const i = crashReadings ?? instruments(world);
  drawCockpit(state.camera === 'cockpit' && state.phase !== 'crashed', i);
  // Wider with speed, eased towards it.
  const fov = FOV.base + FOV.fast * Math.max(0, Math.min(1, (i.speed - FOV.from) / (FOV.to - FOV.from)));
  if (Math.abs(app.camera.fov - fov) > 0.05) {
    app.camera.fov += 0.1 * (fov - app.camera.fov);
    app.camera.updateProjectionMatrix();
  }
  drawCrash();
  updateBanner(world.time);
  updateGoal();
  updateHud(i);
  showThrottleNote();
  placeMessages();
}

/** Instrument readings of the aircraft now: speed, altitude, attitude, heading, the wing's angle of attack (m/s, m, degrees). */
function instruments(world: PhysicsWorld): {
  speed: number;
  altitude: number;
  agl: number;
  climb: number;
  pitch: number;
  roll: number;
  heading: number;
  aoa: number;
} {
  const s: FlightState = flightState(world, handles.body);
  const c = world.components,
    e = handles.body;
  const deg = 180 / Math.PI;
  return {
    speed: s.speed,
    altitude: c.Position.y[e]!,
    agl: c.Position.y[e]! - Math.max(SEA_LEVEL, terrainHeight(handles.terrain, c.Position.x[e]!, c.Position.z[e]!)),
    climb: c.Velocity.y[e]!,
    pitch: s.pitch * deg,
    roll: s.bank * deg,
    heading: s.heading * deg,
    aoa: s.alpha * deg,
  };
}

// Touch: a stick for bank and climb, buttons for speed, rudder and camera.
createStick({
  label: 'stick: bank and climb',
  onChange: (x, y) => {
    // Progressive: a small dead zone, gentle near the centre, full at the rim (./assist.ts stickResponse).
    const r = stickResponse(x, y);
    setStickInput(r);
    // Any touch goes on from a wait, even one inside the dead zone.
    if (x !== 0 || y !== 0) pilotGoes();
  },
});
createButtonBar(
  [
    { label: 'Faster', name: 'faster', key: '+' },
    { label: 'Slower', name: 'slower', key: '-' },
    { label: '◀ Rudder', name: 'rudder left', key: 'q' },
    { label: 'Rudder ▶', name: 'rudder right', key: 'e' },
    { label: 'Camera', name: 'camera: chase / cockpit', key: 'c' },
  ],
  { label: 'speed, rudder and camera' },
).element.style.maxWidth = '240px';

const panel = createPanel(
  params,
  [
    { type: 'checkbox', key: 'assist', label: 'flight assist' },
    { type: 'checkbox', key: 'pilotPitch', label: "pilot's pitch (↓ pulls up)" },
    { type: 'slider', key: 'authority', label: 'control authority (°)', min: 5, max: 30, step: 1 },
    { type: 'slider', key: 'rings', min: 1, max: 30, step: 1, onChange: () => shell.reset() },
    { type: 'slider', key: 'seed', label: 'course', min: 1, max: LAST_SEED, step: 1, onChange: () => shell.reset() },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Flight simulator' },
);

shell.expose({
  /** The pointer to the next ring: its index (-1: none left), whether it is in view, its text and box (px). */
  ringPointer: () => ({ ...ringAim }),
  /** The flight-path marker: visible, inside the next ring, its offset from the ring's centre (m), its place (px), the game time of the drawn frame that placed it (s). */
  pathMarker: () => ({ ...pathAim }),
  /** Trees, houses and cloud puffs drawn now, the cloud layers' lowest and highest base (m), and the scenery's detail (./scenery.ts SCENERY_DETAIL). */
  scenery: () => ({ ...scenery.counts(), detail: sceneryDetail }),
  /** The chase camera's distance from the drawn aircraft now, m (0 in the cockpit view or after a crash), and its offset now behind (-) and above, m. */
  chaseDistance: () => chaseDistance,
  chaseOffset: (): [number, number] => chaseOffsetNow(),
  /** The cockpit view's panel: shown, its top (CSS px in the stage), the gauges drawn last, the attitude indicator's box (px). */
  cockpit: () => {
    const box = horizon.canvas.getBoundingClientRect(),
      stage = layout.stage.getBoundingClientRect();
    return {
      visible: cockpit.canvas.style.display !== 'none',
      panelTop: cockpit.panelTop(),
      gauges: cockpit.gauges(),
      attitude: [box.left - stage.left, box.top - stage.top, box.width, box.height],
    };
  },
  /** The keyboard's ramped inputs now, each in [-1, 1] (./assist.ts rampKey). */
  keyInput: () => ({ ...keyInput }),
  /** The attitude indicator: shown (cockpit view) and the pitch and roll it drew last, degrees. */
  attitude: () => ({ ...shownAttitude }),
  /** The guide's beads drawn now, each centre (m, world). */
  guideBeads,
  /** Each ring's drawn opacity now (0: not drawn; a ring passed or missed fades out and goes). */
  ringOpacity: () => ringMeshes.map((m) => (m.visible ? (m.material as MeshBasicMaterial).opacity : 0)),
  /** The course: each ring's centre (m), normal and status. */
  rings: () => rings.map((r) => ({ ...r })),
  /** The lesson tip over the scene now ('' when none shows). */
  tip: () => tipText,
  /** Every tip this page can show (./course.ts lessonTipText for rings 1 to 4, ./coach.ts courseTipText for rings 5 and 10 of 10, each of RING_WAYS), for its reader: the worst case's fit is tested. */
  tipTexts: () => {
    const reader = { touch: touchFirst, compact, pilotPitch: params.pilotPitch };
    // The coach's (./coach.ts) for ring 5 of 10 and the last (the longest names), each way and on course.
    const coach = [LESSON_RINGS, 9].flatMap((i) => [
      ...RING_WAYS.map((w) => courseTipText(i, 10, w, reader, Infinity)),
      courseTipText(i, 10, RING_WAYS[0]!, reader, 0),
    ]);
    return [...[0, 1, 2, 3].flatMap((i) => RING_WAYS.map((w) => lessonTipText(i, w, reader))), ...coach];
  },
  /** Game time at which the tip now shown goes, s (Infinity: it stays while its ring is next). */
  tipUntil: () => tipGoneAt,
  /** How long the next ring has fallen behind without a break, s (at LEFT_BEHIND_TIME it is missed: ./course.ts leaveBehind). */
  behindFor: () => awayFor,
  /** The messages over the scene as last placed: in the low lane or not, each shown one's name (data-hud) and box (px: left, top, width, height), and the warning's box while it is on (else null). */
  messages: () => ({
    low: messageLayout.low,
    boxes: messageLayout.boxes.map((m) => ({ hud: m.hud, box: [...m.box] })),
    warning: messageLayout.warning ? [...messageLayout.warning] : null,
  }),
  /** The engine's note now ('' when it does not show). */
  throttleNote: () => (throttleNote.style.display === 'none' ? '' : (throttleNote.textContent ?? '')),
  /** The drawn aircraft's opacity (1: it stays solid), its box on the screen (px) and whether the next ring is behind it there. */
  planeFade: () => ({ opacity: planeMaterial.transparent ? planeMaterial.opacity : 1, box: [...planeBox], behind: ringBehindPlane }),
  /** The banner's text now ('' when none shows) and the warning. */
  banner: () => ({ text: banner.style.display === 'none' ? '' : (banner.textContent ?? ''), warning: state.warning }),
  params,
  panel,
  state,
  /** The aircraft entity. */
  aircraftBody: () => handles.body,
  /** Sets the stick as the on-screen one does: deflection x right, y up, each clamped to [-1, 1], through ./assist.ts stickResponse. */
  setStick: (x: number, y: number): void => {
    setStickInput(stickResponse(clamp1(x), clamp1(y)));
  },
  /**
   * Starts recording every step's [game time s, bank degrees (right +), keys' bank input in [-1, 1],
   * stick's bank input in [-1, 1]] (from the next step on, dropping any earlier record) and returns
   * the record, which grows while the flight goes on; `traceBank(false)` stops it (and returns null).
   */
  traceBank: (on: boolean): [number, number, number, number][] | null => {
    bankTrace = on ? [] : null;
    return bankTrace;
  },
  /** Whether the "let go now" cue shows (./let-go.ts letGoCue). */
  letGo: () => letGoShown,
  /** The pilot's stick input now (after the response curve), x right, y up. */
  stickInput: () => ({ ...stickInput }),
  /** Speed, altitude, attitude, heading and the wing's angle of attack now (m/s, m, degrees). */
  instruments: () => instruments(shell.world),
});
