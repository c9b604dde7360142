/**
 * A user-facing message as data: an id and the values to put into it. The sim and URL
 * layers return these; the app renders them in the page's language (src/app/i18n.ts).
 */
/** Every message's id; the language tables in src/app/i18n.ts are keyed by all of them. */
export const MESSAGE_IDS = [
  'paramNotBoolean',
  'paramNotColour',
  'paramNotChoice',
  'paramNotInteger',
  'paramNotNumber',
  'paramClamped',
  'timeInvalid',
  'skyInvalid',
  'cameraInvalid',
  'languageInvalid',
  'embedInvalid',
  'presetUnknown',
  'unknownUrlParam',
  'skyLoadFailed',
  'skyCustomSunFixed',
  'contextLost',
  'shareCopied',
  'shareFallback',
  'webgl2Missing',
  'startFailed',
  'boatPathInvalid',
  'boatLoadFailed',
] as const;

export type MessageId = (typeof MESSAGE_IDS)[number];

export type MessageValues = Record<string, string | number | boolean>;

export interface Message {
  id: MessageId;
  values: MessageValues;
}

export function message(id: MessageId, values: MessageValues = {}): Message {
  return { id, values };
}
