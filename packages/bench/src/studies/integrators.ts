import {
  addBody,
  createPhysicsWorld,
  INTEGRATOR_NAMES,
  INTEGRATOR_ORDER,
  type IntegratorName,
  kineticEnergy,
  type PhysicsWorld,
  potentialEnergy,
  Rng,
  setAttractor,
  setGravitation,
  step,
} from '@bitphysics/physics';
import { sig } from '../scenes/format.js';
import { medianStepMs, nsPerBodyStep } from './timing.js';
import type { BenchStudy, StudyResult, StudyRunOptions } from './types.js';

/**
 * The Kepler orbit every accuracy measurement uses, in units with G M = 1 (G = 1 set with
 * `setGravitation`, a static attractor of mass 1 at the origin): semi-major axis a = 1, eccentricity
 * e = 0.5, so the period is T = 2 pi sqrt(a^3 / G M) = 2 pi s. The planet (mass 1e-3 kg; it does not
 * pull the static attractor) starts at periapsis (a (1 - e), 0) = (0.5, 0) with the periapsis speed
 * sqrt(G M (1 + e) / (a (1 - e))) = sqrt(3) m/s along +y, and orbits counter-clockwise.
 */
export const KEPLER = Object.freeze({ eccentricity: 0.5, semiMajorAxis: 1, period: 2 * Math.PI });

/**
 * Steps per orbit of the three convergence runs: dt = T/400, T/800, T/1600. Small enough for every
 * scheme to be in its asymptotic regime on this orbit (measured orders within 0.05 of theory), large
 * enough that RK4's error at T/1600 (~1e-9 m) stays far above rounding (~1e-13 m).
 */
export const ORDER_STEPS_PER_ORBIT = [400, 800, 1600] as const;

/**
 * Fraction of an orbit after which the position error is read for the convergence order. Not a whole
 * orbit: semi-implicit Euler is conjugate to Stormer-Verlet by an O(h) change of variables, so its
 * first-order error depends only on the start and end states and cancels when they coincide (it
 * would measure order 2 at t = T). At t = 0.3 T no such symmetry hides a scheme's leading error.
 */
export const ORDER_ORBIT_FRACTION = 0.3;

/** Steps per orbit of the two energy runs (`energyErrorCoarse` at T/500, `energyError` at T/1000). */
export const ENERGY_STEPS_PER_ORBIT = Object.freeze({ coarse: 500, fine: 1000 });

/** Default `--orbits`: Kepler orbits of each energy run. */
export const DEFAULT_ORBITS = 100;

/** Steps between energy samples of the fine energy run (for `energyErrorMax`). */
const ENERGY_SAMPLE_EVERY = 10;

/**
 * The exact position (x, y), m, on the `KEPLER` orbit at time t (s) after periapsis: the mean
 * anomaly M = 2 pi t / T, the eccentric anomaly E from Kepler's equation E - e sin E = M by Newton's
 * method (to 1e-15), then x = a (cos E - e), y = a sqrt(1 - e^2) sin E (Murray and Dermott, Solar
 * System Dynamics, ch. 2.4). Writes into `out` and returns it.
 */
export function keplerPosition(t: number, out: Float64Array = new Float64Array(2)): Float64Array {
  const { eccentricity: e, semiMajorAxis: a, period: T } = KEPLER;
  const M = (2 * Math.PI * t) / T;
  let E = e > 0.8 ? Math.PI : M;
  for (let i = 0; i < 60; i++) {
    const d = (E - e * Math.sin(E) - M) / (1 - e * Math.cos(E));
    E -= d;
    if (Math.abs(d) < 1e-15) break;
  }
  out[0] = a * (Math.cos(E) - e);
  out[1] = a * Math.sqrt(1 - e * e) * Math.sin(E);
  return out;
}

/** A 2D world with G = 1, no uniform gravity, a static attractor of mass 1 at the origin and the `KEPLER` planet. */
function keplerWorld(integrator: IntegratorName, stepsPerOrbit: number): { world: PhysicsWorld; planet: number } {
  const { eccentricity: e, semiMajorAxis: a, period: T } = KEPLER;
  const world = createPhysicsWorld({ dimensions: 2, gravity: [0, 0], dt: T / stepsPerOrbit, integrator, capacity: 4 });
  setGravitation(world, { constant: 1 });
  const sun = addBody(world, { position: [0, 0], static: true });
  setAttractor(world, sun, { mass: 1 });
  const planet = addBody(world, { position: [a * (1 - e), 0], velocity: [0, Math.sqrt((1 + e) / (a * (1 - e)))], mass: 1e-3 });
  return { world, planet };
}

/**
 * Global position error, m: |x_numerical - x_exact| on the `KEPLER` orbit after
 * round(ORDER_ORBIT_FRACTION * stepsPerOrbit) steps of T / stepsPerOrbit, against `keplerPosition`
 * at the world's own clock.
 */
