import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { Color, ShaderChunk, SRGBColorSpace } from 'three';
import { describe, expect, it } from 'vitest';
import { LESSON_TEXTS } from '../../../../../src/app/lessons/lessonTexts';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import { defaultParams, type OceanParams } from '../../../../../src/sim/params/params';
import { seaSlopeVariance } from '../../../../../src/sim/optics/coxMunk';
import { HORIZON, ZENITH } from '../../../../../src/sim/optics/skyPainter';
import {
  cascadeWavelengths,
  resolvedShare,
  unresolvedSlopeVariance,
  SUN_DISC_SLOPE_VARIANCE,
} from '../../../../../src/sim/optics/resolvedSlopes';
import { seaStateFromParams } from '../../../../../src/sim/waves/spectra/seaState';
import { fftOceanSetup } from '../../../../../src/sim/waves/fft/fftOcean';
import { cascadeSpread } from '../../../../../src/sim/waves/spectra/spectralBounds';
import { HIGHLIGHT_KNEE, rollOffHighlight } from '../../../../../src/sim/optics/highlightRollOff';
import { SUN_IRRADIANCE, SUN_LIGHT_COLOR } from '../../../../../src/sim/optics/sun';
import { glintPerIrradiance } from '../../../../../src/sim/optics/beckmannGlint';
import { AIR_IOR, WATER_IOR, fresnelReflectance } from '../../../../../src/sim/optics/fresnel';
import {
  PURE_WATER_ABSORPTION,
  REFLECTANCE_FACTOR,
  bodyColor,
  deepWaterReflectance,
  molecularScattering,
  WAVELENGTHS,
} from '../../../../../src/sim/optics/waterColor';
import {
  CHLOROPHYLL,
  CREST_PATH,
  PARTICLE_MEAN_COSINE,
  crestScattering,
  henyeyGreenstein,
} from '../../../../../src/sim/optics/subsurfaceGlow';
import { glslVec3, shaderConstantsChunk } from '../../../../../src/render/shaders/shaderConstants';

/**
 * Every number and equation on the second round of concept cards (slope-filtering,
 * light-units, water-colour) that the code can compute, read out of the card's English and
 * Spanish text and checked against the code; each kind of check has a planted fault that must
 * fail.
 */

type Lang = 'en' | 'es';
const LANGS: Lang[] = ['en', 'es'];
const root = resolve(import.meta.dirname, '..', '..', '..', '..', '..');
const source = (file: string) => readFileSync(resolve(root, file), 'utf8');

function cardText(id: string, lang: Lang): string {
  const t = LESSON_TEXTS[id];
  return [t.text[lang], t.question?.ask[lang] ?? '', t.question?.answer[lang] ?? '', t.choice?.[lang] ?? ''].join(' ');
}

/** The number that follows `before` (a regular expression source), as written: a Spanish decimal comma read as a point. */
function quotedAfter(text: string, before: string): string {
  const match = new RegExp(`${before}\\s*([0-9]+(?:[.,][0-9]+)?)`).exec(text);
  if (!match) throw new Error(`no number after /${before}/ in: ${text.slice(0, 80)}…`);
  return match[1].replace(',', '.');
}
const numberAfter = (text: string, before: string) => Number(quotedAfter(text, before));

/** Whether `computed` rounds to `quoted` at the quote's own number of decimals. */
function roundsTo(quoted: string, computed: number): boolean {
  const decimals = quoted.includes('.') ? quoted.split('.')[1].length : 0;
  return Math.abs(computed - Number(quoted)) <= 0.5 * 10 ** -decimals + 1e-12;
}

const viewParams = (id: string): OceanParams => lessonView(findLesson(id)!).params;

/** Each FFT cascade's mean-square slope, as the renderer hands it to the pixels (fftWaveView.ts setSlopeStatistics). */
function cascadeSlopeVariances(params: OceanParams): number[] {
  const sea = seaStateFromParams(params);
  const { tiles } = fftOceanSetup(sea);
  return tiles.map((tile) => cascadeSpread(tile, sea.depth).slope ** 2);
}

/** three.js's sRGB encoding (its ColorManagement, the twin of the shaders' sRGBTransferOETF) as an 8-bit code. */
function srgbCode(linear: number): number {
  const encoded = { r: 0, g: 0, b: 0 };
  new Color(linear, linear, linear).getRGB(encoded, SRGBColorSpace);
  return Math.round(255 * encoded.r);
}

