/**
 * Solar system: the book's closing project (Ramtal and Dobre ch. 16) against a real ephemeris. The
 * Sun and the eight planets (Earth as the Earth-Moon barycentre) attract each other; they start from
 * astronomy-engine's positions and velocities at the chosen date and are integrated with the world's
 * scheme at the chosen step (default RK4, 1 hour). A table compares each planet with the ephemeris
 * as the simulation runs: |r - r_ephemeris| / |r_ephemeris|, heliocentric.
 *
 * Units: AU, days, solar masses (the scene's; see packages/projects/src/solar-system.ts). One
 * scene unit is 0.1 AU. Time: the rate is simulated days per real second; each loop tick runs as many
 * steps of the chosen size as the rate needs.
 * Keys: P pause, N single step, R reset, [ ] slower / faster, T trails, E exaggerated sizes.
 * URL: ?rate=days-per-second (0..400), ?step=hours (0.25|1|6|24), ?integrator=name, ?date=ISO date.
 */

import { choiceParam, createPanel, flagParam, numberParam, pageLayout } from '@bitphysics/game-kit';
import { ORBIT_CONTROLS, startThreeGame } from '@bitphysics/game-kit/three';
import { createPhysicsWorld, INTEGRATOR_NAMES, type IntegratorName, type PhysicsWorld, Rng, slotOf, step } from '@bitphysics/physics';
import {
  SOLAR_SYSTEM_BODIES,
  SOLAR_SYSTEM_EPOCH,
  SOLAR_SYSTEM_FLOOR,
  SOLAR_SYSTEM_PLANETS,
  type SolarSystemHandles,
  solarSystem,
  solarSystemErrors,
} from '@bitphysics/projects';
import {
  AdditiveBlending,
  BufferGeometry,
  CanvasTexture,
  Float32BufferAttribute,
  Group,
  type Line,
  LineBasicMaterial,
  LineLoop,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  PointLight,
  Points,
  PointsMaterial,
  SphereGeometry,
  Sprite,
  SpriteMaterial,
  Vector3,
} from 'three';

/** Scene units per AU. */
const UNITS_PER_AU = 10;
const STEPS = ['0.25', '1', '6', '24'] as const;
/** Mean radii, AU (IAU), for true-size drawing. */
const RADIUS_AU: Record<string, number> = {
  Sun: 4.652e-3,
  Mercury: 1.631e-5,
  Venus: 4.045e-5,
  Earth: 4.259e-5,
  Mars: 2.266e-5,
  Jupiter: 4.673e-4,
  Saturn: 3.893e-4,
  Uranus: 1.695e-4,
  Neptune: 1.646e-4,
};
const COLOR: Record<string, number> = {
  Sun: 0xffd27a,
  Mercury: 0xb5a89a,
  Venus: 0xe8cf94,
  Earth: 0x4f8fe8,
  Mars: 0xd0643c,
  Jupiter: 0xd9b38c,
  Saturn: 0xe6d19a,
  Uranus: 0x9fd8e0,
  Neptune: 0x5a78e0,
};

const params = {
  rate: numberParam('rate', { default: 30, min: 0, max: 400 }),
  step: choiceParam('step', STEPS, '1'),
  integrator: choiceParam('integrator', INTEGRATOR_NAMES, 'rk4') as IntegratorName,
  date: new URLSearchParams(location.search).get('date') ?? SOLAR_SYSTEM_EPOCH.slice(0, 10),
  exaggerate: new URLSearchParams(location.search).has('exaggerate') ? flagParam('exaggerate') : true,
  trails: new URLSearchParams(location.search).has('trails') ? flagParam('trails') : true,
  reset: () => game.shell.reset(),
  /** Frames Mercury to Mars (key 1). */
  inner: () => frameView(INNER_VIEW),
  /** Frames all eight planets (key 2). */
  all: () => frameView(ALL_VIEW),
};

/** Half-widths of the two framings, AU: Mars' orbit (1.67 AU at aphelion) and Neptune's (30.3 AU) with a small margin. */
const INNER_VIEW = 1.8;
/** The camera looks along this, steep enough that the orbits read as near circles. */
const VIEW_DIRECTION: [number, number, number] = [0.15, 1, 0.7];
const ALL_VIEW = 31;

let handles: SolarSystemHandles;
let carry = 0;

