import {
  addBody,
  addElectricField,
  addFluidRegion,
  addMagneticField,
  addSpring,
  createPhysicsWorld,
  enableMutualGravity,
  type PhysicsWorld,
  Rng,
  setAngularDamping,
  setAttractor,
  setBuoyancy,
  setCentralForce,
  setCharge,
  setDrag,
  setDrivingForce,
  setElectrostatics,
  setGravitation,
  setGravityScale,
  setLift,
  setRandomForce,
  setThrust,
  setVortex,
  setWind,
} from '@bitphysics/physics';
import { sig } from '../scenes/format.js';
import { medianStepMs, nsPerBodyStep } from './timing.js';
import type { BenchStudy, StudyResult, StudyRunOptions } from './types.js';

/**
 * Largest body count the pairwise (O(N^2)) laws are timed at: Coulomb and direct mutual gravity run
 * with min(--count, 2000) bodies (~2 million pair terms a step), their baseline at the same count.
 */
export const PAIRWISE_MAX_COUNT = 2000;

/** Which bodies a law's world and its baseline hold. */
export type BodyKind = 'plain' | 'rotating';

/** One force law as the `forces` study times it. */
export interface ForceLawCase {
  /** Name in the table and the JSON `law` field. */
  readonly law: string;
  /** What the world holds, one line (setter and coefficients). */
  readonly description: string;
  /** Pairwise O(N^2) law: timed at min(count, PAIRWISE_MAX_COUNT) bodies. */
  readonly pairwise?: boolean;
  /**
   * 'plain' (default): bodies of 1 kg without collider or rotation (`addBody`); 'rotating': the same
   * with a moment of inertia 0.1 kg m^2 spinning at 1 rad/s (the angular-damping law acts on spin).
   */
  readonly bodies?: BodyKind;
  /** Gives the law to every body `ids` of `world` (ids in layout order); `rng` is seeded. */
  setup(world: PhysicsWorld, ids: Uint32Array, rng: Rng): void;
}

/**
 * Every force law of the physics package's `forces` stage (PIPELINE), each alone in a world. Uniform
 * gravity is not among them: every integrator adds the world's g to every body (baseline included).
 */
