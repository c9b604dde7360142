import type { OceanParams } from '../../sim/params/params';
import type { Rect } from '../../sim/layout/rect';
import { CROSS_CELLS } from '../../sim/optics/cubeCross';
import { compareModelNames } from '../../sim/compare/compareLayout';
import { surfaceStateAt } from '../../sim/waves/seed/seedSurface';
import { crossPlacement, figurePictures, SKY_CUBE_VIEW } from '../../sim/teaching/teachingFigures';
import type { Translator } from '../language/i18n';
import { teachingWord, type TeachingWordId } from '../language/teachingWords';

/** What a caption says and where it goes: centred under `below`, or in the top left corner of `inside`. */
interface Caption {
  text: string;
  below?: Rect;
  inside?: Rect;
}

/**
 * The captions of a teaching view (view=noise-hash …, sky-cube): one under each picture,
 * naming the step of the noise it shows, and the faces of the unfolded cube. They are HTML
 * placed on the layout the renderer draws with (src/sim/teaching/teachingFigures.ts), so a
 * caption sits under its own picture whatever the free part of the canvas is.
 */
export class FigureCaptions {
  private readonly elements: HTMLElement[] = [];
  private placed = '';

  constructor(
    private readonly container: HTMLElement,
    private readonly tr: Translator,
  ) {}

  /** After each frame: the captions of `params.view` in `free` (CSS px of the canvas), at `time` (the blend's weight). */
  place(params: OceanParams, free: Rect, canvas: HTMLElement, time: number): void {
    const captions = this.captions(params, free, time);
    const key = JSON.stringify([captions, canvas.offsetLeft, canvas.offsetTop]);
    if (key === this.placed) return;
    this.placed = key;
    while (this.elements.length > captions.length) this.elements.pop()?.remove();
    while (this.elements.length < captions.length) {
      const element = document.createElement('div');
      this.container.append(element);
      this.elements.push(element);
    }
    captions.forEach((caption, i) => {
      const element = this.elements[i];
      element.textContent = caption.text;
      element.title = caption.text;
      const rect = caption.below ?? caption.inside!;
      element.className = caption.below ? 'oceano-figure-caption' : 'oceano-figure-caption oceano-figure-face';
      // The canvas may not start at the container's corner (it does in the page and the element).
      const x = canvas.offsetLeft + (caption.below ? rect.x + rect.width / 2 : rect.x + 4);
      const y = canvas.offsetTop + (caption.below ? rect.y + rect.height + 4 : rect.y + 4);
      element.style.transform = `translate(${x}px, ${y}px)`;
      element.style.maxWidth = `${Math.max(0, caption.below ? rect.width : rect.width - 8)}px`;
    });
  }

  private captions(params: OceanParams, free: Rect, time: number): Caption[] {
    const word = (id: TeachingWordId) => teachingWord(this.tr, id);
    // The model the heightmap view shows: the ocean's own, the first of a comparison.
    const waves = compareModelNames(params.compare)[0] ?? params.waves;
    if (params.view === 'heightmap' && waves === 'gerstner') return [];
    if (params.view === SKY_CUBE_VIEW) {
      const { box, cell } = crossPlacement(free);
      const faces = CROSS_CELLS.map((c) => ({
        text: word(`face_${c.face}`),
        inside: { x: box.x + c.column * cell, y: box.y + c.row * cell, width: cell, height: cell },
      }));
      return [...faces, { text: word('skyCubeCaption'), below: box }];
    }
    const b = surfaceStateAt(params, time).rippleBlend;
    return figurePictures(params.view, free).map(({ id, rect }) => {
      // Under waves=fft the heightmap view shows the cascades' height fields.
      const name: TeachingWordId =
        waves === 'fft' && id.startsWith('heightmap') ? (id === 'heightmap0' ? 'picture_cascade0' : 'picture_cascade1') : `picture_${id}`;
      return {
        text: word(name).replace('{b}', b.toLocaleString(this.tr.language, { minimumFractionDigits: 2, maximumFractionDigits: 2 })),
        below: rect,
      };
    });
  }

  /** Takes the captions away (the sea is shown again, or the drawer goes). */
  clear(): void {
    for (const element of this.elements) element.remove();
    this.elements.length = 0;
    this.placed = '';
  }
}
