/**
 * Earth and Moon: the two bodies orbit their barycentre under Newtonian gravity in SI units (G, kg,
 * m, s), the Earth spinning under a cloud layer, the Moon tidally locked; trails trace the orbits.
 * Textures (continents, oceans, ice, clouds, maria and craters) are generated in code from seeded noise.
 *
 * Scale: one scene unit is 10 000 km (`unitsPerMeter` 1e-7). Time: the panel's time scale is in
 * simulated days per real second; each frame's step is split into substeps of at most 10 minutes.
 * Bodies can be drawn larger than life (the orbit stays true).
 * Keys: P pause, N single step, R reset, T trails, F camera follow (barycentre / Earth / Moon),
 * [ and ] slower / faster. Drag orbits the camera, the wheel zooms.
 * URL: ?timeScale=days-per-second (0..30), ?follow=barycentre|earth|moon, ?size=1..20, ?trails=0|1, ?texture=256..2048.
 */

import { choiceParam, createPanel, flagParam, numberParam, pageLayout } from '@bitphysics/game-kit';
import { ORBIT_CONTROLS, startThreeGame } from '@bitphysics/game-kit/three';
import { createPhysicsWorld, type PhysicsWorld, step, totalEnergy } from '@bitphysics/physics';
import {
  AdditiveBlending,
  BackSide,
  BufferAttribute,
  BufferGeometry,
  CanvasTexture,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Points,
  PointsMaterial,
  SphereGeometry,
  SRGBColorSpace,
  Vector3,
} from 'three';
import {
  buildEarthMoon,
  configureStep,
  DAY,
  distance,
  EARTH_RADIUS,
  type EarthMoonHandles,
  earthMoonWorldOptions,
  MOON_RADIUS,
  MOON_SEMI_MAJOR_AXIS,
} from './scene';
import { cloudPixels, earthPixels, moonPixels, toCanvas } from './textures';

/** Real seconds a step of the game loop stands for (the loop runs at 60 Hz). */
const TICK = 1 / 60;
/** Scene units per metre: one unit is 10 000 km. */
const UNITS_PER_METER = 1e-7;
const FOLLOW = ['barycentre', 'earth', 'moon'] as const;
type Follow = (typeof FOLLOW)[number];

const search = new URLSearchParams(location.search);
const params = {
  timeScale: numberParam('timeScale', { default: 2, min: 0, max: 30 }),
  trails: search.has('trails') ? flagParam('trails') : true,
  follow: choiceParam('follow', FOLLOW, 'barycentre') as Follow,
  size: numberParam('size', { default: 5, min: 1, max: 20 }),
  reset: () => game.shell.reset(),
};
const textureWidth = numberParam('texture', { default: 768, min: 256, max: 2048, integer: true });

let handles: EarthMoonHandles;

/** A fresh world with the Earth and the Moon at perigee (the shell calls it at start and on R). */
function createWorld(): PhysicsWorld {
  const world = createPhysicsWorld(earthMoonWorldOptions(TICK));
  handles = buildEarthMoon(world);
  return world;
}

/** One loop step: TICK real seconds of the time scale, in substeps (nothing when the time scale is 0). */
function stepWorld(world: PhysicsWorld): void {
  if (configureStep(world, params.timeScale * DAY, TICK)) step(world);
}

/** Trails: a point every 1600 km, 1500 points (about one orbit of the Moon). */
const TRAILS = { length: 1500, maxEntities: 4, spacing: 1.6e6, alpha: 0.8 };

// Textures are made before the first frame (about a second of noise at the default size).
const earthMap = new CanvasTexture(toCanvas(earthPixels(textureWidth, textureWidth / 2)));
const cloudMap = new CanvasTexture(toCanvas(cloudPixels(Math.min(1024, textureWidth), Math.min(1024, textureWidth) / 2)));
const moonMap = new CanvasTexture(toCanvas(moonPixels(Math.min(512, textureWidth / 2), Math.min(512, textureWidth / 2) / 2)));
for (const t of [earthMap, cloudMap, moonMap]) {
  t.colorSpace = SRGBColorSpace;
  t.anisotropy = 4;
}
const sphere = new SphereGeometry(1, 64, 40);
const earthMaterial = new MeshStandardMaterial({ map: earthMap, roughness: 0.85, metalness: 0 });
const moonMaterial = new MeshStandardMaterial({ map: moonMap, roughness: 0.95, metalness: 0 });

