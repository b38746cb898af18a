import { boxPile3DLayout, pyramid3DLayout, spheresInBoxLayout } from '@bitphysics/physics';
import { asleepSteps } from '../scenes/box-pile-3d.js';
import { boxWalls3d } from './box-walls.js';
import { optimizedWasm } from './rapier2d.js';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

type Rapier = typeof import('@dimforge/rapier3d-compat').default;

/**
 * A loader of one Rapier 3D build (`importer` imports the package): it loads and initialises the
 * module once (it instantiates its inlined WASM module), with V8's baseline WASM compiler turned off
 * first (`optimizedWasm`, see rapier2d.ts for why), and runs one tiny world so the optimizing compiler
 * has compiled what a step runs before any timing.
 */
function rapier3dLoader(importer: () => Promise<{ default: Rapier }>): () => Promise<Rapier> {
  let rapier: Promise<Rapier> | undefined;
  return () => {
    rapier ??= (async () => {
      optimizedWasm();
      const mod = (await importer()).default;
      await mod.init();
      const w = new mod.World({ x: 0, y: -10, z: 0 });
      const b = w.createRigidBody(mod.RigidBodyDesc.dynamic());
      w.createCollider(mod.ColliderDesc.ball(0.5), b);
      w.createCollider(mod.ColliderDesc.cuboid(1, 1, 1).setTranslation(0, -1.5, 0), w.createRigidBody(mod.RigidBodyDesc.fixed()));
      w.step();
      w.free();
      return mod;
    })();
    return rapier;
  };
}

/** Loads @dimforge/rapier3d-compat once (see rapier3dLoader). */
export const loadRapier3d = rapier3dLoader(() => import('@dimforge/rapier3d-compat'));

/**
 * Loads @dimforge/rapier3d-simd-compat once (see rapier3dLoader): the same API built with WASM SIMD,
 * published separately (0.20.0 here against the plain build's 0.21.0); the notes print the version.
 */
export const loadRapier3dSimd = rapier3dLoader(() => import('@dimforge/rapier3d-simd-compat') as unknown as Promise<{ default: Rapier }>);

/**
 * Rapier 3D (@dimforge/rapier3d-compat, WASM): `spheres-in-box` with the layout of
 * `spheresInBoxLayout`: one dynamic body a sphere (ball collider, radius 0.5 m, restitution 0.5,
 * friction 0.1, mass 1 kg, all from the layout), the closed box as six static cuboid slabs on one
 * fixed body, gravity (0, -10, 0) from the layout, timestep 1/60 s, every other integration
 * parameter at Rapier's default (4 solver iterations, 1 internal PGS iteration, sleeping allowed
 * with Rapier's default thresholds). Restitution and friction combine by Rapier's default rule
 * (average). SI units.
 */
function rapier3dAdapter(name: string, pkg: string, load: () => Promise<Rapier>): EngineAdapter {
  return {
    name,
    description: `Rapier 3D (${pkg}, Rust compiled to WASM), default integration parameters`,
    async prepare(): Promise<void> {
      await load();
    },
    supports(scene: string): boolean {
      return scene === 'spheres-in-box' || scene === 'box-pile-3d' || scene === 'pyramid-3d';
    },
    async create(options: SceneRunOptions): Promise<EngineInstance> {
      if (options.scene === 'box-pile-3d' || options.scene === 'pyramid-3d') return createBoxes(await load(), options, name);
      if (options.scene !== 'spheres-in-box') throw new RangeError(`${name}: does not support scene "${options.scene}"`);
      const R = await load();
      const layout = spheresInBoxLayout({ count: options.count, seed: options.seed });
      let world: InstanceType<Rapier['World']> | undefined = new R.World({
        x: layout.gravity[0],
        y: layout.gravity[1],
        z: layout.gravity[2],
      });
      const w = world;
      w.timestep = 1 / 60;
      const ground = w.createRigidBody(R.RigidBodyDesc.fixed());
      const walls = new Set<number>();
      for (const b of boxWalls3d(layout.min, layout.max)) {
        const collider = w.createCollider(
          R.ColliderDesc.cuboid(b.hx, b.hy, b.hz)
            .setTranslation(b.cx, b.cy, b.cz)
            .setRestitution(layout.restitution)
            .setFriction(layout.friction),
          ground,
        );
        walls.add(collider.handle);
      }
      const n = layout.count;
      const bodies: Array<InstanceType<Rapier['RigidBody']>> = new Array(n);
      const colliders: Array<InstanceType<Rapier['Collider']>> = new Array(n);
      const p = layout.positions;
      for (let i = 0; i < n; i++) {
        const body = w.createRigidBody(R.RigidBodyDesc.dynamic().setTranslation(p[3 * i]!, p[3 * i + 1]!, p[3 * i + 2]!));
        colliders[i] = w.createCollider(
          R.ColliderDesc.ball(layout.radius).setRestitution(layout.restitution).setFriction(layout.friction).setMass(layout.mass),
          body,
        );
        bodies[i] = body;
      }
      const ip = w.integrationParameters;
      const notes = [
        `${name} ${R.version()}: dt ${w.timestep.toFixed(6)} s, ${ip.numSolverIterations} solver iterations, ` +
          `${ip.numInternalPgsIterations} internal PGS iteration, sleeping allowed with Rapier's default thresholds (defaults); ` +
          'six static cuboid walls; restitution/friction combine: average; WASM compiled optimized up front (V8 --no-liftoff)',
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
              // Each sphere-sphere pair once (from its lower handle); sphere-wall pairs from the sphere.
              if (!walls.has(other.handle) && other.handle < h) return;
              w.contactPair(c, other, (manifold) => {
                contacts += manifold.numContacts();
              });
            });
          }
          return { bodies: n, contacts, extra: { sleeping } };
        },
        snapshot(): BodySnapshot {
          const positions = new Float64Array(3 * n);
          for (let i = 0; i < n; i++) {
            const t = bodies[i]!.translation();
            positions[3 * i] = t.x;
            positions[3 * i + 1] = t.y;
            positions[3 * i + 2] = t.z;
          }
          return { dimensions: 3, count: n, positions, radius: layout.radius };
        },
        dispose(): void {
          world?.free();
          world = undefined;
        },
      };
    },
  };
}

