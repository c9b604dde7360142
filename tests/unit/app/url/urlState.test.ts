import { describe, expect, it } from 'vitest';
import * as lessons from '../../../../src/app/lessons/lessonCatalog';
import { defaultParams, paramDefs, paramKeys } from '../../../../src/sim/params/params';
import { seededRandom } from '../../../../src/sim/noise/integerHash';
import {
  formatStones,
  formatUrlState,
  parseSettings,
  parseStones,
  parseUrlState,
  type ShareableState,
} from '../../../../src/app/url/urlState';
import { formatCameraText, isCameraPose, parseCameraText } from '../../../../src/app/camera/cameraPose';
import { findPreset, PRESETS, presetNames } from '../../../../src/app/url/presets';
import { Translator } from '../../../../src/app/language/i18n';

const english = new Translator('en');

/** A random valid state: every parameter inside its range, awkward doubles for time and camera. */
function randomState(seed: number): ShareableState {
  const random = seededRandom(seed);
  const params = defaultParams();
  for (const key of paramKeys) {
    const def = paramDefs[key];
    const p = params as Record<string, unknown>;
    if (def.kind === 'boolean') p[key] = random() < 0.5;
    else if (def.kind === 'color')
      p[key] = `#${Math.floor(random() * 0xffffff)
        .toString(16)
        .padStart(6, '0')}`;
    else if (def.kind === 'choice') p[key] = def.options[Math.floor(random() * def.options.length)];
    else if (def.kind === 'integer') p[key] = def.min + Math.floor(random() * Math.min(def.max - def.min, 1e6));
    else p[key] = def.min + random() * (def.max - def.min);
  }
  const v = (): [number, number, number] => [random() * 200 - 100, random() * 50 + 0.1, random() * 200 - 100];
  return {
    params,
    time: random() * 1e5,
    camera: { position: v(), target: v() },
    language: random() < 0.5 ? 'es' : 'en',
    sky: null,
    boat: null,
    embed: false,
  };
}

describe('URL state round trip', () => {
  for (const seed of [1, 2, 3, 4, 5, 6, 7, 8]) {
    it(`reads back every parameter, the time and the camera bit for bit (seed ${seed})`, () => {
      const state = randomState(seed);
      const parsed = parseUrlState(`?${formatUrlState(state)}`);
      expect(parsed.notices).toEqual([]);
      expect(parsed.params).toEqual(state.params);
      expect(parsed.time).toBe(state.time);
      expect(parsed.camera).toEqual(state.camera);
      expect(parsed.language).toBe(state.language);
    });
  }

  it('carries sky and embed when set', () => {
    const parsed = parseUrlState(`?${formatUrlState({ ...randomState(9), sky: 'course/sky', embed: true })}`);
    expect(parsed.sky).toBe('course/sky');
    expect(parsed.embed).toBe(true);
  });

  it('carries the probe as written, and leaves it out without one (the sea tools check its text)', () => {
    const parsed = parseUrlState(`?${formatUrlState({ ...randomState(10), probe: '13.7,-4.2' })}`);
    expect(parsed.probe).toBe('13.7,-4.2');
    expect(parsed.notices).toEqual([]);
    expect(parseUrlState(`?${formatUrlState(randomState(10))}`).probe).toBeNull();
  });
});

describe('camera text', () => {
  it('parses six numbers and rejects anything else with null', () => {
    expect(parseCameraText('0,9,40,0,0,-60')).toEqual({ position: [0, 9, 40], target: [0, 0, -60] });
    for (const bad of [
      '',
      '1,2,3,4,5',
      '1,2,3,4,5,6,7',
      '1,2,x,4,5,6',
      '1,2,,4,5,6',
      '1,2,3,1,2,3',
      '0,1e7,0,0,0,0',
      'NaN,0,0,0,0,1',
      'Infinity,0,0,0,0,1',
    ]) {
      expect(parseCameraText(bad), bad).toBeNull();
    }
  });
  it('formats so that parsing gives the same doubles', () => {
    const pose = {
      position: [0.1 + 0.2, 1 / 3, -1e-7] as [number, number, number],
      target: [Math.PI, -Math.E, 123456.789] as [number, number, number],
    };
    expect(parseCameraText(formatCameraText(pose))).toEqual(pose);
    expect(isCameraPose({ position: [0, 1, 2], target: [0, 1] })).toBe(false);
  });
  it('turns a bad cam into a notice and the default camera', () => {
    const state = parseUrlState('?cam=1,2,3');
    expect(state.camera).toBeNull();
    expect(english.message(state.notices[0])).toMatch(/cam=1,2,3/);
  });
});