/** A fresh world from the ephemeris at params.date with the chosen scheme and step. */
function createWorld(): PhysicsWorld {
  const options = { stepHours: Number(params.step), integrator: params.integrator, date: `${params.date}T00:00:00Z` };
  const world = createPhysicsWorld(solarSystem.worldOptions(options));
  handles = solarSystem.build(world, options);
  carry = 0;
  return world;
}

/** Real seconds a loop tick stands for (the loop is set to 60 Hz, whatever the world's step in days). */
const TICK = 1 / 60;

/** One loop tick: `rate` days a second need rate TICK / dt steps of dt days a tick; the fraction carries over. */
function stepWorld(world: PhysicsWorld): void {
  carry += (params.rate * TICK) / world.dt;
  const n = Math.min(2000, Math.floor(carry));
  carry -= n;
  for (let i = 0; i < n; i++) step(world);
}

const TRAILS = { length: 600, maxEntities: 9, spacing: 0.02, alpha: 0.7 };

/** Labels placed this frame: left, centre y, right (px) and a spare, four numbers each. */
const placed: number[] = [];
/** Labels the last frame showed. */
let shownLabels = 0;

const game = await startThreeGame({
  title: 'Solar system',
  createWorld,
  step: stepWorld,
  bodies: () => SOLAR_SYSTEM_BODIES.length,
  controls: [
    ...ORBIT_CONTROLS,
    { keys: '[ ]', action: 'slower / faster' },
    { keys: 'T', action: 'trails on / off' },
    { keys: 'E', action: 'exaggerated sizes on / off' },
    { keys: '1 2', action: 'inner planets / all eight' },
  ],
  keys: [
    { key: '[', label: 'slower', action: () => setRate(params.rate / 1.5), repeat: true },
    { key: ']', label: 'faster', action: () => setRate(params.rate === 0 ? 1 : params.rate * 1.5), repeat: true },
    { key: 't', label: 'trails', action: () => setTrails(!params.trails) },
    { key: '1', label: 'inner', action: () => frameView(INNER_VIEW) },
    { key: '2', label: 'all', action: () => frameView(ALL_VIEW) },
    {
      key: 'e',
      label: 'sizes',
      action: () => {
        params.exaggerate = !params.exaggerate;
        dress();
        panel.refresh();
      },
    },
  ],
  app: { background: 0x020308, shadows: false, controls: { minDistance: 0.5, maxDistance: 1500 }, cameraPosition: [0, 60, 90] },
  renderer: {
    unitsPerMeter: UNITS_PER_AU,
    boundary: 'none',
    shadows: false,
    lights: { direction: [0, 1, 0], intensity: 0.2, hemisphereIntensity: 0.25, ambientIntensity: 0.25, shadows: false },
    trails: params.trails ? TRAILS : false,
  },
  // All eight planets at start (Neptune's orbit fits; the orbit lines show where each goes); 1 zooms
  // to the inner planets.
  view: { min: [-ALL_VIEW, -0.2, -ALL_VIEW], max: [ALL_VIEW, 0.2, ALL_VIEW] },
  viewDirection: VIEW_DIRECTION,
  onFrame: () => frame(),
});
const { shell, renderer, app } = game;
// The loop ticks at 60 Hz of real time; the world's dt is the physical step in days.
shell.loop.setTimeStep(TICK);
shell.onWorldChange(() => shell.loop.setTimeStep(TICK));
app.scene.add(new PointLight(0xfff2d0, 3, 0, 0));
app.camera.far = 5000;
app.camera.updateProjectionMatrix();

/**
 * The sky: STAR_COUNT stars on a sphere of STAR_SKY_RADIUS scene units (beyond the farthest the
 * camera goes, inside its far plane), a third of them crowded towards a tilted band like the Milky
 * Way, white to pale blue and gold, drawn a pixel or two wide whatever the zoom. Fixed (seeded).
 */
const STAR_COUNT = 3000,
  STAR_SKY_RADIUS = 3000;
{
  const rng = new Rng(2012);
  const pos = new Float32Array(3 * STAR_COUNT),
    col = new Float32Array(3 * STAR_COUNT);
  const tilt = 1.05;
  for (let i = 0; i < STAR_COUNT; i++) {
    let x = rng.normal(),
      y = rng.normal(),
      z = rng.normal();
    if (i % 3 === 0) y *= 0.08; // the band: squashed towards the plane y = 0, then tilted
    const n = Math.hypot(x, y, z) || 1;
    x /= n;
    y /= n;
    z /= n;
    const ty = y * Math.cos(tilt) - z * Math.sin(tilt),
      tz = y * Math.sin(tilt) + z * Math.cos(tilt);
    pos.set([x * STAR_SKY_RADIUS, ty * STAR_SKY_RADIUS, tz * STAR_SKY_RADIUS], 3 * i);
    const b = 0.35 + 0.65 * rng.next() ** 3,
      hue = rng.next();
    col.set(hue < 0.2 ? [b, b * 0.9, b * 0.7] : hue < 0.4 ? [b * 0.8, b * 0.9, b] : [b, b, b], 3 * i);
  }
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new Float32BufferAttribute(pos, 3));
  geometry.setAttribute('color', new Float32BufferAttribute(col, 3));
  app.scene.add(new Points(geometry, new PointsMaterial({ size: 1.6, sizeAttenuation: false, vertexColors: true, depthWrite: false })));
}

