import { describe, expect, it } from 'vitest';
import { LESSONS, lessonIds, lessonView, findLesson } from '../../../../src/app/lessons/lessonCatalog';
import * as lessons from '../../../../src/app/lessons/lessonCatalog';
import {
  LESSON_OUTLINE,
  LESSON_SECTIONS,
  LESSON_TITLES,
  SECTION_NAMES,
  lessonList,
  type LessonSection,
} from '../../../../src/app/lessons/lessonOutline';
import { LESSON_TEXTS } from '../../../../src/app/lessons/lessonTexts';
import { LESSON_QUOTE_SOURCES } from '../../../../src/app/lessons/lessonQuoteSources';
import { PRESETS, presetNames } from '../../../../src/app/url/presets';
import { isParamKey, defaultParams, validateParams } from '../../../../src/sim/params/params';
import { unreadParams } from '../../../../src/app/panel/unreadParams';
import { formatUrlState, parseUrlState } from '../../../../src/app/url/urlState';
import { CONCEPT_PATH, CONCEPT_STAGES } from '../../../../src/app/lessons/conceptPath';
import { teachingWord } from '../../../../src/app/language/teachingWords';

/** The concept lessons' sections, after the models' (lessonOutline.ts), the coast last. */
const CONCEPT_SECTIONS: LessonSection[] = ['linearWaves', 'spectra', 'filtering', 'light', 'coast'];
const words = (text: string) => text.trim().split(/\s+/).length;
/** The presets no lesson opens. */
const presetsWithoutLesson = (lessons: readonly { preset?: string }[]) =>
  presetNames.filter((name) => !lessons.some((lesson) => lesson.preset === name));

