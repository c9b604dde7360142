import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';

/** The chart's height, CSS px: small, so the sea stays in view. */
const CHART_HEIGHT = 120;
const MEASURED_COLOUR = '#ff9f43';
const THEORY_COLOUR = '#7fd4ff';

export interface ProbeChartWords {
  time: string;
  height: string;
  measured: string;
  theory: string;
}

/**
 * η(t) at the probe, a uPlot line chart: the measured heights and, for the seed's swell, its
 * formula at the same times as a dashed line. A chunk of its own with uPlot, fetched when a
 * probe is first placed.
 */
export class ProbeChart {
  private readonly plot: uPlot;

  constructor(
    private readonly parent: HTMLElement,
    words: ProbeChartWords,
  ) {
    const axis = { stroke: '#cfe3ee', grid: { stroke: 'rgba(207, 227, 238, 0.15)' }, ticks: { stroke: 'rgba(207, 227, 238, 0.3)' } };
    this.plot = new uPlot(
      {
        width: this.width(),
        height: CHART_HEIGHT,
        // The legend would repeat the table under the chart.
        legend: { show: false },
        cursor: { show: false },
        scales: { x: { time: false } },
        axes: [
          { ...axis, label: words.time, size: 30, labelSize: 14 },
          { ...axis, label: words.height, size: 40, labelSize: 14 },
        ],
        series: [
          {},
          { label: words.measured, stroke: MEASURED_COLOUR, width: 1.5 },
          { label: words.theory, stroke: THEORY_COLOUR, width: 1, dash: [4, 4] },
        ],
      },
      [[], [], []],
      parent,
    );
  }

  /** Shows the record; `theory` is null where the model gives no curve of its own (a spectral sea). */
  show(times: number[], measured: number[], theory: ArrayLike<number> | null): void {
    const width = this.width();
    if (width !== this.plot.width) this.plot.setSize({ width, height: CHART_HEIGHT });
    this.plot.setData([times, measured, theory ? Array.from(theory) : times.map(() => null)]);
  }

  private width(): number {
    return Math.max(200, this.parent.clientWidth);
  }

  dispose(): void {
    this.plot.destroy();
  }
}
