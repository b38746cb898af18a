/**
 * The value each field of a component takes when the component is added to an entity: the defaults
 * that the components' docstrings give (world/components.ts). bitecs recycles ids at once and leaves
 * the old entity's data in the stores, so every add writes them; create-world.ts installs one observer
 * a component from this table. Position, Velocity, Force, AngularVelocity and Torque are reset there
 * by hand (adding a Position resets an entity's whole motion state), and so is RandomForce's seed (the
 * entity's own id).
 */

import { type Components, DEFAULT_MATERIAL, DEFAULT_RADIUS } from './components.js';

/** A component's fields by name, each with the number it starts at (SI, as its docstring says). */
type Defaults<C> = { readonly [F in keyof C]?: number };

/**
 * Each component's fields and their values on add, in the order they are written.
 * @category World and step
 */
export const COMPONENT_DEFAULTS: { readonly [K in keyof Components]?: Defaults<Components[K]> } = Object.freeze({
  Mass: { value: 1, inv: 1 },
  Ball: { radius: DEFAULT_RADIUS },
  Material: {
    restitution: DEFAULT_MATERIAL.restitution,
    friction: DEFAULT_MATERIAL.friction,
    staticFriction: DEFAULT_MATERIAL.friction,
  },
  Segment: { ax: 0, ay: 0, az: 0, bx: 0, by: 0, bz: 0, radius: 0 },
  Angle: { value: 0 },
  Orientation: { x: 0, y: 0, z: 0, w: 1 },
  Inertia: { value: 0, inv: 0 },
  InertiaTensor: { x: 0, y: 0, z: 0, invX: 0, invY: 0, invZ: 0 },
  AngularDamping: { k: 0 },
  Plane: { nx: 0, ny: 1, nz: 0, d: 0 },
  LinearDrag: { k: 0 },
  QuadraticDrag: { k: 0 },
  GravityScale: { value: 1 },
  Attractor: { mass: 0, softening: 0 },
  Charge: { value: 0 },
  ElectricField: { x: 0, y: 0, z: 0, ampX: 0, ampY: 0, ampZ: 0, omega: 0, phase: 0 },
  MagneticField: { x: 0, y: 0, z: 0, ampX: 0, ampY: 0, ampZ: 0, omega: 0, phase: 0 },
  CentralForce: { cx: 0, cy: 0, cz: 0, k: 0, n: 2 },
  Lift: { k: 0, axisX: 0, axisY: 0, axisZ: 1 },
  Buoyancy: { shape: 0, radius: 0.5, halfX: 0.5, halfY: 0.5, halfZ: 0.5, dragCoefficient: 0 },
  FluidRegion: { surface: 0, density: 1000, minX: -Infinity, maxX: Infinity, minZ: -Infinity, maxZ: Infinity },
  Spring: { a: 0, b: 0, restLength: 1, stiffness: 0, damping: 0, oneSided: 0, anchorX: 0, anchorY: 0, anchorZ: 0 },
  DrivingForce: { x: 0, y: 0, z: 0, omega: 0, phase: 0 },
  RandomForce: { magnitude: 0, correlationTime: 1 },
  Thrust: { exhaustVelocity: 0, massFlowRate: 0, fuel: 0, dirX: 0, dirY: 1, dirZ: 0 },
  Vortex: { cx: 0, cy: 0, cz: 0, axisX: 0, axisY: 0, axisZ: 1, k: 0, n: 1 },
  Lifetime: { age: 0, duration: 1 },
});