export const FORCE_LAWS: readonly ForceLawCase[] = Object.freeze([
  {
    law: 'gravity-scale',
    description: 'setGravityScale 0.5: (s - 1) m g on each body',
    setup: (w, ids) => {
      for (const e of ids) setGravityScale(w, e, 0.5);
    },
  },
  {
    law: 'attractor',
    description: 'one static attractor (G = 1, M = 1 kg, softening 0.1 m) pulling every body',
    setup: (w) => {
      setGravitation(w, { constant: 1 });
      setAttractor(w, addBody(w, { position: [0, 0], static: true }), { mass: 1, softening: 0.1 });
    },
  },
  {
    law: 'central-force',
    description: 'setCentralForce k = -1, n = 2 (Hooke-like k r^(n-1) about the origin)',
    setup: (w, ids) => {
      for (const e of ids) setCentralForce(w, e, { centre: [0, 0], k: -1, n: 2 });
    },
  },
  {
    law: 'linear-drag',
    description: 'setDrag linear 0.1 N s/m, still air',
    setup: (w, ids) => {
      for (const e of ids) setDrag(w, e, { linear: 0.1 });
    },
  },
  {
    law: 'quadratic-drag',
    description: 'setDrag quadratic 0.01 kg/m, still air',
    setup: (w, ids) => {
      for (const e of ids) setDrag(w, e, { quadratic: 0.01 });
    },
  },
  {
    law: 'drag-wind',
    description: 'quadratic drag 0.01 kg/m against a uniform gusting wind (5 m/s, gust 2 m/s at 1 rad/s)',
    setup: (w, ids) => {
      setWind(w, { velocity: [5, 0], gust: [2, 0], gustOmega: 1 });
      for (const e of ids) setDrag(w, e, { quadratic: 0.01 });
    },
  },
  {
    law: 'drag-turbulence',
    description: 'quadratic drag 0.01 kg/m against wind 5 m/s with turbulence (16 modes, 1 m/s RMS, 5 m, 1 s)',
    setup: (w, ids) => {
      setWind(w, { velocity: [5, 0], turbulence: { intensity: 1, lengthScale: 5, timeScale: 1, modes: 16 } });
      for (const e of ids) setDrag(w, e, { quadratic: 0.01 });
    },
  },
  {
    law: 'lift',
    description: 'setLift k = 0.01 kg/m about z, still air',
    setup: (w, ids) => {
      for (const e of ids) setLift(w, e, { k: 0.01 });
    },
  },
  {
    law: 'buoyancy',
    description: 'one fluid region (surface y = 0, 1000 kg/m^2); balls of radius 0.1 m with fluid drag 1 kg/m',
    setup: (w, ids) => {
      addFluidRegion(w, { surface: 0, density: 1000 });
      for (const e of ids) setBuoyancy(w, e, { shape: 'ball', radius: 0.1, dragCoefficient: 1 });
    },
  },
  {
    law: 'spring',
    description: 'a chain: each body tied to the next (N - 1 springs, 10 N/m, damping 0.1 N s/m)',
    setup: (w, ids) => {
      for (let i = 0; i + 1 < ids.length; i++) addSpring(w, { a: ids[i]!, b: ids[i + 1]!, stiffness: 10, damping: 0.1 });
    },
  },
  {
    law: 'driving-force',
    description: 'setDrivingForce 1 N cos(2 t) along x',
    setup: (w, ids) => {
      for (const e of ids) setDrivingForce(w, e, { amplitude: [1, 0], omega: 2 });
    },
  },
  {
    law: 'random-force',
    description: 'setRandomForce 1 N, correlation time 0.5 s (seeded value noise)',
    setup: (w, ids) => {
      for (const e of ids) setRandomForce(w, e, { magnitude: 1, correlationTime: 0.5 });
    },
  },
  {
    law: 'thrust',
    description: 'setThrust: exhaust 100 m/s, 0.01 kg/s, 0.9 kg of fuel (lasts 90 s), along +y; fuel burn included',
    setup: (w, ids) => {
      for (const e of ids) setThrust(w, e, { exhaustVelocity: 100, massFlowRate: 0.01, fuel: 0.9, direction: [0, 1] });
    },
  },
  {
    law: 'lorentz',
    description:
      'charge 1 mC in a uniform electric (1 V/m) and magnetic (0.5 T) field: q (E + v x B); Coulomb constant 0 so the charges do not also interact pairwise',
    setup: (w, ids) => {
      setElectrostatics(w, { constant: 0 });
      addElectricField(w, { field: [1, 0] });
      addMagneticField(w, { field: 0.5 });
      for (const e of ids) setCharge(w, e, 1e-3);
    },
  },
  {
    law: 'vortex',
    description: 'setVortex k = 1, n = 1 about the z axis through the origin',
    setup: (w, ids) => {
      for (const e of ids) setVortex(w, e, { centre: [0, 0], k: 1 });
    },
  },
  {
    law: 'angular-damping',
    bodies: 'rotating',
    description: 'setAngularDamping 0.1 N m s on spinning bodies (baseline: the same spinning bodies)',
    setup: (w, ids) => {
      for (const e of ids) setAngularDamping(w, e, 0.1);
    },
  },
  {
    law: 'coulomb-direct',
    pairwise: true,
    description: 'charges +-1 uC, every pair (Coulomb, softening 0.1 m)',
    setup: (w, ids, rng) => {
      setElectrostatics(w, { softening: 0.1 });
      for (const e of ids) setCharge(w, e, rng.next() < 0.5 ? -1e-6 : 1e-6);
    },
  },
  {
    law: 'mutual-gravity-direct',
    pairwise: true,
    description: "mutual gravity, every pair (method 'direct', SI G, softening 0.1 m)",
    setup: (w, ids) => {
      setGravitation(w, { method: 'direct', softening: 0.1 });
      for (const e of ids) enableMutualGravity(w, e);
    },
  },
  {
    law: 'mutual-gravity-barnes-hut',
    description: "mutual gravity by Barnes-Hut (method 'barnes-hut', opening angle 0.7, SI G, softening 0.1 m) at the full count",
    setup: (w, ids) => {
      setGravitation(w, { method: 'barnes-hut', openingAngle: 0.7, softening: 0.1 });
      for (const e of ids) enableMutualGravity(w, e);
    },
  },
] satisfies ForceLawCase[]);

/**
 * A 2D world (gravity (0, -9.81), default dt 1/60 s and integrator) of `count` bodies of 1 kg without
 * colliders, uniform in a square of side sqrt(count) m (about one body per m^2) around the origin with
 * velocities uniform in [-1, 1] m/s, seeded; 'rotating' bodies also have inertia 0.1 kg m^2 and spin at
 * 1 rad/s. Capacity 2 count + 16 (room for a spring per body and field entities). Returns the body ids.
 */