describe('page settings', () => {
  it('reads lang and embed, and explains bad ones', () => {
    expect(parseUrlState('?lang=es&embed=1')).toMatchObject({ language: 'es', embed: true, notices: [] });
    const bad = parseUrlState('?lang=fr&embed=maybe');
    expect(bad).toMatchObject({ language: null, embed: false });
    expect(bad.notices.map((m) => m.id)).toEqual(['languageInvalid', 'embedInvalid']);
  });
  it('reads element attributes the same way as a URL', () => {
    const state = parseSettings([
      ['swellAmplitude', '2'],
      ['t', '5'],
      ['sky', 'https://evil.example/sky'],
    ]);
    expect(state.params.swellAmplitude).toBe(2);
    expect(state.time).toBe(5);
    expect(state.sky).toBeNull();
    expect(state.notices.map((m) => m.id)).toEqual(['skyInvalid']);
  });
});

describe('presets', () => {
  it('each gives valid parameters and a valid camera', () => {
    for (const name of presetNames) {
      const state = parseUrlState(`?preset=${name}`);
      expect(state.notices, name).toEqual([]);
      expect(isCameraPose(state.camera), name).toBe(true);
      expect(state.params).toMatchObject(PRESETS[name].params);
    }
  });
  it('flat-plane has no displacement and shows the wireframe; still-ocean has no displacement', () => {
    expect(findPreset('flat-plane')?.params).toMatchObject({ swellAmplitude: 0, rippleStrength: 0, wireframe: true });
    expect(findPreset('still-ocean')?.params).toMatchObject({ swellAmplitude: 0, rippleStrength: 0 });
  });
  it('lets explicit parameters override the preset, wherever the preset stands in the URL', () => {
    const state = parseUrlState('?swellAmplitude=1&preset=flat-plane');
    expect(state.params.swellAmplitude).toBe(1);
    expect(state.params.wireframe).toBe(true);
  });
  it('an unknown preset gives a notice naming the known ones and the default view', () => {
    const state = parseUrlState('?preset=nope');
    expect(state.params).toEqual(defaultParams());
    expect(state.camera).toBeNull();
    expect(english.message(state.notices[0])).toMatch(/"nope".*flat-plane, still-ocean/);
  });
  it('does not resolve inherited object keys as presets', () => {
    expect(findPreset('toString')).toBeNull();
    expect(findPreset('__proto__')).toBeNull();
  });
});

describe('stones for the interactive waves (stones=)', () => {
  it("round-trips every number bit for bit, and a preset's stones come with it", () => {
    const stones = [
      [0.1 + 0.2, -3.7, 12 / 7, 1.25, -0.3],
      [10, 1e5, -2, 0.5, 2],
    ] as const;
    expect(parseStones(formatStones(stones))).toEqual(stones);
    expect(parseStones('')).toEqual([]);
    expect(parseUrlState('?preset=stone').stones).toEqual(PRESETS.stone.stones);
    expect(parseUrlState('?preset=stone-compare').stones).toHaveLength(2);
  });

  it("a link writes them with the field on, an empty list too, and its list replaces a lesson's", () => {
    const base = {
      time: 3,
      camera: { position: [0, 5, 10] as [number, number, number], target: [0, 0, 0] as [number, number, number] },
      language: 'en' as const,
      sky: null,
      boat: null,
      embed: false,
    };
    const on = formatUrlState({ ...base, params: { ...defaultParams(), interactiveWaves: true }, stones: [[1, 2, 3, 1, 0.4]] });
    expect(parseUrlState(`?${on}`).stones).toEqual([[1, 2, 3, 1, 0.4]]);
    expect(new URLSearchParams(formatUrlState({ ...base, params: defaultParams(), stones: [[1, 2, 3, 1, 0.4]] })).has('stones')).toBe(
      false,
    );
    const overLesson = formatUrlState({
      ...base,
      params: { ...defaultParams(), interactiveWaves: true },
      lesson: 'iwave-stone',
      stones: [],
    });
    expect(parseUrlState(`?${overLesson}`, lessons).stones).toEqual([]);
    expect(parseUrlState('?lesson=iwave-stone', lessons).stones).toEqual(PRESETS.stone.stones);
  });

  // Control: a good one passes.
  it('a bad list is a notice and no stones: wrong count, time out of range, radius or height too large', () => {
    for (const text of [
      '1,2,3,1',
      '1,2,3,1,0.4,9',
      '-1,0,0,1,0.3',
      '1,0,0,11,0.3',
      '1,0,0,1,2.5',
      '1,NaN,0,1,0.3',
      '1,,0,1,0.3',
      '1,2e6,0,1,0.3',
      '1,0,0,0,0.3',
    ]) {
      const state = parseUrlState(`?stones=${encodeURIComponent(text)}`);
      expect(state.stones, text).toEqual([]);
      expect(
        state.notices.map((n) => n.id),
        text,
      ).toEqual(['stonesInvalid']);
    }
    // A radius under one texel is raised when the stone falls (disturb's rule), not here.
    expect(parseUrlState('?stones=1,0,0,0.1,0.3').stones).toEqual([[1, 0, 0, 0.1, 0.3]]);
    expect(parseUrlState('?stones=1,0,0,1,0.3').notices).toEqual([]);
  });
});