const game = await startThreeGame({
  title: 'Earth and Moon',
  createWorld,
  step: stepWorld,
  bodies: () => 2,
  controls: [
    ...ORBIT_CONTROLS,
    { keys: '[ ]', action: 'slower / faster' },
    { keys: 'F', action: 'camera follows: barycentre, Earth, Moon' },
    { keys: 'T', action: 'trails on / off' },
  ],
  keys: [
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: 'f', label: 'follow', action: () => setFollow(FOLLOW[(FOLLOW.indexOf(params.follow) + 1) % FOLLOW.length]!) },
    { key: '[', label: 'slower', action: () => setTimeScale(params.timeScale / 1.5), repeat: true },
    { key: ']', label: 'faster', action: () => setTimeScale(params.timeScale === 0 ? 0.25 : params.timeScale * 1.5), repeat: true },
  ],
  app: { background: 0x03050a, shadows: false, controls: { minDistance: 0.3, maxDistance: 400 }, cameraPosition: [0, 30, 70] },
  renderer: {
    unitsPerMeter: UNITS_PER_METER,
    boundary: 'none',
    shadows: false,
    // Sunlight from +x; almost no fill, so the night sides and the Moon's phases show.
    lights: { direction: [1, 0.08, 0.25], intensity: 3, hemisphereIntensity: 0.06, ambientIntensity: 0.03, shadows: false },
    trails: params.trails ? TRAILS : false,
  },
  view: { min: [-4.3e8, -0.5e8, -4.3e8], max: [4.3e8, 0.5e8, 4.3e8] },
  viewDirection: [0.35, 0.55, 1],
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;

/** Gives the bodies of `world` their textured looks and trail colours. */
function dress(): void {
  renderer.setShape(handles.earth, { geometry: sphere, material: earthMaterial, scale: EARTH_RADIUS * params.size });
  renderer.setShape(handles.moon, { geometry: sphere, material: moonMaterial, scale: MOON_RADIUS * params.size });
  renderer.setColor(handles.earth, 0x5aa9ff);
  renderer.setColor(handles.moon, 0xd8dde8);
}
dress();
shell.onWorldChange(() => dress());

// Clouds: a slightly larger sphere that follows where the Earth was drawn (position and orientation).
const clouds = new Mesh(sphere, new MeshStandardMaterial({ map: cloudMap, transparent: true, depthWrite: false, roughness: 1 }));
// A thin additive halo for the atmosphere, seen around the limb.
const halo = new Mesh(
  sphere,
  new MeshBasicMaterial({
    color: 0x4d9bff,
    transparent: true,
    opacity: 0.07,
    side: BackSide,
    blending: AdditiveBlending,
    depthWrite: false,
  }),
);
app.scene.add(clouds, halo);

// A seeded star field far away (a fixed sphere of points around the origin).
{
  const n = 2500,
    positions = new Float32Array(n * 3);
  let s = 12345;
  const rand = (): number => {
    s = (Math.imul(s, 1103515245) + 12345) >>> 0;
    return s / 4294967296;
  };
  for (let i = 0; i < n; i++) {
    const u = rand() * 2 - 1,
      phi = rand() * 2 * Math.PI,
      r = Math.sqrt(1 - u * u),
      d = 1500;
    positions[3 * i] = r * Math.cos(phi) * d;
    positions[3 * i + 1] = u * d;
    positions[3 * i + 2] = r * Math.sin(phi) * d;
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(positions, 3));
  const stars = new Points(geometry, new PointsMaterial({ color: 0xcfd8ff, size: 1.4, sizeAttenuation: false }));
  stars.frustumCulled = false;
  app.scene.add(stars);
}
// Near enough to zoom in on the Earth, far enough for the stars (1500 units out).
app.camera.near = 0.05;
app.camera.far = 4000;
app.camera.updateProjectionMatrix();

// ---- Camera follow, clouds and the readout, every frame --------------------------------------

const followed = new Vector3(),
  lastFollowed = new Vector3();
const p3 = [0, 0, 0],
  q4 = [0, 0, 0, 1];
let followReset = true;

// Names beside the bodies, with a dot of the body's colour while it is drawn under 4 px across: at
// the scale of the Moon's orbit the Moon is a speck a player could not find.
const nameLayer = document.createElement('div');
nameLayer.dataset.sceneOverlay = '';
nameLayer.style.cssText =
  'position: absolute; inset: 0; pointer-events: none; z-index: 5; font: 13px system-ui, sans-serif; color: #e6ecff';
pageLayout().stage.append(nameLayer);
const names = (['Earth', 'Moon'] as const).map((name) => {
  const dot = document.createElement('div');
  dot.dataset.dot = name;
  const colour = name === 'Earth' ? '#5aa9ff' : '#d8dde8';
  dot.style.cssText = `position: absolute; width: 6px; height: 6px; margin: -3px 0 0 -3px; border-radius: 50%; background: ${colour}; box-shadow: 0 0 5px ${colour}`;
  const label = document.createElement('div');
  label.dataset.label = name;
  label.textContent = name;
  label.style.cssText =
    'position: absolute; transform: translate(8px, -50%); padding: 0 4px; border-radius: 3px; background: rgba(8, 10, 16, 0.7)';
  nameLayer.append(dot, label);
  return { name, dot, label };
});
const projected = new Vector3();
/** Places the names (and dots) over the bodies' drawn places. */
function placeNames(): void {
  const k = UNITS_PER_METER;
  const w = app.canvas.clientWidth,
    h = app.canvas.clientHeight;
  for (const n of names) {
    const body = n.name === 'Earth' ? handles.earth : handles.moon;
    const shown = renderer.drawnPosition(body, p3) !== null;
    if (shown) projected.set(p3[0]! * k, p3[1]! * k, p3[2]! * k);
    const distance = projected.distanceTo(app.camera.position);
    if (shown) projected.project(app.camera);
    const visible = shown && projected.z < 1 && Math.abs(projected.x) < 1.05 && Math.abs(projected.y) < 1.05;
    const x = ((projected.x + 1) / 2) * w,
      y = ((1 - projected.y) / 2) * h;
    const radius = (n.name === 'Earth' ? EARTH_RADIUS : MOON_RADIUS) * params.size * k;
    const px = (radius * h) / (2 * distance * Math.tan((app.camera.fov * Math.PI) / 360));
    n.dot.style.display = visible && px < 2 ? 'block' : 'none';
    n.label.style.display = visible ? 'block' : 'none';
    if (!visible) continue;
    n.dot.style.left = n.label.style.left = `${x}px`;
    n.dot.style.top = n.label.style.top = `${y}px`;
    n.label.style.transform = `translate(${Math.max(8, px + 4)}px, -50%)`;
  }
}

/** Per frame: clouds on the Earth, the camera target on the followed body, the names, the readout. */
function frame(): void {
  const k = UNITS_PER_METER;
  if (renderer.drawnPosition(handles.earth, p3) && renderer.drawnOrientation(handles.earth, q4)) {
    const r = EARTH_RADIUS * params.size * k;
    clouds.position.set(p3[0]! * k, p3[1]! * k, p3[2]! * k);
    clouds.quaternion.set(q4[0]!, q4[1]!, q4[2]!, q4[3]!);
    clouds.scale.setScalar(r * 1.012);
    halo.position.copy(clouds.position);
    halo.scale.setScalar(r * 1.035);
  }
  if (params.follow === 'barycentre') followed.set(0, 0, 0);
  else if (renderer.drawnPosition(params.follow === 'earth' ? handles.earth : handles.moon, p3))
    followed.set(p3[0]! * k, p3[1]! * k, p3[2]! * k);
  const controls = app.controls;
  if (controls) {
    if (followReset) {
      // Jump: keep the viewing direction, pick a distance that suits the followed body.
      followReset = false;
      const dir = app.camera.position.clone().sub(controls.target).normalize();
      const dist =
        params.follow === 'barycentre'
          ? 2.3 * MOON_SEMI_MAJOR_AXIS * k
          : (params.follow === 'earth' ? 9 * EARTH_RADIUS : 12 * MOON_RADIUS) * params.size * k;
      controls.target.copy(followed);
      app.camera.position.copy(followed).addScaledVector(dir, dist);
    } else {
      // Carry the camera along with the followed body (the user still orbits and zooms around it).
      app.camera.position.add(lastFollowed.subVectors(followed, controls.target));
      controls.target.copy(followed);
    }
  }
  lastFollowed.copy(followed);
  placeNames();
  updateReadout();
}

/** Sets the followed body and jumps the camera to it. */
function setFollow(follow: Follow): void {
  params.follow = follow;
  followReset = true;
  panel.refresh();
}

/** Sets the time scale, days per real second, clamped to [0, 30]. */
function setTimeScale(days: number): void {
  params.timeScale = Math.min(30, Math.max(0, days < 0.01 ? 0 : Math.round(days * 100) / 100));
  panel.refresh();
}

/** Turns the trails on or off. */
function setTrails(on: boolean): void {
  params.trails = on;
  renderer.setTrails(on ? TRAILS : false);
  panel.refresh();
}

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'timeScale', label: 'time scale (days/s)', min: 0, max: 30, step: 0.01 },
    { type: 'checkbox', key: 'trails', label: 'show trails', onChange: (v) => setTrails(v === true) },
    { type: 'choice', key: 'follow', label: 'camera follows', options: FOLLOW, onChange: (v) => setFollow(v as Follow) },
    {
      type: 'slider',
      key: 'size',
      label: 'body size (× true)',
      min: 1,
      max: 20,
      step: 0.5,
      onChange: () => {
        dress();
        followReset = true;
      },
    },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Earth and Moon' },
);

