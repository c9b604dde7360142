import GUI, { type Controller } from 'lil-gui';
import { paramDefs, type OceanParams, type ParamDef, type ParamKey } from '../../sim/params/params';
import type { Translator } from '../language/i18n';
import { panelWord, type PanelWordId } from '../language/panelWords';
import { teachingWord } from '../language/teachingWords';
import { paramLabel } from '../language/paramLabels';
import { froudeNumber } from '../../sim/wake/kelvinWake';
import { WAKE_HULL } from '../../sim/wake/boatWake';
import { unreadParams } from './unreadParams';
import { FreeArea } from '../layout/freeArea';
import type { SeaTools } from '../tools/seaTools';

const FOLDERS: { title: PanelWordId; keys: ParamKey[] }[] = [
  { title: 'folderSwell', keys: ['waves', 'swellAmplitude', 'swellFrequency'] },
  // The wind sea that both waves=fft and waves=gerstner draw from.
  {
    title: 'folderSpectral',
    keys: [
      'windSpeed',
      'windDirection',
      'spectrum',
      'fetch',
      'depth',
      'spreading',
      'spreadingModel',
      'choppiness',
      'fftSize',
      'foam',
      'foamThreshold',
      'foamFade',
      'foamTexture',
      'waveGroups',
      'windrows',
    ],
  },
  { title: 'folderRipples', keys: ['rippleStrength', 'rippleBlendSpeed', 'seed'] },
  { title: 'folderGerstner', keys: ['gerstnerCount', 'gerstnerSteepness'] },
  { title: 'folderCompare', keys: ['compare', 'compareSplit', 'compareSplit2'] },
  { title: 'folderCoast', keys: ['bathymetry', 'beachSlope', 'swellHeight', 'swellPeriod', 'swellDirection', 'windSea'] },
  { title: 'folderPhysics', keys: ['physics'] },
  {
    title: 'folderLight',
    keys: [
      'sunElevation',
      'sunAzimuth',
      'waterColor',
      'waterColorPicked',
      'fresnel',
      'seaRoughness',
      'skyBlur',
      'subsurface',
      'visibility',
      'exposure',
    ],
  },
  {
    title: 'folderBoat',
    keys: [
      'boatSpeed',
      'boatHeading',
      'boatTurnRate',
      'boatResponse',
      'boatFollow',
      'wake',
      'wakeStrength',
      'wakeGuide',
      'interactiveWaves',
      'iwaveEquation',
      'iwaveGuide',
    ],
  },
  {
    title: 'folderUnderwater',
    keys: ['blurStrength', 'fogDensity', 'seaBedDepth', 'caustics', 'causticsIntensity', 'godRays', 'godRaysIntensity'],
  },
  { title: 'folderLod', keys: ['lodDistance', 'lodBands', 'lodColors', 'lodMorph', 'freezeCulling', 'lodBruteForce'] },
  { title: 'folderView', keys: ['wireframe', 'shading', 'normals', 'normalsCompare', 'view', 'fresnelPlot'] },
];

/** Views narrower than this (CSS px; a phone held upright) start with the panel folded. */
const NARROW = 560;

/** What the LOD debugger's read-only counters show. */
export interface LiveCounts {
  chunksVisible: number;
  chunksTotal: number;
  triangles: number;
  drawCalls: number;
  lodCounts: number[];
}

export interface ControlPanelHooks {
  onParam(key: ParamKey, value: OceanParams[ParamKey]): void;
  onPlayingChange(playing: boolean): void;
  onShare(): void;
  onDive(): void;
  onStep(): void;
  onSurface(): void;
  /** The sea tools (the probe, the ruler, stones: src/app/tools/), their code fetched on first use. */
  onSeaTools(): Promise<SeaTools>;
}

/**
 * lil-gui panel built from the parameter definitions, so a new parameter gets its control
 * with its range and unit without touching this file beyond naming its folder.
 */
export class ControlPanel {
  readonly gui: GUI;
  private readonly model: OceanParams & { playing: boolean };
  private readonly controllers: Controller[] = [];
  private readonly paramControllers = new Map<ParamKey, Controller>();
  private readonly folders: { gui: GUI; keys: ParamKey[] }[] = [];
  private readonly counts = { chunks: '', triangles: '', drawCalls: '', perBand: '' };
  private readonly countControllers: Controller[] = [];
  /** The boat folder's read-only Froude number of the hull at the set speed. */
  private readonly froude = { value: '' };
  private readonly froudeController: Controller;

