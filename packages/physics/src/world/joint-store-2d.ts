/**
 * The `Joint` component: the parameters of a joint between two bodies, one entity per joint
 * (a joint is an entity holding its two bodies, like a spring). Data only; the joint solver
 * (joints/solver-2d.ts) builds its packed rows from it each step.
 */

/**
 * Joint types (Box2D v3's joint set, 2D):
 * - `Distance` (0): keeps two anchor points at `length` (a rigid rod), or a spring of `hertz` toward
 *   it, or only within [minLength, maxLength] (a rope link that only pulls: min 0, max L);
 * - `Revolute` (1): a pin; the anchors coincide; optional angle limits, motor and angular spring;
 * - `Prismatic` (2): B slides along `axis` (fixed in A) without turning relative to A; optional
 *   translation limits, motor and spring along the axis;
 * - `Weld` (3): glues B to A (anchors coincide, relative angle fixed), optionally soft;
 * - `Wheel` (4): B's anchor stays on the line through A's anchor along `axis`, with a suspension
 *   spring along it; B spins freely, driven by an optional motor (a car wheel);
 * - `Mouse` (5): pulls B's anchor toward a moving world target with a soft spring of at most
 *   `maxForce` (dragging with the pointer).
 * @category Joints and ropes
 */
export const JointType = Object.freeze({ Distance: 0, Revolute: 1, Prismatic: 2, Weld: 3, Wheel: 4, Mouse: 5 } as const);

/**
 * One of the `JointType` codes.
 * @category Joints and ropes
 */
export type JointTypeCode = (typeof JointType)[keyof typeof JointType];

/**
 * Names of the joint types, indexed by code (for messages).
 * @category Joints and ropes
 */
export const JOINT_TYPE_NAMES = ['distance', 'revolute', 'prismatic', 'weld', 'wheel', 'mouse'] as const;

/**
 * Bits of `Joint.flags`.
 * @category Joints and ropes
 */
export const JointFlag = Object.freeze({ Spring: 1, Limit: 2, Motor: 4 } as const);

/**
 * Parameters of a joint entity. Units SI: m, rad, s, N, N m. Written by the `add*Joint` and
 * `setJoint*` functions (joints/api-2d.ts), which validate them; read by the joint solver.
 * @category Joints and ropes
 */
export interface JointStore {
  /** JointType code. */
  type: Uint8Array;
  /** Body A (entity slot), or 0 for the fixed world (then the local anchor of A is a world point). */
  a: Int32Array;
  /** Body B (entity slot), always a body. */
  b: Int32Array;
  /** Anchor on A in A's body frame (relative to its centre of mass), m; a world point when `a` is 0. */
  localAx: Float64Array;
  localAy: Float64Array;
  /** Anchor on B in B's body frame, m. */
  localBx: Float64Array;
  localBy: Float64Array;
  /** Angle of B minus angle of A when the joint was made, rad: the relative angle the joint holds (revolute limits are measured from it). */
  referenceAngle: Float64Array;
  /** Unit axis in A's body frame (prismatic: the slide; wheel: the suspension), dimensionless. */
  axisX: Float64Array;
  axisY: Float64Array;
  /** Distance joint: rest length, m, and the range [minLength, maxLength] it may not leave, m. */
  length: Float64Array;
  minLength: Float64Array;
  maxLength: Float64Array;
  /**
   * Spring stiffness as a natural frequency, Hz (>= 0; 0 = no spring, or rigid where the joint is
   * rigid) and damping ratio (>= 0): distance (along the rod), revolute (angular, toward the
   * reference angle), prismatic and wheel (along the axis), weld (linear part), mouse (the pull).
   */
  hertz: Float64Array;
  dampingRatio: Float64Array;
  /** Weld: angular softness, Hz (0 = rigid) and damping ratio. */
  angularHertz: Float64Array;
  angularDampingRatio: Float64Array;
  /** JointFlag bits: spring, limit, motor enabled. */
  flags: Uint8Array;
  /** Limits: revolute angle (rad, relative to the reference angle), prismatic and wheel translation along the axis (m). */
  lower: Float64Array;
  upper: Float64Array;
  /** Motor target speed: rad/s (revolute, wheel: B relative to A, counter-clockwise), m/s (prismatic, along the axis). */
  motorSpeed: Float64Array;
  /** Motor's largest torque, N m (revolute, wheel), or force, N (prismatic), >= 0. */
  maxMotorForce: Float64Array;
  /** Mouse joint: largest pulling force, N. */
  maxForce: Float64Array;
  /** The joint breaks (is removed, with a break event) when its constraint force exceeds this, N. Infinity = never. */
  breakForce: Float64Array;
  /** The joint breaks when its constraint torque exceeds this, N m. Infinity = never. */
  breakTorque: Float64Array;
  /** Distance joint: breaks when (length - rest length) / rest length exceeds this strain (tearing cloth), dimensionless. Infinity = never. */
  breakStretch: Float64Array;
  /** Output of the last step: magnitude of the constraint force the joint applied, N (impulse / substep). */
  force: Float64Array;
  /** Output of the last step: magnitude of the constraint torque the joint applied (limits, motor, angular parts), N m. */
  torque: Float64Array;
}

/**
 * The Joint store with empty arrays (it is lazily allocated: see LAZY_COMPONENTS).
 * @category Joints and ropes
 */
export function createJointStore(): JointStore {
  const z = (): Float64Array => new Float64Array(0);
  return {
    type: new Uint8Array(0),
    a: new Int32Array(0),
    b: new Int32Array(0),
    localAx: z(),
    localAy: z(),
    localBx: z(),
    localBy: z(),
    referenceAngle: z(),
    axisX: z(),
    axisY: z(),
    length: z(),
    minLength: z(),
    maxLength: z(),
    hertz: z(),
    dampingRatio: z(),
    angularHertz: z(),
    angularDampingRatio: z(),
    flags: new Uint8Array(0),
    lower: z(),
    upper: z(),
    motorSpeed: z(),
    maxMotorForce: z(),
    maxForce: z(),
    breakForce: z(),
    breakTorque: z(),
    breakStretch: z(),
    force: z(),
    torque: z(),
  };
}
