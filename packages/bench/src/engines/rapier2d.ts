import { setFlagsFromString } from 'node:v8';
import { ballsInBoxLayout } from '@bitphysics/physics';
import { boxWalls } from './box-walls.js';
import { createRapierJointGrid } from './rapier2d-joint-grid.js';
import { createRapierPyramid } from './rapier2d-pyramid.js';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

type Rapier = typeof import('@dimforge/rapier2d-compat').default;

/**
 * Makes V8 compile WebAssembly modules compiled from now on with its optimizing compiler only
 * (`--no-liftoff`). Affects WASM only (our engine and matter are JavaScript). Shared by the rapier
 * adapters; call before the module is instantiated.
 */
export function optimizedWasm(): void {
  setFlagsFromString('--no-liftoff');
}

/**
 * A loader of one Rapier 2D build (`importer` imports the package): it loads and initialises the
 * module once (it instantiates its inlined WASM module).
 *
 * Before the module is compiled, V8's baseline WASM compiler is turned off (`--no-liftoff`, see
 * `optimizedWasm`) so rapier runs its optimized (TurboFan) code from the first step. With Node's
 * default, rapier runs baseline (Liftoff) code until tier-up, which on a busy 2-core machine had not
 * happened after hundreds of steps: its steps measured 1.5 to 2.5 times slower, a benchmark of V8's
 * tiering rather than of rapier.
 */
function rapier2dLoader(importer: () => Promise<{ default: Rapier }>): () => Promise<Rapier> {
  let rapier: Promise<Rapier> | undefined;
  return () => {
    rapier ??= (async () => {
      optimizedWasm();
      const mod = (await importer()).default;
      await mod.init();
      // Compile now what a step runs (the optimizing compiler takes a second or two on first use), so
      // neither the scene's setup time nor its warm-up pays for it.
      const w = new mod.World({ x: 0, y: -10 });
      const b = w.createRigidBody(mod.RigidBodyDesc.dynamic());
      w.createCollider(mod.ColliderDesc.ball(0.5), b);
      w.createCollider(mod.ColliderDesc.cuboid(1, 1).setTranslation(0, -1.5), w.createRigidBody(mod.RigidBodyDesc.fixed()));
      w.step();
      w.free();
      return mod;
    })();
    return rapier;
  };
}

/** Loads @dimforge/rapier2d-compat once (see rapier2dLoader). */
export const loadRapier2d = rapier2dLoader(() => import('@dimforge/rapier2d-compat'));

/**
 * Loads @dimforge/rapier2d-simd-compat once (see rapier2dLoader): the same API built with WASM SIMD
 * (128-bit lanes), the build users pick for speed. Its version is not the plain build's: the SIMD
 * packages are published separately (0.19.3 here against 0.21.0); the notes print both.
 */
export const loadRapier2dSimd = rapier2dLoader(() => import('@dimforge/rapier2d-simd-compat') as unknown as Promise<{ default: Rapier }>);

/**
 * Rapier 2D (@dimforge/rapier2d-compat, WASM): `balls-in-box` with the layout of `ballsInBoxLayout`:
 * one dynamic body a ball (ball collider, radius, restitution and friction from the layout, mass set
 * to the layout's mass), the closed box as four static cuboid walls, gravity from the layout,
 * timestep 1/60 s, every other integration parameter at Rapier's default (4 solver iterations,
 * sleeping allowed). SI units.
 */