  constructor(
    private readonly container: HTMLElement,
    params: OceanParams,
    playing: boolean,
    hooks: ControlPanelHooks,
    private readonly tr: Translator,
  ) {
    // Its styles come from the page's stylesheet (main.ts): no <style> element with a data: font.
    this.gui = new GUI({ container, title: panelWord(tr, 'panelTitle'), injectStyles: false });
    this.model = { ...params, playing };
    let boatFolder: GUI | null = null;
    for (const folder of FOLDERS) {
      const group = this.gui.addFolder(panelWord(tr, folder.title));
      // Folded: a lesson opens the folders of its controls, the user any other.
      group.close();
      this.folders.push({ gui: group, keys: folder.keys });
      for (const key of folder.keys) {
        const controller = this.addControl(group, key, hooks);
        this.controllers.push(controller);
        this.paramControllers.set(key, controller);
      }
      if (folder.title === 'folderBoat') boatFolder = group;
    }
    this.froudeController = (boatFolder ?? this.gui).add(this.froude, 'value').name(panelWord(tr, 'froudeNumber')).disable();
    // Beside the interactiveWaves switch (a button: keyboard operable), in the folded boat folder.
    const dropStone = () => void hooks.onSeaTools().then((tools) => tools.dropStoneAtCentre());
    (boatFolder ?? this.gui).add({ dropStone }, 'dropStone').name(teachingWord(tr, 'dropStone'));
    const live = this.gui.addFolder(panelWord(tr, 'folderLiveCounts')).close();
    const labels: [keyof typeof this.counts, PanelWordId][] = [
      ['chunks', 'countChunks'],
      ['triangles', 'countTriangles'],
      ['drawCalls', 'countDrawCalls'],
      ['perBand', 'countPerBand'],
    ];
    for (const [key, label] of labels) this.countControllers.push(live.add(this.counts, key).name(panelWord(tr, label)).disable());
    this.controllers.push(
      this.gui
        .add(this.model, 'playing')
        .name(panelWord(tr, 'playing'))
        .onChange((value: boolean) => hooks.onPlayingChange(value)),
    );
    // The teacher's time controls beside Play: slow motion, and one frame at a time while paused.
    const speed = this.addControl(this.gui, 'timeScale', hooks);
    this.controllers.push(speed);
    this.paramControllers.set('timeScale', speed);
    this.gui.add({ step: () => hooks.onStep() }, 'step').name(teachingWord(tr, 'step'));
    // lil-gui draws a function as a <button>: focusable and keyboard operable.
    this.gui.add({ share: () => hooks.onShare() }, 'share').name(panelWord(tr, 'share'));
    const camera = { dive: () => hooks.onDive(), surface: () => hooks.onSurface() };
    this.gui.add(camera, 'dive').name(panelWord(tr, 'dive'));
    this.gui.add(camera, 'surface').name(panelWord(tr, 'surface'));
    // Last, so the panel's first rows stay as they were: the tools open a card of their own over the sea.
    this.gui.add({ seaTools: () => void hooks.onSeaTools().then((tools) => tools.open()) }, 'seaTools').name(teachingWord(tr, 'seaTools'));
    // On a phone the open panel would cover most of the sea: start it folded (its title opens it).
    if (container.clientWidth < NARROW) this.gui.close();
    FreeArea.of(container).avoid(this.gui.domElement);
  }

  private addControl(group: GUI, key: ParamKey, hooks: ControlPanelHooks): Controller {
    const def: ParamDef = paramDefs[key];
    const label = paramLabel(this.tr, key);
    const emit = (value: OceanParams[ParamKey]) => hooks.onParam(key, value);
    if (def.kind === 'color') return group.addColor(this.model, key).name(label).onChange(emit);
    if (def.kind === 'boolean') return group.add(this.model, key).name(label).onChange(emit);
    if (def.kind === 'choice')
      return group
        .add(this.model, key, [...def.options])
        .name(label)
        .onChange(emit);
    const name = def.unit ? `${label} (${def.unit})` : label;
    const step = def.kind === 'integer' ? 1 : (def.step ?? (def.max - def.min) / 100);
    // A slider over the whole int32 range of the seed is useless: give it a number box.
    const wideRange = def.max - def.min > 1e6;
    const controller = (wideRange ? group.add(this.model, key).step(1) : group.add(this.model, key, def.min, def.max, step)).name(name);
    // A new seed regenerates both heightmaps: do it once when the user lets go, not per pixel dragged.
    return key === 'seed' ? controller.onFinishChange(emit) : controller.onChange(emit);
  }

  /** Opens the folders that hold `keys` (a lesson's controls) and folds the others. */
  openFoldersOf(keys: readonly ParamKey[]): void {
    for (const folder of this.folders) folder.gui.open(folder.keys.some((key) => keys.includes(key)));
  }

  /** Shows values changed elsewhere (API, keyboard) without echoing them back; what no model on screen reads is disabled, with the reason. */
  sync(params: OceanParams, playing: boolean): void {
    Object.assign(this.model, params, { playing });
    for (const controller of this.controllers) controller.updateDisplay();
    const unread = unreadParams(params);
    for (const [key, controller] of this.paramControllers) {
      const reason = unread.get(key);
      controller.enable(reason === undefined);
      if (reason) controller.domElement.dataset.unread = teachingWord(this.tr, reason);
      else delete controller.domElement.dataset.unread;
    }
    // Fr = U/√(gL) of the hull the wake is made for: what sets the wake's amplitude and look.
    this.froude.value = `${froudeNumber(params.boatSpeed, WAKE_HULL.length).toFixed(2)} (L = ${WAKE_HULL.length} m)`;
    this.froudeController.updateDisplay();
  }

  showCounts(counts: LiveCounts): void {
    this.counts.chunks = `${counts.chunksVisible} / ${counts.chunksTotal}`;
    this.counts.triangles = counts.triangles.toLocaleString('en-US');
    this.counts.drawCalls = String(counts.drawCalls);
    this.counts.perBand = counts.lodCounts.join(' ');
    for (const controller of this.countControllers) controller.updateDisplay();
  }

  dispose(): void {
    FreeArea.of(this.container).release(this.gui.domElement);
    this.gui.destroy();
  }
}
