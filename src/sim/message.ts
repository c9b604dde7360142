/**
 * A user-facing message as data: an id and the values to put into it. The sim and URL
 * layers return these; the app renders them in the page's language (src/app/i18n.ts).
 */
export type MessageId =
  | 'paramNotBoolean'
  | 'paramNotColour'
  | 'paramNotChoice'
  | 'paramNotInteger'
  | 'paramNotNumber'
  | 'paramClamped'
  | 'timeInvalid'
  | 'skyInvalid'
  | 'cameraInvalid'
  | 'languageInvalid'
  | 'embedInvalid'
  | 'presetUnknown'
  | 'unknownUrlParam'
  | 'skyLoadFailed'
  | 'skyCustomSunFixed'
  | 'contextLost'
  | 'shareCopied'
  | 'shareFallback'
  | 'webgl2Missing'
  | 'startFailed'
  | 'boatPathInvalid'
  | 'boatLoadFailed';

export type MessageValues = Record<string, string | number | boolean>;

export interface Message {
  id: MessageId;
  values: MessageValues;
}

export function message(id: MessageId, values: MessageValues = {}): Message {
  return { id, values };
}
