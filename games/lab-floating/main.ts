/**
 * Lab: floating and sinking (Ramtal and Dobre ch. 7, "upthrust"). Three balls and a box of different
 * densities drop into a tank of water; each settles where the upthrust of the water it displaces
 * equals its weight, or sinks if it is denser than the water. The plot follows the draft (immersion
 * depth) of the tracked body against the exact equilibrium draft from the circular-segment formula.
 *
 * Input: click drops a ball (density and radius from the panel). Keys: P pause, N step, R reset, E
 * places the tracked body at rest at its exact equilibrium depth.
 * URL: ?light=&medium=&heavy=&box=&fluid= (densities, kg/m^2, 10..20000), ?drag= (kg/m, 0..5000),
 * ?track=light|medium|heavy|box.
 */

import { choiceParam, createPanel, numberParam, pointerOnCanvas } from '@bitphysics/game-kit';
import { createPlotDock, createStatusLine, dashedLine, plotReserve, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPhysicsWorld, type PhysicsWorld, setPosition, setVelocity, slotOf, step } from '@bitphysics/physics';
import { Graphics, Text } from 'pixi.js';
import {
  BALL_RADIUS,
  BODY_KINDS,
  BOX_HALF,
  type BodyKind,
  buildFloating,
  DIVIDER,
  dropBall,
  equilibriumOf,
  type FloatingHandles,
  floatingWorldOptions,
  immersionDepth,
  resolveFloatingOptions,
  SURFACE,
  setBodyDensity,
  setFluidDensity,
  setFluidDrag,
  TANK,
} from './scene';

const density = (name: string, fallback: number) => numberParam(name, { default: fallback, min: 10, max: 20000 });
const params = readUrlParams(() => {
  const d = resolveFloatingOptions();
  return {
    light: density('light', d.light),
    medium: density('medium', d.medium),
    heavy: density('heavy', d.heavy),
    box: density('box', d.box),
    fluid: density('fluid', d.fluid),
    drag: numberParam('drag', { default: d.drag, min: 0, max: 5000 }),
    tracked: choiceParam('track', BODY_KINDS, 'medium') as BodyKind,
    newDensity: 800,
    newRadius: 0.4,
    equilibrium: () => placeAtEquilibrium(),
    reset: () => game.shell.reset(),
  };
});

/** Samples the plot every this many steps (60 Hz steps: 20 samples a second, a minute on screen). */
const PLOT_EVERY = 3;

let handles: FloatingHandles;

/** Builds a fresh world with the tank (start, and R). */
function createWorld(): PhysicsWorld {
  const options = {
    light: params.light,
    medium: params.medium,
    heavy: params.heavy,
    box: params.box,
    fluid: params.fluid,
    drag: params.drag,
  };
  const world = createPhysicsWorld(floatingWorldOptions(options));
  handles = buildFloating(world, options);
  return world;
}

/** One physics step, then a plot sample of the tracked body's draft and its exact equilibrium. */
function stepLab(world: PhysicsWorld): void {
  step(world);
  if (world.steps % PLOT_EVERY === 0) sample(world);
}

function sample(world: PhysicsWorld): void {
  const e = handles[params.tracked];
  plot.push(world.time, immersionDepth(world, handles, e), equilibriumOf(handles, params.tracked));
}

