/**
 * Flight simulator: the book's aircraft (Ramtal and Dobre ch. 16; the `aircraft` scene) flown with
 * the keyboard over seeded hills. Lift and drag come from each surface's angle of attack (wing
 * halves with ailerons, tailplane with the elevator, fin with the rudder), with a stall past 20
 * degrees; the controls act where the surfaces are, so they turn the aircraft through Euler's
 * equations; the damping of every rotation comes from the surfaces meeting their own motion. Fly
 * through the rings for points; do not fly into the hills.
 * Keys: arrows or W/S/A/D: pitch and roll; Q / E: rudder; Shift / Ctrl (or + / -): throttle;
 * C: camera (chase / cockpit); P pause, N step, R reset.
 * Touch: a virtual stick under the scene (drag up to push the nose down, sideways to roll), hold
 * buttons for throttle and rudder, a camera button. Sound: the engine's hum follows the throttle.
 * URL: ?seed=n, ?rings=n (1..30).
 */

import { createButtonBar, createPanel, createStick, getSound, numberParam, pageLayout, seedParam } from '@bitphysics/game-kit';
import { startThreeGame } from '@bitphysics/game-kit/three';
import { createPhysicsWorld, type PhysicsWorld, Rng, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';
import { AIRCRAFT, AIRCRAFT_TRIM_SPEED, type AircraftHandles, aircraft, aircraftLevelDrag, terrainHeight } from '@bitphysics/projects';
import {
  BoxGeometry,
  type BufferAttribute,
  type BufferGeometry,
  Color,
  ConeGeometry,
  CylinderGeometry,
  DoubleSide,
  Float32BufferAttribute,
  Fog,
  HemisphereLight,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  PlaneGeometry,
  Quaternion,
  TorusGeometry,
  Vector3,
} from 'three';
import { mergeGeometries } from 'three/examples/jsm/utils/BufferGeometryUtils.js';

const params = {
  seed: seedParam(),
  rings: numberParam('rings', { default: 10, min: 1, max: 30, integer: true }),
  /** Full deflection of each control, degrees. */
  authority: 15,
  reset: () => shell.reset(),
};

/** Controls and game state beside the physics. */
const state = {
  throttle: 0,
  elevator: 0,
  aileron: 0,
  rudder: 0,
  score: 0,
  crashed: false,
  camera: 'chase' as 'chase' | 'cockpit',
  stalled: false,
};
let handles: AircraftHandles;
/** Rings: centre (x, y, z) and whether passed. */
let rings: { x: number; y: number; z: number; passed: boolean }[] = [];

function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(aircraft.worldOptions());
  handles = aircraft.build(world, { seed: params.seed, altitude: 900 });
  state.throttle = aircraftLevelDrag(AIRCRAFT_TRIM_SPEED) / AIRCRAFT.maxThrust;
  Object.assign(state, { elevator: 0, aileron: 0, rudder: 0, score: 0, crashed: false, stalled: false });
  const rng = new Rng(params.seed + 7);
  rings = [];
  let x = 0,
    z = 0;
  for (let i = 0; i < params.rings; i++) {
    x += rng.range(1500, 2500);
    z += rng.range(-600, 600);
    // Near the cruise altitude, but always 200 m clear of the hills below.
    rings.push({ x, y: Math.max(terrainHeight(handles.terrain, x, z) + 200, 900 + rng.range(-250, 250)), z, passed: false });
  }
  return world;
}

const held = new Set<string>();
/** The on-screen stick's deflection (x right, y up, in [-1, 1]). */
const stickInput = { x: 0, y: 0 };
addEventListener('keydown', (e) => {
  held.add(e.key.toLowerCase());
  if (e.key === 'Shift' || e.key === 'Control' || e.key.startsWith('Arrow')) e.preventDefault();
});
addEventListener('keyup', (e) => {
  held.delete(e.key.toLowerCase());
});
addEventListener('blur', () => held.clear());

/** Moves a control towards `target` at `rate` per second. */
function approach(value: number, target: number, rate: number, dt: number): number {
  return value + Math.max(-rate * dt, Math.min(rate * dt, target - value));
}

