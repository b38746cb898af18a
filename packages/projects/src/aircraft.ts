import {
  addBody,
  addLiftingSurface,
  DEFAULT_LIFT_SLOPE,
  dragCoefficient,
  liftCoefficient,
  type PhysicsWorld,
  Rng,
  type SceneDefinition,
  setBodyThrust,
  setInertia,
} from '@bitphysics/physics';
import { assertFinite, assertKnownKeys, assertPositive } from '@bitphysics/physics/validate';

/**
 * The book's flight simulator aircraft (Ramtal and Dobre ch. 16) in SI units, 3D, y up: a rigid body
 * of 30,000 kg with principal moments diag(2e4, 1.6e5, 1.6e5) kg m^2 about its body axes (x forward:
 * roll; y up: yaw; z right: pitch), turned by Euler's equations on a unit quaternion, and flown by
 * lifting surfaces acting at their own points (forces/lifting-surface.ts): two wing halves of 75 m^2
 * (150 m^2, span 30 m, aspect ratio 6) with ailerons, a tailplane with the elevator and a fin with the
 * rudder 12 m behind the centre of mass, and a jet's thrust along the body x axis (`BodyThrust`).
 * The wing is set at an incidence of 3 degrees, so with the body level and the elevator neutral the
 * tail carries no lift and lift = weight at the trim speed `AIRCRAFT_TRIM_SPEED`. The roll, pitch and
 * yaw damping come from the surfaces meeting their own motion (no damping term).
 */
export const AIRCRAFT = Object.freeze({
  mass: 30_000,
  inertia: Object.freeze([2e4, 1.6e5, 1.6e5]) as readonly number[],
  wingArea: 150,
  /** Distance of each wing half's centre of pressure from the centre line, m (a quarter of the 30 m span). */
  wingHalfOffset: 7.5,
  /** Wing incidence to the body x axis, rad. */
  incidence: (3 * Math.PI) / 180,
  /** Lift per radian of aileron deflection on each wing half, 1/rad. */
  aileronPower: 0.6,
  tailArea: 30,
  tailArm: 12,
  tailSlope: 3.5,
  elevatorPower: 1.5,
  /** The fin's centre of pressure sits at the height of the centre of mass (its drag makes no pitching moment). */
  finArea: 15,
  finHeight: 0,
  finSlope: 3,
  rudderPower: 1.2,
  /** Largest thrust, N. */
  maxThrust: 150_000,
  airDensity: 1.225,
  stallAngle: (20 * Math.PI) / 180,
  dragZero: 0.02,
  inducedDrag: 0.06,
  tailDragZero: 0.01,
});

/** Gravity, m/s^2, of the scene's world. */
const G = 9.81;

/**
 * The trim speed, m/s: lift = weight with the body level, from m g = rho V^2 S a i / 2,
 * V = sqrt(2 m g / (rho S a i)) (a the wing's lift slope, i its incidence; about 114 m/s).
 */
export const AIRCRAFT_TRIM_SPEED = Math.sqrt(
  (2 * AIRCRAFT.mass * G) / (AIRCRAFT.airDensity * AIRCRAFT.wingArea * DEFAULT_LIFT_SLOPE * AIRCRAFT.incidence),
);

/**
 * Drag of the level, trimmed aircraft at `speed` m/s, N: wing C_D0 + K C_L^2 at its incidence, tail
 * and fin at zero angle of attack (C_D0 each): the thrust steady level flight needs.
 */
export function aircraftLevelDrag(speed: number): number {
  const A = AIRCRAFT,
    q = 0.5 * A.airDensity * speed * speed;
  const cl = liftCoefficient(A.incidence, DEFAULT_LIFT_SLOPE, A.stallAngle, 0);
  return (
    q * (A.wingArea * dragCoefficient(A.incidence, cl, A.stallAngle, A.dragZero, A.inducedDrag) + (A.tailArea + A.finArea) * A.tailDragZero)
  );
}

/** Options of the `aircraft` scene. */
export interface AircraftOptions {
  /** Unused (one aircraft); must be 1 when given. */
  count?: number;
  /** Seed of the terrain; any finite number. Default 1. */
  seed?: number;
  /** Start altitude, m, > 0. Default 1,200. */
  altitude?: number;
  /** Start speed along +x, m/s, > 0. Default the trim speed. */
  speed?: number;
  /** Start thrust, N, in [0, maxThrust]. Default the level drag at the start speed. */
  thrust?: number;
}

/** What `aircraft.build` returns. */
export interface AircraftHandles {
  /** The aircraft body. */
  readonly body: number;
  /** Lifting surfaces (entities): left and right wing halves (with ailerons), tailplane (elevator), fin (rudder). */
  readonly surfaces: { readonly leftWing: number; readonly rightWing: number; readonly tail: number; readonly fin: number };
  /** Terrain height y(x, z), m: a sum of seeded sine hills (`terrainHeight`). */
  readonly terrain: Float64Array;
}

