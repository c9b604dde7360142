import './lessons.css';
import { LESSON_QUOTES } from 'virtual:oceano-lesson-quotes';
import { paramDefs, type OceanParams, type ParamDef, type ParamKey } from '../../sim/params/params';
import type { Translator } from '../language/i18n';
import { teachingWord } from '../language/teachingWords';
import { paramLabel } from '../language/paramLabels';
import { unreadParams } from '../panel/unreadParams';
import { LESSONS, findLesson } from './lessonCatalog';
import { LESSON_TITLES, SECTION_NAMES, outlined, type OutlinedLesson } from './lessonOutline';
import type { LessonHooks } from './lessonHooks';
import { LESSON_TEXTS } from './lessonTexts';
import { LessonLegend } from './lessonLegend';
import { FreeArea } from '../layout/freeArea';
import { FigureCaptions } from './figureCaptions';
import { lessonExercise } from './lessonExercise';


/** Views at least this wide (CSS px) show the list of lessons unfolded when none is open. */
const ROOMY_WIDTH = 1000;
/** Figures in a course page narrower than this show their card folded to its title, the sea in sight; a click unfolds it. */
const SMALL_FIGURE = 480;

/** Keys that walk the lessons while the focus is in the drawer (outside its form fields). */
const NEXT_KEYS = new Set(['ArrowRight', 'PageDown']);
const PREVIOUS_KEYS = new Set(['ArrowLeft', 'PageUp']);
/** Keys that move the focus along the list of lessons. */
const LIST_KEYS = new Set(['ArrowDown', 'ArrowUp', 'Home', 'End']);

function element<K extends keyof HTMLElementTagNameMap>(tag: K, className: string, text?: string): HTMLElementTagNameMap[K] {
  const el = document.createElement(tag);
  el.className = className;
  if (text !== undefined) el.textContent = text;
  return el;
}

function button(className: string, label: string, text: string, onClick: () => void): HTMLButtonElement {
  const b = element('button', className, text);
  b.type = 'button';
  b.setAttribute('aria-label', label);
  b.title = label;
  b.addEventListener('click', onClick);
  return b;
}

/**
 * The Lessons drawer: the course's lessons in order, and the open lesson's card (what you
 * see and why, its equations in MathML, the code that does it quoted from its file, the
 * controls that matter, its legend). Collapsible; every part is a button or a form field,
 * so it is walked with Tab and Enter, or with the arrow keys.
 */
export class LessonDrawer {
  readonly root: HTMLElement;
  private readonly body: HTMLElement;
  private readonly list: HTMLOListElement;
  private readonly card: HTMLElement;
  private readonly toggle: HTMLButtonElement;
  private readonly position: HTMLElement;
  private readonly headerTitle: HTMLElement;
  private readonly lessonButtons = new Map<string, HTMLButtonElement>();
  private readonly controls = new Map<ParamKey, { field: HTMLInputElement | HTMLSelectElement; output: HTMLOutputElement | null; note: HTMLElement; row: HTMLElement }>();
  private readonly legend: LessonLegend;
  private readonly captions: FigureCaptions;
  private current: OutlinedLesson | null = null;
  private params: OceanParams | null = null;

