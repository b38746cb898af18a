/**
 * The `ClothLink` component: one link of a cloth (or any mesh of point masses) between bodies `a` and
 * `b`, its own entity like a joint, solved by the cloth solver (cloth/solver.ts) as a position-based
 * distance constraint. Users see cloth links with `query(world, [world.components.ClothLink])` and
 * remove them with `removeJoint` (or by removing a body they hold).
 */

/**
 * Kinds of cloth link, for renderers and users (the solver treats them alike).
 * @category Cloth
 */
export const ClothLinkKind = Object.freeze({ Structural: 0, Shear: 1, Bending: 2 } as const);

/**
 * Fields of a cloth link. Units SI.
 * @category Cloth
 */
export interface ClothLinkStore {
  /** The two point bodies (entity slots). */
  a: Int32Array;
  b: Int32Array;
  /** Rest length, m, > 0. */
  restLength: Float64Array;
  /**
   * Compliance, m/N (the inverse of stiffness; XPBD, Macklin, Mueller and Chentanez, "XPBD", 2016):
   * 0 is inextensible, larger is softer. Bending links are usually soft.
   */
  compliance: Float64Array;
  /** Strain (length - rest) / rest past which the link tears (is removed, with an event), > 0. Infinity = never. */
  tearStretch: Float64Array;
  /** ClothLinkKind code. */
  kind: Uint8Array;
}

/**
 * The store with empty arrays (lazily allocated on first use; see LAZY_COMPONENTS).
 * @category Cloth
 */
export function createClothLinkStore(): ClothLinkStore {
  return {
    a: new Int32Array(0),
    b: new Int32Array(0),
    restLength: new Float64Array(0),
    compliance: new Float64Array(0),
    tearStretch: new Float64Array(0),
    kind: new Uint8Array(0),
  };
}