/** The Sun's glow: an additive sprite of a radial gradient, following the Sun, a few times its drawn size. */
const sunGlow = (() => {
  const c = document.createElement('canvas');
  c.width = c.height = 128;
  const g = c.getContext('2d')!;
  const grad = g.createRadialGradient(64, 64, 0, 64, 64, 64);
  grad.addColorStop(0, 'rgba(255, 244, 214, 0.9)');
  grad.addColorStop(0.25, 'rgba(255, 200, 110, 0.35)');
  grad.addColorStop(1, 'rgba(255, 150, 60, 0)');
  g.fillStyle = grad;
  g.fillRect(0, 0, 128, 128);
  const sprite = new Sprite(
    new SpriteMaterial({ map: new CanvasTexture(c), blending: AdditiveBlending, depthWrite: false, transparent: true }),
  );
  app.scene.add(sprite);
  return sprite;
})();

const sphere = new SphereGeometry(1, 32, 20);
const materials = Object.fromEntries(
  SOLAR_SYSTEM_BODIES.map((b) => [
    b,
    b === 'Sun'
      ? new MeshBasicMaterial({ color: COLOR[b] })
      : new MeshStandardMaterial({ color: COLOR[b], roughness: 0.8, emissive: COLOR[b], emissiveIntensity: 0.25 }),
  ]),
);

/**
 * Drawn radius of a body, AU: the true radius, or exaggerated so every body shows at the scale of
 * the orbits (planets 0.03 AU + 150 times their radius, keeping the giants larger; the Sun 20 times).
 */
function drawnRadius(name: string): number {
  const r = RADIUS_AU[name]!;
  if (!params.exaggerate) return r;
  return name === 'Sun' ? 20 * r : 0.03 + 150 * r;
}

/** Body sizes (see drawnRadius) and colours. */
function dress(): void {
  for (const name of SOLAR_SYSTEM_BODIES) {
    const r = drawnRadius(name);
    renderer.setShape(handles.bodies[name], { geometry: sphere, material: materials[name]!, scale: r });
    renderer.setColor(handles.bodies[name], COLOR[name]!);
  }
}
dress();
shell.onWorldChange(() => dress());

// Saturn's rings: a flat disc that follows Saturn.
const rings = new Mesh(new SphereGeometry(1, 32, 4), new MeshBasicMaterial({ color: 0xcdb98a, transparent: true, opacity: 0.5 }));
app.scene.add(rings);

/**
 * Frames the Sun and the orbits out to `half` AU, from the start's direction. The box is 5 % of
 * `half` thick either side of the ecliptic: the planets' inclinations lift them up to 0.93 AU
 * (Neptune: 1.77 deg at 30 AU) above it, and the camera fits the box's corners.
 */
function frameView(half: number): void {
  const k = UNITS_PER_AU;
  const thick = 0.05 * half;
  app.frame([-half * k, -thick * k, -half * k], [half * k, thick * k, half * k], VIEW_DIRECTION);
}

// ---- Orbit lines: each planet's Kepler ellipse about the Sun from its state at the start ----------

const orbitLines = new Group();
app.scene.add(orbitLines);
/** Points a drawn orbit. */
const ORBIT_POINTS = 256;

/**
 * Redraws every planet's orbit: the two-body (Sun and planet) Kepler ellipse through its position and
 * velocity now, mu = G (M_sun + m) (AU^3/day^2), from the eccentricity vector e = (v x h) / mu - r / |r|
 * and the semi-major axis a = 1 / (2 / |r| - |v|^2 / mu) (vis-viva): r(f) = a (1 - e^2) / (1 + e cos f)
 * around the focus at the Sun, in the orbit's plane. The giants' pull makes the real paths wander a
 * little from these ellipses over the years.
 */
