import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { LESSON_TEXTS, type LessonText } from '../../../../../src/app/lessons/lessonTexts';
import { findLesson, lessonView } from '../../../../../src/app/lessons/lessonCatalog';
import { defaultParams, paramDefs } from '../../../../../src/sim/params/params';
import { PURE_WATER_ABSORPTION, WAVELENGTHS, molecularScattering } from '../../../../../src/sim/optics/waterColor';
import { sunDirection } from '../../../../../src/sim/optics/sun';
import { crossPoint } from '../../../../../src/sim/optics/cubeCross';
import { SUN_DISC_COS_EDGE } from '../../../../../src/sim/optics/sunDisc';
import { AIR_IOR, WATER_IOR, criticalAngle, fresnelReflectance, schlickReflectance } from '../../../../../src/sim/optics/fresnel';
import { COX_MUNK_INTERCEPT, COX_MUNK_SLOPE, seaSlopeVariance } from '../../../../../src/sim/optics/coxMunk';
import { HIGHLIGHT_KNEE, rollOffHighlight } from '../../../../../src/sim/optics/highlightRollOff';
import { SECOND_SWELL, surfaceStateAt, swellHeight } from '../../../../../src/sim/waves/seed/seedSurface';
import { ANGLE_BAND, HEAVE_BAND } from '../../../../../src/sim/boat/boatMotion';
import { hullSamplePoints, targetPose } from '../../../../../src/sim/boat/boatPose';
import { fresnelTableFromBelow, refractedSunDirection } from '../../../../../src/sim/underwater/snellWindow';
import { WATER_EXTINCTION } from '../../../../../src/sim/underwater/waterFog';
import { GOD_RAY_RANGE } from '../../../../../src/render/underwater/godRayRange';

/**
 * The light cards' numbers and equations against the code that computes them: each number is
 * read out of the card (text, question, choice or MathML), so a card edited without its code,
 * or code changed under its card, fails here. Every kind of check has a planted wrong value
 * that must fail it.
 */
const source = (path: string) => readFileSync(new URL(`../../../../../${path}`, import.meta.url), 'utf8');
const card = (id: string): LessonText => LESSON_TEXTS[id];
const view = (id: string) => lessonView(findLesson(id)!);
const degrees = (radians: number) => (radians * 180) / Math.PI;
const radians = (deg: number) => (deg * Math.PI) / 180;

/** The number a pattern's first group captures in a card's English text (or any string). */
function numberIn(text: string, pattern: RegExp): number {
  const match = text.match(pattern);
  if (!match) throw new Error(`no ${pattern} in: ${text.slice(0, 80)}…`);
  return Number(match[1].replace(/\.$/, '').replace(',', '.').replace('−', '-'));
}

/** |claimed − computed| within half a unit of the claim's last written digit. */
function agrees(claimed: number, written: string, computed: number): boolean {
  const decimals = written.includes('.') || written.includes(',') ? written.split(/[.,]/)[1].length : 0;
  return Math.abs(claimed - computed) <= 0.5 * 10 ** -decimals + 1e-12;
}
/** A number as written in a card, and whether the code's value rounds to it. */
function claim(text: string, pattern: RegExp, computed: number): boolean {
  const match = text.match(pattern);
  if (!match) throw new Error(`no ${pattern} in: ${text.slice(0, 80)}…`);
  // A number that ends a sentence keeps its full stop out.
  const written = match[1].replace(/\.$/, '');
  return agrees(Number(written.replace(',', '.')), written, computed);
}

/** Every number written in a text, as numbers (Spanish decimal commas read as points). */
function numbersOf(text: string): number[] {
  return [...text.replace(/(\d),(\d)/g, '$1.$2').matchAll(/\d+(?:\.\d+)?/g)].map((m) => Number(m[0])).sort((a, b) => a - b);
}

const LIGHT_CARDS = [
  'sky-cube',
  'reflection',
  'fresnel',
  'fresnel-schlick',
  'sun-glint',
  'boat-twin',
  'boat-pitch',
  'snell-window',
  'underwater-fog',
  'caustics',
  'god-rays',
];

