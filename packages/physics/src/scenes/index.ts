import { ballsInBox } from './balls-in-box';
import { particles } from './particles';
import { spheresInBox } from './spheres-in-box';
import { galaxy } from './galaxy';
import { fireworks } from './fireworks';
import type { SceneDefinition } from './types';

/** Every registered scene by name: the bench's `--list` and the gallery read this. */
export const SCENES: Readonly<Record<string, SceneDefinition<{ count?: number; seed?: number }, unknown>>> = Object.freeze({
  [ballsInBox.name]: ballsInBox as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [particles.name]: particles as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [spheresInBox.name]: spheresInBox as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [galaxy.name]: galaxy as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [fireworks.name]: fireworks as SceneDefinition<{ count?: number; seed?: number }, unknown>,
});

export { ballsInBox, ballsInBoxLayout } from './balls-in-box';
export type { BallsInBoxHandles, BallsInBoxLayout, BallsInBoxOptions } from './balls-in-box';
export { particles, particlesLayout } from './particles';
export type { ParticlesHandles, ParticlesLayout, ParticlesOptions } from './particles';
export type { SceneDefinition } from './types';
export { spheresInBox, spheresInBoxLayout } from './spheres-in-box';
export type { SpheresInBoxHandles, SpheresInBoxLayout, SpheresInBoxOptions } from './spheres-in-box';
export { galaxy } from './galaxy';
export type { GalaxyOptions } from './galaxy';
export { fireworks } from './fireworks';
export type { FireworksOptions } from './fireworks';
