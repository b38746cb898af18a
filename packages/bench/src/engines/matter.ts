import { ballsInBoxLayout } from '@bitphysics/physics';
import { boxWalls } from './box-walls.js';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

type MatterModule = typeof import('matter-js');

/**
 * Pixels a metre. Matter is not SI: its lengths are pixels, its time milliseconds, and its
 * tolerances (slop 0.05 px, resting thresholds, circle tessellation) are tuned for bodies tens of
 * pixels across. At 100 px/m its default gravity (y 1, scale 0.001: 0.001 px/ms^2 = 1000 px/s^2)
 * is exactly 10 m/s^2, and a 0.5 m ball is 50 px.
 */
export const MATTER_PIXELS_PER_METRE = 100;

/** Matter's step, ms (1/60 s). */
const DELTA_MS = 1000 / 60;

let matter: Promise<MatterModule> | undefined;

/** Loads matter-js once (CommonJS; its namespace object is the default export). */
export function loadMatter(): Promise<MatterModule> {
  matter ??= import('matter-js').then((m) => ((m as { default?: MatterModule }).default ?? m) as MatterModule);
  return matter;
}

/**
 * matter-js: `balls-in-box` with the layout of `ballsInBoxLayout` scaled to 100 px/m with y
 * flipped (matter's y points down): circles (matter's regular polygons, 25 sides at 50 px) of
 * mass 1, restitution and friction from the layout, no air friction (frictionAir 0; matter's
 * default 0.01 would add drag the scene does not have), static rectangles as the box, default
 * gravity (= 10 m/s^2 at this scale), default iterations (position 6, velocity 4), no sleeping
 * (matter's default), steps of 1000/60 ms. Positions are converted back to metres for metrics.
 */
export const matterEngine: EngineAdapter = {
  name: 'matter',
  description: 'matter-js (pure JavaScript; pixels and milliseconds, not SI: run at 100 px/m), default iterations',
  async prepare(): Promise<void> {
    await loadMatter();
  },
  supports(scene: string): boolean {
    return scene === 'balls-in-box';
  },
  async create(options: SceneRunOptions): Promise<EngineInstance> {
    if (options.scene !== 'balls-in-box') throw new RangeError(`matter: does not support scene "${options.scene}"`);
    const M = await loadMatter();
    const layout = ballsInBoxLayout({ count: options.count, seed: options.seed, restitution: options.params?.restitution ?? 0.5 });
    const S = MATTER_PIXELS_PER_METRE;
    // g = 10 m/s^2 = 10 S px/s^2 = 10 S / 1e6 px/ms^2 = gravity.y * gravity.scale.
    const g = -layout.gravity[1];
    let engine: Matter.Engine | undefined = M.Engine.create({ gravity: { x: 0, y: 1, scale: (g * S) / 1e6 } });
    const e = engine;
    const material = { restitution: layout.restitution, friction: layout.friction, frictionAir: 0 };
    const statics = boxWalls(layout).map((b) =>
      M.Bodies.rectangle(b.cx * S, -b.cy * S, 2 * b.hx * S, 2 * b.hy * S, { ...material, isStatic: true }),
    );
    const n = layout.count;
    const balls: Matter.Body[] = new Array(n);
    const p = layout.positions;
    for (let i = 0; i < n; i++) {
      const body = M.Bodies.circle(p[2 * i]! * S, -p[2 * i + 1]! * S, layout.radius * S, material);
      M.Body.setMass(body, layout.mass);
      balls[i] = body;
    }
    M.Composite.add(e.world, statics);
    M.Composite.add(e.world, balls);
    const sides = balls[0] ? balls[0].vertices.length : 0;
    const notes = [
      `matter ${(M as unknown as { version?: string }).version ?? ''}: not SI; run at ${S} px/m, y down, ms; gravity y 1 scale ${(g * S) / 1e6} ` +
        `(= ${g} m/s^2), position/velocity iterations ${e.positionIterations}/${e.velocityIterations} (defaults), ` +
        `circles are ${sides}-gons, frictionAir 0, frictionStatic ${balls[0]?.frictionStatic ?? ''} (default), no sleeping; ` +
        'restitution combine: max, friction: min',
    ];
    return {
      engine: 'matter',
      notes,
      step(): void {
        M.Engine.update(e, DELTA_MS);
      },
      stats() {
        let contacts = 0;
        const list = e.pairs.list as Array<{ isActive: boolean; contactCount?: number; activeContacts?: unknown[] }>;
        for (const pair of list) {
          if (!pair.isActive) continue;
          contacts += pair.contactCount ?? pair.activeContacts?.length ?? 0;
        }
        return { bodies: n, contacts };
      },
      snapshot(): BodySnapshot {
        const positions = new Float64Array(2 * n),
          velocities = new Float64Array(2 * n);
        for (let i = 0; i < n; i++) {
          const q = balls[i]!.position,
            v = balls[i]!.velocity;
          positions[2 * i] = q.x / S;
          positions[2 * i + 1] = -q.y / S;
          // matter's velocity is px per its base step (1000/60 ms), y down.
          velocities[2 * i] = (v.x / S) * 60;
          velocities[2 * i + 1] = (-v.y / S) * 60;
        }
        return { dimensions: 2, count: n, positions, radius: layout.radius, velocities };
      },
      dispose(): void {
        if (engine) M.Engine.clear(engine);
        engine = undefined;
      },
    };
  },
};
