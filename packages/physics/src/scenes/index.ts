import { ballsInBox } from './balls-in-box.js';
import { boxPile3D } from './box-pile-3d.js';
import { clothScene } from './cloth.js';
import { fireworks } from './fireworks.js';
import { fountain } from './fountain.js';
import { galaxy } from './galaxy.js';
import { jointGrid } from './joint-grid.js';
import { particles } from './particles.js';
import { pyramid } from './pyramid.js';
import { pyramid3D } from './pyramid-3d.js';
import { spheresInBox } from './spheres-in-box.js';
import type { SceneDefinition } from './types.js';

/**
 * Every registered scene by name: the bench's `--list` and the gallery read this.
 * @category Scenes
 */
export const SCENES: Readonly<Record<string, SceneDefinition<{ count?: number; seed?: number }, unknown>>> = Object.freeze({
  [ballsInBox.name]: ballsInBox as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [particles.name]: particles as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [spheresInBox.name]: spheresInBox as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [galaxy.name]: galaxy as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [fireworks.name]: fireworks as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [fountain.name]: fountain as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [pyramid.name]: pyramid as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [jointGrid.name]: jointGrid as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [clothScene.name]: clothScene as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [boxPile3D.name]: boxPile3D as SceneDefinition<{ count?: number; seed?: number }, unknown>,
  [pyramid3D.name]: pyramid3D as SceneDefinition<{ count?: number; seed?: number }, unknown>,
});

export type { BallsInBoxHandles, BallsInBoxLayout, BallsInBoxOptions } from './balls-in-box.js';
export { ballsInBox, ballsInBoxLayout } from './balls-in-box.js';
export type { BoxPile3DHandles, BoxPile3DLayout, BoxPile3DOptions } from './box-pile-3d.js';
export { boxPile3D, boxPile3DLayout } from './box-pile-3d.js';
export type { ClothSceneOptions } from './cloth.js';
export { clothScene } from './cloth.js';
export type { FireworksOptions } from './fireworks.js';
export { fireworks } from './fireworks.js';
export type { FountainOptions } from './fountain.js';
export { FOUNTAIN_MEAN_LIFETIME, fountain } from './fountain.js';
export type { GalaxyOptions } from './galaxy.js';
export { galaxy } from './galaxy.js';
export type { JointGridHandles, JointGridOptions } from './joint-grid.js';
export { jointGrid } from './joint-grid.js';
export type { ParticlesHandles, ParticlesLayout, ParticlesOptions } from './particles.js';
export { particles, particlesLayout } from './particles.js';
export type { PyramidHandles, PyramidLayout, PyramidOptions } from './pyramid.js';
export { pyramid, pyramidLayout } from './pyramid.js';
export type { Pyramid3DHandles, Pyramid3DLayout, Pyramid3DOptions } from './pyramid-3d.js';
export { pyramid3D, pyramid3DLayout } from './pyramid-3d.js';
export type { SpheresInBoxHandles, SpheresInBoxLayout, SpheresInBoxOptions } from './spheres-in-box.js';
export { spheresInBox, spheresInBoxLayout } from './spheres-in-box.js';
export type { SceneDefinition } from './types.js';
