/**
 * @bitphysics/projects: the closing projects of "Physics for JavaScript Games, Animation, and
 * Simulations" (Ramtal and Dobre) built on @bitphysics/physics: the flight simulator's aircraft (lifting
 * surfaces, thrust, terrain), the submarine (buoyancy, ballast tanks, thrust) and the solar system from
 * real ephemerides (astronomy-engine). Each is a scene definition (`build`, `worldOptions`) plus its
 * constants, as the physics package's own scenes. Kept out of the physics package so a game that does
 * not use them does not install or bundle them.
 */

export type { AircraftHandles, AircraftOptions } from './aircraft.js';
export {
  AIRCRAFT,
  AIRCRAFT_TAIL_INCIDENCE,
  AIRCRAFT_TRIM_SPEED,
  aircraft,
  aircraftLevelDrag,
  aircraftTrimSpeed,
  terrainHeight,
} from './aircraft.js';
export type { SolarSystemBody, SolarSystemHandles, SolarSystemOptions, SolarSystemPlanet } from './solar-system.js';
export {
  AU,
  DAY,
  ephemerisHeliocentric,
  ephemerisState,
  SOLAR_SYSTEM_BODIES,
  SOLAR_SYSTEM_EPOCH,
  SOLAR_SYSTEM_FLOOR,
  SOLAR_SYSTEM_PLANETS,
  solarSystem,
  solarSystemErrors,
  solarSystemMass,
} from './solar-system.js';
export type { SubmarineHandles, SubmarineOptions } from './submarine.js';
export {
  SUBMARINE,
  SUBMARINE_NEUTRAL_FILL,
  SUBMARINE_WATER_DENSITY,
  seabedHeight,
  setSubmarineThrusters,
  submarine,
} from './submarine.js';
