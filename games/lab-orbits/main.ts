/**
 * Lab: orbits (Ramtal and Dobre ch. 6). Planets circle a fixed sun whose pull is the physics
 * package's Attractor component (G = 1 through setGravitation, so the panel's G M is the sun's
 * mass in scaled units); the world's integrator moves them. The chart follows the selected orbit's
 * energy against its value when it was selected, and the readout puts the Kepler period
 * 2 pi sqrt(a^3 / G M) (a from that energy) next to the period measured from the body's angle.
 * The dashed ellipse is the exact Kepler orbit through the selected body's state at selection.
 *
 * Input: drag on empty space launches a body (velocity = drag vector per second), click selects the
 * nearest body, S selects the next one, X removes launched bodies. P pause, N step, R reset.
 * URL: ?planets (1-8), ?gm (1-500 m^3/s^2), ?softening (0-3 m), ?integrator, ?seed.
 */

import { choiceParam, createPanel, numberParam, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import {
  createLabDock,
  createReadout,
  drawDashedLine,
  drawnPosition,
  fmt,
  followView,
  PathBuffer,
  readUrlParams,
} from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPlot } from '@bitphysics/game-kit/plot';
import {
  createPhysicsWorld,
  INTEGRATOR_NAMES,
  type IntegratorName,
  type PhysicsWorld,
  step as physicsStep,
  slotOf,
  totalEnergy,
} from '@bitphysics/physics';
import type { Point2, WorldRect } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import { conicRadius, keplerPeriod, type OrbitShape, orbitShape, semiMajorAxis, specificEnergy } from './exact';
import {
  buildOrbits,
  ESCAPE_DISTANCE,
  launchBody,
  ORBITS_DEFAULTS,
  type OrbitsHandles,
  orbitsWorldOptions,
  outerRadius,
  removeOrbiter,
  SUN_RADIUS,
  setCentralMass,
} from './scene';

/** Launch velocity per metre of drag, 1/s. */
const LAUNCH_GAIN = 1;
/** A press moving less than this, CSS px, is a click (select), more a drag (launch). */
const CLICK_SLOP = 6;
const SELECTED_COLOR = 0xffd166;

const USAGE = `Accepted: planets 1-8 (integer); gm 1-500 m³/s²; softening 0-3 m; integrator = ${INTEGRATOR_NAMES.join(' | ')}; seed (integer).`;
const url = readUrlParams(
  () => ({
    planets: numberParam('planets', { default: ORBITS_DEFAULTS.planets, min: 1, max: 8, integer: true }),
    gm: numberParam('gm', { default: ORBITS_DEFAULTS.gm, min: 1, max: 500 }),
    softening: numberParam('softening', { default: ORBITS_DEFAULTS.softening, min: 0, max: 3 }),
    integrator: choiceParam('integrator', INTEGRATOR_NAMES, ORBITS_DEFAULTS.integrator),
    seed: seedParam(ORBITS_DEFAULTS.seed),
  }),
  USAGE,
);

const params = {
  ...url,
  trails: true,
  reset: () => shell.reset(),
  clearLaunched: () => clearLaunched(),
};

let handles: OrbitsHandles;
const view: WorldRect = { minX: -10, minY: -10, maxX: 10, maxY: 10 };

/** Builds a fresh world from the params; the shell calls it at start and on R. */
function createWorld(): PhysicsWorld {
  const options = {
    planets: params.planets,
    gm: params.gm,
    softening: params.softening,
    integrator: params.integrator as IntegratorName,
    seed: params.seed,
  };
  const world = createPhysicsWorld(orbitsWorldOptions(options));
  handles = buildOrbits(world, options);
  const R = outerRadius(params.planets) + 0.5;
  view.minX = -R;
  view.maxX = R;
  view.minY = -R;
  view.maxY = R;
  refit?.();
  select(world, handles.planets[Math.min(1, handles.planets.length - 1)] ?? 0);
  return world;
}

// ---- The selected orbit -----------------------------------------------------------------------------

/** Measurements of the selected orbit (live object, also on window.game). */
const orbit = {
  /** Selected entity, 0 for none. */
  eid: 0,
  /** Specific energy when selected, and now, J/kg. */
  e0: Number.NaN,
  energy: Number.NaN,
  /** Semi-major axis from e0, m (Infinity when unbound). */
  a: Number.NaN,
  /** Kepler period 2 pi sqrt(a^3 / G M) from e0, s. */
  keplerPeriod: Number.NaN,
  /** Period measured from the angle swept (time of the last full turn), s; NaN before one turn. */
  measuredPeriod: Number.NaN,
  /** Full turns completed since selection. */
  turns: 0,
  /** Largest |E - E0| / |E0| since selection. */
  maxDrift: 0,
  /** Total energy of the world when selected (package `totalEnergy`), J. */
  total0: Number.NaN,
};
let swept = 0,
  lastAngle = 0,
  lastTurnTime = 0;
