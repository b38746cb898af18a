/**
 * Procedural planet textures, made in code (no downloaded assets): seeded 3D value noise sampled on
 * the unit sphere, so the equirectangular maps have no seam at the date line and no pinching at the
 * poles. The colour maps are pure functions of (seed, width, height); the canvas is only the container.
 *
 * Noise: value noise on an integer lattice with a hashed value per corner and smoothstep blending
 * (Perlin, "An image synthesizer", SIGGRAPH 1985, section 3), summed over octaves as fractional
 * Brownian motion (Musgrave, in Ebert et al., Texturing and Modeling, ch. 16).
 */

/** 3D value noise in [-1, 1], seeded. */
export function valueNoise3(seed: number): (x: number, y: number, z: number) => number {
  const s = Math.imul(seed | 0, 0x27d4eb2d) ^ 0x165667b1;
  const corner = (i: number, j: number, k: number): number => {
    let h = Math.imul(i, 0x8da6b343) ^ Math.imul(j, 0xd8163841) ^ Math.imul(k, 0xcb1ab31f) ^ s;
    h = Math.imul(h ^ (h >>> 15), 0x2c1b3c6d);
    h = Math.imul(h ^ (h >>> 12), 0x297a2d39);
    h ^= h >>> 15;
    return (h & 0xffffff) / 0x7fffff - 1;
  };
  return (x, y, z) => {
    const xi = Math.floor(x),
      yi = Math.floor(y),
      zi = Math.floor(z);
    const xf = x - xi,
      yf = y - yi,
      zf = z - zi;
    const u = xf * xf * (3 - 2 * xf),
      v = yf * yf * (3 - 2 * yf),
      w = zf * zf * (3 - 2 * zf);
    const c000 = corner(xi, yi, zi),
      c100 = corner(xi + 1, yi, zi),
      c010 = corner(xi, yi + 1, zi),
      c110 = corner(xi + 1, yi + 1, zi);
    const c001 = corner(xi, yi, zi + 1),
      c101 = corner(xi + 1, yi, zi + 1),
      c011 = corner(xi, yi + 1, zi + 1),
      c111 = corner(xi + 1, yi + 1, zi + 1);
    const x00 = c000 + (c100 - c000) * u,
      x10 = c010 + (c110 - c010) * u,
      x01 = c001 + (c101 - c001) * u,
      x11 = c011 + (c111 - c011) * u;
    const y0 = x00 + (x10 - x00) * v,
      y1 = x01 + (x11 - x01) * v;
    return y0 + (y1 - y0) * w;
  };
}

/** Fractional Brownian motion: `octaves` layers of `noise`, each twice the frequency and `gain` the amplitude; about [-1, 1]. */
export function fbm(
  noise: (x: number, y: number, z: number) => number,
  x: number,
  y: number,
  z: number,
  octaves: number,
  gain = 0.5,
): number {
  let sum = 0,
    amp = 1,
    norm = 0,
    f = 1;
  for (let o = 0; o < octaves; o++) {
    sum += amp * noise(x * f + o * 17.1, y * f - o * 9.7, z * f + o * 3.3);
    norm += amp;
    amp *= gain;
    f *= 2.03;
  }
  return sum / norm;
}

/** RGBA pixels of an equirectangular map, row 0 at the north pole (v = 1 in three.js' sphere UVs). */
export interface Pixels {
  width: number;
  height: number;
  data: Uint8ClampedArray;
}

/**
 * Calls `fn(x, y, z, latitude)` for the unit vector of every pixel of a width x height
 * equirectangular map (y up; longitude 0 at +x, growing towards -z, as three.js' SphereGeometry maps u),
 * and stores the [r, g, b, a] it writes into `out`.
 */
function paint(width: number, height: number, fn: (x: number, y: number, z: number, lat: number, out: number[]) => void): Pixels {
  const data = new Uint8ClampedArray(width * height * 4);
  const rgba = [0, 0, 0, 255];
  for (let j = 0; j < height; j++) {
    const lat = Math.PI / 2 - ((j + 0.5) / height) * Math.PI;
    const cl = Math.cos(lat),
      sl = Math.sin(lat);
    for (let i = 0; i < width; i++) {
      const lon = ((i + 0.5) / width) * 2 * Math.PI;
      // three.js SphereGeometry: x = -cos(phi) sin(theta), z = sin(phi) sin(theta) with phi = u 2 pi.
      const x = -Math.cos(lon) * cl,
        z = Math.sin(lon) * cl,
        y = sl;
      rgba[3] = 255;
      fn(x, y, z, lat, rgba);
      const p = (j * width + i) * 4;
      data[p] = rgba[0]!;
      data[p + 1] = rgba[1]!;
      data[p + 2] = rgba[2]!;
      data[p + 3] = rgba[3]!;
    }
  }
  return { width, height, data };
}

function mix(a: readonly number[], b: readonly number[], t: number, out: number[]): void {
  const s = Math.min(1, Math.max(0, t));
  out[0] = a[0]! + (b[0]! - a[0]!) * s;
  out[1] = a[1]! + (b[1]! - a[1]!) * s;
  out[2] = a[2]! + (b[2]! - a[2]!) * s;
}

const DEEP = [8, 30, 72],
  SHALLOW = [28, 92, 150],
  BEACH = [196, 182, 128];
