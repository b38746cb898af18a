/**
 * Lab: rocket (Ramtal and Dobre ch. 6: rockets and Newtonian gravity; ch. 7: drag). A rocket burns
 * its fuel (variable-mass thrust) against a planet's gravity and its atmosphere's drag. Two plots:
 * the speed against Tsiolkovsky's ideal ve ln(m0 / m) (the free-space speed) and against the exact
 * vertical ascent in uniform gravity (v = ve ln(m_l / m) - g0 t: Tsiolkovsky minus the gravity loss);
 * the altitude against the same model. In free space the speed follows Tsiolkovsky exactly; on the
 * toy planet gravity weakens quickly with height (inverse square) and the flight beats the model.
 *
 * Keys: Up / Down (W / S) throttle, Left / Right (A / D) steer, Space engine off, Z full throttle,
 * P pause, N step, R reset. URL: ?planet=toy|earth|none, ?dryMass=, ?fuel= (kg), ?ve= (m/s),
 * ?mdot= (kg/s), ?drag=0|1, ?warp= (1..50).
 */

import { choiceParam, createPanel, flagParam, numberParam } from '@bitphysics/game-kit';
import { createPlotDock, createStatusLine, readUrlParams, trackHeldKeys } from '@bitphysics/game-kit/lab-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { createPhysicsWorld, type PhysicsWorld, step } from '@bitphysics/physics';
import { Graphics } from 'pixi.js';
import {
  altitude,
  applyControls,
  buildRocket,
  orbitAltitudes,
  PLANET_SPECS,
  PLANETS,
  type PlanetName,
  type RocketHandles,
  resolveRocketOptions,
  rocketWorldOptions,
  speed,
  tsiolkovsky,
  uniformGravityModel,
} from './scene';

const params = readUrlParams(() => {
  const planet = choiceParam('planet', PLANETS, 'toy') as PlanetName;
  const s = PLANET_SPECS[planet];
  return {
    planet,
    dryMass: numberParam('dryMass', { default: s.dryMass, min: 1, max: 1e7 }),
    fuel: numberParam('fuel', { default: s.fuel, min: 0, max: 1e7 }),
    exhaustVelocity: numberParam('ve', { default: s.exhaustVelocity, min: 1, max: 10_000 }),
    massFlowRate: numberParam('mdot', { default: s.massFlowRate, min: 0.01, max: 1e5 }),
    drag: new URLSearchParams(location.search).has('drag') ? flagParam('drag') : true,
    warp: numberParam('warp', { default: planet === 'earth' ? 10 : 1, min: 1, max: 50, integer: true }),
    throttle: 1,
    reset: () => game.shell.reset(),
  };
});

let handles!: RocketHandles;
const model = new Float64Array(2);
const orbit = new Float64Array(2);
const PLOT_EVERY = 3;

function createWorld(): PhysicsWorld {
  const options = resolveRocketOptions({
    planet: params.planet,
    dryMass: params.dryMass,
    fuel: params.fuel,
    exhaustVelocity: params.exhaustVelocity,
    massFlowRate: params.massFlowRate,
    drag: params.drag,
    warp: params.warp,
  });
  const world = createPhysicsWorld(rocketWorldOptions(options));
  handles = buildRocket(world, options);
  params.throttle = 1;
  return world;
}

// ---- Controls: held keys steer and throttle in simulated time ---------------------------------------

const keys = trackHeldKeys(['arrowleft', 'arrowright', 'arrowup', 'arrowdown', 'a', 'd', 'w', 's']);

/** Reads the held keys into throttle and heading for a step of `dt` s. */
function pilot(dt: number): void {
  const left = keys.held('arrowleft') || keys.held('a'),
    right = keys.held('arrowright') || keys.held('d');
  const up = keys.held('arrowup') || keys.held('w'),
    down = keys.held('arrowdown') || keys.held('s');
  if (left !== right) handles.heading += (left ? 1 : -1) * handles.spec.turnRate * dt;
  if (up !== down) setThrottle(handles.throttle + (up ? 1 : -1) * 0.8 * dt * Math.max(1, 1 / params.warp));
}

