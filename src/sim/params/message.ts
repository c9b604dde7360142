/**
 * A user-facing message as data: an id and the values to put into it. The sim and URL
 * layers return these; the app renders them in the page's language (src/app/language/i18n.ts).
 */
/** Every message's id; the language tables in src/app/language/i18n.ts are keyed by all of them. */
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
  'lessonUnknown',
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
  'boatUnreachable',
  'boatNotFound',
  'boatWebPage',
  'boatNotGltf',
  'boatNoGeometry',
  'boatStateInvalid',
  'wakeTrackInvalid',
  'modelLoadFailed',
  'panelLoadFailed',
  'underwaterLoadFailed',
  'elementAttributeInvalid',
  'disturbInvalid',
  'disturbRadiusRaised',
  'disturbFieldOff',
  'stonesInvalid',
  'boatAground',
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

/**
 * An error whose notice is a Message, so the page can say it in its own language; the
 * Error's own text (English) is for the console.
 */
export class MessageError extends Error {
  constructor(
    readonly notice: Message,
    english: string,
  ) {
    super(english);
    this.name = 'MessageError';
  }
}

/** The notice for a failure: its own Message when it has one, else `fallback` with the error's text as `reason`. */
export function messageOf(error: unknown, fallback: MessageId): Message {
  if (error instanceof MessageError) return error.notice;
  return message(fallback, { reason: error instanceof Error ? error.message : String(error) });
}
