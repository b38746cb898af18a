/**
 * The free-spin round's guides, drawn only (the physics knows none of them), so the player reads the
 * spin to make and what the torque does instead of watching a number:
 * - a ghost: a small see-through copy of the cube beside the pivot, turning at the lit target spin
 *   ("make yours spin like this"), with the target's axis through it;
 * - the gap: a white arrow from ω's tip to the target's tip, the change of spin still to make;
 * - the torque: while a key pushes, a green arrow from ω's tip along the torque (a cube's three
 *   moments are equal, so ω's tip moves along it at tau / I): green when it points along the gap,
 *   amber across it, red against it;
 * - the hold ring: round the target's ball, filling over SPIN_HOLD while ω's tip stays inside.
 * Kept light for software WebGL: a handful of meshes, no textures.
 */

import { VectorArrow } from '@bitphysics/render-three';
import {
  BoxGeometry,
  type Camera,
  DoubleSide,
  EdgesGeometry,
  Group,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshBasicMaterial,
  Quaternion,
  RingGeometry,
  type Scene,
  Vector3,
} from 'three';
import { pushAlignment, SPIN_HOLD, SPIN_TOLERANCE } from './spin-challenge';

/** Segments of the hold ring (it fills one at a time). */
const RING_SEGMENTS = 48;
/** The ghost's edge, m (the cube's is 1 m). */
const GHOST_SIZE = 0.5;
/** Torque arrow colours by `pushAlignment`: along the gap (cos > 0.7), across it, against it (cos < -0.2). */
const PUSH_GOOD = 0x4ade80,
  PUSH_ACROSS = 0xfbbf24,
  PUSH_BAD = 0xf87171;

/** What `SpinLook.update` draws from: the pivot, ω, the lit target (null: none), the torque and the hold. */
export interface SpinLookState {
  /** The pivot (the arrows' origin), m, world frame. */
  pivot: ArrayLike<number>;
  /** The cube's angular velocity, rad/s, world frame. */
  omega: ArrayLike<number>;
  /** The lit target spin, rad/s, world frame; null hides every guide (another mode, or the round won). */
  aim: ArrayLike<number> | null;
  /** The torque the keys apply now, N m, world frame (zero when none). */
  torque: ArrayLike<number>;
  /** How long ω has held in the ball, s (SpinChallenge `held`). */
  held: number;
  /** Arrow length per rad/s, m (the ω arrow's scale). */
  scale: number;
  /** Seconds since the last update (the ghost turns by aim times this). */
  dt: number;
}

/** The free-spin guides (see the module's comment); `update` each frame. */
export class SpinLook {
  /** The ghost: a see-through cube with its edges, turning at the target spin. */
  readonly ghost = new Group();
  /** The ghost's axis: a thin cyan arrow through it along the target spin. */
  private readonly ghostAxis = new VectorArrow({ color: 0x22d3ee, radius: 0.015, headLength: 0.1 });
  /** The gap from ω's tip to the target's tip. */
  private readonly gapArrow = new VectorArrow({ color: 0xffffff, radius: 0.014, headLength: 0.1 });
  /** The torque at ω's tip, one arrow per colour (along the gap, across it, against it); one shows at a time. */
  private readonly torqueArrows = [PUSH_GOOD, PUSH_ACROSS, PUSH_BAD].map(
    (color) => new VectorArrow({ color, radius: 0.022, headLength: 0.12 }),
  );
  /** The hold ring round the target's ball (faces the camera). */
  private readonly ring: Mesh;
  /** Where the ghost sits from the pivot: along the camera's right and up, m. */
  private readonly offset: [number, number];
  private readonly spin = new Quaternion();
  private readonly axis = new Vector3();
  private readonly right = new Vector3();
  private readonly up = new Vector3();
  private readonly back = new Vector3();
  /** The last state drawn: the gap (rad/s, world frame), the torque's `pushAlignment`, the hold ring's fill in [0, 1], whether the torque arrow and the ghost show. */
  readonly shown = { gap: [0, 0, 0], alignment: 0, hold: 0, torque: false, ghost: false };