/** Sets the throttle, clamped to [0, 1]. */
function setThrottle(t: number): void {
  handles.throttle = Math.min(1, Math.max(0, t));
  params.throttle = handles.throttle;
}

function stepLab(world: PhysicsWorld): void {
  pilot(world.dt);
  applyControls(world, handles);
  step(world);
  if (world.steps % PLOT_EVERY === 0) {
    uniformGravityModel(world, handles, model);
    const m = world.components.Mass.value[handles.rocket]!;
    speedPlot.push(world.time, speed(world, handles), tsiolkovsky(handles.params.exhaustVelocity, handles.initialMass, m), model[0]!);
    altitudePlot.push(world.time, altitude(world, handles), model[1]!);
  }
}

const game = await startPixiGame({
  title: 'Rocket',
  createWorld,
  step: stepLab,
  bodies: () => (handles.planet === 0 ? 1 : 2),
  controls: [
    { keys: '↑ / ↓', action: 'throttle up / down (W / S)' },
    { keys: '← / →', action: 'steer (A / D)' },
    { keys: 'Space', action: 'engine off' },
    { keys: 'Z', action: 'full throttle' },
  ],
  keys: [
    { key: ' ', label: 'engine off', action: () => setThrottle(0) },
    { key: 'z', label: 'full throttle', action: () => setThrottle(1) },
  ],
  renderer: { pixelsPerMeter: 5, rotation: false, trails: { length: 400, maxEntities: 4, width: 2, alpha: 0.6 } },
  onFrame: (alpha, world) => draw(alpha, world),
});
const { shell, renderer, app } = game;

const dock = createPlotDock(2);
const speedPlot = dock.add({
  title: 'Speed',
  yLabel: 'm/s',
  series: [
    { label: 'speed', color: '#ffd166' },
    { label: 'Tsiolkovsky ve ln(m0/m)', color: '#8ecae6', dashed: true },
    { label: '− g0 t (vertical, uniform g)', color: '#ef476f', dashed: true },
  ],
});
const altitudePlot = dock.add({
  title: 'Altitude',
  yLabel: 'm',
  series: [
    { label: 'altitude', color: '#ffd166' },
    { label: 'vertical ascent, uniform g', color: '#ef476f', dashed: true },
  ],
});

function colorBodies(): void {
  renderer.setColor(handles.rocket, 0xd9dde3);
  if (handles.planet !== 0) renderer.setColor(handles.planet, 0x2d4a2b);
}
colorBodies();
shell.onWorldChange(() => {
  speedPlot.clear();
  altitudePlot.clear();
  colorBodies();
  panel.refresh();
});

