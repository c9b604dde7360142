import { Vector3 } from 'three';
import type { OceanParams } from '../../sim/params/params';
import { bandStart, LOD_BAND_COLORS } from '../../sim/lod/lodBands';
import { kelvinGuideLines } from '../../sim/wake/kelvinGuide';
import { snellWindowHalfAngle } from '../../sim/underwater/snellWindow';
import { hullSamplePoints, type HullPointName } from '../../sim/boat/boatPose';
import type { Rect } from '../../sim/layout/rect';
import type { Translator } from '../language/i18n';
import { teachingWord } from '../language/teachingWords';
import type { OutlinedLesson as Lesson } from './lessonOutline';
import type { LessonHooks } from './lessonHooks';
import { FreeArea } from '../layout/freeArea';

/**
 * How far along the wake guide (metres from the boat; the guide is 150 m long) its angle is
 * written: the first of these whose point is in the free part of the canvas, so a narrow
 * screen that shows only the guide's start still names it.
 */
const KELVIN_LABEL_DISTANCES = [45, 35, 25, 60, 80, 15];
/** The hull's sample points, in the order the labels are made. */
const HULL_POINTS: readonly HullPointName[] = ['centre', 'bow', 'stern', 'port', 'starboard'];

/** A linear RGB channel as the sRGB the page's CSS speaks. */
function srgb(linear: number): number {
  const c = linear <= 0.0031308 ? 12.92 * linear : 1.055 * linear ** (1 / 2.4) - 0.055;
  return Math.round(255 * Math.min(1, Math.max(0, c)));
}

/**
 * What a lesson names on the picture: the LOD bands' colours (a legend in the card), the
 * Kelvin angle written at the end of the wake guide's lines, the edge of Snell's window
 * marked where it meets the sea in front of the camera, and the five points where the boat
 * samples the waves. The labels are HTML over the canvas, placed after each frame from the
 * camera's projection, and only in the part of the canvas the panels leave free: a label
 * that would run past its right edge slides back in.
 */
export class LessonLegend {
  private readonly labels: HTMLElement[] = [];
  private kind: Lesson['legend'] | null = null;
  private params: OceanParams | null = null;
  private bandRows: { band: number; text: HTMLElement }[] = [];

  constructor(
    private readonly container: HTMLElement,
    private readonly tr: Translator,
    private readonly hooks: LessonHooks,
  ) {}

  /** The legend inside the card, or null for a lesson without one. */
  cardLegend(lesson: Lesson): HTMLElement | null {
    this.bandRows = [];
    if (!lesson.legend) return null;
    const box = document.createElement('div');
    box.className = 'oceano-lesson-legend';
    const title = document.createElement('p');
    title.className = 'oceano-lesson-legend-title';
    title.textContent = teachingWord(this.tr, 'lessonLegend');
    box.append(title);
    if (lesson.legend === 'lodBands') {
      const list = document.createElement('ul');
      list.className = 'oceano-lesson-bands';
      for (const [band, colour] of LOD_BAND_COLORS.entries()) {
        const row = document.createElement('li');
        const swatch = document.createElement('span');
        swatch.className = 'oceano-lesson-swatch';
        swatch.style.background = `rgb(${colour.map(srgb).join(', ')})`;
        const text = document.createElement('span');
        row.dataset.band = String(band);
        row.append(swatch, text);
        list.append(row);
        this.bandRows.push({ band, text });
      }
      box.append(list);
    } else {
      const text = document.createElement('p');
      text.textContent = teachingWord(
        this.tr,
        lesson.legend === 'kelvinAngle' ? 'kelvinAngleLabel' : lesson.legend === 'snellWindow' ? 'snellWindowLabel' : 'hullPointsLegend',
      );
      box.append(text);
    }
    return box;
  }

  /** Starts showing the labels of `lesson` (null: none). */
  show(lesson: Lesson | null, params: OceanParams | null): void {
    for (const label of this.labels) label.remove();
    this.labels.length = 0;
    this.kind = lesson?.legend ?? null;
    if (params) this.params = params;
    const texts =
      this.kind === 'kelvinAngle'
        ? [1, 2].map(() => teachingWord(this.tr, 'kelvinAngleLabel'))
        : this.kind === 'snellWindow'
          ? [teachingWord(this.tr, 'snellWindowLabel')]
          : this.kind === 'hullPoints'
            ? HULL_POINTS.map((name) => teachingWord(this.tr, `hull_${name}`))
            : [];
    for (const text of texts) {
      const label = document.createElement('div');
      label.className = `oceano-lesson-label oceano-lesson-label-${this.kind}`;
      label.textContent = text;
      label.hidden = true;
      this.container.append(label);
      this.labels.push(label);
    }
    this.place();
  }

