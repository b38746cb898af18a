/**
 * Lab: balloon and parachute (Ramtal and Dobre ch. 7: upthrust, drag, terminal velocity, wind).
 *
 * Scene "parachute": a parachutist jumps from rest and falls with quadratic drag against the wind; O
 * (or a click) pulls the ripcord and the drag coefficient rises from k_closed to k_open over the
 * opening time. The plot shows the descent speed against the terminal speeds sqrt(m g / k) before and
 * after opening and, in still air, the exact fall from rest v_t tanh(g t / v_t).
 * Scene "balloon": a helium balloon rises through an exponential (scaled) atmosphere built from fluid
 * layers and stops where the air it displaces weighs as much as it does; T (or a click) ties or cuts
 * its tether. The plot shows its height against the exact equilibrium height.
 *
 * Keys: P pause, N step, R reset, O open chute, T tether. URL: ?scene=parachute|balloon and any
 * numeric option of the scene (jumperMass, jumpAltitude, kClosed, kOpen, wind, turbulence,
 * balloonRadius, envelopeMass, scaleHeight, tetherLength), ?openingTime= (s, 0..10),
 * ?autoOpen= (m, 0..5000; 0 off), ?tethered.
 */

import { choiceParam, createPanel, flagParam, numberParam, type Panel, type PanelControl } from '@bitphysics/game-kit';
import { createPlotDock, createStatusLine, dashedLine, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import type { Plot } from '@bitphysics/game-kit/plot';
import { createPhysicsWorld, type PhysicsWorld, setMass, slotOf, step } from '@bitphysics/physics';
import { Graphics, Text } from 'pixi.js';
import {
  airDensity,
  applyWind,
  type BalloonHandles,
  balloonMass,
  buildBalloon,
  buildParachute,
  equilibriumAltitude,
  fallSpeedFromRest,
  type Handles,
  JUMPER_RADIUS,
  openChute,
  type ParachuteHandles,
  rangeOf,
  resolveOptions,
  SCENES,
  type SceneName,
  setTether,
  terminalSpeed,
  updateChute,
  worldOptions,
} from './scene';

type NumericOption = Parameters<typeof rangeOf>[0];
const NUMERIC: readonly NumericOption[] = [
  'jumperMass',
  'jumpAltitude',
  'kClosed',
  'kOpen',
  'wind',
  'turbulence',
  'balloonRadius',
  'envelopeMass',
  'scaleHeight',
  'tetherLength',
];

const params = readUrlParams(() => {
  const d = resolveOptions();
  const numbers = {} as Record<NumericOption, number>;
  for (const k of NUMERIC) {
    const [min, max] = rangeOf(k);
    numbers[k] = numberParam(k, { default: d[k], min, max });
  }
  return {
    scene: choiceParam('scene', SCENES, 'parachute') as SceneName,
    ...numbers,
    tethered: flagParam('tethered'),
    openingTime: numberParam('openingTime', { default: 2.5, min: 0, max: 10 }),
    autoOpen: numberParam('autoOpen', { default: 400, min: 0, max: 5000 }),
    zoom: numberParam('zoom', { default: 12, min: 1, max: 60 }),
    open: () => pullRipcord(),
    reset: () => game.shell.reset(),
  };
});

/** Plot sample every this many steps (20 a second). */
const PLOT_EVERY = 3;

let handles: Handles;

/** The scene options from the panel's params. */
function sceneOptions() {
  const o: Record<string, number | boolean> = { tethered: params.tethered };
  for (const k of NUMERIC) o[k] = params[k];
  return resolveOptions(o);
}

function createWorld(): PhysicsWorld {
  const options = sceneOptions();
  const world = createPhysicsWorld(worldOptions(params.scene, options));
  handles = params.scene === 'parachute' ? buildParachute(world, options) : buildBalloon(world, options);
  return world;
}

/** One step: the chute rule (parachute scene), physics, a plot sample. */
function stepLab(world: PhysicsWorld): void {
  if (handles.scene === 'parachute') updateChute(world, handles, params.openingTime, params.autoOpen);
  step(world);
  if (world.steps % PLOT_EVERY === 0) sample(world);
}

function sample(world: PhysicsWorld): void {
  const V = world.components.Velocity,
    P = world.components.Position;
  if (handles.scene === 'parachute') {
    const h = handles,
      p = h.params,
      m = world.components.Mass.value[slotOf(h.jumper)]!;
    const vt1 = terminalSpeed(m, p.kClosed),
      vt2 = terminalSpeed(m, p.kOpen);
    const still = p.wind === 0 && p.turbulence === 0 && Number.isNaN(h.openedAt);
    plot.push(world.time, -V.y[slotOf(h.jumper)]!, vt1, vt2, still ? fallSpeedFromRest(world.time, vt1) : Number.NaN);
  } else {
    const h = handles;
    plot.push(world.time, P.y[slotOf(h.balloon)]!, equilibriumAltitude(h.params));
  }
}

const game = await startPixiGame({
  title: 'Balloon and parachute',
  createWorld,
  step: stepLab,
  bodies: () => 1,
  controls: [
    { keys: 'O / Click', action: 'open the parachute (parachute scene)' },
    { keys: 'T / Click', action: 'tie / cut the tether (balloon scene)' },
    { keys: 'Panel', action: 'scene, masses, drag, wind, turbulence' },
  ],
  keys: [
    { key: 'o', label: 'open chute', action: () => pullRipcord() },
    { key: 't', label: 'tether', action: () => toggleTether() },
  ],
  renderer: { pixelsPerMeter: params.zoom, rotation: false, boundaryColor: 0x4a5a3a },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = game;

// ---- Plot (one per scene) ---------------------------------------------------------------------------

const dock = createPlotDock(1);
let plotScene: SceneName = params.scene;
let plot: Plot = makePlot(params.scene);

function makePlot(scene: SceneName): Plot {
  return scene === 'parachute'
    ? dock.add({
        title: 'Parachutist: descent speed',
        yLabel: 'speed (m/s)',
        series: [
          { label: 'descent speed (m/s)', color: '#ffd166' },
          { label: 'v_t closed', color: '#ef476f', dashed: true },
          { label: 'v_t open', color: '#06d6a0', dashed: true },
          { label: 'exact fall (still air)', color: '#8ecae6', dashed: true },
        ],
      })
    : dock.add({
        title: 'Balloon: height',
        yLabel: 'height (m)',
        series: [
          { label: 'height (m)', color: '#ffd166' },
          { label: 'exact equilibrium (m)', color: '#8ecae6', dashed: true },
        ],
      });
}

// ---- Panel (one per scene) --------------------------------------------------------------------------

type Params = typeof params;
const slider = (
  key: NumericOption | 'openingTime' | 'autoOpen' | 'zoom',
  label: string,
  onChange?: (v: number) => void,
  onRelease = false,
): PanelControl<Params> => {
  const [min, max] = key === 'openingTime' ? [0, 10] : key === 'autoOpen' ? [0, 3000] : key === 'zoom' ? [1, 60] : rangeOf(key);
  const step = 10 ** Math.floor(Math.log10((max - min) / 200));
  return { type: 'slider', key, label, min, max, step, ...(onChange ? { onChange } : {}), onRelease };
};

function controlsFor(scene: SceneName): PanelControl<Params>[] {
  const common: PanelControl<Params>[] = [
    { type: 'choice', key: 'scene', options: SCENES, onChange: () => shell.reset() },
    slider('wind', 'wind (m/s)', () => applyWind(shell.world, syncParams())),
    slider('turbulence', 'turbulence rms (m/s)', () => applyWind(shell.world, syncParams())),
    slider('zoom', 'zoom (px/m)'),
  ];
  const tail: PanelControl<Params>[] = [{ type: 'button', key: 'reset', label: 'reset (R)' }];
  if (scene === 'parachute') {
    return [
      ...common,
      slider('jumperMass', 'mass (kg)', (m) => {
        syncParams();
        if (handles.scene === 'parachute') setMass(shell.world, handles.jumper, m);
      }),
      slider('jumpAltitude', 'jump altitude (m, resets)', () => shell.reset(), true),
      slider('kClosed', 'k closed (kg/m)', () => syncParams()),
      slider('kOpen', 'k open (kg/m)', () => syncParams()),
      slider('openingTime', 'opening time (s)'),
      slider('autoOpen', 'auto-open below (m, 0 off)'),
      { type: 'button', key: 'open', label: 'open chute (O)' },
      ...tail,
    ];
  }
  return [
    ...common,
    slider('balloonRadius', 'balloon radius (m, resets)', () => shell.reset(), true),
    slider('envelopeMass', 'envelope + payload (kg)', () => {
      const p = syncParams();
      if (handles.scene === 'balloon') setMass(shell.world, handles.balloon, balloonMass(p));
    }),
    slider('scaleHeight', 'scale height H (m, resets)', () => shell.reset(), true),
    { type: 'checkbox', key: 'tethered', label: 'tethered (T)', onChange: (v) => setTethered(v === true) },
    slider('tetherLength', 'tether length (m)', (L) => {
      syncParams();
      if (handles.scene === 'balloon' && handles.tether !== 0) shell.world.components.Spring.restLength[slotOf(handles.tether)] = L;
    }),
    ...tail,
  ];
}

/** Copies the panel's scene options into the scene handles (which the rules read) and returns them. */
function syncParams() {
  const p = handles.params;
  for (const k of NUMERIC) p[k] = params[k];
  p.tethered = params.tethered;
  return p;
}

let panel: Panel<Params> = createPanel(params, controlsFor(params.scene), { title: 'Balloon and parachute' });

/** The balloon is red, the parachutist white. */
function colorSubject(): void {
  if (handles.scene === 'balloon') renderer.setColor(handles.balloon, 0xef476f);
  else renderer.setColor(handles.jumper, 0xe8ecf1);
}
colorSubject();

shell.onWorldChange(() => {
  colorSubject();
  if (plotScene !== params.scene) {
    plot.destroy();
    plot = makePlot(params.scene);
    panel.destroy();
    panel = createPanel(params, controlsFor(params.scene), { title: 'Balloon and parachute' });
    plotScene = params.scene;
    shell.expose({ plot, panel });
  } else {
    plot.clear();
  }
});

// ---- Input -------------------------------------------------------------------------------------------

/** Opens the parachute now (the O key, a click, the panel button). @returns whether it opened. */
function pullRipcord(): boolean {
  return handles.scene === 'parachute' ? openChute(shell.world, handles) : false;
}

/** Ties (true) or cuts (false) the balloon's tether. */
function setTethered(on: boolean): void {
  params.tethered = on;
  if (handles.scene === 'balloon') setTether(shell.world, handles, on);
  panel.refresh();
}

function toggleTether(): void {
  if (handles.scene === 'balloon') setTethered(handles.tether === 0);
}

app.canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  if (handles.scene === 'parachute') pullRipcord();
  else toggleTether();
});

// ---- Drawing -----------------------------------------------------------------------------------------

const sky = new Graphics({ label: 'sky' });
const grid = new Graphics({ label: 'grid' });
const overlay = new Graphics({ label: 'overlay' });
app.stage.addChildAt(sky, 0);
app.stage.addChildAt(grid, 1);
app.stage.addChild(overlay);
const tickStyle = { fill: 0x98a2b3, fontSize: 11, fontFamily: 'ui-monospace, monospace' };
const ticks: Text[] = Array.from({ length: 24 }, () => {
  const t = new Text({ text: '', style: tickStyle });
  t.anchor.set(0, 0.5);
  app.stage.addChild(t);
  return t;
});
const status = createStatusLine();
let statusFrame = 0;

/** Vertical spacing of the altitude grid, m, for the current zoom (about 80 px). */
function gridStep(ppm: number): number {
  const raw = 80 / ppm;
  for (const s of [1, 2, 5, 10, 20, 50, 100, 200, 500, 1000]) if (s >= raw) return s;
  return 2000;
}

function draw(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  const P = world.components.Position,
    O = world.components.PreviousPosition;
  const subject = handles.scene === 'parachute' ? handles.jumper : handles.balloon;
  const sx = O.x[slotOf(subject)]! + (P.x[slotOf(subject)]! - O.x[slotOf(subject)]!) * alpha;
  const sy = O.y[slotOf(subject)]! + (P.y[slotOf(subject)]! - O.y[slotOf(subject)]!) * alpha;
  // Follow the subject (keeping the ground in view when it is near it), then place the balls again for this camera.
  const ppm = params.zoom;
  const halfH = cam.height / 2 / ppm;
  cam.setPixelsPerMeter(ppm, sx, Math.max(sy, halfH - 3));
  renderer.render(alpha);
  const view = cam.visibleRect();
  // Sky: the canvas' clear colour (a full-screen fill costs frames under software WebGL); in the
  // balloon scene it darkens with the air density at the balloon's height.
  sky.clear();
  const f = handles.scene === 'balloon' ? Math.min(1, airDensity(Math.max(0, sy), handles.params.scaleHeight) / 1.225) : 0.6;
  app.renderer.background.color = (Math.round(16 + 30 * f) << 16) | (Math.round(24 + 50 * f) << 8) | Math.round(40 + 80 * f);
  // Ground.
  const gy = cam.toScreenY(0);
  if (gy < cam.height) sky.rect(0, gy, cam.width, cam.height - gy).fill({ color: 0x2d4a2b });
  // Grid: altitude lines with labels, and vertical lines that show the drift.
  const s = gridStep(ppm);
  grid.clear();
  let used = 0;
  for (let y = Math.ceil(view.minY / s) * s; y <= view.maxY; y += s) {
    if (y < 0) continue;
    const py = cam.toScreenY(y);
    grid.moveTo(0, py).lineTo(cam.width, py);
    if (used < ticks.length) {
      const t = ticks[used++]!;
      const text = `${y} m`;
      if (t.text !== text) t.text = text;
      t.position.set(6, py - 8);
      t.visible = true;
    }
  }
  for (let i = used; i < ticks.length; i++) ticks[i]!.visible = false;
  for (let x = Math.ceil(view.minX / s) * s; x <= view.maxX; x += s) {
    const px = cam.toScreenX(x);
    grid.moveTo(px, 0).lineTo(px, Math.min(cam.height, gy));
  }
  grid.stroke({ width: 1, color: 0xffffff, alpha: 0.08 });
  overlay.clear();
  const px = cam.toScreenX(sx),
    py = cam.toScreenY(sy);
  if (handles.scene === 'parachute') drawChute(world, handles, px, py);
  else drawBalloon(handles, px, py);
  if (++statusFrame % 6 === 1) status.set(statusLine(world));
}

function drawChute(world: PhysicsWorld, h: ParachuteHandles, px: number, py: number): void {
  const cam = renderer.camera;
  const r = cam.toScreenLength(JUMPER_RADIUS);
  // Body line under the head (the ball is the head and torso).
  overlay
    .moveTo(px, py + r)
    .lineTo(px, py + 2.2 * r)
    .stroke({ width: 2, color: 0xe8ecf1 });
  if (Number.isNaN(h.openedAt)) return;
  const f = params.openingTime > 0 ? Math.min(1, (world.time - h.openedAt) / params.openingTime) : 1;
  const half = cam.toScreenLength(0.6 + 3.4 * f),
    lift = cam.toScreenLength(5);
  const top = py - r - lift;
  overlay
    .moveTo(px - half, top)
    .quadraticCurveTo(px, top - half * 0.9, px + half, top)
    .closePath()
    .fill({ color: 0xef476f, alpha: 0.9 });
  overlay
    .moveTo(px - half, top)
    .lineTo(px, py - r)
    .moveTo(px + half, top)
    .lineTo(px, py - r)
    .stroke({ width: 1, color: 0xe8ecf1, alpha: 0.7 });
}

function drawBalloon(h: BalloonHandles, px: number, py: number): void {
  const cam = renderer.camera;
  const r = cam.toScreenLength(h.params.balloonRadius);
  // Tether or a dangling string.
  if (h.tether !== 0)
    overlay
      .moveTo(px, py + r)
      .lineTo(cam.toScreenX(h.anchor[0]), cam.toScreenY(h.anchor[1]))
      .stroke({ width: 1.5, color: 0xe8ecf1, alpha: 0.8 });
  else
    overlay
      .moveTo(px, py + r)
      .lineTo(px, py + r + cam.toScreenLength(2))
      .stroke({ width: 1.5, color: 0xe8ecf1, alpha: 0.6 });
  const yStar = equilibriumAltitude(h.params);
  if (Number.isFinite(yStar)) {
    const ye = cam.toScreenY(yStar);
    dashedLine(overlay, 0, ye, cam.width, ye, 8, 6).stroke({ width: 1.5, color: 0x8ecae6, alpha: 0.8 });
  }
}

function statusLine(world: PhysicsWorld): string {
  const P = world.components.Position,
    V = world.components.Velocity;
  if (handles.scene === 'parachute') {
    const e = handles.jumper;
    const landed = P.y[slotOf(e)]! - JUMPER_RADIUS < 0.05;
    const state = landed ? 'landed' : Number.isNaN(handles.openedAt) ? 'free fall (O or click: open)' : 'canopy open';
    return `${state} · altitude ${Math.max(0, P.y[slotOf(e)]! - JUMPER_RADIUS).toFixed(0)} m · descent ${(-V.y[slotOf(e)]!).toFixed(1)} m/s · wind ${handles.params.wind.toFixed(1)} m/s`;
  }
  const e = handles.balloon;
  const yStar = equilibriumAltitude(handles.params);
  return `height ${P.y[slotOf(e)]!.toFixed(1)} m · equilibrium ${Number.isFinite(yStar) ? `${yStar.toFixed(1)} m` : 'none (too heavy)'} · ${handles.tether !== 0 ? 'tethered' : 'free'}`;
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** The scene handles. */
  handles: (): Handles => handles,
  /** Opens the parachute; @returns whether it opened now. */
  openChute: pullRipcord,
  /** Ties or cuts the balloon's tether. */
  setTethered,
  /** The parachutist's descent speed (or the balloon's rise speed, negative), m/s. */
  descentSpeed: (): number => -shell.world.components.Velocity.y[handles.scene === 'parachute' ? handles.jumper : handles.balloon]!,
  /** The subject's height, m. */
  height: (): number => shell.world.components.Position.y[handles.scene === 'parachute' ? handles.jumper : handles.balloon]!,
  /** Terminal speeds [closed, open], m/s, for the jumper's current mass. */
  terminalSpeeds: (): [number, number] => {
    const h = handles as ParachuteHandles;
    const m = shell.world.components.Mass.value[slotOf(h.jumper)]!;
    return [terminalSpeed(m, h.params.kClosed), terminalSpeed(m, h.params.kOpen)];
  },
  /** Exact equilibrium height of the balloon, m. */
  equilibriumAltitude: (): number => equilibriumAltitude(handles.params),
  /** Runs `n` steps now (with the chute rule and plot samples). @throws RangeError unless n is an integer in [0, 100000]. */
  advance: (n: number): void => {
    if (!(Number.isInteger(n) && n >= 0 && n <= 100_000)) throw new RangeError(`advance: n must be an integer in [0, 100000], got ${n}`);
    for (let i = 0; i < n; i++) stepLab(shell.world);
  },
});
