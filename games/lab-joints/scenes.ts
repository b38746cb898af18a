/**
 * The lab's six scenes, each a builder of a 2D world (no DOM): pendulum, chain, bridge, car, ragdoll,
 * windmill. Bodies are balls (circles) joined by joints; the lab draws the joints as lines.
 */
import { addBody, addRevoluteJoint, addSegment, addWeldJoint, addWheelJoint, type PhysicsWorld } from '@bitphysics/physics';

/** Names of the scenes, in the panel's order. */
export const SCENE_NAMES = ['pendulum', 'chain', 'bridge', 'car', 'ragdoll', 'windmill'] as const;
export type SceneName = (typeof SCENE_NAMES)[number];

/** What a scene built: handles the lab reads (any may be absent). */
export interface JointScene {
  /** Pendulum: the bob, its pin, length (m), release angle (rad). */
  bob?: number;
  pin?: number;
  length?: number;
  amplitude?: number;
  /** Car: chassis and the driven wheel joints. */
  chassis?: number;
  wheels?: number[];
  /** Windmill: rotor and its motor joint. */
  rotor?: number;
  motor?: number;
}

/** Scene parameters from the panel. */
export interface SceneParams {
  /** Pendulum release angle, degrees. */
  amplitude: number;
  /** Motor speed: car wheels (rad/s, clockwise drives right) and windmill (rad/s). */
  motorSpeed: number;
}

const ground = (world: PhysicsWorld, y = -3): void => {
  addSegment(world, { a: [-12, y], b: [12, y], friction: 0.8 });
};

