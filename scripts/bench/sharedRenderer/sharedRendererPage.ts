/**
 * Prototype for docs/course-pages.md ("One shared renderer"): the chapter of the course-page
 * bench (?count=N figures, one preset each, cycled, frozen at t = 5 + i) drawn as model-viewer
 * draws its elements: one WebGLRenderer on a canvas of its own, every figure a scene with an
 * `Ocean` (the library object) and its sky, drawn in turn and copied to the figure's 2D canvas.
 * A figure builds its ocean when it comes within half a screen, as <oceano-view> starts, and
 * keeps it; only figures on screen are drawn. No boat, panel, lessons or underwater passes.
 * window.shared answers the bench (scripts/bench/coursePages.ts).
 */
import { PerspectiveCamera, Scene, Vector2, WebGLRenderer } from 'three';
import { Ocean } from '../../../src/render/ocean/ocean';
import { presetNames } from '../../../src/app/url/presets';
import { parseSettings } from '../../../src/app/url/urlState';

const renderer = new WebGLRenderer({ canvas: document.createElement('canvas'), antialias: false });
const gl = renderer.getContext();

class SharedFigure {
  readonly element = document.createElement('shared-ocean-figure');
  private readonly canvas = document.createElement('canvas');
  private readonly context = this.canvas.getContext('2d')!;
  private readonly settings: [string, string][];
  private world: { scene: Scene; camera: PerspectiveCamera; ocean: Ocean; time: number } | null = null;
  near = false;
  drawn = false;

  constructor(index: number) {
    this.settings = [['preset', presetNames[index % presetNames.length]], ['t', String(5 + index)], ['seed', String(1 + index)]];
    this.element.append(this.canvas);
  }

  get onScreen(): boolean {
    const box = this.element.getBoundingClientRect();
    return box.bottom > 0 && box.top < innerHeight;
  }

  /** Builds the scene the first time the figure comes near; resolves when its wave model's code is in. */
  async start(): Promise<void> {
    if (this.world) return;
    const state = parseSettings(this.settings);
    const box = this.element.getBoundingClientRect();
    [this.canvas.width, this.canvas.height] = [Math.round(box.width), Math.round(box.height)];
    const camera = new PerspectiveCamera(55, box.width / box.height, 0.5, 20000);
    const pose = state.camera!;
    camera.position.fromArray(pose.position);
    camera.lookAt(...pose.target);
    const scene = new Scene();
    const ocean = new Ocean(renderer, state.params);
    scene.add(ocean, ocean.sky);
    this.world = { scene, camera, ocean, time: state.time ?? 0 };
    await ocean.ready;
  }

  /** Draws through the shared renderer at this figure's size and copies the picture to its canvas. */
  draw(): void {
    if (!this.world) return;
    const { scene, camera, ocean, time } = this.world;
    const size = renderer.getSize(new Vector2());
    if (size.x !== this.canvas.width || size.y !== this.canvas.height) renderer.setSize(this.canvas.width, this.canvas.height, false);
    ocean.update(time, camera);
    renderer.render(scene, camera);
    this.context.drawImage(renderer.domElement, 0, 0);
    this.drawn = true;
  }
}

const count = Number(new URLSearchParams(location.search).get('count') ?? 30);
const figures = Array.from({ length: count }, (_, i) => new SharedFigure(i));
for (const [i, figure] of figures.entries()) {
  const section = document.createElement('section');
  const caption = document.createElement('p');
  caption.textContent = `Figure ${i + 1}`;
  section.append(caption, figure.element);
  document.body.append(section);
}

const starting = new Map<SharedFigure, Promise<void>>();
const watch = new IntersectionObserver(
  (entries) => {
    for (const entry of entries) {
      const figure = figures.find((f) => f.element === entry.target)!;
      figure.near = entry.isIntersecting;
      if (figure.near && !starting.has(figure)) starting.set(figure, figure.start());
    }
  },
  { rootMargin: '50% 0px' },
);
for (const figure of figures) watch.observe(figure.element);

/** One frame: the figures on screen not drawn yet, once their ocean is ready (time is frozen: a drawn figure keeps its picture). */
async function frame(): Promise<void> {
  const waiting = figures.filter((f) => f.onScreen && !f.drawn && starting.has(f));
  await Promise.all(waiting.map((f) => starting.get(f)));
  for (const figure of waiting) figure.draw();
}

function loop(): void {
  void frame().then(() => requestAnimationFrame(loop));
}
requestAnimationFrame(loop);

(window as unknown as { shared: object }).shared = {
  /** Resolves once every figure on screen has been drawn. */
  async onScreenDrawn(): Promise<void> {
    while (!figures.filter((f) => f.onScreen).every((f) => f.drawn)) await new Promise((r) => setTimeout(r, 20));
  },
  /** Milliseconds to draw every figure on screen once, the GPU included (a one-pixel read-back waits for it), median of `frames`. */
  frameMs(frames: number): number {
    const times: number[] = [];
    for (let i = 0; i < frames; i++) {
      const start = performance.now();
      for (const figure of figures) if (figure.onScreen) figure.draw();
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
      times.push(performance.now() - start);
    }
    return times.sort((a, b) => a - b)[Math.floor(frames / 2)];
  },
  programs: () => renderer.info.programs?.length ?? 0,
  started: () => starting.size,
};
