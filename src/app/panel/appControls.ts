import type { OceanParams, ParamKey } from '../../sim/params/params';
import { BoatSteering } from '../boat/boatSteering';
import { CameraKeys } from '../camera/cameraKeys';
import type { CameraPose } from '../camera/cameraPose';
import type { ControlPanel, ControlPanelHooks, LiveCounts } from './controlPanel';
import type { FresnelPlot } from '../physics/fresnelPlot';
import type { Translator } from '../language/i18n';
import type { PhysicsPanel, PhysicsSource } from '../physics/physicsPanel';
import type { CompareDividers } from '../compare/compareDividers';
import { COMPARE_OFF } from '../../sim/compare/compareLayout';

/** How often the GUI's live LOD counts are refreshed (frames). */
const COUNTS_EVERY = 10;

/** What the keys change through the app's own API, so they are checked as any caller's change is. */
export interface KeyedApp {
  setParams(change: Partial<OceanParams>): unknown;
  getParams(): OceanParams;
  camera(): CameraPose;
  setCamera(pose: CameraPose): void;
}

/**
 * What the user steers the ocean with besides the canvas: the lil-gui panel (full page
 * only), the keyboard's boat steering and camera keys, the Fresnel plot and the physics
 * panel, kept in step with the parameters.
 */
export class AppControls {
  /** Built by loadPanel, once lil-gui's code has arrived. */
  private panel?: ControlPanel;
  private panelLoad?: Promise<void>;
  /** What the panel shows when it is built: the last sync's. */
  private shown: { params: OceanParams; playing: boolean };
  /** The parameters whose folders stay open: the open lesson's controls. */
  private opened: readonly ParamKey[] = [];
  private disposed = false;
  private readonly steering: BoatSteering;
  private readonly cameraKeys: CameraKeys;
  private readonly tr: Translator;
  private fresnelPlot?: FresnelPlot;
  private fresnelPlotLoad?: Promise<void>;
  /** Fetched the first time physics=1 or a measurement asks for it: physics is off by default. */
  private physicsPanel?: PhysicsPanel;
  private physicsLoad?: Promise<PhysicsPanel>;
  private dividers?: CompareDividers;
  private dividersLoad?: Promise<void>;

  constructor(
    private readonly container: HTMLElement,
    private readonly fresnelData: Float32Array,
    private readonly state: {
      showPanel: boolean;
      params: OceanParams;
      playing: boolean;
      tr: Translator;
      physics: PhysicsSource;
      panelFailed: () => void;
    },
    app: KeyedApp,
    private readonly hooks: ControlPanelHooks,
  ) {
    this.shown = { params: state.params, playing: state.playing };
    // The full page steers from anywhere; an embedded figure only when it has the focus.
    const keyTarget: Window | HTMLElement = state.showPanel ? window : container;
    this.steering = new BoatSteering(
      keyTarget,
      (change) => app.setParams(change),
      () => app.getParams(),
    );
    this.cameraKeys = new CameraKeys(
      keyTarget,
      () => app.camera(),
      (pose) => app.setCamera(pose),
    );
    this.tr = state.tr;
    this.sync(state.params, state.playing);
  }

  /**
   * Builds the lil-gui panel (full page only). Its code (lil-gui is about 14 KB gzipped) is a
   * chunk of its own, fetched after the first frame (OceanApp.start) so the sea does not wait
   * for it; where it cannot be fetched the ocean runs without a panel and says so.
   */
  loadPanel(): Promise<void> {
    if (!this.state.showPanel) return Promise.resolve();
    this.panelLoad ??= import('./controlPanel').then(
      ({ ControlPanel }) => {
        if (this.disposed) return;
        this.panel = new ControlPanel(this.container, this.shown.params, this.shown.playing, this.hooks, this.tr);
        this.panel.sync(this.shown.params, this.shown.playing);
        this.panel.openFoldersOf(this.opened);
      },
      (error: unknown) => {
        console.warn("Oceano: the control panel's code could not be loaded.", error);
        if (!this.disposed) this.state.panelFailed();
      },
    );
    return this.panelLoad;
  }

  /**
   * The Fresnel plot's code is fetched the first time the plot is asked for: most figures
   * never show it. Settles once it is on screen (or could not be fetched).
   */
  private loadFresnelPlot(): Promise<void> {
    this.fresnelPlotLoad ??= import('../physics/fresnelPlot').then(
      ({ FresnelPlot }) => {
        if (this.disposed) return;
        this.fresnelPlot = new FresnelPlot(this.container, this.fresnelData, this.tr);
        this.fresnelPlot.setVisible(this.shown.params.fresnelPlot);
      },
      (error: unknown) => console.warn("Oceano: the Fresnel plot's code could not be loaded.", error),
    );
    return this.fresnelPlotLoad;
  }

  /**
   * The split view's dividers belong to the view, embedded or not; their code is fetched the
   * first time compare= is set.
   */
  private loadDividers(): Promise<void> {
    this.dividersLoad ??= import('../compare/compareDividers').then(
      ({ CompareDividers }) => {
        if (this.disposed) return;
        this.dividers = new CompareDividers(this.container, this.tr, (key, value) => this.hooks.onParam(key, value));
        this.dividers.sync(this.shown.params);
      },
      (error: unknown) => console.warn("Oceano: the compare dividers' code could not be loaded.", error),
    );
    return this.dividersLoad;
  }

  /** Settles once every part asked for so far (the Fresnel plot, the compare dividers) is on screen. */
  whenPartsLoaded(): Promise<void> {
    return Promise.all([this.fresnelPlotLoad, this.dividersLoad]).then(() => undefined);
  }

  /** Opens the panel's folders that hold `keys` and folds the rest. */
  openFoldersOf(keys: readonly ParamKey[]): void {
    this.opened = keys;
    this.panel?.openFoldersOf(keys);
  }

  /** Applies held steering keys for `seconds` of the loop. */
  steer(seconds: number): void {
    this.steering.apply(seconds);
  }

  /** The physics panel, its code fetched on the first call; it then follows the last sync's parameters. */
  physics(): Promise<PhysicsPanel> {
    this.physicsLoad ??= import('../physics/physicsPanel').then(({ PhysicsPanel }) => {
      const panel = new PhysicsPanel(this.container, this.state.physics);
      if (this.disposed) panel.dispose();
      else panel.sync(this.shown.params);
      return (this.physicsPanel = panel);
    });
    return this.physicsLoad;
  }

  sync(params: OceanParams, playing: boolean): void {
    this.shown = { params, playing };
    if (params.fresnelPlot) void this.loadFresnelPlot();
    this.fresnelPlot?.setVisible(params.fresnelPlot);
    if (this.physicsPanel) this.physicsPanel.sync(params);
    else if (params.physics) void this.physics();
    if (params.compare !== COMPARE_OFF) void this.loadDividers();
    this.dividers?.sync(params);
    this.panel?.sync(params, playing);
  }

  /**
   * The panel's live LOD counts: while looping, every COUNTS_EVERY frames; a paused view
   * draws only on a change (a t= link, a preset, a camera move), so on every such frame.
   */
  showCounts(frame: number, looping: boolean, counts: () => LiveCounts): void {
    if (this.panel && (!looping || frame % COUNTS_EVERY === 0)) this.panel.showCounts(counts());
  }

  dispose(): void {
    this.disposed = true;
    this.steering.dispose();
    this.cameraKeys.dispose();
    this.panel?.dispose();
    this.fresnelPlot?.dispose();
    this.physicsPanel?.dispose();
    this.dividers?.dispose();
  }
}