const GREEN = [52, 104, 44],
  FOREST = [30, 72, 34],
  DESERT = [190, 160, 98],
  ROCK = [112, 98, 80],
  SNOW = [240, 244, 248];

/**
 * An Earth-like colour map: continents where a 6-octave fBm exceeds the sea level (about 30% land),
 * oceans shading from shallow to deep with depth, deserts in the subtropics, forests and grass
 * elsewhere, rock and snow on high ground, and polar ice caps with ragged edges.
 */
export function earthPixels(width: number, height: number, seed = 7): Pixels {
  const n = valueNoise3(seed),
    m = valueNoise3(seed + 101);
  const sea = 0.06;
  const tmp = [0, 0, 0];
  return paint(width, height, (x, y, z, lat, out) => {
    const h = fbm(n, x * 1.7, y * 1.7, z * 1.7, 6) + 0.08 * y * y;
    const moist = fbm(m, x * 2.3, y * 2.3, z * 2.3, 4);
    const alat = Math.abs(lat) * (180 / Math.PI);
    if (h < sea) {
      mix(SHALLOW, DEEP, (sea - h) * 5, out);
    } else {
      const e = h - sea;
      // Deserts around 15-35 degrees of latitude where it is dry; forests where it is wet.
      const dry = Math.max(0, 1 - Math.abs(alat - 25) / 14) * (0.6 - moist);
      if (e < 0.015) mix(BEACH, GREEN, e / 0.015, out);
      else {
        mix(GREEN, FOREST, 0.5 + moist * 1.5, tmp);
        mix(tmp, DESERT, dry * 2.2, out);
        if (e > 0.16) {
          mix(out, ROCK, (e - 0.16) * 8, tmp);
          out[0] = tmp[0]!;
          out[1] = tmp[1]!;
          out[2] = tmp[2]!;
        }
        if (e > 0.26) {
          mix(out, SNOW, (e - 0.26) * 10, tmp);
          out[0] = tmp[0]!;
          out[1] = tmp[1]!;
          out[2] = tmp[2]!;
        }
      }
    }
    const ice = alat + moist * 10 - 68;
    if (ice > 0) {
      mix(out, SNOW, ice / 4, tmp);
      out[0] = tmp[0]!;
      out[1] = tmp[1]!;
      out[2] = tmp[2]!;
    }
  });
}

/** A cloud map: white with alpha from a stretched fBm (bands along latitudes), about 40% cover. */
export function cloudPixels(width: number, height: number, seed = 11): Pixels {
  const n = valueNoise3(seed);
  return paint(width, height, (x, y, z, _lat, out) => {
    const c = fbm(n, x * 2.2, y * 4.5, z * 2.2, 5, 0.55);
    out[0] = 255;
    out[1] = 255;
    out[2] = 255;
    out[3] = Math.round(255 * Math.min(0.85, Math.max(0, (c + 0.02) * 2.6)));
  });
}

/** A Moon-like map: grey highlands, darker maria (low-frequency noise) and craters with bright rims. */
export function moonPixels(width: number, height: number, seed = 3): Pixels {
  const n = valueNoise3(seed),
    maria = valueNoise3(seed + 7);
  // Craters: centres on the sphere (seeded), radii in radians.
  const craters: number[] = [];
  let s = seed * 9301 + 49297;
  const rand = (): number => {
    s = (s * 9301 + 49297) % 233280;
    return s / 233280;
  };
  for (let i = 0; i < 90; i++) {
    const u = rand() * 2 - 1,
      phi = rand() * 2 * Math.PI,
      r = Math.sqrt(1 - u * u);
    const radius = 0.02 + 0.09 * rand() ** 3;
    craters.push(r * Math.cos(phi), u, r * Math.sin(phi), radius, Math.cos(1.25 * radius));
  }
  return paint(width, height, (x, y, z, _lat, out) => {
    let g = 150 + 40 * fbm(n, x * 4, y * 4, z * 4, 5);
    const mare = fbm(maria, x * 1.3, y * 1.3, z * 1.3, 3);
    if (mare > 0.1) g -= Math.min(55, (mare - 0.1) * 300);
    for (let i = 0; i < craters.length; i += 5) {
      const dot = x * craters[i]! + y * craters[i + 1]! + z * craters[i + 2]!;
      if (dot < craters[i + 4]!) continue; // farther than 1.25 crater radii
      const d = Math.acos(Math.min(1, dot)) / craters[i + 3]!;
      if (d < 1.25) g += d < 0.85 ? -22 * (1 - d) : 28 * (1 - Math.abs(d - 1) / 0.25);
    }
    out[0] = g;
    out[1] = g * 0.98;
    out[2] = g * 0.95;
  });
}

/** Puts `pixels` on a new canvas (for a three.js CanvasTexture). @throws Error if 2D canvases are unavailable. */
export function toCanvas(pixels: Pixels): HTMLCanvasElement {
  const canvas = document.createElement('canvas');
  canvas.width = pixels.width;
  canvas.height = pixels.height;
  const ctx = canvas.getContext('2d');
  if (!ctx) throw new Error('earth-moon: this browser has no 2D canvas context for the generated textures');
  const image = ctx.createImageData(pixels.width, pixels.height);
  image.data.set(pixels.data);
  ctx.putImageData(image, 0, 0);
  return canvas;
}
