/**
 * The flight simulator's crash, drawn (nothing here touches the physics): a white flash over the
 * scene, a fireball of several puffs going from white-yellow through orange to dark red, pieces of
 * the aircraft thrown out and tumbling down to the ground, and a column of dark smoke that keeps
 * rising while the crash is in view, so it reads as a crash (a single pale fireball reads as a disc).
 * Timed by the clock (ms, performance.now), so it plays while the game is stopped.
 */

import {
  BoxGeometry,
  Color,
  IcosahedronGeometry,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  type Object3D,
  type Scene,
  Vector3,
} from 'three';

/** Fire puffs, pieces and smoke puffs drawn. */
const FIRE = 8,
  PIECES = 18,
  SMOKE = 12;
/** How long the fireball lasts, s; the flash, s; one smoke puff's rise, s. */
const FIRE_TIME = 1.8,
  FLASH_TIME = 0.5,
  SMOKE_TIME = 6;
/** The smoke's colour as it leaves the fire and high up. */
const SMOKE_LOW = new Color(0x1d1916),
  SMOKE_HIGH = new Color(0x77716b);
/** Gravity on the thrown pieces, m/s^2. */
const G = 9.81;

/** What `createCrash` gives the page. */
export interface Crash {
  /**
   * Starts the crash at `at` (m, world: where the aircraft hit) for an aircraft moving at `velocity`
   * (m/s), the ground's height given by `ground(x, z)` (m), at the clock's `nowMs`.
   */
  start(at: Vector3, velocity: readonly number[], ground: (x: number, z: number) => number, nowMs: number): void;
  /** Draws the crash at the clock's `nowMs` (nothing before `start`). */
  update(nowMs: number): void;
  /** Hides it all (a new flight). */
  hide(): void;
  /** Where it is (the fireball's centre, m, world). */
  readonly centre: Vector3;
  /** Seconds since the start at the clock's `nowMs` (Infinity before `start`). */
  age(nowMs: number): number;
  /** How far the camera shakes now, m (0 after the first 0.7 s). */
  shake(nowMs: number): number;
}

/**
 * Creates the crash's meshes in `scene` and its flash over `stage` (an element the scene's canvas
 * fills, positioned), all hidden until `start`.
 */
