/**
 * Writing a solver body's velocities back to its packed row (CollisionState.bodyState,
 * solver/body-state-layout.ts): the contact sweeps read a row pair's bodies into locals, apply the
 * row's impulses to those, and store them once at the end of the row. One function a dimension, so
 * every sweep writes the same slots in the same way; V8 inlines these small calls into the sweeps'
 * loops.
 */

import { BS2_VX, BS2_VY, BS2_W, BS3_VX, BS3_VY, BS3_VZ, BS3_WX, BS3_WY, BS3_WZ } from './body-state-layout.js';

/**
 * Writes the velocities a 2D contact row left in its locals back to its bodies' rows in `sb`, at
 * offsets `a` and `b` (BS2_STRIDE times the solver indices; not checked: the sweeps' offsets are in
 * range): velocity x and y (m/s) and spin (rad/s) of A, then of B.
 */
export function storeVelocities2D(
  sb: Float64Array,
  a: number,
  b: number,
  vax: number,
  vay: number,
  wa: number,
  vbx: number,
  vby: number,
  wb: number,
): void {
  sb[a + BS2_VX] = vax;
  sb[a + BS2_VY] = vay;
  sb[a + BS2_W] = wa;
  sb[b + BS2_VX] = vbx;
  sb[b + BS2_VY] = vby;
  sb[b + BS2_W] = wb;
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