const q = new Quaternion(),
  f = new Vector3(),
  u = new Vector3(),
  r = new Vector3(),
  v = new Vector3();

/** The body's axes in world coordinates: forward f, up u, right r. */
function axes(world: PhysicsWorld): void {
  const O = world.components.Orientation,
    e = handles.body;
  q.set(O.x[e]!, O.y[e]!, O.z[e]!, O.w[e]!);
  f.set(1, 0, 0).applyQuaternion(q);
  u.set(0, 1, 0).applyQuaternion(q);
  r.set(0, 0, 1).applyQuaternion(q);
}

/** Aileron the rudder adds, as a fraction of full, to bank into the turn it asks for. */
const RUDDER_ROLL = 0.33;

function stepWorld(world: PhysicsWorld): void {
  if (state.crashed) return;
  const dt = world.dt;
  const clamp = (x: number): number => Math.max(-1, Math.min(1, x));
  // Keys and the on-screen stick add up (stick up = push = nose down, as a real stick).
  const pitch = clamp((held.has('arrowdown') || held.has('s') ? 1 : 0) - (held.has('arrowup') || held.has('w') ? 1 : 0) - stickInput.y);
  const yaw = (held.has('e') ? 1 : 0) - (held.has('q') ? 1 : 0);
  // The rudder alone only yaws the nose into a sideslip of about 6 degrees (the fin's own lift
  // balances it) and turns the flight path hardly at all, which reads as broken. As a
  // turn-coordinator does, held rudder also asks for a third of full aileron the same way, so the
  // aircraft banks into the turn.
  const roll = clamp(
    (held.has('arrowright') || held.has('d') ? 1 : 0) - (held.has('arrowleft') || held.has('a') ? 1 : 0) + stickInput.x + RUDDER_ROLL * yaw,
  );
  // Stick inputs spring back to neutral; the throttle stays where it is put.
  state.elevator = approach(state.elevator, pitch, 3, dt);
  state.aileron = approach(state.aileron, roll, 3, dt);
  state.rudder = approach(state.rudder, yaw, 3, dt);
  if (held.has('shift') || held.has('+') || held.has('=')) state.throttle = Math.min(1, state.throttle + 0.4 * dt);
  if (held.has('control') || held.has('-')) state.throttle = Math.max(0, state.throttle - 0.4 * dt);
  const full = (params.authority * Math.PI) / 180;
  const s = handles.surfaces;
  // Pull (down arrow) = elevator trailing edge up = less tail lift = nose up.
  setControlDeflection(world, s.tail, -state.elevator * full);
  // Roll right: the left aileron down (more lift), the right one up.
  setControlDeflection(world, s.leftWing, state.aileron * full);
  setControlDeflection(world, s.rightWing, -state.aileron * full);
  // Right rudder: the fin's force to the left at the tail swings the nose right.
  setControlDeflection(world, s.fin, -state.rudder * full);
  setBodyThrust(world, handles.body, [state.throttle * AIRCRAFT.maxThrust, 0, 0]);
  const P = world.components.Position,
    e = handles.body;
  const x0 = P.x[e]!;
  step(world);
  // Rings: passed when the aircraft crosses a ring's plane (x = const) within 45 m of its centre.
  for (const ring of rings) {
    if (ring.passed || !(x0 < ring.x && P.x[e]! >= ring.x)) continue;
    if (Math.hypot(P.y[e]! - ring.y, P.z[e]! - ring.z) < 45) {
      ring.passed = true;
      state.score++;
      sound.chime(state.score === rings.length ? 1320 : 880);
      ringMeshes[rings.indexOf(ring)]!.material = passedMaterial;
    }
  }
  if (P.y[e]! < terrainHeight(handles.terrain, P.x[e]!, P.z[e]!) + 2) {
    state.crashed = true;
    sound.explosion(1);
  }
}

const sound = getSound();
const engine = sound.engine('propeller');

