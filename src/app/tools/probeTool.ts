import type { ParamKey } from '../../sim/params/params';
import { ProbeRecord } from '../../sim/tools/probeRecord';
import { probeFigures, type ProbeFigures } from '../../sim/tools/probeStatistics';
import { probeTheory, swellRecord, type ProbeTheory } from '../../sim/tools/probeTheory';
import { deepWaterAngularFrequency } from '../../sim/waves/seed/seedSurface';
import { SeaPin } from '../../render/teaching/seaMarkers';
import { toolNumber, toolWord, type ToolWordId } from '../language/toolWords';
import type { SeaTool, SeaToolContext, SeaXZ } from './seaTool';
import type { ProbeChart } from './probeChart';

/** What oceano.probe() answers: where the probe is, its record, and its figures against theory. */
export interface ProbeReading {
  x: number;
  z: number;
  /** Sample times (s of simulation time) and heights (m) of the last 30 s, one per drawn frame. */
  times: number[];
  heights: number[];
  measured: ProbeFigures;
  theory: ProbeTheory;
}

const PIN_COLOUR = 0xff9f43;
/** The figures and chart are redrawn at most this often while the sea plays, ms of wall time. */
const REFRESH_MS = 250;
/**
 * The parameters that make the sea (wave model, swell, ripples, wind spectrum, Gerstner's):
 * when one changes, the record starts afresh, so it never mixes two seas and the theory always
 * speaks of the sea recorded.
 */
const SEA_KEYS = [
  'waves',
  'swellAmplitude',
  'swellFrequency',
  'rippleStrength',
  'rippleBlendSpeed',
  'seed',
  'windSpeed',
  'windDirection',
  'spectrum',
  'fetch',
  'depth',
  'spreading',
  'spreadingModel',
  'choppiness',
  'fftSize',
  'gerstnerCount',
  'gerstnerSteepness',
] as const satisfies readonly ParamKey[];

/**
 * The probe: a point of the sea whose height is recorded at every drawn frame, charted over
 * the last 30 s of simulation time, with its period and height measured the way a wave buoy
 * measures them and set beside the wave model's theory (src/sim/tools/).
 */
export class ProbeTool implements SeaTool {
  readonly body = document.createElement('section');
  private point: SeaXZ | null = null;
  private readonly record = new ProbeRecord();
  private readonly pin = new SeaPin(PIN_COLOUR);
  private readonly where = document.createElement('p');
  private readonly chartBox = document.createElement('div');
  private readonly table = document.createElement('table');
  private readonly waiting = document.createElement('p');
  private readonly note = document.createElement('p');
  private chart?: ProbeChart;
  private chartLoad?: Promise<void>;
  private lastRefresh = -Infinity;
  /** The sea the record was taken on: SEA_KEYS' values. */
  private sea = '';
  private disposed = false;

  constructor(private readonly context: SeaToolContext) {
    this.body.className = 'oceano-tool-probe';
    this.chartBox.className = 'oceano-probe-chart';
    this.table.className = 'oceano-probe-figures';
    this.note.className = 'oceano-tool-note';
    this.waiting.className = 'oceano-tool-note';
    this.waiting.textContent = toolWord(context.tr, 'waiting');
    // The why of the theory is long: folded, so the chart and the figures stay small over the sea.
    const about = document.createElement('details');
    const summary = document.createElement('summary');
    summary.textContent = toolWord(context.tr, 'aboutTheory');
    about.append(summary, this.note);
    const remove = document.createElement('button');
    remove.type = 'button';
    remove.className = 'oceano-tool-button';
    remove.textContent = toolWord(context.tr, 'remove');
    remove.setAttribute('aria-label', toolWord(context.tr, 'probeRemove'));
    remove.addEventListener('click', () => this.clear());
    const head = document.createElement('div');
    head.className = 'oceano-tool-row';
    head.append(this.where, remove);
    this.body.append(head, this.chartBox, this.table, this.waiting, about);
    context.scene.add(this.pin.object);
    this.showPoint();
  }

  holdsMeasurement(): boolean {
    return this.point !== null;
  }

  /** Puts the probe at `point` and starts a new record there. */
  place(point: SeaXZ): void {
    this.point = { x: point.x, z: point.z };
    this.record.clear();
    this.lastRefresh = -Infinity;
    this.showPoint();
    // uPlot comes with the first probe placed, not with the toolbox.
    this.chartLoad ??= import('./probeChart').then(
      ({ ProbeChart }) => {
        if (this.disposed) return;
        const t = this.context.tr;
        this.chart = new ProbeChart(this.chartBox, {
          time: toolWord(t, 'chartTime'),
          height: toolWord(t, 'chartHeight'),
          measured: toolWord(t, 'measured'),
          theory: toolWord(t, 'swellFormula'),
        });
        this.refresh();
      },
      (error: unknown) => console.warn('Oceano: the probe’s chart could not be loaded.', error),
    );
    this.context.redraw();
  }