  constructor(
    private readonly container: HTMLElement,
    private readonly tr: Translator,
    private readonly listed: boolean,
    private readonly hooks: LessonHooks,
  ) {
    this.root = element('nav', 'oceano-lessons');
    this.root.setAttribute('aria-label', teachingWord(tr, 'lessonsTitle'));
    this.root.lang = tr.language;
    const header = element('div', 'oceano-lessons-header');
    this.toggle = button('oceano-lessons-toggle', teachingWord(tr, 'lessonsCollapse'), '', () => this.setCollapsed(!this.root.classList.contains('oceano-lessons-collapsed')));
    this.toggle.setAttribute('aria-expanded', 'true');
    // A figure's card (not listed) is titled with its lesson: folded, that title is all it shows.
    this.headerTitle = element('span', 'oceano-lessons-title', teachingWord(tr, 'lessonsTitle'));
    this.toggle.append(element('span', 'oceano-lessons-chevron'), this.headerTitle);
    this.position = element('span', 'oceano-lessons-position');
    header.append(this.toggle, this.position);
    if (listed) {
      header.append(
        button('oceano-lessons-all', teachingWord(tr, 'lessonsList'), '☰', () => this.showList()),
        button('oceano-lessons-previous', teachingWord(tr, 'lessonPrevious'), '‹', () => this.step(-1)),
        button('oceano-lessons-next', teachingWord(tr, 'lessonNext'), '›', () => this.step(1)),
      );
    }
    this.body = element('div', 'oceano-lessons-body');
    this.body.id = `oceano-lessons-body-${Math.random().toString(36).slice(2)}`;
    this.toggle.setAttribute('aria-controls', this.body.id);
    this.list = element('ol', 'oceano-lessons-list');
    this.card = element('article', 'oceano-lesson-card');
    this.card.hidden = true;
    this.body.append(this.list, this.card);
    this.root.append(header, this.body);
    if (listed) this.buildList();
    else this.list.hidden = true;
    this.root.addEventListener('keydown', this.onKeyDown);
    container.appendChild(this.root);
    container.classList.add(listed ? 'oceano-with-lessons' : 'oceano-with-lesson-card');
    this.legend = new LessonLegend(container, tr, hooks);
    this.captions = new FigureCaptions(container, tr);
    FreeArea.of(container).avoid(this.root);
    this.updatePosition();
    // Where the list would cover much of the sea (a phone, a small window), it starts folded
    // to its header; opening a lesson unfolds it.
    if (container.clientWidth < ROOMY_WIDTH) this.setCollapsed(true);
  }

  private buildList(): void {
    let section = '';
    for (const [index, lesson] of LESSONS.map(outlined).entries()) {
      if (lesson.section !== section) {
        section = lesson.section;
        const info = SECTION_NAMES[lesson.section];
        const heading = element('li', 'oceano-lessons-section', info[this.tr.language]);
        heading.setAttribute('role', 'presentation');
        if (info.beyondSeed) heading.classList.add('oceano-lessons-beyond');
        this.list.append(heading);
      }
      const item = element('li', 'oceano-lessons-item');
      const open = button('oceano-lessons-open', LESSON_TITLES[lesson.id][this.tr.language], `${index + 1}. ${LESSON_TITLES[lesson.id][this.tr.language]}`, () => this.open(lesson.id));
      open.dataset.lesson = lesson.id;
      this.lessonButtons.set(lesson.id, open);
      item.append(open);
      this.list.append(item);
    }
    // The same course as a page of text with its figures live (dist/course/, beside the app).
    const course = element('a', 'oceano-lessons-course', teachingWord(this.tr, 'coursePage'));
    course.href = `course/index.html?lang=${this.tr.language}`;
    const item = element('li', 'oceano-lessons-item');
    item.append(course);
    this.list.append(item);
  }

  private open(id: string): void {
    if (this.hooks.openLesson(id)) this.card.querySelector<HTMLElement>('.oceano-lesson-title')?.focus({ preventScroll: true });
  }

  /** Opens the next (+1) or previous (−1) lesson; from the list with none open, the first or the last. */
  private step(direction: 1 | -1): void {
    const index = this.current ? LESSONS.findIndex((lesson) => lesson.id === this.current?.id) : direction === 1 ? -1 : LESSONS.length;
    const next = LESSONS[index + direction];
    if (next) this.hooks.openLesson(next.id);
  }

  private showList(): void {
    this.setCollapsed(false);
    this.card.hidden = true;
    this.list.hidden = false;
    this.legend.show(null, null);
    (this.current ? this.lessonButtons.get(this.current.id) : this.list.querySelector('button'))?.focus();
  }

