import { assertBoolean, assertKnownKeys, assertPositive, describe } from '@bitphysics/physics/validate';
import { MOUSE, type PerspectiveCamera, TOUCH, Vector3 } from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { assertVector } from './validate.js';

/** Options of `createOrbitControls`. Every field optional; unknown fields are rejected. */
export interface OrbitOptions {
  /** Point orbited, scene units. Default (0, 0, 0). */
  target?: ArrayLike<number>;
  /** Smooth (damped) motion; the controls then need `update()` every frame. Default true. */
  damping?: boolean;
  /** Closest zoom, scene units, > 0. Default 0.01. */
  minDistance?: number;
  /** Farthest zoom, scene units, > minDistance. Default 1e6. */
  maxDistance?: number;
  /**
   * What the left mouse button does: `'rotate'` (three's default), or `'none'` when the game uses
   * left drags itself (throwing, picking); the right button then rotates (with Shift / Ctrl: pans)
   * and the wheel or middle button zooms. Default 'rotate'.
   */
  leftButton?: 'rotate' | 'none';
}

const ORBIT_OPTIONS = ['target', 'damping', 'minDistance', 'maxDistance', 'leftButton'] as const;

/**
 * Camera controls from three.js' own addons: an `OrbitControls` (orbit around a target, zoom, pan;
 * mouse and touch) with the framework's defaults.
 * @throws TypeError | RangeError on bad options (named).
 */
export function createOrbitControls(camera: PerspectiveCamera, domElement: HTMLElement, options: OrbitOptions = {}): OrbitControls {
  const where = 'createOrbitControls';
  assertKnownKeys(where, options, ORBIT_OPTIONS);
  const target = options.target ?? [0, 0, 0];
  assertVector(where, 'target', target, 3);
  const damping = options.damping ?? true;
  assertBoolean(where, 'damping', damping);
  const minDistance = options.minDistance ?? 0.01;
  assertPositive(where, 'minDistance', minDistance);
  const maxDistance = options.maxDistance ?? 1e6;
  assertPositive(where, 'maxDistance', maxDistance);
  if (!(maxDistance > minDistance))
    throw new RangeError(`${where}: maxDistance must be > minDistance, got ${maxDistance} <= ${minDistance}`);
  const left = options.leftButton ?? 'rotate';
  if (left !== 'rotate' && left !== 'none') throw new RangeError(`${where}: leftButton must be 'rotate' or 'none', got ${describe(left)}`);
  const controls = new OrbitControls(camera, domElement);
  controls.target.set(target[0]!, target[1]!, target[2]!);
  controls.enableDamping = damping;
  controls.dampingFactor = 0.12;
  controls.minDistance = minDistance;
  controls.maxDistance = maxDistance;
  controls.screenSpacePanning = true;
  if (left === 'none') {
    controls.mouseButtons = { LEFT: null, MIDDLE: MOUSE.DOLLY, RIGHT: MOUSE.ROTATE };
    controls.touches = { ONE: null, TWO: TOUCH.DOLLY_ROTATE };
  }
  controls.update();
  return controls;
}

/** Options of `frameBox`. */
export interface FrameOptions {
  /** Direction from the box's centre to the camera, any non-zero 3-vector. Default (0.9, 0.65, 1.25). */
  direction?: ArrayLike<number>;
  /** Extra room around the box, a factor >= 1 on the fitted distance. Default 1.15. */
  margin?: number;
}

const scratch = new Vector3();

/**
 * Places a perspective camera so the whole box (min, max) (scene units) is in view, looking at its
 * centre from `direction`; sets the orbit target there and near/far planes to suit the distance.
 * The fitted distance is the least that keeps every corner of the box inside both the vertical and
 * the horizontal field of view (a corner at (x, y) across the view and z along it, from the centre,
 * needs d >= |x| / tan(hfov / 2) - z and d >= |y| / tan(vfov / 2) - z), times `margin`: a tall
 * phone screen frames the box by its width, a wide one by its height, with no room left for the
 * empty corners of the box's bounding sphere.
 * @throws TypeError | RangeError on bad corners (max must exceed min on every axis) or options.
 */
export function frameBox(
  camera: PerspectiveCamera,
  controls: { target: Vector3; update(): unknown } | null,
  min: ArrayLike<number>,
  max: ArrayLike<number>,
  options: FrameOptions = {},
): void {
  const where = 'frameBox';
  assertVector(where, 'min', min, 3);
  assertVector(where, 'max', max, 3);
  for (let i = 0; i < 3; i++) {
    if (!(max[i]! >= min[i]!)) throw new RangeError(`${where}: max[${i}] must be >= min[${i}], got ${describe(min)} and ${describe(max)}`);
  }
  assertKnownKeys(where, options, ['direction', 'margin']);
  const d = options.direction ?? [0.9, 0.65, 1.25];
  assertVector(where, 'direction', d, 3);
  const margin = options.margin ?? 1.15;
  assertPositive(where, 'margin', margin);
  if (margin < 1) throw new RangeError(`${where}: margin must be >= 1, got ${margin}`);
  const cx = 0.5 * (min[0]! + max[0]!),
    cy = 0.5 * (min[1]! + max[1]!),
    cz = 0.5 * (min[2]! + max[2]!);
  scratch.set(d[0]!, d[1]!, d[2]!);
  if (!(scratch.lengthSq() > 0)) throw new RangeError(`${where}: direction must not be zero`);
  scratch.normalize();
  const dist = Math.max(1e-6, fitDistance(camera, scratch, min, max)) * margin;
  camera.position.set(cx + scratch.x * dist, cy + scratch.y * dist, cz + scratch.z * dist);
  camera.near = Math.max(1e-4, dist / 200);
  camera.far = dist * 200;
  camera.updateProjectionMatrix();
  camera.lookAt(cx, cy, cz);
  if (controls) {
    controls.target.set(cx, cy, cz);
    controls.update();
  }
}

/**
 * The least distance from the box's centre along `toCamera` (a unit vector) at which every corner of
 * the box (min, max) is inside the camera's vertical and horizontal fields of view (see frameBox),
 * measured in the axes three.js' `lookAt` gives the camera from there (its right and up columns).
 */
function fitDistance(camera: PerspectiveCamera, toCamera: Vector3, min: ArrayLike<number>, max: ArrayLike<number>): number {
  const cx = 0.5 * (min[0]! + max[0]!),
    cy = 0.5 * (min[1]! + max[1]!),
    cz = 0.5 * (min[2]! + max[2]!);
  camera.position.set(cx + toCamera.x, cy + toCamera.y, cz + toCamera.z);
  camera.lookAt(cx, cy, cz);
  camera.updateMatrixWorld();
  const right = new Vector3().setFromMatrixColumn(camera.matrixWorld, 0);
  const up = new Vector3().setFromMatrixColumn(camera.matrixWorld, 1);
  const tanV = Math.tan((camera.fov * Math.PI) / 360);
  const tanH = tanV * camera.aspect;
  let dist = 0;
  for (let corner = 0; corner < 8; corner++) {
    const qx = (corner & 1 ? max[0]! : min[0]!) - cx,
      qy = (corner & 2 ? max[1]! : min[1]!) - cy,
      qz = (corner & 4 ? max[2]! : min[2]!) - cz;
    const x = qx * right.x + qy * right.y + qz * right.z,
      y = qx * up.x + qy * up.y + qz * up.z,
      z = -(qx * toCamera.x + qy * toCamera.y + qz * toCamera.z);
    dist = Math.max(dist, Math.abs(x) / tanH - z, Math.abs(y) / tanV - z);
  }
  return dist;
}
