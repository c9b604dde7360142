import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { LESSON_TEXTS, type LessonText } from '../../../../../src/app/lessons/lessonTexts';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import { BIBLIOGRAPHY } from '../../../../../src/app/lessons/bibliography';
import { PRESETS } from '../../../../../src/app/url/presets';
import { paramDefs } from '../../../../../src/sim/params/params';
import { unreadParams } from '../../../../../src/app/panel/unreadParams';
import { compareStrips } from '../../../../../src/sim/compare/compareLayout';
import { piersonMoskowitzHs } from '../../../../../src/sim/physics/physicsReport';
import { significantWaveHeight } from '../../../../../src/sim/physics/physicsEstimators';
import {
  PM_ALPHA,
  PM_BETA,
  piersonMoskowitzM0,
  piersonMoskowitzPeak,
  windAt19_5,
} from '../../../../../src/sim/waves/spectra/piersonMoskowitz';
import { KELVIN_HALF_ANGLE, kelvinGuideLines } from '../../../../../src/sim/wake/kelvinGuide';
import {
  FOOTPRINT_PER_LENGTH,
  GRAVITY,
  TAPER_END,
  TAPER_START,
  VOLUME_PER_LENGTH_CUBED,
  froudeNumber,
  wakeHeightAndGradient,
  wakeSources,
  type WakeParams,
  type WakeSource,
} from '../../../../../src/sim/wake/kelvinWake';
import { TRACK_COARSE_INTERVAL, TRACK_INTERVAL, TRACK_POINTS, WakeTrack } from '../../../../../src/sim/wake/wakeTrack';
import {
  IWAVE_CATCH_UP_STEPS,
  IWAVE_DAMPING,
  IWAVE_GRID_SIZE,
  IWAVE_SPACING,
  IWAVE_STEP,
  WAVE_EQUATION_SPEED,
} from '../../../../../src/sim/iwave/interactiveField';
import {
  IWAVE_KERNEL_BAND,
  IWAVE_KERNEL_RADIUS,
  fittedVerticalDerivativeKernel,
  kernelResponse,
} from '../../../../../src/sim/iwave/verticalDerivativeKernel';
import { IWAVE_SPONGE } from '../../../../../src/sim/iwave/iwaveGrid';
import { crestRadii, waveFrontRadius } from '../../../../../src/sim/iwave/cauchyPoissonRings';
import { hullSources } from '../../../../../src/sim/iwave/movingHull';
import { HAND_OVER_WIDTH, handOverDistance } from '../../../../../src/sim/iwave/kelvinHandOver';
import { FAR_FADE_END, FAR_FADE_START, farRings } from '../../../../../src/sim/lod/farRings';
import { OCEAN_EXTENT } from '../../../../../src/sim/lod/chunkSelection';
import { AEROSOL_SCALE_HEIGHT, hazeExtinction, hazeWeight } from '../../../../../src/sim/optics/haze';
import { WAKE_HULL } from '../../../../../src/sim/wake/boatWake';

/**
 * The wake group's cards (compare-models … horizon) checked against the code: every number a
 * card states that the code can compute is computed here and must be found, as the card
 * writes it, in the card's text, answer, choice or MathML (English with a decimal point,
 * Spanish with a decimal comma). Editing a card without the code, or the code without the
 * card, fails. Each kind of check has a negative control: a planted wrong value must not be found.
 */

/** The hull the wake and the interactive waves are made for: its waterline length and beam. */
const HULL_LENGTH = WAKE_HULL.length;
const HULL_BEAM = WAKE_HULL.beam;
/** The Earth's mean radius, metres, for the flat sea's missing horizon. */
const EARTH_RADIUS = 6.371e6;