const game = await startThreeGame({
  title: 'Flight simulator',
  createWorld,
  step: stepWorld,
  bodies: () => 1,
  controls: [
    { keys: '↑ ↓ / W S', action: 'pitch (↓ pulls up)', touch: 'stick ↑ ↓' },
    { keys: '← → / A D', action: 'roll', touch: 'stick ← →' },
    { keys: 'Q / E', action: 'rudder', touch: 'Rudder' },
    { keys: 'Shift / Ctrl', action: 'throttle up / down', touch: 'Throttle + / −' },
    { keys: 'C', action: 'camera: chase / cockpit', touch: 'Camera' },
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
  app: { background: 0x9cc8f0, shadows: false, controls: false, fov: 60 },
  renderer: {
    unitsPerMeter: 1,
    boundary: 'none',
    shadows: false,
    lights: { direction: [0.4, 1, 0.3], intensity: 2.2, hemisphereIntensity: 0.6, ambientIntensity: 0.2, shadows: false },
  },
  view: null,
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;
app.camera.near = 1;
app.camera.far = 30_000;
app.camera.updateProjectionMatrix();
app.scene.fog = new Fog(0x9cc8f0, 4000, 16_000);
app.scene.add(new HemisphereLight(0xcfe6ff, 0x4a5a3a, 0.4));

// ---- The aircraft's looks: fuselage, wings, tailplane and fin in the body frame (x forward, y up) -----

function aircraftGeometry(): BufferGeometry {
  const parts: BufferGeometry[] = [];
  const fuselage = new CylinderGeometry(1.3, 1.1, 24, 16);
  fuselage.rotateZ(-Math.PI / 2);
  fuselage.translate(-1, 0, 0);
  parts.push(fuselage);
  const nose = new ConeGeometry(1.3, 4, 16);
  nose.rotateZ(-Math.PI / 2);
  nose.translate(13, 0, 0);
  parts.push(nose);
  const wing = new BoxGeometry(4, 0.35, 30);
  wing.translate(0.5, -0.4, 0);
  parts.push(wing);
  const tail = new BoxGeometry(2.6, 0.25, 10);
  tail.translate(-12, 0.3, 0);
  parts.push(tail);
  const fin = new BoxGeometry(3, 5, 0.3);
  fin.translate(-12, 2.8, 0);
  parts.push(fin);
  return mergeGeometries(parts.map((p) => p.toNonIndexed()))!;
}
const planeMaterial = new MeshStandardMaterial({ color: 0xe8ecf2, roughness: 0.5, metalness: 0.2 });
const planeGeometry = aircraftGeometry();
function dress(): void {
  renderer.setShape(handles.body, { geometry: planeGeometry, material: planeMaterial, scale: 1 });
}
dress();
shell.onWorldChange(() => {
  dress();
  terrainCentre = null;
});

// ---- Terrain: a 24 km grid that follows the aircraft, heights from the scene's terrain function --------

const SIZE = 24_000,
  SEGMENTS = 160;
const terrainGeometry = new PlaneGeometry(SIZE, SIZE, SEGMENTS, SEGMENTS);
terrainGeometry.rotateX(-Math.PI / 2);
terrainGeometry.setAttribute('color', new Float32BufferAttribute(new Float32Array(terrainGeometry.attributes.position!.count * 3), 3));
const base = Float32Array.from(terrainGeometry.attributes.position!.array as Float32Array);
const terrain = new Mesh(terrainGeometry, new MeshStandardMaterial({ vertexColors: true, roughness: 1, flatShading: true }));
app.scene.add(terrain);
const sea = new Mesh(new PlaneGeometry(SIZE * 2, SIZE * 2), new MeshStandardMaterial({ color: 0x2d6e9e, roughness: 0.4 }));
sea.rotateX(-Math.PI / 2);
sea.position.y = 60;
app.scene.add(sea);
let terrainCentre: [number, number] | null = null;
const low = new Color(0x4f8a3c),
  mid = new Color(0x8a7a52),
  high = new Color(0xf2f4f6),
  tmpColor = new Color();

/** Rebuilds the grid's heights and colours around (cx, cz), snapped to whole cells. */
function rebuildTerrain(cx: number, cz: number): void {
  const cell = SIZE / SEGMENTS;
  const sx = Math.round(cx / cell) * cell,
    sz = Math.round(cz / cell) * cell;
  terrainCentre = [sx, sz];
  const pos = terrainGeometry.attributes.position as BufferAttribute,
    col = terrainGeometry.attributes.color as BufferAttribute;
  for (let i = 0; i < pos.count; i++) {
    const x = base[3 * i]! + sx,
      z = base[3 * i + 2]! + sz;
    const h = terrainHeight(handles.terrain, x, z);
    pos.setXYZ(i, x, h, z);
    if (h < 300) tmpColor.copy(low).lerp(mid, h / 300);
    else tmpColor.copy(mid).lerp(high, Math.min(1, (h - 300) / 300));
    col.setXYZ(i, tmpColor.r, tmpColor.g, tmpColor.b);
  }
  pos.needsUpdate = true;
  col.needsUpdate = true;
  terrainGeometry.computeVertexNormals();
  terrainGeometry.computeBoundingSphere();
}

// ---- Rings ----------------------------------------------------------------------------------------

const ringGeometry = new TorusGeometry(45, 3, 10, 40);
ringGeometry.rotateY(Math.PI / 2);
const ringMaterial = new MeshBasicMaterial({ color: 0xffb020, side: DoubleSide });
const passedMaterial = new MeshBasicMaterial({ color: 0x50e070, transparent: true, opacity: 0.35 });
let ringMeshes: Mesh[] = [];
function placeRings(): void {
  for (const m of ringMeshes) app.scene.remove(m);
  ringMeshes = rings.map((ring) => {
    const m = new Mesh(ringGeometry, ringMaterial);
    m.position.set(ring.x, ring.y, ring.z);
    app.scene.add(m);
    return m;
  });
}
placeRings();
shell.onWorldChange(() => placeRings());

// ---- Camera and instruments, every frame ----------------------------------------------------------

const p3 = [0, 0, 0],
  q4 = [0, 0, 0, 1];
const drawnQ = new Quaternion(),
  at = new Vector3(),
  eye = new Vector3(),
  look = new Vector3(),
  smoothEye = new Vector3();
let smoothReady = false;

const panelEl = document.createElement('div');
panelEl.className = 'bp-hud';
panelEl.dataset.hud = 'instruments';
/** On small screens the instruments are a short block in the status row above the scene (the side column is a closed drawer there). */
const compact = pageLayout().compact();
if (compact) {
  panelEl.style.cssText = 'padding: 4px 10px; white-space: pre; font-size: 12px';
  pageLayout().status.append(panelEl);
} else {
  panelEl.style.cssText = 'top: auto; bottom: 10px; left: auto; right: 10px; min-width: 250px; white-space: pre';
  document.body.append(panelEl);
}
let readoutFrame = 0;

// The attitude indicator (artificial horizon), drawn in the cockpit view at the top of the scene (clear of the touch stick):
// sky over ground split by the horizon, turned by the roll and moved by the pitch (PITCH_PX a
// degree), a pitch ladder every 10 degrees, the bank scale, and the fixed aircraft symbol.
const HORIZON_SIZE = 150;
const PITCH_PX = 2.2;
const horizon = document.createElement('canvas');
horizon.width = HORIZON_SIZE * devicePixelRatio;
horizon.height = HORIZON_SIZE * devicePixelRatio;
horizon.dataset.sceneOverlay = '';
horizon.setAttribute('aria-label', 'attitude indicator');
horizon.style.cssText = `position: absolute; left: 50%; top: 8px; width: ${HORIZON_SIZE}px; height: ${HORIZON_SIZE}px; transform: translateX(-50%); pointer-events: none; z-index: 5; display: none`;
pageLayout().stage.append(horizon);
/** What the indicator showed last: pitch and roll, degrees (tests read them). */
const shownAttitude = { pitch: 0, roll: 0, visible: false };

function drawHorizon(pitch: number, roll: number): void {
  const g = horizon.getContext('2d');
  if (!g) return;
  const S = HORIZON_SIZE,
    c = S / 2;
  g.setTransform(devicePixelRatio, 0, 0, devicePixelRatio, 0, 0);
  g.clearRect(0, 0, S, S);
  g.save();
  g.beginPath();
  g.arc(c, c, c - 2, 0, 2 * Math.PI);
  g.clip();
  g.translate(c, c);
  g.rotate((-roll * Math.PI) / 180);
  const dy = pitch * PITCH_PX;
  g.fillStyle = '#3d8fd6';
  g.fillRect(-S, -2 * S + dy, 2 * S, 2 * S);
  g.fillStyle = '#7a5230';
  g.fillRect(-S, dy, 2 * S, 2 * S);
  g.strokeStyle = '#ffffff';
  g.lineWidth = 2;
  g.beginPath();
  g.moveTo(-S, dy);
  g.lineTo(S, dy);
  g.stroke();
  g.lineWidth = 1;
  g.font = '9px system-ui, sans-serif';
  g.fillStyle = '#ffffff';
  for (let p = -30; p <= 30; p += 10) {
    if (p === 0) continue;
    const y = dy - p * PITCH_PX,
      half = p % 20 === 0 ? 22 : 14;
    g.beginPath();
    g.moveTo(-half, y);
    g.lineTo(half, y);
    g.stroke();
    g.fillText(String(Math.abs(p)), half + 3, y + 3);
  }
  g.restore();
  // Bank marks at 0, 10, 20, 30, 60 degrees each side, and the bank pointer.
  g.strokeStyle = '#ffffff';
  g.lineWidth = 2;
  for (const b of [-60, -30, -20, -10, 0, 10, 20, 30, 60]) {
    const a = ((b - 90) * Math.PI) / 180,
      r1 = c - 4,
      r2 = c - (b % 30 === 0 ? 14 : 9);
    g.beginPath();
    g.moveTo(c + r1 * Math.cos(a), c + r1 * Math.sin(a));
    g.lineTo(c + r2 * Math.cos(a), c + r2 * Math.sin(a));
    g.stroke();
  }
  const pa = ((-roll - 90) * Math.PI) / 180;
  g.fillStyle = '#ffd166';
  g.beginPath();
  g.moveTo(c + (c - 16) * Math.cos(pa), c + (c - 16) * Math.sin(pa));
  g.lineTo(c + (c - 26) * Math.cos(pa + 0.09), c + (c - 26) * Math.sin(pa + 0.09));
  g.lineTo(c + (c - 26) * Math.cos(pa - 0.09), c + (c - 26) * Math.sin(pa - 0.09));
  g.fill();
  // The aircraft symbol: wings and a centre dot, fixed.
  g.strokeStyle = '#ffd166';
  g.lineWidth = 4;
  g.beginPath();
  g.moveTo(c - 42, c);
  g.lineTo(c - 14, c);
  g.lineTo(c - 8, c + 7);
  g.moveTo(c + 42, c);
  g.lineTo(c + 14, c);
  g.lineTo(c + 8, c + 7);
  g.stroke();
  g.fillStyle = '#ffd166';
  g.beginPath();
  g.arc(c, c, 3, 0, 2 * Math.PI);
  g.fill();
  g.strokeStyle = '#0b0f14';
  g.lineWidth = 3;
  g.beginPath();
  g.arc(c, c, c - 2, 0, 2 * Math.PI);
  g.stroke();
}

// ---- Guidance: where the next ring is ---------------------------------------------------------------

/**
 * A marker for the next ring (the first not yet passed, in the order they are laid out along x): a
 * label under it with its distance while it is in view, else an arrow at the edge of the scene
 * pointing the way to turn, so a player always knows where to fly (there was no guidance at all).
 */
const ringPointer = document.createElement('div');
ringPointer.dataset.sceneOverlay = '';
ringPointer.dataset.hud = 'ring-pointer';
ringPointer.style.cssText =
  'position: absolute; z-index: 4; pointer-events: none; transform: translate(-50%, -50%); padding: 2px 8px; border-radius: 10px;' +
  'background: rgba(10, 14, 22, 0.8); color: #ffcf5a; font: 700 14px system-ui, sans-serif; white-space: nowrap;';
pageLayout().stage.append(ringPointer);
const ringAt = new Vector3();
/** What the pointer shows (tests): the ring's index (-1: none left), whether it is in view, the text. */
const ringAim = { index: -1, inView: false, text: '' };
function pointToNextRing(): void {
  const i = rings.findIndex((r) => !r.passed);
  ringAim.index = i;
  ringPointer.style.display = i < 0 || state.crashed ? 'none' : 'block';
  if (i < 0 || state.crashed) return;
  const ring = rings[i]!;
  ringAt.set(ring.x, ring.y, ring.z);
  const d = ringAt.distanceTo(at);
  const w = app.canvas.clientWidth,
    h = app.canvas.clientHeight;
  ringAt.project(app.camera);
  const ahead = ringAt.z < 1;
  let x = ((ringAt.x + 1) / 2) * w,
    y = ((1 - ringAt.y) / 2) * h;
  ringAim.inView = ahead && x > 0 && x < w && y > 0 && y < h;
  const distance = d >= 1000 ? `${(d / 1000).toFixed(1)} km` : `${d.toFixed(0)} m`;
  if (ringAim.inView) {
    ringAim.text = `ring ${i + 1} · ${distance}`;
    y = Math.min(h - 14, y + 30);
  } else {
    // Behind the camera the projection is mirrored: point the other way.
    let dx = x - w / 2,
      dy = y - h / 2;
    if (!ahead) {
      dx = -dx;
      dy = -dy;
    }
    const k = Math.min((w / 2 - 60) / Math.max(1e-6, Math.abs(dx)), (h / 2 - 24) / Math.max(1e-6, Math.abs(dy)));
    x = w / 2 + dx * k;
    y = h / 2 + dy * k;
    const arrow = Math.abs(dx) * (h / 2) > Math.abs(dy) * (w / 2) ? (dx > 0 ? '▶' : '◀') : dy > 0 ? '▼' : '▲';
    ringAim.text = `${arrow} ring ${i + 1} · ${distance}`;
  }
  ringPointer.textContent = ringAim.text;
  ringPointer.style.left = `${x}px`;
  ringPointer.style.top = `${y}px`;
}

function frame(): void {
  const world = shell.world;
  if (!renderer.drawnPosition(handles.body, p3) || !renderer.drawnOrientation(handles.body, q4)) return;
  at.set(p3[0]!, p3[1]!, p3[2]!);
  drawnQ.set(q4[0]!, q4[1]!, q4[2]!, q4[3]!);
  if (!terrainCentre || Math.hypot(at.x - terrainCentre[0], at.z - terrainCentre[1]) > 2000) rebuildTerrain(at.x, at.z);
  sea.position.x = at.x;
  sea.position.z = at.z;
  if (state.camera === 'chase') {
    eye.set(-45, 12, 0).applyQuaternion(drawnQ).add(at);
    // Keep the chase camera level-ish: follow the heading, not all of the roll.
    if (!smoothReady) {
      smoothEye.copy(eye);
      smoothReady = true;
    }
    smoothEye.lerp(eye, 0.12);
    app.camera.position.copy(smoothEye);
    app.camera.up.set(0, 1, 0);
    look.set(30, 0, 0).applyQuaternion(drawnQ).add(at);
    app.camera.lookAt(look);
  } else {
    app.camera.position.set(14, 1.8, 0).applyQuaternion(drawnQ).add(at);
    app.camera.up.set(0, 1, 0).applyQuaternion(drawnQ);
    look.set(100, 0, 0).applyQuaternion(drawnQ).add(at);
    app.camera.lookAt(look);
  }
  pointToNextRing();
  engine.set(state.crashed ? 0 : state.throttle);
  const cockpit = state.camera === 'cockpit';
  horizon.style.display = cockpit ? 'block' : 'none';
  shownAttitude.visible = cockpit;
  if (cockpit) {
    const i = instruments(world);
    shownAttitude.pitch = i.pitch;
    shownAttitude.roll = i.roll;
    drawHorizon(i.pitch, i.roll);
  }
  if (readoutFrame++ % 6 === 0) updateInstruments(world);
}

/** Instrument readings of the aircraft now: speed, altitude, attitude, heading, angle of attack. */
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
  axes(world);
  const c = world.components,
    e = handles.body;
  v.set(c.Velocity.x[e]!, c.Velocity.y[e]!, c.Velocity.z[e]!);
  const deg = 180 / Math.PI;
  return {
    speed: v.length(),
    altitude: c.Position.y[e]!,
    agl: c.Position.y[e]! - terrainHeight(handles.terrain, c.Position.x[e]!, c.Position.z[e]!),
    climb: v.y,
    pitch: Math.asin(Math.max(-1, Math.min(1, f.y))) * deg,
    roll: Math.atan2(-r.y, u.y) * deg,
    heading: (Math.atan2(f.z, f.x) * deg + 360) % 360,
    aoa: Math.atan2(-v.dot(u), v.dot(f)) * deg,
  };
}

function updateInstruments(world: PhysicsWorld): void {
  const i = instruments(world);
  state.stalled = Math.abs(i.aoa) > (AIRCRAFT.stallAngle * 180) / Math.PI;
  const end = state.crashed ? '   CRASHED (reset to retry)' : state.score === rings.length ? '   ALL RINGS!' : '';
  if (compact) {
    panelEl.textContent = [
      `${i.speed.toFixed(0)} m/s  alt ${i.altitude.toFixed(0)} m (ground ${i.agl.toFixed(0)} m)  climb ${i.climb.toFixed(1)}`,
      `throttle ${(state.throttle * 100).toFixed(0)}%  AoA ${i.aoa.toFixed(1)}°${state.stalled ? ' STALL!' : ''}  rings ${state.score}/${rings.length}${end}`,
    ].join('\n');
    return;
  }
  panelEl.textContent = [
    `airspeed  ${i.speed.toFixed(0).padStart(4)} m/s  ${(i.speed * 1.944).toFixed(0).padStart(4)} kt`,
    `altitude  ${i.altitude.toFixed(0).padStart(5)} m   above ground ${i.agl.toFixed(0)} m`,
    `climb     ${i.climb.toFixed(1).padStart(6)} m/s`,
    `pitch ${i.pitch.toFixed(1).padStart(6)}°  roll ${i.roll.toFixed(1).padStart(6)}°`,
    `heading   ${i.heading.toFixed(0).padStart(4)}°`,
    `AoA   ${i.aoa.toFixed(1).padStart(6)}°  ${state.stalled ? 'STALL!' : ''}`,
    `throttle  ${(state.throttle * 100).toFixed(0).padStart(4)}%`,
    `rings     ${state.score}/${rings.length}${end}`,
  ].join('\n');
}

// Touch: a stick for pitch and roll, hold buttons for throttle and rudder, a camera switch.
createStick({
  label: 'stick: pitch and roll',
  onChange: (x, y) => {
    stickInput.x = x;
    stickInput.y = y;
  },
});
createButtonBar(
  [
    { label: 'Throttle +', name: 'throttle up', key: '+' },
    { label: 'Throttle −', name: 'throttle down', key: '-' },
    { label: '◀ Rudder', name: 'rudder left', key: 'q' },
    { label: 'Rudder ▶', name: 'rudder right', key: 'e' },
    { label: 'Camera', name: 'camera: chase / cockpit', key: 'c' },
  ],
  { label: 'throttle, rudder and camera' },
).element.style.maxWidth = '240px';

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'authority', label: 'control authority (°)', min: 5, max: 30, step: 1 },
    { type: 'slider', key: 'rings', min: 1, max: 30, step: 1, onChange: () => shell.reset() },
    { type: 'slider', key: 'seed', min: 0, max: 1000, step: 1, onChange: () => shell.reset() },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Flight simulator' },
);

shell.expose({
  /** The pointer to the next ring: its index (-1: none left), whether it is in view, and its text. */
  ringPointer: () => ({ ...ringAim }),
  /** The attitude indicator: shown (cockpit view) and the pitch and roll it drew last, degrees. */
  attitude: () => ({ ...shownAttitude }),
  params,
  panel,
  state,
  /** The aircraft entity. */
  aircraftBody: () => handles.body,
  /** Speed, altitude, attitude, heading and angle of attack now (m/s, m, degrees). */
  instruments: () => instruments(shell.world),
});
