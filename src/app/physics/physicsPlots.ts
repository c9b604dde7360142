import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import './physicsPanel.css';
import type { PhysicsReport } from '../../sim/physics/physicsReport';
import { onScreen } from './onScreen';

const PLOT_WIDTH = 340;
const PLOT_HEIGHT = 170;

function fixed(value: number | null, digits: number, unit = ''): string {
  return value === null ? '—' : `${value.toFixed(digits)}${unit}`;
}

/**
 * The physics panel's content, loaded only when the panel opens (see PhysicsPanel): the
 * figures as a table, two uPlot charts (dispersion, spectrum) and a footnote per formula.
 */
export class PhysicsView {
  private readonly root: HTMLElement;
  private plots: uPlot[] = [];
  /** Settles when the latest measurement is on screen. */
  drawn: Promise<void> = Promise.resolve();
  /** The measurement waiting for the panel to be seen; dropped when disposed. */
  private waiting: ReturnType<typeof onScreen> | null = null;

  constructor(
    private readonly container: HTMLElement,
    /** Resolves to null when the measurement was given up (`wanted` turned false, or its figure disposed). */
    private readonly measure: (wanted: () => boolean) => Promise<PhysicsReport | null>,
  ) {
    this.root = document.createElement('section');
    this.root.className = 'oceano-physics';
    this.root.setAttribute('aria-label', 'Physics panel: the sea measured against theory');
    container.appendChild(this.root);
  }

  setVisible(visible: boolean): void {
    this.root.hidden = !visible;
    // Closed before its measurement was drawn: reopening measures afresh (PhysicsPanel.setOpen).
    if (!visible) this.dropWaiting();
  }

  private dropWaiting(): void {
    this.waiting?.cancel();
    this.waiting = null;
  }

  /**
   * Says "measuring" now and measures once its figure is on screen (one started near the screen,
   * or given back, does not) and `ready` has settled (the model asked for is in place), on a
   * later task so the line is painted first. A newer refresh supersedes one still waiting: only
   * the latest parameters' sea is measured.
   */
  refresh(ready: Promise<unknown> = Promise.resolve()): void {
    for (const plot of this.plots) plot.destroy();
    this.plots = [];
    this.root.textContent = 'Measuring the sea through its CPU twin…';
    this.dropWaiting();
    const waiting = (this.waiting = onScreen(this.container));
    this.drawn = Promise.all([waiting.settled, ready])
      .then(() => new Promise((resolve) => setTimeout(resolve, 0)))
      .then(() => (this.waiting === waiting ? this.measure(() => this.waiting === waiting) : null))
      .then((report) => {
        if (report && this.waiting === waiting) this.show(report);
      });
  }

  show(report: PhysicsReport): void {
    this.dropWaiting();
    for (const plot of this.plots) plot.destroy();
    this.plots = [];
    this.root.replaceChildren();
    const heading = document.createElement('h2');
    heading.textContent = `Physics of the ${report.model} sea (from t = ${report.time.toFixed(1)} s)`;
    this.root.appendChild(heading);
    this.root.appendChild(this.table(report));
    this.root.appendChild(this.dispersionPlot(report));
    this.root.appendChild(this.spectrumPlot(report));
    for (const note of report.notes) {
      const p = document.createElement('p');
      p.className = 'oceano-physics-note';
      p.textContent = note;
      this.root.appendChild(p);
    }
    const notes = document.createElement('ol');
    notes.className = 'oceano-physics-sources';
    for (const c of report.citations) {
      const li = document.createElement('li');
      li.textContent = `${c.what}: ${c.formula}. ${c.source}.`;
      notes.appendChild(li);
    }
    this.root.appendChild(notes);
  }

