import { ballsInBox } from './balls-in-box.js';
import { particles } from './particles.js';
import { spheresInBox } from './spheres-in-box.js';
import { galaxy } from './galaxy.js';
import { fireworks } from './fireworks.js';
import { fountain } from './fountain.js';
import { pyramid } from './pyramid.js';
import { jointGrid } from './joint-grid.js';
import { clothScene } from './cloth.js';
import { boxPile3D } from './box-pile-3d.js';
import { pyramid3D } from './pyramid-3d.js';
import type { SceneDefinition } from './types.js';

/** Every registered scene by name: the bench's `--list` and the gallery read this. */
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

export { ballsInBox, ballsInBoxLayout } from './balls-in-box.js';
export type { BallsInBoxHandles, BallsInBoxLayout, BallsInBoxOptions } from './balls-in-box.js';
export { particles, particlesLayout } from './particles.js';
export type { ParticlesHandles, ParticlesLayout, ParticlesOptions } from './particles.js';
export type { SceneDefinition } from './types.js';
export { spheresInBox, spheresInBoxLayout } from './spheres-in-box.js';
export type { SpheresInBoxHandles, SpheresInBoxLayout, SpheresInBoxOptions } from './spheres-in-box.js';
export { galaxy } from './galaxy.js';
export type { GalaxyOptions } from './galaxy.js';
export { fireworks } from './fireworks.js';
export type { FireworksOptions } from './fireworks.js';
export { fountain, FOUNTAIN_MEAN_LIFETIME } from './fountain.js';
export type { FountainOptions } from './fountain.js';
export { pyramid, pyramidLayout } from './pyramid.js';
export type { PyramidHandles, PyramidLayout, PyramidOptions } from './pyramid.js';
export { jointGrid } from './joint-grid.js';
export type { JointGridOptions, JointGridHandles } from './joint-grid.js';
export { clothScene } from './cloth.js';
export type { ClothSceneOptions } from './cloth.js';
export { boxPile3D, boxPile3DLayout } from './box-pile-3d.js';
export type { BoxPile3DHandles, BoxPile3DLayout, BoxPile3DOptions } from './box-pile-3d.js';
export { pyramid3D, pyramid3DLayout } from './pyramid-3d.js';
export type { Pyramid3DHandles, Pyramid3DLayout, Pyramid3DOptions } from './pyramid-3d.js';
// The book's closing projects: exported builders, not in SCENES (the bench measures solar-system as a study).
export {
  solarSystem, solarSystemErrors, solarSystemMass, ephemerisState, ephemerisHeliocentric,
  SOLAR_SYSTEM_BODIES, SOLAR_SYSTEM_PLANETS, SOLAR_SYSTEM_FLOOR, SOLAR_SYSTEM_EPOCH, AU, DAY,
} from './solar-system.js';
export type { SolarSystemBody, SolarSystemPlanet, SolarSystemOptions, SolarSystemHandles } from './solar-system.js';
export { submarine, seabedHeight, SUBMARINE, SUBMARINE_NEUTRAL_FILL, SUBMARINE_WATER_DENSITY } from './submarine.js';
export type { SubmarineOptions, SubmarineHandles } from './submarine.js';
export { aircraft, aircraftLevelDrag, terrainHeight, AIRCRAFT, AIRCRAFT_TRIM_SPEED } from './aircraft.js';
export type { AircraftOptions, AircraftHandles } from './aircraft.js';
