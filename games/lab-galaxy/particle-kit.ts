/**
 * Particle-lab kit: the page pieces the seven particle labs of Ramtal and Dobre ch. 12 share
 * (lab-galaxy, lab-wormhole, lab-splash, lab-smoke, lab-fire, lab-sparks, lab-attractors), on top of
 * games/shared. Layout, input, counting and timing only: no physics in here.
 *
 * It lives in this folder because the lab folders are what the labs own.
 */
import { query } from 'bitecs';
import type { PhysicsWorld } from '@bitphysics/physics';
import type { WorldRenderer } from '@bitphysics/render-pixi';

const STYLE_ID = 'bp-particle-lab-style';
const CSS = `
.bp-lab-info { margin-top: 6px; padding-top: 6px; border-top: 1px solid rgba(255, 255, 255, 0.15); white-space: pre; }
.bp-lab-info .bp-lab-key { color: #98a2b3; }
.bp-lab-error { position: fixed; top: 40%; left: 50%; transform: translate(-50%, -50%); z-index: 30; max-width: 80vw;
  background: rgba(160, 20, 40, 0.95); color: #fff; border-radius: 8px; padding: 12px 16px; font: 14px/1.5 system-ui, sans-serif; white-space: pre-wrap; }
`;

function injectStyle(): void {
  if (document.getElementById(STYLE_ID)) return;
  const style = document.createElement('style');
  style.id = STYLE_ID;
  style.textContent = CSS;
  document.head.append(style);
}

/** A block of labelled lines that rewrites only the lines whose text changed. */
export interface InfoBlock {
  /** Sets line `i`'s value text. @throws RangeError if `i` is not a line index. */
  set(i: number, text: string): void;
  /** Current value text of line `i` ('' if never set or out of range). */
  get(i: number): string;
}

/**
 * Appends a block of 'label value' lines to `parent` (usually the HUD readout, `shell.hud.readout`),
 * marked `data-lab="info"`; each value span has `data-info="<i>"`.
 * @throws TypeError if `labels` is empty.
 */
export function createInfo(parent: HTMLElement, labels: readonly string[]): InfoBlock {
  if (labels.length === 0) throw new TypeError('createInfo: labels must not be empty');
  injectStyle();
  const block = document.createElement('div');
  block.className = 'bp-lab-info';
  block.dataset.lab = 'info';
  const values: HTMLElement[] = [];
  const texts: string[] = [];
  labels.forEach((label, i) => {
    const line = document.createElement('div');
    const key = document.createElement('span');
    key.className = 'bp-lab-key';
    key.textContent = `${label} `;
    const value = document.createElement('span');
    value.dataset.info = String(i);
    line.append(key, value);
    block.append(line);
    values.push(value);
    texts.push('');
  });
  parent.append(block);
  return {
    set(i, text) {
      const el = values[i];
      if (!el) throw new RangeError(`InfoBlock.set: no line ${i} (there are ${values.length})`);
      if (texts[i] !== text) { texts[i] = text; el.textContent = text; }
    },
    get(i) { return texts[i] ?? ''; },
  };
}

/** Formats `value` with `digits` significant digits ('–' for NaN, '∞' for infinities). */
export function fmt(value: number, digits = 3): string {
  if (Number.isNaN(value)) return '–';
  if (!Number.isFinite(value)) return value > 0 ? '∞' : '-∞';
  return Number(value.toPrecision(digits)).toString();
}

/** Shows `message` in a red box in the middle of the page (errors that stop a lab before it starts). */
export function showPageError(message: string): void {
  injectStyle();
  const box = document.createElement('div');
  box.className = 'bp-lab-error';
  box.setAttribute('role', 'alert');
  box.dataset.lab = 'error';
  box.textContent = message;
  document.body.append(box);
}

/**
 * Runs `read` (which reads URL parameters with numberParam / choiceParam / flagParam) and returns its
 * value; if it throws, shows the message with `usage` on the page and rethrows, so the page stops.
 */
export function readUrl<T>(read: () => T, usage: string): T {
  try {
    return read();
  } catch (error) {
    showPageError(`${error instanceof Error ? error.message : String(error)}\n\n${usage}`);
    throw error;
  }
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
 * Live particles of `world` that emitter `emitter` made (every particle if `emitter` is 0 or
 * omitted). Walks the live Particle list once: O(particles), no allocation.
 */
export function countParticles(world: PhysicsWorld, emitter = 0): number {
  const c = world.components;
  const ents = query(world, [c.Particle]);
  if (emitter === 0) return ents.length;
  const em = c.Particle.emitter;
  let n = 0;
  for (let i = 0; i < ents.length; i++) if (em[ents[i]!] === emitter) n++;
  return n;
}

/**
 * Mean position (m) of the live particles of emitter `emitter` (every particle if 0), written into
 * `out` [x, y]; returns how many there are (out is left as NaN when there are none). O(particles).
 */
export function particleCentroid(world: PhysicsWorld, emitter: number, out: Float64Array | number[]): number {
  const c = world.components;
  const ents = query(world, [c.Particle]);
  const em = c.Particle.emitter, px = c.Position.x, py = c.Position.y;
  let n = 0, sx = 0, sy = 0;
  for (let i = 0; i < ents.length; i++) {
    const e = ents[i]!;
    if (emitter !== 0 && em[e] !== emitter) continue;
    sx += px[e]!; sy += py[e]!; n++;
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
  let last = Number.NaN, mean = Number.NaN, count = 0;
  return {
    get last() { return last; },
    get mean() { return mean; },
    get count() { return count; },
    run(step, world) {
      const t0 = performance.now();
      step(world);
      last = performance.now() - t0;
      mean = count === 0 ? last : mean + 0.1 * (last - mean);
      count++;
    },
    reset() { last = Number.NaN; mean = Number.NaN; count = 0; },
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
