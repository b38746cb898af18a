/**
 * Writing a solver body's velocities back to its packed row (CollisionState.bodyState,
 * solver/body-state-layout.ts): the contact sweeps read a row pair's bodies into locals, apply the
 * row's impulses to those, and store them once at the end of the row. One function a dimension, so
 * every sweep writes the same slots in the same way; V8 inlines these small calls into the sweeps'
 * loops.
 */

import { BS2_VX, BS2_VY, BS2_W, BS3_VX, BS3_VY, BS3_VZ, BS3_WX, BS3_WY, BS3_WZ } from './body-state-layout.js';

/**
 * Writes a 2D body's velocity (vx, vy, m/s) and spin (w, rad/s) into `sb` at row offset `o`
 * (BS2_STRIDE times the solver index; not checked: the sweeps' offsets are in range).
 */
export function storeBody2D(sb: Float64Array, o: number, vx: number, vy: number, w: number): void {
  sb[o + BS2_VX] = vx;
  sb[o + BS2_VY] = vy;
  sb[o + BS2_W] = w;
}

/**
 * Writes a 3D body's velocity (vx, vy, vz, m/s) and angular velocity (wx, wy, wz, world frame, rad/s)
 * into `sb` at row offset `o` (BS3_STRIDE times the solver index; not checked: the sweeps' offsets are
 * in range).
 */
export function storeBody3D(sb: Float64Array, o: number, vx: number, vy: number, vz: number, wx: number, wy: number, wz: number): void {
  sb[o + BS3_VX] = vx;
  sb[o + BS3_VY] = vy;
  sb[o + BS3_VZ] = vz;
  sb[o + BS3_WX] = wx;
  sb[o + BS3_WY] = wy;
  sb[o + BS3_WZ] = wz;
}