const card = (id: string): LessonText => LESSON_TEXTS[id];
/** Everything a card shows in one language: text, question, answer and choice. */
function words(id: string, language: 'en' | 'es'): string {
  const c = card(id);
  return [c.text[language], c.question?.ask[language] ?? '', c.question?.answer[language] ?? '', c.choice?.[language] ?? ''].join('\n');
}
/** A value as a card writes it: fixed digits, a decimal comma in Spanish. */
const written = (value: number, digits: number, language: 'en' | 'es' | 'math') => {
  const s = value.toFixed(digits);
  return language === 'es' ? s.replace('.', ',') : s;
};
/** The value, written with `digits` decimals, stands in both languages' words (or in the MathML, when `math`). */
function stated(id: string, value: number, digits: number, { math = false, suffix = '' } = {}): boolean {
  const places: [string, 'en' | 'es' | 'math'][] = [
    [words(id, 'en'), 'en'],
    [words(id, 'es'), 'es'],
  ];
  const inText = places.every(([where, language]) =>
    new RegExp(`(^|[^0-9.,])${written(value, digits, language).replace('.', '\\.')}${suffix}`).test(where),
  );
  return inText && (!math || card(id).math.includes(`<mn>${written(value, digits, 'math')}</mn>`));
}
/** The number a card's English text gives after a label, e.g. "about 18.3°". */
function numberAfter(text: string, pattern: RegExp): number {
  const m = text.match(pattern);
  if (!m) throw new Error(`No match for ${pattern}`);
  return Number(m[1].replace(',', '.'));
}
const view = (id: string) => lessonView(findLesson(id)!);

describe('every card of the group has a question, and its references are in the bibliography', () => {
  const ids = [
    'compare-models',
    'physics-panel',
    'kelvin-wake',
    'wake-turn',
    'waves-as-simulation',
    'iwave-stone',
    'iwave-compare',
    'iwave-boat',
    'horizon',
  ];
  it.each(ids)('%s', (id) => {
    const c = card(id);
    expect(c.question).toBeDefined();
    for (const language of ['en', 'es'] as const) {
      expect(c.question!.answer[language].trim().split(/\s+/).length).toBeLessThanOrEqual(60);
      if (c.choice) expect(c.choice[language].trim().split(/\s+/).length).toBeLessThanOrEqual(30);
    }
    for (const key of c.references ?? []) expect(BIBLIOGRAPHY).toHaveProperty(key);
  });
});

describe('compare-models', () => {
  it('32 Gerstner trochoids and a 10 m/s wind, as the view has them; the seed reads no wind, the other two do', () => {
    expect(stated('compare-models', paramDefs.gerstnerCount.default, 0, { suffix: ' ' })).toBe(true);
    expect(stated('compare-models', view('compare-models').params.windSpeed, 0, { suffix: ' m/s' })).toBe(true);
    expect(unreadParams({ waves: 'seed', compare: 'off' }).get('windSpeed')).toBe('unusedBySeed');
    expect(unreadParams({ waves: 'fft', compare: 'off' }).has('windSpeed')).toBe(false);
    expect(unreadParams({ waves: 'gerstner', compare: 'off' }).has('windSpeed')).toBe(false);
  });

  it('a divider at fraction f of the free columns [x₀, x₁) stands on round(x₀ + f(x₁ − x₀))', () => {
    const { compareSplit, compareSplit2 } = view('compare-models').params;
    const strips = compareStrips(3, compareSplit, compareSplit2, 1366, 300, 1200);
    expect(strips.map((s) => s.x1).slice(0, 2)).toEqual([Math.round(300 + compareSplit * 900), Math.round(300 + compareSplit2 * 900)]);
    expect(card('compare-models').math).toContain('<mtext>round</mtext>');
  });

  it('negative control: a planted wrong count is not found', () => {
    expect(stated('compare-models', 33, 0, { suffix: ' ' })).toBe(false);
  });
});

