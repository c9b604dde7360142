import { describe, expect, it } from 'vitest';
import { LESSON_TEXTS } from '../../../../../src/app/lessons/lessonTexts';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import { SECTION_NAMES, LESSON_OUTLINE, LESSON_TITLES } from '../../../../../src/app/lessons/lessonOutline';
import { BIBLIOGRAPHY } from '../../../../../src/app/lessons/bibliography';
import { PRESETS } from '../../../../../src/app/url/presets';
import { defaultParams } from '../../../../../src/sim/params/params';
import { BASE_STEP, BAND_STEPS, bandForDistance, MAX_LOD_BANDS } from '../../../../../src/sim/lod/lodBands';
import {
  GRAVITY,
  HEIGHTMAP_SIZE,
  NORMAL_DELTA,
  RIPPLE_TILE_SIZE,
  SECOND_SWELL,
  rippleHeight,
  surfaceNormal,
  surfaceStateAt,
  swellHeight,
  type SurfaceState,
} from '../../../../../src/sim/waves/seed/seedSurface';
import { integerNoise } from '../../../../../src/sim/noise/integerHash';
import {
  cosineInterpolate,
  defaultNoiseSettings,
  generateRippleHeightmaps,
  octaveSeed,
  smoothedLattice,
} from '../../../../../src/sim/noise/perlinNoise';
import { integerLattice, noiseStages, TEACHING_OCTAVE } from '../../../../../src/sim/noise/noiseStages';

/**
 * The seed group's cards (surface, motion, noise, normals) held to the code: every number
 * they state is read out of the card's text or MathML and compared with what the code
 * computes, so changing either alone fails here. Each kind of check has a planted fault.
 */

const card = (id: string) => LESSON_TEXTS[id];
/** Every number in a string, decimal comma or point, with its sign (−). */
const numbers = (s: string) =>
  [...s.replace(/(\d),(\d)/g, '$1.$2').matchAll(/[−-]?\d+(?:\.\d+)?/g)].map((m) => Number(m[0].replace('−', '-')));
/** The number right after `label` in `s` (decimal comma or point). */
function numberAfter(s: string, label: string): number {
  const i = s.indexOf(label);
  if (i < 0) throw new Error(`“${label}” not in “${s.slice(0, 60)}…”`);
  const match = s
    .slice(i + label.length)
    .replace(/(\d),(\d)/g, '$1.$2')
    .match(/-?\d+(?:\.\d+)?/);
  if (!match) throw new Error(`no number after “${label}”`);
  return Number(match[0]);
}
/** The <mn> numbers of a card's MathML, in order. */
const mathNumbers = (id: string) => [...card(id).math.matchAll(/<mn>([^<]+)<\/mn>/g)].map((m) => Number(m[1]));
/** A stated number agrees with the code to the digits it is written with. */
const agrees = (stated: number, actual: number) => {
  const text = String(stated);
  const decimals = text.includes('.') ? text.split('.')[1].length : 0;
  return Math.abs(stated - actual) <= 0.5 * 10 ** -decimals + 1e-12;
};
const both = (id: string) => [card(id).text.en, card(id).text.es];

function correlation(a: ArrayLike<number>, b: ArrayLike<number>): number {
  const n = a.length;
  let ma = 0,
    mb = 0;
  for (let i = 0; i < n; i++) {
    ma += a[i];
    mb += b[i];
  }
  ma /= n;
  mb /= n;
  let sab = 0,
    saa = 0,
    sbb = 0;
  for (let i = 0; i < n; i++) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) ** 2;
    sbb += (b[i] - mb) ** 2;
  }
  return sab / Math.sqrt(saa * sbb);
}
const std = (a: ArrayLike<number>) => {
  let m = 0;
  for (let i = 0; i < a.length; i++) m += a[i];
  m /= a.length;
  let v = 0;
  for (let i = 0; i < a.length; i++) v += (a[i] - m) ** 2;
  return Math.sqrt(v / a.length);
};

const SEED_CARDS = [
  'flat-plane',
  'displaced-plane',
  'swell',
  'swell-maximum',
  'perlin-hash',
  'perlin-smoothing',
  'perlin-octaves',
  'heightmap-blend',
  'normals-wrong',
  'normals-right',
];

