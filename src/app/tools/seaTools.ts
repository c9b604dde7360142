import { Vector3 } from 'three';
import './seaTools.css';
import { pickSea } from '../../sim/tools/seaPick';
import { cursorStep, isCursorKey } from '../../sim/tools/seaCursor';
import { formatProbeText, isProbeCoordinate, parseProbeText } from '../../sim/tools/probePlace';
import { SeaPin } from '../../render/teaching/seaMarkers';
import { toolNumber, toolWord, type ToolWordId } from '../language/toolWords';
import type { SeaToolsHost } from './seaToolsHost';
import type { SeaTool, SeaToolContext, SeaXZ } from './seaTool';
import { ProbeTool, type ProbeReading } from './probeTool';
import { RulerTool } from './rulerTool';
import { DisturbTool } from './disturbTool';

export type SeaToolName = 'none' | 'probe' | 'ruler' | 'disturb';
const TOOL_NAMES: SeaToolName[] = ['none', 'probe', 'ruler', 'disturb'];
const HELP: Record<SeaToolName, ToolWordId> = { none: 'helpNone', probe: 'helpProbe', ruler: 'helpRuler', disturb: 'helpDisturb' };

/** The keyboard moves its point this far per arrow press, m; with Shift, FINE_STEP. */
const STEP = 1;
const FINE_STEP = 0.1;
const CURSOR_COLOUR = 0x7fd4ff;
const UP: [number, number, number] = [0, 1, 0];
/** A phone held upright (as the page's stylesheets say it): the card starts with its help folded. */
const NARROW = '(max-width: 560px)';
/** Each toolbox's radio group needs a name of its own: a course page may hold several oceans. */
let toolboxes = 0;

/**
 * The teacher's sea tools beside one ocean: a card to choose among the probe, the ruler and
 * stones, and the one way they all pick a point of the sea: a ray from the eye through the
 * pointer, met with the surface as drawn (src/sim/tools/seaPick.ts), or the keyboard's point
 * moved with the arrows. The code is a chunk of its own, fetched when the tools are first
 * opened, a ?probe= link is followed, or oceano.probe() is called.
 *
 * A press on the sea with a tool chosen belongs to the tool; a press on the sky (or with no
 * tool) still turns the camera.
 */
export class SeaTools {
  private tool: SeaToolName = 'none';
  private readonly context: SeaToolContext;
  private readonly card = document.createElement('section');
  private readonly help = document.createElement('p');
  private readonly howTo = document.createElement('details');
  private readonly radios = new Map<SeaToolName, HTMLInputElement>();
  private readonly keys = document.createElement('button');
  /** Where the keyboard's point is, read out as it moves. */
  private readonly cursorText = document.createElement('p');
  private readonly probe: ProbeTool;
  private readonly ruler: RulerTool;
  private readonly disturb: DisturbTool;
  private readonly tools: Record<Exclude<SeaToolName, 'none'>, SeaTool>;
  private readonly cursorPin = new SeaPin(CURSOR_COLOUR);
  /** The keyboard's point, while the keys button has the focus. */
  private cursor: SeaXZ | null = null;
  private dragging = false;
  private readonly ray = new Vector3();

  constructor(private readonly app: SeaToolsHost) {
    const view = app.view;
    this.context = {
      tr: app.tr,
      scene: view.scene,
      camera: view.camera,
      canvas: app.canvas,
      time: () => app.clock.time,
      params: () => app.getParams(),
      pose: () => app.camera(),
      height: (x, z) => this.height(x, z),
      dropStone: (point) => this.dropStone(point),
      notify: (text) => app.notices.show(text),
      redraw: () => app.loop.requestRender(),
    };
    this.probe = new ProbeTool(this.context);
    this.ruler = new RulerTool(this.context, app.container);
    this.disturb = new DisturbTool(this.context);
    this.tools = { probe: this.probe, ruler: this.ruler, disturb: this.disturb };
    view.scene.add(this.cursorPin.object);
    this.buildCard();
    app.container.addEventListener('pointerdown', this.onPointerDown, true);
    const probeText = app.options.state.probe;
    if (probeText !== null) {
      const point = parseProbeText(probeText);
      if (point) this.placeProbe(point);
      else this.context.notify(toolWord(app.tr, 'probeInvalid', { text: probeText }));
    }
  }

  /** Shows the card, its tool choice focused. */
  open(): void {
    this.card.hidden = false;
    this.radios.get(this.tool)?.focus();
  }

  /** Chooses what a press on the sea does; the stones turn the interactive waves on. */
  choose(tool: SeaToolName): void {
    this.tool = tool;
    this.card.hidden = false;
    const radio = this.radios.get(tool);
    if (radio) radio.checked = true;
    this.help.textContent = toolWord(this.app.tr, HELP[tool]);
    if (tool === 'disturb' && !this.app.getParams().interactiveWaves) {
      this.app.setParams({ interactiveWaves: true });
      this.disturb.say(toolWord(this.app.tr, 'wavesOn'));
    }
    this.showSections();
  }