describe('physics-panel', () => {
  const wind = view('physics-panel').params.windSpeed;

  it('U₁₉.₅ = 1.026 U₁₀, 0.21 U₁₉.₅²/g, ωp = 0.877 g/U₁₉.₅: the code’s constants', () => {
    expect(stated('physics-panel', windAt19_5(1), 3, { math: true })).toBe(true);
    // 4√m₀ = 2√(α/β) U²/g.
    expect(card('physics-panel').math).toContain(`<mn>${(2 * Math.sqrt(PM_ALPHA / PM_BETA)).toFixed(2)}</mn>`);
    expect(card('physics-panel').math).toContain(`<mn>${((piersonMoskowitzPeak(1) * windAt19_5(1)) / GRAVITY).toFixed(3)}</mn>`);
  });

  it('at the view’s 10 m/s theory gives Hs ≈ 2.25 m and Tp ≈ 7.5 s; at 20 m/s ≈ 9.0 m and ≈ 15 s', () => {
    expect(wind).toBe(10);
    const hs = piersonMoskowitzHs(wind);
    expect(4 * Math.sqrt(piersonMoskowitzM0(wind))).toBeCloseTo(hs, 1);
    expect(stated('physics-panel', hs, 2, { suffix: ' m' })).toBe(true);
    expect(stated('physics-panel', (2 * Math.PI) / piersonMoskowitzPeak(wind), 1, { suffix: ' s' })).toBe(true);
    expect(stated('physics-panel', piersonMoskowitzHs(2 * wind), 1, { suffix: ' m' })).toBe(true);
    expect(stated('physics-panel', (2 * Math.PI) / piersonMoskowitzPeak(2 * wind), 0, { suffix: ' s' })).toBe(true);
  });

  it('Hs is four standard deviations of one point’s record', () => {
    const a = 0.7;
    const series = Float64Array.from({ length: 4096 }, (_, i) => a * Math.sin((2 * Math.PI * i) / 64));
    expect(significantWaveHeight(series)).toBeCloseTo((4 * a) / Math.SQRT2, 6);
  });

  it('negative control: Hs at a wind 10 % off is not the card’s', () => {
    expect(stated('physics-panel', piersonMoskowitzHs(1.1 * wind), 2, { suffix: ' m' })).toBe(false);
  });
});

// ─── the Kelvin wake, measured on the code's own wake (as tests/unit/sim/wake/kelvinWake.test.ts does) ───

const WAKE: WakeParams = { strength: 1, hullLength: HULL_LENGTH };
function straightSources(speed: number): WakeSource[] {
  const track = new WakeTrack();
  const frame = 1 / 30;
  const frames = Math.round(200 / frame);
  for (let i = 0; i <= frames; i++) track.record(100 + i * frame, speed * i * frame, 0, speed);
  const head = track.points()[0];
  return wakeSources(track.points(), 100 + frames * frame, head.x, head.z);
}
/** Angle off the track of the wake's largest envelope on an arc `lengths` wavelengths astern. */
function crestAngle(speed: number, lengths: number, params: WakeParams = WAKE): number {
  const sources = straightSources(speed);
  const wavelength = (2 * Math.PI * speed * speed) / GRAVITY;
  const radius = lengths * wavelength;
  const step = 0.2;
  const env: number[] = [];
  for (let d = 0; d <= 40 + 1e-9; d += step) {
    const a = (d * Math.PI) / 180;
    let sum = 0;
    for (let i = 0; i < 32; i++) {
      const r = radius - wavelength / 2 + (wavelength * (i + 0.5)) / 32;
      sum += wakeHeightAndGradient(-r * Math.cos(a), r * Math.sin(a), sources, params)[0] ** 2;
    }
    env.push(sum);
  }
  let best = 1;
  for (let i = 1; i < env.length - 1; i++) if (env[i] > env[best]) best = i;
  const [y0, y1, y2] = [env[best - 1], env[best], env[best + 1]].map(Math.sqrt);
  return (best + (y0 - y2) / (2 * (y0 - 2 * y1 + y2))) * step;
}