export function forceWorld(count: number, seed: number, kind: BodyKind): { world: PhysicsWorld; ids: Uint32Array } {
  const world = createPhysicsWorld({ dimensions: 2, gravity: [0, -9.81], capacity: 2 * count + 16, seed });
  const rng = new Rng(seed);
  const half = 0.5 * Math.sqrt(count);
  const ids = new Uint32Array(count);
  for (let i = 0; i < count; i++) {
    const position = [rng.range(-half, half), rng.range(-half, half)];
    const velocity = [rng.range(-1, 1), rng.range(-1, 1)];
    ids[i] =
      kind === 'rotating'
        ? addBody(world, { position, velocity, mass: 1, inertia: 0.1, angularVelocity: 1 })
        : addBody(world, { position, velocity, mass: 1 });
  }
  return { world, ids };
}

/**
 * `forces`: the cost of each force law (`FORCE_LAWS`). For each law, a world of `--count` bodies with
 * only that law (`forceWorld` plus the law's setup) and a baseline world of the same bodies without it
 * are stepped alternately in blocks of 5 steps (`--warmup` untimed, then `--steps` timed, each step
 * timed alone); `nsPerBodyStep` is (median law step - median baseline step) / bodies, in ns, so the
 * law's own systems (all their force evaluations per step) without integration and the pipeline.
 * Pairwise laws run at min(count, 2000) bodies. A law cheaper than the timing noise can come out
 * near 0 or slightly negative; medians keep that noise small.
 */
export const forcesStudy: BenchStudy = {
  name: 'forces',
  description: 'Each force law alone: ns per body-step over a baseline world without forces (pairwise laws at <= 2,000 bodies)',
  defaultCount: 10_000,
  maxCount: 1_000_000,
  defaults: { steps: 100, warmup: 20 },
  run(options: StudyRunOptions): StudyResult {
    const records = FORCE_LAWS.map((c, i) => {
      const count = c.pairwise ? Math.min(options.count, PAIRWISE_MAX_COUNT) : options.count;
      const kind = c.bodies ?? 'plain';
      options.onProgress?.(`${c.law} (${i + 1}/${FORCE_LAWS.length}): ${count} bodies`);
      const law = forceWorld(count, options.seed, kind);
      c.setup(law.world, law.ids, new Rng(options.seed + 1));
      const baseline = forceWorld(count, options.seed, kind);
      const [lawMs, baseMs] = medianStepMs([law.world, baseline.world], options.steps, options.warmup) as [number, number];
      return {
        law: c.law,
        nsPerBodyStep: sig(nsPerBodyStep(lawMs - baseMs, count), 4),
        baselineNsPerBodyStep: sig(nsPerBodyStep(baseMs, count), 4),
        count,
        wholeNsPerBodyStep: sig(nsPerBodyStep(lawMs, count), 4),
        msPerStep: sig(lawMs, 4),
        baselineMsPerStep: sig(baseMs, 4),
        pairwise: c.pairwise === true,
        bodies: kind,
        steps: options.steps,
        description: c.description,
      };
    });
    const rows = records.map((r) => [
      r.law,
      r.nsPerBodyStep.toFixed(1),
      r.baselineNsPerBodyStep.toFixed(1),
      r.wholeNsPerBodyStep.toFixed(1),
      String(r.count),
      r.description,
    ]);
    const capped = options.count > PAIRWISE_MAX_COUNT;
    return {
      records,
      header: ['law', 'ns/body-step', 'baseline ns', 'whole step ns', 'bodies', 'world'],
      rows,
      notes: [
        `ns/body-step: (median step of a world with only this law - median step of the same bodies without it) / bodies; medians over ${options.steps} timed steps ` +
          `after ${options.warmup} warm-up, the two worlds alternating every 5 steps. Baseline: bodies of 1 kg, no collider, gravity (0, -9.81), semi-implicit Euler, dt 1/60 s.`,
        `pairwise laws (coulomb-direct, mutual-gravity-direct) are O(N^2): timed at min(count, ${PAIRWISE_MAX_COUNT}) bodies` +
          (capped ? ` (here ${PAIRWISE_MAX_COUNT}, not ${options.count}); their cost per body grows linearly with N.` : '.'),
        'uniform gravity has no line: every integrator adds g to every body, baseline included. Costs below the timing noise (~1 ns) can show as ~0 or slightly negative.',
      ],
    };
  },
};