function drawOrbits(world: PhysicsWorld): void {
  for (const line of orbitLines.children) (line as Line).geometry.dispose();
  orbitLines.clear();
  const c = world.components,
    G = world.laws.gravitationalConstant,
    sun = slotOf(handles.bodies.Sun),
    k = UNITS_PER_AU;
  for (const name of SOLAR_SYSTEM_PLANETS) {
    const e = slotOf(handles.bodies[name]);
    const r = new Vector3(
      c.Position.x[e]! - c.Position.x[sun]!,
      c.Position.y[e]! - c.Position.y[sun]!,
      c.Position.z[e]! - c.Position.z[sun]!,
    );
    const u = new Vector3(
      c.Velocity.x[e]! - c.Velocity.x[sun]!,
      c.Velocity.y[e]! - c.Velocity.y[sun]!,
      c.Velocity.z[e]! - c.Velocity.z[sun]!,
    );
    const mu = G * (c.Mass.value[sun]! + c.Mass.value[e]!);
    const h = new Vector3().crossVectors(r, u);
    const ecc = new Vector3().crossVectors(u, h).divideScalar(mu).sub(r.clone().divideScalar(r.length()));
    const a = 1 / (2 / r.length() - u.lengthSq() / mu);
    const en = ecc.length();
    if (!(a > 0) || !(en < 1)) continue;
    // Orbit frame: p toward the perihelion (or along r for a circle), q = h x p.
    const p = en > 1e-9 ? ecc.clone().normalize() : r.clone().normalize();
    const q = new Vector3().crossVectors(h, p).normalize();
    const pts: number[] = [];
    for (let i = 0; i < ORBIT_POINTS; i++) {
      const f = (2 * Math.PI * i) / ORBIT_POINTS;
      const rr = (a * (1 - en * en)) / (1 + en * Math.cos(f));
      const x = rr * Math.cos(f),
        y = rr * Math.sin(f);
      pts.push(
        (c.Position.x[sun]! + x * p.x + y * q.x) * k,
        (c.Position.y[sun]! + x * p.y + y * q.y) * k,
        (c.Position.z[sun]! + x * p.z + y * q.z) * k,
      );
    }
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(pts, 3));
    orbitLines.add(new LineLoop(geometry, new LineBasicMaterial({ color: COLOR[name], transparent: true, opacity: 0.45 })));
  }
}
drawOrbits(shell.world);
shell.onWorldChange((world) => drawOrbits(world));

// ---- Labels, date and the error table ---------------------------------------------------------

const labelLayer = document.createElement('div');
labelLayer.style.cssText =
  'position: absolute; inset: 0; pointer-events: none; z-index: 5; font: 12px system-ui, sans-serif; color: #dfe7ff';
// Over the canvas (in the layout's stage): the labels are part of the scene.
labelLayer.dataset.sceneOverlay = '';
pageLayout().stage.append(labelLayer);
const labels = Object.fromEntries(
  SOLAR_SYSTEM_BODIES.map((name) => {
    const el = document.createElement('div');
    el.textContent = name === 'Earth' ? 'Earth–Moon' : name;
    el.dataset.label = name;
    // A dark translucent backing keeps the name legible over a bright planet or trail.
    el.style.cssText =
      'position: absolute; transform: translate(6px, -50%); white-space: nowrap; padding: 0 4px; border-radius: 3px; background: rgba(8, 10, 16, 0.72)';
    labelLayer.append(el);
    return [name, el];
  }),
);

// A dot of the body's colour at its place, kept at least a few pixels wide: at the scale of
// Neptune's orbit (60 AU across a few hundred pixels) even the exaggerated planets are under a
// pixel, and a player could not find them. The dot hides once the body itself is drawn larger.
const dots = Object.fromEntries(
  SOLAR_SYSTEM_BODIES.map((name) => {
    const el = document.createElement('div');
    const size = name === 'Sun' ? 12 : name === 'Jupiter' || name === 'Saturn' ? 8 : 6;
    const colour = `#${COLOR[name]!.toString(16).padStart(6, '0')}`;
    el.style.cssText = `position: absolute; width: ${size}px; height: ${size}px; margin: ${-size / 2}px 0 0 ${-size / 2}px; border-radius: 50%; background: ${colour}; box-shadow: 0 0 6px ${colour}`;
    el.dataset.dot = name;
    labelLayer.append(el);
    return [name, { el, size }];
  }),
);