describe('kelvin-wake', () => {
  const speed = view('kelvin-wake').params.boatSpeed;

  it('19.47°, Fr = 0.45 and λt ≈ 10.2 m at the view’s 4 m/s; 23 m at 6 m/s; the guide lines at 19.47°', () => {
    const degrees = (KELVIN_HALF_ANGLE * 180) / Math.PI;
    expect(stated('kelvin-wake', degrees, 2, { math: true })).toBe(true);
    const [ax, az, px, pz, sx, sz] = kelvinGuideLines(3, -7, 1.1, 100);
    const opening = Math.acos(((px - ax) * (sx - ax) + (pz - az) * (sz - az)) / (100 * 100));
    expect((opening * 90) / Math.PI).toBeCloseTo(degrees, 9);
    expect(stated('kelvin-wake', froudeNumber(speed, HULL_LENGTH), 2, { math: true })).toBe(true);
    expect(stated('kelvin-wake', (2 * Math.PI * speed * speed) / GRAVITY, 1, { math: true, suffix: ' m' })).toBe(true);
    expect(stated('kelvin-wake', (2 * Math.PI * 36) / GRAVITY, 0, { suffix: ' m' })).toBe(true);
    expect(stated('kelvin-wake', froudeNumber(6, HULL_LENGTH), 2)).toBe(true);
    for (const language of ['en', 'es'] as const) expect(card('kelvin-wake').text[language]).toContain(`L = ${HULL_LENGTH} m`);
    expect(card('kelvin-wake').text.en).not.toContain(`L = ${HULL_LENGTH + 2} m`);
  });

  it('the largest crests stand where the card says: ≈ 18.3° at 14 λ for 4 m/s, and 16–17° at 6 m/s', () => {
    const said = numberAfter(card('kelvin-wake').text.en, /about ([0-9.]+)° at 14 wavelengths/);
    expect(Math.abs(crestAngle(speed, 14) - said)).toBeLessThan(0.2);
    const [low, high] = card('kelvin-wake')
      .question!.answer.en.match(/about (\d+)–(\d+)°/)!
      .slice(1)
      .map(Number);
    for (const lengths of [8, 14]) {
      const fast = crestAngle(6, lengths);
      expect(fast).toBeGreaterThan(low - 0.5);
      expect(fast).toBeLessThan(high + 0.5);
    }
  }, 60_000);

  it('negative control: with the wrong dispersion (ω ∝ k^0.6) the crests miss the card’s 18.3°', () => {
    const said = numberAfter(card('kelvin-wake').text.en, /about ([0-9.]+)° at 14 wavelengths/);
    expect(Math.abs(crestAngle(speed, 14, { ...WAKE, dispersionPower: 0.6 }) - said)).toBeGreaterThan(0.2);
    expect(stated('kelvin-wake', 19.5, 1, { math: true })).toBe(false);
  }, 30_000);
});

describe('wake-turn', () => {
  const { boatSpeed, boatTurnRate } = view('wake-turn').params;

  it('3°/s at 4 m/s is a circle of 76 m; σ = 2 m; 64 points every 0.5 s then 2 s; waves fade between 56 and 76 s', () => {
    expect(stated('wake-turn', boatTurnRate, 0, { suffix: '°' })).toBe(true);
    expect(stated('wake-turn', boatSpeed / ((boatTurnRate * Math.PI) / 180), 0, { suffix: ' m' })).toBe(true);
    expect(stated('wake-turn', FOOTPRINT_PER_LENGTH * HULL_LENGTH, 0, { suffix: ' m' })).toBe(true);
    expect(stated('wake-turn', TRACK_POINTS, 0, { suffix: ' ' })).toBe(true);
    expect(stated('wake-turn', TRACK_INTERVAL, 1, { suffix: ' s' })).toBe(true);
    expect(stated('wake-turn', TRACK_COARSE_INTERVAL, 0, { suffix: ' s' })).toBe(true);
    expect(stated('wake-turn', TAPER_START, 0, { suffix: '–' + TAPER_END })).toBe(true);
  });

  it('one source’s wave has k = gτ²/(4r²): its phase gτ²/(4r) turns at −k per metre of r', () => {
    // Two sources of one age at the same point: the segment's phase is exactly g τ²/(4 r′), r′ = √(r² + σ²).
    const tau = 20;
    const sigma = FOOTPRINT_PER_LENGTH * HULL_LENGTH;
    const sources: WakeSource[] = [
      { x: 0, z: 0, age: tau, speed: 4 },
      { x: 0, z: 0, age: tau + 1e-6, speed: 4 },
    ];
    const r = 60;
    const [, gx] = wakeHeightAndGradient(r, 0, sources, WAKE);
    const [h] = wakeHeightAndGradient(r, 0, sources, WAKE);
    const rr = Math.hypot(r, sigma);
    const k = (GRAVITY * tau * tau) / (4 * rr * rr);
    // η ∝ sin Φ: its slope over η is −k cot Φ plus the amplitude's own (small) slope.
    const phase = (GRAVITY * tau * tau) / (4 * rr);
    const ampSlope = ((-4 + k * k * sigma * sigma) / (rr * rr)) * r;
    expect(gx / h).toBeCloseTo((-k * (r / rr)) / Math.tan(phase) + ampSlope, 3);
    expect(card('wake-turn').math).toContain('<mn>4</mn><msup><mi>r</mi><mn>2</mn></msup>');
  });

  it('negative control: the radius of a 6°/s turn is not on the card', () => {
    expect(stated('wake-turn', boatSpeed / ((6 * Math.PI) / 180), 0, { suffix: ' m' })).toBe(false);
  });
});