describe('the seed cards: every card has a question, references that exist', () => {
  it.each(SEED_CARDS)('%s: a question in both languages, answers ≤ 60 words, choice ≤ 30, references in the bibliography', (id) => {
    const { question, choice, references } = card(id);
    expect(question).toBeDefined();
    for (const language of ['en', 'es'] as const) {
      expect(question!.ask[language].length).toBeGreaterThan(10);
      expect(question!.answer[language].trim().split(/\s+/).length).toBeLessThanOrEqual(60);
      if (choice) expect(choice[language].trim().split(/\s+/).length).toBeLessThanOrEqual(30);
    }
    for (const key of references ?? []) expect(Object.keys(BIBLIOGRAPHY)).toContain(key);
  });

  it('the noise section and its cards name value noise beside the report’s “Perlin”', () => {
    expect(SECTION_NAMES.noise.en).toMatch(/value noise/i);
    expect(SECTION_NAMES.noise.en).toMatch(/Perlin/);
    expect(SECTION_NAMES.noise.es).toMatch(/ruido de valor/i);
    expect(card('perlin-hash').text.en).toMatch(/value noise/);
    expect(card('perlin-hash').text.es).toMatch(/ruido de valor/);
    expect(LESSON_TITLES['swell-maximum'].en).toMatch(/wavenumber/);
    expect(LESSON_OUTLINE['perlin-hash'].section).toBe('noise');
  });
});

describe('flat-plane: the bands as the code makes them', () => {
  const view = lessonView(findLesson('flat-plane')!);
  const cameraHeight = view.camera.position[1];
  /** Metres between vertices of the nearest chunk, seen from `height` with LOD distance L. */
  const nearestSpacing = (height: number, L: number) => BAND_STEPS[bandForDistance(height, L, MAX_LOD_BANDS)] * BASE_STEP;

  it('2 m between vertices near the camera, L = 100 m the default, every 2nd and 3rd vertex in the next bands', () => {
    for (const text of both('flat-plane')) {
      expect(numbers(text)[0]).toBe(BASE_STEP);
      expect(numberAfter(text, 'L = ')).toBe(defaultParams().lodDistance);
    }
    expect([BAND_STEPS[1], BAND_STEPS[2]]).toEqual([2, 3]);
    expect(bandForDistance(1.5 * view.params.lodDistance, view.params.lodDistance, MAX_LOD_BANDS)).toBe(1);
    expect(view.params.swellAmplitude).toBe(0);
    expect(view.params.rippleStrength).toBe(0);
  });

  it('the question: from 45 m up, L = 10 m leaves the nearest chunk every 6th vertex, 12 m apart; L = 100 m keeps 2 m', () => {
    const { en, es } = card('flat-plane').question!.answer;
    expect(numberAfter(card('flat-plane').question!.ask.en, 'stands ')).toBe(cameraHeight);
    expect(cameraHeight).toBe(45);
    for (const text of [en, es]) {
      expect(numberAfter(text, '4L = ')).toBe(4 * 10);
      expect(numbers(text)).toContain(nearestSpacing(cameraHeight, 10));
      expect(numbers(text)).toContain(BAND_STEPS[bandForDistance(cameraHeight, 10, MAX_LOD_BANDS)]);
    }
    expect(nearestSpacing(cameraHeight, 100)).toBe(2);
  });

  /** The spacing the answer states: “12 m apart” / “12 m entre ellos”. */
  const statedSpacing = (text: string) => Number(text.match(/(\d+) m (?:apart|entre)/)![1]);

  it('the answer’s spacing is the code’s, in both languages', () => {
    const { en, es } = card('flat-plane').question!.answer;
    for (const text of [en, es]) expect(statedSpacing(text)).toBe(nearestSpacing(cameraHeight, 10));
  });

  it('control: from 35 m up (inside 4L) the nearest chunk would be 6 m apart, not the card’s 12', () => {
    expect(statedSpacing(card('flat-plane').question!.answer.en)).not.toBe(nearestSpacing(35, 10));
  });
});

