/**
 * The flight simulator's scenery (drawing only, no physics): a sky dome shaded from the haze at the
 * horizon to deep blue overhead with the sun in it, the hills of the scene's terrain function on a
 * grid that follows the aircraft, the sea, low-poly cumulus clouds fixed in the world (seeded
 * per 2 km cell, so the same clouds are there when the aircraft comes back) in three layers (small
 * ones 450 to 800 m up and 950 to 1,250 m up, among the rings, and large ones 1,500 to 2,100 m up)
 * that the aircraft flies past and through, so its speed shows; trees on the lowland and the slopes
 * and villages of small houses, fixed in the world the same way (so the ground streams past when
 * low, and gives a scale); and an airfield with a runway under the start.
 * Trees and houses are two instanced meshes and the clouds one merged mesh: a handful of draw calls,
 * cheap enough for a phone.
 */

import { terrainHeight } from '@bitphysics/projects';
import {
  BackSide,
  BoxGeometry,
  type BufferAttribute,
  BufferGeometry,
  type Camera,
  CircleGeometry,
  Color,
  ConeGeometry,
  CylinderGeometry,
  Float32BufferAttribute,
  Fog,
  Frustum,
  IcosahedronGeometry,
  InstancedMesh,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshStandardMaterial,
  PlaneGeometry,
  Quaternion,
  type Scene,
  Sphere,
  SphereGeometry,
  Vector3,
} from 'three';
import { mergeGeometries } from 'three/examples/jsm/utils/BufferGeometryUtils.js';

/** The haze at the horizon: the fog's colour and the sky dome's lowest. */
export const HORIZON_COLOUR = 0xc9dff2;
/** The sky straight up. */
const ZENITH_COLOUR = 0x3f7fcf;
/** Direction towards the sun (world, normalised where used): the same as the scene's light. */
export const SUN_DIRECTION: readonly [number, number, number] = [0.4, 1, 0.3];

/** Terrain grid's side, m. */
const SIZE = 24_000;
/** Cloud cells' side, m. */
const CLOUD_CELL = 2000;
/** Tree cells' side, m (at most one tree a cell). */
const TREE_CELL = 70;

/** How much scenery is drawn round the aircraft (`SCENERY_DETAIL`). */
export interface SceneryDetail {
  /** Terrain grid cells a side (the grid is SIZE m a side), integer >= 8. */
  segments: number;
  /** Clouds are kept within this many CLOUD_CELL cells of the aircraft's cell, integer >= 1. */
  cloudReach: number;
  /** How far from the aircraft trees and villages are drawn, m. */
  treeReach: number;
  /** The haze: where it starts and where it hides everything, m from the camera. */
  fogNear: number;
  fogFar: number;
}

/**
 * The scenery's two levels of detail. 'full' (a desktop): 51,000 terrain triangles, about 1,700 trees
 * and 300 cloud puffs, 144,000 triangles a frame in all. 'light' (a phone): a coarser grid (the hills
 * are smooth sums of sines, so 240 m cells still draw them), trees to 1.7 km and clouds to the haze,
 * which comes nearer to hide the edge: about 64,000 triangles. Under software WebGL (SwiftShader) a
 * phone's few pixels cost little and its frame is the triangles'.
 */
export const SCENERY_DETAIL: Readonly<Record<'full' | 'light', Readonly<SceneryDetail>>> = Object.freeze({
  full: Object.freeze({ segments: 160, cloudReach: 5, treeReach: 2600, fogNear: 5000, fogFar: 17_000 }),
  light: Object.freeze({ segments: 100, cloudReach: 3, treeReach: 1700, fogNear: 3000, fogFar: 8000 }),
});
/** Village cells: side, m (at most one village a cell), and the houses a village has at most. */
const VILLAGE_CELL = 1500,
  VILLAGE_HOUSES = 14;
/** Most trees and houses drawn (the instanced meshes' sizes). */
const MAX_TREES = 6000,
  MAX_HOUSES = 600;
/** The runway: length and width, m, and the least height of its ground above the sea, m. */
const RUNWAY_LENGTH = 1600,
  RUNWAY_WIDTH = 45;

