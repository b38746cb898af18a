/**
 * Lab: cyclotron motion (Ramtal and Dobre ch. 10: the Lorentz force). A charged ball circles in a
 * uniform magnetic field; an optional electric field makes it drift (E x B). Two plots: the radius
 * and the period measured from the trajectory, each against its exact value m v / (|q| B) and
 * 2 pi m / (|q| B). The exact orbit is drawn dashed. Try the Euler schemes: the radius grows (explicit
 * and semi-implicit Euler) or shrinks (implicit Euler) every revolution; RK4 and the Verlets hold it.
 *
 * Keys: P pause, N step, R reset, F flip the magnetic field. Click: restart the run from the current
 * state (new exact orbit). URL: ?charge= (mC, -5..5, not 0), ?mass= (g, 0.5..20), ?B= (T, 0.1..4),
 * ?speed= (m/s, 0.1..20), ?E= (V/m, -5..5), ?integrator=<name>, ?substeps= (1..64).
 */

import { choiceParam, createPanel, numberParam } from '@bitphysics/game-kit';
import {
  createPlotDock,
  createStatusLine,
  dashedLine,
  plotReserve,
  readUrlParams,
  scaleFloor,
  scaleSeries,
} from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPhysicsWorld, INTEGRATOR_NAMES, type IntegratorName, type PhysicsWorld, step } from '@bitphysics/physics';
import { Graphics } from 'pixi.js';
import {
  buildCyclotron,
  type CyclotronHandles,
  cyclotronWorldOptions,
  exactCentre,
  flipField,
  measure,
  rebaseline,
  resolveCyclotronOptions,
} from './scene';

const params = readUrlParams(() => {
  const charge = numberParam('charge', { default: 1, min: -5, max: 5 });
  if (charge === 0) throw new RangeError('URL parameter charge must be non-zero, got "0"');
  return {
    charge,
    mass: numberParam('mass', { default: 1, min: 0.5, max: 20 }),
    field: numberParam('B', { default: 1, min: 0.1, max: 4 }),
    speed: numberParam('speed', { default: 3, min: 0.1, max: 20 }),
    electric: numberParam('E', { default: 0, min: -5, max: 5 }),
    integrator: choiceParam('integrator', INTEGRATOR_NAMES, 'rk4') as IntegratorName,
    substeps: numberParam('substeps', { default: 1, min: 1, max: 64, integer: true }),
    flip: () => flip(),
    reset: () => game.shell.reset(),
  };
});

let handles!: CyclotronHandles;
const centre = new Float64Array(2);

function createWorld(): PhysicsWorld {
  const options = resolveCyclotronOptions({
    // The slider reaches 0, which would not circle: |q| below 0.05 mC is taken as 0.05 mC.
    charge: Math.abs(params.charge) < 0.05 ? 0.05 : params.charge,
    mass: params.mass,
    field: params.field,
    speed: params.speed,
    electric: params.electric,
    integrator: params.integrator,
    substeps: params.substeps,
  });
  const world = createPhysicsWorld(cyclotronWorldOptions(options));
  handles = buildCyclotron(world, options);
  return world;
}

/** Plot samples every this many steps. */
const PLOT_EVERY = 3;
/** The plots' y axes span at least exact +- 5%. */
const BAND = 0.05;

function stepLab(world: PhysicsWorld): void {
  step(world);
  measure(world, handles);
  if (world.steps % PLOT_EVERY === 0) {
    const k = world.steps / PLOT_EVERY;
    radiusPlot.push(world.time, handles.meter.radius, handles.exactRadius, scaleFloor(handles.exactRadius, BAND, k));
    periodPlot.push(world.time, handles.meter.period, handles.exactPeriod, scaleFloor(handles.exactPeriod, BAND, k));
  }
}

