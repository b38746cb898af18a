import { GCProfiler } from 'node:v8';
import {
  contactCount,
  createPhysicsWorld,
  disposeWorld,
  enableThreads,
  type PhysicsWorld,
  SCENES,
  stateHash,
  step,
  warmUp,
} from '@bitphysics/physics';
import { query } from 'bitecs';
import { resolveScene } from '../scenes/index.js';
import type { BodySnapshot, EngineAdapter, EngineInstance, SceneRunOptions } from './types.js';

/**
 * Our engine: any scene of the physics package's `SCENES` registry, built by the scene's own
 * builder in a world made from the scene's `worldOptions` (plus the run's seed), stepped with `step`.
 * The bench scene may add builder options from the run's params (`sceneOptions`) and a probe that
 * measures the world between timed steps (`probe`; its fields join our result line).
 */
export const bitphysicsEngine: EngineAdapter = bitphysicsAdapter('bitphysics', 1);

/** Name of our engine in a world with several threads (`--threads`). */
export const THREADED = 'bitphysics-threads';

/**
 * Our engine in a world made with `threads: n` (`--threads n`): the same scene, run beside the
 * single-threaded `bitphysics` in the same process; its result line adds `threads` and `speedup`.
 */
export function bitphysicsThreadedEngine(threads: number): EngineAdapter {
  return bitphysicsAdapter(THREADED, threads);
}

/** Scenes of thousands of balls, for which `--warm-up` also runs warmUp's ball pile (WarmUpOptions.balls). */
const PILE_SCENES: ReadonlySet<string> = new Set(['balls-in-box', 'spheres-in-box']);

function bitphysicsAdapter(name: string, threads: number): EngineAdapter {
  return {
    name,
    description:
      threads === 1
        ? 'this framework (@bitphysics/physics): the scene builder from SCENES, stepped with step(world)'
        : `this framework in a world with threads: ${threads} (worker threads on shared component arrays)`,
    supports(scene: string): boolean {
      return Object.hasOwn(SCENES, scene);
    },
    async create(options: SceneRunOptions): Promise<EngineInstance> {
      const resolved = resolveScene(options.scene);
      if (!resolved) throw new RangeError(`bitphysics: unknown scene "${options.scene}"`);
      const { definition, bench } = resolved;
      const sceneOptions = { ...(bench.sceneOptions?.(options) ?? {}), count: options.count, seed: options.seed };
      if (threads > 1) enableThreads();
      const worldOptions = definition.worldOptions(sceneOptions);
      const warmStart = performance.now();
      if (options.warmUp === true) warmUp(worldOptions.dimensions ?? 2, { balls: PILE_SCENES.has(options.scene) });
      const warmMs = performance.now() - warmStart;
      const w: PhysicsWorld = createPhysicsWorld({
        ...worldOptions,
        seed: options.seed,
        ...(threads > 1 ? { threads } : {}),
      });
      const handles = definition.build(w, sceneOptions);
      const probe = bench.probe?.(w, handles, options);
      const ids = bench.bodyIds ? Uint32Array.from(bench.bodyIds(handles)) : Uint32Array.from(query(w, [w.components.Position]));
      const dims = w.dimensions;
      const notes = [
        `bitphysics: dt ${fmtDt(w.dt)} s, substeps ${w.substeps}, solver substeps ${w.collision.settings.solverSubsteps}, ` +
          `iterations ${w.collision.settings.solverIterations}, integrator ${w.integrator}, ${w.collision.sleep.enabled ? `sleeping allowed (${w.collision.sleep.linearSpeed} m/s, ${w.collision.sleep.timeToSleep} s)` : 'no sleeping'}` +
          (threads > 1 ? `, threads ${threads}` : '') +
          (options.warmUp === true ? `, warm-up scene run first: ${warmMs.toFixed(0)} ms (counted in setup ms)` : ''),
      ];
      // The garbage collections of this thread while the timed steps run (V8's GCProfiler: each
      // collection's kind and cost): a step that allocates makes them, and each pauses a step.
      let gcProfiler: GCProfiler | null = null;
      let gc = { gcCount: 0, gcMs: 0 };
      return {
        engine: name,
        notes,
        benchBytes: ids.byteLength,
        step(): void {
          step(w);
        },
        stats() {
          const extra = { ...(probe ? probe.extras() : {}), ...(options.hash ? { stateHash: stateHash(w) } : {}), ...gc };
          const bodies = probe?.bodies ? probe.bodies() : ids.length;
          return { bodies, contacts: contactCount(w), extra };
        },
        beginTiming(steps: number): void {
          probe?.beginTiming?.(steps);
          gcProfiler = new GCProfiler();
          gcProfiler.start();
        },
        afterStep: probe?.afterStep ? () => probe.afterStep!() : undefined,
        endTiming(): void {
          probe?.endTiming?.();
          const collections = gcProfiler?.stop().statistics ?? [];
          gcProfiler = null;
          // cost is in microseconds.
          gc = { gcCount: collections.length, gcMs: Math.round(collections.reduce((sum, c) => sum + c.cost, 0)) / 1000 };
        },
        snapshot(): BodySnapshot {
          const c = w.components;
          const positions = new Float64Array(ids.length * dims);
          const velocities = new Float64Array(ids.length * dims);
          const radius = new Float64Array(ids.length);
          let round = false;
          for (let i = 0; i < ids.length; i++) {
            const e = ids[i]!;
            positions[i * dims] = c.Position.x[e]!;
            positions[i * dims + 1] = c.Position.y[e]!;
            if (dims === 3) positions[i * dims + 2] = c.Position.z[e]!;
            velocities[i * dims] = c.Velocity.x[e]!;
            velocities[i * dims + 1] = c.Velocity.y[e]!;
            if (dims === 3) velocities[i * dims + 2] = c.Velocity.z[e]!;
            radius[i] = c.Ball.radius[e]!;
            if (radius[i]! > 0) round = true;
          }
          // 3D: orientations too (identity for a body without one), for scenes of boxes.
          let orientations: Float64Array | undefined;
          if (dims === 3) {
            orientations = new Float64Array(4 * ids.length);
            const Q = c.Orientation;
            for (let i = 0; i < ids.length; i++) {
              const e = ids[i]!;
              const has = Q.w[e] !== undefined && Q.x[e]! ** 2 + Q.y[e]! ** 2 + Q.z[e]! ** 2 + Q.w[e]! ** 2 > 0;
              orientations[4 * i] = has ? Q.x[e]! : 0;
              orientations[4 * i + 1] = has ? Q.y[e]! : 0;
              orientations[4 * i + 2] = has ? Q.z[e]! : 0;
              orientations[4 * i + 3] = has ? Q.w[e]! : 1;
            }
          }
          const base = round
            ? { dimensions: dims, count: ids.length, positions, radius, velocities }
            : { dimensions: dims, count: ids.length, positions, velocities };
          return orientations ? { ...base, orientations } : base;
        },
        dispose(): void {
          // The world's typed arrays go with the instance; a threaded world's workers are stopped here.
          disposeWorld(w);
        },
      };
    },
  };
}

/** Formats a time step as 1/N when it is one. */
export function fmtDt(dt: number): string {
  const n = 1 / dt;
  return Math.abs(n - Math.round(n)) < 1e-9 ? `1/${Math.round(n)}` : String(dt);
}