  private setCollapsed(collapsed: boolean): void {
    this.root.classList.toggle('oceano-lessons-collapsed', collapsed);
    this.toggle.setAttribute('aria-expanded', String(!collapsed));
    const label = teachingWord(this.tr, collapsed ? 'lessonsExpand' : 'lessonsCollapse');
    this.toggle.setAttribute('aria-label', `${teachingWord(this.tr, 'lessonsTitle')}: ${label}`);
    this.toggle.title = label;
  }

  private readonly onKeyDown = (event: KeyboardEvent): void => {
    const target = event.target as HTMLElement;
    if (['INPUT', 'SELECT', 'TEXTAREA'].includes(target.tagName)) return;
    if (this.listed && NEXT_KEYS.has(event.key)) this.step(1);
    else if (this.listed && PREVIOUS_KEYS.has(event.key)) this.step(-1);
    else if (LIST_KEYS.has(event.key) && !this.list.hidden) this.moveListFocus(event.key);
    else return;
    // The page's own keys steer the boat and turn the camera: not while walking the lessons.
    event.preventDefault();
    event.stopPropagation();
  };

  private moveListFocus(key: string): void {
    const buttons = [...this.lessonButtons.values()];
    const at = buttons.indexOf(document.activeElement as HTMLButtonElement);
    const to = key === 'Home' ? 0 : key === 'End' ? buttons.length - 1 : Math.min(buttons.length - 1, Math.max(0, at + (key === 'ArrowDown' ? 1 : -1)));
    buttons[to]?.focus();
  }

  private updatePosition(): void {
    const index = this.current ? LESSONS.findIndex((lesson) => lesson.id === this.current?.id) : -1;
    // A figure shows one lesson: its place in the course would say nothing there.
    this.position.textContent = index < 0 || !this.listed ? '' : `${index + 1} / ${LESSONS.length}`;
    this.position.title = index < 0 ? '' : teachingWord(this.tr, 'lessonPosition').replace('{n}', String(index + 1)).replace('{total}', String(LESSONS.length));
    for (const [id, b] of this.lessonButtons) {
      if (id === this.current?.id) b.setAttribute('aria-current', 'true');
      else b.removeAttribute('aria-current');
    }
  }

  /** Shows the card of lesson `id` (the app has already set its view). */
  show(id: string): void {
    const found = findLesson(id);
    if (!found) return;
    const lesson = outlined(found);
    this.current = lesson;
    this.hooks.openFolders(lesson.controls);
    this.renderCard(lesson);
    this.list.hidden = true;
    this.card.hidden = false;
    if (!this.listed) this.headerTitle.textContent = LESSON_TITLES[lesson.id][this.tr.language];
    if (this.listed || this.container.clientWidth >= SMALL_FIGURE) this.setCollapsed(false);
    this.updatePosition();
    this.legend.show(lesson, this.params);
  }

  private renderCard(lesson: OutlinedLesson): void {
    const language = this.tr.language;
    const words = LESSON_TEXTS[lesson.id];
    const quote = LESSON_QUOTES[lesson.id];
    // Walking with the keys from inside the card: the focus stays in it, on the new title.
    const focusInCard = this.card.contains(document.activeElement);
    this.card.replaceChildren();
    this.card.dataset.lesson = lesson.id;
    const title = element('h2', 'oceano-lesson-title', LESSON_TITLES[lesson.id][language]);
    title.tabIndex = -1;
    const section = element('p', 'oceano-lesson-section', SECTION_NAMES[lesson.section][language]);
    const text = element('p', 'oceano-lesson-text', words.text[language]);
    const math = element('div', 'oceano-lesson-math');
    // Our own MathML, from lessonTexts.ts: never text from the URL or the user.
    math.innerHTML = words.math;
    const code = element('figure', 'oceano-lesson-code');
    const caption = element('figcaption', 'oceano-lesson-code-caption');
    caption.append(`${teachingWord(this.tr, 'lessonCode')}: `, element('code', 'oceano-lesson-code-file', `${quote.file}:${quote.firstLine}–${quote.lastLine}`));
    const pre = element('pre', 'oceano-lesson-code-text');
    pre.append(element('code', '', quote.text));
    pre.tabIndex = 0;
    code.append(caption, pre);
    const controls = element('fieldset', 'oceano-lesson-controls');
    controls.append(element('legend', '', teachingWord(this.tr, 'lessonControls')));
    this.controls.clear();
    for (const key of lesson.controls) controls.append(this.buildControl(key));
    this.card.append(title, section, text, math, code, controls);
    const exercise = lessonExercise(lesson.id, language, () => this.params);
    if (exercise) this.card.append(exercise);
    const legend = this.legend.cardLegend(lesson);
    if (legend) this.card.append(legend);
    if (this.params) this.sync(this.params);
    if (focusInCard) title.focus({ preventScroll: true });
  }

