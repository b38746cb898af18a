/**
 * Lab: electric field (Ramtal and Dobre ch. 10). Fixed point charges, their field lines traced
 * through the Coulomb field, and a free test charge moving under the physics' Coulomb law. The plot
 * shows the test charge's energy (kinetic + electric potential) against its exact, constant value.
 *
 * Input: click places a + charge, Shift-click a - charge, drag moves a charge (or the test charge),
 * right-click removes a charge; clicking a charge selects it for the panel's charge slider.
 * Keys: P pause, N step, R reset, L relaunch the test charge, F field lines on / off.
 * URL: ?preset=dipole|like pair|quadrupole|single|none, ?q= (preset charge, uC, 0.1..20),
 * ?test= (test charge, uC, -10..10), ?mass= (g, 0.01..1000), ?softening= (m, 0..2),
 * ?integrator=<name>, ?substeps= (1..64), ?lines=0|1.
 */

import { choiceParam, createPanel, flagParam, numberParam, plural, pointerOnCanvas } from '@bitphysics/game-kit';
import { createPlotDock, createStatusLine, plotReserve, readUrlParams, scaleFloor, scaleSeries } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import {
  createPhysicsWorld,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  setPosition,
  setVelocity,
  slotOf,
  step,
} from '@bitphysics/physics';
import { Graphics, Text } from 'pixi.js';
import {
  addCharge,
  BOX,
  buildElectric,
  createFieldLines,
  type ElectricHandles,
  electricWorldOptions,
  hasRoom,
  MAX_CHARGES,
  MICRO,
  moveCharge,
  PRESETS,
  type Preset,
  rebaseline,
  relaunch,
  removeCharge,
  setChargeValue,
  setSoftening,
  setTestCharge,
  TEST_RADIUS,
  testEnergy,
  traceFieldLines,
} from './scene';

const params = readUrlParams(() => ({
  preset: choiceParam('preset', PRESETS, 'dipole') as Preset,
  sourceCharge: numberParam('q', { default: 2, min: 0.1, max: 20 }),
  selected: 2,
  testCharge: numberParam('test', { default: 0.5, min: -10, max: 10 }),
  testMass: numberParam('mass', { default: 1, min: 0.01, max: 1000 }),
  softening: numberParam('softening', { default: 0.2, min: 0, max: 2 }),
  integrator: choiceParam('integrator', INTEGRATOR_NAMES, 'rk4') as IntegratorName,
  substeps: numberParam('substeps', { default: 8, min: 1, max: 64, integer: true }),
  lines: new URLSearchParams(location.search).has('lines') ? flagParam('lines') : true,
  relaunch: () => relaunchTest(),
  clear: () => clearCharges(),
  reset: () => game.shell.reset(),
}));

const PLOT_EVERY = 2;
/** The energy plot's y axis spans at least E0 +- 5%. */
const BAND = 0.05;
let handles!: ElectricHandles;
let selected = 0;

function createWorld(): PhysicsWorld {
  const options = {
    preset: params.preset,
    sourceCharge: params.sourceCharge,
    testCharge: params.testCharge,
    testMass: params.testMass,
    softening: params.softening,
    integrator: params.integrator,
    substeps: params.substeps,
  };
  const world = createPhysicsWorld(electricWorldOptions(options));
  handles = buildElectric(world, options);
  selected = handles.charges[0] ?? 0;
  fieldDirty = true;
  return world;
}

function stepLab(world: PhysicsWorld): void {
  step(world);
  if (world.steps % PLOT_EVERY === 0) {
    const e0 = handles.initialEnergy * 1e3;
    plot.push(world.time, testEnergy(world, handles) * 1e3, e0, scaleFloor(e0, BAND, world.steps / PLOT_EVERY));
  }
}

let fieldDirty = true;

const game = await startPixiGame({
  title: 'Electric field',
  createWorld,
  step: stepLab,
  bodies: () => handles.charges.length + 1,
  controls: [
    { keys: 'Click', action: 'place a + charge' },
    { keys: 'Shift-click', action: 'place a − charge' },
    { keys: 'Drag', action: 'move a charge or the test charge' },
    { keys: 'Right-click', action: 'remove a charge' },
    { keys: 'L', action: 'relaunch the test charge' },
    { keys: 'F', action: 'field lines on / off' },
  ],
  keys: [
    { key: 'l', label: 'relaunch', action: () => relaunchTest() },
    {
      key: 'f',
      label: 'field lines',
      action: () => {
        params.lines = !params.lines;
        panel.refresh();
      },
    },
  ],
  // On wide windows the view reaches 9 m right of the box so the plot docked bottom right leaves the box in view.
  renderer: { view: { minX: BOX.minX, minY: BOX.minY, maxX: BOX.maxX + (plotReserve() > 0 ? 9 : 0), maxY: BOX.maxY }, rotation: false },
  onFrame: () => draw(),
});
const { shell, renderer, app } = game;