const game = await startPixiGame({
  title: 'Cyclotron motion',
  createWorld,
  step: stepLab,
  bodies: () => 1,
  controls: [
    { keys: 'F', action: 'flip the magnetic field' },
    { keys: 'Click', action: 'new run from the current state' },
    { keys: 'Panel', action: 'q, m, B, speed, E, integrator' },
  ],
  keys: [{ key: 'f', label: 'flip field', action: () => flip() }],
  renderer: { pixelsPerMeter: 50, rotation: false, trails: { length: 600, maxEntities: 4, width: 2, alpha: 0.8 } },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = game;
renderer.setColor(handles.particle, 0xffd166);

const dock = createPlotDock(2);
const radiusPlot = dock.add({
  title: 'Radius',
  yLabel: 'm',
  series: [
    { label: 'measured (m)', color: '#ffd166' },
    { label: 'exact m v / (|q| B)', color: '#8ecae6', dashed: true },
    scaleSeries(BAND),
  ],
});
const periodPlot = dock.add({
  title: 'Period',
  yLabel: 's',
  series: [
    { label: 'measured (s)', color: '#ffd166' },
    { label: 'exact 2π m / (|q| B)', color: '#8ecae6', dashed: true },
    scaleSeries(BAND),
  ],
});

/** Starts a new run: exact orbit from the present state, empty plots. */
function restartRun(): void {
  rebaseline(shell.world, handles);
  radiusPlot.clear();
  periodPlot.clear();
}

function flip(): void {
  flipField(shell.world, handles);
  radiusPlot.clear();
  periodPlot.clear();
}

shell.onWorldChange(() => {
  radiusPlot.clear();
  periodPlot.clear();
  renderer.setColor(handles.particle, 0xffd166);
});

const rebuild = () => shell.reset();
const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'charge', label: 'charge q (mC)', min: -5, max: 5, step: 0.1, onRelease: true, onChange: rebuild },
    { type: 'slider', key: 'mass', label: 'mass m (g)', min: 0.5, max: 20, step: 0.1, onRelease: true, onChange: rebuild },
    { type: 'slider', key: 'field', label: 'field B (T)', min: 0.1, max: 4, step: 0.05, onRelease: true, onChange: rebuild },
    { type: 'slider', key: 'speed', label: 'speed v (m/s)', min: 0.1, max: 20, step: 0.1, onRelease: true, onChange: rebuild },
    { type: 'slider', key: 'electric', label: 'electric field E_y (V/m)', min: -5, max: 5, step: 0.1, onRelease: true, onChange: rebuild },
    { type: 'choice', key: 'integrator', options: INTEGRATOR_NAMES, onChange: rebuild },
    { type: 'slider', key: 'substeps', min: 1, max: 32, step: 1, onRelease: true, onChange: rebuild },
    { type: 'button', key: 'flip', label: 'flip B (F)' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Cyclotron' },
);

app.canvas.addEventListener('pointerdown', (event) => {
  if (event.button === 0) restartRun();
});

// ---- Drawing: the exact orbit (dashed), the field symbols, the view following the orbit ---------------

const back = new Graphics({ label: 'field' });
const orbit = new Graphics({ label: 'exact-orbit' });
app.stage.addChildAt(back, 0);
app.stage.addChild(orbit);
const status = createStatusLine();
let frame = 0;
let viewX = Number.NaN,
  viewY = 0,
  viewScale = 0;
const reserve = plotReserve();

let backKey = '';

/** The field symbols on a 60 px grid: dots where B points out of the screen, crosses where into it. */
function drawField(bz: number): void {
  const cam = renderer.camera;
  back.clear();
  const spacing = 60;
  for (let x = spacing / 2; x < cam.width; x += spacing) {
    for (let y = spacing / 2; y < cam.height; y += spacing) {
      if (bz > 0) back.circle(x, y, 2.5);
      else
        back
          .moveTo(x - 4, y - 4)
          .lineTo(x + 4, y + 4)
          .moveTo(x + 4, y - 4)
          .lineTo(x - 4, y + 4);
    }
  }
  if (bz > 0) back.fill({ color: 0x5c677d });
  else back.stroke({ width: 1.5, color: 0x5c677d });
}

function draw(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  exactCentre(world, handles, centre);
  // Fit the exact orbit (diameter plus margins) into the part of the screen left of the plots (the
  // whole screen on narrow windows); move the view only when the orbit drifts out of it.
  const r = handles.exactRadius;
  const usable = Math.max(200, cam.width - reserve);
  const scale = Math.min(usable / (2.8 * r), cam.height / (2.8 * r));
  const cx = centre[0]!,
    cy = centre[1]!;
  if (Number.isNaN(viewX) || scale !== viewScale || Math.abs(cx - viewX) > 0.8 * r) {
    viewScale = scale;
    viewX = cx;
    viewY = cy;
    // Centre the orbit in the usable (left) part: the screen centre sits (width/2 - usable/2) px to the right of it.
    const shift = (cam.width / 2 - usable / 2) / scale;
    cam.setPixelsPerMeter(scale, viewX + shift, viewY);
    renderer.render(alpha);
  }
  // The field symbols, redrawn when B flips or the window resizes.
  const bz = world.components.MagneticField.z[handles.magnetic]!;
  const key = `${Math.sign(bz)} ${cam.width} ${cam.height}`;
  if (key !== backKey) drawField(bz);
  backKey = key;
  // The exact orbit.
  orbit.clear();
  const sx = cam.toScreenX(cx),
    sy = cam.toScreenY(cy),
    sr = cam.toScreenLength(r);
  const n = 96;
  for (let i = 0; i < n; i += 2) {
    const a0 = (2 * Math.PI * i) / n,
      a1 = (2 * Math.PI * (i + 1)) / n;
    orbit.moveTo(sx + sr * Math.cos(a0), sy + sr * Math.sin(a0)).lineTo(sx + sr * Math.cos(a1), sy + sr * Math.sin(a1));
  }
  orbit.stroke({ width: 1.5, color: 0x8ecae6, alpha: 0.8 });
  orbit.circle(sx, sy, 3).fill({ color: 0x8ecae6 });
  if (world.components.ElectricField.y[handles.electric] !== 0) {
    const ey = world.components.ElectricField.y[handles.electric]!;
    const x0 = 30,
      y0 = cam.height / 2,
      len = 40 * Math.sign(ey);
    dashedLine(orbit, x0, y0 + len, x0, y0 - len, 1000, 1).stroke({ width: 2, color: 0xef476f });
    orbit
      .moveTo(x0, y0 - len - 6 * Math.sign(ey))
      .lineTo(x0 - 5, y0 - len)
      .lineTo(x0 + 5, y0 - len)
      .closePath()
      .fill({ color: 0xef476f });
  }
  if (++frame % 10 === 1) {
    const m = handles.meter;
    status.set(
      `B ${bz > 0 ? 'out of' : 'into'} the screen · exact r = ${r.toFixed(3)} m, T = ${handles.exactPeriod.toFixed(3)} s · ` +
        `measured r = ${Number.isNaN(m.radius) ? '…' : m.radius.toFixed(3)} m, T = ${Number.isNaN(m.period) ? '…' : m.period.toFixed(3)} s · ${m.revolutions} rev`,
    );
  }
}

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  plot: radiusPlot,
  radiusPlot,
  periodPlot,
  /** The scene handles (meter, exact values). */
  handles: (): CyclotronHandles => handles,
  /** Measured and exact radius (m) and period (s), and revolutions measured. */
  measurement: () => ({
    radius: handles.meter.radius,
    period: handles.meter.period,
    revolutions: handles.meter.revolutions,
    exactRadius: handles.exactRadius,
    exactPeriod: handles.exactPeriod,
  }),
  /** The magnetic field B_z now, T. */
  field: (): number => shell.world.components.MagneticField.z[handles.magnetic]!,
  /** Reverses B. */
  flip,
  /** Runs `n` steps now (with measurements and plot samples). @throws RangeError unless n is an integer in [0, 100000]. */
  advance: (n: number): void => {
    if (!(Number.isInteger(n) && n >= 0 && n <= 100_000)) throw new RangeError(`advance: n must be an integer in [0, 100000], got ${n}`);
    for (let i = 0; i < n; i++) stepLab(shell.world);
  },
});
