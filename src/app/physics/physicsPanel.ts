import type { OceanParams } from '../../sim/params/params';
import { physicsInputs } from '../../sim/physics/physicsInputs';
import type { PhysicsReport } from '../../sim/physics/physicsReport';
import type { LiveWaveModel } from '../../sim/waves/waveModel';

/** What the panel reads of the running app: the active CPU twin, the parameters, the clock. */
export interface PhysicsSource {
  model(): LiveWaveModel;
  params(): OceanParams;
  time(): number;
  /** Settles once the wave model the parameters ask for is the one model() answers (its code may still be on its way). */
  modelsLoaded(): Promise<void>;
}

/** What the lazily loaded plots module exports (src/app/physics/physicsPlots.ts). */
type PlotsModule = typeof import('./physicsPlots');
/** The estimators (with fft.js), also fetched on first use: the default first frame needs none of them. */
type ReportModule = typeof import('../../sim/physics/physicsReport');
type PhysicsView = InstanceType<PlotsModule['PhysicsView']>;

/** The longest task a sliced measurement takes, ms: about two simulated times of the FFT twin. */
const SLICE_MS = 40;

/**
 * physics=1: measures the running sea and plots it against theory. Closed, it costs nothing:
 * no estimator runs and the plotting code (physicsPlots.ts with uPlot and its CSS) is not
 * even loaded; both happen when the panel first opens (dynamic import, a separate chunk).
 */
export class PhysicsPanel {
  /** Estimator runs so far (the panel's and oceano.physics()'s): the test of "costs nothing when closed". */
  runs = 0;
  private open = false;
  private disposed = false;
  private view?: PhysicsView;
  private loading?: Promise<void>;
  private reportLoad?: Promise<ReportModule>;
  /** physicsInputs of the parameters last synced: the sea the figures on show belong to. */
  private inputs?: string;

  constructor(
    private readonly container: HTMLElement,
    private readonly source: PhysicsSource,
  ) {}

  /**
   * Measures from the current time on (a few seconds of CPU: only on demand), once the
   * estimators' code has arrived (the first call fetches it).
   */
  async measure(): Promise<PhysicsReport> {
    const time = this.source.time();
    return this.measureNow(await this.loadReport(), time);
  }

  private loadReport(): Promise<ReportModule> {
    this.reportLoad ??= import('../../sim/physics/physicsReport');
    return this.reportLoad;
  }

  private measureNow(code: ReportModule, time = this.source.time()): PhysicsReport {
    this.runs++;
    return code.measurePhysics(code.measuredSea(this.source.model(), this.source.params()), time);
  }

  /**
   * Follows the parameters: opens or closes the panel, and while it is open measures again
   * whenever a parameter the figures depend on changes (a lesson, the wind, the model), saying
   * "measuring" meanwhile; a change of the sun or the camera measures nothing.
   */
  sync(params: OceanParams): void {
    const inputs = physicsInputs(params);
    const changed = this.inputs !== undefined && inputs !== this.inputs;
    this.inputs = inputs;
    if (params.physics !== this.open) this.setOpen(params.physics);
    else if (changed && this.open && this.view) this.view.refresh(this.source.modelsLoaded());
  }

  /**
   * The same measurement spread over tasks of about SLICE_MS, so the page's other figures keep
   * drawing while it runs (at once it holds the one thread for seconds); null once disposed or
   * no longer `wanted`.
   */
  private async measureSliced(code: ReportModule, wanted: () => boolean): Promise<PhysicsReport | null> {
    this.runs++;
    const steps = code.physicsSteps(code.measuredSea(this.source.model(), this.source.params()), this.source.time());
    for (;;) {
      if (this.disposed || !wanted()) return null;
      const until = performance.now() + SLICE_MS;
      let step = steps.next();
      while (!step.done && performance.now() < until) step = steps.next();
      if (step.done) return step.value;
      await new Promise((resolve) => setTimeout(resolve, 0));
    }
  }

  setOpen(open: boolean): void {
    if (open === this.open) return;
    this.open = open;
    if (!open) {
      this.view?.setVisible(false);
      return;
    }
    if (this.view) {
      this.view.setVisible(true);
      this.view.refresh(this.source.modelsLoaded());
      return;
    }
    this.loading ??= Promise.all([import('./physicsPlots'), this.loadReport(), this.source.modelsLoaded()]).then(([plots, code]) => {
      this.view = new plots.PhysicsView(this.container, (wanted) => this.measureSliced(code, wanted));
      this.view.setVisible(this.open);
      if (this.open) this.view.refresh();
    });
  }

  /** Resolves once the panel, if open, has drawn its first measurement (for tests). */
  async settled(): Promise<void> {
    await this.loading;
    await this.view?.drawn;
  }

  dispose(): void {
    this.disposed = true;
    this.view?.dispose();
  }
}