const table = document.createElement('div');
table.className = 'bp-hud';
table.dataset.hud = 'ephemeris';
pageLayout().side.append(table);
const dateLine = table.appendChild(document.createElement('div'));
dateLine.style.whiteSpace = 'pre-line';
const head = table.appendChild(document.createElement('div'));
head.textContent = 'error vs ephemeris (floor)';
const rows = Object.fromEntries(SOLAR_SYSTEM_PLANETS.map((p) => [p, table.appendChild(document.createElement('div'))]));
const errors = new Float64Array(SOLAR_SYSTEM_PLANETS.length);

const p3 = [0, 0, 0];
const v = new Vector3();
let tableFrame = 0;

/** Places a name may take, as (side, rows) pairs: side +1 right of the body, -1 left; rows of 17 px down. */
const LABEL_PLACES = [1, 0, -1, 0, 1, -1, -1, -1, 1, 1, -1, 1, 1, -2, -1, -2, 1, 2, -1, 2];

/** Whether a label box from `x0` to `x0 + width` at height `y` (px) clears every label placed this frame. */
function labelFree(x0: number, y: number, width: number): boolean {
  for (let i = 0; i < placed.length; i += 4) {
    if (x0 < placed[i + 2]! && x0 + width > placed[i]! && Math.abs(y - placed[i + 1]!) < 16) return false;
  }
  return true;
}

/** Per body (in SOLAR_SYSTEM_BODIES order): screen x, y (px), drawn radius (px), on screen (1) or not (0). */
const onScreen = new Float64Array(4 * SOLAR_SYSTEM_BODIES.length);
/** The order names are placed in this frame (indices into SOLAR_SYSTEM_BODIES). */
const labelOrder = SOLAR_SYSTEM_BODIES.map((_, i) => i);

function frame(): void {
  const k = UNITS_PER_AU;
  const w = app.canvas.clientWidth,
    h = app.canvas.clientHeight;
  SOLAR_SYSTEM_BODIES.forEach((name, i) => {
    onScreen[4 * i + 3] = 0;
    if (!renderer.drawnPosition(handles.bodies[name], p3)) {
      labels[name]!.style.display = 'none';
      dots[name]!.el.style.display = 'none';
      return;
    }
    v.set(p3[0]! * k, p3[1]! * k, p3[2]! * k);
    if (name === 'Sun') {
      sunGlow.position.copy(v);
      sunGlow.scale.setScalar(drawnRadius('Sun') * k * 9);
    }
    if (name === 'Saturn') {
      rings.position.copy(v);
      rings.scale.set(1, 0.01, 1).multiplyScalar(drawnRadius('Saturn') * k * 2.2);
    }
    const distance = v.distanceTo(app.camera.position);
    v.project(app.camera);
    const visible = v.z < 1 && Math.abs(v.x) < 1.1 && Math.abs(v.y) < 1.1;
    const x = ((v.x + 1) / 2) * w,
      y = ((1 - v.y) / 2) * h;
    // Radius the body is drawn with, px (perspective: h / 2 px span tan(fov / 2) x distance).
    const drawnPx = (drawnRadius(name) * k * h) / (2 * distance * Math.tan((app.camera.fov * Math.PI) / 360));
    const { el: dot, size: dotSize } = dots[name]!;
    const showDot = visible && drawnPx < dotSize / 2;
    dot.style.display = showDot ? 'block' : 'none';
    if (showDot) {
      dot.style.left = `${x}px`;
      dot.style.top = `${y}px`;
    }
    onScreen[4 * i] = x;
    onScreen[4 * i + 1] = y;
    onScreen[4 * i + 2] = drawnPx;
    onScreen[4 * i + 3] = visible ? 1 : 0;
  });
  // Names are placed the Sun first, then the planets farthest from it on the screen first: zoomed out,
  // the inner planets crowd the Sun and the outer ones, each alone on its orbit, keep their names.
  const sx = onScreen[0]!,
    sy = onScreen[1]!;
  const apart = (i: number) => (i === 0 ? Infinity : Math.hypot(onScreen[4 * i]! - sx, onScreen[4 * i + 1]! - sy));
  labelOrder.sort((a, b) => apart(b) - apart(a));
  for (const i of labelOrder) {
    const name = SOLAR_SYSTEM_BODIES[i]!;
    const el = labels[name]!;
    const x = onScreen[4 * i]!,
      y = onScreen[4 * i + 1]!,
      drawnPx = onScreen[4 * i + 2]!,
      visible = onScreen[4 * i + 3] === 1;
    // The name goes right of the body, else left, else above or below either side: the first place
    // that covers no name placed before and stays in the view. With none free it waits until the view
    // separates them.
    const width = 7.5 * (el.textContent?.length ?? 4) + 14;
    const gap = Math.max(6, drawnPx + 3);
    let free = false,
      x0 = 0,
      y0 = y;
    if (visible) {
      for (let c = 0; c < LABEL_PLACES.length && !free; c += 2) {
        x0 = LABEL_PLACES[c]! > 0 ? x + gap : x - gap - width;
        y0 = y + LABEL_PLACES[c + 1]! * 17;
        free = x0 >= 0 && x0 + width <= w && labelFree(x0, y0, width);
      }
    }
    el.style.display = free ? 'block' : 'none';
    if (free) {
      el.style.left = `${x0}px`;
      el.style.top = `${y0}px`;
      el.style.transform = 'translate(0, -50%)';
      placed.push(x0, y0, x0 + width, 0);
    }
  }
  shownLabels = placed.length / 4;
  placed.length = 0;
  if (tableFrame++ % 15 === 0) updateTable();
}