  /**
   * @param scene where the guides go.
   * @param faceColors the cube's face colours (0xRRGGBB, +x, -x, +y, -y, +z, -z), for the ghost.
   * @param offset where the ghost sits from the pivot, m, along the camera's right and up.
   */
  constructor(scene: Scene, faceColors: readonly number[], offset: [number, number]) {
    this.offset = offset;
    const faces = faceColors.map((color) => new MeshBasicMaterial({ color, transparent: true, opacity: 0.55, depthWrite: false }));
    const box = new BoxGeometry(GHOST_SIZE, GHOST_SIZE, GHOST_SIZE);
    this.ghost.add(new Mesh(box, faces), new LineSegments(new EdgesGeometry(box), new LineBasicMaterial({ color: 0xffffff })));
    this.ghost.visible = false;
    this.ring = new Mesh(
      new RingGeometry(1.08, 1.3, RING_SEGMENTS, 1, Math.PI / 2, -2 * Math.PI),
      new MeshBasicMaterial({ color: 0x4ade80, side: DoubleSide, transparent: true, opacity: 0.95, depthTest: false }),
    );
    this.ring.renderOrder = 6;
    // The gap and the torque draw over the cube and the other arrows: they overlap ω's and the target's near the target.
    for (const arrow of [this.gapArrow, ...this.torqueArrows])
      arrow.object.traverse((m) => {
        if (m instanceof Mesh) {
          (m.material as MeshBasicMaterial).depthTest = false;
          m.renderOrder = 7;
        }
      });
    this.ring.visible = false;
    scene.add(this.ghost, this.ghostAxis.object, this.gapArrow.object, ...this.torqueArrows.map((a) => a.object), this.ring);
  }

  /** Draws the guides for `s`, facing `camera` (its world matrix up to date). */
  update(s: SpinLookState, camera: Camera): void {
    const aim = s.aim;
    if (!aim) {
      this.hide();
      return;
    }
    const o = s.pivot,
      w = s.omega,
      k = s.scale;
    camera.matrixWorld.extractBasis(this.right, this.up, this.back);
    // The ghost: beside the pivot on screen, turned by the target spin over dt.
    const rate = Math.hypot(aim[0]!, aim[1]!, aim[2]!);
    if (rate > 0 && s.dt > 0) {
      this.axis.set(aim[0]! / rate, aim[1]! / rate, aim[2]! / rate);
      this.spin.setFromAxisAngle(this.axis, rate * Math.min(s.dt, 0.1));
      this.ghost.quaternion.premultiply(this.spin);
    }
    const [gx, gy] = this.offset;
    this.ghost.position.set(
      o[0]! + gx * this.right.x + gy * this.up.x,
      o[1]! + gx * this.right.y + gy * this.up.y,
      o[2]! + gx * this.right.z + gy * this.up.z,
    );
    this.ghost.visible = true;
    const p = this.ghost.position,
      half = 0.45 / Math.max(rate, 1e-9);
    this.ghostAxis.set(p.x - aim[0]! * half, p.y - aim[1]! * half, p.z - aim[2]! * half, aim[0]!, aim[1]!, aim[2]!, 2 * half);
    // The gap: from ω's tip to the target's.
    const gap = this.shown.gap;
    for (let i = 0; i < 3; i++) gap[i] = aim[i]! - w[i]!;
    const tx = o[0]! + w[0]! * k,
      ty = o[1]! + w[1]! * k,
      tz = o[2]! + w[2]! * k;
    this.gapArrow.set(tx, ty, tz, gap[0]!, gap[1]!, gap[2]!, k);
    // The torque: a fixed length (it shows the way the tip goes, not how hard), coloured by how it meets the gap.
    const lt = Math.hypot(s.torque[0]!, s.torque[1]!, s.torque[2]!);
    this.shown.alignment = pushAlignment(s.torque, gap);
    this.shown.torque = lt > 1e-9;
    const a = this.shown.alignment,
      lit = !this.shown.torque ? -1 : a > 0.7 ? 0 : a < -0.2 ? 2 : 1;
    this.torqueArrows.forEach((arrow, i) => {
      if (i === lit) arrow.set(tx, ty, tz, s.torque[0]! / lt, s.torque[1]! / lt, s.torque[2]! / lt, 0.45);
      else arrow.hide();
    });
    // The hold ring: round the ball at the target's tip, facing the camera, filled by the hold so far.
    this.shown.hold = Math.max(0, Math.min(1, s.held / SPIN_HOLD));
    const n = Math.round(this.shown.hold * RING_SEGMENTS);
    this.ring.visible = n > 0;
    this.ring.geometry.setDrawRange(0, 6 * n);
    this.ring.position.set(o[0]! + aim[0]! * k, o[1]! + aim[1]! * k, o[2]! + aim[2]! * k);
    this.ring.quaternion.copy(camera.quaternion);
    this.ring.scale.setScalar(SPIN_TOLERANCE * k);
    this.shown.ghost = true;
  }

  /** Hides every guide. */
  hide(): void {
    this.ghost.visible = false;
    this.ghostAxis.hide();
    this.gapArrow.hide();
    for (const arrow of this.torqueArrows) arrow.hide();
    this.ring.visible = false;
    this.shown.torque = false;
    this.shown.ghost = false;
    this.shown.hold = 0;
  }
}