/** Rapier 3D, the plain WASM build (@dimforge/rapier3d-compat). */
export const rapier3dEngine = rapier3dAdapter('rapier3d', '@dimforge/rapier3d-compat', loadRapier3d);

/** Rapier 3D built with WASM SIMD (@dimforge/rapier3d-simd-compat): `--vs rapier3d-simd`. */
export const rapier3dSimdEngine = rapier3dAdapter('rapier3d-simd', '@dimforge/rapier3d-simd-compat', loadRapier3dSimd);

/**
 * The box scenes with the layouts of `boxPile3DLayout` and `pyramid3DLayout`: one dynamic body a cube
 * (cuboid collider of half extent 0.5 m, density 1 kg/m^3 so 1 kg, friction and restitution from the
 * layout); `box-pile-3d`'s closed box as six static cuboid slabs, `pyramid-3d`'s ground as one static
 * cuboid whose top is y = 0 reaching 10 m past the pyramid; gravity (0, -10, 0), timestep 1/60 s,
 * Rapier's default integration parameters and sleeping. Snapshots carry orientations. After every
 * timed step (outside its time) the bodies asleep are counted, for `halfAsleepStep` and
 * `allAsleepStep` (`asleepSteps`), counted like ours.
 */
function createBoxes(R: Rapier, options: SceneRunOptions, name: string): EngineInstance {
  const pile = options.scene === 'box-pile-3d';
  const layout = pile ? boxPile3DLayout({ count: options.count, seed: options.seed }) : pyramid3DLayout({ count: options.count });
  let world: InstanceType<Rapier['World']> | undefined = new R.World({ x: layout.gravity[0], y: layout.gravity[1], z: layout.gravity[2] });
  const w = world;
  w.timestep = 1 / 60;
  const ground = w.createRigidBody(R.RigidBodyDesc.fixed());
  const walls =
    'min' in layout
      ? boxWalls3d(layout.min, layout.max)
      : [{ cx: 0, cy: -0.5, cz: 0, hx: (layout.base * layout.pitch) / 2 + 10, hy: 0.5, hz: (layout.base * layout.pitch) / 2 + 10 }];
  for (const b of walls) {
    w.createCollider(
      R.ColliderDesc.cuboid(b.hx, b.hy, b.hz)
        .setTranslation(b.cx, b.cy, b.cz)
        .setRestitution(layout.restitution)
        .setFriction(layout.friction),
      ground,
    );
  }
  const n = layout.count,
    h = layout.half,
    p = layout.positions;
  const bodies: Array<InstanceType<Rapier['RigidBody']>> = new Array(n);
  for (let i = 0; i < n; i++) {
    const body = w.createRigidBody(R.RigidBodyDesc.dynamic().setTranslation(p[3 * i]!, p[3 * i + 1]!, p[3 * i + 2]!));
    w.createCollider(
      R.ColliderDesc.cuboid(h, h, h)
        .setDensity(layout.mass / (8 * h * h * h))
        .setRestitution(layout.restitution)
        .setFriction(layout.friction),
      body,
    );
    bodies[i] = body;
  }
  const ip = w.integrationParameters;
  const notes = [
    `${name} ${R.version()}: dt ${w.timestep.toFixed(6)} s, ${ip.numSolverIterations} solver iterations, ` +
      `${ip.numInternalPgsIterations} internal PGS iteration, sleeping allowed with Rapier's default thresholds (defaults); ` +
      (pile ? 'six static cuboid walls' : 'a static cuboid ground') +
      '; restitution/friction combine: average; WASM compiled optimized up front (V8 --no-liftoff)',
  ];
  const sleep = asleepSteps(n);
  let steps = 0;
  return {
    engine: name,
    notes,
    step(): void {
      w.step();
      steps++;
    },
    afterStep(): void {
      let asleep = 0;
      for (let i = 0; i < n; i++) if (bodies[i]!.isSleeping()) asleep++;
      sleep.record(asleep, steps);
    },
    stats() {
      let contacts = 0,
        sleeping = 0;
      for (let i = 0; i < n; i++) if (bodies[i]!.isSleeping()) sleeping++;
      w.forEachCollider((c) => {
        w.contactPairsWith(c, (other) => {
          if (other.handle < c.handle) return; // each pair once
          w.contactPair(c, other, (manifold) => {
            contacts += manifold.numContacts();
          });
        });
      });
      return { bodies: n, contacts, extra: { sleeping, ...sleep.fields() } };
    },
    snapshot(): BodySnapshot {
      const positions = new Float64Array(3 * n),
        orientations = new Float64Array(4 * n);
      for (let i = 0; i < n; i++) {
        const t = bodies[i]!.translation(),
          q = bodies[i]!.rotation();
        positions[3 * i] = t.x;
        positions[3 * i + 1] = t.y;
        positions[3 * i + 2] = t.z;
        orientations[4 * i] = q.x;
        orientations[4 * i + 1] = q.y;
        orientations[4 * i + 2] = q.z;
        orientations[4 * i + 3] = q.w;
      }
      return { dimensions: 3, count: n, positions, orientations };
    },
    dispose(): void {
      world?.free();
      world = undefined;
    },
  };
}
