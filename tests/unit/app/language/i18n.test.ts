import { describe, expect, it, vi } from 'vitest';
import { paramKeys } from '../../../../src/sim/params/params';
import { message, MESSAGE_IDS, type MessageId } from '../../../../src/sim/params/message';
import { preferredLanguage, Translator } from '../../../../src/app/language/i18n';
// The boat's loader brings the texts of the notices only it raises.
import '../../../../src/app/boot/boatLoad';
import '../../../../src/app/boat/agroundNotice';
import { paramLabel, SPANISH_PARAM_LABELS } from '../../../../src/app/language/paramLabels';
import { parseUrlState } from '../../../../src/app/url/urlState';

/** Values that carry English text, which only the English notice repeats. */
const ENGLISH_ONLY: Partial<Record<MessageId, string>> = { startFailed: 'E7', boatLoadFailed: 'R7' };

describe('language', () => {
  it('follows the first browser language we speak, else English', () => {
    expect(preferredLanguage(['es-AR', 'en'])).toBe('es');
    expect(preferredLanguage(['fr-FR', 'ES'])).toBe('es');
    expect(preferredLanguage(['de', 'fr'])).toBe('en');
    expect(preferredLanguage([])).toBe('en');
  });

  it('has a Spanish label for every parameter, different from the English one where words differ', () => {
    const es = new Translator('es');
    const en = new Translator('en');
    for (const key of paramKeys) {
      expect(SPANISH_PARAM_LABELS[key], key).toBeTruthy();
      expect(paramLabel(es, key)).toBe(SPANISH_PARAM_LABELS[key]);
    }
    expect(paramLabel(es, 'swellAmplitude')).not.toBe(paramLabel(en, 'swellAmplitude'));
  });

  it('renders every notice of a bad URL in both languages, with its values in it', () => {
    const state = parseUrlState(
      '?t=abc&seed=-1.5&swellAmplitude=1e9&bogus=1&fresnel=maybe&waterColor=red&sky=//x&cam=1&lang=fr&embed=2&preset=nope',
    );
    expect(state.notices).toHaveLength(11);
    const es = state.notices.map((m) => new Translator('es').message(m));
    const en = state.notices.map((m) => new Translator('en').message(m));
    es.forEach((text, i) => expect(text).not.toBe(en[i]));
    expect(es.join('\n')).toContain('"swellAmplitude=1e9" está fuera de [0, 4] m; se limita a 4.');
    expect(en.join('\n')).toContain('"swellAmplitude=1e9" is outside [0, 4] m; clamped to 4.');
  });

  it('has both languages for every message id, each carrying the same values', () => {
    // Each value a distinct token, so a translation that drops or swaps one shows.
    const values = {
      key: 'K7',
      text: 'T7',
      fallback: 'F7',
      options: 'O7',
      min: 'MIN7',
      max: 'MAX7',
      unit: 'U7',
      clamped: 'C7',
      name: 'N7',
      known: 'KN7',
      base: 'B7',
      url: 'http://x/?a=URL7',
      error: 'E7',
      reason: 'R7',
      allowed: 'AL7',
      got: 'G7',
      radius: 'RA7',
      raised: 'RR7',
    };
    const tokens = Object.values(values);
    for (const id of MESSAGE_IDS) {
      const m = message(id, values);
      const es = new Translator('es').message(m);
      const en = new Translator('en').message(m);
      expect(es, id).not.toBe(en);
      expect(es.length, id).toBeGreaterThan(10);
      // An inner error is English text (a browser's or library's): Spanish leaves it to the console,
      // so a Spanish page never shows an English sentence.
      const english = ENGLISH_ONLY[id];
      const expected = tokens.filter((t) => en.includes(t) && t !== english);
      expect(
        tokens.filter((t) => es.includes(t)),
        id,
      ).toEqual(expected);
      if (english) expect(en, id).toContain(english);
    }
    expect(MESSAGE_IDS.length).toBe(39);
  });

  it("leaves the boat loader's notices to its own chunk: without it their text is missing and says so", async () => {
    vi.resetModules();
    const fresh = await import('../../../../src/app/language/i18n');
    const notFound = message('boatNotFound', { url: 'm/b.glb', status: 404 });
    expect(() => new fresh.Translator('en').message(notFound)).toThrow(/boatNotFound.*has not loaded/);
    // The notice the page gives when that chunk itself cannot be fetched is in the first script.
    expect(new fresh.Translator('es').message(message('boatLoadFailed', { reason: 'R' }))).toMatch(/No se pudo cargar el barco/);
    await import('../../../../src/app/boot/boatLoad');
    expect(new fresh.Translator('en').message(notFound)).toBe(
      'The boat model "m/b.glb" was not found (HTTP 404). The ocean runs without the boat.',
    );
  });
});
