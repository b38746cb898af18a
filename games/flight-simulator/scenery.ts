/**
 * The flight simulator's scenery (drawing only, no physics): a sky dome shaded from the haze at the
 * horizon to deep blue overhead with the sun in it, the hills of the scene's terrain function on a
 * grid that follows the aircraft, the sea, and low-poly cumulus clouds fixed in the world (seeded
 * per 2 km cell, so the same clouds are there when the aircraft comes back) that the aircraft flies
 * past and through, so its speed shows.
 */

import { terrainHeight } from '@bitphysics/projects';
import {
  BackSide,
  type BufferAttribute,
  BufferGeometry,
  CircleGeometry,
  Color,
  Float32BufferAttribute,
  Fog,
  IcosahedronGeometry,
  Mesh,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshStandardMaterial,
  PlaneGeometry,
  type Scene,
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

/** Terrain grid: side, m, and cells a side. */
const SIZE = 24_000,
  SEGMENTS = 160;
/** Cloud cells: side, m; clouds are kept within CLOUD_REACH cells of the aircraft's cell. */
const CLOUD_CELL = 2000,
  CLOUD_REACH = 5;

/** A well-mixed 32-bit hash of an integer cell (i, j) and a salt. */
function hash(i: number, j: number, salt: number): number {
  let h = Math.imul(i, 0x27d4eb2d) ^ Math.imul(j, 0x165667b1) ^ Math.imul(salt, 0x9e3779b1);
  h = Math.imul(h ^ (h >>> 15), 0x85ebca6b);
  h = Math.imul(h ^ (h >>> 13), 0xc2b2ae35);
  return (h ^ (h >>> 16)) >>> 0;
}

/** The scenery of one page: call `update` every frame with the camera's and the aircraft's positions. */
export interface Scenery {
  /** Moves the sky with the camera and rebuilds the terrain and clouds when the aircraft has moved far. */
  update(camera: Vector3, aircraft: Vector3): void;
  /** Uses the terrain of a new world (the aircraft scene's `terrain`) and its seed for the clouds. */
  setTerrain(terrain: Float64Array, seed: number): void;
  /** Clouds drawn now (for tests): puffs in the merged cloud mesh. */
  cloudPuffs(): number;
}

/** Builds the scenery into `scene` (and sets its fog). */
export function createScenery(scene: Scene): Scenery {
  scene.fog = new Fog(HORIZON_COLOUR, 5000, 17_000);

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
  let puffs = 0;
  const puff = new IcosahedronGeometry(1, 1);

  /** Rebuilds the clouds of the cells within CLOUD_REACH of cell (ci, cj). */
  function rebuildClouds(ci: number, cj: number): void {
    cloudCell = [ci, cj];
    const parts: BufferGeometry[] = [];
    for (let i = ci - CLOUD_REACH; i <= ci + CLOUD_REACH; i++)
      for (let j = cj - CLOUD_REACH; j <= cj + CLOUD_REACH; j++) {
        const h = hash(i, j, seed);
        // About half the cells hold a cloud: 4 to 7 puffs around a base 1,400 to 2,000 m up.
        if ((h & 7) > 3) continue;
        const x0 = (i + ((h >>> 3) & 255) / 256) * CLOUD_CELL,
          z0 = (j + ((h >>> 11) & 255) / 256) * CLOUD_CELL,
          y0 = 1400 + ((h >>> 19) & 63) * 10,
          n = 4 + ((h >>> 25) & 3),
          size = 140 + ((h >>> 27) & 7) * 25;
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
        }
      }
    puffs = parts.length;
    clouds.geometry.dispose();
    clouds.geometry = parts.length > 0 ? mergeGeometries(parts)! : new BufferGeometry();
    for (const p of parts) p.dispose();
  }

  return {
    update(camera, aircraft) {
      sky.position.copy(camera);
      sun.position.copy(sunDir).multiplyScalar(18_000).add(camera);
      glow.position.copy(sunDir).multiplyScalar(18_500).add(camera);
      sun.lookAt(camera);
      glow.lookAt(camera);
      if (!terrainCentre || Math.hypot(aircraft.x - terrainCentre[0], aircraft.z - terrainCentre[1]) > 2000)
        rebuildTerrain(aircraft.x, aircraft.z);
      sea.position.x = aircraft.x;
      sea.position.z = aircraft.z;
      const ci = Math.floor(aircraft.x / CLOUD_CELL),
        cj = Math.floor(aircraft.z / CLOUD_CELL);
      if (!cloudCell || Math.abs(ci - cloudCell[0]) > 1 || Math.abs(cj - cloudCell[1]) > 1) rebuildClouds(ci, cj);
    },
    setTerrain(t, s) {
      terrain = t;
      seed = s;
      terrainCentre = null;
      cloudCell = null;
    },
    cloudPuffs: () => puffs,
  };
}
