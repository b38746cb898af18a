import type { PhysicsWorld } from '../world/options.js';
import { contact3DStateOf } from './manifolds-3d.js';

/**
 * Read access to the last step's 3D shape contacts (the manifold rows the soft-step solver used), for
 * debug drawing and game rules: one call per contact point, with a view object that is reused
 * (copy what you keep). Contacts of balls (`forEachContact`) are not listed here.
 */

/**
 * One 3D contact point of the last step. Bodies and shapes are slots (0: the static world or a plane or mesh).
 * @category Events
 */
export interface Contact3DView {
  /** Body slots A and B (A may be 0: the static world), and their shape slots (a plane or mesh entity for those). */
  bodyA: number;
  bodyB: number;
  shapeA: number;
  shapeB: number;
  /** Contact point on B where B was at the start of the step, m (world). */
  x: number;
  y: number;
  z: number;
  /** Unit normal from A to B. */
  nx: number;
  ny: number;
  nz: number;
  /** Separation at the start of the step, m (< 0: overlap; > 0: a speculative contact). */
  separation: number;
  /** Normal impulse the point carried in the last substep, N s (>= 0); 0 for a speculative point that never touched. */
  normalImpulse: number;
}

const view: Contact3DView = {
  bodyA: 0,
  bodyB: 0,
  shapeA: 0,
  shapeB: 0,
  x: 0,
  y: 0,
  z: 0,
  nx: 0,
  ny: 0,
  nz: 0,
  separation: 0,
  normalImpulse: 0,
};

/**
 * Calls `fn` once per contact point of the last step's 3D shape manifolds (up to four a manifold),
 * in solver order, with a reused view. @returns the number of points visited. A world without 3D
 * shapes has none. `fn` must not step or change the world.
 * @category Events
 */
export function forEachContact3D(world: PhysicsWorld, fn: (contact: Readonly<Contact3DView>) => void): number {
  const st = contact3DStateOf(world);
  if (st === undefined) return 0;
  const buf = st.current,
    P = world.components.PreviousPosition;
  let n = 0;
  for (let i = 0; i < buf.count; i++) {
    const b = buf.bodyB[i]!;
    view.bodyA = buf.bodyA[i]!;
    view.bodyB = b;
    view.shapeA = buf.shapeA[i]!;
    view.shapeB = buf.shapeB[i]!;
    view.nx = buf.nx[i]!;
    view.ny = buf.ny[i]!;
    view.nz = buf.nz[i]!;
    for (let k = 0, m = buf.points[i]!; k < m; k++) {
      const q = 4 * i + k;
      view.x = P.x[b]! + buf.rbx[q]!;
      view.y = P.y[b]! + buf.rby[q]!;
      view.z = P.z[b]! + buf.rbz[q]!;
      view.separation = buf.sep[q]!;
      view.normalImpulse = buf.ln[q]!;
      fn(view);
      n++;
    }
  }
  return n;
}
