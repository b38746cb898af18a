import { ballsInBox } from './balls-in-box';
import { particles } from './particles';
import type { SceneDefinition } from './types';

/** Every registered scene by name: the bench's `--list` and the gallery read this. */
export const SCENES: Readonly<Record<string, SceneDefinition<{ count?: number; seed?: number }, unknown>>> = Object.freeze({
  [ballsInBox.name]: ballsInBox as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [particles.name]: particles as SceneDefinition<{ count?: number; seed?: number }, unknown>,
});

export { ballsInBox, ballsInBoxLayout } from './balls-in-box';
export type { BallsInBoxHandles, BallsInBoxLayout, BallsInBoxOptions } from './balls-in-box';
export { particles, particlesLayout } from './particles';
export type { ParticlesHandles, ParticlesLayout, ParticlesOptions } from './particles';
export type { SceneDefinition } from './types';
