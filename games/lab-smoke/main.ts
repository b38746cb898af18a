/**
 * Lab: smoke (Ramtal and Dobre ch. 12). A chimney's emitter releases puffs that rise by buoyancy,
 * drift with the wind and its turbulence through linear drag, grow and fade (see scene.ts for the
 * physics). The number of puffs alive settles where as many expire as are born: rate x mean lifetime.
 *
 * Input: click or drag moves the chimney, P pause, N step, R reset.
 * URL: ?rate (0-600 /s), ?wind (-10..10 m/s), ?turbulence (0-5 m/s), ?buoyancy (0-2), ?seed.
 */

import { createPanel, numberParam, seedParam } from '@bitphysics/game-kit';
import { createReadout, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { advanceSteps, countParticles, exposeLive, fmt, followPointerWhileDown, particleCentroid } from '@bitphysics/game-kit/particle-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import { type PhysicsWorld, windAt } from '@bitphysics/physics';
import { Graphics } from 'pixi.js';
import {
  createSmoke,
  MAX_RATE,
  moveSmokeSource,
  PUFF_LIFETIME,
  type Smoke,
  setSmokeBuoyancy,
  setSmokeRate,
  setSmokeWind,
  stepSmoke,
} from './scene';

/** The ground's height, m, and the lowest the chimney top may be above it. */
const GROUND = -1.5,
  MIN_CHIMNEY = 0.4;
const VIEW = { minX: -6, minY: GROUND - 0.3, maxX: 14, maxY: 11 };

const USAGE = `Accepted: rate 0-${MAX_RATE} /s; wind -10..10 m/s; turbulence 0-5 m/s; buoyancy 0-2; seed (integer).`;
const url = readUrlParams(
  () => ({
    rate: numberParam('rate', { default: 120, min: 0, max: MAX_RATE }),
    wind: numberParam('wind', { default: 1.5, min: -10, max: 10 }),
    turbulence: numberParam('turbulence', { default: 0.8, min: 0, max: 5 }),
    buoyancy: numberParam('buoyancy', { default: 0.25, min: 0, max: 2 }),
    seed: seedParam(),
  }),
  USAGE,
);
const params = { ...url, reset: () => shell.reset() };

let smoke: Smoke;
function createWorld(): PhysicsWorld {
  smoke = createSmoke({
    rate: params.rate,
    wind: params.wind,
    turbulence: params.turbulence,
    buoyancy: params.buoyancy,
    seed: params.seed,
  });
  return smoke.world;
}

const game = await startPixiGame({
  title: 'Smoke',
  createWorld,
  step: () => stepSmoke(smoke),
  bodies: (world) => countParticles(world),
  controls: [{ keys: 'Click', action: 'move the chimney (or drag it)' }],
  renderer: { view: VIEW, padding: 0, particles: { blend: 'normal', minPixelSize: 2 } },
  app: { background: 0x8fa3b8 },
  onFrame: (_alpha, world) => drawFrame(world),
});
const { shell, renderer, app } = game;

const panel = createPanel(
  params,
  [
    {
      type: 'slider',
      key: 'wind',
      label: 'wind (m/s)',
      min: -6,
      max: 8,
      step: 0.1,
      onChange: (v, p) => setSmokeWind(smoke, v, p.turbulence),
    },
    {
      type: 'slider',
      key: 'turbulence',
      label: 'turbulence (m/s rms)',
      min: 0,
      max: 3,
      step: 0.05,
      onChange: (v, p) => setSmokeWind(smoke, p.wind, v),
    },
    { type: 'slider', key: 'rate', label: 'rate (puffs/s)', min: 0, max: MAX_RATE, step: 1, onChange: (v) => setSmokeRate(smoke, v) },
    {
      type: 'slider',
      key: 'buoyancy',
      label: 'buoyancy (× weight)',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (v) => setSmokeBuoyancy(smoke, v),
    },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Smoke' },
);

const info = createReadout(shell.hud.readout, ['puffs alive', 'steady state', 'wind at the chimney']);

// ---- Drawing: sky, ground, chimney, a wind vane ------------------------------------------------------

const scenery = new Graphics({ label: 'scenery' });
renderer.root.addChildAt(scenery, 0);
const chimney = new Graphics({ label: 'chimney' });
renderer.root.addChild(chimney);
const wind = new Float64Array(3);
let sceneryVersion = -1,
  frame = 0;

function drawFrame(world: PhysicsWorld): void {
  const cam = renderer.camera;
  if (cam.version !== sceneryVersion) {
    sceneryVersion = cam.version;
    scenery.clear();
    const r = cam.visibleRect();
    const bands = 10;
    for (let i = 0; i < bands; i++) {
      const y0 = GROUND + ((r.maxY - GROUND) * i) / bands,
        y1 = GROUND + ((r.maxY - GROUND) * (i + 1)) / bands;
      const f = i / bands;
      const color = (Math.round(150 - 60 * f) << 16) | (Math.round(172 - 50 * f) << 8) | Math.round(196 - 30 * f);
      scenery.rect(0, cam.toScreenY(y1), cam.width, cam.toScreenY(y0) - cam.toScreenY(y1) + 1).fill(color);
    }
    scenery.rect(0, cam.toScreenY(GROUND), cam.width, cam.height).fill(0x4a5a3c);
  }
  const [sx, sy] = smoke.source;
  chimney.clear();
  const w = cam.toScreenLength(0.7);
  chimney.rect(cam.toScreenX(sx) - w / 2, cam.toScreenY(sy), w, cam.toScreenY(GROUND) - cam.toScreenY(sy)).fill(0x7a4a3a);
  chimney.rect(cam.toScreenX(sx) - w * 0.6, cam.toScreenY(sy), w * 1.2, cam.toScreenLength(0.18)).fill(0x5b352a);
  // Wind vane at the top right: an arrow as long as the wind at the chimney, 1 m/s = 0.5 m.
  windAt(world, sx, sy, 0, world.time, wind);
  const ax = cam.toScreenX(VIEW.maxX - 3),
    ay = cam.toScreenY(VIEW.maxY - 1.2);
  const len = cam.toScreenLength(0.5);
  chimney
    .moveTo(ax, ay)
    .lineTo(ax + wind[0]! * len, ay - wind[1]! * len)
    .stroke({ width: 3, color: 0xffffff, alpha: 0.8 });
  chimney.circle(ax, ay, 3).fill({ color: 0xffffff, alpha: 0.8 });
  if (frame++ % 6 === 0) {
    const mean = (PUFF_LIFETIME[0] + PUFF_LIFETIME[1]) / 2;
    info.set(0, String(countParticles(world)));
    info.set(1, `≈ ${Math.round(smoke.settings.rate * mean)} (rate × ${mean} s)`);
    info.set(2, `(${fmt(wind[0]!, 2)}, ${fmt(wind[1]!, 2)}) m/s`);
  }
}

// ---- Pointer: click or drag moves the chimney ----------------------------------------------------------

followPointerWhileDown(app.canvas, renderer, (x, y) => moveSmokeSource(smoke, x, Math.max(GROUND + MIN_CHIMNEY, y)));

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  /** Puffs alive now. */
  particleCount: (): number => countParticles(shell.world),
  /** Runs `n` (integer >= 0) steps now. @throws RangeError otherwise. */
  advance: (n: number): void => advanceSteps(n, () => stepSmoke(smoke)),
  /** Mean position of the puffs alive, m, [x, y] ([NaN, NaN] when there are none). */
  puffCentroid: (): number[] => {
    const out = [Number.NaN, Number.NaN];
    particleCentroid(shell.world, 0, out);
    return out;
  },
  /** Moves the chimney to (x, y), m. */
  moveSource: (x: number, y: number): void => moveSmokeSource(smoke, x, y),
});
exposeLive(shell, {
  /** The running smoke: world, emitter id, source position, settings. */
  smoke: (): Smoke => smoke,
});
