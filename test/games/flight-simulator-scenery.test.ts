// The flight simulator's scenery (games/flight-simulator/scenery.ts) in node: three.js builds its
// meshes without WebGL, so the triangles each level of detail draws are counted from its geometry.

import { createPhysicsWorld } from '@bitphysics/physics';
import { aircraft } from '@bitphysics/projects';
import { type BufferGeometry, type Fog, InstancedMesh, Mesh, Scene, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { createScenery, SCENERY_DETAIL, type SceneryDetail } from '../../games/flight-simulator/scenery';

/** Triangles a mesh's geometry draws: indexed or not, times its instances drawn. */
function triangles(g: BufferGeometry, instances: number): number {
  const vertices = g.index ? g.index.count : (g.attributes.position?.count ?? 0);
  return (vertices / 3) * instances;
}

/** The scenery at `detail` round the aircraft's start (0, 900, 0), seed 1: every visible mesh's triangles, and the fog. */
function build(detail: Readonly<SceneryDetail>): { triangles: number; fog: Fog; trees: number; puffs: number } {
  const world = createPhysicsWorld(aircraft.worldOptions());
  const h = aircraft.build(world, { seed: 1, altitude: 900 });
  const scene = new Scene();
  const scenery = createScenery(scene, detail);
  scenery.setTerrain(h.terrain, 1);
  scenery.update(new Vector3(-58, 918, 0), new Vector3(0, 900, 0));
  let n = 0;
  scene.traverse((o) => {
    if (!o.visible) return;
    if (o instanceof InstancedMesh) n += triangles(o.geometry, o.count);
    else if (o instanceof Mesh) n += triangles(o.geometry, 1);
  });
  const { trees, puffs } = scenery.counts();
  return { triangles: n, fog: scene.fog as Fog, trees, puffs };
}

describe('flight simulator scenery', () => {
  it("a phone's light scenery draws under half the full scenery's triangles, and its haze hides the terrain's edge", () => {
    const full = build(SCENERY_DETAIL.full),
      light = build(SCENERY_DETAIL.light);
    // Measured 144,000 and 64,000 triangles (the renderer's count in the page says the same).
    expect(full.triangles).toBeGreaterThan(120_000);
    expect(light.triangles).toBeLessThan(0.5 * full.triangles);
    expect(light.trees).toBeGreaterThan(300);
    expect(light.puffs).toBeGreaterThan(50);
    for (const [detail, built] of [
      [SCENERY_DETAIL.full, full],
      [SCENERY_DETAIL.light, light],
    ] as const) {
      expect(built.fog.far).toBe(detail.fogFar);
      // The clouds reach past the haze's start, so none pops into clear air.
      expect(detail.cloudReach * 2000).toBeGreaterThanOrEqual(detail.fogNear);
    }
    // The terrain grid (24 km a side) is laid again once the aircraft is 2 km from its centre: its
    // nearest edge is then 10 km away, inside the light scenery's haze (the full one's shows the sea beyond it).
    expect(SCENERY_DETAIL.light.fogFar).toBeLessThanOrEqual(24_000 / 2 - 2000);
  });
});
