/**
 * Lab: splash (Ramtal and Dobre ch. 12). Raindrops fall onto a pool and onto the ground; each impact
 * is a burst of an emitter at the impact point: on the ground (found through the drop's contact with
 * the ground segment) droplets fly up, fall under gravity and drag, bounce with the ground's
 * restitution and fade; in the pool (found as the drop crosses the surface) a crown of droplets rises
 * and falls back in, leaving ripples. See scene.ts for the physics.
 *
 * Input: click drops a raindrop at the pointer, P pause, N step, R reset.
 * URL: ?rain (0-40 drops/s), ?droplets (per m/s of impact, 0-20), ?restitution (0-1), ?seed.
 */

import { createPanel, numberParam, plural, pointerOnCanvas, seedParam } from '@bitphysics/game-kit';
import { createReadout, readUrlParams } from '@bitphysics/game-kit/lab-kit';
import { advanceSteps, exposeLive, fmt, hideBallLayer } from '@bitphysics/game-kit/particle-kit';
import { startPixiGame } from '@bitphysics/game-kit/pixi';
import type { PhysicsWorld } from '@bitphysics/physics';
import type { Point2 } from '@bitphysics/render-pixi';
import { Graphics } from 'pixi.js';
import {
  CLOUD_HEIGHT,
  createSplash,
  dropAt,
  dropCount,
  GROUND_END,
  MAX_RAIN,
  MAX_RIPPLES,
  POOL,
  type Splash,
  setDropletsPerSpeed,
  setGroundRestitution,
  setRain,
  splashCount,
  stepSplash,
} from './scene';

const VIEW = { minX: POOL.minX - 0.3, minY: POOL.bottom - 0.3, maxX: GROUND_END + 0.3, maxY: CLOUD_HEIGHT + 0.3 };
/** How long a ripple lasts, s, and how fast it spreads, m/s. */
const RIPPLE_LIFE = 1.2,
  RIPPLE_SPEED = 0.6;

const USAGE = `Accepted: rain 0-${MAX_RAIN} drops/s; droplets 0-20 per m/s; restitution 0-1; seed (integer).`;
const url = readUrlParams(
  () => ({
    rain: numberParam('rain', { default: 6, min: 0, max: MAX_RAIN }),
    droplets: numberParam('droplets', { default: 2, min: 0, max: 20 }),
    restitution: numberParam('restitution', { default: 0.35, min: 0, max: 1 }),
    seed: seedParam(),
  }),
  USAGE,
);
const params = { ...url, trails: true, reset: () => shell.reset() };

let splash: Splash;
function createWorld(): PhysicsWorld {
  splash = createSplash({ rain: params.rain, dropletsPerSpeed: params.droplets, restitution: params.restitution, seed: params.seed });
  return splash.world;
}

const TRAILS = { duration: 0.04, width: 0.5, alpha: 0.5 };
const game = await startPixiGame({
  title: 'Splash',
  createWorld,
  step: () => stepSplash(splash),
  bodies: () => dropCount(splash) + splashCount(splash),
  controls: [{ keys: 'Click', action: 'drop a raindrop' }],
  renderer: { view: VIEW, padding: 0, segmentColor: 0x8a7a62, particles: { blend: 'normal', minPixelSize: 2, trails: TRAILS } },
  app: { background: 0x0b1220 },
  onFrame: (_alpha, world) => drawFrame(world),
});
const { shell, renderer, app } = game;
// Drops and droplets have colliders, hence Balls: the particle layer draws them, the ball layer must not.
hideBallLayer(renderer);
const layer = renderer.particles!;

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'rain', label: 'rain (drops/s)', min: 0, max: MAX_RAIN, step: 0.5, onChange: (v) => setRain(splash, v) },
    {
      type: 'slider',
      key: 'droplets',
      label: 'droplets per m/s',
      min: 0,
      max: 20,
      step: 0.5,
      onChange: (v) => setDropletsPerSpeed(splash, v),
    },
    {
      type: 'slider',
      key: 'restitution',
      label: 'ground restitution',
      min: 0,
      max: 1,
      step: 0.01,
      onChange: (v) => setGroundRestitution(splash, v),
    },
    { type: 'checkbox', key: 'trails', label: 'trails', onChange: (v) => layer.setTrails(v === true ? TRAILS : false) },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Splash' },
);

const info = createReadout(shell.hud.readout, ['raindrops falling', 'splash droplets', 'impacts', 'last impact']);

