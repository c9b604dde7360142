import { schlickReflectance, WATER_IOR, AIR_IOR } from '../../sim/optics/fresnel';
import type { Translator } from '../language/i18n';
import { FRESNEL_PLOT_WORDS } from '../language/fresnelPlotWords';

const WIDTH = 380;
const HEIGHT = 240;
const MARGIN = { left: 44, right: 14, top: 30, bottom: 36 };

/**
 * The seed's Fresnel figure as a live plot: the table the shader samples (exact, mean of s
 * and p) against Schlick's approximation, over the angle of incidence.
 */
export class FresnelPlot {
  private readonly canvas: HTMLCanvasElement;

  constructor(
    container: HTMLElement,
    table: Float32Array,
    private readonly tr: Translator,
  ) {
    this.canvas = document.createElement('canvas');
    this.canvas.className = 'oceano-fresnel-plot';
    this.canvas.width = WIDTH;
    this.canvas.height = HEIGHT;
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', FRESNEL_PLOT_WORDS[tr.language].label);
    this.canvas.hidden = true;
    container.appendChild(this.canvas);
    this.draw(table);
  }

  setVisible(visible: boolean): void {
    this.canvas.hidden = !visible;
  }

  private draw(table: Float32Array): void {
    const ctx = this.canvas.getContext('2d');
    if (!ctx) return;
    const plotW = WIDTH - MARGIN.left - MARGIN.right;
    const plotH = HEIGHT - MARGIN.top - MARGIN.bottom;
    const x = (degrees: number) => MARGIN.left + (degrees / 90) * plotW;
    const y = (reflectance: number) => MARGIN.top + (1 - reflectance) * plotH;

    ctx.fillStyle = 'rgba(255, 255, 255, 0.94)';
    ctx.fillRect(0, 0, WIDTH, HEIGHT);
    ctx.font = '12px system-ui, sans-serif';
    ctx.fillStyle = '#1b2a33';
    ctx.fillText(`${FRESNEL_PLOT_WORDS[this.tr.language].title} (n = ${WATER_IOR})`, MARGIN.left, 18);

    ctx.strokeStyle = '#c9d3d9';
    ctx.lineWidth = 1;
    for (let d = 0; d <= 90; d += 15) {
      ctx.beginPath();
      ctx.moveTo(x(d), y(0));
      ctx.lineTo(x(d), y(1));
      ctx.stroke();
      ctx.fillText(`${d}°`, x(d) - 8, HEIGHT - MARGIN.bottom + 14);
    }
    for (let r = 0; r <= 1.001; r += 0.25) {
      ctx.beginPath();
      ctx.moveTo(x(0), y(r));
      ctx.lineTo(x(90), y(r));
      ctx.stroke();
      ctx.fillText(r.toFixed(2), 6, y(r) + 4);
    }
    ctx.fillText(FRESNEL_PLOT_WORDS[this.tr.language].axis, MARGIN.left + plotW / 2 - 50, HEIGHT - 6);

    const curve = (color: string, dash: number[], reflectance: (degrees: number) => number) => {
      ctx.strokeStyle = color;
      ctx.setLineDash(dash);
      ctx.lineWidth = 2;
      ctx.beginPath();
      for (let d = 0; d <= 90; d += 0.5) {
        if (d === 0) ctx.moveTo(x(d), y(reflectance(d)));
        else ctx.lineTo(x(d), y(reflectance(d)));
      }
      ctx.stroke();
      ctx.setLineDash([]);
    };
    // The table is indexed by cos θ; read it back the way the shader does, linearly.
    const fromTable = (degrees: number) => {
      const position = Math.cos((degrees * Math.PI) / 180) * (table.length - 1);
      const i = Math.floor(position);
      const j = Math.min(i + 1, table.length - 1);
      return table[i] + (table[j] - table[i]) * (position - i);
    };
    curve('#0a6fa8', [], fromTable);
    curve('#d2691e', [6, 4], (d) => schlickReflectance(Math.cos((d * Math.PI) / 180), AIR_IOR, WATER_IOR));

    ctx.fillStyle = '#0a6fa8';
    ctx.fillRect(MARGIN.left + 8, MARGIN.top + 8, 16, 3);
    ctx.fillStyle = '#1b2a33';
    ctx.fillText(FRESNEL_PLOT_WORDS[this.tr.language].exact, MARGIN.left + 30, MARGIN.top + 13);
    ctx.fillStyle = '#d2691e';
    ctx.fillRect(MARGIN.left + 8, MARGIN.top + 26, 16, 3);
    ctx.fillStyle = '#1b2a33';
    ctx.fillText(FRESNEL_PLOT_WORDS[this.tr.language].schlick, MARGIN.left + 30, MARGIN.top + 31);
  }

  dispose(): void {
    this.canvas.remove();
  }
}
