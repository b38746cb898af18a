import { addComponent } from 'bitecs';
import { addBodyAs, createSlot, removeBody } from '../bodies/api.js';
import * as check from '../validation/validate.js';
import { ClothLinkKind } from '../world/cloth-store.js';
import { currentHandle, isAlive, slotOf } from '../world/handles.js';
import { installSystem } from '../world/install.js';
import { ensureJointArrays } from '../world/joint-state-2d.js';
import type { PhysicsWorld } from '../world/options.js';
import { query } from '../world/query.js';
import { trustFiniteOutput } from '../world/trusted-systems.js';
import { clothSystem } from './solver.js';

/**
 * Options of `createCloth`. Unknown fields are rejected.
 * @category Cloth
 */
export interface ClothOptions {
  /** Top-left point of the cloth, m (x, y). Default (0, 0). */
  origin?: ArrayLike<number>;
  /** Width and height of the cloth at rest, m, > 0. Default 1 x 1. */
  width?: number;
  height?: number;
  /** Points across and down, integers in [2, 512]. Default 32 x 32. */
  columns?: number;
  rows?: number;
  /** Total mass of the cloth, kg, > 0 (shared equally by the points). Default 0.5 kg. */
  mass?: number;
  /** Which points are pinned (static): 'top' (the whole top edge), 'corners' (the two top corners), 'none', or an array of point indices (row * columns + column). Default 'top'. */
  pinned?: 'top' | 'corners' | 'none' | readonly number[];
  /** Compliance of the structural (horizontal and vertical) links, m/N, >= 0 (0 = inextensible). Default 0. */
  compliance?: number;
  /** Compliance of the shear (diagonal) links, m/N, >= 0; null leaves them out. Default 0.001 m/N. */
  shearCompliance?: number | null;
  /** Compliance of the bending links (two points apart), m/N, >= 0; null leaves them out. Default 0.01 m/N. */
  bendCompliance?: number | null;
  /** Strain (length - rest) / rest past which structural and shear links tear, > 0. Default Infinity (never). */
  tearStretch?: number;
  /** Linear drag of each point against the wind, N s/m, >= 0: the world's wind and turbulence act through it (setWind). Default 0.002 N s/m. */
  drag?: number;
}

/**
 * What `createCloth` made.
 * @category Cloth
 */
export interface Cloth {
  /** Point bodies' handles, row-major from the top-left: point (row, column) is points[row * columns + column]. Float64Array: a handle needs up to 53 bits (world/handles.ts). */
  readonly points: Float64Array;
  /** Link entities' handles: structural first, then shear, then bending. */
  readonly links: Float64Array;
  readonly columns: number;
  readonly rows: number;
}

const KEYS = [
  'origin',
  'width',
  'height',
  'columns',
  'rows',
  'mass',
  'pinned',
  'compliance',
  'shearCompliance',
  'bendCompliance',
  'tearStretch',
  'drag',
] as const;

let clothTrusted = false;

/**
 * Installs the cloth's system into `world`'s constraints stage at its place (world/install.ts;
 * idempotent), as `createCloth` does for the first cloth and a snapshot restore does: a program that
 * never makes a cloth does not bundle its solver.
 * @category Cloth
 */
export function installCloth(world: PhysicsWorld): void {
  if (!clothTrusted) {
    clothTrusted = true;
    // Trusted (step/finite.ts) only while the world has no cloth link, when it writes nothing.
    trustFiniteOutput([clothSystem], 'all', (w) => query(w, [w.components.ClothLink]).length === 0);
  }
  installSystem(world, 'constraints', 'cloth', clothSystem);
}

/**
 * Builds a cloth (Ramtal and Dobre ch. 13; the mass-spring cloth of Provot, "Deformation constraints in
 * a mass-spring model", 1995): a grid of point masses joined by structural links (to the right and
 * below), shear links (both diagonals of each cell) and bending links (two points apart), each a
 * `ClothLink` entity solved by the cloth solver (cloth/solver.ts). Pinned points are static bodies.
 * The points feel gravity and linear drag against the world's wind; links past `tearStretch` tear.
 * A 2D world only.
 * @returns the points and links.
 * @throws TypeError | RangeError on a 3D world, unknown options, bad sizes, counts, compliances or pins,
 *   or a world too small for the points and links.
 * @category Cloth
 */
