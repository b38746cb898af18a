/**
 * Game sounds synthesised with the Web Audio API (no sound files, so no asset licences): impacts whose
 * loudness follows the contact impulse and whose pitch follows the material, launches, explosions,
 * firework crackle, and a continuous engine hum. One audio context per page, made by the first
 * pointer or key input (browsers start audio only after a user gesture); before that every call is
 * a no-op. Muting is remembered in localStorage ('bitphysics.muted') for every page. DOM only.
 */

import { numberCheck, storedValue } from './storage.js';

/** Materials whose impacts sound different (pitch and brightness). */
export type SoundMaterial = 'wood' | 'stone' | 'glass' | 'metal' | 'soft';

/** A continuous sound (an engine) whose level and pitch the game sets every frame. */
export interface EngineSound {
  /** Sets the engine's `level` in [0, 1] (0 is silent; values outside are clamped). */
  set(level: number): void;
  /** Silences and disconnects it. */
  stop(): void;
}

/** The page's sound. */
export interface Sound {
  /** Whether sound is muted (kept in localStorage). Settable. */
  muted: boolean;
  /** Whether the audio context runs (after the first input, unless the browser refused). */
  readonly running: boolean;
  /** Sounds played so far (a count for tests and the console). */
  readonly played: number;
  /**
   * An impact: `impulse` in N s (>= 0; below `threshold` it is silent), loudness rising with its
   * logarithm from `threshold` up to `loud` N s; pitch and ring from `material`.
   */
  impact(impulse: number, material?: SoundMaterial, options?: { threshold?: number; loud?: number }): void;
  /** A launch: a rising whoosh, `strength` in [0, 1]. */
  launch(strength?: number): void;
  /** An explosion or burst: low noise with a long tail, `size` in [0, 1]. */
  explosion(size?: number): void;
  /** A crackle of `count` small pops spread over `duration` s (fireworks). */
  crackle(count?: number, duration?: number): void;
  /** A short tone (a beacon, a ring passed, a level cleared): `pitch` Hz, `duration` s. */
  chime(pitch?: number, duration?: number): void;
  /** Cloth tearing: a run of short bursts of hiss, `strength` in [0, 1] (longer and louder the larger). */
  rip(strength?: number): void;
  /** A rope or a thread snapping (or cut): a sharp crack and a low thump, `strength` in [0, 1]. */
  snap(strength?: number): void;
  /** A continuous engine hum: `kind` 'propeller' (plane) or 'screw' (submarine). */
  engine(kind: 'propeller' | 'screw'): EngineSound;
}

/** Whether sound is muted, kept for every page: 1 (muted) or 0, as a number's text; anything else reads as 0. */
const mutedStore = storedValue('bitphysics.muted', numberCheck({ max: 1, integer: true }), 0);

/** Impact timbre per material: base frequency Hz, decay s, noise share, filter Q. */
const MATERIALS: Record<SoundMaterial, { f: number; decay: number; noise: number; q: number }> = {
  wood: { f: 220, decay: 0.09, noise: 0.5, q: 4 },
  stone: { f: 120, decay: 0.12, noise: 0.7, q: 1.5 },
  glass: { f: 1900, decay: 0.25, noise: 0.25, q: 18 },
  metal: { f: 620, decay: 0.45, noise: 0.2, q: 25 },
  soft: { f: 90, decay: 0.06, noise: 0.8, q: 0.8 },
};

function readMuted(): boolean {
  return mutedStore.read() === 1;
}

let sound: Sound | null = null;