describe('displaced-plane and swell: the numbers and the identity', () => {
  it('displaced-plane states the default swell amplitude and ripple strength, and the swell’s repeat 2π/k ≈ 126 m', () => {
    const p = lessonView(findLesson('displaced-plane')!).params;
    for (const text of both('displaced-plane')) {
      expect(numberAfter(text, 's (')).toBeGreaterThan(0);
      expect(numbers(text)).toContain(p.swellAmplitude);
      expect(numbers(text)).toContain(p.rippleStrength);
    }
    const repeat = numberAfter(card('displaced-plane').question!.answer.en, '≈ ');
    expect(agrees(repeat, (2 * Math.PI) / p.swellFrequency)).toBe(true);
    expect(agrees(repeat, (2 * Math.PI) / 0.06)).toBe(false);
  });

  const swellMath = mathNumbers('swell');
  const cosineRate = swellMath[0];
  const [fast, slow] = [swellMath[2], swellMath[3]];

  it('the code’s phases: the sine’s ω t with ω = √(g k), the cosine’s at the card’s 0.7 ω; the second product’s 0.45, 1.73, 37°', () => {
    const k = 0.05;
    const t = 3.7;
    const state = surfaceStateAt({ ...defaultParams(), swellFrequency: k }, t);
    const omega = Math.sqrt(GRAVITY * k);
    expect(state.swellPhase[0]).toBeCloseTo((omega * t) % (2 * Math.PI), 12);
    expect(state.swellPhase[1]).toBeCloseTo((cosineRate * omega * t) % (2 * Math.PI), 12);
    for (const text of both('swell')) {
      expect(numberAfter(text, 'g = ')).toBe(GRAVITY);
      expect(numbers(text)).toContain(SECOND_SWELL.amplitude);
      expect(numbers(text)).toContain(SECOND_SWELL.frequency);
      expect(agrees(Number(text.match(/(\d+)°/)![1]), (Math.atan2(SECOND_SWELL.sin, SECOND_SWELL.cos) * 180) / Math.PI)).toBe(true);
    }
  });

  /** The first product, the code's way: swellHeight less the second product (which the state lets us null). */
  const firstProduct = (state: SurfaceState, x: number, z: number) =>
    swellHeight({ ...state, swellPhase: [state.swellPhase[0], state.swellPhase[1], 0, 0] }, x, z) -
    state.swellAmplitude *
      SECOND_SWELL.amplitude *
      Math.sin(state.swellFrequency * SECOND_SWELL.frequency * (SECOND_SWELL.cos * x + SECOND_SWELL.sin * z)) *
      Math.cos(state.swellFrequency * SECOND_SWELL.frequency * (-SECOND_SWELL.sin * x + SECOND_SWELL.cos * z));
  const diagonalWaves = (A: number, k: number, omega: number, t: number, x: number, z: number, a: number, b: number) =>
    (A / 2) * (Math.sin(k * (x + z) + a * omega * t) + Math.sin(k * (x - z) + b * omega * t));

  it('the identity: the code’s first product is the card’s two diagonal plane waves at 1.7 ω and 0.3 ω', () => {
    const k = 0.05;
    const omega = Math.sqrt(GRAVITY * k);
    for (const t of [0, 1.3, 7.9]) {
      const state = surfaceStateAt({ ...defaultParams(), swellFrequency: k }, t);
      for (const [x, z] of [
        [0, 0],
        [13, -40],
        [-77, 21],
      ]) {
        expect(firstProduct(state, x, z)).toBeCloseTo(diagonalWaves(state.swellAmplitude, k, omega, t, x, z, fast, slow), 9);
      }
    }
    expect(fast).toBeCloseTo(1 + cosineRate, 12);
    expect(slow).toBeCloseTo(1 - cosineRate, 12);
  });

  it('control: a planted 1.6 ω in place of 1.7 ω breaks the identity', () => {
    const k = 0.05;
    const omega = Math.sqrt(GRAVITY * k);
    const state = surfaceStateAt({ ...defaultParams(), swellFrequency: k }, 7.9);
    expect(Math.abs(firstProduct(state, 13, -40) - diagonalWaves(state.swellAmplitude, k, omega, 7.9, 13, -40, 1.6, slow))).toBeGreaterThan(
      1e-3,
    );
  });

  it('neither diagonal wave follows dispersion: a wave of √2 k has ω·2^¼ ≈ 1.19 ω', () => {
    const ratio = Math.sqrt(GRAVITY * Math.SQRT2 * 0.05) / Math.sqrt(GRAVITY * 0.05);
    for (const text of both('swell')) expect(agrees(numberAfter(text, 'k) ≈ '), ratio)).toBe(true);
    expect(Math.abs(fast - ratio)).toBeGreaterThan(0.4);
    expect(Math.abs(slow - ratio)).toBeGreaterThan(0.8);
  });

  it('the question: a bump moves √(1 + 0.7²)·√(g/k): about 17 m/s at 0.05, 8.5 at 0.2; ω = √(g k) from 0.70 to 1.40 rad/s', () => {
    const speed = (k: number) => Math.hypot(1, cosineRate) * Math.sqrt(GRAVITY / k);
    const omega = (k: number) => Math.sqrt(GRAVITY * k);
    for (const text of [card('swell').question!.answer.en, card('swell').question!.answer.es]) {
      const plain = text.replace(/(\d),(\d)/g, '$1.$2');
      const [v1, v2] = [...plain.matchAll(/(\d+(?:\.\d+)?) m\/s/g)].map((m) => Number(m[1]));
      expect(agrees(v1, speed(0.05))).toBe(true);
      expect(agrees(v2, speed(0.2))).toBe(true);
      const [, w1, w2] = plain.match(/(\d+\.\d+) (?:to|a) (\d+\.\d+) rad\/s/)!.map(Number);
      expect(agrees(w1, omega(0.05))).toBe(true);
      expect(agrees(w2, omega(0.2))).toBe(true);
      // Four times closer (2π/k) at half the speed: twice as often past a point, as ω says.
      expect(speed(0.2) / ((2 * Math.PI) / 0.2) / (speed(0.05) / ((2 * Math.PI) / 0.05))).toBeCloseTo(w2 / w1, 2);
    }
    // A bump is where sin = 1 and cos = ±1: check it moves so in the code.
    const k = 0.05;
    const at = (t: number) => surfaceStateAt({ ...defaultParams(), swellFrequency: k }, t);
    const s0 = at(0);
    const s1 = at(1);
    const dx = -(s1.swellPhase[0] - s0.swellPhase[0]) / k;
    const dz = -(s1.swellPhase[1] - s0.swellPhase[1]) / k;
    expect(Math.hypot(dx, dz)).toBeCloseTo(speed(k), 9);
  });

  it('control: a planted 14 m/s (ω/k alone) is not the bumps’ speed at 0.05', () => {
    expect(agrees(14, Math.hypot(1, cosineRate) * Math.sqrt(GRAVITY / 0.05))).toBe(false);
  });

  // The card: the first product slides rigidly towards −x and −z; the second slides another way, so the sum changes shape.
  const k = 0.05;
  const omega = Math.sqrt(GRAVITY * k);
  const velocity: [number, number] = [-omega / k, (-cosineRate * omega) / k];
  const at = (t: number) => surfaceStateAt({ ...defaultParams(), swellFrequency: k }, t);
  const points = [
    [0, 0],
    [13, -40],
    [-77, 21],
    [250, 310],
  ];

  it('the first product keeps its shape: at time t it is the pattern of t = 0 moved by (−ω/k, −0.7 ω/k) t', () => {
    for (const text of both('swell')) expect(text).toContain('−x');
    for (const t of [2.5, 11]) {
      for (const [x, z] of points) {
        expect(firstProduct(at(t), x, z)).toBeCloseTo(firstProduct(at(0), x - velocity[0] * t, z - velocity[1] * t), 9);
      }
    }
  });

  it('control: the whole swell, moved at that velocity, is not the same pattern (the second product slides another way)', () => {
    const t = 11;
    const worst = Math.max(
      ...points.map(([x, z]) => Math.abs(swellHeight(at(t), x, z) - swellHeight(at(0), x - velocity[0] * t, z - velocity[1] * t))),
    );
    expect(worst).toBeGreaterThan(0.1);
  });

  it('only the first product repeats every 2π/k: the whole swell does not (displaced-plane’s and swell-maximum’s “the first”)', () => {
    for (const id of ['displaced-plane', 'swell-maximum']) {
      const text = id === 'displaced-plane' ? card(id).question!.answer.en : card(id).text.en;
      expect(text).toContain('the first');
    }
    const lambda = (2 * Math.PI) / k;
    const state = at(3);
    for (const [x, z] of points) expect(firstProduct(state, x + lambda, z)).toBeCloseTo(firstProduct(state, x, z), 9);
    const worst = Math.max(...points.map(([x, z]) => Math.abs(swellHeight(state, x + lambda, z) - swellHeight(state, x, z))));
    expect(worst).toBeGreaterThan(0.1);
  });
});