export function keplerPositionError(integrator: IntegratorName, stepsPerOrbit: number): number {
  const { world, planet } = keplerWorld(integrator, stepsPerOrbit);
  const n = Math.round(ORDER_ORBIT_FRACTION * stepsPerOrbit);
  for (let i = 0; i < n; i++) step(world);
  const exact = keplerPosition(world.time);
  const P = world.components.Position;
  return Math.hypot(P.x[planet]! - exact[0]!, P.y[planet]! - exact[1]!);
}

/** Outcome of one energy run. */
export interface EnergyRun {
  /** |E_end - E_0| / |E_0| after the run (E = kinetic + potential, J), or null if a step threw. */
  readonly final: number | null;
  /** Largest |E - E_0| / |E_0| over the run, sampled every 10 steps and at the end (or up to the failure). */
  readonly max: number;
  /** What stopped the run (the step's error message and the orbit it reached), or null. */
  readonly failure: string | null;
}

/**
 * Relative energy error of the `KEPLER` orbit after `orbits` orbits of `stepsPerOrbit` steps each.
 * A step that throws (implicit Euler's Newton iteration failing as the orbit decays into the
 * attractor's singularity) ends the run: `final` is then null and `failure` says why and when.
 */
export function keplerEnergyError(integrator: IntegratorName, stepsPerOrbit: number, orbits: number): EnergyRun {
  const { world } = keplerWorld(integrator, stepsPerOrbit);
  const E0 = kineticEnergy(world) + potentialEnergy(world);
  const total = stepsPerOrbit * orbits;
  let max = 0;
  const sample = (): number => {
    const err = Math.abs((kineticEnergy(world) + potentialEnergy(world) - E0) / E0);
    if (err > max || Number.isNaN(err)) max = err;
    return err;
  };
  let k = 0;
  try {
    for (; k < total; k++) {
      step(world);
      if (k % ENERGY_SAMPLE_EVERY === 0) sample();
    }
  } catch (error) {
    const message = (error as Error)?.message ?? String(error);
    return { final: null, max, failure: `failed at orbit ${(k / stepsPerOrbit).toFixed(2)}: ${message}` };
  }
  return { final: sample(), max, failure: null };
}

/**
 * N independent bodies (no mutual forces) on circular orbits around a static attractor (G = 1, mass
 * 1, at the origin; softening 0.05 m), radii uniform in [1, 3] m and angles uniform, seeded: the
 * world whose steps `nsPerBodyStep` times. Default dt 1/60 s (>= 377 steps per orbit).
 */
export function centralFieldWorld(integrator: IntegratorName, count: number, seed: number): PhysicsWorld {
  const world = createPhysicsWorld({ dimensions: 2, gravity: [0, 0], integrator, capacity: count + 1, seed });
  setGravitation(world, { constant: 1 });
  const sun = addBody(world, { position: [0, 0], static: true });
  setAttractor(world, sun, { mass: 1, softening: 0.05 });
  const rng = new Rng(seed);
  for (let i = 0; i < count; i++) {
    const r = rng.range(1, 3),
      phi = rng.range(0, 2 * Math.PI),
      v = Math.sqrt(1 / r);
    addBody(world, { position: [r * Math.cos(phi), r * Math.sin(phi)], velocity: [-v * Math.sin(phi), v * Math.cos(phi)], mass: 1 });
  }
  return world;
}

const exp2 = (v: number | null): string => (v === null ? '-' : v.toExponential(2));

/**
 * `integrators`: for each of the physics package's seven schemes (`INTEGRATOR_NAMES`):
 *
 * - `order`: the measured convergence order, log2(err(dt/2) / err(dt/4)), from the global position
 *   error of the `KEPLER` orbit at t = 0.3 T with dt = T/400, T/800, T/1600 (`orders` gives both
 *   ratios, `positionErrors` the three errors in m, `expectedOrder` the theory, `INTEGRATOR_ORDER`);
 * - `energyError`: |dE/E| after `--orbits` (default 100) orbits at dt = T/1000, `energyErrorCoarse`
 *   the same at T/500, `energyErrorMax` the largest |dE/E| over the T/1000 run (sampled every 10
 *   steps); null with `energyFailure` set when the scheme's step threw before the end;
 * - `nsPerBodyStep`: the median time of a whole `step(world)` over `--steps` steps (after `--warmup`),
 *   in ns per body, of `--count` independent bodies orbiting one attractor (`centralFieldWorld`),
 *   the seven worlds alternating in blocks of 5 steps.
 */