function rapier2dAdapter(name: string, pkg: string, load: () => Promise<Rapier>): EngineAdapter {
  return {
    name,
    description: `Rapier 2D (${pkg}, Rust compiled to WASM), default integration parameters`,
    async prepare(): Promise<void> {
      await load();
    },
    supports(scene: string): boolean {
      return scene === 'balls-in-box' || scene === 'pyramid' || scene === 'joint-grid';
    },
    async create(options: SceneRunOptions): Promise<EngineInstance> {
      if (options.scene === 'pyramid') return createRapierPyramid(await load(), options, name);
      if (options.scene === 'joint-grid') return createRapierJointGrid(await load(), options, name);
      if (options.scene !== 'balls-in-box') throw new RangeError(`${name}: does not support scene "${options.scene}"`);
      const R = await load();
      const layout = ballsInBoxLayout({ count: options.count, seed: options.seed, restitution: options.params?.restitution ?? 0.5 });
      let world: InstanceType<Rapier['World']> | undefined = new R.World({ x: layout.gravity[0], y: layout.gravity[1] });
      const w = world;
      w.timestep = 1 / 60;
      const ground = w.createRigidBody(R.RigidBodyDesc.fixed());
      const walls = new Set<number>();
      for (const b of boxWalls(layout)) {
        const collider = w.createCollider(
          R.ColliderDesc.cuboid(b.hx, b.hy).setTranslation(b.cx, b.cy).setRestitution(layout.restitution).setFriction(layout.friction),
          ground,
        );
        walls.add(collider.handle);
      }
      const n = layout.count;
      const bodies: Array<InstanceType<Rapier['RigidBody']>> = new Array(n);
      const colliders: Array<InstanceType<Rapier['Collider']>> = new Array(n);
      const p = layout.positions;
      for (let i = 0; i < n; i++) {
        const body = w.createRigidBody(R.RigidBodyDesc.dynamic().setTranslation(p[2 * i]!, p[2 * i + 1]!));
        colliders[i] = w.createCollider(
          R.ColliderDesc.ball(layout.radius).setRestitution(layout.restitution).setFriction(layout.friction).setMass(layout.mass),
          body,
        );
        bodies[i] = body;
      }
      const ip = w.integrationParameters;
      const notes = [
        `${name} ${R.version()}: dt ${w.timestep.toFixed(6)} s, ${ip.numSolverIterations} solver iterations, ` +
          `${ip.numInternalPgsIterations} internal PGS iteration, sleeping allowed (defaults); restitution/friction combine: average; ` +
          'WASM compiled optimized up front (V8 --no-liftoff)',
      ];
      return {
        engine: name,
        notes,
        step(): void {
          w.step();
        },
        stats() {
          let contacts = 0;
          let sleeping = 0;
          for (let i = 0; i < n; i++) {
            if (bodies[i]!.isSleeping()) sleeping++;
            const c = colliders[i]!;
            const h = c.handle;
            w.contactPairsWith(c, (other) => {
              // Each ball-ball pair once (from its lower handle); ball-wall pairs from the ball.
              if (!walls.has(other.handle) && other.handle < h) return;
              w.contactPair(c, other, (manifold) => {
                contacts += manifold.numContacts();
              });
            });
          }
          return { bodies: n, contacts, extra: { sleeping } };
        },
        snapshot(): BodySnapshot {
          const positions = new Float64Array(2 * n),
            velocities = new Float64Array(2 * n);
          for (let i = 0; i < n; i++) {
            const t = bodies[i]!.translation(),
              v = bodies[i]!.linvel();
            positions[2 * i] = t.x;
            positions[2 * i + 1] = t.y;
            velocities[2 * i] = v.x;
            velocities[2 * i + 1] = v.y;
          }
          return { dimensions: 2, count: n, positions, radius: layout.radius, velocities };
        },
        dispose(): void {
          world?.free();
          world = undefined;
        },
      };
    },
  };
}

/** Rapier 2D, the plain WASM build (@dimforge/rapier2d-compat). */
export const rapier2dEngine = rapier2dAdapter('rapier2d', '@dimforge/rapier2d-compat', loadRapier2d);

/** Rapier 2D built with WASM SIMD (@dimforge/rapier2d-simd-compat): `--vs rapier2d-simd`. */
export const rapier2dSimdEngine = rapier2dAdapter('rapier2d-simd', '@dimforge/rapier2d-simd-compat', loadRapier2dSimd);