// The readout: elapsed days, Earth-Moon distance, the Moon's speed, the energy drift.
const readout = document.createElement('div');
readout.className = 'bp-hud';
readout.dataset.hud = 'orbit';
const lines = Array.from({ length: 5 }, () => readout.appendChild(document.createElement('div')));
shell.hud.readout.after(readout);
let energy0 = totalEnergy(shell.world);
shell.onWorldChange((w) => {
  energy0 = totalEnergy(w);
});
let readoutFrame = 0;

function updateReadout(): void {
  if (readoutFrame++ % 15 !== 0) return;
  const w = shell.world;
  const V = w.components.Velocity,
    m = handles.moon,
    e = handles.earth;
  const vrel = Math.hypot(V.x[m]! - V.x[e]!, V.y[m]! - V.y[e]!, V.z[m]! - V.z[e]!);
  const drift = (totalEnergy(w) - energy0) / Math.abs(energy0);
  lines[0]!.textContent = `day ${(w.time / DAY).toFixed(2)}`;
  lines[1]!.textContent = `Earth–Moon ${(distance(w, e, m) / 1e3).toFixed(0)} km`;
  lines[2]!.textContent = `Moon speed ${(vrel / 1e3).toFixed(3)} km/s`;
  lines[3]!.textContent = `energy drift ${drift.toExponential(1)}`;
  lines[4]!.textContent = `${params.timeScale} days/s`;
}

// ---- Test and console hooks on window.game ---------------------------------------------------

shell.expose({
  params,
  panel,
  /** The entities: { earth, moon }. */
  bodies: () => ({ earth: handles.earth, moon: handles.moon }),
  /** Earth-Moon distance, m. */
  separation: (): number => distance(shell.world, handles.earth, handles.moon),
  /** Sets the time scale, simulated days per real second (clamped to [0, 30]). */
  setTimeScale,
  /** Sets what the camera follows. @throws RangeError on an unknown name. */
  setFollow: (follow: Follow): void => {
    if (!FOLLOW.includes(follow)) throw new RangeError(`setFollow: follow must be one of ${FOLLOW.join(', ')}, got ${String(follow)}`);
    setFollow(follow);
  },
});
