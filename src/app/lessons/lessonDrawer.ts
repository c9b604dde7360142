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
import { GlossaryNote } from './glossaryNote';
import { bibliographyList, glossaryList, referencesFold } from './referenceLists';
import { CONCEPT_STAGES, LESSON_ORDERS, ORDER_NAMES, type LessonOrder } from './conceptPath';
import { lessonDiagram, type LessonDiagram } from './diagrams/lessonDiagram';
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

/** The views reachable from the list beside the lessons: every work cited, every term defined. */
type ListView = 'bibliography' | 'glossary';

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
  private readonly listView: HTMLElement;
  private glossaryNote: GlossaryNote | null = null;
  private readonly toggle: HTMLButtonElement;
  private readonly position: HTMLElement;
  private readonly headerTitle: HTMLElement;
  private readonly lessonButtons = new Map<string, HTMLButtonElement>();
  private readonly controls = new Map<
    ParamKey,
    { field: HTMLInputElement | HTMLSelectElement; output: HTMLOutputElement | null; note: HTMLElement; row: HTMLElement }
  >();
  private readonly legend: LessonLegend;
  private readonly captions: FigureCaptions;
  private current: OutlinedLesson | null = null;
  /** Which order the list shows and ‹ › walk: the seed report's, or the ideas' (conceptPath.ts). */
  private order: LessonOrder = 'report';
  private params: OceanParams | null = null;
  private diagram: LessonDiagram | null = null;

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
    this.toggle = button('oceano-lessons-toggle', teachingWord(tr, 'lessonsCollapse'), '', () =>
      this.setCollapsed(!this.root.classList.contains('oceano-lessons-collapsed')),
    );
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
    // Escape closes a term's definition and returns to the term, before anything else hears it.
    this.card.addEventListener('keydown', (event) => {
      if (event.key === 'Escape' && this.glossaryNote?.close(true)) {
        event.preventDefault();
        event.stopPropagation();
      }
    });
    this.listView = element('section', 'oceano-lessons-view');
    this.listView.hidden = true;
    this.body.append(this.list, this.card, this.listView);
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
    const language = this.tr.language;
    // The two orders, as a switch at the top of the list; choosing one rebuilds the list.
    const orders = element('li', 'oceano-lessons-order');
    orders.setAttribute('role', 'group');
    orders.setAttribute('aria-label', LESSON_ORDERS.map((order) => ORDER_NAMES[order][language]).join(' / '));
    for (const order of LESSON_ORDERS) {
      const choose = button('oceano-lessons-order-option', ORDER_NAMES[order][language], ORDER_NAMES[order][language], () => {
        if (this.order === order) return;
        this.order = order;
        this.list.replaceChildren();
        this.lessonButtons.clear();
        this.buildList();
        this.updatePosition();
        this.list.querySelector<HTMLElement>(`[data-order="${order}"]`)?.focus();
      });
      choose.dataset.order = order;
      choose.setAttribute('aria-pressed', String(this.order === order));
      orders.append(choose);
    }
    this.list.append(orders);
    const heading = (text: string, beyondSeed: boolean) => {
      const item = element('li', 'oceano-lessons-section', text);
      item.setAttribute('role', 'presentation');
      if (beyondSeed) item.classList.add('oceano-lessons-beyond');
      this.list.append(item);
    };
    const entry = (id: string, number: number) => {
      const item = element('li', 'oceano-lessons-item');
      const open = button('oceano-lessons-open', LESSON_TITLES[id][language], `${number}. ${LESSON_TITLES[id][language]}`, () =>
        this.open(id),
      );
      open.dataset.lesson = id;
      this.lessonButtons.set(id, open);
      item.append(open);
      this.list.append(item);
    };
    if (this.order === 'ideas') {
      let number = 0;
      for (const stage of CONCEPT_STAGES) {
        heading(stage.name[language], false);
        for (const id of stage.lessons) entry(id, ++number);
      }
    } else {
      let section = '';
      for (const [index, lesson] of LESSONS.map(outlined).entries()) {
        if (lesson.section !== section) {
          section = lesson.section;
          heading(SECTION_NAMES[lesson.section][language], SECTION_NAMES[lesson.section].beyondSeed);
        }
        entry(lesson.id, index + 1);
      }
    }
    // The same course as a page of text with its figures live (dist/course/, beside the app).
    const course = element('a', 'oceano-lessons-course', teachingWord(this.tr, 'coursePage'));
    course.href = `course/index.html?lang=${this.tr.language}`;
    const item = element('li', 'oceano-lessons-item');
    item.append(course);
    this.list.append(item);
    for (const view of ['bibliography', 'glossary'] as const) {
      const open = button('oceano-lessons-extra', teachingWord(this.tr, view), teachingWord(this.tr, view), () => this.showListView(view));
      open.dataset.view = view;
      const entry = element('li', 'oceano-lessons-item');
      entry.append(open);
      this.list.append(entry);
    }
  }

  /** The bibliography or the glossary in place of the list, with a way back to it. */
  private showListView(view: ListView): void {
    const heading = element('h2', 'oceano-lessons-view-title', teachingWord(this.tr, view));
    heading.tabIndex = -1;
    const back = button('oceano-lessons-back', teachingWord(this.tr, 'backToLessons'), `‹ ${teachingWord(this.tr, 'backToLessons')}`, () =>
      this.showList(),
    );
    this.listView.replaceChildren(back, heading, view === 'bibliography' ? bibliographyList() : glossaryList(this.tr));
    this.listView.dataset.view = view;
    this.list.hidden = true;
    this.card.hidden = true;
    this.listView.hidden = false;
    // From its top, wherever the card or the list had been scrolled to.
    this.body.scrollTop = 0;
    heading.focus({ preventScroll: true });
  }

  private open(id: string): void {
    void this.hooks.openLesson(id).then((opened) => {
      if (opened) this.card.querySelector<HTMLElement>('.oceano-lesson-title')?.focus({ preventScroll: true });
    });
  }

  /**
   * Opens the next (+1) or previous (−1) lesson in the chosen order; from the list with none
   * open, or from a lesson the ideas' order leaves out, the first or the last.
   */
  private step(direction: 1 | -1): void {
    const ids = this.order === 'ideas' ? CONCEPT_STAGES.flatMap((stage) => stage.lessons) : LESSONS.map((lesson) => lesson.id);
    const at = this.current ? ids.indexOf(this.current.id) : -1;
    const index = at >= 0 ? at : direction === 1 ? -1 : ids.length;
    const next = ids[index + direction];
    if (next) void this.hooks.openLesson(next);
  }

  private showList(): void {
    this.setCollapsed(false);
    const fromView = !this.listView.hidden ? this.listView.dataset.view : undefined;
    this.card.hidden = true;
    this.listView.hidden = true;
    this.list.hidden = false;
    this.legend.show(null, null);
    // Back from the bibliography or the glossary: to the item that opened it.
    const opener = fromView ? this.list.querySelector<HTMLElement>(`[data-view="${fromView}"]`) : null;
    if (opener) return opener.focus();
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
    const to =
      key === 'Home'
        ? 0
        : key === 'End'
          ? buttons.length - 1
          : Math.min(buttons.length - 1, Math.max(0, at + (key === 'ArrowDown' ? 1 : -1)));
    buttons[to]?.focus();
  }

  private updatePosition(): void {
    const index = this.current ? LESSONS.findIndex((lesson) => lesson.id === this.current?.id) : -1;
    // A figure shows one lesson: its place in the course would say nothing there.
    this.position.textContent = index < 0 || !this.listed ? '' : `${index + 1} / ${LESSONS.length}`;
    this.position.title =
      index < 0
        ? ''
        : teachingWord(this.tr, 'lessonPosition')
            .replace('{n}', String(index + 1))
            .replace('{total}', String(LESSONS.length));
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
    this.listView.hidden = true;
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
    this.glossaryNote = new GlossaryNote(this.tr, `${this.body.id}-term`);
    const text = this.glossaryNote.paragraph('oceano-lesson-text', words.text[language]);
    const math = element('div', 'oceano-lesson-math');
    // Our own MathML, from lessonTexts.ts: never text from the URL or the user.
    math.innerHTML = words.math;
    const code = element('figure', 'oceano-lesson-code');
    const caption = element('figcaption', 'oceano-lesson-code-caption');
    caption.append(
      `${teachingWord(this.tr, 'lessonCode')}: `,
      element('code', 'oceano-lesson-code-file', `${quote.file}:${quote.firstLine}–${quote.lastLine}`),
    );
    const pre = element('pre', 'oceano-lesson-code-text');
    pre.append(element('code', '', quote.text));
    pre.tabIndex = 0;
    code.append(caption, pre);
    const controls = element('fieldset', 'oceano-lesson-controls');
    controls.append(element('legend', '', teachingWord(this.tr, 'lessonControls')));
    this.controls.clear();
    for (const key of lesson.controls) controls.append(this.buildControl(key));
    this.diagram = lessonDiagram(lesson.id, language);
    this.card.append(title, section);
    if (words.question) this.card.append(this.questionBlock(words.question.ask[language], words.question.answer[language]));
    this.card.append(text, this.glossaryNote.element);
    if (words.choice) {
      const choice = element('p', 'oceano-lesson-choice');
      choice.append(element('strong', 'oceano-lesson-choice-label', teachingWord(this.tr, 'lessonChoice')), ' ', words.choice[language]);
      this.card.append(choice);
    }
    this.card.append(math, ...(this.diagram ? [this.diagram.element] : []), code, controls);
    const exercise = lessonExercise(
      lesson.id,
      language,
      () => this.params,
      () => {
        const { time, stoneDropped } = this.hooks.scene();
        return { stoneAge: stoneDropped === null ? null : time - stoneDropped };
      },
    );
    if (exercise) this.card.append(exercise);
    const legend = this.legend.cardLegend(lesson);
    if (legend) this.card.append(legend);
    if (words.references && words.references.length > 0) this.card.append(referencesFold(this.tr, words.references));
    if (this.params) this.sync(this.params);
    if (focusInCard) title.focus({ preventScroll: true });
  }

  /** The question asked before anything is touched; its answer stays hidden until the button is pressed. */
  private questionBlock(ask: string, answer: string): HTMLElement {
    const block = element('section', 'oceano-lesson-question');
    const label = element('p', 'oceano-lesson-question-label', teachingWord(this.tr, 'lessonQuestion'));
    label.id = `${this.body.id}-question`;
    block.setAttribute('aria-labelledby', label.id);
    const shown = element('p', 'oceano-lesson-answer', answer);
    shown.id = `${this.body.id}-answer`;
    shown.hidden = true;
    const reveal = element('button', 'oceano-lesson-reveal', teachingWord(this.tr, 'showAnswer'));
    reveal.type = 'button';
    reveal.setAttribute('aria-expanded', 'false');
    reveal.setAttribute('aria-controls', shown.id);
    reveal.addEventListener('click', () => {
      shown.hidden = !shown.hidden;
      reveal.setAttribute('aria-expanded', String(!shown.hidden));
      reveal.textContent = teachingWord(this.tr, shown.hidden ? 'showAnswer' : 'hideAnswer');
    });
    block.append(label, element('p', 'oceano-lesson-question-ask', ask), reveal, shown);
    return block;
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
    this.diagram?.update(params, this.hooks.scene().time);
  }

  /** After each frame: the labels on the sea, and the captions of a teaching view (view=noise-hash …). */
  placeLabels(): void {
    this.legend.place();
    if (this.params) this.diagram?.update(this.params, this.hooks.scene().time);
    if (!this.params || this.params.view === 'ocean') return this.captions.clear();
    const { canvas, time } = this.hooks.scene();
    this.captions.place(
      this.params,
      FreeArea.of(this.container).rect ?? { x: 0, y: 0, width: canvas.clientWidth, height: canvas.clientHeight },
      canvas,
      time,
    );
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
