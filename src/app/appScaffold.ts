import type { Translator } from './i18n';
import { Notices } from './notices';
import { PlayButton } from './playButton';

/** What an ocean puts in its container before any GL exists: the canvas, the notices, the play button. */
export interface Scaffold {
  canvas: HTMLCanvasElement;
  notices: Notices;
  playButton: PlayButton;
}

export function buildScaffold(container: HTMLElement, tr: Translator, onPlayToggle: () => void): Scaffold {
  const canvas = document.createElement('canvas');
  canvas.className = 'oceano-canvas';
  canvas.setAttribute('role', 'img');
  canvas.setAttribute('aria-label', tr.ui('canvasLabel'));
  container.appendChild(canvas);
  const notices = new Notices(container, tr.ui('dismiss'));
  const playButton = new PlayButton(container, { play: tr.ui('play'), pause: tr.ui('pause') }, onPlayToggle);
  return { canvas, notices, playButton };
}

/** Removes what buildScaffold made. */
export function disposeScaffold(scaffold: Scaffold): void {
  scaffold.playButton.dispose();
  scaffold.notices.dispose();
  scaffold.canvas.remove();
}
