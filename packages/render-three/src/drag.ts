import { addBody, addDistanceJoint3D, isAlive, type PhysicsWorld, removeBody, setPosition, slotOf } from '@bitphysics/physics';
import { assertFinite, assertKnownKeys, assertNonNegative, assertPositive } from '@bitphysics/physics/validate';
import { type ColorInput, parseColor } from '@bitphysics/render-common';
import { type Camera, Plane, Raycaster, SphereGeometry, Vector2, Vector3 } from 'three';
import type { WorldRenderer3D } from './renderer.js';

/** Options of `new BodyDrag3D`. Every field optional; unknown fields are rejected. */
export interface BodyDrag3DOptions {
  /** Frequency of the pulling spring, Hz, > 0. Default 4 (a held body sags g / (2 pi 4)^2 = 1.6 cm). */
  hertz?: number;
  /** Damping ratio of the spring, >= 0. Default 0.7. */
  dampingRatio?: number;
  /** Radius of the marker drawn at the pointer's target, m, > 0. Default 0.06 m. */
  markerRadius?: number;
  /** Colour of the marker, 0xRRGGBB or '#rrggbb'. Default 0xffd166. */
  markerColor?: ColorInput;
}

/**
 * Dragging 3D bodies with the pointer. A press picks the body under the pointer with
 * `WorldRenderer3D.pick` (a ray cast through the physics, `rayCast3D`), and holds it at the point hit
 * with a spring: a soft distance joint (`addDistanceJoint3D`, `hertz`, `dampingRatio`, rest length
 * 1 mm, solved in the contact solver's soft substeps, so it is stable at any mass) to a kinematic
 * "hand" body without a collider that follows the pointer. The body swings about the point held and
 * collides on the way. While held, the pointer's ray meets the plane through the grab point facing
 * the camera (the point stays at the depth it was grabbed at; `setDepth` moves it nearer or farther).
 * Static and kinematic bodies are not grabbed.
 *
 * The hand is an ordinary world entity (kinematic, drawn as a small sphere); `release` removes it
 * and its joint. A drag ends by itself when the renderer moves to another world.
 */
export class BodyDrag3D {
  private readonly renderer: WorldRenderer3D;
  private readonly hertz: number;
  private readonly dampingRatio: number;
  private readonly markerColor: number;
  private readonly marker: SphereGeometry;
  private readonly markerRadius: number;
  private readonly raycaster = new Raycaster();
  private readonly ndc = new Vector2();
  private readonly plane = new Plane();
  private readonly v = new Vector3();
  private readonly n = new Vector3();
  private state = { world: null as PhysicsWorld | null, body: 0, hand: 0, joint: 0 };
  /** The target the hand was last moved to, m (world). */
  readonly target: [number, number, number] = [0, 0, 0];

  /**
   * @param renderer the renderer whose world and picking are used.
   * @throws TypeError | RangeError on an unknown option or a value out of range.
   */
  constructor(renderer: WorldRenderer3D, options: BodyDrag3DOptions = {}) {
    const where = 'BodyDrag3D';
    assertKnownKeys(where, options, ['hertz', 'dampingRatio', 'markerRadius', 'markerColor']);
    this.hertz = options.hertz ?? 4;
    assertPositive(where, 'hertz', this.hertz);
    this.dampingRatio = options.dampingRatio ?? 0.7;
    assertNonNegative(where, 'dampingRatio', this.dampingRatio);
    this.markerRadius = options.markerRadius ?? 0.06;
    assertPositive(where, 'markerRadius', this.markerRadius);
    this.markerColor = parseColor(where, 'markerColor', options.markerColor ?? 0xffd166);
    this.renderer = renderer;
    this.marker = new SphereGeometry(1, 12, 8);
  }

  /** The body held (its handle), or 0. */
  get body(): number {
    this.check();
    return this.state.body;
  }

  /** The kinematic hand body (its handle), or 0. */
  get hand(): number {
    this.check();
    return this.state.hand;
  }