const shape: OrbitShape = { a: 0, e: 0, omega: 0 };
const keplerPath = new PathBuffer(361);
const orbitPath = new PathBuffer(1500);

/** Specific energy of body `eid` of `world`, J/kg (see exact.ts). */
function energyOf(world: PhysicsWorld, eid: number): number {
  const P = world.components.Position,
    V = world.components.Velocity;
  return specificEnergy(
    P.x[slotOf(eid)]!,
    P.y[slotOf(eid)]!,
    V.x[slotOf(eid)]!,
    V.y[slotOf(eid)]!,
    handles.params.gm,
    handles.params.softening,
  );
}

/** Selects body `eid` (0 for none): restarts the energy chart, the period measurement and the paths. */
function select(world: PhysicsWorld, eid: number): void {
  orbit.eid = eid;
  orbit.turns = 0;
  orbit.measuredPeriod = Number.NaN;
  orbit.maxDrift = 0;
  swept = 0;
  lastTurnTime = world.time;
  orbitPath.clear();
  keplerPath.clear();
  plot?.clear();
  orbit.total0 = totalEnergy(world);
  if (eid === 0) {
    orbit.e0 = orbit.energy = orbit.a = orbit.keplerPeriod = Number.NaN;
    return;
  }
  const P = world.components.Position,
    V = world.components.Velocity;
  const x = P.x[slotOf(eid)]!,
    y = P.y[slotOf(eid)]!;
  lastAngle = Math.atan2(y, x);
  orbit.e0 = orbit.energy = energyOf(world, eid);
  orbit.a = semiMajorAxis(orbit.e0, handles.params.gm);
  orbit.keplerPeriod = keplerPeriod(orbit.a, handles.params.gm);
  orbitShape(x, y, V.x[slotOf(eid)]!, V.y[slotOf(eid)]!, handles.params.gm, shape);
  if (shape.e < 1) {
    for (let i = 0; i <= 360; i++) {
      const th = (i / 360) * 2 * Math.PI;
      const r = conicRadius(shape, th);
      keplerPath.push(r * Math.cos(th), r * Math.sin(th));
    }
  }
  orbitPath.push(x, y);
}

/** All orbiting bodies, planets first (a fresh array; for input handling, not per frame). */
function orbiters(): number[] {
  return [...handles.planets, ...handles.launched];
}

/** Removes the bodies of `list` that fell into the sun or escaped (a game rule, not physics). */
function cull(world: PhysicsWorld, list: number[]): void {
  const P = world.components.Position;
  for (let i = list.length - 1; i >= 0; i--) {
    const e = list[i]!;
    const r = Math.hypot(P.x[slotOf(e)]!, P.y[slotOf(e)]!);
    if (r < SUN_RADIUS || r > ESCAPE_DISTANCE) {
      removeOrbiter(world, handles, e);
      if (e === orbit.eid) select(world, handles.planets[0] ?? handles.launched[0] ?? 0);
    }
  }
}

/** One step: physics, bodies lost to the sun or to space removed, the selected orbit measured. */
function labStep(world: PhysicsWorld): void {
  physicsStep(world);
  cull(world, handles.planets);
  cull(world, handles.launched);
  const P = world.components.Position;
  const e = orbit.eid;
  if (e === 0) return;
  const x = P.x[slotOf(e)]!,
    y = P.y[slotOf(e)]!;
  orbit.energy = energyOf(world, e);
  if (orbit.e0 !== 0) orbit.maxDrift = Math.max(orbit.maxDrift, Math.abs((orbit.energy - orbit.e0) / orbit.e0));
  // Angle swept since selection; each full turn ends a measured period (crossing time interpolated).
  const angle = Math.atan2(y, x);
  let d = angle - lastAngle;
  if (d > Math.PI) d -= 2 * Math.PI;
  else if (d < -Math.PI) d += 2 * Math.PI;
  const before = swept;
  swept += d;
  lastAngle = angle;
  const target = 2 * Math.PI * (orbit.turns + 1);
  if (Math.abs(swept) >= target && Math.abs(before) < target) {
    const f = (target - Math.abs(before)) / (Math.abs(swept) - Math.abs(before));
    const tc = world.time - world.dt + f * world.dt;
    orbit.measuredPeriod = tc - lastTurnTime;
    lastTurnTime = tc;
    orbit.turns++;
  }
  if (world.steps % 2 === 0) orbitPath.push(x, y);
  plot?.push(world.time, orbit.energy, orbit.e0);
}

