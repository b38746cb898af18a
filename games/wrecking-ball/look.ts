/**
 * Wrecking ball, how the site looks (drawing only, no physics): textures painted once into small
 * canvases (a brick, a plank's grain, a painted crate, packed dirt) and box geometries that carry
 * them on each piece the right way round. Lengths are in metres.
 */
import { seededRandom } from '@bitphysics/game-kit';
import {
  BoxGeometry,
  type BufferGeometry,
  CanvasTexture,
  DoubleSide,
  DynamicDrawUsage,
  InstancedMesh,
  LessDepth,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshPhongMaterial,
  MeshStandardMaterial,
  Quaternion,
  RepeatWrapping,
  SphereGeometry,
  SRGBColorSpace,
  Vector3,
} from 'three';

/** A canvas of w x h px and its 2D context. */
function canvas(w: number, h: number): [HTMLCanvasElement, CanvasRenderingContext2D] {
  const c = document.createElement('canvas');
  c.width = w;
  c.height = h;
  return [c, c.getContext('2d')!];
}

/** Speckles: `n` dots of up to `size` px in `colors`, over the whole canvas. */
function speckle(g: CanvasRenderingContext2D, w: number, h: number, n: number, size: number, colors: string[], rand: () => number): void {
  for (let i = 0; i < n; i++) {
    g.fillStyle = colors[i % colors.length]!;
    g.globalAlpha = 0.25 + 0.5 * rand();
    const s = 1 + rand() * size;
    g.fillRect(rand() * w, rand() * h, s, s);
  }
  g.globalAlpha = 1;
}

function texture(c: HTMLCanvasElement): CanvasTexture {
  const t = new CanvasTexture(c);
  t.colorSpace = SRGBColorSpace;
  t.anisotropy = 4;
  return t;
}

/** One brick's face: fired clay, uneven in tone, with a pale mortar edge. */
export function brickTexture(): CanvasTexture {
  const [c, g] = canvas(128, 64);
  const rand = seededRandom(7);
  g.fillStyle = '#d9d2c5';
  g.fillRect(0, 0, 128, 64);
  const grad = g.createLinearGradient(0, 0, 128, 64);
  grad.addColorStop(0, '#b9583c');
  grad.addColorStop(1, '#9c432d');
  g.fillStyle = grad;
  g.fillRect(4, 4, 120, 56);
  speckle(g, 128, 64, 220, 3, ['#7a2f1f', '#c97a55', '#5e2417'], rand);
  g.strokeStyle = 'rgba(255, 255, 255, 0.25)';
  g.lineWidth = 2;
  g.strokeRect(5, 5, 118, 54);
  return texture(c);
}

/** A plank's face: wood with its grain running along (u) and a knot or two. */
export function plankTexture(): CanvasTexture {
  const [c, g] = canvas(256, 48);
  const rand = seededRandom(11);
  g.fillStyle = '#d7a867';
  g.fillRect(0, 0, 256, 48);
  for (let i = 0; i < 14; i++) {
    const y = 2 + rand() * 44;
    g.strokeStyle = rand() < 0.5 ? 'rgba(120, 74, 32, 0.45)' : 'rgba(240, 200, 140, 0.5)';
    g.lineWidth = 1 + rand() * 2;
    g.beginPath();
    g.moveTo(0, y);
    for (let x = 0; x <= 256; x += 32) g.lineTo(x, y + Math.sin(x / 40 + i) * 2 * rand());
    g.stroke();
  }
  for (const [kx, ky] of [
    [70, 20],
    [190, 30],
  ] as const) {
    g.fillStyle = 'rgba(110, 62, 24, 0.8)';
    g.beginPath();
    g.ellipse(kx, ky, 7, 4, 0, 0, 2 * Math.PI);
    g.fill();
  }
  g.strokeStyle = 'rgba(80, 48, 20, 0.8)';
  g.lineWidth = 3;
  g.strokeRect(1.5, 1.5, 253, 45);
  return texture(c);
}

