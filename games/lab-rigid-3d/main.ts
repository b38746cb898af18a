/**
 * Lab: 3D rigid bodies (boxes, capsules, cylinders and their joints). Five scenes, picked with the keys
 * 1 to 5 or the panel: a box tumbling onto a table, a stack of ten boxes, a ring of dominoes, a spinning
 * top standing free on its tip (its precession rate against Omega = m g r / (I3 omega3); its tip's
 * friction on a slider) and a ragdoll of capsules
 * tumbling down steps. Drag any body with the mouse (a spring to the pointer through a ray cast in the
 * physics); Space acts on the scene (throw, knock, push, spin, kick).
 * Keys: 1-5 scene, Space act, G debug layer (contacts, joints, axes), P pause, N step, R reset.
 * URL: ?scene=tumble|stack|dominoes|top|ragdoll, ?dominoes=N, ?spin=rad/s, ?tip=the top's tip friction (0-1.2).
 */

import { choiceParam, createPanel, numberParam, pageLayout } from '@bitphysics/game-kit';
import { ORBIT_CONTROLS_RIGHT, startThreeGame } from '@bitphysics/game-kit/three';
import { addBody, applyImpulse, createPhysicsWorld, type PhysicsWorld, step as physicsStep, spinKineticEnergy } from '@bitphysics/physics';
import { BodyDrag3D } from '@bitphysics/render-three';
import {
  buildLab,
  DOMINO_SPACING,
  hasToppled,
  type LabHandles,
  labWorldOptions,
  SCENES,
  type SceneName,
  topAxis,
  topHeading,
} from './scene';

const params = {
  // The default is the light stack: 100 dominoes cost about 10 ms a step on a loaded 2-core machine (key 3).
  scene: choiceParam('scene', SCENES, 'stack') as SceneName,
  dominoes: numberParam('dominoes', { default: 100, min: 2, max: 400, integer: true }),
  spin: numberParam('spin', { default: 60, min: 20, max: 200 }),
  /** The top's tip friction: 0 a smooth table (the rate then follows the formula), more and the tip rolls and wanders. */
  tip: numberParam('tip', { default: 0, min: 0, max: 1.2 }),
  friction: 0.6,
  debug: false,
  act: () => act(),
  reset: () => game.shell.reset(),
};

let handles: LabHandles;
let stepMs = 0;
/** Dominoes: the time each toppled (s), NaN while standing. */
let toppledAt: number[] = [];
/** Top: unwrapped heading of its axis (rad) per step, the last 2 s. */
const headings: Array<[number, number]> = [];
let heading = 0,
  lastHeading = 0;
const startY: number[] = [];

/** Camera boxes per scene, m. */
const VIEWS: Record<SceneName, { min: [number, number, number]; max: [number, number, number] }> = {
  tumble: { min: [-1.4, 0, -0.8], max: [1.4, 1.4, 0.8] },
  stack: { min: [-1.5, 0, -1.5], max: [1.5, 5, 1.5] },
  dominoes: { min: [-3.4, 0, -3.4], max: [3.4, 0.5, 3.4] },
  top: { min: [-0.6, 0, -0.6], max: [0.6, 0.9, 0.6] },
  ragdoll: { min: [-1, 0, -1.2], max: [3.2, 2.6, 1.2] },
};

function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(labWorldOptions(params.scene));
  handles = buildLab(world, params.scene, {
    dominoes: params.dominoes,
    spin: params.spin,
    friction: params.friction,
    tipFriction: params.tip,
  });
  toppledAt = handles.scene === 'dominoes' ? handles.parts.map(() => Number.NaN) : [];
  headings.length = 0;
  if (handles.top) {
    heading = lastHeading = topHeading(world, handles);
  }
  startY.length = 0;
  for (const b of handles.parts) startY.push(world.components.Position.y[b]!);
  return world;
}