describe('swell-maximum: the preset’s λ, H/λ and slopes', () => {
  const p = lessonView(findLesson('swell-maximum')!).params;
  const lambda = (2 * Math.PI) / p.swellFrequency;

  it('A = 4 m, k = 0.2 are the preset’s and the ranges’ tops; λ = 2π/k ≈ 31 m; H/λ = 2A/λ ≈ 0.25 > 1/7', () => {
    for (const text of both('swell-maximum')) {
      expect(numberAfter(text, 'A = ')).toBe(p.swellAmplitude);
      expect(numberAfter(text, 'k = ')).toBe(p.swellFrequency);
      expect(agrees(numberAfter(text, '2π/k ≈ '), lambda)).toBe(true);
      expect(agrees(numberAfter(text, 'H/λ ≈ '), (2 * p.swellAmplitude) / lambda)).toBe(true);
    }
    const [, mathLambda, , ratio, one, seven] = mathNumbers('swell-maximum');
    expect(agrees(mathLambda, lambda)).toBe(true);
    expect(agrees(ratio, (2 * p.swellAmplitude) / lambda)).toBe(true);
    expect(ratio).toBeGreaterThan(one / seven);
    expect(PRESETS['swell-maximum'].params.swellAmplitude).toBe(4);
  });

  it('the first product’s steepest slope is A k (measured on the code’s swell): 0.8 at 4 m, 0.2 at 1 m; H/λ 0.064 at 1 m', () => {
    const steepest = (A: number) => {
      const state = { ...surfaceStateAt({ ...p, swellAmplitude: A }, 0) };
      let best = 0;
      const h = 1e-4;
      for (let x = 0; x < lambda; x += lambda / 64) {
        for (let z = 0; z < lambda; z += lambda / 64) {
          const gx = (firstOnly(state, x + h, z) - firstOnly(state, x - h, z)) / (2 * h);
          const gz = (firstOnly(state, x, z + h) - firstOnly(state, x, z - h)) / (2 * h);
          best = Math.max(best, Math.hypot(gx, gz));
        }
      }
      return best;
    };
    const firstOnly = (state: SurfaceState, x: number, z: number) =>
      state.swellAmplitude *
      Math.sin(state.swellFrequency * x + state.swellPhase[0]) *
      Math.cos(state.swellFrequency * z + state.swellPhase[1]);
    const answer = card('swell-maximum').question!.answer;
    for (const text of [answer.en, answer.es]) {
      const [[s4, deg4], [s1, deg1]] = [...text.replace(/(\d),(\d)/g, '$1.$2').matchAll(/(\d+(?:\.\d+)?) \((\d+)°\)/g)].map((m) => [
        Number(m[1]),
        Number(m[2]),
      ]);
      expect(agrees(s4, steepest(4))).toBe(true);
      expect(agrees(deg4, (Math.atan(steepest(4)) * 180) / Math.PI)).toBe(true);
      expect(agrees(s1, steepest(1))).toBe(true);
      expect(agrees(deg1, (Math.atan(steepest(1)) * 180) / Math.PI)).toBe(true);
      expect(agrees(Number(text.replace(/(\d),(\d)/g, '$1.$2').match(/(0\.0\d+)/)![1]), 2 / lambda)).toBe(true);
    }
    expect(agrees(0.6, steepest(4))).toBe(false);
  });
});

