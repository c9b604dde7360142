import { describe, expect, it } from 'vitest';
import { message, MESSAGE_IDS, MessageError, messageOf } from '../../../../src/sim/params/message';
import { Translator } from '../../../../src/app/language/i18n';
// The boat's loader brings the texts of the notices only it raises.
import '../../../../src/app/boot/boatLoad';
import '../../../../src/app/boat/agroundNotice';

/** Values as the app passes them: paths, numbers and an English inner error, which Spanish must not repeat. */
const VALUES = {
  key: 'seed',
  text: 'x',
  fallback: 1,
  options: 'water, normals',
  min: 0,
  max: 4,
  unit: 'm',
  clamped: 4,
  base: 'sky',
  url: 'models/none.glb',
  status: 404,
  name: 'nope',
  known: 'still-ocean',
  error: 'The thing was not found (HTTP 404).',
  reason: 'The boat model "models/none.glb" was not found (HTTP 404).',
};
/** Words that only English has, as whole words: one in a Spanish notice means English leaked in. */
const ENGLISH = /\b(the|was|not|found|could|is|with|runs|without|using|boat)\b/i;
/** Doubled punctuation: "..", ".)", ".;" (an inner sentence's stop followed by the outer one). */
const DOUBLED = /[.;:]\s*[.;:)]/;

describe('notices in the page language', () => {
  it('renders every notice in Spanish with no English words and no doubled punctuation', () => {
    const es = new Translator('es');
    for (const id of MESSAGE_IDS) {
      const text = es.message(message(id, VALUES)).replaceAll(/"[^"]*"/g, '""');
      expect(text, id).not.toMatch(ENGLISH);
      expect(text, id).not.toMatch(DOUBLED);
    }
  });

  it('renders every English notice with an inner sentence without doubled punctuation', () => {
    const en = new Translator('en');
    for (const id of MESSAGE_IDS) {
      const text = en.message(message(id, VALUES)).replaceAll(/"[^"]*"/g, '""');
      expect(text, id).not.toMatch(DOUBLED);
    }
  });

  it('carries a failure as a message id, so the boat notice is Spanish end to end', () => {
    const error = new MessageError(message('boatNotFound', { url: 'models/none.glb', status: 404 }), 'English for the console');
    expect(new Translator('es').message(messageOf(error, 'boatLoadFailed'))).toBe(
      'No se encontró el modelo del barco "models/none.glb" (HTTP 404). El océano sigue sin él.',
    );
    expect(messageOf(new Error('boom'), 'boatLoadFailed')).toEqual(message('boatLoadFailed', { reason: 'boom' }));
  });

  // It names the view limit and the way out.
  it('promises nothing about a lost context that the browser may not keep', () => {
    for (const language of ['en', 'es'] as const) {
      const text = new Translator(language).message(message('contextLost'));
      expect(text, language).not.toMatch(/by itself|volverá solo/);
      expect(text, language).toMatch(/16/);
      expect(text, language).toMatch(/reload|recarga/);
    }
  });
});