/** The page's sound (made on first call; the audio context waits for the first input). */
export function getSound(): Sound {
  if (sound) return sound;
  let ctx: AudioContext | null = null;
  let master: GainNode | null = null;
  let noise: AudioBuffer | null = null;
  let muted = readMuted();
  let played = 0;
  /** Impacts started in the current 50 ms window (many contacts at once must not clip). */
  let windowStart = 0,
    windowCount = 0;
  const engines = new Set<{ gain: GainNode; level: number }>();
  const pendingEngines: Array<() => void> = [];

  /** Whether an input has started the sound (browsers allow audio only after one). */
  let started = false;
  /**
   * Makes the audio context and the noise buffer, suspended until an input. Opening the audio device
   * and filling the noise take tens of milliseconds, so this is done at the first idle moment after
   * the page loads, not inside the first input's frame, where it would show as a hitch.
   */
  const prepare = (): void => {
    if (ctx) return;
    const AC = window.AudioContext ?? (window as unknown as { webkitAudioContext?: typeof AudioContext }).webkitAudioContext;
    if (!AC) return;
    try {
      ctx = new AC();
    } catch {
      return;
    }
    master = ctx.createGain();
    master.gain.value = muted ? 0 : 0.8;
    const limiter = ctx.createDynamicsCompressor();
    master.connect(limiter).connect(ctx.destination);
    // One second of white noise, reused by every noisy sound.
    noise = ctx.createBuffer(1, ctx.sampleRate, ctx.sampleRate);
    const data = noise.getChannelData(0);
    let seed = 12345;
    for (let i = 0; i < data.length; i++) {
      seed = (seed * 1103515245 + 12345) >>> 0;
      data[i] = (seed / 2 ** 31 - 1) * 0.9;
    }
  };
  const start = (): void => {
    prepare();
    if (!ctx) return;
    if (ctx.state === 'suspended') void ctx.resume();
    if (started) return;
    started = true;
    for (const make of pendingEngines.splice(0)) make();
  };
  for (const type of ['pointerdown', 'keydown', 'touchstart'] as const)
    window.addEventListener(type, start, { capture: true, passive: true });
  const idle = (window as unknown as { requestIdleCallback?: (f: () => void, o?: { timeout: number }) => number }).requestIdleCallback;
  if (idle) idle(prepare, { timeout: 2000 });
  else setTimeout(prepare, 500);

  const live = (): AudioContext | null => (started && ctx && master && ctx.state === 'running' && !muted ? ctx : null);

  /** A noise burst through a band-pass at `f` Hz, peak `gain`, decaying over `decay` s, `delay` s from now. */
  const noiseBurst = (
    c: AudioContext,
    f: number,
    q: number,
    gain: number,
    decay: number,
    delay = 0,
    type: BiquadFilterType = 'bandpass',
  ): void => {
    const src = c.createBufferSource();
    src.buffer = noise;
    src.playbackRate.value = 0.8 + Math.random() * 0.4;
    const filter = c.createBiquadFilter();
    filter.type = type;
    filter.frequency.value = f;
    filter.Q.value = q;
    const g = c.createGain();
    const t = c.currentTime + delay;
    g.gain.setValueAtTime(0, t);
    g.gain.linearRampToValueAtTime(gain, t + 0.004);
    g.gain.exponentialRampToValueAtTime(0.0005, t + decay);
    src.connect(filter).connect(g).connect(master!);
    src.start(t, Math.random() * 0.5, decay + 0.05);
  };
  /** A tone at `f` Hz falling to `f * drop`, peak `gain`, decaying over `decay` s. */
  const tone = (c: AudioContext, f: number, gain: number, decay: number, drop = 1, type: OscillatorType = 'sine', delay = 0): void => {
    const o = c.createOscillator();
    o.type = type;
    const t = c.currentTime + delay;
    o.frequency.setValueAtTime(f, t);
    if (drop !== 1) o.frequency.exponentialRampToValueAtTime(Math.max(20, f * drop), t + decay);
    const g = c.createGain();
    g.gain.setValueAtTime(0, t);
    g.gain.linearRampToValueAtTime(gain, t + 0.005);
    g.gain.exponentialRampToValueAtTime(0.0005, t + decay);
    o.connect(g).connect(master!);
    o.start(t);
    o.stop(t + decay + 0.05);
  };

  sound = {
    get muted() {
      return muted;
    },
    set muted(value: boolean) {
      muted = value === true;
      mutedStore.write(muted ? 1 : 0);
      if (ctx && master) master.gain.setTargetAtTime(muted ? 0 : 0.8, ctx.currentTime, 0.02);
    },
    get running() {
      return started && ctx?.state === 'running';
    },
    get played() {
      return played;
    },
    impact(impulse, material = 'wood', options = {}) {
      const threshold = options.threshold ?? 0.5,
        loud = options.loud ?? 50;
      if (!(impulse > threshold)) return;
      const c = live();
      if (!c) return;
      const now = c.currentTime;
      if (now - windowStart > 0.05) {
        windowStart = now;
        windowCount = 0;
      }
      if (++windowCount > 6) return;
      const m = MATERIALS[material];
      const level = Math.min(1, Math.log(impulse / threshold) / Math.log(loud / threshold));
      const gain = 0.08 + 0.5 * level;
      const f = m.f * (0.9 + Math.random() * 0.2);
      noiseBurst(c, f * 2, m.q, gain * m.noise, m.decay);
      tone(c, f, gain * (1 - m.noise), m.decay * 1.5, 0.85, material === 'glass' || material === 'metal' ? 'triangle' : 'sine');
      played++;
    },
    launch(strength = 0.6) {
      const c = live();
      if (!c) return;
      const s = Math.min(1, Math.max(0, strength));
      const src = c.createBufferSource();
      src.buffer = noise;
      const filter = c.createBiquadFilter();
      filter.type = 'bandpass';
      filter.Q.value = 2;
      const t = c.currentTime;
      filter.frequency.setValueAtTime(300, t);
      filter.frequency.exponentialRampToValueAtTime(1800 + 1500 * s, t + 0.35);
      const g = c.createGain();
      g.gain.setValueAtTime(0, t);
      g.gain.linearRampToValueAtTime(0.15 + 0.3 * s, t + 0.05);
      g.gain.exponentialRampToValueAtTime(0.0005, t + 0.45);
      src.connect(filter).connect(g).connect(master!);
      src.start(t, Math.random() * 0.4, 0.5);
      tone(c, 140, 0.2 * s, 0.15, 0.5, 'triangle');
      played++;
    },
    explosion(size = 0.6) {
      const c = live();
      if (!c) return;
      const s = Math.min(1, Math.max(0, size));
      noiseBurst(c, 400 + 300 * s, 0.7, 0.35 + 0.45 * s, 0.6 + 1.2 * s, 0, 'lowpass');
      tone(c, 70, 0.4 + 0.3 * s, 0.5 + 0.5 * s, 0.4);
      played++;
    },
    crackle(count = 24, duration = 1.2) {
      const c = live();
      if (!c) return;
      const n = Math.min(60, Math.max(1, Math.round(count)));
      for (let i = 0; i < n; i++)
        noiseBurst(c, 2500 + Math.random() * 4000, 3, 0.05 + Math.random() * 0.12, 0.03, 0.1 + Math.random() * duration, 'highpass');
      played++;
    },
    chime(pitch = 880, duration = 0.35) {
      const c = live();
      if (!c) return;
      tone(c, pitch, 0.22, duration, 1, 'triangle');
      tone(c, pitch * 1.5, 0.1, duration * 0.8, 1, 'sine', 0.06);
      played++;
    },
    rip(strength = 0.5) {
      const c = live();
      if (!c) return;
      const s = Math.min(1, Math.max(0, strength));
      // Fibres parting one after another: 5 to 19 grains of band-passed noise 5 to 19 ms apart.
      const grains = Math.round(5 + 14 * s);
      let t = 0;
      for (let i = 0; i < grains; i++) {
        noiseBurst(c, 1600 + Math.random() * 2800, 1.2, (0.06 + 0.1 * Math.random()) * (0.5 + s), 0.02 + 0.025 * Math.random(), t);
        t += 0.005 + 0.014 * Math.random();
      }
      played++;
    },
    snap(strength = 0.6) {
      const c = live();
      if (!c) return;
      const s = Math.min(1, Math.max(0, strength));
      noiseBurst(c, 2500, 0.8, 0.25 + 0.3 * s, 0.05, 0, 'highpass');
      tone(c, 240, 0.18 + 0.2 * s, 0.14, 0.3, 'triangle');
      played++;
    },
    engine(kind) {
      const entry = { gain: null as unknown as GainNode, level: 0 };
      let osc: OscillatorNode | null = null,
        osc2: OscillatorNode | null = null,
        filter: BiquadFilterNode | null = null,
        stopped = false;
      const base = kind === 'propeller' ? 55 : 38;
      const make = (): void => {
        if (stopped || !ctx || !master) return;
        osc = ctx.createOscillator();
        osc.type = 'sawtooth';
        osc.frequency.value = base;
        osc2 = ctx.createOscillator();
        osc2.type = 'square';
        osc2.frequency.value = base * 0.5;
        filter = ctx.createBiquadFilter();
        filter.type = 'lowpass';
        filter.frequency.value = 300;
        entry.gain = ctx.createGain();
        entry.gain.gain.value = 0;
        osc.connect(filter);
        osc2.connect(filter);
        filter.connect(entry.gain).connect(master);
        osc.start();
        osc2.start();
        engines.add(entry);
      };
      if (ctx && started) make();
      else pendingEngines.push(make);
      return {
        set(level) {
          const l = Math.min(1, Math.max(0, Number.isFinite(level) ? level : 0));
          entry.level = l;
          if (!ctx || !osc || !osc2 || !filter) return;
          const t = ctx.currentTime;
          osc.frequency.setTargetAtTime(base * (1 + 1.6 * l), t, 0.1);
          osc2.frequency.setTargetAtTime(base * 0.5 * (1 + 1.6 * l), t, 0.1);
          filter.frequency.setTargetAtTime(250 + 900 * l, t, 0.1);
          entry.gain.gain.setTargetAtTime(l > 0 ? 0.03 + 0.09 * l : 0, t, 0.1);
        },
        stop() {
          stopped = true;
          if (!osc || !ctx) return;
          entry.gain.gain.setTargetAtTime(0, ctx.currentTime, 0.05);
          osc.stop(ctx.currentTime + 0.3);
          osc2?.stop(ctx.currentTime + 0.3);
          engines.delete(entry);
        },
      };
    },
  };
  return sound;
}

