import { elasticGasStudy } from './elastic-gas.js';
import { forcesStudy } from './forces.js';
import { galtonStudy } from './galton.js';
import { integratorsStudy } from './integrators.js';
import { snapshotStudy } from './snapshot.js';
import { solarSystemStudy } from './solar-system.js';
import type { BenchStudy } from './types.js';

/** Bench-only scenes (measurement studies, not worlds stepped side by side with peers) by name. */
export const STUDIES: Readonly<Record<string, BenchStudy>> = Object.freeze({
  [integratorsStudy.name]: integratorsStudy,
  [forcesStudy.name]: forcesStudy,
  [solarSystemStudy.name]: solarSystemStudy,
  [snapshotStudy.name]: snapshotStudy,
  [elasticGasStudy.name]: elasticGasStudy,
  [galtonStudy.name]: galtonStudy,
});

/** The study called `name`, or undefined. */
export function resolveStudy(name: string): BenchStudy | undefined {
  return Object.hasOwn(STUDIES, name) ? STUDIES[name] : undefined;
}

export type { BenchStudy, StudyResult, StudyRunOptions } from './types.js';
