/**
 * Bytes a WebGL2 upload carries from the CPU, from the call's own arguments (what the driver is
 * asked to copy, row padding and unpack parameters aside). The numbers are the WebGL2 enums, so
 * that this stays a table with no context behind it.
 */

const GL = {
  UNSIGNED_BYTE: 0x1401,
  BYTE: 0x1400,
  UNSIGNED_SHORT: 0x1403,
  SHORT: 0x1402,
  UNSIGNED_INT: 0x1405,
  INT: 0x1404,
  FLOAT: 0x1406,
  HALF_FLOAT: 0x140b,
  UNSIGNED_SHORT_4_4_4_4: 0x8033,
  UNSIGNED_SHORT_5_5_5_1: 0x8034,
  UNSIGNED_SHORT_5_6_5: 0x8363,
  UNSIGNED_INT_2_10_10_10_REV: 0x8368,
  UNSIGNED_INT_10F_11F_11F_REV: 0x8c3b,
  UNSIGNED_INT_5_9_9_9_REV: 0x8c3e,
  UNSIGNED_INT_24_8: 0x84fa,
  FLOAT_32_UNSIGNED_INT_24_8_REV: 0x8dad,
  ALPHA: 0x1906,
  RGB: 0x1907,
  RGBA: 0x1908,
  LUMINANCE: 0x1909,
  LUMINANCE_ALPHA: 0x190a,
  RED: 0x1903,
  RG: 0x8227,
  RED_INTEGER: 0x8d94,
  RG_INTEGER: 0x8228,
  RGB_INTEGER: 0x8d98,
  RGBA_INTEGER: 0x8d99,
  DEPTH_COMPONENT: 0x1902,
  DEPTH_STENCIL: 0x84f9,
} as const;

const CHANNELS = new Map<number, number>([
  [GL.ALPHA, 1],
  [GL.LUMINANCE, 1],
  [GL.RED, 1],
  [GL.RED_INTEGER, 1],
  [GL.DEPTH_COMPONENT, 1],
  [GL.LUMINANCE_ALPHA, 2],
  [GL.RG, 2],
  [GL.RG_INTEGER, 2],
  [GL.RGB, 3],
  [GL.RGB_INTEGER, 3],
  [GL.RGBA, 4],
  [GL.RGBA_INTEGER, 4],
]);

const CHANNEL_BYTES = new Map<number, number>([
  [GL.UNSIGNED_BYTE, 1],
  [GL.BYTE, 1],
  [GL.UNSIGNED_SHORT, 2],
  [GL.SHORT, 2],
  [GL.HALF_FLOAT, 2],
  [GL.UNSIGNED_INT, 4],
  [GL.INT, 4],
  [GL.FLOAT, 4],
]);

/** Types that pack a whole texel into one value, whatever its channels. */
const PACKED_TEXEL_BYTES = new Map<number, number>([
  [GL.UNSIGNED_SHORT_4_4_4_4, 2],
  [GL.UNSIGNED_SHORT_5_5_5_1, 2],
  [GL.UNSIGNED_SHORT_5_6_5, 2],
  [GL.UNSIGNED_INT_2_10_10_10_REV, 4],
  [GL.UNSIGNED_INT_10F_11F_11F_REV, 4],
  [GL.UNSIGNED_INT_5_9_9_9_REV, 4],
  [GL.UNSIGNED_INT_24_8, 4],
  [GL.FLOAT_32_UNSIGNED_INT_24_8_REV, 8],
]);

/** Bytes of one texel of `format` and `type` (texImage2D's last two enums); throws on a pair it does not know. */
export function texelBytes(format: number, type: number): number {
  const packed = PACKED_TEXEL_BYTES.get(type);
  if (packed !== undefined) return packed;
  const channels = format === GL.DEPTH_STENCIL ? 1 : CHANNELS.get(format);
  const bytes = CHANNEL_BYTES.get(type);
  if (channels === undefined || bytes === undefined)
    throw new Error(`Unknown texel format 0x${format.toString(16)} / type 0x${type.toString(16)}.`);
  return channels * bytes;
}

/** A pixel source's size: an ImageBitmap, canvas, ImageData, video or image element. */
function sourceSize(source: unknown): [number, number] {
  const s = source as { width?: number; height?: number; naturalWidth?: number; naturalHeight?: number; videoWidth?: number };
  if (typeof s.videoWidth === 'number') return [s.videoWidth, (source as HTMLVideoElement).videoHeight];
  if (typeof s.naturalWidth === 'number') return [s.naturalWidth, s.naturalHeight ?? 0];
  return [s.width ?? 0, s.height ?? 0];
}

/** Whether a call's pixels come from the CPU: an array or an image, not null (allocation only) nor an offset into a bound buffer. */
const fromCpu = (pixels: unknown): boolean => pixels !== null && pixels !== undefined && typeof pixels !== 'number';

/**
 * Bytes texImage2D or texSubImage2D uploads. `args` as the call got them; `sub`: texSubImage2D
 * (two offsets before the size). Both overloads: with a width and a height, or with a pixel source.
 */
export function texImage2DBytes(args: readonly unknown[], sub: boolean): number {
  const first = sub ? 4 : 3; // width, or format when the call takes a pixel source
  if (args.length >= 9) {
    // (target, level, [xoff, yoff | internalformat], width, height, [border], format, type, pixels)
    const width = args[first] as number;
    const height = args[first + 1] as number;
    const at = sub ? first + 2 : first + 3;
    const [format, type, pixels] = [args[at] as number, args[at + 1] as number, args[at + 2]];
    return fromCpu(pixels) ? width * height * texelBytes(format, type) : 0;
  }
  // (target, level, [xoff, yoff | internalformat], format, type, source)
  const [format, type, source] = [args[first] as number, args[first + 1] as number, args[first + 2]];
  if (!fromCpu(source)) return 0;
  const [width, height] = sourceSize(source);
  return width * height * texelBytes(format, type);
}

/** Bytes texImage3D or texSubImage3D uploads (always with a width, a height and a depth). */
export function texImage3DBytes(args: readonly unknown[], sub: boolean): number {
  const first = sub ? 5 : 3;
  const [width, height, depth] = [args[first] as number, args[first + 1] as number, args[first + 2] as number];
  const at = sub ? first + 3 : first + 4;
  const [format, type, pixels] = [args[at] as number, args[at + 1] as number, args[at + 2]];
  return fromCpu(pixels) ? width * height * depth * texelBytes(format, type) : 0;
}

/** Bytes of a typed array from `srcOffset` for `length` elements (0: to its end), as bufferData and bufferSubData read it. */
function viewBytes(data: unknown, srcOffset: unknown, length: unknown): number {
  if (data === null || data === undefined || typeof data === 'number') return 0;
  if (!ArrayBuffer.isView(data)) return (data as ArrayBuffer).byteLength ?? 0;
  const elementBytes = (data as { BYTES_PER_ELEMENT?: number }).BYTES_PER_ELEMENT ?? 1;
  if (typeof length === 'number' && length > 0) return length * elementBytes;
  return data.byteLength - (typeof srcOffset === 'number' ? srcOffset * elementBytes : 0);
}

/** Bytes bufferData uploads: its data's (a size alone allocates and uploads nothing). */
export const bufferDataBytes = (args: readonly unknown[]): number => viewBytes(args[1], args[3], args[4]);

/** Bytes bufferSubData uploads. */
export const bufferSubDataBytes = (args: readonly unknown[]): number => viewBytes(args[2], args[3], args[4]);