/** A crate's face, painted red: slats, a darker frame and a diagonal brace. */
export function crateTexture(): CanvasTexture {
  const [c, g] = canvas(128, 128);
  const rand = seededRandom(5);
  g.fillStyle = '#d9583f';
  g.fillRect(0, 0, 128, 128);
  g.strokeStyle = 'rgba(90, 20, 16, 0.55)';
  g.lineWidth = 2;
  for (let y = 14; y < 128; y += 25) {
    g.beginPath();
    g.moveTo(0, y);
    g.lineTo(128, y);
    g.stroke();
  }
  g.strokeStyle = '#a83a2c';
  g.lineWidth = 14;
  g.strokeRect(7, 7, 114, 114);
  g.beginPath();
  g.moveTo(12, 116);
  g.lineTo(116, 12);
  g.stroke();
  speckle(g, 128, 128, 120, 3, ['#e7b8a0', '#6e1d18'], rand);
  return texture(c);
}

/** Packed dirt of a building site: brown, blotched, with gravel; repeats `repeat` times across. */
export function dirtTexture(repeat: number): CanvasTexture {
  const [c, g] = canvas(256, 256);
  const rand = seededRandom(3);
  g.fillStyle = '#8b7556';
  g.fillRect(0, 0, 256, 256);
  for (let i = 0; i < 60; i++) {
    g.fillStyle = rand() < 0.5 ? 'rgba(110, 90, 62, 0.35)' : 'rgba(160, 138, 104, 0.3)';
    g.beginPath();
    g.ellipse(rand() * 256, rand() * 256, 8 + rand() * 30, 6 + rand() * 20, rand() * Math.PI, 0, 2 * Math.PI);
    g.fill();
  }
  speckle(g, 256, 256, 900, 3, ['#5c4a33', '#b8a585', '#d3c7b0', '#6e6255'], rand);
  const t = texture(c);
  t.wrapS = t.wrapT = RepeatWrapping;
  t.repeat.set(repeat, repeat);
  return t;
}

/** The materials of the pieces, by kind (textured, tinted per instance). */
export function pieceMaterials(): Record<'tower' | 'wall' | 'planks', MeshStandardMaterial> {
  return {
    tower: new MeshStandardMaterial({ map: crateTexture(), roughness: 0.8 }),
    wall: new MeshStandardMaterial({ map: brickTexture(), roughness: 0.9 }),
    planks: new MeshStandardMaterial({ map: plankTexture(), roughness: 0.75 }),
  };
}

/** Box geometries by size (half extents in the body's frame), shared by pieces of one size. */
const boxes = new Map<string, BufferGeometry>();

/**
 * A box of half extents `half` (m, along the body's x, y, z) whose every face carries its texture
 * with u along the face's longer side (a brick's length, a plank's grain).
 */
export function pieceGeometry(half: readonly [number, number, number]): BufferGeometry {
  const key = half.map((h) => h.toFixed(4)).join(',');
  const known = boxes.get(key);
  if (known) return known;
  const geometry = new BoxGeometry(2 * half[0], 2 * half[1], 2 * half[2]);
  // BoxGeometry's faces, in order +x, -x, +y, -y, +z, -z, four vertices each: the axes its u and v run along.
  const faceAxes: ReadonlyArray<readonly [number, number]> = [
    [2, 1],
    [2, 1],
    [0, 2],
    [0, 2],
    [0, 1],
    [0, 1],
  ];
  const uv = geometry.getAttribute('uv');
  faceAxes.forEach(([u, v], f) => {
    if (half[v]! <= half[u]!) return;
    for (let k = 4 * f; k < 4 * f + 4; k++) {
      const a = uv.getX(k),
        b = uv.getY(k);
      uv.setXY(k, b, a);
    }
  });
  uv.needsUpdate = true;
  boxes.set(key, geometry);
  return geometry;
}

/**
 * The half extents of a box along its body's axes: the body frame is its inertia's principal frame,
 * which may list the box's own axes in another order. `axis(i)` gives body axis i as a world
 * direction (x, y, z); the box's own axes are its x and z turned by `yaw` about the vertical and y.
 */
