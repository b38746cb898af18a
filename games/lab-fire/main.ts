/**
 * Lab: fire (Ramtal and Dobre ch. 12). Many short-lived flame particles rise from the logs with a
 * random spread, going yellow-white to orange, and each becomes a glow particle going red to dark:
 * additive blending makes the dense core white-hot. Sparks fly up with streak trails and smoke rises
 * above (see scene.ts for the physics and the flicker).
 *
 * Input: click or drag moves the fire, P pause, N step, R reset.
 * URL: ?intensity (0-3), ?wind (-6..6 m/s), ?smoke=0|1, ?seed.
 */

import { createPanel, flagParam, numberParam, seedParam } from '@bitphysics/game-kit';
import { createReadout, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { advanceSteps, countParticles, exposeLive, fmt, followPointerWhileDown } from '@bitphysics/game-kit/particle-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import type { PhysicsWorld } from '@bitphysics/physics';
import { ParticleLayer } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import {
  createFire,
  FIRE_LIFETIMES,
  FIRE_RATES,
  type Fire,
  MAX_INTENSITY,
  moveFire,
  setFireIntensity,
  setFireSmoke,
  setFireWind,
  stepFire,
} from './scene';

const GROUND = 0;
/** The logs under the fire: offset from the fire (m, m) and tilt (fraction of their thickness). */
const LOGS: ReadonlyArray<readonly [number, number, number]> = [
  [-0.55, 0.12, 0.25],
  [0.55, 0.12, -0.25],
  [0, 0.2, 0],
];
const VIEW = { minX: -4, minY: -0.6, maxX: 4, maxY: 4.4 };

const USAGE = `Accepted: intensity 0-${MAX_INTENSITY}; wind -6..6 m/s; smoke 0|1; seed (integer).`;
const search = new URLSearchParams(location.search);
const url = readUrlParams(
  () => ({
    intensity: numberParam('intensity', { default: 1, min: 0, max: MAX_INTENSITY }),
    wind: numberParam('wind', { default: 0, min: -6, max: 6 }),
    smoke: search.has('smoke') ? flagParam('smoke') : true,
    seed: seedParam(),
  }),
  USAGE,
);
const params = { ...url, trails: true, additive: true, reset: () => shell.reset() };

let fire: Fire;
function createWorld(): PhysicsWorld {
  fire = createFire({ intensity: params.intensity, wind: params.wind, smoke: params.smoke, seed: params.seed });
  return fire.world;
}

/** Emitter of particle `e` of `world`. */
const emitterOf = (world: PhysicsWorld, e: number): number => world.components.Particle.emitter[e]!;

const game = await startPixiGame({
  title: 'Fire',
  createWorld,
  step: () => stepFire(fire),
  bodies: (world) => countParticles(world),
  controls: [{ keys: 'Click', action: 'move the fire (or drag it)' }],
  renderer: {
    view: VIEW,
    padding: 0,
    // The flames and their glow: additive, so overlapping particles add up towards white.
    particles: {
      blend: 'add',
      minPixelSize: 2,
      include: (w, e) => {
        const em = emitterOf(w, e);
        return em === fire.flames || em === fire.glow;
      },
    },
  },
  app: { background: 0x07060a },
  onFrame: (alpha, world) => drawFrame(alpha, world),
});
const { shell, renderer, app } = game;
const flameLayer = renderer.particles!;

const SPARK_TRAILS = { duration: 0.12, width: 0.7, alpha: 0.7 };
const smokeLayer = new ParticleLayer({ blend: 'normal', minPixelSize: 2, include: (w, e) => emitterOf(w, e) === fire.smoke });
const sparkLayer = new ParticleLayer({
  blend: 'add',
  minPixelSize: 1.5,
  trails: SPARK_TRAILS,
  include: (w, e) => emitterOf(w, e) === fire.sparks,
});
const scenery = new Graphics({ label: 'ground-and-logs' });
// Bottom to top: scenery, smoke, (renderer: walls, trails, flames, balls, debug), sparks.
renderer.root.addChildAt(scenery, 0);
renderer.root.addChildAt(smokeLayer.container, 1);
renderer.root.addChild(sparkLayer.container);

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'intensity', min: 0, max: MAX_INTENSITY, step: 0.05, onChange: (v) => setFireIntensity(fire, v) },
    { type: 'slider', key: 'wind', label: 'wind (m/s)', min: -6, max: 6, step: 0.1, onChange: (v) => setFireWind(fire, v) },
    { type: 'checkbox', key: 'smoke', onChange: (v) => setFireSmoke(fire, v === true) },
    { type: 'checkbox', key: 'trails', label: 'spark trails', onChange: (v) => sparkLayer.setTrails(v === true ? SPARK_TRAILS : false) },
    { type: 'checkbox', key: 'additive', label: 'additive blending', onChange: (v) => flameLayer.setBlend(v === true ? 'add' : 'normal') },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Fire' },
);

const info = createReadout(shell.hud.readout, ['particles alive', 'flames + glow', 'sparks', 'smoke', 'flame rate', 'steady state']);

// ---- Drawing ----------------------------------------------------------------------------------------

let frame = 0;
function drawFrame(alpha: number, world: PhysicsWorld): void {
  const cam = renderer.camera;
  scenery.clear();
  scenery.rect(0, cam.toScreenY(GROUND), cam.width, cam.height).fill(0x17130f);
  // Three logs under the fire.
  const [x, y] = fire.at;
  for (const [dx, dy, tilt] of LOGS) {
    const lx = cam.toScreenX(x + dx),
      ly = cam.toScreenY(y - 0.25 + dy);
    const w = cam.toScreenLength(1.1),
      h = cam.toScreenLength(0.18);
    scenery
      .moveTo(lx - w / 2, ly + tilt * h)
      .lineTo(lx + w / 2, ly - tilt * h)
      .stroke({ width: h, color: 0x4a2d1a, cap: 'round' });
  }
  smokeLayer.render(world, cam, alpha);
  sparkLayer.render(world, cam, alpha);
  if (frame++ % 6 === 0) {
    const s = fire.settings.intensity,
      L = FIRE_LIFETIMES,
      R = FIRE_RATES;
    info.set(0, String(countParticles(world)));
    info.set(1, String(countParticles(world, fire.flames) + countParticles(world, fire.glow)));
    info.set(2, String(countParticles(world, fire.sparks)));
    info.set(3, String(countParticles(world, fire.smoke)));
    info.set(4, `${fmt(fire.flameRate)} /s (flicker)`);
    info.set(
      5,
      `≈ ${Math.round(s * (R.flames * (L.flames + L.glow) + R.sparks * L.sparks + (fire.settings.smoke ? R.smoke * L.smoke : 0)))}`,
    );
  }
}

// ---- Pointer: click or drag moves the fire -------------------------------------------------------------

followPointerWhileDown(app.canvas, renderer, (x, y) => moveFire(fire, x, Math.max(GROUND + 0.25, y)));

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  /** Particles alive now, all of them or those of emitter `emitter` (an id of `fire`). */
  particleCount: (emitter = 0): number => countParticles(shell.world, emitter),
  /** Runs `n` (integer >= 0) steps now. @throws RangeError otherwise. */
  advance: (n: number): void => advanceSteps(n, () => stepFire(fire)),
  /** The three particle layers (flames, smoke, sparks). */
  layers: { flames: flameLayer, smoke: smokeLayer, sparks: sparkLayer },
});
exposeLive(shell, {
  /** The running fire: world, emitter ids, position, settings, this step's flame rate. */
  fire: (): Fire => fire,
});