// Bruneton, Neyret & Holzschuch 2010.
describe('slope-filtering: the slopes a pixel cannot draw become roughness', () => {
  it('the view is the fresh breeze, 10 m/s on the FFT sea, under a low sun, with roughness on', () => {
    const p = viewParams('slope-filtering');
    expect(p.waves).toBe('fft');
    expect(p.seaRoughness).toBe(true);
    expect(p.sunElevation).toBeLessThanOrEqual(10);
    for (const lang of LANGS) expect(numberAfter(cardText('slope-filtering', lang), '(?:at|a)')).toBe(p.windSpeed);
  });

  // Controls: 0.19, and Cox and Munk’s σ² at U₁₀ unconverted to their 12.5 m height.
  it('Cox and Munk’s σ² is 0.055 at 10 m/s and the three cascades’ σ_c² hold 0.019 of it', () => {
    const p = viewParams('slope-filtering');
    const total = seaSlopeVariance(p.windSpeed);
    const cascades = cascadeSlopeVariances(p);
    expect(cascades).toHaveLength(3);
    const held = cascades.reduce((a, b) => a + b, 0);
    for (const lang of LANGS) {
      const text = LESSON_TEXTS['slope-filtering'].text[lang];
      const quotedTotal = /([0-9]+[.,][0-9]+) a(?:t)? 10 m\/s/.exec(text)![1].replace(',', '.');
      const quotedHeld = quotedAfter(text, '(?:hold|suman)');
      expect(roundsTo(quotedTotal, total), lang).toBe(true);
      expect(roundsTo(quotedHeld, held), lang).toBe(true);
    }
    expect(roundsTo('0.19', held)).toBe(false);
    expect(roundsTo('0.055', 0.003 + 5.12e-3 * 10.6)).toBe(false);
  });

  // Control: a rule counting a wave drawn from one footprint instead of two.
  it('a cascade keeps all its slopes while its shortest waves span two footprints, none once its longest do not', () => {
    const p = viewParams('slope-filtering');
    const sea = seaStateFromParams(p);
    const { cascades } = fftOceanSetup(sea);
    for (const cascade of cascades) {
      const { shortest, longest } = cascadeWavelengths(cascade, sea.fftSize);
      expect(resolvedShare(shortest / 2, shortest, longest)).toBe(1);
      expect(resolvedShare(longest / 2, shortest, longest)).toBe(0);
      // Halfway in ln k: half the band's slopes.
      expect(resolvedShare(Math.sqrt(shortest * longest) / 2, shortest, longest)).toBeCloseTo(0.5, 12);
      // Control: a rule counting a wave drawn from one footprint still keeps some of it at λ_max / 2.
      const fromOneFootprint = (footprint: number) =>
        Math.min(1, Math.max(0, Math.log(longest / footprint) / Math.log(longest / shortest)));
      expect(fromOneFootprint(longest / 2)).toBeGreaterThan(0);
    }
  });

  // Near σ²ᵤ is 0.036, far all 0.055, with roughness off only the sun’s disc. Control: a shader weighting by s_c, not s_c².
  it('σ²ᵤ = max(σ²_⊙, σ²_CM − Σ s_c² σ_c²) is what the shader computes, and the card’s equation', () => {
    const shader = source('shaders/waves/fft.glsl');
    const equation = /max\(SUN_DISC_SLOPE_VARIANCE, uSeaSlopeVariance - dot\(share \* share, uFftSlopeVariance\)\)/;
    expect(shader).toMatch(equation);
    expect(shader).toMatch(/vec3 share = clamp\(\(uFftLogLongestWave - log\(2\.0 \* footprint\)\) \* uFftPerLogBand, 0\.0, 1\.0\);/);
    expect(shader.replace('dot(share * share,', 'dot(share,')).not.toMatch(equation);
    // The card's MathML squares the share.
    expect(LESSON_TEXTS['slope-filtering'].math).toContain(
      '<msubsup><mi>s</mi><mi>c</mi><mn>2</mn></msubsup><msubsup><mi>σ</mi><mi>c</mi><mn>2</mn></msubsup>',
    );
    const p = viewParams('slope-filtering');
    const total = seaSlopeVariance(p.windSpeed);
    const held = cascadeSlopeVariances(p).reduce((a, b) => a + b, 0);
    expect(unresolvedSlopeVariance(total, held)).toBeCloseTo(0.036, 3);
    expect(unresolvedSlopeVariance(total, 0)).toBe(total);
    expect(unresolvedSlopeVariance(total, total)).toBe(SUN_DISC_SLOPE_VARIANCE);
    // The roughness-off path compiles the floor in: only the sun's disc is left.
    expect(source('shaders/ocean.frag')).toMatch(/#ifdef OCEAN_SMOOTH_SEA\s+float roughness = SUN_DISC_SLOPE_VARIANCE;/);
  });

  // Far out (a pixel past half the middle cascade's longest wave, 11 m at 10 m/s) only the
  // longest cascade is drawn. Control: the middle cascade's σ_c² is not the answer's.
  it('far out the normal keeps only the longest cascade, σ_c² = 0.004 of Cox and Munk’s 0.055', () => {
    const p = viewParams('slope-filtering');
    const sea = seaStateFromParams(p);
    const bands = fftOceanSetup(sea).cascades.map((cascade) => cascadeWavelengths(cascade, sea.fftSize));
    const variances = cascadeSlopeVariances(p);
    const footprint = bands[1].longest / 2;
    expect(bands.map(({ shortest, longest }) => resolvedShare(footprint, shortest, longest))).toEqual([1, 0, 0]);
    for (const lang of LANGS) {
      const answer = LESSON_TEXTS['slope-filtering'].question!.answer[lang];
      expect(roundsTo(quotedAfter(answer, 'σ_c² ='), variances[0]), lang).toBe(true);
      expect(roundsTo(quotedAfter(answer, '(?:Munk’s|los)'), seaSlopeVariance(p.windSpeed)), lang).toBe(true);
    }
    expect(roundsTo('0.004', variances[1])).toBe(false);
  });
});

describe('light-units: linear radiance, exposure in stops, the tone curve, sRGB', () => {
  // Control: another exposure is not the view’s.
  it('the view is the calm FFT sea at exposure 0, the question’s start, the sun at 10°', () => {
    const p = viewParams('light-units');
    expect(p.waves).toBe('fft');
    for (const lang of LANGS) expect(numberAfter(LESSON_TEXTS['light-units'].question!.ask[lang], '(?:from|de)')).toBe(p.exposure);
    expect(p.exposure).toBe(defaultParams().exposure);
    // A sun at 10°: its glint's core stays far above white even where no wave is drawn (below).
    expect(p.sunElevation).toBe(10);
    expect(numberAfter(LESSON_TEXTS['light-units'].question!.ask.en, 'from') + 1).not.toBe(p.exposure);
  });

  // Rec. 709 luminance of the painted sky's zenith and horizon: 0.34 and 0.82. Control: the
  // horizon's is not 0.3.
  it('the sky cube’s colours lie near 0.3–0.8, from zenith to horizon', () => {
    const luminance = (c: readonly number[]) => 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2];
    for (const lang of LANGS) {
      const range = /([0-9]+[.,][0-9]+)–([0-9]+[.,][0-9]+)/.exec(LESSON_TEXTS['light-units'].text[lang])!;
      expect(roundsTo(range[1].replace(',', '.'), luminance(ZENITH)), lang).toBe(true);
      expect(roundsTo(range[2].replace(',', '.'), luminance(HORIZON)), lang).toBe(true);
    }
    expect(roundsTo('0.3', luminance(HORIZON))).toBe(false);
  });

  // Control: a clipped curve shows 1 as 1.
  it('the sun gives E = 4, the knee k = 0.6; 1 shows as 0.85 and 2 as 0.99', () => {
    for (const lang of LANGS) {
      const text = cardText('light-units', lang);
      expect(numberAfter(text, 'E =')).toBe(SUN_IRRADIANCE);
      expect(numberAfter(text, 'k =')).toBe(HIGHLIGHT_KNEE);
      expect(roundsTo(quotedAfter(text, '1 (?:shows as|se ve como)'), rollOffHighlight(1))).toBe(true);
      expect(roundsTo(quotedAfter(text, '2 (?:as|como)'), rollOffHighlight(2))).toBe(true);
    }
    expect(roundsTo('0.85', Math.min(1, 1))).toBe(false);
  });

  // Control: a curve fed the light without the exposure.
  it('exposure multiplies every pixel by 2^EV before the curve, in three.js’s tone-mapping slot', () => {
    const tone = source('src/render/tone/wholeFrameToneCurve.ts');
    const exposed = /rollOffHighlights\( toneMappingExposure \* color \)/;
    expect(tone).toMatch(exposed);
    expect(source('src/render/ocean/oceanView.ts')).toMatch(/toneMappingExposure = 2 \*\* params\.exposure/);
    expect(tone.replace('toneMappingExposure * color', 'color')).not.toMatch(exposed);
  });

  // V = 1.055 f^{1/2.4} − 0.055, 12.92 f below 0.0031308. Control: no encoding would give the knee 153.
  it('three.js encodes f as sRGB, the card’s V, and the knee is code 203', () => {
    const oetf = ShaderChunk.colorspace_pars_fragment;
    expect(oetf).toContain('pow( value.rgb, vec3( 0.41666 ) ) * 1.055 - vec3( 0.055 )');
    expect(oetf).toContain('value.rgb * 12.92');
    expect(oetf).toContain('0.0031308');
    const math = LESSON_TEXTS['light-units'].math;
    for (const n of ['1.055', '2.4', '0.055', '0.0031308', '12.92']) expect(math).toContain(`<mn>${n}</mn>`);
    for (const lang of LANGS) expect(numberAfter(cardText('light-units', lang), '(?:code|código)')).toBe(srgbCode(HIGHLIGHT_KNEE));
    expect(srgbCode(HIGHLIGHT_KNEE)).toBe(203);
    expect(Math.round(255 * HIGHLIGHT_KNEE)).toBe(153);
  });

  // Control: 8 bits without the sRGB encoding would need c ≈ 2.7.
  it('an 8-bit screen shows white from c ≈ 2.4, and at −2 EV from L ≈ 9.6, far below the glint’s core', () => {
    // The least light, to 0.01, that the curve and the encoding bring to code 255.
    let white = HIGHLIGHT_KNEE;
    while (srgbCode(rollOffHighlight(white)) < 255) white += 0.01;
    for (const lang of LANGS) {
      const text = cardText('light-units', lang);
      expect(roundsTo(quotedAfter(text, '(?:about|unos)'), white), lang).toBe(true);
      expect(roundsTo(quotedAfter(text, 'c ≥'), white), lang).toBe(true);
      expect(roundsTo(quotedAfter(text, 'L ≥'), white / 2 ** -2), lang).toBe(true);
      expect(numberAfter(text, '(?:divided by|se divide entre)')).toBe(2 ** 2);
    }
    // The glint's core in the view, at its mirror point: the view's sun reflected with the
    // roughness of a near pixel (every cascade drawn) and of a far one (none), in its dimmest channel.
    const p = viewParams('light-units');
    const e = (p.sunElevation * Math.PI) / 180;
    const sun: [number, number, number] = [0, Math.sin(e), -Math.cos(e)];
    const eye: [number, number, number] = [0, Math.sin(e), Math.cos(e)];
    const total = seaSlopeVariance(p.windSpeed);
    const drawn = cascadeSlopeVariances(p).reduce((a, b) => a + b, 0);
    const core = (variance: number) =>
      Math.min(...SUN_LIGHT_COLOR) *
      SUN_IRRADIANCE *
      fresnelReflectance(Math.sin(e), AIR_IOR, WATER_IOR) *
      glintPerIrradiance(sun, eye, [0, 1, 0], variance);
    for (const variance of [total - drawn, total]) expect(core(variance)).toBeGreaterThan(2 * white * 4);
    let linearWhite = HIGHLIGHT_KNEE;
    while (Math.round(255 * rollOffHighlight(linearWhite)) < 255) linearWhite += 0.01;
    expect(roundsTo('2.4', linearWhite)).toBe(false);
  });
});