describe('the noise cards: value noise as perlinNoise.ts builds it', () => {
  const cells = defaultNoiseSettings.baseCells << TEACHING_OCTAVE;

  it('perlin-hash: a 16 × 16 lattice, values in [−1, 1) as h/2³¹ − 1, the same for the same point and seed', () => {
    for (const text of both('perlin-hash')) expect(text).toContain(`${cells} × ${cells}`);
    expect(noiseStages(1, 32).hash.size).toBe(cells);
    expect(mathNumbers('perlin-hash')).toEqual([2, 31, 1, 1, 1]);
    let lo = Infinity,
      hi = -Infinity;
    for (let i = 0; i < 20000; i++) {
      const v = integerNoise(i * 7 - 5000, i % 131, 3);
      lo = Math.min(lo, v);
      hi = Math.max(hi, v);
    }
    expect(lo).toBeGreaterThanOrEqual(-1);
    expect(hi).toBeLessThan(1);
    expect(lo).toBeLessThan(-0.99);
    expect(integerNoise(5, 9, 2)).toBe(integerNoise(5, 9, 2));
  });

  it('perlin-hash’s question: seed 1 and seed 2 give unrelated lattices (correlation near zero); the same seed the same one', () => {
    const lattice = (seed: number) => integerLattice(128, octaveSeed(seed * 2, TEACHING_OCTAVE));
    expect(Math.abs(correlation(lattice(1), lattice(2)))).toBeLessThan(0.03);
    expect(Math.abs(correlation(noiseStages(1, 16).hash.data, noiseStages(2, 16).hash.data))).toBeLessThan(0.25);
    // Control: the same seed is perfectly correlated.
    expect(correlation(lattice(1), lattice(1))).toBeCloseTo(1, 12);
  });

  it('perlin-smoothing: weights 1/4, 1/8, 1/16 as the code’s, adding to one; σ falls to 3/8; the right square correlates 0.67 with the left', () => {
    const [n4, e8, c16] = mathNumbers('perlin-smoothing');
    expect([n4, e8, c16]).toEqual([4, 8, 16]);
    expect(1 / n4 + 4 / e8 + 4 / c16).toBe(1);
    const seed = 12345;
    const big = 256;
    const raw = integerLattice(big, seed);
    const smooth = smoothedLattice(big, seed);
    // The code's own lattice at one point, against the card's formula.
    const r = (x: number, y: number) => raw[((y + big) % big) * big + ((x + big) % big)];
    const x = 17,
      y = 40;
    expect(smooth[y * big + x]).toBeCloseTo(
      r(x, y) / n4 +
        (r(x - 1, y) + r(x + 1, y) + r(x, y - 1) + r(x, y + 1)) / e8 +
        (r(x - 1, y - 1) + r(x + 1, y - 1) + r(x - 1, y + 1) + r(x + 1, y + 1)) / c16,
      14,
    );
    const ratio = std(smooth) / std(raw);
    expect(Math.sqrt(1 / 16 + 4 / 64 + 4 / 256)).toBe(3 / 8);
    expect(ratio).toBeGreaterThan(0.36);
    expect(ratio).toBeLessThan(0.39);
    for (const text of both('perlin-smoothing')) expect(text).toContain('3/8');
    const stated = numberAfter(card('perlin-smoothing').question!.answer.en, '≈ ');
    expect(agrees(stated, 0.25 / 0.375)).toBe(true);
    expect(Math.abs(correlation(raw, smooth) - stated)).toBeLessThan(0.02);
    // Control: a planted 1/2 is not the spread.
    expect(Math.abs(ratio - 0.5)).toBeGreaterThan(0.1);
  });

  it('perlin-octaves: five octaves of 4·2ᵒ cells, p = 0.62, cosine curve flat at both ends, H₀ centred with peak 1, 128 texels over 96 m', () => {
    const { en, es } = card('perlin-octaves').text;
    for (const text of [en, es]) {
      expect(agrees(numberAfter(text, 'p = '), defaultNoiseSettings.persistence)).toBe(true);
      expect(text).toContain(`${defaultNoiseSettings.baseCells}·2ᵒ`);
      expect(text).toContain(`${HEIGHTMAP_SIZE} × ${HEIGHTMAP_SIZE}`);
      expect(numbers(text)).toContain(RIPPLE_TILE_SIZE);
    }
    expect(en).toContain(`(0 to ${defaultNoiseSettings.octaves - 1})`);
    expect(cosineInterpolate(0, 1, 0.5)).toBeCloseTo((1 - Math.cos(Math.PI * 0.5)) / 2, 15);
    expect(cosineInterpolate(0, 1, 1e-4) - cosineInterpolate(0, 1, 0)).toBeLessThan(1e-7);
    const [h0] = generateRippleHeightmaps(1, HEIGHTMAP_SIZE);
    let sum = 0,
      peak = 0;
    for (const v of h0.data) {
      sum += v;
      peak = Math.max(peak, Math.abs(v));
    }
    expect(Math.abs(sum / h0.data.length)).toBeLessThan(1e-6);
    expect(peak).toBeCloseTo(1, 6);
    expect(noiseStages(1, HEIGHTMAP_SIZE).octaves.data).toEqual(h0.data);
  });

  it('perlin-octaves’ question: octave 2 enters with 0.62² ≈ 0.38; the left and right pictures correlate about 0.3', () => {
    const answer = card('perlin-octaves').question!.answer.en;
    expect(agrees(numberAfter(answer, '0.62² ≈ '), defaultNoiseSettings.persistence ** 2)).toBe(true);
    const stated = numberAfter(answer, 'correlation about ');
    const stages = noiseStages(lessonView(findLesson('perlin-octaves')!).params.seed, HEIGHTMAP_SIZE);
    const r = correlation(stages.interpolated.data, stages.octaves.data);
    expect(Math.abs(r - stated)).toBeLessThan(0.15);
    // Control: the pictures are not near-copies.
    expect(r).toBeLessThan(0.6);
  });
});

