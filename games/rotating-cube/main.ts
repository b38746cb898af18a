/**
 * Rotating cube: rigid-body rotation in 3D. By default (mode 'room') a 1 m cube falls tumbling into a
 * room and collides with the floor and the walls (a box collider and 3D box contacts): it lands,
 * tumbles, slides and bounces off them; torques from the keys (a couple of forces from
 * `applyForceAtPoint` in a forces-stage system) and impulses from clicks (`applyImpulseAtPoint` at
 * the point of the face clicked, a flick away from it) push it about, and Space makes it jump. The
 * challenge: rest it on five glowing pads in turn, against the clock.
 * Arrows show its angular momentum L (`spinAngularMomentum`, yellow) and angular velocity w (magenta).
 *
 * Mode 'cube' takes gravity away and holds the cube at its centre of mass on a frictionless pivot:
 * it tumbles slowly in place, and with no torque L stays fixed while w moves whenever the body is not
 * spinning about a principal axis. Mode 'flip' spins a box with three distinct moments about its
 * intermediate axis on the pivot: it flips over again and again (the Dzhanibekov effect); the plot
 * shows w in the body frame. The challenge: 10 flips within 20 s (spin it up with the yaw keys).
 * Keys: W/S, A/D, Q/E torque about the camera's right, up and viewing axes; X stops the spin;
 * Space jump (room); M switches mode (room, cube on a pivot, flip); P pause, N single step, R reset.
 * Click a face: an impulse there (in the room a flick away from the point clicked). Drag: orbit.
 * Challenges: room: rest the cube on five pads in turn (stars by time); flip: 10 flips in 20 s.
 * URL: ?mode=room|cube|flip (default room), ?spin=rad/s (flip).
 */

import { choiceParam, createButtonBar, createPanel, createStatusRow, numberParam, pageLayout } from '@bitphysics/game-kit';
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
import { BoxGeometry, Color, Float32BufferAttribute, Mesh, MeshStandardMaterial, Vector3 } from 'three';
import {
  buildRotatingCube,
  FLIP_GOAL,
  FLIP_TIME,
  FlipChallenge,
  JUMP_IMPULSE,
  MODES,
  type Mode,
  PAD_HALF,
  PAD_STAR_TIMES,
  PADS,
  PadChallenge,
  padStars,
  ROOM_HALF,
  ROOM_PUSH,
  type RotatingCubeHandles,
  rotatingCubeWorldOptions,
  torqueCouple,
  WALL_HEIGHT,
} from './scene';

/** A press that moves more than this, CSS px, is a camera drag, not a click. */
const CLICK_SLOP = 5;
/** Room mode: a click's flick rises this much per unit of its horizontal direction (0.5: about 27 degrees up). */
const FLICK_LIFT = 0.5;
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
/** Room mode's challenge (the pads) and flip mode's (flips in FLIP_TIME); reset with the world. */
const pads = new PadChallenge(),
  flips = new FlipChallenge();
/** Best round of this page visit: pad round time, s, and most flips. */
let bestPadTime = Infinity,
  bestFlips = 0;
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
  // The challenges are checked after every step (a system at the end of the step), so they count
  // the same whether the page runs, single-steps or is stepped by a test.
  pads.reset();
  flips.reset();
  addSystem(world, 'finalize', (w) => {
    if (params.mode === 'room') pads.update(w, handles.body);
    else if (params.mode === 'flip') flips.update(w, handles.body);
  });
  // Held at its pivot, the box has no collider: a floor far below only catches the shadow. The room has its own floor.
  if (params.mode !== 'room') addPlane(world, { normal: [0, 1, 0], point: [0, -1.6, 0] });
  return world;
}

/**
 * The walls' material (the renderer's box material, which only the walls use: the body has its own):
 * light and half see-through, so the cube stays in sight behind the near wall from any side.
 */
const wallMaterial = new MeshStandardMaterial({ roughness: 0.75, metalness: 0, transparent: true, opacity: 0.5, depthWrite: false });

// Read by frame(), which the shell may call before this module's code after the await below has run.
const L = new Float64Array(3),
  wb = new Float64Array(3);
let lastPlotted = -1,
  frames = 0,
  /** Angle between L and w, degrees (the readout's, for the status row). */
  angleLw = 0;