export const integratorsStudy: BenchStudy = {
  name: 'integrators',
  description: 'Each integrator: convergence order (Kepler orbit), energy error after 100 orbits at T/500 and T/1000, ns per body-step',
  defaultCount: 10_000,
  maxCount: 100_000,
  defaults: { steps: 60, warmup: 10 },
  params: {
    orbits: {
      default: DEFAULT_ORBITS,
      min: 1,
      max: 10_000,
      integer: true,
      description: 'integrators: Kepler orbits of each energy run (at T/500 and T/1000)',
    },
  },
  run(options: StudyRunOptions): StudyResult {
    const orbits = options.params.orbits ?? DEFAULT_ORBITS;
    const accuracy = INTEGRATOR_NAMES.map((name) => {
      options.onProgress?.(
        `${name}: convergence and ${orbits} Kepler orbits at T/${ENERGY_STEPS_PER_ORBIT.coarse} and T/${ENERGY_STEPS_PER_ORBIT.fine}`,
      );
      const errors = ORDER_STEPS_PER_ORBIT.map((n) => keplerPositionError(name, n));
      const orders = [Math.log2(errors[0]! / errors[1]!), Math.log2(errors[1]! / errors[2]!)];
      const coarse = keplerEnergyError(name, ENERGY_STEPS_PER_ORBIT.coarse, orbits);
      const fine = keplerEnergyError(name, ENERGY_STEPS_PER_ORBIT.fine, orbits);
      return { name, errors, orders, coarse, fine };
    });
    options.onProgress?.(`timing ${INTEGRATOR_NAMES.length} worlds of ${options.count} bodies, ${options.steps} steps each`);
    const worlds = INTEGRATOR_NAMES.map((name) => centralFieldWorld(name, options.count, options.seed));
    const ms = medianStepMs(worlds, options.steps, options.warmup);

    const records = accuracy.map((a, i) => {
      const failure = [
        a.coarse.failure && `T/${ENERGY_STEPS_PER_ORBIT.coarse}: ${a.coarse.failure}`,
        a.fine.failure && `T/${ENERGY_STEPS_PER_ORBIT.fine}: ${a.fine.failure}`,
      ]
        .filter(Boolean)
        .join('; ');
      return {
        integrator: a.name,
        order: sig(a.orders[1]!, 4),
        energyError: a.fine.final === null ? null : sig(a.fine.final, 4),
        nsPerBodyStep: sig(nsPerBodyStep(ms[i]!, options.count), 4),
        expectedOrder: INTEGRATOR_ORDER[a.name],
        orders: a.orders.map((o) => sig(o, 4)),
        positionErrors: a.errors.map((e) => sig(e, 4)),
        orderStepsPerOrbit: [...ORDER_STEPS_PER_ORBIT],
        energyErrorCoarse: a.coarse.final === null ? null : sig(a.coarse.final, 4),
        energyErrorMax: sig(a.fine.max, 4),
        energyStepsPerOrbit: ENERGY_STEPS_PER_ORBIT.fine,
        energyStepsPerOrbitCoarse: ENERGY_STEPS_PER_ORBIT.coarse,
        orbits,
        energyFailure: failure === '' ? null : failure,
        msPerStep: sig(ms[i]!, 4),
        count: options.count,
        steps: options.steps,
      };
    });
    const rows = records.map((r) => [
      r.integrator,
      `${r.order.toFixed(2)} (${r.expectedOrder})`,
      exp2(r.positionErrors[2]!),
      r.energyErrorCoarse === null ? 'failed' : exp2(r.energyErrorCoarse),
      r.energyError === null ? 'failed' : exp2(r.energyError),
      exp2(r.energyErrorMax),
      r.nsPerBodyStep.toFixed(1),
    ]);
    const notes = [
      `order: log2(err(T/${ORDER_STEPS_PER_ORBIT[1]}) / err(T/${ORDER_STEPS_PER_ORBIT[2]})) of the position error at t = ${ORDER_ORBIT_FRACTION} T on a Kepler orbit ` +
        `(G M = 1, a = 1, e = ${KEPLER.eccentricity}, T = 2 pi s, from periapsis) against the exact solution (Kepler's equation); theory in parentheses.`,
      `|dE/E|: relative energy error after ${orbits} orbits at T/${ENERGY_STEPS_PER_ORBIT.coarse} and T/${ENERGY_STEPS_PER_ORBIT.fine} (JSON energyErrorCoarse, energyError); ` +
        `max: largest over the T/${ENERGY_STEPS_PER_ORBIT.fine} run (energyErrorMax). "failed": the scheme's step threw (JSON energyFailure).`,
      `ns/body-step: median whole step(world) over ${options.steps} steps after ${options.warmup} warm-up, / ${options.count} independent bodies orbiting one attractor; ` +
        'the seven worlds alternate every 5 steps. Multi-stage schemes evaluate the forces several times a step (RK4: 4).',
      ...records.filter((r) => r.energyFailure).map((r) => `${r.integrator}: ${r.energyFailure}`),
    ];
    return {
      records,
      header: [
        'integrator',
        'order (theory)',
        `pos. err T/${ORDER_STEPS_PER_ORBIT[2]} m`,
        `|dE/E| T/${ENERGY_STEPS_PER_ORBIT.coarse}`,
        `|dE/E| T/${ENERGY_STEPS_PER_ORBIT.fine}`,
        `max |dE/E| T/${ENERGY_STEPS_PER_ORBIT.fine}`,
        'ns/body-step',
      ],
      rows,
      notes,
    };
  },
};
