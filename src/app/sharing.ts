import { message, type Message } from '../sim/message';
import type { OceanParams } from '../sim/params';
import type { CameraPose } from './cameraPose';
import type { Language } from './i18n';
import { formatUrlState, type UrlState } from './urlState';

/** Everything a shared link carries: the view as it is now, frozen at its time. */
export interface SharedView {
  params: OceanParams;
  time: number;
  camera: CameraPose;
  language: Language;
  /** The asset and embedding choices the page was opened with. */
  opened: Pick<UrlState, 'sky' | 'boat' | 'embed'>;
}

/** A link that reopens this exact view: parameters, camera, language and the current time (frozen). */
export function shareUrl(base: string, view: SharedView): string {
  const { opened } = view;
  const query = formatUrlState({ params: view.params, time: view.time, camera: view.camera, language: view.language, sky: opened.sky, boat: opened.boat, embed: opened.embed });
  return `${base}?${query}`;
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