describe('waves-as-simulation', () => {
  it('Δt = 1/60 s, a 128 m grid of 0.5 m, a 13 × 13 kernel, 10 s of catch-up, e-folding in 100 s', () => {
    expect(IWAVE_STEP).toBe(1 / 60);
    expect(card('waves-as-simulation').text.en).toContain('Δt = 1/60 s');
    for (const language of ['en', 'es'] as const) {
      const text = card('waves-as-simulation').text[language];
      expect(text).toContain(`${IWAVE_GRID_SIZE * IWAVE_SPACING} m`);
      expect(text).toContain(`Δx = ${written(IWAVE_SPACING, 1, language)} m`);
      expect(text).toContain(`${2 * IWAVE_KERNEL_RADIUS + 1} × ${2 * IWAVE_KERNEL_RADIUS + 1}`);
      expect(text).toContain(`${IWAVE_CATCH_UP_STEPS * IWAVE_STEP} s`);
    }
    // ḧ + α ḣ = …: the amplitude decays as e^(−α t / 2).
    expect(stated('waves-as-simulation', 2 / IWAVE_DAMPING, 0, { suffix: ' s' })).toBe(true);
  });

  it('the kernel keeps ω² = g k within 5 % for waves 1.5 to 10 m long, along the axis and the diagonal', () => {
    const kernel = fittedVerticalDerivativeKernel();
    const [shortest, longest] = card('waves-as-simulation')
      .text.en.match(/waves ([0-9.]+) to ([0-9.]+) m long/)!
      .slice(1)
      .map(Number);
    for (let lambda = shortest; lambda <= longest; lambda += 0.25) {
      const k = (2 * Math.PI * IWAVE_SPACING) / lambda; // radians per texel
      for (const angle of [0, Math.PI / 4])
        expect(Math.abs(kernelResponse(kernel, k * Math.cos(angle), k * Math.sin(angle)) / k - 1)).toBeLessThan(0.05);
    }
    // The band it was fitted on, in metres of wavelength.
    const [kMin, kMax] = IWAVE_KERNEL_BAND.map((k) => k / IWAVE_SPACING);
    expect(Math.abs((2 * Math.PI) / kMax - shortest)).toBeLessThan(0.1);
    expect(Math.abs((2 * Math.PI) / kMin - longest)).toBeLessThan(0.6);
  });

  it('the step in the MathML is the shader’s: damping centred in time', () => {
    const shader = readFileSync('shaders/iwaveStep.frag', 'utf8');
    expect(shader).toContain('float half_ = 0.5 * (uDamping + spongeDamping(p)) * uDt;');
    expect(shader).toContain('float next = (2.0 * now.x - (1.0 - half_) * now.y - uKick * convolved) / (1.0 + half_);');
    const math = card('waves-as-simulation').math;
    expect(math).toContain('<mo>(</mo><mn>1</mn><mo>−</mo><mfrac><mrow><mi>α</mi><mi>Δ</mi><mi>t</mi></mrow><mn>2</mn></mfrac><mo>)</mo>');
    expect(math).toContain('<mrow><mn>1</mn><mo>+</mo><mfrac><mrow><mi>α</mi><mi>Δ</mi><mi>t</mi></mrow><mn>2</mn></mfrac></mrow>');
  });

  it('negative control: a wavelength outside the band misses 5 %', () => {
    const kernel = fittedVerticalDerivativeKernel();
    const k = (2 * Math.PI * IWAVE_SPACING) / 40;
    expect(Math.abs(kernelResponse(kernel, k, 0) / k - 1)).toBeGreaterThan(0.05);
  });
});