// ---- Page ------------------------------------------------------------------------------------------

let refit: (() => void) | null = null;
let plot: ReturnType<typeof createPlot> | null = null;
const trailOptions = { length: 120, maxEntities: 40, width: 2, alpha: 0.5 };

const game = await startPixiGame({
  title: 'Orbits',
  createWorld,
  step: labStep,
  bodies: () => handles.planets.length + handles.launched.length,
  controls: [
    { keys: 'Drag', action: 'launch a body (velocity = drag per second)' },
    { keys: 'Click', action: 'select the nearest body' },
    { keys: 'S', action: 'select the next body' },
    { keys: 'X', action: 'remove launched bodies' },
  ],
  keys: [
    { key: 's', label: 'select next', action: () => selectNext() },
    { key: 'x', label: 'clear launched', action: () => clearLaunched() },
  ],
  renderer: { view, balls: 'sprites', trails: trailOptions, rotation: false },
  onFrame: (alpha, world) => drawOverlay(alpha, world),
});
const { shell, renderer, app } = game;
const dock = createLabDock();
refit = followView(app, renderer.camera, dock, () => view);

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'gm', label: 'G M (m³/s²)', min: 1, max: 500, step: 0.5, onChange: () => applyCentralMass() },
    { type: 'slider', key: 'softening', label: 'softening (m)', min: 0, max: 3, step: 0.01, onChange: () => applyCentralMass() },
    {
      type: 'choice',
      key: 'integrator',
      options: INTEGRATOR_NAMES,
      onChange: (name) => {
        // The world reads its scheme by name every step: switching needs no rebuild.
        shell.world.integrator = name as IntegratorName;
        select(shell.world, orbit.eid);
      },
    },
    {
      type: 'slider',
      key: 'planets',
      label: 'planets (rebuilds)',
      min: 1,
      max: 8,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    { type: 'checkbox', key: 'trails', onChange: (on) => renderer.setTrails(on === true ? trailOptions : false) },
    { type: 'button', key: 'clearLaunched', label: 'remove launched bodies (X)' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Orbits', container: dock.panelSlot },
);

/** Applies the panel's G M and softening to the running world and restarts the selected orbit's measurements. */
function applyCentralMass(): void {
  setCentralMass(shell.world, handles, params.gm, params.softening);
  select(shell.world, orbit.eid);
}

const readout = createReadout(shell.hud.readout, [
  'selected body',
  'energy E (J/kg)',
  'E₀ at selection',
  'max |E − E₀|/|E₀|',
  'a = −GM/2E₀',
  'Kepler 2π√(a³/GM)',
  'measured period',
  'turns',
  'drift of the total energy',
]);
plot = createPlot({
  parent: dock.charts,
  title: 'Energy of the selected orbit',
  yLabel: 'E (J/kg)',
  width: dock.chartWidth,
  height: 190,
  capacity: 2400,
  series: [
    { label: 'E(t)', color: '#ffd166' },
    { label: 'E₀ (initial)', color: '#e6e9ef', dashed: true },
  ],
});
select(shell.world, orbit.eid);

/** Selects the body after the selected one (wrapping). */
function selectNext(): void {
  const all = orbiters();
  if (all.length === 0) return;
  select(shell.world, all[(all.indexOf(orbit.eid) + 1) % all.length]!);
}

/** Removes every launched body. */
function clearLaunched(): void {
  for (const e of handles.launched.slice()) {
    removeOrbiter(shell.world, handles, e);
    if (e === orbit.eid) select(shell.world, handles.planets[0] ?? 0);
  }
}

// ---- Pointer: drag launches, click selects --------------------------------------------------------

const canvas = app.canvas;
const down: Point2 = { x: 0, y: 0 },
  now: Point2 = { x: 0, y: 0 };
let pointerId = -1,
  dragged = false;

canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0 || pointerId !== -1) return;
  pointerId = event.pointerId;
  canvas.setPointerCapture(event.pointerId);
  pointerOnCanvas(canvas, event, down);
  now.x = down.x;
  now.y = down.y;
  dragged = false;
});
canvas.addEventListener('pointermove', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerOnCanvas(canvas, event, now);
  if (Math.hypot(now.x - down.x, now.y - down.y) > CLICK_SLOP) dragged = true;
});
canvas.addEventListener('pointerup', (event) => {
  if (event.pointerId !== pointerId) return;
  pointerId = -1;
  pointerOnCanvas(canvas, event, now);
  const cam = renderer.camera;
  const x = cam.toWorldX(down.x),
    y = cam.toWorldY(down.y);
  if (dragged) {
    if (Math.hypot(x, y) < SUN_RADIUS) return;
    launch(x, y, (cam.toWorldX(now.x) - x) * LAUNCH_GAIN, (cam.toWorldY(now.y) - y) * LAUNCH_GAIN);
  } else {
    selectNearest(x, y);
  }
});
canvas.addEventListener('pointercancel', (event) => {
  if (event.pointerId === pointerId) pointerId = -1;
});