/** A well-mixed 32-bit hash of an integer cell (i, j) and a salt. */
function hash(i: number, j: number, salt: number): number {
  let h = Math.imul(i, 0x27d4eb2d) ^ Math.imul(j, 0x165667b1) ^ Math.imul(salt, 0x9e3779b1);
  h = Math.imul(h ^ (h >>> 15), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}

/** `g` with every vertex coloured `colour` (a vertex colour, which the instance's colour then tints). */
function tinted(g: BufferGeometry, colour: number): BufferGeometry {
  const c = new Color(colour),
    n = g.attributes.position!.count;
  const data = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) data.set([c.r, c.g, c.b], 3 * i);
  g.setAttribute('color', new Float32BufferAttribute(data, 3));
  return g;
}

/** The scenery of one page: call `update` every frame with the camera's and the aircraft's positions. */
export interface Scenery {
  /**
   * Moves the sky with the camera and rebuilds the terrain and clouds when the aircraft has moved far.
   * With `view` (the camera the frame is drawn with, its matrices up to date) only the trees and
   * houses inside its view are handed to the GPU; without it, all those placed.
   */
  update(camera: Vector3, aircraft: Vector3, view?: Camera): void;
  /** Uses the terrain of a new world (the aircraft scene's `terrain`) and its seed for the clouds. */
  setTerrain(terrain: Float64Array, seed: number): void;
  /** Clouds drawn now (for tests): puffs in the merged cloud mesh. */
  cloudPuffs(): number;
  /** Trees, houses and cloud puffs drawn now, and the lowest and highest cloud puff's centre (m; tests). */
  counts(): { trees: number; houses: number; puffs: number; cloudLow: number; cloudHigh: number };
  /** The runway's centre (m, world) and its heading (rad, 0 along +x). */
  runway(): { x: number; y: number; z: number; heading: number };
}