function updateTable(): void {
  const world = shell.world;
  const date = new Date(handles.epoch + world.time * 86_400_000);
  // Two short lines: the side column's width must not follow the date's length.
  dateLine.textContent = `${date.toISOString().slice(0, 16).replace('T', ' ')} UTC · day ${world.time.toFixed(1)}\n${params.integrator} ${params.step} h · ${params.rate.toFixed(1)} d/s`;
  solarSystemErrors(world, handles, errors);
  SOLAR_SYSTEM_PLANETS.forEach((p, i) => {
    rows[p]!.textContent = `${p.padEnd(8)} ${errors[i]!.toExponential(2)}  (${SOLAR_SYSTEM_FLOOR[p].toExponential(1)} at 1 yr)`;
  });
}

function setRate(days: number): void {
  params.rate = Math.min(400, Math.max(0, days < 0.05 ? 0 : Math.round(days * 100) / 100));
  panel.refresh();
}

function setTrails(on: boolean): void {
  params.trails = on;
  renderer.setTrails(on ? TRAILS : false);
  panel.refresh();
}

const panel = createPanel(
  params,
  [
    { type: 'slider', key: 'rate', label: 'rate (days/s)', min: 0, max: 400, step: 0.5 },
    { type: 'choice', key: 'step', label: 'step (hours)', options: STEPS, onChange: () => shell.reset() },
    { type: 'choice', key: 'integrator', label: 'integrator', options: INTEGRATOR_NAMES, onChange: () => shell.reset() },
    {
      type: 'text',
      key: 'date',
      label: 'start date (UTC)',
      onChange: () => {
        try {
          shell.reset();
        } catch (error) {
          shell.hud.showError(String((error as Error).message));
        }
      },
    },
    { type: 'checkbox', key: 'exaggerate', label: 'exaggerated sizes', onChange: () => dress() },
    { type: 'checkbox', key: 'trails', label: 'trails', onChange: (x) => setTrails(x === true) },
    { type: 'button', key: 'inner', label: 'inner planets (1)' },
    { type: 'button', key: 'all', label: 'all eight planets (2)' },
    { type: 'button', key: 'reset', label: 'reset (R)' },
  ],
  { title: 'Solar system' },
);

shell.expose({
  params,
  panel,
  /** Entities by name. */
  bodies: () => handles.bodies,
  /** Each planet's relative error against the ephemeris now, by name. */
  errors: (): Record<string, number> => {
    solarSystemErrors(shell.world, handles, errors);
    return Object.fromEntries(SOLAR_SYSTEM_PLANETS.map((p, i) => [p, errors[i]!]));
  },
  /** Sets the rate, simulated days per real second, clamped to [0, 400]. */
  setRate,
  /** Orbit lines drawn (one a planet). */
  orbitCount: (): number => orbitLines.children.length,
  /** Labels the last frame showed (overlapping ones hidden). */
  shownLabels: (): number => shownLabels,
  /** The planets whose centre the camera sees now (projected inside the canvas). */
  planetsInView: (): string[] => {
    const k = UNITS_PER_AU;
    return SOLAR_SYSTEM_PLANETS.filter((name) => {
      if (!renderer.drawnPosition(handles.bodies[name], p3)) return false;
      v.set(p3[0]! * k, p3[1]! * k, p3[2]! * k).project(app.camera);
      return v.z < 1 && Math.abs(v.x) <= 1 && Math.abs(v.y) <= 1;
    });
  },
});
