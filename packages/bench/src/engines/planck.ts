import { pyramidLayout } from '@bitphysics/physics';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

type Planck = typeof import('planck');

let planck: Promise<Planck> | undefined;

/** Loads planck once. */
function loadPlanck(): Promise<Planck> {
  planck ??= import('planck');
  return planck;
}

/**
 * planck.js (a JavaScript port of Box2D v2.4): `pyramid` with the layout of `pyramidLayout`, boxes as
 * dynamic bodies with box fixtures of 1 x 1 m where they touch (a core of 0.49 m half extents inside
 * Box2D's 0.01 m polygon skin; 1 kg each; friction 0.6, restitution 0; with a 0.5 m core the rows
 * start 0.02 m into each other's skins and the pile rises 0.3 m), a static ground box, steps of 1/60 s with planck's default iterations (8 velocity, 3 position) and sleeping
 * allowed. SI units (planck's are metres and seconds).
 */
export const planckEngine: EngineAdapter = {
  name: 'planck',
  description: 'planck.js (JavaScript port of Box2D v2.4), default iterations (8 velocity, 3 position), sleeping allowed',
  async prepare(): Promise<void> {
    await loadPlanck();
  },
  supports(scene: string): boolean {
    return scene === 'pyramid';
  },
  async create(options: SceneRunOptions): Promise<EngineInstance> {
    if (options.scene !== 'pyramid') throw new RangeError(`planck: does not support scene "${options.scene}"`);
    const P = await loadPlanck();
    const layout = pyramidLayout({ count: options.count });
    const world = new P.World({ gravity: { x: layout.gravity[0], y: layout.gravity[1] } });
    world.createBody({ type: 'static', position: { x: 0, y: -layout.groundHalf[1] } }).createFixture({
      shape: new P.Box(layout.groundHalf[0], layout.groundHalf[1]),
      friction: layout.friction,
      restitution: layout.restitution,
    });
    const n = layout.count;
    const bodies = new Array<ReturnType<typeof world.createBody>>(n);
    const p = layout.positions;
    // Box2D v2 polygons carry a skin of Settings.polygonRadius (0.01 m) around their vertices: a core of
    // half - skin makes the box the layout's 1 x 1 m where it touches, and the density is raised so its
    // mass (computed from the core) is the layout's.
    const skin = P.Settings.polygonRadius,
      core = layout.half - skin;
    const density = layout.density * (layout.half / core) ** 2;
    for (let i = 0; i < n; i++) {
      const body = world.createBody({ type: 'dynamic', position: { x: p[2 * i]!, y: p[2 * i + 1]! } });
      body.createFixture({ shape: new P.Box(core, core), density, friction: layout.friction, restitution: layout.restitution });
      bodies[i] = body;
    }
    return {
      engine: 'planck',
      notes: ['planck: pyramid, dt 1/60 s, 8 velocity and 3 position iterations (defaults), sleeping allowed'],
      step(): void {
        world.step(1 / 60);
      },
      stats() {
        let sleeping = 0;
        for (let i = 0; i < n; i++) if (!bodies[i]!.isAwake()) sleeping++;
        return { bodies: n, contacts: null, extra: { sleeping } };
      },
      snapshot(): BodySnapshot {
        const positions = new Float64Array(2 * n);
        for (let i = 0; i < n; i++) {
          const t = bodies[i]!.getPosition();
          positions[2 * i] = t.x;
          positions[2 * i + 1] = t.y;
        }
        return { dimensions: 2, count: n, positions };
      },
      dispose(): void {
        // Plain JavaScript: nothing to free.
      },
    };
  },
};