  /** Closes the card and takes the probe and the ruler off the sea. */
  close(): void {
    this.choose('none');
    for (const tool of Object.values(this.tools)) tool.clear();
    this.card.hidden = true;
    this.hideCursor();
  }

  /** oceano.probe(): (x, z) places it, null removes it, nothing reads it; each answers the reading. */
  async probeCall(args: unknown[]): Promise<ProbeReading | null> {
    if (args.length === 1 && args[0] === null) {
      this.probe.clear();
      this.showSections();
      return null;
    }
    if (args.length === 2 && isProbeCoordinate(args[0]) && isProbeCoordinate(args[1])) {
      this.placeProbe({ x: args[0], z: args[1] });
      await this.probe.chartReady();
    } else if (args.length !== 0) {
      throw new TypeError(toolWord({ language: 'en' }, 'probeArgs'));
    }
    return this.probe.reading();
  }

  /** The probe's place for a share link, "x,z", or null without one. */
  probeText(): string | null {
    const reading = this.probe.reading();
    return reading ? formatProbeText(reading) : null;
  }

  private placeProbe(point: SeaXZ): void {
    this.choose('probe');
    this.probe.place(point);
    this.showSections();
  }

  /** Before each drawn frame, with the camera where it will be drawn from: the marks on the sea, the figures, the labels. */
  frame(): void {
    this.context.camera.updateMatrixWorld();
    for (const tool of Object.values(this.tools)) {
      tool.frame();
      tool.placeLabels();
    }
    if (this.cursor) this.cursorPin.place(this.cursor.x, this.height(this.cursor.x, this.cursor.z), this.cursor.z, this.context.camera);
  }

  /** The panel's button and the stones' card: a stone at the point the camera orbits. */
  dropStoneAtCentre(): Promise<void> {
    const [x, , z] = this.app.camera().target;
    return this.disturb.drop({ x, z });
  }

  /** The sea as drawn at (x, z) now: the model's height (its cheap path, as the boat reads it), the wake's, the interactive waves'. */
  private height(x: number, z: number): number {
    const { app } = this;
    const t = app.clock.time;
    const sample = { height: app.view.waves.height(x, z, t), normal: UP };
    return app.view.ocean.withInteractiveWaves(
      app.boatMotion.withWake(sample, x, z, t, app.getParams(), app.view.ocean.wakeWeight(x, z)),
      x,
      z,
    ).height;
  }

  private async dropStone(point: SeaXZ): Promise<void> {
    if (!this.app.getParams().interactiveWaves) this.app.setParams({ interactiveWaves: true });
    // The interactive waves' code is fetched the first time they are switched on.
    await this.app.whenPartsLoaded();
    this.app.disturb(point.x, point.z, { radius: 1, height: 0.3 });
  }

  /** The point of the sea under the pointer, or null over the sky. */
  private pick(clientX: number, clientY: number): SeaXZ | null {
    const camera = this.context.camera;
    const rect = this.app.canvas.getBoundingClientRect();
    camera.updateMatrixWorld();
    this.ray
      .set(((clientX - rect.left) / rect.width) * 2 - 1, 1 - ((clientY - rect.top) / rect.height) * 2, 0.5)
      .unproject(camera)
      .sub(camera.position);
    const origin = camera.position.toArray();
    // The tallest wave the ocean can draw (its culling bounds) bounds the search.
    const maxHeight = this.app.view.ocean.cullingBounds().vertical;
    const hit = pickSea(origin, this.ray.toArray(), (x, z) => this.height(x, z), { maxHeight });
    return hit ? { x: hit.x, z: hit.z } : null;
  }

  private readonly onPointerDown = (event: PointerEvent): void => {
    if (this.tool === 'none' || event.target !== this.app.canvas || event.button !== 0 || !event.isPrimary) return;
    const point = this.pick(event.clientX, event.clientY);
    if (!point) return;
    // Capture phase on the container: the camera's controls on the canvas never see this press.
    event.stopPropagation();
    event.preventDefault();
    this.dragging = true;
    this.tools[this.tool].down(point);
    this.howTo.open = false;
    this.showSections();
    window.addEventListener('pointermove', this.onPointerMove);
    window.addEventListener('pointerup', this.onPointerUp);
    window.addEventListener('pointercancel', this.onPointerUp);
  };

  private readonly onPointerMove = (event: PointerEvent): void => {
    if (!this.dragging || this.tool === 'none' || !event.isPrimary) return;
    const point = this.pick(event.clientX, event.clientY);
    if (point) this.tools[this.tool].drag(point);
  };