export function bodyHalfExtents(
  half: readonly [number, number, number],
  yaw: number,
  axis: (i: number) => readonly [number, number, number],
): [number, number, number] {
  const own = [
    [Math.cos(yaw), 0, -Math.sin(yaw)],
    [0, 1, 0],
    [Math.sin(yaw), 0, Math.cos(yaw)],
  ];
  const out: [number, number, number] = [0, 0, 0];
  for (let i = 0; i < 3; i++) {
    const d = axis(i);
    let best = 0,
      bestDot = -1;
    for (let j = 0; j < 3; j++) {
      const dot = Math.abs(d[0] * own[j]![0]! + d[1] * own[j]![1]! + d[2] * own[j]![2]!);
      if (dot > bestDot) {
        bestDot = dot;
        best = j;
      }
    }
    out[i] = half[best]!;
  }
  return out;
}

/**
 * A distant city's skyline, drawn once on a clear 1024 x 128 px canvas that repeats around the
 * site: a far row of pale towers and a nearer, darker row, hazy blue-grey as far things look on a
 * clear day, with a few lit windows. Building heights run up to the canvas's top.
 */
export function skylineTexture(): CanvasTexture {
  const [c, g] = canvas(1024, 128);
  const rand = seededRandom(17);
  const row = (color: string, minH: number, maxH: number, minW: number, maxW: number, windows: string | null): void => {
    for (let x = -10; x < 1024; ) {
      const w = minW + rand() * (maxW - minW),
        h = minH + rand() * (maxH - minH);
      g.fillStyle = color;
      g.fillRect(x, 128 - h, w, h);
      // A stepped crown on some of the taller towers, a mast on a few.
      if (h > 0.7 * maxH && rand() < 0.5) g.fillRect(x + w * 0.25, 128 - h - 8, w * 0.5, 8);
      if (h > 0.8 * maxH && rand() < 0.4) g.fillRect(x + w / 2 - 1, 128 - h - 22, 2, 22);
      if (windows)
        for (let wy = 128 - h + 6; wy < 124; wy += 8)
          for (let wx = x + 3; wx < x + w - 4; wx += 6)
            if (rand() < 0.12) {
              g.fillStyle = windows;
              g.fillRect(wx, wy, 2, 3);
            }
      x += w + (rand() < 0.3 ? 4 + rand() * 12 : 0);
    }
  };
  row('#c3d5e4', 40, 110, 18, 46, null);
  row('#a9bccd', 18, 70, 22, 60, 'rgba(255, 250, 235, 0.5)');
  const t = texture(c);
  t.wrapS = RepeatWrapping;
  return t;
}

/**
 * A cheaper stand-in for physically based material `m` (for a slow GPU, see main.ts's quality): its
 * colour, texture, glow (emissive), alpha, side and transparency on a Lambert surface (light per pixel without the
 * physically based highlight), or for a shiny or metal one (roughness under 0.45 or metalness 0.4 and
 * over) on a Phong surface with a highlight as sharp as it is smooth, so steel still glints. The
 * texture is shared, not copied.
 */
export function cheaperMaterial(m: MeshStandardMaterial): MeshLambertMaterial | MeshPhongMaterial {
  const common = {
    color: m.color.clone(),
    map: m.map,
    alphaMap: m.alphaMap,
    alphaTest: m.alphaTest,
    side: m.side,
    transparent: m.transparent,
    opacity: m.opacity,
    depthWrite: m.depthWrite,
    emissive: m.emissive.clone(),
    emissiveMap: m.emissiveMap,
    emissiveIntensity: m.emissiveIntensity,
  };
  if (m.roughness < 0.45 || m.metalness >= 0.4)
    return new MeshPhongMaterial({ ...common, shininess: 8 + 80 * (1 - m.roughness) ** 2, specular: 0x555555 });
  return new MeshLambertMaterial(common);
}

/**
 * Shadows cast on the ground by the sun, drawn without a shadow map (main.ts's lite quality): each
 * box flattened onto the ground along the sun's direction and drawn as a translucent dark shape.
 * The boxes are one instanced mesh (one draw call, no shadow pass) and the ball a mesh of its own.
 * Where shapes overlap (the blocks of a tower) the ground is darkened once, not twice: they all lie
 * in one plane and write its depth, and a later shape's equal depth fails the depth test.
 * The shadows fall on the ground only, not on other pieces.
 */