/** Builds `name` into `world`. */
export function buildScene(world: PhysicsWorld, name: SceneName, p: SceneParams): JointScene {
  switch (name) {
    case 'pendulum': {
      // A 2 m pendulum: a 1 kg ball on a light rigid arm (the ball's own disc inertia about its centre).
      const L = 2,
        a = (p.amplitude * Math.PI) / 180;
      const bob = addBody(world, { position: [L * Math.sin(a), 2 - L * Math.cos(a)], mass: 1, radius: 0.2, inertia: 0.02 });
      const pin = addRevoluteJoint(world, { b: bob, anchor: [0, 2] });
      return { bob, pin, length: L, amplitude: a };
    }
    case 'chain': {
      ground(world);
      let prev = 0;
      for (let i = 0; i < 24; i++) {
        const b = addBody(world, { position: [-4 + (i + 0.5) * 0.3, 2.5], mass: 0.2, radius: 0.12 });
        addRevoluteJoint(world, prev ? { a: prev, b, anchor: [-4 + i * 0.3, 2.5] } : { b, anchor: [-4, 2.5] });
        prev = b;
      }
      return {};
    }
    case 'bridge': {
      ground(world, -3.5);
      const n = 16,
        span = 9,
        y = 0;
      let prev = 0;
      const left = -span / 2,
        w = span / n;
      for (let i = 0; i < n; i++) {
        const b = addBody(world, { position: [left + (i + 0.5) * w, y], mass: 1, radius: 0.14, inertia: (1 * w * w) / 12 });
        addRevoluteJoint(world, prev ? { a: prev, b, anchor: [left + i * w, y] } : { b, anchor: [left, y] });
        prev = b;
      }
      addRevoluteJoint(world, { b: prev, anchor: [left + span, y] });
      // Something to carry: a few heavy balls dropped on the deck.
      for (let i = 0; i < 4; i++) addBody(world, { position: [-2 + i * 1.3, 2 + i * 0.6], mass: 2, radius: 0.3, restitution: 0.2 });
      return {};
    }
    case 'car': {
      addSegment(world, { a: [-12, -3], b: [40, -3], friction: 0.9 });
      for (let i = 0; i < 8; i++) addBody(world, { position: [-3 + i * 4, -3.2], static: true, radius: 0.45, friction: 0.9 });
      const chassis = addBody(world, { position: [-8, -1.6], mass: 4, inertia: (4 * (2.4 * 2.4 + 0.5 * 0.5)) / 12 });
      const wheels: number[] = [];
      for (const dx of [-0.9, 0.9]) {
        const wheel = addBody(world, { position: [-8 + dx, -2.45], mass: 0.6, radius: 0.4, friction: 1.2 });
        wheels.push(
          addWheelJoint(world, {
            a: chassis,
            b: wheel,
            axis: [0, 1],
            hertz: 4,
            dampingRatio: 0.7,
            lower: -0.25,
            upper: 0.25,
            motorSpeed: -p.motorSpeed,
            maxMotorTorque: 20,
          }),
        );
      }
      return { chassis, wheels };
    }
    case 'ragdoll': {
      ground(world);
      // Torso (two balls welded), head, arms and legs of two segments each; pins with angle limits.
      const b = (x: number, y: number, r: number, m: number) => addBody(world, { position: [x, y], radius: r, mass: m, friction: 0.6 });
      const chest = b(0, 1.2, 0.25, 4),
        hips = b(0, 0.75, 0.22, 3);
      addWeldJoint(world, { a: chest, b: hips, anchor: [0, 0.95], hertz: 8, dampingRatio: 0.7, angularHertz: 8, angularDampingRatio: 0.7 });
      const head = b(0, 1.72, 0.18, 1.5);
      addRevoluteJoint(world, { a: chest, b: head, anchor: [0, 1.5], lowerAngle: -0.6, upperAngle: 0.6 });
      for (const s of [-1, 1]) {
        const upperArm = b(s * 0.45, 1.3, 0.09, 0.8),
          lowerArm = b(s * 0.8, 1.3, 0.08, 0.6);
        addRevoluteJoint(world, { a: chest, b: upperArm, anchor: [s * 0.28, 1.3], lowerAngle: -2.5, upperAngle: 2.5 });
        addRevoluteJoint(world, {
          a: upperArm,
          b: lowerArm,
          anchor: [s * 0.62, 1.3],
          lowerAngle: s > 0 ? 0 : -2.4,
          upperAngle: s > 0 ? 2.4 : 0,
        });
        const thigh = b(s * 0.15, 0.3, 0.11, 1.5),
          shin = b(s * 0.15, -0.15, 0.1, 1);
        addRevoluteJoint(world, { a: hips, b: thigh, anchor: [s * 0.15, 0.55], lowerAngle: -1.5, upperAngle: 1.5 });
        addRevoluteJoint(world, { a: thigh, b: shin, anchor: [s * 0.15, 0.08], lowerAngle: -2.4, upperAngle: 0 });
      }
      return {};
    }
    case 'windmill': {
      ground(world);
      addSegment(world, { a: [0, -3], b: [0, 1.4], radius: 0.08 });
      const rotor = addBody(world, { position: [0, 1.5], mass: 2, radius: 0.2, inertia: 0.5 });
      const motor = addRevoluteJoint(world, { b: rotor, anchor: [0, 1.5], motorSpeed: p.motorSpeed, maxMotorTorque: 200 });
      for (let k = 0; k < 4; k++) {
        const a = (k * Math.PI) / 2;
        for (let s = 1; s <= 3; s++) {
          const blade = addBody(world, { position: [0.45 * s * Math.cos(a), 1.5 + 0.45 * s * Math.sin(a)], mass: 0.3, radius: 0.16 });
          addWeldJoint(world, { a: rotor, b: blade, anchor: [0.45 * s * Math.cos(a), 1.5 + 0.45 * s * Math.sin(a)] });
        }
      }
      // Balls to bat around.
      for (let i = 0; i < 12; i++)
        addBody(world, { position: [-3 + (i % 6) * 1.1, 4 + Math.floor(i / 6)], mass: 0.5, radius: 0.22, restitution: 0.4 });
      return { rotor, motor };
    }
  }
}
