/**
 * Lab: joints (Ramtal and Dobre ch. 13; Box2D v3's joint set). Six scenes, picked in the panel: a
 * pendulum on a revolute pin (its measured period against the exact large-amplitude period
 * 4 sqrt(L/g) K(sin(theta0/2))), a chain, a suspension bridge loaded with balls, a car on two wheel
 * joints (suspension springs, motor) driving over bumps, a ragdoll (pins with angle limits, a soft
 * weld), a windmill turned by a motor. Joints are drawn as lines from each body's centre to the joint.
 *
 * Input: drag any body (a mouse joint: a soft spring of limited force). Keys: P pause, N step,
 * R reset. URL: ?scene (pendulum, chain, bridge, car, ragdoll, windmill).
 */

import { choiceParam, createPanel } from '@bitphysics/game-kit';
import { enableMouseDrag } from '@bitphysics/game-kit/drag';
import { createLabDock, createReadout, fmt, followView, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import { createPhysicsWorld, handleOf, jointAnchors, type PhysicsWorld, step as physicsStep, query, slotOf } from '@bitphysics/physics';
import type { WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { buildScene, type JointScene, SCENE_NAMES, type SceneName } from './scenes';

const USAGE = `Accepted: scene ${SCENE_NAMES.join(', ')}.`;
const url = readUrlParams(() => ({ scene: choiceParam('scene', SCENE_NAMES, 'pendulum') as SceneName }), USAGE);
const params = { ...url, amplitude: 120, motorSpeed: 6, gravity: 9.81, reset: () => shell.reset() };

const VIEWS: Record<SceneName, WorldRect> = {
  pendulum: { minX: -3, minY: -1, maxX: 3, maxY: 3 },
  chain: { minX: -5, minY: -3.5, maxX: 5, maxY: 3 },
  bridge: { minX: -6, minY: -4, maxX: 6, maxY: 3.5 },
  car: { minX: -10, minY: -4, maxX: 6, maxY: 2 },
  ragdoll: { minX: -4, minY: -3.5, maxX: 4, maxY: 3 },
  windmill: { minX: -4.5, minY: -3.5, maxX: 4.5, maxY: 5.5 },
};
const view: WorldRect = { ...VIEWS.pendulum };
let handles: JointScene = {};
const measure = { period: Number.NaN, exactPeriod: Number.NaN, turns: 0, lastTurn: Number.NaN, lastW: 0 };

function agm(a: number, b: number): number {
  for (let i = 0; i < 40; i++) {
    const m = (a + b) / 2;
    b = Math.sqrt(a * b);
    a = m;
  }
  return a;
}

function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld({ gravity: [0, -params.gravity], capacity: 2000 });
  handles = buildScene(world, params.scene, params);
  Object.assign(view, VIEWS[params.scene]);
  refit?.();
  measure.period = Number.NaN;
  measure.turns = 0;
  measure.lastTurn = Number.NaN;
  measure.lastW = 0;
  if (handles.bob !== undefined) {
    // Physical pendulum: equivalent length (I + m L^2) / (m L) with the bob's I = 0.02 kg m^2, m = 1 kg.
    const L = handles.length!,
      Leq = (0.02 + L * L) / L,
      k = Math.sin(Math.abs(handles.amplitude!) / 2);
    measure.exactPeriod = (4 * Math.sqrt(Leq / params.gravity) * Math.PI) / (2 * agm(1, Math.sqrt(1 - k * k)));
  } else measure.exactPeriod = Number.NaN;
  plot?.clear();
  return world;
}

let plot: ReturnType<typeof createPlot> | null = null;
let refit: (() => void) | null = null;

function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  if (handles.bob !== undefined) {
    // Period from successive turning points on the same side (angular velocity crossing zero upward).
    const w = world.components.AngularVelocity.z[slotOf(handles.bob)]!;
    if (measure.lastW < 0 && w >= 0) {
      const t = world.time - (world.dt * w) / (w - measure.lastW);
      if (!Number.isNaN(measure.lastTurn)) measure.period = t - measure.lastTurn;
      measure.lastTurn = t;
      measure.turns++;
    }
    measure.lastW = w;
  }
  plot?.push(world.time, world.joints.stats.maxError * 1000);
}