describe('water-colour: the deep water’s reflectance and the crests’ forward-scattered glow', () => {
  it('the view is the fresh breeze, sun ahead at azimuth 20° as the question starts, glow on, colour from optics', () => {
    const p = viewParams('water-colour');
    expect(p.waves).toBe('fft');
    expect(p.subsurface).toBe(true);
    expect(p.waterColorPicked).toBe(false);
    for (const lang of LANGS) expect(numberAfter(LESSON_TEXTS['water-colour'].question!.ask[lang], '(?:from|de)')).toBe(p.sunAzimuth);
  });

  // f = 0.33, a = 0.34 m⁻¹ in red, b ∝ λ^−4.3 give 0.0005, 0.013, 0.045. Control: b_b = b instead of b/2.
  it('R = f b_b/(a + b_b) gives the card’s reflectances in red, green and blue', () => {
    const body = bodyColor();
    for (const lang of LANGS) {
      const text = LESSON_TEXTS['water-colour'].text[lang];
      expect(numberAfter(text, 'f =')).toBe(REFLECTANCE_FACTOR);
      expect(numberAfter(text, 'a =')).toBe(PURE_WATER_ABSORPTION[0]);
      expect(numberAfter(text, 'λ\\^−')).toBe(4.3);
      const quoted = text
        .slice(text.indexOf('R = 0'))
        .match(/\d+[.,]\d+/g)!
        .slice(0, 3)
        .map((q) => q.replace(',', '.'));
      quoted.forEach((q, i) => expect(roundsTo(q, body[i]), `${lang} ${WAVELENGTHS[i]} nm`).toBe(true));
    }
    expect(molecularScattering(1000) / molecularScattering(500)).toBeCloseTo(2 ** -4.3, 12);
    const withoutHalf = WAVELENGTHS.map((w, i) => deepWaterReflectance(PURE_WATER_ABSORPTION[i], 2 * molecularScattering(w)));
    expect(roundsTo('0.0005', withoutHalf[0])).toBe(false);
  });

  // d = 1 m, 1 mg/m³, g = 0.924; p(θ) is 26.5 sr⁻¹ along the sun’s ray, under 0.005 at 90°. Control: an isotropic phase.
  it('the glow’s path, chlorophyll and g are the code’s; p(θ) has the card’s values and integrates to 1', () => {
    for (const lang of LANGS) {
      const text = cardText('water-colour', lang);
      expect(numberAfter(text, 'd =')).toBe(CREST_PATH);
      expect(numberAfter(text, '(?:chlorophyll|clorofila)')).toBe(CHLOROPHYLL);
      expect(numberAfter(text, 'g =')).toBe(PARTICLE_MEAN_COSINE);
      expect(roundsTo(quotedAfter(text, '(?:is|vale)'), henyeyGreenstein(1))).toBe(true);
      expect(henyeyGreenstein(0)).toBeLessThan(numberAfter(text, '(?:under|menos de)'));
    }
    // ∫ p dΩ = 2π ∫ p(μ) dμ = 1, and its mean cosine is g.
    const steps = 200000;
    let integral = 0;
    let meanCosine = 0;
    for (let i = 0; i < steps; i++) {
      const mu = -1 + (2 * (i + 0.5)) / steps;
      integral += 2 * Math.PI * henyeyGreenstein(mu) * (2 / steps);
      meanCosine += 2 * Math.PI * mu * henyeyGreenstein(mu) * (2 / steps);
    }
    expect(integral).toBeCloseTo(1, 4);
    expect(meanCosine).toBeCloseTo(PARTICLE_MEAN_COSINE, 4);
    expect(roundsTo('26.5', 1 / (4 * Math.PI))).toBe(false);
  });

  // Control: a reflectance without the ½ is not the shader’s.
  it('the glow is greener than the deep blue, and the shaders draw exactly these colours', () => {
    const glow = crestScattering();
    const body = bodyColor();
    expect(glow[1] / glow[2]).toBeGreaterThan(3 * (body[1] / body[2]));
    const constants = shaderConstantsChunk();
    expect(constants).toContain(`#define WATER_BODY_REFLECTANCE ${glslVec3(body)}`);
    expect(constants).toContain(`#define SUBSURFACE_SCATTER ${glslVec3(glow)}`);
    const withoutHalf = WAVELENGTHS.map((w, i) => deepWaterReflectance(PURE_WATER_ABSORPTION[i], 2 * molecularScattering(w))) as [
      number,
      number,
      number,
    ];
    expect(constants).not.toContain(`#define WATER_BODY_REFLECTANCE ${glslVec3(withoutHalf)}`);
  });
});