function labStep(world: PhysicsWorld): void {
  const t0 = performance.now();
  physicsStep(world);
  const ms = performance.now() - t0;
  stepMs = stepMs === 0 ? ms : stepMs + (ms - stepMs) / 30;
  if (handles.scene === 'dominoes') {
    for (let i = 0; i < toppledAt.length; i++) if (Number.isNaN(toppledAt[i]!) && hasToppled(world, handles, i)) toppledAt[i] = world.time;
  } else if (handles.top) {
    const hd = topHeading(world, handles);
    let d = hd - lastHeading;
    d -= 2 * Math.PI * Math.round(d / (2 * Math.PI));
    heading += d;
    lastHeading = hd;
    headings.push([world.time, heading]);
    if (headings.length > 120) headings.shift();
  }
}

const game = await startThreeGame({
  title: 'Lab: 3D rigid bodies',
  createWorld,
  step: labStep,
  bodies: () => handles.bodies.length,
  controls: [
    { keys: '1 – 5', action: 'scene: tumble, stack, dominoes, top, ragdoll' },
    { keys: 'Space', action: 'throw / knock / push / spin / kick' },
    { keys: 'Drag body', action: 'pull it on a spring' },
    { keys: 'G', action: 'debug: contacts, joints, axes' },
    ...ORBIT_CONTROLS_RIGHT,
  ],
  keys: [
    ...SCENES.map((s, i) => ({ key: String(i + 1), label: s, action: () => setScene(s) })),
    { key: ' ', label: 'act', action: () => act() },
    { key: 'g', label: 'debug', action: () => setDebug(!params.debug) },
  ],
  app: { controls: { leftButton: 'none', minDistance: 0.5, maxDistance: 40 } },
  renderer: { boundary: 'none', planeSize: 24, initialInstances: 128, shadowBounds: { min: [-5, 0, -5], max: [5, 5, 5] } },
  view: VIEWS[params.scene],
  viewDirection: [0.8, 0.7, 1.2],
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;

const COLORS: Record<SceneName, number[]> = {
  tumble: [0x4d8dff],
  stack: [0xe4572e, 0xf3a712, 0x6cc04a, 0x3d7be0, 0xa06cd5],
  dominoes: [0xf1f1f1, 0x2b2d42],
  top: [0xffd166],
  ragdoll: [0xe9c46a],
};
function dress(): void {
  const colors = COLORS[handles.scene];
  handles.parts.forEach((b, i) => {
    renderer.setColor(b, colors[i % colors.length]!);
  });
  for (const b of handles.statics) renderer.setColor(b, handles.scene === 'tumble' ? 0x8d6748 : 0x6b7385);
}
dress();
shell.onWorldChange(() => {
  drag.release();
  dress();
});

function setScene(scene: SceneName): void {
  params.scene = scene;
  panel.refresh();
  shell.reset();
  const v = VIEWS[scene];
  app.frame(v.min, v.max, [0.8, 0.7, 1.2]);
}

function setDebug(on: boolean): void {
  params.debug = on;
  renderer.setDebug(on ? { axes: true, velocities: false, contacts: true, joints: true, normalLength: 0.15 } : false);
  panel.refresh();
}

/** Space: something for each scene. */
function act(): void {
  const world = shell.world,
    h = handles,
    P = world.components.Position;
  switch (h.scene) {
    case 'tumble':
      shell.reset();
      break;
    case 'stack': {
      // knock the fourth box sideways
      const b = h.parts[3]!;
      applyImpulse(world, b, [60, 0, 20]);
      break;
    }
    case 'dominoes':
      shell.reset();
      break;
    case 'top':
      shell.reset();
      break;
    case 'ragdoll': {
      // A kick up and back on the chest; or a ball thrown at it when it lies still.
      const chest = h.parts[1]!;
      applyImpulse(world, chest, [-30, 60, 10]);
      const ball = addBody(world, {
        position: [P.x[chest]! + 3, P.y[chest]! + 1, P.z[chest]!],
        radius: 0.15,
        mass: 4,
        velocity: [-9, 1, 0],
      });
      renderer.setColor(ball, 0xff5a5f);
      break;
    }
  }
}

// ---- Dragging bodies -------------------------------------------------------------------------

const canvas = app.canvas;
const drag = new BodyDrag3D(renderer, { hertz: 4, dampingRatio: 0.8 });
const ndc: [number, number] = [0, 0];
let pressId = -1;
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  app.toNdc(event.clientX, event.clientY, ndc);
  if (drag.grab(ndc[0], ndc[1], app.camera) !== 0) {
    pressId = event.pointerId;
    canvas.setPointerCapture(event.pointerId);
  }
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pressId) return;
  app.toNdc(event.clientX, event.clientY, ndc);
  drag.move(ndc[0], ndc[1], app.camera);
});
const up = (event: PointerEvent): void => {
  if (event.pointerId !== pressId) return;
  pressId = -1;
  drag.release();
};
canvas.addEventListener('pointerup', up);
canvas.addEventListener('pointercancel', up);
canvas.addEventListener(
  'wheel',
  (event) => {
    if (pressId < 0) return;
    drag.setDepth(event.deltaY > 0 ? 0.2 : -0.2, app.camera);
    event.stopImmediatePropagation(); // the orbit controls would zoom too
  },
  { capture: true },
);

