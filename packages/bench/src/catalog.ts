import { resolveScene, sceneNames } from './scenes/index.js';
import type { SceneParam } from './scenes/types.js';
import { resolveStudy, STUDIES } from './studies/index.js';

/**
 * Everything `--scene` accepts, seen the same way: the physics package's scenes (run by the engines,
 * side by side with peers) and the bench's own studies (`integrators`, `forces`).
 */
export interface CatalogEntry {
  /** Name given to `--scene`. */
  readonly name: string;
  /** 'scene': a world stepped by every engine (`runBenchmark`); 'study': measurements of bitphysics alone (`BenchStudy.run`). */
  readonly kind: 'scene' | 'study';
  /** One line for `--list`. */
  readonly description: string;
  /** `--count` when none is given, integer >= 1. */
  readonly defaultCount: number;
  /** Largest `--count` accepted. */
  readonly maxCount: number;
  /** Timed and warm-up steps when `--steps` / `--warmup` are absent (undefined: the CLI's defaults). */
  readonly defaults: { readonly steps?: number; readonly warmup?: number };
  /** Scene parameters by flag name (`--<name> <value>`); empty when the scene declares none. */
  readonly params: Readonly<Record<string, SceneParam>>;
}

/** Every name `--scene` accepts: the physics package's scenes in registry order, then the studies. */
export function catalogNames(): string[] {
  return [...sceneNames(), ...Object.keys(STUDIES)];
}

/**
 * The scene or study called `name`, or undefined if there is none.
 * @throws Error if a study has the name of a physics scene (a programming error, never user input).
 */
export function catalogEntry(name: string): CatalogEntry | undefined {
  const scene = resolveScene(name);
  const study = resolveStudy(name);
  if (scene && study) throw new Error(`bench study "${name}" has the name of a physics scene; rename the study`);
  if (scene) {
    return {
      name,
      kind: 'scene',
      description: scene.definition.description,
      defaultCount: scene.definition.defaultCount,
      maxCount: scene.bench.maxCount,
      defaults: scene.bench.defaults ?? {},
      params: scene.bench.params ?? {},
    };
  }
  if (study) {
    return {
      name,
      kind: 'study',
      description: study.description,
      defaultCount: study.defaultCount,
      maxCount: study.maxCount,
      defaults: study.defaults,
      params: study.params ?? {},
    };
  }
  return undefined;
}

/** Every scene parameter flag name, with the scenes that declare it, in catalog order. */
export function paramDeclarations(): Map<string, string[]> {
  const out = new Map<string, string[]>();
  for (const name of catalogNames()) {
    for (const param of Object.keys(catalogEntry(name)!.params)) out.set(param, [...(out.get(param) ?? []), name]);
  }
  return out;
}