export function createCloth(world: PhysicsWorld, options: ClothOptions = {}): Cloth {
  const where = 'createCloth';
  if (world.dimensions !== 2) throw new RangeError(`${where}: cloth needs a 2D world, this world has ${world.dimensions} dimensions`);
  check.assertOptions(where, options, KEYS, 'options', ['shearCompliance', 'bendCompliance']);
  const origin = options.origin ?? [0, 0];
  check.assertVector(where, 'origin', origin, 2);
  const width = options.width ?? 1,
    height = options.height ?? 1;
  check.assertPositive(where, 'width', width);
  check.assertPositive(where, 'height', height);
  const cols = options.columns ?? 32,
    rows = options.rows ?? 32;
  check.assertInteger(where, 'columns', cols, 2, 512);
  check.assertInteger(where, 'rows', rows, 2, 512);
  const mass = check.optionOr(where, 'mass', options.mass, 0.5, check.assertPositive);
  const compliance = check.optionOr(where, 'compliance', options.compliance, 0, check.assertNonNegative);
  const shear = options.shearCompliance === undefined ? 0.001 : options.shearCompliance;
  if (shear !== null) check.assertNonNegative(where, 'shearCompliance', shear);
  const bend = options.bendCompliance === undefined ? 0.01 : options.bendCompliance;
  if (bend !== null) check.assertNonNegative(where, 'bendCompliance', bend);
  const tear = options.tearStretch ?? Infinity;
  if (tear !== Infinity) check.assertPositive(where, 'tearStretch', tear);
  const drag = check.optionOr(where, 'drag', options.drag, 0.002, check.assertNonNegative);
  const n = cols * rows;
  const pinned = new Uint8Array(n);
  const pin = options.pinned ?? 'top';
  if (pin === 'top') for (let c = 0; c < cols; c++) pinned[c] = 1;
  else if (pin === 'corners') {
    pinned[0] = 1;
    pinned[cols - 1] = 1;
  } else if (pin !== 'none') {
    if (!Array.isArray(pin))
      throw new TypeError(`${where}: pinned must be 'top', 'corners', 'none' or an array of point indices, got ${check.describe(pin)}`);
    for (const i of pin) {
      check.assertInteger(where, 'pinned[i]', i, 0, n - 1);
      pinned[i] = 1;
    }
  }
  const linkCount =
    2 * cols * rows -
    cols -
    rows +
    (shear === null ? 0 : 2 * (cols - 1) * (rows - 1)) +
    (bend === null ? 0 : (cols - 2) * rows + (rows - 2) * cols);
  if (world.entityIndex.aliveCount + n + linkCount > world.capacity) {
    throw new RangeError(
      `${where}: the cloth needs ${n + linkCount} entities (${n} points, ${linkCount} links), the world has room for ${world.capacity - world.entityIndex.aliveCount}`,
    );
  }

  const dx = width / (cols - 1),
    dy = height / (rows - 1);
  const m = mass / n;
  const far = Math.max(Math.abs(origin[0]!) + width, Math.abs(origin[1]!) + height);
  if (!Number.isFinite(far))
    throw new RangeError(
      `${where}: origin, width and height must keep the cloth finite, got ${check.describe(origin)}, ${width} x ${height}`,
    );
  const points = new Float64Array(n);
  let made = 0;
  try {
    for (let r = 0; r < rows; r++) {
      for (let c = 0; c < cols; c++) {
        const i = r * cols + c;
        const position = [origin[0]! + c * dx, origin[1]! - r * dy];
        points[i] = pinned[i]
          ? addBodyAs(world, { position, static: true }, where, POINT_OPTIONS)
          : addBodyAs(world, { position, mass: m, linearDrag: drag }, where, POINT_OPTIONS);
        made++;
      }
    }
  } catch (err) {
    for (let i = 0; i < made; i++) if (isAlive(world, points[i]!)) removeBody(world, points[i]!);
    throw err;
  }
  installCloth(world);
  const links = new Float64Array(linkCount);
  let k = 0;
  const C = world.components;
  ensureJointArrays(world.joints, world.capacity);
  const att = world.joints.attached;
  const link = (i: number, j: number, comp: number, kind: number, tears: boolean): void => {
    const a = slotOf(points[i]!),
      b = slotOf(points[j]!);
    const e = createSlot(world, 'createCloth');
    addComponent(world, e, C.ClothLink);
    const L = C.ClothLink;
    L.a[e] = a;
    L.b[e] = b;
    L.restLength[e] = Math.hypot(C.Position.x[b]! - C.Position.x[a]!, C.Position.y[b]! - C.Position.y[a]!);
    L.compliance[e] = comp;
    L.tearStretch[e] = tears ? tear : Infinity;
    L.kind[e] = kind;
    att[a] = att[a]! + 1;
    att[b] = att[b]! + 1;
    links[k++] = currentHandle(world, e);
  };
  for (let r = 0; r < rows; r++)
    for (let c = 0; c < cols; c++) {
      const i = r * cols + c;
      if (c + 1 < cols) link(i, i + 1, compliance, ClothLinkKind.Structural, true);
      if (r + 1 < rows) link(i, i + cols, compliance, ClothLinkKind.Structural, true);
    }
  if (shear !== null)
    for (let r = 0; r + 1 < rows; r++)
      for (let c = 0; c + 1 < cols; c++) {
        const i = r * cols + c;
        link(i, i + cols + 1, shear, ClothLinkKind.Shear, true);
        link(i + 1, i + cols, shear, ClothLinkKind.Shear, true);
      }
  if (bend !== null)
    for (let r = 0; r < rows; r++)
      for (let c = 0; c < cols; c++) {
        const i = r * cols + c;
        // Bending links break with their cloth: they tear at twice the stretch, so a cut opens cleanly.
        if (c + 2 < cols) link(i, i + 2, bend, ClothLinkKind.Bending, false);
        if (r + 2 < rows) link(i, i + 2 * cols, bend, ClothLinkKind.Bending, false);
      }
  if (tear !== Infinity && bend !== null) {
    for (let i = linkCount - ((cols - 2) * rows + (rows - 2) * cols); i < linkCount; i++)
      C.ClothLink.tearStretch[slotOf(links[i]!)] = 2 * tear;
  }
  world.cloth.version++;
  return { points, links, columns: cols, rows };
}

/** The body options createCloth passes on (for addBodyAs' check). */
const POINT_OPTIONS = ['position', 'static', 'mass', 'linearDrag'] as const;

/**
 * Index of point (row, column) in `Cloth.points`. @throws RangeError outside the grid.
 * @category Cloth
 */
export function clothPointIndex(cloth: Cloth, row: number, column: number): number {
  check.assertInteger('clothPointIndex', 'row', row, 0, cloth.rows - 1);
  check.assertInteger('clothPointIndex', 'column', column, 0, cloth.columns - 1);
  check.assertFinite('clothPointIndex', 'row', row);
  return row * cloth.columns + column;
}