  private table(r: PhysicsReport): HTMLTableElement {
    const rows: [string, string, string][] = [
      ['Dispersion fit ω / √(g k tanh kh)', fixed(r.dispersion.fitRatio, 3), `1 (rms ${fixed(r.dispersion.rmsRelativeError, 3)})`],
      ['Spectral peak ωp, rad/s', fixed(r.peak.measured, 3), fixed(r.peak.theory, 3)],
      ['Peak period Tp, s', fixed(r.peakPeriod.measured, 2), fixed(r.peakPeriod.theory, 2)],
      ['Hs = 4σ(η) vs 4√m₀, m', fixed(r.hs.measured, 2), fixed(r.hs.spectral, 2)],
      [`Hs empirical${r.hs.empiricalName ? ` (${r.hs.empiricalName})` : ''}, m`, '', fixed(r.hs.empirical, 2)],
      [
        `Slopes σ²: resolved + roughness vs Cox & Munk (U₁₂.₅ = ${fixed(r.slopes.wind, 1)} m/s)`,
        `${fixed(r.slopes.resolved, 4)} + ${fixed(r.slopes.roughness, 4)} = ${fixed(r.slopes.total, 4)}`,
        fixed(r.slopes.coxMunk, 4),
      ],
    ];
    const table = document.createElement('table');
    const head = table.insertRow();
    for (const h of ['', 'measured', 'theory']) {
      const th = document.createElement('th');
      th.textContent = h;
      head.appendChild(th);
    }
    for (const row of rows) {
      const tr = table.insertRow();
      for (const cell of row) tr.insertCell().textContent = cell;
    }
    return table;
  }

  private figure(caption: string): { figure: HTMLElement; target: HTMLElement } {
    const figure = document.createElement('figure');
    const target = document.createElement('div');
    const figcaption = document.createElement('figcaption');
    figcaption.textContent = caption;
    figure.append(target, figcaption);
    return { figure, target };
  }

  private dispersionPlot(r: PhysicsReport): HTMLElement {
    const points = [...r.dispersion.points].sort((a, b) => a.k - b.k);
    const k = points.map((p) => p.k);
    const measured = points.map((p) => p.omega);
    const theory = points.map((p) => p.theory);
    const { figure, target } = this.figure('ω(k): modes measured (dots) against √(g k tanh kh) (line) [1]');
    this.plots.push(
      new uPlot(
        {
          width: PLOT_WIDTH,
          height: PLOT_HEIGHT,
          scales: { x: { time: false } },
          axes: [{ label: 'k, rad/m' }, { label: 'ω, rad/s' }],
          series: [
            {},
            { label: 'measured', stroke: '#d9480f', paths: () => null, points: { show: true, size: 5, fill: '#d9480f' } },
            { label: 'theory', stroke: '#1c7ed6', width: 1.5 },
          ],
        },
        [k, measured, theory],
        target,
      ),
    );
    return figure;
  }

  private spectrumPlot(r: PhysicsReport): HTMLElement {
    const floor = 1e-6;
    const measured = r.spectrum.measured.map((s) => Math.max(s, floor));
    const series: uPlot.Series[] = [{}, { label: 'measured S(ω)', stroke: '#d9480f' }];
    const data: uPlot.AlignedData = [r.spectrum.omega, measured];
    if (r.spectrum.theory) {
      series.push({ label: 'model spectrum', stroke: '#1c7ed6' });
      (data as number[][]).push(r.spectrum.theory.map((s) => Math.max(s, floor)));
    }
    const { figure, target } = this.figure('S(ω) of 16 points’ heights (Welch) against the model’s spectrum [2, 4]');
    this.plots.push(
      new uPlot(
        {
          width: PLOT_WIDTH,
          height: PLOT_HEIGHT,
          scales: { x: { time: false }, y: { distr: 3 } },
          // Log axis: powers of ten written as such (the default rounds 10⁻⁴ to "0").
          axes: [
            { label: 'ω, rad/s' },
            { label: 'S, m²·s', values: (_, ticks) => ticks.map((v) => (v === null ? '' : v >= 1 ? String(v) : v.toExponential(0))) },
          ],
          series,
        },
        data,
        target,
      ),
    );
    return figure;
  }

  dispose(): void {
    this.dropWaiting();
    for (const plot of this.plots) plot.destroy();
    this.root.remove();
  }
}
