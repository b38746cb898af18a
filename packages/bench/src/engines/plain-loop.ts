import { particlesLayout } from '@bitphysics/physics';
import { createPlainFireworks } from './plain-fireworks.js';
import { createPlainFountain } from './plain-fountain.js';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

/** Fixed step of the baseline, s (the physics world's default). */
const DT = 1 / 60;

/**
 * The baseline of the `particles` scene: the same integration as our engine (semi-implicit Euler,
 * v += g h then x += v h, gravity from `particlesLayout`, h = 1/60 s, the same arithmetic in the
 * same order) as one bare loop over four Float64Arrays, with no ECS, no queries, no previous
 * positions and no NaN check. Ours / plain-loop is the framework's overhead factor.
 */
export const plainLoopEngine: EngineAdapter = {
  name: 'plain-loop',
  description:
    'bare loop over Float64Arrays, semi-implicit Euler under gravity: the framework-overhead baseline (particles; fireworks and fountain: the same births, deaths, gravity (and drag) with a free list)',
  supports(scene: string): boolean {
    return scene === 'particles' || scene === 'fireworks' || scene === 'fountain';
  },
  async create(options: SceneRunOptions): Promise<EngineInstance> {
    if (options.scene === 'fireworks') return createPlainFireworks(options);
    if (options.scene === 'fountain') return createPlainFountain(options);
    if (options.scene !== 'particles') throw new RangeError(`plain-loop: does not support scene "${options.scene}"`);
    const layout = particlesLayout({ count: options.count, seed: options.seed });
    const n = layout.count;
    const px = new Float64Array(n),
      py = new Float64Array(n),
      vx = new Float64Array(n),
      vy = new Float64Array(n);
    for (let i = 0; i < n; i++) {
      px[i] = layout.positions[2 * i]!;
      py[i] = layout.positions[2 * i + 1]!;
      vx[i] = layout.velocities[2 * i]!;
      vy[i] = layout.velocities[2 * i + 1]!;
    }
    const gx = layout.gravity[0],
      gy = layout.gravity[1];
    return {
      engine: 'plain-loop',
      notes: ['plain-loop: for i < n { v += g h; x += v h } over separate Float64Arrays px, py, vx, vy; h = 1/60 s'],
      step(): void {
        integrate(px, py, vx, vy, n, gx * DT, gy * DT, DT);
      },
      stats() {
        return { bodies: n, contacts: null };
      },
      snapshot(): BodySnapshot {
        const positions = new Float64Array(2 * n);
        for (let i = 0; i < n; i++) {
          positions[2 * i] = px[i]!;
          positions[2 * i + 1] = py[i]!;
        }
        return { dimensions: 2, count: n, positions };
      },
      dispose(): void {},
    };
  },
};

/**
 * One semi-implicit Euler step of n particles with exact free fall, as bitphysics does it:
 * v += g h, x += (v - g h / 2) h (gxh = g_x h, gyh = g_y h).
 */
function integrate(
  px: Float64Array,
  py: Float64Array,
  vx: Float64Array,
  vy: Float64Array,
  n: number,
  gxh: number,
  gyh: number,
  h: number,
): void {
  const hx = 0.5 * gxh,
    hy = 0.5 * gyh;
  for (let i = 0; i < n; i++) {
    const nvx = vx[i]! + gxh;
    const nvy = vy[i]! + gyh;
    vx[i] = nvx;
    vy[i] = nvy;
    px[i] = px[i]! + (nvx - hx) * h;
    py[i] = py[i]! + (nvy - hy) * h;
  }
}
