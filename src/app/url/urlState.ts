import { defaultParams, isParamKey, paramDefs, paramKeys, parseParamText, type OceanParams } from '../../sim/params/params';
import { message, type Message } from '../../sim/params/message';
import { formatCameraText, parseCameraText, type CameraPose } from '../camera/cameraPose';
import { languageFromTag, type Language } from '../language/i18n';
import { isValidTime } from '../../sim/params/simulationTime';
import { BOAT_EXTENT, type BoatSnapshot } from '../../sim/boat/boatMotion';
import { findPreset, presetNames } from './presets';
import type { LessonCatalog } from '../lessons/lessonCatalogLoader';
import { WakeTrack } from '../../sim/wake/wakeTrack';
import { IWAVE_MAX_HEIGHT, IWAVE_MAX_RADIUS } from '../../sim/iwave/fieldSize';
import type { Stone } from './presets';

/** Settings that are not ocean parameters but are understood by the page and the web component. */
export const PAGE_KEYS = [
  't',
  'sky',
  'cam',
  'lang',
  'embed',
  'preset',
  'lesson',
  'boat',
  'boatState',
  'wakeTrack',
  'probe',
  'stones',
] as const;

/** Everything a URL (or an <oceano-view>'s attributes) can say, validated. */
export interface UrlState {
  params: OceanParams;
  /** Frozen time in seconds when `t` is given, otherwise null (time runs). */
  time: number | null;
  /** Base path of the six sky images when the page names its own. */
  sky: string | null;
  camera: CameraPose | null;
  /** A preset's culling camera: the view whose selection freezeCulling keeps. */
  cullingCamera: CameraPose | null;
  /** null: follow the browser. */
  language: Language | null;
  embed: boolean;
  notices: Message[];
  /** Path of the boat's glTF model when the page names its own. */
  boat: string | null;
  /** The boat's motion at `time` (a share link's), to rebuild it exactly; null: start afresh. */
  boatState: BoatSnapshot | null;
  /** The wake's recorded track (WakeTrack.serialize) at `time`, so a link shows the wake it was made with; null: replayed. */
  wakeTrack: WakeTrack | null;
  /** The lesson opened (src/app/lessons/lessonCatalog.ts): its view is in the other fields. */
  lesson: string | null;
  /** `probe=x,z` as written: the sea tools (a chunk fetched only when it is given) read and check it. */
  probe: string | null;
  /** Stones dropped into the interactive waves, each at its own simulation time (a preset's, a share link's). */
  stones: Stone[];
}

/**
 * A sky or model path must stay on this origin: a relative path or one starting with a single "/",
 * made of ordinary path characters, never climbing out with "..".
 */
export function isSafeAssetPath(path: string): boolean {
  return /^[A-Za-z0-9._~\-/]+$/.test(path) && !path.startsWith('//') && !path.split('/').includes('..');
}

export function parseUrlState(search: string, lessons: LessonCatalog | null = null): UrlState {
  return parseSettings(new URLSearchParams(search), lessons);
}

/**
 * Reads settings from name/value pairs: a URL's query or an element's attributes. A preset,
 * then a lesson, is applied first, whatever its position, so that explicit values override it.
 * A lesson is read from `lessons`, the catalog its caller has loaded (lessonCatalogLoader.ts).
 */
export function parseSettings(entries: Iterable<[string, string]>, lessons: LessonCatalog | null = null): UrlState {
  const pairs = Array.from(entries);
  const params = defaultParams();
  const notices: Message[] = [];
  const state: UrlState = {
    params,
    time: null,
    sky: null,
    boat: null,
    boatState: null,
    wakeTrack: null,
    camera: null,
    cullingCamera: null,
    language: null,
    embed: false,
    notices,
    lesson: null,
    probe: null,
    stones: [],
  };

  for (const [key, text] of pairs) {
    if (key !== 'preset') continue;
    const preset = findPreset(text);
    if (preset) {
      Object.assign(params, preset.params);
      state.camera = { position: [...preset.camera.position], target: [...preset.camera.target] };
      state.stones = [...(preset.stones ?? [])];
      if (preset.cullingCamera)
        state.cullingCamera = { position: [...preset.cullingCamera.position], target: [...preset.cullingCamera.target] };
    } else {
      notices.push(message('presetUnknown', { name: text, known: presetNames.join(', ') }));
    }
  }

  for (const [key, text] of pairs) {
    if (key !== 'lesson') continue;
    if (!lessons) throw new Error("A lesson is named: load the lessons' catalog (loadLessonCatalog) and pass it to parseSettings.");
    const lesson = lessons.findLesson(text);
    if (lesson) {
      const view = lessons.lessonView(lesson);
      Object.assign(params, view.params);
      state.camera = view.camera;
      state.stones = view.stones;
      state.cullingCamera = view.cullingCamera;
      state.lesson = lesson.id;
    } else {
      notices.push(message('lessonUnknown', { name: text, known: lessons.lessonIds.join(', ') }));
    }
  }

  for (const [key, text] of pairs) {
    if (key === 't') {
      const value = text.trim() === '' ? NaN : Number(text);
      if (isValidTime(value)) state.time = value;
      else notices.push(message('timeInvalid', { text }));
    } else if (key === 'sky') {
      if (isSafeAssetPath(text)) state.sky = text;
      else notices.push(message('skyInvalid', { text }));
    } else if (key === 'boat') {
      if (isSafeAssetPath(text)) state.boat = text;
      else notices.push(message('boatPathInvalid', { text }));
    } else if (key === 'boatState') {
      const snapshot = parseBoatState(text);
      if (snapshot) state.boatState = snapshot;
      else notices.push(message('boatStateInvalid', { text }));
    } else if (key === 'wakeTrack') {
      try {
        state.wakeTrack = WakeTrack.parse(text);
      } catch {
        notices.push(message('wakeTrackInvalid', { text: text.slice(0, 80) }));
      }
    } else if (key === 'stones') {
      const stones = parseStones(text);
      if (stones) state.stones = stones;
      else notices.push(message('stonesInvalid', { text: text.slice(0, 80) }));
    } else if (key === 'cam') {
      const camera = parseCameraText(text);
      if (camera) state.camera = camera;
      else notices.push(message('cameraInvalid', { text }));
    } else if (key === 'lang') {
      const language = languageFromTag(text);
      if (language) state.language = language;
      else notices.push(message('languageInvalid', { text }));
    } else if (key === 'probe') {
      state.probe = text;
    } else if (key === 'embed') {
      if (text === '1' || text === '' || text === 'true') state.embed = true;
      else if (text !== '0' && text !== 'false') notices.push(message('embedInvalid', { text }));
    } else if (isParamKey(key)) {
      const { value, notice } = parseParamText(key, text);
      (params as Record<string, unknown>)[key] = value;
      if (notice) notices.push(notice);
    } else if (key !== 'preset' && key !== 'lesson') {
      notices.push(message('unknownUrlParam', { key }));
    }
  }
  return state;
}

