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
 * The wing is set at an incidence of 3 degrees, so with the body level and the elevator neutral
 * lift = weight at the trim speed `AIRCRAFT_TRIM_SPEED`. The roll, pitch and yaw damping come from
 * the surfaces meeting their own motion (no damping term).
 *
 * Lateral stability: each wing half is tilted up by the dihedral angle (its normal leans inboard),
 * so in a sideslip the wing the air comes from meets it at a larger angle of attack (about
 * beta sin(dihedral)) and lifts more: the aircraft rolls away from the slip (the dihedral effect), and
 * the fin, whose centre of pressure stands `finHeight` above the centre of mass, adds its side force's
 * rolling moment. Together with the fin's weathercock yaw this makes the spiral mode converge (a bank
 * left alone slowly levels out) where a flat wing lets it diverge: the spiral mode converges when
 * L_beta N_r - L_r N_beta > 0, the sign of the constant term of the lateral characteristic equation
 * (Etkin and Reid, Dynamics of Flight: Stability and Control). The fin's drag above the centre of
 * mass pitches the nose up; the tailplane is set at the small incidence `AIRCRAFT_TAIL_INCIDENCE`
 * whose lift balances it at every speed.
 */
export const AIRCRAFT = Object.freeze({
  mass: 30_000,
  inertia: Object.freeze([2e4, 1.6e5, 1.6e5]) as readonly number[],
  wingArea: 150,
  /**
   * Distance of each wing half's centre of pressure from the centre line, m (a quarter of the 30 m
   * span). It sits at the height of the centre of mass: the wing's root is below it (a low wing), so
   * the halves' drag makes no pitching moment.
   */
  wingHalfOffset: 7.5,
  /** Wing incidence to the body x axis, rad. */
  incidence: (3 * Math.PI) / 180,
  /** Dihedral: the upward tilt of each wing half about the body x axis, rad (7 degrees, a low wing's usual). */
  dihedral: (7 * Math.PI) / 180,
  /** Lift per radian of aileron deflection on each wing half, 1/rad. */
  aileronPower: 0.6,
  tailArea: 30,
  tailArm: 12,
  tailSlope: 3.5,
  elevatorPower: 1.5,
  /** Induced drag factor of the tailplane. */
  tailInducedDrag: 0.08,
  finArea: 15,
  /** Height of the fin's centre of pressure above the centre of mass, m (mid-height of a 5 m fin on the tail cone). */
  finHeight: 2.5,
  finSlope: 3,
  rudderPower: 1.2,
  /** Induced drag factor of the fin. */
  finInducedDrag: 0.1,
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
 * The tailplane's incidence, rad (about 0.017 degrees): its lift L_t at the tail arm l balances the
 * pitching moment of the fin's drag D_f at the fin height h, l L_t = h D_f, i.e.
 * l q S_t a_t i_t = h q S_f C_D0, so i_t = h S_f C_D0 / (l S_t a_t), the same at every speed.
 */
export const AIRCRAFT_TAIL_INCIDENCE =
  (AIRCRAFT.finHeight * AIRCRAFT.finArea * AIRCRAFT.tailDragZero) / (AIRCRAFT.tailArm * AIRCRAFT.tailArea * AIRCRAFT.tailSlope);

/**
 * The trim speed, m/s, of an aircraft whose wing has dihedral `dihedral` (rad, default
 * `AIRCRAFT.dihedral`): lift = weight with the body level. Each wing half meets the air at its
 * incidence i and lifts q (S/2) a i square to its span, so the vertical part of the wing's lift is
 * q S a i cos(dihedral); the tailplane adds q S_t a_t i_t. From
 * m g = (rho V^2 / 2)(S a i cos(dihedral) + S_t a_t i_t), V = sqrt(2 m g / (rho (S a i cos(dihedral) + S_t a_t i_t))) (a the wing's lift slope; about 114 m/s).
 * @throws RangeError if `dihedral` is not in [0, pi/6].
 */
export function aircraftTrimSpeed(dihedral: number = AIRCRAFT.dihedral): number {
  assertDihedral('aircraftTrimSpeed', dihedral);
  const A = AIRCRAFT;
  return Math.sqrt(
    (2 * A.mass * G) /
      (A.airDensity *
        (A.wingArea * DEFAULT_LIFT_SLOPE * A.incidence * Math.cos(dihedral) + A.tailArea * A.tailSlope * AIRCRAFT_TAIL_INCIDENCE)),
  );
}

/** The trim speed of the aircraft with its own dihedral, m/s (`aircraftTrimSpeed()`, about 114 m/s). */
export const AIRCRAFT_TRIM_SPEED = aircraftTrimSpeed();

/**
 * Drag of the level, trimmed aircraft at `speed` m/s (> 0), N: wing C_D0 + K C_L^2 at its incidence
 * (a wing half with dihedral meets air along the body x axis at its incidence too), tailplane
 * C_D0 + K_t (a_t i_t)^2 at its incidence, fin C_D0 at zero angle of attack: the thrust steady level
 * flight needs.
 */
export function aircraftLevelDrag(speed: number): number {
  const A = AIRCRAFT,
    q = 0.5 * A.airDensity * speed * speed;
  const cl = liftCoefficient(A.incidence, DEFAULT_LIFT_SLOPE, A.stallAngle, 0);
  const clTail = A.tailSlope * AIRCRAFT_TAIL_INCIDENCE;
  return (
    q *
    (A.wingArea * dragCoefficient(A.incidence, cl, A.stallAngle, A.dragZero, A.inducedDrag) +
      A.tailArea * (A.tailDragZero + A.tailInducedDrag * clTail * clTail) +
      A.finArea * A.tailDragZero)
  );
}

/** Refuses a dihedral that is not a finite angle in [0, pi/6] rad (0 to 30 degrees). */
function assertDihedral(where: string, dihedral: number): void {
  assertFinite(where, 'dihedral', dihedral);
  if (dihedral < 0 || dihedral > Math.PI / 6) throw new RangeError(`${where}: dihedral must be in [0, pi/6] rad, got ${dihedral}`);
}

/** Options of the `aircraft` scene. */
export interface AircraftOptions {
  /** Unused (one aircraft); must be 1 when given. */
  count?: number;
  /** Seed of the terrain; any finite number. Default 1. */
  seed?: number;
  /** Start altitude, m, > 0. Default 1,200. */
  altitude?: number;
  /** Start speed along +x, m/s, > 0. Default the trim speed (`aircraftTrimSpeed(dihedral)`). */
  speed?: number;
  /** Start thrust, N, in [0, maxThrust]. Default the level drag at the start speed. */
  thrust?: number;
  /**
   * Dihedral of the wing halves, rad, in [0, pi/6]. Default `AIRCRAFT.dihedral`. 0 gives a flat wing
   * with no dihedral effect (spirally unstable: a bank left alone steepens). The default start speed
   * is the trim speed of this dihedral.
   */
  dihedral?: number;
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
    assertKnownKeys(where, options, ['count', 'seed', 'altitude', 'speed', 'thrust', 'dihedral']);
    if (world.dimensions !== 3) throw new RangeError(`${where}: needs a 3D world, got dimensions ${world.dimensions}`);
    if (options.count !== undefined && options.count !== 1) throw new RangeError(`${where}: count must be 1, got ${String(options.count)}`);
    const seed = options.seed ?? 1;
    assertFinite(where, 'seed', seed);
    const altitude = options.altitude ?? 1200;
    assertPositive(where, 'altitude', altitude);
    const dihedral = options.dihedral ?? AIRCRAFT.dihedral;
    assertDihedral(where, dihedral);
    const speed = options.speed ?? aircraftTrimSpeed(dihedral);
    assertPositive(where, 'speed', speed);
    const A = AIRCRAFT;
    const thrust = options.thrust ?? aircraftLevelDrag(speed);
    assertFinite(where, 'thrust', thrust);
    if (thrust < 0 || thrust > A.maxThrust) throw new RangeError(`${where}: thrust must be in [0, ${A.maxThrust}], got ${thrust}`);
    if (world.capacity - world.entityIndex.aliveCount < 5) throw new RangeError(`${where}: the world needs room for 5 more entities`);

    const body = addBody(world, { position: [0, altitude, 0], velocity: [speed, 0, 0], mass: A.mass });
    setInertia(world, body, A.inertia);
    // Each half's normal: the wing's at its incidence, (-sin i, cos i, 0), turned about the body x
    // axis by the dihedral so that it leans inboard (the tip is raised).
    const ci = Math.cos(A.incidence),
      si = Math.sin(A.incidence),
      cg = Math.cos(dihedral),
      sg = Math.sin(dihedral);
    const wing = {
      area: A.wingArea / 2,
      controlPower: A.aileronPower,
      stallAngle: A.stallAngle,
      dragZero: A.dragZero,
      inducedDrag: A.inducedDrag,
      airDensity: A.airDensity,
    };
    const leftWing = addLiftingSurface(world, { body, offset: [0, 0, -A.wingHalfOffset], normal: [-si, ci * cg, ci * sg], ...wing });
    const rightWing = addLiftingSurface(world, { body, offset: [0, 0, A.wingHalfOffset], normal: [-si, ci * cg, -ci * sg], ...wing });
    const tail = addLiftingSurface(world, {
      body,
      offset: [-A.tailArm, 0, 0],
      normal: [-Math.sin(AIRCRAFT_TAIL_INCIDENCE), Math.cos(AIRCRAFT_TAIL_INCIDENCE), 0],
      area: A.tailArea,
      liftSlope: A.tailSlope,
      controlPower: A.elevatorPower,
      stallAngle: A.stallAngle,
      dragZero: A.tailDragZero,
      inducedDrag: A.tailInducedDrag,
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
      inducedDrag: A.finInducedDrag,
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
