/**
 * The flight simulator's aircraft model (drawing only): a white fuselage with blue stripes and a
 * red nose, the canopy, wing halves tilted up by the scene's dihedral from a root under the
 * fuselage with red tips, the tailplane and a red fin, merged into one geometry with vertex colours
 * in the body frame of the aircraft scene (x forward, y up, z right; metres).
 */

import { AIRCRAFT } from '@bitphysics/projects';
import { BoxGeometry, type BufferGeometry, ConeGeometry, CylinderGeometry, Float32BufferAttribute } from 'three';
import { mergeGeometries } from 'three/examples/jsm/utils/BufferGeometryUtils.js';

/** A part of the model in one colour (a vertex colour on the merged geometry). */
function painted(g: BufferGeometry, colour: number): BufferGeometry {
  const part = g.toNonIndexed();
  const n = part.attributes.position!.count;
  const r = ((colour >> 16) & 255) / 255,
    gr = ((colour >> 8) & 255) / 255,
    b = (colour & 255) / 255;
  const c = new Float32Array(3 * n);
  for (let i = 0; i < n; i++) c.set([r, gr, b], 3 * i);
  part.setAttribute('color', new Float32BufferAttribute(c, 3));
  return part;
}

/** The aircraft model: one merged geometry with vertex colours, body frame (x forward, y up, z right), metres. */
export function aircraftGeometry(): BufferGeometry {
  const white = 0xf2f4f7,
    red = 0xd8342c,
    blue = 0x1f4e8c,
    glass = 0x1b2a3a;
  const parts: BufferGeometry[] = [];
  const fuselage = new CylinderGeometry(1.3, 1.0, 24, 16);
  fuselage.rotateZ(-Math.PI / 2);
  fuselage.translate(-1, 0, 0);
  parts.push(painted(fuselage, white));
  const stripe = new CylinderGeometry(1.33, 1.2, 14, 16, 1, true, Math.PI * 0.35, Math.PI * 0.3);
  stripe.rotateZ(-Math.PI / 2);
  stripe.translate(1, 0, 0);
  parts.push(painted(stripe, blue), painted(stripe.clone().rotateX(Math.PI), blue));
  const nose = new ConeGeometry(1.3, 4, 16);
  nose.rotateZ(-Math.PI / 2);
  nose.translate(13, 0, 0);
  parts.push(painted(nose, red));
  const canopy = new CylinderGeometry(0.75, 0.75, 4.5, 12, 1, false, 0, Math.PI);
  canopy.rotateZ(-Math.PI / 2);
  canopy.rotateX(-Math.PI / 2);
  canopy.translate(8.5, 0.9, 0);
  parts.push(painted(canopy, glass));
  // Each wing half tilted up by the dihedral from a root under the fuselage.
  const dihedral = AIRCRAFT.dihedral;
  for (const side of [-1, 1]) {
    const half = new BoxGeometry(4, 0.35, 15);
    half.translate(0.5, 0, side * 7.5);
    half.rotateX(side * dihedral);
    half.translate(0, -0.9, 0);
    parts.push(painted(half, white));
    const tip = new BoxGeometry(4.05, 0.4, 1.2);
    tip.translate(0.5, 0, side * 14.4);
    tip.rotateX(side * dihedral);
    tip.translate(0, -0.9, 0);
    parts.push(painted(tip, red));
  }
  const tail = new BoxGeometry(2.6, 0.25, 10);
  tail.translate(-12, 0.3, 0);
  parts.push(painted(tail, white));
  const fin = new BoxGeometry(3, 5, 0.3);
  fin.translate(-12, 2.8, 0);
  parts.push(painted(fin, red));
  return mergeGeometries(parts)!;
}