/** What a shared link has to carry to reproduce a view. */
export interface ShareableState {
  params: OceanParams;
  time: number;
  camera: CameraPose;
  language: Language;
  sky: string | null;
  boat: string | null;
  embed: boolean;
  boatState?: BoatSnapshot | null;
  /** WakeTrack.serialize() of the wake on screen; left out when the wake is off. */
  wakeTrack?: string | null;
  /** The lesson open, so the link opens its card too (its view is overridden by the values that follow). */
  lesson?: string | null;
  /** Where the probe stands, "x,z" (src/app/tools/). */
  probe?: string | null;
  /** The stones that still shape the interactive waves (InteractiveWaves.stones); left out when they are off. */
  stones?: readonly Stone[];
}

/**
 * The query string of a link that reproduces the view: every parameter, the camera and the
 * time, numbers written with String() so they parse back to the same doubles.
 */
export function formatUrlState(state: ShareableState): string {
  const query = new URLSearchParams();
  if (state.lesson) query.set('lesson', state.lesson);
  for (const key of paramKeys) {
    const value = state.params[key];
    const kind = paramDefs[key].kind;
    query.set(key, kind === 'boolean' ? (value ? '1' : '0') : kind === 'color' ? String(value).replace(/^#/, '') : String(value));
  }
  query.set('t', String(state.time));
  query.set('cam', formatCameraText(state.camera));
  query.set('lang', state.language);
  if (state.boatState) query.set('boatState', formatBoatState(state.boatState));
  if (state.wakeTrack && state.params.wake) query.set('wakeTrack', state.wakeTrack);
  // Always written with the field on, an empty list too: the link's stones replace a lesson's.
  if (state.params.interactiveWaves) query.set('stones', formatStones(state.stones ?? []));
  if (state.sky !== null) query.set('sky', state.sky);
  if (state.boat !== null) query.set('boat', state.boat);
  if (state.probe) query.set('probe', state.probe);
  if (state.embed) query.set('embed', '1');
  return query.toString();
}

/** `x,z,heading,headingRate,heave,heaveRate,pitch,pitchRate,roll,rollRate`, numbers written to read back bit for bit. */
export function formatBoatState(b: BoatSnapshot): string {
  return [
    b.x,
    b.z,
    b.heading.value,
    b.heading.velocity,
    b.heave.value,
    b.heave.velocity,
    b.pitch.value,
    b.pitch.velocity,
    b.roll.value,
    b.roll.velocity,
  ]
    .map(String)
    .join(',');
}

/** Ten finite numbers, the position within the boat's square; null otherwise. Only meaningful with `t`. */
export function parseBoatState(text: string): BoatSnapshot | null {
  const parts = text.split(',');
  if (parts.length !== 10 || parts.some((p) => p.trim() === '')) return null;
  const n = parts.map(Number);
  if (!n.every((v) => Number.isFinite(v) && Math.abs(v) <= 1e6) || Math.abs(n[0]) > BOAT_EXTENT || Math.abs(n[1]) > BOAT_EXTENT)
    return null;
  const f = (i: number) => ({ value: n[i], velocity: n[i + 1] });
  return { x: n[0], z: n[1], heading: f(2), heave: f(4), pitch: f(6), roll: f(8) };
}

/** `t,x,z,radius,height;…` (seconds, metres), numbers written to read back bit for bit. */
export function formatStones(stones: readonly Stone[]): string {
  return stones.map((stone) => stone.map(String).join(',')).join(';');
}

/**
 * Stones as a link writes them: each five numbers, a time as the URL's t takes, a place within
 * ±1e6 m, a radius and height as disturb() takes (a radius under one texel is raised when the
 * stone falls); null if any is not.
 */
export function parseStones(text: string): Stone[] | null {
  if (text.trim() === '') return [];
  const stones = text.split(';').map((part) => part.split(',').map((p) => (p.trim() === '' ? NaN : Number(p))));
  const fair = ([t, x, z, r, h, ...rest]: number[]) =>
    rest.length === 0 &&
    isValidTime(t) &&
    Math.abs(x) <= 1e6 &&
    Math.abs(z) <= 1e6 &&
    r > 0 &&
    r <= IWAVE_MAX_RADIUS &&
    Math.abs(h) <= IWAVE_MAX_HEIGHT;
  return stones.every(fair) ? (stones as unknown as Stone[]) : null;
}