  /**
   * Grabs the dynamic body under (ndcX, ndcY) (normalised device coordinates of `camera`, y up) at the
   * point the ray hits. @returns the body's handle, or 0 if no dynamic body is there.
   * @throws RangeError if ndcX or ndcY is not finite.
   */
  grab(ndcX: number, ndcY: number, camera: Camera): number {
    const hit = this.renderer.pick(ndcX, ndcY, camera);
    this.release();
    if (hit === null) return 0;
    const world = this.renderer.world;
    const e = slotOf(hit.eid);
    if (!(world.components.Mass.inv[e]! > 0)) return 0;
    const p = hit.point;
    const hand = addBody(world, { position: p, kinematic: true, orientation: [0, 0, 0, 1] });
    const joint = addDistanceJoint3D(world, {
      a: hand,
      b: hit.eid,
      anchorA: p,
      anchorB: p,
      length: 1e-3,
      minLength: 0,
      hertz: this.hertz,
      dampingRatio: this.dampingRatio,
    });
    this.renderer.setShape(hand, { geometry: this.marker, scale: this.markerRadius, color: this.markerColor });
    this.state = { world, body: hit.eid, hand, joint };
    this.target[0] = p[0];
    this.target[1] = p[1];
    this.target[2] = p[2];
    // The drag plane: through the grab point, facing the camera.
    camera.getWorldDirection(this.n);
    this.plane.setFromNormalAndCoplanarPoint(this.n, this.v.set(p[0], p[1], p[2]).multiplyScalar(this.renderer.unitsPerMeter));
    return hit.eid;
  }

  /**
   * Moves the hand to where the ray through (ndcX, ndcY) meets the drag plane (nothing while no body is
   * held, or when the ray runs parallel to the plane). @throws RangeError if ndcX or ndcY is not finite.
   */
  move(ndcX: number, ndcY: number, camera: Camera): void {
    assertFinite('BodyDrag3D.move', 'ndcX', ndcX);
    assertFinite('BodyDrag3D.move', 'ndcY', ndcY);
    if (!this.check()) return;
    this.ndc.set(ndcX, ndcY);
    this.raycaster.setFromCamera(this.ndc, camera);
    const at = this.raycaster.ray.intersectPlane(this.plane, this.v);
    if (at === null) return;
    const k = this.renderer.unitsPerMeter;
    this.moveTo([at.x / k, at.y / k, at.z / k]);
  }

  /** Moves the hand to `point` (m, world). @throws RangeError unless 3 finite numbers. */
  moveTo(point: ArrayLike<number>): void {
    for (let i = 0; i < 3; i++) assertFinite('BodyDrag3D.moveTo', `point[${i}]`, point[i]);
    if (!this.check()) return;
    this.target[0] = point[0]!;
    this.target[1] = point[1]!;
    this.target[2] = point[2]!;
    setPosition(this.state.world!, this.state.hand, this.target);
  }

  /** Moves the drag plane `distance` m along the camera's view (positive: farther), keeping the hand on it. */
  setDepth(distance: number, camera: Camera): void {
    assertFinite('BodyDrag3D.setDepth', 'distance', distance);
    if (!this.check()) return;
    camera.getWorldDirection(this.n);
    this.plane.constant -= distance * this.renderer.unitsPerMeter;
    this.moveTo([this.target[0] + this.n.x * distance, this.target[1] + this.n.y * distance, this.target[2] + this.n.z * distance]);
  }

  /** Lets go: removes the hand and its joint. Does nothing when nothing is held. */
  release(): void {
    const s = this.state;
    if (s.world !== null && s.hand !== 0 && isAlive(s.world, s.hand)) removeBody(s.world, s.hand);
    this.state = { world: null, body: 0, hand: 0, joint: 0 };
  }

  /** Frees the marker geometry (after release). */
  destroy(): void {
    this.release();
    this.marker.dispose();
  }

  /** Whether a drag is live; ends it if its world was replaced or its body or hand removed. */
  private check(): boolean {
    const s = this.state;
    if (s.world === null) return false;
    if (s.world !== this.renderer.world || !isAlive(s.world, s.body) || !isAlive(s.world, s.hand)) {
      if (s.world === this.renderer.world && isAlive(s.world, s.hand)) removeBody(s.world, s.hand);
      this.state = { world: null, body: 0, hand: 0, joint: 0 };
      return false;
    }
    return true;
  }
}