/** Builds the scenery into `scene` (and sets its fog), as much of it as `detail` says (default SCENERY_DETAIL.full). */
export function createScenery(scene: Scene, detail: Readonly<SceneryDetail> = SCENERY_DETAIL.full): Scenery {
  const { segments: SEGMENTS, cloudReach: CLOUD_REACH, treeReach: TREE_REACH } = detail;
  scene.fog = new Fog(HORIZON_COLOUR, detail.fogNear, detail.fogFar);

  // Sky dome: a sphere seen from inside, each vertex coloured by its height (haze to zenith).
  const skyGeometry = new SphereGeometry(20_000, 32, 16);
  const pos = skyGeometry.attributes.position as BufferAttribute;
  const colours = new Float32Array(pos.count * 3);
  const low = new Color(HORIZON_COLOUR),
    high = new Color(ZENITH_COLOUR),
    c = new Color();
  for (let i = 0; i < pos.count; i++) {
    const h = Math.max(0, pos.getY(i) / 20_000);
    c.copy(low).lerp(high, Math.sqrt(h));
    colours.set([c.r, c.g, c.b], 3 * i);
  }
  skyGeometry.setAttribute('color', new Float32BufferAttribute(colours, 3));
  const sky = new Mesh(skyGeometry, new MeshBasicMaterial({ vertexColors: true, side: BackSide, fog: false, depthWrite: false }));
  sky.renderOrder = -2;
  sky.frustumCulled = false;
  scene.add(sky);
  const sunDir = new Vector3(...SUN_DIRECTION).normalize();
  const sun = new Mesh(new CircleGeometry(700, 24), new MeshBasicMaterial({ color: 0xfff6d8, fog: false, depthWrite: false }));
  const glow = new Mesh(
    new CircleGeometry(1800, 24),
    new MeshBasicMaterial({ color: 0xfff2c0, transparent: true, opacity: 0.25, fog: false, depthWrite: false }),
  );
  sun.renderOrder = glow.renderOrder = -1;
  scene.add(glow, sun);

  // Terrain: a grid that follows the aircraft, heights from the scene's terrain function.
  const terrainGeometry = new PlaneGeometry(SIZE, SIZE, SEGMENTS, SEGMENTS);
  terrainGeometry.rotateX(-Math.PI / 2);
  terrainGeometry.setAttribute('color', new Float32BufferAttribute(new Float32Array(terrainGeometry.attributes.position!.count * 3), 3));
  const base = Float32Array.from(terrainGeometry.attributes.position!.array as Float32Array);
  const ground = new Mesh(terrainGeometry, new MeshStandardMaterial({ vertexColors: true, roughness: 1, flatShading: true }));
  scene.add(ground);
  const sea = new Mesh(
    new PlaneGeometry(SIZE * 2, SIZE * 2),
    new MeshStandardMaterial({ color: 0x2a6f9e, roughness: 0.35, metalness: 0.1 }),
  );
  sea.rotateX(-Math.PI / 2);
  sea.position.y = 60;
  scene.add(sea);
  const shore = new Color(0xd8c690),
    forest = new Color(0x2f5f2c),
    rock = new Color(0x8a7a5c),
    snow = new Color(0xf4f6f8),
    tmp = new Color();
  /** Colours of the lowland's fields (a patchwork, one colour a field). */
  const fields = [0x6aa84f, 0x8fbf4a, 0x5c9440, 0xb8b455, 0x7fae5a, 0x9c8f52, 0x4f8a3c, 0xa7c46a].map((c) => new Color(c));
  /** Side of a field, m (about four grid cells). */
  const FIELD = 600;
  let terrain: Float64Array = new Float64Array(0);
  let seed = 1;
  let terrainCentre: [number, number] | null = null;

  /** Rebuilds the grid's heights and colours around (cx, cz), snapped to whole cells. */
  function rebuildTerrain(cx: number, cz: number): void {
    const cell = SIZE / SEGMENTS;
    const sx = Math.round(cx / cell) * cell,
      sz = Math.round(cz / cell) * cell;
    terrainCentre = [sx, sz];
    const p = terrainGeometry.attributes.position as BufferAttribute,
      col = terrainGeometry.attributes.color as BufferAttribute;
    for (let i = 0; i < p.count; i++) {
      const x = base[3 * i]! + sx,
        z = base[3 * i + 2]! + sz;
      const h = terrainHeight(terrain, x, z);
      p.setXYZ(i, x, h, z);
      // Sand at the water's edge; fields, with woods on a third of them and more woods up the
      // slopes; then rock and snow on the tops.
      const fi = Math.floor(x / FIELD),
        fj = Math.floor(z / FIELD),
        f = hash(fi, fj, 11);
      const wood = Math.min(1, Math.max(0, (h - 200) / 180) + ((f >>> 8) % 3 === 0 ? 1 : 0));
      if (h < 72) tmp.copy(shore);
      else if (h < 380) tmp.copy(fields[f % fields.length]!).lerp(forest, wood * 0.85);
      else if (h < 540) tmp.copy(forest).lerp(rock, (h - 380) / 160);
      else tmp.copy(rock).lerp(snow, Math.min(1, (h - 540) / 110));
      col.setXYZ(i, tmp.r, tmp.g, tmp.b);
    }
    p.needsUpdate = true;
    col.needsUpdate = true;
    terrainGeometry.computeVertexNormals();
    terrainGeometry.computeBoundingSphere();
  }

  // Clouds: one merged mesh of flattened icosahedron puffs, rebuilt around the aircraft's cell.
  const cloudMaterial = new MeshLambertMaterial({ color: 0xffffff, emissive: 0x8a96a6, flatShading: true });
  const clouds = new Mesh(new BufferGeometry(), cloudMaterial);
  clouds.frustumCulled = false;
  scene.add(clouds);
  let cloudCell: [number, number] | null = null;
  let puffs = 0,
    cloudLow = Infinity,
    cloudHigh = -Infinity;
  const puff = new IcosahedronGeometry(1, 1);

  /** Rebuilds the clouds of the cells within CLOUD_REACH of cell (ci, cj). */
  function rebuildClouds(ci: number, cj: number): void {
    cloudCell = [ci, cj];
    cloudLow = Infinity;
    cloudHigh = -Infinity;
    const parts: BufferGeometry[] = [];
    for (let i = ci - CLOUD_REACH; i <= ci + CLOUD_REACH; i++)
      for (let j = cj - CLOUD_REACH; j <= cj + CLOUD_REACH; j++) {
        const h = hash(i, j, seed);
        // About half the cells hold a cloud, in one of three layers: small low ones (450 to 800 m up)
        // and middle ones (950 to 1,250 m), among the rings, and large ones (1,500 to 2,100 m).
        if ((h & 7) > 3) continue;
        const layer = (h >>> 29) % 3;
        const x0 = (i + ((h >>> 3) & 255) / 256) * CLOUD_CELL,
          z0 = (j + ((h >>> 11) & 255) / 256) * CLOUD_CELL,
          y0 = layer === 0 ? 450 + ((h >>> 19) & 63) * 5.5 : layer === 1 ? 950 + ((h >>> 19) & 63) * 4.8 : 1500 + ((h >>> 19) & 63) * 9.5,
          n = 4 + ((h >>> 25) & 3),
          size = (layer === 2 ? 140 : 55) + ((h >>> 27) & 3) * (layer === 2 ? 40 : 14);
        for (let k = 0; k < n; k++) {
          const g = hash(i, j, seed + 97 * (k + 1));
          const r = size * (0.6 + ((g & 255) / 255) * 0.7);
          const p = puff.clone();
          p.scale(r * 1.3, r * 0.75, r);
          p.translate(
            x0 + (((g >>> 8) & 255) / 255 - 0.5) * size * 3,
            y0 + r * 0.35 + (((g >>> 16) & 255) / 255) * size * 0.4,
            z0 + (((g >>> 24) & 255) / 255 - 0.5) * size * 1.6,
          );
          parts.push(p);
          cloudLow = Math.min(cloudLow, y0);
          cloudHigh = Math.max(cloudHigh, y0);
        }
      }
    puffs = parts.length;
    clouds.geometry.dispose();
    clouds.geometry = parts.length > 0 ? mergeGeometries(parts)! : new BufferGeometry();
    for (const p of parts) p.dispose();
  }

  // Trees: one instanced low-poly cone on a trunk, at most one a TREE_CELL cell, more in the woods.
  const treeGeometry = mergeGeometries([
    new ConeGeometry(0.5, 1, 6).translate(0, 0.75, 0),
    new CylinderGeometry(0.08, 0.1, 0.3, 5).translate(0, 0.15, 0),
  ])!;
  const trees = new InstancedMesh(
    treeGeometry,
    new MeshLambertMaterial({ color: 0xffffff, emissive: 0x1a2a14, flatShading: true }),
    MAX_TREES,
  );
  trees.frustumCulled = false;
  scene.add(trees);
  // Houses: an instanced box with a pitched roof, walls and roofs coloured per instance.
  const houseGeometry = mergeGeometries([
    tinted(new BoxGeometry(1, 0.6, 1).translate(0, 0.3, 0).toNonIndexed(), 0xffffff),
    tinted(
      new ConeGeometry(0.78, 0.45, 4, 1)
        .rotateY(Math.PI / 4)
        .translate(0, 0.82, 0)
        .toNonIndexed(),
      0xc0483a,
    ),
  ])!;
  const houses = new InstancedMesh(
    houseGeometry,
    new MeshLambertMaterial({ color: 0xffffff, vertexColors: true, flatShading: true }),
    MAX_HOUSES,
  );
  houses.frustumCulled = false;
  scene.add(houses);
  const placedTrees = culledInstances(trees),
    placedHouses = culledInstances(houses);
  const leafColours = [0x3f7a36, 0x4f8a3c, 0x37703a, 0x5f9440].map((c) => new Color(c));
  const houseColours = [0xe8dcc4, 0xd9c7a5, 0xf0ece2, 0xc9b79a].map((c) => new Color(c));
  const m4 = new Matrix4(),
    q = new Quaternion(),
    up = new Vector3(0, 1, 0),
    at = new Vector3(),
    size = new Vector3();
  let treeCount = 0,
    houseCount = 0;
  /** The airfield: the runway's centre (m) and heading (rad). */
  const field = { x: 0, y: 0, z: 0, heading: 0 };

  /** Whether (x, z) is on the runway or its apron (no trees or houses there). */
  function onField(x: number, z: number): boolean {
    const dx = x - field.x,
      dz = z - field.z;
    const along = dx * Math.cos(field.heading) + dz * Math.sin(field.heading),
      across = -dx * Math.sin(field.heading) + dz * Math.cos(field.heading);
    return Math.abs(along) < RUNWAY_LENGTH / 2 + 150 && Math.abs(across) < RUNWAY_WIDTH / 2 + 160;
  }

  /** Places the trees and the villages within TREE_REACH of (cx, cz). */
  function rebuildGround(cx: number, cz: number): void {
    treeCount = 0;
    const i0 = Math.floor((cx - TREE_REACH) / TREE_CELL),
      i1 = Math.floor((cx + TREE_REACH) / TREE_CELL),
      j0 = Math.floor((cz - TREE_REACH) / TREE_CELL),
      j1 = Math.floor((cz + TREE_REACH) / TREE_CELL);
    for (let i = i0; i <= i1 && treeCount < MAX_TREES; i++)
      for (let j = j0; j <= j1 && treeCount < MAX_TREES; j++) {
        const h = hash(i, j, seed + 31);
        const x = (i + (h & 255) / 256) * TREE_CELL,
          z = (j + ((h >>> 8) & 255) / 256) * TREE_CELL;
        if ((x - cx) ** 2 + (z - cz) ** 2 > TREE_REACH * TREE_REACH) continue;
        const y = terrainHeight(terrain, x, z);
        if (y < 75 || y > 520) continue;
        // Woods: a third of the fields (as the ground's colours have them) and the slopes above 200 m.
        const f = hash(Math.floor(x / 600), Math.floor(z / 600), 11);
        const wood = (f >>> 8) % 3 === 0 || y > 220;
        if (((h >>> 16) & 15) > (wood ? 9 : 1)) continue;
        if (onField(x, z)) continue;
        const tall = 12 + ((h >>> 20) & 15) * 1.2;
        m4.compose(at.set(x, y - 2, z), q.identity(), size.set(tall * 0.55, tall, tall * 0.55));
        trees.setMatrixAt(treeCount, m4);
        trees.setColorAt(treeCount, leafColours[(h >>> 24) & 3]!);
        treeCount++;
      }
    trees.count = treeCount;
    trees.instanceMatrix.needsUpdate = true;
    if (trees.instanceColor) trees.instanceColor.needsUpdate = true;
    // Villages: a few lowland cells hold a cluster of houses round a centre, plus a row by the runway.
    houseCount = 0;
    const addHouse = (x: number, z: number, turn: number, g: number): void => {
      if (houseCount >= MAX_HOUSES) return;
      const y = terrainHeight(terrain, x, z);
      if (y < 72) return;
      const w = 14 + (g & 7) * 2,
        d = 10 + ((g >>> 3) & 7) * 1.5,
        tall = 9 + ((g >>> 6) & 3) * 3;
      m4.compose(at.set(x, y - 1.5, z), q.setFromAxisAngle(up, turn), size.set(w, tall, d));
      houses.setMatrixAt(houseCount, m4);
      houses.setColorAt(houseCount, houseColours[(g >>> 9) & 3]!);
      houseCount++;
    };
    const reach = Math.ceil(TREE_REACH / VILLAGE_CELL) + 1;
    const vi = Math.floor(cx / VILLAGE_CELL),
      vj = Math.floor(cz / VILLAGE_CELL);
    for (let i = vi - reach; i <= vi + reach; i++)
      for (let j = vj - reach; j <= vj + reach; j++) {
        const h = hash(i, j, seed + 57);
        if ((h & 3) !== 0) continue;
        const x0 = (i + 0.2 + ((h >>> 2) & 255) / 430) * VILLAGE_CELL,
          z0 = (j + 0.2 + ((h >>> 10) & 255) / 430) * VILLAGE_CELL;
        const y0 = terrainHeight(terrain, x0, z0);
        if (y0 < 80 || y0 > 300 || onField(x0, z0)) continue;
        const n = 6 + ((h >>> 18) % (VILLAGE_HOUSES - 5));
        for (let k = 0; k < n; k++) {
          const g = hash(i, j, seed + 101 * (k + 1));
          const a = (k / n) * 2 * Math.PI + ((g & 255) / 255) * 0.6,
            r = 40 + ((g >>> 12) & 127);
          addHouse(x0 + r * Math.cos(a), z0 + r * Math.sin(a), -a, g);
        }
      }
    for (let k = 0; k < 8; k++) {
      const along = -RUNWAY_LENGTH / 2 + 200 + k * 45,
        across = RUNWAY_WIDTH / 2 + 110;
      addHouse(
        field.x + along * Math.cos(field.heading) - across * Math.sin(field.heading),
        field.z + along * Math.sin(field.heading) + across * Math.cos(field.heading),
        -field.heading,
        hash(k, 3, seed),
      );
    }
    houses.count = houseCount;
    houses.instanceMatrix.needsUpdate = true;
    if (houses.instanceColor) houses.instanceColor.needsUpdate = true;
    placedTrees.keep(treeCount);
    placedHouses.keep(houseCount);
  }

  // The runway: a strip of asphalt draped over the ground, with a white centre line and threshold bars.
  const runwayGeometry = new PlaneGeometry(RUNWAY_LENGTH, RUNWAY_WIDTH, 32, 1);
  runwayGeometry.rotateX(-Math.PI / 2);
  const runwayBase = Float32Array.from(runwayGeometry.attributes.position!.array as Float32Array);
  const runway = new Mesh(runwayGeometry, new MeshLambertMaterial({ color: 0x3a3d42 }));
  const marks = new Mesh(new BufferGeometry(), new MeshBasicMaterial({ color: 0xf2f2f2 }));
  scene.add(runway, marks);

  /**
   * Lays the airfield on the flattest lowland within 4 km of the start (the origin; nearer wins
   * between two about as flat), its runway along the start's heading (+x).
   */
  function placeRunway(): void {
    let best = Infinity;
    field.heading = 0;
    for (let x = -4000; x <= 4000; x += 250)
      for (let z = -4000; z <= 4000; z += 250) {
        let lo = Infinity,
          hi = -Infinity;
        for (const a of [-0.5, -0.25, 0, 0.25, 0.5]) {
          const y = terrainHeight(terrain, x + a * RUNWAY_LENGTH, z);
          lo = Math.min(lo, y);
          hi = Math.max(hi, y);
        }
        if (lo < 75) continue;
        // Flat first; near the start breaks ties.
        const score = hi - lo + Math.hypot(x, z) / 400;
        if (score < best) {
          best = score;
          field.x = x;
          field.z = z;
        }
      }
    field.y = terrainHeight(terrain, field.x, field.z);
    const p = runwayGeometry.attributes.position as BufferAttribute;
    for (let i = 0; i < p.count; i++) {
      const x = runwayBase[3 * i]! + field.x,
        z = runwayBase[3 * i + 2]! + field.z;
      // Draped over the hills' true surface, lifted clear of the flat-shaded ground's cells.
      p.setXYZ(i, x, terrainHeight(terrain, x, z) + 4, z);
    }
    p.needsUpdate = true;
    runwayGeometry.computeVertexNormals();
    runwayGeometry.computeBoundingSphere();
    const bars: BufferGeometry[] = [];
    const bar = (along: number, across: number, length: number, width: number): void => {
      const x = field.x + along,
        z = field.z + across;
      bars.push(new PlaneGeometry(length, width).rotateX(-Math.PI / 2).translate(x, terrainHeight(terrain, x, z) + 4.6, z));
    };
    for (let a = -RUNWAY_LENGTH / 2 + 120; a < RUNWAY_LENGTH / 2 - 120; a += 80) bar(a + 20, 0, 40, 1.5);
    for (const end of [-1, 1]) for (let k = -3; k <= 3; k++) bar(end * (RUNWAY_LENGTH / 2 - 30), k * 5.5, 36, 3);
    marks.geometry.dispose();
    marks.geometry = mergeGeometries(bars)!;
    for (const b of bars) b.dispose();
  }
  let groundCentre: [number, number] | null = null;
  const viewFrustum = new Frustum(),
    viewMatrix = new Matrix4();

  return {
    update(camera, aircraft, view) {
      sky.position.copy(camera);
      sun.position.copy(sunDir).multiplyScalar(18_000).add(camera);
      glow.position.copy(sunDir).multiplyScalar(18_500).add(camera);
      sun.lookAt(camera);
      glow.lookAt(camera);
      if (!terrainCentre || Math.hypot(aircraft.x - terrainCentre[0], aircraft.z - terrainCentre[1]) > 2000)
        rebuildTerrain(aircraft.x, aircraft.z);
      if (!groundCentre || Math.hypot(aircraft.x - groundCentre[0], aircraft.z - groundCentre[1]) > 700) {
        if (!groundCentre) placeRunway();
        groundCentre = [aircraft.x, aircraft.z];
        rebuildGround(aircraft.x, aircraft.z);
      }
      sea.position.x = aircraft.x;
      sea.position.z = aircraft.z;
      const ci = Math.floor(aircraft.x / CLOUD_CELL),
        cj = Math.floor(aircraft.z / CLOUD_CELL);
      if (!cloudCell || Math.abs(ci - cloudCell[0]) > 1 || Math.abs(cj - cloudCell[1]) > 1) rebuildClouds(ci, cj);
      if (view) {
        viewFrustum.setFromProjectionMatrix(viewMatrix.multiplyMatrices(view.projectionMatrix, view.matrixWorldInverse));
        placedTrees.cull(viewFrustum);
        placedHouses.cull(viewFrustum);
      }
    },
    setTerrain(t, s) {
      terrain = t;
      seed = s;
      terrainCentre = null;
      cloudCell = null;
      groundCentre = null;
    },
    cloudPuffs: () => puffs,
    counts: () => ({ trees: treeCount, houses: houseCount, puffs, cloudLow, cloudHigh }),
    runway: () => ({ ...field }),
  };
}

