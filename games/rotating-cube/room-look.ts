/**
 * The rotating cube room's scenery, drawn only (the physics knows none of it): a plank floor inside the
 * walls, stone-block walls (the renderer draws the wall bodies with `wallShape`; `update` makes the
 * walls between the camera and the room see-through, so the cube stays in sight), a paved terrace
 * round the room with lamp posts, planters and crates, a city skyline on a ring far off against a
 * dusk sky, fog that fades the terrace into it, and the lit pad's glow (a halo on the floor and a
 * beam of light rising from it). Every texture is drawn in code on a canvas. Kept light for software
 * WebGL: about a dozen meshes, shared geometries and materials, no extra lights.
 */
import { seededRandom } from '@bitphysics/game-kit';
import {
  AdditiveBlending,
  BackSide,
  BoxGeometry,
  CanvasTexture,
  CylinderGeometry,
  DoubleSide,
  Fog,
  Group,
  IcosahedronGeometry,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  PlaneGeometry,
  RepeatWrapping,
  type Scene,
  Shape,
  ShapeGeometry,
  SRGBColorSpace,
  type Vector3,
} from 'three';

/** A canvas of `w` x `h` px drawn by `draw`, as an sRGB texture repeating both ways. */
function canvasTexture(w: number, h: number, draw: (g: CanvasRenderingContext2D) => void): CanvasTexture {
  const c = document.createElement('canvas');
  c.width = w;
  c.height = h;
  draw(c.getContext('2d')!);
  const t = new CanvasTexture(c);
  t.colorSpace = SRGBColorSpace;
  t.wrapS = t.wrapT = RepeatWrapping;
  t.anisotropy = 4;
  return t;
}

/** Floor boards, 2 m square in 512 px: ten rows of planks 0.2 m wide, staggered, each its own shade of oak with a grain. */
function planksTexture(): CanvasTexture {
  return canvasTexture(512, 512, (g) => {
    const rnd = seededRandom(7);
    const row = 512 / 10;
    for (let r = 0; r < 10; r++) {
      let x = -rnd() * 200;
      while (x < 512) {
        const len = 130 + rnd() * 150;
        // Dark, muted oak: the pads' colours and the grid's light seams stand out on it.
        const l = 22 + rnd() * 8,
          hue = 24 + rnd() * 10;
        g.fillStyle = `hsl(${hue}, 26%, ${l}%)`;
        g.fillRect(x, r * row, len, row);
        // The grain: a few faint streaks along the plank.
        for (let k = 0; k < 5; k++) {
          g.strokeStyle = `hsla(${hue}, 30%, ${l - 7}%, 0.4)`;
          g.lineWidth = 1 + rnd() * 1.5;
          const y = r * row + 4 + rnd() * (row - 8);
          g.beginPath();
          g.moveTo(x, y);
          g.bezierCurveTo(x + len / 3, y + rnd() * 6 - 3, x + (2 * len) / 3, y + rnd() * 6 - 3, x + len, y);
          g.stroke();
        }
        g.fillStyle = 'rgba(20, 10, 4, 0.55)';
        g.fillRect(x, r * row, 2, row);
        x += len;
      }
      g.fillStyle = 'rgba(20, 10, 4, 0.6)';
      g.fillRect(0, r * row, 512, 2);
    }
    // Wrapped: the first plank of a row drawn from x < 0 shows again at the right edge.
  });
}

