import type { OceanParams } from '../../sim/params/params';
import { canvasLabel, type Translator } from '../language/i18n';
import { Notices } from './notices';
import { PlayButton } from '../element/playButton';
import { LoadingProgress } from './loadingProgress';

/** What an ocean puts in its container before any GL exists: the canvas, the notices, the play button, the loading steps. */
export interface Scaffold {
  canvas: HTMLCanvasElement;
  notices: Notices;
  playButton: PlayButton;
  loading: LoadingProgress;
}

export function buildScaffold(
  container: HTMLElement,
  tr: Translator,
  params: OceanParams,
  onPlayToggle: () => void,
  alt?: string,
  onProgress?: (fraction: number) => void,
): Scaffold {
  const canvas = document.createElement('canvas');
  canvas.className = 'oceano-canvas';
  canvas.setAttribute('role', 'img');
  labelCanvas(canvas, tr, params, alt);
  container.appendChild(canvas);
  const notices = new Notices(container, tr.ui('dismiss'));
  const playButton = new PlayButton(container, { play: tr.ui('play'), pause: tr.ui('pause') }, onPlayToggle);
  return { canvas, notices, playButton, loading: new LoadingProgress(container, tr, onProgress) };
}

/** The canvas's aria-label says what it shows: it follows the teaching view (heightmaps, normals), unless the page gave its own words (alt). */
export function labelCanvas(canvas: HTMLCanvasElement, tr: Translator, params: OceanParams, alt?: string): void {
  canvas.setAttribute('aria-label', alt ?? canvasLabel(tr, params));
}

/** Removes what buildScaffold made. */
export function disposeScaffold(scaffold: Scaffold): void {
  scaffold.loading.finish();
  scaffold.playButton.dispose();
  scaffold.notices.dispose();
  scaffold.canvas.remove();
}