// ---- Drawing: pool, ground, ripples --------------------------------------------------------------------

const scenery = new Graphics({ label: 'pool-and-ground' });
const ripples = new Graphics({ label: 'ripples' });
renderer.root.addChildAt(scenery, 0);
renderer.root.addChild(ripples);
let sceneryVersion = -1,
  frame = 0;

function drawFrame(world: PhysicsWorld): void {
  const cam = renderer.camera;
  if (cam.version !== sceneryVersion) {
    sceneryVersion = cam.version;
    scenery.clear();
    // Night sky, lighter towards the horizon.
    const bands = 12,
      top = cam.toWorldY(0);
    for (let i = 0; i < bands; i++) {
      const y1 = (top * (i + 1)) / bands,
        y0 = (top * i) / bands,
        f = 1 - i / bands;
      const color = (Math.round(11 + 22 * f) << 16) | (Math.round(18 + 30 * f) << 8) | Math.round(32 + 40 * f);
      scenery.rect(0, cam.toScreenY(y1), cam.width, cam.toScreenY(y0) - cam.toScreenY(y1) + 1).fill(color);
    }
    const x0 = cam.toScreenX(POOL.minX),
      x1 = cam.toScreenX(POOL.maxX),
      y0 = cam.toScreenY(0),
      yb = cam.toScreenY(POOL.bottom);
    scenery.rect(x0, y0, x1 - x0, yb - y0).fill({ color: 0x1d4f86, alpha: 0.85 });
    scenery.rect(0, yb, cam.width, cam.height - yb).fill(0x2a2620);
    scenery.rect(x1, y0, cam.width - x1, cam.height - y0).fill(0x3b3328);
    scenery.rect(0, y0, x0, cam.height - y0).fill(0x3b3328);
    // The cloud line the rain falls from.
    scenery.rect(x0, cam.toScreenY(CLOUD_HEIGHT) - 3, cam.toScreenX(GROUND_END) - x0, 6).fill({ color: 0x5a6a80, alpha: 0.5 });
  }
  ripples.clear();
  const y = cam.toScreenY(0);
  for (let i = 0; i < MAX_RIPPLES; i++) {
    const age = world.time - splash.rippleT[i]!;
    if (!(age >= 0 && age < RIPPLE_LIFE)) continue;
    const r = cam.toScreenLength(0.1 + RIPPLE_SPEED * age);
    ripples
      .ellipse(cam.toScreenX(splash.rippleX[i]!), y, r, Math.max(1.5, r * 0.18))
      .stroke({ width: 1.5, color: 0xcfe6ff, alpha: 0.7 * (1 - age / RIPPLE_LIFE) });
  }
  if (frame++ % 6 === 0) {
    info.set(0, String(dropCount(splash)));
    info.set(1, String(splashCount(splash)));
    info.set(2, `${splash.groundImpacts} ground, ${splash.waterImpacts} water (${plural(splash.absorbed, 'droplet', 'droplets')} back in)`);
    const l = splash.last;
    info.set(
      3,
      l.surface === '' ? '–' : `${l.surface} at x = ${fmt(l.x)} m, ${fmt(l.speed)} m/s, ${plural(l.droplets, 'droplet', 'droplets')}`,
    );
  }
}

// ---- Pointer: click drops a raindrop ---------------------------------------------------------------------

const canvas = app.canvas;
const at: Point2 = { x: 0, y: 0 };
canvas.addEventListener('pointerdown', (event) => {
  if (event.button !== 0) return;
  pointerOnCanvas(canvas, event, at);
  const x = renderer.camera.toWorldX(at.x),
    yw = renderer.camera.toWorldY(at.y);
  if (yw > 0.1) dropAt(splash, x, yw);
});

// ---- Test and console hooks on window.game -------------------------------------------------------------

shell.expose({
  params,
  panel,
  /** Splash droplets alive now (ground and water splashes). */
  splashCount: (): number => splashCount(splash),
  /** Raindrops in the air now. */
  dropCount: (): number => dropCount(splash),
  /** Drops a raindrop at (x, y), m. @returns 1 if made. */
  drop: (x: number, y: number): number => dropAt(splash, x, y),
  /** Runs `n` (integer >= 0) steps now. @throws RangeError otherwise. */
  advance: (n: number): void => advanceSteps(n, () => stepSplash(splash)),
  layer,
});
exposeLive(shell, {
  /** The running splash: emitters, ground, settings, impact counters, last impact. */
  splash: (): Splash => splash,
});
