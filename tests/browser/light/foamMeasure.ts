import { PNG } from 'pngjs';
import { SkyPainter, type Rgb } from '../../../src/sim/optics/skyPainter';
import { sunDirection, SUN_IRRADIANCE, SUN_LIGHT_COLOR } from '../../../src/sim/optics/sun';
import { foamReflectance } from '../../../src/sim/optics/foamReflectance';
import { rollOffHighlight } from '../../../src/sim/optics/highlightRollOff';
import { linearToSrgb, srgbToLinear } from '../../support/srgb';

/** An 8-bit sRGB level's linear light, and back. */
const levelToLinear = (level: number): number => srgbToLinear(level / 255);
const linearToLevel = (linear: number): number => 255 * linearToSrgb(linear);

/**
 * Level foam is counted white from: this share of the way, in light, from the water to solid
 * foam, so a pixel counts where foam covers about 70 % of it or more. The earlier fixed 170
 * levels was this same share for the earlier, brighter foam.
 */
const WHITE_FROM = 0.7;

/**
 * Solid, flat foam seen from above with the sun `sunElevation` degrees high, from its measured
 * reflectance (src/sim/optics/foamReflectance.ts) as shaders/foam/foamMaterial.glsl lights it:
 * the sun at its irradiance on a surface tilted from it by 90° − elevation, and the sky straight
 * above (the sky painter's colour, which the GPU's cube paints) over the hemisphere, π L;
 * through the tone curve, in sRGB levels.
 */
export function solidFoamLevels(sunElevation: number): Rgb {
  const sun = sunDirection(sunElevation, 0);
  const skyAbove = new SkyPainter(sun).color([0, 1, 0]).map(srgbToLinear);
  return foamReflectance().map((r, c) => {
    const light = SUN_LIGHT_COLOR[c] * SUN_IRRADIANCE * sun[1] + Math.PI * skyAbove[c];
    return linearToLevel(rollOffHighlight((r * light) / Math.PI));
  }) as Rgb;
}

/** The level a pixel's darkest channel must pass to read as white foam, where the water's darkest channel is at `waterLevel`. */
export function foamWhiteFrom(waterLevel: number, solid: Rgb): number {
  const water = levelToLinear(waterLevel);
  return linearToLevel(water + WHITE_FROM * (levelToLinear(Math.min(...solid)) - water));
}

interface Levels {
  /** Each pixel's darkest channel. */
  darkest: Uint8Array;
  /** Each pixel's largest channel less its darkest. */
  spread: Uint8Array;
  image: PNG;
}

function levels(png: Buffer): Levels {
  const image = PNG.sync.read(png);
  const pixels = image.width * image.height;
  const darkest = new Uint8Array(pixels);
  const spread = new Uint8Array(pixels);
  for (let i = 0; i < pixels; i++) {
    const [r, g, b] = [image.data[4 * i], image.data[4 * i + 1], image.data[4 * i + 2]];
    darkest[i] = Math.min(r, g, b);
    spread[i] = Math.max(r, g, b) - darkest[i];
  }
  return { darkest, spread, image };
}

/** 1 where a pixel reads as white foam: its darkest channel WHITE_FROM of the way from the water's (the picture's median) to solid foam's, grey within 40 levels. */
function whiteMask({ darkest, spread }: Levels, solid: Rgb): Uint8Array {
  const from = foamWhiteFrom(Uint8Array.from(darkest).sort()[Math.floor(darkest.length / 2)], solid);
  return darkest.map((level, i) => (level > from && spread[i] < 40 ? 1 : 0));
}

/** The white foam in a picture of the sea from above, as a mask of 1 and 0. */
export function foamMask(png: Buffer, solid: Rgb): Float64Array {
  return Float64Array.from(whiteMask(levels(png), solid));
}

/** What a picture of the sea from above shows of its foam. */
export interface FoamPicture {
  /** Share of the pixels that read as white foam (foamMask). */
  white: number;
  /** The most common darkest channel among them, levels: solid foam's, where most white pixels lie. */
  peak: number;
  /** Blue less red, levels, at the white pixels within 4 levels of the peak (median): foam's tint. */
  blueOverRed: number;
}

/** The foam in a picture of the sea from above, against solid foam's levels (solidFoamLevels). */
export function measureFoam(png: Buffer, solid: Rgb): FoamPicture {
  const picture = levels(png);
  const { darkest, image } = picture;
  const mask = whiteMask(picture, solid);
  const counts = new Float64Array(256);
  let white = 0;
  for (let i = 0; i < mask.length; i++) {
    if (!mask[i]) continue;
    white++;
    counts[darkest[i]]++;
  }
  // The peak of the white pixels' histogram, smoothed over 9 levels.
  let peak = 0;
  let best = -1;
  for (let level = 4; level < 252; level++) {
    let sum = 0;
    for (let k = -4; k <= 4; k++) sum += counts[level + k];
    if (sum > best) [best, peak] = [sum, level];
  }
  const tints: number[] = [];
  for (let i = 0; i < mask.length; i++) {
    if (mask[i] && Math.abs(darkest[i] - peak) <= 4) tints.push(image.data[4 * i + 2] - image.data[4 * i]);
  }
  tints.sort((a, b) => a - b);
  return { white: white / mask.length, peak, blueOverRed: tints[Math.floor(tints.length / 2)] ?? 0 };
}