const game = await startPixiGame({
  title: 'Joints',
  createWorld,
  step: labStep,
  controls: [{ keys: 'Drag', action: 'pull any body' }],
  renderer: { view, balls: 'sprites' },
  onFrame: (_alpha, world) => draw(world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);

createPanel(
  params,
  [
    { type: 'choice', key: 'scene', label: 'scene', options: SCENE_NAMES, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'amplitude',
      label: 'pendulum release (°)',
      min: 5,
      max: 175,
      step: 1,
      onRelease: true,
      onChange: () => {
        if (params.scene === 'pendulum') shell.reset();
      },
    },
    { type: 'slider', key: 'motorSpeed', label: 'motor speed (rad/s)', min: -15, max: 15, step: 0.1, onChange: () => applyMotor() },
    {
      type: 'slider',
      key: 'gravity',
      label: 'gravity g (m/s²)',
      min: 0,
      max: 30,
      step: 0.01,
      onChange: (g) => {
        shell.world.gravity[1] = -(g as number);
      },
    },
    { type: 'button', key: 'reset', label: 'rebuild (R)' },
  ],
  { title: 'Joints', container: dock.panelSlot },
);
const readout = createReadout(shell.hud.readout, [
  'scene',
  'bodies / joints',
  'largest joint error',
  'pendulum period',
  'exact period',
  'speed',
]);
plot = createPlot({
  parent: dock.charts,
  title: 'Largest joint error',
  yLabel: 'mm',
  width: dock.chartWidth,
  height: 180,
  capacity: 1200,
  series: [{ label: 'anchor separation (mm)', color: '#f4a261' }],
});

/** Sets the motors of the car's wheels and the windmill to the panel's speed. */
function applyMotor(): void {
  const J = shell.world.components.Joint;
  for (const h of handles.wheels ?? []) J.motorSpeed[slotOf(h)] = -params.motorSpeed;
  if (handles.motor !== undefined) J.motorSpeed[slotOf(handles.motor)] = params.motorSpeed;
}

const drag = enableMouseDrag(
  app.canvas,
  () => shell.world,
  () => renderer.camera,
  { reach: 0.4, strength: 40 },
);

const lines = new Graphics({ label: 'joints' });
renderer.root.addChild(lines);
function draw(world: PhysicsWorld): void {
  const cam = renderer.camera,
    J = world.components.Joint,
    P = world.components.Position;
  lines.clear();
  const joints = query(world, [J]);
  for (let i = 0; i < joints.length; i++) {
    const j = joints[i]!;
    const [ax, ay, bx, by] = jointAnchors(world, handleOf(world, j));
    const a = J.a[j]!,
      b = J.b[j]!;
    const mouse = J.type[j] === 5;
    if (a !== 0) lines.moveTo(cam.toScreenX(P.x[a]!), cam.toScreenY(P.y[a]!)).lineTo(cam.toScreenX(ax), cam.toScreenY(ay));
    lines.moveTo(cam.toScreenX(bx), cam.toScreenY(by)).lineTo(cam.toScreenX(P.x[b]!), cam.toScreenY(P.y[b]!));
    if (mouse || J.type[j] === 0) lines.moveTo(cam.toScreenX(ax), cam.toScreenY(ay)).lineTo(cam.toScreenX(bx), cam.toScreenY(by));
    lines.stroke({ width: mouse ? 1.5 : 3, color: mouse ? 0xffd166 : 0xd0d6e0, alpha: mouse ? 0.9 : 0.8 });
    lines.circle(cam.toScreenX(ax), cam.toScreenY(ay), mouse ? 4 : 3).fill({ color: mouse ? 0xffd166 : 0xffffff });
  }
  // The car's chassis has no collider: draw it as a box over its wheels.
  if (handles.chassis !== undefined) {
    const e = slotOf(handles.chassis),
      t = world.components.Angle.value[e]!,
      c = Math.cos(t),
      s = Math.sin(t);
    const pts = [
      [-1.2, -0.25],
      [1.2, -0.25],
      [1.2, 0.25],
      [-1.2, 0.25],
    ].map(([x, y]) => [cam.toScreenX(P.x[e]! + c * x! - s * y!), cam.toScreenY(P.y[e]! + s * x! + c * y!)]);
    lines.poly(pts.flat()).fill({ color: 0x2a9d8f, alpha: 0.9 });
  }
  readout.set(0, params.scene);
  readout.set(1, `${query(world, [world.components.Position, world.components.Velocity]).length} / ${joints.length}`);
  readout.set(2, `${fmt(world.joints.stats.maxError * 1000)} mm`);
  readout.set(3, Number.isNaN(measure.period) ? '-' : `${fmt(measure.period)} s`);
  readout.set(4, Number.isNaN(measure.exactPeriod) ? '-' : `${fmt(measure.exactPeriod)} s`);
  const v = handles.chassis ?? handles.bob;
  readout.set(
    5,
    v === undefined ? '-' : `${fmt(Math.hypot(world.components.Velocity.x[slotOf(v)]!, world.components.Velocity.y[slotOf(v)]!))} m/s`,
  );
}

shell.expose({
  params,
  plot,
  drag,
  measure,
  /** The scene's handles. */
  ids: () => ({ ...handles }),
  /** Runs the lab's step n times (tests). */
  advance: (n: number) => {
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
});
