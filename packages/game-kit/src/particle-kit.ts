/**
 * Particle-lab kit: the page pieces the seven particle labs of Ramtal and Dobre ch. 12 share
 * (lab-galaxy, lab-wormhole, lab-splash, lab-smoke, lab-fire, lab-sparks, lab-attractors), on top of
 * the game kit and the lab kit (./lab-kit), whose readout (`createReadout`),
 * number format (`fmt`) and URL-parameter error box (`readUrlParams`) they use as they are. Particle
 * counts, step timing, hiding the ball layer, click-or-drag input and test hooks only: no physics in here.
 */

import { type PhysicsWorld, slotOf } from '@bitphysics/physics';
import type { WorldRenderer } from '@bitphysics/render-pixi';
import { query } from 'bitecs';
import { fmt as labFmt } from './lab-kit.js';
import { pointerOnCanvas } from './pointer.js';

/** Formats `value` for the particle labs' readouts: the lab kit's `fmt`, at 3 significant digits by default. */
export function fmt(value: number, digits = 3): string {
  return labFmt(value, digits);
}

/**
 * Hides the WorldRenderer's ball layer. Emitted particles with a collider radius have a Ball, so the
 * ball layer would draw each one a second time (a seeded-colour disc on top of its particle); labs
 * whose only balls are such particles hide the layer and let the ParticleLayer draw them. Found by
 * the layer's label ('balls'), as the renderer has no option for it (reported).
 * @throws Error if the renderer has no child labelled 'balls'.
 */
export function hideBallLayer(renderer: WorldRenderer): void {
  const balls = renderer.root.getChildByLabel('balls');
  if (!balls) throw new Error('hideBallLayer: the renderer has no ball layer labelled "balls"');
  balls.visible = false;
}

/**
 * "Click or drag moves it": calls `moveTo(x, y)` with the world point (m) under the pointer when the
 * left button goes down on `canvas`, and again on every move while that pointer stays down (it is
 * captured, so a drag may leave the canvas). One pointer at a time. The fire and smoke labs move
 * their source this way.
 */
export function followPointerWhileDown(canvas: HTMLCanvasElement, renderer: WorldRenderer, moveTo: (x: number, y: number) => void): void {
  const at = { x: 0, y: 0 };
  let pointerId = -1;
  const move = (event: PointerEvent): void => {
    pointerOnCanvas(canvas, event, at);
    moveTo(renderer.camera.toWorldX(at.x), renderer.camera.toWorldY(at.y));
  };
  canvas.addEventListener('pointerdown', (event) => {
    if (event.button !== 0 || pointerId !== -1) return;
    pointerId = event.pointerId;
    canvas.setPointerCapture(event.pointerId);
    move(event);
  });
  canvas.addEventListener('pointermove', (event) => {
    if (event.pointerId === pointerId) move(event);
  });
  const release = (event: PointerEvent): void => {
    if (event.pointerId === pointerId) pointerId = -1;
  };
  canvas.addEventListener('pointerup', release);
  canvas.addEventListener('pointercancel', release);
}

/**
 * Live particles of `world` that emitter `emitter` made (every particle if `emitter` is 0 or
 * omitted). Walks the live Particle list once: O(particles), no allocation.
 */
export function countParticles(world: PhysicsWorld, emitter = 0): number {
  const c = world.components;
  const ents = query(world, [c.Particle]);
  if (emitter === 0) return ents.length;
  const em = c.Particle.emitter,
    slot = slotOf(emitter); // Particle.emitter holds the emitter's slot
  let n = 0;
  for (let i = 0; i < ents.length; i++) if (em[ents[i]!] === slot) n++;
  return n;
}

/**
 * Mean position (m) of the live particles of emitter `emitter` (every particle if 0), written into
 * `out` [x, y]; returns how many there are (out is left as NaN when there are none). O(particles).
 */
export function particleCentroid(world: PhysicsWorld, emitter: number, out: Float64Array | number[]): number {
  const c = world.components;
  const ents = query(world, [c.Particle]);
  const em = c.Particle.emitter,
    px = c.Position.x,
    py = c.Position.y,
    slot = slotOf(emitter);
  let n = 0,
    sx = 0,
    sy = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    if (emitter !== 0 && em[e] !== slot) continue;
    sx += px[e]!;
    sy += py[e]!;
    n++;
  }
  out[0] = n > 0 ? sx / n : Number.NaN;
  out[1] = n > 0 ? sy / n : Number.NaN;
  return n;
}

/** Wall-clock cost of physics steps, ms: the last one and an exponential moving average. */
export interface StepTimer {
  /** Milliseconds the last timed step took. */
  readonly last: number;
  /** Moving average over roughly the last 10 steps, ms (NaN before the first). */
  readonly mean: number;
  /** Steps timed since the last reset. */
  readonly count: number;
  /** Runs `step(world)` and times it. */
  run(step: (world: PhysicsWorld) => void, world: PhysicsWorld): void;
  /** Forgets every measurement (after a rebuild). */
  reset(): void;
}

/** Creates a step timer (performance.now around each step; an average with weight 0.1 for the newest). */
export function createStepTimer(): StepTimer {
  let last = Number.NaN,
    mean = Number.NaN,
    count = 0;
  return {
    get last() {
      return last;
    },
    get mean() {
      return mean;
    },
    get count() {
      return count;
    },
    run(step, world) {
      const t0 = performance.now();
      step(world);
      last = performance.now() - t0;
      mean = count === 0 ? last : mean + 0.1 * (last - mean);
      count++;
    },
    reset() {
      last = Number.NaN;
      mean = Number.NaN;
      count = 0;
    },
  };
}

/**
 * Defines live read-only fields on `target` (the game shell, so also `window.game`): each reads its
 * getter every time, so it follows the world across resets. (`shell.expose` copies values with
 * Object.assign, which would freeze a getter's value at the time of the call.)
 * @throws TypeError if `target` already has a field of one of the names.
 */
export function exposeLive(target: object, getters: Readonly<Record<string, () => unknown>>): void {
  for (const [name, get] of Object.entries(getters)) {
    if (name in target) throw new TypeError(`exposeLive: ${JSON.stringify(name)} is already a field of the target`);
    Object.defineProperty(target, name, { get, enumerable: true, configurable: true });
  }
}

/**
 * Checks `n` is an integer >= 0 and runs `step` n times: the labs' `window.game.advance(n)`, which
 * tests call while the page is paused to move the simulation by exact steps.
 * @throws RangeError otherwise.
 */
export function advanceSteps(n: number, step: () => void): void {
  if (!Number.isInteger(n) || n < 0) throw new RangeError(`advance: n must be an integer >= 0, got ${n}`);
  for (let i = 0; i < n; i++) step();
}
