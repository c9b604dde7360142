import { describe, expect, it } from 'vitest';
import {
  GOD_RAY_RANGE,
  planShaftLightTile,
  SHAFT_LIGHT_TEXEL,
  SHAFT_LIGHT_WINDOW_SIDE,
  type ShaftLightTile,
} from '../../../../src/render/underwater/shaftLightTile';
import { refractedSunDirection, type Vec3 } from '../../../../src/sim/underwater/snellWindow';
import { seededRandom } from '../../../../src/sim/noise/integerHash';
import { BLUR_MAX_RADIUS, BLUR_MAX_TAPS, halfResolutionSigma, linearSampledKernel } from '../../../../src/render/underwater/gaussianKernel';
import { paramDefs } from '../../../../src/sim/params/params';

/** Every point the god-ray march of shaders/underwater.frag reads, for one line of sight. */
function marchReads(eye: Vec3, d: Vec3, r: Vec3, steps = 40): [number, number][] {
  const reads: [number, number][] = [];
  for (let i = 0; i <= steps; i++) {
    const t = (GOD_RAY_RANGE * i) / steps;
    const p: Vec3 = [eye[0] + d[0] * t, eye[1] + d[1] * t, eye[2] + d[2] * t];
    if (p[1] >= 0) continue; // above the surface: the march adds nothing there
    reads.push([p[0] - (r[0] * p[1]) / r[1], p[2] - (r[2] * p[1]) / r[1]]);
  }
  return reads;
}

/** Reads that fall outside the baked window (its texel centres span [origin + texel/2, origin + extent − texel/2]). */
function outside(tile: ShaftLightTile, reads: [number, number][]): number {
  const lo = SHAFT_LIGHT_TEXEL / 2;
  const hi = tile.extent - SHAFT_LIGHT_TEXEL / 2;
  return reads.filter(([x, z]) => [x - tile.origin[0], z - tile.origin[1]].some((u) => u < lo || u > hi)).length;
}

function unit(random: () => number): Vec3 {
  for (;;) {
    const v: Vec3 = [2 * random() - 1, 2 * random() - 1, 2 * random() - 1];
    const n = Math.hypot(...v);
    if (n > 0.1 && n <= 1) return [v[0] / n, v[1] / n, v[2] / n];
  }
}

function scenes(seed: number, count: number) {
  const random = seededRandom(seed);
  return Array.from({ length: count }, () => {
    // Suns from the zenith to 1° above the horizon, which lean the refracted ray the most.
    const elevation = (1 + 89 * random()) * (Math.PI / 180);
    const azimuth = 2 * Math.PI * random();
    const sun: Vec3 = [Math.cos(elevation) * Math.cos(azimuth), Math.sin(elevation), Math.cos(elevation) * Math.sin(azimuth)];
    const eye: Vec3 = [2e4 * (random() - 0.5), -40 * random() + 1, 2e4 * (random() - 0.5)];
    return { eye, r: refractedSunDirection(sun) as Vec3, lines: Array.from({ length: 40 }, () => unit(random)) };
  });
}

describe('planShaftLightTile', () => {
  it('bakes one period of a lens that repeats on a small tile (the seed: 96 m in 256 texels, at the origin)', () => {
    const tile = planShaftLightTile(96, [500, -3, -700], [0.3, -0.9, 0.1]);
    expect(tile).toEqual({ kind: 'tile', origin: [0, 0], extent: 96, size: 256 });
  });

  it('bakes a window when the lens does not repeat, or repeats only on a patch larger than the window', () => {
    expect(planShaftLightTile(null, [0, -3, 0], [0, -1, 0]).kind).toBe('window');
    expect(planShaftLightTile(SHAFT_LIGHT_WINDOW_SIDE * 2, [0, -3, 0], [0, -1, 0]).kind).toBe('window');
  });

  it('puts the window where every god-ray read of every line of sight falls, for any sun and eye', () => {
    let reads = 0;
    for (const { eye, r, lines } of scenes(7, 300)) {
      const tile = planShaftLightTile(null, eye, r);
      // The corner is on the texel lattice, so the baked points stay put as the camera moves.
      for (const o of tile.origin) expect(Math.abs(o / SHAFT_LIGHT_TEXEL - Math.round(o / SHAFT_LIGHT_TEXEL))).toBeLessThan(1e-9);
      for (const d of lines) {
        const line = marchReads(eye, d, r);
        reads += line.length;
        expect(outside(tile, line)).toBe(0);
      }
    }
    expect(reads).toBeGreaterThan(100000);
  });

  it('negative control: a window centred on the eye, ignoring where the sun ray crosses the surface, misses reads', () => {
    let missed = 0;
    for (const { eye, r, lines } of scenes(7, 300)) {
      const tile = planShaftLightTile(null, eye, r);
      const naive: ShaftLightTile = { ...tile, origin: [eye[0] - tile.extent / 2, eye[2] - tile.extent / 2] };
      for (const d of lines) missed += outside(naive, marchReads(eye, d, r));
    }
    expect(missed).toBeGreaterThan(100);
  });
});

describe('half-resolution blur sizing', () => {
  it('fits the widest blur the parameter allows in BLUR_MAX_RADIUS and BLUR_MAX_TAPS', () => {
    const sigma = halfResolutionSigma(paramDefs.blurStrength.max);
    expect(Math.ceil(3 * sigma)).toBeLessThanOrEqual(BLUR_MAX_RADIUS);
    expect(() => linearSampledKernel(sigma, BLUR_MAX_RADIUS, BLUR_MAX_TAPS)).not.toThrow();
    // Negative control: twice that σ does not fit the shader's loop.
    expect(() => linearSampledKernel(2 * sigma, 2 * BLUR_MAX_RADIUS, BLUR_MAX_TAPS)).toThrow(RangeError);
  });

  it('adds to the resampling only what it lacks: overall variance σ² = 1 px² + (2 σ_half)²', () => {
    for (const sigma of [1, 1.5, 3, 8]) expect(1 + (2 * halfResolutionSigma(sigma)) ** 2).toBeCloseTo(sigma * sigma, 10);
    expect(halfResolutionSigma(0.5)).toBe(0);
  });
});
