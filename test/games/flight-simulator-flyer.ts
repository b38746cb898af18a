/**
 * The aircraft flown headless as the flight simulator flies it (games/flight-simulator/main.ts): the
 * assist's surface commands followed at SURFACE_RATE.assist, the surfaces deflected through
 * CONTROL_AUTHORITY (ailerons times AILERON_SCALE), and thrust for level flight at 130 m/s. Shared by
 * the node tests that fly a pilot model against the game's cues.
 */

import { createPhysicsWorld, setBodyThrust, setControlDeflection, step } from '@bitphysics/physics';
import { AIRCRAFT, aircraft, aircraftLevelDrag } from '@bitphysics/projects';
import {
  AILERON_SCALE,
  assist,
  CONTROL_AUTHORITY,
  createAssistState,
  type FlightState,
  SURFACE_RATE,
} from '../../games/flight-simulator/assist';

const DEG = Math.PI / 180;

/**
 * A new world with the aircraft at 900 m (seed 1), its assist state, and `fly(s, roll, pitch)`: one
 * step with the keys' roll and pitch (each in [-1, 1]) given to the assist from the flight state `s`
 * read at the step's start.
 */
export function assistedAircraft() {
  const world = createPhysicsWorld(aircraft.worldOptions());
  const h = aircraft.build(world, { seed: 1, altitude: 900 });
  const e = h.body;
  const state = createAssistState(),
    surface = { aileron: 0, elevator: 0, rudder: 0 },
    rate = SURFACE_RATE.assist * world.dt,
    full = CONTROL_AUTHORITY * DEG,
    throttle = aircraftLevelDrag(130) / AIRCRAFT.maxThrust;
  const fly = (s: FlightState, roll: number, pitch: number): void => {
    const c = assist(s, { roll, pitch, yaw: 0 }, state, world.dt);
    surface.aileron += Math.max(-rate, Math.min(rate, c.aileron - surface.aileron));
    surface.elevator += Math.max(-rate, Math.min(rate, c.elevator - surface.elevator));
    surface.rudder += Math.max(-rate, Math.min(rate, c.rudder - surface.rudder));
    setControlDeflection(world, h.surfaces.tail, -surface.elevator * full);
    setControlDeflection(world, h.surfaces.leftWing, surface.aileron * full * AILERON_SCALE);
    setControlDeflection(world, h.surfaces.rightWing, -surface.aileron * full * AILERON_SCALE);
    setControlDeflection(world, h.surfaces.fin, -surface.rudder * full);
    setBodyThrust(world, e, [throttle * AIRCRAFT.maxThrust, 0, 0]);
    step(world);
  };
  return { world, h, e, C: world.components, state, fly };
}