/** Launches a body at (x, y), m, with velocity (vx, vy), m/s, and selects it. @returns its id. */
function launch(x: number, y: number, vx: number, vy: number): number {
  const e = launchBody(shell.world, handles, x, y, vx, vy);
  select(shell.world, e);
  return e;
}

/** Selects the body nearest to world point (x, y), m. @returns its id (0 if there is none). */
function selectNearest(x: number, y: number): number {
  const P = shell.world.components.Position;
  let best = 0,
    bestD = Infinity;
  for (const e of orbiters()) {
    const d = Math.hypot(P.x[slotOf(e)]! - x, P.y[slotOf(e)]! - y);
    if (d < bestD) {
      bestD = d;
      best = e;
    }
  }
  if (best !== 0) select(shell.world, best);
  return best;
}

// ---- Drawing ------------------------------------------------------------------------------------

const overlay = new Graphics({ label: 'lab-overlay' });
renderer.root.addChildAt(overlay, 1);
const at: Point2 = { x: 0, y: 0 };

/** The sun, the exact Kepler ellipse and the path of the selected orbit, its marker, the launch preview. */
function drawOverlay(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  overlay.clear();
  const sx = cam.toScreenX(0),
    sy = cam.toScreenY(0),
    sr = Math.max(5, cam.toScreenLength(SUN_RADIUS));
  overlay.circle(sx, sy, sr * 1.8).fill({ color: 0xffb703, alpha: 0.12 });
  overlay.circle(sx, sy, sr).fill({ color: 0xffd166 });
  if (keplerPath.count > 1) keplerPath.draw(overlay, cam, 1.5, 0xe6e9ef, 0.55, true);
  if (orbit.eid !== 0) {
    drawnPosition(world, orbit.eid, alpha, at);
    orbitPath.draw(overlay, cam, 1.5, SELECTED_COLOR, 0.6, false, at.x, at.y);
    overlay
      .circle(cam.toScreenX(at.x), cam.toScreenY(at.y), Math.max(7, cam.toScreenLength(0.3)))
      .stroke({ width: 2, color: SELECTED_COLOR });
  }
  if (pointerId !== -1 && dragged) {
    drawDashedLine(overlay, down.x, down.y, now.x, now.y, 2, 0xffffff, 0.7, 6, 4);
    overlay.circle(down.x, down.y, 5).stroke({ width: 2, color: 0xffffff, alpha: 0.8 });
  }
  updateReadout(world);
}

let readoutFrame = 0;
/** Refreshes the readout (every 8th frame). */
function updateReadout(world: PhysicsWorld): void {
  if (readoutFrame++ % 8 !== 0) return;
  readout.set(0, orbit.eid === 0 ? 'none' : `#${orbit.eid}${handles.launched.includes(orbit.eid) ? ' (launched)' : ''}`);
  readout.set(1, fmt(orbit.energy, 6));
  readout.set(2, fmt(orbit.e0, 6));
  readout.set(3, fmt(orbit.maxDrift, 3));
  readout.set(4, Number.isFinite(orbit.a) ? `${fmt(orbit.a)} m` : 'unbound');
  readout.set(5, Number.isFinite(orbit.keplerPeriod) ? `${fmt(orbit.keplerPeriod)} s` : 'unbound (no period)');
  readout.set(6, Number.isNaN(orbit.measuredPeriod) ? 'after the first turn' : `${fmt(orbit.measuredPeriod)} s`);
  readout.set(7, String(orbit.turns));
  const total = totalEnergy(world);
  readout.set(8, `${fmt(total - orbit.total0, 3)} J`);
}

// ---- Test and console hooks on window.game ---------------------------------------------------------

shell.expose({
  params,
  panel,
  plot,
  /** The selected orbit's measurements (live object). */
  orbit,
  /** Ids of every orbiting body, planets first. */
  orbiters,
  /** Runs `n` (integer >= 0) lab steps now, measurements included. @throws RangeError otherwise. */
  advance: (n: number): void => {
    if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
    for (let i = 0; i < n; i++) labStep(shell.world);
  },
  launch,
  /** Selects body `eid`. @throws RangeError if it is not an orbiting body. */
  select: (eid: number): void => {
    if (!orbiters().includes(eid)) throw new RangeError(`select: ${eid} is not an orbiting body`);
    select(shell.world, eid);
  },
});
