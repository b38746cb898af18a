import type { JointState } from './joint-state-2d.js';

/**
 * Which jointed pairs of bodies do not collide (Box2D's `collideConnected = false`, the default): per
 * body a count of its joints that keep their bodies apart (`JointState.noCollide`), and a map from the
 * pair's key to how many such joints join it (`JointState.noCollidePairs`). The narrowphase looks the
 * map up only when both bodies have such a joint, so worlds and bodies without joints pay one array read.
 */

/** The key of the unordered body pair (a, b): min * (capacity + 1) + max, exact below 2^53. */
function pairKey(js: JointState, a: number, b: number): number {
  const n = js.noCollide.length;
  return a < b ? a * n + b : b * n + a;
}

/**
 * Counts joint `j` between bodies a and b (0 = the world: not counted) as keeping them apart.
 * @category Joints and ropes
 */
export function addNoCollide(js: JointState, j: number, a: number, b: number): void {
  if (a === 0 || b === 0 || a === b) return;
  js.noCollideJoint[j] = 1;
  js.noCollide[a] = js.noCollide[a]! + 1;
  js.noCollide[b] = js.noCollide[b]! + 1;
  const k = pairKey(js, a, b);
  js.noCollidePairs.set(k, (js.noCollidePairs.get(k) ?? 0) + 1);
}

/**
 * Uncounts joint `j` between bodies a and b, if `addNoCollide` counted it.
 * @category Joints and ropes
 */
export function removeNoCollide(js: JointState, j: number, a: number, b: number): void {
  if (js.noCollideJoint[j] !== 1) return;
  js.noCollideJoint[j] = 0;
  js.noCollide[a] = js.noCollide[a]! - 1;
  js.noCollide[b] = js.noCollide[b]! - 1;
  const k = pairKey(js, a, b),
    left = (js.noCollidePairs.get(k) ?? 1) - 1;
  if (left > 0) js.noCollidePairs.set(k, left);
  else js.noCollidePairs.delete(k);
}

/**
 * Whether a joint without `collideConnected` joins bodies a and b (so their contacts are skipped).
 * @category Joints and ropes
 */
export function jointKeepsApart(js: JointState, a: number, b: number): boolean {
  const nc = js.noCollide;
  if (nc.length === 0 || nc[a] === 0 || nc[b] === 0) return false;
  return js.noCollidePairs.has(pairKey(js, a, b));
}