const panel = createPanel(
  params,
  [
    {
      type: 'choice',
      key: 'planet',
      options: PLANETS,
      onChange: (v) => {
        const s = PLANET_SPECS[v as PlanetName];
        params.dryMass = s.dryMass;
        params.fuel = s.fuel;
        params.exhaustVelocity = s.exhaustVelocity;
        params.massFlowRate = s.massFlowRate;
        params.warp = v === 'earth' ? 10 : 1;
        shell.reset();
      },
    },
    { type: 'slider', key: 'throttle', min: 0, max: 1, step: 0.01, onChange: (v) => setThrottle(v) },
    {
      type: 'slider',
      key: 'dryMass',
      label: 'dry mass (kg, resets)',
      min: 1,
      max: 100_000,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'fuel',
      label: 'fuel (kg, resets)',
      min: 0,
      max: 1_000_000,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'exhaustVelocity',
      label: 'exhaust velocity (m/s, resets)',
      min: 10,
      max: 5000,
      step: 1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'slider',
      key: 'massFlowRate',
      label: 'mass flow (kg/s, resets)',
      min: 0.1,
      max: 5000,
      step: 0.1,
      onRelease: true,
      onChange: () => shell.reset(),
    },
    {
      type: 'checkbox',
      key: 'drag',
      label: 'air drag',
      onChange: (v) => {
        handles.params.drag = v === true;
      },
    },
    { type: 'choice', key: 'warp', label: 'time warp (resets)', options: [1, 2, 5, 10, 20, 50], onChange: () => shell.reset() },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Rocket' },
);

// ---- Drawing -----------------------------------------------------------------------------------------

const ground = new Graphics({ label: 'planet' });
const craft = new Graphics({ label: 'rocket' });
app.stage.addChild(ground, craft);
const status = createStatusLine();
let frame = 0;

function draw(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  const P = world.components.Position,
    O = world.components.PreviousPosition,
    e = handles.rocket,
    s = handles.spec;
  const x = O.x[e]! + (P.x[e]! - O.x[e]!) * alpha,
    y = O.y[e]! + (P.y[e]! - O.y[e]!) * alpha;
  const alt = Math.max(0, altitude(world, handles));
  // Follow the rocket; zoom out as it climbs so the ground below stays in view.
  const half = Math.max(4 * s.rocketLength, 1.15 * (alt + s.rocketLength));
  cam.setPixelsPerMeter(cam.height / 2 / half, x, y);
  renderer.render(alpha);
  // Sky: dark blue fading to black with the air density at the rocket's height. It is the canvas'
  // clear colour, not a full-screen rectangle: under software WebGL every full-screen fill costs frames.
  const f = handles.planet === 0 ? 0 : Math.exp(-alt / s.scaleHeight);
  app.renderer.background.color = (Math.round(8 + 30 * f) << 16) | (Math.round(10 + 60 * f) << 8) | Math.round(20 + 110 * f);
  drawPlanet();
  drawRocket(world, x, y);
  if (++frame % 10 === 1) {
    status.set(statusLine(world));
    panel.controller('throttle').updateDisplay();
  }
}

/** The planet: a full disc when it fits the screen, else the arc of ground near the view (a band between two arcs). */
function drawPlanet(): void {
  ground.clear();
  if (handles.planet === 0) return;
  const cam = renderer.camera,
    R = handles.spec.radius;
  const px = cam.toScreenX(0),
    py = cam.toScreenY(0),
    pr = cam.toScreenLength(R);
  if (pr < 4000) {
    ground.circle(px, py, pr).fill({ color: 0x2d4a2b }).stroke({ width: 2, color: 0x6a8f4e });
  } else {
    const v = cam.visibleRect();
    const cx = (v.minX + v.maxX) / 2,
      cy = (v.minY + v.maxY) / 2;
    const diag = Math.hypot(v.maxX - v.minX, v.maxY - v.minY);
    const phi = Math.atan2(cy, cx),
      span = Math.min(Math.PI, (2 * diag) / R),
      depth = Math.min(R, 2 * diag);
    const n = 96;
    for (let i = 0; i <= n; i++) {
      const a = phi - span + (2 * span * i) / n;
      const sx = cam.toScreenX(R * Math.cos(a)),
        sy = cam.toScreenY(R * Math.sin(a));
      if (i === 0) ground.moveTo(sx, sy);
      else ground.lineTo(sx, sy);
    }
    for (let i = n; i >= 0; i--) {
      const a = phi - span + (2 * span * i) / n;
      ground.lineTo(cam.toScreenX((R - depth) * Math.cos(a)), cam.toScreenY((R - depth) * Math.sin(a)));
    }
    ground.closePath().fill({ color: 0x2d4a2b });
    for (let i = 0; i <= n; i++) {
      const a = phi - span + (2 * span * i) / n;
      const sx = cam.toScreenX(R * Math.cos(a)),
        sy = cam.toScreenY(R * Math.sin(a));
      if (i === 0) ground.moveTo(sx, sy);
      else ground.lineTo(sx, sy);
    }
    ground.stroke({ width: 2, color: 0x6a8f4e });
  }
  // The launch pad at the north pole.
  const w = Math.max(6, cam.toScreenLength(3 * handles.spec.rocketRadius));
  ground.rect(cam.toScreenX(0) - w / 2, cam.toScreenY(R) - 3, w, 3).fill({ color: 0x98a2b3 });
}

/** The rocket along its heading (at least 26 px long so it stays visible when zoomed out), with its flame. */
function drawRocket(world: PhysicsWorld, x: number, y: number): void {
  const cam = renderer.camera,
    s = handles.spec;
  const len = Math.max(26, cam.toScreenLength(s.rocketLength)),
    wid = len * 0.22;
  const ux = Math.cos(handles.heading),
    uy = -Math.sin(handles.heading); // screen y points down
  const nx = -uy,
    ny = ux;
  const base = Math.max(cam.toScreenLength(s.rocketRadius), len * 0.12);
  const bx = cam.toScreenX(x) - ux * base,
    by = cam.toScreenY(y) - uy * base;
  craft.clear();
  const T = world.components.Thrust;
  if (T.fuel[handles.rocket]! > 0 && handles.throttle > 0) {
    const fl = len * (0.35 + 0.5 * handles.throttle);
    craft
      .moveTo(bx + nx * wid * 0.4, by + ny * wid * 0.4)
      .lineTo(bx - ux * fl, by - uy * fl)
      .lineTo(bx - nx * wid * 0.4, by - ny * wid * 0.4)
      .closePath()
      .fill({ color: 0xffa94d, alpha: 0.9 });
  }
  const tx = bx + ux * len,
    ty = by + uy * len;
  craft
    .moveTo(bx + (nx * wid) / 2, by + (ny * wid) / 2)
    .lineTo(bx + ux * len * 0.75 + (nx * wid) / 2, by + uy * len * 0.75 + (ny * wid) / 2)
    .lineTo(tx, ty)
    .lineTo(bx + ux * len * 0.75 - (nx * wid) / 2, by + uy * len * 0.75 - (ny * wid) / 2)
    .lineTo(bx - (nx * wid) / 2, by - (ny * wid) / 2)
    .closePath()
    .fill({ color: 0xd9dde3 })
    .stroke({ width: 1, color: 0x5c677d });
}

function fmt(m: number): string {
  if (!Number.isFinite(m)) return m > 0 ? '∞' : '…';
  return Math.abs(m) >= 1e4 ? `${(m / 1000).toFixed(0)} km` : `${m.toFixed(0)} m`;
}

function statusLine(world: PhysicsWorld): string {
  const e = handles.rocket;
  const fuel = world.components.Thrust.fuel[e]!;
  const alt = altitude(world, handles);
  let text =
    `alt ${fmt(alt)} · v ${speed(world, handles).toFixed(1)} m/s · fuel ${fuel.toFixed(0)} kg · throttle ${(handles.throttle * 100).toFixed(0)}% · ` +
    `heading ${((handles.heading * 180) / Math.PI).toFixed(0)}°`;
  if (handles.planet !== 0) {
    orbitAltitudes(world, handles, orbit);
    const inOrbit = orbit[0]! > 3 * handles.spec.scaleHeight;
    text +=
      orbit[1] === Infinity
        ? ' · escape trajectory'
        : orbit[0]! < 0
          ? ` · suborbital, apoapsis ${fmt(orbit[1]!)}`
          : ` · orbit ${fmt(orbit[0]!)} × ${fmt(orbit[1]!)}${inOrbit ? ' (in orbit!)' : ' (grazes the air)'}`;
  }
  if (params.warp > 1) text += ` · warp ×${params.warp}`;
  return text;
}

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  plot: speedPlot,
  speedPlot,
  altitudePlot,
  /** The scene handles (throttle, heading, lift-off, ...). */
  handles: (): RocketHandles => handles,
  /** Speed (m/s), altitude (m), mass (kg), fuel (kg) and Tsiolkovsky's ideal speed (m/s) now. */
  state: () => {
    const w = shell.world,
      m = w.components.Mass.value[handles.rocket]!;
    return {
      speed: speed(w, handles),
      altitude: altitude(w, handles),
      mass: m,
      fuel: w.components.Thrust.fuel[handles.rocket]!,
      tsiolkovsky: tsiolkovsky(handles.params.exhaustVelocity, handles.initialMass, m),
      throttle: handles.throttle,
      heading: handles.heading,
    };
  },
  /** Sets the throttle in [0, 1] (clamped). */
  setThrottle,
  /** Runs `n` steps now (with the controls and plot samples). @throws RangeError unless n is an integer in [0, 100000]. */
  advance: (n: number): void => {
    if (!(Number.isInteger(n) && n >= 0 && n <= 100_000)) throw new RangeError(`advance: n must be an integer in [0, 100000], got ${n}`);
    for (let i = 0; i < n; i++) stepLab(shell.world);
  },
});