/**
 * Per-instance view culling of an instanced mesh (three.js culls an instanced mesh as one whole, and
 * the trees and houses ring the aircraft, so nearly all of them were drawn out of view): `keep` takes
 * a copy of the first `n` instances as placed, `cull` hands the GPU only those whose bounding sphere
 * (the geometry's, scaled by the instance's largest axis) meets the frustum, in placed order.
 */
function culledInstances(mesh: InstancedMesh): { keep(n: number): void; cull(frustum: Frustum): void } {
  const matrices = new Float32Array(mesh.instanceMatrix.array.length);
  let colours: Float32Array | null = null;
  let placed = 0;
  mesh.geometry.computeBoundingSphere();
  const local = mesh.geometry.boundingSphere!.clone();
  const sphere = new Sphere(),
    m = new Matrix4();
  return {
    keep(n) {
      placed = n;
      matrices.set(mesh.instanceMatrix.array.subarray(0, 16 * n));
      const c = mesh.instanceColor;
      if (c) {
        colours ??= new Float32Array(c.array.length);
        colours.set(c.array.subarray(0, 3 * n));
      }
    },
    cull(frustum) {
      const out = mesh.instanceMatrix.array as Float32Array,
        outColours = mesh.instanceColor?.array as Float32Array | undefined;
      let n = 0;
      for (let i = 0; i < placed; i++) {
        m.fromArray(matrices, 16 * i);
        sphere.copy(local).applyMatrix4(m);
        if (!frustum.intersectsSphere(sphere)) continue;
        out.set(matrices.subarray(16 * i, 16 * i + 16), 16 * n);
        if (outColours && colours) outColours.set(colours.subarray(3 * i, 3 * i + 3), 3 * n);
        n++;
      }
      mesh.count = n;
      mesh.instanceMatrix.needsUpdate = true;
      if (mesh.instanceColor) mesh.instanceColor.needsUpdate = true;
    },
  };
}