describe('iwave-stone', () => {
  const rings = (gravity = GRAVITY) => {
    const [kMin, kMax] = IWAVE_KERNEL_BAND.map((k) => k / IWAVE_SPACING);
    return crestRadii(10, { kMin, kMax, maxRadius: (0.5 * IWAVE_GRID_SIZE - IWAVE_SPONGE.width) * IWAVE_SPACING, gravity });
  };
  const said = (language: 'en' | 'es') => {
    const m = card('iwave-stone').question!.answer[language].match(/(?:at|a) ([0-9.,]+), ([0-9.,]+), ([0-9.,]+) (?:and|y) ([0-9.,]+) m/)!;
    return m.slice(1).map((s) => Number(s.replace(',', '.')));
  };

  it('ten seconds after the stone the guide’s rings stand at 19.5, 13.0, 9.8 and 7.8 m, rₙ = g t²/(8πn)', () => {
    const radii = rings();
    for (const language of ['en', 'es'] as const) {
      const r = said(language);
      expect(r.length).toBe(radii.length);
      r.forEach((v, i) => expect(Math.abs(v - radii[i])).toBeLessThan(0.05));
    }
    expect(radii[0]).toBeCloseTo((GRAVITY * 100) / (8 * Math.PI * 2), 9);
    const stone = PRESETS.stone.stones[0];
    expect(card('iwave-stone').choice!.en).toContain(`${stone[4]} m high`);
    expect(card('iwave-stone').choice!.es).toContain(`${stone[4]} m de alto`);
  });

  it('the gaps between those rings, 6.5, 3.3 and 2.0 m, widen towards the front of the train', () => {
    const radii = rings();
    const gaps = radii.slice(1).map((r, i) => radii[i] - r);
    for (let i = 1; i < gaps.length; i++) expect(gaps[i]).toBeLessThan(gaps[i - 1]);
    for (const language of ['en', 'es'] as const) {
      const m = card('iwave-stone').question!.answer[language].match(
        /(?:gaps of|separaciones de) ([0-9.,]+), ([0-9.,]+) (?:and|y) ([0-9.,]+) m/,
      )!;
      const said = m.slice(1).map((s) => Number(s.replace(',', '.')));
      expect(said.length).toBe(gaps.length);
      said.forEach((v, i) => expect(Math.abs(v - gaps[i])).toBeLessThan(0.05));
    }
  });

  it('negative control: with gravity 10 % off the rings are not the card’s', () => {
    const wrong = rings(1.1 * GRAVITY);
    expect(said('en').some((v, i) => Math.abs(v - (wrong[i] ?? 0)) >= 0.05)).toBe(true);
    const wrongGaps = wrong.slice(1).map((r, i) => wrong[i] - r);
    expect(Math.abs(wrongGaps[0] - 6.5)).toBeGreaterThan(0.05);
  });
});

describe('iwave-compare', () => {
  it('c = 2.56 m/s, deep water’s phase speed at 1.5 rad/m; the ring has run 25.6 m after 10 s', () => {
    expect(WAVE_EQUATION_SPEED).toBeCloseTo(Math.sqrt(GRAVITY / 1.5), 12);
    expect(stated('iwave-compare', WAVE_EQUATION_SPEED, 2, { math: true, suffix: ' m/s' })).toBe(true);
    expect(stated('iwave-compare', waveFrontRadius(10, WAVE_EQUATION_SPEED), 1, { suffix: ' m' })).toBe(true);
  });

  it('negative control: another speed is not on the card', () => {
    expect(stated('iwave-compare', Math.sqrt(GRAVITY / 1.0), 2, { math: true })).toBe(false);
  });
});

