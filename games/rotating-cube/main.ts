/**
 * Rotating cube: rigid-body rotation in 3D. By default (mode 'room') a 1 m cube falls tumbling into a
 * room and collides with the floor and the walls (a box collider and 3D box contacts): it lands,
 * tumbles, slides and bounces off them; torques from the keys (a couple of forces from
 * `applyForceAtPoint` in a forces-stage system) and impulses from clicks (`applyImpulseAtPoint` at
 * the point of the face clicked, along the view direction) push it about, and Space makes it jump.
 * Arrows show its angular momentum L (`spinAngularMomentum`, yellow) and angular velocity w (magenta).
 *
 * Mode 'cube' takes gravity away and holds the cube at its centre of mass on a frictionless pivot:
 * it tumbles slowly in place, and with no torque L stays fixed while w moves whenever the body is not
 * spinning about a principal axis. Mode 'flip' spins a box with three distinct moments about its
 * intermediate axis on the pivot: it flips over again and again (the Dzhanibekov effect); the plot
 * shows w in the body frame.
 * Keys: W/S, A/D, Q/E torque about the camera's right, up and viewing axes; X stops the spin;
 * Space jump (room); M switches mode (room, cube on a pivot, flip); P pause, N single step, R reset.
 * Click a face: an impulse there. Drag: orbit.
 * URL: ?mode=room|cube|flip (default room), ?spin=rad/s (flip).
 */

import { choiceParam, createButtonBar, createPanel, numberParam, pageLayout } from '@bitphysics/game-kit';
import type { Plot } from '@bitphysics/game-kit/plot';
import { ORBIT_CONTROLS, startThreeGame } from '@bitphysics/game-kit/three';
import {
  addPlane,
  addSystem,
  applyImpulse,
  applyImpulseAtPoint,
  createPhysicsWorld,
  type PhysicsWorld,
  rotateVectorInverse,
  spinAngularMomentum,
  spinKineticEnergy,
} from '@bitphysics/physics';
import { VectorArrow } from '@bitphysics/render-three';
import { BoxGeometry, Color, Float32BufferAttribute, MeshStandardMaterial, Vector3 } from 'three';
import {
  buildRotatingCube,
  JUMP_IMPULSE,
  MODES,
  type Mode,
  ROOM_HALF,
  ROOM_PUSH,
  type RotatingCubeHandles,
  rotatingCubeWorldOptions,
  torqueCouple,
  WALL_HEIGHT,
} from './scene';

/** A press that moves more than this, CSS px, is a camera drag, not a click. */
const CLICK_SLOP = 5;
/** Length of the angular-velocity arrow at the starting spin (or at 1 rad/s if slower), m. */
const ARROW_LENGTH = 1.6;

const params = {
  mode: choiceParam('mode', MODES, 'room') as Mode,
  torque: 0.5,
  impulse: 0.3,
  spin: numberParam('spin', { default: 6, min: 0.5, max: 30 }),
  showL: true,
  showOmega: true,
  axes: true,
  stop: () => stopSpin(),
  reset: () => game.shell.reset(),
};

let handles: RotatingCubeHandles;
/** Arrow length per rad/s of angular velocity, m: set per world so the starting spin shows as ARROW_LENGTH. */
let omegaScale = 1;
/** Torque the keys ask for now, N m, world frame (read by the forces-stage system). */
const keyTorque = new Float64Array(3);

/** A fresh world with the body of the current mode (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(rotatingCubeWorldOptions(params.mode));
  handles = buildRotatingCube(world, { mode: params.mode, spin: params.spin });
  const w = world.components.AngularVelocity,
    e = handles.body;
  omegaScale = ARROW_LENGTH / Math.max(1, Math.hypot(w.x[e]!, w.y[e]!, w.z[e]!));
  addSystem(
    world,
    'forces',
    torqueCouple(handles.body, () => keyTorque),
  );
  // Held at its pivot, the box has no collider: a floor far below only catches the shadow. The room has its own floor.
  if (params.mode !== 'room') addPlane(world, { normal: [0, 1, 0], point: [0, -1.6, 0] });
  return world;
}

// Read by frame(), which the shell may call before this module's code after the await below has run.
const L = new Float64Array(3),
  wb = new Float64Array(3);
let lastPlotted = -1,
  frames = 0;

const game = await startThreeGame({
  title: 'Rotating cube',
  createWorld,
  bodies: () => 1,
  controls: [
    { keys: 'Click', action: 'impulse at the point clicked' },
    { keys: 'W S', action: 'torque: pitch', touch: 'Pitch' },
    { keys: 'A D', action: 'torque: yaw', touch: 'Yaw' },
    { keys: 'Q E', action: 'torque: roll', touch: 'Roll' },
    { keys: 'X', action: 'stop spinning', touch: 'Stop' },
    { keys: 'Space', action: 'jump (room mode)', touch: 'Jump' },
    { keys: 'M', action: 'mode: room / cube on a pivot / Dzhanibekov flip', touch: 'Mode' },
    ...ORBIT_CONTROLS,
  ],
  keys: [
    { key: 'x', label: 'stop', action: () => stopSpin() },
    { key: 'm', label: 'mode', action: () => setMode(MODES[(MODES.indexOf(params.mode) + 1) % MODES.length]!) },
    { key: ' ', label: 'jump', action: () => jump() },
  ],
  app: { controls: { minDistance: 1.5, maxDistance: 30 } },
  renderer: { debug: params.axes ? debugOptions() : false, planeSize: 14, boundary: 'none' },
  view: viewOf(params.mode),
  viewDirection: [1, 0.7, 1.4],
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;

/** What the camera frames in each mode, m. */
function viewOf(mode: Mode): { min: [number, number, number]; max: [number, number, number] } {
  return mode === 'room'
    ? { min: [-ROOM_HALF, 0, -ROOM_HALF], max: [ROOM_HALF, WALL_HEIGHT, ROOM_HALF] }
    : { min: [-1.3, -1.3, -1.3], max: [1.3, 1.3, 1.3] };
}

