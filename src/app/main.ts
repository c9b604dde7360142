import './style.css';
import { OceanApp } from './oceanApp';
import { createAutomationApi } from './automationApi';
import { parseUrlState } from './urlState';

function hasWebGL2(): boolean {
  try {
    return document.createElement('canvas').getContext('webgl2') !== null;
  } catch {
    return false;
  }
}

function showFatal(container: HTMLElement, message: string): void {
  const box = document.createElement('div');
  box.className = 'oceano-fatal';
  box.setAttribute('role', 'alert');
  box.textContent = message;
  container.appendChild(box);
}

function boot(): void {
  const container = document.getElementById('oceano') as HTMLElement;
  const canvas = container.querySelector('canvas.oceano-canvas') as HTMLCanvasElement;
  if (!hasWebGL2()) {
    canvas.remove();
    showFatal(container, 'Oceano needs WebGL2, which this browser or device does not provide. Try a recent Chrome, Firefox or Safari, or enable hardware acceleration.');
    return;
  }
  const app = new OceanApp(container, canvas, parseUrlState(window.location.search));
  const ready = app.start().catch((error: unknown) => {
    showFatal(container, `Oceano could not start: ${error instanceof Error ? error.message : String(error)}`);
    throw error;
  });
  window.oceano = createAutomationApi(app, ready);
}

boot();
