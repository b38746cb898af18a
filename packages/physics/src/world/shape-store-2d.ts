/**
 * The `Shape` component's store (see `Components.Shape`). Its arrays are empty until the world's first
 * shape is added (`ensureShapeStore`), so worlds without shapes pay nothing; the vertex arrays hold
 * `MAX_POLYGON_VERTICES` entries an entity.
 * @category Shapes
 */
export interface ShapeStore {
  /** The body entity the shape belongs to (the shape's own id when the shape lives on its body). */
  body: Int32Array;
  /** ShapeKind: 0 circle, 1 capsule, 2 polygon (boxes are polygons). */
  kind: Uint8Array;
  /** Vertices in use: 1 circle, 2 capsule, 3 to 8 polygon. */
  count: Uint8Array;
  /** Radius, m: the circle's or capsule's, a polygon's corner rounding (>= 0). */
  radius: Float64Array;
  /**
   * Vertices in the body frame about the body's centre of mass, m (entity e's vertex i at 8 e + i):
   * the shape's offset and angle are already applied. Counter-clockwise.
   */
  vx: Float64Array;
  /** Vertex y coordinates, m, at 8 e + i (see `vx`). */
  vy: Float64Array;
  /** Outward unit normal x of edge i (vertex i to i + 1), body frame, at 8 e + i. */
  nx: Float64Array;
  /** Outward unit normal y of edge i, at 8 e + i. */
  ny: Float64Array;
  /** Collision filter: the category bits the shape is in (32 bits). Default 1. */
  category: Uint32Array;
  /** Collision filter: the mask of categories it collides with (32 bits). Default all. */
  mask: Uint32Array;
  /** Group: two shapes of the same non-zero group always collide if it is > 0 and never if it is < 0 (overrides the bits). */
  group: Int32Array;
  /** 1: a sensor, which reports overlaps and pushes nothing. */
  sensor: Uint8Array;
  /** Areal density, kg/m^2 (>= 0), used for the body's mass. */
  density: Float64Array;
  /** Rolling resistance coefficient (dimensionless, >= 0) of a circle or capsule: resisting torque = coefficient x radius x normal force. */
  rollingResistance: Float64Array;
  /** The body's next shape entity in its list (0 ends it); see ShapeCollisionState.firstShape. */
  next: Int32Array;
}

/**
 * Shape slots a vertex array holds per entity.
 * @category Shapes
 */
export const SHAPE_STRIDE = 8;

/**
 * An empty store (no arrays allocated).
 * @category Shapes
 */
export function createEmptyShapeStore(): ShapeStore {
  const z = (): Float64Array => new Float64Array(0);
  return {
    body: new Int32Array(0),
    kind: new Uint8Array(0),
    count: new Uint8Array(0),
    radius: z(),
    vx: z(),
    vy: z(),
    nx: z(),
    ny: z(),
    category: new Uint32Array(0),
    mask: new Uint32Array(0),
    group: new Int32Array(0),
    sensor: new Uint8Array(0),
    density: z(),
    rollingResistance: z(),
    next: new Int32Array(0),
  };
}

/**
 * Allocates the store's arrays for `capacity` entities if they are still empty.
 * @category Shapes
 */
export function ensureShapeStore(store: ShapeStore, capacity: number): void {
  if (store.body.length > 0) return;
  const n = capacity + 1;
  store.body = new Int32Array(n);
  store.kind = new Uint8Array(n);
  store.count = new Uint8Array(n);
  store.radius = new Float64Array(n);
  store.vx = new Float64Array(SHAPE_STRIDE * n);
  store.vy = new Float64Array(SHAPE_STRIDE * n);
  store.nx = new Float64Array(SHAPE_STRIDE * n);
  store.ny = new Float64Array(SHAPE_STRIDE * n);
  store.category = new Uint32Array(n);
  store.mask = new Uint32Array(n);
  store.group = new Int32Array(n);
  store.sensor = new Uint8Array(n);
  store.density = new Float64Array(n);
  store.rollingResistance = new Float64Array(n);
  store.next = new Int32Array(n);
}