const SPEAKER_ON =
  '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M2 6h3l4-3v10l-4-3H2z" fill="currentColor"/><path d="M11 5.5a3.5 3.5 0 0 1 0 5M12.8 3.5a6 6 0 0 1 0 9" fill="none" stroke="currentColor" stroke-width="1.4"/></svg>';
const SPEAKER_OFF =
  '<svg viewBox="0 0 16 16" width="16" height="16" aria-hidden="true"><path d="M2 6h3l4-3v10l-4-3H2z" fill="currentColor"/><path d="M11 6l4 4M15 6l-4 4" stroke="currentColor" stroke-width="1.4"/></svg>';

/**
 * Adds the mute button to `addButton`'s toolbar: a speaker icon that flips `getSound().muted`
 * (pressed while muted). @returns the button.
 */
export function addMuteButton(addButton: (icon: string, label: string, onClick: () => void) => HTMLButtonElement): HTMLButtonElement {
  const s = getSound();
  const sync = (): void => {
    b.innerHTML = s.muted ? SPEAKER_OFF : SPEAKER_ON;
    b.setAttribute('aria-pressed', String(s.muted));
  };
  const b = addButton('mute', 'sound on / off', () => {
    s.muted = !s.muted;
    sync();
  });
  b.classList.add('bp-mute');
  sync();
  return b;
}
