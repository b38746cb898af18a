/**
 * rotating-cube's hint mark (games/rotating-cube/hint-mark.ts): the tile the route starts on stays in
 * sight when the cube stands on the cell in front of it. Sight lines are cast with three.js from the
 * room's camera (the default view, direction (0, 2.2, 1): about 65 degrees down, and the lowest the
 * orbit allows, 80 degrees from straight down) at a 1 m cube one cell nearer the camera than the tile.
 */
import { BoxGeometry, Mesh, MeshBasicMaterial, PerspectiveCamera, Raycaster, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { createHintMark, HINT_PIN_HEIGHT } from '../../games/rotating-cube/hint-mark';

/** The tile ringed, (x, z), m, and a 1 m cube resting on the cell in front of it (+z, towards the camera). */
const TILE: [number, number] = [-1.8, 1.1];
const cube = new Mesh(new BoxGeometry(1, 1, 1), new MeshBasicMaterial());
cube.position.set(TILE[0], 0.5, TILE[1] + 1);
cube.updateMatrixWorld(true);

/** A camera `distance` m from the room's centre along `direction`, looking at the centre. */
function cameraAt(direction: [number, number, number], distance = 9): PerspectiveCamera {
  const camera = new PerspectiveCamera(45, 1.6, 0.1, 100);
  camera.position
    .set(...direction)
    .normalize()
    .multiplyScalar(distance);
  camera.lookAt(0, 0, 0);
  camera.updateMatrixWorld(true);
  return camera;
}

/** Whether the cube stands between `camera` and world point `p` (the sight line meets it short of p). */
function hidden(camera: PerspectiveCamera, p: Vector3): boolean {
  const from = camera.position.clone();
  const ray = new Raycaster(from, p.clone().sub(from).normalize());
  const hit = ray.intersectObject(cube)[0];
  return !!hit && hit.distance < from.distanceTo(p) - 1e-6;
}

describe('rotating cube hint mark', () => {
  const mark = createHintMark(0xffe27a);
  const views: [string, [number, number, number]][] = [
    ['default view', [0, 2.2, 1]],
    // 80 degrees from straight down: the lowest the room's orbit goes (main.ts clampOrbit).
    ['lowest orbit', [0, Math.cos((80 * Math.PI) / 180), Math.sin((80 * Math.PI) / 180)]],
  ];

  it('the ring alone is hidden by the cube in front of its tile; the pin over it is not, from either view', () => {
    for (const [name, dir] of views) {
      const camera = cameraAt(dir);
      mark.place(TILE, 0, camera.quaternion);
      mark.group.updateMatrixWorld(true);
      // The ring's near edge (0.35 m from its centre towards the camera): behind the cube. This is what a stranger saw.
      expect(hidden(camera, new Vector3(TILE[0], 0.035, TILE[1] + 0.35)), name).toBe(true);
      // The pin's tip is in sight over the cube.
      const tip = mark.pin.getWorldPosition(new Vector3());
      expect(tip.x).toBeCloseTo(TILE[0], 9);
      expect(tip.z).toBeCloseTo(TILE[1], 9);
      expect(tip.y).toBeGreaterThanOrEqual(HINT_PIN_HEIGHT);
      expect(hidden(camera, tip), name).toBe(false);
    }
  });

  it('the ring is drawn a second time through the cube (depth test off); null hides the mark; the pin bobs over the cube top', () => {
    const through = mark.ringThrough.material as MeshBasicMaterial;
    expect(through.depthTest).toBe(false);
    expect((mark.ring.material as MeshBasicMaterial).depthTest).toBe(true);
    const heights: number[] = [];
    for (let t = 0; t < 2; t += 0.05) {
      mark.place([0.2, -0.8], t);
      heights.push(mark.pin.position.y);
    }
    // Over a 1 m cube's top by 0.3 m at its lowest, and it moves (about 0.12 m) so the eye catches it.
    expect(Math.min(...heights)).toBeGreaterThan(1.25);
    expect(Math.max(...heights) - Math.min(...heights)).toBeGreaterThan(0.1);
    expect(mark.group.visible).toBe(true);
    expect([mark.group.position.x, mark.group.position.z]).toEqual([0.2, -0.8]);
    mark.place(null, 0);
    expect(mark.group.visible).toBe(false);
  });
});
