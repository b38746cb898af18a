import { keepWhileAsleep, pushEvent, resumeAfterSleep } from '../collision/events.js';
import { clearRowIndex, contact3DStateOf, lookupRow, pushTouch, slotOfRow } from '../collision/manifolds-3d.js';
import type { PhysicsWorld } from '../world/options.js';
import { ANCHOR_BX, ANCHOR_BY, ANCHOR_BZ, ANCHOR_STRIDE } from './manifold-layout-3d.js';
import { joinSolverBodies } from './solver-bodies.js';
/**
 * The 3D shape contacts' rows of the contact solver (solver/contact-solver.ts calls these next to the ball contacts',
 * in the same substeps, on the same packed body state, stride 12: v, w, displacement, 1/m, an inverse
 * inertia flag, pushed): Box2D v3's manifold constraint (contact_solver.c) carried to 3D:
 *
 * - anchors r_A, r_B from the centres of mass at the start of the step; separation tracked as
 *   s = s0 + (d_B + theta_B x r_B - d_A - theta_A x r_A) . n, with d and theta each body's displacement
 *   and rotation so far in the step (rotation linearised);
 * - angular terms through the world inverse inertia tensor I^-1 = R diag(1/I_1, 1/I_2, 1/I_3) R^T
 *   (R from the orientation at the start of the solve); effective mass of a row along u:
 *   1 / (1/m_A + 1/m_B + (r_A x u) . I_A^-1 (r_A x u) + (r_B x u) . I_B^-1 (r_B x u));
 * - normal rows: speculative (s > 0: bias s / h_s) or soft (Box2D's soft constraint; twice as stiff
 *   against infinite mass; push-out speed capped), accumulated impulse >= 0; relax passes without bias;
 * - friction once a manifold, not once a point (a friction patch): two tangent rows t1, t2 = n x t1 at
 *   an anchor, the points' centre, solved together and held within the circle
 *   |(lambda_t1, lambda_t2)| <= mu sum(lambda_n) (the same limit whichever way it slides), and a twist row
 *   about n, |lambda_w| <= mu arm sum(lambda_n), arm the points' mean distance from the anchor (the
 *   torque their friction could resist: a cube spinning on its four corners slows as under Coulomb
 *   friction at each). A manifold of four points so solves three friction rows instead of eight. (An
 *   anchor weighted by the points' normal impulses wandered off the centre of a spinning cube, and its
 *   tangent rows then braked the spin too: twice the Coulomb torque after a few steps.);
 * - per point, r x n and I^-1 (r x n) of both bodies, and per manifold the anchor's r x t1, r x t2 and
 *   their I^-1 products, are computed once a step (the I^-1 products apart: `jacobiansInv`,
 *   `frictionInv`), so a pass reads them instead of multiplying tensors; a manifold whose two bodies are
 *   isotropic (I^-1 = i 1: spheres, cubes, or a static side) reads only r x u and scales it by i, half the
 *   memory a pass streams; a manifold's own numbers (normal, tangent, friction, effective masses, the
 *   speculative skip's bounds, both bodies' i), its friction rows' crosses and its points' normal rows,
 *   separations and effective masses are written into one block of `solveRecord`
 *   (solver/manifold-layout-3d.ts), which the warm start, the solve and restitution read instead of a
 *   column each; the points of a manifold are solved in alternating order from
 *   substep to substep; a manifold whose normal rows are all rigid in a pass (speculative, or a relax
 *   pass) is swept until they agree (NORMAL_SWEEPS), so a flat hit does not spin the boxes;
 * - warm start from the previous step's point with the same feature id (collision/shapes-3d.ts);
 * - restitution after the substeps, by the one definition every row family shares (solver/restitution.ts,
 *   after Box2D v3 b2ApplyRestitution): a point that approached faster than the threshold and carried an
 *   impulse leaves with v_n >= -e v_n0.
 */

/**
 * Whether the world has 3D shape rows to solve this step.
 * @category Collision
 */
export function manifolds3DToSolve(world: PhysicsWorld): boolean {
  const st = contact3DStateOf(world);
  return st !== undefined && st.current.count > 0;
}

/**
 * Gives every moving body of a 3D manifold a solver index (continuing the list), writes the rows' indices; returns the new count.
 * @category Collision
 */
