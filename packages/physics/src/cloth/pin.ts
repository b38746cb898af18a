import { addComponent, hasComponent, removeComponent } from 'bitecs';
import { assertNonNegative, assertOptions, assertPositive, assertVector } from '../validation/validate.js';
import type { ClothState } from '../world/cloth-state.js';
import { isAlive, resolveKind } from '../world/handles.js';
import type { PhysicsWorld } from '../world/options.js';

/**
 * Options of `pinClothPoint` that make its pin soft.
 * @category Cloth
 */
export interface ClothPinOptions {
  /**
   * Compliance of the spring that pulls the point toward its position, m/N, >= 0: 1 / stiffness (0.01 m/N
   * is 100 N/m); 0 puts the point on its position in each substep, unless `maxForce` holds it back.
   * Default 0.
   */
  compliance?: number;
  /** Largest force the pin pulls with, N, > 0 (Infinity for no bound). Default Infinity. */
  maxForce?: number;
}

const PIN_KEYS = ['compliance', 'maxForce'] as const;

/**
 * Holds a cloth point (or any dynamic body) at `position` (m), or with `position` null lets it go again.
 * Call it every frame with the pointer's position to drag.
 *
 * Without `options` the pin is hard: the point is kinematic with zero velocity, links pull on it as on a
 * pin, so dragging it away tears the cloth around it (links past their `tearStretch`), all of the strain
 * in the few links at that point.
 *
 * With `options` the pin is soft: the point keeps its mass and, in each substep of the cloth solver
 * (cloth/solver.ts) before its links, is pulled toward `position` by a zero-length XPBD spring of
 * compliance alpha, its force capped at `maxForce`: for C = |x - position|, inverse mass w and alpha~ =
 * alpha / h_s^2, the multiplier dlambda = min(C / (w + alpha~), maxForce h_s^2) moves the point
 * w dlambda toward `position` (Macklin, Mueller and Chentanez, "XPBD", 2016; the force is
 * dlambda / h_s^2). Its links then pull back, so the point lags behind a fast-moving `position` and the
 * pull spreads into the cloth; pinning several neighbouring points softly, each with a share of the
 * stiffness and of the force, grips a patch. A soft pin acts on points of cloth links only (a body
 * without any is not moved) and is stored in `world.cloth` (`softPin*`), with the force it last pulled
 * with in `softPinForce`. A soft pin on a hard-pinned point frees it first, and a hard pin drops a
 * soft one.
 * @param point a body's handle.
 * @param position the point's target (2 numbers, m), or null to let go.
 * @param options absent for a hard pin; for a soft one, its compliance and largest force.
 * @throws RangeError if `point` is not a live body, or is static; TypeError | RangeError on a bad
 *   position or options (unknown keys, compliance < 0, maxForce <= 0).
 * @category Cloth
 */
export function pinClothPoint(world: PhysicsWorld, point: number, position: ArrayLike<number> | null, options?: ClothPinOptions): void {
  const where = 'pinClothPoint';
  const e = resolveKind(world, point, 'body', where, 'point');
  const c = world.components;
  if (hasComponent(world, e, c.Static)) throw new RangeError(`${where}: point must be a moving body, got a static one (id ${point})`);
  if (position !== null) assertVector(where, 'position', position, 2);
  let compliance = 0,
    maxForce = Infinity;
  if (options !== undefined) {
    assertOptions(where, options, PIN_KEYS);
    if (options.compliance !== undefined) {
      assertNonNegative(where, 'compliance', options.compliance);
      compliance = options.compliance;
    }
    if (options.maxForce !== undefined && options.maxForce !== Infinity) {
      assertPositive(where, 'maxForce', options.maxForce);
      maxForce = options.maxForce;
    }
  }
  const cl = world.cloth;
  pruneSoftPins(world, cl);
  if (position === null || options !== undefined) {
    if (hasComponent(world, e, c.Kinematic)) {
      removeComponent(world, e, c.Kinematic);
      const m = c.Mass.value[e]!;
      c.Mass.inv[e] = m > 0 ? 1 / m : 0;
    }
  }
  if (position === null || options === undefined) dropSoftPin(cl, point);
  if (position === null) return;
  if (options !== undefined) {
    let row = findSoftPin(cl, point);
    if (row < 0) {
      row = cl.softPinCount;
      growSoftPins(cl, row + 1);
      cl.softPinCount = row + 1;
      cl.softPinHandle[row] = point;
      cl.softPinForce[row] = 0;
    }
    cl.softPinTarget[2 * row] = position[0]!;
    cl.softPinTarget[2 * row + 1] = position[1]!;
    cl.softPinCompliance[row] = compliance;
    cl.softPinMaxForce[row] = maxForce;
    return;
  }
  if (!hasComponent(world, e, c.Kinematic)) {
    addComponent(world, e, c.Kinematic);
    c.Mass.inv[e] = 0;
  }
  c.Position.x[e] = position[0]!;
  c.Position.y[e] = position[1]!;
  c.PreviousPosition.x[e] = position[0]!;
  c.PreviousPosition.y[e] = position[1]!;
  c.Velocity.x[e] = 0;
  c.Velocity.y[e] = 0;
}

/** Row of `point`'s soft pin in `cl`, or -1. */
function findSoftPin(cl: ClothState, point: number): number {
  for (let i = 0; i < cl.softPinCount; i++) if (cl.softPinHandle[i] === point) return i;
  return -1;
}

/** Removes row `row` of the soft pins, keeping the others in order. */
function removeSoftPinRow(cl: ClothState, row: number): void {
  const n = cl.softPinCount - 1;
  cl.softPinHandle.copyWithin(row, row + 1, n + 1);
  cl.softPinTarget.copyWithin(2 * row, 2 * row + 2, 2 * n + 2);
  cl.softPinCompliance.copyWithin(row, row + 1, n + 1);
  cl.softPinMaxForce.copyWithin(row, row + 1, n + 1);
  cl.softPinForce.copyWithin(row, row + 1, n + 1);
  cl.softPinCount = n;
}

/** Drops `point`'s soft pin, if it has one. */
function dropSoftPin(cl: ClothState, point: number): void {
  const row = findSoftPin(cl, point);
  if (row >= 0) removeSoftPinRow(cl, row);
}

/** Drops the soft pins of removed bodies. */
function pruneSoftPins(world: PhysicsWorld, cl: ClothState): void {
  for (let i = cl.softPinCount - 1; i >= 0; i--) if (!isAlive(world, cl.softPinHandle[i]!)) removeSoftPinRow(cl, i);
}

/** Makes room for `n` soft pins (capacity doubles, contents kept). */
function growSoftPins(cl: ClothState, n: number): void {
  if (cl.softPinHandle.length >= n) return;
  const cap = Math.max(8, 2 * n);
  const grow = (a: Float64Array, k: number): Float64Array => {
    const b = new Float64Array(k * cap);
    b.set(a);
    return b;
  };
  cl.softPinHandle = grow(cl.softPinHandle, 1);
  cl.softPinTarget = grow(cl.softPinTarget, 2);
  cl.softPinCompliance = grow(cl.softPinCompliance, 1);
  cl.softPinMaxForce = grow(cl.softPinMaxForce, 1);
  cl.softPinForce = grow(cl.softPinForce, 1);
}