describe('the lessons', () => {
  it('are at least 24, with unique ids, and every part of each lesson exists: outline, title, text, quote', () => {
    expect(LESSONS.length).toBeGreaterThanOrEqual(24);
    expect(new Set(lessonIds).size).toBe(LESSONS.length);
    for (const table of [LESSON_OUTLINE, LESSON_TITLES, LESSON_TEXTS, LESSON_QUOTE_SOURCES])
      expect(Object.keys(table).sort()).toEqual([...lessonIds].sort());
  });

  it('every preset belongs to a lesson (control: dropping the lesson of one leaves it out)', () => {
    expect(presetsWithoutLesson(LESSONS)).toEqual([]);
    expect(presetsWithoutLesson(LESSONS.filter((lesson) => lesson.preset !== 'gale'))).toEqual(['gale']);
  });

  it('follow the seed report’s sections in order, then the ones beyond it', () => {
    const order = LESSONS.map((lesson) => LESSON_SECTIONS.indexOf(LESSON_OUTLINE[lesson.id].section));
    expect(order).toEqual([...order].sort((a, b) => a - b));
    expect(new Set(order).size).toBe(LESSON_SECTIONS.length);
    const beyond = LESSON_SECTIONS.map((section) => SECTION_NAMES[section].beyondSeed);
    expect(beyond.indexOf(true)).toBe(10);
    expect(beyond.slice(10).every(Boolean)).toBe(true);
    // The ideas under every model (concept lessons) come after the models themselves, in the ideas' order.
    expect(LESSON_SECTIONS.slice(LESSON_SECTIONS.indexOf('horizon') + 1)).toEqual(CONCEPT_SECTIONS);
  });

  it.each(lessonIds)('%s: 40–120 words in each language, MathML, 1–5 real controls', (id) => {
    const { text, math } = LESSON_TEXTS[id];
    for (const language of ['en', 'es'] as const) {
      expect(words(text[language]), language).toBeGreaterThanOrEqual(40);
      expect(words(text[language]), language).toBeLessThanOrEqual(120);
      expect(LESSON_TITLES[id][language].length).toBeGreaterThan(3);
    }
    expect(math).toMatch(/^(<math display="block">.*?<\/math>)+$/);
    expect(math.match(/<math /g)!.length).toBe(math.match(/<\/math>/g)!.length);
    const { controls } = LESSON_OUTLINE[id];
    expect(controls.length).toBeGreaterThanOrEqual(1);
    expect(controls.length).toBeLessThanOrEqual(5);
    for (const key of controls) expect(isParamKey(key), key).toBe(true);
  });

  // Control: Q = 0, below Gerstner steepness’s least, is refused.
  it('every lesson’s view lies within its parameters’ ranges', () => {
    for (const lesson of LESSONS) expect(() => validateParams(lessonView(lesson).params), lesson.id).not.toThrow();
    expect(() => validateParams({ ...lessonView(findLesson('airy-waves')!).params, gerstnerSteepness: 0 })).toThrow(/gerstnerSteepness/);
  });

  it('oceano.lessons() says a lesson has a question exactly when its card asks one', () => {
    const listed = lessonList('en');
    expect(listed.map((l) => l.question)).toEqual(listed.map((l) => Boolean(LESSON_TEXTS[l.id].question?.ask.en)));
    // Control: a card without its question would be reported by the same comparison.
    const without = { ...LESSON_TEXTS, swell: { ...LESSON_TEXTS.swell, question: undefined } } as unknown as typeof LESSON_TEXTS;
    expect(listed.map((l) => l.question)).not.toEqual(listed.map((l) => Boolean(without[l.id].question?.ask.en)));
  });

  it('no question repeats the heading the card puts over it, in either language', () => {
    const repeats = (texts: typeof LESSON_TEXTS): string[] =>
      (['en', 'es'] as const).flatMap((language) => {
        const heading = teachingWord({ language }, 'lessonQuestion').toLowerCase();
        return lessonIds
          .filter((id) => texts[id].question?.ask[language].toLowerCase().startsWith(heading))
          .map((id) => `${id} (${language})`);
      });
    expect(repeats(LESSON_TEXTS)).toEqual([]);
    // Control: a question that opens with the heading's words is reported.
    const ask = { en: 'Before you touch anything: what changes?', es: 'Antes de tocar nada: ¿qué cambia?' };
    const planted = { ...LESSON_TEXTS, swell: { ...LESSON_TEXTS.swell, question: { ...LESSON_TEXTS.swell.question!, ask } } };
    expect(repeats(planted as typeof LESSON_TEXTS)).toEqual(['swell (en)', 'swell (es)']);
  });

  it('the word count check fails a 30-word text (control)', () => {
    expect(words('word '.repeat(30))).toBeLessThan(40);
  });

  it('a lesson’s view is the defaults, then its preset’s, then its own parameters and camera', () => {
    const gale = lessonView(findLesson('fft-gale')!);
    expect(gale.params).toEqual({ ...defaultParams(), ...PRESETS.gale.params });
    expect(gale.camera).toEqual(PRESETS.gale.camera);
    const wake = lessonView(findLesson('kelvin-wake')!);
    expect(wake.params.wakeGuide).toBe(true);
    expect(lessonView(findLesson('frustum-culling')!).cullingCamera).toEqual(PRESETS['frustum-culling'].cullingCamera);
    expect(lessonList('es')[0]).toEqual({
      id: 'flat-plane',
      title: LESSON_TITLES['flat-plane'].es,
      section: 'Superficie del agua',
      question: true,
      exercise: false,
    });
  });

  it('?lesson= opens a lesson, explicit values override it, a share link carries it, and an unknown one is a notice', () => {
    const state = parseUrlState('?swellAmplitude=2&lesson=swell-maximum', lessons);
    expect(state.lesson).toBe('swell-maximum');
    expect(state.params.swellFrequency).toBe(0.2);
    expect(state.params.swellAmplitude).toBe(2);
    expect(state.camera).toEqual(PRESETS['swell-maximum'].camera);
    const query = formatUrlState({
      params: state.params,
      time: 3,
      camera: state.camera!,
      language: 'en',
      sky: null,
      boat: null,
      embed: false,
      lesson: 'swell-maximum',
    });
    expect(parseUrlState(`?${query}`, lessons).lesson).toBe('swell-maximum');
    const unknown = parseUrlState('?lesson=nope', lessons);
    expect(unknown.lesson).toBeNull();
    expect(unknown.params).toEqual(defaultParams());
    expect(unknown.notices.map((n) => n.id)).toEqual(['lessonUnknown']);
  });

  it('a URL without a lesson is read without the catalog; one that names a lesson needs it, never skips it', () => {
    expect(parseUrlState('?preset=calm&swellAmplitude=2').params.swellAmplitude).toBe(2);
    // Control: a lesson read without its catalog would be dropped unseen, so it is an error instead.
    expect(() => parseUrlState('?lesson=swell-maximum')).toThrow(/catalog/);
  });
});

