import { inflateSync } from 'node:zlib';

/** A decoded 8-bit PNG: `data` holds width x height pixels of `channels` bytes each (3 RGB or 4 RGBA), row-major. */
export interface DecodedPng {
  /** Width, px. */
  width: number;
  /** Height, px. */
  height: number;
  /** 3 (RGB) or 4 (RGBA). */
  channels: 3 | 4;
  /** Pixel bytes, unfiltered. */
  data: Uint8Array;
}

/**
 * Decodes the PNGs Chromium writes for screenshots: 8-bit RGB or RGBA, not interlaced
 * (PNG specification, ISO/IEC 15948, sections 5 to 9: chunks, zlib stream, per-row filters).
 * @throws Error on a non-PNG buffer or a format outside that subset.
 */
export function decodePng(png: Uint8Array): DecodedPng {
  const sig = [137, 80, 78, 71, 13, 10, 26, 10];
  for (let i = 0; i < 8; i++) if (png[i] !== sig[i]) throw new Error('decodePng: not a PNG file');
  const view = new DataView(png.buffer, png.byteOffset, png.byteLength);
  let offset = 8;
  let width = 0,
    height = 0,
    channels: 3 | 4 = 4;
  const idat: Uint8Array[] = [];
  while (offset < png.length) {
    const length = view.getUint32(offset);
    const type = String.fromCharCode(png[offset + 4]!, png[offset + 5]!, png[offset + 6]!, png[offset + 7]!);
    const body = png.subarray(offset + 8, offset + 8 + length);
    if (type === 'IHDR') {
      width = view.getUint32(offset + 8);
      height = view.getUint32(offset + 12);
      const depth = body[8],
        colorType = body[9],
        interlace = body[12];
      if (depth !== 8 || (colorType !== 2 && colorType !== 6) || interlace !== 0) {
        throw new Error(
          `decodePng: only 8-bit RGB/RGBA non-interlaced PNGs are supported (depth ${depth}, colour type ${colorType}, interlace ${interlace})`,
        );
      }
      channels = colorType === 2 ? 3 : 4;
    } else if (type === 'IDAT') {
      idat.push(body);
    } else if (type === 'IEND') {
      break;
    }
    offset += 12 + length;
  }
  const raw = inflateSync(Buffer.concat(idat));
  const stride = width * channels;
  const data = new Uint8Array(height * stride);
  for (let y = 0; y < height; y++) {
    const filter = raw[y * (stride + 1)]!;
    const src = y * (stride + 1) + 1;
    const dst = y * stride;
    for (let x = 0; x < stride; x++) {
      const r = raw[src + x]!;
      const a = x >= channels ? data[dst + x - channels]! : 0;
      const b = y > 0 ? data[dst + x - stride]! : 0;
      const c = x >= channels && y > 0 ? data[dst + x - stride - channels]! : 0;
      let v: number;
      switch (filter) {
        case 0:
          v = r;
          break;
        case 1:
          v = r + a;
          break;
        case 2:
          v = r + b;
          break;
        case 3:
          v = r + ((a + b) >> 1);
          break;
        case 4: {
          const p = a + b - c;
          const pa = Math.abs(p - a),
            pb = Math.abs(p - b),
            pc = Math.abs(p - c);
          v = r + (pa <= pb && pa <= pc ? a : pb <= pc ? b : c);
          break;
        }
        default:
          throw new Error(`decodePng: bad filter type ${filter} in row ${y}`);
      }
      data[dst + x] = v & 255;
    }
  }
  return { width, height, channels, data };
}

/** Number of distinct colours (RGB, alpha ignored) in a decoded PNG. */
export function distinctColors(image: DecodedPng): number {
  const seen = new Set<number>();
  const { data, channels } = image;
  for (let i = 0; i < data.length; i += channels) seen.add((data[i]! << 16) | (data[i + 1]! << 8) | data[i + 2]!);
  return seen.size;
}