const dock = createPlotDock(1);
const plot = dock.add({
  title: 'Test charge: energy (kinetic + electric potential)',
  yLabel: 'energy (mJ)',
  series: [
    { label: 'measured K + U (mJ)', color: '#ffd166' },
    { label: 'exact: constant (mJ)', color: '#8ecae6', dashed: true },
    scaleSeries(BAND),
  ],
});

renderer.setColor(handles.test, 0xffd166);
shell.onWorldChange(() => {
  plot.clear();
  renderer.setColor(handles.test, 0xffd166);
});

/** The field or the test charge changed by hand: new exact energy, retrace the lines, restart the plot. */
function changed(): void {
  rebaseline(shell.world, handles);
  fieldDirty = true;
  plot.clear();
}

function relaunchTest(): void {
  relaunch(shell.world, handles);
  changed();
}

function clearCharges(): void {
  for (const e of handles.charges.slice()) removeCharge(shell.world, handles, e);
  selected = 0;
  changed();
}

const panel = createPanel(
  params,
  [
    { type: 'choice', key: 'preset', options: PRESETS, onChange: () => shell.reset() },
    { type: 'slider', key: 'sourceCharge', label: 'new charge |q| (µC)', min: 0.1, max: 20, step: 0.1 },
    {
      type: 'slider',
      key: 'selected',
      label: 'selected charge q (µC)',
      min: -20,
      max: 20,
      step: 0.1,
      onChange: (v) => {
        if (selected === 0 || v === 0) return;
        setChargeValue(shell.world, handles, selected, v);
        changed();
      },
    },
    {
      type: 'slider',
      key: 'testCharge',
      label: 'test charge (µC)',
      min: -10,
      max: 10,
      step: 0.1,
      onChange: (v) => {
        setTestCharge(shell.world, handles, v);
        changed();
      },
    },
    {
      type: 'slider',
      key: 'testMass',
      label: 'test mass (g, resets)',
      min: 0.01,
      max: 20,
      step: 0.01,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'softening',
      label: 'softening (m)',
      min: 0,
      max: 2,
      step: 0.01,
      onChange: (v) => {
        setSoftening(shell.world, handles, v);
        changed();
      },
    },
    { type: 'choice', key: 'integrator', options: INTEGRATOR_NAMES, onChange: () => shell.reset() },
    {
      type: 'slider',
      key: 'substeps',
      label: 'substeps (resets)',
      min: 1,
      max: 32,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'lines', label: 'field lines (F)' },
    { type: 'button', key: 'relaunch', label: 'relaunch test charge (L)' },
    { type: 'button', key: 'clear', label: 'remove all charges' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Electric field' },
);

function select(eid: number): void {
  selected = eid;
  params.selected = Math.round((shell.world.components.Charge.value[slotOf(eid)]! / MICRO) * 10) / 10;
  panel.refresh();
}

// ---- Drawing: field lines (retraced when the field changes), charges, selection ---------------------

const lines = createFieldLines();
const lineLayer = new Graphics({ label: 'field-lines' });
const chargeLayer = new Graphics({ label: 'charges' });
app.stage.addChildAt(lineLayer, 0);
app.stage.addChild(chargeLayer);
const signStyle = { fill: 0xffffff, fontSize: 15, fontWeight: 'bold' as const, fontFamily: 'system-ui, sans-serif' };
const signs: Text[] = Array.from({ length: MAX_CHARGES }, () => {
  const t = new Text({ text: '', style: signStyle });
  t.anchor.set(0.5, 0.55);
  app.stage.addChild(t);
  return t;
});
let cameraVersion = -1;

function drawFieldLines(): void {
  const world = shell.world,
    cam = renderer.camera;
  lineLayer.clear();
  if (!params.lines) return;
  traceFieldLines(world, handles, lines);
  const xy = lines.xy,
    start = lines.start;
  for (let k = 0; k < lines.count; k++) {
    const a = start[k]!,
      b = start[k + 1]!;
    if (b - a < 2) continue;
    lineLayer.moveTo(cam.toScreenX(xy[2 * a]!), cam.toScreenY(xy[2 * a + 1]!));
    for (let i = a + 1; i < b; i++) lineLayer.lineTo(cam.toScreenX(xy[2 * i]!), cam.toScreenY(xy[2 * i + 1]!));
  }
  lineLayer.stroke({ width: 1.2, color: 0x8ecae6, alpha: 0.55 });
  // An arrowhead a third of the way along each line, pointing along the field.
  for (let k = 0; k < lines.count; k++) {
    const a = start[k]!,
      b = start[k + 1]!;
    if (b - a < 8) continue;
    let i = a + Math.floor((b - a) / 3);
    const x0 = cam.toScreenX(xy[2 * i]!),
      y0 = cam.toScreenY(xy[2 * i + 1]!);
    i += 2;
    const x1 = cam.toScreenX(xy[2 * i]!),
      y1 = cam.toScreenY(xy[2 * i + 1]!);
    // Lines traced from negative charges run against the field: point the arrow the other way.
    const first = xy[2 * a]!,
      firstY = xy[2 * a + 1]!;
    let fromNegative = false;
    for (const c of handles.charges) {
      const P = world.components.Position;
      if (Math.hypot(first - P.x[slotOf(c)]!, firstY - P.y[slotOf(c)]!) < 0.2) {
        fromNegative = world.components.Charge.value[slotOf(c)]! < 0;
        break;
      }
    }
    let dx = x1 - x0,
      dy = y1 - y0;
    const n = Math.hypot(dx, dy) || 1;
    dx /= n;
    dy /= n;
    if (fromNegative) {
      dx = -dx;
      dy = -dy;
    }
    const s = 6;
    lineLayer
      .moveTo(x1 + dx * s, y1 + dy * s)
      .lineTo(x1 - dx * s - dy * s * 0.6, y1 - dy * s + dx * s * 0.6)
      .lineTo(x1 - dx * s + dy * s * 0.6, y1 - dy * s - dx * s * 0.6)
      .closePath()
      .fill({ color: 0x8ecae6, alpha: 0.7 });
  }
}

const status = createStatusLine();
let frame = 0;

let linesShown = params.lines;
function draw(): void {
  const world = shell.world,
    cam = renderer.camera;
  if (++frame % 10 === 1) {
    const e = testEnergy(world, handles),
      e0 = handles.initialEnergy;
    status.set(
      `test charge energy ${(e * 1e3).toFixed(4)} mJ · exact ${(e0 * 1e3).toFixed(4)} mJ · ` +
        `relative drift ${(Math.abs(e - e0) / Math.abs(e0 || 1)).toExponential(1)} · ${params.integrator}, ${plural(params.substeps, 'substep', 'substeps')}`,
    );
  }
  if (fieldDirty || cam.version !== cameraVersion || linesShown !== params.lines) {
    drawFieldLines();
    fieldDirty = false;
    cameraVersion = cam.version;
    linesShown = params.lines;
  }
  chargeLayer.clear();
  const P = world.components.Position,
    Q = world.components.Charge.value;
  const r = Math.max(8, cam.toScreenLength(0.22));
  const charges = handles.charges;
  for (let i = 0; i < charges.length; i++) {
    const c = charges[i]!;
    const x = cam.toScreenX(P.x[slotOf(c)]!),
      y = cam.toScreenY(P.y[slotOf(c)]!),
      q = Q[slotOf(c)]! / MICRO;
    const rr = r * (0.8 + 0.2 * Math.min(3, Math.sqrt(Math.abs(q))));
    chargeLayer.circle(x, y, rr).fill({ color: q > 0 ? 0xe63946 : 0x3a86ff });
    if (c === selected) chargeLayer.circle(x, y, rr + 4).stroke({ width: 2, color: 0xffd166 });
    const t = signs[i]!;
    const text = q > 0 ? '+' : '−';
    if (t.text !== text) t.text = text;
    t.position.set(x, y);
    t.visible = true;
  }
  for (let i = charges.length; i < signs.length; i++) signs[i]!.visible = false;
}

// ---- Pointer: click places, Shift-click places negative, drag moves, right-click removes ---------------

const canvas = app.canvas;
const pointer = { x: 0, y: 0 };
let dragging = 0; // entity being dragged (a fixed charge or the test charge), 0 none
let pressed = false,
  moved = false,
  shiftDown = false;
let pressX = 0,
  pressY = 0;

/** The fixed charge (or the test charge) within 0.35 m of screen point (sx, sy), or 0. */
function pick(sx: number, sy: number): number {
  const cam = renderer.camera,
    P = shell.world.components.Position;
  const x = cam.toWorldX(sx),
    y = cam.toWorldY(sy);
  const reach = Math.max(0.35, cam.toWorldX(sx + 12) - x);
  let best = 0,
    bestD = reach;
  for (const e of [...handles.charges, handles.test]) {
    const d = Math.hypot(P.x[slotOf(e)]! - x, P.y[slotOf(e)]! - y);
    if (d < bestD) {
      best = e;
      bestD = d;
    }
  }
  return best;
}

canvas.addEventListener('contextmenu', (event) => event.preventDefault());
canvas.addEventListener('pointerdown', (event) => {
  pointerOnCanvas(canvas, event, pointer);
  const hit = pick(pointer.x, pointer.y);
  if (event.button === 2) {
    if (hit !== 0 && hit !== handles.test) {
      removeCharge(shell.world, handles, hit);
      if (selected === hit) selected = 0;
      changed();
    }
    return;
  }
  if (event.button !== 0) return;
  canvas.setPointerCapture(event.pointerId);
  pressed = true;
  moved = false;
  shiftDown = event.shiftKey;
  pressX = pointer.x;
  pressY = pointer.y;
  dragging = hit;
  if (hit !== 0 && hit !== handles.test) select(hit);
});

canvas.addEventListener('pointermove', (event) => {
  if (!pressed) return;
  pointerOnCanvas(canvas, event, pointer);
  if (Math.hypot(pointer.x - pressX, pointer.y - pressY) > 5) moved = true;
  if (!moved || dragging === 0) return;
  const cam = renderer.camera,
    w = shell.world;
  const x = cam.toWorldX(pointer.x),
    y = cam.toWorldY(pointer.y);
  if (dragging === handles.test) {
    const r = TEST_RADIUS;
    setPosition(w, dragging, [Math.min(BOX.maxX - r, Math.max(BOX.minX + r, x)), Math.min(BOX.maxY - r, Math.max(BOX.minY + r, y))]);
    setVelocity(w, dragging, [0, 0]);
  } else {
    moveCharge(w, handles, dragging, x, y);
  }
  changed();
});

canvas.addEventListener('pointerup', (event) => {
  if (!pressed) return;
  pressed = false;
  pointerOnCanvas(canvas, event, pointer);
  if (!moved && dragging === 0 && hasRoom(shell.world, handles)) {
    const cam = renderer.camera;
    const x = cam.toWorldX(pointer.x),
      y = cam.toWorldY(pointer.y);
    if (x >= BOX.minX && x <= BOX.maxX && y >= BOX.minY && y <= BOX.maxY) {
      const e = addCharge(shell.world, handles, x, y, (shiftDown || event.shiftKey ? -1 : 1) * params.sourceCharge);
      select(e);
      changed();
    }
  }
  dragging = 0;
});
canvas.addEventListener('pointercancel', () => {
  pressed = false;
  dragging = 0;
});

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** The scene handles. */
  handles: (): ElectricHandles => handles,
  /** Fixed charges as [x m, y m, q uC] triples. */
  charges: (): [number, number, number][] => {
    const P = shell.world.components.Position,
      Q = shell.world.components.Charge.value;
    return handles.charges.map((e) => [P.x[slotOf(e)]!, P.y[slotOf(e)]!, Q[slotOf(e)]! / MICRO]);
  },
  /** Places a fixed charge of q uC at (x, y) m; returns its id. */
  place: (x: number, y: number, q: number): number => {
    const e = addCharge(shell.world, handles, x, y, q);
    changed();
    return e;
  },
  /** The test charge's energy now and its exact value, J. */
  energy: (): { measured: number; exact: number } => ({ measured: testEnergy(shell.world, handles), exact: handles.initialEnergy }),
  /** Field lines traced in the last redraw. */
  fieldLineCount: (): number => (params.lines ? lines.count : 0),
  /** Relaunches the test charge. */
  relaunch: relaunchTest,
  /** Runs `n` steps now (with plot samples). @throws RangeError unless n is an integer in [0, 100000]. */
  advance: (n: number): void => {
    if (!(Number.isInteger(n) && n >= 0 && n <= 100_000)) throw new RangeError(`advance: n must be an integer in [0, 100000], got ${n}`);
    for (let i = 0; i < n; i++) stepLab(shell.world);
  },
});