describe('iwave-boat', () => {
  const speed = view('iwave-boat').params.boatSpeed;
  const flux = (u: number) => {
    const [bow, stern] = hullSources({ x: 0, z: 0, heading: 0, speed: u, length: HULL_LENGTH, beam: HULL_BEAM, strength: 1 });
    const area = (Math.PI * bow.radius * bow.radius) / 2;
    return { bow: bow.rate * area, stern: stern.rate * area };
  };

  it('Q = U·V/L = 3.2 m³/s at 4 m/s, bow and stern opposite; D = max(2L, 2πU²/g) = 16 m, blended over 8 m', () => {
    expect(flux(speed).bow).toBeCloseTo((speed * VOLUME_PER_LENGTH_CUBED * HULL_LENGTH ** 3) / HULL_LENGTH, 9);
    expect(flux(speed).stern).toBeCloseTo(-flux(speed).bow, 12);
    expect(stated('iwave-boat', flux(speed).bow, 1, { math: true, suffix: ' m' })).toBe(true);
    expect(stated('iwave-boat', handOverDistance(speed, HULL_LENGTH), 0, { math: true, suffix: ' m' })).toBe(true);
    expect(stated('iwave-boat', HAND_OVER_WIDTH, 0, { suffix: ' m' })).toBe(true);
  });

  it('astern at −2 m/s the stern pushes 1.6 m³/s aside and the bow leaves a hollow', () => {
    const astern = flux(-2);
    expect(astern.stern).toBeGreaterThan(0);
    expect(astern.bow).toBeLessThan(0);
    expect(stated('iwave-boat', astern.stern, 1, { suffix: ' m³/s' })).toBe(true);
  });

  it('negative control: the flux of a 10 m hull is not the card’s', () => {
    expect(stated('iwave-boat', (speed * VOLUME_PER_LENGTH_CUBED * 1000) / 10, 1, { math: true, suffix: ' m' })).toBe(false);
  });
});

describe('horizon', () => {
  it('a 4 km grid, cells doubling ring by ring, waves fading over the first two rings', () => {
    expect(Math.round(OCEAN_EXTENT / 1000)).toBe(4);
    expect(stated('horizon', OCEAN_EXTENT / 1000, 0, { suffix: ' km' })).toBe(true);
    const rings = farRings(OCEAN_EXTENT / 2);
    for (let i = 1; i < rings.length; i++) expect(rings[i].cellSize).toBe(2 * rings[i - 1].cellSize);
    expect(FAR_FADE_START).toBe(rings[0].inner);
    expect(FAR_FADE_END).toBe(rings[1].outer);
  });

  it('β₀ = ln 50 / V ≈ 3.912 / V, H = 1.2 km; lowering V from 20 to 5 km thickens the haze fourfold', () => {
    expect(stated('horizon', Math.log(50), 3, { math: true })).toBe(true);
    expect(stated('horizon', AEROSOL_SCALE_HEIGHT / 1000, 1, { suffix: ' km' })).toBe(true);
    expect(view('horizon').params.visibility).toBe(20);
    expect(hazeExtinction(5000) / hazeExtinction(20000)).toBeCloseTo(4, 12);
  });

  it('the flat sea’s missing horizon: from the view’s 120 m a real one lies 39 km off, 0.35° down', () => {
    const eye = view('horizon').camera.position[1];
    expect(stated('horizon', eye, 0, { suffix: ' m' })).toBe(true);
    expect(stated('horizon', Math.sqrt(2 * EARTH_RADIUS * eye) / 1000, 0, { suffix: ' km' })).toBe(true);
    expect(stated('horizon', (Math.sqrt((2 * eye) / EARTH_RADIUS) * 180) / Math.PI, 2, { suffix: '°' })).toBe(true);
  });

  it('the sea below an aircraft is only lightly veiled; the far sea seen from the view’s 120 m is not', () => {
    const beta = hazeExtinction(view('horizon').params.visibility * 1000);
    // Straight down from 10 km: at most 1 − e^(−β₀H), about a fifth at 20 km visibility.
    const below = hazeWeight(beta, 10_000, 0, 10_000);
    expect(below).toBeLessThan(-Math.expm1(-beta * AEROSOL_SCALE_HEIGHT) + 1e-12);
    expect(below).toBeLessThan(0.25);
    expect(card('horizon').text.en).toContain('only lightly veiled');
    // Negative control: along the surface, 20 km off, the haze all but hides the sea.
    expect(hazeWeight(beta, view('horizon').camera.position[1], 0, 20_000)).toBeGreaterThan(0.9);
  });

  it('negative control: a planted 3.91 or a 2 km scale height is not the card’s', () => {
    expect(stated('horizon', 2, 1, { suffix: ' km' })).toBe(false);
    expect(stated('horizon', Math.log(49), 3, { math: true })).toBe(false);
  });
});
