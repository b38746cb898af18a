import { assertBoolean, assertInteger, assertKnownKeys, assertNonNegative, describe } from '@bitphysics/physics/validate';
import { type ColorInput, parseColor } from '@bitphysics/render-common';
import { AmbientLight, DirectionalLight, Group, HemisphereLight, Vector3 } from 'three';
import { assertVector } from './validate.js';

/** Options of `createLights` (and `WorldRenderer3DOptions.lights`). Every field optional; unknown fields are rejected. */
export interface LightOptions {
  /** Direction the sunlight comes from (towards the light), any non-zero 3-vector, y up. Default (0.45, 1, 0.3). */
  direction?: ArrayLike<number>;
  /** Colour of the directional (sun) light. Default 0xffffff. */
  color?: ColorInput;
  /** Intensity of the directional light, >= 0 (three.js physically based units). Default 2.2. */
  intensity?: number;
  /** Sky colour of the hemisphere light. Default 0xdde8ff. */
  skyColor?: ColorInput;
  /** Ground colour of the hemisphere light. Default 0x3b3328. */
  groundColor?: ColorInput;
  /** Intensity of the hemisphere light, >= 0. Default 1.1. */
  hemisphereIntensity?: number;
  /** Intensity of an extra uniform ambient light, >= 0 (0: none). Default 0. */
  ambientIntensity?: number;
  /** Whether the directional light casts shadows. Default true. */
  shadows?: boolean;
  /** Edge of the shadow map, px, a power of two in [256, 8192]. Default 2048. */
  shadowMapSize?: number;
}

/** Resolved light options. */
export type ResolvedLightOptions = Required<Omit<LightOptions, 'direction' | 'color' | 'skyColor' | 'groundColor'>> & {
  direction: [number, number, number];
  color: number;
  skyColor: number;
  groundColor: number;
};

const LIGHT_OPTIONS = [
  'direction',
  'color',
  'intensity',
  'skyColor',
  'groundColor',
  'hemisphereIntensity',
  'ambientIntensity',
  'shadows',
  'shadowMapSize',
] as const;

/** Checks light options and fills in defaults. @throws TypeError | RangeError naming the bad option and value. */
export function resolveLightOptions(where: string, options: LightOptions = {}): ResolvedLightOptions {
  assertKnownKeys(where, options, LIGHT_OPTIONS);
  const d = options.direction ?? [0.45, 1, 0.3];
  assertVector(where, 'lights.direction', d, 3);
  const len = Math.hypot(d[0]!, d[1]!, d[2]!);
  if (!(len > 0)) throw new RangeError(`${where}: lights.direction must not be zero, got ${describe(d)}`);
  const intensity = options.intensity ?? 2.2;
  assertNonNegative(where, 'lights.intensity', intensity);
  const hemisphereIntensity = options.hemisphereIntensity ?? 1.1;
  assertNonNegative(where, 'lights.hemisphereIntensity', hemisphereIntensity);
  const ambientIntensity = options.ambientIntensity ?? 0;
  assertNonNegative(where, 'lights.ambientIntensity', ambientIntensity);
  const shadows = options.shadows ?? true;
  assertBoolean(where, 'lights.shadows', shadows);
  const shadowMapSize = options.shadowMapSize ?? 2048;
  assertInteger(where, 'lights.shadowMapSize', shadowMapSize, 256, 8192);
  if ((shadowMapSize & (shadowMapSize - 1)) !== 0)
    throw new RangeError(`${where}: lights.shadowMapSize must be a power of two, got ${shadowMapSize}`);
  return {
    direction: [d[0]! / len, d[1]! / len, d[2]! / len],
    color: parseColor(where, 'lights.color', options.color ?? 0xffffff),
    intensity,
    skyColor: parseColor(where, 'lights.skyColor', options.skyColor ?? 0xdde8ff),
    groundColor: parseColor(where, 'lights.groundColor', options.groundColor ?? 0x3b3328),
    hemisphereIntensity,
    ambientIntensity,
    shadows,
    shadowMapSize,
  };
}

/**
 * A light rig: a hemisphere light (sky above, ground below: soft fill that shows shape), a
 * directional "sun" that casts shadows, and an optional ambient light. `fit` aims the sun's shadow
 * camera at a box so its shadow map covers exactly what is drawn.
 */
export class LightRig {
  /** Parent of the lights (and the sun's target); add it to the scene. */
  readonly object = new Group();
  /** The directional light. */
  readonly sun: DirectionalLight;
  /** The hemisphere light. */
  readonly hemisphere: HemisphereLight;
  /** The ambient light, or null. */
  readonly ambient: AmbientLight | null;
  /** The options in use. */
  readonly options: ResolvedLightOptions;
  private readonly dir: Vector3;

  /** @param options resolved options (see `resolveLightOptions`). */
  constructor(options: ResolvedLightOptions) {
    this.options = options;
    this.object.name = 'lights';
    this.hemisphere = new HemisphereLight(options.skyColor, options.groundColor, options.hemisphereIntensity);
    this.sun = new DirectionalLight(options.color, options.intensity);
    this.sun.name = 'sun';
    this.sun.castShadow = options.shadows;
    this.sun.shadow.mapSize.set(options.shadowMapSize, options.shadowMapSize);
    this.sun.shadow.bias = -0.0004;
    this.sun.shadow.normalBias = 0.02;
    this.dir = new Vector3(options.direction[0], options.direction[1], options.direction[2]);
    this.object.add(this.hemisphere, this.sun, this.sun.target);
    this.ambient = options.ambientIntensity > 0 ? new AmbientLight(0xffffff, options.ambientIntensity) : null;
    if (this.ambient) this.object.add(this.ambient);
    this.fit(-10, -10, -10, 10, 10, 10);
  }

  /**
   * Aims the sun at the centre of the box (min, max) (scene units) from its direction and sizes its
   * orthographic shadow camera to enclose the box, so the shadow map's resolution is spent on it.
   */
  fit(minX: number, minY: number, minZ: number, maxX: number, maxY: number, maxZ: number): void {
    const cx = 0.5 * (minX + maxX),
      cy = 0.5 * (minY + maxY),
      cz = 0.5 * (minZ + maxZ);
    const r = 0.5 * Math.hypot(maxX - minX, maxY - minY, maxZ - minZ) || 1;
    const sun = this.sun;
    sun.target.position.set(cx, cy, cz);
    sun.position.set(cx + this.dir.x * 2 * r, cy + this.dir.y * 2 * r, cz + this.dir.z * 2 * r);
    const cam = sun.shadow.camera;
    cam.left = -r;
    cam.right = r;
    cam.top = r;
    cam.bottom = -r;
    cam.near = 0.01 * r;
    cam.far = 4 * r;
    cam.updateProjectionMatrix();
    sun.target.updateMatrixWorld();
    sun.updateMatrixWorld();
  }

  /** Frees the shadow map. */
  dispose(): void {
    this.object.removeFromParent();
    this.sun.dispose();
    this.hemisphere.dispose();
    this.ambient?.dispose();
  }
}

/** Makes a light rig from options (see `LightOptions`). @throws TypeError | RangeError on bad options. */
export function createLights(options: LightOptions = {}): LightRig {
  return new LightRig(resolveLightOptions('createLights', options));
}