export class GroundShadows {
  /** The meshes (boxes, ball); add them to the scene. */
  readonly boxes: InstancedMesh;
  readonly ball: Mesh;
  /** The flattening onto the ground: a point (x, y, z) goes to (x - y sx, LIFT, z - y sz). */
  private readonly flatten = new Matrix4();
  private readonly m = new Matrix4();
  private readonly q = new Quaternion();
  private readonly v = new Vector3();
  private readonly s = new Vector3();
  private n = 0;
  /** Height of the shadows over the ground, m: over the site's dirt (5 mm), under the cue marks (20 mm). */
  static readonly LIFT = 0.012;

  /**
   * @param capacity most boxes drawn at once (boxes past it cast none), integer >= 1.
   * @param sun the direction toward the sun (x, y, z), its y > 0 (need not be a unit vector).
   * @throws RangeError on a bad capacity or a sun not above the horizon.
   */
  constructor(capacity: number, sun: ArrayLike<number>) {
    if (!(Number.isInteger(capacity) && capacity >= 1))
      throw new RangeError(`GroundShadows: capacity must be an integer >= 1, got ${capacity}`);
    if (!(sun.length === 3 && sun[1]! > 0 && Number.isFinite(sun[0]!) && Number.isFinite(sun[2]!)))
      throw new RangeError(`GroundShadows: sun must be 3 finite numbers with y > 0, got ${JSON.stringify(Array.from(sun))}`);
    const sx = sun[0]! / sun[1]!,
      sz = sun[2]! / sun[1]!;
    this.flatten.set(1, -sx, 0, 0, 0, 0, 0, GroundShadows.LIFT, 0, -sz, 1, 0, 0, 0, 0, 1);
    const material = new MeshBasicMaterial({ color: 0x000000, transparent: true, opacity: 0.38, side: DoubleSide, depthFunc: LessDepth });
    // Unit half extents: each instance scaled by its box's.
    this.boxes = new InstancedMesh(new BoxGeometry(2, 2, 2), material, capacity);
    this.boxes.instanceMatrix.setUsage(DynamicDrawUsage);
    this.boxes.frustumCulled = false;
    this.boxes.count = 0;
    this.ball = new Mesh(new SphereGeometry(1, 16, 10), material);
    this.ball.matrixAutoUpdate = false;
    this.ball.frustumCulled = false;
  }

  /** Starts a frame's shadows (no box casts one until `add`). */
  begin(): void {
    this.n = 0;
  }

  /**
   * The shadow of a box centred at (x, y, z), m, turned by the unit quaternion (qx, qy, qz, qw),
   * with half extents `half` (m, along its own turned axes).
   */
  add(x: number, y: number, z: number, qx: number, qy: number, qz: number, qw: number, half: readonly [number, number, number]): void {
    this.addBox(this.m.compose(this.v.set(x, y, z), this.q.set(qx, qy, qz, qw), this.s.set(half[0], half[1], half[2])));
  }

  /**
   * The shadow of the box `box` makes of the cube from -1 to 1 on each axis (its world matrix times a
   * scale by its half extents). `box` is overwritten.
   */
  addBox(box: Matrix4): void {
    if (this.n >= this.boxes.instanceMatrix.count) return;
    this.boxes.setMatrixAt(this.n++, box.premultiply(this.flatten));
  }

  /** Ends the frame: draws the box shadows added since `begin`, and the ball's for a ball of radius `r` at (x, y, z), m. */
  end(x: number, y: number, z: number, r: number): void {
    this.boxes.count = this.n;
    this.boxes.instanceMatrix.needsUpdate = true;
    this.ball.matrix.makeScale(r, r, r).setPosition(x, y, z).premultiply(this.flatten);
    this.ball.matrixWorldNeedsUpdate = true;
  }

  /** Shows or hides the shadows. */
  set visible(on: boolean) {
    this.boxes.visible = this.ball.visible = on;
  }
  get visible(): boolean {
    return this.boxes.visible;
  }
}
