import type { PhysicsWorld } from '../world.js';
import { registerExternalWorldState } from '../snapshot/world-state.js';

/**
 * The 3D shape contacts of a world: this step's manifolds as solver rows (structure of arrays, four
 * point slots a manifold), last step's rows for warm starting (looked up by shape pair, then by
 * feature id), and the per-solver-body world inverse inertia tensors. Kept outside the world object
 * (registered for snapshots).
 */
export interface Manifold3DBuffer {
  count: number;
  /** Body slots (0: the static world, e.g. a plane) and shape slots (a plane's own slot for a plane). */
  bodyA: Int32Array; bodyB: Int32Array; shapeA: Int32Array; shapeB: Int32Array;
  /** Solver indices of the bodies (0: static). */
  ia: Int32Array; ib: Int32Array;
  /** Points in use (1 to 4), unit normal A to B, tangents (t1, t2 = n x t1), friction and restitution. */
  points: Uint8Array;
  nx: Float64Array; ny: Float64Array; nz: Float64Array;
  t1x: Float64Array; t1y: Float64Array; t1z: Float64Array;
  friction: Float64Array; restitution: Float64Array;
  /** Per point (4 i + k): anchors from the centres of mass (m, world), separation at the step's start (m), feature id. */
  rax: Float64Array; ray: Float64Array; raz: Float64Array; rbx: Float64Array; rby: Float64Array; rbz: Float64Array;
  sep: Float64Array; id: Float64Array;
  /** Per point: accumulated impulses (N s) along n, t1, t2; effective masses; approach speed at the start (m/s); largest normal impulse. */
  ln: Float64Array; lt1: Float64Array; lt2: Float64Array;
  mn: Float64Array; mt1: Float64Array; mt2: Float64Array;
  vn0: Float64Array; maxLn: Float64Array;
}

function createBuffer(n: number): Manifold3DBuffer {
  const i = (k: number): Int32Array => new Int32Array(k), f = (k: number): Float64Array => new Float64Array(k);
  const p = 4 * n;
  return {
    count: 0, bodyA: i(n), bodyB: i(n), shapeA: i(n), shapeB: i(n), ia: i(n), ib: i(n), points: new Uint8Array(n),
    nx: f(n), ny: f(n), nz: f(n), t1x: f(n), t1y: f(n), t1z: f(n), friction: f(n), restitution: f(n),
    rax: f(p), ray: f(p), raz: f(p), rbx: f(p), rby: f(p), rbz: f(p), sep: f(p), id: f(p),
    ln: f(p), lt1: f(p), lt2: f(p), mn: f(p), mt1: f(p), mt2: f(p), vn0: f(p), maxLn: f(p),
  };
}

/** Doubles a buffer's room, keeping its rows. */
export function growManifold3DBuffer(b: Manifold3DBuffer): Manifold3DBuffer {
  const n = b.bodyA.length * 2;
  const g = createBuffer(n) as unknown as Record<string, unknown>;
  for (const [k, v] of Object.entries(b)) if (ArrayBuffer.isView(v)) (g[k] as { set(a: ArrayLike<number>): void }).set(v as unknown as ArrayLike<number>);
  g.count = b.count;
  return g as unknown as Manifold3DBuffer;
}

/** The world's 3D contact state. */
export interface Contact3DState {
  current: Manifold3DBuffer;
  previous: Manifold3DBuffer;
  /** Shape pair key (shapeA * (capacity + 1) + shapeB) -> row in `previous`. */
  previousIndex: Map<number, number>;
  /** World inverse inertia tensor per solver body index (6 a body: xx, yy, zz, xy, xz, yz), 1 / (kg m^2). */
  invInertia: Float64Array;
  /** Per solver body: its rotation owed at the start of the solve (the linearised rotation is measured from it). */
  rotationBase: Float64Array;
}

const states = new WeakMap<PhysicsWorld, Contact3DState>();

/** The world's 3D contact state (made when `create` is true). */
export function contact3DStateOf(world: PhysicsWorld, create: true): Contact3DState;
export function contact3DStateOf(world: PhysicsWorld, create?: boolean): Contact3DState | undefined;
export function contact3DStateOf(world: PhysicsWorld, create = false): Contact3DState | undefined {
  let s = states.get(world);
  if (s === undefined && create) {
    s = { current: createBuffer(64), previous: createBuffer(64), previousIndex: new Map(), invInertia: new Float64Array(6 * 64), rotationBase: new Float64Array(3 * 64) };
    states.set(world, s);
  }
  return s;
}

registerExternalWorldState({
  name: 'contacts3d',
  get: (world, create) => contact3DStateOf(world, create),
  clear: (world) => { states.delete(world); },
});