  sync(params: OceanParams): void {
    this.params = params;
    for (const { band, text } of this.bandRows) {
      text.textContent = teachingWord(this.tr, 'lodBandLegend')
        .replace('{band}', String(band))
        .replace('{from}', String(Math.round(bandStart(band, params.lodDistance))));
      text.parentElement?.classList.toggle('oceano-unread', band >= params.lodBands);
    }
  }

  /** Puts each label where its point of the sea is on the canvas, or hides it when that point is out of sight or under a panel. */
  place(): void {
    if (this.labels.length === 0 || !this.params) return;
    const scene = this.hooks.scene();
    const points = this.points(this.params, scene);
    const width = scene.canvas.clientWidth;
    const height = scene.canvas.clientHeight;
    const free: Rect = FreeArea.of(this.container).rect ?? { x: 0, y: 0, width, height };
    // A point's place on the canvas, CSS pixels from its top left, if it is in the free part; none behind the camera.
    const inFree = (world: [number, number, number]): [number, number] | null => {
      const p = new Vector3(...world).project(scene.camera);
      if (Math.abs(p.z) > 1) return null;
      const x = ((p.x + 1) / 2) * width;
      const y = ((1 - p.y) / 2) * height;
      return x >= free.x && x <= free.x + free.width && y >= free.y && y <= free.y + free.height ? [x, y] : null;
    };
    this.labels.forEach((label, i) => {
      let point: [number, number] | null = null;
      for (const world of points[i]) if ((point = inFree(world))) break;
      label.hidden = point === null;
      if (!point) return;
      const right = free.x + free.width;
      let x = point[0];
      if (this.kind === 'hullPoints') {
        // A point's dot stays on its point: the name goes to the dot's left where it would run past the edge.
        label.classList.toggle('oceano-lesson-label-leftwards', x + 4 + label.offsetWidth > right);
      } else {
        // A label begins 4 px right of its point (lessons.css); one that would run past the edge slides back in.
        x = Math.max(free.x, Math.min(x, right - 8 - label.offsetWidth));
      }
      label.style.transform = `translate(${x.toFixed(1)}px, ${point[1].toFixed(1)}px)`;
    });
  }

  /** Where each label may go, in label order: world points, the preferred first; none when it has nothing to mark. */
  private points(params: OceanParams, scene: ReturnType<LessonHooks['scene']>): [number, number, number][][] {
    if (this.kind === 'hullPoints') {
      const { position, heading, hull } = scene.boat;
      const points = hullSamplePoints(position[0], position[2], heading, hull);
      return HULL_POINTS.map((name) => {
        const [x, z] = points[name];
        return [[x, scene.height(x, z), z]];
      });
    }
    if (this.kind === 'kelvinAngle') {
      if (!params.wake || !params.wakeGuide) return [[], []];
      const { position, heading } = scene.boat;
      const ends = KELVIN_LABEL_DISTANCES.map((distance) => kelvinGuideLines(position[0], position[2], heading, distance));
      return [
        ends.map(([, , px, pz]): [number, number, number] => [px, 0, pz]),
        ends.map(([, , , , sx, sz]): [number, number, number] => [sx, 0, sz]),
      ];
    }
    // Where the cone of Snell's window, opening up from the eye, meets a flat sea straight ahead.
    const { position, target } = scene.pose;
    const depth = -position[1];
    if (depth <= 0) return [[]];
    const dx = target[0] - position[0];
    const dz = target[2] - position[2];
    const across = Math.hypot(dx, dz);
    if (across === 0) return [[]];
    const reach = depth * Math.tan(snellWindowHalfAngle());
    return [[[position[0] + (dx / across) * reach, 0, position[2] + (dz / across) * reach]]];
  }

  dispose(): void {
    for (const label of this.labels) label.remove();
  }
}