  private buildControl(key: ParamKey): HTMLElement {
    const def: ParamDef = paramDefs[key];
    const row = element('label', 'oceano-lesson-control');
    const unit = 'unit' in def && def.unit ? ` (${def.unit})` : '';
    row.append(element('span', 'oceano-lesson-control-name', `${paramLabel(this.tr, key)}${unit}`));
    let field: HTMLInputElement | HTMLSelectElement;
    let output: HTMLOutputElement | null = null;
    const emit = (value: OceanParams[ParamKey]) => this.hooks.onParam(key, value);
    if (def.kind === 'choice') {
      const select = element('select', '');
      for (const option of def.options) select.append(new Option(option, option));
      select.addEventListener('change', () => emit(select.value as OceanParams[ParamKey]));
      field = select;
    } else {
      const input = element('input', '');
      if (def.kind === 'boolean') {
        input.type = 'checkbox';
        input.addEventListener('change', () => emit(input.checked));
      } else if (def.kind === 'color') {
        input.type = 'color';
        input.addEventListener('input', () => emit(input.value));
      } else if (def.max - def.min > 1e6) {
        input.type = 'number';
        input.step = '1';
        input.addEventListener('change', () => emit(Number(input.value)));
      } else {
        input.type = 'range';
        input.min = String(def.min);
        input.max = String(def.max);
        input.step = String(def.kind === 'integer' ? 1 : (def.step ?? (def.max - def.min) / 100));
        output = element('output', 'oceano-lesson-control-value');
        input.addEventListener('input', () => emit(Number(input.value)));
      }
      field = input;
    }
    field.dataset.param = key;
    row.append(field);
    if (output) row.append(output);
    const note = element('span', 'oceano-lesson-control-note');
    row.append(note);
    this.controls.set(key, { field, output, note, row });
    return row;
  }

  /** Shows parameter values changed elsewhere, and disables, with the reason, what the models on screen do not read. */
  sync(params: OceanParams): void {
    this.params = params;
    const unread = unreadParams(params);
    for (const [key, { field, output, note, row }] of this.controls) {
      const value = params[key];
      if (field instanceof HTMLInputElement && field.type === 'checkbox') field.checked = value as boolean;
      else if (document.activeElement !== field) field.value = String(value);
      if (output) output.value = String(value);
      const reason = unread.get(key);
      field.disabled = reason !== undefined;
      row.classList.toggle('oceano-unread', reason !== undefined);
      note.textContent = reason ? teachingWord(this.tr, reason) : '';
    }
    this.legend.sync(params);
  }

  /** After each frame: the labels on the sea, and the captions of a teaching view (view=noise-hash …). */
  placeLabels(): void {
    this.legend.place();
    if (!this.params || this.params.view === 'ocean') return this.captions.clear();
    const { canvas, time } = this.hooks.scene();
    this.captions.place(this.params, FreeArea.of(this.container).rect ?? { x: 0, y: 0, width: canvas.clientWidth, height: canvas.clientHeight }, canvas, time);
  }

  dispose(): void {
    this.root.removeEventListener('keydown', this.onKeyDown);
    this.legend.dispose();
    this.captions.clear();
    FreeArea.of(this.container).release(this.root);
    this.root.remove();
    this.container.classList.remove('oceano-with-lessons', 'oceano-with-lesson-card');
  }
}
