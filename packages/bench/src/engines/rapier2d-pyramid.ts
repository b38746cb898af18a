import { pyramidLayout } from '@bitphysics/physics';
import type { BodySnapshot, EngineInstance, SceneRunOptions } from './types.js';

type Rapier = typeof import('@dimforge/rapier2d-compat').default;

/**
 * Rapier 2D's `pyramid`: the layout of `pyramidLayout`, every box a dynamic body with a 0.5 x 0.5
 * cuboid collider (density 1, friction 0.6, restitution 0), the ground one fixed cuboid, gravity from
 * the layout, timestep 1/60 s, every integration parameter at Rapier's default (sleeping allowed).
 * `name` is the engine's name in the results (rapier2d or rapier2d-simd: the same API).
 */
export function createRapierPyramid(R: Rapier, options: SceneRunOptions, name = 'rapier2d'): EngineInstance {
  const layout = pyramidLayout({ count: options.count });
  let world: InstanceType<Rapier['World']> | undefined = new R.World({ x: layout.gravity[0], y: layout.gravity[1] });
  const w = world;
  w.timestep = 1 / 60;
  const ground = w.createRigidBody(R.RigidBodyDesc.fixed().setTranslation(0, -layout.groundHalf[1]));
  w.createCollider(
    R.ColliderDesc.cuboid(layout.groundHalf[0], layout.groundHalf[1]).setFriction(layout.friction).setRestitution(layout.restitution),
    ground,
  );
  const n = layout.count;
  const bodies: Array<InstanceType<Rapier['RigidBody']>> = new Array(n);
  const p = layout.positions;
  for (let i = 0; i < n; i++) {
    const body = w.createRigidBody(R.RigidBodyDesc.dynamic().setTranslation(p[2 * i]!, p[2 * i + 1]!));
    w.createCollider(
      R.ColliderDesc.cuboid(layout.half, layout.half)
        .setDensity(layout.density)
        .setFriction(layout.friction)
        .setRestitution(layout.restitution),
      body,
    );
    bodies[i] = body;
  }
  const ip = w.integrationParameters;
  return {
    engine: name,
    notes: [
      `${name} ${R.version()}: pyramid, dt ${w.timestep.toFixed(6)} s, ${ip.numSolverIterations} solver iterations, sleeping allowed (defaults); WASM compiled optimized up front`,
    ],
    step(): void {
      w.step();
    },
    stats() {
      let sleeping = 0;
      for (let i = 0; i < n; i++) if (bodies[i]!.isSleeping()) sleeping++;
      return { bodies: n, contacts: null, extra: { sleeping } };
    },
    snapshot(): BodySnapshot {
      const positions = new Float64Array(2 * n);
      for (let i = 0; i < n; i++) {
        const t = bodies[i]!.translation();
        positions[2 * i] = t.x;
        positions[2 * i + 1] = t.y;
      }
      return { dimensions: 2, count: n, positions };
    },
    dispose(): void {
      world?.free();
      world = undefined;
    },
  };
}
