import { registerNoticeTexts } from '../language/i18n';
import { HULL_DRAFT } from '../../sim/coast/aground';
import { message, type Message } from '../../sim/params/message';

/** The notice of a boat run aground, its texts fetched the first time it runs aground (only a coast has ground). */
export const agroundNotice: Message = message('boatAground', { draft: HULL_DRAFT });

registerNoticeTexts({
  en: {
    boatAground: (v) => `The boat stopped: the water ahead is shallower than its draft of ${v.draft} m. Turn it towards deeper water.`,
  },
  es: {
    boatAground: (v) =>
      `El barco se detuvo: el agua de delante es menos profunda que su calado de ${v.draft} m. Gíralo hacia aguas más profundas.`,
  },
});