// ---- Panel and readout -----------------------------------------------------------------------

const panel = createPanel(
  params,
  [
    {
      type: 'choice',
      key: 'scene',
      options: {
        'box on a table (1)': 'tumble',
        'stack of ten (2)': 'stack',
        'dominoes (3)': 'dominoes',
        'spinning top (4)': 'top',
        'ragdoll (5)': 'ragdoll',
      },
      onChange: (s) => setScene(s as SceneName),
    },
    {
      type: 'slider',
      key: 'dominoes',
      label: 'dominoes (rebuilds)',
      min: 10,
      max: 400,
      step: 10,
      onRelease: true,
      onChange: () => {
        if (params.scene === 'dominoes') shell.reset();
      },
    },
    {
      type: 'slider',
      key: 'spin',
      label: 'top spin ω₃ (rad/s, rebuilds)',
      min: 20,
      max: 200,
      step: 5,
      onRelease: true,
      onChange: () => {
        if (params.scene === 'top') shell.reset();
      },
    },
    {
      type: 'slider',
      key: 'tip',
      label: 'top tip friction (rebuilds)',
      min: 0,
      max: 1.2,
      step: 0.05,
      onRelease: true,
      onChange: () => {
        if (params.scene === 'top') shell.reset();
      },
    },
    {
      type: 'slider',
      key: 'friction',
      label: 'friction (rebuilds)',
      min: 0,
      max: 1.2,
      step: 0.05,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'debug', label: 'debug layer (G)', onChange: (v) => setDebug(v === true) },
    { type: 'button', key: 'act', label: 'act (Space)' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Lab: 3D rigid bodies' },
);

const readout = document.createElement('div');
readout.className = 'bp-hud';
readout.dataset.hud = 'lab-rigid-3d';
readout.style.cssText = 'position: static; min-width: 260px';
const lines = Array.from({ length: 6 }, () => readout.appendChild(document.createElement('div')));
pageLayout().side.append(readout);

/** Top: the precession rate over the last second of headings, rad/s (NaN before a second has passed). */
function measuredPrecession(): number {
  if (headings.length < 61) return Number.NaN;
  const a = headings[headings.length - 61]!,
    b = headings[headings.length - 1]!;
  return (b[1] - a[1]) / (b[0] - a[0]);
}

const axisNow = [0, 0, 0];
/** Top: current tilt (rad), spin component omega3 (rad/s), the gyroscope formula and the steady root now. */
function topNow(): { tilt: number; omega3: number; gyro: number; steady: number } {
  const world = shell.world,
    t = handles.top!,
    b = handles.main,
    c = world.components;
  const a = topAxis(world, handles, axisNow);
  const tilt = Math.acos(Math.max(-1, Math.min(1, a[1]!)));
  const W = c.AngularVelocity;
  const omega3 = W.x[b]! * a[0]! + W.y[b]! * a[1]! + W.z[b]! * a[2]!;
  const L = t.I3 * omega3,
    torque = t.mass * Math.abs(world.gravity[1]!) * t.r,
    cos = Math.cos(tilt);
  const steady = (L - Math.sqrt(Math.max(0, L * L - 4 * t.I1 * cos * torque))) / (2 * t.I1 * cos);
  return { tilt, omega3, gyro: torque / L, steady };
}

let frames = 0;
function frame(): void {
  if (frames++ % 10 !== 0) return;
  const world = shell.world,
    h = handles,
    c = world.components,
    b = h.main;
  const set = (i: number, text: string): void => {
    lines[i]!.textContent = text;
  };
  for (let i = 0; i < lines.length; i++) set(i, '');
  set(5, `step ${stepMs.toFixed(2)} ms · ${h.bodies.length} bodies · ${renderer.stats.shapes.meshes} shape meshes`);
  switch (h.scene) {
    case 'tumble': {
      const v = Math.hypot(c.Velocity.x[b]!, c.Velocity.y[b]!, c.Velocity.z[b]!);
      const ke = 0.5 * c.Mass.value[b]! * v * v + spinKineticEnergy(world, b);
      set(0, `box 0.3 m, ${c.Mass.value[b]!.toFixed(1)} kg, on a table at 0.8 m`);
      set(
        1,
        `speed ${v.toFixed(2)} m/s · spin ${Math.hypot(c.AngularVelocity.x[b]!, c.AngularVelocity.y[b]!, c.AngularVelocity.z[b]!).toFixed(2)} rad/s`,
      );
      set(2, `kinetic energy ${ke.toFixed(2)} J · height ${c.Position.y[b]!.toFixed(3)} m`);
      break;
    }
    case 'stack': {
      const drift = Math.hypot(c.Position.x[b]!, c.Position.z[b]!);
      set(0, 'ten 0.5 m boxes (600 kg/m³)');
      set(
        1,
        `top box: drifted ${(drift * 1000).toFixed(1)} mm, sank ${((startY[startY.length - 1]! - c.Position.y[b]!) * 1000).toFixed(1)} mm`,
      );
      set(2, 'Space knocks the fourth box');
      break;
    }
    case 'dominoes': {
      const done = toppledAt.filter((t) => !Number.isNaN(t));
      const last = done.length > 0 ? Math.max(...done) : 0,
        first = done.length > 0 ? Math.min(...done) : 0;
      set(0, `${h.parts.length} dominoes 0.5 m tall, ${DOMINO_SPACING} m apart`);
      set(1, `toppled ${done.length} / ${h.parts.length}`);
      set(
        2,
        done.length > 5
          ? `wave speed ${((DOMINO_SPACING * (done.length - 1)) / Math.max(1e-9, last - first)).toFixed(2)} m/s`
          : 'wave speed …',
      );
      break;
    }
    case 'top': {
      const t = h.top!,
        now = topNow(),
        m = measuredPrecession();
      set(
        0,
        `top ${t.mass.toFixed(1)} kg, r ${t.r.toFixed(3)} m, I₃ ${t.I3.toFixed(3)} kg m², free on a ${(t.rho * 200).toFixed(0)} cm ball tip, friction ${t.tipFriction}`,
      );
      set(1, `ω₃ ${now.omega3.toFixed(1)} rad/s · tilt ${((now.tilt * 180) / Math.PI).toFixed(1)}°`);
      set(2, `Ω measured ${Number.isNaN(m) ? '…' : m.toFixed(4)} rad/s`);
      set(3, `Ω = m g r / (I₃ ω₃) = ${now.gyro.toFixed(4)} rad/s`);
      set(4, `steady root (with I₁ Ω² cos θ) ${now.steady.toFixed(4)} rad/s`);
      break;
    }
    case 'ragdoll': {
      set(0, '11 capsules: 6 ball joints with swing cones (spine, neck, shoulders, hips), 4 limited hinges (elbows, knees)');
      set(1, `pelvis height ${c.Position.y[b]!.toFixed(2)} m`);
      set(2, 'Space kicks it and throws a ball');
      break;
    }
  }
}

// ---- window.game ---------------------------------------------------------------------------

shell.expose({
  params,
  panel,
  drag,
  handles: (): LabHandles => handles,
  /** Switches scene (rebuilds). @throws RangeError on an unknown scene. */
  setScene: (scene: SceneName): void => {
    if (!SCENES.includes(scene)) throw new RangeError(`setScene: scene must be one of ${SCENES.join(', ')}, got ${String(scene)}`);
    setScene(scene);
  },
  act,
  /** Dominoes toppled so far. */
  toppled: (): number => toppledAt.filter((t) => !Number.isNaN(t)).length,
  /** The top's measured precession rate over the last second, rad/s (NaN before). */
  measuredPrecession,
  stepTime: (): number => stepMs,
});