describe('heightmap-blend: the weight, the drifts, the period in space', () => {
  const p = lessonView(findLesson('heightmap-blend')!).params;

  it('b = (1 − cos βt)/2 as the code’s rippleBlend, β = 0.25 rad/s the default, a swing every 2π/β ≈ 25 s, H₁ alone 12.6 s after H₀', () => {
    for (const t of [0, 3, 11.1, 40]) expect(surfaceStateAt(p, t).rippleBlend).toBeCloseTo((1 - Math.cos(p.rippleBlendSpeed * t)) / 2, 12);
    const period = (2 * Math.PI) / p.rippleBlendSpeed;
    for (const text of both('heightmap-blend')) {
      expect(numbers(text)).toContain(p.rippleBlendSpeed);
      expect(agrees(numberAfter(text, 'rad/s'), period)).toBe(true);
      expect(numbers(text)).toContain(p.rippleStrength);
    }
    const answer = card('heightmap-blend').question!.answer.en;
    expect(agrees(numberAfter(answer, '≈ '), period)).toBe(true);
    expect(agrees(numberAfter(answer, 'about '), period / 2)).toBe(true);
    expect(surfaceStateAt(p, period).rippleBlend).toBeCloseTo(0, 12);
    expect(surfaceStateAt(p, period / 2).rippleBlend).toBeCloseTo(1, 12);
  });

  it('the drifts are 0.59 and 0.51 m/s, and at any instant the ripples repeat every 96 m', () => {
    // One second's offsets, brought back from the tile's wrap into (−tile/2, tile/2].
    const unwrap = (o: number) => (o > RIPPLE_TILE_SIZE / 2 ? o - RIPPLE_TILE_SIZE : o);
    const o = surfaceStateAt(p, 1).rippleOffset.map(unwrap);
    const speeds = [Math.hypot(o[0], o[1]), Math.hypot(o[2], o[3])];
    for (const text of both('heightmap-blend')) {
      const stated = numbers(text).filter((n) => n > 0.4 && n < 0.7);
      expect(stated.length).toBe(2);
      expect(agrees(stated[0], speeds[0])).toBe(true);
      expect(agrees(stated[1], speeds[1])).toBe(true);
      expect(numbers(text)).toContain(RIPPLE_TILE_SIZE);
    }
    const maps = generateRippleHeightmaps(p.seed, HEIGHTMAP_SIZE);
    const state = surfaceStateAt(p, 17.3);
    for (const [x, z] of [
      [3.3, 7.1],
      [-40.2, 12.9],
    ]) {
      expect(rippleHeight(state, maps, x + RIPPLE_TILE_SIZE, z)).toBeCloseTo(rippleHeight(state, maps, x, z), 9);
      expect(rippleHeight(state, maps, x, z - RIPPLE_TILE_SIZE)).toBeCloseTo(rippleHeight(state, maps, x, z), 9);
      // Control: half a tile away is another height.
      expect(Math.abs(rippleHeight(state, maps, x + RIPPLE_TILE_SIZE / 2, z) - rippleHeight(state, maps, x, z))).toBeGreaterThan(1e-4);
    }
  });
});