/** Terrain height at (x, z), m, from the terrain parameters of a build (sum of seeded hills; 0 to ~700 m). */
export function terrainHeight(terrain: Float64Array, x: number, z: number): number {
  let h = 0;
  for (let i = 0; i < terrain.length; i += 5) {
    h += terrain[i]! * (1 + Math.sin(terrain[i + 1]! * x + terrain[i + 2]! * z + terrain[i + 3]!) * Math.cos(terrain[i + 4]! * (x - z)));
  }
  return h;
}

/**
 * `aircraft`: the aircraft flying level along +x at `altitude` over seeded hills, at the trim speed
 * with the thrust that balances its drag (so it holds height and speed until flown).
 */
export const aircraft: SceneDefinition<AircraftOptions, AircraftHandles> = {
  name: 'aircraft',
  description: "The book's flight-simulator aircraft: lifting surfaces with stall and controls, thrust, Euler's equations (SI, 3D)",
  defaultCount: 1,
  // Four integration substeps: the wings damp a roll at the rate lambda = rho V S a y^2 / (2 I_xx),
  // about 1.2 V per second here, which grows with the airspeed V; classical RK4 is stable only for
  // lambda h up to about 2.8, so at h = 1/60 s a full-throttle dive (past about 190 m/s) blew up,
  // while h = 1/240 s holds to above 500 m/s, beyond the fastest dive (about 300 m/s).
  worldOptions() {
    return { dimensions: 3, capacity: 16, gravity: [0, -G, 0], dt: 1 / 60, substeps: 4, integrator: 'rk4', sleep: false };
  },
  build(world: PhysicsWorld, options: AircraftOptions = {}) {
    const where = 'aircraft.build';
    assertKnownKeys(where, options, ['count', 'seed', 'altitude', 'speed', 'thrust']);
    if (world.dimensions !== 3) throw new RangeError(`${where}: needs a 3D world, got dimensions ${world.dimensions}`);
    if (options.count !== undefined && options.count !== 1) throw new RangeError(`${where}: count must be 1, got ${String(options.count)}`);
    const seed = options.seed ?? 1;
    assertFinite(where, 'seed', seed);
    const altitude = options.altitude ?? 1200;
    assertPositive(where, 'altitude', altitude);
    const speed = options.speed ?? AIRCRAFT_TRIM_SPEED;
    assertPositive(where, 'speed', speed);
    const A = AIRCRAFT;
    const thrust = options.thrust ?? aircraftLevelDrag(speed);
    assertFinite(where, 'thrust', thrust);
    if (thrust < 0 || thrust > A.maxThrust) throw new RangeError(`${where}: thrust must be in [0, ${A.maxThrust}], got ${thrust}`);
    if (world.capacity - world.entityIndex.aliveCount < 5) throw new RangeError(`${where}: the world needs room for 5 more entities`);

    const body = addBody(world, { position: [0, altitude, 0], velocity: [speed, 0, 0], mass: A.mass });
    setInertia(world, body, A.inertia);
    const wing = {
      area: A.wingArea / 2,
      normal: [-Math.sin(A.incidence), Math.cos(A.incidence), 0],
      controlPower: A.aileronPower,
      stallAngle: A.stallAngle,
      dragZero: A.dragZero,
      inducedDrag: A.inducedDrag,
      airDensity: A.airDensity,
    };
    const leftWing = addLiftingSurface(world, { body, offset: [0, 0, -A.wingHalfOffset], ...wing });
    const rightWing = addLiftingSurface(world, { body, offset: [0, 0, A.wingHalfOffset], ...wing });
    const tail = addLiftingSurface(world, {
      body,
      offset: [-A.tailArm, 0, 0],
      normal: [0, 1, 0],
      area: A.tailArea,
      liftSlope: A.tailSlope,
      controlPower: A.elevatorPower,
      stallAngle: A.stallAngle,
      dragZero: A.tailDragZero,
      inducedDrag: 0.08,
      airDensity: A.airDensity,
    });
    const fin = addLiftingSurface(world, {
      body,
      offset: [-A.tailArm, A.finHeight, 0],
      normal: [0, 0, 1],
      area: A.finArea,
      liftSlope: A.finSlope,
      controlPower: A.rudderPower,
      stallAngle: A.stallAngle,
      dragZero: A.tailDragZero,
      inducedDrag: 0.1,
      airDensity: A.airDensity,
    });
    setBodyThrust(world, body, [thrust, 0, 0]);

    const rng = new Rng(seed);
    const terrain = new Float64Array(5 * 6);
    for (let i = 0; i < 6; i++) {
      const scale = 1 / (i + 1);
      terrain[5 * i] = rng.range(40, 120) * scale;
      terrain[5 * i + 1] = rng.range(0.4, 1.2) * 1e-3 * (i + 1);
      terrain[5 * i + 2] = rng.range(-1.2, 1.2) * 1e-3 * (i + 1);
      terrain[5 * i + 3] = rng.range(0, 2 * Math.PI);
      terrain[5 * i + 4] = rng.range(0.2, 0.8) * 1e-3 * (i + 1);
    }
    return { body, surfaces: { leftWing, rightWing, tail, fin }, terrain };
  },
};