  down(point: SeaXZ): void {
    this.place(point);
  }

  drag(point: SeaXZ): void {
    this.place(point);
  }

  enter(point: SeaXZ): void {
    this.place(point);
  }

  cursorMoved(): void {}

  /** Settles once the chart's code has arrived (or failed). */
  chartReady(): Promise<void> {
    return this.chartLoad ?? Promise.resolve();
  }

  frame(): void {
    if (!this.point) return;
    const { x, z } = this.point;
    const params = this.context.params();
    const sea = SEA_KEYS.map((key) => params[key]).join('|');
    if (sea !== this.sea) {
      this.sea = sea;
      this.record.clear();
    }
    const height = this.context.height(x, z);
    this.pin.place(x, height, z, this.context.camera);
    if (!this.record.add(this.context.time(), height)) return;
    if (performance.now() - this.lastRefresh >= REFRESH_MS) this.refresh();
  }

  placeLabels(): void {}

  /** The probe's figures now (null without a probe). */
  reading(): ProbeReading | null {
    if (!this.point) return null;
    const { times, heights } = this.record.window();
    const record = { times, heights };
    return {
      x: this.point.x,
      z: this.point.z,
      times,
      heights,
      measured: probeFigures(record),
      theory: probeTheory(this.context.params(), this.point.x, this.point.z, times),
    };
  }

  /** The chart and the table redrawn from the record. */
  private refresh(): void {
    this.lastRefresh = performance.now();
    const reading = this.reading();
    if (!reading) return;
    const params = this.context.params();
    const swell = reading.theory.kind === 'swell' ? swellRecord(params, reading.x, reading.z, reading.times).heights : null;
    this.chart?.show(reading.times, reading.heights, swell);
    this.showFigures(reading);
  }

  private showFigures({ measured, theory }: ProbeReading): void {
    const tr = this.context.tr;
    const n = (value: number, digits: number, unit: string) => (Number.isFinite(value) ? `${toolNumber(tr, value, digits)} ${unit}` : '—');
    this.waiting.hidden = Number.isFinite(measured.period);
    const rows: [ToolWordId, string, string][] =
      theory.kind === 'swell'
        ? [
            ['periodTz', n(measured.period, 2, 's'), n(theory.period, 2, 's')],
            ['crestTrough', n(measured.crestToTrough, 2, 'm'), n(theory.height, 2, 'm')],
          ]
        : [
            ['periodTz', n(measured.period, 2, 's'), n(theory.period, 2, 's')],
            ['hs', n(measured.significantHeight, 2, 'm'), n(theory.height, 2, 'm')],
            ['peakPeriod', '', n(theory.peakPeriod, 2, 's')],
          ];
    this.table.replaceChildren();
    const head = this.table.createTHead().insertRow();
    for (const id of ['quantity', 'measured', 'theory'] as const) {
      const th = document.createElement('th');
      th.scope = 'col';
      th.textContent = toolWord(tr, id);
      head.append(th);
    }
    const body = this.table.createTBody();
    for (const [label, value, expected] of rows) {
      const row = body.insertRow();
      const th = document.createElement('th');
      th.scope = 'row';
      th.textContent = toolWord(tr, label);
      row.append(th);
      row.insertCell().textContent = value;
      row.insertCell().textContent = expected;
    }
    if (theory.kind === 'swell') {
      const omega = deepWaterAngularFrequency(this.context.params().swellFrequency);
      this.note.textContent = toolWord(tr, 'swellNote', { omega: toolNumber(tr, omega, 3), period: toolNumber(tr, theory.swellPeriod, 2) });
    } else {
      this.note.textContent = toolWord(tr, 'spectrumNote');
    }
  }

  private showPoint(): void {
    const tr = this.context.tr;
    this.where.textContent = this.point
      ? toolWord(tr, 'probeAt', { x: toolNumber(tr, this.point.x, 1), z: toolNumber(tr, this.point.z, 1) })
      : toolWord(tr, 'probeNone');
    this.body.classList.toggle('oceano-tool-empty', !this.point);
    if (!this.point) {
      this.table.replaceChildren();
      this.note.textContent = '';
    }
  }

  clear(): void {
    this.point = null;
    this.record.clear();
    this.pin.hide();
    this.chart?.show([], [], null);
    this.showPoint();
    this.context.redraw();
  }

  dispose(): void {
    this.disposed = true;
    this.chart?.dispose();
    this.pin.dispose();
  }
}
