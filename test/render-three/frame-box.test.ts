/**
 * frameBox fits the camera to a box's corners, not to its bounding sphere: with margin 1 every corner
 * projects inside the view (normalised device coordinates within [-1, 1]) and the outermost one on
 * its edge (|ndc| >= 0.999; a sphere fit leaves the corners of a flat or long box far inside, which
 * on a tall phone screen drew a scene at a third of the width); with the default margin they are
 * all inside. Tolerance 1e-3: three.js tilts a camera looking straight down by 1e-4 rad to give it an up.
 * Projection is three.js' own (Vector3.project), independent of the fit's arithmetic.
 */
import { PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { frameBox } from '../../packages/render-three/src/index';

function extremes(camera: PerspectiveCamera, min: number[], max: number[]): { inside: boolean; widest: number } {
  camera.updateMatrixWorld();
  let inside = true,
    widest = 0;
  for (let corner = 0; corner < 8; corner++) {
    const p = new Vector3(corner & 1 ? max[0] : min[0], corner & 2 ? max[1] : min[1], corner & 4 ? max[2] : min[2]).project(camera);
    if (!(Math.abs(p.x) <= 1 + 1e-3 && Math.abs(p.y) <= 1 + 1e-3 && p.z < 1)) inside = false;
    widest = Math.max(widest, Math.abs(p.x), Math.abs(p.y));
  }
  return { inside, widest };
}

describe('frameBox', () => {
  const cases: Array<[string, number, number[], number[], number[]]> = [
    ['wide screen, flat ground box', 1280 / 800, [-9, 0, -9], [9, 5, 9], [0.8, 0.75, 1]],
    ['tall phone screen, flat ground box', 390 / 760, [-9, 0, -9], [9, 5, 9], [0.8, 0.75, 1]],
    ['tall phone screen, tower', 390 / 760, [-1, 0, -1], [1, 12, 1], [1, 0.4, 1]],
    ['looking straight down', 1, [-4, 0, -2], [4, 1, 2], [0, 1, 0]],
    ['cube, default direction', 1.5, [-1, -1, -1], [1, 1, 1], [0.9, 0.65, 1.25]],
  ];
  for (const [name, aspect, min, max, direction] of cases) {
    it(`${name}: every corner in view, the outermost on the edge`, () => {
      const camera = new PerspectiveCamera(50, aspect, 0.1, 1000);
      frameBox(camera, null, min, max, { direction, margin: 1 });
      const tight = extremes(camera, min, max);
      expect(tight.inside).toBe(true);
      expect(tight.widest).toBeGreaterThanOrEqual(0.999);
      frameBox(camera, null, min, max, { direction });
      const roomy = extremes(camera, min, max);
      expect(roomy.inside).toBe(true);
      expect(roomy.widest).toBeLessThan(0.95);
    });
  }
});