export function gatherManifold3DBodies(world: PhysicsWorld, count: number): number {
  const st = contact3DStateOf(world);
  if (st === undefined || st.current.count === 0) return count;
  const buf = st.current;
  return joinSolverBodies(world.collision, buf.bodyA, buf.bodyB, buf.ia, buf.ib, buf.count, count);
}

/** finishManifolds3D's scratch: 1 for each entry of last step's touch list that a row touching now continues. */
let continued = new Uint8Array(0);

/**
 * After the solve: which pairs touch (a point carried a normal impulse, or overlapped at the start of
 * the step) against those of the last step gives the begin and end touch events. Called at the end of
 * the contact solver, also on steps without rows (so the last contacts end).
 * @category Collision
 */
export function finishManifolds3D(world: PhysicsWorld): void {
  const st = contact3DStateOf(world);
  if (st === undefined) return;
  const buf = st.current,
    P = st.previous,
    key = world.capacity + 1,
    prev = st.touching,
    now = st.touchingNext;
  const events = world.collision.events;
  now.count = 0;
  clearRowIndex(now.index, buf.count);
  if (continued.length < prev.count) continued = new Uint8Array(2 * prev.count);
  continued.fill(0, 0, prev.count);
  const NK = now.index.keys;
  for (let i = 0; i < buf.count; i++) {
    buf.touch[i] = -1;
    let touch = -1;
    for (let k = 0, m = buf.points[i]!; k < m; k++) {
      const q = 4 * i + k;
      if (buf.carried[q] === 1 || buf.sep[q]! < 0) {
        touch = q;
        break;
      }
    }
    if (touch < 0) continue;
    const k = buf.shapeA[i]! * key + buf.shapeB[i]!;
    // One probe finds the pair among this step's touching pairs, or where it goes.
    const slot = slotOfRow(now.index, k);
    if (NK[slot] === k) {
      buf.touch[i] = now.index.rows[slot]!;
      continue;
    }
    const entry = pushTouch(now, k, buf.shapeA[i]!, buf.shapeB[i]!, buf.bodyA[i]!, buf.bodyB[i]!);
    NK[slot] = k;
    now.index.rows[slot] = entry;
    now.index.count++;
    buf.touch[i] = entry;
    // Whether the pair touched last step: its previous row's entry in that step's list when it holds
    // this pair (a row that did not touch, or a buffer no finish wrote, falls back to the look-up).
    const p = buf.prevRow[i]!;
    let was = p >= 0 ? P.touch[p]! : -1;
    if (!(was >= 0 && was < prev.count && prev.keys[was] === k)) was = lookupRow(prev.index, k);
    if (was >= 0) {
      continued[was] = 1;
      continue;
    }
    if (resumeAfterSleep(world, buf.shapeA[i]!, buf.shapeB[i]!)) continue;
    const ev = events.begin;
    const r = pushEvent(world, ev, buf.shapeA[i]!, buf.shapeB[i]!, buf.bodyA[i]!, buf.bodyB[i]!);
    const c = world.components,
      b = buf.bodyB[i]!;
    const o = ANCHOR_STRIDE * touch;
    ev.px[r] = c.PreviousPosition.x[b]! + buf.anchors[o + ANCHOR_BX]!;
    ev.py[r] = c.PreviousPosition.y[b]! + buf.anchors[o + ANCHOR_BY]!;
    ev.pz[r] = c.PreviousPosition.z[b]! + buf.anchors[o + ANCHOR_BZ]!;
    ev.nx[r] = buf.nx[i]!;
    ev.ny[r] = buf.ny[i]!;
    ev.nz[r] = buf.nz[i]!;
    ev.approachSpeed[r] = Math.max(0, -buf.vn0[touch]!);
    let impulse = 0;
    for (let k = 0, m = buf.points[i]!; k < m; k++) impulse += buf.ln[4 * i + k]!;
    ev.impulse[r] = impulse;
  }
  // A pair of last step's list not continued by a row touching now has ended.
  for (let i = 0; i < prev.count; i++) {
    if (continued[i] === 1) continue;
    if (keepWhileAsleep(world, prev.shapeA[i]!, prev.shapeB[i]!, prev.bodyA[i]!, prev.bodyB[i]!)) continue;
    pushEvent(world, events.end, prev.shapeA[i]!, prev.shapeB[i]!, prev.bodyA[i]!, prev.bodyB[i]!);
  }
  st.touching = now;
  st.touchingNext = prev;
}
