import { message, type Message } from '../../sim/params/message';
import type { OceanParams } from '../../sim/params/params';
import type { BoatSnapshot } from '../../sim/boat/boatMotion';
import type { CameraPose } from '../camera/cameraPose';
import type { OceanAppOptions } from '../boot/appOptions';
import { formatUrlState } from './urlState';
import type { Stone } from './presets';

/** What a shared link carries of the view as it is now, frozen at its time. */
export interface SharedView {
  params: OceanParams;
  time: number;
  camera: CameraPose;
  /** The boat's motion at `time`, so the link rebuilds it exactly (null: it starts afresh). */
  boatState: BoatSnapshot | null;
  /** The wake's track then (WakeTrack.serialize), so the link shows the same wake. */
  wakeTrack?: string | null;
  lesson?: string | null;
  probe?: string | null;
  /** The stones that still shape the interactive waves. */
  stones?: readonly Stone[];
}

/** What it carries of the page as it was opened: its address, language, assets and embedding. */
export type OpenedPage = Pick<OceanAppOptions, 'shareBase' | 'language'> & {
  state: Pick<OceanAppOptions['state'], 'sky' | 'boat' | 'embed'>;
};

/** A link that reopens this exact view: parameters, camera, language, the current time (frozen) and the boat's motion then. */
export function shareUrl(page: OpenedPage, view: SharedView): string {
  const { sky, boat, embed } = page.state;
  const query = formatUrlState({ ...view, language: page.language, sky, boat, embed });
  return `${page.shareBase}?${query}`;
}

/** Copies the link; where the clipboard is refused, shows the link for the user to copy. */
export async function shareLink(url: string, notify: (m: Message) => void): Promise<string> {
  try {
    if (!navigator.clipboard) throw new Error('no clipboard');
    await navigator.clipboard.writeText(url);
    notify(message('shareCopied'));
  } catch {
    notify(message('shareFallback', { url }));
  }
  return url;
}
