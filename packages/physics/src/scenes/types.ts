import type { PhysicsWorld, PhysicsWorldOptions } from '../world/options.js';

/**
 * A scene: a pure, seeded, deterministic builder shared by tests, the headless bench and the games.
 * `worldOptions` says what world the scene is designed for; `build` fills a world and returns handles.
 * @category Scenes
 */
export interface SceneDefinition<Options extends { count?: number; seed?: number }, Handles> {
  /** Name used on the command line (`--scene`). */
  readonly name: string;
  /** One line for `--list` and the gallery. */
  readonly description: string;
  /** Body count used when none is given. */
  readonly defaultCount: number;
  /** World options the scene expects (dimensions, gravity, capacity for `count` bodies). */
  worldOptions(options?: Options): PhysicsWorldOptions;
  /** Fills `world` with the scene. @throws RangeError on bad options or a world of the wrong shape. */
  build(world: PhysicsWorld, options?: Options): Handles;
}