const game = await startThreeGame({
  title: 'Rotating cube',
  createWorld,
  bodies: () => 1,
  controls: [
    { keys: 'Click', action: 'poke a face: the cube is flicked away from it' },
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
  app: { background: 0x1a2232, controls: { minDistance: 1.5, maxDistance: 30 } },
  renderer: {
    debug: params.axes ? debugOptions() : false,
    planeSize: 14,
    boundary: 'none',
    floorColor: 0x3c4660,
    boxMaterial: wallMaterial,
    lights: { intensity: 2.4, hemisphereIntensity: 1.2, skyColor: 0xeaf2ff, groundColor: 0x5a4e40, direction: [0.5, 1, 0.35] },
  },
  view: viewOf(params.mode),
  viewDirection: viewDirectionOf(params.mode),
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;
clampOrbit();

/** What the camera frames in each mode, m: the room with its walls, or the box on its pivot. */
function viewOf(mode: Mode): { min: [number, number, number]; max: [number, number, number] } {
  return mode === 'room'
    ? { min: [-ROOM_HALF, 0, -ROOM_HALF], max: [ROOM_HALF, WALL_HEIGHT, ROOM_HALF] }
    : { min: [-1.3, -1.3, -1.3], max: [1.3, 1.8, 1.3] };
}

/**
 * Direction the camera looks from in each mode: the room from high up (about 50 degrees), so a cube
 * against the near wall stays in sight over it; the pivot from a little above.
 */
function viewDirectionOf(mode: Mode): [number, number, number] {
  return mode === 'room' ? [1, 2.1, 1.4] : [1, 0.7, 1.4];
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

/** Space: in room mode, a jump (an impulse up at the centre of mass). */
function jump(): void {
  if (params.mode !== 'room') return;
  applyImpulse(shell.world, handles.body, [0, JUMP_IMPULSE, 0]);
}

// The body: a unit box with one colour per face (x red, y green, z blue; a pale tint of it on the
// negative side, so every face reads in the light), scaled by the renderer to the body's
// equivalent-inertia box.
const faceColors = [0xef5b3a, 0xf6b09a, 0x5cc043, 0xbde8a4, 0x3d7be0, 0xa9c6f7];
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
  for (const wall of handles.walls) renderer.setColor(wall, 0xb9c8e6);
};
dress();
shell.onWorldChange(() => {
  dress();
  plot?.clear();
});

// The lit pad of the room's challenge: a glowing square on the floor (drawn only; the physics knows nothing of it).
const padMesh = new Mesh(
  new BoxGeometry(2 * PAD_HALF, 0.02, 2 * PAD_HALF),
  new MeshStandardMaterial({ color: 0x0c8f52, emissive: 0x12c46e, emissiveIntensity: 0.9, roughness: 0.4 }),
);
padMesh.receiveShadow = true;
app.scene.add(padMesh);

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
 * params.impulse N s (times ROOM_PUSH in the room) at the hit point: on the pivot along the ray; in
 * the room a flick away from the point poked: horizontally from the hit point towards the cube's
 * centre (along the ray's horizontal direction when the hit is within 10 cm of above the centre),
 * tilted FLICK_LIFT up. So a poke at the cube's west side sends it east, whichever way the camera
 * looks (the steep camera's ray points mostly down: along it the cube would only be pressed into
 * the floor).
 * @returns whether the body was hit.
 */
function clickAt(ndcX: number, ndcY: number): boolean {
  const hit = renderer.pick(ndcX, ndcY, app.camera);
  if (!hit || hit.eid !== handles.body) return false;
  rayDir.set(ndcX, ndcY, 0.5).unproject(app.camera).sub(app.camera.position).normalize();
  const P = shell.world.components.Position,
    e = handles.body;
  const hx = P.x[e]! - hit.point[0]!,
    hz = P.z[e]! - hit.point[2]!;
  if (params.mode === 'room' && Math.hypot(hx, hz) > 0.1) rayDir.set(hx, 0, hz);
  if (params.mode === 'room' && Math.hypot(rayDir.x, rayDir.z) > 1e-6) {
    rayDir.y = 0;
    rayDir.normalize();
    rayDir.y = FLICK_LIFT;
    rayDir.normalize();
  }
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
  app.frame(v.min, v.max, viewDirectionOf(mode));
  clampOrbit();
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

// ---- The challenge's status row (above the scene, on every screen) ---------------------------------

const status = createStatusRow({ name: 'challenge' });
const touch = pageLayout().touch();
const stars = (n: number): string => '★'.repeat(n) + '☆'.repeat(3 - n);

/** Writes the status row: the mode's goal, its numbers (the key readout) and how to play. */
function updateStatus(wx: number, wy: number, wz: number): void {
  const world = shell.world,
    t = world.time,
    w = Math.hypot(wx, wy, wz);
  if (params.mode === 'room') {
    const flick = touch ? 'Tap a face to flick it · hold Pitch, Yaw, Roll' : 'Click a face to flick it · W A S D Q E turn it · Space jumps';
    if (pads.done) {
      const time = pads.doneAt;
      if (time < bestPadTime) bestPadTime = time;
      status.set(
        {
          goal: `All ${PADS.length} pads in ${time.toFixed(1)} s ${stars(padStars(time))}`,
          numbers: `best ${bestPadTime.toFixed(1)} s · ★★★ within ${PAD_STAR_TIMES[0]} s`,
          hint: 'R: play again · M: next mode (free spin, then the flip challenge)',
        },
        true,
      );
    } else
      status.set({
        goal: `Land the cube on the glowing pad (${pads.pad + 1} of ${PADS.length})`,
        numbers: `Pads ${pads.pad}/${PADS.length} · ${t.toFixed(1)} s · ${stars(padStars(Math.max(t, 0)))}`,
        hint: flick,
      });
  } else if (params.mode === 'flip') {
    const n = flips.counter.count;
    const over = flips.over(world);
    if (over && n > bestFlips) bestFlips = n;
    const spin = touch ? 'hold Yaw' : 'hold A or D';
    status.set(
      over
        ? {
            goal:
              flips.wonAt >= 0
                ? `${FLIP_GOAL} flips in ${flips.wonAt.toFixed(1)} s ${stars(3)}`
                : `Time! ${n} flips ${stars(flips.stars())}`,
            numbers: `best ${bestFlips} flips · |ω| ${w.toFixed(1)} rad/s`,
            hint: 'R: try again · M: back to the pads',
          }
        : {
            goal: `Make the box flip over ${FLIP_GOAL} times in ${FLIP_TIME} s`,
            numbers: `Flips ${n}/${FLIP_GOAL} · ${Math.max(0, FLIP_TIME - t).toFixed(1)} s left · |ω| ${w.toFixed(1)} rad/s`,
            hint: `It flips by itself; spun faster it flips faster: ${spin}`,
          },
      over && flips.wonAt >= 0,
    );
  } else {
    status.set({
      // A cube's inertia is the same about every axis, so its ω stays along L; the box (M) is the one
      // whose ω wanders and flips.
      goal: 'Free spin: a cube turns alike about every axis, so ω (magenta) stays on L (yellow)',
      numbers: `|ω| ${w.toFixed(2)} rad/s · angle L–ω ${angleLw.toFixed(1)}°`,
      hint: 'M: a box, whose ω wanders and flips',
    });
  }
}

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
    lines[4]!.textContent = `arrows: L yellow, ω magenta; 1 rad/s = ${omegaScale.toFixed(2)} m`;
    // For a cube (equal moments) L stays parallel to w; for other boxes it does not.
    const lw = Math.hypot(L[0]!, L[1]!, L[2]!) * Math.hypot(wx, wy, wz);
    const angle = lw > 0 ? (Math.acos(Math.min(1, (L[0]! * wx + L[1]! * wy + L[2]! * wz) / lw)) * 180) / Math.PI : 0;
    lines[5]!.textContent = `angle between L and ω ${angle.toFixed(1)}°`;
    angleLw = angle;
  }
  if (frames % 5 === 0) updateStatus(wx, wy, wz);
  // The lit pad glows (pulsing) while the room's round runs.
  const padLit = params.mode === 'room' && !pads.done;
  padMesh.visible = padLit;
  if (padLit) {
    const spot = PADS[pads.pad]!;
    padMesh.position.set(spot[0], 0.02, spot[1]);
    (padMesh.material as MeshStandardMaterial).emissiveIntensity = 0.8 + 0.4 * Math.sin(performance.now() / 250);
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
  /**
   * The challenge's state: room: the lit pad's index (PADS.length when the round is over), the round's
   * time (s, -1 while it runs) and the pads' centres (x, z, m); flip: the flips counted and the time
   * the goal was reached (s, -1 if not yet).
   */
  challenge: () => ({
    mode: params.mode,
    pad: pads.pad,
    padsDoneAt: pads.doneAt,
    pads: PADS.map((p) => [p[0], p[1]]),
    flips: flips.counter.count,
    flipsWonAt: flips.wonAt,
  }),
  /** Clicks at (ndcX, ndcY) as the mouse would; returns whether the body was hit. */
  clickAt,
  /** Switches mode ('room', 'cube' or 'flip') and rebuilds. @throws RangeError on an unknown mode. */
  setMode: (mode: Mode): void => {
    if (!MODES.includes(mode)) throw new RangeError(`setMode: mode must be one of ${MODES.join(', ')}, got ${String(mode)}`);
    setMode(mode);
  },
});