/** Stone blocks, 1 m square in 256 px: four courses 0.25 m high of blocks 0.5 m long, every other course offset, pale mortar. */
function blocksTexture(): CanvasTexture {
  return canvasTexture(256, 256, (g) => {
    const rnd = seededRandom(11);
    g.fillStyle = '#8d8577';
    g.fillRect(0, 0, 256, 256);
    for (let r = 0; r < 4; r++)
      for (let b = -1; b < 3; b++) {
        const x = b * 128 + (r % 2) * 64,
          y = r * 64;
        const l = 62 + rnd() * 12;
        g.fillStyle = `hsl(${34 + rnd() * 10}, ${14 + rnd() * 8}%, ${l}%)`;
        g.fillRect(x + 3, y + 3, 122, 58);
        // A lighter top edge and a darker foot: each block reads as carved.
        g.fillStyle = 'rgba(255, 255, 255, 0.12)';
        g.fillRect(x + 3, y + 3, 122, 6);
        g.fillStyle = 'rgba(0, 0, 0, 0.12)';
        g.fillRect(x + 3, y + 55, 122, 6);
      }
  });
}

/** Paving, 2 m square in 256 px: four slabs a side, grey-blue, each its own shade, with dark joints. */
function pavingTexture(): CanvasTexture {
  return canvasTexture(256, 256, (g) => {
    const rnd = seededRandom(5);
    g.fillStyle = '#1d222c';
    g.fillRect(0, 0, 256, 256);
    for (let i = 0; i < 4; i++)
      for (let j = 0; j < 4; j++) {
        g.fillStyle = `hsl(${215 + rnd() * 12}, 10%, ${27 + rnd() * 7}%)`;
        g.fillRect(i * 64 + 2, j * 64 + 2, 60, 60);
      }
  });
}

/**
 * The skyline's picture, 1024 x 256 px (repeated three times round the ring): clear above, and at its
 * foot a row of towers in dark violet with lit windows, a lower row of nearer ones in front.
 */
function skylineTexture(): CanvasTexture {
  const t = canvasTexture(1024, 256, (g) => {
    const rnd = seededRandom(3);
    for (const [base, tall, shade] of [
      [256, 150, '#2a2544'],
      [256, 90, '#1c1a30'],
    ] as const) {
      let x = 0;
      while (x < 1024) {
        const w = 40 + rnd() * 70,
          h = tall * (0.35 + rnd() * 0.65);
        g.fillStyle = shade;
        g.fillRect(x, base - h, w, h);
        for (let wy = base - h + 8; wy < base - 6; wy += 11)
          for (let wx = x + 6; wx < x + w - 6; wx += 9)
            if (rnd() < 0.28) {
              g.fillStyle = rnd() < 0.7 ? 'rgba(255, 214, 140, 0.85)' : 'rgba(170, 210, 255, 0.7)';
              g.fillRect(wx, wy, 4, 5);
            }
        x += w + rnd() * 6;
      }
    }
  });
  t.repeat.set(3, 1);
  t.wrapT = RepeatWrapping;
  return t;
}

/** The dusk sky behind everything: deep blue at the top to a warm violet at the horizon (the scene's background). */
function skyTexture(): CanvasTexture {
  const t = canvasTexture(4, 256, (g) => {
    const grad = g.createLinearGradient(0, 0, 0, 256);
    grad.addColorStop(0, '#0b1024');
    grad.addColorStop(0.55, '#2a2550');
    grad.addColorStop(1, '#6a4a6e');
    g.fillStyle = grad;
    g.fillRect(0, 0, 4, 256);
  });
  t.wrapS = t.wrapT = RepeatWrapping;
  return t;
}

/** A soft round spot, white at its centre to clear at its rim (the lit pad's halo). */
function haloTexture(): CanvasTexture {
  return canvasTexture(128, 128, (g) => {
    const grad = g.createRadialGradient(64, 64, 0, 64, 64, 64);
    grad.addColorStop(0, 'rgba(255, 255, 255, 0.9)');
    grad.addColorStop(0.45, 'rgba(255, 255, 255, 0.35)');
    grad.addColorStop(1, 'rgba(255, 255, 255, 0)');
    g.fillStyle = grad;
    g.fillRect(0, 0, 128, 128);
  });
}