describe('the normals cards: the flat normal’s colour, the fabricated normal’s formula', () => {
  it('normals-wrong: the preset’s 2.5 m swell, flat normals, colour (N + 1)/2 = (0.5, 1, 0.5)', () => {
    const p = lessonView(findLesson('normals-wrong')!).params;
    expect(p.normals).toBe('flat');
    expect(p.shading).toBe('normals');
    expect(numberAfter(card('normals-wrong').question!.ask.en, 'has a ')).toBe(p.swellAmplitude);
    const colour = [0, 1, 0].map((c) => (c + 1) / 2);
    expect(mathNumbers('normals-wrong').slice(-3)).toEqual(colour);
    for (const text of both('normals-wrong')) expect(numbers(text).slice(-3)).toEqual(colour);
  });

  it('normals-right: Δ = 1 m, and the card’s components are the code’s normal; a face falling towards +x gains red', () => {
    const p = lessonView(findLesson('normals-right')!).params;
    expect(p.normals).toBe('fabricated');
    for (const text of both('normals-right')) expect(numberAfter(text, 'Δ = ')).toBe(NORMAL_DELTA);
    const maps = generateRippleHeightmaps(p.seed, HEIGHTMAP_SIZE);
    const state = surfaceStateAt(p, 5.5);
    const height = (x: number, z: number) => swellHeight(state, x, z) + rippleHeight(state, maps, x, z);
    for (const [x, z] of [
      [1.7, -3.2],
      [40, 25],
    ]) {
      const d = NORMAL_DELTA;
      const [h1, h2, h3] = [height(x, z), height(x + d, z), height(x, z + d)];
      const card = [-d * (h2 - h1), d * d, -d * (h3 - h1)];
      const length = Math.hypot(...card);
      const code = surfaceNormal(state, maps, x, z);
      card.forEach((c, i) => expect(code[i]).toBeCloseTo(c / length, 12));
    }
    // A plane falling towards +x: the normal leans to +x, red (n.x + 1)/2 above one half.
    const falling: SurfaceState = { ...state, swellAmplitude: 0, rippleStrength: 0 };
    const tilted = (x: number) => -0.3 * x;
    const nx = -NORMAL_DELTA * (tilted(NORMAL_DELTA) - tilted(0));
    expect((nx / Math.hypot(nx, NORMAL_DELTA ** 2) + 1) / 2).toBeGreaterThan(0.5);
    expect(surfaceNormal(falling, maps, 0, 0)[0]).toBe(-0);
  });

  it('normals-right’s question: raising the swell from 2.5 m to 4 m tilts the faces more (mean |n.x| grows)', () => {
    const p = lessonView(findLesson('normals-right')!).params;
    const maps = generateRippleHeightmaps(p.seed, HEIGHTMAP_SIZE);
    const meanTilt = (A: number) => {
      const state = surfaceStateAt({ ...p, swellAmplitude: A }, 2);
      let sum = 0,
        n = 0;
      for (let x = -60; x < 60; x += 3.1)
        for (let z = -60; z < 60; z += 2.9) {
          sum += Math.abs(surfaceNormal(state, maps, x, z)[0]);
          n++;
        }
      return sum / n;
    };
    expect(meanTilt(4)).toBeGreaterThan(meanTilt(2.5) * 1.2);
    // Control: with no swell the tilt is smaller still (the ripples alone).
    expect(meanTilt(0)).toBeLessThan(meanTilt(2.5));
  });
});