export function createCrash(scene: Scene, stage: HTMLElement): Crash {
  const puff = new IcosahedronGeometry(1, 1);
  const fire = Array.from({ length: FIRE }, () => {
    const m = new Mesh(
      puff,
      new MeshBasicMaterial({ color: 0xffa020, transparent: true, fog: false, depthWrite: false, toneMapped: false }),
    );
    m.renderOrder = 2;
    return m;
  });
  const smoke = Array.from(
    { length: SMOKE },
    () => new Mesh(puff, new MeshBasicMaterial({ color: 0x221e1b, transparent: true, depthWrite: false })),
  );
  // The pieces: the aircraft's white, red and grey and charred black, lit as the aircraft is.
  const colours = [0xf2f2ee, 0xd8453a, 0x8a9099, 0x1c1a18];
  const pieces = Array.from({ length: PIECES }, (_, k) => {
    const size = 1.2 + (k % 5) * 0.7;
    const m = new Mesh(
      new BoxGeometry(size * 2.2, size * 0.5, size * 1.4),
      new MeshStandardMaterial({ color: colours[k % colours.length], roughness: 0.7, flatShading: true }),
    );
    return m;
  });
  const all: Object3D[] = [...fire, ...smoke, ...pieces];
  for (const m of all) m.visible = false;
  scene.add(...all);
  const flash = document.createElement('div');
  flash.dataset.hud = 'crash-flash';
  flash.style.cssText =
    'position: absolute; inset: 0; z-index: 5; pointer-events: none; opacity: 0; background: radial-gradient(circle at 50% 60%, rgba(255, 255, 240, 1) 0%, rgba(255, 200, 90, 0.85) 35%, rgba(230, 80, 20, 0.6) 100%);';
  stage.append(flash);

  const centre = new Vector3();
  let startedAt = Number.NaN;
  let groundOf: (x: number, z: number) => number = () => 0;
  /** Each piece's start velocity (m/s), spin (rad/s about x, y, z) and when it landed (s after the start; NaN: in the air). */
  const throws = pieces.map(() => ({ v: new Vector3(), spin: new Vector3(), landed: Number.NaN }));
  const colour = new Color();
  /** A fixed spread in [0, 1) for index `k` and salt `s` (the same crash every time). */
  const spread = (k: number, s: number): number => {
    const x = Math.sin(k * 12.9898 + s * 78.233) * 43758.5453;
    return x - Math.floor(x);
  };

  function hide(): void {
    startedAt = Number.NaN;
    for (const m of all) m.visible = false;
    flash.style.opacity = '0';
  }

  return {
    centre,
    start(at, velocity, ground, nowMs) {
      startedAt = nowMs;
      groundOf = ground;
      // Lifted clear of the drawn ground, whose flat cells can stand above the true surface.
      centre.copy(at).setY(Math.max(at.y, ground(at.x, at.z)) + 12);
      const [vx = 0, , vz = 0] = velocity;
      pieces.forEach((m, k) => {
        const a = 2 * Math.PI * spread(k, 1),
          out = 18 + 30 * spread(k, 2);
        // Thrown outward and up, carried on a little the way the aircraft was going.
        throws[k]!.v.set(0.25 * vx + out * Math.cos(a), 22 + 38 * spread(k, 3), 0.25 * vz + out * Math.sin(a));
        throws[k]!.spin.set(6 * (spread(k, 4) - 0.5), 6 * (spread(k, 5) - 0.5), 6 * (spread(k, 6) - 0.5));
        throws[k]!.landed = Number.NaN;
        m.position.copy(centre);
        m.rotation.set(0, 0, 0);
        m.visible = true;
      });
    },
    hide,
    age(nowMs) {
      return Number.isNaN(startedAt) ? Number.POSITIVE_INFINITY : (nowMs - startedAt) / 1000;
    },
    shake(nowMs) {
      const u = (nowMs - startedAt) / 1000;
      return Number.isNaN(startedAt) || u > 0.7 ? 0 : 4 * (1 - u / 0.7);
    },
    update(nowMs) {
      if (Number.isNaN(startedAt)) return;
      const u = (nowMs - startedAt) / 1000;
      flash.style.opacity = u < FLASH_TIME ? (0.85 * (1 - u / FLASH_TIME) ** 2).toFixed(3) : '0';
      // The fireball: puffs round the centre swell in 0.35 s, rise, and cool from white-yellow through
      // orange to dark red as they fade.
      fire.forEach((m, k) => {
        const life = u / (FIRE_TIME * (0.75 + 0.35 * spread(k, 7)));
        m.visible = life < 1;
        if (!m.visible) return;
        const a = 2 * Math.PI * spread(k, 8),
          r = k === 0 ? 0 : 12 + 12 * spread(k, 9);
        const grow = Math.min(1, u / 0.35);
        m.position.set(
          centre.x + r * (0.4 + 0.6 * grow) * Math.cos(a),
          centre.y + (k === 0 ? 0 : 14 * (spread(k, 10) - 0.3)) + 20 * life,
          centre.z + r * (0.4 + 0.6 * grow) * Math.sin(a),
        );
        m.scale.setScalar((k === 0 ? 22 : 12 + 12 * spread(k, 11)) * (0.3 + 0.7 * grow) * (1 + 0.4 * life));
        const mat = m.material as MeshBasicMaterial;
        // The core yellow, the puffs round it orange to red, all darkening to a smoky red as they cool.
        const hue = k === 0 ? 0.14 : 0.1 - 0.08 * spread(k, 12);
        colour.setHSL(hue * (1 - 0.7 * life), 1, 0.55 - 0.3 * life);
        mat.color.copy(colour);
        mat.opacity = Math.min(1, 1.6 * (1 - life));
      });
      // Smoke: a column of dark puffs, each rising, swelling and fading over SMOKE_TIME, the next
      // taking its place, for as long as the crash is in view.
      smoke.forEach((m, k) => {
        const t = u - 0.25 - (k * SMOKE_TIME) / SMOKE;
        if (t < 0) {
          m.visible = false;
          return;
        }
        const v = (t % SMOKE_TIME) / SMOKE_TIME;
        m.visible = true;
        const a = 2 * Math.PI * spread(k, 13);
        m.position.set(centre.x + 8 * Math.cos(a) + 40 * v, centre.y + 10 + 170 * v, centre.z + 8 * Math.sin(a) + 12 * v);
        m.scale.setScalar(12 + 42 * v);
        // Dark and thick low down, greyer and thinner as it rises.
        const mat = m.material as MeshBasicMaterial;
        mat.color.copy(SMOKE_LOW).lerp(SMOKE_HIGH, v);
        mat.opacity = 0.85 * Math.min(1, v / 0.08) * (1 - v);
      });
      // The pieces: thrown, tumbling, until they lie on the ground.
      pieces.forEach((m, k) => {
        const flung = throws[k]!;
        const t = Number.isNaN(flung.landed) ? u : flung.landed;
        const x = centre.x + flung.v.x * t,
          z = centre.z + flung.v.z * t,
          y = centre.y + flung.v.y * t - 0.5 * G * t * t;
        const floor = groundOf(x, z) + 1;
        if (y <= floor && Number.isNaN(flung.landed)) flung.landed = t;
        m.position.set(x, Math.max(floor, y), z);
        m.rotation.set(flung.spin.x * t, flung.spin.y * t, flung.spin.z * t);
      });
    },
  };
}