/**
 * Debug layer: on the pivot the body's axes; in the room the contact points instead (the layer draws
 * axes for every body, 1.5 times its size: the walls' would cross the whole room).
 */
function debugOptions() {
  const room = params.mode === 'room';
  return { axes: !room, velocities: false, contacts: room, joints: false };
}

/** Room mode: the key torque and click impulse scale. */
function push(): number {
  return params.mode === 'room' ? ROOM_PUSH : 1;
}

/** Space: in room mode, a jump (an impulse up at the centre of mass). */
function jump(): void {
  if (params.mode !== 'room') return;
  applyImpulse(shell.world, handles.body, [0, JUMP_IMPULSE, 0]);
}

// The body: a unit box with one colour per face (x red, y green, z blue; darker on the negative
// side), scaled by the renderer to the body's equivalent-inertia box.
const faceColors = [0xe4572e, 0x7a2a17, 0x6cc04a, 0x2f5e22, 0x3d7be0, 0x1d3b6e];
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
const boxMaterial = new MeshStandardMaterial({ vertexColors: true, roughness: 0.55, metalness: 0.05 });
const dress = (): void => {
  renderer.setShape(handles.body, { geometry: boxGeometry, material: boxMaterial, scale: 'inertia' });
  for (const wall of handles.walls) renderer.setColor(wall, 0x5a6478);
};
dress();
shell.onWorldChange(() => {
  dress();
  plot?.clear();
});

const lArrow = new VectorArrow({ color: 0xffd166, radius: 0.025, headLength: 0.14 });
const wArrow = new VectorArrow({ color: 0xff5ce1, radius: 0.02, headLength: 0.12 });
app.scene.add(lArrow.object, wArrow.object);

// ---- Keys held: torque about the camera's axes ------------------------------------------------

const held = new Set<string>();
const TORQUE_KEYS = ['w', 's', 'a', 'd', 'q', 'e'];
function typing(target: EventTarget | null): boolean {
  const el = target as HTMLElement | null;
  return !!el && (el.tagName === 'INPUT' || el.tagName === 'SELECT' || el.tagName === 'TEXTAREA');
}
window.addEventListener('keydown', (event) => {
  const k = event.key.toLowerCase();
  if (!TORQUE_KEYS.includes(k) || typing(event.target) || event.ctrlKey || event.metaKey || event.altKey) return;
  held.add(k);
  event.preventDefault();
});
window.addEventListener('keyup', (event) => held.delete(event.key.toLowerCase()));
window.addEventListener('blur', () => held.clear());

// Touch: the torque keys as hold buttons, and stop, jump and mode (the same keys).
createButtonBar(
  [
    { label: 'Pitch ▲', name: 'torque: pitch forward', key: 'w' },
    { label: 'Pitch ▼', name: 'torque: pitch back', key: 's' },
    { label: 'Yaw ◀', name: 'torque: yaw left', key: 'a' },
    { label: 'Yaw ▶', name: 'torque: yaw right', key: 'd' },
    { label: 'Roll ⟲', name: 'torque: roll left', key: 'q' },
    { label: 'Roll ⟳', name: 'torque: roll right', key: 'e' },
    { label: 'Stop', name: 'stop spinning', key: 'x' },
    { label: 'Jump', name: 'jump (room mode)', key: ' ' },
    { label: 'Mode', name: 'mode: room / pivot / flip', key: 'm' },
  ],
  { label: 'torques and modes' },
);

const right = new Vector3(),
  up = new Vector3(),
  back = new Vector3();