/** A beam's side, bright at its foot fading to clear at its top. */
function beamTexture(): CanvasTexture {
  return canvasTexture(4, 128, (g) => {
    const grad = g.createLinearGradient(0, 0, 0, 128);
    grad.addColorStop(0, 'rgba(255, 255, 255, 0)');
    grad.addColorStop(1, 'rgba(255, 255, 255, 0.75)');
    g.fillStyle = grad;
    g.fillRect(0, 0, 4, 128);
  });
}

/**
 * A box `2 hx` x `2 hy` x `2 hz` m whose texture coordinates are in metres on every face (a repeating
 * texture of 1 m keeps its size on long walls and short ends alike), centred on the origin.
 */
export function metricBox(hx: number, hy: number, hz: number): BoxGeometry {
  if (!(hx > 0 && hy > 0 && hz > 0)) throw new RangeError(`metricBox: half extents must be > 0, got ${hx}, ${hy}, ${hz}`);
  const geometry = new BoxGeometry(2 * hx, 2 * hy, 2 * hz);
  const uv = geometry.getAttribute('uv');
  // BoxGeometry's faces in order: +x, -x (z by y), +y, -y (x by z), +z, -z (x by y), four vertices each.
  const size: [number, number][] = [
    [2 * hz, 2 * hy],
    [2 * hz, 2 * hy],
    [2 * hx, 2 * hz],
    [2 * hx, 2 * hz],
    [2 * hx, 2 * hy],
    [2 * hx, 2 * hy],
  ];
  for (let f = 0; f < 6; f++)
    for (let v = 0; v < 4; v++) {
      const i = 4 * f + v;
      uv.setXY(i, uv.getX(i) * size[f]![0], uv.getY(i) * size[f]![1]);
    }
  return geometry;
}

/** What `buildRoomLook` returns. */
export interface RoomLook {
  /** Everything it drew (shown in the room mode only, `setShown`). */
  readonly object: Group;
  /**
   * The look of wall `i` (the order of scene.ts `buildRoom`'s walls: +x, -x, +z, -z) with half extents
   * (hx, hy, hz), m: its geometry and material, for the renderer's `setShape` (scale 1).
   */
  wallShape(i: number, hx: number, hy: number, hz: number): { geometry: BoxGeometry; material: MeshStandardMaterial; scale: number };
  /**
   * Shows the look (and its fog and sky) with its ground at height `floorY`, m (the pivot modes' floor
   * lies under the pivot; the planters and crates show only at 0, the room's), or hides it (`shown`
   * false: the renderer's plain scenery).
   */
  setShown(shown: boolean, floorY?: number): void;
  /**
   * Per frame: the walls on the camera's side of the room (`camera`, m) see-through, the others solid;
   * the lit pad's glow at (x, z), m, `half` its half edge, m, in colour `color` (0xRRGGBB), at
   * `strength` in [0, 1] (0 hides it).
   */
  update(camera: Vector3, x: number, z: number, half: number, color: number, strength: number): void;
}

/** Height of the lit pad's rim of light, m: well under the 1 m cube, so the pad reads as a mark on the floor. */
const PAD_RIM_HEIGHT = 0.3;

/** Opacity of a wall between the camera and the room: the cube behind it stays in sight. */
const NEAR_WALL_OPACITY = 0.4;

/**
 * Builds the room's look into `scene` for a room of inside half width `roomHalf` m, walls `wallHalfThickness`
 * m thick (half) and `wallHeight` m high. @throws RangeError on a size that is not positive.
 */
