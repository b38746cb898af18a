/**
 * The submarine's dive planes: small wings at the bow and the stern that the helm turns together, so
 * the water flowing past a boat under way lifts or presses the hull across its axis at once, without
 * waiting for the tanks. A foil's lift is L = 1/2 rho A C_L u^2 with C_L = a delta (thin-aerofoil
 * theory corrected for a short span: a = 2 pi AR / (AR + 2), Anderson, Fundamentals of Aerodynamics,
 * ch. 5), and its induced drag D = L^2 / (1/2 rho u^2 pi AR e A) with e = 0.9 (the same chapter). At
 * rest the planes do nothing; at the boat's top speed of 8 m/s they give up to 170 kN (440 kN at 12.9 m/s), beside the
 * vertical thrusters' 600 kN, so a boat under way answers the helm faster and stops its dive sooner.
 * Headless (no drawing), so the law is tested in node.
 */

import { addSystem, type PhysicsWorld, slotOf } from '@bitphysics/physics';
import { SUBMARINE, type SubmarineHandles } from '@bitphysics/projects';

const DEG = Math.PI / 180;

/** The planes' settings. */
export const PLANES = Object.freeze({
  /** Area of the bow and stern planes together, m^2 (two pairs of 2 m x 1 m foils, span 2 m each). */
  area: 4,
  /** Aspect ratio of each foil (span^2 / area). */
  aspectRatio: 2,
  /** Largest plane angle, rad (25 degrees: a foil of this aspect ratio stalls not far beyond). */
  maxAngle: 25 * DEG,
  /** How fast the hydraulics turn the planes, rad/s: full throw in an eighth of a second. */
  rate: 200 * DEG,
  /** Sea water, kg/m^3 (the planes are real 3D foils: SUBMARINE.seaWaterDensity, not the 2D water). */
  density: SUBMARINE.seaWaterDensity,
  /** Span efficiency of the foils (Oswald factor). */
  efficiency: 0.9,
});

/** Lift slope of a foil of the planes' aspect ratio, per radian: 2 pi AR / (AR + 2). */
export const PLANE_LIFT_SLOPE = (2 * Math.PI * PLANES.aspectRatio) / (PLANES.aspectRatio + 2);

/**
 * The planes' lift across the hull, N (positive: toward the hull's own +y, up when level), at plane
 * angle `angle` (rad, positive: leading edge up, lifting) with the water flowing past at `u` (m/s,
 * along the hull, positive ahead; astern the lift reverses) and the fraction `submerged` in [0, 1]
 * of the hull under water (planes in the air lift nothing): 1/2 rho A a angle u |u| submerged.
 */
export function planeLift(angle: number, u: number, submerged: number): number {
  return 0.5 * PLANES.density * PLANES.area * PLANE_LIFT_SLOPE * angle * u * Math.abs(u) * submerged;
}

/** The plane angle now, rad, of each world's hull that has planes (set by the helm each step). */
const planeAngles = new WeakMap<PhysicsWorld, Float64Array>();

/**
 * The plane angle of the submarine in `world`, rad, as a one-element array the helm writes: installs
 * the planes' force law on the world the first time (one submarine a world). Each step the law pushes
 * the hull across its axis by `planeLift` at the hull's speed along its axis, and holds it back along
 * its velocity by the planes' induced drag.
 */
export function divePlanes(world: PhysicsWorld, handles: SubmarineHandles): Float64Array {
  let angle = planeAngles.get(world);
  if (angle) return angle;
  const a = new Float64Array(1);
  planeAngles.set(world, a);
  const e = slotOf(handles.hull),
    sea = slotOf(handles.sea);
  const H = SUBMARINE.height;
  addSystem(world, 'forces', (w: PhysicsWorld) => {
    const delta = a[0]!;
    if (delta === 0) return;
    const c = w.components;
    const th = c.Angle.value[e]!,
      co = Math.cos(th),
      s = Math.sin(th);
    const vx = c.Velocity.x[e]!,
      vy = c.Velocity.y[e]!;
    const u = vx * co + vy * s;
    const submerged = Math.max(0, Math.min(1, (c.FluidRegion.surface[sea]! - (c.Position.y[e]! - H / 2)) / H));
    const lift = planeLift(delta, u, submerged);
    if (lift === 0) return;
    // Lift along the hull's own y axis (-sin, cos); induced drag against the velocity.
    const q = 0.5 * PLANES.density * u * u * submerged;
    const drag = (lift * lift) / (q * Math.PI * PLANES.aspectRatio * PLANES.efficiency * PLANES.area);
    const speed = Math.hypot(vx, vy);
    c.Force.x[e] = c.Force.x[e]! - lift * s - (speed > 0 ? (drag * vx) / speed : 0);
    c.Force.y[e] = c.Force.y[e]! + lift * co - (speed > 0 ? (drag * vy) / speed : 0);
  });
  angle = a;
  return angle;
}