const game = await startPixiGame({
  title: 'Floating and sinking',
  createWorld,
  step: stepLab,
  bodies: () => handles.balls.length + 1,
  controls: [
    { keys: 'Click', action: 'drop a ball (panel: density, radius)' },
    { keys: 'E', action: 'put the tracked body at its equilibrium' },
    { keys: 'Panel', action: 'densities, fluid, drag, tracked body' },
  ],
  keys: [{ key: 'e', label: 'equilibrium', action: () => placeAtEquilibrium() }],
  // On wide windows the view reaches past the tank on the right, so the plot docked there does not cover it.
  // Above the tank, room for the divider's label.
  renderer: {
    view: { minX: TANK.minX, minY: TANK.minY, maxX: TANK.maxX + (plotReserve() > 0 ? 8 : 0), maxY: TANK.maxY + 1.4 },
    rotation: true,
  },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = game;

const dock = createPlotDock(1);
const plot = dock.add({
  title: 'Draft of the tracked body',
  yLabel: 'depth of lowest point (m)',
  series: [
    { label: 'measured draft (m)', color: '#ffd166' },
    { label: 'exact equilibrium (m)', color: '#8ecae6', dashed: true },
  ],
});

/** Colour of a body by its density relative to the fluid: light bodies pale, dense ones dark. */
function densityColor(rho: number): number {
  const t = Math.max(0, Math.min(1, rho / params.fluid / 1.6));
  const r = Math.round(250 - 170 * t),
    g = Math.round(215 - 140 * t),
    b = Math.round(140 - 40 * t);
  return (r << 16) | (g << 8) | b;
}

function recolor(): void {
  const w = shell.world;
  for (const kind of ['light', 'medium', 'heavy'] as const) renderer.setColor(handles[kind], densityColor(params[kind]));
  for (const e of handles.dropped) {
    const r = w.components.Ball.radius[slotOf(e)]!;
    renderer.setColor(e, densityColor(w.components.Mass.value[slotOf(e)]! / (Math.PI * r * r)));
  }
}
recolor();
shell.onWorldChange(() => {
  plot.clear();
  recolor();
});

/** Puts the tracked body at rest at its exact equilibrium draft (the E key, the panel button). */
function placeAtEquilibrium(): void {
  const d = equilibriumOf(handles, params.tracked);
  if (!Number.isFinite(d)) return; // it sinks: there is no floating equilibrium
  const e = handles[params.tracked];
  const extent = params.tracked === 'box' ? BOX_HALF[1] : BALL_RADIUS;
  const w = shell.world;
  setPosition(w, e, [w.components.Position.x[slotOf(e)]!, SURFACE - d + extent]);
  setVelocity(w, e, [0, 0]);
  w.components.AngularVelocity.z[slotOf(e)] = 0;
}

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'light',
      label: 'light ball ρ (kg/m²)',
      min: 10,
      max: 3000,
      step: 10,
      onChange: (v) => {
        setBodyDensity(shell.world, handles, 'light', v);
        recolor();
      },
    },
    {
      type: 'slider',
      key: 'medium',
      label: 'medium ball ρ (kg/m²)',
      min: 10,
      max: 3000,
      step: 10,
      onChange: (v) => {
        setBodyDensity(shell.world, handles, 'medium', v);
        recolor();
      },
    },
    {
      type: 'slider',
      key: 'heavy',
      label: 'heavy ball ρ (kg/m²)',
      min: 10,
      max: 3000,
      step: 10,
      onChange: (v) => {
        setBodyDensity(shell.world, handles, 'heavy', v);
        recolor();
      },
    },
    {
      type: 'slider',
      key: 'box',
      label: 'box ρ (kg/m²)',
      min: 10,
      max: 3000,
      step: 10,
      onChange: (v) => setBodyDensity(shell.world, handles, 'box', v),
    },
    {
      type: 'slider',
      key: 'fluid',
      label: 'fluid ρ (kg/m²)',
      min: 100,
      max: 3000,
      step: 10,
      onChange: (v) => {
        setFluidDensity(shell.world, handles, v);
        recolor();
      },
    },
    {
      type: 'slider',
      key: 'drag',
      label: 'fluid drag k (kg/m)',
      min: 0,
      max: 5000,
      step: 10,
      onChange: (v) => setFluidDrag(shell.world, handles, v),
    },
    { type: 'choice', key: 'tracked', label: 'tracked body', options: BODY_KINDS, onChange: () => plot.clear() },
    { type: 'slider', key: 'newDensity', label: 'new ball ρ (kg/m²)', min: 10, max: 3000, step: 10 },
    { type: 'slider', key: 'newRadius', label: 'new ball radius (m)', min: 0.15, max: 1, step: 0.01 },
    { type: 'button', key: 'equilibrium', label: 'place at equilibrium (E)' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Floating' },
);

// ---- Drawing: the box, the water over everything, the tracked body's equilibrium mark -------------

const boxLayer = new Graphics({ label: 'box' });
const water = new Graphics({ label: 'water' });
const marks = new Graphics({ label: 'marks' });
app.stage.addChild(boxLayer, water, marks);
const labelStyle = { fill: 0xe8ecf1, fontSize: 12, fontFamily: 'system-ui, sans-serif', align: 'center' as const };
const labels = new Map<BodyKind, Text>(BODY_KINDS.map((k) => [k, new Text({ text: '', style: labelStyle })]));
for (const t of labels.values()) {
  t.anchor.set(0.5, 1);
  app.stage.addChild(t);
}
// The pole between the box and the balls: the box has no collider (it cannot touch the balls), so a
// divider keeps it in a compartment of its own.
const dividerLabel = new Text({
  text: 'divider: keeps the box\n(no collider) on its side',
  style: { ...labelStyle, fontSize: 11, fill: 0x98a2b3, align: 'center' },
});
dividerLabel.anchor.set(0.5, 1);
app.stage.addChild(dividerLabel);
const shownDensity = new Map<BodyKind, number>();
const status = createStatusLine();
let frame = 0;

function draw(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  const P = world.components.Position,
    O = world.components.PreviousPosition;
  const lerpX = (e: number) => O.x[slotOf(e)]! + (P.x[slotOf(e)]! - O.x[slotOf(e)]!) * alpha;
  const lerpY = (e: number) => O.y[slotOf(e)]! + (P.y[slotOf(e)]! - O.y[slotOf(e)]!) * alpha;
  // Box (no collider, so the world renderer does not draw it).
  const b = handles.box;
  const bx = cam.toScreenX(lerpX(b) - BOX_HALF[0]),
    by = cam.toScreenY(lerpY(b) + BOX_HALF[1]);
  const bw = cam.toScreenLength(2 * BOX_HALF[0]),
    bh = cam.toScreenLength(2 * BOX_HALF[1]);
  boxLayer
    .clear()
    .rect(bx, by, bw, bh)
    .fill({ color: densityColor(params.box) })
    .stroke({ width: 1.5, color: 0x3a3020 });
  // Water: translucent, over the bodies, so what is submerged looks submerged.
  const wx = cam.toScreenX(TANK.minX),
    wy = cam.toScreenY(SURFACE);
  const ww = cam.toScreenLength(TANK.maxX - TANK.minX),
    wh = cam.toScreenLength(SURFACE - TANK.minY);
  water
    .clear()
    .rect(wx, wy, ww, wh)
    .fill({ color: 0x2a7fd4, alpha: 0.33 })
    .moveTo(wx, wy)
    .lineTo(wx + ww, wy)
    .stroke({ width: 2, color: 0x8ecae6, alpha: 0.9 });
  // Tracked body: a ring, and a dashed line where its lowest point sits at equilibrium.
  const e = handles[params.tracked];
  const ex = lerpX(e),
    ey = lerpY(e);
  const halfW = params.tracked === 'box' ? BOX_HALF[0] : BALL_RADIUS;
  const extent = params.tracked === 'box' ? BOX_HALF[1] : BALL_RADIUS;
  marks.clear();
  if (params.tracked === 'box') marks.rect(bx - 3, by - 3, bw + 6, bh + 6).stroke({ width: 2, color: 0xffd166 });
  else marks.circle(cam.toScreenX(ex), cam.toScreenY(ey), cam.toScreenLength(extent) + 3).stroke({ width: 2, color: 0xffd166 });
  const d = equilibriumOf(handles, params.tracked);
  if (Number.isFinite(d)) {
    const yEq = cam.toScreenY(SURFACE - d);
    dashedLine(marks, cam.toScreenX(ex - halfW - 0.35), yEq, cam.toScreenX(ex + halfW + 0.35), yEq, 5, 4).stroke({
      width: 2,
      color: 0x8ecae6,
    });
  }
  if (++frame % 10 === 1) {
    const ratio = (params[params.tracked] / params.fluid).toFixed(3);
    status.set(
      `tracked: ${params.tracked} · ρ/ρ_fluid = ${ratio} · draft ${immersionDepth(world, handles, e).toFixed(3)} m · ` +
        (Number.isFinite(d) ? `equilibrium ${d.toFixed(3)} m` : 'denser than the fluid: it sinks'),
    );
  }
  // Density labels above the starting bodies: on one line, or on two ('box' over '500 kg/m²') when
  // the box's label is wider than its compartment (a phone's scale).
  const compartment = cam.toScreenLength(DIVIDER.x - TANK.minX) - 6;
  if (shownCompartment !== compartment) {
    shownCompartment = compartment;
    const box = labels.get('box')!;
    box.text = `box ${params.box} kg/m²`;
    twoLineLabels = box.width > compartment;
    shownDensity.clear();
  }
  for (const kind of BODY_KINDS) {
    const rho = params[kind];
    if (shownDensity.get(kind) === rho) continue;
    shownDensity.set(kind, rho);
    labels.get(kind)!.text = `${kind}${twoLineLabels ? '\n' : ' '}${rho} kg/m²`;
  }
  // The divider's label above the tank, where no body goes, joined to the pole's top by a dotted
  // line; placed last, so it is lifted over a density label in its way rather than the other way round.
  const poleX = cam.toScreenX(DIVIDER.x);
  placeLabels([
    ...BODY_KINDS.map((kind) => {
      const id = handles[kind];
      const top = kind === 'box' ? BOX_HALF[1] : BALL_RADIUS;
      return { t: labels.get(kind)!, x: cam.toScreenX(lerpX(id)), y: cam.toScreenY(lerpY(id) + top) - 4 };
    }),
    { t: dividerLabel, x: poleX, y: cam.toScreenY(TANK.maxY) - 6, last: true },
  ]);
  dashedLine(marks, poleX, cam.toScreenY(DIVIDER.top) - 3, poleX, dividerLabel.y + 2, 2, 3).stroke({
    width: 1,
    color: 0x98a2b3,
    alpha: 0.8,
  });
}

/** Whether the density labels are on two lines, and the box compartment's width (px) that was decided for. */
let twoLineLabels = false;
let shownCompartment = Number.NaN;

/** Gap kept between two labels, px. */
const LABEL_GAP = 2;

/**
 * Puts each label (anchored at its bottom centre) at its wanted point or, where it would overlap one
 * already placed, just above what it overlaps. The lowest wanted points on screen go first (those
 * marked `last` after all the others), so a label is only ever lifted, never pushed onto its body.
 */
function placeLabels(wanted: { t: Text; x: number; y: number; last?: boolean }[]): void {
  const boxOf = (t: Text, x: number, y: number) => ({ left: x - t.width / 2, right: x + t.width / 2, top: y - t.height, bottom: y });
  const placed: ReturnType<typeof boxOf>[] = [];
  const order = [...wanted].sort((a, b) => Number(a.last ?? false) - Number(b.last ?? false) || b.y - a.y);
  for (const w of order) {
    let y = w.y;
    for (let moved = true, n = 0; moved && n < 8; n++) {
      moved = false;
      const me = boxOf(w.t, w.x, y);
      for (const o of placed) {
        if (
          me.left < o.right + LABEL_GAP &&
          o.left < me.right + LABEL_GAP &&
          me.top < o.bottom + LABEL_GAP &&
          o.top < me.bottom + LABEL_GAP
        ) {
          y = o.top - LABEL_GAP;
          moved = true;
          break;
        }
      }
    }
    w.t.position.set(w.x, y);
    placed.push(boxOf(w.t, w.x, y));
  }
}

// ---- Pointer: a click drops a ball -------------------------------------------------------------

const canvas = app.canvas;
const pointer = { x: 0, y: 0 };
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  pointerOnCanvas(canvas, event, pointer);
  const cam = renderer.camera;
  const e = dropBall(shell.world, handles, cam.toWorldX(pointer.x), cam.toWorldY(pointer.y), params.newDensity, params.newRadius);
  renderer.setColor(e, densityColor(params.newDensity));
});

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** The scene's handles (entity ids). */
  handles: (): FloatingHandles => handles,
  /** Draft of body `kind` now, m. */
  draft: (kind: BodyKind): number => immersionDepth(shell.world, handles, handles[kind]),
  /** Exact equilibrium draft of body `kind`, m (NaN if it sinks). */
  equilibrium: (kind: BodyKind): number => equilibriumOf(handles, kind),
  /** Screen boxes (canvas px) of the divider's and the density labels, as last drawn: [name, left, top, right, bottom]. */
  labelBoxes: (): [string, number, number, number, number][] =>
    [['divider', dividerLabel] as const, ...BODY_KINDS.map((k) => [k, labels.get(k)!] as const)].map(([name, t]) => {
      const b = t.getBounds();
      return [name, b.minX, b.minY, b.maxX, b.maxY];
    }),
  /** Puts the tracked body at rest at its exact equilibrium. */
  placeAtEquilibrium,
  /** Drops a ball at (x, y), m; returns its id. */
  drop: (x: number, y: number, rho = params.newDensity, r = params.newRadius): number => dropBall(shell.world, handles, x, y, rho, r),
  /** Runs `n` steps now (with plot samples), paused or not. @throws RangeError unless n is an integer in [0, 100000]. */
  advance: (n: number): void => {
    if (!(Number.isInteger(n) && n >= 0 && n <= 100_000)) throw new RangeError(`advance: n must be an integer in [0, 100000], got ${n}`);
    for (let i = 0; i < n; i++) stepLab(shell.world);
  },
});
