import { type Container, type Particle, ParticleContainer, type Texture } from 'pixi.js';
import { sharedStreakTexture } from './textures.js';

/**
 * The display side that the particle layer (particles.ts) and the point layer (points.ts) share: a
 * parent container holding an optional streak `ParticleContainer` (below) and the main one (sparks or
 * dots), each fed from a pool of display particles that only grows.
 *
 * A layer's render loop writes pool[0..n-1] of `mainPool` and pool[0..k-1] of `streakPool` itself
 * (pools pulled into locals, nothing here runs per particle), then calls `commit(n, k)`. The two
 * layers keep their own loops because they compute different things per particle (a look over the
 * particle's lifetime; a palette colour by speed or radius).
 */
export class QuadPools {
  /** The main container (sparks or dots), above the streaks. */
  readonly main: ParticleContainer<Particle>;
  /** The streak container, made the first time streaks are shown; null until then. */
  streaks: ParticleContainer<Particle> | null = null;
  /** Display particles of `main`, in slot order; grows, never shrinks until `destroy`. */
  readonly mainPool: Particle[] = [];
  /** Display particles of `streaks`, in slot order. */
  readonly streakPool: Particle[] = [];
  /** Most particles each container held since its static data (texture coordinates) was last uploaded. */
  private mainHigh = 0;
  private streakHigh = 0;
  private blend: 'normal' | 'add';

  /**
   * @param container the layer's parent container (the main container is added to it).
   * @param labels pixi labels of the main and the streak container.
   * @param texture the main container's texture.
   * @param vertex whether the main quads' size changes per frame (pixi's dynamic `vertex` property).
   * @param blend the blend mode of both containers.
   */
  constructor(
    readonly container: Container,
    private readonly labels: { main: string; streaks: string },
    texture: Texture,
    vertex: boolean,
    blend: 'normal' | 'add',
  ) {
    this.main = new ParticleContainer<Particle>({
      label: labels.main,
      texture,
      dynamicProperties: { position: true, vertex, color: true, rotation: false, uvs: false },
    });
    container.addChild(this.main);
    this.blend = blend;
    this.main.blendMode = blend;
  }

  /** Display particles ever created (both pools). */
  get pooled(): number {
    return this.mainPool.length + this.streakPool.length;
  }

  /** Sets the blend mode of both containers. */
  setBlend(blend: 'normal' | 'add'): void {
    this.blend = blend;
    this.main.blendMode = blend;
    if (this.streaks) this.streaks.blendMode = blend;
  }

  /**
   * Shows or hides the streaks; the streak container (with the shared streak texture, under the main
   * one) is made the first time they are shown.
   * @throws Error if there is no 2D canvas for the streak texture.
   */
  showStreaks(on: boolean): void {
    if (on && !this.streaks) {
      this.streaks = new ParticleContainer<Particle>({
        label: this.labels.streaks,
        texture: sharedStreakTexture(),
        dynamicProperties: { position: true, vertex: true, rotation: true, color: true, uvs: false },
      });
      this.streaks.blendMode = this.blend;
      this.container.addChildAt(this.streaks, 0);
    }
    if (this.streaks) this.streaks.visible = on;
  }

  /** Makes the main container show mainPool[0..n-1] and the streak container (if any) streakPool[0..k-1]. */
  commit(n: number, k: number): void {
    this.mainHigh = commit(this.main, this.mainPool, n, this.mainHigh);
    if (this.streaks) this.streakHigh = commit(this.streaks, this.streakPool, k, this.streakHigh);
  }

  /** Removes the parent container from its parent and frees it, both containers and the pools (shared textures stay). */
  destroy(): void {
    this.container.parent?.removeChild(this.container);
    this.main.particleChildren.length = 0;
    if (this.streaks) this.streaks.particleChildren.length = 0;
    this.container.destroy({ children: true });
    this.mainPool.length = 0;
    this.streakPool.length = 0;
  }
}

/**
 * Makes `container` show pool[0..n-1]: its list holds pool[j] at index j, so only the length changes
 * (grown by pushing from the pool, cut by setting the length). When it holds more particles than at
 * its last static upload, the static data (texture coordinates) is marked for upload. Returns the new
 * high-water mark.
 */
function commit(container: ParticleContainer<Particle>, pool: Particle[], n: number, high: number): number {
  const list = container.particleChildren;
  if (list.length < n) {
    for (let j = list.length; j < n; j++) list.push(pool[j]!);
  } else if (list.length > n) {
    list.length = n;
  }
  if (n > high) {
    container.update();
    return n;
  }
  return high;
}
