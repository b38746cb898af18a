/**
 * The room's hint mark: the floor tile where the status row's route starts ("click the ringed tile"),
 * ringed on the floor and pinned from above. A ring alone lay hidden behind the cube whenever the cube
 * stood on the cell in front of the tile (a stranger could not find "the ringed tile"). So the ring
 * is drawn twice, once in the scene and once faintly through the cube (depth test off), and a pin, a
 * flat arrow pointing down at the tile and turned to face the camera, floats with its tip above the
 * cube's top and bobs, so it shows over a cube in front of the tile from any camera height the room allows.
 */
import { DoubleSide, Group, Mesh, MeshBasicMaterial, type Quaternion, RingGeometry, Shape, ShapeGeometry } from 'three';

/** Height of the pin's tip over the floor, m: above a 1 m cube's top, so a cube in front of the tile does not cover it. */
export const HINT_PIN_HEIGHT = 1.3;
/** How far the pin bobs up from HINT_PIN_HEIGHT, m, and the bob's period, s. */
export const HINT_PIN_BOB = 0.12;
const BOB_PERIOD = 1.1;

/** The hint mark's parts (a `Group` with the ring, the ring seen through the cube and the pin). */
export interface HintMark {
  /** The mark, to add to the scene; placed on the floor at the tile's centre. */
  group: Group;
  /** The ring on the floor (inner radius 0.3 m, outer 0.4 m). */
  ring: Mesh;
  /** The same ring drawn faintly with the depth test off: it shows through the cube. */
  ringThrough: Mesh;
  /** The pin: a flat arrow (outlined) whose tip points down at the tile, HINT_PIN_HEIGHT m up and bobbing. */
  pin: Group;
  /**
   * Shows the mark on the tile at (x, z), m (null: hides it), its pin bobbed for time `time`, s, and
   * turned to face a camera of orientation `facing` (the camera's world quaternion; none: left as it is).
   */
  place(at: readonly [number, number] | null, time: number, facing?: Quaternion): void;
}

/** A down arrow in its plane (x right, y up), tip at the origin: a head `scale` * 0.4 m wide over a shaft. */
function arrowShape(scale: number): Shape {
  const pts: [number, number][] = [
    [0, 0],
    [0.2, 0.24],
    [0.075, 0.24],
    [0.075, 0.5],
    [-0.075, 0.5],
    [-0.075, 0.24],
    [-0.2, 0.24],
  ];
  const shape = new Shape();
  // Scaled about the arrow's middle (0, 0.25), so the outline's tip sits just below the arrow's.
  for (const [i, [x, y]] of pts.entries()) {
    const sx = x * scale,
      sy = 0.25 + (y - 0.25) * scale;
    if (i === 0) shape.moveTo(sx, sy);
    else shape.lineTo(sx, sy);
  }
  shape.closePath();
  return shape;
}

/** Makes the hint mark in colour `color` (0xRRGGBB). */
export function createHintMark(color: number): HintMark {
  const ringGeometry = new RingGeometry(0.3, 0.4, 40).rotateX(-Math.PI / 2);
  const ring = new Mesh(
    ringGeometry,
    new MeshBasicMaterial({ color, transparent: true, opacity: 0.9, side: DoubleSide, depthWrite: false }),
  );
  const ringThrough = new Mesh(
    ringGeometry,
    new MeshBasicMaterial({ color, transparent: true, opacity: 0.35, side: DoubleSide, depthWrite: false, depthTest: false }),
  );
  ring.position.y = ringThrough.position.y = 0.035;
  ring.renderOrder = 2;
  ringThrough.renderOrder = 3;
  // The arrow over a dark outline a little larger and behind it, so it reads against the light floor and the cube.
  const arrow = new Mesh(new ShapeGeometry(arrowShape(1)), new MeshBasicMaterial({ color, side: DoubleSide }));
  const outline = new Mesh(new ShapeGeometry(arrowShape(1.3)), new MeshBasicMaterial({ color: 0x2a2108, side: DoubleSide }));
  outline.position.z = -0.01;
  const pin = new Group();
  pin.add(outline, arrow);
  pin.position.y = HINT_PIN_HEIGHT;
  const group = new Group();
  group.add(ring, ringThrough, pin);
  group.visible = false;
  return {
    group,
    ring,
    ringThrough,
    pin,
    place(at, time, facing) {
      group.visible = at !== null;
      if (!at) return;
      group.position.set(at[0], 0, at[1]);
      pin.position.y = HINT_PIN_HEIGHT + HINT_PIN_BOB * 0.5 * (1 + Math.sin((2 * Math.PI * time) / BOB_PERIOD));
      if (facing) pin.quaternion.copy(facing);
    },
  };
}