  private readonly onPointerUp = (): void => {
    this.dragging = false;
    window.removeEventListener('pointermove', this.onPointerMove);
    window.removeEventListener('pointerup', this.onPointerUp);
    window.removeEventListener('pointercancel', this.onPointerUp);
  };

  private buildCard(): void {
    const tr = this.app.tr;
    this.card.className = 'oceano-sea-tools';
    this.card.hidden = true;
    this.card.setAttribute('aria-label', toolWord(tr, 'title'));
    const head = document.createElement('div');
    head.className = 'oceano-tool-row';
    const title = document.createElement('h2');
    title.textContent = toolWord(tr, 'title');
    const close = document.createElement('button');
    close.type = 'button';
    close.className = 'oceano-tool-close';
    close.textContent = '×';
    close.setAttribute('aria-label', toolWord(tr, 'close'));
    close.addEventListener('click', () => this.close());
    head.append(title, close);

    // Native radio buttons: Tab reaches the group, the arrows move the choice.
    const choice = document.createElement('fieldset');
    choice.className = 'oceano-tool-choice';
    const legend = document.createElement('legend');
    legend.textContent = toolWord(tr, 'choice');
    choice.append(legend);
    const group = `oceano-sea-tool-${++toolboxes}`;
    for (const name of TOOL_NAMES) {
      const label = document.createElement('label');
      const radio = document.createElement('input');
      radio.type = 'radio';
      radio.name = group;
      radio.value = name;
      radio.checked = name === this.tool;
      radio.addEventListener('change', () => radio.checked && this.choose(name));
      label.append(radio, toolWord(tr, name));
      choice.append(label);
      this.radios.set(name, radio);
    }

    this.help.className = 'oceano-tool-help';
    this.help.id = `${group}-help`;
    this.help.textContent = toolWord(tr, HELP[this.tool]);
    // Open until the first measurement, then folded to its summary so the card stays small.
    const summary = document.createElement('summary');
    summary.textContent = toolWord(tr, 'howTo');
    this.howTo.append(summary, this.help);
    this.howTo.open = !window.matchMedia(NARROW).matches;
    this.keys.type = 'button';
    this.keys.className = 'oceano-tool-button oceano-tool-keys';
    this.keys.textContent = toolWord(tr, 'keys');
    this.keys.setAttribute('aria-describedby', this.help.id);
    this.keys.addEventListener('focus', () => this.showCursor());
    this.keys.addEventListener('blur', () => this.hideCursor());
    this.keys.addEventListener('keydown', this.onCursorKey);
    this.cursorText.className = 'oceano-tool-note';
    this.cursorText.setAttribute('aria-live', 'polite');

    this.card.append(head, choice, this.howTo, this.keys, this.cursorText, this.probe.body, this.ruler.body, this.disturb.body);
    this.app.container.append(this.card);
    this.showSections();
  }

  /** Each tool's part of the card: shown while it is chosen or holds a measurement. */
  private showSections(): void {
    for (const [name, tool] of Object.entries(this.tools)) tool.body.hidden = !(this.tool === name || tool.holdsMeasurement());
    this.keys.hidden = this.tool === 'none';
  }

  private showCursor(): void {
    const [x, , z] = this.app.camera().target;
    this.cursor = { x, z };
    this.describeCursor();
    this.context.redraw();
  }

  private hideCursor(): void {
    this.cursor = null;
    this.cursorPin.hide();
    this.cursorText.textContent = '';
    this.context.redraw();
  }

  private describeCursor(): void {
    if (!this.cursor) return;
    const tr = this.app.tr;
    this.cursorText.textContent = toolWord(tr, 'keysLabel', { x: toolNumber(tr, this.cursor.x, 1), z: toolNumber(tr, this.cursor.z, 1) });
  }

  /** The keys button's own keys: arrows move the point, Enter uses it. The page's boat and camera keys do not see them. */
  private readonly onCursorKey = (event: KeyboardEvent): void => {
    if (!this.cursor || this.tool === 'none') return;
    if (isCursorKey(event.key)) {
      const pose = this.app.camera();
      const [dx, dz] = cursorStep(event.key, pose.position, pose.target, event.shiftKey ? FINE_STEP : STEP);
      this.cursor = { x: this.cursor.x + dx, z: this.cursor.z + dz };
      this.tools[this.tool].cursorMoved(this.cursor);
      this.describeCursor();
      this.context.redraw();
    } else if (event.key === 'Enter' || event.key === ' ') {
      this.tools[this.tool].enter(this.cursor);
      this.howTo.open = false;
      this.showSections();
    } else {
      return;
    }
    event.preventDefault();
    event.stopPropagation();
  };

  dispose(): void {
    this.onPointerUp();
    this.app.container.removeEventListener('pointerdown', this.onPointerDown, true);
    for (const tool of Object.values(this.tools)) tool.dispose();
    this.cursorPin.dispose();
    this.card.remove();
  }
}