/** Updates keyTorque from the keys held and the camera's axes (called every frame). */
function updateKeyTorque(): void {
  const pitch = (held.has('s') ? 1 : 0) - (held.has('w') ? 1 : 0);
  const yaw = (held.has('d') ? 1 : 0) - (held.has('a') ? 1 : 0);
  const roll = (held.has('q') ? 1 : 0) - (held.has('e') ? 1 : 0);
  app.camera.matrixWorld.extractBasis(right, up, back);
  const T = params.torque * push();
  keyTorque[0] = T * (pitch * right.x + yaw * up.x + roll * back.x);
  keyTorque[1] = T * (pitch * right.y + yaw * up.y + roll * back.y);
  keyTorque[2] = T * (pitch * right.z + yaw * up.z + roll * back.z);
}

// ---- Clicks: an impulse at the point of the face clicked ----------------------------------------

const canvas = app.canvas;
const ndc: [number, number] = [0, 0];
let downX = 0,
  downY = 0,
  downId = -1;
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  downId = event.pointerId;
  downX = event.clientX;
  downY = event.clientY;
});
canvas.addEventListener('pointerup', (event) => {
  if (event.pointerId !== downId) return;
  downId = -1;
  if (Math.hypot(event.clientX - downX, event.clientY - downY) > CLICK_SLOP) return;
  app.toNdc(event.clientX, event.clientY, ndc);
  clickAt(ndc[0], ndc[1]);
});

const rayDir = new Vector3();
/**
 * Casts a ray from the camera through (ndcX, ndcY); if it hits the body, applies an impulse of
 * params.impulse N s along the ray at the hit point. @returns whether the body was hit.
 */
function clickAt(ndcX: number, ndcY: number): boolean {
  const hit = renderer.pick(ndcX, ndcY, app.camera);
  if (!hit || hit.eid !== handles.body) return false;
  rayDir.set(ndcX, ndcY, 0.5).unproject(app.camera).sub(app.camera.position).normalize();
  const J = params.impulse * push();
  applyImpulseAtPoint(shell.world, handles.body, [rayDir.x * J, rayDir.y * J, rayDir.z * J], hit.point);
  flash = 12;
  return true;
}
let flash = 0;

/** Zeroes the body's angular velocity (X key, panel button). */
function stopSpin(): void {
  const w = shell.world.components.AngularVelocity;
  w.x[handles.body] = 0;
  w.y[handles.body] = 0;
  w.z[handles.body] = 0;
}

/** Switches mode, rebuilds the world and frames it. */
function setMode(mode: Mode): void {
  params.mode = mode;
  panel.refresh();
  shell.reset();
  const v = viewOf(mode);
  app.frame(v.min, v.max, [1, 0.7, 1.4]);
  if (params.axes) renderer.setDebug(debugOptions());
}

const panel = createPanel(
  params,
  [
    {
      type: 'choice',
      key: 'mode',
      options: { 'room (gravity, floor, walls)': 'room', 'cube on a pivot (no gravity)': 'cube', 'Dzhanibekov flip (pivot)': 'flip' },
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
let plot: Plot | null = null;
try {
  const { createPlot } = await import('@bitphysics/game-kit/plot');
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
} catch (error) {
  console.warn('rotating-cube: no plot:', error instanceof Error ? error.message : error);
}

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
  if (params.showL) lArrow.set(o[0], o[1], o[2], L[0]!, L[1]!, L[2]!, omegaScale / iMid);
  else lArrow.hide();
  if (params.showOmega) wArrow.set(o[0], o[1], o[2], wx, wy, wz, omegaScale);
  else wArrow.hide();
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
    lines[4]!.textContent = `arrows: 1 rad/s = ${omegaScale.toFixed(2)} m`;
    // For a cube (equal moments) L stays parallel to w; for other boxes it does not.
    const lw = Math.hypot(L[0]!, L[1]!, L[2]!) * Math.hypot(wx, wy, wz);
    const angle = lw > 0 ? (Math.acos(Math.min(1, (L[0]! * wx + L[1]! * wy + L[2]! * wz) / lw)) * 180) / Math.PI : 0;
    lines[5]!.textContent = `angle between L and ω ${angle.toFixed(1)}°`;
  }
  if (flash > 0) flash--;
}

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
  /** The body's y axis in the world frame (a unit vector): flips sign in flip mode. */
  bodyUp: (): number[] => {
    const q = shell.world.components.Orientation,
      e = handles.body,
      out = new Float64Array(3);
    // Rotating (0, 1, 0) by q is the inverse of rotating by its conjugate.
    rotateVectorInverse(-q.x[e]!, -q.y[e]!, -q.z[e]!, q.w[e]!, 0, 1, 0, out);
    return Array.from(out);
  },
  /** Clicks at (ndcX, ndcY) as the mouse would; returns whether the body was hit. */
  clickAt,
  /** Switches mode ('room', 'cube' or 'flip') and rebuilds. @throws RangeError on an unknown mode. */
  setMode: (mode: Mode): void => {
    if (!MODES.includes(mode)) throw new RangeError(`setMode: mode must be one of ${MODES.join(', ')}, got ${String(mode)}`);
    setMode(mode);
  },
});
