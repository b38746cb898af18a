import { createPhysicsWorld, INTEGRATOR_NAMES, type IntegratorName, step } from '@bitphysics/physics';
import { SOLAR_SYSTEM_PLANETS, solarSystem, solarSystemErrors } from '@bitphysics/projects';
import { sig } from '../scenes/format.js';
import { medianStepMs, nsPerBodyStep } from './timing.js';
import type { BenchStudy, StudyResult, StudyRunOptions } from './types.js';

/** Default `--days`: one (leap) year, the issue's goal from 2012-01-01. */
export const SOLAR_SYSTEM_DAYS = 366;
/** The steps every scheme is run at, hours: one day down to a quarter hour. */
export const SOLAR_SYSTEM_STEP_HOURS = [24, 6, 1, 0.25] as const;
/** The reference run that measures the point-mass floor: RK4 at this step, hours. */
export const SOLAR_SYSTEM_FLOOR_STEP_HOURS = 0.1;
/** A run reaches the floor when every planet's error is within this factor of the reference run's. */
export const SOLAR_SYSTEM_FLOOR_FACTOR = 1.5;

/** Each planet's relative position error after `days` days of `integrator` at `stepHours`. */
function errorsAfter(integrator: IntegratorName, stepHours: number, days: number): Float64Array {
  const world = createPhysicsWorld(solarSystem.worldOptions({ integrator, stepHours }));
  const handles = solarSystem.build(world);
  const n = Math.round((days * 24) / stepHours);
  for (let i = 0; i < n; i++) step(world);
  return solarSystemErrors(world, handles);
}

const exp2 = (v: number): string => v.toExponential(2);

/**
 * `solar-system`: the physics package's solar-system scene (the Sun and eight planets from
 * astronomy-engine at 2012-01-01, mutual gravity, AU and days) run for `--days` days (default 366)
 * with every scheme at 24 h, 6 h, 1 h and 15 min, and the reference RK4 at 0.1 h:
 *
 * - `positionError`: per planet, |r_sim - r_ephemeris| / |r_ephemeris| (heliocentric) at the end;
 * - `worstRatio`: the largest positionError / reference error over the planets; `reachesFloor`:
 *   worstRatio <= 1.5 (the reference run is the point-mass floor: the model's error, not the scheme's);
 * - `msPerStep`, `nsPerBodyStep`: median `step(world)` over `--steps` steps after `--warmup`, nine
 *   bodies, each scheme at 1 h, the seven worlds alternating every 5 steps.
 */
export const solarSystemStudy: BenchStudy = {
  name: 'solar-system',
  description:
    "Sun and eight planets from astronomy-engine: each planet's position error after --days, every scheme at 24 h .. 15 min, and the point-mass floor",
  defaultCount: 9,
  maxCount: 9,
  defaults: { steps: 300, warmup: 30 },
  params: {
    days: {
      default: SOLAR_SYSTEM_DAYS,
      min: 0,
      exclusiveMin: true,
      max: 36_600,
      description: 'solar-system: simulated days after 2012-01-01 at which the errors are read',
    },
  },
  run(options: StudyRunOptions): StudyResult {
    const days = options.params.days ?? SOLAR_SYSTEM_DAYS;
    options.onProgress?.(`reference: rk4 at ${SOLAR_SYSTEM_FLOOR_STEP_HOURS} h for ${days} days`);
    const floor = errorsAfter('rk4', SOLAR_SYSTEM_FLOOR_STEP_HOURS, days);
    const perPlanet = (e: Float64Array): Record<string, number> =>
      Object.fromEntries(SOLAR_SYSTEM_PLANETS.map((p, i) => [p, sig(e[i]!, 3)]));
    options.onProgress?.(`timing ${INTEGRATOR_NAMES.length} worlds at 1 h, ${options.steps} steps each`);
    const worlds = INTEGRATOR_NAMES.map((integrator) => {
      const w = createPhysicsWorld(solarSystem.worldOptions({ integrator, stepHours: 1 }));
      solarSystem.build(w);
      return w;
    });
    const ms = medianStepMs(worlds, options.steps, options.warmup);
    const records: Array<Record<string, unknown>> = [
      {
        integrator: 'rk4',
        stepHours: SOLAR_SYSTEM_FLOOR_STEP_HOURS,
        days,
        reference: true,
        positionError: perPlanet(floor),
        worstRatio: 1,
        reachesFloor: true,
      },
    ];
    INTEGRATOR_NAMES.forEach((integrator, k) => {
      for (const stepHours of SOLAR_SYSTEM_STEP_HOURS) {
        options.onProgress?.(`${integrator} at ${stepHours} h for ${days} days`);
        let errors: Float64Array | null = null;
        let failure: string | null = null;
        try {
          errors = errorsAfter(integrator, stepHours, days);
        } catch (error) {
          failure = (error as Error)?.message ?? String(error);
        }
        let worst = Infinity;
        if (errors) {
          worst = 0;
          errors.forEach((e, i) => {
            worst = Math.max(worst, e / floor[i]!);
          });
        }
        records.push({
          integrator,
          stepHours,
          days,
          reference: false,
          positionError: errors ? perPlanet(errors) : null,
          worstRatio: errors ? sig(worst, 3) : null,
          reachesFloor: errors !== null && worst <= SOLAR_SYSTEM_FLOOR_FACTOR,
          failure,
          ...(stepHours === 1 ? { msPerStep: sig(ms[k]!, 4), nsPerBodyStep: sig(nsPerBodyStep(ms[k]!, 9), 4) } : {}),
        });
      }
    });
    const rows = records.map((r) => {
      const e = r.positionError as Record<string, number> | null;
      return [
        `${String(r.integrator)}${r.reference ? ' (floor)' : ''}`,
        String(r.stepHours),
        ...SOLAR_SYSTEM_PLANETS.map((p) => (e ? exp2(e[p]!) : 'failed')),
        r.worstRatio === null ? '-' : String(r.worstRatio),
        r.reachesFloor ? 'yes' : 'no',
        typeof r.msPerStep === 'number' ? (r.msPerStep * 1000).toFixed(1) : '',
      ];
    });
    const reach = INTEGRATOR_NAMES.map((name) => {
      const ok = records.filter((r) => r.integrator === name && !r.reference && r.reachesFloor).map((r) => r.stepHours as number);
      return `${name}: ${ok.length ? `<= ${Math.max(...ok)} h` : 'not at 15 min'}`;
    });
    return {
      records,
      header: ['integrator', 'step h', ...SOLAR_SYSTEM_PLANETS, 'worst/floor', 'floor?', 'µs/step (1 h)'],
      rows,
      notes: [
        `Relative heliocentric position error |r - r_eph| / |r_eph| against astronomy-engine after ${days} days from 2012-01-01 (Earth = Earth-Moon barycentre).`,
        `floor: RK4 at ${SOLAR_SYSTEM_FLOOR_STEP_HOURS} h, the point-mass model's own error; a run reaches it when every planet is within ${SOLAR_SYSTEM_FLOOR_FACTOR}x.`,
        `Reaches the floor: ${reach.join('; ')}.`,
        `µs/step: median step(world) of nine bodies at 1 h over ${options.steps} steps after ${options.warmup} warm-up; the seven worlds alternate every 5 steps.`,
      ],
    };
  },
};