export function buildRoomLook(scene: Scene, roomHalf: number, wallHeight: number, wallHalfThickness: number): RoomLook {
  if (!(roomHalf > 0 && wallHeight > 0 && wallHalfThickness > 0))
    throw new RangeError(`buildRoomLook: sizes must be > 0, got ${roomHalf}, ${wallHeight}, ${wallHalfThickness}`);
  const object = new Group();
  object.name = 'room-look';
  scene.add(object);
  const outer = roomHalf + 2 * wallHalfThickness;

  // The floor inside the walls: boards (one picture per 2 m), taking the cube's shadow.
  const planks = planksTexture();
  planks.repeat.set(roomHalf, roomHalf);
  const floor = new Mesh(
    new PlaneGeometry(2 * outer, 2 * outer).rotateX(-Math.PI / 2),
    new MeshStandardMaterial({ map: planks, roughness: 0.72, metalness: 0 }),
  );
  floor.receiveShadow = true;
  object.add(floor);

  // The terrace round the room: paving with a square hole where the floor is.
  const paving = pavingTexture();
  paving.repeat.set(0.5, 0.5);
  const far = 40;
  const terraceShape = new Shape().moveTo(-far, -far).lineTo(far, -far).lineTo(far, far).lineTo(-far, far).lineTo(-far, -far);
  const hole = new Shape().moveTo(-outer, -outer).lineTo(-outer, outer).lineTo(outer, outer).lineTo(outer, -outer).lineTo(-outer, -outer);
  terraceShape.holes.push(hole);
  // ShapeGeometry's texture coordinates are its x, y in metres: the paving's repeat of 0.5 makes a picture 2 m.
  const terrace = new Mesh(
    new ShapeGeometry(terraceShape).rotateX(-Math.PI / 2),
    new MeshStandardMaterial({ map: paving, roughness: 0.9, metalness: 0 }),
  );
  terrace.receiveShadow = true;
  object.add(terrace);

  // The walls' stone: one picture a metre; a material each, so each can be see-through on its own.
  const blocks = blocksTexture();
  const wallMaterials = [0, 1, 2, 3].map(
    () => new MeshStandardMaterial({ map: blocks, roughness: 0.85, metalness: 0, transparent: true, opacity: 1 }),
  );
  const wallGeometries = new Map<string, BoxGeometry>();
  const wallSides = [
    [1, 0],
    [-1, 0],
    [0, 1],
    [0, -1],
  ] as const;

  // Props on the terrace: a glowing bollard at each outer corner (low: from the high camera a tall
  // post ran across the view), planters and crates along the walls.
  const metal = new MeshStandardMaterial({ color: 0x2b2f3a, roughness: 0.45, metalness: 0.6 });
  const bulb = new MeshStandardMaterial({ color: 0xfff1d0, emissive: 0xffc870, emissiveIntensity: 2.2 });
  const post = new CylinderGeometry(0.16, 0.2, 0.6, 12).translate(0, 0.3, 0);
  const lamp = new CylinderGeometry(0.15, 0.15, 0.14, 12).translate(0, 0.67, 0);
  for (const sx of [-1, 1])
    for (const sz of [-1, 1]) {
      const p = new Mesh(post, metal),
        b = new Mesh(lamp, bulb);
      p.position.set(sx * (outer + 0.6), 0, sz * (outer + 0.6));
      b.position.copy(p.position);
      p.castShadow = true;
      object.add(p, b);
    }
  // The planters and crates stand by the room's walls; on the pivot they stood behind the spinning box
  // and muddled its outline, so they show in the room only (`setShown`).
  const props = new Group();
  object.add(props);
  const pot = new MeshStandardMaterial({ color: 0x8a4b32, roughness: 0.8 });
  const leaves = new MeshStandardMaterial({ color: 0x3f7d3a, roughness: 0.9, flatShading: true });
  const potGeometry = new CylinderGeometry(0.32, 0.24, 0.55, 12).translate(0, 0.275, 0);
  const bush = new IcosahedronGeometry(0.48, 0).translate(0, 0.85, 0);
  for (const [x, z] of [
    [-(outer + 0.8), 1.2],
    [outer + 0.8, -1.6],
    [1.8, -(outer + 0.8)],
  ] as const) {
    const a = new Mesh(potGeometry, pot),
      b = new Mesh(bush, leaves);
    a.position.set(x, 0, z);
    b.position.set(x, 0, z);
    b.rotation.y = x + z;
    a.castShadow = b.castShadow = true;
    props.add(a, b);
  }
  const crateMaterial = new MeshStandardMaterial({ map: planks, color: 0xd9b98c, roughness: 0.8 });
  const crate = metricBox(0.35, 0.35, 0.35).translate(0, 0.35, 0);
  for (const [x, y, z, turn] of [
    [-2.2, 0, -(outer + 0.75), 0.2],
    [-1.45, 0, -(outer + 0.8), -0.15],
    [-1.85, 0.7, -(outer + 0.78), 0.5],
  ] as const) {
    const c = new Mesh(crate, crateMaterial);
    c.position.set(x, y, z);
    c.rotation.y = turn;
    c.castShadow = c.receiveShadow = true;
    props.add(c);
  }

  // The skyline: a ring of towers far off, unfogged, against the dusk sky (the scene's background).
  const skyline = new Mesh(
    new CylinderGeometry(34, 34, 16, 48, 1, true).translate(0, 6.5, 0),
    new MeshBasicMaterial({ map: skylineTexture(), side: BackSide, transparent: true, fog: false, depthWrite: false }),
  );
  skyline.renderOrder = -2;
  object.add(skyline);
  const sky = skyTexture();
  const fog = new Fog(0x3a3160, 16, 42);
  const background = scene.background;

  // The lit pad's glow: a halo on the floor round it and a low square rim of light rising from its
  // edge (PAD_RIM_HEIGHT), added to what is behind: a floor marking, not a glowing block the size of the cube.
  const halo = new Mesh(
    new PlaneGeometry(1, 1).rotateX(-Math.PI / 2),
    new MeshBasicMaterial({ map: haloTexture(), transparent: true, blending: AdditiveBlending, depthWrite: false }),
  );
  const beam = new Mesh(
    new CylinderGeometry(1, 1, 1, 4, 1, true).rotateY(Math.PI / 4).translate(0, 0.5, 0),
    new MeshBasicMaterial({ map: beamTexture(), transparent: true, blending: AdditiveBlending, depthWrite: false, side: DoubleSide }),
  );
  halo.renderOrder = beam.renderOrder = 4;
  object.add(halo, beam);

  return {
    object,
    wallShape(i, hx, hy, hz) {
      const key = `${hx},${hy},${hz}`;
      let geometry = wallGeometries.get(key);
      if (!geometry) {
        geometry = metricBox(hx, hy, hz);
        wallGeometries.set(key, geometry);
      }
      const material = wallMaterials[i];
      if (!material) throw new RangeError(`RoomLook.wallShape: i must be 0 to 3, got ${i}`);
      return { geometry, material, scale: 1 };
    },
    setShown(shown, floorY = 0) {
      object.visible = shown;
      object.position.y = floorY;
      props.visible = floorY === 0;
      scene.fog = shown ? fog : null;
      scene.background = shown ? sky : background;
    },
    update(camera, x, z, half, color, strength) {
      wallSides.forEach(([nx, nz], i) => {
        // The camera beyond this wall's outer face: the wall stands between it and the room.
        const between = nx * camera.x + nz * camera.z > outer;
        const m = wallMaterials[i]!;
        m.opacity = between ? NEAR_WALL_OPACITY : 1;
        m.depthWrite = !between;
      });
      halo.visible = beam.visible = strength > 0;
      if (strength <= 0) return;
      const c = (halo.material as MeshBasicMaterial).color;
      c.setHex(color).multiplyScalar(0.6 * strength);
      (beam.material as MeshBasicMaterial).color.copy(c).multiplyScalar(0.45);
      halo.position.set(x, 0.006, z);
      halo.scale.set(4.4 * half, 1, 4.4 * half);
      beam.position.set(x, 0.02, z);
      beam.scale.set(1.02 * half * Math.SQRT2, PAD_RIM_HEIGHT, 1.02 * half * Math.SQRT2);
    },
  };
}