describe('the ideas’ order (conceptPath.ts)', () => {
  /** What is wrong with an order: unknown ids, repeats, and concept lessons it leaves out. */
  const faults = (path: readonly string[]) => {
    const concept = LESSONS.filter((lesson) => (CONCEPT_SECTIONS as string[]).includes(LESSON_OUTLINE[lesson.id].section)).map(
      (lesson) => lesson.id,
    );
    return {
      unknown: path.filter((id) => !lessonIds.includes(id)),
      repeated: path.filter((id, i) => path.indexOf(id) !== i),
      missing: concept.filter((id) => !path.includes(id)),
    };
  };

  it('holds every concept lesson, only known ids, each once, every stage named in both languages and not empty', () => {
    expect(faults(CONCEPT_PATH)).toEqual({ unknown: [], repeated: [], missing: [] });
    expect(CONCEPT_PATH.length).toBeGreaterThanOrEqual(4);
    for (const stage of CONCEPT_STAGES) {
      expect(stage.lessons.length).toBeGreaterThan(0);
      expect(stage.name.es).not.toBe(stage.name.en);
    }
    // Linear waves first, group velocity before Gerstner, spectra before the FFT.
    const at = (id: string) => CONCEPT_PATH.indexOf(id);
    expect(at('airy-waves')).toBe(0);
    expect(at('group-velocity')).toBeLessThan(at('gerstner-gentle'));
    expect(at('spectra-compared')).toBeLessThan(at('fft-transform'));
    // The FFT before filtering with distance, filtering before light; light's units open light's stage.
    expect(at('fft-transform')).toBeLessThan(at('slope-filtering'));
    expect(at('slope-filtering')).toBeLessThan(at('light-units'));
    expect(CONCEPT_STAGES.find((stage) => stage.lessons.includes('water-colour'))!.lessons[0]).toBe('light-units');
  });

  it('controls: an unknown id, a repeat and a dropped concept lesson are each reported', () => {
    expect(faults([...CONCEPT_PATH, 'no-such-lesson']).unknown).toEqual(['no-such-lesson']);
    expect(faults([...CONCEPT_PATH, 'fresnel']).repeated).toEqual(['fresnel']);
    expect(faults(CONCEPT_PATH.filter((id) => id !== 'fft-transform')).missing).toEqual(['fft-transform']);
    expect(faults(CONCEPT_PATH.filter((id) => id !== 'water-colour')).missing).toEqual(['water-colour']);
  });
});

describe('parameters a wave model does not read', () => {
  // A comparison reads what each of its models reads.
  it("each model's controls: the swell under fft and gerstner, wind under seed, Gerstner’s under the others", () => {
    const of = (waves: 'seed' | 'fft' | 'gerstner', compare = 'off') => unreadParams({ waves, compare } as never);
    expect(of('fft').get('swellAmplitude')).toBe('unusedBySpectral');
    expect(of('gerstner').has('rippleStrength')).toBe(true);
    expect(of('seed').get('windSpeed')).toBe('unusedBySeed');
    expect(of('seed').has('gerstnerSteepness')).toBe(true);
    expect(of('fft').has('gerstnerSteepness')).toBe(true);
    expect(of('gerstner').has('choppiness')).toBe(true);
    expect(of('seed').has('sunElevation')).toBe(false);
    const compared = of('seed', 'seed,gerstner,fft');
    expect(compared.size).toBe(0);
    expect(of('seed', 'seed,fft').has('gerstnerCount')).toBe(true);
    expect(of('seed', 'seed,fft').has('windSpeed')).toBe(false);
  });

  // The foam’s bias with foam off; the model’s reason first.
  it('what a switch turns off: foam’s bias, the sky’s blur on a mirror, the picked colour under optics', () => {
    const all = defaultParams();
    const bySwitch = (params: typeof all) => [...unreadParams(params).entries()].filter(([, reason]) => reason.startsWith('unusedWithout'));
    // By default the water's colour comes from optics, so only the picked colour is left unread.
    expect(bySwitch({ ...all, waves: 'fft' })).toEqual([['waterColor', 'unusedWithoutPickedColor']]);
    expect(unreadParams({ ...all, waves: 'fft', foam: false }).get('foamFade')).toBe('unusedWithoutFoam');
    expect(unreadParams({ ...all, waves: 'fft', foam: true }).has('foamFade')).toBe(false);
    expect(unreadParams({ ...all, seaRoughness: false }).get('skyBlur')).toBe('unusedWithoutRoughness');
    expect(unreadParams({ ...all, seaRoughness: true }).has('skyBlur')).toBe(false);
    expect(unreadParams({ ...all, waterColorPicked: false }).get('waterColor')).toBe('unusedWithoutPickedColor');
    expect(unreadParams({ ...all, waterColorPicked: true }).has('waterColor')).toBe(false);
    expect(unreadParams({ ...all, caustics: false }).get('causticsIntensity')).toBe('unusedWithoutCaustics');
    expect(unreadParams({ ...all, godRays: false }).get('godRaysIntensity')).toBe('unusedWithoutGodRays');
    // Foam's bias on the seed sea: not read by the model, whatever the switch says.
    expect(unreadParams({ ...all, waves: 'seed', foam: false }).get('foamFade')).toBe('unusedByNonFft');
  });
});