describe('light cards: both languages state the same numbers', () => {
  it.each(LIGHT_CARDS)('%s: text, question and choice carry the same numbers in English and Spanish', (id) => {
    const c = card(id);
    const pairs: [string, string][] = [[c.text.en, c.text.es]];
    if (c.question) pairs.push([c.question.ask.en, c.question.ask.es], [c.question.answer.en, c.question.answer.es]);
    if (c.choice) pairs.push([c.choice.en, c.choice.es]);
    for (const [en, es] of pairs) expect(numbersOf(es)).toEqual(numbersOf(en));
  });

  it('a Spanish number changed alone is caught (control)', () => {
    const en = card('snell-window').text.en;
    const es = card('snell-window').text.es.replace('48,6', '46,8');
    expect(numbersOf(es)).not.toEqual(numbersOf(en));
  });

  it('every light card asks a question', () => {
    for (const id of LIGHT_CARDS) expect(card(id).question, id).toBeDefined();
  });
});

describe('sky-cube', () => {
  const c = card('sky-cube');
  const elevation = view('sky-cube').params.sunElevation;

  it('the sun at the asked azimuth lands in the +z cell (rightmost of the middle row), at 20° right of −z’s centre', () => {
    const asked = numberIn(c.question!.ask.en, /Set Sun azimuth to (\d+)°/);
    const from = numberIn(c.question!.ask.en, /azimuth (\d+)°/);
    expect(from).toBe(view('sky-cube').params.sunAzimuth);
    const [x, y] = crossPoint(sunDirection(elevation, asked));
    expect([Math.floor(x), Math.floor(y)]).toEqual([3, 1]);
    const [x0, y0] = crossPoint(sunDirection(elevation, from));
    expect([Math.floor(x0), Math.floor(y0)]).toEqual([1, 1]);
    expect(x0 - 1).toBeGreaterThan(0.5);
    const d = sunDirection(elevation, asked);
    const h = Math.hypot(d[0], d[2]);
    expect(
      claim(c.question!.answer.en, /along \((−?[\d.]+)/, d[0] / h) || claim(c.question!.answer.en, /along \(−([\d.]+)/, -d[0] / h),
    ).toBe(true);
    expect(claim(c.question!.answer.en, /along \(−?[\d.]+, ([\d.]+)\)/, d[2] / h)).toBe(true);
  });

  it('the painted disc’s radius and the real one’s are the code’s', () => {
    expect(claim(c.choice!.en, /drawn ([\d.]+)° in radius/, degrees(Math.acos(SUN_DISC_COS_EDGE)))).toBe(true);
    expect(claim(c.choice!.en, /real one’s is ([\d.]+)°/, 0.2666)).toBe(true);
  });

  it('controls: a sun at 110° is not in the +z cell; a width claim of the diameter 0.53° fails', () => {
    const [x] = crossPoint(sunDirection(elevation, 110));
    expect(Math.floor(x)).not.toBe(3);
    expect(agrees(0.27, '0.27', 2 * 0.2666)).toBe(false);
  });

  it('the equation squares what the cube stores, as skyCube.glsl does', () => {
    expect(source('shaders/skyCube.glsl')).toMatch(/mix\(stored, stored \* stored, uSkySquared\)/);
    expect(c.math).toContain('<msup><mi>s</mi><mn>2</mn></msup>');
  });
});

describe('reflection', () => {
  const c = card('reflection');
  const glslReflect = (i: number[], n: number[]) => {
    const d = i[0] * n[0] + i[1] * n[1] + i[2] * n[2];
    return i.map((v, k) => v - 2 * d * n[k]);
  };
  const v = [0.3, 0.5, Math.sqrt(1 - 0.34)];
  const n = [0.1, Math.sqrt(1 - 0.02), 0.1];

  it('the card’s r = −v + 2(v·n)n is GLSL’s reflect(−v, n), the line the shader runs, and points into the air', () => {
    expect(source('shaders/ocean.frag')).toContain('vec3 r = reflect(-v, n);');
    expect(c.math).toContain('<mi>r</mi><mo>=</mo><mo>−</mo><mi>v</mi><mo>+</mo><mn>2</mn>');
    const vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    const card = v.map((x, k) => -x + 2 * vn * n[k]);
    const shader = glslReflect(
      v.map((x) => -x),
      n,
    );
    card.forEach((x, k) => expect(x).toBeCloseTo(shader[k], 12));
    expect(card[0] * n[0] + card[1] * n[1] + card[2] * n[2]).toBeGreaterThan(0);
  });

  it('control: the old r = v − 2(v·n)n points into the water', () => {
    const vn = v[0] * n[0] + v[1] * n[1] + v[2] * n[2];
    const old = v.map((x, k) => x - 2 * vn * n[k]);
    expect(old[0] * n[0] + old[1] * n[1] + old[2] * n[2]).toBeLessThan(0);
  });

  it('the view is still: no swell, no ripples, roughness off', () => {
    const p = view('reflection').params;
    expect([p.swellAmplitude, p.rippleStrength, p.seaRoughness]).toEqual([0, 0, false]);
  });

  it('Fresnel off is F = 0.5 in the shader; near the camera the true F is below one half, near the horizon above', () => {
    const off = numberIn(source('shaders/ocean.frag'), /fresnelLookup\(uFresnelTable, cosIncidence\) : ([\d.]+);/);
    expect(claim(c.question!.answer.en, /uses F = ([\d.]+)/, off)).toBe(true);
    const { camera } = view('reflection');
    const fov = numberIn(source('src/render/ocean/oceanView.ts'), /new PerspectiveCamera\((\d+),/);
    const [px, py, pz] = camera.position;
    const [tx, ty, tz] = camera.target;
    const down = Math.atan2(py - ty, Math.hypot(tx - px, tz - pz));
    // The lowest ray of the view meets the sea nearest the camera; the centre ray farther off.
    const nearest = Math.PI / 2 - (down + radians(fov / 2));
    expect(fresnelReflectance(Math.cos(nearest), AIR_IOR, WATER_IOR)).toBeLessThan(0.25);
    expect(fresnelReflectance(Math.cos(radians(89)), AIR_IOR, WATER_IOR)).toBeGreaterThan(0.75);
  });

  it('control: a planted F = 0.3 for Fresnel off fails', () => {
    const off = numberIn(source('shaders/ocean.frag'), /fresnelLookup\(uFresnelTable, cosIncidence\) : ([\d.]+);/);
    expect(agrees(0.3, '0.3', off)).toBe(false);
  });
});

describe('fresnel', () => {
  const c = card('fresnel');
  it('2 % at normal incidence, 1 at grazing, water’s index, and the answer’s 0.060 at 60° and one half near 84°', () => {
    expect(claim(c.text.en, /: (\d+) % looking straight down/, 100 * fresnelReflectance(1, AIR_IOR, WATER_IOR))).toBe(true);
    expect(fresnelReflectance(0, AIR_IOR, WATER_IOR)).toBe(1);
    expect(claim(c.text.en, /n₂ = ([\d.]+) \(water\)/, WATER_IOR)).toBe(true);
    const at = numberIn(c.question!.ask.en, /at (\d+)° from the vertical/);
    expect(claim(c.question!.answer.en, /\(([\d.]+) there\)/, fresnelReflectance(Math.cos(radians(at)), AIR_IOR, WATER_IOR))).toBe(true);
    let half = 0;
    for (let d = 0; d <= 90; d += 0.01) if (fresnelReflectance(Math.cos(radians(d)), AIR_IOR, WATER_IOR) < 0.5) half = d;
    expect(claim(c.question!.answer.en, /one half near (\d+)°/, half)).toBe(true);
  });

  it('the table has 256 entries, uploaded as a 256 × 1 float texture read with texelFetch and a hand-written lerp', () => {
    expect(
      claim(
        c.text.en,
        /tabulates F once, (\d+) entries/,
        Number(source('src/render/ocean/oceanEngine.ts').match(/fresnelData = fresnelTable\((\d+)\)/)![1]),
      ),
    ).toBe(true);
    expect(source('src/render/optics/dataTextures.ts')).toMatch(/floatTexture\(table, table.length, 1, RedFormat/);
    expect(source('src/render/optics/dataTextures.ts')).toMatch(/new DataTexture\(data, width, height, format, FloatType\)/);
    const lookup = source('shaders/fresnelLookup.glsl');
    expect(lookup).toContain('texelFetch(table, ivec2(i, 0), 0)');
    expect(lookup).toContain('mix(a, b, x - float(i))');
  });

  it('control: a planted 25 % at 60° fails', () => {
    expect(agrees(0.25, '0.25', fresnelReflectance(Math.cos(radians(60)), AIR_IOR, WATER_IOR))).toBe(false);
  });
});

describe('fresnel-schlick', () => {
  const c = card('fresnel-schlick');
  let largest = 0;
  let angle = 0;
  for (let d = 0; d <= 90; d += 0.01) {
    const cos = Math.cos(radians(d));
    const gap = Math.abs(schlickReflectance(cos, AIR_IOR, WATER_IOR) - fresnelReflectance(cos, AIR_IOR, WATER_IOR));
    if (gap > largest) [largest, angle] = [gap, d];
  }
  const cosAt = Math.cos(radians(angle));

  it('R₀, the largest difference, its angle and both values there are the code’s', () => {
    const r0 = ((WATER_IOR - 1) / (WATER_IOR + 1)) ** 2;
    expect(claim(c.text.en, /= ([\d.]+) for water/, r0)).toBe(true);
    expect(claim(c.math, /<mo>=<\/mo><mn>([\d.]+)<\/mn><\/math>$/, schlickReflectance(1, AIR_IOR, WATER_IOR))).toBe(true);
    expect(claim(c.text.en, /the largest difference, ([\d.]+),/, largest)).toBe(true);
    expect(claim(c.text.en, /lies near (\d+)°/, angle)).toBe(true);
    expect(claim(c.text.en, /Schlick gives ([\d.]+)/, schlickReflectance(cosAt, AIR_IOR, WATER_IOR))).toBe(true);
    expect(claim(c.text.en, /exact table ([\d.]+)/, fresnelReflectance(cosAt, AIR_IOR, WATER_IOR))).toBe(true);
    expect(claim(c.question!.answer.en, /Schlick lies ([\d.]+) above/, largest)).toBe(true);
    const at60 = Math.abs(schlickReflectance(0.5, AIR_IOR, WATER_IOR) - fresnelReflectance(0.5, AIR_IOR, WATER_IOR));
    expect(at60).toBeLessThan(numberIn(c.question!.answer.en, /differ by less than ([\d.]+)/));
  });

  it('the view has Fresnel off, and off the shader uses F = 0.5 for the sky and the glint alike', () => {
    expect(view('fresnel-schlick').params.fresnel).toBe(false);
    const frag = source('shaders/ocean.frag');
    const written = numberIn(c.text.en, /constant F = ([\d.]+)/);
    expect(numberIn(frag, /fresnelLookup\(uFresnelTable, cosIncidence\) : ([\d.]+);/)).toBe(written);
    expect(numberIn(frag, /facetFresnel\(dot\(v, halfway\)\) : ([\d.]+);/)).toBe(written);
  });

  it('control: the old “a few hundredths” (0.03) is not the largest difference', () => {
    expect(agrees(0.03, '0.03', largest)).toBe(false);
  });
});

describe('sun-glint', () => {
  const c = card('sun-glint');
  it('Cox and Munk’s constants, U at 12.5 m, and the tone curve’s knee are the code’s', () => {
    expect(claim(c.text.en, /σ² = ([\d.]+) \+/, COX_MUNK_INTERCEPT)).toBe(true);
    expect(claim(c.text.en, /\+ ([\d.]+) U/, COX_MUNK_SLOPE)).toBe(true);
    expect(source('src/sim/optics/coxMunk.ts')).toContain('coxMunkSlopeVariance(windAtHeight(windSpeed10, 12.5))');
    expect(numberIn(c.text.en, /U the wind speed in m\/s ([\d.]+) m above/)).toBe(12.5);
    expect(claim(c.text.en, /below k = ([\d.]+)/, HIGHLIGHT_KNEE)).toBe(true);
  });

  it('the card’s piecewise f(c) is the code’s roll-off', () => {
    const k = numberIn(c.text.en, /below k = ([\d.]+)/);
    const f = (x: number) => (x <= k ? x : k + (1 - k) * (1 - Math.exp(-(x - k) / (1 - k))));
    for (const x of [0.1, 0.6, 0.8, 1, 2, 10]) expect(f(x)).toBeCloseTo(rollOffHighlight(x), 12);
  });

  it('the answer’s σ² at the view’s wind and at the asked one, the wind converted to 12.5 m', () => {
    const [from, to] = [numberIn(c.question!.ask.en, /from (\d+) to/), numberIn(c.question!.ask.en, /to (\d+) m\/s/)];
    expect(from).toBe(view('sun-glint').params.windSpeed);
    expect(claim(c.question!.answer.en, /from ([\d.]+) to/, seaSlopeVariance(from))).toBe(true);
    expect(claim(c.question!.answer.en, /to ([\d.]+) \(/, seaSlopeVariance(to))).toBe(true);
  });

  it('control: σ² with U₁₀ put in unconverted (0.080 at 15 m/s) fails the card’s 0.081', () => {
    expect(claim(c.question!.answer.en, /to ([\d.]+) \(/, COX_MUNK_INTERCEPT + COX_MUNK_SLOPE * 15)).toBe(false);
  });
});

describe('boat-twin', () => {
  const c = card('boat-twin');
  it('the card’s swell equation, with its 0.45, 1.73 and 37°, is the twin’s swellHeight', () => {
    const amp = numberIn(c.math, /<mo>\+<\/mo><mn>([\d.]+)<\/mn><mspace width="0.1em"\/><mi>sin<\/mi>/);
    const freq = numberIn(c.math, /<mi>sin<\/mi><mo>\(<\/mo><mn>([\d.]+)<\/mn><mi>k<\/mi><mi>u<\/mi>/);
    const turn = radians(numberIn(c.text.en, /axes turned by (\d+)°/));
    expect(agrees(amp, '0.45', SECOND_SWELL.amplitude)).toBe(true);
    expect(claim(c.math, /<mn>(1\.73)<\/mn>/, SECOND_SWELL.frequency)).toBe(true);
    expect(agrees(degrees(turn), '37', degrees(Math.atan2(SECOND_SWELL.sin, SECOND_SWELL.cos)))).toBe(true);
    const params = { ...defaultParams(), swellAmplitude: 1.6, swellFrequency: 0.12 };
    const state = surfaceStateAt(params, 12.3);
    const [p1, p2, p3, p4] = state.swellPhase;
    const k = params.swellFrequency;
    for (const [x, z] of [
      [3, -7],
      [120, 45],
      [-800, 2500],
    ]) {
      // The card's 37° is atan(0.6 / 0.8) rounded (checked above); the sum itself uses the exact turn.
      const u = SECOND_SWELL.cos * x + SECOND_SWELL.sin * z;
      const v = -SECOND_SWELL.sin * x + SECOND_SWELL.cos * z;
      const card =
        params.swellAmplitude *
        (Math.sin(k * x + p1) * Math.cos(k * z + p2) + amp * Math.sin(freq * k * u + p3) * Math.cos(freq * k * v + p4));
      expect(card).toBeCloseTo(swellHeight(state, x, z), 9);
    }
  });

  it('the parity the card quotes is the browser test’s limit, and the answer’s bands are the boat’s', () => {
    const limit = numberIn(source('tests/browser/parity.ts'), /defaults: \{ height: ([\de.-]+),/);
    expect(claim(c.text.en, /within ([\d.]+) mm of this twin/, limit * 1000)).toBe(true);
    expect(claim(c.question!.answer.en, /within ([\d.]+) m of the twin/, HEAVE_BAND)).toBe(true);
    expect(claim(c.question!.answer.en, /within ([\d.]+) rad/, ANGLE_BAND)).toBe(true);
    expect(claim(c.question!.answer.en, /rad \(([\d.]+)°\)/, degrees(ANGLE_BAND))).toBe(true);
    expect(source('src/sim/boat/boatMotion.ts')).toContain('const omega = 1 / controls.response;');
  });

  it('control: a planted 0.5 m band and 0.3 mm parity fail', () => {
    expect(agrees(0.5, '0.5', HEAVE_BAND)).toBe(false);
    expect(agrees(0.3, '0.3', 3e-5 * 1000)).toBe(false);
  });
});

describe('boat-pitch', () => {
  const c = card('boat-pitch');
  const hull = { length: 8, beam: 2.6 };

  it('on a tilted plane the pose is the card’s θ and φ', () => {
    const [sx, sz] = [0.13, -0.21];
    const plane = (x: number, z: number) => sx * x + sz * z;
    for (const heading of [0, 0.7, 2.4]) {
      const pose = targetPose(plane, 3, -4, heading, hull);
      const h = (dx: number, dz: number) => plane(3 + dx, -4 + dz);
      const f = [Math.sin(heading), -Math.cos(heading)];
      const s = [Math.cos(heading), Math.sin(heading)];
      const bow = h(f[0] * 4, f[1] * 4);
      const stern = h(-f[0] * 4, -f[1] * 4);
      const theta = Math.atan((bow - stern) / hull.length);
      const phi = Math.atan((h(s[0] * 1.3, s[1] * 1.3) - h(-s[0] * 1.3, -s[1] * 1.3)) / (hull.beam * Math.sqrt(1 + Math.tan(theta) ** 2)));
      expect(pose.pitch).toBeCloseTo(theta, 12);
      expect(pose.roll).toBeCloseTo(phi, 12);
    }
    expect(c.math).toContain('<msqrt><mn>1</mn><mo>+</mo><msup><mi>tan</mi><mn>2</mn></msup><mi>θ</mi></msqrt>');
  });

  function largestPitch(amplitude: number): { pitch: number; slope: number } {
    const params = { ...view('boat-pitch').params, swellAmplitude: amplitude, rippleStrength: 0 };
    let pitch = 0;
    let slope = 0;
    for (let t = 0; t < 120; t += 0.25) {
      const state = surfaceStateAt(params, t);
      const pose = targetPose((x, z) => swellHeight(state, x, z), 7, -5, 0, hull);
      pitch = Math.max(pitch, Math.abs(pose.pitch));
      slope = Math.max(slope, Math.abs(Math.tan(pose.pitch)));
    }
    return { pitch, slope };
  }

  it('halving the swell about halves the largest pitch; its slopes stay under the answer’s bound', () => {
    const [from, to] = [numberIn(c.question!.ask.en, /from ([\d.]+) m/), numberIn(c.question!.ask.en, /to ([\d.]+) m/)];
    expect(from).toBe(view('boat-pitch').params.swellAmplitude);
    const full = largestPitch(from);
    const half = largestPitch(to);
    expect(half.pitch / full.pitch).toBeGreaterThan(0.48);
    expect(half.pitch / full.pitch).toBeLessThan(0.53);
    expect(full.slope).toBeLessThan(numberIn(c.question!.answer.en, /\(under ([\d.]+)\)/));
  });

  it('the choice’s bands are the boat’s', () => {
    expect(claim(c.choice!.en, /within ([\d.]+) m/, HEAVE_BAND)).toBe(true);
    expect(claim(c.choice!.en, /and ([\d.]+)°/, degrees(ANGLE_BAND))).toBe(true);
  });

  it('control: at four times the amplitude the pitch does not scale (arctangent), and a 0.1 slope bound fails', () => {
    const full = largestPitch(1.6);
    const big = largestPitch(6.4);
    expect(big.pitch / full.pitch).toBeLessThan(3.9);
    expect(full.slope).toBeGreaterThan(0.1);
  });
});

describe('snell-window', () => {
  const c = card('snell-window');
  const theta = degrees(criticalAngle(WATER_IOR, AIR_IOR));
  const below = fresnelTableFromBelow(4096);
  const fromBelow = (deg: number) => below[Math.round(Math.cos(radians(deg)) * 4095)];

  it('θc in text and MathML, the index, the cone’s 97° and 2 % overhead', () => {
    expect(claim(c.text.en, /= ([\d.]+)° it cannot/, theta)).toBe(true);
    expect(claim(c.math, /<mn>([\d.]+)<\/mn><mo>°<\/mo>/, theta)).toBe(true);
    expect(claim(c.text.en, /n_water = ([\d.]+)/, WATER_IOR)).toBe(true);
    expect(claim(c.text.en, /a cone (\d+)° across/, 2 * theta)).toBe(true);
    expect(claim(c.text.en, /from (\d+) % overhead/, 100 * below[below.length - 1])).toBe(true);
  });

  it('the reflectance from below climbs steeply only just before θc, and is 1 beyond it', () => {
    expect(fromBelow(40)).toBeLessThan(0.1);
    expect(fromBelow(48)).toBeGreaterThan(0.3);
    expect(fromBelow(50)).toBe(1);
    expect(source('shaders/ocean.frag')).toContain('(totalReflection ? 1.0 : 0.0)');
  });

  it('control: a planted 41.8° (glass’s θc) fails', () => {
    expect(agrees(41.8, '41.8', theta)).toBe(false);
  });
});

describe('underwater-fog', () => {
  const c = card('underwater-fog');
  it('the extinction ratios, the default and the view’s density are the code’s', () => {
    const [r, g, b] = [...c.text.en.matchAll(/([\d.]+) : ([\d.]+) : ([\d.]+)/g)][0].slice(1).map(Number);
    expect(agrees(r, '9.7', WATER_EXTINCTION[0])).toBe(true);
    expect(agrees(g, '1', WATER_EXTINCTION[1])).toBe(true);
    expect(agrees(b, '0.43', WATER_EXTINCTION[2])).toBe(true);
    expect(numberIn(c.text.en, /\(([\d.]+) is pure water/)).toBe(defaultParams().fogDensity);
    expect(numberIn(c.text.en, /this view sets ([\d.]+)\)/)).toBe(view('underwater-fog').params.fogDensity);
    expect(numberIn(c.question!.ask.en, /density, ([\d.]+) per metre/)).toBe(view('underwater-fog').params.fogDensity);
    expect(numberIn(c.choice!.en, /from ([\d.]+) looking down/)).toBe(
      numberIn(source('shaders/waterVolume.glsl'), /mix\(([\d.]+), 1\.0, up \* up\)/),
    );
  });

  it('the answer’s transmittances over 10 m, and the doubled distance at half the density', () => {
    const sigma = view('underwater-fog').params.fogDensity;
    const d = numberIn(c.question!.answer.en, /over (\d+) m/);
    const t = WATER_EXTINCTION.map((e) => 100 * Math.exp(-sigma * e * d));
    expect(claim(c.question!.answer.en, /red keeps ([\d.]+) %/, t[0])).toBe(true);
    expect(claim(c.question!.answer.en, /green (\d+) %/, t[1])).toBe(true);
    expect(claim(c.question!.answer.en, /blue (\d+) %/, t[2])).toBe(true);
    const twice = numberIn(c.question!.answer.en, /takes (\d+) m/);
    expect(Math.exp(-(sigma / 2) * WATER_EXTINCTION[0] * twice)).toBeCloseTo(t[0] / 100, 12);
  });

  it('control: the old “nearly 10” for red, as a ratio to one decimal, fails', () => {
    expect(agrees(10.0, '10.0', WATER_EXTINCTION[0])).toBe(false);
  });
});

describe('caustics', () => {
  const c = card('caustics');
  const glsl = source('shaders/caustics.glsl');
  it('the patch, the cap and the mix by intensity are the shader’s', () => {
    expect(claim(c.text.en, /of a ([\d.]+) m patch/, numberIn(glsl, /CAUSTICS_PATCH = ([\d.]+);/))).toBe(true);
    expect(claim(c.text.en, /capped at (\d+)/, numberIn(glsl, /CAUSTICS_MAX_GAIN = ([\d.]+);/))).toBe(true);
    expect(claim(c.math, /<mo>,<\/mo><mn>(\d+)<\/mn><mo>\)<\/mo>/, numberIn(glsl, /CAUSTICS_MAX_GAIN = ([\d.]+);/))).toBe(true);
    expect(glsl).toContain('return max(mix(1.0, gain, uCausticsStrength), 0.0);');
    expect(source('src/render/underwater/causticsUniforms.ts')).toContain('u.uCausticsStrength.value = enabled ? intensity : 0;');
  });

  it('control: a planted cap of 4 fails', () => {
    expect(agrees(4, '4', numberIn(glsl, /CAUSTICS_MAX_GAIN = ([\d.]+);/))).toBe(false);
  });
});

describe('god-rays', () => {
  const c = card('god-rays');
  const glsl = source('shaders/godRays.frag');
  const lesson = view('god-rays');

  it('the steps, range, fade depth and phase are the shader’s', () => {
    expect(numberIn(c.text.en, /marches N = (\d+) steps/)).toBe(numberIn(glsl, /GOD_RAY_STEPS = (\d+);/));
    expect(numberIn(c.text.en, /up to (\d+) m/)).toBe(GOD_RAY_RANGE);
    expect(numberIn(c.text.en, /over D = (\d+) m/)).toBe(numberIn(glsl, /SHAFT_FADE_DEPTH = ([\d.]+);/));
    expect(glsl).toContain('float phase = 0.3 + 3.0 * pow(towardsSun, 4.0);');
    expect(c.math).toContain('<mn>0.3</mn><mo>+</mo><mn>3</mn><msup><mi>cos</mi><mn>4</mn></msup>');
  });

  const mu = () => -refractedSunDirection(sunDirection(lesson.params.sunElevation, lesson.params.sunAzimuth))![1];
  /** The card's sum for a level line of sight at the camera's depth, S = 1, one channel of extinction ε. */
  function shafts(sigma: number, epsilon: number): number {
    const depth = -lesson.camera.position[1];
    const n = 40;
    const dt = GOD_RAY_RANGE / n;
    let sum = 0;
    for (let i = 0; i < n; i++) {
      const t = (i + 0.5) * dt;
      sum += Math.exp(-depth / 30) * Math.exp(-sigma * epsilon * (t + depth / mu()));
    }
    return sigma * dt * sum;
  }

  it('the answer: the path down is about 12 m, green keeps about 3 %, blue about a fifth; every channel’s shafts fade', () => {
    const sigma = numberIn(c.question!.ask.en, /to ([\d.]+) per metre/);
    const from = numberIn(c.question!.ask.en, /view’s ([\d.]+) to/);
    expect(from).toBe(lesson.params.fogDensity);
    const path = -lesson.camera.position[1] / mu();
    expect(claim(c.question!.answer.en, /some (\d+) m of water/, path)).toBe(true);
    expect(claim(c.question!.answer.en, /green keeps about (\d+) %/, 100 * Math.exp(-sigma * WATER_EXTINCTION[1] * path))).toBe(true);
    expect(Math.exp(-sigma * WATER_EXTINCTION[2] * path)).toBeCloseTo(1 / 5, 1);
    for (const e of WATER_EXTINCTION) expect(shafts(sigma, e)).toBeLessThan(shafts(from, e));
  });

  it('control: without extinction the denser fog would brighten the shafts, so the answer rests on it', () => {
    expect(shafts(0.3, 0)).toBeGreaterThan(shafts(0.035, 0));
  });
});

describe('second reading: the remaining numbers the code can compute', () => {
  it('sky-cube: the default sky’s cube holds 8 bits a channel', () => {
    expect(numberIn(card('sky-cube').text.en, /in (\d+) bits/)).toBe(8);
    expect(source('src/render/sky/sunSky.ts')).toMatch(/new WebGLCubeRenderTarget\(size, \{\s*type: UnsignedByteType,/);
  });

  it('control: a cube of half floats would not be the card’s 8 bits', () => {
    expect(source('src/render/sky/sunSky.ts')).not.toMatch(/new WebGLCubeRenderTarget\(size, \{\s*type: HalfFloatType,/);
    expect(numberIn(card('sky-cube').text.en, /in (\d+) bits/)).not.toBe(16);
  });

  it('fresnel: still under a quarter at 75°, then most of the rise to 1 comes after it', () => {
    const c = card('fresnel');
    const knee = numberIn(c.question!.answer.en, /only past (\d+)°/);
    const F = (deg: number) => fresnelReflectance(Math.cos(radians(deg)), AIR_IOR, WATER_IOR);
    expect(F(knee)).toBeLessThan(0.25);
    expect(1 - F(knee)).toBeGreaterThan(0.75);
    // Per degree, the rise after the knee is at least three times the rise over the 15° before it.
    expect((F(84) - F(knee)) / (84 - knee)).toBeGreaterThan((3 * (F(knee) - F(knee - 15))) / 15);
  });

  it('control: a knee claimed at 84° would fail, the curve is at one half there', () => {
    expect(fresnelReflectance(Math.cos(radians(84)), AIR_IOR, WATER_IOR)).not.toBeLessThan(0.25);
  });

  it('boat-twin: the question starts from the default response time and ends at the slider’s maximum', () => {
    const ask = card('boat-twin').question!.ask.en;
    expect(numberIn(ask, /from ([\d.]+) s/)).toBe(paramDefs.boatResponse.default);
    expect(numberIn(ask, /to ([\d.]+) s/)).toBe(paramDefs.boatResponse.max);
  });

  it('boat-twin and boat-pitch: five sample points on the hull', () => {
    const points = Object.keys(hullSamplePoints(0, 0, 0, { length: 8, beam: 2.6 })).length;
    expect(points).toBe(5);
    for (const id of ['boat-twin', 'boat-pitch']) {
      expect(card(id).text.en).toContain('five points');
      expect(card(id).text.es).toContain('cinco puntos');
    }
  });

  it('control: a planted response of 0.5 s is not the default, and four points are not the hull’s', () => {
    expect(paramDefs.boatResponse.default).not.toBe(0.5);
    expect(Object.keys(hullSamplePoints(0, 0, 0, { length: 8, beam: 2.6 })).length).not.toBe(4);
  });

  it('snell-window: n_air is the code’s air index', () => {
    expect(claim(card('snell-window').text.en, /n_air = ([\d.]+)\)/, AIR_IOR)).toBe(true);
  });

  it('underwater-fog: 0.035 is pure water’s beam attenuation at the green channel’s wavelength, absorption plus scattering', () => {
    const green = PURE_WATER_ABSORPTION[1] + molecularScattering(WAVELENGTHS[1]);
    expect(claim(card('underwater-fog').text.en, /\(([\d.]+) is pure water/, green)).toBe(true);
  });

  it('control: absorption alone (0.0325) would not give the card’s 0.035', () => {
    expect(claim(card('underwater-fog').text.en, /\(([\d.]+) is pure water/, PURE_WATER_ABSORPTION[1])).toBe(false);
  });

  it('caustics: the choice’s intensities 2 and 3 lie on the slider, and 1 is the physical one', () => {
    const [a, b] = [
      numberIn(card('caustics').choice!.en, /intensity (\d) or/),
      numberIn(card('caustics').choice!.en, /or (\d) exaggerates/),
    ];
    expect(a).toBeGreaterThan(1);
    expect(b).toBeLessThanOrEqual(paramDefs.causticsIntensity.max);
    expect(source('shaders/caustics.glsl')).toContain('uniform float uCausticsStrength;    // 0: flat light, 1: physical concentration');
  });

  it('control: an intensity of 4 would be off the slider', () => {
    expect(4).toBeGreaterThan(paramDefs.causticsIntensity.max);
  });
});
