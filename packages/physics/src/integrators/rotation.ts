import type { PhysicsWorld } from '../world';
import { reportNonFinite } from '../errors';
import { spinningBodies, torquedBodies } from './queries';

/**
 * Angular velocity update from torque with a scalar moment of inertia: w += tau I^-1 h
 * (2D: the z component; 3D: bodies whose inertia is isotropic, such as balls). Newton's second law
 * for rotation, Ramtal and Dobre ch. 13.
 */
export function applyTorques(world: PhysicsWorld, h: number): void {
  const c = world.components;
  const ents = torquedBodies(world);
  if (ents.length === 0) return;
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  const tx = c.Torque.x, ty = c.Torque.y, tz = c.Torque.z;
  const ii = c.Inertia.inv;
  if (world.dimensions === 2) {
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      wz[e] = wz[e]! + tz[e]! * ii[e]! * h;
    }
  } else {
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const k = ii[e]! * h;
      wx[e] = wx[e]! + tx[e]! * k;
      wy[e] = wy[e]! + ty[e]! * k;
      wz[e] = wz[e]! + tz[e]! * k;
    }
  }
}

/**
 * Advances orientations with the current angular velocity over h.
 * 2D: angle += w_z h. 3D: q <- exp(w h / 2) q, the exact rotation by |w| h about w (world frame)
 * for constant w, then renormalised so |q| stays 1 to rounding.
 * Source: Shoemake, "Animating rotation with quaternion curves" (SIGGRAPH 1985); Ramtal and Dobre ch. 15.
 */
export function advanceOrientations(world: PhysicsWorld, h: number): void {
  const c = world.components;
  const ents = spinningBodies(world);
  if (ents.length === 0) return;
  const wx = c.AngularVelocity.x, wy = c.AngularVelocity.y, wz = c.AngularVelocity.z;
  let check = 0;
  if (world.dimensions === 2) {
    const a = c.Angle.value;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const w = wz[e]!;
      a[e] = a[e]! + w * h;
      check += w;
    }
  } else {
    const qx = c.Orientation.x, qy = c.Orientation.y, qz = c.Orientation.z, qw = c.Orientation.w;
    for (let i = 0; i < ents.length; i++) {
      const e = ents[i]!;
      const ax = wx[e]!, ay = wy[e]!, az = wz[e]!;
      check += ax + ay + az;
      const speed = Math.sqrt(ax * ax + ay * ay + az * az);
      if (speed === 0) continue;
      const half = 0.5 * speed * h;
      const s = Math.sin(half) / speed;
      const dx = ax * s, dy = ay * s, dz = az * s, dw = Math.cos(half);
      const x = qx[e]!, y = qy[e]!, z = qz[e]!, w = qw[e]!;
      // d * q (Hamilton product)
      let nx = dw * x + dx * w + dy * z - dz * y;
      let ny = dw * y - dx * z + dy * w + dz * x;
      let nz = dw * z + dx * y - dy * x + dz * w;
      let nw = dw * w - dx * x - dy * y - dz * z;
      const inv = 1 / Math.sqrt(nx * nx + ny * ny + nz * nz + nw * nw);
      nx *= inv; ny *= inv; nz *= inv; nw *= inv;
      qx[e] = nx; qy[e] = ny; qz[e] = nz; qw[e] = nw;
    }
  }
  if (check - check !== 0) reportNonFinite(world, ents, 'integrate');
}
